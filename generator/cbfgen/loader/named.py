"""Coverage by named fields (issue 25, point 1), resolved: the shared rules of the passes that
resolve it (``arg-checksums``, ``header-coverages``) and of those that check it.

A ``fields`` segment names fields of the checksum's own place: for an argument's checksum,
arguments of its layout or record head fields (record byte ranges, per layout); for a header
checksum, fields of each header layout that carries it (header segments, the same bytes in every
such layout). Every function here is pure: it says what a name resolves to, or why it does not.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from typing import Literal

from ..model import Checksums, Coverage, Field, HeaderLayout, Layout, RecordLayout, Segment

Trouble = Literal["", "both", "neither", "itself"]
ArgTrouble = Literal["", "untagged", "shape", "tag", "repeat"]


@dataclass(frozen=True)
class Resolved:
    """One named field of a coverage: the bytes it stands for, or why it stands for none
    (``both``: an argument and a record head field; ``neither``: none of them; ``itself``: the
    checksum's own bytes)."""

    name: str
    span: tuple[int, int] | None
    trouble: Trouble = ""


def record_tags(record: RecordLayout) -> set[str]:
    return {str(f.checksum) for f in record.fields if f.checksum}


def header_tags(headers: Iterable[HeaderLayout]) -> set[str]:
    return {str(f.checksum) for h in headers for f in h.fields if f.checksum}


def named_coverages(cs: Checksums) -> set[str]:
    """The coverages with a segment by named fields."""
    return {k for k, cov in cs.coverages.items() if any(seg.region == "fields" for seg in cov.segments)}


def arg_trouble(a: Field, lay: Layout, head: set[str], header: set[str]) -> ArgTrouble:
    """Why the argument ``a`` of ``lay`` is no checksum field every binding can fill ("": it is one,
    or carries no tag and no checksum role)."""
    if a.role == "checksum" and not a.checksum:
        return "untagged"
    if not a.checksum:
        return ""
    if a.role != "checksum" or a.kind != "uint" or a.count != 1:
        return "shape"
    if a.checksum in head or a.checksum in header:
        return "tag"
    if lay.repeated is not None:
        return "repeat"
    return ""


def arg_coverage(cs: Checksums, tag: str) -> Coverage | None:
    """The coverage of an argument checksum's definition (None: the tag or coverage is undefined)."""
    cf = next((f for f in cs.fields if f.field == tag), None)
    return cs.coverages.get(cf.coverage) if cf is not None else None


def in_record(cov: Coverage, lay: Layout, a: Field, record: RecordLayout) -> list[Resolved]:
    """Each name of ``cov`` as record bytes of ``lay`` (an argument's or a record head field's)."""
    head = {f.name: f for f in record.fields}
    hs = record.head_size
    own = (hs + a.offset, hs + a.end)
    out: list[Resolved] = []
    for n in (n for seg in cov.segments for n in seg.fields):
        arg, hf = lay.arg(n), head.get(n)
        if arg is not None and hf is not None:
            out.append(Resolved(n, None, "both"))
        elif arg is not None or hf is not None:
            span = (hs + arg.offset, hs + arg.end) if arg is not None else (hf.offset, hf.end)  # type: ignore[union-attr]
            out.append(Resolved(n, span))
        else:
            out.append(Resolved(n, None, "neither"))
    if any(r.span is not None and r.span[0] < own[1] and own[0] < r.span[1] for r in out):
        out.append(Resolved(a.name, own, "itself"))
    return out


def in_header(cov: Coverage, h: HeaderLayout, holder: Field) -> list[Resolved]:
    """Each name of ``cov`` as header bytes of ``h``, whose field ``holder`` stores the checksum."""
    out: list[Resolved] = []
    for n in (n for seg in cov.segments for n in seg.fields):
        hf = h.field(n)
        if hf is None:
            out.append(Resolved(n, None, "neither"))
        elif hf.offset < holder.end and holder.offset < hf.end:
            out.append(Resolved(n, (hf.offset, hf.end), "itself"))
        else:
            out.append(Resolved(n, (hf.offset, hf.end)))
    return out


def header_segments(cov: Coverage, h: HeaderLayout, holder: Field) -> tuple[Segment, ...]:
    """``cov`` with its named fields as header segments of ``h`` (names ``h`` lacks left out)."""
    byname = {r.name: r for r in in_header(cov, h, holder)}
    segs: list[Segment] = []
    for seg in cov.segments:
        if seg.region != "fields":
            segs.append(seg)
            continue
        for n in seg.fields:
            span = byname[n].span
            if span is not None:
                segs.append(Segment("header", span[0], span[1], fields=(n,)))
    return tuple(segs)


def holders(headers: Iterable[HeaderLayout], tag: str) -> list[tuple[HeaderLayout, Field]]:
    """The header layouts that carry checksum ``tag``, each with its field."""
    out = []
    for h in headers:
        holder = next((x for x in h.fields if x.checksum == tag), None)
        if holder is not None:
            out.append((h, holder))
    return out
