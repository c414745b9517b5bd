"""The cbf command line: exit codes, one-line errors with offset or line, atomic output."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest
from cli_many import run_many
from conftest import ENV

from cbf import tables as T

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"


def cbf(*args: str, stdin: bytes | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "cbf", *args], env=ENV, capture_output=True, text=True,
                          input=stdin.decode("latin-1") if stdin is not None else None)


def _one_line_error(res: subprocess.CompletedProcess[str]) -> str:
    assert res.returncode == 2, res
    assert "Traceback" not in res.stderr
    lines = res.stderr.strip().splitlines()
    assert len(lines) == 1, res.stderr
    return lines[0]


def test_good_file_validates() -> None:
    res = cbf("validate", str(GOLDEN / "valid.v3.all_commands.cbf"))
    assert res.returncode == 0 and "ok: 0 error(s)" in res.stdout


def test_flipped_byte_reports_clause_and_offset(tmp_path: Path) -> None:
    data = bytearray((GOLDEN / "valid.v3.small.cbf").read_bytes())
    data[218] ^= 0x10  # inside SPEED's argument
    p = tmp_path / "flip.cbf"
    p.write_bytes(bytes(data))
    res = cbf("validate", str(p), "--json")
    assert res.returncode == 1
    doc = json.loads(res.stdout)
    assert doc["file"] == str(p) and doc["profile"] == "default"
    checks = {(f["check"], f["record"], f["offset"]) for f in doc["findings"]}
    assert ("6.4.4", 2, 214) in checks and ("6.2.1", None, 4) in checks
    assert set(doc["findings"][0]) == {"check", "severity", "record", "offset", "message"}


def test_truncated_file(tmp_path: Path) -> None:
    p = tmp_path / "cut.cbf"
    p.write_bytes((GOLDEN / "valid.v3.small.cbf").read_bytes()[:300])
    assert "offset 276" in _one_line_error(cbf("decode", str(p)))
    res = cbf("validate", str(p))
    assert res.returncode == 1 and "error 4.3 (record 5)" in res.stdout


def test_text_file_renamed_cbf(tmp_path: Path) -> None:
    p = tmp_path / "notes.cbf"
    p.write_text("These are my notes, not a cutfile.\n" * 20)
    # the diagnosis, as decode gives it, instead of findings that would all follow from it (README)
    line = _one_line_error(cbf("validate", str(p)))
    assert line.startswith(f"cbf: {p}: offset 0: not a CBF file") and "it is text" in line
    assert "not a CBF file" in _one_line_error(cbf("decode", str(p)))


def test_validate_prints_at_most_max_findings(tmp_path: Path) -> None:
    p = tmp_path / "notes.cbf"
    # a CBF header, then text where records should be: hundreds of findings
    header = (GOLDEN / "valid.v3.small.cbf").read_bytes()[:T.HEADER_SIZE]
    p.write_bytes(header + b"These are my notes, not a cutfile.\n" * 200)
    flags: list[tuple[tuple[str, ...], int | None]] = [((), 50), (("--max-findings", "7"), 7),
                                                        (("--max-findings", "0"), None)]
    # one process runs them all (cli_many), each with its own streams and exit code
    (whole, _), *runs, (negative, _) = run_many([["validate", str(p), "--json"],
                                                 *(["validate", str(p), *flag] for flag, _ in flags),
                                                 ["validate", str(p), "--max-findings", "-1"]], ENV)
    every = json.loads(whole.stdout)["findings"]
    errors = sum(f["severity"] == "error" for f in every)
    assert len(every) > 60
    for (flag, limit), (res, _) in zip(flags, runs, strict=True):
        shown = len(every) if limit is None else limit
        assert res.returncode == 1
        lines = res.stdout.splitlines()
        findings = [ln for ln in lines if ": error " in ln or ": warning " in ln]
        assert len(findings) == shown, flag
        more = [ln for ln in lines if "more finding(s) not shown" in ln]
        assert more == ([f"{p}: {len(every) - shown} more finding(s) not shown "
                         "(--max-findings 0 prints all)"] if shown < len(every) else [])
        # the verdict still counts every finding
        assert lines[-1] == f"{p}: FAIL: {errors} error(s), {len(every) - errors} warning(s) [profile default]"
    assert "--max-findings" in _one_line_error(negative)


@pytest.mark.parametrize("cmd", ["decode", "validate", "info"])
def test_unreadable_inputs(cmd: str, tmp_path: Path) -> None:
    assert "no such file" in _one_line_error(cbf(cmd, str(tmp_path / "missing.cbf")))
    assert "is a directory" in _one_line_error(cbf(cmd, str(tmp_path)))


def test_stdin_and_stdout() -> None:
    data = (GOLDEN / "valid.v3.small.cbf").read_bytes()
    res = subprocess.run([sys.executable, "-m", "cbf", "decode", "-", "--to", "json"], env=ENV, input=data,
                         capture_output=True)
    assert res.returncode == 0 and json.loads(res.stdout)["header"]["command_count"] == 14


def test_encode_round_trip_and_atomic_output(tmp_path: Path) -> None:
    src = GOLDEN / "valid.v3.small.cbf"
    cut = tmp_path / "a.cut"
    assert cbf("decode", str(src), "--to", "cut", "-o", str(cut)).returncode == 0
    out = tmp_path / "a.cbf"
    assert cbf("encode", str(cut), "-o", str(out)).returncode == 0
    assert out.read_bytes() == src.read_bytes()
    # a failing encode leaves the previous output untouched and no temp file behind
    lines = cut.read_text().splitlines()
    lines[3] = "speed fast"
    cut.write_text("\n".join(lines) + "\n")
    msg = _one_line_error(cbf("encode", str(cut), "-o", str(out)))
    assert "line 4" in msg and "speed" in msg
    assert out.read_bytes() == src.read_bytes()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.cbf", "a.cut"]
    assert "does not exist" in _one_line_error(cbf("encode", str(cut), "-o", str(tmp_path / "no" / "x.cbf")))


def test_json_of_the_wrong_shape(tmp_path: Path) -> None:
    p = tmp_path / "x.json"
    p.write_text(json.dumps({"header": {"version_major": 3, "version_minor": 0}, "records": [{"code": 999}]}))
    assert "$.records[0].code" in _one_line_error(cbf("encode", str(p), "-o", str(tmp_path / "x.cbf")))
    p.write_text("{not json")
    assert "line 1: not JSON" in _one_line_error(cbf("encode", str(p), "-o", str(tmp_path / "x.cbf")))


def test_bad_usage_exits_2() -> None:
    res = cbf("validate")
    assert res.returncode == 2 and "Traceback" not in res.stderr
    assert cbf("validate", "x", "--profile", "nope").returncode == 2


def test_info_counts_commands() -> None:
    res = cbf("info", str(GOLDEN / "valid.v3.small.cbf"))
    assert res.returncode == 0
    assert "  CHECKPOINT: 2" in res.stdout and "version: 3.0 (3.0)" in res.stdout
