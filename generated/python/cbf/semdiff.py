"""`cbf diff`: a semantic diff of two files.

Records are aligned on their exact content (command code and argument bytes),
so an inserted record is one insertion, not a cascade of changes: the common
leading and trailing records are found first, by comparing whole columns with
numpy (identical input costs one pass over the bytes); each record of the rest
is then hashed to a small integer, and a patience matcher (unique records as
anchors, their longest increasing run by binary search, then the same again
between anchors) aligns those: O(N) for the ends and O(M log M) for the M
records between them, where difflib's matcher was quadratic. A stretch with no
unique record is aligned by difflib only when short; a long one stays one
replaced block, whose records pair by command in order. Records that differ
within the tolerance land in such blocks and pair there, equal.
Paired records of the same command compare
argument by argument: numbers (and vectors, by their largest component) are
equal within ``tol``, strings and bytes exactly. Header fields are compared
by name, except the ones the writer derives (magic numbers, checksums, the
command count). The version is compared too.
"""

from __future__ import annotations

import difflib
import math
from array import array
from bisect import bisect_left
from collections import Counter
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, fields
from typing import Any

import numpy as np

from . import tables as T
from .model import Cbf, PackedRecords, Record, RecordList

Progress = Callable[[str], None]
_SMALL = 400  # a stretch without unique records, at most this long (both sides), goes to difflib


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
    vals = {f.name: getattr(model.header, f.name) for f in info.fields if f.role not in T.DERIVED_ROLES}
    vals["version"] = "{}.{}".format(*model.version)
    return vals


def _uint(buf: np.ndarray, at: np.ndarray, size: int) -> np.ndarray:
    """The unsigned integers of ``size`` bytes at each offset ``at`` of ``buf`` (the spec's byte order)."""
    out = np.zeros(len(at), dtype=np.int64)
    order = range(size) if T.BO == ">" else range(size - 1, -1, -1)
    for k in order:
        out = (out << 8) | buf[at + k].astype(np.int64)
    return out


Columns = tuple[np.ndarray, np.ndarray, np.ndarray]  # codes, argument bytes one after another, bounds


def _columns(records: Sequence[Record]) -> Columns:
    """Every record's code and argument bytes as columns (record i's are flat[bounds[i]:bounds[i + 1]])."""
    if isinstance(records, RecordList):
        src, offsets = records.source
        buf = np.frombuffer(src, dtype=np.uint8)
        off = (np.frombuffer(offsets, dtype=offsets.typecode) if isinstance(offsets, array) else
               np.asarray(offsets)).astype(np.int64)  # array.array: no element-by-element copy
        code, size = T.RECORD_BY_ROLE["code"], T.RECORD_BY_ROLE["arg_size"]
        codes = _uint(buf, off + code.offset, code.size)
        sizes = _uint(buf, off + size.offset, size.size)
        bounds = np.zeros(len(off) + 1, dtype=np.int64)
        np.cumsum(sizes, out=bounds[1:])
        if len(off) and int(off[-1]) + T.HEAD_SIZE + int(sizes[-1]) - int(off[0]) == int(bounds[-1]) + \
                T.HEAD_SIZE * len(off):  # the records lie end to end (decode made them): drop the heads
            keep = np.zeros(len(buf), dtype=bool)
            keep[int(off[0]):int(off[-1]) + T.HEAD_SIZE + int(sizes[-1])] = True
            for k in range(T.HEAD_SIZE):  # a head byte column at a time: no records x head-size index matrix
                keep[off + k] = False
            return codes, buf[keep], bounds
        gather = np.repeat(off + T.HEAD_SIZE - bounds[:-1], sizes) + np.arange(int(bounds[-1]), dtype=np.int64)
        return codes, buf[gather], bounds
    if isinstance(records, PackedRecords):
        return (np.asarray(records.codes, dtype=np.int64), np.frombuffer(records.args, dtype=np.uint8),
                np.asarray(records.bounds, dtype=np.int64))
    rs = list(records)
    bounds = np.zeros(len(rs) + 1, dtype=np.int64)
    np.cumsum([len(r.raw_args) for r in rs], out=bounds[1:])
    return (np.asarray([r.code for r in rs], dtype=np.int64),
            np.frombuffer(b"".join(r.raw_args for r in rs), dtype=np.uint8), bounds)


def _same_bytes(ra: Sequence[Record], rb: Sequence[Record]) -> bool:
    """Whether two decoded record lists are the same bytes, laid out alike (the fast path)."""
    if not (isinstance(ra, RecordList) and isinstance(rb, RecordList)) or not len(ra):
        return False
    (sa, oa), (sb, ob) = ra.source, rb.source
    ea, eb = oa[-1] + T.HEAD_SIZE + len(ra[-1].raw_args), ob[-1] + T.HEAD_SIZE + len(rb[-1].raw_args)
    if ea - oa[0] != eb - ob[0] or memoryview(sa)[oa[0]:ea] != memoryview(sb)[ob[0]:eb]:
        return False
    da = np.asarray(oa, dtype=np.int64) if not isinstance(oa, array) else np.frombuffer(oa, dtype=oa.typecode)
    db = np.asarray(ob, dtype=np.int64) if not isinstance(ob, array) else np.frombuffer(ob, dtype=ob.typecode)
    return bool(np.array_equal(da - da[0], db - db[0]))


def _common_run(a: Columns, b: Columns, limit: int) -> int:
    """How many leading records (at most ``limit``) are equal in content, compared column-wise."""
    (ca, fa, ba), (cb, fb, bb) = a, b
    if limit <= 0:
        return 0
    bad = (ca[:limit] != cb[:limit]) | (np.diff(ba[:limit + 1]) != np.diff(bb[:limit + 1]))
    n = int(np.argmax(bad)) if bad.any() else limit
    end = int(ba[n])  # the sizes agree up to n, so do the bounds
    neq = fa[:end] != fb[:end]
    if neq.any():
        n = int(np.searchsorted(ba, int(np.argmax(neq)), side="right")) - 1
    return n


def _reverse(c: Columns) -> Columns:
    codes, flat, bounds = c
    return codes[::-1], flat[::-1], bounds[-1] - bounds[::-1]


def _keys(c: Columns, lo: int, hi: int, ids: dict[tuple[int, bytes], int]) -> list[int]:
    """Records lo..hi as small integers, equal exactly when their code and argument bytes are."""
    codes, flat, bounds = c
    data = flat.tobytes()
    cl, bl = codes.tolist(), bounds.tolist()
    return [ids.setdefault((cl[i], data[bl[i]:bl[i + 1]]), len(ids)) for i in range(lo, hi)]


def _anchors(a: list[int], alo: int, ahi: int, b: list[int], blo: int, bhi: int) -> list[tuple[int, int]]:
    """Patience: the records unique on both sides, their longest run in order on both."""
    ca, cb = Counter(a[alo:ahi]), Counter(b[blo:bhi])
    where_b = {b[j]: j for j in range(blo, bhi) if cb[b[j]] == 1}
    pairs = [(i, where_b[a[i]]) for i in range(alo, ahi) if ca[a[i]] == 1 and a[i] in where_b]
    tails: list[int] = []  # the smallest j ending a run of each length
    tail_at: list[int] = []
    back: list[int] = []
    for k, (_, j) in enumerate(pairs):
        at = bisect_left(tails, j)
        if at == len(tails):
            tails.append(j)
            tail_at.append(k)
        else:
            tails[at], tail_at[at] = j, k
        back.append(tail_at[at - 1] if at else -1)
    run: list[tuple[int, int]] = []
    k = tail_at[-1] if tail_at else -1
    while k >= 0:
        run.append(pairs[k])
        k = back[k]
    return run[::-1]


def match(a: list[int], b: list[int]) -> list[tuple[int, int, int]]:
    """Matching blocks (i, j, n) of two sequences, ascending, then the sentinel (len a, len b, 0)."""
    pairs: list[tuple[int, int]] = []
    todo = [(0, len(a), 0, len(b))]
    while todo:
        alo, ahi, blo, bhi = todo.pop()
        while alo < ahi and blo < bhi and a[alo] == b[blo]:
            pairs.append((alo, blo))
            alo, blo = alo + 1, blo + 1
        while alo < ahi and blo < bhi and a[ahi - 1] == b[bhi - 1]:
            ahi, bhi = ahi - 1, bhi - 1
            pairs.append((ahi, bhi))
        if alo == ahi or blo == bhi:
            continue
        anchors = _anchors(a, alo, ahi, b, blo, bhi)
        if anchors:
            i0, j0 = alo, blo
            for i, j in anchors:
                todo.append((i0, i, j0, j))
                pairs.append((i, j))
                i0, j0 = i + 1, j + 1
            todo.append((i0, ahi, j0, bhi))
        elif (ahi - alo) + (bhi - blo) <= _SMALL:
            sm = difflib.SequenceMatcher(None, a[alo:ahi], b[blo:bhi], autojunk=False)
            pairs.extend((alo + i + k, blo + j + k) for i, j, n in sm.get_matching_blocks() for k in range(n))
    pairs.sort()
    blocks: list[tuple[int, int, int]] = []
    for i, j in pairs:
        if blocks and blocks[-1][0] + blocks[-1][2] == i and blocks[-1][1] + blocks[-1][2] == j:
            blocks[-1] = (blocks[-1][0], blocks[-1][1], blocks[-1][2] + 1)
        else:
            blocks.append((i, j, 1))
    blocks.append((len(a), len(b), 0))
    return blocks


def _opcodes(blocks: list[tuple[int, int, int]], shift: int) -> list[tuple[str, int, int, int, int]]:
    """What difflib's get_opcodes gives for these blocks, the equal ones left out, indices + shift."""
    out = []
    i = j = 0
    for ai, bj, n in blocks:
        if i < ai and j < bj:
            out.append(("replace", i + shift, ai + shift, j + shift, bj + shift))
        elif i < ai:
            out.append(("delete", i + shift, ai + shift, j + shift, j + shift))
        elif j < bj:
            out.append(("insert", i + shift, i + shift, j + shift, bj + shift))
        i, j = ai + n, bj + n
    return out


def diff(a: Cbf, b: Cbf, tol: float, progress: Progress | None = None) -> Diff:
    """The semantic diff of two files; ``progress`` hears what a long run is doing."""
    say = progress or (lambda _: None)
    out = Diff(tol, _compare(_header_values(a), _header_values(b), 0.0), [], len(a.records), len(b.records))
    ra, rb = a.records, b.records
    na, nb = len(ra), len(rb)
    if na == nb and _same_bytes(ra, rb):
        return out  # identical records, head and all: one comparison of the bytes
    ca, cb = _columns(ra), _columns(rb)
    head = _common_run(ca, cb, min(na, nb))
    tail = _common_run(_reverse(ca), _reverse(cb), min(na, nb) - head)
    if head + tail == max(na, nb):
        return out  # the same records: nothing to align
    say(f"{head} leading and {tail} trailing records equal; aligning {na - head - tail} against "
        f"{nb - head - tail} records")
    ids: dict[tuple[int, bytes], int] = {}
    ka, kb = _keys(ca, head, na - tail, ids), _keys(cb, head, nb - tail, ids)
    codes = _opcodes(match(ka, kb), 0)
    say(f"{len(codes)} differing stretch(es); comparing their records")
    for tag, i1, i2, j1, j2 in codes:
        i1, i2, j1, j2 = i1 + head, i2 + head, j1 + head, j2 + head
        if tag in ("insert", "delete"):
            out.ops.append(Op(tag, (i1, i2), (j1, j2)))
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
    # one tolerance for every number (mm, m/s, percent alike): its unit is the number's own
    lines.append(f"{path_a} vs {path_b}: {verdict}, every number within {d.tol:g}: {d.count('insert')} insertion(s), "
                 f"{d.count('delete')} deletion(s), {d.count('change')} change(s), "
                 f"{len(d.header)} header field(s) differ")
    return "\n".join(lines) + "\n"
