"""How the Python binding's work grows with the number of records (issue 32): the structural measure
that a loaded machine cannot fool, used by tests/test_engine_scaling.py on the spec and on every
revision fixture.

For each version of the spec, one block of records holds every record layout the version has (each
command's layouts, a repeated group's one per n), with plain values read from the model (vectors
(0, ..., 0, 1), scalars 1, strings "B"; curves by their motion role so that every motion starts where
the last one ended), inside a start and an end shape when the spec has shapes. A file of ``n`` blocks
and one of ``8 n`` blocks, sealed under each profile (testing.seal: every derived value filled), are
decoded, validated and encoded with the interpreter's profiler hook counting calls:

- ``py``: Python-level function calls ('call' events: a function, a lambda, a generator resumed);
- ``c``: calls of built-in functions and methods ('c_call' events: a numpy function, list.append).

A vectorised engine makes the same calls at n and 8 n blocks: numpy does the per-record work. Each
finding costs a few calls when it is read (its message is made then), so the validate counts are
compared with the findings they gave. Nothing here names a command, a size or a version: everything
comes from ``cbf.tables`` of the binding on the path, so the probe runs on any revision's binding.

    python tests/engine_probe.py [BLOCKS]      prints the counts as JSON (a revision's binding on PYTHONPATH)
"""

from __future__ import annotations

import gc
import json
import sys
from collections.abc import Callable
from typing import Any

import cbf
from cbf import tables as T
from cbf.model import Cbf, Record, new_header
from cbf.testing import seal

SCALE = 8  # the larger file has this many times the blocks of the smaller


def _floats(count: int) -> list[float]:
    """A float argument's plain value: (0, 0, 1) per point of a vector of points, else (0, ..., 1)."""
    if count % 3 == 0:
        return [0.0, 0.0, 1.0] * (count // 3)
    return [0.0] * (count - 1) + [1.0]


def _values(cmd: T.CommandInfo, lay: T.LayoutInfo) -> dict[str, list[Any]]:
    out: dict[str, list[Any]] = {}
    for f in lay.args:
        if f.kind == "float":
            out[f.name] = _floats(f.count)
        elif f.kind == "string":
            out[f.name] = [b"B"]
        elif f.code is None:  # raw bytes
            out[f.name] = [bytes(f.size)]
        else:
            out[f.name] = [1] * f.count
    motion = cmd.motion or {}
    if motion.get("kind") in ("circle", "helix"):  # a full turn about (1, 0, 1) from (0, 0, 1), length 0
        counts = {f.name: f.count for f in lay.args}
        out[motion["center"]] = [1.0] + _floats(counts[motion["center"]])[1:]
        out[motion["degrees"]] = [360.0]
        if "normal" in motion:
            out[motion["normal"]] = _floats(counts[motion["normal"]])
        if "length" in motion:
            out[motion["length"]] = [0.0]
    return out


def _record(cmd: T.CommandInfo, lay: T.LayoutInfo, values: dict[str, list[Any]]) -> Record:
    flat = [v for f in lay.args for v in values[f.name]]
    return Record(code=cmd.code, raw_args=lay.struct.pack(*flat))


def block(version: str, profile: str) -> list[Record]:
    """Every record layout of ``version`` that ``profile`` accepts, once (shapes: one pair a start
    layout, cycling the ends)."""
    plain: list[Record] = []
    starts: list[tuple[T.CommandInfo, T.LayoutInfo]] = []
    ends: list[tuple[T.CommandInfo, T.LayoutInfo]] = []
    for cmd in T.COMMANDS:
        for lay in cmd.layouts_for(version):
            if not lay.accepted_under(profile):
                continue
            if cmd.shape is None:
                plain.append(_record(cmd, lay, _values(cmd, lay)))
            else:
                (starts if cmd.shape["kind"] == "start" else ends).append((cmd, lay))
    if not starts or not ends:
        return plain + [_record(c, lay, _values(c, lay)) for c, lay in starts + ends]
    moves = sum(1 for r in plain if T.BY_CODE[r.code].motion)
    out: list[Record] = []
    for k in range(max(len(starts), len(ends))):
        pair = []
        for cmd, lay in (starts[k % len(starts)], ends[k % len(ends)]):
            values = _values(cmd, lay)
            shape = cmd.shape or {}
            values[shape["count"]] = [moves]
            pair.append(_record(cmd, lay, values))
        out += [pair[0], *plain, pair[1]]
    return out


def _version_text(v: T.VersionInfo) -> str:
    return f"{v.major}.{v.minor or 0}"


def layouts_in_blocks() -> set[tuple[str, int]]:
    """(version, id of the layout) of every layout some profile's block holds."""
    return {(v.id, id(lay)) for v in T.VERSIONS for p in T.PROFILES for cmd in T.COMMANDS
            for lay in cmd.layouts_for(v.id) if lay.accepted_under(p)}


def _header(v: T.VersionInfo) -> Any:
    """A header of version v whose implant descriptor holds a word (else a finding in every file)."""
    f = T.HEADERS[v.header].by_role("implant_descriptor")
    return new_header(_version_text(v), **({f.name: "PROBE"} if f is not None else {}))


def files(blocks: int) -> dict[str, tuple[bytes, bytes, int]]:
    """(version/profile) -> (the file of ``blocks`` blocks, of SCALE x ``blocks``, records a block)."""
    out: dict[str, tuple[bytes, bytes, int]] = {}
    for v in T.VERSIONS:
        header = _header(v)
        for profile in T.PROFILES:
            one = block(v.id, profile)
            if not one:
                continue
            n = max(1, min(blocks, T.LIMITS["max_commands"] // (SCALE * len(one))))
            small = seal(Cbf(header, tuple(one * n)), profile)
            large = seal(Cbf(header, tuple(one * (SCALE * n))), profile)
            out[f"{v.id}/{profile}"] = (small, large, len(one) * n)
    return out


Counts = dict[str, int]


def count(fn: Callable[[], Any]) -> tuple[Counts, Any]:
    """The calls ``fn()`` makes, by kind, and its result."""
    seen = {"call": 0, "c_call": 0}

    def hook(frame: Any, event: str, arg: Any) -> None:
        if event in seen:
            seen[event] += 1

    # The collector's finalizers (a generator closed, a weakref callback) of garbage left by earlier
    # code would be counted at random points: collected before, and off while counting. probe() froze
    # what was alive before it, so this collection walks only what the probe made since.
    gc.collect()
    gc.disable()
    sys.setprofile(hook)
    try:
        got = fn()
    finally:
        sys.setprofile(None)
        gc.enable()
    return {"py": seen["call"], "c": seen["c_call"]}, got


def measure(data: bytes, profile: str) -> dict[str, Any]:
    """The calls of decode, validate (of bytes, and of the decoded model) and encode of one file."""
    model = cbf.decode(data)
    for _ in range(2):  # caches filled (tables per version and profile, plans per layout)
        cbf.validate(data, profile=profile)
        cbf.encode(model, keep_stored=True)
    dec, _ = count(lambda: cbf.decode(data))
    val, found = count(lambda: cbf.validate(data, profile=profile))
    again = cbf.decode(data)
    val_model, _ = count(lambda: cbf.validate(again, profile=profile))
    enc, _ = count(lambda: cbf.encode(model, keep_stored=True))
    got = {"records": len(model.records), "findings": len(found), "decode": dec, "validate": val,
           "validate_model": val_model, "encode_stored": enc}
    vid = T.version_id(*model.version)
    if vid is not None and T.VERSION_BY_ID[vid].writable:  # the writer: fills every derived value, validates
        try:
            cbf.encode(model, profile=profile)
            got["encode"], _ = count(lambda: cbf.encode(model, profile=profile))
        except cbf.EncodeError as exc:
            got["encode_refused"] = str(exc)
    return got


def probe(blocks: int = 2) -> dict[str, Any]:
    """For each version and profile: the measures of the small and the large file."""
    out: dict[str, Any] = {}
    # count() collects before each count. In a pytest worker that ran other test files first, the heap
    # holds millions of objects, and a full collection walked them all: 16 files' 5 counts each took
    # 48 s there against 1 s in a fresh process. What lives now is frozen (gc.freeze: left out of every
    # collection) and is no garbage to collect (collected first), so each count's collection walks
    # only what the probe made since, as in a fresh process.
    gc.collect()
    gc.freeze()
    try:
        for key, (small, large, _) in files(blocks).items():
            profile = key.split("/", 1)[1]
            out[key] = {"small": measure(small, profile), "large": measure(large, profile)}
    finally:
        gc.unfreeze()
    return out


if __name__ == "__main__":
    print(json.dumps(probe(int(sys.argv[1]) if len(sys.argv) > 1 else 2), indent=1, sort_keys=True))
