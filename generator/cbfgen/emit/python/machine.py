"""The machine limits (decision L1) as runtime data and as the JSON Schema of a machine file.

A machine file has the shape of the spec's ``machine:`` block: ``limits`` with, for every
limit of the spec, its ``unit`` (which must be the spec's: a file in other units is refused),
``min`` and ``max`` (a number, or one number per axis for a box); ``name``, ``doc``,
``decision`` and a limit's ``doc`` and ``axes`` are optional.
"""

from __future__ import annotations

from typing import Any

from ...model import MACHINE_FILE_KEYS, MACHINE_LIMIT_KEYS, MachineLimit, Spec

SCHEMA_ID = "https://cbf-toolkit.invalid/machine.schema.json"


def _bound(lim: MachineLimit, values: tuple[float, ...]) -> float | list[float]:
    return list(values) if lim.is_vector else values[0]


def machine_data(spec: Spec) -> dict[str, Any]:
    """The default machine, in the shape a machine file has (so the default is a valid file)."""
    m = spec.machine
    return {
        "decision": m.decision,
        "doc": m.doc,
        "limits": {
            lim.name: {"unit": lim.unit, **({"axes": list(lim.axes)} if lim.axes else {}),
                       "min": _bound(lim, lim.min), "max": _bound(lim, lim.max), "doc": lim.doc}
            for lim in m.limits
        },
    }


def machine_schema(spec: Spec) -> dict[str, Any]:
    """JSON Schema of a machine file (`cbf validate --machine FILE`), from the model."""
    number: dict[str, Any] = {"type": "number"}

    def bound(lim: MachineLimit) -> dict[str, Any]:
        if not lim.is_vector:
            return number
        return {"type": "array", "items": number, "minItems": len(lim.axes), "maxItems": len(lim.axes)}

    limits = {}
    for lim in spec.machine.limits:
        props: dict[str, Any] = {"unit": {"type": "string", "const": lim.unit}, "min": bound(lim), "max": bound(lim),
                                 "doc": {"type": "string"}}
        if lim.is_vector:
            props["axes"] = {"type": "array", "items": {"type": "string"}, "const": list(lim.axes)}
        props = {k: props[k] for k in MACHINE_LIMIT_KEYS if k in props}
        limits[lim.name] = {"type": "object", "additionalProperties": False, "required": ["unit", "min", "max"],
                            "properties": props, "description": lim.doc}
    top: dict[str, Any] = {"name": {"type": "string"}, "doc": {"type": "string"}, "decision": {"type": "string"},
                           "limits": {"type": "object", "additionalProperties": False, "required": list(limits),
                                      "properties": limits}}
    return {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "$id": SCHEMA_ID,
        "title": f"CBF machine limits ({spec.revision}, decision {spec.machine.decision})",
        "description": "A machine file for `cbf validate --machine FILE` and `cbf-c validate --machine FILE`: "
                       "every limit of the spec, in the spec's units; min <= max (checked beyond this schema).",
        "type": "object",
        "additionalProperties": False,
        "required": ["limits"],
        "properties": {k: top[k] for k in MACHINE_FILE_KEYS},
    }
