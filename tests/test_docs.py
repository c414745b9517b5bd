"""The generated format documentation: complete, linked, and traceable."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from conftest import generate, load_yaml, spec_with_fixture_command

from cbfgen.loader import load

REPO = Path(__file__).resolve().parents[1]
DOC = (REPO / "generated" / "docs" / "index.md").read_text(encoding="utf-8")
SPEC = load(REPO / "spec" / "cbf.yaml")


def _anchors(text: str) -> set[str]:
    return set(re.findall(r'<a id="([^"]+)"></a>', text))


def test_every_internal_link_resolves() -> None:
    anchors = _anchors(DOC)
    links = re.findall(r"\]\(#([^)]+)\)", DOC)
    assert links
    missing = sorted({link for link in links if link not in anchors})
    assert not missing, missing


def test_relative_file_links_exist() -> None:
    base = REPO / "generated" / "docs"
    for target in re.findall(r"\]\((\.\./[^)#]+)\)", DOC):
        assert (base / target).resolve().exists(), target


@pytest.mark.parametrize("name", [c.name for c in SPEC.commands])
def test_every_command_has_a_page(name: str) -> None:
    page = f"commands/{name.lower().replace('_', '-')}.md"
    text = (REPO / "generated" / "docs" / page).read_text(encoding="utf-8")
    assert f"# {name} (0x" in text
    assert f"[{name}]({page})" in DOC


def test_every_check_is_documented_and_traced() -> None:
    trace = DOC[DOC.index('<a id="traceability-matrix"></a>'):]
    for check in SPEC.checks:
        assert f"`{check.id}`" in DOC
        assert f"[{check.id}](#check-" in trace, check.id


def test_decisions_and_errata_are_published() -> None:
    for note in SPEC.decisions + SPEC.errata:
        assert note.text.split()[0] in DOC


def test_missing_report_is_said(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    import cbfgen.emit.docs as docs

    monkeypatch.setattr(docs, "REPORT", tmp_path / "absent.json")
    text = docs.emit(SPEC)["docs/index.md"].decode()
    assert "No conformance report is present: no status is shown (`cbfgen --report FILE`" in text
    assert "pass (" not in text


def test_new_command_appears_in_the_docs(tmp_path: Path) -> None:
    generate(spec_with_fixture_command(tmp_path), tmp_path / "gen", "docs")
    docs = tmp_path / "gen" / "docs"
    index = (docs / "index.md").read_text(encoding="utf-8")
    page = (docs / "commands" / "dwell.md").read_text(encoding="utf-8")
    assert "[DWELL](commands/dwell.md)" in index
    assert "# DWELL (0x44)" in page and "`seconds`" in page
    assert "seconds" in (docs / "svg" / "cmd-dwell.svg").read_text(encoding="utf-8")


# Checks that read every record alike: the command pages point to the integrity checks for these.
RECORD_LEVEL = {"sequence", "code_copy", "arg_size", "arg_checksum", "reserved_byte", "unknown_code",
                "truncated_record"}


def test_command_pages_list_every_check_the_golden_cases_raise_on_them() -> None:
    """Each finding a golden case expects on a record is listed on that record's command page."""

    from cbf.codec import decode

    kinds = {k.id: k.kind for k in SPEC.checks}
    seen = 0
    for expect in sorted((REPO / "conformance" / "golden").glob("*.expect.yaml")):
        doc = load_yaml(expect)
        if doc.get("decode") != "ok":
            continue
        records = decode(expect.with_name(expect.name.replace(".expect.yaml", ".cbf")).read_bytes()).records
        for check, _severity, rec, _offset in (f for findings in doc["validate"].values() for f in findings):
            check = str(check)
            if rec is None or kinds[check] in RECORD_LEVEL or records[rec].command is None:
                continue
            name = records[rec].command.name
            page = (REPO / "generated" / "docs" / "commands" / f"{name.lower().replace('_', '-')}.md")
            assert f"[{check}](../index.md#check-" in page.read_text(encoding="utf-8"), (expect.name, check, name)
            seen += 1
    assert seen > 20
