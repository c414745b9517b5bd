"""The record checks: one engine, vectorised with numpy, one kernel per check kind.

``KERNELS`` maps each record check kind of the spec to the one function that implements it.
A kernel reads the file's records as columns (``Records``: the head fields of every record,
and ``Batch``es: the records of one layout, their arguments as columns) and reports the rows
it flags. A new check kind is one kernel and one entry in ``KERNELS``. The file-level checks
(header, framing, file checksum) are in validation.py, which calls ``record_findings``.

Findings come out in validate's order (findings.finding_order), one at a time: each check
keeps only the rows it flagged (a few bytes each) and makes a finding's message when it is
read, so memory stays a small multiple of the file however many findings it gives.
"""

from __future__ import annotations

import heapq
import math
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from functools import lru_cache
from typing import TYPE_CHECKING, Any

import numpy as np

from . import tables as T
from .codec import field_checksum
from .findings import (
    Check,
    Cutters,
    Finding,
    availability_checks,
    finding,
    finding_order,
    range_text,
    string_value,
)
from .machine import DEFAULT as DEFAULT_MACHINE
from .machine import Limit, Machine, breach, machine_rules
from .optfiles import CUTTER_NAME, CUTTER_VALUES
from .rowsums import exact_sums32, row_checksums

if TYPE_CHECKING:
    from numpy.typing import NDArray

Message = Callable[[Any], str]


@dataclass(slots=True)
class Batch:
    """The records of one layout: their row numbers, argument offsets and argument columns
    (floats as float64, a vector as an n x count array; uints as they are; strings n x size)."""

    lay: T.LayoutInfo
    cmd: T.CommandInfo
    rows: Any
    aoff: Any
    cols: Mapping[str, Any]  # floats as float64
    raw: Mapping[str, Any]  # the arguments as stored (floats binary32: exact, half the memory)
    nul: dict[str, Any] = field(default_factory=dict)  # string argument -> where its first NUL is
    plain: dict[str, bool] = field(default_factory=dict)  # string argument -> every row a plain string
    bytes_: Any = None  # the argument bytes, rows x layout size
    # the records of every layout of this argument size the file uses, batched together: (the
    # position of the first layout in _size_order, their rows, their argument bytes, where their
    # rows start in the order of _batches)
    group: tuple[int, Any, Any, int] | None = None

    def at(self, name: str) -> Any:
        """The file offset of argument ``name`` in every row."""
        return self.aoff + next(f.offset for f in self.lay.args if f.name == name)


@dataclass(slots=True)
class Records:
    """What the kernels read, and where they report."""

    buf: bytes
    a: Any  # the file as uint8
    off: Any  # record offsets (int64)
    version: str
    profile: str
    cutters: Cutters | None
    machine: Machine  # the limits of check kind machine_limits (machine.DEFAULT when none is given)
    head: dict[str, Any] = field(default_factory=dict)  # head field role -> column
    groups: list[Iterator[Finding]] = field(default_factory=list)  # each in validate's order
    pending: list[Finding] = field(default_factory=list)  # findings made one at a time
    state: dict[str, Any] = field(default_factory=dict)  # what a kernel keeps between batches

    def add(self, check: Check | None, rows: Any, offs: Any, keys: Any, msg: Message) -> None:
        """The findings of ``check`` at ``rows`` (ascending), the k-th message msg(keys[k])."""
        if check is None or not len(rows):
            return
        narrow = _narrow(self)
        held = np.asarray(rows).astype(narrow)
        self.groups.append(_lazy(check, held, np.asarray(offs).astype(narrow), held if keys is rows else keys, msg))

    def found(self, check: Check, record: int, offset: int, message: str) -> None:
        self.pending.append(finding(check, record, offset, message))


def _narrow(r: Records) -> type[np.signedinteger[Any]]:
    """The integer type that holds every row number and offset of the file (4 bytes under 2 GiB)."""
    return np.int32 if len(r.buf) < 1 << 31 else np.int64


def _lazy(check: Check, rows: Any, offs: Any, keys: Any, msg: Message) -> Iterator[Finding]:
    cid, sev = check["id"], check["severity"]
    for k in range(len(rows)):
        yield Finding(cid, sev, int(rows[k]), int(offs[k]), msg(keys[k]))


def _const(message: str) -> Message:
    return lambda _: message


def _valued(before: str, values: Any, after: str) -> Message:
    """before + the k-th value (as %g) + after, bound now (the caller's loop moves on)."""
    return lambda k: f"{before}{float(values[k]):g}{after}"


# -- columns ------------------------------------------------------------------------
def _uint(cols: NDArray[np.uint8], f: T.FieldInfo) -> NDArray[Any]:
    """An unsigned field of every row, in its own width (memory stays a few bytes a record)."""
    if f.size in (1, 2, 4, 8):
        part = np.ascontiguousarray(cols[:, f.offset:f.offset + f.size])
        return part.view(np.dtype(f"{T.BO}u{f.size}"))[:, 0]
    v = np.zeros(cols.shape[0], dtype=np.int64)
    for k in range(f.size):
        shift = 8 * (k if T.BO == "<" else f.size - 1 - k)
        v |= cols[:, f.offset + k].astype(np.int64) << shift
    return v


def _gather(a: NDArray[np.uint8], starts: NDArray[np.int64], width: int) -> NDArray[np.uint8]:
    """Bytes a[s:s+width] for each start, as rows (each start + width <= len(a)). The file is viewed
    as overlapping items of ``width`` bytes, one at each offset (no copy), so the gather copies one
    item a row: about ten times faster than an index matrix or a sliding-window view on rows of a
    few bytes. (Opaque items: numpy copies a structured item field by field, ten times slower.)"""
    if width == 0 or starts.shape[0] == 0:
        return np.empty((starts.shape[0], width), dtype=np.uint8)
    items = np.ndarray((a.shape[0] - width + 1,), dtype=np.dtype((np.void, width)), buffer=a, strides=(1,))
    return items[starts].view(np.uint8).reshape(starts.shape[0], width)


def _head(a: NDArray[np.uint8], off: NDArray[np.int64]) -> dict[str, Any]:
    """The head fields of every record (role -> column): one gather of the heads as opaque
    items, each field a strided view of them (1-, 2-, 4- and 8-byte fields; others are assembled
    from their bytes). The views hold the gathered heads, as many bytes as copies of every field
    would, and spare a copy a field."""
    plain, dtype = _head_dtype()
    rows = _gather(a, off, T.HEAD_SIZE)
    heads = rows.view(dtype)[:, 0]
    out = {f.role or f.name: heads[f.name] for f in plain}  # views of the rows (copies cost more than they save)
    for f in T.RECORD_FIELDS:
        if f.size not in _PLAIN_SIZES:
            out[f.role or f.name] = _uint(rows, f)
    return out


_PLAIN_SIZES = (1, 2, 4, 8)


@lru_cache(maxsize=1)
def _head_dtype() -> tuple[list[T.FieldInfo], np.dtype[Any]]:
    """The head fields of 1, 2, 4 or 8 bytes, and the structured dtype of a head that holds them."""
    plain = [f for f in T.RECORD_FIELDS if f.size in _PLAIN_SIZES]
    return plain, np.dtype({"names": [f.name for f in plain], "formats": [f"{T.BO}u{f.size}" for f in plain],
                            "offsets": [f.offset for f in plain], "itemsize": T.HEAD_SIZE})


_DTYPES: dict[int, np.dtype[Any]] = {}


def _dtype(lay: T.LayoutInfo) -> np.dtype[Any]:
    """The structured dtype of a layout's arguments (made once a layout: layouts are constants)."""
    got = _DTYPES.get(id(lay))
    if got is None:
        got = _DTYPES[id(lay)] = _make_dtype(lay)
    return got


def _make_dtype(lay: T.LayoutInfo) -> np.dtype[Any]:
    fields: list[Any] = []
    for f in lay.args:
        if f.numpy is None:  # str, bytes: rows of bytes
            fields.append((f.name, np.uint8, (f.size,)))
        elif f.count > 1:
            fields.append((f.name, np.dtype(T.BO + f.numpy), (f.count,)))
        else:
            fields.append((f.name, T.BO + f.numpy))
    return np.dtype(fields)


@lru_cache(maxsize=16)
def _tables(version: str, profile: str) -> tuple[Any, Any, Any, Any, list[T.LayoutInfo]]:
    """Per (code) and (code, nb) look-up tables for one version and profile."""
    known = np.zeros(256, dtype=bool)
    avail = np.zeros(256, dtype=bool)
    size_ok = np.zeros((256, 256), dtype=bool)
    lay_of = np.full((256, 256), -1, dtype=np.int16)
    lays: list[T.LayoutInfo] = []
    for cmd in T.COMMANDS:
        known[cmd.code] = True
        avail[cmd.code] = bool(cmd.layouts_for(version))
        for lay in cmd.candidates(version):
            if lay.accepted_under(profile):
                size_ok[cmd.code, lay.size] = True
        for lay in reversed(cmd.candidates(version)):  # the first candidate of a size wins
            if lay not in lays:
                lays.append(lay)
            lay_of[cmd.code, lay.size] = lays.index(lay)
    return known, avail, size_ok, lay_of, lays


@lru_cache(maxsize=16)
def _size_bad(version: str, profile: str) -> NDArray[np.bool_]:
    """Per (code, argument size) as one index (``_key``): a known code with a size no layout of
    it accepts."""
    known, _, size_ok = _tables(version, profile)[:3]
    return (known[:, None] & ~size_ok).reshape(-1)  # type: ignore[no-any-return]


def _key(r: Records) -> Any:
    """(code, argument size) of every record as one index into the tables of ``_tables`` (a 1-d
    take, not a 2-d one), made once a validation and kept in 2 bytes a record."""
    got = r.state.get(_KEY)
    if got is None:
        code, nb = r.head["code"], r.head["arg_size"]
        # 1-byte fields: 2 bytes a record (the tables are 256 x 256; wider fields index as before)
        got = code.astype(np.uint16 if code.itemsize == nb.itemsize == 1 else np.intp)
        got <<= 8
        got |= nb
        r.state[_KEY] = got
    return got


_KEY = "(code, size)"  # r.state's key of _key's column (check ids are never this)
_NO_LAYOUT = "rows of no layout"  # r.state's key of the records no layout fits (made by _batches)
_ORDER = "rows by layout"  # r.state's key of every record by layout position (made by _batches; a group's rows
# are a slice of it)


@lru_cache(maxsize=16)
def _size_order(version: str, profile: str) -> tuple[Any, list[int], list[int]]:
    """The layouts of ``_tables`` ordered by argument size (then as listed): per (code, size) index
    (``_key``) the position + 1 of its layout in that order (0: no layout fits; one byte while
    there are fewer than 256 layouts: numpy's stable sort of bytes is one radix pass), the layout
    index at each position, and where each run of one size starts (a position, per position)."""
    lay_of, lays = _tables(version, profile)[3:]
    by_pos = sorted(range(len(lays)), key=lambda li: (lays[li].size, li))
    rank = np.zeros(len(lays) + 1, dtype=np.uint8 if len(lays) < 255 else np.int32)
    rank[[li + 1 for li in by_pos]] = np.arange(1, len(lays) + 1)
    pos_of = rank.take(lay_of.reshape(-1).astype(np.intp) + 1)
    first = [next(q for q in range(p + 1) if lays[by_pos[q]].size == lays[by_pos[p]].size) for p in range(len(by_pos))]
    return pos_of, by_pos, first


def _batches(r: Records) -> Iterator[Batch]:
    """The records of each layout the file uses, one layout at a time. The layouts of one argument
    size are gathered together (one gather for several commands: a file of many layouts pays numpy's
    per-call cost once a size, not once a layout); each layout's rows are a slice of them."""
    lays = _tables(r.version, r.profile)[4]
    pos_of, by_pos, first = _size_order(r.version, r.profile)
    pos = _positions(r)  # 0: no layout fits
    # the rows of every layout at once, by size then layout, each in file order: one stable sort
    order = np.argsort(pos, kind="stable")
    bounds = np.cumsum(np.bincount(pos, minlength=len(lays) + 1)).tolist()
    del pos
    r.state[_NO_LAYOUT] = order[:bounds[0]]  # position 0 first: the records no layout fits, in file order
    r.state[_ORDER] = order
    p, count = 0, len(by_pos)
    while p < count:
        q = p + 1
        while q < count and first[q] == p:
            q += 1
        lo, hi = bounds[p], bounds[q]  # the rows of positions p .. q-1: one size
        if hi > lo:
            rows = order[lo:hi]
            aoff = r.off[rows] + T.HEAD_SIZE
            lay0 = lays[by_pos[p]]
            data = _gather(r.a, aoff, lay0.size)
            group = (p, rows, data, lo)
            for k in range(p, q):
                if bounds[k + 1] > bounds[k]:
                    yield _batch(lays[by_pos[k]], group, bounds[k] - lo, bounds[k + 1] - lo, aoff)
        p = q


def _batch(lay: T.LayoutInfo, group: tuple[int, Any, Any, int], lo: int, hi: int, aoff: Any) -> Batch:
    """The batch of one layout: rows lo .. hi of its size group."""
    rows, data = group[1][lo:hi], group[2][lo:hi]
    raw = _Raw(lay, data)
    return Batch(lay, T.BY_CODE[lay.code], rows, aoff[lo:hi], _Columns(raw), raw, bytes_=data, group=group)


class _Raw(Mapping[str, Any]):
    """A layout's arguments as stored, each a view of the batch's argument bytes, made when a
    kernel first reads one (where the bounds test stands for the float kernels, often none is)."""

    __slots__ = ("_arr", "_data", "_lay")

    def __init__(self, lay: T.LayoutInfo, data: Any) -> None:
        self._lay, self._data = lay, data
        self._arr: Any = None

    def __getitem__(self, name: str) -> Any:
        if name not in _names(self._lay):
            raise KeyError(name)  # (as a dict: Mapping.get relies on it)
        if self._arr is None:
            self._arr = self._data.view(_dtype(self._lay))[:, 0]
        return self._arr[name]

    def __contains__(self, name: object) -> bool:
        return name in _names(self._lay)

    def __iter__(self) -> Iterator[str]:
        return iter(_names(self._lay))

    def __len__(self) -> int:
        return len(_names(self._lay))


_NAMES: dict[int, dict[str, None]] = {}


def _names(lay: T.LayoutInfo) -> dict[str, None]:
    """A layout's argument names, in order (made once a layout)."""
    got = _NAMES.get(id(lay))
    if got is None:
        got = _NAMES[id(lay)] = dict.fromkeys(f.name for f in lay.args)
    return got


class _Columns(Mapping[str, Any]):
    """A layout's argument columns, floats widened to float64 when a kernel first reads them
    (many kernels read the stored binary32 columns, ``Batch.raw``, and need no copy)."""

    __slots__ = ("_done", "_raw")

    def __init__(self, raw: Mapping[str, Any]) -> None:
        self._raw = raw
        self._done: dict[str, Any] = {}

    def __getitem__(self, name: str) -> Any:
        col = self._done.get(name)
        if col is None:
            col = self._raw[name]
            if col.dtype.kind == "f":
                # signalling NaNs stay NaN (its own errstate: a message may read a column late)
                with np.errstate(invalid="ignore"):
                    col = col.astype(np.float64)
            self._done[name] = col
        return col

    def __contains__(self, name: object) -> bool:
        return name in self._raw

    def __iter__(self) -> Iterator[str]:
        return iter(self._raw)

    def __len__(self) -> int:
        return len(self._raw)


# Row reductions over the few components of a vector (n x 3): numpy sets its loop up for every
# row, which made ``.all(axis=1)`` / ``.sum(axis=1)`` of 20,000 rows 5 to 10 times slower than the
# same work done a column at a time. The helpers below work a column at a time.
def _finite_rows(v: Any) -> Any:
    """Per row: every component finite."""
    if v.ndim == 1:
        return np.isfinite(v)
    fin = np.isfinite(v[:, 0])
    for j in range(1, v.shape[1]):
        fin &= np.isfinite(v[:, j])
    return fin


def _all_cols(m: Any) -> Any:
    """Per row of a boolean matrix: every column true."""
    out = m[:, 0].copy()
    for j in range(1, m.shape[1]):
        out &= m[:, j]
    return out


def _any_cols(m: Any) -> Any:
    """Per row of a boolean matrix: some column true."""
    out = m[:, 0].copy()
    for j in range(1, m.shape[1]):
        out |= m[:, j]
    return out


def _rowsum(x: Any) -> Any:
    """``x.sum(axis=1)`` of a float64 matrix of fewer than 8 columns, with the same bits: numpy adds
    such a row from +0.0, one element after the other (pairwise summation starts at 8), so the
    columns are added to zeros in their order."""
    if x.dtype != np.float64 or x.shape[1] >= 8:
        return x.sum(axis=1)
    out = np.zeros(x.shape[0], dtype=np.float64)
    for j in range(x.shape[1]):
        out += x[:, j]
    return out


# -- head kernels (every record) -------------------------------------------------------
def _sequence(r: Records, check: Check) -> None:
    seq, wrap = r.head["sequence"], T.SEQ_MASK
    first = _first_numbers(wrap, seq.dtype)
    if first is not None and len(r.off) <= len(first):
        differ = seq != first[:len(r.off)]  # the numbers before the first wrap, made once, in the field's type
    else:
        expected = np.arange(len(r.off), dtype=np.int64)
        expected &= wrap  # in place: the peak of a file of empty records is here
        differ = seq != expected
        del expected
    if not differ.any():
        return
    bad = np.flatnonzero(differ)
    at = r.off[bad] + T.RECORD_FIELDS[T.I_SEQ].offset
    r.add(check, bad, at, bad, lambda i: f"sequence number {seq[i]}, expected {i & wrap}")


@lru_cache(maxsize=4)
def _first_numbers(wrap: int, dtype: np.dtype[Any]) -> Any:
    """0 .. wrap in the sequence field's type (a record's expected number, up to the first wrap),
    when that is at most 65,536 numbers of an unsigned type that holds them (else None)."""
    if dtype.kind != "u" or wrap >= 1 << 16 or wrap >= 1 << (8 * dtype.itemsize):
        return None
    return np.arange(wrap + 1, dtype=dtype)


def _reserved(r: Records, check: Check) -> None:
    res = r.head["reserved"]
    if not res.any():
        return
    bad = np.flatnonzero(res)
    r.add(check, bad, r.off[bad] + T.RECORD_FIELDS[T.I_RES].offset, bad, lambda i: f"reserved byte is 0x{res[i]:02X}")


def _code_copy(r: Records, check: Check) -> None:
    copy, code = r.head["code_copy"], r.head["code"]
    differ = copy != code
    if not differ.any():
        return
    bad = np.flatnonzero(differ)
    r.add(check, bad, r.off[bad] + T.RECORD_FIELDS[T.I_COPY].offset, bad,
          lambda i: f"code copy 0x{copy[i]:02X} differs from code 0x{code[i]:02X}")


@lru_cache(maxsize=1)
def _head_coverage() -> tuple[str, int] | None:
    """The head's argument checksum (6.4.4) as (algorithm kind, how many times its coverage feeds
    the arguments), computed for every record of a layout at once; None when its coverage also
    feeds bytes outside the record (a header or file range: then one record at a time, as
    codec.field_checksum feeds them). A ``records`` segment feeds nothing here: the head's sum
    is taken over one record's arguments, with no record offsets (as codec.arg_checksum)."""
    spec = T.CHECKSUMS["fields"]["args"]
    segs = T.CHECKSUMS["coverages"][spec["coverage"]]
    if any(s["region"] in ("header", "file") for s in segs):
        return None
    return str(T.CHECKSUMS["algorithms"][spec["algorithm"]]), sum(1 for s in segs if s["region"] == "args")


def _arg_sums(cov: tuple[str, int], rows: NDArray[np.uint8]) -> NDArray[np.int64]:
    """The head's argument checksum of each row of argument bytes (all rows at once)."""
    kind, copies = cov
    fed = rows if copies == 1 else np.tile(rows, (1, copies))
    return row_checksums(kind, fed, T.ARG_CHECKSUM.size)


def _arg_checksum_batch(r: Records, check: Check, b: Batch) -> None:
    """The checksums of the records of every layout of a batch's argument size (when the first of
    them comes), from the argument bytes the batch gathered; the end kernel compares them with the
    stored ones, for every record at once."""
    cov = _head_coverage()
    if cov is None:
        return
    if b.group is None:
        r.state.setdefault(check["id"], None)  # (no size group: judged here, none left for the end)
        _report_sums(r, check, b.rows, _arg_sums(cov, b.bytes_))
        return
    key = f"{check['id']} size group {b.group[0]}"  # r.state keys are strings
    if key in r.state:
        return
    r.state[key] = True
    # the batches judge the records that have a layout: their checksums in the order _batches put
    # the records in (a group's rows are a slice of it: no scatter), in the stored field's type
    want = r.state.get(check["id"])
    if want is None:
        want = r.state[check["id"]] = np.zeros(len(r.off), dtype=r.head["checksum"].dtype)
    lo, data = b.group[3], b.group[2]
    sums = exact_sums32(data) if cov == ("sum", 1) and 255 * data.shape[1] < 1 << (8 * T.ARG_CHECKSUM.size) else None
    want[lo:lo + len(b.group[1])] = _arg_sums(cov, data) if sums is None else sums


def _report_sums(r: Records, check: Check, rows: Any, want: Any) -> None:
    """The records ``rows`` whose stored argument checksum is not ``want`` (computed, per row)."""
    got = r.head["checksum"][rows]
    differ = got != want
    if not differ.any():  # (a quick no: flatnonzero costs several times as much)
        return
    bad = np.flatnonzero(differ)
    bad = bad[np.argsort(rows[bad], kind="stable")]  # a size group's rows are by layout: in file order
    at, stored, computed = rows[bad], got[bad], want[bad]
    r.add(check, at, r.off[at] + T.ARG_CHECKSUM.offset, np.arange(bad.size),
          lambda k: f"stored argument checksum {stored[k]}, computed {computed[k]}")


def _arg_checksum(r: Records, check: Check) -> None:
    nb, chk, off, a, hs = r.head["arg_size"], r.head["checksum"], r.off, r.a, T.HEAD_SIZE
    cov = _head_coverage()
    if cov is not None:
        # The batches judged the records of each layout; the others (no layout fits: _batches
        # keeps them) are summed here, one argument size at a time, their arguments gathered as
        # rows (memory: the arguments of one size; a cumulative sum would hold 8 bytes a file byte).
        judged = check["id"] in r.state
        want = r.state.pop(check["id"], None)
        left = r.state.get(_NO_LAYOUT) if judged else None
        if want is not None:  # the records of each layout at once, in the order _batches put them in
            order = r.state[_ORDER]
            done = slice(len(r.state[_NO_LAYOUT]), len(order))
            differ = chk.take(order[done]) != want[done]
            if differ.any():
                at = np.flatnonzero(differ)
                rows = order[done][at]
                _report_sums(r, check, rows, want[done][at])
        if left is None:  # no batch judged any: every record here
            left = np.arange(len(off))
        if left.size:
            nbl = nb[left]
            for size in np.flatnonzero(np.bincount(nbl, minlength=1)).tolist():
                rows = left[nbl == size]
                _report_sums(r, check, rows, _arg_sums(cov, _gather(a, off[rows] + hs, size)))
        return
    # a coverage reaching outside the record (no spec has one): a record at a time
    buf = r.buf
    want = np.array([field_checksum("args", buf, [], args=buf[o + hs:o + hs + int(s)])
                     for o, s in zip(off.tolist(), nb.tolist(), strict=True)], dtype=np.int64)
    bad = np.nonzero(chk != want)[0]
    r.add(check, bad, off[bad] + T.ARG_CHECKSUM.offset, bad,
          lambda i: f"stored argument checksum {chk[i]}, computed {want[i]}")


def _judges_head(check: Check) -> bool:
    """An arg_checksum check of the record head's argument checksum (6.4.4), not of a checksum
    field among a command's arguments (issue 25, point 1)."""
    return check["field"] in (None, T.ARG_CHECKSUM.checksum)


def _record_checksum_batch(r: Records, check: Check, b: Batch) -> None:
    if _judges_head(check):
        _arg_checksum_batch(r, check, b)
        return
    hs = T.HEAD_SIZE
    for ck in b.lay.checksums:
        if ck.tag != check["field"]:
            continue
        got = b.raw[ck.arg.name].astype(np.int64)
        # the byte ranges its named fields resolve to are the same in every record of the layout:
        # those columns of the records' bytes (the arguments the batch gathered, or whole records
        # when a range lies in the head), in order, are what the checksum is fed
        whole = any(lo < hs for lo, _ in ck.ranges)
        rec, base = (_gather(r.a, b.aoff - hs, hs + b.lay.size), 0) if whole else (b.bytes_, hs)
        cols = np.concatenate([np.arange(lo - base, hi - base, dtype=np.intp) for lo, hi in ck.ranges]
                              or [np.zeros(0, dtype=np.intp)])
        want = row_checksums(str(T.CHECKSUMS["algorithms"][ck.algorithm]), rec[:, cols], ck.arg.size)
        bad = np.nonzero(got != want)[0]  # a batch's rows are in file order
        r.add(check, b.rows[bad], b.aoff[bad] + ck.arg.offset, bad, _stored_vs(ck.tag, got, want))


def _stored_vs(tag: str, got: Any, want: Any) -> Message:
    return lambda k: f"stored {tag} checksum {got[k]}, computed {want[k]}"


def _record_checksum_end(r: Records, check: Check) -> None:
    if _judges_head(check):
        _arg_checksum(r, check)


def _carries(check: Check, lay: T.LayoutInfo, cmd: T.CommandInfo) -> bool:
    return _judges_head(check) or any(ck.tag == check["field"] for ck in lay.checksums)


@lru_cache(maxsize=16)
def _code_faults(version: str, profile: str) -> NDArray[np.bool_]:
    """Per (code, argument size) index (``_key``): an unknown code, a command not available in the
    version, or a size no layout of it accepts (what unknown_code, availability, arg_size flag)."""
    known, avail = _tables(version, profile)[:2]
    return (~(known & avail)[:, None] | _size_bad(version, profile).reshape(256, 256)).reshape(-1)  # type: ignore[no-any-return]


_FINE = "codes and sizes fine"  # r.state's key of _codes_fine's answer
_POS = "layout positions"  # r.state's key of _positions' column


@lru_cache(maxsize=16)
def _position_faults(version: str, profile: str) -> Any:
    """Per (code, argument size) index: the position + 1 of its layout in _size_order (0: none),
    with the top bit of the byte set where _code_faults has a fault (None: 128 layouts or more)."""
    pos_of = _size_order(version, profile)[0]
    if pos_of.dtype != np.uint8 or pos_of.max(initial=0) >= 0x80:
        return None
    return pos_of | (_code_faults(version, profile).astype(np.uint8) << 7)


def _positions(r: Records) -> Any:
    """Every record's layout position (_size_order, 0: no layout fits); one look-up a record also
    answers _codes_fine (the look-up kept only until both have read it)."""
    got = r.state.pop(_POS, None)
    if got is None:
        both = _position_faults(r.version, r.profile)
        if both is None:
            return _size_order(r.version, r.profile)[0].take(_key(r))
        got = both.take(_key(r))
    got &= 0x7F
    return got


def _codes_fine(r: Records) -> bool:
    """No record has a code, or a (code, argument size), that unknown_code, availability or arg_size
    flags: one look-up a record for the three (asked once a validation), made with the layout
    positions (_positions) where it can be."""
    got = r.state.get(_FINE)
    if got is None:
        both = _position_faults(r.version, r.profile)
        if both is None:
            got = not _code_faults(r.version, r.profile).take(_key(r)).any()
        else:
            looked = r.state[_POS] = both.take(_key(r))
            got = not np.count_nonzero(looked >= 0x80)
        r.state[_FINE] = got
    return bool(got)


def _unknown_code(r: Records, check: Check) -> None:
    if _codes_fine(r):
        return
    code = r.head["code"]
    known = _tables(r.version, r.profile)[0]
    bad = np.flatnonzero(~known.take(code))  # take: several times a fancy index by a byte column
    r.add(check, bad, r.off[bad] + T.RECORD_FIELDS[T.I_CODE].offset, bad,
          lambda i: f"unknown command code 0x{code[i]:02X}")


def _availability(r: Records, check: Check) -> None:
    if _codes_fine(r):
        return
    code, version = r.head["code"], r.version
    known, avail = _tables(version, r.profile)[:2]
    bad = np.flatnonzero((known & ~avail).take(code))
    if bad.size == 0:
        return
    covering = availability_checks()  # (version, command) -> the one check that covers it
    for c in np.unique(code[bad]):
        name = T.BY_CODE[int(c)].name
        if (covering.get((version, name)) or {}).get("id") != check["id"]:
            continue
        rows = bad[code[bad] == c]
        r.add(check, rows, r.off[rows] + T.RECORD_FIELDS[T.I_CODE].offset, rows,
              _const(f"{name} is not available in version {version}"))


def _arg_size(r: Records, check: Check) -> None:
    if _codes_fine(r):
        return
    code, nb, version, profile = r.head["code"], r.head["arg_size"], r.version, r.profile
    bad = np.flatnonzero(_size_bad(version, profile).take(_key(r)))

    def sizes_msg(i: Any) -> str:
        cmd = T.BY_CODE[int(code[i])]
        sizes = sorted({lay.size for lay in cmd.candidates(version) if lay.accepted_under(profile)})
        return f"{cmd.name} with {nb[i]} argument bytes; expected {' or '.join(map(str, sizes))}"

    r.add(check, bad, r.off[bad] + T.RECORD_FIELDS[T.I_SIZE].offset, bad, sizes_msg)


# -- argument kernels (one layout at a time) -------------------------------------------
_FLOAT_WORDS: dict[int, Any] = {}
_EXPONENT32 = 0x7F800000  # a binary32 is not finite when these bits are all set


def _float_words(lay: T.LayoutInfo) -> Any:
    """The 4-byte words of a layout's arguments that hold its binary32 floats (a slice when they
    are all of them), or None when its floats are not all binary32 at word offsets (made once a
    layout)."""
    key = id(lay)
    if key not in _FLOAT_WORDS:
        floats = [f for f in lay.args if f.kind == "float"]
        ok = lay.size % 4 == 0 and all(f.numpy == "f4" and f.offset % 4 == 0 for f in floats)
        words = [f.offset // 4 + k for f in floats for k in range(f.size // 4)] if ok else None
        _FLOAT_WORDS[key] = (slice(None) if words == list(range(lay.size // 4)) else np.asarray(words, dtype=np.intp)
                             ) if words is not None else None
    return _FLOAT_WORDS[key]


def _all_finite32(b: Batch) -> bool:
    """True when every binary32 float of the batch is finite: one test of the exponent bits over
    the floats' words as one flat run (no loop set-up a row); False when not known so."""
    words = _float_words(b.lay)
    if words is None or b.bytes_ is None:
        return False
    sel = b.bytes_.view(T.BO + "u4")[:, words].reshape(-1)
    exp = np.uint32(_EXPONENT32)
    return not (np.bitwise_and(sel, exp) == exp).any()


def _finite(r: Records, check: Check, b: Batch) -> None:
    floats = [f for f in b.lay.args if f.kind == "float"]
    if not floats or _all_finite32(b):
        return
    # A NaN or an infinity makes the sum not finite, so rows whose sum is finite hold only
    # finite floats; the others (an overflow too) are looked at field by field.
    total = np.zeros(b.rows.size, dtype=np.float32)
    for f in floats:
        col = b.raw[f.name]
        if col.ndim == 1:
            total += col
        else:
            for j in range(col.shape[1]):
                total += col[:, j]
    suspect = np.flatnonzero(~np.isfinite(total))
    if suspect.size == 0:
        return
    for f in floats:
        bad = suspect[~_finite_rows(b.raw[f.name][suspect])]
        r.add(check, b.rows[bad], b.aoff[bad] + f.offset, bad, _const(f"{b.cmd.name}.{f.name} is not finite"))


def _string_tail(r: Records, check: Check, b: Batch) -> None:
    for f in b.lay.args:
        if f.kind == "string" and not _plain_strings(b, f):
            string_tail(r.add, check, b.cols[f.name], b.rows, b.aoff + f.offset, f"{b.cmd.name}.{f.name}",
                        _first_nul(b, f.name))


def _string_ascii(r: Records, check: Check, b: Batch) -> None:
    for f in b.lay.args:
        if f.kind == "string" and not _plain_strings(b, f):
            string_ascii(r.add, check, b.cols[f.name], b.rows, b.aoff + f.offset, f"{b.cmd.name}.{f.name}",
                         _first_nul(b, f.name))


def _plain_strings(b: Batch, f: T.FieldInfo) -> bool:
    """Every row of string argument ``f`` is printable ASCII then NULs only: neither string
    kernel flags a row (a quick yes for the whole column, made once for both; on False they
    look row by row). The tests run on the column's bytes as one flat run: numpy's operations
    on rows of a few bytes pay a loop set-up a row. Neither way makes a Python call a row, and the
    few-rows way makes more calls than the other (the call-count guard compares a file with 8x
    the records: tests/test_engine_scaling.py)."""
    name = f.name
    got = b.plain.get(name)
    if got is None and b.raw[name].shape[0] <= _PLAIN_PYTHON_ROWS:
        got = _plain_rows(b.raw[name])
        b.plain[name] = got
    if got is None:
        # the field's bytes from the batch's argument bytes (no copy when it is the whole row)
        col = b.raw[name] if b.bytes_ is None else b.bytes_[:, f.offset:f.offset + f.size]
        width = col.shape[1]
        flat = np.ascontiguousarray(col).reshape(-1)
        used = flat != 0
        rise = used[1:] > used[:-1]  # a byte after a NUL (where a row starts: the row before's end)
        rise[width - 1::width] = False
        got = not _any(rise) and not _any(used & ((flat - np.uint8(0x20)) > np.uint8(0x7E - 0x20)))
        b.plain[name] = got
    return got


_any = np.logical_or.reduce  # ndarray.any() runs numpy's Python wrapper: a call the call-count guard counts
_PLAIN_PYTHON_ROWS = 8  # up to this many rows, plain Python on the bytes (~0.5 us a row) beats ~8 numpy calls (~5 us)
_PRINTABLE = bytes(range(0x20, 0x7F))


def _plain_rows(col: NDArray[np.uint8]) -> bool:
    """_plain_strings on a few rows: each row, its trailing NULs dropped, holds printable ASCII only."""
    width = col.shape[1]
    raw = col.tobytes()
    return not any([raw[i:i + width].rstrip(b"\0").translate(None, _PRINTABLE) for i in range(0, len(raw), width)])


def _plain_bytes(raw: bytes) -> bool:
    """One string field's bytes are printable ASCII then NULs only (plain Python: a header field
    is one short row, where numpy's per-call cost is all there is)."""
    text = raw.rstrip(b"\0")
    return b"\0" not in text and all(0x20 <= c <= 0x7E for c in text)


def _first_nul(b: Batch, name: str) -> Any:
    """Per row, where the first NUL of string argument ``name`` is (its size when none); made once
    for both string kernels."""
    if name not in b.nul:
        b.nul[name] = first_nul(b.cols[name])
    return b.nul[name]


def first_nul(col: NDArray[np.uint8]) -> Any:
    is_nul = col == 0
    return np.where(is_nul.any(axis=1), is_nul.argmax(axis=1), col.shape[1])


Add = Callable[[Check | None, Any, Any, Any, Message], None]


def string_tail(add: Add, check: Check | None, col: NDArray[np.uint8], rows: Any, offs: Any, name: str,
                first: Any) -> None:
    """string_tail: bytes other than NUL after the first NUL of a string field (rows x size)."""
    after = np.arange(col.shape[1])[None, :] > first[:, None]
    bad = np.nonzero((after & (col != 0)).any(axis=1))[0]
    add(check, rows[bad], offs[bad], bad,
        lambda k: f"{name}: bytes after the first NUL: {bytes(col[k, first[k] + 1:]).rstrip(bytes(1)).hex()}")


def string_ascii(add: Add, check: Check | None, col: NDArray[np.uint8], rows: Any, offs: Any, name: str,
                 first: Any) -> None:
    """string_ascii: a byte outside printable ASCII before the first NUL of a string field."""
    before = np.arange(col.shape[1])[None, :] < first[:, None]
    nonascii = before & ((col < 0x20) | (col > 0x7E))
    bad = np.nonzero(nonascii.any(axis=1))[0]
    add(check, rows[bad], offs[bad], bad, lambda k: f"{name}: non-ASCII byte 0x{int(col[k][nonascii[k]][0]):02X}")


def _targets(check: Check, b: Batch) -> Iterator[tuple[str, ...]]:
    """The argument-name tuples ``check`` names for this batch's command."""
    for t in check["targets"]:
        if t["command"] == b.cmd.name:
            yield tuple(t["args"])


def _positive(r: Records, check: Check, b: Batch) -> None:
    for names in _targets(check, b):
        for nm in (n for n in names if n in b.cols):
            v = b.cols[nm]
            bad = np.nonzero(np.isfinite(v) & (v <= 0))[0]
            r.add(check, b.rows[bad], b.at(nm)[bad], bad, _valued(f"{b.cmd.name}.{nm} is ", v, ", must be > 0"))


def _nonzero_vector(r: Records, check: Check, b: Batch) -> None:
    for names in _targets(check, b):
        for nm in (n for n in names if n in b.cols):
            v = b.cols[nm]
            bad = np.nonzero(_finite_rows(v) & _all_cols(v == 0.0))[0]
            r.add(check, b.rows[bad], b.at(nm)[bad], bad, _const(f"{b.cmd.name}.{nm} has zero length"))


def _range(r: Records, check: Check, b: Batch) -> None:
    lo = -np.inf if check["min"] is None else check["min"]
    hi = np.inf if check["max"] is None else check["max"]
    for names in _targets(check, b):
        for nm in (n for n in names if n in b.cols):
            v = b.cols[nm]
            out = ((v <= lo) if check["min_exclusive"] else (v < lo)) | ((v >= hi) if check["max_exclusive"]
                                                                       else (v > hi))
            bad = np.nonzero(np.isfinite(v) & out)[0]
            r.add(check, b.rows[bad], b.at(nm)[bad], bad,
                  _valued(f"{b.cmd.name}.{nm} is ", v, f", {range_text(check)}"))


def _ordered(r: Records, check: Check, b: Batch) -> None:
    cname, cols = b.cmd.name, b.cols
    for names in _targets(check, b):
        if not all(nm in cols for nm in names):
            continue
        stored = [b.raw[nm] for nm in names]  # as stored: binary32 orders as its float64 widening
        pairs = zip(stored, stored[1:], strict=False)
        if all(c.ndim == 1 for c in stored) and not any((x > y).any() for x, y in pairs):
            continue  # no pair out of order anywhere (a quick no; NaN compares false, as in the test below)
        vals = np.stack([cols[nm] for nm in names], axis=1)
        fin = _finite_rows(vals)
        bad = np.nonzero(fin & _any_cols(vals[:, :-1] > vals[:, 1:]))[0]
        r.add(check, b.rows[bad], b.aoff[bad], bad, _ordered_msg(cname, cols, names))


def _ordered_msg(cname: str, cols: Mapping[str, Any], names: tuple[str, ...]) -> Message:
    return lambda k: f"{cname}: {' <= '.join(f'{nm}={float(cols[nm][k]):g}' for nm in names)} does not hold"


def _nondecreasing(r: Records, check: Check, b: Batch) -> None:
    held = r.state.setdefault(check["id"], {})  # command.argument -> [(rows, values, offsets)]
    for names in _targets(check, b):
        for nm in (n for n in names if n in b.cols):
            v = b.raw[nm]  # as stored (widened where parts are joined: binary32 to float64 is exact)
            fin = np.isfinite(v)
            if fin.all():
                held.setdefault(f"{b.cmd.name}.{nm}", []).append((b.rows, v, b.at(nm)))
                continue
            keep = np.flatnonzero(fin)
            held.setdefault(f"{b.cmd.name}.{nm}", []).append((b.rows[keep], v[keep], b.at(nm)[keep]))


def _nondecreasing_end(r: Records, check: Check) -> None:
    """Each finite value against the last finite value of the same command argument."""
    for key, parts in r.state.pop(check["id"], {}).items():
        rows, (values, offs) = _in_file_order(parts)
        falls = values[1:] < values[:-1]
        if not falls.any():
            continue
        bad = np.flatnonzero(falls) + 1
        prev = values[bad - 1]
        r.add(check, rows[bad], offs[bad], np.arange(bad.size),
              _falls(key, prev, values[bad]))


def _falls(key: str, before: Any, after: Any) -> Message:
    return lambda k: f"{key} falls from {float(before[k]):g} to {float(after[k]):g}"


def _cutter_table(r: Records, check: Check, b: Batch) -> None:
    role, cutters = b.cmd.cutter, r.cutters
    if not role or cutters is None:
        return
    tol = T.TOL["cutter_mm"]
    names = b.cols[role[CUTTER_NAME]]
    for k, row in enumerate(b.rows.tolist()):
        at = int(b.aoff[k])
        name = string_value(bytes(names[k]))
        if name not in cutters:
            r.found(check, row, at, f"cutter {name!r} is not in the cutter table")
            continue
        for key, ref in zip(CUTTER_VALUES, cutters[name], strict=True):  # the table's columns
            col = b.cols.get(role.get(key, ""))
            if col is None or col.ndim != 1 or col.dtype.kind != "f":
                continue
            v = float(col[k])
            if math.isfinite(v) and abs(v - ref) > tol:
                r.found(check, row, at, f"cutter {name!r} {key} {v:g} mm, the table says {ref:g} mm")


# -- sequential kernels (the records in file order) ------------------------------------
def _machine_limits(r: Records, check: Check, b: Batch) -> None:
    """A finite target argument outside its machine limit: one finding per argument, naming
    the first component out (values <= 0 of an argument a positive check targets are that
    check's). With a machine file given the check reports at its input severity."""
    rules = machine_rules(check, b.cmd.name, b.lay.variant)
    if not rules:
        return
    m = r.machine
    if m.given and check.get("input_severity"):
        check = dict(check, severity=check["input_severity"])
    for f, limit, positive in rules:
        if f.name not in b.raw:
            continue
        lim = m.limits[limit]
        stored = b.raw[f.name]  # binary32 as stored: compared exactly with the binary32 bounds
        if f.per:
            _machine_limits_group(r, check, b, f, lim, positive)
            continue
        lo, hi = _bounds32(lim) if stored.dtype == np.float32 else _bounds(lim)
        out = _outside(stored, lo, hi)  # NaN compares false: the finite check's
        if not out.any():
            continue
        v = np.asarray(b.cols[f.name], dtype=np.float64).reshape(len(b.rows), -1)
        keep = out & _finite_rows(v)
        if positive:
            keep &= ~_any_cols(v <= 0.0)
        bad = np.nonzero(keep)[0]
        r.add(check, b.rows[bad], b.at(f.name)[bad], bad, _breach(f"{b.cmd.name}.{f.name}", v, lim, positive))


def _machine_limits_group(r: Records, check: Check, b: Batch, f: T.FieldInfo, lim: Limit, positive: bool) -> None:
    """machine_limits on a repeated group (issue 25, point 3): each item is a position; one finding
    per record, at its first item out, named argument[item]."""
    f = next(a for a in b.lay.args if a.name == f.name)  # as this batch's layout holds it (its n items)
    lo, hi = _bounds(lim)
    stored = b.raw[f.name].reshape(len(b.rows), f.items, -1)
    v = np.asarray(stored, dtype=np.float64)
    out = ((stored < lo) | (stored > hi)).any(axis=2) & np.isfinite(v).all(axis=2)
    if positive:
        out &= ~(v <= 0.0).any(axis=2)
    bad = np.flatnonzero(out.any(axis=1))
    if bad.size == 0:
        return
    first = out[bad].argmax(axis=1)
    item_size = f.size // f.items

    def msg(k: int) -> str:
        i = int(first[np.searchsorted(bad, k)])
        return f"{b.cmd.name}.{f.name}[{i}]" + (breach(tuple(v[k, i].tolist()), lim, positive) or "")

    r.add(check, b.rows[bad], b.at(f.name)[bad] + first * item_size, bad, msg)


@lru_cache(maxsize=64)
def _bounds(lim: Limit) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """A limit's bounds as arrays (one per axis), rounded to binary32 as machine.Limit keeps them."""
    return np.asarray(lim.lo32, dtype=np.float64), np.asarray(lim.hi32, dtype=np.float64)


@lru_cache(maxsize=64)
def _bounds32(lim: Limit) -> tuple[NDArray[np.float32], NDArray[np.float32]]:
    """The bounds as binary32 (they are binary32 values: comparing binary32 columns with them is
    exact, and spares widening every value to float64)."""
    return np.asarray(lim.lo32, dtype=np.float32), np.asarray(lim.hi32, dtype=np.float32)


_OUTSIDE_WHOLE_ROWS = 512  # below this many rows the whole-array test is the cheaper (fewer numpy calls)


def _outside(v: Any, lo: Any, hi: Any) -> Any:
    """Per row: some component below lo or above hi. Many rows: a column a component (numpy's row
    reductions pay a loop set-up a row); few rows (a small file's batches): two whole-array comparisons
    and one reduction, ~2 us where the columns' ~10 numpy calls cost ~10 us."""
    if v.ndim == 1 or v.shape[0] < _OUTSIDE_WHOLE_ROWS:
        out: Any = v < lo
        out |= v > hi
        return out if v.ndim == 1 else np.logical_or.reduce(out, axis=1)
    lo, hi = np.broadcast_to(lo, v.shape[1:]), np.broadcast_to(hi, v.shape[1:])
    out = v[:, 0] < lo[0]
    out |= v[:, 0] > hi[0]
    for j in range(1, v.shape[1]):
        out |= v[:, j] < lo[j]
        out |= v[:, j] > hi[j]
    return out


def _breach(before: str, v: Any, lim: Limit, positive: bool) -> Message:
    def msg(k: int) -> str:
        return before + (breach(tuple(v[k].tolist()), lim, positive) or "")
    return msg


def _ends(m: dict[str, str], cols: Mapping[str, Any], k: int) -> Any:
    """Where each motion leaves the tool (NaN when not finite); as geometry.motion_end."""
    kind = m["kind"]
    if kind in ("point", "line"):
        end = cols[m["end"]][:, -3:].copy()  # a repeated group's last point (issue 25, point 3)
        fin = _finite_rows(end)
        if not fin.all():
            end[~fin] = np.nan
        return end
    start, center, normal = cols[m["start"]], cols[m["center"]], cols[m["normal"]]
    deg = cols[m["degrees"]]
    length = cols[m["length"]] if kind == "helix" else np.zeros(k)
    ok = (_finite_rows(start) & _finite_rows(center) & _finite_rows(normal)
          & np.isfinite(deg) & np.isfinite(length))
    nn = np.sqrt(_rowsum(normal * normal))
    ok &= nn != 0.0
    kk = normal / nn[:, None]
    v = start - center
    th = deg * (math.pi / 180.0)
    c, s = np.cos(th), np.sin(th)
    kxv = _cross(kk, v)
    kdv = _rowsum(kk * v)
    rot = v * c[:, None] + kxv * s[:, None] + kk * (kdv * (1.0 - c))[:, None]
    end = center + rot + length[:, None] * kk
    end[~ok] = np.nan
    return end


def _continuity(r: Records, check: Check, b: Batch) -> None:
    m = b.cmd.motion
    if m is None:
        return
    n = b.rows.size
    # points and lines: their vectors as stored (binary32; widening to float64 is exact, and
    # the distance is measured in float64), half the memory of float64 copies
    plain = m["kind"] in ("point", "line")
    cols = b.raw if plain else b.cols
    start = np.full((n, 3), np.nan, dtype=np.float32 if plain else np.float64) if m["kind"] == "point" \
        else cols[m["start"]]
    at = b.aoff + next((f.offset for f in b.lay.args if f.name == m.get("start")), 0)
    # rows and offsets narrowed as Records.add keeps them (held until the end: 4 bytes each, not 8)
    narrow = _narrow(r)
    # a point's or line's end as stored (no copy): a part flagged plain has its ends that are not
    # finite taken as NaN (as _ends makes them) by the end kernel, on the few rows it measures
    end = cols[m["end"]][:, -3:] if plain else _ends(m, cols, n)
    r.state.setdefault(check["id"], []).append((b.rows.astype(narrow), start, end, at.astype(narrow),
                                                b.cmd.name, plain))


def _merge_order(parts: list[Any]) -> tuple[list[Any], Any]:
    """The parts (one per layout; part[0] their rows, ascending) in the order to concatenate them,
    and the permutation that puts the concatenation in file order (None: it is in file order).
    When the parts do not interleave (a file of one motion command after a few set-up records),
    their concatenation by first row is the file order: no permutation, no gather. Otherwise a
    stable sort of the concatenated rows: numpy's stable sort of 4- and 8-byte integers is a
    timsort, which merges the parts' ascending runs (a few microseconds for thousands of rows,
    where a scatter into a table of every record cost a pass over the file's records); a row in
    two parts (two targets naming one argument) keeps the parts' order."""
    ordered = sorted((p for p in parts if len(p[0])), key=lambda p: int(p[0][0]))
    if ordered and all(int(x[0][-1]) < int(y[0][0]) for x, y in zip(ordered, ordered[1:], strict=False)):
        return ordered, None
    rows = np.concatenate([p[0] for p in parts])
    if rows.size == 0:
        return parts, None
    return parts, np.argsort(rows, kind="stable")


def _field(parts: list[Any], j: int, pick: Any) -> Any:
    """Field j of the parts concatenated, at ``pick`` (None: all, as concatenated)."""
    got = parts[0][j] if len(parts) == 1 else np.concatenate([p[j] for p in parts])
    return got if pick is None else got.take(pick, axis=0)  # take: several times a 2-d fancy index


def _part_of(parts: list[Any], at: Any) -> list[int]:
    """Which part each position ``at`` of the concatenation is in."""
    ends = np.cumsum([len(p[0]) for p in parts])
    return np.searchsorted(ends, at, side="right").tolist()  # type: ignore[no-any-return]


def _in_file_order(parts: list[Any]) -> tuple[Any, list[Any]]:
    """The rows of every part (one per layout) in file order, and each field of the parts
    concatenated in that order (field j of a part is part[j + 1])."""
    if len(parts) == 1:
        return parts[0][0], list(parts[0][1:])
    cat, order = _merge_order(parts)
    return _field(cat, 0, order), [_field(cat, j, order) for j in range(1, len(parts[0]))]


def _cross(a: Any, b: Any) -> Any:
    """Row-wise cross products of n x 3 float64 arrays: the operations of ``np.cross`` in its
    order (the same bits), without its axis handling (some twenty Python-level calls)."""
    cp = np.empty(a.shape, dtype=np.float64)
    tmp = np.empty(a.shape[0], dtype=np.float64)
    for i, j, k in ((0, 1, 2), (1, 2, 0), (2, 0, 1)):  # cp_i = a_j b_k - a_k b_j
        np.multiply(a[:, j], b[:, k], out=cp[:, i])
        np.multiply(a[:, k], b[:, j], out=tmp)
        cp[:, i] -= tmp
    return cp


def _same_rows(x: Any, y: Any) -> Any:
    """Per row: the vectors are equal, component by component (False where either is NaN)."""
    eq = x[:, 0] == y[:, 0]
    for j in range(1, x.shape[1]):
        eq &= x[:, j] == y[:, j]
    return eq


def _continuity_end(r: Records, check: Check) -> None:
    # (rows, start, end, start offsets, command name, plain) a layout
    parts = r.state.pop(check["id"], [])
    if not parts:
        return
    cat, order = _merge_order(parts)
    start, end = _field(cat, 1, order), _field(cat, 2, order)
    # A motion that starts exactly where the last one ended is 0 mm away: only the others are
    # measured (a valid file's motions all start so). (A plain end that is not finite is not where
    # a motion starts either: NaN below, as geometry.motion_end.)
    same = _same_rows(start[1:], end[:-1])
    same |= np.isnan(start[1:, 0])  # a start that is not finite (a point has none) is not measured below
    if same.all():
        return
    todo = np.flatnonzero(~same) + 1
    first, prev = start.take(todo, axis=0), end.take(todo - 1, axis=0)
    dvec = first.astype(np.float64)
    dvec -= prev
    d = np.sqrt(_rowsum(dvec * dvec))
    plain = [p[5] for p in cat]
    if any(plain):
        unknown = ~_finite_rows(prev)  # where the last motion ended is not known
        if not all(plain):
            unknown &= np.asarray(plain)[_part_of(cat, todo - 1 if order is None else order[todo - 1])]
        d[unknown] = np.nan
    keep = _finite_rows(first) & (d > T.TOL["position_mm"])
    bad = todo[keep]
    if bad.size == 0:
        return
    dist, src = d[keep], bad if order is None else order[bad]  # src: positions in the concatenation
    names = [cat[j][4] for j in _part_of(cat, src)]
    r.add(check, _field(cat, 0, src), _field(cat, 3, src), np.arange(bad.size),
          lambda k: f"{names[k]} starts {float(dist[k]):.6g} mm from the current position")


def _orientation(r: Records, check: Check, b: Batch) -> None:
    o = b.cmd.orientation
    if o is None:
        return
    # the vectors as stored (binary32), widened exactly where an angle is measured
    s = np.full((b.rows.size, 3), np.nan, dtype=np.float32) if o["kind"] == "set" else b.raw[o["start"]]
    r.state.setdefault(check["id"], []).append((b.rows, s, b.raw[o["end"]], b.aoff, b.cmd.name))


def _orientation_end(r: Records, check: Check) -> None:
    parts = r.state.pop(check["id"], [])  # (rows, start, end, argument offsets, command name) a layout
    if not parts:
        return
    cat, order = _merge_order(parts)
    start, end = _field(cat, 1, order), _field(cat, 2, order)
    tol = T.TOL["orientation_deg"]
    # A path that starts exactly on the orientation in force turns 0 degrees: only the others
    # are measured (a valid file's paths all start so).
    if tol >= 0:
        same = _same_rows(start[1:], end[:-1])
        same |= np.isnan(start[1:, 0])  # a start that is not finite (a set has none) is not measured below
        if same.all():
            return
        todo = np.flatnonzero(~same) + 1
    else:
        todo = np.arange(1, len(start))
    if todo.size == 0:
        return
    s, prev = start.take(todo, axis=0).astype(np.float64), end.take(todo - 1, axis=0).astype(np.float64)
    prev_ok = _finite_rows(prev) & (np.sqrt(_rowsum(prev * prev)) > 0.0)
    s_ok = _finite_rows(s) & (np.sqrt(_rowsum(s * s)) > 0.0)
    cx = _cross(s, prev)
    ang = np.degrees(np.arctan2(np.sqrt(_rowsum(cx * cx)), _rowsum(s * prev)))
    keep = s_ok & prev_ok & (ang > tol)
    bad = todo[keep]
    if bad.size == 0:
        return
    angle, src = ang[keep], bad if order is None else order[bad]  # src: positions in the concatenation
    names = [cat[j][4] for j in _part_of(cat, src)]
    r.add(check, _field(cat, 0, src), _field(cat, 3, src), np.arange(bad.size),
          lambda k: f"{names[k]} starts {float(angle[k]):.6g} deg from the current orientation")


def _shape(r: Records, check: Check, b: Batch) -> None:
    held = r.state.setdefault(check["id"], {"parts": [], "motion": []})
    if b.cmd.motion is not None:
        held["motion"].append(b.rows)
    sh = b.cmd.shape
    if sh is not None:
        kind = 0 if sh["kind"] == "start" else 1
        held["parts"].append((b.rows, kind, b.cols[sh["name"]], b.cols[sh["count"]].astype(np.int64), b.cmd.name))


def _shape_end(r: Records, check: Check) -> None:
    held = r.state.pop(check["id"], None)
    if held is None or not held["parts"]:
        return
    parts = held["parts"]
    if _shapes_balanced(parts, held["motion"]):
        return
    motion = np.zeros(len(r.off) + 1, dtype=np.int32)  # 4 bytes a record: counts stay below 2**31 records
    for rows in held["motion"]:
        motion[rows + 1] = 1
    cm = np.cumsum(motion, out=motion)  # motions before each record
    shape_rows = sorted((row, kind, bytes(names[k]), int(counts[k]), cname)
                        for rows, kind, names, counts, cname in parts for k, row in enumerate(rows.tolist()))
    off = r.off
    open_: tuple[int, bytes, int] | None = None
    for row, kind, name, cnt, cname in shape_rows:
        at = int(off[row])
        if kind == 0:
            if open_ is not None:
                r.found(check, row, at, f"{cname} inside the open shape of record {open_[0]}")
            open_ = (row, name, cnt)
        elif open_ is None:
            r.found(check, row, at, f"{cname} without an open shape")
        else:
            si, sname, scnt = open_
            moves = int(cm[row] - cm[si + 1])
            if name != sname or cnt != scnt:
                r.found(check, row, at, f"{cname} {string_value(name)},{cnt} does not repeat record {si}'s "
                                        f"{string_value(sname)},{scnt}")
            elif moves != scnt:
                r.found(check, row, at,
                        f"shape {string_value(sname)} encloses {moves} motion commands, declares {scnt}")
            open_ = None
    if open_ is not None:
        r.found(check, open_[0], int(off[open_[0]]), f"shape {string_value(open_[1])} is never closed")


def _shapes_balanced(parts: list[Any], motion: list[Any]) -> bool:
    """True when the loop of _shape_end would find nothing: starts and ends alternate, from a
    start to an end, each end repeats its start's name and count, and the count is the number
    of motions between them (motion: the rows of motion commands, ascending a part: counted by
    binary search, no pass over the file's records). Only a quick yes: on False the loop decides."""
    if len({p[2].shape[1] for p in parts}) != 1:
        return False
    starts, ends = [p for p in parts if p[1] == 0], [p for p in parts if p[1] == 1]
    if len(starts) == 1 and len(ends) == 1:
        # one start command and one end command (a part each): no merge into file order; they
        # alternate from a start when each start comes before its end and each end before the next start
        (opened, _, s_names, s_counts, _), (closed, _, e_names, e_counts, _) = starts[0], ends[0]
        if len(opened) != len(closed) or not ((opened < closed).all() and (closed[:-1] < opened[1:]).all()):
            return False
        if not ((s_names == e_names).all() and (s_counts == e_counts).all()):
            return False
        counts = s_counts
    else:
        rows, (kinds, names, counts) = _in_file_order(
            [(p[0], np.full(len(p[0]), p[1], dtype=np.int8), p[2], p[3]) for p in parts])
        if len(rows) % 2 or not ((kinds[0::2] == 0).all() and (kinds[1::2] == 1).all()):
            return False
        opened, closed = rows[0::2], rows[1::2]
        if not ((names[0::2] == names[1::2]).all() and (counts[0::2] == counts[1::2]).all()):
            return False
        counts = counts[0::2]
    if not motion:
        return bool((counts == 0).all())
    # the motions after each start and before its end; the parts' rows as one ascending run (a stable
    # sort of a few ascending runs merges them), searched once for the starts and once for the ends
    moves = motion[0] if len(motion) == 1 else np.sort(np.concatenate(motion), kind="stable")
    inside = np.searchsorted(moves, closed)
    inside -= np.searchsorted(moves, opened + 1)
    return bool((inside == counts).all())


# -- one test for the bounded checks of a layout -----------------------------------------
# finite, positive, range and machine_limits each bound the binary32 arguments of a layout from
# below and above (finite: the largest binary32; positive: the least one above 0; range: its
# limits as the least / greatest binary32 inside them; machine_limits: its binary32 bounds). When
# every float of a layout's records lies within the tightest bounds of its words (a NaN never
# does), none of those kernels has anything to report there, and they are not called: one test of
# three array operations over the layout's floats instead of a few operations a check and target.
# Only a quick yes: where some value lies outside, the kernels run and decide.
@dataclass(frozen=True)
class _Bounds:
    """A layout's bounded checks as one test: the float words tested (None: every word of the
    arguments), each one's lowest and highest binary32 within bounds, and the plan without the
    kernels the test stands for."""

    cols: Any
    lo: Any  # a column: one bound a tested word
    hi: Any
    rest: tuple[tuple[Check, Any], ...]


_BOUNDS: dict[tuple[int, int, str, int], tuple[Machine, Any, _Bounds | None]] = {}


def _at_least32(x: float, strict: bool) -> float:
    """The least binary32 y with y >= x (y > x when strict): v >= y <=> v >= x (> x) for binary32 v."""
    with np.errstate(over="ignore"):
        y = np.float32(x)
    if float(y) < x or (strict and float(y) == x):
        y = np.nextafter(y, np.float32(np.inf))
    return math.nan if strict and y == np.inf else float(y)


def _at_most32(x: float, strict: bool) -> float:
    """The greatest binary32 y with y <= x (y < x when strict)."""
    return -_at_least32(-x, strict)


def _float32_words(lay: T.LayoutInfo, name: str) -> list[int] | None:
    """The 4-byte words of argument ``name`` when it is binary32 at a word offset, else None."""
    f = next((a for a in lay.args if a.name == name), None)
    if f is None or f.kind != "float" or f.numpy != "f4" or f.offset % 4:
        return None
    return [f.offset // 4 + k for k in range(f.size // 4)]


def _bounds_of(r: Records, lay: T.LayoutInfo, plan: tuple[tuple[Check, Any], ...], elsewhere: frozenset[str]
               ) -> _Bounds | None:
    """The bounded-check test of a layout (made once a layout, plan, version and machine)."""
    key = (id(lay), id(plan), r.version, id(r.machine))
    got = _BOUNDS.get(key)
    if got is None or got[0] is not r.machine or got[1] is not plan:
        if len(_BOUNDS) > 512:
            _BOUNDS.clear()
        got = _BOUNDS[key] = (r.machine, plan, _make_bounds(r.machine, lay, plan, elsewhere))
    return got[2]


class _Box:
    """The tightest [lo, hi] of each float32 word of a layout that the checks folded so far allow."""

    def __init__(self, words: int) -> None:
        self.lo, self.hi = [-math.inf] * words, [math.inf] * words
        self.bounded: set[int] = set()

    def bound(self, ws: list[int], low: float, high: float) -> None:
        for w in ws:
            self.lo[w], self.hi[w] = max(self.lo[w], low), min(self.hi[w], high)
            self.bounded.add(w)


def _fold_finite(box: _Box, check: Check, lay: T.LayoutInfo, machine: Machine) -> bool:
    big = float(np.finfo(np.float32).max)
    for f in lay.args:
        if f.kind == "float":
            box.bound(_float32_words(lay, f.name) or [], -big, big)
    return True


def _fold_range(box: _Box, check: Check, lay: T.LayoutInfo, machine: Machine) -> bool:
    """A positive or a range check: its bounds on the layout's float32 targets (False: a target is
    not float32 words, and the check runs as its kernel)."""
    cmd = T.BY_CODE[lay.code]
    names = [nm for t in _targets_of(check, cmd) for nm in t if any(a.name == nm for a in lay.args)]
    if any(_float32_words(lay, nm) is None for nm in names):
        return False
    if check["kind"] == "positive":
        low, high = _at_least32(0.0, True), math.inf
    else:
        low = -math.inf if check["min"] is None else _at_least32(float(check["min"]), check["min_exclusive"])
        high = math.inf if check["max"] is None else _at_most32(float(check["max"]), check["max_exclusive"])
    for nm in names:
        box.bound(_float32_words(lay, nm) or [], low, high)
    return True


def _fold_machine(box: _Box, check: Check, lay: T.LayoutInfo, machine: Machine) -> bool:
    rules = machine_rules(check, T.BY_CODE[lay.code].name, lay.variant)
    have = [(f, limit) for f, limit, _ in rules if any(a.name == f.name for a in lay.args)]
    if any(f.per or _float32_words(lay, f.name) is None for f, _ in have):
        return False
    for f, limit in have:
        lim = machine.limits[limit]
        for k, w in enumerate(_float32_words(lay, f.name) or []):
            j = k if len(lim.lo32) > 1 else 0
            box.bound([w], lim.lo32[j], lim.hi32[j])
    return True


# The check kinds whose batch kernel one bounds test can stand for, and how each folds into the box.
_FOLDS: dict[str, Callable[[_Box, Check, T.LayoutInfo, Machine], bool]] = {
    "finite": _fold_finite, "positive": _fold_range, "range": _fold_range, "machine_limits": _fold_machine}


def _make_bounds(machine: Machine, lay: T.LayoutInfo, plan: tuple[tuple[Check, Any], ...],
                 elsewhere: frozenset[str]) -> _Bounds | None:
    if lay.size % 4 or _float_words(lay) is None:
        return None
    words = lay.size // 4
    box = _Box(words)
    rest: list[tuple[Check, Any]] = []
    mine = [(check, fn) for check, fn in plan if check["id"] not in elsewhere]
    for check, fn in mine:
        fold = _FOLDS.get(check["kind"]) if fn is KERNELS[check["kind"]].batch else None
        if fold is None or not fold(box, check, lay, machine):
            rest.append((check, fn))
    if len(rest) == len(mine) or not box.bounded:
        return None
    order = sorted(box.bounded)
    cols = None if order == list(range(words)) else np.asarray(order, dtype=np.intp)
    return _Bounds(cols, np.asarray([box.lo[w] for w in order], dtype=np.float32)[:, None],
                   np.asarray([box.hi[w] for w in order], dtype=np.float32)[:, None], tuple(rest))


def _targets_of(check: Check, cmd: T.CommandInfo) -> Iterator[tuple[str, ...]]:
    for t in check["targets"]:
        if t["command"] == cmd.name:
            yield tuple(t["args"])


def _within(b: Batch, q: _Bounds) -> bool:
    """Every bounded float of the batch within its bounds (NaN is not). The words are compared a
    word at a time (transposed: a bound a row), not a record at a time: numpy sets its inner loop
    up for every row, and a record's row holds a few words."""
    if b.bytes_ is None:
        return False
    v = b.bytes_.view(T.BO + "f4").T
    v = np.ascontiguousarray(v) if q.cols is None else v.take(q.cols, axis=0)
    ok = np.greater_equal(v, q.lo)
    ok &= np.less_equal(v, q.hi)
    return bool(np.count_nonzero(ok) == ok.size)


Applies = Callable[[Check, T.LayoutInfo, T.CommandInfo], bool]


@dataclass(frozen=True)
class Kernel:
    """How one check kind runs: ``every`` once over the head columns of every record,
    ``batch`` once per layout batch, then ``end`` once (for what needs file order).
    ``applies``: whether ``batch`` has anything to look at in a layout's records (None: always);
    a batch kernel is not called where it has nothing (the plan is made once a layout)."""

    every: Callable[[Records, Check], None] | None = None
    batch: Callable[[Records, Check, Batch], None] | None = None
    end: Callable[[Records, Check], None] | None = None
    applies: Applies | None = None


def _has_field(kind: str) -> Applies:
    return lambda check, lay, cmd: any(f.kind == kind for f in lay.args)


def _targeted(check: Check, lay: T.LayoutInfo, cmd: T.CommandInfo) -> bool:
    return any(t["command"] == cmd.name for t in check["targets"])


def _has_role(role: str) -> Applies:
    return lambda check, lay, cmd: bool(getattr(cmd, role))


def _has_rules(check: Check, lay: T.LayoutInfo, cmd: T.CommandInfo) -> bool:
    return bool(machine_rules(check, cmd.name, lay.variant))


def _deprecates(check: Check, lay: T.LayoutInfo, cmd: T.CommandInfo) -> bool:
    return T.deprecates(check, cmd.name, lay.variant)


def _deprecated(r: Records, check: Check, b: Batch) -> None:
    """Every record of a deprecated command or layout (its versions: validation's scope filter).
    Like every batch kernel it judges the layout itself: `applies` only spares the call."""
    if not _deprecates(check, b.lay, b.cmd):
        return
    r.add(check, b.rows, r.off[b.rows] + T.RECORD_FIELDS[T.I_CODE].offset, b.rows,
          _const(f"{b.cmd.name} is deprecated since version {check['since']}"))


def _moves_or_shapes(check: Check, lay: T.LayoutInfo, cmd: T.CommandInfo) -> bool:
    return cmd.motion is not None or cmd.shape is not None


# check kind -> its kernel. The file-level kinds (header, framing, file checksum) are
# validation.py's; every other kind of the spec must be here (tests/test_engine_structure.py).
KERNELS: dict[str, Kernel] = {
    "sequence": Kernel(every=_sequence),
    "reserved_byte": Kernel(every=_reserved),
    "code_copy": Kernel(every=_code_copy),
    "arg_checksum": Kernel(batch=_record_checksum_batch, end=_record_checksum_end, applies=_carries),
    "unknown_code": Kernel(every=_unknown_code),
    "availability": Kernel(every=_availability),
    "arg_size": Kernel(every=_arg_size),
    "finite": Kernel(batch=_finite, applies=_has_field("float")),
    "string_tail": Kernel(batch=_string_tail, applies=_has_field("string")),
    "string_ascii": Kernel(batch=_string_ascii, applies=_has_field("string")),
    "positive": Kernel(batch=_positive, applies=_targeted),
    "nonzero_vector": Kernel(batch=_nonzero_vector, applies=_targeted),
    "range": Kernel(batch=_range, applies=_targeted),
    "ordered": Kernel(batch=_ordered, applies=_targeted),
    "nondecreasing": Kernel(batch=_nondecreasing, end=_nondecreasing_end, applies=_targeted),
    "cutter_table": Kernel(batch=_cutter_table, applies=_has_role("cutter")),
    "continuity": Kernel(batch=_continuity, end=_continuity_end, applies=_has_role("motion")),
    "orientation": Kernel(batch=_orientation, end=_orientation_end, applies=_has_role("orientation")),
    "shape": Kernel(batch=_shape, end=_shape_end, applies=_moves_or_shapes),
    "machine_limits": Kernel(batch=_machine_limits, applies=_has_rules),
    "deprecated": Kernel(batch=_deprecated, applies=_deprecates),
}

@lru_cache(maxsize=2)
def _active(with_cutters: bool) -> tuple[tuple[Check, Kernel], ...]:
    out: list[tuple[Check, Kernel]] = []
    for kind, kernel in KERNELS.items():
        if kind == "cutter_table" and not with_cutters:
            continue
        # every check of the kind runs (its own id, severity, parameters), as in the C engine
        out.extend((c, kernel) for c in T.checks_of(kind))
    return tuple(out)


BatchFn = Callable[[Records, Check, Batch], None]
_PLANS: dict[tuple[bool, int], tuple[tuple[Check, BatchFn], ...]] = {}


def _plan(with_cutters: bool, lay: T.LayoutInfo) -> tuple[tuple[Check, BatchFn], ...]:
    """The batch kernels that have something to look at in a layout's records, in KERNELS order
    (made once a layout: layouts are constants)."""
    got = _PLANS.get((with_cutters, id(lay)))
    if got is None:
        cmd = T.BY_CODE[lay.code]
        got = _PLANS[(with_cutters, id(lay))] = tuple(
            (c, k.batch) for c, k in _active(with_cutters)
            if k.batch is not None and (k.applies is None or k.applies(c, lay, cmd)))
    return got


def record_findings(buf: bytes, offsets: Sequence[int], version: str, profile: str, cutters: Cutters | None,
                    machine: Machine | None = None) -> Iterator[Finding]:
    """The record findings in validate's order, one at a time."""
    if len(offsets) == 0:
        return iter(())
    r = Records(buf, np.frombuffer(buf, dtype=np.uint8), np.asarray(offsets, dtype=np.int64), version, profile,
                cutters, machine if machine is not None else DEFAULT_MACHINE)
    r.head.update(_head(r.a, r.off))
    # a check scoped to other versions judges nothing in this file (validation drops what it would
    # say): its kernel is not run, rather than made to find what is thrown away
    elsewhere = T.scoped_out(version)
    active = tuple(x for x in _active(cutters is not None) if x[0]["id"] not in elsewhere)
    # The kernels meet NaNs (signalling ones too), infinities and huge values on purpose: the
    # checks report them as findings. numpy's floating-point warnings (an invalid cast, an
    # overflow) would only be noise on stderr, never a finding: they are off while the kernels run
    # (here, once: a kernel opens no errstate of its own, each cost a few microseconds a call).
    with np.errstate(all="ignore"):
        for check, kernel in active:
            if kernel.every is not None:
                kernel.every(r, check)
        for b in _batches(r):
            plan = _plan(cutters is not None, b.lay)
            q = _bounds_of(r, b.lay, plan, elsewhere)
            if q is not None and _within(b, q):
                plan = q.rest
            for check, fn in plan:
                if check["id"] not in elsewhere:
                    fn(r, check, b)
        for check, kernel in active:
            if kernel.end is not None:
                kernel.end(r, check)
    r.pending.sort(key=finding_order)
    return iter(heapq.merge(iter(r.pending), *r.groups, key=finding_order))


def header_string_findings(raw: bytes, offset: int, name: str) -> list[Finding]:
    """The string checks of one header string field: the same kernels, one row, no record (none
    when the field is printable ASCII then NULs only: neither kernel flags that, as _plain_strings)."""
    out: list[Finding] = []
    if _plain_bytes(raw):
        return out

    def add(check: Check | None, rows: Any, offs: Any, keys: Any, msg: Message) -> None:
        if check is not None:
            out.extend(finding(check, None, int(offs[k]), msg(keys[k])) for k in range(len(rows)))

    col = np.frombuffer(raw, dtype=np.uint8).reshape(1, -1)
    first = first_nul(col)
    for kind, kernel in (("string_tail", string_tail), ("string_ascii", string_ascii)):
        for check in T.checks_of(kind):
            kernel(add, check, col, np.zeros(1, dtype=np.int64), np.full(1, offset, dtype=np.int64), name, first)
    return out
