"""CI users, round 3 (issue #35, points 1-4): output no input can forge, reports GitHub and GitLab
accept, names that always encode, file systems that bite.

1. Hostile file names (a forged ``::error`` workflow command, line feeds, carriage returns, bytes
   that are not UTF-8, terminal escapes, U+2028) and hostile contents (a duplicate JSON key, an
   unknown machine-file key, a repeated cutter, a header string holding escapes) go through every
   command and every --format of both tools: no output line starts with ``::`` (but the github
   format's own commands, one per finding), none carries an input's line break, every output is
   UTF-8 and parses (JSON, XML, SVG). Both tools print the same quoted name (one rule).
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

import json
import os
import re
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
from c_programs import built
from conftest import ENV, REPO

import cbf
from cbf import tables as T
from cbf.quoting import quote, unquote

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


def test_the_kit_carries_the_same_rule() -> None:
    """The conformance kit installs without the codec: it ships its own copy of the one rule."""
    rule = REPO / "generator" / "cbfgen" / "emit" / "python" / "runtime" / "quoting.py"
    assert (REPO / "conformance" / "runner" / "quoting.py").read_bytes() == rule.read_bytes()


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
    names = _names(hostile_dir)
    found = {n: len(cbf.validate((hostile_dir / os.fsdecode(n)).read_bytes())) for n in names if b" not" not in n}
    for args in (["."], [os.fsdecode(n) for n in names]):  # a folder (./NAME), and each name as given
        res = py("validate", "--format", fmt, "--max-findings", "0", *args, cwd=hostile_dir)
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


def test_one_hostile_name_alone_streams_quoted(hostile_dir: Path) -> None:
    for name in _names(hostile_dir):
        for fmt in ("text", "json"):
            res = py("validate", "--format", fmt, os.fsdecode(name), cwd=hostile_dir)
            assert_clean(res)
            if fmt == "json" and res.returncode != 2:
                assert unquote(json.loads(res.stdout)["file"]) == name


def test_both_tools_print_the_same_quoted_name(hostile_dir: Path, cbf_c: Path) -> None:
    for name in _names(hostile_dir):
        a, b = py("validate", os.fsdecode(name), cwd=hostile_dir), c(cbf_c, "validate", name, cwd=hostile_dir)
        assert_clean(b)
        assert a.returncode == b.returncode
        assert a.stdout == b.stdout, (name, a.stdout, b.stdout)
        assert a.stderr.replace(b"cbf: ", b"", 1).split(b":")[0] == b.stderr.replace(b"cbf-c: ", b"", 1).split(b":")[0]
        d = c(cbf_c, "dump", name, cwd=hostile_dir)
        assert_clean(d)


def _tool_runs(name: str, tmp: Path) -> Iterator[tuple[str, ...]]:
    out = tmp / "out"
    out.mkdir(exist_ok=True)
    writable = [v.id for v in T.VERSIONS if v.writable]
    yield "info", name
    yield "info", "--json", name
    yield "decode", name
    yield "decode", "--to", "cut", name, "-o", str(out / "x.cut")
    yield "convert", name, "--to-version", writable[-1], "-o", str(out / "c.cbf")
    yield "stats", name
    yield "stats", "--json", name
    yield "diff", name, name
    yield "diff", "--json", name, name
    yield "plot", name, "-o", str(out / "p.svg")


def test_hostile_names_in_every_other_command(hostile_dir: Path, tmp_path: Path) -> None:
    # the worst three (a forged command, a line feed, bytes that are not UTF-8), one clean and two with findings
    worst = [n for n in _names(hostile_dir) if n.startswith((HOSTILE[0] + b".", HOSTILE[1][:2], HOSTILE[3][:2]))]
    assert len(worst) == 3
    for k, raw in enumerate(worst):
        name = os.fsdecode(raw)
        for argv in _tool_runs(name, tmp_path):
            if k and argv[0] not in ("info", "stats"):
                continue  # every command for one name, the readers for the others (each run starts Python)
            res = py(*argv, cwd=hostile_dir)
            assert_clean(res)
            if "--json" in argv and res.returncode == 0:
                doc = json.loads(res.stdout)
                assert raw in {unquote(doc.get(k, "")) for k in ("file", "a")}
            if argv[0] == "plot" and res.returncode == 0:
                ET.parse(tmp_path / "out" / "p.svg")  # the title (the name) leaves the SVG well-formed
        cut = Path(os.fsdecode(bytes(tmp_path) + b"/" + raw + b".cut"))
        cut.write_text("NOT A COMMAND\n", encoding="utf-8")
        for argv in (("encode", "--check", str(cut)), ("encode", str(cut), "-o", str(tmp_path / "e.cbf"))):
            res = py(*argv)
            assert res.returncode == 2 and res.stderr.count(b"\n") == 1
            assert_clean(res)


def _header_string_field() -> T.FieldInfo:
    info = T.HEADERS[T.VERSION_BY_ID[T.DEFAULT_VERSION].header]
    return next(f for f in info.fields if f.kind == "string")


def test_hostile_contents(tmp_path: Path, cbf_c: Path) -> None:
    """Values from inside files: a duplicate JSON key, an unknown machine-file key, a repeated
    cutter name, a header string with a forged command and a terminal escape."""
    evil = "\n::error file=x::forged\x1b[2J"
    doc = json.loads(py("decode", str(CLEAN)).stdout)
    text = json.dumps(doc)
    inner = '{"' + evil.replace("\n", "\\n").replace("\x1b", "\\u001b") + '": 1, "' + \
            evil.replace("\n", "\\n").replace("\x1b", "\\u001b") + '": 2}'
    dup = tmp_path / "dup.cut"
    dup.write_text(text[:-1] + ', "x": ' + inner + "}", encoding="utf-8")  # JSON text in a .cut file
    out = tmp_path / "o.cbf"
    writable = [v.id for v in T.VERSIONS if v.writable]
    for argv in (("encode", "--check", str(dup)), ("stats", str(dup)), ("diff", str(dup), str(CLEAN)),
                 ("convert", str(dup), "--to-version", writable[-1], "-o", str(out)),
                 ("plot", str(dup), "-o", str(tmp_path / "p.svg"))):
        res = py(*argv)
        assert res.returncode == 2, argv
        assert b"duplicate key" in res.stderr, (argv, res.stderr)
        assert_clean(res)
    machine = tmp_path / "m.json"
    machine.write_text(json.dumps({evil: 1}), encoding="utf-8")
    cutters = tmp_path / "t.yaml"
    from cbf.cutters import TABLE

    name = json.dumps(evil[: TABLE["max_name"]])  # as long as a cutter record's name may be
    cutters.write_text(f"cutters:\n- {{name: {name}, length: 1, radius: 1}}\n"
                       f"- {{name: {name}, length: 1, radius: 1}}\n", encoding="utf-8")
    for opt, path, needle in (("--machine", machine, b"unknown key"), ("--cutters", cutters, b"given twice")):
        for res in (py("validate", opt, str(path), str(CLEAN)), c(cbf_c, "validate", opt, str(path), str(CLEAN))):
            assert res.returncode == 2 and needle in res.stderr, res.stderr
            assert_clean(res)
    f = _header_string_field()
    data = bytearray(CLEAN.read_bytes())
    value = b"\n::warning ::forged\x1b[2J\r\x85"[: f.size]
    data[f.offset:f.offset + len(value)] = value
    header = tmp_path / "header.cbf"
    header.write_bytes(bytes(data))
    for res in (py("info", str(header)), py("info", "--json", str(header)), py("validate", str(header)),
                py("validate", "--format", "junit", str(header), str(CLEAN)), c(cbf_c, "dump", str(header)),
                c(cbf_c, "validate", str(header))):
        assert res.returncode in (0, 1), res
        assert_clean(res)
    assert b'"\\n::warning' in py("info", str(header)).stdout  # quoted, escapes visible


# -- SARIF and GitLab as the platforms take them ------------------------------------------------------
def _multitool(sarif: Path) -> list[dict[str, object]]:
    if not MULTITOOL.exists():
        pytest.skip("the SARIF multitool is not installed (npm ci installs it: package.json)")
    log = sarif.with_suffix(".validation.sarif")
    res = subprocess.run([str(MULTITOOL), "validate", "--rule-kind", "Gh;Sarif", str(sarif), "-o", str(log),
                          "--log", "ForceOverwrite"], capture_output=True, text=True, timeout=540,
                         env=dict(os.environ, DOTNET_CLI_TELEMETRY_OPTOUT="1"))
    assert res.returncode == 0, res.stdout + res.stderr
    results: list[dict[str, object]] = json.loads(log.read_text(encoding="utf-8"))["runs"][0]["results"]
    return results


def test_the_multitool_accepts_our_sarif(hostile_dir: Path, tmp_path: Path) -> None:
    out = tmp_path / "cbf.sarif"
    res = py("validate", "--format", "sarif", "--docs-url", "https://docs.example.org/cbf/index.html",
             "--base", str(REPO), str(GOLDEN), str(hostile_dir), str(tmp_path / "missing.cbf"))
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
    assert _multitool(out) == []  # 0 errors, 0 warnings
    # the test can fail: a rule without its help is an error GitHub's rules report
    del run["tool"]["driver"]["rules"][0]["help"]
    bad = tmp_path / "bad.sarif"
    bad.write_text(json.dumps(doc), encoding="utf-8")
    assert _multitool(bad)


def _one_bad_byte_a_record(src: Path, tmp: Path) -> tuple[Path, int]:
    """A copy of src with the last argument byte of every record flipped, and its number of findings."""
    data = bytearray(src.read_bytes())
    model = cbf.decode(bytes(data))
    for r in model.records:
        if r.raw_args:
            data[r.offset + T.HEAD_SIZE + len(r.raw_args) - 1] ^= 0x01
    path = tmp / "bad.cbf"
    path.write_bytes(bytes(data))
    return path, len(cbf.validate(bytes(data)))


def test_a_file_of_65536_findings_gives_sarif_github_accepts(tmp_path: Path) -> None:
    from cbf.report import SARIF_MAX_RESULTS

    path, n = _one_bad_byte_a_record(GOLDEN / "big.v3.65535.cbf", tmp_path)
    assert n > SARIF_MAX_RESULTS
    res = py("validate", "--format", "sarif", str(path), timeout=300)
    assert res.returncode == 1
    assert len(res.stdout) <= 10 * 1000 * 1000  # GitHub's limit of an upload (and gzip makes it far smaller)
    run = json.loads(res.stdout)["runs"][0]
    kept = len(run["results"])
    assert 20_000 <= kept <= SARIF_MAX_RESULTS == 25_000  # GitHub's results a run (and its 10 MB)
    assert run["properties"]["resultsLeftOut"] == n - kept
    notes = [x["message"]["text"] for x in run["invocations"][0]["toolExecutionNotifications"]]
    assert any(f"{n - kept} result(s) left out" in t for t in notes)


def test_max_findings_caps_every_format(tmp_path: Path) -> None:
    path, n = _one_bad_byte_a_record(CLEAN, tmp_path)
    cap = 3
    assert n > cap
    shutil.copy(CLEAN, tmp_path / "clean.cbf")
    for fmt in FORMATS:
        res = py("validate", "--format", fmt, "--max-findings", str(cap), path.name, "clean.cbf", cwd=tmp_path)
        doc = parses(fmt, res.stdout)
        if fmt == "text":
            assert str(doc).count(": error ") == cap and f"{n - cap} more finding(s)" in str(doc)
        elif fmt == "json":
            entry = doc["files"][0]  # type: ignore[index]
            assert len(entry["findings"]) == cap and entry["not_shown"] == n - cap
        elif fmt == "junit":
            assert f"{n - cap} more finding(s)" in ET.tostring(doc, encoding="unicode")  # type: ignore[arg-type]
        elif fmt == "sarif":
            run = doc["runs"][0]  # type: ignore[index]
            assert len(run["results"]) == cap and run["properties"]["findingsLeftOut"] == n - cap
        elif fmt == "github":
            assert_clean(res, cap + 1)
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
        for path, kind in ((fifo, "a FIFO"), (sock_path, "a socket"), (Path(os.devnull), "a character device")):
            for argv in (["validate", str(path)], ["info", str(path)], ["stats", str(path)],
                         ["encode", "--check", str(path)], ["validate", "--machine", str(path), str(CLEAN)],
                         ["validate", "--cutters", str(path), str(CLEAN)]):
                res = _as_nobody(argv, timeout=30)  # a blocking open would hang until the timeout
                assert res.returncode == 2 and res.stderr.count(b"\n") == 1, (argv, res.stderr)
                assert f"is {kind}; only regular files are read".encode() in res.stderr, (argv, res.stderr)
            for argv in (["validate", str(path)], ["dump", str(path)],
                         ["validate", "--machine", str(path), str(CLEAN)]):
                res = _as_nobody(argv, tool=str(cbf_c), timeout=30)
                assert res.returncode == 2 and f"is {kind}".encode() in res.stderr, (argv, res.stderr)
        res = _as_nobody(["validate", str(folder)], timeout=30)
        assert res.returncode == 2 and b"x.cbf: is a FIFO" in res.stderr and b"ok.cbf: ok" in res.stdout
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
    res = _as_nobody(["validate", str(open_tmp)])
    assert res.returncode == 2, res
    assert f"{locked}: permission denied".encode() in res.stderr
    assert f"{unreadable}: permission denied".encode() in res.stderr
    assert b"3 file(s): 1 ok, 0 failed, 2 not validated" in res.stdout
    for fmt in ("json", "sarif", "junit", "gitlab", "github"):
        assert _as_nobody(["validate", "--format", fmt, str(open_tmp)]).returncode == 2
    res = _as_nobody(["validate", str(unreadable)], tool=str(cbf_c))
    assert res.returncode == 2 and f"{unreadable}: permission denied".encode() in res.stderr
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
