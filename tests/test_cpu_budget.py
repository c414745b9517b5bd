"""The suite's CPU budget (tests/cpu_budget.py): the reports add up per file, an excess is named, and
`make test` checks it after pytest."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import cpu_budget
from conftest import REPO


def _report(folder: Path, worker: str, files: dict[str, float]) -> None:
    folder.mkdir(exist_ok=True)
    tests = {f"{name}::test_x": cpu for name, cpu in files.items()}
    (folder / f"{worker}.json").write_text(json.dumps({"tests": tests, "files": files}), encoding="utf-8")


def test_the_workers_reports_add_up_and_an_excess_is_named(tmp_path: Path) -> None:
    small = cpu_budget.FILE_BUDGET / 4
    _report(tmp_path / "r", "gw0", {"tests/test_a.py": small, "tests/test_b.py": small})
    _report(tmp_path / "r", "gw1", {"tests/test_a.py": small})
    files, tests = cpu_budget.read(tmp_path / "r")
    assert files == {"tests/test_a.py": 2 * small, "tests/test_b.py": small}
    assert sum(tests.values()) == 3 * small
    assert cpu_budget.problems(files) == []
    over = {"tests/test_a.py": cpu_budget.FILE_BUDGET + 1}
    assert [p.split(" took")[0] for p in cpu_budget.problems(over)] == ["tests/test_a.py"]
    many = {f"tests/test_{i}.py": cpu_budget.FILE_BUDGET for i in range(int(cpu_budget.SUITE_BUDGET
                                                                            // cpu_budget.FILE_BUDGET) + 1)}
    assert cpu_budget.problems(many)[0].startswith("the test suite took")
    _report(tmp_path / "r", "gw2", over)
    res = subprocess.run([sys.executable, str(REPO / "tests" / "cpu_budget.py"), "check", str(tmp_path / "r")],
                         capture_output=True, text=True)
    assert res.returncode == 1 and "tests/test_a.py took" in res.stderr, res.stderr
    assert all(b > 0 for b in cpu_budget.FILE_BUDGETS.values())


def test_make_test_checks_the_budget_after_pytest() -> None:
    res = subprocess.run(["make", "-n", "-s", "test-py"], cwd=REPO, capture_output=True, text=True)
    lines = res.stdout.splitlines()
    run = next(i for i, line in enumerate(lines) if "-m pytest" in line)
    assert "CBF_CPU_REPORT=" in lines[run]
    assert any("cpu_budget.py check" in line for line in lines[run + 1:]), res.stdout
