"""The c-wasm row of issue 34 (point 6): `cbf-c validate` of the 65,535-record file as the C engine
built for wasm32-wasi (build/wasm/cbf-c.wasm, mk/wasm.mk) against the same engine built natively
(build/c/cbf-c), in one run, alternating in blocks, wall seconds, medians:

- native: the cbf-c process (fork, exec, read, validate, print), timed from here;
- wasm: a fresh instance of cbf-c.wasm under node's node:wasi, the module compiled once before
  (bench/wasm_time.mjs), as the workbench page runs it; node's own start-up is not counted (a page
  pays it never, a WASI command user once per process), and is reported apart with the compile.

Both must exit alike. `make bench` builds both (mk/wasm.mk); a missing one stops the bench.
"""

from __future__ import annotations

import json
import statistics
import subprocess
import time
from pathlib import Path
from typing import Any

REPO = Path(__file__).resolve().parents[1]
WASM = REPO / "build" / "wasm" / "cbf-c.wasm"
NATIVE = REPO / "build" / "c" / "cbf-c"
TIMER = REPO / "bench" / "wasm_time.mjs"
NODE = ["node", "--disable-warning=ExperimentalWarning"]


def _native(args: list[str], reps: int) -> tuple[list[float], set[int]]:
    times, status = [], set()
    for _ in range(reps):
        t0 = time.perf_counter()
        res = subprocess.run([str(NATIVE), *args], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        times.append(time.perf_counter() - t0)
        status.add(res.returncode)
    return times, status


def wasm_rows(big: Path, reps: int, blocks: int = 5) -> dict[str, Any]:
    for p in (WASM, NATIVE):
        if not p.exists():  # a row that cannot run is a failure, not a missing line (make bench builds both)
            raise FileNotFoundError(f"{p.relative_to(REPO)} is not built: run make wasm-build build/c/cbf-c")
    args = ["validate", str(big)]
    _native(args, 3)  # untimed: the page cache
    native: list[float] = []
    wasm: list[float] = []
    compiles: list[float] = []
    status: set[int] = set()
    for _ in range(blocks):
        t, s = _native(args, reps)
        native += t
        status |= s
        timer = [*NODE, "--expose-gc", str(TIMER), str(WASM), str(reps), *args]
        res = json.loads(subprocess.run(timer, capture_output=True, text=True, check=True).stdout)
        wasm += res["wall_s"]
        compiles.append(res["compile_wall_s"])
        status |= set(res["status"])
    assert len(status) == 1, f"cbf-c and cbf-c.wasm exit differently on {big}: {sorted(status)}"
    node_start = [_wall([*NODE, "-e", "0"]) for _ in range(3)]
    n, w = statistics.median(native), statistics.median(wasm)
    return {"native_s": n, "wasm_s": w, "ratio": w / n, "runs": len(wasm),
            "compile_s": statistics.median(compiles), "node_start_s": statistics.median(node_start),
            "wasm_bytes": WASM.stat().st_size}


def _wall(argv: list[str]) -> float:
    t0 = time.perf_counter()
    subprocess.run(argv, check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - t0
