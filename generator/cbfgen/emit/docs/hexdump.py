"""Annotated hex of a CBF file for the docs' golden pages, drawn by the codec's own dump.

The view itself (runs, values, rows, marks) is the `cbf` runtime's hexdump.py
(generator/cbfgen/emit/python/runtime/hexdump.py), the one `cbf hexdump` prints: this module loads
that file alone (it imports only the standard library) and hands it the layouts of the spec model
being generated from, so the pages and the command draw the same view of the same bytes, and a
revised spec's pages follow its model. `records` frames the records for the pages' structure.
"""

from __future__ import annotations

import importlib.util
import sys
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from types import ModuleType
from typing import Any

from ...model import Command, Field, Layout, Spec

RUNTIME_FILE = Path(__file__).resolve().parents[1] / "python" / "runtime" / "hexdump.py"


@cache
def _rt() -> ModuleType:
    """The runtime's hexdump.py, loaded alone (not as part of the cbf package)."""
    name = "cbfgen_runtime_hexdump"
    spec = importlib.util.spec_from_file_location(name, RUNTIME_FILE)
    assert spec is not None and spec.loader is not None
    mod = importlib.util.module_from_spec(spec)
    sys.modules[name] = mod  # dataclasses resolve their module by name
    spec.loader.exec_module(mod)
    return mod


ROW: int = _rt().ROW


@dataclass(frozen=True)
class Record:
    index: int
    offset: int
    command: Command | None
    layout: Layout | None
    raw_args: bytes


def shortest_float(bits: int) -> str:
    """The fewest digits that give back the same binary32."""
    return str(_rt().shortest_float(bits))


def _cell(f: Field) -> Any:
    return _rt().Cell(f.name, f.kind, f.offset, f.elem_size, f.count,
                      f.magic is not None or f.role in ("code", "code_copy"))


_LAYOUTS: dict[int, tuple[Spec, Any]] = {}  # id(spec) -> (spec, its Layouts): a model is not hashable


def layouts(spec: Spec) -> Any:
    """The runtime dump's Layouts, from the model (made once a model)."""
    got = _LAYOUTS.get(id(spec))
    if got is None or got[0] is not spec:
        got = _LAYOUTS[id(spec)] = (spec, _layouts(spec))
    return got[1]


def _layouts(spec: Spec) -> Any:
    rt = _rt()

    def header(version: str) -> tuple[int, Sequence[Any]]:
        h = spec.header_for(version)
        return h.size, tuple(_cell(f) for f in h.fields)

    by_code = {c.code: c for c in spec.commands}

    def command(code: int, version: str, nb: int) -> tuple[str, Sequence[Any] | None] | None:
        cmd = by_code.get(code)
        if cmd is None:
            return None
        lays = [x for lay in cmd.layouts_for(version) if (x := lay.sized(nb)) is not None]
        return cmd.name, (tuple(_cell(a) for a in lays[0].args) if lays else None)

    rec = spec.record
    code, nb = rec.by_role("code"), rec.by_role("arg_size")
    return rt.Layouts(spec.meta["byte_order"], spec.meta["string_padding"], lambda d: version_of(spec, d), header,
                      rec.head_size, tuple(_cell(f) for f in rec.fields), _cell(code), _cell(nb), command)


def version_of(spec: Spec, data: bytes) -> str:
    """The version id the header's version bytes select (the fallback when none matches)."""
    try:
        major = spec.common_header_field("version_major")
        minor = spec.common_header_field("version_minor")
    except KeyError:
        return spec.fallback_version
    if len(data) <= max(major.offset, minor.offset):
        return spec.fallback_version
    for v in spec.versions:
        if v.matches(data[major.offset], data[minor.offset]):
            return v.id
    return spec.fallback_version


def _uint(spec: Spec, f: Field, data: bytes, base: int) -> int:
    return int.from_bytes(data[base + f.offset:base + f.end], spec.meta["byte_order"])


def records(spec: Spec, data: bytes) -> Iterator[Record]:
    """The whole records after the header, framed by their nb byte (D1)."""
    rec = spec.record
    code_f, nb_f = rec.by_role("code"), rec.by_role("arg_size")
    by_code = {c.code: c for c in spec.commands}
    version = version_of(spec, data)
    pos, index = spec.header_for(version).size, 0
    while pos + rec.head_size <= len(data):
        nb = _uint(spec, nb_f, data, pos)
        if pos + rec.head_size + nb > len(data):
            return
        cmd = by_code.get(_uint(spec, code_f, data, pos))
        lays = [x for lay in cmd.layouts_for(version) if (x := lay.sized(nb)) is not None] if cmd else []
        yield Record(index, pos, cmd, lays[0] if lays else None,
                     data[pos + rec.head_size:pos + rec.head_size + nb])
        pos += rec.head_size + nb
        index += 1


def runs(spec: Spec, data: bytes) -> Iterator[Any]:
    """Every byte of the file in one run (offset, data, label, record), in order."""
    return iter(_rt().runs(layouts(spec), data))


def dump(spec: Spec, data: bytes, *, max_lines: int | None = None, only_record: int | None = None,
         header_only: bool = False) -> str:
    """The annotated hex of data (the runtime's dump; see its doc)."""
    return str(_rt().dump(layouts(spec), data, max_lines=max_lines, only_record=only_record,
                          header_only=header_only))
