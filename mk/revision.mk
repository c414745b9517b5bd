# Format revisions (issue #12).
#   breaking BASE=<git ref>   `cbfgen diff` of spec/cbf.yaml at BASE (via `git show`) against the
#                             working tree's spec: every change by version and command, each
#                             wire-breaking, text-breaking or neither; exit 0 when none breaks
#                             anything, else make's 2 with cbfgen diff's code on the last line.
#   revision-drill            every fixture of tests/revisions/ (a new command, a new version
#                             dropping a command, a layout change in one version, another
#                             checksum algorithm chosen by a profile, a rename), its ids
#                             chosen for the spec it meets, applied to a temporary copy of
#                             the tree, then `cbfgen diff` (the classification the fixture
#                             states), `make revision` without conformance (generate, golden,
#                             generated/ fresh, expectations), `make conformance` (every
#                             binding), a commit of the revision (the copy is committed before
#                             the fixture) and a check that it changed no file outside spec/,
#                             generated/, conformance/golden/, conformance/failures/ and
#                             conformance/report.json (drill.REVISION_PATHS), and `make test`
#                             in the revised tree (CI=true; its quick drill applies every fixture
#                             on top of this revision, its own kind too): the README's walkthrough
#                             to its end; then every fixture applied on top of the others in ONE
#                             copy (`drill.py run --together`) and the same steps there.
#   revision-drill-quick      the subset `make test` runs (tests/revisions/drill.py): the fixtures
#                             whose kind no in-tree test makes (IN_TREE: a new command is made
#                             by tests/test_new_command.py, another checksum algorithm by
#                             tests/test_golden_checksums.py, both in `make test`), each one's
#                             `cbfgen diff` checked alone, then all of them applied to ONE copy
#                             of the tree, twice over (drill.QUICK_ROUNDS: each fixture then
#                             meets its own revision; drill_together): generate, golden, conformance of
#                             QUICK_BINDINGS (python, c, kaitai-javascript: the two runtimes that
#                             implement the checks and one Kaitai parser) on the golden files up
#                             to QUICK_MAX_BYTES (not the 65,535-record case), and the pytest
#                             files QUICK_TESTS (spec loader, check coverage, codec, CUT, docs,
#                             golden assembly, rev 03 facts, CLI), once.
# Measured with rename added, the three together: 16 s and 13.9 CPU s (user + sys) at load 2,
# 46 s and 15.8 CPU s at load 7 (14.7 CPU s for the two without it). Before, on an idle 2-core machine: 32 s
# and 31 CPU s for layout_change and new_version together (diffs 2 s, copy 1 s, generate 3 s,
# golden 2 s, C testee 3 s, conformance 2 s, tests 19 s); a tree a fixture, as before, took 72 s on the CI run's two cores, and with the
# 65,535-record case in its conformance about 105 CPU s. The full drill takes 3-7 minutes a
# fixture (every binding's build and the whole suite, a tree each): its five fixtures passed in
# 1,531 s at DRILL_JOBS=1 under nice 19 on the shared machine at load 7-13. The quick drill does not
# re-assemble the goldens `make golden` just wrote, and builds its ASan/UBSan testee at -O0
# (QUICK_DESELECT, QUICK_C_SAN). Round 5, 17 fixtures (15 quick: prose_edit, new_section, header_move,
# polyline_new_version and rename_real added): 28-37 s and 21 CPU s (user + sys) at load 2-4, its first step
# `make revision` 7-14 s. Round 7, the fixtures applied twice over (QUICK_ROUNDS): 23 s alone on the idle machine,
# 40 s inside a fresh clone's `make test` (beside its other checks).
BASE ?= HEAD
# Fixtures drilled at once by `make revision-drill`, a tree each (one per core of the 2-core CI machine).
DRILL_JOBS ?= $(shell nproc 2>/dev/null || echo 1)
.PHONY: breaking revision-drill revision-drill-quick witness-drill

# make's own exit status is 0 or 2 (any failed recipe), so `make breaking` cannot pass on cbfgen diff's
# codes (0 none, 1 wire-breaking, 3 text-breaking only, 2 bad input): it exits 0 when nothing breaks and
# 2 otherwise, and its last line (stderr) names cbfgen diff's code and class. NEW_SPEC: the spec to
# compare with BASE's (default the working tree's).
NEW_SPEC ?= spec/cbf.yaml
breaking: venv  ## cbfgen diff of spec/cbf.yaml at BASE=<git ref> (default HEAD) against the working tree
	@tmp=$$(mktemp -d) && trap 'rm -rf "$$tmp"' EXIT && \
	  git show "$(BASE):spec/cbf.yaml" > "$$tmp/cbf.yaml" && \
	  { $(PY) -m cbfgen diff "$$tmp/cbf.yaml" "$(NEW_SPEC)" --old-name "$(BASE):spec/cbf.yaml" $(if $(JSON),--json); \
	    rc=$$?; } && \
	  case $$rc in \
	    0) ;; \
	    1) echo "make breaking: cbfgen diff exit 1: wire-breaking" >&2 ;; \
	    3) echo "make breaking: cbfgen diff exit 3: text-breaking only" >&2 ;; \
	    *) echo "make breaking: cbfgen diff exit $$rc: usage, or a spec that does not load" >&2 ;; \
	  esac && exit $$rc

revision-drill: venv kaitai-setup  ## apply every tests/revisions/ fixture in a temp copy: generate, golden, conformance, tests
	$(PY) tests/revisions/drill.py run --jobs $(DRILL_JOBS)
	$(PY) tests/revisions/drill.py run --together

revision-drill-quick: venv kaitai-setup
	$(PY) tests/revisions/drill.py run --quick

TEST_DEPS += revision-drill-quick

# `cbfgen diff --witness` on every breaking fixture, through the command line (tests/test_witness.py
# checks the same in-process in `make test`): the files land in build/witness/<fixture>/.
witness-drill: venv  ## cbfgen diff --witness for every breaking tests/revisions/ fixture: a verified file per change
	$(PY) tests/revisions/witness_drill.py build/witness

# The README's walkthrough as one command (conformance/revise.py): generate, golden, generated/ fresh,
# the golden cases the revision judges differently (each proposed expectation as a diff in
# build/revision/expectations.patch, never written: `git apply` it to accept), conformance; then what to
# review and commit. NO_CONFORMANCE=1 stops before `make conformance` (the drill runs its own).
.PHONY: revision
revision: venv kaitai-setup  ## after an edit of spec/cbf.yaml: generate, golden, freshness, expectations, conformance
	$(PY) -m conformance.revise $(if $(NO_CONFORMANCE),--no-conformance)

# One kind of revision drilled alone: `make revision-kind KIND=header_move` (a fixture of tests/revisions/,
# every step in full in a copy of the tree; QUICK=1 for the quick drill's steps).
.PHONY: revision-kind
revision-kind: venv kaitai-setup  ## drill one fixture of tests/revisions/ alone: KIND=<fixture name>
	@test -n "$(KIND)" -a -f "tests/revisions/$(KIND).yaml" || { \
	  echo "make revision-kind: KIND= one of: $$(cd tests/revisions && ls *.yaml | sed 's/\.yaml$$//' | tr '\n' ' ')" >&2; exit 2; }
	$(PY) tests/revisions/drill.py run $(if $(QUICK),--quick) tests/revisions/$(KIND).yaml
