"""Cutter tables for check 6.1.2: CSV or YAML rows of name, length, radius (mm)."""

from __future__ import annotations

import csv
import io
from pathlib import Path

from .errors import CbfError


def load_cutter_table(path: str | Path) -> dict[str, tuple[float, float]]:
    """{name: (length, radius)}. Raises CbfError naming the line of a bad row."""
    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise CbfError(f"{p}: cannot read cutter table ({exc})", kind="cutters") from None
    rows: list[tuple[int, dict[str, object]]] = []
    if p.suffix.lower() in (".yaml", ".yml"):
        import yaml

        try:
            data = yaml.safe_load(text)
        except yaml.YAMLError as exc:
            raise CbfError(f"{p}: not YAML ({exc})", kind="cutters") from None
        if isinstance(data, dict) and "cutters" in data:
            data = data["cutters"]
        if not isinstance(data, list):
            raise CbfError(f"{p}: expected a list of {{name, length, radius}}", kind="cutters")
        rows = [(i + 1, r) for i, r in enumerate(data) if isinstance(r, dict)]
        if len(rows) != len(data):
            raise CbfError(f"{p}: every entry must be a mapping", kind="cutters")
    else:
        reader = csv.DictReader(io.StringIO(text))
        rows = [(reader.line_num, dict(r)) for r in reader]
    table: dict[str, tuple[float, float]] = {}
    for line, row in rows:
        try:
            name = str(row["name"]).strip()
            table[name] = (float(str(row["length"])), float(str(row["radius"])))
        except (KeyError, TypeError, ValueError):
            raise CbfError(f"{p}: line {line}: needs name, length, radius", line=line, kind="cutters") from None
    return table
