"""`cbf-c encode` warns as `cbf encode` does for a record the written version deprecates (cli.py,
_warn_deprecated: one line a record on stderr, at most ten and then one line counting the rest, after
the file is written, exit status unchanged): the same lines, the tool's name aside, the same bytes
written and the same exit status.

Today's spec deprecates nothing, so the tools are compared on a revision that does: the revision drill's
deprecation fixture (tests/revisions/deprecation.yaml) applied to a copy of spec/cbf.yaml in a temporary
folder, the Python and C bindings generated from it there (`cbfgen --spec X --out Y`) and cbf-c compiled
from that C. Its golden case (assembled for the revised spec) is the file holding the deprecated record;
its expectation names the record and the profiles. When the fixture does not apply to the spec (its
command has left the model), the test deprecates a command a golden file holds instead (a revision is a
spec edit only); that path is run too, so that it keeps working. The CUT texts are the ones the revised
`cbf decode --to cut` writes for the file, once as written and once with the deprecated record's line
repeated past the most the writers name one by one."""

from __future__ import annotations

import shutil
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest
import yaml
from conftest import REPO, cbfgen_here
from revisions import drill

from cbf import codec
from cbf import tables as T
from conformance.assembler import assemble_text

SPEC = REPO / "spec" / "cbf.yaml"
GOLDEN = REPO / "conformance" / "golden"
FIXTURE = REPO / "tests" / "revisions" / "deprecation.yaml"
FALLBACK_FILE = GOLDEN / "valid.v3.small.cbf"  # a valid file of a writable version: the fallback's records
REPEAT = 12  # copies of the deprecated record's line: more than the writers name one by one (ten)

pytestmark = pytest.mark.skipif(shutil.which("gcc") is None, reason="no C compiler")


@dataclass(frozen=True)
class Revision:
    spec: Path  # the revised spec
    data: bytes  # a file of it holding a deprecated record
    found: dict[str, list[int]]  # profile -> the records a deprecation check finds in data under it
    check: str  # the deprecation check's id


def _fixture(tmp: Path) -> Revision:
    """The drill fixture applied (drill.FixtureError when it does not apply to this spec)."""
    fx = drill.load_fixture(FIXTURE, drill.read_spec(SPEC))
    path = drill.revised_spec(fx, SPEC, tmp)
    (check,) = [c["id"] for c in drill.read_spec(path)["checks"] if c["kind"] == "deprecated"
                and c["id"] not in {x["id"] for x in T.checks_of("deprecated")}]
    name = next(n for n in fx.files if n.endswith(".hex"))
    data = assemble_text(fx.files[name], name, base=GOLDEN, spec=path)
    expect = yaml.safe_load(fx.files[name.removesuffix(".hex") + ".expect.yaml"])
    found = {p: [int(f[2]) for f in fs if str(f[0]) == check] for p, fs in expect["validate"].items()}
    return Revision(path, data, found, check)


def _from_model(tmp: Path) -> Revision:
    """A deprecation the model can make: the first command of FALLBACK_FILE that nothing deprecates yet,
    deprecated since the file's version (a new check citing a new clause, as the fixture adds one)."""
    doc = drill.read_spec(SPEC)
    data = FALLBACK_FILE.read_bytes()
    model = codec.decode(data)
    taken = {n.split("/")[0] for c in T.checks_of("deprecated") for n in c["deprecates"]}
    name = next(r.command.name for r in model.records if r.command.name not in taken)
    clause = drill.variables(doc)["free_clause"]
    drill.apply_edit(doc, {"op": "add_clause", "value": {"number": clause, "text": f"{name} deprecated (a test)."}})
    drill.apply_edit(doc, {"op": "append", "path": "checks", "value": {
        "id": clause, "kind": "deprecated", "severity": "warning", "clause": clause, "since": model.version_id,
        "deprecates": [name], "text": f"{name} is deprecated.", "fails": f"A {name} record."}})
    tmp.mkdir(parents=True, exist_ok=True)
    path = tmp / "cbf.yaml"
    path.write_text(yaml.safe_dump(doc, sort_keys=False), encoding="utf-8")
    found = [i for i, r in enumerate(model.records) if r.command.name == name]
    return Revision(path, data, {p: found for p in T.PROFILES}, clause)


def _revision(source: str, tmp: Path) -> Revision:
    if source == "fixture":
        try:
            return _fixture(tmp)
        except drill.FixtureError:  # the fixture's command or layout is gone from the model: the model's own
            pass
    return _from_model(tmp)


@dataclass(frozen=True)
class Tools:
    rev: Revision
    python: Path  # the revised Python binding's folder (PYTHONPATH)
    cbf_c: Path


def _built(source: str, tmp: Path) -> Tools:
    rev = _revision(source, tmp / "spec")
    gen = tmp / "gen"
    for only in ("python", "c"):
        code, _, err = cbfgen_here("--spec", str(rev.spec), "--out", str(gen), "--only", only, "--no-ksc")
        assert code == 0, err[-3000:]
    tool = tmp / "cbf-c"
    done = subprocess.run(["gcc", "-std=c99", "-O0", "-o", str(tool), str(gen / "c" / "cbf_tool.c"), "-lm"],
                          capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stderr
    return Tools(rev, gen / "python", tool)


@pytest.fixture(scope="module", params=["fixture", "model"])
def tools(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Tools:
    return _built(str(request.param), tmp_path_factory.mktemp(f"deprecation_{request.param}"))


def _run(tools: Tools, tool: str, argv: list[str], cwd: Path) -> subprocess.CompletedProcess[bytes]:
    exe = [str(tools.cbf_c)] if tool == "cbf-c" else [sys.executable, "-m", "cbf"]
    env = {"PYTHONPATH": str(tools.python), "PATH": "/usr/bin:/bin", "LC_ALL": "C.UTF-8"}
    return subprocess.run([*exe, *argv], cwd=cwd, env=env, capture_output=True, timeout=120, check=False)


def _lines(res: subprocess.CompletedProcess[bytes], tool: str) -> list[str]:
    """The lines on stderr, each without the tool's name (each must start with it)."""
    out = []
    for line in res.stderr.decode("utf-8").splitlines():
        assert line.startswith(f"{tool}: "), (tool, line)
        out.append(line[len(tool) + 2:])
    return out


def _cut_texts(tools: Tools, profile: str, tmp: Path) -> dict[str, bytes]:
    """The revised cbf's CUT text of the file under profile, and that text with the first deprecated
    record's line repeated REPEAT times (the record lines are the lines that are no header line)."""
    src = tmp / "in.cbf"
    src.write_bytes(tools.rev.data)
    res = _run(tools, "cbf", ["decode", src.name, "--to", "cut", "--profile", profile, "-o", "in.cut"], tmp)
    assert res.returncode == 0, res.stderr
    text = (tmp / "in.cut").read_bytes()
    cut, ext = T.CUT, T.CUT["extensions"]
    fold = bytes.lower if cut["keyword_case"] == "lower" else bytes
    heads = {fold(str(k).encode()) for k in (cut["header_keyword"], cut["header_ext_keyword"],
                                             cut["checksum_keyword"], ext["version_keyword"],
                                             ext["field_keyword"])}
    lines = text.splitlines(keepends=True)
    records = [i for i, ln in enumerate(lines) if ln.strip() and fold(ln.split()[0]) not in heads]
    at = records[tools.rev.found[profile][0]]
    repeated = b"".join([*lines[:at], *[lines[at]] * REPEAT, *lines[at + 1:]])
    return {"once": text, "repeated": repeated}


def _compare(tools: Tools, argv: list[str], cwd: Path, written: str | None) -> dict[str, Any]:
    """Both tools on argv: the same exit status, stdout, stderr lines and file written; cbf's answer."""
    got = {}
    for tool in ("cbf", "cbf-c"):
        if written is not None:
            (cwd / written).unlink(missing_ok=True)
        res = _run(tools, tool, argv, cwd)
        out = (cwd / written).read_bytes() if written is not None and (cwd / written).exists() else None
        got[tool] = {"status": res.returncode, "stdout": res.stdout, "stderr": _lines(res, tool), "file": out}
    assert got["cbf-c"] == got["cbf"], argv
    return got["cbf"]


def test_cbf_c_encode_warns_as_cbf_encode_for_a_deprecated_record(tools: Tools, tmp_path: Path) -> None:
    warned = 0
    for profile, records in sorted(tools.rev.found.items()):
        if not records:  # no deprecation under this profile: nothing to compare but the bytes
            continue
        work = tmp_path / profile
        work.mkdir()
        for name, text in _cut_texts(tools, profile, work).items():
            (work / f"{name}.cut").write_bytes(text)
            to_file = _compare(tools, ["encode", "--profile", profile, f"{name}.cut", "-o", "out.cbf"], work,
                               "out.cbf")
            to_stdout = _compare(tools, ["encode", "--profile", profile, f"{name}.cut", "-o", "-"], work, None)
            checked = _compare(tools, ["encode", "--check", "--profile", profile, f"{name}.cut"], work, None)
            assert checked["stderr"] == [] or checked["status"] != 0  # --check writes nothing: no warning
            if to_file["status"] == 0:
                assert to_stdout["stdout"] == to_file["file"]
                lines = [ln for ln in to_file["stderr"] if ln.startswith("warning: ")]
                assert lines and all(f"check {tools.rev.check}" in ln or "more" in ln for ln in lines), lines
                assert len(lines) > 1 or name == "once", lines  # the repeated records: more than one line
                warned += 1
    assert warned, f"no profile encodes the deprecated record: {tools.rev.found}"
