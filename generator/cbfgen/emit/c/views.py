"""What the C templates read: one small typed view a section of cbf.h (frozen dataclasses), built
from the model by one function each. `CContext.namespace()` is what Jinja sees: the sections'
fields by name (the templates, cbf_testee's and cbf_tool's included, use those names).

Nothing here names a command, field, offset or check: every identifier and number comes from the
model, the field types and check kinds from the registry.
"""

from __future__ import annotations

from dataclasses import dataclass, fields
from typing import Any

from ... import __license__ as TOOLKIT_LICENSE
from ... import __version__ as TOOLKIT_VERSION
from ... import registry
from ...model import Command, Field, Layout, Spec
from ...options import cutter_columns
from .cnames import cfloat, cname, ctype, macro, member_doc
from .machine import MachineView, machine_view

# The model's vocabulary the engine understands (loader.py, spec comments); the role kinds, field
# types and check kinds come from the registry (cbfgen/registry.py), never from a list here.
MOTION_KINDS = registry.ROLE_KINDS["motion"]
MOTION_KEYS = ("start", "end", "center", "normal", "degrees", "length", "through")
ORIENT_KINDS = registry.ROLE_KINDS["orientation"]
ORIENT_KEYS = ("start", "end")
SHAPE_KINDS = registry.ROLE_KINDS["shape"]
SHAPE_KEYS = ("name", "count")
REGIONS = ("file", "header", "records", "args", "fields")  # fields: an argument checksum's named fields (cbf__argcks)
ALGORITHMS = tuple(registry.ALGORITHMS)  # each kind a row of cbf/algorithms.c.j2 (checksums.c: one per family)
CHECKSUM_TAGS = ("args", "header", "file")  # first, in this order; a spec's own tags follow (_tags)


def _tags(spec: Spec) -> tuple[str, ...]:
    """The checksum tags of the spec: today's three, then any other, in checksums.fields order."""
    return CHECKSUM_TAGS + tuple(f.field for f in spec.checksums.fields if f.field not in CHECKSUM_TAGS)
# The signature ("shape") of a targeted check kind's C kernel, cbf__<kind>_at (runtime/validator.c), from the
# registry: a kind that judges a target's items (registry `items`) runs its own machine rules (machine.py); a
# kind that compares a target's arguments with each other (registry `whole`) judges the target whole; every
# other one float argument. The kernels are called through per-shape tables indexed by kind
# (validator_layouts.c.j2), so a targeted kind the registry gains and the C engine lacks fails the build,
# naming its kernel.


def kernel_shape(kind: registry.CheckKind) -> str:
    """argument, target, items, or "" for a kind that judges no target (the engine's own passes)."""
    if not kind.targeted:
        return ""
    if kind.items:
        return "items"
    return "target" if kind.whole else "argument"


# -- rows -------------------------------------------------------------------------------------

@dataclass(frozen=True)
class FieldRow:
    """A header field, record head field or argument: its struct member and its cbf_field_info row."""

    name: str
    member: str
    ctype: str
    suffix: str
    kind: str  # UINT, SINT, FLOAT, STRING, BYTES (CBF_KIND_*)
    role: str  # ROLE_*
    offset: int
    elem: int
    count: int
    size: int
    struct: str | None
    magic: int | None
    checksum: str  # CK_*
    flags: tuple[str, ...]  # RESERVED, TEXT, MAGIC (CBF__F_*)
    unit: str | None
    macro: str
    doc: str
    # A repeated argument group (issue 25, point 3): (min n, max n); the row describes one item
    # (count: its elements), the struct member a bounded array of max n items beside their count n.
    repeat: tuple[int, int] | None = None

    @property
    def designator(self) -> str:
        """The member designator of the field's values in its struct (offsetof): a group's items."""
        return f"{self.member}.items" if self.repeat else self.member


def field_row(f: Field, struct: str | None, units: dict[str, str]) -> FieldRow:
    type_, suffix = ctype(f)
    flags = tuple(x for x, on in (("RESERVED", f.reserved), ("TEXT", f.text), ("MAGIC", f.magic is not None)) if on)
    return FieldRow(
        name=f.name, member=cname(f.name), ctype=type_, suffix=suffix, kind=macro(f.kind),
        role=("ROLE_" + macro(f.role)) if f.role else "ROLE_NONE", offset=f.offset, elem=f.elem_size,
        count=f.count, size=f.size, struct=struct, magic=f.magic,
        checksum=("CK_" + macro(f.checksum)) if f.checksum else "CK_NONE", flags=flags, unit=f.unit,
        macro=macro(f.name), doc=member_doc(f, units), repeat=f.repeat)


@dataclass(frozen=True)
class HeaderRow:
    id: str
    macro: str
    struct: str
    size: int
    clause: str
    doc: str
    fields: tuple[FieldRow, ...]


@dataclass(frozen=True)
class RecordView:
    head_size: int
    fields: tuple[FieldRow, ...]
    clause: str
    doc: str


@dataclass(frozen=True)
class VersionRow:
    id: str
    macro: str
    major: int
    minor: int  # -1: any
    header: int
    writable: int
    doc: str
    clause: str


@dataclass(frozen=True)
class DecodedArg:
    """A float or string argument the layout function reads once a record (x<arg>, ok<arg>)."""

    name: str
    kind: str
    offset: int
    count: int
    row: int  # in cbf__args
    arg: int  # in the layout


@dataclass(frozen=True)
class PlannedCheck:
    """A (check, target) pair a layout's records run, with the kernel and the float rows it reads."""

    check: int
    target: int
    kind: str  # the kind's macro (CBF__KIND_*), the index of its kernel
    shape: str  # argument or target (kernel_shape)
    text: str
    args: tuple[int, ...]


@dataclass(frozen=True)
class Motion:
    start: int
    end: int
    center: int
    normal: int
    degrees: tuple[int, int]
    length: tuple[int, int]
    start_var: str
    end_var: str


@dataclass(frozen=True)
class Orientation:
    start: int
    end: int
    start_var: str
    end_var: str


@dataclass(frozen=True)
class Group:
    """A layout's repeated argument group (issue 25, point 3): nb = size + item_size * n, min <= n <= max.
    The group is the layout's last argument (arg); its row in cbf__args describes one item."""

    arg: int  # index in the layout
    name: str
    offset: int  # of the first item, in the argument bytes (the fixed arguments' size)
    item_size: int
    count: int  # elements an item
    kind: str  # FLOAT, UINT, SINT
    min: int
    max: int


@dataclass(frozen=True)
class Plan:
    """What a record of a layout checks, as constants (templates/cbf/validator_layouts.c.j2)."""

    values: tuple[DecodedArg, ...]
    motion: Motion
    orient: Orientation
    targets: tuple[PlannedCheck, ...]


@dataclass(frozen=True)
class LayoutRow:
    index: int
    command: int
    cmd_name: str
    variant: str | None
    macro: str
    member: str
    struct: str
    size: int
    versions: tuple[str, ...]
    vmask: tuple[str, ...]  # the macros of its versions (CBF__VBIT(CBF_V*))
    pmask: tuple[int, ...]  # the indexes of the profiles it is accepted under, none: every profile (CBF__PBIT)
    profiles: tuple[str, ...]
    first_arg: int
    nargs: int
    args: tuple[FieldRow, ...]
    motion: tuple[int, ...]
    orient: tuple[int, ...]
    shape: tuple[int, ...]
    cutter: tuple[int, ...]
    progress: int
    doc: str
    clause: str
    plan: Plan
    group: Group | None = None  # the repeated argument group (issue 25, point 3), None: a fixed layout

    @property
    def max_size(self) -> int:
        """The most argument bytes a record of the layout holds (its size when it has no group)."""
        return self.size + (self.group.item_size * self.group.max if self.group else 0)


@dataclass(frozen=True)
class VersionLayouts:
    macro: str
    layouts: tuple[LayoutRow, ...]


@dataclass(frozen=True)
class CommandRow:
    index: int
    name: str
    macro: str
    code: int
    doc: str
    clause: str
    first: int
    nlayouts: int
    cands: tuple[tuple[int, ...], ...]  # per version, padded with -1
    motion: str
    orient: str
    shape: str
    cutter: int
    vmask: tuple[str, ...]  # the macros of its versions (CBF__VBIT(CBF_V*))
    layouts: tuple[LayoutRow, ...]
    per_version: tuple[VersionLayouts, ...]
    first_ct: int
    n_ct: int
    former: tuple[str, ...] = ()  # macros of the command's former names (issue 25, point 6): aliases


@dataclass(frozen=True)
class SegmentRow:
    region: str
    start: int
    end: int
    exclude: tuple[int, ...]  # the record head fields (index) the segment leaves out


@dataclass(frozen=True)
class CoverageRow:
    name: str
    first: int
    n: int
    doc: str


@dataclass(frozen=True)
class CkFieldRow:
    tag: str
    alg: str
    coverage: int
    check: int = -1  # the header_checksum check that judges the field (index in cbf__checks), -1: none


@dataclass(frozen=True)
class ProfileRow:
    id: str
    macro: str
    doc: str
    file: tuple[int, ...]
    hint: tuple[int, ...]
    file_alg: str
    hint_alg: tuple[str, ...]
    file_pad: tuple[int, ...]
    hint_pad: tuple[int, ...]
    hint_alg_pad: tuple[str, ...]
    hint_owner_pad: tuple[int, ...]  # the profile (index) that accepts each hint coverage, -1: none


@dataclass(frozen=True)
class AvailRow:
    name: str
    row: tuple[int, ...]


@dataclass(frozen=True)
class CheckRow:
    id: str
    macro: str
    kind: str  # KIND_*
    kind_name: str  # the registry's name
    severity: str
    error: int
    vmask: tuple[str, ...]  # the macros of its versions (CBF__VBIT(CBF_V*))
    first: int
    n: int
    has_min: int
    min: str
    has_max: int
    max: str
    min_open: int
    max_open: int
    text: str
    fails: str
    clause: str
    decision: str


@dataclass(frozen=True)
class TargetRow:
    command: int
    first: int
    n: int
    text: str


@dataclass(frozen=True)
class CheckTarget:
    """A (check, target) pair of one command's records (grouped by command, in check order)."""

    check: int
    target: int
    text: str


@dataclass(frozen=True)
class Constant:
    macro: str
    value: str | int
    name: str


# -- sections ---------------------------------------------------------------------------------

@dataclass(frozen=True)
class About:
    """prologue.h.j2, cbf.pc.in.j2: the spec's identity and the byte order."""

    meta: dict[str, Any]
    toolkit_version: str
    toolkit_license: str
    spec_revision: str
    little: bool
    pad: int


@dataclass(frozen=True)
class Vocabulary:
    """impl_prologue.c.j2, enums.h.j2: the model's vocabulary, numbered (kinds from the registry)."""

    roles: tuple[str, ...]
    tags: tuple[str, ...]
    algorithms: tuple[str, ...]
    regions: tuple[str, ...]
    motion_kinds: tuple[str, ...]
    motion_keys: tuple[str, ...]
    orient_kinds: tuple[str, ...]
    orient_keys: tuple[str, ...]
    shape_kinds: tuple[str, ...]
    shape_keys: tuple[str, ...]
    cutter_keys: tuple[str, ...]
    check_kinds: tuple[str, ...]
    kernel_shapes: tuple[str, ...]  # per check kind, its kernel's shape (kernel_shape)
    pass_kinds: tuple[str, ...]  # the kinds no kernel table holds: the engine's passes judge them (CBF__PASS_KINDS)
    check_kind_names: tuple[str, ...]
    field_kinds: tuple[str, ...]


@dataclass(frozen=True)
class Framing:
    """structs.h.j2, ids.h.j2, impl_prologue.c.j2: headers and the record head."""

    headers: tuple[HeaderRow, ...]
    header_size: int
    record: RecordView
    head: dict[str, FieldRow]  # record head fields by role (without ROLE_)
    head_checksum: FieldRow | None
    version_major_offset: int


@dataclass(frozen=True)
class Versions:
    versions: tuple[VersionRow, ...]
    default_version: int
    fallback_version: int


@dataclass(frozen=True)
class Commands:
    """ids.h.j2, structs.h.j2, tables.c.j2, writer.c.j2, validator_layouts.c.j2."""

    commands: tuple[CommandRow, ...]
    sorted_commands: tuple[CommandRow, ...]
    index_by_code: tuple[int, ...]
    names_by_code: tuple[str | None, ...]
    layouts: tuple[LayoutRow, ...]
    arg_rows: tuple[FieldRow, ...]
    max_layouts: int
    max_arg: int


@dataclass(frozen=True)
class ArgCkRow:
    """A checksum field among a layout's arguments (issue 25, point 1): its layout (index in
    cbf__layouts), its row of cbf__ckfields, its argument's offset and width, its record ranges."""

    layout: int
    ckfield: int
    offset: int
    elem: int
    first: int
    n: int
    what: str


@dataclass(frozen=True)
class Checksums:
    segments: tuple[SegmentRow, ...]
    coverages: tuple[CoverageRow, ...]
    ckfields: tuple[CkFieldRow, ...]
    fill: tuple[str, ...]
    argcks: tuple[ArgCkRow, ...] = ()  # in fill order within each layout
    ranges: tuple[tuple[int, int], ...] = ()


@dataclass(frozen=True)
class Profiles:
    profiles: tuple[ProfileRow, ...]
    max_cov: int
    avail_rows: tuple[AvailRow, ...]


@dataclass(frozen=True)
class Checks:
    checks: tuple[CheckRow, ...]
    targets: tuple[TargetRow, ...]  # one placeholder row when there is none (C has no empty array)
    ntargets: int
    tnames: tuple[str, ...]
    tindex: tuple[tuple[int, ...], ...]  # per target argument, its index in each layout (-1: none)
    deprecated: tuple[int, ...] = ()  # per layout: the deprecation check that names it (-1: none)


@dataclass(frozen=True)
class Constants:
    tolerances: tuple[Constant, ...]
    limits: tuple[Constant, ...]


@dataclass(frozen=True)
class CContext:
    about: About
    vocabulary: Vocabulary
    framing: Framing
    versions: Versions
    commands: Commands
    checksums: Checksums
    profiles: Profiles
    checks: Checks
    constants: Constants
    machine: MachineView

    def namespace(self) -> dict[str, Any]:
        """The names the templates read: every section's fields (no two sections share a name)."""
        out: dict[str, Any] = {}
        for section in fields(self):
            view = getattr(self, section.name)
            for f in fields(view):
                assert f.name not in out, f"two sections of the C context name {f.name}"
                out[f.name] = getattr(view, f.name)
        return out


# -- builders ---------------------------------------------------------------------------------

def _roles(spec: Spec) -> list[str]:
    roles: list[str] = []
    for f in [f for h in spec.headers.values() for f in h.fields] + list(spec.record.fields):
        if f.role and f.role not in roles:
            roles.append(f.role)
    return roles


def _about(spec: Spec) -> About:
    if spec.meta.get("byte_order") not in ("little", "big"):
        raise ValueError("C binding: byte_order must be little or big")
    return About(meta=spec.meta, toolkit_version=TOOLKIT_VERSION, toolkit_license=TOOLKIT_LICENSE,
                 spec_revision=spec.revision, little=spec.meta["byte_order"] == "little",
                 pad=int(spec.meta.get("string_padding", 0)))


def _vocabulary(spec: Spec) -> Vocabulary:
    def m(names: tuple[str, ...] | list[str]) -> tuple[str, ...]:
        return tuple(macro(k) for k in names)

    return Vocabulary(
        roles=m(_roles(spec)), tags=m(_tags(spec)), algorithms=m(ALGORITHMS), regions=m(REGIONS),
        motion_kinds=m(MOTION_KINDS), motion_keys=m(MOTION_KEYS), orient_kinds=m(ORIENT_KINDS),
        orient_keys=m(ORIENT_KEYS), shape_kinds=m(SHAPE_KINDS), shape_keys=m(SHAPE_KEYS),
        cutter_keys=cutter_columns(spec).all, check_kinds=m(list(registry.CHECK_KINDS)),
        kernel_shapes=tuple(kernel_shape(k) for k in registry.CHECK_KINDS.values()),
        pass_kinds=m([k.name for k in registry.CHECK_KINDS.values() if kernel_shape(k) in ("", "items")]),
        check_kind_names=tuple(registry.CHECK_KINDS), field_kinds=m(registry.FIELD_KINDS))


def _framing(spec: Spec) -> Framing:
    headers = tuple(HeaderRow(
        id=hid, macro=macro(hid), struct="cbf_header_" + cname(hid), size=h.size, clause=h.clause,
        doc=h.doc, fields=tuple(field_row(f, "cbf_header_" + cname(hid), spec.units) for f in h.fields))
        for hid, h in spec.headers.items())
    if any(f.kind != "uint" for f in spec.record.fields):
        raise ValueError("C binding: record head fields must be unsigned integers")
    rec = tuple(field_row(f, "cbf_record_head", spec.units) for f in spec.record.fields)
    return Framing(
        headers=headers, header_size=spec.header_size,
        record=RecordView(head_size=spec.record.head_size, fields=rec, clause=spec.record.clause,
                          doc=spec.record.doc),
        head={f.role[len("ROLE_"):]: f for f in rec if f.role != "ROLE_NONE"},
        head_checksum=next((f for f in rec if f.checksum == "CK_ARGS"), None),
        version_major_offset=spec.common_header_field("version_major").offset)


def _versions(spec: Spec) -> Versions:
    header_ids = list(spec.headers)
    ids = [v.id for v in spec.versions]
    return Versions(
        versions=tuple(VersionRow(id=v.id, macro=macro(v.id), major=v.major, minor=-1 if v.minor is None else v.minor,
                                  header=header_ids.index(v.header), writable=int(v.writable), doc=v.doc,
                                  clause=v.clause) for v in spec.versions),
        default_version=ids.index(spec.default_version), fallback_version=ids.index(spec.fallback_version))


def _vmask(versions: tuple[str, ...] | list[str]) -> tuple[str, ...]:
    """The macros of the versions (the templates spell the mask)."""
    return tuple(macro(v) for v in versions)


def _role_index(lay: Layout, role: dict[str, str] | None, keys: tuple[str, ...]) -> tuple[int, ...]:
    """Per key of a command's role (motion, orientation ...), the index of the argument it names (-1: none)."""
    names = [a.name for a in lay.args]
    return tuple(names.index(n) if (n := (role or {}).get(k)) in names else -1 for k in keys)


def _plan(args: tuple[FieldRow, ...], first_arg: int, motion: tuple[int, ...], orient: tuple[int, ...],
          targets: list[PlannedCheck]) -> Plan:
    """The constants a layout's checks read: its float and string arguments, the offsets the motion
    and orientation roles read (-1: none)."""

    def vec(i: int) -> int:
        """Offset of a 3-element float argument, -1 when the role has none."""
        return args[i].offset if i >= 0 and args[i].kind == "FLOAT" and args[i].count == 3 else -1

    def scalar(i: int) -> tuple[int, int]:
        """(offset, element count) of a float argument, (-1, 0) when the role has none."""
        return (args[i].offset, args[i].count) if i >= 0 and args[i].kind == "FLOAT" else (-1, 0)

    def var(i: int) -> str:
        """The generated local that holds a 3-element float argument, decoded once a record (NULL: none)."""
        return f"x{i}" if vec(i) >= 0 else "NULL"

    m = dict(zip(MOTION_KEYS, motion, strict=True))
    o = dict(zip(ORIENT_KEYS, orient, strict=True))
    return Plan(
        # each float argument is decoded once into x<arg> (finite flag ok<arg>) and shared by the checks
        values=tuple(DecodedArg(name=a.name, kind=a.kind, offset=a.offset, count=a.count, row=first_arg + i, arg=i)
                     for i, a in enumerate(args) if a.kind in ("FLOAT", "STRING")),
        motion=Motion(start=vec(m["start"]), end=vec(m["end"]), center=vec(m["center"]), normal=vec(m["normal"]),
                      degrees=scalar(m["degrees"]), length=scalar(m["length"]), start_var=var(m["start"]),
                      end_var=var(m["end"])),
        orient=Orientation(start=vec(o["start"]), end=vec(o["end"]), start_var=var(o["start"]),
                           end_var=var(o["end"])),
        targets=tuple(targets))


def _checks(spec: Spec) -> tuple[tuple[CheckRow, ...], list[tuple[int, int, str, tuple[str, ...]]]]:
    """The checks as rows, and their targets (command index, check index, text, argument names)."""
    cmd_index = {c.name: i for i, c in enumerate(spec.commands)}
    rows: list[CheckRow] = []
    targets: list[tuple[int, int, str, tuple[str, ...]]] = []
    for ci, ch in enumerate(spec.checks):
        if ch.kind not in registry.CHECK_KINDS:
            raise ValueError(f"C binding: check {ch.id}: kind {ch.kind!r} is not in the registry")
        rows.append(CheckRow(
            id=ch.id, macro=macro(ch.id), kind="KIND_" + macro(ch.kind), kind_name=ch.kind, severity=ch.severity,
            error=int(ch.severity == "error"), vmask=_vmask(ch.versions), first=len(targets),
            n=len(ch.targets), has_min=int(ch.min is not None), min=cfloat(0.0 if ch.min is None else ch.min),
            has_max=int(ch.max is not None), max=cfloat(0.0 if ch.max is None else ch.max),
            min_open=int(ch.min_exclusive),
            max_open=int(ch.max_exclusive), text=ch.text,
            fails=ch.fails, clause=ch.clause or "", decision=ch.decision or ""))
        targets.extend((cmd_index[t.command], ci, f"{t.command} {' '.join(t.args)}", tuple(t.args))
                       for t in ch.targets)
    return tuple(rows), targets


def _group(lay: Layout) -> Group | None:
    """The layout's repeated argument group as the C engine reads it (issue 25, point 3), else None."""
    rep = lay.repeated
    if rep is None or rep.repeat is None:
        return None
    if rep.kind not in ("float", "uint", "sint"):
        raise ValueError(f"C binding: {lay.command} {rep.name}: only numbers repeat (the loader refuses it first)")
    return Group(arg=len(lay.args) - 1, name=rep.name, offset=rep.offset, item_size=rep.size, count=rep.count,
                 kind=macro(rep.kind), min=rep.repeat[0], max=rep.repeat[1])


def _layout_rows(spec: Spec, c: Command, ci: int, first: int, first_arg: int, profiles: list[str],
                 planned: dict[int, list[PlannedCheck]]) -> list[LayoutRow]:
    out: list[LayoutRow] = []
    for j, lay in enumerate(c.layouts):
        suffix = ("_" + cname(lay.variant)) if lay.variant else ""
        struct = f"cbf_{cname(c.name)}{suffix}_args"
        for a in lay.args:
            if a.kind == "float" and a.elem_size != 4:  # the codec carries it; the checks read binary32
                raise ValueError(f"C binding: {c.name} {a.name}: the C validator reads binary32 arguments only "
                                 "(registry.unsupported says so; the loader refuses it first)")
        args = tuple(field_row(a, struct, spec.units) for a in lay.args)
        group = _group(lay)
        motion = _role_index(lay, c.motion, MOTION_KEYS)
        orient = _role_index(lay, c.orientation, ORIENT_KEYS)
        out.append(LayoutRow(
            index=first + j, command=ci, cmd_name=c.name, variant=lay.variant,
            macro=macro(c.name) + (("_" + macro(lay.variant)) if lay.variant else ""),
            member=cname(c.name) + suffix, struct=struct, size=lay.size, versions=tuple(lay.versions),
            vmask=_vmask(lay.versions),
            pmask=tuple(profiles.index(p) for p in lay.profiles),
            profiles=tuple(lay.profiles), first_arg=first_arg, nargs=len(args), args=args, motion=motion,
            orient=orient, shape=_role_index(lay, c.shape, SHAPE_KEYS),
            cutter=_role_index(lay, c.cutter, cutter_columns(spec).all),
            progress=_role_index(lay, {"p": c.progress} if c.progress else None, ("p",))[0],
            doc=lay.doc or c.doc, clause=lay.clause or c.clause,
            plan=_plan(args, first_arg, motion, orient, planned.get(first + j, [])), group=group))
        first_arg += len(args)
    return out


@dataclass(frozen=True)
class _Targets:
    """The checks' targets, flat (command index, check index, text, argument names), and per target
    argument its index in each layout (-1: the layout does not carry it)."""

    rows: tuple[tuple[int, int, str, tuple[str, ...]], ...]
    names: tuple[str, ...]  # every target's argument names, in order
    index: tuple[tuple[int, ...], ...]  # per target argument, its index in each layout
    first: tuple[int, ...]  # per target, its first argument in names and index

    def arg_rows(self, target: int, layout: int) -> list[int]:
        """The indexes (in the layout) of the arguments a target names (-1: not in the layout)."""
        return [self.index[self.first[target] + a][layout] for a in range(len(self.rows[target][3]))]


def _flat_layouts(spec: Spec) -> list[tuple[int, Layout]]:
    """Every layout with its command's index, in cbf__layouts order."""
    return [(ci, lay) for ci, c in enumerate(spec.commands) for lay in c.layouts]


def _arg_index(lay: Layout, name: str) -> int:
    return next((i for i, a in enumerate(lay.args) if a.name == name), -1)


def _target_table(spec: Spec, rows: list[tuple[int, int, str, tuple[str, ...]]]) -> _Targets:
    flat = _flat_layouts(spec)
    index = tuple(tuple(_arg_index(lay, n) if ci == tc else -1 for ci, lay in flat)
                  for tc, _, _, names in rows for n in names)
    first = tuple(sum(len(t[3]) for t in rows[:k]) for k in range(len(rows)))
    return _Targets(rows=tuple(rows), names=tuple(n for *_, names in rows for n in names), index=index, first=first)


def _by_command(spec: Spec, check_rows: tuple[CheckRow, ...], targets: _Targets) -> tuple[list[CheckTarget], list[int]]:
    """The (check, target) pairs grouped by command, so that the validator visits only the checks that
    name the record's command (in check order), and each command's first pair (one more: the end)."""
    pairs: list[CheckTarget] = []
    first: list[int] = []
    for ci in range(len(spec.commands)):
        first.append(len(pairs))
        pairs.extend(CheckTarget(check=t[1], target=ti, text=f"{check_rows[t[1]].id}: {t[2]}")
                     for ti, t in enumerate(targets.rows) if t[0] == ci)
    first.append(len(pairs))
    return pairs, first


def _planned_pair(lay: Layout, li: int, first_arg: int, ct: CheckTarget, row: CheckRow,
                  targets: _Targets) -> PlannedCheck | None:
    """The kernel a layout's records run for a (check, target) pair of its command; None when the
    kind judges items (its own rules, machine.py) or the layout lacks the float arguments it reads."""
    rows = targets.arg_rows(ct.target, li)
    floats = tuple(first_arg + i for i in rows if i >= 0 and lay.args[i].kind == "float")
    kind = registry.CHECK_KINDS[row.kind_name]
    shape = kernel_shape(kind)
    if shape == "items":
        return None  # its own rules (machine.py), called from the layout function too
    if lay.repeated is not None and len(lay.args) - 1 in rows:
        # a repeated group is judged item by item by the kinds that know items (machine_limits)
        raise ValueError(f"C binding: check {row.id} ({row.kind_name}) targets the repeated argument group "
                         f"{lay.command} {lay.args[-1].name}: only machine_limits judges a group, item by item")
    # a check finds nothing in a layout without its float arguments (a whole target: without all of them)
    reads = bool(floats) if shape == "argument" else len(floats) == len(rows)
    return PlannedCheck(check=ct.check, target=ct.target, kind=macro(kind.name), shape=shape, text=ct.text,
                        args=floats) if reads else None


def _planned(spec: Spec, check_rows: tuple[CheckRow, ...], targets: _Targets, pairs: list[CheckTarget],
             first_ct: list[int]) -> dict[int, list[PlannedCheck]]:
    """Per layout (index), the (check, target) pairs whose kernel runs on its records."""
    planned: dict[int, list[PlannedCheck]] = {}
    first_arg = 0
    for li, (ci, lay) in enumerate(_flat_layouts(spec)):
        for ct in pairs[first_ct[ci]:first_ct[ci + 1]]:
            got = _planned_pair(lay, li, first_arg, ct, check_rows[ct.check], targets)
            if got is not None:
                planned.setdefault(li, []).append(got)
        first_arg += len(lay.args)
    return planned


def _candidates(spec: Spec, c: Command, first: int) -> list[list[int]]:
    """Decode candidates per version: the version's own layouts in spec order, else every layout,
    newest first (PROTOCOL.md)."""
    vorder = {v.id: i for i, v in enumerate(spec.versions)}
    newest_first = sorted(range(len(c.layouts)), key=lambda i: -max(vorder[x] for x in c.layouts[i].versions))
    return [[first + i for i, lay in enumerate(c.layouts) if v.id in lay.versions] or [first + i for i in newest_first]
            for v in spec.versions]


def _role_macro(prefix: str, role: dict[str, str] | None) -> str:
    """The enum constant of a role's kind (``prefix`` ends in "_": the orientation role's prefix is
    not the word of the command of that name, which no emitter may spell)."""
    return prefix + (macro(role["kind"]) if role else "NONE")


def _command_row(spec: Spec, ci: int, layouts: list[LayoutRow], first: int, cands: list[list[int]],
                 max_layouts: int, first_ct: list[int]) -> CommandRow:
    c = spec.commands[ci]
    mine = tuple(lay for lay in layouts if lay.command == ci)
    return CommandRow(
        index=ci, name=c.name, macro=macro(c.name), code=c.code, doc=c.doc, clause=c.clause,
        first=first, nlayouts=len(c.layouts),
        cands=tuple(tuple(row + [-1] * (max_layouts - len(row))) for row in cands),
        motion=_role_macro("MOTION_", c.motion), orient=_role_macro("ORIENT_", c.orientation),
        shape=_role_macro("SHAPE_", c.shape), cutter=int(bool(c.cutter)), vmask=_vmask(c.versions), layouts=mine,
        per_version=tuple(VersionLayouts(macro=macro(v.id), layouts=tuple(x for x in mine if v.id in x.versions))
                          for v in spec.versions),
        first_ct=first_ct[ci], n_ct=first_ct[ci + 1] - first_ct[ci],
        former=tuple(macro(n) for n in c.former_names))


def _deprecated_by_layout(spec: Spec) -> tuple[int, ...]:
    """Per layout, the deprecation check that names it (-1: none)."""
    def check_of(c: Command, lay: Layout) -> int:
        return next((i for i, ch in enumerate(spec.checks)
                     if ch.kind == "deprecated" and ch.deprecates_layout(c.name, lay.variant)), -1)

    return tuple(check_of(c, lay) for c in spec.commands for lay in c.layouts) or (-1,)


def _commands(spec: Spec, planned: dict[int, list[PlannedCheck]], first_ct: list[int]) -> Commands:
    profiles = [p.id for p in spec.profiles]
    layouts: list[LayoutRow] = []
    firsts: list[int] = []
    cands_all: list[list[list[int]]] = []
    for ci, c in enumerate(spec.commands):
        firsts.append(len(layouts))
        cands_all.append(_candidates(spec, c, len(layouts)))
        layouts.extend(_layout_rows(spec, c, ci, len(layouts), sum(len(x.args) for x in layouts), profiles, planned))
    max_layouts = max((len(row) for cands in cands_all for row in cands), default=0)
    commands = [_command_row(spec, ci, layouts, firsts[ci], cands_all[ci], max_layouts, first_ct)
                for ci in range(len(spec.commands))]
    code_of = {c.code: c for c in commands}
    return Commands(
        commands=tuple(commands), sorted_commands=tuple(sorted(commands, key=lambda c: c.code)),
        index_by_code=tuple(code_of[k].index if k in code_of else -1 for k in range(256)),
        names_by_code=tuple(code_of[k].name if k in code_of else None for k in range(256)),
        layouts=tuple(layouts), arg_rows=tuple(a for lay in layouts for a in lay.args), max_layouts=max_layouts,
        max_arg=max([lay.max_size for lay in layouts] + [0]))


def _commands_and_checks(spec: Spec) -> tuple[Commands, Checks]:
    """The commands with their layouts, and the checks with their targets: each layout's plan
    reads the (check, target) pairs of its command, so both are built here."""
    check_rows, rows = _checks(spec)
    targets = _target_table(spec, rows)
    pairs, first_ct = _by_command(spec, check_rows, targets)
    cmds = _commands(spec, _planned(spec, check_rows, targets, pairs, first_ct), first_ct)
    target_rows = tuple(TargetRow(command=t[0], first=targets.first[k], n=len(t[3]), text=t[2])
                        for k, t in enumerate(rows))
    checks = Checks(checks=check_rows, targets=target_rows or (TargetRow(command=-1, first=0, n=0, text="none"),),
                    ntargets=len(rows), tnames=targets.names or ("",),
                    tindex=targets.index or (tuple([-1] * len(cmds.layouts)),),
                    deprecated=_deprecated_by_layout(spec))
    return cmds, checks


def _checksums(spec: Spec) -> Checksums:
    cov_names = list(spec.checksums.coverages)
    rec_names = [f.name for f in spec.record.fields]
    segments: list[SegmentRow] = []
    coverages: list[CoverageRow] = []
    for name, cov in spec.checksums.coverages.items():
        coverages.append(CoverageRow(name=name, first=len(segments), n=len(cov.segments), doc=cov.doc))
        segments.extend(SegmentRow(region="REGION_" + macro(s.region), start=s.start or 0,
                                   end=-1 if s.end is None else s.end,
                                   exclude=tuple(rec_names.index(x) for x in s.exclude))
                        for s in cov.segments)
    ckfields: list[CkFieldRow] = []
    check_index = {ch.id: i for i, ch in enumerate(spec.checks)}
    for tag in _tags(spec):
        cf = spec.checksums.for_field(tag)
        kind = spec.checksums.algorithms[cf.algorithm].kind
        if kind not in ALGORITHMS:
            raise ValueError(f"C binding: checksum algorithm kind {kind!r} is not supported")
        judge = spec.checksum_check(tag)
        ckfields.append(CkFieldRow(tag=tag, alg="ALG_" + macro(kind), coverage=cov_names.index(cf.coverage),
                                   check=-1 if judge is None else check_index[judge.id]))
    argcks, ranges = _arg_checksum_rows(spec)
    return Checksums(segments=tuple(segments), coverages=tuple(coverages), ckfields=tuple(ckfields),
                     fill=tuple("CK_" + macro(t) for t in spec.checksums.fill_order), argcks=argcks, ranges=ranges)


def _arg_checksum_rows(spec: Spec) -> tuple[tuple[ArgCkRow, ...], tuple[tuple[int, int], ...]]:
    """Each layout's checksum fields among its arguments, in fill order, and their record ranges."""
    tags = list(_tags(spec))
    order = list(spec.checksums.fill_order)
    rows: list[ArgCkRow] = []
    ranges: list[tuple[int, int]] = []
    flat = [(c, lay) for c in spec.commands for lay in c.layouts]
    for li, (c, lay) in enumerate(flat):
        for ck in sorted(lay.checksums, key=lambda k: order.index(k.tag)):
            rows.append(ArgCkRow(layout=li, ckfield=tags.index(ck.tag), offset=ck.field.offset,
                                 elem=ck.field.size, first=len(ranges), n=len(ck.ranges),
                                 what=f"{c.name} {ck.field.name}: {ck.tag} over {', '.join(ck.covers)}"))
            ranges.extend(ck.ranges)
    return tuple(rows), tuple(ranges)


def _profiles(spec: Spec) -> Profiles:
    cov_names = list(spec.checksums.coverages)

    def alg(profile: str) -> str:
        return "CBF__ALG_" + macro(spec.checksums.algorithms[spec.file_algorithm(profile)].kind)

    width = max([len(p.file_coverages) for p in spec.profiles] + [len(p.hint_coverages) for p in spec.profiles] + [1])
    rows: list[ProfileRow] = []
    for p in spec.profiles:
        # a hint coverage is computed with the algorithm of the profile that accepts it
        owners = [next((q for q in spec.profiles if x in q.file_coverages), p) for x in p.hint_coverages]
        owner_ix = tuple(next((k for k, q in enumerate(spec.profiles) if x in q.file_coverages), -1)
                         for x in p.hint_coverages)
        file = tuple(cov_names.index(x) for x in p.file_coverages)
        hint = tuple(cov_names.index(x) for x in p.hint_coverages)
        hint_alg = tuple(alg(q.id) for q in owners)
        rows.append(ProfileRow(id=p.id, macro=macro(p.id), doc=p.doc, file=file, hint=hint,
                               file_alg=alg(p.id), hint_alg=hint_alg, file_pad=file + (-1,) * (width - len(file)),
                               hint_pad=hint + (-1,) * (width - len(hint)),
                               hint_alg_pad=hint_alg + ("CBF__ALG_NONE",) * (width - len(hint_alg)),
                               hint_owner_pad=owner_ix + (-1,) * (width - len(owner_ix))))
    # per command and version: the index of the one availability check covering a command the
    # version lacks (the loader guarantees one), -1 when it has it
    check_index = {ch.id: i for i, ch in enumerate(spec.checks)}
    avail = tuple(AvailRow(name=c.name, row=tuple(
        check_index[a.id] if (a := spec.availability_check(c.name, v.id)) is not None else -1 for v in spec.versions))
        for c in spec.commands)
    return Profiles(profiles=tuple(rows), max_cov=width, avail_rows=avail)


def _constants(spec: Spec) -> Constants:
    return Constants(tolerances=tuple(Constant(macro=macro(k), value=cfloat(v), name=k)
                                      for k, v in spec.tolerances.items()),
                     limits=tuple(Constant(macro=macro(k), value=v, name=k) for k, v in spec.limits.items()))


def _unique_names(cmds: Commands, versions: Versions, checks: Checks, profiles: Profiles) -> None:
    groups = {"command": [c.macro for c in cmds.commands], "layout": [lay.macro for lay in cmds.layouts],
              "version": [v.macro for v in versions.versions], "check": [c.macro for c in checks.checks],
              "profile": [p.macro for p in profiles.profiles]}
    for what, names in groups.items():
        dup = sorted({n for n in names if names.count(n) > 1})
        if dup:
            raise ValueError(f"C binding: two {what}s map to the same C name {dup[0]}")


def context(spec: Spec) -> CContext:
    cmds, checks = _commands_and_checks(spec)
    versions, profiles = _versions(spec), _profiles(spec)
    _unique_names(cmds, versions, checks, profiles)
    return CContext(about=_about(spec), vocabulary=_vocabulary(spec), framing=_framing(spec), versions=versions,
                    commands=cmds, checksums=_checksums(spec), profiles=profiles, checks=checks,
                    constants=_constants(spec), machine=machine_view(spec, cmds.layouts))
