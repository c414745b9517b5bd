"""The Kaitai parsers used from outside this repository (issue 14): the Python parser
installs as the `cbf-kaitai` wheel (module cbf_kaitai, never shadowing the codec's `cbf`),
the JavaScript parser as an npm tarball; each parses a golden file in a scratch project."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import clean_venv

import cbf

REPO = Path(__file__).resolve().parents[1]
KAITAI = REPO / "generated" / "kaitai"
GOLDEN = next(p for p in sorted((REPO / "conformance" / "golden").glob("valid.v3.*.cbf")) if p.stat().st_size < 4096)
CODES = [r.code for r in cbf.decode(GOLDEN.read_bytes()).records]


# A consumer's environment: none of this checkout's paths.
CLEAN_ENV = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "NODE_PATH")}


def _run(*cmd: str | Path, cwd: Path) -> str:
    return subprocess.run([str(c) for c in cmd], cwd=cwd, capture_output=True, text=True, check=True,
                          env=CLEAN_ENV).stdout


@pytest.mark.skipif(not (KAITAI / "python" / "cbf_kaitai" / "cbf.py").exists(), reason="ksc output missing")
def test_python_parser_wheel_in_a_clean_venv(tmp_path: Path) -> None:
    src = tmp_path / "src"
    shutil.copytree(KAITAI / "python", src, ignore=shutil.ignore_patterns("__pycache__", "testee.py"))
    _run(sys.executable, "-m", "build", "--no-isolation", "--wheel", "--outdir", tmp_path / "dist", src, cwd=tmp_path)
    wheel = next((tmp_path / "dist").glob("cbf_kaitai-*.whl"))
    py = clean_venv(tmp_path / "venv", wheel) / "python"
    out = _run(py, "-c", "import json, sys; from cbf_kaitai import Cbf, SPEC_REVISION; "
               "print(json.dumps([SPEC_REVISION, [r.code for r in Cbf.from_file(sys.argv[1]).records]]))",
               GOLDEN, cwd=tmp_path)
    assert json.loads(out) == [cbf.SPEC_REVISION, CODES]
    # the codec's name stays free
    assert subprocess.run([str(py), "-c", "import cbf"], capture_output=True, env=CLEAN_ENV).returncode != 0


@pytest.mark.skipif(shutil.which("npm") is None or not (KAITAI / "javascript" / "Cbf.js").exists(),
                    reason="needs npm and the ksc output")
def test_javascript_parser_npm_pack_and_install(tmp_path: Path) -> None:
    pkg = tmp_path / "pkg"
    shutil.copytree(KAITAI / "javascript", pkg)
    meta = json.loads((pkg / "package.json").read_text(encoding="utf-8"))
    assert meta["version"] == cbf.__version__ and "kaitai-struct" in meta["dependencies"]
    tarball = _run("npm", "pack", "--silent", "--pack-destination", tmp_path, cwd=pkg).strip().splitlines()[-1]
    scratch = tmp_path / "scratch"
    scratch.mkdir()
    (scratch / "package.json").write_text('{"name": "scratch", "private": true}\n', encoding="utf-8")
    _run("npm", "install", "--no-audit", "--no-fund", "--loglevel=error", tmp_path / tarball, cwd=scratch)
    (scratch / "parse.js").write_text(
        "const { Cbf } = require('cbf-kaitai');\n"
        "const KaitaiStream = require('kaitai-struct/KaitaiStream');\n"
        "const f = new Cbf(new KaitaiStream(require('fs').readFileSync(process.argv[2])));\n"
        "console.log(JSON.stringify(f.records.map((r) => r.code)));\n", encoding="utf-8")
    assert json.loads(_run("node", "parse.js", GOLDEN, cwd=scratch)) == CODES


GO_CONSUMER = """package main

import (
	"fmt"
	"os"

	cbf "cbf-kaitai"
	"github.com/kaitai-io/kaitai_struct_go_runtime/kaitai"
)

func main() {
	file, err := os.Open(os.Args[1])
	if err != nil {
		panic(err)
	}
	f := cbf.NewCbf()
	if err := f.Read(kaitai.NewStream(file), nil, f); err != nil {
		panic(err)
	}
	for _, r := range f.Records {
		fmt.Println(r.Code)
	}
}
"""


@pytest.mark.skipif(shutil.which("go") is None or not (KAITAI / "go" / "cbf.go").exists(), reason="needs go")
def test_go_parser_module_through_replace(tmp_path: Path) -> None:
    mod = (KAITAI / "go" / "go.mod").read_text(encoding="utf-8")
    module = next(line.split()[1] for line in mod.splitlines() if line.startswith("module "))
    assert not (KAITAI / "go" / "testee.go").exists(), "the testee is not part of the parser's module"
    consumer = tmp_path / "consumer"
    consumer.mkdir()
    requires = [line.strip() for line in mod.split("require (", 1)[1].split(")", 1)[0].splitlines() if line.strip()]
    (consumer / "go.mod").write_text(
        "module consumer\n\ngo 1.23.0\n\nrequire (\n\t" + module + " v0.0.0\n"
        + "".join(f"\t{r}\n" for r in requires) + f")\n\nreplace {module} => {KAITAI / 'go'}\n", encoding="utf-8")
    shutil.copy(KAITAI / "go" / "go.sum", consumer / "go.sum")
    (consumer / "main.go").write_text(GO_CONSUMER, encoding="utf-8")
    env = dict(CLEAN_ENV, GOFLAGS="-mod=readonly")
    subprocess.run(["go", "build", "-o", "consumer", "."], cwd=consumer, env=env, check=True, capture_output=True)
    out = subprocess.run([str(consumer / "consumer"), str(GOLDEN)], capture_output=True, text=True, check=True)
    assert [int(x) for x in out.stdout.split()] == CODES
