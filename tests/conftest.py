"""Shared helpers: the repository, a spec copy with an extra command, generation."""

from __future__ import annotations

import copy
import functools
import os
import re
import resource
import shutil
import subprocess
import sys
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any

import pytest
import yaml
from hypothesis import HealthCheck, settings

# libyaml's parser (PyYAML's C binding) when present: the same values, about ten times faster than
# yaml.safe_load (0.013 against 0.12 CPU s for spec/cbf.yaml, which many tests read).
YAML_LOADER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


YAML_DUMPER = getattr(yaml, "CSafeDumper", yaml.SafeDumper)


def load_yaml(path: Path) -> Any:
    """A YAML file's data, as yaml.safe_load gives it."""
    return yaml.load(path.read_text(encoding="utf-8"), Loader=YAML_LOADER)


@functools.cache
def _spec_yaml() -> Any:
    return load_yaml(SPEC)


def spec_doc() -> dict[str, Any]:
    """spec/cbf.yaml as data, parsed once per process: a deep copy of its own, for the caller to edit."""
    return copy.deepcopy(_spec_yaml())


def dump_yaml(data: Any, **options: Any) -> str:
    """data as YAML text, as yaml.safe_dump writes it (options: sort_keys, width, ...)."""
    return str(yaml.dump(data, Dumper=YAML_DUMPER, **options))

# Hypothesis never decides whether a submission lands (issue 13, item 17). `make test`
# loads the derandomised "ci" profile: a fixed seed per test and no example database,
# so the same commit draws the same examples every time. Random exploration is
# `make test-long` (HYPOTHESIS_PROFILE=long, 5,000 examples); what it finds becomes an @example.
# The ci profile draws 100 examples a test (200 took 150 of pytest's 650 CPU s in `make test`).
_HEALTH = [HealthCheck.too_slow, HealthCheck.data_too_large, HealthCheck.filter_too_much]
settings.register_profile("ci", derandomize=True, database=None, deadline=None, print_blob=True,
                          max_examples=100, suppress_health_check=_HEALTH)
settings.register_profile("long", derandomize=False, database=None, deadline=None, print_blob=True,
                          max_examples=5000, suppress_health_check=_HEALTH)
HYPOTHESIS_PROFILE = os.environ.get("HYPOTHESIS_PROFILE", "ci")
settings.load_profile(HYPOTHESIS_PROFILE)

REPO = Path(__file__).resolve().parents[1]
SPEC = REPO / "spec" / "cbf.yaml"

# -- the environments tests run tools in -------------------------------------------------------
# `python -m cbf` of this checkout's generated package, as `make test` runs it
ENV = dict(os.environ, PYTHONPATH=str(REPO / "generated" / "python"))
# a consumer's environment: none of this checkout's paths (the packages used from outside, issue 14)
CLEAN_ENV = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "NODE_PATH")}


def run_clean(*cmd: str | Path, cwd: Path, check: bool = True,
              env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    """A command (its text captured) in a consumer's environment (``env``: another one)."""
    return subprocess.run([str(c) for c in cmd], cwd=cwd, capture_output=True, text=True, check=check,
                          env=CLEAN_ENV if env is None else env)


def pytest_configure(config: pytest.Config) -> None:
    """The suite's CPU budget (tests/cpu_budget.py): each test's CPU seconds, when CBF_CPU_REPORT names a folder."""
    import cpu_budget

    cpu_budget.register(config)


@pytest.fixture(scope="session")
def html_site(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The HTML site of spec/cbf.yaml as `make docs` builds it, built once a session: tests only read it."""
    from cbfgen.emit.docs import site
    from cbfgen.loader import load

    out = tmp_path_factory.mktemp("site")
    site.build(load(SPEC), out)
    return out


def cover_missing(spec: dict[str, Any], command: dict[str, Any], preferred: Iterable[str] = ()) -> None:
    """Name a command added to a parsed spec in one availability check for each version it lacks (loader.py):
    a preferred check when it covers that version, else the first that does, else a new one."""
    has = {v for lay in command["layouts"] for v in lay["versions"]}
    preferred = {str(p) for p in preferred}
    gates = [c for c in spec["checks"] if c["kind"] == "availability"]
    covered = {v for c in gates if command["name"] in c["commands"] for v in c["versions"]}
    for v in spec["versions"]:
        if v["id"] in has or v["id"] in covered:
            continue
        # a check that names the command covers it in each of its versions: none may have the command, nor
        # be covered for it already (a real revision's check may span versions another check gates too)
        covering = [c for c in gates if v["id"] in c["versions"] and not set(c["versions"]) & (has | covered)]
        if not covering:  # a version that lacks nothing else yet
            # a check id the schema takes ([a-z][a-z0-9_]*): a version id such as "5.0" or "1.x" spelled with "_"
            ident = "fixture_" + re.sub(r"[^a-z0-9_]", "_", str(v["id"]).lower())
            covering = [{"id": ident, "kind": "availability", "severity": "error",
                         "versions": [v["id"]], "commands": [], "decision": spec["decisions"][0]["id"],
                         "text": "The fixture command is not in this version.", "fails": "A record holds it."}]
            spec["checks"].append(covering[0])
            gates.append(covering[0])
        chosen = next((c for c in covering if str(c["id"]) in preferred), covering[0])
        if command["name"] not in chosen["commands"]:
            chosen["commands"].append(command["name"])
        covered |= set(chosen["versions"])


def spec_with_fixture_command(tmp: Path) -> Path:
    """spec/cbf.yaml plus tests/fixtures/dwell_command.yaml, written to tmp."""
    spec = spec_doc()
    extra = load_yaml(REPO / "tests" / "fixtures" / "dwell_command.yaml")
    spec["units"].update(extra["units"])
    # a revision may have taken its code or dropped one of its versions: the next free code, the versions there are
    cmd, used = extra["command"], {int(c["code"]) for c in spec["commands"]}
    cmd["code"] = next(c for c in [*range(int(cmd["code"]), 256), *range(1, 256)] if c not in used)
    ids = {str(v["id"]) for v in spec["versions"]}
    for lay in cmd["layouts"]:
        lay["versions"] = [v for v in lay["versions"] if v in ids]
    spec["commands"].append(cmd)
    cover_missing(spec, extra["command"], extra.get("covered_by", ()))
    path = tmp / "cbf.yaml"
    path.write_text(yaml.safe_dump(spec, sort_keys=False), encoding="utf-8")
    return path


def generate(spec: Path, out: Path, *only: str) -> None:
    cmd = [sys.executable, "-m", "cbfgen", "--spec", str(spec), "--out", str(out)]
    for o in only:
        cmd += ["--only", o]
    subprocess.run(cmd, cwd=REPO, check=True, capture_output=True)


@pytest.fixture
def repo() -> Path:
    return REPO


# -- bad-input files, shared by the CLI tests (test_exit_codes.py, test_cli_bad_input.py) -------
# Root reads any file whatever its mode: without these two capabilities it is held to the mode
# bits like any user (CI runs as root).
AS_UNPRIVILEGED_ROOT = ["setpriv", "--bounding-set", "-dac_override,-dac_read_search"]


def file_maker(name: str, data: bytes) -> Callable[[Path], Path]:
    """A maker of the file ``name`` holding ``data`` in a given folder."""
    def make(tmp: Path) -> Path:
        p = tmp / name
        p.write_bytes(data)
        return p
    return make


def locked_file(tmp: Path, data: bytes) -> Path:
    """A file nobody but root may read (mode 0); see unprivileged_prefix()."""
    p = tmp / "locked.cbf"
    p.write_bytes(data)
    p.chmod(0)
    return p


def unprivileged_prefix() -> list[str]:
    """What runs a command held to the mode bits: nothing, or setpriv as root; skips when it cannot."""
    if os.geteuid() != 0:
        return []
    if shutil.which(AS_UNPRIVILEGED_ROOT[0]) is None:
        pytest.skip("running as root, which reads any file whatever its mode, and setpriv is missing")
    return AS_UNPRIVILEGED_ROOT


# -- consumer venvs (issue 14: the packages used from outside this checkout) ---------------------
def clean_venv(where: Path, *wheels: Path) -> Path:
    """A consumer's fresh venv holding only ``wheels`` and what they depend on; returns its bin/.

    This checkout's pinned pip installs into it (``pip --python``), so the venv gets no pip of its
    own (ensurepip costs about 8 CPU seconds a venv), and no bytecode is compiled (about 3 more):
    what the consumer tests check (which modules import, which commands run) is the same."""
    env = CLEAN_ENV
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(where)], check=True, capture_output=True,
                   env=env)
    subprocess.run([sys.executable, "-m", "pip", "--python", str(where / "bin" / "python"), "install", "-q",
                    "--no-compile", "--disable-pip-version-check", *map(str, wheels)], check=True,
                   capture_output=True, env=env)
    return where / "bin"


def capped_run(argv: list[str], env: dict[str, str] | None, memory: int,
               timeout: float) -> subprocess.CompletedProcess[str]:
    """argv under an address-space cap of ``memory`` bytes; past ``timeout`` seconds it is killed and
    subprocess.TimeoutExpired fails the test (the time bound of the bounded-cost tests)."""

    def cap() -> None:
        resource.setrlimit(resource.RLIMIT_AS, (memory, memory))

    return subprocess.run(argv, env=env, capture_output=True, text=True, preexec_fn=cap, timeout=timeout)


def file_checksum_of(data: bytes) -> int:
    """The file checksum an encoded CBF states in its header (the field and byte order from the model):
    the number a CUT text's check_sum line must give."""
    from cbf import tables as T

    f = T.HEADER_CHECKSUM_FIELDS["file"]
    return int.from_bytes(data[f.offset:f.offset + f.size], "little" if T.BO == "<" else "big")


def cite_clause(spec: dict[str, Any], number: str, text: str, section_title: str = "Revisions") -> None:
    """Give a parsed spec the text of a clause a new check cites (the loader refuses a citation the
    document cannot quote): the clause in meta.clauses and, when new, its section in meta.sections."""
    meta = spec["meta"]
    section = str(number).split(".")[0]
    if not any(str(s["id"]) == section for s in meta["sections"]):
        meta["sections"].append({"id": section, "title": section_title})
    if not any(str(c["number"]) == str(number) for c in meta["clauses"]):
        meta["clauses"].append({"number": str(number), "text": text})
