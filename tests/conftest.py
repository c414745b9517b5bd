"""Shared helpers: the repository, a spec copy with an extra command, generation."""

from __future__ import annotations

import contextlib
import copy
import functools
import io
import os
import re
import resource
import shutil
import subprocess
import sys
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import TYPE_CHECKING, Any

import pytest
import yaml
from hypothesis import HealthCheck, settings

if TYPE_CHECKING:
    from cbf.model import Cbf

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


def readme_ci_blocks() -> list[Any]:
    """The YAML blocks of README.md's section "In CI and before a commit", in order (the pre-commit
    config, then the GitHub and GitLab jobs): test_ci_examples runs them from this tree,
    test_release from the released wheel."""
    text = (REPO / "README.md").read_text(encoding="utf-8")
    start = text.index("### In CI and before a commit")
    section = text[start:text.index("\n## ", start)]
    return [yaml.safe_load(b) for b in re.findall(r"```yaml\n(.*?)```", section, re.S)]


def convert_fills(model: Cbf, target: str) -> dict[str, str]:
    """`--fill NAME=0` for each argument a record's target layout has and its own layout lacks
    (none in rev 03; a revision may add one, as the layout_change drill fixture does): what
    test_convert and test_convert_versions pass to convert."""
    out: dict[str, str] = {}
    for r in model.records:
        cmd = r.command
        src = cmd.layout_for_size(model.version_id, len(r.raw_args)) if cmd else None
        if cmd is None or src is None or not cmd.layouts_for(target):
            continue
        have = {a.name for a in src.args}
        out.update({a.name: "0" for a in cmd.layouts_for(target)[0].args if not a.reserved and a.name not in have})
    return out


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


def cbfgen_here(*argv: str) -> tuple[int, str, str]:
    """`cbfgen ARGV` run in this process (its main(): the same code and exit code, without the 0.3 CPU s of
    a Python start and the 0.17 of a process's first load): the exit code, stdout and stderr."""
    from cbfgen.__main__ import main  # noqa: PLC0415  (the generator, imported when a test generates)
    from cbfgen.emit import docs  # noqa: PLC0415

    # main() points the docs emitter at its inputs through the module's constants (ROOT, GOLDEN, REPORT, ...):
    # restored after, so that no later test of this process sees another run's folders
    saved = {k: v for k, v in vars(docs).items() if k.isupper()}
    out, err = io.StringIO(), io.StringIO()
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            code = main(list(argv))
    finally:
        for k in [k for k in vars(docs) if k.isupper() and k not in saved]:
            delattr(docs, k)
        for k, v in saved.items():
            setattr(docs, k, v)
    return code, out.getvalue(), err.getvalue()


def generate(spec: Path, out: Path, *only: str) -> None:
    """`cbfgen --spec spec --out out [--only ...]` (cbfgen_here); AssertionError with its stderr unless it exits 0."""
    argv = ["--spec", str(spec), "--out", str(out)]
    for o in only:
        argv += ["--only", o]
    code, _, err = cbfgen_here(*argv)
    assert code == 0, f"cbfgen {' '.join(argv)} exited {code}: {err[-3000:]}"


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
