"""Checksum fields among command arguments (issue 25, point 1): resolved to byte ranges of the
record in each layout that carries one, then checked."""

from __future__ import annotations

from dataclasses import replace

from ...model import ArgChecksum, Command, Field, Layout
from .. import named
from ..pipeline import State, define
from ..problems import Problems


def _resolved(st: State, lay: Layout, a: Field) -> ArgChecksum | None:
    cov = named.arg_coverage(st.bare_checksums, str(a.checksum))
    if cov is None or any(seg.region != "fields" for seg in cov.segments):
        return None
    got = [r for r in named.in_record(cov, lay, a, st.record) if r.span is not None and r.trouble != "itself"]
    algorithm = next(f.algorithm for f in st.bare_checksums.fields if f.field == a.checksum)
    return ArgChecksum(str(a.checksum), a, algorithm, tuple(r.name for r in got),
                       tuple(r.span for r in got if r.span is not None))


def _command(st: State, cmd: Command, head: set[str], header: set[str]) -> Command:
    layouts = []
    for lay in cmd.layouts:
        found = [_resolved(st, lay, a) for a in lay.args
                 if a.checksum and named.arg_trouble(a, lay, head, header) == ""]
        layouts.append(replace(lay, checksums=tuple(x for x in found if x is not None)))
    return replace(cmd, layouts=tuple(layouts))


@define("arg-checksums", "resolve", reads=("headers", "record", "bare_commands", "bare_checksums"),
        produces=("commands",))
def ARG_CHECKSUMS(ctx: Problems, st: State) -> None:
    """Each layout's argument checksums (model.ArgChecksum): the fields its coverage names,
    resolved to the record's bytes in that layout."""
    head, header = named.record_tags(st.record), named.header_tags(st.headers.values())
    st.commands = tuple(_command(st, cmd, head, header) for cmd in st.bare_commands)


def _seg_node(st: State, cov: str) -> object:
    raw_cov = st.raw["checksums"]["coverages"]
    return next((s for s in raw_cov[cov]["segments"] if "fields" in s), raw_cov[cov])


def _argument(ctx: Problems, st: State, name: str, lay: Layout, a: Field, first: dict[str, Field]) -> None:
    head, header = named.record_tags(st.record), named.header_tags(st.headers.values())
    trouble = named.arg_trouble(a, lay, head, header)
    if trouble == "untagged":
        ctx.at(a.line, f"{name} argument {a.name}: role checksum needs a checksum tag (`checksum:`)")
    elif trouble == "shape":
        ctx.at(a.line, f"{name} argument {a.name}: a checksum field needs role checksum and one unsigned integer")
    elif trouble == "tag":
        ctx.at(a.line, f"{name} argument {a.name}: checksum {a.checksum} is the tag of a header or record head field")
    elif trouble == "repeat":
        ctx.at(a.line, f"{name} argument {a.name}: a checksum field in a layout with a repeated group (its "
                       f"coverage would move with n) is not supported")
    if trouble or not a.checksum:
        return
    other = first.setdefault(a.checksum, a)
    if other.size != a.size:
        ctx.at(a.line, f"{name} argument {a.name}: checksum {a.checksum} is {a.size} bytes here, "
                       f"{other.size} at line {other.line}")
    cov = named.arg_coverage(st.bare_checksums, a.checksum)
    if cov is None:
        return  # the checksum-defs pass said so
    if any(seg.region != "fields" for seg in cov.segments):
        ctx.at(a.line, f"{name} argument {a.name}: checksum {a.checksum} has coverage {cov.name}, not made of "
                       f"named fields (an argument's checksum covers named fields of its record)")
        return
    _names(ctx, st, name, lay, a, cov.name)


def _names(ctx: Problems, st: State, name: str, lay: Layout, a: Field, cov_name: str) -> None:
    node = _seg_node(st, cov_name)
    for r in named.in_record(st.bare_checksums.coverages[cov_name], lay, a, st.record):
        if r.trouble == "both":
            ctx.fail(node, f"coverage {cov_name}: {r.name} names both an argument of {name} and a record head "
                           f"field", "fields")
        elif r.trouble == "neither":
            ctx.fail(node, f"coverage {cov_name}: {name} {'/'.join(lay.versions)} has no argument or record head "
                           f"field {r.name}", "fields")
        elif r.trouble == "itself":
            ctx.fail(node, f"coverage {cov_name}: checksum {a.checksum} covers itself ({name} argument {a.name})",
                     "fields")


@define("arg-checksum-fields", "check", reads=("raw", "headers", "record", "bare_commands", "bare_checksums"))
def ARG_CHECKSUM_FIELDS(ctx: Problems, st: State) -> None:
    """An argument with ``checksum: TAG`` is a checksum field: role checksum, one unsigned integer,
    one width for its tag, a tag no header or record head field uses, in a layout of fixed size,
    and a coverage made of named fields only, each naming one argument of its layout or record
    head field, not the checksum itself."""
    first: dict[str, Field] = {}
    for cmd in st.bare_commands:
        for lay in cmd.layouts:
            for a in lay.args:
                _argument(ctx, st, cmd.name, lay, a, first)


@define("named-coverage-users", "check", reads=("raw", "record", "bare_checksums", "profiles"))
def NAMED_COVERAGE_USERS(ctx: Problems, st: State) -> None:
    """A coverage by named fields serves one header or argument checksum field, no record head
    checksum and no profile."""
    cs, raw_cov = st.bare_checksums, st.raw["checksums"]["coverages"]
    head = named.record_tags(st.record)
    users: dict[str, list[str]] = {}
    for f in cs.fields:
        users.setdefault(f.coverage, []).append(f.field)
    for p in st.profiles:
        for k in (*p.file_coverages, *p.hint_coverages):
            users.setdefault(k, []).append(f"profile {p.id}")
    for k in sorted(named.named_coverages(cs)):
        if len(users.get(k, [])) > 1 or any(u in head for u in users.get(k, [])):
            ctx.fail(raw_cov[k], f"coverage {k}: a coverage by named fields serves one header or argument checksum "
                                 f"field (used by {', '.join(users[k])})", "segments")
