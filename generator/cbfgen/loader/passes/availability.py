"""Availability: every (version, command) pair without a layout is covered by exactly one gating
check (registry.CheckKind.gates), and a gating check covers only such pairs."""

from __future__ import annotations

from ...model import Check
from ...registry import CHECK_KINDS, loader_rules
from ..pipeline import State, define
from ..problems import Problems


@define("availability", "check", reads=("vids", "commands", "raw_checks", "checks"))
def AVAILABILITY(ctx: Problems, st: State) -> None:
    """Every (version, command) pair where the command has no layout is covered by exactly one
    availability check, and a check covers only such pairs: its findings name the right clause."""
    covered: dict[tuple[str, str], Check] = {}
    by_name = {c.name: c for c in st.commands}
    for ch in (c for c in st.checks if CHECK_KINDS[c.kind].gates):
        node = st.raw_checks[ch.id]
        for v, name in ((v, n) for v in ch.versions for n in ch.commands if n in by_name):
            if by_name[name].available_in(v):
                ctx.fail(node, f"check {ch.id}: {name} has a layout in version {v}, nothing to cover", "commands")
                continue
            other = covered.get((v, name))
            if other is not None:
                ctx.fail(node, f"check {ch.id}: {name} in version {v} is already covered by check "
                               f"{other.id} (line {other.line}); one check per command and version", "commands")
            covered[(v, name)] = ch
    for cmd in st.commands:
        if not any(cmd.available_in(v) for v in st.vids):
            ctx.at(cmd.line, f"{cmd.name} is available in no version")
            continue
        for v in st.vids:
            if not cmd.available_in(v) and (v, cmd.name) not in covered:
                ctx.at(cmd.line, f"{cmd.name} has no layout in version {v} and no availability check covers it "
                                 f"(name it in a check's commands)")


@define("machine-coverage", "check", reads=("commands", "machine", "checks"))
def MACHINE_COVERAGE(ctx: Problems, st: State) -> None:
    """Which arguments are positions comes from the model: every float vector argument whose unit
    is a box limit's unit (mm: points, starts, ends, centres) is targeted by that limit (in a check
    of a limited kind, registry.LoaderRules.limits)."""
    limited = [ch for ch in st.checks if loader_rules(ch.kind).limits]
    if not limited:
        return
    machine = st.machine
    names = {lim.name for lim in machine.limits}
    covered = {(t.command, a) for ch in limited for t in ch.targets
               if t.limit in names and machine.limit(t.limit).is_vector for a in t.args}
    for lim in (lim for lim in machine.limits if lim.is_vector):
        for cmd in st.commands:
            for lay in cmd.layouts:
                for a in lay.args:
                    if a.kind == "float" and a.count == len(lim.axes) and a.unit == lim.unit \
                            and (cmd.name, a.name) not in covered:
                        ctx.at(lay.line, f"{cmd.name}.{a.name} is a position ({a.count} x {a.unit}) that no "
                                         f"machine_limits target bounds by limit {lim.name}")
