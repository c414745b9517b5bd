"""Mutations of a cutfile's bytes. Pure functions; every random choice comes
from a seeded ``random.Random``, so a run is reproducible from its seed.

Record boundaries come from the header size, the record head size and the
position of the argument-size byte, read from spec/cbf.yaml as data (the
campaign imports no binding).
"""

from __future__ import annotations

import random
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from pathlib import Path

import yaml

# libyaml's parser (PyYAML's C binding) when present: the same values, about ten times faster.
_YAML_LOADER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)

REPO = Path(__file__).resolve().parents[2]


@dataclass(frozen=True)
class Framing:
    """What the mutations need to know of the format, read from the spec: where
    records start and end, and where headers keep their command count."""

    header_size: int
    head_size: int
    arg_size_offset: int
    count_fields: tuple[tuple[int, int], ...]  # (offset, size) in each header layout

    @classmethod
    def from_spec(cls, spec: Path = REPO / "spec" / "cbf.yaml") -> Framing:
        doc = yaml.load(spec.read_text(encoding="utf-8"), Loader=_YAML_LOADER)
        types = doc["types"]
        rec = doc["record"]
        arg = next(f for f in rec["fields"] if f.get("role") == "arg_size")
        sizes = {int(h["size"]) for h in doc["headers"].values()}
        if len(sizes) != 1:
            raise ValueError("spec: header layouts of different sizes")
        counts = sorted({(int(f["offset"]), int(types[f["type"]]["size"]))
                         for h in doc["headers"].values() for f in h["fields"] if f.get("role") == "command_count"})
        return cls(sizes.pop(), int(rec["head_size"]), int(arg["offset"]), tuple(counts))

    def records(self, data: bytes) -> list[tuple[int, int]]:
        """(start, end) of each complete record, framed as the spec's D1 says."""
        out = []
        pos = self.header_size
        while len(data) - pos >= self.head_size:
            end = pos + self.head_size + data[pos + self.arg_size_offset]
            if end > len(data):
                break
            out.append((pos, end))
            pos = end
        return out


@dataclass(frozen=True)
class Mutant:
    """A mutated file: the class of mutation, where, and the bytes."""

    cls: str
    offset: int
    detail: str
    data: bytes


def bit_flips(data: bytes, offsets: Iterable[int] | None = None) -> Iterator[Mutant]:
    for i in range(len(data)) if offsets is None else offsets:
        for bit in range(8):
            b = bytearray(data)
            b[i] ^= 1 << bit
            yield Mutant("bit_flip", i, f"bit {bit}", bytes(b))


def byte_sets(data: bytes, offsets: Iterable[int] | None = None) -> Iterator[Mutant]:
    """Each byte set to 0x00 and to 0xFF; a byte that already has the value is skipped (no change)."""
    for i in range(len(data)) if offsets is None else offsets:
        for value, cls in ((0x00, "byte_00"), (0xFF, "byte_ff")):
            if data[i] != value:
                b = bytearray(data)
                b[i] = value
                yield Mutant(cls, i, f"0x{data[i]:02x} -> 0x{value:02x}", bytes(b))


def truncations(data: bytes, offsets: Iterable[int] | None = None) -> Iterator[Mutant]:
    for n in range(len(data)) if offsets is None else offsets:
        yield Mutant("truncation", n, f"{n} of {len(data)} bytes", data[:n])


def sample_offsets(data: bytes, framing: Framing, rng: random.Random, count: int) -> list[int]:
    """For a file too big to mutate at every offset: the header, the first and last
    records whole, and ``count`` offsets drawn at random (seeded), in order."""
    recs = framing.records(data)
    keep = set(range(min(len(data), framing.header_size)))
    for start, end in recs[:2] + recs[-2:]:
        keep.update(range(start, end))
    keep.update(rng.sample(range(len(data)), min(count, len(data))))
    return sorted(keep)


def transpositions(data: bytes) -> Iterator[Mutant]:
    """Adjacent bytes swapped, where they differ."""
    for i in range(len(data) - 1):
        if data[i] != data[i + 1]:
            b = bytearray(data)
            b[i], b[i + 1] = b[i + 1], b[i]
            yield Mutant("transposition", i, f"bytes {i} and {i + 1}", bytes(b))


def record_swaps(data: bytes, framing: Framing) -> Iterator[Mutant]:
    """Every pair of records with different bytes, swapped whole (sequence numbers travel with them)."""
    recs = framing.records(data)
    for x in range(len(recs)):
        for y in range(x + 1, len(recs)):
            (a0, a1), (b0, b1) = recs[x], recs[y]
            if data[a0:a1] == data[b0:b1]:
                continue
            swapped = data[:a0] + data[b0:b1] + data[a1:b0] + data[a0:a1] + data[b1:]
            yield Mutant("record_swap", a0, f"records {x} and {y}", swapped)


def compensating_pairs(data: bytes, rng: random.Random, count: int) -> Iterator[Mutant]:
    """One byte +1 and another -1 (a sum over both is unchanged), at random places."""
    up = [i for i, v in enumerate(data) if v < 0xFF]
    down = [i for i, v in enumerate(data) if v > 0x00]
    for _ in range(count):
        i, j = rng.choice(up), rng.choice(down)
        if i == j:
            continue
        b = bytearray(data)
        b[i] += 1
        b[j] -= 1
        yield Mutant("compensating_pair", i, f"+1 at {i}, -1 at {j}", bytes(b))


def random_mutant(data: bytes, rng: random.Random, framing: Framing, others: list[bytes]) -> Mutant:
    """One mutation of a kind drawn at random, for differential testing."""
    kind = rng.choice(("flip", "set", "truncate", "swap", "splice", "count", "multi", "insert"))
    b = bytearray(data)
    n = len(b)
    if kind == "flip" and n:
        i = rng.randrange(n)
        b[i] ^= 1 << rng.randrange(8)
        return Mutant("flip", i, "", bytes(b))
    if kind == "set" and n:
        i = rng.randrange(n)
        b[i] = rng.choice((0x00, 0xFF, 0x7F, 0x80, rng.randrange(256)))
        return Mutant("set", i, "", bytes(b))
    if kind == "truncate" and n:
        i = rng.randrange(n)
        return Mutant("truncate", i, "", bytes(b[:i]))
    if kind == "swap":
        swaps = list(record_swaps(data, framing))
        if swaps:
            return rng.choice(swaps)
    if kind == "splice" and others:
        other = rng.choice(others)
        i, j = rng.randrange(n + 1), rng.randrange(len(other) + 1)
        return Mutant("splice", i, "", bytes(b[:i]) + other[j:])
    if kind == "count" and n >= framing.header_size and framing.count_fields:
        at, size = rng.choice(framing.count_fields)
        b[at:at + size] = bytes(rng.randrange(256) for _ in range(size))
        return Mutant("count", at, "", bytes(b))
    if kind == "insert":
        i = rng.randrange(n + 1)
        return Mutant("insert", i, "", bytes(b[:i]) + bytes(rng.randrange(256) for _ in range(rng.randrange(1, 30)))
                      + bytes(b[i:]))
    for _ in range(rng.randrange(2, 6)):  # multi: several random byte changes
        if n:
            b[rng.randrange(n)] = rng.randrange(256)
    return Mutant("multi", 0, "", bytes(b))
