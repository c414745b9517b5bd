"""The roles of each command (motion, orientation, shape, cutter, sets, progress): what they name."""

from __future__ import annotations

from typing import Any

from ...model import Command
from ...registry import ROLE_ARGS, ROLE_NEEDS, TYPES, RoleArg, role_arg_fits
from ..pipeline import State, define
from ..problems import Problems

_SHAPES = {"float": "a float", "string": "a string", "integer": "an integer"}


def require_arg(ctx: Problems, node: Any, cmd: Command, argname: str, what: str, want: RoleArg | None = None) -> None:
    """An argument a role or a check names: some layout has it, and (``want``) each layout that has it
    gives it the shape the role reads (registry.ROLE_ARGS)."""
    args = [a for lay in cmd.layouts if (a := lay.arg(argname)) is not None]
    if not args:
        ctx.fail(node, f"{cmd.name}: {what} names {argname!r}, which no layout has")
    for a in args:
        if want is not None and not role_arg_fits(want, TYPES[a.type], a.count):
            shape = _SHAPES[want[0]] if want[0] != "float" or want[1] == 1 else f"a vector of {want[1]} floats"
            ctx.at(a.line, f"{cmd.name}: {what} names {argname} ({a.type} x{a.count}), which must be {shape}")
            break


def _needs(ctx: Problems, node: Any, cmd: Command) -> None:
    """Each kinded role names every key its kind needs (registry.ROLE_NEEDS, the one list)."""
    for role, needs in ROLE_NEEDS.items():
        value: dict[str, str] | None = getattr(cmd, role)
        if not value:
            continue
        for key in needs[value["kind"]]:
            if key not in value:
                ctx.fail(node, f"{cmd.name}: {role} kind {value['kind']} needs {key}", role)


@define("roles", "check", reads=("raw", "bare_commands"))
def ROLES(ctx: Problems, st: State) -> None:
    """Each argument a role names exists in some layout with the shape the role reads
    (registry.ROLE_ARGS), and each kinded role names every key its kind needs (registry.ROLE_NEEDS)."""
    for c, cmd in zip(st.raw["commands"], st.bare_commands, strict=True):
        for role in ("motion", "orientation", "shape", "cutter"):
            for key, argname in (getattr(cmd, role) or {}).items():
                if key != "kind":
                    require_arg(ctx, c, cmd, argname, f"{role}.{key}", ROLE_ARGS[role].get(key))
        for key, value in (cmd.sets or {}).items():
            if isinstance(value, str):
                require_arg(ctx, c, cmd, value, f"sets.{key}", ROLE_ARGS["sets"].get(key))
        if cmd.progress:
            require_arg(ctx, c, cmd, cmd.progress, "progress", ROLE_ARGS["progress"][""])
        _needs(ctx, c, cmd)
