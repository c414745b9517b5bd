"""Annotated hex of a CBF file, read from its bytes with the spec model.

The file is split into runs: each header field of the layout its version
selects, then each record's head fields and argument fields (the layout is
the one of the command code whose size matches the record's nb byte), then
anything that frames no record. Each run is printed hexdump-style: the
offset, up to ROW bytes, an ASCII column, and after a gutter the field the
bytes belong to with its value. A run longer than a row carries its name on
every row, marked "(cont.)". Nothing here knows a command, a field or a
size: all of it comes from the model.
"""

from __future__ import annotations

import struct
from collections.abc import Iterator
from dataclasses import dataclass
from decimal import Decimal

from ...model import Command, Field, Layout, Spec

ROW = 16


@dataclass(frozen=True)
class Run:
    """Bytes [offset, offset + len(data)) and what they are."""

    offset: int
    data: bytes
    label: str
    record: int | None = None  # the record index, None for the header and unframed bytes


@dataclass(frozen=True)
class Record:
    index: int
    offset: int
    command: Command | None
    layout: Layout | None
    raw_args: bytes


def _fmt(spec: Spec) -> str:
    return "<" if spec.meta["byte_order"] == "little" else ">"


def shortest_float(bits: int) -> str:
    """The fewest digits that give back the same binary32."""
    v: float = struct.unpack("<f", struct.pack("<I", bits))[0]
    if v != v or v in (float("inf"), float("-inf")):
        return repr(v)
    text = repr(v)
    for p in range(1, 10):
        cand = f"{v:.{p}g}"
        if struct.unpack("<I", struct.pack("<f", float(cand)))[0] == bits:
            text = cand
            break
    return format(Decimal(text), "f") if "e" in text else text


def value_text(spec: Spec, f: Field, raw: bytes) -> str:
    """The value of a field's bytes as the reader sees it."""
    if len(raw) < f.size:
        return "(truncated)"
    if f.kind == "float":
        words = struct.unpack(_fmt(spec) + "I" * f.count, raw)
        vals = [shortest_float(w) for w in words]
        return vals[0] if f.count == 1 else "<" + ", ".join(vals) + ">"
    if f.ftype.is_integer:
        code = f.ftype.struct_code or ""
        vals_u = struct.unpack(_fmt(spec) + code * f.count, raw)
        hexa = f.magic is not None or f.role in ("code", "code_copy")
        return ", ".join(f"0x{u:0{2 * f.elem_size}X}" if hexa else str(u) for u in vals_u)
    if f.kind == "string":
        return repr(raw.rstrip(bytes([spec.meta["string_padding"]])).decode("latin-1"))
    return "all zero" if not any(raw) else f"{len(raw)} bytes"


def version_of(spec: Spec, data: bytes) -> str:
    """The version id the header's version bytes select (the fallback when none matches)."""
    try:
        major = spec.common_header_field("version_major")
        minor = spec.common_header_field("version_minor")
    except KeyError:
        return spec.fallback_version
    if len(data) <= max(major.offset, minor.offset):
        return spec.fallback_version
    for v in spec.versions:
        if v.matches(data[major.offset], data[minor.offset]):
            return v.id
    return spec.fallback_version


def _uint(spec: Spec, f: Field, data: bytes, base: int) -> int:
    return int.from_bytes(data[base + f.offset:base + f.end], spec.meta["byte_order"])


def records(spec: Spec, data: bytes) -> Iterator[Record]:
    """The whole records after the header, framed by their nb byte (D1)."""
    rec = spec.record
    code_f, nb_f = rec.by_role("code"), rec.by_role("arg_size")
    by_code = {c.code: c for c in spec.commands}
    version = version_of(spec, data)
    pos, index = spec.header_for(version).size, 0
    while pos + rec.head_size <= len(data):
        nb = _uint(spec, nb_f, data, pos)
        if pos + rec.head_size + nb > len(data):
            return
        cmd = by_code.get(_uint(spec, code_f, data, pos))
        lays = [x for lay in cmd.layouts_for(version) if (x := lay.sized(nb)) is not None] if cmd else []
        yield Record(index, pos, cmd, lays[0] if lays else None,
                     data[pos + rec.head_size:pos + rec.head_size + nb])
        pos += rec.head_size + nb
        index += 1


def runs(spec: Spec, data: bytes) -> Iterator[Run]:
    """Every byte of the file in one run, in order."""
    version = version_of(spec, data)
    header = spec.header_for(version)
    for f in header.fields:
        raw = data[f.offset:f.end]
        if raw:
            yield Run(f.offset, raw, f"header {f.name} = {value_text(spec, f, raw)}")
    pos = header.size
    for r in records(spec, data):
        name = r.command.name if r.command else "unknown code"
        for f in spec.record.fields:
            raw = data[r.offset + f.offset:r.offset + f.end]
            yield Run(r.offset + f.offset, raw, f"#{r.index} {name} {f.name} = {value_text(spec, f, raw)}",
                      r.index)
        base = r.offset + spec.record.head_size
        if r.layout is not None:
            for f in r.layout.args:
                raw = r.raw_args[f.offset:f.end]
                yield Run(base + f.offset, raw, f"#{r.index} {name} {f.name} = {value_text(spec, f, raw)}",
                          r.index)
        elif r.raw_args:
            yield Run(base, r.raw_args, f"#{r.index} {name} arguments (no layout of {len(r.raw_args)} bytes)",
                      r.index)
        pos = base + len(r.raw_args)
    if pos < len(data):
        yield Run(pos, data[pos:], "bytes that frame no whole record")


def _ascii(raw: bytes) -> str:
    return "".join(chr(b) if 0x20 <= b < 0x7F else "." for b in raw)


def dump(spec: Spec, data: bytes, *, max_lines: int | None = None, only_record: int | None = None,
         header_only: bool = False) -> str:
    """The annotated hex of data: `offset  bytes  ascii │ field = value`, one run per line or more.

    only_record keeps the runs of one record, header_only those of the header; max_lines cuts the dump
    (and says so)."""
    if not data:
        return "(no bytes: the file is empty)"
    lines: list[str] = []
    for run in runs(spec, data):
        if only_record is not None and run.record != only_record:
            continue
        if header_only and not run.label.startswith("header "):
            break
        for k in range(0, max(1, len(run.data)), ROW):
            chunk = run.data[k:k + ROW]
            label = run.label if k == 0 else run.label.split(" = ")[0] + " (cont.)"
            if max_lines is not None and len(lines) == max_lines:
                lines.append(f"... cut here: the first {max_lines} lines of {len(data)} bytes")
                return "\n".join(lines)
            lines.append(f"{run.offset + k:08X}  {chunk.hex(' ').upper():<{3 * ROW - 1}}  "
                         f"{_ascii(chunk):<{ROW}} \u2502 {label}")
    return "\n".join(lines)
