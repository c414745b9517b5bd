"""The checksum algorithms, each implemented once; the spec says which field uses which.

Every function takes the byte ranges of a coverage, in order, as one logical
stream (a range may end in the middle of a Fletcher-32 word). The kinds and
their parameters are those of spec/cbf.yaml ``checksums.algorithms`` (the
names follow the CRC catalogue):

- ``sum``: unsigned byte sum, reduced to the width of the field;
- ``crc16_ccitt``: CRC-16/CCITT-FALSE, poly 0x1021, init 0xFFFF, not reflected, xorout 0;
- ``crc32``: CRC-32/ISO-HDLC, poly 0x04C11DB7, init and xorout 0xFFFFFFFF, reflected;
- ``crc32c``: CRC-32C (Castagnoli, CRC-32/ISCSI), poly 0x1EDC6F41, init and xorout 0xFFFFFFFF, reflected;
- ``fletcher16``: over bytes, sums modulo 255, result ``sum2 << 8 | sum1``;
- ``fletcher32``: over 16-bit little-endian words (odd last byte padded with 0),
  sums modulo 65535, result ``sum2 << 16 | sum1``.
"""

from __future__ import annotations

import binascii
import zlib
from collections.abc import Callable, Iterable

Buffer = bytes | bytearray | memoryview


def _byte_sum(part: Buffer) -> int:
    """Sum of the bytes; numpy for long ranges (the same number, faster)."""
    if len(part) < 1 << 18:
        return sum(part)
    import numpy as np

    return int(np.frombuffer(part, dtype=np.uint8).sum(dtype=np.uint64))


def byte_sum(parts: Iterable[Buffer]) -> int:
    return sum(_byte_sum(p) for p in parts)


def crc16_ccitt(parts: Iterable[Buffer]) -> int:
    crc = 0xFFFF
    for p in parts:
        crc = binascii.crc_hqx(p, crc)
    return crc


def crc32(parts: Iterable[Buffer]) -> int:
    crc = 0
    for p in parts:
        crc = zlib.crc32(p, crc)
    return crc


def _crc32c_table() -> tuple[int, ...]:
    rows = []
    for n in range(256):
        c = n
        for _ in range(8):
            c = (c >> 1) ^ 0x82F63B78 if c & 1 else c >> 1  # 0x1EDC6F41 reflected
        rows.append(c)
    return tuple(rows)


_CRC32C = _crc32c_table()


def crc32c(parts: Iterable[Buffer]) -> int:
    crc, table = 0xFFFFFFFF, _CRC32C
    for p in parts:
        for b in bytes(p):
            crc = table[(crc ^ b) & 0xFF] ^ (crc >> 8)
    return crc ^ 0xFFFFFFFF


def fletcher16(parts: Iterable[Buffer]) -> int:
    s1 = s2 = 0
    for p in parts:
        for b in bytes(p):
            s1 = (s1 + b) % 255
            s2 = (s2 + s1) % 255
    return s2 << 8 | s1


def fletcher32(parts: Iterable[Buffer]) -> int:
    data = b"".join(bytes(p) for p in parts)
    if len(data) % 2:
        data += b"\0"
    s1 = s2 = 0
    for k in range(0, len(data), 2):
        s1 = (s1 + (data[k] | data[k + 1] << 8)) % 65535
        s2 = (s2 + s1) % 65535
    return s2 << 16 | s1


KINDS: dict[str, Callable[[Iterable[Buffer]], int]] = {
    "sum": byte_sum,
    "crc16_ccitt": crc16_ccitt,
    "crc32": crc32,
    "crc32c": crc32c,
    "fletcher16": fletcher16,
    "fletcher32": fletcher32,
}


def compute(kind: str, parts: Iterable[Buffer], width: int) -> int:
    """The checksum of kind ``kind`` over ``parts``, as stored in a field of ``width`` bytes.

    The loader refuses an algorithm wider than its field, so only a sum is reduced here."""
    try:
        fn = KINDS[kind]
    except KeyError:
        raise ValueError(f"unknown checksum algorithm kind {kind!r}") from None
    return fn(parts) & ((1 << (8 * width)) - 1)
