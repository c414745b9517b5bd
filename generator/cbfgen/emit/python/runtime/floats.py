"""binary32 and decimal text, both ways, each rounding exactly once.

``format_float`` writes a binary32 with the fewest significant digits whose text
reads back as the same bits; ``parse_float`` reads decimal text (or a JSON number)
as the binary32 nearest its exact value, ties to even. Reading goes through the
nearest double first (Python's ``float`` rounds correctly) and takes the decimal
path only when that double lies exactly halfway between two binary32 values: only
there can rounding twice differ from rounding once (issue 13, item 6). Both
functions are proven over all 2^32 bit patterns by ``make floats-exhaustive``.
"""

from __future__ import annotations

import math
import struct
from decimal import Decimal
from functools import lru_cache

_F = struct.Struct("<f")
_I = struct.Struct("<I")
_SIGN = 0x80000000
_INF = 0x7F800000
_LIMIT = 2.0 ** 128  # where binary32 would put its next value after the largest finite one


class OutOfRange(ValueError):
    """A number no finite binary32 holds: beyond the range, infinite or not a number."""


def finite(bits: int) -> bool:
    """Whether a binary32 bit pattern is a finite number (not NaN, not infinite)."""
    return bits & _INF != _INF


def _value(bits: int) -> float:
    return float(_F.unpack(_I.pack(bits))[0])


def _neighbour(bits: int, d: float, f: float) -> float:
    """The binary32 on the other side of d from f (the one after the largest is 2^128)."""
    nb = bits + 1 if abs(d) > abs(f) else bits - 1
    if nb & ~_SIGN == _INF:
        return math.copysign(_LIMIT, d)
    return _value(nb)


def _nearest(d: float, exact: str | int | Decimal | None) -> int:
    """Bits of the binary32 nearest the exact value; ``d`` is that value rounded to a double,
    ``exact`` the value itself (None: ``d`` is exact), read as a Decimal only when needed."""
    if not math.isfinite(d):
        raise OutOfRange("is outside the binary32 range" if d == d else "is not a number")
    try:
        bits = int(_I.unpack(_F.pack(d))[0])
    except OverflowError:  # d is at least the largest finite binary32 plus half an ulp
        if exact is None or abs(d) != _LIMIT - 2.0 ** 103 or Decimal(exact).copy_abs() >= Decimal(abs(d)):
            raise OutOfRange("is outside the binary32 range") from None
        return (_SIGN if d < 0 else 0) | 0x7F7FFFFF  # the decimal lies below the halfway point
    f = _value(bits)
    if exact is None or f == d:
        return bits
    g = _neighbour(bits, d, f)
    if d + d != f + g:  # not a halfway point: rounding the decimal directly gives the same
        return bits
    # exact, as is every double (copy_abs: abs() would round to the context's 28 digits)
    half, value = Decimal(abs(d)), Decimal(exact).copy_abs()
    if value == half:
        return bits  # a true tie: struct rounded it to even
    toward_g = (value > half) == (abs(g) > abs(f))
    if not toward_g:
        return bits
    if abs(g) == _LIMIT:
        raise OutOfRange("is outside the binary32 range")
    return int(_I.unpack(_F.pack(g))[0])


def parse_float(text: str) -> int:
    """Bits of the binary32 nearest a decimal numeral (the caller checks its syntax)."""
    return _nearest(float(text), text)


def float_bits(value: int | float | Decimal) -> int:
    """Bits of the binary32 nearest a number: an int or Decimal exactly, a float as the double it is."""
    if isinstance(value, float):
        return _nearest(value, None)
    try:
        d = float(value)
    except OverflowError:  # an int beyond any double
        raise OutOfRange("is outside the binary32 range") from None
    return _nearest(d, value)


def _reads_back(text: str, bits: int) -> bool:
    try:
        return parse_float(text) == bits
    except OutOfRange:  # e.g. 3.403e+38 for 3.40250016e38: no shorter text holds it
        return False


@lru_cache(maxsize=4096)  # a motion starts where the last one ended: values repeat close together
def format_float(bits: int) -> str:
    """The fewest significant digits that read back as ``bits``, in positional notation."""
    v = _value(bits)
    if not math.isfinite(v):
        raise OutOfRange(f"0x{bits:08x} is not a finite binary32 (no CUT number holds it)")
    for p in range(1, 10):
        text = f"{v:.{p}g}"
        if _reads_back(text, bits):
            break
    else:  # 9 significant digits always suffice (make floats-exhaustive checks every pattern)
        raise AssertionError(f"0x{bits:08x}: no text of at most 9 digits reads back")
    if "e" in text:
        text = format(Decimal(text), "f")
    return text
