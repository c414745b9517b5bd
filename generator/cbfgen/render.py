"""Shared jinja2 set-up for the emitters: strict undefined, no timestamps."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import jinja2

from .model import camel, ident


def environment(folder: Path, **options: Any) -> jinja2.Environment:
    env = jinja2.Environment(
        loader=jinja2.FileSystemLoader(str(folder)),
        undefined=jinja2.StrictUndefined,
        keep_trailing_newline=True,
        trim_blocks=True,
        lstrip_blocks=True,
        autoescape=False,
        **options,
    )
    env.filters["camel"] = camel
    env.filters["ident"] = ident
    env.filters["hex2"] = lambda n: f"0x{int(n):02X}"
    env.filters["hex8"] = lambda n: f"0x{int(n):08X}"
    return env
