"""The toolpath gallery: `cbf plot` and `cbf stats` of every file that validates clean.

    python -m cbf.gallery OUT_DIR FILE.cbf ...

writes, for each file that validates with no finding under some profile,
NAME.png, NAME.svg, NAME.stats.txt and NAME.stats.json, and an index.md
that shows each image beside its stats. Files that do not validate are
listed at the end of index.md with the reason, and drawn nowhere.
`make gallery` runs it on conformance/golden/.
"""

from __future__ import annotations

import json
import sys
from collections.abc import Sequence
from pathlib import Path

from . import geometry as G
from . import plot
from . import tables as T
from .codec import decode
from .errors import CbfError
from .stats import render, stats
from .validation import validate


def _clean_under(data: bytes) -> str | None:
    for profile in T.PROFILES:
        if not validate(data, profile=profile):
            return profile
    return None


def build(out: Path, files: Sequence[Path]) -> list[str]:
    out.mkdir(parents=True, exist_ok=True)
    shown: list[str] = []
    skipped: list[str] = []
    index = ["# Toolpath gallery", "",
             "`cbf plot` and `cbf stats` of every golden file that validates clean "
             "(made by `make gallery`).", ""]
    for path in sorted(files):
        name = path.name.removesuffix(".cbf")
        data = path.read_bytes()
        profile = _clean_under(data)
        if profile is None:
            skipped.append(name)
            continue
        try:
            model = decode(data)
        except CbfError as exc:  # pragma: no cover - a clean file decodes
            skipped.append(f"{name} ({exc})")
            continue
        steps = list(G.walk(model))  # walked once, drawn and counted
        for fmt, image in plot.renderings(model, ("png", "svg"), "cut", name, steps).items():
            (out / f"{name}.{fmt}").write_bytes(image)
        s = stats(model, steps)
        text = render(s, path.name)
        (out / f"{name}.stats.txt").write_text(text, encoding="utf-8")
        (out / f"{name}.stats.json").write_text(json.dumps({"file": path.name, **s.as_dict()}, indent=1) + "\n",
                                                 encoding="utf-8")
        index += [f"## {name}", "", f"Validates clean under profile `{profile}`.", "",
                  f"![{name}]({name}.svg)", "", "```text", text.rstrip("\n"), "```", ""]
        shown.append(name)
    if skipped:
        index += ["## Not drawn", "", "These files do not validate clean (they test the checks):", ""]
        index += [f"- {n}" for n in skipped]
    (out / "index.md").write_text("\n".join(index) + "\n", encoding="utf-8")
    return shown


def main(argv: Sequence[str] | None = None) -> int:
    args = list(sys.argv[1:] if argv is None else argv)
    if len(args) < 2:
        sys.stderr.write("usage: python -m cbf.gallery OUT_DIR FILE.cbf ...\n")
        return 2
    try:
        shown = build(Path(args[0]), [Path(a) for a in args[1:]])
    except plot.PlotUnavailable as exc:
        sys.stderr.write(f"gallery: {exc}\n")
        return 2
    sys.stdout.write(f"gallery: {len(shown)} file(s) drawn in {args[0]}/ (index.md)\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
