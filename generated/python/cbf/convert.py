"""`cbf convert`: move a file to another version of the format.

Everything version-specific comes from the model: which commands the
target version lacks (no layout for it), what a motion becomes (a command
the target has whose motion role is a plain line, with an orientation path
when the source has one), how arguments and header fields carry over (by
name), and where the format version is recorded (``sets.format_version``).

- A command the target lacks, with a curved motion (ARC*, CIRCLE*, HELIX*),
  becomes the fewest line segments that keep the chordal deviation within
  ``chord_tol``: n = ceil(angle / (2 acos(1 - tol / r))) for exact vertices,
  corrected by a bisection up to the same formula less the binary32
  rounding until the deviation measured along the true curve is within the
  tolerance (the inner vertices are rounded to binary32 away from the axis,
  which keeps the sagitta); a count beyond the count field is refused
  before any point is made. Each
  segment starts at the binary32 point the last one ended at; the first
  starts at the record's own start, an arc's last ends at its stored end.
  An orientation path is slerped (directions along the great circle, their
  lengths linearly) at the same parameters.
- A command the target has is copied byte for byte when its layout is the
  same, else argument by argument; an argument the source layout lacks is
  refused with its record unless ``fill`` names a value for it (a number,
  or ``position``: the tool position at that record).
- Shape counts grow by the segments added; the format version stamp is
  rewritten; the result must validate without error (encode refuses it
  otherwise) and fit the count field.
"""

from __future__ import annotations

import math
import struct
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, fields
from typing import Any

from . import geometry as G
from . import tables as T
from .errors import CbfError
from .fields import pack_args, unpack_args
from .model import Cbf, Record, new_header

_F32 = struct.Struct("<f")


class ConvertError(CbfError):
    """The file cannot be converted as asked (names the record and why)."""

    kind = "convert"


def f32(x: float) -> float:
    return float(_F32.unpack(_F32.pack(x))[0])


def f32v(v: G.Vec) -> G.Vec:
    return (f32(v[0]), f32(v[1]), f32(v[2]))


@dataclass(frozen=True)
class Conversion:
    model: Cbf
    source_version: str
    target_version: str
    chord_tol: float
    max_deviation: float  # mm, the largest chordal deviation introduced
    curves: int  # records replaced by line segments
    segments: int  # line records written for them
    filled: int  # --fill arguments used


# -- linearisation ---------------------------------------------------------------
def _rounding(points: Sequence[G.Vec]) -> float:
    """A bound on how far binary32 rounding moves a point of this size (half an ulp per axis)."""
    big = max((abs(x) for p in points for x in p), default=0.0)
    return math.sqrt(3.0) * big * 2.0 ** -24


def analytic_segments(angle: float, radius: float, tol: float) -> int:
    """The fewest chords of a circular arc of ``radius`` turning ``angle`` (rad) within ``tol``.

    Raises ConvertError, before any division by it, when the count cannot be computed: a chord
    step that rounds to nothing (a radius so large, or a tolerance so small, that tol / radius
    vanishes) or a count beyond any number (issue 36: an ARC of radius 1e14 mm was a
    ZeroDivisionError)."""
    if not (math.isfinite(angle) and math.isfinite(radius) and math.isfinite(tol)) or tol <= 0.0:
        raise ConvertError(f"has no computable segment count (angle {angle:g} rad, radius {radius:g} mm, "
                           f"tolerance {tol:g} mm)")
    if angle <= 0.0 or radius <= 0.0:
        return 1
    u = tol / radius
    x = 1.0 - u
    if x <= -1.0:
        step = 2.0 * math.pi
    elif x < 1.0:
        step = 2.0 * math.acos(x)
    else:  # u below the double's resolution at 1: acos(1 - u) = 2 asin(sqrt(u / 2)), which keeps it
        step = 4.0 * math.asin(math.sqrt(u / 2.0))
    if not (step > 0.0 and math.isfinite(angle / step)):
        raise ConvertError(f"has no computable segment count: a radius of {radius:g} mm leaves no chord step "
                           f"within {tol:g} mm")
    return max(1, math.ceil(angle / step - 1e-12))


def chord_deviation(curve: G.Curve, pts: Sequence[G.Vec], samples: int = 16) -> float:
    """The largest distance from the true curve (sampled ``samples`` times along each segment's
    stretch of it) to that segment: G.point_segment_distance(curve.at(t), a, b) in numpy, the same
    formulas in the same order, memory in proportion to the segments."""
    import numpy as np

    n = len(pts) - 1
    seg = np.asarray(pts, dtype=np.float64)
    t = (np.arange(n, dtype=np.float64)[:, None] + np.arange(samples + 1, dtype=np.float64)[None, :] / samples) / n
    if curve.curved:
        c, s = np.cos(curve.angle * t), np.sin(curve.angle * t)
        p = [curve.center[i] + curve.radius * (c * curve.e1[i] + s * curve.e2[i]) + t * curve.rise[i]
             for i in range(3)]
    else:
        p = [curve.start[i] + (curve.end[i] - curve.start[i]) * t for i in range(3)]
    a = [seg[:-1, i][:, None] for i in range(3)]
    ab = [seg[1:, i][:, None] - a[i] for i in range(3)]
    den = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2]
    pa = [p[i] - a[i] for i in range(3)]
    dots = pa[0] * ab[0] + pa[1] * ab[1] + pa[2] * ab[2]
    safe = np.where(den == 0.0, 1.0, den)
    u = np.where(den == 0.0, 0.0, np.clip(dots / safe, 0.0, 1.0))
    d = [p[i] - (a[i] + ab[i] * u) for i in range(3)]
    return float(np.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).max())


def _neighbours(x: float) -> tuple[float, ...]:
    """The binary32 values bracketing ``x`` (one when it is one)."""
    y = f32(x)
    if y == x:
        return (y,)
    import numpy as np

    return (y, float(np.nextafter(np.float32(y), np.float32(math.inf if x > y else -math.inf))))


def _outward(curve: G.Curve, t: float) -> G.Vec:
    """The binary32 point nearest p(t) that lies no nearer the axis than the curve.

    Rounding a vertex inwards would add to the chord's sagitta; outwards it
    costs at most the rounding itself, so the count stays the analytic one."""
    p = curve.at(t)
    axis_pt = G.add(curve.center, G.scale(curve.rise, t))
    k = G.cross(curve.e1, curve.e2)
    best: tuple[float, G.Vec] | None = None
    fallback: tuple[float, G.Vec] | None = None
    for x in _neighbours(p[0]):
        for y in _neighbours(p[1]):
            for z in _neighbours(p[2]):
                q = (x, y, z)
                d = G.norm(G.sub(q, p))
                rel = G.sub(q, axis_pt)
                radial = G.norm(G.sub(rel, G.scale(k, G.dot(rel, k))))
                if fallback is None or d < fallback[0]:
                    fallback = (d, q)
                if radial >= curve.radius and (best is None or d < best[0]):
                    best = (d, q)
    chosen = best or fallback
    assert chosen is not None
    return chosen[1]


def _outward_all(curve: G.Curve, ts: Sequence[float]) -> list[G.Vec]:
    """``_outward(curve, t)`` for every t, in numpy: p(t) as Curve.at gives it; of the binary32
    points bracketing it (one to eight), the nearest lying no nearer the axis than the curve (the
    nearest of all when none does). The same formulas in the same order as G.norm, G.dot: the
    same points, bit for bit, as the scalar loop, at a fraction of its time."""
    import numpy as np

    if not ts:
        return []
    p = np.array([curve.at(t) for t in ts], dtype=np.float64)  # (m, 3), exactly Curve.at
    tt = np.asarray(ts, dtype=np.float64)[:, None]
    axis_pt = np.asarray(curve.center)[None, :] + np.asarray(curve.rise)[None, :] * tt
    kx = G.cross(curve.e1, curve.e2)
    y = p.astype(np.float32)
    toward = np.where(p > y.astype(np.float64), np.float32(np.inf), np.float32(-np.inf)).astype(np.float32)
    other = np.where(y.astype(np.float64) == p, y, np.nextafter(y, toward)).astype(np.float64)
    choices = np.stack([y.astype(np.float64), other], axis=0)  # (2, m, 3)
    best_d = np.full(len(ts), np.inf)
    best_q = np.zeros_like(p)
    fall_d = np.full(len(ts), np.inf)
    fall_q = np.zeros_like(p)
    for ix in (0, 1):
        for iy in (0, 1):
            for iz in (0, 1):
                q = np.stack([choices[ix, :, 0], choices[iy, :, 1], choices[iz, :, 2]], axis=1)
                dq = q - p
                d = np.sqrt(dq[:, 0] * dq[:, 0] + dq[:, 1] * dq[:, 1] + dq[:, 2] * dq[:, 2])
                rel = q - axis_pt
                along = rel[:, 0] * kx[0] + rel[:, 1] * kx[1] + rel[:, 2] * kx[2]
                rad = rel - np.stack([kx[0] * along, kx[1] * along, kx[2] * along], axis=1)
                radial = np.sqrt(rad[:, 0] * rad[:, 0] + rad[:, 1] * rad[:, 1] + rad[:, 2] * rad[:, 2])
                nearer = d < fall_d
                fall_d = np.where(nearer, d, fall_d)
                fall_q = np.where(nearer[:, None], q, fall_q)
                ok = (radial >= curve.radius) & (d < best_d)
                best_d = np.where(ok, d, best_d)
                best_q = np.where(ok[:, None], q, best_q)
    chosen = np.where(np.isfinite(best_d)[:, None], best_q, fall_q)
    return [(float(q[0]), float(q[1]), float(q[2])) for q in chosen]


def _vertices(curve: G.Curve, n: int, exact_end: bool) -> list[G.Vec]:
    pts = [curve.start, *_outward_all(curve, [k / n for k in range(1, n)])]
    pts.append(curve.end if exact_end else _outward(curve, 1.0))
    return pts


def linearise(curve: G.Curve, tol: float, exact_end: bool) -> tuple[list[G.Vec], float]:
    """Binary32 points p0..pn of the fewest chords within ``tol``, and the deviation measured.

    p0 is the curve's start; pn its end as stored (``exact_end``) or rounded outwards. The count
    is decided before any point is made: the chord formula gives the fewest for exact vertices
    (n_lo; beyond the count field it is refused at once); when the binary32 vertices measure
    beyond ``tol`` there, the same formula for the tolerance less the share the rounding took is
    an upper bracket, and a bisection between them finds the fewest that measure within ``tol``:
    a handful of passes, whatever the gap (one segment at a time took one pass per segment)."""
    if not curve.curved:
        return [curve.start, curve.end if exact_end else f32v(curve.end)], 0.0
    limit = T.LIMITS["max_commands"]
    n_lo = analytic_segments(curve.angle, curve.radius, tol)
    if n_lo > limit:
        raise ConvertError(f"needs more than {limit} segments to stay within {tol} mm")
    margin = _rounding(G.curve_bounds(curve))
    if 2.0 * margin >= tol:
        raise ConvertError(f"a chord tolerance of {tol} mm is below the binary32 resolution here ({margin:.3g} mm)")

    def measured(n: int) -> tuple[list[G.Vec], float]:
        pts = _vertices(curve, n, exact_end)
        return pts, chord_deviation(curve, pts)

    first = measured(n_lo)
    if first[1] <= tol:
        return first
    # the rounding's share of the deviation at n_lo, as measured: the chord formula for the
    # tolerance less that share is the guess, an upper bracket; then bisect
    share = first[1] - curve.radius * (1.0 - math.cos(curve.angle / (2.0 * n_lo)))
    try:
        guess = analytic_segments(curve.angle, curve.radius, tol - share) if share < tol else limit
    except ConvertError:  # no count for what is left of the tolerance: the field's largest is the bracket
        guess = limit
    lo, hi = n_lo, min(max(guess, n_lo + 1), limit)  # lo fails; hi is to be measured
    step = max(1, hi - lo)
    while True:  # the upper bracket: the guess, then farther by doubling steps
        best = measured(hi)
        if best[1] <= tol:
            break
        if hi >= limit:
            raise ConvertError(f"needs more than {limit} segments to stay within {tol} mm")
        lo, hi, step = hi, min(hi + step, limit), 2 * step
    while hi - lo > 1:  # the fewest within tol between a failing and a passing count
        mid = (lo + hi) // 2
        got = measured(mid)
        if got[1] <= tol:
            hi, best = mid, got
        else:
            lo = mid
    return best


def slerp(a: G.Vec, b: G.Vec, t: float) -> G.Vec:
    """Directions along the great circle from a to b, lengths linearly (zero vectors: linearly)."""
    la, lb = G.norm(a), G.norm(b)
    if la == 0.0 or lb == 0.0:
        return G.add(G.scale(a, 1.0 - t), G.scale(b, t))
    ua, ub = G.scale(a, 1.0 / la), G.scale(b, 1.0 / lb)
    omega = math.atan2(G.norm(G.cross(ua, ub)), G.dot(ua, ub))
    length = la + (lb - la) * t
    if omega < 1e-12:
        u = G.add(G.scale(ua, 1.0 - t), G.scale(ub, t))
    elif math.pi - omega < 1e-9:
        # opposite directions: no unique great circle; turn about any axis normal to a
        axis = G.cross(ua, (1.0, 0.0, 0.0) if abs(ua[0]) < 0.9 else (0.0, 1.0, 0.0))
        axis = G.scale(axis, 1.0 / G.norm(axis))
        th = math.pi * t
        u = G.add(G.scale(ua, math.cos(th)), G.scale(G.cross(axis, ua), math.sin(th)))
    else:
        s = math.sin(omega)
        u = G.add(G.scale(ua, math.sin((1.0 - t) * omega) / s), G.scale(ub, math.sin(t * omega) / s))
    un = G.norm(u)
    return G.scale(u, length / un) if un else u


# -- the plan: what each command becomes -------------------------------------------
def _line_target(src: T.CommandInfo, version: str) -> tuple[T.CommandInfo, T.LayoutInfo] | None:
    """A command of ``version`` whose motion is a plain line, with an orientation path iff ``src`` has one."""
    want_path = bool(src.orientation and src.orientation["kind"] == "path")
    for c in T.COMMANDS:
        m = c.motion
        if not m or m["kind"] != "line" or "through" in m or not c.layouts_for(version):
            continue
        has_path = bool(c.orientation and c.orientation["kind"] == "path")
        # a layout whose every argument the segments give: the motion's start and end, the path's ends
        given = {m.get("start"), m.get("end")} | ({c.orientation.get("start"), c.orientation.get("end")}
                                                  if has_path and c.orientation else set())
        lay = next((x for x in c.layouts_for(version) if all(f.reserved or f.name in given for f in x.args)), None)
        if has_path == want_path and lay is not None:
            return c, lay
    return None


def _layout_in(cmd: T.CommandInfo, src: T.LayoutInfo, version: str, profile: str) -> T.LayoutInfo | None:
    lays = [lay for lay in cmd.layouts_for(version) if lay.accepted_under(profile)]
    for lay in lays:  # a layout with a repeated group is made once per n: the one of the record's n
        if (lay.variant == src.variant and lay.n == src.n) or lay.size == src.size:
            return lay
    return lays[0] if lays else None


def _same_shape(a: T.LayoutInfo, b: T.LayoutInfo) -> bool:
    return [(f.name, f.kind, f.offset, f.size) for f in a.args] == [(f.name, f.kind, f.offset, f.size) for f in b.args]


def _zero(f: T.FieldInfo) -> Any:
    if f.kind == "string":
        return ""
    if f.kind == "bytes":
        return bytes(f.size)
    if f.kind == "float":
        return (0.0,) * f.count if f.count > 1 else 0.0
    return 0


def _fill_value(f: T.FieldInfo, text: str, pos: G.Vec | None, where: str) -> Any:
    if text == "position":
        if f.kind != "float" or f.count != 3:
            raise ConvertError(f"{where}: --fill {f.name}=position needs a 3-vector argument")
        if pos is None:
            raise ConvertError(f"{where}: --fill {f.name}=position, but no motion precedes this record")
        return pos
    try:
        x = float(text)
    except ValueError:
        raise ConvertError(f"{where}: --fill {f.name}={text!r} is neither a number nor 'position'") from None
    if f.kind == "float":
        return (x,) * f.count if f.count > 1 else x
    if f.is_int and x.is_integer() and f.holds(int(x)):
        return int(x)
    raise ConvertError(f"{where}: --fill {f.name}={text!r} does not fit a {f.kind} argument")


def _carry(old: Any, src: T.LayoutInfo, dst: T.LayoutInfo, fill: Mapping[str, str], pos: G.Vec | None,
           where: str, used: set[str]) -> Any:
    have = {f.name: f for f in src.args}
    values: dict[str, Any] = {}
    for f in dst.args:
        g = have.get(f.name)
        if g is not None and (g.kind, g.count) == (f.kind, f.count) and (f.kind != "bytes" or g.size == f.size):
            v = getattr(old, f.name)
            if f.kind == "string" and len(v.encode("latin-1")) > f.size:
                raise ConvertError(f"{where}: {f.name} {v!r} is longer than the {f.size} bytes of version "
                                   f"{', '.join(sorted(dst.versions))}")
            values[f.name] = v
        elif f.reserved:
            values[f.name] = _zero(f)
        elif f.name in fill:
            values[f.name] = _fill_value(f, fill[f.name], pos, where)
            used.add(f.name)
        else:
            raise ConvertError(f"{where}: {dst.command} of version {', '.join(sorted(dst.versions))} needs "
                               f"{f.name}, which this layout lacks (give it with --fill {f.name}=VALUE)")
    for g in src.args:  # nothing may be dropped silently
        if g.name not in values and not g.reserved:
            raise ConvertError(f"{where}: {src.command} argument {g.name} has no place in the target layout")
    return dst.cls(**values)


def _header(model: Cbf, target: str) -> Any:
    src_info = T.HEADERS[T.VERSION_BY_ID[model.version_id].header]
    dst_info = T.HEADERS[T.VERSION_BY_ID[target].header]
    derived = T.DERIVED_ROLES
    by_role = {f.role: f for f in src_info.fields if f.role not in derived and f.role != "reserved"}
    by_name = {f.name: f for f in src_info.fields}
    values: dict[str, Any] = {}
    used: set[str] = set()
    for f in dst_info.fields:
        if f.role in derived:
            continue
        g = by_name.get(f.name) or by_role.get(f.role or "")
        if g is None or g.kind != f.kind:
            continue
        v = getattr(model.header, g.name)
        if f.kind == "string" and len(v.encode("latin-1")) > f.size:
            raise ConvertError(f"header: {g.name} ({len(v)} characters) does not fit the {f.size} bytes of "
                               f"{f.name} in version {target}", offset=g.offset)
        if f.kind == "bytes" and len(v) != f.size:
            continue
        values[f.name] = v
        used.add(g.name)
    for g in src_info.fields:
        if g.role in derived or g.name in used:
            continue
        v = getattr(model.header, g.name)
        if v not in ("", 0) and (g.kind != "bytes" or any(v)):
            raise ConvertError(f"header: {g.name} is not empty and has no place in version {target}", offset=g.offset)
    return new_header(target, **values)


def _stamp(cmd: T.CommandInfo, lay: T.LayoutInfo, raw: bytes, text: str) -> bytes | None:
    """``raw`` with the format version argument rewritten, or None when the command has none."""
    name = (cmd.sets or {}).get("format_version")
    if not isinstance(name, str):
        return None
    args = unpack_args(lay, raw)
    if getattr(args, name) == text:
        return None
    values = {f.name: getattr(args, f.name) for f in fields(args)}
    values[name] = text
    return pack_args(lay, lay.cls(**values))


def _target_version(to_version: str, chord_tol: float | None) -> float:
    """The chord tolerance, once the target version is known writable and the tolerance usable."""
    if to_version not in T.VERSION_BY_ID or not T.VERSION_BY_ID[to_version].writable:
        writable = ", ".join(v.id for v in T.VERSIONS if v.writable)
        raise ConvertError(f"version {to_version} cannot be written (writable: {writable})")
    tol = T.TOL["position_mm"] if chord_tol is None else chord_tol
    if not (math.isfinite(tol) and tol > 0.0):
        raise ConvertError(f"--chord-tol must be a positive number of mm, not {chord_tol}")
    return tol


class _Converter:
    """The records of one conversion, one at a time: what is carried, what is linearised, the open
    shape whose count grows with the segments added inside it, and the statistics."""

    def __init__(self, src_v: str, to_version: str, tol: float, fill: dict[str, str], profile: str) -> None:
        tv = T.VERSION_BY_ID[to_version]
        self.src_v, self.to_version, self.tol, self.fill, self.profile = src_v, to_version, tol, fill, profile
        self.stamp_text = f"{tv.major}.{tv.minor if tv.minor is not None else 0}"
        self.out: list[Record] = []
        self.shape_open: tuple[int, T.LayoutInfo] | None = None  # the open shape's start: output index, layout
        self.extra = 0  # segments added inside the open shape
        self.worst, self.curves, self.segments = 0.0, 0, 0
        self.filled: set[str] = set()
        self.pos: G.Vec | None = None

    def record(self, i: int, r: Record) -> None:
        where = f"record {i}"
        cmd = r.command
        if cmd is None:
            raise ConvertError(f"{where}: unknown command code 0x{r.code:02X}", offset=r.offset)
        src_lay = cmd.layout_for_size(self.src_v, len(r.raw_args))
        if src_lay is None:
            raise ConvertError(f"{where}: {cmd.name} of {len(r.raw_args)} argument bytes has no layout",
                               offset=r.offset)
        args = unpack_args(src_lay, r.raw_args)
        curve = G.curve_of(cmd.motion, args, self.pos) if cmd.motion else None
        if cmd.motion and curve is None:
            raise ConvertError(f"{where}: {cmd.name} has non-finite values or a zero axis", offset=r.offset)
        dst_lay = _layout_in(cmd, src_lay, self.to_version, self.profile)
        if dst_lay is not None:
            self._carry(where, r, cmd, src_lay, dst_lay, args)
            if curve is not None:
                self.pos = curve.end
        elif curve is not None:
            self._linearise(where, r, cmd, args, curve)
        else:
            raise ConvertError(f"{where}: {cmd.name} is not in version {self.to_version} and has no motion to "
                               f"carry over", offset=r.offset)

    def _carry(self, where: str, r: Record, cmd: T.CommandInfo, src_lay: T.LayoutInfo, dst_lay: T.LayoutInfo,
               args: Any) -> None:
        """A record the target version has: its arguments carried into the target's layout."""
        if _same_shape(src_lay, dst_lay):
            raw = r.raw_args
        else:
            raw = pack_args(dst_lay, _carry(args, src_lay, dst_lay, self.fill, self.pos, f"{where} ({cmd.name})",
                                            self.filled))
        raw = _stamp(cmd, dst_lay, raw, self.stamp_text) or raw
        rec = Record(code=cmd.code, raw_args=raw, reserved=r.reserved)
        if cmd.shape and cmd.shape["kind"] == "start":
            self.shape_open, self.extra = (len(self.out), dst_lay), 0
        elif cmd.shape and self.shape_open is not None:
            if self.extra:
                at, start_lay = self.shape_open
                self.out[at] = _grown(self.out[at], start_lay, self.extra, where)
                rec = _grown(rec, dst_lay, self.extra, where)
            self.shape_open = None
        self.out.append(rec)

    def _linearise(self, where: str, r: Record, cmd: T.CommandInfo, args: Any, curve: Any) -> None:
        """A motion the target version lacks: line segments of a line command it has."""
        target = _line_target(cmd, self.to_version)
        if target is None:
            raise ConvertError(f"{where}: {cmd.name} is not in version {self.to_version}, and no line command "
                               f"of it can carry its motion", offset=r.offset)
        motion = cmd.motion or {}
        try:
            pts, dev = linearise(curve, self.tol, "end" in motion)  # an arc ends exactly where it says
        except ConvertError as exc:  # name the record, as every other refusal does
            raise ConvertError(f"{where}: {cmd.name} {exc}; raise --chord-tol", offset=r.offset) from None
        if "through" in motion and not curve.curved:  # straight in binary32: its middle is still off
            dev = max(dev, G.line_distance(G.vec(getattr(args, motion["through"])), curve.start, curve.end))
        self.worst = max(self.worst, dev)
        self.curves += 1
        self.segments += len(pts) - 1
        if self.shape_open is not None:
            self.extra += len(pts) - 2
        try:
            self.out.extend(_segments(target, cmd, args, pts, r.reserved))
        except ConvertError as exc:  # the record and the reason
            raise ConvertError(f"{where}: {exc}", offset=r.offset) from None
        if len(self.out) > T.LIMITS["max_commands"]:
            raise ConvertError(f"{where}: the result passes {T.LIMITS['max_commands']} records, the most the "
                               f"count holds; raise --chord-tol", offset=r.offset)
        self.pos = pts[-1]


def convert(model: Cbf, to_version: str, *, chord_tol: float | None = None, fill: Mapping[str, str] | None = None,
            profile: str = "default") -> Conversion:
    """``model`` in version ``to_version``; raises ConvertError naming the record that cannot go."""
    tol = _target_version(to_version, chord_tol)
    src_v = model.version_id
    if model.trailing:
        raise ConvertError(f"{len(model.trailing)} trailing byte(s) after the last record; nothing to carry them")
    header = _header(model, to_version)
    c = _Converter(src_v, to_version, tol, dict(fill or {}), profile)
    for i, r in enumerate(model.records):
        c.record(i, r)
    if len(c.out) > T.LIMITS["max_commands"]:
        raise ConvertError(f"the result has {len(c.out)} records, at most {T.LIMITS['max_commands']} fit the count")
    unused = sorted(set(c.fill) - c.filled)
    if unused:
        raise ConvertError(f"--fill {unused[0]}: no record of this file needs it")
    return Conversion(Cbf(header, c.out), src_v, to_version, tol, c.worst, c.curves, c.segments, len(c.filled))


def _grown(rec: Record, lay: T.LayoutInfo, extra: int, where: str) -> Record:
    """A shape record (of layout ``lay``) whose count is grown by ``extra``."""
    c = rec.command
    assert c is not None and c.shape is not None
    name = c.shape["count"]
    a = unpack_args(lay, rec.raw_args)
    f = next(x for x in lay.args if x.name == name)
    n = int(getattr(a, name)) + extra
    if n >= 1 << (8 * f.elem_size):
        raise ConvertError(f"{where}: the shape would enclose {n} motions; its {f.name} field holds at most "
                           f"{(1 << (8 * f.elem_size)) - 1}; raise --chord-tol")
    values = {x.name: getattr(a, x.name) for x in fields(a)}
    values[name] = n
    return Record(code=rec.code, raw_args=pack_args(lay, lay.cls(**values)), reserved=rec.reserved)


def _segments(target: tuple[T.CommandInfo, T.LayoutInfo], src: T.CommandInfo, args: Any, pts: list[G.Vec],
              reserved: int) -> list[Record]:
    cmd, lay = target
    m = cmd.motion or {}
    o = cmd.orientation
    n = len(pts) - 1
    orients: list[G.Vec] = []
    if o and src.orientation:
        a = G.vec(getattr(args, src.orientation["start"]))
        b = G.vec(getattr(args, src.orientation["end"]))
        orients = [a] + [f32v(slerp(a, b, k / n)) for k in range(1, n)] + [b]
    recs = []
    for k in range(n):
        values: dict[str, Any] = {}
        for f in lay.args:
            if f.name == m.get("start"):
                values[f.name] = pts[k]
            elif f.name == m.get("end"):
                values[f.name] = pts[k + 1]
            elif o and f.name == o.get("start"):
                values[f.name] = orients[k]
            elif o and f.name == o.get("end"):
                values[f.name] = orients[k + 1]
            elif f.reserved:
                values[f.name] = _zero(f)
            else:
                raise ConvertError(f"{cmd.name}: argument {f.name} has no value when it carries a motion")
        recs.append(Record(code=cmd.code, raw_args=pack_args(lay, lay.cls(**values)), reserved=reserved))
    return recs
