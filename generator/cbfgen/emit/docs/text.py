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
from html import escape

from ...model import Spec

SPECIAL = re.compile(r"([\\`*_\[\]<>|&#!~])")
KEYREF = re.compile(r"\b(tolerances|limits)\.([a-z][a-z0-9_]*)")


def md_escape(text: str) -> str:
    """text as Markdown that renders to exactly text (one line, safe in a table cell)."""
    return _escape(" ".join(str(text).split()))


def _escape(text: str) -> str:
    return SPECIAL.sub(r"\\\1", text)


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
    return f'<abbr title="{escape(table)}.{escape(key)}">{escape(q)}</abbr>'


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
    return "".join(out)
