"""`cbf stats`: what a toolpath does, read from the spec's roles.

Path length follows the true geometry of every motion (decision M1: arcs,
circles and helices by their arc length, not their chords); a move cuts when
the cutter is on (M2). A point-kind motion is a straight move from the
previous position.

Machining time, a model with stated limits: each move runs a trapezoidal
speed profile (accelerate at ``accel`` to the SPEED in force, cruise,
decelerate at ``decel``; a triangle when the move is too short to reach the
speed). With blending off (the default, DECEL_ON) every move starts and ends
at rest. With blending on (DECEL_OFF) a run of consecutive moves is one
profile: rest at its start and end, each move cruising at its own speed,
no slowing at the joints. Not modelled: corner or junction speed limits,
jerk, axis limits, orientation-only turns, dwell, tool changes, force
control (FCPARMS). Moves before the first speed are not timed (counted as
``untimed_moves``); without an acceleration a move is timed at constant speed.
"""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any

from . import geometry as G
from . import tables as T
from .model import Cbf

SCHEMA_VERSION = 1


@dataclass
class _Run:
    """Moves joined by blending: their length and cruise time, the speeds at both ends."""

    length: float = 0.0
    cruise: float = 0.0
    first: tuple[float, float | None] | None = None  # speed, accel at the start
    last: tuple[float, float | None] | None = None  # speed, decel at the end


def profile_time(length: float, speed: float, accel: float | None, decel: float | None) -> float:
    """Seconds for one rest-to-rest move of ``length`` mm (trapezoid, or triangle when short)."""
    if length <= 0.0:
        return 0.0
    if not accel or not decel:
        return length / speed
    ramp = speed * speed / (2 * accel) + speed * speed / (2 * decel)
    if length >= ramp:
        return length / speed + speed / (2 * accel) + speed / (2 * decel)
    peak = math.sqrt(2 * length * accel * decel / (accel + decel))
    return peak / accel + peak / decel


def _run_time(run: _Run) -> float:
    if run.first is None or run.last is None or run.length <= 0.0:
        return 0.0
    (v0, a), (v1, d) = run.first, run.last
    if not a or not d:
        return run.cruise
    ramp = v0 * v0 / (2 * a) + v1 * v1 / (2 * d)
    if run.length >= ramp:
        return run.cruise + v0 / (2 * a) + v1 / (2 * d)
    return profile_time(run.length, min(v0, v1), a, d)


def _label(cmd: T.CommandInfo, args: Any) -> str:
    """A record's name: its first string argument (the spec gives names first)."""
    lay = next(iter(cmd.layouts))
    for f in lay.args:
        if f.kind == "string" and hasattr(args, f.name):
            return str(getattr(args, f.name))
    return ""


def _r(x: float) -> float:
    return round(x, 6)


@dataclass
class Stats:
    version: str
    records: int
    commands: dict[str, int] = field(default_factory=dict)
    unknown_records: int = 0
    box: tuple[G.Vec, G.Vec] | None = None
    cutting_mm: float = 0.0
    moving_mm: float = 0.0
    time_s: float = 0.0
    timed_moves: int = 0
    untimed_moves: int = 0
    moves: int = 0
    shapes: list[dict[str, Any]] = field(default_factory=list)
    cutters: list[dict[str, Any]] = field(default_factory=list)
    phases: list[dict[str, Any]] = field(default_factory=list)
    checkpoints: list[dict[str, Any]] = field(default_factory=list)

    def as_dict(self) -> dict[str, Any]:
        box = None if self.box is None else {"min": [_r(x) for x in self.box[0]], "max": [_r(x) for x in self.box[1]]}
        return {
            "schema": SCHEMA_VERSION,
            "version": self.version,
            "records": self.records,
            "commands": dict(sorted(self.commands.items())),
            "unknown_records": self.unknown_records,
            "bounding_box_mm": box,
            "path_length_mm": {"cutting": _r(self.cutting_mm), "non_cutting": _r(self.moving_mm),
                               "total": _r(self.cutting_mm + self.moving_mm)},
            "time_s": {"estimate": round(self.time_s, 3), "moves": self.moves, "timed_moves": self.timed_moves,
                       "untimed_moves": self.untimed_moves},
            "shapes": self.shapes,
            "cutters": self.cutters,
            "phases": self.phases,
            "checkpoints": self.checkpoints,
        }


def stats(model: Cbf, steps: Iterable[G.Step] | None = None) -> Stats:
    """The stats of ``model``; ``steps`` is ``G.walk(model)`` when the caller has walked it already."""
    out = Stats(model.version_id, len(model.records))
    counts: Counter[str] = Counter()
    for r in model.records:
        counts[r.name or f"unknown 0x{r.code:02X}"] += 1
        if r.command is None:
            out.unknown_records += 1
    out.commands = dict(counts)
    lo: list[float] = []
    hi: list[float] = []
    run = _Run()
    open_shape: dict[str, Any] | None = None
    for step in G.walk(model) if steps is None else steps:
        cmd, a, st = step.cmd, step.args, step.state
        if cmd.shape:
            if cmd.shape["kind"] == "start":
                open_shape = {"name": str(getattr(a, cmd.shape["name"])), "record": step.index, "end_record": None,
                              "moves": int(getattr(a, cmd.shape["count"])), "length_mm": 0.0}
                out.shapes.append(open_shape)
            elif open_shape is not None:
                open_shape["end_record"] = step.index
                open_shape["length_mm"] = _r(open_shape["length_mm"])
                open_shape = None
        if cmd.cutter:
            out.cutters.append({"name": str(getattr(a, cmd.cutter["name"])), "record": step.index,
                                "length_mm": float(getattr(a, cmd.cutter["length"])),
                                "radius_mm": float(getattr(a, cmd.cutter["radius"]))})
        phase_arg = (cmd.sets or {}).get("phase")
        if isinstance(phase_arg, str):
            out.phases.append({"name": str(getattr(a, phase_arg)), "record": step.index})
        if cmd.progress:
            v = float(getattr(a, cmd.progress))
            out.checkpoints.append({"name": _label(cmd, a), "record": step.index,
                                    "progress": v if math.isfinite(v) else None})
        c = step.curve
        if c is None:
            continue
        b0, b1 = G.curve_bounds(c)
        lo = [min(x, y) for x, y in zip(lo or b0, b0, strict=True)]
        hi = [max(x, y) for x, y in zip(hi or b1, b1, strict=True)]
        length = c.length
        out.moves += 1
        if st.cutting:
            out.cutting_mm += length
        else:
            out.moving_mm += length
        if open_shape is not None:
            open_shape["length_mm"] += length
        if st.speed is None:
            out.untimed_moves += 1
            continue
        out.timed_moves += 1
        if not st.blending:
            out.time_s += _run_time(run)
            run = _Run()
            out.time_s += profile_time(length, st.speed, st.accel, st.decel)
            continue
        if run.first is None:
            run.first = (st.speed, st.accel)
        run.last = (st.speed, st.decel)
        run.length += length
        run.cruise += length / st.speed
    out.time_s += _run_time(run)
    if lo:
        out.box = ((lo[0], lo[1], lo[2]), (hi[0], hi[1], hi[2]))
    return out


def render(s: Stats, path: str) -> str:
    d = s.as_dict()
    lines = [f"file: {path}", f"version: {s.version}", f"records: {s.records}"]
    box = d["bounding_box_mm"]
    if box is None:
        lines.append("bounding box: none (no motion)")
    else:
        size = [round(b - a, 6) for a, b in zip(box["min"], box["max"], strict=True)]
        lines.append(f"bounding box (mm): min {box['min']} max {box['max']} size {size}")
    pl = d["path_length_mm"]
    lines.append(f"path length (mm): {pl['total']} = cutting {pl['cutting']} + non-cutting {pl['non_cutting']}")
    t = d["time_s"]
    lines.append(f"estimated time (s): {t['estimate']} ({t['timed_moves']} of {t['moves']} moves timed; "
                 f"trapezoidal profile per move, see cbf.stats)")
    lines.append("commands:")
    lines.extend(f"  {k}: {v}" for k, v in sorted(s.commands.items(), key=lambda kv: (-kv[1], kv[0])))
    for title, items, keys in (("shapes", s.shapes, ("moves", "end_record", "length_mm")),
                               ("cutters", s.cutters, ("length_mm", "radius_mm")),
                               ("phases", s.phases, ()),
                               ("checkpoints", s.checkpoints, ("progress",))):
        lines.append(f"{title}: {len(items)}")
        for it in items:
            extra = "".join(f", {k} {it[k]}" for k in keys)
            lines.append(f"  record {it['record']}: {it['name']!r}{extra}")
    return "\n".join(lines) + "\n"
