"""One table of option-file cases through both tools (issue 28, items 1, 6 and 7).

tests/option_files/cases.yaml lists cutter tables and machine files; each row runs through
`cbf validate` and `cbf-c validate` on the same CBF file. Both tools give the same exit code, and
on a refusal the same one line naming the file, the line (or JSON path) and the limit: the
row's `says`, whose limits are read from cbf/option_files.json (generated from
generator/cbfgen/option_files.yaml and the spec, as cbf-c's are). Rows marked `bounded` run again
under a memory cap and a time limit: a YAML bomb, deep nesting or a 100 MiB table costs no more
than the refusal.
"""

from __future__ import annotations

import json
import random
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from c_programs import built
from cli_many import run_many
from conftest import ENV, capped_run, dump_yaml, load_yaml

from cbf.optfiles import RULES
from cbfgen.emit.python.machine import machine_data
from cbfgen.loader import load

REPO = Path(__file__).resolve().parents[1]
HERE = REPO / "tests" / "option_files"
CASES: list[dict[str, Any]] = load_yaml(HERE / "cases.yaml")
TARGET = REPO / "conformance" / "golden" / "valid.v3.small.cbf"
SPEC = load(REPO / "spec" / "cbf.yaml")
CUT, MACHINE = RULES["cutter_table"], RULES["machine_file"]
HEADER = ",".join(CUT["columns"]) + "\n"  # a CSV table's first line: the spec's columns (options.cutter_columns)


def _row(name: str, value: str = "10") -> str:
    """A CSV row: the name, then ``value`` in each number column."""
    return ",".join([name] + [value] * (len(CUT["columns"]) - 1)) + "\n"
MEMORY_CAP = 512 << 20
TIME_CAP = 10.0


def _machine_text(edit: Callable[[dict[str, Any]], None] | None = None, yaml: bool = False) -> str:
    doc = machine_data(SPEC)
    if edit:
        edit(doc)
    return dump_yaml(doc, width=10**6, sort_keys=False) if yaml else json.dumps(doc, indent=1)


def _scalar_limit() -> str:
    return next(lim.name for lim in SPEC.machine.limits if not lim.axes)


def _with_min(text: str) -> Callable[[Path], tuple[str, dict[str, Any]]]:
    """A YAML machine file whose first range's min is written as ``text``."""
    def make(p: Path) -> tuple[str, dict[str, Any]]:
        lim = _scalar_limit()
        body = _machine_text(lambda d: d["limits"][lim].__setitem__("min", "SENTINEL"), yaml=True)
        p.write_text(body.replace("SENTINEL", text, 1), encoding="utf-8")
        return p.name, {"limit": lim}
    return make


def _write(text: str, extra: dict[str, Any] | None = None) -> Callable[[Path], tuple[str, dict[str, Any]]]:
    def make(p: Path) -> tuple[str, dict[str, Any]]:
        p.write_text(text, encoding="utf-8")
        return p.name, extra or {}
    return make


def _rows(p: Path) -> tuple[str, dict[str, Any]]:
    n = CUT["max_rows"] + 4
    p.write_text(HEADER + "".join(_row(f"C{i}") for i in range(n)), encoding="utf-8")
    return p.name, {"line": CUT["max_rows"] + 2}  # the header, then the rows: the one beyond the limit


def _long_name(p: Path) -> tuple[str, dict[str, Any]]:
    chars = max(200, CUT["max_name"] + 1)
    p.write_text(HEADER + _row("N" * chars), encoding="utf-8")
    return p.name, {"chars": chars}


def _huge_csv(p: Path) -> tuple[str, dict[str, Any]]:
    with p.open("wb") as fh:  # 100 MiB, sparse: the header, then zeros
        fh.write(HEADER.encode())
        fh.truncate(100 << 20)
    return p.name, {}


def _duplicate_unit(p: Path) -> tuple[str, dict[str, Any]]:
    first = SPEC.machine.limits[0]
    unit = json.dumps({"unit": first.unit})[1:-1]
    p.write_text(json.dumps(machine_data(SPEC)).replace(unit, f"{unit}, {unit}", 1), encoding="utf-8")
    return p.name, {"limit": first.name}


MAKERS: dict[str, tuple[str, Callable[[Path], tuple[str, dict[str, Any]]]]] = {
    "rows": ("rows.csv", _rows),
    "long_name": ("long_name.csv", _long_name),
    "huge_csv": ("huge.csv", _huge_csv),
    "wide_csv": ("wide.csv", _write(HEADER + ",".join(["1"] * (CUT["max_columns"] + 1)) + "\n")),
    "deep_yaml": ("deep.yaml", _write("[" * 1000 + "]" * 1000 + "\n")),
    "missing": ("missing.csv", lambda p: (p.name, {})),
    "machine_json": ("machine.json", _write(_machine_text())),
    "machine_yaml": ("machine.yaml", _write(_machine_text(yaml=True))),
    "machine_too_big": ("big.json", _write(_machine_text(lambda d: d.__setitem__("doc", "x" * MACHINE["max_bytes"])))),
    "machine_deep_json": ("deep.json", _write("[" * 2000 + "]" * 2000 + "\n", {"column": MACHINE["max_depth"] + 1})),
    "machine_deep_yaml": ("deep_machine.yaml", _write("[" * 1000 + "]" * 1000 + "\n")),
    "machine_nan_yaml": ("nan_machine.yaml", _with_min(".nan")),
    "machine_underscore_yaml": ("underscore_machine.yaml", _with_min("1_00")),
    "machine_duplicate_key": ("duplicate_machine.json", _duplicate_unit),
}


def _id(case: dict[str, Any]) -> str:
    return f"{case['option']}-{case.get('file') or case['make']}"


def _input(case: dict[str, Any], tmp: Path) -> tuple[Path, dict[str, Any]]:
    if "file" in case:
        return HERE / case["file"], {}
    name, make = MAKERS[case["make"]]
    path = tmp / name
    _, extra = make(path)
    return path, extra


def _says(case: dict[str, Any], path: Path, extra: dict[str, Any]) -> str | None:
    if "says" not in case:
        return None
    return str(case["says"]).format(file=path, cutter=CUT, machine=MACHINE, yaml=RULES["yaml"], extra=extra,
                                    columns=", ".join(CUT["columns"]))


def test_the_table_covers_every_file_and_maker() -> None:
    """Every file beside the table is a row, every maker is used, and rows are unique."""
    files = {c["file"] for c in CASES if "file" in c}
    assert files == {p.name for p in HERE.iterdir() if p.name != "cases.yaml"}
    assert {c["make"] for c in CASES if "make" in c} == set(MAKERS)
    assert len({_id(c) for c in CASES}) == len(CASES)


@pytest.fixture(scope="module")
def cbf_c() -> Path:
    return built("cbf-c")


def test_both_tools_give_the_same_line_on_every_row(cbf_c: Path, tmp_path: Path) -> None:
    inputs = [_input(c, tmp_path) for c in CASES]
    argvs = [["validate", f"--{c['option']}", str(path), str(TARGET)]
             for c, (path, _) in zip(CASES, inputs, strict=True)]
    pys = run_many(argvs, ENV)  # one process for every row
    problems = []
    for case, (path, extra), argv, (py, _) in zip(CASES, inputs, argvs, pys, strict=True):
        c = subprocess.run([str(cbf_c), *argv], capture_output=True, text=True, timeout=TIME_CAP)
        want = _says(case, path, extra)
        got_py = py.stderr.strip().removeprefix("cbf: ")
        got_c = c.stderr.strip().removeprefix("cbf-c: ")
        if want is None:
            ok = py.returncode == c.returncode and py.returncode in (0, 1) and not py.stderr and not c.stderr
        else:
            ok = py.returncode == c.returncode == 2 and got_py == got_c == want and py.stderr.count("\n") == 1 \
                and c.stderr.count("\n") == 1 and not py.stdout and not c.stdout
        if not ok:
            problems.append(f"{_id(case)}:\n  want {want}\n  cbf   {py.returncode} {got_py}\n"
                            f"  cbf-c {c.returncode} {got_c}")
    assert not problems, "\n".join(problems)


@pytest.mark.parametrize("case", [c for c in CASES if c.get("bounded")], ids=_id)
def test_a_bomb_costs_no_more_than_its_refusal(case: dict[str, Any], cbf_c: Path, tmp_path: Path) -> None:
    """Under a 512 MiB address-space cap, each tool refuses the row within seconds (before issue 28
    a YAML alias bomb ran 48 s to a 2.9 GB cap and a 100 MiB table was read at 4.5 GB)."""
    path, extra = _input(case, tmp_path)
    argv = ["validate", f"--{case['option']}", str(path), str(TARGET)]
    for cmd, env, prefix in (([sys.executable, "-m", "cbf", *argv], ENV, "cbf: "),
                             ([str(cbf_c), *argv], None, "cbf-c: ")):
        r = capped_run(cmd, env, MEMORY_CAP, TIME_CAP)
        assert r.returncode == 2 and r.stderr == prefix + str(_says(case, path, extra)) + "\n", (cmd[0], r.stderr)


def _random_table(rnd: random.Random) -> str:
    """A YAML cutter table, block or flow rows, with odd values, keys and lines mixed in."""
    odd = ["C 1", "'q x'", '"d\\"q"', "-2", "0", ".nan", "nan", "1_00", "1e400", "", "~", "null", "true", "[1]",
           "{a: 1}", "&a 1", "*a", "!!str 5", "|", "'open", "x: y", "1.5e1"]
    keys = [*CUT["columns"], "diameter", "? x"]
    lines = ["cutters:"] if rnd.random() < 0.5 else []
    ind = "  " if lines and rnd.random() < 0.5 else ""
    for _ in range(rnd.randint(0, 4)):
        ks = list(CUT["columns"]) if rnd.random() < 0.7 else rnd.sample(keys, rnd.randint(1, 4))
        vals = [rnd.choice(odd) if rnd.random() < 0.3 else {CUT["name"]: f"C{rnd.randint(0, 5)}"}.get(k, "2")
                for k in ks]
        if rnd.random() < 0.5:
            lines.append(ind + "- {" + ", ".join(f"{k}: {v}" for k, v in zip(ks, vals, strict=True)) + "}")
        else:
            lines += [ind + ("- " if i == 0 else "  ") + f"{k}: {v}"
                      for i, (k, v) in enumerate(zip(ks, vals, strict=True))]
        if rnd.random() < 0.1:
            lines.append(rnd.choice(["# note", "", "---", "  x", "- ", "key: v"]))
    return "\n".join(lines) + "\n"


def test_random_tables_get_the_same_verdict_from_both_tools(cbf_c: Path, tmp_path: Path) -> None:
    """300 seeded random YAML tables (valid rows, odd values, explicit keys, anchors, bad lines):
    the same exit code from both tools, and the same line unless the text is not YAML at all (then
    PyYAML's scanner, which reads ahead, may name a later fault first, in its own words). 96 of 300
    disagreed before the readers were aligned."""
    rnd = random.Random(28)
    paths = []
    for i in range(300):
        p = tmp_path / f"t{i}.yaml"
        p.write_text(_random_table(rnd), encoding="utf-8")
        paths.append(p)
    pys = run_many([["validate", "--cutters", str(p), str(TARGET)] for p in paths], ENV)
    problems = []
    for p, (py, _) in zip(paths, pys, strict=True):
        c = subprocess.run([str(cbf_c), "validate", "--cutters", str(p), str(TARGET)], capture_output=True, text=True,
                           timeout=TIME_CAP)
        a, b = py.stderr.strip().removeprefix("cbf: "), c.stderr.strip().removeprefix("cbf-c: ")
        syntax = "not YAML" in a or "not YAML" in b  # PyYAML's scanner reads ahead: its error may come first
        if py.returncode != c.returncode or (py.returncode == 2 and a != b and not syntax):
            problems.append(f"{p.read_text()}\n  cbf   {py.returncode} {a}\n  cbf-c {c.returncode} {b}")
    assert not problems, "\n".join(problems[:5])
