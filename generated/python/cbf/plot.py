"""`cbf plot`: the toolpath drawn with matplotlib (the `plot` extra).

Four views of one cube around the path, in mm with equal aspect: an
isometric 3-D view and the top (X-Y), front (X-Z) and side (Y-Z)
projections. Arcs, circles and helices are drawn from their geometry
(decision M1), every 5 degrees of turn, at most geometry.MAX_DRAW_POINTS a curve
whatever its sweep (a circle of many turns is drawn as one turn and the rest). Moves are coloured cutting /
non-cutting (M2), or by phase, shape or cutter; checkpoints and shape starts
are marked; one legend for the figure. Titles and labels are literal text, never mathtext.

matplotlib is imported here only, so ``cbf`` starts fast and works without it.
"""

from __future__ import annotations

import io
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

from . import geometry as G
from .model import Cbf

COLOR_MODES = ("cut", "phase", "shape", "cutter")
FORMATS = ("png", "svg", "pdf")
CUTTING = "#d62728"
NON_CUTTING = "#1f77b4"
CHECKPOINT = "#2ca02c"
SHAPE_START = "#ff7f0e"
PALETTE = ("#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf",
           "#ff7f0e")
# (title, horizontal axis, vertical axis) of the three projections
VIEWS = (("top (X-Y)", 0, 1), ("front (X-Z)", 0, 2), ("side (Y-Z)", 1, 2))
_AXIS = "XYZ"
# matplotlib names SVG clip paths and markers by a hash salted with a random UUID unless the
# salt is fixed: a fixed salt makes the same figure the same SVG bytes on every run.
SVG_HASH_SALT = "cbf plot"


class PlotUnavailable(RuntimeError):
    """matplotlib is not installed."""


@dataclass(frozen=True)
class Path:
    """What the figure draws: polylines with their category, and the marks."""

    lines: list[tuple[str, list[G.Vec]]]
    checkpoints: list[tuple[int, G.Vec]]
    shape_starts: list[tuple[int, str, G.Vec]]


def _category(step: G.Step, mode: str) -> str:
    st = step.state
    if mode == "cut":
        return "cutting" if st.cutting else "non-cutting"
    value = {"phase": st.phase, "shape": st.shape, "cutter": st.cutter}[mode]
    return f"{mode} {value}" if value else f"no {mode}"


def path_of(model: Cbf, mode: str = "cut", steps: Iterable[G.Step] | None = None) -> Path:
    """What to draw of ``model``; ``steps`` is ``G.walk(model)`` when the caller has walked it already."""
    if mode not in COLOR_MODES:
        raise ValueError(f"colour mode {mode!r}: one of {', '.join(COLOR_MODES)}")
    lines: list[tuple[str, list[G.Vec]]] = []
    checkpoints: list[tuple[int, G.Vec]] = []
    shapes: list[tuple[int, str, G.Vec]] = []
    pos: G.Vec | None = None
    pending_shapes: list[tuple[int, str]] = []
    pending_checks: list[int] = []
    for step in G.walk(model) if steps is None else steps:
        cmd = step.cmd
        if cmd.progress:
            if pos is not None:
                checkpoints.append((step.index, pos))
            else:  # before any motion: marked where the path starts
                pending_checks.append(step.index)
        if cmd.shape and cmd.shape["kind"] == "start":
            pending_shapes.append((step.index, str(getattr(step.args, cmd.shape["name"]))))
        c = step.curve
        if c is None:
            continue
        for i, name in pending_shapes:
            shapes.append((i, name, c.start))
        pending_shapes = []
        checkpoints.extend((i, c.start) for i in pending_checks)
        pending_checks = []
        pts = c.points()
        cat = _category(step, mode)
        if lines and lines[-1][0] == cat and lines[-1][1][-1] == pts[0]:
            lines[-1][1].extend(pts[1:])  # one polyline while the category holds
        else:
            lines.append((cat, list(pts)))
        pos = c.end
    return Path(lines, checkpoints, shapes)


def _colors(path: Path, mode: str) -> dict[str, str]:
    if mode == "cut":
        return {"cutting": CUTTING, "non-cutting": NON_CUTTING}
    cats = list(dict.fromkeys(cat for cat, _ in path.lines))
    return {cat: PALETTE[i % len(PALETTE)] for i, cat in enumerate(cats)}


def _cube(path: Path) -> tuple[G.Vec, float]:
    pts = [p for _, line in path.lines for p in line]
    box = G.bounds(pts) or ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0))
    lo, hi = box
    center = ((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2)
    span = max(hi[i] - lo[i] for i in range(3))
    return center, (span if span > 0 else 1.0) * 1.1


def _literal(text: str) -> str:
    """``text`` for a legend label, which matplotlib reads as mathtext between dollars: each
    dollar escaped, so a phase, shape or cutter name is drawn as written."""
    return text.replace("$", "\\$")


def figure(model: Cbf, mode: str = "cut", title: str = "", steps: Iterable[G.Step] | None = None) -> Any:
    """A matplotlib Figure of the path (no pyplot, no global state); ``steps`` as for ``path_of``."""
    try:
        from matplotlib.collections import LineCollection
        from matplotlib.figure import Figure
        from matplotlib.lines import Line2D
        from mpl_toolkits.mplot3d.art3d import Line3DCollection  # type: ignore[import-untyped]
    except ImportError:
        raise PlotUnavailable("cbf plot needs matplotlib: pip install matplotlib") from None
    path = path_of(model, mode, steps)
    colors = _colors(path, mode)
    center, span = _cube(path)
    lims = [(center[i] - span / 2, center[i] + span / 2) for i in range(3)]
    fig = Figure(figsize=(10, 10), dpi=100)
    if title:  # literal text: a title or file name with $ is never mathtext (issue 28)
        fig.suptitle(title, parse_math=False)
    iso = fig.add_subplot(2, 2, 1, projection="3d")
    iso.set_title("isometric")
    iso.view_init(elev=35.264, azim=-45)
    segs3 = [line for _, line in path.lines]
    iso.add_collection3d(Line3DCollection(segs3, colors=[colors[c] for c, _ in path.lines], linewidths=1.0),
                         autolim=False)
    iso.set_xlim(*lims[0])
    iso.set_ylim(*lims[1])
    iso.set_zlim(*lims[2])
    iso.set_box_aspect((1, 1, 1))
    iso.set_xlabel("X (mm)")
    iso.set_ylabel("Y (mm)")
    iso.set_zlabel("Z (mm)")
    for n, (name, h, v) in enumerate(VIEWS, start=2):
        ax = fig.add_subplot(2, 2, n)
        ax.set_title(name)
        segs = [[(p[h], p[v]) for p in line] for _, line in path.lines]
        ax.add_collection(LineCollection(segs, colors=[colors[c] for c, _ in path.lines], linewidths=1.0))
        if path.checkpoints:
            ax.plot([p[h] for _, p in path.checkpoints], [p[v] for _, p in path.checkpoints], "D",
                    color=CHECKPOINT, markersize=5, linestyle="none")
        if path.shape_starts:
            ax.plot([p[h] for _, _, p in path.shape_starts], [p[v] for _, _, p in path.shape_starts], "^",
                    color=SHAPE_START, markersize=6, linestyle="none")
        ax.set_xlim(*lims[h])
        ax.set_ylim(*lims[v])
        ax.set_aspect("equal", adjustable="box")
        ax.set_xlabel(f"{_AXIS[h]} (mm)")
        ax.set_ylabel(f"{_AXIS[v]} (mm)")
        ax.grid(True, linewidth=0.3, alpha=0.5)
    for pts, marker, color in ((path.checkpoints, "D", CHECKPOINT), (path.shape_starts, "^", SHAPE_START)):
        if pts:
            xs = [t[-1] for t in pts]
            iso.plot([p[0] for p in xs], [p[1] for p in xs], [p[2] for p in xs], marker, color=color,
                     markersize=5, linestyle="none")
    handles = [Line2D([], [], color=col, label=_literal(cat)) for cat, col in colors.items()]
    handles.append(Line2D([], [], marker="D", color=CHECKPOINT, linestyle="none",
                          label=f"checkpoint ({len(path.checkpoints)})"))
    handles.append(Line2D([], [], marker="^", color=SHAPE_START, linestyle="none",
                          label=f"shape start ({len(path.shape_starts)})"))
    fig.legend(handles=handles, loc="lower center", ncol=min(6, len(handles)), frameon=False)
    fig.subplots_adjust(left=0.07, right=0.97, top=0.93, bottom=0.09, wspace=0.25, hspace=0.25)
    return fig


def renderings(model: Cbf, fmts: Sequence[str], mode: str = "cut", title: str = "",
               steps: Iterable[G.Step] | None = None) -> dict[str, bytes]:
    """The figure in each of ``fmts`` (PNG, SVG, PDF bytes), drawn from ONE figure: the same bytes
    as ``render`` gives each format alone. Deterministic: no timestamps in SVG/PDF metadata, and
    SVG ids hashed with a fixed salt."""
    for fmt in fmts:
        if fmt not in FORMATS:
            raise ValueError(f"format {fmt!r}: one of {', '.join(FORMATS)}")
    fig = figure(model, mode, title, steps)
    from matplotlib import rc_context

    out: dict[str, bytes] = {}
    with rc_context({"svg.hashsalt": SVG_HASH_SALT}):
        for fmt in fmts:
            buf = io.BytesIO()
            meta: dict[str, Any] = {"png": {"Software": None}, "svg": {"Date": None},
                                    "pdf": {"CreationDate": None}}[fmt]
            fig.savefig(buf, format=fmt, metadata=meta)
            out[fmt] = buf.getvalue()
    return out


def render(model: Cbf, fmt: str, mode: str = "cut", title: str = "") -> bytes:
    """The figure as PNG, SVG or PDF bytes (deterministic, see ``renderings``)."""
    return renderings(model, (fmt,), mode, title)[fmt]
