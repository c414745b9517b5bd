"""`make docs-check`: headless Chromium renders the HTML docs and must stay silent.

Chromium (Debian's `chromium`) is started once per page with a fresh profile,
writes a PNG screenshot, and logs to stderr (`--enable-logging=stderr --v=0`).
Every message a page sends to the browser console appears there as a line
with `:CONSOLE` in its tag (`[pid:tid:time:INFO:CONSOLE:1] "message", source:
...`); the pages have no JavaScript, so any such line is a failure. Chromium's
own start-up noise (D-Bus, GPU) carries other tags and is ignored. To prove
that the grep still sees console output on this Chromium, a canary page that
logs one error is rendered first: the check fails if its message is missing.
A page also fails when Chromium exits non-zero, times out or writes no PNG.

    python -m cbfgen.emit.docs.browser --site build/docs-html --out build/docs-check
"""

from __future__ import annotations

import argparse
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

from ...loader import load
from . import command_page

FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--hide-scrollbars", "--enable-logging=stderr", "--v=0")
CONSOLE = re.compile(r"^\[[^\]]*:CONSOLE[^\]]*\].*$", re.MULTILINE)
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
CANARY = "cbf-docs-check-canary"
TIMEOUT = 90


def chromium() -> str | None:
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


def render(browser: str, page: Path, png: Path, size: str) -> tuple[int, list[str]]:
    """Render page to png; (exit status, console lines)."""
    with tempfile.TemporaryDirectory(prefix="cbf-chromium-") as profile:
        cmd = [browser, *FLAGS, f"--user-data-dir={profile}", f"--screenshot={png}", f"--window-size={size}",
               page.resolve().as_uri()]
        try:
            proc = subprocess.run(cmd, capture_output=True, text=True, timeout=TIMEOUT, stdin=subprocess.DEVNULL)
        except subprocess.TimeoutExpired:
            return 124, [f"timed out after {TIMEOUT} s"]
    return proc.returncode, CONSOLE.findall(proc.stderr)


def _png_ok(png: Path) -> bool:
    return png.exists() and png.stat().st_size > 1000 and png.read_bytes()[:8] == PNG_MAGIC


def canary(browser: str, out: Path) -> list[str]:
    page = out / "canary.html"
    page.write_text(f'<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>canary</title></head>'
                    f'<body><p>canary</p><script>console.error("{CANARY}")</script></body></html>\n',
                    encoding="utf-8")
    _, lines = render(browser, page, out / "canary.png", "400,300")
    if not any(CANARY in line for line in lines):
        return ["canary: Chromium's console output was not seen on stderr; the check cannot judge the pages"]
    return []


def check(browser: str, site: Path, out: Path, pages: list[str], size: str) -> list[str]:
    problems = canary(browser, out)
    for rel in pages:
        page = site / rel
        png = out / (rel.replace("/", "_")[:-5] + ".png")
        if not page.exists():
            problems.append(f"{rel}: missing (run `make docs`)")
            continue
        status, lines = render(browser, page, png, size)
        problems += [f"{rel}: console: {line}" for line in lines]
        if status != 0:
            problems.append(f"{rel}: chromium exited with {status}")
        if not _png_ok(png):
            problems.append(f"{rel}: no screenshot written")
        elif status == 0 and not lines:
            print(f"docs-check: {rel} -> {png} ({png.stat().st_size} bytes), no console messages")
    return problems


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="cbf-docs-check", description="Render the HTML docs in headless Chromium.")
    ap.add_argument("--site", default="build/docs-html")
    ap.add_argument("--out", default="build/docs-check")
    ap.add_argument("--spec", default="spec/cbf.yaml")
    ap.add_argument("--window-size", default="1280,2400")
    args = ap.parse_args(argv)
    browser = chromium()
    if browser is None:
        print("docs-check: chromium not found (CBF_WANT_CHROMIUM=1 .ci/setup-debian.sh installs it)", file=sys.stderr)
        return 2
    spec = load(args.spec)
    # A command page with a motion figure link and an argument diagram when the spec has one.
    first = next((c for c in spec.commands if c.motion and c.motion.get("kind") == "circle"), spec.commands[0])
    pages = ["index.html", command_page(first)[:-3] + ".html"]
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    problems = check(browser, Path(args.site), out, pages, args.window_size)
    for p in problems:
        print(f"docs-check: {p}", file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
