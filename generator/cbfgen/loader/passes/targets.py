"""The targets of targeted checks: the arguments they read, and for a limited kind the limit."""

from __future__ import annotations

from ...model import Command, Machine
from ...registry import CHECK_KINDS, TYPES, loader_rules, role_arg_fits
from ..pipeline import State, define
from ..problems import Problems
from ..yaml_reader import Map
from .roles import require_arg


def _machine_target(ctx: Problems, t: Map, cmd: Command, machine: Machine, cid: str) -> None:
    """A limited kind's target: its limit exists, and every layout's argument of that name has the
    limit's unit and shape (a box bounds float vectors of as many components as it has axes)."""
    try:
        lim = machine.limit(str(t["limit"]))
    except KeyError:
        ctx.fail(t, f"check {cid}: unknown machine limit {t['limit']!r}", "limit")
        return
    for lay in cmd.layouts:
        for name in t["args"]:
            a = lay.arg(name)
            if a is None:
                continue
            shape_ok = a.kind == "float" and a.count == (len(lim.axes) if lim.axes else 1)
            if a.unit != lim.unit or not shape_ok:
                ctx.fail(t, f"check {cid}: {cmd.name}.{name} ({a.type} x{a.count}, unit {a.unit}) does not "
                            f"fit machine limit {lim.name} (unit {lim.unit}"
                            + (f", {len(lim.axes)} axes)" if lim.axes else ", a scalar)"), "args")
                return


def _shapes(ctx: Problems, t: Map, cmd: Command, cid: str, kname: str) -> None:
    """Each target argument has the shape the kind reads (registry.CheckKind.target_shape)."""
    want = CHECK_KINDS[kname].target_shape
    for argname in t["args"]:
        require_arg(ctx, t, cmd, argname, f"check {cid}")
        for lay in cmd.layouts:
            a = lay.arg(argname)
            if a is not None and want is not None and not role_arg_fits(want, TYPES[a.type], a.count):
                ctx.fail(t, f"check {cid}: {cmd.name}.{argname} is {a.type} x{a.count}; kind {kname} reads "
                            + ("one float" if want[1] == 1 else f"vectors of {want[1]} floats"), "args")
                break


@define("check-targets", "check", reads=("bare_commands", "machine", "raw_checks"))
def CHECK_TARGETS(ctx: Problems, st: State) -> None:
    """Each target names a command and arguments it has, each once, and no argument another target of
    the check names (a whole kind: no target twice) (a name twice made the bindings judge it a
    different number of times: spec-fuzz mutant 240 of seed 3601, and a machine_limits target twice
    mutant 194 of seed 2026120606), of the shape its kind reads, and names a machine limit exactly
    when its kind is limited (registry.LoaderRules.limits), one its arguments fit."""
    by_name = {c.name: c for c in st.bare_commands}
    for cid, ch in st.raw_checks.items():
        kname = ch["kind"]
        limited = loader_rules(kname).limits
        named: set[tuple[str, ...]] = set()
        for t in ch.get("targets", []):
            cmd = by_name.get(t["command"])
            if cmd is None:
                ctx.fail(t, f"check {cid}: unknown command {t['command']}", "command")
                continue
            twice = sorted({a for a in t["args"] if list(t["args"]).count(a) > 1})
            if twice:
                ctx.fail(t, f"check {cid}: target {cmd.name} names argument {twice[0]} twice", "args")
                continue
            mine = {(cmd.name, *t["args"])} if CHECK_KINDS[kname].whole else {(cmd.name, a) for a in t["args"]}
            again = sorted(mine & named)
            named |= mine
            if again:
                ctx.fail(t, f"check {cid}: {'.'.join(again[0][:2])}{'...' if len(again[0]) > 2 else ''} is "
                            f"named by another target of the check as well", "args")
                continue
            _shapes(ctx, t, cmd, cid, kname)
            if ("limit" in t) != limited:
                ctx.fail(t, f"check {cid}: a target names a limit exactly when its kind is machine_limits",
                         "limit" if "limit" in t else "command")
            elif "limit" in t:
                _machine_target(ctx, t, cmd, st.machine, cid)
