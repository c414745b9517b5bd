"""binary32 and decimal text, both ways, each rounding exactly once.

``format_float`` writes a binary32 with the fewest significant digits whose text
reads back as the same bits; ``read_decimal`` reads decimal text (CUT's and JSON's numbers alike:
the one reader) as the binary32 nearest its exact value, ties to even, the sign of zero kept,
the exponent bounded before any arithmetic. Reading goes through the
nearest double first (Python's ``float`` rounds correctly) and takes the decimal
path only when that double lies exactly halfway between two binary32 values: only
there can rounding twice differ from rounding once (issue 13, item 6). Both
functions are proven over all 2^32 bit patterns by ``make floats-exhaustive``.
"""

from __future__ import annotations

import math
import re
import struct
from decimal import Decimal
from functools import lru_cache
from itertools import repeat
from typing import Any

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


# A decimal numeral: an optional sign, digits with an optional point (or a point and digits), an
# optional exponent. Python's float() also takes "inf", "nan", "1_0", spaces and non-ASCII digits:
# none of them is decimal text, and none reaches it.
_NUMERAL = re.compile(r"([+-]?)(?:(\d+)(?:\.(\d*))?|\.(\d+))(?:[eE]([+-]?\d+))?", re.ASCII)
_EXP_DIGITS = 6  # an exponent of more digits (leading zeros aside) is beyond any binary32 either way
_ABOVE = 38  # a leading digit at 10^39 or above: at least 1e39, beyond FLT_MAX (3.4e38)
_BELOW = -46  # a value below 10^-46 lies under half the smallest subnormal (7.0e-46): a signed zero


class NotDecimal(ValueError):
    """Text that is not a decimal numeral."""


def read_decimal(text: str) -> int:
    """Bits of the binary32 nearest a decimal numeral: THE reader of decimal text (CUT and JSON).

    The sign of zero is kept (``-0`` and ``-0.0e5`` are 0x80000000); the exponent is bounded
    before any arithmetic (``1e1000000000000000000`` is beyond the range at once, ``1e-999999999``
    a signed zero), so no text costs more than reading it; a value no finite binary32 holds raises
    OutOfRange, text that is not a numeral NotDecimal."""
    m = _NUMERAL.fullmatch(text)
    if m is None:
        raise NotDecimal("is not a decimal number")
    sign, whole, frac, only_frac, exp = m.groups()
    digits = (whole or "") + (frac or only_frac or "")
    lead = len(digits) - len(digits.lstrip("0"))
    if lead == len(digits):  # every digit zero: a zero of the sign written
        return _SIGN if sign == "-" else 0
    e_text = (exp or "0").lstrip("+-").lstrip("0")
    if len(e_text) > _EXP_DIGITS:
        if exp is not None and exp.startswith("-"):
            return _SIGN if sign == "-" else 0
        raise OutOfRange("is outside the binary32 range")
    e = int(e_text or "0") * (-1 if exp is not None and exp.startswith("-") else 1)
    point = len(whole or "")  # digits before the point
    top = e + point - lead - 1  # the power of ten of the leading non-zero digit
    if top > _ABOVE:
        raise OutOfRange("is outside the binary32 range")
    if top < _BELOW:
        return _SIGN if sign == "-" else 0
    return _nearest(float(text), text)


def parse_float(text: str) -> int:
    """Bits of the binary32 nearest a decimal numeral: ``read_decimal`` (kept for its callers)."""
    return read_decimal(text)


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
        return read_decimal(text) == bits
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


# -- many at once ------------------------------------------------------------------------
# format_floats computes format_float's function for a whole array, with numpy doing the
# reading back. It is the same function, not an approximation of it:
#
# - A pattern whose mantissa bits are zero (a power of two, zero, the smallest normal) has an
#   interval of binary32 rounding that is narrower below than above; for those the plain loop
#   of format_float runs.
# - Every other finite pattern has a symmetric interval (both ends in or both out, ties to
#   even). The p-digit numbers are among the (p+1)-digit ones, so "%.{p+1}g" lies no farther
#   from the value than "%.{p}g"; in a symmetric interval, once "%.{p}g" reads back, every
#   longer one does. So the fewest p that reads back is the one p that reads back while p - 1
#   does not (or p = 1), and a search from any first guess that stops there finds it.
# - Reading back is parse_float's test, vectorised: float() rounds the text to the nearest
#   double, numpy rounds that to binary32 (ties to even, as struct does); where the double
#   lies exactly halfway between two binary32 values, or is beyond the range, parse_float
#   itself decides, as it does for the loop.
_SPECS = tuple(f".{p}g" for p in range(10))
_GUESS = ".7g"  # %g drops trailing zeros after the point: its significant digits are a close guess


def _reads_back_many(texts: list[str], bits: Any) -> Any:
    """Whether each text reads back as its pattern (parse_float's test)."""
    got, bad = parse_floats(texts)
    ok = got == bits
    ok[bad] = False
    return ok


def format_floats(bits: Any) -> list[str]:
    """``[format_float(b) for b in bits]`` for a numpy array of finite binary32 patterns (uint32)."""
    import numpy as np
    import numpy.strings as ns

    bits = np.ascontiguousarray(bits, dtype=np.uint32)
    out: list[str] = [""] * len(bits)
    for k in np.flatnonzero((bits & 0x7FFFFF) == 0).tolist():
        out[k] = format_float(int(bits[k]))
    idx = np.flatnonzero((bits & 0x7FFFFF) != 0)
    if not len(idx):
        return out
    b = bits[idx]
    v = b.view(np.float32).astype(np.float64)
    specs = np.array(_SPECS, dtype=object)
    # The guess: "%.7g" has p <= 7 significant digits once its trailing zeros go; when p < 7 it
    # is the value rounded to p digits (the value lies within half a 7th digit of it), so it
    # is "%.{p}g" as a number (and the same text once written positionally).
    texts = list(map(format, v.tolist(), repeat(_GUESS)))
    mant = ns.replace(ns.replace(ns.partition(np.array(texts), "e")[0], "-", ""), ".", "")
    p = np.maximum(ns.str_len(ns.strip(mant, "0")), 1).astype(np.int64)
    ok = _reads_back_many(texts, b)
    # When the guess reads back, p - 1 digits can only read back too for p >= 7 or a subnormal:
    # the guess ends in a non-zero digit, so "%.{p-1}g" lies at least one p-th digit unit U
    # from it, and at least U/2 from the value; for p <= 6 and a normal value U/2 is above
    # 0.47e-6 of the value, the interval's half-width below 0.6e-7 of it.
    down = ok & (p > 1) & ((p >= 7) | ((b & 0x7F800000) == 0))
    # Up: until a p reads back (at most 9: make floats-exhaustive proves it).
    todo = np.flatnonzero(~ok)
    while len(todo):
        p[todo] += 1
        if np.any(p[todo] > 9):
            k = int(todo[p[todo] > 9][0])
            raise AssertionError(f"0x{int(b[k]):08x}: no text of at most 9 digits reads back")
        t = list(map(format, v[todo].tolist(), specs[p[todo]].tolist()))
        good = _reads_back_many(t, b[todo])
        for k, s in zip(todo[good].tolist(), [s for s, g in zip(t, good.tolist(), strict=True) if g], strict=True):
            texts[k] = s
        todo = todo[~good]
    # Down: while p - 1 reads back too.
    todo = np.flatnonzero(down)
    while len(todo):
        t = list(map(format, v[todo].tolist(), specs[p[todo] - 1].tolist()))
        good = _reads_back_many(t, b[todo])
        for k, s in zip(todo[good].tolist(), [s for s, g in zip(t, good.tolist(), strict=True) if g], strict=True):
            texts[k] = s
        todo = todo[good]
        p[todo] -= 1
        todo = todo[p[todo] > 1]
    for k, s in zip(idx.tolist(), texts, strict=True):
        out[k] = format(Decimal(s), "f") if "e" in s else s
    return out


def parse_floats(texts: list[str]) -> tuple[Any, list[int]]:
    """``parse_float`` of each decimal numeral (syntax checked by the caller), vectorised: the
    bits as a numpy uint32 array, and the indices of the texts read_decimal refuses (OutOfRange,
    NotDecimal; their bits are 0). The double nearest each text is rounded to binary32 by numpy (ties to
    even, as struct does); where it lies exactly halfway, or beyond the range, parse_float decides."""
    import numpy as np

    # float() takes more than decimal numerals ("inf", "1_0", spaces): texts of other characters,
    # or that float() refuses, are read one by one by read_decimal, which refuses them
    strange = bool("".join(texts).encode("ascii", "replace").translate(None, b"0123456789.eE+-"))
    try:
        d = np.fromiter(map(float, texts), dtype=np.float64, count=len(texts)) if not strange else None
    except ValueError:
        d = None
    if d is None:
        return _parse_floats_one_by_one(texts)
    with np.errstate(over="ignore", invalid="ignore"):
        f = d.astype(np.float32)
        fd = f.astype(np.float64)
        toward = np.where(d > fd, np.float32(np.inf), np.float32(-np.inf))
        g = np.nextafter(f, toward).astype(np.float64)
        unsure = ~np.isfinite(f) | ((fd != d) & (d + d == fd + g))
    bits = f.view(np.uint32).copy()
    bad: list[int] = []
    for k in np.flatnonzero(unsure).tolist():
        try:
            bits[k] = read_decimal(texts[k])
        except (OutOfRange, NotDecimal):
            bits[k] = 0
            bad.append(k)
    return bits, bad


def _parse_floats_one_by_one(texts: list[str]) -> tuple[Any, list[int]]:
    import numpy as np

    bits = np.zeros(len(texts), dtype=np.uint32)
    bad: list[int] = []
    for k, text in enumerate(texts):
        try:
            bits[k] = read_decimal(text)
        except (OutOfRange, NotDecimal):
            bad.append(k)
    return bits, bad
