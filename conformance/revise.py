"""`make revision`: the README's format-revision walkthrough as one command (issue 37, point 4).

    python -m conformance.revise [--no-conformance] [--proposals FILE]

After an edit of spec/cbf.yaml (and any golden case the revision adds), it runs, in the order that
leaves nothing stale: `make generate`, `make golden` (the .cbf files from their .hex, then what is made
from them), a check that generated/ is then fresh, the expectations check below, and `make
conformance` (every binding; it writes conformance/report.json and the docs' traceability pages).
Then it says what to review and commit.

A revision may change how existing golden cases are judged (a new error check some golden files
break, a deprecation of a command they hold, a rename of a command they decode). The expectations
check asks the Python binding's testee (through the conformance protocol, as the runner does: the
golden files and this tool import no binding) to decode and validate every golden case, and for
each case whose `.expect.yaml` it contradicts (a profile's findings, a command's name in
`decode_subset`) proposes the new expectation as a unified diff, written to FILE
(default build/revision/expectations.patch) and printed. Nothing is written to the golden files:
the owner reviews the diff and accepts it with `git apply FILE`, then runs `make revision` again.
Exit codes: 0 every step passes and no expectation changes; 1 a step fails, or expectations to review.
"""

from __future__ import annotations

import argparse
import difflib
import json
import re
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import yaml

from conformance.runner.compare import finding_key, findings_difference
from conformance.runner.run import DEFAULT_GOLDEN, TIMEOUT, Case, load_bindings, load_cases
from conformance.runner.testee import Testee, TesteeError

REPO = Path(__file__).resolve().parents[1]
PROPOSALS = REPO / "build" / "revision" / "expectations.patch"
PROPOSER = "python"  # the binding whose answers the proposals are: the reference runtime


def _finding(f: dict[str, Any]) -> list[Any]:
    """A testee's finding as an expectation writes it: [check, severity, record, offset]."""
    k = finding_key(f)
    return [k[0], k[1], None if k[2] < 0 else k[2], None if k[3] < 0 else k[3]]


def _flow(value: Any) -> str:
    """A value in YAML flow style (JSON is YAML): a check id such as "9.1" stays a string."""
    return json.dumps(value)


def _resolve(doc: Any, pointer: str) -> Any:
    cur = doc
    for part in pointer.strip("/").split("/"):
        cur = cur[int(part)] if isinstance(cur, list) else cur[part]
    return cur


def proposed_validate(t: Testee, case: Case) -> dict[str, list[list[Any]]]:
    """Each profile of the case's `validate:` whose findings the testee's contradict, with the testee's."""
    out: dict[str, list[list[Any]]] = {}
    opts = case.expect.get("options") or {}
    for profile, expected in (case.expect.get("validate") or {}).items():
        cutters, machine = opts.get("cutters"), opts.get("machine")
        ans = t.ask({"op": "validate", "file": str(case.cbf), "profile": profile,
                     "part_number": opts.get("part_number"),
                     "cutters": str(case.cbf.parent / cutters) if cutters else None,
                     "machine": str(case.cbf.parent / machine) if machine else None})
        if ans.get("ok") and findings_difference(expected or [], ans.get("findings") or []):
            got = [_finding(f) for f in ans.get("findings") or []]
            out[str(profile)] = sorted(got, key=lambda f: (f[2] if f[2] is not None else -1, f[3] or 0, f[0]))
    return out


def proposed_names(t: Testee, case: Case) -> dict[str, tuple[str, str]]:
    """Each `decode_subset` pointer whose expected value is a name (a command's, after a rename) the testee
    now decodes as another name: pointer -> (old, new). Numbers are not proposed: a changed number is a
    change of meaning, for the owner to judge by hand (the conformance run names it)."""
    subset = case.expect.get("decode_subset") or {}
    names = {p: v for p, v in subset.items() if isinstance(v, str) and re.fullmatch(r"[A-Z][A-Z0-9_]*", v)}
    if not names:
        return {}
    ans = t.ask({"op": "decode", "file": str(case.cbf)})
    out: dict[str, tuple[str, str]] = {}
    for pointer, old in names.items():
        try:
            got = _resolve(ans.get("result"), pointer)
        except (KeyError, IndexError, TypeError):
            continue
        if isinstance(got, str) and got != old:
            out[pointer] = (old, got)
    return out


def _block_end(lines: list[str], i: int) -> int:
    """The index after the YAML entry that starts at line i (its continuation lines are more indented)."""
    indent = len(lines[i]) - len(lines[i].lstrip())
    j = i + 1
    while j < len(lines) and (not lines[j].strip() or len(lines[j]) - len(lines[j].lstrip()) > indent):
        j += 1
    return j


def rewrite(text: str, validate: dict[str, list[list[Any]]], names: dict[str, tuple[str, str]]) -> str:
    """The expectation text with the proposed findings and names, every other line as it was."""
    lines = text.splitlines(keepends=True)
    top = next((i for i, ln in enumerate(lines) if ln.startswith("validate:")), None)
    if validate and top is not None:
        if lines[top].strip() != "validate:":  # the flow form, one entry: written whole again
            current = dict(yaml.safe_load("".join(lines[top:_block_end(lines, top)]))["validate"])
            current.update(validate)
            body = ", ".join(f"{k}: {_flow(v)}" for k, v in current.items())
            lines[top:_block_end(lines, top)] = [f"validate: {{{body}}}\n"]
        else:
            end = _block_end(lines, top)
            for profile, found in validate.items():
                at = next(i for i in range(top + 1, end) if lines[i].strip().startswith(f"{profile}:"))
                pad = lines[at][: len(lines[at]) - len(lines[at].lstrip())]
                lines[at:_block_end(lines, at)] = [f"{pad}{profile}: {_flow(found)}\n"]
                end = _block_end(lines, top)
    for pointer, (old, new) in names.items():
        at = next((i for i, ln in enumerate(lines) if pointer in ln), -1)
        if at >= 0:
            head, tail = lines[at].split(pointer, 1)
            lines[at] = head + pointer + re.sub(rf"\b{re.escape(old)}\b", new, tail, count=1)
    return "".join(lines)


def proposed(golden: Path = DEFAULT_GOLDEN) -> dict[Path, tuple[str, str]]:
    """Each expectation file the proposing testee contradicts: its text now and the proposed one."""
    binding = next(b for b in load_bindings(REPO / "conformance" / "bindings.yaml") if b.name == PROPOSER)
    t = Testee(binding, TIMEOUT, expand=lambda s: s.format(repo=REPO, python=sys.executable))
    t.start()
    out: dict[Path, tuple[str, str]] = {}
    try:
        for case in load_cases(golden):
            if not case.cbf.exists():
                continue
            validate, names = proposed_validate(t, case), proposed_names(t, case)
            if validate or names:
                path = golden / f"{case.name}.expect.yaml"
                old = path.read_text(encoding="utf-8")
                out[path] = (old, rewrite(old, validate, names))
    finally:
        t.stop()
    return out


def proposals(golden: Path = DEFAULT_GOLDEN) -> str:
    """The unified diff (paths as the repository names them) of every expectation the proposing testee
    contradicts; empty when none."""
    patch: list[str] = []
    for path, (old, new) in proposed(golden).items():
        rel = f"conformance/golden/{path.name}"  # as the repository names it (golden may be a copy)
        patch += difflib.unified_diff(old.splitlines(keepends=True), new.splitlines(keepends=True),
                                      f"a/{rel}", f"b/{rel}")
    return "".join(patch)


def _step(name: str, cmd: list[str]) -> bool:
    t = time.monotonic()
    res = subprocess.run(cmd, cwd=REPO, capture_output=True, text=True, stdin=subprocess.DEVNULL)
    print(f"  {'ok' if res.returncode == 0 else 'FAIL':<4} {name} ({time.monotonic() - t:.1f} s)", flush=True)
    if res.returncode:
        print("\n".join("       | " + ln for ln in (res.stdout + res.stderr).strip().splitlines()[-30:]))
    return res.returncode == 0


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="make revision", description=__doc__.split("\n\n")[0])
    ap.add_argument("--no-conformance", action="store_true", help="stop after the expectations check")
    ap.add_argument("--proposals", type=Path, default=PROPOSALS, help="where the proposed expectations go")
    ap.add_argument("--make-arg", action="append", default=[], help="an argument for every make it runs (the drill's "
                    "-o .venv/.stamp: its copy links this checkout's .venv)")
    args = ap.parse_args(argv)
    make = ["make", "--no-print-directory", *args.make_arg]
    print("make revision: generate, golden, freshness, expectations, conformance")
    for name, cmd in (("make generate", [*make, "generate"]), ("make golden", [*make, "golden"]),
                      ("generated/ fresh after golden", [*make, "-q", "build/stamps/generate-py"])):
        if not _step(name, cmd):
            return 1
    try:
        patch = proposals()
    except (TesteeError, OSError) as exc:
        print(f"  FAIL expectations: the {PROPOSER} testee: {exc}")
        return 1
    if patch:
        args.proposals.parent.mkdir(parents=True, exist_ok=True)
        args.proposals.write_text(patch, encoding="utf-8")
        cases = sorted({ln[len("+++ b/"):].strip() for ln in patch.splitlines() if ln.startswith("+++ b/")})
        print(f"  REVIEW the revision changes how {len(cases)} golden case(s) are judged; proposed expectations "
              f"({PROPOSER} testee's answers) in {args.proposals}:")
        print(patch, end="")
        print(f"  accept with `git apply {args.proposals}` (or edit the cases), then run `make revision` again")
        return 1
    print("  ok   expectations: every golden case is judged as its .expect.yaml says")
    if not args.no_conformance and not _step("make conformance", [*make, "conformance"]):
        return 1
    print("review `git diff` (spec, generated/, conformance/report.json), then commit:\n"
          "  git add spec generated conformance && git commit\n"
          "and run `make test` (`make breaking BASE=origin/main` classifies the revision)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
