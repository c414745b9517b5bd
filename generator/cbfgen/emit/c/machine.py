"""C view of the machine limits (decision L1, check kind machine_limits; machine.h.j2).

Per layout, the rules the validator applies: the argument (its index in the layout), the
limit that bounds it and the check that reports it. A machine is a struct of ranges, one
per limit, one per axis for a box; the spec's default machine is a constant of cbf.h.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Protocol

from ...model import MACHINE_FILE_KEYS, MACHINE_LIMIT_KEYS, Spec


class ArgLike(Protocol):
    """What a machine rule reads of a layout's argument (views.FieldRow has it)."""

    @property
    def name(self) -> str: ...
    @property
    def kind(self) -> str: ...
    @property
    def offset(self) -> int: ...
    @property
    def count(self) -> int: ...


class LayoutLike(Protocol):
    """What the machine rules read of a layout (views.LayoutRow has it): this module imports no view."""

    @property
    def cmd_name(self) -> str: ...
    @property
    def macro(self) -> str: ...
    @property
    def args(self) -> Sequence[ArgLike]: ...


@dataclass(frozen=True)
class MachineLimitRow:
    """A limit as plain data (machine.h.j2 spells it: |macro, |cfloat)."""

    name: str
    unit: str
    naxes: int
    axes: tuple[str, ...]
    doc: str
    min: tuple[float, ...]  # padded with 0.0 to machine_axes
    max: tuple[float, ...]


@dataclass(frozen=True)
class MachineRule:
    offset: int
    count: int
    arg: int  # index in the layout
    limit: int
    check: int
    given_error: int
    positive: int  # a positive check targets the argument: a value <= 0 is that check's
    text: str


@dataclass(frozen=True)
class MachineView:
    """machine.h.j2, validator_layouts.c.j2, cbf_tools.h.j2."""

    machine_axes: int
    machine_limits: tuple[MachineLimitRow, ...]
    machine_rules: tuple[MachineRule, ...]  # one placeholder rule when there is none
    machine_first: tuple[int, ...]  # per layout, its first rule (and the end)
    machine_decision: str
    machine_file_keys: tuple[str, ...]
    machine_limit_keys: tuple[str, ...]


def machine_view(spec: Spec, layouts: Sequence[LayoutLike]) -> MachineView:
    lims = spec.machine.limits
    axes = max([len(lim.axes) for lim in lims] + [1])
    names = [lim.name for lim in lims]
    limits = tuple(MachineLimitRow(
        name=lim.name, unit=lim.unit, naxes=len(lim.axes), axes=tuple(lim.axes), doc=lim.doc,
        min=tuple(float(x) for x in lim.min) + (0.0,) * (axes - len(lim.min)),
        max=tuple(float(x) for x in lim.max) + (0.0,) * (axes - len(lim.max))) for lim in lims)
    check_index = {ch.id: i for i, ch in enumerate(spec.checks)}
    # a value <= 0 of an argument a positive check targets is that check's (one fault, one finding)
    positive = {(t.command, a) for ch in spec.checks_of_kind("positive") for t in ch.targets for a in t.args}
    rules: list[MachineRule] = []
    first: list[int] = []
    for lay in layouts:
        first.append(len(rules))
        for ch in spec.checks_of_kind("machine_limits"):
            for t in ch.targets:
                if t.command != lay.cmd_name or t.limit is None:
                    continue
                for name in t.args:
                    idx = next((i for i, a in enumerate(lay.args) if a.name == name), -1)
                    if idx >= 0:
                        arg = lay.args[idx]
                        assert arg.kind == "FLOAT", f"{lay.macro} {name}: a machine limit bounds floats only"
                        rules.append(MachineRule(
                            offset=arg.offset, count=arg.count, arg=idx, limit=names.index(t.limit),
                            check=check_index[ch.id], given_error=int((ch.input_severity or ch.severity) == "error"),
                            positive=int((t.command, name) in positive), text=f"{lay.macro} {name}: {t.limit}"))
    first.append(len(rules))
    assert all(r.count <= axes for r in rules), "a machine-limited argument has more components than a limit's axes"
    return MachineView(
        machine_axes=axes, machine_limits=limits,
        machine_rules=tuple(rules) or (MachineRule(offset=0, count=0, arg=-1, limit=0, check=0, given_error=0,
                                                   positive=0, text="none"),),
        machine_first=tuple(first), machine_decision=spec.machine.decision,
        machine_file_keys=tuple(MACHINE_FILE_KEYS), machine_limit_keys=tuple(MACHINE_LIMIT_KEYS))
