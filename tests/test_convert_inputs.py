"""Issue 36, point 4: `cbf convert` reads what it says it reads. CUT input converts (it stores no
checksums: the encoder fills them, then they are judged as a file's), and geometry whose segment
count cannot be computed (an ARC of radius 1e14 mm was a ZeroDivisionError; a tolerance so small
that tol / radius vanishes) is refused with its record and the reason. Commands, keywords and
versions come from the spec tables, never from this file."""

from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import ENV, load_yaml

import cbf as cbf_lib
from cbf import tables as T
from cbf.convert import ConvertError, analytic_segments
from cbf.cut import keyword

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"
VALID = sorted(p for p in GOLDEN.glob("valid.*.cbf") if p.stat().st_size < 1 << 16)
WRITABLE = [v.id for v in T.VERSIONS if v.writable]
C = T.CUT


def cbf(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "cbf", *args], env=ENV, capture_output=True, text=True, timeout=120)


def _one_line_exit_2(res: subprocess.CompletedProcess[str]) -> str:
    assert res.returncode == 2, (res.returncode, res.stderr)
    assert "Traceback" not in res.stderr, res.stderr
    lines = res.stderr.strip().splitlines()
    assert len(lines) == 1, res.stderr
    return lines[0]


def _clean_profile(golden: Path) -> str:
    """A profile under which the golden file validates clean (its expectation says)."""
    expect = load_yaml(golden.with_suffix(".expect.yaml")).get("validate", {})
    return next((p for p in T.PROFILES if expect.get(p) == []), next(iter(T.PROFILES)))


@pytest.mark.parametrize("golden", VALID, ids=lambda p: p.stem)
def test_cut_input_converts_as_its_cbf_does(golden: Path, tmp_path: Path) -> None:
    profile = _clean_profile(golden)
    cut = tmp_path / "in.cut"
    assert cbf("decode", str(golden), "--to", "cut", "--profile", profile, "-o", str(cut)).returncode == 0
    version = cbf_lib.decode(golden.read_bytes()).version_id
    if not T.VERSION_BY_ID[version].writable:  # no encoder fills its stored fields: refused with a line
        line = _one_line_exit_2(cbf("convert", str(cut), "--to-version", WRITABLE[0], "-o", str(tmp_path / "b.cbf")))
        assert f"CUT text of version {version}" in line and "convert its CBF file" in line, line
        return
    done = 0
    for version in WRITABLE:
        from_cbf = cbf("convert", str(golden), "--profile", profile, "--to-version", version,
                       "-o", str(tmp_path / "a.cbf"))
        if from_cbf.returncode != 0:
            continue  # the file cannot go to this version (a refusal test_convert covers)
        from_cut = cbf("convert", str(cut), "--profile", profile, "--to-version", version,
                       "-o", str(tmp_path / "b.cbf"))
        assert from_cut.returncode == 0, from_cut.stderr
        assert (tmp_path / "a.cbf").read_bytes() == (tmp_path / "b.cbf").read_bytes()
        done += 1
    assert done, f"{golden.name} converts to no writable version"


def _vec(v: tuple[float, float, float]) -> str:
    return f"{C['vector_open']} {(C['vector_separator'] + ' ').join(format(x, '.0f') for x in v)} {C['vector_close']}"


def _through_command() -> tuple[T.CommandInfo, T.LayoutInfo, str, str]:
    """A command whose motion passes through a middle point (an arc), a version that has it with a
    layout of only its motion's points, and a writable version that lacks it (convert linearises)."""
    for cmd in T.COMMANDS:
        m = cmd.motion or {}
        if "through" not in m:
            continue
        for v in WRITABLE:
            lays = cmd.layouts_for(v)
            names = {m["start"], m["through"], m["end"]}
            if lays and {f.name for f in lays[0].args if not f.reserved} == names:
                lacking = next((w for w in WRITABLE if not cmd.layouts_for(w)), None)
                if lacking is not None:
                    return cmd, lays[0], v, lacking
    raise AssertionError("the spec has no command whose motion passes through a middle point")


def _point_command() -> T.CommandInfo:
    return next(c for c in T.COMMANDS if (c.motion or {}).get("kind") == "point")


def _arc_cut(radius: float, tmp: Path) -> tuple[Path, str]:
    cmd, lay, version, lacking = _through_command()
    m = cmd.motion or {}
    points = {m["start"]: (0.0, 0.0, 0.0), m["through"]: (radius, radius, 0.0), m["end"]: (2 * radius, 0.0, 0.0)}
    start = _point_command()
    lines = [f"{C['header_keyword']} X", f"{keyword(start)} {_vec((0.0, 0.0, 0.0))}",
             " ".join([keyword(cmd)] + [_vec(points[f.name]) for f in lay.args if not f.reserved])]
    if version != T.DEFAULT_VERSION:
        lines.insert(1, f"{C['extensions']['version_keyword']} {version}")
    path = tmp / "arc.cut"
    path.write_text("\n".join(lines) + "\n")
    return path, lacking


def test_a_huge_arc_is_refused_with_its_record_and_reason(tmp_path: Path) -> None:
    src, lacking = _arc_cut(1e14, tmp_path)
    assert cbf("encode", str(src), "-o", str(tmp_path / "arc.cbf")).returncode == 0  # it validates
    for inp in (src, tmp_path / "arc.cbf"):
        line = _one_line_exit_2(cbf("convert", str(inp), "--to-version", lacking, "-o", str(tmp_path / "o.cbf")))
        assert "record 1: " in line and "segments" in line and "raise --chord-tol" in line, line
        line = _one_line_exit_2(cbf("convert", str(inp), "--to-version", lacking, "--chord-tol", "5e-324",
                                    "-o", str(tmp_path / "o.cbf")))
        assert "record 1: " in line and "no computable segment count" in line, line
    assert not (tmp_path / "o.cbf").exists()


@pytest.mark.parametrize(("radius", "tol"), [(1e14, 1e-3), (1e38, 1e-3), (1.0, 1e-300), (3e38, 1e-30)])
def test_a_tiny_chord_step_is_counted_not_divided_by_zero(radius: float, tol: float) -> None:
    n = analytic_segments(math.pi, radius, tol)
    assert n > 1 << 16  # beyond any count field: linearise refuses it before making a point


@pytest.mark.parametrize(("angle", "radius", "tol"), [(math.pi, 1e14, 5e-324), (math.pi, 1.0, 0.0),
                                                      (math.inf, 1.0, 1e-3), (math.pi, math.nan, 1e-3)])
def test_no_computable_count_is_refused(angle: float, radius: float, tol: float) -> None:
    with pytest.raises(ConvertError, match="no computable segment count"):
        analytic_segments(angle, radius, tol)
