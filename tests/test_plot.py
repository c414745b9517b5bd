"""cbf plot: a known straight path lights the expected pixels and leaves the others blank."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest
from cli_many import run_many

from cbf import tables as T
from cbf.codec import decode
from cbf.model import Cbf, Record, new_header

pytest.importorskip("matplotlib")

from matplotlib.backends.backend_agg import FigureCanvasAgg  # noqa: E402
from matplotlib.colors import to_rgb  # noqa: E402

from cbf import plot  # noqa: E402

V = next(v.id for v in T.VERSIONS if v.writable)
GOLDEN = Path(__file__).resolve().parents[1] / "conformance" / "golden"


def _straight() -> Cbf:
    """POINT at the origin, then one LINE 100 mm along X, cutter never on."""
    point = next(c for c in T.COMMANDS if c.motion and c.motion["kind"] == "point" and c.layouts_for(V))
    line = next(c for c in T.COMMANDS if c.motion and c.motion["kind"] == "line" and "through" not in c.motion
                and not c.orientation and c.layouts_for(V))
    pm, lm = point.motion, line.motion
    assert pm and lm
    recs = [Record.of(point.layouts_for(V)[0].cls(**{pm["end"]: (0.0, 0.0, 0.0)})),
            Record.of(line.layouts_for(V)[0].cls(**{lm["start"]: (0.0, 0.0, 0.0), lm["end"]: (100.0, 0.0, 0.0)}))]
    return Cbf(new_header(V), recs)


def _near(rgb: np.ndarray, color: str, tol: float = 0.12) -> np.ndarray:
    return np.all(np.abs(rgb - np.array(to_rgb(color))) < tol, axis=-1)  # type: ignore[no-any-return]


def test_a_straight_path_lights_the_expected_pixels() -> None:
    fig = plot.figure(_straight())
    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    img = np.asarray(canvas.buffer_rgba())[:, :, :3].astype(float) / 255.0
    height = img.shape[0]
    top = next(ax for ax in fig.axes if ax.get_title() == plot.VIEWS[0][0])

    def pixel(x: float, y: float) -> tuple[int, int]:
        px, py = top.transData.transform((x, y))
        return int(round(height - py)), int(round(px))

    # on the line: the non-cutting colour, within a pixel of where the line runs
    for x in np.linspace(5, 95, 19):
        row, col = pixel(float(x), 0.0)
        window = img[row - 1:row + 2, col]
        assert _near(window, plot.NON_CUTTING).any(), (x, window)
        assert not _near(window, plot.CUTTING).any()
    # off the line, away from grid lines: blank
    for x in (13.0, 37.0, 63.0, 87.0):
        for y in (-30.0, -10.0, 10.0, 30.0):
            row, col = pixel(x, y)
            assert (img[row, col] > 0.93).all(), (x, y, img[row, col])
    # nothing else in the top view has the path's colour
    (x0, y0), (x1, y1) = top.bbox.get_points()
    r0, r1 = int(height - y1) + 2, int(height - y0) - 2
    c0, c1 = int(x0) + 2, int(x1) - 2
    rows, cols = np.nonzero(_near(img[r0:r1, c0:c1], plot.NON_CUTTING))
    line_row = pixel(50.0, 0.0)[0] - r0
    assert rows.size > 0
    assert np.abs(rows - line_row).max() <= 2
    start_col, end_col = pixel(0.0, 0.0)[1] - c0, pixel(100.0, 0.0)[1] - c0
    assert cols.min() >= start_col - 2 and cols.max() <= end_col + 2


def test_every_colour_mode_and_format_renders() -> None:
    model = _straight()
    assert plot.render(model, "png").startswith(b"\x89PNG")
    assert b"<svg" in plot.render(model, "svg", "phase")
    assert plot.render(model, "pdf", "cutter").startswith(b"%PDF")
    with pytest.raises(ValueError):
        plot.render(model, "bmp")


def test_one_figure_gives_every_format_the_bytes_it_gives_alone() -> None:
    """The gallery draws each file once and saves it in two formats (``plot.renderings``): the bytes
    are those ``render`` gives each format from a figure of its own, and the same on every call
    (SVG ids are hashed with a fixed salt, not matplotlib's random one)."""
    model = decode((GOLDEN / "valid.v3.all_commands.cbf").read_bytes())
    together = plot.renderings(model, plot.FORMATS, "shape", "all commands")
    assert list(together) == list(plot.FORMATS)
    for fmt in plot.FORMATS:
        assert together[fmt] == plot.render(model, fmt, "shape", "all commands"), fmt
    with pytest.raises(ValueError):
        plot.renderings(model, ("png", "bmp"))


def test_cli_plot_and_bad_output(tmp_path: Path) -> None:
    """Both command lines in one process (cli_many: each judged by its own exit code and output;
    a process of its own imports matplotlib, about 0.5 CPU s, for each)."""
    src = GOLDEN / "valid.v3.all_commands.cbf"
    out = tmp_path / "p.svg"
    (r, _), (bad, _) = run_many([["plot", str(src), "-o", str(out), "--color", "shape"],
                                 ["plot", str(src), "-o", str(tmp_path / "p.bmp")]], os.environ)
    assert r.returncode == 0, r.stderr
    assert out.read_bytes().lstrip().startswith(b"<?xml")
    assert bad.returncode == 2 and bad.stderr.count("\n") == 1 and "--format" in bad.stderr


def test_cbf_starts_without_matplotlib() -> None:
    """matplotlib made unimportable (as for a user without it), both command lines in one process."""
    small = str(GOLDEN / "valid.v3.small.cbf")
    (r, _), (stats, _) = run_many([["plot", small, "-o", "/tmp/unused-h7.png"], ["stats", small]], os.environ,
                                  hide=["matplotlib"])
    assert r.returncode == 2
    assert r.stderr.strip().endswith("pip install matplotlib") and r.stderr.count("\n") == 1
    assert stats.returncode == 0, stats.stderr
