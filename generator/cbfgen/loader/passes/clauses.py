"""What the published document needs (issue 37, point 2): the text of every clause it links to.

The document (generated/docs/index.md, the site, the PDF) prints each section of ``meta.sections``
with the clauses of ``meta.clauses`` whose number starts with its id, and links a check, a history
entry and an erratum to the clause they cite. A revision that cites a new clause adds its text
(``meta.clauses``: ``{number: "8.3", text: ...}``) and, for a new section, the section
(``meta.sections``: ``{id: "8", title: ...}``); the loader refuses a citation without them.
"""

from __future__ import annotations

from ..pipeline import State, define
from ..problems import Problems
from ..yaml_reader import Map


def section_of(number: str) -> str:
    """The section a clause number belongs to: "6.4.3" -> "6"."""
    return number.split(".")[0]


def _document(ctx: Problems, meta: Map) -> set[str]:
    """Every clause number of the document, once, each in a section of the document."""
    sections: set[str] = set()
    for s in meta["sections"]:
        if str(s["id"]) in sections:
            ctx.fail(s, f"meta.sections: section {s['id']} is listed twice", "id")
        sections.add(str(s["id"]))
    numbers: set[str] = set()
    for c in meta["clauses"]:
        n = str(c["number"])
        if n in numbers:
            ctx.fail(c, f"meta.clauses: clause {n} is listed twice", "number")
        numbers.add(n)
        if section_of(n) not in sections:
            ctx.fail(c, f"meta.clauses: clause {n} is in no section of meta.sections (add "
                        f"{{id: \"{section_of(n)}\", title: ...}} there)", "number")
    return numbers


@define("clauses", "check", reads=("raw",))
def CLAUSES(ctx: Problems, st: State) -> None:
    """Every clause a check, a history entry or an erratum cites has its text in meta.clauses, in a
    section of meta.sections: the document quotes and links it."""
    numbers = _document(ctx, st.raw["meta"])
    for ch in st.raw["checks"]:
        if ch.get("clause") is not None and str(ch["clause"]) not in numbers:
            ctx.fail(ch, f"check {ch['id']}: clause {ch['clause']} has no text in meta.clauses (the document "
                         f"quotes it: add {{number: \"{ch['clause']}\", text: ...}} there)", "clause")
    for h in st.raw["history"]:
        if str(h["clause"]) not in numbers:
            ctx.fail(h, f"history {h['version']}: clause {h['clause']} has no text in meta.clauses (the document "
                        f"links it: add {{number: \"{h['clause']}\", text: ...}} there)", "clause")
    for e in st.raw["errata"]:
        if str(e["clause"]) not in numbers:
            ctx.fail(e, f"erratum {e['id']}: clause {e['clause']} has no text in meta.clauses (the document "
                        f"links it: add {{number: \"{e['clause']}\", text: ...}} there)", "clause")
