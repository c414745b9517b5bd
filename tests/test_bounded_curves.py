"""Curves of any sweep (issue 28, items 2-5): convert, stats and plot of a file that validates clean
finish in bounded memory and time whatever a curve's ndegrees; convert decides its segment count
before sampling; a nearly straight ARC is judged against the chord tolerance; titles are literal.

Commands are found by their roles in the model (cbf.tables), never by name.
"""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
from conftest import capped_run

import cbf
from cbf import geometry as G
from cbf import plot
from cbf import tables as T
from cbf.convert import ConvertError, convert, f32, linearise
from cbf.model import Cbf, Record, new_header

REPO = Path(__file__).resolve().parents[1]
ENV = dict(os.environ, PYTHONPATH=str(REPO / "generated" / "python"), OPENBLAS_NUM_THREADS="1", MPLBACKEND="Agg")
WRITABLE = [v.id for v in T.VERSIONS if v.writable]
FLT_MAX = float.fromhex("0x1.fffffep+127")
MEMORY_CAP = 1 << 30  # address space of each command: numpy and matplotlib fit well inside
TIME_CAP = 60.0  # seconds of wall time for each command (they take about one)


def _curve_pair(kind: str) -> tuple[T.CommandInfo, str, str]:
    """A curve command of ``kind`` some writable version has and another lacks (convert's case)."""
    for c in T.COMMANDS:
        if c.motion and c.motion["kind"] == kind:
            has = [v for v in WRITABLE if c.layouts_for(v)]
            lacks = [v for v in WRITABLE if not c.layouts_for(v)]
            if has and lacks:
                return c, has[0], lacks[0]
    pytest.skip(f"no writable version lacks a {kind} command")


def _args(cmd: T.CommandInfo, version: str, values: dict[str, Any]) -> Any:
    lay = cmd.layouts_for(version)[0]
    full: dict[str, Any] = {}
    for f in lay.args:
        if f.name in values:
            full[f.name] = values[f.name]
        elif f.kind == "float":
            full[f.name] = (0.0, 0.0, 1.0) if f.count == 3 else 0.0
        else:
            full[f.name] = "" if f.kind == "string" else bytes(f.size) if f.kind == "bytes" else 0
    return lay.cls(**full)


def _point(version: str, at: G.Vec) -> Record:
    cmd = next(c for c in T.COMMANDS if c.motion and c.motion["kind"] == "point" and c.layouts_for(version))
    assert cmd.motion is not None
    return Record.of(_args(cmd, version, {cmd.motion["end"]: at}))


def _huge(kind: str, degrees: float) -> tuple[Cbf, str]:
    """A file of a point and one curve of ``kind`` turning ``degrees``, and a version lacking it."""
    cmd, has, lacks = _curve_pair(kind)
    m = cmd.motion
    assert m is not None
    start = (10.0, 0.0, 0.0)
    values: dict[str, Any] = {m["start"]: start, m["center"]: (0.0, 0.0, 0.0), m["normal"]: (0.0, 0.0, 1.0),
                              m["degrees"]: degrees}
    if "length" in m:
        values[m["length"]] = 5.0
    model = Cbf(new_header(has, implant_descriptor="PN-28 SWEEP"), (_point(has, start),
                                                                     Record.of(_args(cmd, has, values))))
    return model, lacks


def _capped(argv: list[str]) -> subprocess.CompletedProcess[str]:
    return capped_run([sys.executable, "-m", "cbf", *argv], ENV, MEMORY_CAP, TIME_CAP)


@pytest.mark.parametrize(("kind", "degrees"), [("circle", 360_000_000.0), ("helix", FLT_MAX), ("circle", FLT_MAX)])
def test_a_huge_sweep_stays_bounded_in_convert_stats_and_plot(kind: str, degrees: float, tmp_path: Path) -> None:
    model, lacks = _huge(kind, degrees)
    data = cbf.encode(model)
    assert not [f for f in cbf.validate(data) if f.severity == "error"], "the file must validate clean"
    src = tmp_path / "huge.cbf"
    src.write_bytes(data)
    conv = _capped(["convert", str(src), "--to-version", lacks, "-o", str(tmp_path / "out.cbf")])
    assert conv.returncode == 2 and conv.stderr.count("\n") == 1, conv.stderr
    assert str(T.LIMITS["max_commands"]) in conv.stderr and "Traceback" not in conv.stderr
    st = _capped(["stats", "--json", str(src)])
    assert st.returncode == 0, st.stderr[-2000:]
    box = json.loads(st.stdout)["bounding_box_mm"]
    # the circle's box, analytically: radius 10 about the z axis, whatever the number of turns
    assert box["min"][:2] == [-10.0, -10.0] and box["max"][:2] == [10.0, 10.0], box
    pl = _capped(["plot", str(src), "-o", str(tmp_path / "huge.png")])
    assert pl.returncode == 0, pl.stderr[-2000:]


def test_curve_bounds_are_exact_without_sampling(monkeypatch: pytest.MonkeyPatch) -> None:
    """A helix's box from its stationary turns matches a dense sampling of a few turns, and a
    box of a billion turns costs no more than one of two turns (counted in points evaluated, not
    in wall time, so a loaded machine cannot fail it)."""
    c = G._circular((3.0, 1.0, 0.5), (0.0, 0.0, 0.0), (0.2, -0.3, 1.0), 3.0 * 360.0 + 70.0, 4.0)
    assert c is not None
    lo, hi = G.curve_bounds(c)
    n = 200_000
    pts = [c.at(k / n) for k in range(n + 1)]
    for i in range(3):
        assert min(p[i] for p in pts) >= lo[i] - 1e-12 and min(p[i] for p in pts) - lo[i] < 1e-7
        assert max(p[i] for p in pts) <= hi[i] + 1e-12 and hi[i] - max(p[i] for p in pts) < 1e-7
    two = G._circular((3.0, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), 720.0, 0.0)
    huge = G._circular((3.0, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), 360.0e9, 0.0)
    assert two is not None and huge is not None
    calls = [0]
    real_at = G.Curve.at

    def counted(self: G.Curve, t: float) -> G.Vec:
        calls[0] += 1
        return real_at(self, t)

    monkeypatch.setattr(G.Curve, "at", counted)
    G.curve_bounds(two)
    few, calls[0] = calls[0], 0
    (hlo, hhi) = G.curve_bounds(huge)
    assert 0 < calls[0] <= few, (calls[0], few)
    monkeypatch.undo()
    assert hlo[:2] == (-3.0, -3.0) and hhi[:2] == (3.0, 3.0)
    assert len(huge.points()) <= G.MAX_DRAW_POINTS


def test_convert_refuses_before_sampling(monkeypatch: pytest.MonkeyPatch) -> None:
    """Beyond the count field the refusal comes from the chord formula alone: no vertex is made."""
    import cbf.convert as C

    def no_vertices(*_: Any) -> list[G.Vec]:
        raise AssertionError("a vertex was made before the refusal")

    model, lacks = _huge("circle", FLT_MAX)
    monkeypatch.setattr(C, "_vertices", no_vertices)
    with pytest.raises(ConvertError, match=str(T.LIMITS["max_commands"])):
        convert(model, lacks, chord_tol=0.01)


def test_a_19_turn_helix_needs_few_passes(monkeypatch: pytest.MonkeyPatch) -> None:
    """The count comes from the chord formula, corrected by a bisection: a handful of measured
    passes at a tolerance where binary32 rounding moves the count by thousands (one segment at a
    time took 25 passes and 154 s for 63,655 segments)."""
    import cbf.convert as C

    cmd, has, _ = _curve_pair("helix")
    m = cmd.motion
    assert m is not None
    radius, turns = 50.0, 19
    center, normal = (100.3, -42.1, 7.7), (0.3, 0.2, 1.0)  # off the origin, tilted: rounding moves the count
    args = _args(cmd, has, {m["start"]: (center[0] + radius, center[1], center[2]), m["center"]: center,
                            m["normal"]: normal, m["degrees"]: 360.0 * turns, m["length"]: 20.0})
    curve = G.curve_of(m, args, None)
    assert curve is not None
    tol = 4.4e-5
    passes: list[int] = []
    real = C.chord_deviation

    def counted(c: G.Curve, pts: Any, samples: int = 16) -> float:
        passes.append(len(pts) - 1)
        assert len(passes) <= 10, f"more than 10 passes: {passes}"
        return real(c, pts, samples)

    monkeypatch.setattr(C, "chord_deviation", counted)
    pts, dev = linearise(curve, tol, False)  # the cost is bounded by the pass count above, not by a clock
    n = len(pts) - 1
    assert dev <= tol and n > C.analytic_segments(curve.angle, curve.radius, tol), passes  # rounding counts
    assert n - 1 in passes, passes  # the fewest: one less was measured and failed


def test_a_nearly_straight_arc_is_judged_against_the_tolerance() -> None:
    """(0,0,0), (100, 9.9e-5, 0), (200,0,0) at 5e-5 mm: its middle is 9.9e-5 mm off the line, so
    one segment is too few, and the deviation reported is the one measured."""
    cmd = next((c for c in T.COMMANDS if c.motion and "through" in c.motion
                and any(not c.layouts_for(v) for v in WRITABLE) and any(c.layouts_for(v) for v in WRITABLE)), None)
    if cmd is None:
        pytest.skip("no writable version lacks a three-point arc")
    has = next(v for v in WRITABLE if cmd.layouts_for(v))
    lacks = next(v for v in WRITABLE if not cmd.layouts_for(v))
    m = cmd.motion
    assert m is not None
    mid = (100.0, f32(9.9e-5), 0.0)
    arc = Record.of(_args(cmd, has, {m["start"]: (0.0, 0.0, 0.0), m["through"]: mid, m["end"]: (200.0, 0.0, 0.0)}))
    model = Cbf(new_header(has, implant_descriptor="PN-28 ARC"), (_point(has, (0.0, 0.0, 0.0)), arc))
    conv = convert(model, lacks, chord_tol=5e-5)
    assert conv.segments >= 2 and 0.0 < conv.max_deviation <= 5e-5, conv
    loose = convert(model, lacks, chord_tol=2e-4)  # one segment is within 2e-4: its true deviation
    assert loose.segments == 1 and math.isclose(loose.max_deviation, mid[1], rel_tol=0.02), loose.max_deviation
    assert cbf.validate(cbf.encode(conv.model)) == []
    # a middle binary32 cannot tell from the line is straight (M1), and its distance is reported
    flat_mid = (100.0, f32(1e-6), 0.0)
    flat = Record.of(_args(cmd, has, {m["start"]: (0.0, 0.0, 0.0), m["through"]: flat_mid,
                                      m["end"]: (200.0, 0.0, 0.0)}))
    straight = convert(Cbf(model.header, (model.records[0], flat)), lacks, chord_tol=5e-5)
    assert straight.segments == 1 and straight.max_deviation == pytest.approx(flat_mid[1], rel=1e-6)


@pytest.mark.parametrize("title", ["$\\foo$", "x$\\bad$.cbf", "50$ and 20$", "^_{}%#&"])
def test_titles_are_drawn_literally(title: str) -> None:
    """A title is text, never mathtext: a TeX-like title draws without a traceback."""
    pytest.importorskip("matplotlib")
    model, _ = _huge("circle", 90.0)
    svg = plot.render(model, "svg", title=title)
    assert svg.lstrip().startswith(b"<?xml")


def test_a_file_name_with_dollars_plots(tmp_path: Path) -> None:
    pytest.importorskip("matplotlib")
    model, _ = _huge("circle", 90.0)
    src = tmp_path / "x$\\bad$.cbf"
    src.write_bytes(cbf.encode(model))
    r = subprocess.run([sys.executable, "-m", "cbf", "plot", str(src), "-o", str(tmp_path / "p.png")], env=ENV,
                       capture_output=True, text=True, timeout=TIME_CAP)
    assert r.returncode == 0 and "Traceback" not in r.stderr, r.stderr[-2000:]


def test_the_bench_row_converts_a_helix(monkeypatch: pytest.MonkeyPatch) -> None:
    """`make bench`'s helix row (issue 28: 60,000 segments there; 2,000 here, the same code)."""
    sys.path.insert(0, str(REPO))
    import bench.bench as B

    monkeypatch.setattr(B, "HELIX_SEGMENTS", 2_000)
    result: dict[str, Any] = {"files": {}, "rows": {}, "targets": {}}
    B._helix_convert_row(result, 1)
    (name,) = result["files"]
    segments = int(name.split("(")[1].split(" ")[0].replace(",", ""))
    assert abs(segments - 2_000) <= 2_000 // 50, name  # the chord formula, backwards, gives about that many
    assert result["rows"]["Python convert (curve to segments)"][name]["n"] == 1
    assert "Python convert (curve to segments)" in B.table(result)


def test_legend_labels_from_the_file_are_literal() -> None:
    """A shape named like TeX colours the legend by its name as written (--color shape)."""
    pytest.importorskip("matplotlib")
    model, _ = _huge("circle", 90.0)
    start = next((c for c in T.COMMANDS if c.shape and c.shape["kind"] == "start" and c.layouts_for(model.version_id)),
                 None)
    if start is None or start.shape is None:
        pytest.skip("no command of this version starts a shape")
    rec = Record.of(_args(start, model.version_id, {start.shape["name"]: "$\\x$", start.shape["count"]: 1}))
    shaped = Cbf(model.header, (model.records[0], rec, model.records[1]))
    assert plot.render(shaped, "svg", "shape").lstrip().startswith(b"<?xml")
