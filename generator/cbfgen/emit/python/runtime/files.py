"""Reading input files safely (issue #35, point 4): regular files only, and folders walked without recursion.

``open_regular`` looks at a path before it opens it and opens it without blocking: a FIFO, a
device or a socket is refused (``NotRegular``, one line naming what it is) and never read, so a
FIFO named ``*.cbf`` cannot hang a run and ``/dev/zero`` cannot fill memory. ``walk`` lists a
folder's files by a suffix, depth first with a stack (a tree of any depth, no RecursionError),
not following symbolic links to folders; a folder it cannot read is reported, never skipped.
"""

from __future__ import annotations

import os
import stat
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import BinaryIO


class NotRegular(OSError):
    """The path names something other than a regular file (a FIFO, a device, a socket)."""

    def __init__(self, kind: str) -> None:
        self.kind = kind
        self.message = f"is {kind}; only regular files are read"
        super().__init__(self.message)


def kind_of(mode: int) -> str:
    """What a file of this mode is, as a message says it."""
    for test, name in ((stat.S_ISFIFO, "a FIFO"), (stat.S_ISCHR, "a character device"),
                       (stat.S_ISBLK, "a block device"), (stat.S_ISSOCK, "a socket"), (stat.S_ISDIR, "a directory")):
        if test(mode):
            return name
    return "not a regular file"


def _check(mode: int) -> None:
    if stat.S_ISDIR(mode):
        raise IsADirectoryError("is a directory")
    if not stat.S_ISREG(mode):
        raise NotRegular(kind_of(mode))


def open_regular(path: str | Path) -> BinaryIO:
    """Open a regular file for reading; anything else raises NotRegular (or IsADirectoryError)
    unopened, or opened without blocking and closed again when it changed in between."""
    _check(os.stat(path).st_mode)
    fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOCTTY", 0)
                 | getattr(os, "O_CLOEXEC", 0))
    try:
        _check(os.fstat(fd).st_mode)  # the file opened is the file looked at
        os.set_blocking(fd, True)
        return os.fdopen(fd, "rb")
    except BaseException:
        os.close(fd)
        raise


@dataclass(frozen=True, slots=True)
class Unreadable:
    """A folder of the walk that could not be listed, and why."""

    path: str
    error: OSError


def walk(root: str, suffix: str) -> Iterator[str | Unreadable]:
    """Each file under ``root`` whose name ends in ``suffix`` (any type but a folder: the reader
    refuses what is not a regular file), and each folder that could not be read, depth first."""
    stack = [root]
    while stack:
        folder = stack.pop()
        try:
            with os.scandir(folder) as it:
                entries = list(it)
        except OSError as exc:
            yield Unreadable(folder, exc)
            continue
        below: list[str] = []
        for e in entries:
            try:
                is_dir = e.is_dir(follow_symlinks=False)
            except OSError:
                is_dir = False
            if is_dir:
                below.append(e.path)
            elif e.name.endswith(suffix):
                yield e.path
        stack.extend(sorted(below, reverse=True))
