"""A no-op `make` is fast because nothing is rewritten that did not change (issue 14, set-up):
ksc leaves unchanged parser files alone, so the Go and Java testees are not rebuilt."""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
HAVE_KSC = (REPO / "node_modules" / "kaitai-struct-compiler").exists() and shutil.which("node") is not None
DRIVER = REPO / "generator" / "cbfgen" / "emit" / "kaitai" / "ksc_driver.js"
KSY = REPO / "generated" / "kaitai" / "cbf.ksy.json"


def _compile(out: Path) -> str:
    res = subprocess.run(["node", str(DRIVER), str(KSY), str(out), "python", "go"], cwd=REPO,
                         capture_output=True, text=True, check=True)
    return res.stdout


@pytest.mark.skipif(not HAVE_KSC, reason="kaitai-struct-compiler not installed (make kaitai-setup)")
def test_ksc_rewrites_only_changed_files(tmp_path: Path) -> None:
    first = _compile(tmp_path)
    written = sorted(p for p in tmp_path.rglob("*") if p.is_file())
    assert written and "ksc: python:" in first
    past = 1_000_000_000  # 2001: any rewrite would move the mtime to now
    for p in written:
        os.utime(p, (past, past))
    assert _compile(tmp_path) == ""  # nothing reported as written
    assert all(p.stat().st_mtime == past for p in written)
    # a changed (here: damaged) output is written again, and only that one
    victim = written[0]
    victim.write_text("damaged", encoding="utf-8")
    os.utime(victim, (past, past))
    again = _compile(tmp_path)
    assert victim.name in again and victim.read_text(encoding="utf-8") != "damaged"
    assert all(p.stat().st_mtime == past for p in written if p != victim)


def test_make_steps_are_stamped() -> None:
    """The expensive steps of `make` have stamps whose prerequisites are their inputs."""
    text = "\n".join(p.read_text(encoding="utf-8") for p in [REPO / "Makefile", *sorted((REPO / "mk").glob("*.mk"))])
    for stamp in ("generate-py", "lint", "ksc", "golden-check", "conformance"):
        assert f"$(STAMPS)/{stamp}:" in text, stamp


@pytest.mark.parametrize("changed", ["spec/cbf.yaml", "generator/cbfgen/loader/__init__.py", "conformance/report.json",
                                     "generated/c/cbf.h"])
def test_generate_runs_when_what_it_reads_changed(changed: str) -> None:
    """`make -n -W FILE` (as if FILE had just changed) plans the cbfgen run: the generator's
    stamp lists what it reads among its prerequisites."""
    res = subprocess.run(["make", "-n", "-W", changed, "build/stamps/generate-py"], cwd=REPO, capture_output=True,
                         text=True, check=True)
    assert "-m cbfgen --spec spec/cbf.yaml --out generated" in res.stdout, res.stdout
