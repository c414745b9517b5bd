"""The smaller frictions of issue 27 item 7, each fixed: `info --json` with a schema, the schemas
shipped in the package and named by their installed path, CUT-line positions in encode errors,
the messages, `encode --check` for many files (the pre-commit hook on *.cut)."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from dataclasses import fields, replace
from pathlib import Path

import jsonschema

import cbf
from cbf import tables as T

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"
SMALL = GOLDEN / "valid.v3.small.cbf"
PKG = Path(cbf.__file__).resolve().parent


def run(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    env = dict(os.environ, PYTHONPATH=str(REPO / "generated" / "python"))
    res = subprocess.run([sys.executable, "-m", "cbf", *args], env=env, cwd=cwd, capture_output=True, text=True,
                         timeout=120)
    assert "Traceback" not in res.stderr, res.stderr
    return res


def _help(*cmd: str) -> str:
    return " ".join(run(*cmd, "--help").stdout.split()).replace(". json", ".json")


def test_info_json_has_a_schema_and_the_decoded_values() -> None:
    res = run("info", "--json", str(SMALL))
    doc = json.loads(res.stdout)
    jsonschema.validate(doc, json.loads((PKG / "info.schema.json").read_text(encoding="utf-8")))
    model = cbf.decode(SMALL.read_bytes())
    assert doc["records"] == len(model.records)
    assert sum(doc["commands"].values()) == len(model.records)
    assert doc["header"][T.COUNT.name] == getattr(model.header, T.COUNT.name)


def test_help_names_schemas_by_their_installed_path() -> None:
    for cmd, name in (("stats", "stats"), ("diff", "diff"), ("info", "info"), ("decode", "canonical"),
                      ("validate", "machine")):
        text = _help(cmd)
        assert "schemas/" not in text, cmd
        paths = re.findall(r"schema:(/[^)]+?\.schema\.json)", text.replace(" ", ""))
        assert any(Path(p).name == f"{name}.schema.json" and Path(p).is_file() for p in paths), (cmd, text)
    assert "canonical JSON" in _help("decode")  # --to has help text


def test_encode_errors_in_cut_text_name_the_cut_line(tmp_path: Path) -> None:
    text = cbf.to_cut(cbf.decode(SMALL.read_bytes()))
    lines = text.splitlines()
    # break continuity (6.4.5): move the start of the first LINE record far away
    at = next(i for i, ln in enumerate(lines) if ln.startswith("line "))
    lines[at] = "line < 900, 900, 900 > < 901, 900, 900 >"
    bad = tmp_path / "bad.cut"
    bad.write_text("\n".join(lines) + "\n", encoding="utf-8")
    res = run("encode", str(bad), "-o", str(tmp_path / "out.cbf"))
    assert res.returncode == 2
    assert res.stderr.startswith(f"cbf: {bad}: line {at + 1}: "), res.stderr
    assert "offset" not in res.stderr.split(":")[2]


def test_messages(tmp_path: Path) -> None:
    speed = next(c for c in T.COMMANDS if c.name.lower() == "speed")
    p = tmp_path / "s.cut"
    p.write_text(f"header X\n{speed.name.lower()}\n", encoding="utf-8")
    res = run("encode", "--check", str(p))
    assert res.returncode == 2
    line = res.stderr.strip()
    assert line.endswith("a number is missing") and line.count(f"{speed.name.lower()}:") == 1, line
    a = tmp_path / "a.cbf"
    a.write_bytes(SMALL.read_bytes())
    model = cbf.decode(SMALL.read_bytes())
    # a SPEED value (m/s) changed: the verdict does not call the tolerance millimetres
    recs = list(model.records)
    k = next(i for i, r in enumerate(recs) if r.code == speed.code)
    args = recs[k].decode_args(model.version_id)
    assert args is not None
    field = fields(args)[0].name
    recs[k] = cbf.Record.of(replace(args, **{field: getattr(args, field) * 2}))
    b = tmp_path / "b.cbf"
    b.write_bytes(cbf.encode(cbf.Cbf(model.header, recs)))
    out = run("diff", str(a), str(b)).stdout.splitlines()[-1]
    assert "differ" in out and " mm" not in out, out


def test_encode_check_many_files(tmp_path: Path) -> None:
    good = tmp_path / "good.cut"
    good.write_text(cbf.to_cut(cbf.decode(SMALL.read_bytes())), encoding="utf-8")
    bad = tmp_path / "bad.cut"
    bad.write_text("header X\nno_such_keyword 1\n", encoding="utf-8")
    res = run("encode", "--check", str(good), str(good))
    assert res.returncode == 0 and res.stdout == res.stderr == ""
    assert list(tmp_path.iterdir()) == sorted([good, bad]) or set(tmp_path.iterdir()) == {good, bad}
    res = run("encode", "--check", str(bad), str(good), str(tmp_path / "missing.cut"))
    assert res.returncode == 2
    assert [ln.split(": ")[1] for ln in res.stderr.splitlines()] == [str(bad), str(tmp_path / "missing.cut")]
    res = run("encode", str(good))
    assert res.returncode == 2 and "-o/--output" in res.stderr and res.stderr.count("\n") == 1


def test_readme_states_no_count_a_revision_changes() -> None:
    """The README's conformance paragraph names no count of golden cases, bindings or Kaitai failure-list
    entries: each revision changes them (a new check brings a golden case), and a README count went
    stale unnoticed before (59 stated, 64 present). report.json and the published document count them."""
    text = (REPO / "README.md").read_text(encoding="utf-8")
    stated = re.findall(r"\b(\d+) (?:golden )?cases\b|\b(?:four|five|six|seven|eight|\d+) bindings\b", text)
    assert not stated, f"the README states counts that a revision changes: {stated}"
    report = json.loads((REPO / "conformance" / "report.json").read_text(encoding="utf-8"))
    assert len(report["cases"]) == len(list(GOLDEN.glob("*.expect.yaml")))


def test_readme_c_snippet_compiles_with_wextra(tmp_path: Path) -> None:
    import shutil

    cc = shutil.which("gcc") or shutil.which("cc")
    if cc is None:
        import pytest

        pytest.skip("no C compiler")
    text = (REPO / "README.md").read_text(encoding="utf-8")
    snippet = next(b for b in re.findall(r"```c\n(.*?)```", text, re.S) if "cut_file_ok" in b)
    src = tmp_path / "snippet.c"
    src.write_text(snippet, encoding="utf-8")
    res = subprocess.run([cc, "-std=c99", "-Wall", "-Wextra", "-Werror", "-c", "-I", str(REPO / "generated" / "c"),
                          "-o", str(tmp_path / "snippet.o"), str(src)], capture_output=True, text=True)
    assert res.returncode == 0, res.stderr[-2000:]
