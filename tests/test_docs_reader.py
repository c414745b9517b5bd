"""Issue 34, point 5: the site as a reader found it, measured in headless Chromium (one start for the module).

The reader saw no snippet in the search results, golden cases listed above the
section searched for, byte-field diagrams shrunk to unreadable text and the
approval block as the first screen at 390 px, and the sidebar's background
stopping partway down long pages at 1280 px. Each finding is measured on the
site built from the model (reader.py, which `make docs-check` runs on the
published site too) and on a planted fault, so that each measurement can fail.
The queries and the sections they must find come from the model and the built
pages; screenshots of what is measured are written beside the test's files.
"""

from __future__ import annotations

import json
import re
import shutil
import struct
from collections.abc import Iterator
from pathlib import Path
from urllib.parse import unquote, urlparse

import pytest

from cbfgen.emit.docs import browser as docs_browser
from cbfgen.emit.docs import reader
from cbfgen.emit.docs.cdp import Browser
from cbfgen.emit.docs.site import NARROW_FIGURES, SEARCH_KINDS, search_documents
from cbfgen.loader import load

REPO = Path(__file__).resolve().parents[1]
SPEC = load(REPO / "spec" / "cbf.yaml")
HEAD = '<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>t</title></head><body>'

pytestmark = pytest.mark.skipif(not shutil.which("chromium"), reason="Debian chromium not installed (make docs-check)")


@pytest.fixture(scope="module")
def chromium() -> Iterator[Browser]:
    path = docs_browser.chromium()
    assert path
    with Browser(path) as b:
        yield b


@pytest.fixture(scope="module")
def shots(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("reader-shots")


def _png_size(png: Path) -> tuple[int, int]:
    data = png.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    width, height = struct.unpack(">II", data[16:24])
    return width, height


def _shot(b: Browser, png: Path, width: int, height: int) -> None:
    """A screenshot of what the browser shows at width x height; the file is a PNG of that size."""
    b.screenshot(png)
    assert _png_size(png) == (width, height)


def _documents(site: Path) -> list[dict[str, str]]:
    return search_documents({p.relative_to(site).as_posix(): p.read_bytes() for p in site.rglob("*.html")})


# -- search: snippets, groups, sections first ------------------------------------------------------

def test_every_section_of_the_model_is_found_first_with_a_marked_snippet(html_site: Path, chromium: Browser,
                                                                         shots: Path) -> None:
    queries, missing = reader.ranking_queries(SPEC, _documents(html_site))
    assert missing == []
    titled = [s["title"] for s in SPEC.meta["sections"]]
    titled += [c["title"] for c in SPEC.meta["clauses"] if c.get("title")]
    assert titled
    for title in titled:  # each section and titled clause of the model is searched, as written and singular
        assert reader.bare(title) in queries and reader.singular(reader.bare(title)) in queries, title
    results = reader.search(chromium, html_site, list(queries))
    assert reader.search_problems(results, queries) == []
    # the query that lists the most results lists results of more than one kind, the document's first
    busiest = max(results, key=lambda q: len(results[q]))
    kinds = [h.kind for h in results[busiest]]
    assert kinds[0] == next(iter(SEARCH_KINDS)) and len(set(kinds)) > 1, (busiest, set(kinds))
    for width, height in ((1280, 900), reader.NARROW):
        chromium.open((html_site / "search.html").resolve().as_uri() + "?q=" + busiest, width, height)
        marks = chromium.evaluate("document.querySelectorAll('#search-results li .snippet mark').length")
        assert marks >= len(chromium.evaluate("Array.from(document.querySelectorAll('#search-results li'))"))
        _shot(chromium, shots / f"search-{width}.png", width, height)


def test_search_checker_fails_on_a_missing_snippet_a_mixed_order_and_a_wrong_first_result() -> None:
    document, golden = "document", "golden"
    assert [document, golden] == [k for k in SEARCH_KINDS if k in (document, golden)]
    good = [reader.Hit(document, "index.html#s", "Section", "a word", ("word",)),
            reader.Hit(golden, "golden/x.html", "Golden case x", "the word", ("word",))]
    expected = {"word": {"index.html#s"}}
    assert reader.search_problems({"word": good}, expected) == []
    bare = [reader.Hit(document, "index.html#s", "Section", "a word", ()), good[1]]
    assert any("no snippet" in p for p in reader.search_problems({"word": bare}, expected))
    mixed = [good[1], good[0]]
    found = reader.search_problems({"word": mixed}, expected)
    assert any("not grouped" in p for p in found) and any("first result golden/x.html" in p for p in found)
    assert reader.search_problems({"word": []}, expected) == ["search 'word': no result"]


def test_ranking_queries_come_from_the_model_and_name_a_section_without_its_part() -> None:
    section = SPEC.meta["sections"][0]
    docs = [{"kind": "document", "heading": f"{section['id']} {section['title']}", "url": "index.html#a"},
            {"kind": "golden", "heading": f"Golden case {section['title']}", "url": "golden/a.html"}]
    queries, missing = reader.ranking_queries(SPEC, docs)
    assert queries[reader.bare(section["title"])] == {"index.html#a"}
    # every other section and titled clause of the model is named as missing from this index
    assert len(missing) == len(SPEC.meta["sections"]) - 1 + sum(1 for c in SPEC.meta["clauses"] if c.get("title"))


# -- figures at 390 px ----------------------------------------------------------------------------

def test_figures_keep_readable_text_at_390_px(html_site: Path, chromium: Browser, shots: Path) -> None:
    """The reference page and a command page with a wide diagram (docs-check measures every page): every
    figure is drawn with its smallest text at MIN_FONT_PX or more, its page no wider than the screen."""
    narrow, tall = reader.NARROW
    below = [p for p in sorted(html_site.glob("*/*.html"))  # a page below the top with a wide diagram
             if f'srcset="../{reader.FIGURES}{NARROW_FIGURES}/' in p.read_text(encoding="utf-8")]
    pages = [html_site / "index.html", *below[:1]]
    for page in pages:
        rel = page.relative_to(html_site).as_posix()
        assert docs_browser.check_page(chromium, page, rel, (narrow,)) == []
        figures = json.loads(chromium.evaluate(reader.LAYOUT_PROBE))["figures"]
        assert figures, rel
        for src, shown, natural, _box in figures:
            font = reader.svg_min_font(Path(unquote(urlparse(src).path)))  # the figure's file in the site
            assert font * shown / natural >= reader.MIN_FONT_PX, (rel, src)
        # a byte-field diagram is drawn NARROW_ROW bytes a row there, no wider than the page's column: its
        # box does not scroll (at 8 bytes a row of the wide drawing's bytes it scrolled 74 px)
        narrow_drawn = [f for f in figures if f"/{reader.FIGURES}{NARROW_FIGURES}/" in f[0]]
        assert narrow_drawn, rel
        assert all(0 < natural <= box for _, _, natural, box in narrow_drawn), narrow_drawn
    chromium.open((html_site / "index.html").resolve().as_uri(), narrow, tall)
    chromium.evaluate(f"document.querySelector('img[src*=\"{reader.FIGURES}\"]').scrollIntoView()")
    _shot(chromium, shots / f"figure-{narrow}.png", narrow, tall)


def test_figure_check_fails_on_a_figure_shrunk_to_the_screen(html_site: Path, chromium: Browser,
                                                             tmp_path: Path) -> None:
    figure = next((html_site / reader.FIGURES).glob("*.svg"))
    (tmp_path / reader.FIGURES).mkdir()
    shutil.copy(figure, tmp_path / reader.FIGURES / figure.name)
    (tmp_path / "p.html").write_text(HEAD + f'<img style="max-width:100%" src="{reader.FIGURES}{figure.name}" '
                                     'alt="x"></body></html>', encoding="utf-8")
    problems = docs_browser.check_page(chromium, tmp_path / "p.html", "p.html", (reader.NARROW[0],))
    assert any(f"figure {figure.name} drawn with text of" in p for p in problems), problems


# -- the first screen at 390 px ------------------------------------------------------------------------

def test_first_screen_at_390_px_is_title_and_content(html_site: Path, chromium: Browser, shots: Path) -> None:
    assert reader.first_screen(chromium, html_site / "index.html", "index.html") == []
    _shot(chromium, shots / f"index-{reader.NARROW[0]}.png", *reader.NARROW)
    # the folded frame is one tap away: checked, its title block shows
    chromium.evaluate("document.getElementById('frame-toggle').click()")
    assert chromium.evaluate("document.querySelector('.doc-frame').getBoundingClientRect().height") > 0
    # on a wide screen it is there without a tap, and no button is drawn
    chromium.open((html_site / "index.html").resolve().as_uri(), 1280, 900)
    assert chromium.evaluate("document.querySelector('.doc-frame').getBoundingClientRect().height") > 0
    assert chromium.evaluate("document.querySelector('.frame-button').getBoundingClientRect().height") == 0


def test_first_screen_check_fails_on_a_frame_before_the_content(chromium: Browser, tmp_path: Path) -> None:
    # the frame is taller than any screen whatever the browser's table metrics (30 small tables were
    # 844 px high in one Chromium and less in Chromium 156, which then showed the h2)
    frame = ('<div class="doc-frame">' + "<table><tr><td>approval</td></tr></table>" * 30
             + '<p style="height: 4000px">notice</p></div>')
    (tmp_path / "framed.html").write_text(HEAD + f"<main><h1>T</h1>{frame}<h2>Content</h2></main></body></html>",
                                          encoding="utf-8")
    problems = reader.first_screen(chromium, tmp_path / "framed.html", "framed.html")
    assert any("part(s) of the document's frame" in p for p in problems)
    assert any("no heading of the content" in p for p in problems)
    (tmp_path / "bare.html").write_text(HEAD + "<main><p>text</p></main></body></html>", encoding="utf-8")
    problems = reader.first_screen(chromium, tmp_path / "bare.html", "bare.html")
    assert any("title is not on the first screen" in p for p in problems)
    assert any("no document frame" in p for p in problems)


# -- the sidebar at 1280 px ------------------------------------------------------------------------------

def test_sidebar_spans_the_longest_page_at_1280_px(html_site: Path, chromium: Browser, shots: Path) -> None:
    own = [p for p in html_site.rglob("*.html") if "files" not in p.relative_to(html_site).parts]
    longest = max(own, key=lambda p: p.stat().st_size)
    shortest = min(own, key=lambda p: p.stat().st_size)
    for page, height in ((longest, 900), (shortest, 3000)):  # a short page on a tall screen too
        chromium.open(page.resolve().as_uri(), 1280, height)
        probe = json.loads(chromium.evaluate(reader.LAYOUT_PROBE))
        assert probe["beside"] and probe["page"] >= height
        assert probe["nav"] >= probe["page"] - 1, (page.name, probe["nav"], probe["page"])
        assert reader.layout_problems(page.name, 1280, probe) == []
    chromium.open(longest.resolve().as_uri(), 1280, 900)
    chromium.evaluate("window.scrollTo(0, document.documentElement.scrollHeight)")
    _shot(chromium, shots / "foot-1280.png", 1280, 900)


def test_sidebar_check_fails_on_a_sidebar_that_stops(chromium: Browser, tmp_path: Path) -> None:
    """The layout the reader saw: a sticky sidebar no higher than the screen beside a long text."""
    page = (HEAD + '<div style="display:flex;align-items:flex-start"><nav class="side" style="position:sticky;'
            'top:0;flex:0 0 200px;max-height:100vh;background:#eee"><p style="margin:0">links</p></nav>'
            '<main style="height:5000px">text</main></div></body></html>')
    (tmp_path / "stops.html").write_text(page, encoding="utf-8")
    problems = docs_browser.check_page(chromium, tmp_path / "stops.html", "stops.html", (1280,))
    assert len(problems) == 1 and re.fullmatch(r"stops\.html @1280px: the sidebar is [0-9]{1,3} px high on a page of "
                                               r"50[0-9]{2} px", problems[0]), problems
