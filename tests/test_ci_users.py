"""CI users, round 3 (issue #35, points 1-4): output no input can forge, reports GitHub and GitLab
accept, names that always encode, file systems that bite.

1. Hostile file names (a forged ``::error`` workflow command, line feeds, carriage returns, bytes
   that are not UTF-8, terminal escapes, U+2028) and hostile contents (a duplicate JSON key, an
   unknown machine-file key, a repeated cutter, a header string holding escapes) go through every
   command and every format option of cbf (read from its parser: a new command or format joins the
   test or fails it), both commands of cbf-c, the pre-commit hooks' entries and the conformance kit
   (a hostile --name, a testee whose answers hold forged commands): no output line starts with ``::``
   (but the github format's own commands, one per finding), none carries an input's line break,
   every output is UTF-8 and parses (JSON, XML, SVG). Both tools print the same quoted name (one
   rule). The command lines run in one process each (tests/cli_many.py), one real process a format.
2. SARIF: Microsoft's SARIF multitool (npm, pinned in package.json) finds 0 errors and 0 warnings
   under ``--rule-kind Gh;Sarif``; the 65,536 findings of a file with one bad byte in every record
   give a SARIF of at most GitHub's 25,000 results (and under its 10 MB) that says what it left
   out; --max-findings caps every format. GitLab's report passes schemas/gitlab-code-quality.schema.json.
3. A name's exact bytes come back from JSON (cbf.quoting.unquote) and SARIF (percent-decoding).
4. A FIFO, a device or a socket is refused in one line, never opened blocking; an unreadable
   folder or file is exit 2 naming it, run as a user the mode bits hold (nobody, when the tests
   run as root); a folder 1,000 levels deep is walked.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import shlex
import shutil
import socket
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
from collections.abc import Iterator, Sequence
from pathlib import Path
from urllib.parse import unquote_to_bytes

import jsonschema
import pytest
import yaml
from c_programs import built
from cli_many import run_many
from conftest import ENV, REPO, unprivileged_prefix

import cbf
from cbf import tables as T
from cbf.cli import parser as cli_parser
from cbf.quoting import quote, unquote
from conformance.kit import stage

GOLDEN = REPO / "conformance" / "golden"
FORMATS = ("text", "json", "junit", "sarif", "github", "gitlab")
ENV_STRICT = dict(ENV, PYTHONIOENCODING="utf-8:strict", LC_ALL="C.UTF-8")
MULTITOOL = REPO / "node_modules" / "@microsoft" / "sarif-multitool-linux" / "Sarif.Multitool"
GITLAB_SCHEMA = json.loads((REPO / "schemas" / "gitlab-code-quality.schema.json").read_text(encoding="utf-8"))
FORGED = b"::"  # GitHub runs a line starting with it as a workflow command
# Names that break a naive printer: a forged annotation, line breaks before a command, bytes that
# are not UTF-8, controls and a terminal escape, a Unicode line separator, quotes and backslashes.
HOSTILE = [b"::error file=README.md,line=1,title=Forged::all good", b"a\n::stop-commands::x",
           b"r\r::warning ::x", b"b\xff\xfe", b"c\x01\x1b[31m", "\u2028::error ::u".encode(), b" ::lead",
           b'q"\\', b"%41#?=&;,x"]
Result = subprocess.CompletedProcess[str]
BREAKS = (b"\r", b"\x1b", "\u2028".encode(), "\u0085".encode(), b"\x01")


def _small(clean: bool) -> Path:
    """The first golden file (small) with no finding, or with an error finding (from the engine)."""
    for p in sorted(GOLDEN.glob("*.cbf")):
        data = p.read_bytes()
        if len(data) > 4096:
            continue
        try:
            found = cbf.validate(data)
        except cbf.CbfError:
            continue
        if (not found) if clean else any(f.severity == "error" for f in found):
            return p
    raise AssertionError("no such golden file")


CLEAN, BAD = _small(True), _small(False)


@pytest.fixture(scope="module")
def cbf_c() -> Path:
    return built("cbf-c")


def py(*argv: str | bytes, cwd: Path | None = None, timeout: float = 120,
       stdin: bytes | None = None) -> subprocess.CompletedProcess[bytes]:
    res = subprocess.run([sys.executable, "-m", "cbf", *argv], env=ENV_STRICT, cwd=cwd, capture_output=True,
                         timeout=timeout, input=stdin)
    assert b"Traceback" not in res.stderr, res.stderr.decode(errors="replace")
    return res


def c(tool: Path, *argv: str | bytes, cwd: Path | None = None,
      timeout: float = 60) -> subprocess.CompletedProcess[bytes]:
    return subprocess.run([str(tool), *argv], cwd=cwd, capture_output=True, timeout=timeout)


def assert_clean(res: subprocess.CompletedProcess[bytes], annotations: int | None = None) -> None:
    """No line starts with '::' (the github format: exactly ``annotations`` commands, each one line),
    no input's line break or control reaches the output, and both streams are UTF-8."""
    what = (res.args, res.returncode, res.stdout[-800:], res.stderr[-800:])
    for stream in (res.stdout, res.stderr):
        stream.decode("utf-8")  # strict: every name encodes
        for b in BREAKS:
            assert b not in stream, (b, *what)
    commands = [ln for ln in res.stdout.split(b"\n") if ln.startswith(FORGED)]
    assert not [ln for ln in res.stderr.split(b"\n") if ln.startswith(FORGED)], what
    if annotations is None:
        assert not commands, what
    else:
        assert len(commands) == annotations, what
        for ln in commands:  # ::error file=F,title=T::message: F and T hold no raw ':' or ','
            assert re.fullmatch(rb"::(error|warning|notice) file=[^:,]*,title=[^:,]*::.*", ln), (ln, *what)


def parses(fmt: str, out: bytes) -> object:
    """The document of a format, parsed (an error here fails the test)."""
    if fmt in ("json", "sarif", "gitlab"):
        return json.loads(out)
    if fmt == "junit":
        return ET.fromstring(out)
    return out.decode("utf-8")


@pytest.fixture(scope="module")
def hostile_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A folder of golden copies (one with findings, one clean) and a refused file under each hostile name."""
    root = tmp_path_factory.mktemp("hostile")
    for i, name in enumerate(HOSTILE):
        src = BAD if i % 2 == 0 else CLEAN
        (Path(os.fsdecode(bytes(root) + b"/" + name + b".cbf"))).write_bytes(src.read_bytes())
    (Path(os.fsdecode(bytes(root) + b"/" + HOSTILE[0] + b" not.cbf"))).write_text("text, not CBF\n")
    return root


def _names(root: Path) -> list[bytes]:
    return sorted(os.fsencode(p.name) for p in root.iterdir() if p.name.endswith(".cbf"))


def test_the_kit_carries_the_same_rule(tmp_path: Path) -> None:
    """The conformance kit installs without the codec: the runner's rule is the runtime's module
    (a link in the repository), and staging the kit copies that file in as a file."""
    rule = REPO / "generator" / "cbfgen" / "emit" / "python" / "runtime" / "quoting.py"
    assert (REPO / "conformance" / "runner" / "quoting.py").resolve() == rule.resolve()
    staged = stage(tmp_path / "kit") / "cbf_conformance" / "quoting.py"
    assert not staged.is_symlink() and staged.read_bytes() == rule.read_bytes()


def test_the_rule_reads_back_and_never_starts_a_command() -> None:
    for name in [*HOSTILE, b"plain/name.cbf", "é€😀.cbf".encode()]:
        shown = quote(os.fsdecode(name))
        assert unquote(shown) == name
        assert not shown.startswith("::") and "\n" not in shown and "\r" not in shown
        shown.encode("utf-8")
    assert quote("conformance/golden/x.cbf") == "conformance/golden/x.cbf"  # a plain name stays as it is
    assert quote("a\nb") == '"a\\nb"'  # the test can fail: an unquoted line break would


@pytest.mark.parametrize("fmt", FORMATS)
def test_hostile_names_in_every_format(fmt: str, hostile_dir: Path) -> None:
    """A real process a format (the checked writer to file descriptor 1, a strict UTF-8 stdout): a folder
    of hostile names (./NAME)."""
    names = _names(hostile_dir)
    found = {n: len(cbf.validate((hostile_dir / os.fsdecode(n)).read_bytes())) for n in names if b" not" not in n}
    res = py("validate", "--format", fmt, "--max-findings", "0", ".", cwd=hostile_dir)
    assert res.returncode == 2  # the text file is not validated
    refused = 1
    assert_clean(res, sum(found.values()) + refused if fmt == "github" else None)
    doc = parses(fmt, res.stdout)
    if fmt == "json":
        got = {unquote(f["file"]).removeprefix(b"./") for f in doc["files"]}  # type: ignore[index]
        assert got == set(names)  # exact bytes back
    elif fmt == "sarif":
        uris = {unquote_to_bytes(r["locations"][0]["physicalLocation"]["artifactLocation"]["uri"])
                for r in doc["runs"][0]["results"]}  # type: ignore[index]
        assert uris == {n for n in names if found.get(n, 1)}  # percent-encoded bytes: exact
    elif fmt == "gitlab":
        jsonschema.validate(doc, GITLAB_SCHEMA)
    elif fmt == "junit":
        cases = doc.findall("./testsuite/testcase")  # type: ignore[attr-defined]
        assert {unquote(c.get("name")).removeprefix(b"./") for c in cases} == set(names)


# -- every command and every format of cbf, in one process (tests/cli_many.py) --------------------------
def _subcommands() -> dict[str, argparse.ArgumentParser]:
    for action in cli_parser()._actions:
        if isinstance(action, argparse._SubParsersAction):
            return dict(action.choices)
    raise AssertionError("the cbf parser has no subcommands")


SUBCOMMANDS = _subcommands()
# The options that choose what a command writes (or reads): each of their choices is run, each flag once.
FORMAT_OPTIONS = ("--format", "--to", "--json", "--input-format")


def _format_uses() -> set[tuple[str, str, str | None]]:
    """(command, option, choice) for every output format the parser offers."""
    out: set[tuple[str, str, str | None]] = set()
    for name, sub in SUBCOMMANDS.items():
        for a in sub._actions:
            for opt in set(a.option_strings) & set(FORMAT_OPTIONS):
                out |= {(name, opt, str(c)) for c in a.choices} if a.choices else {(name, opt, None)}
    return out


def _covered(argvs: Sequence[Sequence[str]]) -> set[tuple[str, str, str | None]]:
    got: set[tuple[str, str, str | None]] = set()
    for argv in argvs:
        for i, arg in enumerate(argv):
            if arg in FORMAT_OPTIONS:
                value = argv[i + 1] if i + 1 < len(argv) and not argv[i + 1].startswith("-") else None
                got.add((argv[0], arg, value if arg != "--json" else None))
    return got


def _every_command(p: str, out: Path, first: bool) -> list[list[str]]:
    """Every command of cbf on one input (a hostile name, or a file with hostile contents), in every format;
    the slow ones (plot, convert) for the first input only."""
    writable = [v.id for v in T.VERSIONS if v.writable]
    o = os.fsdecode(bytes(out) + b"/" + os.fsencode(p).rsplit(b"/", 1)[-1])  # an output of the same hostile name
    runs = [["validate", "--format", f, "--max-findings", "0", p] for f in FORMATS]
    runs += [["validate", "--json", p], ["validate", "--part-number", HOSTILE_VALUE, p],
             ["info", p], ["info", "--json", p], ["stats", p], ["stats", "--json", p],
             ["diff", p, str(CLEAN)], ["diff", "--json", str(CLEAN), p], ["hexdump", p],
             ["decode", p], ["decode", "--to", "json", p, "-o", o + ".json"], ["decode", "--to", "cut", p],
             ["decode", "--to", "cut", p, "-o", o + ".cut"],
             ["encode", "--check", "--input-format", "json", o + ".json"],
             ["encode", "--input-format", "cut", o + ".cut", "-o", o + ".again.cbf"]]
    if first:
        runs += [["convert", p, "--to-version", writable[-1], "-o", o + ".c.cbf"],
                 ["convert", p, "--to-version", writable[-1], "--fill", HOSTILE_VALUE, "-o", o + ".d.cbf"],
                 ["plot", p, "--format", "svg", "-o", "-"],
                 *(["plot", p, "--format", f, "-o", f"{o}.{f}"] for f in ("png", "pdf"))]
    return runs


HOSTILE_VALUE = "::error file=x::forged\n\r\x1b[2J"


def _clean_text(res: subprocess.CompletedProcess[str], binary_ok: bool = False) -> None:
    """assert_clean for a result of cli_many (text decoded from a strict UTF-8 stream); the github format's
    own commands each one well-formed line."""
    assert "Traceback" not in res.stderr, (res.args, res.stderr)
    stdout = "" if binary_ok else res.stdout
    github = "github" in list(res.args)
    assert_clean(subprocess.CompletedProcess(res.args, res.returncode, stdout.encode(), res.stderr.encode()),
                 sum(ln.startswith("::") for ln in stdout.split("\n")) if github else None)


@pytest.fixture(scope="module")
def every_command(hostile_dir: Path, tmp_path_factory: pytest.TempPathFactory) -> list[Result]:
    """Every command and format of cbf on every hostile name, in one process."""
    out = tmp_path_factory.mktemp("every_out")
    argvs = [argv for k, n in enumerate(_names(hostile_dir))
             for argv in _every_command(os.fsdecode(bytes(hostile_dir) + b"/" + n), out, k == 0)]
    return [r for r, _ in run_many(argvs, ENV_STRICT, timeout=600)]


def test_hostile_names_through_every_command_and_format(every_command: list[Result]) -> None:
    argvs = [list(r.args) for r in every_command]
    assert {a[0] for a in argvs} == set(SUBCOMMANDS)  # a new command joins this test, or it fails
    assert _covered(argvs) == _format_uses()  # and so does a new format
    for res in every_command:
        argv = list(res.args)
        _clean_text(res, binary_ok="-o" in argv and argv[argv.index("-o") + 1] == "-" and "svg" not in argv)
        fmt = argv[argv.index("--format") + 1] if "--format" in argv else "json" if "--json" in argv else "text"
        if argv[0] == "validate" and res.stdout:  # a file a report refuses is in it
            parses(fmt, res.stdout.encode())
        elif res.returncode == 2:
            assert len(res.stderr.splitlines()) == 1, (argv, res.stderr)  # one line, naming what and where
        elif "--json" in argv or argv[:2] == ["decode", argv[1]] and "-o" not in argv and "cut" not in argv:
            doc = json.loads(res.stdout)
            assert isinstance(doc, dict)
        elif argv[0] == "plot" and "svg" in argv:
            ET.fromstring(res.stdout.encode())  # the title (the name) leaves the SVG well-formed


def test_one_hostile_name_alone_gives_its_bytes_back(every_command: list[Result], hostile_dir: Path) -> None:
    """JSON holds the exact bytes of a name (the quoted form where they are not UTF-8)."""
    seen = set()
    for res in every_command:
        argv = list(res.args)
        if argv[:2] == ["validate", "--json"] and res.returncode != 2:
            name = os.fsencode(argv[-1])
            assert unquote(json.loads(res.stdout)["file"]) == name
            seen.add(name)
    assert len(seen) >= len(HOSTILE) - 1  # all but the text file not CBF


def test_every_hidden_character_is_quoted_alike_by_both_tools(tmp_path: Path, cbf_c: Path) -> None:
    """Each end of each hidden range of the rule (and the character just outside it) in a file name:
    `cbf` and `cbf-c` print the same line, and a hidden one is quoted. Up to round 6, `cbf` printed
    U+FEFF, U+FFF9-U+FFFB and U+FFFE/U+FFFF as they are, where `cbf-c` quoted them."""
    from cbf import quoting

    hidden = [(lo, hi) for lo, hi in quoting.HIDDEN if (lo, hi) != quoting.SURROGATES]
    chars = sorted({ch for lo, hi in hidden for ch in (lo - 1, lo, hi, hi + 1)})
    names = []
    for ch in chars:
        p = tmp_path / f"a{chr(ch)}b.cbf"
        p.write_bytes(CLEAN.read_bytes())
        names.append(p)
        assert quoting.is_plain(p.name) == (not any(lo <= ch <= hi for lo, hi in hidden)), hex(ch)
    a = py("validate", "--max-findings", "0", *map(str, names))
    b = c(cbf_c, "validate", "--max-findings", "0", *map(str, names))
    assert a.returncode == b.returncode == 0, (a.stderr, b.stderr)
    assert a.stdout.splitlines()[:-1] == b.stdout.splitlines(), (a.stdout, b.stdout)  # cbf adds a summary line
    assert b.stdout.count(b'"') == 2 * sum(any(lo <= ch <= hi for lo, hi in hidden) for ch in chars)


def test_both_tools_print_the_same_quoted_name(every_command: list[Result], hostile_dir: Path,
                                               cbf_c: Path) -> None:
    by_name = {os.fsencode(r.args[-1]): r for r in every_command if list(r.args[:5]) == [
        "validate", "--format", "text", "--max-findings", "0"]}
    assert len(by_name) == len(_names(hostile_dir))
    for name, a in by_name.items():
        b = c(cbf_c, "validate", "--max-findings", "0", name)
        assert_clean(b)
        assert a.returncode == b.returncode
        assert a.stdout.encode() == b.stdout, (name, a.stdout, b.stdout)
        assert a.stderr.replace("cbf: ", "", 1).split(":")[0].encode() == \
            b.stderr.replace(b"cbf-c: ", b"", 1).split(b":")[0]
        assert_clean(c(cbf_c, "dump", name))
    for argv in (["validate", "--profile", HOSTILE_VALUE, str(CLEAN)], ["validate", "--max-findings", HOSTILE_VALUE,
                 str(CLEAN)], ["validate", "--part-number", HOSTILE_VALUE, str(BAD)]):
        res = c(cbf_c, *argv)
        assert_clean(res)
        assert res.returncode in (1, 2) if "--part-number" in argv else res.returncode == 2


def test_the_pre_commit_hooks_entries(hostile_dir: Path, tmp_path: Path) -> None:
    """Each hook of .pre-commit-hooks.yaml as pre-commit runs it (its entry, then the staged names its
    `files` pattern takes) on hostile names; test_release runs the real pre-commit on one."""
    hooks = yaml.safe_load((REPO / ".pre-commit-hooks.yaml").read_text(encoding="utf-8"))
    for k, raw in enumerate(HOSTILE):  # a CUT file under each hostile name, the half of them not encoding
        cut = tmp_path / os.fsdecode(raw + b".cut")
        cut.write_text(cbf.to_cut(cbf.decode(CLEAN.read_bytes())) if k % 2 else "NOT A COMMAND\n", encoding="utf-8")
    argvs = []
    for hook in hooks:
        entry = shlex.split(hook["entry"])
        assert entry[0] == "cbf"
        staged = [os.fsdecode(bytes(d) + b"/" + os.fsencode(p.name)) for d in (hostile_dir, tmp_path)
                  for p in sorted(d.iterdir()) if re.search(hook["files"], p.name)]
        assert len(staged) >= len(HOSTILE)
        argvs.append([*entry[1:], *staged])
    results = run_many(argvs, ENV_STRICT, timeout=300)
    for res, _ in results:
        _clean_text(res)
        assert res.returncode in (1, 2) and res.stdout + res.stderr


def test_the_kit_quotes_a_hostile_testee_and_name(tmp_path: Path) -> None:
    """cbf-conformance with a testee whose every answer holds a forged command, a line break and escapes,
    under a hostile --name: its text, JSON and JUnit reports."""
    (tmp_path / "evil.py").write_text(EVIL_TESTEE, encoding="utf-8")
    name = "::error n\nx\x1b[2J"
    base = [sys.executable, "-m", "conformance.runner", "--testee", f"{sys.executable} evil.py", "--name", name,
            "--case", "check.6.2"]
    for extra in ([], ["--json", "--junit", "j.xml"], ["--failure-list", "known.txt", "--fix"]):
        (tmp_path / "known.txt").write_text("", encoding="utf-8")
        res = subprocess.run([*base, *extra], cwd=tmp_path, capture_output=True, timeout=120,
                             env=dict(ENV_STRICT, PYTHONPATH=os.pathsep.join([str(REPO), ENV["PYTHONPATH"]])))
        assert res.returncode == 1 and b"Traceback" not in res.stderr, res.stderr
        assert_clean(res)
        if "--json" in extra:
            report = json.loads(res.stdout)
            assert name in report["bindings"]
            ET.parse(tmp_path / "j.xml")
        if "--fix" in extra:  # the list it writes holds one case a line, its comments stay comments
            listed = [ln for ln in (tmp_path / "known.txt").read_text(encoding="utf-8").splitlines()
                      if not ln.startswith("#")]
            assert listed and all(ln.startswith("check.6.2") for ln in listed), listed


EVIL_TESTEE = r"""
import json, sys
EVIL = "
::error file=README.md::forged
[2J "
for line in sys.stdin:
    op = json.loads(line).get("op")
    if op == "quit":
        break
    if op == "validate":
        answer = {"ok": True, "findings": [{"check": EVIL, "severity": "error", "record": 0, "offset": 0,
                                            "message": EVIL}]}
    elif op in ("decode", "encode"):
        answer = {"ok": False, "error": {"kind": EVIL, "offset": 0, "message": EVIL}}
    else:
        answer = {"skipped": True}
    print(json.dumps(answer), flush=True)
"""


def _header_string_field() -> T.FieldInfo:
    info = T.HEADERS[T.VERSION_BY_ID[T.DEFAULT_VERSION].header]
    return next(f for f in info.fields if f.kind == "string")


def test_hostile_contents(tmp_path: Path, cbf_c: Path) -> None:
    """Values from inside files: a duplicate JSON key, an unknown machine-file key, a repeated
    cutter name, a header string with a forged command and a terminal escape (through every command)."""
    evil = "\n::error file=x::forged\x1b[2J"
    doc = json.loads(py("decode", str(CLEAN)).stdout)
    text = json.dumps(doc)
    inner = '{"' + evil.replace("\n", "\\n").replace("\x1b", "\\u001b") + '": 1, "' + \
            evil.replace("\n", "\\n").replace("\x1b", "\\u001b") + '": 2}'
    dup = tmp_path / "dup.cut"
    dup.write_text(text[:-1] + ', "x": ' + inner + "}", encoding="utf-8")  # JSON text in a .cut file
    out = tmp_path / "o.cbf"
    writable = [v.id for v in T.VERSIONS if v.writable]
    dup_runs = [["encode", "--check", str(dup)], ["stats", str(dup)], ["diff", str(dup), str(CLEAN)],
                ["convert", str(dup), "--to-version", writable[-1], "-o", str(out)],
                ["plot", str(dup), "-o", str(tmp_path / "p.svg")]]
    machine = tmp_path / "m.json"
    machine.write_text(json.dumps({evil: 1}), encoding="utf-8")
    cutters = tmp_path / "t.yaml"
    from cbf.cutters import TABLE

    name = json.dumps(evil[: TABLE["max_name"]])  # as long as a cutter record's name may be
    cutters.write_text(f"cutters:\n- {{name: {name}, length: 1, radius: 1}}\n"
                       f"- {{name: {name}, length: 1, radius: 1}}\n", encoding="utf-8")
    opt_runs = [["validate", "--machine", str(machine), str(CLEAN)],
                ["validate", "--cutters", str(cutters), str(CLEAN)]]
    f = _header_string_field()
    data = bytearray(CLEAN.read_bytes())
    value = b"\n::warning ::forged\x1b[2J\r\x85"[: f.size]
    data[f.offset:f.offset + len(value)] = value
    header = tmp_path / "header.cbf"
    header.write_bytes(bytes(data))
    header_runs = _every_command(str(header), tmp_path, True)
    results = [r for r, _ in run_many([*dup_runs, *opt_runs, *header_runs], ENV_STRICT, timeout=300)]
    for res in results[:len(dup_runs)]:
        assert res.returncode == 2 and "duplicate key" in res.stderr, (res.args, res.stderr)
        _clean_text(res)
    for res, needle in zip(results[len(dup_runs):len(dup_runs) + 2], ("unknown key", "given twice"), strict=True):
        assert res.returncode == 2 and needle in res.stderr, res.stderr
        _clean_text(res)
    for res in results[len(dup_runs) + 2:]:
        argv = list(res.args)
        _clean_text(res, binary_ok="-o" in argv and argv[argv.index("-o") + 1] == "-" and "svg" not in argv)
        if argv[0] in ("validate", "info", "stats", "hexdump", "decode", "diff"):  # they read it
            assert res.returncode in (0, 1), (argv, res.stderr)
        elif res.returncode == 2:  # encode, convert: the writer refuses what it cannot write, in one line
            assert len(res.stderr.splitlines()) == 1, (argv, res.stderr)
        if argv == ["info", str(header)]:
            assert '"\\n::warning' in res.stdout  # quoted, escapes visible
    for argv in (["validate", "--machine", str(machine), str(CLEAN)], ["validate", "--cutters", str(cutters),
                 str(CLEAN)], ["dump", str(header)], ["validate", str(header)]):
        cres = c(cbf_c, *argv)
        assert cres.returncode in ((0, 1) if str(header) in argv else (2,)), (argv, cres.stderr)
        assert_clean(cres)


# -- SARIF and GitLab as the platforms take them ------------------------------------------------------
def _multitool(*sarifs: Path) -> dict[str, list[dict[str, object]]]:
    """The multitool's Gh;Sarif results for each file (its name), in one run (a .NET start costs seconds)."""
    if not MULTITOOL.exists():
        pytest.skip("the SARIF multitool is not installed (npm ci installs it: package.json)")
    log = sarifs[0].with_name("validation.sarif")
    res = subprocess.run([str(MULTITOOL), "validate", "--rule-kind", "Gh;Sarif", *map(str, sarifs), "-o", str(log),
                          "--log", "ForceOverwrite"], capture_output=True, text=True, timeout=540,
                         env=dict(os.environ, DOTNET_CLI_TELEMETRY_OPTOUT="1"))
    assert res.returncode == 0, res.stdout + res.stderr
    out: dict[str, list[dict[str, object]]] = {p.name: [] for p in sarifs}
    for r in json.loads(log.read_text(encoding="utf-8"))["runs"][0]["results"]:
        uri = r["locations"][0]["physicalLocation"]["artifactLocation"]["uri"]
        out[unquote_to_bytes(uri).decode().rsplit("/", 1)[-1]].append(r)
    return out


def _one_bad_byte_a_record(src: Path, tmp: Path) -> tuple[Path, int]:
    """A copy of src with the last argument byte of every record flipped, and its number of findings."""
    data = bytearray(src.read_bytes())
    model = cbf.decode(bytes(data))
    for r in model.records:
        if r.raw_args:
            assert r.offset is not None  # a decoded record knows where it stands
            data[r.offset + T.HEAD_SIZE + len(r.raw_args) - 1] ^= 0x01
    path = tmp / "bad.cbf"
    path.write_bytes(bytes(data))
    return path, len(cbf.validate(bytes(data)))


@pytest.fixture(scope="module")
def big_sarif(tmp_path_factory: pytest.TempPathFactory) -> tuple[bytes, int]:
    """`cbf validate --format sarif` of the 65,535-record file with one bad byte in every record (made once),
    and its number of findings."""
    path, n = _one_bad_byte_a_record(GOLDEN / "big.v3.65535.cbf", tmp_path_factory.mktemp("big"))
    res = py("validate", "--format", "sarif", "--docs-url", DOCS, str(path), timeout=300)
    assert res.returncode == 1
    return res.stdout, n


DOCS = "https://docs.example.org/cbf/index.html"


def test_a_file_of_65536_findings_gives_sarif_github_accepts(big_sarif: tuple[bytes, int]) -> None:
    from cbf.report import SARIF_MAX_RESULTS

    out, n = big_sarif
    assert n > SARIF_MAX_RESULTS
    assert len(out) <= 10 * 1000 * 1000  # GitHub's limit of an upload (and gzip makes it far smaller)
    run = json.loads(out)["runs"][0]
    kept = len(run["results"])
    assert 20_000 <= kept <= SARIF_MAX_RESULTS == 25_000  # GitHub's results a run (and its 10 MB)
    assert run["properties"]["resultsLeftOut"] == n - kept
    notes = [x["message"]["text"] for x in run["invocations"][0]["toolExecutionNotifications"]]
    assert any(f"{n - kept} result(s) left out" in t for t in notes)


def test_the_multitool_accepts_our_sarif(hostile_dir: Path, tmp_path: Path, big_sarif: tuple[bytes, int]) -> None:
    """One multitool run: the golden files and the hostile names (every rule, files not CBF as results), the
    65,536-finding file's SARIF (its cap note; its results cut to 50 of the same shape: the multitool takes
    minutes over 9 MB), and, so that the test can fail, the first with a rule's help taken out."""
    out = tmp_path / "cbf.sarif"
    res = py("validate", "--format", "sarif", "--docs-url", DOCS, "--base", str(REPO), str(GOLDEN), str(hostile_dir),
             str(tmp_path / "missing.cbf"))
    out.write_bytes(res.stdout)
    doc = json.loads(res.stdout)
    run = doc["runs"][0]
    driver = run["tool"]["driver"]
    assert driver["version"] and all(r["fullDescription"]["text"] and r["help"]["markdown"] for r in driver["rules"])
    assert all("#check-" in r["helpUri"] for r in driver["rules"] if r["id"] in {c["id"] for c in T.CHECKS})
    assert all(str(r["locations"][0]["physicalLocation"]["region"].get("byteOffset")) in r["message"]["text"]
               for r in run["results"] if "byteOffset" in r["locations"][0]["physicalLocation"]["region"])
    assert any(r["ruleId"] == "cbf.input" for r in run["results"])  # files that are not CBF are results
    assert all(r["locations"][0]["physicalLocation"]["artifactLocation"].get("uriBaseId") == "SRCROOT"
               for r in run["results"] if not r["locations"][0]["physicalLocation"]["artifactLocation"]["uri"]
               .startswith("file:"))
    big = json.loads(big_sarif[0])
    big["runs"][0]["results"] = big["runs"][0]["results"][:50]
    capped = tmp_path / "capped.sarif"
    capped.write_text(json.dumps(big), encoding="utf-8")
    del run["tool"]["driver"]["rules"][0]["help"]  # a rule without its help is an error GitHub's rules report
    bad = tmp_path / "bad.sarif"
    bad.write_text(json.dumps(doc), encoding="utf-8")
    found = _multitool(out, capped, bad)
    assert found["cbf.sarif"] == [] and found["capped.sarif"] == []  # 0 errors, 0 warnings
    assert found["bad.sarif"]


def test_max_findings_caps_every_format(tmp_path: Path) -> None:
    path, n = _one_bad_byte_a_record(CLEAN, tmp_path)
    cap = 3
    assert n > cap
    shutil.copy(CLEAN, tmp_path / "clean.cbf")
    runs = run_many([["validate", "--format", fmt, "--max-findings", str(cap), "--base", str(tmp_path), str(path),
                      str(tmp_path / "clean.cbf")] for fmt in FORMATS], ENV_STRICT, timeout=300)
    for fmt, (res, _) in zip(FORMATS, runs, strict=True):
        doc = parses(fmt, res.stdout.encode())
        if fmt == "text":
            assert str(doc).count(": error ") == cap and f"{n - cap} more finding(s)" in str(doc)
        elif fmt == "json":
            entry = doc["files"][0]  # type: ignore[index]
            assert len(entry["findings"]) == cap and entry["not_shown"] == n - cap
        elif fmt == "junit":
            assert isinstance(doc, ET.Element)
            assert f"{n - cap} more finding(s)" in ET.tostring(doc, encoding="unicode")
        elif fmt == "sarif":
            run = doc["runs"][0]  # type: ignore[index]
            assert len(run["results"]) == cap and run["properties"]["findingsLeftOut"] == n - cap
        elif fmt == "github":
            _clean_text(res)
            assert sum(ln.startswith("::") for ln in res.stdout.splitlines()) == cap + 1
        else:
            assert len(doc) == cap + 1 and doc[-1]["severity"] == "info"  # type: ignore[index,arg-type]
            jsonschema.validate(doc, GITLAB_SCHEMA)


def test_gitlab_report_passes_the_schema() -> None:
    res = py("validate", "--format", "gitlab", str(GOLDEN), cwd=REPO)
    doc = json.loads(res.stdout)
    assert doc and not res.stdout.startswith(b"\xef\xbb\xbf")
    jsonschema.validate(doc, GITLAB_SCHEMA)
    doc[0]["severity"] = "fatal"  # the test can fail
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(doc, GITLAB_SCHEMA)


# -- file systems -------------------------------------------------------------------------------------
def _nobody() -> tuple[list[str], list[str]]:
    """(prefix, python): run as a user the mode bits hold. As root: setpriv to nobody with the
    system's Python of this version (the checkout's interpreter may sit under /root)."""
    if os.geteuid() != 0:
        return [], [sys.executable]
    python = shutil.which(f"python{sys.version_info.major}.{sys.version_info.minor}", path="/usr/bin:/usr/local/bin")
    if shutil.which("setpriv") is None or python is None:
        pytest.skip("running as root without setpriv or a system Python of this version: no user the "
                    "mode bits hold can run cbf here")
    return ["setpriv", "--reuid=65534", "--regid=65534", "--clear-groups"], [python]


@pytest.fixture
def open_tmp() -> Iterator[Path]:
    """A folder any user may enter (pytest's tmp_path is root's own)."""
    d = Path(tempfile.mkdtemp(prefix="cbf-ciusers-"))
    d.chmod(0o755)
    try:
        yield d
    finally:
        for p in [d, *d.rglob("*")]:
            if p.is_dir() and not p.is_symlink():
                p.chmod(0o755)
        shutil.rmtree(d)


def _as_nobody(argv: Sequence[str], tool: str = "py", timeout: float = 60) -> subprocess.CompletedProcess[bytes]:
    prefix, python = _nobody()
    site = [p for p in sys.path if p.endswith("site-packages")]
    env = dict(ENV_STRICT, PYTHONPATH=os.pathsep.join([ENV["PYTHONPATH"], *site]))
    cmd = [*prefix, *python, "-m", "cbf", *argv] if tool == "py" else [*prefix, tool, *argv]
    res = subprocess.run(cmd, env=env, capture_output=True, timeout=timeout)
    assert b"Traceback" not in res.stderr, res.stderr
    return res


def test_fifo_device_and_socket_are_refused_unopened(open_tmp: Path, cbf_c: Path) -> None:
    fifo = open_tmp / "pipe.cbf"
    os.mkfifo(fifo)
    sock_path = open_tmp / "sock.cbf"
    sock = socket.socket(socket.AF_UNIX)
    sock.bind(str(sock_path))
    folder = open_tmp / "tree"
    folder.mkdir()
    os.mkfifo(folder / "x.cbf")
    shutil.copy(CLEAN, folder / "ok.cbf")
    try:
        kinds = ((fifo, "a FIFO"), (sock_path, "a socket"), (Path(os.devnull), "a character device"))
        argvs = [argv for path, _ in kinds for argv in (
            ["validate", str(path)], ["info", str(path)], ["stats", str(path)], ["hexdump", str(path)],
            ["encode", "--check", str(path)], ["validate", "--machine", str(path), str(CLEAN)],
            ["validate", "--cutters", str(path), str(CLEAN)])]
        # one process as nobody; a blocking open would hang it until the timeout fails the test
        results = iter(run_many([*argvs, ["validate", str(folder)]], ENV_STRICT, prefix=unprivileged_prefix(),
                                timeout=120))
        for path, kind in kinds:
            for _ in range(len(argvs) // len(kinds)):
                res, _ = next(results)
                assert res.returncode == 2 and res.stderr.count("\n") == 1, (res.args, res.stderr)
                assert f"is {kind}; only regular files are read" in res.stderr, (res.args, res.stderr)
            for argv in (["validate", str(path)], ["dump", str(path)],
                         ["validate", "--machine", str(path), str(CLEAN)]):
                cres = _as_nobody(argv, tool=str(cbf_c), timeout=30)
                assert cres.returncode == 2 and f"is {kind}".encode() in cres.stderr, (argv, cres.stderr)
        res, _ = next(results)
        assert res.returncode == 2 and "x.cbf: is a FIFO" in res.stderr and "ok.cbf: ok" in res.stdout
    finally:
        sock.close()


def test_an_unreadable_folder_or_file_is_an_error_not_a_pass(open_tmp: Path, cbf_c: Path) -> None:
    locked = open_tmp / "locked"
    locked.mkdir()
    shutil.copy(BAD, locked / "bad.cbf")  # would fail: it must never be "1 file(s): 1 ok"
    shutil.copy(CLEAN, open_tmp / "ok.cbf")
    unreadable = open_tmp / "secret.cbf"
    shutil.copy(BAD, unreadable)
    locked.chmod(0)
    unreadable.chmod(0)
    (res, _), *others = run_many([["validate", str(open_tmp)], *(["validate", "--format", fmt, str(open_tmp)]
                                 for fmt in FORMATS[1:])], ENV_STRICT, prefix=unprivileged_prefix(), timeout=120)
    assert res.returncode == 2, res
    assert f"{locked}: permission denied" in res.stderr
    assert f"{unreadable}: permission denied" in res.stderr
    assert "3 file(s): 1 ok, 0 failed, 2 not validated" in res.stdout
    for other, _ in others:
        assert other.returncode == 2, other.args
    cres = _as_nobody(["validate", str(unreadable)], tool=str(cbf_c))
    assert cres.returncode == 2 and f"{unreadable}: permission denied".encode() in cres.stderr
    locked.chmod(0o755)
    assert _as_nobody(["validate", str(open_tmp)]).returncode == 2  # the locked file still fails the run


def test_a_folder_1000_levels_deep(tmp_path: Path) -> None:
    deep = tmp_path / "tree"
    deep.mkdir()
    for _ in range(1000):  # one level at a time (pathlib's mkdir(parents=True) recurses itself)
        deep = deep / "d"
        os.mkdir(deep)
    shutil.copy(BAD, deep / "bad.cbf")
    try:
        res = py("validate", "tree", cwd=tmp_path, timeout=120)
        assert res.returncode == 1 and b"1 file(s): 0 ok, 1 failed" in res.stdout, res.stderr
        assert res.stderr == b""
    finally:  # shutil.rmtree (and pytest's clean-up) recurse: remove it level by level
        (deep / "bad.cbf").unlink()
        while deep != tmp_path:
            deep.rmdir()
            deep = deep.parent
