"""The loader gates of issue 36, point 1, beyond their bad specs (tests/bad_specs/): the layout-size
check never builds a repeated group's sizes, and answers as building them would."""

from __future__ import annotations

import random

from cbfgen.loader.passes.commands import Span, sizes_meet


def _built(s: Span) -> set[int]:
    start, step, lo, hi = s
    return {start + step * n for n in range(lo, hi + 1)}


def test_two_layouts_share_a_size_exactly_when_their_built_sizes_do() -> None:
    rng = random.Random(36)
    shared = 0
    for _ in range(5000):
        a, b = ((rng.randint(0, 40), rng.randint(1, 9), rng.randint(0, 6), rng.randint(0, 12)) for _ in range(2))
        want = bool(_built(a) & _built(b))
        shared += want
        assert sizes_meet(a, b) == want == sizes_meet(b, a), (a, b)
    assert 500 < shared < 4500, shared  # the sample holds both answers


def test_a_group_of_a_billion_sizes_is_answered_without_building_it() -> None:
    group = (0, 12, 1, 10 ** 9)
    assert sizes_meet(group, (12 * 777_777_777, 1, 0, 0))
    assert not sizes_meet(group, (12 * 777_777_777 + 5, 1, 0, 0))
    assert not sizes_meet(group, (12 * (10 ** 9 + 1), 1, 0, 0))
    assert not sizes_meet(group, (6, 8, 0, 10 ** 9))  # 6 + 8n is never a multiple of 12 (4 does not divide 6)
    assert sizes_meet(group, (4, 8, 0, 10 ** 9))  # 4 + 8 x 1 = 12 x 1
