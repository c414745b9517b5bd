"""Cutter tables for check 6.1.2: CSV or YAML rows of a cutter's name and its numbers (mm).

The columns are the keys of the spec's cutter role (cbf/option_files.json's cutter_table.columns:
today name, length, radius): ``NAME`` the cutter's name, ``VALUES`` the numbers check 6.1.2
compares. The rules are the option-file rules both tools share (optfiles.py): at most max_bytes
and max_rows; a name the spec's cutter record can hold, given once; values that are finite
numbers (RFC 8259 syntax) and, where the spec's positive check targets them, greater than 0: a
NaN would switch check 6.1.2 off (it compares finite values only), so it is refused with its
line, never read. CSV: the first non-blank line names the columns (in any order), cells are
split at commas and trimmed of blanks and one pair of quotes. YAML: a list of mappings of the
columns, or a mapping whose one key `cutters` holds that list.
"""

from __future__ import annotations

from pathlib import Path

from .optfiles import (
    CUTTER_NAME,
    CUTTER_VALUES,
    RULES,
    Mapping,
    OptionFileError,
    Scalar,
    Sequence,
    is_yaml,
    number,
    read_text,
    yaml_tree,
)
from .quoting import quote

TABLE = RULES["cutter_table"]
COLUMNS: tuple[str, ...] = tuple(TABLE["columns"])
NAME = CUTTER_NAME
VALUES = CUTTER_VALUES
BLANKS = " \t\r\n\f\v"


class _Rows:
    """The rows read so far: each checked as it comes, by the shared rules."""

    def __init__(self, where: str) -> None:
        self.where = where
        self.table: dict[str, tuple[float, ...]] = {}
        self.lines: dict[str, int] = {}

    def fail(self, line: int, what: str) -> OptionFileError:
        return OptionFileError(f"{self.where}: line {line}: {what}", line=line, kind="cutters")

    def add(self, line: int, cells: dict[str, str]) -> None:
        """A row: ``cells`` holds a text for each column."""
        name = cells[NAME]
        if len(self.table) >= TABLE["max_rows"]:
            raise self.fail(line, f"more than {TABLE['max_rows']} cutters (limit max_rows)")
        if not name:
            raise self.fail(line, "empty cutter name")
        if len(name) > TABLE["max_name"]:
            raise self.fail(line, f"cutter name of {len(name)} characters, longer than the {TABLE['max_name']} "
                                  f"a cutter record holds (limit max_name)")
        values = []
        for rule in TABLE["values"]:
            text = cells[rule["column"]]
            v = number(text)
            if isinstance(v, str):
                raise self.fail(line, f"{rule['column']} '{quote(text)}' is {v}")
            if rule["positive"] and v <= 0.0:
                raise self.fail(line, f"{rule['column']} {text} is not greater than 0 (check {rule['check']})")
            values.append(v)
        if name in self.lines:
            raise self.fail(line, f"cutter '{quote(name)}' given twice (first on line {self.lines[name]})")
        self.lines[name] = line
        self.table[name] = tuple(values)

    def result(self) -> dict[str, tuple[float, ...]]:
        if not self.table:
            raise OptionFileError(f"{self.where}: no cutters (the table is empty)", kind="cutters")
        return self.table


def _cell(text: str) -> str:
    s = text.strip(BLANKS)
    if len(s) >= 2 and s[0] in "\"'" and s[-1] == s[0]:
        s = s[1:-1]
    return s


def _csv(text: str, rows: _Rows) -> None:
    col: dict[str, int] | None = None
    max_columns = TABLE["max_columns"]
    for n, raw in enumerate(text.split("\n"), start=1):
        if not raw.strip(BLANKS):
            continue
        cells = [_cell(c) for c in raw.split(",")]
        if len(cells) > max_columns:
            raise rows.fail(n, f"more than {max_columns} columns (limit max_columns)")
        if col is None:
            col = {name: cells.index(name) for name in COLUMNS if name in cells}
            if len(col) != len(COLUMNS):
                raise rows.fail(n, f"the header row needs the columns {', '.join(COLUMNS)}")
            continue
        if any(k >= len(cells) for k in col.values()):
            raise rows.fail(n, f"needs {', '.join(COLUMNS)}")
        rows.add(n, {name: cells[col[name]] for name in COLUMNS})


def _text(node: Scalar) -> str:
    return "null" if node.value is None else node.text


def _yaml(text: str, rows: _Rows) -> None:
    """Rows from the YAML tree, in document order (as cbf-c meets them in one pass)."""
    root = yaml_tree(text, rows.where, TABLE["max_depth"])
    if isinstance(root, Mapping):
        for k, (key, value) in enumerate(root.pairs):
            if key.text != "cutters":
                raise rows.fail(key.line, f"unknown key '{quote(key.text)}' (known: cutters)")
            if k:
                raise rows.fail(key.line, "duplicate key 'cutters'")
            _rows(value, rows)
    elif root is not None:
        _rows(root, rows)


def _rows(node: Scalar | Mapping | Sequence, rows: _Rows) -> None:
    if isinstance(node, Scalar) and node.value is None:
        return
    if not isinstance(node, Sequence):
        raise rows.fail(node.line, f"expected a list of cutters ({', '.join(COLUMNS)})")
    for item in node.items:
        if not isinstance(item, Mapping):
            raise rows.fail(item.line, f"a cutter is a mapping of {', '.join(COLUMNS)}")
        got: dict[str, str] = {}
        for key, value in item.pairs:
            if key.text not in COLUMNS:
                raise rows.fail(key.line, f"unknown key '{quote(key.text)}' (known: {', '.join(COLUMNS)})")
            if key.text in got:
                raise rows.fail(key.line, f"duplicate key '{quote(key.text)}'")
            if not isinstance(value, Scalar):
                raise rows.fail(value.line, f"{key.text} must be one value")
            got[key.text] = _text(value)
        if len(got) != len(COLUMNS):
            raise rows.fail(item.line, f"needs {', '.join(COLUMNS)}")
        rows.add(item.line, got)


def load_cutter_table(path: str | Path) -> dict[str, tuple[float, ...]]:
    """{name: (value, ...)}, the values in the order of ``VALUES`` (today length, radius). Raises
    OptionFileError (a CbfError) naming the line and the limit."""
    p = Path(path)
    text = read_text(p, TABLE["what"], TABLE["max_bytes"])
    rows = _Rows(quote(str(p)))
    (_yaml if is_yaml(p) else _csv)(text, rows)
    return rows.result()
