"""The static HTML site of the format documentation (`make docs`).

The pages are the Markdown pages of the docs emitter, rendered from the same
model context, turned into HTML by markdown-it-py and placed in the page
shell templates/page.html.j2 (also rendered from that context: the command
navigation comes from the model). Links between pages point to .html, links
to files of the repository (the spec, the golden cases) are rewritten to
reach them from the site folder, and the SVG figures are copied beside the
pages. No CDN, no JavaScript: one inline style sheet per page.

    python -m cbfgen.emit.docs.site --spec spec/cbf.yaml --out build/docs-html
"""

from __future__ import annotations

import argparse
import os
import posixpath
import shutil
import sys
from pathlib import Path
from typing import Any

from markdown_it import MarkdownIt
from markdown_it.token import Token

from ...loader import SpecError, load
from ...model import Spec
from ...render import environment
from . import HERE, OUT, REPO, command_page, context, emit

KAITAI_SVG = "kaitai/cbf.svg"  # written by `make docs` (ksc graphviz + dot) before the pages
KEEP = ("kaitai",)  # folders of the site that later or earlier build steps own


def _markdown() -> MarkdownIt:
    return MarkdownIt("commonmark", {"html": True}).enable("table")


def rewrite(href: str, page: str, out: Path) -> str:
    """A link of the Markdown page `page` (relative to the docs folder) as the HTML site needs it."""
    path, hash_, frag = href.partition("#")
    if not path or "://" in path or path.startswith(("mailto:", "/")):
        return href
    target = posixpath.normpath(posixpath.join(posixpath.dirname(page), path))
    if not target.startswith("../"):
        if target.endswith(".md"):
            target = target[:-3] + ".html"
        rel = posixpath.relpath(target, posixpath.dirname(page) or ".")
        return rel + hash_ + frag
    # Outside the docs: a file of the repository, reached from the site folder.
    in_repo = (REPO / "generated" / OUT / posixpath.dirname(page) / path).resolve()
    rel = os.path.relpath(in_repo, (out / posixpath.dirname(page)).resolve())
    return Path(rel).as_posix() + hash_ + frag


def _walk(tokens: list[Token], page: str, out: Path) -> None:
    for tok in tokens:
        for attr in ("href", "src"):
            value = tok.attrs.get(attr)
            if isinstance(value, str):
                tok.attrs[attr] = rewrite(value, page, out)
        if tok.children:
            _walk(tok.children, page, out)


def _title(tokens: list[Token]) -> str:
    for i, tok in enumerate(tokens):
        if tok.type == "heading_open" and tok.tag == "h1":
            return tokens[i + 1].content
    return ""


def to_html(md: MarkdownIt, text: str, page: str, out: Path) -> tuple[str, str]:
    """(title, body HTML) of one Markdown page."""
    tokens = md.parse(text)
    _walk(tokens, page, out)
    return _title(tokens), md.renderer.render(tokens, md.options, {})


def pages(spec: Spec, out: Path, kaitai: bool) -> dict[str, bytes]:
    """Every file of the site (HTML pages and figures), by path relative to out."""
    files = emit(spec)
    ctx: dict[str, Any] = context(spec)
    env = environment(HERE / "templates")
    shell = env.get_template("page.html.j2")
    md = _markdown()
    prefix = OUT + "/"
    site: dict[str, bytes] = {}
    for rel, data in sorted(files.items()):
        page = rel[len(prefix):]
        if not page.endswith(".md"):
            site[page] = data
            continue
        title, body = to_html(md, data.decode(), page, out)
        root = "../" * page.count("/")
        nav = [(c.name, root + command_page(c)[:-3] + ".html") for c in spec.commands]
        html = shell.render(title=title, body=body, root=root, nav=nav, current=page[:-3] + ".html",
                            kaitai=root + KAITAI_SVG if kaitai else None, **ctx)
        site[page[:-3] + ".html"] = html.encode()
    return site


def build(spec: Spec, out: Path) -> int:
    """Write the site into out (its old pages removed, the KEEP folders kept); the number of files."""
    out.mkdir(parents=True, exist_ok=True)
    for p in sorted(out.iterdir()):
        if p.name in KEEP:
            continue
        shutil.rmtree(p) if p.is_dir() else p.unlink()
    site = pages(spec, out.resolve(), (out / KAITAI_SVG).exists())
    for rel, data in site.items():
        (out / rel).parent.mkdir(parents=True, exist_ok=True)
        (out / rel).write_bytes(data)
    return len(site)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="cbfgen-docs-site", description="Build the HTML format documentation.")
    ap.add_argument("--spec", default="spec/cbf.yaml")
    ap.add_argument("--out", default="build/docs-html")
    args = ap.parse_args(argv)
    try:
        spec = load(args.spec)
    except SpecError as exc:
        print(f"docs-site: {exc}", file=sys.stderr)
        return 2
    n = build(spec, Path(args.out))
    print(f"docs-site: {args.spec} -> {args.out}/index.html ({n} files)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
