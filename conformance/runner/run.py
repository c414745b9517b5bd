"""Run the golden cases through every binding's testee and judge the answers."""

from __future__ import annotations

import argparse
import base64
import difflib
import json
import os
import shlex
import shutil
import stat
import sys
import time
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Protocol, TextIO

import yaml

from .about import SPEC_REVISION, VERSION, version_line
from .compare import findings_difference, first_difference
from .quoting import line as one_line
from .quoting import lines as one_lines
from .quoting import quote
from .reasons import bad_pattern, failure_class, fixed_entries, matches
from .testee import CAPABILITIES, Binding, Testee, TesteeError, install_handlers

# libyaml's parser (PyYAML's C binding) when present: the same values, about ten times faster.
_YAML_LOADER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)

ROOT = Path(__file__).resolve().parents[1]
REPO = ROOT.parent
# Installed as the cbf-conformance kit, the golden cases ship beside the runner.
PACKAGED_GOLDEN = Path(__file__).resolve().parent / "golden"
DEFAULT_GOLDEN = PACKAGED_GOLDEN if PACKAGED_GOLDEN.is_dir() else ROOT / "golden"
TIMEOUT = 60.0  # seconds a testee may take to answer one request
MAX_TIMEOUTS = 3  # consecutive timeouts after which a testee's run stops
DEADLINE = 3600.0  # seconds the whole run may take


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
    return [Binding(b["name"], list(b["command"]), dict(b.get("env", {})), list(b.get("requires", [])), REPO,
                    parse_capabilities(",".join(b.get("capabilities", CAPABILITIES))))
            for b in data["bindings"]]


def parse_capabilities(text: str) -> tuple[str, ...]:
    """``decode,validate,encode`` or a part of it, in the protocol's order. Encode sends back the
    testee's own decode, so it needs decode. Raises ValueError with the reason."""
    names = [n.strip() for n in text.split(",") if n.strip()]
    unknown = [n for n in names if n not in CAPABILITIES]
    if unknown:
        raise ValueError(f"unknown capability {unknown[0]!r} (one or more of {', '.join(CAPABILITIES)})")
    if not names:
        raise ValueError(f"no capability named (one or more of {', '.join(CAPABILITIES)})")
    if "encode" in names and "decode" not in names:
        raise ValueError("encode needs decode (the runner re-encodes the testee's own decode)")
    return tuple(c for c in CAPABILITIES if c in names)


# -- one case, one binding ---------------------------------------------------------


@dataclass(frozen=True)
class Outcome:
    """One case on one testee: its status and message, and which operations were judged and which
    the testee answered with "skipped" (per capability, what every report counts)."""

    status: str  # pass | fail | skip
    message: str
    judged: tuple[str, ...] = ()
    skipped: tuple[str, ...] = ()

    def as_result(self) -> dict[str, Any]:
        return {"status": self.status, "message": self.message, "judged": list(self.judged),
                "skipped": list(self.skipped)}


SKIPPED = "skipped"  # the message of a case whose declared operations the testee answered with skipped


class Asks(Protocol):
    """What a case needs of a testee: one request of PROTOCOL.md answered (a Testee process, or a
    stand-in in this process such as tests/test_witness.py's)."""

    def ask(self, request: dict[str, Any], /) -> dict[str, Any]: ...


def run_case(t: Asks, case: Case, capabilities: tuple[str, ...] = CAPABILITIES) -> Outcome:
    """One case on one testee. Only the operations of ``capabilities`` are asked; an operation of
    them that the testee answers with ``{"skipped": true}`` fails the case (``OP: skipped``: a
    failure list may name it), so a testee cannot pass by answering nothing. A case that asks none
    of the testee's capabilities is a skip."""
    path = str(case.cbf)
    judged: list[str] = []
    skipped: list[str] = []
    decoded: dict[str, Any] = {}  # the decode step's answer, which the encode step sends back
    for step in CAPABILITIES:
        if step not in capabilities:
            continue
        try:
            result = _step(t, case, step, path, decoded)
        except TesteeError as exc:
            return Outcome("fail", f"{step}: {exc}", tuple(judged), tuple(skipped))
        if result is None:
            continue
        if result == "skipped":
            skipped.append(step)
            continue
        judged.append(step)
        if result != "ok":
            return Outcome("fail", f"{step}: {result}", tuple(judged), tuple(skipped))
    if skipped:
        return Outcome("fail", f"{', '.join(skipped)}: {SKIPPED}", tuple(judged), tuple(skipped))
    if not judged:
        return Outcome("skip", f"asks none of the testee's capabilities ({', '.join(capabilities)})")
    return Outcome("pass", "", tuple(judged))


def _step(t: Asks, case: Case, step: str, path: str, decoded: dict[str, Any]) -> str | None:
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
class FailureListError(Exception):
    """A failure list that cannot be read: one line, exit 2."""


MAX_FAILURE_LIST = 4 * 1024 * 1024  # bytes: a line per golden case is a few hundred; 4 MiB is far beyond any list


def _read_bounded(path: Path) -> str:
    """A failure list's text: a regular file (a FIFO, a device such as /dev/zero, a folder is
    refused before it is read) of at most MAX_FAILURE_LIST bytes, read no further than that."""
    fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0))
    with os.fdopen(fd, "rb") as f:
        if not stat.S_ISREG(os.fstat(f.fileno()).st_mode):
            raise FailureListError(f"{path}: not a regular file")
        data = f.read(MAX_FAILURE_LIST + 1)
    if len(data) > MAX_FAILURE_LIST:
        raise FailureListError(f"{path}: larger than {MAX_FAILURE_LIST // (1 << 20)} MiB: not a failure list")
    return data.decode("utf-8")


def read_failures(path: Path, required: bool = False) -> dict[str, str]:
    """``case message`` lines (``#`` comments). A missing file is an empty list unless ``required``
    (a --failure-list the user named must exist: a typo must not turn every failure green)."""
    out: dict[str, str] = {}
    try:
        text = _read_bounded(path)
    except FileNotFoundError:
        if required:
            raise FailureListError(f"{path}: no such file") from None
        return out
    except (OSError, UnicodeDecodeError) as exc:
        why = exc.strerror if isinstance(exc, OSError) else "not UTF-8 text"
        raise FailureListError(f"{path}: cannot read ({why})") from None
    for n, line in enumerate(text.splitlines(), 1):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        name, _, reason = line.partition(" ")
        if name in out:
            raise FailureListError(f"{path}: line {n}: case {name} is listed twice")
        bad = bad_pattern(reason.strip())
        if bad:
            raise FailureListError(f"{path}: line {n}: case {name}: {bad}")
        out[name] = reason.strip()
    return out


def write_failures(path: Path, failures: dict[str, str], binding: str,
                   rewrite: str = "python -m conformance.runner --fix") -> str:
    """Rewrite the list (``failures``: case -> reason); the comment block at its top (the reasons)
    is kept. Returns the unified diff from the old list to the new one ("" when unchanged)."""
    head = (f"# Known conformance failures of the {quote(binding)} binding: `case reason`, one a line (a failure\n"
            "#   class, `~ REGEX` or the exact message: conformance/runner/reasons.py).\n"
            "# The run fails on an unlisted failure, a listed case that passes, or one failing for another reason.\n"
            f"# Rewrite with: {rewrite}\n")
    old = path.read_text(encoding="utf-8") if path.exists() else ""
    kept = [ln for ln in old.splitlines(keepends=True) if ln.startswith("#")]
    if kept:
        head = "".join(kept)
    new = head + "".join(f"{k} {v}\n" for k, v in sorted(failures.items()))
    if new != old:
        tmp = path.with_name(path.name + ".tmp")
        tmp.write_text(new, encoding="utf-8")
        os.replace(tmp, path)
    return "".join(difflib.unified_diff(old.splitlines(keepends=True), new.splitlines(keepends=True),
                                        f"a/{path.name}", f"b/{path.name}"))


# -- judging a run ---------------------------------------------------------------------
def judge(results: dict[str, dict[str, Any]], listed: dict[str, str], list_name: str) -> None:
    """Mark each result against the failure list, in place. A listed case failing for its listed
    reason (reasons.matches) is an expected failure: status stays "fail" and ``expected_failure``
    is true (reports count it apart). A listed case that passes, or fails otherwise, is a failure."""
    for name, r in results.items():
        r["expected_failure"] = False
        if name not in listed:
            continue
        if r["status"] == "fail" and matches(listed[name], r["message"]):
            r["expected_failure"] = True
        elif r["status"] == "fail":
            r["message"] = (f"listed as failing with '{listed[name]}', now fails with '{r['message']}' "
                            f"(reason '{failure_class(r['message'])}')")
        elif r["status"] == "pass":
            r["status"] = "fail"
            r["message"] = f"listed as failing but passes: remove it from {list_name}"


def stale_entries(listed: dict[str, str], cases: list[Case], list_name: str) -> str | None:
    """One line when the failure list names cases no golden case has (a case a revision removed or
    renamed): the list is stale (a run of every case only; --case runs some)."""
    gone = sorted(set(listed) - {c.name for c in cases})
    if not gone:
        return None
    return (f"{list_name}: names {len(gone)} case(s) no golden case has: {', '.join(gone)} "
            "(stale: rewrite the list with --fix, or `make failures` here)")


def kind(r: dict[str, Any]) -> str:
    """pass, fail, xfail (an expected failure) or skip: what every report counts."""
    if r["status"] == "fail" and r.get("expected_failure"):
        return "xfail"
    return str(r["status"])


def counts(results: dict[str, dict[str, Any]]) -> dict[str, int]:
    out = {"passed": 0, "failed": 0, "expected_failures": 0, "skipped": 0}
    names = {"pass": "passed", "fail": "failed", "xfail": "expected_failures", "skip": "skipped"}
    for r in results.values():
        out[names[kind(r)]] += 1
    return out


def _testee_binding(args: argparse.Namespace) -> Binding:
    """The --testee command, checked before anything runs: a missing program is one line, exit 2."""
    try:
        cmd = shlex.split(args.testee)
    except ValueError as exc:
        raise FailureListError(f"--testee: cannot split {args.testee!r} ({exc})") from None
    if not cmd:  # `--testee "$UNSET"` in a CI line must not run something else and pass
        raise FailureListError("--testee: empty command (name the program that starts your testee)")
    prog = cmd[0]
    if os.sep in prog:
        if not Path(prog).is_file():
            raise FailureListError(f"--testee: {prog}: no such file")
        if not os.access(prog, os.X_OK):
            raise FailureListError(f"--testee: {prog}: not executable")
    elif shutil.which(prog) is None:
        raise FailureListError(f"--testee: {prog}: no such program on PATH")
    try:
        capabilities = parse_capabilities(args.capabilities)
    except ValueError as exc:
        raise FailureListError(f"--capabilities: {exc}") from None
    return Binding(args.name, cmd, cwd=Path.cwd(), capabilities=capabilities)


def main_run(args: argparse.Namespace) -> int:
    human = sys.stderr if args.json else sys.stdout
    try:
        bindings = [_testee_binding(args)] if args.testee is not None else load_bindings(args.bindings)
        if args.failure_list is not None and not (args.fix and not args.failure_list.exists()):
            read_failures(args.failure_list, required=True)
        for option, path in (("--junit", args.junit), ("--report", args.report)):
            if path is not None and (path.is_dir() or not path.resolve().parent.is_dir()):
                why = "is a directory" if path.is_dir() else f"folder {str(path.resolve().parent)!r} does not exist"
                raise FailureListError(f"{option} {path}: {why}")
    except FailureListError as exc:
        print(f"cbf-conformance: {exc}", file=sys.stderr)
        return 2
    cases = load_cases(args.golden, args.case)
    if not cases:
        print(f"cbf-conformance: no golden cases in {args.golden}"
              + (f" starting with {', '.join(args.case)}" if args.case else ""), file=sys.stderr)
        return 2
    if args.binding:
        unknown = set(args.binding) - {b.name for b in bindings}
        if unknown:
            print(f"cbf-conformance: unknown binding {sorted(unknown)[0]}", file=sys.stderr)
            return 2
        bindings = [b for b in bindings if b.name in args.binding]
    if args.python_path:
        for b in bindings:
            if b.name == "python":
                b.env["PYTHONPATH"] = args.python_path
    install_handlers()
    deadline = time.monotonic() + args.deadline
    report: dict[str, Any] = {"kit": {"version": VERSION, "spec_revision": SPEC_REVISION},
                              "cases": {c.name: {"group": c.group, "clauses": c.expect.get("clauses", []),
                                                 "checks": sorted({str(f[0]) for fs in (c.expect.get("validate") or {})
                                                                   .values() for f in (fs or [])})}
                                        for c in cases},
                              "bindings": {}}
    notes: list[str] = []
    stale: list[str] = []
    for b in bindings:
        missing = b.missing()
        results: dict[str, dict[str, Any]] = {}
        if missing:
            print(f"conformance: {quote(b.name)}: not built ({', '.join(missing)}); every case skipped", file=human)
            results = {c.name: {"status": "skip", "message": "binding not built"} for c in cases}
            report["bindings"][b.name] = {"available": False, "results": results}
            continue
        results = _run_binding(b, cases, args.timeout, deadline, notes)
        report["bindings"][b.name] = {"available": True, "capabilities": list(b.capabilities), "results": results}
        fpath = args.failure_list if args.failure_list else args.failures / f"{b.name}.txt"
        try:
            listed = read_failures(fpath)
            if args.fix:
                listed = _fix(args, fpath, b.name, results, listed, cases, human)
        except FailureListError as exc:
            print(f"cbf-conformance: {exc}", file=sys.stderr)
            return 2
        judge(results, listed, fpath.name)
        if not args.case:
            stale.extend(line for line in [stale_entries(listed, cases, fpath.name)] if line)
    for b_report in report["bindings"].values():
        b_report["summary"] = counts(b_report["results"])
        if b_report["available"]:
            b_report["judged"] = judged_per_capability(b_report["results"], cases, b_report["capabilities"])
    unjudged = [line for name, b_report in report["bindings"].items() if b_report["available"]
                for line in [judging_problem(name, b_report)] if line]
    total = counts({f"{n}/{c}": r for n, b in report["bindings"].items() for c, r in b["results"].items()})
    report["summary"] = total
    print(version_line(), file=human)
    _print_matrix(report, cases, human)
    _print_judged(report, human)
    # The committed report is the evidence of a full run: a partial run (some
    # bindings, some cases, a scratch build, an outside testee) writes only where it is told to.
    out: Path | None = args.report
    if out is None and not (args.binding or args.case or args.python_path or args.testee is not None) and ROOT.joinpath(
            "bindings.yaml").exists():
        out = ROOT / "report.json"
    if out is not None:
        tmp = out.with_suffix(".json.tmp")
        tmp.write_text(json.dumps(report, indent=1, sort_keys=True) + "\n", encoding="utf-8")
        os.replace(tmp, out)
    if args.junit:
        write_junit(args.junit, report, cases)
    # a case failing only because the testee skipped an operation it declared is said once, in the
    # binding's judging line (unjudged), not once a case
    problems = [f"{quote(n)}: {quote(c)}: FAIL {one_line(r['message'])}" for n, b in report["bindings"].items()
                for c, r in b["results"].items() if kind(r) == "fail" and not r.get("not_run")
                and not r["message"].endswith(f": {SKIPPED}")]
    report["problems"] = problems + notes + unjudged + stale
    if args.json:
        json.dump(report, sys.stdout, indent=1, sort_keys=True)
        sys.stdout.write("\n")
    for p in problems + notes + unjudged + stale:
        print(p, file=human)
    print(f"conformance: {total['passed']} passed, {total['failed']} failed, {total['expected_failures']} expected "
          f"failure(s), {total['skipped']} skipped", file=human)
    return 1 if total["failed"] or unjudged or stale else 0


def _fix(args: argparse.Namespace, fpath: Path, name: str, results: dict[str, dict[str, Any]],
         listed: dict[str, str], cases: list[Case], human: TextIO) -> dict[str, str]:
    """--fix: rewrite the failure list to this run's failures, by reason (reasons.fixed_entries),
    and print the diff to review. A --case run keeps the entries of the cases it did not run."""
    rewrite = (f"cbf-conformance --testee {shlex.quote(args.testee)} --failure-list {fpath.name} --fix"
               if args.testee is not None else "python -m conformance.runner --fix")
    ran = {c.name for c in cases}
    failing = {n: r["message"] for n, r in results.items() if r["status"] == "fail"}
    kept = {n: v for n, v in listed.items() if args.case and n not in ran}
    entries = {**kept, **fixed_entries(failing, listed)}
    diff = write_failures(fpath, entries, name, rewrite)
    print(one_lines(diff) if diff else f"conformance: {quote(fpath.name)}: unchanged", file=human,
          end="" if diff else "\n")
    return entries


def judged_per_capability(results: dict[str, dict[str, Any]], cases: list[Case],
                          capabilities: list[str]) -> dict[str, dict[str, int]]:
    """Per operation: how many cases state an expectation for it (``cases``), how many the testee's
    answers were judged on (``judged``) and how many it answered with skipped (``skipped``; an
    operation outside its capabilities is never asked: 0 judged, 0 skipped)."""
    out: dict[str, dict[str, int]] = {}
    for cap in CAPABILITIES:
        out[cap] = {"cases": sum(1 for c in cases if states(c.expect, cap)),
                    "judged": sum(1 for r in results.values() if cap in r.get("judged", ())),
                    "skipped": sum(1 for r in results.values() if cap in r.get("skipped", ())),
                    "declared": int(cap in capabilities)}
    return out


def states(expect: dict[str, Any], op: str) -> bool:
    """Whether a case's expectation states an outcome for an operation (what run_case then asks)."""
    return expect.get("decode") is not None if op == "decode" else bool(expect.get(op))


def judging_problem(name: str, b_report: dict[str, Any]) -> str:
    """One line when the testee was judged on nothing it declared, or skipped operations its failure
    list does not name; "" when its answers were judged as declared."""
    results, judged, caps = b_report["results"], b_report["judged"], b_report["capabilities"]
    none = [c for c in caps if judged[c]["cases"] and not judged[c]["judged"]]
    unlisted: dict[str, int] = {}
    for r in results.values():
        if kind(r) == "fail" and r["message"].endswith(f": {SKIPPED}"):
            for c in r.get("skipped", ()):
                unlisted[c] = unlisted.get(c, 0) + 1
    if not none and not unlisted:
        return ""
    parts = []
    if none:
        parts.append(f"judged no {' and no '.join(none)} case")
    if unlisted:
        parts.append("skipped " + ", ".join(f"{c} in {n} of {judged[c]['cases']} case(s)" for c, n in unlisted.items())
                     + " that its failure list does not name")
    return (f"{quote(name)}: FAIL {'; '.join(parts)}: a testee answers every operation of its capabilities "
            f"({','.join(caps)}); one that lacks one says so with --capabilities (e.g. --capabilities decode)")


def _run_binding(b: Binding, cases: list[Case], timeout: float, deadline: float,
                 notes: list[str]) -> dict[str, dict[str, Any]]:
    """Every case on one testee: a surplus answer fails the case that produced it; after
    MAX_TIMEOUTS timeouts in a row, or past the deadline, the rest are not run (one note says why)."""
    results: dict[str, dict[str, Any]] = {}
    t = Testee(b, timeout, expand=lambda s: s.format(repo=REPO, python=sys.executable))
    t.deadline = deadline
    stopped: str | None = None
    try:
        for c in cases:
            if stopped is None and time.monotonic() >= deadline:
                stopped = "the run's deadline passed"
            if stopped is not None:
                results[c.name] = {"status": "fail", "message": f"not run: {stopped}", "not_run": True}
                continue
            try:
                outcome = run_case(t, c, b.capabilities)
            except OSError as exc:  # the testee cannot be started
                outcome = Outcome("fail", f"testee cannot start: {exc.strerror or exc}")
            surplus = t.drain()
            if surplus:  # this case's testee answered more than it was asked: the case fails, no later one
                outcome = Outcome("fail", surplus if outcome.status != "fail" else f"{surplus}; before it: "
                                  f"{outcome.message}", outcome.judged, outcome.skipped)
            results[c.name] = outcome.as_result()
            if t.consecutive_timeouts >= MAX_TIMEOUTS:
                stopped = f"{quote(b.name)} stopped after {MAX_TIMEOUTS} timeouts in a row"
        if stopped is not None:
            skipped = sum(1 for r in results.values() if r.get("not_run"))
            notes.append(f"{quote(b.name)}: {stopped}: {skipped} case(s) not run")
    finally:
        t.stop()
    return results


def write_junit(path: Path, report: dict[str, Any], cases: list[Case]) -> None:
    """JUnit XML for CI dashboards: a test suite per binding, a test case per golden case. An
    expected failure (from the failure list) is <skipped> with its reason, and a property."""
    suites = ET.Element("testsuites", name="cbf-conformance")
    for name, b in report["bindings"].items():
        results = b["results"]
        n = counts(results)
        suite = ET.SubElement(suites, "testsuite", name=quote(name), tests=str(len(results)), failures=str(n["failed"]),
                              errors="0", skipped=str(n["skipped"] + n["expected_failures"]))
        props = ET.SubElement(suite, "properties")
        for key, value in (("kit.version", report["kit"]["version"]),
                           ("spec.revision", report["kit"]["spec_revision"]),
                           ("expected_failures", str(n["expected_failures"]))):
            ET.SubElement(props, "property", name=key, value=value)
        if "capabilities" in b:
            ET.SubElement(props, "property", name="capabilities", value=",".join(b["capabilities"]))
            for cap, got in b["judged"].items():
                ET.SubElement(props, "property", name=f"judged.{cap}", value=f"{got['judged']}/{got['cases']}")
        for c in cases:
            r = results.get(c.name)
            if r is None:
                continue
            tc = ET.SubElement(suite, "testcase", classname=quote(f"{name}.{c.group}"), name=quote(c.name))
            k = kind(r)
            if k == "fail":
                ET.SubElement(tc, "failure", message=one_line(r["message"])).text = one_line(r["message"])
            elif k == "xfail":
                ET.SubElement(tc, "skipped", message=one_line(f"expected failure (failure list): {r['message']}"),
                              type="expected-failure")
                tp = ET.SubElement(tc, "properties")
                ET.SubElement(tp, "property", name="expected_failure", value="true")
            elif k == "skip":
                ET.SubElement(tc, "skipped", message=one_line(r["message"]))
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_bytes(ET.tostring(suites, encoding="utf-8", xml_declaration=True) + b"\n")
    os.replace(tmp, path)


def _print_matrix(report: dict[str, Any], cases: list[Case], out: TextIO) -> None:
    groups = sorted({c.group for c in cases})
    names = list(report["bindings"])
    width = max([len(g) for g in groups] + [10])
    print("group".ljust(width) + "".join(f"  {quote(n):>16}" for n in names), file=out)
    for g in groups:
        row = g.ljust(width)
        for n in names:
            res = [r for cn, r in report["bindings"][n]["results"].items() if report["cases"][cn]["group"] == g]
            k = [kind(r) for r in res]
            cell = f"{k.count('pass')}/{k.count('fail')}/{k.count('xfail')}/{k.count('skip')}"
            row += f"  {cell:>16}"
        print(row, file=out)
    print("(pass/fail/expected failure/skip)", file=out)


def _print_judged(report: dict[str, Any], out: TextIO) -> None:
    """Per capability, the cases each testee's answers were judged on: judged/cases that state the
    operation, or "not declared" when the testee does not offer it (--capabilities)."""
    names = [n for n, b in report["bindings"].items() if b["available"]]
    if not names:
        return
    width = 10
    print("judged".ljust(width) + "".join(f"  {quote(n):>16}" for n in names), file=out)
    for cap in CAPABILITIES:
        row = cap.ljust(width)
        for n in names:
            got = report["bindings"][n]["judged"][cap]
            cell = f"{got['judged']}/{got['cases']}" if got["declared"] else "not declared"
            row += f"  {cell:>16}"
        print(row, file=out)
    print("(cases whose answers were judged / cases that state the operation)", file=out)
