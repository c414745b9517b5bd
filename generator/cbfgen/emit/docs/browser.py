"""`make docs-check`: the HTML docs in real headless Chromium.

Chromium (Debian's `chromium`) is driven over the DevTools protocol
(cdp.py). Every HTML page of the site (the reference, the CUT companion,
each command and golden case page, the indexes, the gallery, the search page,
the imported repository files) is loaded once at 390 CSS pixels wide and
measured there and, after the viewport is widened, at 1280, and must show:
  - no horizontal overflow (the document is no wider than the viewport);
  - every image loaded (complete, with a natural width);
  - no console message, no uncaught exception and no browser log entry
    (a missing file is a log entry).
A canary page that logs one console error is loaded first: the check fails
if that message is not seen, so a silent browser cannot pass it. The site
must also be self-contained (site_links.problems: every link and anchor
resolves, none leaves the site). The search page is then asked for a
check id and a command name and must list a result for each. The reader's
findings of issue 34 are measured too (reader.py): on every page at each
width the docs' figures keep readable text and the sidebar spans the page;
the reference page's first screen at 390 px shows its title and content, not
its frame; the search lists snippets with the matched words marked, groups
its results by kind and lists a section first when its title is searched
(for every section, titled clause and heading of the document). Screenshots
at 1280 px of the index and of one command page, and the reader's screenshots
(reader-*.png: the first screen, a figure and the search at 390 px, the
page's foot and the search at 1280 px), are written to --out; --shots writes
390 px screenshots of the index and one golden case too.

    python -m cbfgen.emit.docs.browser --site build/docs-html --out build/docs-check
"""

from __future__ import annotations

import argparse
import shutil
import sys
from collections.abc import Mapping
from pathlib import Path
from urllib.parse import quote

from ...loader import load
from . import CUT_PAGE, FIELD_INDEX, GALLERY, GOLDEN_INDEX, command_page, reader, site_links
from .cdp import Browser, CdpError
from .site import SEARCH_PAGE, search_documents

WIDTHS = (1280, 390)
HEIGHT = 900
CANARY = "cbf-docs-check-canary"
PROBE = """JSON.stringify({
  scroll: document.documentElement.scrollWidth, client: document.documentElement.clientWidth,
  images: document.images.length,
  broken: Array.from(document.images).filter(i => !i.complete || i.naturalWidth === 0).map(i => i.src)
})"""


def chromium() -> str | None:
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


def canary(b: Browser, out: Path) -> list[str]:
    page = out / "canary.html"
    page.write_text(f'<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>canary</title></head>'
                    f'<body><p>canary</p><script>console.error("{CANARY}")</script></body></html>\n',
                    encoding="utf-8")
    since = len(b.events)
    b.open(page.resolve().as_uri(), 400, 300)
    if not any(CANARY in line for line in b.console(since)):
        return ["canary: Chromium's console message was not seen; the check cannot judge the pages"]
    return []


# The layout is forced first (a <picture> chooses its source at layout after a resize), and every image
# must be complete on two polls in a row: right after a resize the old drawing is still complete until
# the browser starts loading the one the new width selects (docs-check saw "image not loaded" of a
# drawing that loaded a moment later, on a loaded machine).
SETTLED = "document.body.offsetHeight >= 0 && Array.from(document.images).every(i => i.complete)"


def settle(b: Browser, seconds: float = 10.0) -> None:
    """Wait until every image of the page has loaded or failed (complete), at most seconds."""
    import time

    deadline = time.monotonic() + seconds
    calm = 0
    while calm < 2 and time.monotonic() < deadline:
        calm = calm + 1 if b.evaluate(SETTLED) else 0
        time.sleep(0.05)


def check_page(b: Browser, page: Path, rel: str, widths: tuple[int, ...] = WIDTHS) -> list[str]:
    """Load the page once at the narrowest width, then measure it at each width (the viewport
    resized, the page not reloaded: the layout follows, the console and images are the load's)."""
    import json

    order = sorted(widths)
    since = len(b.events)
    b.open(page.resolve().as_uri(), order[0], HEIGHT)
    problems: list[str] = []
    for width in order:
        if width != order[0]:
            b.page("Emulation.setDeviceMetricsOverride",
                   {"width": width, "height": HEIGHT, "deviceScaleFactor": 1, "mobile": False})
            settle(b)  # a <picture> may load another drawing at this width
        probe = json.loads(b.evaluate(PROBE))
        if probe["broken"]:  # one that was switching source when probed is judged once settled
            settle(b)
            probe = json.loads(b.evaluate(PROBE))
        if probe["scroll"] > probe["client"]:
            problems.append(f"{rel} @{width}px: horizontal overflow ({probe['scroll']} px wide in "
                            f"{probe['client']} px)")
        problems += [f"{rel} @{width}px: image not loaded: {src}" for src in probe["broken"]]
        problems += reader.layout_problems(rel, width, json.loads(b.evaluate(reader.LAYOUT_PROBE)))
    problems += [f"{rel}: console: {line}" for line in b.console(since)]
    return problems


def check_search(b: Browser, site: Path, queries: list[str]) -> list[str]:
    """The search page finds each query (MiniSearch over the built index, from file://)."""
    page = site / SEARCH_PAGE
    if not page.exists():
        return [f"{SEARCH_PAGE}: missing (run `make docs`)"]
    problems = []
    for q in queries:
        since = len(b.events)
        b.open(page.resolve().as_uri() + "?q=" + quote(q), 1280, HEIGHT)
        found = b.evaluate("document.querySelectorAll('#search-results li').length")
        ready = b.evaluate("document.body.getAttribute('data-search-ready')")
        problems += [f"{SEARCH_PAGE}?q={q}: console: {line}" for line in b.console(since)]
        if not ready or not found:
            problems.append(f"{SEARCH_PAGE}?q={q}: no result (index of {ready or 'no'} documents)")
    return problems


def shoot(b: Browser, page: Path, png: Path, width: int, height: int, then: str = "") -> None:
    """A screenshot of page at width x height (loaded at width x HEIGHT); then: a script run before it."""
    b.open(page.resolve().as_uri(), width, HEIGHT)
    b.page("Emulation.setDeviceMetricsOverride",
           {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False})
    if then:
        b.evaluate(then)
    b.screenshot(png)
    print(f"docs-check: screenshot {png}")


def reader_shots(b: Browser, site: Path, out: Path, query: str) -> None:
    """What the reader of issue 34 saw, as screenshots in out: the reference page's first screen at 390 px,
    its first figure at 390 px, its foot at 1280 px (the sidebar beside it), the search for query at both."""
    narrow, tall = reader.NARROW
    index = site / "index.html"
    shoot(b, index, out / f"reader-index-first-screen-{narrow}.png", narrow, tall)
    shoot(b, index, out / f"reader-index-figure-{narrow}.png", narrow, tall,
          f"document.querySelector('img[src*=\"{reader.FIGURES}\"]').scrollIntoView()")
    shoot(b, index, out / f"reader-index-foot-{WIDTHS[0]}.png", WIDTHS[0], HEIGHT,
          "window.scrollTo(0, document.documentElement.scrollHeight)")
    for width, height in ((WIDTHS[0], HEIGHT), reader.NARROW):
        b.open((site / SEARCH_PAGE).resolve().as_uri() + "?q=" + quote(query), width, height)
        png = out / f"reader-search-{width}.png"
        b.screenshot(png)
        print(f"docs-check: screenshot {png}")


def check(browser: str, site: Path, out: Path, pages: list[str], shots: list[str], queries: list[str],
          narrow_shots: tuple[str, ...] | list[str] = (), ranking: Mapping[str, set[str]] | None = None) -> list[str]:
    """Every check of the module on the built site; ranking: reader.ranking_queries (the sections that
    searches for their titles must list first)."""
    import time

    problems = site_links.problems(site)
    start = time.monotonic()
    with Browser(browser) as b:
        problems += canary(b, out)
        for rel in pages:
            page = site / rel
            if not page.exists():
                problems.append(f"{rel}: missing (run `make docs`)")
                continue
            problems += check_page(b, page, rel)
            if rel in shots:
                shoot(b, page, out / (rel.replace("/", "_")[:-5] + ".png"), WIDTHS[0], 2400)
            if rel in narrow_shots:
                shoot(b, page, out / (rel.replace("/", "_")[:-5] + f"-{min(WIDTHS)}.png"), min(WIDTHS), 1600)
        problems += check_search(b, site, queries)
        if (site / "index.html").exists():
            problems += reader.first_screen(b, site / "index.html", "index.html")
        if ranking:
            results = reader.search(b, site, list(ranking))
            problems += reader.search_problems(results, ranking)
            reader_shots(b, site, out, max(results, key=lambda q: (len(results[q]), q)))
        print(f"docs-check: {len(pages)} pages at {', '.join(f'{w} px' for w in WIDTHS)}, search "
              f"{len(queries) + len(ranking or {})} queries, in {time.monotonic() - start:.1f} s")
    return problems


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="cbf-docs-check", description="Check the HTML docs in headless Chromium.")
    ap.add_argument("--site", default="build/docs-html")
    ap.add_argument("--out", default="build/docs-check")
    ap.add_argument("--spec", default="spec/cbf.yaml")
    ap.add_argument("--shots", action="store_true", help="also screenshots at 390 px of the index and a golden case")
    args = ap.parse_args(argv)
    browser = chromium()
    if browser is None:
        print("docs-check: chromium not found (CBF_WANT_CHROMIUM=1 .ci/setup-debian.sh installs it)", file=sys.stderr)
        return 2
    spec = load(args.spec)
    site = Path(args.site)
    # A command page with the motion figure and an argument diagram when the spec has one.
    first = next((c for c in spec.commands if c.motion and c.motion.get("kind") == "circle"), spec.commands[0])
    shots = ["index.html", command_page(first)[:-3] + ".html"]
    pages = sorted(p.relative_to(site).as_posix() for p in site.rglob("*.html"))
    for need in ["index.html", CUT_PAGE[:-3] + ".html", GOLDEN_INDEX[:-3] + ".html", FIELD_INDEX[:-3] + ".html",
                 "changes.html", SEARCH_PAGE, *(command_page(c)[:-3] + ".html" for c in spec.commands)]:
        if need not in pages:
            pages.append(need)  # reported missing
    if (site / GALLERY / "index.html").exists():  # the toolpath gallery's drawings load too
        shots.append(f"{GALLERY}/index.html")
    cases = sorted(p for p in pages if p.startswith("golden/") and p != GOLDEN_INDEX[:-3] + ".html")
    # the longest case name: its h1 must wrap at 390 px
    narrow = ["index.html", *(sorted(cases, key=len)[-1:])] if args.shots else []
    queries = [spec.checks[-1].id, spec.commands[-1].name]
    documents = search_documents({p.relative_to(site).as_posix(): p.read_bytes() for p in site.rglob("*.html")})
    ranking, missing = reader.ranking_queries(spec, documents)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    try:
        problems = missing + check(browser, site, out, pages, shots, queries, narrow, ranking)
    except CdpError as exc:
        problems = [f"chromium: {exc}"]
    for p in problems:
        print(f"docs-check: {p}", file=sys.stderr)
    if not problems:
        print("docs-check: every link stays in the site, no overflow, every image loaded, no console message")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
