"""Memory and start-up of the Python engine, held by structure (issue 32), not by a timer:

- tracemalloc's peak of decode + validate, above the file's own bytes, stays within the bound `make
  bench` reports on (bench.bench.MEMORY_BOUND x the file) on the largest golden file and on a file of
  every record layout (tests/engine_probe.py);
- what `cbf validate` has imported when it opens its first file: the toolkit's own modules a fixed
  list, no third-party package, and at most a stated number of standard-library modules beyond those
  a bare interpreter has; numpy and the engine come after (they are the price of validating, not of
  starting).

On the generated/python of 6b44d7d the first peak was 5.9x the file (the argument checksums held as
Python ints); bench/NOTES.md has the evidence.
"""

from __future__ import annotations

import json
import subprocess
import sys
import tracemalloc
from pathlib import Path

import engine_probe
import pytest
from conftest import REPO

import cbf
from bench.bench import MEMORY_BOUND, rss_decode_validate

GOLDEN = REPO / "conformance" / "golden"


def peak_ratio(data: bytes) -> float:
    """tracemalloc's peak during decode + validate of data, over its length (the bytes exist before)."""
    cbf.validate(cbf.decode(data))  # caches and lazy imports first: they are not the file's
    tracemalloc.start()
    try:
        found = cbf.validate(cbf.decode(data))
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert isinstance(found, list)
    return peak / len(data)


def _largest_golden() -> Path:
    return max(GOLDEN.glob("*.cbf"), key=lambda p: p.stat().st_size)


def test_decode_validate_peak_of_the_largest_golden_is_within_the_bench_bound() -> None:
    path = _largest_golden()
    ratio = peak_ratio(path.read_bytes())
    assert ratio <= MEMORY_BOUND, f"{path.name}: decode + validate peaked at {ratio:.2f}x the file " \
                                  f"(make bench's bound: {MEMORY_BOUND}x)"


@pytest.mark.skipif(not Path("/proc/self/clear_refs").exists(), reason="needs Linux's /proc/PID/clear_refs")
def test_decode_validate_peak_rss_of_the_largest_golden_is_within_the_bench_bound() -> None:
    """The resident peak, as `make bench` measures it (the same function): what tracemalloc cannot see
    (numpy's buffers reusing heap pages, pages the allocator keeps) counts too. make bench had 4.9x on a
    fresh clone while the tracemalloc test above passed at 3.8x (bench/NOTES.md, "Peak RSS, round 5")."""
    path = _largest_golden()
    peak, _ = rss_decode_validate(path)
    ratio = peak / path.stat().st_size
    assert ratio <= MEMORY_BOUND, f"{path.name}: decode + validate peaked at {ratio:.2f}x the file in resident " \
                                  f"memory (make bench's bound: {MEMORY_BOUND}x)"


def test_decode_validate_peak_of_every_layout_is_within_the_bench_bound() -> None:
    for key, (_, large, _) in engine_probe.files(64).items():
        ratio = peak_ratio(large)
        assert ratio <= MEMORY_BOUND, f"{key} ({len(large)} B): decode + validate peaked at {ratio:.2f}x the file"


# Imported by `cbf validate FILE` before FILE is opened: the command line, its option files, the tables.
# cbf.quoting: every line printed goes through it (issue 35); cbf.files: the reader that opens the file
# (stat, then a non-blocking open: regular files only), imported as the first file is opened.
STARTUP_CBF = {"cbf", "cbf.cli", "cbf.errors", "cbf.files", "cbf.optfiles", "cbf.quoting", "cbf.tables",
               "cbf.version"}
# Standard-library modules beyond a bare interpreter's (argparse, json, dataclasses, pathlib and what
# they import: 36 on Python 3.11). A new one needs a reason: most belong where they are used.
STARTUP_STDLIB_MAX = 50  # measured in a venv without an editable finder (bench/NOTES.md, "Start-up imports")

_SNAPSHOT = """
import json, sys
sys.path.insert(0, sys.argv[1])
target, seen = sys.argv[2], []
def hook(event, args):
    if event == "open" and not seen and str(args[0]) == target:
        seen.append(sorted(sys.modules))
sys.addaudithook(hook)
from cbf.cli import main
out = sys.stdout
sys.stdout = open("/dev/null", "w")
try:
    code = main(["validate", target])
except SystemExit as exc:
    code = exc.code
sys.stdout = out
print(json.dumps({"code": code, "modules": seen[0] if seen else None}))
"""


PKG = REPO / "generated" / "python"


def _imported_before_the_first_file(path: Path, pkg: Path = PKG) -> tuple[set[str], set[str]]:
    """The modules `cbf validate` has when it opens ``path``, and those of a bare interpreter (both -I)."""
    run = subprocess.run([sys.executable, "-I", "-c", _SNAPSHOT, str(pkg), str(path)],
                         capture_output=True, text=True, check=False, timeout=120)
    got = json.loads(run.stdout.strip().splitlines()[-1])
    assert got["code"] == 0 and got["modules"], run.stderr[-2000:]
    bare = subprocess.run([sys.executable, "-I", "-c", "import sys, json; print(json.dumps(sorted(sys.modules)))"],
                          capture_output=True, text=True, check=True, timeout=120)
    return set(got["modules"]), set(json.loads(bare.stdout)) - {"json", "json.decoder", "json.encoder",
                                                                  "json.scanner"}


def startup_problems(mods: set[str], bare: set[str]) -> list[str]:
    new = mods - bare
    out = []
    ours = {m for m in new if m == "cbf" or m.startswith("cbf.")}
    if not ours <= STARTUP_CBF:
        out.append(f"cbf validate imports {sorted(ours - STARTUP_CBF)} before it reads a file: import them where "
                   f"they are used")
    stdlib = set(sys.stdlib_module_names)
    third = sorted({m.split(".")[0] for m in new - ours} - stdlib)
    if third:
        out.append(f"cbf validate imports {third} before it reads a file (numpy: the engine imports it)")
    std = sorted(m for m in new - ours if m.split(".")[0] in stdlib)
    if len(std) > STARTUP_STDLIB_MAX:
        out.append(f"{len(std)} standard-library modules before the first file (at most {STARTUP_STDLIB_MAX}): {std}")
    return out


def test_cbf_validate_imports_little_before_reading_its_first_file() -> None:
    assert startup_problems(*_imported_before_the_first_file(GOLDEN / "valid.v3.small.cbf")) == []


def test_the_startup_guard_fails_on_an_eager_import(tmp_path: Path) -> None:
    """A copy of the package whose command line imports the engine at the top fails the guard."""
    import shutil

    pkg = tmp_path / "python"
    shutil.copytree(PKG, pkg, ignore=shutil.ignore_patterns("__pycache__"))
    cli = pkg / "cbf" / "cli.py"
    text = cli.read_text(encoding="utf-8")
    cli.write_text(text.replace("\nimport argparse\n", "\nimport argparse\n\nimport cbf.records  # noqa\n", 1),
                   encoding="utf-8")
    got = startup_problems(*_imported_before_the_first_file(GOLDEN / "valid.v3.small.cbf", pkg))
    assert len(got) >= 2 and "cbf.records" in got[0] and "numpy" in got[1], got


def test_the_snapshot_sees_what_the_engine_imports_later(tmp_path: Path) -> None:
    # a file opened after the engine ran (the second of two) sees numpy and records: the hook is not blind
    script = _SNAPSHOT.replace('main(["validate", target])',
                               'main(["validate", sys.argv[3], target])')
    small = GOLDEN / "valid.v3.small.cbf"
    (tmp_path / "second.cbf").write_bytes(small.read_bytes())
    run = subprocess.run([sys.executable, "-I", "-c", script, str(REPO / "generated" / "python"),
                          str(tmp_path / "second.cbf"), str(small)], capture_output=True, text=True, check=False,
                         timeout=120)
    got = json.loads(run.stdout.strip().splitlines()[-1])
    assert got["modules"] and "numpy" in got["modules"] and "cbf.records" in got["modules"], run.stderr[-2000:]
