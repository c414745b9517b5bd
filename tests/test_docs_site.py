"""The documentation as a site: Markdown pages, SVG figures and the HTML built by `make docs`.

The pages are taken from the emitter (what `make generate` would write) and
the HTML is built into a temporary folder, so these tests judge the generator,
not a previous build. The link checkers are themselves tested on broken pages.
"""

from __future__ import annotations

import functools
import json
import posixpath
import re
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import html5lib  # type: ignore[import-untyped]
import pytest
from conftest import generate, spec_with_fixture_command
from markdown_it import MarkdownIt
from markdown_it.token import Token

import cbfgen.emit.docs as docs
from cbfgen.emit.docs import golden, site, site_links
from cbfgen.emit.docs.site import SEARCH_PAGE, search_documents
from cbfgen.loader import load
from cbfgen.model import Spec

REPO = Path(__file__).resolve().parents[1]
SPEC = load(REPO / "spec" / "cbf.yaml")
DOCS = REPO / "generated" / "docs"
ANCHOR = re.compile(r'<a id="([^"]+)"></a>')
CASES = golden.load_cases(docs.GOLDEN)


# -- helpers ---------------------------------------------------------------------

@functools.cache
def _emitted() -> dict[str, bytes]:
    """docs.emit(SPEC), made once per module (about 0.27 CPU s a call): the tests only read it.
    test_pages_and_figures_are_deterministic compares it with a call of its own."""
    return docs.emit(SPEC)


def _md_pages(spec: Spec) -> dict[str, str]:
    """The Markdown pages of the emitter, by path relative to the docs folder."""
    emitted = _emitted() if spec is SPEC else docs.emit(spec)
    return {rel[len("docs/"):]: data.decode() for rel, data in emitted.items() if rel.endswith(".md")}


def _md_links(text: str) -> list[str]:
    out: list[str] = []

    def walk(tokens: list[Token]) -> None:
        for tok in tokens:
            for attr in ("href", "src"):
                value = tok.attrs.get(attr)
                if isinstance(value, str):
                    out.append(value)
            if tok.children:
                walk(tok.children)

    walk(MarkdownIt("commonmark", {"html": True}).enable("table").parse(text))
    return out


def _external(href: str) -> bool:
    return "://" in href or href.startswith("mailto:")


def md_problems(pages: dict[str, str], files: set[str], root: Path) -> list[str]:
    """Every Markdown link or image that does not resolve (file, then anchor)."""
    anchors = {page: set(ANCHOR.findall(text)) for page, text in pages.items()}
    problems = []
    for page, text in pages.items():
        for href in _md_links(text):
            if _external(href):
                continue
            path, _, frag = href.partition("#")
            target = posixpath.normpath(posixpath.join(posixpath.dirname(page), path)) if path else page
            if target.startswith("../"):
                if not (root / posixpath.dirname(page) / path).resolve().exists():
                    problems.append(f"{page}: {href}: no such file")
            elif target not in pages and target not in files:
                problems.append(f"{page}: {href}: no such page")
            elif frag and frag not in anchors.get(target, set()):
                problems.append(f"{page}: {href}: no such anchor")
    return problems


def parse_html(text: str) -> ET.Element:
    """Parse with html5lib in strict mode: any parse error raises."""
    parser = html5lib.HTMLParser(strict=True, namespaceHTMLElements=False)
    tree: ET.Element = parser.parse(text)
    return tree


@functools.cache
def _parsed_page(path: Path) -> ET.Element:
    """parse_html of a page of the module's html_site, once per module (the 161 pages take about
    1.3 CPU s): the tests only read the trees. A parse error is not cached, so it raises again in
    every test that reads the page."""
    return parse_html(path.read_text(encoding="utf-8"))


def _ids(tree: ET.Element) -> list[str]:
    return [el.attrib["id"] for el in tree.iter() if "id" in el.attrib]


def html_problems(out: Path) -> list[str]:
    """The site's own link checker (make docs-check runs it): links resolve, none leaves the site."""
    return site_links.problems(out)


def _text(tree: ET.Element) -> str:
    return " ".join("".join(tree.itertext()).split())


# -- Markdown --------------------------------------------------------------------

def test_every_markdown_link_and_anchor_resolves() -> None:
    pages = _md_pages(SPEC)
    files = {rel[len("docs/"):] for rel in _emitted()}
    # the reference, the changes, the CUT companion, a page per command, the golden index, a page per case,
    # the field index
    assert len(pages) == 3 + len(SPEC.commands) + 1 + len(CASES) + 1
    assert sum(len(_md_links(t)) for t in pages.values()) > 100
    assert md_problems(pages, files, DOCS) == []


def test_markdown_link_checker_finds_broken_links() -> None:
    pages = {"index.md": '<a id="here"></a>\n[a](#here) [b](#gone) [c](commands/none.md) [d](../../no/such.file)\n'
                         "![e](svg/none.svg)\n"}
    problems = md_problems(pages, set(), DOCS)
    assert len(problems) == 4, problems


def test_every_page_and_figure_is_in_generated() -> None:
    for rel in _emitted():
        path = REPO / "generated" / rel
        assert path.exists(), f"{rel} is not committed: run make generate"


def test_every_command_and_check_is_in_the_markdown() -> None:
    pages = _md_pages(SPEC)
    index = pages["index.md"]
    for c in SPEC.commands:
        assert f"[{c.name}]({docs.command_page(c)})" in index
        assert f"# {c.name} (0x{c.code:02X})" in pages[docs.command_page(c)]
        for lay in c.layouts:
            for a in lay.args:
                assert f"`{a.name}`" in pages[docs.command_page(c)], (c.name, a.name)
    for k in SPEC.checks:
        assert re.search(f'<a id="check-{docs._anchor(k.id)}"></a>(Check )?`{re.escape(k.id)}`', index), k.id


def test_markdown_traceability_matrix_lists_every_check() -> None:
    index = _md_pages(SPEC)["index.md"]
    matrix = index[index.index('<a id="traceability-matrix"></a>'):index.index('<a id="reliability"></a>')]
    listed = re.findall(r"^\| \[([^\]]+)\]\(#check-", matrix, re.MULTILINE)
    assert listed == [k.id for k in SPEC.checks]


# -- SVG figures -----------------------------------------------------------------

def test_figures_are_svg_with_every_field() -> None:
    figures = docs.figures(SPEC)
    for h in SPEC.headers.values():
        text = figures[docs.header_svg(h.id)]
        root = ET.fromstring(text.encode())
        assert root.tag == "{http://www.w3.org/2000/svg}svg"
        for f in h.fields:
            assert f"{f.name}: offset {f.offset}, {f.size} bytes" in text, (h.id, f.name)
        # one box per byte row a field touches; their widths add up to the layout size
        widths = [float(r.attrib["width"]) for g in root.iter("{http://www.w3.org/2000/svg}g")
                  for r in g.iter("{http://www.w3.org/2000/svg}rect")]
        assert sum(widths) == h.size * 46
    for f in SPEC.record.fields:
        assert f"{f.name}: offset {f.offset}, {f.size} bytes" in figures[docs.RECORD_SVG]
    for c in SPEC.commands:
        for lay in c.layouts:
            if lay.args:
                ET.fromstring(figures[docs.layout_svg(lay)].encode())
    assert docs.MOTION_SVG in figures


def test_pages_and_figures_are_deterministic() -> None:
    assert docs.emit(SPEC) == _emitted()  # two calls: the module's first one and this one
    pages = _md_pages(SPEC)
    assert not re.search(r"\b20\d\d-\d\d-\d\dT\d\d:", "".join(pages.values()))


# -- HTML ------------------------------------------------------------------------

def test_html_parses_without_errors(html_site: Path) -> None:
    pages = sorted(html_site.rglob("*.html"))
    own = [p for p in pages if "files" not in p.relative_to(html_site).parts]
    assert len(own) == 6 + len(SPEC.commands) + len(CASES)  # the search page too
    for p in pages:
        _parsed_page(p)


def test_html_parser_is_strict() -> None:
    with pytest.raises(html5lib.html5parser.ParseError):
        parse_html("<!DOCTYPE html><html><head><title>x</title></head><body><p><table></p></body></html>")


def test_every_html_link_and_anchor_resolves(html_site: Path) -> None:
    assert html_problems(html_site) == []


def test_html_link_checker_finds_broken_links(tmp_path: Path) -> None:
    (tmp_path / "index.html").write_text(
        '<!DOCTYPE html><html><head><title>t</title></head><body><p id="a">x</p><p id="a">y</p>'
        '<a href="#a">ok</a><a href="#gone">1</a><a href="other.html">2</a>'
        '<img src="svg/none.svg" alt=""></body></html>',
        encoding="utf-8")
    assert len(html_problems(tmp_path)) == 4


@pytest.mark.parametrize("href", ["https://example.org/spec", "../../spec/cbf.yaml", "/etc/hosts",
                                  "file:///work/spec/cbf.yaml", "mailto:owner@example.org", "sub/../../x.html"])
def test_link_checker_fails_on_a_link_leaving_the_site(tmp_path: Path, href: str) -> None:
    """A planted link out of the site: the checker names it, although the target may exist."""
    (tmp_path / "index.html").write_text(
        f'<!DOCTYPE html><html><head><title>t</title></head><body><a href="{href}">out</a></body></html>',
        encoding="utf-8")
    problems = html_problems(tmp_path)
    assert problems == [f"index.html: {href}: leaves the site"]


def test_site_works_alone_when_copied(html_site: Path, tmp_path: Path) -> None:
    """The site copied to an empty folder: every link still resolves, the spec and golden README are in it."""
    import shutil

    copy = tmp_path / "moved" / "site"
    shutil.copytree(html_site, copy)
    assert html_problems(copy) == []
    assert (copy / "files" / "spec" / "cbf.yaml").read_bytes() == (REPO / "spec" / "cbf.yaml").read_bytes()
    assert (copy / "files" / "conformance" / "golden" / "README.html").exists()
    index = (copy / "index.html").read_text(encoding="utf-8")
    assert 'href="files/spec/cbf.yaml.html"' in index


def test_html_is_self_contained(html_site: Path) -> None:
    for p in html_site.rglob("*.html"):
        tree = _parsed_page(p)
        scripts = [el.attrib.get("src", "") for el in tree.iter("script")]
        if p.name == SEARCH_PAGE:  # the search page's scripts are files of the site (issue 26)
            assert all((p.parent / s).is_file() for s in scripts if s) and scripts, scripts
            assert all(not _external(s) for s in scripts)
        else:
            assert not scripts, p
        for el in tree.iter():
            if el.tag in ("link", "img", "iframe", "object"):
                ref = el.attrib.get("href") or el.attrib.get("src") or ""
                assert not _external(ref), (p, ref)


def test_search_documents_cover_every_page(html_site: Path) -> None:
    site = {p.relative_to(html_site).as_posix(): p.read_bytes() for p in html_site.rglob("*.html")}
    docs_ = search_documents(site)
    pages = {d["url"].split("#")[0] for d in docs_}
    assert pages == {p for p in site if p != SEARCH_PAGE and not p.startswith("files/")}
    # a check id and a command name are in the text the index is built from
    assert any(SPEC.checks[-1].id in d["text"] for d in docs_)
    assert any(d["title"].startswith(SPEC.commands[-1].name) for d in docs_)
    index = (html_site / "search" / "search-index.js").read_text(encoding="utf-8")
    assert index.startswith("window.CBF_SEARCH_INDEX = ") and '\\"documentCount\\":' in index


def test_search_titles_a_part_without_heading_by_whole_words() -> None:
    """At 390 px the result list showed titles cut inside a word ("CIRCL", "the m") after the page's whole
    title, which the result already shows beside it."""
    body = ("<html><head><title>Page T · x</title></head><body><main><a id=\"n9\"></a><p>" + "N9 Version 4.0 forbids "
            "ARC, ARC5B, CIRCLE, CIRCLE5B, HELIX and HELIX5B in every file</p><footer></footer></main></body></html>")
    docs_ = search_documents({"p.html": body.encode()})
    title = next(d["title"] for d in docs_ if d["url"] == "p.html#n9")
    assert title == "N9 Version 4.0 forbids ARC, ARC5B, CIRCLE, CIRCLE5B, HELIX …", title
    assert all(w in body for w in title[:-2].split())


def test_a_long_title_wraps_at_a_dot_or_underscore_and_a_date_cell_not_at_all() -> None:
    """At 390 px a golden case's h1 broke inside a word ("helix_ra / w_normal") and a date column broke
    "2027-01-15" after a hyphen; the title text, the page's <title> and links stay as they were."""
    from cbfgen.emit.docs.site import Imports, _markdown, to_html

    title, body = to_html(_markdown(), "# Golden case check.6.4.5.helix_raw\n\n| d |\n|---|\n| 2027-01-15 |\n",
                          "golden/x.html", Imports())
    assert title == "Golden case check.6.4.5.helix_raw"
    assert "<h1>Golden case check.6.4.5.<wbr>helix_<wbr>raw</h1>" in body
    assert '<td style="white-space: nowrap">2027-01-15</td>' in body


def test_every_command_and_check_is_in_the_html(html_site: Path) -> None:
    index = _parsed_page(html_site / "index.html")
    text = _text(index)
    ids = set(_ids(index))
    for c in SPEC.commands:
        assert c.name in text
        page = _parsed_page(html_site / (docs.command_page(c)[:-3] + ".html"))
        h1 = next(page.iter("h1"))
        assert "".join(h1.itertext()) == f"{c.name} (0x{c.code:02X})"
    for k in SPEC.checks:
        assert k.id in text and f"check-{docs._anchor(k.id)}" in ids


def test_html_traceability_matrix_lists_every_check(html_site: Path) -> None:
    index = _parsed_page(html_site / "index.html")
    seen = False
    listed: list[str] = []
    for el in index.find("body").iter():  # type: ignore[union-attr]
        if el.tag in ("h2", "h3"):
            seen = "".join(el.itertext()) == "Traceability matrix"
        elif seen and el.tag == "tr":
            cells = list(el)
            if cells and cells[0].tag == "td":
                listed.append("".join(cells[0].itertext()))
    assert listed == [k.id for k in SPEC.checks]


# -- a new command in the spec ----------------------------------------------------

def test_new_command_appears_in_markdown_and_html(tmp_path: Path) -> None:
    spec_path = spec_with_fixture_command(tmp_path)
    generate(spec_path, tmp_path / "gen", "docs")
    spec = load(spec_path)
    gen = tmp_path / "gen" / "docs"
    pages = {p.relative_to(gen).as_posix(): p.read_text(encoding="utf-8") for p in gen.rglob("*.md")}
    assert "# DWELL (0x44)" in pages["commands/dwell.md"] and "`seconds`" in pages["commands/dwell.md"]
    assert "[DWELL](commands/dwell.md)" in pages["index.md"]
    files = {p.relative_to(gen).as_posix() for p in gen.rglob("*")}
    assert md_problems(pages, files, DOCS) == []
    out = tmp_path / "html"
    site.build(spec, out)
    index = _text(parse_html((out / "index.html").read_text(encoding="utf-8")))
    page = _text(parse_html((out / "commands" / "dwell.html").read_text(encoding="utf-8")))
    assert "DWELL" in index and "DWELL (0x44)" in page and "seconds" in page
    assert html_problems(out) == []


# -- reliability -------------------------------------------------------------------

RELIABILITY: dict[str, Any] = {
    "corruption": {"c": {"bit_flip": {"trials": 200, "detected": 199,
                                      "misses": [{"file": "a.cbf", "offset": 7, "detail": "flip"}]},
                         "truncation": {"trials": 20000, "detected": 19999, "misses": []}}},
    "blind_spots": {"no_file_checksum": {"bit_flip": {"trials": 80, "detected": 20}}},
    "differential": {"files": 1000, "seed": 1234, "bindings": ["c", "python"], "disagreements": 0},
    "fuzz": {"cbf_fuzz": {"executions": 123456, "seconds": 60.0, "crashes": 0}},
    "mode": "full",
}


def test_reliability_tables(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    path = tmp_path / "reliability.json"
    path.write_text(json.dumps(RELIABILITY), encoding="utf-8")
    monkeypatch.setattr(docs, "RELIABILITY", path)
    text = docs.emit(SPEC)["docs/index.md"].decode()
    assert "| c | bit_flip | 200 | 199 | 99.50 % | 1 |" in text
    assert "| c | truncation | 20000 | 19999 | 99.99 % | 0 |" in text
    assert "| no_file_checksum | bit_flip | 80 | 20 | 25.00 % |" in text
    assert "| 1000 | 1234 | c, python | 0 |" in text
    assert "| cbf_fuzz | 123456 | 60.0 | 0 |" in text
    assert "| c | bit_flip | `a.cbf` | 7 | detail=flip |" in text and "mode `full`" in text
    assert "No reliability report is present" not in text
    out = tmp_path / "html"
    site.build(SPEC, out)
    html = (out / "index.html").read_text(encoding="utf-8")
    assert "<td>99.50 %</td>" in html
    parse_html(html)


def test_missing_reliability_is_said(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.setattr(docs, "RELIABILITY", tmp_path / "absent.json")
    text = docs.emit(SPEC)["docs/index.md"].decode()
    assert "No reliability report is present: no figures are shown (`cbfgen --report FILE`" in text
    assert " %" not in text[text.index('<a id="reliability"></a>'):]


def test_empty_reliability_sections_are_said(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    path = tmp_path / "reliability.json"
    path.write_text("{}\n", encoding="utf-8")
    monkeypatch.setattr(docs, "RELIABILITY", path)
    text = docs.emit(SPEC)["docs/index.md"].decode()
    for what in ("corruption", "blind-spot", "fuzzing"):
        assert f"No {what} results recorded." in text
    assert "No reliability report is present" not in text
