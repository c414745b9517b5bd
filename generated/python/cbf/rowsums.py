"""Checksums of many records at once: a checksum algorithm kind of checksums.py over every row of a
byte matrix (one row a record: its argument bytes, or the byte ranges a coverage feeds, in order),
in a few numpy passes over the whole matrix, never a Python step a row.

``row_checksums(kind, rows, width)[i] == checksums.compute(kind, [rows[i]], width)`` for every kind
of ``checksums.KINDS`` (tests/test_rowsums.py holds the two equal on every kind):

- ``sum``: row sums (einsum on a widened copy, a block of rows at a time);
- ``fletcher16`` / ``fletcher32``: the running sums modulo 255 / 65535 are weighted sums of the
  bytes / words (the k-th of m counts m - k times in sum2), so one matrix product a block;
- the CRCs: table-driven, one step a byte column over every row at once (the table made once from
  the CRC's parameters).

A kind this module does not know (none today) is computed one row at a time by checksums.compute,
which is correct but costs a Python call a record; tests/test_rowsums.py fails when checksums.KINDS
has such a kind, so a new algorithm comes with its kernel here.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from functools import lru_cache
from typing import TYPE_CHECKING, Any

import numpy as np

from .checksums import compute

if TYPE_CHECKING:
    from numpy.typing import NDArray

Rows = Any  # NDArray[np.uint8], rows x bytes
_BLOCK = 1 << 13  # rows widened at once (memory: a few hundred KiB however many rows)


def _blocks(rows: Rows, fn: Callable[[Rows], Any], block: int = _BLOCK) -> NDArray[np.int64]:
    if rows.shape[0] <= block:
        return fn(rows).astype(np.int64, copy=False)  # type: ignore[no-any-return]
    out = np.empty(rows.shape[0], dtype=np.int64)
    for s in range(0, rows.shape[0], block):
        out[s:s + block] = fn(rows[s:s + block])
    return out


_ONES: dict[int, Any] = {}
_EXACT32 = 1 << 24  # binary32 holds every integer below this, so sums below it add exactly


def _sum(rows: Rows) -> NDArray[np.int64]:
    """The byte sum of each row. Rows whose sum stays below 2**24 are widened to binary32 and
    multiplied by a vector of ones (one matrix-vector product: every partial sum is an integer
    below 2**24, so exact in any order), about twice as fast as einsum on uint16, which in turn
    is three times faster than numpy's row reduction on rows of a few bytes; half the rows a
    block, so the widened copy holds what the uint16 one did. Wider rows: einsum on int64."""
    width = rows.shape[1]
    if width * 255 < _EXACT32:
        ones = _ONES.get(width)
        if ones is None:
            ones = _ONES[width] = np.ones(width, dtype=np.float32)  # one a width (a few microseconds a call)
        return _blocks(rows, lambda part: part.astype(np.float32) @ ones, _BLOCK // 2)
    return _blocks(rows, lambda part: np.einsum("ij->i", part.astype(np.int64)))


def exact_sums32(rows: Rows) -> Any:
    """The byte sum of each row as binary32 (exact: every partial sum is an integer below 2**24),
    or None when a row is too wide for that; for a caller that stores the sums in a narrower
    integer type anyway (no int64 copy)."""
    width = rows.shape[1]
    if width * 255 >= _EXACT32 or rows.shape[0] > _BLOCK // 2:
        return None
    ones = _ONES.get(width)
    if ones is None:
        ones = _ONES[width] = np.ones(width, dtype=np.float32)
    return np.ascontiguousarray(rows, dtype=np.uint8).astype(np.float32) @ ones


def _weighted(rows: Rows, modulus: int) -> NDArray[np.int64]:
    """(sum2 << bits) | sum1 of a Fletcher checksum over rows of words (modulus 2**bits - 1):
    sum1 = the words' sum, sum2 = the sum of the running sums = sum of (m - k) x word k."""
    m = rows.shape[1]
    weights = np.arange(m, 0, -1, dtype=np.int64)
    bits = 8 if modulus == 255 else 16

    def block(part: Rows) -> Any:
        wide = part.astype(np.int64)
        s1 = wide.sum(axis=1) % modulus
        s2 = (wide @ weights) % modulus
        return (s2 << bits) | s1

    return _blocks(rows, block)


def _fletcher16(rows: Rows) -> NDArray[np.int64]:
    return _weighted(rows, 255)


def _fletcher32(rows: Rows) -> NDArray[np.int64]:
    """Over 16-bit little-endian words, an odd last byte padded with 0."""
    if rows.shape[1] % 2:
        rows = np.concatenate((rows, np.zeros((rows.shape[0], 1), dtype=np.uint8)), axis=1)
    words = rows[:, 0::2].astype(np.uint16) | (rows[:, 1::2].astype(np.uint16) << 8)
    return _weighted(words, 65535)


@dataclass(frozen=True)
class Crc:
    """A CRC by its catalogue parameters (the poly as written, not reflected)."""

    width: int
    poly: int
    init: int
    reflected: bool
    xorout: int


# The CRC kinds of checksums.py, by the parameters its doc names.
CRCS: dict[str, Crc] = {
    "crc16_ccitt": Crc(16, 0x1021, 0xFFFF, False, 0),
    "crc32": Crc(32, 0x04C11DB7, 0xFFFFFFFF, True, 0xFFFFFFFF),
    "crc32c": Crc(32, 0x1EDC6F41, 0xFFFFFFFF, True, 0xFFFFFFFF),
}


def _reflect(v: int, bits: int) -> int:
    return int(format(v, f"0{bits}b")[::-1], 2)


@lru_cache(maxsize=8)
def _table(crc: Crc) -> NDArray[np.uint64]:
    """The 256 entries of a byte-at-a-time CRC table, all at once (8 steps over the 256 bytes)."""
    mask = (1 << crc.width) - 1
    if crc.reflected:
        t = np.arange(256, dtype=np.uint64)
        poly = np.uint64(_reflect(crc.poly, crc.width))
        for _ in range(8):
            t = np.where(t & np.uint64(1), (t >> np.uint64(1)) ^ poly, t >> np.uint64(1))
    else:
        top = np.uint64(1 << (crc.width - 1))
        t = np.arange(256, dtype=np.uint64) << np.uint64(crc.width - 8)
        for _ in range(8):
            t = np.where(t & top, (t << np.uint64(1)) ^ np.uint64(crc.poly), t << np.uint64(1)) & np.uint64(mask)
    return t.astype(np.uint64)


def _crc(crc: Crc, rows: Rows) -> NDArray[np.int64]:
    """One table step a byte column, over every row at once."""
    table = _table(crc)
    reg = np.full(rows.shape[0], crc.init, dtype=np.uint64)
    mask, low = np.uint64((1 << crc.width) - 1), np.uint64(0xFF)
    eight, shift = np.uint64(8), np.uint64(crc.width - 8)
    for j in range(rows.shape[1]):
        col = rows[:, j].astype(np.uint64)
        if crc.reflected:
            reg = table[(reg ^ col) & low] ^ (reg >> eight)
        else:
            reg = table[((reg >> shift) ^ col) & low] ^ ((reg << eight) & mask)
    reg ^= np.uint64(crc.xorout)
    return reg.astype(np.int64)


def _crc_kind(crc: Crc) -> Callable[[Rows], NDArray[np.int64]]:
    return lambda rows: _crc(crc, rows)


# kind of checksums.KINDS -> its kernel over rows (the result before the field's width is applied)
KINDS: dict[str, Callable[[Rows], NDArray[np.int64]]] = {
    "sum": _sum,
    "fletcher16": _fletcher16,
    "fletcher32": _fletcher32,
    **{k: _crc_kind(c) for k, c in CRCS.items()},
}


def row_checksums(kind: str, rows: Rows, width: int) -> NDArray[np.int64]:
    """The checksum of kind ``kind`` (checksums.KINDS) of each row, as stored in a field of
    ``width`` bytes."""
    n = rows.shape[0]
    fn = KINDS.get(kind)
    if fn is None:  # a kind without a kernel here: one call a row (tests/test_rowsums.py refuses it)
        return np.array([compute(kind, [bytes(r)], width) for r in rows], dtype=np.int64).reshape(n)
    if n == 0:
        return np.zeros(0, dtype=np.int64)
    got = fn(np.ascontiguousarray(rows, dtype=np.uint8))
    if width < 8 and not (kind == "sum" and 255 * rows.shape[1] < 1 << (8 * width)):  # a sum that fits: as is
        got &= (1 << (8 * width)) - 1
    return got
