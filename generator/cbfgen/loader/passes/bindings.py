"""What every binding can implement: each field's type, and names every binding can use."""

from __future__ import annotations

from ...escape import NAME_MAX, keyword_clash
from ...model import Command, Field
from ...registry import GENERATED_NAMES, TYPES, unsupported, unsupported_in_head
from ..pipeline import State, define
from ..problems import Problems


def _head_fields(st: State) -> list[Field]:
    return [f for h in st.headers.values() for f in h.fields] + list(st.record.fields)


@define("capabilities", "check", reads=("headers", "record", "commands"))
def CAPABILITIES(ctx: Problems, st: State) -> None:
    """Each field's type in each binding (registry.unsupported, registry.unsupported_in_head)."""
    args = [a for c in st.commands for lay in c.layouts for a in lay.args]
    for f in _head_fields(st) + args:
        gaps = unsupported(TYPES[f.type], f.count)
        if gaps:
            what = f"{f.type} x {f.count}" if f.count != 1 else f.type
            ctx.at(f.line, f"field {f.name}: type {what} is not implemented by the "
                           f"{', '.join(gaps)} binding{'s' if len(gaps) > 1 else ''} (generator/cbfgen/registry.py)")
    for f in _head_fields(st):
        head_gaps = unsupported_in_head(TYPES[f.type])
        if head_gaps:
            ctx.at(f.line, f"field {f.name}: type {f.type} in a header or record head is not implemented by the "
                           f"{', '.join(head_gaps)} binding (it reads those fields unsigned, at most 4 bytes; "
                           f"generator/cbfgen/registry.py)")
    # The version fields sit in the same place in every header layout (the header-layouts pass):
    # Kaitai reads them by position when the layouts diverge before them (emit/kaitai).


@define("names", "check", reads=("headers", "record", "commands", "checks"))
def NAMES(ctx: Problems, st: State) -> None:
    """Names every binding can use as identifiers, as the spec spells them: a command, argument or
    field name reserved in a binding's language (escape.keyword_clash) is refused, never renamed;
    a header or record field may not take a name the generated code gives a member of its own; no
    name is longer than every binding takes (escape.NAME_MAX)."""
    named: list[tuple[str, int, str, str]] = [(c.name, c.line, "command name", "command") for c in st.commands]
    named += [(a.name, a.line, f"{c.name} argument", "field")
              for c in st.commands for lay in c.layouts for a in lay.args]
    named += [(f.name, f.line, f"header {h.id} field", "field") for h in st.headers.values() for f in h.fields]
    named += [(f.name, f.line, "record field", "field") for f in st.record.fields]
    seen: set[tuple[str, int]] = set()
    for name, line, what in [(n, ln, w) for n, ln, w, _ in named] + [(ch.id, ch.line, "check id") for ch in st.checks]:
        if len(name) > NAME_MAX and (name, line) not in seen:
            seen.add((name, line))
            ctx.at(line, f"{what}: a name of {len(name)} characters; every binding takes at most {NAME_MAX} "
                         f"(escape.NAME_MAX)")
    for name, line, what, kind in named:
        why = keyword_clash(name, what=kind)
        if why and (name, line) not in seen:
            seen.add((name, line))
            ctx.at(line, f"{what}: the name {why}")
    own = [(f, "header", f"header {h.id} field") for h in st.headers.values() for f in h.fields]
    own += [(f, "record", "record field") for f in st.record.fields]
    for f, part, what in own:
        if f.name in GENERATED_NAMES[part]:
            ctx.at(f.line, f"{what} {f.name}: the generated code names a member of the {part} so "
                           f"({', '.join(GENERATED_NAMES[part])} are taken)")


@define("former-names", "check", reads=("raw", "commands"))
def FORMER_NAMES(ctx: Problems, st: State) -> None:
    """A command's former names (issue 25, point 6) name it alone: no command's current name, no
    other former name, and a name every binding can use (they become aliases)."""
    owner: dict[str, Command] = {c.name: c for c in st.commands}
    raw = {str(x["name"]): x for x in st.raw["commands"]}
    for c in st.commands:
        for old in c.former_names:
            other = owner.get(old)
            why = keyword_clash(old, what="command")
            if other is not None:
                what = "its own name" if other is c else f"already a name of {other.name} (line {other.line})"
                ctx.fail(raw[c.name], f"{c.name}: former name {old} is {what}", "former_names")
            elif why:
                ctx.fail(raw[c.name], f"{c.name}: former name {old}: the name {why}", "former_names")
            owner.setdefault(old, c)
