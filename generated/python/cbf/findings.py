"""What validation reports: a Finding, their one order, and the spec's checks by kind.

The lowest layer of validation: the record engine (records.py) and the file checks
(validation.py) both build on it.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from . import tables as T


@dataclass(frozen=True, slots=True)
class Finding:
    check: str
    severity: str
    record: int | None
    offset: int | None
    message: str

    def as_dict(self) -> dict[str, Any]:
        return {"check": self.check, "severity": self.severity, "record": self.record, "offset": self.offset,
                "message": self.message}

    def __str__(self) -> str:
        where = f"record {self.record}" if self.record is not None else "header"
        at = f" @{self.offset}" if self.offset is not None else ""
        return f"{self.severity} {self.check} {where}{at}: {self.message}"


Cutters = Mapping[str, tuple[float, ...]]  # name: the values, in the order of optfiles.CUTTER_VALUES
Check = dict[str, Any]

_CHECK_ORDER = {c["id"]: i for i, c in enumerate(T.CHECKS)}


def finding_order(f: Finding) -> tuple[int, int, int, str]:
    """validate's one order: header first, then by record, spec check order, offset."""
    return (-1 if f.record is None else f.record, _CHECK_ORDER.get(f.check, 0), f.offset or 0, f.message)


def check_of(kind: str) -> Check | None:
    """The spec's first check of a kind (None when the spec has none: nothing is reported)."""
    found = T.checks_of(kind)
    return found[0] if found else None


def finding(check: Mapping[str, Any], record: int | None, offset: int | None, message: str) -> Finding:
    return Finding(check["id"], check["severity"], record, offset, message)


def availability_checks() -> dict[tuple[str, str], Check]:
    """(version, command) -> the one availability check that covers the pair (the loader
    refuses a pair covered twice or not at all), so a finding names the right clause."""
    return {(v, name): c for c in T.checks_of("availability") for v in c["versions"] for name in c["commands"]}


def range_text(ch: Mapping[str, Any]) -> str:
    """How a value fails a range check; either bound may be absent from the spec."""
    lo, hi = ch["min"], ch["max"]
    lo_open, hi_open = ch.get("min_exclusive", False), ch.get("max_exclusive", False)
    if lo is not None and hi is not None:
        return f"outside {'(' if lo_open else '['}{lo:g}..{hi:g}{')' if hi_open else ']'}"
    if lo is not None:
        return f"must be {'>' if lo_open else '>='} {lo:g}"
    return f"must be {'<' if hi_open else '<='} {hi:g}"


def string_value(raw: bytes) -> str:
    """A string field's value: the bytes before the first NUL."""
    return raw.split(b"\0", 1)[0].decode("latin-1")
