"""Facts in prose (issue 37, point 1): a decision's text names a fact of the model by placeholder,
``{{writable_versions}}``, which the loader renders (``cbfgen.prose``); a placeholder that names no
fact is refused with its YAML line, so the document never prints one."""

from __future__ import annotations

from ...prose import FACTS, unknown
from ..pipeline import State, define
from ..problems import Problems


@define("prose", "check", reads=("raw",))
def PROSE(ctx: Problems, st: State) -> None:
    """Every placeholder of a decision's text names a fact the loader renders from the model."""
    known = ", ".join(f"{{{{{k}}}}}" for k in FACTS)
    for d in st.raw["decisions"]:
        for key in ("decision", "evidence"):
            for bad in unknown(str(d[key])):
                ctx.fail(d, f"decision {d['id']}: {bad!r} in its {key} names no fact of the model (known: {known})",
                         key)
