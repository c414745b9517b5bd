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
decimal text rounds to binary32 once (``floats.read_decimal``, JSON's reader too) and a number
beyond the binary32 range is refused.
"""

from __future__ import annotations

import re
from array import array
from collections.abc import Callable, Iterator
from dataclasses import dataclass, replace
from functools import lru_cache
from itertools import compress, repeat
from operator import attrgetter
from typing import Any

from . import tables as T
from .errors import CutSyntaxError
from .floats import NotDecimal, OutOfRange, finite, format_float, read_decimal
from .model import Cbf, PackedRecords, Record

C = T.CUT
EXT = C["extensions"]
_FLOAT = re.compile(C["float_pattern"], re.ASCII)
_SEP: str = C["arg_separator"]
# What a CUT line cannot hold: anything but printable ASCII, and a CR that does not end the line.
_NOT_CUT = re.compile(r"[^\x20-\x7e\n\r]|\r(?!\n)")
_CUT_BYTES = bytes(range(0x20, 0x7F)) + b"\n\r"
_VERSION = re.compile(r"([0-9]{1,3})\.([0-9]{1,3})", re.ASCII)
_SHOW = 40  # characters of a bad token quoted in a message

__all__ = ["format_float", "from_cut", "keyword", "to_cut"]


def keyword(cmd: T.CommandInfo) -> str:
    return cmd.name.lower() if C["keyword_case"] == "lower" else cmd.name


_BY_KEYWORD = {keyword(c): c for c in T.COMMANDS}
# a former name's keyword reads as the command (issue 25, point 6); to_cut writes the new keyword
_BY_KEYWORD.update({(n.lower() if C["keyword_case"] == "lower" else n): c for n, c in T.BY_ANY_NAME.items()
                    if n != c.name})


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


def _sized(cmd: T.CommandInfo, lay: T.LayoutInfo, nb: int) -> T.LayoutInfo:
    """For a layout with a repeated group, its sibling made for nb argument bytes (when there is one)."""
    if lay.n is None:
        return lay
    return next((x for x in cmd.layouts if x.variant == lay.variant and x.size == nb), lay)


def _float_text(f: Any, v: tuple[Any, ...]) -> list[str] | None:
    """A float argument's words (None: a value that is not finite has no keyword line)."""
    if not all(finite(b) for b in v):
        return None
    text = [format_float(b) for b in v]
    if f.per:  # a repeated group: its n values or vectors, one after another
        return text if f.per == 1 else [
            f"{C['vector_open']} {(C['vector_separator'] + ' ').join(text[k:k + f.per])} {C['vector_close']}"
            for k in range(0, f.count, f.per)]
    return [f"{C['vector_open']} {(C['vector_separator'] + ' ').join(text)} {C['vector_close']}"
            if f.count > 1 else text[0]]


def _last_text(lay: T.LayoutInfo, k: int) -> bool:
    """Whether argument k is the last one before only reserved arguments (a text argument must be)."""
    return k == len(lay.args) - 1 - sum(1 for g in lay.args[k + 1:] if g.reserved)


def _arg_words(cmd: T.CommandInfo, lay: T.LayoutInfo, k: int, v: tuple[Any, ...], profile: str) -> list[str] | None:
    """Argument k's words on the keyword line (None: the record has no keyword line)."""
    f = lay.args[k]
    if f.kind == "float":
        return _float_text(f, v)
    if f.is_int:
        return list(map(str, v)) if f.per else [str(v[0])]
    if f.kind == "bytes":
        return None if any(v[0]) else []
    if f.text:
        if not _plain_text(v[0]) or not _last_text(lay, k):
            return None
        value = v[0].rstrip(T.PAD).decode("ascii")
        return [value] if value else []
    if not _plain_word(v[0]):
        return None
    word = v[0].rstrip(T.PAD).decode("ascii")
    _profile_word(profile, cmd.name, f.name, word)
    return [word]


def _keyword_line(r: Record, version: str, profile: str) -> str | None:
    """The record's keyword line, or None when it has none (no plain layout, a reserved byte, a code
    copy, a value only the record line keeps)."""
    cmd = T.BY_CODE.get(r.code)
    lay = _plain_layout(cmd, version, profile) if cmd else None
    if cmd is None or lay is None:
        return None
    lay = _sized(cmd, lay, len(r.raw_args))
    if lay.size != len(r.raw_args) or r.reserved != 0 or (r.code_copy is not None and r.code_copy != r.code):
        return None
    vals = lay.bits.unpack(r.raw_args)
    parts = [keyword(cmd)]
    j = 0
    for k, f in enumerate(lay.args):
        words = _arg_words(cmd, lay, k, vals[j:j + f.count], profile)
        if words is None:
            return None
        parts.extend(words)
        j += f.count
    return _SEP.join(parts)


def _record_line(r: Record, version: str, profile: str) -> str:
    line = _keyword_line(r, version, profile)
    if line is not None:
        return line
    copy = r.code if r.code_copy is None else r.code_copy
    line = f"{EXT['record_keyword']} {r.code:02x} {copy:02x} {r.reserved:02x}"
    return line + (f" {bytes(r.raw_args).hex()}" if r.raw_args else "")


def _template(cmd: T.CommandInfo, lay: T.LayoutInfo) -> str | None:
    """The line of a layout as a str.format template, one {} a number; None when a field
    is a string (those lines are written one by one, by _record_line)."""
    parts = [keyword(cmd).replace("{", "{{").replace("}", "}}")]
    vec = (C["vector_open"], C["vector_separator"] + " ", C["vector_close"])
    opn, sep, cls = (x.replace("{", "{{").replace("}", "}}") for x in vec)
    for f in lay.args:
        if f.per:  # a repeated group: n values or vectors
            one = f"{opn} {sep.join(['{}'] * f.per)} {cls}" if f.per > 1 and f.kind == "float" else "{}"
            parts.extend([one] * f.items)
        elif f.kind == "float":
            parts.append(f"{opn} {sep.join(['{}'] * f.count)} {cls}" if f.count > 1 else "{}")
        elif f.kind == "uint":
            parts.append("{}")
        elif f.kind != "bytes":
            return None
    return _SEP.join(parts)


def _column(u8: Any, at: Any, offset: int, size: int, count: int = 1) -> Any:
    """Unsigned values of ``count`` fields of ``size`` bytes at ``at + offset`` (shape (n, count))."""
    import numpy as np

    idx = at[:, None] + (offset + np.arange(size * count))
    return np.ascontiguousarray(u8[idx]).view(f"{T.BO}u{size}").astype(np.uint64)


def _key_template(k: int, version: str, profile: str) -> tuple[T.LayoutInfo, str] | None:
    """The layout and line template of the records of key k (code << 16 | nb), None: no template."""
    cmd = T.BY_CODE.get(k >> 16)
    lay = _plain_layout(cmd, version, profile) if cmd else None
    if cmd is None or lay is None:
        return None
    lay = _sized(cmd, lay, k & 0xFFFF)
    tmpl = _template(cmd, lay) if lay.size == k & 0xFFFF else None
    return None if tmpl is None else (lay, tmpl)


def _layout_columns(u8: Any, base: Any, lay: T.LayoutInfo) -> tuple[Any, list[tuple[str, Any]]]:
    """The rows a template can write (finite floats, zero reserved bytes) and the template's columns."""
    import numpy as np

    good = np.ones(len(base), dtype=bool)
    cols: list[tuple[str, Any]] = []
    for f in lay.args:
        if f.kind == "float":
            vals = _column(u8, base, f.offset, f.elem_size, f.count)
            good &= ((vals & 0x7F800000) != 0x7F800000).all(axis=1)
            cols.extend(("float", vals[:, j]) for j in range(f.count))
        elif f.kind == "uint" and f.per:
            ints = _column(u8, base, f.offset, f.elem_size, f.count)
            cols.extend(("uint", ints[:, j]) for j in range(f.count))
        elif f.kind == "uint":
            cols.append(("uint", _column(u8, base, f.offset, f.elem_size)[:, 0]))
        else:
            good &= (np.ascontiguousarray(u8[base[:, None] + (f.offset + np.arange(f.size))]) == 0).all(axis=1)
    return good, cols


def _fill(lines: Any, groups: list[tuple[Any, str, list[tuple[str, Any]]]]) -> None:
    """Each group's lines from its template, its floats formatted once per distinct value."""
    import numpy as np

    from .floats import format_floats

    floats = [c for _, _, cols in groups for kind, c in cols if kind == "float"]
    if not floats:
        for rows, tmpl, _ in groups:
            lines[rows] = [tmpl] * len(rows)
        return
    uniq, inverse = np.unique(np.concatenate(floats), return_inverse=True)
    texts = np.array(format_floats(uniq.astype(np.uint32)), dtype=object)[inverse]
    pos = 0
    for rows, tmpl, cols in groups:
        args = []
        for kind, c in cols:
            if kind == "float":
                args.append(texts[pos:pos + len(c)].tolist())
                pos += len(c)
            else:
                args.append(c.tolist())
        lines[rows] = list(map(tmpl.format, *args)) if args else [tmpl] * len(rows)


def _record_lines(records: Any, version: str, profile: str) -> list[str]:
    """The lines of the records, in order. The records of a decoded file are read as numpy
    columns, a layout at a time, and their floats formatted once per distinct value
    (floats.format_floats); a record a template cannot write (a string, a reserved byte or
    a float that is not finite, another size, a code copy) goes to _record_line."""
    source = getattr(records, "source", None)
    if source is None or len(records) < 64:
        return _lines_one_by_one(records, range(len(records)), version, profile)
    import numpy as np

    buf, offsets = source
    u8 = np.frombuffer(buf, dtype=np.uint8)
    at = np.asarray(offsets, dtype=np.int64)
    head = {role: _column(u8, at, f.offset, f.size)[:, 0] for role, f in T.RECORD_BY_ROLE.items()
            if role in ("code", "code_copy", "reserved", "arg_size")}
    n = len(at)
    lines = np.empty(n, dtype=object)
    done = np.zeros(n, dtype=bool)
    plain = (head["reserved"] == 0) & (head["code_copy"] == head["code"])
    key = head["code"] * 65536 + head["arg_size"]
    groups: list[tuple[Any, str, list[tuple[str, Any]]]] = []
    for k in np.unique(key[plain]).tolist():
        got = _key_template(k, version, profile)
        if got is None:
            continue
        lay, tmpl = got
        rows = np.flatnonzero(plain & (key == k))
        good, cols = _layout_columns(u8, at[rows] + T.HEAD_SIZE, lay)
        rows = rows[good]
        groups.append((rows, tmpl, [(kind, c[good]) for kind, c in cols]))
        done[rows] = True
    _fill(lines, groups)
    rest = np.flatnonzero(~done).tolist()
    lines[rest] = _lines_one_by_one(records, rest, version, profile) if rest else []
    return list(lines.tolist())


def _lines_one_by_one(records: Any, which: Any, version: str, profile: str) -> list[str]:
    out = []
    for i in which:
        try:
            out.append(_record_line(records[i], version, profile))
        except ValueError as exc:
            raise ValueError(f"record {i}: {exc}") from None
    return out


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
        if f.role in T.DERIVED_ROLES:
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
    lines.extend(_record_lines(model.records, vid, profile))
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
            label = "" if name.lower() == self.what.lower() else f"{name}: "  # not "speed: speed: ..."
            raise self.fail(f"{label}{_show(got[0])} is not a number" if got else f"{label}a number is missing")
        self.pos = m.end()
        try:
            return read_decimal(m.group(0))
        except (OutOfRange, NotDecimal) as exc:
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


def _parse_group(cur: _Cursor, lay: T.LayoutInfo, vals: list[Any]) -> T.LayoutInfo:
    """A repeated group's items to the end of the line (issue 25, point 3): the values go to vals,
    and the layout made for their number is returned."""
    f = lay.args[-1]
    one = replace(f, count=f.per, per=0)
    n = 0
    while True:
        cur.skip()
        if cur.pos >= len(cur.text):
            break
        vals.extend(_parse_values(cur, (one,), f"{f.name}[{n}]"))
        n += 1
    for x in T.BY_CODE[lay.code].layouts:
        if x.variant == lay.variant and x.n == n:
            return x
    assert f.repeat is not None
    raise cur.fail(f"{f.name}: {n} items; the group holds {f.repeat[0]} to {f.repeat[1]}")


def _parse_args(cur: _Cursor, lay: T.LayoutInfo) -> bytes:
    vals: list[Any] = []
    if lay.n is not None:
        vals = _parse_values(cur, lay.args[:-1])
        lay = _parse_group(cur, lay, vals)
    else:
        vals = _parse_values(cur, lay.args)
    cur.end()
    return lay.bits.pack(*vals)


def _parse_values(cur: _Cursor, fields: tuple[T.FieldInfo, ...], label: str | None = None) -> list[Any]:
    vals: list[Any] = []  # floats as their bits: packing a double as "f" would round a second time
    for f in fields:
        name = label or f.name
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
        elif f.is_int:  # signed: an optional minus, then ASCII digits, within the field's range
            w = cur.word(name)
            digits = w[1:] if w.startswith("-") else w
            if (not (digits.isascii() and digits.isdigit()) or len(digits.lstrip("0")) > len(str(-(f.lo or 0)))
                    or not f.holds(int(w))):
                raise cur.fail(f"{name}: {_show(w)} is not {f.int_name}")
            vals.append(int(w))
        elif f.kind == "bytes":
            vals.append(bytes(f.size))
        else:
            value = cur.rest() if f.text else cur.word(name)
            raw = value.encode("ascii")  # the line holds printable ASCII only
            if len(raw) > f.size:
                raise cur.fail(f"{name}: {len(raw)} characters, the field holds {f.size}")
            vals.append(raw)
    return vals


def _hex(cur: _Cursor, name: str) -> bytes:
    w = cur.word(name)
    try:
        return bytes.fromhex(w)
    except ValueError:
        raise cur.fail(f"{name}: {_show(w)} is not hex") from None


def _plain_chars(text: str) -> bool:
    """Whether every character is one a CUT line holds (a quick test; _NOT_CUT finds which is not)."""
    if not text.isascii() or ("\r" in text and "\r" in text.replace("\r\n", "")):
        return False
    step = 1 << 20  # a piece at a time: the copy as bytes stays small
    return not any(text[k:k + step].encode("ascii").translate(None, _CUT_BYTES) for k in range(0, len(text), step))


def _check_chars(text: str) -> None:
    """Refuse a character a CUT line cannot hold, with its line and column."""
    if _plain_chars(text):
        return
    bad = _NOT_CUT.search(text)
    if bad:
        at = bad.start()
        line_start = text.rfind("\n", 0, at) + 1
        char = text[at]
        what = f"character U+{ord(char):04X}" + (" (a CR not followed by LF)" if char == "\r" else "")
        raise CutSyntaxError(f"{what} is not allowed: CUT text is printable ASCII, "
                             f"and only LF or CR LF ends a line", line=text.count("\n", 0, at) + 1,
                             column=at - line_start + 1)


def _lines(text: str, checked: bool = False) -> Iterator[tuple[int, str]]:
    """Numbered lines, split at LF only (a CR before it is dropped), without a list of them all."""
    if not checked:
        _check_chars(text)
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
    if vkw not in text:  # no line can start with it
        _check_chars(text)
        return None
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


# -- the fast path ---------------------------------------------------------------------
# Most lines of a big file are a command keyword and its numbers, as to_cut writes them. A
# line of a layout whose fields are all floats (and reserved bytes) is matched by one regular
# expression, built from the model to follow the careful parser step by step (spaces skipped
# before each token; each number the longest float_pattern match there, atomic, as
# _Cursor.number takes it; nothing but spaces after the last), and its numbers are read in
# batches by floats.parse_floats. Every other line, and every line the expression does not
# match, goes to the careful parser; a number the batch cannot read sends its line there too,
# which raises the careful parser's error. tests/test_cut_fast.py checks that both paths read
# the same language into the same bytes.
_BATCH = 1 << 16  # numbers read between two batch conversions (bounds the texts held)
_CHUNK = 1 << 18  # characters of text split into lines at a time


@dataclass(frozen=True)
class _Fast:
    pattern: re.Pattern[str]
    code: int
    layout: T.LayoutInfo
    count: int  # floats on the line


def _fast_pattern(lay: T.LayoutInfo) -> str | None:
    number = f"((?>{C['float_pattern']}))"
    opn, sep, cls = (re.escape(C[k]) for k in ("vector_open", "vector_separator", "vector_close"))
    parts = []
    for f in lay.args:
        if f.kind == "float":
            parts.append(f" *{opn} *" + f" *{sep} *".join([number] * f.count) + f" *{cls}" if f.count > 1
                         else f" *{number}")
        elif f.kind != "bytes":
            return None
    return "".join(parts) + r" *\Z"


@lru_cache(maxsize=16)
def _fast_table(version: str, profile: str) -> dict[str, _Fast]:
    """Keyword -> how its lines are read on the fast path, for the layouts of this version."""
    taken = {C["header_keyword"], C["header_ext_keyword"], C["checksum_keyword"], *EXT.values()}
    table: dict[str, _Fast] = {}
    for cmd in T.COMMANDS:
        kw = keyword(cmd)
        lay = _plain_layout(cmd, version, profile)
        pattern = _fast_pattern(lay) if lay is not None else None
        if lay is None or pattern is None or kw in taken or kw.lower() in taken or " " in kw or lay.n is not None:
            continue
        count = sum(f.count for f in lay.args if f.kind == "float")
        table[kw] = _Fast(re.compile(pattern, re.ASCII), cmd.code, lay, count)
    return table


class _Records:
    """The records read so far: a Record of each careful line, the _Fast entry of each fast
    line, whose numbers wait as text for a batch conversion (``flush``)."""

    def __init__(self) -> None:
        self.items: list[_Fast | Record] = []
        self.blobs: list[bytes] = []  # the arguments of the records converted so far, one after another
        self.sizes: list[Any] = []  # and their sizes (numpy arrays)
        self.done = 0
        self.texts: list[str] = []  # the numbers of the waiting fast lines
        self.lines: list[int] = []  # their line numbers

    def flush(self, careful: Callable[[int, str], Record | None], text: str) -> None:
        """Convert the waiting lines; the first whose number cannot be read is read again by
        the careful parser, which raises its error."""
        import numpy as np

        from .floats import parse_floats

        seg = self.items[self.done:]
        if not seg:
            return
        texts, lines, self.texts, self.lines = self.texts, self.lines, [], []
        is_fast = np.fromiter(map(isinstance, seg, repeat(_Fast)), dtype=bool, count=len(seg))
        fast = np.flatnonzero(is_fast)
        entries: list[_Fast] = list(compress(seg, is_fast.tolist()))  # type: ignore[arg-type]
        sizes = np.zeros(len(seg), dtype=np.int64)
        slow = np.flatnonzero(~is_fast).tolist()
        for j in slow:
            rec = seg[j]
            assert isinstance(rec, Record)
            sizes[j] = len(rec.raw_args)
        bits: Any = None
        if entries:
            bits, bad = parse_floats(texts)
            counts = np.fromiter(map(attrgetter("count"), entries), dtype=np.int64, count=len(entries))
            starts = np.concatenate(([0], np.cumsum(counts)))
            if bad:
                n = lines[int(np.searchsorted(starts, bad[0], side="right")) - 1]
                careful(n, _nth_line(text, n))  # raises
                raise AssertionError(f"line {n}: the careful parser took a number the fast path refused")
            codes = np.fromiter(map(attrgetter("code"), entries), dtype=np.int64, count=len(entries))
            sizes[fast] = np.fromiter((e.layout.size for e in entries), dtype=np.int64, count=len(entries))
        pos = np.concatenate(([0], np.cumsum(sizes)))
        out = np.zeros(int(pos[-1]), dtype=np.uint8)
        if entries:
            for code in np.unique(codes).tolist():
                ks = np.flatnonzero(codes == code)
                entry = entries[int(ks[0])]
                vals = bits[starts[ks][:, None] + np.arange(entry.count)]
                col = 0
                for f in entry.layout.args:
                    if f.kind == "float":
                        cols = np.ascontiguousarray(vals[:, col:col + f.count]).astype(f"{T.BO}u4")
                        at = pos[fast[ks]][:, None] + (f.offset + np.arange(f.size))
                        out[at] = cols.view(np.uint8).reshape(len(ks), f.size)
                        col += f.count
        for j in slow:
            rec = seg[j]
            assert isinstance(rec, Record)
            out[pos[j]:pos[j + 1]] = np.frombuffer(rec.raw_args, dtype=np.uint8)
        self.blobs.append(out.tobytes())
        self.sizes.append(sizes)
        self.done = len(self.items)

    def records(self) -> PackedRecords:
        import numpy as np

        items = self.items
        sizes = np.concatenate(self.sizes) if self.sizes else np.zeros(0, dtype=np.int64)
        bounds = array("q", np.concatenate(([0], np.cumsum(sizes))).astype(np.int64).tobytes())
        codes = array("B", np.fromiter(map(attrgetter("code"), items), dtype=np.uint8, count=len(items)).tobytes())
        copies = array("h", [-1]) * len(items)
        reserved = array("B", [0]) * len(items)
        for j in np.flatnonzero(~np.fromiter(map(isinstance, items, repeat(_Fast)), dtype=bool,
                                             count=len(items))).tolist():
            rec = items[j]
            assert isinstance(rec, Record)
            copies[j] = -1 if rec.code_copy is None else rec.code_copy
            reserved[j] = rec.reserved
        return PackedRecords(codes, b"".join(self.blobs), bounds, copies, reserved)


def _nth_line(text: str, n: int) -> str:
    for k, line in _lines(text, checked=True):
        if k == n:
            return line
    raise IndexError(n)


def _line_chunks(text: str) -> Iterator[tuple[int, list[str]]]:
    """The lines of ``text`` as _lines numbers them, a list of about _CHUNK characters at a time."""
    n, start, size = 1, 0, len(text)
    while start < size:
        cut = text.find("\n", min(start + _CHUNK, size) - 1)
        cut = size if cut < 0 else cut + 1
        piece = text[start:cut]
        lines = piece.split("\n")
        if piece.endswith("\n"):
            lines.pop()
        if "\r" in piece:
            lines = [line[:-1] if line.endswith("\r") else line for line in lines]
        yield n, lines
        n += len(lines)
        start = cut


def from_cut(text: str, *, version: str | None = None, profile: str = "default", fast: bool = True) -> Cbf:
    """A model from CUT text. ``version`` applies when the text has no version line.

    ``fast=False`` reads every line with the careful parser: the same result, slower (the
    reference tests/test_cut_fast.py holds the fast path to)."""
    from .model import new_header

    vkw, fkw, rkw = EXT["version_keyword"], EXT["field_keyword"], EXT["record_keyword"]
    chosen = _version_line(text, vkw, version) or version or T.DEFAULT_VERSION
    major, minor = T.parse_version(chosen)
    vid = T.version_id(major, minor)
    if vid is None:
        at = next((n for n, line in _lines(text, checked=True) if line.strip(" ").partition(" ")[0] == vkw), 1)
        raise CutSyntaxError(f"version {chosen} is not a version of this spec", line=at)  # its line (cbf-c's too)
    info = T.HEADERS[T.VERSION_BY_ID[vid].header]
    fields: dict[str, Any] = {}
    set_on: dict[str, int] = {}  # header field (or check_sum) -> the line that set it
    limit = T.LIMITS["max_commands"]
    stated: list[tuple[int, str]] = []  # the check_sum line: (line, number), compared at the end

    def once(cur: _Cursor, name: str) -> None:
        if name in set_on:
            raise cur.fail(f"{name} is already set on line {set_on[name]}; a header line is given once")
        set_on[name] = cur.line

    def descriptor(cur: _Cursor, key: str) -> None:
        role = "implant_descriptor" if key == C["header_keyword"] else "configuration_descriptor"
        f = info.by_role(role)
        if f is None:
            raise cur.fail(f"version {vid} has no {role.replace('_', ' ')}")
        once(cur, f.name)
        value = cur.rest()
        if len(value) > f.size:
            raise cur.fail(f"{len(value)} characters, the {f.name} holds {f.size}")
        fields[f.name] = value

    def checksum(cur: _Cursor, n: int) -> None:
        once(cur, C["checksum_keyword"])
        w = cur.word("checksum")
        if not (w.isascii() and w.isdigit()):
            raise cur.fail(f"{_show(w)} is not a number")
        cur.end()
        stated.append((n, w))

    def header_field(cur: _Cursor) -> None:
        name = cur.word("field name")
        f = next((g for g in info.fields if g.name == name and g.role not in T.DERIVED_ROLES), None)
        if f is None:
            raise cur.fail(f"{_show(name)} is not a writable header field of layout {info.id}")
        once(cur, f.name)
        raw = _hex(cur, name)
        if len(raw) != f.size:
            raise cur.fail(f"{name}: {len(raw)} bytes, the field holds {f.size}")
        cur.end()
        fields[f.name] = (raw.rstrip(T.PAD).decode("latin-1") if f.kind == "string"
                          else int.from_bytes(raw, "little" if T.BO == "<" else "big", signed=f.kind == "sint")
                          if f.is_int
                          else raw)

    def raw_record(cur: _Cursor) -> Record:
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
        return Record(code=code[0], raw_args=raw, code_copy=copy[0], reserved=res[0])

    def keyword_record(cur: _Cursor, key: str, kw: str, n: int) -> Record:
        cmd = _BY_KEYWORD.get(key)
        if cmd is None:
            raise CutSyntaxError(f"unknown keyword {_show(kw)}", line=n)
        lay = _plain_layout(cmd, vid, profile)
        if lay is None:
            raise cur.fail(f"not available in version {vid}")
        return Record(code=cmd.code, raw_args=_parse_args(cur, lay))

    def careful(n: int, line: str) -> Record | None:
        """One line, read by the careful parser (issue 13): a record, or None for a header line."""
        stripped = line.strip(" ")
        if not stripped:
            return None
        kw, _, rest = stripped.partition(" ")
        key = kw.lower() if C["keyword_case"] == "lower" else kw
        cur = _Cursor(rest, n, kw)
        if kw == vkw:
            return None
        if key in (C["header_keyword"], C["header_ext_keyword"]):
            descriptor(cur, key)
        elif key == C["checksum_keyword"]:
            checksum(cur, n)
        elif kw == fkw:
            header_field(cur)
        elif kw == rkw:
            return raw_record(cur)
        else:
            return keyword_record(cur, key, kw, n)
        return None

    out = _Records()
    items, texts, lines = out.items, out.texts, out.lines
    table = _fast_table(vid, profile) if fast else {}
    get = table.get
    for first, chunk in _line_chunks(text):
        for n, line in enumerate(chunk, first):
            sp = line.find(" ")
            entry = get(line if sp < 0 else line[:sp])
            m = entry.pattern.match(line, len(line) if sp < 0 else sp) if entry is not None else None
            if m is not None and entry is not None:
                items.append(entry)
                texts.extend(m.groups())
                lines.append(n)
            else:
                try:
                    rec = careful(n, line)
                except CutSyntaxError:
                    out.flush(careful, text)  # a line before this one may hold the first error
                    raise
                if rec is None:
                    continue
                items.append(rec)
            if len(items) > limit:
                out.flush(careful, text)
                raise CutSyntaxError(f"{len(items)} commands, at most {limit}", line=n)
        if len(texts) >= _BATCH:
            out.flush(careful, text)
            texts, lines = out.texts, out.lines
    out.flush(careful, text)
    model = Cbf(new_header(f"{major}.{minor}", **fields), out.records())
    if stated:
        _check_sum(model, *stated[0], profile)
    return model


# -- check_sum (issue 26) ------------------------------------------------------------
def _check_sum(model: Cbf, line: int, stated: str, profile: str) -> None:
    """Refuse a check_sum line whose number is not the file checksum of the CBF the text encodes to
    (any of the file coverages the profile accepts): the companion document says so."""
    from .codec import pack_file
    from .validation import validate

    fsum = T.HEADER_CHECKSUM_FIELDS.get("file")
    if fsum is None:
        raise CutSyntaxError(f"{C['checksum_keyword']}: this spec's header has no file checksum", line=line)
    try:
        data = bytearray(pack_file(model, profile=profile))
    except (ValueError, OverflowError) as exc:
        raise CutSyntaxError(f"{C['checksum_keyword']}: the text does not encode, so no checksum compares: {exc}",
                             line=line) from None
    computed = int.from_bytes(data[fsum.offset:fsum.offset + fsum.size], "little" if T.BO == "<" else "big")
    value = int(stated)
    if value == computed:
        return
    if value < 1 << (8 * fsum.size):  # another coverage the profile accepts may give this number
        data[fsum.offset:fsum.offset + fsum.size] = value.to_bytes(fsum.size, "little" if T.BO == "<" else "big")
        if not any(f.check == _FILE_CHECK for f in validate(bytes(data), profile=profile)):
            return
    raise CutSyntaxError(f"{C['checksum_keyword']}: {_show(stated)} is not the file checksum of this text, "
                         f"{computed}", line=line)


_FILE_CHECK = next(c["id"] for c in T.checks_of("file_checksum"))
