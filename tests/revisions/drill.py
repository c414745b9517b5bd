"""The format-revision drill (issue 12, point 4): `make revision-drill`.

Each fixture tests/revisions/*.yaml is a small, patch-like revision of
spec/cbf.yaml: a list of edits addressed by path into the YAML (so it keeps
applying while unrelated parts of the spec change), the files the revision
adds (a golden case for a new check, a new expectation for a golden whose
meaning changes), and what `cbfgen diff` must say about it.

    python tests/revisions/drill.py apply FIXTURE ROOT     apply to the tree at ROOT
    python tests/revisions/drill.py run [--quick] [--together] [FIXTURE ...]

`run` copies the working tree (tracked and untracked files, not ignored
ones) into a temporary folder per fixture, applies the fixture there, and
runs, in order: `cbfgen diff` (the classification the fixture states),
`make revision` without its conformance (conformance/revise.py: `make
generate`, `make golden` (the golden .cbf re-assembled from their .hex: the
assembler follows the revised checksums; then the docs made from them
regenerated), a check that generated/ is fresh (the README's order leaves
nothing to regenerate), and every golden case judged as its expectation says:
a case the fixture judges differently without its new expectation fails,
with the proposed one shown), `make conformance`
(every binding), a commit of the revision (the copy is committed before the
fixture, as a clone is) and a check that it changed no file outside
REVISION_PATHS, and `make test` in the revised tree (CI=true: the README's
walkthrough ends there; it runs the quick drill there too, every fixture on
top of this revision, its own kind included).
`--quick` runs the subset `make test` uses (QUICK_BINDINGS, QUICK_TESTS and
quick_cases below; mk/revision.mk has the times); without FIXTURE it checks
each fixture's `cbfgen diff` alone and then applies them all to ONE tree, twice
over (QUICK_ROUNDS: each fixture then meets a tree holding its own revision),
where the steps run once (drill_together); `--together` does that with every
step in full (every fixture on top of the others, once).
It prints one line per step with its time and exits 1 when a step fails,
showing the end of that step's output.

Path syntax of an edit: keys separated by dots; `[N]` indexes a list,
`[key=value]` picks the list item whose key equals value, `[*]` every
item, `[key~=value]` the list items whose list `key` holds value. Operations:
    set      replace (or create) the value at path (`may_be_none: true`: at each place it selects,
             none when a key or [key=value] on the way selects nothing)
    merge    update the mapping at path with value
    append   append value to the list(s) at path
    extend_where   append value to every list at path that holds `contains` (at least one, unless
                   `may_be_none: true`)
    remove   delete the item at path, or, with value, remove value from every list at path
             that holds it (at least one)
    prune    drop the items of the list(s) at path whose `key` is empty
    sub      replace the regular expression `pattern` by value in the text at path
    append_line    (no path) append the line value to the text `file:` (a known-failure list)
    sub_text       (no path) replace `pattern` (a regular expression) by value in the text `file:`
    copy           set path to a copy of the value at `from`
    splice         replace the list item at path by the items of value
    insert         put the items of value into the list at path before its item `before` (else last)
    add_clause     (no path) the clause value = {number, text[, section]} a new check cites: its text under
                   meta.clauses and, when its section is new, the section (titled `section`) under meta.sections
An edit applies to spec/cbf.yaml unless it names another `file:` (an
expectation of a golden case, a binding's known-failure list; `optional:
true` skips it when that file is missing). `files:` maps new paths to their
text. Ids are never written by hand: `${...}` in a fixture is chosen for the
spec it applies to (the next free version, command code and clause, the
newest version, a command's code: `variables` and `render` below), so a
fixture applies on top of any spec, another fixture's result included.
"""

from __future__ import annotations

import argparse
import copy
import functools
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

# libyaml's parser (PyYAML's C binding) when present: the same values, about ten times faster.
_YAML_LOADER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)

REPO = Path(__file__).resolve().parents[2]
# The generator's package (cbfgen.registry names the checksum algorithms a fixture may choose): on the path when
# the drill is run as `.venv/bin/python tests/revisions/drill.py`, not only under make (which exports PYTHONPATH).
if str(REPO / "generator") not in sys.path:
    sys.path.append(str(REPO / "generator"))
HERE = Path(__file__).resolve().parent
SPEC = "spec/cbf.yaml"
_TOKEN = re.compile(r"\[([^\]]*)\]|([^.\[\]]+)")
# The quick drill leaves the drill's own test out (`make test` runs it in its own tree).
SELF_TESTS = ("tests/test_revision_drill.py",)
# What a revision made as the README says may change (issue 37, Done-when): the spec, what `make revision`
# generates and assembles (generated/, the golden .cbf files and the docs made from them), the golden cases and
# expectations a revision adds, the failure lists' entries, and the report its conformance writes (README, "Stage
# the revision"). The full drill commits the tree before the fixture and the revision after `make revision` and
# conformance (as the README's "commit, make test"), and fails on a file changed anywhere else.
REVISION_PATHS = ("spec/", "generated/", "conformance/golden/", "conformance/failures/", "conformance/report.json")
# The subset of `make test` (`--quick`), measured to keep `make test` under ten minutes on
# 2 cores: conformance of the bindings whose runtimes implement the checks and of one Kaitai
# parser (QUICK_BINDINGS; the full drill runs every binding), and the suites that read the
# spec, the codec, the CUT form, the docs and the golden cases (QUICK_TESTS; the full drill
# runs the whole suite).
QUICK_BINDINGS = ("python", "c", "kaitai-javascript")
# The fixtures whose kind of revision an in-tree test of `make test` already makes, on a revised
# copy of the spec, through generation and the bindings: the quick drill leaves them out
# (about 42 CPU s a fixture); `make revision-drill` drills every fixture.
IN_TREE = {"new_command": "tests/test_new_command.py", "checksum_profile": "tests/test_golden_checksums.py"}
QUICK_TESTS = ("tests/test_spec_loader.py", "tests/test_check_coverage.py", "tests/test_codec.py", "tests/test_cut.py",
               "tests/test_docs.py", "tests/test_golden_assembly.py", "tests/test_rev03_facts.py", "tests/test_cli.py")
# What the drill's own steps already did, so the quick drill does not do it twice: `make golden` has just
# written every .cbf from its .hex, so re-assembling them to compare (golden-check, and this test) cannot
# fail there (about 3 CPU s a fixture, most of it the 65,535-record case).
QUICK_DESELECT = ("tests/test_golden_assembly.py::test_reassembles_to_committed_bytes",)
# The quick drill's C testee keeps AddressSanitizer and UBSan but is compiled without optimisation: 2 CPU s
# instead of 6 a fixture (the main tree's testee, which conformance and reliability run, stays at -O1).
# The quick drill's conformance leaves out the golden files larger than this (quick_cases).
QUICK_MAX_BYTES = 256 * 1024
# The quick drill applies the fixtures twice over, the second round on top of the first: each fixture then meets a
# tree that holds its own revision, as `make test`'s quick drill does in a tree a real revision of that kind left
# (the README's walkthrough ends with `make test`). A fixture whose precondition its first round met says so and
# is left out (drill.unmet); the others choose new ids and add files of their own. About 1 CPU s more than one round.
QUICK_ROUNDS = 2
# The test of `make test` that checks each fixture's `cbfgen diff` alone (the quick drill does not repeat it).
DIFF_ALONE_TEST = "tests/test_revision_drill.py::test_cbfgen_diff_classifies_the_fixture"
QUICK_C_SAN = "C_SAN=-g0 -O0 -fsanitize=address,undefined -fno-sanitize-recover=all"

class FixtureError(Exception):
    """A fixture that does not apply: str() names the fixture, the edit and why."""


class FixtureUnmet(FixtureError):
    """A fixture whose stated precondition (`requires:`) the spec it meets does not hold, typically because that
    spec already holds what the fixture adds (a deprecation of a layout a revision already deprecated): the drill
    and the tests skip it there, saying why (str() names the fixture and the reason)."""


@dataclass(frozen=True)
class Fixture:
    name: str
    path: Path
    title: str
    adds: str
    breaking: bool  # wire-breaking
    text_breaking: bool  # text-breaking (a name changes, every byte keeps its meaning)
    expect: tuple[dict[str, Any], ...]
    edits: tuple[dict[str, Any], ...]
    files: dict[str, str]


def fixtures() -> list[Path]:
    return sorted(HERE.glob("*.yaml"))


def applicable(spec: dict[str, Any] | None = None, paths: list[Path] | None = None) -> list[Fixture]:
    """The fixtures (default: all) whose precondition spec holds (default: this tree's), loaded for it: a
    fixture whose `requires:` a revision already met (drill.unmet) is left out, not failed."""
    base = spec if spec is not None else read_spec(REPO / SPEC)
    out = []
    for path in paths if paths is not None else fixtures():
        try:
            out.append(load_fixture(path, base))
        except FixtureUnmet:
            continue
    return out


# A fixture's `requires:` block (a top-level key, to the next one): read and rendered alone, before the rest, so that
# a precondition naming what the spec lacks is said as unmet, not as a ${...} that names nothing.
_REQUIRES = re.compile(r"^requires:[^\n]*\n(?:(?:[ #][^\n]*)?\n)*", re.MULTILINE)


def unmet(path: Path, spec: dict[str, Any]) -> str | None:
    """Why the fixture at path does not apply to spec (a parsed spec/cbf.yaml), None when it does. A fixture
    states what its hand-written files assume of the spec in `requires:`, a list of:
        {layout: NAME[/variant], version: V}   the command (its layout `variant`) has a layout in version V
        {not_deprecated: NAME[/variant]}       no deprecating check names it (nor, for a layout, its command)
        {unranged: NAME}                       no range check judges the command's arguments, in any version
    Strings are rendered (${...}) for spec; a ${...} naming nothing there is itself the reason."""
    m = _REQUIRES.search(path.read_text(encoding="utf-8"))
    if m is None:
        return None
    try:
        items = yaml.load(render(m.group(0), spec, path.name), Loader=_YAML_LOADER)["requires"] or []
    except FixtureError as exc:
        return str(exc)
    cmds = {str(c["name"]): c for c in spec.get("commands", ())}
    for item in items:
        if "layout" in item:
            name, _, variant = str(item["layout"]).partition("/")
            version = str(item["version"])
            lays = [lay for lay in (cmds[name]["layouts"] if name in cmds else ())
                    if (not variant or lay.get("variant") == variant) and version in lay.get("versions", ())]
            if not lays:
                return f"the spec has no {item['layout']} layout in version {version}"
        elif "not_deprecated" in item:
            what = str(item["not_deprecated"])
            names = {what, what.partition("/")[0]}
            by = [str(c.get("id")) for c in spec.get("checks", ()) if c.get("kind") == "deprecated"
                  and names & {str(d) for d in c.get("deprecates", ())}]
            if by:
                return f"the spec already deprecates {what} (check {', '.join(by)})"
        elif "unranged" in item:
            what = str(item["unranged"])
            by = [str(c.get("id")) for c in spec.get("checks", ()) if c.get("kind") == "range"
                  and any(t.get("command") == what for t in c.get("targets", ()))]
            if by:
                return f"a range check already judges {what} (check {', '.join(by)})"
        else:
            raise FixtureError(f"{path.name}: requires: unknown condition {item!r}")
    return None


def load_fixture(path: Path, spec: dict[str, Any] | None = None) -> Fixture:
    """The fixture at path, its ${...} ids chosen for spec (a parsed spec/cbf.yaml; default this tree's).
    FixtureUnmet when spec does not hold the fixture's `requires:` (unmet)."""
    try:
        text = path.read_text(encoding="utf-8")
        base = spec if spec is not None else read_spec(REPO / SPEC)
        why = unmet(path, base)
        if why is not None:
            raise FixtureUnmet(f"{path.name}: skipped, its precondition does not hold: {why}")
        doc = yaml.load(render(text, base, path.name), Loader=_YAML_LOADER)
    except (OSError, yaml.YAMLError) as exc:
        raise FixtureError(f"{path}: {' '.join(str(exc).split())}") from None
    if not isinstance(doc, dict):
        raise FixtureError(f"{path}: not a mapping")
    missing = {"title", "adds", "breaking", "expect", "edits"} - set(doc)
    if missing:
        raise FixtureError(f"{path}: missing {', '.join(sorted(missing))}")
    return Fixture(path.stem, path, str(doc["title"]), " ".join(str(doc["adds"]).split()), bool(doc["breaking"]),
                   bool(doc.get("text_breaking", False)), tuple(doc["expect"]), tuple(doc["edits"]),
                   dict(doc.get("files") or {}))


def read_spec(path: Path) -> Any:
    return yaml.load(path.read_text(encoding="utf-8"), Loader=_YAML_LOADER)


# -- free ids -------------------------------------------------------------------
# A fixture names what it adds through ${...}, chosen for the spec it applies to, so that it applies on top
# of any spec: after a real revision, and after another fixture (the quick drill applies them one after the
# other to one tree). ${code:NAME} and ${dec:NAME} are a command's code in hex (two digits) and decimal;
# ${name:BASE} is BASE, or BASE_2, BASE_3 ... when a command already has that name, ${slug:BASE} the same in
# lower case (a golden file's name: the fixture applied on top of its own revision adds files of its own).
# ${version_with:NAME} and ${major_with:NAME}: the newest writable version whose files may hold the command
# (_version_with); ${unranged_version:NAME} and ${unranged_major:NAME} the same where no range check judges it.
_VAR = re.compile(r"\$\{([a-z][a-z0-9_]*)(?::([A-Za-z0-9_]+))?\}")
_FIRST_FREE_CODE = 0x70  # where the search for a free command code starts (the drill's PROBE)


# A golden file's source writes a record's code and its copy as one byte twice at the head of a line (`77 77 04 00`).
_GOLDEN_CODE = re.compile(r"^([0-9a-f]{2}) \1 [0-9a-f]{2} [0-9a-f]{2}\b", re.MULTILINE)


@functools.cache
def golden_codes() -> frozenset[int]:
    """The command codes the golden files' records hold, those of no command included (framing.unknown_command's
    is a code no command has): a fixture's new command takes none of them, so that no golden case changes meaning
    under it (its unknown code would become a known command of another size). Read once from this checkout's
    golden sources; a fixture's own golden files hold the codes of its own commands, which the spec then has."""
    return frozenset(int(m.group(1), 16) for hexfile in sorted((REPO / "conformance" / "golden").glob("*.hex"))
                     for m in _GOLDEN_CODE.finditer(hexfile.read_text("utf-8")))


@functools.cache
def fixture_commands() -> frozenset[str]:
    """The commands the fixtures' own golden files hold (each named by ${code:NAME}): a revision the drill makes never
    drops them from a version (new_version's ${drop})."""
    return frozenset(m.group(2) for path in fixtures() for m in _VAR.finditer(path.read_text(encoding="utf-8"))
                     if m.group(1) == "code" and m.group(2))


def _key(v: dict[str, Any]) -> tuple[int, int]:
    return int(v["major"]), int(v.get("minor") or 0)


def _has(cmd: dict[str, Any], vid: str) -> bool:
    return any(vid in lay.get("versions", ()) for lay in cmd.get("layouts", ()))


def _flow(items: list[str]) -> str:
    return json.dumps(items)


def _prose(items: list[str]) -> str:
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def variables(doc: dict[str, Any]) -> dict[str, str]:
    """The free ids and the facts a fixture may name, read from a parsed spec."""
    versions = list(doc["versions"])
    newest = max(versions, key=_key)
    nid = str(newest["id"])
    major = max(int(v["major"]) for v in versions) + 1
    cmds = list(doc["commands"])
    used_codes = {int(c["code"]) for c in cmds} | golden_codes()
    code = next(c for c in [*range(_FIRST_FREE_CODE, 256), *range(1, _FIRST_FREE_CODE)] if c not in used_codes)
    ids = {str(x.get(k)) for group in ("checks", "versions", "commands") for x in doc.get(group, ())
           for k in ("id", "clause")} | {str(lay.get("clause")) for c in cmds for lay in c.get("layouts", ())}
    ids |= {str(c.get("number")) for c in doc.get("meta", {}).get("clauses", ())}  # a clause the document has
    clause = next(f"9.{n}" for n in range(1, 1000) if f"9.{n}" not in ids)
    # The command a new version drops: the first of the newest version whose arguments are all f4 in one layout and
    # that no fixture's golden file holds (fixture_commands): applied again on top of its own revision, the fixture
    # drops another, and every other fixture's golden files still find their commands in the newest version.
    held_by_fixtures = fixture_commands()
    drop = next((c for c in cmds for lay in c["layouts"] if nid in lay["versions"] and c["name"] not in held_by_fixtures
                 and lay.get("args") and all(a.get("type") == "f4" for a in lay["args"])),
                None)
    drop_lay: dict[str, Any] = next((lay for lay in drop["layouts"] if nid in lay["versions"]), {}) if drop else {}
    drop_floats = sum(int(a.get("count", 1)) for a in drop_lay.get("args", ()))
    lacks = [str(c["name"]) for c in cmds if not _has(c, nid) or c is drop]
    writable = [str(v["id"]) for v in versions if v.get("writable")]
    unwritable = [v for v in versions if not v.get("writable")]
    older = max((v for v in versions if v is not newest), key=_key, default=newest)  # the newest but one
    out = {"newest_version": nid, "newest_major": str(newest["major"]), "newest_header": str(newest["header"]),
           "older_version": str(older["id"]), "older_major": str(older["major"]),
           "older_minor": str(older.get("minor") or 0),
           "newest_lacks": _flow([str(c["name"]) for c in cmds if not _has(c, nid)]),  # what a copy of it lacks
           "new_version": f"{major}.0", "new_major": str(major), "free_clause": clause, "free_code": str(code),
           "free_code_hex": f"{code:02x}", "writable": _flow(writable),
           "writable_with_new": _prose([*writable, f"{major}.0"]),
           "unwritable": _flow([str(v["id"]) for v in unwritable]),
           "gate_major": str(max((int(v["major"]) for v in unwritable), default=0)),
           "new_lacks": _flow(lacks), "new_lacks_text": _prose(lacks) if lacks else "nothing",
           "versions": _flow([str(v["id"]) for v in versions])}
    # The next decision of the toolkit's own (D9 today): a revision's prose may add one.
    taken = {str(d.get("id")) for d in doc.get("decisions", ())}
    out["free_decision"] = next(f"D{n}" for n in range(1, 1000) if f"D{n}" not in taken)
    # The next section of the document (8 today): a revision that opens a section of its own, with its clauses.
    sections = {str(s.get("id")) for s in doc.get("meta", {}).get("sections", ())}
    out["free_section"] = str(next(n for n in range(1, 1000) if str(n) not in sections and n > max(
        (int(s) for s in sections if s.isdigit()), default=0)))
    # The header of the newest version that still reserves the checksum bytes (4.2: offset 10, 6 bytes
    # "reserved for future checksum usage"), the newest header when none does.
    headers = doc.get("headers", {})
    reserving = [v for v in sorted(versions, key=_key, reverse=True)
                 if any(f.get("role") == "reserved" and f.get("offset") == 10 and f.get("size", 0) >= 4
                        for f in headers.get(v["header"], {}).get("fields", ()))]
    out["reserve_header"] = str(reserving[0]["header"]) if reserving else str(newest["header"])
    # The newest version whose header reserves those bytes, and the one before it: a fixture's golden
    # files written with _header_v3.inc (zeros there) name these, so that they hold on top of a
    # revision whose newest header fills a checksum there (header_crc).
    rv = reserving[0] if reserving else newest
    ro = reserving[1] if len(reserving) > 1 else older
    out.update({"reserve_version": str(rv["id"]), "reserve_major": str(rv["major"]),
                "reserve_older_version": str(ro["id"]), "reserve_older_major": str(ro["major"]),
                "reserve_older_minor": str(ro.get("minor") or 0)})
    # Another algorithm for the default profile's file checksum: the first of the spec's algorithms, in
    # its order, that is no plain sum, fills the file checksum field (else the first that fits it), and
    # is not the one the default profile uses now (so the revision changes it on any spec, its own
    # result included).
    from cbfgen.registry import ALGORITHMS  # noqa: PLC0415  (the drill runs with the generator on its path)

    checksums = doc.get("checksums", {})
    algorithms = checksums.get("algorithms", {})
    file_field: dict[str, Any] = next((f for f in checksums.get("fields", ()) if f.get("field") == "file"), {})
    default: dict[str, Any] = next((p for p in doc.get("profiles", ()) if p.get("id") == "default"), {})
    current = default.get("file_algorithm", file_field.get("algorithm"))
    width = 8 * next((int(doc["types"][f["type"]].get("size") or 0) for h in headers.values()
                      for f in h.get("fields", ()) if f.get("checksum") == "file"), 0)
    kinds = {n: ALGORITHMS.get(str(a.get("kind"))) for n, a in algorithms.items()}
    bits = {n: k.width or 0 for n, k in kinds.items() if k is not None and k.family != "sum" and n != current}
    other = sorted((n for n, b in bits.items() if 0 < b <= width), key=lambda n: bits[n] != width)  # full width first
    if other:
        out["other_file_algorithm"] = other[0]
    # The command whose layout in the newest version holds reserved bytes a layout change may turn into floats: 4 of
    # them (CUTTER's today) first, else the fewest that 4-byte floats tile (ORIENT's 12, VERSION's 16), so that a
    # revision that took CUTTER's leaves another. ${reserved4_count}, ${reserved4_zero}, ${reserved4_unit}: the floats.
    held = [(c, a) for c in cmds for lay in c["layouts"] if nid in lay["versions"] for a in lay.get("args", ())
            if a.get("reserved") and int(a.get("size") or 0) % 4 == 0 and a.get("size")]
    if held:
        c, a = min(held, key=lambda ca: int(ca[1]["size"]) != 4)
        n = int(a["size"]) // 4
        out.update({"reserved4_command": str(c["name"]), "reserved4_arg": str(a["name"]),
                    "reserved4_count": f", count: {n}" if n > 1 else "",
                    "reserved4_zero": _flow([0.0] * n) if n > 1 else "0.0",
                    "reserved4_unit": "mm" if n == 1 else "deg"})  # 3 x mm would be a position the machine bounds
    if drop is not None:
        out.update({"drop": str(drop["name"]), "drop_code": str(int(drop["code"])),
                    "drop_code_hex": f"{int(drop['code']):02x}", "drop_size_hex": f"{int(drop_lay['size']):02x}",
                    "drop_f32": " ".join(str(n) for n in range(1, drop_floats + 1))})
    out.update(_real_rename(doc))
    return out


# Where a command's name is its reference, not prose: its own entry and a check's targets (a rename edits both).
_NAME_SLOTS = {("commands", "name"), ("checks", "targets", "command")}


def _texts(node: Any, path: tuple[str, ...] = ()) -> Any:
    """(path of keys, text) for every string of a parsed spec but the names of _NAME_SLOTS."""
    if isinstance(node, dict):
        for k, v in node.items():
            yield from _texts(v, (*path, str(k)))
    elif isinstance(node, list):
        for v in node:
            yield from _texts(v, path)
    elif isinstance(node, str) and path not in _NAME_SLOTS:
        yield path, node


def _real_rename(doc: dict[str, Any]) -> dict[str, str]:
    """${real_rename}: the command a real rename (rename_real) takes, chosen from the model so that the fixture
    applies after any revision, itself included (it drops the old name, so no ${now:NAME} finds it again): the
    last command, in the spec's order, that every version has (no command a revision added, which golden cases of
    its own may name), with no former name (not the one rename.yaml renamed) and named by no text of the spec
    (only its entry and the checks' targets: a rename leaves no prose stale). LINE5B on rev 03. ${real_rename_to}:
    its new name (a 5B becomes _5AXIS, LINE_5AXIS on rev 03; else the name itself), the next free one (_2 ...)."""
    vids = [str(v["id"]) for v in doc["versions"]]
    names = [str(c["name"]) for c in doc["commands"]]
    texts = [t for _, t in _texts(doc)]

    def named(n: str) -> bool:
        word = re.compile(rf"(?<![A-Za-z0-9_]){re.escape(n)}(?![A-Za-z0-9_])")
        return any(word.search(t) for t in texts)

    pick = next((c for c in reversed(doc["commands"]) if all(_has(c, v) for v in vids) and not c.get("former_names")
                 and not named(str(c["name"]))), None)
    if pick is None:
        return {}
    old = str(pick["name"])
    base = old[:-2] + "_5AXIS" if old.endswith("5B") else old
    return {"real_rename": old,
            "real_rename_to": next(n for n in (base, *(f"{base}_{i}" for i in range(2, 100))) if n not in names)}


def _ranged(doc: dict[str, Any], name: str, vid: str) -> bool:
    """Whether a range check of the spec judges the command name's arguments in version vid."""
    return any(c.get("kind") == "range" and (c.get("versions") is None or vid in c["versions"])
               and any(t.get("command") == name for t in c.get("targets", ())) for c in doc.get("checks", ()))


def _version_with(doc: dict[str, Any], name: str, unranged: bool = False) -> dict[str, Any]:
    """The newest writable version that has the command name and whose header reserves the checksum bytes (a golden
    file written with _header_v3.inc holds zeros there), else the newest writable one that has it: a fixture's
    golden file of such a version holding the command stays valid after a revision that drops it from a new
    version (a 5.0 without POINT). unranged: only a version where no range check judges the command's arguments
    (${unranged_version:NAME}: a fixture bounding them there meets no other bound, its own of an earlier
    application included, and no golden file another bound there made)."""
    cmd = next(c for c in doc["commands"] if c["name"] == name)
    headers = doc.get("headers", {})
    ranked = sorted((v for v in doc["versions"] if v.get("writable") and _has(cmd, str(v["id"]))
                     and not (unranged and _ranged(doc, name, str(v["id"])))), key=_key, reverse=True)
    reserving = [v for v in ranked if any(f.get("role") == "reserved" and f.get("offset") == 10
                                          and f.get("size", 0) >= 4
                                          for f in headers.get(v["header"], {}).get("fields", ()))]
    if not ranked:
        raise FixtureError(f"no writable version has {name}" + (" unjudged by a range check" if unranged else ""))
    return reserving[0] if reserving else ranked[0]


def _drill_revision(doc: dict[str, Any], where: str) -> str:
    """${drill_revision}: the name a fixture gives its revision (meta.revision), from the spec's own: its revision
    before any drill suffix, then "-drill-" and the fixture's name ("03-drill-new-command" on rev 03, "04-drill-..."
    after a real revision 04), and "-again" when the spec already bears that name (the fixture applied on top of
    its own result, as the drill's tests do in its revised tree: a revision names itself anew)."""
    current = str(doc.get("meta", {}).get("revision", ""))
    name = f"{current.split('-drill-')[0]}-drill-{Path(where).stem.replace('_', '-')}"
    return name if name != current else f"{name}-again"


def render(text: str, doc: dict[str, Any], where: str) -> str:
    """text with each ${...} replaced by its value for the spec doc (FixtureError for an unknown one)."""
    values = variables(doc)
    by_name = {str(c["name"]): int(c["code"]) for c in doc["commands"]}
    had = {str(n) for c in doc["commands"] for n in c.get("former_names", ())}

    def one(m: re.Match[str]) -> str:
        var, arg = m.group(1), m.group(2)
        if arg is None and var in values:
            return values[var]
        if var in ("code", "dec") and arg in by_name:
            return f"{by_name[arg]:02x}" if var == "code" else str(by_name[arg])
        if var == "drill_revision" and arg is None:  # what the fixture names its revision (meta.revision)
            return _drill_revision(doc, where)
        if var in ("name", "slug") and arg is not None:  # slug: the name in lower case, for a golden file's name
            # free of every name a command has or had (a former name stays a command's: a rename on top of its own
            # revision never takes back the name it gave up)
            name = next(n for n in (arg, *(f"{arg}_{i}" for i in range(2, 100))) if n not in by_name and n not in had)
            return name if var == "name" else name.lower()
        if var in ("version_with", "major_with") and arg in by_name:  # a version whose files may hold the command
            v = _version_with(doc, arg)
            return str(v["id"]) if var == "version_with" else str(v["major"])
        if var in ("unranged_version", "unranged_major") and arg in by_name:  # ... and no range check judges it in
            v = _version_with(doc, arg, unranged=True)
            return str(v["id"]) if var == "unranged_version" else str(v["major"])
        if var in ("now", "formerly") and arg is not None:  # a command as the spec calls it now, and its past names
            cmd = next((c for c in doc["commands"] if c["name"] == arg or arg in c.get("former_names", ())), None)
            if cmd is not None:
                past = [str(n) for n in cmd.get("former_names", ())]
                past += [] if cmd["name"] in past else [str(cmd["name"])]
                return str(cmd["name"]) if var == "now" else _flow(past)
        raise FixtureError(f"{where}: {m.group(0)} names nothing in this spec")

    out = _VAR.sub(one, text)
    if "${" in out:
        raise FixtureError(f"{where}: {out[out.index('${'):].split(chr(10))[0]!r}: not a ${{name}} or ${{name:ARG}}")
    return out


# -- edits ----------------------------------------------------------------------
def _tokens(path: str) -> list[str]:
    out = []
    for m in _TOKEN.finditer(path):
        out.append(f"[{m.group(1)}]" if m.group(1) is not None else m.group(2))
    return out


def _step(node: Any, tok: str, where: str, lenient: bool = False) -> list[tuple[Any, Any]]:
    """The (container, key) pairs tok selects in node (lenient: none when a selector picks nothing)."""
    if tok.startswith("["):
        sel = tok[1:-1]
        if not isinstance(node, list):
            raise FixtureError(f"{where}: {tok} needs a list")
        if sel == "*":
            return [(node, i) for i in range(len(node))]
        if "~=" in sel:  # the items whose list `key` holds value
            key, value = sel.split("~=", 1)
            hits = [(node, i) for i, item in enumerate(node) if isinstance(item, dict)
                    and value in [str(x) for x in item.get(key) or ()]]
            if not hits:
                raise FixtureError(f"{where}: no item whose {key} holds {value}")
            return hits
        if "=" in sel:
            key, value = sel.split("=", 1)
            hits = [(node, i) for i, item in enumerate(node) if isinstance(item, dict) and str(item.get(key)) == value]
            if not hits and not lenient:
                raise FixtureError(f"{where}: no item with {key}={value}")
            return hits
        return [(node, int(sel))]
    if not isinstance(node, dict):
        raise FixtureError(f"{where}: key {tok!r} needs a mapping")
    return [(node, tok)]


def _resolve(root: Any, path: str, lenient: bool = False) -> list[tuple[Any, Any]]:
    """The (container, key) pairs path selects; lenient (an edit's `may_be_none: true`): a key a node lacks on the
    way, or a [key=value] no item matches, selects nothing there instead of failing."""
    toks = _tokens(path)
    if not toks:
        raise FixtureError("empty path")
    slots: list[tuple[Any, Any]] = [(None, None)]
    nodes = [root]
    for i, tok in enumerate(toks):
        where = "".join(t if t.startswith("[") or j == 0 else "." + t for j, t in enumerate(toks[: i + 1]))
        slots = [s for n in nodes for s in _step(n, tok, where, lenient)]
        if i < len(toks) - 1:
            nodes = []
            for c, k in slots:
                try:
                    nodes.append(c[k])
                except (KeyError, IndexError):
                    if lenient:
                        continue
                    raise FixtureError(f"{where}: not found") from None
    return slots


def add_clause(root: Any, value: dict[str, Any]) -> None:
    """What the document needs for a clause a new check (or history entry) cites: its text under meta.clauses
    and, when its section is new, the section under meta.sections (titled `section`, default "Revisions")."""
    meta = root["meta"]
    number = str(value["number"])
    sid = number.split(".")[0]
    if not any(str(s.get("id")) == sid for s in meta["sections"]):
        meta["sections"].append({"id": sid, "title": str(value.get("section") or "Revisions")})
    if any(str(c.get("number")) == number for c in meta["clauses"]):
        raise FixtureError(f"add_clause: clause {number} is already in meta.clauses")
    meta["clauses"].append({k: v for k, v in value.items() if k != "section"})


def apply_edit(root: Any, edit: dict[str, Any]) -> None:
    op, path = edit.get("op"), str(edit.get("path", ""))
    if op == "add_clause":
        add_clause(root, copy.deepcopy(edit["value"]))
        return
    slots = _resolve(root, path, lenient=op == "set" and bool(edit.get("may_be_none")))
    value: Any = copy.deepcopy(edit.get("value"))  # never the fixture's own object: a later edit may change it in place
    if op == "set":
        for c, k in slots:
            c[k] = value
    elif op == "merge":
        for c, k in slots:
            c[k].update(value)
    elif op == "append":
        for c, k in slots:
            c[k].append(value)
    elif op == "append_new":  # unless an item with the same `key` is there (a section a revision may have added)
        for c, k in slots:
            if not any(isinstance(x, dict) and x.get(edit["key"]) == value[edit["key"]] for x in c[k]):
                c[k].append(value)
    elif op == "extend_where":
        hits = 0
        for c, k in slots:
            if edit["contains"] in c[k] and value not in c[k]:
                c[k].append(value)
                hits += 1
        if not hits and not edit.get("may_be_none"):  # may_be_none: what the newest version lacks, maybe nothing
            raise FixtureError(f"{path}: no list holds {edit['contains']!r}")
    elif op == "remove":
        if "value" in edit:  # from every list at path that holds it (at least one)
            held = [(c, k) for c, k in slots if value in c[k]]
            if not held:
                raise FixtureError(f"{path}: {value!r} is not there")
            for c, k in held:
                c[k].remove(value)
        else:
            for c, k in sorted(slots, key=lambda s: s[1] if isinstance(s[1], int) else 0, reverse=True):
                del c[k]
    elif op == "copy":  # the value at `from` (its first match), e.g. a new header layout from the newest one
        src = _resolve(root, str(edit["from"]))[0]
        for c, k in slots:
            c[k] = copy.deepcopy(src[0][src[1]])
    elif op == "splice":  # one list item replaced by the items of value (reserved bytes become fields)
        for c, k in sorted(slots, key=lambda s: s[1] if isinstance(s[1], int) else 0, reverse=True):
            c[k:k + 1] = copy.deepcopy(value)
    elif op == "insert":  # the items of value put into the list at path before its item `before`
        for c, k in slots:
            at = c[k].index(edit["before"]) if edit["before"] in c[k] else len(c[k])
            c[k][at:at] = copy.deepcopy(value)
    elif op == "prune":  # drop the items of the list(s) at path whose `key` is empty (a layout left no version)
        for c, k in slots:
            c[k][:] = [item for item in c[k] if not (isinstance(item, dict) and not item.get(edit["key"]))]
    elif op == "sub":  # a regular-expression replacement in the text at path
        for c, k in slots:
            text, n = re.subn(str(edit["pattern"]), str(value), str(c[k]))
            if not n:
                raise FixtureError(f"{path}: {edit['pattern']!r} does not match")
            c[k] = text
    else:
        raise FixtureError(f"{path}: unknown op {op!r}")


# libyaml's emitter when present: the same text as yaml.safe_dump on the spec and every revised spec, about five
# times faster (0.03 against 0.17 CPU s for spec/cbf.yaml; test_revision_drill writes a spec per fixture pair).
_YAML_DUMPER = getattr(yaml, "CSafeDumper", yaml.SafeDumper)


def _dump(doc: Any) -> str:
    return str(yaml.dump(doc, Dumper=_YAML_DUMPER, sort_keys=False, width=1000, allow_unicode=False))


def apply(fx: Fixture, root: Path) -> None:
    """Apply fx, its ids chosen for the spec at root, to the tree at root: the spec, the YAML files it edits,
    the files it adds. An edit of another file marked `optional: true` is skipped when that file is missing
    (a golden case of a version the spec at root does not have)."""
    fx = load_fixture(fx.path, read_spec(root / SPEC))
    # A file the fixture adds names what it is for by ids chosen for this spec (${free_clause}, ${name:...}): one
    # the tree already holds (a fixed name, on a tree that holds this fixture's own revision) would be overwritten.
    taken = sorted(rel for rel in fx.files if (root / rel).exists())
    if taken:
        raise FixtureError(f"{fx.path.name}: adds {', '.join(taken)}, which the tree already holds: name an added "
                           "file by the ids the fixture chooses for the spec")
    docs: dict[str, Any] = {}
    for i, edit in enumerate(fx.edits):
        rel = str(edit.get("file", SPEC))
        if rel != SPEC and edit.get("optional") and not (root / rel).exists():
            continue
        if edit.get("op") == "append_line":  # a line of a text file (a binding's known-failure list)
            line = str(edit["value"]).rstrip("\n")
            if (root / rel).exists() and line in (root / rel).read_text(encoding="utf-8").splitlines():
                raise FixtureError(f"{fx.path.name}: edit {i + 1} ({rel}): the line {line!r} is already there")
            with (root / rel).open("a", encoding="utf-8") as fh:
                fh.write(line + "\n")
            continue
        if edit.get("op") == "sub_text":  # a regular-expression replacement in a text file (a failure list)
            text = (root / rel).read_text(encoding="utf-8")
            text, n = re.subn(str(edit["pattern"]), str(edit["value"]), text, flags=re.MULTILINE)
            if not n:
                raise FixtureError(f"{fx.path.name}: edit {i + 1} ({rel}): {edit['pattern']!r} does not match")
            (root / rel).write_text(text, encoding="utf-8")
            continue
        if rel not in docs:
            docs[rel] = read_spec(root / rel)
        try:
            apply_edit(docs[rel], edit)
        except FixtureError as exc:
            raise FixtureError(f"{fx.path.name}: edit {i + 1} ({rel}): {exc}") from None
    for rel, doc in docs.items():
        head = f"# Revised by tests/revisions/{fx.path.name}: {fx.title}\n"
        (root / rel).write_text(head + _dump(doc), encoding="utf-8")
    for rel, text in fx.files.items():
        (root / rel).parent.mkdir(parents=True, exist_ok=True)
        (root / rel).write_text(text, encoding="utf-8")


def revised_spec(fx: Fixture, base: Path, out: Path, parsed: Any = None) -> Path:
    """The spec at base, revised by fx (its ids chosen for base), written to out/cbf.yaml (no other file).
    parsed: read_spec(base) when the caller has it (a copy of its own: it is edited)."""
    doc = read_spec(base) if parsed is None else parsed
    fx = load_fixture(fx.path, doc)
    for i, edit in enumerate(fx.edits):
        if str(edit.get("file", SPEC)) == SPEC:
            try:
                apply_edit(doc, edit)
            except FixtureError as exc:
                raise FixtureError(f"{fx.path.name}: edit {i + 1}: {exc}") from None
    out.mkdir(parents=True, exist_ok=True)
    path = out / "cbf.yaml"
    path.write_text(_dump(doc), encoding="utf-8")
    return path


def check_diff(fx: Fixture, base: Path, revised: Path, python: str = sys.executable) -> list[str]:
    """What is wrong with `cbfgen diff base revised --json` for fx; empty when it says what fx expects."""
    fx = load_fixture(fx.path, read_spec(base))  # what it expects, its ids chosen for base
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(REPO / "generator"), os.environ.get("PYTHONPATH", "")]))
    res = subprocess.run([python, "-m", "cbfgen", "diff", str(base), str(revised), "--json"], capture_output=True,
                         text=True, env=env, cwd=REPO)
    if res.returncode not in (0, 1, 3):
        return [f"cbfgen diff exit {res.returncode}: {res.stderr.strip()}"]
    return judge(fx, res.returncode, json.loads(res.stdout))


def judge(fx: Fixture, code: int, doc: dict[str, Any]) -> list[str]:
    """What is wrong with cbfgen diff's exit code and JSON document for fx (its ids chosen for the spec the
    diff starts from); empty when they say what fx expects."""
    problems = []
    exit_code = 1 if fx.breaking else 3 if fx.text_breaking else 0
    if code != exit_code or doc["breaking"] != fx.breaking or (fx.text_breaking and not doc["text_breaking"]):
        problems.append(f"expected {_verdict(fx)} (exit {exit_code}), cbfgen diff exit {code}")
    for want in fx.expect:
        if not any(all(c.get(k) == v for k, v in want.items()) for c in doc["changes"]):
            problems.append(f"no change {want}")
    return problems


def _verdict(fx: Fixture) -> str:
    return "wire-breaking" if fx.breaking else "text-breaking" if fx.text_breaking else "not breaking"


# -- the drill --------------------------------------------------------------------
def copy_tree(dest: Path) -> None:
    """The working tree (tracked and untracked, not ignored) with mtimes, and links to .venv and node_modules."""
    listed = subprocess.run(["git", "ls-files", "-z", "-co", "--exclude-standard"], cwd=REPO, check=True,
                            capture_output=True).stdout.decode().split("\0")
    for rel in listed:
        src = REPO / rel
        if rel and src.is_symlink():  # a tracked link (schemas/ links into the runtime): the same link
            (dest / rel).parent.mkdir(parents=True, exist_ok=True)
            (dest / rel).symlink_to(os.readlink(src))
            continue
        if not rel or not src.is_file():
            continue
        (dest / rel).parent.mkdir(parents=True, exist_ok=True)
        try:
            shutil.copy2(src, dest / rel)
        except FileNotFoundError:  # an untracked file another step of `make -j test` just removed
            continue
    for link in (".venv", "node_modules"):
        if (REPO / link).exists():
            (dest / link).symlink_to(REPO / link)
    jars = REPO / "build" / "kaitai-java" / "lib"  # Maven's download, not a product of the spec
    if jars.is_dir():
        shutil.copytree(jars, dest / "build" / "kaitai-java" / "lib")


def quick_cases(root: Path) -> list[str]:
    """The golden cases the quick drill's conformance runs, named whole: every case of the tree at root but the
    large files (over QUICK_MAX_BYTES, the 65,535-record case: most of the conformance time, and run by the main
    tree's conformance and the full drill). Sized before the drill's `make golden` rewrites them; a case the
    fixture adds, with no .cbf yet, is run."""
    golden = root / "conformance" / "golden"
    names = sorted(p.name[: -len(".expect.yaml")] for p in golden.glob("*.expect.yaml"))
    return [n for n in names if not (golden / f"{n}.cbf").exists() or (golden / f"{n}.cbf").stat().st_size
            <= QUICK_MAX_BYTES]


# The links copy_tree makes to this checkout's .venv and node_modules are not the revision's files.
_GIT = "git -c user.name=drill -c user.email=drill@localhost -c commit.gpgsign=false"
BASE_SH = (f"git init -q && printf '/.venv\\n/node_modules\\n' >> .git/info/exclude && git add -A && "
           f"{_GIT} commit -q --no-verify -m 'the tree before the revision'")
COMMIT_SH = f"git add -A && {_GIT} commit -q --no-verify --allow-empty -m 'the revision'"


def outside(root: Path) -> int:
    """`drill.py outside ROOT`: the files the last commit of the tree at ROOT (the revision) changed, by area;
    exit 1 when one lies outside REVISION_PATHS."""
    names = subprocess.run(["git", "diff", "--name-only", "HEAD~1", "HEAD"], cwd=root, check=True,
                           capture_output=True, text=True).stdout.split()
    bad = [n for n in names if not n.startswith(REVISION_PATHS)]
    areas = {a: sum(n.startswith(a) for n in names) for a in REVISION_PATHS}
    print("changed: " + ", ".join(f"{a} {k}" for a, k in areas.items() if k) + f"; elsewhere {len(bad)}")
    for n in bad:
        print(f"  outside {', '.join(REVISION_PATHS)}: {n}")
    return 1 if bad else 0


Step = tuple[str, list[str], dict[str, str]]  # (what, argv, extra environment)


def _steps(root: Path, quick: bool, keep_going: bool = False) -> list[Step]:
    make = ["make", "-C", str(root), "-o", ".venv/.stamp", "-o", "node_modules/.stamp"]
    env = {"PYTHONPATH": os.pathsep.join(str(root / p) for p in ("generator", "generated/python", "."))}
    py = str(REPO / ".venv" / "bin" / "python") if (REPO / ".venv").exists() else sys.executable
    tests = [t for t in QUICK_TESTS if (root / t).exists()]
    pytest = [py, "-m", "pytest", "-p", "no:cacheprovider", "-q", *([] if keep_going else ["-x"]), *tests,
              *(f"--ignore={t}" for t in SELF_TESTS), *(f"--deselect={t}" for t in QUICK_DESELECT)]
    if quick:
        runner = [py, "-m", "conformance.runner", "--report", str(root / "build" / "drill-report.json"),
                  *(a for b in QUICK_BINDINGS for a in ("--binding", b)),
                  *(a for c in quick_cases(root) for a in ("--case", c))]
        conformance = [("build C testee", [*make, QUICK_C_SAN, "build/c/cbf_testee"], {}),
                       (f"conformance ({', '.join(QUICK_BINDINGS)}; files up to {QUICK_MAX_BYTES // 1024} KiB)",
                        runner, env)]
    else:
        conformance = [("conformance (every binding)", [*make, "conformance"], {})]
    # The README's walkthrough, `make revision` (conformance/revise.py): generate, then golden, leaves generated/
    # fresh (make has nothing to regenerate), and the fixture gave every golden case it judges differently its new
    # expectation (else the proposed ones are shown and the step fails). Conformance is the drill's own step.
    revision: Step = ("make revision (generate, golden, generated/ fresh, expectations)",
                [py, "-m", "conformance.revise", "--no-conformance", *(f"--make-arg={a}" for a in make[3:])], env)
    # The copy is a checkout of the tree before the revision (drill: BASE_SH); the revision, regenerated, is
    # committed as the README says before `make test` (the full suite reads what git tracks: test_python_dist's
    # `git ls-files generated`, test_revision_drill's `make breaking BASE=HEAD`), and it changed no file outside
    # REVISION_PATHS.
    index: list[Step] = [] if quick else [
        ("commit the revision (git add -A, git commit)", ["sh", "-c", COMMIT_SH], {}),
        ("no file changed outside " + ", ".join(REVISION_PATHS), [py, str(Path(__file__).resolve()), "outside",
                                                                  str(root)], {})]
    # Then `make test` in the revised tree, as the README's walkthrough ends and as a fresh clone's CI runs it (CI=true,
    # no stdin): every check, the quick drill there (every fixture on top of this revision, its own kind included),
    # lint, the docs and the browser check, reliability, the report git holds. The quick drill runs its subset.
    last: Step = (("pytest (subset)", pytest, env) if quick else
                  ("make test (CI=true)", [*make, "test"], {"CI": "true"}))
    return [revision, *conformance, *index, last]


_FAILED = re.compile(r"^FAILED |^ERROR |\*\*\* |^E  |: error:|FAIL ")


def _run_steps(root: Path, quick: bool, keep_going: bool) -> bool:
    """The steps of _steps in the tree at root, a line each; False at the first that fails (its output's end shown)."""
    for name, cmd, extra in _steps(root, quick, keep_going):
        t = time.monotonic()
        env = dict(os.environ, **extra)
        for var in ("MAKEFLAGS", "MAKELEVEL", "MFLAGS"):
            env.pop(var, None)
        res = subprocess.run(cmd, cwd=root, env=env, capture_output=True, text=True, stdin=subprocess.DEVNULL)
        good = res.returncode == 0
        print(f"  {'ok' if good else 'FAIL':<4} {name} ({time.monotonic() - t:.1f} s)", flush=True)
        if not good:
            lines = (res.stdout + res.stderr).strip().splitlines()
            tail = lines[-(80 if keep_going else 40):]
            # make test's output is long: the lines that say what failed first (pytest's, make's), then its end
            said = [line for line in lines[: len(lines) - len(tail)] if _FAILED.search(line)][:30]
            print("\n".join("       | " + line for line in [*said, *(["       ..."] if said else []), *tail]))
            return False
    return True


def _said(fx: Fixture, problems: list[str], t0: float, what: str) -> None:
    print(f"{fx.name}: {fx.title}\n  adds: {fx.adds}")
    verdict = _verdict(fx)
    print(f"  {'ok' if not problems else 'FAIL':<4} cbfgen diff says {verdict}{'' if not problems else ': '}"
          f"{'; '.join(problems)} ({time.monotonic() - t0:.1f} s {what})")


def drill(fx: Fixture, quick: bool, keep: bool, keep_going: bool = False) -> bool:
    root = Path(tempfile.mkdtemp(prefix=f"cbf-drill-{fx.name}-"))
    root.chmod(0o755)  # as a clone is: tests/test_ci_users.py runs the CLI from it as another user (nobody)
    ok = True
    try:
        t0 = time.monotonic()
        copy_tree(root)
        if not quick:  # a checkout of the tree before the revision: the revision's commit shows what it changed
            subprocess.run(["sh", "-c", BASE_SH], cwd=root, check=True, capture_output=True)
        apply(fx, root)
        problems = check_diff(fx, REPO / SPEC, root / SPEC)
        _said(fx, problems, t0, "with the copy")
        ok = _run_steps(root, quick, keep_going) and not problems
        return ok
    finally:
        if keep or not ok:
            print(f"  tree kept: {root}")
        else:
            shutil.rmtree(root, ignore_errors=True)


def drill_together(chosen: list[Fixture], quick: bool, keep: bool, keep_going: bool = False,
                   rounds: int = 1) -> dict[str, bool]:
    """The quick drill: each fixture's `cbfgen diff` checked alone (on the spec it alone revises), then every
    fixture applied, one after the other, to ONE copy of the tree, and the steps run once there (one generation,
    one golden assembly, one testee build, one conformance run, one test run: half the CPU of a tree a
    fixture). A failure fails every fixture of the run; `drill.py run FIXTURE` (and `make revision-drill`)
    drills each alone."""
    root = Path(tempfile.mkdtemp(prefix="cbf-drill-together-"))
    root.chmod(0o755)  # as a clone is: tests/test_ci_users.py runs the CLI from it as another user (nobody)
    results: dict[str, bool] = {}
    ok = False
    try:
        t0 = time.monotonic()
        copy_tree(root)
        if not quick:  # a checkout of the tree before the revisions: their commit shows what they changed
            subprocess.run(["sh", "-c", BASE_SH], cwd=root, check=True, capture_output=True)
        for fx in chosen:
            if quick:  # the same check_diff on the same specs as test_cbfgen_diff_classifies_the_fixture, which
                # `make test` runs beside the quick drill for every fixture (about 1.2 CPU s a fixture)
                print(f"{fx.name}: {fx.title}\n  cbfgen diff alone: {DIFF_ALONE_TEST}")
                results[fx.name] = True
                continue
            t = time.monotonic()
            problems = check_diff(fx, REPO / SPEC, revised_spec(fx, REPO / SPEC, root / "build" / "drill" / fx.name))
            _said(fx, problems, t, "alone")
            results[fx.name] = not problems
        applied: list[Fixture] = []
        try:
            for _ in range(rounds):
                for fx in chosen:
                    try:
                        apply(fx, root)
                    except FixtureUnmet as exc:  # the fixtures before it already hold what it adds: said, left out
                        print(f"  skip {exc} (on top of {', '.join(f.name for f in applied) or 'nothing'})")
                        continue
                    applied.append(fx)
        except FixtureError as exc:
            print(f"  FAIL the fixtures do not apply together: {exc}")
            return dict.fromkeys(results, False)
        print(f"together: {', '.join(fx.name for fx in applied)}, applied to one copy of the tree "
              f"({time.monotonic() - t0:.1f} s with the copy)")
        ok = _run_steps(root, quick, keep_going)
        return {name: good and ok for name, good in results.items()}
    finally:
        if keep or not ok:
            print(f"  tree kept: {root}")
        else:
            shutil.rmtree(root, ignore_errors=True)


def _in_parallel(chosen: list[Fixture], args: argparse.Namespace) -> dict[str, bool]:
    """Each fixture drilled by its own `drill.py run FIXTURE` process, args.jobs at a time; each
    report printed whole, in the fixtures' order, so the log reads as a serial run."""
    flags = [f for f, on in (("--quick", args.quick), ("--keep", args.keep), ("--keep-going", args.keep_going)) if on]

    def one(fx: Fixture) -> subprocess.CompletedProcess[str]:
        return subprocess.run([sys.executable, __file__, "run", str(fx.path), *flags], capture_output=True, text=True)

    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        done = list(pool.map(one, chosen))
    results: dict[str, bool] = {}
    for fx, res in zip(chosen, done, strict=True):
        report = res.stdout.rstrip("\n").splitlines()
        print("\n".join(line for line in report if not line.startswith("revision drill")), flush=True)
        if res.stderr.strip():
            print(res.stderr.rstrip(), flush=True)
        results[fx.name] = res.returncode == 0
    return results


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="drill.py", description=__doc__.split("\n\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    a = sub.add_parser("apply", help="apply a fixture to a tree")
    a.add_argument("fixture", type=Path)
    a.add_argument("root", type=Path)
    o = sub.add_parser("outside", help="the files the revision committed at ROOT changed outside REVISION_PATHS")
    o.add_argument("root", type=Path)
    r = sub.add_parser("run", help="run the drill")
    r.add_argument("fixture", nargs="*", type=Path)
    r.add_argument("--quick", action="store_true",
                   help="the subset `make test` runs (without FIXTURE: the fixtures not in IN_TREE)")
    r.add_argument("--keep", action="store_true", help="keep the temporary trees")
    r.add_argument("--keep-going", action="store_true", help="report every failing test, not the first")
    r.add_argument("--jobs", type=int, default=1, help="fixtures drilled at once (each in its own process)")
    r.add_argument("--together", action="store_true",
                   help="apply the fixtures (default: all) to one tree and run every step there once")
    r.add_argument("--rounds", type=int, default=None,
                   help="together: apply the fixtures this many times over, each round on top of the last (default: "
                        f"{QUICK_ROUNDS} for the quick drill, 1 with --together)")
    args = ap.parse_args(argv)
    try:
        if args.cmd == "apply":
            apply(load_fixture(args.fixture), args.root)
            return 0
        if args.cmd == "outside":
            return outside(args.root)
        chosen, skipped = [], []
        for p in args.fixture or fixtures():
            try:
                chosen.append(load_fixture(p))
            except FixtureUnmet as exc:  # this tree's spec already holds what it adds: said, not drilled
                print(f"{p.stem}: {exc}", flush=True)
                skipped.append(p.stem)
        if args.quick and not args.fixture:
            chosen = [fx for fx in chosen if fx.name not in IN_TREE]
    except FixtureError as exc:
        print(f"drill: {exc}", file=sys.stderr)
        return 2
    t0 = time.monotonic()
    if not chosen:
        results: dict[str, bool] = {}
    elif (args.together or (args.quick and not args.fixture)) and len(chosen) > 1:
        rounds = args.rounds or (QUICK_ROUNDS if args.quick else 1)
        results = drill_together(chosen, args.quick, args.keep, args.keep_going, rounds)
    elif args.jobs > 1 and len(chosen) > 1:
        results = _in_parallel(chosen, args)
    else:
        results = {fx.name: drill(fx, args.quick, args.keep, args.keep_going) for fx in chosen}
    bad = [n for n, good in results.items() if not good]
    print(f"revision drill{' (quick)' if args.quick else ''}: {len(results) - len(bad)} of {len(results)} "
          f"fixture(s) pass in {time.monotonic() - t0:.0f} s" + (f"; failing: {', '.join(bad)}" if bad else "")
          + (f"; skipped (precondition unmet, said above): {', '.join(skipped)}" if skipped else ""))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
