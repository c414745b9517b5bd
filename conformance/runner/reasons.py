"""Known failures by case and reason, not by byte (issue 37, point 3).

A failure list entry is ``case REASON``. REASON is one of:

- a failure class, what ``failure_class`` makes of the failure's message and what ``--fix`` writes:
  the operation and what went wrong, without the testee's own wording, offsets or values
  (``decode: refused validation``, ``decode: differs at $.records[2].args.point[2]``,
  ``validate: [default] findings differ: missing 6.2.1/error``). A revision that only moves a
  message (a Kaitai parser's ``seq/3`` becoming ``seq/6``, an error 4 bytes later) keeps its class;
- ``~ REGEX``: a message pattern, searched for in the message (a hand-written entry);
- the exact message (lists written before classes existed still read).

An entry whose case now passes, or fails for another reason, fails the run (a stale entry is said,
never kept silently); ``--fix`` rewrites the list and prints the diff to review.
"""

from __future__ import annotations

import re

from .quoting import line as one_line

PATTERN_MARK = "~ "

# Each rule: a message's shape -> its class ("{step}" is the operation the message starts with).
_KIND = r".*?'kind': '(?P<kind>[^']*)'"
_RULES: tuple[tuple[re.Pattern[str], str], ...] = tuple((re.compile(p, re.S), c) for p, c in (
    (r"failed to decode: \{" + _KIND, "refused {kind}"),
    (r"cannot decode to re-encode: \{" + _KIND, "cannot decode to re-encode: refused {kind}"),
    (r"error (?P<got>\S*)@\S*, expected (?P<want>\S*)@", "error {got}, expected {want}"),
    (r"decoded, expected error (?P<want>\S+)", "decoded, expected error {want}"),
    (r"(?P<where>[$/][^:\s]*): (expected|missing)", "differs at {where}"),
    (r"expected \d+ records, got \d+", "record count differs"),
    (r"\[(?P<profile>[^\]]+)\] validate failed: \{" + _KIND, "[{profile}] refused {kind}"),
    (r"\[(?P<profile>[^\]]+)\] (?P<diff>(missing|unexpected) .*)", "[{profile}] findings differ: {diff}"),
    (r"keep_stored=(?P<keep>\w+): refused", "keep_stored={keep}: refused"),
    (r"keep_stored=(?P<keep>\w+): bytes differ", "keep_stored={keep}: bytes differ"),
))
_FINDING = re.compile(r"(?P<check>[^,;\s]+)/(?P<severity>[a-z]+)/(header|record -?\d+) @(no offset|offset -?\d+)")


def _findings(diff: str) -> str:
    """`missing 6.2.1/error/header @offset 4, ...; unexpected ...` -> `missing 6.2.1/error; unexpected ...`:
    which checks at which severity, not where (a revision moves offsets and records)."""
    parts = []
    for part in diff.split("; "):
        word, _, rest = part.partition(" ")
        keys = sorted({f"{m['check']}/{m['severity']}" for m in _FINDING.finditer(rest)})
        parts.append(f"{word} {', '.join(keys)}" if keys else part)
    return "; ".join(parts)


def failure_class(message: str) -> str:
    """The stable reason of a failure message: its operation and what went wrong (see the module), one
    line (a testee's control characters and line breaks escaped: a list holds a case a line)."""
    return one_line(_failure_class(message))


def _failure_class(message: str) -> str:
    step, sep, rest = message.partition(": ")
    if not sep:
        return re.sub(r"\d+", "N", message)
    if rest == "skipped":
        return message
    for pattern, cls in _RULES:
        m = pattern.match(rest)
        if m:
            groups = {k: v for k, v in m.groupdict().items() if v is not None}
            if "diff" in groups:
                groups["diff"] = _findings(groups["diff"])
            return f"{step}: {cls.format(**groups)}"
    # a testee's own failure (it exited, wrote no JSON, ...): its words without numbers or quoted text
    rest = re.sub(r"'[^']*'|\"[^\"]*\"", "'...'", rest)
    return f"{step}: {re.sub(r'[0-9]+', 'N', rest)}"


def matches(reason: str, message: str) -> bool:
    """Whether a failure list's REASON covers a failure's message (a class, a pattern, the message)."""
    if reason.startswith(PATTERN_MARK):
        try:
            return re.search(reason[len(PATTERN_MARK):], message) is not None
        except re.error:
            return False
    return reason == message or reason == failure_class(message)


def bad_pattern(reason: str) -> str | None:
    """Why a ``~ REGEX`` reason is not a regular expression, or None."""
    if not reason.startswith(PATTERN_MARK):
        return None
    try:
        re.compile(reason[len(PATTERN_MARK):])
    except re.error as exc:
        return f"not a regular expression ({exc})"
    return None


def fixed_entries(failures: dict[str, str], listed: dict[str, str]) -> dict[str, str]:
    """The list ``--fix`` writes: each failing case with its listed reason when that still covers
    its failure (a hand-written pattern is kept), else its failure class (an exact message becomes one)."""
    def keep(case: str, msg: str) -> bool:
        return case in listed and listed[case].startswith(PATTERN_MARK) and matches(listed[case], msg)
    return {case: listed[case] if keep(case, msg) else failure_class(msg) for case, msg in failures.items()}
