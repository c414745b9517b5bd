"""Install lines that are true (issue 35, point 6): a fresh clone, wheels only, offline.

`make release-tag` tags the clone `v` + the toolkit's version; the README's pre-commit example
then runs as written (its `repo:` pointed at the clone) with the real pre-commit against that tag,
and its hooks' environment holds the lean `cbf` (the root package) and numpy, nothing of the
development environment; the README's GitHub Actions and GitLab CI jobs run as written, their
`pip install` of the wheel `make dist` builds included. pip never reaches an index
(PIP_NO_INDEX): the third-party wheels they need (numpy, setuptools to build) are repacked
from this checkout's .venv into a local wheelhouse, so nothing of ours can come from anywhere else.
"""

from __future__ import annotations

import base64
import hashlib
import os
import re
import shutil
import subprocess
import sys
import tomllib
import zipfile
from importlib import metadata
from pathlib import Path
from typing import Any

import pytest
import yaml
from conftest import readme_ci_blocks

import cbf
import cbfgen

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"
# What the clone needs from this working tree (a clone holds HEAD; these make it this tree's state).
OVERLAY = (".pre-commit-hooks.yaml", "pyproject.toml", "Makefile", "mk", "generated/python",
           "generator/cbfgen/__init__.py", "README.md")


def test_the_root_package_is_the_lean_cbf_distribution() -> None:
    """`pip install .` of this repository (what pre-commit runs) builds the `cbf` distribution
    of generated/python: the same name, dependencies, extras, command and licence."""
    root = tomllib.loads((REPO / "pyproject.toml").read_text(encoding="utf-8"))
    gen = tomllib.loads((REPO / "generated" / "python" / "pyproject.toml").read_text(encoding="utf-8"))
    rp, gp = root["project"], gen["project"]
    for key in ("name", "dependencies", "scripts", "requires-python", "license"):
        assert rp[key] == gp[key], key
    extras = {k: v for k, v in rp["optional-dependencies"].items() if k != "dev"}
    assert extras == gp["optional-dependencies"]
    assert root["tool"]["setuptools"]["packages"] == gen["tool"]["setuptools"]["packages"]
    assert root["tool"]["setuptools"]["package-data"] == gen["tool"]["setuptools"]["package-data"]
    assert root["tool"]["setuptools"]["package-dir"] == {"": "generated/python"}
    assert root["tool"]["setuptools"]["dynamic"]["version"] == {"attr": "cbf.version.__version__"}
    assert cbf.__version__ == cbfgen.__version__ and gp["version"] == cbfgen.__version__


def _repack(dist: str, out: Path) -> Path:
    """The installed distribution `dist` of this interpreter as a wheel file in `out` (its files as
    RECORD lists them; scripts outside site-packages left out): a wheelhouse without a network."""
    d = metadata.distribution(dist)
    info = Path(str(d._path))  # type: ignore[attr-defined]
    site = info.parent
    tag = next(ln.split(": ", 1)[1].strip() for ln in (info / "WHEEL").read_text().splitlines()
               if ln.startswith("Tag: "))
    name = re.sub(r"[-_.]+", "_", d.metadata["Name"]).lower()
    wheel = out / f"{name}-{d.version}-{tag}.whl"
    record: list[str] = []
    with zipfile.ZipFile(wheel, "w", zipfile.ZIP_DEFLATED) as z:
        for f in d.files or []:
            rel = str(f)
            if rel.startswith("..") or "__pycache__" in rel or rel.endswith(("/RECORD", "/INSTALLER",
                                                                              "/direct_url.json", "/REQUESTED")):
                continue
            data = (site / rel).read_bytes()
            z.writestr(rel, data)
            digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
            record.append(f"{rel},sha256={digest},{len(data)}")
        record.append(f"{info.name}/RECORD,,")
        z.writestr(f"{info.name}/RECORD", "\n".join(record) + "\n")
    return wheel


@pytest.fixture(scope="module")
def released(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    """A clone of this checkout with this tree's state committed and `make release-tag` run in it;
    the cbf wheel as `make dist` builds it; a wheelhouse of the third-party wheels; an env offline."""
    work = tmp_path_factory.mktemp("release")
    env = {k: v for k, v in os.environ.items() if not k.startswith(("PRE_COMMIT", "GIT_", "PIP_", "PYTHON"))}
    env.update(HOME=str(work / "home"), GIT_AUTHOR_NAME="t", GIT_AUTHOR_EMAIL="t@example.com",
               GIT_COMMITTER_NAME="t", GIT_COMMITTER_EMAIL="t@example.com", PIP_NO_INDEX="1",
               PIP_DISABLE_PIP_VERSION_CHECK="1", PRE_COMMIT_HOME=str(work / "pre-commit-home"))
    (work / "home").mkdir()
    clone = work / "clone"
    cloned = subprocess.run(["git", "clone", "-q", "--no-local", str(REPO), str(clone)], env=env,
                            capture_output=True)
    if cloned.returncode:  # a copy of the tree that is no git checkout (the revision drill's): a new repository
        clone.mkdir(exist_ok=True)
        subprocess.run(["git", "init", "-q", str(clone)], check=True, env=env)
    for rel in OVERLAY:
        src, dst = REPO / rel, clone / rel
        dst.parent.mkdir(parents=True, exist_ok=True)
        if src.is_dir():
            shutil.rmtree(dst, ignore_errors=True)
            shutil.copytree(src, dst, ignore=shutil.ignore_patterns("__pycache__", "*.egg-info", "build"))
        else:
            shutil.copy2(src, dst)
    git = ["git", "-C", str(clone)]
    subprocess.run([*git, "add", "-A"], check=True, env=env)
    if subprocess.run([*git, "diff", "--cached", "--quiet"], env=env).returncode:
        subprocess.run([*git, "commit", "-qm", "this working tree"], check=True, env=env)
    wheelhouse = work / "wheelhouse"
    wheelhouse.mkdir()
    for dist in ("numpy", "setuptools", "pip"):
        _repack(dist, wheelhouse)
    dist_dir = work / "dist"
    subprocess.run([sys.executable, "-m", "build", "--no-isolation", "--wheel", "--outdir", str(dist_dir),
                    str(clone / "generated" / "python")], check=True, capture_output=True, env={**env, "PATH":
                   os.environ["PATH"]})
    env["PIP_FIND_LINKS"] = str(wheelhouse)
    return {"clone": clone, "dist": dist_dir, "wheelhouse": wheelhouse, "work": work, "env": env}  # type: ignore[dict-item]


def _make_tag(clone: Path, env: dict[str, str]) -> subprocess.CompletedProcess[str]:
    return subprocess.run(["make", "-s", "release-tag"], cwd=clone, env=env, capture_output=True, text=True)


def test_make_release_tags_the_toolkit_version(released: dict[str, Any]) -> None:
    clone, env = released["clone"], released["env"]
    first = _make_tag(clone, env)
    assert first.returncode == 0, first.stderr
    tag = f"v{cbfgen.__version__}"
    assert subprocess.run(["git", "-C", str(clone), "tag", "--list", "v*"], capture_output=True, text=True,
                          env=env).stdout.split() == [tag]
    assert f"tagged {tag}" in first.stdout or "already names HEAD" in first.stdout
    again = _make_tag(clone, env)
    assert again.returncode == 0 and "already names HEAD" in again.stdout
    # the README's pre-commit example names that tag
    assert readme_ci_blocks()[0]["repos"][0]["rev"] == tag
    # a tag naming another commit is refused, one line, exit 2
    (clone / "note.txt").write_text("x\n", encoding="utf-8")
    subprocess.run(["git", "-C", str(clone), "add", "note.txt"], check=True, env=env)
    dirty = _make_tag(clone, env)
    assert dirty.returncode == 2 and "uncommitted changes" in dirty.stderr
    subprocess.run(["git", "-C", str(clone), "commit", "-qm", "later"], check=True, env=env)
    moved = _make_tag(clone, env)
    assert moved.returncode == 2 and f"{tag} already names" in moved.stderr and "raise __version__" in moved.stderr
    subprocess.run(["git", "-C", str(clone), "reset", "-q", "--hard", tag], check=True, env=env)


def _failing_case() -> Path:
    from cbf.validation import validate

    for p in sorted(GOLDEN.glob("*.cbf")):
        data = p.read_bytes()
        if len(data) > 200 and cbf.decode(data) and any(f.severity == "error" for f in validate(data)):
            return p
    raise AssertionError("no golden file with an error finding")


def test_pre_commit_example_against_the_tag_offline(released: dict[str, Any]) -> None:
    clone, work, env = released["clone"], released["work"], dict(released["env"])
    assert _make_tag(clone, env).returncode == 0
    user = work / "user"
    user.mkdir()
    subprocess.run(["git", "init", "-q"], cwd=user, check=True, env=env)
    config = readme_ci_blocks()[0]
    config["repos"][0]["repo"] = str(clone)  # the one change: where the repository is
    (user / ".pre-commit-config.yaml").write_text(yaml.safe_dump(config), encoding="utf-8")
    (user / "cuts").mkdir()
    shutil.copy(GOLDEN / "valid.v3.small.cbf", user / "cuts" / "good.cbf")
    shutil.copy(_failing_case(), user / "cuts" / "bad.cbf")
    (user / "cuts" / "bad.cut").write_text("header X\nbogus 1\n", encoding="utf-8")
    # hostile names (issue 35): a forged workflow command (plain after "cuts/"), a line break before one (quoted)
    forged = "::error file=README.md,line=1::forged"
    shutil.copy(_failing_case(), user / "cuts" / f"{forged}.cbf")
    (user / "cuts" / "x\n::stop-commands::y.cut").write_text("header X\nbogus 1\n", encoding="utf-8")
    subprocess.run(["git", "add", "-A"], cwd=user, check=True, env=env)
    env["PATH"] = f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}"  # the pinned pre-commit
    res = subprocess.run([sys.executable, "-m", "pre_commit", "run", "--all-files"], cwd=user, env=env,
                         capture_output=True, text=True, timeout=900)
    out = res.stdout + res.stderr
    assert res.returncode == 1, out
    assert re.search(r"cbf validate\.+Failed", out) and re.search(r"cbf encode --check\.+Failed", out), out
    assert "cuts/bad.cbf: FAIL" in out and "cuts/good.cbf: ok" in out and "unknown keyword" in out
    assert f"cuts/{forged}.cbf: FAIL" in out and '"cuts/x\\n::stop-commands::y.cut"' in out, out
    assert not [ln for ln in out.splitlines() if ln.startswith("::")], out
    # the hooks' environment: the lean cbf and numpy, built from the tag, nothing of the development package
    envs = [p for p in Path(env["PRE_COMMIT_HOME"]).glob("repo*/py_env-*") if p.is_dir()]
    assert len(envs) == 1, envs
    py = next(envs[0].glob("bin/python"))
    listed = subprocess.run([str(py), "-c", "import importlib.metadata as m; print('\\n'.join(sorted("
                             "(d.metadata['Name'] or '').lower() for d in m.distributions())))"],
                            capture_output=True, text=True, check=True, env=env).stdout.split()
    assert "cbf" in listed and "numpy" in listed
    for heavy in ("jinja2", "jsonschema", "pytest", "hypothesis", "matplotlib", "mypy", "cbfgen", "pyyaml"):
        assert heavy not in listed, listed
    version = subprocess.run([str(envs[0] / "bin" / "cbf"), "--version"], capture_output=True, text=True,
                             env=env).stdout
    assert version.startswith(f"cbf {cbfgen.__version__} ")


@pytest.mark.parametrize("which", ["github", "gitlab"])
def test_the_readme_ci_jobs_run_as_written_from_the_wheel(released: dict[str, Any], which: str) -> None:
    """Every `run:`/`script:` line as the README writes it, in a fresh venv on PATH (the runner's
    Python), with the project's `wheels/` holding the wheel `make dist` built."""
    github, gitlab = readme_ci_blocks()[1:3]
    job = next(iter(github["jobs"].values())) if which == "github" else gitlab["validate-cut-files"]
    lines = [s["run"] for s in job["steps"] if "run" in s] if which == "github" else list(job["script"])
    installs = [ln for ln in lines if ln.startswith("pip install")]
    assert installs and all("wheels/cbf-" in ln for ln in installs), installs  # never `pip install cbf` by name
    work: Path = released["work"] / f"ci-{which}"
    (work / "wheels").mkdir(parents=True)
    shutil.copy(next(released["dist"].glob("cbf-*.whl")), work / "wheels")
    # the runner's venv with its pip: this interpreter's pip (repacked) installed without bytecode, as
    # conftest.clean_venv does (ensurepip compiles all of pip: 2.7 CPU s a venv, 0.6 this way)
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(work / "py")], check=True)
    subprocess.run([sys.executable, "-m", "pip", "--python", str(work / "py" / "bin" / "python"), "install", "-q",
                    "--no-compile", "--no-index", str(next(released["wheelhouse"].glob("pip-*.whl")))], check=True,
                   capture_output=True, env={**released["env"], "PATH": os.environ["PATH"]})
    env = dict(released["env"])
    env["PATH"] = f"{work / 'py' / 'bin'}{os.pathsep}{os.environ['PATH']}"
    (work / "cuts").mkdir()
    shutil.copy(GOLDEN / "valid.v3.small.cbf", work / "cuts" / "a.cbf")
    (work / "cuts" / "a.cut").write_text(cbf.to_cut(cbf.decode((GOLDEN / "valid.v3.small.cbf").read_bytes())),
                                         encoding="utf-8")
    codes = []
    for line in lines:
        res = subprocess.run(["bash", "-c", line], cwd=work, env=env, capture_output=True, text=True, timeout=600)
        assert "Traceback" not in res.stderr, res.stderr
        codes.append(res.returncode)
        assert res.returncode == 0, (line, res.stdout[-2000:], res.stderr[-2000:])
    assert (work / "py" / "bin" / "cbf").exists()
    shutil.copy(_failing_case(), work / "cuts" / "bad.cbf")
    last = subprocess.run(["bash", "-c", lines[-1]], cwd=work, env=env, capture_output=True, text=True)
    assert last.returncode == 1
