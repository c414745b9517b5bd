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
#   revision-drill-quick      the same, with the pytest subset QUICK_TESTS of
#                             tests/revisions/drill.py (spec loader, check coverage, codec,
#                             CUT, docs, golden assembly, rev 03 facts, diff, CLI).
# `make test` runs revision-drill-quick: the full suite four more times would take
# about 8 more minutes on 2 cores, the quick drill about 1 minute a fixture (measured:
# copy 1-3 s, generate 7-15 s, golden 8-12 s, conformance 60-105 s, subset 10-20 s).
BASE ?= HEAD
.PHONY: breaking revision-drill revision-drill-quick

breaking: venv  ## cbfgen diff of spec/cbf.yaml at BASE=<git ref> (default HEAD) against the working tree
	@tmp=$$(mktemp -d) && trap 'rm -rf "$$tmp"' EXIT && \
	  git show "$(BASE):spec/cbf.yaml" > "$$tmp/cbf.yaml" && \
	  $(PY) -m cbfgen diff "$$tmp/cbf.yaml" spec/cbf.yaml --old-name "$(BASE):spec/cbf.yaml" $(if $(JSON),--json)

revision-drill: venv kaitai-setup  ## apply every tests/revisions/ fixture in a temp copy: generate, golden, conformance, tests
	$(PY) tests/revisions/drill.py run

revision-drill-quick: venv kaitai-setup
	$(PY) tests/revisions/drill.py run --quick

TEST_DEPS += revision-drill-quick
