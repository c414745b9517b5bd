"""Benchmarks: the same files, the same machine, one run, interleaved repetitions.

Rows: the Kaitai-generated Python parser (the 1x reference), the Python codec
(decode, decode + full validate, encode, CBF -> CUT, CUT -> CBF), the C codec
(decode and validate, in-process, and a plain byte sum of the same buffer as
its yardstick), `cbf validate` as a whole process, and
`make generate` without and with the ksc step; and two ratios (bench/ci_rows.py):
`cbf diff` against GNU diff, and `cbf validate` on a folder in one call against a
call per file; and two reported ratios (bench/ratio_rows.py): SARIF against text output of the
same findings, `cbfgen diff` against `cbfgen --check-spec`. A target that says NO makes `make
bench` exit 1, naming it (issue 32); `make bench` is not part of CI, whose guards are the
structural tests of `make test` (tests/test_engine_scaling.py, tests/test_engine_footprint.py).
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import time
from collections.abc import Callable
from functools import partial
from pathlib import Path
from typing import Any

REPO = Path(__file__).resolve().parents[1]
WORK = REPO / "bench" / "work"
PY = sys.executable


def _files() -> dict[str, Path]:
    """The three benchmark files, made deterministically with the codec's model API."""
    import cbf
    from cbf.layouts import Checkpoint, Endshape, Orient, Point, Speed, Startshape
    from cbf.model import Cbf, Record, new_header

    line5 = _five_axis_line("3.0")
    WORK.mkdir(parents=True, exist_ok=True)
    files = {"65535 records": REPO / "conformance" / "golden" / "big.v3.65535.cbf"}
    five = WORK / "five_axis.v2.cbf"  # v2: within the default machine (check machine_limits)
    if not five.exists():
        recs: list[Record] = [Record.of(Speed(speed=0.02)), Record.of(Orient(approach=(0.0, 0.0, 1.0))),
                              Record.of(Point(point=(0.0, 0.0, 0.0)))]
        x = 0.0
        shape = 0
        while len(recs) < 20_000:
            n = 50
            recs.append(Record.of(Startshape(name=f"S{shape % 1000}", moves=n)))
            step = 0.25 if shape % 2 == 0 else -0.25  # back and forth: within any machine's workspace
            for _ in range(n):
                recs.append(Record.of(line5((x, 0.0, 0.0), (x + step, 0.0, 0.0))))
                x += step
            recs.append(Record.of(Endshape(name=f"S{shape % 1000}", moves=n)))
            shape += 1
            if shape % 20 == 0:
                recs.append(Record.of(Checkpoint(name=f"CP{shape}", recovery_point=(x, 0.0, 0.0),
                                                 completion=min(100.0, shape / 4.0))))
        five.write_bytes(cbf.encode(Cbf(new_header("3.0", implant_descriptor="BENCH-5AX"), tuple(recs))))
    files["5-axis ~20k"] = five
    small = WORK / "small.cbf"
    if not small.exists():
        recs = [Record.of(Point(point=(0.0, 0.0, 0.0)))]
        recs += [Record.of(line5((float(i), 0.0, 0.0), (float(i + 1), 0.0, 0.0))) for i in range(29)]
        small.write_bytes(cbf.encode(Cbf(new_header("3.0", implant_descriptor="BENCH-SMALL"), tuple(recs))))
    every = WORK / "every_command.cbf"
    if not every.exists():
        every.write_bytes(_every_command_file(20_000))
    files["every command ~20k"] = every
    files["small (30)"] = small
    return files


def _five_axis_line(version: str) -> Callable[[tuple[float, ...], tuple[float, ...]], Any]:
    """The arguments of the 5-axis straight line from start to end, oriented (0, 0, 1), made by its motion role
    (a line with no through point whose layout carries more than its two ends: LINE5B on rev 03), not by its
    name: a revision may rename it (tests/revisions/rename_real.yaml)."""
    from cbf import tables as T
    from cbf.layouts import ARGS_CLASSES

    cmd, lay = next((c, lay) for c in T.COMMANDS if c.motion and c.motion["kind"] == "line"
                    and "through" not in c.motion for lay in c.layouts_for(version) if len(lay.args) > 2)
    cls = ARGS_CLASSES[(cmd.name, lay.variant)]
    motion = cmd.motion or {}
    start, end = str(motion["start"]), str(motion["end"])
    others = [f.name for f in lay.args if f.name not in (start, end)]

    def make(a: tuple[float, ...], b: tuple[float, ...]) -> Any:
        return cls(**{start: a, end: b}, **dict.fromkeys(others, (0.0, 0.0, 1.0)))

    return make


def _curve_values(cmd: Any, lay: Any) -> dict[str, Any]:
    """The arguments a circle or helix (by its motion role) needs to stay valid and end where it starts, at
    (0, 0, 1) as every other motion does: a full turn about (1, 0, 1) with the normal (0, 0, 1), a helix
    of length 0. Nothing for other commands (their plain values are valid)."""
    motion = cmd.motion or {}
    if motion.get("kind") not in ("circle", "helix"):
        return {}
    counts = {f.name: f.count for f in lay.args}

    def vec(first: float, n: int) -> tuple[float, ...]:  # (first, 0, ..., 0, 1)
        return (first, *([0.0] * (n - 2)), 1.0) if n > 1 else (1.0,)

    out: dict[str, Any] = {motion["center"]: vec(1.0, counts[motion["center"]]), motion["degrees"]: 360.0}
    if "normal" in motion:
        out[motion["normal"]] = vec(0.0, counts[motion["normal"]])
    if "length" in motion:
        out[motion["length"]] = 0.0
    return out


def _every_command_file(size: int, version_id: str | None = None) -> bytes:
    """About ``size`` records: every command of a version (default the newest writable one), read from
    the model (cbf.tables), over and over, each round in one shape. Plain values keep it valid: vectors
    (0, 0, 1) (so every motion starts where the last ended), scalars 1.0, uints 1, strings "B"; curves
    by their motion role (_curve_values)."""
    import cbf
    from cbf import tables as T
    from cbf.model import Cbf, Record, new_header

    version = (T.VERSION_BY_ID[version_id] if version_id is not None
               else max((v for v in T.VERSIONS if v.writable), key=lambda v: (v.major, v.minor or 0)))
    plain: list[Record] = []
    shape: tuple[T.CommandInfo, T.CommandInfo] | None = None
    starts = [c for c in T.COMMANDS if c.shape and c.shape["kind"] == "start" and c.layouts_for(version.id)]
    ends = [c for c in T.COMMANDS if c.shape and c.shape["kind"] == "end" and c.layouts_for(version.id)]
    if starts and ends:
        shape = (starts[0], ends[0])
    for cmd in T.COMMANDS:
        lay = next((x for x in cmd.layouts_for(version.id) if x.accepted_under("default")), None)
        if lay is None or cmd.shape:
            continue
        values: dict[str, Any] = {}
        for f in lay.args:
            if f.kind == "float":
                values[f.name] = tuple([0.0] * (f.count - 1) + [1.0]) if f.count > 1 else 1.0
            elif f.kind in ("uint", "sint"):  # any integer the registry carries, signed or not
                values[f.name] = 1
            elif f.kind == "string":
                values[f.name] = "B"
            else:
                values[f.name] = bytes(f.size)
        values.update(_curve_values(cmd, lay))
        plain.append(Record(code=cmd.code, raw_args=lay.struct.pack(*_flat(lay, values))))
    moves = sum(1 for r in plain if T.BY_CODE[r.code].motion)
    recs: list[Record] = []
    while len(recs) < size:
        if shape is None:
            recs += plain
            continue
        for cmd, at in ((shape[0], len(recs)), (shape[1], None)):
            lay = next(x for x in cmd.layouts_for(version.id) if x.accepted_under("default"))
            sh = cmd.shape or {}
            values = {f.name: ("B" if f.kind == "string" else bytes(f.size) if f.kind == "bytes" else 0.0
                               if f.kind == "float" else 0) for f in lay.args}
            values[sh["count"]] = moves
            rec = Record(code=cmd.code, raw_args=lay.struct.pack(*_flat(lay, values)))
            if at is not None:
                recs.append(rec)
                recs += plain
            else:
                recs.append(rec)
    header = new_header(f"{version.major}.{version.minor or 0}", implant_descriptor="BENCH-EVERY")
    return cbf.encode(Cbf(header, tuple(recs)))


def _flat(lay: Any, values: dict[str, Any]) -> list[Any]:
    out: list[Any] = []
    for f in lay.args:
        v = values[f.name]
        if f.kind == "string":
            out.append(v.encode("ascii"))
        elif f.kind == "float" and f.count > 1:
            out.extend(v)
        else:
            out.append(v)
    return out


def _kaitai() -> Any | None:
    path = REPO / "generated" / "kaitai" / "python"
    if not (path / "cbf_kaitai" / "cbf.py").exists():
        return None
    sys.path.insert(0, str(path))
    try:
        mod = _load_kaitai(path)
    finally:
        sys.path.remove(str(path))
    return mod


def _load_kaitai(path: Path) -> Any:
    import importlib.util

    spec = importlib.util.spec_from_file_location("cbf_kaitai_parser", path / "cbf_kaitai" / "cbf.py")
    assert spec and spec.loader
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod.Cbf


CLI_NUMPY_RATIO = 2.0  # issue 32, point 4
GZIP_GOAL = 150 * 1024  # issue 34, point 6: the workbench page's code, gzipped (bench/workbench_rows.py)
WASM_RATIO_TARGET = 2.0  # issue 34, point 6: cbf-c.wasm validate within 2x of native cbf-c (bench/wasm_rows.py)
MEMORY_BOUND = 4  # issue 8: Python peak of decode + validate, times the file (tests/test_engine_footprint.py too)
C_BYTESUM = "C byte sum (baseline)"
C_RATIO_TARGET = 2.5  # issue 17: C validate within 2.5x of a plain one-pass byte sum
C_RATIO_FILES = ("65535 records", "5-axis ~20k")  # both file shapes; the small file is too short to time


def _c_driver() -> Path | None:
    out = REPO / "build" / "bench" / "c_bench"
    src = REPO / "bench" / "c_bench.c"
    hdr = REPO / "generated" / "c" / "cbf.h"
    if not hdr.exists():
        return None
    if not out.exists() or out.stat().st_mtime < max(src.stat().st_mtime, hdr.stat().st_mtime):
        out.parent.mkdir(parents=True, exist_ok=True)
        subprocess.run(["gcc", "-std=c99", "-O2", "-I", str(hdr.parent), "-o", str(out), str(src), "-lm"], check=True)
    return out


def _time(fn: Callable[..., Any], *args: Any) -> float:
    """CPU seconds of ``fn(*args)`` in this process (issue 32: on a shared machine the wall time of
    an in-process row follows the other jobs' load; its CPU time much less)."""
    t0 = time.process_time()
    fn(*args)
    return time.process_time() - t0


def _child_cpu(argv: list[str], **kw: Any) -> tuple[float, float]:
    """(wall, CPU) seconds of one child process: user + system time of the process and its own
    children (resource.getrusage), which a shared machine's load changes much less than wall time."""
    import resource

    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run(argv, capture_output=True, check=True, **kw)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def _kaitai_parse(kaitai: Any, data: bytes) -> int:
    return len(kaitai.from_bytes(data).records)


def _decode(data: bytes) -> int:
    import cbf

    return len(cbf.decode(data).records)


def _decode_validate(data: bytes) -> Any:
    import cbf

    return cbf.validate(cbf.decode(data))


def _to_cut(data: bytes) -> str:
    import cbf

    return str(cbf.to_cut(cbf.decode(data)))


def _from_cut(text: str) -> bytes:
    import cbf

    return bytes(cbf.encode(cbf.from_cut(text)))


def _stats(samples: list[float]) -> dict[str, float]:
    return {"median": statistics.median(samples), "min": min(samples), "max": max(samples), "n": len(samples)}


# Peak RSS of decode + validate (issue 8's bound, MEMORY_BOUND x the file), in ONE process: VmHWM after
# the peak was reset, minus VmRSS at the reset. It was the VmHWM of one interpreter that validated minus
# that of another that only imported, which moved by about 2x the file with the state of the tree
# (bench/NOTES.md, "Peak RSS, round 5"): without __pycache__ the second one's peak held the compile of
# cbf's modules (~3 MB), with it the first one's held numpy's machine code paged in by a first
# validation (~2.2 MB, file-backed) and cbf.layouts' import; neither grows with the file. So a small
# golden file is validated first (lazy imports, code pages, caches: reported apart as the one-off),
# free heap pages are given back (malloc_trim: the check pays for those it touches again), then the
# peak is reset (Linux >= 4.0: "5" to /proc/self/clear_refs) and the file checked.
# Not ru_maxrss: Linux carries it over exec from the forking parent.
RSS_PROBE = """
import ctypes, gc, sys, numpy, cbf, cbf.records, cbf.validation
def kb(key):
    return next(int(x.split()[1]) for x in open('/proc/self/status') if x.startswith(key + ':'))
start = kb('VmRSS')
cbf.validate(cbf.decode(open(sys.argv[2], 'rb').read()))
warm = kb('VmRSS')
data = open(sys.argv[1], 'rb').read()
gc.collect()
try:  # glibc: free heap pages (an import's compile leaves some) back to the system, so that the check
    ctypes.CDLL(None).malloc_trim(0)  # pays for what it reuses of them
except (OSError, AttributeError):
    pass
with open('/proc/self/clear_refs', 'w') as f:
    f.write('5')
before = kb('VmRSS')
found = cbf.validate(cbf.decode(data))
print(kb('VmHWM') - before, warm - start, len(found))
"""
WARM_FILE = REPO / "conformance" / "golden" / "valid.v3.small.cbf"


def rss_decode_validate(path: Path, pkg: Path = REPO / "generated" / "python") -> tuple[int, int]:
    """(peak RSS of decode + validate of ``path`` above the process just before it, the one-off RSS of a
    first validation after import), bytes, in a fresh interpreter importing cbf from ``pkg``."""
    env = dict(os.environ, PYTHONPATH=str(pkg))
    out = subprocess.run([PY, "-c", RSS_PROBE, str(path), str(WARM_FILE)], env=env, capture_output=True, text=True,
                         check=True).stdout.split()
    return int(out[0]) * 1024, int(out[1]) * 1024


USER_VENV = WORK / "user-venv"


def _user_env() -> dict[str, str]:
    """A user's environment: none of the PYTHON* variables make or the dev shell set."""
    return {k: v for k, v in os.environ.items() if not k.startswith("PYTHON")}


def _user_cbf(small: Path) -> tuple[list[str], dict[str, str], str]:
    """The command that validates ``small`` as a user runs it, its environment, and how it was
    installed. The wheel is built from a copy of generated/python (the tree stays clean) and
    installed, with numpy at the pin of .ci/constraints.txt, into a new venv under bench/work.
    When that cannot be done (no network, no cached numpy wheel), the dev venv's interpreter
    runs it isolated (-I: no PYTHONPATH, no user site; its editable-install finders still load)."""
    env = _user_env()
    try:
        src, dist = WORK / "wheel-src", WORK / "dist"
        for d in (src, dist, USER_VENV):
            shutil.rmtree(d, ignore_errors=True)
        shutil.copytree(REPO / "generated" / "python", src, ignore=shutil.ignore_patterns("__pycache__"))
        subprocess.run([PY, "-m", "build", "--no-isolation", "--wheel", "--outdir", str(dist), str(src)],
                       capture_output=True, check=True)
        wheel = next(dist.glob("cbf-*.whl"))
        subprocess.run([PY, "-m", "venv", "--without-pip", str(USER_VENV)], capture_output=True, check=True)
        subprocess.run([PY, "-m", "pip", "--python", str(USER_VENV / "bin" / "python"), "install", "-q",
                        "-c", str(REPO / ".ci" / "constraints.txt"), str(wheel)], env=env, capture_output=True,
                       check=True)
        return [str(USER_VENV / "bin" / "cbf"), "validate", str(small)], env, "wheel + numpy in a clean venv"
    except (OSError, subprocess.CalledProcessError, StopIteration):
        code = (f"import sys; sys.path.insert(0, {str(REPO / 'generated' / 'python')!r}); "
                "from cbf.cli import main; sys.exit(main())")
        return [PY, "-I", "-c", code, "validate", str(small)], env, "dev venv, python -I (clean install failed)"


def run(reps: int) -> dict[str, Any]:
    import cbf

    files = _files()
    kaitai = _kaitai()
    rows: dict[str, dict[str, list[float]]] = {}

    def add(row: str, name: str, t: float) -> None:
        rows.setdefault(row, {}).setdefault(name, []).append(t)

    data = {name: p.read_bytes() for name, p in files.items()}
    models = {name: cbf.decode(d) for name, d in data.items()}
    cuts = {name: cbf.to_cut(m) for name, m in models.items()}
    for _ in range(reps):  # interleaved: every row once per repetition
        for name, d in data.items():
            if kaitai is not None:
                add("Kaitai Python parse (1x)", name, _time(_kaitai_parse, kaitai, d))
            add("Python decode", name, _time(_decode, d))
            add("Python decode + full validate", name, _time(_decode_validate, d))
            add("Python encode (stored values)", name, _time(partial(cbf.encode, keep_stored=True), models[name]))
            add("Python CBF -> CUT", name, _time(_to_cut, d))
            add("Python CUT -> CBF", name, _time(_from_cut, cuts[name]))
    sizes = {n: {"bytes": len(d), "records": len(models[n].records)} for n, d in data.items()}
    result: dict[str, Any] = {"rows": {}, "reps": reps, "files": sizes}
    for row, per in rows.items():
        result["rows"][row] = {n: _stats(s) for n, s in per.items()}
    driver = _c_driver()
    if driver is not None:
        for name, p in files.items():
            res = json.loads(subprocess.run([str(driver), str(p), str(max(reps, 5))], capture_output=True, text=True,
                                            check=True).stdout)
            for op, row in (("decode", "C decode"), ("validate", "C validate"), ("bytesum", C_BYTESUM)):
                st = _stats(res[op])
                st["MB/s"] = res["bytes"] / st["median"] / 1e6
                st["records/s"] = res["records"] / st["median"]
                result["rows"].setdefault(row, {})[name] = st
    # As a user runs it: the `cbf` command of the built wheel, installed with numpy into a clean
    # venv (no editable-install finders, no PYTHONPATH); pip compiled the modules to bytecode.
    argv, env, how = _user_cbf(files["small (30)"])
    # issue 32: the same interpreter importing numpy alone, alternating with the command: what the
    # command does beyond the interpreter and numpy is the toolkit's cost
    numpy_argv = [argv[0].rsplit("/", 1)[0] + "/python" if how.startswith("wheel") else PY, "-c", "import numpy"]
    subprocess.run(argv, env=env, capture_output=True, check=True)  # one untimed run (page cache)
    cli, numpy_only = [], []
    for _ in range(max(reps, 5)):
        cli.append(_child_cpu(argv, env=env))
        numpy_only.append(_child_cpu(numpy_argv, env=env))
    result["rows"]["cbf validate (process, small)"] = {"small (30)": _stats([w for w, _ in cli])}
    result["rows"]["cbf validate (process, small), CPU"] = {"small (30)": _stats([c for _, c in cli])}
    result["rows"]["python -c 'import numpy' (process), CPU"] = {"small (30)": _stats([c for _, c in numpy_only])}
    result["cli_process"] = how
    genv = dict(os.environ, PYTHONPATH=str(REPO / "generator"))
    tmp = WORK / "gen"
    gen_runs = [_child_cpu([PY, "-m", "cbfgen", "--no-ksc", "--out", str(tmp)], cwd=REPO, env=genv) for _ in range(3)]
    result["rows"]["generate without ksc"] = {"spec": _stats([w for w, _ in gen_runs])}
    result["rows"]["generate without ksc, CPU"] = {"spec": _stats([c for _, c in gen_runs])}
    gen = [w for w, _ in gen_runs]
    if (REPO / "node_modules" / "kaitai-struct-compiler").exists():
        ksc_argv = ["node", "generator/cbfgen/emit/kaitai/ksc_driver.js", str(tmp / "kaitai" / "cbf.ksy.json"),
                  str(tmp / "kaitai"), "python", "javascript", "java", "go"]
        ksc = [g + _child_cpu(ksc_argv, cwd=REPO)[0] for g in gen]
        result["rows"]["generate with ksc"] = {"spec": _stats(ksc)}
    _helix_convert_row(result, reps)
    from .ci_rows import diff_rows, validate_rows  # issue 27: the CI users' ratios
    from .ratio_rows import sarif_rows, spec_diff_rows  # issue 32
    from .wasm_rows import wasm_rows  # issue 34
    from .workbench_rows import workbench_rows  # issue 34, point 6

    result["diff_vs_gnu"] = diff_rows(files["65535 records"], WORK / "diff", max(reps, 5))
    result["sarif_vs_text"] = sarif_rows(argv[:-2], env, files["65535 records"], WORK / "sarif", max(reps, 3))
    result["spec_diff_vs_check"] = spec_diff_rows(WORK / "specdiff", genv, max(reps, 3))
    result["validate_folder"] = validate_rows(argv[:-2], env, REPO / "conformance" / "golden", WORK,
                                              int(os.environ.get("BENCH_VALIDATE_CALLS", "100")))
    result["wasm_vs_native"] = wasm_rows(files["65535 records"], max(reps, 5))
    result["workbench"] = workbench_rows(files["65535 records"], WORK / "workbench", max(reps, 3))
    big = files["65535 records"]
    peak, once = rss_decode_validate(big)
    result["memory"] = {"python_decode_validate_peak_extra_bytes": peak, "python_first_validate_once_bytes": once,
                        "file_bytes": big.stat().st_size}
    result["targets"] = _targets(result)
    return result


HELIX_SEGMENTS = 60_000  # issue 28: convert found the count one segment at a time (154 s for 63,655)


def _helix_convert_row(result: dict[str, Any], reps: int) -> None:
    """`cbf convert` of one 19-turn helix into about HELIX_SEGMENTS line segments: a helix command
    of a writable version that another writable version lacks, found by roles (none: no row)."""
    import math

    import cbf
    from cbf import tables as T
    from cbf.convert import convert
    from cbf.model import Cbf, Record, new_header

    writable = [v.id for v in T.VERSIONS if v.writable]
    pick = [(c, has, lacks) for c in T.COMMANDS if c.motion and c.motion["kind"] == "helix"
            for has in writable if c.layouts_for(has) for lacks in writable if not c.layouts_for(lacks)]
    if not pick:
        return
    cmd, has, lacks = pick[0]
    m = cmd.motion or {}
    lay = cmd.layouts_for(has)[0]
    radius, turns = 50.0, 19
    values = {m["start"]: (radius, 0.0, 0.0), m["center"]: (0.0, 0.0, 0.0), m["normal"]: (0.0, 0.0, 1.0),
              m["degrees"]: 360.0 * turns, m["length"]: 20.0}
    full = {f.name: values.get(f.name, (0.0, 0.0, 1.0) if f.kind == "float" and f.count == 3 else
                                 0.0 if f.kind == "float" else "" if f.kind == "string" else
                                 bytes(f.size) if f.kind == "bytes" else 0) for f in lay.args}
    model = Cbf(new_header(has, implant_descriptor="BENCH-HELIX"), (Record.of(lay.cls(**full)),))
    step = 2.0 * math.pi * turns / HELIX_SEGMENTS  # the chord formula, backwards: the sagitta at that step
    tol = radius * (1.0 - math.cos(step / 2.0))
    times, segments = [], 0
    for _ in range(max(1, min(reps, 3))):
        t0 = time.perf_counter()
        conv = convert(model, lacks, chord_tol=tol)
        cbf.encode(conv.model)
        times.append(time.perf_counter() - t0)
        segments = conv.segments
    name = f"helix ({segments:,} segments)"
    result["files"][name] = {"bytes": len(cbf.encode(model)), "records": 1}
    result["rows"]["Python convert (curve to segments)"] = {name: _stats(times)}


def _targets(r: dict[str, Any]) -> dict[str, Any]:
    rows = r["rows"]
    out: dict[str, Any] = {}
    for name in ("65535 records", "5-axis ~20k", "every command ~20k"):  # issue 17: 40x on every file shape
        k = rows.get("Kaitai Python parse (1x)", {}).get(name)
        pv = rows["Python decode + full validate"].get(name)
        if k and pv:
            ratio = k["median"] / pv["median"]
            out[f"cbf.validate >= 40x Kaitai ({name})"] = {"value": round(ratio, 1), "met": ratio >= 40}
    for name in C_RATIO_FILES:
        cv = rows.get("C validate", {}).get(name)
        # the least any validator does is read every byte once (the file checksum): a plain
        # byte sum over the same buffer, same compiler and flags, is the yardstick
        base = rows.get(C_BYTESUM, {}).get(name)
        if cv and base:
            ratio = cv["median"] / base["median"]
            out[f"C validate / byte sum <= {C_RATIO_TARGET}x ({name})"] = {
                "value": round(ratio, 2), "unit": "x", "met": ratio <= C_RATIO_TARGET}
    # issue 17: CBF -> CUT and CUT -> CBF 3x faster than before it. Measured against the Kaitai parse
    # of the same file in the same run (a load-independent yardstick): before #17 they ran at 1.15x
    # and 0.78x the Kaitai parse on the 65,535-record file (bench/NOTES.md), so 3x is 3.45x and 2.35x.
    k = rows.get("Kaitai Python parse (1x)", {}).get("65535 records")
    for row, before in (("Python CBF -> CUT", 1.15), ("Python CUT -> CBF", 0.78)):
        t = rows.get(row, {}).get("65535 records")
        if k and t:
            speed = k["median"] / t["median"] / before
            out[f"{row} >= 3x before #17 (65535 records)"] = {"value": round(speed, 1), "unit": "x",
                                                              "met": speed >= 3.0}
    # issue 32 (bench/NOTES.md, "Targets changed"): the command's CPU time against the same interpreter
    # importing numpy alone, in the same run; an absolute 80 ms was below numpy's own import here
    cli = rows["cbf validate (process, small), CPU"]["small (30)"]["median"]
    npy = rows["python -c 'import numpy' (process), CPU"]["small (30)"]["median"]
    out[f"cbf validate small <= {CLI_NUMPY_RATIO}x python -c 'import numpy' (CPU)"] = {
        "value": round(cli / npy, 2), "unit": "x", "met": cli / npy <= CLI_NUMPY_RATIO,
        "why": f"{cli * 1000:.0f} ms against {npy * 1000:.0f} ms"}
    g = rows["generate without ksc, CPU"]["spec"]["median"]
    out["generate without ksc < 2 s (CPU)"] = {"value": round(g, 2), "unit": "s", "met": g < 2.0}
    for name, d in r.get("diff_vs_gnu", {}).items():
        out[f"cbf diff 65535 records ({name}) <= 3x GNU diff of the CUT texts"] = {
            "value": round(d["ratio"], 2), "unit": "x", "met": d["ratio"] <= 3.0}
    v = r.get("validate_folder")
    if v:
        out[f"cbf validate: {v['files']} files in 1 call vs {v['files']} calls (timed {v['calls_timed']}, "
            f"scaled)"] = {"value": round(v["ratio"], 1), "unit": "x faster", "met": v["ratio"] >= 10.0}
    for name, d in r.get("sarif_vs_text", {}).items():
        out[f"cbf validate --format sarif vs text, {name} (report only)"] = {
            "value": round(d["ratio"], 2), "unit": "x", "met": None}
    for name, d in r.get("spec_diff_vs_check", {}).items():
        out[f"cbfgen diff of two specs vs --check-spec of one, {name} (report only)"] = {
            "value": round(d["ratio"], 2), "unit": "x", "met": None}
    w = r.get("wasm_vs_native")
    if w:
        out[f"cbf-c.wasm validate 65535 records (node:wasi, fresh instance) <= {WASM_RATIO_TARGET:g}x native cbf-c"] = {
            "value": round(w["ratio"], 2), "unit": "x", "met": w["ratio"] <= WASM_RATIO_TARGET,
            "why": (f"{w['wasm_s'] * 1000:.1f} ms against {w['native_s'] * 1000:.1f} ms, medians of {w['runs']}; "
                    f"not counted: compile {w['compile_s'] * 1000:.1f} ms once, node start-up "
                    f"{w['node_start_s'] * 1000:.0f} ms; module {w['wasm_bytes']:,} B")}
    wb = r.get("workbench") or {}
    if "gzip_bytes" in wb:
        out[f"workbench page gzipped (engine, script, data) < {GZIP_GOAL // 1024} KB"] = {
            "value": round(wb["gzip_bytes"] / 1024, 1), "unit": "KB", "met": wb["gzip_bytes"] < GZIP_GOAL,
            "why": f"{wb['page_bytes']:,} B as written"}
        out["workbench page, 65535 records: file chosen to findings shown, headless Chromium (report only)"] = {
            "value": round(wb["next_s"] * 1000), "unit": "ms", "met": None,
            "why": f"median of {wb['runs'] - 1} ({wb['next_min_s'] * 1000:.0f}-{wb['next_max_s'] * 1000:.0f} ms); "
                   f"the page's first file, which also compiles the module: {wb['first_s'] * 1000:.0f} ms"}
    elif wb:
        out["workbench page rows"] = {"value": wb.get("skipped", "?"), "unit": "", "met": False,
                                      "why": "Chromium and playwright-core are part of make's set-up"}
    mem = r["memory"]
    ratio = mem["python_decode_validate_peak_extra_bytes"] / mem["file_bytes"]
    out[f"python peak RSS of decode+validate <= {MEMORY_BOUND}x file"] = {
        "value": round(ratio, 2), "unit": "x file", "met": ratio <= MEMORY_BOUND,
        "why": f"{mem['python_decode_validate_peak_extra_bytes'] / 1e6:.2f} MB above the warm process"}
    if "python_first_validate_once_bytes" in mem:
        out["python first validation after import, one-off RSS (report only)"] = {
            "value": round(mem["python_first_validate_once_bytes"] / 1e6, 2), "unit": "MB", "met": None}
    return out


def table(r: dict[str, Any]) -> str:
    names = list(r["files"])
    ref = r["rows"].get("Kaitai Python parse (1x)", {})
    lines = ["| row | " + " | ".join(f"{n} ({r['files'][n]['bytes']:,} B)" for n in names) + " |",
             "|---|" + "---|" * len(names)]
    for row, per in r["rows"].items():
        cells = []
        for n in names:
            st = per.get("spec") if row.startswith("generate") and n == names[0] else per.get(n)
            if not st:
                cells.append("")
                continue
            cell = f"{st['median'] * 1000:.2f} ms ({st['min'] * 1000:.2f}-{st['max'] * 1000:.2f})"
            if n in ref and not row.startswith(("generate", "cbf validate", "python -c")):
                cell += f", {ref[n]['median'] / st['median']:.1f}x"
            if "MB/s" in st:
                cell += f", {st['MB/s']:.0f} MB/s, {st['records/s'] / 1e6:.1f} M rec/s"
            cells.append(cell)
        lines.append(f"| {row} | " + " | ".join(cells) + " |")
    lines.append("")
    lines.append("| target | value | met | measured |")
    lines.append("|---|---|---|---|")
    for name, t in r["targets"].items():
        met = "-" if t["met"] is None else "yes" if t["met"] else "NO"
        lines.append(f"| {name} | {t['value']} {t.get('unit', 'x')} | {met} | {t.get('why', '')} |")
    if "cli_process" in r:
        lines += ["", f"`cbf validate (process, small)` runs the `cbf` command: {r['cli_process']}."]
    return "\n".join(lines)


def machine() -> dict[str, Any]:
    """What the numbers were measured on: they mean little without it."""
    import platform

    cpu = next((line.split(":", 1)[1].strip() for line in Path("/proc/cpuinfo").read_text().splitlines()
                if line.startswith("model name")), platform.processor()) if Path("/proc/cpuinfo").exists() else ""
    gcc = subprocess.run(["gcc", "-dumpfullversion"], capture_output=True, text=True).stdout.strip()
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else None
    return {"cpu": cpu, "cores": os.cpu_count(), "python": platform.python_version(), "gcc": gcc,
            "load_1min_at_end": load}


README_BEGIN, README_END = "<!-- bench:begin (written by make bench-readme) -->", "<!-- bench:end -->"


def readme_block(r: dict[str, Any], text: str) -> str:
    m = r["machine"]
    return (f"{README_BEGIN}\nMedians of {r['reps']} interleaved repetitions (min-max in brackets) on "
            f"{m['cpu']}, {m['cores']} cores, Python {m['python']}, gcc {m['gcc']} -O2 (Python rows: CPU time of "
            f"the process; C rows: the driver's wall time); "
            f"load {m['load_1min_at_end']:.2f} at the end of the run.\n\n{text}\n{README_END}")


def update_readme(path: Path, block: str) -> bool:
    """Replace the marked block in the README; False when the markers are missing."""
    doc = path.read_text(encoding="utf-8")
    start, end = doc.find(README_BEGIN), doc.find(README_END)
    if start < 0 or end < start:
        return False
    path.write_text(doc[:start] + block + doc[end + len(README_END):], encoding="utf-8")
    return True


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="bench")
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--out", type=Path, default=REPO / "bench" / "results.json")
    ap.add_argument("--readme", type=Path, default=None,
                    help="only copy the table of --out (a finished run) into this README's marked block; runs nothing")
    args = ap.parse_args(argv)
    if args.readme is not None:
        # `make bench-readme`: the README is tracked, so only an explicit request rewrites it.
        result = json.loads(args.out.read_text(encoding="utf-8"))
        if not update_readme(args.readme, readme_block(result, table(result))):
            print(f"bench: {args.readme} has no {README_BEGIN} ... {README_END} block; not updated", file=sys.stderr)
            return 2
        print(f"bench: {args.readme} now shows the table of {args.out}")
        return 0
    result = run(args.reps)
    result["machine"] = machine()
    text = table(result)
    print(text)
    args.out.write_text(json.dumps(result, indent=1, sort_keys=True) + "\n", encoding="utf-8")
    (args.out.parent / "TABLE.md").write_text(readme_block(result, text).split("\n", 1)[1].rsplit("\n", 1)[0] + "\n",
                                               encoding="utf-8")
    missed = misses(result)
    for line in missed:
        print(f"bench: {line}", file=sys.stderr)
    return 1 if missed else 0


def misses(r: dict[str, Any]) -> list[str]:
    """One line per target the run did not meet (issue 32: a NO fails `make bench`), with the load."""
    load = (r.get("machine") or {}).get("load_1min_at_end")
    at = f"; load {load:.2f} at the end of the run" if isinstance(load, float) else ""
    return [f"target NO: {name}: {t['value']} {t.get('unit', 'x')}" + (f" ({t['why']})" if t.get("why") else "") + at
            for name, t in r.get("targets", {}).items() if t["met"] is False]
