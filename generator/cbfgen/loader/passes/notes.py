"""Every note a spec names is one it has (issue 36, point 1): the document links a clause's notes
and a command's erratum by id, and a note id that names nothing stopped generation with a traceback.
A note id is one note's: a decision or erratum id given twice was accepted, and a clause's note (or a
finding's clause id, a traceability row) naming it could mean either; the document gave both one anchor."""

from __future__ import annotations

from ..pipeline import State, define
from ..problems import Problems
from ..yaml_reader import node_line


@define("notes", "check", reads=("raw", "decisions"))
def NOTES(ctx: Problems, st: State) -> None:
    """Each note of meta.clauses names a decision or an erratum, and each command's erratum an
    erratum, of the spec."""
    errata = {str(e["id"]) for e in st.raw["errata"]}
    notes = errata | {d.id for d in st.decisions}
    _unique_ids(ctx, st)
    for c in st.raw["meta"]["clauses"]:
        for note in c.get("notes", ()):
            if note not in notes:
                ctx.fail(c, f"meta.clauses: clause {c['number']} notes {note!r}, which is no decision or erratum "
                            f"of the spec", "notes")
    for cmd in st.raw["commands"]:
        if "erratum" in cmd and str(cmd["erratum"]) not in errata:
            ctx.fail(cmd, f"{cmd['name']}: erratum {cmd['erratum']!r} is no erratum of the spec", "erratum")


def _unique_ids(ctx: Problems, st: State) -> None:
    """No two decisions or errata share an id (a decision and an erratum neither: a note names either)."""
    seen: dict[str, tuple[str, int]] = {}
    for key in ("decisions", "errata"):
        for item in st.raw[key]:
            nid = str(item["id"])
            if nid in seen:
                other, line = seen[nid]
                ctx.fail(item, f"{key}: duplicate note id {nid!r} (also {other}, line {line})", "id")
            else:
                seen[nid] = (key, node_line(item, "id"))
