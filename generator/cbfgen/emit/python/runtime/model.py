"""The decoded file: a header, the records, and any trailing bytes.

Records keep their argument bytes verbatim (``raw_args``); the typed
arguments (``Record.args``) are decoded from them on demand, so nothing is
lost and big files stay small in memory.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field
from typing import Any, overload

from . import tables as T
from .fields import pack_args, unpack_args


@dataclass(frozen=True, slots=True)
class Record:
    """One command record. Head fields are named by their spec roles."""

    code: int
    raw_args: bytes = b""
    sequence: int = 0
    code_copy: int | None = None
    reserved: int = 0
    arg_checksum: int | None = None
    offset: int | None = field(default=None, compare=False)

    @property
    def arg_size(self) -> int:
        return len(self.raw_args)

    @property
    def command(self) -> T.CommandInfo | None:
        return T.BY_CODE.get(self.code)

    @property
    def name(self) -> str | None:
        c = T.BY_CODE.get(self.code)
        return c.name if c else None

    def layout(self, version: str = T.DEFAULT_VERSION) -> T.LayoutInfo | None:
        c = T.BY_CODE.get(self.code)
        return c.layout_for_size(version, len(self.raw_args)) if c else None

    def decode_args(self, version: str = T.DEFAULT_VERSION) -> Any | None:
        """The typed arguments (a dataclass of cbf.layouts), or None when no layout fits."""
        lay = self.layout(version)
        return unpack_args(lay, self.raw_args) if lay else None

    @property
    def args(self) -> Any | None:
        return self.decode_args()

    @classmethod
    def of(cls, args: Any, **head: Any) -> Record:
        """A record for a typed argument object, e.g. ``Record.of(Line(start=..., end=...))``."""
        lay = layout_of(args)
        return cls(code=lay.code, raw_args=pack_args(lay, args), **head)


def layout_of(args: Any) -> T.LayoutInfo:
    for c in T.COMMANDS:
        for lay in c.layouts:
            if type(args) is lay.cls:
                return lay
    raise TypeError(f"{type(args).__name__} is not a command layout of cbf.layouts")


class _Records(Sequence[Record]):
    """What the lazy record sequences share: equal to any sequence of equal records."""

    __slots__ = ()

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Sequence):
            return NotImplemented
        return len(self) == len(other) and all(a == b for a, b in zip(self, other, strict=True))

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        return f"{type(self).__name__}({len(self)} records)"


class RecordList(_Records):
    """The records of a decoded file: a view on its bytes that makes each
    Record when asked, so decoding a big file costs one framing pass."""

    __slots__ = ("_buf", "_offsets", "framed")

    def __init__(self, buf: bytes, offsets: Sequence[int], framed: int | None = None) -> None:
        self._buf = buf
        self._offsets = offsets
        # When these are all the records of ``buf`` (as decode made them): where framing stopped.
        self.framed = framed

    @property
    def source(self) -> tuple[bytes, Sequence[int]]:
        return self._buf, self._offsets

    def __len__(self) -> int:
        return len(self._offsets)

    def _make(self, off: int) -> Record:
        h = T.HEAD_STRUCT.unpack_from(self._buf, off)
        start = off + T.HEAD_SIZE
        return Record(h[T.I_CODE], self._buf[start:start + h[T.I_SIZE]], h[T.I_SEQ], h[T.I_COPY], h[T.I_RES],
                      h[T.I_CHK], off)

    @overload
    def __getitem__(self, index: int) -> Record: ...

    @overload
    def __getitem__(self, index: slice) -> Sequence[Record]: ...

    def __getitem__(self, index: int | slice) -> Record | Sequence[Record]:
        if isinstance(index, slice):
            return RecordList(self._buf, self._offsets[index])
        return self._make(self._offsets[index])

    def __iter__(self) -> Iterator[Record]:
        make = self._make
        for off in self._offsets:
            yield make(off)


class PackedRecords(_Records):
    """Records as compact columns, as CUT text gives them (cut.from_cut): the codes, every
    record's arguments one after another (record i's are ``args[bounds[i]:bounds[i + 1]]``),
    and the code copy (negative: none given) and reserved byte of each. A Record is made when
    asked, the same Record the text describes; encode reads the columns as they are."""

    __slots__ = ("args", "bounds", "codes", "copies", "reserved")

    def __init__(self, codes: Sequence[int], args: bytes, bounds: Sequence[int], copies: Sequence[int],
                 reserved: Sequence[int]) -> None:
        if not (len(codes) + 1 == len(bounds) and len(codes) == len(copies) == len(reserved)):
            raise ValueError("PackedRecords: columns of different lengths")
        self.codes, self.args, self.bounds, self.copies, self.reserved = codes, args, bounds, copies, reserved

    def __len__(self) -> int:
        return len(self.codes)

    def _make(self, i: int) -> Record:
        copy = self.copies[i]
        return Record(self.codes[i], self.args[self.bounds[i]:self.bounds[i + 1]], 0, None if copy < 0 else copy,
                      self.reserved[i])

    @overload
    def __getitem__(self, index: int) -> Record: ...

    @overload
    def __getitem__(self, index: slice) -> Sequence[Record]: ...

    def __getitem__(self, index: int | slice) -> Record | Sequence[Record]:
        if isinstance(index, slice):
            return tuple(self._make(i) for i in range(*index.indices(len(self))))
        return self._make(range(len(self))[index])

    def __iter__(self) -> Iterator[Record]:
        return map(self._make, range(len(self)))


@dataclass(frozen=True)
class Cbf:
    """A CBF file. ``header`` is a dataclass of cbf.layouts (Header<layout>);
    ``records`` any sequence of Record (a lazy RecordList when decoded)."""

    header: Any
    records: Sequence[Record]
    trailing: bytes = b""

    @property
    def version(self) -> tuple[int, int]:
        return int(getattr(self.header, T.VMAJOR.name)), int(getattr(self.header, T.VMINOR.name))

    @property
    def version_id(self) -> str:
        return T.version_id(*self.version) or T.FALLBACK_VERSION

    def typed_records(self) -> list[tuple[Record, Any | None]]:
        vid = self.version_id
        return [(r, r.decode_args(vid)) for r in self.records]


def new_header(version: str = T.DEFAULT_VERSION, **values: Any) -> Any:
    """A header of the layout ``version`` selects, every field zero/empty unless given."""
    major, minor = T.parse_version(version)
    vid = T.version_id(major, minor) or T.FALLBACK_VERSION
    info = T.HEADERS[T.VERSION_BY_ID[vid].header]
    init: dict[str, Any] = {}
    for f in info.fields:
        if f.kind == "string":
            init[f.name] = ""
        elif f.kind == "bytes":
            init[f.name] = bytes(f.size)
        elif f.magic is not None:
            init[f.name] = f.magic
        else:
            init[f.name] = 0
    init[T.VMAJOR.name], init[T.VMINOR.name] = major, minor
    init.update(values)
    return info.cls(**init)
