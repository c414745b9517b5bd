"""The helpers tests share live once, in conftest.py: no test module writes its own copy of one.

Nine modules each spelt the environment of `python -m cbf` (ENV), three a consumer's environment
(CLEAN_ENV) with a runner around it, two the html_site fixture that built the site a second time.
A module that needs another environment names it otherwise or writes another value.
"""

from __future__ import annotations

import ast
from pathlib import Path

from conftest import REPO

TESTS = REPO / "tests"
SHARED = ("ENV", "CLEAN_ENV", "run_clean", "html_site")  # what conftest holds for three or more modules


def _definitions(tree: ast.Module) -> dict[str, str]:
    """Module-level names: an assignment's value, a function's body, as ast.dump gives them."""
    out: dict[str, str] = {}
    for node in tree.body:
        if isinstance(node, ast.Assign) and len(node.targets) == 1 and isinstance(node.targets[0], ast.Name):
            out[node.targets[0].id] = ast.dump(node.value)
        elif isinstance(node, ast.FunctionDef):
            out[node.name] = ast.dump(ast.Module(body=node.body, type_ignores=[]))
    return out


def _copies(shared: dict[str, str], path: Path) -> list[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    own = _definitions(tree)
    found = [name for name, body in own.items() if name in SHARED and shared.get(name) == body]
    fixtures = {n.name for n in tree.body if isinstance(n, ast.FunctionDef)} & {"html_site"}
    return found + [f"{f} (a fixture of conftest)" for f in fixtures]


def test_no_test_module_copies_a_shared_helper() -> None:
    shared = _definitions(ast.parse((TESTS / "conftest.py").read_text(encoding="utf-8")))
    assert set(SHARED) <= set(shared)
    problems = {p.name: c for p in sorted(TESTS.glob("*.py")) if p.name != "conftest.py" and (c := _copies(shared, p))}
    assert not problems, problems


def test_the_scan_finds_a_copy(tmp_path: Path) -> None:
    shared = _definitions(ast.parse((TESTS / "conftest.py").read_text(encoding="utf-8")))
    copy = tmp_path / "test_copy.py"
    copy.write_text('import os\nREPO = None\nENV = dict(os.environ, PYTHONPATH=str(REPO / "generated" / "python"))\n'
                    "def html_site(tmp_path_factory):\n    return None\n", encoding="utf-8")
    assert _copies(shared, copy) == ["ENV", "html_site (a fixture of conftest)"]
