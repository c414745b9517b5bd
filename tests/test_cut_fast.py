"""The fast paths of the CUT form (issue 17) against the careful ones they stand in for.

- ``from_cut`` reads the common lines (a keyword and its numbers) with one regular
  expression and converts their numbers in batches; ``from_cut(fast=False)`` reads every
  line with the careful parser of issue 13. Both must accept the same texts, give the same
  records, header and encoded bytes, and refuse the same texts with the same error (message,
  line, column): on hypothesis-generated text (grammar fragments, valid and not), on the
  golden files written as CUT, and on those texts mutated a character at a time.
- ``to_cut`` writes the records of a decoded file a layout at a time; the same records as a
  plain tuple are written one by one. Both must give the same text.
- ``floats.format_floats`` (batched) must give ``format_float``'s text for every pattern.

Keywords, separators and layouts come from the model (cbf.tables), never from here.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import example, given
from hypothesis import strategies as st

import cbf
from cbf import tables as T
from cbf.cut import keyword
from cbf.floats import format_float, format_floats, parse_float, parse_floats
from cbf.model import Cbf

GOLDEN = Path(__file__).resolve().parents[1] / "conformance" / "golden"
C = T.CUT
EXT = C["extensions"]
PROFILES = list(T.PROFILES)


def _golden_models() -> list[tuple[str, Cbf]]:
    out = []
    for p in sorted(GOLDEN.glob("*.cbf")):
        try:
            out.append((p.name, cbf.decode(p.read_bytes())))
        except cbf.CbfError:
            continue
    return out


GOLDEN_MODELS = _golden_models()
SMALL = 20_000  # characters of CUT text: every golden file but the 65,535-record one


def _golden_texts() -> list[tuple[str, str, str]]:
    """(name, profile, CUT text) of every golden file that has a CUT form, small ones first."""
    out = []
    for name, model in GOLDEN_MODELS:
        for profile in PROFILES:
            try:
                out.append((name, profile, cbf.to_cut(model, profile=profile)))
            except ValueError:
                continue
    return sorted(out, key=lambda t: len(t[2]))


GOLDEN_TEXTS = _golden_texts()
SMALL_TEXTS = [t for t in GOLDEN_TEXTS if len(t[2]) < SMALL]


def _outcome(text: str, fast: bool, profile: str = "default", version: str | None = None) -> Any:
    """What from_cut makes of a text: the records, header and encoded bytes, or the error."""
    try:
        model = cbf.from_cut(text, version=version, profile=profile, fast=fast)
    except cbf.CutSyntaxError as exc:
        return ("refused", str(exc), exc.line, exc.column)
    recs = [(r.code, bytes(r.raw_args), r.sequence, r.code_copy, r.reserved, r.arg_checksum) for r in model.records]
    try:
        data: Any = cbf.encode(model, profile=profile)
    except cbf.EncodeError as exc:
        data = ("encode refused", str(exc), exc.offset)
    return ("read", recs, model.header, model.trailing, data)


def _same(text: str, profile: str = "default", version: str | None = None) -> Any:
    fast = _outcome(text, True, profile, version)
    assert fast == _outcome(text, False, profile, version), text[:2000]
    return fast


# -- from_cut: the golden files as CUT ---------------------------------------------------------
def test_the_golden_corpus_is_there() -> None:
    assert len(GOLDEN_TEXTS) >= 10
    assert any(len(t) > 1_000_000 for _, _, t in GOLDEN_TEXTS)  # the 65,535-record file


@pytest.mark.parametrize(("name", "profile", "text"), GOLDEN_TEXTS, ids=lambda x: x if len(x) < 60 else "")
def test_golden_texts_read_alike(name: str, profile: str, text: str) -> None:
    got = _same(text, profile)
    if got[0] == "read":  # a version this spec has: the records' arguments as in the file
        model = dict(GOLDEN_MODELS)[name]  # cbf.decode of the file, made once at import
        assert [r[1] for r in got[1]] == [bytes(r.raw_args) for r in model.records]
    else:
        assert EXT["version_keyword"] in text


def _mutants(text: str, count: int) -> list[str]:
    """The text with one character deleted, doubled or replaced, at evenly spread places."""
    out = []
    step = max(1, len(text) // count)
    fillers = [" ", "-", ".", "0", "9", C["vector_separator"], C["vector_open"], C["vector_close"], "e", "\n", "\r"]
    for k, at in enumerate(range(0, len(text), step)):
        out.append(text[:at] + text[at + 1:])
        out.append(text[:at] + text[at] + text[at:])
        out.append(text[:at] + fillers[k % len(fillers)] + text[at + 1:])
    return out


@pytest.mark.parametrize(("name", "profile", "text"), SMALL_TEXTS[:12], ids=lambda x: x if len(x) < 60 else "")
def test_mutated_golden_texts_read_alike(name: str, profile: str, text: str) -> None:
    outcomes = {_same(m, profile)[0] for m in _mutants(text, 60)}
    assert outcomes <= {"read", "refused"}


# -- from_cut: generated text --------------------------------------------------------------------
def _fast_layouts() -> list[tuple[str, T.LayoutInfo]]:
    out = []
    for cmd in T.COMMANDS:
        lay = next(iter(cmd.layouts_for(T.DEFAULT_VERSION)), None)
        if lay is not None and all(f.kind in ("float", "bytes") for f in lay.args):
            out.append((keyword(cmd), lay))
    return out


LAYOUTS = _fast_layouts()
NUMBERS = st.one_of(
    st.integers(-10**6, 10**6).map(str),
    st.floats(-1e4, 1e4, allow_nan=False).map(lambda x: f"{x:.{abs(hash(x)) % 12}f}"),
    st.floats(width=32, allow_nan=False, allow_infinity=False).map(lambda x: format(x, "f")),
    st.sampled_from(["0", "-0", "0.", "-0.0", "1.", "00012.5000", "1.000000059604644775390625",
                     "340282356779733661637539395458142568447", "340282356779733661637539395458142568448",
                     "1" + "0" * 60, "0." + "0" * 50 + "1", "-", ".5", "1.2.3", "1e5", "--1", "+1", "1,5"]),
)
SPACES = st.sampled_from(["", " ", "  "])


@st.composite
def _line(draw: st.DrawFn) -> str:
    """A line of a float layout, mostly well formed, sometimes broken at one place."""
    kw, lay = draw(st.sampled_from(LAYOUTS))
    tokens: list[str] = [draw(st.sampled_from([kw, kw, kw, kw.upper(), " " + kw]))]
    for f in lay.args:
        if f.kind != "float":
            continue
        if f.count > 1:
            inner = [draw(NUMBERS) for _ in range(f.count)]
            sep = draw(SPACES) + C["vector_separator"] + draw(SPACES)
            tokens.append(C["vector_open"] + draw(SPACES) + sep.join(inner) + draw(SPACES) + C["vector_close"])
        else:
            tokens.append(draw(NUMBERS))
    line = tokens[0] + "".join(draw(st.sampled_from([" ", "  "])) + t for t in tokens[1:]) + draw(SPACES)
    edit = draw(st.integers(0, 9))
    if edit == 0 and len(line) > 1:  # drop a character
        at = draw(st.integers(0, len(line) - 1))
        line = line[:at] + line[at + 1:]
    elif edit == 1:  # insert one
        at = draw(st.integers(0, len(line)))
        line = line[:at] + draw(st.sampled_from([" ", "x", "1", ".", "-", C["vector_separator"]])) + line[at:]
    elif edit == 2:  # trailing text
        line += draw(st.sampled_from([" 1", " x", C["vector_close"], " " + C["vector_open"]]))
    elif edit == 3 and " " in line.strip(" "):  # two tokens run together
        spaces = [k for k, ch in enumerate(line) if ch == " "]
        at = draw(st.sampled_from(spaces))
        line = line[:at] + line[at + 1:]
    return line


@st.composite
def _texts(draw: st.DrawFn) -> str:
    head = draw(st.sampled_from(["", f"{C['header_keyword']} PN-1 TEST\n"]))
    lines = draw(st.lists(st.one_of(_line(), _line(), st.sampled_from(["", "  ", "cutter_on", "bogus 1"])),
                          min_size=1, max_size=12))
    end = draw(st.sampled_from(["\n", "\r\n"]))
    return head + end.join(lines) + draw(st.sampled_from(["", end]))


# Two scalar numbers run together: the careful parser takes the longest number, then finds
# none; a regular expression that backtracks would split "1234" into "123" and "4".
SCALARS = next((k for k, x in LAYOUTS if len(x.args) >= 2 and all(f.kind == "float" and f.count == 1 for f in x.args)),
               None)


@given(_texts(), st.sampled_from(PROFILES))
@example(f"{LAYOUTS[0][0]} " + " ".join(["1"] * 40), "default")
@example(f"{SCALARS} 1234\n", "default")
@example(f"{SCALARS} 12.5.5\n", "default")
def test_generated_texts_read_alike(text: str, profile: str) -> None:
    _same(text, profile)


def test_run_together_numbers_are_refused_on_both_paths() -> None:
    assert SCALARS is not None
    got = _same(f"{SCALARS} 1234\n")
    assert got[0] == "refused" and ("not a number" in got[1] or "a number is missing" in got[1])


def test_an_error_on_a_line_before_a_careful_line_comes_first() -> None:
    """A number the batch refuses (beyond binary32) on line 2, an unknown keyword on line 3:
    the error of line 2 is the one raised, as the careful parser raises it."""
    kw, lay = next((k, x) for k, x in LAYOUTS if len(x.args) == 1 and x.args[0].count == 1)
    text = f"{kw} 1\n{kw} 1{'0' * 40}\nbogus 1\n"
    got = _same(text)
    assert got[0] == "refused" and got[2] == 2


def test_the_command_limit_is_counted_on_the_fast_path() -> None:
    kw, lay = next((k, x) for k, x in LAYOUTS if len(x.args) == 1 and x.args[0].count == 1)
    limit = T.LIMITS["max_commands"]
    got = _same(f"{kw} 1\n" * (limit + 1))
    assert got[0] == "refused" and got[2] == limit + 1


# -- to_cut ----------------------------------------------------------------------------------------
@pytest.mark.parametrize(("name", "model"), GOLDEN_MODELS, ids=lambda x: x if isinstance(x, str) else "")
def test_to_cut_by_layout_writes_what_one_by_one_writes(name: str, model: Cbf) -> None:
    plain = Cbf(model.header, tuple(model.records), model.trailing)
    for profile in PROFILES:
        try:
            one = cbf.to_cut(plain, profile=profile)
        except ValueError as exc:
            with pytest.raises(ValueError) as got:
                cbf.to_cut(model, profile=profile)
            assert str(got.value) == str(exc)
            continue
        assert cbf.to_cut(model, profile=profile) == one


# -- the floats, batched ---------------------------------------------------------------------------
def _patterns() -> np.ndarray:
    """Finite patterns, both signs: the places the batched formatter could part from the loop
    (every exponent with edge mantissas, the neighbours of d * 10^k, binary fractions whose
    decimal digits end in a tie, millimetres to three places, the subnormals) and a seeded
    sample of all 2^32 (make floats-exhaustive checks every pattern)."""
    rng = np.random.default_rng(17)
    edges = (0, 1, 2, 3, 0x155555, 0x2AAAAA, 0x3FFFFF, 0x400000, 0x400001, 0x7FFFFD, 0x7FFFFE, 0x7FFFFF)
    tens = np.array([d * 10.0**k for k in range(-45, 39) for d in range(1, 10)])
    tens = tens[tens < float(np.finfo(np.float32).max)].astype(np.float32).view(np.uint32).astype(np.int64)
    steps = [np.array([(e << 23) | m for e in range(255) for m in edges], dtype=np.int64),
             (tens[:, None] + np.arange(-2, 3)).ravel(),
             np.array([(2 * m + 1) / 2.0**j for j in range(1, 12) for m in range(64)], dtype=np.float32)
             .view(np.uint32).astype(np.int64),
             (np.arange(-2_000, 2_000) / np.float32(1000)).astype(np.float32).view(np.uint32).astype(np.int64),
             np.arange(0, 1_024, dtype=np.int64),
             rng.integers(0, 1 << 23, 1_000, dtype=np.int64),
             np.arange(0, 1 << 32, 1_000_003, dtype=np.int64),
             rng.integers(0, 1 << 32, 8_000, dtype=np.int64)]
    bits = np.concatenate(steps)
    bits = bits[(bits >= 0) & (bits < 1 << 31)].astype(np.uint32)
    bits = np.concatenate([bits, bits | np.uint32(0x80000000)])
    finite: np.ndarray = bits[(bits & 0x7F800000) != 0x7F800000]
    return finite


def _digits(text: str) -> int:
    return max(len(text.replace("-", "").replace(".", "").strip("0")), 1)


def test_format_floats_writes_what_format_float_writes() -> None:
    bits = _patterns()
    want = [format_float(b) for b in bits.tolist()]
    assert format_floats(bits) == want
    # The set reaches both sides of the batched search's first guess (7 digits): every length
    # of text from 1 to 9 digits among the normals, and from 1 to 8 among the subnormals
    # (whose 23 bits or fewer never needed a 9th digit here).
    normal = (bits & 0x7F800000) != 0
    for kind, mask, lengths in (("normal", normal, range(1, 10)), ("subnormal", ~normal, range(1, 9))):
        got = {_digits(t) for t, m in zip(want, mask.tolist(), strict=True) if m}
        assert got >= set(lengths), (kind, sorted(got))


@given(st.lists(st.integers(0, (1 << 32) - 1), max_size=50))
def test_format_floats_on_generated_patterns(patterns: list[int]) -> None:
    bits = np.array([b for b in patterns if b & 0x7F800000 != 0x7F800000], dtype=np.uint32)
    assert format_floats(bits) == [format_float(b) for b in bits.tolist()]


def test_parse_floats_reads_what_parse_float_reads() -> None:
    texts = [format(x, "f") for x in np.linspace(-1e6, 1e6, 2001).tolist()]
    texts += ["1.000000059604644775390625", "1.0000000596046447753906249", "1.0000000596046447753906251",
              "340282356779733661637539395458142568447", "340282356779733661637539395458142568448",
              "0." + "0" * 44 + "7", "0." + "0" * 46 + "7", "-0", "1" + "0" * 50]
    bits, bad = parse_floats(texts)
    for k, t in enumerate(texts):
        try:
            assert int(bits[k]) == parse_float(t) and k not in bad, t
        except ValueError:
            assert k in bad, t
