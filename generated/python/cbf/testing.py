"""Hypothesis strategies for CBF files, driven by the spec tables.

Needs hypothesis (``pip install hypothesis``); ``import cbf`` does not import
this module, so the codec itself does not need it::

    from hypothesis import given
    from cbf.testing import cutfiles, mutations

    @given(cutfiles(profile="default"))
    def test_my_reader(data: bytes) -> None: ...     # data validates with no finding

    @given(mutations())
    def test_my_reader_survives(data: bytes) -> None: ...

``cutfiles()`` gives bytes; ``models()`` the Cbf models before sealing
(``seal(model, profile)`` fills the derived values for any version);
``mutations()`` corrupts files (bit flips, byte replacements, truncation,
swapped / dropped records, count and size fields that lie, ...), and
``reseal_checksums()`` recomputes the checksums of a mutated file so the
checks behind them are reached.

Everything is read from the spec (cbf.tables): the versions, the commands a
version has and their argument layouts, the checks and their targets. A
command added to the spec is drawn with no change here.

What ``cutfiles()`` guarantees, for the profile it is given: the file
validates with **no finding at all** (no error, no warning) -- framing,
count, sequence numbers, code copies, checksums, magic numbers, versions,
command availability, argument sizes (layouts the profile accepts), finite
floats (no NaN, infinity or subnormal, within ``bound``), ASCII strings
without tails, zero reserved bytes, the checks of the spec that bound values
(each check's ``accepts``, from the registry of check kinds: ``positive``,
``range``, ``nonzero_vector``, ...), the ``nondecreasing`` and ``ordered`` checks, the
``machine_limits`` checks against the spec's default machine (positions stay
inside its workspace: ``bound`` is narrowed to fit), motion
continuity (each motion starts where the last one ended, circles and helices
included), orientation continuity, and balanced shapes whose declared count
matches the motions they enclose. With ``part_number`` the implant descriptor
starts with it (check 6.1.1); with ``cutters`` every cutter command names a
cutter of that table with its length and radius (check 6.1.2).
``continuous=False`` draws start points and start orientations freely: the
continuity (6.4.5) and orientation checks may then fire, nothing else does.
A check kind added to the spec that this module does not know is not
guaranteed.
"""

from __future__ import annotations

import functools
import math
import re
import struct
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import Any, TypeVar

try:
    from hypothesis import strategies as st
except ImportError as exc:  # pragma: no cover - depends on the environment
    raise ImportError("cbf.testing needs hypothesis: pip install hypothesis") from exc

from . import tables as T
from .codec import field_checksum, file_algorithm, fill_arg_checksums, fill_header, frame, header_info, pack_file
from .geometry import motion_end
from .model import Cbf, Record, new_header
from .optfiles import CUTTER_NAME, CUTTER_VALUES

__all__ = ["cutfiles", "models", "mutations", "reseal_checksums", "seal"]

_T = TypeVar("_T")

_F32 = struct.Struct("<f")
# Circles and helices are drawn around a centre this close to their start, so
# that chains of them stay near the drawing box.
_RADIUS = 10.0
_SIGN = st.sampled_from([1.0, -1.0])
_BYTE = st.sampled_from([0x00, 0xFF]) | st.integers(0, 255)
_COUNT_LIE = st.sampled_from([0, 1, (1 << (8 * T.COUNT.size)) - 1]) | st.integers(0, (1 << (8 * T.COUNT.size)) - 1)
_CODE = st.sampled_from(sorted(c.code for c in T.COMMANDS)) | st.integers(0, 255)


def _f32(x: float) -> float:
    v: float = _F32.unpack(_F32.pack(x))[0]
    return v


def _max_bound() -> float:
    """The largest box where rounding a position to binary32 stays well within the
    position tolerance (positions may wander to twice the box)."""
    return T.TOL["position_mm"] * float(1 << 23) / 4.0


@dataclass
class _Limits:
    """What the spec's checks ask of one argument."""

    lo: float | None = None
    hi: float | None = None
    lo_open: bool = False  # lo itself is refused (positive; a range's min_exclusive)
    hi_open: bool = False  # hi itself is refused (a range's max_exclusive)
    nonzero: bool = False
    monotone: list[str] = field(default_factory=list)  # keys of nondecreasing checks


@dataclass
class _Rules:
    limits: dict[tuple[str, str], _Limits]
    ordered: dict[str, list[tuple[str, ...]]]


def _rules() -> _Rules:
    limits: dict[tuple[str, str], _Limits] = {}
    ordered: dict[str, list[tuple[str, ...]]] = {}
    for ch in T.CHECKS:
        kind = ch["kind"]
        for t in ch["targets"]:
            cmd, names = t["command"], tuple(t["args"])
            if kind == "ordered":
                ordered.setdefault(cmd, []).append(names)
                continue
            for n in names:
                lim = limits.setdefault((cmd, n), _Limits())
                if ch["accepts"] is not None:
                    _bound(lim, ch["accepts"])
                elif kind == "nondecreasing":
                    lim.monotone.append(f"{ch['id']}:{cmd}.{n}")
                elif kind == "machine_limits":  # the default machine (L1): its tightest bound on any axis
                    m = T.SPEC["machine"]["limits"][t["limit"]]
                    lo, hi = max(_as_list(m["min"])), min(_as_list(m["max"]))
                    lim.lo = lo if lim.lo is None else max(lim.lo, lo)
                    lim.hi = hi if lim.hi is None else min(lim.hi, hi)
    return _Rules(limits, ordered)


def _bound(lim: _Limits, acc: Mapping[str, Any]) -> None:
    """Narrows ``lim`` to what one check accepts (its ``accepts``: min, max, min_open, max_open, nonzero)."""
    lo, hi = acc["min"], acc["max"]
    if lo is not None:
        if lim.lo is None or lo > lim.lo:
            lim.lo, lim.lo_open = lo, bool(acc["min_open"])
        elif lo == lim.lo:
            lim.lo_open = lim.lo_open or bool(acc["min_open"])
    if hi is not None:
        if lim.hi is None or hi < lim.hi:
            lim.hi, lim.hi_open = hi, bool(acc["max_open"])
        elif hi == lim.hi:
            lim.hi_open = lim.hi_open or bool(acc["max_open"])
    lim.nonzero = lim.nonzero or bool(acc["nonzero"])


def _int_lo(lim: _Limits | None) -> int:
    """The least unsigned value a check's bound lets an integer argument take."""
    if lim is None or lim.lo is None:
        return 0
    return max(0, math.floor(lim.lo) + 1 if lim.lo_open else math.ceil(lim.lo))


def _as_list(v: float | list[float]) -> list[float]:
    return list(v) if isinstance(v, list) else [v]


def _machine_bound(bound: float) -> float:
    """``bound`` narrowed so that positions, which may wander to twice the bound plus a circle's
    radius, stay inside every box of the default machine (the box holds the origin)."""
    for m in T.SPEC["machine"]["limits"].values():
        if "axes" in m:
            half = min(min(-x for x in m["min"]), min(m["max"]))
            if half > _RADIUS:
                bound = min(bound, (half - _RADIUS) / 2.0)
    return bound


@dataclass
class _State:
    pos: tuple[float, ...] | None = None
    orient: tuple[float, ...] | None = None
    prev: dict[str, float] = field(default_factory=dict)


@functools.lru_cache(maxsize=256)
def _ascii(size: int, *, spaces: bool, min_size: int = 0) -> st.SearchStrategy[str]:
    """Printable ASCII, one draw per string (a byte string mapped onto the range)."""
    lo = 0x20 if spaces else 0x21
    span = 0x7F - lo
    return st.binary(min_size=min_size, max_size=size).map(lambda raw: "".join(chr(lo + b % span) for b in raw))


@functools.lru_cache(maxsize=256)
def _word(size: int, profile: str, arg: str) -> st.SearchStrategy[str]:
    """A one-word string; a name the profile's CUT reader reads whole when the spec limits it
    (cut.profile_words: implib reads \\w+), so that the file's CUT text under that profile exists."""
    rule = T.CUT.get("profile_words", {}).get(profile)
    if rule is None or arg not in rule["args"]:
        return _ascii(size, spaces=False)
    pattern = rule["pattern"]
    return st.from_regex(pattern, fullmatch=True).map(lambda w: w[:size]).filter(
        lambda w: re.fullmatch(pattern, w) is not None)


def _pick(draw: st.DrawFn, items: Sequence[_T]) -> _T:
    """One of ``items`` (by index: cheaper than sampled_from over spec objects)."""
    return items[draw(st.integers(0, len(items) - 1))]


@functools.lru_cache(maxsize=256)
def _floats(lo: float, hi: float, exclude_lo: bool = False) -> st.SearchStrategy[float]:
    """binary32 values in [lo, hi] (hypothesis wants bounds that binary32 holds exactly)."""
    lo32, hi32 = _f32(lo), _f32(hi)
    if lo32 < lo:
        lo32 = _f32_step(lo32, up=True)
    if hi32 > hi:
        hi32 = _f32_step(hi32, up=False)
    if lo32 >= hi32:
        return st.just(lo32)
    return st.floats(lo32, hi32, width=32, allow_nan=False, allow_infinity=False, allow_subnormal=False,
                     exclude_min=exclude_lo)


def _f32_step(v: float, *, up: bool) -> float:
    """The neighbouring binary32 of a finite binary32 ``v``."""
    if v == 0.0:
        return _f32(1e-45) if up else -_f32(1e-45)
    bits = struct.unpack("<I", _F32.pack(v))[0]
    bits += 1 if (v > 0) == up else -1
    out: float = _F32.unpack(struct.pack("<I", bits))[0]
    return out


def _vector(draw: st.DrawFn, count: int, lo: float, hi: float, nonzero: bool) -> tuple[float, ...]:
    if nonzero:
        vals = [draw(_floats(-1.0, 1.0)) for _ in range(count)]
        if sum(v * v for v in vals) < 1e-4:
            vals[draw(st.integers(0, count - 1))] = draw(_SIGN)
        return tuple(vals)
    return tuple(draw(_floats(lo, hi)) for _ in range(count))


class _Draw:
    """Draws the records of one file: keeps the motion, orientation and progress state."""

    def __init__(self, draw: st.DrawFn, version: str, profile: str, bound: float, continuous: bool,
                 cutters: Mapping[str, tuple[float, ...]] | None, rules: _Rules) -> None:
        self.draw, self.version, self.profile, self.bound = draw, version, profile, bound
        self.continuous, self.cutters, self.rules = continuous, cutters, rules
        self.state = _State()

    def value(self, cmd: T.CommandInfo, f: T.FieldInfo) -> Any:
        draw = self.draw
        if f.kind == "bytes":
            return bytes(f.size)  # reserved bytes are zero
        if f.kind == "string":
            if not f.text:
                return draw(_word(f.size, self.profile, f.name)).encode("ascii")
            return draw(_ascii(f.size, spaces=f.text)).encode("ascii")
        if f.kind == "uint":
            ulim = self.rules.limits.get((cmd.name, f.name))
            return draw(st.integers(_int_lo(ulim), (1 << (8 * f.elem_size)) - 1))
        if f.is_int:  # signed: its whole range
            return draw(st.integers(f.lo, f.hi))
        lim = self.rules.limits.get((cmd.name, f.name)) or _Limits()
        lo: float = -self.bound
        hi: float = self.bound
        if lim.lo is not None:
            lo = max(lo, lim.lo)
        if lim.hi is not None:
            hi = min(hi, lim.hi)
            if lim.hi_open and hi == lim.hi:
                hi = _f32_step(_f32(hi), up=False)  # an open bound: the binary32 just below it
        for key in lim.monotone:
            if key in self.state.prev:
                lo = max(lo, self.state.prev[key])
        if f.per > 1:  # a repeated group of vectors: its n items, each a vector (a polyline's points)
            return tuple(_vector(draw, f.per, lo, hi, lim.nonzero) for _ in range(f.items))
        if f.count > 1:
            return _vector(draw, f.count, lo, hi, lim.nonzero)
        return draw(_floats(lo, max(lo, hi), exclude_lo=lim.lo_open and lim.lo is not None and lo <= lim.lo))

    def args(self, cmd: T.CommandInfo, lay: T.LayoutInfo, fixed: Mapping[str, Any] | None = None) -> bytes:
        """The argument bytes of one record; ``fixed`` values are kept as given."""
        a: dict[str, Any] = {}
        later = self._derived(cmd)
        for f in lay.args:
            if fixed and f.name in fixed:
                a[f.name] = fixed[f.name]
            elif f.name not in later:
                a[f.name] = self.value(cmd, f)
        for names in self.rules.ordered.get(cmd.name, ()):
            if all(n in a and isinstance(a[n], float) for n in names):
                for n, v in zip(names, sorted(a[n] for n in names), strict=True):
                    a[n] = v
        if self.cutters is not None and cmd.cutter is not None:
            self._cutter(cmd, lay, a, self.cutters)
        self._geometry(cmd, lay, a)
        for f in lay.args:
            if f.kind == "float":
                for key in (self.rules.limits.get((cmd.name, f.name)) or _Limits()).monotone:
                    self.state.prev[key] = a[f.name]
        return _pack(lay, a)

    def _cutter(self, cmd: T.CommandInfo, lay: T.LayoutInfo, a: dict[str, Any], cutters: Any) -> None:
        """A cutter of the table, by name, with the table's values for the arguments it sets."""
        role = cmd.cutter or {}
        name = _pick(self.draw, self._cutter_names(cmd, lay))
        a[role[CUTTER_NAME]] = name.encode("ascii")
        for key, ref in zip(CUTTER_VALUES, cutters[name], strict=True):  # the table's columns
            if role.get(key) in a:
                a[role[key]] = _f32(ref)

    def _cutter_names(self, cmd: T.CommandInfo, lay: T.LayoutInfo) -> list[str]:
        role = cmd.cutter or {}
        size = next((f.size for f in lay.args if f.name == role.get(CUTTER_NAME)), 0)
        return [n for n in sorted(self.cutters or {}) if n.isascii() and n.isprintable() and 0 < len(n) <= size]

    def usable(self, cmd: T.CommandInfo, lay: T.LayoutInfo) -> bool:
        if cmd.cutter is not None and self.cutters is not None:
            return bool(self._cutter_names(cmd, lay))
        return True

    def _derived(self, cmd: T.CommandInfo) -> set[str]:
        """The arguments _geometry sets, so not drawn before it."""
        out: set[str] = set()
        m, o = cmd.motion, cmd.orientation
        if m is not None:
            if m["kind"] != "point" and self.continuous and self.state.pos is not None:
                out.add(m["start"])
            out.update(m[k] for k in ("center", "length") if k in m)
        if o is not None and o["kind"] == "path" and self.continuous and self.state.orient is not None:
            out.add(o["start"])
        return out

    def _geometry(self, cmd: T.CommandInfo, lay: T.LayoutInfo, a: dict[str, Any]) -> None:
        st_ = self.state
        m = cmd.motion
        if m is not None:
            if m["kind"] != "point" and self.continuous and st_.pos is not None:
                a[m["start"]] = tuple(_f32(x) for x in st_.pos)
            if "center" in m:
                start = a[m["start"]]
                d = _vector(self.draw, len(start), -_RADIUS, _RADIUS, False)
                a[m["center"]] = tuple(_f32(s + x) for s, x in zip(start, d, strict=True))
                if sum(x * x for x in a[m["normal"]]) < 1e-4:
                    a[m["normal"]] = _vector(self.draw, len(start), -1.0, 1.0, True)
                if "length" in m:
                    a[m["length"]] = self.draw(_floats(-_RADIUS, _RADIUS))
                end = motion_end(m, a)
                if end is not None and max(abs(x) for x in end) > 2 * self.bound:
                    # keep chains near the box: a full stop on the spot
                    a[m["degrees"]] = 0.0
                    if "length" in m:
                        a[m["length"]] = 0.0
            st_.pos = motion_end(m, a)
        o = cmd.orientation
        if o is not None:
            if o["kind"] == "path" and self.continuous and st_.orient is not None:
                a[o["start"]] = st_.orient
            e = a[o["end"]]
            st_.orient = e if all(math.isfinite(x) for x in e) and math.sqrt(sum(x * x for x in e)) > 0.0 else None


def _deprecated(version: str, cmd: T.CommandInfo, lay: T.LayoutInfo) -> bool:
    """Whether a check of kind deprecated reports this layout's records in files of this version."""
    return any(version in c["versions"] and T.deprecates(c, cmd.name, lay.variant)
               for c in T.checks_of("deprecated"))


def _pool(version: str, profile: str) -> list[tuple[T.CommandInfo, T.LayoutInfo]]:
    """Every (command, layout) a file of this version may hold under this profile without a finding
    (a deprecated one draws a warning: it is left out)."""
    out = []
    for cmd in T.COMMANDS:
        own = [lay for lay in cmd.layouts_for(version) if profile in lay.profiles]
        for lay in own or cmd.layouts_for(version):  # the profile's writers write its own layout (N8)
            if (lay.accepted_under(profile) and cmd.layout_for_size(version, lay.size) is lay
                    and not _deprecated(version, cmd, lay)):
                out.append((cmd, lay))
    return out


def _header(draw: st.DrawFn, version: T.VersionInfo, part_number: str | None) -> Any:
    info = T.HEADERS[version.header]
    minor = version.minor if version.minor is not None else draw(st.integers(0, (1 << (8 * T.VMINOR.size)) - 1))
    values: dict[str, Any] = {}
    for f in info.fields:
        if f.role in T.DERIVED_ROLES or f.kind != "string":
            continue  # derived, or reserved (zero)
        if f.role == "implant_descriptor" and part_number is not None:
            rest = draw(_ascii(max(0, f.size - len(part_number) - 1), spaces=True))
            values[f.name] = f"{part_number} {rest}".rstrip(" ") if rest.strip() else part_number
        else:
            value = draw(_ascii(f.size, spaces=True))
            if f.role == "implant_descriptor" and T.checks_of("descriptor_word") and not value.split():
                value = ("P" + value)[:f.size]  # a word comes first (4.2), else the file has a finding
            values[f.name] = value
    return new_header(f"{version.major}.{minor}", **values)


def seal(model: Cbf, profile: str = "default") -> bytes:
    """The bytes of ``model`` with every derived value filled (sequence numbers, code
    copies, count, magic numbers, checksums under ``profile``), for any version --
    also the versions ``encode`` does not write -- and without validating."""
    records = tuple(replace(r, sequence=i & T.SEQ_MASK, code_copy=r.code, arg_checksum=None)
                    for i, r in enumerate(model.records))
    out = bytearray(pack_file(Cbf(model.header, records, model.trailing), keep_stored=True))
    offsets, _ = frame(out)
    _fill_records(out, offsets, head_sums=False)
    fill_header(out, list(offsets), len(records), profile)
    return bytes(out)


def _fill_records(b: bytearray, offsets: Sequence[int], head_sums: bool) -> None:
    """Fill the checksum fields among each record's arguments (issue 25, point 1; the layout of
    its code and nb for the file's version), then the head's argument checksum over them: of every
    record with ``head_sums``, else of those whose arguments carry one."""
    chk = T.ARG_CHECKSUM
    vid = header_info(b)[0] or T.FALLBACK_VERSION
    code_at = T.RECORD_BY_ROLE["code"].offset
    for o in offsets:
        start = o + T.HEAD_SIZE
        nb = b[o + T.ARG_SIZE_OFFSET]
        cmd = T.BY_CODE.get(b[o + code_at])
        lay = cmd.layout_for_size(vid, nb) if cmd is not None else None
        carries = lay is not None and bool(lay.checksums)
        if lay is not None and carries:
            b[start:start + nb] = fill_arg_checksums(lay, bytes(b[o:start]), b[start:start + nb])
        if head_sums or carries:
            _put(b, chk, o, field_checksum("args", b"", (), args=bytes(b[start:start + nb])))


def _check_args(profile: str, min_records: int, max_records: int, bound: float,
                versions: Sequence[str] | None, part_number: str | None) -> list[T.VersionInfo]:
    if profile not in T.PROFILES:
        raise ValueError(f"unknown profile {profile!r}; known: {', '.join(T.PROFILES)}")
    if not 0 <= min_records <= max_records <= T.LIMITS["max_commands"]:
        raise ValueError(f"need 0 <= min_records <= max_records <= {T.LIMITS['max_commands']}")
    if not 0.0 < bound <= _max_bound():
        raise ValueError(f"bound must be in (0, {_max_bound():g}] mm (binary32 positions within tolerance)")
    unknown = [v for v in versions or () if v not in T.VERSION_BY_ID]
    if unknown:
        raise ValueError(f"unknown version(s) {', '.join(unknown)}; known: {', '.join(T.VERSION_BY_ID)}")
    chosen = [T.VERSION_BY_ID[v] for v in versions] if versions is not None else list(T.VERSIONS)
    if not chosen:
        raise ValueError("no version to draw from")
    if part_number is not None:
        for v in chosen:
            f = T.HEADERS[v.header].by_role("implant_descriptor")
            if f is None or not (part_number.isascii() and part_number.isprintable()) or " " in part_number \
                    or not 0 < len(part_number) <= f.size:
                raise ValueError(f"part number {part_number!r}: one printable ASCII word that fits the implant "
                                 f"descriptor of version {v.id}")
    return chosen


def models(*, versions: Sequence[str] | None = None, profile: str = "default", min_records: int = 0,
           max_records: int = 30, continuous: bool = True, bound: float = 1000.0, part_number: str | None = None,
           cutters: Mapping[str, tuple[float, ...]] | None = None) -> st.SearchStrategy[Cbf]:
    """Models of valid files (see the module doc), before the derived values are filled:
    records carry code and arguments only. ``seal(model, profile)`` gives the bytes."""
    chosen = _check_args(profile, min_records, max_records, bound, versions, part_number)
    rules = _rules()
    bound = _machine_bound(bound)

    @st.composite
    def build(draw: st.DrawFn) -> Cbf:
        version = _pick(draw, chosen)
        header = _header(draw, version, part_number)
        d = _Draw(draw, version.id, profile, bound, continuous, cutters, rules)
        pool = [(c, lay) for c, lay in _pool(version.id, profile) if d.usable(c, lay)]
        plain = [(c, lay) for c, lay in pool if c.shape is None]
        starts = [(c, lay) for c, lay in pool if c.shape is not None and c.shape["kind"] == "start"]
        ends = [(c, lay) for c, lay in pool if c.shape is not None and c.shape["kind"] == "end"]
        n = draw(st.integers(min_records, max_records))
        records: list[Record] = []
        while len(records) < n:
            left = n - len(records)
            if starts and ends and left >= 2 and draw(st.integers(0, 7)) == 0:
                records.extend(_shape(draw, d, plain, starts, ends, left))
            elif plain:
                cmd, lay = _pick(draw, plain)
                records.append(Record(code=cmd.code, raw_args=d.args(cmd, lay)))
            else:
                break
        return Cbf(header, tuple(records))

    return build()


def _shape(draw: st.DrawFn, d: _Draw, plain: list[tuple[T.CommandInfo, T.LayoutInfo]],
           starts: list[tuple[T.CommandInfo, T.LayoutInfo]], ends: list[tuple[T.CommandInfo, T.LayoutInfo]],
           left: int) -> list[Record]:
    """A shape: its start, records that declare as many motions as it encloses, its end."""
    scmd, slay = _pick(draw, starts)
    ecmd, elay = _pick(draw, ends)
    sh_s, sh_e = scmd.shape or {}, ecmd.shape or {}
    count_field = next(f for f in slay.args if f.name == sh_s["count"])
    name_field = next(f for f in slay.args if f.name == sh_s["name"])
    end_name = next(f for f in elay.args if f.name == sh_e["name"])
    most = min(left - 2, (1 << (8 * count_field.elem_size)) - 1)
    k = draw(st.integers(0, most)) if plain and most > 0 else 0
    inner = [_pick(draw, plain) for _ in range(k)]
    moves = sum(1 for c, _ in inner if c.motion is not None)
    if moves > (1 << (8 * count_field.elem_size)) - 1:
        inner, moves = [], 0
    name = draw(_word(min(name_field.size, end_name.size), d.profile, name_field.name)).encode("ascii")
    fixed = {sh_s["name"]: name, sh_s["count"]: moves}
    out = [Record(code=scmd.code, raw_args=d.args(scmd, slay, fixed))]
    out.extend(Record(code=c.code, raw_args=d.args(c, lay)) for c, lay in inner)
    out.append(Record(code=ecmd.code, raw_args=d.args(ecmd, elay, {sh_e["name"]: name, sh_e["count"]: moves})))
    return out


def cutfiles(*, versions: Sequence[str] | None = None, profile: str = "default", min_records: int = 0,
             max_records: int = 30, continuous: bool = True, bound: float = 1000.0, part_number: str | None = None,
             cutters: Mapping[str, tuple[float, ...]] | None = None) -> st.SearchStrategy[bytes]:
    """Valid CBF files (bytes): ``validate(data, profile=profile, part_number=part_number,
    cutters=cutters)`` finds nothing. Every version of the spec unless ``versions`` names
    some (ids such as "3.0"); floats within +-``bound`` mm; see the module doc."""
    return models(versions=versions, profile=profile, min_records=min_records, max_records=max_records,
                  continuous=continuous, bound=bound, part_number=part_number,
                  cutters=cutters).map(lambda m: seal(m, profile))


# -- mutation ---------------------------------------------------------------------------
Mutator = Callable[[st.DrawFn, bytearray], bytearray]


def _put(buf: bytearray, f: T.FieldInfo, base: int, value: int) -> None:
    if base + f.end <= len(buf):
        struct.pack_into(T.BO + f.fmt, buf, base + f.offset, value & ((1 << (8 * f.size)) - 1))


def _flip(draw: st.DrawFn, b: bytearray) -> bytearray:
    if b:
        i = draw(st.integers(0, len(b) - 1))
        b[i] ^= 1 << draw(st.integers(0, 7))
    return b


def _set_byte(draw: st.DrawFn, b: bytearray) -> bytearray:
    if b:
        b[draw(st.integers(0, len(b) - 1))] = draw(_BYTE)
    return b


def _truncate(draw: st.DrawFn, b: bytearray) -> bytearray:
    return b[:draw(st.integers(0, len(b)))]


def _delete(draw: st.DrawFn, b: bytearray) -> bytearray:
    i = draw(st.integers(0, len(b)))
    j = draw(st.integers(i, min(len(b), i + 64)))
    return b[:i] + b[j:]


def _insert(draw: st.DrawFn, b: bytearray) -> bytearray:
    i = draw(st.integers(0, len(b)))
    return b[:i] + draw(st.binary(min_size=1, max_size=32)) + b[i:]


def _records(b: bytearray) -> list[tuple[int, int]]:
    offsets, _ = frame(b) if len(b) >= T.HEADER_SIZE else ((), 0)
    return [(o, o + T.HEAD_SIZE + b[o + T.ARG_SIZE_OFFSET]) for o in offsets]


def _swap_records(draw: st.DrawFn, b: bytearray) -> bytearray:
    recs = _records(b)
    if len(recs) < 2:
        return b
    i = draw(st.integers(0, len(recs) - 2))
    j = draw(st.integers(i + 1, len(recs) - 1))
    (a0, a1), (b0, b1) = recs[i], recs[j]
    return b[:a0] + b[b0:b1] + b[a1:b0] + b[a0:a1] + b[b1:]


def _drop_or_repeat_record(draw: st.DrawFn, b: bytearray) -> bytearray:
    recs = _records(b)
    if not recs:
        return b
    s, e = recs[draw(st.integers(0, len(recs) - 1))]
    return b[:s] + b[e:] if draw(st.booleans()) else b[:e] + b[s:e] + b[e:]


def _lying_count(draw: st.DrawFn, b: bytearray) -> bytearray:
    _put(b, T.COUNT, 0, draw(_COUNT_LIE))
    return b


def _lying_size(draw: st.DrawFn, b: bytearray) -> bytearray:
    recs = _records(b)
    if recs:
        s, _ = recs[draw(st.integers(0, len(recs) - 1))]
        b[s + T.ARG_SIZE_OFFSET] = draw(_BYTE)
    return b


def _retag(draw: st.DrawFn, b: bytearray) -> bytearray:
    """A record's code (and its copy) set to another command's, or to an unknown code."""
    recs = _records(b)
    if recs:
        s, _ = recs[draw(st.integers(0, len(recs) - 1))]
        code = draw(_CODE)
        _put(b, T.RECORD_FIELDS[T.I_CODE], s, code)
        _put(b, T.RECORD_FIELDS[T.I_COPY], s, code)
    return b


def _version(draw: st.DrawFn, b: bytearray) -> bytearray:
    v = _pick(draw, T.VERSIONS)
    _put(b, T.VMAJOR, 0, v.major if draw(st.booleans()) else draw(st.integers(0, 255)))
    _put(b, T.VMINOR, 0, v.minor if v.minor is not None else draw(st.integers(0, 255)))
    return b


def _trailing(draw: st.DrawFn, b: bytearray) -> bytearray:
    return b + draw(st.binary(min_size=1, max_size=16))


MUTATORS: tuple[Mutator, ...] = (_flip, _set_byte, _truncate, _delete, _insert, _swap_records,
                                 _drop_or_repeat_record, _lying_count, _lying_size, _retag, _version, _trailing)


def reseal_checksums(data: bytes | bytearray, profile: str = "default") -> bytes:
    """Recompute the argument checksums (those among a command's arguments, then the head's) and
    the header checksums of whatever frames, and nothing else
    (a mutation then reaches the checks behind the checksums)."""
    b = bytearray(data)
    if len(b) < T.HEADER_SIZE:
        return bytes(b)
    offsets, _ = frame(b)
    _fill_records(b, offsets, head_sums=True)
    own = T.LAYOUT_CHECKSUM_FIELDS[header_info(b)[1].id]  # this version's header's checksum fields
    for tag in T.CHECKSUMS["fill_order"]:
        if tag in own:
            cov = T.PROFILES[profile]["file_coverages"][0] if tag == "file" else None
            alg = file_algorithm(profile) if tag == "file" else None
            _put(b, own[tag], 0, field_checksum(tag, b, offsets, cov, algorithm=alg))
    return bytes(b)


def mutations(files: st.SearchStrategy[bytes] | None = None, *, max_steps: int = 3,
              reseal: bool | None = None, profile: str = "default") -> st.SearchStrategy[bytes]:
    """Files from ``files`` (default ``cutfiles(profile=profile)``) changed by 1 to
    ``max_steps`` mutations: bit flips, byte replacements, truncation, deletion,
    insertion, swapped / dropped / repeated records, count and size fields that lie,
    retagged records, other versions, trailing bytes. ``reseal`` recomputes the
    checksums afterwards (so later checks are reached); ``None`` draws it."""
    source = files if files is not None else cutfiles(profile=profile)

    @st.composite
    def build(draw: st.DrawFn) -> bytes:
        b = bytearray(draw(source))
        for _ in range(draw(st.integers(1, max_steps))):
            b = _pick(draw, MUTATORS)(draw, b)
        do_reseal = draw(st.booleans()) if reseal is None else reseal
        return reseal_checksums(b, profile) if do_reseal else bytes(b)

    return build()


def _pack(lay: T.LayoutInfo, a: Mapping[str, Any]) -> bytes:
    """The argument bytes of the values ``a`` (strings padded, vectors and groups flattened)."""
    vals: list[Any] = []
    for f in lay.args:
        v = a[f.name]
        if f.kind == "string":
            v = v + T.PAD * (f.size - len(v))
        if f.per > 1:
            vals.extend(x for item in v for x in item)
        else:
            vals.extend(v if f.kind == "float" and f.count > 1 else [v])
    return lay.struct.pack(*vals)
