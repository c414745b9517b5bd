"""Issue 36, point 3: one number reader. CUT and JSON decimal text go through one function
(cbf.floats.read_decimal): the sign of zero is kept from both, an exponent is bounded before any
arithmetic (a 41-byte JSON with ``1e1000000000000000000`` was a decimal.InvalidOperation traceback
in six commands), text that is not a decimal numeral is refused, and a bound of a check prints by
one rule in both tools (a ``min: -0.0`` was ``[-0..100]`` in cbf, ``[0..100]`` in cbf-c).
Commands, keywords and sizes come from the spec tables, never from this file."""

from __future__ import annotations

import json
import re
import struct
from pathlib import Path

import pytest

import cbf
from cbf import tables as T
from cbf.canonical import loads
from cbf.cli import EXIT_USAGE, main
from cbf.cut import keyword
from cbf.floats import NotDecimal, OutOfRange, read_decimal

GOLDEN = Path(__file__).resolve().parents[1] / "conformance" / "golden"
VALID = GOLDEN / "valid.v3.small.cbf"
DEFAULT = T.DEFAULT_VERSION
SIGN = 0x80000000
HUGE = "1e1000000000000000000"  # the issue's exponent: beyond what decimal.Decimal constructs


def _vector_command() -> tuple[T.CommandInfo, T.LayoutInfo]:
    """A command of the default version whose one argument is a float vector."""
    for cmd in T.COMMANDS:
        lays = cmd.layouts_for(DEFAULT)
        if len(lays) == 1 and [(f.kind, f.count > 1) for f in lays[0].args] == [("float", True)]:
            return cmd, lays[0]
    raise AssertionError("the spec has no command with one float vector argument")


VEC_CMD, VEC_LAY = _vector_command()
ARG = VEC_LAY.args[0]
VEC_KW = keyword(VEC_CMD)
C = T.CUT


def _cut(values: list[str]) -> str:
    inner = (C["vector_separator"] + " ").join(values)
    return f"{C['header_keyword']} X\n{VEC_KW} {C['vector_open']} {inner} {C['vector_close']}\n"


def _json(values: list[str]) -> str:
    implant = T.HEADERS[T.VERSION_BY_ID[DEFAULT].header].by_role("implant_descriptor")
    assert implant is not None
    doc = {"header": {T.VMAJOR.name: T.parse_version(DEFAULT)[0], T.VMINOR.name: T.parse_version(DEFAULT)[1],
                      implant.name: "X"},
           "records": [{"command": VEC_CMD.name, "args": {ARG.name: "@"}}]}
    return json.dumps(doc).replace('"@"', "[" + ", ".join(values) + "]")


def _bits(model: cbf.Cbf) -> list[int]:
    return [int(b) for b in VEC_LAY.bits.unpack(model.records[0].raw_args)]


def _values(first: str) -> list[str]:
    return [first] + ["1"] * (ARG.count - 1)


# -- the sign of zero ------------------------------------------------------------------------------
@pytest.mark.parametrize("text", ["-0", "-0.0", "-0.000", "-0e5", "-0.0E-7"])
def test_negative_zero_is_negative_from_cut_and_from_json(text: str) -> None:
    from_json = _bits(cbf.from_canonical(loads(_json(_values(text)))))
    assert from_json[0] == SIGN, hex(from_json[0])
    if re.fullmatch(C["float_pattern"], text):  # a numeral CUT writes too (its pattern may lack exponents)
        assert _bits(cbf.from_cut(_cut(_values(text)))) == from_json


def test_the_two_texts_of_one_toolpath_encode_to_one_file(tmp_path: Path,
                                                          capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "a.cut").write_text(_cut(_values("-0")))
    (tmp_path / "a.json").write_text(_json(_values("-0")))
    for name in ("a.cut", "a.json"):
        assert main(["encode", str(tmp_path / name), "-o", str(tmp_path / f"{name}.cbf")]) == 0, capsys.readouterr()
    assert (tmp_path / "a.cut.cbf").read_bytes() == (tmp_path / "a.json.cbf").read_bytes()


def test_a_json_integer_minus_zero_is_zero_in_an_integer_field() -> None:
    doc = json.loads(_json(_values("1")))
    doc["records"][0]["sequence"] = "@"
    model = cbf.from_canonical(loads(json.dumps(doc).replace('"@"', "-0")))
    assert model.records[0].sequence == 0


# -- exponents bounded before any arithmetic ---------------------------------------------------------
@pytest.mark.parametrize(("text", "bits"), [
    ("1e-1000000000000000000", 0), ("-1e-1000000000000000000", SIGN), ("0e1000000000000000000", 0),
    ("-0e1000000000000000000", SIGN), ("-0.0e-99999999999999999999999", SIGN), ("1e-000000000000000000001", None),
    ("1e+000000000000000000038", None), ("0.000000000000000000000000000000000000000000000001", 0),
])
def test_an_exponent_of_any_size_reads_at_once(text: str, bits: int | None) -> None:
    want = bits if bits is not None else int(struct.unpack("<I", struct.pack("<f", float(text)))[0])
    assert read_decimal(text) == want


@pytest.mark.parametrize("text", [HUGE, "-" + HUGE, "1e39", "3.5e38", "1" + "0" * 39, "1e+0000000000000000039",
                                  "10e1000000000000000000000000000000000000"])
def test_beyond_binary32_is_out_of_range(text: str) -> None:
    with pytest.raises(OutOfRange):
        read_decimal(text)


@pytest.mark.parametrize("text", ["inf", "nan", "Infinity", "1_0", " 1", "1 ", "\u0661", "1e", ".", "-", "0x10",
                                  "--1", "1e1e1", ""])
def test_text_that_is_no_decimal_numeral_is_refused(text: str) -> None:
    float_takes = True
    try:
        float(text)
    except ValueError:
        float_takes = False
    with pytest.raises(NotDecimal):
        read_decimal(text)
    assert text in ("", ".", "-", "1e", "0x10", "--1", "1e1e1") or float_takes  # what float() alone would take


def _commands(src: Path, good: Path, out: Path) -> list[list[str]]:
    writable = next(v.id for v in T.VERSIONS if v.writable)
    return [["encode", str(src), "-o", str(out)], ["encode", "--check", str(src)], ["stats", str(src)],
            ["diff", str(src), str(good)], ["convert", str(src), "--to-version", writable, "-o", str(out)],
            ["plot", str(src), "-o", str(out) + ".png"]]


def test_the_issue_json_is_one_line_and_exit_2_in_every_command(tmp_path: Path,
                                                                 capsys: pytest.CaptureFixture[str]) -> None:
    src = tmp_path / "big.json"
    src.write_text(_json(_values(HUGE)))
    for argv in _commands(src, VALID, tmp_path / "out.cbf"):
        rc = main(argv)
        err = capsys.readouterr().err
        assert rc == EXIT_USAGE, (argv, err)
        assert len(err.splitlines()) == 1 and err.startswith(f"cbf: {src}: $.records[0].args.{ARG.name}[0]: "), err
        assert "outside the binary32 range" in err
        assert not (tmp_path / "out.cbf").exists()


# A bound of -0.0 (cbf printed [-0..100], cbf-c [0..100]) is refused by the loader now:
# tests/bad_specs/number_signed_zero.yaml and the spec campaign's class range_min_negative_zero.
