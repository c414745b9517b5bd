"""The generated .ksy: valid against the official KSY schema, compiles cleanly, and
carries a command added to the spec into the parsers and testees."""

from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path
from typing import Any

import jsonschema
import pytest
from conftest import generate, load_yaml, spec_with_fixture_command

REPO = Path(__file__).resolve().parents[1]
SCHEMA = REPO.parent / "shared" / "kaitai" / "ksy_schema.json"
KSY = REPO / "generated" / "kaitai" / "cbf.ksy"
DRIVER = REPO / "generator" / "cbfgen" / "emit" / "kaitai" / "ksc_driver.js"
HAVE_KSC = (REPO / "node_modules" / "kaitai-struct-compiler").exists() and shutil.which("node") is not None


def _stringify_keys(x: Any) -> Any:
    if isinstance(x, dict):
        return {str(k): _stringify_keys(v) for k, v in x.items()}
    if isinstance(x, list):
        return [_stringify_keys(v) for v in x]
    return x


def test_ksy_validates_against_the_official_schema() -> None:
    if not SCHEMA.exists():
        pytest.skip(f"{SCHEMA} is not beside the repository")
    ksy = _stringify_keys(load_yaml(KSY))
    validator = jsonschema.Draft7Validator(json.loads(SCHEMA.read_text(encoding="utf-8")))
    errors = sorted(validator.iter_errors(ksy), key=lambda e: list(e.absolute_path))
    assert not errors, [f"{'/'.join(map(str, e.absolute_path))}: {e.message}" for e in errors[:5]]
    # gaps of the schema (shared/kaitai/README.md)
    assert ksy["meta"]["id"] == "cbf"
    for name, t in ksy["types"].items():
        for attr in t.get("seq", []):
            assert not (attr.get("repeat") == "expr" and "repeat-expr" not in attr), name
            assert not ("contents" in attr and "type" in attr), name


def test_ksy_follows_the_style_guide() -> None:
    ksy = load_yaml(KSY)
    # the style guide's key order; xref carries the spec's own references
    assert list(ksy["meta"]) == ["id", "title", "file-extension", "xref", "license", "ks-version", "endian"]
    spec = load_yaml(REPO / "spec" / "cbf.yaml")
    for key, refs in spec["meta"]["xref"].items():
        assert ksy["meta"]["xref"][key] in (refs, refs[0]), key
    assert ksy["meta"]["ks-version"] == "0.11" and ksy["meta"]["endian"] == "le"
    for name, t in ksy["types"].items():
        assert t.get("doc"), name
        for attr in t.get("seq", []):
            assert attr["id"] == attr["id"].lower() and attr.get("doc"), (name, attr["id"])


@pytest.mark.skipif(not HAVE_KSC, reason="kaitai-struct-compiler not installed (make kaitai-setup)")
def test_compiles_without_warnings(tmp_path: Path) -> None:
    res = subprocess.run(["node", str(DRIVER), str(KSY.with_suffix(".ksy.json")), str(tmp_path),
                          "python", "javascript", "java", "go"], cwd=REPO, capture_output=True, text=True)
    assert res.returncode == 0, res.stderr
    assert res.stderr == ""
    # with the options cbfgen writes beside the .ksy, the Java parser is in its package (ksc's
    # --java-package) and in the Maven source folder of that package
    package = json.loads((KSY.parent / "ksc-options.json").read_text(encoding="utf-8"))["java_package"]
    java = Path("java", "src", "main", "java", *package.split("."), "Cbf.java")
    for f in (Path("python/cbf_kaitai/cbf.py"), Path("javascript/Cbf.js"), java, Path("go/cbf.go")):
        assert (tmp_path / f).stat().st_size > 10_000
    assert f"\npackage {package};\n" in (tmp_path / java).read_text(encoding="utf-8")


@pytest.mark.skipif(not HAVE_KSC, reason="kaitai-struct-compiler not installed (make kaitai-setup)")
def test_new_command_reaches_parsers_and_testees(tmp_path: Path) -> None:
    out = tmp_path / "gen"
    generate(spec_with_fixture_command(tmp_path), out, "kaitai")
    subprocess.run(["node", str(DRIVER), str(out / "kaitai" / "cbf.ksy.json"), str(out / "kaitai"),
                    "python", "javascript", "java", "go"], cwd=REPO, check=True, capture_output=True)
    assert "args_dwell" in (out / "kaitai" / "cbf.ksy").read_text()
    assert "class ArgsDwell" in (out / "kaitai" / "python" / "cbf_kaitai" / "cbf.py").read_text()
    assert "ArgsDwell" in (out / "kaitai" / "javascript" / "Cbf.js").read_text()
    assert "ArgsDwell" in next((out / "kaitai" / "java" / "src").rglob("Cbf.java")).read_text()
    assert "ArgsDwell" in (out / "kaitai" / "go" / "cbf.go").read_text()
    assert "ArgsDwell" in (out / "kaitai" / "python" / "testee.py").read_text()
    assert "ArgsDwell" in (out / "kaitai" / "java-testee" / "Testee.java").read_text()
    js = (out / "kaitai" / "javascript" / "testee.js").read_text()
    assert "ArgsDwell" in js and '"DWELL"' in js
