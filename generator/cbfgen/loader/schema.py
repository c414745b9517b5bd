"""The first gate: the JSON Schema (spec.schema.json) for shape, its vocabulary enums filled from
the registry and the model. The semantic passes need the shape, so they wait for it."""

from __future__ import annotations

import functools
import json
from pathlib import Path
from typing import Any

import jsonschema

from ..escape import NAME_MAX
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
    _bound_names(out)
    return out


def _bound_names(out: dict[str, Any]) -> None:
    """Every name of the spec no longer than every binding takes (escape.NAME_MAX): the names of
    $defs and every key of a map. A layout variant of 4,098 characters passed and generation died
    writing a file named by it (spec-fuzz seed 2026120606 #90)."""
    for name in ("name", "cmdname", "keyword"):
        out["$defs"][name]["maxLength"] = NAME_MAX

    def walk(node: Any) -> None:
        if isinstance(node, dict):
            if isinstance(node.get("additionalProperties"), dict):
                node.setdefault("propertyNames", {})["maxLength"] = NAME_MAX
            for sub in node.values():
                walk(sub)
        elif isinstance(node, list):
            for sub in node:
                walk(sub)

    walk(out)


def _integer(_checker: Any, value: Any) -> bool:
    """An integer is an int: JSON Schema also takes 3.5e38, 1.0 and -0.0 (and a YAML bool is no int),
    but a binding reads a code, a size or a limit as an integer, and an integer-valued float
    breaks it (a class code of -0.0 crashed generation; 3.5e38 left cbf_tool.c uncompilable)."""
    return isinstance(value, int) and not isinstance(value, bool)


_VALIDATOR = jsonschema.validators.extend(
    jsonschema.Draft202012Validator,
    type_checker=jsonschema.Draft202012Validator.TYPE_CHECKER.redefine("integer", _integer))


def shape_problems(raw: Map) -> list[Problem]:
    """Every shape problem of the spec, by line (an integer is an int, never a float: ``_integer``).
    A spec the schema accepts (`valid_by_pieces`: the same
    validator, piece by piece, remembering each piece's verdict) has none; any other is checked
    whole by `iter_errors`, so the problems are exactly jsonschema's."""
    if valid_by_pieces(raw):
        return []
    errors = sorted(_validator().iter_errors(raw), key=lambda e: (line_of_path(raw, e.absolute_path), str(e.message)))
    out = []
    for e in errors:
        where = "/".join(str(p) for p in e.absolute_path) or "(top)"
        out.append(Problem("schema", "error", line_of_path(raw, e.absolute_path), f"schema: {where}: {_message(e)}"))
    return out


def _message(e: jsonschema.ValidationError) -> str:
    """jsonschema's message, but a name (or a map's key) over NAME_MAX by its length, not the 4,096
    characters again."""
    if str(e.validator) == "maxLength" and isinstance(e.instance, str):
        return f"a name of {len(e.instance)} characters; every binding takes at most {NAME_MAX} (escape.NAME_MAX)"
    return str(e.message)


# Why pieces: a `load()` spent 0.09 CPU s in jsonschema on the whole spec, and the tests load hundreds
# of specs that differ from spec/cbf.yaml (and from each other) in one place. The root schema is only
# `type`, `required`, `additionalProperties: false` and `properties`, so the spec is valid exactly when
# the root is valid with each property's schema replaced by `true` (the keys) and each property's value
# is valid against its own schema; an array property whose schema is only `type`, `minItems` and `items`
# is valid exactly when the array is valid with `items: true` and each item is valid against `items`.
# A piece's verdict depends only on its value, remembered by its repr (which tells 1, 1.0, True and
# "1", a list from a tuple, apart), so a piece seen before costs its repr. `$ref` resolves within the
# whole schema (each piece's validator carries its `$defs` and `$id`).
_SHALLOW_ARRAY = {"type", "minItems", "items", "$comment", "description"}
_ROOT_KEYS = {"$schema", "$id", "$defs", "$comment", "title", "description",
              "type", "required", "additionalProperties", "properties"}
_MEMO_MAX = 4096
_memo: dict[tuple[str, str], bool] = {}


@functools.cache
def _validator() -> jsonschema.Draft202012Validator:
    full = schema()
    jsonschema.Draft202012Validator.check_schema(full)
    return _VALIDATOR(full)  # type: ignore[no-any-return]


@functools.cache
def _piece(name: str) -> jsonschema.Draft202012Validator:
    """The validator of one piece of the schema: "/" the root with its properties' schemas replaced by
    `true`; "/KEY" the schema of property KEY ("/KEY/" with its items `true`); "/KEY/items" its items."""
    full = schema()
    if name == "/":
        body: Any = {k: v for k, v in full.items() if k not in ("$schema", "$id", "$defs")}
        body["properties"] = dict.fromkeys(full["properties"], True)
    else:
        key, _, rest = name[1:].partition("/")
        body = full["properties"][key]
        if rest == "items":
            body = body["items"]
        elif name.endswith("/"):
            body = {**body, "items": True}
    return _VALIDATOR({  # type: ignore[no-any-return]
        "$schema": full["$schema"], "$id": full["$id"], "$defs": {**full["$defs"], "_piece": body},
        "$ref": "#/$defs/_piece"})


def _valid_piece(name: str, value: Any) -> bool:
    key = (name, repr(value))
    known = _memo.get(key)
    if known is None:
        known = _piece(name).is_valid(value)
        if len(_memo) >= _MEMO_MAX:
            _memo.clear()
        _memo[key] = known
    return known


def valid_by_pieces(raw: Map) -> bool:
    """jsonschema's verdict on the whole spec, by pieces (see above); whole when the root schema
    grows a keyword the pieces do not account for."""
    if not _by_pieces():
        return _validator().is_valid(raw)
    if not _piece("/").is_valid(raw):
        return False
    properties = _properties()
    for key, value in raw.items():
        sub = properties.get(key)
        if sub is None:  # refused by the root piece already (additionalProperties: false)
            return False
        if (isinstance(sub, dict) and set(sub) <= _SHALLOW_ARRAY and sub.get("type") == "array"
                and isinstance(sub.get("items"), dict) and isinstance(value, list)):
            if not (_piece(f"/{key}/").is_valid(value) and all(_valid_piece(f"/{key}/items", v) for v in value)):
                return False
        elif not _valid_piece(f"/{key}", value):
            return False
    return True


@functools.cache
def _by_pieces() -> bool:
    return not set(schema()) - _ROOT_KEYS


@functools.cache
def _properties() -> dict[str, Any]:
    props: dict[str, Any] = schema()["properties"]
    return props
