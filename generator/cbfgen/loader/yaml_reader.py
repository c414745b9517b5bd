"""The YAML reader of the loader: safe, bounded, and remembering the line of every node and key.

``read`` returns the spec as ``Map``/``Seq`` (dict and list that know their lines) or raises a
``SpecError`` naming the line: a YAML syntax error, a duplicate key, an alias bomb, a nesting too deep.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

import yaml

from .errors import SpecError


class Map(dict[Any, Any]):
    """A YAML mapping with the line of its start and of each key."""

    line = 0
    key_lines: dict[Any, int]


class Seq(list[Any]):
    """A YAML sequence with the line of its start."""

    line = 0


# libyaml's parser (PyYAML's C binding, in its wheels) when present: it reads the spec about ten
# times faster than the pure-Python one, with the same marks (line, column) and the same safe types.
# PyYAML's composer (Python) goes in front of libyaml's, so that Loader can bound composition.
if TYPE_CHECKING:  # the stubs type both alike
    SafeLoader = yaml.SafeLoader
elif hasattr(yaml, "CSafeLoader"):
    class SafeLoader(yaml.composer.Composer, yaml.CSafeLoader):
        def __init__(self, stream):
            yaml.CSafeLoader.__init__(self, stream)
            yaml.composer.Composer.__init__(self)
else:
    SafeLoader = yaml.SafeLoader


# Bounds of the spec reader, far above any real spec (spec/cbf.yaml: 3,379 nodes, nesting 7) and far
# below what a hostile file needs: a YAML alias bomb (a few lines whose aliases expand to billions
# of nodes) or a 1,000-deep nesting. Counted while composing, before anything walks the tree.
MAX_NODES = 100_000  # nodes once every alias is expanded
MAX_DEPTH = 50  # nested mappings and sequences

if TYPE_CHECKING:
    _Composer = yaml.SafeLoader
else:
    _Composer = yaml.composer.Composer


class BoundedComposer(_Composer):
    """PyYAML's composer (over libyaml's events, or PyYAML's own parser) that counts every node,
    each alias at the expanded size of its anchor, and the depth, and stops at the first node past
    a bound with a SpecError naming the line. Composition stays linear in the file's size."""

    def compose_document(self) -> Any:
        self._nodes = 0  # nodes so far, aliases counted at their expanded size
        self._depth = 0
        self._sizes: dict[int, int] = {}  # id(anchored node) -> its expanded size
        return super().compose_document()

    def _count(self, n: int, mark: Any) -> None:
        self._nodes += n
        if self._nodes > MAX_NODES:
            raise SpecError(self.name, mark.line + 1, f"YAML: more than {MAX_NODES:,} nodes once aliases "
                         "are expanded (an alias bomb?); the spec reader stops there")

    def compose_node(self, parent: Any, index: Any) -> Any:
        if self.check_event(yaml.AliasEvent):  # type: ignore[no-untyped-call]
            event = self.peek_event()  # type: ignore[no-untyped-call]
            node = super().compose_node(parent, index)  # the anchored node, or the undefined-alias error
            self._count(self._sizes.get(id(node), 1), event.start_mark)
            return node
        event = self.peek_event()  # type: ignore[no-untyped-call]
        start = self._nodes
        self._count(1, event.start_mark)
        nested = isinstance(event, (yaml.MappingStartEvent, yaml.SequenceStartEvent))
        if nested:
            self._depth += 1
            if self._depth > MAX_DEPTH:
                raise SpecError(self.name, event.start_mark.line + 1,
                             f"YAML: nested more than {MAX_DEPTH} deep; the spec reader stops there")
        node = super().compose_node(parent, index)
        if nested:
            self._depth -= 1
        if getattr(event, "anchor", None) is not None:
            self._sizes[id(node)] = self._nodes - start
        return node


class Loader(BoundedComposer, SafeLoader):
    """A SafeLoader that remembers lines, refuses duplicate keys, and bounds size and depth."""


def _construct_map(loader: Loader, node: yaml.MappingNode) -> Map:
    loader.flatten_mapping(node)
    m = Map()
    m.line = node.start_mark.line + 1
    m.key_lines = {}
    for k_node, v_node in node.value:
        key = loader.construct_object(k_node, deep=True)  # type: ignore[no-untyped-call]
        if key in m:
            raise SpecError(loader.name, k_node.start_mark.line + 1, f"duplicate key {key!r}")
        m[key] = loader.construct_object(v_node, deep=True)  # type: ignore[no-untyped-call]
        m.key_lines[key] = k_node.start_mark.line + 1
    return m


def _construct_seq(loader: Loader, node: yaml.SequenceNode) -> Seq:
    s = Seq(loader.construct_object(n, deep=True) for n in node.value)  # type: ignore[no-untyped-call]
    s.line = node.start_mark.line + 1
    return s


Loader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _construct_map)
Loader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_SEQUENCE_TAG, _construct_seq)


def read(text: str, path: str, loader: type[Loader] = Loader) -> Any:
    """The YAML document of ``text`` (``path`` names it in errors), as Map/Seq with lines."""
    try:
        ld = loader(text)
        ld.name = path
        try:
            return ld.get_single_data()
        finally:
            ld.dispose()  # type: ignore[no-untyped-call]
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark
        raise SpecError(path, (mark.line + 1) if mark else 0, f"YAML: {exc.problem}") from None


def node_line(node: Any, key: Any = None) -> int:
    """The line of ``node`` (of its ``key``, when given and the node is a mapping holding it)."""
    if isinstance(node, Map) and key is not None and key in node.key_lines:
        return node.key_lines[key]
    return int(getattr(node, "line", 0))


def line_of_path(root: Any, path: Iterable[Any]) -> int:
    """The line of the deepest node of ``path`` (keys and indexes from ``root``) that exists."""
    node, line = root, 1
    for step in path:
        try:
            line = node_line(node, step) if isinstance(node, Map) else node_line(node[step]) or line
            node = node[step]
        except (KeyError, IndexError, TypeError):
            break
        line = node_line(node) or line
    return line


def plain(x: Any) -> Any:
    """Map/Seq as plain dict/list, all the way down."""
    if isinstance(x, dict):
        return {k: plain(v) for k, v in x.items()}
    if isinstance(x, list):
        return [plain(v) for v in x]
    return x
