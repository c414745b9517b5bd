"""A revision bump reads as that revision (issue 26).

With meta.revision "04" and a history entry, the published document is 300071 rev 04 (title, title
block, page header, revision history) while the errata of rev 03 stay labelled rev 03: an erratum
names the revision it corrects, and no template names a revision by hand.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

import pytest
from conftest import dump_yaml, spec_doc

from cbfgen.emit import docs
from cbfgen.emit.docs import pdf
from cbfgen.loader import load
from cbfgen.model import Spec

REPO = Path(__file__).resolve().parents[1]
TEMPLATES = REPO / "generator" / "cbfgen" / "emit" / "docs" / "templates"


@dataclass(frozen=True)
class Bump:
    """The spec bumped to the revision after its history's newest (04 on top of rev 03)."""

    spec: Spec
    new: str  # the bumped revision
    old: str  # meta.revision before the bump
    history: list[str]  # the history's revisions, the new one last
    errata: dict[str, str]  # each erratum's id and the revision it corrects


def _next_revision(revisions: list[str]) -> str:
    """The two-digit revision after the highest numeric one (a revised tree's meta.revision may be a label)."""
    numbers = [int(r) for r in revisions if r.isdigit()]
    return f"{max(numbers, default=0) + 1:02d}"


@pytest.fixture(scope="module")
def rev04(tmp_path_factory: pytest.TempPathFactory) -> Bump:
    doc = spec_doc()
    old = str(doc["meta"]["revision"])
    history = [str(h["revision"]) for h in doc["meta"]["history"]]
    errata = {str(e["id"]): str(e["revision"]) for e in doc["errata"]}
    assert set(errata.values()) <= set(history), errata  # an erratum names a published revision
    new = _next_revision([old, *history])
    doc["meta"]["revision"] = new
    doc["meta"]["release"] = {"date": "2027-01-15", "change_order": "CO-0815"}
    doc["meta"]["history"].append({"revision": new, "date": "2027-01-15", "change_order": "CO-0815",
                                   "summary": "Published from spec/cbf.yaml; errata corrected."})
    path = tmp_path_factory.mktemp("rev04") / "cbf.yaml"
    path.write_text(dump_yaml(doc, sort_keys=False), encoding="utf-8")
    return Bump(load(path), new, old, [*history, new], errata)


def test_the_document_reads_as_rev_04(rev04: Bump) -> None:
    spec, new = rev04.spec, rev04.new
    page = docs.reference(spec)
    part = spec.meta["part_number"]
    assert page.startswith(f"# {part} rev {new}: ")
    assert f"| {part} | {new} |" in page  # the title block
    assert "| 2027-01-15 | CO-0815 |" in page  # release date and change order
    history = page[page.index('<a id="document-history"></a>'):page.index('<a id="how-to-read"></a>')]
    cells = [m.group(1) for row in history.splitlines() if (m := re.match(r"\| ([^|]+?) \|", row))]
    assert [c for c in cells if c in rev04.history] == rev04.history
    header, _ = pdf.frame(spec, "0")
    assert f"Revision: {new}" in header and f"Revision: {rev04.old}" not in header
    cut = docs.emit(spec)[f"docs/{docs.CUT_PAGE}"].decode()
    assert cut.startswith(f"# The CUT text format: companion document to {part} rev {new}")


def test_the_errata_of_rev_03_stay_labelled_rev_03(rev04: Bump) -> None:
    spec, new = rev04.spec, rev04.new
    page = docs.reference(spec)
    part = spec.meta["part_number"]
    errata = page[page.index('<a id="errata"></a>'):page.index('<a id="toolkit-reference"></a>')]
    assert f"## Appendix B: Errata in {part}\n" in errata
    assert {e.id for e in spec.errata} == set(rev04.errata)
    for eid, rev in rev04.errata.items():
        assert re.search(rf'<a id="erratum-{eid.lower()}"></a>{eid} \| rev {rev} \|', errata), eid
        assert f"Erratum [{eid}](#erratum-{eid.lower()}) (in {part} rev {rev})" in page, eid
    assert f"rev {new}" not in errata
    # every other mention of an erratum's revision is the history row or the spec's own words
    for rev in set(rev04.errata.values()):
        for line in page.splitlines():
            if (re.search(rf"\brev {rev}\b", line) and "Erratum [" not in line and f"| rev {rev} |" not in line
                    and "CO-0815" not in line):
                assert "specified by" in line, line


def test_no_template_names_a_revision() -> None:
    for t in sorted(TEMPLATES.glob("*.j2")):
        text = t.read_text(encoding="utf-8")
        assert not re.search(r"\brev(ision)?\.? ?0[0-9]\b|\b30007[12]\b", text, re.I), t.name
