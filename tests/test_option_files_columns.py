"""A cutter table's columns are the keys of the spec's cutter role (cbfgen/options.py), in both tools.

The rules name no column: a spec copy whose cutter role has one key more gives a table of one
column more, read by `cbf validate --cutters` and `cbf-c validate --cutters` generated from that
copy (with no code edit), compared by check 6.1.2 in both, and refused with the same line when a
table lacks it; the committed tools, generated from spec/cbf.yaml, do not know the column.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
from conftest import REPO, dump_yaml, generate, spec_doc

import cbf
import cbf.optfiles
from cbfgen.loader import load
from cbfgen.model import Spec
from cbfgen.options import cutter_columns, option_rules

EXTRA = "fixture_column"  # the key the spec copy adds to its cutter roles
SPEC = load(REPO / "spec" / "cbf.yaml")


def _write(doc: dict[str, Any], path: Path) -> Path:
    path.write_text(dump_yaml(doc, sort_keys=False, width=1000), encoding="utf-8")
    return path


def _with_extra_column(tmp: Path) -> Path:
    """The spec, each cutter role with EXTRA naming the argument its first number key names."""
    doc = spec_doc()
    first = cutter_columns(SPEC).values[0]
    for c in doc["commands"]:
        if "cutter" in c:
            c["cutter"][EXTRA] = c["cutter"][first]
    return _write(doc, tmp / "cbf.yaml")


def _arg_kind(spec: Spec, command: str, arg: str) -> set[str]:
    cmd = next(c for c in spec.commands if c.name == command)
    return {a.kind for lay in cmd.layouts if (a := lay.arg(arg)) is not None}


def test_the_columns_are_the_cutter_roles_keys() -> None:
    """The rules' columns are the roles' keys (the string one first), each number with the positive
    check its argument has; nothing else."""
    rules = option_rules(SPEC)["cutter_table"]
    roles = [c for c in SPEC.commands if c.cutter]
    keys = {k for c in roles for k in c.cutter or {}}
    assert set(rules["columns"]) == keys and len(rules["columns"]) == len(keys)
    assert rules["columns"][0] == rules["name"]
    assert all(_arg_kind(SPEC, c.name, (c.cutter or {})[rules["name"]]) == {"string"} for c in roles)
    assert [v["column"] for v in rules["values"]] == rules["columns"][1:]
    positive = {(t.command, a): ch.id for ch in SPEC.checks_of_kind("positive") for t in ch.targets for a in t.args}
    for v in rules["values"]:
        want = {positive.get((c.name, (c.cutter or {})[v["column"]])) for c in roles} - {None}
        assert v["positive"] == bool(want) and (v["check"] in want if want else v["check"] == "")
    assert cbf.optfiles.RULES["cutter_table"] == rules  # what the runtime reads is what the spec gives


def test_a_key_more_is_a_column_more(tmp_path: Path) -> None:
    rules = option_rules(load(_with_extra_column(tmp_path)))["cutter_table"]
    today = option_rules(SPEC)["cutter_table"]
    assert rules["columns"] == [*today["columns"], EXTRA]
    assert rules["values"][-1] == {**today["values"][0], "column": EXTRA}


@pytest.mark.parametrize("kind", ["bytes", "two strings"])
def test_a_role_that_makes_no_table_is_refused(kind: str, tmp_path: Path) -> None:
    doc = spec_doc()
    cmd = next(c for c in doc["commands"] if "cutter" in c)
    if kind == "bytes":  # a key naming an argument that is no number
        arg = next((a["name"] for lay in cmd["layouts"] for a in lay["args"] if a["type"] == "bytes"), None)
        if arg is None:
            pytest.skip("the cutter command has no bytes argument")
        want = f"cutter role key {EXTRA} names a bytes"
    else:  # a second key naming the name: which column is the cutter's name?
        arg = cmd["cutter"][cutter_columns(SPEC).name]
        want = "the cutter role needs one key naming a string argument .*, has 2"
    cmd["cutter"][EXTRA] = arg
    spec = load(_write(doc, tmp_path / "cbf.yaml"))
    with pytest.raises(ValueError, match=want):
        option_rules(spec)


# -- both tools, generated from the spec copy -------------------------------------------------
def _cutter_rows(spec: Spec) -> tuple[Path, dict[str, dict[str, float]]]:
    """A valid golden file with cutter records, and per cutter name the numbers its records hold by column."""
    roles = {c.name: c.cutter for c in spec.commands if c.cutter}
    cols = cutter_columns(spec)
    for path in sorted((REPO / "conformance" / "golden").glob("valid*.cbf")):
        doc = cbf.to_canonical(cbf.decode(path.read_bytes()))
        rows: dict[str, dict[str, float]] = {}
        consistent = True
        for rec in doc["records"]:
            role = roles.get(rec.get("command"))
            if role is None:
                continue
            args = rec["args"]
            row = {k: float(args[role[k]]) for k in cols.values if role[k] in args}
            if len(row) != len(cols.values):
                continue
            consistent &= rows.setdefault(str(args[role[cols.name]]), row) == row
        if rows and consistent:
            return path, rows
    pytest.skip("no valid golden file holds cutter records")


def _csv(columns: list[str], rows: dict[str, dict[str, float]], bump: float = 0.0) -> str:
    body = [",".join(columns)]
    for name, row in rows.items():
        body.append(",".join([name] + [repr(row[c] + (bump if c == EXTRA else 0.0)) for c in columns[1:]]))
    return "\n".join(body) + "\n"


@pytest.fixture(scope="module")
def revised(tmp_path_factory: pytest.TempPathFactory) -> tuple[Spec, dict[str, Any], Path, Path]:
    """The spec copy, its rules, its Python package (PYTHONPATH) and its cbf-c."""
    if shutil.which("gcc") is None:
        pytest.skip("gcc not installed")
    tmp = tmp_path_factory.mktemp("columns")
    path = _with_extra_column(tmp)
    generate(path, tmp / "gen", "python", "c")
    tool = tmp / "cbf-c"
    source = tmp / "gen" / "c" / "cbf_tool.c"
    subprocess.run(["gcc", "-std=c99", "-O0", "-Wall", "-Werror", "-o", str(tool), str(source), "-lm"], check=True,
                   capture_output=True)
    spec = load(path)
    return spec, option_rules(spec)["cutter_table"], tmp / "gen" / "python", tool


def _both(py_path: Path, tool: Path, table: Path, target: Path) -> list[subprocess.CompletedProcess[str]]:
    argv = ["validate", "--cutters", str(table), str(target)]
    env = dict(os.environ, PYTHONPATH=str(py_path))
    return [subprocess.run([sys.executable, "-m", "cbf", *argv], env=env, capture_output=True, text=True,
                           timeout=60),
            subprocess.run([str(tool), *argv], capture_output=True, text=True, timeout=60)]


def test_both_tools_read_and_compare_a_column_the_spec_adds(revised: tuple[Spec, dict[str, Any], Path, Path],
                                                           tmp_path: Path) -> None:
    spec, rules, py_path, tool = revised
    assert rules["columns"][-1] == EXTRA
    target, rows = _cutter_rows(spec)
    for row in rows.values():
        row[EXTRA] = row[cutter_columns(SPEC).values[0]]
    ok = tmp_path / "ok.csv"
    ok.write_text(_csv(rules["columns"], rows), encoding="utf-8")
    for r in _both(py_path, tool, ok, target):
        assert r.returncode == 0 and not r.stderr, (r.args[0], r.stdout, r.stderr)
    # the added column is compared: off by more than the tolerance, each tool names it
    off = tmp_path / "off.csv"
    off.write_text(_csv(rules["columns"], rows, bump=1.0 + 100 * spec.tolerances["cutter_mm"]), encoding="utf-8")
    py, c = _both(py_path, tool, off, target)
    assert py.returncode == c.returncode == 1 and py.stdout == c.stdout, (py.stdout, c.stdout, c.stderr)
    assert sum(f"' {EXTRA} " in line for line in py.stdout.splitlines()) >= len(rows), py.stdout
    # a table without it is refused, in the same words
    short = tmp_path / "short.csv"
    short.write_text(_csv(rules["columns"][:-1], rows), encoding="utf-8")
    want = f"{short}: line 1: the header row needs the columns {', '.join(rules['columns'])}"
    py, c = _both(py_path, tool, short, target)
    assert (py.returncode, c.returncode) == (2, 2)
    assert py.stderr == f"cbf: {want}\n" and c.stderr == f"cbf-c: {want}\n", (py.stderr, c.stderr)


def test_the_committed_tools_do_not_know_the_added_column(tmp_path: Path) -> None:
    """The column really came from the spec copy: the tools of spec/cbf.yaml refuse it as a key."""
    from c_programs import built

    target, rows = _cutter_rows(SPEC)
    table = tmp_path / "extra.yaml"
    cols = cutter_columns(SPEC)
    table.write_text(dump_yaml([{cols.name: n, **r, EXTRA: 1.0} for n, r in rows.items()], sort_keys=False),
                     encoding="utf-8")
    py, c = _both(REPO / "generated" / "python", built("cbf-c"), table, target)
    assert py.returncode == c.returncode == 2
    assert f"unknown key '{EXTRA}'" in py.stderr and py.stderr.removeprefix("cbf: ") == c.stderr.removeprefix("cbf-c: ")
