"""The `cbf` command line.

Exit codes: 0 ok; 1 validation found an error; 2 bad usage, unreadable or
malformed input (one line on stderr naming what and where, no traceback).
``-`` means stdin/stdout. Inputs larger than a CBF file (or its text) can be
are refused before they are read. Outputs are written atomically: the bytes
go, in chunks through ``os.write``, to an unnamed temporary file in the target
folder (O_TMPFILE; a named one where that is missing) that is linked and
renamed over the target only when complete, so a killed ``cbf`` leaves the
target as it was. An output that is a symlink is written through: the temporary
file goes beside the link's final target and replaces that, the link stays a
link. A character device or FIFO is written into, never replaced (a block device
or socket is refused). A standard output that cannot be written (a full disk,
/dev/full, a disk that fills part way) is one line on stderr and exit 2, for every
command: each write is checked (a short one written on), and what this process wrote to a
regular file on stdout is cut off again. A temporary name fits NAME_MAX whenever the final
name does.
"""

from __future__ import annotations

import argparse
import json
import os
import stat
import sys
from collections import Counter
from collections.abc import Iterator, Sequence
from pathlib import Path
from typing import Any, NoReturn

from .quoting import json_name, lines, quote

EXIT_OK, EXIT_FINDINGS, EXIT_USAGE = 0, 1, 2


class _Usage(Exception):
    """Bad usage found after parsing: the line argparse would print, exit 2."""

    def __init__(self, message: str) -> None:
        super().__init__(message)
        self.message = message


class _Fail(Exception):
    def __init__(self, message: str) -> None:
        super().__init__(message)
        self.message = message


class _StdoutFailed(Exception):
    """Standard output cannot be written (full disk, /dev/full): a usage-level failure (exit 2)."""

    def __init__(self, exc: OSError) -> None:
        super().__init__(exc.strerror)
        self.message = f"standard output: cannot write ({exc.strerror or exc})"


def _max_file_size() -> int:
    from . import tables as T

    return T.HEADER_SIZE + (T.LIMITS["max_commands"] + 1) * (T.HEAD_SIZE + T.LIMITS["max_arg_size"])


_CHUNK = 1 << 16


def _unreadable(path: str, exc: OSError) -> _Fail:
    """The one line for input that cannot be read (README, exit codes: 2)."""
    if isinstance(exc, FileNotFoundError):
        return _Fail(f"{quote(path)}: no such file")
    if isinstance(exc, PermissionError):
        return _Fail(f"{quote(path)}: permission denied")
    if isinstance(exc, IsADirectoryError):
        return _Fail(f"{quote(path)}: is a directory")
    from .files import NotRegular

    if isinstance(exc, NotRegular):
        return _Fail(f"{quote(path)}: {exc.message}")
    return _Fail(f"{quote(path)}: cannot read ({exc.strerror})")


def _too_big(path: str, limit: int) -> _Fail:
    """The one line for input over its limit (cbf-c says the same for a CBF file, from its size, unread)."""
    what = "a CBF file" if limit == _max_file_size() else "the text of a CBF file"
    return _Fail(f"{quote(path)}: larger than {limit} bytes, the most {what} can hold")


def _read(path: str, limit: int) -> bytes:
    """Read at most ``limit`` bytes; larger input is refused (memory stays bounded)."""
    try:
        if path == "-":
            data = sys.stdin.buffer.read(limit + 1)
        else:
            from .files import open_regular

            with open_regular(path) as fh:
                if os.fstat(fh.fileno()).st_size > limit:
                    raise _too_big(path, limit)  # refused unread
                data = fh.read(limit + 1)
    except OSError as exc:
        raise _unreadable(path, exc) from None
    if len(data) > limit:
        raise _too_big(path, limit)
    return data


def _read_text(path: str, limit: int) -> str:
    """Read UTF-8 text chunk by chunk: binary input fails at its first bad byte, unread beyond."""
    try:
        if path == "-":
            return _decode_chunks(path, sys.stdin.buffer, limit)
        from .files import open_regular

        with open_regular(path) as fh:
            if os.fstat(fh.fileno()).st_size > limit:
                raise _too_big(path, limit)
            return _decode_chunks(path, fh, limit)
    except OSError as exc:
        raise _unreadable(path, exc) from None


def _decode_chunks(path: str, fh: Any, limit: int) -> str:
    parts: list[str] = []
    carry = b""
    done = 0  # bytes before ``carry``
    lines = 1
    while True:
        chunk = fh.read(1 << 20)
        buf = carry + chunk
        if done + len(buf) > limit:
            raise _too_big(path, limit)
        try:
            text = buf.decode("utf-8")
            carry = b""
        except UnicodeDecodeError as exc:
            if chunk and exc.reason == "unexpected end of data":
                text, carry = buf[:exc.start].decode("utf-8"), buf[exc.start:]  # a character split by the chunk
            else:
                line = lines + buf[:exc.start].count(b"\n")
                raise _Fail(f"{quote(path)}: line {line} (offset {done + exc.start}): byte 0x{buf[exc.start]:02X} "
                            f"is not UTF-8 text") from None
        if not parts and not done and text.startswith("\ufeff"):
            text = text[1:]  # a byte order mark (editors on Windows write one)
        parts.append(text)
        lines += text.count("\n")
        done += len(buf) - len(carry)
        if not chunk:
            return "".join(parts)


def _output_target(path: str) -> tuple[Path, os.stat_result | None]:
    """Where ``-o path`` writes: a symlink is followed to its final target (the link stays a
    link), with that target's status, or None when it does not exist yet."""
    target = Path(os.path.realpath(path))
    try:
        return target, os.stat(target)
    except FileNotFoundError:
        return target, None
    except OSError as exc:
        raise _Fail(f"{quote(path)}: cannot write ({exc.strerror})") from None


def _check_output(path: str) -> None:
    """Refuse an output path that cannot be written, before doing the work."""
    if path == "-":
        return
    target, st = _output_target(path)
    if st is None:
        if not target.parent.is_dir():
            raise _Fail(f"{quote(path)}: folder {quote(str(target.parent))} does not exist")
        return
    if stat.S_ISDIR(st.st_mode):
        raise _Fail(f"{quote(path)}: is a directory")
    if not (stat.S_ISREG(st.st_mode) or stat.S_ISCHR(st.st_mode) or stat.S_ISFIFO(st.st_mode)):
        kind = "a block device" if stat.S_ISBLK(st.st_mode) else "a socket" if stat.S_ISSOCK(st.st_mode) else \
            "not a regular file"
        raise _Fail(f"{quote(path)}: is {kind}; cbf writes regular files, character devices and FIFOs only")


def _write_all(fd: int, data: bytes, sync: bool = True) -> None:
    """Write every byte of ``data`` to ``fd``, or raise: a short write is written on from where it
    stopped, and a write that takes nothing is an error (a full disk) rather than a short output.
    (BufferedWriter.write returns a short count without raising: 51,200 bytes of 1.4 MB, exit 0.)"""
    view = memoryview(data)
    while view:
        n = os.write(fd, view[:_CHUNK])
        if n <= 0:
            import errno

            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
        view = view[n:]
    if sync:
        os.fsync(fd)


def _name_max(folder: Path) -> int:
    """The longest file name (in bytes) the folder's file system takes."""
    try:
        return int(os.pathconf(folder, "PC_NAME_MAX"))
    except (OSError, ValueError):
        return 255


def _temp_prefix(target: Path, extra: int) -> str:
    """``.NAME.`` for a temporary file beside ``target``, NAME cut so that the prefix and ``extra``
    more bytes fit NAME_MAX whenever the target's own name does (a 244-byte name was refused)."""
    name = os.fsencode(target.name)
    room = _name_max(target.parent) - extra - 2  # the two dots
    if len(name) > room:
        name = name[:max(room, 1)]
    return f".{os.fsdecode(name)}."


def _temp_name(target: Path) -> Path:
    import secrets  # here, not at the top: a command that writes nothing starts faster without it

    rand = secrets.token_hex(6)
    return target.parent / f"{_temp_prefix(target, len(rand) + 4)}{rand}.tmp"


def _ordinary_mode() -> int:
    """The mode of an ordinary new file (0666 under the umask)."""
    umask = os.umask(0)
    os.umask(umask)
    return 0o666 & ~umask


def _write_unnamed(target: Path, data: bytes, mode: int) -> bool:
    """Write into an unnamed file (O_TMPFILE), then link it beside the target and rename
    it over the target. False when the system offers no unnamed files or cannot link
    them (nothing was made)."""
    flag = getattr(os, "O_TMPFILE", 0)
    if not flag or not Path("/proc/self/fd").is_dir():
        return False
    try:
        fd = os.open(target.parent, flag | os.O_WRONLY, 0o600)
    except OSError:
        return False
    tmp = _temp_name(target)
    try:
        os.fchmod(fd, mode)
        _write_all(fd, data)
        dir_fd = os.open(target.parent, os.O_RDONLY | getattr(os, "O_DIRECTORY", 0))
        try:
            # linkat(AT_SYMLINK_FOLLOW) through /proc: the dir_fd makes os.link call linkat
            os.link(f"/proc/self/fd/{fd}", tmp.name, dst_dir_fd=dir_fd, follow_symlinks=True)
        except OSError:
            return False
        finally:
            os.close(dir_fd)
    finally:
        os.close(fd)
    try:
        os.replace(tmp, target)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise
    return True


def _write_named(target: Path, data: bytes, mode: int) -> None:
    import tempfile  # here, not at the top (with shutil, random): a command that writes nothing starts faster

    fd, name = tempfile.mkstemp(dir=target.parent, prefix=_temp_prefix(target, 8 + 4), suffix=".tmp")
    try:
        os.fchmod(fd, mode)  # mkstemp makes 0600
        try:
            _write_all(fd, data)
        finally:
            os.close(fd)
        os.replace(name, target)
    except BaseException:
        Path(name).unlink(missing_ok=True)
        raise


# Standard output: every command's output goes through _out (text) or _write_stdout (bytes), which
# write through _write_all to file descriptor 1 (each write checked, a short one continued), text
# gathered to _CHUNK bytes first. A stdout that fails is one line on stderr and exit 2, and what this
# process had written to a regular file there is cut off again: nothing that looks complete stays.
_PENDING: list[bytes] = []
_STDOUT_START: list[int] = []  # where this process began writing a regular file on stdout


def _stdout_fd() -> int | None:
    """Standard output's file descriptor, or None when it is no file (a test's capture)."""
    try:
        return sys.stdout.fileno()
    except (AttributeError, OSError, ValueError):
        return None


def _stdout_failed(fd: int, exc: OSError) -> _StdoutFailed:
    if _STDOUT_START:
        try:
            os.ftruncate(fd, _STDOUT_START[0])  # the part written must not pass for the whole
        except OSError:
            pass
    return _StdoutFailed(exc)


def _write_fd1(fd: int, data: bytes) -> None:
    if not _STDOUT_START:
        try:
            start = os.lseek(fd, 0, os.SEEK_CUR) if stat.S_ISREG(os.fstat(fd).st_mode) else -1
        except OSError:
            start = -1
        _STDOUT_START.append(start)
        if start < 0:
            _STDOUT_START.clear()
            _STDOUT_START.append(-1)
    try:
        sys.stdout.flush()  # anything printed another way goes first
        _write_all(fd, data, sync=False)
    except BrokenPipeError:
        raise
    except OSError as exc:
        if _STDOUT_START[0] < 0:
            raise _StdoutFailed(exc) from None
        raise _stdout_failed(fd, exc) from None


def _flush_out() -> None:
    fd = _stdout_fd()
    if not _PENDING or fd is None:
        return
    data = b"".join(_PENDING)
    _PENDING.clear()
    _write_fd1(fd, data)


def _err(text: str) -> None:
    """Print to stderr, each line through the quoting rule's net (quoting.lines)."""
    sys.stderr.write(lines(text))


def _out(text: str) -> None:
    """Print to stdout, each line through the quoting rule's net (quoting.lines); a stdout that
    cannot be written is one line on stderr and exit 2."""
    text = lines(text)
    fd = _stdout_fd()
    if fd is None:
        try:
            sys.stdout.write(text)
        except BrokenPipeError:
            raise
        except OSError as exc:
            raise _StdoutFailed(exc) from None
        return
    _PENDING.append(text.encode(sys.stdout.encoding or "utf-8", sys.stdout.errors or "strict"))
    if len(_PENDING) > 256 or len(text) >= _CHUNK:
        _flush_out()


def _write_stdout(data: bytes) -> None:
    fd = _stdout_fd()
    if fd is None:
        try:
            sys.stdout.buffer.write(data)
            sys.stdout.buffer.flush()
        except BrokenPipeError:
            raise
        except OSError as exc:
            raise _StdoutFailed(exc) from None
        return
    _flush_out()
    _write_fd1(fd, data)


def _write(path: str, data: bytes) -> None:
    """Write ``data`` to ``path``: atomically to a regular file (a temporary file beside the
    final target of any symlink, renamed over that target), straight into a character
    device or FIFO (which is never replaced)."""
    if path == "-":
        _write_stdout(data)
        return
    _check_output(path)
    target, st = _output_target(path)
    try:
        if st is not None and not stat.S_ISREG(st.st_mode):  # a device or FIFO: _check_output allowed it
            fd = os.open(target, os.O_WRONLY | getattr(os, "O_NOCTTY", 0))
            try:
                _write_all(fd, data, sync=False)
            finally:
                os.close(fd)
            return
        mode = _ordinary_mode()
        if not _write_unnamed(target, data, mode):
            _write_named(target, data, mode)
    except OSError as exc:
        raise _Fail(f"{quote(path)}: cannot write ({exc.strerror})") from None


def _not_cbf(data: bytes) -> str | None:
    """Why a whole header is not a CBF header (both magic numbers wrong), or None."""
    from . import tables as T

    if len(data) < T.HEADER_SIZE:
        return None
    start, end = (int.from_bytes(data[f.offset:f.end], "little" if T.BO == "<" else "big") for f in (T.START, T.END))
    if start == T.START.magic or end == T.END.magic:
        return None
    hint = " (it is text: cbf encode reads CUT and JSON)" if _looks_like_text(data) else ""
    return (f"offset {T.START.offset}: not a CBF file: neither {T.START.name} nor {T.END.name} "
            f"holds its magic number{hint}")


def _decode(path: str) -> Any:
    from .codec import decode
    from .errors import CbfError

    data = _read(path, _max_file_size())
    reason = _not_cbf(data)
    if reason:
        raise _Fail(f"{quote(path)}: {reason}")
    try:
        return decode(data)
    except CbfError as exc:
        raise _Fail(f"{quote(path)}: {exc}") from None


def _looks_like_text(data: bytes) -> bool:
    head = data[:256]
    try:
        text = head.decode("utf-8")
    except UnicodeDecodeError as exc:
        if exc.start < len(head) - 3:
            return False
        text = head[:exc.start].decode("utf-8")  # a character cut by the slice
    return all(c.isprintable() or c in "\t\r\n" for c in text)


def cmd_decode(a: argparse.Namespace) -> int:
    _check_output(a.output)
    model = _decode(a.file)
    if a.to == "cut":
        from .cut import to_cut

        try:
            out = to_cut(model, profile=a.profile).encode()
        except ValueError as exc:
            raise _Fail(f"{quote(a.file)}: {exc}") from None
    else:
        from .canonical import to_canonical

        out = (json.dumps(to_canonical(model), indent=1) + "\n").encode()
    _write(a.output, out)
    return EXIT_OK


def cmd_encode(a: argparse.Namespace) -> int:
    if a.check:
        return _encode_check(a)
    if a.output is None:
        raise _Usage("cbf encode: the following arguments are required: -o/--output (see cbf encode --help)")
    if len(a.files) > 1:
        raise _Usage("cbf encode: one FILE with -o; several only with --check (see cbf encode --help)")
    a.file = a.files[0]
    data = _encode_one(a)
    _write(a.output, data)
    _warn_deprecated(a.output, data)
    return EXIT_OK


def _warn_deprecated(label: str, data: bytes, most: int = 10) -> None:
    """Writers warn (stderr, exit status unchanged) for each record of a command or layout the
    written version deprecates: the spec's deprecated checks, as validate reports them."""
    from . import tables as T
    from .validation import iter_findings

    ids = {c["id"] for c in T.checks_of("deprecated")}
    if not ids:
        return
    found = [f for f in iter_findings(data) if f.check in ids]
    for f in found[:most]:
        _err(f"cbf: warning: {quote(label)}: record {f.record} at offset {f.offset}: {f.message} "
                         f"(check {f.check}, {f.severity})\n")
    if len(found) > most:
        _err(f"cbf: warning: {quote(label)}: {len(found) - most} more deprecated record(s)\n")


def _cut_line_of(text: str, message: str) -> int | None:
    """The CUT line of the record an encode error names ("record N: ..."), or None."""
    import re

    from . import tables as T

    m = re.search(r"\brecord (\d+)\b", message)
    if m is None:
        return None
    want = int(m.group(1))
    ext = T.CUT["extensions"]
    fold = str.lower if T.CUT["keyword_case"] == "lower" else str
    not_records = {fold(T.CUT[k]) for k in ("header_keyword", "header_ext_keyword", "checksum_keyword")} | \
        {fold(ext["version_keyword"]), fold(ext["field_keyword"])}
    index = -1
    for n, line in enumerate(text.splitlines(), 1):
        word = line.strip(" ").split(" ", 1)[0]
        if word and fold(word) not in not_records:
            index += 1
            if index == want:
                return n
    return None


def _encode_check(a: argparse.Namespace) -> int:
    """--check: encode each file in memory, write nothing; one line per file that does not encode."""
    if a.output is not None:
        raise _Usage("cbf encode: --check writes nothing: drop -o (see cbf encode --help)")
    status = EXIT_OK
    for path in a.files:
        a.file = path
        try:
            _encode_one(a)
        except _Fail as exc:
            _err(f"cbf: {exc.message}\n")
            status = EXIT_USAGE
    return status


def _encode_one(a: argparse.Namespace) -> bytes:
    from .errors import CbfError
    from .writer import encode

    if a.output is not None:
        _check_output(a.output)
    text = _read_text(a.file, 64 * _max_file_size())
    if not text.strip():
        raise _Fail(f"{quote(a.file)}: empty input: nothing to encode")
    kind = a.input_format or ("json" if a.file.endswith(".json") or text.lstrip().startswith("{") else "cut")
    if a.keep_stored and kind != "json":
        # CUT carries no sequence numbers, count or checksums: there is nothing stored to keep
        raise _Fail(f"{quote(a.file)}: --keep-stored applies to JSON input only: CUT text carries no stored "
                    f"sequence numbers, count or checksums to keep")
    try:
        if kind == "json":
            from .canonical import from_canonical, loads

            try:
                doc = loads(text)  # exact numbers; duplicate keys refused with their path
            except json.JSONDecodeError as exc:
                raise _Fail(f"{quote(a.file)}: line {exc.lineno}: not JSON ({exc.msg})") from None
            except RecursionError:
                raise _Fail(f"{quote(a.file)}: JSON nested too deep to read") from None
            except ValueError as exc:  # e.g. an integer of more digits than Python converts
                raise _Fail(f"{quote(a.file)}: not JSON the codec reads ({exc})") from None
            model = from_canonical(doc)
            if a.version:
                raise _Fail("--version applies to CUT input; JSON carries its version in the header")
        else:
            from .cut import from_cut

            model = from_cut(text, version=a.version, profile=a.profile)
        return encode(model, keep_stored=a.keep_stored, profile=a.profile)
    except CbfError as exc:
        if kind == "cut" and exc.line is None:
            line = _cut_line_of(text, str(exc))
            if line is not None:  # CUT input: the line people edit, not an offset in bytes they never saw
                raise _Fail(f"{quote(a.file)}: line {line}: {exc.message}") from None
        raise _Fail(f"{quote(a.file)}: {exc}") from None


def _refuse_not_cbf(path: str, data: bytes) -> None:
    """Exit 2 for input that is not a CBF file (README, exit codes): shorter than the
    header, or both magic numbers wrong. Its findings would all follow from that."""
    from . import tables as T

    if len(data) < T.HEADER_SIZE:
        raise _Fail(f"{quote(path)}: offset 0: file is {len(data)} bytes, the header needs {T.HEADER_SIZE}: "
                    f"not a CBF file")
    reason = _not_cbf(data)
    if reason:
        raise _Fail(f"{quote(path)}: {reason}")


def _json_finding(d: dict[str, Any]) -> str:
    """One finding (a flat object) as json.dumps(..., indent=1) writes it inside the document,
    without its slow pure-Python indenting encoder (millions of findings are possible)."""
    from json.encoder import encode_basestring_ascii as jstr  # what json.dumps uses for str

    body = ",\n".join(f"   {jstr(k)}: " + ("null" if v is None else jstr(v) if isinstance(v, str)
                                             else str(v) if type(v) is int else json.dumps(v))
                      for k, v in d.items())
    return "  {\n" + body + "\n  }"


def _validate_options(a: argparse.Namespace) -> dict[str, Any]:
    """The options every input is validated with, read (and refused) once for the batch."""
    cutters = None
    if a.cutters:
        from .cutters import load_cutter_table
        from .errors import CbfError

        try:
            cutters = load_cutter_table(a.cutters)
        except CbfError as exc:
            raise _Fail(exc.message) from None  # names the table and its line already
    machine = None
    if a.machine:
        from .machine import MachineError, load_machine

        try:
            machine = load_machine(a.machine)
        except MachineError as exc:
            raise _Fail(exc.message) from None  # names the file and the JSON path already
    return {"profile": a.profile, "part_number": a.part_number, "cutters": cutters, "machine": machine}


def _expand(paths: Sequence[str]) -> list[tuple[str, str | None]]:
    """Each input as (path, why it is refused or None), in the order given: a folder is its
    ``*.cbf`` files, recursively, sorted by path; a folder with none is refused."""
    from .files import Unreadable, walk

    out: list[tuple[str, str | None]] = []
    for path in paths:
        if path != "-" and Path(path).is_dir():
            found: list[tuple[str, str | None]] = []
            for item in walk(path, ".cbf"):  # iterative: a tree of any depth
                if isinstance(item, Unreadable):  # never skipped: the batch fails (exit 2) naming it
                    found.append((item.path, f"{_unreadable(item.path, item.error).message} "
                                             f"(a folder: its files were not validated)"))
                else:
                    found.append((item, None))
            if not found:
                out.append((path, f"{quote(path)}: is a directory holding no *.cbf file"))
            out.extend(sorted(found))
        else:
            out.append((path, None))
    return out


_BATCH_OPTIONS: dict[str, Any] = {}  # set before the process pool forks: its workers read it


def _validate_one(item: tuple[str, str | None, bytes | None]) -> Any:
    """One input's FileResult (cbf.report): its findings, or the one line that refuses it."""
    from .report import FileResult
    from .validation import iter_findings

    path, refused, data = item
    if refused is not None:
        return FileResult(path, refused=refused)
    try:
        if data is None:
            data = _read(path, _max_file_size())
        _refuse_not_cbf(path, data)
    except _Fail as exc:
        return FileResult(path, refused=exc.message)
    return FileResult(path, tuple(iter_findings(data, **_BATCH_OPTIONS)))


def _jobs(text: str) -> int:
    n = _count(text)
    return n or len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else n or (os.cpu_count() or 1)


def _results(items: list[tuple[str, str | None, bytes | None]], jobs: int) -> Iterator[Any]:
    """Each input's result, in input order. A process pool (forked after the engine and numpy are
    imported, so no worker imports them again) only where it pays: several cores, many files."""
    if jobs <= 1 or len(items) < 4 * jobs or not hasattr(os, "fork"):
        yield from map(_validate_one, items)
        return
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    with ProcessPoolExecutor(jobs, mp_context=multiprocessing.get_context("fork")) as pool:
        yield from pool.map(_validate_one, items, chunksize=max(1, min(64, len(items) // (8 * jobs))))


def cmd_validate(a: argparse.Namespace) -> int:
    fmt = "json" if a.json else a.format
    if len(a.files) == 1 and fmt in ("text", "json") and (a.files[0] == "-" or not Path(a.files[0]).is_dir()):
        return _validate_stream(a, a.files[0], fmt)
    from . import report

    if a.files.count("-") > 1:
        raise _Fail("-: standard input given more than once")
    expanded = _expand(a.files)
    if len(expanded) == 1 and expanded[0][1] is not None:
        raise _Fail(expanded[0][1])  # one input, refused: one line, nothing on stdout (as for one file)
    items: list[tuple[str, str | None, bytes | None]] = []
    for path, refused in expanded:
        data = None
        if path == "-" and refused is None:  # read here: a worker process cannot share stdin
            try:
                data = _read(path, _max_file_size())
            except _Fail as exc:
                refused = exc.message
        items.append((path, refused, data))
    _BATCH_OPTIONS.clear()
    _BATCH_OPTIONS.update(_validate_options(a))
    from . import validation  # noqa: F401  (the engine and numpy, imported once, before any fork)

    most = _max_findings(a, fmt)
    results: list[Any] = []
    for r in _results(items, a.jobs):
        results.append(r)
        if r.refused is not None and fmt in ("text", "github"):
            _err(f"cbf: {r.refused}\n")
        if fmt == "text" and r.refused is None:
            _out(report.text(r, a.profile, most))
        elif fmt == "github":
            _out(report.github(r, most))
    if fmt == "text":
        _out(report.summary_line(results))
    elif fmt == "github":
        _err(report.summary_line(results))
    elif fmt == "json":
        _out(report.as_json(results, a.profile, most))
    elif fmt == "junit":
        _out(report.junit(results, a.profile, most))
    elif fmt == "sarif":
        _out(report.sarif(results, a.profile, most, base=a.base, docs_url=a.docs_url))
    else:
        _out(report.gitlab(results, most, base=a.base))
    return report.batch_status(results)


def _max_findings(a: argparse.Namespace, fmt: str) -> int:
    """--max-findings, or its default for the format: 50 where a person reads the lines, all elsewhere."""
    if a.max_findings is not None:
        return int(a.max_findings)
    return 50 if fmt in ("text", "github") else 0


def _validate_stream(a: argparse.Namespace, path: str, fmt: str) -> int:
    """One file: its findings printed as they are made, never all held (a file can give millions)."""
    data = _read(path, _max_file_size())
    _refuse_not_cbf(path, data)
    options = _validate_options(a)
    # The engine (and numpy) is imported once every input has been read and checked: a refused
    # file, cutter table or machine file costs no more than the refusal.
    from .report import finding_line, more_line, verdict_line
    from .validation import iter_findings

    findings = iter_findings(data, **options)
    errors = total = 0
    most = _max_findings(a, fmt)
    if fmt == "json":
        head = json.dumps({"file": json_name(path), "profile": a.profile}, indent=1)
        _out(head[:-2] + ',\n "findings": [')  # the same text as json.dumps of the whole document
        for f in findings:
            errors += f.severity == "error"
            total += 1
            if most == 0 or total <= most:
                _out(("\n" if total == 1 else ",\n") + _json_finding(f.as_dict()))
        _out("\n ]" if total else "]")
        _out(f',\n "not_shown": {total - most}\n}}\n' if most and total > most else "\n}\n")
    else:
        for f in findings:
            errors += f.severity == "error"
            total += 1
            if most == 0 or total <= most:
                _out(finding_line(path, f))
        if most and total > most:
            _out(more_line(path, total - most))
        _out(verdict_line(path, errors, total - errors, a.profile))
    return EXIT_FINDINGS if errors else EXIT_OK


def cmd_info(a: argparse.Namespace) -> int:
    from . import tables as T

    model = _decode(a.file)
    h = model.header
    vid = T.version_id(*model.version)
    info = T.HEADERS[T.VERSION_BY_ID[model.version_id].header]
    counts = Counter(r.name or f"unknown 0x{r.code:02X}" for r in model.records)
    by_count = sorted(counts.items(), key=lambda kv: (-kv[1], kv[0]))
    if a.json:
        header = {f.name: getattr(h, f.name).hex() if f.kind == "bytes" else getattr(h, f.name) for f in info.fields}
        doc = {"schema": 1, "file": json_name(a.file), "version": f"{model.version[0]}.{model.version[1]}",
               "version_id": vid,
               "read_as": model.version_id, "header": header, "records": len(model.records),
               "commands": dict(by_count), "trailing_bytes": len(model.trailing)}
        _out(json.dumps(doc, indent=1) + "\n")
        return EXIT_OK
    out = [f"file: {quote(a.file)}",
           f"version: {model.version[0]}.{model.version[1]} ({vid or 'unknown; read as ' + T.FALLBACK_VERSION})"]
    for f in info.fields:
        v = getattr(h, f.name)
        if f.kind == "bytes":
            v = v.hex()
        elif f.kind == "uint" and (f.magic is not None or f.checksum):
            v = f"0x{v:0{2 * f.size}X}"
        out.append(f"{f.name}: {quote(v) if f.kind == 'string' else v}")
    out.append(f"records: {len(model.records)}")
    for name, n in by_count:
        out.append(f"  {name}: {n}")
    if model.trailing:
        out.append(f"trailing bytes: {len(model.trailing)}")
    _out("\n".join(out) + "\n")
    return EXIT_OK


# -- toolpath tools (issue 16): convert, stats, diff, plot ------------------------
def _peek(path: str) -> bytes:
    """The first bytes of a file (not of stdin), with the errors _read gives."""
    from .files import open_regular

    try:
        with open_regular(path) as fh:
            return fh.read(256)
    except OSError as exc:
        raise _unreadable(path, exc) from None


def _load_any(path: str, fill_profile: str | None = None) -> Any:
    """A CBF file, or CUT / canonical JSON text, as a model: text when the first bytes are text.
    ``fill_profile``: CUT text stores no sequence numbers, count or checksums, so the encoder fills
    them under this profile (the model of the file ``cbf encode`` would write), to be judged as a
    file's are."""
    from .errors import CbfError

    if path == "-":
        data = _read(path, 64 * _max_file_size())
        if data and not _looks_like_text(data):
            return _decode_bytes(path, data)
        try:
            text = data.decode("utf-8")
        except UnicodeDecodeError as exc:
            raise _Fail(f"{quote(path)}: offset {exc.start}: byte 0x{data[exc.start]:02X} is not UTF-8 text") from None
    else:
        head = _peek(path)
        if head and not _looks_like_text(head):
            return _decode(path)  # CBF: read with the CBF size limit
        text = _read_text(path, 64 * _max_file_size()) if head else ""
    if not text.strip():
        raise _Fail(f"{quote(path)}: offset 0: empty input (0 bytes of CBF, no CUT or JSON text)")
    try:
        if text.lstrip().startswith("{"):
            from .canonical import from_canonical, loads

            try:  # as encode reads it: exact numbers, a key given twice refused with its path
                return from_canonical(loads(text))
            except json.JSONDecodeError as exc:
                raise _Fail(f"{quote(path)}: line {exc.lineno}: not JSON ({exc.msg})") from None
            except (RecursionError, ValueError) as exc:
                raise _Fail(f"{quote(path)}: not JSON the codec reads ({type(exc).__name__})") from None
        from .cut import from_cut

        model = from_cut(text)
        if fill_profile is None:
            return model
        from . import tables as T
        from .codec import decode, pack_file

        if not T.VERSION_BY_ID[model.version_id].writable:
            raise _Fail(f"{quote(path)}: CUT text of version {model.version_id}, which this toolkit reads but does not "
                        f"write: the stored fields cannot be filled to be judged; convert its CBF file")
        return decode(pack_file(model, profile=fill_profile))
    except CbfError as exc:
        raise _Fail(f"{quote(path)}: {exc}") from None
    except (ValueError, OverflowError) as exc:  # packing: a value no field holds
        raise _Fail(f"{quote(path)}: {exc}") from None


def _decode_bytes(path: str, data: bytes) -> Any:
    from .codec import decode
    from .errors import CbfError

    if len(data) > _max_file_size():
        raise _too_big(path, _max_file_size())
    try:
        return decode(data)
    except CbfError as exc:
        raise _Fail(f"{quote(path)}: {exc}") from None


def _clean(path: str, model: Any, profile: str) -> None:
    """Refuse a model that fails validation under the profile the tool writes: the tools below
    assume a sound file."""
    from .validation import validate

    errors = [f for f in validate(model, profile=profile) if f.severity == "error"]
    if errors:
        e = errors[0]
        where = f"record {e.record}" if e.record is not None else "header"
        again = f"cbf validate {quote(path)}" if profile == "default" else \
            f"cbf validate --profile {profile} {quote(path)}"
        raise _Fail(f"{quote(path)}: offset {e.offset}: {where} fails check {e.check} ({e.message}); run {again}")


def _mm(text: str) -> float:
    try:
        x = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a length in mm: {text!r}") from None
    if not (x > 0.0 and x < float("inf")):
        raise argparse.ArgumentTypeError(f"not a positive length in mm: {text!r}")
    return x


def cmd_convert(a: argparse.Namespace) -> int:
    from .convert import convert
    from .errors import CbfError
    from .writer import encode

    _check_output(a.output)
    fill: dict[str, str] = {}
    for item in a.fill:
        name, eq, value = item.partition("=")
        if not eq or not name or not value:
            raise _Fail(f"--fill '{quote(item)}': expected ARG=VALUE, e.g. --fill completion=0")
        if name in fill:
            raise _Fail(f"--fill {quote(name)}: given twice")
        fill[name] = value
    model = _load_any(a.file, fill_profile=a.profile)  # CUT input: its checksums are the encoder's to fill
    _clean(a.file, model, a.profile)
    try:
        conv = convert(model, a.to_version, chord_tol=a.chord_tol, fill=fill, profile=a.profile)
        out = encode(conv.model, profile=a.profile)
    except CbfError as exc:
        raise _Fail(f"{quote(a.file)}: {exc}") from None
    _write(a.output, out)
    _warn_deprecated(a.output, out)
    line = (f"{quote(a.file)} -> {quote(a.output)}: version {conv.source_version} -> {conv.target_version}, "
            f"{len(model.records)} -> {len(conv.model.records)} records, {conv.curves} curve(s) as "
            f"{conv.segments} line segment(s), largest deviation {conv.max_deviation:.6f} mm "
            f"(tolerance {conv.chord_tol} mm)\n")
    if a.output == "-":
        _err(line)
    else:
        _out(line)
    return EXIT_OK


def cmd_stats(a: argparse.Namespace) -> int:
    from .stats import render, stats

    model = _load_any(a.file)
    s = stats(model)
    if a.json:
        _out(json.dumps({"file": json_name(a.file), **s.as_dict()}, indent=1) + "\n")
    else:
        _out(render(s, quote(a.file)))
    return EXIT_OK


def cmd_diff(a: argparse.Namespace) -> int:
    import time

    from . import semdiff
    from . import tables as T

    start = time.monotonic()

    def progress(message: str) -> None:  # a long run says what it is doing; a short one stays quiet
        if time.monotonic() - start > 1.0:
            _err(f"cbf diff: {message} ({time.monotonic() - start:.1f} s)\n")
            sys.stderr.flush()

    ma = _load_any(a.a)
    progress(f"read {quote(a.a)}: {len(ma.records)} records")
    mb = _load_any(a.b)
    progress(f"read {quote(a.b)}: {len(mb.records)} records")
    tol = T.TOL["position_mm"] if a.tol is None else a.tol
    d = semdiff.diff(ma, mb, tol, progress)
    if a.json:
        _out(json.dumps(semdiff.as_dict(d, json_name(a.a), json_name(a.b)), indent=1) + "\n")
    else:
        _out(semdiff.render(d, ma, mb, quote(a.a), quote(a.b)))
    return EXIT_OK if d.equal else EXIT_FINDINGS


def cmd_plot(a: argparse.Namespace) -> int:
    from . import plot

    _check_output(a.output)
    model = _load_any(a.file)
    fmt = a.format or Path(a.output).suffix.lstrip(".").lower()
    if fmt not in plot.FORMATS:
        raise _Fail(f"{quote(a.output)}: cannot tell the format from the name; end it in "
                    f"{', '.join('.' + f for f in plot.FORMATS)} or give --format")
    try:
        out = plot.render(model, fmt, a.color, a.title if a.title is not None else quote(a.file))
    except plot.PlotUnavailable as exc:
        raise _Fail(str(exc)) from None
    _write(a.output, out)
    return EXIT_OK


class _Parser(argparse.ArgumentParser):
    def print_help(self, file: Any = None) -> None:
        # argparse ignores a failed write; --help into a full stdout must not (exit 2)
        if file is None or file is sys.stdout:
            _out(self.format_help())
        else:
            super().print_help(file)

    def error(self, message: str) -> NoReturn:
        # one line, like every other error (the usage is one --help away)
        _err(f"{self.prog}: {' '.join(message.split())} (see {self.prog} --help)\n")
        raise SystemExit(EXIT_USAGE)


def _count(text: str) -> int:
    if not text.isascii() or not text.isdigit():
        raise argparse.ArgumentTypeError(f"not a count: {text!r}")
    return int(text)


class _Version(argparse.Action):
    def __init__(self, option_strings: Sequence[str], dest: str, help: str | None = None) -> None:
        super().__init__(option_strings, dest, nargs=0, help=help)

    def __call__(self, parser: argparse.ArgumentParser, namespace: argparse.Namespace, values: Any,
                 option_string: str | None = None) -> None:
        _out(version_text() + "\n")  # not argparse's "version" action: it ignores a failed write
        parser.exit(EXIT_OK)


def version_text() -> str:
    """What ``cbf --version`` prints: the toolkit version and the spec revision (cbf-c prints the same)."""
    from .version import SPEC_REVISION, __version__

    return f"cbf {__version__} (spec {SPEC_REVISION})"


def _schema_path(name: str) -> str:
    """Where the installed package keeps a JSON schema (shipped beside the code)."""
    return str(Path(__file__).resolve().parent / f"{name}.schema.json")


def parser() -> argparse.ArgumentParser:
    from . import tables as T

    profiles = list(T.PROFILES)
    writable = [v.id for v in T.VERSIONS if v.writable]
    p = _Parser(prog="cbf", description=f"{T.SPEC_TITLE} toolkit: decode, encode, validate, info, "
                                        f"convert, stats, diff, plot.",
                epilog="Exit codes: 0 ok, 1 validation found an error, 2 bad usage or unreadable input.")
    p.add_argument("--version", action=_Version, help="print the toolkit version and the spec revision, and exit")
    sub = p.add_subparsers(dest="cmd", required=True, parser_class=_Parser)
    d = sub.add_parser("decode", help="CBF to canonical JSON or CUT text")
    d.add_argument("file", help="CBF file, or - for stdin")
    d.add_argument("--to", choices=["json", "cut"], default="json",
                   help="canonical JSON (default; PROTOCOL.md's shape, schema: "
                        f"{_schema_path('canonical')}) or CUT text (cbf encode reads both back)")
    d.add_argument("--profile", choices=profiles, default=profiles[0], help="for CUT output")
    d.add_argument("-o", "--output", default="-", help="output file (default: stdout)")
    d.set_defaults(func=cmd_decode)
    e = sub.add_parser("encode", help="CUT text or canonical JSON to CBF")
    e.add_argument("files", nargs="+", metavar="file", help="FILE.cut or FILE.json, or - for stdin (several with "
                                                             "--check)")
    e.add_argument("-o", "--output", help="output CBF file, or - for stdout (required unless --check)")
    e.add_argument("--check", action="store_true",
                   help="only check that each file encodes (a pre-commit hook on *.cut): write nothing, one line "
                        "per file that does not, exit 2 then")
    e.add_argument("--version", choices=writable, help=f"CBF version for CUT input (default {T.DEFAULT_VERSION})")
    e.add_argument("--profile", choices=profiles, default=profiles[0])
    e.add_argument("--input-format", choices=["cut", "json"], help="default: from the extension or content")
    e.add_argument("--keep-stored", action="store_true",
                   help="JSON input only: write stored sequence numbers, count and checksums as given "
                        "(reproduce a faulty file); refused for CUT input, which stores none")
    e.set_defaults(func=cmd_encode)
    v = sub.add_parser("validate", help="run every integrity check on files and folders",
                       description="Validate CBF files: each FILE, each folder's *.cbf files (recursively, "
                                   "sorted), - for stdin; in one process, results in input order. Exit status: "
                                   "the worst of the inputs (0 ok, 1 an error finding, 2 an input not validated).")
    v.add_argument("files", nargs="+", metavar="file", help="CBF file, folder (its *.cbf files), or - for stdin")
    v.add_argument("--profile", choices=profiles, default=profiles[0])
    v.add_argument("--part-number", help="implant part number to compare (check 6.1.1)")
    from .optfiles import RULES

    table = ", ".join(RULES["cutter_table"]["columns"])  # the spec's cutter role keys (cbfgen/options.py)
    checks = "/".join(c["id"] for c in T.checks_of("cutter_table"))
    v.add_argument("--cutters", help=f"cutter table, CSV or YAML: {table} (check {checks})")
    v.add_argument("--machine", metavar="FILE",
                   help=f"machine limits, JSON or YAML (schema: {_schema_path('machine')}): breaches become "
                        f"errors; without it the spec's default machine gives warnings (check machine_limits)")
    v.add_argument("--format", choices=["text", "json", "junit", "sarif", "github", "gitlab"], default="text",
                   help=f"text (default); json (schema: {_schema_path('validate')}); junit (JUnit XML); sarif "
                        f"(SARIF 2.1.0); github (workflow annotation commands); gitlab (code quality report)")
    v.add_argument("--json", action="store_true", help="the same as --format json")
    v.add_argument("--max-findings", type=_count, default=None, metavar="N",
                   help="at most N findings a file in every format, then how many more there are; 0 gives all "
                        "(default 50 for text and github, 0 for the others; sarif holds at most GitHub's "
                        "25,000 results a run and says what it left out)")
    v.add_argument("--base", metavar="DIR", default=".",
                   help="sarif and gitlab: paths relative to this folder (the repository's root; default: the "
                        "working directory), SARIF's uriBaseId SRCROOT")
    v.add_argument("--docs-url", metavar="URL", default=os.environ.get("CBF_DOCS_URL"),
                   help="sarif: the published reference page (its index.html) the rules' help links to, at each "
                        "check's anchor (default: $CBF_DOCS_URL; without it the help names the clause and anchor)")
    v.add_argument("-j", "--jobs", type=_jobs, default=_jobs("0"), metavar="N",
                   help="processes for many files (default 0: every core this process may use)")
    v.set_defaults(func=cmd_validate)
    i = sub.add_parser("info", help="header summary and counts by command")
    i.add_argument("file", help="CBF file, or - for stdin")
    i.add_argument("--json", action="store_true", help=f"print JSON (schema: {_schema_path('info')})")
    i.set_defaults(func=cmd_info)
    _tool_parsers(sub, profiles, writable)
    _hexdump_parser(sub, profiles)
    return p


def _flush_stdout() -> None:
    _flush_out()
    try:
        sys.stdout.flush()
    except BrokenPipeError:
        raise
    except OSError as exc:
        raise _StdoutFailed(exc) from None


def _drop_stdout() -> None:
    """After stdout failed: send what is still buffered to /dev/null, so that the
    interpreter's flush at exit cannot fail a second time with a traceback."""
    try:
        fd = sys.stdout.fileno()
        null = os.open(os.devnull, os.O_WRONLY)
    except (OSError, ValueError):
        return
    try:
        os.dup2(null, fd)
    finally:
        os.close(null)


def _tool_parsers(sub: Any, profiles: list[str], writable: list[str]) -> None:
    from . import tables as T

    c = sub.add_parser("convert", help="move a file to another version (curves to line segments for versions "
                                       "without them)")
    c.add_argument("file", help="CBF file (or CUT / JSON text), or - for stdin")
    c.add_argument("-o", "--output", required=True, help="output CBF file, or - for stdout")
    c.add_argument("--to-version", required=True, choices=writable, help="the version to write")
    c.add_argument("--chord-tol", type=_mm, metavar="MM",
                   help=f"largest chordal deviation of a curve's line segments (default {T.TOL['position_mm']} "
                        f"mm, tolerances.position_mm)")
    c.add_argument("--fill", action="append", default=[], metavar="ARG=VALUE",
                   help="value of an argument the source layout lacks: a number, or 'position' (the tool "
                        "position at that record); e.g. --fill recovery_point=position --fill completion=0")
    c.add_argument("--profile", choices=profiles, default=profiles[0])
    c.set_defaults(func=cmd_convert)
    s = sub.add_parser("stats", help="toolpath summary: bounding box, path length, time estimate, shapes, "
                                     "cutters, phases, checkpoints")
    s.add_argument("file", help="CBF file (or CUT / JSON text), or - for stdin")
    s.add_argument("--json", action="store_true", help=f"print JSON (schema: {_schema_path('stats')})")
    s.set_defaults(func=cmd_stats)
    f = sub.add_parser("diff", help="semantic diff of two files (CBF or CUT on either side); exit 0 equal "
                                    "within --tol, 1 differ, 2 bad input")
    f.add_argument("a", help="first file (CBF, CUT or JSON)")
    f.add_argument("b", help="second file (CBF, CUT or JSON)")
    f.add_argument("--tol", type=_mm, metavar="MM",
                   help=f"every number (mm, m/s, ... in its own unit) is equal within this (default "
                        f"{T.TOL['position_mm']}, tolerances.position_mm)")
    f.add_argument("--json", action="store_true", help=f"print JSON (schema: {_schema_path('diff')})")
    f.set_defaults(func=cmd_diff)
    g = sub.add_parser("plot", help="draw the toolpath: isometric view and three projections (needs matplotlib, "
                                    "the plot extra)")
    g.add_argument("file", help="CBF file (or CUT / JSON text), or - for stdin")
    g.add_argument("-o", "--output", required=True, help="OUT.png, OUT.svg or OUT.pdf (- for stdout with --format)")
    g.add_argument("--format", choices=["png", "svg", "pdf"], help="default: from the output's extension")
    g.add_argument("--color", choices=["cut", "phase", "shape", "cutter"], default="cut",
                   help="colour moves by cutting / non-cutting (default), phase, shape or cutter")
    g.add_argument("--title", help="figure title (default: the file name)")
    g.set_defaults(func=cmd_plot)


# -- cbf hexdump (issue 35, point 7): the golden pages' annotated view of any file, findings marked ---------
def _hexdump_parser(sub: Any, profiles: list[str]) -> None:
    h = sub.add_parser("hexdump", help="annotated hex of a file: every header field, record head and argument "
                                       "with its value, findings marked (the golden pages' view)",
                       description="Print FILE as hex, 16 bytes a row, each run of bytes named by the field it "
                                   "is and its value; a row holding a finding's offset ends with \u25c0 and the "
                                   "finding as validate prints it (FILE:OFFSET: severity check (record N): "
                                   "message). The same view the format reference draws for its golden files.")
    h.add_argument("file", help="CBF file, or - for stdin")
    h.add_argument("--record", type=_count, metavar="N", help="only record N (0-based)")
    h.add_argument("--header", action="store_true", help="only the header")
    h.add_argument("--max-lines", type=_count, default=0, metavar="N", help="stop after N lines (default 0: all)")
    h.add_argument("--profile", choices=profiles, default=profiles[0], help="the profile findings are judged by")
    h.add_argument("--no-findings", action="store_true", help="do not validate; no marks")
    h.set_defaults(func=cmd_hexdump)


def cmd_hexdump(a: argparse.Namespace) -> int:
    from . import hexdump
    from .validation import validate

    data = _read(a.file, _max_file_size())
    _refuse_not_cbf(a.file, data)  # as validate: exit 2, one line, for input that is not a CBF file
    from .report import finding_line

    marks: list[hexdump.Mark] = []
    errors = 0
    if not a.no_findings:
        for f in validate(data, profile=a.profile):
            # each mark is the finding as validate prints it: the file (quoted) and the offset name it
            errors += f.severity == "error"
            marks.append(hexdump.Mark(f.offset if f.offset is not None else len(data),
                                      finding_line(a.file, f).rstrip("\n")))
    _out(hexdump.dump(hexdump.for_runtime(), data, max_lines=a.max_lines or None, only_record=a.record,
                      header_only=a.header, marks=marks) + "\n")
    return EXIT_FINDINGS if errors else EXIT_OK


def main(argv: Sequence[str] | None = None) -> int:
    _PENDING.clear()
    _STDOUT_START.clear()
    try:
        try:
            args = parser().parse_args(argv)
            code = int(args.func(args))
        except SystemExit as exc:  # argparse: --help, --version, a usage error
            code = exc.code if isinstance(exc.code, int) else EXIT_OK if exc.code is None else EXIT_USAGE
        _flush_stdout()
        return code
    except (_Fail, _Usage) as exc:
        try:
            _flush_out()  # what was printed before the failure (a batch's earlier files)
        except _StdoutFailed:
            _drop_stdout()
        _err(f"cbf: {exc.message}\n" if isinstance(exc, _Fail) else f"{exc.message}\n")
        return EXIT_USAGE
    except _StdoutFailed as exc:
        _drop_stdout()
        _err(f"cbf: {exc.message}\n")
        return EXIT_USAGE
    except KeyboardInterrupt:
        _err("cbf: interrupted\n")
        return 130
    except BrokenPipeError:
        _drop_stdout()
        return EXIT_OK
    except MemoryError:
        _err("cbf: out of memory\n")
        return EXIT_USAGE


if __name__ == "__main__":
    sys.exit(main())
