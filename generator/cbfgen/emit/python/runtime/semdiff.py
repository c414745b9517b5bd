"""`cbf diff`: a semantic diff of two files.

Records are aligned by difflib.SequenceMatcher on (command, arguments
rounded to the tolerance's decimals), so an inserted record is one insertion,
not a cascade of changes. Paired records of the same command compare
argument by argument: numbers (and vectors, by their largest component) are
equal within ``tol``, strings and bytes exactly. Header fields are compared
by name, except the ones the writer derives (magic numbers, checksums, the
command count). The version is compared too.
"""

from __future__ import annotations

import difflib
import math
from dataclasses import dataclass, field, fields
from typing import Any

from . import tables as T
from .model import Cbf, Record

_DERIVED = {"start_pattern", "end_pattern", "checksum", "command_count"}


@dataclass(frozen=True)
class ArgDelta:
    name: str
    a: Any
    b: Any
    delta: float | None  # the largest absolute difference of a number or vector; None for text and bytes


@dataclass(frozen=True)
class Op:
    kind: str  # insert | delete | change
    a: tuple[int, int]  # record range in A, [start, end)
    b: tuple[int, int]
    deltas: tuple[ArgDelta, ...] = ()


@dataclass
class Diff:
    tol: float
    header: list[ArgDelta] = field(default_factory=list)
    ops: list[Op] = field(default_factory=list)
    records_a: int = 0
    records_b: int = 0

    @property
    def equal(self) -> bool:
        return not self.header and not self.ops

    def count(self, kind: str) -> int:
        return sum(1 for o in self.ops if o.kind == kind)


def _plain(v: Any) -> Any:
    if isinstance(v, bytes):
        return v.hex()
    if isinstance(v, float) and not math.isfinite(v):
        return repr(v)
    if isinstance(v, tuple):
        return [_plain(x) for x in v]
    return v


def _values(model: Cbf, r: Record) -> dict[str, Any]:
    """The record's arguments by name, or its raw bytes when no layout decodes them."""
    a = r.decode_args(model.version_id) if r.command else None
    if a is None:
        return {"raw_args": r.raw_args}
    return {f.name: getattr(a, f.name) for f in fields(a)}


def _key(model: Cbf, r: Record, decimals: int) -> tuple[Any, ...]:
    out: list[Any] = [r.code]
    for v in _values(model, r).values():
        if isinstance(v, float):
            out.append(round(v, decimals) if math.isfinite(v) else repr(v))
        elif isinstance(v, tuple):
            out.append(tuple(round(x, decimals) if math.isfinite(x) else repr(x) for x in v))
        else:
            out.append(v)
    return tuple(out)


def _delta(a: Any, b: Any) -> float | None:
    if isinstance(a, float) and isinstance(b, float):
        if a == b or (math.isnan(a) and math.isnan(b)):
            return 0.0
        return abs(a - b) if math.isfinite(a) and math.isfinite(b) else math.inf
    if isinstance(a, tuple) and isinstance(b, tuple) and len(a) == len(b):
        ds = [_delta(x, y) for x, y in zip(a, b, strict=True)]
        return max((d for d in ds if d is not None), default=0.0)
    if isinstance(a, int) and isinstance(b, int) and not isinstance(a, bool):
        return float(abs(a - b))
    return None


def _compare(va: dict[str, Any], vb: dict[str, Any], tol: float) -> list[ArgDelta]:
    out = []
    for name in dict.fromkeys([*va, *vb]):
        a, b = va.get(name), vb.get(name)
        d = _delta(a, b)
        if d is None:
            if a != b:
                out.append(ArgDelta(name, a, b, None))
        elif d > tol or (isinstance(a, int) and d > 0):
            out.append(ArgDelta(name, a, b, d))
    return out


def _header_values(model: Cbf) -> dict[str, Any]:
    info = T.HEADERS[T.VERSION_BY_ID[model.version_id].header]
    vals = {f.name: getattr(model.header, f.name) for f in info.fields if f.role not in _DERIVED
            and f.role not in ("version_major", "version_minor")}
    vals["version"] = "{}.{}".format(*model.version)
    return vals


def diff(a: Cbf, b: Cbf, tol: float) -> Diff:
    decimals = max(0, math.ceil(-math.log10(tol))) if tol > 0 else 9
    out = Diff(tol, _compare(_header_values(a), _header_values(b), 0.0), [], len(a.records), len(b.records))
    ra, rb = list(a.records), list(b.records)
    ka = [_key(a, r, decimals) for r in ra]
    kb = [_key(b, r, decimals) for r in rb]
    sm = difflib.SequenceMatcher(None, ka, kb, autojunk=False)
    for tag, i1, i2, j1, j2 in sm.get_opcodes():
        if tag == "equal":
            continue
        if tag == "insert":
            out.ops.append(Op("insert", (i1, i2), (j1, j2)))
            continue
        if tag == "delete":
            out.ops.append(Op("delete", (i1, i2), (j1, j2)))
            continue
        # replace: pair records of the same command in order; the rest are deletions / insertions
        i, j = i1, j1
        while i < i2 or j < j2:
            if i < i2 and j < j2 and ra[i].code == rb[j].code:
                deltas = _compare(_values(a, ra[i]), _values(b, rb[j]), tol)
                if deltas:
                    out.ops.append(Op("change", (i, i + 1), (j, j + 1), tuple(deltas)))
                i, j = i + 1, j + 1
            elif i < i2 and (j >= j2 or (i2 - i) >= (j2 - j)):
                out.ops.append(Op("delete", (i, i + 1), (j, j)))
                i += 1
            else:
                out.ops.append(Op("insert", (i, i), (j, j + 1)))
                j += 1
    out.ops = _merge(out.ops)
    return out


def _merge(ops: list[Op]) -> list[Op]:
    """Adjacent insertions (or deletions) at one place are one operation."""
    merged: list[Op] = []
    for o in ops:
        p = merged[-1] if merged else None
        if p and o.kind == p.kind == "insert" and p.a == o.a and p.b[1] == o.b[0]:
            merged[-1] = Op("insert", p.a, (p.b[0], o.b[1]))
        elif p and o.kind == p.kind == "delete" and p.a[1] == o.a[0] and p.b == o.b:
            merged[-1] = Op("delete", (p.a[0], o.a[1]), p.b)
        else:
            merged.append(o)
    return merged


def as_dict(d: Diff, path_a: str, path_b: str) -> dict[str, Any]:
    def delta(x: ArgDelta) -> dict[str, Any]:
        return {"name": x.name, "a": _plain(x.a), "b": _plain(x.b), "delta": x.delta}

    return {
        "schema": 1,
        "a": path_a, "b": path_b, "tol": d.tol, "equal": d.equal,
        "records": {"a": d.records_a, "b": d.records_b},
        "header": [delta(x) for x in d.header],
        "ops": [{"op": o.kind, "a": list(o.a), "b": list(o.b), "args": [delta(x) for x in o.deltas]} for o in d.ops],
        "summary": {k: d.count(k) for k in ("insert", "delete", "change")},
    }


def _fmt(v: Any) -> str:
    if isinstance(v, tuple):
        return "<" + ", ".join(f"{x:g}" if isinstance(x, float) else str(x) for x in v) + ">"
    if isinstance(v, float):
        return f"{v:g}"
    if isinstance(v, bytes):
        return v.hex()
    return repr(v)


def _describe(model: Cbf, r: Record) -> str:
    vals = _values(model, r)
    name = r.name or f"0x{r.code:02X}"
    return name + "".join(f" {k}={_fmt(v)}" for k, v in vals.items())


def render(d: Diff, a: Cbf, b: Cbf, path_a: str, path_b: str) -> str:
    lines = [f"--- {path_a}", f"+++ {path_b}"]
    for x in d.header:
        lines.append(f"header {x.name}: {_fmt(x.a)} -> {_fmt(x.b)}")
    for o in d.ops:
        if o.kind == "insert":
            lines.append(f"@@ after record {o.a[0] - 1} of A: {o.b[1] - o.b[0]} record(s) inserted")
            lines.extend(f"+ B[{j}] {_describe(b, b.records[j])}" for j in range(*o.b))
        elif o.kind == "delete":
            lines.append(f"@@ A records {o.a[0]}..{o.a[1] - 1}: {o.a[1] - o.a[0]} record(s) deleted")
            lines.extend(f"- A[{i}] {_describe(a, a.records[i])}" for i in range(*o.a))
        else:
            name = a.records[o.a[0]].name or "record"
            lines.append(f"~ A[{o.a[0]}] -> B[{o.b[0]}] {name}: " + "; ".join(
                f"{x.name} {_fmt(x.a)} -> {_fmt(x.b)}" + (f" (delta {x.delta:g})" if x.delta is not None else "")
                for x in o.deltas))
    verdict = "equal" if d.equal else "differ"
    lines.append(f"{path_a} vs {path_b}: {verdict} within {d.tol} mm: {d.count('insert')} insertion(s), "
                 f"{d.count('delete')} deletion(s), {d.count('change')} change(s), "
                 f"{len(d.header)} header field(s) differ")
    return "\n".join(lines) + "\n"
