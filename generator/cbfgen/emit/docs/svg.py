"""SVG figures for the format documentation, written as text from the model.

Byte-field diagrams place every field at its offset and size as the model
gives them (header layouts, the record head, command arguments); the motion
figure labels its points with the argument names of the model's circle and
helix commands. The output is deterministic: fixed geometry, rounded
coordinates, no timestamps, no ids from memory addresses.
"""

from __future__ import annotations

import math
import textwrap
from collections.abc import Sequence
from html import escape

from ...model import Field

CELL = 46  # width of one byte
ROW = 40  # height of one row of bytes
LEFT = 52  # room for the row offsets
TOP = 48  # room for the title and the byte ruler
CHAR = 7.0  # width of one character at FONT px (monospace)
FONT = 12
LEGEND_LINE = 17

FILL = {
    "magic": "#f7d9a8",
    "checksum": "#f4b8b8",
    "reserved": "#e2e2e2",
    "string": "#cfe3f7",
    "bytes": "#ececec",
    "float": "#d3efcd",
    "uint": "#e4daf5",
    "sint": "#e4daf5",  # every integer alike (registry.FIELD_KINDS)
}


def _x(v: float) -> str:
    """A coordinate as short, stable text."""
    return f"{v:.1f}".rstrip("0").rstrip(".")


def category(f: Field) -> str:
    """The colour class of a field: magic, checksum, reserved, or its kind."""
    if f.magic is not None:
        return "magic"
    if f.checksum:
        return "checksum"
    if f.reserved or f.role == "reserved":
        return "reserved"
    return f.kind


def _segments(f: Field, per_row: int) -> list[tuple[int, int, int]]:
    """(row, first byte in row, byte count) for each row a field touches."""
    out = []
    pos = f.offset
    while pos < f.end:
        row, col = divmod(pos, per_row)
        n = min(f.end - pos, per_row - col)
        out.append((row, col, n))
        pos += n
    return out


def _label(text: str, width: float) -> bool:
    return len(text) * CHAR + 6 <= width


def _type_text(f: Field) -> str:
    if f.count > 1:
        return f"{f.type}({f.count})"
    if f.kind in ("string", "bytes"):
        return f"{f.type}({f.size})"
    return f.type


def _open(width: float, height: float, title: str | list[str]) -> list[str]:
    heads = [title] if isinstance(title, str) else title
    whole = " ".join(heads)
    return [
        '<?xml version="1.0" encoding="UTF-8"?>',
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{_x(width)}" height="{_x(height)}" '
        f'viewBox="0 0 {_x(width)} {_x(height)}" role="img" font-family="monospace" font-size="{FONT}">',
        f"<title>{escape(whole)}</title>",
        f'<rect x="0" y="0" width="{_x(width)}" height="{_x(height)}" fill="#ffffff"/>',
        *(f'<text x="{LEFT}" y="{18 + i * LEGEND_LINE}" font-size="14" font-weight="bold">'
          f"{escape(head)}</text>" for i, head in enumerate(heads)),
    ]


def box_label(k: int, name: str, width: float, cont: bool) -> list[str]:
    """The lines written in one box of field k: its name, or its legend number when the name does not fit;
    every piece after the first is marked as a continuation. Never empty: a box always says what it is."""
    first = [[name], [str(k)]]
    rest = [[f"{name} (cont.)"], [name, "(cont.)"], [str(k), "(cont.)"], [str(k), "cont."], [f"{k}+"]]
    for lines in rest if cont else first:
        if all(_label(line, width) for line in lines):
            return lines
    return (rest if cont else first)[-1]


def _field_shapes(k: int, f: Field, per_row: int, cell: float = CELL) -> list[str]:
    segs = _segments(f, per_row)
    fill = FILL.get(category(f), "#ffffff")
    out = [f"<g><title>{escape(f'{f.name}: offset {f.offset}, {f.size} bytes, {_type_text(f)}')}</title>"]
    for n_seg, (row, col, n) in enumerate(segs):
        x, y, w = LEFT + col * cell, TOP + row * ROW, n * cell
        out.append(f'<rect x="{_x(x)}" y="{_x(y)}" width="{_x(w)}" height="{ROW}" fill="{fill}" stroke="#333333"/>')
        lines = box_label(k, f.name, w, n_seg > 0)
        cx = _x(x + w / 2)
        if len(lines) == 1:
            out.append(f'<text x="{cx}" y="{_x(y + ROW / 2 + 4)}" text-anchor="middle">{escape(lines[0])}</text>')
        else:
            top, bottom = (escape(t) for t in lines)
            out.append(f'<text x="{cx}" y="{_x(y + ROW / 2 - 3)}" text-anchor="middle">{top}'
                       f'<tspan x="{cx}" dy="14">{bottom}</tspan></text>')
    out.append("</g>")
    return out


TITLE_CHAR = 8.6  # width of one character of a title (14 px bold monospace)
NARROW_CELL = 36  # width of one byte in a diagram drawn for a narrow screen (byte_field's narrow)


def byte_field(title: str, fields: Sequence[Field], size: int, per_row: int = 16, narrow: bool = False) -> str:
    """A byte-field diagram: per_row bytes a row, one box per field, a numbered legend. narrow: drawn for a
    phone's screen (the site's 390 px rule: at 8 bytes a row it was 432 px wide, 74 px more than the page's
    column there): narrower bytes, the title wrapped and each legend entry on two lines."""
    per_row = max(1, min(per_row, size))
    cell = NARROW_CELL if narrow else CELL
    rows = max(1, math.ceil(size / per_row))
    width = LEFT + per_row * cell + 12
    # the title (14 px bold) wrapped at spaces to the drawing's width
    heads = textwrap.wrap(title, max(12, int((width - LEFT) / TITLE_CHAR))) if narrow else [title]
    top = TOP + (len(heads) - 1) * LEGEND_LINE
    legend_top = top + rows * ROW + 24
    lines = []
    for k, f in enumerate(fields, 1):
        if narrow:
            lines.append([f"{k:>2}  {f.name}", f"    @{f.offset} +{f.size} {_type_text(f)}"])
        else:
            lines.append([f"{k:>2}  {f.name:<26} @{f.offset:<4} +{f.size:<3} {_type_text(f)}"])
    height = legend_top + sum(len(x) for x in lines) * LEGEND_LINE + 8
    svg = _open(width, height, heads)
    for col in range(per_row):
        svg.append(f'<text x="{_x(LEFT + col * cell + cell / 2)}" y="{top - 8}" text-anchor="middle" '
                   f'fill="#666666">+{col}</text>')
    shapes = []
    for row in range(rows):
        svg.append(f'<text x="{LEFT - 6}" y="{_x(top + row * ROW + ROW / 2 + 4)}" text-anchor="end" '
                   f'fill="#666666">{row * per_row}</text>')
    for k, f in enumerate(fields, 1):
        shapes += _field_shapes(k, f, per_row, cell)
    if top != TOP:
        shapes = [f'<g transform="translate(0 {top - TOP})">', *shapes, "</g>"]
    svg += shapes
    y = legend_top
    for f, entry in zip(fields, lines, strict=True):
        fill = FILL.get(category(f), "#ffffff")
        svg.append(f'<rect x="{LEFT}" y="{y - 10}" width="12" height="12" fill="{fill}" stroke="#333333"/>')
        for line in entry:
            svg.append(f'<text x="{LEFT + 20}" y="{y}" xml:space="preserve">{escape(line)}</text>')
            y += LEGEND_LINE
    svg.append("</svg>")
    return "\n".join(svg) + "\n"


# -- motion geometry ----------------------------------------------------------

def _marker() -> str:
    return ('<defs><marker id="arrow" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="7" markerHeight="7" '
            'orient="auto-start-reverse"><path d="M0,0 L10,5 L0,10 z" fill="#333333"/></marker></defs>')


def _dot(x: float, y: float, label: str, dx: float, dy: float) -> list[str]:
    return [f'<circle cx="{_x(x)}" cy="{_x(y)}" r="4" fill="#333333"/>',
            f'<text x="{_x(x + dx)}" y="{_x(y + dy)}">{escape(label)}</text>']


def _circle_panel(names: dict[str, str], cx: float, cy: float, r: float, degrees: float) -> list[str]:
    """Top view along the normal: start rotated by +degrees (counter-clockwise, right-hand rule)."""
    t = math.radians(degrees)
    sx, sy = cx + r, cy
    ex, ey = cx + r * math.cos(t), cy - r * math.sin(t)
    large = 1 if degrees > 180 else 0
    out = [f'<circle cx="{_x(cx)}" cy="{_x(cy)}" r="{_x(r)}" fill="none" stroke="#bbbbbb" stroke-dasharray="4 4"/>',
           f'<path d="M{_x(sx)},{_x(sy)} A{_x(r)},{_x(r)} 0 {large} 0 {_x(ex)},{_x(ey)}" fill="none" '
           f'stroke="#1f5fa8" stroke-width="2.5" marker-end="url(#arrow)"/>',
           f'<line x1="{_x(cx)}" y1="{_x(cy)}" x2="{_x(sx)}" y2="{_x(sy)}" stroke="#888888"/>',
           f'<line x1="{_x(cx)}" y1="{_x(cy)}" x2="{_x(ex)}" y2="{_x(ey)}" stroke="#888888"/>',
           f'<circle cx="{_x(cx)}" cy="{_x(cy)}" r="9" fill="none" stroke="#333333"/>']
    out += _dot(cx, cy, names["center"], -60, 18)
    out.append(f'<text x="{_x(cx - r)}" y="{_x(cy + r + 24)}">k = {escape(names["normal"])}, out of the page</text>')
    out += _dot(sx, sy, names["start"], 8, 16)
    out += _dot(ex, ey, "end", 8, -8)
    out.append(f'<text x="{_x(cx + 18)}" y="{_x(cy - 14)}">t = {names["degrees"]} = +{degrees:g} deg</text>')
    return out


def _helix_panel(names: dict[str, str], x0: float, base: float, r: float, rise: float, degrees: float) -> list[str]:
    """Side view: the circle's end point, then `length` along k."""
    pts = []
    steps = 24
    for i in range(steps + 1):
        a = math.radians(degrees) * i / steps
        pts.append(f"{_x(x0 + r * math.cos(a))},{_x(base - rise * i / steps)}")
    cend = x0 + r * math.cos(math.radians(degrees))
    out = [f'<line x1="{_x(x0 - r - 20)}" y1="{_x(base)}" x2="{_x(x0 + r + 20)}" y2="{_x(base)}" stroke="#bbbbbb"/>',
           f'<line x1="{_x(x0)}" y1="{_x(base + 10)}" x2="{_x(x0)}" y2="{_x(base - rise - 30)}" stroke="#333333" '
           f'marker-end="url(#arrow)"/>',
           f'<text x="{_x(x0 + 6)}" y="{_x(base - rise - 32)}">k</text>',
           f'<polyline points="{" ".join(pts)}" fill="none" stroke="#1f5fa8" stroke-width="2.5" '
           f'marker-end="url(#arrow)"/>',
           f'<line x1="{_x(cend)}" y1="{_x(base)}" x2="{_x(cend)}" y2="{_x(base - rise)}" stroke="#888888" '
           f'stroke-dasharray="4 3"/>']
    out += _dot(x0 + r, base, names["start"], 8, 16)
    out += _dot(cend, base, "circle end", -92, 16)
    out += _dot(cend, base - rise, "end = circle end + " + names["length"] + " k", 8, -8)
    return out


def motion(circle: dict[str, str], helix: dict[str, str] | None, title: str) -> str:
    """Circle (top view) and helix (side view) from the argument names of the model's motion roles."""
    width, height = 860.0, 340.0
    svg = _open(width, height, title)
    svg.append(_marker())
    svg.append(f'<text x="{LEFT}" y="40" fill="#666666">circle, seen from the tip of k</text>')
    svg += _circle_panel(circle, 190.0, 190.0, 110.0, 90.0)
    if helix:
        svg.append('<text x="430" y="40" fill="#666666">helix, seen from the side</text>')
        svg += _helix_panel(helix, 560.0, 280.0, 100.0, 170.0, 90.0)
    svg.append("</svg>")
    return "\n".join(svg) + "\n"
