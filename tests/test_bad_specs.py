"""One small bad spec per refusal of the loader (tests/bad_specs/*.yaml), each checked for its
message and its YAML line, and every refusal in the loader made by one of them.

A bad spec is a patch on the real spec/cbf.yaml, not a copy of it: `edits:` in the revision
drill's path syntax (tests/revisions/drill.py: `commands[name=SPEED].layouts[0].size`), so the
set keeps applying while the spec is revised. `refuses:` is a regular expression one problem's
message must match, at the line of `line:` (the key the path ends in; `at: node`: the line of
the mapping or list it names; a selector that picks several items picks the last). YAML-level
refusals give `text_replace: [OLD, NEW]` (or the whole `text:`) and `line_text:` (the `nth`
line that reads so).
"""

from __future__ import annotations

import ast
import functools
import re
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

import pytest
from conftest import REPO, dump_yaml, load_yaml, spec_doc
from revisions.drill import _tokens, apply_edit

from cbfgen import loader
from cbfgen.loader import SpecError, SpecErrors, load

BAD = sorted((REPO / "tests" / "bad_specs").glob("*.yaml"))
LOADER = Path(loader.__file__).parent  # the package: every pass module

# Refusals no spec file can make, and why.
EXEMPT = {
    "cannot read: {}": "a path, not a spec: test_cli_bad_input reads a missing spec",
    "check {}: a second check of kind {} (first: {}, line {}); the kind takes one":
        "every kind of the registry is repeatable today (registry.CheckKind.repeatable)",
    "{} argument {}: a repeated argument group is not implemented by the binding(s) {} (generator/cbfgen/registry.py "
    "REPEAT_BINDINGS)": "every binding carries repeated groups today; test_repeat_groups drops each from "
                        "registry.REPEAT_BINDINGS in turn and sees this refusal name it",
}


def _problems(exc: SpecError) -> tuple[tuple[int, str], ...]:
    return exc.problems if isinstance(exc, SpecErrors) else ((exc.line, exc.message),)


def _line_of(text: str, path: str, at: str | None) -> int:
    """The line the loader names for the node at path of the YAML text (see the module doc)."""
    ld = loader.Loader(text)
    try:
        node: Any = ld.get_single_data()
    finally:
        ld.dispose()  # type: ignore[no-untyped-call]
    toks = _tokens(path)
    for i, tok in enumerate(toks):
        last = i == len(toks) - 1
        if tok.startswith("["):
            sel = tok[1:-1]
            if "=" in sel:
                key, value = sel.split("=", 1)
                node = [x for x in node if str(x.get(key)) == value][-1]
            else:
                node = node[int(sel)]
            if last:
                return int(node.line)
        elif last and at != "node":
            return int(node.key_lines[tok])
        else:
            node = node[tok]
    return int(node.line)


def _apply(case: dict[str, Any]) -> str:
    if "text" in case:
        return str(case["text"])
    if "text_replace" in case:
        old, new = case["text_replace"]
        text = (REPO / "spec" / "cbf.yaml").read_text(encoding="utf-8")
        assert old in text, f"text_replace: {old!r} is not in spec/cbf.yaml"
        return text.replace(old, new, 1)
    doc = spec_doc()
    for edit in case["edits"]:
        apply_edit(doc, edit)
    return dump_yaml(doc, sort_keys=False, width=1000)


def _expected_line(case: dict[str, Any], text: str) -> int:
    if "line_text" in case:
        hits = [i for i, ln in enumerate(text.splitlines(), 1) if ln.strip() == case["line_text"]]
        return hits[int(case.get("nth", 1)) - 1]
    return _line_of(text, str(case["line"]), case.get("at"))


def refusal(path: Path, tmp: Path) -> tuple[int, str]:
    """The problem the bad spec at path is about: (line, message), checked against its file."""
    case = load_yaml(path)
    text = _apply(case)
    spec = tmp / "cbf.yaml"
    spec.write_text(text, encoding="utf-8")
    with pytest.raises(SpecError) as err:
        load(spec)
    problems = _problems(err.value)
    want = _expected_line(case, text)
    hits = [(ln, msg) for ln, msg in problems if re.search(case["refuses"], msg)]
    assert hits, f"{path.name}: no problem matches {case['refuses']!r}: {problems}"
    assert any(ln == want for ln, _ in hits), f"{path.name}: {hits} is not at line {want}"
    lines = str(err.value).splitlines()
    assert len(lines) == len(problems) and all(ln.startswith(f"{spec}:") for ln in lines), lines
    return next((ln, msg) for ln, msg in hits if ln == want)


@functools.cache
def checked(path: Path) -> tuple[int, str]:
    """refusal(), once a process per bad spec (the coverage test reuses the parametrised runs:
    --dist loadfile keeps one file's tests in one worker)."""
    with tempfile.TemporaryDirectory() as tmp:
        return refusal(path, Path(tmp))


@pytest.mark.parametrize("path", BAD, ids=[p.stem for p in BAD])
def test_a_bad_spec_is_refused_with_its_message_at_its_line(path: Path) -> None:
    checked(path)


# -- every refusal of the loader runs ---------------------------------------------------
def _pattern(node: ast.expr) -> str:
    """A message expression of the loader as a regular expression (each value: .+)."""
    if isinstance(node, ast.Constant):
        return re.escape(str(node.value))
    if isinstance(node, ast.JoinedStr):
        return "".join(_pattern(v) if isinstance(v, ast.Constant) else "(.+?)" for v in node.values)
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
        return _pattern(node.left) + _pattern(node.right)
    if isinstance(node, ast.IfExp):
        return f"(?:{_pattern(node.body)}|{_pattern(node.orelse)})"
    return "(.+?)"


def _template(node: ast.expr) -> str:
    if isinstance(node, ast.JoinedStr):
        return "".join(str(v.value) if isinstance(v, ast.Constant) else "{}" for v in node.values)
    return re.sub(r"\(\?:.*\)|\(\.\+\?\)", "{}", _pattern(node)).replace("\\", "")


def refusals() -> dict[str, str]:
    """Every message the loader can refuse a spec with: template -> regular expression."""
    out: dict[str, str] = {}
    trees = [ast.parse(p.read_text(encoding="utf-8")) for p in sorted(LOADER.rglob("*.py"))]
    for node in (n for tree in trees for n in ast.walk(tree)):
        if not isinstance(node, ast.Call):
            continue
        name = node.func.attr if isinstance(node.func, ast.Attribute) else getattr(node.func, "id", "")
        where = {"fail": 1, "at": 1, "SpecError": 2}.get(name)
        if where is not None and len(node.args) > where:
            msg = node.args[where]
            out[_template(msg)] = _pattern(msg)
    return out


def test_every_refusal_of_the_loader_is_made_by_a_bad_spec() -> None:
    templates = refusals()
    assert len(templates) > 60, "the loader's refusals were not found"  # a parse that finds none proves nothing
    made = [checked(p)[1] for p in BAD]
    unmade = [t for t, rx in templates.items()
              if t not in EXEMPT and not any(re.fullmatch(rx, m, re.DOTALL) for m in made)]
    assert not unmade, "refusals no bad spec makes (add one under tests/bad_specs/):\n" + "\n".join(unmade)
    assert set(EXEMPT) <= set(templates), set(EXEMPT) - set(templates)


def test_check_spec_prints_every_problem_and_exits_2(tmp_path: Path) -> None:
    doc = spec_doc()
    for name in ("layout_sum", "check_versions_unscoped", "type_not_registered"):
        for edit in load_yaml(REPO / "tests" / "bad_specs" / f"{name}.yaml")["edits"]:
            apply_edit(doc, edit)
    spec = tmp_path / "cbf.yaml"
    spec.write_text(dump_yaml(doc, sort_keys=False, width=1000), encoding="utf-8")
    done = subprocess.run([sys.executable, "-m", "cbfgen", "--spec", str(spec), "--check-spec"], capture_output=True,
                          text=True, check=False)
    assert done.returncode == 2, done
    lines = done.stderr.splitlines()
    assert len(lines) >= 3 and all(re.match(rf"cbfgen: {re.escape(str(spec))}:\d+: ", ln) for ln in lines), lines
    for what in ("arguments sum to", "versions on a check of kind", "is not in the registry"):
        assert any(what in ln for ln in lines), (what, lines)
