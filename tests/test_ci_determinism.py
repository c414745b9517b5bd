"""CI is deterministic (issue 13, item 17): `make test` draws the same hypothesis
examples on every run, and random exploration lives in `make test-long`."""

from __future__ import annotations

import os
import re
from pathlib import Path

import pytest
from hypothesis import settings

REPO = Path(__file__).resolve().parents[1]


@pytest.mark.skipif(os.environ.get("HYPOTHESIS_PROFILE", "ci") != "ci", reason="make test-long explores at random")
def test_the_default_profile_is_derandomised_without_a_database() -> None:
    assert settings.default.derandomize is True
    assert settings.default.database is None


def test_no_test_file_opts_back_into_randomness() -> None:
    exempt = ("conftest.py", Path(__file__).name)
    for path in sorted((REPO / "tests").glob("*.py")):
        if path.name in exempt:
            continue
        text = path.read_text(encoding="utf-8")
        assert not re.search(r"derandomize\s*=\s*False", text), path.name
        assert "load_profile(" not in text, path.name


def test_random_exploration_has_its_own_target() -> None:
    mk = (REPO / "mk" / "reliability.mk").read_text(encoding="utf-8")
    assert re.search(r"^test-long:", mk, re.M)
    assert "HYPOTHESIS_PROFILE=long" in mk
    assert re.search(r"^reliability:.*\btest-long\b", mk, re.M)
