# CBF toolkit. Two commands for a fresh machine: `make` and `make test`.
# Every target bootstraps what it needs (.venv, npm ci, Debian packages) and
# is idempotent. Fragments in mk/*.mk add the targets of each binding.

SHELL := /bin/bash
.SHELLFLAGS := -eu -o pipefail -c
.DEFAULT_GOAL := all
MAKEFLAGS += --no-print-directory

PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
export PYTHONPATH := $(CURDIR)/generator:$(CURDIR)/generated/python:$(CURDIR)
export PYTHONDONTWRITEBYTECODE := 1
export PIP_DISABLE_PIP_VERSION_CHECK := 1

# Stamps of steps that run only when their inputs changed (a no-op `make` stays fast).
STAMPS := build/stamps

# Hooks the fragments in mk/*.mk append to (before the rules that use them).
GENERATE_POST :=
TEST_DEPS :=
TEST_BUILD :=
TEST_EARLY :=
CONFORMANCE_BUILD :=
DIST_EXTRA :=
-include mk/*.mk
.PHONY: all venv generate generate-py check-generated check-spec lint typecheck test test-py clean help

all: generate check-generated lint conformance  ## regenerate everything from the spec and check it

help:
	@grep -hE '^[a-z-]+:.*## ' $(MAKEFILE_LIST) | sed 's/:.*## /\t/' | sort

# -- Python environment -------------------------------------------------------
$(VENV)/.stamp: pyproject.toml .ci/constraints.txt
	@test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install -q --upgrade "pip==24.3.1"
	$(PY) -m pip install -q -c .ci/constraints.txt -e ".[dev]"
	@touch $@

# Toolchains (Python, Node, Go, JDK + Maven, gcc/clang, graphviz) from Debian's packages
# when missing; elsewhere it stops and names what is missing (README "Prerequisites").
.PHONY: setup
setup:
	@.ci/setup-debian.sh

venv: setup $(VENV)/.stamp  ## create .venv with the pinned dependencies

# -- generation ---------------------------------------------------------------
check-spec: venv  ## load and check spec/cbf.yaml only
	$(PY) -m cbfgen --check-spec

# cbfgen runs when what it reads changed: the spec, the generator, conformance/ (golden cases, the
# reports the docs show) or a file of generated/ itself (a hand edit is overwritten, as always).
# A deleted file of generated/ makes it run too. Outside a git checkout (the revision drill's
# copy of the tree) the files of generated/ that are there stand for the tracked ones.
GENERATED_TRACKED := $(shell git ls-files generated 2>/dev/null || find generated -type f -not -path '*/__pycache__/*' \
  -not -path 'generated/docs/site/*' -not -path 'generated/kaitai/java/target/*' 2>/dev/null)
GENERATE_INPUTS = $(shell find spec generator conformance -type f -not -path '*/__pycache__/*' \
  -not -name '*.tmp' 2>/dev/null) $(wildcard $(GENERATED_TRACKED))
# A file of generated/ that cbfgen itself removed (a renamed or dropped command's page) is gone by design: the
# stamp's recipe lists those (git's deleted files of generated/ right after generation), and only another missing
# file forces a run. Else a revision that removes one is never fresh until committed, and `make revision`'s
# freshness check fails in a clone (the drill's rename fixture, once its copy became a checkout).
GENERATED_REMOVED := $(shell cat $(STAMPS)/generate-py.removed 2>/dev/null)
GENERATE_FORCE = $(if $(filter-out $(wildcard $(GENERATED_TRACKED)) $(GENERATED_REMOVED),$(GENERATED_TRACKED)),FORCE)
.PHONY: FORCE
FORCE:
generate-py: venv $(STAMPS)/generate-py  ## run every Python emitter (no ksc)
$(STAMPS)/generate-py: $(GENERATE_INPUTS) $(VENV)/.stamp $(GENERATE_FORCE)
	$(PY) -m cbfgen --spec spec/cbf.yaml --out generated --no-ksc
	@mkdir -p $(@D) && { git ls-files --deleted -- generated 2>/dev/null || true; } > $(@D)/generate-py.removed && touch $@

# One make process runs the Python emitters once, then the later steps (ksc, ...).
generate: generate-py $(GENERATE_POST)  ## regenerate generated/ from the spec

# Later build steps (ksc, docs rendering) hook in here from mk/*.mk.
.PHONY: generate-post
generate-post: $(GENERATE_POST)

check-generated: generate  ## fail when generated/ differs from what the spec gives
	@if ! git diff --exit-code --stat -- generated/ || [ -n "$$(git status --porcelain --untracked-files=all -- generated/)" ]; then \
	  git status --short -- generated/ | head -20; \
	  echo "generated/ is stale: run 'make generate' and commit the result" >&2; exit 1; fi
	@echo "generated/ is fresh"

# Bytecode of this checkout's Python, compiled once beside the sources (__pycache__/, ignored by git).
# PYTHONDONTWRITEBYTECODE (above, and set by the CI environment) stops Python writing it, so without this
# every Python process `make test` starts (CLI calls, testees, tools, revised trees) compiles cbf, cbfgen
# and the runner again: about 0.1 CPU s a process. A .pyc whose source changed later is ignored.
BYTECODE_DIRS = generator generated/python generated/kaitai/python conformance tests $(wildcard bench)
.PHONY: bytecode
bytecode: generate
	@$(PY) -m compileall -q -j0 $(BYTECODE_DIRS) >/dev/null

# -- quality ------------------------------------------------------------------
MYPY_PATHS = generator/cbfgen generated/python/cbf $(wildcard conformance/runner conformance/assembler conformance/reliability conformance/kit.py conformance/revise.py bench/bench.py)
LINT_INPUTS = $(shell find generator conformance tests generated/python bench -name '*.py' -not -path '*/__pycache__/*' 2>/dev/null) pyproject.toml
lint: venv $(STAMPS)/lint  ## ruff + mypy --strict on hand-written Python
$(STAMPS)/lint: $(LINT_INPUTS) $(VENV)/.stamp
	$(PY) -m ruff check generator conformance tests generated/python $(wildcard bench)
	$(PY) -m mypy --strict $(MYPY_PATHS)
	@mkdir -p $(@D) && touch $@

# One worker per core; a test file stays on one worker (--dist loadfile), so module-scoped
# fixtures (built wheels, venvs) are made once. The two plugins the suite uses are named, not
# autoloaded: an autoloaded plugin's package is marked for pytest's assertion rewriting, which
# PYTHONDONTWRITEBYTECODE never lets it cache (hypothesis' modules: about 0.6 CPU s a process).
# Each test's CPU seconds (children included) go to build/test-results/cpu/, one report a worker, and
# tests/cpu_budget.py holds the suite and each file to a CPU budget (CPU time, not wall time: the same
# on a loaded machine, within about a fifth). `make test-profile` prints the costliest files and tests
# of the last run. What costs what: tests/README-speed.md.
CPU_REPORT := build/test-results/cpu
PYTEST_PLUGINS_NAMED := -p xdist.plugin -p _hypothesis_pytestplugin
test-py: venv
	@rm -rf $(CPU_REPORT)
	CBF_CPU_REPORT=$(CURDIR)/$(CPU_REPORT) PYTEST_DISABLE_PLUGIN_AUTOLOAD=1 $(PY) -m pytest -p no:cacheprovider \
	  $(PYTEST_PLUGINS_NAMED) -n auto --dist loadfile --junitxml=build/test-results/pytest.xml
	$(PY) tests/cpu_budget.py check $(CPU_REPORT)

.PHONY: test-profile
test-profile:  ## the CPU seconds of each test file and the costliest tests of the last `make test-py`
	@$(PY) tests/cpu_budget.py show $(CPU_REPORT)

# `make test`: the toolchains first (setup, alone: apt-get takes one lock); then ONE make of
# TEST_JOBS jobs (one per core) runs everything else as one graph (test-run), so that no core
# waits at a phase boundary:
#   - test-ready: .venv, `generate check-generated`, the bytecode, and the builds of what the
#     checks run (the testees, cbf-c, Chromium: CONFORMANCE_BUILD, TEST_BUILD). The builds read
#     only committed files of generated/ (cbfgen and ksc replace a file atomically and only when
#     its content changed; when one changes, check-generated fails and so does `make test`), so
#     they run while pip fills .venv;
#   - the checks that need .venv (TEST_CHECKS) and their long prerequisites (TEST_GATED) start once
#     test-ready is made (their recipes' own `$(MAKE) $(CONFORMANCE_BUILD)` then finds nothing to
#     do: no two makes build one file);
#   - the C checks (TEST_EARLY) need no .venv and fill whatever core is free, from the start.
# Goals are listed longest first (pytest, the revision drill, mypy: one process of about 20 s), so
# make starts them first and the short ones fill the last minute on both cores. Each
# check's output is printed whole (--output-sync). The checks only read the tree and write their
# own build/ folders and temporary folders. check-report compares the run's report and docs last.
TEST_JOBS ?= $(shell nproc 2>/dev/null || echo 1)
TEST_CHECKS = $(filter-out $(CONFORMANCE_BUILD) $(TEST_BUILD),test-py $(filter revision-drill-quick,$(TEST_DEPS)) lint \
  $(filter-out revision-drill-quick,$(TEST_DEPS)) conformance)
.PHONY: test-ready test-run
test-ready: check-generated bytecode $(CONFORMANCE_BUILD) $(TEST_BUILD)
test-run: $(TEST_CHECKS) $(TEST_EARLY)
# The checks' own long prerequisites (mypy, the gallery and site) wait for test-ready too: queued
# before it, they held the short generate -> ksc -> bytecode chain back, and pytest (the longest
# check) with it, by about 20 s.
TEST_GATED = $(STAMPS)/lint docs-site
ifneq ($(filter test-run,$(MAKECMDGOALS)),)
$(TEST_CHECKS) $(TEST_GATED): | test-ready
endif
test:  ## the full test suite (what CI runs)
	@$(MAKE) setup
	@$(MAKE) -j$(TEST_JOBS) --output-sync=recurse test-run
	@$(MAKE) check-report

# -- distributions (what users install) ------------------------------------------
# `cbf` (codec + CLI, from generated/python), `cbfgen` (the generator), `cbf-kaitai` (the Kaitai
# Python parser, generated/kaitai/python) and `cbf-conformance` (the runner with the golden cases,
# staged by conformance/kit.py), as wheels and
# sdists in dist/. Built with the pinned setuptools of .venv (no download at build time).
.PHONY: dist
# Artefacts that are not Python packages (DIST_EXTRA, from mk/*.mk: cbf-c.wasm) are copied beside them.
dist: generate $(DIST_EXTRA)  ## build the cbf, cbfgen, cbf-kaitai and cbf-conformance wheels and sdists into dist/
	@rm -rf dist && mkdir -p dist
	$(PY) -m build --no-isolation --outdir dist generated/python >/dev/null
	$(PY) -m build --no-isolation --outdir dist generator >/dev/null
	$(PY) -m build --no-isolation --outdir dist generated/kaitai/python >/dev/null
	$(PY) -m conformance.kit build/kit >/dev/null
	$(PY) -m build --no-isolation --outdir dist build/kit >/dev/null
	@rm -rf generated/python/build generated/python/*.egg-info generator/build generator/*.egg-info \
	  generated/kaitai/python/build generated/kaitai/python/*.egg-info
	@$(if $(strip $(DIST_EXTRA)),cp $(DIST_EXTRA) dist/,true)
	@ls dist

clean:
	rm -rf $(VENV) node_modules build dist .pytest_cache .mypy_cache .ruff_cache
