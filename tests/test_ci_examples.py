"""The README's CI examples (issue 27 item 2): the GitHub Actions and GitLab CI jobs' commands (all
but `pip install`, with this checkout's cbf) on a folder of cut files: clean, then with a file that
fails validation, then with CUT text that does not encode. The pre-commit example runs with the
real `pre-commit` against a release tag, and the jobs' `pip install` of the wheel, in
tests/test_release.py (a fresh clone, wheels only, offline)."""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
import yaml
from conftest import readme_ci_blocks

import cbf

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"
SMALL = GOLDEN / "valid.v3.small.cbf"
BIN = Path(sys.executable).parent  # the dev venv: its cbf is the one under test


def _failing_case() -> Path:
    """A golden file with an error finding (read from the codec, not assumed)."""
    from cbf.validation import validate

    for p in sorted(GOLDEN.glob("*.cbf")):
        data = p.read_bytes()
        if len(data) > 200 and cbf.decode(data) and any(f.severity == "error" for f in validate(data)):
            return p
    raise AssertionError("no golden file with an error finding")


def _env(home: Path) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if not k.startswith(("PRE_COMMIT", "GIT_"))}
    env.update(PATH=f"{BIN}{os.pathsep}{env.get('PATH', '')}", PRE_COMMIT_HOME=str(home / "pre-commit-home"),
               GIT_AUTHOR_NAME="t", GIT_AUTHOR_EMAIL="t@example.com", GIT_COMMITTER_NAME="t",
               GIT_COMMITTER_EMAIL="t@example.com", HOME=str(home))
    return env


def _project(where: Path, cbf_files: dict[str, Path], cut_texts: dict[str, str]) -> None:
    cuts = where / "cuts"
    cuts.mkdir(parents=True, exist_ok=True)
    for name, src in cbf_files.items():
        shutil.copy(src, cuts / name)
    for name, text in cut_texts.items():
        (cuts / name).write_text(text, encoding="utf-8")


def test_the_hooks_file_names_what_the_readme_says() -> None:
    hooks = {h["id"]: h for h in yaml.safe_load((REPO / ".pre-commit-hooks.yaml").read_text(encoding="utf-8"))}
    config = readme_ci_blocks()[0]
    assert [h["id"] for h in config["repos"][0]["hooks"]] == list(hooks)
    assert hooks["cbf-validate"]["entry"] == "cbf validate" and re.search(hooks["cbf-validate"]["files"], "a.cbf")
    assert hooks["cbf-cut-check"]["entry"] == "cbf encode --check" and re.search(hooks["cbf-cut-check"]["files"],
                                                                                  "a.cut")


def _commands(job: dict[str, Any]) -> list[str]:
    lines = [s["run"] for s in job["steps"] if "run" in s] if "steps" in job else list(job["script"])
    kept = [c for c in lines if not c.startswith("pip install")]
    assert kept and len(kept) < len(lines)  # the install is the one step that needs the network
    return kept


def _run_job(commands: list[str], cwd: Path, env: dict[str, str]) -> list[tuple[int, str]]:
    out = []
    for c in commands:
        res = subprocess.run(["bash", "-c", c], cwd=cwd, env=env, capture_output=True, text=True, timeout=300)
        assert "Traceback" not in res.stderr, res.stderr
        out.append((res.returncode, res.stdout + res.stderr))
    return out


@pytest.mark.parametrize("which", ["github", "gitlab"])
def test_the_ci_jobs_commands(tmp_path: Path, which: str) -> None:
    github, gitlab = readme_ci_blocks()[1:3]
    job = next(iter(github["jobs"].values())) if which == "github" else gitlab["validate-cut-files"]
    commands = _commands(job)
    env = _env(tmp_path)
    good_cut = cbf.to_cut(cbf.decode(SMALL.read_bytes()))
    _project(tmp_path, {"a.cbf": SMALL}, {"a.cut": good_cut})
    assert [rc for rc, _ in _run_job(commands, tmp_path, env)] == [0] * len(commands)
    bad = _failing_case()
    shutil.copy(bad, tmp_path / "cuts" / "bad.cbf")
    results = _run_job(commands, tmp_path, env)
    assert [rc for rc, _ in results] == [0, 1]  # the job fails at validate, exit 1
    if which == "github":
        assert "::error file=cuts/bad.cbf,title=" in results[1][1]
    else:
        report = json.loads((tmp_path / "gl-code-quality-report.json").read_text(encoding="utf-8"))
        assert report and {i["location"]["path"] for i in report} == {"cuts/bad.cbf"}
    (tmp_path / "cuts" / "bad.cbf").unlink()
    (tmp_path / "cuts" / "bad.cut").write_text("header X\nbogus 1\n", encoding="utf-8")
    assert [rc for rc, _ in _run_job(commands, tmp_path, env)][0] == 2  # CUT that does not encode: exit 2
