"""The workbench page is reached from the document (issue 34, point 3): every page of the site links it,
and the PDF's front matter does, by a link relative to the PDF's folder (Chromium prints links absolute:
cbfgen.emit.docs.pdf rewrites it, and its check fails without it). The page's name is the emitter's."""

from __future__ import annotations

import html
import posixpath
import re
from pathlib import Path

from cbfgen.emit.docs import browser, pdf, site, workbench
from cbfgen.emit.docs.cdp import Browser
from cbfgen.loader import load

REPO = Path(__file__).resolve().parents[1]
SPEC = load(REPO / "spec" / "cbf.yaml")
_HREF = re.compile(r'<a [^>]*href="([^"#]*)[^"]*"')


def test_every_page_of_the_site_links_the_workbench_page() -> None:
    files = site.pages(SPEC, workbench=True)
    htmls = {p: b.decode() for p, b in files.items() if p.endswith(".html")}
    assert htmls
    missing = [p for p, text in htmls.items()
               if workbench.PAGE not in {posixpath.normpath(posixpath.join(posixpath.dirname(p), html.unescape(h)))
                                         for h in _HREF.findall(text)}]
    assert not missing, missing[:5]
    # and none without it (the page exists only when make workbench wrote it)
    assert not any(workbench.PAGE in b.decode() for p, b in site.pages(SPEC).items() if p.endswith(".html"))


def test_the_pdf_links_the_workbench_page_relative_to_its_folder(tmp_path: Path) -> None:
    out = tmp_path / "docs-pdf" / "r.pdf"
    out.parent.mkdir()
    work = out.parent / "work"
    work.mkdir()
    href = f"../site/{workbench.PAGE}"
    doc = f'<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>t</title></head><body>' \
          f'{pdf.workbench_note(href)}<p id="x"><a href="#x">inside</a></p></body></html>'
    assert pdf.dangling(doc, href) == [] and pdf.dangling(doc) != []  # the one link that may leave the PDF
    (work / "d.html").write_text(doc, encoding="utf-8")
    chromium = browser.chromium()
    assert chromium
    with Browser(chromium) as b:
        b.open((work / "d.html").resolve().as_uri(), 800, 1000)
        b.pdf(out, "<span>f</span>", "<span>h</span>")
    absolute = (work / href).resolve().as_uri()
    assert pdf.link_targets(out) == [absolute]  # as Chromium prints it
    assert pdf.relative_links(out, {absolute: href}) == 1
    assert pdf.link_targets(out) == [href]
    assert workbench.PAGE in pdf.pdf_pages(out)[0][1]
