"""Format documentation emitter: Markdown pages rendered from the spec model.

Every command, field, check, clause, decision and erratum comes from the
model; the golden hex dumps and the traceability status come from
conformance/ (the committed report.json; when it is missing the page says so).
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from ...model import Spec, ident
from ...render import environment

HERE = Path(__file__).parent
REPO = HERE.parents[3]
OUT = "docs"
DUMPS = ("valid.v3.small", "check.6.4.4.arg_checksum")
REPORT = REPO / "conformance" / "report.json"


def _anchor(text: str) -> str:
    return ident(text).replace("_", "-")


def _report() -> dict[str, Any] | None:
    try:
        data: dict[str, Any] = json.loads(REPORT.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    return data


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


def _hexdump(name: str) -> str | None:
    path = REPO / "conformance" / "golden" / f"{name}.hex"
    if not path.exists():
        return None
    return path.read_text(encoding="utf-8")


def _worked_example(spec: Spec) -> dict[str, Any]:
    """A checksum example computed here from a record the model describes (the first motion command)."""
    cmd = next(c for c in spec.commands if c.motion and c.motion.get("kind") == "line")
    lay = cmd.primary
    import struct

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


def emit(spec: Spec) -> dict[str, bytes]:
    env = environment(HERE / "templates")
    env.filters["anchor"] = _anchor
    report = _report()
    ctx = {
        "spec": spec,
        "report": report,
        "trace": _traceability(spec, report),
        "dumps": {name: _hexdump(name) for name in DUMPS},
        "example": _worked_example(spec),
        "versions": [v.id for v in spec.versions],
    }
    return {f"{OUT}/index.md": env.get_template("index.md.j2").render(**ctx).encode()}
