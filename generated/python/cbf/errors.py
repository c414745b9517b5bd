"""Errors of the CBF codec. Every one names what failed and where."""

from __future__ import annotations


class CbfError(Exception):
    """Base of every error the codec raises on bad input.

    ``kind`` is a stable machine name (see conformance/PROTOCOL.md),
    ``offset`` the byte offset (or None), ``line`` the text line (or None),
    ``column`` the character in that line, from 1 (or None).
    """

    kind = "error"

    def __init__(self, message: str, *, offset: int | None = None, line: int | None = None,
                 kind: str | None = None, column: int | None = None) -> None:
        super().__init__(message)
        self.message = message
        self.offset = offset
        self.line = line
        self.column = column
        if kind is not None:
            self.kind = kind

    def __str__(self) -> str:
        where = f"offset {self.offset}: " if self.offset is not None else ""
        where = f"line {self.line}: " if self.line is not None else where
        where = f"line {self.line}, column {self.column}: " if self.line is not None and self.column else where
        return where + self.message


class TruncatedError(CbfError):
    """The framing broke: the file ends inside the header or a record."""


class EncodeError(CbfError):
    """The encoder cannot represent the model (names the command and field)."""

    kind = "encode"


class JsonShapeError(CbfError):
    """Canonical JSON of the wrong shape (names the JSON path)."""

    kind = "json"


class CutSyntaxError(CbfError):
    """CUT text that does not parse (names the line)."""

    kind = "cut"
