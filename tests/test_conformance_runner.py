"""The runner turns red when the codec is broken, and its comparison rules hold."""

from __future__ import annotations

import importlib.util
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
import yaml
from conftest import load_yaml

from conformance.runner.compare import f32_bits, findings_difference, first_difference
from conformance.runner.reasons import failure_class, fixed_entries, matches
from conformance.runner.run import FailureListError, judge, kind, load_cases, read_failures, run_case, write_failures

REPO = Path(__file__).resolve().parents[1]


def _scratch_codec(tmp: Path, edit: str) -> Path:
    """The Python codec generated from an edited copy of the spec."""
    spec = load_yaml(REPO / "spec" / "cbf.yaml")
    if edit == "swap_line_args":
        line = next(c for c in spec["commands"] if c["name"] == "LINE")
        args = line["layouts"][0]["args"]
        args[0]["name"], args[1]["name"] = args[1]["name"], args[0]["name"]
        line["motion"] = {"kind": "line", "start": "end", "end": "start"}
    elif edit == "drop_shape_check":
        spec["checks"] = [c for c in spec["checks"] if c["id"] != "shape"]
    path = tmp / "cbf.yaml"
    path.write_text(yaml.safe_dump(spec, sort_keys=False), encoding="utf-8")
    out = tmp / "gen"
    subprocess.run([sys.executable, "-m", "cbfgen", "--spec", str(path), "--out", str(out), "--only", "python"],
                   cwd=REPO, check=True, capture_output=True)
    return out / "python"


def _run(tmp: Path, pythonpath: Path, case: str) -> subprocess.CompletedProcess[str]:
    failures = tmp / "failures"
    failures.mkdir(exist_ok=True)
    (failures / "python.txt").write_text("", encoding="utf-8")
    return subprocess.run(
        [sys.executable, "-m", "conformance.runner", "--binding", "python", "--python-path", str(pythonpath),
         "--failures", str(failures), "--report", str(tmp / "report.json"), "--case", case],
        cwd=REPO, capture_output=True, text=True)


def test_swapped_fields_turn_the_run_red(tmp_path: Path) -> None:
    res = _run(tmp_path, _scratch_codec(tmp_path, "swap_line_args"), "valid")
    assert res.returncode == 1
    assert "python: valid.v3.all_commands: FAIL decode" in res.stdout
    assert "python: valid.v4.all_commands: FAIL decode" in res.stdout


def test_a_skipped_check_turns_the_run_red(tmp_path: Path) -> None:
    res = _run(tmp_path, _scratch_codec(tmp_path, "drop_shape_check"), "check.shape")
    assert res.returncode == 1
    assert "python: check.shape.count: FAIL validate: [default] missing shape/error/record 10" in res.stdout


def test_the_real_codec_is_green(tmp_path: Path) -> None:
    res = _run(tmp_path, REPO / "generated" / "python", "check.6.4")
    assert res.returncode == 0, res.stdout + res.stderr
    assert "0 failed" in res.stdout


def test_stale_failure_list_fails(tmp_path: Path) -> None:
    failures = tmp_path / "failures"
    failures.mkdir()
    write_failures(failures / "python.txt", {"check.6.4.4.arg_checksum": "decode: something"}, "python")
    assert read_failures(failures / "python.txt") == {"check.6.4.4.arg_checksum": "decode: something"}
    res = subprocess.run(
        [sys.executable, "-m", "conformance.runner", "--binding", "python", "--failures", str(failures),
         "--report", str(tmp_path / "r.json"), "--case", "check.6.4.4"], cwd=REPO, capture_output=True, text=True)
    assert res.returncode == 1
    assert "listed as failing but passes" in res.stdout


def test_floats_compare_by_bits() -> None:
    assert first_difference(0.1, 0.10000000149011612) is None  # the same binary32
    assert first_difference(0.1, 0.1000001) is not None
    assert first_difference("0x80000000", -0.0) is None
    assert first_difference(0.0, -0.0) is not None
    assert first_difference("0x7fc00001", "0x7fc00000") is not None
    assert f32_bits(1.0) == 0x3F800000
    assert first_difference({"a": [1.0, "*"]}, {"a": [1.0, 5], "offset": 3}) is None
    assert first_difference({"a": 1}, {"a": 1, "b": 2}) == "$.b: unexpected key"


def test_findings_compare_as_multisets() -> None:
    found = {"check": "6.4.4", "severity": "error", "record": 2, "offset": 214}
    assert findings_difference([["6.4.4", "error", 2, 214]], [found]) is None
    diff = findings_difference([["6.4.4", "error", 2, 214], ["6.4.4", "error", 2, 214]], [found])
    assert diff and "missing" in diff
    assert findings_difference([], [{"check": "shape", "severity": "error", "record": None, "offset": 0}]) == \
        "unexpected shape/error/header @offset 0"


def test_findings_compare_offsets() -> None:
    """The offset of the field concerned is part of a finding (issue 13 item 13): the record start is not it."""
    expected = [["6.4.2", "error", 2, 211]]
    at_record_start = {"check": "6.4.2", "severity": "error", "record": 2, "offset": 208}
    assert findings_difference(expected, [at_record_start]) == \
        "missing 6.4.2/error/record 2 @offset 211; unexpected 6.4.2/error/record 2 @offset 208"
    assert findings_difference(expected, [{**at_record_start, "offset": None}]) is not None
    with pytest.raises(ValueError, match="offset"):
        findings_difference([["6.4.2", "error", 2]], [at_record_start])  # an expectation must state its offset


def test_every_golden_expectation_states_offsets() -> None:
    for exp in sorted((REPO / "conformance" / "golden").glob("*.expect.yaml")):
        doc = load_yaml(exp)
        for profile, findings in (doc.get("validate") or {}).items():
            for f in findings or []:
                assert len(f) == 4 and isinstance(f[3], int), (exp.name, profile, f)


def test_a_finding_at_the_record_start_turns_the_run_red(tmp_path: Path) -> None:
    """A codec that names the record start instead of the code copy field fails the golden case."""
    codec = tmp_path / "python"
    shutil.copytree(REPO / "generated" / "python", codec)
    records = codec / "cbf" / "records.py"  # the kernel of check kind code_copy
    text = records.read_text(encoding="utf-8")
    field = "r.off[bad] + T.RECORD_FIELDS[T.I_COPY].offset"
    assert text.count(field) == 1
    records.write_text(text.replace(field, "r.off[bad]"), encoding="utf-8")
    res = _run(tmp_path, codec, "check.6.4.2")
    assert res.returncode == 1, res.stdout
    assert "python: check.6.4.2.code_copy: FAIL validate: [default] missing" in res.stdout
    assert "@offset" in res.stdout


def test_encode_sends_back_what_the_decode_step_got() -> None:
    """The encode step re-encodes the decode step's answer instead of asking for a second decode
    (which cost a second decode of every file)."""
    path = REPO / "conformance" / "testees" / "python" / "testee.py"
    loader = importlib.util.spec_from_file_location("py_testee", path)
    assert loader is not None and loader.loader is not None
    testee = importlib.util.module_from_spec(loader)
    loader.loader.exec_module(testee)

    class Recorder:
        def __init__(self) -> None:
            self.asked: list[dict[str, Any]] = []

        def ask(self, request: dict[str, Any]) -> dict[str, Any]:
            self.asked.append(request)
            answer: dict[str, Any] = testee.handle(request)
            return answer

    golden = REPO / "conformance" / "golden"
    cases = [c for c in load_cases(golden) if c.expect.get("encode") and c.cbf.stat().st_size < 4096]
    with_decode = next(c for c in cases if c.expect.get("decode") is not None)
    rec = Recorder()
    outcome = run_case(rec, with_decode)
    assert (outcome.status, outcome.message, outcome.judged) == ("pass", "", ("decode", "validate", "encode"))
    ops = [r["op"] for r in rec.asked]
    assert ops.count("decode") == 1 and "encode" in ops
    decoded = testee.handle({"op": "decode", "file": str(with_decode.cbf)})["result"]
    assert all(r["json"] == decoded for r in rec.asked if r["op"] == "encode")


# -- known failures by case and reason (issue 37, point 3) ---------------------------------
def _kaitai_refusal(path: str) -> str:
    return ("decode: failed to decode: {'kind': 'validation', 'offset': 0, 'message': "
            f"'{path}: at pos 128: validation failed: not equal, expected 1, but got 2'}}")


def test_an_entry_by_reason_survives_a_moved_message() -> None:
    """A revision that moves a Kaitai message (seq/3 -> seq/6) keeps the entry's class: still an
    expected failure; the exact message of before would not have matched."""
    before, after = _kaitai_refusal("/types/header_v2/seq/3"), _kaitai_refusal("/types/header_v2/seq/6")
    entry = fixed_entries({"check.x": before}, {})["check.x"]
    assert entry == failure_class(before) == failure_class(after) and "seq" not in entry
    results: dict[str, dict[str, Any]] = {"check.x": {"status": "fail", "message": after}}
    judge(results, {"check.x": entry}, "k.txt")
    assert results["check.x"]["expected_failure"] is True
    exact: dict[str, dict[str, Any]] = {"check.x": {"status": "fail", "message": after}}
    judge(exact, {"check.x": before}, "k.txt")  # an exact-message entry (old lists) pins the bytes
    assert exact["check.x"]["expected_failure"] is False


def test_a_new_failure_is_still_a_failure() -> None:
    """An unlisted case failing, or a listed one failing for another reason, fails the run."""
    refused = _kaitai_refusal("/types/record/seq/1")
    results = {"a": {"status": "fail", "message": refused},
               "b": {"status": "fail", "message": "decode: $.records[0].code: expected 1, got 2"}}
    judge(results, {"b": failure_class(refused)}, "k.txt")
    assert [kind(r) for r in results.values()] == ["fail", "fail"]
    assert "now fails with" in results["b"]["message"] and "differs at $.records[0].code" in results["b"]["message"]
    # findings: which checks at which severity, not where
    missing = "validate: [default] missing 6.4.4/error/record 2 @offset 214; unexpected shape/error/header @offset 0"
    moved = "validate: [default] missing 6.4.4/error/record 3 @offset 230; unexpected shape/error/header @offset 0"
    other = "validate: [default] missing 6.4.5/error/record 2 @offset 214"
    assert failure_class(missing) == failure_class(moved) == \
        "validate: [default] findings differ: missing 6.4.4/error; unexpected shape/error"
    assert not matches(failure_class(missing), other)
    # a testee's words are one line in a list (a case a line): controls and line breaks escaped
    hostile = failure_class("decode: failed to decode: {'kind': 'x\n\x1b[2Jcase.y decode: ok', 'offset': 0}")
    assert "\n" not in hostile and "\x1b" not in hostile and hostile.startswith("decode: refused x")


def test_a_pattern_entry_is_kept_by_fix_and_a_bad_one_refused(tmp_path: Path) -> None:
    msg = _kaitai_refusal("/types/header_v2/seq/6")
    assert matches("~ header_v\\d+/seq/", msg) and not matches("~ record/seq", msg)
    listed = {"a": "~ header_v\\d+/seq/", "b": "~ record/seq"}
    assert fixed_entries({"a": msg, "b": msg}, listed) == {"a": listed["a"], "b": failure_class(msg)}
    bad = tmp_path / "bad.txt"
    bad.write_text("check.x ~ seq/(\n", encoding="utf-8")
    with pytest.raises(FailureListError, match="line 1: case check.x: not a regular expression"):
        read_failures(bad)


def test_fix_rewrites_by_reason_and_reports_stale_entries(tmp_path: Path) -> None:
    """--fix rewrites a list to the run's failures (here: none), prints the diff, and a list naming
    a case that passes, or no golden case at all, fails the run before it."""
    failures = tmp_path / "failures"
    failures.mkdir()
    listed = {"check.6.4.4.arg_checksum": "decode: refused validation", "no.such.case": "decode: refused validation"}
    write_failures(failures / "python.txt", listed, "python")
    golden = tmp_path / "golden"
    golden.mkdir()
    for f in (REPO / "conformance" / "golden").glob("check.6.4.4.arg_checksum.*"):
        shutil.copy(f, golden / f.name)
    cmd = [sys.executable, "-m", "conformance.runner", "--binding", "python", "--failures", str(failures),
           "--golden", str(golden), "--report", str(tmp_path / "r.json")]
    res = subprocess.run(cmd, cwd=REPO, capture_output=True, text=True)
    assert res.returncode == 1
    assert "listed as failing but passes" in res.stdout
    assert "python.txt: names 1 case(s) no golden case has: no.such.case (stale" in res.stdout
    fixed = subprocess.run([*cmd, "--fix"], cwd=REPO, capture_output=True, text=True)
    assert fixed.returncode == 0, fixed.stdout + fixed.stderr
    assert "-check.6.4.4.arg_checksum decode: refused validation" in fixed.stdout
    assert "-no.such.case decode: refused validation" in fixed.stdout
    assert read_failures(failures / "python.txt") == {}
