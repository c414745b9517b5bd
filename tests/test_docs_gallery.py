"""The docs show the toolpath gallery (issue 16, point 6): `python -m cbf.gallery` draws every
golden file that validates clean, and the site carries that page and its drawings, linked
from every page, with no link leaving the site."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

import cbf
from cbf import tables as T
from cbf.stats import render, stats
from cbfgen.emit.docs import GALLERY, site, site_links
from cbfgen.loader import load

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"
pytest.importorskip("matplotlib")


def _clean(path: Path) -> bool:
    data = path.read_bytes()
    return any(not cbf.validate(data, profile=p) for p in T.PROFILES)


def test_the_site_shows_the_gallery(tmp_path: Path) -> None:
    files = sorted(GOLDEN.glob("*.cbf"))
    small = [p for p in files if p.stat().st_size < 4096][:6]  # a few small ones keep the test quick
    folder = tmp_path / "gallery"
    subprocess.run([sys.executable, "-m", "cbf.gallery", str(folder), *map(str, small)], check=True,
                   capture_output=True, text=True)
    drawn = {p.name.removesuffix(".cbf") for p in small if _clean(p)}
    assert drawn and {p.stem for p in folder.glob("*.svg")} == drawn
    for p in small:  # the gallery walks each file once for its drawing and its stats: the stats of `cbf stats`
        name = p.name.removesuffix(".cbf")
        if name in drawn:
            s = stats(cbf.decode(p.read_bytes()))
            assert s.moves and (folder / f"{name}.stats.txt").read_text(encoding="utf-8") == render(s, p.name)
            assert json.loads((folder / f"{name}.stats.json").read_text(encoding="utf-8")) == {"file": p.name,
                                                                                             **s.as_dict()}
    out = tmp_path / "site"
    site.build(load(REPO / "spec" / "cbf.yaml"), out, folder)
    page = (out / GALLERY / "index.html").read_text(encoding="utf-8")
    for name in drawn:
        assert f'src="{name}.svg"' in page and (out / GALLERY / f"{name}.svg").exists()
    assert f'href="{GALLERY}/index.html"' in (out / "index.html").read_text(encoding="utf-8")
    assert site_links.problems(out) == []
