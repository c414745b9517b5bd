"""python -m conformance.runner [--binding NAME]... [--fix] [--report PATH]

Runs every golden case against every binding's testee, prints the matrix
binding x case group, writes conformance/report.json, and fails on an
unlisted failure, a listed case that passes, or a listed case that fails
with a different message.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .run import ROOT, main_run


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="conformance.runner")
    ap.add_argument("--binding", action="append", help="run only this binding (repeatable)")
    ap.add_argument("--bindings", type=Path, default=ROOT / "bindings.yaml", help="bindings file")
    ap.add_argument("--golden", type=Path, default=ROOT / "golden")
    ap.add_argument("--failures", type=Path, default=ROOT / "failures")
    ap.add_argument("--report", type=Path,
                    help="write the report here (default: conformance/report.json, on a full run only)")
    ap.add_argument("--case", action="append", help="run only cases whose name starts with this")
    ap.add_argument("--fix", action="store_true", help="rewrite the failure lists to the current result")
    ap.add_argument("--python-path", help="PYTHONPATH for the python testee (test a scratch build)")
    return main_run(ap.parse_args(argv))


if __name__ == "__main__":
    sys.exit(main())
