"""Every checksum field is judged by exactly one check of the kind that judges its place
(registry.LoaderRules.judges): header checksum fields by a header kind, record ones by a record kind."""

from __future__ import annotations

from ...model import Check, Field
from ...registry import loader_rules
from .. import named
from ..pipeline import State, define
from ..problems import Problems


def _header_widths(ctx: Problems, st: State) -> dict[str, Field]:
    """The first header field of each checksum tag; a tag of two widths, or a field that is no
    unsigned checksum field, is refused."""
    width: dict[str, Field] = {}
    for h in st.headers.values():
        for f in h.fields:
            if not f.checksum:
                continue
            if f.role != "checksum" or f.kind != "uint":
                ctx.at(f.line, f"header {h.id} field {f.name}: a checksum field needs role checksum and an "
                               f"unsigned integer type")
            first = width.setdefault(f.checksum, f)
            if first.size != f.size:
                ctx.at(f.line, f"header {h.id} field {f.name}: checksum {f.checksum} is {f.size} bytes here, "
                               f"{first.size} at line {first.line}")
    return width


def _judge_header(ctx: Problems, st: State, ch: Check, width: dict[str, Field], judged: dict[str, Check]) -> None:
    tag = ch.checksum_field or "header"
    if tag not in width or tag in named.record_tags(st.record) or tag == "file":
        ctx.at(ch.line, f"check {ch.id}: field {tag} is no header checksum field (a tag of a header "
                        f"field, other than the file checksum)")
        return
    if tag in judged:
        ctx.at(ch.line, f"check {ch.id}: checksum {tag} is judged by check {judged[tag].id} already")
    judged.setdefault(tag, ch)
    defined = {f.field: f for f in st.checksums.fields}
    cov = st.checksums.coverages.get(defined[tag].coverage) if tag in defined else None
    if cov is not None and any(seg.region != "header" for seg in cov.segments):
        ctx.at(ch.line, f"check {ch.id}: checksum {tag} covers more than header bytes (coverage "
                        f"{cov.name}); a header_checksum check judges header bytes only")


@define("header-checksum-fields", "check", reads=("headers", "record", "checksums", "checks"))
def HEADER_CHECKSUM_FIELDS(ctx: Problems, st: State) -> None:
    """Checksum fields as data: a tag may sit in any header layout (a new version's header turns
    reserved bytes into one); each tag has one width; every header checksum field but the file
    checksum is judged by exactly one header-judging check (its `field`), over header bytes only
    (the header is judged before the records are framed)."""
    width = _header_widths(ctx, st)
    judged: dict[str, Check] = {}
    for ch in st.checks:
        if loader_rules(ch.kind).judges == "header":
            _judge_header(ctx, st, ch, width, judged)
    for tag, f in width.items():
        if tag != "file" and tag not in judged:
            ctx.at(f.line, f"field {f.name}: no header_checksum check judges checksum {tag} (every binding "
                           f"would read it and none check it)")


@define("record-checksum-checks", "check", reads=("record", "commands", "checks"))
def RECORD_CHECKSUM_CHECKS(ctx: Problems, st: State) -> None:
    """Every checksum field among command arguments is judged by exactly one record-judging check
    (its ``field``); such a check names a record checksum field (the head's or an argument's)."""
    head_tags = named.record_tags(st.record)
    arg_tags = {ck.tag: ck.field for c in st.commands for lay in c.layouts for ck in lay.checksums}
    judged: dict[str, Check] = {}
    for ch in st.checks:
        if loader_rules(ch.kind).judges != "record":
            continue
        tag = ch.checksum_field or "args"
        if tag not in head_tags and tag not in arg_tags:
            ctx.at(ch.line, f"check {ch.id}: field {tag} is no record checksum field (the record head's, or a "
                            f"checksum among a command's arguments)")
            continue
        if tag in arg_tags and tag in judged:
            ctx.at(ch.line, f"check {ch.id}: checksum {tag} is judged by check {judged[tag].id} already")
        judged.setdefault(tag, ch)
    for tag, f in arg_tags.items():
        if tag not in judged:
            ctx.at(f.line, f"argument {f.name}: no arg_checksum check judges checksum {tag} (every binding would "
                           f"read it and none check it)")
