"""The site as a reader finds it (issue 34, point 5), measured in headless Chromium.

What a reader of the published site reported, each as a measurement that
`make docs-check` (browser.py) takes on the built site and tests take on
planted faults:
  - the search lists each result with a snippet of its text in which the
    words that matched are marked, and groups the results by the kind of page
    (the document's sections before the golden cases);
  - searching for the title of a section of the document (a section or a
    titled clause of the model, or any heading of a document page) lists that
    section first, and so does the title with its plurals made singular
    ("checksum" finds the Checksums section first, not one of the golden
    cases that name a checksum check);
  - a figure of the docs (svg/: the byte-field diagrams, the motion figure)
    is drawn with its smallest text at least MIN_FONT_PX on screen, at 390 px
    too (the page scrolls the figure sideways instead of shrinking it);
  - the first screen of the reference page at 390 px shows its title and its
    content, not the document's frame (title block, approvals, notice);
  - where the sidebar stands beside the text, its box spans the page's height.
No expectation names today's prose or sections: the queries and the sections
they must find come from the model and the built pages.
"""

from __future__ import annotations

import json
import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any
from urllib.parse import unquote, urlparse

from ...model import Spec
from .cdp import Browser
from .site import SEARCH_KINDS, SEARCH_PAGE

MIN_FONT_PX = 11.0  # the smallest text of a docs figure on screen, in CSS pixels
NARROW = (390, 844)  # a phone's screen, CSS pixels
FIGURES = "svg/"  # the docs' figures, the folder the emitter writes them to (docs.header_svg, ...)
_FONT = re.compile(r'font-size="([0-9.]+)"')
_NUMBER = re.compile(r"^(?:[0-9]+(?:\.[0-9]+)*|[A-Z][0-9]+)\s+")

# For check_page: the docs' figures and the sidebar, measured at the width the page is shown at.
LAYOUT_PROBE = """JSON.stringify((function () {
  const nav = document.querySelector("nav.side"), main = document.querySelector("main");
  const n = nav && nav.getBoundingClientRect(), m = main && main.getBoundingClientRect();
  return {
    figures: Array.from(document.images).map(i => i.currentSrc || i.src).map((src, k) => [src, k])
      .filter(([src]) => /\\/svg\\//.test(src))
      .map(([src, k]) => { const img = document.images[k], box = img.closest(".figure");
        return [src, img.getBoundingClientRect().width, img.naturalWidth, box ? box.clientWidth : 0]; }),
    beside: !!(n && m && n.right <= m.left + 1),
    nav: n ? n.height : 0, page: document.documentElement.scrollHeight
  };
})())"""

FIRST_SCREEN_PROBE = """JSON.stringify((function (h) {
  const seen = el => { const r = el.getBoundingClientRect(); return r.height > 0 && r.top < h && r.bottom > 0; };
  const main = document.querySelector("main");
  return {
    title: Array.from(main.querySelectorAll("h1")).some(seen),
    frame: Array.from(main.querySelectorAll(".doc-frame table, .doc-frame p")).filter(seen).length,
    frames: main.querySelectorAll(".doc-frame").length,
    content: Array.from(main.querySelectorAll("h2")).filter(seen).map(e => e.textContent)
  };
})(%d))"""

# The search page: every query typed into its box, and what it lists.
SEARCH_PROBE = """JSON.stringify((function (queries) {
  const input = document.getElementById("search-input");
  return queries.map(q => {
    input.value = q;
    input.dispatchEvent(new Event("input"));
    return Array.from(document.querySelectorAll("#search-results li")).map(li => ({
      kind: (li.closest("[data-kind]") || {dataset: {}}).dataset.kind || "",
      url: li.querySelector("a").getAttribute("href"), title: li.querySelector("a").textContent,
      marks: Array.from(li.querySelectorAll(".snippet mark")).map(m => m.textContent),
      snippet: (li.querySelector(".snippet") || {textContent: ""}).textContent}));
  });
})(%s))"""


@dataclass(frozen=True)
class Hit:
    """One result the search page lists: its group, link, title, snippet and marked words."""

    kind: str
    url: str
    title: str
    snippet: str
    marks: tuple[str, ...]


def svg_min_font(path: Path) -> float:
    """The smallest font size an SVG file sets (its text at the size it is drawn in), 16 if none."""
    sizes = [float(s) for s in _FONT.findall(path.read_text(encoding="utf-8"))]
    return min(sizes, default=16.0)


def layout_problems(rel: str, width: int, probe: Mapping[str, Any]) -> list[str]:
    """The figures' text size and the sidebar's height of one page at one width (LAYOUT_PROBE's answer)."""
    problems = []
    for src, shown, natural, _box in probe["figures"]:
        if not natural:
            continue  # not loaded: check_page names it
        px = svg_min_font(Path(unquote(urlparse(src).path))) * shown / natural
        if px < MIN_FONT_PX:
            problems.append(f"{rel} @{width}px: figure {src.rsplit('/', 1)[-1]} drawn with text of {px:.1f} px "
                            f"(at least {MIN_FONT_PX:g})")
    if probe["beside"] and probe["nav"] + 1 < probe["page"]:
        problems.append(f"{rel} @{width}px: the sidebar is {probe['nav']:.0f} px high on a page of "
                        f"{probe['page']} px")
    return problems


def first_screen(b: Browser, page: Path, rel: str, size: tuple[int, int] = NARROW) -> list[str]:
    """The first screen of the page at size shows its title and a heading of its content, and no part of
    the document's frame (the .doc-frame block: title block, approvals, notice)."""
    width, height = size
    b.open(page.resolve().as_uri(), width, height)
    seen = json.loads(b.evaluate(FIRST_SCREEN_PROBE % height))
    problems = []
    if not seen["title"]:
        problems.append(f"{rel} @{width}x{height}: the title is not on the first screen")
    if not seen["frames"]:
        problems.append(f"{rel}: no document frame (.doc-frame) to fold")
    if seen["frame"]:
        problems.append(f"{rel} @{width}x{height}: the first screen shows {seen['frame']} part(s) of the "
                        "document's frame (title block, approvals, notice)")
    if not seen["content"]:
        problems.append(f"{rel} @{width}x{height}: no heading of the content on the first screen")
    return problems


def search(b: Browser, site: Path, queries: list[str]) -> dict[str, list[Hit]]:
    """What the search page of site lists for each query (typed into its box, one page load)."""
    b.open((site / SEARCH_PAGE).resolve().as_uri(), 1280, 900)
    answers = json.loads(b.evaluate(SEARCH_PROBE % json.dumps(queries)))
    return {q: [Hit(h["kind"], h["url"], h["title"], h["snippet"], tuple(h["marks"])) for h in hits]
            for q, hits in zip(queries, answers, strict=True)}


def bare(heading: str) -> str:
    """A heading without its number (a clause's 6.2.1, a decision's C1), in lower case, spaces folded."""
    return " ".join(_NUMBER.sub("", heading.strip()).lower().split())


def singular(title: str) -> str:
    """The title with each longer word's plural s dropped (the reader types "checksum", not "Checksums")."""
    return " ".join(w[:-1] if len(w) > 3 and w.endswith("s") and not w.endswith("ss") else w for w in title.split())


def ranking_queries(spec: Spec, documents: Iterable[Mapping[str, str]]) -> tuple[dict[str, set[str]], list[str]]:
    """The queries a section must win, each with the links of the sections whose heading it is (several
    sections may share a heading): every section and titled clause of the model and every heading of a
    document page of the search index (site.search_documents), as written and made singular. Also the
    problems: a section of the model that has no part of its own in the index."""
    by_heading: dict[str, set[str]] = {}
    for d in documents:
        if d["kind"] == "document" and d["heading"]:
            by_heading.setdefault(bare(d["heading"]), set()).add(d["url"])
    titles = [f"{s['id']} {s['title']}" for s in spec.meta.get("sections", [])]
    titles += [f"{c['number']} {c['title']}" for c in spec.meta.get("clauses", []) if c.get("title")]
    problems = [f"search: the section {t!r} of the model has no part of its own" for t in titles
                if bare(t) not in by_heading]
    queries: dict[str, set[str]] = {}
    for key in sorted(by_heading):
        if not re.search(r"[a-z]", key):
            continue  # a heading that is a number only: searched by number, not by title
        for q in dict.fromkeys([key, singular(key)]):
            queries.setdefault(q, set()).update(by_heading[key])
    return queries, problems


def search_problems(results: Mapping[str, list[Hit]], expected: Mapping[str, set[str]]) -> list[str]:
    """Every result has a snippet with a marked word; results come grouped by kind in SEARCH_KINDS's order;
    the first result of a query is one of the sections expected for it."""
    order = list(SEARCH_KINDS)
    problems = []
    for q, hits in results.items():
        if not hits:
            problems.append(f"search {q!r}: no result")
            continue
        for h in hits:
            if not h.marks or not h.snippet.strip():
                problems.append(f"search {q!r}: {h.url}: no snippet with the matched words marked")
                break
        ranks = [order.index(h.kind) if h.kind in order else len(order) for h in hits]
        if ranks != sorted(ranks) or len(order) in ranks:
            problems.append(f"search {q!r}: results not grouped by kind in the order {', '.join(order)}")
        if q in expected and hits[0].url not in expected[q]:
            problems.append(f"search {q!r}: first result {hits[0].url} ({hits[0].title!r}), not the section "
                            f"{' or '.join(sorted(expected[q]))}")
    return problems
