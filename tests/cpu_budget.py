"""The suite's CPU budget: what each test file costs, in CPU seconds, and the bound `make test` holds.

`make test` must stay under ten minutes of wall time on the 2-core CI machine. Wall time on a shared
machine depends on the load, CPU time (user + sys of the pytest process and of every child it waited
for: the CLI calls, compilers, ksc, Java, Node) does not, or much less: so the budget is in CPU seconds.

The plugin (registered by conftest.py) measures each test's setup, call and teardown with getrusage
(RUSAGE_SELF + RUSAGE_CHILDREN; a module fixture's cost goes to the first test of the file that asks
for it) and, when CBF_CPU_REPORT names a folder, writes one JSON file per pytest process (one per
xdist worker) there: {"tests": {nodeid: cpu_s}, "files": {path: cpu_s}}.

    python tests/cpu_budget.py check FOLDER   sum the processes' reports; exit 1 when the suite or a
                                              file is over its bound in BUDGET (below), a line each
    python tests/cpu_budget.py show FOLDER    the files and tests, costliest first

`make test` runs pytest with CBF_CPU_REPORT=build/test-results/cpu and then `check` (Makefile,
test-py). The bounds have room for a slower machine and a loaded one (CPU time still grows by
about a fifth under load: caches and frequency), not for a new minute: a file that needs more
either becomes cheaper or raises its bound here with the reason in tests/README-speed.md.
"""

from __future__ import annotations

import json
import os
import resource
import sys
from collections.abc import Generator
from pathlib import Path
from typing import Any

import pytest

# The whole pytest run, summed over the workers (CPU s). Measured in tests/README-speed.md: the bounds
# hold today's suite with room for a loaded machine (CPU s grow by up to half at load 15 on the 2-core
# machine), and stop a new minute. Lower them when a file gets cheaper (tests/README-speed.md, "Budget").
SUITE_BUDGET = 1300.0  # round 5: about 1,000 on the last CI run, less about 100, less 50 (README-speed.md)
# Any one test file (CPU s): the longest file runs on one worker (--dist loadfile), so its cost bounds
# the wall time of pytest from below on any number of cores. Files named here have their own bound, each
# the file's cost on the last fresh-clone CI run (durations.txt: wall s of its tests) plus the same room.
FILE_BUDGET = 90.0
FILE_BUDGETS: dict[str, float] = {
    "tests/test_spec_fuzz.py": 170.0,  # 111 s: the derandomised sample generates and builds each spec
    "tests/test_registry.py": 90.0,  # 67 CPU s on CI; 23.7 -> 19.2 idle with one ksc process (round 5)
    "tests/test_revision_drill.py": 75.0,  # 92 s wall on CI; 42.7 -> 31.4 at load 2.5 (round 5, second pass)
    "tests/test_engine_scaling.py": 25.0,  # 60 s wall on CI, 48.7 of it collections: 19.5 -> 4.6 after others here
    "tests/test_repeat_groups.py": 40.0,  # 35 s wall on CI; 11.0 -> 6.8 idle, the testee at -O0 (round 5, second pass)
    "tests/test_outputs_checked.py": 115.0,  # 75 s: every command on the 65,535-record file, to a full disk
    "tests/test_near_miss.py": 60.0,  # 78 CPU s on CI; 31.7 -> 14.6 idle: in-process cbfgen, one ksc (round 5)
    "tests/test_escaping.py": 100.0,  # 66 s: ksc on 13 hostile specs, Java and Go compiled once
}


ENV = "CBF_CPU_REPORT"
REPO = Path(__file__).resolve().parents[1]


def _cpu() -> float:
    me, kids = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return me.ru_utime + me.ru_stime + kids.ru_utime + kids.ru_stime


class CpuPlugin:
    """Collects each test's CPU seconds (setup + call + teardown, children included)."""

    def __init__(self, folder: Path) -> None:
        self.folder = folder
        self.tests: dict[str, float] = {}

    @pytest.hookimpl(hookwrapper=True)
    def pytest_runtest_protocol(self, item: pytest.Item) -> Generator[None, None, None]:
        # A pytest a test starts (its CPU is this test's, as a child) writes no report of its own. Dropped
        # here, in the process that runs tests, not at configure time: xdist's workers inherit it later.
        os.environ.pop(ENV, None)
        t = _cpu()
        yield
        self.tests[item.nodeid] = self.tests.get(item.nodeid, 0.0) + _cpu() - t

    def pytest_sessionfinish(self, session: pytest.Session) -> None:
        if not self.tests:
            return
        files: dict[str, float] = {}
        for nodeid, cpu in self.tests.items():
            name = nodeid.split("::", 1)[0]
            files[name] = files.get(name, 0.0) + cpu
        worker = os.environ.get("PYTEST_XDIST_WORKER", "main")
        self.folder.mkdir(parents=True, exist_ok=True)
        out = self.folder / f"{worker}.json"
        tmp = out.with_suffix(".tmp")
        tmp.write_text(json.dumps({"tests": self.tests, "files": files}, indent=1, sort_keys=True), encoding="utf-8")
        tmp.replace(out)


def register(config: pytest.Config) -> None:
    """Register the plugin when CBF_CPU_REPORT names a folder and pytest runs this checkout's suite (not a
    copy of the tree a test or the revision drill runs: conftest.py's pytest_configure)."""
    folder = os.environ.get(ENV)
    if folder and config.rootpath.resolve() == REPO:
        config.pluginmanager.register(CpuPlugin(Path(folder)), "cbf_cpu_budget")


def read(folder: Path) -> tuple[dict[str, float], dict[str, float]]:
    """The per-file and per-test CPU seconds of every report in folder, summed."""
    files: dict[str, float] = {}
    tests: dict[str, float] = {}
    for path in sorted(folder.glob("*.json")):
        doc: dict[str, Any] = json.loads(path.read_text(encoding="utf-8"))
        for name, cpu in doc["files"].items():
            files[name] = files.get(name, 0.0) + float(cpu)
        for name, cpu in doc["tests"].items():
            tests[name] = tests.get(name, 0.0) + float(cpu)
    return files, tests


def problems(files: dict[str, float]) -> list[str]:
    """What is over its bound: the suite, then each file."""
    out = []
    total = sum(files.values())
    if total > SUITE_BUDGET:
        out.append(f"the test suite took {total:.0f} CPU s, over its budget of {SUITE_BUDGET:.0f}")
    for name, cpu in sorted(files.items(), key=lambda kv: -kv[1]):
        bound = FILE_BUDGETS.get(name, FILE_BUDGET)
        if cpu > bound:
            out.append(f"{name} took {cpu:.0f} CPU s, over its budget of {bound:.0f}")
    return out


def main(argv: list[str]) -> int:
    if len(argv) != 2 or argv[0] not in ("check", "show"):
        print("usage: cpu_budget.py check|show FOLDER", file=sys.stderr)
        return 2
    folder = Path(argv[1])
    files, tests = read(folder)
    if not files:
        print(f"cpu_budget: no report in {folder} (pytest ran without CBF_CPU_REPORT?)", file=sys.stderr)
        return 2
    total = sum(files.values())
    if argv[0] == "show":
        print(f"{total:8.1f}  the whole suite ({len(files)} files, {len(tests)} tests)")
        for name, cpu in sorted(files.items(), key=lambda kv: -kv[1]):
            print(f"{cpu:8.1f}  {name}")
        print()
        for name, cpu in sorted(tests.items(), key=lambda kv: -kv[1])[:40]:
            print(f"{cpu:8.1f}  {name}")
        return 0
    bad = problems(files)
    for line in bad:
        print(f"cpu budget: {line} (tests/cpu_budget.py; `python tests/cpu_budget.py show {folder}`)",
              file=sys.stderr)
    if not bad:
        top = max(files.items(), key=lambda kv: kv[1])
        print(f"cpu budget: the test suite took {total:.0f} CPU s (budget {SUITE_BUDGET:.0f}); "
              f"the costliest file {top[0]} {top[1]:.0f} CPU s")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
