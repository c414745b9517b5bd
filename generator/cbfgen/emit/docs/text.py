"""Free text of the spec as Markdown that means what it says.

Every doc, decision and check text of spec/cbf.yaml passes through prose():
Markdown's special characters are escaped (so `118*255, 68*255` stays text
and never turns into emphasis, and `|` never splits a table cell), a
reference to a tolerance or a limit (`tolerances.position_mm`) becomes its
value with its unit, the key shown only as a tooltip, and a decision or
erratum id (N1, C1, E2 ...) becomes a link to its row.
"""

from __future__ import annotations

import re

from ... import escape as esc
from ...model import Spec

_LINE_START = re.compile(r"^([#+=-]|\d+[.)])")  # what would start a heading or a list (escape.py)
KEYREF = re.compile(r"\b(tolerances|limits)\.([a-z][a-z0-9_]*)")


def md_escape(text: str) -> str:
    """text as Markdown that renders to exactly text (one line, safe in a table cell): escape.py's."""
    return esc.markdown_cell(str(text))


def _escape(text: str) -> str:
    """A piece of one line of prose, its spaces at either end kept (escape.py strips them)."""
    lead = text[:len(text) - len(text.lstrip(" "))]
    trail = text[len(text.rstrip(" ")):] if text.strip(" ") else ""
    # Not at the start of a line: escape.py's escapes of what would start a list or a heading there
    # ("1.", "-", "#") are not needed; an "x" before the text keeps them out of the result.
    inner = esc.markdown_cell("x" + text.strip(" "))[1:] if text.strip(" ") else ""
    return lead + inner + trail


def quantity(spec: Spec, table: str, key: str) -> str | None:
    """The value of tolerances.key or limits.key with its unit (from the key's suffix when it names a unit)."""
    values: dict[str, float] | dict[str, int] = spec.tolerances if table == "tolerances" else spec.limits
    if key not in values:
        return None
    value = values[key]
    base, _, suffix = key.rpartition("_")
    unit = suffix if base and suffix in spec.units else ""
    return f"{value:g} {unit}".strip() if isinstance(value, float) else f"{value} {unit}".strip()


def value_html(spec: Spec, table: str, key: str) -> str:
    """A tolerance or limit as the reader needs it: the value; the key in a tooltip."""
    q = quantity(spec, table, key) or key
    return f'<abbr title="{esc.html_text(table)}.{esc.html_text(key)}">{esc.html_text(q)}</abbr>'


def _note_ids(spec: Spec) -> dict[str, str]:
    ids = {d.id: f"decision-{d.id.lower()}" for d in spec.decisions}
    ids.update({e.id: f"erratum-{e.id.lower()}" for e in spec.errata})
    return ids


def prose(spec: Spec, text: str | None, index: str = "") -> str:
    """Escaped Markdown of one free text; index is the link to index.md from the page ("" on index.md)."""
    if not text:
        return ""
    notes = _note_ids(spec)
    pattern = re.compile(KEYREF.pattern + (r"|\b(" + "|".join(map(re.escape, notes)) + r")\b" if notes else ""))
    out, pos = [], 0
    flat = " ".join(text.split())
    for m in pattern.finditer(flat):
        if m.group(1):
            if quantity(spec, m.group(1), m.group(2)) is None:
                continue
            out += [_escape(flat[pos:m.start()]), value_html(spec, m.group(1), m.group(2))]
        else:
            out += [_escape(flat[pos:m.start()]), f"[{m.group(3)}]({index}#{notes[m.group(3)]})"]
        pos = m.end()
    out.append(_escape(flat[pos:]))
    first = _LINE_START.sub(lambda m: m.group(1)[:-1] + "\\" + m.group(1)[-1], out[0])
    return "".join([first, *out[1:]])
