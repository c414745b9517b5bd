"""Facts the spec's free prose states, rendered from the model (issue 37, point 1).

A decision's text may name a fact by placeholder, ``{{writable_versions}}``: the loader renders it
from the model (``render``), so a revision that adds a version or a checksum keeps the prose true
without editing it, and no test or drill fixture rewrites prose. The loader refuses a placeholder
that names no fact, with its YAML line (``unknown``). ``stale`` finds free prose that states one of
these facts by hand and no longer agrees with the model, and says how to fix the sentence.

    {{writable_versions}}   the versions writers emit: "3.0 and 4.0"
    {{read_only_versions}}  the versions only read: "1.x and 2.x"
    {{versions}}            every version, in the spec's order
    {{default_version}}     the version a CUT text without one is read as
    {{fallback_version}}    the version whose layout reads a file of no known version
    {{checksum_count}}      how many checksum fields the format has, as a word: "three"
    {{checksum_algorithms}} which checksums use which algorithm, one sentence:
                            "All three checksums are plain unsigned byte sums."
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable
from dataclasses import dataclass

from .model import Checksums, Version

PLACEHOLDER = re.compile(r"\{\{\s*([A-Za-z_][A-Za-z0-9_]*)\s*\}\}")
_WORDS = ("no", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve")


@dataclass(frozen=True)
class Facts:
    """What the prose may state, read from the model."""

    versions: tuple[Version, ...]
    checksums: Checksums
    default_version: str
    fallback_version: str


def and_list(items: Iterable[str]) -> str:
    """"a", "a and b", "a, b and c"."""
    xs = list(items)
    if not xs:
        return "none"
    return xs[0] if len(xs) == 1 else ", ".join(xs[:-1]) + " and " + xs[-1]


def number_word(n: int) -> str:
    return _WORDS[n] if 0 <= n < len(_WORDS) else str(n)


def _algorithm_label(f: Facts, name: str, plural: bool) -> str:
    alg = f.checksums.algorithms[name]
    if alg.is_sum:
        return "plain unsigned byte sums" if plural else "a plain unsigned byte sum"
    return alg.doc.split(" (")[0].rstrip(".")  # "CRC-32/ISO-HDLC (polynomial ...)" -> "CRC-32/ISO-HDLC"


def checksum_algorithms(f: Facts) -> str:
    """One sentence: which checksum fields use which algorithm (the plain sums first)."""
    fields = f.checksums.fields
    algs = list(dict.fromkeys(x.algorithm for x in fields))
    if len(algs) == 1:
        return f"All {number_word(len(fields))} checksums are {_algorithm_label(f, algs[0], True)}."
    algs.sort(key=lambda a: not f.checksums.algorithms[a].is_sum)
    parts = []
    for a in algs:
        names = [x.field for x in fields if x.algorithm == a]
        many = len(names) > 1
        parts.append(f"the {and_list(names)} checksum{'s are' if many else ' is'} {_algorithm_label(f, a, many)}")
    text = "; ".join(parts) + "."
    return text[0].upper() + text[1:]


FACTS: dict[str, Callable[[Facts], str]] = {
    "writable_versions": lambda f: and_list(v.id for v in f.versions if v.writable),
    "read_only_versions": lambda f: and_list(v.id for v in f.versions if not v.writable),
    "versions": lambda f: and_list(v.id for v in f.versions),
    "default_version": lambda f: f.default_version,
    "fallback_version": lambda f: f.fallback_version,
    "checksum_count": lambda f: number_word(len(f.checksums.fields)),
    "checksum_algorithms": checksum_algorithms,
}


def unknown(text: str) -> list[str]:
    """The placeholders of text that name no fact, and a stray "{{" or "}}" (a placeholder mistyped)."""
    bad = [m.group(0) for m in PLACEHOLDER.finditer(text) if m.group(1) not in FACTS]
    rest = PLACEHOLDER.sub("", text)
    if "{{" in rest or "}}" in rest:
        bad.append(rest[max(rest.find("{{"), 0):][:40] if "{{" in rest else "}}")
    return bad


def render(text: str, facts: Facts) -> str:
    """text with each placeholder replaced by its fact (unknown() is empty: the loader checked)."""
    return PLACEHOLDER.sub(lambda m: FACTS[m.group(1)](facts), text)


# -- prose that states a fact by hand ---------------------------------------------------------------

_VID = r"\d+\.(?:\d+|x)"
_EMIT = re.compile(rf"Writers emit ({_VID}(?:, {_VID})*(?: and {_VID})?)")
_ALL_SUMS = re.compile(r"\ball (?:three|the|\w+) checksums are\b[^.]*\bsums?\b", re.IGNORECASE)


def stale(where: str, text: str, facts: Facts) -> list[str]:
    """What text (rendered) states by hand that the model no longer says, each with its fix: a version
    the spec lacks, writable versions that are not the writable ones, checksums called sums that are not."""
    out = []
    ids = {v.id for v in facts.versions}
    named = set(re.findall(r"\b\d+\.x\b", text)) | set(re.findall(rf"\b[Vv]ersions? ({_VID})\b", text))
    for major in sorted(v for v in named - ids if f"{v.split('.')[0]}.x" not in ids):  # 1.01 is a 1.x
        out.append(f"{where}: names version {major}, which the spec does not have: reword the sentence "
                   f"(or name the versions by a fact: {{{{versions}}}}, {{{{read_only_versions}}}})")
    emit = _EMIT.search(text)
    writable = FACTS["writable_versions"](facts)
    if emit and set(re.split(r", | and ", emit.group(1))) != {v.id for v in facts.versions if v.writable}:
        out.append(f"{where}: {emit.group(0)!r} is stale, writers emit {writable}: write "
                   f"'Writers emit {{{{writable_versions}}}}' in spec/cbf.yaml")
    sums = _ALL_SUMS.search(text)
    if sums and not all(facts.checksums.algorithms[x.algorithm].is_sum for x in facts.checksums.fields):
        out.append(f"{where}: {sums.group(0)!r} is stale ({checksum_algorithms(facts)}): write "
                   f"'{{{{checksum_algorithms}}}}' in spec/cbf.yaml")
    return out
