"""Checksum fields as data (issue 25, points 1 and 2), on the spec the header_crc drill fixture
revises: a new version's header turns the reserved checksum bytes into a CRC-32 field. Spec level
and binding-free (the loader, the C tables, the .ksy, the assembler); the drill
(tests/revisions/drill.py run tests/revisions/header_crc.yaml) runs every binding on it."""

from __future__ import annotations

import struct
import zlib
from pathlib import Path

import pytest
from conftest import REPO
from revisions import drill

from cbfgen.emit.c.views import context
from cbfgen.emit.kaitai import build
from cbfgen.loader import SpecError, load
from cbfgen.model import Spec, common_header_prefix
from conformance.assembler import assemble_text

FIXTURE = REPO / "tests" / "revisions" / "header_crc.yaml"


@pytest.fixture(scope="module")
def revised(tmp_path_factory: pytest.TempPathFactory) -> tuple[Spec, Path, drill.Fixture]:
    base = REPO / "spec" / "cbf.yaml"
    fx = drill.load_fixture(FIXTURE, drill.read_spec(base))
    path = drill.revised_spec(fx, base, tmp_path_factory.mktemp("header_crc"))
    return load(path), path, fx


def _new(spec: Spec) -> tuple[str, str]:
    """The fixture's new version and its CRC's tag (the tag no older header carries)."""
    old = load(REPO / "spec" / "cbf.yaml")
    vid = next(v.id for v in spec.versions if v.id not in {o.id for o in old.versions})
    tag = next(t for t in spec.header_checksum_tags(spec.version(vid).header) if t not in
               {f.field for f in old.checksums.fields})
    return vid, tag


def test_the_new_field_belongs_to_the_new_version_and_its_check(revised: tuple[Spec, Path, drill.Fixture]) -> None:
    spec, _, _ = revised
    vid, tag = _new(spec)
    assert spec.checksum_versions(tag) == (vid,)
    judge = spec.checksum_check(tag)
    assert judge is not None and judge.kind == "header_checksum"
    # today's header checksum stays judged by its own check, for every version
    assert spec.checksum_check("header") is not None and spec.checksum_check("header") != judge
    assert set(spec.checksum_versions("header")) == {v.id for v in spec.versions}


def test_the_c_tables_tie_the_field_to_its_check(revised: tuple[Spec, Path, drill.Fixture]) -> None:
    spec, _, _ = revised
    _, tag = _new(spec)
    rows = {r.tag: r for r in context(spec).checksums.ckfields}
    judge = spec.checksum_check(tag)
    assert judge is not None
    assert rows[tag].check == [c.id for c in spec.checks].index(judge.id)
    assert rows["file"].check == -1 and rows["args"].check == -1  # judged by their own kinds


def test_kaitai_reads_the_version_by_position_when_headers_diverge_before_it(
        revised: tuple[Spec, Path, drill.Fixture]) -> None:
    spec, _, _ = revised
    header = build(spec)["types"]["header"]
    seq_ids = [a["id"] for a in header["seq"]]
    for role in ("version_major", "version_minor"):
        f = spec.common_header_field(role)
        assert f.name not in seq_ids
        assert header["instances"][f.name]["pos"] == f.offset
    # headers that share the version before they diverge (rev 03's) keep it in the sequence
    base = load(REPO / "spec" / "cbf.yaml")
    vmajor = base.common_header_field("version_major").name
    if vmajor in {f.name for f in common_header_prefix(tuple(base.headers.values()))}:
        plain = build(base)["types"]["header"]
        assert vmajor in [a["id"] for a in plain["seq"]] and vmajor not in plain["instances"]


def test_the_assembler_fills_the_crc_before_the_header_checksum(revised: tuple[Spec, Path, drill.Fixture]) -> None:
    spec, path, fx = revised
    vid, tag = _new(spec)
    crc = next(f for f in spec.header_for(vid).fields if f.checksum == tag)
    hsum = next(f for f in spec.header_for(vid).fields if f.checksum == "header")
    name = next(r for r in fx.files if r.endswith(".hex") and r.split("/")[-1].startswith("valid."))
    data = assemble_text(fx.files[name], name, base=REPO / "conformance" / "golden", spec=path)
    cov = spec.checksums.coverages[spec.checksums.for_field(tag).coverage].segments[0]
    assert cov.start is not None and cov.end is not None
    stored = struct.unpack_from("<I", data, crc.offset)[0]
    assert stored == zlib.crc32(data[cov.start:cov.end]) != 0
    hcov = spec.checksums.coverages[spec.checksums.for_field("header").coverage].segments[0]
    assert hcov.start is not None and hcov.start <= crc.offset  # the header checksum covers the CRC ...
    assert struct.unpack_from("<H", data, hsum.offset)[0] == sum(data[hcov.start:hcov.end]) & 0xFFFF  # ... as filled


def test_a_field_no_check_judges_is_refused(revised: tuple[Spec, Path, drill.Fixture], tmp_path: Path) -> None:
    spec, path, _ = revised
    _, tag = _new(spec)
    judge = spec.checksum_check(tag)
    assert judge is not None
    doc = drill.read_spec(path)
    drill.apply_edit(doc, {"op": "remove", "path": f"checks[id={judge.id}]"})
    bad = tmp_path / "cbf.yaml"
    bad.write_text(drill._dump(doc), encoding="utf-8")
    with pytest.raises(SpecError, match=f"no header_checksum check judges checksum {tag}"):
        load(bad)
