"""The bindings checklist (issue 33, point 2): generated/checklist/BINDINGS.md.

Per binding of the registry (cbfgen/registry.py ``BINDING_LIST``): what it is made of (emitter,
languages, testees, failure lists, make fragment) and which check kinds, checksum algorithm kinds
and role kinds it implements, against everything the registry lists; and how many checks of each
kind the spec has. A new binding appears here implementing nothing until its registry entry claims
what it implements (tests/test_bindings.py then fails until it does).
"""

from __future__ import annotations

from ...escape import markdown_cell
from ...model import Spec
from ...registry import ALGORITHMS, BINDING_LIST, CHECK_KINDS, ROLE_KINDS, ROLE_NEEDS, Binding

OUT = "checklist/BINDINGS.md"


def _mark(ok: bool) -> str:
    return "yes" if ok else "**no**"


def _table(title: str, rows: list[tuple[str, str]], claims: list[tuple[str, ...]]) -> list[str]:
    head = "| " + title + " | " + " | ".join(b.name for b in BINDING_LIST) + " | |"
    out = [head, "|" + "---|" * (len(BINDING_LIST) + 2)]
    for name, note in rows:
        cells = " | ".join(_mark(name in c) for c in claims)
        out.append(f"| `{name}` | {cells} | {markdown_cell(note)} |")
    return out


def _binding(b: Binding) -> list[str]:
    failures = ", ".join(f"`conformance/failures/{t}.txt`" for t in b.testees) or "none"
    return [
        f"### {b.name}",
        "",
        markdown_cell(b.doc),
        "",
        f"- emitter: `generator/cbfgen/emit/{b.emitter}/`",
        f"- reserved words of: {', '.join(b.languages) or 'none'} (`generator/cbfgen/escape.py` RESERVED)",
        f"- testees (`conformance/bindings.yaml`): {', '.join(f'`{t}`' for t in b.testees) or 'none'}",
        f"- failure lists: {failures}",
        f"- make fragment: {f'`mk/{b.make}.mk`' if b.make else 'none (`make generate`)'}",
        "- the loader " + ("refuses a spec it cannot carry (`registry.BINDINGS`)" if b.gated
                           else f"answers for it through `{b.engine_of}` (the same engine files)" if b.engine_of
                           else "does not answer for it yet (under construction)"),
        f"- implements {len(b.check_kinds)} of {len(CHECK_KINDS)} check kinds, {len(b.algorithms)} of "
        f"{len(ALGORITHMS)} algorithm kinds, {len(b.roles)} of {sum(len(k) for k in ROLE_KINDS.values())} role kinds",
        "",
    ]


def checklist(spec: Spec) -> str:
    lines = ["# Bindings checklist", "",
             "Generated from `generator/cbfgen/registry.py` (BINDING_LIST, CHECK_KINDS, ALGORITHMS, ROLE_KINDS); "
             "do not edit. `tests/test_bindings.py` fails when a binding lacks what it claims here.", "",
             "## Bindings", ""]
    for b in BINDING_LIST:
        lines += _binding(b)
    lines += ["## Check kinds", ""]
    kinds = [(k, f"{c.scope}; {len(spec.checks_of_kind(k))} check(s) in this spec") for k, c in CHECK_KINDS.items()]
    lines += _table("kind", kinds, [b.check_kinds for b in BINDING_LIST]) + [""]
    lines += ["## Checksum algorithm kinds", ""]
    used = {a.kind for a in spec.checksums.algorithms.values()}
    algs = [(k, f"{a.family}, {a.width or 'field'} bits, check 0x{a.check:X}"
                + ("; named by this spec" if k in used else "")) for k, a in ALGORITHMS.items()]
    lines += _table("algorithm", algs, [b.algorithms for b in BINDING_LIST]) + [""]
    lines += ["## Role kinds", ""]
    roles = [(f"{r}/{k}", "needs " + ", ".join(ROLE_NEEDS[r][k])) for r, ks in ROLE_KINDS.items() for k in ks]
    lines += _table("role/kind", roles, [b.roles for b in BINDING_LIST]) + [""]
    return "\n".join(lines)


def emit(spec: Spec) -> dict[str, bytes]:
    return {OUT: checklist(spec).encode("utf-8")}
