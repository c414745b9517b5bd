"""Every binding names the toolkit version and the spec revision it was generated from,
and they agree with their one source (cbfgen.__version__, the spec's meta)."""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import cbf
import cbfgen
from cbfgen.loader import load

REPO = Path(__file__).resolve().parents[1]


def test_python_binding_names_version_and_revision() -> None:
    spec = load(REPO / "spec" / "cbf.yaml")
    assert cbf.__version__ == cbfgen.__version__
    assert cbf.SPEC_REVISION == spec.revision
    assert spec.meta["part_number"] in spec.revision and spec.meta["revision"] in spec.revision


def test_c_header_names_version_revision_and_licence() -> None:
    header = (REPO / "generated" / "c" / "cbf.h").read_text(encoding="utf-8")
    assert re.search(rf'#define CBF_TOOLKIT_VERSION "{re.escape(cbfgen.__version__)}"', header)
    assert f'#define CBF_SPEC_REVISION "{cbf.SPEC_REVISION}"' in header
    assert f"SPDX-License-Identifier: {cbfgen.__license__}" in header
    pc = (REPO / "generated" / "c" / "cbf.pc.in").read_text(encoding="utf-8")
    assert f"Version: {cbfgen.__version__}" in pc


def test_pyproject_takes_version_and_licence_from_cbfgen() -> None:
    project = tomllib.loads((REPO / "pyproject.toml").read_text(encoding="utf-8"))
    assert "version" in project["project"]["dynamic"]
    assert project["tool"]["setuptools"]["dynamic"]["version"] == {"attr": "cbf.version.__version__"}
    assert project["project"]["license"] == {"text": cbfgen.__license__}
