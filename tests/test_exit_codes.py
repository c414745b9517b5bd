"""Both command-line tools, `cbf` (Python) and `cbf-c` (C), against ONE table: the README's
"Exit codes and bad input" (issue 13 item 14). The table is read from README.md, so it cannot
drift: each row names an input, the commands run on it, each tool's exit code and the lines it
prints (patterns with FILE, N, ID, PATH, ... placeholders). The inputs are built here from the
model (cbf.tables, the codec) and the golden files; each row has exactly one builder.
"""

from __future__ import annotations

import json
import re
import subprocess
import sys
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest
from c_programs import built
from cli_many import run_many
from conftest import ENV, file_maker, locked_file, unprivileged_prefix

import cbf
from cbf import tables as T
from cbf.codec import decode
from cbf.cut import keyword

REPO = Path(__file__).resolve().parents[1]
README = REPO / "README.md"
GOLDEN = REPO / "conformance" / "golden"
VALID = GOLDEN / "valid.v3.small.cbf"
CBF_C = REPO / "build" / "c" / "cbf-c"
OK, FINDINGS, USAGE = 0, 1, 2
LIMIT = T.HEADER_SIZE + (T.LIMITS["max_commands"] + 1) * (T.HEAD_SIZE + T.LIMITS["max_arg_size"])
READER = {"cbf": "info", "cbf-c": "dump"}
_PLACES = re.compile(r"\b(FILE|OUT|GOOD|VERSION)\b")  # in a command of the table


# -- the README table --------------------------------------------------------------------------------
@dataclass(frozen=True)
class Row:
    input: str
    commands: tuple[str, ...]  # cbf's argv templates; cbf-c runs the same with `dump` for `info`
    exits: dict[str, int | None]  # per tool; None: the tool has no such command
    patterns: tuple[str, ...]

    @property
    def usage(self) -> bool:
        return self.input.startswith("bad usage")


def readme_table() -> list[Row]:
    text = README.read_text(encoding="utf-8")
    section = text[text.index("### Exit codes and bad input"):]
    section = section[:section.index("\n#", 1)]
    lines = [ln for ln in section.splitlines() if ln.startswith("|")]
    head = [c.strip() for c in lines[0].strip("|").split("|")]
    assert head == ["input", "command", "`cbf`", "`cbf-c`", "says"], head
    rows = []
    for ln in lines[2:]:
        cells = [c.strip() for c in ln.strip("|").split(" | ")]
        assert len(cells) == 5, ln
        exits = {"cbf": int(cells[2]), "cbf-c": None if cells[3] == "—" else int(cells[3])}
        rows.append(Row(cells[0], tuple(re.findall(r"`([^`]*)`", cells[1])), exits,
                        tuple(re.findall(r"`([^`]*)`", cells[4]))))
    return rows


_TOKEN = re.compile(r"\.\.\.|U\+XXXX|\b(?:FILE|OUT|GOOD|TOOL|N|ID|PATH)\b")


def _regex(pattern: str, tool: str, subs: dict[str, str]) -> re.Pattern[str]:
    """A README pattern as a regular expression for one tool and one run."""
    free = {"...": ".*", "U+XXXX": r"U\+[0-9A-F]{4,6}", "N": r"\d+", "ID": r"[\w.]+", "PATH": r"\$\S*",
            "TOOL": re.escape(tool)}
    out, at = [], 0
    for m in _TOKEN.finditer(pattern):
        out.append(re.escape(pattern[at:m.start()]))
        tok = m.group(0)
        out.append(free[tok] if tok in free else re.escape(subs[tok]))
        at = m.end()
    out.append(re.escape(pattern[at:]))
    return re.compile("".join(out))


def _applies(pattern: str, tool: str) -> bool:
    """A pattern naming `cbf-c` is cbf-c's, one naming `cbf` cbf's, any other both tools'."""
    if "cbf-c" in pattern:
        return tool == "cbf-c"
    if re.search(r"\bcbf\b(?!-)", pattern):
        return tool == "cbf"
    return True


# -- the inputs, from the model ------------------------------------------------------------------------
@dataclass(frozen=True)
class Input:
    path: Path
    needles: tuple[str, ...] = ()  # what the model says the message holds (beyond the README pattern)
    unprivileged: bool = False  # run held to the mode bits
    hide_matplotlib: bool = False


def _cut_record() -> tuple[bytes, int, int]:
    """VALID cut in the middle of its last record: (bytes, that record's offset, its index)."""
    data = VALID.read_bytes()
    records = decode(data).records
    last = records[-1]
    assert last.offset is not None and last.arg_size > 1
    return data[:last.offset + T.HEAD_SIZE + last.arg_size // 2], last.offset, len(records) - 1


def _arg_flipped() -> tuple[bytes, int]:
    """VALID with one argument byte of record 0 changed: the argument checksum fails (an error finding)."""
    data = bytearray(VALID.read_bytes())
    first = decode(bytes(data)).records[0]
    assert first.offset is not None and first.arg_size > 0
    data[first.offset + T.HEAD_SIZE] ^= 0x01
    return bytes(data), first.offset


CUT, CUT_AT, CUT_INDEX = _cut_record()
FLIPPED, FLIPPED_AT = _arg_flipped()
MODEL = decode(VALID.read_bytes())
VERSION = MODEL.version_id
TARGET = next(v.id for v in T.VERSIONS if v.writable and v.id != VERSION)


def _check_id(kind: str) -> str:
    return str(T.checks_of(kind)[0]["id"])


def _layout(record: int) -> T.LayoutInfo:
    r = MODEL.records[record]
    lay = T.BY_CODE[r.code].layout_for_size(VERSION, len(r.raw_args))
    assert lay is not None
    return lay


def _record_where(test: Callable[[T.LayoutInfo], bool]) -> int:
    return next(i for i in range(len(MODEL.records)) if test(_layout(i)))


def _one_float(lay: T.LayoutInfo) -> bool:
    return [(f.kind, f.count) for f in lay.args] == [("float", 1)]


# The CUT text of VALID: its header lines, then one line per record.
CUT_LINES = cbf.to_cut(MODEL).splitlines()
HEAD_LINES = len(CUT_LINES) - len(MODEL.records)
FLOAT_REC = _record_where(_one_float)
NO_TEXT_REC = _record_where(lambda lay: bool(lay.args) and all(f.kind != "string" for f in lay.args))


def _cut(tmp: Path, name: str, lines: list[str]) -> Path:
    p = tmp / name
    p.write_bytes(("\n".join(lines) + "\n").encode("latin-1"))
    return p


def _json(tmp: Path, name: str, doc: Any) -> Path:
    p = tmp / name
    p.write_text(json.dumps(doc), encoding="utf-8")
    return p


def _doc() -> dict[str, Any]:
    doc: dict[str, Any] = json.loads(json.dumps(cbf.to_canonical(MODEL)))
    return doc


def _float_path() -> tuple[str, str]:
    arg = _layout(FLOAT_REC).args[0].name
    return arg, f"$.records[{FLOAT_REC}].args.{arg}"


def _control_character(tmp: Path) -> list[Input]:
    a, b = CUT_LINES[HEAD_LINES], CUT_LINES[HEAD_LINES + 1]
    lines = CUT_LINES[:HEAD_LINES] + [a + "\x0c" + b] + CUT_LINES[HEAD_LINES + 2:]
    return [Input(_cut(tmp, "control.cut", lines), (f"line {HEAD_LINES + 1}, column {len(a) + 1}", "U+000C"))]


def _header_twice(tmp: Path) -> list[Input]:
    return [Input(_cut(tmp, "twice.cut", [CUT_LINES[0], *CUT_LINES]), ("line 2", "line 1"))]


def _trailing_text(tmp: Path) -> list[Input]:
    lines = list(CUT_LINES)
    lines[HEAD_LINES + NO_TEXT_REC] += " extra"
    return [Input(_cut(tmp, "trailing.cut", lines), (f"line {HEAD_LINES + NO_TEXT_REC + 1}", "'extra'"))]


def _long_version(tmp: Path) -> list[Input]:
    line = f"{T.CUT['extensions']['version_keyword']} 4.{'0' * 5000}"
    lines = CUT_LINES[:HEAD_LINES] + [line] + CUT_LINES[HEAD_LINES:]
    return [Input(_cut(tmp, "version.cut", lines), (f"line {HEAD_LINES + 1}",))]


def _cut_beyond_binary32(tmp: Path) -> list[Input]:
    lines = list(CUT_LINES)
    lines[HEAD_LINES + FLOAT_REC] = f"{keyword(T.BY_CODE[MODEL.records[FLOAT_REC].code])} 1{'0' * 310}"
    return [Input(_cut(tmp, "beyond.cut", lines), (f"line {HEAD_LINES + FLOAT_REC + 1}",))]


def _fails_a_check(tmp: Path) -> list[Input]:
    """CUT text that reads, but whose file fails an error check: the one float of a record that a check of kind
    positive targets, set to -1 (the model's check and VALID's record)."""
    for check in T.checks_of("positive"):
        names = {t["command"] for t in check.get("targets", ())}
        rec = next((i for i, r in enumerate(MODEL.records) if T.BY_CODE[r.code].name in names
                    and _one_float(_layout(i))), None)
        if check["severity"] == "error" and rec is not None:
            break
    else:
        pytest.skip("no error check of kind positive targets a record of one float in VALID")
    lines = list(CUT_LINES)
    lines[HEAD_LINES + rec] = f"{keyword(T.BY_CODE[MODEL.records[rec].code])} -1"
    return [Input(_cut(tmp, "fails.cut", lines), (f"line {HEAD_LINES + rec + 1}: record {rec}: ",
                                                  f"check {check['id']}: "))]


def _json_beyond_binary32(tmp: Path) -> list[Input]:
    arg, path = _float_path()
    out = []
    for name, literal in (("1e400", "1e400"), ("nan", "NaN"), ("inf", "Infinity"),
                          ("huge", "1e1000000000000000000")):  # issue 36: a decimal.InvalidOperation traceback
        doc = _doc()
        doc["records"][FLOAT_REC]["args"][arg] = "@@"
        p = tmp / f"{name}.json"
        p.write_text(json.dumps(doc).replace('"@@"', literal), encoding="utf-8")
        out.append(Input(p, (path,)))
    return out


def _bad_bit_pattern(tmp: Path) -> list[Input]:
    arg, path = _float_path()
    doc = _doc()
    doc["records"][FLOAT_REC]["args"][arg] = "0x-0000001"
    return [Input(_json(tmp, "pattern.json", doc), (path,))]


def _key_twice(tmp: Path) -> list[Input]:
    text = json.dumps(_doc())
    first = next(iter(_doc()))
    p = tmp / "twice.json"
    p.write_text("{" + json.dumps(first) + ": null, " + text[1:], encoding="utf-8")
    return [Input(p, (f"'{first}'",))]


def _not_ascii(tmp: Path) -> list[Input]:
    doc = _doc()
    field = T.HEADERS[T.VERSION_BY_ID[VERSION].header].by_role("implant_descriptor")
    assert field is not None
    doc["header"][field.name] = "ok\u0000\u0001"
    return [Input(_json(tmp, "ascii.json", doc), (field.name,))]


def _cut_text(tmp: Path) -> list[Input]:
    return [Input(_cut(tmp, "valid.cut", CUT_LINES))]


def _many_segments(tmp: Path) -> list[Input]:
    """A full circle of many turns at a large radius: more segments at --chord-tol than a file holds."""
    circle = next((c for c in T.COMMANDS if c.motion and c.motion["kind"] == "circle" and c.layouts_for(VERSION)
                   and not c.layouts_for(TARGET)), None)
    point = next(c for c in T.COMMANDS if c.motion and c.motion["kind"] == "point" and c.layouts_for(VERSION))
    if circle is None:
        pytest.skip(f"no circle command of {VERSION} is missing in {TARGET}")
    assert circle.motion is not None and point.motion is not None
    values = {circle.motion["start"]: (5000.0, 0.0, 0.0), circle.motion["center"]: (0.0, 0.0, 0.0),
              circle.motion["normal"]: (0.0, 0.0, 1.0), circle.motion["degrees"]: 360.0 * 40}

    def args(cmd: T.CommandInfo, given: dict[str, Any]) -> Any:
        lay = cmd.layouts_for(VERSION)[0]
        full = {f.name: given.get(f.name, (0.0, 0.0, 0.0) if f.count == 3 else 0.0) for f in lay.args}
        return lay.cls(**full)

    model = cbf.Cbf(MODEL.header, [cbf.model.Record.of(args(point, {point.motion["end"]: (5000.0, 0.0, 0.0)})),
                                   cbf.model.Record.of(args(circle, values))])
    p = tmp / "circles.cbf"
    p.write_bytes(cbf.encode(model))
    return [Input(p, ("record 1", circle.name))]


def _unreadable_for_tools(tmp: Path) -> list[Input]:
    bad_cut = _cut(tmp, "bad.cut", [CUT_LINES[0], f"{keyword(T.BY_CODE[MODEL.records[FLOAT_REC].code])} fast"])
    bad_json = tmp / "bad.json"
    bad_json.write_text('{"header": {,}}', encoding="utf-8")
    return [Input(tmp / "missing.cbf", ("no such file",)),
            Input(file_maker("cut.cbf", CUT)(tmp), (f"offset {CUT_AT}",)),
            Input(file_maker("short.cbf", VALID.read_bytes()[:T.HEADER_SIZE - 1])(tmp), ("offset 0",)),
            Input(bad_cut, ("line 2",)), Input(bad_json, ("line 1",))]


def _differs(tmp: Path) -> list[Input]:
    lines = list(CUT_LINES)
    kw = keyword(T.BY_CODE[MODEL.records[FLOAT_REC].code])
    lines[HEAD_LINES + FLOAT_REC] = f"{kw} 123.5"
    return [Input(_cut(tmp, "changed.cut", lines))]


def _too_large(tmp: Path) -> list[Input]:
    p = tmp / "huge.cbf"
    with p.open("wb") as fh:
        fh.write(VALID.read_bytes())
        fh.truncate(LIMIT + 1)  # sparse: the valid file, then zeros past the largest CBF file
    return [Input(p, (f"larger than {LIMIT} bytes",))]


def _bad_machine_files(tmp: Path) -> list[Input]:
    """Machine files (check machine_limits) that cannot be used: a limit in another unit, a key
    given twice, and text that is not JSON; built from the spec's default machine."""
    from cbfgen.emit.python.machine import machine_data
    from cbfgen.loader import load

    doc = machine_data(load(REPO / "spec" / "cbf.yaml"))
    name = next(iter(doc["limits"]))
    unit = json.loads(json.dumps(doc))
    unit["limits"][name]["unit"] = "furlong"
    text = json.dumps(doc)
    key = next(iter(doc))
    twice = text.replace("{", "{" + json.dumps(key) + ": " + json.dumps(doc[key]) + ", ", 1)  # the same key, twice
    return [Input(file_maker("unit.json", json.dumps(unit).encode())(tmp), (f"$.limits.{name}.unit",)),
            Input(file_maker("twice.json", twice.encode())(tmp), ("duplicate",)),
            Input(file_maker("broken.json", b"{")(tmp), ("line 1",))]


def _one(name: str, data: bytes, *needles: str) -> Callable[[Path], list[Input]]:
    return lambda tmp: [Input(file_maker(name, data)(tmp), needles)]


FINDING_ARG = f":{FLIPPED_AT + T.ARG_CHECKSUM.offset}: error {_check_id('arg_checksum')} (record 0)"
FINDING_CUT = f":{CUT_AT}: error {_check_id('truncated_record')} (record {CUT_INDEX})"

# Each README row's input, by the row's first cell.
INPUTS: dict[str, Callable[[Path], list[Input]]] = {
    "a CBF file without error findings": _one("valid.cbf", VALID.read_bytes()),
    "a CBF file with an error finding": _one("flipped.cbf", FLIPPED, FINDING_ARG),
    "a CBF file with or without error findings": lambda tmp: [Input(file_maker("valid.cbf", VALID.read_bytes())(tmp)),
                                                             Input(file_maker("flipped.cbf", FLIPPED)(tmp))],
    "a CBF file whose last record is cut (4.3, D1)": _one("cut.cbf", CUT, str(CUT_AT), f"record {CUT_INDEX}"),
    "empty, or shorter than the header": lambda tmp: [
        Input(file_maker("empty.cbf", b"")(tmp), ("file is 0 bytes", f"the header needs {T.HEADER_SIZE}")),
        Input(file_maker("short.cbf", VALID.read_bytes()[:T.HEADER_SIZE - 1])(tmp),
              (f"file is {T.HEADER_SIZE - 1} bytes", f"the header needs {T.HEADER_SIZE}"))],
    "not CBF: both magic numbers wrong (a text file, say)": _one(
        "notes.cbf", b"These are my notes, not a cutfile.\n" * 20, f"offset {T.START.offset}"),
    "a missing file": lambda tmp: [Input(tmp / "missing.cbf")],
    "a directory": lambda tmp: [Input(tmp)],
    "a file it may not read": lambda tmp: [Input(locked_file(tmp, VALID.read_bytes()), unprivileged=True)],
    "larger than a CBF file can be (`cbf` refuses it unread)": _too_large,
    "bad usage: an unknown option": _one("valid.cbf", VALID.read_bytes()),
    "bad usage: no file": lambda tmp: [Input(tmp / "unused")],
    "a machine file (`--machine`) that is not the spec's `machine:` shape: another unit, an unknown or "
    "duplicate key, not JSON": _bad_machine_files,
    "the version": lambda tmp: [Input(tmp / "unused", (f"{cbf.__version__} (spec {cbf.SPEC_REVISION})",))],
    "CUT text with a control character (VT, FF, NUL, TAB, DEL, U+0085, U+2028, a CR without LF...) or any "
    "non-ASCII character: only LF and CR LF end a line": _control_character,
    "a CUT header line given twice (`header`, `header_ext`, `check_sum`, `cbf_version`, even when both agree), "
    "or `header` and `cbf_field` setting one field": _header_twice,
    "text after the arguments of any CUT keyword (`cbf_record`, `check_sum`, `cbf_field` included)": _trailing_text,
    "a `cbf_version` that is not two numbers 0 to 255 (a 5,000-digit one included)": _long_version,
    "a CUT number beyond the binary32 range (a 310-digit integer)": _cut_beyond_binary32,
    "CUT text that reads, but whose file would fail an error-severity check under the profile (a number a "
    "positive check bounds, as -1): a writer writes files that validate": _fails_a_check,
    "a JSON number beyond the binary32 range (`1e400`, `1e1000000000000000000`), `NaN` or `Infinity` (write NaN "
    "and infinity as a bit pattern)": _json_beyond_binary32,
    "a JSON float bit pattern other than `0x` and exactly 8 hex digits": _bad_bit_pattern,
    "a JSON object with a key twice": _key_twice,
    "a string with a byte outside printable ASCII anywhere in the field, after a NUL too (unless "
    "`--keep-stored`)": _not_ascii,
    "`--keep-stored` with CUT input (CUT stores no sequence numbers, count or checksums to keep)": _cut_text,
    "canonical JSON given to `cbf-c encode` (cbf-c reads CUT text only)": lambda tmp: [
        Input(_json(tmp, "valid.json", _doc()))],
    "an output that cannot be written: a full disk (`/dev/full`)": _cut_text,
    "an output in a folder that does not exist": _cut_text,
    "bad usage: `encode` without `-o`": _cut_text,
    "`encode --version` a version that cannot be written": lambda tmp: [
        Input(_cut(tmp, "valid.cut", CUT_LINES), (TARGET,))],
    "`convert` of a file that fails validation": _one("flipped.cbf", FLIPPED),
    "`convert --to-version` a version that cannot be written": _one("valid.cbf", VALID.read_bytes(), TARGET),
    "`convert --chord-tol` not a positive number": _one("valid.cbf", VALID.read_bytes()),
    "`convert --fill` malformed": _one("valid.cbf", VALID.read_bytes()),
    "`convert`: a curve needs more than 65,535 segments": _many_segments,
    "`stats`, `diff`, `plot` of a missing, truncated or not CBF file, or CUT or JSON text that does not "
    "parse": _unreadable_for_tools,
    "`diff` of two files that differ": _differs,
    "`plot -o` with an extension other than .png, .svg, .pdf and no `--format`": _one("valid.cbf", VALID.read_bytes()),
    "`plot` without matplotlib installed": lambda tmp: [Input(file_maker("valid.cbf", VALID.read_bytes())(tmp),
                                                              hide_matplotlib=True)],
}
ROWS = readme_table()


def test_every_row_has_its_input_and_every_input_its_row() -> None:
    assert {r.input for r in ROWS} == set(INPUTS)
    assert all(r.commands and r.exits["cbf"] is not None for r in ROWS)


# -- the two tools ----------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def cbf_c() -> Path:
    """cbf-c as `make c-build` builds it (c_programs.built: an up-to-date tool is reused, not compiled again,
    and two workers never build it at once)."""
    path = built(CBF_C.name)
    assert path == CBF_C
    return path


HIDE_MATPLOTLIB = "import sys, runpy; sys.modules['matplotlib'] = None; sys.argv[0] = 'cbf'; " \
                  "runpy.run_module('cbf', run_name='__main__')"


def _run(tool: str, cbf_c: Path, argv: list[str], inp: Input) -> subprocess.CompletedProcess[str]:
    prefix = unprivileged_prefix() if inp.unprivileged else []
    if tool == "cbf-c":
        exe = [str(cbf_c)]
    elif inp.hide_matplotlib:
        exe = [sys.executable, "-c", HIDE_MATPLOTLIB]
    else:
        exe = [sys.executable, "-m", "cbf"]
    return subprocess.run([*prefix, *exe, *argv], env=ENV, capture_output=True, text=True,
                          stdin=subprocess.DEVNULL, errors="replace")


@dataclass(frozen=True)
class Run:
    """One command of a row on one of its inputs, with its own output folder."""
    inp: Input
    command: str
    argv: list[str]
    subs: dict[str, str]
    out_dir: Path


def _plan(row: Row, tool: str, tmp: Path) -> list[Run]:
    src = tmp / "in"
    src.mkdir()
    good = file_maker("good.cbf", VALID.read_bytes())(tmp)
    runs: list[Run] = []
    for inp in INPUTS[row.input](src):
        for command in row.commands:
            out_dir = tmp / f"out{len(runs)}"
            out_dir.mkdir()
            subs = {"FILE": str(inp.path), "OUT": str(out_dir / "out"), "GOOD": str(good), "VERSION": TARGET}
            argv = [_PLACES.sub(lambda m: str(subs[m.group(1)]), a) for a in command.split()]  # noqa: B023
            if tool == "cbf-c" and argv[0] == READER["cbf"]:
                argv[0] = READER["cbf-c"]
            runs.append(Run(inp, command, argv, subs, out_dir))
    return runs


Done = list[tuple[Run, subprocess.CompletedProcess[str]]]


@pytest.fixture(scope="module")
def cbf_done(tmp_path_factory: pytest.TempPathFactory) -> dict[tuple[str, tuple[str, ...]], Done | str]:
    """Every row's `cbf` runs (or why the row is skipped), from one process per kind of run
    (cli_many: main() per command line, each with its own streams and exit code): plain, held
    to the mode bits, without matplotlib. A process per run cost about 0.3 CPU s each."""
    plans: dict[tuple[str, tuple[str, ...]], list[Run] | str] = {}  # by input and commands: a row
    for row in ROWS:
        try:
            plans[row.input, row.commands] = _plan(row, "cbf", tmp_path_factory.mktemp("row"))
        except pytest.skip.Exception as exc:
            plans[row.input, row.commands] = str(exc.msg)
    runs = [run for plan in plans.values() if not isinstance(plan, str) for run in plan]
    results: dict[int, subprocess.CompletedProcess[str] | str] = {}
    for unprivileged, hide in sorted({(r.inp.unprivileged, r.inp.hide_matplotlib) for r in runs}):
        group = [r for r in runs if (r.inp.unprivileged, r.inp.hide_matplotlib) == (unprivileged, hide)]
        try:
            prefix = unprivileged_prefix() if unprivileged else []
        except pytest.skip.Exception as exc:
            results.update((id(r), str(exc.msg)) for r in group)
            continue
        done = run_many([r.argv for r in group], ENV, prefix=prefix, hide=["matplotlib"] if hide else [])
        results.update((id(r), res) for r, (res, _) in zip(group, done, strict=True))
    out: dict[tuple[str, tuple[str, ...]], Done | str] = {}
    for key, plan in plans.items():
        if isinstance(plan, str):
            out[key] = plan
            continue
        got = [results[id(r)] for r in plan]
        why = next((g for g in got if isinstance(g, str)), None)
        out[key] = why if why is not None else [(r, g) for r, g in zip(plan, got, strict=True)
                                                 if not isinstance(g, str)]
    return out


@pytest.mark.parametrize("tool", ["cbf", "cbf-c"])
@pytest.mark.parametrize("row", ROWS, ids=lambda r: r.input[:60])
def test_the_readme_table(row: Row, tool: str, request: pytest.FixtureRequest, tmp_path: Path) -> None:
    code = row.exits[tool]
    if code is None:
        pytest.skip(f"{tool} has no {row.commands[0].split()[0]} of this input (`—` in the table)")
    if tool == "cbf":
        done: Done | str = request.getfixturevalue("cbf_done")[row.input, row.commands]
    else:
        cbf_c = request.getfixturevalue("cbf_c")
        done = [(run, _run(tool, cbf_c, run.argv, run.inp)) for run in _plan(row, tool, tmp_path)]
    if isinstance(done, str):
        pytest.skip(done)
    assert done
    for run, res in done:
        inp, command, subs = run.inp, run.command, run.subs
        what = (tool, command, inp.path.name, res.returncode, res.stderr[-600:], res.stdout[-600:])
        assert "Traceback" not in res.stderr + res.stdout, what
        assert res.returncode == code, what
        if code == USAGE:
            assert res.stdout == "", what
            assert list(run.out_dir.iterdir()) == [], what  # nothing written to -o
            lines = res.stderr.splitlines()
            assert len(lines) == 1 or (row.usage and lines), what
            text = lines
        else:
            assert res.stderr == "", what
            text = res.stdout.splitlines()
        for pattern in (p for p in row.patterns if _applies(p, tool)):
            rx = _regex(pattern, tool, subs)
            assert any(rx.fullmatch(line) for line in text), (pattern, rx.pattern, *what)
        for needle in inp.needles:
            assert needle in "\n".join(text), (needle, *what)
        if code != USAGE and run.argv[0] == "validate":
            verdict = "FAIL" if code == FINDINGS else "ok"
            assert text[-1].startswith(f"{inp.path}: {verdict}: "), what
        elif code == OK and run.argv[0] in READER.values():
            assert text, what  # the header and the records


# -- what the table does not say row by row ---------------------------------------------------------------
@pytest.mark.parametrize("data", [VALID.read_bytes(), FLIPPED, CUT], ids=["valid", "error_finding", "record_cut"])
def test_both_tools_print_the_same_findings(data: bytes, cbf_c: Path, tmp_path: Path) -> None:
    """Finding lines agree (README's `file:offset: severity check (record N): message`) but for the message."""
    path = file_maker("in.cbf", data)(tmp_path)

    def findings(tool: str) -> set[str]:
        argv = ["validate", "--max-findings", "0", str(path)] if tool == "cbf" else ["validate", str(path)]
        res = _run(tool, cbf_c, argv, Input(path))
        return {ln.split("): ", 1)[0] for ln in res.stdout.splitlines() if ln.startswith(f"{path}:") and "): " in ln}

    py, c = findings("cbf"), findings("cbf-c")
    assert py == c
    assert bool(py) == (data != VALID.read_bytes())


def test_cbf_c_validate_exits_with_the_worst_status(cbf_c: Path, tmp_path: Path) -> None:
    flipped = file_maker("flipped.cbf", FLIPPED)(tmp_path)
    assert _run("cbf-c", cbf_c, ["validate", str(VALID), str(flipped)], Input(flipped)).returncode == FINDINGS
    res = _run("cbf-c", cbf_c, ["validate", str(flipped), str(tmp_path / "missing.cbf"), str(VALID)], Input(flipped))
    assert res.returncode == USAGE and f"{VALID}: ok: " in res.stdout


def test_cbf_validate_json_prints_nothing_for_input_that_is_not_cbf(tmp_path: Path) -> None:
    rows = [r for r in ROWS if r.exits["cbf"] == USAGE and "validate FILE" in r.commands]
    assert rows
    todo = []
    for k, row in enumerate(rows):
        (tmp_path / str(k)).mkdir()
        todo += [(row, inp) for inp in INPUTS[row.input](tmp_path / str(k)) if not inp.unprivileged]
    done = run_many([["validate", "--json", str(inp.path)] for _, inp in todo], ENV)  # one process
    for (row, inp), (res, _) in zip(todo, done, strict=True):
        assert res.returncode == USAGE and res.stdout == "", (row.input, res)
        assert len(res.stderr.splitlines()) == 1 and res.stderr.startswith(f"cbf: {inp.path}: ")
