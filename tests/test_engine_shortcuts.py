"""The record engine's shortcuts change no finding (issue 17, second performance round).

records.py skips work where a quick test shows there is nothing to find: the batch kernels of
a layout are planned once (``Kernel.applies``: a kernel is not called on a layout it has
nothing in), and a string column that is printable ASCII then NULs only, tested as a whole, is
not looked at row by row, nor a layout's binary32 floats whose exponent bits, tested as one flat
run, show them all finite, nor a header string field that is plain, nor the finite, positive,
range and machine_limits kernels of a layout whose floats all lie within the tightest of their
bounds (``_within``, round 6). Here the same files are validated with the shortcuts and without
them (every batch kernel on every layout, every string column row by row, every float field by
field, every header string by the kernels), and the row gather and the argument byte sums are
compared with plain Python. These are the engine's own
private helpers, so the test reaches into records.py on purpose.
"""

from __future__ import annotations

import random
from typing import Any

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import cbf
from cbf import records, rowsums, testing
from cbf import tables as T

CUTTERS = {"C1": (100.0, 3.0), "C2": (50.0, 1.5)}


def _all_kernels(with_cutters: bool, lay: Any) -> tuple[Any, ...]:
    return tuple((c, k.batch) for c, k in records._active(with_cutters) if k.batch is not None)


def _both(data: bytes, **opts: Any) -> tuple[list[cbf.Finding], list[cbf.Finding]]:
    fast = cbf.validate(data, **opts)
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(records, "_plan", _all_kernels)
        mp.setattr(records, "_plain_strings", lambda b, name: False)
        mp.setattr(records, "_all_finite32", lambda b: False)
        mp.setattr(records, "_plain_bytes", lambda raw: False)
        mp.setattr(records, "_within", lambda b, q: False)
        slow = cbf.validate(data, **opts)
    return fast, slow


@given(st.sampled_from(sorted(T.PROFILES)), st.booleans(), st.data())
def test_shortcuts_change_no_finding(profile: str, cutters: bool, data: st.DataObject) -> None:
    raw = data.draw(testing.mutations(testing.cutfiles(profile=profile, max_records=40), profile=profile,
                                      max_steps=4))
    fast, slow = _both(raw, profile=profile, cutters=CUTTERS if cutters else None)
    assert fast == slow


def _damage(data: bytes, n: int, rng: random.Random) -> bytes:
    """``n`` arguments of random records set to values the argument checks flag (or not):
    floats to specials and out-of-range values, strings to bytes of every kind, uints anyhow;
    the checksums sealed again."""
    model = cbf.decode(data)
    starts, at = [], T.HEADER_SIZE
    for rec in model.records:
        starts.append(at + T.HEAD_SIZE)
        at += T.HEAD_SIZE + len(rec.raw_args)
    b = bytearray(data)
    floats = (0.0, -0.0, -1.0, 1.0, 1e-3, 150.0, -1e30, 1e30, float("inf"), float("nan"))
    for _ in range(n):
        k = rng.randrange(len(starts))
        lay = model.records[k].layout(model.version_id)
        if lay is None or not lay.args:
            continue
        f = rng.choice(lay.args)
        if f.kind == "float":
            pos = starts[k] + f.offset + 4 * rng.randrange(f.count)
            b[pos:pos + 4] = np.array(rng.choice(floats), dtype=f"{T.BO}f4").tobytes()
        else:
            b[starts[k] + f.offset + rng.randrange(f.size)] = rng.choice(
                (0, 0x20, 0x41, 0x7E, 0x7F, 0x80, 0xFF, rng.randrange(256)))
    return testing.reseal_checksums(bytes(b))


def test_shortcuts_change_no_finding_on_a_large_damaged_file() -> None:
    """Every command of the newest version, over and over (the benchmark's file), with bad
    arguments in many records, so that every argument check finds something somewhere."""
    from bench.bench import _every_command_file

    rng = random.Random(17)
    base = _every_command_file(4000)
    for n in (30, 3000):
        damaged = _damage(base, n, rng)
        fast, slow = _both(damaged)
        assert fast == slow
        assert len(fast) > n // 4  # the damage is seen (the comparison is not of two empty lists)
        if n > 1000:
            kinds = {T.CHECKS[[c["id"] for c in T.CHECKS].index(f.check)]["kind"] for f in fast}
            assert {"finite", "string_tail", "string_ascii", "range", "positive"} <= kinds, kinds


def test_gather_and_row_sums_are_exact() -> None:
    size_field = next(f for f in T.RECORD_FIELDS if f.role == "arg_size")
    widest = (1 << (8 * size_field.size)) - 1  # the largest argument block a record can hold
    rng = np.random.default_rng(17)
    a = rng.integers(0, 256, 4 * widest + 100, dtype=np.uint8)
    a[: 2 * widest] = 255  # the largest sums
    for width in sorted({1, 3, 8, 48, widest}):
        starts = np.sort(rng.integers(0, len(a) - width + 1, 300))
        starts[0], starts[-1] = 0, len(a) - width
        rows = records._gather(a, starts, width)
        assert rows.tolist() == [a[s:s + width].tolist() for s in starts.tolist()]
        assert rowsums.row_checksums("sum", rows, 8).tolist() == [int(a[s:s + width].sum()) for s in starts.tolist()]
        sums32 = rowsums.exact_sums32(rows)  # binary32 sums (what the argument checksums store where they fit)
        assert sums32 is not None and sums32.tolist() == [int(a[s:s + width].sum()) for s in starts.tolist()]
    assert records._gather(a, np.zeros(0, dtype=np.int64), 8).shape == (0, 8)
