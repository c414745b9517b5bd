"""The checksum algorithms: one implementation per family, driven by the parameters.

Every algorithm kind is a set of parameters (cbfgen/registry.py ``ALGORITHMS``, carried here in
``spec_data.json`` as ``checksums.kinds``): a ``sum`` (unsigned byte sum, reduced to the width of
its field), a ``crc`` (the CRC catalogue's model: width, poly, init, refin, refout, xorout) or a
``fletcher`` (16 or 32 bits: little-endian words of width/16 bytes, an odd tail padded with zeros,
two sums modulo 2^(width/2) - 1, result ``sum2 << width/2 | sum1``). Which field uses which
algorithm, the spec says (``checksums.algorithms`` names a kind).

Every function takes the byte ranges of a coverage, in order, as one logical stream (a range may
end in the middle of a Fletcher-32 word). A CRC whose parameters zlib or binascii compute (found
by its parameters, never by its name) runs there, in C; any other runs a table made from its
parameters at first use.
"""

from __future__ import annotations

import binascii
import zlib
from collections.abc import Callable, Iterable
from functools import cache
from typing import Any

from .tables import CHECKSUMS

Buffer = bytes | bytearray | memoryview
Algorithm = Callable[[Iterable[Buffer]], int]

# The parameters of each algorithm kind (registry.ALGORITHMS), by kind.
PARAMETERS: dict[str, dict[str, Any]] = CHECKSUMS["kinds"]


def _byte_sum(part: Buffer) -> int:
    """Sum of the bytes; numpy for long ranges (the same number, faster)."""
    if len(part) < 1 << 18:
        return sum(part)
    import numpy as np

    # numpy adds uint32 about three times faster than uint64; exact while 255 x the length fits
    acc = np.uint32 if len(part) * 255 < 1 << 32 else np.uint64
    return int(np.frombuffer(part, dtype=np.uint8).sum(dtype=acc))


def byte_sum(parts: Iterable[Buffer]) -> int:
    return sum(_byte_sum(p) for p in parts)


def _reflect(value: int, bits: int) -> int:
    return int(format(value, f"0{bits}b")[::-1], 2)


@cache
def _crc_table(width: int, poly: int, refin: bool) -> tuple[int, ...]:
    """The byte table of a CRC: reflected (register right-aligned, poly reflected) when the bytes go
    in least significant bit first, else for a register left-aligned in 32 bits (any width)."""
    rows = []
    if refin:
        rpoly = _reflect(poly, width)
        for n in range(256):
            c = n
            for _ in range(8):
                c = (c >> 1) ^ rpoly if c & 1 else c >> 1
            rows.append(c)
    else:
        apoly = poly << (32 - width)
        for n in range(256):
            c = n << 24
            for _ in range(8):
                c = ((c << 1) ^ apoly) & 0xFFFFFFFF if c & 0x80000000 else (c << 1) & 0xFFFFFFFF
            rows.append(c)
    return tuple(rows)


def _crc(p: dict[str, Any]) -> Algorithm:
    width, poly, init, xorout = int(p["width"]), int(p["poly"]), int(p["init"]), int(p["xorout"])
    refin, refout = bool(p["refin"]), bool(p["refout"])
    if (width, poly, init, refin, refout, xorout) == (32, 0x04C11DB7, 0xFFFFFFFF, True, True, 0xFFFFFFFF):
        def zlib_crc32(parts: Iterable[Buffer]) -> int:
            crc = 0
            for part in parts:
                crc = zlib.crc32(part, crc)
            return crc
        return zlib_crc32
    if (width, poly, refin, refout) == (16, 0x1021, False, False):
        def hqx(parts: Iterable[Buffer]) -> int:
            crc = init
            for part in parts:
                crc = binascii.crc_hqx(part, crc)
            return crc ^ xorout
        return hqx
    table = _crc_table(width, poly, refin)
    shift = 32 - width

    def crc(parts: Iterable[Buffer]) -> int:
        if refin:
            reg = _reflect(init, width)
            for part in parts:
                for b in bytes(part):
                    reg = table[(reg ^ b) & 0xFF] ^ (reg >> 8)
        else:
            reg = init << shift
            for part in parts:
                for b in bytes(part):
                    reg = table[((reg >> 24) ^ b) & 0xFF] ^ ((reg << 8) & 0xFFFFFFFF)
            reg >>= shift
        return (reg if refin == refout else _reflect(reg, width)) ^ xorout

    return crc


def _fletcher(p: dict[str, Any]) -> Algorithm:
    half = int(p["width"]) // 2
    word, modulus = half // 8, (1 << half) - 1

    def fletcher(parts: Iterable[Buffer]) -> int:
        data = b"".join(bytes(part) for part in parts)
        data += bytes(-len(data) % word)
        words: Iterable[int] = data if word == 1 else (int.from_bytes(data[k:k + word], "little")
                                                       for k in range(0, len(data), word))
        s1 = s2 = 0
        for w in words:
            s1 = (s1 + w) % modulus
            s2 = (s2 + s1) % modulus
        return s2 << half | s1

    return fletcher


_FAMILIES: dict[str, Callable[[dict[str, Any]], Algorithm]] = {
    "sum": lambda p: byte_sum,
    "crc": _crc,
    "fletcher": _fletcher,
}

# Every algorithm kind, implemented by its family from its parameters.
KINDS: dict[str, Algorithm] = {k: _FAMILIES[p["family"]](p) for k, p in PARAMETERS.items()}


def compute(kind: str, parts: Iterable[Buffer], width: int) -> int:
    """The checksum of kind ``kind`` over ``parts``, as stored in a field of ``width`` bytes.

    The loader refuses an algorithm wider than its field, so only a sum is reduced here."""
    try:
        fn = KINDS[kind]
    except KeyError:
        raise ValueError(f"unknown checksum algorithm kind {kind!r}") from None
    return fn(parts) & ((1 << (8 * width)) - 1)
