"""Toolpath geometry read from the spec's roles (decisions M1, M2).

Nothing here names a command: a command moves the tool when it has a
``motion`` role, turns an orientation when it has an ``orientation`` role,
opens a shape, names a cutter or sets machine state (``sets``) by its roles.

``curve_of`` turns one motion record into a ``Curve`` (a point, a straight
line, or a circular/helical arc with its true geometry); ``walk`` runs the
records of a file and yields each motion with the machine state in force.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from typing import Any

from . import tables as T
from .fields import unpack_args
from .model import Cbf

Vec = tuple[float, float, float]
# binary32 carries 24 bits: an ARC whose middle point lies within this fraction of its size of
# the line through its ends is straight in the values stored (no circle through it is computable)
_BINARY32_RESOLUTION = 2.0 ** -24
# At most this many points per curve for drawing: two full turns at 5 degrees. A circle drawn
# beyond a turn retraces itself (drawn as one turn and the rest); a helix of more turns is
# sampled evenly at this many points, so a plot is bounded whatever the sweep.
MAX_DRAW_POINTS = 145
TWO_PI = 2.0 * math.pi


def vec(x: Any) -> Vec:
    """A 3-vector argument as floats."""
    return (float(x[0]), float(x[1]), float(x[2]))


def sub(a: Vec, b: Vec) -> Vec:
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def add(a: Vec, b: Vec) -> Vec:
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def scale(a: Vec, s: float) -> Vec:
    return (a[0] * s, a[1] * s, a[2] * s)


def dot(a: Vec, b: Vec) -> float:
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a: Vec, b: Vec) -> Vec:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a: Vec) -> float:
    return math.sqrt(dot(a, a))


def finite(*vs: Any) -> bool:
    for v in vs:
        if isinstance(v, tuple):
            if not all(math.isfinite(x) for x in v):
                return False
        elif not math.isfinite(v):
            return False
    return True


def motion_end(m: dict[str, str] | Any, a: dict[str, Any] | Any) -> tuple[float, ...] | None:
    """Where a motion record leaves the tool (the arguments ``a`` by name, its motion role
    ``m``), computed as the validator's continuity check does; None when not finite."""
    kind = m["kind"]
    if kind in ("point", "line"):
        end = a[m["end"]]
        if end and isinstance(end[0], tuple):  # a repeated group (a polyline): its last point
            end = end[-1]
        return tuple(end) if finite(end) else None
    start, center, normal, deg = a[m["start"]], a[m["center"]], a[m["normal"]], a[m["degrees"]]
    length = a[m["length"]] if kind == "helix" else 0.0
    if not finite(start, center, normal, deg, length):
        return None
    nn = math.sqrt(sum(x * x for x in normal))
    if nn == 0.0:
        return None
    k = tuple(x / nn for x in normal)
    v = tuple(x - y for x, y in zip(start, center, strict=True))
    th = math.radians(deg)
    c, s = math.cos(th), math.sin(th)
    kxv = (k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2], k[0] * v[1] - k[1] * v[0])
    kdv = k[0] * v[0] + k[1] * v[1] + k[2] * v[2]
    rot = tuple(v[i] * c + kxv[i] * s + k[i] * kdv * (1.0 - c) for i in range(3))
    return tuple(center[i] + rot[i] + length * k[i] for i in range(3))


def point_segment_distance(p: Vec, a: Vec, b: Vec) -> float:
    ab = sub(b, a)
    den = dot(ab, ab)
    t = 0.0 if den == 0.0 else max(0.0, min(1.0, dot(sub(p, a), ab) / den))
    return norm(sub(p, add(a, scale(ab, t))))


def line_distance(p: Vec, a: Vec, b: Vec) -> float:
    """The distance from p to the line through a and b (to a when they coincide)."""
    ab = sub(b, a)
    den = dot(ab, ab)
    if den == 0.0:
        return norm(sub(p, a))
    return norm(sub(sub(p, a), scale(ab, dot(sub(p, a), ab) / den)))


@dataclass(frozen=True, slots=True)
class Curve:
    """A motion's path p(t), t in [0, 1].

    Straight when ``radius`` is 0: p(t) = start + t (end - start). Otherwise
    p(t) = center + radius (cos(angle t) e1 + sin(angle t) e2) + t rise, with
    e1, e2 orthonormal and angle >= 0 (M1: right-hand rule about the axis).
    """

    start: Vec
    end: Vec
    center: Vec = (0.0, 0.0, 0.0)
    e1: Vec = (0.0, 0.0, 0.0)
    e2: Vec = (0.0, 0.0, 0.0)
    radius: float = 0.0
    angle: float = 0.0
    rise: Vec = (0.0, 0.0, 0.0)

    @property
    def curved(self) -> bool:
        return self.radius > 0.0 and self.angle > 0.0

    def at(self, t: float) -> Vec:
        if not self.curved:
            return add(self.start, scale(sub(self.end, self.start), t))
        th = self.angle * t
        c, s = math.cos(th), math.sin(th)
        return (self.center[0] + self.radius * (c * self.e1[0] + s * self.e2[0]) + t * self.rise[0],
                self.center[1] + self.radius * (c * self.e1[1] + s * self.e2[1]) + t * self.rise[1],
                self.center[2] + self.radius * (c * self.e1[2] + s * self.e2[2]) + t * self.rise[2])

    @property
    def length(self) -> float:
        if not self.curved:
            return norm(sub(self.end, self.start))
        return math.hypot(self.radius * self.angle, norm(self.rise))

    def points(self, max_step_deg: float = 5.0) -> list[Vec]:
        """Points along the curve for drawing: every ``max_step_deg`` degrees of turn, at most
        MAX_DRAW_POINTS whatever the sweep (a circle of many turns: one turn, then on to its end)."""
        if not self.curved:
            return [self.start, self.end]
        step = math.radians(max_step_deg)
        if self.rise == (0.0, 0.0, 0.0) and self.angle > TWO_PI:
            turn = max(1, math.ceil(TWO_PI / step))
            rest = math.fmod(self.angle, TWO_PI)
            tail = max(1, math.ceil(rest / step))
            return ([self._turned(TWO_PI * k / turn) for k in range(turn)]
                    + [self._turned(rest * k / tail) for k in range(tail)] + [self.end])
        n = max(1, min(MAX_DRAW_POINTS - 1, math.ceil(math.degrees(self.angle) / max_step_deg)))
        return [self.at(k / n) for k in range(n + 1)]

    def _turned(self, th: float) -> Vec:
        """The point of a flat circle (no rise) at turn ``th``."""
        c, s = math.cos(th), math.sin(th)
        return (self.center[0] + self.radius * (c * self.e1[0] + s * self.e2[0]),
                self.center[1] + self.radius * (c * self.e1[1] + s * self.e2[1]),
                self.center[2] + self.radius * (c * self.e1[2] + s * self.e2[2]))


def _circular(start: Vec, center: Vec, normal: Vec, degrees: float, length: float) -> Curve | None:
    nn = norm(normal)
    if nn == 0.0:
        return None
    k = scale(normal, 1.0 / nn)
    rise = scale(k, length)
    v = sub(start, center)
    par = scale(k, dot(v, k))
    perp = sub(v, par)
    r = norm(perp)
    th = math.radians(degrees)
    axis_pt = add(center, par)
    if r == 0.0 or th == 0.0:
        end = add(start, rise)
        return Curve(start, end)
    if th < 0.0:  # a negative turn about k is a positive turn about -k
        k, th = scale(k, -1.0), -th
    e1 = scale(perp, 1.0 / r)
    e2 = cross(k, e1)
    c = Curve(start, start, axis_pt, e1, e2, r, th, rise)
    return Curve(start, c.at(1.0), axis_pt, e1, e2, r, th, rise)


def _through(start: Vec, mid: Vec, end: Vec) -> Curve:
    u, w = sub(mid, start), sub(end, start)
    n = cross(u, w)
    n2 = dot(n, n)
    big = max(abs(x) for x in (*start, *mid, *end))
    if n2 == 0.0 or line_distance(mid, start, end) <= _BINARY32_RESOLUTION * big:
        # collinear (M1), or so nearly that the stored values cannot tell: straight. Anything
        # further off is a circle, however large: convert judges it against its tolerance.
        return Curve(start, end)
    # circumcentre of start, mid, end
    rel = scale(cross(sub(scale(w, dot(u, u)), scale(u, dot(w, w))), n), 1.0 / (2.0 * n2))
    center = add(start, rel)
    k = scale(n, 1.0 / math.sqrt(n2))  # start -> mid -> end runs anticlockwise about k
    a = sub(start, center)
    r = norm(a)
    e1 = scale(a, 1.0 / r)
    e2 = cross(k, e1)
    b = sub(end, center)
    th = math.atan2(dot(b, e2), dot(b, e1))
    if th <= 0.0:
        th += 2.0 * math.pi
    return Curve(start, end, center, e1, e2, r, th)


def curve_of(motion: dict[str, str], args: Any, pos: Vec | None) -> Curve | None:
    """The path of a motion record, or None when its values are not finite or its axis is zero.

    A point-kind motion runs straight from ``pos`` (the tool's position) when
    there is one; it has no path otherwise."""
    kind = motion["kind"]

    def get(key: str) -> Any:
        return getattr(args, motion[key])

    if kind == "point":
        got = get("end")
        end = vec(got[-1] if got and isinstance(got[0], tuple) else got)  # a polyline: its last point
        if not finite(end):
            return None
        return Curve(pos if pos is not None else end, end)
    if kind == "line":
        start, end = vec(get("start")), vec(get("end"))
        if "through" in motion:
            mid = vec(get("through"))
            if not finite(start, mid, end):
                return None
            return _through(start, mid, end)
        return Curve(start, end) if finite(start, end) else None
    start, center, normal = vec(get("start")), vec(get("center")), vec(get("normal"))
    deg = float(get("degrees"))
    length = float(get("length")) if "length" in motion else 0.0
    if not finite(start, center, normal, deg, length):
        return None
    return _circular(start, center, normal, deg, length)


# -- the machine state (M2) ------------------------------------------------------
_SPEED_UNITS = {"m/s": 1000.0, "mm/s": 1.0}
_ACCEL_UNITS = {"m/s^2": 1000.0, "mm/s^2": 1.0}


@dataclass(frozen=True, slots=True)
class State:
    cutting: bool = False
    blending: bool = False
    speed: float | None = None  # mm/s
    accel: float | None = None  # mm/s^2
    decel: float | None = None  # mm/s^2
    phase: str | None = None
    shape: str | None = None
    cutter: str | None = None


@dataclass(frozen=True, slots=True)
class Step:
    """One record seen by ``walk``: its index and command; the motion's curve when it moves."""

    index: int
    cmd: T.CommandInfo
    args: Any
    state: State
    curve: Curve | None = None


def _units() -> dict[tuple[int, str, str], str | None]:
    """The unit the spec gives each argument, by (command code, layout variant, argument name):
    spec_data keeps it, FieldInfo does not. The first the spec lists wins."""
    units: dict[tuple[int, str, str], str | None] = {}
    for c in T.SPEC["commands"]:
        for sl in c["layouts"]:
            for arg in sl["args"]:
                units.setdefault((c["code"], sl["variant"], arg["name"]), str(arg["unit"]) if arg.get("unit") else None)
    return units


_ARG_UNITS = _units()


def _arg_unit(cmd: T.CommandInfo, lay: T.LayoutInfo, argname: str) -> str | None:
    """The unit the spec gives an argument (spec_data keeps it; FieldInfo does not)."""
    return _ARG_UNITS.get((cmd.code, lay.variant, argname))


def _scaled(cmd: T.CommandInfo, lay: T.LayoutInfo, argname: str, value: Any, units: dict[str, float]) -> float | None:
    v = float(value)
    if not math.isfinite(v) or v <= 0.0:
        return None
    return v * units.get(_arg_unit(cmd, lay, argname) or "", 1.0)


def walk(model: Cbf) -> Iterator[Step]:
    """Every record of ``model`` with decodable arguments, in order, with the state in force at it."""
    vid = model.version_id
    st = State()
    pos: Vec | None = None
    for i, r in enumerate(model.records):
        cmd = r.command
        if cmd is None:
            continue
        lay = cmd.layout_for_size(vid, len(r.raw_args))
        if lay is None:
            continue
        a = unpack_args(lay, r.raw_args)  # r.decode_args(vid), without finding lay again
        changes: dict[str, Any] = {}
        for key, val in (cmd.sets or {}).items():
            if isinstance(val, bool):
                changes[key] = val
            elif key == "phase":
                changes[key] = str(getattr(a, val))
            elif key == "speed":
                changes[key] = _scaled(cmd, lay, val, getattr(a, val), _SPEED_UNITS)
            elif key in ("accel", "decel"):
                changes[key] = _scaled(cmd, lay, val, getattr(a, val), _ACCEL_UNITS)
        if cmd.cutter:
            changes["cutter"] = str(getattr(a, cmd.cutter["name"]))
        if cmd.shape:
            changes["shape"] = str(getattr(a, cmd.shape["name"])) if cmd.shape["kind"] == "start" else None
        if changes:
            fields = {f: getattr(st, f) for f in State.__slots__}
            fields.update({k: v for k, v in changes.items() if k in fields})
            st = State(**fields)
        curve = None
        if cmd.motion is not None:
            curve = curve_of(cmd.motion, a, pos)
            pos = curve.end if curve is not None else None
        yield Step(i, cmd, a, st, curve)


def bounds(points: Sequence[Vec]) -> tuple[Vec, Vec] | None:
    if not points:
        return None
    lo = tuple(min(p[i] for p in points) for i in range(3))
    hi = tuple(max(p[i] for p in points) for i in range(3))
    return (lo[0], lo[1], lo[2]), (hi[0], hi[1], hi[2])


def curve_bounds(c: Curve) -> tuple[Vec, Vec]:
    """The exact axis-aligned box of a curve, found analytically whatever its sweep: its ends,
    and per axis the turns where that coordinate is stationary. Coordinate i is
    center_i + radius A cos(th - phi) + (th / angle) rise_i, stationary where
    sin(th - phi) = rise_i / (angle radius A): two families of turns a full turn apart, and along
    each family the value moves by a constant step, so its first and last member in [0, angle]
    are the family's extremes (no sampling, whatever the number of turns)."""
    s, e = c.start, c.end
    if not c.curved:  # bounds([s, e]), without the generic loops (every move of a straight path)
        return ((min(s[0], e[0]), min(s[1], e[1]), min(s[2], e[2])),
                (max(s[0], e[0]), max(s[1], e[1]), max(s[2], e[2])))
    lo, hi = [min(s[i], e[i]) for i in range(3)], [max(s[i], e[i]) for i in range(3)]
    for i in range(3):
        amp = c.radius * math.hypot(c.e1[i], c.e2[i])
        if amp == 0.0:
            continue
        phi = math.atan2(c.e2[i], c.e1[i])
        ratio = c.rise[i] / (c.angle * amp)
        if abs(ratio) > 1.0:  # the rise outruns the turn: monotonic, the ends bound it
            continue
        shift = math.asin(ratio)
        for base in (phi + shift, phi + math.pi - shift):
            first = math.ceil(-base / TWO_PI)
            last = math.floor((c.angle - base) / TWO_PI)
            for k in {first, last} if first <= last else ():
                th = min(max(base + TWO_PI * k, 0.0), c.angle)
                x = c.at(th / c.angle)[i]
                lo[i], hi[i] = min(lo[i], x), max(hi[i], x)
    return (lo[0], lo[1], lo[2]), (hi[0], hi[1], hi[2])
