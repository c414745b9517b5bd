"""Issue 36, point 5: no silent short output. Every command's output goes through one checked
writer: a disk that fills part way through `-o -` was 51,200 bytes of 1.4 MB and exit 0, `stats`
and `diff` into /dev/full an OSError traceback (for diff, exit 1 means "differ"); now one line,
exit 2, and what was written cut off again. A temporary name fits NAME_MAX whenever the final name
does (a legal 244-byte name was refused); a file over the largest CBF is refused from its size with
the same line by both tools (cbf-c read 17 MB, then said "file too large")."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest
from c_programs import built
from conftest import ENV

from cbf import cli
from cbf import tables as T

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"
SMALL = GOLDEN / "valid.v3.small.cbf"
BIG = max(GOLDEN.glob("*.cbf"), key=lambda p: p.stat().st_size)  # the largest golden file
WRITABLE = next(v.id for v in T.VERSIONS if v.writable)


def cbf(*args: str, stdout: int | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "cbf", *args], env=ENV, text=True,
                          stdout=subprocess.PIPE if stdout is None else stdout, stderr=subprocess.PIPE, timeout=300)


def _one_line_exit_2(res: subprocess.CompletedProcess[str]) -> str:
    assert res.returncode == 2, (res.returncode, res.stderr)
    assert "Traceback" not in res.stderr and "Exception ignored" not in res.stderr, res.stderr
    # a long diff says what it is doing on stderr (cbf diff: ... (N.N s)); the failure is one line
    lines = [ln for ln in res.stderr.strip().splitlines() if not re.fullmatch(r"cbf diff: .* \(\d+\.\d s\)", ln)]
    assert len(lines) == 1, res.stderr
    return lines[0]


def _commands(src: Path, cut: Path, out: str) -> dict[str, list[tuple[str, ...]]]:
    """Each subcommand of cbf with the invocations that print to stdout (or to ``out``)."""
    return {
        "decode": [("decode", str(src)), ("decode", str(src), "--to", "cut"), ("decode", str(src), "-o", out)],
        "encode": [("encode", str(cut), "-o", out)],
        "validate": [("validate", str(src)), *(("validate", "--format", f, str(src), str(SMALL))
                                               for f in ("text", "json", "junit", "sarif", "gitlab"))],
        "info": [("info", str(src)), ("info", "--json", str(src))],
        "convert": [("convert", str(src), "--to-version", WRITABLE, "-o", out)],
        "stats": [("stats", str(src)), ("stats", "--json", str(src))],
        "diff": [("diff", str(src), str(src)), ("diff", str(src), str(SMALL)),
                 ("diff", "--json", str(src), str(SMALL))],
        "plot": [("plot", str(src), "--format", "svg", "-o", out)],
        "hexdump": [("hexdump", str(src))],
    }


def test_every_subcommand_is_covered() -> None:
    sub = next(a for a in cli.parser()._actions if a.dest == "cmd")
    assert set(_commands(SMALL, SMALL, "-")) == set(sub.choices)  # type: ignore[arg-type]


@pytest.fixture(scope="module")
def cut_of_big(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("cut") / "big.cut"
    assert cbf("decode", str(BIG), "--to", "cut", "-o", str(path)).returncode == 0
    return path


def _plot_missing(args: tuple[str, ...]) -> bool:
    if args[0] != "plot":
        return False
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        return True
    return False


@pytest.mark.parametrize("name", sorted(_commands(SMALL, SMALL, "-")))
def test_full_stdout_is_one_line_and_exit_2_for_every_command(name: str, cut_of_big: Path) -> None:
    for args in _commands(SMALL, cut_of_big, "-")[name]:
        if _plot_missing(args):
            continue
        with open("/dev/full", "w") as full:
            res = cbf(*args, stdout=full.fileno())
        line = _one_line_exit_2(res)
        assert line.startswith("cbf: ") and "standard output" in line and "No space left" in line, (args, line)


# -- a disk that fills part way --------------------------------------------------------------------
@pytest.fixture
def small_disk(tmp_path: Path) -> Iterator[Path]:
    """A 64 KiB tmpfs (as root, as CI runs): smaller than the outputs of the largest golden file."""
    where = tmp_path / "small"
    where.mkdir()
    res = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=64k", "tmpfs", str(where)], capture_output=True,
                         text=True)
    if res.returncode != 0:
        pytest.skip(f"cannot mount a small tmpfs here ({res.stderr.strip() or 'mount failed'}); /dev/full "
                    f"covers a stdout that takes nothing, not one that takes part")
    try:
        yield where
    finally:
        subprocess.run(["umount", str(where)], check=False)


@pytest.mark.parametrize("name", ["decode", "encode", "convert", "stats", "diff", "validate"])
def test_a_disk_that_fills_part_way_leaves_nothing_that_looks_complete(name: str, small_disk: Path,
                                                                       cut_of_big: Path) -> None:
    for args in _commands(BIG, cut_of_big, "-")[name]:
        out = small_disk / "out"
        with open(out, "w") as fh:
            res = cbf(*args, stdout=fh.fileno())
        size = out.stat().st_size
        out.unlink()
        if res.returncode in (0, 1) and "standard output" not in res.stderr:
            continue  # it fit: nothing to refuse
        line = _one_line_exit_2(res)
        assert "standard output" in line and "No space left" in line, (args, line)
        assert size == 0, (args, size)  # what was written is cut off again


@pytest.mark.parametrize("name", ["decode", "encode", "convert"])
def test_a_full_disk_under_o_file_leaves_no_file(name: str, small_disk: Path, cut_of_big: Path) -> None:
    target = small_disk / "out.bin"
    args = _commands(BIG, cut_of_big, str(target))[name][-1]
    line = _one_line_exit_2(cbf(*args))
    assert str(target) in line and "No space left" in line, line
    assert sorted(p.name for p in small_disk.iterdir()) == []


def test_short_writes_are_written_on_and_a_write_of_nothing_fails(monkeypatch: pytest.MonkeyPatch) -> None:
    got: list[bytes] = []

    def short(fd: int, data: object) -> int:
        chunk = bytes(data)[:3]  # type: ignore[call-overload]
        got.append(chunk)
        return len(chunk)

    monkeypatch.setattr(os, "write", short)  # the module cbf.cli writes through
    cli._write_all(1, b"0123456789", sync=False)
    assert b"".join(got) == b"0123456789"
    monkeypatch.setattr(os, "write", lambda fd, data: 0)
    with pytest.raises(OSError):
        cli._write_all(1, b"x", sync=False)


# -- NAME_MAX -----------------------------------------------------------------------------------------
@pytest.mark.parametrize("spare", [0, 11], ids=["NAME_MAX", "the issue's 244 bytes"])
def test_a_name_of_up_to_name_max_bytes_is_written(spare: int, tmp_path: Path, cut_of_big: Path) -> None:
    longest = os.pathconf(tmp_path, "PC_NAME_MAX")
    for name in ("decode", "encode", "convert"):
        target = tmp_path / ("n" * (longest - spare))
        args = _commands(SMALL, cut_of_big, str(target))[name][-1]
        res = cbf(*args)
        assert res.returncode == 0, (args, res.stderr)
        assert target.stat().st_size > 0
        assert sorted(p.name for p in tmp_path.iterdir()) == [target.name]
        target.unlink()
    res = cbf("decode", str(SMALL), "-o", str(tmp_path / ("n" * (longest + 1))))
    assert "File name too long" in _one_line_exit_2(res)  # one over: the final name itself is too long


# -- larger than any CBF file: one line, from the size, in both tools -----------------------------------
@pytest.mark.parametrize("over", [1, 2, 1 << 30])
def test_too_large_is_the_same_line_in_both_tools(over: int, tmp_path: Path) -> None:
    limit = cli._max_file_size()
    path = tmp_path / "huge.cbf"
    with open(path, "wb") as fh:
        fh.truncate(limit + over)  # sparse: nothing to read, only a size
    cbf_c = built("cbf-c")
    want = f"{path}: larger than {limit} bytes, the most a CBF file can hold"
    for argv, tool in (([sys.executable, "-m", "cbf", "validate", str(path)], "cbf"),
                       ([sys.executable, "-m", "cbf", "info", str(path)], "cbf"),
                       ([str(cbf_c), "validate", str(path)], "cbf-c"), ([str(cbf_c), "dump", str(path)], "cbf-c")):
        res = subprocess.run(argv, env=ENV, capture_output=True, text=True, timeout=60)
        assert res.returncode == 2 and res.stderr == f"{tool}: {want}\n", (argv, res.stderr)
