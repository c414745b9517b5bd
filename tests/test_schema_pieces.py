"""The loader's shape check by pieces (loader/schema.py `valid_by_pieces`) gives jsonschema's verdict on the
whole spec: checked here on the spec and on edits of it at every top-level key and in the first, middle and
last item of every array (a wrong type, a missing key, an unknown key, in turn), each edit seen twice (the second
time from the remembered pieces). A piece wrongly accepted would lose a shape problem; a piece wrongly
refused would only cost the full check, but is counted as a failure here too."""

from __future__ import annotations

import copy
from collections.abc import Iterator
from typing import Any

import jsonschema
import pytest
from conftest import SPEC

from cbfgen.loader import Loader, schema
from cbfgen.loader.schema import shape_problems, valid_by_pieces
from cbfgen.loader.yaml_reader import read

RAW = read(SPEC.read_text(encoding="utf-8"), str(SPEC), Loader)
WHOLE = jsonschema.Draft202012Validator(schema())
WRONG: tuple[Any, ...] = (None, "x", 7, 1.5, True, [], {})


def _edits() -> Iterator[tuple[str, Any]]:
    """(label, edited spec): a deterministic set reaching every piece of the check."""
    def at(path: tuple[Any, ...], change: Any) -> Any:
        doc = copy.deepcopy(RAW)
        node = doc
        for step in path[:-1]:
            node = node[step]
        change(node, path[-1])
        return doc

    def setter(value: Any) -> Any:
        def change(node: Any, key: Any) -> None:
            node[key] = value
        return change

    def drop(node: Any, key: Any) -> None:
        del node[key]

    yield "the spec", copy.deepcopy(RAW)
    yield "an unknown top-level key", {**copy.deepcopy(RAW), "extra": 1}
    for n, key in enumerate(RAW):  # one edit a key and three items an array, the kind of edit in turn
        wrong = WRONG[n % len(WRONG)]
        value = RAW[key]
        if n % 3 == 0:
            yield f"{key} dropped", at((key,), drop)
        elif not isinstance(value, (list, dict)) or n % 3 == 1:
            yield f"{key} = {wrong!r}", at((key,), setter(wrong))
        if isinstance(value, list) and value:
            for k, i in enumerate(sorted({0, len(value) // 2, len(value) - 1})):
                item, wrong = value[i], WRONG[(n + i) % len(WRONG)]
                first = next(iter(item)) if isinstance(item, dict) and item else None
                if first is None or (n + k) % 4 == 0:
                    yield f"{key}[{i}] = {wrong!r}", at((key, i), setter(wrong))
                elif (n + k) % 4 == 1:
                    yield f"{key}[{i}].{first} dropped", at((key, i, first), drop)
                elif (n + k) % 4 == 2:
                    yield f"{key}[{i}].{first} = {wrong!r}", at((key, i, first), setter(wrong))
                else:
                    yield f"{key}[{i}] unknown key", at((key, i, "extra_key"), setter(1))
        elif isinstance(value, dict) and value and n % 3 == 2:
            first = next(iter(value))
            yield f"{key}.{first} = {wrong!r}", at((key, first), setter(wrong))


EDITS = list(_edits())
VERDICTS = {label: WHOLE.is_valid(doc) for label, doc in EDITS}


@pytest.mark.parametrize(("label", "doc"), EDITS, ids=[label for label, _ in EDITS])
def test_the_check_by_pieces_is_jsonschemas_verdict_on_the_whole(label: str, doc: Any) -> None:
    whole = VERDICTS[label]
    assert valid_by_pieces(doc) == whole, label
    assert valid_by_pieces(doc) == whole, f"{label} (remembered)"
    assert (shape_problems(doc) == []) == whole, label


def test_the_edits_refuse_something() -> None:
    """The edits are not all harmless: most are shape errors (the check must be able to fail)."""
    assert VERDICTS["the spec"]
    assert sum(not ok for ok in VERDICTS.values()) > len(EDITS) // 2
