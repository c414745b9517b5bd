"""The typed model of spec/cbf.yaml.

Every emitter reads the format from these frozen dataclasses and from
nothing else. The loader (the package loader/) builds them and refuses a spec that
contradicts itself. `line` attributes point back into the YAML.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field, replace
from typing import Any

from .registry import ALGORITHMS, CHECK_KINDS, TYPES, FieldType, Params, Target

__all__ = ["FieldType", "PrimitiveType", "Target"]


def camel(name: str) -> str:
    """LINE5B -> Line5b, CUTTER_ON -> CutterOn, v1 -> V1."""
    return "".join(part[:1].upper() + part[1:].lower() for part in re.split(r"[_\W]+", name) if part)


def ident(name: str) -> str:
    """A lower_snake identifier for any spec id ("6.4.4" -> "c6_4_4", "1.x" -> "v1_x")."""
    s = re.sub(r"\W+", "_", name).strip("_").lower()
    return s if s and not s[0].isdigit() else "c" + s


# A type of the spec's `types:`: the registry's entry (registry.TYPES) of that name.
PrimitiveType = FieldType


@dataclass(frozen=True)
class Field:
    """A header field, a record-head field or a command argument."""

    name: str
    type: str
    kind: str  # registry.FIELD_KINDS: uint | sint | float | string | bytes
    offset: int
    elem_size: int
    count: int
    doc: str
    line: int
    clause: str | None = None
    unit: str | None = None
    role: str | None = None
    magic: int | None = None
    checksum: str | None = None
    reserved: bool = False
    text: bool = False
    # A repeated argument group (issue 25, point 3): (min n, max n) when this, the last argument of a
    # command layout, stands n times after the fixed arguments (nb = Layout.size + n * size).
    repeat: tuple[int, int] | None = None

    @property
    def size(self) -> int:
        return self.elem_size * self.count

    @property
    def end(self) -> int:
        return self.offset + self.size

    @property
    def is_vector(self) -> bool:
        return self.kind == "float" and self.count > 1

    @property
    def ftype(self) -> FieldType:
        """The field's type, from the registry (struct code, numpy, Kaitai and C types)."""
        return TYPES[self.type]


@dataclass(frozen=True)
class ArgChecksum:
    """A checksum field among a command layout's arguments (issue 25, point 1): the argument that
    stores it, its tag (a key of checksums.fields), its algorithm, and the byte ranges of the record
    (offsets from the record's first byte: the head, then the arguments) its named-field coverage
    resolves to in this layout, fed in order."""

    tag: str
    field: Field  # the argument (offset within the arguments)
    algorithm: str
    covers: tuple[str, ...]  # the named fields, in order
    ranges: tuple[tuple[int, int], ...]  # (start, end) from the record's first byte


@dataclass(frozen=True)
class Layout:
    command: str
    variant: str  # "" for the primary layout
    versions: tuple[str, ...]
    size: int
    args: tuple[Field, ...]
    profiles: tuple[str, ...]  # empty: accepted under every profile
    doc: str
    clause: str | None
    line: int
    # Checksum fields among the arguments (issue 25, point 1), each resolved to the bytes it covers.
    checksums: tuple[ArgChecksum, ...] = ()

    @property
    def class_name(self) -> str:
        return camel(self.command) + camel(self.variant)

    def arg(self, name: str) -> Field | None:
        for a in self.args:
            if a.name == name:
                return a
        return None

    def accepted_under(self, profile: str) -> bool:
        return not self.profiles or profile in self.profiles

    # -- repeated argument groups (issue 25, point 3): `size` is then the fixed arguments' size --
    @property
    def repeated(self) -> Field | None:
        """The repeated group (the last argument, when it has `repeat`), else None."""
        return self.args[-1] if self.args and self.args[-1].repeat is not None else None

    @property
    def fixed_args(self) -> tuple[Field, ...]:
        return self.args[:-1] if self.repeated is not None else self.args

    @property
    def sizes(self) -> tuple[int, ...]:
        """Every nb this layout takes: its size, or size + k*n for each n of the group."""
        rep = self.repeated
        if rep is None or rep.repeat is None:
            return (self.size,)
        return tuple(self.size + rep.size * n for n in range(rep.repeat[0], rep.repeat[1] + 1))

    def count_for(self, nb: int) -> int | None:
        """n for an nb this layout takes (1 for a fixed layout of that size), else None."""
        rep = self.repeated
        if rep is None or rep.repeat is None:
            return 1 if nb == self.size else None
        n, extra = divmod(nb - self.size, rep.size)
        return n if nb >= self.size and not extra and rep.repeat[0] <= n <= rep.repeat[1] else None

    def sized(self, nb: int) -> Layout | None:
        """This layout as it stands in a record of nb argument bytes, else None: a repeated group
        spelled out as its n items, fields named ``name[i]`` one after another (what a hex dump or
        a CUT line shows item by item)."""
        n = self.count_for(nb)
        rep = self.repeated
        if n is None or rep is None:
            return self if n is not None else None
        items = tuple(replace(rep, name=f"{rep.name}[{i}]", offset=rep.offset + i * rep.size, repeat=None)
                      for i in range(n))
        return replace(self, size=nb, args=(*self.fixed_args, *items))


@dataclass(frozen=True)
class Command:
    name: str
    code: int
    doc: str
    clause: str
    layouts: tuple[Layout, ...]
    line: int
    motion: dict[str, str] | None = None
    orientation: dict[str, str] | None = None
    shape: dict[str, str] | None = None
    cutter: dict[str, str] | None = None
    # M2: machine state set by the command: state -> argument name, or a constant (bool).
    sets: dict[str, str | bool] | None = None
    progress: str | None = None
    declared_size: int | None = None
    listed_size: int | None = None
    erratum: str | None = None
    # Issue 25, point 6: names the command had before a rename. Readers of CUT and JSON accept
    # them, writers write ``name``; the C header and the Python package keep them as aliases.
    former_names: tuple[str, ...] = ()

    @property
    def primary(self) -> Layout:
        return self.layouts[0]

    @property
    def class_name(self) -> str:
        return camel(self.name)

    @property
    def versions(self) -> tuple[str, ...]:
        seen: list[str] = []
        for lay in self.layouts:
            for v in lay.versions:
                if v not in seen:
                    seen.append(v)
        return tuple(seen)

    def layouts_for(self, version: str) -> tuple[Layout, ...]:
        return tuple(lay for lay in self.layouts if version in lay.versions)

    def available_in(self, version: str) -> bool:
        return bool(self.layouts_for(version))


@dataclass(frozen=True)
class Version:
    id: str
    major: int
    minor: int | None
    header: str
    clause: str
    writable: bool
    doc: str
    line: int
    since: str | None = None

    def matches(self, major: int, minor: int) -> bool:
        return major == self.major and (self.minor is None or minor == self.minor)


@dataclass(frozen=True)
class HeaderLayout:
    id: str
    size: int
    clause: str
    doc: str
    fields: tuple[Field, ...]
    line: int

    def by_role(self, role: str) -> Field | None:
        for f in self.fields:
            if f.role == role:
                return f
        return None

    def field(self, name: str) -> Field | None:
        for f in self.fields:
            if f.name == name:
                return f
        return None


def common_header_prefix(headers: tuple[HeaderLayout, ...]) -> tuple[Field, ...]:
    """The fields every header layout shares from offset 0, in order (same name, offset, type,
    size and magic): what a reader knows before it knows the version (the .ksy's header type)."""
    if not headers:
        return ()
    out: list[Field] = []
    for f in headers[0].fields:
        key = (f.name, f.offset, f.type, f.size, f.magic)
        twins = [h.field(f.name) for h in headers]
        if all(t is not None and (t.name, t.offset, t.type, t.size, t.magic) == key for t in twins):
            out.append(f)
        else:
            break
    return tuple(out)


@dataclass(frozen=True)
class RecordLayout:
    head_size: int
    clause: str
    doc: str
    fields: tuple[Field, ...]

    def by_role(self, role: str) -> Field:
        for f in self.fields:
            if f.role == role:
                return f
        raise KeyError(role)


@dataclass(frozen=True)
class Segment:
    """A part of a coverage. ``fields``: named fields (issue 25, point 1). In a header checksum's
    coverage the loader resolves them to one header segment a field (``fields`` keeps its name);
    in a record checksum's coverage the region stays ``fields`` and each layout that carries the
    checksum holds its own byte ranges (Layout.checksums)."""

    region: str  # file | header | records | args | fields
    start: int | None = None
    end: int | None = None
    exclude: tuple[str, ...] = ()
    fields: tuple[str, ...] = ()


@dataclass(frozen=True)
class Coverage:
    name: str
    doc: str
    segments: tuple[Segment, ...]


@dataclass(frozen=True)
class Algorithm:
    name: str
    kind: str  # a key of registry.ALGORITHMS (its parameters and check value)
    doc: str

    @property
    def is_sum(self) -> bool:
        return ALGORITHMS[self.kind].family == "sum"

    @property
    def bits(self) -> int | None:
        """Width of the result; None for a sum (it takes its field's width)."""
        return ALGORITHMS[self.kind].width


@dataclass(frozen=True)
class ChecksumField:
    field: str  # args | header | file (the `checksum:` tag of a layout field)
    algorithm: str
    coverage: str
    clause: str


@dataclass(frozen=True)
class Checksums:
    algorithms: dict[str, Algorithm]
    coverages: dict[str, Coverage]
    fields: tuple[ChecksumField, ...]
    fill_order: tuple[str, ...]

    def for_field(self, name: str) -> ChecksumField:
        for f in self.fields:
            if f.field == name:
                return f
        raise KeyError(name)


@dataclass(frozen=True)
class Profile:
    id: str
    doc: str
    file_coverages: tuple[str, ...]
    hint_coverages: tuple[str, ...]
    file_algorithm: str | None = None  # None: the file checksum field's own algorithm


@dataclass(frozen=True)
class MachineLimit:
    """One limit of a machine (decision L1): a range, or with ``axes`` a box (per component)."""

    name: str
    unit: str
    min: tuple[float, ...]
    max: tuple[float, ...]
    axes: tuple[str, ...]  # empty for a scalar range
    doc: str

    @property
    def is_vector(self) -> bool:
        return bool(self.axes)


# The keys of a machine file (cbf validate --machine FILE), in the order their messages list them:
# the file's own, then a limit's. Both emitters (the Python schema, the C reader) read these.
MACHINE_FILE_KEYS = ("name", "doc", "decision", "limits")
MACHINE_LIMIT_KEYS = ("unit", "min", "max", "doc", "axes")


@dataclass(frozen=True)
class Machine:
    """The default machine of check kind machine_limits; a machine file has the same limits."""

    decision: str
    doc: str
    limits: tuple[MachineLimit, ...]

    def limit(self, name: str) -> MachineLimit:
        for lim in self.limits:
            if lim.name == name:
                return lim
        raise KeyError(name)


@dataclass(frozen=True)
class Check:
    """A check of the spec: its kind (registry.CHECK_KINDS) and that kind's typed parameters.
    The parameter properties below read ``params`` (None / empty where the kind takes none)."""

    id: str
    kind: str
    severity: str
    text: str
    fails: str
    line: int
    params: Params
    clause: str | None = None
    decision: str | None = None

    def _param(self, name: str, default: Any) -> Any:
        return getattr(self.params, name, default)

    @property
    def input(self) -> str | None:
        return self._param("input", None)  # type: ignore[no-any-return]

    @property
    def input_severity(self) -> str | None:
        """The severity when the input is given (machine_limits: a machine file)."""
        return self._param("input_severity", None)  # type: ignore[no-any-return]

    @property
    def versions(self) -> tuple[str, ...]:
        """The versions whose files the check judges (empty: every version); availability: the
        versions it covers."""
        return self._param("versions", ())  # type: ignore[no-any-return]

    @property
    def commands(self) -> tuple[str, ...]:
        """availability: the commands it covers in its versions."""
        return self._param("commands", ())  # type: ignore[no-any-return]

    @property
    def targets(self) -> tuple[Target, ...]:
        return self._param("targets", ())  # type: ignore[no-any-return]

    @property
    def min(self) -> float | None:
        return self._param("min", None)  # type: ignore[no-any-return]

    @property
    def max(self) -> float | None:
        return self._param("max", None)  # type: ignore[no-any-return]

    @property
    def min_exclusive(self) -> bool:
        """range: the value must be > min (not >=)."""
        return bool(self._param("min_exclusive", False))

    @property
    def max_exclusive(self) -> bool:
        """range: the value must be < max (not <=)."""
        return bool(self._param("max_exclusive", False))

    @property
    def since(self) -> str | None:
        """deprecated: the first version that deprecates its commands or layouts."""
        return self._param("since", None)  # type: ignore[no-any-return]

    @property
    def deprecates(self) -> tuple[str, ...]:
        """deprecated: the commands ("NAME") and layouts ("NAME/variant") it deprecates."""
        return self._param("deprecates", ())  # type: ignore[no-any-return]

    def deprecates_layout(self, command: str, variant: str) -> bool:
        return command in self.deprecates or f"{command}/{variant}" in self.deprecates

    def applies_to(self, version: str) -> bool:
        """Whether the check judges a file of ``version`` (its ``versions:`` scope)."""
        return not self.versions or version in self.versions

    @property
    def checksum_field(self) -> str | None:
        """header_checksum: the checksum tag of the header field it judges; arg_checksum: the tag of
        the record checksum field it judges (``args``, the head's, or an argument's)."""
        return self._param("field", None)  # type: ignore[no-any-return]

    @property
    def anchor(self) -> str:
        return "check-" + ident(self.id).replace("_", "-")


# A check's attributes as one flat list: its own, then its kind's parameters (registry.py).
CHECK_ATTRS = ("id", "kind", "severity", "text", "fails", "line", "clause", "decision", "input", "input_severity",
               "versions", "commands", "targets", "min", "max", "min_exclusive", "max_exclusive",
               "since", "deprecates", "checksum_field")


@dataclass(frozen=True)
class Note:
    """A decision, an erratum or a change-history entry."""

    id: str
    topic: str
    text: str
    evidence: str = ""
    clause: str | None = None
    date: str | None = None


@dataclass(frozen=True)
class Spec:
    path: str
    meta: dict[str, Any]
    types: dict[str, PrimitiveType]
    units: dict[str, str]
    versions: tuple[Version, ...]
    default_version: str
    fallback_version: str
    headers: dict[str, HeaderLayout]
    record: RecordLayout
    commands: tuple[Command, ...]
    checksums: Checksums
    profiles: tuple[Profile, ...]
    tolerances: dict[str, float]
    limits: dict[str, int]
    machine: Machine
    checks: tuple[Check, ...]
    cut: dict[str, Any]
    decisions: tuple[Note, ...]
    errata: tuple[Note, ...]
    history: tuple[Note, ...]
    raw: dict[str, Any] = field(repr=False, compare=False, default_factory=dict)

    # -- look-ups used by every emitter -------------------------------------
    @property
    def revision(self) -> str:
        """The spec's own revision, as every binding names it: "300071 rev 03"."""
        return f"{self.meta['part_number']} rev {self.meta['revision']}"

    def command(self, name: str) -> Command:
        for c in self.commands:
            if c.name == name:
                return c
        raise KeyError(name)

    def version(self, vid: str) -> Version:
        for v in self.versions:
            if v.id == vid:
                return v
        raise KeyError(vid)

    def check(self, cid: str) -> Check:
        for c in self.checks:
            if c.id == cid:
                return c
        raise KeyError(cid)

    def checks_of_kind(self, kind: str) -> tuple[Check, ...]:
        return tuple(c for c in self.checks if c.kind == kind)

    def availability_check(self, command: str, version: str) -> Check | None:
        """The one availability check that covers a command missing from a version (the loader
        guarantees exactly one); None when the version has the command."""
        for c in self.checks:
            if CHECK_KINDS[c.kind].gates and version in c.versions and command in c.commands:
                return c
        return None

    def file_algorithm(self, profile: str) -> str:
        """The algorithm of the file checksum under a profile."""
        for p in self.profiles:
            if p.id == profile and p.file_algorithm:
                return p.file_algorithm
        return self.checksums.for_field("file").algorithm

    def header_for(self, vid: str) -> HeaderLayout:
        return self.headers[self.version(vid).header]

    @property
    def header_size(self) -> int:
        return next(iter(self.headers.values())).size

    def common_header_field(self, role: str) -> Field:
        """A field with the same place in every header layout (magic, checksums, version, count)."""
        f = next(iter(self.headers.values())).by_role(role)
        if f is None:
            raise KeyError(role)
        return f

    def header_checksum_tags(self, hid: str) -> dict[str, Field]:
        """A header layout's checksum fields by tag (a new version's header may add its own)."""
        return {f.checksum: f for f in self.headers[hid].fields if f.checksum}

    def checksum_versions(self, tag: str) -> tuple[str, ...]:
        """The versions that carry the checksum field ``tag``: every one for the record head's, the
        versions of the layouts that carry it for an argument's, else those whose header holds it."""
        if any(f.checksum == tag for f in self.record.fields):
            return tuple(v.id for v in self.versions)
        lays = self.checksum_layouts(tag)
        if lays:
            return tuple(v.id for v in self.versions if any(v.id in lay.versions for _, lay, _ in lays))
        return tuple(v.id for v in self.versions if tag in self.header_checksum_tags(v.header))

    def checksum_check(self, tag: str) -> Check | None:
        """The check that judges the checksum field ``tag``: a header_checksum check for a header
        field, an arg_checksum check for a field among command arguments; None for the file and the
        record head's checksums (judged by their own kinds)."""
        kind = "arg_checksum" if tag in self.record_checksum_tags() else "header_checksum"
        return next((c for c in self.checks if c.kind == kind and c.checksum_field == tag), None)

    def record_checksum_tags(self) -> tuple[str, ...]:
        """The tags of the checksum fields among command arguments (issue 25, point 1)."""
        seen: list[str] = []
        for c in self.commands:
            for lay in c.layouts:
                for ck in lay.checksums:
                    if ck.tag not in seen:
                        seen.append(ck.tag)
        return tuple(seen)

    def checksum_layouts(self, tag: str) -> tuple[tuple[Command, Layout, ArgChecksum], ...]:
        """Every command layout that carries the argument checksum field ``tag``."""
        return tuple((c, lay, ck) for c in self.commands for lay in c.layouts for ck in lay.checksums
                     if ck.tag == tag)

    def header_checksum_field(self, tag: str) -> Field:
        for f in next(iter(self.headers.values())).fields:
            if f.checksum == tag:
                return f
        raise KeyError(tag)

    @property
    def writable_versions(self) -> tuple[Version, ...]:
        return tuple(v for v in self.versions if v.writable)

    @property
    def sorted_commands(self) -> tuple[Command, ...]:
        return tuple(sorted(self.commands, key=lambda c: c.code))
