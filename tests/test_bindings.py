"""Bindings as data (issue 33, point 2): the registry's BINDING_LIST against what is on disk, and
each binding against what it claims to implement.

What the registry says a binding is made of must exist (its emitter, testees in
conformance/bindings.yaml with a failure list each, its make fragment, the reserved words of its
languages); and what it claims to implement must be there: a Python kernel per check kind and an
implementation per algorithm kind, a C use of each kind's and algorithm's enum constant beyond its
definition (a kernel or a row), and for Kaitai a `valid:` rule that makes its parsers refuse the
golden cases of each kind it states. Nothing here names a kind, an algorithm or a binding: all come
from the registry and the spec.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from conftest import load_yaml

from cbfgen import escape, registry
from cbfgen.emit import checklist
from cbfgen.emit.c.cnames import macro
from cbfgen.loader import load
from cbfgen.registry import BINDING, BINDING_LIST

ROOT = Path(__file__).resolve().parents[1]
SPEC = ROOT / "spec" / "cbf.yaml"


def test_the_registry_lists_the_bindings_the_loader_answers_for() -> None:
    assert tuple(b.name for b in BINDING_LIST if b.gated) == registry.BINDINGS


@pytest.mark.parametrize("b", BINDING_LIST, ids=lambda b: b.name)
def test_a_binding_is_what_the_registry_says(b: registry.Binding) -> None:
    assert (ROOT / "generator" / "cbfgen" / "emit" / b.emitter / "__init__.py").is_file()
    assert not set(b.languages) - set(escape.RESERVED), "a language whose reserved words escape.py lacks"
    if b.make is not None:
        assert (ROOT / "mk" / f"{b.make}.mk").is_file()
    for t in b.testees:
        assert (ROOT / "conformance" / "failures" / f"{t}.txt").is_file(), t
    assert set(b.check_kinds) <= set(registry.CHECK_KINDS)
    assert set(b.algorithms) <= set(registry.ALGORITHMS)
    assert set(b.roles) <= {f"{r}/{k}" for r, ks in registry.ROLE_KINDS.items() for k in ks}


@pytest.mark.parametrize("b", [b for b in BINDING_LIST if b.engine_of], ids=lambda b: b.name)
def test_a_build_of_another_engine_claims_what_that_engine_claims(b: registry.Binding) -> None:
    """A binding that builds another's engine files for another target (no second copy of any
    check) claims exactly what that engine implements, and the loader answers for it through it."""
    engine = BINDING[b.engine_of or ""]
    assert engine.gated and not b.gated and engine.emitter == b.emitter
    assert (b.check_kinds, b.algorithms, b.roles) == (engine.check_kinds, engine.algorithms, engine.roles)


def test_conformance_runs_exactly_the_registered_testees() -> None:
    listed = [t["name"] for t in load_yaml(ROOT / "conformance" / "bindings.yaml")["bindings"]]
    assert sorted(listed) == sorted(t for b in BINDING_LIST for t in b.testees)
    on_disk = {p.stem for p in (ROOT / "conformance" / "failures").glob("*.txt")}
    assert on_disk == set(listed)


def test_every_reserved_word_table_belongs_to_a_binding() -> None:
    assert set(escape.RESERVED) == {lang for b in BINDING_LIST for lang in b.languages}


def test_the_checklist_says_what_each_binding_implements() -> None:
    text = (ROOT / "generated" / "checklist" / "BINDINGS.md").read_text(encoding="utf-8")
    assert text == checklist.checklist(load(SPEC))
    for b in BINDING_LIST:
        assert f"### {b.name}" in text
        assert f"implements {len(b.check_kinds)} of {len(registry.CHECK_KINDS)} check kinds" in text


# -- each binding implements what it claims ----------------------------------------------------

def _claims(name: str) -> registry.Binding:
    if name not in BINDING:
        pytest.skip(f"no binding {name} in the registry")
    return BINDING[name]


def test_python_implements_what_it_claims() -> None:
    from cbf import checksums, records, validation

    b = _claims("python")
    lacking = [k for k in b.check_kinds if k not in records.KERNELS and k not in validation.FILE_KINDS]
    assert not lacking, f"Python claims check kinds it has no kernel for: {lacking}"
    assert not set(b.algorithms) - set(checksums.KINDS)
    # Role kinds: the engines follow them in if/else branches (no symbol per kind to look for);
    # tests/test_bounded_curves.py and the golden cases exercise each one.


def _c_uses(text: str, prefix: str, name: str) -> int:
    """How often cbf.h uses the enum constant CBF__<prefix>_<NAME> outside every enum definition
    (an enum's body, inline or one constant a line, is its definition, not a use)."""
    sym = f"CBF__{prefix}_{macro(name)}"
    uses = re.sub(r"\benum\b[^{;]*\{[^}]*\}", "", text)
    return len(re.findall(rf"\b{sym}\b", uses))


def test_c_implements_what_it_claims() -> None:
    b = _claims("c")
    text = (ROOT / "generated" / "c" / "cbf.h").read_text(encoding="utf-8")
    # a kind's kernel: its constant used beyond its enum, or a kernel cbf__<kind>_at, or the engine's
    # own generated table cbf__<kind> (a deprecated check: cbf__deprecated[layout])
    lacking = [k for k in b.check_kinds if _c_uses(text, "KIND", k) < 1
               and not re.search(rf"\bcbf__{k}(_at)?\b", text)]
    assert not lacking, f"C claims check kinds with no kernel (no use of CBF__KIND_x): {lacking}"
    rows = re.search(r"cbf__algs\[CBF__ALG__COUNT\] = \{(.*?)\n\};", text, re.S)
    assert rows is not None
    assert [m for m in re.findall(r"/\* (\w+) \*/", rows.group(1))] == list(b.algorithms)
    for role in b.roles:
        r, k = role.split("/")
        prefix = {"motion": "MOTION", "orientation": "ORIENT", "shape": "SHAPE"}[r]
        assert re.search(rf"\bCBF__{prefix}_{macro(k)}\b", text), role


def _failures(testee: str) -> dict[str, str]:
    lines = (ROOT / "conformance" / "failures" / f"{testee}.txt").read_text(encoding="utf-8").splitlines()
    return {ln.split(" ", 1)[0]: ln for ln in lines if ln and not ln.startswith("#")}


def test_kaitai_states_what_it_claims() -> None:
    """Each check kind Kaitai claims is a `valid:` rule: its parsers refuse every golden case that
    expects a finding of a check of that kind under every profile (the failure list records the
    refusal; a .ksy knows no profile, so a case one profile accepts is not asked of it)."""
    b = _claims("kaitai")
    spec = load(SPEC)
    golden = ROOT / "conformance" / "golden"
    seen = 0
    for kind in b.check_kinds:
        for check in spec.checks_of_kind(kind):
            for exp in sorted(golden.glob(f"check.{check.id}.*.expect.yaml")):
                profiles = (load_yaml(exp).get("validate") or {}).values()  # Kaitai reads under no profile
                if not profiles or not all(any(str(f[0]) == check.id for f in fs or []) for fs in profiles):
                    continue
                case = exp.name[: -len(".expect.yaml")]
                for testee in b.testees:
                    line = _failures(testee).get(case, "")
                    assert "validation" in line, f"{testee} claims {kind} but decodes {case}"
                seen += 1
    assert seen or not b.check_kinds


def test_per_kind_wording_lives_with_the_kind() -> None:
    """issue 33, point 3: the docs emitter names no check kind; the registry's KIND_WORDING does,
    for registered kinds only."""
    assert set(registry.KIND_WORDING) <= set(registry.CHECK_KINDS)
    docs = (ROOT / "generator" / "cbfgen" / "emit" / "docs" / "__init__.py").read_text(encoding="utf-8")
    # a comparison with a kind's name, or a kind's name as the key of a text
    pattern = r"""kind\s*(==|!=)\s*["']{k}["']|["']{k}["']\s*:\s*f?["']"""
    named = [k for k in registry.CHECK_KINDS if re.search(pattern.format(k=re.escape(k)), docs)]
    assert not named, f"the docs emitter has per-kind branches or text: {named}"
