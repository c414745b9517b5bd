"""The cbf command line under bad input: every bad input through every subcommand (read
from the CLI's own argparse), one line on stderr naming the problem, the documented exit
code, no traceback, bounded memory; an encode killed mid-write leaves no partial output."""

from __future__ import annotations

import argparse
import json
import os
import random
import signal
import subprocess
import sys
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

import pytest
from cli_many import run_many
from conftest import file_maker, locked_file, unprivileged_prefix

from cbf import tables as T
from cbf.cli import EXIT_FINDINGS, EXIT_USAGE, parser

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"
ENV = dict(os.environ, PYTHONPATH=str(REPO / "generated" / "python"))
VALID = GOLDEN / "valid.v3.small.cbf"
# The CLI, then its peak resident memory (VmHWM: ru_maxrss would carry the parent's peak over exec).
RUNNER = r"""
import sys
from cbf.cli import main
try:
    rc = main(sys.argv[2:])
finally:
    peak = [l.split()[1] for l in open("/proc/self/status") if l.startswith("VmHWM")]
    open(sys.argv[1], "w").write(peak[0] if peak else "0")
sys.exit(rc)
"""


def _subcommands() -> dict[str, argparse.ArgumentParser]:
    for action in parser()._actions:
        if isinstance(action, argparse._SubParsersAction):
            return dict(action.choices)
    raise AssertionError("the cbf parser has no subcommands")


def _has_output(sub: argparse.ArgumentParser) -> bool:
    return any("--output" in a.option_strings for a in sub._actions)


SUBCOMMANDS = _subcommands()
# What each subcommand reads: ``encode`` text (CUT or JSON), every other one a CBF file.
TEXT_INPUT = {"encode"}
# ``validate`` reports a broken CBF file as findings (exit 1, on stdout); input that is not
# a CBF file (empty, shorter than the header, both magic numbers wrong) is exit 2 for it too.
REPORTS_FINDINGS = {"validate"}
# These read CBF, or CUT / JSON text when the first bytes are text (issue 16).
EITHER_INPUT = {"convert", "stats", "diff", "plot"}
# What else they need on the command line.
EXTRA_ARGS = {"convert": ["--to-version", next(v.id for v in T.VERSIONS if v.writable)], "diff": [str(VALID)]}


def _cut_with_error_on_line_57() -> str:
    lines = ["header PN-57 TEST"] + ["speed 0.5"] * 55 + ["speed fast"] + ["cutter_off"] * 5
    assert lines[56] == "speed fast"
    return "\n".join(lines) + "\n"


@dataclass(frozen=True)
class Case:
    name: str
    make: Callable[[Path], Path]
    # expected (exit code, substrings of the one stderr line) per kind of subcommand
    cbf_reader: tuple[int, tuple[str, ...]]
    text_reader: tuple[int, tuple[str, ...]]
    validator: tuple[int, tuple[str, ...]] | None = None  # None: as cbf_reader
    text: bool = False  # the input is text: EITHER_INPUT commands answer as text_reader


def _random_100mb(tmp: Path) -> Path:
    p = tmp / "random.cbf"
    rnd = random.Random(7)
    with p.open("wb") as fh:
        for _ in range(100):
            fh.write(rnd.randbytes(1 << 20))
    return p


def _no_permission(tmp: Path) -> Path:
    return locked_file(tmp, VALID.read_bytes())


TRUNCATED_AT = 300  # inside record 5 of valid.v3.small.cbf, which starts at offset 276
LIMIT = T.HEADER_SIZE + (T.LIMITS["max_commands"] + 1) * (T.HEAD_SIZE + T.LIMITS["max_arg_size"])
WRONG_SHAPE = {"header": {"version_major": 3, "version_minor": 0}, "records": [{"code": 999}]}
CASES = [
    Case("empty", file_maker("empty.cbf", b""),
         (EXIT_USAGE, ("offset 0", "0 bytes")), (EXIT_USAGE, ("empty",))),
    Case("directory", lambda tmp: tmp,
         (EXIT_USAGE, ("is a directory",)), (EXIT_USAGE, ("is a directory",))),
    Case("missing", lambda tmp: tmp / "missing.cbf",
         (EXIT_USAGE, ("no such file",)), (EXIT_USAGE, ("no such file",))),
    Case("no_permission", _no_permission,
         (EXIT_USAGE, ("permission denied",)), (EXIT_USAGE, ("permission denied",))),
    Case("random_100mb", _random_100mb,
         (EXIT_USAGE, (f"larger than {LIMIT} bytes",)), (EXIT_USAGE, ("line 1", "offset", "not UTF-8 text"))),
    Case("truncated", file_maker("truncated.cbf", VALID.read_bytes()[:TRUNCATED_AT]),
         (EXIT_USAGE, ("offset 276", "record 5")), (EXIT_USAGE, ("line 1", "offset 0", "not UTF-8 text")),
         (EXIT_FINDINGS, ("4.3", ":276:"))),
    Case("cut_syntax_line_57", file_maker("bad.cut", _cut_with_error_on_line_57().encode()),
         (EXIT_USAGE, ("offset 0", "not a CBF file", "it is text")), (EXIT_USAGE, ("line 57", "speed", "'fast'")),
         text=True),
    Case("json_wrong_shape", file_maker("shape.json", (json.dumps(WRONG_SHAPE, indent=1) + " " * 200).encode()),
         (EXIT_USAGE, ("offset 0", "not a CBF file")), (EXIT_USAGE, ("$.records[0].code",)), text=True),
]


def _run(tmp: Path, *args: str, prefix: Sequence[str] = ()) -> tuple[subprocess.CompletedProcess[str], int]:
    peak_file = tmp / "peak.txt"
    res = subprocess.run([*prefix, sys.executable, "-c", RUNNER, str(peak_file), *args], env=ENV,
                         capture_output=True, text=True, stdin=subprocess.DEVNULL)
    peak = int(peak_file.read_text() or 0)
    peak_file.unlink()
    return res, peak


def _argv(cmd: str, path: Path, out: Path) -> list[str]:
    return [cmd, str(path), *EXTRA_ARGS.get(cmd, [])] + (["-o", str(out)] if _has_output(SUBCOMMANDS[cmd]) else [])


def _expect(case: Case, cmd: str) -> tuple[int, tuple[str, ...]]:
    if cmd in TEXT_INPUT or (cmd in EITHER_INPUT and case.text):
        return case.text_reader
    if cmd in REPORTS_FINDINGS and case.validator is not None:
        return case.validator
    return case.cbf_reader


def _assert_outcome(res: subprocess.CompletedProcess[str], code: int, needles: tuple[str, ...]) -> None:
    assert "Traceback" not in res.stderr + res.stdout, res.stderr
    assert res.returncode == code, (res.returncode, res.stderr, res.stdout[:500])
    if code == EXIT_USAGE:
        lines = res.stderr.splitlines()
        assert len(lines) == 1 and lines[0].startswith("cbf"), res.stderr
        text = lines[0]
    else:  # findings: reported on stdout, nothing on stderr
        assert res.stderr == ""
        text = res.stdout
    for needle in needles:
        assert needle in text, (needle, text)


def test_the_table_covers_the_cli() -> None:
    assert set(SUBCOMMANDS) >= TEXT_INPUT | REPORTS_FINDINGS
    assert [c for c in SUBCOMMANDS if _has_output(SUBCOMMANDS[c])], "no subcommand writes a file"


@pytest.mark.parametrize("case", CASES, ids=lambda c: c.name)
def test_bad_input_through_every_subcommand(case: Case, tmp_path: Path) -> None:
    prefix = unprivileged_prefix() if case.name == "no_permission" else []
    src = tmp_path / "in"
    src.mkdir()
    path = case.make(src)
    out_dir = tmp_path / "out"
    out_dir.mkdir()
    argvs = [_argv(cmd, path, out_dir / f"{cmd}.out") for cmd in SUBCOMMANDS]
    results = run_many(argvs, ENV, prefix=prefix)
    assert list(out_dir.iterdir()) == [], f"output written for bad input: {sorted(out_dir.iterdir())}"
    for cmd, (res, peak_kb) in zip(SUBCOMMANDS, results, strict=True):
        code, needles = _expect(case, cmd)
        _assert_outcome(res, code, (str(path),) + needles)
        if case.name == "random_100mb":
            # refused without reading it all: peak memory far below the file's 100 MB
            assert peak_kb < 60_000, f"{cmd}: peak RSS {peak_kb} kB for a 100 MB input"


def test_output_in_a_missing_folder(tmp_path: Path) -> None:
    cut = tmp_path / "a.cut"
    inputs = {cmd: cut if cmd in TEXT_INPUT else VALID for cmd in SUBCOMMANDS}
    writers = [cmd for cmd in SUBCOMMANDS if _has_output(SUBCOMMANDS[cmd])]
    targets = [tmp_path / "no" / "such" / f"{cmd}.out" for cmd in writers]
    # one process, in order: the decode writes the CUT text the encode then reads
    argvs = [_argv(cmd, inputs[cmd], target) for cmd, target in zip(writers, targets, strict=True)]
    (res, _), *results = run_many([["decode", str(VALID), "--to", "cut", "-o", str(cut)], *argvs], ENV)
    assert res.returncode == 0, res.stderr
    for target, (res, _) in zip(targets, results, strict=True):
        _assert_outcome(res, EXIT_USAGE, (str(target), "does not exist"))
    assert not (tmp_path / "no").exists()


# -- an encode killed mid-write ------------------------------------------------------------------
# The CLI writes its output in chunks through os.write: after half of the first chunk this
# runner says so on stderr and stops itself, and the test kills it (SIGKILL) right there.
KILLED_MID_WRITE = r"""
import os, signal, sys
from cbf.cli import main
real = os.write
def write(fd, data):
    if fd > 2:
        real(fd, bytes(data[:max(1, len(data) // 2)]))
        sys.stderr.write("MID-WRITE\n")
        sys.stderr.flush()
        os.kill(os.getpid(), signal.SIGSTOP)
    return real(fd, data)
os.write = write
sys.exit(main(sys.argv[1:]))
"""


def _big_cut(records: int) -> str:
    lines = ["header PN-KILL"]
    x = 0.0
    for i in range(records):
        nx = float((i % 500) + 1)
        lines.append(f"line < {x:g}, 0, 0 > < {nx:g}, 0, 0 >")
        x = nx
    return "\n".join(lines) + "\n"


def test_an_encode_killed_mid_write_leaves_the_target_whole(tmp_path: Path) -> None:
    src = tmp_path / "big.cut"
    src.write_text(_big_cut(8000))
    target = tmp_path / "out.cbf"
    previous = VALID.read_bytes()
    target.write_bytes(previous)
    proc = subprocess.Popen([sys.executable, "-c", KILLED_MID_WRITE, "encode", str(src), "-o", str(target)],
                            env=ENV, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    try:
        line = proc.stderr.readline() if proc.stderr else ""
        assert line == "MID-WRITE\n", "the encode finished without writing through os.write: " + line
        proc.send_signal(signal.SIGKILL)
        proc.wait()
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
        if proc.stderr:
            proc.stderr.close()
    assert proc.returncode == -signal.SIGKILL
    assert target.read_bytes() == previous  # the complete previous content, not a partial new one
    assert sorted(p.name for p in tmp_path.iterdir()) == ["big.cut", "out.cbf"]  # no temp file left
    # and the same encode, left alone, replaces it whole
    res = subprocess.run([sys.executable, "-m", "cbf", "encode", str(src), "-o", str(target)], env=ENV,
                         capture_output=True, text=True)
    assert res.returncode == 0, res.stderr
    assert len(target.read_bytes()) > 1 << 16 and target.read_bytes() != previous
    assert sorted(p.name for p in tmp_path.iterdir()) == ["big.cut", "out.cbf"]


def test_a_bad_cutter_table_is_named_once(tmp_path: Path) -> None:
    table = tmp_path / "cutters.csv"
    table.write_text("name,length,radius\nBALL6,50,3\nFLAT4,forty,2\n")
    res, _ = _run(tmp_path, "validate", str(VALID), "--cutters", str(table))
    _assert_outcome(res, EXIT_USAGE, (str(table), "line 3"))
    assert res.stderr.count("line 3") == 1, res.stderr


@pytest.mark.parametrize(("name", "text", "needle"), [
    ("deep", "[" * 100_000 + "]" * 100_000, "nested too deep"),
    ("long_number", '{"header": ' + "1" * 5000 + "}", "digits"),
    ("not_json", '{"header": {"version_major": 3,}}', "line 1: not JSON"),
])
def test_json_the_parser_chokes_on(name: str, text: str, needle: str, tmp_path: Path) -> None:
    src = tmp_path / f"{name}.json"
    src.write_text(text)
    res, _ = _run(tmp_path, "encode", str(src), "-o", str(tmp_path / "out.cbf"))
    _assert_outcome(res, EXIT_USAGE, (str(src), needle))
    assert not (tmp_path / "out.cbf").exists()


def test_a_byte_order_mark_is_accepted(tmp_path: Path) -> None:
    cut = tmp_path / "a.cut"
    res, _ = _run(tmp_path, "decode", str(VALID), "--to", "cut", "-o", str(cut))
    assert res.returncode == 0, res.stderr
    cut.write_bytes(b"\xef\xbb\xbf" + cut.read_bytes())
    res, _ = _run(tmp_path, "encode", str(cut), "-o", str(tmp_path / "a.cbf"))
    assert res.returncode == 0, res.stderr
    assert (tmp_path / "a.cbf").read_bytes() == VALID.read_bytes()


def test_text_is_read_in_chunks_without_splitting_characters(tmp_path: Path) -> None:
    from cbf.cli import _Fail, _read_text

    p = tmp_path / "long.cut"
    head = "comment " + "x" * ((1 << 20) - 9)  # the 2-byte 'é' straddles the first chunk boundary
    p.write_bytes((head + "\u00e9\n" + "comment \u00e9\n").encode())
    assert _read_text(str(p), 1 << 22) == head + "\u00e9\ncomment \u00e9\n"
    p.write_bytes((head + "\n" + "ok\n").encode() + b"\xc3(")
    with pytest.raises(_Fail, match=rf"line 3 \(offset {(1 << 20) + 3}\): byte 0xC3"):
        _read_text(str(p), 1 << 22)
    p.write_bytes(b"x" * 100)
    with pytest.raises(_Fail, match="larger than 99 bytes"):
        _read_text(str(p), 99)


BAD_USAGE = [[], ["nope"], *([cmd] for cmd in SUBCOMMANDS), *([cmd, "x", "--nope"] for cmd in SUBCOMMANDS)]


@pytest.fixture(scope="module")
def bad_usage() -> dict[str, subprocess.CompletedProcess[str]]:
    """Each bad command line's result, all from one process (cli_many)."""
    return {" ".join(argv): res for argv, (res, _) in zip(BAD_USAGE, run_many(BAD_USAGE, ENV), strict=True)}


@pytest.mark.parametrize("argv", BAD_USAGE, ids=" ".join)
def test_bad_usage_is_one_line(argv: list[str], bad_usage: dict[str, subprocess.CompletedProcess[str]]) -> None:
    _assert_outcome(bad_usage[" ".join(argv)], EXIT_USAGE, ("--help",))


@pytest.mark.parametrize("unnamed", [True, False], ids=["O_TMPFILE", "named_temp"])
def test_output_replaces_whole_with_ordinary_permissions(unnamed: bool, tmp_path: Path,
                                                         monkeypatch: pytest.MonkeyPatch) -> None:
    from cbf import cli

    if not unnamed:
        monkeypatch.delattr(os, "O_TMPFILE", raising=False)
    target = tmp_path / "out.cbf"
    target.write_bytes(b"old")
    old_umask = os.umask(0o027)
    try:
        cli._write(str(target), b"new" * 50_000)
    finally:
        os.umask(old_umask)
    assert target.read_bytes() == b"new" * 50_000
    assert target.stat().st_mode & 0o777 == 0o640  # 0666 under the umask, not mkstemp's 0600
    assert [p.name for p in tmp_path.iterdir()] == ["out.cbf"]
