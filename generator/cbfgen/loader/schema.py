"""The first gate: the JSON Schema (spec.schema.json) for shape, its vocabulary enums filled from
the registry and the model. The semantic passes need the shape, so they wait for it."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import jsonschema

from ..registry import ALGORITHMS, CHECK_KINDS, FIELD_KINDS, ROLE_KINDS, SEVERITIES, TYPES
from .problems import Problem
from .yaml_reader import Map, line_of_path

SCHEMA_PATH = Path(__file__).parent.parent / "spec.schema.json"


def schema() -> dict[str, Any]:
    """spec.schema.json with its vocabulary enums filled from the registry (field types, type
    kinds, check kinds, severities, role kinds) and the model (checksum algorithm kinds): the schema names no
    type and no kind itself."""
    out: dict[str, Any] = json.loads(SCHEMA_PATH.read_text(encoding="utf-8"))
    out["$defs"]["field"]["properties"]["type"] = {"enum": list(TYPES)}
    out["properties"]["types"]["additionalProperties"]["properties"]["kind"] = {"enum": list(FIELD_KINDS)}
    check = out["properties"]["checks"]["items"]["properties"]
    check["kind"] = {"enum": list(CHECK_KINDS)}
    check["severity"] = check["input_severity"] = {"enum": list(SEVERITIES)}
    algorithm = out["properties"]["checksums"]["properties"]["algorithms"]["additionalProperties"]
    algorithm["properties"]["kind"] = {"enum": list(ALGORITHMS)}
    command = out["properties"]["commands"]["items"]["properties"]
    for role, kinds in ROLE_KINDS.items():
        command[role]["allOf"][1]["properties"]["kind"] = {"enum": list(kinds)}
    return out


def _integer(_checker: Any, value: Any) -> bool:
    """An integer is an int: JSON Schema also takes 3.5e38, 1.0 and -0.0 (and a YAML bool is no int),
    but a binding reads a code, a size or a limit as an integer, and an integer-valued float
    breaks it (a class code of -0.0 crashed generation; 3.5e38 left cbf_tool.c uncompilable)."""
    return isinstance(value, int) and not isinstance(value, bool)


_VALIDATOR = jsonschema.validators.extend(
    jsonschema.Draft202012Validator,
    type_checker=jsonschema.Draft202012Validator.TYPE_CHECKER.redefine("integer", _integer))


def shape_problems(raw: Map) -> list[Problem]:
    """Every shape problem of the spec, by line (an integer is an int, never a float: ``_integer``)."""
    validator = _VALIDATOR(schema())
    errors = sorted(validator.iter_errors(raw), key=lambda e: (line_of_path(raw, e.absolute_path), str(e.message)))
    out = []
    for e in errors:
        where = "/".join(str(p) for p in e.absolute_path) or "(top)"
        out.append(Problem("schema", "error", line_of_path(raw, e.absolute_path), f"schema: {where}: {e.message}"))
    return out
