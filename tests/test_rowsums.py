"""The vectorised checksums (cbf.rowsums, issue 32) equal the one-record-at-a-time algorithms of
cbf.checksums on every kind, every row width a layout may have, every field width; and every kind
checksums.py implements has a kernel there (else validate would fall back to a Python call a record)."""

from __future__ import annotations

import numpy as np
import pytest

from cbf import checksums, rowsums
from cbf import tables as T

WIDTHS = (0, 1, 2, 3, 4, 7, 8, 9, 31, 56, 255)  # row widths: empty, odd, a word, a SWAR step, the largest nb


def test_every_kind_has_a_kernel() -> None:
    missing = set(checksums.KINDS) - set(rowsums.KINDS)
    assert not missing, f"no vectorised kernel in cbf/rowsums.py for {sorted(missing)}: validate would compute " \
                        f"them one record at a time"
    assert {str(k) for k in T.CHECKSUMS["algorithms"].values()} <= set(rowsums.KINDS)


@pytest.mark.parametrize("kind", sorted(checksums.KINDS))
@pytest.mark.parametrize("width", WIDTHS)
def test_rows_equal_the_scalar_algorithm(kind: str, width: int) -> None:
    rng = np.random.default_rng(width * 7919 + len(kind))
    rows = rng.integers(0, 256, size=(40, width), dtype=np.uint8)
    rows[0] = 0xFF  # the sums' carries and the moduli's edge (255, 65535)
    rows[1] = 0
    for field in (1, 2, 4):
        if checksums.KINDS[kind] is not checksums.byte_sum and field < {"crc16_ccitt": 2, "fletcher16": 2}.get(kind, 4):
            continue  # the loader refuses an algorithm wider than its field
        got = rowsums.row_checksums(kind, rows, field).tolist()
        want = [checksums.compute(kind, [bytes(r)], field) for r in rows]
        assert got == want, (kind, width, field)


def test_rows_of_a_strided_view_and_of_no_record() -> None:
    rng = np.random.default_rng(3)
    wide = rng.integers(0, 256, size=(50, 40), dtype=np.uint8)
    cols = np.r_[3:9, 20:23]  # named fields: byte ranges of a record, in order
    for kind in checksums.KINDS:
        got = rowsums.row_checksums(kind, wide[:, cols], 4).tolist()
        assert got == [checksums.compute(kind, [bytes(r[3:9]), bytes(r[20:23])], 4) for r in wide]
        assert rowsums.row_checksums(kind, wide[:0], 4).shape == (0,)
