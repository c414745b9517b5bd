"""The rules of the option files (cutter tables, machine files) both tools read: option_files.yaml
beside this module, completed from the model (issue 28). One dict, emitted as the Python
runtime's cbf/option_files.json and as the C tool's macros, so the limits cannot drift."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import yaml

from .model import Spec

RULES_PATH = Path(__file__).with_name("option_files.yaml")
NUMBER_GRAMMARS = ("rfc8259",)  # what both readers implement


def option_rules(spec: Spec) -> dict[str, Any]:
    """The rules, with the spec's part: the cutter name's size and the cutter value checks."""
    with RULES_PATH.open(encoding="utf-8") as fh:
        rules: dict[str, Any] = yaml.safe_load(fh)
    if rules.get("number") not in NUMBER_GRAMMARS:
        raise ValueError(f"{RULES_PATH}: number must be one of {', '.join(NUMBER_GRAMMARS)}")
    cutters = [c for c in spec.commands if c.cutter]
    if not cutters:
        raise ValueError("no command of the spec names a cutter: a cutter table has nothing to check")
    name_size = max(a.size for c in cutters for lay in c.layouts for a in lay.args
                    if a.name == (c.cutter or {})["name"])
    positive = {(t.command, a): ch.id for ch in spec.checks_of_kind("positive") for t in ch.targets for a in t.args}
    values = []
    for key in ("length", "radius"):
        check = next((positive[(c.name, (c.cutter or {})[key])] for c in cutters
                      if (c.name, (c.cutter or {})[key]) in positive), None)
        values.append({"column": key, "positive": check is not None, "check": check or ""})
    rules["cutter_table"].update({
        "columns": ["name", "length", "radius"],
        "max_name": name_size,
        "values": values,
    })
    return rules
