"""Comparison rules: floats by binary32 bits, findings as sorted multisets of (check, severity, record, offset)."""

from __future__ import annotations

import math
import struct
from collections import Counter
from typing import Any

WILDCARD = "*"


def f32_bits(value: Any) -> int | None:
    """The binary32 bits a canonical-JSON float stands for, or None if it is not one."""
    if isinstance(value, bool):
        return None
    if isinstance(value, str) and len(value) == 10 and value.startswith("0x"):
        try:
            return int(value[2:], 16)
        except ValueError:
            return None
    if isinstance(value, (int, float)):
        try:
            return int(struct.unpack("<I", struct.pack("<f", float(value)))[0])
        except OverflowError:
            return None
    return None


def _floatish(v: Any) -> bool:
    return isinstance(v, float) or (isinstance(v, str) and len(v) == 10 and v.startswith("0x"))


def _number_like(v: Any) -> bool:
    return not isinstance(v, bool) and isinstance(v, int | float | str)


def first_difference(expected: Any, actual: Any, path: str = "$") -> str | None:
    """None when actual matches expected; else where and how they differ.

    Keys named ``offset`` may be left out of the expectation; ``"*"`` matches anything.
    """
    if expected == WILDCARD:
        return None
    if isinstance(expected, dict):
        if not isinstance(actual, dict):
            return f"{path}: expected an object, got {_short(actual)}"
        for key in expected:
            if key not in actual:
                return f"{path}.{key}: missing"
        for key in actual:
            if key not in expected and key != "offset":
                return f"{path}.{key}: unexpected key"
        for key, value in expected.items():
            diff = first_difference(value, actual[key], f"{path}.{key}")
            if diff:
                return diff
        return None
    if isinstance(expected, list):
        if not isinstance(actual, list):
            return f"{path}: expected a list, got {_short(actual)}"
        if len(expected) != len(actual):
            return f"{path}: expected {len(expected)} items, got {len(actual)}"
        for i, (e, a) in enumerate(zip(expected, actual, strict=True)):
            diff = first_difference(e, a, f"{path}[{i}]")
            if diff:
                return diff
        return None
    if _number_like(expected) and _number_like(actual) and (_floatish(expected) or _floatish(actual)):
        eb, ab = f32_bits(expected), f32_bits(actual)
        if eb is None or ab is None or eb != ab:
            return f"{path}: expected {_short(expected)} ({_bits(eb)}), got {_short(actual)} ({_bits(ab)})"
        return None
    if type(expected) is not type(actual) and not (isinstance(expected, int) and isinstance(actual, int)):
        return f"{path}: expected {_short(expected)}, got {_short(actual)}"
    if expected != actual:
        return f"{path}: expected {_short(expected)}, got {_short(actual)}"
    return None


def _bits(b: int | None) -> str:
    return "-" if b is None else f"0x{b:08x}"


def _short(v: Any) -> str:
    text = repr(v)
    return text if len(text) <= 60 else text[:57] + "..."


FindingKey = tuple[str, str, int, int]


def finding_key(f: Any) -> FindingKey:
    """(check, severity, record, offset), record -1 for null, from a testee's finding dict or an
    expectation's [check, severity, record, offset] list. Offset -1 when absent (never expected)."""
    if isinstance(f, dict):
        check, sev, rec, off = f.get("check"), f.get("severity"), f.get("record"), f.get("offset")
    else:
        if len(f) != 4:
            raise ValueError(f"expected finding {f!r}: needs [check, severity, record, offset]")
        check, sev, rec, off = f[0], f[1], f[2], f[3]
    return (str(check), str(sev), -1 if rec is None else int(rec), -1 if off is None else int(off))


def findings_difference(expected: list[Any], actual: list[Any]) -> str | None:
    """None when the multisets of (check, severity, record, offset) are equal; else what is missing and extra."""
    e = sorted(finding_key(f) for f in expected)
    a = sorted(finding_key(f) for f in actual)
    if e == a:
        return None
    # counted once (list.count per finding was quadratic: a broken binding that reports the 65,535
    # records of the largest case ran for minutes before it said so)
    ec, ac = Counter(e), Counter(a)
    missing = [k for k in dict.fromkeys(e) if ec[k] > ac[k]]
    extra = [k for k in dict.fromkeys(a) if ac[k] > ec[k]]
    parts = []
    if missing:
        parts.append("missing " + ", ".join(_fk(k) for k in missing))
    if extra:
        parts.append("unexpected " + ", ".join(_fk(k) for k in extra))
    return "; ".join(parts)


def _fk(k: FindingKey) -> str:
    where = "header" if k[2] < 0 else f"record {k[2]}"
    at = "no offset" if k[3] < 0 else f"offset {k[3]}"
    return f"{k[0]}/{k[1]}/{where} @{at}"


def is_nan_bits(bits: int) -> bool:
    return math.isnan(struct.unpack("<f", struct.pack("<I", bits))[0])
