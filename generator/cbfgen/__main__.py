"""`python -m cbfgen`: load the spec and run every emitter; `cbfgen diff` compares two specs.

    python -m cbfgen [--spec spec/cbf.yaml] [--out generated] [--only EMITTER] [--check-spec]
    python -m cbfgen diff OLD.yaml NEW.yaml [--json]

`diff` exits 0 when nothing is breaking, 1 when something is, 2 on bad input
(a spec that does not load: the loader's one-line message).

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

from . import emit as emit_pkg
from .diff import diff, render
from .loader import SpecError, load

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
    ap = argparse.ArgumentParser(prog="cbfgen diff", description=(
        "List every change from OLD to NEW by version and command, and mark BREAKING each change to the wire "
        "meaning of a version OLD already has. Exit 0: nothing breaking, 1: breaking, 2: bad input."))
    ap.add_argument("old", help="the spec before the revision")
    ap.add_argument("new", help="the spec after the revision")
    ap.add_argument("--json", action="store_true", help="one JSON document for tools")
    ap.add_argument("--old-name", help="name OLD by this in the output (default: its path)")
    args = ap.parse_args(argv)
    try:
        old, new = load(args.old), load(args.new)
    except SpecError as exc:
        print(f"cbfgen diff: {exc}", file=sys.stderr)
        return EXIT_BAD_INPUT
    result = diff(old, new, args.old_name or args.old, args.new)
    sys.stdout.write(render(result, args.json))
    return EXIT_BREAKING if result.breaking else EXIT_OK


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if argv[:1] == ["diff"]:
        try:
            return diff_main(argv[1:])
        except SystemExit as exc:  # argparse: usage errors are bad input
            return EXIT_BAD_INPUT if exc.code else EXIT_OK
    ap = argparse.ArgumentParser(prog="cbfgen", description="Generate every CBF binding from the spec.")
    ap.add_argument("--spec", default="spec/cbf.yaml", help="the format spec (default: %(default)s)")
    ap.add_argument("--out", default="generated", help="output folder (default: %(default)s)")
    ap.add_argument("--only", action="append", choices=emitters(), help="run only this emitter (repeatable)")
    ap.add_argument("--check-spec", action="store_true", help="only load and check the spec")
    args = ap.parse_args(argv)
    try:
        spec = load(args.spec)
    except SpecError as exc:  # every problem of the spec, one `file:line: message` a line
        print("\n".join(f"cbfgen: {line}" for line in str(exc).splitlines()), file=sys.stderr)
        return 2
    if args.check_spec:
        print(f"{args.spec}: ok ({len(spec.commands)} commands, {len(spec.checks)} checks)")
        return 0
    out = Path(args.out)
    changed = 0
    for name in args.only or emitters():
        module = importlib.import_module(f"{emit_pkg.__name__}.{name}")
        files: dict[str, bytes] = module.emit(spec)
        owned = {Path(p).parts[0] for p in files}
        for rel, data in sorted(files.items()):
            changed += write_atomic(out / rel, data)
        # Remove stale files in the top folders this emitter owns, except
        # those produced by later build steps it declares (e.g. ksc output).
        keep = tuple(getattr(module, "KEEP", ()))
        for top in owned:
            root = out / top
            for p in sorted(root.rglob("*")):
                rel = p.relative_to(out).as_posix()
                if p.is_file() and rel not in files and not rel.startswith(keep) and "__pycache__" not in rel:
                    p.unlink()
                    changed += 1
    print(f"cbfgen: {args.spec} -> {out}/ ({changed} file(s) changed)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
