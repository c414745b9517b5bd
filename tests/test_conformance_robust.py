"""A runner that survives its testee (issue 27 item 5), each behaviour against a hostile testee:
a tiny Python script that answers through the real codec (cbf, from generated/python) but
misbehaves once in a chosen way."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from conformance.runner import testee as runner_testee

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"
ENV = dict(os.environ, PYTHONPATH=f"{REPO / 'generated' / 'python'}:{REPO}")
CASES = "check.6.4"  # a handful of small cases that the real codec passes

# The real codec's answers (the Python testee), then a hook that may misbehave; `n` counts requests.
HEAD = f"""
import json, os, sys, time
sys.path.insert(0, {str(REPO / 'conformance' / 'testees' / 'python')!r})
from testee import handle
n = 0
for line in sys.stdin:
    req = json.loads(line)
    if req.get("op") == "quit":
        break
    n += 1
    answer = handle(req)
"""
ANSWER = "    print(json.dumps(answer), flush=True)\n"


def _running(pid: int) -> bool:
    """Whether a process runs (a zombie, killed but not reaped by its parent, does not)."""
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except FileNotFoundError:
        return False
    return stat.rsplit(")", 1)[1].split()[0] != "Z"


def _once(tmp: Path, code: str) -> str:
    """A hook that misbehaves in the first testee process only (a restarted one behaves)."""
    marker = tmp / "misbehaved"
    body = "".join(f"        {ln}\n" for ln in code.splitlines())
    return f"    if {CONDITION} and not os.path.exists({str(marker)!r}):\n" \
           f"        open({str(marker)!r}, 'w').close()\n{body}"


CONDITION = "True"


def _script(tmp: Path, hook: str) -> Path:
    p = tmp / "hostile.py"
    p.write_text(HEAD + hook + ANSWER, encoding="utf-8")
    return p


def _runner(tmp: Path, testee: str, *extra: str, timeout: float = 120) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "conformance.runner", "--testee", testee, "--case", CASES, "--json",
                           *extra], cwd=tmp, env=ENV, capture_output=True, text=True, timeout=timeout)


def _results(res: subprocess.CompletedProcess[str]) -> dict[str, dict[str, str]]:
    assert "Traceback" not in res.stderr, res.stderr[-3000:]
    out: dict[str, dict[str, str]] = json.loads(res.stdout)["bindings"]["testee"]["results"]
    return out


def _names() -> list[str]:
    return sorted(p.name[: -len(".expect.yaml")] for p in GOLDEN.glob(f"{CASES}*.expect.yaml"))


def test_the_well_behaved_script_passes(tmp_path: Path) -> None:
    res = _runner(tmp_path, f"{sys.executable} {_script(tmp_path, '')}")
    assert res.returncode == 0 and {r["status"] for r in _results(res).values()} == {"pass"}


def test_a_surplus_answer_fails_only_its_own_case(tmp_path: Path) -> None:
    # request 3 is answered twice: without the sync drain every later answer would shift by one
    hook = _once(tmp_path, "print(json.dumps(answer), flush=True)").replace(CONDITION, "n == 3")
    res = _runner(tmp_path, f"{sys.executable} {_script(tmp_path, hook)}")
    results = _results(res)
    failed = [n for n, r in results.items() if r["status"] == "fail"]
    assert len(failed) == 1 and "surplus answer" in results[failed[0]]["message"], results
    assert res.returncode == 1


def test_a_stray_answer_id_fails_its_case_only(tmp_path: Path) -> None:
    hook = _once(tmp_path, "answer['id'] = req['id'] + 1").replace(CONDITION, "n == 2")
    results = _results(_runner(tmp_path, f"{sys.executable} {_script(tmp_path, hook)}"))
    failed = [r["message"] for r in results.values() if r["status"] == "fail"]
    assert len(failed) == 1 and "a stray or surplus answer" in failed[0], results


def test_a_timeout_does_not_leak_into_the_next_case(tmp_path: Path) -> None:
    # the first testee process hangs on its first request; its successor behaves
    marker = tmp_path / "hung-once"
    hook = (f"    if not os.path.exists({str(marker)!r}):\n        open({str(marker)!r}, 'w').close()\n"
            "        time.sleep(3600)\n")
    results = _results(_runner(tmp_path, f"{sys.executable} {_script(tmp_path, hook)}", "--timeout", "2"))
    names = _names()
    assert results[names[0]]["status"] == "fail" and "no answer within 2 s" in results[names[0]]["message"]
    assert all(results[n]["status"] == "pass" for n in names[1:]), results


def test_the_whole_process_group_dies_on_timeout_and_at_exit(tmp_path: Path) -> None:
    # a wrapper shell script starts the testee, which starts a grandchild that would outlive it
    pids = tmp_path / "pids"
    child = tmp_path / "child.py"
    child.write_text(f"import os, time\nopen({str(pids)!r}, 'a').write(f'{{os.getpid()}}\\n')\ntime.sleep(3600)\n")
    hook = (f"    if n == 1:\n        import subprocess\n        subprocess.Popen([sys.executable, {str(child)!r}])\n"
            "        time.sleep(0.5)\n        time.sleep(3600)\n")
    script = _script(tmp_path, hook)
    wrapper = tmp_path / "wrapper.sh"
    wrapper.write_text(f"#!/bin/sh\n{sys.executable} {script}\n", encoding="utf-8")
    wrapper.chmod(0o755)
    _runner(tmp_path, str(wrapper), "--timeout", "2")
    started = [int(p) for p in pids.read_text().split()]
    assert started
    time.sleep(0.2)
    assert not any(_running(pid) for pid in started)  # each grandchild was killed with its group


def test_an_endless_answer_line_is_bounded(tmp_path: Path) -> None:
    hook = _once(tmp_path, "while True:\n    sys.stdout.write('x' * 65536)")
    binding = runner_testee.Binding("t", [sys.executable, str(_script(tmp_path, hook))], cwd=tmp_path,
                                    env={"PYTHONPATH": ENV["PYTHONPATH"]})
    t = runner_testee.Testee(binding, timeout=60, max_answer=1 << 20)
    try:
        with pytest.raises(runner_testee.TesteeError, match="longer than 1048576 bytes"):
            t.ask({"op": "decode", "file": str(next(GOLDEN.glob("*.cbf")))})
        assert t.proc is None  # killed
        assert t.ask({"op": "nothing"}) == {"skipped": True}  # a new process answers
    finally:
        t.stop()


def test_consecutive_timeouts_stop_the_run_with_one_message(tmp_path: Path) -> None:
    hook = "    time.sleep(3600)\n"
    # three 1 s timeouts, then the rest not run: well inside 30 s, else subprocess's timeout fails the test
    res = _runner(tmp_path, f"{sys.executable} {_script(tmp_path, hook)}", "--timeout", "1", timeout=30)
    results = _results(res)
    assert res.returncode == 1
    timed_out = [r for r in results.values() if "no answer within" in r["message"]]
    not_run = [r for r in results.values() if r["message"].startswith("not run:")]
    assert len(timed_out) == 3 and len(not_run) == len(results) - 3
    assert res.stderr.count("stopped after 3 timeouts in a row") == 1


def test_the_overall_deadline(tmp_path: Path) -> None:
    hook = "    time.sleep(0.6)\n"
    res = _runner(tmp_path, f"{sys.executable} {_script(tmp_path, hook)}", "--deadline", "1.5")
    results = _results(res)
    assert res.returncode == 1
    assert any(r["message"] == "not run: the run's deadline passed" for r in results.values())
    assert "deadline passed" in res.stderr


def test_sigterm_kills_the_testee(tmp_path: Path) -> None:
    pids = tmp_path / "pid"
    hook = f"    open({str(pids)!r}, 'w').write(str(os.getpid()))\n    time.sleep(3600)\n"
    proc = subprocess.Popen([sys.executable, "-m", "conformance.runner", "--testee",
                             f"{sys.executable} {_script(tmp_path, hook)}", "--case", CASES], cwd=tmp_path, env=ENV,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    for _ in range(200):
        if pids.exists() and pids.read_text():
            break
        time.sleep(0.05)
    proc.send_signal(signal.SIGTERM)
    assert proc.wait(timeout=20) == 128 + signal.SIGTERM
    time.sleep(0.2)
    assert not _running(int(pids.read_text()))


def test_each_reader_thread_feeds_only_its_own_testee(tmp_path: Path) -> None:
    """A killed testee's reader thread keeps its own queue: its end of output (or a late line)
    never reaches its successor's queue, whatever the timing."""
    slow_eof = tmp_path / "late.py"
    # answers, then keeps its stdout open a moment in a child (the old pipe's end comes late)
    slow_eof.write_text("import json, subprocess, sys\nfor line in sys.stdin:\n"
                        "    req = json.loads(line)\n"
                        "    subprocess.Popen([sys.executable, '-c', 'import time; time.sleep(1.5)'])\n"
                        "    print(json.dumps({'skipped': True, 'late': True}), flush=True)\n", encoding="utf-8")
    t = runner_testee.Testee(runner_testee.Binding("t", [sys.executable, str(slow_eof)], cwd=tmp_path), timeout=30)
    try:
        assert t.ask({"op": "x"}) == {"skipped": True, "late": True}
        first = t.lines
        t.kill()
        t.start()
        assert t.lines is not first
        for _ in range(3):  # the old thread's end of output arrives while the new testee answers
            assert t.ask({"op": "x"}) == {"skipped": True, "late": True}
            time.sleep(0.6)
    finally:
        t.stop()
