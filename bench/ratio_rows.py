"""Bench rows of issue 32, each a ratio of two commands timed in the same run (CPU seconds of the
child processes, alternating, medians):

- SARIF against text: `cbf validate --format sarif --max-findings 0` of a file with 65,536 findings
  (the 65,535-record file with every record's sequence number off by one, so its file checksum
  fails too) against `--format text` of the same file;
- `cbfgen diff OLD NEW` of the spec and the spec every revision fixture of tests/revisions/ revises
  (one on top of the other), against `cbfgen --check-spec` of NEW alone (loading one spec is the
  least a diff of two does).
"""

from __future__ import annotations

import statistics
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

REPO = Path(__file__).resolve().parents[1]


def _cpu(argv: list[str], ok: tuple[int, ...], **kw: Any) -> float:
    import resource

    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    res = subprocess.run(argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, **kw)
    assert res.returncode in ok, (argv, res.returncode, res.stderr[-2000:])
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def _pair(a: list[str], b: list[str], ok: tuple[int, ...], reps: int, **kw: Any) -> dict[str, float]:
    ta, tb = [], []
    _cpu(a, ok, **kw)  # untimed: the page cache
    for _ in range(reps):
        ta.append(_cpu(a, ok, **kw))
        tb.append(_cpu(b, ok, **kw))
    ma, mb = statistics.median(ta), statistics.median(tb)
    return {"a_cpu_s": ma, "b_cpu_s": mb, "ratio": ma / mb}


def many_findings(big: Path, out: Path) -> int:
    """``big`` with every record's sequence number off by one (and so its file checksum wrong),
    written to ``out``; returns how many findings `cbf.validate` gives for it."""
    import cbf
    from cbf import tables as T
    from cbf.codec import frame

    data = bytearray(big.read_bytes())
    offsets, _ = frame(bytes(data))
    seq = T.RECORD_BY_ROLE["sequence"]
    for off in offsets:
        at = off + seq.offset
        value = (int.from_bytes(data[at:at + seq.size], "little" if T.BO == "<" else "big") + 1) & T.SEQ_MASK
        data[at:at + seq.size] = value.to_bytes(seq.size, "little" if T.BO == "<" else "big")
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_bytes(bytes(data))
    return len(cbf.validate(bytes(data)))


def sarif_rows(prefix: list[str], env: dict[str, str], big: Path, work: Path, reps: int) -> dict[str, Any]:
    path = work / "many_findings.cbf"
    n = many_findings(big, path)
    base = [*prefix, "validate", "--max-findings", "0"]
    got = _pair([*base, "--format", "sarif", str(path)], [*base, "--format", "text", str(path)], (1,), reps, env=env)
    return {f"{n:,} findings": got}


def spec_diff_rows(work: Path, env: dict[str, str], reps: int) -> dict[str, Any]:
    sys.path.insert(0, str(REPO / "tests"))
    try:
        from revisions import drill  # type: ignore[import-not-found]
    finally:
        sys.path.remove(str(REPO / "tests"))
    old = REPO / "spec" / "cbf.yaml"
    new = old
    for fx_path in drill.fixtures():
        try:
            fx = drill.load_fixture(fx_path, drill.read_spec(new))
        except drill.FixtureUnmet:  # the fixtures before it already hold what it adds
            continue
        new = drill.revised_spec(fx, new, work / fx.name)
    py = sys.executable
    t0 = time.perf_counter()
    got = _pair([py, "-m", "cbfgen", "diff", str(old), str(new)],
                [py, "-m", "cbfgen", "--check-spec", "--spec", str(new)], (0, 1, 3), reps, env=env, cwd=REPO)
    got["wall_s"] = time.perf_counter() - t0
    return {f"every fixture ({len(drill.fixtures())})": got}
