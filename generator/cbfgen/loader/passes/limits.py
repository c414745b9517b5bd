"""Limits against the fields that store them, and wire values every binding implements alike
(issue 36, point 1)."""

from __future__ import annotations

from ..pipeline import State, define
from ..problems import Problems


@define("limits", "check", reads=("raw", "headers"))
def LIMITS(ctx: Problems, st: State) -> None:
    """limits.max_commands fits the command_count field of every header layout (the bindings size
    their record tables by it: 2^40 made cbf-c a 289 TB static buffer)."""
    limits = st.raw["limits"]
    for h in st.headers.values():
        f = h.by_role("command_count")
        if f is None or f.kind != "uint":
            continue  # the header-layouts pass refuses it
        most = (1 << (8 * f.size)) - 1
        if limits["max_commands"] > most:
            ctx.fail(limits, f"limits.max_commands {limits['max_commands']} does not fit header {h.id}'s "
                             f"{f.name} ({f.type}: at most {most})", "max_commands")


# The padding bytes every binding strips and writes alike (C's reader keeps only NUL).
PADDINGS = (0,)


@define("padding", "check", reads=("raw",))
def PADDING(ctx: Problems, st: State) -> None:
    """meta.string_padding is a padding byte every binding implements alike: NUL (another made
    cbf and cbf-c differ on 834 lines of the golden files)."""
    meta = st.raw["meta"]
    if meta["string_padding"] not in PADDINGS:
        ctx.fail(meta, f"meta.string_padding {meta['string_padding']}: the bindings pad and strip strings alike "
                       f"only with {', '.join(map(str, PADDINGS))} (NUL)", "string_padding")
