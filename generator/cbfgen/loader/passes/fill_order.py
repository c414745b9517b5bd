"""A writer fills the checksums in fill_order: a checksum that covers another checksum's stored
bytes comes after it, and no checksum covers its own."""

from __future__ import annotations

from ...model import Coverage, Field, HeaderLayout
from ..pipeline import State, define
from ..problems import Problems


def _in_headers(headers: list[HeaderLayout], lo: int, hi: int) -> set[str]:
    """The tags of header checksum fields that overlap header bytes lo..hi."""
    return {str(x.checksum) for h in headers for x in h.fields if x.checksum and x.offset < hi and lo < x.end}


def _by_coverage(st: State, cov: Coverage, head: list[Field], arg_tags: set[str]) -> set[str]:
    """The checksum fields a coverage reaches, as each binding computes it."""
    headers = list(st.headers.values())
    out: set[str] = set()
    for seg in cov.segments:
        if seg.region == "header" and seg.start is not None and seg.end is not None:
            out |= _in_headers(headers, seg.start, seg.end)
        elif seg.region == "file" and seg.start is not None:
            out |= {str(x.checksum) for h in headers for x in h.fields if x.checksum and x.end > seg.start}
            out |= {str(x.checksum) for x in head} | arg_tags
        elif seg.region == "records":
            out |= {str(x.checksum) for x in head if x.name not in seg.exclude} | arg_tags
        elif seg.region == "args":
            out |= arg_tags
    return out


def _in_layouts(st: State, head: list[Field]) -> dict[str, set[str]]:
    """What each argument checksum covers: head fields and argument checksums of its layout."""
    hs = st.record.head_size
    out: dict[str, set[str]] = {}
    for c in st.commands:
        for lay in c.layouts:
            for ck in lay.checksums:
                got = out.setdefault(ck.tag, set())
                for lo, hi in ck.ranges:
                    got |= {str(x.checksum) for x in head if x.offset < hi and lo < x.end}
                    got |= {o.tag for o in lay.checksums if hs + o.field.offset < hi and lo < hs + o.field.end}
    return out


def covers(st: State) -> dict[str, set[str]]:
    """Each checksum tag -> the checksum tags whose stored bytes it covers (with each profile's file
    coverages for the file checksum)."""
    cs = st.checksums
    head = [f for f in st.record.fields if f.checksum]
    arg_tags = {ck.tag for c in st.commands for lay in c.layouts for ck in lay.checksums}
    out: dict[str, set[str]] = {f.field: set() for f in cs.fields}
    for f in cs.fields:
        if f.coverage in cs.coverages:
            out[f.field] |= _by_coverage(st, cs.coverages[f.coverage], head, arg_tags)
        if f.field == "file":
            for k in (k for p in st.profiles for k in p.file_coverages if k in cs.coverages):
                out["file"] |= _by_coverage(st, cs.coverages[k], head, arg_tags)
    for tag, got in _in_layouts(st, head).items():
        out.setdefault(tag, set()).update(got)
    return out


@define("fill-order", "check", reads=("raw", "headers", "record", "commands", "checksums", "profiles"))
def FILL_ORDER(ctx: Problems, st: State) -> None:
    """A checksum that covers another checksum's stored bytes comes after it in fill_order, and no
    checksum covers its own: header byte ranges, the file region and the records region (less the
    head fields it excludes) and the args region are followed as each binding computes them."""
    cs, raw_cs = st.checksums, st.raw["checksums"]
    order = list(cs.fill_order)
    if sorted(order) != sorted(f.field for f in cs.fields):
        return  # the checksum-defs pass said so
    got = covers(st)
    for tag in order:
        if tag in got[tag]:
            node = next((x for x in raw_cs["fields"] if x["field"] == tag), raw_cs)
            ctx.fail(node, f"checksum {tag} covers its own stored bytes", "coverage")
        for other in sorted(got[tag] - {tag}):
            if other not in got:
                continue
            if tag in got[other]:
                if order.index(tag) < order.index(other):
                    ctx.fail(raw_cs, f"checksums {tag} and {other} cover each other: no fill order computes both",
                             "fill_order")
            elif order.index(other) > order.index(tag):
                ctx.fail(raw_cs, f"checksums.fill_order: {tag} covers {other}, so {other} must be filled before it",
                         "fill_order")
