"""Runtime tables built once, at import, from the generated spec data.

Nothing here knows a command, field or check by name: it reads the roles,
kinds and layouts of ``_spec_data.SPEC``.
"""

from __future__ import annotations

import struct
from dataclasses import dataclass
from struct import Struct
from typing import Any

from . import layouts
from ._spec_data import SPEC

BO = "<" if SPEC["byte_order"] == "little" else ">"
PAD = bytes([SPEC["string_padding"]])
_UINT = {1: "B", 2: "H", 4: "I"}


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

    @property
    def size(self) -> int:
        return self.elem_size * self.count

    @property
    def end(self) -> int:
        return self.offset + self.size

    @property
    def fmt(self) -> str:
        if self.kind == "uint":
            return _UINT[self.elem_size]
        if self.kind == "float":
            return f"{self.count}f" if self.count > 1 else "f"
        return f"{self.size}s"

    @property
    def bits_fmt(self) -> str:
        if self.kind == "float":
            return f"{self.count}I" if self.count > 1 else "I"
        return self.fmt


def _field(d: dict[str, Any]) -> FieldInfo:
    return FieldInfo(d["name"], d["kind"], d["offset"], d["elem_size"], d["count"], d["role"], d["magic"],
                     d["checksum"], d["reserved"], d["text"])


def _struct(fields: tuple[FieldInfo, ...], bits: bool = False) -> struct.Struct:
    return struct.Struct(BO + "".join(f.bits_fmt if bits else f.fmt for f in fields))


@dataclass(frozen=True, slots=True)
class LayoutInfo:
    command: str
    code: int
    variant: str
    cls: type
    versions: frozenset[str]
    size: int
    profiles: frozenset[str]
    args: tuple[FieldInfo, ...]
    struct: Struct
    bits: Struct

    def accepted_under(self, profile: str) -> bool:
        return not self.profiles or profile in self.profiles


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

    def layouts_for(self, version: str) -> tuple[LayoutInfo, ...]:
        return tuple(lay for lay in self.layouts if version in lay.versions)

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
    cls: type
    struct: Struct

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
    HEADERS[_hid] = HeaderInfo(_hid, _h["size"], _fields, layouts.HEADER_CLASSES[_hid], _struct(_fields))
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
HEADER_CHECKSUM_FIELDS = {f.checksum: f for f in _H0.fields if f.checksum}

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

COMMANDS: tuple[CommandInfo, ...] = tuple(
    CommandInfo(
        c["name"], c["code"],
        tuple(
            LayoutInfo(c["name"], c["code"], lay["variant"], layouts.ARGS_CLASSES[(c["name"], lay["variant"])],
                       frozenset(lay["versions"]), lay["size"], frozenset(lay["profiles"]),
                       tuple(_field(a) for a in lay["args"]),
                       _struct(tuple(_field(a) for a in lay["args"])),
                       _struct(tuple(_field(a) for a in lay["args"]), bits=True))
            for lay in c["layouts"]
        ),
        c["motion"], c["orientation"], c["shape"], c["cutter"], c["progress"],
    )
    for c in SPEC["commands"]
)
BY_CODE = {c.code: c for c in COMMANDS}
BY_NAME = {c.name: c for c in COMMANDS}

CHECKS: tuple[dict[str, Any], ...] = tuple(SPEC["checks"])


def checks_of(kind: str) -> tuple[dict[str, Any], ...]:
    return tuple(c for c in CHECKS if c["kind"] == kind)


PROFILES: dict[str, dict[str, Any]] = SPEC["profiles"]
TOL: dict[str, float] = SPEC["tolerances"]
LIMITS: dict[str, int] = SPEC["limits"]
CUT: dict[str, Any] = SPEC["cut"]
CHECKSUMS: dict[str, Any] = SPEC["checksums"]
RECORD_BY_ROLE_NAME = {f.name: f for f in RECORD_FIELDS}


def available(cmd: CommandInfo, version: str | None) -> bool:
    return version is not None and bool(cmd.layouts_for(version))
SPEC_TITLE: str = SPEC["title"]
