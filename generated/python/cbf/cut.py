"""The CUT text form (implib's syntax, FORMAT-NOTES), lossless in both directions.

One command a line; the keyword is the command name in lower case; vectors
as ``< x, y, z >``; floats with the fewest digits that round-trip binary32,
in plain positional notation; a first line ``header <implant descriptor>``,
optional ``header_ext <configuration descriptor>`` and ``check_sum <n>``.
What the plain syntax cannot carry is written with the toolkit's extension
keywords (spec ``cut.extensions``), so CBF -> CUT -> CBF is byte-exact.

Reading never changes what the text means (issue 13): a line holds printable
ASCII and ends at LF or CR LF, any other character (a control character, a
lone CR, U+2028, ...) is refused with its line and column; a header line
(``header``, ``header_ext``, ``check_sum``, ``cbf_version``, ``cbf_field`` of
one field, or two of them that set the same field) given twice is refused,
even when both say the same; every keyword refuses text after its arguments;
decimal text rounds to binary32 once (``floats.parse_float``) and a number
beyond the binary32 range is refused.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from typing import Any

from . import tables as T
from .errors import CutSyntaxError
from .floats import OutOfRange, finite, format_float, parse_float
from .model import Cbf, Record

C = T.CUT
EXT = C["extensions"]
_FLOAT = re.compile(C["float_pattern"], re.ASCII)
_SEP: str = C["arg_separator"]
_DERIVED_ROLES = ("checksum", "command_count", "start_pattern", "end_pattern", "version_major", "version_minor")
# What a CUT line cannot hold: anything but printable ASCII, and a CR that does not end the line.
_NOT_CUT = re.compile(r"[^\x20-\x7e\n\r]|\r(?!\n)")
_VERSION = re.compile(r"([0-9]{1,3})\.([0-9]{1,3})", re.ASCII)
_SHOW = 40  # characters of a bad token quoted in a message

__all__ = ["format_float", "from_cut", "keyword", "to_cut"]


def keyword(cmd: T.CommandInfo) -> str:
    return cmd.name.lower() if C["keyword_case"] == "lower" else cmd.name


_BY_KEYWORD = {keyword(c): c for c in T.COMMANDS}


def _show(text: str) -> str:
    """A token for a message: quoted, and cut short when long."""
    if len(text) <= _SHOW:
        return repr(text)
    return f"{text[:_SHOW]!r}... ({len(text)} characters)"


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
                if not all(finite(b) for b in v):
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
    from .fields import pack_fields

    vid = model.version_id
    info = T.HEADERS[T.VERSION_BY_ID[vid].header]
    raw = pack_fields(info.fields, info.struct, model.header, "header")
    lines: list[str] = []
    extra: list[str] = []
    if model.version != T.parse_version(T.DEFAULT_VERSION):
        extra.append(f"{EXT['version_keyword']} {model.version[0]}.{model.version[1]}")
    head = C["header_keyword"]
    # The header line, unless a cbf_field line carries the implant descriptor (never both: a reader
    # refuses a field set twice)
    head_line = info.by_role("implant_descriptor") is not None
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
            head_line = head_line and f.role != "implant_descriptor"
    if head_line:
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
        while self.pos < len(self.text) and self.text[self.pos] == " ":
            self.pos += 1

    def word(self, name: str) -> str:
        self.skip()
        start = self.pos
        end = self.text.find(" ", start)
        self.pos = len(self.text) if end < 0 else end
        if start == self.pos:
            raise self.fail(f"missing {name}")
        return self.text[start:self.pos]

    def expect(self, token: str, name: str) -> None:
        self.skip()
        if not self.text.startswith(token, self.pos):
            raise self.fail(f"expected {token!r} in {name}")
        self.pos += len(token)

    def number(self, name: str) -> int:
        """The bits of the binary32 nearest the decimal text here (rounded once)."""
        self.skip()
        m = _FLOAT.match(self.text, self.pos)
        if not m or m.end() == self.pos:
            got = self.text[self.pos:].split(maxsplit=1)
            raise self.fail(f"{name}: {_show(got[0]) if got else 'nothing'} is not a number")
        self.pos = m.end()
        try:
            return parse_float(m.group(0))
        except OutOfRange as exc:
            raise self.fail(f"{name}: {_show(m.group(0))} {exc}") from None

    def rest(self) -> str:
        value = self.text[self.pos:].strip(" ")
        self.pos = len(self.text)
        return value

    def end(self) -> None:
        """Nothing but spaces may follow the arguments."""
        self.skip()
        if self.pos < len(self.text):
            raise self.fail(f"unexpected text {_show(self.text[self.pos:])}")


def _parse_args(cur: _Cursor, lay: T.LayoutInfo) -> bytes:
    vals: list[Any] = []  # floats as their bits: packing a double as "f" would round a second time
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
                raise cur.fail(f"{name}: {_show(w)} is not an unsigned {8 * f.elem_size}-bit integer")
            vals.append(int(w))
        elif f.kind == "bytes":
            vals.append(bytes(f.size))
        else:
            value = cur.rest() if f.text else cur.word(name)
            raw = value.encode("ascii")  # the line holds printable ASCII only
            if len(raw) > f.size:
                raise cur.fail(f"{name}: {len(raw)} characters, the field holds {f.size}")
            vals.append(raw)
    cur.end()
    return lay.bits.pack(*vals)


def _hex(cur: _Cursor, name: str) -> bytes:
    w = cur.word(name)
    try:
        return bytes.fromhex(w)
    except ValueError:
        raise cur.fail(f"{name}: {_show(w)} is not hex") from None


def _lines(text: str) -> Iterator[tuple[int, str]]:
    """Numbered lines, split at LF only (a CR before it is dropped), without a list of them all."""
    bad = _NOT_CUT.search(text)
    if bad:
        at = bad.start()
        line_start = text.rfind("\n", 0, at) + 1
        char = text[at]
        what = f"character U+{ord(char):04X}" + (" (a CR not followed by LF)" if char == "\r" else "")
        raise CutSyntaxError(f"{what} is not allowed: CUT text is printable ASCII, "
                             f"and only LF or CR LF ends a line", line=text.count("\n", 0, at) + 1,
                             column=at - line_start + 1)
    n, start, size = 1, 0, len(text)
    while start < size:
        end = text.find("\n", start)
        nxt = end + 1
        if end < 0:
            end = nxt = size
        yield n, text[start:end - 1] if end > start and text[end - 1] == "\r" else text[start:end]
        n, start = n + 1, nxt


def _version_line(text: str, vkw: str, requested: str | None) -> str | None:
    """The version the text's one version line names (bounded: each part is a byte)."""
    found: tuple[int, str] | None = None
    for n, line in _lines(text):
        kw, _, rest = line.strip(" ").partition(" ")
        if kw != vkw:
            continue
        if found is not None:
            raise CutSyntaxError(f"{vkw}: a second version line (the first is line {found[0]}); "
                                 f"a header line is given once", line=n)
        v = rest.strip(" ")
        m = _VERSION.fullmatch(v)
        if not m or max(int(m.group(1)), int(m.group(2))) > 255:
            raise CutSyntaxError(f"{vkw}: {_show(v)} is not major.minor (two numbers 0 to 255)", line=n)
        if requested is not None and T.parse_version(requested) != T.parse_version(v):
            raise CutSyntaxError(f"{vkw} {v} contradicts the requested version {requested}", line=n)
        found = (n, v)
    return found[1] if found else None


def from_cut(text: str, *, version: str | None = None, profile: str = "default") -> Cbf:
    """A model from CUT text. ``version`` applies when the text has no version line."""
    from .model import new_header

    vkw, fkw, rkw = EXT["version_keyword"], EXT["field_keyword"], EXT["record_keyword"]
    chosen = _version_line(text, vkw, version) or version or T.DEFAULT_VERSION
    major, minor = T.parse_version(chosen)
    vid = T.version_id(major, minor)
    if vid is None:
        raise CutSyntaxError(f"version {chosen} is not a version of this spec", line=1)
    info = T.HEADERS[T.VERSION_BY_ID[vid].header]
    fields: dict[str, Any] = {}
    set_on: dict[str, int] = {}  # header field (or check_sum) -> the line that set it
    records: list[Record] = []
    limit = T.LIMITS["max_commands"]

    def once(cur: _Cursor, name: str) -> None:
        if name in set_on:
            raise cur.fail(f"{name} is already set on line {set_on[name]}; a header line is given once")
        set_on[name] = cur.line

    for n, line in _lines(text):
        stripped = line.strip(" ")
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
            once(cur, f.name)
            value = cur.rest()
            if len(value) > f.size:
                raise cur.fail(f"{len(value)} characters, the {f.name} holds {f.size}")
            fields[f.name] = value
        elif key == C["checksum_keyword"]:
            once(cur, C["checksum_keyword"])
            w = cur.word("checksum")
            if not (w.isascii() and w.isdigit()):
                raise cur.fail(f"{_show(w)} is not a number")
            cur.end()
        elif kw == fkw:
            name = cur.word("field name")
            f = next((g for g in info.fields if g.name == name and g.role not in _DERIVED_ROLES), None)
            if f is None:
                raise cur.fail(f"{_show(name)} is not a writable header field of layout {info.id}")
            once(cur, f.name)
            raw = _hex(cur, name)
            if len(raw) != f.size:
                raise cur.fail(f"{name}: {len(raw)} bytes, the field holds {f.size}")
            cur.end()
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
            cur.end()
            records.append(Record(code=code[0], raw_args=raw, code_copy=copy[0], reserved=res[0]))
        else:
            cmd = _BY_KEYWORD.get(key)
            if cmd is None:
                raise CutSyntaxError(f"unknown keyword {_show(kw)}", line=n)
            lay = _plain_layout(cmd, vid, profile)
            if lay is None:
                raise cur.fail(f"not available in version {vid}")
            records.append(Record(code=cmd.code, raw_args=_parse_args(cur, lay)))
        if len(records) > limit:
            raise CutSyntaxError(f"{len(records)} commands, at most {limit}", line=n)
    return Cbf(new_header(f"{major}.{minor}", **fields), tuple(records))
