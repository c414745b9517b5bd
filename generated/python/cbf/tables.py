"""Runtime tables built once, at import, from the generated spec data.

Nothing here knows a command, field or check by name: it reads the roles,
kinds and layouts of ``_spec_data.SPEC``.
"""

from __future__ import annotations

import json
import struct
from dataclasses import dataclass, replace
from functools import cache
from importlib import import_module
from pathlib import Path
from struct import Struct
from typing import Any

# The spec as data, generated from spec/cbf.yaml beside this module.
SPEC: dict[str, Any] = json.loads(Path(__file__).with_name("spec_data.json").read_text(encoding="utf-8"))


@cache  # LayoutInfo.cls is asked once per decoded record: look each class up once
def _layouts_class(registry: str, key: Any) -> type:
    """A generated dataclass of cbf.layouts, imported on first use (keeps start-up fast)."""
    table: dict[Any, type] = getattr(import_module(f"{__package__}.layouts"), registry)
    return table[key]

BO = "<" if SPEC["byte_order"] == "little" else ">"
PAD = bytes([SPEC["string_padding"]])


@dataclass(frozen=True, slots=True)
class FieldInfo:
    name: str
    kind: str
    offset: int
    elem_size: int
    count: int
    role: str | None
    magic: int | None
    checksum: str | None
    reserved: bool
    text: bool
    code: str | None = None  # struct code of one element (the spec's type, cbfgen/registry.py); None: str, bytes
    bits_code: str | None = None  # struct code of an element's bit pattern (a float as the unsigned of its width)
    numpy: str | None = None  # numpy dtype code without byte order ("u2", "f4"); None: str, bytes
    lo: int | None = None  # an integer's least and greatest value (unsigned or two's complement)
    hi: int | None = None
    # A repeated argument group (issue 25, point 3): (min n, max n) in the spec's layout; in a layout
    # made for one n (LayoutInfo.n), count is n * per, the elements of n items of `per` elements.
    repeat: tuple[int, int] | None = None
    per: int = 0

    @property
    def items(self) -> int:
        """How many items a repeated field holds in its layout (count // per); 1 when not repeated."""
        return self.count // self.per if self.per else 1

    @property
    def is_int(self) -> bool:
        return self.lo is not None

    @property
    def int_name(self) -> str:
        """"an unsigned 16-bit integer", "a signed 8-bit integer" (for messages)."""
        return f"{'an unsigned' if self.kind == 'uint' else 'a signed'} {8 * self.elem_size}-bit integer"

    def holds(self, value: int) -> bool:
        return self.lo is not None and self.hi is not None and self.lo <= value <= self.hi

    @property
    def size(self) -> int:
        return self.elem_size * self.count

    @property
    def end(self) -> int:
        return self.offset + self.size

    @property
    def fmt(self) -> str:
        if self.code is None:
            return f"{self.size}s"
        return f"{self.count}{self.code}" if self.count > 1 else self.code

    @property
    def bits_fmt(self) -> str:
        if self.bits_code is None:
            return self.fmt
        return f"{self.count}{self.bits_code}" if self.count > 1 else self.bits_code


def _field(d: dict[str, Any]) -> FieldInfo:
    rep = d.get("repeat")
    return FieldInfo(d["name"], d["kind"], d["offset"], d["elem_size"], d["count"], d["role"], d["magic"],
                     d["checksum"], d["reserved"], d["text"], d["code"], d["bits_code"], d["numpy"], d["min"], d["max"],
                     (rep[0], rep[1]) if rep else None)


def _for_n(f: FieldInfo, n: int) -> FieldInfo:
    """A repeated field as it stands in the layout made for n items."""
    return replace(f, count=f.count * n, per=f.count)


def _struct(fields: tuple[FieldInfo, ...], bits: bool = False) -> struct.Struct:
    return struct.Struct(BO + "".join(f.bits_fmt if bits else f.fmt for f in fields))


@dataclass(frozen=True, slots=True)
class ArgChecksumInfo:
    """A checksum field among a layout's arguments (issue 25, point 1): its tag, the argument that
    stores it, its algorithm (a key of checksums.algorithms), and the byte ranges of the record
    (from its first byte: head, then arguments) it covers, fed in order."""

    tag: str
    arg: FieldInfo
    algorithm: str
    ranges: tuple[tuple[int, int], ...]


@dataclass(frozen=True, slots=True)
class LayoutInfo:
    command: str
    code: int
    variant: str
    versions: frozenset[str]
    size: int
    profiles: frozenset[str]
    args: tuple[FieldInfo, ...]
    struct: Struct
    bits: Struct
    # A layout with a repeated group is made once per n it takes (nb = fixed + k*n): n, else None.
    n: int | None = None
    checksums: tuple[ArgChecksumInfo, ...] = ()  # in the spec's fill order

    @property
    def repeated(self) -> FieldInfo | None:
        return self.args[-1] if self.n is not None else None

    def accepted_under(self, profile: str) -> bool:
        return not self.profiles or profile in self.profiles

    @property
    def cls(self) -> type:
        return _layouts_class("ARGS_CLASSES", (self.command, self.variant))


@dataclass(frozen=True, slots=True)
class CommandInfo:
    name: str
    code: int
    layouts: tuple[LayoutInfo, ...]
    motion: dict[str, str] | None
    orientation: dict[str, str] | None
    shape: dict[str, str] | None
    cutter: dict[str, str] | None
    progress: str | None
    by_version: dict[str, tuple[LayoutInfo, ...]]
    # M2: the machine state the command sets: state -> argument name, or a constant.
    sets: dict[str, str | bool] | None = None

    def __repr__(self) -> str:
        """Short: a list of records' commands prints one word each, not every layout of each."""
        return f"<command {self.name} 0x{self.code:02X}>"

    def layouts_for(self, version: str) -> tuple[LayoutInfo, ...]:
        return self.by_version.get(version, ())

    def candidates(self, version: str) -> tuple[LayoutInfo, ...]:
        """Layouts to decode with: the version's own, else all, newest first (PROTOCOL.md)."""
        own = self.layouts_for(version)
        return own if own else self.layouts

    def layout_for_size(self, version: str, size: int) -> LayoutInfo | None:
        for lay in self.candidates(version):
            if lay.size == size:
                return lay
        return None


@dataclass(frozen=True, slots=True)
class HeaderInfo:
    id: str
    size: int
    fields: tuple[FieldInfo, ...]
    struct: Struct

    @property
    def cls(self) -> type:
        return _layouts_class("HEADER_CLASSES", self.id)

    def by_role(self, role: str) -> FieldInfo | None:
        for f in self.fields:
            if f.role == role:
                return f
        return None


@dataclass(frozen=True, slots=True)
class VersionInfo:
    id: str
    major: int
    minor: int | None
    header: str
    writable: bool


VERSIONS: tuple[VersionInfo, ...] = tuple(
    VersionInfo(v["id"], v["major"], v["minor"], v["header"], v["writable"]) for v in SPEC["versions"]
)
VERSION_BY_ID = {v.id: v for v in VERSIONS}
DEFAULT_VERSION: str = SPEC["default_version"]
FALLBACK_VERSION: str = SPEC["fallback_version"]


def version_id(major: int, minor: int) -> str | None:
    for v in VERSIONS:
        if v.major == major and (v.minor is None or v.minor == minor):
            return v.id
    return None


def parse_version(text: str) -> tuple[int, int]:
    """"3.0" -> (3, 0); the id of a version with a fixed minor, or major.minor."""
    v = VERSION_BY_ID.get(text)
    if v is not None and v.minor is not None:
        return v.major, v.minor
    major, _, minor = text.partition(".")
    return int(major), int(minor or "0")


HEADERS: dict[str, HeaderInfo] = {}
for _hid, _h in SPEC["headers"].items():
    _fields = tuple(_field(f) for f in _h["fields"])
    HEADERS[_hid] = HeaderInfo(_hid, _h["size"], _fields, _struct(_fields))
HEADER_SIZE: int = next(iter(HEADERS.values())).size
_H0 = next(iter(HEADERS.values()))


def _common(role: str) -> FieldInfo:
    f = _H0.by_role(role)
    assert f is not None, role
    return f


START = _common("start_pattern")
END = _common("end_pattern")
VMAJOR = _common("version_major")
VMINOR = _common("version_minor")
COUNT = _common("command_count")
# The header roles whose values the writer derives (patterns, checksums, count, version): a model,
# a CUT file or a diff never sets or compares them field by field. The generator's list
# (registry.DERIVED_HEADER_ROLES), as spec_data.json carries it: no second copy here.
DERIVED_ROLES: frozenset[str] = frozenset(SPEC["derived_roles"])
HEADER_CHECKSUM_FIELDS = {f.checksum: f for f in _H0.fields if f.checksum}
# Each header layout's checksum fields by tag: a new version's header may carry its own.
LAYOUT_CHECKSUM_FIELDS: dict[str, dict[str, FieldInfo]] = {
    hid: {f.checksum: f for f in h.fields if f.checksum} for hid, h in HEADERS.items()}

RECORD_FIELDS = tuple(_field(f) for f in SPEC["record"]["fields"])
HEAD_SIZE: int = SPEC["record"]["head_size"]
HEAD_STRUCT = _struct(RECORD_FIELDS)
ROLE_INDEX = {f.role: i for i, f in enumerate(RECORD_FIELDS)}
RECORD_BY_ROLE = {f.role: f for f in RECORD_FIELDS}
ARG_SIZE_OFFSET = RECORD_BY_ROLE["arg_size"].offset
ARG_CHECKSUM = next(f for f in RECORD_FIELDS if f.checksum)
# The head tuple's positions, by role.
I_SEQ = ROLE_INDEX["sequence"]
I_CODE = ROLE_INDEX["code"]
I_COPY = ROLE_INDEX["code_copy"]
I_SIZE = ROLE_INDEX["arg_size"]
I_RES = ROLE_INDEX["reserved"]
I_CHK = RECORD_FIELDS.index(ARG_CHECKSUM)
# Sequence numbers count modulo the width of their field.
SEQ_MASK = (1 << (8 * RECORD_FIELDS[I_SEQ].size)) - 1

def _arg_checksums(lay: dict[str, Any], args: tuple[FieldInfo, ...]) -> tuple[ArgChecksumInfo, ...]:
    """A layout's argument checksum fields, in the spec's fill order (each later one may cover an
    earlier one)."""
    order = SPEC["checksums"]["fill_order"]
    found = [ArgChecksumInfo(ck["tag"], next(a for a in args if a.name == ck["arg"]), ck["algorithm"],
                             tuple((r[0], r[1]) for r in ck["ranges"])) for ck in lay.get("checksums", ())]
    return tuple(sorted(found, key=lambda ck: order.index(ck.tag)))


def _command(c: dict[str, Any]) -> CommandInfo:
    lays = []
    for lay in c["layouts"]:
        args = tuple(_field(a) for a in lay["args"])
        rep = args[-1].repeat if args else None
        if rep is not None:  # one layout per n (issue 25, point 3): every look-up by nb finds its own
            for n in range(rep[0], rep[1] + 1):
                nargs = (*args[:-1], _for_n(args[-1], n))
                lays.append(LayoutInfo(c["name"], c["code"], lay["variant"], frozenset(lay["versions"]),
                                       lay["size"] + args[-1].size * n, frozenset(lay["profiles"]), nargs,
                                       _struct(nargs), _struct(nargs, bits=True), n))
            continue
        lays.append(LayoutInfo(c["name"], c["code"], lay["variant"], frozenset(lay["versions"]), lay["size"],
                               frozenset(lay["profiles"]), args, _struct(args), _struct(args, bits=True),
                               checksums=_arg_checksums(lay, args)))
    by_version = {v["id"]: tuple(x for x in lays if v["id"] in x.versions) for v in SPEC["versions"]}
    return CommandInfo(c["name"], c["code"], tuple(lays), c["motion"], c["orientation"], c["shape"], c["cutter"],
                       c["progress"], {k: v for k, v in by_version.items() if v}, c.get("sets"))


COMMANDS: tuple[CommandInfo, ...] = tuple(_command(c) for c in SPEC["commands"])
BY_CODE = {c.code: c for c in COMMANDS}
BY_NAME = {c.name: c for c in COMMANDS}
# What readers (CUT, JSON) accept: every name, and each command's former names (issue 25, point 6);
# writers write ``CommandInfo.name``.
BY_ANY_NAME = {**{old: BY_CODE[c["code"]] for c in SPEC["commands"] for old in c.get("former_names", ())},
               **BY_NAME}

CHECKS: tuple[dict[str, Any], ...] = tuple(SPEC["checks"])


def _checks_by_kind() -> dict[str, tuple[dict[str, Any], ...]]:
    out: dict[str, tuple[dict[str, Any], ...]] = {}
    for c in CHECKS:
        out[c["kind"]] = (*out.get(c["kind"], ()), c)
    return out


_CHECKS_BY_KIND = _checks_by_kind()


@cache
def scoped_out(version: str) -> frozenset[str]:
    """The ids of the checks whose ``versions:`` leave out ``version`` (they judge no file of it)."""
    return frozenset(c["id"] for c in SPEC["checks"] if c["versions"] and version not in c["versions"])


def checks_of(kind: str) -> tuple[dict[str, Any], ...]:
    """The spec's checks of a kind, in spec order (a look-up: validation asks for every kind)."""
    return _CHECKS_BY_KIND.get(kind, ())


def deprecates(check: dict[str, Any], command: str, variant: str) -> bool:
    """Whether a check of kind deprecated names this command, or this layout (NAME/variant) of it."""
    return command in check["deprecates"] or f"{command}/{variant}" in check["deprecates"]


PROFILES: dict[str, dict[str, Any]] = SPEC["profiles"]
TOL: dict[str, float] = SPEC["tolerances"]
LIMITS: dict[str, int] = SPEC["limits"]
CUT: dict[str, Any] = SPEC["cut"]
CHECKSUMS: dict[str, Any] = SPEC["checksums"]
RECORD_BY_ROLE_NAME = {f.name: f for f in RECORD_FIELDS}


def available(cmd: CommandInfo, version: str | None) -> bool:
    return version is not None and bool(cmd.layouts_for(version))
SPEC_TITLE: str = SPEC["title"]
