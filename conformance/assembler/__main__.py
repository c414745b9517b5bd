"""python -m conformance.assembler [--check]: (re)assemble every golden case."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from . import AsmError, assemble

GOLDEN = Path(__file__).resolve().parents[1] / "golden"


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="conformance.assembler")
    ap.add_argument("--check", action="store_true", help="fail when a committed .cbf differs")
    ap.add_argument("--dir", type=Path, default=GOLDEN)
    ap.add_argument("--spec", type=Path, default=None, help="the format spec (default: spec/cbf.yaml)")
    args = ap.parse_args(argv)
    stale = 0
    for src in sorted(args.dir.glob("*.hex")):
        try:
            data = assemble(src, args.spec)
        except AsmError as exc:
            print(exc, file=sys.stderr)
            return 2
        dst = src.with_suffix(".cbf")
        if args.check:
            if not dst.exists() or dst.read_bytes() != data:
                print(f"{dst}: stale (re-run python -m conformance.assembler)", file=sys.stderr)
                stale += 1
        elif not dst.exists() or dst.read_bytes() != data:
            dst.write_bytes(data)
            print(f"wrote {dst} ({len(data)} bytes)")
    return 1 if stale else 0


if __name__ == "__main__":
    sys.exit(main())
