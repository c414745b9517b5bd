"""The reliability campaign (conformance/reliability) can fail, and its parts do what they say."""

from __future__ import annotations

import random
import sys
import tracemalloc
from pathlib import Path

import pytest
from conftest import load_yaml

import cbf
from conformance.reliability.campaign import Base, Pool, Scratch, compare, detection, valid_bases
from conformance.reliability.mutate import (
    Framing,
    bit_flips,
    byte_sets,
    compensating_pairs,
    record_swaps,
    sample_offsets,
    transpositions,
    truncations,
)
from conformance.runner import testee
from conformance.runner.testee import Binding

REPO = Path(__file__).resolve().parents[1]
SMALL = (REPO / "conformance" / "golden" / "valid.v3.small.cbf").read_bytes()
BIG = (REPO / "conformance" / "golden" / "big.v3.65535.cbf").read_bytes()
FRAMING = Framing.from_spec()


def test_exhaustive_mutations_cover_every_offset() -> None:
    flips = list(bit_flips(SMALL))
    assert len(flips) == 8 * len(SMALL)
    assert all(sum(a != b for a, b in zip(m.data, SMALL, strict=True)) == 1 for m in flips)
    sets = list(byte_sets(SMALL))
    assert len(sets) == sum((b != 0) + (b != 0xFF) for b in SMALL)  # unchanged bytes are skipped
    assert sorted(len(m.data) for m in truncations(SMALL)) == list(range(len(SMALL)))


def test_blind_spot_mutations_keep_the_byte_sum() -> None:
    rng = random.Random(1)
    for m in list(transpositions(SMALL)) + list(compensating_pairs(SMALL, rng, 50)):
        assert sum(m.data) == sum(SMALL) and m.data != SMALL
    swaps = list(record_swaps(SMALL, FRAMING))
    assert swaps and all(sorted(m.data) == sorted(SMALL) and len(m.data) == len(SMALL) for m in swaps)


def test_framing_and_samples_come_from_the_spec() -> None:
    recs = FRAMING.records(BIG)
    assert len(recs) == 65535 and recs[0][0] == FRAMING.header_size and recs[-1][1] == len(BIG)
    offs = sample_offsets(BIG, FRAMING, random.Random(7), 100)
    assert offs == sorted(set(offs)) and set(range(FRAMING.header_size)) <= set(offs)
    assert recs[-1][0] in offs and len(offs) < 500


def test_a_binding_that_misses_corruption_fails_the_campaign(tmp_path: Path) -> None:
    """A testee that validates everything as clean: every mutant is listed as a miss."""
    blind = tmp_path / "blind.py"
    blind.write_text("import sys, json\nfor line in sys.stdin:\n"
                     "    r = json.loads(line)\n"
                     "    if r.get('op') == 'quit': break\n"
                     "    print(json.dumps({'ok': True, 'findings': []}), flush=True)\n", encoding="utf-8")
    pool = Pool(Binding("blind", [sys.executable, str(blind)]))
    scratch = Scratch()
    try:
        data = SMALL[:140]
        res = detection(pool, [Base("cut", data, "default")], scratch, {})
    finally:
        pool.close()
        scratch.remove()
    assert res["truncation"]["trials"] == len(data) and res["truncation"]["detected"] == 0
    assert len(res["bit_flip"]["misses"]) == 8 * len(data)
    assert res["bit_flip"]["misses"][0] == {"file": "cut", "offset": 0, "detail": "bit_flip bit 0"}


def test_the_real_codec_detects_corruption_of_a_small_file() -> None:
    pool = Pool(Binding("python", ["{python}", "conformance/testees/python/testee.py"],
                        {"PYTHONPATH": "{repo}/generated/python"}))
    scratch = Scratch()
    try:
        res = detection(pool, [Base("small", SMALL[:168], "default")], scratch, {})
    finally:
        pool.close()
        scratch.remove()
    for cls, row in res.items():
        assert row["trials"] > 0 and row["detected"] == row["trials"], (cls, row["misses"][:3])


def test_valid_bases_are_the_error_free_golden_files() -> None:
    bases = valid_bases(600)
    names = {b.name for b in bases}
    assert "valid.v3.small" in names and "valid.implib.checksum" in names
    assert "check.6.4.4.arg_checksum" not in names and "truncated.args" not in names
    for b in bases:  # warnings allowed, errors not, under the profile the base is used with
        doc = load_yaml(REPO / "conformance" / "golden" / f"{b.name}.expect.yaml")
        assert not [f for f in doc["validate"][b.profile] if f[1] == "error"], b


def test_distinct_bases_drop_only_repeated_bytes() -> None:
    """--quick mutates each file once: the distinct bases hold the same bytes (and profiles) as all
    of them, each once."""
    every, distinct = valid_bases(700), valid_bases(700, distinct=True)
    assert {(b.data, b.profile) for b in distinct} == {(b.data, b.profile) for b in every}
    assert len({(b.data, b.profile) for b in distinct}) == len(distinct)


OK = {"ok": True, "result": {"header": {}, "records": [], "trailing": ""}}
KINDS = {"6.4.2": "code_copy", "6.2.1": "file_checksum"}


@pytest.mark.parametrize(("ref_val", "dec", "val", "structural", "agree"), [
    ({"findings": []}, OK, {"findings": []}, False, True),
    ({"findings": [{"check": "6.2.1"}]}, OK, {"findings": []}, False, False),  # a finding the binding missed
    ({"findings": []}, {"ok": False, "error": {"kind": "truncated_record", "offset": 128}}, None, False, False),
    # Kaitai may reject what the reference flags with a valid: rule, and nothing else
    ({"findings": [{"check": "6.4.2"}]}, {"ok": False, "error": {"kind": "validation", "offset": 0}}, None, True, True),
    ({"findings": [{"check": "6.2.1"}]}, {"ok": False, "error": {"kind": "validation", "offset": 0}}, None, True,
     False),
    ({"findings": []}, {"ok": False, "error": {"kind": "exception", "offset": None}}, None, True, False),
])
def test_differential_comparison_rules(ref_val: dict[str, object], dec: dict[str, object],
                                       val: dict[str, object] | None, structural: bool, agree: bool) -> None:
    assert (compare(OK, ref_val, dec, val, structural, KINDS) is None) is agree


def test_nan_payloads_may_differ_only_for_kaitai() -> None:
    a = {"ok": True, "result": {"records": [{"args": {"x": "0x7fa00000"}}]}}
    b = {"ok": True, "result": {"records": [{"args": {"x": "0x7fe00000"}}]}}
    assert compare(a, {"findings": []}, b, None, True, {}) is None
    assert compare(a, {"findings": []}, b, None, False, {}) is not None


def test_memory_stays_bounded_on_the_biggest_file_and_on_lying_counts() -> None:
    cbf.validate(cbf.decode(BIG))  # imports and table caches first: they are not per file
    tracemalloc.start()
    try:
        cbf.validate(cbf.decode(BIG))
        _, peak = tracemalloc.get_traced_memory()
        assert peak < 12 * len(BIG), peak
        tracemalloc.reset_peak()
        liar = bytearray(BIG[:FRAMING.header_size])
        at, size = FRAMING.count_fields[0]
        liar[at:at + size] = b"\xff" * size  # 65,535 records claimed, none present
        found = cbf.validate(bytes(liar))
        _, peak = tracemalloc.get_traced_memory()
        assert peak < 1_000_000, peak
        assert any(f.as_dict()["check"] == "6.2.2" for f in found)
    finally:
        tracemalloc.stop()


def test_the_report_names_an_out_path_outside_the_repository(tmp_path: Path) -> None:
    """--out outside the checkout is named whole (it raised ValueError, a traceback, after the whole run)."""
    from conformance.reliability.__main__ import shown

    assert shown(tmp_path / "r.json") == str((tmp_path / "r.json").resolve())
    assert shown(REPO / "build" / "reliability" / "r.json") == str(Path("build") / "reliability" / "r.json")


def test_a_testee_that_exits_mid_campaign_is_named_on_one_line(tmp_path: Path) -> None:
    """A binding's testee that exits on a file (a Kaitai printer that met an integer type it did not know) stops
    the campaign with its binding's name, not a traceback from deep in the pool."""
    pool = Pool(Binding(name="exits", command=[sys.executable, "-c", "import sys; sys.stdin.readline()"],
                        cwd=tmp_path))
    try:
        with pytest.raises(testee.TesteeError, match=r"^exits: testee exited \(its stderr is above\)$"):
            pool.many([{"op": "decode", "file": str(tmp_path / "x.cbf")}])
    finally:
        pool.close()
