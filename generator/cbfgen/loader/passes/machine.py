"""The decisions (notes) and the default machine (L1) whose limits machine_limits checks name."""

from __future__ import annotations

from typing import Any

from ...model import Machine, MachineLimit, Note
from ..pipeline import State, define
from ..problems import Problems


@define("decisions", "resolve", reads=("raw",), produces=("decisions",))
def DECISIONS(ctx: Problems, st: State) -> None:
    """The decisions where the format's text is silent (notes by id)."""
    st.decisions = tuple(Note(d["id"], d["topic"], " ".join(str(d["decision"]).split()), str(d["evidence"]))
                         for d in st.raw["decisions"])


def _bound(ctx: Problems, node: Any, name: str, key: str, value: Any, axes: int | None) -> tuple[float, ...] | None:
    """A limit's min or max: a number, or (a box) a list of one number per axis."""
    if (axes is None) != (not isinstance(value, list)) or (axes is not None and len(value) != axes):
        ctx.fail(node, f"machine limit {name}: {key} must be "
                       + (f"a list of {axes} numbers (one per axis)" if axes else "a number"), key)
        return None
    return tuple(float(x) for x in (value if isinstance(value, list) else [value]))


@define("machine", "resolve", reads=("raw",), produces=("machine",))
def MACHINE(ctx: Problems, st: State) -> None:
    """The default machine's limits; a box has one bound per axis (a limit of another shape is
    refused and left out)."""
    m = st.raw["machine"]
    limits: list[MachineLimit] = []
    for name, lim in m["limits"].items():
        axes = tuple(str(a) for a in lim.get("axes", []))
        want = len(axes) if axes else None
        los = _bound(ctx, lim, name, "min", lim["min"], want)
        his = _bound(ctx, lim, name, "max", lim["max"], want)
        if los is not None and his is not None:
            limits.append(MachineLimit(str(name), str(lim["unit"]), los, his, axes, str(lim["doc"]).strip()))
    st.machine = Machine(str(m["decision"]), str(m["doc"]).strip(), tuple(limits))


@define("machine-limits", "check", reads=("raw", "machine", "decisions"))
def MACHINE_LIMITS(ctx: Problems, st: State) -> None:
    """Each limit's unit is a unit of the spec and its min does not exceed its max; the machine's
    decision is a decision of the spec."""
    m, units = st.raw["machine"], st.raw["units"]
    for name, lim in m["limits"].items():
        if lim["unit"] not in units:
            ctx.fail(lim, f"machine limit {name}: unknown unit {lim['unit']!r}", "unit")
    for built in st.machine.limits:
        if any(a > b for a, b in zip(built.min, built.max, strict=True)):
            ctx.fail(m["limits"][built.name], f"machine limit {built.name}: min exceeds max", "min")
    if st.machine.decision not in {d.id for d in st.decisions}:
        ctx.fail(m, f"machine: unknown decision {st.machine.decision!r}", "decision")
