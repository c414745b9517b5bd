# Format documentation (issue #6).
#   docs        generated/docs/ (Markdown + SVG, committed; also written by `make generate`)
#               and the static HTML site in $(DOCS_HTML)/ (ignored): open $(DOCS_HTML)/index.html.
#               The Kaitai graph (ksc's graphviz target, rendered by Graphviz `dot`) goes
#               into $(DOCS_HTML)/kaitai/ only; without dot the site says it is not built.
#   docs-check  headless Chromium (Debian `chromium`, installed by .ci/setup-debian.sh with
#               CBF_WANT_CHROMIUM=1) renders the index and a command page to PNG and fails
#               on any console message (see generator/cbfgen/emit/docs/browser.py).
DOCS_HTML := build/docs-html
DOCS_KAITAI := $(DOCS_HTML)/kaitai
.PHONY: docs docs-kaitai docs-site docs-check

docs: docs-site  ## Markdown docs (generated/docs/) and the HTML site ($(DOCS_HTML)/index.html)

# After docs-kaitai: the pages link the Kaitai graph only when it was built.
docs-site: generate-py docs-kaitai
	$(PY) -m cbfgen.emit.docs.site --spec spec/cbf.yaml --out $(DOCS_HTML)

# ksc's own view of the .ksy. Graphviz comes from .ci/setup-debian.sh (c-deps).
docs-kaitai: kaitai-setup generate-py c-deps
	@rm -rf $(DOCS_KAITAI) && mkdir -p $(DOCS_KAITAI)
	@if command -v dot >/dev/null; then \
	  node generator/cbfgen/emit/kaitai/ksc_driver.js generated/kaitai/cbf.ksy.json $(DOCS_KAITAI) graphviz >/dev/null; \
	  dot -Tsvg -o $(DOCS_KAITAI)/cbf.svg $(DOCS_KAITAI)/graphviz/cbf.dot 2>$(DOCS_KAITAI)/dot.log; \
	  echo "docs: $(DOCS_KAITAI)/cbf.svg (ksc graphviz, dot $$(dot -V 2>&1 | awk '{print $$5}'))"; \
	else echo "docs: Graphviz 'dot' not found: the Kaitai graph is not built" >&2; fi

docs-check: docs  ## render the HTML docs in headless Chromium; fail on console errors
	@CBF_WANT_CHROMIUM=1 .ci/setup-debian.sh
	$(PY) -m cbfgen.emit.docs.browser --site $(DOCS_HTML) --out build/docs-check

# Installing chromium (about 15 s on Debian 12 with a warm apt mirror) and three
# renders (about 5 s) fit in CI's budget: `make test` runs the browser check.
TEST_DEPS += docs-check
