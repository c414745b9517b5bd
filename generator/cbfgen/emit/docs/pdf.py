"""`make docs-pdf`: the format reference as one PDF, printed by headless Chromium.

The chapters are the sections of the reference page (one per `##` heading)
and then one per command page, rendered from the same Markdown as the site.
Each chapter starts on a new page, so its length does not depend on what
comes before it: every chapter is printed alone first to count its pages,
the table of contents is written with the page each chapter starts on, and
the whole document is printed with page numbers in the footer. The check
then reads the PDF (pypdf): its page count must be the count the contents
promise, and each chapter's title must be on the page the contents give.
Figures, code blocks and table rows are not split across pages.

    python -m cbfgen.emit.docs.pdf --out build/docs-pdf/cbf-reference.pdf
"""

from __future__ import annotations

import argparse
import html
import re
import shutil
import sys
import unicodedata
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from pypdf import PdfReader

from ...loader import load
from ...model import Spec
from . import command_page, context, emit, figures
from .browser import chromium
from .cdp import Browser, CdpError
from .site import Imports, _markdown, to_html

STYLE = """
@page { size: A4; }
body { font: 10pt/1.4 "DejaVu Sans", sans-serif; color: #111; margin: 0; }
h1 { font-size: 17pt; } h2 { font-size: 14pt; } h3 { font-size: 12pt; }
h1, h2, h3 { break-after: avoid; }
.chapter { break-before: page; }
table { border-collapse: collapse; margin: 0.5em 0; width: 100%; font-size: 8pt; }
th, td { border: 1px solid #999; padding: 2px 4px; vertical-align: top; text-align: left; overflow-wrap: break-word; }
th { background: #eee; }
tr, img, pre, svg, .toc li { break-inside: avoid; }
img { max-width: 100%; height: auto; }
code { font: 8pt "DejaVu Sans Mono", monospace; }
pre { white-space: pre-wrap; background: #f6f6f6; border: 1px solid #ccc; padding: 4px; font-size: 6.5pt; }
pre code { font-size: 6.5pt; }
details > summary { display: none; }
a { color: inherit; text-decoration: none; }
.toc ol { list-style: none; padding: 0; } .toc li { display: flex; gap: 0.5em; }
.toc li .dots { flex: 1; border-bottom: 1px dotted #999; margin-bottom: 0.3em; }
"""
FOOTER = ('<div style="font-size:8px;width:100%;text-align:center;color:#555">'
          '{title} · page <span class="pageNumber"></span> of <span class="totalPages"></span></div>')


@dataclass(frozen=True)
class Chapter:
    title: str
    anchor: str
    body: str


def _doc(title: str, body: str) -> str:
    return (f'<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>{html.escape(title)}</title>'
            f"<style>{STYLE}</style></head><body>{body}</body></html>\n")


def _local_links(body: str, cmd_anchors: dict[str, str]) -> str:
    """Links as the single document needs them: index anchors and command pages inside it, the rest as text."""
    def fix(m: re.Match[str]) -> str:
        href = m.group(1)
        path, _, frag = href.partition("#")
        name = path.rsplit("/", 1)[-1]
        if not path:
            return f'href="#{frag}"'
        if name == "index.html" and frag and "golden" not in path:
            return f'href="#{frag}"'
        if name in cmd_anchors:
            return f'href="#{cmd_anchors[name]}"'
        return 'data-href=""'
    body = re.sub(r'href="([^"]*)"', fix, body)
    return re.sub(r'src="(?:\.\./)*svg/', 'src="svg/', body)


def chapters(spec: Spec) -> list[Chapter]:
    """The reference's sections, then one chapter per command."""
    ctx = context(spec)
    files = emit(spec, ctx)
    md = _markdown()
    imports = Imports()
    cmd_anchors = {command_page(c)[len("commands/"):-3] + ".html": f"cmd-{command_page(c)[9:-3]}"
                   for c in spec.commands}
    _, index = to_html(md, files["docs/index.md"].decode(), "index.html", imports)
    out = []
    parts = re.split(r"(?=<h2>)", index)
    head = parts[0]
    title = re.search(r"<h1>(.*?)</h1>", head)
    out.append(Chapter(html.unescape(re.sub("<[^>]+>", "", title.group(1))) if title else "Reference", "top",
                       _local_links(head, cmd_anchors)))
    for part in parts[1:]:
        h2 = re.match(r"<h2>(.*?)</h2>", part)
        name = html.unescape(re.sub("<[^>]+>", "", h2.group(1))) if h2 else "Section"
        if name == "Contents":
            continue  # the PDF has its own contents, with page numbers
        out.append(Chapter(name, f"ch-{len(out)}", _local_links(part, cmd_anchors)))
    for c in spec.commands:
        page = command_page(c)
        _, body = to_html(md, files[f"docs/{page}"].decode(), page[:-3] + ".html", imports)
        out.append(Chapter(f"{c.name} (0x{c.code:02X})", f"ch-{len(out)}", _local_links(body, cmd_anchors)))
    return out


def _toc(spec: Spec, chs: list[Chapter], starts: list[int], total: int) -> str:
    items = "".join(f'<li><a href="#{c.anchor}">{html.escape(c.title)}</a><span class="dots"></span>'
                    f"<span>{s}</span></li>" for c, s in zip(chs, starts, strict=True))
    return (f'<section class="toc"><h1>{html.escape(spec.meta["title"])}: format reference</h1>'
            f"<p>Spec {html.escape(spec.revision)}. This document has {total} pages.</p>"
            f"<h2>Contents</h2><ol>{items}</ol></section>")


def _norm(text: str) -> str:
    """Text as extracted from a PDF compares: ligatures undone (NFKC), whitespace collapsed."""
    return " ".join(unicodedata.normalize("NFKC", text).split())


def _pages(path: Path) -> int:
    return len(PdfReader(str(path)).pages)


def build(spec: Spec, browser_path: str, out: Path, version: str) -> tuple[int, list[str]]:
    """Print the reference to out; (page count, problems found by the check)."""
    work = out.parent / "work"
    shutil.rmtree(work, ignore_errors=True)
    (work / "svg").mkdir(parents=True)
    for rel, text in figures(spec).items():
        (work / rel).write_text(text, encoding="utf-8")
    chs = chapters(spec)
    footer = FOOTER.format(title=html.escape(f"{spec.meta['title']} · spec {spec.revision} · cbfgen {version}"))
    lengths = []
    with Browser(browser_path) as b:
        def print_(name: str, doc: str) -> Path:
            page = work / f"{name}.html"
            page.write_text(doc, encoding="utf-8")
            b.open(page.resolve().as_uri(), 800, 1000)
            pdf = work / f"{name}.pdf"
            b.pdf(pdf, footer)
            return pdf

        for k, c in enumerate(chs):
            lengths.append(_pages(print_(f"chapter-{k}", _doc(c.title, c.body))))
        toc_pages, starts, total = 1, [0], 0
        for _ in range(5):  # the contents' own length moves every start; stable after a pass or two
            starts = [toc_pages + 1 + sum(lengths[:k]) for k in range(len(chs))]
            total = toc_pages + sum(lengths)
            measured = _pages(print_("toc", _doc("contents", _toc(spec, chs, starts, total))))
            if measured == toc_pages:
                break
            toc_pages = measured
        body = _toc(spec, chs, starts, total) + "".join(
            f'<section class="chapter" id="{c.anchor}">{c.body}</section>' for c in chs)
        final = print_("reference", _doc(f"{spec.meta['title']}: format reference", body))
    shutil.copyfile(final, out)
    texts = PageTexts(PdfReader(str(out)))
    return len(texts), verify(out.name, texts, [(c.title, s) for c, s in zip(chs, starts, strict=True)], total)


class PageTexts(Sequence[str]):
    """The text of a PDF's pages, each extracted when first read: verify reads the pages the contents
    name, and pypdf's extraction of all 74 pages took most of the check's time."""

    def __init__(self, reader: PdfReader) -> None:
        self._pages = reader.pages
        self._texts: dict[int, str] = {}

    def __len__(self) -> int:
        return len(self._pages)

    def __getitem__(self, index: int) -> str:  # type: ignore[override]
        if index not in self._texts:
            self._texts[index] = self._pages[index].extract_text() or ""
        return self._texts[index]


def verify(name: str, texts: Sequence[str], toc: list[tuple[str, int]], total: int) -> list[str]:
    """What the contents promise against the PDF's pages (their text): the page count, and each title
    on its page."""
    if len(texts) != total:
        return [f"{name}: {len(texts)} pages, the contents promise {total}"]
    problems = []
    for title, page in toc:
        if not 1 <= page <= total or _norm(title)[:30] not in _norm(texts[page - 1]):
            problems.append(f"{name}: '{title}' is not on page {page}, where the contents put it")
    return problems


def main(argv: list[str] | None = None) -> int:
    from ... import __version__

    ap = argparse.ArgumentParser(prog="cbf-docs-pdf", description="Print the format reference to one PDF.")
    ap.add_argument("--spec", default="spec/cbf.yaml")
    ap.add_argument("--out", default="build/docs-pdf/cbf-reference.pdf")
    args = ap.parse_args(argv)
    browser = chromium()
    if browser is None:
        print("docs-pdf: chromium not found (CBF_WANT_CHROMIUM=1 .ci/setup-debian.sh installs it)", file=sys.stderr)
        return 2
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    try:
        pages, problems = build(load(args.spec), browser, out, __version__)
    except CdpError as exc:
        print(f"docs-pdf: chromium: {exc}", file=sys.stderr)
        return 1
    for p in problems:
        print(f"docs-pdf: {p}", file=sys.stderr)
    if problems:
        return 1
    print(f"docs-pdf: {out} ({pages} pages, each chapter on the page the contents give)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
