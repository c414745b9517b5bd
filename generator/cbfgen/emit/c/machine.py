"""C context of the machine limits (decision L1, check kind machine_limits; machine.h.j2).

Per layout, the rules the validator applies: the argument (its index in the layout), the
limit that bounds it and the check that reports it. A machine is a struct of ranges, one
per limit, one per axis for a box; the spec's default machine is a constant of cbf.h.
"""

from __future__ import annotations

from typing import Any

from ...model import MACHINE_FILE_KEYS, MACHINE_LIMIT_KEYS, Spec


def machine_context(spec: Spec, layouts: list[dict[str, Any]], cfloat: Any, macro: Any) -> dict[str, Any]:
    lims = spec.machine.limits
    axes = max([len(lim.axes) for lim in lims] + [1])
    names = [lim.name for lim in lims]
    limits = []
    for lim in lims:
        pad = axes - len(lim.min)
        limits.append({
            "name": lim.name, "macro": macro(lim.name), "unit": lim.unit, "naxes": len(lim.axes),
            "axes": list(lim.axes), "doc": lim.doc,
            "min": [cfloat(x) for x in lim.min] + ["0.0"] * pad, "max": [cfloat(x) for x in lim.max] + ["0.0"] * pad,
        })
    check_index = {ch.id: i for i, ch in enumerate(spec.checks)}
    # a value <= 0 of an argument a positive check targets is that check's (one fault, one finding)
    positive = {(t.command, a) for ch in spec.checks_of_kind("positive") for t in ch.targets for a in t.args}
    rules: list[dict[str, Any]] = []
    first: list[int] = []
    for lay in layouts:
        first.append(len(rules))
        for ch in spec.checks_of_kind("machine_limits"):
            for t in ch.targets:
                if t.command != lay["cmd_name"] or t.limit is None:
                    continue
                for name in t.args:
                    idx = next((i for i, a in enumerate(lay["args"]) if a["name"] == name), -1)
                    if idx >= 0:
                        arg = lay["args"][idx]
                        assert arg["kind"] == "FLOAT", f"{lay['macro']} {name}: a machine limit bounds floats only"
                        rules.append({
                            "offset": arg["offset"], "count": arg["count"],
                            "arg": idx, "limit": names.index(t.limit), "check": check_index[ch.id],
                            "given_error": int((ch.input_severity or ch.severity) == "error"),
                            "positive": int((t.command, name) in positive),
                            "text": f"{lay['macro']} {name}: {t.limit}",
                        })
    first.append(len(rules))
    assert all(r["count"] <= axes for r in rules), "a machine-limited argument has more components than a limit's axes"
    return {"machine_axes": axes, "machine_limits": limits,
            "machine_rules": rules or [{"offset": 0, "count": 0, "arg": -1, "limit": 0, "check": 0, "given_error": 0,
                                        "positive": 0, "text": "none"}],
            "machine_first": first, "machine_decision": spec.machine.decision,
            "machine_file_keys": list(MACHINE_FILE_KEYS), "machine_limit_keys": list(MACHINE_LIMIT_KEYS)}
