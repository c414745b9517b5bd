"""Checksums as data (#12 point 7, #33 point 1): every algorithm kind of the registry, in every runtime.

Each kind is a registry entry (cbfgen/registry.py ALGORITHMS): its parameters and its check value,
the checksum of ASCII "123456789" (the CRC catalogue's "check", a fact of the algorithm, not of
the CBF format). Every kind the registry lists runs here through the Python runtime
(cbf.checksums), the C header (cbf.h's checksum section) and the golden assembler
(conformance/assembler/checksums.py), whole and split into odd pieces (a coverage feeds several
ranges as one stream). A new kind is tested by being registered. The published Fletcher examples
("abcde", "abcdef", "abcdefgh") check the Fletcher family beyond "123456789"; a few catalogue CRCs
the spec does not offer check the CRC family's corners (16-bit reflected, 32-bit not reflected,
refin differing from refout, widths below 8) in the two Python implementations.
"""

from __future__ import annotations

import functools
import shutil
import subprocess
from pathlib import Path
from typing import Any

import pytest
from c_programs import built
from conftest import dump_yaml, load_yaml, spec_doc

from cbf import checksums as runtime
from cbfgen.emit.c.cnames import macro
from cbfgen.loader import SpecError, load
from cbfgen.registry import ALGORITHMS, CHECK_INPUT, ChecksumAlgorithm
from conformance.assembler import checksums as assembler

ROOT = Path(__file__).resolve().parents[1]
SPEC = ROOT / "spec" / "cbf.yaml"


@functools.cache
def _yaml(path: Path) -> Any:
    """A YAML file's data, parsed once (libyaml's parser, the same safe constructors: the
    pure-Python parser took 0.12 CPU s for the spec). Callers that edit it take a deep copy."""
    return load_yaml(path)


# (kind, data, value): every registered kind's check value, then published values of a family
PUBLISHED = [
    ("fletcher16", b"abcde", 0xC8F0),
    ("fletcher16", b"abcdef", 0x2057),
    ("fletcher16", b"abcdefgh", 0x0627),
    ("fletcher32", b"abcde", 0xF04FC729),
    ("fletcher32", b"abcdef", 0x56502D2A),
    ("fletcher32", b"abcdefgh", 0xEBE19591),
]
VECTORS = [(k, CHECK_INPUT, a.check) for k, a in ALGORITHMS.items()] + [v for v in PUBLISHED if v[0] in ALGORITHMS]

# CRCs of the catalogue (reveng) the spec does not offer, with their check values: the CRC
# family's corners, run through both Python implementations from their parameters alone.
CATALOGUE = [
    ChecksumAlgorithm("crc16_arc", "crc", 16, 0xBB3D, "CRC-16/ARC", 0x8005, 0, True, True, 0),
    ChecksumAlgorithm("crc32_mpeg2", "crc", 32, 0x0376E6E7, "CRC-32/MPEG-2", 0x04C11DB7, 0xFFFFFFFF, False, False, 0),
    ChecksumAlgorithm("crc16_xmodem", "crc", 16, 0x31C3, "CRC-16/XMODEM", 0x1021, 0, False, False, 0),
    ChecksumAlgorithm("crc12_umts", "crc", 12, 0xDAF, "CRC-12/UMTS", 0x80F, 0, False, True, 0),
    ChecksumAlgorithm("crc5_usb", "crc", 5, 0x19, "CRC-5/USB", 0x05, 0x1F, True, True, 0x1F),
    ChecksumAlgorithm("crc3_gsm", "crc", 3, 0x4, "CRC-3/GSM", 0x3, 0, False, False, 0x7),
    ChecksumAlgorithm("crc8_smbus", "crc", 8, 0xF4, "CRC-8/SMBUS", 0x07, 0, False, False, 0),
]


def _pieces(data: bytes) -> list[bytes]:
    return [data[:1], data[1:4], b"", data[4:]]


def test_every_runtime_has_every_registered_kind() -> None:
    assert set(runtime.KINDS) == set(ALGORITHMS) == set(assembler.ALGORITHMS)
    assert runtime.PARAMETERS == {k: a.parameters for k, a in ALGORITHMS.items()}


@pytest.mark.parametrize(("kind", "data", "value"), VECTORS)
def test_python_runtime(kind: str, data: bytes, value: int) -> None:
    assert runtime.compute(kind, [data], 4) == value
    assert runtime.compute(kind, _pieces(data), 4) == value
    assert runtime.compute(kind, [memoryview(data)], 4) == value


@pytest.mark.parametrize(("kind", "data", "value"), VECTORS)
def test_assembler(kind: str, data: bytes, value: int) -> None:
    assert assembler.compute(kind, data, 4) == value


@pytest.mark.parametrize("alg", CATALOGUE, ids=lambda a: a.name)
def test_the_crc_family_from_parameters_alone(alg: ChecksumAlgorithm) -> None:
    """Python runtime (its table path and, where the parameters match, zlib or binascii) and
    assembler, each built from the parameters only."""
    params = alg.parameters
    assert runtime._FAMILIES["crc"](params)([CHECK_INPUT]) == alg.check
    assert runtime._FAMILIES["crc"](params)(_pieces(CHECK_INPUT)) == alg.check
    assert assembler._FAMILIES["crc"](alg)(CHECK_INPUT) == alg.check


def test_a_sum_is_reduced_to_its_field_and_nothing_else_is() -> None:
    data = bytes([0xFF]) * 300  # 76500
    total = next(k for k, a in ALGORITHMS.items() if a.family == "sum")
    wide = next(k for k, a in ALGORITHMS.items() if (a.width or 0) > 16)
    assert runtime.compute(total, [data], 2) == assembler.compute(total, data, 2) == 76500 % 65536
    with pytest.raises(ValueError, match="wider than its 2-byte field"):
        assembler.compute(wide, CHECK_INPUT, 2)


def test_the_registry_refuses_parameters_that_do_not_fit() -> None:
    with pytest.raises(ValueError, match="does not fit family crc"):
        ChecksumAlgorithm("crc40", "crc", 40, 0, "too wide for a 32-bit runtime", 1)
    with pytest.raises(ValueError, match="wider than 16 bits"):
        ChecksumAlgorithm("crc16_bad", "crc", 16, 0, "poly too wide", 0x11021)
    with pytest.raises(ValueError, match="does not fit family fletcher"):
        ChecksumAlgorithm("fletcher8", "fletcher", 8, 0, "no such Fletcher")


def _c_program(vectors: list[tuple[str, bytes, int]]) -> str:
    """A C program that prints, for each (kind, data), the checksum whole and split in pieces."""
    rows = ",\n".join(f'    {{ CBF__ALG_{macro(k)}, "{k}", "{d.decode()}" }}' for k, d, _ in vectors)
    return r"""
#define CBF_IMPLEMENTATION
#include "cbf.h"
#include <stdio.h>
static const struct { int alg; const char *name, *data; } cases[] = {
""" + rows + r"""
};
int main(void)
{
    size_t a;
    for (a = 0; a < sizeof cases / sizeof cases[0]; a++) {
        cbf__ck whole, split;
        const char *data = cases[a].data;
        size_t n = strlen(data);
        cbf__ck_init(&whole, cases[a].alg);
        cbf__ck_feed(&whole, (const uint8_t *)data, n);
        cbf__ck_init(&split, cases[a].alg);
        cbf__ck_feed(&split, (const uint8_t *)data, 1u);
        cbf__ck_feed(&split, (const uint8_t *)data + 1, 3u);
        cbf__ck_feed(&split, (const uint8_t *)data + 4, 0u);
        cbf__ck_feed(&split, (const uint8_t *)data + 4, n - 4u);
        printf("%s %s %lu %lu\n", cases[a].name, data, (unsigned long)cbf__ck_value(&whole, 4u),
               (unsigned long)cbf__ck_value(&split, 4u));
    }
    return 0;
}
"""


def test_c_header(tmp_path: Path) -> None:
    cc = shutil.which("gcc")
    if cc is None:
        pytest.skip("gcc not installed")
    src = tmp_path / "ck.c"
    src.write_text(_c_program(VECTORS), encoding="utf-8")
    exe = tmp_path / "ck"
    subprocess.run([cc, "-std=c99", "-Wall", "-Werror", "-Wno-unused-function", "-I", str(ROOT / "generated" / "c"),
                    "-o", str(exe), str(src), "-lm"], check=True, capture_output=True)
    out = subprocess.run([str(exe)], check=True, capture_output=True, text=True).stdout.split("\n")
    got = {(k, d): (int(w), int(s)) for k, d, w, s in (line.split() for line in out if line)}
    assert len(got) == len(VECTORS)
    for kind, data, value in VECTORS:
        assert got[(kind, data.decode())] == (value, value), (kind, data)


# -- the loader: algorithms are data, and a result must fit its field ---------------
def _spec_with(tmp_path: Path, edit: object) -> tuple[Path, list[str]]:
    doc = spec_doc()
    assert callable(edit)
    edit(doc)
    text = dump_yaml(doc, sort_keys=False)
    path = tmp_path / "cbf.yaml"
    path.write_text(text, encoding="utf-8")
    return path, text.splitlines()


def _narrowest(doc: dict[str, Any]) -> tuple[str, int]:
    """The checksum tag whose field is narrowest, and its width in bits (read from the YAML)."""
    sizes = {n: t.get("size") for n, t in doc["types"].items()}
    fields = [f for h in doc["headers"].values() for f in h["fields"]] + doc["record"]["fields"]
    tagged = [(f["checksum"], 8 * sizes[f["type"]]) for f in fields if "checksum" in f]
    return min(tagged, key=lambda t: t[1])


def test_loader_refuses_a_result_wider_than_its_field(tmp_path: Path) -> None:
    doc0 = spec_doc()
    tag, bits = _narrowest(doc0)
    wide = next(name for name, a in doc0["checksums"]["algorithms"].items()
                if (ALGORITHMS[a["kind"]].width or 0) > bits)

    def edit(doc: dict[str, object]) -> None:
        for f in doc["checksums"]["fields"]:  # type: ignore[index]
            if f["field"] == tag:
                f["algorithm"] = wide

    path, lines = _spec_with(tmp_path, edit)
    with pytest.raises(SpecError) as err:
        load(path)
    assert f"algorithm {wide} gives" in err.value.message and f"holds {bits}" in err.value.message
    assert "algorithm:" in lines[err.value.line - 1] and wide in lines[err.value.line - 1]


def test_a_profile_chooses_the_file_algorithm(tmp_path: Path) -> None:
    doc0 = spec_doc()
    pid = doc0["profiles"][-1]["id"]
    current = next(f["algorithm"] for f in doc0["checksums"]["fields"] if f["field"] == "file")
    other = next(n for n, a in doc0["checksums"]["algorithms"].items() if n != current and a["kind"] != "sum")

    def edit(doc: dict[str, object]) -> None:
        doc["profiles"][-1]["file_algorithm"] = other  # type: ignore[index]

    before = load(SPEC)
    path, _ = _spec_with(tmp_path, edit)
    spec = load(path)
    assert spec.file_algorithm(pid) == other
    # every other profile keeps what it had (the field's algorithm, or its own file_algorithm)
    for prof in spec.profiles:
        if prof.id != pid:
            assert spec.file_algorithm(prof.id) == before.file_algorithm(prof.id)

    def bad(doc: dict[str, object]) -> None:
        doc["profiles"][-1]["file_algorithm"] = "no_such_algorithm"  # type: ignore[index]

    path, lines = _spec_with(tmp_path, bad)
    with pytest.raises(SpecError, match="unknown algorithm 'no_such_algorithm'") as err:
        load(path)
    assert "file_algorithm" in lines[err.value.line - 1]


# -- messages: "checksum", never "sums to" -------------------------------------------
@functools.cache
def _checksum_cases() -> tuple[set[str], list[Path]]:
    """The checksum check ids (by kind, from the spec) and the golden files that fail one of them
    (found once for the Python and the C test)."""
    doc = _yaml(SPEC)
    ids = {str(c["id"]) for c in doc["checks"] if c["kind"] in ("file_checksum", "header_checksum", "arg_checksum")}
    golden = ROOT / "conformance" / "golden"
    cases = []
    for exp_path in sorted(golden.glob("*.expect.yaml")):
        exp = _yaml(exp_path)
        if any(str(f[0]) in ids for f in (exp.get("validate") or {}).get("default") or []):
            cases.append(golden / exp_path.name.replace(".expect.yaml", ".cbf"))
    return ids, cases


def _assert_messages(messages: list[str]) -> None:
    assert messages
    for m in messages:
        assert "checksum" in m and "sums to" not in m and "sum to" not in m, m


def test_checksum_messages_python() -> None:
    import cbf

    ids, cases = _checksum_cases()
    found = [f for p in cases for f in cbf.validate(p.read_bytes())]
    assert {f.check for f in found} >= ids
    _assert_messages([f.message for f in found if f.check in ids])


def test_checksum_messages_c() -> None:
    import json

    ids, cases = _checksum_cases()
    testee = built("cbf_testee")  # as make c-build builds it, not compiled again here (c_programs.py)
    req = "".join(json.dumps({"op": "validate", "file": str(p), "profile": "default", "part_number": None,
                              "cutters": None}) + "\n" for p in cases) + '{"op": "quit"}\n'
    ans = subprocess.run([str(testee)], input=req, capture_output=True, text=True, check=True)
    found = [f for line in ans.stdout.splitlines() for f in json.loads(line)["findings"]]
    assert {f["check"] for f in found} >= ids
    _assert_messages([f["message"] for f in found if f["check"] in ids])
