"""The `cbf` command line.

Exit codes: 0 ok; 1 validation found an error; 2 bad usage, unreadable or
malformed input (one line on stderr naming what and where, no traceback).
``-`` means stdin/stdout. Outputs are written atomically (temp + rename).
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
from collections import Counter
from collections.abc import Sequence
from pathlib import Path
from typing import Any, NoReturn

EXIT_OK, EXIT_FINDINGS, EXIT_USAGE = 0, 1, 2


class _Fail(Exception):
    def __init__(self, message: str) -> None:
        super().__init__(message)
        self.message = message


def _max_file_size() -> int:
    from . import tables as T

    return T.HEADER_SIZE + (T.LIMITS["max_commands"] + 1) * (T.HEAD_SIZE + T.LIMITS["max_arg_size"])


def _read(path: str, limit: int) -> bytes:
    """Read at most ``limit`` bytes; larger input is refused (memory stays bounded)."""
    try:
        if path == "-":
            data = sys.stdin.buffer.read(limit + 1)
        else:
            p = Path(path)
            if p.is_dir():
                raise _Fail(f"{path}: is a directory")
            with p.open("rb") as fh:
                data = fh.read(limit + 1)
    except FileNotFoundError:
        raise _Fail(f"{path}: no such file") from None
    except PermissionError:
        raise _Fail(f"{path}: permission denied") from None
    except OSError as exc:
        raise _Fail(f"{path}: cannot read ({exc.strerror})") from None
    if len(data) > limit:
        raise _Fail(f"{path}: larger than {limit} bytes, the most a CBF file (or its text) can hold")
    return data


def _check_output(path: str) -> None:
    """Refuse an output path that cannot be written, before doing the work."""
    if path == "-":
        return
    target = Path(path)
    if not target.parent.is_dir():
        raise _Fail(f"{path}: folder {str(target.parent)!r} does not exist")
    if target.is_dir():
        raise _Fail(f"{path}: is a directory")


def _write(path: str, data: bytes) -> None:
    if path == "-":
        sys.stdout.buffer.write(data)
        sys.stdout.buffer.flush()
        return
    target = Path(path)
    if not target.parent.is_dir():
        raise _Fail(f"{path}: folder {str(target.parent)!r} does not exist")
    if target.is_dir():
        raise _Fail(f"{path}: is a directory")
    try:
        fd, tmp = tempfile.mkstemp(dir=target.parent, prefix=f".{target.name}.", suffix=".tmp")
    except OSError as exc:
        raise _Fail(f"{path}: cannot write ({exc.strerror})") from None
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, target)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def _decode(path: str) -> Any:
    from .codec import decode
    from .errors import CbfError

    data = _read(path, _max_file_size())
    try:
        return decode(data)
    except CbfError as exc:
        raise _Fail(f"{path}: {exc}") from None


def _text(path: str, data: bytes) -> str:
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = data[:exc.start].count(b"\n") + 1
        raise _Fail(f"{path}: line {line}: byte 0x{data[exc.start]:02X} is not text") from None


def cmd_decode(a: argparse.Namespace) -> int:
    _check_output(a.output)
    model = _decode(a.file)
    if a.to == "cut":
        from .cut import to_cut

        try:
            out = to_cut(model, profile=a.profile).encode()
        except ValueError as exc:
            raise _Fail(f"{a.file}: {exc}") from None
    else:
        from .canonical import to_canonical

        out = (json.dumps(to_canonical(model), indent=1) + "\n").encode()
    _write(a.output, out)
    return EXIT_OK


def cmd_encode(a: argparse.Namespace) -> int:
    from .codec import encode
    from .errors import CbfError

    _check_output(a.output)
    data = _read(a.file, 64 * _max_file_size())
    text = _text(a.file, data)
    kind = a.input_format or ("json" if a.file.endswith(".json") or text.lstrip().startswith("{") else "cut")
    try:
        if kind == "json":
            from .canonical import from_canonical

            try:
                doc = json.loads(text)
            except json.JSONDecodeError as exc:
                raise _Fail(f"{a.file}: line {exc.lineno}: not JSON ({exc.msg})") from None
            model = from_canonical(doc)
            if a.version:
                raise _Fail("--version applies to CUT input; JSON carries its version in the header")
        else:
            from .cut import from_cut

            model = from_cut(text, version=a.version, profile=a.profile)
        out = encode(model, keep_stored=a.keep_stored, profile=a.profile)
    except CbfError as exc:
        raise _Fail(f"{a.file}: {exc}") from None
    _write(a.output, out)
    return EXIT_OK


def cmd_validate(a: argparse.Namespace) -> int:
    from .validation import validate

    data = _read(a.file, _max_file_size())
    cutters = None
    if a.cutters:
        from .cutters import load_cutter_table
        from .errors import CbfError

        try:
            cutters = load_cutter_table(a.cutters)
        except CbfError as exc:
            raise _Fail(str(exc)) from None
    findings = validate(data, profile=a.profile, part_number=a.part_number, cutters=cutters)
    errors = sum(1 for f in findings if f.severity == "error")
    if a.json:
        doc = {"file": a.file, "profile": a.profile, "findings": [f.as_dict() for f in findings]}
        sys.stdout.write(json.dumps(doc, indent=1) + "\n")
    else:
        for f in findings:
            where = f"record {f.record}" if f.record is not None else "header"
            sys.stdout.write(f"{a.file}:{f.offset}: {f.severity} {f.check} ({where}): {f.message}\n")
        warnings = len(findings) - errors
        verdict = "FAIL" if errors else "ok"
        sys.stdout.write(f"{a.file}: {verdict}: {errors} error(s), {warnings} warning(s) [profile {a.profile}]\n")
    return EXIT_FINDINGS if errors else EXIT_OK


def cmd_info(a: argparse.Namespace) -> int:
    from . import tables as T

    model = _decode(a.file)
    h = model.header
    vid = T.version_id(*model.version)
    out = [f"file: {a.file}",
           f"version: {model.version[0]}.{model.version[1]} ({vid or 'unknown; read as ' + T.FALLBACK_VERSION})"]
    info = T.HEADERS[T.VERSION_BY_ID[model.version_id].header]
    for f in info.fields:
        v = getattr(h, f.name)
        if f.kind == "bytes":
            v = v.hex()
        elif f.kind == "uint" and (f.magic is not None or f.checksum):
            v = f"0x{v:0{2 * f.size}X}"
        out.append(f"{f.name}: {v}")
    out.append(f"records: {len(model.records)}")
    counts = Counter(r.name or f"unknown 0x{r.code:02X}" for r in model.records)
    for name, n in sorted(counts.items(), key=lambda kv: (-kv[1], kv[0])):
        out.append(f"  {name}: {n}")
    if model.trailing:
        out.append(f"trailing bytes: {len(model.trailing)}")
    sys.stdout.write("\n".join(out) + "\n")
    return EXIT_OK


class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> NoReturn:
        self.print_usage(sys.stderr)
        sys.stderr.write(f"{self.prog}: error: {message}\n")
        raise SystemExit(EXIT_USAGE)


def parser() -> argparse.ArgumentParser:
    from . import tables as T

    profiles = list(T.PROFILES)
    writable = [v.id for v in T.VERSIONS if v.writable]
    p = _Parser(prog="cbf", description=f"{T.SPEC_TITLE} toolkit: decode, encode, validate, info.",
                epilog="Exit codes: 0 ok, 1 validation found an error, 2 bad usage or unreadable input.")
    sub = p.add_subparsers(dest="cmd", required=True, parser_class=_Parser)
    d = sub.add_parser("decode", help="CBF to canonical JSON or CUT text")
    d.add_argument("file", help="CBF file, or - for stdin")
    d.add_argument("--to", choices=["json", "cut"], default="json")
    d.add_argument("--profile", choices=profiles, default=profiles[0], help="for CUT output")
    d.add_argument("-o", "--output", default="-", help="output file (default: stdout)")
    d.set_defaults(func=cmd_decode)
    e = sub.add_parser("encode", help="CUT text or canonical JSON to CBF")
    e.add_argument("file", help="FILE.cut or FILE.json, or - for stdin")
    e.add_argument("-o", "--output", required=True, help="output CBF file, or - for stdout")
    e.add_argument("--version", choices=writable, help=f"CBF version for CUT input (default {T.DEFAULT_VERSION})")
    e.add_argument("--profile", choices=profiles, default=profiles[0])
    e.add_argument("--input-format", choices=["cut", "json"], help="default: from the extension or content")
    e.add_argument("--keep-stored", action="store_true",
                   help="write stored sequence numbers, count and checksums as given (reproduce a faulty file)")
    e.set_defaults(func=cmd_encode)
    v = sub.add_parser("validate", help="run every integrity check")
    v.add_argument("file", help="CBF file, or - for stdin")
    v.add_argument("--profile", choices=profiles, default=profiles[0])
    v.add_argument("--part-number", help="implant part number to compare (check 6.1.1)")
    v.add_argument("--cutters", help="cutter table, CSV or YAML: name, length, radius (check 6.1.2)")
    v.add_argument("--json", action="store_true", help="print findings as JSON")
    v.set_defaults(func=cmd_validate)
    i = sub.add_parser("info", help="header summary and counts by command")
    i.add_argument("file", help="CBF file, or - for stdin")
    i.set_defaults(func=cmd_info)
    return p


def main(argv: Sequence[str] | None = None) -> int:
    try:
        args = parser().parse_args(argv)
        return int(args.func(args))
    except _Fail as exc:
        sys.stderr.write(f"cbf: {exc.message}\n")
        return EXIT_USAGE
    except KeyboardInterrupt:
        sys.stderr.write("cbf: interrupted\n")
        return 130
    except BrokenPipeError:
        return EXIT_OK
    except MemoryError:
        sys.stderr.write("cbf: out of memory\n")
        return EXIT_USAGE


if __name__ == "__main__":
    sys.exit(main())
