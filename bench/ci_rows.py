"""Bench rows for CI users (issue 27): `cbf diff` against GNU diff, and `cbf validate` on a folder
in one call against one call per file. Both are ratios; targets are reported, never enforced.

- diff: ``cbf.semdiff.diff`` of two decoded 65,535-record files (identical, and with one record
  changed), against ``diff A.cut B.cut`` (GNU diffutils, a whole process) on the CUT texts of the
  same files. The ratio is cbf's time over GNU diff's; the target is at most 3.
- validate: `cbf validate DIR` over a folder of 1,000 golden-sized files (the golden cases under
  64 KiB, copied round-robin), one process, against `cbf validate FILE` once per file. The per-file
  calls are timed on the first ``calls`` files and scaled to 1,000 (1,000 processes take minutes
  on a shared 2-core machine): the row says how many were timed.
"""

from __future__ import annotations

import shutil
import statistics
import subprocess
import time
from pathlib import Path
from typing import Any

FILES = 1000


def _median(fn: Any, reps: int) -> float:
    out = []
    for _ in range(reps):
        t = time.perf_counter()
        fn()
        out.append(time.perf_counter() - t)
    return statistics.median(out)


def _interleaved(first: Any, second: Any, reps: int) -> tuple[float, float]:
    """Medians of ``reps`` wall times of each function, the two timed in turn."""
    a: list[float] = []
    b: list[float] = []
    for _ in range(reps):
        for fn, out in ((first, a), (second, b)):
            t = time.perf_counter()
            fn()
            out.append(time.perf_counter() - t)
    return statistics.median(a), statistics.median(b)


def diff_rows(big: Path, work: Path, reps: int) -> dict[str, Any]:
    """cbf diff vs GNU diff on the 65,535-record file: identical input, and one record changed."""
    import cbf
    from cbf import semdiff
    from cbf import tables as T

    gnu = shutil.which("diff")
    if gnu is None:
        return {}
    work.mkdir(parents=True, exist_ok=True)
    model = cbf.decode(big.read_bytes())
    text = cbf.to_cut(model)
    lines = text.splitlines(keepends=True)
    # one record changed: the middle record's line replaced by the line of another record of the file
    # the first record past the middle that has a later record of its command with other values
    mid, other = next((m, k) for m in range(len(lines) // 2, len(lines)) for k in range(m + 1, min(m + 8, len(lines)))
                      if lines[k].split()[0] == lines[m].split()[0] and lines[k] != lines[m])
    changed = "".join(lines[:mid] + [lines[other]] + lines[mid + 1:])
    (work / "a.cut").write_text(text, encoding="utf-8")
    (work / "b.cut").write_text(text, encoding="utf-8")
    (work / "c.cut").write_text(changed, encoding="utf-8")
    same = cbf.decode(big.read_bytes())
    edited = cbf.from_cut(changed)
    tol = T.TOL["position_mm"]
    assert semdiff.diff(model, same, tol).equal and not semdiff.diff(model, edited, tol).equal
    out: dict[str, Any] = {}
    for name, b_model, b_cut, gnu_rc in (("identical", same, "b.cut", 0), ("one record changed", edited, "c.cut", 1)):
        def run_gnu(b_cut: str = b_cut, rc: int = gnu_rc) -> None:
            res = subprocess.run([gnu, str(work / "a.cut"), str(work / b_cut)], stdout=subprocess.DEVNULL)
            assert res.returncode == rc

        # interleaved, a repetition of each in turn: timed one after the other (all of GNU diff's, then
        # all of cbf's), a change of load on the shared machine between the halves moved the ratio
        # by 2x (bench/NOTES.md, round 6: 3.73x in one run, 0.87-1.81x in six runs of the same code)
        t_gnu, t_cbf = _interleaved(run_gnu, lambda b_model=b_model: semdiff.diff(model, b_model, tol), reps)
        out[name] = {"cbf_s": t_cbf, "gnu_diff_s": t_gnu, "ratio": t_cbf / t_gnu}
    return out


def validate_rows(prefix: list[str], env: dict[str, str], golden: Path, work: Path, calls: int) -> dict[str, Any]:
    """`cbf validate DIR` (1,000 golden-sized files) in one process against one process per file."""
    small = [p for p in sorted(golden.glob("*.cbf")) if p.stat().st_size <= 64 * 1024]
    folder = work / "validate-1000"
    shutil.rmtree(folder, ignore_errors=True)
    folder.mkdir(parents=True)
    files = []
    for k in range(FILES):
        src = small[k % len(small)]
        dst = folder / f"{k:04d}-{src.name}"
        shutil.copyfile(src, dst)
        files.append(dst)

    def one_call() -> None:
        res = subprocess.run([*prefix, "validate", str(folder)], env=env, capture_output=True)
        assert res.returncode in (0, 1, 2) and "Traceback" not in res.stderr.decode(), res.stderr

    one_call()  # untimed: the page cache
    t_one = _median(one_call, 3)
    timed = files[:calls]
    t0 = time.perf_counter()
    for f in timed:
        subprocess.run([*prefix, "validate", str(f)], env=env, capture_output=True)
    per_call = (time.perf_counter() - t0) / len(timed)
    t_many = per_call * FILES
    return {"files": FILES, "one_call_s": t_one, "per_file_calls_s": t_many, "calls_timed": len(timed),
            "ratio": t_many / t_one}
