"""The CUT companion document (generated/docs/cut.md, issue 26) and the reader agree.

- The document's complete example file encodes to its golden case's bytes, validates without a
  finding, and decodes back to the same text.
- (A CUT file written by hand from the document alone uses rev 03's commands: it is one of the rev 03
  facts, tests/test_rev03_facts.py.)
- What the document says the reader does: a check_sum line that is not the file checksum is refused
  (naming its line), a file without a header line is read and `validate` reports it, the version comes
  from cbf_version and not from the VERSION command, and the inputs section 6 lists are refused.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from conftest import file_checksum_of

import cbf
from cbf import tables as T
from cbfgen.emit import docs
from cbfgen.loader import load

REPO = Path(__file__).resolve().parents[1]
SPEC = load(REPO / "spec" / "cbf.yaml")
C = T.CUT


def _page() -> str:
    return docs.emit(SPEC)[f"docs/{docs.CUT_PAGE}"].decode()


def _example(page: str) -> str:
    block = page[page.index('<a id="cut-example"></a>'):]
    m = re.search(r"```\n(.*?)```", block, re.S)
    assert m, "the companion document has no example file"
    return m.group(1)


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


def test_a_wrong_check_sum_is_refused_with_its_line() -> None:
    text = _example(_page())
    good = file_checksum_of(cbf.encode(cbf.from_cut(text)))
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
