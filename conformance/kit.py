"""Stage the cbf-conformance kit: the runner and the golden cases as one installable package.

    python -m conformance.kit OUTDIR     # then: python -m build OUTDIR

The package `cbf_conformance` is the runner's modules, the golden cases (.cbf, their
expectations and the files they name) as package data, PROTOCOL.md with the JSON schemas
and the byte layouts (layouts.json) it names, a stamp of the kit version and the spec
revision (reports name both), and the page "Run the CBF conformance suite against your
reader" as its README. The output quoting rule is the Python runtime's own module
(generator/cbfgen/emit/python/runtime/quoting.py; runner/quoting.py is a link to it), staged
here as a file: one source, and the kit needs no `cbf`. Its one dependency
is PyYAML (the expectations are YAML). `make dist` builds it next to `cbf` and `cbfgen`.
"""

from __future__ import annotations

import shutil
import sys
from pathlib import Path

from conformance.runner.about import from_repo

ROOT = Path(__file__).resolve().parent
REPO = ROOT.parent
PAGE = "RUN-AGAINST-YOUR-READER.md"
# the one quoting rule (issue #35): the runtime's module, which runner/quoting.py links to
RULE = REPO / "generator" / "cbfgen" / "emit" / "python" / "runtime" / "quoting.py"
# generated into the cbf package, named by PROTOCOL.md, shipped beside it
SCHEMAS = ("machine.schema.json", "canonical.schema.json", "layouts.json")


def _stamp() -> tuple[str, str]:
    """The toolkit version and the spec revision, read by the runner's own reader (runner/about.py:
    the spec as YAML, the version from its one source, without importing the generator)."""
    found = from_repo(REPO)
    if found is None:
        raise SystemExit("conformance.kit: no __version__ in generator/cbfgen/__init__.py "
                         "or no meta part_number / revision in spec/cbf.yaml")
    return found


def golden_files(golden: Path) -> list[Path]:
    """Each case's .cbf and expectation, and the option files (cutter tables, machine files) they name."""
    out: list[Path] = []
    for exp in sorted(golden.glob("*.expect.yaml")):
        name = exp.name[: -len(".expect.yaml")]
        out += [exp, golden / f"{name}.cbf"]
        out += sorted(p for p in golden.glob(f"{name}.*") if p.suffix in (".csv", ".yaml", ".json") and p not in out)
    return out


def stage(dest: Path) -> Path:
    if dest.exists():
        shutil.rmtree(dest)
    pkg = dest / "cbf_conformance"
    (pkg / "golden").mkdir(parents=True)
    for src in sorted((ROOT / "runner").glob("*.py")):
        shutil.copy2(RULE if src.name == RULE.name else src, pkg / src.name)
    for src in golden_files(ROOT / "golden"):
        shutil.copy2(src, pkg / "golden" / src.name)
    shutil.copy2(ROOT / "PROTOCOL.md", pkg / "PROTOCOL.md")
    for schema in SCHEMAS:  # the schemas PROTOCOL.md names ship beside it
        shutil.copy2(REPO / "generated" / "python" / "cbf" / schema, pkg / schema)
    version, revision = _stamp()
    (pkg / "_stamp.py").write_text(f'"""Written by conformance/kit.py when the kit was staged."""\n\n'
                                   f'VERSION = {version!r}\nSPEC_REVISION = {revision!r}\n',
                                   encoding="utf-8")
    shutil.copy2(ROOT / PAGE, dest / "README.md")
    (pkg / "py.typed").write_text("", encoding="utf-8")
    (dest / "pyproject.toml").write_text(f'''# Staged by `python -m conformance.kit`: the CBF conformance kit.
[build-system]
requires = ["setuptools>=69"]
build-backend = "setuptools.build_meta"

[project]
name = "cbf-conformance"
version = "{version}"
description = "Run the CBF (Cutfile Binary Format) golden cases against any reader that speaks PROTOCOL.md."
readme = "README.md"
requires-python = ">=3.11"
dependencies = ["pyyaml>=6.0,<7"]

[project.scripts]
cbf-conformance = "cbf_conformance.__main__:main"

[tool.setuptools]
packages = ["cbf_conformance"]

[tool.setuptools.package-data]
cbf_conformance = ["golden/*", "PROTOCOL.md", "*.schema.json", "layouts.json", "py.typed"]
''', encoding="utf-8")
    return dest


if __name__ == "__main__":
    if len(sys.argv) != 2:
        raise SystemExit("usage: python -m conformance.kit OUTDIR")
    print(stage(Path(sys.argv[1])))
