"""What a newcomer expects (issue 35, point 7): `cbf hexdump` of any file with the golden pages'
view and its findings marked; `dir(cbf)` shows the API; the Python README's first snippet prints
what it promises; CHANGELOG.md from the release tags and `cbfgen diff`; the licences; bash
completion and man pages written from the argument parsers."""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import yaml
from cli_many import run_many

import cbf
import cbfgen
from cbf import hexdump as rt_hexdump
from cbf.report import finding_line
from cbf.validation import validate

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"
SMALL = sorted((p for p in GOLDEN.glob("*.cbf") if p.stat().st_size < 4096), key=lambda p: p.name)


def _cbf(*args: str | Path, cwd: Path = REPO) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "cbf", *map(str, args)], cwd=cwd, capture_output=True, text=True)


def test_hexdump_is_the_golden_pages_view_with_findings_marked() -> None:
    """The command's dump (the codec's tables) is byte for byte the docs' dump (the spec model) of every
    small golden file, and each finding is marked once, on the row holding its offset."""
    from cbfgen.emit.docs import hexdump as docs_hexdump
    from cbfgen.loader import load

    spec = load(REPO / "spec" / "cbf.yaml")
    assert len(SMALL) > 20
    # validate's verdict on each file, from one `cbf validate` of them all (its per-file status is the exit
    # status validate gives that file alone; a process a file cost 0.4 CPU s)
    batch = _cbf("validate", "--format", "json", *SMALL)
    status = {f["file"]: f["status"] for f in json.loads(batch.stdout)["files"]}
    assert sorted(status) == sorted(map(str, SMALL)), batch.stderr
    # both hexdumps of every file from one process (tests/cli_many.py: each command line judged by its own
    # exit code and streams, as if alone; 128 processes cost 0.19 CPU s each). A real process runs
    # hexdump in test_hexdump_of_a_hostile_file_and_its_options.
    argvs = [["hexdump", str(path), *flags] for path in SMALL for flags in (["--no-findings"], [])]
    dumps = iter(done for done, _peak in run_many(argvs, dict(os.environ)))
    for path in SMALL:
        data = path.read_bytes()
        plain, marked = next(dumps), next(dumps)
        if status[str(path)] == 2:  # not a CBF file: refused as validate refuses it
            assert plain.returncode == 2 and len(plain.stderr.splitlines()) == 1 and not plain.stdout, path.name
            assert marked.returncode == 2 and len(marked.stderr.splitlines()) == 1 and not marked.stdout, path.name
            continue
        assert plain.returncode == 0, plain.stderr
        assert plain.stdout == docs_hexdump.dump(spec, data) + "\n", path.name
        found = validate(data)
        assert marked.returncode == (1 if any(f.severity == "error" for f in found) else 0), path.name
        rows = marked.stdout.splitlines()
        assert sum(r.count(rt_hexdump.MARK) for r in rows) == len(found), path.name
        for f in found:  # each mark is the finding as validate prints it: the file and the offset name it
            text = finding_line(str(path), f).rstrip("\n")
            hit = [r for r in rows if f"{rt_hexdump.MARK} {text}" in r]
            assert hit, (path.name, f)
            if f.offset is not None and f.offset < len(data):
                start = int(hit[0][:8], 16)
                assert start <= f.offset < start + rt_hexdump.ROW, (path.name, f, hit[0])
        assert not any(r.startswith("::") for r in rows)


def test_hexdump_of_a_hostile_file_and_its_options(tmp_path: Path) -> None:
    base = next(p for p in SMALL if p.name.startswith("valid.v3"))
    data = bytearray(base.read_bytes())
    data[0x12:0x18] = b"\n::e\x1b["  # a line break, a workflow command and an escape in the descriptor
    bad = tmp_path / "bad.cbf"
    bad.write_bytes(bytes(data))
    res = _cbf("hexdump", bad)
    assert "Traceback" not in res.stderr
    assert all(re.match(r"[0-9A-F]{8}  |\u25c0 ", line) for line in res.stdout.splitlines()), res.stdout[:500]
    assert "\x1b" not in res.stdout
    header = _cbf("hexdump", base, "--header").stdout.splitlines()
    assert header and all(" header " in line for line in header)
    one = _cbf("hexdump", base, "--record", "1").stdout.splitlines()
    assert one and all(" #1 " in line for line in one)
    assert len(_cbf("hexdump", base, "--max-lines", "5").stdout.splitlines()) == 6
    missing = _cbf("hexdump", tmp_path / "nope.cbf")
    assert missing.returncode == 2 and len(missing.stderr.strip().splitlines()) == 1


def test_dir_shows_the_public_api() -> None:
    names = dir(cbf)
    assert set(cbf.__all__) <= set(names)
    for name in cbf.__all__:
        assert getattr(cbf, name) is not None


def test_the_python_readme_snippet_prints_what_it_promises(tmp_path: Path) -> None:
    text = (REPO / "generated" / "python" / "README.md").read_text(encoding="utf-8")
    line = next(ln for ln in text.splitlines() if ln.startswith("python -c "))
    golden = max((p for p in SMALL if p.name.startswith("valid.")), key=lambda p: p.stat().st_size)
    shutil.copy(golden, tmp_path / "part.cbf")
    env = {**os.environ, "PYTHONPATH": str(REPO / "generated" / "python")}
    res = subprocess.run(["bash", "-c", line.replace("python ", f"{sys.executable} ", 1)], cwd=tmp_path, env=env,
                         capture_output=True, text=True, check=True)
    names = [r.name for r in cbf.decode(golden.read_bytes()).records]
    assert res.stdout.strip() == str(names)
    assert len(res.stdout) < 20 * len(names)  # a name a record, not every layout of every command
    assert len(repr([r.command for r in cbf.decode(golden.read_bytes()).records])) < 40 * len(names)


def _git(repo: Path, *args: str) -> None:
    env = {**os.environ, "GIT_AUTHOR_NAME": "t", "GIT_AUTHOR_EMAIL": "t@example.com", "GIT_COMMITTER_NAME": "t",
           "GIT_COMMITTER_EMAIL": "t@example.com"}
    subprocess.run(["git", "-C", str(repo), *args], check=True, capture_output=True, env=env)


def test_changelog_from_the_release_tags(tmp_path: Path) -> None:
    """Two releases: the newer section lists what cbfgen diff finds between their specs."""
    repo = tmp_path / "repo"
    (repo / "spec").mkdir(parents=True)
    spec_text = (REPO / "spec" / "cbf.yaml").read_text(encoding="utf-8")
    (repo / "spec" / "cbf.yaml").write_text(spec_text, encoding="utf-8")
    _git(repo, "init", "-q")
    _git(repo, "add", "-A")
    _git(repo, "commit", "-qm", "one")
    _git(repo, "tag", "-a", "v0.0.1", "-m", "first")
    doc = yaml.safe_load(spec_text)
    # The next revision's name: any other string (a revision names itself as it likes: "04", "03-drill-rename")
    rev = str(doc["meta"]["revision"])
    new_rev = f"{int(rev) + 1:02d}" if rev.isdigit() else f"{rev}-next"
    doc["meta"]["revision"] = new_rev
    (repo / "spec" / "cbf.yaml").write_text(yaml.safe_dump(doc, sort_keys=False, allow_unicode=True), encoding="utf-8")
    _git(repo, "commit", "-qam", "two")
    out = repo / "CHANGELOG.md"
    run = [sys.executable, "-m", "cbfgen", "changelog", "--repo", str(repo), "--out", str(out)]
    assert subprocess.run(run, capture_output=True, text=True).returncode == 0
    text = out.read_text(encoding="utf-8")
    newest, first = text.index(f"## {cbfgen.__version__}"), text.index("## 0.0.1")
    assert newest < first
    section = text[newest:first]
    assert f"cbfgen diff v0.0.1 v{cbfgen.__version__}" in section and "revision_changed" in section
    assert f"rev {new_rev}" in section and "First release." in text[first:]
    assert subprocess.run([*run, "--check"], capture_output=True).returncode == 0
    out.write_text(text + "edited\n", encoding="utf-8")
    stale = subprocess.run([*run, "--check"], capture_output=True, text=True)
    assert stale.returncode == 1 and "stale" in stale.stderr


def test_licences_are_files_and_a_recorded_decision() -> None:
    assert "Apache License" in (REPO / "LICENSE").read_text(encoding="utf-8")
    content = (REPO / "LICENSE-CONTENT.md").read_text(encoding="utf-8")
    spec = yaml.safe_load((REPO / "spec" / "cbf.yaml").read_text(encoding="utf-8"))
    assert spec["meta"]["license"] in content and cbfgen.__license__ in content
    readme = (REPO / "README.md").read_text(encoding="utf-8")
    section = readme[readme.index("## Licences"):]
    assert cbfgen.__license__ in section[:1500] and "LICENSE-CONTENT.md" in section[:1500]


def _complete(script: Path, words: list[str]) -> list[str]:
    cmd = (f"source {script}; COMP_WORDS=({' '.join(repr(w) for w in words)}); COMP_CWORD={len(words) - 1}; "
           "_cbf; printf '%s\\n' \"${COMPREPLY[@]}\"")
    return subprocess.run(["bash", "-c", cmd], capture_output=True, text=True, check=True).stdout.split()


def test_bash_completion_and_man_page_come_from_the_parser(tmp_path: Path) -> None:
    import argparse

    from cbf.cli import parser
    from cbf.shellfiles import commands

    script = tmp_path / "cbf.bash"
    script.write_text(subprocess.run([sys.executable, "-m", "cbf.shellfiles", "bash"], capture_output=True,
                                     text=True, check=True).stdout, encoding="utf-8")
    cmds = commands(parser())
    subs = [c.path[0] for c in cmds if len(c.path) == 1]
    assert "hexdump" in subs and "validate" in subs
    assert _complete(script, ["cbf", ""]) == subs
    for c in cmds[1:]:
        options = [s for a in c.parser._actions if a.option_strings and a.help != argparse.SUPPRESS
                   for s in a.option_strings]
        assert _complete(script, ["cbf", *c.path, "-"]) == [o for o in options if o.startswith("-")], c.path
        for a in c.parser._actions:
            if a.option_strings and a.choices and a.nargs != 0:
                assert _complete(script, ["cbf", *c.path, a.option_strings[-1], ""]) == [str(x) for x in a.choices]
    page = subprocess.run([sys.executable, "-m", "cbf.shellfiles", "man"], capture_output=True, text=True,
                          check=True).stdout
    for c in cmds[1:]:
        assert f'.SH "CBF {" ".join(c.path).upper()}"' in page
        for a in c.parser._actions:
            for s in a.option_strings:
                assert s.replace("-", "\\-") in page
    if shutil.which("man"):
        shown = subprocess.run(["man", "-l", "-"], input=page, capture_output=True, text=True,
                               env={**os.environ, "MANWIDTH": "100", "MANPAGER": "cat", "PAGER": "cat"})
        assert shown.returncode == 0 and "CBF HEXDUMP" in shown.stdout, shown.stderr


def test_the_api_reference_page_is_read_from_the_code(tmp_path: Path) -> None:
    """pdoc reads the package: every public name has its section, functions their signatures with
    types, and the site shows the page in its navigation."""
    import inspect

    from cbfgen.emit.docs import api, site
    from cbfgen.loader import load

    text = api.page()
    for name in cbf.__all__:
        assert f"## `{name}` (" in text, name
    for name in ("decode", "validate", "encode"):
        params = inspect.signature(getattr(cbf, name)).parameters
        block = text[text.index(f"## `{name}` ("):]
        assert f"def {name}(" in block and all(p in block.split("```")[1] for p in params), name
    (tmp_path / "api.md").write_text(text, encoding="utf-8")
    files = site.pages(load(REPO / "spec" / "cbf.yaml"), api=tmp_path / "api.md")
    assert site.API_PAGE in files
    assert f'href="{site.API_PAGE}"' in files["index.html"].decode()
    assert "decode" in files[site.API_PAGE].decode()
