"""Every committed golden .cbf is what its annotated hex assembles to, and every
case is complete and well-formed."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from conftest import load_yaml, spec_doc

from cbfgen.registry import SEVERITIES
from conformance.assembler import AsmError, assemble, assemble_text

GOLDEN = Path(__file__).resolve().parents[1] / "conformance" / "golden"
CASES = sorted(p.name[: -len(".hex")] for p in GOLDEN.glob("*.hex"))
PROFILES = tuple(p["id"] for p in spec_doc()["profiles"])  # a revision's new profile may have cases


def test_there_are_cases() -> None:
    assert len(CASES) >= 50


@pytest.mark.parametrize("name", CASES)
def test_reassembles_to_committed_bytes(name: str) -> None:
    committed = (GOLDEN / f"{name}.cbf").read_bytes()
    assert assemble(GOLDEN / f"{name}.hex") == committed


@pytest.mark.parametrize("name", CASES)
def test_expectation_is_well_formed(name: str) -> None:
    exp = load_yaml(GOLDEN / f"{name}.expect.yaml")
    assert isinstance(exp["description"], str) and exp["description"]
    assert exp["clauses"], "every case names the clauses it exercises"
    assert "decode" in exp
    for profile, findings in exp["validate"].items():
        assert profile in PROFILES, f"{profile}: a profile of the spec"
        for f in findings:
            assert len(f) == 4 and f[1] in SEVERITIES and (f[2] is None or isinstance(f[2], int))
            assert isinstance(f[3], int) and f[3] >= 0, f"{f}: the offset of the field concerned"


def test_assembler_language() -> None:
    text = """
    01 02          # bytes
    u16 0x0304     # little-endian
    f32 1.0 -0
    str 4 "AB"
    zeros 2
    """
    out = assemble_text(text)
    assert out == bytes([1, 2, 4, 3]) + bytes.fromhex("0000803f00000080") + b"AB\0\0" + bytes(2)


def test_errors_name_the_line() -> None:
    with pytest.raises(AsmError, match=r"<text>:2: .*unknown directive"):
        assemble_text("01\n0g\n")
    with pytest.raises(AsmError, match=r"<text>:2: .*defines no 'nonsense' checksum"):
        assemble_text("01\nchecksum nonsense\n")
    with pytest.raises(AsmError, match=r"<text>:1: .*unknown profile"):
        assemble_text("checksum file no_such_profile\n")


def test_assembler_imports_no_binding() -> None:
    """The assembler imports no binding and no generator code: of generator/ it reads only the
    registry's algorithm parameters (data; cbfgen/registry.py imports nothing of cbfgen), so a
    golden file is never made by the code it tests."""
    root = Path(__file__).resolve().parents[1]
    files = (root / "conformance" / "assembler").glob("*.py")
    lines = [ln.strip() for p in files for ln in p.read_text().splitlines()]
    imports = [ln for ln in lines if ln.startswith(("import ", "from "))]
    assert imports
    allowed = ("from cbfgen.registry import ",)
    for line in imports:
        if line.startswith(allowed):
            continue
        assert not any(word in line for word in ("cbfgen", "cbf", "generated", "conformance.runner")), line
    registry = (root / "generator" / "cbfgen" / "registry.py").read_text().splitlines()
    own = [ln for ln in registry if ln.startswith(("import ", "from ")) and ("cbf" in ln or ln.startswith("from ."))]
    assert not own
    # and at run time: importing the assembler loads no module of a binding or of the generator but the registry
    probe = ("import sys, conformance.assembler; print(sorted(m for m in sys.modules "
             "if m.split('.')[0] in ('cbf', 'cbfgen', 'cbf_kaitai') or m.startswith('conformance.runner')))")
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True, cwd=root).stdout
    assert out.strip() == str(["cbfgen", "cbfgen.registry"]), out
