"""Issue 13, items 2 to 8 and 11: the text forms (CUT and canonical JSON) never silently
change meaning. Control characters do not split lines, contradictions and duplicates are
refused, trailing text is refused, strings stay ASCII, decimal text rounds to binary32
once, numbers out of range and malformed bit patterns are refused with their line or JSON
path, and --keep-stored refuses CUT input. Commands, keywords and sizes come from the
spec tables (cbf.tables), never from this file."""

from __future__ import annotations

import json
import struct
from decimal import Decimal, localcontext
from fractions import Fraction
from pathlib import Path
from typing import Any

import pytest
from conftest import file_checksum_of
from hypothesis import example, given
from hypothesis import strategies as st

import cbf
from cbf import tables as T
from cbf.canonical import Numeral, loads
from cbf.cli import EXIT_OK, EXIT_USAGE, main
from cbf.cut import keyword

GOLDEN = Path(__file__).resolve().parents[1] / "conformance" / "golden"
VALID = GOLDEN / "valid.v3.small.cbf"
C = T.CUT
EXT = C["extensions"]
HEADER, HEADER_EXT, CHECK_SUM = C["header_keyword"], C["header_ext_keyword"], C["checksum_keyword"]
VERSION_KW, FIELD_KW, RECORD_KW = EXT["version_keyword"], EXT["field_keyword"], EXT["record_keyword"]
DEFAULT = T.DEFAULT_VERSION
OTHER_VERSION = next(v.id for v in T.VERSIONS if v.writable and v.id != DEFAULT)


def _own(cmd: T.CommandInfo) -> T.LayoutInfo | None:
    lays = cmd.layouts_for(DEFAULT)
    return lays[0] if len(lays) == 1 else None


def _command(want: str) -> tuple[T.CommandInfo, T.LayoutInfo]:
    for cmd in T.COMMANDS:
        lay = _own(cmd)
        if lay is None:
            continue
        kinds = [(f.kind, f.count, f.text) for f in lay.args]
        if ((want == "float" and kinds == [("float", 1, False)])
                or (want == "text" and kinds == [("string", 1, True)])
                or (want == "none" and kinds == [])):
            return cmd, lay
    raise AssertionError(f"the spec has no command with {want} arguments")


FLOAT_CMD, FLOAT_LAY = _command("float")   # one float argument
TEXT_CMD, TEXT_LAY = _command("text")      # one text argument (the rest of the line)
BARE_CMD, _ = _command("none")             # no argument
FLOAT_KW, TEXT_KW, BARE_KW = keyword(FLOAT_CMD), keyword(TEXT_CMD), keyword(BARE_CMD)


def _header_field(role: str) -> T.FieldInfo:
    found = T.HEADERS[T.VERSION_BY_ID[DEFAULT].header].by_role(role)
    assert found is not None, role
    return found


IMPLANT = _header_field("implant_descriptor")
CONFIG = _header_field("configuration_descriptor")


def _bits(model: cbf.Cbf, record: int = 0) -> int:
    return int(FLOAT_LAY.bits.unpack(model.records[record].raw_args)[0])


def _f32(bits: int) -> float:
    return float(struct.unpack("<f", struct.pack("<I", bits))[0])


def _refused(text: str, line: int, *needles: str, column: int | None = None) -> cbf.CutSyntaxError:
    with pytest.raises(cbf.CutSyntaxError) as err:
        cbf.from_cut(text)
    assert err.value.line == line, str(err.value)
    if column is not None:
        assert err.value.column == column, str(err.value)
        assert f"line {line}, column {column}:" in str(err.value)
    for needle in needles:
        assert needle in str(err.value), (needle, str(err.value))
    return err.value


def _cli(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str]:
    rc = main(list(argv))
    err = capsys.readouterr().err
    if rc != EXIT_OK:
        assert len(err.splitlines()) == 1 and err.startswith("cbf: "), err
    return rc, err


# -- item 2: only LF and CR LF end a line; every other control character is refused -----------
CONTROLS = ["\x0b", "\x0c", "\x1c", "\x1d", "\x1e", "\x85", "\u2028", "\u2029", "\r", "\x00", "\x01", "\x7f",
            "\t", "\x1f", "\x9f"]


@pytest.mark.parametrize("char", CONTROLS, ids=lambda c: f"U+{ord(c):04X}")
def test_a_control_character_is_refused_with_its_line_and_column(char: str) -> None:
    # `<text command> hello<FF><bare command>` once encoded as two records, exit 0
    line = f"{TEXT_KW} hello{char}{BARE_KW}"
    _refused(f"{HEADER} X\n{line}\n", 2, f"U+{ord(char):04X}", column=len(TEXT_KW) + 7)
    _refused(f"{HEADER} X\r\n{FLOAT_KW} 1\r\n{line}\r\n", 3, column=len(TEXT_KW) + 7)


@given(st.lists(st.sampled_from(["\n", "\r\n"]), min_size=1, max_size=6), st.sampled_from(CONTROLS))
def test_line_numbers_count_only_lf_and_crlf(ends: list[str], char: str) -> None:
    text = f"{HEADER} X" + "".join(f"{e}{FLOAT_KW} 0.5" for e in ends) + f"\n{FLOAT_KW} {char}1\n"
    _refused(text, len(ends) + 2, column=len(FLOAT_KW) + 2)


def test_crlf_and_lf_read_alike() -> None:
    lf = f"{HEADER} X\n{FLOAT_KW} 0.5\n{TEXT_KW} a b c\n"
    assert cbf.from_cut(lf.replace("\n", "\r\n")) == cbf.from_cut(lf)


def test_a_control_character_through_the_cli(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    src = tmp_path / "a.cut"
    src.write_bytes(f"{HEADER} X\n{TEXT_KW} hello\x0c{BARE_KW}\n".encode())
    rc, err = _cli(capsys, "encode", str(src), "-o", str(tmp_path / "a.cbf"))
    assert rc == EXIT_USAGE and f"line 2, column {len(TEXT_KW) + 7}" in err and "U+000C" in err
    assert not (tmp_path / "a.cbf").exists()


# -- item 3: contradictions and duplicates ------------------------------------------------------
@pytest.mark.parametrize(("lines", "bad_line", "needle"), [
    ([f"{HEADER} A", f"{HEADER} B"], 2, IMPLANT.name),
    ([f"{HEADER} A", f"{FIELD_KW} {IMPLANT.name} {'42' * IMPLANT.size}"], 2, IMPLANT.name),
    ([f"{FIELD_KW} {IMPLANT.name} {'42' * IMPLANT.size}", f"{HEADER} A"], 2, IMPLANT.name),
    ([f"{HEADER} A", f"{HEADER_EXT} B", f"{HEADER_EXT} C"], 3, CONFIG.name),
    ([f"{HEADER} A", f"{HEADER_EXT} B", f"{FIELD_KW} {CONFIG.name} {'43' * CONFIG.size}"], 3, CONFIG.name),
    ([f"{HEADER} A", f"{CHECK_SUM} 1", f"{CHECK_SUM} 2"], 3, CHECK_SUM),
    ([f"{HEADER} A", f"{CHECK_SUM} 1", f"{CHECK_SUM} 1"], 3, CHECK_SUM),
    ([f"{HEADER} A", f"{VERSION_KW} {DEFAULT}", f"{VERSION_KW} {OTHER_VERSION}"], 3, VERSION_KW),
    ([f"{HEADER} A", f"{VERSION_KW} {OTHER_VERSION}", f"{VERSION_KW} {OTHER_VERSION}"], 3, VERSION_KW),
], ids=["header_twice", "header_then_field", "field_then_header", "header_ext_twice", "header_ext_then_field",
        "check_sum_disagree", "check_sum_agree", "version_disagree", "version_agree"])
def test_a_header_line_given_twice_is_refused(lines: list[str], bad_line: int, needle: str) -> None:
    _refused("\n".join(lines + [f"{FLOAT_KW} 1"]) + "\n", bad_line, needle)


def _doc() -> dict[str, Any]:
    return dict(cbf.to_canonical(cbf.decode(VALID.read_bytes())))


def _float_record(doc: dict[str, Any]) -> int:
    return next(i for i, r in enumerate(doc["records"]) if r["command"] == FLOAT_CMD.name)


def _obj_text(pairs: list[tuple[str, str]]) -> str:
    return "{" + ", ".join(f"{json.dumps(k)}: {v}" for k, v in pairs) + "}"


def test_duplicate_json_keys_are_refused_with_their_path() -> None:
    doc = _doc()
    i = _float_record(doc)
    arg = FLOAT_LAY.args[0].name
    recs = [json.dumps(r) for r in doc["records"]]
    rec = dict(doc["records"][i])
    args_text = _obj_text([(arg, "1.0"), (arg, "2.0")])
    recs[i] = _obj_text([(k, args_text if k == "args" else json.dumps(v)) for k, v in rec.items()])
    text = _obj_text([("header", json.dumps(doc["header"])), ("records", "[" + ", ".join(recs) + "]"),
                      ("trailing", '""')])
    with pytest.raises(cbf.JsonShapeError, match=rf"^\$\.records\[{i}\]\.args: duplicate key '{arg}'"):
        loads(text)
    with pytest.raises(cbf.JsonShapeError, match=r"^\$: duplicate key 'trailing'"):
        loads(text[:-1] + ', "trailing": ""}')
    head = _obj_text([(k, json.dumps(v)) for k, v in doc["header"].items()] + [(T.VMAJOR.name, "3")])
    with pytest.raises(cbf.JsonShapeError, match=rf"^\$\.header: duplicate key '{T.VMAJOR.name}'"):
        loads(_obj_text([("header", head), ("records", "[]")]))
    # without a duplicate key: the same document, its fractions kept as their text (a Numeral)
    assert loads(json.dumps(doc)) == json.loads(json.dumps(doc), parse_float=Numeral)


def test_duplicate_json_keys_through_the_cli(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    src = tmp_path / "a.json"
    src.write_text('{"records": [], "records": [], "header": {}}')
    rc, err = _cli(capsys, "encode", str(src), "-o", str(tmp_path / "a.cbf"))
    assert rc == EXIT_USAGE and "$: duplicate key 'records'" in err


# -- item 4: trailing text ---------------------------------------------------------------------
@pytest.mark.parametrize("line", [
    f"{RECORD_KW} {FLOAT_CMD.code:02x} {FLOAT_CMD.code:02x} 00 {'00' * FLOAT_LAY.size} ffffffff",
    f"{RECORD_KW} {FLOAT_CMD.code:02x} {FLOAT_CMD.code:02x} 00 {'00' * FLOAT_LAY.size} x",
    f"{CHECK_SUM} {{}} whatever",  # {} : the file checksum of the text without this line (issue 26)
    f"{FIELD_KW} {CONFIG.name} {'41' * CONFIG.size} junk",
], ids=["record", "record_word", "check_sum", "field"])
def test_trailing_text_is_refused(line: str) -> None:
    if "{}" in line:
        line = line.format(file_checksum_of(cbf.encode(cbf.from_cut(f"{HEADER} X\n"))))
    _refused(f"{HEADER} X\n{line}\n", 2, "unexpected text")
    assert cbf.from_cut(f"{HEADER} X\n{line.rsplit(' ', 1)[0]}\n") is not None  # fine without it


# -- item 5: ASCII only, wherever in the field ---------------------------------------------------
def test_control_bytes_after_a_nul_are_refused_in_cut() -> None:
    _refused(f"{HEADER} X\n{TEXT_KW} ok\x00\x01\x02\x7f\n", 2, "U+0000", column=len(TEXT_KW) + 4)
    raw = (b"ok\x00\x01\x02\x7f").ljust(TEXT_LAY.size, b"\x00")
    hidden = f"{RECORD_KW} {TEXT_CMD.code:02x} {TEXT_CMD.code:02x} 00 {raw.hex()}\n"
    model = cbf.from_cut(f"{HEADER} X\n{hidden}")  # the hex form carries any bytes, the writer refuses them
    with pytest.raises(cbf.EncodeError, match="string_ascii.*0x01"):
        cbf.encode(model)
    tail = (b"ok\x00tail").ljust(TEXT_LAY.size, b"\x00")  # a printable tail stays a warning (N4)
    cbf.encode(cbf.from_cut(f"{HEADER} X\n{RECORD_KW} {TEXT_CMD.code:02x} {TEXT_CMD.code:02x} 00 {tail.hex()}\n"))


def test_control_bytes_after_a_nul_are_refused_in_json(tmp_path: Path,
                                                        capsys: pytest.CaptureFixture[str]) -> None:
    doc = _doc()
    doc["records"].append({"command": TEXT_CMD.name, "args": {TEXT_LAY.args[0].name: "ok\u0000\u0001\u0002"}})
    with pytest.raises(cbf.EncodeError, match="string_ascii.*0x01"):
        cbf.encode(cbf.from_canonical(doc))
    doc["header"][IMPLANT.name] = "PN\u0000\u001b"
    doc["records"].pop()
    with pytest.raises(cbf.EncodeError, match=f"{IMPLANT.name}.*0x1B"):
        cbf.encode(cbf.from_canonical(doc))
    src = tmp_path / "a.json"
    src.write_text(json.dumps(doc))
    rc, err = _cli(capsys, "encode", str(src), "-o", str(tmp_path / "a.cbf"))
    assert rc == EXIT_USAGE and "0x1B" in err
    # --keep-stored reproduces a faulty file as given
    rc, _ = _cli(capsys, "encode", str(src), "--keep-stored", "-o", str(tmp_path / "a.cbf"))
    assert rc == EXIT_OK and b"PN\x00\x1b" in (tmp_path / "a.cbf").read_bytes()


@pytest.mark.parametrize("digit", ["\uff10", "\u0660", "\u00b2", "\u0030\u0301"])
def test_numbers_are_ascii_digits(digit: str) -> None:
    _refused(f"{HEADER} X\n{FLOAT_KW} {digit}.05\n", 2, column=len(FLOAT_KW) + 2 + (digit[0] == "0"))


# -- item 6: decimal text rounds to binary32 once ------------------------------------------------
def _nearest_binary32(x: Fraction) -> int | None:
    """The reference: round-to-nearest-even of an exact rational, None beyond the range."""
    sign = 0x80000000 if x < 0 else 0
    x = abs(x)
    lo, hi = 0, 0x7F800000  # bit patterns of non-negative floats order like their values
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if Fraction(_f32(mid)) <= x:
            lo = mid
        else:
            hi = mid
    below = Fraction(_f32(lo))
    above = Fraction(2) ** 128 if hi == 0x7F800000 else Fraction(_f32(hi))
    pick = lo if x - below < above - x or (x - below == above - x and lo % 2 == 0) else hi
    return None if pick == 0x7F800000 else sign | pick


def _decimal(x: Fraction, digits: int = 60) -> str:
    with localcontext() as ctx:  # the default context keeps 28 digits and would round the nudge away
        ctx.prec = digits + 10
        return format(Decimal(x.numerator) / Decimal(x.denominator), f".{digits}e") if x else "0"


def _positional(text: str) -> str:
    return format(Decimal(text), "f")


HALF_ULP_ABOVE_ONE = "1.000000059604644775390625"  # exactly halfway between 1 and the next binary32


@given(st.integers(0, 0x7F7FFFFE), st.integers(-3, 3), st.booleans())
@example(0x3F800000, 1, False)        # 1 + half an ulp + 1e-35: rounds up, not to 1 (the double is the midpoint)
@example(0x3F800000, 0, False)        # exactly halfway: ties to even
@example(0x3F800000, -1, False)
@example(0x7F7FFFFE, 0, False)
@example(0x00000000, 1, True)         # just above half the smallest subnormal
def test_decimal_text_near_a_halfway_point_rounds_once(bits: int, nudge: int, negative: bool) -> None:
    mid = (Fraction(_f32(bits)) + Fraction(_f32(bits + 1))) / 2
    x = (mid + Fraction(nudge, 10 ** 35) * mid) * (-1 if negative else 1) if mid else Fraction(0)
    text = _positional(_decimal(x, 130))  # enough digits for any binary32 midpoint exactly
    want = _nearest_binary32(Fraction(Decimal(text)))
    assert want is not None
    assert _bits(cbf.from_cut(f"{FLOAT_KW} {text}\n")) == want
    doc = {"header": {T.VMAJOR.name: 3, T.VMINOR.name: 0},
           "records": [{"command": FLOAT_CMD.name, "args": {FLOAT_LAY.args[0].name: "@"}}]}
    model = cbf.from_canonical(loads(json.dumps(doc).replace('"@"', text)))
    assert _bits(model) == want


def test_the_issue_example_rounds_up() -> None:
    assert _bits(cbf.from_cut(f"{FLOAT_KW} 1.00000005960464477539062500000000001\n")) == 0x3F800001
    assert _bits(cbf.from_cut(f"{FLOAT_KW} {HALF_ULP_ABOVE_ONE}\n")) == 0x3F800000
    assert _bits(cbf.from_cut(f"{FLOAT_KW} 1.00000005960464477539062499999999999\n")) == 0x3F800000


LARGEST = "340282356779733661637539395458142568447"  # just below FLT_MAX + half an ulp: FLT_MAX
BEYOND = ["340282356779733661637539395458142568448",    # FLT_MAX + half an ulp: ties to infinity
          "1" + "0" * 309, "9" * 310, "-" + "1" * 310, "1" + "0" * 400]


def test_numbers_beyond_binary32_are_refused_with_their_line() -> None:
    # the double nearest 3.4028235677973366e38 is FLT_MAX + half an ulp; the decimal is below it
    assert _bits(cbf.from_cut(f"{FLOAT_KW} {_positional('3.4028235677973366e38')}\n")) == 0x7F7FFFFF
    assert _bits(cbf.from_cut(f"{FLOAT_KW} {LARGEST}\n")) == 0x7F7FFFFF
    assert _bits(cbf.from_cut(f"{FLOAT_KW} -{LARGEST}\n")) == 0xFF7FFFFF
    for text in BEYOND:
        _refused(f"{HEADER} X\n{FLOAT_KW} {text}\n", 2, "outside the binary32 range")


JSON_BEYOND = ["1e400", "-1e39", "3.4028235677973367e38", "NaN", "Infinity", "-Infinity", "1" + "0" * 310,
               "1" + "0" * 5000]


@pytest.mark.parametrize("number", JSON_BEYOND, ids=lambda s: s[:12])
def test_json_numbers_beyond_binary32_are_refused_with_their_path(number: str, tmp_path: Path,
                                                                    capsys: pytest.CaptureFixture[str]) -> None:
    doc = _doc()
    i = _float_record(doc)
    arg = FLOAT_LAY.args[0].name
    doc["records"][i]["args"][arg] = "@"
    text = json.dumps(doc).replace('"@"', number)
    path = f"$.records[{i}].args.{arg}"
    with pytest.raises(cbf.JsonShapeError) as err:
        cbf.from_canonical(loads(text))
    assert str(err.value).startswith(f"{path}: "), str(err.value)
    src = tmp_path / "a.json"
    src.write_text(text)
    for extra in ([], ["--keep-stored"]):
        rc, said = _cli(capsys, "encode", str(src), *extra, "-o", str(tmp_path / "a.cbf"))
        assert rc == EXIT_USAGE and path in said, said
        assert not (tmp_path / "a.cbf").exists()


# -- item 7: a JSON bit pattern is 0x and exactly 8 hex digits --------------------------------
@pytest.mark.parametrize("pattern", ["0x-0000001", "0x+3f80000", "0x 3f80000", "0x3f8_0000", "0x3f80000",
                                     "0x3f8000000", "0X3F800000", "0x3f80000g", "0x\uff13f800000"[:10]])
def test_a_bad_bit_pattern_is_one_line_with_its_path(pattern: str, tmp_path: Path,
                                                      capsys: pytest.CaptureFixture[str]) -> None:
    doc = _doc()
    i = _float_record(doc)
    arg = FLOAT_LAY.args[0].name
    doc["records"][i]["args"][arg] = pattern
    path = f"$.records[{i}].args.{arg}"
    with pytest.raises(cbf.JsonShapeError) as err:
        cbf.from_canonical(doc)
    assert str(err.value).startswith(f"{path}: ")
    src = tmp_path / "a.json"
    src.write_text(json.dumps(doc))
    rc, msg = _cli(capsys, "encode", str(src), "-o", str(tmp_path / "a.cbf"))
    assert rc == EXIT_USAGE and path in msg


def test_a_good_bit_pattern_is_exact() -> None:
    doc = _doc()
    i = _float_record(doc)
    for pattern, bits in (("0x3f800001", 0x3F800001), ("0xFF7FFFFF", 0xFF7FFFFF), ("0x7fc00001", 0x7FC00001)):
        doc["records"][i]["args"][FLOAT_LAY.args[0].name] = pattern
        assert _bits(cbf.from_canonical(doc), i) == bits


# -- item 8: --keep-stored on CUT input --------------------------------------------------------
def test_keep_stored_refuses_cut_input(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    cut = tmp_path / "a.cut"
    cut.write_text(cbf.to_cut(cbf.decode(VALID.read_bytes())))
    out = tmp_path / "a.cbf"
    rc, err = _cli(capsys, "encode", str(cut), "--keep-stored", "-o", str(out))
    assert rc == EXIT_USAGE and "--keep-stored" in err and "JSON" in err
    assert not out.exists()
    rc, _ = _cli(capsys, "encode", str(cut), "--input-format", "cut", "--keep-stored", "-o", str(out))
    assert rc == EXIT_USAGE and not out.exists()
    src = tmp_path / "a.json"
    src.write_text(json.dumps(_doc()))
    rc, _ = _cli(capsys, "encode", str(src), "--keep-stored", "-o", str(out))
    assert rc == EXIT_OK and out.read_bytes() == VALID.read_bytes()


# -- item 11: integers are bounded before conversion ------------------------------------------
@pytest.mark.parametrize("version", ["4." + "0" * 5000, "4" * 5000 + ".0", "256.0", "4.256", "4", "4.0.0",
                                     "\uff14.0", "-4.0", "4.+0"])
def test_a_bad_version_line_is_one_line(version: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    text = f"{HEADER} X\n{VERSION_KW} {version}\n{FLOAT_KW} 1\n"
    if version.isascii():
        err = _refused(text, 2, VERSION_KW)
        assert len(str(err)) < 200
    src = tmp_path / "a.cut"
    src.write_text(text)
    rc, msg = _cli(capsys, "encode", str(src), "-o", str(tmp_path / "a.cbf"))
    assert rc == EXIT_USAGE and "line 2" in msg and len(msg) < 300


def test_a_long_json_integer_is_refused_with_its_path() -> None:
    doc = _doc()
    text = json.dumps(doc).replace(f'"{T.VMAJOR.name}": 3', f'"{T.VMAJOR.name}": {"3" * 5000}')
    with pytest.raises(cbf.JsonShapeError, match=rf"^\$\.header\.{T.VMAJOR.name}: .*5000 digits"):
        cbf.from_canonical(loads(text))
