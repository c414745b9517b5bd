"""Goldens follow the spec's checksums (#12 point 2).

The assembler computes every checksum with the algorithm and coverage the
spec declares. Under a revision that changes them (made here from the spec's
own lists, not from rev 03's values), every golden case assembled with the
revised spec must still meet its unchanged expectation in a Python runtime
generated from the same revised spec: the two share no code, so a fixed
algorithm in either one fails this test. For rev 03 itself the committed
bytes do not change (test_golden_assembly). The 65,535-record case is checked
under the revision that changes all of its checksums (REVISIONS says why not
under the others).
"""

from __future__ import annotations

import functools
import json
import os
import shutil
import subprocess
import sys
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest
import yaml
from conftest import load_yaml, spec_doc

from cbfgen.registry import ALGORITHMS
from conformance.assembler import assemble, assemble_text
from conformance.assembler.spec import load as load_sums
from conformance.runner.compare import findings_difference

ROOT = Path(__file__).resolve().parents[1]
SPEC = ROOT / "spec" / "cbf.yaml"
GOLDEN = ROOT / "conformance" / "golden"
Doc = dict[str, Any]


@dataclass(frozen=True)
class Case:
    """A golden case as committed: its .hex source, its .cbf bytes and its parsed expectation."""
    name: str
    source: str
    committed: bytes
    expect: Doc


@functools.cache
def golden_cases() -> tuple[Case, ...]:
    """Every golden case, in name order, read once per module (each test used to parse the 64
    expectations again: about 0.13 CPU s a test). The tests only read them."""
    out = []
    for src in sorted(GOLDEN.glob("*.hex")):
        name = src.name[: -len(".hex")]
        out.append(Case(name, src.read_text(encoding="utf-8"), (GOLDEN / f"{name}.cbf").read_bytes(),
                        load_yaml(GOLDEN / f"{name}.expect.yaml")))
    return tuple(out)


def largest_case() -> str:
    """The golden case with the most bytes (65,535 records, 1.4 MB): about 1.35 CPU s to assemble
    and, in the writer test, about 5 s to decode and encode with both bindings, where every other
    case together takes a tenth of a second. See REVISIONS for where it is kept."""
    return max(golden_cases(), key=lambda c: len(c.committed)).name


def _widths(doc: Doc) -> dict[str, int]:
    """Bits of the field that stores each checksum tag, read from the YAML."""
    sizes = {n: t.get("size") for n, t in doc["types"].items()}
    fields = [f for h in doc["headers"].values() for f in h["fields"]] + doc["record"]["fields"]
    fields += [a for c in doc["commands"] for lay in c["layouts"] for a in lay["args"]]  # issue 25, point 1
    return {f["checksum"]: 8 * sizes[f["type"]] for f in fields if "checksum" in f}


def _fitting(doc: Doc, bits: int, avoid: set[str]) -> str:
    """A non-sum algorithm of the spec whose result fits `bits`, not in `avoid` when possible."""
    fit = [n for n, a in doc["checksums"]["algorithms"].items()
           if ALGORITHMS[a["kind"]].family != "sum" and (ALGORITHMS[a["kind"]].width or 0) <= bits]
    assert fit, "the spec lists no non-sum algorithm that fits"
    return next((n for n in fit if n not in avoid), fit[0])


def every_field_another_algorithm(doc: Doc) -> None:
    """Each checksum field switches to another, non-sum algorithm (profiles follow the file field),
    one no profile names either: a profile's own file algorithm stays apart from the field's (else
    the two coverages of an empty file would sum alike again)."""
    widths = _widths(doc)
    used = {p["file_algorithm"] for p in doc["profiles"] if p.get("file_algorithm")}
    for f in doc["checksums"]["fields"]:
        f["algorithm"] = _fitting(doc, widths[f["field"]], used | {f["algorithm"]})
        used.add(f["algorithm"])


def last_profile_another_algorithm(doc: Doc) -> None:
    """The last profile computes the file checksum with another, non-sum algorithm."""
    file_alg = next(f["algorithm"] for f in doc["checksums"]["fields"] if f["field"] == "file")
    named = {p["file_algorithm"] for p in doc["profiles"] if p.get("file_algorithm")}
    doc["profiles"][-1]["file_algorithm"] = _fitting(doc, _widths(doc)["file"], {file_alg} | named)


def header_coverage_moves(doc: Doc) -> None:
    """The header checksum covers fewer bytes (its first header segment starts 6 bytes later)."""
    cov = next(f["coverage"] for f in doc["checksums"]["fields"] if f["field"] == "header")
    seg = next(s for s in doc["checksums"]["coverages"][cov]["segments"] if s["region"] == "header")
    assert seg["end"] - seg["start"] > 6
    seg["start"] += 6


def _every(name: str, profile: str, source: str, doc: Doc) -> bool:
    return True


def _unchanged_profiles(name: str, profile: str, source: str, doc: Doc) -> bool:
    """A profile that changes its algorithm changes what a file written by another profile means
    under it (an empty file then fails its file checksum): those expectations are the revision's
    to change. Kept: every other profile, and the cases written as the changed profile writes."""
    changed = doc["profiles"][-1]["id"]
    return profile != changed or f"checksum file {changed}" in source


Edit = Callable[[Doc], None]
Keeps = Callable[[str, str, str, Doc], bool]


@dataclass(frozen=True)
class Revision:
    """The spec edits of a revised tree (applied in order), which (case, profile) expectations they
    leave unchanged, and whether the tree's goldens include the largest case."""
    edits: tuple[Edit, ...]
    keeps: Keeps
    largest: bool


# The writer test needs a tree where every field has another algorithm and the last profile yet
# another file algorithm (_fitting avoids the file field's revised one). The check of
# last_profile_another_algorithm runs on that same tree instead of a tree of its own (one
# generation, assembly and C build less, about 2.5 CPU s): it keeps the same expectations (the
# filter depends on the changed profile and the case's source only), and each bug the edit alone
# exposes still changes bytes or findings, since the profile's algorithm differs from the file
# field's here too: a binding or assembler that ignores the profile's algorithm uses the field's
# (another algorithm), one that fixes it to the spec's present one disagrees with the revised
# one, one that gives every profile the last profile's algorithm changes every default case.
#
# The largest golden case is assembled and checked in every_field_another_algorithm only: there
# each of its checksums (65,535 argument checksums, the header, the file over 1.4 MB under both
# profiles) has another algorithm, with both bindings. Elsewhere it would prove nothing the small
# cases do not: under header_coverage_moves the moved coverage is inside the 128-byte header,
# whatever follows it; the profile edit leaves it, written as the first profile writes, with the
# bytes every_field_another_algorithm checks; and a writer picks a checksum's algorithm per file
# and profile, as the small cases show, and computes it with the function its validator checks
# it with (field_checksum in Python, cbf__cover in C), which the validators run on the largest
# case above (a C CRC that drops bytes past 64 KiB fails there), while `make conformance`
# re-encodes the largest case, filled, under the spec itself.
REVISIONS: dict[str, Revision] = {
    "every_field_another_algorithm": Revision((every_field_another_algorithm,), _every, largest=True),
    "last_profile_another_algorithm": Revision((every_field_another_algorithm, last_profile_another_algorithm),
                                               _unchanged_profiles, largest=False),
    "header_coverage_moves": Revision((header_coverage_moves,), _every, largest=False),
}
WRITERS = REVISIONS["last_profile_another_algorithm"]

SCRIPT = r"""
import json, sys
import cbf
out = []
for path, profile, part_number, cutters, machine in json.loads(sys.stdin.read()):
    from cbf.cutters import load_cutter_table
    table = load_cutter_table(cutters) if cutters else None
    limits = cbf.load_machine(machine) if machine else None
    found = cbf.validate(open(path, "rb").read(), profile=profile, part_number=part_number, cutters=table,
                         machine=limits)
    out.append([[f.check, f.severity, f.record, f.offset] for f in found])
print(json.dumps(out))
"""


def _python(rev: Revised, jobs: list[Any], tmp_path: Path) -> list[list[Any]]:
    env = dict(os.environ, PYTHONPATH=str(rev.gen / "python"))
    run = subprocess.run([sys.executable, "-c", SCRIPT], input=json.dumps(jobs), env=env, cwd=tmp_path,
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr[-2000:]
    return list(json.loads(run.stdout))


def _c(rev: Revised, jobs: list[Any], tmp_path: Path) -> list[list[Any]]:
    testee = rev.testee["c"]
    if not testee:
        pytest.skip("gcc not installed")
    req = "".join(json.dumps({"op": "validate", "file": f, "profile": p, "part_number": pn, "cutters": ct,
                              "machine": m}) + "\n"
                  for f, p, pn, ct, m in jobs) + '{"op": "quit"}\n'
    ans = subprocess.run(testee, input=req, capture_output=True, text=True, check=True)
    out = []
    for line in ans.stdout.splitlines():
        a = json.loads(line)
        assert a["ok"], a
        out.append([[f["check"], f["severity"], f["record"], f["offset"]] for f in a["findings"]])
    return out


BINDINGS = {"python": _python, "c": _c}


@dataclass(frozen=True)
class Revised:
    """A revision of the spec, generated (Python and C) and the golden .hex assembled with it: made
    once per revision and shared by the tests of both bindings (they only read it)."""
    doc: Doc
    spec: Path
    gen: Path
    golden: dict[str, bytes]  # case name -> bytes assembled with the revised spec
    testee: dict[str, list[str]]  # binding -> its testee command (the C one compiled once)


@pytest.fixture(scope="module")
def revised(tmp_path_factory: pytest.TempPathFactory) -> Callable[[Revision], Revised]:
    made: dict[tuple[tuple[str, ...], bool], Revised] = {}

    def make(revision: Revision) -> Revised:
        names = tuple(e.__name__ for e in revision.edits)
        key = (names, revision.largest)
        if key not in made:
            work = tmp_path_factory.mktemp("-".join(names))
            doc = spec_doc()
            for edit in revision.edits:
                edit(doc)
            spec = work / "cbf.yaml"
            spec.write_text(yaml.safe_dump(doc, sort_keys=False), encoding="utf-8")
            gen = work / "gen"
            subprocess.run([sys.executable, "-m", "cbfgen", "--spec", str(spec), "--out", str(gen), "--only", "python",
                            "--only", "c"], check=True, cwd=ROOT, capture_output=True)
            skip = set() if revision.largest else {largest_case()}
            golden = {c.name: assemble(GOLDEN / f"{c.name}.hex", spec) for c in golden_cases() if c.name not in skip}
            made[key] = Revised(doc, spec, gen, golden, {"python": _testee("python", gen, work),
                                                         "c": _testee("c", gen, work)})
        return made[key]
    return make


@pytest.mark.parametrize("binding", sorted(BINDINGS))
@pytest.mark.parametrize("revision", sorted(REVISIONS))
def test_goldens_meet_their_expectations_under_a_checksum_revision(tmp_path: Path, revision: str, binding: str,
                                                                   revised: Callable[..., Revised]) -> None:
    keeps = REVISIONS[revision].keeps
    rev = revised(REVISIONS[revision])
    doc = rev.doc
    jobs: list[tuple[str, str, str | None, str | None, str | None]] = []
    wanted: list[tuple[str, str, list[Any]]] = []
    changed = 0
    for case in golden_cases():
        name = case.name
        if name not in rev.golden:  # the largest case, outside every_field_another_algorithm (REVISIONS)
            continue
        data = rev.golden[name]
        changed += data != case.committed
        path = tmp_path / f"{name}.cbf"
        path.write_bytes(data)
        exp = case.expect
        opts = exp.get("options") or {}
        cutters = str(GOLDEN / opts["cutters"]) if opts.get("cutters") else None
        machine = str(GOLDEN / opts["machine"]) if opts.get("machine") else None
        for profile, findings in (exp.get("validate") or {}).items():
            if not keeps(name, profile, case.source, doc):
                continue
            jobs.append((str(path), profile, opts.get("part_number"), cutters, machine))
            wanted.append((name, profile, findings or []))
    assert changed, "the revision must change the bytes of golden files"
    assert len(wanted) > len(rev.golden), "most expectations are kept"
    got = BINDINGS[binding](rev, jobs, tmp_path)
    assert len(got) == len(wanted)
    diffs = [f"{name} [{profile}] {d}" for (name, profile, exp), act in zip(wanted, got, strict=True)
             if (d := findings_difference(exp, [dict(zip(("check", "severity", "record", "offset"), a, strict=True))
                                                for a in act]))]
    assert not diffs, "\n".join(diffs)


def test_version_premise_follows_the_spec() -> None:
    """spec_next_major is a major no version of the spec has, also after a version is added."""
    doc = spec_doc()
    majors = {v["major"] for v in doc["versions"]}
    out = assemble_text("u8 spec_next_major\n")
    assert out[0] not in majors and out[0] == max(majors) + 1


def test_a_new_version_moves_the_premise(tmp_path: Path) -> None:
    doc = spec_doc()
    newest = max(doc["versions"], key=lambda v: v["major"])
    doc["versions"].append({**newest, "id": f"{newest['major'] + 1}.0", "major": newest["major"] + 1})
    spec = tmp_path / "cbf.yaml"
    spec.write_text(yaml.safe_dump(doc, sort_keys=False), encoding="utf-8")
    assert assemble_text("u8 spec_next_major\n", spec=spec)[0] == newest["major"] + 2


def test_an_override_is_stored_literally_under_any_algorithm(tmp_path: Path) -> None:
    """A wrong checksum on purpose is the literal of its `override` line, whatever the spec's algorithm."""
    src = GOLDEN / "check.6.3.1.header_checksum.hex"
    line = next(ln for ln in src.read_text(encoding="utf-8").splitlines() if ln.startswith("override"))
    off, *hexbytes = line.split("#", 1)[0].split()[1:]
    literal = bytes(int(b, 16) for b in hexbytes)
    doc = spec_doc()
    every_field_another_algorithm(doc)
    last_profile_another_algorithm(doc)
    spec = tmp_path / "cbf.yaml"
    spec.write_text(yaml.safe_dump(doc, sort_keys=False), encoding="utf-8")
    for s in (None, spec):
        data = assemble(src, s)
        assert data[int(off):int(off) + len(literal)] == literal


def test_assembler_reads_the_checksum_rules_from_the_spec() -> None:
    doc = spec_doc()
    sums = load_sums(SPEC)
    for f in doc["checksums"]["fields"]:
        if f["field"] != "file":
            assert sums.rule(f["field"], None) == (doc["checksums"]["algorithms"][f["algorithm"]]["kind"],
                                                   f["coverage"])
    for p in doc["profiles"]:
        alg = p.get("file_algorithm") or next(f["algorithm"] for f in doc["checksums"]["fields"]
                                              if f["field"] == "file")
        assert sums.rule("file", p["id"]) == (doc["checksums"]["algorithms"][alg]["kind"], p["file_coverages"][0])
    assert {t: 8 * s.width for t, s in sums.slots.items()} == _widths(doc)


def _testee(binding: str, gen: Path, tmp_path: Path) -> list[str]:
    """The testee command of a binding generated into gen (the Python one runs with PYTHONPATH=gen/python);
    [] when the C compiler is missing."""
    if binding == "python":
        return [sys.executable, str(ROOT / "conformance" / "testees" / "python" / "testee.py")]
    cc = shutil.which("gcc")
    if cc is None:
        return []
    exe = tmp_path / "testee"
    subprocess.run([cc, "-std=c99", "-O0", "-o", str(exe), str(gen / "c" / "cbf_testee.c"), "-lm"], check=True,
                   capture_output=True)
    return [str(exe)]


@pytest.mark.parametrize("binding", sorted(BINDINGS))
def test_writers_fill_the_profile_algorithm(tmp_path: Path, binding: str, revised: Callable[..., Revised]) -> None:
    """Under a revision where a profile has its own file algorithm, every writer fills each valid
    golden (written as that profile writes; not the largest, see REVISIONS) to the bytes the
    assembler made from the spec."""
    import base64

    rev = revised(WRITERS)
    doc, gen = rev.doc, rev.gen
    cases: list[tuple[str, str, bytes]] = []
    for case in golden_cases():
        name, exp = case.name, case.expect
        if not exp.get("encode") or exp.get("encode_fill") is False or name not in rev.golden:
            continue  # not filled by a writer, or the largest case (see REVISIONS)
        for profile, findings in (exp.get("validate") or {}).items():
            if not findings and _unchanged_profiles(name, profile, case.source, doc):
                cases.append((name, profile, rev.golden[name]))
    assert {p for _, p, _ in cases} == {p["id"] for p in doc["profiles"]}, "every profile writes some case"
    reqs = []
    for name, _, data in cases:
        (tmp_path / f"{name}.cbf").write_bytes(data)
        reqs.append({"op": "decode", "file": str(tmp_path / f"{name}.cbf")})
    env = dict(os.environ, PYTHONPATH=str(gen / "python"))
    cmd = rev.testee[binding]
    if not cmd:
        pytest.skip("gcc not installed")
    run = subprocess.run(cmd, input="".join(json.dumps(r) + "\n" for r in reqs) + '{"op": "quit"}\n', env=env,
                         capture_output=True, text=True, check=True)
    decoded = [json.loads(line) for line in run.stdout.splitlines()]
    enc = [{"op": "encode", "json": d["result"], "keep_stored": False, "profile": p}
           for d, (_, p, _) in zip(decoded, cases, strict=True)]
    run = subprocess.run(cmd, input="".join(json.dumps(r) + "\n" for r in enc) + '{"op": "quit"}\n', env=env,
                         capture_output=True, text=True, check=True)
    for line, (name, profile, data) in zip(run.stdout.splitlines(), cases, strict=True):
        ans = json.loads(line)
        assert ans["ok"], (name, profile, ans)
        assert base64.b64decode(ans["bytes"]) == data, (name, profile)
