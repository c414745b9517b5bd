"""The drawn toolpath of `cbf-c dump --path` (cbf_motion_path, runtime/path.c), which the workbench page
draws (issue 34: curves drawn with the engine's own geometry): on every golden file it gives, for each
motion record, the points the Python codec's drawing gives (cbf.geometry: walk, Curve.points), and a curve
is a curve: an arc's points lie on the circle through its start, middle and end, not on its chord."""

from __future__ import annotations

import functools
import math
import subprocess
from pathlib import Path

import pytest
from c_programs import built

from cbf import codec
from cbf import geometry as G
from cbf.errors import CbfError

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"


@functools.cache
def _c_paths(path: Path) -> dict[int, list[tuple[float, ...]]]:
    res = subprocess.run([str(built("cbf-c")), "dump", "--path", str(path)], capture_output=True, text=True)
    assert res.returncode == 0, res.stderr
    out = {}
    for line in res.stdout.splitlines():
        index, *points = line.split(" ")
        out[int(index)] = [tuple(float(x) for x in p.split(",")) for p in points]
    return out


def _python_paths(path: Path) -> dict[int, list[G.Vec]]:
    return {s.index: s.curve.points() for s in G.walk(codec.decode(path.read_bytes())) if s.curve is not None}


def _close(a: tuple[float, ...], b: G.Vec) -> bool:
    # %.9g as printed: nine significant digits of the larger coordinate
    scale = max(1.0, *(abs(x) for x in a), *(abs(x) for x in b))
    return all(abs(x - y) <= 2e-8 * scale for x, y in zip(a, b, strict=True))


def _readable() -> list[Path]:
    files = []
    for f in sorted(GOLDEN.glob("*.cbf")):
        try:
            codec.decode(f.read_bytes())
        except CbfError:  # a file the codec cannot frame has no toolpath to compare
            continue
        files.append(f)
    return files


def test_cbf_c_draws_each_motion_as_the_python_codec_does_on_every_golden_file() -> None:
    curved = 0
    differ = []
    for f in _readable():
        want = _python_paths(f)
        got = _c_paths(f)
        if sorted(want) != sorted(got):
            differ.append(f"{f.name}: records drawn: cbf-c {sorted(got)}, cbf {sorted(want)}")
            continue
        for i, pts in want.items():
            curved += len(pts) > 2
            if len(pts) != len(got[i]) or not all(_close(a, b) for a, b in zip(got[i], pts, strict=True)):
                differ.append(f"{f.name} record {i}: cbf-c {got[i][:3]}..., cbf {pts[:3]}...")
    assert curved > 0, "no golden file has a curve: the comparison proves nothing"
    assert not differ, "\n".join(differ[:5])


def test_an_arc_is_drawn_on_its_circle() -> None:
    # an arc through a middle point (the spec's motion role `through`), as cbf.geometry reads it
    arcs = [(f, s.index, s.curve) for f in _readable() for s in G.walk(codec.decode(f.read_bytes()))
            if s.curve is not None and s.cmd.motion is not None and "through" in s.cmd.motion and s.curve.curved]
    assert arcs, "no golden file has an arc through a middle point"
    for f, index, curve in arcs:
        pts = _c_paths(f)[index]
        c, r = curve.center, curve.radius
        assert len(pts) > 2, f"{f.name} record {index}: drawn as a chord"
        for p in pts:
            assert math.isclose(math.dist(p, c), r, rel_tol=1e-6, abs_tol=1e-6), (f.name, index, p)
        assert pts[0] == pytest.approx(curve.start, rel=1e-7, abs=1e-7)
        assert pts[-1] == pytest.approx(curve.end, rel=1e-7, abs=1e-7)
