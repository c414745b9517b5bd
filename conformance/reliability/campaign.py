"""The reliability campaign: corruption detection, blind spots, differential testing.

Every binding is driven through its conformance testee (PROTOCOL.md), the
same programs `make conformance` checks, so what is measured is the real
binding. Requests are pipelined: a batch of mutated files is written to a
scratch folder, all requests are sent, then all answers are read.
"""

from __future__ import annotations

import base64
import random
import shutil
import subprocess
import sys
import tempfile
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

from conformance.runner.compare import f32_bits, first_difference, is_nan_bits
from conformance.runner.run import ROOT, load_bindings
from conformance.runner.testee import Binding, Testee, TesteeError

from .mutate import (
    Framing,
    Mutant,
    bit_flips,
    byte_sets,
    compensating_pairs,
    random_mutant,
    record_swaps,
    sample_offsets,
    transpositions,
    truncations,
)

# libyaml's parser (PyYAML's C binding) when present: the same values, about ten times faster.
_YAML_LOADER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)

REPO = ROOT.parent
GOLDEN = ROOT / "golden"
BATCH = 400

# Check kinds that the .ksy states as Kaitai `valid:` rules (or that Kaitai's
# `repeat: eos` turns into a parse error): where the reference reports one of
# these, a Kaitai parser rejects the file instead of decoding it. The same
# reasons head conformance/failures/kaitai-*.txt.
KAITAI_REJECTS = ("magic", "code_copy", "arg_size", "availability", "trailing")


class Pool:
    """A started testee that answers a batch of requests at a time."""

    def __init__(self, binding: Binding) -> None:
        self.binding = binding
        self.testee = Testee(binding, timeout=120, expand=lambda s: s.format(repo=REPO, python=sys.executable))
        self.testee.start()

    def many(self, requests: list[dict[str, Any]]) -> list[dict[str, Any]]:
        try:
            return self.testee.many(requests)
        except TesteeError as exc:  # said with the binding's name: the campaign stops on one line, no traceback
            said = str(exc) if str(exc).startswith(f"{self.binding.name}: ") else f"{self.binding.name}: {exc}"
            raise TesteeError(f"{said} (its stderr is above)") from None

    def close(self) -> None:
        self.testee.stop()


@dataclass
class Scratch:
    """A folder for the mutated files of one batch (tmpfs when there is one)."""

    root: Path = field(default_factory=lambda: Path(tempfile.mkdtemp(
        prefix="cbf-rel-", dir="/dev/shm" if Path("/dev/shm").is_dir() else None)))

    def write(self, items: list[bytes]) -> list[str]:
        paths = []
        for i, data in enumerate(items):
            p = self.root / f"{i}.cbf"
            p.write_bytes(data)
            paths.append(str(p))
        return paths

    def remove(self) -> None:
        shutil.rmtree(self.root, ignore_errors=True)


def batched(items: Iterable[Mutant], n: int = BATCH) -> Iterator[list[Mutant]]:
    batch: list[Mutant] = []
    for m in items:
        batch.append(m)
        if len(batch) == n:
            yield batch
            batch = []
    if batch:
        yield batch


def has_error(answer: dict[str, Any]) -> bool:
    """A validate answer that rejects the file: an error finding, or a refusal."""
    if not answer.get("ok"):
        return True
    return any(f.get("severity") == "error" for f in answer.get("findings", []))


def validating(pool: Pool, sample: Path) -> bool:
    return "skipped" not in pool.many([{"op": "validate", "file": str(sample), "profile": "default"}])[0]


# -- valid bases -------------------------------------------------------------------
@dataclass(frozen=True)
class Base:
    name: str
    data: bytes
    profile: str


def valid_bases(max_size: int | None = None, distinct: bool = False) -> list[Base]:
    """The golden files that validate with no error, each under the first profile its expectation accepts;
    ``distinct``: the first of the files with the same bytes and profile only (their mutants are the same)."""
    out: list[Base] = []
    for exp in sorted(GOLDEN.glob("*.expect.yaml")):
        name = exp.name[: -len(".expect.yaml")]
        doc = yaml.load(exp.read_text(encoding="utf-8"), Loader=_YAML_LOADER)
        dec = doc.get("decode")
        if (isinstance(dec, dict) and "error" in dec) or doc.get("part_number") or doc.get("cutters"):
            continue
        data = (GOLDEN / f"{name}.cbf").read_bytes()
        if max_size is not None and len(data) > max_size:
            continue
        for profile, findings in (doc.get("validate") or {}).items():
            if not any(f[1] == "error" for f in (findings or [])):
                if not (distinct and any(b.data == data and b.profile == profile for b in out)):
                    out.append(Base(name, data, profile))
                break
    return out


# -- 1. corruption detection -----------------------------------------------------------
CORRUPTIONS: tuple[tuple[str, Callable[[bytes, Iterable[int] | None], Iterator[Mutant]]], ...] = (
    ("bit_flip", bit_flips), ("byte_set", byte_sets), ("truncation", truncations))
# Files above this size are mutated at a seeded sample of offsets (with the
# header and the first and last two records whole), not at every offset.
SAMPLE_ABOVE = 65536
SAMPLE_COUNT = 256


def sampled(bases: list[Base], framing: Framing, seed: int) -> dict[str, list[int]]:
    rng = random.Random(seed)
    return {b.name: sample_offsets(b.data, framing, rng, SAMPLE_COUNT) for b in bases if len(b.data) > SAMPLE_ABOVE}


def detection(pool: Pool, bases: list[Base], scratch: Scratch, samples: dict[str, list[int]],
              share: float = 1.0, seed: int = 0) -> dict[str, Any]:
    """Every corruption of every base, each answered by the binding; ``share`` < 1 keeps that
    share of the mutants, drawn with a seeded generator (the same ones every run)."""
    result: dict[str, Any] = {}
    rng = random.Random(seed)
    for cls, gen in CORRUPTIONS:
        row = result.setdefault(cls, {"trials": 0, "detected": 0, "misses": []})
        for base in bases:
            mutants = gen(base.data, samples.get(base.name))
            if share < 1.0:
                mutants = (m for m in mutants if rng.random() < share)
            for batch in batched(mutants):
                paths = scratch.write([m.data for m in batch])
                answers = pool.many([{"op": "validate", "file": p, "profile": base.profile} for p in paths])
                for m, a in zip(batch, answers, strict=True):
                    row["trials"] += 1
                    if has_error(a):
                        row["detected"] += 1
                    else:
                        row["misses"].append({"file": base.name, "offset": m.offset, "detail": f"{m.cls} {m.detail}"})
    return result


# -- 2. blind spots -------------------------------------------------------------------------
def blind_spots(pool: Pool, bases: list[Base], profile: str, scratch: Scratch, framing: Framing,
                pairs: int, seed: int, share: float = 1.0) -> dict[str, Any]:
    """Each blind-spot class over every base; ``share`` < 1 keeps that share of the mutants, drawn
    with a seeded generator of its own (the same ones every run)."""
    rng = random.Random(seed)
    keep = random.Random(seed + 1)
    gens: tuple[tuple[str, Callable[[bytes], Iterable[Mutant]]], ...] = (
        ("transposition", transpositions),
        ("record_swap", lambda d: record_swaps(d, framing)),
        ("compensating_pair", lambda d: compensating_pairs(d, rng, pairs)))
    result: dict[str, Any] = {}
    for cls, gen in gens:
        row = result.setdefault(cls, {"trials": 0, "detected": 0})
        for base in bases:
            mutants = gen(base.data)
            if share < 1.0:
                mutants = (m for m in mutants if keep.random() < share)
            for batch in batched(mutants):
                paths = scratch.write([m.data for m in batch])
                answers = pool.many([{"op": "validate", "file": p, "profile": profile} for p in paths])
                row["trials"] += len(batch)
                row["detected"] += sum(has_error(a) for a in answers)
    return result


def profile_bases(pool: Pool, bases: list[Base], profile: str, scratch: Scratch) -> list[Base]:
    """The bases that validate with no error under this profile."""
    paths = scratch.write([b.data for b in bases])
    answers = pool.many([{"op": "validate", "file": p, "profile": profile} for p in paths])
    return [Base(b.name, b.data, profile) for b, a in zip(bases, answers, strict=True) if not has_error(a)]


def crc_variant(work: Path, algorithm: str = "crc32") -> Binding:
    """The Python codec generated from a copy of the spec whose file checksum uses another algorithm."""
    spec = yaml.load((REPO / "spec" / "cbf.yaml").read_text(encoding="utf-8"), Loader=_YAML_LOADER)
    for f in spec["checksums"]["fields"]:
        if f["field"] == "file":
            f["algorithm"] = algorithm
    work.mkdir(parents=True, exist_ok=True)
    path = work / f"cbf-{algorithm}.yaml"
    path.write_text(yaml.safe_dump(spec, sort_keys=False), encoding="utf-8")
    out = work / algorithm
    subprocess.run([sys.executable, "-m", "cbfgen", "--spec", str(path), "--out", str(out), "--only", "python"],
                   cwd=REPO, check=True, capture_output=True, env=_env())
    return Binding(f"python-{algorithm}", ["{python}", "conformance/testees/python/testee.py"],
                   {"PYTHONPATH": str(out / "python")})


def _env() -> dict[str, str]:
    import os

    env = dict(os.environ)
    env["PYTHONPATH"] = f"{REPO / 'generator'}:{REPO / 'generated' / 'python'}"
    return env


def reencode(pool: Pool, bases: list[Base], scratch: Scratch) -> list[Base]:
    """The bases decoded and encoded again by this binding (its checksums filled)."""
    paths = scratch.write([b.data for b in bases])
    decoded = pool.many([{"op": "decode", "file": p} for p in paths])
    reqs = [{"op": "encode", "json": d["result"], "keep_stored": False, "profile": b.profile}
            for b, d in zip(bases, decoded, strict=True)]
    encoded = pool.many(reqs)
    return [Base(b.name, base64.b64decode(e["bytes"]), b.profile)
            for b, e in zip(bases, encoded, strict=True) if e.get("ok")]


# -- 3. differential ------------------------------------------------------------------------------
@dataclass
class Disagreement:
    binding: str
    index: int
    mutant: Mutant
    reason: str


def differential(pools: dict[str, Pool], validators: set[str], count: int, seed: int, scratch: Scratch,
                 framing: Framing, kinds: dict[str, str]) -> tuple[int, list[Disagreement]]:
    """``count`` seeded mutants of the golden files through every binding, compared with the Python codec."""
    rng = random.Random(seed)
    sources = [p.read_bytes() for p in sorted(GOLDEN.glob("*.cbf")) if p.stat().st_size < 100_000]
    mutants = (random_mutant(rng.choice(sources), rng, framing, sources) for _ in range(count))
    found: list[Disagreement] = []
    index = 0
    for batch in batched(mutants):
        paths = scratch.write([m.data for m in batch])
        answers: dict[str, list[dict[str, Any]]] = {}
        for name, pool in pools.items():
            reqs: list[dict[str, Any]] = [{"op": "decode", "file": p} for p in paths]
            if name in validators:
                reqs += [{"op": "validate", "file": p, "profile": "default"} for p in paths]
            answers[name] = pool.many(reqs)
        ref = answers["python"]
        n = len(batch)
        for k, m in enumerate(batch):
            ref_dec, ref_val = ref[k], ref[n + k]
            for name in pools:
                if name == "python":
                    continue
                dec = answers[name][k]
                val = answers[name][n + k] if name in validators else None
                why = compare(ref_dec, ref_val, dec, val, name.startswith("kaitai"), kinds)
                if why:
                    found.append(Disagreement(name, index + k, m, why))
        index += n
    return index, found


def compare(ref_dec: dict[str, Any], ref_val: dict[str, Any], dec: dict[str, Any], val: dict[str, Any] | None,
            structural: bool, kinds: dict[str, str]) -> str | None:
    """Why a binding's answers disagree with the reference's, or None."""
    if dec.get("error", {}).get("kind") == "exception" or dec.get("skipped"):
        return f"decode: {dec.get('error') or 'skipped'}"
    if structural and not dec.get("ok"):
        if not ref_dec.get("ok"):
            return None  # both reject
        ref_kinds = {kinds.get(f["check"], "") for f in ref_val.get("findings", [])}
        if ref_kinds & set(KAITAI_REJECTS):
            return None  # a Kaitai valid: rule, or trailing bytes under repeat: eos
        return f"rejects ({dec['error']}) a file the reference decodes with findings {sorted(ref_kinds)}"
    if bool(dec.get("ok")) != bool(ref_dec.get("ok")):
        err = ref_dec.get("error") or dec.get("error")
        return f"decode ok={dec.get('ok')}, reference ok={ref_dec.get('ok')} ({err})"
    if not dec.get("ok"):
        a, b = dec["error"], ref_dec["error"]
        if (a.get("kind"), a.get("offset")) != (b.get("kind"), b.get("offset")):
            return f"decode error {a.get('kind')}@{a.get('offset')}, reference {b.get('kind')}@{b.get('offset')}"
    else:
        diff = first_difference(ref_dec["result"], dec["result"])
        if diff and not (structural and _nan_only(ref_dec["result"], dec["result"])):
            return f"decoded JSON differs: {diff}"
    if val is not None:
        mine = sorted({f["check"] for f in val.get("findings", [])})
        theirs = sorted({f["check"] for f in ref_val.get("findings", [])})
        if mine != theirs:
            return f"finding ids {mine}, reference {theirs}"
    return None


def _nan_only(a: Any, b: Any) -> bool:
    """True when a and b differ only in NaN payloads (a Kaitai target quiets signalling NaNs when it widens)."""
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(_nan_only(a[k], b[k]) for k in a)
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(_nan_only(x, y) for x, y in zip(a, b, strict=True))
    if a == b:
        return True
    x, y = f32_bits(a), f32_bits(b)
    return x is not None and y is not None and (x == y or (is_nan_bits(x) and is_nan_bits(y)))


def check_kinds() -> dict[str, str]:
    spec = yaml.load((REPO / "spec" / "cbf.yaml").read_text(encoding="utf-8"), Loader=_YAML_LOADER)
    return {str(c["id"]): str(c["kind"]) for c in spec["checks"]}


def built_bindings() -> list[Binding]:
    return [b for b in load_bindings(ROOT / "bindings.yaml") if not b.missing()]
