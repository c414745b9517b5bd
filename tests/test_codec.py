"""Round trips, totality and the canonical JSON schema of the Python codec."""

from __future__ import annotations

import json
import random
import struct
from pathlib import Path
from typing import Any

import jsonschema
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import cbf
import cbf.layouts
from cbf import tables as T
from cbf.model import Cbf, Record, new_header
from cbfgen.model import camel

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"
VALID = sorted(p for p in GOLDEN.glob("*.cbf") if p.stat().st_size < 100_000)


@st.composite
def models(draw: st.DrawFn, version: str) -> Cbf:
    """Any well-formed model of a version: every command the version has, random argument bytes."""
    cmds = [c for c in T.COMMANDS if c.layouts_for(version)]
    n = draw(st.integers(0, 12))
    records = []
    for _ in range(n):
        cmd = draw(st.sampled_from(cmds))
        lay = draw(st.sampled_from(cmd.layouts_for(version)))
        raw = draw(st.binary(min_size=lay.size, max_size=lay.size))
        records.append(Record(code=cmd.code, raw_args=raw, reserved=draw(st.sampled_from([0, 0, 0, 7]))))
    header = new_header(version, implant_descriptor=draw(st.text("ABC- 123", max_size=20)))
    return Cbf(header, tuple(records), b"")


@pytest.mark.parametrize("version", [v.id for v in T.VERSIONS if v.minor is not None])
@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_decode_encode_decode(version: str, data: st.DataObject) -> None:
    model = data.draw(models(version))
    raw = cbf.encode(model, keep_stored=True)
    back = cbf.decode(raw)
    assert cbf.encode(back, keep_stored=True) == raw
    assert [(r.code, r.raw_args, r.reserved) for r in back.records] == \
        [(r.code, r.raw_args, r.reserved) for r in model.records]
    assert back.header == cbf.decode(cbf.encode(back, keep_stored=True)).header


@pytest.mark.parametrize("path", VALID, ids=lambda p: p.stem)
def test_encode_decode_is_byte_exact_for_every_golden_file(path: Path) -> None:
    data = path.read_bytes()
    try:
        model = cbf.decode(data)
    except cbf.CbfError:
        return  # truncated cases: their framing error is checked by conformance
    assert cbf.encode(model, keep_stored=True) == data
    assert cbf.encode(cbf.from_canonical(json.loads(json.dumps(cbf.to_canonical(model)))), keep_stored=True) == data


def test_keep_stored_reproduces_every_well_framed_mutation() -> None:
    rnd = random.Random(5)
    seeds = [p.read_bytes() for p in VALID if p.stat().st_size >= 128]
    checked = 0
    for _ in range(400):
        x = bytearray(rnd.choice(seeds))
        for _ in range(rnd.randint(1, 4)):
            x[rnd.randrange(len(x))] = rnd.randrange(256)
        try:
            model = cbf.decode(bytes(x))
        except cbf.CbfError:
            continue
        assert cbf.encode(model, keep_stored=True) == bytes(x)
        checked += 1
    assert checked > 100


@settings(deadline=None)  # examples: the profile (tests/conftest.py)
@given(st.binary(max_size=2000))
def test_decoder_and_validator_are_total(data: bytes) -> None:
    try:
        cbf.decode(data)
    except cbf.CbfError as exc:
        assert exc.offset is not None and exc.kind in ("truncated_header", "truncated_record")
    found = cbf.validate(data)
    assert all(f.severity in ("error", "warning") for f in found)


@settings(deadline=None)  # examples: the profile (tests/conftest.py)
@given(st.binary(min_size=0, max_size=600))
def test_header_plus_random_records_are_total(tail: bytes) -> None:
    head = (GOLDEN / "valid.v3.small.cbf").read_bytes()[:128]
    try:
        model = cbf.decode(head + tail)
        assert cbf.encode(model, keep_stored=True) == head + tail
    except cbf.CbfError as exc:
        assert exc.kind == "truncated_record" and exc.offset is not None and exc.offset >= 128


def test_fill_mode_fills_every_derived_field() -> None:
    model = cbf.decode((GOLDEN / "valid.v3.small.cbf").read_bytes())
    scrambled = Cbf(model.header, tuple(Record(r.code, r.raw_args, sequence=99, code_copy=0, arg_checksum=1)
                                        for r in model.records))
    assert cbf.encode(scrambled) == (GOLDEN / "valid.v3.small.cbf").read_bytes()


def test_encoder_refuses_what_it_cannot_represent() -> None:
    writable = [v for v in T.VERSIONS if v.writable]
    # a command a writable version lacks (today ARC in 4.0)
    missing = [(c, v) for v in writable for c in T.COMMANDS if not c.layouts_for(v.id) and c.layouts]
    for c, v in missing[:1]:
        rec = Record(code=c.code, raw_args=bytes(c.layouts[0].size))
        with pytest.raises(cbf.EncodeError, match=f"{c.name} is not available in version {v.id}"):
            cbf.encode(Cbf(new_header(v.id), (rec,)))
    # a string argument one character too long, and a non-ASCII one (the first string layout of the default version)
    lay, arg = next((lay, a) for c in T.COMMANDS for lay in c.layouts_for(T.DEFAULT_VERSION) if not lay.variant
                    for a in lay.args if a.kind == "string")
    cls = getattr(cbf.layouts, camel(lay.command))

    def make(text: str) -> Any:
        def value(a: Any) -> Any:
            if a.name == arg.name:
                return text
            return {"string": "", "bytes": bytes(a.size), "uint": 0}.get(a.kind, (0.0,) * a.count if a.count > 1
                                                                          else 0.0)
        return cls(**{a.name: value(a) for a in lay.args})

    with pytest.raises(cbf.EncodeError, match=f"{lay.command} field {arg.name}: {arg.size + 1} characters, "
                                              f"the field holds {arg.size}"):
        Record.of(make("x" * (arg.size + 1)))
    with pytest.raises(cbf.EncodeError, match="non-ASCII"):
        cbf.encode(Cbf(new_header(T.DEFAULT_VERSION), (Record.of(make("caf\u00e9")),)))
    empty = next(c for c in T.COMMANDS for lay in c.layouts_for(T.DEFAULT_VERSION) if lay.size == 0)
    limit = T.LIMITS["max_commands"]
    with pytest.raises(cbf.EncodeError, match=f"{limit + 1} commands, at most {limit}"):
        cbf.encode(Cbf(new_header(T.DEFAULT_VERSION), (Record(code=empty.code, raw_args=b""),) * (limit + 1)))
    for v in [v for v in T.VERSIONS if not v.writable][:1]:
        vid = f"{v.major}.{v.minor or 0}"
        with pytest.raises(cbf.EncodeError, match=f"version {vid} is not writable"):
            cbf.encode(Cbf(new_header(vid), ()))


def test_canonical_json_matches_its_schema() -> None:
    schema = json.loads((REPO / "generated" / "python" / "cbf" / "canonical.schema.json").read_text())
    validator = jsonschema.Draft202012Validator(schema)
    for path in VALID:
        try:
            doc = cbf.to_canonical(cbf.decode(path.read_bytes()))
        except cbf.CbfError:
            continue
        errors = list(validator.iter_errors(doc))
        assert not errors, f"{path.name}: {errors[0].message}"


def test_floats_keep_their_bits() -> None:
    from cbf.canonical import float_bits, float_json

    for bits in (0x80000000, 0x7FC00001, 0x7FA00001, 0xFF800000, 0x00000001, 0x3DCCCCCD):
        assert float_bits(float_json(bits), "x") == bits
    assert float_json(0x3F800000) == 1.0
    assert struct.pack("<f", float_json(0x3DCCCCCD)) == struct.pack("<I", 0x3DCCCCCD)
