"""`cbfgen diff OLD NEW`: every change by version and command, BREAKING for the wire meaning of OLD's versions.

The revisions are built from the model of spec/cbf.yaml (which command, which
version), so the tests hold under any legitimate revision of the spec.
"""

from __future__ import annotations

import contextlib
import copy
import io
import json
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from conftest import cite_clause, dump_yaml, load_yaml

from cbfgen.__main__ import main as cbfgen_main
from cbfgen.diff import Diff, diff
from cbfgen.loader import load
from cbfgen.model import Spec

REPO = Path(__file__).resolve().parents[1]
SPEC_PATH = REPO / "spec" / "cbf.yaml"
SPEC = load(SPEC_PATH)
RAW: dict[str, Any] = load_yaml(SPEC_PATH)
Edit = Callable[[dict[str, Any]], None]


def _variant(tmp: Path, edit: Edit, name: str = "new.yaml") -> Path:
    doc = copy.deepcopy(RAW)
    edit(doc)
    p = tmp / name
    p.write_text(dump_yaml(doc, sort_keys=False), encoding="utf-8")
    return p


def _diff(tmp: Path, edit: Edit) -> Diff:
    return diff(SPEC, load(_variant(tmp, edit)))


def _process(*args: str) -> subprocess.CompletedProcess[str]:
    """`python -m cbfgen diff ARGS`, a process of its own."""
    return subprocess.run([sys.executable, "-m", "cbfgen", "diff", *args], capture_output=True, text=True, cwd=REPO)


def _cli(*args: str) -> subprocess.CompletedProcess[str]:
    """`cbfgen diff ARGS` run in this process: the main() `python -m cbfgen` runs, its exit code
    (what it returns: the module exits with it) and what it writes to stdout and stderr. A process
    costs 0.35 CPU s of interpreter and imports; test_bad_input_is_one_line_and_exit_2 runs the
    real command (_process) for the exit code and the one line a process gives."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = cbfgen_main(["diff", *args])
    return subprocess.CompletedProcess(["cbfgen", "diff", *args], rc, out.getvalue(), err.getvalue())


def _free_clause(n: int) -> str:
    """The n-th clause id "9.k" no check, version or command of the spec uses (a revision may have taken 9.9)."""
    used = {str(x) for c in SPEC.checks for x in (c.id, c.clause)} | {str(v.clause) for v in SPEC.versions}
    return [f"9.{k}" for k in range(1, 1000) if f"9.{k}" not in used][n]


GATE, DWELL_GATE = _free_clause(0), _free_clause(1)


def _raw_command(doc: dict[str, Any], name: str) -> dict[str, Any]:
    return next(c for c in doc["commands"] if c["name"] == name)


def _last_version() -> str:
    return SPEC.versions[-1].id


def _reserved_in_last_version() -> tuple[str, int, str]:
    """(command, layout index, reserved arg) of a command of the newest version with 4 reserved bytes."""
    vid = _last_version()
    for c in SPEC.commands:
        for i, lay in enumerate(c.layouts):
            if vid in lay.versions:
                for a in lay.args:
                    if a.reserved and a.size == 4:
                        return c.name, i, a.name
    pytest.skip(f"no command of {vid} has 4 reserved bytes")


def _new_version_id(spec: Spec) -> tuple[str, int]:
    major = max(v.major for v in spec.versions) + 1
    return f"{major}.0", major


def _add_version(doc: dict[str, Any], drop: str | None = None) -> str:
    """A new version after the newest one, with its command table, minus `drop`."""
    base = _last_version()
    vid, major = _new_version_id(SPEC)
    doc["versions"].append({"id": vid, "major": major, "minor": 0, "header": SPEC.version(base).header,
                            "clause": GATE, "writable": True, "doc": f"Version {vid}."})
    for c in doc["commands"]:
        for lay in c["layouts"]:
            if base in lay["versions"] and c["name"] != drop:
                lay["versions"].append(vid)
    missing = [c.name for c in SPEC.commands if not c.available_in(base)] + ([drop] if drop else [])
    if missing:
        named = any("commands" in ch for ch in doc["checks"] if ch["kind"] == "availability")
        cite_clause(doc, GATE, f"Version {vid} lacks some commands.")
        doc["checks"].append({"id": GATE, "kind": "availability", "severity": "error", "clause": GATE,
                              "versions": [vid], "commands": missing, "text": f"{vid} lacks {missing}.",
                              "fails": "A record's command has no layout for the file's version."})
        if not named:
            del doc["checks"][-1]["commands"]  # a spec whose availability checks name versions only
    return vid


def _kinds(d: Diff) -> set[tuple[str, str | None, str | None, bool]]:
    return {(c.kind, c.version, c.command, c.breaking) for c in d.changes}


def test_a_spec_against_itself_has_no_change() -> None:
    d = diff(SPEC, SPEC)
    assert d.changes == () and d.breaking == ()
    res = _cli(str(SPEC_PATH), str(SPEC_PATH))
    assert res.returncode == 0 and "0 change(s), 0 wire-breaking, 0 text-breaking" in res.stdout
    assert res.stdout.splitlines()[-1].startswith("not breaking (exit 0)")


def test_a_layout_change_to_the_newest_version_is_breaking(tmp_path: Path) -> None:
    cmd, idx, arg = _reserved_in_last_version()
    vid = _last_version()

    def edit(doc: dict[str, Any]) -> None:
        lays = _raw_command(doc, cmd)["layouts"]
        old = lays[idx]
        new = copy.deepcopy(old)
        old["versions"] = [v for v in old["versions"] if v != vid]
        new["versions"], new["variant"] = [vid], "drill"
        for a in new["args"]:
            if a["name"] == arg:
                a.clear()
                a.update({"name": "wear", "type": "f4", "unit": "mm", "doc": "Was reserved."})
        lays.append(new)
        if not old["versions"]:
            lays.remove(old)

    d = _diff(tmp_path, edit)
    changes = [c for c in d.changes if c.kind == "field_retyped"]
    assert [(c.version, c.command, c.breaking) for c in changes] == [(vid, cmd, True)]
    assert f"{arg} (bytes" in changes[0].detail and "wear (f4" in changes[0].detail
    others = {v for v in {c.version for c in d.changes} if v not in (vid, None)}
    assert not others, "the other versions keep their layout"
    res = _cli(str(SPEC_PATH), str(_variant(tmp_path, edit, "v.yaml")))
    assert res.returncode == 1 and "BREAKING" in res.stdout and cmd in res.stdout
    assert res.stdout.splitlines()[-1].startswith("wire-breaking (exit 1)")


def test_a_new_version_is_not_breaking(tmp_path: Path) -> None:
    dropped = SPEC.commands[0].name
    vid = ""

    def edit(doc: dict[str, Any]) -> None:
        nonlocal vid
        vid = _add_version(doc, drop=dropped)

    d = _diff(tmp_path, edit)
    assert not d.breaking, d.text()
    assert ("version_added", vid, None, False) in _kinds(d)
    assert ("command_removed", vid, dropped, False) in _kinds(d)
    res = _cli(str(SPEC_PATH), str(_variant(tmp_path, edit, "v.yaml")), "--json")
    assert res.returncode == 0, res.stdout + res.stderr
    doc = json.loads(res.stdout)
    assert doc["breaking"] is False and {"kind": "version_added", "version": vid, "command": None,
                                         "breaking": False} in [{k: c[k] for k in ("kind", "version", "command",
                                                                                    "breaking")}
                                                               for c in doc["changes"]]


def _dwell(versions: list[str]) -> dict[str, Any]:
    free = next(code for code in range(1, 256) if all(c.code != code for c in SPEC.commands))
    return {"name": "DRILL_DWELL", "code": free, "clause": DWELL_GATE, "doc": "Dwell.",
            "layouts": [{"versions": versions, "size": 4,
                         "args": [{"name": "seconds", "type": "f4", "doc": "Dwell time."}]}]}


def _gate(doc: dict[str, Any], versions: list[str], command: str) -> None:
    if versions:
        cite_clause(doc, DWELL_GATE, "DRILL_DWELL was added later.")
        check = {"id": DWELL_GATE, "kind": "availability", "severity": "error", "clause": DWELL_GATE,
                 "versions": versions,
                 "commands": [command], "text": "added later.", "fails": "no layout for the version."}
        if not any("commands" in ch for ch in doc["checks"] if ch["kind"] == "availability"):
            del check["commands"]
        doc["checks"].append(check)


def test_a_command_added_to_an_existing_version_is_breaking(tmp_path: Path) -> None:
    target = SPEC.default_version

    def edit(doc: dict[str, Any]) -> None:
        doc["commands"].append(_dwell([target]))
        _gate(doc, [v.id for v in SPEC.versions if v.id != target], "DRILL_DWELL")

    d = _diff(tmp_path, edit)
    assert ("command_added", target, "DRILL_DWELL", True) in _kinds(d)


def test_a_command_of_a_new_version_only_is_not_breaking(tmp_path: Path) -> None:
    def edit(doc: dict[str, Any]) -> None:
        vid = _add_version(doc)
        doc["commands"].append(_dwell([vid]))
        _gate(doc, [v.id for v in SPEC.versions], "DRILL_DWELL")

    d = _diff(tmp_path, edit)
    assert not d.breaking, d.text()
    assert any(c.kind == "command_added" and c.command == "DRILL_DWELL" for c in d.changes)


def test_checksum_algorithm_and_coverage_changes_are_breaking(tmp_path: Path) -> None:
    field = SPEC.checksums.fields[0]
    other = next(a for a in SPEC.checksums.algorithms if a != field.algorithm)

    def algorithm(doc: dict[str, Any]) -> None:
        next(f for f in doc["checksums"]["fields"] if f["field"] == field.field)["algorithm"] = other

    d = _diff(tmp_path, algorithm)
    assert [(c.kind, c.breaking) for c in d.changes] == [("checksum_algorithm_changed", True)]
    assert f"{field.algorithm} -> {other}" in d.changes[0].detail

    file_cov = SPEC.checksums.for_field("file").coverage

    def coverage(doc: dict[str, Any]) -> None:
        seg = doc["checksums"]["coverages"][file_cov]["segments"][0]
        seg["start"] = seg.get("start", 0) + 1

    d = _diff(tmp_path, coverage)
    assert {(c.kind, c.breaking) for c in d.changes} >= {("checksum_coverage_changed", True)}


def test_version_removed_and_writable_changed(tmp_path: Path) -> None:
    oldest = SPEC.versions[0].id
    writable = SPEC.writable_versions[0].id

    def edit(doc: dict[str, Any]) -> None:
        doc["versions"] = [v for v in doc["versions"] if v["id"] != oldest]
        for v in doc["versions"]:
            if v["id"] == writable:
                v["writable"] = False
        for c in doc["commands"]:
            for lay in c["layouts"]:
                lay["versions"] = [x for x in lay["versions"] if x != oldest]
            c["layouts"] = [lay for lay in c["layouts"] if lay["versions"]]
        doc["commands"] = [c for c in doc["commands"] if c["layouts"]]
        for ch in doc["checks"]:
            if "versions" in ch:
                ch["versions"] = [x for x in ch["versions"] if x != oldest]
        doc["checks"] = [ch for ch in doc["checks"] if ch.get("versions", True)]
        used = {h for v in doc["versions"] for h in [v["header"]]}
        doc["headers"] = {k: h for k, h in doc["headers"].items() if k in used}

    d = _diff(tmp_path, edit)
    assert ("version_removed", oldest, None, True) in _kinds(d)
    assert ("writable_changed", writable, None, False) in _kinds(d)


def test_check_severity_and_new_warning(tmp_path: Path) -> None:
    warning = next(c for c in SPEC.checks if c.severity == "warning")

    def edit(doc: dict[str, Any]) -> None:
        next(c for c in doc["checks"] if str(c["id"]) == warning.id)["severity"] = "error"
        doc["checks"].append({"id": "drill_note", "kind": "reserved_byte", "severity": "warning",
                              "decision": SPEC.decisions[0].id, "text": "t.", "fails": "f."})

    d = _diff(tmp_path, edit)
    assert ("check_severity_changed", None, None, True) in _kinds(d)
    assert ("check_added", None, None, False) in _kinds(d)
    assert [c for c in d.changes if c.kind == "check_severity_changed"][0].detail == f"{warning.id}: warning -> error"


def test_fields_renamed_moved_resized(tmp_path: Path) -> None:
    # A command of the default version with two arguments of the same type and size: swapping them moves both.
    vid = SPEC.default_version
    cmd, lay = next((c.name, lay) for c in SPEC.commands for lay in c.layouts_for(vid)
                    if len(lay.args) >= 2 and lay.args[0].size == lay.args[1].size
                    and lay.args[0].type == lay.args[1].type and not lay.variant)
    b = lay.args[1].name

    def swap(doc: dict[str, Any]) -> None:
        raw = next(x for x in _raw_command(doc, cmd)["layouts"] if vid in x["versions"])
        raw["args"][0], raw["args"][1] = raw["args"][1], raw["args"][0]

    moved = {(c.kind, c.command) for c in _diff(tmp_path, swap).changes if c.version == vid}
    assert moved == {("field_moved", cmd)}

    rcmd, ridx, rarg = _reserved_in_last_version()  # nothing refers to a reserved argument by name

    def rename(doc: dict[str, Any]) -> None:
        raw = _raw_command(doc, rcmd)["layouts"][ridx]
        next(x for x in raw["args"] if x["name"] == rarg)["name"] = "drill_" + rarg

    renamed = [c for c in _diff(tmp_path, rename).changes if c.command == rcmd]
    assert renamed and all(c.kind == "field_renamed" and c.text_breaking and not c.breaking and rarg in c.detail
                           for c in renamed)

    def resize(doc: dict[str, Any]) -> None:
        layouts = _raw_command(doc, cmd)["layouts"]
        raw = next(x for x in layouts if vid in x["versions"])
        raw["args"].append({"name": "drill_extra", "type": "bytes", "size": 2, "reserved": True, "doc": "x."})
        raw["size"] += 2

    kinds = {c.kind for c in _diff(tmp_path, resize).changes if c.command == cmd}
    assert {"layout_resized", "field_added"} <= kinds
    assert b  # both names exist in the model


def test_bad_input_is_one_line_and_exit_2(tmp_path: Path) -> None:
    bad = tmp_path / "bad.yaml"
    bad.write_text("meta: [\n", encoding="utf-8")
    res = _process(str(SPEC_PATH), str(bad))
    assert res.returncode == 2 and res.stdout == ""
    lines = res.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"cbfgen diff: {bad}:") and "Traceback" not in res.stderr
    missing = _cli(str(tmp_path / "missing.yaml"), str(SPEC_PATH))
    assert missing.returncode == 2 and "cannot read" in missing.stderr
    assert _cli(str(SPEC_PATH)).returncode == 2  # usage


def test_generation_keeps_its_command_line() -> None:
    res = subprocess.run([sys.executable, "-m", "cbfgen", "--spec", str(SPEC_PATH), "--check-spec"],
                         capture_output=True, text=True, cwd=REPO)
    assert res.returncode == 0 and f"{len(SPEC.commands)} commands" in res.stdout


def test_the_changes_page_is_the_diff_of_each_version_with_the_one_before() -> None:
    from cbfgen.diff import version_steps
    from cbfgen.emit import docs

    page = docs.emit(SPEC)["docs/changes.md"].decode()
    steps = version_steps(SPEC)
    assert len(steps) == len(SPEC.versions) - 1
    for prev, vid, changes in steps:
        assert f"### {vid}, relative to {prev}" in page
        for c in changes:
            assert f"| {c.command or 'header'} | {c.detail} |" in page
    for h in SPEC.history:
        assert f"| {h.id} | {h.date} | {h.clause} | {h.text} |" in page
    assert SPEC.revision in page.splitlines()[0]


def test_an_availability_check_extended_to_a_new_version_is_not_breaking(tmp_path: Path) -> None:
    base = _last_version()
    gates = [c.id for c in SPEC.checks if c.kind == "availability" and base in c.versions]
    if not gates:
        pytest.skip(f"{base} lacks no command")

    def edit(doc: dict[str, Any]) -> None:
        vid = _add_version(doc)  # the command table of the newest version, gated like it
        doc["checks"] = [c for c in doc["checks"] if c["id"] != GATE]
        for c in doc["checks"]:
            if str(c["id"]) in gates:
                c["versions"].append(vid)

    d = _diff(tmp_path, edit)
    # each gate is changed; a check whose versions follow from `since:` (a deprecation) extends too
    changed = {c.detail.split(":")[0] for c in d.changes if c.kind == "check_changed"}
    assert set(gates) <= changed and not d.breaking, d.text()


def _rename_everywhere(doc: Any, old: str, new: str) -> Any:
    """doc with every string equal to old (the command's name and each reference to it) spelled new."""
    if isinstance(doc, dict):
        return {k: _rename_everywhere(v, old, new) for k, v in doc.items()}
    if isinstance(doc, list):
        return [_rename_everywhere(v, old, new) for v in doc]
    return new if doc == old else doc


def _most_referenced_command() -> str:
    """The command the checks name most often (so the rename reaches checks of several kinds), from the model."""
    def refs(name: str) -> int:
        return sum(name in ch.commands or any(t.command == name for t in ch.targets) for ch in SPEC.checks)
    return max(SPEC.commands, key=lambda c: (refs(c.name), -SPEC.commands.index(c))).name


def test_a_rename_is_text_breaking_and_not_wire_breaking(tmp_path: Path) -> None:
    """A command renamed with the same code and layouts keeps every byte's meaning: each version that has it
    reports command_renamed as TEXT, nothing is BREAKING, the exit code is 3 and the footer says so. The same
    rename with a layout change as well is wire-breaking (exit 1)."""
    cmd = _most_referenced_command()
    versions = {v.id for v in SPEC.versions if SPEC.command(cmd).available_in(v.id)}

    def rename(doc: dict[str, Any]) -> None:
        doc.update(_rename_everywhere(copy.deepcopy(doc), cmd, cmd + "_NEW"))

    d = _diff(tmp_path, rename)
    assert not d.breaking, d.text()
    renamed = {(c.version, c.impact) for c in d.changes if c.kind == "command_renamed" and c.command == cmd}
    assert renamed == {(v, "text") for v in versions}, d.text()
    assert d.exit_code == 3 and d.impact == "text"
    res = _cli(str(SPEC_PATH), str(_variant(tmp_path, rename, "r.yaml")))
    assert res.returncode == 3, res.stdout + res.stderr
    assert res.stdout.splitlines()[-1].startswith("text-breaking only (exit 3)") and "TEXT" in res.stdout
    assert "BREAKING" not in res.stdout
    doc = json.loads(_cli(str(SPEC_PATH), str(tmp_path / "r.yaml"), "--json").stdout)
    assert (doc["breaking"], doc["text_breaking"], doc["impact"], doc["exit"]) == (False, True, "text", 3)

    def rename_and_grow(doc: dict[str, Any]) -> None:
        rename(doc)
        lay = _raw_command(doc, cmd + "_NEW")["layouts"][0]
        lay["args"].append({"name": "drill_extra", "type": "bytes", "size": 2, "reserved": True, "doc": "x."})
        lay["size"] += 2

    grown = _diff(tmp_path, rename_and_grow)
    assert grown.breaking and grown.exit_code == 1 and grown.impact == "wire"
    assert any(c.kind == "command_renamed" and c.impact == "text" for c in grown.changes)


def test_a_layout_variant_renamed_is_text_breaking(tmp_path: Path) -> None:
    """A layout's variant names its C and Python identifiers: renaming it keeps every byte (TEXT, not BREAKING)."""
    cmd, idx, variant = next(((c.name, i, lay.variant) for c in SPEC.commands for i, lay in enumerate(c.layouts)
                              if lay.variant), ("", 0, None))
    if not variant:
        pytest.skip("no layout has a variant name")

    def rename(doc: dict[str, Any]) -> None:
        _raw_command(doc, cmd)["layouts"][idx]["variant"] = f"{variant}_new"

    d = _diff(tmp_path, rename)
    assert d.changes and not d.breaking and d.exit_code == 3, d.text()
    assert {c.kind for c in d.changes} == {"layout_variant_renamed"}


def test_the_exit_codes_are_documented() -> None:
    """`--help` and the README name each exit code of cbfgen diff with its class."""
    from cbfgen.diff import EXIT_CODES

    res = _cli("--help")
    assert res.returncode == 0
    help_text = " ".join(res.stdout.split())
    readme = " ".join((REPO / "README.md").read_text(encoding="utf-8").split())
    assert len({code for code, _ in EXIT_CODES}) == 5
    for code, what in EXIT_CODES:
        assert f"{code} {what}" in help_text, (code, what)
        assert f"{code} {what}" in readme, (code, what)


def test_a_check_renamed_is_text_breaking(tmp_path: Path) -> None:
    """A check given another id, judging the same: every file is judged the same, findings name the new id
    (TEXT, exit 3). Given another id and another bound too, it is a removal and an addition (wire-breaking
    when an error)."""
    check = next(c for c in SPEC.checks if c.severity == "error" and c.kind != "availability")

    def rename(doc: dict[str, Any]) -> None:
        next(c for c in doc["checks"] if str(c["id"]) == check.id)["id"] = "drill_renamed_check"

    d = _diff(tmp_path, rename)
    assert [(c.kind, c.impact) for c in d.changes] == [("check_renamed", "text")], d.text()
    assert d.exit_code == 3 and check.id in d.changes[0].detail

    def rename_and_change(doc: dict[str, Any]) -> None:
        raw = next(c for c in doc["checks"] if str(c["id"]) == check.id)
        raw["id"], raw["severity"] = "drill_renamed_check", "warning"

    kinds = {(c.kind, c.impact) for c in _diff(tmp_path, rename_and_change).changes}
    assert kinds == {("check_removed", "wire"), ("check_added", "none")}, kinds
