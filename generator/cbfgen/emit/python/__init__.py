"""Python codec emitter: typed layouts and spec tables rendered from the
model, plus the hand-written runtime (runtime/*.py) copied beside them into
generated/python/cbf/."""

from __future__ import annotations

import json
from dataclasses import asdict, replace
from pathlib import Path
from typing import Any

from ... import __license__ as TOOLKIT_LICENSE
from ... import __version__ as TOOLKIT_VERSION
from ...model import Field, Spec
from ...options import option_rules
from ...registry import ALGORITHMS, DERIVED_HEADER_ROLES, TYPES
from ...registry import kind as check_kind
from ...render import environment
from .machine import machine_data, machine_schema

HERE = Path(__file__).parent
PKG = "python/cbf"
# What the `cbf` distribution needs at run time, as ranges a user's resolver can meet
# (the development pins are in .ci/constraints.txt). Only the codec's own imports.
DEPENDENCIES = ("numpy>=2.0,<3",)
EXTRAS: dict[str, tuple[str, ...]] = {
    "testing": ("hypothesis>=6.100,<7",),  # cbf.testing: strategies
    "plot": ("matplotlib>=3.8,<4",),  # cbf plot, imported lazily
}


def _py_type(f: Field) -> str:
    if f.repeat is not None:  # a repeated group (issue 25, point 3): a tuple of n items
        return f"tuple[{_py_type(replace(f, repeat=None))}, ...]"
    if f.kind == "float":
        return "float" if f.count == 1 else "tuple[" + ", ".join(["float"] * f.count) + "]"
    return {"uint": "int", "sint": "int", "string": "str", "bytes": "bytes"}[f.kind]


def _field_data(f: Field) -> dict[str, Any]:
    """A field as the runtime reads it; its codes (struct, numpy) come from the registry's type."""
    t = f.ftype
    return {
        "name": f.name, "type": f.type, "kind": f.kind, "offset": f.offset, "elem_size": f.elem_size,
        "count": f.count, "role": f.role, "magic": f.magic, "checksum": f.checksum,
        "reserved": f.reserved, "text": f.text, "unit": f.unit,
        "code": t.struct_code, "bits_code": t.bits_code, "numpy": t.numpy, "min": t.min, "max": t.max,
        "repeat": list(f.repeat) if f.repeat is not None else None,
    }


def spec_data(spec: Spec) -> dict[str, Any]:
    """The slice of the model the runtime needs, as plain data."""
    return {
        "title": spec.meta["title"],
        "part_number": spec.meta["part_number"],
        "revision": spec.meta["revision"],
        "byte_order": spec.meta["byte_order"],
        "string_padding": spec.meta["string_padding"],
        "versions": [
            {"id": v.id, "major": v.major, "minor": v.minor, "header": v.header, "writable": v.writable}
            for v in spec.versions
        ],
        "default_version": spec.default_version,
        "fallback_version": spec.fallback_version,
        "headers": {
            h.id: {"size": h.size, "fields": [_field_data(f) for f in h.fields]} for h in spec.headers.values()
        },
        # the header roles the codec derives (registry.DERIVED_HEADER_ROLES): tables.DERIVED_ROLES
        "derived_roles": list(DERIVED_HEADER_ROLES),
        "record": {"head_size": spec.record.head_size, "fields": [_field_data(f) for f in spec.record.fields]},
        "commands": [
            {
                "name": c.name, "former_names": list(c.former_names), "code": c.code, "motion": c.motion,
                "orientation": c.orientation, "shape": c.shape,
                "cutter": c.cutter, "progress": c.progress, "sets": c.sets,
                "layouts": [
                    {"variant": lay.variant, "class": lay.class_name, "versions": list(lay.versions),
                     "size": lay.size, "profiles": list(lay.profiles), "args": [_field_data(a) for a in lay.args],
                     # checksum fields among the arguments, each with the record's byte ranges it covers
                     "checksums": [{"tag": ck.tag, "arg": ck.field.name, "algorithm": ck.algorithm,
                                    "ranges": [list(r) for r in ck.ranges]} for ck in lay.checksums]}
                    for lay in c.layouts
                ],
            }
            for c in spec.commands
        ],
        "checksums": {
            "algorithms": {k: a.kind for k, a in spec.checksums.algorithms.items()},
            # every algorithm kind of the registry, as parameters: checksums.py implements each family once
            "kinds": {k: a.parameters for k, a in ALGORITHMS.items()},
            "coverages": {
                k: [{"region": s.region, "start": s.start, "end": s.end, "exclude": list(s.exclude),
                     "fields": list(s.fields)} for s in cov.segments]
                for k, cov in spec.checksums.coverages.items()
            },
            "fields": {f.field: {"algorithm": f.algorithm, "coverage": f.coverage} for f in spec.checksums.fields},
            "fill_order": list(spec.checksums.fill_order),
        },
        "profiles": {p.id: {"file_coverages": list(p.file_coverages), "hint_coverages": list(p.hint_coverages),
                            "file_algorithm": p.file_algorithm or spec.checksums.for_field("file").algorithm}
                     for p in spec.profiles},
        "tolerances": spec.tolerances,
        "limits": spec.limits,
        "machine": machine_data(spec),
        "checks": [
            {"id": c.id, "kind": c.kind, "severity": c.severity, "clause": c.clause, "text": c.text,
             "fails": c.fails, "anchor": c.anchor, "versions": list(c.versions),
             "commands": list(c.commands),
             "targets": [{"command": t.command, "args": list(t.args), "limit": t.limit} for t in c.targets],
             "min": c.min, "max": c.max, "min_exclusive": c.min_exclusive, "max_exclusive": c.max_exclusive,
             "since": c.since, "deprecates": list(c.deprecates),
             "input": c.input, "input_severity": c.input_severity,
             "field": c.checksum_field,
             "accepts": None if (a := check_kind(c.kind).accepted(c)) is None else asdict(a)}
            for c in spec.checks
        ],
        "cut": spec.cut,
    }


def _layout_field(f: Field) -> dict[str, Any]:
    """A field as a third-party reader needs it: where it is, what it holds, what it means."""
    out: dict[str, Any] = {"name": f.name, "offset": f.offset, "size": f.size, "type": f.type, "count": f.count}
    for key, value in (("unit", f.unit), ("role", f.role), ("magic", f.magic), ("checksum", f.checksum),
                       ("clause", f.clause)):
        if value is not None:
            out[key] = value
    if f.reserved:
        out["reserved"] = True
    if f.repeat is not None:
        out["repeat"] = {"min": f.repeat[0], "max": f.repeat[1]}
    out["doc"] = f.doc
    return out


def layouts_data(spec: Spec) -> dict[str, Any]:
    """layouts.json: the byte layouts a reader needs (the conformance kit ships it beside PROTOCOL.md):
    versions and their header, the header layouts, the record head, every command's code and argument
    layouts per version, and the checksums. Offsets of header and head fields are from the start of
    the header or record; argument offsets from the start of the arguments."""
    return {
        "$comment": "Generated from spec/cbf.yaml by cbfgen: the byte layouts of the Cutfile Binary Format.",
        "title": spec.meta["title"],
        "spec": f"{spec.meta['part_number']} rev {spec.meta['revision']}",
        "byte_order": spec.meta["byte_order"],
        "string_padding": spec.meta["string_padding"],
        "types": {t: {"size": TYPES[t].size, "kind": TYPES[t].kind, "doc": TYPES[t].doc} for t in sorted(
            {f.type for h in spec.headers.values() for f in h.fields}
            | {f.type for f in spec.record.fields}
            | {a.type for c in spec.commands for lay in c.layouts for a in lay.args})},
        "versions": [{"id": v.id, "major": v.major, "minor": v.minor, "header": v.header, "writable": v.writable}
                     for v in spec.versions],
        "fallback_version": spec.fallback_version,
        "headers": {h.id: {"size": h.size, "fields": [_layout_field(f) for f in h.fields]}
                    for h in spec.headers.values()},
        "record_head": {"size": spec.record.head_size, "fields": [_layout_field(f) for f in spec.record.fields]},
        "commands": [
            {"name": c.name, "code": c.code, "clause": c.clause, "former_names": list(c.former_names),
             "layouts": [{"variant": lay.variant, "versions": list(lay.versions), "size": lay.size,
                          "profiles": list(lay.profiles), "args": [_layout_field(a) for a in lay.args]}
                         for lay in c.layouts]}
            for c in spec.commands
        ],
        "checksums": {
            "algorithms": {k: {"kind": a.kind, "doc": a.doc} for k, a in spec.checksums.algorithms.items()},
            "coverages": {k: {"doc": cov.doc, "segments": [
                {key: value for key, value in (("region", s.region), ("start", s.start), ("end", s.end),
                                               ("exclude", list(s.exclude)), ("fields", list(s.fields)))
                 if value not in (None, [])} for s in cov.segments]}
                for k, cov in spec.checksums.coverages.items()},
            "fields": [{"field": f.field, "algorithm": f.algorithm, "coverage": f.coverage, "clause": f.clause}
                       for f in spec.checksums.fields],
            "fill_order": list(spec.checksums.fill_order),
        },
        "profiles": {p.id: {"file_coverages": list(p.file_coverages),
                            "file_algorithm": p.file_algorithm or spec.checksums.for_field("file").algorithm}
                     for p in spec.profiles},
    }


def canonical_schema(spec: Spec) -> dict[str, Any]:
    """JSON Schema of the canonical JSON (PROTOCOL.md), from the model."""
    f32: dict[str, Any] = {"oneOf": [{"type": "number"}, {"type": "string", "pattern": "^0x[0-9a-f]{8}$"}]}

    def value(f: Field) -> dict[str, Any]:
        if f.repeat is not None:  # a repeated group: a list of min..max items
            return {"type": "array", "items": value(replace(f, repeat=None)), "minItems": f.repeat[0],
                    "maxItems": f.repeat[1]}
        if f.kind == "float":
            return f32 if f.count == 1 else {"type": "array", "items": f32, "minItems": f.count, "maxItems": f.count}
        if f.ftype.is_integer:
            return {"type": "integer", "minimum": f.ftype.min, "maximum": f.ftype.max}
        if f.kind == "string":
            return {"type": "string", "maxLength": f.size, "description": f.doc}
        return {"type": "string", "pattern": "^([0-9a-f]{2}){" + str(f.size) + "}$", "description": f.doc}

    headers = [
        {"type": "object", "title": f"header {h.id}", "additionalProperties": False,
         "required": [f.name for f in h.fields], "properties": {f.name: value(f) for f in h.fields}}
        for h in spec.headers.values()
    ]
    layouts = []
    for c in spec.commands:
        for lay in c.layouts:
            layouts.append({
                "title": lay.class_name, "type": "object", "additionalProperties": False,
                "required": [a.name for a in lay.args], "properties": {a.name: value(a) for a in lay.args},
            })
    rec_props: dict[str, Any] = {f.name: value(f) for f in spec.record.fields}
    rec_props.update({
        "offset": {"type": "integer", "minimum": 0},
        "command": {"oneOf": [{"enum": [c.name for c in spec.commands]}, {"type": "null"}]},
        "args": {"anyOf": [{"type": "null"}, *layouts]},
        "raw_args": {"type": "string", "pattern": "^([0-9a-f]{2})*$"},
    })
    return {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "title": f"{spec.meta['title']} ({spec.revision}), canonical JSON",
        "type": "object",
        "additionalProperties": False,
        "required": ["header", "records"],
        "properties": {
            # anyOf, not oneOf: two versions may lay their headers out alike (a revision adding a version
            # whose header is a copy of another's), and a header valid under both is still one header.
            "header": {"anyOf": headers},
            "records": {"type": "array", "maxItems": spec.limits["max_commands"] + 1_000_000,
                        "items": {"type": "object", "additionalProperties": False,
                                  "required": ["command"], "properties": rec_props}},
            "trailing": {"type": "string", "pattern": "^([0-9a-f]{2})*$"},
        },
    }


def emit(spec: Spec) -> dict[str, bytes]:
    env = environment(HERE / "templates")
    env.filters["pytype"] = _py_type
    out: dict[str, bytes] = {}
    out[f"{PKG}/spec_data.json"] = (json.dumps(spec_data(spec), indent=1) + "\n").encode()
    out[f"{PKG}/layouts.json"] = (json.dumps(layouts_data(spec), indent=1) + "\n").encode()
    dist = {"spec": spec, "version": TOOLKIT_VERSION, "license": TOOLKIT_LICENSE,
            "dependencies": DEPENDENCIES, "extras": EXTRAS}
    out["python/pyproject.toml"] = env.get_template("pyproject.toml.j2").render(**dist).encode()
    out["python/README.md"] = env.get_template("README.md.j2").render(**dist).encode()
    out[f"{PKG}/version.py"] = (
        '"""The toolkit version and the spec revision this package was generated from."""\n\n'
        f"__version__ = {TOOLKIT_VERSION!r}\n"
        f"SPEC_REVISION = {spec.revision!r}\n"
    ).encode()
    out[f"{PKG}/layouts.py"] = env.get_template("layouts.py.j2").render(spec=spec).encode()
    out[f"{PKG}/canonical.schema.json"] = (json.dumps(canonical_schema(spec), indent=1) + "\n").encode()
    out[f"{PKG}/machine.schema.json"] = (json.dumps(machine_schema(spec), indent=1) + "\n").encode()
    out[f"{PKG}/option_files.json"] = (json.dumps(option_rules(spec), indent=1) + "\n").encode()  # issue 28
    out[f"{PKG}/py.typed"] = b""
    for src in sorted([*(HERE / "runtime").glob("*.py"), *(HERE / "runtime").glob("*.schema.json")]):
        out[f"{PKG}/{src.name}"] = src.read_bytes()  # the JSON schemas of the CLI's outputs ship too
    return out
