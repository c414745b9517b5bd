# Format revisions (issue #12).
#   breaking BASE=<git ref>   `cbfgen diff` of spec/cbf.yaml at BASE (via `git show`) against the
#                             working tree's spec: every change by version and command; exit 1
#                             when one changes the wire meaning of a version BASE has.
#   revision-drill            every fixture of tests/revisions/ (a new command, a new version
#                             dropping a command, a layout change in one version, another
#                             checksum algorithm chosen by a profile) applied to a temporary
#                             copy of the tree, then `cbfgen diff` (the classification the
#                             fixture states), `make generate`, `make golden`,
#                             `make conformance` (every binding) and the whole pytest suite.
#   revision-drill-quick      the same with the subset of tests/revisions/drill.py: the fixtures
#                             whose kind no in-tree test makes (IN_TREE: a new command is made
#                             by tests/test_new_command.py, another checksum algorithm by
#                             tests/test_golden_checksums.py, both in `make test`), conformance
#                             of QUICK_BINDINGS (python, c, kaitai-javascript: the two runtimes
#                             that implement the checks and one Kaitai parser) on the golden
#                             files up to QUICK_MAX_BYTES (not the 65,535-record case) and the pytest
#                             files QUICK_TESTS (spec loader, check coverage, codec, CUT, docs,
#                             golden assembly, rev 03 facts, CLI).
# `make test` runs revision-drill-quick, its two fixtures at once (DRILL_JOBS). Before IN_TREE: 77-97 s on an idle
# 2-core machine. Measured serially on the shared machine (load 6-9):
# the quick drill takes 205-267 s for the four fixtures (150-160 s of CPU): per fixture,
# copy 1-2 s, generate 6-9 s, golden 3-5 s, C testee 9-10 s, conformance 14-20 s, tests
# 24-45 s. The full drill takes 3-7 minutes a fixture (every binding's build and the whole
# suite four more times), too much for the five minutes `make test` may take. The quick drill does not
# re-assemble the goldens `make golden` just wrote, and builds its ASan/UBSan testee at -O0
# (tests/revisions/drill.py: QUICK_DESELECT, QUICK_C_SAN): about 42 CPU s a fixture.
BASE ?= HEAD
# Fixtures drilled at once in the quick drill (one per core of the 2-core CI machine).
DRILL_JOBS ?= $(shell nproc 2>/dev/null || echo 1)
.PHONY: breaking revision-drill revision-drill-quick

breaking: venv  ## cbfgen diff of spec/cbf.yaml at BASE=<git ref> (default HEAD) against the working tree
	@tmp=$$(mktemp -d) && trap 'rm -rf "$$tmp"' EXIT && \
	  git show "$(BASE):spec/cbf.yaml" > "$$tmp/cbf.yaml" && \
	  $(PY) -m cbfgen diff "$$tmp/cbf.yaml" spec/cbf.yaml --old-name "$(BASE):spec/cbf.yaml" $(if $(JSON),--json)

revision-drill: venv kaitai-setup  ## apply every tests/revisions/ fixture in a temp copy: generate, golden, conformance, tests
	$(PY) tests/revisions/drill.py run --jobs $(DRILL_JOBS)

revision-drill-quick: venv kaitai-setup
	$(PY) tests/revisions/drill.py run --quick --jobs $(DRILL_JOBS)

TEST_DEPS += revision-drill-quick
