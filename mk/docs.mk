# Format documentation (issues #6, #15).
#   docs        generated/docs/ (Markdown + SVG, committed; also written by `make generate`)
#               and the static HTML site in $(DOCS_HTML)/ (ignored): open $(DOCS_HTML)/index.html.
#               The site is self-contained: repository files it links (the spec, the golden
#               README, hex sources) are copied in under files/; copy the folder anywhere.
#               ksc's Graphviz view of the .ksy is not built: one graph of every type, about
#               21 m wide, that no reader can use (the docs' byte-field diagrams show the layouts).
#               The search index is built by node with MiniSearch from node_modules.
#   docs-pdf    headless Chromium prints the whole site to $(DOCS_PDF) in 300071's frame
#               (header and footer from `meta`, page N of M); fails unless each chapter is on
#               the page the contents give, every page but a part's last is filled at least half
#               way down (pdftotext -bbox of poppler-utils, installed with chromium), no navigation
#               line of the site is printed and every link stays inside the PDF
#               (generator/cbfgen/emit/docs/pdf.py).
#   docs-check  every link of the site stays inside it and resolves; in headless Chromium
#               (Debian `chromium`, installed by .ci/setup-debian.sh with CBF_WANT_CHROMIUM=1)
#               no page of the site overflows at 1280 px or 390 px, every image loads, no
#               console message, the search finds a check and a command
#               (generator/cbfgen/emit/docs/browser.py); then docs-pdf.
DOCS_HTML := build/docs-html
DOCS_PDF := build/docs-pdf/cbf-reference.pdf
.PHONY: docs docs-site docs-pdf docs-check docs-chromium

docs: docs-site  ## Markdown docs (generated/docs/) and the HTML site ($(DOCS_HTML)/index.html)

# The site shows the toolpath gallery (`cbf plot` and `cbf stats` of every golden file that
# validates clean, mk/gallery.mk) on a page of its own.
# and the Python API reference, read from the cbf package's code with pdoc (cbfgen.emit.docs.api).
DOCS_API := build/docs-api/api.md
docs-site: generate-py node_modules/.stamp
	@rm -rf $(GALLERY) && $(PY) -m cbf.gallery $(GALLERY) conformance/golden/*.cbf
	$(PY) -m cbfgen.emit.docs.api $(DOCS_API)
	$(PY) -m cbfgen.emit.docs.site --spec spec/cbf.yaml --out $(DOCS_HTML) --gallery $(GALLERY) --api $(DOCS_API) $(DOCS_SITE_FLAGS)

docs-chromium:
	@CBF_WANT_CHROMIUM=1 .ci/setup-debian.sh

docs-pdf: generate-py docs-chromium  ## the reference as one PDF ($(DOCS_PDF)), checked against its contents
	$(PY) -m cbfgen.emit.docs.pdf --spec spec/cbf.yaml --out $(DOCS_PDF) $(DOCS_PDF_FLAGS)

docs-check: docs docs-chromium  ## links stay in the site; Chromium: no overflow, images load, no console; the PDF
	$(PY) -m cbfgen.emit.docs.browser --site $(DOCS_HTML) --out build/docs-check
	$(PY) -m cbfgen.emit.docs.pdf --spec spec/cbf.yaml --out $(DOCS_PDF) $(DOCS_PDF_FLAGS)

# Installing chromium (about 15 s on Debian 12 with a warm apt mirror), the browser
# check (164 pages, about 17 s) and the PDF (about 200 pages, two prints, about 13 s) fit in
# CI's budget: `make test` runs them.
TEST_DEPS += docs-check
TEST_BUILD += docs-chromium
