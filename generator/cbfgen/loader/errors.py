"""The error every loader refusal raises (``problems.SpecErrors``, every problem at once, is one)."""

from __future__ import annotations


class SpecError(Exception):
    """A spec that cannot be used. str() is `file:line: message`."""

    def __init__(self, path: str, line: int, message: str) -> None:
        super().__init__(f"{path}:{line}: {message}")
        self.path = path
        self.line = line
        self.message = message
