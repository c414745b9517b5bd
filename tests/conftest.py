"""Shared helpers: the repository, a spec copy with an extra command, generation."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
import yaml
from hypothesis import HealthCheck, settings

# Hypothesis never decides whether a submission lands (issue 13, item 17). `make test`
# loads the derandomised "ci" profile: a fixed seed per test and no example database,
# so the same commit draws the same examples every time. Random exploration is
# `make test-long` (HYPOTHESIS_PROFILE=long); what it finds becomes an @example.
_HEALTH = [HealthCheck.too_slow, HealthCheck.data_too_large, HealthCheck.filter_too_much]
settings.register_profile("ci", derandomize=True, database=None, deadline=None, print_blob=True,
                          max_examples=200, suppress_health_check=_HEALTH)
settings.register_profile("long", derandomize=False, database=None, deadline=None, print_blob=True,
                          max_examples=5000, suppress_health_check=_HEALTH)
HYPOTHESIS_PROFILE = os.environ.get("HYPOTHESIS_PROFILE", "ci")
settings.load_profile(HYPOTHESIS_PROFILE)

REPO = Path(__file__).resolve().parents[1]
SPEC = REPO / "spec" / "cbf.yaml"


def spec_with_fixture_command(tmp: Path) -> Path:
    """spec/cbf.yaml plus tests/fixtures/dwell_command.yaml, written to tmp."""
    spec = yaml.safe_load(SPEC.read_text(encoding="utf-8"))
    extra = yaml.safe_load((REPO / "tests" / "fixtures" / "dwell_command.yaml").read_text(encoding="utf-8"))
    spec["units"].update(extra["units"])
    spec["commands"].append(extra["command"])
    for check in spec["checks"]:
        if str(check["id"]) in extra.get("covered_by", []):
            check["commands"].append(extra["command"]["name"])
    path = tmp / "cbf.yaml"
    path.write_text(yaml.safe_dump(spec, sort_keys=False), encoding="utf-8")
    return path


def generate(spec: Path, out: Path, *only: str) -> None:
    cmd = [sys.executable, "-m", "cbfgen", "--spec", str(spec), "--out", str(out)]
    for o in only:
        cmd += ["--only", o]
    subprocess.run(cmd, cwd=REPO, check=True, capture_output=True)


@pytest.fixture
def repo() -> Path:
    return REPO
