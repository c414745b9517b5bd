"""The C programs of `make c-build` (build/c/), for the tests that run them.

Compiling generated/c/cbf_testee.c or cbf_tool.c costs about 1.2 CPU s at -O1, and the tests
that compiled their own copy did so once per test. `make` is asked for the one file instead (as
test_exit_codes.py does for cbf-c): in `make test` it is built before pytest starts and make
finds nothing to do; run alone, the first test builds it and later ones reuse it; a program
older than its source is rebuilt, so no test runs a stale one. The testee is the sanitizer
build the conformance runner uses (AddressSanitizer and UBSan on, which only adds checks).
A lock keeps two pytest workers from building the same file at once.
"""

from __future__ import annotations

import fcntl
import shutil
import subprocess
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
BUILT = REPO / "build" / "c"


def built(name: str) -> Path:
    """build/c/NAME, made up to date by make; skips without gcc."""
    if shutil.which("gcc") is None:
        pytest.skip("gcc not installed")
    BUILT.mkdir(parents=True, exist_ok=True)
    with (BUILT / ".tests.lock").open("w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        subprocess.run(["make", "-s", "-C", str(REPO), str((BUILT / name).relative_to(REPO))], check=True,
                       capture_output=True)
    return BUILT / name
