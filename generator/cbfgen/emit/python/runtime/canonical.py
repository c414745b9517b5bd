"""Canonical JSON (conformance/PROTOCOL.md) in both directions, float bits exact.

``loads`` reads JSON text so that nothing silently changes meaning (issue 13): a
duplicate key is refused with its JSON path, numbers stay text (a fraction, ``-0``
or a long integer as a Numeral: no arithmetic on an exponent of any size before it is
bounded), read into a float by floats.read_decimal, the reader CUT's numbers go through
too (issue 36: ``-0`` is -0.0 from both), and NaN and Infinity reach the model's checks,
which refuse them with their path.
"""

from __future__ import annotations

import json
import math
import re
import struct
from dataclasses import dataclass, replace
from decimal import Decimal
from typing import Any

from . import tables as T
from .errors import JsonShapeError
from .floats import NotDecimal, OutOfRange, read_decimal
from .floats import float_bits as _nearest_bits
from .model import Cbf, Record
from .quoting import quote

_F = struct.Struct("<f")
_I = struct.Struct("<I")
_PATTERN = re.compile(r"0x[0-9a-fA-F]{8}", re.ASCII)  # a float's bit pattern: 0x and exactly 8 hex digits
_INT_DIGITS = 20  # longer integers stay text: int() refuses 4301+ digits, and no field needs 21
_SHOW = 40


@dataclass(frozen=True, slots=True)
class Numeral:
    """A JSON number kept as its text: a fraction, an exponent, -0, a long integer, NaN or Infinity."""

    text: str

    def __str__(self) -> str:
        return self.text


def _show(value: Any) -> str:
    """A value for a message: its JSON-like text, cut short when long."""
    text = str(value) if isinstance(value, (Decimal, Numeral)) else repr(value)
    if len(text) <= _SHOW:
        return text
    digits = isinstance(value, (Decimal, Numeral)) and text.lstrip("-").isdigit()
    return f"{text[:_SHOW]}... ({len(text)} {'digits' if digits else 'characters'})"


class _Duplicates(dict[str, Any]):
    """An object that had a key twice (the last value kept, the key named)."""

    duplicate: str = ""


def _pairs(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    obj = dict(pairs)
    if len(obj) == len(pairs):
        return obj
    marked = _Duplicates(obj)
    seen: set[str] = set()
    for key, _ in pairs:
        if key in seen:
            marked.duplicate = key
            break
        seen.add(key)
    return marked


def _int(text: str) -> int | Numeral:
    """A JSON integer: an int, but -0 (a float's sign) and one longer than any field as text."""
    return int(text) if len(text.lstrip("-")) <= _INT_DIGITS and text != "-0" else Numeral(text)


def _integer(value: Any) -> Any:
    """An integer field's value: the JSON integer -0 is 0 there (its sign means something to a float only)."""
    return 0 if isinstance(value, Numeral) and value.text == "-0" else value


def _find_duplicate(doc: Any) -> tuple[str, str] | None:
    """The JSON path of the first object with a duplicate key, and that key (iterative: no depth limit)."""
    stack: list[tuple[Any, str]] = [(doc, "$")]
    while stack:
        node, path = stack.pop()
        if isinstance(node, _Duplicates):
            return path, node.duplicate
        if isinstance(node, dict):
            stack.extend((v, f"{path}.{quote(k)}") for k, v in reversed(node.items()))
        elif isinstance(node, list):
            stack.extend((v, f"{path}[{i}]") for i, v in reversed(list(enumerate(node))))
    return None


def loads(text: str) -> Any:
    """Canonical JSON text as Python data: exact numbers, and duplicate keys refused.

    Raises json.JSONDecodeError (and RecursionError, ValueError) as ``json.loads``
    does, and JsonShapeError naming the path of a duplicate key."""
    doc = json.loads(text, parse_float=Numeral, parse_int=_int, parse_constant=Numeral,
                     object_pairs_hook=_pairs)
    found = _find_duplicate(doc)
    if found is not None:
        raise JsonShapeError(f"{found[0]}: duplicate key '{quote(found[1])}': text must not say a thing twice")
    return doc


def float_json(bits: int) -> float | str:
    """A binary32 bit pattern as canonical JSON: a number, or "0x..." for -0, inf, NaN."""
    v: float = _F.unpack(_I.pack(bits))[0]
    if not math.isfinite(v) or (v == 0.0 and bits >> 31):
        return f"0x{bits:08x}"
    return v


def float_bits(value: Any, where: str) -> int:
    """A JSON float: a number (rounded once to the nearest binary32) or "0x" and 8 hex digits."""
    if isinstance(value, str):
        if _PATTERN.fullmatch(value):
            return int(value[2:], 16)
        raise JsonShapeError(f"{where}: {_show(value)} is neither a number nor a bit pattern (0x and 8 hex digits)")
    if isinstance(value, bool) or not isinstance(value, (int, float, Decimal, Numeral)):
        raise JsonShapeError(f"{where}: expected a float, got {type(value).__name__}")
    try:
        if isinstance(value, Numeral):  # JSON text: the reader of CUT's numbers too
            return read_decimal(value.text)
        if isinstance(value, int):
            return read_decimal(str(value))
        return _nearest_bits(value)  # a float (the double it is) or a Decimal given by a caller
    except (OutOfRange, NotDecimal) as exc:
        raise JsonShapeError(f"{where}: {_show(value)} {exc} (NaN and infinity are written as "
                             f"their bit pattern: 0x and 8 hex digits)") from None


def _str_json(raw: bytes) -> str:
    return raw.rstrip(T.PAD).decode("latin-1")


def _fields_json(fields: tuple[T.FieldInfo, ...], vals: tuple[Any, ...]) -> dict[str, Any]:
    out: dict[str, Any] = {}
    j = 0
    for f in fields:
        if f.per:  # a repeated group: a list of n items (issue 25, point 3)
            one = (replace(f, count=f.per, per=0),)
            out[f.name] = [_fields_json(one, vals[k:k + f.per])[f.name] for k in range(j, j + f.count, f.per)]
        elif f.kind == "float":
            items = [float_json(b) for b in vals[j:j + f.count]]
            out[f.name] = items if f.count > 1 else items[0]
        elif f.kind == "string":
            out[f.name] = _str_json(vals[j])
        elif f.kind == "bytes":
            out[f.name] = vals[j].hex()
        else:
            out[f.name] = vals[j]
        j += f.count
    return out


def to_canonical(model: Cbf) -> dict[str, Any]:
    from .fields import pack_fields

    vid = model.version_id
    info = T.HEADERS[T.VERSION_BY_ID[vid].header]
    hbytes = pack_fields(info.fields, info.struct, model.header, "header")
    header = _fields_json(info.fields, info.struct.unpack(hbytes))
    names = {f.role: f.name for f in T.RECORD_FIELDS}
    chk_name = T.ARG_CHECKSUM.name
    records = []
    for r in model.records:
        rec: dict[str, Any] = {}
        if r.offset is not None:
            rec["offset"] = r.offset
        rec[names["sequence"]] = r.sequence
        rec[names["code"]] = r.code
        rec[names["code_copy"]] = r.code if r.code_copy is None else r.code_copy
        rec[names["arg_size"]] = len(r.raw_args)
        rec[names["reserved"]] = r.reserved
        rec[chk_name] = r.arg_checksum
        cmd = T.BY_CODE.get(r.code)
        rec["command"] = cmd.name if cmd else None
        lay = cmd.layout_for_size(vid, len(r.raw_args)) if cmd else None
        if lay is None:
            rec["args"] = None
            rec["raw_args"] = bytes(r.raw_args).hex()
        else:
            rec["args"] = _fields_json(lay.args, lay.bits.unpack(r.raw_args))
        records.append(rec)
    return {"header": header, "records": records, "trailing": model.trailing.hex()}


# -- JSON -> model ----------------------------------------------------------------
def _hex(value: Any, where: str, size: int | None = None) -> bytes:
    if not isinstance(value, str):
        raise JsonShapeError(f"{where}: expected a hex string")
    try:
        raw = bytes.fromhex(value)
    except ValueError:
        raise JsonShapeError(f"{where}: {value!r} is not hex") from None
    if size is not None and len(raw) != size:
        raise JsonShapeError(f"{where}: {len(raw)} bytes, the field holds {size}")
    return raw


def _uint(value: Any, where: str, size: int) -> int:
    value = _integer(value)
    if isinstance(value, bool) or not isinstance(value, int) or not 0 <= value < 1 << (8 * size):
        raise JsonShapeError(f"{where}: expected an unsigned {8 * size}-bit integer, got {_show(value)}")
    return int(value)


def _str(value: Any, where: str, size: int) -> bytes:
    if not isinstance(value, str):
        raise JsonShapeError(f"{where}: expected a string")
    try:
        raw = value.encode("latin-1")
    except UnicodeEncodeError:
        raise JsonShapeError(f"{where}: character outside U+0000..U+00FF") from None
    if len(raw) > size:
        raise JsonShapeError(f"{where}: {len(raw)} characters, the field holds {size}")
    return raw + T.PAD * (size - len(raw))


def _pack_json(fields: tuple[T.FieldInfo, ...], st: struct.Struct, obj: dict[str, Any], where: str) -> bytes:
    vals: list[Any] = []
    for f in fields:
        w = f"{where}.{f.name}"
        v = obj[f.name]
        if f.per:  # a repeated group: a list of exactly the layout's n items
            if not isinstance(v, list) or len(v) != f.items:
                raise JsonShapeError(f"{w}: expected a list of {f.items} items")
            one = (replace(f, count=f.per, per=0),)
            st1 = struct.Struct(_fmt(one))
            for k, item in enumerate(v):
                vals.extend(st1.unpack(_pack_json(one, st1, {f.name: item}, f"{w}[{k}]")))
            continue
        if f.kind == "float":
            items = v if f.count > 1 else [v]
            if not isinstance(items, list) or len(items) != f.count:
                raise JsonShapeError(f"{w}: expected {f.count} floats")
            vals.extend(float_bits(x, f"{w}[{k}]" if f.count > 1 else w) for k, x in enumerate(items))
        elif f.kind == "uint":
            vals.append(_uint(v, w, f.elem_size))
        elif f.is_int:  # signed
            v = _integer(v)
            if isinstance(v, bool) or not isinstance(v, int) or not f.holds(v):
                raise JsonShapeError(f"{w}: expected {f.int_name}, got {_show(v)}")
            vals.append(int(v))
        elif f.kind == "string":
            vals.append(_str(v, w, f.size))
        else:
            vals.append(_hex(v, w, f.size))
    return st.pack(*vals)


def _fmt(fields: tuple[T.FieldInfo, ...]) -> str:
    """The bit-pattern struct format of fields (floats as their unsigned bits, as _pack_json packs)."""
    return T.BO + "".join(f.bits_fmt for f in fields)


def _items_fit(lay: T.LayoutInfo, args: dict[str, Any]) -> bool:
    """A layout made for n items of a repeated group fits a JSON group of n items (else any)."""
    rep = lay.repeated
    return rep is None or (isinstance(args.get(rep.name), list) and len(args[rep.name]) == rep.items)


def _obj(value: Any, where: str) -> dict[str, Any]:
    if not isinstance(value, dict):
        got = f"the number {_show(value)}" if isinstance(value, (Decimal, Numeral)) else type(value).__name__
        raise JsonShapeError(f"{where}: expected an object, got {got}")
    return value


def _header_values(h: dict[str, Any], info: Any) -> dict[str, Any]:
    """The header's values by field: given, or the stored fields' and strings' defaults."""
    hv: dict[str, Any] = {}
    for f in info.fields:
        if f.name in h:
            hv[f.name] = h[f.name]
        elif f.role in ("checksum", "command_count") or f.magic is not None:
            hv[f.name] = (f.magic or 0)
        elif f.kind == "string":
            hv[f.name] = ""
        elif f.kind == "bytes":
            hv[f.name] = "00" * f.size
        else:
            raise JsonShapeError(f"$.header: missing {f.name}")
    unknown = set(h) - {f.name for f in info.fields}
    if unknown:
        raise JsonShapeError(f"$.header: unknown key '{quote(sorted(unknown)[0])}' for header layout {info.id}")
    return hv


_NAMES = {f.role: f.name for f in T.RECORD_FIELDS}


def _record_code(r: dict[str, Any], w: str) -> int:
    """The record's code: given, or its command's (by any of its names)."""
    code = r.get(_NAMES["code"])
    if code is None:
        cname = r.get("command")
        if cname not in T.BY_ANY_NAME:
            raise JsonShapeError(f"{w}: needs {_NAMES['code']} or a known command name, got {cname!r}")
        code = T.BY_ANY_NAME[cname].code
    return _uint(code, f"{w}.{_NAMES['code']}", 1)


def _record_args(r: dict[str, Any], w: str, cmd: Any, code: int, vid: str) -> bytes:
    """The record's argument bytes: its args packed in the layout whose names (and size) they match,
    or its raw_args."""
    args = r.get("args")
    if args is None:
        return _hex(r.get("raw_args", ""), f"{w}.raw_args")
    a = _obj(args, f"{w}.args")
    if cmd is None:
        raise JsonShapeError(f"{w}.args: unknown code 0x{code:02X} takes raw_args only")
    want_size = r.get(_NAMES["arg_size"])
    lay = next((x for x in cmd.candidates(vid) + cmd.layouts
                if {f.name for f in x.args} == set(a) and (want_size is None or want_size == x.size)
                and _items_fit(x, a)), None)
    if lay is None:
        raise JsonShapeError(f"{w}.args: keys {sorted(a)} match no layout of {cmd.name}")
    return _pack_json(lay.args, lay.struct.__class__(lay.bits.format), a, f"{w}.args")


def _record(rv: Any, i: int, vid: str) -> Record:
    w = f"$.records[{i}]"
    r = _obj(rv, w)
    bad = set(r) - (set(_NAMES.values()) | {"offset", "command", "args", "raw_args"})
    if bad:
        raise JsonShapeError(f"{w}: unknown key '{quote(sorted(bad)[0])}'")
    code = _record_code(r, w)
    cmd = T.BY_CODE.get(code)
    if r.get("command") is not None and (cmd is None or T.BY_ANY_NAME.get(r["command"]) is not cmd):
        raise JsonShapeError(f"{w}.command: {r['command']!r} does not match code 0x{code:02X}")
    raw = _record_args(r, w, cmd, code, vid)
    size = r.get(_NAMES["arg_size"])
    if size is not None and size != len(raw):
        raise JsonShapeError(f"{w}.{_NAMES['arg_size']}: {size}, but the arguments are {len(raw)} bytes")

    def opt(role: str, size: int) -> int | None:
        v = r.get(_NAMES[role])
        return None if v is None else _uint(v, f"{w}.{_NAMES[role]}", size)

    return Record(code=code, raw_args=raw, sequence=opt("sequence", 2) or 0,
                  code_copy=opt("code_copy", 1), reserved=opt("reserved", 1) or 0,
                  arg_checksum=opt("checksum", T.ARG_CHECKSUM.size))


def from_canonical(doc: Any) -> Cbf:
    """A model from canonical JSON. Stored fields may be left out; encode fills them."""
    from .codec import decode_header

    d = _obj(doc, "$")
    extra = set(d) - {"header", "records", "trailing"}
    if extra:
        raise JsonShapeError(f"$: unknown key '{quote(sorted(extra)[0])}'")
    h = _obj(d.get("header"), "$.header")
    major = _uint(h.get(T.VMAJOR.name, 0), f"$.header.{T.VMAJOR.name}", 1)
    minor = _uint(h.get(T.VMINOR.name, 0), f"$.header.{T.VMINOR.name}", 1)
    vid = T.version_id(major, minor) or T.FALLBACK_VERSION
    info = T.HEADERS[T.VERSION_BY_ID[vid].header]
    header = decode_header(_pack_json(info.fields, info.struct, _header_values(h, info), "$.header"))
    recs = d.get("records", [])
    if not isinstance(recs, list):
        raise JsonShapeError("$.records: expected a list")
    out = [_record(rv, i, vid) for i, rv in enumerate(recs)]
    trailing = _hex(d.get("trailing", ""), "$.trailing")
    return Cbf(header, tuple(out), trailing)

