"""The conformance kit for anyone (issue 14): cbf-conformance, installed from its wheel into
a clean venv outside this repository, judges an outside testee, passes the reference C
testee, fails a broken one naming exactly the cases it breaks, and never hangs on a
testee that stops answering."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from conftest import clean_venv, load_yaml
from conftest import run_clean as _run

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"
C_TESTEE = REPO / "build" / "c" / "cbf_testee"
PY_TESTEE = REPO / "conformance" / "testees" / "python" / "testee.py"

# A testee that answers validate with no findings: every case expecting one must fail.
NO_FINDINGS = """
import json, sys
for line in sys.stdin:
    req = json.loads(line)
    if req.get("op") == "quit":
        break
    print(json.dumps({"ok": True, "findings": []} if req.get("op") == "validate" else {"skipped": True}), flush=True)
"""
# A testee that never answers.
SILENT = "import sys, time\nfor line in sys.stdin:\n    time.sleep(3600)\n"


@pytest.fixture(scope="module")
def wheels(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The kit's wheel and the cbf wheel, built once for the module (each build is a process of about
    1.5 CPU s; the tests only install them)."""
    work = tmp_path_factory.mktemp("wheels")
    _run(sys.executable, "-m", "conformance.kit", work / "stage", cwd=REPO)
    _run(sys.executable, "-m", "build", "--no-isolation", "--wheel", "--outdir", work / "dist", work / "stage",
         cwd=work)
    shutil.copytree(REPO / "generated" / "python", work / "cbf-src", ignore=shutil.ignore_patterns("__pycache__"))
    _run(sys.executable, "-m", "build", "--no-isolation", "--wheel", "--outdir", work / "dist", work / "cbf-src",
         cwd=work)
    return work / "dist"


@pytest.fixture(scope="module")
def kit(tmp_path_factory: pytest.TempPathFactory, wheels: Path) -> Path:
    """The cbf-conformance command of a clean venv that installed the kit's wheel."""
    work = tmp_path_factory.mktemp("kit")
    return clean_venv(work / "venv", next(wheels.glob("cbf_conformance-*.whl"))) / "cbf-conformance"


@pytest.fixture(scope="module")
def consumer(tmp_path_factory: pytest.TempPathFactory, wheels: Path) -> Path:
    """The bin/ of a consumer's clean venv that installed only the two wheels (the tests only run its
    commands, each in a folder of its own)."""
    return clean_venv(tmp_path_factory.mktemp("consumer") / "venv", *sorted(wheels.glob("*.whl")))


def _expected_validate_failures() -> set[str]:
    out = set()
    for exp in GOLDEN.glob("*.expect.yaml"):
        want = load_yaml(exp).get("validate") or {}
        if any(want.values()):
            out.add(exp.name[: -len(".expect.yaml")])
    return out


@pytest.mark.skipif(not C_TESTEE.exists(), reason="make c-build first")
def test_the_kit_passes_the_reference_c_testee(kit: Path, tmp_path: Path) -> None:
    res = _run(kit, "--testee", C_TESTEE, "--name", "c", "--failure-list", REPO / "conformance" / "failures" / "c.txt",
               "--junit", tmp_path / "j.xml", "--json", cwd=tmp_path, check=False)
    assert res.returncode == 0, res.stderr[-2000:]
    report = json.loads(res.stdout)
    cases = {p.name[: -len(".expect.yaml")] for p in GOLDEN.glob("*.expect.yaml")}
    assert set(report["bindings"]["c"]["results"]) == cases  # the shipped cases are all the cases
    suite = ET.parse(tmp_path / "j.xml").getroot().find("testsuite")
    assert suite is not None and suite.get("tests") == str(len(cases))


def test_the_kit_fails_a_broken_testee_with_the_right_cases(kit: Path, tmp_path: Path) -> None:
    (tmp_path / "broken.py").write_text(NO_FINDINGS, encoding="utf-8")
    res = _run(kit, "--testee", f"{sys.executable} broken.py", "--name", "broken", "--capabilities", "validate",
               "--junit", tmp_path / "j.xml", cwd=tmp_path, check=False)
    assert res.returncode == 1
    failed = {line.split(": ")[1] for line in res.stdout.splitlines() if line.startswith("broken: ")}
    assert failed == _expected_validate_failures()
    junit_failed = {tc.get("name") for tc in ET.parse(tmp_path / "j.xml").getroot().iter("testcase")
                    if tc.find("failure") is not None}
    assert junit_failed == failed


def test_a_silent_testee_times_out_instead_of_hanging(kit: Path, tmp_path: Path) -> None:
    (tmp_path / "silent.py").write_text(SILENT, encoding="utf-8")
    first = sorted(GOLDEN.glob("*.expect.yaml"))[0].name[: -len(".expect.yaml")]
    res = _run(kit, "--testee", f"{sys.executable} silent.py", "--case", first, "--timeout", "1",
               cwd=tmp_path, check=False)
    assert res.returncode == 1
    assert f"{first}: FAIL" in res.stdout and "gave no answer within 1 s" in res.stdout


def _one_line_2(res: subprocess.CompletedProcess[str]) -> str:
    assert res.returncode == 2, (res.returncode, res.stderr)
    assert "Traceback" not in res.stderr and len(res.stderr.strip().splitlines()) == 1, res.stderr
    return res.stderr.strip()


def test_usage_errors_exit_2(kit: Path, tmp_path: Path) -> None:
    assert "--testee" in _one_line_2(_run(kit, cwd=tmp_path, check=False))  # outside the repository, no --testee
    assert "no such program" in _one_line_2(_run(kit, "--testee", "no-such-reader-xyz", cwd=tmp_path, check=False))
    assert "no such file" in _one_line_2(_run(kit, "--testee", "./missing-testee", cwd=tmp_path, check=False))
    (tmp_path / "t.py").write_text(NO_FINDINGS, encoding="utf-8")
    testee = f"{sys.executable} t.py"
    line = _one_line_2(_run(kit, "--testee", testee, "--failure-list", "typo.txt", cwd=tmp_path, check=False))
    assert "typo.txt: no such file" in line
    (tmp_path / "locked.txt").write_bytes(b"\xff\xfe not text")
    assert "cannot read" in _one_line_2(_run(kit, "--testee", testee, "--failure-list", "locked.txt", cwd=tmp_path,
                                             check=False))
    assert "unrecognized arguments" in _one_line_2(_run(kit, "--testee", testee, "--no-such-option", cwd=tmp_path,
                                                        check=False))
    assert "--timeout" in _one_line_2(_run(kit, "--testee", testee, "--timeout", "soon", cwd=tmp_path, check=False))
    assert "does not exist" in _one_line_2(_run(kit, "--testee", testee, "--junit", "no/such/j.xml", cwd=tmp_path,
                                                check=False))


def test_help_version_and_what_ships(kit: Path, tmp_path: Path) -> None:
    help_text = " ".join(_run(kit, "--help", cwd=tmp_path).stdout.split())
    for internal in ("--bindings", "--python-path", "--report", "--failures ", "--binding ", "--golden"):
        assert internal not in help_text
    assert "--fix" in help_text and "cbf-conformance --testee CMD --failure-list" in help_text
    version = _run(kit, "--version", cwd=tmp_path).stdout.strip()
    import cbf.version as v

    assert version == f"cbf-conformance {v.__version__} (spec {v.SPEC_REVISION})"
    # PROTOCOL.md and every file it names ship in the package
    pkg = Path(_run(kit.parent / "python", "-c", "import cbf_conformance, os; print(os.path.dirname("
                    "cbf_conformance.__file__))", cwd=tmp_path).stdout.strip())
    protocol = (pkg / "PROTOCOL.md").read_text(encoding="utf-8")
    named = set(re.findall(r"[\w./-]+\.(?:json|yaml|md)\b", protocol)) - {"PROTOCOL.md"}
    named = {n for n in named if not n.startswith(("golden/", ".")) and "*" not in n}
    assert named >= {"machine.schema.json", "canonical.schema.json"}
    for name in named:
        assert (pkg / name).is_file(), name
    assert "spec/cbf.yaml" not in protocol and "generated/" not in protocol


# A third party's reader: the cbf wheel, with one check it does not implement (its findings dropped).
THIRD_PARTY = """
import json, sys
import cbf
DROP = sys.argv[1]
for line in sys.stdin:
    req = json.loads(line)
    if req.get("op") == "quit":
        break
    if req.get("op") != "validate":
        print(json.dumps({"skipped": True}), flush=True)
        continue
    data = open(req["file"], "rb").read()
    cutters = cbf.load_cutter_table(req["cutters"]) if req.get("cutters") else None
    try:
        machine = cbf.load_machine(req["machine"]) if req.get("machine") else None
    except cbf.CbfError as exc:
        print(json.dumps({"ok": False, "error": {"kind": exc.kind, "offset": None, "message": str(exc)}}), flush=True)
        continue
    found = cbf.validate(data, profile=req["profile"], part_number=req.get("part_number"), cutters=cutters,
                         machine=machine)
    print(json.dumps({"ok": True, "id": req["id"], "findings": [f.as_dict() for f in found if f.check != DROP]}),
          flush=True)
"""


def test_consumer_third_party_testee_with_a_failure_list(tmp_path_factory: pytest.TempPathFactory,
                                                          consumer: Path) -> None:
    """Only the wheels in a temporary folder: the kit judges a third-party testee with a failure
    list, and text, JSON and JUnit give the same pass / fail / expected-failure counts."""
    work = tmp_path_factory.mktemp("consumer")
    bin_ = consumer
    folder = work / "user"
    folder.mkdir()
    (folder / "reader.py").write_text(THIRD_PARTY, encoding="utf-8")
    # the check to drop: the one whose findings the most cases expect (several cases then fail)
    per_check: dict[str, set[str]] = {}
    for exp in GOLDEN.glob("*.expect.yaml"):
        for findings in (load_yaml(exp).get("validate") or {}).values():
            for f in findings or []:
                per_check.setdefault(str(f[0]), set()).add(exp.name[: -len(".expect.yaml")])
    drop = max(sorted(per_check), key=lambda c: len(per_check[c]))
    failing = sorted(per_check[drop])
    assert len(failing) >= 2
    testee = f"{bin_ / 'python'} reader.py {drop}"
    base: list[str | Path] = [bin_ / "cbf-conformance", "--testee", testee, "--name", "reader",
                              "--capabilities", "validate"]
    # --fix writes the list; then one listed case is dropped from it: that one fails, the rest are expected
    fixed = _run(*base, "--failure-list", "known.txt", "--fix", cwd=folder, check=False)
    assert "Traceback" not in fixed.stderr
    listed = [ln for ln in (folder / "known.txt").read_text().splitlines() if ln and not ln.startswith("#")]
    assert sorted(ln.split(" ")[0] for ln in listed) == failing
    # by reason (issue 37, point 3): each entry is its failure's class, no offset in it, and --fix showed the diff
    assert all(" validate: [" in ln and f"findings differ: missing {drop}/" in ln and "@" not in ln for ln in listed)
    assert all(f"+{ln}" in fixed.stdout for ln in listed), fixed.stdout[-2000:]
    assert "Rewrite with: cbf-conformance --testee" in (folder / "known.txt").read_text()
    (folder / "known.txt").write_text("# my reader's known failures\n" + "\n".join(listed[1:]) + "\n")
    text = _run(*base, "--failure-list", "known.txt", "--junit", "j.xml", cwd=folder, check=False)
    js = _run(*base, "--failure-list", "known.txt", "--json", cwd=folder, check=False)
    assert text.returncode == js.returncode == 1, text.stdout[-2000:] + text.stderr[-2000:]
    total = len(list(GOLDEN.glob("*.expect.yaml")))
    m = re.search(r"conformance: (\d+) passed, (\d+) failed, (\d+) expected failure\(s\), (\d+) skipped",
                  text.stdout)
    assert m, text.stdout
    from_text = tuple(int(x) for x in m.groups())
    want_fail, want_xfail = 1, len(failing) - 1
    assert from_text[1:3] == (want_fail, want_xfail)
    report = json.loads(js.stdout)
    summary = report["bindings"]["reader"]["summary"]
    from_json = (summary["passed"], summary["failed"], summary["expected_failures"], summary["skipped"])
    results = report["bindings"]["reader"]["results"]
    assert sum(r["expected_failure"] for r in results.values()) == want_xfail
    suite = ET.parse(folder / "j.xml").getroot().find("testsuite")
    assert suite is not None
    cases = suite.findall("testcase")
    xfail = [c for c in cases if (s := c.find("skipped")) is not None and s.get("type") == "expected-failure"]
    plain_skip = [c for c in cases if (s := c.find("skipped")) is not None and s.get("type") != "expected-failure"]
    fails = [c for c in cases if c.find("failure") is not None]
    from_junit = (len(cases) - len(xfail) - len(plain_skip) - len(fails), len(fails), len(xfail), len(plain_skip))
    assert from_text == from_json == from_junit
    assert sum(from_text) == total
    assert suite.get("failures") == str(want_fail)
    assert [c.get("name") for c in fails] == [listed[0].split(" ")[0]]
    assert all("expected failure" in (c.find("skipped").get("message") or "") for c in xfail)  # type: ignore[union-attr]
    # the kit's version and the spec revision in every report
    props = {p.get("name"): p.get("value") for p in suite.iter("property")}
    assert report["kit"]["version"] == props["kit.version"] and report["kit"]["spec_revision"] == props["spec.revision"]
    assert f"cbf-conformance {props['kit.version']} (spec {props['spec.revision']})" in text.stdout
    # the matrix counts expected failures apart
    assert "(pass/fail/expected failure/skip)" in text.stdout


# A testee that answers every operation with skipped (issue 35): it judges nothing.
SKIP_ALL = """
import json, sys
for line in sys.stdin:
    if json.loads(line).get("op") == "quit":
        break
    print(json.dumps({"skipped": True}), flush=True)
"""
# A reader that only decodes, with the cbf wheel's codec.
DECODE_ONLY = """
import json, sys
import cbf
for line in sys.stdin:
    req = json.loads(line)
    if req.get("op") == "quit":
        break
    if req.get("op") != "decode":
        print(json.dumps({"skipped": True}), flush=True)
        continue
    try:
        answer = {"ok": True, "result": cbf.to_canonical(cbf.decode(open(req["file"], "rb").read()))}
    except cbf.CbfError as exc:
        answer = {"ok": False, "error": {"kind": exc.kind, "offset": exc.offset, "message": str(exc)}}
    print(json.dumps(answer), flush=True)
"""


def _stated(op: str) -> int:
    """How many golden cases state an expectation for an operation (read from the cases)."""
    wants: dict[str, Callable[[dict[str, Any]], bool]] = {
        "decode": lambda e: e.get("decode") is not None, "validate": lambda e: bool(e.get("validate")),
        "encode": lambda e: bool(e.get("encode"))}
    return sum(1 for exp in GOLDEN.glob("*.expect.yaml") if wants[op](load_yaml(exp)))


def _judged_table(stdout: str) -> dict[str, str]:
    lines = stdout.splitlines()
    start = next(i for i, ln in enumerate(lines) if ln.startswith("judged "))
    return {ln.split()[0]: " ".join(ln.split()[1:]) for ln in lines[start + 1:start + 4]}


def test_consumer_a_kit_that_judges_nothing_fails(tmp_path_factory: pytest.TempPathFactory, consumer: Path) -> None:
    """From the wheels in a temporary folder: a testee that skips everything, and a decode-only
    reader run as if it validated, both fail with one line naming what was not judged; the report
    counts per capability; the decode-only reader passes once it says so (--capabilities decode),
    and every report names that."""
    work = tmp_path_factory.mktemp("judging")
    bin_ = consumer
    folder = work / "user"
    folder.mkdir()
    (folder / "skip.py").write_text(SKIP_ALL, encoding="utf-8")
    (folder / "dec.py").write_text(DECODE_ONLY, encoding="utf-8")
    kit_bin = bin_ / "cbf-conformance"
    stated = {op: _stated(op) for op in ("decode", "validate", "encode")}
    assert all(stated.values())

    skip = _run(kit_bin, "--testee", f"{bin_ / 'python'} skip.py", "--name", "lazy", cwd=folder, check=False)
    assert skip.returncode == 1 and "Traceback" not in skip.stderr
    lines = [ln for ln in skip.stdout.splitlines() if ln.startswith("lazy: ")]
    assert len(lines) == 1, skip.stdout[-3000:]  # one line, not one a case
    assert "judged no decode and no validate and no encode case" in lines[0]
    for op, n in stated.items():
        assert f"{op} in {n} of {n} case(s)" in lines[0]
    assert _judged_table(skip.stdout) == {op: f"0/{n}" for op, n in stated.items()}
    # a failure list naming every case cannot make a run that judged nothing pass
    fixed = _run(kit_bin, "--testee", f"{bin_ / 'python'} skip.py", "--name", "lazy", "--failure-list", "known.txt",
                 "--fix", cwd=folder, check=False)
    assert fixed.returncode == 1 and "judged no decode" in fixed.stdout
    again = _run(kit_bin, "--testee", f"{bin_ / 'python'} skip.py", "--name", "lazy", "--failure-list", "known.txt",
                 cwd=folder, check=False)
    assert again.returncode == 1 and re.search(r"lazy: FAIL judged no decode and no validate and no encode case",
                                               again.stdout)

    decode_only: list[str | Path] = [kit_bin, "--testee", f"{bin_ / 'python'} dec.py", "--name", "dec"]
    as_full = _run(*decode_only, "--json", cwd=folder, check=False)
    assert as_full.returncode == 1
    one = [ln for ln in as_full.stderr.splitlines() if ln.startswith("dec: ")]
    assert len(one) == 1, one
    assert "judged no validate and no encode case" in one[0] and "--capabilities decode" in one[0], one
    judged = json.loads(as_full.stdout)["bindings"]["dec"]["judged"]
    assert {op: (j["judged"], j["skipped"]) for op, j in judged.items()} == {
        "decode": (stated["decode"], 0), "validate": (0, stated["validate"]), "encode": (0, stated["encode"])}

    declared = _run(*decode_only, "--capabilities", "decode", "--junit", "j.xml", "--json", cwd=folder, check=False)
    assert declared.returncode == 0, declared.stderr[-3000:]
    report = json.loads(declared.stdout)["bindings"]["dec"]
    assert report["capabilities"] == ["decode"]
    assert report["judged"]["decode"]["judged"] == stated["decode"] and report["judged"]["validate"]["judged"] == 0
    table = _judged_table(declared.stderr)
    assert table["decode"] == f"{stated['decode']}/{stated['decode']}"
    assert table["validate"] == table["encode"] == "not declared"
    props = {p.get("name"): p.get("value") for p in ET.parse(folder / "j.xml").getroot().iter("property")}
    assert props["capabilities"] == "decode" and props["judged.validate"] == f"0/{stated['validate']}"


def test_an_empty_testee_and_an_endless_failure_list_are_refused(kit: Path, tmp_path: Path) -> None:
    """`--testee ""` (a CI line with an unset variable) is refused, never replaced by anything; a
    failure list that is not a regular file, or larger than a list can be, is one line, at once."""
    for empty in ("", "   "):
        assert "--testee: empty command" in _one_line_2(_run(kit, "--testee", empty, cwd=REPO, check=False))
    (tmp_path / "t.py").write_text(SKIP_ALL, encoding="utf-8")
    testee = f"{sys.executable} t.py"
    assert "not a regular file" in _one_line_2(_run(kit, "--testee", testee, "--failure-list", "/dev/zero",
                                                    cwd=tmp_path, check=False))
    with open(tmp_path / "huge.txt", "wb") as f:
        f.truncate(64 * 1024 * 1024)  # sparse: 64 MiB of NULs, no disk
    assert "larger than" in _one_line_2(_run(kit, "--testee", testee, "--failure-list", "huge.txt", cwd=tmp_path,
                                             check=False))
    for bad in ("decode,print", "", "encode,validate"):
        assert "--capabilities" in _one_line_2(_run(kit, "--testee", testee, "--capabilities", bad, cwd=tmp_path,
                                                    check=False))


def test_layouts_json_states_the_byte_layouts_of_the_model() -> None:
    """layouts.json (shipped beside PROTOCOL.md) says what the model says: every header's fields tile
    it, every command layout's arguments fit its size, codes and offsets as the spec has them."""
    from cbfgen.loader import load

    spec = load(REPO / "spec" / "cbf.yaml")
    doc = json.loads((REPO / "generated" / "python" / "cbf" / "layouts.json").read_text(encoding="utf-8"))
    assert doc["spec"] == spec.revision and doc["byte_order"] == spec.meta["byte_order"]
    assert [v["id"] for v in doc["versions"]] == [v.id for v in spec.versions]
    for hid, h in spec.headers.items():
        got = doc["headers"][hid]
        assert got["size"] == h.size
        assert [(f["name"], f["offset"], f["size"]) for f in got["fields"]] == [(f.name, f.offset, f.size)
                                                                            for f in h.fields]
        assert sum(f["size"] for f in got["fields"]) == h.size
    assert doc["record_head"]["size"] == spec.record.head_size
    by_name = {c["name"]: c for c in doc["commands"]}
    for c in spec.commands:
        assert by_name[c.name]["code"] == c.code
        for lay, got in zip(c.layouts, by_name[c.name]["layouts"], strict=True):
            assert got["size"] == lay.size and sorted(got["versions"]) == sorted(lay.versions)
            assert all(a["offset"] + a["size"] <= lay.size or "repeat" in a for a in got["args"])
    assert {f["field"] for f in doc["checksums"]["fields"]} == {f.field for f in spec.checksums.fields}
