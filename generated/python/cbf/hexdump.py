"""Annotated hex of a CBF file: `cbf hexdump FILE` and the docs' golden pages draw the same view.

The file is split into runs: each header field of the layout its version selects, then each
record's head fields and argument fields (the layout of the command code whose size matches the
record's argument size, in the file's version), then anything that frames no record. Each run is
printed hexdump-style: the offset, up to ROW bytes, an ASCII column, and after a gutter the field
the bytes belong to with its value. A run longer than a row carries its name on every row, marked
"(cont.)". Findings are marked on the row that holds their offset.

One copy of this logic: this module uses the standard library only and is handed the layouts
(`Layouts`); `for_runtime()` makes them from the codec's tables, and the generator's docs emitter
loads this very file (generator/cbfgen/emit/python/runtime/hexdump.py) and makes them from the
spec model it generates from. Nothing here knows a command, a field or a size.
"""

from __future__ import annotations

import struct
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass
from decimal import Decimal
from typing import TYPE_CHECKING, Literal

if TYPE_CHECKING:  # the codec's tables; this module itself imports none (the docs emitter loads it alone)
    from .tables import FieldInfo

ROW = 16
MARK = "\u25c0"  # the finding marker after a row's field


@dataclass(frozen=True)
class Cell:
    """A field as the dump shows it: where it is and how its bytes read."""

    name: str
    kind: str  # uint | sint | float | string | bytes
    offset: int
    elem_size: int
    count: int = 1
    hexa: bool = False  # integers shown in hex (magic numbers, command codes)

    @property
    def size(self) -> int:
        return self.elem_size * self.count

    @property
    def end(self) -> int:
        return self.offset + self.size


@dataclass(frozen=True)
class Layouts:
    """What the dump needs of the format."""

    byte_order: str  # "little" | "big"
    string_padding: int
    version_of: Callable[[bytes], str]  # the version id the header selects (the fallback when none)
    header: Callable[[str], tuple[int, Sequence[Cell]]]  # version id -> header size, fields
    head_size: int
    head: Sequence[Cell]
    code: Cell  # the record head's code field
    nb: Cell  # the record head's argument-size field
    # (code, version id, nb) -> (command name, argument cells, or None when no layout of nb bytes); None: unknown code
    command: Callable[[int, str, int], tuple[str, Sequence[Cell] | None] | None]


@dataclass(frozen=True)
class Run:
    """Bytes [offset, offset + len(data)) and what they are."""

    offset: int
    data: bytes
    label: str
    record: int | None = None  # the record index, None for the header and unframed bytes
    header: bool = False


@dataclass(frozen=True)
class Mark:
    """A finding to mark at a file offset."""

    offset: int
    text: str


def shortest_float(bits: int, size: int = 4) -> str:
    """The fewest digits that give back the same binary32 (binary64 for 8 bytes)."""
    fmt, ifmt = ("<f", "<I") if size == 4 else ("<d", "<Q")
    v: float = struct.unpack(fmt, struct.pack(ifmt, bits))[0]
    if v != v or v in (float("inf"), float("-inf")):
        return repr(v)
    text = repr(v)
    for p in range(1, 18):
        cand = f"{v:.{p}g}"
        if struct.unpack(ifmt, struct.pack(fmt, float(cand)))[0] == bits:
            text = cand
            break
    return format(Decimal(text), "f") if "e" in text else text


def value_text(lay: Layouts, f: Cell, raw: bytes) -> str:
    """The value of a field's bytes as the reader sees it."""
    if len(raw) < f.size:
        return "(truncated)"
    words = [raw[i * f.elem_size:(i + 1) * f.elem_size] for i in range(f.count)]
    order: Literal["little", "big"] = "little" if lay.byte_order == "little" else "big"
    if f.kind == "float":
        vals = [shortest_float(int.from_bytes(w, order), f.elem_size) for w in words]
        return vals[0] if f.count == 1 else "<" + ", ".join(vals) + ">"
    if f.kind in ("uint", "sint"):
        ints = [int.from_bytes(w, order, signed=f.kind == "sint") for w in words]
        return ", ".join(f"0x{u:0{2 * f.elem_size}X}" if f.hexa else str(u) for u in ints)
    if f.kind == "string":
        return repr(raw.rstrip(bytes([lay.string_padding])).decode("latin-1"))
    return "all zero" if not any(raw) else f"{len(raw)} bytes"


def runs(lay: Layouts, data: bytes) -> Iterator[Run]:
    """Every byte of the file in one run, in order."""
    version = lay.version_of(data)
    size, fields = lay.header(version)
    for f in fields:
        raw = data[f.offset:f.end]
        if raw:
            yield Run(f.offset, raw, f"header {f.name} = {value_text(lay, f, raw)}", header=True)
    order: Literal["little", "big"] = "little" if lay.byte_order == "little" else "big"
    pos, index = size, 0
    while pos + lay.head_size <= len(data):
        nb = int.from_bytes(data[pos + lay.nb.offset:pos + lay.nb.end], order)
        if pos + lay.head_size + nb > len(data):
            break
        found = lay.command(int.from_bytes(data[pos + lay.code.offset:pos + lay.code.end], order), version, nb)
        name = found[0] if found else "unknown code"
        for f in lay.head:
            raw = data[pos + f.offset:pos + f.end]
            yield Run(pos + f.offset, raw, f"#{index} {name} {f.name} = {value_text(lay, f, raw)}", index)
        base = pos + lay.head_size
        args = data[base:base + nb]
        if found is not None and found[1] is not None:
            for f in found[1]:
                raw = args[f.offset:f.end]
                yield Run(base + f.offset, raw, f"#{index} {name} {f.name} = {value_text(lay, f, raw)}", index)
        elif args:
            yield Run(base, args, f"#{index} {name} arguments (no layout of {len(args)} bytes)", index)
        pos, index = base + nb, index + 1
    if pos < len(data):
        yield Run(pos, data[pos:], "bytes that frame no whole record")


def _ascii(raw: bytes) -> str:
    return "".join(chr(b) if 0x20 <= b < 0x7F else "." for b in raw)


def dump(lay: Layouts, data: bytes, *, max_lines: int | None = None, only_record: int | None = None,
         header_only: bool = False, marks: Sequence[Mark] = ()) -> str:
    """The annotated hex of data: `offset  bytes  ascii │ field = value`, one run per line or more.

    only_record keeps the runs of one record, header_only those of the header; max_lines cuts the dump
    (and says so). Each mark is appended to the row holding its offset (`◀ text`); a mark at no byte
    of the dump (an offset past the end) is listed after it."""
    if not data:
        return "(no bytes: the file is empty)" + "".join(f"\n{MARK} {m.text}" for m in marks)
    at: dict[int, list[str]] = {}
    for m in marks:
        at.setdefault(m.offset, []).append(m.text)
    placed: set[int] = set()
    lines: list[str] = []
    for run in runs(lay, data):
        if only_record is not None and run.record != only_record:
            continue
        if header_only and not run.header:
            break
        for k in range(0, max(1, len(run.data)), ROW):
            chunk = run.data[k:k + ROW]
            label = run.label if k == 0 else run.label.split(" = ")[0] + " (cont.)"
            if max_lines is not None and len(lines) == max_lines:
                lines.append(f"... cut here: the first {max_lines} lines of {len(data)} bytes")
                return "\n".join(lines)
            here = [o for o in range(run.offset + k, run.offset + k + max(1, len(chunk))) if o in at]
            note = "".join(f" {MARK} {t}" for o in here for t in at[o])
            placed.update(here)
            lines.append(f"{run.offset + k:08X}  {chunk.hex(' ').upper():<{3 * ROW - 1}}  "
                         f"{_ascii(chunk):<{ROW}} \u2502 {label}{note}")
    if only_record is None and not header_only:
        lines += [f"{MARK} {t} (at offset {o}, past the bytes shown)" for o in sorted(at) if o not in placed
                  for t in at[o]]
    return "\n".join(lines)


def _cell(f: FieldInfo) -> Cell:
    """A codec table field as a Cell."""
    return Cell(f.name, f.kind, f.offset, f.elem_size, f.count, f.magic is not None or f.role in ("code", "code_copy"))


def for_runtime() -> Layouts:
    """The layouts of the codec's own tables (the spec this package was generated from)."""
    from . import tables as T

    def version_of(data: bytes) -> str:
        vmaj, vmin = T.VMAJOR.offset, T.VMINOR.offset
        if len(data) <= max(vmaj, vmin):
            return T.FALLBACK_VERSION
        return T.version_id(data[vmaj], data[vmin]) or T.FALLBACK_VERSION

    def header(version: str) -> tuple[int, Sequence[Cell]]:
        h = T.HEADERS[T.VERSION_BY_ID[version].header]
        return h.size, tuple(_cell(f) for f in h.fields)

    def command(code: int, version: str, nb: int) -> tuple[str, Sequence[Cell] | None] | None:
        c = T.BY_CODE.get(code)
        if c is None:
            return None
        lay = next((x for x in c.layouts_for(version) if x.size == nb), None)
        if lay is None:
            return c.name, None
        cells: list[Cell] = []
        for f in lay.args:
            if lay.n is not None and f is lay.repeated:  # a repeated group: one cell an item, name[i]
                item = f.elem_size * f.per
                cells += [Cell(f"{f.name}[{i}]", f.kind, f.offset + i * item, f.elem_size, f.per, _cell(f).hexa)
                          for i in range(lay.n)]
            else:
                cells.append(_cell(f))
        return c.name, tuple(cells)

    code, nb = T.RECORD_BY_ROLE["code"], T.RECORD_BY_ROLE["arg_size"]
    return Layouts(str(T.SPEC["byte_order"]), int(T.SPEC["string_padding"]), version_of, header, T.HEAD_SIZE,
                   tuple(_cell(f) for f in T.RECORD_FIELDS), _cell(code), _cell(nb), command)


def marks_of(findings: Mapping[int, Sequence[str]]) -> tuple[Mark, ...]:
    """Marks from offset -> texts."""
    return tuple(Mark(o, t) for o in sorted(findings) for t in findings[o])
