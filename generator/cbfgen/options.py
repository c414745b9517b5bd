"""The rules of the option files (cutter tables, machine files) both tools read: option_files.yaml
beside this module, completed from the model (issue 28). One dict, emitted as the Python
runtime's cbf/option_files.json and as the C tool's macros, so the limits cannot drift.

A cutter table's columns are the keys of the spec's cutter role (``cutter: {name: name, length:
length, radius: radius}``): the one key naming a string argument is the cutter's name, each
other key a number of the table (a float argument) that check 6.1.2 compares within
tolerances.cutter_mm. A revision that gives the role another key gives the table another column;
no reader, kernel or test names a column itself."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

from .model import Command, Spec

RULES_PATH = Path(__file__).with_name("option_files.yaml")
NUMBER_GRAMMARS = ("rfc8259",)  # what both readers implement


@dataclass(frozen=True)
class CutterColumns:
    """The cutter table's columns: ``name`` the key of the cutter's name, ``values`` the number keys,
    in the order the spec writes the role (first the commands' first, then any key a later one adds)."""

    name: str
    values: tuple[str, ...]

    @property
    def all(self) -> tuple[str, ...]:
        return (self.name, *self.values)


def _kinds(cmd: Command, key: str) -> set[str]:
    """The kinds of the arguments a cutter role's key names, over the command's layouts (with their
    element counts: a vector is not one number)."""
    arg = (cmd.cutter or {})[key]
    return {f"{a.kind}x{a.count}" for lay in cmd.layouts if (a := lay.arg(arg)) is not None}


def cutter_columns(spec: Spec) -> CutterColumns:
    """The cutter table's columns, from the commands' cutter roles. Raises ValueError for a spec
    whose roles do not make a table (no cutter command, no string key or two, a key naming neither
    a string nor one float)."""
    cutters = [c for c in spec.commands if c.cutter]
    if not cutters:
        raise ValueError("no command of the spec names a cutter: a cutter table has nothing to check")
    keys: dict[str, set[str]] = {}
    for c in cutters:
        for key in c.cutter or {}:
            keys.setdefault(key, set()).update(_kinds(c, key))
    names = [k for k, kinds in keys.items() if kinds == {"stringx1"}]
    if len(names) != 1:
        raise ValueError(f"the cutter role needs one key naming a string argument (the cutter's name), has "
                         f"{len(names)}: {', '.join(names) or 'none'}")
    values = tuple(k for k in keys if k not in names)
    odd = [k for k in values if keys[k] != {"floatx1"}]
    if odd:
        raise ValueError(f"cutter role key {odd[0]} names a {'/'.join(sorted(keys[odd[0]]))} argument: a cutter "
                         f"table column is the name (a string) or one number (a float)")
    if not values:
        raise ValueError("the cutter role names no number: a cutter table has nothing to compare")
    return CutterColumns(names[0], values)


def option_rules(spec: Spec) -> dict[str, Any]:
    """The rules, with the spec's part: the cutter table's columns, the name's size and the value checks."""
    with RULES_PATH.open(encoding="utf-8") as fh:
        rules: dict[str, Any] = yaml.safe_load(fh)
    if rules.get("number") not in NUMBER_GRAMMARS:
        raise ValueError(f"{RULES_PATH}: number must be one of {', '.join(NUMBER_GRAMMARS)}")
    columns = cutter_columns(spec)
    if len(columns.all) > rules["cutter_table"]["max_columns"]:
        raise ValueError(f"{RULES_PATH}: cutter_table.max_columns is below the {len(columns.all)} columns of the "
                         f"spec's cutter role")
    cutters = [c for c in spec.commands if c.cutter]
    name_size = max(a.size for c in cutters for lay in c.layouts for a in lay.args
                    if a.name == (c.cutter or {})[columns.name])
    positive = {(t.command, a): ch.id for ch in spec.checks_of_kind("positive") for t in ch.targets for a in t.args}
    values = []
    for key in columns.values:
        check = next((positive[(c.name, role[key])] for c in cutters
                      if key in (role := c.cutter or {}) and (c.name, role[key]) in positive), None)
        values.append({"column": key, "positive": check is not None, "check": check or ""})
    rules["cutter_table"].update({
        "columns": list(columns.all),
        "name": columns.name,
        "max_name": name_size,
        "values": values,
    })
    return rules
