"""Load spec/cbf.yaml into the typed model, refusing a spec that contradicts itself.

Two gates: the JSON Schema (spec.schema.json, ``schema``) for shape, then the passes
(``passes/``: tiling, uniqueness, references, what every binding and the document can carry).
Every refusal names the file, the YAML line and the rule:
``spec/cbf.yaml:212: LINE v3.0 arguments sum to 20 bytes, declared 24``; every problem of a run is
collected (``SpecErrors``, each a ``Problem``: rule id, severity, line, text) before one error is raised.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

from ..model import Note, Spec
from ..prose import Facts, render
from .errors import SpecError
from .passes import PASSES
from .pipeline import Pass, State, check_order, run
from .problems import Problem, Problems, SpecErrors
from .schema import SCHEMA_PATH, schema, shape_problems
from .yaml_reader import MAX_DEPTH, MAX_NODES, Loader, Map, plain, read

__all__ = ["MAX_DEPTH", "MAX_NODES", "PASSES", "SCHEMA_PATH", "Loader", "Pass", "Problem", "SpecError", "SpecErrors",
           "load", "passes_markdown", "schema"]

check_order(PASSES)


def load(path: str | Path) -> Spec:
    """Load, check and return the spec model. Raises SpecError (SpecErrors: every problem found)."""
    spath = str(path)
    try:
        text = Path(path).read_text(encoding="utf-8")
    except OSError as exc:
        raise SpecError(spath, 0, f"cannot read: {exc.strerror}") from None
    raw = read(text, spath, Loader)
    if not isinstance(raw, Map):
        raise SpecError(spath, 1, "the spec must be a mapping")
    shape = shape_problems(raw)
    if shape:  # the semantic passes need the shape, so they wait for it
        raise SpecErrors(spath, shape)
    problems = Problems(spath)
    state = run(PASSES, problems, raw)
    if problems.found:
        raise SpecErrors(spath, problems.found)
    return _spec(spath, state)


def _spec(path: str, st: State) -> Spec:
    raw = st.raw
    errata = tuple(Note(e["id"], e["clause"], str(e["text"]), clause=e["clause"]) for e in raw["errata"])
    history = tuple(Note(h["version"], h["version"], str(h["text"]), clause=h["clause"], date=str(h["date"]))
                    for h in raw["history"])
    facts = Facts(st.versions, st.checksums, str(raw["default_version"]), str(raw["fallback_version"]))
    decisions = tuple(replace(d, text=render(d.text, facts), evidence=render(d.evidence, facts)) for d in st.decisions)
    return Spec(
        path=path, meta=plain(raw["meta"]), types=st.types,
        units={k: str(v["doc"]) for k, v in raw["units"].items()},
        versions=st.versions, default_version=raw["default_version"],
        fallback_version=raw["fallback_version"], headers=st.headers, record=st.record,
        commands=st.commands, checksums=st.checksums, profiles=st.profiles,
        tolerances={k: float(v) for k, v in raw["tolerances"].items()},
        limits={k: int(v) for k, v in raw["limits"].items()}, machine=st.machine, checks=st.checks,
        cut=plain(raw["cut"]), decisions=decisions, errata=errata, history=history, raw=plain(raw),
    )


def passes_markdown() -> str:
    """The pass list of generator/README.md: each pass, what it reads and produces, what it does."""
    rows = ["| # | pass (rule id) | role | reads | produces | what it does |", "|---|---|---|---|---|---|"]
    for i, p in enumerate(PASSES, 1):
        reads = ", ".join(f"`{r}`" for r in p.reads)
        made = ", ".join(f"`{r}`" for r in p.produces) or "-"
        rows.append(f"| {i} | `{p.name}` | {p.role} | {reads} | {made} | {p.doc} |")
    return "\n".join(rows) + "\n"
