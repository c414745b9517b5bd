"""The facts of 300071 rev 03 itself, read from the seed's text and compared with the model.

This is the one place where the suite holds the content of rev 03: table 5.1
(commands, codes, sizes, arguments, versions), table 4.2 (the header), 4.3
(the record head), the magic numbers, the numbered checks of section 6 and
the plain byte sums of decision C1. Every other test reads its expectations
from the model (cbfgen.loader.load), so that a legitimate format revision
keeps them green. A spec that names another revision (meta.revision) is no
longer rev 03: these facts are then skipped, with the reason, and `cbfgen
diff` (tests/test_diff.py) says what the revision changed.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

import pytest
from conftest import file_checksum_of

import cbf
from cbf import tables as T
from cbfgen.loader import load
from cbfgen.model import Field

REPO = Path(__file__).resolve().parents[1]
SPEC = load(REPO / "spec" / "cbf.yaml")
# The seed lies beside the repository (shared/seed), as shared/kaitai does for
# tests/test_kaitai.py; a worktree one folder deeper finds it one level up.
_CANDIDATES = [base / "shared" / "seed" / "300071-rev03-cbf-spec.txt" for base in (REPO.parent, REPO.parent.parent)]
SEED = next((p for p in _CANDIDATES if p.exists()), _CANDIDATES[0])

pytestmark = [
    pytest.mark.skipif((SPEC.meta["part_number"], SPEC.meta["revision"]) != ("300071", "03"),
                       reason=f"the spec names {SPEC.revision}, not 300071 rev 03: the facts of rev 03 do not apply"),
    pytest.mark.skipif(not SEED.exists(), reason=f"{SEED} is not beside the repository"),
]


@dataclass(frozen=True)
class Row:
    versions: tuple[str, ...]
    name: str
    code: int
    size: int
    args: str


def _text() -> str:
    return SEED.read_text(encoding="utf-8")


def _table_5_1() -> list[Row]:
    text = _text()
    body = text[text.index("Ver#\tCMD CODE\tHEX"): text.index("5.2 ")]
    rows: list[Row] = []
    for line in body.splitlines()[1:]:
        parts = line.split("\t")
        if len(parts) < 5 or not re.fullmatch(r"[0-9,]+", parts[0]):
            continue
        versions = tuple(f"{v}.0" for v in parts[0].split(","))
        args = rows[-1].args if parts[4].startswith("same as above") else parts[4]  # ENDSHAPE
        rows.append(Row(versions, parts[1], int(parts[2], 16), int(parts[3]), args))
    return rows


def _offset_table(after: str) -> list[tuple[int, int, str]]:
    """(start, bytes, description) rows of the first 'Start byte' table after `after`."""
    text = _text()
    body = text[text.index("Start byte", text.index(after)):]
    rows: list[tuple[int, int, str]] = []
    for line in body.splitlines()[1:]:
        m = re.fullmatch(r"(\d+)\t(\d+)\t(.*)", line)
        if not m:
            if rows:
                break
            continue
        rows.append((int(m.group(1)), int(m.group(2)), m.group(3)))
    return rows


def _listed_bytes(args: str) -> int:
    """The argument bytes table 5.1 lists: string(N), float(k), float, byte, 'N bytes reserved' (N2: 4-byte floats)."""
    n = sum(int(x) for x in re.findall(r"string\((\d+)\)", args))
    n += 4 * sum(int(x) for x in re.findall(r"float\((\d+)\)", args))
    n += 4 * len(re.findall(r"float(?!\()", args))
    n += len(re.findall(r"\bbyte\b", args))
    n += sum(int(x) for x in re.findall(r"(\d+) bytes reserved", args))
    return n


def _tiles(fields: tuple[Field, ...], start: int, size: int) -> bool:
    inside = [f for f in fields if start <= f.offset and f.end <= start + size]
    return bool(inside) and inside[0].offset == start and sum(f.size for f in inside) == size


def test_the_seed_is_300071_rev_03() -> None:
    assert "Part No: 300071\tRevision: 03" in _text()
    assert SPEC.revision == "300071 rev 03"


def test_table_5_1_is_the_command_table_of_3_0_and_4_0() -> None:
    rows = _table_5_1()
    assert len(rows) >= 20, "table 5.1 was not found in the seed"
    documented = {v for r in rows for v in r.versions}
    assert documented == {v.id for v in SPEC.writable_versions}
    in_model = {c.name for c in SPEC.commands if any(c.available_in(v) for v in documented)}
    assert in_model == {r.name for r in rows}
    for r in rows:
        cmd = SPEC.command(r.name)
        assert cmd.code == r.code, r.name
        for v in documented:
            assert cmd.available_in(v) == (v in r.versions), (r.name, v)
        declared = cmd.declared_size if cmd.declared_size is not None else cmd.layouts_for(r.versions[0])[0].size
        assert declared == r.size, r.name
        listed = cmd.listed_size if cmd.listed_size is not None else r.size
        assert _listed_bytes(r.args) == listed, (r.name, r.args)


def test_table_5_1_arguments_are_the_layouts_floats_and_strings() -> None:
    for r, vid in [(row, v) for row in _table_5_1() for v in row.versions]:
        lay = SPEC.command(r.name).layouts_for(vid)[0]
        floats = 3 * len(re.findall(r"float\(3\)", r.args)) + len(re.findall(r"float(?!\()", r.args))
        strings = sorted(int(x) for x in re.findall(r"string\((\d+)\)", r.args))
        model_floats = sum(a.count for a in lay.args if a.kind == "float")
        # ORIENT lists its reserved bytes as float(3)
        model_floats += sum(a.size // 4 for a in lay.args if a.reserved and "float" in a.doc)
        assert model_floats == floats, (r.name, vid)
        assert sorted(a.size for a in lay.args if a.kind == "string") == strings, (r.name, vid)


def test_table_4_2_is_the_header_of_3_0_and_4_0() -> None:
    rows = _offset_table("4.2 **File Header**")
    assert rows and sum(n for _, n, _ in rows) == 128
    for vid in ("3.0", "4.0"):
        h = SPEC.header_for(vid)
        assert h.size == 128
        for start, size, what in rows:
            assert _tiles(h.fields, start, size), (vid, start, size, what)
    pattern = SPEC.common_header_field("start_pattern")
    m = re.search(r"0x([0-9A-F]{8})", rows[0][2])
    assert m and pattern.magic == int(m.group(1), 16)
    assert SPEC.common_header_field("end_pattern").magic == 0xFFFFFFFF - int(m.group(1), 16)  # "complement"


def test_table_4_3_is_the_record_head() -> None:
    rows = _offset_table("4.3 **Data Records**")
    fixed = [(s, n, d) for s, n, d in rows]
    assert SPEC.record.head_size == sum(n for _, n, _ in fixed) == 8
    for start, size, what in fixed:
        assert _tiles(SPEC.record.fields, start, size), (start, size, what)


def test_every_numbered_check_of_section_6_and_7_is_a_check() -> None:
    numbered = set(re.findall(r"^\s*-?\s*(6\.\d+\.\d+) ", _text(), re.MULTILINE))
    assert len(numbered) == 11
    assert numbered <= {c.id for c in SPEC.checks}
    assert {"7.2.3.1", "7.2.2.4"} <= {c.id for c in SPEC.checks_of_kind("availability")}


def test_versions_of_rev_03() -> None:
    assert [v.id for v in SPEC.versions] == ["1.x", "2.x", "3.0", "4.0"]
    assert [v.id for v in SPEC.writable_versions] == ["3.0", "4.0"]
    assert "4.1 This document specifies Version 3.0 and 4.0" in _text()
    assert SPEC.default_version == "3.0"


def test_checksums_are_plain_byte_sums_c1() -> None:
    """Decision C1: all three checksums are byte sums; a golden file's stored values are the sums by hand."""
    assert {f.field: SPEC.checksums.algorithms[f.algorithm].kind for f in SPEC.checksums.fields} == {
        "args": "sum", "header": "sum", "file": "sum"}
    for p in SPEC.profiles:  # no profile chooses another algorithm for the file checksum
        assert SPEC.checksums.algorithms[SPEC.file_algorithm(p.id)].kind == "sum", p.id
    data = (REPO / "conformance" / "golden" / "valid.v3.small.cbf").read_bytes()
    assert int.from_bytes(data[4:8], "little") == sum(data[8:]) % 2**32
    assert int.from_bytes(data[8:10], "little") == sum(data[10:128]) % 2**16
    nb = data[128 + 4]
    assert int.from_bytes(data[128 + 6:128 + 8], "little") == sum(data[136:136 + nb]) % 2**16




def test_issue_13_implausible_values_fall_outside_the_default_machine() -> None:
    """#13 item 16: rev 03 states no range for these values; the default machine (L1) puts a speed
    of 1e30 m/s, a POINT at 1e30 mm and a cutter radius of 1e-30 mm outside it, in the units the
    spec gives (6.1.2 millimetres; N11). conformance/golden/check.machine_limits.default holds
    those three values and expects one warning each (and tests/test_machine_limits.py the rest)."""
    ch = SPEC.check("machine_limits")
    limit_of = {(t.command, a): SPEC.machine.limit(t.limit) for t in ch.targets if t.limit for a in t.args}
    speed, point, radius = limit_of[("SPEED", "speed")], limit_of[("POINT", "point")], limit_of[("CUTTER", "radius")]
    assert (speed.unit, point.unit, radius.unit) == ("m/s", "mm", "mm")
    assert speed.max[0] < 1e30 and all(hi < 1e30 for hi in point.max) and radius.min[0] > 1e-30
    assert "0.01 millimeters" in _text()  # 6.1.2: cutter sizes in millimetres
    assert (ch.severity, ch.input_severity) == ("warning", "error")


# The CUT companion document (issue 26): a CUT file written from generated/docs/cut.md alone, with rev
# 03's commands and versions (so it lives here, not in tests/test_cut_companion.py). Each line names the
# section of the document it follows.
HAND = """\
header PN-1234 KNEE FEMORAL SIZE 3
header_ext ROBODOC CFG 7
cbf_version 4.0
comment   hand-written from the companion doc
cutter C6-BALL 100.5 3 12.25
speed 0.05
accel 1.5 2
phase ROUGH
point <0,0,0>
cutter_on
startshape SQ 2
line < 0, 0, 0 > < 10, 0, 0 >
line <10, 0, 0> <10, -2.5, 0>
endshape SQ 2
checkpoint CP1 < 10, -2.5, 0 > 50
orient5b < 0, 0, 1 > < 0, 0.5, 1 >
guide Remove the cutter now
CUTTER_OFF
version 1.0 4.0
"""
HAND_SECTIONS = [
    "3 header: the implant descriptor, part number first (4.2, 6.1.1)",
    "3 header_ext: the configuration descriptor",
    "5 version choice: cbf_version sets the header version (4.0)",
    "2 text: the rest of the line, spaces before it dropped (1.2)",
    "4 cutter: word, float, float, float (the reserved bytes have no token)",
    "4 speed: float",
    "4 accel: float float",
    "4 phase: word",
    "2 vector: spaces around < , > are optional",
    "4 cutter_on: no arguments",
    "4 startshape: word, integer (byte)",
    "2 vector, float: digits with an optional point",
    "2 float: a leading minus, a point and digits",
    "4 endshape: the same word and integer (X2)",
    "4 checkpoint: word, vector, float",
    "4 orient5b: two vectors (D6: need not be of unit length)",
    "2 text: GUIDE's message is the rest of the line",
    "1.3 command keywords in any letter case",
    "5 the VERSION command: a record, its format string sets nothing",
]


def test_a_hand_written_cut_file_encodes_and_validates() -> None:
    assert len(HAND_SECTIONS) == len(HAND.splitlines())
    model = cbf.from_cut(HAND)
    assert model.version_id == "4.0"
    data = cbf.encode(model)
    assert [f for f in cbf.validate(data) if f.severity == "error"] == []
    back = cbf.decode(data)
    assert back.header.implant_descriptor == "PN-1234 KNEE FEMORAL SIZE 3"
    args = back.records[0].decode_args()
    assert args is not None and args.text == "hand-written from the companion doc"
    # with the check line the document describes (section 3), the same file reads the same
    assert cbf.from_cut(HAND + f"{T.CUT['checksum_keyword']} {file_checksum_of(data)}\n") == model
