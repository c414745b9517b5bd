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
from typing import Any

import pytest
from cli_many import run_many
from conftest import ENV, file_maker, locked_file, unprivileged_prefix

from cbf import tables as T
from cbf.cli import EXIT_FINDINGS, EXIT_USAGE, parser
from cbf.optfiles import RULES

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"
VALID = GOLDEN / "valid.v3.small.cbf"
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
# ``validate`` and ``hexdump`` report a broken CBF file as findings (exit 1, on stdout, each as
# FILE:OFFSET: ...; hexdump marks the row holding the offset with it); input that is not a CBF file
# (empty, shorter than the header, both magic numbers wrong) is exit 2 for it too.
REPORTS_FINDINGS = {"validate", "hexdump"}  # hexdump marks the findings in the bytes, exit 1 on an error
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


Result = tuple[subprocess.CompletedProcess[str], int]  # cli_many's: the outcome, the peak memory in kB
Ran = tuple[Path, Path, list[Result]]  # a case's input, its output folder, every subcommand's result
Shared = dict[str, tuple[Any, list[Result]]]  # the one_process fixture's


def _case_lines(cases: Sequence[Case], tmp: Path) -> tuple[dict[str, tuple[Path, Path]], list[list[str]]]:
    """Each case's input and output folder, made in tmp, and the command lines running every
    subcommand on each input, case by case."""
    made: dict[str, tuple[Path, Path]] = {}
    argvs = []
    for case in cases:
        src, out_dir = tmp / case.name / "in", tmp / case.name / "out"
        src.mkdir(parents=True)
        out_dir.mkdir()
        made[case.name] = (case.make(src), out_dir)
        argvs += [_argv(cmd, made[case.name][0], out_dir / f"{cmd}.out") for cmd in SUBCOMMANDS]
    return made, argvs


def _ran(made: dict[str, tuple[Path, Path]], results: list[Result]) -> dict[str, Ran]:
    n = len(SUBCOMMANDS)
    return {name: (path, out, results[k * n:(k + 1) * n]) for k, (name, (path, out)) in enumerate(made.items())}


# a cutter table of the spec's columns (the name's first) whose second row holds a word for a number
_COLUMNS: list[str] = RULES["cutter_table"]["columns"]
CUTTER_TABLE = "".join(",".join(row) + "\n" for row in (_COLUMNS, ["BALL6"] + ["3"] * (len(_COLUMNS) - 1),
                                                         ["FLAT4", "forty"] + ["2"] * (len(_COLUMNS) - 2)))
JSON_CHOKES = [
    ("deep", "[" * 100_000 + "]" * 100_000, "nested too deep"),
    ("long_number", '{"header": ' + "1" * 5000 + "}", "digits"),
    ("not_json", '{"header": {"version_major": 3,}}', "line 1: not JSON"),
]


def _lone_lines(tmp: Path) -> tuple[dict[str, Path], list[list[str]]]:
    """The input of test_a_bad_cutter_table_is_named_once and of each test_json_the_parser_chokes_on,
    made in tmp, and their command lines."""
    tmp.mkdir()
    inputs = {"cutters": tmp / "cutters.csv"}
    inputs["cutters"].write_text(CUTTER_TABLE)
    argvs = [["validate", str(VALID), "--cutters", str(inputs["cutters"])]]
    for name, text, _ in JSON_CHOKES:
        (tmp / name).mkdir()
        src = inputs[name] = tmp / name / f"{name}.json"
        src.write_text(text)
        argvs.append(["encode", str(src), "-o", str(tmp / name / "out.cbf")])
    return inputs, argvs


BAD_USAGE = [[], ["nope"], *([cmd] for cmd in SUBCOMMANDS), *([cmd, "x", "--nope"] for cmd in SUBCOMMANDS)]


def _missing_folder_lines(tmp: Path) -> tuple[list[Path], list[list[str]]]:
    """test_output_in_a_missing_folder's targets and command lines, in order: a decode writes the
    CUT text the encode then reads."""
    tmp.mkdir()
    cut = tmp / "a.cut"
    inputs = {cmd: cut if cmd in TEXT_INPUT else VALID for cmd in SUBCOMMANDS}
    writers = [cmd for cmd in SUBCOMMANDS if _has_output(SUBCOMMANDS[cmd])]
    targets = [tmp / "no" / "such" / f"{cmd}.out" for cmd in writers]
    argvs = [_argv(cmd, inputs[cmd], target) for cmd, target in zip(writers, targets, strict=True)]
    return targets, [["decode", str(VALID), "--to", "cut", "-o", str(cut)], *argvs]


def _bom_lines(tmp: Path) -> tuple[tuple[int, Path], list[list[str]]]:
    """test_a_byte_order_mark_is_accepted's input, CUT text as `decode --to cut` writes it (run in
    this process) with a byte order mark put before it; the decode's exit code, the encode's target
    and its command line."""
    from cbf.cli import main

    tmp.mkdir()
    cut = tmp / "a.cut"
    decoded = main(["decode", str(VALID), "--to", "cut", "-o", str(cut)])
    if cut.exists():
        cut.write_bytes(b"\xef\xbb\xbf" + cut.read_bytes())
    return (decoded, tmp / "a.cbf"), [["encode", str(cut), "-o", str(tmp / "a.cbf")]]


def _case_group(tmp: Path) -> tuple[dict[str, tuple[Path, Path]], list[list[str]]]:
    # no_permission needs a process held to the mode bits (its test runs it); random_100mb comes
    # first, so that its peak memory is measured as in a process of its own
    return _case_lines(sorted((c for c in CASES if c.name != "no_permission"), key=lambda c: c.name != "random_100mb"),
                       tmp)


# What each group of command lines needs (made in a folder of its own) and the lines, in order.
GROUPS: dict[str, Callable[[Path], tuple[Any, list[list[str]]]]] = {
    "cases": _case_group, "lone": _lone_lines, "usage": lambda tmp: (None, BAD_USAGE),
    "missing_folder": _missing_folder_lines, "bom": _bom_lines}


@pytest.fixture(scope="module")
def one_process(tmp_path_factory: pytest.TempPathFactory) -> Shared:
    """Every command line of this module that needs no process of its own, all in one process
    (cli_many: each judged by its own exit code, output and peak memory, as if alone) instead of
    one process a test (0.22 CPU s of interpreter and imports each); by group, what the group's
    test needs to judge them and their results."""
    tmp = tmp_path_factory.mktemp("one_process")
    groups = {name: make(tmp / name) for name, make in GROUPS.items()}
    results = run_many([argv for _, argvs in groups.values() for argv in argvs], ENV)
    out: Shared = {}
    for name, (made, argvs) in groups.items():
        out[name], results = (made, results[:len(argvs)]), results[len(argvs):]
    return out


def test_the_table_covers_the_cli() -> None:
    assert set(SUBCOMMANDS) >= TEXT_INPUT | REPORTS_FINDINGS
    assert [c for c in SUBCOMMANDS if _has_output(SUBCOMMANDS[c])], "no subcommand writes a file"


@pytest.mark.parametrize("case", CASES, ids=lambda c: c.name)
def test_bad_input_through_every_subcommand(case: Case, tmp_path: Path, one_process: Shared) -> None:
    if case.name == "no_permission":
        made, argvs = _case_lines([case], tmp_path)
        path, out_dir, results = _ran(made, run_many(argvs, ENV, prefix=unprivileged_prefix()))[case.name]
    else:
        path, out_dir, results = _ran(*one_process["cases"])[case.name]
    assert list(out_dir.iterdir()) == [], f"output written for bad input: {sorted(out_dir.iterdir())}"
    for cmd, (res, peak_kb) in zip(SUBCOMMANDS, results, strict=True):
        code, needles = _expect(case, cmd)
        _assert_outcome(res, code, (str(path), *needles))
        if case.name == "random_100mb":
            # refused without reading it all: peak memory far below the file's 100 MB
            assert peak_kb < 60_000, f"{cmd}: peak RSS {peak_kb} kB for a 100 MB input"


def test_output_in_a_missing_folder(one_process: Shared) -> None:
    targets, ((res, _), *results) = one_process["missing_folder"]
    assert res.returncode == 0, res.stderr
    for target, (res, _) in zip(targets, results, strict=True):
        _assert_outcome(res, EXIT_USAGE, (str(target), "does not exist"))
    assert not (targets[0].parents[1]).exists()


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


def test_a_bad_cutter_table_is_named_once(one_process: Shared) -> None:
    inputs, results = one_process["lone"]
    table, (res, _) = inputs["cutters"], results[list(inputs).index("cutters")]
    assert table.read_text() == CUTTER_TABLE
    _assert_outcome(res, EXIT_USAGE, (str(table), "line 3"))
    assert res.stderr.count("line 3") == 1, res.stderr


@pytest.mark.parametrize(("name", "text", "needle"), JSON_CHOKES)
def test_json_the_parser_chokes_on(name: str, text: str, needle: str, one_process: Shared) -> None:
    inputs, results = one_process["lone"]
    src, (res, _) = inputs[name], results[list(inputs).index(name)]
    assert src.read_text() == text
    _assert_outcome(res, EXIT_USAGE, (str(src), needle))
    assert not (src.parent / "out.cbf").exists()


def test_a_byte_order_mark_is_accepted(one_process: Shared) -> None:
    (decoded, target), ((res, _),) = one_process["bom"]
    assert decoded == 0
    assert res.returncode == 0, res.stderr
    assert target.read_bytes() == VALID.read_bytes()


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


@pytest.mark.parametrize("argv", BAD_USAGE, ids=" ".join)
def test_bad_usage_is_one_line(argv: list[str], one_process: Shared) -> None:
    _, results = one_process["usage"]
    _assert_outcome(results[BAD_USAGE.index(argv)][0], EXIT_USAGE, ("--help",))


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
