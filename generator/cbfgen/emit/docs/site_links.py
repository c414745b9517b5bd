"""The site's link checker: every link and anchor resolves, and none leaves the site.

Walks every .html page of a built site and every href and src in it. A link
fails when it names a scheme (http:, file:, mailto: ...), starts with "/",
or resolves outside the site folder (the site must work when copied alone
anywhere), when its file is missing, or when its #fragment names no id of
the target page. Duplicate ids fail too.

    python -m cbfgen.emit.docs.site_links build/docs-html
"""

from __future__ import annotations

import posixpath
import re
import sys
from html.parser import HTMLParser
from pathlib import Path

SCHEME = re.compile(r"^[A-Za-z][A-Za-z0-9+.-]*:")


class _Page(HTMLParser):
    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.ids: list[str] = []
        self.links: list[str] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        for name, value in attrs:
            if value is None:
                continue
            if name == "id" or (tag == "a" and name == "name"):
                self.ids.append(value)
            elif name in ("href", "src"):
                self.links.append(value)


def _parse(path: Path) -> _Page:
    page = _Page()
    page.feed(path.read_text(encoding="utf-8"))
    return page


def problems(site: Path) -> list[str]:
    """Every link that leaves the site or does not resolve, and every duplicate id."""
    root = site.resolve()
    pages = {p.relative_to(site).as_posix(): _parse(p) for p in sorted(site.rglob("*.html"))}
    if not pages:
        return [f"{site}: no HTML pages"]
    out = []
    for rel, page in pages.items():
        out += [f"{rel}: duplicate id {i}" for i in sorted(set(page.ids)) if page.ids.count(i) > 1]
        for href in page.links:
            path, _, frag = href.partition("#")
            if SCHEME.match(href) or href.startswith(("/", "\\")):
                out.append(f"{rel}: {href}: leaves the site")
                continue
            target = posixpath.normpath(posixpath.join(posixpath.dirname(rel), path)) if path else rel
            if target.startswith("../") or target == "..":
                out.append(f"{rel}: {href}: leaves the site")
                continue
            file = (root / target).resolve()
            if not file.is_relative_to(root):
                out.append(f"{rel}: {href}: leaves the site")
            elif not file.is_file():
                out.append(f"{rel}: {href}: no such file")
            elif frag and target.endswith(".html") and frag not in pages[target].ids:
                out.append(f"{rel}: {href}: no such anchor")
    return out


def markdown_problems(docs: Path, root: Path) -> list[str]:
    """The same for the Markdown pages cbfgen writes (docs/ of its --out folder), read as a site of their
    own: every link of every page (Markdown links and HTML attributes) resolves to a file inside root (the
    folder the docs may link into: out's parent, where the spec and conformance/ sit in a checkout), and a
    #fragment into a page names an id of that page."""
    from markdown_it import MarkdownIt

    md = MarkdownIt("commonmark", {"html": True}).enable("table")
    base = root.resolve()
    pages: dict[Path, _Page] = {}  # every page's ids and links, each page parsed once
    for file in sorted(docs.rglob("*.md")):
        page = pages[file.resolve()] = _Page()
        stack = list(md.parse(file.read_text(encoding="utf-8")))
        while stack:
            tok = stack.pop()
            page.links += [v for a in ("href", "src") if isinstance(v := (tok.attrs or {}).get(a), str)]
            if tok.type in ("html_inline", "html_block"):
                page.feed(tok.content)
            stack += tok.children or []
    out = []
    for file, page in pages.items():
        rel = file.relative_to(docs.resolve()).as_posix()
        for href in page.links:
            path, _, frag = href.partition("#")
            if SCHEME.match(href) or href.startswith(("/", "\\")):
                out.append(f"{rel}: {href}: leaves the site")
                continue
            target = (file.parent / path).resolve() if path else file
            if not target.is_relative_to(base):
                out.append(f"{rel}: {href}: leaves {root}")
            elif not target.is_file():
                out.append(f"{rel}: {href}: no such file")
            elif frag and target in pages and frag not in pages[target].ids:
                out.append(f"{rel}: {href}: no such anchor")
    return out


def main(argv: list[str] | None = None) -> int:
    site = Path((argv if argv is not None else sys.argv[1:] or ["build/docs-html"])[0])
    found = problems(site)
    for p in found:
        print(f"site-links: {p}", file=sys.stderr)
    print(f"site-links: {site}: {len(found)} problem(s)")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
