"""Validation reports non-finite and huge values as findings and says nothing else: no numpy
floating-point warning (an invalid cast of a signalling NaN, an overflow) reaches stderr.

The full reliability campaign found `RuntimeWarning: invalid value encountered in cast` on the
Python testee's stderr for mutants with a signalling NaN in a position. Here every 4-byte word
of every record's arguments of each golden file is set to one special pattern at a time (NaNs
signalling of both signs, a quiet NaN, an infinity, the largest finite binary32), and the
file is validated under every profile with warnings raised as errors.
"""

from __future__ import annotations

import struct
import warnings
from pathlib import Path

import pytest

import cbf
from cbf import tables as T

GOLDEN = Path(__file__).resolve().parents[1] / "conformance" / "golden"
PATTERNS = (0x7F800001, 0xFF800001, 0x7FC00000, 0xFF800000, 0x7F7FFFFF)


def _decodable() -> list[Path]:
    out = []
    for p in sorted(GOLDEN.glob("*.cbf")):
        try:
            cbf.decode(p.read_bytes())
        except cbf.CbfError:
            continue
        out.append(p)
    return out


def _every_word(data: bytes, model: cbf.Cbf, pattern: int) -> bytes:
    """``data`` with each whole 4-byte word of every record's arguments set to ``pattern``."""
    out = bytearray(data)
    word = struct.pack(T.BO + "I", pattern)
    for r in model.records:
        assert r.offset is not None  # a decoded record knows where it is
        start = r.offset + T.HEAD_SIZE
        for k in range(0, len(r.raw_args) - 3, 4):
            out[start + k:start + k + 4] = word
    return bytes(out)


@pytest.mark.parametrize("path", _decodable(), ids=lambda p: p.stem)
def test_special_floats_give_findings_and_no_warning(path: Path) -> None:
    data = path.read_bytes()
    if len(data) > 100_000:
        pytest.skip("the big files hold the same layouts as the small ones")
    model = cbf.decode(data)
    if not any(len(r.raw_args) >= 4 for r in model.records):
        pytest.skip("no argument word to set")
    for pattern in PATTERNS:
        bad = _every_word(data, model, pattern)
        assert bad != data
        for profile in T.PROFILES:
            with warnings.catch_warnings():
                warnings.simplefilter("error")
                found = cbf.validate(bad, profile=profile)
            assert all(f.check and f.severity in ("error", "warning") for f in found)
