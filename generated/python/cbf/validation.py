"""validate: every check of the spec, reported as findings, never raising on bad input.

Each check's id, severity and parameters come from the spec; this module
implements the check *kinds*. The rules are the "fails" texts of
spec/cbf.yaml and conformance/PROTOCOL.md.
"""

from __future__ import annotations

import heapq
import math
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from . import tables as T
from .codec import Buffer, field_checksum, file_algorithm, frame, header_info
from .model import Cbf

if TYPE_CHECKING:
    from .machine import Machine


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


Cutters = Mapping[str, tuple[float, float]]


class _Out:
    def __init__(self) -> None:
        self.findings: list[Finding] = []

    def add(self, check: Mapping[str, Any] | None, record: int | None, offset: int | None, message: str) -> None:
        if check is not None:
            self.findings.append(Finding(check["id"], check["severity"], record, offset, message))


def _one(kind: str) -> dict[str, Any] | None:
    found = T.checks_of(kind)
    return found[0] if found else None


def availability_checks() -> dict[tuple[str, str], dict[str, Any]]:
    """(version, command) -> the one availability check that covers the pair (the loader
    refuses a pair covered twice or not at all), so a finding names the right clause."""
    return {(v, name): c for c in T.checks_of("availability") for v in c["versions"] for name in c["commands"]}


def _finite(v: Any) -> bool:
    if isinstance(v, tuple):
        return all(math.isfinite(x) for x in v)
    return isinstance(v, float) and math.isfinite(v)


def _value_of_string(raw: bytes) -> bytes:
    return raw.split(b"\0", 1)[0]


def _string_checks(out: _Out, raw: bytes, record: int | None, offset: int, name: str) -> None:
    head, sep, tail = raw.partition(b"\0")
    if sep and tail.strip(b"\0"):
        out.add(_one("string_tail"), record, offset,
                f"{name}: bytes after the first NUL: {tail.rstrip(bytes(1)).hex()}")
    bad = [b for b in head if not 0x20 <= b <= 0x7E]
    if bad:
        out.add(_one("string_ascii"), record, offset, f"{name}: non-ASCII byte 0x{bad[0]:02X}")


def validate(data: Buffer | Cbf, *, profile: str = "default", part_number: str | None = None,
             cutters: Cutters | None = None, engine: str = "auto", machine: Machine | None = None) -> list[Finding]:
    """Findings for a file (bytes) or a model (encoded with its stored values first).

    ``engine``: "auto" (numpy for big files), "python" or "numpy"; all give the same findings.
    ``machine``: a machine file's limits (cbf.machine.load_machine; breaches are errors), or None:
    the spec's default machine (breaches are warnings).
    """
    return list(iter_findings(data, profile=profile, part_number=part_number, cutters=cutters, engine=engine,
                              machine=machine))


def iter_findings(data: Buffer | Cbf, *, profile: str = "default", part_number: str | None = None,
                  cutters: Cutters | None = None, engine: str = "auto",
                  machine: Machine | None = None) -> Iterator[Finding]:
    """validate's findings, in its order, made one at a time as they are read: memory stays
    bounded however many findings a file gives (the checks run now; bad arguments raise now)."""
    framing: tuple[Sequence[int], int] | None = None
    if isinstance(data, Cbf):
        reuse = _decoded_source(data)
        if reuse is not None:
            data, framing = reuse
        else:
            from .codec import encode

            data = encode(data, keep_stored=True)
    buf = bytes(data)
    if profile not in T.PROFILES:
        raise ValueError(f"unknown profile {profile!r}; known: {', '.join(T.PROFILES)}")
    out = _Out()
    n = len(buf)
    if n < T.HEADER_SIZE:
        out.add(_one("truncated_header"), None, 0, f"file is {n} bytes, the header needs {T.HEADER_SIZE}")
        return iter(out.findings)
    if engine not in ("auto", "python", "numpy"):
        raise ValueError(f"unknown engine {engine!r}")
    vid, info = header_info(buf)
    hvals = info.struct.unpack_from(buf, 0)
    header = {f.name: v for f, v in zip(info.fields, hvals, strict=True)}
    if vid is None:
        out.add(_one("version"), None, T.VMAJOR.offset,
                f"version {buf[T.VMAJOR.offset]}.{buf[T.VMINOR.offset]} is not a version of this spec; "
                f"read as {T.FALLBACK_VERSION}")
    version = vid or T.FALLBACK_VERSION
    for f in (T.START, T.END):
        if header[f.name] != f.magic:
            out.add(_one("magic"), None, f.offset, f"{f.name} is 0x{header[f.name]:08X}, expected 0x{f.magic:08X}")
    hsum = T.HEADER_CHECKSUM_FIELDS.get("header")
    if hsum is not None:
        want = _field_sum("header", buf, [])
        if header[hsum.name] != want:
            out.add(_one("header_checksum"), None, hsum.offset,
                    f"stored header checksum {header[hsum.name]}, computed {want}")
    for f in info.fields:
        if f.kind == "string":
            _string_checks(out, header[f.name], None, f.offset, f.name)

    offsets, end = framing if framing is not None else frame(buf)
    count = header[T.COUNT.name]
    truncated = False
    if end < n:
        if len(offsets) < count:
            truncated = True
            out.add(_one("truncated_record"), len(offsets), end,
                    f"the file ends inside record {len(offsets)} ({n - end} byte(s) left)")
        else:
            out.add(_one("trailing"), None, end, f"{n - end} byte(s) after the last record")
    if not truncated and len(offsets) != count:
        out.add(_one("command_count"), None, T.COUNT.offset,
                f"header count {count}, the file holds {len(offsets)} records")

    fsum = T.HEADER_CHECKSUM_FIELDS.get("file")
    if fsum is not None:
        stored = header[fsum.name]
        prof = T.PROFILES[profile]
        alg = file_algorithm(profile)
        if not any(_field_sum("file", buf, offsets, cov, algorithm=alg) == stored for cov in prof["file_coverages"]):
            want = _field_sum("file", buf, offsets, prof["file_coverages"][0], algorithm=alg)
            msg = f"stored file checksum {stored}, computed {want}"
            for cov in prof["hint_coverages"]:
                # a hint coverage is computed as the profile that accepts it computes it
                owner = _profile_with(cov)
                hint_alg = file_algorithm(owner) if owner in T.PROFILES else alg
                if _field_sum("file", buf, offsets, cov, algorithm=hint_alg) == stored:
                    msg += f"; it matches coverage {cov} (use profile {owner})"
            out.add(_one("file_checksum"), None, fsum.offset, msg)

    stream: Iterator[Finding] = iter(())
    if engine == "numpy" or (engine == "auto" and len(offsets) >= VECTOR_MIN_RECORDS):
        from .vectorized import records

        stream = records(buf, offsets, version, profile, cutters)
    else:
        _records(out, buf, offsets, version, profile, cutters)
    if part_number is not None:
        _part_number(out, info, header, part_number)
    _descriptor_word(out, info, header)
    from .machine import machine_findings  # machine limits (L1, #13 item 16): one stream, engine-independent

    return iter(heapq.merge(sorted(out.findings, key=finding_order), stream,
                            machine_findings(buf, offsets, version, machine, engine), key=finding_order))


# Files with at least this many records are checked by the numpy engine
# (vectorized.py); smaller ones by the reference loop below, which starts fast.
VECTOR_MIN_RECORDS = 2000
_CHECK_ORDER = {c["id"]: i for i, c in enumerate(T.CHECKS)}


def finding_order(f: Finding) -> tuple[int, int, int, str]:
    """One order for both engines: header first, then by record, spec check order, offset."""
    return (-1 if f.record is None else f.record, _CHECK_ORDER.get(f.check, 0), f.offset or 0, f.message)


def _decoded_source(model: Cbf) -> tuple[bytes, tuple[Sequence[int], int]] | None:
    """The bytes and framing of a model that decode made and nobody changed since."""
    from .codec import decode_header
    from .model import RecordList

    recs = model.records
    if not isinstance(recs, RecordList) or recs.framed is None:
        return None
    buf, offsets = recs.source
    if buf[recs.framed:] != model.trailing or decode_header(buf) != model.header:
        return None
    return buf, (list(offsets), recs.framed)


def _profile_with(coverage: str) -> str:
    for pid, p in T.PROFILES.items():
        if coverage in p["file_coverages"]:
            return pid
    return "?"


def _field_sum(tag: str, buf: bytes, offsets: Sequence[int], coverage: str | None = None, args: bytes | None = None,
               algorithm: str | None = None) -> int:
    return field_checksum(tag, buf, offsets, coverage, args, algorithm)


def _part_number(out: _Out, info: T.HeaderInfo, header: Mapping[str, Any], part_number: str) -> None:
    f = info.by_role("implant_descriptor")
    if f is None:
        return
    words = _value_of_string(header[f.name]).decode("latin-1").split()
    first = words[0] if words else ""
    if first != part_number:
        out.add(_one("part_number"), None, f.offset,
                f"implant descriptor starts with {first!r}, expected {part_number!r}")


def _descriptor_word(out: _Out, info: T.HeaderInfo, header: Mapping[str, Any]) -> None:
    """4.2: the implant descriptor begins with the part number, so it holds a word."""
    f = info.by_role("implant_descriptor")
    if f is not None and not _value_of_string(header[f.name]).decode("latin-1").split():
        out.add(_one("descriptor_word"), None, f.offset, "implant descriptor holds no word: no part number comes first")


def _vec_sub(a: tuple[float, ...], b: tuple[float, ...]) -> tuple[float, ...]:
    return tuple(x - y for x, y in zip(a, b, strict=True))


def _norm(a: tuple[float, ...]) -> float:
    return math.sqrt(sum(x * x for x in a))


def _motion_end(m: Mapping[str, str], a: Mapping[str, Any]) -> tuple[float, ...] | None:
    kind = m["kind"]
    if kind in ("point", "line"):
        end = a[m["end"]]
        return end if _finite(end) else None
    start, center, normal, deg = a[m["start"]], a[m["center"]], a[m["normal"]], a[m["degrees"]]
    length = a[m["length"]] if kind == "helix" else 0.0
    if not all(_finite(v) for v in (start, center, normal, deg, length)):
        return None
    nn = _norm(normal)
    if nn == 0.0:
        return None
    k = tuple(x / nn for x in normal)
    v = _vec_sub(start, center)
    th = math.radians(deg)
    c, s = math.cos(th), math.sin(th)
    kxv = (k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2], k[0] * v[1] - k[1] * v[0])
    kdv = k[0] * v[0] + k[1] * v[1] + k[2] * v[2]
    rot = tuple(v[i] * c + kxv[i] * s + k[i] * kdv * (1.0 - c) for i in range(3))
    return tuple(center[i] + rot[i] + length * k[i] for i in range(3))


def _angle_deg(a: tuple[float, ...], b: tuple[float, ...]) -> float:
    cx = (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
    return math.degrees(math.atan2(_norm(cx), sum(x * y for x, y in zip(a, b, strict=True))))


def _records(out: _Out, buf: bytes, offsets: Sequence[int], version: str, profile: str,
             cutters: Cutters | None) -> None:
    c_seq, c_copy, c_size, c_chk = _one("sequence"), _one("code_copy"), _one("arg_size"), _one("arg_checksum")
    c_res, c_unknown = _one("reserved_byte"), _one("unknown_code")
    c_finite, c_cont, c_orient, c_shape = _one("finite"), _one("continuity"), _one("orientation"), _one("shape")
    c_cutter = _one("cutter_table") if cutters is not None else None
    avail = availability_checks()
    targeted: dict[str, list[tuple[dict[str, Any], tuple[str, ...]]]] = {}
    for kind in ("positive", "nonzero_vector", "range", "nondecreasing", "ordered"):
        for ch in T.checks_of(kind):
            for t in ch["targets"]:
                targeted.setdefault(t["command"], []).append((ch, tuple(t["args"])))
    prev: dict[tuple[str, str], float] = {}
    tol_pos, tol_deg, tol_cut = T.TOL["position_mm"], T.TOL["orientation_deg"], T.TOL["cutter_mm"]
    unpack_head = T.HEAD_STRUCT.unpack_from
    hs = T.HEAD_SIZE
    i_seq, i_code, i_copy, i_res, i_chk, i_size = T.I_SEQ, T.I_CODE, T.I_COPY, T.I_RES, T.I_CHK, T.I_SIZE
    alg = T.CHECKSUMS["fields"]["args"]["algorithm"]
    chk_width = T.ARG_CHECKSUM.size
    plain_sum = T.CHECKSUMS["algorithms"][alg] == "sum" and T.CHECKSUMS["coverages"][
        T.CHECKSUMS["fields"]["args"]["coverage"]] == [{"region": "args", "start": None, "end": None, "exclude": []}]
    mask = (1 << (8 * chk_width)) - 1
    mv = memoryview(buf)
    cur_pos: tuple[float, ...] | None = None
    cur_or: tuple[float, ...] | None = None
    shape_open: list[Any] | None = None  # [index, name, count, moves, offset]
    for i, off in enumerate(offsets):
        h = unpack_head(buf, off)
        code, nb = h[i_code], h[i_size]
        aoff = off + hs
        raw = mv[aoff:aoff + nb]
        if h[i_seq] != i & T.SEQ_MASK:
            out.add(c_seq, i, off + T.RECORD_FIELDS[i_seq].offset,
                    f"sequence number {h[i_seq]}, expected {i & T.SEQ_MASK}")
        if h[i_res] != 0:
            out.add(c_res, i, off + T.RECORD_FIELDS[i_res].offset, f"reserved byte is 0x{h[i_res]:02X}")
        if h[i_copy] != code:
            out.add(c_copy, i, off + T.RECORD_FIELDS[i_copy].offset,
                    f"code copy 0x{h[i_copy]:02X} differs from code 0x{code:02X}")
        want = (sum(raw) & mask) if plain_sum else _field_sum("args", buf, [], args=bytes(raw))
        if h[i_chk] != want:
            out.add(c_chk, i, off + T.ARG_CHECKSUM.offset, f"stored argument checksum {h[i_chk]}, computed {want}")
        cmd = T.BY_CODE.get(code)
        if cmd is None:
            out.add(c_unknown, i, off + T.RECORD_FIELDS[i_code].offset, f"unknown command code 0x{code:02X}")
            continue
        if not cmd.layouts_for(version):
            out.add(avail.get((version, cmd.name)), i, off + T.RECORD_FIELDS[i_code].offset,
                    f"{cmd.name} is not available in version {version}")
        cands = cmd.candidates(version)
        if not any(lay.size == nb and lay.accepted_under(profile) for lay in cands):
            sizes = sorted({lay.size for lay in cands if lay.accepted_under(profile)})
            out.add(c_size, i, off + T.RECORD_FIELDS[i_size].offset,
                    f"{cmd.name} with {nb} argument bytes; expected {' or '.join(map(str, sizes))}")
        lay = cmd.layout_for_size(version, nb)
        if lay is None:
            continue
        vals = lay.struct.unpack_from(buf, aoff)
        a: dict[str, Any] = {}
        j = 0
        for f in lay.args:
            if f.count > 1:
                a[f.name] = tuple(vals[j:j + f.count])
            else:
                a[f.name] = vals[j]
            j += f.count
            if f.kind == "string":
                _string_checks(out, a[f.name], i, aoff + f.offset, f"{cmd.name}.{f.name}")
            elif f.kind == "float" and not _finite(a[f.name]):
                out.add(c_finite, i, aoff + f.offset, f"{cmd.name}.{f.name} is not finite")
        for ch, names in targeted.get(cmd.name, ()):
            _targeted(out, ch, names, cmd.name, lay, a, i, aoff, prev)
        if c_cutter is not None and cmd.cutter and cutters is not None:
            _cutter(out, c_cutter, cmd, lay, a, i, aoff, cutters, tol_cut)
        m = cmd.motion
        if m is not None:
            if m["kind"] != "point" and cur_pos is not None:
                start = a[m["start"]]
                if _finite(start):
                    d = _norm(_vec_sub(start, cur_pos))
                    if d > tol_pos:
                        out.add(c_cont, i, aoff + lay.args[[f.name for f in lay.args].index(m["start"])].offset,
                                f"{cmd.name} starts {d:.6g} mm from the current position")
            cur_pos = _motion_end(m, a)
            if shape_open is not None:
                shape_open[3] += 1
        o = cmd.orientation
        if o is not None:
            if o["kind"] == "path" and cur_or is not None:
                s = a[o["start"]]
                if _finite(s) and _norm(s) > 0.0:
                    ang = _angle_deg(s, cur_or)
                    if ang > tol_deg:
                        out.add(c_orient, i, aoff, f"{cmd.name} starts {ang:.6g} deg from the current orientation")
            e = a[o["end"]]
            cur_or = e if _finite(e) and _norm(e) > 0.0 else None
        sh = cmd.shape
        if sh is not None:
            name, cnt = a[sh["name"]], a[sh["count"]]
            if sh["kind"] == "start":
                if shape_open is not None:
                    out.add(c_shape, i, off, f"{cmd.name} inside the open shape of record {shape_open[0]}")
                shape_open = [i, name, cnt, 0, off]
            else:
                if shape_open is None:
                    out.add(c_shape, i, off, f"{cmd.name} without an open shape")
                else:
                    si, sname, scnt, moves, _ = shape_open
                    if name != sname or cnt != scnt:
                        out.add(c_shape, i, off, f"{cmd.name} {_s(name)},{cnt} does not repeat record {si}'s "
                                                 f"{_s(sname)},{scnt}")
                    elif moves != scnt:
                        out.add(c_shape, i, off, f"shape {_s(sname)} encloses {moves} motion commands, declares {scnt}")
                    shape_open = None
    if shape_open is not None:
        out.add(c_shape, shape_open[0], shape_open[4], f"shape {_s(shape_open[1])} is never closed")


def _s(raw: bytes) -> str:
    return _value_of_string(raw).decode("latin-1")


def _targeted(out: _Out, ch: dict[str, Any], names: tuple[str, ...], cname: str, lay: T.LayoutInfo,
              a: dict[str, Any], i: int, aoff: int, prev: dict[tuple[str, str], float]) -> None:
    present = [n for n in names if n in a]
    kind = ch["kind"]
    if kind == "ordered":
        if len(present) == len(names) and all(_finite(a[n]) for n in names):
            vals = [a[n] for n in names]
            if any(x > y for x, y in zip(vals, vals[1:], strict=False)):
                out.add(ch, i, aoff, f"{cname}: {' <= '.join(f'{n}={a[n]:g}' for n in names)} does not hold")
        return
    for n in present:
        v = a[n]
        at = aoff + next(f.offset for f in lay.args if f.name == n)
        if kind == "positive":
            if _finite(v) and v <= 0:
                out.add(ch, i, at, f"{cname}.{n} is {v:g}, must be > 0")
        elif kind == "nonzero_vector":
            if _finite(v) and all(x == 0.0 for x in v):
                out.add(ch, i, at, f"{cname}.{n} has zero length")
        elif kind == "range":
            if _finite(v) and ((ch["min"] is not None and v < ch["min"]) or (ch["max"] is not None and v > ch["max"])):
                out.add(ch, i, at, f"{cname}.{n} is {v:g}, {range_text(ch)}")
        elif kind == "nondecreasing":
            if _finite(v):
                key = (ch["id"], f"{cname}.{n}")
                if key in prev and v < prev[key]:
                    out.add(ch, i, at, f"{cname}.{n} falls from {prev[key]:g} to {v:g}")
                prev[key] = v


def range_text(ch: Mapping[str, Any]) -> str:
    """How a value fails a range check; either bound may be absent from the spec."""
    lo, hi = ch["min"], ch["max"]
    if lo is not None and hi is not None:
        return f"outside {lo:g}..{hi:g}"
    return f"must be >= {lo:g}" if lo is not None else f"must be <= {hi:g}"


def _cutter(out: _Out, ch: dict[str, Any], cmd: T.CommandInfo, lay: T.LayoutInfo, a: dict[str, Any], i: int,
            aoff: int, cutters: Cutters, tol: float) -> None:
    role = cmd.cutter or {}
    name = _s(a[role["name"]])
    if name not in cutters:
        out.add(ch, i, aoff, f"cutter {name!r} is not in the cutter table")
        return
    length, radius = cutters[name]
    for key, ref in (("length", length), ("radius", radius)):
        v = a.get(role[key])
        if isinstance(v, float) and math.isfinite(v) and abs(v - ref) > tol:
            out.add(ch, i, aoff, f"cutter {name!r} {key} {v:g} mm, the table says {ref:g} mm")
