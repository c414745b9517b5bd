"""Near-miss specs (issue 24, point 3): each is refused by the loader with a line, or generates,
compiles and passes conformance in every binding (tests/near_miss.py says what that means).

The specs are drawn from the real spec/cbf.yaml by a few edits of the kinds a format owner makes
and the bindings once disagreed on: a second check of a kind, ``versions:`` on a check, a new type
(registered or not, used or not), a header layout that diverges from the others, a range without
a bound, other texts and names. Every draw reads the spec it edits (its checks, commands, fields),
so the test holds under any revision.

`make test` runs it derandomised with few examples (each accepted spec costs a generation, a C
compile and a ksc run, about 2 CPU s); `make test-long` (HYPOTHESIS_PROFILE=long) runs it random,
with more.
"""

from __future__ import annotations

import copy
import itertools
import os
import string
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import near_miss
import pytest
from conftest import spec_doc
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st
from near_miss import judge, write_spec

from cbfgen.emit.kaitai import build
from cbfgen.loader import load
from cbfgen.registry import CHECK_KINDS, TYPES


@pytest.fixture(scope="module", autouse=True)
def _ksc_server() -> Iterator[None]:
    """The examples share one ksc process (tests/ksc_serve.py), stopped with the module."""
    yield
    near_miss.close()


LONG = os.environ.get("HYPOTHESIS_PROFILE") == "long"
EXAMPLES = 80 if LONG else 12

Doc = dict[str, Any]
Edit = Callable[[st.DrawFn, Doc], str]

# Text a binding carries into comments, docstrings and strings: every emitter escapes it for its
# target (cbfgen.escape), so hostile text must generate, compile and agree like any other.
# Names reserved in a binding's language are refused (escape.keyword_clash).
RESERVED = ("class", "new", "default", "None", "int", "switch")
SAFE_TEXT = string.ascii_letters + string.digits + " .,;:()[]-+='&%<>!?"
HOSTILE = ('"""', "'''", "\\x", "\\u", "/*", "*/", "//", "??/", "\\", "{{", "}}", "{%", "#", "</script>", "`",
           "\n", "\t", "\u00e9", "\u2028", "\U0001f600")
TEXTS = st.one_of(st.text(SAFE_TEXT, min_size=1, max_size=30).filter(lambda s: s.strip() != ""),
                  st.lists(st.sampled_from(HOSTILE + tuple(SAFE_TEXT)), min_size=1, max_size=12).map("".join)
                  .filter(lambda s: s.strip() != ""))


def _pick(draw: st.DrawFn, items: list[Any]) -> Any:
    return items[draw(st.integers(0, len(items) - 1))]


def second_check(draw: st.DrawFn, doc: Doc) -> str:
    """A second check of an existing kind, maybe with the other severity."""
    ch = copy.deepcopy(_pick(draw, doc["checks"]))
    ch["id"] = "twin_" + "".join(x if x.isalnum() else "_" for x in str(ch["id"]).lower())
    if draw(st.booleans()):
        ch["severity"] = "warning" if ch["severity"] == "error" else "error"
    doc["checks"].append(ch)
    return f"second {ch['kind']} check"


def versions_on_check(draw: st.DrawFn, doc: Doc) -> str:
    """``versions:`` on a check (only availability checks are scoped by every runtime)."""
    ch = _pick(draw, doc["checks"])
    ch["versions"] = [_pick(draw, doc["versions"])["id"]]
    return f"versions on {ch['kind']}"


def _fields(doc: Doc) -> list[dict[str, Any]]:
    out = [f for h in doc["headers"].values() for f in h["fields"]] + list(doc["record"]["fields"])
    return out + [a for c in doc["commands"] for lay in c["layouts"] for a in lay["args"]]


def new_type(draw: st.DrawFn, doc: Doc) -> str:
    """A type added to `types:` (registered or not), maybe given to a field of the same size or a
    float argument widened (its layout's size follows)."""
    choice = draw(st.integers(0, 3))
    if choice == 0:
        name = draw(st.sampled_from(["u3", "i16", "f2", "q8"]))
        doc["types"][name] = {"kind": "uint", "size": 3, "doc": "not a registered type"}
        return f"unregistered type {name}"
    unused = [t for t in TYPES.values() if t.name not in doc["types"]]
    if not unused:
        return "no type left to add"
    t = _pick(draw, unused)
    entry: dict[str, Any] = {"kind": t.kind, "doc": t.doc}
    if t.size is not None:
        entry["size"] = t.size
    doc["types"][t.name] = entry
    if choice == 1:
        return f"unused type {t.name}"
    if choice == 2 and t.kind in ("uint", "sint"):
        same = [f for f in _fields(doc)
                if TYPES[f["type"]].kind in ("uint", "sint") and TYPES[f["type"]].size == t.size]
        if same:
            f = _pick(draw, same)
            f["type"] = t.name
            return f"{f['name']} as {t.name}"
    if t.kind == "float" and t.size is not None:
        lays = [(lay, a) for c in doc["commands"] for lay in c["layouts"] for a in lay["args"] if a["type"] == "f4"]
        if lays:
            lay, a = _pick(draw, lays)
            a["type"] = t.name
            growth = (t.size - 4) * int(a.get("count", 1))
            lay["size"] += growth
            for later in lay["args"][lay["args"].index(a) + 1:]:
                if "offset" in later:
                    later["offset"] += growth
            return f"{a['name']} as {t.name}"
    return f"type {t.name}"


def header_diverges(draw: st.DrawFn, doc: Doc) -> str:
    """A header layout's field renamed: before the version fields (what Kaitai's header type reads
    first), or after them."""
    hid = _pick(draw, sorted(doc["headers"]))
    fields = doc["headers"][hid]["fields"]
    f = _pick(draw, fields)
    f["name"] = f["name"] + "_" + hid
    return f"header {hid} field {f['name']}"


def header_renamed(draw: st.DrawFn, doc: Doc) -> str:
    """A header field renamed alike in every layout (the .ksy names fields by the spec's names)."""
    name = _pick(draw, [f["name"] for f in next(iter(doc["headers"].values()))["fields"]])
    new = draw(st.sampled_from(["vmaj", "field_x", name + "_2", "layout", "version_index"]))
    for h in doc["headers"].values():
        for f in h["fields"]:
            if f["name"] == name:
                f["name"] = new
    return f"header field {name} as {new}"


def range_bounds(draw: st.DrawFn, doc: Doc) -> str:
    """A range check losing a bound, or both."""
    ranges = [c for c in doc["checks"] if c["kind"] == "range"]
    if not ranges:
        return "no range check"
    ch = _pick(draw, ranges)
    for key in draw(st.sampled_from([("min",), ("max",), ("min", "max")])):
        ch.pop(key, None)
    return f"range {ch['id']} without some bound"


def texts(draw: st.DrawFn, doc: Doc) -> str:
    """Other prose in a command's doc, a check's text or a field's doc."""
    where = draw(st.integers(0, 2))
    text = draw(TEXTS)
    if where == 0:
        _pick(draw, doc["commands"])["doc"] = text
    elif where == 1:
        _pick(draw, doc["checks"])["text"] = text
    else:
        _pick(draw, _fields(doc))["doc"] = text
    return "text"


def names(draw: st.DrawFn, doc: Doc) -> str:
    """An argument renamed (what names it elsewhere is not: a refusal, or nothing names it)."""
    cmd = _pick(draw, doc["commands"])
    args = [a for lay in cmd["layouts"] for a in lay["args"]]
    if not args:
        return "no argument"
    a = _pick(draw, args)
    a["name"] = draw(st.sampled_from(["value", "x_1", "a" * 31, a["name"] + "_2", *RESERVED]))
    return f"{cmd['name']} argument {a['name']}"


def roles(draw: st.DrawFn, doc: Doc) -> str:
    """A role (motion, orientation, shape, cutter, sets, progress) naming another argument of its
    command: refused unless it has the shape the role reads."""
    cmds = [c for c in doc["commands"] if any(k in c for k in ("motion", "orientation", "shape", "cutter", "sets"))]
    cmd = _pick(draw, cmds)
    role = _pick(draw, [k for k in ("motion", "orientation", "shape", "cutter", "sets") if k in cmd])
    keys = [k for k, v in cmd[role].items() if k != "kind" and isinstance(v, str)]
    args = sorted({a["name"] for lay in cmd["layouts"] for a in lay["args"]})
    if not keys or not args:
        return "no role to move"
    key = _pick(draw, keys)
    cmd[role][key] = _pick(draw, args)
    return f"{cmd['name']} {role}.{key} as {cmd[role][key]}"


def retarget(draw: st.DrawFn, doc: Doc) -> str:
    """A targeted check aimed at another command's argument, whatever its shape."""
    checks = [c for c in doc["checks"] if c.get("targets") and c["kind"] != "machine_limits"]
    cmd = _pick(draw, doc["commands"])
    args = sorted({a["name"] for lay in cmd["layouts"] for a in lay["args"]})
    if not checks or not args:
        return "nothing to retarget"
    ch = _pick(draw, checks)
    ch["targets"] = [{"command": cmd["name"], "args": [_pick(draw, args)]}]
    return f"{ch['id']} on {cmd['name']}.{ch['targets'][0]['args'][0]}"


def severity(draw: st.DrawFn, doc: Doc) -> str:
    ch = _pick(draw, doc["checks"])
    ch["severity"] = "warning" if ch["severity"] == "error" else "error"
    return f"severity of {ch['id']}"


_EXAMPLE = itertools.count()
EDITS: tuple[Edit, ...] = (second_check, versions_on_check, new_type, header_diverges, header_renamed, range_bounds,
                           texts, names, roles, retarget, severity)


@st.composite
def near_misses(draw: st.DrawFn) -> tuple[Doc, list[str]]:
    doc = spec_doc()
    said = [draw(st.sampled_from(EDITS))(draw, doc) for _ in range(draw(st.integers(1, 2)))]
    return doc, said


@settings(max_examples=EXAMPLES, suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(near_misses())
def test_a_near_miss_spec_is_refused_with_a_line_or_works_in_every_binding(tmp_path: Path,
                                                                             case: tuple[Doc, list[str]]) -> None:
    doc, said = case
    verdict = judge(doc, tmp_path / f"example{next(_EXAMPLE)}")
    event("refused" if verdict.refused else "accepted: generated, compiled, agreed")


# -- each edit kind, once, with the outcome it must have -------------------------------------
def test_header_version_fields_renamed_in_every_layout_work_everywhere(tmp_path: Path) -> None:
    """The .ksy's version switch names the version fields by their names (it wrote version_major
    whatever the spec called it, so ksc failed on a spec --check-spec accepted)."""
    doc = spec_doc()
    for h in doc["headers"].values():
        for f in h["fields"]:
            if f.get("role") in ("version_major", "version_minor"):
                f["name"] = "v_" + f["role"]
    assert not judge(doc, tmp_path).refused


def test_a_second_check_of_a_record_kind_runs_in_python_and_c(tmp_path: Path) -> None:
    """A second finite check (a warning): both bindings report both (records.py ran only the first)."""
    doc = spec_doc()
    first = next(c for c in doc["checks"] if c["kind"] == "finite")
    doc["checks"].append({**first, "id": "finite_again", "severity": "warning"})
    assert not judge(doc, tmp_path).refused


def test_versions_on_a_range_check_is_refused(tmp_path: Path) -> None:
    doc = spec_doc()
    ch = next(c for c in doc["checks"] if not CHECK_KINDS[c["kind"]].versioned)
    ch["versions"] = [doc["versions"][-1]["id"]]
    verdict = judge(doc, tmp_path)
    assert verdict.refused and any(f"check {ch['id']}: versions on a check of kind" in p for p in verdict.problems)


def test_a_header_diverging_before_its_version_fields_is_read_by_position(tmp_path: Path) -> None:
    """ksc failed inside make generate ("unable to access 'version_major' in cbf::header context")
    when a header layout renamed a field before the version fields; the loader refused it. Now the
    .ksy reads the version where every layout has it, by position (a new version's header may turn
    the reserved checksum bytes into fields, issue 25), and the spec loads."""
    doc = spec_doc()
    hid = sorted(doc["headers"])[-1]
    first = next(f for f in doc["headers"][hid]["fields"] if f.get("role") == "reserved")
    first["name"] += "_renamed"
    spec = load(write_spec(doc, tmp_path))
    header = build(spec)["types"]["header"]
    names = [a["id"] for a in header["seq"]]
    assert first["name"] not in names and "layout" in names
    for role in ("version_major", "version_minor"):
        f = spec.common_header_field(role)
        assert f.name not in names and header["instances"][f.name]["pos"] == f.offset


@pytest.mark.parametrize("name", sorted(t for t in TYPES if TYPES[t].size is not None))
def test_every_registered_type_is_accepted_unused(tmp_path: Path, name: str) -> None:
    """A revision may list any registered type in `types:`; unused, nothing changes anywhere."""
    doc = spec_doc()
    t = TYPES[name]
    doc["types"][name] = {"kind": t.kind, "size": t.size, "doc": t.doc}
    assert name in load(write_spec(doc, tmp_path)).types
