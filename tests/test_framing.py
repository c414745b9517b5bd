"""Framing has two code paths: the loop of codec.frame (D1) and, for big files, the numpy
pointer doubling of codec._frame_ahead that the loop finishes. Both must give the same
offsets and the same end on every input (the loop is the reference)."""

from __future__ import annotations

import random
from array import array
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from cbf import codec
from cbf.fields import Buffer
from cbf.testing import cutfiles, mutations

GOLDEN = Path(__file__).resolve().parents[1] / "conformance" / "golden"


def _both(data: bytes, monkeypatch: pytest.MonkeyPatch) -> tuple[tuple[list[int], int], tuple[list[int], int]]:
    monkeypatch.setattr(codec, "FAST_FRAME_BYTES", 1 << 62)
    loop = codec.frame(data)
    monkeypatch.setattr(codec, "FAST_FRAME_BYTES", 0)
    ahead = codec.frame(data)
    return (list(loop[0]), loop[1]), (list(ahead[0]), ahead[1])


def _mutate(rnd: random.Random, data: bytes) -> bytes:
    x = bytearray(data)
    for _ in range(rnd.choice([0, 1, 2, 5, 20])):
        if not x:
            break
        p = rnd.randrange(len(x))
        op = rnd.random()
        if op < 0.6:
            x[p] = rnd.randrange(256)
        elif op < 0.8:
            x[p] ^= 1 << rnd.randrange(8)
        else:
            del x[p:p + rnd.randrange(1, 10)]
    return bytes(x)


def test_frame_ahead_agrees_with_the_loop_on_mutated_goldens(monkeypatch: pytest.MonkeyPatch) -> None:
    rnd = random.Random(20261123)
    seeds = [p.read_bytes() for p in sorted(GOLDEN.glob("*.cbf"))]
    framed = 0
    for _ in range(300):
        data = _mutate(rnd, rnd.choice(seeds))
        loop, ahead = _both(data, monkeypatch)
        assert loop == ahead, f"framings differ on {len(data)} bytes"
        framed += len(loop[0])
    assert framed > 1000


def test_frame_ahead_is_used_and_frames_a_valid_big_file(monkeypatch: pytest.MonkeyPatch) -> None:
    data = max((p.read_bytes() for p in GOLDEN.glob("*.cbf")), key=len)
    assert len(data) >= codec.FAST_FRAME_BYTES  # the fast path is the one a big file takes
    calls: list[int] = []
    real = codec._frame_ahead

    def counted(buf: Buffer, offs: array[int]) -> int:
        calls.append(1)
        return real(buf, offs)

    monkeypatch.setattr(codec, "_frame_ahead", counted)
    offsets, end = codec.frame(data)
    assert calls and end == len(data) and len(offsets) > 1000


@settings(deadline=None, suppress_health_check=[HealthCheck.too_slow])  # examples: the profile
@given(st.one_of(mutations(), cutfiles(max_records=40), st.binary(max_size=2000)))
def test_frame_ahead_agrees_with_the_loop_on_generated_files(data: bytes) -> None:
    with pytest.MonkeyPatch.context() as mp:
        loop, ahead = _both(data, mp)
    assert loop == ahead
