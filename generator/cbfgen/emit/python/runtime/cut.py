"""The CUT text form (implib's syntax, FORMAT-NOTES), lossless in both directions.

One command a line; the keyword is the command name in lower case; vectors
as ``< x, y, z >``; floats with the fewest digits that round-trip binary32,
in plain positional notation; a first line ``header <implant descriptor>``,
optional ``header_ext <configuration descriptor>`` and ``check_sum <n>``.
What the plain syntax cannot carry is written with the toolkit's extension
keywords (spec ``cut.extensions``), so CBF -> CUT -> CBF is byte-exact.
"""

from __future__ import annotations

import re
import struct
from collections.abc import Iterator
from decimal import Decimal
from functools import lru_cache
from typing import Any

from . import tables as T
from .errors import CutSyntaxError
from .model import Cbf, Record

C = T.CUT
EXT = C["extensions"]
_F = struct.Struct("<f")
_I = struct.Struct("<I")
_FLOAT = re.compile(C["float_pattern"])
_SEP: str = C["arg_separator"]
_DERIVED_ROLES = ("checksum", "command_count", "start_pattern", "end_pattern", "version_major", "version_minor")


def keyword(cmd: T.CommandInfo) -> str:
    return cmd.name.lower() if C["keyword_case"] == "lower" else cmd.name


_BY_KEYWORD = {keyword(c): c for c in T.COMMANDS}


@lru_cache(maxsize=4096)  # a motion starts where the last one ended: values repeat close together
def format_float(bits: int) -> str:
    """Fewest digits that give back the same binary32, positional notation."""
    v: float = _F.unpack(_I.pack(bits))[0]
    s = repr(v)
    for p in range(1, 10):
        cand = f"{v:.{p}g}"
        if _I.unpack(_F.pack(float(cand)))[0] == bits:
            s = cand
            break
    if "e" in s or "E" in s:
        s = str(format(Decimal(s), "f"))
    return s


def _plain_word(raw: bytes) -> bool:
    value = raw.rstrip(T.PAD)
    return bool(value) and all(0x21 <= b <= 0x7E for b in value)


def _profile_word(profile: str, command: str, arg: str, word: str) -> None:
    """Refuse a name the profile's CUT reader would read differently (implib reads \\w+)."""
    rule = C.get("profile_words", {}).get(profile)
    if rule is None or arg not in rule["args"] or re.fullmatch(rule["pattern"], word):
        return
    pattern = rule["pattern"]
    m = re.match(pattern, word)
    read = repr(m.group(0)) if m else "nothing"
    raise ValueError(f"{command}.{arg} {word!r}: the {profile} profile's CUT reader takes a name as {pattern} "
                     f"and would read {read}; this name cannot be written in CUT for {profile}")


def _plain_text(raw: bytes) -> bool:
    value = raw.rstrip(T.PAD)
    return all(0x20 <= b <= 0x7E for b in value) and value == value.strip(b" ")


def _plain_layout(cmd: T.CommandInfo, version: str, profile: str) -> T.LayoutInfo | None:
    """The layout a CUT reader picks for this command, version and profile."""
    own = [lay for lay in cmd.layouts_for(version) if lay.accepted_under(profile)]
    special = [lay for lay in own if profile in lay.profiles]
    chosen = special or own
    return chosen[0] if chosen else None


def _record_line(r: Record, version: str, profile: str) -> str:
    cmd = T.BY_CODE.get(r.code)
    lay = _plain_layout(cmd, version, profile) if cmd else None
    plain = (cmd is not None and lay is not None and lay.size == len(r.raw_args) and r.reserved == 0
             and (r.code_copy is None or r.code_copy == r.code))
    parts: list[str] = []
    if plain and cmd is not None and lay is not None:
        vals = lay.bits.unpack(r.raw_args)
        j = 0
        parts.append(keyword(cmd))
        for k, f in enumerate(lay.args):
            v = vals[j:j + f.count]
            j += f.count
            if f.kind == "float":
                fl = [_F.unpack(_I.pack(b))[0] for b in v]
                if not all(x == x and abs(x) != float("inf") for x in fl):
                    plain = False
                    break
                text = [format_float(b) for b in v]
                parts.append(f"{C['vector_open']} {(C['vector_separator'] + ' ').join(text)} {C['vector_close']}"
                             if f.count > 1 else text[0])
            elif f.kind == "uint":
                parts.append(str(v[0]))
            elif f.kind == "bytes":
                if any(v[0]):
                    plain = False
                    break
            elif f.text:
                if not _plain_text(v[0]) or k != len(lay.args) - 1 - sum(1 for g in lay.args[k + 1:] if g.reserved):
                    plain = False
                    break
                value = v[0].rstrip(T.PAD).decode("ascii")
                if value:
                    parts.append(value)
            else:
                if not _plain_word(v[0]):
                    plain = False
                    break
                word = v[0].rstrip(T.PAD).decode("ascii")
                _profile_word(profile, cmd.name, f.name, word)
                parts.append(word)
    if plain:
        return _SEP.join(parts)
    copy = r.code if r.code_copy is None else r.code_copy
    line = f"{EXT['record_keyword']} {r.code:02x} {copy:02x} {r.reserved:02x}"
    return line + (f" {bytes(r.raw_args).hex()}" if r.raw_args else "")


def to_cut(model: Cbf, *, profile: str = "default") -> str:
    """The CUT text of a model (records keep their order; checksums are not written)."""
    from .codec import pack_fields

    vid = model.version_id
    info = T.HEADERS[T.VERSION_BY_ID[vid].header]
    raw = pack_fields(info.fields, info.struct, model.header, "header")
    lines: list[str] = []
    extra: list[str] = []
    if model.version != T.parse_version(T.DEFAULT_VERSION):
        extra.append(f"{EXT['version_keyword']} {model.version[0]}.{model.version[1]}")
    head = C["header_keyword"]
    for f in info.fields:
        fb = raw[f.offset:f.end]
        if f.role in _DERIVED_ROLES:
            continue
        if f.role in ("implant_descriptor", "configuration_descriptor") and _plain_text(fb):
            value = fb.rstrip(T.PAD).decode("ascii")
            if f.role == "implant_descriptor":
                head = f"{head} {value}" if value else head
            elif value:
                extra.append(f"{C['header_ext_keyword']} {value}")
            continue
        if f.role in ("implant_descriptor", "configuration_descriptor") or any(fb):
            extra.append(f"{EXT['field_keyword']} {f.name} {fb.hex()}")
    lines.append(head)
    lines.extend(extra)
    for i, r in enumerate(model.records):
        try:
            lines.append(_record_line(r, vid, profile))
        except ValueError as exc:
            raise ValueError(f"record {i}: {exc}") from None
    if model.trailing:
        raise ValueError("trailing bytes have no CUT form")
    return "\n".join(lines) + "\n"


# -- reading -------------------------------------------------------------------------
class _Cursor:
    def __init__(self, text: str, line: int, what: str) -> None:
        self.text, self.pos, self.line, self.what = text, 0, line, what

    def fail(self, message: str) -> CutSyntaxError:
        return CutSyntaxError(f"{self.what}: {message}", line=self.line)

    def skip(self) -> None:
        while self.pos < len(self.text) and self.text[self.pos].isspace():
            self.pos += 1

    def word(self, name: str) -> str:
        self.skip()
        start = self.pos
        while self.pos < len(self.text) and not self.text[self.pos].isspace():
            self.pos += 1
        if start == self.pos:
            raise self.fail(f"missing {name}")
        return self.text[start:self.pos]

    def expect(self, token: str, name: str) -> None:
        self.skip()
        if not self.text.startswith(token, self.pos):
            raise self.fail(f"expected {token!r} in {name}")
        self.pos += len(token)

    def number(self, name: str) -> float:
        self.skip()
        m = _FLOAT.match(self.text, self.pos)
        if not m or m.end() == self.pos:
            got = self.text[self.pos:].split(maxsplit=1)
            raise self.fail(f"{name}: {got[0] if got else 'nothing'!r} is not a number")
        self.pos = m.end()
        value = float(m.group(0))
        try:
            _F.pack(value)
        except OverflowError:
            raise self.fail(f"{name}: {m.group(0)} is out of binary32 range") from None
        return value

    def rest(self) -> str:
        value = self.text[self.pos:].strip()
        self.pos = len(self.text)
        return value


def _parse_args(cur: _Cursor, lay: T.LayoutInfo) -> bytes:
    vals: list[Any] = []
    for f in lay.args:
        name = f.name
        if f.kind == "float":
            if f.count > 1:
                cur.expect(C["vector_open"], name)
                for k in range(f.count):
                    if k:
                        cur.expect(C["vector_separator"], name)
                    vals.append(cur.number(name))
                cur.expect(C["vector_close"], name)
            else:
                vals.append(cur.number(name))
        elif f.kind == "uint":
            w = cur.word(name)
            # ASCII digits only (str.isdigit also takes '²', which int() refuses), and no
            # more of them than the field's largest value has (int() refuses 4301+ digits)
            if (not (w.isascii() and w.isdigit()) or len(w.lstrip("0")) > len(str((1 << (8 * f.elem_size)) - 1))
                    or int(w) >= 1 << (8 * f.elem_size)):
                raise cur.fail(f"{name}: {w!r} is not an unsigned {8 * f.elem_size}-bit integer")
            vals.append(int(w))
        elif f.kind == "bytes":
            vals.append(bytes(f.size))
        else:
            value = cur.rest() if f.text else cur.word(name)
            try:
                raw = value.encode("ascii")
            except UnicodeEncodeError:
                raise cur.fail(f"{name}: {value!r} is not ASCII") from None
            if len(raw) > f.size:
                raise cur.fail(f"{name}: {len(raw)} characters, the field holds {f.size}")
            vals.append(raw)
    cur.skip()
    if cur.pos < len(cur.text):
        raise cur.fail(f"unexpected text {cur.text[cur.pos:]!r}")
    return lay.struct.pack(*vals)


def _hex(cur: _Cursor, name: str) -> bytes:
    w = cur.word(name)
    try:
        return bytes.fromhex(w)
    except ValueError:
        raise cur.fail(f"{name}: {w!r} is not hex") from None


def _lines(text: str, block: int = 1 << 16) -> Iterator[str]:
    """text.splitlines(), one line at a time: never a list of every line (400 MB of empty
    lines made a 3.2 GB list). Blocks end just after a newline, where a line always ends."""
    start, n = 0, len(text)
    while start < n:
        cut = text.find("\n", start + block)
        end = n if cut < 0 else cut + 1
        yield from text[start:end].splitlines()
        start = end


def from_cut(text: str, *, version: str | None = None, profile: str = "default") -> Cbf:
    """A model from CUT text. ``version`` applies when the text has no version line."""
    from .model import new_header

    vkw, fkw, rkw = EXT["version_keyword"], EXT["field_keyword"], EXT["record_keyword"]
    file_version: str | None = None
    for n, line in enumerate(_lines(text), 1):
        kw, _, rest = line.strip().partition(" ")
        if kw == vkw:
            v = rest.strip()
            if not re.fullmatch(r"\d+\.\d+", v):
                raise CutSyntaxError(f"{vkw}: {v!r} is not major.minor", line=n)
            if version is not None and T.parse_version(version) != T.parse_version(v):
                raise CutSyntaxError(f"{vkw} {v} contradicts the requested version {version}", line=n)
            file_version = v
    chosen = file_version or version or T.DEFAULT_VERSION
    major, minor = T.parse_version(chosen)
    vid = T.version_id(major, minor)
    if vid is None:
        raise CutSyntaxError(f"version {chosen} is not a version of this spec", line=1)
    info = T.HEADERS[T.VERSION_BY_ID[vid].header]
    fields: dict[str, Any] = {}
    records: list[Record] = []
    seen_header = False
    n = 0
    for n, line in enumerate(_lines(text), 1):
        stripped = line.strip()
        if not stripped:
            continue
        kw, _, rest = stripped.partition(" ")
        key = kw.lower() if C["keyword_case"] == "lower" else kw
        cur = _Cursor(rest, n, kw)
        if kw == vkw:
            continue
        if key in (C["header_keyword"], C["header_ext_keyword"]):
            role = "implant_descriptor" if key == C["header_keyword"] else "configuration_descriptor"
            f = info.by_role(role)
            if f is None:
                raise cur.fail(f"version {vid} has no {role.replace('_', ' ')}")
            value = cur.rest()
            if len(value.encode("latin-1", "replace")) > f.size:
                raise cur.fail(f"{len(value)} characters, the {f.name} holds {f.size}")
            if not value.isascii():
                raise cur.fail(f"{value!r} is not ASCII")
            fields[f.name] = value
            seen_header = seen_header or role == "implant_descriptor"
        elif key == C["checksum_keyword"]:
            w = cur.word("checksum")
            if not (w.isascii() and w.isdigit()):
                raise cur.fail(f"{w!r} is not a number")
        elif kw == fkw:
            name = cur.word("field name")
            f = next((g for g in info.fields if g.name == name and g.role not in _DERIVED_ROLES), None)
            if f is None:
                raise cur.fail(f"{name!r} is not a writable header field of layout {info.id}")
            raw = _hex(cur, name)
            if len(raw) != f.size:
                raise cur.fail(f"{name}: {len(raw)} bytes, the field holds {f.size}")
            fields[f.name] = (raw.rstrip(T.PAD).decode("latin-1") if f.kind == "string"
                              else int.from_bytes(raw, "little" if T.BO == "<" else "big") if f.kind == "uint"
                              else raw)
        elif kw == rkw:
            code = _hex(cur, "code")
            copy = _hex(cur, "code copy")
            res = _hex(cur, "reserved byte")
            if not (len(code) == len(copy) == len(res) == 1):
                raise cur.fail("code, code copy and reserved byte are one hex byte each")
            cur.skip()
            raw = _hex(cur, "arguments") if cur.pos < len(cur.text) else b""
            if len(raw) > T.LIMITS["max_arg_size"]:
                raise cur.fail(f"{len(raw)} argument bytes, at most {T.LIMITS['max_arg_size']}")
            records.append(Record(code=code[0], raw_args=raw, code_copy=copy[0], reserved=res[0]))
        else:
            cmd = _BY_KEYWORD.get(key)
            if cmd is None:
                raise CutSyntaxError(f"unknown keyword {kw!r}", line=n)
            lay = _plain_layout(cmd, vid, profile)
            if lay is None:
                raise cur.fail(f"not available in version {vid}")
            records.append(Record(code=cmd.code, raw_args=_parse_args(cur, lay)))
    if len(records) > T.LIMITS["max_commands"]:
        raise CutSyntaxError(f"{len(records)} commands, at most {T.LIMITS['max_commands']}",
                             line=n)
    return Cbf(new_header(f"{major}.{minor}", **fields), tuple(records))
