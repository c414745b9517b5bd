"""The kit's version and the spec revision its golden cases come from, named in every report.

Installed (the cbf-conformance wheel), they come from ``_stamp.py``, written when the kit is
staged (conformance/kit.py); in this repository, from the generator's version and the spec.
"""

from __future__ import annotations

import re
from pathlib import Path

import yaml

__all__ = ["SPEC_REVISION", "VERSION", "from_repo", "version_line"]


def from_repo(root: Path) -> tuple[str, str] | None:
    """The toolkit version and the spec revision of the repository at root, or None when either is
    missing (the kit's stamp, conformance/kit.py, reads them here too)."""
    init = (root / "generator" / "cbfgen" / "__init__.py").read_text(encoding="utf-8")
    version = re.search(r'^__version__ = "([^"]+)"', init, re.M)
    # the spec read as YAML, not as text: a revised spec written by another dumper quotes its scalars its own way
    text = (root / "spec" / "cbf.yaml").read_text(encoding="utf-8")
    doc = yaml.load(text, Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))
    meta = doc.get("meta") if isinstance(doc, dict) else None
    if not (version and isinstance(meta, dict) and meta.get("part_number") is not None
            and meta.get("revision") is not None):
        return None
    return version.group(1), f"{meta['part_number']} rev {meta['revision']}"


def _stamped() -> tuple[str, str]:
    try:
        from . import _stamp  # type: ignore[attr-defined,unused-ignore]
    except ImportError:
        return from_repo(Path(__file__).resolve().parents[2]) or ("unknown", "unknown")
    return str(_stamp.VERSION), str(_stamp.SPEC_REVISION)


VERSION, SPEC_REVISION = _stamped()


def version_line() -> str:
    return f"cbf-conformance {VERSION} (spec {SPEC_REVISION})"
