"""Availability without ambiguity (#12 point 1).

Each availability check names the commands it covers; the loader refuses a
spec where a command missing from a version is covered by no check or by two,
and every binding reports a missing command under the check that covers it,
also when two checks cover the same version. Expectations come from the YAML
of the spec (not from the loader under test) and from the revision the test
itself makes.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest
import yaml
from conftest import spec_doc

from cbfgen.loader import SpecError, load

ROOT = Path(__file__).resolve().parents[1]
SPEC = ROOT / "spec" / "cbf.yaml"
NEW_CHECK = "availability_newcmd"


def _gates(doc: dict[str, Any]) -> list[dict[str, Any]]:
    return [c for c in doc["checks"] if c["kind"] == "availability"]


def _missing(doc: dict[str, Any]) -> set[tuple[str, str]]:
    """(version, command) pairs where the command has no layout, read from the YAML."""
    out = set()
    for v in doc["versions"]:
        for c in doc["commands"]:
            if not any(v["id"] in lay["versions"] for lay in c["layouts"]):
                out.add((v["id"], c["name"]))
    return out


def _write(doc: dict[str, Any], path: Path) -> tuple[Path, list[str]]:
    text = yaml.safe_dump(doc, sort_keys=False)
    path.write_text(text, encoding="utf-8")
    return path, text.splitlines()


def _line_after(lines: list[str], first: str, then: str) -> int:
    """1-based line of the first line containing `then` after the line containing `first`."""
    start = next(i for i, t in enumerate(lines) if first in t.replace("'", ""))
    return next(i for i in range(start, len(lines)) if then in lines[i]) + 1


def test_every_missing_command_is_covered_by_exactly_one_check() -> None:
    doc = spec_doc()
    missing = _missing(doc)
    assert missing, "the spec has versions without some commands; this test must see them"
    covered: dict[tuple[str, str], list[str]] = {}
    for g in _gates(doc):
        for v in g["versions"]:
            for name in g["commands"]:
                covered.setdefault((v, name), []).append(str(g["id"]))
    assert set(covered) == missing
    assert all(len(ids) == 1 for ids in covered.values()), covered
    spec = load(SPEC)
    for v, name in sorted(missing):
        check = spec.availability_check(name, v)
        assert check is not None and [check.id] == covered[(v, name)]


def test_loader_refuses_a_missing_command_no_check_covers(tmp_path: Path) -> None:
    doc = spec_doc()
    gate = _gates(doc)[0]
    dropped = gate["commands"].pop()
    path, lines = _write(doc, tmp_path / "cbf.yaml")
    with pytest.raises(SpecError) as err:
        load(path)
    assert err.value.line == _line_after(lines, f"name: {dropped}", f"name: {dropped}")
    assert dropped in err.value.message and "no availability check covers it" in err.value.message
    assert str(err.value).startswith(f"{path}:{err.value.line}: ")


def test_loader_refuses_a_command_two_checks_cover(tmp_path: Path) -> None:
    doc = spec_doc()
    first = _gates(doc)[0]
    twin = {**first, "id": "availability_twin", "clause": first["clause"], "commands": first["commands"][:1]}
    twin.pop("decision", None)
    doc["checks"].append(twin)
    path, lines = _write(doc, tmp_path / "cbf.yaml")
    with pytest.raises(SpecError) as err:
        load(path)
    assert err.value.line == _line_after(lines, "id: availability_twin", "commands:")
    assert f"already covered by check {first['id']}" in err.value.message
    assert first["commands"][0] in err.value.message


def test_loader_refuses_a_check_naming_a_command_the_version_has(tmp_path: Path) -> None:
    doc = spec_doc()
    gate = _gates(doc)[0]
    present = next(c["name"] for c in doc["commands"]
                   if all(v in lay["versions"] for lay in c["layouts"][:1] for v in gate["versions"]))
    gate["commands"].append(present)
    path, lines = _write(doc, tmp_path / "cbf.yaml")
    with pytest.raises(SpecError) as err:
        load(path)
    assert err.value.line == _line_after(lines, f"id: {gate['id']}", "commands:")
    assert f"{present} has a layout in version" in err.value.message


def test_schema_wants_commands_on_availability_checks_only(tmp_path: Path) -> None:
    doc = spec_doc()
    del _gates(doc)[0]["commands"]
    path, _ = _write(doc, tmp_path / "a.yaml")
    with pytest.raises(SpecError, match="schema: checks/.*'commands' is a required property"):
        load(path)
    doc = spec_doc()
    other = next(c for c in doc["checks"] if c["kind"] != "availability")
    other["commands"] = [doc["commands"][0]["name"]]
    path, _ = _write(doc, tmp_path / "b.yaml")
    with pytest.raises(SpecError, match="schema: checks/"):
        load(path)


# -- two checks covering one version: every binding names the right one -------------
def _revision(tmp_path: Path) -> tuple[Path, dict[tuple[str, str], str], dict[str, Any]]:
    """A spec copy with a new command that only the default version has, and a new
    availability check for every other version: each of those versions is then
    covered by two checks (the old one for the old commands, the new one for the new)."""
    doc = spec_doc()
    expected = {}
    for g in _gates(doc):
        for v in g["versions"]:
            for name in g["commands"]:
                expected[(v, name)] = str(g["id"])
    used = {c["code"] for c in doc["commands"]}
    code = next(c for c in range(1, 255) if c not in used and c != doc["commands"][0]["code"])
    keep = doc["default_version"]
    doc["commands"].append({
        "name": "NEWCMD", "code": code, "clause": doc["commands"][0]["clause"], "doc": "A command added later.",
        "layouts": [{"versions": [keep], "size": 4, "args": [{"name": "value", "type": "f4", "doc": "A value."}]}],
    })
    lacking = [v["id"] for v in doc["versions"] if v["id"] != keep]
    doc["checks"].append({
        "id": NEW_CHECK, "kind": "availability", "severity": "error", "versions": lacking, "commands": ["NEWCMD"],
        "text": "NEWCMD was added later.", "fails": "A record's command has no layout for the file's version.",
    })
    for v in lacking:
        expected[(v, "NEWCMD")] = NEW_CHECK
    # (an old check may cover the kept version too: NEWCMD has no pair there)
    shared = set(lacking) & {v for (v, n), cid in expected.items() if cid != NEW_CHECK}
    assert shared, "the revision must make two checks cover one version"
    path, _ = _write(doc, tmp_path / "cbf.yaml")
    return path, expected, doc


SCRIPT = r"""
import json, sys
import cbf
from cbf import tables as T
from cbf.model import Cbf, Record, new_header
from cbf.testing import seal

out = {}
for vid, name in json.loads(sys.argv[1]):
    v = T.VERSION_BY_ID[vid]
    cmd = T.BY_NAME[name]
    rec = Record(code=cmd.code, raw_args=bytes(cmd.layouts[0].size))
    data = seal(Cbf(new_header(f"{v.major}.{v.minor or 0}"), (rec,)))
    open(sys.argv[2] + f"/{vid}_{name}.cbf", "wb").write(data)
    gates = {c["id"] for c in T.checks_of("availability")}
    out[f"{vid} {name}"] = sorted({f.check for f in cbf.validate(data) if f.check in gates})
print(json.dumps(out))
"""


@dataclass(frozen=True)
class Revised:
    """The revision of _revision(), generated (Python and C) by one cbfgen run, and SCRIPT's
    answers from the Python binding with the files it sealed (one per (version, command) pair)."""
    expected: dict[tuple[str, str], str]
    doc: dict[str, Any]
    gen: Path
    files: Path
    python_found: dict[str, list[str]]


@pytest.fixture(scope="module")
def revised(tmp_path_factory: pytest.TempPathFactory) -> Revised:
    """Made once for both bindings' tests (they only read it): the revision, its generation and the
    Python binding's run took about 1.1 CPU s in each test (the C one generated in two runs)."""
    tmp = tmp_path_factory.mktemp("availability")
    spec, expected, doc = _revision(tmp)
    gen = tmp / "gen"
    subprocess.run([sys.executable, "-m", "cbfgen", "--spec", str(spec), "--out", str(gen), "--only", "python",
                    "--only", "c"], check=True, cwd=ROOT, capture_output=True)
    files = tmp / "files"
    files.mkdir()
    env = dict(os.environ, PYTHONPATH=str(gen / "python"))
    run = subprocess.run([sys.executable, "-c", SCRIPT, json.dumps(sorted(expected)), str(files)], env=env, cwd=tmp,
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    return Revised(expected, doc, gen, files, json.loads(run.stdout))


def test_two_checks_on_one_version_each_names_its_commands_python(revised: Revised) -> None:
    got = revised.python_found
    for (v, name), cid in revised.expected.items():
        assert got[f"{v} {name}"] == [cid], (v, name)


def test_two_checks_on_one_version_each_names_its_commands_c(revised: Revised, tmp_path: Path) -> None:
    cc = shutil.which("gcc")
    if cc is None:
        pytest.skip("gcc not installed")
    expected, files = revised.expected, revised.files
    ids = {str(g["id"]) for g in _gates(revised.doc)}
    testee = tmp_path / "testee"
    # -O0: the test checks which check a finding names, not the optimiser (about 0.5 CPU s less than -O1)
    subprocess.run([cc, "-std=c99", "-O0", "-o", str(testee), str(revised.gen / "c" / "cbf_testee.c"), "-lm"],
                   check=True, capture_output=True)
    pairs = sorted(expected)
    req = "".join(json.dumps({"op": "validate", "file": str(files / f"{v}_{n}.cbf"), "profile": "default",
                              "part_number": None, "cutters": None}) + "\n" for v, n in pairs) + '{"op": "quit"}\n'
    ans = subprocess.run([str(testee)], input=req, capture_output=True, text=True, check=True)
    answers = [json.loads(line) for line in ans.stdout.splitlines()]
    assert len(answers) == len(pairs)
    for (v, name), a in zip(pairs, answers, strict=True):
        assert a["ok"], a
        gates = sorted({f["check"] for f in a["findings"] if f["check"] in ids})
        assert gates == [expected[(v, name)]], (v, name, a["findings"])
