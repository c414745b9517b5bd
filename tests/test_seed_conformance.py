"""The published document against 300071 rev 03 itself (issue 26).

The seed, shared/seed/300071-rev03-cbf-spec.txt, lies beside the repository
(CI clones the repository into a fresh folder with a copy of shared/ beside it;
a developer's worktree may sit one folder deeper, so every ancestor of the
repository is tried). The test reads its tables 4.2, 4.3 and 5.1 and its
numbered clause texts, and checks that the normative sections (1 to 7) of the
reference page generated from spec/cbf.yaml state every one of them under the
same clause id: the clause texts verbatim, every start byte and size of 4.2
and 4.3, every Ver#, code, size and argument type list of 5.1, a check of
every clause of 6.x. Where the page differs from the seed (a row of 5.1, a
value of 4.2) the row must name a decision or an erratum of the spec, and each
erratum must be shown at the clause it corrects. Then the spec is edited, one
seed value at a time, and the same comparison must fail.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest
from conftest import dump_yaml, spec_doc

from cbfgen.emit import docs
from cbfgen.loader import load

REPO = Path(__file__).resolve().parents[1]
SEED_NAME = "300071-rev03-cbf-spec.txt"


def _seed_path() -> Path | None:
    for folder in REPO.parents:
        candidate = folder / "shared" / "seed" / SEED_NAME
        if candidate.is_file():
            return candidate
    return None


SEED_PATH = _seed_path()
_META = load(REPO / "spec" / "cbf.yaml").meta
# The seed is rev 03: compared with a spec that names another revision, every difference is the revision's
# (a rev-03 fact, as in tests/test_rev03_facts.py; `cbfgen diff` says what the revision changed).
pytestmark = [
    pytest.mark.skipif((_META["part_number"], _META["revision"]) != ("300071", "03"),
                       reason=f"the spec names {_META['part_number']} rev {_META['revision']}, not the seed's rev 03"),
    pytest.mark.skipif(SEED_PATH is None, reason=f"shared/seed/{SEED_NAME} is not beside the repository "
                                                 "(CI copies shared/ beside its clone)"),
]


# -- the seed ------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Seed:
    clauses: dict[str, str]  # clause id -> text
    header: list[tuple[str, str, str]]  # 4.2: (start byte, # bytes, description)
    record: list[tuple[str, str, str]]  # 4.3
    commands: list[tuple[str, str, str, str, list[str]]]  # 5.1: (Ver#, name, hex, bytes, argument types)


def _types(arguments: str) -> list[str]:
    """The argument types of a 5.1 row ("name: float(3)" -> "float(3)", "4 bytes reserved" -> "4 bytes")."""
    out = []
    for piece in arguments.rstrip(";").split(", "):
        piece = piece.strip().rstrip(";")
        m = re.fullmatch(r"(\d+) bytes reserved", piece)
        if m:
            out.append(f"{m.group(1)} bytes")
        elif ":" in piece:
            out.append(piece.rsplit(":", 1)[1].strip())
    return out


def _table(lines: list[str], head: str) -> list[list[str]]:
    start = next(k for k, line in enumerate(lines) if line.startswith(head)) + 1
    rows = []
    for line in lines[start:]:
        if not line.strip():
            break
        rows.append([cell.strip() for cell in line.split("\t")])
    return rows


def read_seed(text: str) -> Seed:
    lines = text.splitlines()
    clauses: dict[str, str] = {}
    for line in lines:
        m = re.match(r"^\s*(?:-\s*)?(\d\.\d+(?:\.\d+)*)\s+(?:\*\*[^*]+\*\*\s*-\s*)?(.*\S)\s*$", line)
        if m and not re.match(r"^\d", m.group(2)):
            clauses.setdefault(m.group(1), m.group(2))
    head = "Start byte\t# bytes\tDescription"
    idx = [k for k, line in enumerate(lines) if line.startswith(head)]
    header = [(r[0], r[1], r[2]) for r in _table(lines[idx[0]:], head)]
    record = [(r[0], r[1], r[2]) for r in _table(lines[idx[1]:], head)]
    commands: list[tuple[str, str, str, str, list[str]]] = []
    for r in _table(lines, "Ver#\tCMD CODE"):
        types = _types(r[4]) if "same as above" not in r[4] else list(commands[-1][4])
        commands.append((r[0], r[1], r[2], r[3], types))
    return Seed(clauses, header, record, commands)


# -- the generated normative sections ------------------------------------------------------------
def normative(page: str) -> str:
    """Sections 1 to 7 of the reference page (the appendices cut off)."""
    return page[page.index('<a id="section-1"></a>'):page.index('<a id="appendices"></a>')]


def _unescape(text: str) -> str:
    return re.sub(r"\\(.)", r"\1", text)


def clause_block(page: str, cid: str) -> str | None:
    m = re.search(rf'<a id="clause-{re.escape(docs._anchor(cid))}"></a>\n(.*?)(?=<a id="clause-|<a id="section-|\Z)',
                  page, re.S)
    return m.group(1) if m else None


def _rows(block: str) -> list[list[str]]:
    rows = []
    lines = block.splitlines()
    for k, line in enumerate(lines):
        heading = k + 1 < len(lines) and lines[k + 1].startswith("|---")
        if line.startswith("| ") and not heading:
            rows.append([c.strip() for c in re.split(r"(?<!\\)\|", line.strip())[1:-1]])
    return rows


def _text(cell: str) -> str:
    return _unescape(re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", re.sub(r"<[^>]+>", "", cell)))


def problems(seed: Seed, page: str, note_ids: set[str], errata: dict[str, str]) -> list[str]:
    """Where the normative sections of page fail to state the seed (empty when they state all of it)."""
    body = normative(page)
    out: list[str] = []
    has_note = re.compile(r"\b(" + "|".join(map(re.escape, sorted(note_ids))) + r")\b")
    for cid, text in seed.clauses.items():
        block = clause_block(body, cid)
        if block is None:
            out.append(f"{cid}: no clause with this id")
            continue
        quoted = " ".join(_unescape(line[2:]) for line in block.splitlines() if line.startswith("> ")
                          and not re.match(r"> (Decision|Erratum) ", line))
        if " ".join(text.split()) not in " ".join(quoted.split()):
            out.append(f"{cid}: the clause text is not the seed's: {text!r}")
        if cid.startswith("6.") and cid.count(".") == 2 and f"Check `{cid}`" not in block:
            out.append(f"{cid}: no check under the clause")
    for eid, cid in errata.items():
        block = clause_block(body, cid) or ""
        if f"Erratum [{eid}]" not in block:
            out.append(f"{cid}: erratum {eid} is not shown at the clause it corrects")
    for label, seed_rows, anchor in (("4.2", seed.header, "Table 4.2"), ("4.3", seed.record, "Table 4.3")):
        block = clause_block(body, label) or ""
        tables = block[block.find(anchor):] if anchor in block else ""
        rows = _rows(tables)
        for start, size, desc in seed_rows:
            row = next((r for r in rows if r[0] == start and r[1] == size), None)
            if row is None:  # one field of the seed as several of the spec: they must fill it and say why
                k = next((k for k, r in enumerate(rows) if r[0] == start), None)
                run: list[list[str]] = []
                while k is not None and k < len(rows) and rows[k][1].isdigit() and \
                        sum(int(r[1]) for r in run) < int(size):
                    run.append(rows[k])
                    k += 1
                if not run or sum(int(r[1]) for r in run) != int(size) or not any(
                        has_note.search(" ".join(r)) for r in run):
                    out.append(f"{label}: no row at start byte {start} of {size} bytes ({desc}), nor rows that "
                               f"fill it and name a decision")
                    continue
                row = [c for r in run for c in r]
            words = re.split(r"\s*[(:]", desc)[0]  # the field's name as the seed gives it
            if words.lower() not in _text(" ".join(row)).lower():
                out.append(f"{label}: start byte {start}: the description does not name {words!r}")
            for value in re.findall(r"0x[0-9A-Fa-f]+", desc):
                if value.upper() not in " ".join(row).upper():
                    out.append(f"{label}: start byte {start}: {value} is not stated")
            if desc.startswith("Special pattern") and "e.g." in desc and not has_note.search(" ".join(row)):
                out.append(f"{label}: start byte {start}: the seed's example value is made a fixed value without "
                           f"a decision id")
    block = clause_block(body, "5.1") or ""
    table = {_text(r[1]): r for r in _rows(block[block.find("Table 5.1"):])} if "Table 5.1" in block else {}
    seen = set()
    for ver, name, hexcode, size, types in seed.commands:
        row = table.get(name)
        if row is None:
            out.append(f"5.1: {name} is not in the table")
            continue
        seen.add(name)
        arg_types = _types(", ".join(_text(row[4]).split(", ")))
        got = (row[0], row[2], row[3], arg_types)
        want = (ver, hexcode, size, types)
        for what, g, w in zip(("Ver#", "HEX", "# bytes", "argument types"), got, want, strict=True):
            if g != w and not has_note.search(row[5]):
                out.append(f"5.1: {name}: {what} {g!r}, the seed says {w!r}, and the row names no decision or "
                           f"erratum")
    for name, cells in table.items():
        if name not in seen and not has_note.search(cells[5]):
            out.append(f"5.1: {name} is not in the seed's table, and the row names no decision or erratum")
    return out


# -- the tests -----------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def seed() -> Seed:
    assert SEED_PATH is not None
    return read_seed(SEED_PATH.read_text(encoding="utf-8"))


def _check(seed: Seed, spec_path: Path) -> list[str]:
    spec = load(spec_path)
    notes = {d.id for d in spec.decisions} | {e.id for e in spec.errata}
    return problems(seed, docs.reference(spec), notes, {e.id: e.clause or "" for e in spec.errata})


def test_the_seed_is_read_whole(seed: Seed) -> None:
    """The reader of the seed finds what the seed holds (else the comparison would pass on nothing)."""
    assert len(seed.header) == 9 and len(seed.record) == 7 and len(seed.commands) == 27
    assert {"1.1", "4.2", "5.1", "6.1.1", "6.4.5", "7.2.3.1"} <= set(seed.clauses)
    assert [c for c in seed.clauses if c.startswith("6.")] == [
        "6.1", "6.1.1", "6.1.2", "6.2", "6.2.1", "6.2.2", "6.3", "6.3.1", "6.3.2",
        "6.4", "6.4.1", "6.4.2", "6.4.3", "6.4.4", "6.4.5"]
    assert seed.commands[0] == ("3,4", "CHECKPOINT", "3C", "32", ["string(16)", "float(3)", "float"])


def test_the_published_document_states_the_seed(seed: Seed) -> None:
    assert _check(seed, REPO / "spec" / "cbf.yaml") == []


def test_the_committed_document_states_the_seed(seed: Seed) -> None:
    page = (REPO / "generated" / "docs" / "index.md").read_text(encoding="utf-8")
    spec = load(REPO / "spec" / "cbf.yaml")
    notes = {d.id for d in spec.decisions} | {e.id for e in spec.errata}
    assert problems(seed, page, notes, {e.id: e.clause or "" for e in spec.errata}) == []


def _command(doc: dict[str, Any], name: str) -> dict[str, Any]:
    return next(c for c in doc["commands"] if c["name"] == name)


def _clause(doc: dict[str, Any], cid: str) -> dict[str, Any]:
    return next(c for c in doc["meta"]["clauses"] if c["number"] == cid)


def _field(doc: dict[str, Any], name: str) -> dict[str, Any]:
    return next(f for f in doc["headers"]["v2"]["fields"] if f["name"] == name)


EDITS: dict[str, Callable[[dict[str, Any]], object]] = {
    # 5.1: a code, a size (every layout of 3.0 and 4.0), an argument type, the versions that have a command
    "code": lambda d: _command(d, "LINE").update(code=0xB5),
    "size": lambda d: _command(d, "SPEED")["layouts"][0]["args"].append(
        {"name": "extra", "type": "f4", "doc": "x"}) or _command(d, "SPEED")["layouts"][0].update(size=8),
    "arg_type": lambda d: _command(d, "PHASE")["layouts"][0]["args"][0].update(size=15) or
    _command(d, "PHASE")["layouts"][0]["args"].append({"name": "pad", "type": "bytes", "size": 1, "reserved": True,
                                                        "doc": "pad"}),
    "versions": lambda d: _command(d, "ARC")["layouts"][0]["versions"].append("4.0") or next(
        k for k in d["checks"] if k["id"] == "7.2.3.1")["commands"].remove("ARC"),
    # 4.2: an offset and size; the start pattern's value without its decision
    "header_field": lambda d: _field(d, "configuration_descriptor").update(size=33) or d["headers"]["v2"][
        "fields"].insert(8, {"name": "pad", "offset": 121, "type": "bytes", "size": 1, "role": "reserved",
                             "clause": "4.2", "doc": "pad"}),
    "magic_note": lambda d: _field(d, "start_pattern").update(doc="Special pattern indicating cutting file."),
    # 4.3: the record head
    "record_field": lambda d: d["record"]["fields"][4].update(name="flags", doc="Flags."),
    # 6.x and others: a clause text, a check's id, an erratum dropped
    "clause_text": lambda d: _clause(d, "6.4.4").update(text="The checksum of the argument bytes must match."),
    "check_id": lambda d: next(k for k in d["checks"] if k["id"] == "6.2.2").update(id="count"),
    "erratum": lambda d: _clause(d, "6.4.3").update(notes=["D5"]),
}


@pytest.mark.parametrize("edit", sorted(EDITS))
def test_a_seed_value_changed_in_the_spec_is_found(seed: Seed, edit: str, tmp_path: Path) -> None:
    doc = spec_doc()
    EDITS[edit](doc)
    path = tmp_path / "cbf.yaml"
    path.write_text(dump_yaml(doc, sort_keys=False), encoding="utf-8")
    assert _check(seed, path) != [], edit
