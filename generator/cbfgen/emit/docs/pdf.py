"""`make docs-pdf`: the published document as one PDF, printed by headless Chromium.

The PDF holds what the site holds: 300071 rev N (the reference page, its
front matter, sections 1 to 7 and appendices), the CUT companion document,
every command page, the changes between versions, the index of fields and
checks, the golden case index and every golden case page. Links between them
become links inside the PDF; a link to anything the PDF does not hold (a
repository file) becomes plain text, and the pages' navigation lines are left
out. Each page carries 300071's frame from `meta`: a header with the title,
document type, part number and revision, a footer with the owner, the
proprietary marking and "page N of M".

The text flows: a new page starts only where a part starts (the contents,
section 1, the appendices, the companion document, the command pages, the
changes, the field index, the golden cases), never after each short section,
so no page is left mostly blank by a forced break. Tables of up to a page
(table 5.1) are not split. The contents' page numbers come from the PDF's own
outline (Chromium writes one destination per heading): the document is
printed with placeholder numbers of the same width, the outline read, the
contents filled in and the document printed again. The check then reads the
final PDF (pypdf): its outline must put every chapter on the page the contents
give, and the first chapters' titles must be on those pages' text. It also reads
the words' boxes of every page (pdftotext -bbox, poppler-utils): a page whose
text ends above half its body, other than a part's last page, fails (left
mostly blank); so does a site page's navigation line found in the text, and a
link of the printed document to anything it does not hold.

    python -m cbfgen.emit.docs.pdf --out build/docs-pdf/cbf-reference.pdf
"""

from __future__ import annotations

import argparse
import html
import os
import posixpath
import re
import shutil
import subprocess
import sys
import unicodedata
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pypdf import PdfReader

from ...loader import load
from ...model import Spec
from . import CUT_PAGE, FIELD_INDEX, GOLDEN_INDEX, case_page, command_page, context, emit, figures
from .browser import chromium
from .cdp import MARGIN_BOTTOM, MARGIN_TOP, Browser, CdpError
from .site import Imports, _markdown, to_html

STYLE = """
@page { size: A4; }
body { font: 10pt/1.4 "DejaVu Sans", sans-serif; color: #111; margin: 0; }
h1 { font-size: 17pt; } h2 { font-size: 14pt; } h3 { font-size: 12pt; } h4 { font-size: 10.5pt; }
h1, h2, h3, h4 { break-after: avoid; overflow-wrap: anywhere; }
.part { break-before: page; }
table { border-collapse: collapse; margin: 0.5em 0; width: 100%; font-size: 8pt; }
th, td { border: 1px solid #999; padding: 2px 4px; vertical-align: top; text-align: left; overflow-wrap: anywhere; }
th { background: #eee; }
tr, img, svg, .toc li, blockquote { break-inside: avoid; }
table.one-page { break-inside: avoid; font-size: 7.5pt; }
table.one-page td:nth-child(-n+4), table.one-page th:nth-child(-n+4) { white-space: nowrap; overflow-wrap: normal; }
caption { text-align: left; font-size: 9pt; padding: 0.3em 0; }
img { max-width: 100%; height: auto; }
code { font: 8pt "DejaVu Sans Mono", monospace; overflow-wrap: break-word; }
pre { white-space: pre-wrap; background: #f6f6f6; border: 1px solid #ccc; padding: 4px; font-size: 6.5pt; }
pre code { font-size: 6.5pt; }
blockquote { margin: 0.4em 0; padding: 0.1em 0.6em; border-left: 2px solid #99a; background: #f6f7fa; }
details > summary { display: none; }
a { color: inherit; text-decoration: none; }
.toc ol { list-style: none; padding: 0; margin: 0; } .toc li { display: flex; gap: 0.5em; font-size: 9pt; }
.toc li.sub { padding-left: 1.5em; font-size: 8pt; }
.toc li .dots { flex: 1; border-bottom: 1px dotted #999; margin-bottom: 0.3em; }
"""
# A table's caption as the document writes it ("Table 5.1: ..."): the PDF makes it the table's <caption>, and a
# page whose text opens with one starts a table (blank_pages).
_CAPTION = re.compile(r"Table [0-9.]+:")
FRAME = "font-size:7.5px;width:100%;margin:0 0.6in;display:flex;justify-content:space-between;color:#444"
HEADER = '<div style="{style}"><span>{title}</span><span>{kind}</span><span>{part}</span></div>'
FOOTER = ('<div style="{style}"><span>{owner}</span><span>{mark}</span>'
          '<span>page <span class="pageNumber"></span> of <span class="totalPages"></span></span></div>')
PLACEHOLDER = "000"  # the width of a page number while the pages are not yet known


@dataclass(frozen=True)
class Chapter:
    title: str
    anchor: str
    body: str
    part: bool  # starts on a new page
    level: int = 1  # 1: listed in the contents; 2: listed indented
    nav: str = ""  # the text of the site page's "Spec" line and navigation line, which the PDF must not print


@dataclass(frozen=True)
class Page:
    """One page of the site as the PDF holds it: its path in the site, its prefix for ids, its HTML."""

    path: str
    pid: str
    html: str


def _pid(path: str) -> str:
    return "" if path == "index.html" else re.sub(r"[^a-z0-9]+", "-", path[:-5].lower()).strip("-")


def _text(fragment: str) -> str:
    return " ".join(html.unescape(re.sub("<[^>]+>", "", fragment)).split())


# A site page's navigation line: the paragraph of links joined by " · " after its "Spec ... · toolkit ..."
# line (a page's first paragraph of links may be an anchor before its h1)
_NAV = re.compile(r"(<p>Spec [^<]*</p>\n)<p>(?:<a [^>]*>[^<]*</a>(?: · )?)+</p>\n?")
# What the check looks for in the PDF's text: the "Spec" line and the links the next paragraph starts with
# (found more loosely than _NAV, so a line _NAV leaves in is seen)
_LEAD = re.compile(r"<p>(Spec [^<]*)</p>\n<p>((?:<a [^>]*>[^<]*</a>[\s·]*)+)")


def _repository_file(target: str) -> str:
    """The repository file a site page under files/ copies (site.imported's inverse), else ""."""
    if not target.startswith("files/") or not target.endswith(".html"):
        return ""
    rel = target[len("files/"):-len(".html")]
    return rel if "." in posixpath.basename(rel) else rel + ".md"


def _localise(page: Page, held: dict[str, str]) -> str:
    """A page's HTML inside the one document: ids prefixed with the page's id, links to held pages as
    links inside the PDF, links to anything else as plain text, the navigation line left out."""
    body = _NAV.sub(r"\1", page.html, count=1) if page.pid else page.html
    prefix = f"{page.pid}-" if page.pid else ""
    body = re.sub(r'id="([^"]+)"', lambda m: f'id="{prefix}{m.group(1)}"', body)

    def link(m: re.Match[str]) -> str:
        href = html.unescape(m.group(1))
        path, _, frag = href.partition("#")
        if not path:
            return f'<a href="#{prefix}{frag}">' if frag else "<a>"
        if "://" in path or path.startswith("mailto:"):
            return "<a>"
        target = posixpath.normpath(posixpath.join(posixpath.dirname(page.path), path))
        if target not in held:
            return f'<a data-file="{html.escape(_repository_file(target))}">'
        pid = held[target]
        return f'<a href="#{(pid + "-" + frag) if pid and frag else frag or pid or "top"}">'
    body = re.sub(r'<a href="([^"]*)">', link, body)

    def unheld(m: re.Match[str]) -> str:  # a file the PDF does not hold: named where the label does not
        file, label = html.unescape(m.group(1)), m.group(2)
        return label if not file or file in _text(label) else f"{label} (<code>{html.escape(file)}</code>)"
    body = re.sub(r'<a data-file="([^"]*)">(.*?)</a>', unheld, body, flags=re.S)
    body = re.sub(r'src="(?:\.\./)*svg/', 'src="svg/', body)
    first_row = "<table>\n<thead>\n<tr>\n<th>Ver#</th>"  # table 5.1: one page
    body = body.replace(first_row, first_row.replace("<table>", '<table class="one-page">'))
    # "Table N: ..." before its table becomes the table's caption, so the two stay on one page
    return re.sub(r'<p>((?:<a id="[^"]*"></a>\s*)?)(' + _CAPTION.pattern + r'[^<]*)</p>\n(<table[^>]*>)',
                  r"\1\3<caption>\2</caption>", body)


class Unplaced(ValueError):
    """A page of the site that the PDF's order does not name."""


def site_pages(spec: Spec) -> list[tuple[str, str]]:
    """(site path, Markdown) of every page the PDF holds, in its order."""
    ctx = context(spec)
    files = emit(spec, ctx)
    order = ["index.md", CUT_PAGE, *(command_page(c) for c in spec.commands), "changes.md", FIELD_INDEX,
             GOLDEN_INDEX, *(case_page(c.name) for c in ctx["cases"])]
    unplaced = sorted(rel[len("docs/"):] for rel in files if rel.endswith(".md") and rel[len("docs/"):] not in order)
    if unplaced:  # the PDF holds every page of the site (the gallery, made apart from the spec, aside)
        raise Unplaced(f"pages of the site the PDF does not place: {', '.join(unplaced)} (pdf.site_pages)")
    return [(rel[:-3] + ".html", files[f"docs/{rel}"].decode()) for rel in order]


def chapters(spec: Spec) -> list[Chapter]:
    """The reference page in parts (front matter, then one chapter a section), then one chapter a page."""
    md = _markdown()
    imports = Imports()
    rendered = [(path, to_html(md, text, path, imports)[1]) for path, text in site_pages(spec)]
    held = {path: _pid(path) for path, _ in rendered}
    out: list[Chapter] = []
    first_command = command_page(spec.commands[0])[:-3] + ".html"
    golden_index = GOLDEN_INDEX[:-3] + ".html"
    for path, body in rendered:
        local = _localise(Page(path, held[path], body), held)
        if path != "index.html":
            h1 = re.search(r"<h1[^>]*>(.*?)</h1>", local, re.S)
            title = _text(h1.group(1)) if h1 else path
            command = path.startswith("commands/")
            case = path.startswith("golden/") and path != golden_index
            # a new page for each part; the command pages and the cases flow one after the other
            part = not (command and path != first_command) and not case and path != golden_index
            lead = _LEAD.search(body)
            nav = _text(lead.group(1) + " " + lead.group(2)) if lead else ""
            out.append(Chapter(title, held[path], f'<a id="{held[path]}"></a>{local}', part,
                               level=2 if command or case else 1, nav=nav))
            continue
        parts = re.split(r"(?=<h2>)", local)
        head = parts[0]
        h1 = re.search(r"<h1>(.*?)</h1>", head)
        out.append(Chapter(_text(h1.group(1)) if h1 else "Reference", "top", f'<a id="top"></a>{head}', False))
        for section in parts[1:]:
            h2 = re.match(r"<h2>(.*?)</h2>", section)
            name = _text(h2.group(1)) if h2 else "Section"
            if name == "Contents":
                continue  # the PDF has its own contents, with page numbers
            starts_part = bool(re.match(r"1\b", name)) or name.startswith("Appendix A")
            out.append(Chapter(name, f"ch-{len(out)}", f'<a id="ch-{len(out)}"></a>{section}', starts_part))
    return out


def _toc_title(spec: Spec) -> str:
    return f"Contents of {spec.meta['part_number']} rev {spec.meta['revision']}"


def _toc(spec: Spec, chs: list[Chapter], starts: list[str]) -> str:
    items = "".join(
        f'<li class="{"sub" if c.level == 2 else "top"}"><a href="#{c.anchor}">{html.escape(c.title)}</a>'
        f'<span class="dots"></span><span>{s}</span></li>' for c, s in zip(chs, starts, strict=True))
    return f'<section class="toc part"><h2>{html.escape(_toc_title(spec))}</h2><ol>{items}</ol></section>'


def _doc(title: str, body: str) -> str:
    return (f'<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>{html.escape(title)}</title>'
            f"<style>{STYLE}</style></head><body>{body}</body></html>\n")


def _norm(text: str) -> str:
    """Text as extracted from a PDF compares: ligatures undone (NFKC), whitespace collapsed."""
    return " ".join(unicodedata.normalize("NFKC", text).split())


def _key(text: str) -> str:
    """A title as the outline compares: Chromium drops the space where a heading wraps."""
    return "".join(unicodedata.normalize("NFKC", text).split())


def outline_pages(reader: PdfReader) -> list[tuple[str, int]]:
    """(title, page number from 1) of every entry of the PDF's outline, in document order."""
    out: list[tuple[str, int]] = []

    def walk(items: Any) -> None:
        for item in items:
            if isinstance(item, list):
                walk(item)
            else:
                page = reader.get_destination_page_number(item)
                if page is not None:
                    out.append((_key(str(item.title)), page + 1))
    walk(reader.outline)
    return out


def chapter_pages(titles: list[str], outline: list[tuple[str, int]]) -> list[int | None]:
    """The page each chapter starts on: its title's next entry in the outline, in order."""
    pages: list[int | None] = []
    k = 0
    for title in titles:
        want = _key(title)
        j = next((j for j in range(k, len(outline)) if outline[j][0] == want), None)
        if j is None:
            pages.append(None)
            continue
        pages.append(outline[j][1])
        k = j + 1
    return pages


def frame(spec: Spec, version: str) -> tuple[str, str]:
    """The page header and footer: 300071's frame from meta."""
    m = spec.meta
    esc = html.escape
    header = HEADER.format(style=FRAME, title=esc(f"{m['document']}: {m['title']}"),
                           kind=esc(f"Document type: {m['document_type']}"),
                           part=esc(f"Part No: {m['part_number']} · Revision: {m['revision']}"))
    footer = FOOTER.format(style=FRAME, owner=esc(m["owner"]),
                           mark=esc(f"Proprietary: see the notice on page 1 · cbfgen {version}"))
    return header, footer


WORKBENCH_CLASS = "workbench-link"


def workbench_note(href: str) -> str:
    """The front matter's link to the site's workbench page (issue 34): the one link that leaves the PDF."""
    return (f'<p class="{WORKBENCH_CLASS}">Check a cut file in the browser, with nothing installed: the site\'s '
            f'workbench page (<a href="{html.escape(href)}">{html.escape(posixpath.basename(href))}</a>).</p>')


def relative_links(pdf: Path, links: dict[str, str]) -> int:
    """Rewrite the PDF's link targets named in links (absolute URI -> relative one): Chromium prints every
    link absolute, a reader's copy of the build folder keeps the PDF and the site side by side. The count."""
    from pypdf import PdfWriter
    from pypdf.generic import NameObject, TextStringObject

    writer = PdfWriter(clone_from=str(pdf))
    n = 0
    for page in writer.pages:
        for ref in page.get("/Annots") or []:
            action = ref.get_object().get("/A")
            if action is not None and str(action.get_object().get("/URI", "")) in links:
                act = action.get_object()
                act[NameObject("/URI")] = TextStringObject(links[str(act["/URI"])])
                n += 1
    tmp = pdf.with_suffix(".pdf.tmp")
    with tmp.open("wb") as fh:
        writer.write(fh)
    tmp.replace(pdf)
    return n


def link_targets(pdf: Path) -> list[str]:
    """Every URI a link of the PDF opens (a link inside it is a destination, not a URI)."""
    out = []
    for page in PdfReader(str(pdf)).pages:
        for ref in page.get("/Annots") or []:
            action = ref.get_object().get("/A")
            if action is not None and "/URI" in action.get_object():
                out.append(str(action.get_object()["/URI"]))
    return out


def build(spec: Spec, browser_path: str, out: Path, version: str,
          workbench: Path | None = None) -> tuple[int, list[str]]:
    """Print the document to out; (page count, problems found by the check). workbench: the site's
    workbench page, linked from the front matter by its path relative to out's folder."""
    work = out.parent / "work"
    shutil.rmtree(work, ignore_errors=True)
    (work / "svg").mkdir(parents=True)
    for rel, text in figures(spec).items():
        (work / rel).write_text(text, encoding="utf-8")
    chs = chapters(spec)
    header, footer = frame(spec, version)
    href = "" if workbench is None else Path(os.path.relpath(workbench.resolve(), out.resolve().parent)).as_posix()

    def document(starts: list[str]) -> str:
        first, rest = chs[0], chs[1:]
        # the front matter and the first chapters (revision history, how to read) precede the contents
        lead = [first, *[c for c in rest if not c.part][:2]] if rest else [first]
        note = "" if workbench is None else workbench_note(href)
        body = note + "".join(c.body for c in lead) + _toc(spec, chs, starts) + "".join(
            f'<section class="{"part" if c.part else "flow"}">{c.body}</section>' for c in chs if c not in lead)
        return _doc(f"{spec.meta['part_number']} rev {spec.meta['revision']}", body)

    with Browser(browser_path) as b:
        def print_(name: str, doc: str) -> Path:
            page = work / f"{name}.html"
            page.write_text(doc, encoding="utf-8")
            b.open(page.resolve().as_uri(), 800, 1000)
            pdf = work / f"{name}.pdf"
            b.pdf(pdf, footer, header)
            return pdf

        draft = PdfReader(str(print_("draft", document([PLACEHOLDER] * len(chs)))))
        found = chapter_pages([c.title for c in chs], outline_pages(draft))
        starts = [str(p) if p is not None else "?" for p in found]
        final_doc = document(starts)
        final = print_("document", final_doc)
    shutil.copyfile(final, out)
    problems: list[str] = []
    if workbench is not None:  # Chromium printed it absolute, against the work folder
        absolute = (work / href).resolve().as_uri()
        if relative_links(out, {absolute: href}) != 1 or href not in link_targets(out):
            problems.append(f"{out.name}: no link to the workbench page {href}")
    reader = PdfReader(str(out))
    outline = outline_pages(reader)
    problems += verify(out.name, [c.title for c in chs], starts, outline, PageTexts(reader))
    problems += [f"{out.name}: {p}" for p in dangling(final_doc, href)]
    # the pages a part starts on (the contents, and each chapter that starts a new page)
    toc = chapter_pages([_toc_title(spec)], outline)
    part_starts = {p for c, p in zip([None, *chs], [*toc, *chapter_pages([c.title for c in chs], outline)],
                                     strict=True) if p is not None and (c is None or c.part)}
    pages = pdf_pages(out)
    tables = frozenset(n for n, (_, text) in enumerate(pages, 1) if _CAPTION.match(text))
    problems += [f"{out.name}: {p}" for p in blank_pages([fill for fill, _ in pages], part_starts, tables)]
    problems += [f"{out.name}: {p}" for p in navigation_printed([c.nav for c in chs], [t for _, t in pages])]
    return len(reader.pages), problems


def navigation_printed(navs: list[str], texts: list[str]) -> list[str]:
    """Every navigation line of the site's pages (given with the line before it) that the PDF's text holds
    (dead text on paper)."""
    text = _key(" ".join(texts))
    return [f"the site's navigation line '{nav}' is printed" for nav in sorted(set(navs)) if nav and _key(nav) in text]


BLANK = 0.5  # a page whose text ends above this fraction of its body's height is mostly blank
_PAGE = re.compile(r'<page width="[^"]*" height="([^"]*)">(.*?)</page>', re.S)
_WORD = re.compile(r'<word xMin="[^"]*" yMin="([^"]*)" xMax="[^"]*" yMax="([^"]*)">([^<]*)</word>')


def pdf_pages(pdf: Path) -> list[tuple[float, str]]:
    """(fill, text) of every page of a PDF printed by Browser.pdf: how far down the page's body (between
    the header's and the footer's bands) its lowest word reaches, 0 to 1, and the body's words; from
    pdftotext -bbox (poppler-utils), one call for the whole document."""
    tool = shutil.which("pdftotext")
    if tool is None:
        raise FileNotFoundError("pdftotext not found (poppler-utils: CBF_WANT_CHROMIUM=1 .ci/setup-debian.sh "
                                "installs it)")
    run = subprocess.run([tool, "-bbox", str(pdf), "-"], capture_output=True, text=True, check=True, timeout=300)
    out = []
    top = MARGIN_TOP * 72  # PDF points
    for page in _PAGE.finditer(run.stdout):
        bottom = float(page.group(1)) - MARGIN_BOTTOM * 72
        body = [(float(y1), html.unescape(w)) for y0, y1, w in _WORD.findall(page.group(2))
                if float(y0) >= top - 1 and float(y1) <= bottom + 1]
        fill = (max(y for y, _ in body) - top) / (bottom - top) if body else 0.0
        out.append((fill, " ".join(w for _, w in body)))
    return out


def blank_pages(fills: list[float], part_starts: set[int], table_starts: frozenset[int] = frozenset()) -> list[str]:
    """Every page left mostly blank that is not the last page of a part (the page before a part starts,
    and the document's last page, may end anywhere) nor the page before one that opens with a table's
    caption (table_starts: a table kept on one page, such as table 5.1, moved whole to the next page when
    the rest of this one could not hold it: a revision's longer command table)."""
    lasts = {p - 1 for p in part_starts} | {p - 1 for p in table_starts} | {len(fills)}
    return [f"page {n} is mostly blank (its text ends {fill:.0%} down the page) and no part ends there"
            for n, fill in enumerate(fills, 1) if fill < BLANK and n not in lasts]


_HREF = re.compile(r'<a [^>]*href="([^"]*)"')
_ID = re.compile(r'\sid="([^"]+)"')


def dangling(doc: str, workbench: str = "") -> list[str]:
    """Every link of the printed document that leaves it or names no id of it: the PDF refers only to
    what it holds, and to the site's workbench page (workbench: its href)."""
    ids = set(_ID.findall(doc))
    return [f"link to {href!r}, which the PDF does not hold" for href in _HREF.findall(doc)
            if (not href.startswith("#") or html.unescape(href[1:]) not in ids)
            and not (workbench and html.unescape(href) == workbench)]


TEXT_CHECKED = 12  # chapters whose title is also looked for in their page's text (extraction is slow)


def verify(name: str, titles: list[str], starts: list[str], outline: list[tuple[str, int]],
           texts: Sequence[str]) -> list[str]:
    """The contents against the PDF: every chapter in the outline on the page the contents give, and
    the first chapters' titles in those pages' text."""
    problems = []
    pages = chapter_pages(titles, outline)
    for title, s, p in zip(titles, starts, pages, strict=True):
        if p is None or str(p) != s:
            problems.append(f"{name}: '{title}' is on page {p}, the contents say {s}")
        elif titles.index(title) < TEXT_CHECKED and _norm(title)[:30] not in _norm(texts[p - 1]):
            problems.append(f"{name}: '{title}' is not in the text of page {p}")
    return problems


class PageTexts(Sequence[str]):
    """The text of a PDF's pages, each extracted when first read."""

    def __init__(self, reader: PdfReader) -> None:
        self._pages = reader.pages
        self._texts: dict[int, str] = {}

    def __len__(self) -> int:
        return len(self._pages)

    def __getitem__(self, index: int) -> str:  # type: ignore[override]
        if index not in self._texts:
            self._texts[index] = self._pages[index].extract_text() or ""
        return self._texts[index]


def main(argv: list[str] | None = None) -> int:
    from ... import __version__

    ap = argparse.ArgumentParser(prog="cbf-docs-pdf", description="Print the published document to one PDF.")
    ap.add_argument("--spec", default="spec/cbf.yaml")
    ap.add_argument("--out", default="build/docs-pdf/cbf-reference.pdf")
    ap.add_argument("--workbench", type=Path, help="the site's workbench page, linked from the front matter")
    args = ap.parse_args(argv)
    browser = chromium()
    if browser is None:
        print("docs-pdf: chromium not found (CBF_WANT_CHROMIUM=1 .ci/setup-debian.sh installs it)", file=sys.stderr)
        return 2
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    try:
        pages, problems = build(load(args.spec), browser, out, __version__, args.workbench)
    except CdpError as exc:
        print(f"docs-pdf: chromium: {exc}", file=sys.stderr)
        return 1
    except (FileNotFoundError, Unplaced) as exc:
        print(f"docs-pdf: {exc}", file=sys.stderr)
        return 2 if isinstance(exc, FileNotFoundError) else 1
    for p in problems:
        print(f"docs-pdf: {p}", file=sys.stderr)
    if problems:
        return 1
    print(f"docs-pdf: {out} ({pages} pages, each chapter on the page the contents give, none mostly blank "
          "but a part's last, no navigation line, every link inside it)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
