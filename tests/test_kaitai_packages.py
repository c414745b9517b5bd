"""The Kaitai parsers used from outside this repository (issue 14): the Python parser
installs as the `cbf-kaitai` wheel (module cbf_kaitai, never shadowing the codec's `cbf`),
the JavaScript parser as an npm tarball, the Java parser as a Maven artifact, the Go parser
as a module; each parses a golden file in a scratch project."""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from conftest import CLEAN_ENV, clean_venv, run_clean

import cbf
from cbf import tables

REPO = Path(__file__).resolve().parents[1]
KAITAI = REPO / "generated" / "kaitai"
GOLDEN = next(p for p in sorted((REPO / "conformance" / "golden").glob("valid.v3.*.cbf")) if p.stat().st_size < 4096)
CODES = [r.code for r in cbf.decode(GOLDEN.read_bytes()).records]


def _run(*cmd: str | Path, cwd: Path, env: dict[str, str] | None = None) -> str:
    return run_clean(*cmd, cwd=cwd, env=env).stdout


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


POM_NS = {"m": "http://maven.apache.org/POM/4.0.0"}
JAVA_CONSUMER = """package org.example.consumer;

import {package}.Cbf;

public class Main {{
    public static void main(String[] args) throws Exception {{
        Cbf f = Cbf.fromFile(args[0]);
        for (Cbf.Record r : f.records()) {{
            System.out.println(r.code() + " " + r.command());
        }}
    }}
}}
"""
CONSUMER_POM = """<?xml version="1.0" encoding="UTF-8"?>
<project xmlns="http://maven.apache.org/POM/4.0.0">
  <modelVersion>4.0.0</modelVersion>
  <groupId>org.example</groupId>
  <artifactId>consumer</artifactId>
  <version>1.0</version>
  <properties>
    <project.build.sourceEncoding>UTF-8</project.build.sourceEncoding>
    <maven.compiler.release>11</maven.compiler.release>
  </properties>
  <dependencies>
    <dependency>
      <groupId>{group}</groupId>
      <artifactId>{artifact}</artifactId>
      <version>{version}</version>
    </dependency>
  </dependencies>
  <build>
    <pluginManagement>{plugins}</pluginManagement>
  </build>
</project>
"""
# The user's ~/.m2 is read as a repository (file://), never written: everything this test
# installs or fetches goes to a temporary local repository. Central stays the fallback, so
# a cold ~/.m2 costs a download; `make kaitai-java-build` (dependency:go-offline) warms it.
MAVEN_SETTINGS = """<settings xmlns="http://maven.apache.org/SETTINGS/1.0.0">
  <profiles><profile><id>warm</id>
    <repositories><repository><id>warm</id><url>{url}</url></repository></repositories>
    <pluginRepositories><pluginRepository><id>warm</id><url>{url}</url></pluginRepository></pluginRepositories>
  </profile></profiles>
  <activeProfiles><activeProfile>warm</activeProfile></activeProfiles>
</settings>
"""


def _coordinates(element: ET.Element) -> tuple[str, str, str]:
    group, artifact, version = (element.findtext(f"m:{k}", namespaces=POM_NS) or ""
                                for k in ("groupId", "artifactId", "version"))
    return group, artifact, version


def _jar(repo: Path, coordinates: tuple[str, str, str]) -> Path:
    """Where Maven keeps an artifact's jar in the local repository `repo`."""
    group, artifact, version = coordinates
    return repo / Path(*group.split(".")) / artifact / version / f"{artifact}-{version}.jar"


@pytest.mark.skipif(shutil.which("mvn") is None or shutil.which("java") is None, reason="needs mvn and a JDK")
def test_java_parser_mvn_install_and_a_consumer_in_a_named_package(tmp_path: Path) -> None:
    pom = ET.parse(KAITAI / "java" / "pom.xml").getroot()
    parser_id = _coordinates(pom)
    assert parser_id[2] == cbf.__version__
    sources = KAITAI / "java" / "src" / "main" / "java"
    found = sorted(sources.rglob("Cbf.java"))
    assert len(found) == 1, "the parser is in the Maven source folder"
    source = found[0]
    package = re.search(r"^package ([\w.]+);$", source.read_text(encoding="utf-8"), re.M)
    assert package, "the parser is in a named package"
    assert source.parent.relative_to(sources).as_posix() == package[1].replace(".", "/")
    runtime = pom.find("m:dependencies/m:dependency", POM_NS)
    assert runtime is not None and _coordinates(runtime)[1] == "kaitai-struct-runtime"

    repo = tmp_path / "repo"
    warm = Path.home() / ".m2" / "repository"
    (tmp_path / "settings.xml").write_text(MAVEN_SETTINGS.format(url=warm.as_uri()), encoding="utf-8")
    mvn = ["mvn", "-q", "-B", "-Dstyle.color=never", "-s", str(tmp_path / "settings.xml"), f"-Dmaven.repo.local={repo}"]
    # Maven's JVM with the quick JIT only: half the CPU time of these short builds.
    env = dict(CLEAN_ENV, MAVEN_OPTS=(CLEAN_ENV.get("MAVEN_OPTS", "") + " -XX:TieredStopAtLevel=1").strip())
    parser = tmp_path / "parser"
    shutil.copytree(KAITAI / "java", parser, ignore=shutil.ignore_patterns("target"))
    _run(*mvn, "install", cwd=parser, env=env)
    assert _jar(repo, parser_id).is_file()

    consumer = tmp_path / "consumer"
    main = consumer / "src" / "main" / "java" / "org" / "example" / "consumer" / "Main.java"
    main.parent.mkdir(parents=True)
    main.write_text(JAVA_CONSUMER.format(package=package[1]), encoding="utf-8")
    # the same plugin versions as the parser's pom, so that nothing new is fetched
    managed = pom.find("m:build/m:pluginManagement/m:plugins", POM_NS)
    assert managed is not None
    plugins = ET.tostring(managed, encoding="unicode").replace("ns0:", "").replace(":ns0", "")
    group, artifact, version = parser_id
    (consumer / "pom.xml").write_text(CONSUMER_POM.format(group=group, artifact=artifact, version=version,
                                                          plugins=plugins), encoding="utf-8")
    # javac needs the Kaitai runtime (Cbf's superclass): Maven finds it through the parser's pom.
    _run(*mvn, "compile", cwd=consumer, env=env)
    classpath = os.pathsep.join(str(p) for p in (consumer / "target" / "classes", _jar(repo, parser_id),
                                                 _jar(repo, _coordinates(runtime))))
    out = _run("java", "-cp", classpath, "org.example.consumer.Main", GOLDEN, cwd=consumer)
    assert out.splitlines() == [f"{code} {tables.BY_CODE[code].name}" for code in CODES]
