"""The spec language's vocabulary: every field type and every check kind, declared once.

The schema (its enums are filled from here when the loader reads it), the loader (what it accepts
and refuses), every emitter and the tests read this module. Nothing else lists a type or a kind.

Field types
    A ``FieldType`` says what a field's bytes are (kind, size, signedness). Every binding derives
    what it needs from those properties: the struct code, the numpy dtype, the Kaitai type, the C
    type. A revision picks the types it uses in spec/cbf.yaml ``types:``; each must be registered
    here with the same kind and size.

Check kinds
    A ``CheckKind`` names one rule every binding implements once (a Python kernel, a C kernel) and
    the parameters a check of that kind takes, as a frozen dataclass (``params``): the loader
    builds it from the YAML and refuses any key the kind does not take. ``versions`` scopes a check
    to files of those versions (empty: every version; a file of no known version is judged as the
    fallback version, as its records are read): every kind takes it but the two that judge a file
    before its version is known (``truncated_header``, ``version``). Availability requires it.

Binding capabilities
    ``unsupported(t)`` names the bindings that cannot yet carry a field of type ``t`` (the loader
    refuses such a field with its line, before any emitter runs).

Checksum algorithms (issue 33, point 1)
    A ``ChecksumAlgorithm`` is a kind a spec's ``checksums.algorithms`` may name: its family (sum,
    CRC, Fletcher), its parameters and its check value. Each runtime implements each family once.

Bindings (issue 33, point 2)
    A ``Binding`` says what a binding is made of (emitter, languages, testees, make fragment) and
    what it implements (check kinds, algorithm kinds, role kinds); generated/checklist/BINDINGS.md
    lists it and tests/test_bindings.py holds each binding to it.

Kind wording (issue 33, point 3)
    ``KIND_WORDING``: what the docs say of a check of a kind beyond its own text.

See generator/README.md, "Extending the spec language".
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import MISSING, dataclass, fields
from typing import Any, Literal

# -- field types ------------------------------------------------------------------------------

FieldKind = Literal["uint", "sint", "float", "string", "bytes"]
FIELD_KINDS: tuple[FieldKind, ...] = ("uint", "sint", "float", "string", "bytes")
NUMERIC_KINDS: tuple[FieldKind, ...] = ("uint", "sint", "float")
INTEGER_KINDS: tuple[FieldKind, ...] = ("uint", "sint")

# struct (and array) codes by kind and size: the one place a width maps to a code
_STRUCT_CODES: dict[tuple[str, int], str] = {
    ("uint", 1): "B", ("uint", 2): "H", ("uint", 4): "I", ("uint", 8): "Q",
    ("sint", 1): "b", ("sint", 2): "h", ("sint", 4): "i", ("sint", 8): "q",
    ("float", 4): "f", ("float", 8): "d",
}
_FLOAT_FORMATS = {4: "IEEE-754 binary32", 8: "IEEE-754 binary64"}


@dataclass(frozen=True)
class FieldType:
    """One type a field may have. ``size`` is None for str and bytes (the field gives it)."""

    name: str
    kind: FieldKind
    size: int | None
    doc: str

    @property
    def signed(self) -> bool:
        return self.kind in ("sint", "float")

    @property
    def is_integer(self) -> bool:
        return self.kind in INTEGER_KINDS

    @property
    def bits(self) -> int | None:
        return None if self.size is None else 8 * self.size

    @property
    def struct_code(self) -> str | None:
        """The Python struct code of one element (None: str and bytes, packed as ``Ns``)."""
        return None if self.size is None else _STRUCT_CODES[(self.kind, self.size)]

    @property
    def bits_code(self) -> str | None:
        """The struct code of the element's bit pattern: a float as the unsigned integer of its
        width (exact for NaN payloads), any other type as itself."""
        if self.kind == "float" and self.size is not None:
            return _STRUCT_CODES[("uint", self.size)]
        return self.struct_code

    @property
    def numpy(self) -> str | None:
        """The numpy dtype code without byte order ("u2", "i8", "f4"); None for str and bytes."""
        if self.size is None:
            return None
        return {"uint": "u", "sint": "i", "float": "f"}[self.kind] + str(self.size)

    @property
    def kaitai(self) -> str | None:
        """The Kaitai Struct type ("u2", "s8", "f4"); None for str and bytes (size-based)."""
        if self.size is None:
            return None
        return {"uint": "u", "sint": "s", "float": "f"}[self.kind] + str(self.size)

    @property
    def c_type(self) -> str | None:
        """The C type of one element; None for str and bytes (arrays of char / uint8_t)."""
        if self.size is None:
            return None
        if self.kind == "float":
            return {4: "float", 8: "double"}[self.size]
        return f"{'u' if self.kind == 'uint' else ''}int{8 * self.size}_t"

    @property
    def min(self) -> int | None:
        """The least integer value (None for other kinds)."""
        if not self.is_integer or self.size is None:
            return None
        return -(1 << (8 * self.size - 1)) if self.kind == "sint" else 0

    @property
    def max(self) -> int | None:
        if not self.is_integer or self.size is None:
            return None
        return (1 << (8 * self.size - (1 if self.kind == "sint" else 0))) - 1

    @property
    def float_format(self) -> str | None:
        return _FLOAT_FORMATS.get(self.size or 0) if self.kind == "float" else None


def _ints() -> dict[str, FieldType]:
    out: dict[str, FieldType] = {}
    kinds: tuple[tuple[FieldKind, str, str], ...] = (
        ("uint", "u", "unsigned"), ("sint", "s", "signed, two's complement"))
    for kind, prefix, what in kinds:
        for size in (1, 2, 4, 8):
            out[f"{prefix}{size}"] = FieldType(f"{prefix}{size}", kind, size, f"{what} {8 * size}-bit integer")
    return out


# Every type a revision may pick, by the name spec/cbf.yaml `types:` and the fields use.
TYPES: dict[str, FieldType] = {
    **_ints(),
    "f4": FieldType("f4", "float", 4, _FLOAT_FORMATS[4]),
    "f8": FieldType("f8", "float", 8, _FLOAT_FORMATS[8]),
    "str": FieldType("str", "string", None, "string(N): N bytes, NUL-padded"),
    "bytes": FieldType("bytes", "bytes", None, "raw bytes, kept verbatim"),
}

# The bindings the loader answers for, and what each carries today. Python and Kaitai read every
# type's codes from this registry; what a binding cannot carry yet is refused at load (the
# binding-capabilities pass), with the field's line, before any emitter runs:
#   c       every integer (the testee and cbf-c print them from their bits); binary32
#   python  every integer; no binary64 (canonical JSON and the CUT text carry binary32)
#   kaitai  every integer; no binary64 (its conformance testees report floats as binary32)
# Vectors (count > 1) are float vectors only (x, y, z) in every binding.
BINDINGS = ("python", "kaitai", "c")


# The bindings that read, write and validate a repeated argument group (issue 25, point 3: nb =
# fixed + k*n); the loader refuses a `repeat:` while any binding is missing here.
REPEAT_BINDINGS: tuple[str, ...] = ("python", "kaitai", "c")
# The most sizes one repeated group may take (max - min + 1): the generated tables hold a layout
# (Python, Kaitai) or a size case per n, and C's struct holds max items; the loader refuses more.
REPEAT_MAX_SIZES = 4096
# The largest CBF file the limits may allow (header + (max_commands + 1) x (record head + max_arg_size)):
# cbf-c holds a file in one static buffer of that size (2^40 commands made it 289 TB, and every call
# segfaulted), and cbf holds it in memory; the loader refuses limits past it.
MAX_FILE_BYTES = 1 << 28


def repeat_unsupported() -> tuple[str, ...]:
    """The bindings that cannot carry a repeated argument group yet; empty: all can."""
    return tuple(b for b in BINDINGS if b not in REPEAT_BINDINGS)


def unsupported(t: FieldType, count: int = 1) -> tuple[str, ...]:
    """The bindings that cannot carry a field of type ``t`` (``count`` elements); empty: all can.
    When a binding learns a type, its rule here changes, and nothing else in the loader."""
    gaps: set[str] = set()
    if t.kind == "float" and t.size != 4:
        gaps |= {"python", "kaitai", "c"}
    if count != 1 and t.kind != "float":
        gaps |= set(BINDINGS)
    return tuple(b for b in BINDINGS if b in gaps)


def unsupported_in_head(t: FieldType) -> tuple[str, ...]:
    """The bindings that cannot carry a header or record-head field of type ``t``: the C engine
    reads those (magic numbers, counts, sequence numbers, codes, checksums) unsigned, at most 4
    bytes wide; an argument may be any integer."""
    return ("c",) if t.is_integer and (t.kind == "sint" or (t.size or 0) > 4) else ()


# The header roles the codec derives (patterns, version, count, checksums): no text or caller sets them,
# and they sit in the same place in every header layout (the loader checks it).
DERIVED_HEADER_ROLES = ("start_pattern", "end_pattern", "version_major", "version_minor", "command_count", "checksum")


# What the argument a role names must be, by role and key: ("float", 3) a vector of three floats
# (the runtimes' geometry is 3-D), ("float", 1) one float, ("string", 1) a string, ("integer", 1)
# an integer. The loader refuses a role naming another argument (the kernels read these shapes).
RoleArg = tuple[Literal["float", "string", "integer"], int]
_VEC: RoleArg = ("float", 3)
_NUM: RoleArg = ("float", 1)
_STR: RoleArg = ("string", 1)
ROLE_ARGS: dict[str, dict[str, RoleArg]] = {
    "motion": {"start": _VEC, "end": _VEC, "center": _VEC, "normal": _VEC, "through": _VEC, "degrees": _NUM,
               "length": _NUM},
    "orientation": {"start": _VEC, "end": _VEC},
    "shape": {"name": _STR, "count": ("integer", 1)},
    "cutter": {"name": _STR, "length": _NUM, "radius": _NUM},
    "sets": {"speed": _NUM, "accel": _NUM, "decel": _NUM, "phase": _STR, "format_version": _STR},
    "progress": {"": _NUM},
}


# The kinds a command's motion, orientation and shape role may have, and for each kind the keys
# (of ROLE_ARGS[role]) the role must name for the engines to follow it: a circle needs its start,
# centre, normal and angle. The schema's enums are filled from here and the loader refuses a role
# that lacks a key its kind needs; every engine has a branch for each kind.
ROLE_NEEDS: dict[str, dict[str, tuple[str, ...]]] = {
    "motion": {"point": ("end",), "line": ("start", "end"), "circle": ("start", "center", "normal", "degrees"),
               "helix": ("start", "center", "normal", "degrees", "length")},
    "orientation": {"set": ("end",), "path": ("start", "end")},
    "shape": {"start": ("name", "count"), "end": ("name", "count")},
}
ROLE_KINDS: dict[str, tuple[str, ...]] = {role: tuple(kinds) for role, kinds in ROLE_NEEDS.items()}


def role_arg_fits(want: RoleArg, t: FieldType, count: int) -> bool:
    kind, n = want
    ok = t.kind == "float" if kind == "float" else t.kind == "string" if kind == "string" else t.is_integer
    return ok and count == n


# Names the generated code gives members of its own beside the spec's fields: the .ksy's header
# type switches on `version_index` into `layout`, its record type holds `args` and the `command`
# enum; a record of the canonical JSON (conformance/PROTOCOL.md) adds `offset`, `command`, `args`
# and `raw_args` to its head fields. A header or record field may not take them (names pass).
GENERATED_NAMES: dict[str, tuple[str, ...]] = {
    "header": ("layout", "version_index"),
    "record": ("args", "command", "offset", "raw_args"),
}


# -- check kinds ------------------------------------------------------------------------------

Severity = Literal["error", "warning"]


@dataclass(frozen=True)
class Target:
    """Arguments a check reads in one command's records (``limit``: machine_limits' limit)."""

    command: str
    args: tuple[str, ...]
    limit: str | None = None


@dataclass(frozen=True)
class NoParams:
    """A kind that takes nothing but its id, severity and texts."""


@dataclass(frozen=True)
class ScopedParams:
    """A kind that takes nothing but ``versions`` (and its id, severity and texts)."""

    versions: tuple[str, ...] = ()  # the versions whose files it judges (empty: every version)


@dataclass(frozen=True)
class PartNumberParams:
    input: Literal["part_number"] | None = None  # the run's input the check compares (cbf validate --part-number)
    versions: tuple[str, ...] = ()


@dataclass(frozen=True)
class CutterTableParams:
    input: Literal["cutters"] | None = None  # cbf validate --cutters FILE
    versions: tuple[str, ...] = ()


@dataclass(frozen=True)
class HeaderChecksumParams:
    field: str = "header"  # the checksum tag (checksums.fields) of the header field it judges
    versions: tuple[str, ...] = ()


@dataclass(frozen=True)
class ArgChecksumParams:
    """A record checksum (issue 25, point 1): ``field`` is the tag of the checksum field it judges,
    the record head's (``args``, 6.4.4) or one a command layout carries among its arguments."""

    field: str = "args"  # the checksum tag (checksums.fields) of the record's field it judges
    versions: tuple[str, ...] = ()


@dataclass(frozen=True)
class AvailabilityParams:
    versions: tuple[str, ...]  # the versions it covers
    commands: tuple[str, ...]  # the commands missing from them


@dataclass(frozen=True)
class TargetParams:
    targets: tuple[Target, ...]
    versions: tuple[str, ...] = ()


@dataclass(frozen=True)
class RangeParams:
    """``min``/``max`` are closed bounds unless ``min_exclusive``/``max_exclusive`` opens them:
    ``min: 0, min_exclusive: true, max: 36000`` says (0, 36000]."""

    targets: tuple[Target, ...]
    min: float | None = None  # at least one bound (the loader refuses a range without one)
    max: float | None = None
    min_exclusive: bool = False  # the value must be > min (the loader refuses it without min)
    max_exclusive: bool = False  # the value must be < max
    versions: tuple[str, ...] = ()


@dataclass(frozen=True)
class MachineLimitsParams:
    targets: tuple[Target, ...]  # each names a limit of machine.limits
    input: Literal["machine"] | None = None  # cbf validate --machine FILE
    input_severity: Severity | None = None  # the severity when a machine file is given
    versions: tuple[str, ...] = ()


@dataclass(frozen=True)
class DeprecatedParams:
    """A deprecation (issue 25, point 5): the commands ("NAME") or layouts ("NAME/variant") it names
    stay valid but every record of them draws a finding, in files of ``since`` and of every version
    after it in the spec's list. The loader fills ``versions`` from ``since`` (the YAML gives since)."""

    since: str
    deprecates: tuple[str, ...]
    versions: tuple[str, ...] = ()


Params = (NoParams | DeprecatedParams | ScopedParams | PartNumberParams | CutterTableParams | HeaderChecksumParams
          | ArgChecksumParams | AvailabilityParams | TargetParams | RangeParams | MachineLimitsParams)

Scope = Literal["file", "record"]


@dataclass(frozen=True)
class Accepts:
    """The values a check of a value-bounding kind accepts in each of its target arguments: what
    a generator of valid files (the Python runtime's ``testing``) may draw. A new kind that bounds
    values says it here, and the generators follow without naming the kind."""

    min: float | None = None
    max: float | None = None
    min_open: bool = False  # min itself is refused (``positive``: > 0; ``range`` with min_exclusive)
    max_open: bool = False  # max itself is refused (``range`` with max_exclusive)
    nonzero: bool = False  # a vector of zeros is refused


def _at_least(bound: float, open_: bool = False) -> Callable[[Any], Accepts]:
    return lambda check: Accepts(min=bound, min_open=open_)


@dataclass(frozen=True)
class CheckKind:
    """A check kind. ``scope``: file (judged once a file) or record (a kernel over records).
    ``repeatable``: several checks of the kind may exist, and every binding runs each one.
    ``kaitai``: the .ksy expresses it as a ``valid:`` expression (the rest is said in its doc)."""

    name: str
    params: type[Params]
    scope: Scope
    doc: str
    repeatable: bool = True
    kaitai: bool = False
    target_shape: RoleArg | None = None  # what each target argument must be (None: the kind checks it itself)
    accepts: Callable[[Any], Accepts] | None = None  # a check (model.Check) -> the values it accepts
    items: bool = False  # a target may be a repeated argument group, judged item by item in every binding
    whole: bool = False  # compares a target's arguments with each other: its kernels judge the target whole

    def accepted(self, check: Any) -> Accepts | None:
        """What ``check`` (of this kind) accepts in its targets; None: the kind bounds no value."""
        return None if self.accepts is None else self.accepts(check)

    @property
    def keys(self) -> tuple[str, ...]:
        """The YAML keys a check of this kind may carry beyond the common ones."""
        return tuple(f.name for f in fields(self.params))

    @property
    def required(self) -> tuple[str, ...]:
        """The parameters a check of this kind must give (not empty)."""
        return tuple(f.name for f in fields(self.params) if f.default is MISSING and f.default_factory is MISSING)

    @property
    def versioned(self) -> bool:
        """Whether ``versions:`` scopes the check in every runtime (only then may a check carry it)."""
        return "versions" in self.keys

    @property
    def gates(self) -> bool:
        """Whether a check of the kind covers (version, command) pairs (availability)."""
        return "commands" in self.keys

    @property
    def targeted(self) -> bool:
        return "targets" in self.keys


def _k(name: str, params: type[Params], scope: Scope, doc: str, kaitai: bool = False,
       target: RoleArg | None = None, accepts: Callable[[Any], Accepts] | None = None,
       whole: bool = False) -> CheckKind:
    return CheckKind(name, params, scope, doc, kaitai=kaitai, target_shape=target, accepts=accepts, whole=whole)


# In the order of the C engine's kind enum (and of the schema's list).
_KINDS = (
    _k("truncated_header", NoParams, "file", "the file is shorter than the header"),
    # not scoped by version: a file that ends inside a record cannot be read, whatever its version
    _k("truncated_record", NoParams, "file", "the file ends inside a record"),
    _k("part_number", PartNumberParams, "file", "the implant descriptor's first word is the given part number"),
    _k("descriptor_word", ScopedParams, "file", "the implant descriptor holds a word"),
    _k("cutter_table", CutterTableParams, "record", "cutters agree with the given cutter table"),
    _k("file_checksum", ScopedParams, "file", "the file checksum matches a coverage of the profile"),
    _k("command_count", ScopedParams, "file", "the header's count is the number of records"),
    _k("header_checksum", HeaderChecksumParams, "file",
       "the header checksum field it names (its `field`, a checksum tag) matches"),
    # Not scoped by version, like every kind the .ksy states as a `valid:` rule (kaitai=True) but
    # availability (whose rule is per version): a Kaitai parser applies the rule in every version.
    _k("magic", NoParams, "file", "the start and end patterns hold their values", kaitai=True),
    _k("sequence", ScopedParams, "record", "record i carries sequence number i"),
    _k("code_copy", NoParams, "record", "the code copy equals the code", kaitai=True),
    _k("arg_size", NoParams, "record", "nb is the size of a layout of the version", kaitai=True),
    _k("arg_checksum", ArgChecksumParams, "record",
       "the record checksum field it names (its `field`: the head's argument checksum, or a checksum among "
       "a command's arguments) matches"),
    _k("continuity", ScopedParams, "record", "a motion starts where the last one ended"),
    _k("availability", AvailabilityParams, "record", "the version has the command", kaitai=True),
    _k("version", NoParams, "file", "the header's version is a version of the spec"),
    _k("unknown_code", ScopedParams, "record", "the command code is in the table"),
    _k("trailing", ScopedParams, "file", "no byte follows the last record"),
    _k("reserved_byte", ScopedParams, "record", "the record's reserved byte is 0"),
    _k("string_tail", ScopedParams, "record", "only NULs follow a string's first NUL"),
    _k("string_ascii", ScopedParams, "record", "strings are printable ASCII"),
    _k("finite", ScopedParams, "record", "float arguments are finite"),
    _k("positive", TargetParams, "record", "target arguments are > 0", target=_NUM, accepts=_at_least(0.0, True)),
    _k("nonzero_vector", TargetParams, "record", "target vectors are not all zero", target=_VEC,
       accepts=lambda check: Accepts(nonzero=True)),
    _k("range", RangeParams, "record", "target arguments lie within min..max", target=_NUM,
       accepts=lambda check: Accepts(min=check.min, max=check.max, min_open=check.min_exclusive,
                                     max_open=check.max_exclusive)),
    _k("nondecreasing", TargetParams, "record", "a target argument does not fall from record to record", target=_NUM),
    _k("ordered", TargetParams, "record", "a target's arguments are in non-decreasing order", target=_NUM,
       whole=True),
    _k("orientation", ScopedParams, "record", "a 5-axis command starts at the current orientation"),
    _k("shape", ScopedParams, "record", "STARTSHAPE ... ENDSHAPE enclose their count of motions"),
    CheckKind("machine_limits", MachineLimitsParams, "record", "target arguments lie within the machine's limits",
              items=True),
    _k("deprecated", DeprecatedParams, "record", "a deprecated command or layout draws a finding"),
)

CHECK_KINDS: dict[str, CheckKind] = {k.name: k for k in _KINDS}

# Keys every check has, whatever its kind (the schema's `checks` items).
COMMON_CHECK_KEYS = ("id", "kind", "severity", "clause", "decision", "text", "fails")
SEVERITIES: tuple[Severity, ...] = ("error", "warning")


def kind(name: str) -> CheckKind:
    return CHECK_KINDS[name]


def kinds_with(scope: Scope) -> tuple[str, ...]:
    return tuple(k.name for k in _KINDS if k.scope == scope)


def targeted_kinds() -> tuple[str, ...]:
    return tuple(k.name for k in _KINDS if k.targeted)


# -- the loader's rules per check kind (issue 33, point 3) ------------------------------------
# What the loader checks of a check beyond the parameters its kind takes, as flags of the kind:
# the loader (cbfgen/loader/passes/) branches on these flags, never on a kind's name. A new kind
# with one of these rules is a line here; a kind with none needs no line.

@dataclass(frozen=True)
class LoaderRules:
    """``bounds``: ``min``/``max`` with ``min_exclusive``/``max_exclusive``: at least one bound,
    min <= max, an open bound needs its bound and leaves a value. ``limits``: each target names a
    machine limit (only these kinds' targets do) whose unit and shape fit its arguments, and every
    position argument is bounded by one. ``judges``: ``field`` names a checksum tag of the header
    (``header``) or of the record, head or arguments (``record``), and each such checksum field is
    judged by exactly one check. ``since``: the check gives ``since`` (a version), not
    ``versions``, which become since and every version after it; what it ``deprecates`` (commands
    or layouts) exists there and is deprecated by no other check."""

    bounds: bool = False
    limits: bool = False
    judges: Literal["header", "record"] | None = None
    since: bool = False


LOADER_RULES: dict[str, LoaderRules] = {
    "range": LoaderRules(bounds=True),
    "machine_limits": LoaderRules(limits=True),
    "header_checksum": LoaderRules(judges="header"),
    "arg_checksum": LoaderRules(judges="record"),
    "deprecated": LoaderRules(since=True),
}


def loader_rules(kind_name: str) -> LoaderRules:
    """The loader's rules for checks of the kind (none: ``LoaderRules()``)."""
    return LOADER_RULES.get(kind_name, LoaderRules())


# -- checksum algorithms (issue 33, point 1) ------------------------------------------------------
# Every algorithm kind a spec's `checksums.algorithms` may name (its `kind:`), as parameters: each
# runtime has ONE implementation per family, driven by them (the Python runtime's checksums.py, the
# C runtime's checksums.c with the tables cbfgen/emit/c/algorithms.py computes, the golden
# assembler's checksums.py). A new CRC is one line here with its catalogue check value, nothing
# else; tests/test_checksum_algorithms.py runs `check` through every runtime.

AlgorithmFamily = Literal["sum", "crc", "fletcher"]
# The families, in the order of the C runtime's family enum (its switches have no default).
ALGORITHM_FAMILIES: tuple[AlgorithmFamily, ...] = ("sum", "crc", "fletcher")
CHECK_INPUT = b"123456789"  # what `check` is the checksum of (the CRC catalogue's "check")
MAX_ALGORITHM_BITS = 32  # every runtime holds a result in 32 bits (the C runtime's uint32_t)


@dataclass(frozen=True)
class ChecksumAlgorithm:
    """One algorithm kind.

    ``family``
        ``sum``: the unsigned sum of the bytes, reduced to the width of the field that stores it
        (``width`` None). ``crc``: the Rocksoft model of the CRC catalogue (reveng): ``width``
        bits, ``poly`` (normal form, top bit implied), ``init``, ``refin`` (bytes fed least
        significant bit first), ``refout`` (the register reflected before ``xorout``).
        ``fletcher``: ``width`` 16 or 32; the data as little-endian words of ``width/16`` bytes
        (an odd tail padded with zeros), two running sums modulo ``2^(width/2) - 1``, the result
        ``sum2 << width/2 | sum1``.
    ``check``
        The algorithm's value over ASCII "123456789" (CHECK_INPUT; a sum unreduced): the CRC
        catalogue's check for a CRC, a fact of the algorithm that every runtime is tested with.
    """

    name: str
    family: AlgorithmFamily
    width: int | None
    check: int
    doc: str
    poly: int = 0
    init: int = 0
    refin: bool = False
    refout: bool = False
    xorout: int = 0

    def __post_init__(self) -> None:
        fits = self.width is None if self.family == "sum" else (
            self.width in (16, 32) if self.family == "fletcher" else 1 <= (self.width or 0) <= MAX_ALGORITHM_BITS)
        if not fits:
            raise ValueError(f"checksum algorithm {self.name}: width {self.width} does not fit family {self.family}")
        mask = (1 << (self.width or 0)) - 1
        if self.family == "crc" and any(v & ~mask for v in (self.poly, self.init, self.xorout, self.check)):
            raise ValueError(f"checksum algorithm {self.name}: a parameter is wider than {self.width} bits")

    @property
    def bits(self) -> int | None:
        """Width of the result; None for a sum (it takes its field's width)."""
        return self.width

    @property
    def parameters(self) -> dict[str, Any]:
        """The parameters as plain data (what the runtimes' tables carry), check value included."""
        return {"family": self.family, "width": self.width, "poly": self.poly, "init": self.init,
                "refin": self.refin, "refout": self.refout, "xorout": self.xorout, "check": self.check}


def _crc(name: str, width: int, poly: int, init: int, refin: bool, refout: bool, xorout: int, check: int,
         catalogue: str) -> ChecksumAlgorithm:
    return ChecksumAlgorithm(name, "crc", width, check, f"{catalogue}: poly 0x{poly:X}, init 0x{init:X}, "
                             f"refin {str(refin).lower()}, refout {str(refout).lower()}, xorout 0x{xorout:X}",
                             poly, init, refin, refout, xorout)


_ALGORITHMS = (
    ChecksumAlgorithm("sum", "sum", None, 0x1DD, "unsigned byte sum, reduced to the width of its field"),
    _crc("crc16_ccitt", 16, 0x1021, 0xFFFF, False, False, 0x0000, 0x29B1, "CRC-16/CCITT-FALSE (CRC-16/IBM-3740)"),
    _crc("crc32", 32, 0x04C11DB7, 0xFFFFFFFF, True, True, 0xFFFFFFFF, 0xCBF43926, "CRC-32/ISO-HDLC"),
    _crc("crc32c", 32, 0x1EDC6F41, 0xFFFFFFFF, True, True, 0xFFFFFFFF, 0xE3069283, "CRC-32/ISCSI (Castagnoli)"),
    ChecksumAlgorithm("fletcher16", "fletcher", 16, 0x1EDE, "Fletcher-16: bytes, sums modulo 255"),
    ChecksumAlgorithm("fletcher32", "fletcher", 32, 0xDF09D509,
                      "Fletcher-32: 16-bit little-endian words (odd tail padded with 0), sums modulo 65535"),
)

ALGORITHMS: dict[str, ChecksumAlgorithm] = {a.name: a for a in _ALGORITHMS}


def algorithm(name: str) -> ChecksumAlgorithm:
    return ALGORITHMS[name]


# -- bindings (issue 33, point 2) -----------------------------------------------------------------
# Every binding as data: what it is made of and what it implements. conformance/bindings.yaml (its
# testees), conformance/failures/ (a failure list per testee), mk/ (its make fragment) and
# escape.RESERVED (the reserved words of the languages its identifiers land in) are checked against
# it (tests/test_bindings.py), and generated/BINDINGS.md (cbfgen/emit/checklist) says, per binding,
# which check kinds, algorithm kinds and role kinds it implements. tests/test_bindings.py fails when
# a binding claims something it lacks (a Python kernel, a C kernel symbol, a Kaitai `valid:` rule).


@dataclass(frozen=True)
class Binding:
    """One binding. ``check_kinds``, ``algorithms`` and ``roles`` ("role/kind") are what it
    implements; a new binding starts with all three empty and its testees' failure lists full."""

    name: str
    doc: str
    emitter: str  # its emitter: cbfgen/emit/<emitter>/
    languages: tuple[str, ...]  # keys of escape.RESERVED: the languages its identifiers land in
    testees: tuple[str, ...]  # names in conformance/bindings.yaml; each has conformance/failures/<name>.txt
    make: str | None  # mk/<make>.mk builds and tests it (None: `make generate` alone)
    check_kinds: tuple[str, ...]
    algorithms: tuple[str, ...]
    roles: tuple[str, ...]
    # The loader answers for it (BINDINGS: it refuses what the binding cannot carry). A binding under
    # construction is not yet: its failure lists say what it lacks, and no spec is refused for it.
    gated: bool = True
    # Another binding whose engine files it builds, unchanged, for another target (c-wasm: c's). The
    # loader answers for it through that binding; it claims exactly what that binding claims.
    engine_of: str | None = None


def _all_roles() -> tuple[str, ...]:
    return tuple(f"{role}/{k}" for role, kinds in ROLE_KINDS.items() for k in kinds)


BINDING_LIST: tuple[Binding, ...] = (
    Binding("python", "the Python codec, validator and CLI (package cbf)", "python", ("Python",), ("python",), None,
            tuple(CHECK_KINDS), tuple(ALGORITHMS), _all_roles()),
    Binding("kaitai", "the .ksy and the parsers ksc 0.11 compiles from it (Python, JavaScript, Java, Go): it decodes, "
            "and states as valid: rules the kinds it can express", "kaitai",
            ("Kaitai", "Python", "JavaScript", "Java", "Go"),
            ("kaitai-python", "kaitai-javascript", "kaitai-go", "kaitai-java"), "kaitai",
            tuple(k.name for k in _KINDS if k.kaitai), (), ()),
    Binding("c", "the single-header C codec and validator (cbf.h), the testee and cbf-c", "c", ("C", "C++"), ("c",),
            "c", tuple(CHECK_KINDS), tuple(ALGORITHMS), _all_roles()),
    Binding("c-wasm", "the same C engine files (cbf.h, cbf_tools.h) built for wasm32-wasi: cbf-c.wasm and the "
            "testee, run under node's node:wasi", "c", ("C",), ("c-wasm",), "wasm",
            tuple(CHECK_KINDS), tuple(ALGORITHMS), _all_roles(), gated=False, engine_of="c"),
)
BINDING: dict[str, Binding] = {b.name: b for b in BINDING_LIST}


# -- per-kind wording of the docs (issue 33, point 3) ---------------------------------------------
# What the format documentation says of a check beyond its spec text, by kind: why it reads a
# command's records (`reads`: (check, command) -> a phrase, None when it does not read them, for
# the command pages) and what its parameters add to its prose (`scope`: check -> sentences). The
# docs emitter asks here and names no kind; a kind with no entry is listed per command only when
# one of its targets names the command. `own_versions`: the kind says its versions itself.


@dataclass(frozen=True)
class KindWording:
    reads: Callable[[Any, Any], str | None] | None = None
    scope: Callable[[Any], str | None] | None = None
    own_versions: bool = False


def _arg_kinds(c: Any) -> set[str]:
    return {a.kind for lay in c.layouts for a in lay.args}


def _availability_reads(k: Any, c: Any) -> str | None:
    if c.name not in k.commands:  # another availability check covers this command
        return None
    missing = [v for v in k.versions if not c.available_in(v)]
    return f"{c.name} is not in version {', '.join(missing)}" if missing else None


def _arg_checksum_reads(k: Any, c: Any) -> str | None:
    if not k.checksum_field:
        return None
    carried = [ck for lay in c.layouts for ck in lay.checksums if ck.tag == k.checksum_field]
    return (f"its argument {carried[0].field.name} holds checksum {k.checksum_field} over "
            f"{', '.join(carried[0].covers)}") if carried else None


def _deprecated_reads(k: Any, c: Any) -> str | None:
    lays = [lay.variant or "primary" for lay in c.layouts if k.deprecates_layout(c.name, lay.variant)]
    what = c.name if len(lays) == len(c.layouts) else f"{c.name} layout {', '.join(lays)}"
    return f"deprecated: {what}, since version {k.since}" if lays else None


def _range_scope(k: Any) -> str:
    lo = "-inf" if k.min is None else f"{k.min:g}"
    hi = "inf" if k.max is None else f"{k.max:g}"
    return (f"Range {'(' if k.min_exclusive or k.min is None else '['}{lo}, {hi}"
            f"{')' if k.max_exclusive or k.max is None else ']'}.")


KIND_WORDING: dict[str, KindWording] = {
    "availability": KindWording(reads=_availability_reads),
    "arg_checksum": KindWording(reads=_arg_checksum_reads),
    "deprecated": KindWording(reads=_deprecated_reads, own_versions=True, scope=lambda k: (
        f"Deprecates {', '.join(k.deprecates)} in files of version {', '.join(k.versions)}.")),
    "range": KindWording(scope=_range_scope),
    "continuity": KindWording(reads=lambda k, c: "a motion command" if c.motion else None),
    "orientation": KindWording(reads=lambda k, c: "a 5-axis command" if c.orientation else None),
    "shape": KindWording(reads=lambda k, c: "opens or closes a shape" if c.shape
                         else "a motion command, counted in shapes" if c.motion else None),
    "cutter_table": KindWording(reads=lambda k, c: "a cutter" if c.cutter else None),
    "finite": KindWording(reads=lambda k, c: "float arguments" if "float" in _arg_kinds(c) else None),
    "string_tail": KindWording(reads=lambda k, c: "string arguments" if "string" in _arg_kinds(c) else None),
    "string_ascii": KindWording(reads=lambda k, c: "string arguments" if "string" in _arg_kinds(c) else None),
}


def wording(kind_name: str) -> KindWording:
    """The docs' wording of a kind (an empty KindWording for a kind that needs none)."""
    return KIND_WORDING.get(kind_name, KindWording())
