"""Checksum fields in record layouts and coverage by named fields (issue 25, point 1), on the specs
the record_crc and header_fields_crc drill fixtures revise: a command whose arguments end with a
CRC-16 of its named payload fields, and a new version's header CRC over named header fields.

Everything is read from the revised model (the command, the tag, the offsets, the check); nothing
names a command, size or offset of rev 03. The loader, the assembler and the C tables are checked
in process; the Python and C bindings generated for the revised spec in a subprocess (the drill,
tests/revisions/drill.py run tests/revisions/record_crc.yaml, runs every binding on it)."""

from __future__ import annotations

import base64
import binascii
import json
import shutil
import struct
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest
import yaml
from conftest import REPO, cbfgen_here
from revisions import drill

from cbfgen.emit.c.views import context
from cbfgen.loader import SpecError, load
from cbfgen.model import ArgChecksum, Command, Layout, Spec
from conformance.assembler import assemble_text

RECORD = REPO / "tests" / "revisions" / "record_crc.yaml"
HEADER = REPO / "tests" / "revisions" / "header_fields_crc.yaml"
GOLDEN = REPO / "conformance" / "golden"

Revised = tuple[Spec, Path, drill.Fixture]


def _revise(fixture: Path, tmp: Path) -> Revised:
    base = REPO / "spec" / "cbf.yaml"
    fx = drill.load_fixture(fixture, drill.read_spec(base))
    path = drill.revised_spec(fx, base, tmp)
    return load(path), path, fx


@pytest.fixture(scope="module")
def record(tmp_path_factory: pytest.TempPathFactory) -> Revised:
    return _revise(RECORD, tmp_path_factory.mktemp("record_crc"))


@pytest.fixture(scope="module")
def header(tmp_path_factory: pytest.TempPathFactory) -> Revised:
    return _revise(HEADER, tmp_path_factory.mktemp("header_fields_crc"))


def _carrier(spec: Spec) -> tuple[Command, Layout, ArgChecksum]:
    """The one layout the fixture gives an argument checksum (the tag the unrevised spec lacks)."""
    before = set(load(REPO / "spec" / "cbf.yaml").record_checksum_tags())
    (tag,) = [t for t in spec.record_checksum_tags() if t not in before]
    (found,) = spec.checksum_layouts(tag)
    return found


def _golden(fx: drill.Fixture, prefix: str, path: Path) -> tuple[str, bytes, dict[str, object]]:
    """The fixture's golden case whose name starts with prefix: its name, bytes and expectation."""
    name = next(n for n in fx.files if n.endswith(".hex") and n.split("/")[-1].startswith(prefix))
    data = assemble_text(fx.files[name], name, base=GOLDEN, spec=path)
    expect = yaml.safe_load(fx.files[name.removesuffix(".hex") + ".expect.yaml"])
    return name, data, expect


def _records(spec: Spec, data: bytes) -> list[tuple[int, int, int]]:
    """(offset, code, nb) of each record, framed from the model's head fields."""
    code, nb = spec.record.by_role("code"), spec.record.by_role("arg_size")
    out, pos = [], spec.header_size
    while pos + spec.record.head_size <= len(data):
        n = int.from_bytes(data[pos + nb.offset:pos + nb.end], "little")
        out.append((pos, int.from_bytes(data[pos + code.offset:pos + code.end], "little"), n))
        pos += spec.record.head_size + n
    return out


# -- the model ---------------------------------------------------------------------------------
def test_the_named_fields_resolve_to_the_layouts_bytes(record: Revised) -> None:
    spec, _, _ = record
    cmd, lay, ck = _carrier(spec)
    hs = spec.record.head_size
    cov = spec.checksums.coverages[spec.checksums.for_field(ck.tag).coverage]
    names = tuple(n for seg in cov.segments for n in seg.fields)
    assert ck.covers == names and names
    want = []
    for n in names:
        a = lay.arg(n)
        assert a is not None
        want.append((hs + a.offset, hs + a.end))
    assert ck.ranges == tuple(want)
    assert ck.field.role == "checksum" and ck.field.checksum == ck.tag
    assert not any(lo < hs + ck.field.end and hs + ck.field.offset < hi for lo, hi in ck.ranges)
    assert ck.algorithm == spec.checksums.for_field(ck.tag).algorithm


def test_the_fields_versions_are_those_of_the_layouts_that_carry_it(record: Revised) -> None:
    spec, _, _ = record
    cmd, lay, ck = _carrier(spec)
    assert spec.checksum_versions(ck.tag) == tuple(v.id for v in spec.versions if v.id in lay.versions)
    assert set(spec.checksum_versions(ck.tag)) < {v.id for v in spec.versions}  # not every version
    judge = spec.checksum_check(ck.tag)
    assert judge is not None and judge.kind == "arg_checksum" and judge.checksum_field == ck.tag
    assert spec.checksum_check("args") is None  # the head's sum keeps its own kind, unnamed


def test_the_fill_order_puts_the_field_before_the_checksums_that_cover_it(record: Revised) -> None:
    spec, _, _ = record
    _, _, ck = _carrier(spec)
    order = spec.checksums.fill_order
    assert order.index(ck.tag) < order.index("args") < order.index("file")


def test_the_c_tables_hold_the_layouts_ranges_and_judge(record: Revised) -> None:
    spec, _, _ = record
    cmd, lay, ck = _carrier(spec)
    cs = context(spec).checksums
    flat = [x for c in spec.commands for x in c.layouts]
    (row,) = [r for r in cs.argcks if flat[r.layout] is lay]
    assert flat[row.layout] is lay
    assert (row.offset, row.elem) == (ck.field.offset, ck.field.size)
    assert cs.ranges[row.first:row.first + row.n] == ck.ranges
    judge = spec.checksum_check(ck.tag)
    assert judge is not None
    assert cs.ckfields[row.ckfield].tag == ck.tag
    assert cs.ckfields[row.ckfield].check == [c.id for c in spec.checks].index(judge.id)


def test_a_field_no_check_judges_is_refused(record: Revised, tmp_path: Path) -> None:
    spec, path, _ = record
    _, _, ck = _carrier(spec)
    judge = spec.checksum_check(ck.tag)
    assert judge is not None
    doc = drill.read_spec(path)
    drill.apply_edit(doc, {"op": "remove", "path": f"checks[id={judge.id}]"})
    bad = tmp_path / "cbf.yaml"
    bad.write_text(drill._dump(doc), encoding="utf-8")
    with pytest.raises(SpecError, match=f"no arg_checksum check judges checksum {ck.tag}"):
        load(bad)


# -- the assembler -----------------------------------------------------------------------------
def test_the_assembler_fills_the_crc_then_the_argument_checksum(record: Revised) -> None:
    spec, path, fx = record
    cmd, lay, ck = _carrier(spec)
    _, data, _ = _golden(fx, "valid.", path)
    recs = [r for r in _records(spec, data) if r[1] == cmd.code and r[2] == lay.size]
    assert recs
    hs, head_ck = spec.record.head_size, next(f for f in spec.record.fields if f.checksum == "args")
    for pos, _, nb in recs:
        at = pos + hs + ck.field.offset
        stored = int.from_bytes(data[at:at + ck.field.size], "little")
        assert spec.checksums.algorithms[ck.algorithm].kind == "crc16_ccitt"
        assert stored == binascii.crc_hqx(b"".join(data[pos + a:pos + b] for a, b in ck.ranges), 0xFFFF) != 0
        args = data[pos + hs:pos + hs + nb]
        assert int.from_bytes(data[pos + head_ck.offset:pos + head_ck.end], "little") == sum(args) & 0xFFFF


def test_the_assembler_resolves_named_header_fields(header: Revised) -> None:
    spec, path, fx = header
    old = {f.field for f in load(REPO / "spec" / "cbf.yaml").checksums.fields}
    tag = next(f.field for f in spec.checksums.fields if f.field not in old)
    vid = spec.checksum_versions(tag)[0]
    h = spec.header_for(vid)
    holder = next(f for f in h.fields if f.checksum == tag)
    segs = spec.checksums.coverages[spec.checksums.for_field(tag).coverage].segments
    assert all(s.region == "header" and len(s.fields) == 1 for s in segs)
    for s in segs:
        f = h.field(s.fields[0])
        assert f is not None and (s.start, s.end) == (f.offset, f.end)
    _, data, _ = _golden(fx, "valid.", path)
    stored = int.from_bytes(data[holder.offset:holder.end], "little")
    assert stored == binascii.crc_hqx(b"".join(data[s.start:s.end] for s in segs), 0xFFFF) != 0


# -- the bindings ------------------------------------------------------------------------------
def _generate(path: Path, out: Path, only: str) -> None:
    code, _, err = cbfgen_here("--spec", str(path), "--out", str(out), "--only", only, "--no-ksc")
    assert code == 0, err


_PY = textwrap.dedent("""
    import json, sys
    import cbf
    good, bad = open(sys.argv[1], "rb").read(), open(sys.argv[2], "rb").read()
    found = [[f.check, f.severity, f.record, f.offset] for f in cbf.validate(bad)]
    model = cbf.decode(bad)
    refilled = cbf.encode(model)  # the writer fills the CRC (and the sums after it)
    from cbf.testing import reseal_checksums
    print(json.dumps({"good": [f.check for f in cbf.validate(good)], "bad": found,
                      "refilled": refilled == good, "resealed": reseal_checksums(bad) == good}))
""")


def test_python_validates_and_fills_the_field(record: Revised, tmp_path: Path) -> None:
    spec, path, fx = record
    _generate(path, tmp_path / "gen", "python")
    _, good, _ = _golden(fx, "valid.", path)
    _, bad, expect = _golden(fx, "check.", path)
    assert good != bad
    (tmp_path / "good.cbf").write_bytes(good)
    (tmp_path / "bad.cbf").write_bytes(bad)
    done = subprocess.run([sys.executable, "-c", _PY, str(tmp_path / "good.cbf"), str(tmp_path / "bad.cbf")],
                          capture_output=True, text=True, check=False,
                          env={"PYTHONPATH": str(tmp_path / "gen" / "python"), "PATH": "/usr/bin:/bin"})
    assert done.returncode == 0, done.stderr
    got = json.loads(done.stdout)
    assert got["good"] == []
    validate = expect["validate"]
    assert isinstance(validate, dict)
    assert got["bad"] == [[str(x) for x in f[:2]] + list(f[2:]) for f in validate["default"]]
    assert got["refilled"] and got["resealed"]


@pytest.mark.skipif(shutil.which("gcc") is None, reason="no C compiler")
def test_c_validates_the_field_at_its_offset(record: Revised, tmp_path: Path) -> None:
    spec, path, fx = record
    cmd, lay, ck = _carrier(spec)
    _generate(path, tmp_path / "gen", "c")
    tool = tmp_path / "cbf-c"
    built = subprocess.run(["gcc", "-std=c99", "-O0", "-o", str(tool), str(tmp_path / "gen" / "c" / "cbf_tool.c"),
                            "-lm"], capture_output=True, text=True, check=False)
    assert built.returncode == 0, built.stderr
    _, good, _ = _golden(fx, "valid.", path)
    _, bad, _ = _golden(fx, "check.", path)
    judge = spec.checksum_check(ck.tag)
    assert judge is not None
    (tmp_path / "good.cbf").write_bytes(good)
    (tmp_path / "bad.cbf").write_bytes(bad)
    ok = subprocess.run([str(tool), "validate", str(tmp_path / "good.cbf")], capture_output=True, text=True,
                        check=False)
    assert ok.returncode == 0, ok.stdout + ok.stderr
    hs = spec.record.head_size
    (pos,) = [r[0] for r in _records(spec, bad) if r[1] == cmd.code]
    fail = subprocess.run([str(tool), "validate", str(tmp_path / "bad.cbf")], capture_output=True, text=True,
                          check=False)
    assert fail.returncode == 1
    lines = [ln for ln in fail.stdout.splitlines() if " error " in ln]
    assert len(lines) == 1 and f":{pos + hs + ck.field.offset}: error {judge.id} " in lines[0], fail.stdout
    stored = struct.unpack_from("<H", bad, pos + hs + ck.field.offset)[0]
    assert f"stored {ck.tag} checksum {stored}," in lines[0]
    # the C writer fills the field: the bad file decoded and encoded with derived values filled
    # gives the good one (the CRC, then the head's argument checksum over it, then the file's)
    testee = tmp_path / "cbf_testee"
    built = subprocess.run(["gcc", "-std=c99", "-O0", "-o", str(testee), str(tmp_path / "gen" / "c" / "cbf_testee.c"),
                            "-lm"], capture_output=True, text=True, check=False)
    assert built.returncode == 0, built.stderr
    asks = [{"op": "decode", "file": str(tmp_path / "bad.cbf")}]
    first = subprocess.run([str(testee)], input=json.dumps(asks[0]) + "\n", capture_output=True, text=True,
                           check=False, timeout=60)
    decoded = json.loads(first.stdout.splitlines()[0])
    assert decoded["ok"], decoded
    ask = {"op": "encode", "json": decoded["result"], "keep_stored": False, "profile": "default"}
    second = subprocess.run([str(testee)], input=json.dumps(ask) + "\n", capture_output=True, text=True,
                            check=False, timeout=60)
    encoded = json.loads(second.stdout.splitlines()[0])
    assert encoded["ok"], encoded
    assert base64.b64decode(encoded["bytes"]) == good
