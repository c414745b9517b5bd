"""Deprecations (issue 25, point 5): a record of a command or layout the spec deprecates in the
file's version draws the deprecation check's finding in validate (the golden cases, every binding),
and the writers (encode, convert) warn on stderr for it, their exit status unchanged.

Read from the spec: every golden case whose expectation names a deprecated check. The spec of
rev 03 deprecates nothing (the test then has no case); the revision drill's deprecation fixture
adds one, and this test runs in the drill's copy of the tree."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from conftest import ENV, load_yaml
from hypothesis import given, settings
from hypothesis import strategies as st

from cbf import tables as T
from cbf import testing, validate

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"
IDS = {c["id"] for c in T.checks_of("deprecated")}


def _cases() -> list[tuple[str, str]]:
    out = []
    for exp in sorted(GOLDEN.glob("*.expect.yaml")):
        found = load_yaml(exp).get("validate", {}).get("default", [])
        for f in found:
            if str(f[0]) in IDS:
                out.append((exp.name.removesuffix(".expect.yaml"), str(f[0])))
                break
    return out


def cbf(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "cbf", *args], env=ENV, capture_output=True, text=True)


@pytest.mark.parametrize(("case", "check"), _cases())
def test_writers_warn_for_a_deprecated_record(tmp_path: Path, case: str, check: str) -> None:
    src = GOLDEN / f"{case}.cbf"
    as_json = tmp_path / "in.json"
    res = cbf("decode", str(src), "--to", "json", "-o", str(as_json))
    assert res.returncode == 0, res.stderr
    assert check not in res.stderr  # a reader does not warn
    # under every profile the record is deprecated; implib accepts the layouts it alone writes
    res = cbf("encode", str(as_json), "--profile", "implib", "-o", str(tmp_path / "out.cbf"))
    assert res.returncode == 0, res.stderr
    assert "warning" in res.stderr and f"check {check}" in res.stderr, res.stderr
    version = next(v["id"] for v in T.SPEC["versions"] if v["major"] == src.read_bytes()[T.VMAJOR.offset])
    res = cbf("convert", str(tmp_path / "out.cbf"), "--to-version", version, "--profile", "implib", "-o",
              str(tmp_path / "conv.cbf"))
    assert res.returncode == 0, res.stderr
    assert f"check {check}" in res.stderr, res.stderr


def test_every_deprecation_has_a_golden_case() -> None:
    """A deprecation the spec adds comes with its golden case (the issue's rule for a new check)."""
    have = {check for _, check in _cases()}
    assert IDS <= have, sorted(IDS - have)


@pytest.mark.skipif(not IDS, reason="the spec deprecates nothing")
@settings(max_examples=60)
@given(st.data())
def test_the_valid_file_drawer_draws_no_deprecated_record(data: st.DataObject) -> None:
    """cbf.testing's files validate with no finding: a deprecated command or layout (a warning) is
    never drawn, in any version and profile (found when every drill fixture was applied together)."""
    profile = data.draw(st.sampled_from(sorted(T.PROFILES)))
    raw = data.draw(testing.cutfiles(profile=profile, min_records=1, max_records=30))
    assert not [f for f in validate(raw, profile=profile) if f.check in IDS]
