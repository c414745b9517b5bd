"""The revision fixtures of tests/revisions/ and `cbfgen diff` of the real spec against each.

The drill itself (`make revision-drill`, a temporary tree per fixture through
generate, golden, conformance and tests) runs from mk/revision.mk; this file
checks the fixtures and their classification without building anything. It
compares with the unrevised spec, so the drill does not run it inside a
revision.
"""

from __future__ import annotations

import copy
import hashlib
import os
import re
import shutil
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
import yaml
from conftest import YAML_LOADER, load_yaml
from revisions import drill

from cbfgen import loader
from cbfgen.diff import diff
from cbfgen.model import Spec
from conformance.runner.reasons import failure_class

REPO = Path(__file__).resolve().parents[1]
SPEC = REPO / "spec" / "cbf.yaml"
FIXTURES = drill.fixtures()

# The pairwise tests load the same spec text many times (the base of every pair, the revised spec both
# for the loader's checks and for cbfgen diff): the loader's result is a function of the path it names
# and the text, so each (path, text) is loaded once a process (about 0.16 CPU s a load; this file loaded
# 400 specs, 2 of 3 of them again). A spec the loader refuses is not kept: it raises every time.
_LOADED: dict[tuple[str, bytes], Spec] = {}


def load(path: Path) -> Spec:
    """cbfgen.loader.load(path), once per path and text."""
    key = (str(path), hashlib.sha256(Path(path).read_bytes()).digest())
    if key not in _LOADED:
        _LOADED[key] = loader.load(path)
    return _LOADED[key]


_PARSED: dict[bytes, Any] = {}


@pytest.fixture(scope="module", autouse=True)
def _forget() -> Iterator[None]:
    """The caches of this file dropped when it ends: the specs, parsed texts and fixtures it kept (320,000
    objects) would stay alive in the xdist worker for every later file, and every full collection there
    (gc.collect, or the collector's own) would walk them again."""
    yield
    for cache in (_LOADED, _PARSED, _FOR):
        cache.clear()


def _read_spec(path: Path) -> Any:
    """drill.read_spec(path), parsed once per text (a copy of its own each call: the caller may edit it)."""
    text = Path(path).read_bytes()
    key = hashlib.sha256(text).digest()
    if key not in _PARSED:
        _PARSED[key] = drill.read_spec(path)
    return copy.deepcopy(_PARSED[key])


def test_the_kinds_of_revision_are_drilled_and_classed_as_a_format_owner_would() -> None:
    """The fixtures make each kind of revision, and each states the class a format owner gives it: a new
    version is not breaking, a layout change to an existing version is wire-breaking, a rename is
    text-breaking and not wire-breaking (test_cbfgen_diff_classifies_the_fixture holds cbfgen diff to it)."""
    fixtures = [_fixture_for(p, SPEC) for p in FIXTURES if _unmet(p, SPEC) is None]
    kinds = {(w["kind"], w.get("breaking")) for fx in fixtures for w in fx.expect}
    assert len(FIXTURES) >= 5
    assert {("command_added", True), ("version_added", False), ("command_removed", False), ("field_retyped", True),
            ("profile_checksum_algorithm_changed", True), ("command_renamed", False)} <= kinds
    for fx in fixtures:
        stated = {w["kind"] for w in fx.expect}
        if "command_renamed" in stated and len(stated - {"revision_changed"}) == 1:
            assert fx.text_breaking and not fx.breaking, fx.name
        if "version_added" in stated:
            assert not fx.breaking and not fx.text_breaking, fx.name
        if "field_retyped" in stated:
            assert fx.breaking, fx.name


def test_the_quick_drill_leaves_out_only_what_an_in_tree_test_makes() -> None:
    """`make test` makes every fixture's kind of revision: in the quick drill, or in the in-tree
    test IN_TREE names, which revises a copy of the spec the same way (a new command, another
    checksum algorithm) and runs generation and the bindings on it."""
    names = {p.stem for p in FIXTURES}
    assert set(drill.IN_TREE) < names, "IN_TREE names a fixture that does not exist, or every fixture"
    kinds = {"new_command": "command_added", "checksum_profile": "profile_checksum_algorithm_changed"}
    for name, test in drill.IN_TREE.items():
        fx = drill.load_fixture(drill.HERE / f"{name}.yaml")
        assert kinds[name] in {w["kind"] for w in fx.expect}, name
        text = (REPO / test).read_text(encoding="utf-8")
        assert "generate(" in text or "cbfgen" in text, f"{test} does not generate from a revised spec"


def test_the_quick_fixtures_apply_together(tmp_path: Path) -> None:
    """The quick drill applies its fixtures to one tree: their spec edits, one after the other, give a spec
    the loader accepts that holds each fixture's own revision (each changes what cbfgen diff says of it
    alone), and no two of them add the same file."""
    quick = [_fixture_for(p, SPEC) for p in FIXTURES if p.stem not in drill.IN_TREE and _unmet(p, SPEC) is None]
    assert len(quick) > 1
    path, added = SPEC, list[str]()
    for fx in list(quick):  # as drill.apply does: each fixture's ids chosen for the spec the ones before it left
        if _unmet(fx.path, path) is not None:  # the ones before it hold what it adds: left out, as the drill does
            quick.remove(fx)
            continue
        added += _fixture_for(fx.path, path).files
        path = drill.revised_spec(fx, path, tmp_path / f"then_{fx.name}", _read_spec(path))
    together, before = load(path), len(load(SPEC).versions)
    names = {c.name for c in load(SPEC).commands}
    new_versions = 0
    for fx in quick:
        alone = load(drill.revised_spec(fx, SPEC, tmp_path / fx.name))
        new_versions += len(alone.versions) - before
        mine = {c.name for c in alone.commands}
        assert mine - names <= {c.name for c in together.commands}, f"{fx.name}: a command it adds is not there"
        assert not (names - mine) & {c.name for c in together.commands}, f"{fx.name}: a name it drops is there"
    assert len(together.versions) - before == new_versions, "each version a fixture adds is there, once"
    assert len(added) == len(set(added)), "two quick fixtures add the same file"


def test_the_quick_drill_leaves_out_only_the_large_golden_files() -> None:
    """The quick drill's conformance runs every golden case but the files over QUICK_MAX_BYTES (which the main
    tree's conformance runs): each case is named whole, and a threshold that drops small files fails here."""
    golden = REPO / "conformance" / "golden"
    every = sorted(p.name[: -len(".expect.yaml")] for p in golden.glob("*.expect.yaml"))
    chosen = drill.quick_cases(REPO)
    left_out = set(every) - set(chosen)
    assert set(chosen) <= set(every) and left_out, "the quick drill runs the large files or names unknown cases"
    assert all((golden / f"{n}.cbf").stat().st_size > drill.QUICK_MAX_BYTES for n in left_out)
    assert all((golden / f"{n}.cbf").stat().st_size <= drill.QUICK_MAX_BYTES for n in chosen)
    assert len(left_out) <= len(every) // 20, f"the quick drill leaves out {len(left_out)} of {len(every)} cases"


@pytest.mark.parametrize("path", FIXTURES, ids=[p.stem for p in FIXTURES])
def test_cbfgen_diff_classifies_the_fixture(path: Path, tmp_path: Path) -> None:
    _skip_unmet(path)
    fx = drill.load_fixture(path)
    revised = drill.revised_spec(fx, SPEC, tmp_path)
    assert drill.check_diff(fx, SPEC, revised) == []
    assert load(revised).revision != load(SPEC).revision, "a revision names itself in meta.revision"


def test_the_quick_drill_leaves_each_fixtures_diff_alone_to_this_file() -> None:
    """The quick drill (`make test`) does not check each fixture's `cbfgen diff` alone: the test it names does,
    for every fixture, with the same drill.check_diff on the same specs."""
    path, name = drill.DIFF_ALONE_TEST.split("::")
    assert (REPO / path).resolve() == Path(__file__).resolve()
    test = globals()[name]
    marks = [m for m in getattr(test, "pytestmark", []) if m.name == "parametrize"]
    assert [m.args[1] for m in marks] == [FIXTURES]
    assert "drill.check_diff(fx, SPEC, revised)" in Path(__file__).read_text(encoding="utf-8")


@pytest.mark.parametrize("path", FIXTURES, ids=[p.stem for p in FIXTURES])
def test_a_fixture_adds_golden_cases_and_expectations_only(path: Path, tmp_path: Path) -> None:
    _skip_unmet(path)
    fx = drill.load_fixture(path)
    assert fx.title and fx.adds, "a fixture says what it adds beyond the spec edit"
    for rel in fx.files:
        assert rel.startswith("conformance/golden/") and rel.endswith((".hex", ".expect.yaml")), rel
    for edit in fx.edits:
        rel = edit.get("file", drill.SPEC)
        if edit["op"] == "append_line":  # a new case a Kaitai parser cannot decode, listed as a known failure
            assert re.fullmatch(r"conformance/failures/kaitai-[a-z]+\.txt", rel), rel
            assert any(str(edit["value"]).startswith(c.split("/")[-1][: -len(".hex")] + " ") for c in fx.files), edit
            # by case and reason, as `make failures` writes it (a failure class): never a message, which a revision
            # of the header or another fixture's moves (issue 37, point 3)
            reason = str(edit["value"]).split(" ", 1)[1]
            assert failure_class(reason) == reason, f"{edit['value']!r}: list a class, not a message"
            continue
        if edit["op"] == "sub_text":  # a known failure's message the revision changes (a Kaitai parser's path)
            assert re.fullmatch(r"conformance/failures/kaitai-[a-z]+\.txt", rel), rel
            assert str(edit["pattern"]).startswith("^"), "sub_text names the case it changes, from the line's start"
            continue
        assert rel == drill.SPEC or (rel.startswith("conformance/golden/") and rel.endswith(".expect.yaml")), rel
    cases = {r[: -len(".hex")] for r in fx.files if r.endswith(".hex")}
    assert cases == {r[: -len(".expect.yaml")] for r in fx.files if r.endswith(".expect.yaml")}
    # A check the revision adds has a case that reports it and nothing else.
    new_checks = {str(c["id"]) for e in fx.edits if e.get("path") == "checks" and e["op"] == "append"
                  for c in [e["value"]]}
    reported = {str(f[0]) for r, text in fx.files.items() if r.endswith(".expect.yaml")
                for f in (yaml.load(text, Loader=YAML_LOADER).get("validate") or {}).get("default", [])}
    assert new_checks <= reported


def test_apply_writes_the_revision_into_a_tree(tmp_path: Path) -> None:
    fx = next(fx for fx in drill.applicable() if any("file" in e for e in fx.edits))
    for rel in {drill.SPEC, *(e["file"] for e in fx.edits if "file" in e)}:
        (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(REPO / rel, tmp_path / rel)
    drill.apply(fx, tmp_path)
    spec = load(tmp_path / drill.SPEC)
    assert spec.revision == load(drill.revised_spec(fx, SPEC, tmp_path / "r")).revision
    for e in fx.edits:
        if "file" in e:
            assert (tmp_path / e["file"]).read_text(encoding="utf-8").startswith("# Revised by tests/revisions/")


def test_a_fixture_that_does_not_apply_names_the_edit(tmp_path: Path) -> None:
    bad = tmp_path / "bad.yaml"
    bad.write_text(yaml.safe_dump({"title": "t", "adds": "nothing", "breaking": False, "expect": [],
                                   "edits": [{"op": "set", "path": "commands[name=NO_SUCH].code", "value": 1}]}))
    with pytest.raises(drill.FixtureError, match=r"bad.yaml: edit 1: commands\[name=NO_SUCH\]: no item with name"):
        drill.revised_spec(drill.load_fixture(bad), SPEC, tmp_path / "out")
    bad.write_text("title: [\n")
    with pytest.raises(drill.FixtureError, match="bad.yaml"):
        drill.load_fixture(bad)


def test_a_fixture_never_overwrites_what_the_tree_holds(tmp_path: Path) -> None:
    """A file a fixture adds that the tree already holds (a fixed name, on a tree holding the fixture's own
    revision), or a failure-list line already there, refuses the fixture with both named, before anything is
    written: the drill never silently replaces a golden case or lists a case twice."""
    fx = next(fx for fx in drill.applicable() if fx.files and any(e.get("op") == "append_line" for e in fx.edits))
    for rel in {drill.SPEC, *(e["file"] for e in fx.edits if "file" in e)}:
        (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(REPO / rel, tmp_path / rel)
    held = next(iter(fx.files))
    (tmp_path / held).parent.mkdir(parents=True, exist_ok=True)
    (tmp_path / held).write_text("# already here\n", encoding="utf-8")
    before = (tmp_path / drill.SPEC).read_bytes()
    with pytest.raises(drill.FixtureError, match=rf"{re.escape(fx.path.name)}: adds {re.escape(held)}.*already"):
        drill.apply(fx, tmp_path)
    assert (tmp_path / drill.SPEC).read_bytes() == before and (tmp_path / held).read_text() == "# already here\n"
    (tmp_path / held).unlink()
    edit = next(e for e in fx.edits if e.get("op") == "append_line")
    with (tmp_path / edit["file"]).open("a", encoding="utf-8") as fh:
        fh.write(str(edit["value"]) + "\n")
    with pytest.raises(drill.FixtureError, match="is already there"):
        drill.apply(fx, tmp_path)


def _fixture_with(breaking: bool) -> drill.Fixture:
    return next(fx for fx in (_fixture_for(p, SPEC) for p in FIXTURES if _unmet(p, SPEC) is None)
                if fx.breaking == breaking)


def test_make_breaking_reads_the_spec_at_a_git_ref(tmp_path: Path) -> None:
    """`make breaking BASE=HEAD NEW_SPEC=...` prints what `cbfgen diff` of the spec at HEAD against that spec
    prints, exits 0 when cbfgen diff does and 2 (make's status for a failed recipe) otherwise, and names cbfgen
    diff's own code on its last line. Run on a wire-breaking fixture's spec and a non-breaking one's, so it
    holds whether or not the working tree's spec equals HEAD's."""
    if shutil.which("git") is None or not (REPO / ".git").exists():
        pytest.skip("not a git checkout")
    head = tmp_path / "head.yaml"
    head.write_bytes(subprocess.run(["git", "show", "HEAD:spec/cbf.yaml"], cwd=REPO, capture_output=True,
                                    check=True).stdout)
    codes = []
    for fx in (_fixture_with(True), _fixture_with(False)):
        new = drill.revised_spec(fx, SPEC, tmp_path / fx.name)
        direct = subprocess.run([sys.executable, "-m", "cbfgen", "diff", str(head), str(new), "--old-name",
                                 "HEAD:spec/cbf.yaml"], cwd=REPO, capture_output=True, text=True,
                                env=dict(os.environ, PYTHONPATH=os.pathsep.join(  # cbfgen, whoever runs pytest
                                    [str(REPO / "generator"), os.environ.get("PYTHONPATH", "")])))
        res = subprocess.run(["make", "-s", "breaking", "BASE=HEAD", f"NEW_SPEC={new}"], cwd=REPO,
                             capture_output=True, text=True)
        assert direct.returncode in (0, 1, 3), direct.stderr
        assert res.stdout == direct.stdout and res.stdout.startswith(f"cbfgen diff: HEAD:spec/cbf.yaml -> {new}:")
        assert res.returncode == (0 if direct.returncode == 0 else 2), res.stderr
        if direct.returncode:
            assert f"make breaking: cbfgen diff exit {direct.returncode}: " in res.stderr
        codes.append(direct.returncode)
    assert codes[0] == 1, "a wire-breaking fixture is wire-breaking against HEAD's spec too"
    assert "TEST_DEPS += revision-drill-quick" in (REPO / "mk" / "revision.mk").read_text(encoding="utf-8")


def test_the_walkthrough_order_leaves_a_tree_make_test_accepts() -> None:
    """The README's walkthrough runs `make generate` (step 2) before `make golden` (step 4), and the docs' golden
    pages are made from the .cbf files: `make golden` assembles and then regenerates, so the tree it leaves is
    fresh (the drill's `generated fresh` step checks it in a revised tree)."""
    res = subprocess.run(["make", "-n", "-s", "golden"], cwd=REPO, capture_output=True, text=True)
    lines = res.stdout.splitlines()
    assembler = next(i for i, line in enumerate(lines) if "-m conformance.assembler" in line)
    assert any(re.fullmatch(r"\S*make\b.* generate", line) for line in lines[assembler:]), res.stdout
    readme = (REPO / "README.md").read_text(encoding="utf-8")
    steps = [readme.index(s) for s in ("**`make revision`**", "**Stage the revision**", "**`make test`.**")]
    assert steps == sorted(steps), "the README's walkthrough order changed: check make revision's steps"
    # `make revision` (conformance/revise.py) runs generate, golden, the freshness check, the expectations, then
    # conformance, in that order
    source = (REPO / "conformance" / "revise.py").read_text(encoding="utf-8").split("def main(", 1)[1]
    order = [source.index(s) for s in ('"generate"]', '"golden"]', '"build/stamps/generate-py"]', "proposals()",
                                       '"conformance"]')]
    assert order == sorted(order), "make revision's steps are out of the walkthrough's order"
    # make test ends with check-report, which compares the run's report with what git holds: the walkthrough
    # has the report made and staged before make test
    assert "check-report" in (REPO / "Makefile").read_text(encoding="utf-8").split("\ntest:", 1)[1].split("\n\n")[0]


def test_the_readme_lists_no_versions_by_hand() -> None:
    """A list of versions in the README goes stale with the next revision: it points to the model instead."""
    ids = [v.id for v in load(SPEC).versions]
    for n, line in enumerate((REPO / "README.md").read_text(encoding="utf-8").splitlines(), 1):
        found = {v for v in ids if re.search(rf"(?<![\w.]){re.escape(v)}(?![\w])", line)}
        assert len(found) < 3, f"README.md:{n} lists versions {sorted(found)}: {line}"
        assert not re.search(r"(?<![\w.])\d\.[\dx]\|\d\.[\dx](?![\w])", line), f"README.md:{n}: {line}"


_FOR: dict[tuple[Path, bytes], drill.Fixture] = {}


def _unmet(path: Path, base: Path) -> str | None:
    """drill.unmet(path) for the spec at base: why the fixture does not apply there (its `requires:`), or None."""
    return drill.unmet(path, _read_spec(base))


def _skip_unmet(path: Path, base: Path = SPEC) -> None:
    """A fixture whose stated precondition the spec does not hold (a revision already made what it adds: this
    tree may be one the drill revised) is skipped, saying why, as the drill skips it."""
    why = _unmet(path, base)
    if why is not None:
        pytest.skip(f"{path.name}: {why}")


def _fixture_for(path: Path, base: Path) -> drill.Fixture:
    """drill.load_fixture(path, drill.read_spec(base)), once per fixture and base text: a pair's revision, its
    files and its judged diff all read the fixture as it reads for the base (a Fixture is frozen; its edits are
    read, never changed: revised_spec renders its own copy)."""
    key = (path, hashlib.sha256(Path(base).read_bytes()).digest())
    if key not in _FOR:
        _FOR[key] = drill.load_fixture(path, _read_spec(base))
    return _FOR[key]


def _revised(fx: drill.Fixture, base: Path, out: Path) -> tuple[Path, drill.Fixture]:
    """base revised by fx into out, and fx as it reads for base (its ids chosen there)."""
    return drill.revised_spec(fx, base, out, _read_spec(base)), _fixture_for(fx.path, base)


def _judged(fx: drill.Fixture, base: Path, revised: Path, models: tuple[Spec, Spec] | None = None) -> list[str]:
    """drill.check_diff in this process: what cbfgen diff of base against revised says, judged for fx (models: the
    two specs already loaded, each load about a third of a pair's time)."""
    d = diff(*(models or (load(base), load(revised))))
    return drill.judge(_fixture_for(fx.path, base), d.exit_code, d.as_json())


@pytest.mark.parametrize("first", FIXTURES, ids=[p.stem for p in FIXTURES])
def test_each_fixture_applies_on_top_of_each_other(first: Path, tmp_path: Path) -> None:
    """Fixture B applied to fixture A's revised spec (every ordered pair, A on top of itself included: the tree a
    real revision of A's kind leaves, where `make test`'s quick drill applies A again; the spec edits only) gives
    a spec the loader accepts, B's ids are free there (no file of A's is added again, no version, code or clause
    taken twice) and cbfgen diff of A's spec against it says what B states."""
    _skip_unmet(first)
    a = _fixture_for(first, SPEC)
    base, a_here = _revised(a, SPEC, tmp_path / "a")
    spec_a = load(base)
    for other in FIXTURES:
        if _unmet(other, SPEC) is not None:
            continue
        if _unmet(other, base) is not None:  # A made what B adds (B states it): B says so instead of applying
            with pytest.raises(drill.FixtureUnmet, match=re.escape(other.name)):
                drill.load_fixture(other, _read_spec(base))
            continue
        b = _fixture_for(other, SPEC)
        both, b_there = _revised(b, base, tmp_path / f"a_{other.stem}")
        spec = load(both)  # the loader's checks (make check-spec)
        assert len({c.code for c in spec.commands}) == len(spec.commands), (first.stem, other.stem)
        assert not set(a_here.files) & set(b_there.files), f"{other.stem} adds a file {first.stem} added"
        assert _judged(b, base, both, (spec_a, spec)) == [], (first.stem, other.stem)
        assert {v.id for v in spec_a.versions} <= {v.id for v in spec.versions}


def _layouts_moved(tmp_path: Path) -> Path:
    """A real revision that gives every command its own layout for the newest version (the same bytes, under a
    variant of its own), as a revision that changes one of them in that version does: the layout a fixture
    edits for the newest version is no longer the first (a fixture that addresses layouts[0] edits the wrong
    one)."""
    doc = load_yaml(SPEC)
    newest = max(load(SPEC).versions, key=lambda v: (v.major, v.minor or 0)).id
    for c in doc["commands"]:
        first = c["layouts"][0]
        if newest in first["versions"] and len(first["versions"]) > 1:
            own = copy.deepcopy(first)
            first["versions"].remove(newest)
            own.update(versions=[newest], variant=f"own_{newest.replace('.', '_')}")
            c["layouts"].append(own)
    path = tmp_path / "moved" / "cbf.yaml"
    path.parent.mkdir()
    path.write_text(drill._dump(doc), encoding="utf-8")
    return path


def test_the_fixtures_apply_after_a_real_revision(tmp_path: Path) -> None:
    """A spec that already had a revision adding a version (the new_version fixture's result, as a format owner
    would commit it), and one whose layouts moved, take every fixture, new_version again included: the next
    free version, code and clause are chosen there, the loader accepts the result and cbfgen diff says what
    each fixture states."""
    adds_version = next(fx for fx in (_fixture_for(p, SPEC) for p in FIXTURES if _unmet(p, SPEC) is None)
                        if any(w["kind"] == "version_added" for w in fx.expect))
    real = drill.revised_spec(adds_version, SPEC, tmp_path / "real")
    newest = max(load(real).versions, key=lambda v: (v.major, v.minor or 0)).id
    assert newest not in {v.id for v in load(SPEC).versions}
    for base in (real, _layouts_moved(tmp_path)):
        for path in FIXTURES:
            if _unmet(path, SPEC) is not None or _unmet(path, base) is not None:
                continue
            fx = _fixture_for(path, SPEC)
            revised, there = _revised(fx, base, tmp_path / base.parent.name / path.stem)
            load(revised)
            assert _judged(fx, base, revised) == [], (base, path.stem)
            if base == real and fx.name == adds_version.name:
                assert any(w.get("version") not in (None, newest) for w in there.expect
                           if w["kind"] == "version_added")


def test_fixture_ids_are_chosen_for_the_spec(tmp_path: Path) -> None:
    """${...} names what the spec it renders for has free or holds: a version, code and clause no one uses,
    the newest version, a command's code; and an unknown name is refused with the fixture's name."""
    doc = load_yaml(SPEC)
    v = drill.variables(doc)
    model = load(SPEC)
    assert v["new_version"] not in {x.id for x in model.versions}
    assert int(v["new_major"]) > max(x.major for x in model.versions)
    assert int(v["free_code"]) not in {c.code for c in model.commands} and 0 < int(v["free_code"]) < 256
    assert v["free_clause"] not in {c.id for c in model.checks} | {str(c.clause) for c in model.checks}
    assert v["newest_version"] == max(model.versions, key=lambda x: (x.major, x.minor or 0)).id
    cmd = model.commands[-1]
    assert drill.render(f"${{code:{cmd.name}}} ${{dec:{cmd.name}}}", doc, "t") == f"{cmd.code:02x} {cmd.code}"
    assert drill.render(f"${{name:{cmd.name}}}", doc, "t") == f"{cmd.name}_2"
    assert drill.render(f"${{slug:{cmd.name}}}", doc, "t") == f"{cmd.name}_2".lower()
    # a new command's code is one no golden file's record holds either (framing.unknown_command's unknown code)
    assert drill.golden_codes() - {c.code for c in model.commands}, "no golden file holds an unknown code"
    assert int(v["free_code"]) not in drill.golden_codes()
    taken = dict(doc, commands=[*doc["commands"], *({"name": f"X{c}", "code": c, "layouts": []} for c in
                                                    sorted(drill.golden_codes() - {c.code for c in model.commands}))])
    assert int(drill.variables(taken)["free_code"]) == int(v["free_code"])
    # ${unranged_version:NAME}: a writable version of the command where no range check judges it; a range check on
    # that version moves it to another (or, on none left, names nothing: the fixture's precondition is unmet)
    target = next(c for c in model.commands if any(x.writable and c.layouts_for(x.id) for x in model.versions)
                  and not any(k.kind == "range" and any(t.command == c.name for t in k.targets) for k in model.checks))
    first = drill.render(f"${{unranged_version:{target.name}}}", doc, "t")
    bounded = dict(doc, checks=[*doc["checks"], {"id": "x", "kind": "range", "versions": [first],
                                                 "targets": [{"command": target.name}]}])
    then = drill.render(f"${{unranged_version:{target.name}}}", bounded, "t")
    assert then != first and target.layouts_for(then)
    everywhere = dict(doc, checks=[*doc["checks"], {"id": "x", "kind": "range", "targets": [{"command": target.name}]}])
    with pytest.raises(drill.FixtureError, match="unjudged by a range check"):
        drill.render(f"${{unranged_version:{target.name}}}", everywhere, "t")
    with pytest.raises(drill.FixtureError, match=r"t: \$\{code:NO_SUCH\} names nothing"):
        drill.render("${code:NO_SUCH}", doc, "t")


def test_cover_missing_names_checks_the_schema_takes(tmp_path: Path) -> None:
    """conftest.cover_missing gives a version no availability check covers yet a check of its own, its id from
    the version's ("3.0", "5.0", "1.x") in the schema's id pattern: a command in one version only loads."""
    from conftest import cover_missing

    doc = load_yaml(SPEC)
    model = load(SPEC)
    only = model.versions[-1].id
    free = next(c for c in range(1, 256) if c not in {x.code for x in model.commands})
    cmd = {"name": "ONE_VERSION_ONLY", "code": free, "clause": "9.9", "doc": "In one version.",
           "layouts": [{"versions": [only], "size": 4, "args": [{"name": "value", "type": "f4", "doc": "A value."}]}]}
    doc["commands"].append(cmd)
    cover_missing(doc, cmd)
    path = tmp_path / "cbf.yaml"
    path.write_text(drill._dump(doc), encoding="utf-8")
    spec = load(path)
    made = [c for c in spec.checks if c.id not in {k.id for k in model.checks}]
    assert all("." not in c.id and len(c.versions) == 1 for c in made), made  # one version each, an id the schema takes
    assert len(made) <= len(model.versions) - 1
    assert all(spec.availability_check("ONE_VERSION_ONLY", v.id) for v in spec.versions if v.id != only)


def test_the_bench_file_of_every_writable_version_validates() -> None:
    """bench's every-command file is made for the newest writable version, which a revision may give curves (3.0
    has them today): for each writable version the file holds every command the version has and validates with
    no finding (curves by their motion role, a full turn ending where they start)."""
    import cbf
    from bench.bench import _every_command_file
    from cbf import tables as T

    writable = [v for v in T.VERSIONS if v.writable]
    assert any(any(c.motion and c.motion.get("kind") in ("circle", "helix") and c.layouts_for(v.id)
                   for c in T.COMMANDS) for v in writable), "no writable version has a curve: this test proves less"
    for v in writable:
        data = _every_command_file(300, v.id)
        assert cbf.validate(data) == [], v.id
        codes = {r.code for r in cbf.decode(data).records}
        assert codes == {c.code for c in T.COMMANDS if c.layouts_for(v.id)}, v.id


def test_a_fixture_states_its_precondition_and_is_skipped_where_it_is_already_met(tmp_path: Path) -> None:
    """A fixture whose hand-written files assume something of the spec states it (`requires:`, drill.unmet): on a
    spec a revision of the same kind already made (a second deprecation of a layout, which the loader refuses), or
    one lacking what its files hold, it is skipped with a reason naming what, never failed nor applied blindly."""
    stating = [p for p in FIXTURES if drill._REQUIRES.search(p.read_text(encoding="utf-8"))]
    assert stating, "no fixture states a precondition: this test proves nothing"
    for path in stating:
        if _unmet(path, SPEC) is not None:
            continue
        fx = drill.load_fixture(path)
        again = drill.revised_spec(fx, SPEC, tmp_path / path.stem)
        why = drill.unmet(path, drill.read_spec(again))
        if why is None:  # it applies on top of itself: the loader takes the result
            load(drill.revised_spec(fx, again, tmp_path / f"{path.stem}_twice"))
            continue
        assert "already" in why or "no " in why, why
        with pytest.raises(drill.FixtureUnmet, match=rf"{re.escape(path.name)}: skipped, .*: {re.escape(why)}"):
            drill.load_fixture(path, drill.read_spec(again))
    # a condition naming what the spec lacks is the reason itself, not a ${...} error of the whole fixture
    bare = tmp_path / "bare.yaml"
    bare.write_text('title: t\nrequires:\n  - {layout: NO_SUCH/x, version: "${newest_version}"}\nadds: nothing\n',
                    encoding="utf-8")
    newest = drill.variables(_read_spec(SPEC))["newest_version"]
    assert drill.unmet(bare, _read_spec(SPEC)) == f"the spec has no NO_SUCH/x layout in version {newest}"
    bare.write_text('title: t\nrequires:\n  - {not_deprecated: "${code:NO_SUCH}"}\nadds: nothing\n', encoding="utf-8")
    assert "${code:NO_SUCH} names nothing in this spec" in str(drill.unmet(bare, _read_spec(SPEC)))
    ranged = next(str(t.command) for k in load(SPEC).checks if k.kind == "range" for t in k.targets)
    bare.write_text(f'title: t\nrequires:\n  - {{unranged: {ranged}}}\nadds: nothing\n', encoding="utf-8")
    assert f"a range check already judges {ranged} (check " in str(drill.unmet(bare, _read_spec(SPEC)))
