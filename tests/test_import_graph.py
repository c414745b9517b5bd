"""The import graph of generator/ has no circle (issue #33: "imports point one way").

Every module under generator/ (the generator cbfgen, its loader and emitters, and the Python runtime
kept there as real files) is read with ast; each import, at module level, in a function or under
TYPE_CHECKING, is resolved with importlib.util.resolve_name to the module it loads. A submodule's
own ancestors are not edges (Python loads a package before any of its modules). ``make import-graph``
draws the same graph with pydeps (build/import-graph.svg)."""

from __future__ import annotations

import ast
from functools import lru_cache
from importlib.util import resolve_name
from pathlib import Path

from graph_cycles import cycles

GENERATOR = Path(__file__).resolve().parent.parent / "generator"


def modules(root: Path) -> dict[str, Path]:
    """Dotted name -> file, for every module and package under ``root``."""
    out: dict[str, Path] = {}
    for p in sorted(root.rglob("*.py")):
        parts = list(p.relative_to(root).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts.pop()
        out[".".join(parts)] = p
    return out


def _targets(name: str, is_pkg: bool, node: ast.Import | ast.ImportFrom, known: set[str]) -> set[str]:
    """The known modules an import statement of module ``name`` loads."""
    package = name if is_pkg else name.rpartition(".")[0]
    if isinstance(node, ast.Import):
        wanted = [a.name for a in node.names]
    else:
        base = resolve_name("." * node.level + (node.module or ""), package) if node.level else node.module or ""
        # `from p import x`: x is a module of p, or a name defined in p
        wanted = [f"{base}.{a.name}" if f"{base}.{a.name}" in known else base for a in node.names]
    out: set[str] = set()
    for w in wanted:
        while w and w not in known:
            w = w.rpartition(".")[0]
        if w and w != name and not name.startswith(w + "."):
            out.add(w)
    return out


def graph(root: Path) -> dict[str, set[str]]:
    mods = modules(root)
    known = set(mods)
    edges: dict[str, set[str]] = {}
    for name, path in mods.items():
        tree = ast.parse(path.read_text(encoding="utf-8"), str(path))
        is_pkg = path.name == "__init__.py"
        edges[name] = set()
        for node in ast.walk(tree):
            if isinstance(node, ast.Import | ast.ImportFrom):
                edges[name] |= _targets(name, is_pkg, node, known)
    return edges


@lru_cache(maxsize=1)
def _edges() -> dict[str, set[str]]:
    return graph(GENERATOR)


def test_the_graph_is_read() -> None:
    edges = _edges()
    assert len(edges) > 80
    # what must be seen for the test below to mean something: relative, absolute, function-level imports
    assert "cbfgen.registry" in edges["cbfgen.emit.c.views"]
    assert "cbfgen.emit.c.machine" in edges["cbfgen.emit.c.views"]
    assert "cbfgen.emit.python.runtime.tables" in edges["cbfgen.emit.python.runtime.codec"]
    assert "cbfgen.emit.python.runtime.codec" in edges["cbfgen.emit.python.runtime.cut"]  # in a function


def test_no_import_circle_in_the_generator() -> None:
    assert cycles(_edges()) == []


def test_a_circle_is_found(tmp_path: Path) -> None:
    """The reader and the search on a package made to hold one circle, through a relative import in a
    function and an absolute one (so the test above can fail)."""
    pkg = tmp_path / "p"
    pkg.mkdir()
    (pkg / "__init__.py").write_text("", encoding="utf-8")
    (pkg / "a.py").write_text("from . import b\n", encoding="utf-8")
    (pkg / "b.py").write_text("def f():\n    from .c import x\n", encoding="utf-8")
    (pkg / "c.py").write_text("import p.a\nx = 1\n", encoding="utf-8")
    assert cycles(graph(tmp_path)) == [["p.a", "p.b", "p.c", "p.a"]]
