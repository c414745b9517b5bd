"""The CUT companion document (generated/docs/cut.md, issue 26) and the reader agree.

- The document's complete example file encodes to its golden case's bytes, validates without a
  finding, and decodes back to the same text.
- A CUT file written by hand from the document alone (HAND below, each line with the section of the
  document it follows) encodes and validates.
- What the document says the reader does: a check_sum line that is not the file checksum is refused
  (naming its line), a file without a header line is read and `validate` reports it, the version comes
  from cbf_version and not from the VERSION command, and the inputs section 6 lists are refused.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import cbf
from cbf import tables as T
from cbfgen.emit import docs
from cbfgen.loader import load

REPO = Path(__file__).resolve().parents[1]
SPEC = load(REPO / "spec" / "cbf.yaml")
C = T.CUT
ORDER = "little" if T.BO == "<" else "big"


def _page() -> str:
    return docs.emit(SPEC)[f"docs/{docs.CUT_PAGE}"].decode()


def _example(page: str) -> str:
    block = page[page.index('<a id="cut-example"></a>'):]
    m = re.search(r"```\n(.*?)```", block, re.S)
    assert m, "the companion document has no example file"
    return m.group(1)


def _file_checksum(data: bytes) -> int:
    f = T.HEADER_CHECKSUM_FIELDS["file"]
    return int.from_bytes(data[f.offset:f.offset + f.size], ORDER)


def test_the_committed_page_is_the_generated_one() -> None:
    assert (REPO / "generated" / "docs" / docs.CUT_PAGE).read_text(encoding="utf-8") == _page()


def test_the_example_file_encodes_validates_and_decodes_back() -> None:
    page = _page()
    text = _example(page)
    case = re.search(r"The golden case \[([^\]]+)\]", page)
    assert case, "the example names no golden case"
    data = cbf.encode(cbf.from_cut(text))
    assert data == (REPO / "conformance" / "golden" / f"{case.group(1)}.cbf").read_bytes()
    assert cbf.validate(data) == []
    assert cbf.to_cut(cbf.decode(data)) == text
    # the example uses the header keywords the document defines
    assert text.startswith(C["header_keyword"] + " ") and f"\n{C['header_ext_keyword']} " in text


# Written from generated/docs/cut.md alone (rev 03's commands: a revision that drops one of them
# rewrites this file, as it would any hand-written CUT file). Each line names the section it follows.
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


def test_a_hand_written_file_encodes_and_validates() -> None:
    assert len(HAND_SECTIONS) == len(HAND.splitlines())
    model = cbf.from_cut(HAND)
    assert model.version_id == "4.0"
    data = cbf.encode(model)
    assert [f for f in cbf.validate(data) if f.severity == "error"] == []
    back = cbf.decode(data)
    assert back.header.implant_descriptor == "PN-1234 KNEE FEMORAL SIZE 3"
    assert back.records[0].decode_args().text == "hand-written from the companion doc"
    # with the check line the document describes (section 3), the same file reads the same
    assert cbf.from_cut(HAND + f"{C['checksum_keyword']} {_file_checksum(data)}\n") == model


def test_a_wrong_check_sum_is_refused_with_its_line() -> None:
    text = _example(_page())
    good = _file_checksum(cbf.encode(cbf.from_cut(text)))
    lines = text.splitlines()
    assert cbf.from_cut("\n".join([*lines[:1], f"{C['checksum_keyword']} {good}", *lines[1:]]) + "\n")
    with pytest.raises(cbf.CutSyntaxError) as exc:
        cbf.from_cut("\n".join([*lines[:1], f"{C['checksum_keyword']} {good + 1}", *lines[1:]]) + "\n")
    assert exc.value.line == 2 and str(good) in str(exc.value)


def test_a_file_without_a_header_line_is_reported_as_the_document_says() -> None:
    page = _page()
    checks = T.checks_of("descriptor_word")
    assert checks, "the spec has no check that reports an empty implant descriptor"
    assert all(f"[{k['id']}]" in page for k in checks)  # the document names the check
    lines = [line for line in _example(page).splitlines() if not line.startswith(C["header_keyword"] + " ")]
    data = cbf.encode(cbf.from_cut("\n".join(lines) + "\n"))
    assert {f.check for f in cbf.validate(data)} >= {k["id"] for k in checks}


def test_the_version_command_does_not_choose_the_version() -> None:
    """The document's section 5: `version 1.0 4.0` leaves the header at the default version; only
    cbf_version chooses 4.0, which then refuses a command 4.0 lacks."""
    lacking = next(((v.id, c) for v in T.VERSIONS if v.writable for c in T.COMMANDS
                    if not c.layouts_for(v.id) and c.layouts_for(T.DEFAULT_VERSION)), None)
    assert lacking, "no writable version lacks a command of the default version"
    version, cmd = lacking
    probe = next(c for c in T.COMMANDS if c.sets and "format_version" in c.sets)
    rec = cbf.to_cut(cbf.decode(cbf.encode(cbf.from_cut(_example(_page())))))
    line = next(x for x in rec.splitlines() if x.split(" ", 1)[0] == cmd.name.lower())
    text = f"{C['header_keyword']} P\n{probe.name.lower()} 1.0 {version}\n{line}\n"
    assert cbf.from_cut(text).version_id == T.DEFAULT_VERSION
    with pytest.raises(cbf.CutSyntaxError) as exc:
        cbf.from_cut(f"{C['extensions']['version_keyword']} {version}\n" + text)
    assert exc.value.line == 4


@pytest.mark.parametrize("bad", ["1e-3", ".5", "+1", "nan", "inf"])
def test_floats_the_document_refuses(bad: str) -> None:
    speed = next(c for c in T.COMMANDS if c.sets and "speed" in c.sets)
    with pytest.raises(cbf.CutSyntaxError) as exc:
        cbf.from_cut(f"{C['header_keyword']} P\n{speed.name.lower()} {bad}\n")
    assert exc.value.line == 2
    assert f"`{bad}`" in _page()


@pytest.mark.parametrize("line", ["# a comment", "\tcutter_on"])
def test_comments_and_tabs_are_refused(line: str) -> None:
    with pytest.raises(cbf.CutSyntaxError) as exc:
        cbf.from_cut(f"{C['header_keyword']} P\n{line}\n")
    assert exc.value.line == 2


def test_the_grammar_defines_every_token_it_uses() -> None:
    page = _page()
    grammar = page[page.index('<a id="cut-grammar"></a>'):page.index('<a id="cut-keywords"></a>')]
    code = re.search(r"```\n(.*?)```", grammar, re.S)
    assert code
    rules = code.group(1)
    defined = set(re.findall(r"^([a-z][a-z-]*)\s*=", rules, re.M))
    used = set(re.findall(r"(?<![\"a-z_-])([a-z][a-z-]*[a-z])(?![\"a-z_-])", re.sub(r'"[^"]*"|\(\*.*?\*\)|\?[^?]*\?',
                                                                                  "", rules)))
    assert used - defined - {"LF", "CR"} == set(), used - defined
    for keyword in (C["header_keyword"], C["header_ext_keyword"], C["checksum_keyword"], *C["extensions"].values()):
        assert f'"{keyword}"' in rules, keyword
    for c in T.COMMANDS:
        assert f'"{c.name.lower()}"' in rules, c.name
