"""CBF codec: the Cutfile Binary Format, generated from spec/cbf.yaml (the spec's part number and
revision, from its `meta`: ``cbf.SPEC_REVISION``).

    import cbf
    model = cbf.decode(open("part.cbf", "rb").read())   # raises cbf.CbfError on broken framing
    findings = cbf.validate(data, profile="default")     # list of cbf.Finding
    data = cbf.encode(model)                              # fills sequence numbers, count, checksums
    text = cbf.to_cut(model); model = cbf.from_cut(text)
    doc = cbf.to_canonical(model); model = cbf.from_canonical(doc)

Imports are lazy so that the command line starts fast.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

from .version import SPEC_REVISION, __version__

if TYPE_CHECKING:
    from .canonical import from_canonical, to_canonical
    from .codec import decode
    from .cut import from_cut, to_cut
    from .cutters import load_cutter_table
    from .errors import CbfError, CutSyntaxError, EncodeError, JsonShapeError, TruncatedError
    from .layouts import CommandCode
    from .machine import load_machine
    from .model import Cbf, Record, new_header
    from .validation import Finding, validate
    from .writer import encode

_EXPORTS = {
    "decode": "codec", "encode": "writer",
    "validate": "validation", "Finding": "validation",
    "to_canonical": "canonical", "from_canonical": "canonical",
    "to_cut": "cut", "from_cut": "cut",
    "Cbf": "model", "Record": "model", "new_header": "model",
    "CommandCode": "layouts",
    "CbfError": "errors", "TruncatedError": "errors", "EncodeError": "errors", "JsonShapeError": "errors",
    "CutSyntaxError": "errors",
    "load_cutter_table": "cutters",
    "load_machine": "machine",
}

__all__ = [
    "SPEC_REVISION", "__version__",
    "Cbf", "CbfError", "CommandCode", "CutSyntaxError", "EncodeError", "Finding", "JsonShapeError", "Record",
    "TruncatedError", "decode", "encode", "from_canonical", "from_cut", "load_cutter_table", "load_machine",
    "new_header",
    "to_canonical", "to_cut", "validate",
]


def __getattr__(name: str) -> Any:
    module = _EXPORTS.get(name)
    if module is None:
        raise AttributeError(f"module 'cbf' has no attribute {name!r}")
    value = getattr(importlib.import_module(f"{__name__}.{module}"), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    """dir(cbf) lists the public API although the names load lazily (on first use)."""
    return sorted(set(__all__) | {n for n in globals() if n.startswith("__") and n.endswith("__")})
