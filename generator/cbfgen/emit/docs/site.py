"""The static HTML site of the format documentation (`make docs`).

The pages are the Markdown pages of the docs emitter, rendered from the same
model context, turned into HTML by markdown-it-py and placed in the page
shell templates/page.html.j2 (also rendered from that context: the command
navigation comes from the model). Links between pages point to .html. A
link to a file of the repository outside the docs (the spec, the golden
README, a case's hex source) is copied into the site under files/ (a
Markdown file rendered as a page, any other text file also as a page with
its text, beside the verbatim copy), so the site works alone wherever it is
copied. The SVG figures are copied beside the pages. No CDN: one inline style
sheet per page. The navigation folds behind a button on narrow screens (a
checkbox and CSS, no script). Search (search.html) is MiniSearch, vendored
from node_modules at build time (search/minisearch.js with its licence), over
an index built at build time by node (search/build_index.cjs) into
search/search-index.js: it works offline and from file://.

    python -m cbfgen.emit.docs.site --spec spec/cbf.yaml --out build/docs-html
"""

from __future__ import annotations

import argparse
import html
import json
import posixpath
import re
import shutil
import subprocess
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from markdown_it import MarkdownIt
from markdown_it.token import Token

from ...loader import SpecError, load
from ...model import Spec
from ...render import environment
from . import (
    COMMANDS,
    CUT_PAGE,
    FIELD_INDEX,
    GALLERY,
    GOLDEN_INDEX,
    HERE,
    OUT,
    REPO,
    command_page,
    context,
    emit,
    figures,
)

DOCS = f"generated/{OUT}"  # where the Markdown pages live in the repository
FILES = "files"  # repository files the pages link to, copied in
SEARCH_PAGE = "search.html"
NODE_MODULES = REPO / "node_modules"
SEARCH_SRC = HERE / "search"
# MiniSearch's options: the fields searched (a part's heading weighs more than its text) and the fields a
# result shows (its snippet is cut from its text); the page reads them too. The term rule (lower case, a
# plural's s dropped) is search/terms.js, the same file for the index and the page.
SEARCH_OPTIONS = {"fields": ["heading", "text"], "storeFields": ["title", "url", "page", "kind", "text"],
                  "searchOptions": {"boost": {"heading": 6}}}
# The kinds of page a result comes from, in the order the search page groups them: the parts of the
# document (the reference, the CUT companion, the command pages, the changes, the field index) first,
# then the toolkit's own pages, then the golden cases (many, each naming checks in its title).
SEARCH_KINDS = {"document": "In the document", "toolkit": "The toolkit", "golden": "Golden cases"}
_ANCHOR = re.compile(r'<a id="([^"]+)"></a>')
_TAG = re.compile(r"<[^>]+>")
_HEADING = re.compile(r"<h([1-4])>(.*?)</h\1>", re.S)
_DATE_CELL = re.compile(r"<td>([0-9]{4}-[0-9]{2}-[0-9]{2})</td>")
_H1 = re.compile(r"(<h1>)(.*?)(</h1>)", re.S)
# a figure of the docs (a byte-field diagram, the motion figure) alone in its paragraph
_FIGURE = re.compile(r'<p>(<img src="((?:\.\./)*)(svg/[^"]*)" alt="([^"]*)"[^>]*>)</p>')
NARROW_ROW = 8  # bytes a row of a byte-field diagram drawn for a narrow screen
NARROW_MEDIA = "(max-width: 50rem)"  # the page shell's narrow layout (page.html.j2)
NARROW_FIGURES = "narrow"  # the narrow drawings' folder beside the figures (svg/narrow/)
FRAME = '<div class="doc-frame">'  # the reference page's title block, approvals and notice (index.md.j2)
_BREAK = re.compile(r"([._])(?=[A-Za-z])")


class SearchError(RuntimeError):
    """The search index could not be built (node or the minisearch package missing)."""


def _excerpt(words: str, width: int = 60) -> str:
    """A part without a heading is titled by its first words, cut at a word (its page is shown beside it)."""
    if len(words) <= width:
        return words
    cut = words[:width + 1].rsplit(" ", 1)[0] if " " in words[:width + 1] else words[:width]
    return cut.rstrip(" ,;:(") + " …"


def search_kind(page: str) -> str:
    """The kind of a page of the site (a key of SEARCH_KINDS)."""
    if page.startswith(posixpath.dirname(GOLDEN_INDEX) + "/"):
        return "golden"
    document = {"index.html", "changes.html", CUT_PAGE[:-3] + ".html", FIELD_INDEX[:-3] + ".html"}
    return "document" if page in document or page.startswith(COMMANDS + "/") else "toolkit"


def search_documents(site: dict[str, bytes]) -> list[dict[str, str]]:
    """One document a part of a page: the text from one anchor to the next, titled by its heading
    (or the page title), for every HTML page of the site but the search page and imported files.
    heading: the part's own heading (h1 to h4), empty when it has none; kind: search_kind of its page."""
    docs: list[dict[str, str]] = []
    for page, data in sorted(site.items()):
        if not page.endswith(".html") or page == SEARCH_PAGE or page.startswith(FILES + "/"):
            continue
        text = data.decode()
        body = text[text.find("<main>"):text.find("<footer>")]
        title_m = re.search(r"<title>(.*?) · ", text)
        page_title = html.unescape(title_m.group(1)) if title_m else page
        cuts = [(0, "")] + [(m.start(), m.group(1)) for m in _ANCHOR.finditer(body)]
        for k, (start, anchor) in enumerate(cuts):
            chunk = body[start:cuts[k + 1][0] if k + 1 < len(cuts) else len(body)]
            words = " ".join(html.unescape(_TAG.sub(" ", chunk)).split())
            if not words:
                continue
            head = _HEADING.search(chunk)
            title = " ".join(html.unescape(_TAG.sub("", head.group(2))).split()) if head else \
                (_excerpt(words) if anchor else page_title)
            docs.append({"id": str(len(docs)), "title": title, "url": page + (f"#{anchor}" if anchor else ""),
                         "page": page_title, "kind": search_kind(page), "heading": title if head else "",
                         "text": words})
    return docs


def search_files(site: dict[str, bytes]) -> dict[str, bytes]:
    """The vendored library, its licence, the page script and the index built by node."""
    lib = NODE_MODULES / "minisearch"
    node = shutil.which("node")
    if node is None or not (lib / "dist" / "umd" / "index.js").is_file():
        raise SearchError("the search index needs node and node_modules/minisearch (`make kaitai-setup`: npm ci)")
    payload = json.dumps({"options": SEARCH_OPTIONS, "documents": search_documents(site)})
    run = subprocess.run([node, str(SEARCH_SRC / "build_index.cjs"), str(NODE_MODULES)], input=payload.encode(),
                         capture_output=True, check=False, timeout=300)
    if run.returncode != 0:
        raise SearchError(f"building the search index failed: {run.stderr.decode(errors='replace')[:500]}")
    return {"search/minisearch.js": (lib / "dist" / "umd" / "index.js").read_bytes(),
            "search/minisearch-LICENSE.txt": (lib / "LICENSE.txt").read_bytes(),
            "search/search.js": (SEARCH_SRC / "search.js").read_bytes(),
            "search/terms.js": (SEARCH_SRC / "terms.js").read_bytes(),
            "search/search-index.js": run.stdout}


def _search_body() -> str:
    return ("<h1>Search</h1>\n"
            '<form class="search-form" action="search.html" role="search">'
            '<label for="search-input">Search the documentation</label> '
            '<input id="search-input" name="q" type="search" autocomplete="off"></form>\n'
            '<p id="search-status" aria-live="polite">Search needs JavaScript.</p>\n'
            '<div id="search-results"></div>\n'
            f'<script type="application/json" id="search-options">{json.dumps(SEARCH_OPTIONS)}</script>\n'
            f'<script type="application/json" id="search-kinds">{json.dumps(SEARCH_KINDS)}</script>\n'
            '<script src="search/minisearch.js"></script>\n<script src="search/search-index.js"></script>\n'
            '<script src="search/terms.js"></script>\n'
            '<script src="search/search.js"></script>\n'
            '<p class="note">Search: <a href="search/minisearch-LICENSE.txt">MiniSearch</a> (MIT licence), '
            "with an index built when the site was built; it works offline.</p>\n")


@dataclass
class Imports:
    """Repository files (relative to REPO) that pages link to, collected while the links are rewritten."""

    paths: set[str] = field(default_factory=set)


def _markdown() -> MarkdownIt:
    return MarkdownIt("commonmark", {"html": True}).enable("table")


def imported(repo_rel: str) -> str:
    """Where a repository file is published in the site: a page for text, named after the file."""
    return f"{FILES}/{repo_rel}.html" if not repo_rel.endswith(".md") else f"{FILES}/{repo_rel[:-3]}.html"


def rewrite(href: str, page: str, imports: Imports, source: str | None = None) -> str:
    """A link of a Markdown page as the HTML site needs it. page: the HTML page's path in the site;
    source: the Markdown file's path in the repository (default: the docs page of that name)."""
    path, hash_, frag = href.partition("#")
    if not path or "://" in path or path.startswith(("mailto:", "/")):
        return href
    source = source or f"{DOCS}/{page[:-5]}.md"
    repo_target = posixpath.normpath(posixpath.join(posixpath.dirname(source), path))
    if repo_target.startswith(DOCS + "/"):
        target = repo_target[len(DOCS) + 1:]
        if target.endswith(".md"):
            target = target[:-3] + ".html"
    elif not repo_target.startswith("../") and (REPO / repo_target).is_file():
        imports.paths.add(repo_target)
        target = imported(repo_target)
    else:
        return href  # left as it is: the link checker reports it
    return posixpath.relpath(target, posixpath.dirname(page) or ".") + hash_ + frag


def _walk(tokens: list[Token], page: str, imports: Imports, source: str | None) -> None:
    for tok in tokens:
        for attr in ("href", "src"):
            value = tok.attrs.get(attr)
            if isinstance(value, str):
                tok.attrs[attr] = rewrite(value, page, imports, source)
        if tok.children:
            _walk(tok.children, page, imports, source)


def _title(tokens: list[Token]) -> str:
    for i, tok in enumerate(tokens):
        if tok.type == "heading_open" and tok.tag == "h1":
            return tokens[i + 1].content
    return ""


def to_html(md: MarkdownIt, text: str, page: str, imports: Imports,
            source: str | None = None) -> tuple[str, str]:
    """(title, body HTML) of one Markdown page (page: its HTML path in the site)."""
    tokens = md.parse(text)
    _walk(tokens, page, imports, source)
    # a date alone in a cell stays on one line (narrow columns broke "2027-01-15" after its hyphen)
    rendered: str = md.renderer.render(tokens, md.options, {})
    body = _DATE_CELL.sub(r'<td style="white-space: nowrap">\1</td>', rendered)

    def breaks(m: re.Match[str]) -> str:  # in the h1's text, not in its tags' attributes
        text = re.sub(r"(>[^<]*)", lambda t: _BREAK.sub(r"\1<wbr>", t.group(1)), ">" + m.group(2))[1:]
        return m.group(1) + text + m.group(3)
    # a long name in a title (a golden case's) may wrap after a dot or an underscore, not inside a word
    return _title(tokens), _H1.sub(breaks, body)


def narrow_figure(figure: str) -> str:
    """Where the narrow drawing of a figure (its path in the site, svg/...) is."""
    folder, name = posixpath.split(figure)
    return f"{folder}/{NARROW_FIGURES}/{name}"


def for_screens(body: str, part_number: str, narrow: frozenset[str] = frozenset()) -> str:
    """What a page of the site adds to its Markdown's HTML for a reader on a screen (the PDF renders the
    Markdown without it): each figure of the docs in a box that scrolls sideways, reachable by keyboard,
    so that its text keeps its size on a narrow screen, drawn NARROW_ROW bytes a row there when it is a
    byte-field diagram (narrow: the figures that have such a drawing); before the reference page's frame
    (title block, approvals, notice) a button that shows it, as the page's style folds the frame on narrow
    screens."""
    def figure(m: re.Match[str]) -> str:
        img, up, src, alt = m.groups()
        if src in narrow:
            img = f'<picture><source media="{NARROW_MEDIA}" srcset="{up}{narrow_figure(src)}">{img}</picture>'
        return f'<div class="figure" role="region" tabindex="0" aria-label="{alt}">{img}</div>'
    body = _FIGURE.sub(figure, body)
    toggle = ('<input type="checkbox" id="frame-toggle" class="frame-toggle" aria-label="Show the document frame">'
              f'<label for="frame-toggle" class="frame-button">{html.escape(part_number)}: title block, '
              "approvals and notice</label>\n")
    return body.replace(FRAME, toggle + FRAME, 1)


def _nav(spec: Spec, root: str) -> list[tuple[str, str]]:
    return [(c.name, root + command_page(c)[:-3] + ".html") for c in spec.commands]


def gallery_files(folder: Path) -> dict[str, bytes]:
    """The toolpath gallery that `python -m cbf.gallery` wrote into folder: its index page and the
    SVG drawings, as docs files under gallery/ (the stats text is already on the page)."""
    files = {f"{OUT}/{GALLERY}/index.md": (folder / "index.md").read_bytes()}
    for svg_file in sorted(folder.glob("*.svg")):
        files[f"{OUT}/{GALLERY}/{svg_file.name}"] = svg_file.read_bytes()
    return files


API_PAGE = "api.html"  # the Python API reference (cbfgen.emit.docs.api, read from the code with pdoc)


def pages(spec: Spec, gallery: Path | None = None, api: Path | None = None,
          workbench: bool = False) -> dict[str, bytes]:
    """Every file of the site (HTML pages, figures, imported repository files), by path relative to it.
    gallery: a folder made by `python -m cbf.gallery`, shown as the site's toolpath gallery; api: the
    Markdown page `python -m cbfgen.emit.docs.api` wrote (both made from the code, apart from the spec)."""
    ctx: dict[str, Any] = context(spec)
    ctx["gallery_page"] = f"{GALLERY}/index.html" if gallery is not None else None
    ctx["api_page"] = API_PAGE if api is not None else None
    # the workbench page (cbfgen.emit.docs.workbench, issue 34) is written into the site after it
    ctx["workbench_page"] = "workbench.html" if workbench else None
    files = emit(spec, ctx)
    wide = figures(spec)
    narrow = {rel: text for rel, text in figures(spec, NARROW_ROW, narrow=True).items() if text != wide[rel]}
    if gallery is not None:
        files.update(gallery_files(gallery))
    if api is not None:
        files[f"{OUT}/{API_PAGE[:-5]}.md"] = api.read_bytes()
    env = environment(HERE / "templates")
    shell = env.get_template("page.html.j2")
    md = _markdown()
    prefix = OUT + "/"
    site: dict[str, bytes] = {}
    imports = Imports()

    def render(page: str, title: str, body: str) -> bytes:
        root = "../" * page.count("/")
        return shell.render(title=title, body=for_screens(body, spec.meta["part_number"], frozenset(narrow)),
                            root=root, nav=_nav(spec, root), current=page, **ctx).encode()

    for rel, data in sorted(files.items()):
        page = rel[len(prefix):]
        if not page.endswith(".md"):
            site[page] = data
            continue
        html_page = page[:-3] + ".html"
        title, body = to_html(md, data.decode(), html_page, imports)
        site[html_page] = render(html_page, title, body)
    site.update({narrow_figure(rel): text.encode() for rel, text in narrow.items()})
    site[SEARCH_PAGE] = render(SEARCH_PAGE, "Search", _search_body())
    site.update(search_files(site))
    done: set[str] = set()
    while imports.paths - done:  # an imported Markdown file may link further files
        repo_rel = sorted(imports.paths - done)[0]
        done.add(repo_rel)
        text = (REPO / repo_rel).read_text(encoding="utf-8")
        page = imported(repo_rel)
        if repo_rel.endswith(".md"):
            # Links of the imported page are relative to its place in the repository.
            title, body = to_html(md, text, page, imports, source=repo_rel)
            title = title or repo_rel
        else:
            title = repo_rel
            raw = posixpath.basename(repo_rel)
            site[f"{FILES}/{repo_rel}"] = text.encode()
            body = (f"<h1>{html.escape(repo_rel)}</h1>\n<p>A copy of <code>{html.escape(repo_rel)}</code> "
                    f"from the repository (<a href=\"{html.escape(raw)}\">the file itself</a>).</p>\n"
                    f"<pre><code>{html.escape(text)}</code></pre>\n")
        site[page] = render(page, title, body)
    return site


def build(spec: Spec, out: Path, gallery: Path | None = None, api: Path | None = None,
          workbench: bool = False) -> int:
    """Write the site into out (its old content removed); the number of files."""
    out.mkdir(parents=True, exist_ok=True)
    for p in sorted(out.iterdir()):
        shutil.rmtree(p) if p.is_dir() else p.unlink()
    site = pages(spec, gallery, api, workbench)
    for rel, data in site.items():
        (out / rel).parent.mkdir(parents=True, exist_ok=True)
        (out / rel).write_bytes(data)
    return len(site)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="cbfgen-docs-site", description="Build the HTML format documentation.")
    ap.add_argument("--spec", default="spec/cbf.yaml")
    ap.add_argument("--out", default="build/docs-html")
    ap.add_argument("--gallery", type=Path, help="a folder written by `python -m cbf.gallery`, shown in the site")
    ap.add_argument("--api", type=Path, help="the Python API page `python -m cbfgen.emit.docs.api` wrote")
    ap.add_argument("--workbench", action="store_true", help="link the workbench page (make workbench writes it)")
    args = ap.parse_args(argv)
    try:
        spec = load(args.spec)
    except SpecError as exc:
        print(f"docs-site: {exc}", file=sys.stderr)
        return 2
    try:
        n = build(spec, Path(args.out), args.gallery, args.api, args.workbench)
    except SearchError as exc:
        print(f"docs-site: {exc}", file=sys.stderr)
        return 2
    print(f"docs-site: {args.spec} -> {args.out}/index.html ({n} files)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
