"""Reading the option files (cutter tables, machine files) by the rules both tools share (issue 28).

The rules (sizes, rows, name length, nesting, the number grammar, the YAML both tools read) are
cbf/option_files.json, generated from generator/cbfgen/option_files.yaml and the spec; cbf-c's
reader (emit/c/tools/optfiles.c, in cbf_tools.h) takes its limits from the same file and says the same
line for every case of tests/option_files/cases.yaml. Every refusal is one line naming the file, the line (or
the JSON path) and the limit.

YAML is read event by event (PyYAML's parser, never its constructor): an anchor, an alias, a tag,
a complex key, a value over several lines or a second document is refused where it starts, and
nesting is bounded before a collection is built, so no YAML bomb, deep nesting or odd key costs
more than reading the text. A JSON file's nesting is measured before the JSON reader sees it.
"""

from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .errors import CbfError
from .quoting import quote

RULES: dict[str, Any] = json.loads(Path(__file__).with_name("option_files.json").read_text(encoding="utf-8"))
# A cutter table's columns (options.cutter_columns): the cutter role's key of the name, and the
# numbers of a row in the order a table's values hold them (today length and radius).
CUTTER_NAME: str = RULES["cutter_table"]["name"]
CUTTER_VALUES: tuple[str, ...] = tuple(v["column"] for v in RULES["cutter_table"]["values"])

# RFC 8259's number grammar (RULES["number"] == "rfc8259"); words for the non-finite values
NUMBER = re.compile(r"-?(?:0|[1-9][0-9]*)(?:\.[0-9]+)?(?:[eE][+-]?[0-9]+)?")
NON_FINITE = re.compile(r"[+-]?\.?(?:nan|inf|infinity)", re.IGNORECASE)


class OptionFileError(CbfError):
    """An option file that cannot be used: one line naming the file, the place and the limit."""

    kind = "option_file"


def number(text: str) -> float | str:
    """The value of a number as an option file writes it, or why it is not one."""
    if NUMBER.fullmatch(text):
        value = float(text)
        return value if math.isfinite(value) else "not a finite number"
    return "not a finite number" if NON_FINITE.fullmatch(text) else "not a number"


def read_text(path: Path, what: str, max_bytes: int) -> str:
    """The file's text: at most ``max_bytes`` bytes (never more read), UTF-8."""
    from .files import NotRegular, open_regular

    try:
        with open_regular(path) as fh:
            data = fh.read(max_bytes + 1)
    except NotRegular as exc:
        raise OptionFileError(f"{quote(str(path))}: cannot read {what} ({exc.message})") from None
    except FileNotFoundError:
        raise OptionFileError(f"{quote(str(path))}: cannot read {what} (no such file)") from None
    except PermissionError:
        raise OptionFileError(f"{quote(str(path))}: cannot read {what} (permission denied)") from None
    except IsADirectoryError:
        raise OptionFileError(f"{quote(str(path))}: cannot read {what} (is a directory)") from None
    except OSError:
        raise OptionFileError(f"{quote(str(path))}: cannot read {what} (read error)") from None
    if len(data) > max_bytes:
        raise OptionFileError(f"{quote(str(path))}: larger than the {max_bytes} bytes a {what} may have "
                              f"(limit max_bytes)")
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise OptionFileError(f"{quote(str(path))}: offset {exc.start}: not UTF-8 text") from None
    if "\x00" in text:
        raise OptionFileError(f"{quote(str(path))}: offset {data.index(0)}: not text (a NUL byte)")
    return text


def is_yaml(path: Path) -> bool:
    return path.suffix.lower() in (".yaml", ".yml")


# -- YAML, event by event ----------------------------------------------------------------------
@dataclass(frozen=True, slots=True)
class Scalar:
    text: str
    plain: bool
    line: int

    @property
    def value(self) -> Any:
        """A plain scalar: a number, true, false, null ('~' and nothing too), else the text."""
        if not self.plain:
            return self.text
        if NUMBER.fullmatch(self.text):
            return float(self.text)
        return {"true": True, "false": False, "null": None, "~": None, "": None}.get(self.text, self.text)


@dataclass(slots=True)
class Mapping:
    line: int
    pairs: list[tuple[Scalar, Node]] = field(default_factory=list)


@dataclass(slots=True)
class Sequence:
    line: int
    items: list[Node] = field(default_factory=list)


Node = Scalar | Mapping | Sequence


class _Tree:
    """The tree of one YAML document, built event by event under the shared rules (the limits and
    refusals of yaml_tree, in the order the events come)."""

    def __init__(self, text: str, where: str, max_depth: int) -> None:
        self.text, self.where, self.max_depth = text, where, max_depth
        self.max_keys = RULES["yaml"]["max_keys"]
        self.stack: list[Mapping | Sequence] = []
        self.pending_key: list[Scalar | None] = []  # per open mapping: the key awaiting its value
        self.flows: list[bool] = []  # per open collection: whether it is a flow one
        self.flow_line: int | None = None  # the line of the outermost open flow collection
        self.root: Node | None = None
        self.documents = 0

    def fail(self, line: int, what: str) -> OptionFileError:
        return OptionFileError(f"{self.where}: line {line}: {what}")

    def put(self, node: Node) -> None:
        if not self.stack:
            self.root = node
            return
        top = self.stack[-1]
        if isinstance(top, Sequence):
            top.items.append(node)
            return
        key = self.pending_key[-1]
        if key is None:
            if not isinstance(node, Scalar):
                raise self.fail(node.line, "a key must be a plain value (complex key)")
            if len(top.pairs) >= self.max_keys:
                raise self.fail(node.line, f"more than {self.max_keys} keys in one mapping (limit max_keys)")
            self.pending_key[-1] = node
            return
        top.pairs.append((key, node))
        self.pending_key[-1] = None

    def event(self, ev: Any, yaml: Any) -> None:
        line = ev.start_mark.line + 1
        if isinstance(ev, (yaml.StreamStartEvent, yaml.StreamEndEvent, yaml.DocumentEndEvent)):
            return
        if isinstance(ev, yaml.DocumentStartEvent):
            self.documents += 1
            if self.documents > 1:
                raise self.fail(line, "more than one document")
            return
        self._allowed(ev, line, yaml)
        if isinstance(ev, yaml.ScalarEvent):
            if ev.end_mark.line != ev.start_mark.line or ev.style in ("|", ">"):
                raise self.fail(line, "a value over more than one line (one-line values only)")
            self.put(Scalar(ev.value, not ev.style, line))
        elif isinstance(ev, yaml.CollectionStartEvent):
            self._open(ev, line, yaml)
        elif isinstance(ev, yaml.CollectionEndEvent):
            self.stack.pop()
            self.pending_key.pop()
            self.flows.pop()
            if not any(self.flows):
                self.flow_line = None

    def _allowed(self, ev: Any, line: int, yaml: Any) -> None:
        """What no event may be: past its flow collection's line, an anchor or alias, tagged, an explicit key."""
        if self.flow_line is not None and line != self.flow_line:
            raise self.fail(self.flow_line, "a value over more than one line (one-line values only)")
        if isinstance(ev, yaml.AliasEvent) or getattr(ev, "anchor", None) is not None:
            raise self.fail(line, "anchors and aliases are not allowed (limit: none)")
        if getattr(ev, "tag", None) is not None and not isinstance(ev, yaml.CollectionEndEvent):
            raise self.fail(line, "tags are not allowed")
        if isinstance(ev, (yaml.ScalarEvent, yaml.CollectionStartEvent)) and \
                _explicit_key(self.text, ev.start_mark.index):
            raise self.fail(line, "a key must be a plain value (complex key)")

    def _open(self, ev: Any, line: int, yaml: Any) -> None:
        if self.stack and isinstance(self.stack[-1], Mapping) and self.pending_key[-1] is None:
            raise self.fail(line, "a key must be a plain value (complex key)")
        if len(self.stack) >= self.max_depth:
            raise self.fail(line, f"nested deeper than {self.max_depth} levels (limit max_depth)")
        node: Mapping | Sequence = Mapping(line) if isinstance(ev, yaml.MappingStartEvent) else Sequence(line)
        self.put(node)
        self.stack.append(node)
        self.pending_key.append(None)
        self.flows.append(bool(ev.flow_style))
        if ev.flow_style and self.flow_line is None:
            self.flow_line = line


def yaml_tree(text: str, where: str, max_depth: int) -> Node | None:
    """The one document of ``text`` as a tree (None when it is empty), by the shared rules."""
    import yaml

    loader: Any = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
    tree = _Tree(text, where, max_depth)
    try:
        for ev in yaml.parse(text, Loader=loader):
            tree.event(ev, yaml)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        at = f"line {mark.line + 1}, column {mark.column + 1}: " if mark is not None else ""
        raise OptionFileError(f"{where}: {at}not YAML ({getattr(exc, 'problem', None) or exc})") from None
    return tree.root


def _explicit_key(text: str, at: int) -> bool:
    """Whether the node at ``at`` follows a '?' indicator: an explicit key, refused as a complex key
    is (cbf-c's reader refuses every '?' key; a plain key needs none)."""
    k = at - 1
    while k >= 0 and text[k] in " \t":
        k -= 1
    return k >= 0 and text[k] == "?" and k + 1 < at


def plain_data(node: Node | None) -> Any:
    """The tree as JSON-like data: mappings keep every pair (a duplicate is the schema's to refuse)."""
    if node is None or isinstance(node, Scalar):
        return None if node is None else node.value
    if isinstance(node, Sequence):
        return [plain_data(x) for x in node.items]
    return Pairs([(k.text, plain_data(v)) for k, v in node.pairs])


class Pairs(dict[Any, Any]):
    """An object that keeps its pairs in order, a key given twice included: the duplicate is
    refused where a reader meets it, never "the last one wins"."""

    pairs: list[tuple[Any, Any]]

    def __init__(self, pairs: list[tuple[Any, Any]]) -> None:
        super().__init__(pairs)
        self.pairs = pairs


# -- JSON nesting, before the JSON reader ---------------------------------------------------------
def json_depth_error(text: str, max_depth: int) -> str | None:
    """"line L, column C: nested deeper than N levels" for the first bracket beyond ``max_depth``
    outside strings, else None (the JSON reader then reads a file of bounded nesting)."""
    depth = 0
    line, col0 = 1, 0
    in_string = escaped = False
    for i, ch in enumerate(text):
        if in_string:
            if escaped:
                escaped = False
            elif ch == "\\":
                escaped = True
            elif ch == '"':
                in_string = False
            elif ch == "\n":
                line, col0 = line + 1, i + 1
            continue
        if ch == '"':
            in_string = True
        elif ch in "[{":
            depth += 1
            if depth > max_depth:
                return f"line {line}, column {i - col0 + 1}: nested deeper than {max_depth} levels (limit max_depth)"
        elif ch in "]}":
            depth -= 1
        elif ch == "\n":
            line, col0 = line + 1, i + 1
    return None
