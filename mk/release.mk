# -- releases: CHANGELOG.md and the tag vX.Y.Z ------------------------------------------
# `make release` builds dist/ (the wheels the README installs), checks that CHANGELOG.md is what
# `cbfgen changelog` writes, and tags the clean HEAD `vX.Y.Z` from the toolkit's one version
# (__version__ in generator/cbfgen/__init__.py), so that a pre-commit config's `rev: vX.Y.Z` exists.
# A tag that already names HEAD is fine; one that names another commit is refused (raise the
# version). `make release-tag` is the tagging alone: it needs no .venv (the version is read with
# sed), so tests/test_release.py runs it in a temporary clone.
RELEASE_VERSION = $(shell sed -n 's/^__version__ = "\(.*\)"$$/\1/p' generator/cbfgen/__init__.py)
.PHONY: release release-tag changelog check-changelog

changelog: venv  ## write CHANGELOG.md from the release tags and cbfgen diff between their specs
	$(PY) -m cbfgen changelog

check-changelog: venv
	$(PY) -m cbfgen changelog --check

release: check-changelog dist  ## check CHANGELOG.md, build dist/, tag vX.Y.Z (the toolkit's version) on a clean HEAD
	@$(MAKE) release-tag

release-tag:
	@test -n "$(RELEASE_VERSION)" || { echo "make release: no __version__ in generator/cbfgen/__init__.py" >&2; exit 2; }
	@if [ -n "$$(git status --porcelain --untracked-files=no)" ]; then \
	  echo "make release: uncommitted changes: commit them first (the tag names a commit)" >&2; exit 2; fi
	@tag=v$(RELEASE_VERSION); head=$$(git rev-parse HEAD); \
	if at=$$(git rev-parse -q --verify "refs/tags/$$tag^{commit}"); then \
	  if [ "$$at" = "$$head" ]; then echo "make release: $$tag already names HEAD"; exit 0; fi; \
	  echo "make release: $$tag already names $$at, not HEAD: raise __version__ in generator/cbfgen/__init__.py" >&2; \
	  exit 2; fi; \
	git tag -a "$$tag" -m "CBF toolkit $(RELEASE_VERSION)" && echo "make release: tagged $$tag at $$(git rev-parse --short HEAD)"

# -- shell completion and man pages, from the argument parsers (cbf.shellfiles) ----------------------
SHELLFILES := build/shellfiles
.PHONY: shellfiles
shellfiles: generate-py  ## bash completion and man pages of cbf and cbf-conformance from their parsers ($(SHELLFILES)/)
	@mkdir -p $(SHELLFILES)
	$(PY) -m cbf.shellfiles bash > $(SHELLFILES)/cbf.bash
	$(PY) -m cbf.shellfiles man > $(SHELLFILES)/cbf.1
	$(PY) -m cbf.shellfiles bash --parser conformance.runner.__main__:parser > $(SHELLFILES)/cbf-conformance.bash
	$(PY) -m cbf.shellfiles man --parser conformance.runner.__main__:parser > $(SHELLFILES)/cbf-conformance.1
	@ls $(SHELLFILES)
