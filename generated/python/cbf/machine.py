"""Machine limits (decision L1): check kind ``machine_limits`` and machine files.

A machine bounds every position argument by a box and speeds, accelerations and
cutter sizes by ranges, in the units of the arguments (N11). The spec ships a
conservative default machine (``SPEC["machine"]``), whose breaches are warnings;
a machine file (``cbf validate --machine FILE``: JSON, or YAML for .yaml/.yml,
the shape of the default, schema ``machine.schema.json`` beside this module)
replaces it, and its breaches are errors (the check's ``input_severity``).

Which arguments a limit bounds is data: the check's targets (command, arguments,
limit); the spec loader requires a box to target every float vector of its unit.
"""

from __future__ import annotations

import functools
import json
import math
import struct
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from . import tables as T
from .errors import CbfError
from .optfiles import RULES, OptionFileError, Pairs, is_yaml, json_depth_error, plain_data, read_text, yaml_tree
from .quoting import quote

SCHEMA: dict[str, Any] = json.loads(Path(__file__).with_name("machine.schema.json").read_text(encoding="utf-8"))


_F32 = struct.Struct("<f")
_F32_MAX = 3.4028234663852886e38


def as_binary32(bound: float) -> float:
    """A bound as the values it limits are stored: rounded to binary32, beyond its range
    infinite (a value equal to a bound written in decimal is inside)."""
    if abs(bound) > _F32_MAX:
        return math.copysign(math.inf, bound)
    v: float = _F32.unpack(_F32.pack(bound))[0]
    return v


@dataclass(frozen=True, slots=True)
class Limit:
    name: str
    unit: str
    lo: tuple[float, ...]  # as given (messages)
    hi: tuple[float, ...]
    axes: tuple[str, ...]  # empty: a scalar range
    lo32: tuple[float, ...]  # the bounds compared with: each rounded to binary32 (as_binary32)
    hi32: tuple[float, ...]


@dataclass(frozen=True, slots=True)
class Machine:
    """The limits a file is checked against; ``given``: a machine file (findings are errors)."""

    limits: Mapping[str, Limit]
    given: bool


class MachineError(CbfError):
    """A machine file that cannot be used; the message names the file and the JSON path."""

    kind = "machine"


def _limits(doc: Mapping[str, Any]) -> dict[str, Limit]:
    out = {}
    for name, lim in doc["limits"].items():
        lo = tuple(map(float, lim["min"] if isinstance(lim["min"], list) else [lim["min"]]))
        hi = tuple(map(float, lim["max"] if isinstance(lim["max"], list) else [lim["max"]]))
        out[name] = Limit(name, lim["unit"], lo, hi, tuple(T.SPEC["machine"]["limits"][name].get("axes", [])),
                          tuple(map(as_binary32, lo)), tuple(map(as_binary32, hi)))
    return out


DEFAULT = Machine(_limits(T.SPEC["machine"]), given=False)


# -- machine files ----------------------------------------------------------------------
def _object_errors(value: Any, schema: Mapping[str, Any], path: str) -> str | None:
    if not isinstance(value, dict):
        return f"{path}: expected an object"
    props = schema.get("properties", {})
    seen: set[Any] = set()
    for key, v in value.pairs if isinstance(value, Pairs) else value.items():
        if key in seen:
            return f"{path}: duplicate key '{quote(key)}'"
        seen.add(key)
        if key not in props:
            if schema.get("additionalProperties") is False:
                return f"{path}: unknown key '{quote(key)}' (known: {', '.join(props)})"
            continue
        err = _schema_errors(v, props[key], f"{path}.{key}")
        if err:
            return err
    return next((f"{path}: missing '{key}'" for key in schema.get("required", []) if key not in value), None)


def _array_errors(value: Any, schema: Mapping[str, Any], path: str) -> str | None:
    if not isinstance(value, list):
        return f"{path}: expected a list"
    for i, v in enumerate(value):
        err = _schema_errors(v, schema.get("items", {}), f"{path}[{i}]")
        if err:
            return err
    if "minItems" in schema and len(value) != schema["minItems"]:
        return f"{path}: expected {schema['minItems']} items, got {len(value)}"
    return None


def _schema_errors(value: Any, schema: Mapping[str, Any], path: str) -> str | None:
    """The first breach of ``schema`` (the subset machine.schema.json uses), as "PATH: what", in
    the order a reader meets it: each key or item in turn, then what is missing (cbf-c's reader
    reads the file the same way and says the same)."""
    want = schema.get("type")
    if want == "object":
        return _object_errors(value, schema, path)
    if want == "array":
        err = _array_errors(value, schema, path)
        if err:
            return err
    if want == "number" and (isinstance(value, bool) or not isinstance(value, (int, float))):
        return f"{path}: expected a number"
    if want == "number" and not _finite(value):
        return f"{path}: not a finite number"
    if want == "string" and not isinstance(value, str):
        return f"{path}: expected a string"
    if "const" in schema and value != schema["const"]:
        return f"{path}: must be {_dumps(schema['const'])}, got {_dumps(value)}"
    return None


def _finite(value: float) -> bool:
    try:
        return math.isfinite(float(value))
    except OverflowError:  # an integer beyond any double
        return False


def _dumps(value: Any) -> str:
    return json.dumps(value, ensure_ascii=False)


def _read(p: Path, text: str) -> Any:
    """The file's data by the option-file rules (optfiles.py): YAML event by event, JSON after its
    nesting is measured; objects keep every pair, so a duplicate key is the schema's to refuse."""
    rules = RULES["machine_file"]
    if is_yaml(p):
        return plain_data(yaml_tree(text, quote(str(p)), rules["max_depth"]))
    deep = json_depth_error(text, rules["max_depth"])
    if deep is not None:
        raise OptionFileError(f"{quote(str(p))}: {deep}")

    def constant(name: str) -> Any:
        raise OptionFileError(f"{quote(str(p))}: {name} is not a number")

    try:
        return json.loads(text, object_pairs_hook=Pairs, parse_constant=constant, parse_int=float)
    except json.JSONDecodeError as exc:
        raise OptionFileError(f"{quote(str(p))}: line {exc.lineno}, column {exc.colno}: not JSON ({exc.msg})") from None


def load_machine(path: str | Path) -> Machine:
    """The machine of a file; raises MachineError with one line naming the file and the JSON path."""
    p = Path(path)
    try:
        doc = _read(p, read_text(p, RULES["machine_file"]["what"], RULES["machine_file"]["max_bytes"]))
    except OptionFileError as exc:
        raise MachineError(exc.message) from None
    err = _schema_errors(doc, SCHEMA, "$")
    if err is None:
        for name in SCHEMA["properties"]["limits"]["properties"]:  # the spec's order
            lo, hi = doc["limits"][name]["min"], doc["limits"][name]["max"]
            axes = T.SPEC["machine"]["limits"][name].get("axes", [])
            bad = [k for k, (a, b) in enumerate(zip(lo, hi, strict=True) if axes else [(lo, hi)]) if a > b]
            if bad:
                err = f"$.limits.{name}: min exceeds max" + (f" on axis {axes[bad[0]]}" if axes else "")
                break
    if err is not None:
        raise MachineError(f"{quote(str(p))}: {err}")
    return Machine(_limits(doc), given=True)


# -- the check (its kernel is records.py's _machine_limits) -------------------------------------
# Per (command, layout variant): (check id, argument, limit name, whether a positive check targets
# the argument too).
_Rule = tuple[str, T.FieldInfo, str, bool]


def _rules() -> dict[tuple[str, str], list[_Rule]]:
    positive = {(t["command"], a) for ch in T.checks_of("positive") for t in ch["targets"] for a in t["args"]}
    out: dict[tuple[str, str], list[_Rule]] = {}
    for ch in T.checks_of("machine_limits"):
        for t in ch["targets"]:
            cmd = T.BY_NAME[t["command"]]
            for lay in cmd.layouts:
                rules = out.setdefault((cmd.name, lay.variant), [])
                for f in lay.args:
                    # a layout with a repeated group is made once per n, all of one variant: one rule
                    if f.name in t["args"] and not any(r[0] == ch["id"] and r[1].name == f.name for r in rules):
                        rules.append((ch["id"], f, t["limit"], (cmd.name, f.name) in positive))
    return out


_RULES = _rules()
_NUM = "{:.9g}".format


def machine_rules(check: Mapping[str, Any], command: str, variant: str) -> tuple[tuple[T.FieldInfo, str, bool], ...]:
    """The arguments ``check`` bounds in a layout: (argument, limit name, positive-checked)."""
    return _rules_of(check["id"], command, variant)


@functools.lru_cache(maxsize=1024)
def _rules_of(check: str, command: str, variant: str) -> tuple[tuple[T.FieldInfo, str, bool], ...]:
    return tuple((f, lim, pos) for cid, f, lim, pos in _RULES.get((command, variant), ()) if cid == check)


def breach(values: tuple[float, ...], lim: Limit, positive: bool) -> str | None:
    """How a value breaks a limit, or None. Non-finite values are the finite check's, and with
    ``positive`` values <= 0 are the positive check's (one fault, one finding)."""
    if not all(math.isfinite(v) for v in values) or (positive and any(v <= 0.0 for v in values)):
        return None
    for k, v in enumerate(values):
        if v < lim.lo32[k] or v > lim.hi32[k]:
            axis = f" {lim.axes[k]}" if lim.axes else ""
            return (f"{axis} is {_NUM(v)} {lim.unit}, outside the machine's {lim.name} "
                    f"{_NUM(lim.lo[k])}..{_NUM(lim.hi[k])} {lim.unit}")
    return None
