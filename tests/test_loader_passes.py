"""The loader as a package of passes (issue 33, points 3, 4 and 6): each pass declares what it reads
and produces, and the runner holds it to that; problems are typed and all collected; per-kind rules
are registry flags; the README's pass list is the code's; no function above the complexity ceiling."""

from __future__ import annotations

import ast
import re
from dataclasses import FrozenInstanceError, replace
from pathlib import Path

import pytest
from conftest import REPO, dump_yaml, load_yaml, spec_doc
from revisions.drill import apply_edit

from cbfgen import loader, registry
from cbfgen.loader import PASSES, Pass, Problem, SpecErrors, load, passes_markdown, pipeline, readme
from cbfgen.loader.problems import Problems

PACKAGE = Path(loader.__file__).parent
CEILING = 25  # issue 33, point 6: no function of the loader above this cyclomatic complexity


def test_every_pass_reads_only_what_a_pass_before_it_produced() -> None:
    pipeline.check_order(PASSES)  # raises on a slot read before it is produced, or produced twice
    produced = {s for p in PASSES for s in p.produces}
    assert produced | {"raw"} == set(pipeline.SLOTS), "a slot of State that no pass produces"
    assert all(not p.produces for p in PASSES if p.role == "check")
    assert len({p.name for p in PASSES}) == len(PASSES), "two passes share a rule id"


def test_the_order_check_refuses_a_pass_that_reads_before_the_producer() -> None:
    types, headers = (next(p for p in PASSES if p.name == n) for n in ("types", "headers"))
    with pytest.raises(AssertionError, match="read before produced"):
        pipeline.check_order([headers, types])
    with pytest.raises(AssertionError, match="produced twice"):
        pipeline.check_order([types, types])


def test_a_pass_sees_only_the_slots_it_declares() -> None:
    """The runner hands each pass a view: an undeclared read or write fails at once."""
    def sneaky(ctx: Problems, st: pipeline.State) -> None:
        st.types  # noqa: B018  (the read is the test)

    def writer(ctx: Problems, st: pipeline.State) -> None:
        st.types = {}

    raw = loader.yaml_reader.Map()
    with pytest.raises(AttributeError, match="reads types, which it does not declare"):
        pipeline.run([Pass("sneaky", "check", ("raw",), (), sneaky, "")], Problems("x"), raw)
    with pytest.raises(AttributeError, match="writes types, which it does not produce"):
        pipeline.run([Pass("writer", "check", ("raw",), (), writer, "")], Problems("x"), raw)
    with pytest.raises(AssertionError, match="did not produce"):
        pipeline.run([Pass("lazy", "resolve", ("raw",), ("types",), lambda ctx, st: None, "")], Problems("x"), raw)


def test_problems_are_typed_and_carry_their_pass_as_rule(tmp_path: Path) -> None:
    doc = spec_doc()
    for name in ("layout_sum", "check_versions_unscoped", "clause_check_text"):
        for edit in load_yaml(REPO / "tests" / "bad_specs" / f"{name}.yaml")["edits"]:
            apply_edit(doc, edit)
    spec = tmp_path / "cbf.yaml"
    spec.write_text(dump_yaml(doc, sort_keys=False, width=1000), encoding="utf-8")
    with pytest.raises(SpecErrors) as err:
        load(spec)
    typed = err.value.typed
    assert all(isinstance(p, Problem) and p.severity == "error" and p.line > 0 for p in typed)
    assert err.value.problems == tuple((p.line, p.text) for p in typed)
    rules = {p.rule for p in typed}
    assert {"commands", "check-params", "clauses"} <= rules, rules
    assert rules <= {p.name for p in PASSES}, rules
    assert str(err.value).splitlines() == [p.format(str(spec)) for p in typed]
    with pytest.raises(FrozenInstanceError):
        typed[0].line = 1  # type: ignore[misc]


def test_a_shape_problem_is_a_schema_rule(tmp_path: Path) -> None:
    doc = spec_doc()
    doc["versions"][0]["major"] = "three"
    spec = tmp_path / "cbf.yaml"
    spec.write_text(dump_yaml(doc, sort_keys=False, width=1000), encoding="utf-8")
    with pytest.raises(SpecErrors) as err:
        load(spec)
    assert {p.rule for p in err.value.typed} == {"schema"}


def test_the_readme_lists_the_passes_the_loader_runs() -> None:
    text = (REPO / "generator" / "README.md").read_text(encoding="utf-8")
    assert readme.rewrite(text) == text, "generator/README.md's pass list is stale: run `make loader-readme`"
    table = passes_markdown()
    assert len(table.splitlines()) == len(PASSES) + 2
    for p in PASSES:
        assert f"`{p.name}`" in table and p.doc and p.doc in table, p.name


def _is_kind(node: ast.expr) -> bool:
    """An expression that reads a check's kind: x.kind, kname, kind, x["kind"]."""
    if isinstance(node, ast.Attribute):
        return node.attr == "kind"
    if isinstance(node, ast.Name):
        return node.id in ("kind", "kname")
    return isinstance(node, ast.Subscript) and isinstance(node.slice, ast.Constant) and node.slice.value == "kind"


def test_the_loader_branches_on_no_check_kind_name() -> None:
    """Per-kind rules are registry flags (registry.LOADER_RULES): no pass compares a kind with a
    kind's name, nor tests for a kind's parameter class."""
    kinds = set(registry.CHECK_KINDS)
    for path in sorted(PACKAGE.rglob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, ast.Compare):
                sides = (node.left, *node.comparators)
                named = {str(c.value) for c in sides if isinstance(c, ast.Constant)}
                assert not (named & kinds and any(_is_kind(c) for c in sides)), \
                    f"{path.name}:{node.lineno}: a branch on a kind's name"
    assert set(registry.LOADER_RULES) <= kinds, set(registry.LOADER_RULES) - kinds


def test_a_new_kind_with_a_loader_rule_is_a_registry_line(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    """Dropping the bounds rule from the range kind's flags drops the loader's refusal of a range with
    no bound: the flag, not the kind's name, carries the rule."""
    doc = spec_doc()
    for edit in load_yaml(REPO / "tests" / "bad_specs" / "check_range_no_bound.yaml")["edits"]:
        apply_edit(doc, edit)
    spec = tmp_path / "cbf.yaml"
    spec.write_text(dump_yaml(doc, sort_keys=False, width=1000), encoding="utf-8")
    bounded = [k for k, r in registry.LOADER_RULES.items() if r.bounds]
    assert bounded
    with pytest.raises(SpecErrors, match="needs min, max or both"):
        load(spec)
    for k in bounded:
        monkeypatch.setitem(registry.LOADER_RULES, k, replace(registry.LOADER_RULES[k], bounds=False))
    try:
        load(spec)
    except SpecErrors as exc:
        assert not re.search("needs min, max or both", str(exc)), exc


def _radon() -> dict[str, int]:
    cc = pytest.importorskip("radon.complexity")
    out: dict[str, int] = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        for block in cc.cc_visit(path.read_text(encoding="utf-8")):
            out[f"{path.relative_to(PACKAGE)}:{block.name}"] = block.complexity
    return out


def _lizard() -> dict[str, int]:
    lizard = pytest.importorskip("lizard")
    out: dict[str, int] = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        info = lizard.analyze_file(str(path))
        for fn in info.function_list:
            out[f"{path.relative_to(PACKAGE)}:{fn.name}"] = fn.cyclomatic_complexity
    return out


@pytest.mark.parametrize("count", [_radon, _lizard], ids=["radon", "lizard"])
def test_no_function_of_the_loader_is_above_the_ceiling(count: object) -> None:
    got = count()  # type: ignore[operator]
    assert len(got) > 50, "the loader's functions were not found"
    over = {name: n for name, n in got.items() if n > CEILING}
    assert not over, over
