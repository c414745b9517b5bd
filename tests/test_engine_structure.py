"""The Python runtime's structure (issue 17): one validation engine, imports one way.

- Every check kind of the spec is implemented exactly once: in validation.py (the file-level
  kinds, ``FILE_KINDS``) or by one kernel of records.py (``KERNELS``).
- The runtime modules' imports (read with ast, function-level and TYPE_CHECKING imports
  included) form no cycle, no module imports another's private (``_x``) names or reads them
  off an imported module, and the layers point one way: tables -> codec -> validation -> cli.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest
from graph_cycles import cycles

from cbf import tables as T

REPO = Path(__file__).resolve().parents[1]
PKG = REPO / "generated" / "python" / "cbf"
FACADE = {"__init__", "__main__"}  # the package's lazy re-exports, not a layer


def _modules(pkg: Path) -> dict[str, ast.Module]:
    return {p.stem: ast.parse(p.read_text(encoding="utf-8"), str(p)) for p in sorted(pkg.glob("*.py"))
            if p.stem not in FACADE}


def _imports(name: str, tree: ast.Module, known: set[str]) -> tuple[set[str], list[str]]:
    """The sibling modules ``name`` imports, and its uses of their private names."""
    deps: set[str] = set()
    private: list[str] = []
    aliases: dict[str, str] = {}  # a local name bound to a sibling module -> that module
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.level == 1:
            if node.module:  # from .x import y
                deps.add(node.module.split(".")[0])
                private += [f"{name}: from .{node.module} import {a.name}" for a in node.names
                            if a.name.startswith("_") and not a.name.startswith("__")]
            else:  # from . import x
                for a in node.names:
                    if a.name in known:
                        deps.add(a.name)
                        aliases[a.asname or a.name] = a.name
                    elif a.name.startswith("_"):
                        private.append(f"{name}: from . import {a.name}")
        elif isinstance(node, ast.Import | ast.ImportFrom) and not getattr(node, "level", 0):
            for a in node.names:
                parts = (getattr(node, "module", None) or a.name).split(".")
                if parts[0] == "cbf" and len(parts) > 1 and parts[1] in known:
                    deps.add(parts[1])
    for node in ast.walk(tree):
        if (isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id in aliases
                and node.attr.startswith("_") and not node.attr.startswith("__")):
            private.append(f"{name}: {aliases[node.value.id]}.{node.attr} (line {node.lineno})")
    deps.discard(name)
    return deps, private


def graph(pkg: Path) -> tuple[dict[str, set[str]], list[str]]:
    mods = _modules(pkg)
    known = set(mods)
    edges: dict[str, set[str]] = {}
    private: list[str] = []
    for name, tree in mods.items():
        deps, priv = _imports(name, tree, known)
        edges[name] = deps & known
        private += priv
    return edges, private


def reach(edges: dict[str, set[str]], start: str) -> set[str]:
    seen: set[str] = set()
    todo = [start]
    while todo:
        for d in edges.get(todo.pop(), ()):
            if d not in seen:
                seen.add(d)
                todo.append(d)
    return seen


EDGES, PRIVATE = graph(PKG)


def test_the_graph_is_read() -> None:
    # the reader sees the imports it must see (else the tests below pass on nothing)
    assert {"tables", "codec", "validation", "cli", "records"} <= set(EDGES)
    assert "tables" in EDGES["codec"] and "codec" in EDGES["validation"] and "records" in EDGES["validation"]
    assert "validation" in EDGES["cli"]  # a function-level import counts


def test_no_import_cycle() -> None:
    assert cycles(EDGES) == []


def test_no_private_name_crosses_a_module() -> None:
    assert PRIVATE == []


@pytest.mark.parametrize(("lower", "upper"), [("tables", "codec"), ("codec", "validation"), ("validation", "cli"),
                                              ("records", "validation"), ("codec", "writer")])
def test_layers_point_one_way(lower: str, upper: str) -> None:
    assert upper not in reach(EDGES, lower), f"{lower} imports {upper} (directly or through another module)"
    assert lower in reach(EDGES, upper)


def test_the_checkers_find_what_they_look_for() -> None:
    # a cycle, a private import and a private attribute read, each found
    assert cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}}) == [["a", "b", "c", "a"]]
    tree = ast.parse("from .codec import _fill\nfrom . import validation as V\nx = V._one('k')\n")
    deps, private = _imports("m", tree, {"codec", "validation"})
    assert deps == {"codec", "validation"} and len(private) == 2


def test_every_check_kind_is_implemented_once() -> None:
    from cbf.records import KERNELS
    from cbf.validation import FILE_KINDS

    kinds = {c["kind"] for c in T.CHECKS}
    assert not set(KERNELS) & set(FILE_KINDS)
    assert kinds <= set(KERNELS) | set(FILE_KINDS), f"no implementation: {kinds - set(KERNELS) - set(FILE_KINDS)}"
