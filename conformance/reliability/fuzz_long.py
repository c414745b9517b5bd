"""python -m conformance.reliability.fuzz_long [--runs N] [--jobs J] [--seconds S] [--max-len L]

The long libFuzzer run of the C harness (generated/c/cbf_fuzz.c, built by
`make c-build` with ASan and UBSan): J processes share N executions (or run
for S seconds each), seeded with the golden files. The executions, the time
and the crashes (artifacts left by libFuzzer) go into the "fuzz" part of
conformance/reliability.json. Exit 1 when a worker crashed or found a
sanitizer report.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import time
from typing import Any

from conformance.runner.run import ROOT

REPO = ROOT.parent
OUT = REPO / "build" / "fuzz-long"
FUZZER = REPO / "build" / "c" / "cbf_fuzz"
RESULTS = ROOT / "reliability.json"
STAT = re.compile(r"stat::number_of_executed_units:\s*(\d+)")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="conformance.reliability.fuzz_long")
    ap.add_argument("--runs", type=int, default=10_000_000, help="executions in all (default 10 M)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--seconds", type=int, default=0, help="stop each worker after this long (0: no limit)")
    ap.add_argument("--max-len", type=int, default=1024)
    args = ap.parse_args(argv)
    if not FUZZER.exists():
        print(f"fuzz-long: {FUZZER.relative_to(REPO)} is missing: run make c-build", file=sys.stderr)
        return 2
    shutil.rmtree(OUT, ignore_errors=True)
    seeds = OUT / "seeds"
    seeds.mkdir(parents=True)
    for p in sorted((ROOT / "golden").glob("*.cbf")):
        if p.stat().st_size <= args.max_len * 4:
            shutil.copy(p, seeds / p.name)
    procs = []
    start = time.monotonic()
    for j in range(args.jobs):
        corpus = OUT / f"corpus-{j}"
        corpus.mkdir()
        cmd = [str(FUZZER), f"-runs={args.runs // args.jobs}", f"-max_len={args.max_len}", "-timeout=10",
               "-rss_limit_mb=2048", "-print_final_stats=1", f"-seed={1000 + j}",
               f"-artifact_prefix={OUT}/crash-{j}-", str(corpus), str(seeds)]
        if args.seconds:
            cmd.insert(1, f"-max_total_time={args.seconds}")
        log = (OUT / f"worker-{j}.log").open("w")
        procs.append((subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT), log))
    codes = []
    for proc, log in procs:
        codes.append(proc.wait())
        log.close()
    seconds = time.monotonic() - start
    executed = 0
    for j in range(args.jobs):
        found = STAT.findall((OUT / f"worker-{j}.log").read_text(errors="replace"))
        executed += int(found[-1]) if found else 0
    crashes = sorted(p.name for p in OUT.glob("crash-*"))
    entry: dict[str, Any] = {"executions": executed, "seconds": round(seconds, 1), "crashes": len(crashes),
                             "workers": args.jobs, "max_len": args.max_len, "exit_codes": codes,
                             "sanitizers": "address,undefined", "target_executions": args.runs}
    data: dict[str, Any] = json.loads(RESULTS.read_text(encoding="utf-8")) if RESULTS.exists() else {}
    data.setdefault("fuzz", {})["c-libfuzzer"] = entry
    tmp = RESULTS.with_suffix(".tmp")
    tmp.write_text(json.dumps(data, indent=1, sort_keys=True) + "\n", encoding="utf-8")
    os.replace(tmp, RESULTS)
    print(f"fuzz-long: {executed} executions in {seconds:.0f} s by {args.jobs} worker(s), {len(crashes)} crash(es)"
          f"{': ' + ', '.join(crashes) if crashes else ''}; logs in {OUT.relative_to(REPO)}")
    return 1 if crashes or any(c != 0 for c in codes) else 0


if __name__ == "__main__":
    sys.exit(main())
