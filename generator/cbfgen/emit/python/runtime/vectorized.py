"""The record checks of validation.py, vectorised with numpy for big files.

Same checks, same findings, same messages as ``validation._records`` (the
reference); the test suite runs both on the same inputs and requires equal
output. Used by ``validate`` for files with many records, where the per-record
Python loop dominates; small files keep the reference path and its fast start.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from functools import lru_cache
from typing import TYPE_CHECKING, Any

import numpy as np

from . import tables as T
from .validation import range_text

if TYPE_CHECKING:
    from numpy.typing import NDArray

    from .validation import Cutters, _Out

Rows = "NDArray[np.int64]"


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
    """Bytes a[s:s+width] for each start, one column at a time (no n x width index matrix)."""
    out = np.empty((starts.shape[0], width), dtype=np.uint8)
    for k in range(width):
        np.take(a, starts + k, out=out[:, k])
    return out


def _dtype(lay: T.LayoutInfo) -> np.dtype[Any]:
    fields: list[Any] = []
    for f in lay.args:
        if f.kind == "float":
            fields.append((f.name, np.dtype(T.BO + "f4"), (f.count,)) if f.count > 1 else (f.name, T.BO + "f4"))
        elif f.kind == "uint":
            fields.append((f.name, T.BO + {1: "u1", 2: "u2", 4: "u4"}[f.elem_size]))
        else:
            fields.append((f.name, np.uint8, (f.size,)))
    return np.dtype(fields)


def records(out: _Out, buf: bytes, offsets: Sequence[int], version: str, profile: str, cutters: Cutters | None) -> None:
    from . import validation as V

    one = V._one
    n = len(offsets)
    if n == 0:
        return
    a = np.frombuffer(buf, dtype=np.uint8)
    off = np.asarray(offsets, dtype=np.int64)  # no copy when framing gave an int64 array
    hs = T.HEAD_SIZE
    head = _gather(a, off, hs)
    F = T.RECORD_FIELDS
    seq, code, copy = _uint(head, F[T.I_SEQ]), _uint(head, F[T.I_CODE]), _uint(head, F[T.I_COPY])
    nb, res, chk = _uint(head, F[T.I_SIZE]), _uint(head, F[T.I_RES]), _uint(head, F[T.I_CHK])
    del head  # each field is its own small array now (memory stays a few bytes a record)
    pending: list[tuple[int, int, Any, int, str]] = []  # (record, order, check, offset, message)

    def add(check: dict[str, Any] | None, rows: Any, order: int, offs: Any, msgs: Any) -> None:
        if check is None:
            return
        for r, o, m in zip(rows, offs, msgs, strict=True):
            pending.append((int(r), order, check, int(o), m))

    # -- head checks ----------------------------------------------------------
    wrap = T.SEQ_MASK
    bad = np.nonzero(seq != (np.arange(n, dtype=np.int64) & wrap))[0]
    add(one("sequence"), bad, 0, off[bad] + F[T.I_SEQ].offset,
        (f"sequence number {seq[i]}, expected {i & wrap}" for i in bad))
    bad = np.nonzero(res != 0)[0]
    add(one("reserved_byte"), bad, 1, off[bad] + F[T.I_RES].offset, (f"reserved byte is 0x{res[i]:02X}" for i in bad))
    bad = np.nonzero(copy != code)[0]
    add(one("code_copy"), bad, 2, off[bad] + F[T.I_COPY].offset,
        (f"code copy 0x{copy[i]:02X} differs from code 0x{code[i]:02X}" for i in bad))
    spec = T.CHECKSUMS["fields"]["args"]
    if T.CHECKSUMS["algorithms"][spec["algorithm"]] == "sum" and T.CHECKSUMS["coverages"][spec["coverage"]] == [
            {"region": "args", "start": None, "end": None, "exclude": []}]:
        # The k-th argument byte of every record that has one, added column by
        # column: memory stays a few vectors of n (a cumulative sum or reduceat
        # over the file would hold 8 bytes per file byte).
        sums = np.zeros(n, dtype=np.int64)
        starts = off + hs
        last = a.shape[0] - 1
        for k in range(int(nb.max())):
            sums += np.where(nb > k, a[np.minimum(starts + k, last)], 0)
        want = sums & ((1 << (8 * T.ARG_CHECKSUM.size)) - 1)
    else:
        want = np.array([V._field_sum("args", buf, [], args=buf[o + hs:o + hs + int(s)])
                         for o, s in zip(offsets, nb, strict=True)], dtype=np.int64)
    bad = np.nonzero(chk != want)[0]
    add(one("arg_checksum"), bad, 3, off[bad] + T.ARG_CHECKSUM.offset,
        (f"stored argument checksum {chk[i]}, computed {want[i]}" for i in bad))

    # -- command tables ------------------------------------------------------------
    known, avail, size_ok, lay_of, lays = _tables(version, profile)
    code_off = F[T.I_CODE].offset
    bad = np.nonzero(~known[code])[0]
    add(one("unknown_code"), bad, 4, off[bad] + code_off, (f"unknown command code 0x{code[i]:02X}" for i in bad))
    covering = V.availability_checks()
    bad = np.nonzero(known[code] & ~avail[code])[0]
    for c in np.unique(code[bad]):
        name = T.BY_CODE[int(c)].name
        rows = bad[code[bad] == c]
        add(covering.get((version, name)), rows, 5, off[rows] + code_off,
            (f"{name} is not available in version {version}" for _ in rows))
    bad = np.nonzero(known[code] & ~size_ok[code, nb])[0]

    def sizes_msg(i: int) -> str:
        cmd = T.BY_CODE[int(code[i])]
        sizes = sorted({lay.size for lay in cmd.candidates(version) if lay.accepted_under(profile)})
        return f"{cmd.name} with {nb[i]} argument bytes; expected {' or '.join(map(str, sizes))}"

    add(one("arg_size"), bad, 6, off[bad] + F[T.I_SIZE].offset, (sizes_msg(int(i)) for i in bad))

    # -- arguments, one group per layout -------------------------------------------------
    which = lay_of[code, nb]
    c_finite = one("finite")
    targeted: dict[str, list[tuple[dict[str, Any], tuple[str, ...]]]] = {}
    for kind in ("positive", "nonzero_vector", "range", "nondecreasing", "ordered"):
        for ch in T.checks_of(kind):
            for t in ch["targets"]:
                targeted.setdefault(t["command"], []).append((ch, tuple(t["args"])))
    motion_parts: list[Any] = []  # (rows, start, end, layout, argument offsets)
    orient_parts: list[Any] = []  # (rows, start, end, argument offsets, command name)
    shape_rows: list[Any] = []  # (record, 0 start / 1 end, name, count, command name)
    motion_mask = np.zeros(n, dtype=bool)
    nondec: list[tuple[int, dict[str, Any], str, str, float, int]] = []
    for li, lay in enumerate(lays):
        rows = np.nonzero(which == li)[0]
        if rows.size == 0:
            continue
        cmd = T.BY_CODE[lay.code]
        aoff = off[rows] + hs
        arr = _gather(a, aoff, lay.size).view(_dtype(lay))[:, 0] if lay.size else None
        cols: dict[str, Any] = {}
        for f in lay.args:
            assert arr is not None
            col = arr[f.name]
            if f.kind == "float":
                with np.errstate(invalid="ignore"):  # signalling NaNs stay NaN
                    cols[f.name] = col.astype(np.float64)
                fin = np.isfinite(cols[f.name]) if f.count == 1 else np.isfinite(cols[f.name]).all(axis=1)
                bad = np.nonzero(~fin)[0]
                add(c_finite, rows[bad], 10, aoff[bad] + f.offset, (f"{cmd.name}.{f.name} is not finite" for _ in bad))
            elif f.kind == "string":
                cols[f.name] = col
                _strings(add, one, col, rows, aoff + f.offset, f"{cmd.name}.{f.name}")
            else:
                cols[f.name] = col
        for ch, names in targeted.get(cmd.name, ()):
            _targeted(add, ch, names, cmd.name, lay, cols, rows, aoff, nondec)
        if cutters is not None and cmd.cutter and one("cutter_table") is not None:
            from .validation import _cutter

            for k, r in enumerate(rows):
                vals = lay.struct.unpack_from(buf, int(aoff[k]))
                argd: dict[str, Any] = {}
                j = 0
                for f in lay.args:
                    argd[f.name] = tuple(vals[j:j + f.count]) if f.count > 1 else vals[j]
                    j += f.count
                sub = V._Out()
                _cutter(sub, one("cutter_table") or {}, cmd, lay, argd, int(r), int(aoff[k]), cutters,
                        T.TOL["cutter_mm"])
                for fnd in sub.findings:
                    pending.append((int(r), 13, one("cutter_table"), fnd.offset or 0, fnd.message))
        m = cmd.motion
        if m is not None:
            motion_mask[rows] = True
            start = (np.full((rows.size, 3), np.nan) if m["kind"] == "point" else cols[m["start"]])
            motion_parts.append((rows, start, _ends(m, cols, rows.size), lay, aoff))
        o = cmd.orientation
        if o is not None:
            s = np.full((rows.size, 3), np.nan) if o["kind"] == "set" else cols[o["start"]]
            orient_parts.append((rows, s, cols[o["end"]], aoff, cmd.name))
        sh = cmd.shape
        if sh is not None:
            for k, r in enumerate(rows):
                shape_rows.append((int(r), 0 if sh["kind"] == "start" else 1,
                                   bytes(cols[sh["name"]][k]), int(cols[sh["count"]][k]), cmd.name))

    # -- sequential checks ---------------------------------------------------------
    nondec.sort(key=lambda t: t[0])
    prev: dict[tuple[str, str], float] = {}
    for r, ch, key, msgname, v, at in nondec:
        k2 = (ch["id"], key)
        if k2 in prev and v < prev[k2]:
            pending.append((r, 11, ch, at, f"{msgname} falls from {prev[k2]:g} to {v:g}"))
        prev[k2] = v
    _continuity(pending, one("continuity"), motion_parts)
    _orientation(pending, one("orientation"), orient_parts)
    _shapes(pending, one("shape"), shape_rows, motion_mask, off)
    for r, _, ch, at, msg in pending:
        out.add(ch, r, at, msg)


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


def _strings(add: Any, one: Any, col: NDArray[np.uint8], rows: Any, offs: Any, name: str) -> None:
    is_nul = col == 0
    has_nul = is_nul.any(axis=1)
    first = np.where(has_nul, is_nul.argmax(axis=1), col.shape[1])
    pos = np.arange(col.shape[1])
    after = pos[None, :] > first[:, None]
    tail = (after & (col != 0)).any(axis=1)
    bad = np.nonzero(tail)[0]
    add(one("string_tail"), rows[bad], 10, offs[bad],
        (f"{name}: bytes after the first NUL: {bytes(col[k, first[k] + 1:]).rstrip(bytes(1)).hex()}" for k in bad))
    before = pos[None, :] < first[:, None]
    nonascii = before & ((col < 0x20) | (col > 0x7E))
    bad = np.nonzero(nonascii.any(axis=1))[0]
    add(one("string_ascii"), rows[bad], 10, offs[bad],
        (f"{name}: non-ASCII byte 0x{int(col[k][nonascii[k]][0]):02X}" for k in bad))


def _targeted(add: Any, ch: dict[str, Any], names: tuple[str, ...], cname: str, lay: T.LayoutInfo,
              cols: dict[str, Any], rows: Any, aoff: Any, nondec: list[Any]) -> None:
    present = [nm for nm in names if nm in cols]
    kind = ch["kind"]
    if kind == "ordered":
        if len(present) != len(names):
            return
        vals = np.stack([cols[nm] for nm in names], axis=1)
        fin = np.isfinite(vals).all(axis=1)
        bad = np.nonzero(fin & (vals[:, :-1] > vals[:, 1:]).any(axis=1))[0]
        add(ch, rows[bad], 12, aoff[bad],
            (f"{cname}: {' <= '.join(f'{nm}={float(cols[nm][k]):g}' for nm in names)} does not hold" for k in bad))
        return
    for nm in present:
        v = cols[nm]
        at = aoff + next(f.offset for f in lay.args if f.name == nm)
        if kind == "positive":
            bad = np.nonzero(np.isfinite(v) & (v <= 0))[0]
            add(ch, rows[bad], 12, at[bad], (f"{cname}.{nm} is {float(v[k]):g}, must be > 0" for k in bad))
        elif kind == "nonzero_vector":
            bad = np.nonzero(np.isfinite(v).all(axis=1) & (v == 0.0).all(axis=1))[0]
            add(ch, rows[bad], 12, at[bad], (f"{cname}.{nm} has zero length" for _ in bad))
        elif kind == "range":
            lo = -np.inf if ch["min"] is None else ch["min"]
            hi = np.inf if ch["max"] is None else ch["max"]
            bad = np.nonzero(np.isfinite(v) & ((v < lo) | (v > hi)))[0]
            add(ch, rows[bad], 12, at[bad],
                (f"{cname}.{nm} is {float(v[k]):g}, {range_text(ch)}" for k in bad))
        elif kind == "nondecreasing":
            for k in np.nonzero(np.isfinite(v))[0]:
                nondec.append((int(rows[k]), ch, f"{cname}.{nm}", f"{cname}.{nm}", float(v[k]), int(at[k])))


def _ends(m: dict[str, str], cols: dict[str, Any], k: int) -> Any:
    kind = m["kind"]
    if kind in ("point", "line"):
        end = cols[m["end"]].copy()
        end[~np.isfinite(end).all(axis=1)] = np.nan
        return end
    start, center, normal = cols[m["start"]], cols[m["center"]], cols[m["normal"]]
    deg = cols[m["degrees"]]
    length = cols[m["length"]] if kind == "helix" else np.zeros(k)
    ok = (np.isfinite(start).all(axis=1) & np.isfinite(center).all(axis=1) & np.isfinite(normal).all(axis=1)
          & np.isfinite(deg) & np.isfinite(length))
    nn = np.sqrt((normal * normal).sum(axis=1))
    ok &= nn != 0.0
    with np.errstate(invalid="ignore", divide="ignore"):
        kk = normal / nn[:, None]
        v = start - center
        th = deg * (math.pi / 180.0)
        c, s = np.cos(th), np.sin(th)
        kxv = np.cross(kk, v)
        kdv = (kk * v).sum(axis=1)
        rot = v * c[:, None] + kxv * s[:, None] + kk * (kdv * (1.0 - c))[:, None]
        end = center + rot + length[:, None] * kk
    end[~ok] = np.nan
    return end


def _continuity(pending: list[Any], check: dict[str, Any] | None, parts: list[Any]) -> None:
    if check is None or not parts:
        return
    rows = np.concatenate([p[0] for p in parts])
    order = np.argsort(rows, kind="stable")
    start = np.concatenate([p[1] for p in parts])[order]
    end = np.concatenate([p[2] for p in parts])[order]
    rows = rows[order]
    dvec = start.copy()  # start - previous end, in place (memory: one n x 3 array)
    dvec[0] = np.nan
    dvec[1:] -= end[:-1]
    del end
    with np.errstate(invalid="ignore"):
        np.multiply(dvec, dvec, out=dvec)
        d = np.sqrt(dvec.sum(axis=1))
    del dvec
    with np.errstate(invalid="ignore"):
        bad = np.nonzero(np.isfinite(start).all(axis=1) & (d > T.TOL["position_mm"]))[0]
    if bad.size == 0:
        return
    names = np.concatenate([np.full(len(p[0]), T.BY_CODE[p[3].code].name, dtype=object) for p in parts])[order]
    starts = np.concatenate([p[4] + _start_offset(p[3]) for p in parts])[order]
    for k in bad:
        pending.append((int(rows[k]), 14, check, int(starts[k]),
                        f"{names[k]} starts {float(d[k]):.6g} mm from the current position"))


def _start_offset(lay: T.LayoutInfo) -> int:
    m = T.BY_CODE[lay.code].motion or {}
    return next((f.offset for f in lay.args if f.name == m.get("start")), 0)


def _orientation(pending: list[Any], check: dict[str, Any] | None, parts: list[Any]) -> None:
    if check is None or not parts:
        return
    rows = np.concatenate([p[0] for p in parts])
    order = np.argsort(rows, kind="stable")
    start = np.concatenate([p[1] for p in parts])[order]
    end = np.concatenate([p[2] for p in parts])[order]
    aoff = np.concatenate([p[3] for p in parts])[order]
    cnames = np.concatenate([np.full(len(p[0]), p[4], dtype=object) for p in parts])[order]
    rows = rows[order]
    with np.errstate(invalid="ignore"):
        valid_end = np.isfinite(end).all(axis=1) & (np.sqrt((end * end).sum(axis=1)) > 0.0)
        end = np.where(valid_end[:, None], end, np.nan)
        prev = np.vstack((np.full((1, 3), np.nan), end[:-1]))
        s_ok = np.isfinite(start).all(axis=1) & (np.sqrt((start * start).sum(axis=1)) > 0.0)
        cx = np.cross(start, prev)
        ang = np.degrees(np.arctan2(np.sqrt((cx * cx).sum(axis=1)), (start * prev).sum(axis=1)))
        bad = np.nonzero(s_ok & np.isfinite(prev).all(axis=1) & (ang > T.TOL["orientation_deg"]))[0]
    for k in bad:
        r = int(rows[k])
        pending.append((r, 15, check, int(aoff[k]),
                        f"{cnames[k]} starts {float(ang[k]):.6g} deg from the current orientation"))


def _shapes(pending: list[Any], check: dict[str, Any] | None, shape_rows: list[Any], motion: Any, off: Any) -> None:
    if check is None or not shape_rows:
        return
    from .validation import _s

    cm = np.concatenate((np.zeros(1, dtype=np.int64), np.cumsum(motion, dtype=np.int64)))
    shape_rows.sort()
    open_: tuple[int, bytes, int] | None = None
    for r, kind, name, cnt, cname in shape_rows:
        at = int(off[r])
        if kind == 0:
            if open_ is not None:
                pending.append((r, 16, check, at, f"{cname} inside the open shape of record {open_[0]}"))
            open_ = (r, name, cnt)
        elif open_ is None:
            pending.append((r, 16, check, at, f"{cname} without an open shape"))
        else:
            si, sname, scnt = open_
            moves = int(cm[r] - cm[si + 1])
            if name != sname or cnt != scnt:
                pending.append((r, 16, check, at,
                                f"{cname} {_s(name)},{cnt} does not repeat record {si}'s {_s(sname)},{scnt}"))
            elif moves != scnt:
                pending.append((r, 16, check, at, f"shape {_s(sname)} encloses {moves} motion commands, "
                                                  f"declares {scnt}"))
            open_ = None
    if open_ is not None:
        pending.append((open_[0], 16, check, int(off[open_[0]]), f"shape {_s(open_[1])} is never closed"))
