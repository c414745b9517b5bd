"""`cbfgen diff OLD.yaml NEW.yaml`: what a format revision changes, and what it breaks.

Both specs are loaded into the model (loader.load) and compared version by
version and command by command. Each change is in one of three classes:

- wire-breaking (BREAKING, `breaking`): it changes the wire meaning of a
  version that already exists in OLD: a file of that version, written or
  read by code generated from OLD, would mean something else (or be judged
  otherwise) under NEW;
- text-breaking (TEXT, `text_breaking`): every byte of OLD's versions keeps
  its meaning, but a name a user or a program writes changes: a CUT keyword
  or argument name, a JSON key, a C macro or struct member, a Python name
  (a command renamed with the same code and layouts -- when it keeps the
  old name in its `former_names`, readers of CUT and JSON, cbf.h and the
  Python package still accept the old name, and only what writers write
  changes (`old_name_reads`); an argument renamed
  at the same offset with the same type, a layout variant renamed, a
  check whose findings carry another id);
- neither. Adding a version, and anything inside a version that OLD does
  not have, is neither; those changes are listed relative to the version
  before it, so a reader sees what the new version changes.

`cbfgen diff` exits with the class of the worst change (EXIT_* below).

The same comparison of two versions of one spec (`version_steps`) builds
the docs' "Changes" page.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import sys
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from .loader import SpecError, load
from .model import CHECK_ATTRS, Check, Command, Coverage, Field, HeaderLayout, Layout, Spec

# `cbfgen diff`'s exit codes: the class of its worst change, or bad input.
EXIT_NONE, EXIT_WIRE, EXIT_BAD_INPUT, EXIT_TEXT, EXIT_UNVERIFIED = 0, 1, 2, 3, 4
EXIT_CODES = ((EXIT_NONE, "no change breaks anything"), (EXIT_WIRE, "wire-breaking (with or without text-breaking)"),
              (EXIT_BAD_INPUT, "usage, or a spec that does not load"), (EXIT_TEXT, "text-breaking only"),
              (EXIT_UNVERIFIED, "--witness: a wire-breaking change no file was found to show"))

# Attributes of a check that define what it judges (not its prose or line).
_CHECK_IGNORED = frozenset({"id", "severity", "text", "fails", "line", "clause", "decision"})
# Attributes of a profile that define what it accepts (not its prose).
_PROFILE_IGNORED = frozenset({"id", "doc", "hint_coverages"})
# Meta keys that define how bytes are read.
_WIRE_META = ("byte_order", "float_format", "string_encoding", "string_padding")


@dataclass(frozen=True)
class Change:
    """One change. version/command are None when the change is not tied to one."""

    kind: str
    version: str | None
    command: str | None
    detail: str
    breaking: bool  # wire-breaking
    text_breaking: bool = False  # a name changes, every byte keeps its meaning
    # a text-breaking rename whose old name still reads (a former name): writers write the new one
    old_name_reads: bool = False

    @property
    def impact(self) -> str:
        return "wire" if self.breaking else "text" if self.text_breaking else "none"

    def as_json(self) -> dict[str, Any]:
        return {**dataclasses.asdict(self), "impact": self.impact}


@dataclass(frozen=True)
class Diff:
    old: str
    new: str
    changes: tuple[Change, ...]

    @property
    def breaking(self) -> tuple[Change, ...]:
        """The wire-breaking changes."""
        return tuple(c for c in self.changes if c.breaking)

    @property
    def text_breaking(self) -> tuple[Change, ...]:
        """The text-breaking changes (a change is in one class: wire-breaking ones are not among them)."""
        return tuple(c for c in self.changes if c.impact == "text")

    @property
    def exit_code(self) -> int:
        return EXIT_WIRE if self.breaking else EXIT_TEXT if self.text_breaking else EXIT_NONE

    @property
    def impact(self) -> str:
        return "wire" if self.breaking else "text" if self.text_breaking else "none"

    def as_json(self) -> dict[str, Any]:
        return {"old": self.old, "new": self.new, "breaking": bool(self.breaking),
                "text_breaking": bool(self.text_breaking), "impact": self.impact, "exit": self.exit_code,
                "changes": [c.as_json() for c in self.changes]}

    def footer(self) -> str:
        if self.breaking:
            return (f"wire-breaking (exit {EXIT_WIRE}): a file of a version in OLD changes meaning or judgement "
                    "(BREAKING above)")
        if self.text_breaking and all(c.old_name_reads for c in self.text_breaking):
            return (f"text-breaking only (exit {EXIT_TEXT}): every byte of OLD's versions keeps its meaning; writers "
                    "write the new names (TEXT above), and readers of CUT and JSON, cbf.h and the Python package "
                    "still accept the former ones")
        if self.text_breaking:
            return (f"text-breaking only (exit {EXIT_TEXT}): every byte of OLD's versions keeps its meaning; names "
                    "in the CUT and JSON forms or the C and Python bindings change (TEXT above)")
        return (f"not breaking (exit {EXIT_NONE}): every version in OLD keeps its wire meaning and its names")

    def text(self) -> str:
        n, b, t = len(self.changes), len(self.breaking), len(self.text_breaking)
        lines = [f"cbfgen diff: {self.old} -> {self.new}: {n} change(s), {b} wire-breaking, {t} text-breaking"]
        for c in self.changes:
            mark = {"wire": "BREAKING", "text": "TEXT"}.get(c.impact, "")
            where = f"{c.version or 'all'} {c.command or '-'}"
            lines.append(f"  {mark:<8}  {where:<22} {c.kind}: {c.detail}")
        lines.append(self.footer())
        return "\n".join(lines) + "\n"


# -- descriptions ---------------------------------------------------------------
def _type_text(f: Field) -> str:
    text = f"{f.type}[{f.count}]" if f.count > 1 else f.type
    # a repeated group (issue 25, point 3): n items, n in min..max
    return text + (f" x n ({f.repeat[0]} <= n <= {f.repeat[1]})" if f.repeat is not None else "")


def describe_field(f: Field) -> str:
    return f"{f.name} ({_type_text(f)}, {f.size} byte(s) at offset {f.offset})"


def _layout_name(lay: Layout) -> str:
    return f"layout {lay.variant}" if lay.variant else "primary layout"


def _pair_name(o: Layout, n: Layout) -> str:
    return _layout_name(o) if o.variant == n.variant else f"{_layout_name(o)} -> {_layout_name(n)}"


def _coverage_text(cov: Coverage | None) -> str:
    if cov is None:
        return "(none)"
    parts = []
    for s in cov.segments:
        rng = f"{'' if s.start is None else s.start}..{'' if s.end is None else s.end}"
        ex = f" without {', '.join(s.exclude)}" if s.exclude else ""
        if s.region == "fields":  # named fields of each layout that carries it (issue 25, point 1)
            parts.append(f"fields({', '.join(s.fields)})")
            continue
        parts.append(f"{s.region}[{rng}]{ex}")
    return f"{cov.name} = " + " + ".join(parts)


# -- fields ---------------------------------------------------------------------
def compare_fields(old: Iterable[Field], new: Iterable[Field], version: str | None, command: str | None,
                   where: str, breaking: bool) -> list[Change]:
    """Fields matched by name, then unmatched ones by offset (a rename or a replacement)."""
    olds, news = list(old), list(new)
    out: list[Change] = []

    def add(kind: str, detail: str, names_only: bool = False) -> None:
        # A change of names only is text-breaking where a change of bytes would be wire-breaking.
        out.append(Change(kind, version, command, f"{where}: {detail}", breaking and not names_only,
                          breaking and names_only))

    new_by_name = {f.name: f for f in news}
    old_names = {f.name for f in olds}
    rest_old = [f for f in olds if f.name not in new_by_name]
    rest_new = [f for f in news if f.name not in old_names]
    for o in olds:
        n = new_by_name.get(o.name)
        if n is None:
            continue
        if o.offset != n.offset:
            add("field_moved", f"{o.name} moved from offset {o.offset} to {n.offset}")
        if o.size != n.size:
            add("field_resized", f"{o.name} resized from {o.size} to {n.size} byte(s)")
        if (o.type, o.count) != (n.type, n.count):
            add("field_retyped", f"{o.name} retyped from {_type_text(o)} to {_type_text(n)}")
        for attr, kind in (("unit", "field_unit_changed"), ("magic", "field_value_changed"),
                           ("role", "field_role_changed"), ("checksum", "field_role_changed"),
                           ("reserved", "field_role_changed"), ("text", "field_role_changed"),
                           ("repeat", "field_repeat_changed")):  # which nb a group takes: a file's judgement
            a, b = getattr(o, attr), getattr(n, attr)
            if a != b:
                add(kind, f"{o.name} {attr} changed from {a!r} to {b!r}")
    by_offset = {f.offset: f for f in rest_new}
    matched: set[str] = set()
    for o in rest_old:
        n = by_offset.get(o.offset)
        if n is None:
            add("field_removed", describe_field(o))
            continue
        matched.add(n.name)
        if (o.type, o.count, o.size) == (n.type, n.count, n.size):
            add("field_renamed", f"{o.name} renamed to {n.name} at offset {o.offset}, the same bytes (the CUT and "
                "JSON forms and the C and Python names change)", names_only=True)
        else:
            add("field_retyped", f"{describe_field(o)} replaced by {describe_field(n)}")
    for n in rest_new:
        if n.name not in matched:
            add("field_added", describe_field(n))
    return out


def _pair_layouts(old: tuple[Layout, ...], new: tuple[Layout, ...]) -> tuple[list[tuple[Layout, Layout]],
                                                                              list[Layout], list[Layout]]:
    """Pairs by variant name, then by size, then the last one left on each side."""
    pairs: list[tuple[Layout, Layout]] = []
    rest_o, rest_n = list(old), list(new)
    for key in ("variant", "size"):
        for o in list(rest_o):
            n = next((x for x in rest_n if getattr(x, key) == getattr(o, key)), None)
            if n is not None:
                pairs.append((o, n))
                rest_o.remove(o)
                rest_n.remove(n)
    if len(rest_o) == 1 and len(rest_n) == 1:
        pairs.append((rest_o.pop(), rest_n.pop()))
    return pairs, rest_o, rest_n


def _compare_layouts(old: tuple[Layout, ...], new: tuple[Layout, ...], version: str, command: str,
                     breaking: bool) -> list[Change]:
    out: list[Change] = []
    pairs, removed, added = _pair_layouts(old, new)
    for o, n in pairs:
        name = _pair_name(o, n)
        if o.variant != n.variant and breaking:
            # One version's layout under another variant name: its C and Python names change (between two
            # versions, as on the docs' "Changes" page, each version has its own layout: not a rename).
            out.append(Change("layout_variant_renamed", version, command,
                              f"{_layout_name(o)} renamed to {_layout_name(n)}", False, breaking))
        if o.size != n.size:
            out.append(Change("layout_resized", version, command,
                              f"{name}: argument size {o.size} -> {n.size} byte(s)", breaking))
        out += compare_fields(o.args, n.args, version, command, name, breaking)
        if set(o.profiles) != set(n.profiles):
            out.append(Change("layout_profiles_changed", version, command,
                              f"{name}: accepted under {list(o.profiles) or 'every profile'} -> "
                              f"{list(n.profiles) or 'every profile'}", breaking))
    for o in removed:
        out.append(Change("layout_removed", version, command, f"{_layout_name(o)} of {o.size} byte(s)", breaking))
    for n in added:
        out.append(Change("layout_added", version, command, f"{_layout_name(n)} of {n.size} byte(s)", breaking))
    return out


# -- one version against another ----------------------------------------------------
def _version_numbers(ov: Any, nv: Any, vid: str, same: bool, breaking: bool) -> list[Change]:
    out: list[Change] = []
    if (ov.major, ov.minor) != (nv.major, nv.minor) and same:
        out.append(Change("version_number_changed", vid, None,
                          f"header bytes match {ov.major}.{ov.minor} -> {nv.major}.{nv.minor}", breaking))
    if ov.writable != nv.writable and same:
        # Which versions the toolkit writes is policy, not the meaning of a file.
        out.append(Change("writable_changed", vid, None, f"writable {ov.writable} -> {nv.writable}", False))
    return out


def _gone(old: Spec, new: Spec, oc: Command, olays: tuple[Layout, ...], new_vid: str,
          breaking: bool) -> list[Change]:
    """A command of the old version that the new one lacks: renamed (the same code, a new name), or removed."""
    old_names = {c.name for c in old.commands}
    renamed = [c.name for c in new.commands if c.code == oc.code and c.name not in old_names
               and c.available_in(new_vid)]
    if not renamed:
        return [Change("command_removed", new_vid, oc.name, f"code 0x{oc.code:02X}", breaking)]
    # a rename that keeps the old name among the command's former names is no text break for
    # readers: CUT and JSON readers accept it, cbf.h and the Python package keep it as an alias
    keeps = oc.name in new.command(renamed[0]).former_names
    why = (f"{oc.name} stays a former name: CUT and JSON readers accept it, CBF_CMD_{oc.name} and "
           f"CommandCode.{oc.name} stay as deprecated aliases; writers write {renamed[0]}" if keeps else
           "the CUT keyword, the JSON form and the C and Python names change")
    return [Change("command_renamed", new_vid, oc.name,
                   f"{oc.name} renamed to {renamed[0]}, the same code 0x{oc.code:02X} ({why})", False,
                   breaking, keeps),
            *_compare_layouts(olays, new.command(renamed[0]).layouts_for(new_vid), new_vid, renamed[0], breaking)]


def _kept_or_gone(old: Spec, old_vid: str, new: Spec, new_vid: str, oc: Command, breaking: bool) -> list[Change]:
    """What became of one command of the old version in the new one."""
    olays = oc.layouts_for(old_vid)
    nc = next((c for c in new.commands if c.name == oc.name), None)
    nlays = nc.layouts_for(new_vid) if nc else ()
    if olays and not nlays:
        return _gone(old, new, oc, olays, new_vid, breaking)
    if not nlays or nc is None or not olays:
        return []  # not in either, or added (reported by _added)
    out: list[Change] = []
    if oc.code != nc.code:
        out.append(Change("command_code_changed", new_vid, oc.name,
                          f"code 0x{oc.code:02X} -> 0x{nc.code:02X}", breaking))
    return out + _compare_layouts(olays, nlays, new_vid, oc.name, breaking)


def _sizes(layouts: tuple[Layout, ...]) -> str:
    return "/".join(str(lay.size) if lay.repeated is None or lay.repeated.repeat is None else
                    f"{lay.size} + {lay.repeated.size} n ({lay.repeated.repeat[0]} <= n <= "
                    f"{lay.repeated.repeat[1]})" for lay in layouts)


def _added(old: Spec, old_vid: str, new: Spec, new_vid: str, breaking: bool) -> list[Change]:
    """The commands of the new version that the old one lacks (a rename is reported by _gone)."""
    old_cmds = {c.name: c for c in old.commands}
    new_names = {c.name for c in new.commands}
    out: list[Change] = []
    for nc in new.commands:
        was = old_cmds.get(nc.name)
        if not nc.available_in(new_vid) or (was is not None and was.available_in(old_vid)):
            continue
        if any(c.code == nc.code and c.available_in(old_vid) and c.name not in new_names for c in old.commands):
            continue  # a rename, reported above
        out.append(Change("command_added", new_vid, nc.name,
                          f"code 0x{nc.code:02X}, {_sizes(nc.layouts_for(new_vid))} argument byte(s)", breaking))
    return out


def compare_version(old: Spec, old_vid: str, new: Spec, new_vid: str, breaking: bool) -> list[Change]:
    """The header and command table of old_vid in OLD against new_vid in NEW, labelled new_vid."""
    out = _version_numbers(old.version(old_vid), new.version(new_vid), new_vid, old_vid == new_vid, breaking)
    out += _compare_header(old.header_for(old_vid), new.header_for(new_vid), new_vid, breaking)
    for oc in old.commands:
        out += _kept_or_gone(old, old_vid, new, new_vid, oc, breaking)
    return out + _added(old, old_vid, new, new_vid, breaking)


def _compare_header(oh: HeaderLayout, nh: HeaderLayout, vid: str, breaking: bool) -> list[Change]:
    out: list[Change] = []
    if oh.size != nh.size:
        out.append(Change("header_resized", vid, None, f"header size {oh.size} -> {nh.size} byte(s)", breaking))
    out += compare_fields(oh.fields, nh.fields, vid, None, "header", breaking)
    return out


# -- whole specs ----------------------------------------------------------------------
def _previous(spec: Spec, vid: str) -> str | None:
    """The version listed before vid in spec, if any."""
    ids = [v.id for v in spec.versions]
    i = ids.index(vid)
    return ids[i - 1] if i > 0 else None


def renames(old: Spec, new: Spec) -> dict[str, str]:
    """The commands renamed from OLD to NEW: an old name NEW lacks -> the new name NEW gives its code."""
    new_names, old_names = {c.name for c in new.commands}, {c.name for c in old.commands}
    out: dict[str, str] = {}
    for oc in old.commands:
        if oc.name not in new_names:
            nc = next((c for c in new.commands if c.code == oc.code and c.name not in old_names), None)
            if nc is not None:
                out[oc.name] = nc.name
    return out


def _renamed(value: Any, names: dict[str, str]) -> Any:
    """A check attribute of OLD with its command names as NEW spells them."""
    if isinstance(value, str):
        return names.get(value, value)
    if isinstance(value, tuple):
        return tuple(_renamed(v, names) for v in value)
    if dataclasses.is_dataclass(value) and not isinstance(value, type) and hasattr(value, "command"):
        return dataclasses.replace(value, command=names.get(value.command, value.command))
    return value


def _checks(old: Spec, new: Spec) -> list[Change]:
    out: list[Change] = []
    old_ids = {v.id for v in old.versions}
    new_by_id = {c.id: c for c in new.checks}
    names = renames(old, new)

    def applies_to_old(c: Check) -> bool:
        vs = getattr(c, "versions", ())
        if c.kind == "header_checksum" and c.checksum_field:  # the versions whose header has its field
            vs = new.checksum_versions(c.checksum_field)
            return any(v in old_ids for v in vs)
        return not vs or any(v in old_ids for v in vs)

    moved = _check_renames(old, new, names)
    for oc in old.checks:
        nc = new_by_id.get(oc.id)
        if nc is None and oc.id in moved:
            # the same check under another id: every file is judged the same, but findings name the new id
            out.append(Change("check_renamed", None, None, f"{oc.id} renamed to {moved[oc.id]} ({oc.kind}, "
                              f"{oc.severity}; findings name the new id)", False, True))
            continue
        if nc is None:
            out.append(Change("check_removed", None, None, f"{oc.id} ({oc.kind}, {oc.severity})",
                              oc.severity == "error"))
            continue
        if oc.severity != nc.severity:
            out.append(Change("check_severity_changed", None, None, f"{oc.id}: {oc.severity} -> {nc.severity}",
                              applies_to_old(nc)))
        for name in _judged_attrs(oc):
            a, b = getattr(oc, name), getattr(nc, name)
            if a != b:
                if _renamed(a, names) == b:  # the same check of a renamed command (reported as command_renamed)
                    out.append(Change("check_changed", None, None, f"{oc.id}: {name} {_short(a)} -> {_short(b)} "
                                      "(the renamed commands' new names)", False))
                    continue
                breaking = applies_to_old(nc) and "error" in (oc.severity, nc.severity)
                if name in ("versions", "commands") and oc.kind == nc.kind == "availability":
                    # new versions, commands: no
                    breaking = _covered(old, oc, old, {}) != _covered(old, nc, new, names)
                out.append(Change("check_changed", None, None, f"{oc.id}: {name} {_short(a)} -> {_short(b)}",
                                  breaking))
    old_by_id = {c.id for c in old.checks}
    for nc in new.checks:
        if nc.id not in old_by_id and nc.id not in moved.values():
            vs = getattr(nc, "versions", ())
            scope = f" for {', '.join(vs)}" if vs else ""
            out.append(Change("check_added", None, None, f"{nc.id} ({nc.kind}, {nc.severity}){scope}",
                              nc.severity == "error" and applies_to_old(nc) and not _only_gates_new(old, new, nc)))
    return out


def _judged_attrs(c: Check) -> list[str]:
    """The attributes of a check that define what it judges (not its id, severity, prose or line):
    its own and its kind's parameters, flat (model.CHECK_ATTRS)."""
    return [name for name in CHECK_ATTRS if name not in _CHECK_IGNORED]


def _judges(c: Check, names: dict[str, str]) -> tuple[Any, ...]:
    """What a check judges, and how severely (its id and prose aside), its command names as NEW spells them."""
    return (c.kind, c.severity, *(_renamed(getattr(c, name), names) for name in _judged_attrs(c)))


def _check_renames(old: Spec, new: Spec, names: dict[str, str]) -> dict[str, str]:
    """Old check id -> new id, for a check of OLD that NEW has under another id and nothing else changed."""
    gone = [c for c in old.checks if c.id not in {n.id for n in new.checks}]
    came = [c for c in new.checks if c.id not in {o.id for o in old.checks}]
    out: dict[str, str] = {}
    for oc in gone:
        same = [nc for nc in came if nc.id not in out.values() and type(nc) is type(oc)
                and _judges(nc, {}) == _judges(oc, names)]
        if len(same) == 1:
            out[oc.id] = same[0].id
    return out


def _covered(old: Spec, check: Check, spec: Spec, names: dict[str, str]) -> set[tuple[str, str]]:
    """The (version, command) pairs of OLD's versions and commands an availability check covers in spec, each
    command named as OLD names it (names: OLD's name -> spec's, for a renamed command)."""
    back = {n: o for o, n in names.items()}
    named = {back.get(x, x) for x in getattr(check, "commands", ()) or ()}
    old_ids = {v.id for v in old.versions}
    old_names = {c.name for c in old.commands}
    return {(v, back.get(c.name, c.name)) for v in check.versions if v in old_ids for c in spec.commands
            if back.get(c.name, c.name) in old_names and not c.available_in(v)
            and (not named or back.get(c.name, c.name) in named)}


def _only_gates_new(old: Spec, new: Spec, check: Check) -> bool:
    """An availability check that covers only commands OLD did not have in those versions (already errors there)."""
    if check.kind != "availability":
        return False
    named: tuple[str, ...] = tuple(getattr(check, "commands", ()) or ())
    vids = [v for v in check.versions if any(o.id == v for o in old.versions)]
    pairs = [(c.name, v) for c in new.commands for v in vids
             if not c.available_in(v) and (not named or c.name in named)]
    old_cmds = {c.name: c for c in old.commands}
    return not any(n in old_cmds and old_cmds[n].available_in(v) for n, v in pairs)


def _short(x: Any) -> str:
    if isinstance(x, tuple) and x and dataclasses.is_dataclass(x[0]):
        return repr([dataclasses.astuple(t) for t in x])
    return repr(list(x) if isinstance(x, tuple) else x)


def _checksums(old: Spec, new: Spec, breaking: bool) -> list[Change]:
    out: list[Change] = []
    ocs, ncs = old.checksums, new.checksums
    for of in ocs.fields:
        nf = next((f for f in ncs.fields if f.field == of.field), None)
        if nf is None:
            continue  # the loader requires all three
        if of.algorithm != nf.algorithm or ocs.algorithms[of.algorithm].kind != ncs.algorithms[nf.algorithm].kind:
            out.append(Change("checksum_algorithm_changed", None, None,
                              f"{of.field} checksum: {of.algorithm} -> {nf.algorithm}", breaking))
        ocov, ncov = ocs.coverages.get(of.coverage), ncs.coverages.get(nf.coverage)
        if _coverage_text(ocov).split(" = ")[-1] != _coverage_text(ncov).split(" = ")[-1]:
            out.append(Change("checksum_coverage_changed", None, None,
                              f"{of.field} checksum: {_coverage_text(ocov)} -> {_coverage_text(ncov)}", breaking))
    if ocs.fill_order != ncs.fill_order:
        # a new tag placed among the old ones (a new version's header checksum) changes no existing
        # file; the old tags in another order, or one dropped, do
        kept = [t for t in ncs.fill_order if t in ocs.fill_order]
        out.append(Change("checksum_fill_order_changed", None, None,
                          f"{list(ocs.fill_order)} -> {list(ncs.fill_order)}",
                          breaking and kept != list(ocs.fill_order)))
    return out


def _profiles(old: Spec, new: Spec) -> list[Change]:
    out: list[Change] = []
    new_by_id = {p.id: p for p in new.profiles}
    for op in old.profiles:
        np_ = new_by_id.get(op.id)
        if np_ is None:
            out.append(Change("profile_removed", None, None, op.id, True))
            continue
        for f in dataclasses.fields(op):
            if f.name in _PROFILE_IGNORED:
                continue
            a, b = getattr(op, f.name), getattr(np_, f.name)
            if f.name.endswith("coverages"):
                a = [_coverage_text(old.checksums.coverages.get(x)).split(" = ")[-1] for x in a]
                b = [_coverage_text(new.checksums.coverages.get(x)).split(" = ")[-1] for x in b]
            if a != b:
                kind = "profile_checksum_algorithm_changed" if "algorithm" in f.name else "profile_changed"
                out.append(Change(kind, None, None, f"profile {op.id}: {f.name} {_short(a)} -> {_short(b)}", True))
    old_ids = {p.id for p in old.profiles}
    for np_ in new.profiles:
        if np_.id not in old_ids:
            out.append(Change("profile_added", None, None, np_.id, False))
    return out


def diff(old: Spec, new: Spec, old_name: str = "OLD", new_name: str = "NEW") -> Diff:
    """Every change from old to new, by version and command; see the module doc for BREAKING."""
    out: list[Change] = []
    new_ids = {v.id for v in new.versions}
    old_ids = [v.id for v in old.versions]
    for key in _WIRE_META:
        if old.meta.get(key) != new.meta.get(key):
            out.append(Change("encoding_changed", None, None, f"meta.{key}: {old.meta.get(key)!r} -> "
                              f"{new.meta.get(key)!r}", True))
    if old.record.head_size != new.record.head_size:
        out.append(Change("record_head_resized", None, None,
                          f"record head {old.record.head_size} -> {new.record.head_size} byte(s)", True))
    out += compare_fields(old.record.fields, new.record.fields, None, None, "record head", True)
    out += _checksums(old, new, bool(set(old_ids) & new_ids))
    out += _profiles(old, new)
    for vid in old_ids:
        if vid not in new_ids:
            out.append(Change("version_removed", vid, None, f"files of {vid} are no longer read as {vid}", True))
            continue
        out += compare_version(old, vid, new, vid, True)
    for v in new.versions:
        if v.id in old_ids:
            continue
        prev = _previous(new, v.id)
        rel = f"; relative to {prev}" if prev else ""
        out.append(Change("version_added", v.id, None,
                          f"major {v.major}, minor {'any' if v.minor is None else v.minor}, "
                          f"writable {v.writable}{rel}", False))
        if prev is not None:
            out += compare_version(new, prev, new, v.id, False)
    out += _checks(old, new)
    if old.default_version != new.default_version:
        out.append(Change("default_version_changed", None, None,
                          f"{old.default_version} -> {new.default_version}", False))
    if old.fallback_version != new.fallback_version:
        out.append(Change("fallback_version_changed", None, None,
                          f"{old.fallback_version} -> {new.fallback_version}", False))
    for name in sorted(set(old.tolerances) | set(new.tolerances)):
        a, b = old.tolerances.get(name), new.tolerances.get(name)
        if a != b:
            out.append(Change("tolerance_changed", None, None, f"{name}: {a} -> {b}", False))
    out += _machine(old, new)
    if old.revision != new.revision:
        out.append(Change("revision_changed", None, None, f"{old.revision} -> {new.revision}", False))
    return Diff(old_name, new_name, tuple(out))


def _machine(old: Spec, new: Spec) -> list[Change]:
    """The machine limits (L1). The default machine's bounds only move warnings: not breaking. A
    limit added or removed, or another unit or axes, is: a machine file written for OLD is refused
    (or would be read in other units) under NEW, and its findings are errors."""
    out: list[Change] = []
    olim = {lim.name: lim for lim in old.machine.limits}
    nlim = {lim.name: lim for lim in new.machine.limits}
    for name in olim.keys() - nlim.keys():
        out.append(Change("machine_limit_removed", None, None, f"{name} ({olim[name].unit})", True))
    for name in nlim.keys() - olim.keys():
        out.append(Change("machine_limit_added", None, None, f"{name} ({nlim[name].unit})", True))
    for name in sorted(olim.keys() & nlim.keys()):
        a, b = olim[name], nlim[name]
        if (a.unit, a.axes) != (b.unit, b.axes):
            out.append(Change("machine_limit_changed", None, None,
                              f"{name}: unit {a.unit} -> {b.unit}, axes {list(a.axes)} -> {list(b.axes)}", True))
        if (a.min, a.max) != (b.min, b.max):
            out.append(Change("machine_default_changed", None, None,
                              f"{name}: {_short(list(a.min))}..{_short(list(a.max))} -> "
                              f"{_short(list(b.min))}..{_short(list(b.max))}", False))
    return out


def version_steps(spec: Spec) -> list[tuple[str, str, list[Change]]]:
    """(previous version, version, changes) for each version after the first, in spec order."""
    steps = []
    for v in spec.versions[1:]:
        prev = _previous(spec, v.id)
        assert prev is not None
        steps.append((prev, v.id, compare_version(spec, prev, spec, v.id, False)))
    return steps


def render(d: Diff, as_json: bool) -> str:
    return json.dumps(d.as_json(), indent=2) + "\n" if as_json else d.text()


def main(argv: list[str], witness: Callable[[tuple[Change, ...], Path, Path, Path], int] | None = None) -> int:
    """`cbfgen diff OLD NEW [--json] [--old-name NAME] [--witness DIR]`: the diff on stdout, the exit code
    of its worst class (``witness``: cbfgen.witness.run, which writes and verifies the files)."""
    codes = "; ".join(f"{code} {what}" for code, what in sorted(EXIT_CODES))
    ap = argparse.ArgumentParser(prog="cbfgen diff", description=(
        "List every change from OLD to NEW by version and command, and mark each change BREAKING when it changes "
        "the wire meaning of a version OLD already has (a file of that version means something else), or TEXT "
        "when every byte keeps its meaning but a name changes (a CUT keyword, a JSON key, a C or Python name: a "
        f"rename). Exit codes: {codes}."))
    ap.add_argument("old", help="the spec before the revision")
    ap.add_argument("new", help="the spec after the revision")
    ap.add_argument("--json", action="store_true",
                    help="one JSON document for tools (`impact` and `exit` say the class)")
    ap.add_argument("--old-name", help="name OLD by this in the output (default: its path)")
    if witness is not None:
        ap.add_argument("--witness", type=Path, metavar="DIR",
                        help="for each wire-breaking change, write to DIR the smallest file found that OLD's and "
                             "NEW's generated codecs read or judge differently (annotated hex, .cbf, a golden "
                             "expectation, a note of what each side says), verified by running both; for each "
                             "text-breaking one, the JSON and CUT text NEW writes and OLD refuses. A change no file "
                             f"shows: exit {EXIT_UNVERIFIED}, nothing written for it")
    try:
        args = ap.parse_args(argv)
    except SystemExit as exc:  # argparse: a usage error is bad input; --help is not
        return EXIT_BAD_INPUT if exc.code else EXIT_NONE
    try:
        old, new = load(args.old), load(args.new)
    except SpecError as exc:
        print(f"cbfgen diff: {exc}", file=sys.stderr)
        return EXIT_BAD_INPUT
    result = diff(old, new, args.old_name or args.old, args.new)
    sys.stdout.write(render(result, args.json))
    if witness is not None and args.witness is not None:
        code = witness(result.changes, Path(args.old), Path(args.new), args.witness)
        if code in (EXIT_UNVERIFIED, EXIT_BAD_INPUT):
            return code
    return result.exit_code
