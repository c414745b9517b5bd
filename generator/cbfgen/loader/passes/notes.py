"""Every note a spec names is one it has (issue 36, point 1): the document links a clause's notes
and a command's erratum by id, and a note id that names nothing stopped generation with a traceback."""

from __future__ import annotations

from ..pipeline import State, define
from ..problems import Problems


@define("notes", "check", reads=("raw", "decisions"))
def NOTES(ctx: Problems, st: State) -> None:
    """Each note of meta.clauses names a decision or an erratum, and each command's erratum an
    erratum, of the spec."""
    errata = {str(e["id"]) for e in st.raw["errata"]}
    notes = errata | {d.id for d in st.decisions}
    for c in st.raw["meta"]["clauses"]:
        for note in c.get("notes", ()):
            if note not in notes:
                ctx.fail(c, f"meta.clauses: clause {c['number']} notes {note!r}, which is no decision or erratum "
                            f"of the spec", "notes")
    for cmd in st.raw["commands"]:
        if "erratum" in cmd and str(cmd["erratum"]) not in errata:
            ctx.fail(cmd, f"{cmd['name']}: erratum {cmd['erratum']!r} is no erratum of the spec", "erratum")
