# The site links the page (site.py --workbench).
DOCS_SITE_FLAGS += --workbench
# The PDF links it from its front matter, relative to the PDF's folder (cbfgen.emit.docs.pdf --workbench).
DOCS_PDF_FLAGS += --workbench $(DOCS_HTML)/workbench.html

# The workbench page (issue 34, point 3): $(DOCS_HTML)/workbench.html, the C engine (build/wasm/cbf-c.wasm,
# mk/wasm.mk) inlined in one page with the spec's layouts (cbfgen.emit.docs.workbench). It is written into
# the site after the site's own build (which empties the folder), so `make docs` gives both; it is checked
# in headless Chromium by tests/test_workbench_page.py (playwright-core, package.json).
.PHONY: workbench
workbench: docs-site wasm-build  ## the workbench page of the site: drop a .cbf file, see what cbf-c says
	$(PY) -m cbfgen.emit.docs.workbench --spec spec/cbf.yaml --wasm $(WASM_OUT)/cbf-c.wasm --out $(DOCS_HTML)

docs: workbench
