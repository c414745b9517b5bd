"""The vocabulary registry (generator/cbfgen/registry.py) is the one list of field types and check
kinds: the schema's enums are filled from it, every binding implements each registered kind, and
each binding carries every type the registry says it carries, end to end.
"""

from __future__ import annotations

import importlib
import json
import struct
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import ksc_serve
import numpy as np
import pytest
from conftest import REPO, dump_yaml, spec_doc

from cbfgen import loader, registry
from cbfgen.loader import load
from cbfgen.loader.passes import bindings as capabilities  # the pass that asks registry.unsupported
from cbfgen.model import camel
from cbfgen.registry import CHECK_KINDS, TYPES, FieldType, kinds_with, unsupported


def test_the_schema_names_no_type_and_no_kind_itself() -> None:
    on_disk = (REPO / "generator" / "cbfgen" / "spec.schema.json").read_text(encoding="utf-8")
    for word in ('"u4"', '"f4"', '"finite"', '"range"', '"uint"', '"warning"', '"crc32"', '"helix"'):
        assert word not in on_disk, word
    schema = loader.schema()
    assert schema["$defs"]["field"]["properties"]["type"]["enum"] == list(TYPES)
    assert schema["properties"]["checks"]["items"]["properties"]["kind"]["enum"] == list(CHECK_KINDS)
    assert schema["properties"]["types"]["additionalProperties"]["properties"]["kind"]["enum"] == list(
        registry.FIELD_KINDS)
    algorithm = schema["properties"]["checksums"]["properties"]["algorithms"]["additionalProperties"]
    assert algorithm["properties"]["kind"]["enum"] == list(registry.ALGORITHMS)
    command = schema["properties"]["commands"]["items"]["properties"]
    for role, kinds in registry.ROLE_KINDS.items():
        assert command[role]["allOf"][1]["properties"]["kind"]["enum"] == list(kinds), role


def test_each_role_kind_needs_keys_the_role_has() -> None:
    """registry.ROLE_NEEDS names, per role kind, keys of that role (ROLE_ARGS): nothing to misspell."""
    for role, needs in registry.ROLE_NEEDS.items():
        assert needs, role
        for kind, keys in needs.items():
            assert set(keys) <= set(registry.ROLE_ARGS[role]), (role, kind)


def test_the_loader_refuses_a_role_by_the_registrys_needs(monkeypatch: pytest.MonkeyPatch) -> None:
    """A need added to registry.ROLE_NEEDS is a refusal of every command whose role kind lacks it: the
    loader keeps no list of its own (it had _MOTION_NEEDS, keyed apart from ROLE_KINDS)."""
    spec = load(REPO / "spec" / "cbf.yaml")
    load_errors = loader.SpecError
    for role, needs in registry.ROLE_NEEDS.items():
        used = [(c.name, r["kind"]) for c in spec.commands if (r := getattr(c, role))]
        assert used, role  # the spec has a command of this role: the check sees the needs it guards
        name, kind = used[0]
        monkeypatch.setitem(needs, kind, (*needs[kind], "fixture_key"))
        with pytest.raises(load_errors) as err:
            load(REPO / "spec" / "cbf.yaml")
        monkeypatch.undo()
        assert f"{name}: {role} kind {kind} needs fixture_key" in str(err.value), role


def test_the_python_runtime_spells_no_list_of_the_derived_header_roles() -> None:
    """tables.DERIVED_ROLES is registry.DERIVED_HEADER_ROLES (through spec_data.json), and no runtime
    module writes a literal of three or more of those roles: cut.py, testing.py, convert.py and
    semdiff.py each kept a copy once, and tables.py one after them."""
    import ast

    tables = importlib.import_module("cbf.tables")
    derived = set(registry.DERIVED_HEADER_ROLES)
    assert tables.DERIVED_ROLES == derived
    runtime = REPO / "generator" / "cbfgen" / "emit" / "python" / "runtime"
    copies = []
    for path in sorted(runtime.glob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Tuple | ast.List | ast.Set):
                words = {e.value for e in node.elts if isinstance(e, ast.Constant) and isinstance(e.value, str)}
                if len(words & derived) >= 3:
                    copies.append(f"{path.name}:{node.lineno}")
    assert not copies, f"a copy of registry.DERIVED_HEADER_ROLES: {copies}"


def test_every_kind_of_the_registry_has_one_python_implementation() -> None:
    """records.KERNELS holds the record kinds, validation.FILE_KINDS the file kinds: together the
    registry's kinds, each once (a registered kind without a kernel fails here)."""
    records = importlib.import_module("cbf.records")
    validation = importlib.import_module("cbf.validation")
    assert set(records.KERNELS) == set(kinds_with("record"))
    assert set(validation.FILE_KINDS) == set(kinds_with("file"))
    assert not set(records.KERNELS) & set(validation.FILE_KINDS)


def test_the_ksy_names_no_member_of_its_own_beyond_the_registry_generated_names() -> None:
    """The .ksy's header and record types hold the spec's fields and only the members that
    registry.GENERATED_NAMES reserves (the loader refuses a field of those names)."""
    spec = load(REPO / "spec" / "cbf.yaml")
    ksy = importlib.import_module("cbfgen.emit.kaitai").build(spec)
    fields = {"header": {f.name for h in spec.headers.values() for f in h.fields},
              "record": {f.name for f in spec.record.fields}}
    for part, names in fields.items():
        t = ksy["types"][part]
        own = {a["id"] for a in t["seq"]} | set(t.get("instances", {})) - names
        assert own - names <= set(registry.GENERATED_NAMES[part]), (part, own - names)
        assert own - names, part  # the check sees the members it guards


def test_every_kind_takes_the_parameters_its_dataclass_declares() -> None:
    spec = load(REPO / "spec" / "cbf.yaml")
    for ch in spec.checks:
        assert isinstance(ch.params, CHECK_KINDS[ch.kind].params), ch.id
    # versions: scopes every kind but those that judge a file before its version is known, and the
    # truncated record (a file no binding reads whole may not pass in any version) (issue 25, point 4)
    # and the kinds the .ksy states as a `valid:` rule for every version (availability's rule is per version)
    kaitai_rules = {k.name for k in CHECK_KINDS.values() if k.kaitai and not k.gates}
    assert {k.name for k in CHECK_KINDS.values() if not k.versioned} == {"truncated_header", "truncated_record",
                                                                         "version"} | kaitai_rules
    assert kaitai_rules


def test_type_codes_follow_from_kind_and_size() -> None:
    for t in TYPES.values():
        if t.size is None:
            assert (t.struct_code, t.numpy, t.kaitai, t.c_type) == (None, None, None, None)
            continue
        assert struct.calcsize("<" + (t.struct_code or "")) == t.size, t
        assert np.dtype("<" + (t.numpy or "")).itemsize == t.size, t
        assert (t.kaitai or "")[1:] == str(t.size)
        if t.is_integer:
            assert t.min is not None and t.max is not None and t.max - t.min == (1 << (8 * t.size)) - 1


# -- each type, end to end, in each binding that claims it -----------------------------------
def _value(t: FieldType) -> Any:
    if t.kind == "uint":
        return t.max
    if t.kind == "sint":
        return t.min
    if t.kind == "float":
        return 1.5
    return "abc" if t.kind == "string" else b"\x01\x02\x03"


# The probe command's name: PROBE, or the first PROBE_<n> the spec leaves free (a revision, or the
# drill's new_command fixture, may already hold a PROBE).
PROBE = next(n for n in ("PROBE", *(f"PROBE_{i}" for i in range(2, 100)))
             if n not in {c["name"] for c in spec_doc()["commands"]})


def _spec_using(t: FieldType, tmp: Path) -> Path:
    """The real spec plus the PROBE command, one argument of type t, in every version."""
    doc = spec_doc()
    entry: dict[str, Any] = {"kind": t.kind, "doc": t.doc}
    if t.size is not None:
        entry["size"] = t.size
    doc["types"][t.name] = entry
    used = {c["code"] for c in doc["commands"]}
    arg: dict[str, Any] = {"name": "value", "type": t.name, "doc": "The value."}
    if t.size is None:
        arg["size"] = 3
    doc["commands"].append({
        "name": PROBE, "code": next(c for c in range(1, 256) if c not in used), "clause": "5.1",
        "doc": "A command with one argument of the type under test.",
        "layouts": [{"versions": [v["id"] for v in doc["versions"]], "size": t.size or 3, "args": [arg]}],
    })
    path = tmp / "cbf.yaml"
    path.write_text(dump_yaml(doc, sort_keys=False, width=1000), encoding="utf-8")
    return path


def _generate(t: FieldType, tmp: Path, binding: str, monkeypatch: pytest.MonkeyPatch) -> Path:
    """Generate one binding for a spec that uses t: the loader answers for that binding alone."""
    monkeypatch.setattr(capabilities, "unsupported",
                        lambda ft, count=1: tuple(b for b in unsupported(ft, count) if b == binding))
    spec = load(_spec_using(t, tmp))
    out = tmp / "out"
    for rel, data in importlib.import_module(f"cbfgen.emit.{binding}").emit(spec).items():
        (out / rel).parent.mkdir(parents=True, exist_ok=True)
        (out / rel).write_bytes(data)
    return out


PYTHON_SCRIPT = r"""
import ast, sys
import cbf
from cbf import tables as T
from cbf import layouts
Probe = getattr(layouts, sys.argv[3])
from cbf.model import Cbf, Record, new_header
values = ast.literal_eval(sys.argv[1])
model = Cbf(new_header(T.DEFAULT_VERSION, implant_descriptor="PN-1"), tuple(Record.of(Probe(value=v)) for v in values))
data = cbf.encode(model)
back = cbf.decode(data)
assert [r.decode_args() for r in back.records] == [Probe(value=v) for v in values], back.records
assert cbf.validate(data) == [], cbf.validate(data)
assert cbf.encode(cbf.from_cut(cbf.to_cut(back))) == data, cbf.to_cut(back)
assert cbf.encode(cbf.from_canonical(cbf.to_canonical(back))) == data
open(sys.argv[2], "wb").write(data)
# cbf.testing draws valid files that hold the type too
from hypothesis import given, settings
from cbf.testing import cutfiles
seen = []
@settings(max_examples=200, derandomize=True, database=None, deadline=None)
@given(cutfiles(max_records=8))
def drawn(d):
    assert cbf.validate(d) == [], cbf.validate(d)
    seen.extend(r for r in cbf.decode(d).records if r.code == Probe.CODE)
drawn()
assert seen, "no probe record drawn"
"""


def _types_of(binding: str) -> list[str]:
    return [n for n, t in TYPES.items() if binding not in unsupported(t)]


@pytest.mark.parametrize("name", _types_of("python"))
def test_python_carries_each_type_it_claims(name: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    t = TYPES[name]
    out = _generate(t, tmp_path, "python", monkeypatch)
    values = [t.min, -1, 0, 1, t.max] if t.kind == "sint" else [0, t.max] if t.kind == "uint" else [_value(t)]
    done = subprocess.run([sys.executable, "-c", PYTHON_SCRIPT, repr(values), str(tmp_path / "f.cbf"), camel(PROBE)],
                          env={"PYTHONPATH": str(out / "python"), "PATH": "/usr/bin:/bin"}, capture_output=True,
                          text=True, check=False)
    assert done.returncode == 0, done.stderr[-3000:]


KAITAI_SCRIPT = r"""
import ast, sys
from cbf_kaitai.cbf import Cbf
value = ast.literal_eval(sys.argv[1])
parsed = Cbf.from_bytes(bytes.fromhex(sys.argv[2]))
got = parsed.records[-1].args.value
print(repr(got))
assert got == value or (isinstance(value, str) and got == value), (got, value)
"""


@pytest.fixture(scope="module")
def ksc() -> Iterator[ksc_serve.KscServer]:
    """ksc_driver.js in one node process for every type (tests/ksc_serve.py: a node a type cost 0.5 CPU s)."""
    if not ksc_serve.available():
        pytest.skip("node or the Kaitai compiler is not installed")
    with ksc_serve.server() as server:
        yield server


@pytest.mark.parametrize("name", [n for n in _types_of("kaitai") if TYPES[n].size is not None])
def test_kaitai_carries_each_type_it_claims(name: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                            ksc: ksc_serve.KscServer) -> None:
    """ksc compiles the .ksy of a spec using the type, and its parser reads the value back (the file
    written by hand from the registry's struct code: no other binding is asked)."""
    t = TYPES[name]
    out = _generate(t, tmp_path, "kaitai", monkeypatch)
    error = ksc.compile(out / "kaitai" / "cbf.ksy.json", out / "kaitai", ["python"])
    assert error is None, error
    ksy = json.loads((out / "kaitai" / "cbf.ksy.json").read_text(encoding="utf-8"))
    probe = next(k for k, v in ksy["types"].items() if k.startswith(f"args_{PROBE.lower()}"))
    assert ksy["types"][probe]["seq"][0]["type"] == t.kaitai
    data = _file_with(t, _value(t))
    done = subprocess.run([sys.executable, "-c", KAITAI_SCRIPT, repr(_value(t)), data.hex()],
                          env={"PYTHONPATH": f"{out / 'kaitai' / 'python'}:{':'.join(sys.path)}"},
                          capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stderr[-3000:]


def _file_with(t: FieldType, value: Any) -> bytes:
    """A CBF file holding one PROBE record, packed with the current Python binding's header and
    the registry's struct code for the argument (Kaitai checks no checksum)."""
    from cbf import tables as T  # noqa: PLC0415  (the binding under generated/, imported when asked)
    spec = load(REPO / "spec" / "cbf.yaml")
    code = 1
    while any(c.code == code for c in spec.commands):
        code += 1
    cbf = importlib.import_module("cbf")
    model = importlib.import_module("cbf.model")
    head = bytearray(cbf.encode(model.Cbf(model.new_header(T.DEFAULT_VERSION, implant_descriptor="PN-1"), ())))
    count = T.COUNT
    head[count.offset:count.end] = (1).to_bytes(count.size, "little" if T.BO == "<" else "big")
    args = struct.pack(T.BO + (t.struct_code or ""), value)
    rec = bytearray(T.HEAD_SIZE)
    for f in T.RECORD_FIELDS:
        v = {"code": code, "code_copy": code, "arg_size": len(args)}.get(f.role or "", 0)
        rec[f.offset:f.end] = v.to_bytes(f.size, "little" if T.BO == "<" else "big")
    return bytes(head) + bytes(rec) + args


@pytest.mark.parametrize("name", [n for n, t in TYPES.items() if set(unsupported(t)) != set(registry.BINDINGS)])
def test_the_docs_emitter_writes_every_type_a_binding_carries(name: str, tmp_path: Path,
                                                              monkeypatch: pytest.MonkeyPatch) -> None:
    """The reference pages (field tables, layout pictures, golden pages) of a spec using the type."""
    monkeypatch.setattr(capabilities, "unsupported", lambda ft, count=1: ())
    spec = load(_spec_using(TYPES[name], tmp_path))
    files = importlib.import_module("cbfgen.emit.docs").emit(spec)
    assert any(PROBE.encode() in data for rel, data in files.items() if rel.endswith(".md"))
