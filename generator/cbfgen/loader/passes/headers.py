"""The header layouts: each tiles its size; all have one size; the shared fields sit in shared places."""

from __future__ import annotations

from ...model import HeaderLayout
from ...registry import DERIVED_HEADER_ROLES
from ..fields import fields
from ..pipeline import State, define
from ..problems import Problems

# The roles every header layout has (each an unsigned integer).
HEADER_ROLES = ("start_pattern", "end_pattern", "version_major", "version_minor", "command_count")


@define("headers", "resolve", reads=("raw", "types"), produces=("headers",))
def HEADERS(ctx: Problems, st: State) -> None:
    """Each header layout's fields, tiling its declared size."""
    out: dict[str, HeaderLayout] = {}
    for hid, h in st.raw["headers"].items():
        got, end, whole = fields(ctx, h["fields"], st.types, f"header {hid}")
        if whole and end != h["size"]:
            ctx.fail(h, f"header {hid} fields tile {end} bytes, declared {h['size']}", "size")
        out[hid] = HeaderLayout(hid, h["size"], h["clause"], str(h["doc"]).strip(), got, h.line)
    st.headers = out


@define("header-layouts", "check", reads=("raw", "headers"))
def HEADER_LAYOUTS(ctx: Problems, st: State) -> None:
    """All header layouts have the first one's size, its derived fields (registry.DERIVED_HEADER_ROLES)
    in the same places, and a field of each header role."""
    raw = st.raw
    first = next(iter(st.headers.values()))
    for h in st.headers.values():
        if h.size != first.size:
            ctx.fail(raw["headers"][h.id], f"header {h.id} is {h.size} bytes, header {first.id} {first.size}", "size")
        for f in h.fields:
            if f.role == "checksum" and f.checksum not in {x.checksum for x in first.fields}:
                continue  # a checksum field of this layout's own (a new version's): the checksum-fields pass
            if f.role in DERIVED_HEADER_ROLES:
                twin = first.field(f.name)
                if twin is None or (twin.offset, twin.type, twin.role, twin.magic, twin.checksum) != (
                        f.offset, f.type, f.role, f.magic, f.checksum):
                    ctx.at(f.line, f"header {h.id} field {f.name} must match header {first.id}")
        for role in HEADER_ROLES:
            rf = h.by_role(role)
            if rf is None:
                ctx.fail(raw["headers"][h.id], f"header {h.id} has no field with role {role}")
            elif rf.kind != "uint":
                ctx.at(rf.line, f"header {h.id}: the {role} field needs an unsigned integer type")
