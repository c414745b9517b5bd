"""The checksum definitions: algorithms, coverages, one definition per checksum field, a fill order."""

from __future__ import annotations

from ...model import Algorithm, ChecksumField, Checksums, Coverage, Field, Segment
from ..pipeline import State, define
from ..problems import Problems
from ..yaml_reader import Map


def _segment(s: Map) -> Segment:
    if "fields" in s:  # named fields: resolved per layout (the arg-checksums and header-coverages passes)
        return Segment("fields", fields=tuple(str(n) for n in s["fields"]))
    return Segment(s["region"], s.get("start"), s.get("end"), tuple(s.get("exclude", [])))


@define("checksums", "resolve", reads=("raw",), produces=("bare_checksums",))
def CHECKSUMS(ctx: Problems, st: State) -> None:
    """Algorithms, coverages (their named fields not yet resolved) and checksum fields; a field
    defined twice is refused (and its second definition left out)."""
    cs = st.raw["checksums"]
    algorithms = {k: Algorithm(k, a["kind"], str(a["doc"]).strip()) for k, a in cs["algorithms"].items()}
    coverages = {k: Coverage(k, str(cov["doc"]).strip(), tuple(_segment(s) for s in cov["segments"]))
                 for k, cov in cs["coverages"].items()}
    cfields: list[ChecksumField] = []
    for f in cs["fields"]:
        if any(o.field == f["field"] for o in cfields):
            ctx.fail(f, f"checksum {f['field']}: defined twice", "field")
            continue
        cfields.append(ChecksumField(f["field"], f["algorithm"], f["coverage"], f["clause"]))
    st.bare_checksums = Checksums(algorithms, coverages, tuple(cfields), tuple(cs["fill_order"]))


def stored_widths(st: State) -> dict[str, int]:
    """The stored field's width of each checksum tag (bytes): it bounds the algorithm's result."""
    widths = {f.checksum: f.size for h in st.headers.values() for f in h.fields if f.checksum}
    widths.update({f.checksum: f.size for f in st.record.fields if f.checksum})
    for a in arg_checksum_fields(st):
        widths.setdefault(str(a.checksum), a.size)
    return {str(k): v for k, v in widths.items()}


def arg_checksum_fields(st: State) -> list[Field]:
    """The arguments that carry a checksum tag, in every layout."""
    return [a for c in st.bare_commands for lay in c.layouts for a in lay.args if a.checksum]


def fits(ctx: Problems, st: State, node: Map, key: str, tag: str, alg_name: str, what: str) -> None:
    """The algorithm's result fits the stored field of ``tag``."""
    bits = st.bare_checksums.algorithms[alg_name].bits
    widths = stored_widths(st)
    if tag in widths and bits is not None and bits > 8 * widths[tag]:
        ctx.fail(node, f"{what}: algorithm {alg_name} gives {bits} bits, the {tag} checksum field "
                       f"holds {8 * widths[tag]}", key)


@define("coverages", "check", reads=("raw", "headers", "record"))
def COVERAGES(ctx: Problems, st: State) -> None:
    """A header segment lies within the header, a file segment has a start, an excluded name is a
    record head field."""
    first = next(iter(st.headers.values()))
    rnames = {f.name for f in st.record.fields}
    for k, cov in st.raw["checksums"]["coverages"].items():
        for s in cov["segments"]:
            if "fields" in s:
                continue
            seg = _segment(s)
            if seg.region == "header" and (seg.start is None or seg.end is None or seg.end > first.size
                                           or seg.start >= seg.end):
                ctx.fail(s, f"coverage {k}: header segment needs 0 <= start < end <= {first.size}")
            if seg.region == "file" and seg.start is None:
                ctx.fail(s, f"coverage {k}: file segment needs a start")
            for ex in seg.exclude:
                if ex not in rnames:
                    ctx.fail(s, f"coverage {k}: unknown record field {ex!r}", "exclude")


@define("checksum-defs", "check", reads=("raw", "headers", "record", "bare_commands", "bare_checksums"))
def CHECKSUM_DEFS(ctx: Problems, st: State) -> None:
    """Each definition names a known algorithm whose result fits the stored field and a known
    coverage; the args, header and file checksums are defined; every tag a field carries is
    defined; fill_order names every checksum once."""
    cs, raw_cs = st.bare_checksums, st.raw["checksums"]
    for f in raw_cs["fields"]:
        if f["algorithm"] not in cs.algorithms:
            ctx.fail(f, f"checksum {f['field']}: unknown algorithm {f['algorithm']!r}", "algorithm")
        elif next(o for o in raw_cs["fields"] if o["field"] == f["field"]) is f:
            fits(ctx, st, f, "algorithm", f["field"], f["algorithm"], f"checksum {f['field']}")
        if f["coverage"] not in cs.coverages:
            ctx.fail(f, f"checksum {f['field']}: unknown coverage {f['coverage']!r}", "coverage")
    tags = {f.field for f in cs.fields}
    for tag in ("args", "header", "file"):
        if tag not in tags:
            ctx.fail(raw_cs, f"checksums: no definition for the {tag} checksum", "fields")
    for hf in [f for h in st.headers.values() for f in h.fields] + arg_checksum_fields(st):
        if hf.checksum and hf.checksum not in tags:
            ctx.at(hf.line, f"field {hf.name}: checksum {hf.checksum} is not defined")
    if sorted(cs.fill_order) != sorted(tags):
        ctx.fail(raw_cs, "checksums.fill_order must name every checksum once", "fill_order")
