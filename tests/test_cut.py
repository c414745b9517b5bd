"""The CUT text form: implib's syntax in, lossless both ways."""

from __future__ import annotations

import struct
from pathlib import Path

import pytest
from conftest import file_checksum_of
from hypothesis import given, settings
from hypothesis import strategies as st

import cbf
from cbf import tables as T
from cbf.cut import format_float
from cbf.model import Cbf, Record, new_header

GOLDEN = Path(__file__).resolve().parents[1] / "conformance" / "golden"
WELL_FRAMED = []
for _p in sorted(GOLDEN.glob("*.cbf")):
    if _p.stat().st_size > 100_000:
        continue
    try:
        _m = cbf.decode(_p.read_bytes())
    except cbf.CbfError:
        continue
    if not _m.trailing:
        WELL_FRAMED.append(_p)


@pytest.mark.parametrize("path", WELL_FRAMED, ids=lambda p: p.stem)
def test_cbf_cut_cbf_is_byte_exact(path: Path) -> None:
    data = path.read_bytes()
    model = cbf.decode(data)
    profile = "implib" if "implib" in path.name else "default"
    text = cbf.to_cut(model, profile=profile)
    refused = [f for f in cbf.validate(data, profile=profile) if f.severity == "error" or f.check == "string_ascii"]
    if refused or not cbf.tables.VERSION_BY_ID[model.version_id].writable:
        # CUT carries no sequence numbers, count or checksums: CUT -> CBF writes what a writer may
        # write (repaired), or refuses with the reason; never a file that fails validation.
        try:
            out = cbf.encode(cbf.from_cut(text, profile=profile), profile=profile)
        except cbf.CbfError:
            return
        assert not [f for f in cbf.validate(out, profile=profile) if f.severity == "error"]
        return
    assert cbf.encode(cbf.from_cut(text, profile=profile), profile=profile) == data
    assert cbf.to_cut(cbf.from_cut(text, profile=profile), profile=profile) == text


def test_reads_implib_text() -> None:
    text = """header PN-4711 ACME KNEE 4
header_ext CFG-A
point < 0.0000, 0.0000, 0.0000 >
speed 0.5000
line < 0.0000, 0.0000, 0.0000 > < 10.0000, 0.0000, 0.0000 >
cutter_on
comment rest of the line is the text
check_sum {}
"""
    data = cbf.encode(cbf.from_cut(text.format(0).replace("check_sum 0\n", "")))
    model = cbf.from_cut(text.format(file_checksum_of(data)))  # check_sum must state the file checksum (issue 26)
    assert model.header.implant_descriptor == "PN-4711 ACME KNEE 4"
    assert model.header.configuration_descriptor == "CFG-A"
    names = [r.name for r in model.records]
    assert names == ["POINT", "SPEED", "LINE", "CUTTER_ON", "COMMENT"]
    comment = model.records[4].decode_args()
    assert comment is not None and comment.text == "rest of the line is the text"
    assert cbf.validate(cbf.encode(model)) == []


def test_syntax_errors_name_the_line() -> None:
    with pytest.raises(cbf.CutSyntaxError) as err:
        cbf.from_cut("header X\nspeed 0.5\nline < 1, 2 > < 3, 4, 5 >\n")
    assert err.value.line == 3 and "expected ',' in start" in str(err.value)
    with pytest.raises(cbf.CutSyntaxError, match="line 2: unknown keyword 'lne'"):
        cbf.from_cut("header X\nlne < 1, 2, 3 > < 3, 4, 5 >\n")
    with pytest.raises(cbf.CutSyntaxError, match="phase: name: 17 characters, the field holds 16"):
        cbf.from_cut("phase ABCDEFGHIJKLMNOPQ\n")
    # a command a writable version lacks (today ARC in 4.0), written as CUT by a version that has it
    missing = [(c, v) for v in T.VERSIONS if v.writable for c in T.COMMANDS if not c.layouts_for(v.id)]
    for c, v in missing[:1]:
        has = next(w for w in T.VERSIONS if w.writable and c.layouts_for(w.id))
        lay = c.layouts_for(has.id)[0]
        line = cbf.to_cut(Cbf(new_header(has.id), (Record(code=c.code, raw_args=bytes(lay.size)),))).splitlines()[-1]
        with pytest.raises(cbf.CutSyntaxError, match=f"not available in version {v.id}"):
            cbf.from_cut(line + "\n", version=v.id)


@settings(max_examples=500, deadline=None)
@given(st.integers(0, 0xFFFFFFFF))
def test_floats_print_with_fewest_digits_and_round_trip(bits: int) -> None:
    value = struct.unpack("<f", struct.pack("<I", bits))[0]
    if value != value or value in (float("inf"), float("-inf")):
        return
    text = format_float(bits)
    assert "e" not in text.lower()
    assert struct.unpack("<I", struct.pack("<f", float(text)))[0] == bits
