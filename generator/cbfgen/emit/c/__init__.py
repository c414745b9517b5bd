"""C binding emitter: an stb-style single header (generated/c/cbf.h) with the
command enum (spec 5.2), per-layout argument structs, the spec as C tables, a
table-driven codec and a validator whose record checks are straight-line code
per layout (the offsets as constants); plus the conformance testee, the
`cbf-c` tool and a libFuzzer harness, all from templates beside this file.

Nothing here names a command, field, offset or check: every identifier and
number comes from the model. The hand-written C engine lives as real C files in
runtime/ (compiled and linted on their own by mk/c.mk) and goes verbatim into
cbf.h beside the generated sections of templates/cbf/ (tables, enums, structs,
per-layout code); it knows only the model's vocabulary (field kinds and roles,
check kinds, motion kinds, coverage regions, algorithm kinds).
"""

from __future__ import annotations

import textwrap
from pathlib import Path
from typing import Any

from ...model import Spec
from ...options import option_rules
from ...registry import DERIVED_HEADER_ROLES
from ...render import environment
from .algorithms import algorithm_tables
from .cnames import c_or, cfloat, cname, comment, ctype, macro
from .views import CContext, context

__all__ = ["CContext", "cfloat", "cname", "comment", "context", "ctype", "emit", "macro", "runtime_section",
           "tools_section"]

HERE = Path(__file__).parent
OUT = "c"

RUNTIME = HERE / "runtime"
RUNTIME_REL = "generator/cbfgen/emit/c/runtime"  # as a compiler names it from the repository's root
TOOLS = HERE / "tools"  # the tools' engine (cbf_tools.h), cbf-c's command line and the testee
TOOLS_REL = "generator/cbfgen/emit/c/tools"
_RESUME = '#line @@NEXT@@ "@@FILE@@"'


def _section(folder: str, rel: str, name: str) -> str:
    text = (HERE / folder / name).read_text(encoding="utf-8")
    return (f"/* ==== BEGIN {folder}/{name}: verbatim from {rel}/{name}, edit it there ==== */\n"
            f'#line 1 "{rel}/{name}"\n{text.rstrip(chr(10))}\n'
            f"/* ==== END {folder}/{name} ==== */\n{_RESUME}")


def runtime_section(name: str) -> str:
    """A hand-written runtime file (runtime/<name>), verbatim, between markers that name it (mk/c.mk
    compiles the files themselves in their place) and #line directives, so that a compiler's message
    about it names runtime/<name> and its line; after it, the lines are the generated file's again."""
    return _section("runtime", RUNTIME_REL, name)


def tools_section(name: str) -> str:
    """A hand-written file of the tools (tools/<name>), verbatim, framed as runtime_section frames one."""
    return _section("tools", TOOLS_REL, name)


def _resume_lines(text: str, name: str) -> str:
    """Number each #line that resumes the generated file after a section with the line that follows it."""
    lines = text.split("\n")
    for i, line in enumerate(lines):
        if line == _RESUME:
            lines[i] = f'#line {i + 2} "{name}"'
    return "\n".join(lines)


# The number grammar runtime/cut.c reads (an optional minus, digits, an optional point and digits): the
# spec's float_pattern must be this one, or the C reader would read another language than cbf's.
CUT_FLOAT_PATTERN = r"-?\d+\.?\d*"


def cut_syntax(spec: Spec) -> dict[str, Any]:
    """The CUT syntax's words for the C reader (runtime/cut.c), from the model's `cut` section."""
    cut = spec.cut
    if cut["float_pattern"] != CUT_FLOAT_PATTERN or cut["arg_separator"] != " ":
        raise ValueError(f"C binding: runtime/cut.c reads numbers as {CUT_FLOAT_PATTERN} and separates arguments "
                         f"with one space; the spec's cut section asks {cut['float_pattern']!r} and "
                         f"{cut['arg_separator']!r}: teach runtime/cut.c first")
    ext = cut["extensions"]
    roles = {f.role for h in spec.headers.values() for f in h.fields if f.role}
    lower = cut["keyword_case"] == "lower"
    return {
        "lower": lower, "header": cut["header_keyword"], "header_ext": cut["header_ext_keyword"],
        "checksum": cut["checksum_keyword"], "version": ext["version_keyword"], "field": ext["field_keyword"],
        "record": ext["record_keyword"], "open": cut["vector_open"], "close": cut["vector_close"],
        "sep": cut["vector_separator"],
        "derived": tuple(macro(r) for r in DERIVED_HEADER_ROLES if r in roles),
        "former": tuple((n, c.code) for c in spec.commands for n in c.former_names),
        "max_header_fields": max(len(h.fields) for h in spec.headers.values()),
    }


def emit(spec: Spec) -> dict[str, bytes]:
    env = environment(HERE / "templates")
    env.globals["runtime"] = runtime_section
    env.globals["tools"] = tools_section
    env.filters["comment"] = comment
    env.filters["cfloat"] = cfloat
    env.filters["cname"] = cname
    env.filters["macro"] = macro
    env.filters["c_or"] = c_or
    env.filters["wrap"] = lambda s, width=76, indent="": ("\n" + indent).join(textwrap.wrap(s, width))
    names = context(spec).namespace()
    assert "options" not in names
    names["options"] = option_rules(spec)  # option files, cbf_tools.h.j2 (issue 28)
    names["checksum_algorithms"] = algorithm_tables()  # cbf/algorithms.c.j2 (issue 33, point 1)
    assert "cut_syntax" not in names
    names["cut_syntax"] = cut_syntax(spec)  # cbf/cut.c.j2, read by runtime/cut.c (issue 34: a dropped CUT file)
    out: dict[str, bytes] = {}
    for name in ("cbf.h", "cbf_tools.h", "cbf_testee.c", "cbf_tool.c", "cbf_fuzz.c", "cbf.pc.in"):
        text = env.get_template(name + ".j2").render(**names)
        out[f"{OUT}/{name}"] = _resume_lines(text, name).encode()
    return out
