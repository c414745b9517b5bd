"""The ksc server the generating tests share (tests/ksc_serve.py) writes what `cbfgen` writes, and fails as ksc does."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import ksc_serve
import pytest
from conftest import REPO

from cbfgen import ksc as ksc_mod

pytestmark = pytest.mark.skipif(not ksc_serve.available(), reason="node or the Kaitai compiler is not installed")
KAITAI = REPO / "generated" / "kaitai"


def test_the_server_writes_the_parsers_cbfgen_wrote_and_reports_a_failure(tmp_path: Path) -> None:
    """The committed .ksy (with its ksc-options.json) compiled by the server: every parser file is the one
    `make generate` (cbfgen, then node ksc_driver.js) committed, byte for byte. A .ksy ksc refuses is an
    error naming what ksc refused, as the driver prints it, and the server goes on compiling."""
    src = tmp_path / "kaitai"
    src.mkdir()
    for name in ("cbf.ksy.json", "ksc-options.json"):
        shutil.copy(KAITAI / name, src / name)
    bad = tmp_path / "bad"
    bad.mkdir()
    ksy = json.loads((KAITAI / "cbf.ksy.json").read_text(encoding="utf-8"))
    ksy["seq"] = [{"id": "x", "type": "no_such_type"}]
    (bad / "cbf.ksy.json").write_text(json.dumps(ksy), encoding="utf-8")
    with ksc_serve.server() as ksc:
        error = ksc.compile(bad / "cbf.ksy.json", bad)
        assert error is not None and error.startswith("ksc: ") and "'no_such_type'" in error, error
        assert ksc.compile(src / "cbf.ksy.json", src) is None
    written = sorted(p.relative_to(src).as_posix() for p in src.rglob("*") if p.is_file()
                     and p.name not in ("cbf.ksy.json", "ksc-options.json"))
    assert {w.split("/", 1)[0] for w in written} == set(ksc_mod.LANGS), written
    for rel in written:
        assert (src / rel).read_bytes() == (KAITAI / rel).read_bytes(), rel
