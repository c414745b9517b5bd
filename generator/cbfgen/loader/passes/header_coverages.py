"""Header checksums covering named fields: resolved to header segments (the same bytes in every
header layout that carries the checksum), then checked."""

from __future__ import annotations

from dataclasses import replace

from ...model import ChecksumField, Coverage
from .. import named
from ..pipeline import State, define
from ..problems import Problems


def _covered(st: State) -> list[tuple[ChecksumField, Coverage]]:
    """The header checksums whose coverage names fields, each with that coverage."""
    cs = st.bare_checksums
    names = named.named_coverages(cs)
    head, header = named.record_tags(st.record), named.header_tags(st.headers.values())
    arg_tags = {ck.tag for c in st.commands for lay in c.layouts for ck in lay.checksums}
    out = []
    for f in cs.fields:
        cov = cs.coverages.get(f.coverage)
        if cov is not None and cov.name in names and f.field not in head | arg_tags and f.field in header:
            out.append((f, cov))
    return out


@define("header-coverages", "resolve", reads=("headers", "record", "bare_checksums", "commands"),
        produces=("checksums",))
def HEADER_COVERAGES(ctx: Problems, st: State) -> None:
    """The checksum definitions, each header coverage by named fields resolved to header segments
    when its names sit at the same bytes in every header that carries the checksum."""
    coverages = dict(st.bare_checksums.coverages)
    for f, cov in _covered(st):
        resolved = [named.header_segments(cov, h, holder) for h, holder in named.holders(st.headers.values(), f.field)]
        spans = {tuple((s.start, s.end) for s in segs) for segs in resolved}
        if len(spans) == 1:
            coverages[cov.name] = replace(cov, segments=resolved[0])
    st.checksums = replace(st.bare_checksums, coverages=coverages)


@define("header-coverage-fields", "check", reads=("raw", "headers", "record", "bare_checksums", "commands"))
def HEADER_COVERAGE_FIELDS(ctx: Problems, st: State) -> None:
    """Each name of a header checksum's coverage is a field of every header layout that carries the
    checksum, not the checksum itself, at the same bytes in all of them."""
    raw_cov = st.raw["checksums"]["coverages"]
    for f, cov in _covered(st):
        node = next((s for s in raw_cov[cov.name]["segments"] if "fields" in s), raw_cov[cov.name])
        spans: dict[str, tuple[tuple[int | None, int | None], ...]] = {}
        for h, holder in named.holders(st.headers.values(), f.field):
            for r in named.in_header(cov, h, holder):
                if r.trouble == "neither":
                    ctx.fail(node, f"coverage {cov.name}: header {h.id} has no field {r.name}", "fields")
                elif r.trouble == "itself":
                    ctx.fail(node, f"coverage {cov.name}: checksum {f.field} covers itself (header {h.id} field "
                                   f"{r.name})", "fields")
            spans[h.id] = tuple((s.start, s.end) for s in named.header_segments(cov, h, holder))
        other = next((hid for hid in spans if spans[hid] != next(iter(spans.values()))), None)
        if other is not None:
            ctx.fail(node, f"coverage {cov.name}: its named fields sit at other bytes in header {next(iter(spans))} "
                           f"than in header {other} (a header checksum covers the same bytes in every header that "
                           f"carries it)", "fields")
