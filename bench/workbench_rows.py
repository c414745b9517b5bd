"""The workbench page's rows of issue 34 (point 6), measured on the page itself:

- its time to first findings for a file in headless Chromium: choosing the file (Playwright's
  setInputFiles) until the page shows what cbf-c says of it (verdict, findings, records: the page's
  `done` mark), as tests/workbench/drive.mjs times it for the browser test. The page's first check
  also compiles the inlined module (once a page); the next ones are reported apart. Files alternate
  with a small one, so that every choice is a change;
- the page's size gzipped (level 9): the engine, the page's script, its data and style, all of it
  (goal under 150 KB; tests/test_workbench_page.py holds the same bound).

The page is built as mk/workbench.mk builds it (cbfgen.emit.docs.workbench, build/wasm/cbf-c.wasm).
"""

from __future__ import annotations

import gzip
import json
import os
import shutil
import statistics
import subprocess
import sys
from pathlib import Path
from typing import Any

REPO = Path(__file__).resolve().parents[1]
WASM = REPO / "build" / "wasm" / "cbf-c.wasm"
DRIVER = REPO / "tests" / "workbench" / "drive.mjs"
GZIP_GOAL = 150 * 1024  # issue 34, point 6
SMALL = REPO / "conformance" / "golden" / "valid.v3.small.cbf"


def workbench_rows(big: Path, work: Path, reps: int) -> dict[str, Any]:
    """The page's gzipped size and its time to first findings for ``big`` (first and then ``reps``
    more), or {"skipped": why} when Chromium or playwright-core is missing."""
    if shutil.which("chromium") is None and not os.environ.get("CBF_CHROMIUM"):
        return {"skipped": "no chromium"}
    if not (REPO / "node_modules" / "playwright-core").is_dir():
        return {"skipped": "no playwright-core (npm ci)"}
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(REPO / "generator"), str(REPO / "generated" / "python")]))
    subprocess.run([sys.executable, "-m", "cbfgen.emit.docs.workbench", "--spec", str(REPO / "spec" / "cbf.yaml"),
                    "--wasm", str(WASM), "--out", str(work)], check=True, capture_output=True, env=env, cwd=REPO)
    page = work / "workbench.html"
    size = len(gzip.compress(page.read_bytes(), 9))
    feed = [[str(big), "default"]]
    for _ in range(reps):
        feed += [[str(SMALL), "default"], [str(big), "default"]]
    jobs = work / "jobs.json"
    jobs.write_text(json.dumps({"files": feed}), encoding="utf-8")
    run = subprocess.run(["node", str(DRIVER), str(page), str(work), str(jobs)], capture_output=True, text=True,
                         check=True, cwd=REPO, timeout=600)
    got = json.loads(run.stdout.strip().splitlines()[-1])
    big_ms = [r["ms"] / 1000 for r in got["results"] if r["path"] == str(big)]
    return {"gzip_bytes": size, "page_bytes": page.stat().st_size, "first_s": big_ms[0],
            "next_s": statistics.median(big_ms[1:]), "next_min_s": min(big_ms[1:]), "next_max_s": max(big_ms[1:]),
            "runs": len(big_ms)}
