"""A check kind that bounds values says what it accepts in the registry (registry.Accepts), and the
valid-file generator (cbf.testing) draws within it without naming the kind: a new value-bounding
kind is then the registry, its two kernels, its wording and a golden case, nothing in testing.py."""

from __future__ import annotations

from dataclasses import asdict

from conftest import REPO

from cbf import tables as T
from cbf import testing
from cbfgen.loader import load
from cbfgen.registry import CHECK_KINDS


def test_every_check_carries_what_its_kind_accepts() -> None:
    spec = load(REPO / "spec" / "cbf.yaml")
    got = {c["id"]: c["accepts"] for c in T.CHECKS}
    for c in spec.checks:
        acc = CHECK_KINDS[c.kind].accepted(c)
        assert got[c.id] == (None if acc is None else asdict(acc)), c.id


def test_the_generator_draws_within_every_bound_a_check_accepts() -> None:
    rules = testing._rules()
    bounded = [c for c in T.CHECKS if c["accepts"] is not None]
    assert bounded, "the spec has no value-bounding check: nothing to test"
    for c in bounded:
        acc = c["accepts"]
        for t in c["targets"]:
            for arg in t["args"]:
                lim = rules.limits[(t["command"], arg)]
                if acc["min"] is not None:
                    assert lim.lo is not None and lim.lo >= acc["min"], (c["id"], arg)
                    if acc["min_open"] and lim.lo == acc["min"]:
                        assert lim.lo_open, (c["id"], arg)
                if acc["max"] is not None:
                    assert lim.hi is not None and lim.hi <= acc["max"], (c["id"], arg)
                if acc["nonzero"]:
                    assert lim.nonzero, (c["id"], arg)
