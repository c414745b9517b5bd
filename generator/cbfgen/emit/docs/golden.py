"""The golden cases of the conformance suite as the docs show them.

Each case is read from its assembled .cbf (committed beside the hand-written
.hex) and its .expect.yaml; the annotated hex comes from hexdump.py and the
model, never from the assembler's source text. A command page's example is
the first record of that command in a valid case, with its CUT line written
from the model's `cut` section (tests/test_docs_site.py checks it against
the CUT writer of the Python binding).
"""

from __future__ import annotations

import struct
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

from ...model import Command, Layout, Spec
from . import hexdump

SCAN_RECORDS = 1000  # records of a case searched for examples
MAX_LINES = 160  # annotated hex lines shown per case; longer cases are cut and say so
_LOADER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


@dataclass(frozen=True)
class Case:
    name: str
    description: str
    group: str
    clauses: tuple[str, ...]
    findings: tuple[tuple[str, str, str, Any], ...]  # (profile, check, severity, record)
    decode_ok: bool
    data: bytes


@dataclass(frozen=True)
class Example:
    case: str
    record: int
    layout: Layout
    cut: str
    hex: str


def _group(name: str) -> str:
    parts = name.split(".")
    return parts[0] if parts[0] != "check" else ".".join(parts[:2])


def _decodes(expected: Any) -> bool:
    """The expectation's decode entry: "ok", the decoded model (both decode) or {error: ...}."""
    return expected is not None and not (isinstance(expected, dict) and "error" in expected)


def load_cases(folder: Path) -> list[Case]:
    """Every case with an assembled .cbf and an expectation, by name."""
    out = []
    for expect in sorted(folder.glob("*.expect.yaml")):
        name = expect.name[: -len(".expect.yaml")]
        cbf = folder / f"{name}.cbf"
        if not cbf.exists():
            continue
        doc = yaml.load(expect.read_text(encoding="utf-8"), Loader=_LOADER) or {}
        validate = doc.get("validate") or {}
        findings = tuple((str(p), str(f[0]), str(f[1]), f[2])
                         for p, lst in sorted(validate.items()) for f in (lst or []))
        out.append(Case(name, str(doc.get("description", "")), _group(name),
                        tuple(str(c) for c in doc.get("clauses", []) or []), findings,
                        _decodes(doc.get("decode")), cbf.read_bytes()))
    return out


def _word(spec: Spec, raw: bytes) -> str:
    return raw.rstrip(bytes([spec.meta["string_padding"]])).decode("latin-1")


def cut_line(spec: Spec, cmd: Command, lay: Layout, raw: bytes) -> str:
    """The CUT line of a record's arguments in the model's `cut` syntax."""
    cut = spec.cut
    order = "<" if spec.meta["byte_order"] == "little" else ">"
    parts = [cmd.name.lower() if cut["keyword_case"] == "lower" else cmd.name]
    for f in lay.args:
        chunk = raw[f.offset:f.end]
        if f.kind == "float":
            vals = [hexdump.shortest_float(w) for w in struct.unpack(order + "I" * f.count, chunk)]
            sep = cut["vector_separator"] + " "
            parts.append(f"{cut['vector_open']} {sep.join(vals)} {cut['vector_close']}" if f.count > 1 else vals[0])
        elif f.ftype.is_integer:
            parts.append(str(int.from_bytes(chunk, spec.meta["byte_order"], signed=f.kind == "sint")))
        elif f.kind == "string" and _word(spec, chunk):
            parts.append(_word(spec, chunk))
    return str(cut["arg_separator"]).join(parts)


def _plain(spec: Spec, lay: Layout, raw: bytes) -> bool:
    """A record the CUT syntax writes as a keyword line (not as a lossless hex record line)."""
    for f in lay.args:
        chunk = raw[f.offset:f.end]
        if f.kind == "bytes" and any(chunk):
            return False
        if f.kind == "float" and any(v != v or abs(v) == float("inf")
                                     for v in struct.unpack("<" + "f" * f.count, chunk)):
            return False
        if f.kind == "string":
            word = _word(spec, chunk)
            if "\x00" in word or (not f.text and (not word or " " in word)):
                return False
    return True


def examples(spec: Spec, cases: list[Case]) -> dict[str, Example]:
    """Per command name: its first plain record in a valid case (valid cases first, then the others)."""
    out: dict[str, Example] = {}
    ordered = sorted(cases, key=lambda c: (not c.name.startswith("valid."), bool(c.findings), c.name))
    for case in ordered:
        if not case.decode_ok:
            continue
        if len(out) == len(spec.commands):
            break
        for rec in hexdump.records(spec, case.data):
            if rec.index >= SCAN_RECORDS:
                break
            if rec.command is None or rec.layout is None or rec.command.name in out:
                continue
            if rec.layout.profiles or not _plain(spec, rec.layout, rec.raw_args):
                continue
            out[rec.command.name] = Example(case.name, rec.index, rec.layout,
                                            cut_line(spec, rec.command, rec.layout, rec.raw_args),
                                            hexdump.dump(spec, case.data, only_record=rec.index))
    return out


def page_context(spec: Spec, case: Case) -> dict[str, Any]:
    return {"case": case, "hex": hexdump.dump(spec, case.data, max_lines=MAX_LINES),
            "version": hexdump.version_of(spec, case.data)}


def header_example(spec: Spec, cases: list[Case]) -> tuple[str, str] | None:
    """(case name, annotated hex of its header) of the first valid case of the default version."""
    for case in cases:
        if case.name.startswith("valid.") and case.decode_ok and hexdump.version_of(spec, case.data) == \
                spec.default_version and len(case.data) >= spec.header_for(spec.default_version).size:
            return case.name, hexdump.dump(spec, case.data, header_only=True)
    return None


EXAMPLE_RECORDS = 40  # the companion document's example file: a valid case of at most this many records


def _example_records(spec: Spec, case: Case) -> list[Any] | None:
    """The records of a case the complete example may show (None: the case does not qualify): a valid
    case of the default version, no finding under the default profile, at most EXAMPLE_RECORDS records,
    each with a keyword line of a layout no profile restricts."""
    if not case.name.startswith("valid.") or not case.decode_ok or any(prof == "default" for prof, *_ in case.findings):
        return None
    if hexdump.version_of(spec, case.data) != spec.default_version or \
            len(case.data) < spec.header_for(spec.default_version).size:
        return None
    recs = list(hexdump.records(spec, case.data))
    if len(recs) > EXAMPLE_RECORDS or any(r.command is None or r.layout is None or r.layout.profiles
                                          or not _plain(spec, r.layout, r.raw_args) for r in recs):
        return None
    return recs


def _header_lines(spec: Spec, data: bytes) -> list[str]:
    """The CUT header line, and the header_ext line when the configuration descriptor is set."""
    cut = spec.cut
    lines = []
    for f in spec.header_for(spec.default_version).fields:
        if f.role in ("implant_descriptor", "configuration_descriptor"):
            value = _word(spec, data[f.offset:f.offset + f.size]).strip()
            key = cut["header_keyword"] if f.role == "implant_descriptor" else cut["header_ext_keyword"]
            if f.role == "implant_descriptor" or value:
                lines.append(f"{key} {value}".rstrip())
    return lines


def cut_example(spec: Spec, cases: list[Case]) -> tuple[str, str] | None:
    """(case name, CUT text) of the companion document's complete example: of the valid cases of the
    default version without findings under the default profile whose records all have a keyword line,
    the one with the most distinct commands (at most EXAMPLE_RECORDS records). The text is what the CUT
    writer writes: the header line, the header_ext line when the configuration descriptor is set, one line a record."""
    best: tuple[int, str, str] | None = None
    for case in cases:
        recs = _example_records(spec, case)
        if recs is None:
            continue
        lines = _header_lines(spec, case.data) + [cut_line(spec, r.command, r.layout, r.raw_args) for r in recs
                                                  if r.command is not None and r.layout is not None]
        distinct = len({r.command.name for r in recs if r.command is not None})
        if best is None or distinct > best[0]:
            best = (distinct, case.name, "\n".join(lines) + "\n")
    return (best[1], best[2]) if best else None
