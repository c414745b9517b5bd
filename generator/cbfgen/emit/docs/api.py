"""The Python API reference page of the site, read from the code of the `cbf` package with pdoc.

    python -m cbfgen.emit.docs.api OUT.md          # `make docs` writes it, the site shows it

pdoc (a pinned development dependency) reads the package the way Python sees it: its public names
(``cbf.__all__``: the lazily imported ones are loaded first, as a user's first use does), each
function's signature with its type hints, each class with its public methods, and every docstring.
This module only lays that out as a Markdown page of the site (the site's shell, navigation and
checks apply to it like to any page); nothing on the page is written by hand.
"""

from __future__ import annotations

import argparse
import html
import importlib
import inspect
import re
import sys
from pathlib import Path
from typing import Any

PACKAGE = "cbf"


def _text(doc: str) -> str:
    """A docstring as Markdown paragraphs: reST's ``code`` as code, HTML and emphasis marks escaped;
    indented blocks (examples) as code blocks."""
    out: list[str] = []
    block: list[str] = []
    for para in re.split(r"\n\s*\n", inspect.cleandoc(doc or "")):
        lines = para.splitlines()
        if lines and all(ln.startswith("    ") or not ln.strip() for ln in lines):
            block = [ln[4:] for ln in lines]
            out.append("```python\n" + "\n".join(block) + "\n```")
            continue
        text = " ".join(ln.strip() for ln in lines)
        parts = re.split(r"``(.+?)``", text)
        rendered = []
        for i, part in enumerate(parts):
            if i % 2:
                rendered.append("`" + part.replace("`", "'") + "`")
            else:
                rendered.append(re.sub(r"([*\[\]\\])", r"\\\1", html.escape(part, quote=False)))
        out.append("".join(rendered))
    return "\n\n".join(p for p in out if p.strip())


def _signature(name: str, d: Any, method: bool = False) -> str:
    try:
        if d.kind == "class":
            sig = str(inspect.signature(d.obj))
        else:
            sig = str(d.signature_without_self if method else d.signature)
    except (AttributeError, ValueError, TypeError):
        sig = "(...)"
    return f"{name}{sig}"


def page(package: str = PACKAGE) -> str:
    import pdoc.doc

    mod = importlib.import_module(package)
    for name in getattr(mod, "__all__", ()):  # resolve the lazy names, as a first use does
        getattr(mod, name)
    doc = pdoc.doc.Module(mod)
    version = getattr(mod, "__version__", "")
    lines = [f"# Python API: the `{package}` package", "",
             f"The public names of `{package}` {version} (`{package}.__all__`, which `dir({package})` lists), "
             "read from the code with pdoc: each function's signature with its types, each class with its "
             "public methods and fields, and their docstrings. The command line is on the "
             "[format reference](index.html)'s pages and in `cbf --help`.", ""]
    if doc.docstring:
        lines += [_text(doc.docstring), ""]
    names = list(doc.members)
    lines += ["Contents: " + ", ".join(f"[`{n}`](#{n.lower().strip('_')})" for n in names), ""]
    for name, member in doc.members.items():
        kind = member.kind
        lines += [f"<a id=\"{name.lower().strip('_')}\"></a>", "", f"## `{name}` ({kind})", ""]
        if kind in ("function", "class"):
            lines += ["```python", _signature(("class " if kind == "class" else "def ") + name, member), "```", ""]
        elif kind == "variable":
            value = getattr(mod, name)
            lines += ["```python", f"{name} = {value!r}", "```", ""]
        if member.docstring:
            lines += [_text(member.docstring), ""]
        if isinstance(member, pdoc.doc.Class):
            for sub in member.own_members:
                if sub.name.startswith("_") or not (sub.docstring or sub.kind == "function"):
                    continue
                if sub.kind == "function":
                    lines += [f"### `{name}.{sub.name}`", "", "```python",
                              _signature(f"def {sub.name}", sub, method=True), "```", ""]
                else:
                    annotation = getattr(sub, "annotation_str", "")
                    lines += [f"### `{name}.{sub.name}`{html.escape(annotation, quote=False)}", ""]
                if sub.docstring:
                    lines += [_text(sub.docstring), ""]
    return "\n".join(lines).rstrip() + "\n"


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="cbfgen-docs-api", description="Write the Python API reference page.")
    ap.add_argument("out", type=Path, help="the Markdown page to write")
    args = ap.parse_args(argv)
    text = page()
    tmp = args.out.with_name(f".{args.out.name}.tmp")
    args.out.parent.mkdir(parents=True, exist_ok=True)
    tmp.write_text(text, encoding="utf-8")
    tmp.replace(args.out)
    print(f"docs-api: {PACKAGE} -> {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
