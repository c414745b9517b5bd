"""The passes of the loader and how they run.

A pass is a small module (``passes/*.py``) that declares what it reads and what it produces, by the
names of ``State``'s slots, and whether it resolves (builds a part of the model) or checks (reports
problems, builds nothing). ``run`` runs them in order; each sees only the slots it declared (a pass
that reads an undeclared slot, or writes one it does not produce, fails at once: ``View``), and a
slot is written once, by its one producer. ``check_order`` proves, before anything runs, that every
slot a pass reads is produced by a pass before it (tests/test_loader_passes.py runs it too).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import Any, Literal, cast

from ..model import Check, Checksums, Command, HeaderLayout, Machine, Note, Profile, RecordLayout, Version
from ..registry import FieldType
from .problems import Problems
from .yaml_reader import Map

Role = Literal["resolve", "check"]


class State:
    """Every slot a pass may read or produce, with its type. ``raw`` (the YAML, as the schema let
    it through) is there from the start; every other slot appears when its producer has run."""

    raw: Map
    types: dict[str, FieldType]  # the spec's types, as the registry has them
    versions: tuple[Version, ...]
    vids: tuple[str, ...]  # the versions' ids, in the spec's order
    headers: dict[str, HeaderLayout]
    record: RecordLayout
    bare_commands: tuple[Command, ...]  # the commands, their layouts' argument checksums not yet resolved
    bare_checksums: Checksums  # algorithms, coverages (named fields not yet resolved), fields, fill order
    profiles: tuple[Profile, ...]
    decisions: tuple[Note, ...]
    machine: Machine
    raw_checks: dict[str, Map]  # the YAML of each check, by id (the first of an id)
    checks: tuple[Check, ...]
    commands: tuple[Command, ...]  # with each layout's argument checksums (model.ArgChecksum)
    checksums: Checksums  # with header coverages by named fields resolved to header segments

    def __init__(self, raw: Map) -> None:
        self.raw = raw


SLOTS: tuple[str, ...] = tuple(State.__annotations__)


@dataclass(frozen=True)
class Pass:
    """One pass: ``run(problems, state)`` reads ``reads`` and sets ``produces`` on the state."""

    name: str  # its rule id: the problems it finds carry it
    role: Role
    reads: tuple[str, ...]
    produces: tuple[str, ...]
    run: Callable[[Problems, State], None]
    doc: str  # one line: what it resolves or checks (the README's pass list)


def define(name: str, role: Role, reads: Iterable[str], produces: Iterable[str] = ()) -> Callable[
        [Callable[[Problems, State], None]], Pass]:
    """Decorator: the function as a Pass; its docstring's first sentence is the pass's doc."""
    def wrap(fn: Callable[[Problems, State], None]) -> Pass:
        doc = " ".join((fn.__doc__ or "").split())
        first = doc.split(". ")[0].rstrip(".") + "." if doc else ""
        return Pass(name, role, tuple(reads), tuple(produces), fn, first)
    return wrap


class View:
    """What one pass sees of the state: the slots it reads; the slots it produces, once each."""

    def __init__(self, state: State, p: Pass) -> None:
        object.__setattr__(self, "_state", state)
        object.__setattr__(self, "_pass", p)

    def __getattr__(self, name: str) -> Any:
        p: Pass = object.__getattribute__(self, "_pass")
        if name not in p.reads and name not in p.produces:
            raise AttributeError(f"loader pass {p.name} reads {name}, which it does not declare")
        return getattr(object.__getattribute__(self, "_state"), name)

    def __setattr__(self, name: str, value: Any) -> None:
        p: Pass = object.__getattribute__(self, "_pass")
        state: State = object.__getattribute__(self, "_state")
        if name not in p.produces:
            raise AttributeError(f"loader pass {p.name} writes {name}, which it does not produce")
        if hasattr(state, name):
            raise AttributeError(f"loader pass {p.name} writes {name} a second time")
        setattr(state, name, value)


def check_order(passes: Iterable[Pass]) -> None:
    """Every slot read is produced before, by exactly one pass; check passes produce nothing."""
    have = {"raw"}
    for p in passes:
        unknown = [s for s in (*p.reads, *p.produces) if s not in SLOTS]
        missing = [s for s in p.reads if s not in have]
        twice = [s for s in p.produces if s in have]
        if unknown or missing or twice or (p.role == "check" and p.produces):
            raise AssertionError(f"loader pass {p.name}: unknown slots {unknown}, read before produced {missing}, "
                                 f"produced twice {twice}, role {p.role} producing {list(p.produces)}")
        have.update(p.produces)


def run(passes: Iterable[Pass], problems: Problems, raw: Map) -> State:
    """Run the passes in order over ``raw``; every problem lands in ``problems``."""
    state = State(raw)
    for p in passes:
        problems.rule = p.name
        p.run(problems, cast(State, View(state, p)))
        unset = [s for s in p.produces if not hasattr(state, s)]
        if unset:
            raise AssertionError(f"loader pass {p.name} did not produce {unset}")
    problems.rule = "loader"
    return state
