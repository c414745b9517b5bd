"""cbf-conformance --testee "CMD ARGS" [--capabilities OPS] [--failure-list FILE [--fix]] [--junit FILE] [--json]

Runs the golden cases against a testee that speaks PROTOCOL.md, prints the matrix (case group x
pass/fail/expected failure/skip) and per capability how many cases were judged, and fails on an
unlisted failure, a listed case that passes, a listed case that fails with a different message, or
a testee judged on no case of an operation it offers (--capabilities). Exit 0 conformant, 1 failures, 2 bad usage
(a missing testee program, an unreadable failure list, a bad option: one line on stderr).

In this repository, `python -m conformance.runner` runs every binding of bindings.yaml and writes
conformance/report.json; the options for that (--binding, --bindings, --failures, --report,
--python-path) are not shown by --help, as a kit user has no use for them.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import NoReturn

from .about import version_line
from .run import DEADLINE, DEFAULT_GOLDEN, ROOT, TIMEOUT, main_run
from .testee import CAPABILITIES, MAX_ANSWER


class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> NoReturn:
        sys.stderr.write(f"{self.prog}: {' '.join(message.split())} (see {self.prog} --help)\n")
        raise SystemExit(2)


def _seconds(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number of seconds: {text!r}") from None
    if not 0 < value < float("inf"):
        raise argparse.ArgumentTypeError(f"not a positive number of seconds: {text!r}")
    return value


def parser() -> argparse.ArgumentParser:
    ap = _Parser(prog="cbf-conformance", description="Run the CBF golden cases against your reader's testee "
                 "(PROTOCOL.md, shipped in the package).",
                 epilog="Exit codes: 0 every case passes or fails as listed, 1 a case does not, 2 bad usage.")
    ap.add_argument("--version", action="version", version=version_line(),
                    help="print the kit version and the spec revision, and exit")
    ap.add_argument("--testee", help="your testee command, split like a shell command, run in this folder")
    ap.add_argument("--name", default="testee", help="the testee's name in reports (default: %(default)s)")
    ap.add_argument("--capabilities", default=",".join(CAPABILITIES), metavar="OPS",
                    help="the operations your testee offers, comma-separated (default: %(default)s): only these "
                         "are asked, and each must be answered; a decode-only reader runs with --capabilities "
                         "decode (every report names them). A run fails when its testee was judged on no case of "
                         "an operation it offers, or answered one with skipped where the failure list does not "
                         "name the case")
    ap.add_argument("--failure-list", type=Path, metavar="FILE",
                    help="your known failures, `case message` lines (# comments); the file must exist")
    ap.add_argument("--fix", action="store_true",
                    help="rewrite --failure-list FILE to this run's failures (its # comment lines are kept), "
                         "e.g. cbf-conformance --testee CMD --failure-list known.txt --fix")
    ap.add_argument("--junit", type=Path, metavar="FILE",
                    help="also write JUnit XML here (an expected failure is <skipped> with its reason)")
    ap.add_argument("--json", action="store_true", help="print the report as JSON on stdout (the table to stderr)")
    ap.add_argument("--case", action="append", metavar="PREFIX", help="run only cases whose name starts with this")
    ap.add_argument("--timeout", type=_seconds, default=TIMEOUT,
                    help=f"seconds one answer may take (default: %(default)s); after 3 timeouts in a row the "
                         f"testee's run stops. An answer line may hold {MAX_ANSWER // (1 << 20)} MiB.")
    ap.add_argument("--deadline", type=_seconds, default=DEADLINE,
                    help="seconds the whole run may take (default: %(default)s); cases left are not run, and fail")
    ap.add_argument("--golden", type=Path, default=DEFAULT_GOLDEN, help=argparse.SUPPRESS)
    # this repository's own runs (bindings.yaml, conformance/failures, report.json): hidden from --help
    ap.add_argument("--binding", action="append", help=argparse.SUPPRESS)
    ap.add_argument("--bindings", type=Path, default=ROOT / "bindings.yaml", help=argparse.SUPPRESS)
    ap.add_argument("--failures", type=Path, default=ROOT / "failures", help=argparse.SUPPRESS)
    ap.add_argument("--report", type=Path, help=argparse.SUPPRESS)
    ap.add_argument("--python-path", help=argparse.SUPPRESS)
    return ap


def main(argv: list[str] | None = None) -> int:
    ap = parser()
    try:
        args = ap.parse_args(argv)
        if args.testee is None and not args.bindings.exists():
            ap.error("--testee is required (the command that starts your testee)")
        if args.capabilities != ",".join(CAPABILITIES) and args.testee is None:
            ap.error("--capabilities goes with --testee (bindings.yaml names each binding's own)")
        if args.failure_list is not None and args.testee is None:
            ap.error("--failure-list goes with --testee")
        if args.fix and args.testee is not None and args.failure_list is None:
            ap.error("--fix rewrites the --failure-list FILE: name one")
    except SystemExit as exc:
        return exc.code if isinstance(exc.code, int) else 0
    try:
        return main_run(args)
    except KeyboardInterrupt:
        sys.stderr.write("cbf-conformance: interrupted\n")
        return 130


if __name__ == "__main__":
    sys.exit(main())
