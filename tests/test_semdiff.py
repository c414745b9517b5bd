"""cbf diff: alignment by a sequence matcher, deltas within a tolerance, exit codes, CUT on either side."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path
from typing import Any

import jsonschema
from hypothesis import given
from hypothesis import strategies as st

import cbf
from cbf import semdiff
from cbf import tables as T
from cbf.model import Cbf, Record, new_header
from cbf.semdiff import diff

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"
SCHEMA = json.loads((REPO / "schemas" / "diff.schema.json").read_text(encoding="utf-8"))
V = next(v.id for v in T.VERSIONS if v.writable)
LINE = next(c for c in T.COMMANDS if c.motion and c.motion["kind"] == "line" and "through" not in c.motion
            and not c.orientation and c.layouts_for(V))
TOL = T.TOL["position_mm"]


def _line(x0: float, x1: float) -> Record:
    m = LINE.motion
    assert m
    lay = LINE.layouts_for(V)[0]
    return Record.of(lay.cls(**{m["start"]: (x0, 0.0, 0.0), m["end"]: (x1, 0.0, 0.0)}))


def _chain(n: int) -> list[Record]:
    return [_line(float(i), float(i + 1)) for i in range(n)]


@given(st.integers(1, 60), st.data())
def test_one_inserted_record_is_one_insertion(n: int, data: st.DataObject) -> None:
    recs = _chain(n)
    at = data.draw(st.integers(0, n))
    extra = _line(data.draw(st.floats(-1000, 1000).map(round)), 0.5)
    a = Cbf(new_header(V), recs)
    b = Cbf(new_header(V), recs[:at] + [extra] + recs[at:])
    d = diff(a, b, TOL)
    assert [o.kind for o in d.ops] == ["insert"]
    assert d.ops[0].b == (at, at + 1)
    back = diff(b, a, TOL)
    assert [o.kind for o in back.ops] == ["delete"]


def test_changes_within_the_tolerance_are_equal() -> None:
    a = Cbf(new_header(V), _chain(5))
    moved = _chain(5)
    moved[2] = _line(2.0, 3.0 + TOL / 2)
    assert diff(a, Cbf(new_header(V), moved), TOL).equal
    moved[2] = _line(2.0, 3.0 + 10 * TOL)
    d = diff(a, Cbf(new_header(V), moved), TOL)
    assert [o.kind for o in d.ops] == ["change"]
    (delta,) = d.ops[0].deltas
    assert abs((delta.delta or 0.0) - 10 * TOL) < 1e-6


def _run(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "cbf", *args], capture_output=True, text=True)


def test_cli_exit_codes_json_and_cut_on_either_side(tmp_path: Path) -> None:
    src = GOLDEN / "valid.v3.small.cbf"
    cut = tmp_path / "same.cut"
    cut.write_text(cbf.to_cut(cbf.decode(src.read_bytes())), encoding="utf-8")
    assert _run("diff", str(src), str(cut)).returncode == 0
    assert _run("diff", str(cut), str(src)).returncode == 0
    model = cbf.decode(src.read_bytes())
    plain = next(r for r in model.records if r.command and not (r.command.motion or r.command.shape
                                                                 or r.command.progress or r.command.orientation))
    changed = Cbf(model.header, [*model.records, Record(code=plain.code, raw_args=plain.raw_args)])
    other = tmp_path / "other.cbf"
    other.write_bytes(cbf.encode(changed))
    r = _run("diff", "--json", str(cut), str(other))
    assert r.returncode == 1, r.stderr
    doc: dict[str, Any] = json.loads(r.stdout)
    jsonschema.validate(doc, SCHEMA)
    assert doc["summary"] == {"insert": 1, "delete": 0, "change": 0}
    bad = _run("diff", str(src), str(tmp_path / "missing.cbf"))
    assert bad.returncode == 2 and bad.stderr.count("\n") == 1
    junk = tmp_path / "junk.cut"
    junk.write_text("header X\nnot_a_command 1\n", encoding="utf-8")
    bad = _run("diff", str(src), str(junk))
    assert bad.returncode == 2 and "line 2" in bad.stderr and "Traceback" not in bad.stderr


# -- the matcher (issue 27 item 3): hashes first, the ends by columns, patience in between ----------
def _valid_blocks(a: list[int], b: list[int], blocks: list[tuple[int, int, int]]) -> int:
    """Blocks ascend on both sides, match equal elements, end with the sentinel; the matched count."""
    assert blocks[-1] == (len(a), len(b), 0)
    i0 = j0 = 0
    for i, j, n in blocks[:-1]:
        assert n > 0 and i >= i0 and j >= j0 and a[i:i + n] == b[j:j + n]
        i0, j0 = i + n, j + n
    return sum(n for _, _, n in blocks)


@given(st.lists(st.integers(0, 6), max_size=60), st.lists(st.integers(0, 6), max_size=60))
def test_match_gives_valid_blocks(a: list[int], b: list[int]) -> None:
    _valid_blocks(a, b, semdiff.match(a, b))


@given(st.integers(0, 3000), st.data())
def test_match_finds_every_common_record_of_a_few_edits(n: int, data: st.DataObject) -> None:
    a = list(range(n))
    b = list(a)
    edits = data.draw(st.lists(st.tuples(st.booleans(), st.integers(0, max(n - 1, 0))), max_size=5))
    fresh = n
    for insert, at in edits:
        if insert:
            b.insert(min(at, len(b)), fresh)
            fresh += 1
        elif b:
            del b[min(at, len(b) - 1)]
    common = len(set(a) & set(b))  # distinct elements: every common one is matchable, in order
    assert _valid_blocks(a, b, semdiff.match(a, b)) == common


def _big() -> Cbf:
    return cbf.decode((GOLDEN / "big.v3.65535.cbf").read_bytes())


def test_identical_input_takes_the_fast_path(monkeypatch: Any) -> None:
    def no_hashing(*_: Any) -> list[int]:
        raise AssertionError("identical input hashed its records")

    monkeypatch.setattr(semdiff, "_keys", no_hashing)
    assert diff(_big(), _big(), TOL).equal
    text = cbf.to_cut(_big())  # CUT on both sides: packed columns, compared whole
    assert diff(cbf.from_cut(text), cbf.from_cut(text), TOL).equal


def test_one_change_hashes_only_the_records_between_the_equal_ends(monkeypatch: Any) -> None:
    hashed: list[int] = []
    keys = semdiff._keys

    def counting(c: Any, lo: int, hi: int, ids: Any) -> list[int]:
        hashed.append(hi - lo)
        return keys(c, lo, hi, ids)

    monkeypatch.setattr(semdiff, "_keys", counting)
    a = _big()
    recs = list(a.records)
    at = len(recs) // 2
    other = next(r for r in recs[at + 1:] if r.code == recs[at].code and r.raw_args != recs[at].raw_args)
    b = Cbf(a.header, [*recs[:at], other, *recs[at + 1:]])
    messages: list[str] = []
    d = diff(a, b, TOL, messages.append)
    assert [(o.kind, o.a, o.b) for o in d.ops] == [("change", (at, at + 1), (at, at + 1))]
    assert hashed == [1, 1] and messages  # one record a side; progress heard what ran
