"""Repeated argument groups (issue 25, point 3): the drill fixture tests/revisions/pending/polyline.yaml
(a command whose argument is n points, nb = 12 n) applied to a copy of the spec, the Python package
generated from it, and, in that package: binary, CUT and canonical JSON round trips for random n
(hypothesis, derandomised under the ci profile), the nb that no n tiles refused by the writer and
refused by the writer and the CUT reader, and continuity through the polyline's last point.

The loader refuses groups while a binding lacks them (registry.REPEAT_BINDINGS); the Python
binding carries them, so this test lets the loader through for Python alone.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
import yaml
from conftest import HYPOTHESIS_PROFILE, REPO, dump_yaml, spec_doc
from revisions.drill import apply_edit, load_fixture, render

from cbfgen import loader
from cbfgen.emit import python as py_emit
from cbfgen.model import Spec

FIXTURE = REPO / "tests" / "revisions" / "pending" / "polyline.yaml"

SCRIPT = r"""
import math, struct, sys
from hypothesis import given, settings, strategies as st
import cbf
from cbf import tables as T
from cbf.errors import EncodeError
from cbf.layouts import CommandCode, Line, Point
from cbf.model import Cbf, Record, new_header

NAME = sys.argv[1]
cmd = T.BY_NAME[NAME]
lays = [lay for lay in cmd.layouts if lay.n is not None]
grp = lays[0].repeated
LO, HI = grp.repeat
K = grp.size // grp.items   # bytes per item, from the tables
FIXED = lays[0].size - K * lays[0].n
cls = lays[0].cls
version = next(v for v in T.VERSIONS if v.writable and cmd.layouts_for(v.id))
vtext = f"{version.major}.{version.minor or 0}"
f32 = st.floats(-500, 500, width=32)
vec = st.tuples(f32, f32, f32)

@settings(max_examples=int(sys.argv[2]), derandomize=sys.argv[3] == "ci", database=None, deadline=None)
@given(st.integers(LO, HI).flatmap(lambda n: st.lists(vec, min_size=n, max_size=n)))
def round_trip(points):
    model = Cbf(new_header(vtext, implant_descriptor="PN-1"),
                (Record.of(Point(point=(0.0, 0.0, 0.0))), Record.of(cls(points=tuple(points))),
                 Record.of(Line(start=points[-1], end=(1.0, 1.0, 1.0)))))
    data = cbf.encode(model)
    back = cbf.decode(data)
    rec = back.records[1]
    assert len(rec.raw_args) == FIXED + K * len(points)          # nb = fixed + k n
    assert rec.decode_args(back.version_id) == cls(points=tuple(points))
    assert cbf.encode(back) == data                               # encode(decode(b)) == b
    text = cbf.to_cut(back)
    line = text.splitlines()[-2]
    assert line.split()[0] == NAME.lower() and line.count("<") == len(points), line
    assert cbf.encode(cbf.from_cut(text)) == data                 # CUT written and read back exactly
    assert cbf.encode(cbf.from_canonical(cbf.to_canonical(back))) == data
    # continuity runs through the polyline: the LINE starts at its last point
    assert not [f for f in cbf.validate(data) if f.check == "6.4.5"]

round_trip()

# n outside min..max: the writer refuses, naming the group (the golden cases hold the validator's findings)
for n in (LO - 1, HI + 1):
    if n < 0 or FIXED + K * n > T.LIMITS["max_arg_size"]:
        continue
    try:
        cbf.encode(Cbf(new_header(vtext), (Record.of(cls(points=((1.0, 2.0, 3.0),) * n)),)))
    except EncodeError as exc:
        assert "points" in str(exc) and f"{LO} to {HI}" in str(exc), exc
    else:
        raise AssertionError(f"n={n} encoded")
# a LINE that starts at the polyline's FIRST point is discontinuous (the end is the last point)
# (the writer refuses it, naming the continuity check and the distance from the last point)
pts = ((1.0, 2.0, 3.0), (50.0, 50.0, 50.0))
cont = [c["id"] for c in T.CHECKS if c["kind"] == "continuity"]
try:
    cbf.encode(Cbf(new_header(vtext), (Record.of(Point(point=(0.0, 0.0, 0.0))), Record.of(cls(points=pts)),
                                       Record.of(Line(start=pts[0], end=(1.0, 1.0, 1.0))))))
except EncodeError as exc:
    away = f"{math.dist(pts[0], pts[-1]):.4f}"
    assert f"fail check {cont[0]}" in str(exc) and "record 2" in str(exc) and away in str(exc), exc
else:
    raise AssertionError("a LINE from the polyline's first point was written")
try:
    cbf.from_cut(f"{NAME.lower()}\n")
except Exception as exc:
    assert "0 items" in str(exc), exc
else:
    raise AssertionError("an empty group was read")
print("ok")
"""


def _revised_spec(tmp: Path) -> Path:
    doc = spec_doc()
    fx = load_fixture(FIXTURE, doc)
    for edit in fx.edits:
        if "file" not in edit:
            apply_edit(doc, edit)
    path = tmp / "cbf.yaml"
    path.write_text(dump_yaml(doc), encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def package(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, str]:
    tmp = tmp_path_factory.mktemp("polyline")
    spec_path = _revised_spec(tmp)
    with pytest.MonkeyPatch.context() as mp:
        # every binding but Python is still refused by the gate: let it through for Python alone
        mp.setattr(loader, "repeat_unsupported", lambda: ())
        spec: Spec = loader.load(spec_path)
    for rel, data in py_emit.emit(spec).items():
        out = tmp / "gen" / rel
        out.parent.mkdir(parents=True, exist_ok=True)
        out.write_bytes(data)
    name = render("${name:POLYLINE}", spec_doc(), "test")
    return tmp / "gen" / "python", name


def test_the_gate_refuses_groups_while_a_binding_lacks_them(tmp_path: Path) -> None:
    with pytest.raises(loader.SpecError, match="a repeated argument group is not implemented by the"):
        loader.load(_revised_spec(tmp_path))


def test_round_trips_for_random_n(package: tuple[Path, str]) -> None:
    pkg, name = package
    profile = HYPOTHESIS_PROFILE
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(pkg), *sys.path]))
    run = subprocess.run([sys.executable, "-c", SCRIPT, name, "60", profile], env=env, capture_output=True,
                         text=True, cwd=pkg)
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-4000:]
    assert run.stdout.strip().endswith("ok")


def test_diff_classifies_groups(tmp_path: Path) -> None:
    """cbfgen diff: the new variable command is a command_added whose size says nb = fixed + k n; a
    changed min or max of an existing version's group changes which files are judged valid: breaking."""
    from cbfgen.diff import diff

    base = tmp_path / "base"
    base.mkdir()
    new_path = _revised_spec(base)
    narrowed = yaml.safe_load(new_path.read_text(encoding="utf-8"))
    name = render("${name:POLYLINE}", spec_doc(), "test")
    group = next(c for c in narrowed["commands"] if c["name"] == name)["layouts"][0]["args"][-1]
    group["repeat"]["max"] -= 1
    narrow_path = tmp_path / "narrow.yaml"
    narrow_path.write_text(dump_yaml(narrowed), encoding="utf-8")
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(loader, "repeat_unsupported", lambda: ())
        old, new, narrow = loader.load(REPO / "spec" / "cbf.yaml"), loader.load(new_path), loader.load(narrow_path)
    added = [c for c in diff(old, new).changes if c.kind == "command_added"]
    assert added and all(" n (" in c.detail for c in added)
    changed = [c for c in diff(new, narrow).changes if c.kind == "field_repeat_changed"]
    assert changed and all(c.breaking for c in changed)


def test_kaitai_reads_the_group_count_from_nb(tmp_path: Path) -> None:
    """The .ksy: the group as `repeat: expr` with n from the argument substream's size, one args case per
    nb the group takes, and the arg_size rule accepting exactly nb = fixed + k n for n in min..max."""
    from cbfgen.emit.kaitai import build

    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(loader, "repeat_unsupported", lambda: ())
        spec = loader.load(_revised_spec(tmp_path))
    ksy = build(spec)
    cmd = next(c for c in spec.commands if any(lay.repeated is not None for lay in c.layouts))
    lay = next(lay for lay in cmd.layouts if lay.repeated is not None)
    rep = lay.repeated
    assert rep is not None and rep.repeat is not None
    seq = ksy["types"]["args_" + cmd.name.lower()]["seq"]
    assert seq[-1]["repeat"] == "expr"
    assert seq[-1]["repeat-expr"] == f"(_io.size - {lay.size}) / {rep.size}" + (
        f" * {rep.count}" if rep.count > 1 else "")
    record = {a["id"]: a for a in ksy["types"]["record"]["seq"]}
    cases = record["args"]["type"]["cases"]
    vi = 1 + [v.id for v in spec.versions].index(lay.versions[0])
    taken = {nb for nb in range(256) if cases.get(cmd.code * 65536 + nb * 256 + vi) == "args_" + cmd.name.lower()}
    assert taken == set(lay.sizes)
    lo, hi = lay.size + rep.size * rep.repeat[0], lay.size + rep.size * rep.repeat[1]
    size_rule = next(a for a in record.values() if a.get("valid", {}).get("expr", "").count("?"))
    assert f"(_ >= {lo} and _ <= {hi} and (_ - {lay.size}) % {rep.size} == 0)" in size_rule["valid"]["expr"]
