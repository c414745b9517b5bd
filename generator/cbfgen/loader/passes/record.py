"""The record head: its fields tile head_size, with a field of each record role."""

from __future__ import annotations

from ...model import RecordLayout
from ..fields import fields
from ..pipeline import State, define
from ..problems import Problems

RECORD_ROLES = ("sequence", "code", "code_copy", "arg_size", "reserved")


@define("record", "resolve", reads=("raw", "types"), produces=("record",))
def RECORD(ctx: Problems, st: State) -> None:
    """The record head's fields, tiling its declared head_size."""
    r = st.raw["record"]
    rfields, rend, whole = fields(ctx, r["fields"], st.types, "record")
    if whole and rend != r["head_size"]:
        ctx.fail(r, f"record head fields tile {rend} bytes, declared {r['head_size']}", "head_size")
    st.record = RecordLayout(r["head_size"], r["clause"], str(r["doc"]).strip(), rfields)


@define("record-roles", "check", reads=("raw", "record"))
def RECORD_ROLES_PASS(ctx: Problems, st: State) -> None:
    """The record head has an unsigned field of each record role, its arg_size wide enough for
    limits.max_arg_size."""
    r = st.raw["record"]
    missing = False
    for role in RECORD_ROLES:
        f = next((x for x in st.record.fields if x.role == role), None)
        if f is None:
            ctx.fail(r, f"record has no field with role {role}")
            missing = True
        elif f.kind != "uint":
            ctx.at(f.line, f"record field {f.name}: role {role} needs an unsigned integer type")
    if not missing and 1 << (8 * st.record.by_role("arg_size").size) <= st.raw["limits"]["max_arg_size"]:
        ctx.fail(r, "arg_size field too small for limits.max_arg_size")
