"""Where `cbf` writes (issue 13 item 9) and its version line (item 18).

`-o` onto a symlink writes through the link to its target, atomically, and the
link stays a link; `-o` onto a character device or FIFO writes into it and never
replaces it; a standard output that cannot be written (/dev/full) is one line on
stderr and exit 2 for every subcommand (never 1: for validate, 1 means "found an error").
"""

from __future__ import annotations

import os
import stat
import subprocess
import sys
import threading
from pathlib import Path

import pytest
from conftest import ENV

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"
SMALL = GOLDEN / "valid.v3.small.cbf"


def cbf(*args: str, stdout: int | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "cbf", *args], env=ENV, text=True, stdout=stdout or subprocess.PIPE,
                          stderr=subprocess.PIPE, timeout=120)


def _one_line_exit_2(res: subprocess.CompletedProcess[str]) -> str:
    assert res.returncode == 2, (res.returncode, res.stderr)
    assert "Traceback" not in res.stderr and "Exception ignored" not in res.stderr, res.stderr
    lines = res.stderr.strip().splitlines()
    assert len(lines) == 1, res.stderr
    return lines[0]


def _json_of_small() -> str:
    res = cbf("decode", str(SMALL))
    assert res.returncode == 0 and res.stdout
    return res.stdout


def _leftovers(*folders: Path) -> list[str]:
    return sorted(p.name for d in folders for p in d.iterdir() if p.name.endswith(".tmp"))


def test_symlink_is_written_through_and_stays_a_link(tmp_path: Path) -> None:
    real_dir, link_dir = tmp_path / "real", tmp_path / "links"
    real_dir.mkdir()
    link_dir.mkdir()
    target = real_dir / "part.json"
    target.write_text("old\n")
    link = link_dir / "part.json"
    link.symlink_to(target)
    res = cbf("decode", str(SMALL), "-o", str(link))
    assert res.returncode == 0, res.stderr
    assert link.is_symlink() and os.readlink(link) == str(target)
    assert target.read_text() == _json_of_small()
    assert _leftovers(real_dir, link_dir) == []


def test_chain_of_links_and_dangling_link(tmp_path: Path) -> None:
    target = tmp_path / "out.cbf"
    hop = tmp_path / "hop.cbf"
    link = tmp_path / "link.cbf"
    hop.symlink_to(target.name)  # relative, and the target does not exist yet
    link.symlink_to(hop.name)
    cut = tmp_path / "in.cut"
    dec = cbf("decode", str(SMALL), "--to", "cut", "-o", str(cut))
    assert dec.returncode == 0, dec.stderr
    res = cbf("encode", str(cut), "-o", str(link))
    assert res.returncode == 0, res.stderr
    assert link.is_symlink() and hop.is_symlink()
    assert not target.is_symlink() and target.read_bytes() == SMALL.read_bytes()
    assert _leftovers(tmp_path) == []


def _char_device(tmp_path: Path, name: str = "null") -> Path:
    """A character device to write into that no run of this test can damage, even against a
    cbf that replaces what it writes to: as root, a fresh node in tmp_path with the numbers of
    /dev/<name>; otherwise /dev/<name> itself, which an unprivileged process cannot replace."""
    dev = Path("/dev") / name
    if not dev.exists() or not stat.S_ISCHR(os.stat(dev).st_mode):
        pytest.skip(f"no character device {dev}")
    if os.geteuid() != 0:
        return dev
    node = tmp_path / name
    os.mknod(node, 0o666 | stat.S_IFCHR, os.stat(dev).st_rdev)
    return node


def test_character_device_is_written_into_not_replaced(tmp_path: Path) -> None:
    dev = _char_device(tmp_path)
    before = os.stat(dev)
    for args in (("decode", str(SMALL)), ("decode", str(SMALL), "--to", "cut")):
        res = cbf(*args, "-o", str(dev))
        assert res.returncode == 0, res.stderr
        after = os.stat(dev)
        assert stat.S_ISCHR(after.st_mode)
        assert (after.st_ino, after.st_rdev, after.st_dev) == (before.st_ino, before.st_rdev, before.st_dev)
    assert _leftovers(tmp_path) == []


def test_full_device_as_output_file_is_one_line(tmp_path: Path) -> None:
    full = _char_device(tmp_path, "full")
    before = os.stat(full)
    line = _one_line_exit_2(cbf("decode", str(SMALL), "-o", str(full)))
    assert str(full) in line and "cannot write" in line
    after = os.stat(full)
    assert (after.st_ino, after.st_rdev) == (before.st_ino, before.st_rdev) and stat.S_ISCHR(after.st_mode)


def test_fifo_is_written_into_not_replaced(tmp_path: Path) -> None:
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    got: list[bytes] = []

    def reader() -> None:
        with open(fifo, "rb") as fh:  # blocks until cbf opens the other end
            got.append(fh.read())

    t = threading.Thread(target=reader, daemon=True)
    t.start()
    res = cbf("decode", str(SMALL), "-o", str(fifo))
    if res.returncode != 0:  # unblock the reader before failing
        with open(fifo, "wb"):
            pass
    t.join(30)
    assert res.returncode == 0, res.stderr
    assert stat.S_ISFIFO(os.stat(fifo).st_mode)
    assert got == [_json_of_small().encode()]
    assert _leftovers(tmp_path) == []


FULL_STDOUT_COMMANDS = [
    ("decode", str(SMALL)),
    ("decode", str(SMALL), "--to", "cut"),
    ("encode", "CUT", "-o", "-"),
    ("validate", str(SMALL)),
    ("validate", str(SMALL), "--json"),
    ("validate", str(GOLDEN / "big.v3.65535.cbf"), "--json"),  # more than any buffer: fails mid-write
    ("info", str(SMALL)),
    ("--version",),
    ("--help",),
    ("validate", "--help"),
]


@pytest.mark.parametrize("args", FULL_STDOUT_COMMANDS, ids=lambda a: " ".join(Path(x).name for x in a))
def test_full_stdout_is_one_line_and_exit_2(args: tuple[str, ...], tmp_path: Path) -> None:
    full_dev = _char_device(tmp_path, "full")  # only ever opened here, never passed to -o
    if "CUT" in args:
        cut = tmp_path / "in.cut"
        assert cbf("decode", str(SMALL), "--to", "cut", "-o", str(cut)).returncode == 0
        args = tuple(str(cut) if a == "CUT" else a for a in args)
    with open(full_dev, "w") as full:
        res = cbf(*args, stdout=full.fileno())
    line = _one_line_exit_2(res)
    assert line.startswith("cbf: ") and "standard output" in line and "No space left" in line


def test_version_names_toolkit_and_spec_revision() -> None:
    import cbf as lib

    res = cbf("--version")
    assert res.returncode == 0 and res.stderr == ""
    assert res.stdout == f"cbf {lib.__version__} (spec {lib.SPEC_REVISION})\n"
    assert lib.__version__ and lib.SPEC_REVISION  # both come from the generator and the spec


def test_encode_version_option_is_still_the_cbf_version(tmp_path: Path) -> None:
    cut = tmp_path / "in.cut"
    assert cbf("decode", str(SMALL), "--to", "cut", "-o", str(cut)).returncode == 0
    res = cbf("encode", str(cut), "--version", "nope", "-o", str(tmp_path / "x.cbf"))
    assert res.returncode == 2 and "--version" in res.stderr
