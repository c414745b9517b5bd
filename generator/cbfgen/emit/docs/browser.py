"""`make docs-check`: the HTML docs in real headless Chromium.

Chromium (Debian's `chromium`) is driven over the DevTools protocol
(cdp.py). Every page of the reference (the index, each command page, the
golden case index and the field index) is loaded at 1280 and at 390 CSS
pixels wide, and must show:
  - no horizontal overflow (the document is no wider than the viewport);
  - every image loaded (complete, with a natural width);
  - no console message, no uncaught exception and no browser log entry
    (a missing file is a log entry).
A canary page that logs one console error is loaded first: the check fails
if that message is not seen, so a silent browser cannot pass it. The site
must also be self-contained (site_links.problems: every link and anchor
resolves, none leaves the site). Screenshots at 1280 px of the index and of
one command page are written to --out.

    python -m cbfgen.emit.docs.browser --site build/docs-html --out build/docs-check
"""

from __future__ import annotations

import argparse
import shutil
import sys
from pathlib import Path

from ...loader import load
from . import FIELD_INDEX, GALLERY, GOLDEN_INDEX, command_page, site_links
from .cdp import Browser, CdpError

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


def check_page(b: Browser, page: Path, rel: str, width: int) -> list[str]:
    import json

    since = len(b.events)
    b.open(page.resolve().as_uri(), width, HEIGHT)
    probe = json.loads(b.evaluate(PROBE))
    problems = [f"{rel} @{width}px: console: {line}" for line in b.console(since)]
    if probe["scroll"] > probe["client"]:
        problems.append(f"{rel} @{width}px: horizontal overflow ({probe['scroll']} px wide in {probe['client']} px)")
    problems += [f"{rel} @{width}px: image not loaded: {src}" for src in probe["broken"]]
    return problems


def check(browser: str, site: Path, out: Path, pages: list[str], shots: list[str]) -> list[str]:
    problems = site_links.problems(site)
    with Browser(browser) as b:
        problems += canary(b, out)
        for rel in pages:
            page = site / rel
            if not page.exists():
                problems.append(f"{rel}: missing (run `make docs`)")
                continue
            for width in WIDTHS:
                problems += check_page(b, page, rel, width)
            if rel in shots:
                png = out / (rel.replace("/", "_")[:-5] + ".png")
                b.open(page.resolve().as_uri(), WIDTHS[0], HEIGHT)
                b.page("Emulation.setDeviceMetricsOverride",
                       {"width": WIDTHS[0], "height": 2400, "deviceScaleFactor": 1, "mobile": False})
                b.screenshot(png)
                print(f"docs-check: screenshot {png}")
        print(f"docs-check: {len(pages)} pages at {', '.join(f'{w} px' for w in WIDTHS)}")
    return problems


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="cbf-docs-check", description="Check the HTML docs in headless Chromium.")
    ap.add_argument("--site", default="build/docs-html")
    ap.add_argument("--out", default="build/docs-check")
    ap.add_argument("--spec", default="spec/cbf.yaml")
    args = ap.parse_args(argv)
    browser = chromium()
    if browser is None:
        print("docs-check: chromium not found (CBF_WANT_CHROMIUM=1 .ci/setup-debian.sh installs it)", file=sys.stderr)
        return 2
    spec = load(args.spec)
    # A command page with the motion figure and an argument diagram when the spec has one.
    first = next((c for c in spec.commands if c.motion and c.motion.get("kind") == "circle"), spec.commands[0])
    shots = ["index.html", command_page(first)[:-3] + ".html"]
    pages = ["index.html", *(command_page(c)[:-3] + ".html" for c in spec.commands),
             GOLDEN_INDEX[:-3] + ".html", FIELD_INDEX[:-3] + ".html", "changes.html"]
    if (Path(args.site) / GALLERY / "index.html").exists():  # the toolpath gallery's drawings load too
        pages.append(f"{GALLERY}/index.html")
        shots.append(f"{GALLERY}/index.html")
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    try:
        problems = check(browser, Path(args.site), out, pages, shots)
    except CdpError as exc:
        problems = [f"chromium: {exc}"]
    for p in problems:
        print(f"docs-check: {p}", file=sys.stderr)
    if not problems:
        print("docs-check: every link stays in the site, no overflow, every image loaded, no console message")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
