"""Repeated argument groups (issue 25, point 3)."""

from __future__ import annotations

from ...model import Command, Field
from ...registry import CHECK_KINDS, NUMERIC_KINDS, REPEAT_MAX_SIZES, repeat_unsupported
from ..pipeline import State, define
from ..problems import Problems
from ..yaml_reader import Map


def _group(ctx: Problems, lay: Map, name: str, fixed: int, rep: Field, max_nb: int) -> None:
    """A repeated argument group: the last argument, of numbers (what CUT writes as n values or
    vectors), n in [min, max] with n = 0 allowed only beside fixed arguments (a record's arguments
    are never empty of meaning), and the largest nb within limits.max_arg_size."""
    assert rep.repeat is not None
    lo, hi = rep.repeat
    raw_rep = next((a for a in lay["args"] if a["name"] == rep.name), lay)
    if lo > hi:
        ctx.fail(raw_rep, f"{name} argument {rep.name}: repeat min {lo} exceeds max {hi}", "repeat")
    if lo == 0 and fixed == 0:
        ctx.fail(raw_rep, f"{name} argument {rep.name}: repeat min 0 with no fixed argument leaves nb = 0 "
                          f"ambiguous with a command that takes no arguments", "repeat")
    if rep.kind not in NUMERIC_KINDS:
        ctx.fail(raw_rep, f"{name} argument {rep.name}: only numbers repeat (type {rep.type})", "repeat")
    if hi - lo >= REPEAT_MAX_SIZES:
        ctx.fail(raw_rep, f"{name} argument {rep.name}: repeat min {lo} to max {hi} is {hi - lo + 1} sizes; the "
                          f"bindings generate a layout per size, at most {REPEAT_MAX_SIZES} "
                          f"(registry.REPEAT_MAX_SIZES)", "repeat")
    if fixed + rep.size * hi > max_nb:
        ctx.fail(raw_rep, f"{name} argument {rep.name}: {fixed} + {rep.size} x {hi} = {fixed + rep.size * hi} "
                          f"bytes exceeds limits.max_arg_size {max_nb}", "repeat")


@define("repeat-groups", "check", reads=("raw", "bare_commands"))
def REPEAT_GROUPS(ctx: Problems, st: State) -> None:
    """A repeated group's bounds: min <= max, n = 0 only beside fixed arguments, numbers only, and
    the largest record within limits.max_arg_size."""
    max_nb = int(st.raw["limits"]["max_arg_size"])
    for c, cmd in zip(st.raw["commands"], st.bare_commands, strict=True):
        for raw_lay, lay in zip(c["layouts"], cmd.layouts, strict=True):
            if lay.repeated is not None:
                _group(ctx, raw_lay, cmd.name, lay.size, lay.repeated, max_nb)


def _roles(cmd: Command) -> list[tuple[str, str]]:
    """What each role of the command names: (role.key, argument name)."""
    roles = [(f"{role}.{key}", arg) for role in ("motion", "orientation", "shape", "cutter")
             for key, arg in (getattr(cmd, role) or {}).items() if key != "kind"]
    roles += [(f"sets.{key}", arg) for key, arg in (cmd.sets or {}).items() if isinstance(arg, str)]
    roles += [("progress", cmd.progress)] if cmd.progress else []
    return roles


def _layouts(ctx: Problems, cmd: Command, gaps: tuple[str, ...]) -> None:
    for lay in cmd.layouts:
        for a in lay.args[:-1]:
            if a.repeat is not None:
                ctx.at(a.line, f"{cmd.name} argument {a.name}: only the last argument of a layout repeats")
        rep = lay.repeated
        if rep is None:
            continue
        if gaps:
            ctx.at(rep.line, f"{cmd.name} argument {rep.name}: a repeated argument group is not implemented by "
                             f"the binding(s) {', '.join(gaps)} (generator/cbfgen/registry.py REPEAT_BINDINGS)")
        for what, arg in _roles(cmd):
            point_end = what == "motion.end" and (cmd.motion or {}).get("kind") == "point"
            if arg == rep.name and not point_end:
                ctx.at(rep.line, f"{cmd.name}: {what} names the repeated argument {rep.name} (only a point "
                                 f"motion's end may: the group's last element)")


@define("repeat", "check", reads=("headers", "record", "commands", "checks"))
def REPEAT(ctx: Problems, st: State) -> None:
    """Only the last argument of a command layout repeats; a role reads one value, so only a point
    motion's end may name a group (its last element: where a polyline leaves the tool); every
    binding must carry groups; a check's target may be a group only where its kind judges items
    (registry CheckKind.items)."""
    for h in st.headers.values():
        for f in h.fields:
            if f.repeat is not None:
                ctx.at(f.line, f"header {h.id} field {f.name}: only a command's arguments repeat")
    for f in st.record.fields:
        if f.repeat is not None:
            ctx.at(f.line, f"record field {f.name}: only a command's arguments repeat")
    gaps = repeat_unsupported()
    for cmd in st.commands:
        _layouts(ctx, cmd, gaps)
    groups = {(cmd.name, lay.repeated.name) for cmd in st.commands for lay in cmd.layouts if lay.repeated is not None}
    judges = ", ".join(k.name for k in CHECK_KINDS.values() if k.items)
    for ch in (ch for ch in st.checks if not CHECK_KINDS[ch.kind].items):
        for t in ch.targets:
            for arg_name in (a for a in t.args if (t.command, a) in groups):
                ctx.at(ch.line, f"check {ch.id}: kind {ch.kind} targets the repeated argument group "
                                f"{t.command} {arg_name}; only {judges} judges a group, item by item")
