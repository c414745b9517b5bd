"""Fields as the header, the record head and each command layout declare them: built in order,
each at the offset the fields before it end at, with every problem of a field reported."""

from __future__ import annotations

from ..model import Field
from ..registry import FieldType
from .problems import Problems
from .yaml_reader import Map, Seq


def _element(ctx: Problems, raw: Map, ptype: FieldType, where: str) -> tuple[int, int] | None:
    """The element size and count of a field of ``ptype`` (None: a size-less type without a size)."""
    count = int(raw.get("count", 1))
    if ptype.size is not None:
        if "size" in raw and raw["size"] != ptype.size * count:
            ctx.fail(raw, f"{where}: size {raw['size']} contradicts type {ptype.name} x {count}", "size")
        return ptype.size, count
    if "size" not in raw:
        ctx.fail(raw, f"{where}: type {ptype.name} needs a size", "type")
        return None
    if count != 1:
        ctx.fail(raw, f"{where}: type {ptype.name} takes no count", "count")
    return int(raw["size"]), 1


def field(ctx: Problems, raw: Map, types: dict[str, FieldType], offset: int, where: str) -> Field | None:
    """The field ``raw`` at ``offset`` (None: its type or size is unknown, so its end is too)."""
    ptype = types.get(raw["type"])
    if ptype is None:
        ctx.fail(raw, f"{where}: unknown type {raw['type']!r} (not in the spec's types)", "type")
        return None
    shape = _element(ctx, raw, ptype, where)
    if shape is None:
        return None
    elem, count = shape
    if "offset" in raw and raw["offset"] != offset:
        ctx.fail(raw, f"{where}: offset {raw['offset']} but the fields before end at {offset}", "offset")
    if raw.get("text") and ptype.kind != "string":
        ctx.fail(raw, f"{where}: text applies to strings only", "text")
    if "magic" in raw and ptype.kind != "uint":
        ctx.fail(raw, f"{where}: magic needs an unsigned integer type", "magic")
    elif "magic" in raw and raw["magic"] >= 1 << (8 * elem):
        ctx.fail(raw, f"{where}: magic 0x{raw['magic']:X} does not fit {ptype.name}", "magic")
    return Field(
        name=raw["name"], type=ptype.name, kind=ptype.kind, offset=offset, elem_size=elem, count=count,
        doc=str(raw["doc"]).strip(), line=raw.line, clause=raw.get("clause"), unit=raw.get("unit"),
        role=raw.get("role"), magic=raw.get("magic"), checksum=raw.get("checksum"),
        reserved=bool(raw.get("reserved", False)), text=bool(raw.get("text", False)),
        repeat=(int(raw["repeat"]["min"]), int(raw["repeat"]["max"])) if "repeat" in raw else None,
    )


def fields(ctx: Problems, raws: Seq, types: dict[str, FieldType], where: str) -> tuple[tuple[Field, ...], int, bool]:
    """The fields, where they end, and whether every one was understood (else the end is unknown)."""
    out: list[Field] = []
    offset, whole = 0, True
    names: set[str] = set()
    for raw in raws:
        if raw["name"] in names:
            ctx.fail(raw, f"{where}: duplicate field name {raw['name']!r}", "name")
        names.add(raw["name"])
        f = field(ctx, raw, types, offset, f"{where} field {raw['name']}")
        if f is None:
            whole = False
            continue
        out.append(f)
        offset = f.end
    return tuple(out), offset, whole
