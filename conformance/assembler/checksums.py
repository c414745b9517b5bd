"""The checksum algorithms the format spec may name, written for the assembler alone.

Shares no code with the runtimes (a golden file is never made by the code it
tests). Each function takes one byte string. Parameters, by the names of the
CRC catalogue, as spec/cbf.yaml ``checksums.algorithms`` documents them:

- sum          unsigned byte sum (the caller reduces it to the field's width)
- crc16_ccitt  CRC-16/CCITT-FALSE: poly 0x1021, init 0xFFFF, not reflected, xorout 0
- crc32        CRC-32/ISO-HDLC: poly 0x04C11DB7, init 0xFFFFFFFF, reflected, xorout 0xFFFFFFFF
- crc32c       CRC-32C (Castagnoli): poly 0x1EDC6F41, init 0xFFFFFFFF, reflected, xorout 0xFFFFFFFF
- fletcher16   bytes, both sums modulo 255, result sum2 << 8 | sum1
- fletcher32   16-bit little-endian words (odd last byte padded with 0), sums modulo 65535,
               result sum2 << 16 | sum1
"""

from __future__ import annotations

from collections.abc import Callable


def _reflect(value: int, bits: int) -> int:
    out = 0
    for _ in range(bits):
        out = (out << 1) | (value & 1)
        value >>= 1
    return out


def _table(poly: int, bits: int, reflected: bool) -> list[int]:
    top, mask = 1 << (bits - 1), (1 << bits) - 1
    rpoly = _reflect(poly, bits)
    rows = []
    for n in range(256):
        if reflected:
            c = n
            for _ in range(8):
                c = (c >> 1) ^ rpoly if c & 1 else c >> 1
        else:
            c = n << (bits - 8)
            for _ in range(8):
                c = ((c << 1) ^ poly) & mask if c & top else (c << 1) & mask
        rows.append(c)
    return rows


def _crc(poly: int, bits: int, init: int, reflected: bool, xorout: int) -> Callable[[bytes], int]:
    table = _table(poly, bits, reflected)
    mask = (1 << bits) - 1

    def run(data: bytes) -> int:
        c = init
        if reflected:
            for b in data:
                c = table[(c ^ b) & 0xFF] ^ (c >> 8)
        else:
            for b in data:
                c = table[((c >> (bits - 8)) ^ b) & 0xFF] ^ ((c << 8) & mask)
        return c ^ xorout

    return run


def byte_sum(data: bytes) -> int:
    return sum(data)


def fletcher16(data: bytes) -> int:
    a = b = 0
    for x in data:
        a = (a + x) % 255
        b = (b + a) % 255
    return b << 8 | a


def fletcher32(data: bytes) -> int:
    if len(data) % 2:
        data += b"\0"
    a = b = 0
    for k in range(0, len(data), 2):
        a = (a + int.from_bytes(data[k:k + 2], "little")) % 65535
        b = (b + a) % 65535
    return b << 16 | a


ALGORITHMS: dict[str, Callable[[bytes], int]] = {
    "sum": byte_sum,
    "crc16_ccitt": _crc(0x1021, 16, 0xFFFF, False, 0),
    "crc32": _crc(0x04C11DB7, 32, 0xFFFFFFFF, True, 0xFFFFFFFF),
    "crc32c": _crc(0x1EDC6F41, 32, 0xFFFFFFFF, True, 0xFFFFFFFF),
    "fletcher16": fletcher16,
    "fletcher32": fletcher32,
}


def compute(kind: str, data: bytes, width: int) -> int:
    """The checksum of ``kind`` over ``data`` as stored in ``width`` bytes; refuses a result that does not fit."""
    if kind not in ALGORITHMS:
        raise ValueError(f"unknown checksum algorithm kind {kind!r}")
    value = ALGORITHMS[kind](data)
    if kind == "sum":
        return value % (1 << (8 * width))
    if value >> (8 * width):
        raise ValueError(f"{kind} gives {value:#x}, wider than its {width}-byte field")
    return value
