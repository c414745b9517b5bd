"""python -m conformance.runner [--binding NAME]... [--fix] [--report PATH]
cbf-conformance --testee "CMD ARGS" [--failure-list FILE] [--junit FILE] [--json]

Runs every golden case against every binding's testee (or against one outside
testee that speaks PROTOCOL.md), prints the matrix binding x case group, writes
conformance/report.json on a full in-repository run, and fails on an unlisted
failure, a listed case that passes, or a listed case that fails with a different
message. Exit 0 conformant, 1 failures, 2 bad usage.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .run import DEFAULT_GOLDEN, ROOT, TIMEOUT, main_run


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="cbf-conformance", description="Run the CBF golden cases against testees.")
    ap.add_argument("--testee", help="run this one testee command (split like a shell) instead of bindings.yaml")
    ap.add_argument("--name", default="testee", help="the --testee's name in reports (default: %(default)s)")
    ap.add_argument("--failure-list", type=Path, help="the --testee's known failures: `case message` lines")
    ap.add_argument("--junit", type=Path, help="also write JUnit XML here")
    ap.add_argument("--json", action="store_true", help="print the report as JSON on stdout (the table to stderr)")
    ap.add_argument("--timeout", type=float, default=TIMEOUT, help="seconds per request (default: %(default)s)")
    ap.add_argument("--binding", action="append", help="run only this binding (repeatable)")
    ap.add_argument("--bindings", type=Path, default=ROOT / "bindings.yaml", help="bindings file")
    ap.add_argument("--golden", type=Path, default=DEFAULT_GOLDEN, help="golden cases (default: the shipped ones)")
    ap.add_argument("--failures", type=Path, default=ROOT / "failures")
    ap.add_argument("--report", type=Path,
                    help="write the report here (default: conformance/report.json, on a full run only)")
    ap.add_argument("--case", action="append", help="run only cases whose name starts with this")
    ap.add_argument("--fix", action="store_true", help="rewrite the failure lists to the current result")
    ap.add_argument("--python-path", help="PYTHONPATH for the python testee (test a scratch build)")
    args = ap.parse_args(argv)
    if args.testee is None and not args.bindings.exists():
        ap.error("--testee is required outside the repository (no bindings file)")
    if args.failure_list is not None and args.testee is None:
        ap.error("--failure-list goes with --testee")
    return main_run(args)


if __name__ == "__main__":
    sys.exit(main())
