"""What the loader reports: a problem (rule, severity, YAML line, text) and the errors that carry them.

A pass never stops the run: it adds every problem it finds (``Problems``), and ``load`` raises one
``SpecErrors`` holding them all once every pass has run (the kaitai_struct_compiler shape: each
precompile step returns its problems, and only a step that makes the rest meaningless stops).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any, Literal

from .errors import SpecError
from .yaml_reader import node_line

Severity = Literal["error", "warning"]


@dataclass(frozen=True)
class Problem:
    """One problem of a spec. ``rule``: the id of the loader rule that found it (``yaml``,
    ``schema``, or the name of the pass: ``commands``, ``checksum-fields`` ...); ``line``: the
    YAML line (1-based; 0: no line, as for a file that cannot be read)."""

    rule: str
    severity: Severity
    line: int
    text: str

    def format(self, path: str) -> str:
        """The one-line form every tool prints: ``file:line: text``."""
        return f"{path}:{self.line}: {self.text}"


class SpecErrors(SpecError):
    """Every problem of a spec, found in one run. str() is one `file:line: message` a line;
    ``line`` and ``message`` are the first problem's (in pass order). ``problems`` holds
    ``(line, text)`` pairs (as before the problems were typed); ``typed`` the ``Problem``s."""

    def __init__(self, path: str, problems: Iterable[Problem]) -> None:
        typed = tuple(problems)
        first = typed[0]
        super().__init__(path, first.line, first.text)
        self.typed = typed
        self.problems = tuple((p.line, p.text) for p in typed)
        self.args = ("\n".join(p.format(path) for p in typed),)

    def __str__(self) -> str:
        return str(self.args[0])


class Problems:
    """The problems found so far; every pass adds to them under its own rule id (``rule``)."""

    def __init__(self, path: str) -> None:
        self.path = path
        self.rule = "loader"
        self.found: list[Problem] = []

    def fail(self, node: Any, message: str, key: Any = None) -> None:
        """A problem at the line of ``node`` (of its ``key`` when given)."""
        self.found.append(Problem(self.rule, "error", node_line(node, key), message))

    def at(self, line: int, message: str) -> None:
        """A problem at a line the model kept (a field's, a layout's, a check's)."""
        self.found.append(Problem(self.rule, "error", line, message))
