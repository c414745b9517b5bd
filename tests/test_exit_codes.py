"""Both command-line tools, `cbf` (Python) and `cbf-c` (C), against ONE table of inputs
and exit codes: the README's "Exit codes and bad input" table (issue 13 item 14).

Each row is an input; for `validate` and for the reader (`cbf info`, `cbf-c dump`) it
gives the exit code and what the output must say. Exit 2 is one line on stderr naming
the file; exit 0 and 1 say nothing on stderr. The findings of both tools are compared too.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import pytest

import cbf
from cbf import tables as T
from cbf.codec import decode

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"
VALID = GOLDEN / "valid.v3.small.cbf"
ENV = dict(os.environ, PYTHONPATH=str(REPO / "generated" / "python"))
STRICT = ["-std=c99", "-Wall", "-Wextra", "-Wpedantic", "-Wconversion", "-Wsign-conversion", "-Wdouble-promotion",
          "-Werror"]
# Root reads any file whatever its mode: without these capabilities it is held to the mode bits.
AS_UNPRIVILEGED_ROOT = ["setpriv", "--bounding-set", "-dac_override,-dac_read_search"]
OK, FINDINGS, USAGE = 0, 1, 2
LIMIT = T.HEADER_SIZE + (T.LIMITS["max_commands"] + 1) * (T.HEAD_SIZE + T.LIMITS["max_arg_size"])


def _check_id(kind: str) -> str:
    return str(T.checks_of(kind)[0]["id"])


def _cut_record() -> tuple[bytes, int, int]:
    """VALID cut in the middle of its last record: (bytes, that record's offset, its index)."""
    data = VALID.read_bytes()
    records = decode(data).records
    last = records[-1]
    assert last.offset is not None and last.arg_size > 1
    return data[:last.offset + T.HEAD_SIZE + last.arg_size // 2], last.offset, len(records) - 1


def _arg_flipped() -> tuple[bytes, int]:
    """VALID with one argument byte of record 0 changed: the argument checksum fails (an error finding)."""
    data = bytearray(VALID.read_bytes())
    first = decode(bytes(data)).records[0]
    assert first.offset is not None and first.arg_size > 0
    data[first.offset + T.HEAD_SIZE] ^= 0x01
    return bytes(data), first.offset


CUT, CUT_AT, CUT_INDEX = _cut_record()
FLIPPED, FLIPPED_AT = _arg_flipped()


@dataclass(frozen=True)
class Row:
    name: str
    make: Callable[[Path], Path]
    validate: int
    read: int
    says: tuple[str, ...] = ()  # in the one stderr line (exit 2), or on stdout (exit 0 and 1)
    validate_says: tuple[str, ...] | None = None  # when validate says something else than the reader
    as_unprivileged_root: bool = False


def _file(name: str, data: bytes) -> Callable[[Path], Path]:
    def make(tmp: Path) -> Path:
        p = tmp / name
        p.write_bytes(data)
        return p
    return make


def _locked(tmp: Path) -> Path:
    p = tmp / "locked.cbf"
    p.write_bytes(VALID.read_bytes())
    p.chmod(0)
    return p


def _too_large(tmp: Path) -> Path:
    p = tmp / "huge.cbf"
    with p.open("wb") as fh:
        fh.write(VALID.read_bytes())
        fh.truncate(LIMIT + 1)  # sparse: the valid file, then zeros past the largest CBF file
    return p


# THE table (README, "Exit codes and bad input").
TABLE = [
    Row("valid", _file("valid.cbf", VALID.read_bytes()), OK, OK),
    Row("error_finding", _file("flipped.cbf", FLIPPED), FINDINGS, OK,
        validate_says=(f":{FLIPPED_AT + T.ARG_CHECKSUM.offset}: error {_check_id('arg_checksum')} (record 0)",)),
    Row("record_cut", _file("cut.cbf", CUT), FINDINGS, USAGE, (f"offset {CUT_AT}", f"record {CUT_INDEX}"),
        validate_says=(f":{CUT_AT}: error {_check_id('truncated_record')} (record {CUT_INDEX})",)),
    Row("empty", _file("empty.cbf", b""), USAGE, USAGE,
        ("offset 0", "file is 0 bytes", f"the header needs {T.HEADER_SIZE}")),
    Row("shorter_than_header", _file("short.cbf", VALID.read_bytes()[:T.HEADER_SIZE - 1]), USAGE, USAGE,
        ("offset 0", f"file is {T.HEADER_SIZE - 1} bytes", f"the header needs {T.HEADER_SIZE}")),
    Row("text", _file("notes.cbf", b"These are my notes, not a cutfile.\n" * 20), USAGE, USAGE,
        (f"offset {T.START.offset}: not a CBF file", "text")),
    Row("missing", lambda tmp: tmp / "missing.cbf", USAGE, USAGE, ("no such file",)),
    Row("directory", lambda tmp: tmp, USAGE, USAGE, ("is a directory",)),
    Row("no_permission", _locked, USAGE, USAGE, ("permission denied",), as_unprivileged_root=True),
    Row("too_large", _too_large, USAGE, USAGE, (f"larger than {LIMIT} bytes",)),
]


# -- the two tools ----------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def cbf_c(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """cbf-c, compiled from the generated source as `make c-build` does."""
    cc = shutil.which("gcc")
    if cc is None:
        pytest.skip("gcc not installed")
    exe = tmp_path_factory.mktemp("cbf-c") / "cbf-c"
    subprocess.run([cc, *STRICT, "-O1", "-o", str(exe), str(REPO / "generated" / "c" / "cbf_tool.c"), "-lm"],
                   check=True, capture_output=True)
    return exe


TOOLS = ["cbf", "cbf-c"]
READER = {"cbf": "info", "cbf-c": "dump"}


def _argv(tool: str, exe: Path) -> list[str]:
    return [sys.executable, "-m", "cbf"] if tool == "cbf" else [str(exe)]


def _run(argv: list[str], prefix: list[str] | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*(prefix or []), *argv], env=ENV, capture_output=True, text=True,
                          stdin=subprocess.DEVNULL, errors="replace")


def _assert_outcome(tool: str, res: subprocess.CompletedProcess[str], path: Path, code: int,
                    says: tuple[str, ...]) -> None:
    assert "Traceback" not in res.stderr + res.stdout
    assert res.returncode == code, (tool, res.returncode, res.stderr, res.stdout[:400])
    if code == USAGE:
        lines = res.stderr.splitlines()
        assert len(lines) == 1 and lines[0].startswith(f"{tool}: {path}: "), res.stderr
        assert res.stdout == ""
        text = lines[0]
    else:
        assert res.stderr == ""
        text = res.stdout
    for needle in says:
        assert needle in text, (tool, needle, text)


@pytest.mark.parametrize("tool", TOOLS)
@pytest.mark.parametrize("row", TABLE, ids=lambda r: r.name)
@pytest.mark.parametrize("op", ["validate", "read"])
def test_exit_code_table(tool: str, row: Row, op: str, cbf_c: Path, tmp_path: Path) -> None:
    prefix: list[str] = []
    if row.as_unprivileged_root and os.geteuid() == 0:
        if shutil.which(AS_UNPRIVILEGED_ROOT[0]) is None:
            pytest.skip("running as root, which reads any file whatever its mode, and setpriv is missing")
        prefix = AS_UNPRIVILEGED_ROOT
    path = row.make(tmp_path)
    sub = "validate" if op == "validate" else READER[tool]
    res = _run([*_argv(tool, cbf_c), sub, str(path)], prefix)
    code = row.validate if op == "validate" else row.read
    says = row.validate_says if op == "validate" and row.validate_says is not None else row.says
    _assert_outcome(tool, res, path, code, says)
    if op == "validate" and code != USAGE:
        verdict = "FAIL" if code == FINDINGS else "ok"
        assert res.stdout.splitlines()[-1].startswith(f"{path}: {verdict}: "), res.stdout


@pytest.mark.parametrize("tool", TOOLS)
@pytest.mark.parametrize("argv", [["validate"], ["validate", "--no-such-option", str(VALID)], ["no-such-command"]],
                         ids=["no_file", "unknown_option", "unknown_command"])
def test_bad_usage_exits_2(tool: str, argv: list[str], cbf_c: Path) -> None:
    res = _run([*_argv(tool, cbf_c), *argv])
    assert res.returncode == USAGE and res.stderr and "Traceback" not in res.stderr, res


@pytest.mark.parametrize("row", [r for r in TABLE if r.validate != USAGE], ids=lambda r: r.name)
def test_both_tools_print_the_same_findings(row: Row, cbf_c: Path, tmp_path: Path) -> None:
    """Finding lines agree (README's `file:offset: severity check (record N): message`) but for the message."""
    path = row.make(tmp_path)

    def findings(tool: str) -> set[str]:
        res = _run([*_argv(tool, cbf_c), "validate", "--max-findings", "0", str(path)] if tool == "cbf"
                   else [*_argv(tool, cbf_c), "validate", str(path)])
        return {ln.split("): ", 1)[0] for ln in res.stdout.splitlines() if ln.startswith(f"{path}:") and "): " in ln}

    py, c = findings("cbf"), findings("cbf-c")
    assert py == c
    assert bool(py) == (row.validate == FINDINGS)


def test_cbf_c_validate_exits_with_the_worst_status(cbf_c: Path, tmp_path: Path) -> None:
    flipped = _file("flipped.cbf", FLIPPED)(tmp_path)
    assert _run([str(cbf_c), "validate", str(VALID), str(flipped)]).returncode == FINDINGS
    res = _run([str(cbf_c), "validate", str(flipped), str(tmp_path / "missing.cbf"), str(VALID)])
    assert res.returncode == USAGE and f"{VALID}: ok: " in res.stdout


def test_cbf_c_version(cbf_c: Path) -> None:
    """`cbf-c --version`: the toolkit version and the spec revision, in the format `cbf --version` uses."""
    res = _run([str(cbf_c), "--version"])
    assert res.returncode == 0 and res.stderr == ""
    assert res.stdout == f"cbf-c {cbf.__version__} (spec {cbf.SPEC_REVISION})\n"


def test_cbf_validate_json_prints_nothing_for_input_that_is_not_cbf(cbf_c: Path, tmp_path: Path) -> None:
    for row in (r for r in TABLE if r.validate == USAGE and not r.as_unprivileged_root):
        path = row.make(tmp_path)
        res = _run([*_argv("cbf", cbf_c), "validate", "--json", str(path)])
        _assert_outcome("cbf", res, path, USAGE, row.says)
