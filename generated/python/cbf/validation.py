"""validate: every check of the spec, reported as findings, never raising on bad input.

Each check's id, severity and parameters come from the spec; the code implements the
check *kinds*, each once: the file-level kinds (header, framing, file checksum, part
number) here, the record kinds in records.py (one kernel per kind, ``KERNELS``). The
rules are the "fails" texts of spec/cbf.yaml and conformance/PROTOCOL.md.

Imports point one way: tables -> codec -> findings -> records -> validation -> writer, cli.
"""

from __future__ import annotations

import heapq
from collections.abc import Iterator, Mapping, Sequence
from typing import Any

from . import tables as T
from .codec import decode_header, field_checksum, file_algorithm, frame, header_info, pack_file
from .fields import Buffer
from .findings import Cutters, Finding, finding, finding_order, string_value
from .machine import Machine
from .model import Cbf, RecordList
from .records import header_string_findings, record_findings

__all__ = ["FILE_KINDS", "Cutters", "Finding", "finding_order", "iter_findings", "validate"]

# The check kinds implemented here, on the file as a whole; records.KERNELS has the others.
FILE_KINDS = ("truncated_header", "version", "magic", "header_checksum", "truncated_record", "trailing",
              "command_count", "file_checksum", "part_number", "descriptor_word")


class _Out:
    def __init__(self) -> None:
        self.findings: list[Finding] = []

    def add(self, kind: str, record: int | None, offset: int | None, message: str) -> None:
        """A finding for every check of ``kind`` (none when the spec has none), as the C engine."""
        for check in T.checks_of(kind):
            self.findings.append(finding(check, record, offset, message))


def validate(data: Buffer | Cbf, *, profile: str = "default", part_number: str | None = None,
             cutters: Cutters | None = None, machine: Machine | None = None) -> list[Finding]:
    """Findings for a file (bytes) or a model (encoded with its stored values first).

    ``machine``: a machine file's limits (cbf.machine.load_machine; breaches are errors), or None:
    the spec's default machine (breaches are warnings).
    """
    return list(iter_findings(data, profile=profile, part_number=part_number, cutters=cutters, machine=machine))


def _source(data: Buffer | Cbf) -> tuple[bytes, tuple[Sequence[int], int] | None]:
    """The bytes to judge, and their framing when decode made the model and nobody changed it since."""
    if isinstance(data, Cbf):
        reuse = _decoded_source(data)
        if reuse is not None:
            return bytes(reuse[0]), reuse[1]
        data = pack_file(data, keep_stored=True)
    return bytes(data), None


def _header_findings(out: _Out, buf: bytes, vid: str | None, header: dict[str, Any], info: Any) -> None:
    """The version, the magic numbers, the header checksums and the header's strings."""
    if vid is None:
        out.add("version", None, T.VMAJOR.offset,
                f"version {buf[T.VMAJOR.offset]}.{buf[T.VMINOR.offset]} is not a version of this spec; "
                f"read as {T.FALLBACK_VERSION}")
    for f in (T.START, T.END):
        if header[f.name] != f.magic:
            out.add("magic", None, f.offset, f"{f.name} is 0x{header[f.name]:08X}, expected 0x{f.magic:08X}")
    own = T.LAYOUT_CHECKSUM_FIELDS[info.id]
    for check in T.checks_of("header_checksum"):  # each judges its field, where this version's header has it
        hsum = own.get(check["field"])
        if hsum is not None:
            want = _field_sum(check["field"], buf, [])
            if header[hsum.name] != want:
                out.findings.append(finding(check, None, hsum.offset,
                                            f"stored {check['field']} checksum {header[hsum.name]}, computed {want}"))
    for f in info.fields:
        if f.kind == "string":
            out.findings.extend(header_string_findings(header[f.name], f.offset, f.name))


def _framing_findings(out: _Out, n: int, offsets: Sequence[int], end: int, count: int) -> None:
    """A record cut off, bytes after the last record, a count that is not the number of records."""
    truncated = False
    if end < n:
        if len(offsets) < count:
            truncated = True
            out.add("truncated_record", len(offsets), end,
                    f"the file ends inside record {len(offsets)} ({n - end} byte(s) left)")
        else:
            out.add("trailing", None, end, f"{n - end} byte(s) after the last record")
    if not truncated and len(offsets) != count:
        out.add("command_count", None, T.COUNT.offset,
                f"header count {count}, the file holds {len(offsets)} records")


def _file_checksum(out: _Out, buf: bytes, offsets: Sequence[int], header: dict[str, Any], profile: str) -> None:
    """The file checksum against the profile's coverages (and which other coverage it matches)."""
    fsum = T.HEADER_CHECKSUM_FIELDS.get("file")
    if fsum is None:
        return
    stored = header[fsum.name]
    prof = T.PROFILES[profile]
    alg = file_algorithm(profile)
    if any(_field_sum("file", buf, offsets, cov, algorithm=alg) == stored for cov in prof["file_coverages"]):
        return
    want = _field_sum("file", buf, offsets, prof["file_coverages"][0], algorithm=alg)
    msg = f"stored file checksum {stored}, computed {want}"
    for cov in prof["hint_coverages"]:
        # a hint coverage is computed as the profile that accepts it computes it
        owner = _profile_with(cov)
        hint_alg = file_algorithm(owner) if owner in T.PROFILES else alg
        if _field_sum("file", buf, offsets, cov, algorithm=hint_alg) == stored:
            msg += f"; it matches coverage {cov} (use profile {owner})"
    out.add("file_checksum", None, fsum.offset, msg)


def iter_findings(data: Buffer | Cbf, *, profile: str = "default", part_number: str | None = None,
                  cutters: Cutters | None = None, machine: Machine | None = None) -> Iterator[Finding]:
    """validate's findings, in its order, made one at a time as they are read: memory stays
    bounded however many findings a file gives (the checks run now; bad arguments raise now)."""
    buf, framing = _source(data)
    if profile not in T.PROFILES:
        raise ValueError(f"unknown profile {profile!r}; known: {', '.join(T.PROFILES)}")
    out = _Out()
    n = len(buf)
    if n < T.HEADER_SIZE:
        out.add("truncated_header", None, 0, f"file is {n} bytes, the header needs {T.HEADER_SIZE}")
        return iter(out.findings)
    vid, info = header_info(buf)
    hvals = info.struct.unpack_from(buf, 0)
    header = {f.name: v for f, v in zip(info.fields, hvals, strict=True)}
    version = vid or T.FALLBACK_VERSION
    _header_findings(out, buf, vid, header, info)
    offsets, end = framing if framing is not None else frame(buf)
    _framing_findings(out, n, offsets, end, header[T.COUNT.name])
    _file_checksum(out, buf, offsets, header, profile)
    stream = record_findings(buf, offsets, version, profile, cutters, machine)
    if part_number is not None:
        _part_number(out, info, header, part_number)
    _descriptor_word(out, info, header)
    merged = iter(heapq.merge(sorted(out.findings, key=finding_order), stream, key=finding_order))
    elsewhere = T.scoped_out(version)
    # a check scoped to other versions (versions:) judges nothing in this file, as in the C engine
    if elsewhere:
        return (f for f in merged if f.check not in elsewhere)
    return merged


def _decoded_source(model: Cbf) -> tuple[bytes, tuple[Sequence[int], int]] | None:
    """The bytes and framing of a model that decode made and nobody changed since."""
    recs = model.records
    if not isinstance(recs, RecordList) or recs.framed is None:
        return None
    buf, offsets = recs.source
    if buf[recs.framed:] != model.trailing or decode_header(buf) != model.header:
        return None
    return buf, (offsets, recs.framed)


def _profile_with(coverage: str) -> str:
    for pid, p in T.PROFILES.items():
        if coverage in p["file_coverages"]:
            return pid
    return "?"


def _field_sum(tag: str, buf: bytes, offsets: Sequence[int], coverage: str | None = None, args: bytes | None = None,
               algorithm: str | None = None) -> int:
    return field_checksum(tag, buf, offsets, coverage, args, algorithm)


def _part_number(out: _Out, info: T.HeaderInfo, header: Mapping[str, Any], part_number: str) -> None:
    f = info.by_role("implant_descriptor")
    if f is None:
        return
    words = string_value(header[f.name]).split()
    first = words[0] if words else ""
    if first != part_number:
        out.add("part_number", None, f.offset,
                f"implant descriptor starts with {first!r}, expected {part_number!r}")


def _descriptor_word(out: _Out, info: T.HeaderInfo, header: Mapping[str, Any]) -> None:
    """4.2: the implant descriptor begins with the part number, so it holds a word."""
    f = info.by_role("implant_descriptor")
    if f is not None and not string_value(header[f.name]).split():
        out.add("descriptor_word", None, f.offset,
                "implant descriptor holds no word: no part number comes first")
