"""The checksum algorithms the format spec may name, written for the assembler alone.

Shares no code with the runtimes (a golden file is never made by the code it tests): what it
takes from generator/ is data, the parameters of each algorithm kind (cbfgen/registry.py
``ALGORITHMS``: family, width, poly, init, refin, refout, xorout). Each family is implemented here
once, the CRC as the catalogue's model reads (most significant bit first, each message byte
reflected for refin; a byte at a time through a table of that same step), not as a runtime does
it. Each kind's catalogue check value (over ASCII "123456789") is tested here as in every runtime
(tests/test_checksum_algorithms.py): a wrong parameter fails there, not silently in both. Each
function takes one byte string.

- sum       unsigned byte sum (the caller reduces it to the field's width)
- crc       the Rocksoft model: width, poly, init, refin, refout, xorout
- fletcher  16 or 32 bits: little-endian words of width/16 bytes (odd tail padded with 0), two
            sums modulo 2^(width/2) - 1, result sum2 << width/2 | sum1
"""

from __future__ import annotations

from collections.abc import Callable

from cbfgen.registry import ALGORITHMS as PARAMETERS
from cbfgen.registry import ChecksumAlgorithm


def _reflect(value: int, bits: int) -> int:
    out = 0
    for _ in range(bits):
        out = (out << 1) | (value & 1)
        value >>= 1
    return out


def _crc(a: ChecksumAlgorithm) -> Callable[[bytes], int]:
    bits = a.width or 0
    top, mask = 1 << (bits - 1), (1 << bits) - 1

    def step(c: int, byte: int) -> int:
        """The register after one message byte, bit by bit, most significant bit first."""
        for k in range(8):
            bit = (byte >> (7 - k)) & 1
            c = ((c << 1) & mask) ^ (a.poly if bool(c & top) != bool(bit) else 0)
        return c

    # 8 bits at a time once the register holds a byte: the register's top byte, shifted out, is
    # a function of itself and the message byte (the same arithmetic as step, tabulated)
    table = [step(n << (bits - 8), 0) for n in range(256)] if bits >= 8 else []
    order = [_reflect(b, 8) if a.refin else b for b in range(256)]  # refin: least significant bit first

    def run(data: bytes) -> int:
        c = a.init
        for b in data:
            m = order[b]
            c = ((c << 8) & mask) ^ table[((c >> (bits - 8)) ^ m) & 0xFF] if table else step(c, m)
        return (_reflect(c, bits) if a.refout else c) ^ a.xorout

    return run


def byte_sum(data: bytes) -> int:
    return sum(data)


def _fletcher(a: ChecksumAlgorithm) -> Callable[[bytes], int]:
    half = (a.width or 0) // 2
    word, modulus = half // 8, (1 << half) - 1

    def run(data: bytes) -> int:
        data += b"\0" * (-len(data) % word)
        s1 = s2 = 0
        for k in range(0, len(data), word):
            s1 = (s1 + int.from_bytes(data[k:k + word], "little")) % modulus
            s2 = (s2 + s1) % modulus
        return s2 << half | s1

    return run


_FAMILIES: dict[str, Callable[[ChecksumAlgorithm], Callable[[bytes], int]]] = {
    "sum": lambda a: byte_sum,
    "crc": _crc,
    "fletcher": _fletcher,
}

ALGORITHMS: dict[str, Callable[[bytes], int]] = {k: _FAMILIES[a.family](a) for k, a in PARAMETERS.items()}


def compute(kind: str, data: bytes, width: int) -> int:
    """The checksum of ``kind`` over ``data`` as stored in ``width`` bytes; refuses a result that does not fit."""
    if kind not in ALGORITHMS:
        raise ValueError(f"unknown checksum algorithm kind {kind!r}")
    value = ALGORITHMS[kind](data)
    if PARAMETERS[kind].family == "sum":
        return value % (1 << (8 * width))
    if value >> (8 * width):
        raise ValueError(f"{kind} gives {value:#x}, wider than its {width}-byte field")
    return value
