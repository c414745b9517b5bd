"""`cbf-c encode FILE -o OUT` against `cbf encode FILE -o OUT`: the same command line for CUT input, the
same bytes, the same refusals (one line each, the tool's name aside) and the same way of writing (README,
"Exit codes and bad input": an output written atomically, every write checked, nothing written on a
refusal). What the README table does not say row by row: --version, a disk that fills part way (a file
size limit, RLIMIT_FSIZE, with SIGXFSZ ignored: the write fails with EFBIG as on a full disk), a standard
output that fails (for every command), a symlink as the output, the new file's mode. Every expectation is
what `cbf` does on the same input; the inputs are the CUT text cbf writes for a golden file."""

from __future__ import annotations

import os
import resource
import signal
import stat
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import pytest
from c_programs import built
from conftest import ENV
from test_exit_codes import HEAD_LINES, NO_TEXT_REC, READER

import cbf
from cbf import tables as T
from cbf.codec import decode

REPO = Path(__file__).resolve().parents[1]
VALID = REPO / "conformance" / "golden" / "valid.v3.small.cbf"
MODEL = decode(VALID.read_bytes())
WRITABLE = [v.id for v in T.VERSIONS if v.writable]
VERSION_KW = T.CUT["extensions"]["version_keyword"]


@pytest.fixture(scope="module")
def cbf_c() -> Path:
    return built("cbf-c")


def _run(tool: str, cbf_c: Path, argv: list[str], cwd: Path, limit: int | None = None,
         stdout: object = subprocess.PIPE, stdin: object = subprocess.DEVNULL) -> subprocess.CompletedProcess[bytes]:
    exe = [str(cbf_c)] if tool == "cbf-c" else [sys.executable, "-m", "cbf"]
    pre: Callable[[], None] | None = None
    if limit is not None:
        def pre() -> None:  # a file may grow to `limit` bytes; a write past it fails (EFBIG), no signal
            signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
            resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))
    return subprocess.run([*exe, *argv], cwd=cwd, env=ENV, stdout=stdout, stderr=subprocess.PIPE,
                          stdin=stdin, preexec_fn=pre, timeout=120)


def _line(res: subprocess.CompletedProcess[bytes], tool: str) -> str:
    """The one line a refusal says, without the tool's name."""
    lines = res.stderr.decode().splitlines()
    assert res.returncode == 2 and len(lines) == 1 and lines[0].startswith(f"{tool}: "), (tool, res)
    return lines[0][len(tool) + 2:]


def _both(cbf_c: Path, argv: list[str], cwd: Path, **kw: object) -> dict[str, subprocess.CompletedProcess[bytes]]:
    return {tool: _run(tool, cbf_c, argv, cwd, **kw) for tool in ("cbf", "cbf-c")}  # type: ignore[arg-type]


@pytest.fixture()
def cut(tmp_path: Path) -> Path:
    """The CUT text cbf writes for the golden file (no version line: it is the default version)."""
    text = cbf.to_cut(MODEL)
    assert MODEL.version_id == T.DEFAULT_VERSION and f"{VERSION_KW} " not in text
    p = tmp_path / "part.cut"
    p.write_text(text, encoding="ascii")
    return p


def test_the_same_bytes_to_a_file_and_to_standard_output(cbf_c: Path, cut: Path) -> None:
    for profile in T.PROFILES:
        made = {}
        for tool in ("cbf", "cbf-c"):
            out = cut.parent / f"{tool}.{profile}.cbf"
            res = _run(tool, cbf_c, ["encode", "--profile", profile, cut.name, "-o", out.name], cut.parent)
            assert res.returncode == 0 and res.stdout == b"", (tool, res)
            piped = _run(tool, cbf_c, ["encode", "--profile", profile, cut.name, "-o", "-"], cut.parent)
            assert piped.returncode == 0 and piped.stdout == out.read_bytes(), (tool, piped.stderr)
            made[tool] = out.read_bytes()
        assert made["cbf"] == made["cbf-c"], profile
    assert sorted(p.name for p in cut.parent.iterdir() if p.name.startswith(".")) == []  # no temporary file stays


@pytest.mark.parametrize("version", WRITABLE)
def test_version_is_the_version_of_a_text_without_a_version_line(cbf_c: Path, cut: Path, version: str) -> None:
    """--version V, as cbf encode: the text's version when it names none; a version line naming another is
    refused with its line."""
    got = {}
    for tool in ("cbf", "cbf-c"):
        out = cut.parent / f"{tool}.cbf"
        res = _run(tool, cbf_c, ["encode", "--version", version, cut.name, "-o", out.name], cut.parent)
        got[tool] = (res.returncode, out.read_bytes() if res.returncode == 0 else _line(res, tool))
    assert got["cbf"] == got["cbf-c"]
    other = next((v for v in WRITABLE if v != version), None)
    if other is None:
        pytest.skip("one writable version only")
    named = cut.parent / "named.cut"
    named.write_text(f"{VERSION_KW} {other}\n" + cut.read_text(), encoding="ascii")
    res = _both(cbf_c, ["encode", "--version", version, named.name, "-o", "out.cbf"], cut.parent)
    assert _line(res["cbf"], "cbf") == _line(res["cbf-c"], "cbf-c")
    assert not (cut.parent / "out.cbf").exists()


def test_a_version_that_is_not_writable_is_refused_with_the_writable_ones(cbf_c: Path, cut: Path) -> None:
    bad = next(v.id for v in T.VERSIONS if not v.writable)
    res = _run("cbf-c", cbf_c, ["encode", "--version", bad, cut.name, "-o", "out.cbf"], cut.parent)
    line = _line(res, "cbf-c")
    assert repr(bad).strip("'") in line and all(v in line for v in WRITABLE), line
    assert not (cut.parent / "out.cbf").exists()


@pytest.mark.parametrize("case", ["keep_stored", "empty", "too_large", "no_folder", "a_directory", "dev_full",
                                  "stdout_full"])
def test_refusals_say_cbfs_line(cbf_c: Path, cut: Path, case: str) -> None:
    """One line, cbf's words, exit 2, and the output as it was (here: never made)."""
    (cut.parent / "sub").mkdir()
    (cut.parent / "blank.cut").write_text(" \n\n  \n", encoding="ascii")
    with (cut.parent / "huge.cut").open("wb") as fh:  # sparse: more text than either tool reads (the line names
        fh.truncate(1 << 40)                          # the limit, so both lines agree only when the limits do)
    argv = {"keep_stored": ["encode", cut.name, "--keep-stored", "-o", "out.cbf"],
            "empty": ["encode", "blank.cut", "-o", "out.cbf"],
            "too_large": ["encode", "huge.cut", "-o", "out.cbf"],
            "no_folder": ["encode", cut.name, "-o", "none/out.cbf"],
            "a_directory": ["encode", cut.name, "-o", "sub"],
            "dev_full": ["encode", cut.name, "-o", "/dev/full"],
            "stdout_full": ["encode", cut.name, "-o", "-"]}[case]
    if case in ("dev_full", "stdout_full") and not Path("/dev/full").exists():
        pytest.skip("no /dev/full")
    lines = {}
    for tool in ("cbf", "cbf-c"):
        if case == "stdout_full":
            with open("/dev/full", "wb") as full:
                res = _run(tool, cbf_c, argv, cut.parent, stdout=full)
        else:
            res = _run(tool, cbf_c, argv, cut.parent)
            assert res.stdout == b""
        lines[tool] = _line(res, tool)
        assert not (cut.parent / "out.cbf").exists() and list((cut.parent / "sub").iterdir()) == []
    assert lines["cbf"] == lines["cbf-c"]


def test_a_byte_order_mark_is_read_past(cbf_c: Path, cut: Path) -> None:
    """Editors on Windows start a text with one: cbf reads the text after it, and so does cbf-c (the line
    and column of a refusal counted without it)."""
    marked = cut.parent / "marked.cut"
    marked.write_bytes(b"\xef\xbb\xbf" + cut.read_bytes())
    only = cut.parent / "only.cut"
    only.write_bytes(b"\xef\xbb\xbf\n")
    bad = cut.parent / "bad.cut"
    bad.write_bytes(b"\xef\xbb\xbf" + cut.read_bytes().replace(b"\n", b"\n\x0c", 1))
    got = {}
    for tool in ("cbf", "cbf-c"):
        res = _run(tool, cbf_c, ["encode", marked.name, "-o", "-"], cut.parent)
        assert res.returncode == 0, (tool, res.stderr)
        got[tool] = (res.stdout, *(_line(_run(tool, cbf_c, ["encode", p.name, "-o", "out.cbf"], cut.parent), tool)
                                   for p in (only, bad)))
    assert got["cbf"] == got["cbf-c"] and got["cbf"][0] == cbf.encode(MODEL)
    assert ": line 2, column 1: " in got["cbf"][2]


@pytest.mark.parametrize("bad", [b"\xff", b"\xc0\xaf", b"\xed\xa0\x80", b"\xf4\x90\x80\x80", b"\xe2\x82"],
                         ids=["not_a_start", "overlong", "surrogate", "beyond_u10ffff", "cut_by_the_end"])
def test_text_that_is_not_utf8_is_cbfs_line(cbf_c: Path, cut: Path, bad: bytes) -> None:
    """Text is UTF-8 before anything else is asked of it: the first byte a strict decoder stops at, with its
    line and offset, past a character that is UTF-8 but not CUT (which the CUT reader would name first)."""
    text = cut.read_bytes()
    cut.write_bytes(b"\xef\xbb\xbf" + text.replace(b"\n", "\n\u00e9\n".encode(), 1) + bad)
    res = _both(cbf_c, ["encode", cut.name, "-o", "out.cbf"], cut.parent)
    assert _line(res["cbf"], "cbf") == _line(res["cbf-c"], "cbf-c")
    assert "is not UTF-8 text" in _line(res["cbf-c"], "cbf-c")


def test_json_is_refused_with_one_line(cbf_c: Path, tmp_path: Path) -> None:
    """cbf-c reads no JSON: canonical JSON, by its name or its first character, is one line, exit 2."""
    doc = cbf.to_canonical(MODEL)
    import json

    for name in ("part.json", "part.txt"):
        (tmp_path / name).write_text(json.dumps(doc), encoding="utf-8")
        res = _run("cbf-c", cbf_c, ["encode", name, "-o", "out.cbf"], tmp_path)
        assert _line(res, "cbf-c").startswith(f"{name}: not CUT text: "), res.stderr
        assert not (tmp_path / "out.cbf").exists()


def test_a_disk_that_fills_part_way_leaves_the_target_as_it_was(cbf_c: Path, cut: Path) -> None:
    """The write fails after some bytes (EFBIG past RLIMIT_FSIZE): one line and exit 2, the temporary file
    removed, the old output untouched, as cbf."""
    old = b"an older output\n"
    size = len(cbf.encode(MODEL))
    lines = {}
    for tool in ("cbf", "cbf-c"):
        out = cut.parent / "out.cbf"
        out.write_bytes(old)
        res = _run(tool, cbf_c, ["encode", cut.name, "-o", out.name], cut.parent, limit=size // 2)
        lines[tool] = _line(res, tool)
        assert out.read_bytes() == old, tool
        assert sorted(p.name for p in cut.parent.iterdir()) == ["out.cbf", "part.cut"], tool
    assert lines["cbf"] == lines["cbf-c"]


def test_what_went_to_a_regular_file_on_standard_output_is_cut_off_again(cbf_c: Path, cut: Path) -> None:
    before = b"written before\n"
    size = len(cbf.encode(MODEL))
    for tool in ("cbf", "cbf-c"):
        log = cut.parent / f"{tool}.log"
        log.write_bytes(before)
        with log.open("ab") as fh:
            res = _run(tool, cbf_c, ["encode", cut.name, "-o", "-"], cut.parent, limit=len(before) + size // 2,
                       stdout=fh)
        assert _line(res, tool).startswith("standard output: cannot write ("), tool
        assert log.read_bytes() == before, tool


def test_a_symlink_stays_a_link_and_the_new_file_has_cbfs_mode(cbf_c: Path, cut: Path) -> None:
    modes = {}
    for tool in ("cbf", "cbf-c"):
        target = cut.parent / f"{tool}.target.cbf"
        target.write_bytes(b"old")
        link = cut.parent / f"{tool}.link.cbf"
        link.symlink_to(target.name)
        assert _run(tool, cbf_c, ["encode", cut.name, "-o", link.name], cut.parent).returncode == 0
        assert link.is_symlink() and target.read_bytes() == cbf.encode(MODEL), tool
        fresh = cut.parent / f"{tool}.new.cbf"
        assert _run(tool, cbf_c, ["encode", cut.name, "-o", fresh.name], cut.parent).returncode == 0
        modes[tool] = stat.S_IMODE(os.stat(fresh).st_mode)
    assert modes["cbf"] == modes["cbf-c"]
    assert not [p.name for p in cut.parent.iterdir() if p.name.startswith(".")]


@pytest.mark.parametrize("command", ["validate GOOD", "READER GOOD", "--version", "encode CUT -o -"])
def test_every_command_checks_standard_output(cbf_c: Path, cut: Path, command: str) -> None:
    """A standard output that cannot be written (/dev/full) is one line and exit 2 for every command, cbf's
    line (README: "Every write is checked, to a file and to standard output alike")."""
    if not Path("/dev/full").exists():
        pytest.skip("no /dev/full")
    lines = {}
    for tool in ("cbf", "cbf-c"):
        argv = [{"GOOD": str(VALID), "CUT": cut.name, "READER": READER[tool]}.get(a, a) for a in command.split()]
        with open("/dev/full", "wb") as full:
            lines[tool] = _line(_run(tool, cbf_c, argv, cut.parent, stdout=full), tool)
    assert lines["cbf"] == lines["cbf-c"]


def test_dash_is_standard_input(cbf_c: Path, cut: Path) -> None:
    """`-` as the input is standard input, as in cbf: the same bytes, and a refusal names `-` and the line."""
    bad = cut.parent / "bad.cut"
    lines = cut.read_text().splitlines()
    at = HEAD_LINES + NO_TEXT_REC  # a record with no text argument: text after it is refused
    lines[at] += " extra"
    bad.write_text("\n".join(lines) + "\n", encoding="ascii")
    got = {}
    for tool in ("cbf", "cbf-c"):
        with cut.open("rb") as fh:
            res = _run(tool, cbf_c, ["encode", "-", "-o", "-"], cut.parent, stdin=fh)
        assert res.returncode == 0, (tool, res.stderr)
        with bad.open("rb") as fh:
            refused = _run(tool, cbf_c, ["encode", "-", "-o", "out.cbf"], cut.parent, stdin=fh)
        with VALID.open("rb") as fh:
            checked = _run(tool, cbf_c, ["validate", "-"], cut.parent, stdin=fh)
        got[tool] = (res.stdout, _line(refused, tool), checked.returncode, checked.stdout.splitlines()[-1])
    assert got["cbf"] == got["cbf-c"]
    assert got["cbf"][0] == cbf.encode(MODEL) and got["cbf"][1].startswith(f"-: line {at + 1}: ")


def test_the_longest_name_the_folder_takes_is_written(cbf_c: Path, cut: Path) -> None:
    """The temporary name fits NAME_MAX whenever the final name does; one byte more is cbf's line."""
    longest = os.pathconf(cut.parent, "PC_NAME_MAX")
    for tool in ("cbf", "cbf-c"):
        target = cut.parent / ("n" * longest)
        res = _run(tool, cbf_c, ["encode", cut.name, "-o", target.name], cut.parent)
        assert res.returncode == 0 and target.read_bytes() == cbf.encode(MODEL), (tool, res.stderr)
        assert sorted(p.name for p in cut.parent.iterdir()) == sorted([cut.name, target.name]), tool
        target.unlink()
    res = _both(cbf_c, ["encode", cut.name, "-o", "n" * (longest + 1)], cut.parent)
    assert _line(res["cbf"], "cbf") == _line(res["cbf-c"], "cbf-c")


def test_check_encodes_each_file_and_writes_nothing(cbf_c: Path, cut: Path) -> None:
    """--check (a pre-commit hook on *.cut): each file encoded in memory, one line for each that does not,
    exit 2 then; nothing written; cbf's lines."""
    lines = cut.read_text().splitlines()
    lines[HEAD_LINES + NO_TEXT_REC] += " extra"
    (cut.parent / "bad.cut").write_text("\n".join(lines) + "\n", encoding="ascii")
    (cut.parent / "blank.cut").write_text("\n", encoding="ascii")
    before = sorted(p.name for p in cut.parent.iterdir())
    got = {}
    for tool in ("cbf", "cbf-c"):
        good = _run(tool, cbf_c, ["encode", "--check", cut.name, cut.name], cut.parent)
        assert good.returncode == 0 and good.stdout == good.stderr == b"", (tool, good)
        res = _run(tool, cbf_c, ["encode", "--check", "bad.cut", cut.name, "blank.cut"], cut.parent)
        assert res.returncode == 2 and res.stdout == b"", (tool, res)
        got[tool] = [ln.removeprefix(f"{tool}: ") for ln in res.stderr.decode().splitlines()]
        assert sorted(p.name for p in cut.parent.iterdir()) == before
    assert got["cbf"] == got["cbf-c"] and len(got["cbf"]) == 2
