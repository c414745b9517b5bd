"""cbf convert: curves to line segments within the chord tolerance, upgrades, relabels.

Commands are found by their roles in the model (cbf.tables), never by name.
"""

from __future__ import annotations

import math
import os
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from cli_many import run_many
from conftest import convert_fills
from hypothesis import given
from hypothesis import strategies as st

import cbf
from cbf import geometry as G
from cbf import tables as T
from cbf.convert import ConvertError, analytic_segments, convert, f32, linearise
from cbf.model import Cbf, Record, new_header

GOLDEN = Path(__file__).resolve().parents[1] / "conformance" / "golden"
TOL = T.TOL["position_mm"]
WRITABLE = [v.id for v in T.VERSIONS if v.writable]


def _curve(c: T.CommandInfo) -> bool:
    """A motion convert lines: a circle, a helix or a three-point arc (a point motion, of n points or one, is none)."""
    return bool(c.motion) and (c.motion["kind"] in ("circle", "helix") or "through" in c.motion)  # type: ignore[index]


def _lacking(version: str, has: str) -> list[T.CommandInfo]:
    return [c for c in T.COMMANDS if _curve(c) and not c.layouts_for(version) and c.layouts_for(has)]


# a writable version that lacks some curve, and a writable one that has it (a revision may add a version whose new
# command no other version has, a polyline of n points: it is no curve, and no version is picked for it)
LACKS, HAS = next((a, b) for a in WRITABLE for b in WRITABLE if a != b and _lacking(a, b))


def _curved_commands(kind: str) -> list[T.CommandInfo]:
    """The commands of a kind of motion that HAS has (_args draws their arguments in HAS's layout)."""
    return [c for c in T.COMMANDS if c.motion and c.motion["kind"] == kind and c.layouts_for(HAS)]


def _missing_in(version: str) -> list[T.CommandInfo]:
    """Curves HAS has and ``version`` lacks."""
    return _lacking(version, HAS)


def _args(cmd: T.CommandInfo, values: dict[str, Any]) -> Any:
    lay = cmd.layouts_for(HAS)[0]
    full = {}
    for f in lay.args:
        if f.name in values:
            full[f.name] = values[f.name]
        elif f.kind == "float":
            full[f.name] = (0.0, 0.0, 1.0) if f.count == 3 else 0.0
        elif f.kind == "string":
            full[f.name] = ""
        elif f.kind == "bytes":
            full[f.name] = bytes(f.size)
        else:
            full[f.name] = 0
    return lay.cls(**full)


def _v32(v: tuple[float, float, float]) -> tuple[float, float, float]:
    return (f32(v[0]), f32(v[1]), f32(v[2]))


_coord = st.floats(-100.0, 100.0, allow_nan=False).map(f32)
_unit = st.sampled_from([(1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0), (0.0, 0.0, -1.0), (1.0, 1.0, 0.0),
                         (0.0, -1.0, 1.0)])
_normal = st.one_of(_unit, st.tuples(_coord, _coord, _coord).filter(lambda v: G.norm(v) > 1e-3))


@st.composite
def circular(draw: st.DrawFn) -> tuple[T.CommandInfo, Any]:
    """A random circle or helix command of the model, in any plane."""
    kind = draw(st.sampled_from(["circle", "helix"]))
    cmd = draw(st.sampled_from(_curved_commands(kind)))
    m = cmd.motion
    assert m is not None
    center = draw(st.tuples(_coord, _coord, _coord))
    normal = _v32(draw(_normal))
    k = G.scale(normal, 1 / G.norm(normal))
    # a start point off the axis
    helper = (1.0, 0.0, 0.0) if abs(k[0]) < 0.9 else (0.0, 1.0, 0.0)
    u = G.cross(k, helper)
    u = G.scale(u, 1 / G.norm(u))
    radius = draw(st.floats(0.05, 80.0))
    start = _v32(G.add(center, G.scale(u, radius)))
    values = {m["start"]: start, m["center"]: center, m["normal"]: normal,
              m["degrees"]: f32(draw(st.floats(-720.0, 720.0).filter(lambda d: abs(d) > 0.5)))}
    if "length" in m:
        values[m["length"]] = f32(draw(st.floats(-50.0, 50.0)))
    return cmd, _args(cmd, values)


@st.composite
def arcs(draw: st.DrawFn) -> tuple[T.CommandInfo, Any]:
    """A random three-point arc command of the model (a line motion with a through point)."""
    cmd = draw(st.sampled_from([c for c in T.COMMANDS if c.motion and "through" in c.motion and c.layouts_for(HAS)]))
    m = cmd.motion
    assert m is not None
    center = draw(st.tuples(_coord, _coord, _coord))
    normal = draw(_normal)
    k = G.scale(normal, 1 / G.norm(normal))
    helper = (1.0, 0.0, 0.0) if abs(k[0]) < 0.9 else (0.0, 1.0, 0.0)
    e1 = G.cross(k, helper)
    e1 = G.scale(e1, 1 / G.norm(e1))
    e2 = G.cross(k, e1)
    radius = draw(st.floats(0.5, 80.0))
    a0 = draw(st.floats(0, 2 * math.pi))
    sweep = draw(st.floats(0.2, 2 * math.pi - 0.2))

    def on(t: float) -> tuple[float, float, float]:
        th = a0 + sweep * t
        return _v32(G.add(center, G.add(G.scale(e1, radius * math.cos(th)), G.scale(e2, radius * math.sin(th)))))

    values = {m["start"]: on(0.0), m["through"]: on(draw(st.floats(0.25, 0.75))), m["end"]: on(1.0)}
    return cmd, _args(cmd, values)


def _sampled_deviation(curve: G.Curve, pts: list[G.Vec]) -> float:
    """The largest distance from the curve, at 65 evenly spaced points of each segment's stretch
    of it (t = (k + j/64) / n), to that segment: G.point_segment_distance(curve.at(t), ...) in
    numpy, the same formulas in the same order (a plain loop of them was 70% of the test's time).
    The sampled points are checked against curve.at itself where each stretch begins."""
    n = len(pts) - 1
    t = (np.arange(n, dtype=np.float64)[:, None] + np.arange(65, dtype=np.float64)[None, :] / 64) / n
    if curve.curved:  # Curve.at: center + radius (cos(angle t) e1 + sin(angle t) e2) + t rise
        c, s = np.cos(curve.angle * t), np.sin(curve.angle * t)
        p = [curve.center[i] + curve.radius * (c * curve.e1[i] + s * curve.e2[i]) + t * curve.rise[i]
             for i in range(3)]
    else:  # start + t (end - start)
        p = [curve.start[i] + (curve.end[i] - curve.start[i]) * t for i in range(3)]
    begins = np.array([curve.at(k / n) for k in range(n)])
    assert np.allclose(np.stack([q[:, 0] for q in p], axis=1), begins, rtol=0, atol=1e-9), "not Curve.at"
    seg = np.array(pts, dtype=np.float64)
    a = [seg[:-1, i][:, None] for i in range(3)]  # each segment's ends, against its row of samples
    ab = [seg[1:, i][:, None] - a[i] for i in range(3)]
    den = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2]
    pa = [p[i] - a[i] for i in range(3)]
    dots = pa[0] * ab[0] + pa[1] * ab[1] + pa[2] * ab[2]
    with np.errstate(divide="ignore", invalid="ignore"):
        u = np.where(den == 0.0, 0.0, np.clip(dots / np.where(den == 0.0, 1.0, den), 0.0, 1.0))
    d = [p[i] - (a[i] + ab[i] * u) for i in range(3)]
    return float(np.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).max())


def _check_linearisation(cmd: T.CommandInfo, args: Any, tol: float) -> None:
    assert cmd.motion is not None
    curve = G.curve_of(cmd.motion, args, None)
    assert curve is not None
    exact_end = "end" in cmd.motion
    pts, dev = linearise(curve, tol, exact_end)
    n = len(pts) - 1
    # every vertex is binary32, the first is the start, an arc ends where it says
    assert all(_v32(p) == p for p in pts)
    assert pts[0] == curve.start
    if exact_end:
        assert pts[-1] == G.vec(getattr(args, cmd.motion["end"]))
    # deviation sampled densely along the true curve, independently of linearise
    worst = _sampled_deviation(curve, pts)
    assert worst <= tol * (1 + 1e-9), (worst, tol, n)
    assert dev <= tol
    if curve.curved:
        x = 1 - tol / curve.radius
        minimum = math.ceil(curve.angle / (2 * math.acos(x))) if x > -1 else math.ceil(curve.angle / (2 * math.pi))
        assert abs(n - minimum) <= 1, (n, minimum)
        assert n >= 1 and analytic_segments(curve.angle, curve.radius, tol) in (minimum, minimum - 1, minimum + 1)


@given(circular(), st.sampled_from([TOL, 0.01, 0.1, 1.0]))
def test_circles_and_helices_stay_within_the_tolerance(case: tuple[T.CommandInfo, Any], tol: float) -> None:
    _check_linearisation(*case, tol)


@given(arcs(), st.sampled_from([TOL, 0.01, 0.1]))
def test_arcs_stay_within_the_tolerance(case: tuple[T.CommandInfo, Any], tol: float) -> None:
    _check_linearisation(*case, tol)


def _file(version: str, *records: tuple[T.CommandInfo, Any]) -> Cbf:
    recs = [Record.of(a) for _, a in records]
    return Cbf(new_header(version, implant_descriptor="PN-1 CONVERT TEST"), recs)


def _point(at: tuple[float, float, float]) -> tuple[T.CommandInfo, Any]:
    cmd = next(c for c in T.COMMANDS if c.motion and c.motion["kind"] == "point" and c.layouts_for(HAS))
    assert cmd.motion is not None
    return cmd, _args(cmd, {cmd.motion["end"]: at})


def _same_layouts(model: Cbf, target: str) -> bool:
    """Every record's command has the same argument names in the target version (a relabel)."""
    for r in model.records:
        cmd = T.BY_CODE.get(r.code)
        src = cmd.layout_for_size(model.version_id, len(r.raw_args)) if cmd else None
        if cmd and src and cmd.layouts_for(target) and \
                [a.name for a in src.args] != [a.name for a in cmd.layouts_for(target)[0].args]:
            return False
    return True


def _goldens(version: str) -> list[Path]:
    out = []
    for p in sorted(GOLDEN.glob("valid.*.cbf")):
        m = cbf.decode(p.read_bytes())
        if m.version_id == version and not cbf.validate(p.read_bytes()):
            out.append(p)
    return out


@pytest.mark.parametrize("tol", [0.05, 0.5])
def test_golden_files_convert_and_validate_clean(tol: float) -> None:
    done = 0
    for path in _goldens(HAS):
        model = cbf.decode(path.read_bytes())
        try:
            conv = convert(model, LACKS, chord_tol=tol, fill=convert_fills(model, LACKS))
        except ConvertError as exc:
            assert "raise --chord-tol" in str(exc)  # a shape count that cannot hold the segments
            continue
        data = cbf.encode(conv.model)
        assert cbf.validate(data) == []
        assert conv.max_deviation <= tol
        back = cbf.decode(data)
        assert back.version_id == LACKS
        assert not any(r.command is None or not r.command.layouts_for(LACKS) for r in back.records)
        done += 1
    assert done >= 2


def test_continuity_is_exact_and_shape_counts_follow() -> None:
    shape_start = next(c for c in T.COMMANDS if c.shape and c.shape["kind"] == "start")
    shape_end = next(c for c in T.COMMANDS if c.shape and c.shape["kind"] == "end")
    circle_cmd = next(c for c in _missing_in(LACKS) if c.motion and c.motion["kind"] == "circle"
                      and not c.orientation)
    m = circle_cmd.motion
    assert m is not None and shape_start.shape and shape_end.shape
    circle = _args(circle_cmd, {m["start"]: (10.0, 0.0, 0.0), m["center"]: (0.0, 0.0, 0.0),
                                m["normal"]: (0.0, 0.0, 1.0), m["degrees"]: 90.0})
    names = {shape_start.shape["name"]: "S", shape_start.shape["count"]: 1}
    model = _file(HAS, _point((10.0, 0.0, 0.0)), (shape_start, _args(shape_start, names)), (circle_cmd, circle),
                  (shape_end, _args(shape_end, {shape_end.shape["name"]: "S", shape_end.shape["count"]: 1})))
    conv = convert(model, LACKS, chord_tol=0.01)
    n = analytic_segments(math.pi / 2, 10.0, 0.01)
    assert conv.segments in (n, n + 1)
    data = cbf.encode(conv.model)
    assert cbf.validate(data) == []
    recs = cbf.decode(data).typed_records()
    lines = [(r.command, a) for r, a in recs if r.command and r.command.motion and r.command.motion["kind"] == "line"]
    assert len(lines) == conv.segments
    prev = None
    for c, a in lines:
        assert c.motion is not None
        start, end = getattr(a, c.motion["start"]), getattr(a, c.motion["end"])
        if prev is not None:
            assert start == prev  # bit for bit: both are the same binary32 values
        prev = end
    counts = [getattr(a, r.command.shape["count"]) for r, a in recs if r.command and r.command.shape]
    assert counts == [conv.segments, conv.segments]


def test_relabel_back_is_plain() -> None:
    for path in _goldens(LACKS):
        model = cbf.decode(path.read_bytes())
        if not _same_layouts(model, HAS):  # a revision changed a layout: not a plain relabel
            with pytest.raises(ConvertError):
                convert(model, HAS)
            continue
        conv = convert(model, HAS)
        assert conv.segments == 0 and conv.max_deviation == 0.0
        out = cbf.decode(cbf.encode(conv.model))
        assert [r.raw_args for r in out.records] == [r.raw_args for r in model.records] or any(
            r.command and r.command.sets and "format_version" in r.command.sets for r in model.records)
        assert out.version_id == HAS


def test_format_version_stamp_is_rewritten() -> None:
    stamp = next(c for c in T.COMMANDS if c.sets and "format_version" in c.sets and c.layouts_for(HAS))
    arg = stamp.sets["format_version"] if stamp.sets else ""
    assert isinstance(arg, str)
    model = _file(HAS, (stamp, _args(stamp, {arg: HAS})))
    conv = convert(model, LACKS)
    (rec,) = cbf.decode(cbf.encode(conv.model)).typed_records()
    major, minor = T.parse_version(LACKS)
    assert getattr(rec[1], arg) == f"{major}.{minor}"


def _old_only() -> tuple[str, T.CommandInfo, T.LayoutInfo, T.LayoutInfo]:
    """A readable-only version, a command whose layout there lacks an argument of its writable layout."""
    for v in T.VERSIONS:
        if v.writable:
            continue
        for c in T.COMMANDS:
            for old in c.layouts_for(v.id):
                new = c.layouts_for(HAS)
                if new and any(not f.reserved and f.name not in {g.name for g in old.args} for f in new[0].args):
                    return v.id, c, old, new[0]
    pytest.skip("no older layout lacks an argument")


def test_upgrade_refuses_a_missing_argument_unless_filled() -> None:
    from cbf.testing import seal

    version, cmd, old, new = _old_only()
    values = {f.name: ("CP" if f.kind == "string" else bytes(f.size) if f.kind == "bytes" else 0) for f in old.args}
    major = T.VERSION_BY_ID[version].major
    record = Record(code=cmd.code, raw_args=cbf.fields.pack_args(old, old.cls(**values)))
    model = Cbf(new_header(f"{major}.0", implant_descriptor="PN-1 CONVERT TEST"), [record])
    model = cbf.decode(seal(model))
    missing = [f for f in new.args if not f.reserved and f.name not in {g.name for g in old.args}]
    with pytest.raises(ConvertError, match=f"record 0.*--fill {missing[0].name}="):
        convert(model, HAS)
    fill = {f.name: "0" for f in missing}
    conv = convert(model, HAS, fill=fill)
    assert conv.filled == len(missing)
    assert cbf.validate(cbf.encode(conv.model)) == []


def test_too_many_segments_are_refused() -> None:
    circle_cmd = next(c for c in _missing_in(LACKS) if c.motion and c.motion["kind"] == "circle")
    m = circle_cmd.motion
    assert m is not None
    big = _args(circle_cmd, {m["start"]: (5000.0, 0.0, 0.0), m["center"]: (0.0, 0.0, 0.0),
                             m["normal"]: (0.0, 0.0, 1.0), m["degrees"]: 360.0 * 40})
    model = _file(HAS, _point((5000.0, 0.0, 0.0)), (circle_cmd, big))
    with pytest.raises(ConvertError, match="65535|resolution"):
        convert(model, LACKS, chord_tol=0.002)


def test_cli_convert_reports_and_refuses(tmp_path: Path) -> None:
    """The command lines in order in one process (cli_many: each judged by its own exit code and
    output, as if alone; the validate reads what the first convert wrote)."""
    src = _goldens(HAS)[0]
    out = tmp_path / "out.cbf"
    fills = [f"--fill={k}={v}" for k, v in convert_fills(cbf.decode(src.read_bytes()), LACKS).items()]
    (r, _), (valid, _), (chord, _), (missing, _), (fill, _) = run_many([
        ["convert", str(src), "-o", str(out), "--to-version", LACKS, "--chord-tol", "0.5", *fills],
        ["validate", str(out)],
        ["convert", str(src), "-o", str(out), "--to-version", LACKS, "--chord-tol", "-1"],
        ["convert", str(tmp_path / "missing.cbf"), "-o", str(out), "--to-version", LACKS],
        ["convert", str(src), "-o", str(out), "--to-version", LACKS, "--fill", "nothing"],
    ], os.environ)
    assert r.returncode == 0, r.stderr
    assert "largest deviation" in r.stdout
    assert valid.returncode == 0
    assert chord.returncode == 2 and chord.stderr.count("\n") == 1
    assert missing.returncode == 2 and "no such file" in missing.stderr
    assert fill.returncode == 2 and "ARG=VALUE" in fill.stderr
