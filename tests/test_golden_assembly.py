"""Every committed golden .cbf is what its annotated hex assembles to, and every
case is complete and well-formed."""

from __future__ import annotations

from pathlib import Path

import pytest
from conftest import load_yaml

from conformance.assembler import AsmError, assemble, assemble_text

GOLDEN = Path(__file__).resolve().parents[1] / "conformance" / "golden"
CASES = sorted(p.name[: -len(".hex")] for p in GOLDEN.glob("*.hex"))


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
        assert profile in ("default", "implib")
        for f in findings:
            assert len(f) == 4 and f[1] in ("error", "warning") and (f[2] is None or isinstance(f[2], int))
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
    root = Path(__file__).resolve().parents[1] / "conformance" / "assembler"
    imports = [ln.strip() for p in root.glob("*.py") for ln in p.read_text().splitlines()
               if ln.strip().startswith(("import ", "from "))]
    assert imports
    for line in imports:
        assert not any(word in line for word in ("cbfgen", "cbf", "generated", "conformance.runner")), line
