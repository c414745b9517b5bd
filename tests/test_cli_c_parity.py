"""`cbf validate` and `cbf-c validate` print alike (issue 27 item 1, the README's claim): over every
golden file, the same lines in the same order (file, offset, severity, check, record), with the
same cap (--max-findings), the same verdict lines and the same exit status, under every profile.
The messages are the same words too: the C engine (generator/cbfgen/emit/c/runtime/) says what the
Python runtime says, with the spec's names (fields, commands, coverages, profiles, sizes) from its tables."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from cbf import tables as T

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"
CBF_C = REPO / "build" / "c" / "cbf-c"
FILES = [str(p) for p in sorted(GOLDEN.glob("*.cbf"))]


def _both(*args: str) -> tuple[subprocess.CompletedProcess[str], subprocess.CompletedProcess[str]]:
    env = dict(os.environ, PYTHONPATH=str(REPO / "generated" / "python"))
    py = subprocess.run([sys.executable, "-m", "cbf", "validate", "--jobs", "1", *args, *FILES], env=env,
                        capture_output=True, text=True, timeout=300)
    c = subprocess.run([str(CBF_C), "validate", *args, *FILES], capture_output=True, text=True, timeout=300)
    return py, c


def _head(line: str) -> str:
    """A finding line up to its message (`file:offset: severity check (record N)`); other lines whole."""
    head, sep, _ = line.partition("): ")
    return head + ")" if sep and " (record " in head or " (header" in head else line


@pytest.mark.skipif(not CBF_C.exists(), reason="make c-build first")
@pytest.mark.parametrize("profile", list(T.PROFILES))
def test_the_messages_are_the_same_words(profile: str) -> None:
    py, c = _both("--profile", profile, "--max-findings", "0")
    assert py.stdout.splitlines()[:-1] == c.stdout.splitlines()


@pytest.mark.skipif(not CBF_C.exists(), reason="make c-build first")
@pytest.mark.parametrize("profile", list(T.PROFILES))
@pytest.mark.parametrize("cap", ["0", "1", "50"])
def test_cbf_and_cbf_c_print_alike(profile: str, cap: str) -> None:
    py, c = _both("--profile", profile, "--max-findings", cap)
    assert py.returncode == c.returncode
    lines = py.stdout.splitlines()
    assert lines[-1].startswith("cbf validate: ")  # the batch summary: cbf's alone
    py_lines, c_lines = lines[:-1], c.stdout.splitlines()
    assert [_head(ln) for ln in py_lines] == [_head(ln) for ln in c_lines]
    if cap == "1":
        assert "more finding(s) not shown" in c.stdout  # the cap applies to some file
    # the files neither tool validates are the same ones
    assert {ln.split(": ")[1] for ln in py.stderr.splitlines()} == {ln.split(": ")[1] for ln in c.stderr.splitlines()}
