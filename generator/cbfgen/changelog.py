"""`cbfgen changelog`: CHANGELOG.md from the release tags and the spec's own history.

    python -m cbfgen changelog [--repo DIR] [--out CHANGELOG.md] [--check]

A release is a git tag ``vX.Y.Z`` (``make release`` makes it from ``cbfgen.__version__``). Each
release's section names the spec revision it implements and lists what `cbfgen diff` finds between
the previous release's spec and its own (BREAKING, TEXT, or neither); the toolkit version of the
working tree, when no tag names it yet, is the newest section (the spec of the working tree). The
format's own history (``history:`` and the document's revisions, ``meta.history``) closes the file.
Nothing else is read: the same tags and spec give the same file. ``--check`` exits 1 when the file
differs from what it would write (``make release`` checks it before tagging).
"""

from __future__ import annotations

import argparse
import re
import subprocess
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

from . import __version__
from .diff import diff
from .loader import SpecError, load
from .model import Spec

TAG = re.compile(r"^v(\d+)\.(\d+)\.(\d+)$")
SPEC = "spec/cbf.yaml"
EXIT_OK, EXIT_STALE, EXIT_BAD_INPUT = 0, 1, 2


@dataclass(frozen=True)
class Release:
    version: str
    ref: str | None  # the tag, or None for the working tree
    spec: Spec | None
    problem: str = ""  # why the spec at that ref does not load, if it does not


def _git(repo: Path, *args: str) -> str:
    return subprocess.run(["git", "-C", str(repo), *args], check=True, capture_output=True, text=True).stdout


def release_tags(repo: Path) -> list[str]:
    """The tags vX.Y.Z, oldest version first."""
    try:
        tags = _git(repo, "tag", "--list", "v*").split()
    except (OSError, subprocess.CalledProcessError):
        return []
    found = [(tuple(int(g) for g in m.groups()), t) for t in tags if (m := TAG.match(t))]
    return [t for _, t in sorted(found)]


def _spec_at(repo: Path, ref: str) -> tuple[Spec | None, str]:
    try:
        text = _git(repo, "show", f"{ref}:{SPEC}")
    except subprocess.CalledProcessError:
        return None, f"{ref} has no {SPEC}"
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "cbf.yaml"
        path.write_text(text, encoding="utf-8")
        try:
            return load(path), ""
        except SpecError as exc:
            return None, f"its spec does not load with today's loader: {str(exc).splitlines()[0]}"


def releases(repo: Path, spec_path: Path) -> list[Release]:
    out: list[Release] = []
    for tag in release_tags(repo):
        spec, problem = _spec_at(repo, tag)
        out.append(Release(tag[1:], tag, spec, problem))
    if not any(r.version == __version__ for r in out):
        out.append(Release(__version__, None, load(spec_path)))
    return out


def _section(rel: Release, prev: Release | None) -> list[str]:
    head = f"## {rel.version}"
    if rel.spec is None:
        return [head, "", f"Spec: not read ({rel.problem}).", ""]
    lines = [head, "", f"Implements spec {rel.spec.revision} ({rel.spec.meta['title']}), format versions "
             f"{', '.join(v.id for v in rel.spec.versions)}."]
    if prev is None:
        return [*lines, "", "First release.", ""]
    if prev.spec is None:
        return [*lines, "", f"Not compared with {prev.version}: {prev.problem}.", ""]
    d = diff(prev.spec, rel.spec, f"v{prev.version}", f"v{rel.version}")
    if not d.changes:
        return [*lines, "", f"The format is unchanged since {prev.version} (`cbfgen diff`: no change).", ""]
    lines += ["", f"`cbfgen diff v{prev.version} v{rel.version}`: {len(d.changes)} change(s), "
              f"{len(d.breaking)} wire-breaking, {len(d.text_breaking)} text-breaking.", ""]
    for c in d.changes:
        mark = {"wire": "**BREAKING** ", "text": "**TEXT** "}.get(c.impact, "")
        where = " ".join(x for x in (c.version, c.command) if x)
        lines.append(f"- {mark}{where + ': ' if where else ''}{c.kind}: {_md(c.detail)}")
    return [*lines, ""]


def _md(text: str) -> str:
    return re.sub(r"([\\`*_\[\]<>|])", r"\\\1", " ".join(text.split()))


def render(rels: list[Release], current: Spec) -> str:
    lines = ["# Changelog", "",
             "<!-- Written by `make changelog` (cbfgen changelog) from the release tags (vX.Y.Z, `make release`)",
             "     and the spec's history; do not edit. -->", "",
             "What each release of the CBF toolkit implements, and what `cbfgen diff` finds between the spec of",
             "one release and the next (BREAKING: a file of a version that exists changes meaning or judgement;",
             "TEXT: a name changes, every byte keeps its meaning). Newest first.", ""]
    for i in range(len(rels) - 1, -1, -1):
        lines += _section(rels[i], rels[i - 1] if i else None)
    lines += ["## The format's own history", "", f"From `{SPEC}` (`history:`, 7.2), spec {current.revision}:", ""]
    for note in current.history:
        lines.append(f"- version {_md(note.topic)}{' (' + note.date + ')' if note.date else ''}"
                     f"{', ' + note.clause if note.clause else ''}: {_md(note.text)}")
    doc_history = current.meta.get("history") or []
    if doc_history:
        lines += ["", f"Revisions of document {current.meta['part_number']}:", ""]
        for rev in doc_history:
            date = rev.get("date") or "date not stated"
            lines.append(f"- rev {rev.get('revision')} ({date}): {_md(str(rev.get('summary') or ''))}")
    return "\n".join(lines) + "\n"


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(prog="cbfgen changelog", description="Write CHANGELOG.md from the release tags "
                                 "(vX.Y.Z) and cbfgen diff between the releases' specs.",
                                 epilog="Exit codes: 0 written (or fresh with --check), 1 stale (--check), "
                                        "2 bad input.")
    ap.add_argument("--repo", type=Path, default=Path("."), help="the git checkout (default: this folder)")
    ap.add_argument("--out", type=Path, default=Path("CHANGELOG.md"), help="the file (default: %(default)s)")
    ap.add_argument("--check", action="store_true", help="write nothing; exit 1 when the file is stale")
    try:
        args = ap.parse_args(argv)
    except SystemExit as exc:
        return EXIT_BAD_INPUT if exc.code else EXIT_OK
    spec_path = args.repo / SPEC
    try:
        rels = releases(args.repo, spec_path)
        text = render(rels, load(spec_path))
    except SpecError as exc:
        print(f"cbfgen changelog: {str(exc).splitlines()[0]}", file=sys.stderr)
        return EXIT_BAD_INPUT
    if args.check:
        try:
            fresh = args.out.read_text(encoding="utf-8") == text
        except OSError:
            fresh = False
        if not fresh:
            print(f"cbfgen changelog: {args.out} is stale: run `make changelog` and commit it", file=sys.stderr)
            return EXIT_STALE
        return EXIT_OK
    tmp = args.out.with_name(f".{args.out.name}.tmp")
    tmp.write_text(text, encoding="utf-8")
    tmp.replace(args.out)
    return EXIT_OK
