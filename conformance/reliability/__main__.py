"""python -m conformance.reliability [--quick] [--files N] [--seed S] [--out PATH]

Runs the reliability campaign (issue #7) and writes its results as JSON:
1. corruption detection: every bit flip, every byte set to 0x00 and 0xFF,
   every truncation of each valid golden file, through every validating
   binding; each must report an error. Any miss fails the run.
2. blind spots: adjacent transpositions, swapped records and +-1 compensating
   byte pairs, under each profile, and again under a CRC-32 file checksum
   (a spec variant generated into build/reliability/).
3. differential: N seeded mutants through every built binding; any
   disagreement with the Python codec fails the run and is kept under
   conformance/regressions/.

--quick (CI) uses the golden files up to 700 bytes, fewer compensating pairs
and 1,000 differential files, and writes build/reliability/reliability.json;
the full run writes conformance/reliability.json (committed, deterministic:
no times, seeded). Fuzzing results (make fuzz-long) are kept from the file.
Exit codes: 0 all targets met, 1 a miss or a disagreement, 2 bad usage.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from pathlib import Path
from typing import Any

from conformance.runner.run import ROOT
from conformance.runner.testee import TesteeError

from .campaign import (
    REPO,
    SAMPLE_ABOVE,
    Base,
    Pool,
    Scratch,
    blind_spots,
    built_bindings,
    check_kinds,
    crc_variant,
    detection,
    differential,
    profile_bases,
    reencode,
    sampled,
    valid_bases,
    validating,
)
from .mutate import Framing

FULL_OUT = ROOT / "reliability.json"
QUICK_OUT = REPO / "build" / "reliability" / "reliability.json"
REGRESSIONS = ROOT / "regressions"
# The share of its mutants the Python codec answers in --quick (seeded: the same ones every run). A
# twenty-fifth: about 3,500 corruption mutants over every small base and class; all of them were most of
# reliability-quick's CPU (numpy kernels, ~2.7 ms a small file). The full campaign answers every mutant.
QUICK_PYTHON_SHARE = 0.04


def shown(path: Path) -> str:
    """path as the report names it: relative to the repository when inside it (--out may be anywhere)."""
    full = path.resolve()
    return str(full.relative_to(REPO) if full.is_relative_to(REPO) else full)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="conformance.reliability")
    ap.add_argument("--quick", action="store_true", help="the CI subset")
    ap.add_argument("--files", type=int, help="differential files (default 10,000; 1,000 with --quick)")
    ap.add_argument("--seed", type=int, default=20261122)
    ap.add_argument("--out", type=Path)
    args = ap.parse_args(argv)
    files = args.files if args.files is not None else (1000 if args.quick else 10000)
    out_path: Path = args.out or (QUICK_OUT if args.quick else FULL_OUT)
    framing = Framing.from_spec()
    # --quick: a golden file with the same bytes as an earlier one (valid.v3.small,
    # valid.v3.part_and_cutters and check.machine_limits.within are one file) is mutated once
    bases = valid_bases(700, distinct=True) if args.quick else valid_bases()
    pools = {b.name: Pool(b) for b in built_bindings()}
    if "python" not in pools:
        print("reliability: the python testee is not available", file=sys.stderr)
        return 2
    scratch = Scratch()
    problems: list[str] = []
    result: dict[str, Any] = {"seed": args.seed, "mode": "quick" if args.quick else "full",
                              "bases": sorted({f"{b.name} ({b.profile})" for b in bases})}
    try:
        validators = {n for n, p in pools.items() if validating(p, ROOT / "golden" / f"{bases[0].name}.cbf")}
        samples = sampled(bases, framing, args.seed)
        result["sampled"] = {name: len(offs) for name, offs in samples.items()}
        result["corruption"] = {}
        for name in sorted(validators):
            # --quick: the Python codec's validator (numpy kernels: ~2.5 ms a small file, 7x the
            # other bindings' cost) answers a seeded QUICK_PYTHON_SHARE of the mutants; the full campaign all
            share = QUICK_PYTHON_SHARE if args.quick and name == "python" else 1.0
            res = detection(pools[name], bases, scratch, samples, share, args.seed)
            result["corruption"][name] = res
            for cls, row in res.items():
                print(f"reliability: corruption {name:8} {cls:11} {row['detected']}/{row['trials']} detected")
                problems += [f"{name}: {cls} not detected in {m['file']} at {m['offset']} ({m['detail']})"
                             for m in row["misses"]]

        pairs = 100 if args.quick else 1000
        # --quick: the blind spots are measured, not judged (the full campaign publishes them), and
        # both pools are the Python codec: it answers a seeded QUICK_PYTHON_SHARE of them, as for corruption
        share = QUICK_PYTHON_SHARE if args.quick else 1.0
        py = pools["python"]
        result["blind_spots"] = {}
        crc = Pool(crc_variant(REPO / "build" / "reliability"))
        try:
            small = [b for b in bases if len(b.data) <= SAMPLE_ABOVE]
            for profile in ("default", "implib"):
                # every small base, written again by the codec under this profile
                own = reencode(py, [Base(b.name, b.data, profile) for b in small], scratch)
                pb = profile_bases(py, own, profile, scratch)
                result["blind_spots"][f"byte_sum/{profile}"] = blind_spots(py, pb, profile, scratch, framing, pairs,
                                                                           args.seed, share)
                cb = profile_bases(crc, reencode(crc, pb, scratch), profile, scratch)
                result["blind_spots"][f"crc32/{profile}"] = blind_spots(crc, cb, profile, scratch, framing, pairs,
                                                                        args.seed, share)
        finally:
            crc.close()
        for variant, classes in result["blind_spots"].items():
            for cls, row in classes.items():
                rate = 100.0 * row["detected"] / row["trials"] if row["trials"] else 0.0
                print(f"reliability: blind spot {variant:16} {cls:17} {rate:6.2f}% of {row['trials']}")

        count, found = differential(pools, validators, files, args.seed, scratch, framing, check_kinds())
        result["differential"] = {"files": count, "seed": args.seed, "bindings": sorted(pools),
                                  "disagreements": len(found),
                                  "by_binding": {n: sum(d.binding == n for d in found) for n in sorted(pools)
                                                 if n != "python"}}
        print(f"reliability: differential {count} files x {len(pools)} bindings, {len(found)} disagreement(s)")
        if found:
            REGRESSIONS.mkdir(exist_ok=True)
        for d in found[:50]:
            stem = REGRESSIONS / f"diff-{args.seed}-{d.index}-{d.binding}"
            stem.with_suffix(".cbf").write_bytes(d.mutant.data)
            stem.with_suffix(".txt").write_text(f"{d.binding}: {d.reason}\nmutation: {d.mutant.cls} at "
                                                f"{d.mutant.offset}\n", encoding="utf-8")
            problems.append(f"{d.binding}: differential file {d.index} ({d.mutant.cls}): {d.reason}")
    finally:
        for p in pools.values():
            p.close()
        scratch.remove()

    old = _load(FULL_OUT)
    result["fuzz"] = old.get("fuzz", {})
    out_path.parent.mkdir(parents=True, exist_ok=True)
    tmp = out_path.with_suffix(".tmp")
    tmp.write_text(json.dumps(result, indent=1, sort_keys=True) + "\n", encoding="utf-8")
    os.replace(tmp, out_path)
    for line in problems[:100]:
        print(line)
    print(f"reliability: {len(problems)} problem(s); results in {shown(out_path)}")
    return 1 if problems else 0


def _load(path: Path) -> dict[str, Any]:
    try:
        data: dict[str, Any] = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
    return data


if __name__ == "__main__":
    try:
        sys.exit(main())
    except TesteeError as exc:  # a testee that exits or times out mid-campaign: a binding's bug, named on one line
        print(f"reliability: the campaign stopped: {exc}", file=sys.stderr)
        sys.exit(1)
