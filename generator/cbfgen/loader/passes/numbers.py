"""Numbers every binding reads alike (issue 36, point 1): finite, and no signed zero.

The schema takes an integer only as an int (loader/schema.py); a number may still be a float the
bindings would implement differently: NaN or an infinity compares false with everything (a bound
of NaN judges nothing in one binding and everything in another), and -0.0 prints as ``-0`` in one
tool and ``0`` in another and reads back as another value. A spec writes 0 for a zero.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from typing import Any

from ..pipeline import State, define
from ..problems import Problems
from ..yaml_reader import Map, Seq


def _floats(node: Any, path: str) -> Iterator[tuple[Any, Any, str, float]]:
    """(parent, key or None, path, value) of every float below ``node`` (a list item: its list's line)."""
    items = node.items() if isinstance(node, Map) else enumerate(node) if isinstance(node, Seq) else ()
    for k, v in items:
        where = f"{path}.{k}" if isinstance(node, Map) else f"{path}[{_label(v, k)}]"
        if isinstance(v, float):
            yield node, (k if isinstance(node, Map) else None), where.lstrip("."), v
        else:
            yield from _floats(v, where)


def _label(item: Any, index: int) -> str:
    """A list item as a message names it: by its id or name when it has one, else by its index."""
    for key in ("id", "name"):
        if isinstance(item, Map) and isinstance(item.get(key), str):
            return f"{key}={item[key]}"
    return str(index)


@define("numbers", "check", reads=("raw",))
def NUMBERS(ctx: Problems, st: State) -> None:
    """Every number is finite and no zero is signed: NaN, an infinity and -0.0 are read, compared
    and printed differently by the bindings."""
    for parent, key, where, value in _floats(st.raw, ""):
        if not math.isfinite(value):
            ctx.fail(parent, f"{where}: {value} is not a finite number (the bindings compare and print it "
                             f"differently)", key)
        elif value == 0 and math.copysign(1.0, value) < 0:
            ctx.fail(parent, f"{where}: -0.0 is a signed zero (cbf and cbf-c print and read it differently); "
                             f"write 0", key)
