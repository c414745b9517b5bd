"""Machine limits (decision L1, check kind machine_limits; issue #13 item 16).

Every expectation is read from the model: the targets of the machine_limits
checks, the default machine's limits, the check's severity and input severity.
A value far outside a limit is a warning with the default machine and an error
with a machine file; a value inside is clean; a bad machine file is one line
and exit 2 in both tools, with the same words. The rev 03 values of the issue
(speed 1e30 m/s, a POINT at 1e30 mm, a cutter radius of 1e-30 mm) are in
tests/test_rev03_facts.py.
"""

from __future__ import annotations

import copy
import json
import math
import os
import subprocess
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import jsonschema
import pytest
from c_programs import built
from cli_many import run_many
from conftest import dump_yaml, spec_doc

import cbf
from cbf import tables as T
from cbf.machine import DEFAULT, MachineError, load_machine
from cbf.testing import seal
from cbfgen.emit.python.machine import machine_data, machine_schema
from cbfgen.loader import SpecError, load

REPO = Path(__file__).resolve().parents[1]
SPEC_PATH = REPO / "spec" / "cbf.yaml"
SPEC = load(SPEC_PATH)
CHECKS = SPEC.checks_of_kind("machine_limits")
POSITIVE = {(t.command, a) for ch in SPEC.checks_of_kind("positive") for t in ch.targets for a in t.args}
ENV = dict(os.environ, PYTHONPATH=os.pathsep.join([str(REPO / "generated" / "python"), str(REPO / "generator")]))


def _cases() -> Iterator[tuple[str, str, str, str]]:
    for ch in CHECKS:
        for t in ch.targets:
            for a in t.args:
                assert t.limit is not None
                yield ch.id, t.command, a, t.limit


CASES = list(_cases())


def _inside(lim: Any) -> list[float]:
    return [(lo + hi) / 2.0 for lo, hi in zip(lim.min, lim.max, strict=True)]


def _record(command: str, arg: str, value: float | None, axis: int = 0) -> tuple[Any, bytes, int]:
    """A record of command whose machine-bounded arguments lie inside the default machine, and
    arg's component ``axis`` set to value. Returns the layout, the argument bytes and arg's offset."""
    cmd = T.BY_NAME[command]
    lay = cmd.candidates(T.DEFAULT_VERSION)[0]  # the layout a reader takes there, also for a command the version lacks
    bounded = {(t.command, a): SPEC.machine.limit(t.limit) for ch in CHECKS for t in ch.targets if t.limit
               for a in t.args}
    vals: list[Any] = []
    at = -1
    for f in lay.args:
        if f.kind == "float":
            lim = bounded.get((command, f.name))
            comp = _inside(lim) if lim is not None else [1.0] * f.count
            if f.name == arg:
                at = f.offset
                if value is not None:
                    comp[axis] = value
            vals.extend(comp)
        else:
            vals.append(b"" if f.kind in ("string", "bytes") else 1)
    assert at >= 0
    return lay, lay.struct.pack(*vals), at


def _file(command: str, arg: str, value: float | None, axis: int = 0) -> tuple[bytes, int]:
    """The bytes of a one-record file, and the file offset of arg."""
    _, raw, at = _record(command, arg, value, axis)
    data = seal(cbf.Cbf(cbf.new_header(T.DEFAULT_VERSION), (cbf.Record(code=T.BY_NAME[command].code, raw_args=raw),)))
    return data, T.HEADER_SIZE + T.HEAD_SIZE + at


def _machine_file(tmp: Path, doc: Any, name: str = "machine.json") -> Path:
    p = tmp / name
    p.write_text(doc if isinstance(doc, str) else json.dumps(doc), encoding="utf-8")
    return p


def _outside(lim: Any, k: int, positive: bool) -> list[float]:
    """binary32 values outside component k of a limit: far above, and far below (but > 0 when a
    positive check owns the values <= 0)."""
    out = []
    if lim.max[k] < 1e30:
        out.append(1e30)
    low = 1e-30 if positive else -1e30
    if lim.min[k] > low:
        out.append(low)
    return out


def _machine_of(findings: list[Any]) -> list[tuple[str, str, int | None, int | None]]:
    return [(f.check, f.severity, f.record, f.offset) for f in findings if f.check in {c.id for c in CHECKS}]


@pytest.mark.parametrize(("check", "command", "arg", "limit"), CASES, ids=[f"{c[1]}.{c[2]}" for c in CASES])
def test_outside_the_default_machine_warns_and_a_machine_file_makes_it_an_error(
        check: str, command: str, arg: str, limit: str, tmp_path: Path) -> None:
    ch = SPEC.check(check)
    lim = SPEC.machine.limit(limit)
    given = load_machine(_machine_file(tmp_path, machine_data(SPEC)))  # the default, as a file
    tried = 0
    for k in range(max(1, len(lim.axes))):
        for value in _outside(lim, k, (command, arg) in POSITIVE):
            data, at = _file(command, arg, value, k)
            assert _machine_of(cbf.validate(data)) == [(check, ch.severity, 0, at)], (value, k)
            assert _machine_of(cbf.validate(data, machine=given)) == [
                (check, ch.input_severity or ch.severity, 0, at)]
            tried += 1
    assert tried, "a limit with no value outside it cannot be tested"
    assert ch.severity == "warning" and ch.input_severity == "error"  # L1: the default warns, a file refuses


@pytest.mark.parametrize(("check", "command", "arg", "limit"), CASES, ids=[f"{c[1]}.{c[2]}" for c in CASES])
def test_inside_the_machine_is_clean_and_non_positive_values_stay_the_positive_checks(
        check: str, command: str, arg: str, limit: str) -> None:
    data, _ = _file(command, arg, None)
    assert _machine_of(cbf.validate(data)) == []
    lim = SPEC.machine.limit(limit)
    for value in (lim.min[0], lim.max[0]):  # the bounds themselves are inside
        data, _ = _file(command, arg, value)
        assert _machine_of(cbf.validate(data)) == []
    if (command, arg) in POSITIVE:
        data, at = _file(command, arg, 0.0)
        found = cbf.validate(data)
        assert _machine_of(found) == []
        assert any(f.offset == at and f.check in {c.id for c in SPEC.checks_of_kind("positive")} for f in found)
    data, at = _file(command, arg, math.inf)  # non-finite: the finite check's
    assert _machine_of(cbf.validate(data)) == []


def test_the_default_machine_is_a_valid_machine_file_and_the_schema_is_the_spec() -> None:
    schema = machine_schema(SPEC)
    jsonschema.Draft202012Validator.check_schema(schema)
    jsonschema.validate(machine_data(SPEC), schema)
    shipped = json.loads((REPO / "generated" / "python" / "cbf" / "machine.schema.json").read_text(encoding="utf-8"))
    assert shipped == schema
    assert set(DEFAULT.limits) == {lim.name for lim in SPEC.machine.limits}
    assert not DEFAULT.given


def _bad_docs() -> dict[str, Any]:
    """Machine files that break one rule each, built from the default machine."""
    base = machine_data(SPEC)
    vec = next(lim for lim in SPEC.machine.limits if lim.axes)
    sca = next(lim for lim in SPEC.machine.limits if not lim.axes)
    out: dict[str, Any] = {}

    def bad(name: str, edit: Any) -> None:
        d = copy.deepcopy(base)
        edit(d)
        out[name] = d

    bad("missing_limit", lambda d: d["limits"].pop(sca.name))
    bad("wrong_unit", lambda d: d["limits"][sca.name].__setitem__("unit", sca.unit + "x"))
    bad("unit_not_a_string", lambda d: d["limits"][sca.name].__setitem__("unit", 1))
    bad("unknown_key", lambda d: d.__setitem__("extra", 1))
    bad("unknown_limit", lambda d: d["limits"].__setitem__("not_a_limit", {}))
    bad("unknown_limit_key", lambda d: d["limits"][sca.name].__setitem__("typo", 1))
    bad("axes_on_a_range", lambda d: d["limits"][sca.name].__setitem__("axes", ["x"]))
    bad("wrong_axes", lambda d: d["limits"][vec.name].__setitem__("axes", list(reversed(vec.axes))))
    bad("min_a_string", lambda d: d["limits"][sca.name].__setitem__("min", "1"))
    bad("min_a_bool", lambda d: d["limits"][sca.name].__setitem__("min", True))
    bad("box_a_number", lambda d: d["limits"][vec.name].__setitem__("min", 1))
    bad("box_too_short", lambda d: d["limits"][vec.name].__setitem__("min", list(vec.min)[:-1]))
    bad("box_item_a_string", lambda d: d["limits"][vec.name].__setitem__("max", ["1", *vec.max[1:]]))
    bad("range_a_list", lambda d: d["limits"][sca.name].__setitem__("min", [sca.min[0]]))
    bad("min_above_max", lambda d: d["limits"][sca.name].__setitem__("min", sca.max[0] + 1))
    bad("box_min_above_max", lambda d: d["limits"][vec.name].__setitem__("min", [*vec.min[:-1], vec.max[-1] + 1]))
    bad("missing_max", lambda d: d["limits"][sca.name].pop("max"))
    bad("no_limits", lambda d: d.pop("limits"))
    bad("name_a_number", lambda d: d.__setitem__("name", 3))
    out["not_an_object"] = []
    out["not_json"] = '{"limits": '
    out["duplicate_key"] = json.dumps(base).replace('"unit":', '"unit": "x", "unit":', 1)
    out["too_big"] = json.dumps(base).replace(f'"max": {json.dumps(sca.max[0])}', '"max": 1e400', 1)
    return out


BAD = _bad_docs()


@pytest.mark.parametrize("name", sorted(BAD))
def test_a_bad_machine_file_is_one_line_naming_the_place(name: str, tmp_path: Path) -> None:
    path = _machine_file(tmp_path, BAD[name])
    with pytest.raises(MachineError) as info:
        load_machine(path)
    msg = info.value.message
    assert "\n" not in msg and msg.startswith(f"{path}: ")
    assert ": $" in msg or ": line " in msg, msg  # a JSON path, or a line and column
    if not isinstance(BAD[name], str):  # the shipped schema refuses it too (min <= max is beyond a schema)
        valid = jsonschema.Draft202012Validator(machine_schema(SPEC)).is_valid(BAD[name])
        assert not valid or "above_max" in name


def test_a_yaml_machine_file_reads_as_its_json(tmp_path: Path) -> None:
    doc = machine_data(SPEC)
    y = tmp_path / "m.yaml"
    one_line = dump_yaml(doc, width=10**6)  # the option-file YAML has one-line values (option_files.yaml)
    y.write_text(one_line, encoding="utf-8")
    assert load_machine(y) == load_machine(_machine_file(tmp_path, doc))
    y.write_text(one_line + "limits: {}\n", encoding="utf-8")
    with pytest.raises(MachineError, match=r"\$: duplicate key 'limits'"):
        load_machine(y)


@pytest.fixture(scope="module")
def cbf_c() -> Path | None:
    """cbf-c as `make c-build` builds it (not compiled again here: c_programs.py), or None without gcc."""
    try:
        return built("cbf-c")
    except pytest.skip.Exception:
        return None


def test_both_tools_refuse_a_bad_machine_file_alike_with_exit_2(cbf_c: Path | None, tmp_path: Path) -> None:
    exe = cbf_c
    data, _ = _file(CASES[0][1], CASES[0][2], None)
    target = tmp_path / "ok.cbf"
    target.write_bytes(data)
    paths = {name: _machine_file(tmp_path, doc, f"{name}.json") for name, doc in sorted(BAD.items())}
    pys = run_many([["validate", "--machine", str(path), str(target)] for path in paths.values()], ENV)  # one process
    for (name, path), (py, _) in zip(paths.items(), pys, strict=True):
        assert py.returncode == 2 and py.stdout == "", (name, py)
        lines = py.stderr.splitlines()
        assert len(lines) == 1 and lines[0].startswith(f"cbf: {path}: "), (name, py.stderr)
        if exe is None:
            continue
        c = subprocess.run([str(exe), "validate", "--machine", str(path), str(target)], capture_output=True, text=True)
        assert c.returncode == 2 and c.stdout == "", (name, c)
        assert len(c.stderr.splitlines()) == 1, (name, c.stderr)
        if ": line " not in lines[0]:  # syntax errors name line and column; the words of JSON's reader differ
            assert c.stderr.strip().removeprefix("cbf-c: ") == lines[0].removeprefix("cbf: "), name


def test_both_tools_give_the_same_findings_with_and_without_a_machine_file(cbf_c: Path | None, tmp_path: Path) -> None:
    """Every target's values outside its limit, one record each in one file: `cbf validate` and
    `cbf-c validate` print the same machine_limits lines (one a record), without and with a
    machine file (one process per tool and mode, not one per value)."""
    exe = cbf_c
    if exe is None:
        pytest.skip("no C compiler")
    machine = _machine_file(tmp_path, machine_data(SPEC))
    records = []
    for _, command, arg, limit in CASES:
        lim = SPEC.machine.limit(limit)
        k = len(lim.axes) - 1 if lim.axes else 0
        for value in _outside(lim, k, (command, arg) in POSITIVE):
            _, raw, _ = _record(command, arg, value, k)
            records.append(cbf.Record(code=T.BY_NAME[command].code, raw_args=raw))
    f = tmp_path / "outside.cbf"
    f.write_bytes(seal(cbf.Cbf(cbf.new_header(T.DEFAULT_VERSION), tuple(records))))
    modes: list[list[str]] = [[], ["--machine", str(machine)]]
    pys = run_many([["validate", "--max-findings", "0", *extra, str(f)] for extra in modes], ENV)  # one process
    for extra, (py, _) in zip(modes, pys, strict=True):
        c = subprocess.run([str(exe), "validate", "--max-findings", "0", *extra, str(f)], capture_output=True,
                           text=True)
        want = [ln for ln in py.stdout.splitlines() if "machine_limits" in ln]
        assert len(want) == len(records) > len(CASES), (extra, py.stdout[-2000:])
        assert want == [ln for ln in c.stdout.splitlines() if "machine_limits" in ln], extra
        # records of many commands in a row also fail other checks (continuity, shapes): the
        # exit codes agree, and with a machine file the breaches alone make it 1
        assert py.returncode == c.returncode, (extra, py.stdout[-500:], c.stdout[-500:])
        if extra:
            assert py.returncode == 1 and all(" error machine_limits " in ln for ln in want), extra
        else:
            assert all(" warning machine_limits " in ln for ln in want)


def _variant(tmp: Path, edit: Any) -> Path:
    doc = spec_doc()
    edit(doc)
    p = tmp / "cbf.yaml"
    p.write_text(dump_yaml(doc, sort_keys=False, width=1000), encoding="utf-8")
    return p


def test_the_loader_wants_every_position_bounded_and_targets_that_fit(tmp_path: Path) -> None:
    """Which arguments are positions comes from the layouts: a float vector of a box's unit."""
    ch_id = CHECKS[0].id
    vec = next(lim for lim in SPEC.machine.limits if lim.axes)
    sca = next(lim for lim in SPEC.machine.limits if not lim.axes)

    def drop_target(doc: dict[str, Any]) -> None:
        ch = next(c for c in doc["checks"] if c["id"] == ch_id)
        ch["targets"] = [t for t in ch["targets"] if t["limit"] != vec.name or t is not ch["targets"][0]]

    first = next(t for t in CHECKS[0].targets if t.limit == vec.name)
    with pytest.raises(SpecError, match=f"{first.command}.{first.args[0]} is a position"):
        load(_variant(tmp_path, drop_target))

    def wrong_limit(doc: dict[str, Any]) -> None:
        ch = next(c for c in doc["checks"] if c["id"] == ch_id)
        t = next(t for t in ch["targets"] if t["limit"] == vec.name)
        t["limit"] = sca.name

    with pytest.raises(SpecError, match=f"does not fit machine limit {sca.name}"):
        load(_variant(tmp_path, wrong_limit))

    def min_above_max(doc: dict[str, Any]) -> None:
        doc["machine"]["limits"][sca.name]["min"] = sca.max[0] + 1

    with pytest.raises(SpecError, match=f"machine limit {sca.name}: min exceeds max"):
        load(_variant(tmp_path, min_above_max))



def test_the_kernel_agrees_with_a_record_by_record_reading(tmp_path: Path) -> None:
    """validate's numpy kernel (records._machine_limits) gives what machine.breach says of each
    record's decoded values, one record at a time, on a file whose targeted values lie inside,
    outside, at the limits, at 0 and non-finite; with the default machine and with a file."""
    import random

    from cbf.codec import frame
    from cbf.machine import DEFAULT, breach, machine_rules

    rnd = random.Random(13)
    pool = [math.nan, math.inf, 0.0, -1e30, 1e30, 1e-30]
    records = []
    for _ in range(600):
        _, command, arg, limit = rnd.choice(CASES)
        lim = SPEC.machine.limit(limit)
        value = rnd.choice([*pool, *_inside(lim), *lim.min, *lim.max])
        _, raw, _ = _record(command, arg, value, rnd.randrange(max(1, len(lim.axes))))
        records.append(cbf.Record(code=T.BY_NAME[command].code, raw_args=raw))
    data = seal(cbf.Cbf(cbf.new_header(T.DEFAULT_VERSION), tuple(records)))
    offsets, _ = frame(data)
    given = load_machine(_machine_file(tmp_path, machine_data(SPEC)))
    for machine in (None, given):
        m = machine or DEFAULT
        expected = []
        for i, rec in enumerate(cbf.decode(data).records):
            cmd = T.BY_CODE[rec.code]
            lay = cmd.layout_for_size(T.DEFAULT_VERSION, len(rec.raw_args))
            assert lay is not None
            values = rec.decode_args(T.DEFAULT_VERSION)
            for ch in T.checks_of("machine_limits"):
                for f, limit, positive in machine_rules(ch, cmd.name, lay.variant):
                    v = getattr(values, f.name)
                    # a repeated group (issue 25, point 3): each item an argument, the first out reported
                    for k, item in enumerate(v if f.per else (v,)):
                        text = breach(tuple(item) if isinstance(item, tuple) else (item,), m.limits[limit], positive)
                        if text is not None:
                            sev = ch["input_severity"] if machine is not None else ch["severity"]
                            at = offsets[i] + T.HEAD_SIZE + f.offset + k * f.elem_size * max(f.per, 1)
                            expected.append((ch["id"], sev, i, at))
                            break
        assert len(expected) > 10
        assert _machine_of(cbf.validate(data, machine=machine)) == expected


def test_cbfgen_diff_classifies_machine_changes(tmp_path: Path) -> None:
    """A default bound moves warnings only (not breaking); another unit breaks machine files."""
    from cbfgen.diff import diff

    sca = next(lim for lim in SPEC.machine.limits if not lim.axes)

    def wider(doc: dict[str, Any]) -> None:
        doc["machine"]["limits"][sca.name]["max"] = sca.max[0] * 2

    got = [(c.kind, c.breaking) for c in diff(SPEC, load(_variant(tmp_path, wider))).changes]
    assert got == [("machine_default_changed", False)]

    def other_unit(doc: dict[str, Any]) -> None:
        other = next(u for u in doc["units"] if u != sca.unit)
        doc["machine"]["limits"][sca.name]["unit"] = other
        for ch in doc["checks"]:
            ch["targets"] = [t for t in ch.get("targets", []) if t.get("limit") != sca.name] or ch.get("targets")
            if not ch["targets"]:
                del ch["targets"]

    got = [(c.kind, c.breaking) for c in diff(SPEC, load(_variant(tmp_path, other_unit))).changes
           if c.kind.startswith("machine_")]
    assert got == [("machine_limit_changed", True)]
