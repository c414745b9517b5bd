"""What the assembler reads from spec/cbf.yaml: how each checksum is computed.

Read with plain yaml, not through the generator or a binding: the field that
stores each checksum (its place and width), the algorithm and the coverage the
spec declares for it, what each profile changes for the file checksum, the
fill order, and the versions (for premises such as "a major no version has").
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

# libyaml's parser (PyYAML's C binding) when present: the same values, about ten times faster.
_YAML_LOADER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)

SPEC = Path(__file__).resolve().parents[2] / "spec" / "cbf.yaml"


@dataclass(frozen=True)
class Slot:
    """A stored field: offset (in the header, or in the record head) and width."""

    offset: int
    width: int


@dataclass(frozen=True)
class ArgSum:
    """A checksum field among a command layout's arguments (issue 25, point 1): the command code and
    argument size of its layout, the argument's offset and width, and the record's byte ranges (from
    its first byte: head, then arguments) its named fields cover, in order."""

    code: int
    size: int
    offset: int
    width: int
    ranges: tuple[tuple[int, int], ...]


@dataclass(frozen=True)
class SpecSums:
    byte_order: str
    header_size: int
    head_size: int
    record_fields: dict[str, Slot]  # every record-head field by name
    arg_size: Slot  # the record head field holding nb
    slots: dict[str, Slot]  # checksum tag -> its field (header offset; record-head offset for args)
    kinds: dict[str, str]  # algorithm name -> kind
    fields: dict[str, tuple[str, str]]  # tag -> (algorithm, coverage)
    coverages: dict[str, list[dict[str, Any]]]
    profiles: dict[str, tuple[str, str | None]]  # id -> (first file coverage, file_algorithm)
    default_profile: str
    fill_order: tuple[str, ...]
    majors: tuple[int, ...]
    code: Slot | None = None  # the record head field holding the command code
    arg_sums: dict[str, tuple[ArgSum, ...]] = field(default_factory=dict)  # tag -> every layout carrying it
    header_fields: dict[str, dict[str, Slot]] = field(default_factory=dict)  # header layout -> name -> slot
    header_tags: dict[str, tuple[str, ...]] = field(default_factory=dict)  # tag -> header layouts carrying it

    def rule(self, tag: str, profile: str | None) -> tuple[str, str]:
        """(algorithm kind, coverage) of a checksum, under a profile for the file checksum."""
        if tag not in self.fields:
            raise ValueError(f"the spec defines no {tag!r} checksum; it has {', '.join(self.fields)}")
        alg, cov = self.fields[tag]
        if profile is not None and tag != "file":
            raise ValueError(f"only the file checksum depends on the profile, not {tag!r}")
        if tag == "file":
            pid = profile or self.default_profile
            if pid not in self.profiles:
                raise ValueError(f"unknown profile {pid!r}; the spec has {', '.join(self.profiles)}")
            cov, palg = self.profiles[pid]
            alg = palg or alg
        return self.kinds[alg], cov


def _sizes(doc: dict[str, Any]) -> dict[str, int | None]:
    return {name: t.get("size") for name, t in doc["types"].items()}


def _tile(fields: list[dict[str, Any]], sizes: dict[str, int | None]) -> list[tuple[dict[str, Any], Slot]]:
    out, at = [], 0
    for f in fields:
        size = sizes[f["type"]]
        width = (size or 0) * int(f.get("count", 1)) if size else int(f["size"])
        out.append((f, Slot(int(f.get("offset", at)), width)))
        at = out[-1][1].offset + width
    return out


def load(path: Path = SPEC) -> SpecSums:
    doc = yaml.load(path.read_text(encoding="utf-8"), Loader=_YAML_LOADER)
    sizes = _sizes(doc)
    header = next(iter(doc["headers"].values()))
    slots: dict[str, Slot] = {}
    for layout in doc["headers"].values():  # a new version's header may carry a checksum field of its own
        for f, slot in _tile(layout["fields"], sizes):
            if "checksum" in f:
                slots.setdefault(f["checksum"], slot)
    record: dict[str, Slot] = {}
    arg_size = None
    for f, slot in _tile(doc["record"]["fields"], sizes):
        record[f["name"]] = slot
        if "checksum" in f:
            slots[f["checksum"]] = slot
        if f.get("role") == "arg_size":
            arg_size = slot
    if arg_size is None:
        raise ValueError(f"{path}: the record has no arg_size field")
    cs = doc["checksums"]
    code = next((record[f["name"]] for f in doc["record"]["fields"] if f.get("role") == "code"), None)
    arg_sums = _arg_sums(doc, sizes, record, int(doc["record"]["head_size"]))
    for tag, found in arg_sums.items():
        slots.setdefault(tag, Slot(found[0].offset, found[0].width))
    header_fields = {hid: {f["name"]: slot for f, slot in _tile(h["fields"], sizes)}
                     for hid, h in doc["headers"].items()}
    header_tags: dict[str, tuple[str, ...]] = {}
    for hid, h in doc["headers"].items():
        for f in h["fields"]:
            if "checksum" in f:
                header_tags[f["checksum"]] = (*header_tags.get(f["checksum"], ()), hid)
    profiles = {p["id"]: (p["file_coverages"][0], p.get("file_algorithm")) for p in doc["profiles"]}
    return SpecSums(
        byte_order=doc["meta"]["byte_order"], header_size=int(header["size"]),
        head_size=int(doc["record"]["head_size"]), record_fields=record, arg_size=arg_size, slots=slots,
        kinds={name: a["kind"] for name, a in cs["algorithms"].items()},
        fields={f["field"]: (f["algorithm"], f["coverage"]) for f in cs["fields"]},
        coverages={name: list(c["segments"]) for name, c in cs["coverages"].items()},
        profiles=profiles, default_profile=doc["profiles"][0]["id"], fill_order=tuple(cs["fill_order"]),
        majors=tuple(int(v["major"]) for v in doc["versions"]), code=code, arg_sums=arg_sums,
        header_fields=header_fields, header_tags=header_tags,
    )


def _arg_sums(doc: dict[str, Any], sizes: dict[str, int | None], head: dict[str, Slot],
              head_size: int) -> dict[str, tuple[ArgSum, ...]]:
    """Every layout's checksum fields among its arguments, their named coverage resolved in that
    layout (arguments first, then record head fields)."""
    coverages = {name: list(c["segments"]) for name, c in doc["checksums"]["coverages"].items()}
    defined = {f["field"]: f["coverage"] for f in doc["checksums"]["fields"]}
    out: dict[str, tuple[ArgSum, ...]] = {}
    for cmd in doc["commands"]:
        for lay in cmd["layouts"]:
            args = {f["name"]: slot for f, slot in _tile(lay["args"], sizes)}
            for f in lay["args"]:
                tag = f.get("checksum")
                if tag is None:
                    continue
                ranges = []
                for seg in coverages[defined[tag]]:
                    for n in seg.get("fields", ()):
                        if n in args:
                            ranges.append((head_size + args[n].offset, head_size + args[n].offset + args[n].width))
                        elif n in head:
                            ranges.append((head[n].offset, head[n].offset + head[n].width))
                        else:
                            raise ValueError(f"checksum {tag}: {cmd['name']} has no field {n!r}")
                own = args[f["name"]]
                out[tag] = (*out.get(tag, ()), ArgSum(int(cmd["code"]), int(lay["size"]), own.offset, own.width,
                                                      tuple(ranges)))
    return out
