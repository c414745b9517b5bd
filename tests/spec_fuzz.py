"""Spec fuzzing as a standing campaign (issue 36, point 2): `make fuzz-spec`.

A grammar-aware mutator of spec/cbf.yaml: it walks the parsed spec and changes one thing the
grammar lets a contributor change (a number to a boundary value, a string to an edge case or to
another name of the spec, a list item dropped or repeated, a key dropped, a value of another
type), plus the classes a hostile contributor found in issue 36 (each a fixed case, `CLASSES`).
Each mutant is then either

  refused   `cbfgen --check-spec` exits 2 with its lines and no traceback (`run` calls the loader in its
            own process instead: the same verdict without a process a mutant), or
  accepted  and then generated (Python, C and the documents), the C tool compiled under the project's strict
            flags (mk/c.mk's rule, so the flags are the build's own), the Python package imported,
            and both tools run over the golden files: `cbf validate` and `cbf-c validate` must
            print the same lines with the same exit status.

Anything else is a finding, by class: `crash:check-spec` (a traceback, a signal, the time or
memory cap), `broken:generate`, `broken:compile`, `broken:import`, `broken:crash` (a tool died on
a golden file), `broken:differ` (the two tools disagree), `broken:docs` (a document links a clause
anchor it lacks), `broken:cut-roundtrip` (the generated CUT
writer's text of a golden file is refused, or read as other records, by the generated reader).

    python tests/spec_fuzz.py run [--seed N] [--count N] [--jobs N] [--keep DIR] [--loader-only] [--index I ...]
    python tests/spec_fuzz.py case NAME        one fixed class (CLASSES), its outcome

`run` prints one line per mutant (seed, index, what changed, outcome) and a closing line with
the counts by outcome; it exits 1 when a mutant crashed or was accepted but broken. The same
seed gives the same mutants (random.Random(seed), the spec as it is); tests/test_spec_fuzz.py
runs a fixed sample and every fixed class in `make test`.
"""

from __future__ import annotations

import argparse
import copy
import hashlib
import json
import os
import random
import re
import resource
import shutil
import subprocess
import sys
import tempfile
import threading
import time
from collections import Counter, defaultdict, deque
from collections.abc import Callable, Iterator
from concurrent.futures import Future, ThreadPoolExecutor, wait
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

REPO = Path(__file__).resolve().parents[1]
SPEC = REPO / "spec" / "cbf.yaml"
GOLDEN = REPO / "conformance" / "golden"
_YAML_LOADER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
_YAML_DUMPER = getattr(yaml, "CSafeDumper", yaml.SafeDumper)
MEMORY = 2 << 30  # address space of each step: a spec that makes a step enumerate is a crash, not a hang
TIMEOUT = {"check": 30, "generate": 180, "compile": 240, "import": 60, "run": 300}
GOLDEN_MAX = 1 << 16  # the golden files both tools run over (the 1.3 MB one adds time, not cases)

Path_ = tuple[Any, ...]  # keys and indexes from the root of the spec


@dataclass(frozen=True)
class Mutant:
    what: str  # one line: the class and the change
    doc: Any


@dataclass(frozen=True)
class Outcome:
    kind: str  # refused | accepted | crash:... | broken:...
    detail: str  # the refusal's first line, or what broke

    @property
    def bad(self) -> bool:
        return self.kind.startswith(("crash", "broken"))


# -- the spec as data ---------------------------------------------------------------------------------
def load_spec() -> Any:
    return yaml.load(SPEC.read_text(encoding="utf-8"), Loader=_YAML_LOADER)


def dump(doc: Any) -> str:
    return str(yaml.dump(doc, Dumper=_YAML_DUMPER, sort_keys=False, allow_unicode=False, width=1 << 16))


def _walk(node: Any, path: Path_ = ()) -> Iterator[tuple[Path_, Any]]:
    yield path, node
    if isinstance(node, dict):
        for k, v in node.items():
            yield from _walk(v, (*path, k))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from _walk(v, (*path, i))


def _get(doc: Any, path: Path_) -> Any:
    for k in path:
        doc = doc[k]
    return doc


def _set(doc: Any, path: Path_, value: Any) -> None:
    _get(doc, path[:-1])[path[-1]] = value


def _show_path(path: Path_) -> str:
    return "".join(f"[{k}]" if isinstance(k, int) else f".{k}" for k in path).lstrip(".")


def _short(value: Any) -> str:
    text = json.dumps(value, default=str) if not isinstance(value, float) else repr(value)
    return text if len(text) <= 40 else f"{text[:30]}... ({len(text)} characters)"


# -- random mutations: one change the grammar allows ----------------------------------------------------
NUMBERS: tuple[Any, ...] = (0, 1, -1, 2, 255, 256, 65535, 65536, 2 ** 31, 2 ** 32, 2 ** 40, 2 ** 63, 2 ** 64,
                            10 ** 9, 0.5, -0.0, 3.5e38, 1e308, float("inf"), float("nan"), 12, 7)
STRINGS: tuple[str, ...] = ("", "[", "(", "*", "\\", " ", "x" * 4096, "é", "a b", "\t", "-", "0x",
                            "{{ x }}", "*/", "\"", "'", "<", "&")


def _leaves(doc: Any) -> list[tuple[Path_, Any]]:
    return [(p, v) for p, v in _walk(doc) if p and not isinstance(v, (dict, list))]


def _strings_of(doc: Any) -> list[str]:
    return sorted({v for _, v in _walk(doc) if isinstance(v, str) and 0 < len(v) <= 40})


def _number(rng: random.Random, doc: Any) -> str:
    leaves = [(p, v) for p, v in _leaves(doc) if isinstance(v, (int, float)) and not isinstance(v, bool)]
    path, old = rng.choice(leaves)
    new = rng.choice(NUMBERS + (old + 1, old - 1, -old))
    _set(doc, path, new)
    return f"number {_show_path(path)}: {_short(old)} -> {_short(new)}"


def _string(rng: random.Random, doc: Any) -> str:
    leaves = [(p, v) for p, v in _leaves(doc) if isinstance(v, str)]
    path, old = rng.choice(leaves)
    pool = STRINGS + tuple(rng.sample(_strings_of(doc), 6)) + (old.upper(), old + old, old[:-1] or "x")
    new = rng.choice(pool)
    _set(doc, path, new)
    return f"string {_show_path(path)}: {_short(old)} -> {_short(new)}"


def _drop(rng: random.Random, doc: Any) -> str:
    parents = [(p, v) for p, v in _walk(doc) if isinstance(v, (dict, list)) and v and len(p) >= 1]
    path, node = rng.choice(parents)
    key = rng.choice(list(node)) if isinstance(node, dict) else rng.randrange(len(node))
    del node[key]
    return f"drop {_show_path((*path, key))}"


def _repeat(rng: random.Random, doc: Any) -> str:
    lists = [(p, v) for p, v in _walk(doc) if isinstance(v, list) and v]
    path, node = rng.choice(lists)
    i = rng.randrange(len(node))
    node.insert(i + 1, copy.deepcopy(node[i]))
    return f"repeat {_show_path((*path, i))}"


def _retype(rng: random.Random, doc: Any) -> str:
    path, old = rng.choice(_leaves(doc))
    new = rng.choice([None, True, [old], {"x": old}, str(old), 0])
    _set(doc, path, new)
    return f"type {_show_path(path)}: {_short(old)} -> {_short(new)}"


def _rekey(rng: random.Random, doc: Any) -> str:
    """A mapping key renamed in place (the value and the order kept): misspelt, upper-cased, emptied,
    made a sibling's (that sibling then dropped, as a YAML mapping cannot hold a key twice), or a key of
    elsewhere in the spec. The loader's schema gate sees a key it does not know, or one it needs gone."""
    maps = [(p, v) for p, v in _walk(doc) if isinstance(v, dict) and v]
    path, node = rng.choice(maps)
    old = rng.choice(list(node))
    keys = sorted({str(k) for _, v in _walk(doc) if isinstance(v, dict) for k in v})
    new = rng.choice([old + "s", old[:-1] or "x", old.upper(), "", " " + old, *rng.sample(list(node), 1),
                      *rng.sample(keys, 2)])
    items = [(new if k == old else k, v) for k, v in node.items() if k != new or k == old]
    node.clear()
    node.update(items)
    return f"key {_show_path((*path, old))} -> {_short(new)}"


RANDOM: tuple[Callable[[random.Random, Any], str], ...] = (_number, _number, _string, _string, _drop, _repeat,
                                                           _retype, _rekey)


def mutants(seed: int, count: int) -> Iterator[tuple[int, Mutant]]:
    """``count`` mutants of the spec, the same for the same seed and spec."""
    base = load_spec()
    rng = random.Random(seed)
    names = sorted(CLASSES)
    for i in range(count):
        doc = copy.deepcopy(base)
        if rng.random() < 0.1:  # now and then one of the known classes, so a campaign keeps checking them
            name = rng.choice(names)
            yield i, Mutant(f"class {name}: {CLASSES[name][0](doc)}", doc)
            continue
        what = rng.choice(RANDOM)(rng, doc)
        while doc == base:  # a mutation that wrote what was there (a value a revision happens to hold): draw again
            doc = copy.deepcopy(base)
            what = rng.choice(RANDOM)(rng, doc)
        yield i, Mutant(what, doc)


# -- the classes of issue 36 (each a fixed regression case) ---------------------------------------------
def _first_range(doc: Any) -> dict[str, Any]:
    return next(c for c in doc["checks"] if c.get("kind") == "range" and c.get("min") is not None)


def _range_min_negative_zero(doc: Any) -> str:
    check = _first_range(doc)
    check["min"] = -0.0
    return f"checks[id={check['id']}].min: -0.0"


def _unreferenced_arg(doc: Any) -> tuple[dict[str, Any], str]:
    """An argument whose name appears nowhere else in the spec (renaming it breaks no reference)."""
    text = dump(doc)
    for cmd in doc["commands"]:
        for lay in cmd.get("layouts", []):
            for arg in lay.get("args", []):
                if len(re.findall(rf"\b{re.escape(arg['name'])}\b", text)) == 1:
                    return arg, cmd["name"]
    raise AssertionError("every argument name is referenced elsewhere")


def _long_name(doc: Any) -> str:
    arg, cmd = _unreferenced_arg(doc)
    arg["name"] = "n" * 4096
    return f"an argument of {cmd} named with 4096 characters"


def _repeat_max_huge(doc: Any) -> str:
    for cmd in doc["commands"]:
        m = cmd.get("motion") or {}
        if m.get("kind") == "point" and len(cmd.get("layouts", [])) >= 1:
            lay = cmd["layouts"][-1]
            if len(lay["args"]) == 1 and lay["args"][0]["name"] == m.get("end"):
                lay["size"] = 0
                lay["args"][0]["repeat"] = {"min": 1, "max": 1000000000}
                return f"{cmd['name']}.{lay['args'][0]['name']}: repeat {{min: 1, max: 1000000000}}"
    raise AssertionError("no point motion of one argument")


def _set_path(path: Path_, value: Any) -> Callable[[Any], str]:
    def apply(doc: Any) -> str:
        _set(doc, path, value)
        return f"{_show_path(path)}: {_short(value)}"
    return apply


def _header_keyword_is_a_command(doc: Any) -> str:
    kw = doc["commands"][0]["name"]
    kw = kw.lower() if doc["cut"].get("keyword_case") == "lower" else kw
    doc["cut"]["header_keyword"] = kw
    return f"cut.header_keyword: {kw!r} (a command's keyword)"


def _separators_collide(doc: Any) -> str:
    doc["cut"]["vector_separator"] = doc["cut"]["arg_separator"]
    return f"cut.vector_separator: {doc['cut']['arg_separator']!r} (the arg_separator)"


def _note_names_nothing(doc: Any) -> str:
    clause = next(c for c in doc["meta"]["clauses"] if c.get("notes"))
    clause["notes"] = [*clause["notes"], "ZZ99"]
    return f"meta.clauses[number={clause['number']}].notes: + ZZ99 (no decision or erratum)"


def _check_cites_no_clause(doc: Any) -> str:
    numbers = {c["number"] for c in doc["meta"]["clauses"]}
    check = next(c for c in doc["checks"] if c.get("clause") in numbers)
    check["clause"] = "9.9.9"
    return f"checks[id={check['id']}].clause: 9.9.9 (not in meta.clauses)"


def _code_negative_zero(doc: Any) -> str:
    cmd = doc["commands"][0]
    cmd["code"] = -0.0
    return f"commands[name={cmd['name']}].code: -0.0"


def _tolerance_nan(doc: Any) -> str:
    key = next(iter(doc["tolerances"]))
    doc["tolerances"][key] = float("nan")
    return f"tolerances.{key}: nan"


# name -> (apply, the loader rule that refuses it (issue 36, point 1), or None when a build that
# behaves alike is as good as a refusal)
CLASSES: dict[str, tuple[Callable[[Any], str], str | None]] = {
    "repeat_max_1e9": (_repeat_max_huge, "repeat-groups"),
    "max_commands_2_40": (_set_path(("limits", "max_commands"), 1 << 40), "limits"),
    "max_commands_float": (_set_path(("limits", "max_commands"), 3.5e38), "schema"),
    "code_negative_zero": (_code_negative_zero, "schema"),
    "float_pattern_bracket": (_set_path(("cut", "float_pattern"), "["), "cut"),
    "float_pattern_list": (_set_path(("cut", "float_pattern"), ["-?\\d+"]), "schema"),
    "header_keyword_is_a_command": (_header_keyword_is_a_command, "cut"),
    "vector_separator_is_arg_separator": (_separators_collide, "schema"),
    "clause_note_names_nothing": (_note_names_nothing, "notes"),
    "check_cites_no_clause": (_check_cites_no_clause, "clauses"),
    "name_4096": (_long_name, "schema"),
    "string_padding_32": (_set_path(("meta", "string_padding"), 32), "padding"),
    "range_min_negative_zero": (_range_min_negative_zero, "numbers"),
    "tolerance_nan": (_tolerance_nan, "numbers"),
}


def class_mutant(name: str) -> Mutant:
    doc = load_spec()
    return Mutant(f"class {name}: {CLASSES[name][0](doc)}", doc)


# -- running one mutant -----------------------------------------------------------------------------------
def _cap(cpu: int) -> Callable[[], None]:
    """Caps of a step: address space, and CPU seconds (not wall time: on a loaded machine a nice'd
    step waits, which is no fault of the spec; a wall-clock cap twenty times longer backs it up)."""
    def apply() -> None:
        resource.setrlimit(resource.RLIMIT_AS, (MEMORY, MEMORY))
        resource.setrlimit(resource.RLIMIT_CPU, (cpu, cpu + 5))
        os.nice(5)
    return apply


def _run(argv: list[str], step: str, env: dict[str, str] | None = None,
         cwd: Path | None = None) -> subprocess.CompletedProcess[str] | None:
    try:
        return subprocess.run(argv, env=env, cwd=cwd or REPO, capture_output=True, text=True, errors="replace",
                              timeout=20 * TIMEOUT[step], preexec_fn=_cap(TIMEOUT[step]))
    except subprocess.TimeoutExpired:
        return None


def _crashed(res: subprocess.CompletedProcess[str] | None) -> str | None:
    """Why a step did not end as a tool should: a timeout, a signal, a traceback; None if it did."""
    if res is None:
        return "timed out"
    if res.returncode < 0:
        import signal

        if -res.returncode == signal.SIGXCPU:
            return "over its CPU time cap"
        return f"killed by signal {-res.returncode}"
    for marker in ("Traceback (most recent call last)", "MemoryError", "Segmentation fault", "AddressSanitizer"):
        if marker in res.stderr:
            tail = res.stderr.strip().splitlines()[-1] if res.stderr.strip() else marker
            return tail[:200]
    return None


def _first(text: str) -> str:
    lines = text.strip().splitlines()
    return lines[0][:200] if lines else ""


_CFLAGS: list[str] = []


def _strict_flags() -> list[str]:
    """The C build's strict flags, from mk/c.mk (C_STRICT), read once."""
    if not _CFLAGS:
        text = (REPO / "mk" / "c.mk").read_text(encoding="utf-8")
        defs = dict(re.findall(r"^(C_\w+) :?= (.*)$", text, re.M))
        flags = re.sub(r"\$\((\w+)\)", lambda m: defs.get(m.group(1), ""), defs["C_STRICT"])
        _CFLAGS.extend(flags.split())
    return _CFLAGS


def _goldens() -> list[str]:
    return [str(p) for p in sorted(GOLDEN.glob("*.cbf")) if p.stat().st_size <= GOLDEN_MAX]


# The generated CUT writer's text of each golden file must read back, record for record, with the
# generated reader (a header keyword equal to a command's, or two equal separators, broke that).
_ROUNDTRIP = """
import sys
import cbf
from cbf import tables as T
from cbf.cut import from_cut, to_cut
for path in sys.argv[1:]:
    try:
        model = cbf.decode(open(path, "rb").read())
        if T.version_id(*model.version) is None:
            continue  # a version the spec does not have: CUT names versions of the spec only
        text = to_cut(model)
    except (cbf.CbfError, ValueError):
        continue  # not decodable, or nothing CUT carries (trailing bytes): no text to read back
    try:
        back = from_cut(text)
    except cbf.CbfError as exc:
        print(f"{path}: the CUT writer's text is refused by the reader: {exc}")
        sys.exit(1)
    key = lambda m: [(r.code, bytes(r.raw_args), r.reserved, r.code if r.code_copy is None else r.code_copy)
                     for r in m.records]
    if key(back) != key(model):
        print(f"{path}: the CUT text reads back as other records")
        sys.exit(1)
"""


_LINK = re.compile(r"\]\(([^)#\s]*)#(clause-[^)\s]+)\)")


def _dead_clause_links(docs: Path) -> str:
    """The first link of the generated documents to a clause anchor its target file lacks ('' if none):
    a check citing a clause meta.clauses does not hold linked nowhere."""
    for page in sorted(docs.rglob("*.md")):
        text = page.read_text(encoding="utf-8", errors="replace")
        for target, anchor in _LINK.findall(text):
            dest = (page.parent / target).resolve() if target else page
            if not dest.is_file() or f'id="{anchor}"' not in dest.read_text(encoding="utf-8", errors="replace"):
                return f"{page.relative_to(docs)}: a link to {target}#{anchor}, which it lacks"
    return ""


def judge(mutant: Mutant, work: Path, seen: dict[str, Outcome] | None = None) -> Outcome:
    """Refused with a line by `cbfgen --check-spec` (a process), or built alike (``build``)."""
    work.mkdir(parents=True, exist_ok=True)
    spec = work / "cbf.yaml"
    spec.write_text(dump(mutant.doc), encoding="utf-8")
    py = sys.executable
    env = dict(os.environ, PYTHONPATH=str(REPO / "generator"), PYTHONDONTWRITEBYTECODE="1")
    res = _run([py, "-m", "cbfgen", "--check-spec", "--spec", str(spec)], "check", env)
    why = _crashed(res)
    if why is not None:
        return Outcome("crash:check-spec", why)
    assert res is not None
    if res.returncode != 0:
        if res.returncode == 2 and res.stderr.strip():
            return Outcome("refused", _first(res.stderr))
        return Outcome("crash:check-spec", f"exit {res.returncode}: {_first(res.stderr)}")
    return build(spec, work, seen)


def _digest(out: Path) -> str:
    """What the Python package and the C tool are made of: two mutants with the same digest compile, import
    and run alike (the golden files are the same), so the second reuses the first's outcome."""
    h = hashlib.sha256()
    for top in ("python", "c"):
        for p in sorted((out / top).rglob("*")):
            if p.is_file() and "__pycache__" not in p.parts:
                h.update(p.relative_to(out).as_posix().encode() + b"\0" + p.read_bytes() + b"\0")
    return h.hexdigest()


_SEEN = threading.Lock()


def build(spec: Path, work: Path, seen: dict[str, Outcome] | None = None) -> Outcome:
    """A spec the loader accepted: generated, compiled, imported and run alike by both tools. ``seen`` maps the
    digest of a generated Python package and C tool to its outcome (the documents are judged every time)."""
    py = sys.executable
    env = dict(os.environ, PYTHONPATH=str(REPO / "generator"), PYTHONDONTWRITEBYTECODE="1")
    out = work / "gen"
    res = _run([py, "-m", "cbfgen", "--spec", str(spec), "--out", str(out), "--only", "python", "--only", "c",
                "--only", "docs"],
               "generate", env)
    why = _crashed(res) or (None if res is None or res.returncode == 0 else f"exit {res.returncode}: "
                            f"{_first(res.stderr)}")
    if why is not None:
        return Outcome("broken:generate", why)
    dead = _dead_clause_links(out / "docs")
    if dead:
        return Outcome("broken:docs", dead)
    digest = _digest(out)
    with _SEEN:
        first = None if seen is None else seen.get(digest)
    if first is not None:
        return Outcome(first.kind, f"{first.detail} (its Python and C alike an earlier mutant's: not rebuilt)")
    outcome = _compile_and_run(out, work)
    if seen is not None:
        with _SEEN:
            seen[digest] = outcome
    return outcome


def _compile_and_run(out: Path, work: Path) -> Outcome:
    py = sys.executable
    tool = work / "cbf-c"
    res = _run(["gcc", *_strict_flags(), "-O1", "-o", str(tool), str(out / "c" / "cbf_tool.c"), "-lm"], "compile",
               cwd=out / "c")
    why = _crashed(res) or (None if res is None or res.returncode == 0 else _first(
        "\n".join(ln for ln in res.stderr.splitlines() if "error" in ln) or res.stderr))
    if why is not None:
        return Outcome("broken:compile", why)
    penv = dict(os.environ, PYTHONPATH=str(out / "python"), PYTHONDONTWRITEBYTECODE="1")
    res = _run([py, "-c", "import cbf, cbf.cli, cbf.validation, cbf.cut, cbf.canonical, cbf.writer, cbf.convert; "
                          "cbf.cli.parser()"], "import", penv, cwd=work)
    why = _crashed(res) or (None if res is None or res.returncode == 0 else _first(res.stderr))
    if why is not None:
        return Outcome("broken:import", why)
    files = _goldens()
    res = _run([py, "-c", _ROUNDTRIP, *files], "run", penv, cwd=work)
    why = _crashed(res) or (None if res is None or res.returncode == 0 else _first(res.stdout + res.stderr))
    if why is not None:
        return Outcome("broken:cut-roundtrip", why)
    pres = _run([py, "-m", "cbf", "validate", "--jobs", "1", "--max-findings", "0", *files], "run", penv, cwd=work)
    cres = _run([str(tool), "validate", "--max-findings", "0", *files], "run", cwd=work)
    for name, r in (("cbf", pres), ("cbf-c", cres)):
        why = _crashed(r)
        if why is not None:
            return Outcome("broken:crash", f"{name}: {why}")
    assert pres is not None and cres is not None
    plines, clines = pres.stdout.splitlines()[:-1], cres.stdout.splitlines()  # the batch summary: cbf's alone
    if plines != clines or pres.returncode != cres.returncode:
        diff = next((f"cbf: {a!r} / cbf-c: {b!r}" for a, b in zip(plines, clines, strict=False) if a != b),
                    f"{len(plines)} lines / {len(clines)} lines, exit {pres.returncode} / {cres.returncode}")
        return Outcome("broken:differ", diff[:300])
    return Outcome("accepted", f"{len(plines)} lines alike over {len(files)} golden files")


# -- the campaign ---------------------------------------------------------------------------------------
def judge_loader(mutant: Mutant, work: Path) -> Outcome:
    """The loader alone, in this process (``run --loader-only``: the gate of every mutant in seconds, not
    the build): refused with its lines, accepted, or a crash (any exception but SpecError, or over
    TIMEOUT["check"] seconds: a spec that makes the loader enumerate)."""
    import signal

    from cbfgen.loader import SpecError, load

    work.mkdir(parents=True, exist_ok=True)
    spec = work / "cbf.yaml"
    spec.write_text(dump(mutant.doc), encoding="utf-8")

    def late(_sig: int, _frame: Any) -> None:
        raise TimeoutError(f"over {TIMEOUT['check']} s")

    old = signal.signal(signal.SIGALRM, late)
    signal.alarm(TIMEOUT["check"])
    try:
        load(spec)
    except SpecError as exc:
        line = _first(str(exc))
        return Outcome("refused", line) if line else Outcome("crash:check-spec", "a refusal without a line")
    except BaseException as exc:  # noqa: BLE001 - any other end of the loader is the finding
        return Outcome("crash:check-spec", f"{type(exc).__name__}: {exc}"[:200])
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)
    return Outcome("accepted", "by the loader (not built: --loader-only)")


def run(seed: int, count: int, jobs: int, keep: Path | None, loader_only: bool = False,
        only: frozenset[int] = frozenset()) -> int:
    """Every mutant through the loader in this process first (what `--check-spec` runs: a refusal is its
    SpecError's lines, a crash any other end; a process each cost a second a mutant); the accepted ones,
    unless ``loader_only``, then built in ``jobs`` threads, a mutant whose generated Python and C equal an
    earlier one's reusing its outcome. ``only``: judge just these indexes of the campaign (its failing
    mutants, again), the others drawn and skipped."""
    base = Path(tempfile.mkdtemp(prefix="spec-fuzz-"))
    counts: Counter[str] = Counter()
    by_class: defaultdict[str, Counter[str]] = defaultdict(Counter)  # mutation class -> outcomes
    start = time.monotonic()
    sys.path.insert(0, str(REPO / "generator"))
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY, MEMORY))  # the loader's cap, as _cap gives --check-spec
    seen: dict[str, Outcome] = {}

    def built(spec: Path, work: Path) -> Outcome:
        try:
            return build(spec, work, seen)
        finally:
            shutil.rmtree(work, ignore_errors=True)

    bad = 0
    pending: deque[tuple[int, Mutant, Future[Outcome]]] = deque()

    def report(block: bool) -> None:
        nonlocal bad
        while pending and (block or pending[0][2].done()):
            i, m, fut = pending.popleft()
            o = fut.result()
            counts[o.kind] += 1
            by_class[m.what.split(" ", 1)[0]][o.kind] += 1
            bad += o.bad
            print(f"spec-fuzz seed {seed} #{i}: {m.what}: {o.kind}: {o.detail}", flush=True)
            if keep is not None and o.bad:
                keep.mkdir(parents=True, exist_ok=True)
                (keep / f"seed{seed}-{i:05d}.yaml").write_text(dump(m.doc), encoding="utf-8")

    try:
        with ThreadPoolExecutor(max(1, jobs)) as pool:
            for i, m in mutants(seed, count):
                if only and i not in only:
                    continue
                work = base / f"m{i:05d}"
                o = judge_loader(m, work)
                if o.kind == "accepted" and not loader_only:
                    pending.append((i, m, pool.submit(built, work / "cbf.yaml", work)))
                else:
                    shutil.rmtree(work, ignore_errors=True)
                    done: Future[Outcome] = Future()
                    done.set_result(o)
                    pending.append((i, m, done))
                while len(pending) > 4 * max(1, jobs) and not pending[0][2].done():
                    wait([pending[0][2]])  # the loader no further ahead of the builds than a few mutants
                report(False)
            report(True)
    finally:
        shutil.rmtree(base, ignore_errors=True)
    took = time.monotonic() - start
    by = ", ".join(f"{n} {k}" for k, n in sorted(counts.items()))
    rebuilt = f"; {len(seen)} distinct builds" if not loader_only else ""
    print(f"spec-fuzz: {sum(counts.values())} mutants (seed {seed}) in {took:.0f} s: {by}; "
          f"{bad} crashed or accepted-but-broken{rebuilt}")
    print("spec-fuzz: by mutation class: " + "; ".join(
        f"{name} {sum(c.values())} ({', '.join(f'{n} {k}' for k, n in sorted(c.items()))})"
        for name, c in sorted(by_class.items())))
    return 1 if bad else 0


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="spec_fuzz.py", description=__doc__.split("\n\n")[0] if __doc__ else None)
    sub = p.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("run", help="a campaign of random mutants")
    r.add_argument("--seed", type=int, default=None, help="default: from the clock (printed)")
    r.add_argument("--count", type=int, default=1000)
    r.add_argument("--jobs", type=int, default=1)
    r.add_argument("--keep", type=Path, help="write each crashing or broken mutant's spec here")
    r.add_argument("--index", type=int, action="append", default=[],
                   help="judge only this mutant of the campaign (repeatable): its failing mutants again")
    r.add_argument("--loader-only", action="store_true",
                   help="judge each mutant by the loader alone, in this process (refused, accepted, or a crash)")
    c = sub.add_parser("case", help="one fixed class of issue 36")
    c.add_argument("name", choices=sorted(CLASSES))
    a = p.parse_args(argv)
    if a.cmd == "case":
        with tempfile.TemporaryDirectory(prefix="spec-fuzz-") as tmp:
            m = class_mutant(a.name)
            o = judge(m, Path(tmp))
            print(f"{m.what}: {o.kind}: {o.detail}")
            return 1 if o.bad else 0
    seed = a.seed if a.seed is not None else int(time.time())
    return run(seed, a.count, a.jobs, a.keep, a.loader_only, frozenset(a.index))


if __name__ == "__main__":
    sys.exit(main())
