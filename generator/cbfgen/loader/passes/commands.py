"""The command table: each command's layouts (their arguments tiling the declared size) and roles."""

from __future__ import annotations

import math
from typing import Any

from ...model import Command, Layout
from ..fields import fields
from ..pipeline import State, define
from ..problems import Problems
from ..yaml_reader import Map

ROLES = ("motion", "orientation", "shape", "cutter", "sets")


def _layout(ctx: Problems, st: State, name: str, lay: Map, variant: str) -> Layout:
    args, total, whole = fields(ctx, lay["args"], st.types, f"{name}")
    vtext = "/".join("v" + v for v in lay["versions"])
    rep = args[-1] if args and args[-1].repeat is not None else None
    if whole and rep is not None:
        total -= rep.size  # a repeated group: `size` is the fixed arguments' (issue 25, point 3)
    if whole and total != lay["size"]:
        ctx.fail(lay, f"{name} {vtext} arguments sum to {total} bytes, declared {lay['size']}", "size")
    return Layout(name, variant, tuple(str(v) for v in lay["versions"]), lay["size"], args,
                  tuple(lay.get("profiles", [])), str(lay.get("doc", "")).strip(), lay.get("clause"), lay.line)


def _role(c: Map, role: str) -> dict[str, Any] | None:
    return dict(c[role]) if role in c else None


def _command(ctx: Problems, st: State, c: Map) -> Command:
    name = c["name"]
    layouts = tuple(_layout(ctx, st, name, lay, lay.get("variant", "")) for lay in c["layouts"])
    return Command(
        name=name, code=c["code"], doc=str(c["doc"]).strip(), clause=c["clause"], layouts=layouts, line=c.line,
        motion=_role(c, "motion"), orientation=_role(c, "orientation"), shape=_role(c, "shape"),
        cutter=_role(c, "cutter"), sets=_role(c, "sets"), progress=c.get("progress"),
        declared_size=c.get("declared_size"), listed_size=c.get("listed_size"), erratum=c.get("erratum"),
        former_names=tuple(str(x) for x in c.get("former_names", ())),
    )


@define("commands", "resolve", reads=("raw", "types"), produces=("bare_commands",))
def COMMANDS(ctx: Problems, st: State) -> None:
    """Each command and its layouts, the arguments of each tiling its declared size."""
    st.bare_commands = tuple(_command(ctx, st, c) for c in st.raw["commands"])


def _variants(ctx: Problems, name: str, lays: list[Map]) -> None:
    seen: list[str] = []
    for i, lay in enumerate(lays):
        variant = lay.get("variant", "")
        if i == 0 and variant:
            ctx.fail(lay, f"{name}: the first layout is the primary one and takes no variant", "variant")
        if i > 0 and not variant:
            ctx.fail(lay, f"{name}: layout {i + 1} needs a variant name")
        if variant in seen:
            ctx.fail(lay, f"{name}: duplicate variant {variant!r}", "variant")
        seen.append(variant)


def _layout_refs(ctx: Problems, st: State, name: str, lay: Map) -> None:
    profile_ids = [q["id"] for q in st.raw["profiles"]]
    for v in lay["versions"]:
        if v not in st.vids:
            ctx.fail(lay, f"{name}: unknown version {v!r}", "versions")
    for p in lay.get("profiles", []):
        if p not in profile_ids:
            ctx.fail(lay, f"{name}: unknown profile {p!r}", "profiles")
    if lay["size"] > st.raw["limits"]["max_arg_size"]:
        ctx.fail(lay, f"{name}: size {lay['size']} exceeds limits.max_arg_size", "size")


@define("command-table", "check", reads=("raw", "vids", "bare_commands"))
def COMMAND_TABLE(ctx: Problems, st: State) -> None:
    """Names and codes are unique; the first layout is the primary one, the others have distinct
    variant names; layouts name known versions and profiles, fit limits.max_arg_size, and no two
    layouts of a version have one size."""
    names: dict[str, int] = {}
    codes: dict[int, str] = {}
    for c, cmd in zip(st.raw["commands"], st.bare_commands, strict=True):
        name, code = c["name"], c["code"]
        if name in names:
            ctx.fail(c, f"duplicate command name {name} (also line {names[name]})", "name")
        if code in codes:
            ctx.fail(c, f"{name}: duplicate code 0x{code:02X}, already {codes[code]}", "code")
        names.setdefault(name, c.line)
        codes.setdefault(code, name)
        _variants(ctx, name, list(c["layouts"]))
        for lay in c["layouts"]:
            _layout_refs(ctx, st, name, lay)
        for v in st.vids:
            spans = [size_span(lay) for lay in cmd.layouts if v in lay.versions]
            if any(sizes_meet(a, b) for i, a in enumerate(spans) for b in spans[i + 1:]):
                ctx.fail(c, f"{name}: two layouts of version {v} have the same size", "layouts")


Span = tuple[int, int, int, int]  # the sizes start + step * n, lo <= n <= hi


def size_span(lay: Layout) -> Span:
    """The sizes a layout takes, as a progression (never built: a repeat's max may be 1e9)."""
    rep = lay.repeated
    if rep is None or rep.repeat is None or rep.size <= 0:
        return lay.size, 1, 0, 0
    return lay.size, rep.size, rep.repeat[0], rep.repeat[1]


def _ceil(a: int, b: int) -> int:
    return -(-a // b)


def sizes_meet(a: Span, b: Span) -> bool:
    """Whether two progressions of sizes share a size: s1 + k1 n1 = s2 + k2 n2 with each n in its
    bounds, solved for n1 = r + (k2 / g) t, n2 = n0 + (k1 / g) t over the integers t."""
    (s1, k1, lo1, hi1), (s2, k2, lo2, hi2) = a, b
    g, d = math.gcd(k1, k2), s2 - s1
    if d % g:
        return False
    m1, m2 = k1 // g, k2 // g
    r = (d // g) * pow(m1, -1, m2) % m2 if m2 > 1 else 0
    n0 = (k1 * r - d) // k2
    t_lo = max(_ceil(lo1 - r, m2), _ceil(lo2 - n0, m1))
    t_hi = min((hi1 - r) // m2, (hi2 - n0) // m1)
    return t_lo <= t_hi
