"""The two validation engines (reference loop, numpy) must agree on every input.

validate() picks the numpy engine for big files only, so everything the
reference loop checks on small files must come out the same from the numpy
engine: same findings, same order, same messages.
"""

from __future__ import annotations

import random
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import cbf
from cbf import tables as T
from cbf.validation import validate

GOLDEN = Path(__file__).resolve().parents[1] / "conformance" / "golden"


def _sample_file() -> bytes:
    """A valid file with one record of every command of the default version, built from the spec tables."""
    from cbf.model import Cbf, Record, new_header

    records = []
    for cmd in T.COMMANDS:
        lay = cmd.layout_for_size(T.DEFAULT_VERSION, next(iter(cmd.layouts_for(T.DEFAULT_VERSION) or cmd.layouts)).size)
        if lay is None:
            continue
        records.append(Record(code=cmd.code, raw_args=bytes(lay.size)))
    return cbf.encode(Cbf(new_header(T.DEFAULT_VERSION, implant_descriptor="PN1 X"), tuple(records)), keep_stored=True)


def _seeds() -> list[bytes]:
    seeds = [_sample_file()]
    seeds += [p.read_bytes() for p in sorted(GOLDEN.glob("*.cbf")) if p.stat().st_size < 20_000]
    return seeds


def _mutate(rnd: random.Random, data: bytes) -> bytes:
    x = bytearray(data * rnd.choice([1, 1, 2]))
    for _ in range(rnd.choice([1, 1, 2, 3, 8])):
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


def _both(data: bytes, profile: str) -> tuple[list[cbf.Finding], list[cbf.Finding]]:
    opts = {"profile": profile, "part_number": "PN1", "cutters": {"C1": (10.0, 2.0)}}
    return validate(data, engine="python", **opts), validate(data, engine="numpy", **opts)  # type: ignore[arg-type]


@pytest.mark.parametrize("profile", list(T.PROFILES))
def test_engines_agree_on_seeded_mutations(profile: str) -> None:
    rnd = random.Random(20261122)
    seeds = _seeds()
    compared = 0
    for _ in range(600):
        data = _mutate(rnd, rnd.choice(seeds))
        ref, vec = _both(data, profile)
        assert ref == vec, f"engines disagree on {data.hex()}"
        compared += len(ref)
    assert compared > 0  # the mutations did produce findings to compare


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.binary(min_size=0, max_size=600))
def test_engines_agree_on_random_bytes(tail: bytes) -> None:
    data = _sample_file()[:128] + tail
    ref, vec = _both(data, "default")
    assert ref == vec


def test_auto_switches_engine_by_size(monkeypatch: pytest.MonkeyPatch) -> None:
    import cbf.vectorized as vec

    calls: list[int] = []
    real = vec.records
    monkeypatch.setattr(vec, "records", lambda buf, offs, *a: (calls.append(len(offs)), real(buf, offs, *a))[1])
    data = _sample_file()
    validate(data)
    assert calls == []
    from cbf import validation

    monkeypatch.setattr(validation, "VECTOR_MIN_RECORDS", 1)
    validate(data)
    assert calls and calls[0] > 0
