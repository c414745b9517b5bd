"""`python -m cbfgen`: load the spec and run every emitter; `cbfgen diff` compares two specs.

    python -m cbfgen [--spec spec/cbf.yaml] [--out generated] [--only EMITTER] [--check-spec]
                     [--no-ksc] [--golden DIR] [--report FILE]
    python -m cbfgen diff OLD.yaml NEW.yaml [--json]
    python -m cbfgen changelog [--check]         # CHANGELOG.md from the release tags (cbfgen.changelog)
    python -m cbfgen --version

Every binding or none: with the kaitai emitter, the Kaitai parsers are compiled too (cbfgen.ksc
says how the compiler is found); when it is not found, cbfgen says what is missing in one line
and exits 2 before writing anything. --no-ksc writes the .ksy without its parsers (this
repository's `make` compiles them in a later step). The docs' golden-case pages, the command
pages' CUT examples and the traceability matrix need the golden cases (--golden DIR) and the
conformance report (--report FILE, with the failure lists in failures/ beside it); without them
those sections say that no case or report is present, and cbfgen says so on stderr. A docs page
links a repository file (spec/cbf.yaml, conformance/golden/README.md, a case's .hex) only when it is
there beside the output folder, as in this repository (--out generated); elsewhere it names the file.

`diff` exits 0 when nothing is breaking, 1 when something is wire-breaking,
3 when something is text-breaking only (a rename), 2 on bad input (a spec
that does not load: the loader's one-line message); see cbfgen.diff.

Each emitter is a subpackage of cbfgen.emit exposing
``emit(spec: Spec) -> dict[str, bytes]`` (paths relative to the output
folder). The driver writes them atomically and removes files it no longer
produces from the folders it owns, so `generated/` is a pure function of
the spec.
"""

from __future__ import annotations

import argparse
import importlib
import os
import pkgutil
import sys
import tempfile
from pathlib import Path

from . import __version__
from . import emit as emit_pkg
from . import ksc as ksc_mod
from .diff import main as diff_cli
from .loader import SpecError, load
from .model import Spec

EXIT_OK, EXIT_BREAKING, EXIT_BAD_INPUT = 0, 1, 2


def emitters() -> list[str]:
    return sorted(m.name for m in pkgutil.iter_modules(emit_pkg.__path__) if m.ispkg)


def write_atomic(path: Path, data: bytes) -> bool:
    """Write data to path unless it already holds it; True when written."""
    try:
        if path.read_bytes() == data:
            return False
    except OSError:
        pass
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
        os.chmod(tmp, 0o755 if data.startswith(b"#!") else 0o644)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return True


def diff_main(argv: list[str]) -> int:
    from .witness import run as witness  # --witness: generates and runs both codecs

    # its exit codes (0 none, 1 wire-breaking, 3 text-breaking only, 2 bad input, 4 no witness): cbfgen.diff
    return diff_cli(argv, witness)


def _parser() -> argparse.ArgumentParser:
    ap = argparse.ArgumentParser(prog="cbfgen", description="Generate every CBF binding from the spec.",
                                 epilog="Exit codes: 0 written, 2 a spec that does not load or a tool that is "
                                        "missing (nothing written).")
    ap.add_argument("--version", action="version", version=f"cbfgen {__version__}")
    ap.add_argument("--spec", default="spec/cbf.yaml", help="the format spec (default: %(default)s)")
    ap.add_argument("--out", default="generated", help="output folder (default: %(default)s)")
    ap.add_argument("--only", action="append", choices=emitters(), help="run only this emitter (repeatable)")
    ap.add_argument("--check-spec", action="store_true", help="only load and check the spec")
    ap.add_argument("--no-ksc", action="store_true",
                    help="write the .ksy but not the Kaitai parsers (by default they are compiled, and a missing "
                         f"kaitai-struct-compiler {ksc_mod.VERSION} is an error)")
    ap.add_argument("--golden", type=Path, metavar="DIR",
                    help="golden cases (*.cbf, *.expect.yaml) for the docs' golden pages and CUT examples")
    ap.add_argument("--report", type=Path, metavar="FILE",
                    help="conformance report.json (failure lists in failures/ beside it) for the docs' "
                         "traceability matrix")
    return ap


def _subcommand(argv: list[str]) -> int | None:
    """The exit code of a subcommand (changelog, diff); None: argv asks for generation."""
    if argv[:1] == ["changelog"]:
        from .changelog import main as changelog_main  # only this subcommand needs git

        return changelog_main(argv[1:])
    if argv[:1] == ["diff"]:
        try:
            return diff_main(argv[1:])
        except SystemExit as exc:  # argparse: usage errors are bad input
            return EXIT_BAD_INPUT if exc.code else EXIT_OK
    return None


def _missing_input(args: argparse.Namespace) -> str | None:
    """The one line that names a --golden folder or --report file that is not there (None: both are)."""
    if args.golden is not None and not args.golden.is_dir():
        return f"{args.golden}: no such folder"
    if args.report is not None and not args.report.is_file():
        return f"{args.report}: no such file"
    return None


def _emit(spec: Spec, name: str, out: Path) -> int:
    """Run one emitter into ``out``; the number of files written or removed."""
    module = importlib.import_module(f"{emit_pkg.__name__}.{name}")
    files: dict[str, bytes] = module.emit(spec)
    changed = sum(write_atomic(out / rel, data) for rel, data in sorted(files.items()))
    # Remove stale files in the top folders this emitter owns, except
    # those produced by later build steps it declares (e.g. ksc output).
    keep = tuple(getattr(module, "KEEP", ()))
    for top in {Path(p).parts[0] for p in files}:
        for p in sorted((out / top).rglob("*")):
            rel = p.relative_to(out).as_posix()
            if p.is_file() and rel not in files and not rel.startswith(keep) and "__pycache__" not in rel:
                p.unlink()
                changed += 1
    return changed


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    code = _subcommand(argv)
    if code is not None:
        return code
    args = _parser().parse_args(argv)
    try:
        spec = load(args.spec)
    except SpecError as exc:  # every problem of the spec, one `file:line: message` a line
        print("\n".join(f"cbfgen: {line}" for line in str(exc).splitlines()), file=sys.stderr)
        return 2
    if args.check_spec:
        print(f"{args.spec}: ok ({len(spec.commands)} commands, {len(spec.checks)} checks)")
        return 0
    selected = args.only or emitters()
    compiler = None
    try:
        if "kaitai" in selected and not args.no_ksc:
            compiler = ksc_mod.find()  # before anything is written: every binding or none
    except ksc_mod.KscMissing as exc:
        print(f"cbfgen: {exc}", file=sys.stderr)
        return 2
    missing = _missing_input(args)
    if missing is not None:
        print(f"cbfgen: {missing}", file=sys.stderr)
        return 2
    out = Path(args.out)
    if "docs" in selected:
        _docs_inputs(args.golden, args.report, out)
    changed = sum(_emit(spec, name, out) for name in selected)
    if compiler is not None:
        try:
            ksc_mod.compile_parsers(compiler, out)
        except ksc_mod.KscMissing as exc:
            print(f"cbfgen: {exc}", file=sys.stderr)
            return 2
    print(f"cbfgen: {args.spec} -> {out}/ ({changed} file(s) changed"
          f"{', Kaitai parsers compiled' if compiler is not None else ''})")
    return 0


def _docs_inputs(golden: Path | None, report: Path | None, out: Path) -> None:
    """Point the docs emitter at the golden cases and the conformance report (its module's paths,
    read when it runs) and at the folder its links to repository files start from (out's parent: a
    page links such a file only when it is there); say on stderr which sections stay empty without them."""
    from .emit import docs

    docs.ROOT = out.resolve().parent

    if golden is not None:
        docs.GOLDEN = golden.resolve()
    if report is not None:
        docs.REPORT = report.resolve()
        docs.FAILURES = report.resolve().parent / "failures"
        docs.RELIABILITY = report.resolve().parent / "reliability.json"
    if not docs.GOLDEN.is_dir():
        print("cbfgen: docs: no golden cases (--golden DIR): the golden-case pages and the command pages' CUT "
              "examples say none is present", file=sys.stderr)
    if not docs.REPORT.is_file():
        print("cbfgen: docs: no conformance report (--report FILE): the traceability matrix shows no status",
              file=sys.stderr)


if __name__ == "__main__":
    sys.exit(main())
