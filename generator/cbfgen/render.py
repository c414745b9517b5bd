"""Shared jinja2 set-up for the emitters: strict undefined, no timestamps."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import jinja2

from . import escape
from .model import camel, ident

# Spec text into target code: one filter per target language (escape.py says what each guarantees).
ESCAPE_FILTERS = {
    "c_comment": escape.c_comment,
    "c_str": escape.c_string,
    "py_doc": escape.py_docstring,
    "py_str": escape.py_string,
    "ksy_doc": escape.kaitai_doc,
    "yaml_str": escape.yaml_scalar,
    "toml_str": escape.toml_string,
    "json_str": escape.json_string,
    "line_comment": escape.line_comment,
    "xml_comment": escape.xml_comment,
    "md": escape.markdown_inline,
    "md_cell": escape.markdown_cell,
    "html": escape.html_text,
    "one_line": escape.one_line,
}


def environment(folder: Path, **options: Any) -> jinja2.Environment:
    """The templates of ``folder``. Compiled templates are kept in jinja2's bytecode cache (a folder of
    the user's own under the system's temporary folder, keyed by each template's source): compiling
    the ~40 templates was ~40 % of a `make generate` (issue 32); the output is the same either way."""
    options.setdefault("bytecode_cache", jinja2.FileSystemBytecodeCache())
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
    env.filters.update(ESCAPE_FILTERS)
    return env
