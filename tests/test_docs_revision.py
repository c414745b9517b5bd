"""A revision bump reads as that revision (issue 26).

With meta.revision "04" and a history entry, the published document is 300071 rev 04 (title, title
block, page header, revision history) while the errata of rev 03 stay labelled rev 03: an erratum
names the revision it corrects, and no template names a revision by hand.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from conftest import dump_yaml, spec_doc

from cbfgen.emit import docs
from cbfgen.emit.docs import pdf
from cbfgen.loader import load
from cbfgen.model import Spec

REPO = Path(__file__).resolve().parents[1]
TEMPLATES = REPO / "generator" / "cbfgen" / "emit" / "docs" / "templates"


@pytest.fixture(scope="module")
def rev04(tmp_path_factory: pytest.TempPathFactory) -> Spec:
    doc = spec_doc()
    old = doc["meta"]["revision"]
    assert all(e["revision"] == old for e in doc["errata"])
    doc["meta"]["revision"] = "04"
    doc["meta"]["release"] = {"date": "2027-01-15", "change_order": "CO-0815"}
    doc["meta"]["history"].append({"revision": "04", "date": "2027-01-15", "change_order": "CO-0815",
                                   "summary": "Published from spec/cbf.yaml; errata E1 to E4 of rev 03 corrected."})
    path = tmp_path_factory.mktemp("rev04") / "cbf.yaml"
    path.write_text(dump_yaml(doc, sort_keys=False), encoding="utf-8")
    return load(path)


def test_the_document_reads_as_rev_04(rev04: Spec) -> None:
    page = docs.reference(rev04)
    part = rev04.meta["part_number"]
    assert page.startswith(f"# {part} rev 04: ")
    assert f"| {part} | 04 |" in page  # the title block
    assert "| 2027-01-15 | CO-0815 |" in page  # release date and change order
    history = page[page.index('<a id="document-history"></a>'):page.index('<a id="how-to-read"></a>')]
    assert [row.split("|")[1].strip() for row in history.splitlines() if re.match(r"\| 0\d ", row)] == ["03", "04"]
    header, _ = pdf.frame(rev04, "0")
    assert "Revision: 04" in header and "Revision: 03" not in header
    cut = docs.emit(rev04)[f"docs/{docs.CUT_PAGE}"].decode()
    assert cut.startswith(f"# The CUT text format: companion document to {part} rev 04")


def test_the_errata_of_rev_03_stay_labelled_rev_03(rev04: Spec) -> None:
    page = docs.reference(rev04)
    part = rev04.meta["part_number"]
    errata = page[page.index('<a id="errata"></a>'):page.index('<a id="toolkit-reference"></a>')]
    assert f"## Appendix B: Errata in {part}\n" in errata
    for e in rev04.errata:
        assert re.search(rf'<a id="erratum-{e.id.lower()}"></a>{e.id} \| rev 03 \|', errata), e.id
        assert f"Erratum [{e.id}](#erratum-{e.id.lower()}) (in {part} rev 03)" in page, e.id
    assert "rev 04" not in errata
    # every other "rev 03" of the page is the history row or the spec's own words
    for line in page.splitlines():
        if "rev 03" in line and "Erratum [" not in line and "| rev 03 |" not in line and "CO-0815" not in line:
            assert "specified by" in line, line


def test_no_template_names_a_revision() -> None:
    for t in sorted(TEMPLATES.glob("*.j2")):
        text = t.read_text(encoding="utf-8")
        assert not re.search(r"\brev(ision)?\.? ?0[0-9]\b|\b30007[12]\b", text, re.I), t.name
