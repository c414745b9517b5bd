"""The CUT text form (``cut:``), compiled (issue 36, point 1).

The schema types each value (keywords are words, the vector's punctuation printable ASCII, the
argument separator spaces); this pass compiles what the generated CUT reader compiles and keeps
apart what it tells apart: a pattern that does not compile left the generated codec unimportable,
and a header keyword equal to a command's, or two equal separators, made the generated writer's
text unreadable by its own reader.
"""

from __future__ import annotations

import re

from ...model import Command
from ..pipeline import State, define
from ..problems import Problems
from ..yaml_reader import Map

# Numerals as the CUT writer prints them (the fewest digits that round-trip binary32, positional):
# float_pattern must read each whole, and no punctuation of a vector may extend or start one.
NUMERALS = ("0", "-0", "7", "-1.5", "0.0001", "123456.78", "-340282350000000000000000000000000000000")
KEYWORDS = ("header_keyword", "header_ext_keyword", "checksum_keyword")
TOKENS = ("vector_open", "vector_close", "vector_separator")


def _compile(ctx: Problems, node: Map, key: str, where: str) -> re.Pattern[str] | None:
    try:
        pattern = re.compile(node[key], re.ASCII)
    except re.error as exc:
        ctx.fail(node, f"{where}: {node[key]!r} is not a regular expression: {exc}", key)
        return None
    if pattern.groups:
        ctx.fail(node, f"{where}: {node[key]!r} has a capturing group; the reader's expressions number their "
                       f"own (write (?:...))", key)
        return None
    return pattern


def _numbers(ctx: Problems, cut: Map, number: re.Pattern[str]) -> None:
    """float_pattern reads every numeral the writer prints, and no vector punctuation runs into one."""
    for x in NUMERALS:
        if not number.fullmatch(x):
            ctx.fail(cut, f"cut.float_pattern: {cut['float_pattern']!r} does not read {x}, a number the CUT "
                          f"writer prints", "float_pattern")
            return
    for key in TOKENS:
        if _runs_into(number, cut[key]):
            ctx.fail(cut, f"cut.{key}: {cut[key]!r} reads as part of a number (cut.float_pattern)", key)


def _runs_into(number: re.Pattern[str], tok: str) -> bool:
    """Whether the token starts a number, or a numeral followed by it reads on into it."""
    starts = number.match(tok)
    if starts is not None and starts.end() > 0:
        return True
    for x in NUMERALS:
        m = number.match(x + tok)
        if m is None or m.end() != len(x):
            return True
    return False


def _keywords(cut: Map, commands: tuple[Command, ...]) -> dict[str, str]:
    """Each keyword a CUT line may start with, as the reader compares it -> what it is."""
    fold = cut["keyword_case"] == "lower"
    out: dict[str, str] = {}
    for c in commands:
        for name in (c.name, *c.former_names):
            out.setdefault((name.lower() if fold else name).lower(), f"the keyword of command {c.name}")
    return out


@define("cut", "check", reads=("raw", "bare_commands"))
def CUT(ctx: Problems, st: State) -> None:
    """cut: patterns compile (float_pattern reads what the writer prints), keywords differ from each
    other and from every command's, under keyword_case, and the vector's punctuation is three
    distinct tokens that never read as part of a number."""
    cut = st.raw["cut"]
    number = _compile(ctx, cut, "float_pattern", "cut.float_pattern")
    for profile, rule in cut.get("profile_words", {}).items():
        _compile(ctx, rule, "pattern", f"cut.profile_words.{profile}.pattern")
    if number is not None:
        _numbers(ctx, cut, number)
    taken = _keywords(cut, st.bare_commands)
    ext = cut["extensions"]
    named = [(cut, k, f"cut.{k}") for k in KEYWORDS] + [(ext, k, f"cut.extensions.{k}") for k in ext]
    for node, key, where in named:
        word = str(node[key])
        if cut["keyword_case"] == "lower" and node is cut and word != word.lower():
            ctx.fail(node, f"{where}: {word!r} is never read: keyword_case lower folds every keyword", key)
        other = taken.setdefault(word.lower(), where)
        if other != where:
            ctx.fail(node, f"{where}: {word!r} is also {other}; a CUT line's keyword names one thing", key)
    seen: dict[str, str] = {}
    for key in TOKENS:
        other = seen.setdefault(cut[key], key)
        if other != key:
            ctx.fail(cut, f"cut.{key}: {cut[key]!r} is also cut.{other}; the reader tells them apart", key)
