"""Limits against the fields that store them, and wire values every binding implements alike
(issue 36, point 1)."""

from __future__ import annotations

from ...registry import MAX_FILE_BYTES
from ..pipeline import State, define
from ..problems import Problems


@define("limits", "check", reads=("raw", "headers", "record"))
def LIMITS(ctx: Problems, st: State) -> None:
    """limits.max_commands fits the command_count field of every header layout, and the largest file
    the limits allow fits the buffer a binding holds it in (registry.MAX_FILE_BYTES: 2^40 commands
    made cbf-c a 289 TB static buffer)."""
    limits = st.raw["limits"]
    head = max((h.size for h in st.headers.values()), default=0)
    largest = head + (limits["max_commands"] + 1) * (st.record.head_size + limits["max_arg_size"])
    if largest > MAX_FILE_BYTES:
        ctx.fail(limits, f"limits: the largest file is {largest} bytes ({head} + ({limits['max_commands']} + 1) x "
                         f"({st.record.head_size} + {limits['max_arg_size']})); the bindings hold a file of at most "
                         f"{MAX_FILE_BYTES} (registry.MAX_FILE_BYTES)", "max_commands")
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
