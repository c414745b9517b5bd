"""The kit's version and the spec revision its golden cases come from, named in every report.

Installed (the cbf-conformance wheel), they come from ``_stamp.py``, written when the kit is
staged (conformance/kit.py); in this repository, from the generator's version and the spec.
"""

from __future__ import annotations

import re
from pathlib import Path

__all__ = ["SPEC_REVISION", "VERSION", "version_line"]


def _from_repo() -> tuple[str, str]:
    root = Path(__file__).resolve().parents[2]
    init = (root / "generator" / "cbfgen" / "__init__.py").read_text(encoding="utf-8")
    version = re.search(r'^__version__ = "([^"]+)"', init, re.M)
    spec = (root / "spec" / "cbf.yaml").read_text(encoding="utf-8")
    # either quote: the revision drill writes the spec back with YAML's single quotes
    part = re.search(r"^  part_number: [\"']?([^\"'\n]+)[\"']?", spec, re.M)
    rev = re.search(r"^  revision: [\"']?([^\"'\n]+)[\"']?", spec, re.M)
    if not (version and part and rev):
        return "unknown", "unknown"
    return version.group(1), f"{part.group(1)} rev {rev.group(1)}"


def _stamped() -> tuple[str, str]:
    try:
        from . import _stamp  # type: ignore[attr-defined,unused-ignore]
    except ImportError:
        return _from_repo()
    return str(_stamp.VERSION), str(_stamp.SPEC_REVISION)


VERSION, SPEC_REVISION = _stamped()


def version_line() -> str:
    return f"cbf-conformance {VERSION} (spec {SPEC_REVISION})"
