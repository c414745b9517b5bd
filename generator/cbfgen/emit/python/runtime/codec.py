"""decode and pack_file: bytes <-> Cbf, lossless (``pack_file(decode(b), keep_stored=True) == b``).

Framing and the checksums live here too; validation builds on them, the writer (writer.py) on both."""

from __future__ import annotations

import struct
from array import array
from collections.abc import Iterable, Iterator, Sequence
from functools import lru_cache
from typing import Any

from . import tables as T
from .checksums import compute
from .errors import EncodeError, TruncatedError
from .fields import Buffer, check_strings, convert_values, pack_fields
from .model import Cbf, PackedRecords, RecordList


# -- framing -------------------------------------------------------------------
def frame(buf: Buffer) -> tuple[Sequence[int], int]:
    """Record offsets from the header to the end (D1), and where framing stopped.

    The offsets are a compact array (8 bytes a record, not a list of int objects)."""
    n = len(buf)
    pos = T.HEADER_SIZE
    head, at = T.HEAD_SIZE, T.ARG_SIZE_OFFSET
    last = n - head  # a record head must start at or before this offset
    offsets = array("q")
    if n >= FAST_FRAME_BYTES:
        pos = _frame_ahead(buf, offsets)
    append = offsets.append
    while pos <= last:
        nxt = pos + head + buf[pos + at]
        if nxt > n:
            break
        append(pos)
        pos = nxt
    return offsets, pos


# Files of at least this many bytes are framed ahead with numpy (_frame_ahead) before the
# loop above finishes what is left: the loop alone costs about 0.2 us a record.
FAST_FRAME_BYTES = 1 << 18
_BLOCK = 1 << 18


def _frame_ahead(buf: Buffer, offsets: array[int]) -> int:
    """Frame as far as the record heads look like record heads, vectorised; returns where the
    loop of ``frame`` goes on (its result is the same: this only follows the links it would).

    Candidates are the offsets whose head has a known code, its copy equal and the reserved
    byte zero (each record of a valid file; seldom anything else). Each candidate links to the
    offset its size field gives when that is a candidate too; the records are the chain of links
    from the first record, found by pointer doubling (about log2(records) passes over the
    candidates). Where the chain leaves the candidates, the loop of ``frame`` goes on."""
    import numpy as np

    n, start = len(buf), T.HEADER_SIZE
    head, at = T.HEAD_SIZE, T.ARG_SIZE_OFFSET
    last = n - head
    a = np.frombuffer(buf, dtype=np.uint8)
    known, sized = _head_tables()
    f_code, f_copy, f_res = (T.RECORD_FIELDS[i] for i in (T.I_CODE, T.I_COPY, T.I_RES))
    parts = []
    for s in range(start, last + 1, _BLOCK):
        e = min(s + _BLOCK, last + 1)
        # each test in place, with no temporary (the candidates are ~1 ns a byte of a validation)
        if f_code.size == 1 and f_copy.size == 1:
            ok = np.empty(e - s, dtype=bool)
            code = a[s + f_code.offset:e + f_code.offset]
            np.equal(code, a[s + f_copy.offset:e + f_copy.offset], out=ok)
            if not known[0]:  # runs of zero bytes (zero floats) look like heads otherwise
                np.logical_and(ok, code.view(np.bool_), out=ok)  # the code is not 0 (bytes as bools: no cast)
        else:
            ok = np.ones(e - s, dtype=bool)
        if f_res.size == 1:
            np.greater(ok, a[s + f_res.offset:e + f_res.offset], out=ok)  # True (1) > the byte: it is 0
        found = np.flatnonzero(ok) + s
        if f_code.size == 1:  # a table look-up costs more than a comparison: on the few left only
            key = a[found + f_code.offset].astype(np.intp)  # (code, size) as one index: a 1-d take
            key <<= 8
            key += a[found + at]
            found = found[sized.reshape(-1).take(key)]
        parts.append(found)
    cand = np.concatenate(parts) if parts else np.zeros(0, dtype=np.int64)
    del parts
    m = cand.shape[0]
    if m == 0 or cand[0] != start:
        return start
    nxt = a[cand + at].astype(np.int64)  # (memory: a few vectors of the records, in place)
    nxt += cand
    nxt += head
    if np.array_equal(cand[1:], nxt[:-1]):  # each candidate is the last one's successor: all records
        return _chain_end(cand, nxt, None, n, offsets)
    succ = np.searchsorted(cand, nxt)
    linked = succ < m
    linked[linked] = cand[succ[linked]] == nxt[linked]
    jump = np.full(m + 1, m, dtype=np.int64)  # m: the sentinel, linked to itself
    jump[:m][linked] = succ[linked]
    del succ, linked
    reached = [np.zeros(1, dtype=np.int64)]  # the first 2**k records of the chain, as candidate indices
    have = reached[0]
    while True:
        more = jump[have]
        more = more[more != m]
        if more.size == 0:
            break
        reached.append(more)
        have = np.concatenate((have, more))
        jump = jump[jump]
    return _chain_end(cand, nxt, have, n, offsets)  # in file order: each pass appends what follows


@lru_cache(maxsize=1)
def _head_tables() -> tuple[Any, Any]:
    """The codes the spec knows, and the (code, argument size) pairs of some layout, as tables
    (made once: rebuilding them cost about 30 us a file)."""
    import numpy as np

    known = np.zeros(256, dtype=bool)
    sized = np.zeros((256, 256), dtype=bool)  # (code, argument size) of some layout
    for c in T.COMMANDS:
        if c.code < 256:
            known[c.code] = True
            for lay in c.layouts:
                sized[c.code, lay.size] = lay.size < 256
    return known, sized


def _chain_end(cand: Any, nxt: Any, chain: Any, n: int, offsets: array[int]) -> int:
    """Append the chain's offsets (candidate indices; None: every candidate), its last one only
    if that record fits; returns where the loop goes on."""
    last = len(cand) - 1 if chain is None else int(chain[-1])
    fits = int(nxt[last]) <= n  # the last record fits: the loop goes on after it
    pos = int(nxt[last]) if fits else int(cand[last])
    if chain is None:
        chain_offsets = cand if fits else cand[:-1]
    else:
        chain_offsets = cand[chain] if fits else cand[chain[:-1]]
    offsets.frombytes(memoryview(chain_offsets.astype("int64", copy=False)).cast("B"))
    return pos


def header_info(buf: Buffer) -> tuple[str | None, T.HeaderInfo]:
    vid = T.version_id(buf[T.VMAJOR.offset], buf[T.VMINOR.offset])
    return vid, T.HEADERS[T.VERSION_BY_ID[vid or T.FALLBACK_VERSION].header]


def decode_header(buf: Buffer) -> Any:
    _, info = header_info(buf)
    vals = convert_values(info.fields, info.struct.unpack_from(buf, 0))
    return info.cls(**{f.name: v for f, v in zip(info.fields, vals, strict=True)})


def decode(data: Buffer) -> Cbf:
    """Parse the structure, keeping every byte. Raises TruncatedError when framing breaks."""
    buf = bytes(data)
    n = len(buf)
    if n < T.HEADER_SIZE:
        raise TruncatedError(f"file is {n} bytes, the header needs {T.HEADER_SIZE}", offset=0,
                             kind="truncated_header")
    header = decode_header(buf)
    offsets, end = frame(buf)
    count = getattr(header, T.COUNT.name)
    trailing = b""
    if end < n:
        if len(offsets) < count:
            left = n - end
            part = "record head" if left < T.HEAD_SIZE else "arguments"
            raise TruncatedError(
                f"record {len(offsets)} is cut: {left} byte(s) left, its {part} need more "
                f"({len(offsets)} of {count} records complete)", offset=end, kind="truncated_record")
        trailing = buf[end:]
    return Cbf(header, RecordList(buf, offsets, end), trailing)


# -- checksums -----------------------------------------------------------------
def _width(tag: str) -> int:
    if tag == "args":
        return T.ARG_CHECKSUM.size
    return next(own[tag].size for own in T.LAYOUT_CHECKSUM_FIELDS.values() if tag in own)


def checksum(algorithm: str, parts: Iterable[Buffer], width: int) -> int:
    """The checksum of a spec algorithm (a key of checksums.algorithms) over parts."""
    return compute(T.CHECKSUMS["algorithms"][algorithm], parts, width)


def file_algorithm(profile: str) -> str:
    """The file checksum's algorithm under a profile (its file_algorithm, else the field's own)."""
    return str(T.PROFILES[profile].get("file_algorithm") or T.CHECKSUMS["fields"]["file"]["algorithm"])


def coverage_parts(coverage: str, buf: Buffer, offsets: Sequence[int], args: Buffer | None = None
                   ) -> Iterator[Buffer]:
    """The byte ranges a coverage feeds, in order, one at a time (never a list of a slice
    per record: memory stays bounded for a coverage over every record)."""
    mv = memoryview(buf)
    for seg in T.CHECKSUMS["coverages"][coverage]:
        region = seg["region"]
        if region == "file":
            yield mv[seg["start"]:]
        elif region == "header":
            yield mv[seg["start"]:seg["end"]]
        elif region == "args":
            yield args if args is not None else b""
        elif region == "records":
            yield from _records_region(buf, offsets, seg["exclude"])


def _records_region(buf: Buffer, offsets: Sequence[int], exclude: Sequence[str]) -> Iterator[Buffer]:
    """The records' bytes, less the head fields ``exclude`` names, in file order. Records that lie
    end to end (framing's always do) are one range of the file: its bytes less the excluded ones are
    picked by numpy in one pass (a copy of at most the records' bytes), not a slice a record."""
    if len(offsets) == 0:
        return
    import numpy as np

    mv = memoryview(buf)
    skip = sorted((T.RECORD_BY_ROLE_NAME[n].offset, T.RECORD_BY_ROLE_NAME[n].size) for n in exclude)
    hs, at = T.HEAD_SIZE, T.ARG_SIZE_OFFSET
    a = np.frombuffer(mv, dtype=np.uint8)
    off = np.asarray(offsets, dtype=np.int64)
    ends = off + hs + a[off + at]
    if np.array_equal(off[1:], ends[:-1]):
        lo, hi = int(off[0]), int(ends[-1])
        if not skip:
            yield mv[lo:hi]
            return
        keep = np.ones(hi - lo, dtype=bool)
        for s_off, s_size in skip:
            for k in range(s_size):
                keep[off - (lo - s_off - k)] = False
        yield memoryview(a[lo:hi][keep])
        return
    for o, end in zip(off.tolist(), ends.tolist(), strict=True):  # records apart (never from framing)
        cur = o
        for s_off, s_size in skip:
            yield mv[cur:o + s_off]
            cur = o + s_off + s_size
        yield mv[cur:end]


def field_checksum(tag: str, buf: Buffer, offsets: Sequence[int], coverage: str | None = None,
                   args: Buffer | None = None, algorithm: str | None = None) -> int:
    spec = T.CHECKSUMS["fields"][tag]
    return checksum(algorithm or spec["algorithm"], coverage_parts(coverage or spec["coverage"], buf, offsets, args),
                    _width(tag))


def arg_checksum(raw: Buffer) -> int:
    return field_checksum("args", b"", (), args=raw)


def record_checksum(ck: T.ArgChecksumInfo, rec: Buffer) -> int:
    """A checksum field among the arguments (issue 25, point 1) over the record ``rec`` (its head,
    then its arguments): the record's byte ranges its named fields resolve to, in order."""
    mv = memoryview(rec)
    return checksum(ck.algorithm, (mv[a:b] for a, b in ck.ranges), ck.arg.size)


def fill_arg_checksums(lay: T.LayoutInfo, head: bytes, raw: Buffer) -> bytes:
    """The arguments with the layout's checksum fields filled, in the spec's fill order (the head's
    argument checksum, which covers them, is computed after)."""
    rec = bytearray(head) + bytes(raw)
    for ck in lay.checksums:
        struct.pack_into(T.BO + ck.arg.fmt, rec, T.HEAD_SIZE + ck.arg.offset, record_checksum(ck, rec))
    return bytes(rec[T.HEAD_SIZE:])


# -- encode --------------------------------------------------------------------
def _refuse_unwritable(model: Cbf, vid: str | None) -> None:
    """What pack_file refuses to write unless it keeps stored values: a version it does not write,
    more records than the count holds, trailing bytes."""
    if vid is None or not T.VERSION_BY_ID[vid].writable:
        writable = ", ".join(v.id for v in T.VERSIONS if v.writable)
        major, minor = model.version
        raise EncodeError(f"header: version {major}.{minor} is not writable (writable: {writable})")
    if len(model.records) > T.LIMITS["max_commands"]:
        raise EncodeError(f"{len(model.records)} commands, at most {T.LIMITS['max_commands']} fit the count")
    if model.trailing:
        raise EncodeError("trailing bytes can only be written with keep_stored")


def _written_args(code: int, raw: bytes, i: int, vid: str | None, profile: str, at: int) -> bytes:
    """Record i's argument bytes as written (its profile's layout), refused when its command is unknown
    or not in the version, no layout has its size, or a string is not one the format carries (at: the
    arguments' offset in the file)."""
    cmd = T.BY_CODE.get(code)
    if cmd is None:
        raise EncodeError(f"record {i}: unknown command code 0x{code:02X}")
    if not T.available(cmd, vid):
        raise EncodeError(f"record {i}: {cmd.name} is not available in version {vid}")
    lay = cmd.layout_for_size(vid or "", len(raw))
    if lay is None:
        raise EncodeError(f"record {i}: {cmd.name} has no layout of {len(raw)} bytes in version {vid}")
    check_strings(lay.args, bytes(raw), at, f"record {i}: {cmd.name}")
    return _profile_layout(cmd, vid or "", profile, raw, i)


def pack_file(model: Cbf, *, keep_stored: bool = False, profile: str = "default") -> bytes:
    """The bytes of a Cbf, NOT validated: ``cbf.encode`` (writer.py) is the writer, which
    refuses a result that does not validate. By default fills sequence numbers, code copies,
    the count, the magic numbers and every checksum. ``keep_stored=True`` writes every stored
    value as given, so a faulty file is reproduced byte for byte."""
    if profile not in T.PROFILES:
        raise EncodeError(f"unknown profile {profile!r}")
    major, minor = model.version
    vid = T.version_id(major, minor)
    info = T.HEADERS[T.VERSION_BY_ID[vid or T.FALLBACK_VERSION].header]
    if not isinstance(model.header, info.cls):
        raise EncodeError(f"header: version {major}.{minor} needs layout {info.id}, got {type(model.header).__name__}")
    records = model.records
    if not keep_stored:
        _refuse_unwritable(model, vid)
    out = bytearray(pack_fields(info.fields, info.struct, model.header, "header"))
    if not keep_stored:
        check_strings(info.fields, bytes(out), 0, "header")
    offsets: list[int] = []
    if not keep_stored and isinstance(records, PackedRecords):  # CUT text's records: a layout at a time
        from .packing import pack_records

        packed = pack_records(records, vid or "", profile, bytes(out))
        if packed is not None:
            out, offsets = packed[0], packed[1].tolist()
            records = ()  # written: the loop has nothing left to do
    pack_head = T.HEAD_STRUCT.pack
    head_vals: list[Any] = [0] * len(T.RECORD_FIELDS)
    for i, r in enumerate(records):
        raw = r.raw_args
        if len(raw) > T.LIMITS["max_arg_size"]:
            raise EncodeError(f"record {i}: {len(raw)} argument bytes, at most {T.LIMITS['max_arg_size']}")
        if keep_stored:
            seq, copy, chk = r.sequence, r.code if r.code_copy is None else r.code_copy, r.arg_checksum
            if chk is None:
                chk = arg_checksum(raw)
        else:
            seq, copy = i & T.SEQ_MASK, r.code  # the checksum of what is written, below
            raw = _written_args(r.code, raw, i, vid, profile, len(out) + T.HEAD_SIZE)
            chk = 0
        head_vals[T.I_SEQ], head_vals[T.I_CODE], head_vals[T.I_COPY] = seq, r.code, copy
        head_vals[T.I_SIZE], head_vals[T.I_RES], head_vals[T.I_CHK] = len(raw), r.reserved, chk
        if not keep_stored:
            written = T.BY_CODE[r.code].layout_for_size(vid or "", len(raw))
            if written is not None and written.checksums:
                try:
                    raw = fill_arg_checksums(written, pack_head(*head_vals), raw)
                except struct.error as exc:
                    raise EncodeError(f"record {i}: head field out of range ({exc})") from None
            head_vals[T.I_CHK] = arg_checksum(raw)
        try:
            offsets.append(len(out))
            out += pack_head(*head_vals)
        except struct.error as exc:
            raise EncodeError(f"record {i}: head field out of range ({exc})") from None
        out += raw
    out += model.trailing
    if not keep_stored:
        fill_header(out, offsets, len(model.records), profile)
    return bytes(out)


def _profile_layout(cmd: T.CommandInfo, version: str, profile: str, raw: bytes, i: int) -> bytes:
    """The arguments as the profile's writers write them. A command with a layout of its own
    under ``profile`` (implib's 16-byte VERSION, N8) is written in that layout: the arguments of
    a longer layout that starts with the same fields are cut to it when the fields cut off are
    reserved and zero, and refused otherwise (the profile's reader could not read them)."""
    own = [lay for lay in cmd.layouts_for(version) if profile in lay.profiles]
    have = cmd.layout_for_size(version, len(raw))
    if not own or have is None or have in own:
        return raw
    lay = own[0]
    cut = raw[lay.size:]
    same = (len(lay.args) <= len(have.args) and lay.size <= have.size
            and all(a == b for a, b in zip(lay.args, have.args, strict=False)))
    if same and all(f.reserved for f in have.args[len(lay.args):]) and not any(cut):
        return raw[:lay.size]
    why = "its bytes past them are not zero" if same else "they do not start this layout"
    raise EncodeError(f"record {i}: {cmd.name} of {len(raw)} bytes: the {profile} profile writes its "
                      f"{lay.size}-byte layout, and {why}; {profile}'s reader cannot read it")


def _put(out: bytearray, f: T.FieldInfo, value: int) -> None:
    struct.pack_into(T.BO + f.fmt, out, f.offset, value)


def fill_header(out: bytearray, offsets: list[int], count: int, profile: str) -> None:
    _put(out, T.START, T.START.magic or 0)
    _put(out, T.END, T.END.magic or 0)
    _put(out, T.COUNT, count)
    own = T.LAYOUT_CHECKSUM_FIELDS[header_info(out)[1].id]  # the checksum fields of this version's header
    for tag in T.CHECKSUMS["fill_order"]:
        if tag not in own:
            continue  # the arguments' are written with each record; another version's are not here
        cov = T.PROFILES[profile]["file_coverages"][0] if tag == "file" else None
        alg = file_algorithm(profile) if tag == "file" else None
        _put(out, own[tag], field_checksum(tag, out, offsets, cov, algorithm=alg))
