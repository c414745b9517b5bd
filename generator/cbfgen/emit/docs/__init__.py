"""Format documentation emitter: Markdown pages and SVG figures from the spec model.

Every command, field, check, clause, decision and erratum comes from the
model; the golden hex dumps, the traceability status and the reliability
figures come from conformance/ (the committed report.json and
reliability.json; when one is missing the page says so). The pages are
index.md and one page per command under commands/; the figures are under
svg/. The HTML site (site.py, `make docs`) renders the same pages.
"""

from __future__ import annotations

import json
import math
import struct
from pathlib import Path
from typing import Any

from ...diff import version_steps
from ...model import Check, Command, Layout, Spec, ident
from ...render import environment
from . import svg

HERE = Path(__file__).parent
REPO = HERE.parents[3]
OUT = "docs"
DUMPS = ("valid.v3.small", "check.6.4.4.arg_checksum")
REPORT = REPO / "conformance" / "report.json"
RELIABILITY = REPO / "conformance" / "reliability.json"


def _anchor(text: str) -> str:
    return ident(text).replace("_", "-")


def command_page(c: Command) -> str:
    """The page of a command, relative to the docs folder."""
    return f"commands/{_anchor(c.name)}.md"


def layout_svg(lay: Layout) -> str:
    """The argument diagram of a layout, relative to the docs folder."""
    suffix = f"-{_anchor(lay.variant)}" if lay.variant else ""
    return f"svg/cmd-{_anchor(lay.command)}{suffix}.svg"


def header_svg(layout_id: str) -> str:
    return f"svg/header-{_anchor(layout_id)}.svg"


RECORD_SVG = "svg/record.svg"
MOTION_SVG = "svg/motion.svg"


def _read_json(path: Path) -> dict[str, Any] | None:
    try:
        data: dict[str, Any] = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    return data if isinstance(data, dict) else None


def _report() -> dict[str, Any] | None:
    return _read_json(REPORT)


def _reliability_file() -> dict[str, Any] | None:
    return _read_json(RELIABILITY)


def _traceability(spec: Spec, report: dict[str, Any] | None) -> list[dict[str, Any]]:
    rows = []
    for check in spec.checks:
        cases = []
        if report:
            cases = sorted(name for name, c in report.get("cases", {}).items() if check.id in c.get("checks", []))
        status: dict[str, str] = {}
        if report:
            for binding, b in sorted(report.get("bindings", {}).items()):
                res = [b["results"].get(name, {}).get("status", "skip") for name in cases]
                if not b.get("available", True) or not res:
                    status[binding] = "not run"
                elif all(r == "pass" for r in res):
                    status[binding] = f"pass ({len(res)})"
                else:
                    status[binding] = f"FAIL ({sum(r == 'fail' for r in res)}/{len(res)})"
        rows.append({"check": check, "cases": cases, "status": status})
    return rows


def _rate(entry: Any) -> dict[str, Any]:
    """trials, detected and the detection rate in percent of one reliability entry."""
    e = entry if isinstance(entry, dict) else {}
    trials, detected = int(e.get("trials", 0) or 0), int(e.get("detected", 0) or 0)
    # Truncated, never rounded up: 19,999 of 20,000 reads 99.99 %, not 100.00 %.
    rate = f"{math.floor(10000 * detected / trials) / 100:.2f} %" if trials else "—"
    misses = e.get("misses", [])
    missed = len(misses) if isinstance(misses, list) else 0
    return {"trials": trials, "detected": detected, "rate": rate, "misses": missed}


def _rate_rows(table: Any, outer: str) -> list[dict[str, Any]]:
    rows = []
    for key, classes in sorted((table or {}).items()):
        for cls, entry in sorted((classes or {}).items()):
            rows.append({outer: key, "class": cls, **_rate(entry)})
    return rows


MISSES_SHOWN = 5  # missed corruptions listed per binding and class


def _misses(table: Any) -> list[dict[str, Any]]:
    rows = []
    for binding, classes in sorted((table or {}).items()):
        for cls, entry in sorted((classes or {}).items()):
            misses = entry.get("misses", []) if isinstance(entry, dict) else []
            for m in (misses if isinstance(misses, list) else [])[:MISSES_SHOWN]:
                m = m if isinstance(m, dict) else {}
                rest = ", ".join(f"{k}={m[k]}" for k in sorted(m) if k not in ("file", "offset"))
                rows.append({"binding": binding, "class": cls, "file": m.get("file", ""),
                             "offset": m.get("offset", ""), "detail": rest})
    return rows


def _reliability(data: dict[str, Any] | None) -> dict[str, Any] | None:
    """conformance/reliability.json as table rows (None when the file is missing or unreadable)."""
    if data is None:
        return None
    diff = data.get("differential") or {}
    fuzz = data.get("fuzz") or {}
    return {
        "corruption": _rate_rows(data.get("corruption"), "binding"),
        "misses": _misses(data.get("corruption")),
        "misses_shown": MISSES_SHOWN,
        "run": {k: data[k] for k in ("mode", "seed") if k in data},
        "blind_spots": _rate_rows(data.get("blind_spots"), "variant"),
        "differential": diff if isinstance(diff, dict) else {},
        "fuzz": [{"name": name, **(v if isinstance(v, dict) else {})} for name, v in sorted(fuzz.items())],
    }


def _hexdump(name: str) -> str | None:
    path = REPO / "conformance" / "golden" / f"{name}.hex"
    if not path.exists():
        return None
    return path.read_text(encoding="utf-8")


def _worked_example(spec: Spec) -> dict[str, Any]:
    """A checksum example computed here from a record the model describes (the first motion command)."""
    cmd = next(c for c in spec.commands if c.motion and c.motion.get("kind") == "line")
    lay = cmd.primary
    values: list[float] = []
    raw = b""
    n = 0
    for a in lay.args:
        if a.kind == "float":
            vals = [float(n + k) for k in range(a.count)]
            n += a.count
            values += vals
            raw += struct.pack(("<" if spec.meta["byte_order"] == "little" else ">") + "f" * a.count, *vals)
        else:
            raw += bytes(a.size)
    return {"command": cmd, "layout": lay, "numbers": values, "hex": raw.hex(" "),
            "sum": sum(raw), "nonzero": [f"0x{b:02X}" for b in raw if b]}


def _motion_names(spec: Spec, kind: str) -> dict[str, str] | None:
    for c in spec.commands:
        if c.motion and c.motion.get("kind") == kind:
            return dict(c.motion)
    return None


def figures(spec: Spec) -> dict[str, str]:
    """Every SVG figure, by path relative to the docs folder."""
    out: dict[str, str] = {}
    for h in spec.headers.values():
        versions = ", ".join(v.id for v in spec.versions if v.header == h.id)
        out[header_svg(h.id)] = svg.byte_field(f"Header layout {h.id} (versions {versions}), {h.size} bytes",
                                               h.fields, h.size)
    rec = spec.record
    out[RECORD_SVG] = svg.byte_field(f"Record head, {rec.head_size} bytes (then the arguments)",
                                     rec.fields, rec.head_size, rec.head_size)
    for c in spec.commands:
        for lay in c.layouts:
            if lay.args:
                name = f"{c.name}{' ' + lay.variant if lay.variant else ''}"
                out[layout_svg(lay)] = svg.byte_field(f"{name} arguments, {lay.size} bytes", lay.args, lay.size)
    circle = _motion_names(spec, "circle")
    if circle:
        out[MOTION_SVG] = svg.motion(circle, _motion_names(spec, "helix"), "Circle and helix end points")
    return out


def context(spec: Spec) -> dict[str, Any]:
    """The context every page (Markdown and HTML) is rendered from."""
    report = _report()
    return {
        "spec": spec,
        "report": report,
        "trace": _traceability(spec, report),
        "reliability": _reliability(_reliability_file()),
        "dumps": {name: _hexdump(name) for name in DUMPS},
        "example": _worked_example(spec),
        "versions": [v.id for v in spec.versions],
        "figures": figures(spec),
        "record_svg": RECORD_SVG,
        "motion_svg": MOTION_SVG,
    }


def _why(k: Check, c: Command) -> str | None:
    """Why check k reads the arguments of command c, from the model; None when it does not. Checks that
    read every record alike (sequence, code copy, size, checksum, ...) are not listed per command."""
    kinds = {a.kind for lay in c.layouts for a in lay.args}
    if any(t.command == c.name for t in k.targets):
        return f"names {c.name}"
    if k.kind == "availability":
        missing = [v for v in k.versions if not c.available_in(v)]
        return f"{c.name} is not in version {', '.join(missing)}" if missing else None
    reasons = {
        "continuity": "a motion command" if c.motion else None,
        "orientation": "a 5-axis command" if c.orientation else None,
        "shape": "opens or closes a shape" if c.shape else "a motion command, counted in shapes" if c.motion else None,
        "cutter_table": "a cutter" if c.cutter else None,
        "finite": "float arguments" if "float" in kinds else None,
        "string_tail": "string arguments" if "string" in kinds else None,
        "string_ascii": "string arguments" if "string" in kinds else None,
    }
    return reasons.get(k.kind)


def _checks_of(spec: Spec, c: Command) -> list[tuple[Check, str]]:
    return [(k, why) for k in spec.checks if (why := _why(k, c)) is not None]


def emit(spec: Spec) -> dict[str, bytes]:
    env = environment(HERE / "templates")
    env.filters["anchor"] = _anchor
    env.filters["page"] = command_page
    env.filters["layout_svg"] = layout_svg
    env.filters["header_svg"] = header_svg
    ctx = context(spec)
    files = {f"{OUT}/index.md": env.get_template("index.md.j2").render(**ctx).encode()}
    page = env.get_template("command.md.j2")
    for c in spec.commands:
        files[f"{OUT}/{command_page(c)}"] = page.render(c=c, checks=_checks_of(spec, c), **ctx).encode()
    for rel, text in ctx["figures"].items():
        files[f"{OUT}/{rel}"] = text.encode()
    # The "Changes" page: each version against the one before it, by cbfgen diff's comparison (issue 12).
    available = {v.id: [c.name for c in spec.commands if c.available_in(v.id)] for v in spec.versions}
    files[f"{OUT}/changes.md"] = env.get_template("changes.md.j2").render(
        steps=version_steps(spec), available=available, **ctx).encode()
    return files
