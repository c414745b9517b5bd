"""Shared helpers: the repository, a spec copy with an extra command, generation."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
import yaml

REPO = Path(__file__).resolve().parents[1]
SPEC = REPO / "spec" / "cbf.yaml"


def spec_with_fixture_command(tmp: Path) -> Path:
    """spec/cbf.yaml plus tests/fixtures/dwell_command.yaml, written to tmp."""
    spec = yaml.safe_load(SPEC.read_text(encoding="utf-8"))
    extra = yaml.safe_load((REPO / "tests" / "fixtures" / "dwell_command.yaml").read_text(encoding="utf-8"))
    spec["units"].update(extra["units"])
    spec["commands"].append(extra["command"])
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
