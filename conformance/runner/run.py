"""Run the golden cases through every binding's testee and judge the answers."""

from __future__ import annotations

import argparse
import base64
import json
import os
import queue
import shlex
import subprocess
import sys
import threading
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, TextIO

import yaml

from .compare import findings_difference, first_difference

# libyaml's parser (PyYAML's C binding) when present: the same values, about ten times faster.
_YAML_LOADER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)

ROOT = Path(__file__).resolve().parents[1]
REPO = ROOT.parent
# Installed as the cbf-conformance kit, the golden cases ship beside the runner.
PACKAGED_GOLDEN = Path(__file__).resolve().parent / "golden"
DEFAULT_GOLDEN = PACKAGED_GOLDEN if PACKAGED_GOLDEN.is_dir() else ROOT / "golden"
TIMEOUT = 60.0  # seconds a testee may take to answer one request


@dataclass
class Case:
    name: str
    cbf: Path
    expect: dict[str, Any]

    @property
    def group(self) -> str:
        """valid.v3, check.6 (check.extra beyond the spec), else the first component (truncated, framing)."""
        parts = self.name.split(".")
        if parts[0] == "check" and len(parts) > 1 and not parts[1][:1].isdigit():
            return "check.extra"
        if parts[0] in ("valid", "check"):
            return ".".join(parts[:2])
        return parts[0]


@dataclass
class Binding:
    name: str
    command: list[str]
    env: dict[str, str] = field(default_factory=dict)
    requires: list[str] = field(default_factory=list)
    cwd: Path = REPO  # an outside testee (--testee) runs where the runner was started

    def missing(self) -> list[str]:
        return [r for r in self.requires if not (self.cwd / r).exists()]


class Testee:
    """A testee process, started once, one JSON line per request."""

    def __init__(self, binding: Binding, timeout: float = TIMEOUT) -> None:
        self.binding = binding
        self.timeout = timeout
        self.proc: subprocess.Popen[str] | None = None
        self.lines: queue.Queue[str | None] = queue.Queue()

    def start(self) -> None:
        env = dict(os.environ)
        env.update({k: v.format(repo=REPO) for k, v in self.binding.env.items()})
        cmd = [c.format(repo=REPO, python=sys.executable) for c in self.binding.command]
        self.proc = subprocess.Popen(cmd, cwd=self.binding.cwd, env=env, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                     stderr=sys.stderr, text=True, encoding="utf-8", bufsize=1)
        self.lines = queue.Queue()
        out = self.proc.stdout
        assert out is not None

        def pump() -> None:
            for line in out:
                self.lines.put(line)
            self.lines.put(None)

        threading.Thread(target=pump, daemon=True).start()

    def ask(self, request: dict[str, Any]) -> dict[str, Any]:
        if self.proc is None or self.proc.poll() is not None:
            self.start()
        assert self.proc is not None and self.proc.stdin is not None
        try:
            self.proc.stdin.write(json.dumps(request) + "\n")
            self.proc.stdin.flush()
            line = self.lines.get(timeout=self.timeout)
        except queue.Empty:
            self.stop(ask_first=False)  # it did not answer this request: it will not answer quit either
            raise RuntimeError(f"testee gave no answer within {self.timeout:g} s") from None
        except (BrokenPipeError, OSError) as exc:
            self.stop()
            raise RuntimeError(f"testee died ({type(exc).__name__})") from None
        if line is None:
            self.stop()
            raise RuntimeError("testee exited")
        try:
            answer = json.loads(line)
        except json.JSONDecodeError:
            raise RuntimeError(f"testee wrote a line that is not JSON: {line[:80]!r}") from None
        if not isinstance(answer, dict):
            raise RuntimeError("testee answered with something other than an object")
        return answer

    def stop(self, ask_first: bool = True) -> None:
        """Ask the testee to quit (5 s), then kill it; or kill it at once (ask_first=False)."""
        if self.proc is None:
            return
        quit_ = False
        if ask_first:
            try:
                if self.proc.poll() is None and self.proc.stdin:
                    self.proc.stdin.write('{"op": "quit"}\n')
                    self.proc.stdin.flush()
                self.proc.wait(timeout=5)
                quit_ = True
            except (OSError, subprocess.TimeoutExpired):
                pass
        if not quit_:
            self.proc.kill()
            self.proc.wait()
        self.proc = None


def load_cases(golden: Path, prefixes: list[str] | None = None) -> list[Case]:
    cases = []
    for exp in sorted(golden.glob("*.expect.yaml")):
        name = exp.name[: -len(".expect.yaml")]
        if prefixes and not any(name.startswith(p) for p in prefixes):
            continue
        data = yaml.load(exp.read_text(encoding="utf-8"), Loader=_YAML_LOADER)
        cases.append(Case(name, golden / f"{name}.cbf", data))
    return cases


def load_bindings(path: Path) -> list[Binding]:
    data = yaml.load(path.read_text(encoding="utf-8"), Loader=_YAML_LOADER)
    return [Binding(b["name"], list(b["command"]), dict(b.get("env", {})), list(b.get("requires", [])))
            for b in data["bindings"]]


# -- one case, one binding ---------------------------------------------------------
def run_case(t: Testee, case: Case) -> tuple[str, str]:
    """('pass'|'fail'|'skip', message) for one case on one testee."""
    path = str(case.cbf)
    skipped, ran = 0, 0
    decoded: dict[str, Any] = {}  # the decode step's answer, which the encode step sends back
    for step in ("decode", "validate", "encode"):
        try:
            result = _step(t, case, step, path, decoded)
        except RuntimeError as exc:
            return "fail", f"{step}: {exc}"
        if result is None:
            continue
        if result == "skipped":
            skipped += 1
            continue
        ran += 1
        if result != "ok":
            return "fail", f"{step}: {result}"
    if ran == 0 and skipped:
        return "skip", "every operation skipped"
    return "pass", ""


def _step(t: Testee, case: Case, step: str, path: str, decoded: dict[str, Any]) -> str | None:
    exp = case.expect
    if step == "decode":
        want = exp.get("decode")
        if want is None:
            return None
        ans = decoded["answer"] = t.ask({"op": "decode", "file": path})
        if ans.get("skipped"):
            return "skipped"
        if isinstance(want, dict) and "error" in want:
            if ans.get("ok"):
                return f"decoded, expected error {want['error']}"
            err = ans.get("error") or {}
            if err.get("kind") != want["error"]["kind"] or err.get("offset") != want["error"]["offset"]:
                return f"error {err.get('kind')}@{err.get('offset')}, expected {want['error']['kind']}@" \
                       f"{want['error']['offset']}"
            return "ok"
        if not ans.get("ok"):
            return f"failed to decode: {ans.get('error')}"
        result = ans.get("result")
        if want != "ok":
            diff = first_difference(want, result)
            if diff:
                return diff
        for pointer, value in (exp.get("decode_subset") or {}).items():
            try:
                got = _resolve(result, pointer)
            except (KeyError, IndexError, TypeError):
                return f"{pointer}: missing"
            diff = first_difference(value, got, pointer)
            if diff:
                return diff
        count = exp.get("decode_records")
        if count is not None and len((result or {}).get("records", [])) != count:
            return f"expected {count} records, got {len((result or {}).get('records', []))}"
        return "ok"
    if step == "validate":
        want_v = exp.get("validate")
        if not want_v:
            return None
        opts = exp.get("options") or {}
        cutters = opts.get("cutters")
        machine = opts.get("machine")
        for profile, expected in want_v.items():
            ans = t.ask({"op": "validate", "file": path, "profile": profile,
                         "part_number": opts.get("part_number"),
                         "cutters": str(case.cbf.parent / cutters) if cutters else None,
                         "machine": str(case.cbf.parent / machine) if machine else None})
            if ans.get("skipped"):
                return "skipped"
            if not ans.get("ok"):
                return f"[{profile}] validate failed: {ans.get('error')}"
            try:
                diff = findings_difference(expected or [], ans.get("findings") or [])
            except ValueError as exc:  # an expectation without its offset
                return f"[{profile}] {exc}"
            if diff:
                return f"[{profile}] {diff}"
        return "ok"
    # encode: the decoded JSON back to the exact bytes (stored values kept), and for
    # files with no default finding also with every derived value filled in. The JSON is the
    # decode step's answer when that step ran (asking again cost a second decode of every
    # file, about 1.3 s a binding for the 65,535-record case); else the testee decodes now.
    if not exp.get("encode"):
        return None
    dec = decoded.get("answer") or t.ask({"op": "decode", "file": path})
    if dec.get("skipped"):
        return "skipped"
    if not dec.get("ok"):
        return f"cannot decode to re-encode: {dec.get('error')}"
    data = case.cbf.read_bytes()
    modes = [True]
    if not (exp.get("validate") or {}).get("default") and exp.get("encode_fill", True):
        modes.append(False)
    for keep in modes:
        ans = t.ask({"op": "encode", "json": dec["result"], "keep_stored": keep, "profile": "default"})
        if ans.get("skipped"):
            return "skipped"
        if not ans.get("ok"):
            return f"keep_stored={keep}: refused: {ans.get('error')}"
        got = base64.b64decode(ans.get("bytes", ""))
        if got != data:
            at = next((i for i in range(min(len(got), len(data))) if got[i] != data[i]), min(len(got), len(data)))
            return f"keep_stored={keep}: bytes differ at offset {at} ({len(got)} vs {len(data)} bytes)"
    return "ok"


def _resolve(doc: Any, pointer: str) -> Any:
    cur = doc
    for part in pointer.strip("/").split("/"):
        cur = cur[int(part)] if isinstance(cur, list) else cur[part]
    return cur


# -- failure lists -----------------------------------------------------------------
def read_failures(path: Path) -> dict[str, str]:
    out: dict[str, str] = {}
    if not path.exists():
        return out
    for line in path.read_text(encoding="utf-8").splitlines():
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        name, _, message = line.partition(" ")
        out[name] = message.strip()
    return out


def write_failures(path: Path, failures: dict[str, str], binding: str) -> None:
    """Rewrite the list; the comment block at its top (the reasons) is kept."""
    head = (f"# Known conformance failures of the {binding} binding: `case message`, one a line.\n"
            "# The run fails on an unlisted failure, a listed case that passes, or a changed message.\n"
            "# Rewrite with: python -m conformance.runner --fix\n")
    if path.exists():
        kept = [ln for ln in path.read_text(encoding="utf-8").splitlines(keepends=True) if ln.startswith("#")]
        if kept:
            head = "".join(kept)
    body = "".join(f"{k} {v}\n" for k, v in sorted(failures.items()))
    path.write_text(head + body, encoding="utf-8")


def main_run(args: argparse.Namespace) -> int:
    cases = load_cases(args.golden, args.case)
    if not cases:
        print(f"conformance: no golden cases in {args.golden}", file=sys.stderr)
        return 2
    if args.testee:
        bindings = [Binding(args.name, shlex.split(args.testee), cwd=Path.cwd())]
    else:
        bindings = load_bindings(args.bindings)
    if args.binding:
        unknown = set(args.binding) - {b.name for b in bindings}
        if unknown:
            print(f"conformance: unknown binding {sorted(unknown)[0]}", file=sys.stderr)
            return 2
        bindings = [b for b in bindings if b.name in args.binding]
    if args.python_path:
        for b in bindings:
            if b.name == "python":
                b.env["PYTHONPATH"] = args.python_path
    report: dict[str, Any] = {"cases": {c.name: {"group": c.group, "clauses": c.expect.get("clauses", []),
                                                  "checks": sorted({str(f[0]) for fs in (c.expect.get("validate") or {})
                                                                    .values() for f in (fs or [])})}
                                        for c in cases},
                              "bindings": {}}
    problems: list[str] = []
    for b in bindings:
        missing = b.missing()
        results: dict[str, dict[str, str]] = {}
        if missing:
            print(f"conformance: {b.name}: not built ({', '.join(missing)}); every case skipped")
            results = {c.name: {"status": "skip", "message": "binding not built"} for c in cases}
            report["bindings"][b.name] = {"available": False, "results": results}
            continue
        t = Testee(b, args.timeout)
        try:
            for c in cases:
                status, message = run_case(t, c)
                results[c.name] = {"status": status, "message": message}
        finally:
            t.stop()
        report["bindings"][b.name] = {"available": True, "results": results}
        fpath = args.failure_list if args.failure_list else args.failures / f"{b.name}.txt"
        listed = read_failures(fpath)
        failing = {n: r["message"] for n, r in results.items() if r["status"] == "fail"}
        if args.fix:
            write_failures(fpath, failing, b.name)
            continue
        for name, msg in sorted(failing.items()):
            if name not in listed:
                problems.append(f"{b.name}: {name}: FAIL {msg}")
            elif listed[name] != msg:
                problems.append(f"{b.name}: {name}: listed as failing with '{listed[name]}', now fails with '{msg}'")
        for name in sorted(listed):
            if name in results and name not in failing:
                problems.append(f"{b.name}: {name}: listed as failing but passes: remove it from {fpath.name}")
    human = sys.stderr if args.json else sys.stdout
    _print_matrix(report, cases, human)
    # The committed report is the evidence of a full run: a partial run (some
    # bindings, some cases, a scratch build, an outside testee) writes only where it is told to.
    out: Path | None = args.report
    if out is None and not (args.binding or args.case or args.python_path or args.testee) and ROOT.joinpath(
            "bindings.yaml").exists():
        out = ROOT / "report.json"
    if out is not None:
        tmp = out.with_suffix(".json.tmp")
        tmp.write_text(json.dumps(report, indent=1, sort_keys=True) + "\n", encoding="utf-8")
        os.replace(tmp, out)
    if args.junit:
        write_junit(args.junit, report, cases)
    report["problems"] = problems
    if args.json:
        json.dump(report, sys.stdout, indent=1, sort_keys=True)
        sys.stdout.write("\n")
    for p in problems:
        print(p, file=human)
    total = sum(1 for b in report["bindings"].values() for r in b["results"].values() if r["status"] == "pass")
    print(f"conformance: {total} passed, {len(problems)} failed", file=human)
    return 1 if problems else 0


def write_junit(path: Path, report: dict[str, Any], cases: list[Case]) -> None:
    """JUnit XML for CI dashboards: a test suite per binding, a test case per golden case."""
    suites = ET.Element("testsuites", name="cbf-conformance")
    for name, b in report["bindings"].items():
        results = b["results"]
        suite = ET.SubElement(suites, "testsuite", name=name, tests=str(len(results)),
                              failures=str(sum(r["status"] == "fail" for r in results.values())),
                              skipped=str(sum(r["status"] == "skip" for r in results.values())))
        for c in cases:
            r = results.get(c.name)
            if r is None:
                continue
            tc = ET.SubElement(suite, "testcase", classname=f"{name}.{c.group}", name=c.name)
            if r["status"] == "fail":
                ET.SubElement(tc, "failure", message=r["message"]).text = r["message"]
            elif r["status"] == "skip":
                ET.SubElement(tc, "skipped", message=r["message"])
    path.write_bytes(ET.tostring(suites, encoding="utf-8", xml_declaration=True) + b"\n")


def _print_matrix(report: dict[str, Any], cases: list[Case], out: TextIO) -> None:
    groups = sorted({c.group for c in cases})
    names = list(report["bindings"])
    width = max([len(g) for g in groups] + [10])
    print("group".ljust(width) + "".join(f"  {n:>16}" for n in names), file=out)
    for g in groups:
        row = g.ljust(width)
        for n in names:
            res = [r for cn, r in report["bindings"][n]["results"].items() if report["cases"][cn]["group"] == g]
            p = sum(r["status"] == "pass" for r in res)
            f = sum(r["status"] == "fail" for r in res)
            s = sum(r["status"] == "skip" for r in res)
            row += f"  {f'{p}/{f}/{s}':>16}"
        print(row, file=out)
    print("(pass/fail/skip)", file=out)
