"""Memory stays bounded (issue 13 item 10): the peak RSS of a `cbf` process stays within a
small constant times its input, above the interpreter with the codec imported.

Before the fix, `validate --json` on 16 MiB of zeros peaked near 7 GB (every finding held,
then the whole JSON document), `encode` of 400 MB of newlines at 3.5 GB (a list of every
line), and the 65,535-record golden with a wrong file checksum at 19x its size (a list of a
slice per record for the hint coverage). The inputs here are small so the test stays quick;
the per-byte ratio is what grows without bound.

The peak is VmHWM, read by the child itself: ru_maxrss of a child carries over the parent's
(large, pytest) image from before exec, VmHWM belongs to the new address space.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from conftest import ENV

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"

# Runs the cbf command line in-process, then prints its peak RSS (kB) as the last stderr line.
# Both the measured run and the baseline import the same modules first.
_WRAPPER = """
import sys, numpy, cbf.cli, cbf.codec, cbf.cut, cbf.validation, cbf.records, cbf.writer
try:
    code = cbf.cli.main(sys.argv[1:])
finally:
    sys.stdout.flush()
    hwm = next(int(x.split()[1]) for x in open('/proc/self/status') if x.startswith('VmHWM'))
    sys.stderr.write(f"\\nVmHWM {hwm}\\n")
sys.exit(code)
"""

MiB = 1 << 20
# Peak RSS above the baseline, per input byte. Binary input: findings are printed as they are
# made; what is held is the file, its framing (8 bytes a record: for zeros, one per 8 bytes)
# and a few numpy columns of it (measured: about 7.5x, the file included; the README's bench
# target says under 10x). Text input is held as text, twice while it is joined, and read a line
# at a time (measured: about 2.4x).
BINARY_RATIO = 10
TEXT_RATIO = 4
SLACK = 4 * MiB  # allocator and import noise


def _peak(args: list[str], cwd: Path) -> int:
    if not Path("/proc/self/status").exists():
        pytest.skip("needs /proc/self/status (VmHWM)")
    res = subprocess.run([sys.executable, "-c", _WRAPPER, *args], env=ENV, cwd=cwd, capture_output=True,
                         text=True, timeout=600)
    last = res.stderr.strip().splitlines()[-1]
    assert last.startswith("VmHWM "), res.stderr[-2000:]
    assert "Traceback" not in res.stderr, res.stderr[-2000:]
    return int(last.split()[1]) * 1024


@pytest.fixture(scope="module")
def baseline(tmp_path_factory: pytest.TempPathFactory) -> int:
    return _peak(["--version"], tmp_path_factory.mktemp("base"))


def _assert_bounded(args: list[str], size: int, baseline: int, cwd: Path, ratio: int = BINARY_RATIO) -> None:
    extra = _peak(args, cwd) - baseline
    assert extra <= ratio * size + SLACK, (
        f"cbf {' '.join(args)}: peak {extra / MiB:.1f} MiB above the interpreter for {size / MiB:.1f} MiB of input "
        f"(bound {ratio}x + {SLACK / MiB:.0f} MiB)")


@pytest.mark.parametrize("flags", [["--json"], [], ["--max-findings", "0"]], ids=["json", "text", "text-all"])
def test_validate_zeros_is_bounded(flags: list[str], tmp_path: Path, baseline: int) -> None:
    zeros = tmp_path / "zeros.bin"
    zeros.write_bytes(bytes(MiB))  # about 2 findings for every 8 bytes
    _assert_bounded(["validate", *flags, str(zeros)], MiB, baseline, tmp_path)


def test_validate_wrong_file_checksum_of_many_records_is_bounded(tmp_path: Path, baseline: int) -> None:
    import cbf
    from cbf import tables as T

    data = bytearray((GOLDEN / "big.v3.65535.cbf").read_bytes())
    field = T.HEADER_CHECKSUM_FIELDS.get("file")
    if field is None:
        pytest.skip("this spec has no file checksum")
    data[field.offset] ^= 0x01
    bad = tmp_path / "bad.cbf"
    bad.write_bytes(bytes(data))
    assert any(f.offset == field.offset for f in cbf.validate(bytes(data)))  # the hint coverages run
    _assert_bounded(["validate", str(bad)], len(data), baseline, tmp_path)


def test_encode_of_many_empty_lines_is_bounded(tmp_path: Path, baseline: int) -> None:
    import cbf

    small = cbf.decode((GOLDEN / "valid.v3.small.cbf").read_bytes())
    text = cbf.to_cut(small) + "\n" * (4 * MiB)
    cut = tmp_path / "blank.cut"
    cut.write_text(text)
    out = tmp_path / "out.cbf"
    _assert_bounded(["encode", str(cut), "-o", str(out)], len(text), baseline, tmp_path, TEXT_RATIO)
    assert out.read_bytes() == (GOLDEN / "valid.v3.small.cbf").read_bytes()
