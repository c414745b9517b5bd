"""The checks: each a known kind with the parameters that kind takes (registry.CHECK_KINDS)."""

from __future__ import annotations

from typing import Any

from ...model import Check
from ...registry import CHECK_KINDS, COMMON_CHECK_KEYS, Target, loader_rules
from ..pipeline import State, define
from ..problems import Problems
from ..yaml_reader import Map


def _params(st: State, ch: Map) -> Any:
    ck = CHECK_KINDS[ch["kind"]]
    values: dict[str, Any] = {k: ch[k] for k in ck.keys if k in ch}
    if "targets" in ck.keys:
        names = {c.name for c in st.bare_commands}
        values["targets"] = tuple(Target(t["command"], tuple(t["args"]), t.get("limit"))
                                  for t in ch.get("targets", []) if t["command"] in names)
    for k in ("versions", "commands", "deprecates"):
        if k in values:
            values[k] = tuple(str(x) for x in values[k])
    since = ch.get("since")
    if loader_rules(ch["kind"]).since and since in st.vids:  # since and every version after it
        values["versions"] = st.vids[st.vids.index(since):]
    return ck.params(**values)


@define("checks", "resolve", reads=("raw", "vids", "bare_commands"), produces=("raw_checks", "checks"))
def CHECKS(ctx: Problems, st: State) -> None:
    """Each check with its kind's parameters (a deprecation's versions from its since); a duplicate
    id, or a check without a parameter its kind needs, is refused (and left out)."""
    raw_checks: dict[str, Map] = {}
    checks: list[Check] = []
    for ch in st.raw["checks"]:
        cid, kname = str(ch["id"]), ch["kind"]
        if cid in raw_checks:
            ctx.fail(ch, f"duplicate check id {cid!r}", "id")
            continue
        raw_checks[cid] = ch
        missing = [k for k in CHECK_KINDS[kname].required if not ch.get(k)]
        for k in missing:
            ctx.fail(ch, f"check {cid}: kind {kname} needs {k}", "kind")
        if missing:
            continue
        checks.append(Check(id=cid, kind=kname, severity=ch["severity"], text=str(ch["text"]).strip(),
                            fails=" ".join(str(ch["fails"]).split()), line=ch.line, params=_params(st, ch),
                            clause=ch.get("clause"), decision=ch.get("decision")))
    st.raw_checks = raw_checks
    st.checks = tuple(checks)


def _keys(ctx: Problems, cid: str, ch: Map) -> None:
    """Nothing a runtime would ignore: ``versions:`` only where every runtime scopes by it."""
    kname = ch["kind"]
    ck = CHECK_KINDS[kname]
    for key in ch:
        if key in COMMON_CHECK_KEYS or key in ck.keys:
            continue
        if key == "versions" and ck.kaitai:
            ctx.fail(ch, f"check {cid}: versions on a check of kind {kname}, which the Kaitai parsers state "
                         f"as a valid: rule in every version (a file of another version would pass Python "
                         f"and C and fail Kaitai)", key)
        elif key == "versions":
            ctx.fail(ch, f"check {cid}: versions on a check of kind {kname}, which no runtime scopes by "
                         f"version (only {', '.join(k.name for k in CHECK_KINDS.values() if k.versioned)} does)",
                     key)
        else:
            ctx.fail(ch, f"check {cid}: kind {kname} takes no {key!r} (it takes "
                         f"{', '.join(ck.keys) or 'no parameters'})", key)


def _bounds(ctx: Problems, cid: str, ch: Map) -> None:
    """A bounded kind (registry.LoaderRules.bounds): a bound, min <= max, a value between them."""
    lo, hi = ch.get("min"), ch.get("max")
    if lo is None and hi is None:
        ctx.fail(ch, f"check {cid}: a range check needs min, max or both", "kind")
    elif lo is not None and hi is not None and lo > hi:
        ctx.fail(ch, f"check {cid}: min {ch['min']} exceeds max {ch['max']}", "min")
    elif lo is not None and lo == hi and (ch.get("min_exclusive") or ch.get("max_exclusive")):
        ctx.fail(ch, f"check {cid}: an open bound at min = max {ch['min']} leaves no value", "min")
    for b in ("min", "max"):
        if ch.get(f"{b}_exclusive") and ch.get(b) is None:
            ctx.fail(ch, f"check {cid}: {b}_exclusive without {b}", f"{b}_exclusive")


def _refs(ctx: Problems, st: State, cid: str, ch: Map) -> None:
    names = {c.name for c in st.bare_commands}
    for v in ch.get("versions", []):
        if v not in st.vids:
            ctx.fail(ch, f"check {cid}: unknown version {v!r}", "versions")
    for cname in ch.get("commands", []):
        if cname not in names:
            ctx.fail(ch, f"check {cid}: unknown command {cname}", "commands")
    if ch.get("decision") and ch["decision"] not in {d.id for d in st.decisions}:
        ctx.fail(ch, f"check {cid}: unknown decision {ch['decision']!r}", "decision")


@define("check-params", "check", reads=("vids", "bare_commands", "decisions", "raw_checks", "checks"))
def CHECK_PARAMS(ctx: Problems, st: State) -> None:
    """A check carries only the keys its kind takes (``versions:`` only where every runtime scopes
    by it), at most one check of a kind that takes one, known versions, commands and decision, and
    the bounds of a bounded kind."""
    first: dict[str, Check] = {}
    for c in st.checks:
        first.setdefault(c.kind, c)
    for cid, ch in st.raw_checks.items():
        kname = ch["kind"]
        _keys(ctx, cid, ch)
        other = first.get(kname)
        if other is not None and other.id != cid and not CHECK_KINDS[kname].repeatable:
            ctx.fail(ch, f"check {cid}: a second check of kind {kname} (first: {other.id}, line "
                         f"{other.line}); the kind takes one", "kind")
        _refs(ctx, st, cid, ch)
        if loader_rules(kname).bounds:
            _bounds(ctx, cid, ch)
