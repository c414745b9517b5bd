"""Every check of the spec has a golden case that violates exactly that check."""

from __future__ import annotations

from pathlib import Path

import pytest
from conftest import load_yaml

from cbfgen.loader import load

REPO = Path(__file__).resolve().parents[1]
SPEC = load(REPO / "spec" / "cbf.yaml")
EXPECT = {p.name[: -len(".expect.yaml")]: load_yaml(p)
          for p in (REPO / "conformance" / "golden").glob("*.expect.yaml")}


@pytest.mark.parametrize("check", [c.id for c in SPEC.checks])
def test_a_case_violates_exactly_this_check(check: str) -> None:
    alone = [name for name, exp in EXPECT.items()
             if any({str(f[0]) for f in fs} == {check} for fs in (exp.get("validate") or {}).values() if fs)]
    assert alone, f"no golden case reports {check} and nothing else"
