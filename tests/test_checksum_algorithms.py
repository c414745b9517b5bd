"""Checksums as data (#12 point 7): every algorithm kind, once per runtime, against published values.

The check values are facts of the algorithms, not of the CBF format: the
"123456789" check of the CRC catalogue (reveng) for the CRCs, and the
published Fletcher examples ("abcde", "abcdef", "abcdefgh"). Each is run
through the Python runtime (cbf.checksums), the C header (cbf.h's checksum
section) and the golden assembler (conformance/assembler/checksums.py), whole
and split into odd pieces (a coverage feeds several ranges as one stream).
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
from cbfgen.loader import SpecError, load
from cbfgen.model import ALGORITHM_KINDS
from conformance.assembler import checksums as assembler

ROOT = Path(__file__).resolve().parents[1]
SPEC = ROOT / "spec" / "cbf.yaml"


@functools.cache
def _yaml(path: Path) -> Any:
    """A YAML file's data, parsed once (libyaml's parser, the same safe constructors: the
    pure-Python parser took 0.12 CPU s for the spec). Callers that edit it take a deep copy."""
    return load_yaml(path)



# (kind, data, value): published check values
VECTORS = [
    ("sum", b"123456789", 477),
    ("crc16_ccitt", b"123456789", 0x29B1),  # CRC-16/CCITT-FALSE
    ("crc32", b"123456789", 0xCBF43926),  # CRC-32/ISO-HDLC
    ("crc32c", b"123456789", 0xE3069283),  # CRC-32/ISCSI
    ("fletcher16", b"abcde", 0xC8F0),
    ("fletcher16", b"abcdef", 0x2057),
    ("fletcher16", b"abcdefgh", 0x0627),
    ("fletcher32", b"abcde", 0xF04FC729),
    ("fletcher32", b"abcdef", 0x56502D2A),
    ("fletcher32", b"abcdefgh", 0xEBE19591),
]


def _pieces(data: bytes) -> list[bytes]:
    return [data[:1], data[1:4], b"", data[4:]]


def test_vectors_cover_every_kind() -> None:
    assert {k for k, _, _ in VECTORS} == set(ALGORITHM_KINDS) == set(runtime.KINDS) == set(assembler.ALGORITHMS)


@pytest.mark.parametrize(("kind", "data", "value"), VECTORS)
def test_python_runtime(kind: str, data: bytes, value: int) -> None:
    assert runtime.compute(kind, [data], 4) == value
    assert runtime.compute(kind, _pieces(data), 4) == value
    assert runtime.compute(kind, [memoryview(data)], 4) == value


@pytest.mark.parametrize(("kind", "data", "value"), VECTORS)
def test_assembler(kind: str, data: bytes, value: int) -> None:
    assert assembler.compute(kind, data, 4) == value


def test_a_sum_is_reduced_to_its_field_and_nothing_else_is() -> None:
    data = bytes([0xFF]) * 300  # 76500
    assert runtime.compute("sum", [data], 2) == assembler.compute("sum", data, 2) == 76500 % 65536
    with pytest.raises(ValueError, match="wider than its 2-byte field"):
        assembler.compute("crc32", b"123456789", 2)


C_PROGRAM = r"""
#define CBF_IMPLEMENTATION
#include "cbf.h"
#include <stdio.h>
static const char *data[] = { "123456789", "abcde", "abcdef", "abcdefgh" };
static const int kinds[] = { CBF__ALG_SUM, CBF__ALG_CRC16_CCITT, CBF__ALG_CRC32, CBF__ALG_CRC32C,
                             CBF__ALG_FLETCHER16, CBF__ALG_FLETCHER32 };
static const char *names[] = { "sum", "crc16_ccitt", "crc32", "crc32c", "fletcher16", "fletcher32" };
int main(void)
{
    size_t a, d;
    for (a = 0; a < sizeof kinds / sizeof kinds[0]; a++) {
        for (d = 0; d < sizeof data / sizeof data[0]; d++) {
            cbf__ck whole, split;
            size_t n = strlen(data[d]);
            cbf__ck_init(&whole, kinds[a]);
            cbf__ck_feed(&whole, (const uint8_t *)data[d], n);
            cbf__ck_init(&split, kinds[a]);
            cbf__ck_feed(&split, (const uint8_t *)data[d], 1u);
            cbf__ck_feed(&split, (const uint8_t *)data[d] + 1, 3u);
            cbf__ck_feed(&split, (const uint8_t *)data[d] + 4, 0u);
            cbf__ck_feed(&split, (const uint8_t *)data[d] + 4, n - 4u);
            printf("%s %s %lu %lu\n", names[a], data[d], (unsigned long)cbf__ck_value(&whole, 4u),
                   (unsigned long)cbf__ck_value(&split, 4u));
        }
    }
    return 0;
}
"""


def test_c_header(tmp_path: Path) -> None:
    cc = shutil.which("gcc")
    if cc is None:
        pytest.skip("gcc not installed")
    src = tmp_path / "ck.c"
    src.write_text(C_PROGRAM, encoding="utf-8")
    exe = tmp_path / "ck"
    subprocess.run([cc, "-std=c99", "-Wall", "-Werror", "-Wno-unused-function", "-I", str(ROOT / "generated" / "c"),
                    "-o", str(exe), str(src), "-lm"], check=True, capture_output=True)
    out = subprocess.run([str(exe)], check=True, capture_output=True, text=True).stdout.split("\n")
    got = {(k, d): (int(w), int(s)) for k, d, w, s in (line.split() for line in out if line)}
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


def _narrowest(doc: dict[str, object]) -> tuple[str, int]:
    """The checksum tag whose field is narrowest, and its width in bits (read from the YAML)."""
    sizes = {n: t.get("size") for n, t in doc["types"].items()}  # type: ignore[attr-defined]
    fields = [f for h in doc["headers"].values() for f in h["fields"]] + doc["record"]["fields"]  # type: ignore[attr-defined]
    tagged = [(f["checksum"], 8 * sizes[f["type"]]) for f in fields if "checksum" in f]
    return min(tagged, key=lambda t: t[1])


def test_loader_refuses_a_result_wider_than_its_field(tmp_path: Path) -> None:
    doc0 = spec_doc()
    tag, bits = _narrowest(doc0)
    wide = next(name for name, a in doc0["checksums"]["algorithms"].items()
                if (ALGORITHM_KINDS[a["kind"]] or 0) > bits)

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
