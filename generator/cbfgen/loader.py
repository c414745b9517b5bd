"""Load spec/cbf.yaml into the typed model, refusing a spec that contradicts itself.

Two gates: the JSON Schema (spec.schema.json) for shape, then semantic rules
(tiling, uniqueness, references). Every refusal names the file, the YAML
line and the rule: ``spec/cbf.yaml:212: LINE v3.0 arguments sum to 20 bytes, declared 24``.
"""

from __future__ import annotations

import json
from collections.abc import Iterable
from pathlib import Path
from typing import TYPE_CHECKING, Any

import jsonschema
import yaml

from .escape import keyword_clash
from .model import (
    ALGORITHM_KINDS,
    Algorithm,
    Check,
    ChecksumField,
    Checksums,
    Command,
    Coverage,
    Field,
    HeaderLayout,
    Layout,
    Machine,
    MachineLimit,
    Note,
    PrimitiveType,
    Profile,
    RecordLayout,
    Segment,
    Spec,
    Target,
    Version,
)

SCHEMA_PATH = Path(__file__).with_name("spec.schema.json")


class SpecError(Exception):
    """A spec that cannot be used. str() is `file:line: message`."""

    def __init__(self, path: str, line: int, message: str) -> None:
        super().__init__(f"{path}:{line}: {message}")
        self.path = path
        self.line = line
        self.message = message


class _Map(dict[Any, Any]):
    line = 0
    key_lines: dict[Any, int]


class _Seq(list[Any]):
    line = 0


# libyaml's parser (PyYAML's C binding, in its wheels) when present: it reads the spec about ten
# times faster than the pure-Python one, with the same marks (line, column) and the same safe types.
# PyYAML's composer (Python) goes in front of libyaml's, so that _Loader can bound composition.
if TYPE_CHECKING:  # the stubs type both alike
    _SafeLoader = yaml.SafeLoader
elif hasattr(yaml, "CSafeLoader"):
    class _SafeLoader(yaml.composer.Composer, yaml.CSafeLoader):
        def __init__(self, stream):
            yaml.CSafeLoader.__init__(self, stream)
            yaml.composer.Composer.__init__(self)
else:
    _SafeLoader = yaml.SafeLoader


# Bounds of the spec reader, far above any real spec (spec/cbf.yaml: 3,379 nodes, nesting 7) and far
# below what a hostile file needs: a YAML alias bomb (a few lines whose aliases expand to billions
# of nodes) or a 1,000-deep nesting. Counted while composing, before anything walks the tree.
MAX_NODES = 100_000  # nodes once every alias is expanded
MAX_DEPTH = 50  # nested mappings and sequences


class _Loader(_SafeLoader):
    """A SafeLoader that remembers lines, refuses duplicate keys, and bounds size and depth.

    The composer is PyYAML's (Python), over libyaml's events when present: it counts every node
    with the expanded size of each alias, and the depth, and stops at the first node past a bound
    with a SpecError naming the line. Composition stays linear in the file's size.
    """

    def __init__(self, stream: str) -> None:
        super().__init__(stream)
        self._nodes = 0  # nodes so far, aliases counted at their expanded size
        self._depth = 0
        self._sizes: dict[int, int] = {}  # id(anchored node) -> its expanded size

    def _count(self, n: int, mark: Any) -> None:
        self._nodes += n
        if self._nodes > MAX_NODES:
            raise SpecError(self.name, mark.line + 1, f"YAML: more than {MAX_NODES:,} nodes once aliases "
                            "are expanded (an alias bomb?); the spec reader stops there")

    def compose_node(self, parent: Any, index: Any) -> Any:
        if self.check_event(yaml.AliasEvent):  # type: ignore[no-untyped-call]
            event = self.peek_event()  # type: ignore[no-untyped-call]
            node = super().compose_node(parent, index)  # the anchored node, or the undefined-alias error
            self._count(self._sizes.get(id(node), 1), event.start_mark)
            return node
        event = self.peek_event()  # type: ignore[no-untyped-call]
        start = self._nodes
        self._count(1, event.start_mark)
        nested = isinstance(event, (yaml.MappingStartEvent, yaml.SequenceStartEvent))
        if nested:
            self._depth += 1
            if self._depth > MAX_DEPTH:
                raise SpecError(self.name, event.start_mark.line + 1,
                                f"YAML: nested more than {MAX_DEPTH} deep; the spec reader stops there")
        node = super().compose_node(parent, index)
        if nested:
            self._depth -= 1
        if getattr(event, "anchor", None) is not None:
            self._sizes[id(node)] = self._nodes - start
        return node


def _construct_map(loader: _Loader, node: yaml.MappingNode) -> _Map:
    loader.flatten_mapping(node)
    m = _Map()
    m.line = node.start_mark.line + 1
    m.key_lines = {}
    for k_node, v_node in node.value:
        key = loader.construct_object(k_node, deep=True)  # type: ignore[no-untyped-call]
        if key in m:
            raise SpecError(loader.name, k_node.start_mark.line + 1, f"duplicate key {key!r}")
        m[key] = loader.construct_object(v_node, deep=True)  # type: ignore[no-untyped-call]
        m.key_lines[key] = k_node.start_mark.line + 1
    return m


def _construct_seq(loader: _Loader, node: yaml.SequenceNode) -> _Seq:
    s = _Seq(loader.construct_object(n, deep=True) for n in node.value)  # type: ignore[no-untyped-call]
    s.line = node.start_mark.line + 1
    return s


_Loader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _construct_map)
_Loader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_SEQUENCE_TAG, _construct_seq)


def _line(node: Any, key: Any = None) -> int:
    if isinstance(node, _Map) and key is not None and key in node.key_lines:
        return node.key_lines[key]
    return int(getattr(node, "line", 0))


def _line_of_path(root: Any, path: Iterable[Any]) -> int:
    node, line = root, 1
    for step in path:
        try:
            line = _line(node, step) if isinstance(node, _Map) else _line(node[step]) or line
            node = node[step]
        except (KeyError, IndexError, TypeError):
            break
        line = _line(node) or line
    return line


class _Ctx:
    def __init__(self, path: str) -> None:
        self.path = path

    def fail(self, node: Any, message: str, key: Any = None) -> SpecError:
        return SpecError(self.path, _line(node, key), message)


def _field(ctx: _Ctx, raw: _Map, types: dict[str, PrimitiveType], offset: int, where: str) -> Field:
    if clash := keyword_clash(raw["name"]):  # escape.py; vocab's names pass may take this over
        raise ctx.fail(raw, f"{where}: the name {clash}", "name")
    ptype = types.get(raw["type"])
    if ptype is None:
        raise ctx.fail(raw, f"{where}: unknown type {raw['type']!r}", "type")
    count = int(raw.get("count", 1))
    if ptype.size is not None:
        elem = ptype.size
        if "size" in raw and raw["size"] != ptype.size * count:
            raise ctx.fail(raw, f"{where}: size {raw['size']} contradicts type {ptype.name} x {count}", "size")
    else:
        if "size" not in raw:
            raise ctx.fail(raw, f"{where}: type {ptype.name} needs a size", "type")
        if count != 1:
            raise ctx.fail(raw, f"{where}: type {ptype.name} takes no count", "count")
        elem = int(raw["size"])
    if "offset" in raw and raw["offset"] != offset:
        raise ctx.fail(raw, f"{where}: offset {raw['offset']} but the fields before end at {offset}", "offset")
    if raw.get("text") and ptype.kind != "string":
        raise ctx.fail(raw, f"{where}: text applies to strings only", "text")
    if "magic" in raw and ptype.kind != "uint":
        raise ctx.fail(raw, f"{where}: magic needs an integer type", "magic")
    if "magic" in raw and raw["magic"] >= 1 << (8 * elem):
        raise ctx.fail(raw, f"{where}: magic 0x{raw['magic']:X} does not fit {ptype.name}", "magic")
    return Field(
        name=raw["name"],
        type=ptype.name,
        kind=ptype.kind,
        offset=offset,
        elem_size=elem,
        count=count,
        doc=str(raw["doc"]).strip(),
        line=raw.line,
        clause=raw.get("clause"),
        unit=raw.get("unit"),
        role=raw.get("role"),
        magic=raw.get("magic"),
        checksum=raw.get("checksum"),
        reserved=bool(raw.get("reserved", False)),
        text=bool(raw.get("text", False)),
    )


def _fields(ctx: _Ctx, raws: _Seq, types: dict[str, PrimitiveType], where: str) -> tuple[tuple[Field, ...], int]:
    out: list[Field] = []
    offset = 0
    names: set[str] = set()
    for raw in raws:
        f = _field(ctx, raw, types, offset, f"{where} field {raw['name']}")
        if f.name in names:
            raise ctx.fail(raw, f"{where}: duplicate field name {f.name!r}", "name")
        names.add(f.name)
        out.append(f)
        offset = f.end
    return tuple(out), offset


def load(path: str | Path) -> Spec:
    """Load, check and return the spec model. Raises SpecError."""
    spath = str(path)
    ctx = _Ctx(spath)
    try:
        text = Path(path).read_text(encoding="utf-8")
    except OSError as exc:
        raise SpecError(spath, 0, f"cannot read: {exc.strerror}") from None
    try:
        loader = _Loader(text)
        loader.name = spath
        try:
            raw = loader.get_single_data()
        finally:
            loader.dispose()  # type: ignore[no-untyped-call]
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark
        raise SpecError(spath, (mark.line + 1) if mark else 0, f"YAML: {exc.problem}") from None
    if not isinstance(raw, _Map):
        raise SpecError(spath, 1, "the spec must be a mapping")

    schema = json.loads(SCHEMA_PATH.read_text(encoding="utf-8"))
    validator = jsonschema.Draft202012Validator(schema)
    errors = sorted(validator.iter_errors(raw), key=lambda e: (_line_of_path(raw, e.absolute_path), str(e.message)))
    if errors:
        e = errors[0]
        where = "/".join(str(p) for p in e.absolute_path) or "(top)"
        raise SpecError(spath, _line_of_path(raw, e.absolute_path), f"schema: {where}: {e.message}")
    return _build(ctx, raw)


def _build(ctx: _Ctx, raw: _Map) -> Spec:
    types = {
        name: PrimitiveType(name, t["kind"], t.get("size"), str(t["doc"]))
        for name, t in raw["types"].items()
    }

    # -- versions ------------------------------------------------------------
    versions: list[Version] = []
    for v in raw["versions"]:
        if any(o.id == str(v["id"]) for o in versions):
            raise ctx.fail(v, f"duplicate version id {v['id']!r}", "id")
        if v["header"] not in raw["headers"]:
            raise ctx.fail(v, f"version {v['id']}: unknown header layout {v['header']!r}", "header")
        versions.append(
            Version(str(v["id"]), v["major"], v.get("minor"), v["header"], v["clause"], v["writable"],
                    str(v["doc"]).strip(), v.line, v.get("since"))
        )
    for a in versions:
        for b in versions:
            if a is not b and a.major == b.major and (a.minor is None or b.minor is None or a.minor == b.minor):
                raise ctx.fail(raw["versions"], f"versions {a.id} and {b.id} both match major {a.major}")
    vids = [v.id for v in versions]
    for key in ("default_version", "fallback_version"):
        if raw[key] not in vids:
            raise ctx.fail(raw, f"{key} {raw[key]!r} is not a version", key)

    # -- header layouts: tile the size, shared fields in shared places ------
    headers: dict[str, HeaderLayout] = {}
    for hid, h in raw["headers"].items():
        fields, end = _fields(ctx, h["fields"], types, f"header {hid}")
        if end != h["size"]:
            raise ctx.fail(h, f"header {hid} fields tile {end} bytes, declared {h['size']}", "size")
        headers[hid] = HeaderLayout(hid, h["size"], h["clause"], str(h["doc"]).strip(), fields, h.line)
    first = next(iter(headers.values()))
    shared_roles = ("start_pattern", "end_pattern", "version_major", "version_minor", "command_count", "checksum")
    for h in headers.values():
        if h.size != first.size:
            raise ctx.fail(raw["headers"][h.id], f"header {h.id} is {h.size} bytes, header {first.id} {first.size}",
                           "size")
        for f in h.fields:
            if f.role in shared_roles:
                twin = next((g for g in first.fields if g.name == f.name), None)
                if twin is None or (twin.offset, twin.type, twin.role, twin.magic, twin.checksum) != (
                    f.offset, f.type, f.role, f.magic, f.checksum):
                    raise SpecError(ctx.path, f.line, f"header {h.id} field {f.name} must match header {first.id}")
        for role in ("start_pattern", "end_pattern", "version_major", "version_minor", "command_count"):
            if h.by_role(role) is None:
                raise ctx.fail(raw["headers"][h.id], f"header {h.id} has no field with role {role}")

    # -- record layout -------------------------------------------------------
    r = raw["record"]
    rfields, rend = _fields(ctx, r["fields"], types, "record")
    if rend != r["head_size"]:
        raise ctx.fail(r, f"record head fields tile {rend} bytes, declared {r['head_size']}", "head_size")
    record = RecordLayout(r["head_size"], r["clause"], str(r["doc"]).strip(), rfields)
    for role in ("sequence", "code", "code_copy", "arg_size", "reserved"):
        try:
            record.by_role(role)
        except KeyError:
            raise ctx.fail(r, f"record has no field with role {role}") from None
    if record.by_role("arg_size").type != "u1" and raw["limits"]["max_arg_size"] > 255:
        raise ctx.fail(r, "arg_size field too small for limits.max_arg_size")

    # -- commands ------------------------------------------------------------
    commands: list[Command] = []
    names: dict[str, int] = {}
    codes: dict[int, str] = {}
    for c in raw["commands"]:
        name, code = c["name"], c["code"]
        if name in names:
            raise ctx.fail(c, f"duplicate command name {name} (also line {names[name]})", "name")
        if clash := keyword_clash(name):  # escape.py; vocab's names pass may take this over
            raise ctx.fail(c, f"command name {clash}", "name")
        if code in codes:
            raise ctx.fail(c, f"{name}: duplicate code 0x{code:02X}, already {codes[code]}", "code")
        names[name] = c.line
        codes[code] = name
        layouts: list[Layout] = []
        for i, lay in enumerate(c["layouts"]):
            variant = lay.get("variant", "")
            if i == 0 and variant:
                raise ctx.fail(lay, f"{name}: the first layout is the primary one and takes no variant", "variant")
            if i > 0 and not variant:
                raise ctx.fail(lay, f"{name}: layout {i + 1} needs a variant name")
            if any(o.variant == variant for o in layouts):
                raise ctx.fail(lay, f"{name}: duplicate variant {variant!r}", "variant")
            for v in lay["versions"]:
                if v not in vids:
                    raise ctx.fail(lay, f"{name}: unknown version {v!r}", "versions")
            for p in lay.get("profiles", []):
                if p not in [q["id"] for q in raw["profiles"]]:
                    raise ctx.fail(lay, f"{name}: unknown profile {p!r}", "profiles")
            args, total = _fields(ctx, lay["args"], types, f"{name}")
            vtext = "/".join("v" + v for v in lay["versions"])
            if total != lay["size"]:
                raise ctx.fail(lay, f"{name} {vtext} arguments sum to {total} bytes, declared {lay['size']}", "size")
            if lay["size"] > raw["limits"]["max_arg_size"]:
                raise ctx.fail(lay, f"{name}: size {lay['size']} exceeds limits.max_arg_size", "size")
            layouts.append(
                Layout(name, variant, tuple(str(v) for v in lay["versions"]), lay["size"], args,
                       tuple(lay.get("profiles", [])), str(lay.get("doc", "")).strip(), lay.get("clause"), lay.line)
            )
        for v in vids:
            sizes = [lay.size for lay in layouts if v in lay.versions]
            if len(sizes) != len(set(sizes)):
                raise ctx.fail(c, f"{name}: two layouts of version {v} have the same size", "layouts")
        cmd = Command(
            name=name, code=code, doc=str(c["doc"]).strip(), clause=c["clause"], layouts=tuple(layouts), line=c.line,
            motion=dict(c["motion"]) if "motion" in c else None,
            orientation=dict(c["orientation"]) if "orientation" in c else None,
            shape=dict(c["shape"]) if "shape" in c else None,
            cutter=dict(c["cutter"]) if "cutter" in c else None,
            sets=dict(c["sets"]) if "sets" in c else None,
            progress=c.get("progress"),
            declared_size=c.get("declared_size"), listed_size=c.get("listed_size"), erratum=c.get("erratum"),
        )
        for role in ("motion", "orientation", "shape", "cutter"):
            refs = getattr(cmd, role) or {}
            for key, argname in refs.items():
                if key == "kind":
                    continue
                _require_arg(ctx, c, cmd, argname, f"{role}.{key}")
        for key, value in (cmd.sets or {}).items():
            if isinstance(value, str):
                _require_arg(ctx, c, cmd, value, f"sets.{key}")
        if cmd.progress:
            _require_arg(ctx, c, cmd, cmd.progress, "progress")
        _check_roles(ctx, c, cmd)
        commands.append(cmd)

    # -- checksums and profiles --------------------------------------------
    cs = raw["checksums"]
    algorithms = {k: Algorithm(k, a["kind"], str(a["doc"]).strip()) for k, a in cs["algorithms"].items()}
    coverages: dict[str, Coverage] = {}
    rnames = {f.name for f in rfields}
    for k, cov in cs["coverages"].items():
        segs = []
        for s in cov["segments"]:
            seg = Segment(s["region"], s.get("start"), s.get("end"), tuple(s.get("exclude", [])))
            if seg.region == "header" and (seg.start is None or seg.end is None or seg.end > first.size
                                           or seg.start >= seg.end):
                raise ctx.fail(s, f"coverage {k}: header segment needs 0 <= start < end <= {first.size}")
            if seg.region == "file" and seg.start is None:
                raise ctx.fail(s, f"coverage {k}: file segment needs a start")
            for ex in seg.exclude:
                if ex not in rnames:
                    raise ctx.fail(s, f"coverage {k}: unknown record field {ex!r}", "exclude")
            segs.append(seg)
        coverages[k] = Coverage(k, str(cov["doc"]).strip(), tuple(segs))
    # the stored field of each checksum tag: its width bounds the algorithm's result
    widths = {f.checksum: f.size for h in headers.values() for f in h.fields if f.checksum}
    widths.update({f.checksum: f.size for f in rfields if f.checksum})

    def fits(node: _Map, key: str, tag: str, alg_name: str, what: str) -> None:
        bits = ALGORITHM_KINDS[algorithms[alg_name].kind]
        if tag in widths and bits is not None and bits > 8 * widths[tag]:
            raise ctx.fail(node, f"{what}: algorithm {alg_name} gives {bits} bits, the {tag} checksum field "
                                 f"holds {8 * widths[tag]}", key)

    cfields: list[ChecksumField] = []
    for f in cs["fields"]:
        if f["algorithm"] not in algorithms:
            raise ctx.fail(f, f"checksum {f['field']}: unknown algorithm {f['algorithm']!r}", "algorithm")
        if f["coverage"] not in coverages:
            raise ctx.fail(f, f"checksum {f['field']}: unknown coverage {f['coverage']!r}", "coverage")
        if any(o.field == f["field"] for o in cfields):
            raise ctx.fail(f, f"checksum {f['field']}: defined twice", "field")
        fits(f, "algorithm", f["field"], f["algorithm"], f"checksum {f['field']}")
        cfields.append(ChecksumField(f["field"], f["algorithm"], f["coverage"], f["clause"]))
    tags = {f.field for f in cfields}
    for tag in ("args", "header", "file"):
        if tag not in tags:
            raise ctx.fail(cs, f"checksums: no definition for the {tag} checksum", "fields")
    for h in headers.values():
        for f in h.fields:
            if f.checksum and f.checksum not in tags:
                raise SpecError(ctx.path, f.line, f"field {f.name}: checksum {f.checksum} is not defined")
    if sorted(cs["fill_order"]) != sorted(tags):
        raise ctx.fail(cs, "checksums.fill_order must name every checksum once", "fill_order")
    checksums = Checksums(algorithms, coverages, tuple(cfields), tuple(cs["fill_order"]))
    profiles: list[Profile] = []
    for p in raw["profiles"]:
        for cov_name in list(p["file_coverages"]) + list(p["hint_coverages"]):
            if cov_name not in coverages:
                raise ctx.fail(p, f"profile {p['id']}: unknown coverage {cov_name!r}")
        if "file_algorithm" in p:
            if p["file_algorithm"] not in algorithms:
                raise ctx.fail(p, f"profile {p['id']}: unknown algorithm {p['file_algorithm']!r}", "file_algorithm")
            fits(p, "file_algorithm", "file", p["file_algorithm"], f"profile {p['id']}")
        profiles.append(Profile(p["id"], str(p["doc"]).strip(), tuple(p["file_coverages"]), tuple(p["hint_coverages"]),
                                p.get("file_algorithm")))
    if profiles[0].id != "default":
        raise ctx.fail(raw["profiles"], "the first profile must be 'default'")

    machine = _machine(ctx, raw["machine"], raw["units"])

    # -- checks --------------------------------------------------------------
    checks: list[Check] = []
    cmd_by_name = {c.name: c for c in commands}
    for ch in raw["checks"]:
        if any(o.id == str(ch["id"]) for o in checks):
            raise ctx.fail(ch, f"duplicate check id {ch['id']!r}", "id")
        targets = []
        for t in ch.get("targets", []):
            tcmd = cmd_by_name.get(t["command"])
            if tcmd is None:
                raise ctx.fail(t, f"check {ch['id']}: unknown command {t['command']}", "command")
            for argname in t["args"]:
                _require_arg(ctx, t, tcmd, argname, f"check {ch['id']}")
            if ("limit" in t) != (ch["kind"] == "machine_limits"):
                raise ctx.fail(t, f"check {ch['id']}: a target names a limit exactly when its kind is "
                                  f"machine_limits", "limit" if "limit" in t else "command")
            if "limit" in t:
                _machine_target(ctx, t, tcmd, machine, ch["id"])
            targets.append(Target(t["command"], tuple(t["args"]), t.get("limit")))
        for v in ch.get("versions", []):
            if v not in vids:
                raise ctx.fail(ch, f"check {ch['id']}: unknown version {v!r}", "versions")
        if ch["kind"] in ("positive", "nonzero_vector", "range", "nondecreasing", "ordered",
                          "machine_limits") and not targets:
            raise ctx.fail(ch, f"check {ch['id']}: kind {ch['kind']} needs targets", "kind")
        if ch["kind"] == "availability" and not ch.get("versions"):
            raise ctx.fail(ch, f"check {ch['id']}: availability needs versions", "kind")
        for cname in ch.get("commands", []):
            if cname not in cmd_by_name:
                raise ctx.fail(ch, f"check {ch['id']}: unknown command {cname}", "commands")
        checks.append(
            Check(id=str(ch["id"]), kind=ch["kind"], severity=ch["severity"], text=str(ch["text"]).strip(),
                  fails=" ".join(str(ch["fails"]).split()), line=ch.line, clause=ch.get("clause"),
                  decision=ch.get("decision"), input=ch.get("input"), input_severity=ch.get("input_severity"),
                  versions=tuple(ch.get("versions", [])),
                  commands=tuple(ch.get("commands", [])), targets=tuple(targets), min=ch.get("min"),
                  max=ch.get("max"))
        )
    _check_availability(ctx, raw["checks"], checks, commands, vids)
    _check_machine_coverage(ctx, raw["checks"], checks, commands, machine)

    for c in commands:
        if not any(c.available_in(v.id) for v in versions):
            raise SpecError(ctx.path, c.line, f"{c.name} is available in no version")

    decisions = tuple(Note(d["id"], d["topic"], " ".join(str(d["decision"]).split()), str(d["evidence"]))
                      for d in raw["decisions"])
    known_notes = {d.id for d in decisions}
    for ch in checks:
        if ch.decision and ch.decision not in known_notes:
            raise SpecError(ctx.path, ch.line, f"check {ch.id}: unknown decision {ch.decision!r}")
    if machine.decision not in known_notes:
        raise ctx.fail(raw["machine"], f"machine: unknown decision {machine.decision!r}", "decision")
    errata = tuple(Note(e["id"], e["clause"], str(e["text"]), clause=e["clause"]) for e in raw["errata"])
    history = tuple(Note(h["version"], h["version"], str(h["text"]), clause=h["clause"], date=str(h["date"]))
                    for h in raw["history"])
    return Spec(
        path=ctx.path,
        meta=_plain(raw["meta"]),
        types=types,
        units={k: str(v["doc"]) for k, v in raw["units"].items()},
        versions=tuple(versions),
        default_version=raw["default_version"],
        fallback_version=raw["fallback_version"],
        headers=headers,
        record=record,
        commands=tuple(commands),
        checksums=checksums,
        profiles=tuple(profiles),
        tolerances={k: float(v) for k, v in raw["tolerances"].items()},
        limits={k: int(v) for k, v in raw["limits"].items()},
        machine=machine,
        checks=tuple(checks),
        cut=_plain(raw["cut"]),
        decisions=decisions,
        errata=errata,
        history=history,
        raw=_plain(raw),
    )


def _check_availability(ctx: _Ctx, raws: _Seq, checks: list[Check], commands: list[Command],
                        vids: list[str]) -> None:
    """Every (version, command) pair where the command has no layout is covered by exactly one
    availability check, and a check covers only such pairs: its findings name the right clause."""
    raw_of = {str(r["id"]): r for r in raws}
    covered: dict[tuple[str, str], Check] = {}
    for ch in checks:
        if ch.kind != "availability":
            continue
        node = raw_of[ch.id]
        for v in ch.versions:
            for name in ch.commands:
                cmd = next(c for c in commands if c.name == name)
                if cmd.available_in(v):
                    raise ctx.fail(node, f"check {ch.id}: {name} has a layout in version {v}, nothing to cover",
                                   "commands")
                other = covered.get((v, name))
                if other is not None:
                    raise ctx.fail(node, f"check {ch.id}: {name} in version {v} is already covered by check "
                                         f"{other.id} (line {other.line}); one check per command and version",
                                   "commands")
                covered[(v, name)] = ch
    for v in vids:
        for cmd in commands:
            if not cmd.available_in(v) and (v, cmd.name) not in covered:
                raise SpecError(ctx.path, cmd.line, f"{cmd.name} has no layout in version {v} and no availability "
                                                    f"check covers it (name it in a check's commands)")


def _machine(ctx: _Ctx, m: _Map, units: _Map) -> Machine:
    """The default machine (L1): each limit's unit is a unit of the spec, min <= max, a box has
    one bound per axis."""
    limits: list[MachineLimit] = []
    for name, lim in m["limits"].items():
        node = m["limits"][name]
        if lim["unit"] not in units:
            raise ctx.fail(node, f"machine limit {name}: unknown unit {lim['unit']!r}", "unit")
        axes = tuple(str(a) for a in lim.get("axes", []))
        lo, hi = lim["min"], lim["max"]
        want = len(axes) if axes else None
        for key, v in (("min", lo), ("max", hi)):
            if (want is None) != (not isinstance(v, list)) or (want is not None and len(v) != want):
                raise ctx.fail(node, f"machine limit {name}: {key} must be "
                                     + (f"a list of {want} numbers (one per axis)" if want else "a number"), key)
        los = tuple(float(x) for x in (lo if isinstance(lo, list) else [lo]))
        his = tuple(float(x) for x in (hi if isinstance(hi, list) else [hi]))
        if any(a > b for a, b in zip(los, his, strict=True)):
            raise ctx.fail(node, f"machine limit {name}: min exceeds max", "min")
        limits.append(MachineLimit(str(name), str(lim["unit"]), los, his, axes, str(lim["doc"]).strip()))
    return Machine(str(m["decision"]), str(m["doc"]).strip(), tuple(limits))


def _machine_target(ctx: _Ctx, t: _Map, cmd: Command, machine: Machine, cid: str) -> None:
    """A machine_limits target: its limit exists, and every layout's argument of that name has the
    limit's unit and shape (a box bounds float vectors of as many components as it has axes)."""
    try:
        lim = machine.limit(str(t["limit"]))
    except KeyError:
        raise ctx.fail(t, f"check {cid}: unknown machine limit {t['limit']!r}", "limit") from None
    for lay in cmd.layouts:
        for name in t["args"]:
            a = lay.arg(name)
            if a is None:
                continue
            shape_ok = a.kind == "float" and a.count == (len(lim.axes) if lim.axes else 1)
            if a.unit != lim.unit or not shape_ok:
                raise ctx.fail(t, f"check {cid}: {cmd.name}.{name} ({a.type} x{a.count}, unit {a.unit}) does not "
                                  f"fit machine limit {lim.name} (unit {lim.unit}"
                                  + (f", {len(lim.axes)} axes)" if lim.axes else ", a scalar)"), "args")


def _check_machine_coverage(ctx: _Ctx, raws: _Seq, checks: list[Check], commands: list[Command],
                            machine: Machine) -> None:
    """Which arguments are positions comes from the model: every float vector argument whose unit is a
    box limit's unit (mm: points, starts, ends, centres) is targeted by that limit."""
    covered = {(t.command, a) for ch in checks if ch.kind == "machine_limits" for t in ch.targets
               if t.limit and machine.limit(t.limit).is_vector for a in t.args}
    if not any(ch.kind == "machine_limits" for ch in checks):
        return
    for lim in machine.limits:
        if not lim.is_vector:
            continue
        for cmd in commands:
            for lay in cmd.layouts:
                for a in lay.args:
                    if a.kind == "float" and a.count == len(lim.axes) and a.unit == lim.unit \
                            and (cmd.name, a.name) not in covered:
                        raise SpecError(ctx.path, lay.line, f"{cmd.name}.{a.name} is a position ({a.count} x "
                                                            f"{a.unit}) that no machine_limits target bounds by "
                                                            f"limit {lim.name}")


def _require_arg(ctx: _Ctx, node: Any, cmd: Command, argname: str, what: str) -> None:
    if not any(lay.arg(argname) for lay in cmd.layouts):
        raise ctx.fail(node, f"{cmd.name}: {what} names {argname!r}, which no layout has")


def _check_roles(ctx: _Ctx, node: Any, cmd: Command) -> None:
    needs = {"point": ("end",), "line": ("start", "end"), "circle": ("start", "center", "normal", "degrees"),
             "helix": ("start", "center", "normal", "degrees", "length")}
    if cmd.motion:
        for key in needs[cmd.motion["kind"]]:
            if key not in cmd.motion:
                raise ctx.fail(node, f"{cmd.name}: motion kind {cmd.motion['kind']} needs {key}", "motion")
    if cmd.orientation and cmd.orientation["kind"] == "path" and "start" not in cmd.orientation:
        raise ctx.fail(node, f"{cmd.name}: orientation path needs start", "orientation")


def _plain(x: Any) -> Any:
    if isinstance(x, dict):
        return {k: _plain(v) for k, v in x.items()}
    if isinstance(x, list):
        return [_plain(v) for v in x]
    return x
