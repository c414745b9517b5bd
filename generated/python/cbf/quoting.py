"""The one quoting rule for names and values from input in what `cbf` prints (issue #35, point 1).

A path, key, cutter name or header string reaches an output line only through ``quote``:

- it is printed as it is when it is *plain*: not empty, every character plain (printable ASCII
  other than ``"`` and ``\\``, or a character from U+00A0 up that neither breaks a line, turns
  text around nor hides: not U+2028/U+2029, U+200B-U+200F, U+202A-U+202E, U+2060-U+206F,
  U+FEFF, U+FFF9-U+FFFB, U+FFFE/U+FFFF, nor a surrogate), not starting with ``:`` or a space, not ending in a
  space;
- otherwise between double quotes, with ``"`` and ``\\`` as ``\\"`` and ``\\\\``, a line feed, carriage
  return and tab as ``\\n``, ``\\r``, ``\\t``, a byte that is not UTF-8 (a file name git or a
  file system holds; Python reads it as a lone surrogate) as ``\\xHH``, any other character that
  is not plain as ``\\u{H...}``.

So a name never starts a line with ``::`` (GitHub runs such a line as a workflow command), never
carries a line break or a terminal escape, and ``unquote`` gives back its exact bytes. `cbf-c`
applies the same rule (cbf_quote in its runtime), so both tools print the same line.

``line`` is the net under every line of text printed: a character that is not plain and not a
space (a control, a line break a message still held) is escaped as ``quote`` escapes it.
"""

from __future__ import annotations

import re

HIDDEN = ((0x2028, 0x2029), (0x200B, 0x200F), (0x202A, 0x202E), (0x2060, 0x206F), (0xFEFF, 0xFEFF),
           (0xFFF9, 0xFFFB), (0xFFFE, 0xFFFF), (0xD800, 0xDFFF))
SURROGATES = (0xD800, 0xDFFF)  # last in the class: a range of lone surrogates is spelt on its own
_ESCAPES = {'"': '\\"', "\\": "\\\\", "\n": "\\n", "\r": "\\r", "\t": "\\t"}
# The characters that are not plain, as one class of small ranges: the controls (C0, DEL, C1), every
# hidden range, the surrogates. (Written as the complement of the printable ranges, a class up to
# U+10FFFF, re took ~6 ms to compile each pattern, a good part of `cbf`'s own start-up. Both forms
# left out the hidden ranges above the surrogates until round 6: U+FEFF, U+FFF9-U+FFFB and
# U+FFFE/U+FFFF printed as they are, where cbf-c quoted them.)
_NOT_PRINTABLE = "\x00-\x1f\x7f-\x9f" + "".join(
    f"{chr(lo)}-{chr(hi)}" if lo != hi else chr(lo) for lo, hi in HIDDEN if (lo, hi) != SURROGATES) + "\ud800-\udfff"
_NOT_PLAIN = re.compile("[" + _NOT_PRINTABLE + '"\\\\]')
_NOT_LINE = re.compile("[" + _NOT_PRINTABLE + "]")


def _escape(m: re.Match[str]) -> str:
    c = m.group()
    if c in _ESCAPES:
        return _ESCAPES[c]
    n = ord(c)
    if 0xDC80 <= n <= 0xDCFF:  # a byte os.fsdecode could not decode (surrogateescape)
        return f"\\x{n - 0xDC00:02X}"
    if n < 0x80:
        return f"\\x{n:02X}"
    return f"\\u{{{n:X}}}"


def is_plain(s: str) -> bool:
    """Whether ``quote`` prints ``s`` as it is."""
    return bool(s) and _NOT_PLAIN.search(s) is None and s[0] not in ": " and s[-1] != " "


def quote(s: str | bytes) -> str:
    """A name or value from input as an output line may hold it (the rule above)."""
    if isinstance(s, bytes):
        import os

        s = os.fsdecode(s)
    if is_plain(s):
        return s
    return '"' + _NOT_PLAIN.sub(_escape, s) + '"'


def json_name(s: str) -> str:
    """A name as a JSON string holds it: as it is when it is Unicode text (JSON escapes a control
    itself), ``quote``'s form when it holds bytes that are not UTF-8 (``unquote`` gives them back)."""
    try:
        s.encode("utf-8")
    except UnicodeEncodeError:
        return quote(s)
    return s


def line(text: str) -> str:
    """A line of text with every control, line break and hidden character escaped (a net under
    each printed line: its names went through ``quote`` already)."""
    return _NOT_LINE.sub(_escape, text)


def lines(text: str) -> str:
    """Text of several lines (ending in a line feed each): each line through ``line``."""
    return "".join(line(part) + "\n" for part in text.split("\n")[:-1]) + line(text.rsplit("\n", 1)[-1])


_SIMPLE = {'"': b'"', "\\": b"\\", "n": b"\n", "r": b"\r", "t": b"\t"}
_UNESCAPE = re.compile(r'\\(["\\nrt]|x[0-9A-F]{2}|u\{[0-9A-F]+\})')


def unquote(shown: str) -> bytes:
    """The exact bytes of a name ``quote`` printed (file names as os.fsencode gives them)."""
    import os

    if not (len(shown) >= 2 and shown[0] == '"' and shown[-1] == '"'):
        return os.fsencode(shown)
    out = bytearray()
    pos = 0
    body = shown[1:-1]
    for m in _UNESCAPE.finditer(body):
        out += body[pos:m.start()].encode("utf-8")
        e = m.group(1)
        if e[0] == "x":
            out.append(int(e[1:], 16))
        elif e[0] == "u":
            out += chr(int(e[2:-1], 16)).encode("utf-8", "surrogatepass")
        else:
            out += _SIMPLE[e]
        pos = m.end()
    out += body[pos:].encode("utf-8")
    return bytes(out)
