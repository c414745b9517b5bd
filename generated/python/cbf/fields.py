"""Field values <-> bytes, one layout at a time: the lowest layer under the model and the codec."""

from __future__ import annotations

import struct
from collections.abc import Sequence
from dataclasses import replace
from typing import Any

from . import tables as T
from .errors import EncodeError

Buffer = bytes | bytearray | memoryview


def convert_values(fields: Sequence[T.FieldInfo], values: Sequence[Any]) -> list[Any]:
    out: list[Any] = []
    i = 0
    for f in fields:
        if f.per:  # a repeated group: n items of `per` elements (a vector each when per > 1)
            flat = values[i:i + f.count]
            out.append(tuple(flat) if f.per == 1 else tuple(tuple(flat[k:k + f.per]) for k in range(0, f.count, f.per)))
            i += f.count
            continue
        if f.kind == "float" and f.count > 1:
            out.append(tuple(values[i:i + f.count]))
            i += f.count
            continue
        v = values[i]
        i += 1
        if f.kind == "string":
            v = v.rstrip(T.PAD).decode("latin-1")
        out.append(v)
    return out


def unpack_args(lay: T.LayoutInfo, raw: Buffer) -> Any:
    vals = convert_values(lay.args, lay.struct.unpack_from(raw, 0))
    return lay.cls(**{f.name: v for f, v in zip(lay.args, vals, strict=True)})


def pack_value(f: T.FieldInfo, value: Any, where: str) -> list[Any]:
    if f.per:  # a repeated group: exactly the layout's n items
        if not isinstance(value, (tuple, list)) or len(value) != f.items:
            got = f"{len(value)} items" if isinstance(value, (tuple, list)) else repr(value)
            raise EncodeError(f"{where}: expected {f.items} items, got {got}")
        one = replace(f, count=f.per, per=0)
        return [v for k, item in enumerate(value) for v in pack_value(one, item, f"{where}[{k}]")]
    if f.is_int:
        if not isinstance(value, int) or isinstance(value, bool) or not f.holds(value):
            raise EncodeError(f"{where}: {value!r} is not {f.int_name}")
        return [value]
    if f.kind == "float":
        vals = list(value) if f.count > 1 else [value]
        if len(vals) != f.count or not all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in vals):
            raise EncodeError(f"{where}: expected {f.count} float(s), got {value!r}")
        for v in vals:
            try:
                struct.pack("<f", v)
            except OverflowError:
                raise EncodeError(f"{where}: {v!r} is out of binary32 range") from None
        return vals
    if f.kind == "string":
        if not isinstance(value, str):
            raise EncodeError(f"{where}: expected a string, got {type(value).__name__}")
        try:
            raw = value.encode("latin-1")
        except UnicodeEncodeError:
            raise EncodeError(f"{where}: {value!r} has a character outside one byte") from None
        if len(raw) > f.size:
            raise EncodeError(f"{where}: {len(raw)} characters, the field holds {f.size}")
        return [raw + T.PAD * (f.size - len(raw))]
    if not isinstance(value, (bytes, bytearray)) or len(value) != f.size:
        raise EncodeError(f"{where}: expected {f.size} bytes")
    return [bytes(value)]


def pack_fields(fields: Sequence[T.FieldInfo], st: struct.Struct, obj: Any, where: str) -> bytes:
    vals: list[Any] = []
    for f in fields:
        vals.extend(pack_value(f, getattr(obj, f.name), f"{where} field {f.name}"))
    return st.pack(*vals)


def pack_args(lay: T.LayoutInfo, args: Any) -> bytes:
    rep = lay.repeated
    if rep is not None:  # a repeated group: the layout made for the object's n (issue 25, point 3)
        lay = layout_for_items(lay, getattr(args, rep.name), lay.command)
    return pack_fields(lay.args, lay.struct, args, lay.command)


def layout_for_items(lay: T.LayoutInfo, items: Any, where: str) -> T.LayoutInfo:
    """The layout of lay's command and variant made for len(items) items of its repeated group."""
    rep = lay.repeated
    assert rep is not None and rep.repeat is not None
    n = len(items) if isinstance(items, (tuple, list)) else -1
    for x in T.BY_CODE[lay.code].layouts:
        if x.variant == lay.variant and x.n == n:
            return x
    lo, hi = rep.repeat
    raise EncodeError(f"{where} field {rep.name}: {n if n >= 0 else repr(items)} items; the group holds "
                      f"{lo} to {hi}")


# A writer's strings hold printable ASCII and the NUL padding, before AND after the first
# NUL (N4): a NUL must not carry control bytes into the file (issue 13, item 5).
_STRING_BYTES = bytes(range(0x20, 0x7F)) + T.PAD


def check_strings(fields: Sequence[T.FieldInfo], raw: bytes, base: int, where: str) -> None:
    for f in fields:
        if f.kind != "string":
            continue
        value = raw[f.offset:f.end]
        bad = value.translate(None, _STRING_BYTES)
        if bad:
            k = value.index(bad[0])
            check = T.checks_of("string_ascii")[0]["id"]
            raise EncodeError(f"{where}: the result would fail check {check}: {f.name} holds non-ASCII byte "
                              f"0x{bad[0]:02X} at position {k} (strings are printable ASCII, NUL-padded)",
                              offset=base + f.offset + k)
