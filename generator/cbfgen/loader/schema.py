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


def shape_problems(raw: Map) -> list[Problem]:
    """Every shape problem of the spec, by line."""
    validator = jsonschema.Draft202012Validator(schema())
    errors = sorted(validator.iter_errors(raw), key=lambda e: (line_of_path(raw, e.absolute_path), str(e.message)))
    out = []
    for e in errors:
        where = "/".join(str(p) for p in e.absolute_path) or "(top)"
        out.append(Problem("schema", "error", line_of_path(raw, e.absolute_path), f"schema: {where}: {e.message}"))
    return out
