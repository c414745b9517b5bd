"""The Python engine's work does not grow with the number of records (issue 32): structure, not time,
so a loaded machine cannot make it pass or fail.

tests/engine_probe.py counts the calls that decode, validate and encode make on a file of n blocks and
on one of 8 n blocks, where a block holds every record layout of a version (each profile's), for every
version and profile of the spec; here on this spec, and on the spec every revision fixture of
tests/revisions/ revises together (its Python binding generated into a temporary folder).

- decode: the same Python-level calls at n and 8 n (its framing loop for files under
  codec.FAST_FRAME_BYTES calls one built-in a record, list.append: counted as 'c' and not bounded);
- validate, of the bytes: the same Python-level calls, but for a few a finding (a message is made
  when a finding is read); of the decoded model (framing reused): the same calls of any kind,
  built-in ones too, but for a few a finding;
- encode: at most a stated number of calls a record (encode is a record at a time by design: it
  packs each record's arguments).

Before the fix (31be96a..6b44d7d) validate called codec.field_checksum once a record (four Python
calls and more a record), and under the implib profile the file checksum fed one slice a record.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path
from typing import Any

import engine_probe
import pytest
from conftest import REPO, cbfgen_here
from revisions import drill

from cbfgen.loader import load
from cbfgen.loader.problems import SpecErrors

# A finding costs calls when it is read: its generator resumed, its message (a lambda, an f-string),
# the Finding, heapq.merge's key (measured 11 Python-level calls, 3 built-in ones).
PER_FINDING_PY = 16
PER_FINDING_ALL = 24
# encode (the writer: each record's arguments packed, checked and summed; then the file validated)
# and encode(keep_stored=True) (each record packed as stored). Measured 31 and 3 Python-level calls a
# record, 20 and 6 built-in ones, on this spec.
ENCODE_PY_PER_RECORD = 40
ENCODE_C_PER_RECORD = 30
STORED_PY_PER_RECORD = 4
STORED_C_PER_RECORD = 8


def _grew(key: str, small: dict[str, Any], large: dict[str, Any], what: str, kinds: tuple[str, ...],
          allowed: int) -> list[str]:
    a, b = sum(small[what][k] for k in kinds), sum(large[what][k] for k in kinds)
    if b - a <= allowed:
        return []
    more, found = large["records"] - small["records"], large["findings"] - small["findings"]
    return [f"{key}: {what} made {a} calls ({'+'.join(kinds)}) for {small['records']} records and {b} for "
            f"{large['records']}: {(b - a) / more:.2f} more a record ({found} more findings)"]


def problems(result: dict[str, Any]) -> list[str]:
    """What grows with the records where it must not, one line each (empty: the engine holds)."""
    out: list[str] = []
    for key, got in sorted(result.items()):
        small, large = got["small"], got["large"]
        more = large["records"] - small["records"]
        found = max(0, large["findings"] - small["findings"])
        assert more > 0, key
        out += _grew(key, small, large, "decode", ("py",), 0)
        out += _grew(key, small, large, "validate", ("py",), PER_FINDING_PY * found)
        out += _grew(key, small, large, "validate_model", ("py", "c"), PER_FINDING_ALL * found)
        for what, py, c in (("encode_stored", STORED_PY_PER_RECORD, STORED_C_PER_RECORD),
                            ("encode", ENCODE_PY_PER_RECORD, ENCODE_C_PER_RECORD)):
            if what in small and what in large:
                out += _grew(key, small, large, what, ("py",), py * more)
                out += _grew(key, small, large, what, ("c",), c * more)
    return out


@pytest.fixture(scope="module")
def here() -> dict[str, Any]:
    return engine_probe.probe(2)


def test_every_layout_takes_part() -> None:
    from cbf import tables as T

    every = {(v.id, id(lay)) for v in T.VERSIONS for cmd in T.COMMANDS for lay in cmd.layouts_for(v.id)}
    assert every and engine_probe.layouts_in_blocks() == every
    for v in T.VERSIONS:
        for profile in T.PROFILES:
            held = {(r.code, len(r.raw_args)) for r in engine_probe.block(v.id, profile)}
            want = {(c.code, lay.size) for c in T.COMMANDS for lay in c.layouts_for(v.id)
                    if lay.accepted_under(profile)}
            assert held == want, (v.id, profile)


def test_the_probe_measures_every_version_and_profile(here: dict[str, Any]) -> None:
    from cbf import tables as T

    assert {k.split("/")[0] for k in here} == {v.id for v in T.VERSIONS if engine_probe.block(v.id, "default")}
    assert {k.split("/")[1] for k in here} == set(T.PROFILES)
    # the writer ran on the files of the writable versions (they validate: it would refuse them else)
    assert any("encode" in got["small"] for got in here.values())
    assert not [got["small"]["encode_refused"] for got in here.values() if "encode_refused" in got["small"]]


def test_calls_do_not_grow_with_records(here: dict[str, Any]) -> None:
    assert problems(here) == []


def test_the_guard_fails_on_a_per_record_path() -> None:
    """The guard sees a Python call a record: a copy of a measure with one call more a record fails."""
    small = {"records": 10, "findings": 0, "decode": {"py": 12, "c": 40}, "validate": {"py": 100, "c": 90},
             "validate_model": {"py": 100, "c": 80}, "encode_stored": {"py": 30, "c": 60}}
    same = {**small, "records": 80}
    per_record = {**small, "records": 80, "validate": {"py": 170, "c": 90}}
    assert problems({"v/p": {"small": small, "large": same}}) == []
    assert len(problems({"v/p": {"small": small, "large": per_record}})) == 1
    many = {**per_record, "findings": 70}  # a finding a record, a call each: allowed
    assert problems({"v/p": {"small": small, "large": many}}) == []


def _loads(path: Path) -> bool:
    try:
        load(path)
    except SpecErrors:
        return False
    return True


def _revised_together(tmp: Path) -> Path:
    """The spec every fixture of tests/revisions/ revises, one on top of the other (as the quick drill). A
    fixture that this spec refuses alone is left out: a revision already made it (a spec that deprecates
    VERSION/implib refuses the deprecation fixture's second deprecation of it), and whether each fixture applies
    to this spec is tests/test_revision_drill.py's to judge, not this test's; one that loads alone but not on
    top of the others fails here."""
    base = path = REPO / "spec" / "cbf.yaml"
    for fx_path in drill.fixtures():
        doc = drill.read_spec(path)  # parsed once: the fixture renders for it, then revised_spec edits it
        try:
            fx = drill.load_fixture(fx_path, doc)
        except drill.FixtureUnmet:  # its stated precondition does not hold here (drill.unmet): left out
            continue
        new = drill.revised_spec(fx, path, tmp / fx.name, doc)
        if not _loads(new) and not _loads(drill.revised_spec(fx, base, tmp / f"{fx.name}.alone")):
            continue
        path = new
    assert path != base, "no fixture of tests/revisions/ applies to this spec"
    return path


def test_calls_do_not_grow_with_records_on_every_revision(tmp_path: Path) -> None:
    assert drill.fixtures(), "no revision fixture found"
    spec = _revised_together(tmp_path)
    out = tmp_path / "gen"
    code, _, err = cbfgen_here("--spec", str(spec), "--out", str(out), "--only", "python", "--no-ksc")
    assert code == 0, err
    probe = subprocess.run([sys.executable, str(REPO / "tests" / "engine_probe.py"), "2"], capture_output=True,
                           text=True, check=False, cwd=tmp_path,
                           env={"PYTHONPATH": str(out / "python"), "PATH": "/usr/bin:/bin"})
    assert probe.returncode == 0, probe.stderr[-3000:]
    result = json.loads(probe.stdout)
    assert result
    assert problems(result) == []
