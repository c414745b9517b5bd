"""Spec names and text as C: identifiers, macros, comments, numbers, and the C type of a field (from
the registry). Every spec string reaches cbf.h through these or render.py's c_str filter (string
literals): escape.py's C rules."""

from __future__ import annotations

import re

from ...escape import RESERVED, c_comment, keyword_clash, one_line
from ...model import Field


def cname(name: str) -> str:
    """A C identifier for a spec name: lower case, ASCII. A name that is reserved in C or C++ is
    refused (the loader refuses it first, escape.keyword_clash: one spelling in every binding)."""
    s = re.sub(r"\W+", "_", name, flags=re.ASCII).strip("_").lower()
    if not s or s[0].isdigit():
        s = "x" + s
    if s in RESERVED["C++"]:
        raise ValueError(f"C binding: the name {name!r} is reserved in C or C++ ({keyword_clash(name)})")
    return s


def macro(name: str) -> str:
    """An upper-case macro fragment for a spec id ("9.8.7" -> 9_8_7, "1.x" -> 1_X), ASCII only."""
    return re.sub(r"\W+", "_", name, flags=re.ASCII).strip("_").upper()


# What starts a Doxygen command, an HTML tag or an entity in a /** */ comment (clang -Wdocumentation
# warns on an unknown \cmd, a lone <b, a \b without its word): escaped the Doxygen way, \x.
_DOXYGEN = re.compile(r"([\\@]|<(?=[A-Za-z/!?])|&(?=[A-Za-z#]))")


def comment(text: str) -> str:
    """Spec text on one line, safe inside /* */, /** */ and after // (escape.c_comment: no comment
    delimiters, no trigraphs, no line splice), then Doxygen's escapes: \\ and @, and < or & where
    a tag or an entity would start."""
    return _DOXYGEN.sub(r"\\\1", c_comment(one_line(text)))


def cfloat(x: float) -> str:
    r = repr(float(x))
    return r if any(c in r for c in ".eE") else r + ".0"


def ctype(f: Field) -> tuple[str, str]:
    """(type, array suffix) of a struct member for a field: the registry type's C type, an array
    of them for a vector; a string is char[N + 1] (NUL-terminated copy), bytes uint8_t[N]."""
    t = f.ftype
    if t.c_type is not None:
        return t.c_type, (f"[{f.count}]" if f.count > 1 else "")
    if t.kind == "string":
        return "char", f"[{f.size} + 1]"
    return "uint8_t", f"[{f.size}]"


def member_doc(f: Field, units: dict[str, str]) -> str:
    """A struct member's documentation as plain text (structs.h.j2 spells it as a comment, |comment)."""
    parts = [f.doc.rstrip(".") + "."]
    t = f.ftype
    what = (f"string({f.size}), NUL-terminated copy" if t.kind == "string" else f"{f.size} raw bytes"
            if t.kind == "bytes" else t.float_format.removeprefix("IEEE-754 ") if t.float_format
            else f"{t.kind[0]}{t.bits}")  # u32, s16
    if t.size is not None and f.count > 1:
        what += f" x {f.count}"
    extra = [what, f"offset {f.offset}"]
    if f.unit:
        extra.append(f"unit {f.unit} ({units.get(f.unit, '').rstrip('.')})")
    if f.clause:
        extra.append(f"clause {f.clause}")
    if f.reserved:
        extra.append("reserved, kept verbatim")
    return " ".join(parts) + " [" + "; ".join(extra) + "]"


def c_or(items: tuple[object, ...] | list[object], each: str, empty: str) -> str:
    """A C bit mask: each item spelled by ``each`` (a str.format pattern), joined by |, or ``empty``."""
    return " | ".join(each.format(x) for x in items) or empty
