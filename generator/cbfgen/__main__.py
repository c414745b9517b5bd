"""`python -m cbfgen`: load the spec and run every emitter.

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
from .loader import SpecError, load


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


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="cbfgen", description="Generate every CBF binding from the spec.")
    ap.add_argument("--spec", default="spec/cbf.yaml", help="the format spec (default: %(default)s)")
    ap.add_argument("--out", default="generated", help="output folder (default: %(default)s)")
    ap.add_argument("--only", action="append", choices=emitters(), help="run only this emitter (repeatable)")
    ap.add_argument("--check-spec", action="store_true", help="only load and check the spec")
    args = ap.parse_args(argv)
    try:
        spec = load(args.spec)
    except SpecError as exc:
        print(f"cbfgen: {exc}", file=sys.stderr)
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
