"""The profiles: which coverages (and which file algorithm) a file may use."""

from __future__ import annotations

from ...model import Profile
from ..pipeline import State, define
from ..problems import Problems
from .checksums import fits


@define("profiles", "resolve", reads=("raw",), produces=("profiles",))
def PROFILES(ctx: Problems, st: State) -> None:
    """The profiles, in the spec's order; a duplicate id is refused (and left out): the C binding
    names each profile once (a profile repeated broke generation: spec-fuzz seed 2026120607 #214)."""
    out: list[Profile] = []
    for p in st.raw["profiles"]:
        if any(o.id == p["id"] for o in out):
            ctx.fail(p, f"duplicate profile id {p['id']!r}", "id")
            continue
        out.append(Profile(p["id"], str(p["doc"]).strip(), tuple(p["file_coverages"]), tuple(p["hint_coverages"]),
                           p.get("file_algorithm")))
    st.profiles = tuple(out)


@define("profile-refs", "check",
        reads=("raw", "headers", "record", "bare_commands", "bare_checksums", "profiles"))
def PROFILE_REFS(ctx: Problems, st: State) -> None:
    """A profile names known coverages and a known file algorithm that fits the file checksum
    field; the first profile is 'default'."""
    cs = st.bare_checksums
    for p in st.raw["profiles"]:
        for cov_name in list(p["file_coverages"]) + list(p["hint_coverages"]):
            if cov_name not in cs.coverages:
                ctx.fail(p, f"profile {p['id']}: unknown coverage {cov_name!r}")
        if "file_algorithm" not in p:
            continue
        if p["file_algorithm"] not in cs.algorithms:
            ctx.fail(p, f"profile {p['id']}: unknown algorithm {p['file_algorithm']!r}", "file_algorithm")
        else:
            fits(ctx, st, p, "file_algorithm", "file", p["file_algorithm"], f"profile {p['id']}")
    if st.profiles[0].id != "default":
        ctx.fail(st.raw["profiles"], "the first profile must be 'default'")
