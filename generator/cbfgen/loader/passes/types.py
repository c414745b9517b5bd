"""The spec's types, each a type of the registry with the registry's kind and size."""

from __future__ import annotations

from ...registry import TYPES, FieldType
from ..pipeline import State, define
from ..problems import Problems


@define("types", "resolve", reads=("raw",), produces=("types",))
def TYPES_PASS(ctx: Problems, st: State) -> None:
    """Each type of `types:` is a type of the registry, with its kind and size."""
    out: dict[str, FieldType] = {}
    for name, t in st.raw["types"].items():
        known = TYPES.get(name)
        if known is None:
            ctx.fail(st.raw["types"], f"type {name} is not in the registry (generator/cbfgen/registry.py); "
                                      f"known: {', '.join(TYPES)}", name)
            continue
        if (t["kind"], t.get("size")) != (known.kind, known.size):
            ctx.fail(t, f"type {name}: kind {t['kind']} size {t.get('size')} contradicts the registry's "
                        f"{known.kind} size {known.size}", "kind")
            continue
        out[name] = FieldType(name, known.kind, known.size, str(t["doc"]))
    st.types = out
