"""The versions of the format, and the checks of what they name."""

from __future__ import annotations

from ...model import Version
from ..pipeline import State, define
from ..problems import Problems


@define("versions", "resolve", reads=("raw",), produces=("versions", "vids"))
def VERSIONS(ctx: Problems, st: State) -> None:
    """The versions, in the spec's order; a duplicate id is refused (and left out)."""
    out: list[Version] = []
    for v in st.raw["versions"]:
        if any(o.id == str(v["id"]) for o in out):
            ctx.fail(v, f"duplicate version id {v['id']!r}", "id")
            continue
        out.append(Version(str(v["id"]), v["major"], v.get("minor"), v["header"], v["clause"], v["writable"],
                           str(v["doc"]).strip(), v.line, v.get("since")))
    st.versions = tuple(out)
    st.vids = tuple(v.id for v in out)


@define("version-refs", "check", reads=("raw", "versions", "vids"))
def VERSION_REFS(ctx: Problems, st: State) -> None:
    """Each version names a header layout of the spec; no two versions match one major; the default
    and fallback versions are versions."""
    raw = st.raw
    for v in st.versions:
        node = next(x for x in raw["versions"] if str(x["id"]) == v.id)
        if v.header not in raw["headers"]:
            ctx.fail(node, f"version {v.id}: unknown header layout {v.header!r}", "header")
    for i, a in enumerate(st.versions):
        for b in st.versions[i + 1:]:
            if a.major == b.major and (a.minor is None or b.minor is None or a.minor == b.minor):
                ctx.at(b.line, f"versions {a.id} and {b.id} both match major {a.major}")
    for key in ("default_version", "fallback_version"):
        if raw[key] not in st.vids:
            ctx.fail(raw, f"{key} {raw[key]!r} is not a version", key)
