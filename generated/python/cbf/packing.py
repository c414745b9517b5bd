"""encode's records, written a layout at a time from the columns of PackedRecords.

``cut.from_cut`` gives its records as columns (model.PackedRecords). For those, encode
writes every record head and argument with numpy instead of one record at a time: the
same bytes as its loop, which still runs whenever anything needs a record's own attention
(a code without a layout in the version, a string with a byte N4 refuses, a layout the
profile rewrites, a value too wide for its head field): the loop then raises or rewrites
as it always has. The argument checksums are computed here by the spec's algorithm.
"""

from __future__ import annotations

from typing import Any

from . import tables as T
from .checksums import compute
from .model import PackedRecords

# A writer's strings: printable ASCII and the padding (N4), as codec._check_strings takes them.
_STRING_OK = bytes(range(0x20, 0x7F)) + T.PAD


def _arg_checksums(np: Any, records: PackedRecords, bounds: Any, u8: Any) -> Any:
    spec = T.CHECKSUMS["fields"]["args"]
    kind = T.CHECKSUMS["algorithms"][spec["algorithm"]]
    segments = T.CHECKSUMS["coverages"][spec["coverage"]]
    mask = (1 << (8 * T.ARG_CHECKSUM.size)) - 1
    if kind == "sum" and [s["region"] for s in segments] == ["args"]:
        total = np.zeros(len(u8) + 1, dtype=np.uint64)
        np.cumsum(u8, dtype=np.uint64, out=total[1:])
        return (total[bounds[1:]] - total[bounds[:-1]]) & np.uint64(mask)
    if [s["region"] for s in segments] != ["args"]:
        return None
    args = records.args
    return np.array([compute(kind, (args[a:b],), T.ARG_CHECKSUM.size) for a, b in
                     zip(bounds[:-1].tolist(), bounds[1:].tolist(), strict=True)], dtype=np.uint64)


def pack_records(records: PackedRecords, version: str, profile: str, header: bytes) -> tuple[bytearray, Any] | None:
    """The header followed by every record (sequence numbers, code copies and argument
    checksums filled, as encode fills them), and the records' offsets; None when encode's own
    loop must write them."""
    import numpy as np

    n = len(records)
    codes = np.asarray(records.codes, dtype=np.int64)
    bounds = np.asarray(records.bounds, dtype=np.int64)
    sizes = bounds[1:] - bounds[:-1]
    u8 = np.frombuffer(records.args, dtype=np.uint8)
    if n == 0 or int(sizes.max()) > T.LIMITS["max_arg_size"]:
        return None
    key = codes * 65536 + sizes
    for k in np.unique(key).tolist():
        cmd = T.BY_CODE.get(k >> 16)
        if cmd is None or not T.available(cmd, version):
            return None
        lay = cmd.layout_for_size(version, k & 0xFFFF)
        if lay is None:
            return None
        own = [x for x in cmd.layouts_for(version) if profile in x.profiles]
        if (own and lay not in own) or lay.checksums:  # a checksum among the arguments: encode's loop fills it
            return None
        strings = [f for f in lay.args if f.kind == "string"]
        if strings:
            rows = np.flatnonzero(key == k)
            ok = np.zeros(256, dtype=bool)
            ok[list(_STRING_OK)] = True
            for f in strings:
                if not ok[u8[bounds[rows][:, None] + (f.offset + np.arange(f.size))]].all():
                    return None
    chk = _arg_checksums(np, records, bounds, u8)
    if chk is None:
        return None
    values = {"sequence": np.arange(n, dtype=np.uint64) & np.uint64(T.SEQ_MASK), "code": codes.astype(np.uint64),
              "code_copy": codes.astype(np.uint64), "arg_size": sizes.astype(np.uint64),
              "reserved": np.asarray(records.reserved, dtype=np.uint64), T.ARG_CHECKSUM.role or "": chk}
    hs = T.HEAD_SIZE
    offsets = T.HEADER_SIZE + np.arange(n, dtype=np.int64) * hs + bounds[:-1]
    out = np.zeros(T.HEADER_SIZE + n * hs + len(u8), dtype=np.uint8)
    out[:T.HEADER_SIZE] = np.frombuffer(header, dtype=np.uint8)
    for f in T.RECORD_FIELDS:
        v = values.get(f.role or "", np.zeros(n, dtype=np.uint64))  # encode's loop writes 0 for any other
        if f.kind != "uint" or int(v.max(initial=0)) >= 1 << (8 * f.size):
            return None
        b = v.astype(f"{T.BO}u{f.size}").view(np.uint8).reshape(n, f.size)
        out[offsets[:, None] + (f.offset + np.arange(f.size))] = b
    out[np.arange(len(u8), dtype=np.int64) + np.repeat(offsets + hs - bounds[:-1], sizes)] = u8
    return bytearray(out.tobytes()), offsets
