"""The Python distributions used from outside this repository (issue 14): the `cbf` wheel
installs alone into a clean venv (no generator dependency comes with it) and decodes,
validates and converts a file there; the `cbfgen` wheel generates a binding from a spec
given on its command line, with no checkout around it."""

from __future__ import annotations

import shutil
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest
from conftest import CLEAN_ENV, clean_venv
from conftest import run_clean as _run

import cbf
import cbfgen
from cbfgen.emit.docs import site_links

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"




def _build(src: Path, work: Path) -> Path:
    """Build a wheel from a copy of src (the tree stays clean), with the pinned setuptools."""
    copy = work / src.name
    shutil.copytree(src, copy, ignore=shutil.ignore_patterns("__pycache__", "build", "*.egg-info"))
    _run(sys.executable, "-m", "build", "--no-isolation", "--wheel", "--outdir", work / "dist", copy, cwd=work)
    return next((work / "dist").glob("*.whl"))


def _venv(where: Path, *wheels: Path) -> Path:
    return clean_venv(where, *wheels)


@pytest.fixture(scope="module")
def outside(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("consumer")


def test_cbf_wheel_alone_decodes_validates_converts(outside: Path) -> None:
    wheel = _build(REPO / "generated" / "python", outside / "cbf-build")
    assert wheel.name.startswith(f"cbf-{cbf.__version__}-")
    bin_ = _venv(outside / "venv-cbf", wheel)
    py = bin_ / "python"
    # only the codec's own dependencies came along
    assert _run(py, "-c", "import jinja2", cwd=outside, check=False).returncode != 0
    assert _run(py, "-c", "import jsonschema", cwd=outside, check=False).returncode != 0
    version = _run(py, "-c", "import cbf; print(cbf.__version__, cbf.SPEC_REVISION)", cwd=outside)
    assert version.stdout.split(" ", 1) == [cbf.__version__, cbf.SPEC_REVISION + "\n"]
    assert _run(bin_ / "cbf", "--version", cwd=outside).stdout.strip() == \
        f"cbf {cbf.__version__} (spec {cbf.SPEC_REVISION})"
    typed = _run(py, "-c", "import cbf, pathlib; print((pathlib.Path(cbf.__file__).parent / 'py.typed').exists())",
                 cwd=outside)
    assert typed.stdout.strip() == "True"
    golden = next(p for p in sorted(GOLDEN.glob("valid.v3.*.cbf")) if p.stat().st_size < 100_000)
    work = outside / "files"
    work.mkdir()
    shutil.copy(golden, work / "part.cbf")
    assert _run(bin_ / "cbf", "validate", "part.cbf", cwd=work).returncode == 0
    _run(bin_ / "cbf", "decode", "part.cbf", "--to", "cut", "-o", "part.cut", cwd=work)
    _run(bin_ / "cbf", "encode", "part.cut", "-o", "back.cbf", cwd=work)
    assert cbf.decode((work / "back.cbf").read_bytes()).records == cbf.decode(golden.read_bytes()).records


def test_cbf_wheel_declares_ranges_not_pins() -> None:
    project = tomllib.loads((REPO / "generated" / "python" / "pyproject.toml").read_text(encoding="utf-8"))["project"]
    gen = tomllib.loads((REPO / "generator" / "pyproject.toml").read_text(encoding="utf-8"))["project"]
    for dep in [*project["dependencies"], *gen["dependencies"],
                *(d for ds in project["optional-dependencies"].values() for d in ds)]:
        assert "==" not in dep and "<" in dep and ">=" in dep, dep
    deps = " ".join(project["dependencies"])
    for generator_only in ("jinja2", "jsonschema", "pyyaml"):
        assert generator_only not in deps.lower()


def test_cbfgen_wheel_generates_from_a_spec_argument(outside: Path) -> None:
    wheel = _build(REPO / "generator", outside / "cbfgen-build")
    assert wheel.name.startswith(f"cbfgen-{cbfgen.__version__}-")
    bin_ = _venv(outside / "venv-cbfgen", wheel)
    work = outside / "gen"
    work.mkdir()
    shutil.copy(REPO / "spec" / "cbf.yaml", work / "format.yaml")
    # no spec here and none given: one line, exit 2
    missing = _run(bin_ / "cbfgen", "--out", "out", cwd=work, check=False)
    assert missing.returncode == 2 and len(missing.stderr.strip().splitlines()) == 1
    assert "Traceback" not in missing.stderr
    # every binding or none: without the Kaitai compiler, one line naming it, exit 2, nothing written
    no_ksc = {k: v for k, v in CLEAN_ENV.items() if k != "NODE_PATH"}
    res = subprocess.run([str(bin_ / "cbfgen"), "--spec", "format.yaml", "--out", "out"], cwd=work, env=no_ksc,
                         capture_output=True, text=True)
    assert res.returncode == 2 and len(res.stderr.strip().splitlines()) == 1, res.stderr
    assert "kaitai-struct-compiler" in res.stderr and "Traceback" not in res.stderr
    assert not (work / "out").exists()
    # every target, as the README shows it, with the compiler found as cbfgen.ksc says (NODE_PATH), and the
    # docs' inputs given: the wheel carries every file an emitter reads (a missing package-data file, such as
    # the Kaitai Go module's go.sum, fails here and nowhere in the tree)
    # a consumer's project laid out as this repository is (spec/, conformance/ beside the output folder), so
    # the docs' links to the spec, the golden README and each case's hex resolve there as they do here
    (work / "spec").mkdir()
    shutil.copy(REPO / "spec" / "cbf.yaml", work / "spec" / "cbf.yaml")
    shutil.copytree(REPO / "conformance", work / "conformance",
                    ignore=shutil.ignore_patterns("__pycache__", "*.py", "runner", "assembler", "reliability",
                                                  "testees"))
    conf = work / "conformance"
    env = dict(no_ksc, NODE_PATH=str(REPO / "node_modules"))
    res = subprocess.run([str(bin_ / "cbfgen"), "--spec", "spec/cbf.yaml", "--out", "out", "--golden",
                          str(conf / "golden"), "--report", str(conf / "report.json")], cwd=work, env=env,
                         capture_output=True, text=True)
    assert res.returncode == 0 and "Traceback" not in res.stderr, res.stderr[-2000:]
    assert "Kaitai parsers compiled" in res.stdout and res.stderr == ""
    written = {p.relative_to(work / "out").as_posix() for p in (work / "out").rglob("*") if p.is_file()}
    assert {rel.split("/", 1)[0] for rel in written} == {p.name for p in (REPO / "generated").iterdir() if p.is_dir()}
    # the Kaitai parsers are there (the package's __init__ imports a module that exists), and every file,
    # the docs' golden pages and traceability included, is the checkout's byte for byte
    assert "kaitai/python/cbf_kaitai/cbf.py" in written
    tracked = set(subprocess.run(["git", "ls-files", "generated"], cwd=REPO, capture_output=True, text=True,
                                 check=True).stdout.split()) or {f"generated/{r}" for r in written}
    differ = sorted(rel for rel in written if f"generated/{rel}" in tracked
                    and (work / "out" / rel).read_bytes() != (REPO / "generated" / rel).read_bytes())
    assert not differ, differ
    assert {f"generated/{r}" for r in written} >= {t for t in tracked if not t.startswith("generated/docs/site/")}
    # without the docs' inputs the run says which sections stay empty (and still writes every binding); its
    # output folder's parent holds no spec/ or conformance/
    bare = outside / "bare" / "out"
    res = subprocess.run([str(bin_ / "cbfgen"), "--spec", "format.yaml", "--out", str(bare), "--only", "docs"],
                         cwd=work, env=env, capture_output=True, text=True)
    assert res.returncode == 0 and "--golden DIR" in res.stderr and "--report FILE" in res.stderr, res.stderr
    # the docs read as a site of their own: with the docs' inputs every link resolves in the consumer's tree;
    # without them (bare, whose parent holds no conformance/ or spec/) the pages that need
    # them say so and link nothing that is not there; a broken link is seen (the check can fail)
    assert site_links.markdown_problems(work / "out" / "docs", work) == []
    assert [p.name for p in (bare / "docs" / "golden").iterdir()] == ["index.md"]
    assert site_links.markdown_problems(bare / "docs", bare.parent) == []
    index = (bare / "docs" / "golden" / "index.md").read_text(encoding="utf-8")
    assert "No golden case was given" in index and "](" + "../../../conformance" not in index
    for page in (bare / "docs" / "cut.md", next((bare / "docs" / "commands").glob("*.md"))):
        assert "No golden case was given to cbfgen" in page.read_text(encoding="utf-8"), page
    broken = index + "\n[x](../missing.md) [y](../index.md#nowhere)\n"
    (bare / "docs" / "golden" / "index.md").write_text(broken, encoding="utf-8")
    assert len(site_links.markdown_problems(bare / "docs", bare.parent)) == 2
    assert _run(bin_ / "cbfgen", "--version", cwd=work).stdout.strip() == f"cbfgen {cbfgen.__version__}"
