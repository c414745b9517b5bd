"""Issue 13, item 1: the CUT float formatter. Every finite binary32 pattern is written with
the fewest significant digits that read back (correctly rounded) as the same bits, in
plain positional notation the CUT float pattern accepts; NaN and infinity are written as
cbf_record. `make floats-exhaustive` proves it over all 2^32 patterns with the C twin
tests/floats/exhaustive.c; this file checks the edges, a sample, and that the twin and
this formatter write the same text."""

from __future__ import annotations

import random
import re
import shutil
import struct
import subprocess
from decimal import Decimal
from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import example, given
from hypothesis import strategies as st

import cbf
from cbf import tables as T
from cbf.cut import format_float, keyword
from cbf.model import Cbf, Record, new_header

REPO = Path(__file__).resolve().parents[1]
TWIN = REPO / "tests" / "floats" / "exhaustive.c"
FLOAT_PATTERN = re.compile(T.CUT["float_pattern"], re.ASCII)
SPEED = next(c for c in T.COMMANDS
             if [(f.kind, f.count) for f in c.layouts_for(T.DEFAULT_VERSION)[0].args] == [("float", 1)])
SPEED_LAY = SPEED.layouts_for(T.DEFAULT_VERSION)[0]


def _f32(bits: int) -> float:
    return float(struct.unpack("<f", struct.pack("<I", bits))[0])


def _bits_of(value: float) -> int:
    return int(struct.unpack("<I", struct.pack("<f", value))[0])


# The first value `cbf decode --to cut` crashed on (3.40250016e38), and every larger one.
CRASH_FROM = _bits_of(3.40250016e38)
CRASHED = [b for lo in (CRASH_FROM, CRASH_FROM | 0x80000000) for b in range(lo, (lo & 0x80000000) | 0x7F800000)]


def _reference_bits(text: str) -> int | None:
    """Round-to-nearest-even of the exact decimal, None beyond the binary32 range (the reference).

    Exact integer arithmetic on the decimal's fraction n/d, independent of the formatter and of
    any float parsing: the quantum 2^q of binary32 at the value's binade (2^-149 below the
    normals), the quotient n/d in quanta rounded half to even, and the bits as exponent and
    mantissa (a quotient that rounds up to the next binade, or to infinity, carries into the
    exponent field). It agreed with a bisection over the 2^31 patterns by Fraction comparisons
    on 104,725 texts (every edge's text and its shorter %g forms, random patterns, the ties
    around the smallest subnormal and FLT_MAX), at a hundredth of the cost."""
    x = Fraction(Decimal(text))
    sign = 0x80000000 if x < 0 or text.startswith("-") else 0
    n, d = abs(x.numerator), x.denominator
    if n == 0:
        return sign
    e = n.bit_length() - d.bit_length()  # 2^e <= n/d < 2^(e+1), or one binade too high
    if (n << max(0, -e)) < (d << max(0, e)):
        e -= 1
    q = max(e - 23, -149)
    num, den = (n << -q, d) if q < 0 else (n, d << q)
    m, r = divmod(num, den)
    if 2 * r > den or (2 * r == den and m & 1):
        m += 1
    bits = ((q + 150) << 23) + m - (1 << 23)  # a subnormal (q = -149, m < 2^23) gives m itself
    return None if bits >= 0x7F800000 else sign | bits


def _read_back(texts: list[str]) -> list[int]:
    """The bits from_cut reads from each text, each on a line of its own, all in one CUT text: a
    call costs about 0.4 ms of setup whatever its length, and a line's number is its own."""
    model = cbf.from_cut("".join(f"{keyword(SPEED)} {text}\n" for text in texts))
    assert len(model.records) == len(texts)
    return [int(SPEED_LAY.bits.unpack(r.raw_args)[0]) for r in model.records]


def _check_all(patterns: list[int]) -> None:
    finite = []
    for bits in patterns:
        value = _f32(bits)
        if value != value or value in (float("inf"), float("-inf")):
            model = Cbf(new_header(), (Record(code=SPEED.code, raw_args=SPEED_LAY.bits.pack(bits)),))
            line = cbf.to_cut(model).splitlines()[-1]
            assert line.startswith(T.CUT["extensions"]["record_keyword"] + " "), line
            assert cbf.from_cut(cbf.to_cut(model)).records[0].raw_args == SPEED_LAY.bits.pack(bits)
        else:
            finite.append(bits)
    texts = [format_float(bits) for bits in finite]
    for bits, text, back in zip(finite, texts, _read_back(texts), strict=True):
        assert FLOAT_PATTERN.fullmatch(text), text
        assert back == bits, (hex(bits), text)
        assert _reference_bits(text) == bits, (hex(bits), text)
        digits = len(text.lstrip("-").replace(".", "").strip("0")) or 1
        value = _f32(bits)
        for p in range(1, digits):  # no shorter correctly rounded text reads back
            assert _reference_bits(f"{value:.{p}g}") != bits, (hex(bits), text, p)


def _check(bits: int) -> None:
    _check_all([bits])


@given(st.integers(0, 0xFFFFFFFF))
@example(CRASH_FROM)        # 3.40250016e38: 4 digits gave 3.403e+38, which overflows
@example(0x7F7FFFFF)        # FLT_MAX
@example(0xFF7FFFFF)        # -FLT_MAX
@example(0x7F7FFFFE)
@example(CRASH_FROM - 1)
@example(0x00000001)        # the smallest subnormal
@example(0x807FFFFF)        # the largest subnormal, negative
@example(0x80000000)        # -0
@example(0x7F800000)        # infinity: cbf_record
@example(0xFFC00001)        # a NaN: cbf_record
def test_every_pattern_reads_back_or_is_a_record(bits: int) -> None:
    _check(bits)


def test_every_pattern_that_crashed_now_reads_back() -> None:
    assert len(CRASHED) == 3190  # as the issue counted
    texts = [format_float(bits) for bits in CRASHED]
    for bits, text, back in zip(CRASHED, texts, _read_back(texts), strict=True):
        assert FLOAT_PATTERN.fullmatch(text) and back == bits, (hex(bits), text)


def _edges() -> list[int]:
    out = {0, 0x80000000, 1, 0x007FFFFF, 0x00800000, 0x7F7FFFFF, 0x7F800000, 0x7FC00000, 0xFFFFFFFF}
    for e in range(256):
        for m in (0, 1, 2, 0x3FFFFF, 0x400000, 0x400001, 0x7FFFFE, 0x7FFFFF):
            out.update({(e << 23) | m, 0x80000000 | (e << 23) | m})
    for k in range(-46, 39):  # the binary32 values around each power of ten
        try:
            b = _bits_of(float(f"1e{k}"))
        except OverflowError:
            continue
        out.update(b + d for d in (-2, -1, 0, 1, 2) if 0 <= b + d <= 0xFFFFFFFF)
    return sorted(out)


EDGES = _edges()


def test_edges() -> None:
    _check_all(EDGES)


@pytest.fixture(scope="module")
def twin(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The C twin, compiled once for both tests that run it."""
    cc = shutil.which("gcc") or shutil.which("cc")
    if cc is None:
        pytest.skip("no C compiler for the formatter's C twin")
    exe = tmp_path_factory.mktemp("twin") / "exhaustive"
    subprocess.run([cc, "-std=c99", "-O2", "-Wall", "-Wextra", "-Werror", "-o", str(exe), str(TWIN), "-lm"],
                   check=True, capture_output=True)
    return exe


def test_the_c_twin_writes_what_the_formatter_writes(twin: Path) -> None:
    """What makes `make floats-exhaustive` a proof about this formatter: its C twin agrees."""
    exe = twin
    rnd = random.Random(13)
    sample = EDGES + CRASHED + [rnd.getrandbits(32) for _ in range(20_000)]
    res = subprocess.run([str(exe), "--print"], input="".join(f"{b:08x}\n" for b in sample),
                         capture_output=True, text=True, check=True)
    got = res.stdout.splitlines()
    assert len(got) == len(sample)
    for bits, text in zip(sample, got, strict=True):
        value = _f32(bits)
        want = "cbf_record" if value != value or abs(value) == float("inf") else format_float(bits)
        assert text == want, (hex(bits), text, want)


def test_the_c_twin_sweeps_a_range(twin: Path) -> None:
    exe = twin
    res = subprocess.run([str(exe), hex(CRASH_FROM - 50_000), "0x7f800010"], capture_output=True, text=True)
    assert res.returncode == 0, res.stderr
    finite = 0x7F7FFFFF - (CRASH_FROM - 50_000) + 1
    assert f": {finite} finite read back byte-exact, 17 NaN/infinity written as cbf_record, 0 failed" in res.stdout
