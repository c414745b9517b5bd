"""The conformance kit for anyone (issue 14): cbf-conformance, installed from its wheel into
a clean venv outside this repository, judges an outside testee, passes the reference C
testee, fails a broken one naming exactly the cases it breaks, and never hangs on a
testee that stops answering."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from conftest import clean_venv, load_yaml

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"
C_TESTEE = REPO / "build" / "c" / "cbf_testee"
PY_TESTEE = REPO / "conformance" / "testees" / "python" / "testee.py"
CLEAN_ENV = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}

# A testee that answers validate with no findings: every case expecting one must fail.
NO_FINDINGS = """
import json, sys
for line in sys.stdin:
    req = json.loads(line)
    if req.get("op") == "quit":
        break
    print(json.dumps({"ok": True, "findings": []} if req.get("op") == "validate" else {"skipped": True}), flush=True)
"""
# A testee that never answers.
SILENT = "import sys, time\nfor line in sys.stdin:\n    time.sleep(3600)\n"


def _run(*cmd: str | Path, cwd: Path, check: bool = True) -> subprocess.CompletedProcess[str]:
    return subprocess.run([str(c) for c in cmd], cwd=cwd, capture_output=True, text=True, check=check, env=CLEAN_ENV)


@pytest.fixture(scope="module")
def kit(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The cbf-conformance command of a clean venv that installed the kit's wheel."""
    work = tmp_path_factory.mktemp("kit")
    _run(sys.executable, "-m", "conformance.kit", work / "stage", cwd=REPO)
    _run(sys.executable, "-m", "build", "--no-isolation", "--wheel", "--outdir", work / "dist", work / "stage",
         cwd=work)
    return clean_venv(work / "venv", next((work / "dist").glob("cbf_conformance-*.whl"))) / "cbf-conformance"


def _expected_validate_failures() -> set[str]:
    out = set()
    for exp in GOLDEN.glob("*.expect.yaml"):
        want = load_yaml(exp).get("validate") or {}
        if any(want.values()):
            out.add(exp.name[: -len(".expect.yaml")])
    return out


@pytest.mark.skipif(not C_TESTEE.exists(), reason="make c-build first")
def test_the_kit_passes_the_reference_c_testee(kit: Path, tmp_path: Path) -> None:
    res = _run(kit, "--testee", C_TESTEE, "--name", "c", "--failure-list", REPO / "conformance" / "failures" / "c.txt",
               "--junit", tmp_path / "j.xml", "--json", cwd=tmp_path, check=False)
    assert res.returncode == 0, res.stderr[-2000:]
    report = json.loads(res.stdout)
    cases = {p.name[: -len(".expect.yaml")] for p in GOLDEN.glob("*.expect.yaml")}
    assert set(report["bindings"]["c"]["results"]) == cases  # the shipped cases are all the cases
    suite = ET.parse(tmp_path / "j.xml").getroot().find("testsuite")
    assert suite is not None and suite.get("tests") == str(len(cases))


def test_the_kit_fails_a_broken_testee_with_the_right_cases(kit: Path, tmp_path: Path) -> None:
    (tmp_path / "broken.py").write_text(NO_FINDINGS, encoding="utf-8")
    res = _run(kit, "--testee", f"{sys.executable} broken.py", "--name", "broken", "--junit", tmp_path / "j.xml",
               cwd=tmp_path, check=False)
    assert res.returncode == 1
    failed = {line.split(": ")[1] for line in res.stdout.splitlines() if line.startswith("broken: ")}
    assert failed == _expected_validate_failures()
    junit_failed = {tc.get("name") for tc in ET.parse(tmp_path / "j.xml").getroot().iter("testcase")
                    if tc.find("failure") is not None}
    assert junit_failed == failed


def test_a_silent_testee_times_out_instead_of_hanging(kit: Path, tmp_path: Path) -> None:
    (tmp_path / "silent.py").write_text(SILENT, encoding="utf-8")
    first = sorted(GOLDEN.glob("*.expect.yaml"))[0].name[: -len(".expect.yaml")]
    res = _run(kit, "--testee", f"{sys.executable} silent.py", "--case", first, "--timeout", "1",
               cwd=tmp_path, check=False)
    assert res.returncode == 1
    assert f"{first}: FAIL" in res.stdout and "gave no answer within 1 s" in res.stdout


def test_usage_errors_exit_2(kit: Path, tmp_path: Path) -> None:
    res = _run(kit, cwd=tmp_path, check=False)  # outside the repository, no --testee
    assert res.returncode == 2 and "--testee" in res.stderr
