"""Deprecations (issue 25, point 5): what a deprecating check names, and in which versions."""

from __future__ import annotations

from ...model import Check, Command
from ...registry import DeprecatedParams, loader_rules
from ..pipeline import State, define
from ..problems import Problems
from ..yaml_reader import Map


def _item(ctx: Problems, ch: Check, node: Map, item: str, by_name: dict[str, Command],
          seen: dict[tuple[str, str], Check]) -> None:
    name, _, variant = item.partition("/")
    cmd = by_name.get(name)
    lays = [] if cmd is None else [lay for lay in cmd.layouts if not variant or lay.variant == variant]
    if not lays:
        ctx.fail(node, f"check {ch.id}: deprecates {item}, which names no command or layout", "deprecates")
        return
    if not any(v in lay.versions for lay in lays for v in ch.versions):
        ctx.fail(node, f"check {ch.id}: {item} has no layout in {', '.join(ch.versions)}, nothing to deprecate",
                 "deprecates")
    for lay in lays:
        other = seen.get((name, lay.variant))
        if other is not None:
            ctx.fail(node, f"check {ch.id}: {name} layout {lay.variant or 'primary'} is already deprecated "
                           f"by check {other.id} (line {other.line})", "deprecates")
        seen[(name, lay.variant)] = ch


@define("deprecations", "check", reads=("vids", "commands", "raw_checks", "checks"))
def DEPRECATIONS(ctx: Problems, st: State) -> None:
    """Each deprecating check (registry.LoaderRules.since) gives a known version ``since``, not
    ``versions``; each command or NAME/variant layout it names exists, has a layout in since or a
    version after it, and is deprecated by no other check."""
    by_name = {c.name: c for c in st.commands}
    seen: dict[tuple[str, str], Check] = {}
    for ch in st.checks:
        if not loader_rules(ch.kind).since or not isinstance(ch.params, DeprecatedParams):
            continue
        node = st.raw_checks[ch.id]
        if "versions" in node:
            ctx.fail(node, f"check {ch.id}: a deprecation gives since, not versions", "versions")
            continue
        if ch.params.since not in st.vids:
            ctx.fail(node, f"check {ch.id}: unknown version {ch.params.since!r}", "since")
            continue
        for item in ch.params.deprecates:
            _item(ctx, ch, node, item, by_name, seen)
