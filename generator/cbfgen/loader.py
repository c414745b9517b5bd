"""Load spec/cbf.yaml into the typed model, refusing a spec that contradicts itself.

Two gates: the JSON Schema (spec.schema.json) for shape, then semantic rules
(tiling, uniqueness, references). Every refusal names the file, the YAML
line and the rule: ``spec/cbf.yaml:212: LINE v3.0 arguments sum to 20 bytes, declared 24``.
"""

from __future__ import annotations

import json
from collections.abc import Callable, Iterable
from dataclasses import dataclass, replace
from dataclasses import field as dataclass_field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import jsonschema
import yaml

from .escape import keyword_clash
from .model import (
    Algorithm,
    ArgChecksum,
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
    Profile,
    RecordLayout,
    Segment,
    Spec,
    Version,
)
from .registry import (
    ALGORITHMS,
    CHECK_KINDS,
    COMMON_CHECK_KEYS,
    DERIVED_HEADER_ROLES,
    FIELD_KINDS,
    GENERATED_NAMES,
    NUMERIC_KINDS,
    ROLE_ARGS,
    ROLE_KINDS,
    ROLE_NEEDS,
    SEVERITIES,
    TYPES,
    DeprecatedParams,
    FieldType,
    RoleArg,
    Target,
    repeat_unsupported,
    role_arg_fits,
    unsupported,
    unsupported_in_head,
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

if TYPE_CHECKING:
    _Composer = yaml.SafeLoader
else:
    _Composer = yaml.composer.Composer


class _BoundedComposer(_Composer):
    """PyYAML's composer (over libyaml's events, or PyYAML's own parser) that counts every node,
    each alias at the expanded size of its anchor, and the depth, and stops at the first node past
    a bound with a SpecError naming the line. Composition stays linear in the file's size."""

    def compose_document(self) -> Any:
        self._nodes = 0  # nodes so far, aliases counted at their expanded size
        self._depth = 0
        self._sizes: dict[int, int] = {}  # id(anchored node) -> its expanded size
        return super().compose_document()

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


class _Loader(_BoundedComposer, _SafeLoader):
    """A SafeLoader that remembers lines, refuses duplicate keys, and bounds size and depth."""


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


class SpecErrors(SpecError):
    """Every problem of a spec, found in one run. str() is one `file:line: message` a line;
    ``line`` and ``message`` are the first problem's (in pass order)."""

    def __init__(self, path: str, problems: list[tuple[int, str]]) -> None:
        line, message = problems[0]
        super().__init__(path, line, message)
        self.problems = tuple(problems)
        self.args = ("\n".join(f"{path}:{ln}: {msg}" for ln, msg in problems),)

    def __str__(self) -> str:
        return str(self.args[0])


class _Ctx:
    """The problems found so far (every pass adds to them; none stops the run)."""

    def __init__(self, path: str) -> None:
        self.path = path
        self.problems: list[tuple[int, str]] = []

    def fail(self, node: Any, message: str, key: Any = None) -> None:
        self.problems.append((_line(node, key), message))

    def at(self, line: int, message: str) -> None:
        self.problems.append((line, message))


def _schema() -> dict[str, Any]:
    """spec.schema.json with its vocabulary enums filled from the registry (field types, type
    kinds, check kinds, severities, role kinds) and the model (checksum algorithm kinds): the schema names no
    type and no kind itself."""
    schema: dict[str, Any] = json.loads(SCHEMA_PATH.read_text(encoding="utf-8"))
    schema["$defs"]["field"]["properties"]["type"] = {"enum": list(TYPES)}
    schema["properties"]["types"]["additionalProperties"]["properties"]["kind"] = {"enum": list(FIELD_KINDS)}
    check = schema["properties"]["checks"]["items"]["properties"]
    check["kind"] = {"enum": list(CHECK_KINDS)}
    check["severity"] = check["input_severity"] = {"enum": list(SEVERITIES)}
    algorithm = schema["properties"]["checksums"]["properties"]["algorithms"]["additionalProperties"]
    algorithm["properties"]["kind"] = {"enum": list(ALGORITHMS)}
    command = schema["properties"]["commands"]["items"]["properties"]
    for role, kinds in ROLE_KINDS.items():
        command[role]["allOf"][1]["properties"]["kind"] = {"enum": list(kinds)}
    return schema


def load(path: str | Path) -> Spec:
    """Load, check and return the spec model. Raises SpecError (SpecErrors: every problem found)."""
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

    validator = jsonschema.Draft202012Validator(_schema())
    errors = sorted(validator.iter_errors(raw), key=lambda e: (_line_of_path(raw, e.absolute_path), str(e.message)))
    for e in errors:  # every shape problem; the semantic passes need the shape, so they wait for it
        where = "/".join(str(p) for p in e.absolute_path) or "(top)"
        ctx.at(_line_of_path(raw, e.absolute_path), f"schema: {where}: {e.message}")
    if ctx.problems:
        raise SpecErrors(spath, ctx.problems)
    spec = _build(ctx, raw)
    if ctx.problems or spec is None:
        raise SpecErrors(spath, ctx.problems or [(1, "the spec could not be built")])
    return spec


# -- the passes ---------------------------------------------------------------------------------
# Each pass checks one part of the spec and adds every problem it finds to ctx; it builds what it
# can, so the passes after it still run and report their own problems in the same run.

@dataclass
class _State:
    raw: _Map
    types: dict[str, FieldType] = dataclass_field(default_factory=dict)
    versions: list[Version] = dataclass_field(default_factory=list)
    headers: dict[str, HeaderLayout] = dataclass_field(default_factory=dict)
    record: RecordLayout | None = None
    commands: list[Command] = dataclass_field(default_factory=list)
    checksums: Checksums | None = None
    profiles: list[Profile] = dataclass_field(default_factory=list)
    machine: Machine | None = None
    checks: list[Check] = dataclass_field(default_factory=list)
    raw_checks: dict[str, _Map] = dataclass_field(default_factory=dict)
    decisions: tuple[Note, ...] = ()

    @property
    def vids(self) -> list[str]:
        return [v.id for v in self.versions]


def _build(ctx: _Ctx, raw: _Map) -> Spec | None:
    st = _State(raw)
    for p in PASSES:
        p(ctx, st)
    if ctx.problems or st.record is None or st.checksums is None or st.machine is None:
        return None
    errata = tuple(Note(e["id"], e["clause"], str(e["text"]), clause=e["clause"]) for e in raw["errata"])
    history = tuple(Note(h["version"], h["version"], str(h["text"]), clause=h["clause"], date=str(h["date"]))
                    for h in raw["history"])
    return Spec(
        path=ctx.path, meta=_plain(raw["meta"]), types=st.types,
        units={k: str(v["doc"]) for k, v in raw["units"].items()},
        versions=tuple(st.versions), default_version=raw["default_version"],
        fallback_version=raw["fallback_version"], headers=st.headers, record=st.record,
        commands=tuple(st.commands), checksums=st.checksums, profiles=tuple(st.profiles),
        tolerances={k: float(v) for k, v in raw["tolerances"].items()},
        limits={k: int(v) for k, v in raw["limits"].items()}, machine=st.machine, checks=tuple(st.checks),
        cut=_plain(raw["cut"]), decisions=st.decisions, errata=errata, history=history, raw=_plain(raw),
    )


def _types_pass(ctx: _Ctx, st: _State) -> None:
    """Each type of `types:` is a type of the registry, with its kind and size."""
    for name, t in st.raw["types"].items():
        node = st.raw["types"][name]
        known = TYPES.get(name)
        if known is None:
            ctx.fail(st.raw["types"], f"type {name} is not in the registry (generator/cbfgen/registry.py); "
                                      f"known: {', '.join(TYPES)}", name)
            continue
        if (t["kind"], t.get("size")) != (known.kind, known.size):
            ctx.fail(node, f"type {name}: kind {t['kind']} size {t.get('size')} contradicts the registry's "
                           f"{known.kind} size {known.size}", "kind")
            continue
        st.types[name] = FieldType(name, known.kind, known.size, str(t["doc"]))


def _versions_pass(ctx: _Ctx, st: _State) -> None:
    raw = st.raw
    for v in raw["versions"]:
        if any(o.id == str(v["id"]) for o in st.versions):
            ctx.fail(v, f"duplicate version id {v['id']!r}", "id")
            continue
        if v["header"] not in raw["headers"]:
            ctx.fail(v, f"version {v['id']}: unknown header layout {v['header']!r}", "header")
        st.versions.append(Version(str(v["id"]), v["major"], v.get("minor"), v["header"], v["clause"], v["writable"],
                                   str(v["doc"]).strip(), v.line, v.get("since")))
    for i, a in enumerate(st.versions):
        for b in st.versions[i + 1:]:
            if a.major == b.major and (a.minor is None or b.minor is None or a.minor == b.minor):
                ctx.at(b.line, f"versions {a.id} and {b.id} both match major {a.major}")
    for key in ("default_version", "fallback_version"):
        if raw[key] not in st.vids:
            ctx.fail(raw, f"{key} {raw[key]!r} is not a version", key)


def _field(ctx: _Ctx, raw: _Map, types: dict[str, FieldType], offset: int, where: str) -> Field | None:
    ptype = types.get(raw["type"])
    if ptype is None:
        ctx.fail(raw, f"{where}: unknown type {raw['type']!r} (not in the spec's types)", "type")
        return None
    count = int(raw.get("count", 1))
    if ptype.size is not None:
        elem = ptype.size
        if "size" in raw and raw["size"] != ptype.size * count:
            ctx.fail(raw, f"{where}: size {raw['size']} contradicts type {ptype.name} x {count}", "size")
    else:
        if "size" not in raw:
            ctx.fail(raw, f"{where}: type {ptype.name} needs a size", "type")
            return None
        if count != 1:
            ctx.fail(raw, f"{where}: type {ptype.name} takes no count", "count")
        elem, count = int(raw["size"]), 1
    if "offset" in raw and raw["offset"] != offset:
        ctx.fail(raw, f"{where}: offset {raw['offset']} but the fields before end at {offset}", "offset")
    if raw.get("text") and ptype.kind != "string":
        ctx.fail(raw, f"{where}: text applies to strings only", "text")
    if "magic" in raw and ptype.kind != "uint":
        ctx.fail(raw, f"{where}: magic needs an unsigned integer type", "magic")
    elif "magic" in raw and raw["magic"] >= 1 << (8 * elem):
        ctx.fail(raw, f"{where}: magic 0x{raw['magic']:X} does not fit {ptype.name}", "magic")
    return Field(
        name=raw["name"], type=ptype.name, kind=ptype.kind, offset=offset, elem_size=elem, count=count,
        doc=str(raw["doc"]).strip(), line=raw.line, clause=raw.get("clause"), unit=raw.get("unit"),
        role=raw.get("role"), magic=raw.get("magic"), checksum=raw.get("checksum"),
        reserved=bool(raw.get("reserved", False)), text=bool(raw.get("text", False)),
        repeat=(int(raw["repeat"]["min"]), int(raw["repeat"]["max"])) if "repeat" in raw else None,
    )


def _repeat(ctx: _Ctx, lay: _Map, name: str, fixed: int, rep: Field, max_nb: int) -> None:
    """A repeated argument group (issue 25, point 3): the last argument, of numbers (what CUT writes
    as n values or vectors), n in [min, max] with n = 0 allowed only beside fixed arguments (a
    record's arguments are never empty of meaning), and the largest nb within limits.max_arg_size."""
    assert rep.repeat is not None
    lo, hi = rep.repeat
    raw_rep = next((a for a in lay["args"] if a["name"] == rep.name), lay)
    if lo > hi:
        ctx.fail(raw_rep, f"{name} argument {rep.name}: repeat min {lo} exceeds max {hi}", "repeat")
    if lo == 0 and fixed == 0:
        ctx.fail(raw_rep, f"{name} argument {rep.name}: repeat min 0 with no fixed argument leaves nb = 0 "
                          f"ambiguous with a command that takes no arguments", "repeat")
    if rep.kind not in NUMERIC_KINDS:
        ctx.fail(raw_rep, f"{name} argument {rep.name}: only numbers repeat (type {rep.type})", "repeat")
    if fixed + rep.size * hi > max_nb:
        ctx.fail(raw_rep, f"{name} argument {rep.name}: {fixed} + {rep.size} x {hi} = {fixed + rep.size * hi} "
                          f"bytes exceeds limits.max_arg_size {max_nb}", "repeat")


def _fields(ctx: _Ctx, raws: _Seq, types: dict[str, FieldType], where: str) -> tuple[tuple[Field, ...], int, bool]:
    """The fields, where they end, and whether every one was understood (else the end is unknown)."""
    out: list[Field] = []
    offset, whole = 0, True
    names: set[str] = set()
    for raw in raws:
        if raw["name"] in names:
            ctx.fail(raw, f"{where}: duplicate field name {raw['name']!r}", "name")
        names.add(raw["name"])
        f = _field(ctx, raw, types, offset, f"{where} field {raw['name']}")
        if f is None:
            whole = False
            continue
        out.append(f)
        offset = f.end
    return tuple(out), offset, whole


_SHARED_ROLES = DERIVED_HEADER_ROLES
_HEADER_ROLES = ("start_pattern", "end_pattern", "version_major", "version_minor", "command_count")


def _headers_pass(ctx: _Ctx, st: _State) -> None:
    """Each header layout tiles its size; all have one size; the shared fields sit in shared places."""
    raw = st.raw
    for hid, h in raw["headers"].items():
        fields, end, whole = _fields(ctx, h["fields"], st.types, f"header {hid}")
        if whole and end != h["size"]:
            ctx.fail(h, f"header {hid} fields tile {end} bytes, declared {h['size']}", "size")
        st.headers[hid] = HeaderLayout(hid, h["size"], h["clause"], str(h["doc"]).strip(), fields, h.line)
    first = next(iter(st.headers.values()))
    for h in st.headers.values():
        if h.size != first.size:
            ctx.fail(raw["headers"][h.id], f"header {h.id} is {h.size} bytes, header {first.id} {first.size}", "size")
        for f in h.fields:
            if f.role == "checksum" and f.checksum not in {x.checksum for x in first.fields}:
                continue  # a checksum field of this layout's own (a new version's): _checksum_fields_pass
            if f.role in _SHARED_ROLES:
                twin = first.field(f.name)
                if twin is None or (twin.offset, twin.type, twin.role, twin.magic, twin.checksum) != (
                        f.offset, f.type, f.role, f.magic, f.checksum):
                    ctx.at(f.line, f"header {h.id} field {f.name} must match header {first.id}")
        for role in _HEADER_ROLES:
            rf = h.by_role(role)
            if rf is None:
                ctx.fail(raw["headers"][h.id], f"header {h.id} has no field with role {role}")
            elif rf.kind != "uint":
                ctx.at(rf.line, f"header {h.id}: the {role} field needs an unsigned integer type")


def _record_pass(ctx: _Ctx, st: _State) -> None:
    raw = st.raw
    r = raw["record"]
    rfields, rend, whole = _fields(ctx, r["fields"], st.types, "record")
    if whole and rend != r["head_size"]:
        ctx.fail(r, f"record head fields tile {rend} bytes, declared {r['head_size']}", "head_size")
    record = RecordLayout(r["head_size"], r["clause"], str(r["doc"]).strip(), rfields)
    missing = False
    for role in ("sequence", "code", "code_copy", "arg_size", "reserved"):
        f = next((x for x in rfields if x.role == role), None)
        if f is None:
            ctx.fail(r, f"record has no field with role {role}")
            missing = True
        elif f.kind != "uint":
            ctx.at(f.line, f"record field {f.name}: role {role} needs an unsigned integer type")
    if not missing and 1 << (8 * record.by_role("arg_size").size) <= raw["limits"]["max_arg_size"]:
        ctx.fail(r, "arg_size field too small for limits.max_arg_size")
    st.record = record


def _commands_pass(ctx: _Ctx, st: _State) -> None:
    raw = st.raw
    names: dict[str, int] = {}
    codes: dict[int, str] = {}
    profile_ids = [q["id"] for q in raw["profiles"]]
    for c in raw["commands"]:
        name, code = c["name"], c["code"]
        if name in names:
            ctx.fail(c, f"duplicate command name {name} (also line {names[name]})", "name")
        if code in codes:
            ctx.fail(c, f"{name}: duplicate code 0x{code:02X}, already {codes[code]}", "code")
        names.setdefault(name, c.line)
        codes.setdefault(code, name)
        layouts: list[Layout] = []
        for i, lay in enumerate(c["layouts"]):
            variant = lay.get("variant", "")
            if i == 0 and variant:
                ctx.fail(lay, f"{name}: the first layout is the primary one and takes no variant", "variant")
            if i > 0 and not variant:
                ctx.fail(lay, f"{name}: layout {i + 1} needs a variant name")
            if any(o.variant == variant for o in layouts):
                ctx.fail(lay, f"{name}: duplicate variant {variant!r}", "variant")
            for v in lay["versions"]:
                if v not in st.vids:
                    ctx.fail(lay, f"{name}: unknown version {v!r}", "versions")
            for p in lay.get("profiles", []):
                if p not in profile_ids:
                    ctx.fail(lay, f"{name}: unknown profile {p!r}", "profiles")
            args, total, whole = _fields(ctx, lay["args"], st.types, f"{name}")
            vtext = "/".join("v" + v for v in lay["versions"])
            rep = args[-1] if args and args[-1].repeat is not None else None
            if whole and rep is not None:
                total -= rep.size  # a repeated group: `size` is the fixed arguments' (issue 25, point 3)
            if whole and total != lay["size"]:
                ctx.fail(lay, f"{name} {vtext} arguments sum to {total} bytes, declared {lay['size']}", "size")
            if rep is not None:
                _repeat(ctx, lay, name, lay["size"], rep, int(raw["limits"]["max_arg_size"]))
            if lay["size"] > raw["limits"]["max_arg_size"]:
                ctx.fail(lay, f"{name}: size {lay['size']} exceeds limits.max_arg_size", "size")
            layouts.append(Layout(name, variant, tuple(str(v) for v in lay["versions"]), lay["size"], args,
                                  tuple(lay.get("profiles", [])), str(lay.get("doc", "")).strip(), lay.get("clause"),
                                  lay.line))
        for v in st.vids:
            sizes = [nb for lay in layouts if v in lay.versions for nb in lay.sizes]
            if len(sizes) != len(set(sizes)):
                ctx.fail(c, f"{name}: two layouts of version {v} have the same size", "layouts")
        cmd = Command(
            name=name, code=code, doc=str(c["doc"]).strip(), clause=c["clause"], layouts=tuple(layouts), line=c.line,
            motion=dict(c["motion"]) if "motion" in c else None,
            orientation=dict(c["orientation"]) if "orientation" in c else None,
            shape=dict(c["shape"]) if "shape" in c else None,
            cutter=dict(c["cutter"]) if "cutter" in c else None,
            sets=dict(c["sets"]) if "sets" in c else None,
            progress=c.get("progress"),
            declared_size=c.get("declared_size"), listed_size=c.get("listed_size"), erratum=c.get("erratum"),
            former_names=tuple(str(x) for x in c.get("former_names", ())),
        )
        for role in ("motion", "orientation", "shape", "cutter"):
            for key, argname in (getattr(cmd, role) or {}).items():
                if key != "kind":
                    _require_arg(ctx, c, cmd, argname, f"{role}.{key}", ROLE_ARGS[role].get(key))
        for key, value in (cmd.sets or {}).items():
            if isinstance(value, str):
                _require_arg(ctx, c, cmd, value, f"sets.{key}", ROLE_ARGS["sets"].get(key))
        if cmd.progress:
            _require_arg(ctx, c, cmd, cmd.progress, "progress", ROLE_ARGS["progress"][""])
        _check_roles(ctx, c, cmd)
        st.commands.append(cmd)


def _checksums_pass(ctx: _Ctx, st: _State) -> None:
    """Algorithms, coverages and the checksum fields; the profiles that choose among them."""
    raw = st.raw
    cs = raw["checksums"]
    first = next(iter(st.headers.values()))
    rfields = st.record.fields if st.record else ()
    algorithms = {k: Algorithm(k, a["kind"], str(a["doc"]).strip()) for k, a in cs["algorithms"].items()}
    coverages: dict[str, Coverage] = {}
    rnames = {f.name for f in rfields}
    for k, cov in cs["coverages"].items():
        segs = []
        for s in cov["segments"]:
            if "fields" in s:  # named fields: resolved per layout by _named_coverage_pass
                segs.append(Segment("fields", fields=tuple(str(n) for n in s["fields"])))
                continue
            seg = Segment(s["region"], s.get("start"), s.get("end"), tuple(s.get("exclude", [])))
            if seg.region == "header" and (seg.start is None or seg.end is None or seg.end > first.size
                                           or seg.start >= seg.end):
                ctx.fail(s, f"coverage {k}: header segment needs 0 <= start < end <= {first.size}")
            if seg.region == "file" and seg.start is None:
                ctx.fail(s, f"coverage {k}: file segment needs a start")
            for ex in seg.exclude:
                if ex not in rnames:
                    ctx.fail(s, f"coverage {k}: unknown record field {ex!r}", "exclude")
            segs.append(seg)
        coverages[k] = Coverage(k, str(cov["doc"]).strip(), tuple(segs))
    # the stored field of each checksum tag: its width bounds the algorithm's result
    widths = {f.checksum: f.size for h in st.headers.values() for f in h.fields if f.checksum}
    widths.update({f.checksum: f.size for f in rfields if f.checksum})
    arg_fields = [a for c in st.commands for lay in c.layouts for a in lay.args if a.checksum]
    widths.update({str(a.checksum): a.size for a in arg_fields if a.checksum not in widths})

    def fits(node: _Map, key: str, tag: str, alg_name: str, what: str) -> None:
        bits = algorithms[alg_name].bits
        if tag in widths and bits is not None and bits > 8 * widths[tag]:
            ctx.fail(node, f"{what}: algorithm {alg_name} gives {bits} bits, the {tag} checksum field "
                           f"holds {8 * widths[tag]}", key)

    cfields: list[ChecksumField] = []
    for f in cs["fields"]:
        ok = True
        if f["algorithm"] not in algorithms:
            ctx.fail(f, f"checksum {f['field']}: unknown algorithm {f['algorithm']!r}", "algorithm")
            ok = False
        if f["coverage"] not in coverages:
            ctx.fail(f, f"checksum {f['field']}: unknown coverage {f['coverage']!r}", "coverage")
        if any(o.field == f["field"] for o in cfields):
            ctx.fail(f, f"checksum {f['field']}: defined twice", "field")
            continue
        if ok:
            fits(f, "algorithm", f["field"], f["algorithm"], f"checksum {f['field']}")
        cfields.append(ChecksumField(f["field"], f["algorithm"], f["coverage"], f["clause"]))
    tags = {f.field for f in cfields}
    for tag in ("args", "header", "file"):
        if tag not in tags:
            ctx.fail(cs, f"checksums: no definition for the {tag} checksum", "fields")
    for hf in [f for h in st.headers.values() for f in h.fields] + arg_fields:
        if hf.checksum and hf.checksum not in tags:
            ctx.at(hf.line, f"field {hf.name}: checksum {hf.checksum} is not defined")
    if sorted(cs["fill_order"]) != sorted(tags):
        ctx.fail(cs, "checksums.fill_order must name every checksum once", "fill_order")
    st.checksums = Checksums(algorithms, coverages, tuple(cfields), tuple(cs["fill_order"]))
    for p in raw["profiles"]:
        for cov_name in list(p["file_coverages"]) + list(p["hint_coverages"]):
            if cov_name not in coverages:
                ctx.fail(p, f"profile {p['id']}: unknown coverage {cov_name!r}")
        if "file_algorithm" in p:
            if p["file_algorithm"] not in algorithms:
                ctx.fail(p, f"profile {p['id']}: unknown algorithm {p['file_algorithm']!r}", "file_algorithm")
            else:
                fits(p, "file_algorithm", "file", p["file_algorithm"], f"profile {p['id']}")
        st.profiles.append(Profile(p["id"], str(p["doc"]).strip(), tuple(p["file_coverages"]),
                                   tuple(p["hint_coverages"]), p.get("file_algorithm")))
    if st.profiles[0].id != "default":
        ctx.fail(raw["profiles"], "the first profile must be 'default'")


def _machine_pass(ctx: _Ctx, st: _State) -> None:
    """The default machine (L1): each limit's unit is a unit of the spec, min <= max, a box has
    one bound per axis."""
    m, units = st.raw["machine"], st.raw["units"]
    limits: list[MachineLimit] = []
    for name, lim in m["limits"].items():
        node = m["limits"][name]
        if lim["unit"] not in units:
            ctx.fail(node, f"machine limit {name}: unknown unit {lim['unit']!r}", "unit")
        axes = tuple(str(a) for a in lim.get("axes", []))
        lo, hi = lim["min"], lim["max"]
        want = len(axes) if axes else None
        shaped = True
        for key, v in (("min", lo), ("max", hi)):
            if (want is None) != (not isinstance(v, list)) or (want is not None and len(v) != want):
                ctx.fail(node, f"machine limit {name}: {key} must be "
                               + (f"a list of {want} numbers (one per axis)" if want else "a number"), key)
                shaped = False
        if not shaped:
            continue
        los = tuple(float(x) for x in (lo if isinstance(lo, list) else [lo]))
        his = tuple(float(x) for x in (hi if isinstance(hi, list) else [hi]))
        if any(a > b for a, b in zip(los, his, strict=True)):
            ctx.fail(node, f"machine limit {name}: min exceeds max", "min")
        limits.append(MachineLimit(str(name), str(lim["unit"]), los, his, axes, str(lim["doc"]).strip()))
    st.machine = Machine(str(m["decision"]), str(m["doc"]).strip(), tuple(limits))
    st.decisions = tuple(Note(d["id"], d["topic"], " ".join(str(d["decision"]).split()), str(d["evidence"]))
                         for d in st.raw["decisions"])
    if st.machine.decision not in {d.id for d in st.decisions}:
        ctx.fail(m, f"machine: unknown decision {st.machine.decision!r}", "decision")


def _checks_pass(ctx: _Ctx, st: _State) -> None:
    """Each check: a known kind with the parameters that kind takes (registry.CHECK_KINDS), and
    nothing a runtime would ignore: ``versions:`` only where every runtime scopes by it."""
    cmd_by_name = {c.name: c for c in st.commands}
    known_notes = {d.id for d in st.decisions}
    seen_kinds: dict[str, Check] = {}
    for ch in st.raw["checks"]:
        cid, kname = str(ch["id"]), ch["kind"]
        ck = CHECK_KINDS[kname]
        if any(o.id == cid for o in st.checks) or cid in st.raw_checks:
            ctx.fail(ch, f"duplicate check id {cid!r}", "id")
            continue
        st.raw_checks[cid] = ch
        for key in ch:
            if key in COMMON_CHECK_KEYS or key in ck.keys:
                continue
            if key == "versions" and ck.kaitai:
                ctx.fail(ch, f"check {cid}: versions on a check of kind {kname}, which the Kaitai parsers state "
                             f"as a valid: rule in every version (a file of another version would pass Python "
                             f"and C and fail Kaitai)", key)
            elif key == "versions":
                ctx.fail(ch, f"check {cid}: versions on a check of kind {kname}, which no runtime scopes by "
                             f"version (only {', '.join(k.name for k in CHECK_KINDS.values() if k.versioned)} does)",
                         key)
            else:
                ctx.fail(ch, f"check {cid}: kind {kname} takes no {key!r} (it takes "
                             f"{', '.join(ck.keys) or 'no parameters'})", key)
        if kname in seen_kinds and not ck.repeatable:
            ctx.fail(ch, f"check {cid}: a second check of kind {kname} (first: {seen_kinds[kname].id}, line "
                         f"{seen_kinds[kname].line}); the kind takes one", "kind")
        targets = _targets(ctx, st, ch, cid, kname, cmd_by_name)
        for v in ch.get("versions", []):
            if v not in st.vids:
                ctx.fail(ch, f"check {cid}: unknown version {v!r}", "versions")
        missing = [k for k in ck.required if not ch.get(k)]
        for k in missing:
            ctx.fail(ch, f"check {cid}: kind {kname} needs {k}", "kind")
        for cname in ch.get("commands", []):
            if cname not in cmd_by_name:
                ctx.fail(ch, f"check {cid}: unknown command {cname}", "commands")
        if kname == "range":
            if ch.get("min") is None and ch.get("max") is None:
                ctx.fail(ch, f"check {cid}: a range check needs min, max or both", "kind")
            elif ch.get("min") is not None and ch.get("max") is not None and ch["min"] > ch["max"]:
                ctx.fail(ch, f"check {cid}: min {ch['min']} exceeds max {ch['max']}", "min")
            elif (ch.get("min") is not None and ch.get("min") == ch.get("max")
                  and (ch.get("min_exclusive") or ch.get("max_exclusive"))):
                ctx.fail(ch, f"check {cid}: an open bound at min = max {ch['min']} leaves no value", "min")
            for b in ("min", "max"):
                if ch.get(f"{b}_exclusive") and ch.get(b) is None:
                    ctx.fail(ch, f"check {cid}: {b}_exclusive without {b}", f"{b}_exclusive")
        if ch.get("decision") and ch["decision"] not in known_notes:
            ctx.fail(ch, f"check {cid}: unknown decision {ch['decision']!r}", "decision")
        if missing:
            continue
        values: dict[str, Any] = {k: ch[k] for k in ck.keys if k in ch}
        if "targets" in ck.keys:
            values["targets"] = tuple(targets)
        for k in ("versions", "commands", "deprecates"):
            if k in values:
                values[k] = tuple(str(x) for x in values[k])
        check = Check(id=cid, kind=kname, severity=ch["severity"], text=str(ch["text"]).strip(),
                      fails=" ".join(str(ch["fails"]).split()), line=ch.line, params=ck.params(**values),
                      clause=ch.get("clause"), decision=ch.get("decision"))
        seen_kinds.setdefault(kname, check)
        st.checks.append(check)


def _targets(ctx: _Ctx, st: _State, ch: _Map, cid: str, kname: str, cmd_by_name: dict[str, Command]) -> list[Target]:
    out: list[Target] = []
    for t in ch.get("targets", []):
        tcmd = cmd_by_name.get(t["command"])
        if tcmd is None:
            ctx.fail(t, f"check {cid}: unknown command {t['command']}", "command")
            continue
        for argname in t["args"]:
            _require_arg(ctx, t, tcmd, argname, f"check {cid}")
            want = CHECK_KINDS[kname].target_shape
            for lay in tcmd.layouts:
                a = lay.arg(argname)
                if a is not None and want is not None and not role_arg_fits(want, TYPES[a.type], a.count):
                    ctx.fail(t, f"check {cid}: {tcmd.name}.{argname} is {a.type} x{a.count}; kind {kname} reads "
                                + ("one float" if want[1] == 1 else f"vectors of {want[1]} floats"), "args")
                    break
        if ("limit" in t) != (kname == "machine_limits"):
            ctx.fail(t, f"check {cid}: a target names a limit exactly when its kind is machine_limits",
                     "limit" if "limit" in t else "command")
        elif "limit" in t and st.machine is not None:
            _machine_target(ctx, t, tcmd, st.machine, cid)
        out.append(Target(t["command"], tuple(t["args"]), t.get("limit")))
    return out


def _availability_pass(ctx: _Ctx, st: _State) -> None:
    """Every (version, command) pair where the command has no layout is covered by exactly one
    availability check, and a check covers only such pairs: its findings name the right clause."""
    covered: dict[tuple[str, str], Check] = {}
    by_name = {c.name: c for c in st.commands}
    for ch in st.checks:
        if not CHECK_KINDS[ch.kind].gates:
            continue
        node = st.raw_checks[ch.id]
        for v in ch.versions:
            for name in ch.commands:
                cmd = by_name.get(name)
                if cmd is None:
                    continue
                if cmd.available_in(v):
                    ctx.fail(node, f"check {ch.id}: {name} has a layout in version {v}, nothing to cover", "commands")
                    continue
                other = covered.get((v, name))
                if other is not None:
                    ctx.fail(node, f"check {ch.id}: {name} in version {v} is already covered by check "
                                   f"{other.id} (line {other.line}); one check per command and version", "commands")
                covered[(v, name)] = ch
    for cmd in st.commands:
        if not any(cmd.available_in(v) for v in st.vids):
            ctx.at(cmd.line, f"{cmd.name} is available in no version")
            continue
        for v in st.vids:
            if not cmd.available_in(v) and (v, cmd.name) not in covered:
                ctx.at(cmd.line, f"{cmd.name} has no layout in version {v} and no availability check covers it "
                                 f"(name it in a check's commands)")
    _check_machine_coverage(ctx, st)


def _checksum_fields_pass(ctx: _Ctx, st: _State) -> None:
    """Checksum fields as data: a tag may sit in any header layout (a new version's header turns
    reserved bytes into one); each tag has one width; every header checksum field but the file
    checksum is judged by exactly one header_checksum check (its `field`), over header bytes only
    (the header is judged before the records are framed)."""
    if st.record is None or st.checksums is None:
        return
    defined = {f.field: f for f in st.checksums.fields}
    width: dict[str, Field] = {}
    for h in st.headers.values():
        for f in h.fields:
            if not f.checksum:
                continue
            if f.role != "checksum" or f.kind != "uint":
                ctx.at(f.line, f"header {h.id} field {f.name}: a checksum field needs role checksum and an "
                               f"unsigned integer type")
            first = width.setdefault(f.checksum, f)
            if first.size != f.size:
                ctx.at(f.line, f"header {h.id} field {f.name}: checksum {f.checksum} is {f.size} bytes here, "
                               f"{first.size} at line {first.line}")
    record_tags = {f.checksum for f in st.record.fields if f.checksum}
    judged: dict[str, Check] = {}
    for ch in st.checks:
        if ch.kind != "header_checksum":
            continue
        tag = ch.checksum_field or "header"
        if tag not in width or tag in record_tags or tag == "file":
            ctx.at(ch.line, f"check {ch.id}: field {tag} is no header checksum field (a tag of a header "
                            f"field, other than the file checksum)")
            continue
        if tag in judged:
            ctx.at(ch.line, f"check {ch.id}: checksum {tag} is judged by check {judged[tag].id} already")
        judged.setdefault(tag, ch)
        cov = st.checksums.coverages.get(defined[tag].coverage) if tag in defined else None
        if cov is not None and any(seg.region != "header" for seg in cov.segments):
            ctx.at(ch.line, f"check {ch.id}: checksum {tag} covers more than header bytes (coverage "
                            f"{cov.name}); a header_checksum check judges header bytes only")
    for tag, f in width.items():
        if tag != "file" and tag not in judged:
            ctx.at(f.line, f"field {f.name}: no header_checksum check judges checksum {tag} (every binding "
                           f"would read it and none check it)")


def _named_coverage_pass(ctx: _Ctx, st: _State) -> None:
    """Checksum fields among command arguments and coverage by named fields (issue 25, point 1).

    An argument with ``checksum: TAG`` is a checksum field: role checksum, one unsigned integer,
    one width for its tag, a tag no header or record head field uses, in a layout of fixed size,
    and a coverage made of named fields only. A ``fields`` segment names fields of the checksum's
    own place: for an argument's checksum, arguments of its layout or record head fields (resolved
    per layout to byte ranges of the record); for a header checksum, fields of each header layout
    that carries it (resolved to header segments, the same bytes in every such layout). A name a
    layout lacks, a field covering itself, and a named coverage that serves another checksum or a
    profile are refused."""
    if st.record is None or st.checksums is None:
        return
    cs, raw_cov = st.checksums, st.raw["checksums"]["coverages"]
    defined = {f.field: f for f in cs.fields}
    head_tags = {f.checksum for f in st.record.fields if f.checksum}
    header_tags = {f.checksum for h in st.headers.values() for f in h.fields if f.checksum}
    head = {f.name: f for f in st.record.fields}
    hs = st.record.head_size
    named = {k for k, cov in cs.coverages.items() if any(seg.region == "fields" for seg in cov.segments)}
    users: dict[str, list[str]] = {}
    for f in cs.fields:
        users.setdefault(f.coverage, []).append(f.field)
    for p in st.profiles:
        for k in (*p.file_coverages, *p.hint_coverages):
            users.setdefault(k, []).append(f"profile {p.id}")
    for k in sorted(named):
        if len(users.get(k, [])) > 1 or any(u in head_tags for u in users.get(k, [])):
            ctx.fail(raw_cov[k], f"coverage {k}: a coverage by named fields serves one header or argument checksum "
                                 f"field (used by {', '.join(users[k])})", "segments")

    def seg_node(cov: str) -> Any:
        return next((s for s in raw_cov[cov]["segments"] if "fields" in s), raw_cov[cov])

    arg_first: dict[str, Field] = {}
    commands: list[Command] = []
    for cmd in st.commands:
        layouts: list[Layout] = []
        for lay in cmd.layouts:
            found: list[ArgChecksum] = []
            for a in lay.args:
                if a.role == "checksum" and not a.checksum:
                    ctx.at(a.line, f"{cmd.name} argument {a.name}: role checksum needs a checksum tag (`checksum:`)")
                if not a.checksum:
                    continue
                if a.role != "checksum" or a.kind != "uint" or a.count != 1:
                    ctx.at(a.line, f"{cmd.name} argument {a.name}: a checksum field needs role checksum and one "
                                   f"unsigned integer")
                    continue
                if a.checksum in head_tags or a.checksum in header_tags:
                    ctx.at(a.line, f"{cmd.name} argument {a.name}: checksum {a.checksum} is the tag of a header or "
                                   f"record head field")
                    continue
                if lay.repeated is not None:
                    ctx.at(a.line, f"{cmd.name} argument {a.name}: a checksum field in a layout with a repeated "
                                   f"group (its coverage would move with n) is not supported")
                    continue
                first = arg_first.setdefault(a.checksum, a)
                if first.size != a.size:
                    ctx.at(a.line, f"{cmd.name} argument {a.name}: checksum {a.checksum} is {a.size} bytes here, "
                                   f"{first.size} at line {first.line}")
                cf = defined.get(a.checksum)
                cov = cs.coverages.get(cf.coverage) if cf is not None else None
                if cf is None or cov is None:
                    continue  # _checksums_pass said so
                if any(seg.region != "fields" for seg in cov.segments):
                    ctx.at(a.line, f"{cmd.name} argument {a.name}: checksum {a.checksum} has coverage {cov.name}, "
                                   f"not made of named fields (an argument's checksum covers named fields of its "
                                   f"record)")
                    continue
                names: list[str] = []
                ranges: list[tuple[int, int]] = []
                for seg in cov.segments:
                    for n in seg.fields:
                        arg, hf = lay.arg(n), head.get(n)
                        if arg is not None and hf is not None:
                            ctx.fail(seg_node(cov.name), f"coverage {cov.name}: {n} names both an argument of "
                                                         f"{cmd.name} and a record head field", "fields")
                        elif arg is None and hf is None:
                            ctx.fail(seg_node(cov.name), f"coverage {cov.name}: {cmd.name} {'/'.join(lay.versions)} "
                                                         f"has no argument or record head field {n}", "fields")
                        else:
                            got = (hs + arg.offset, hs + arg.end) if arg is not None else (hf.offset, hf.end)  # type: ignore[union-attr]
                            names.append(n)
                            ranges.append(got)
                own = (hs + a.offset, hs + a.end)
                if any(lo < own[1] and own[0] < hi for lo, hi in ranges):
                    ctx.fail(seg_node(cov.name), f"coverage {cov.name}: checksum {a.checksum} covers itself "
                                                 f"({cmd.name} argument {a.name})", "fields")
                found.append(ArgChecksum(a.checksum, a, cf.algorithm, tuple(names), tuple(ranges)))
            layouts.append(replace(lay, checksums=tuple(found)))
        commands.append(replace(cmd, layouts=tuple(layouts)))
    st.commands[:] = commands
    # header checksums: named fields become header segments, the same bytes in every layout
    coverages = dict(cs.coverages)
    for f in cs.fields:
        cov = cs.coverages.get(f.coverage)
        if cov is None or cov.name not in named or f.field in head_tags or f.field in arg_first:
            continue
        if f.field not in header_tags:
            continue  # no field carries it: the checks of _checksum_fields_pass say so
        resolved: dict[str, tuple[Segment, ...]] = {}
        for h in st.headers.values():
            holder = next((x for x in h.fields if x.checksum == f.field), None)
            if holder is None:
                continue
            segs: list[Segment] = []
            for seg in cov.segments:
                if seg.region != "fields":
                    segs.append(seg)
                    continue
                for n in seg.fields:
                    hf = h.field(n)
                    if hf is None:
                        ctx.fail(seg_node(cov.name), f"coverage {cov.name}: header {h.id} has no field {n}", "fields")
                        continue
                    if hf.offset < holder.end and holder.offset < hf.end:
                        ctx.fail(seg_node(cov.name), f"coverage {cov.name}: checksum {f.field} covers itself "
                                                     f"(header {h.id} field {n})", "fields")
                    segs.append(Segment("header", hf.offset, hf.end, fields=(n,)))
            resolved[h.id] = tuple(segs)
        spans = {hid: tuple((x.start, x.end) for x in v) for hid, v in resolved.items()}
        other = next((hid for hid in spans if spans[hid] != next(iter(spans.values()))), None)
        if other is not None:
            ctx.fail(seg_node(cov.name), f"coverage {cov.name}: its named fields sit at other bytes in header "
                                         f"{next(iter(spans))} than in header {other} (a header checksum covers the "
                                         f"same bytes in every header that carries it)", "fields")
        elif resolved:
            coverages[cov.name] = replace(cov, segments=next(iter(resolved.values())))
    st.checksums = replace(cs, coverages=coverages)


def _arg_checksum_checks_pass(ctx: _Ctx, st: _State) -> None:
    """Every checksum field among command arguments is judged by exactly one arg_checksum check
    (its ``field``); an arg_checksum check names a record checksum field (the head's or an argument's)."""
    if st.record is None:
        return
    head_tags = {f.checksum for f in st.record.fields if f.checksum}
    arg_tags = {ck.tag: ck.field for c in st.commands for lay in c.layouts for ck in lay.checksums}
    judged: dict[str, Check] = {}
    for ch in st.checks:
        if ch.kind != "arg_checksum":
            continue
        tag = ch.checksum_field or "args"
        if tag not in head_tags and tag not in arg_tags:
            ctx.at(ch.line, f"check {ch.id}: field {tag} is no record checksum field (the record head's, or a "
                            f"checksum among a command's arguments)")
            continue
        if tag in arg_tags and tag in judged:
            ctx.at(ch.line, f"check {ch.id}: checksum {tag} is judged by check {judged[tag].id} already")
        judged.setdefault(tag, ch)
    for tag, f in arg_tags.items():
        if tag not in judged:
            ctx.at(f.line, f"argument {f.name}: no arg_checksum check judges checksum {tag} (every binding would "
                           f"read it and none check it)")


def _fill_order_pass(ctx: _Ctx, st: _State) -> None:
    """A writer fills the checksums in fill_order: a checksum that covers another checksum's stored
    bytes comes after it, and no checksum covers its own. Header byte ranges, the file region and
    the records region (less the head fields it excludes) and the args region are followed as
    each binding computes them, with each profile's file coverages for the file checksum."""
    if st.record is None or st.checksums is None:
        return
    cs, raw_cs = st.checksums, st.raw["checksums"]
    order = list(cs.fill_order)
    if sorted(order) != sorted(f.field for f in cs.fields):
        return  # _checksums_pass said so
    head = [f for f in st.record.fields if f.checksum]
    arg_tags = {ck.tag for c in st.commands for lay in c.layouts for ck in lay.checksums}
    covers: dict[str, set[str]] = {f.field: set() for f in cs.fields}

    def by_coverage(tag: str, cov: Coverage) -> None:
        for seg in cov.segments:
            if seg.region == "header" and seg.start is not None and seg.end is not None:
                for h in st.headers.values():
                    covers[tag].update(x.checksum for x in h.fields
                                       if x.checksum and x.offset < seg.end and seg.start < x.end)
            elif seg.region == "file" and seg.start is not None:
                for h in st.headers.values():
                    covers[tag].update(x.checksum for x in h.fields if x.checksum and x.end > seg.start)
                covers[tag].update(x.checksum for x in head if x.checksum)
                covers[tag].update(arg_tags)
            elif seg.region == "records":
                covers[tag].update(x.checksum for x in head if x.checksum and x.name not in seg.exclude)
                covers[tag].update(arg_tags)
            elif seg.region == "args":
                covers[tag].update(arg_tags)

    for f in cs.fields:
        if f.coverage in cs.coverages:
            by_coverage(f.field, cs.coverages[f.coverage])
        if f.field == "file":
            for p in st.profiles:
                for k in p.file_coverages:
                    if k in cs.coverages:
                        by_coverage("file", cs.coverages[k])
    hs = st.record.head_size
    for c in st.commands:
        for lay in c.layouts:
            for ck in lay.checksums:
                for lo, hi in ck.ranges:
                    covers[ck.tag].update(x.checksum for x in head if x.checksum and x.offset < hi and lo < x.end)
                    covers[ck.tag].update(o.tag for o in lay.checksums
                                          if hs + o.field.offset < hi and lo < hs + o.field.end)
    covers = {t: {x for x in got if x is not None} for t, got in covers.items()}
    for tag in order:
        if tag in covers[tag]:
            node = next((x for x in raw_cs["fields"] if x["field"] == tag), raw_cs)
            ctx.fail(node, f"checksum {tag} covers its own stored bytes", "coverage")
        for other in sorted(covers[tag] - {tag}):
            if other not in covers:
                continue
            if tag in covers[other]:
                if order.index(tag) < order.index(other):
                    ctx.fail(raw_cs, f"checksums {tag} and {other} cover each other: no fill order computes both",
                             "fill_order")
            elif order.index(other) > order.index(tag):
                ctx.fail(raw_cs, f"checksums.fill_order: {tag} covers {other}, so {other} must be filled before it",
                         "fill_order")


def _capabilities_pass(ctx: _Ctx, st: _State) -> None:
    """What every binding can implement: each field's type in each binding (registry.unsupported),
    and a header every reader can pick a layout for: Kaitai reads the version in the fields all
    header layouts share from offset 0 (its `header` type) before it switches to a layout."""
    fields = [f for h in st.headers.values() for f in h.fields]
    fields += list(st.record.fields if st.record else ())
    fields += [a for c in st.commands for lay in c.layouts for a in lay.args]
    for f in fields:
        gaps = unsupported(TYPES[f.type], f.count)
        if gaps:
            what = f"{f.type} x {f.count}" if f.count != 1 else f.type
            ctx.at(f.line, f"field {f.name}: type {what} is not implemented by the "
                           f"{', '.join(gaps)} binding{'s' if len(gaps) > 1 else ''} (generator/cbfgen/registry.py)")
    for f in [f for h in st.headers.values() for f in h.fields] + list(st.record.fields if st.record else ()):
        head_gaps = unsupported_in_head(TYPES[f.type])
        if head_gaps:
            ctx.at(f.line, f"field {f.name}: type {f.type} in a header or record head is not implemented by the "
                           f"{', '.join(head_gaps)} binding (it reads those fields unsigned, at most 4 bytes; "
                           f"generator/cbfgen/registry.py)")
    # The version fields sit in the same place in every header layout (_headers_pass, _SHARED_ROLES):
    # Kaitai reads them by position when the layouts diverge before them (emit/kaitai).


def _names_pass(ctx: _Ctx, st: _State) -> None:
    """Names every binding can use as identifiers, as the spec spells them: a command, argument or
    field name reserved in a binding's language (escape.keyword_clash) is refused, never renamed."""
    named: list[tuple[str, int, str, str]] = [(c.name, c.line, "command name", "command") for c in st.commands]
    named += [(a.name, a.line, f"{c.name} argument", "field")
              for c in st.commands for lay in c.layouts for a in lay.args]
    named += [(f.name, f.line, f"header {h.id} field", "field") for h in st.headers.values() for f in h.fields]
    named += [(f.name, f.line, "record field", "field") for f in (st.record.fields if st.record else ())]
    seen: set[tuple[str, int]] = set()
    for name, line, what, kind in named:
        why = keyword_clash(name, what=kind)
        if why and (name, line) not in seen:
            seen.add((name, line))
            ctx.at(line, f"{what}: the name {why}")
    own = [(f, "header", f"header {h.id} field") for h in st.headers.values() for f in h.fields]
    own += [(f, "record", "record field") for f in (st.record.fields if st.record else ())]
    for f, part, what in own:
        if f.name in GENERATED_NAMES[part]:
            ctx.at(f.line, f"{what} {f.name}: the generated code names a member of the {part} so "
                           f"({', '.join(GENERATED_NAMES[part])} are taken)")


def _former_names_pass(ctx: _Ctx, st: _State) -> None:
    """A command's former names (issue 25, point 6) name it alone: no command's current name, no
    other former name, and a name every binding can use (they become aliases)."""
    owner: dict[str, Command] = {c.name: c for c in st.commands}
    raw = {str(x["name"]): x for x in st.raw["commands"]}
    for c in st.commands:
        for old in c.former_names:
            other = owner.get(old)
            why = keyword_clash(old, what="command")
            if other is not None:
                what = "its own name" if other is c else f"already a name of {other.name} (line {other.line})"
                ctx.fail(raw[c.name], f"{c.name}: former name {old} is {what}", "former_names")
            elif why:
                ctx.fail(raw[c.name], f"{c.name}: former name {old}: the name {why}", "former_names")
            owner.setdefault(old, c)


def _deprecations_pass(ctx: _Ctx, st: _State) -> None:
    """Each deprecation (kind deprecated, issue 25 point 5): a known version ``since``, whose
    ``versions`` become it and every version after it in the spec's list; each command or
    NAME/variant layout it names exists, has a layout in one of those versions, and is deprecated
    by no other check."""
    by_name = {c.name: c for c in st.commands}
    seen: dict[tuple[str, str], Check] = {}
    for i, ch in enumerate(st.checks):
        if not isinstance(ch.params, DeprecatedParams):
            continue
        node = st.raw_checks[ch.id]
        if "versions" in node:
            ctx.fail(node, f"check {ch.id}: a deprecation gives since, not versions", "versions")
            continue
        if ch.params.since not in st.vids:
            ctx.fail(node, f"check {ch.id}: unknown version {ch.params.since!r}", "since")
            continue
        versions = tuple(st.vids[st.vids.index(ch.params.since):])
        for item in ch.params.deprecates:
            name, _, variant = item.partition("/")
            cmd = by_name.get(name)
            lays = [] if cmd is None else [lay for lay in cmd.layouts if not variant or lay.variant == variant]
            if not lays:
                ctx.fail(node, f"check {ch.id}: deprecates {item}, which names no command or layout", "deprecates")
                continue
            if not any(v in lay.versions for lay in lays for v in versions):
                ctx.fail(node, f"check {ch.id}: {item} has no layout in {', '.join(versions)}, nothing to deprecate",
                         "deprecates")
            for lay in lays:
                other = seen.get((name, lay.variant))
                if other is not None:
                    ctx.fail(node, f"check {ch.id}: {name} layout {lay.variant or 'primary'} is already deprecated "
                                   f"by check {other.id} (line {other.line})", "deprecates")
                seen[(name, lay.variant)] = ch
        st.checks[i] = replace(ch, params=replace(ch.params, versions=versions))


def _repeat_pass(ctx: _Ctx, st: _State) -> None:
    """Repeated argument groups (issue 25, point 3): only the last argument of a command layout
    repeats; a role reads one value, so only a point motion's end may name a group (its last
    element: where a polyline leaves the tool); and every binding must carry groups."""
    for h in st.headers.values():
        for f in h.fields:
            if f.repeat is not None:
                ctx.at(f.line, f"header {h.id} field {f.name}: only a command's arguments repeat")
    for f in st.record.fields if st.record else ():
        if f.repeat is not None:
            ctx.at(f.line, f"record field {f.name}: only a command's arguments repeat")
    gaps = repeat_unsupported()
    for cmd in st.commands:
        roles = [(f"{role}.{key}", arg) for role in ("motion", "orientation", "shape", "cutter")
                 for key, arg in (getattr(cmd, role) or {}).items() if key != "kind"]
        roles += [(f"sets.{key}", arg) for key, arg in (cmd.sets or {}).items() if isinstance(arg, str)]
        roles += [("progress", cmd.progress)] if cmd.progress else []
        for lay in cmd.layouts:
            for a in lay.args[:-1]:
                if a.repeat is not None:
                    ctx.at(a.line, f"{cmd.name} argument {a.name}: only the last argument of a layout repeats")
            rep = lay.repeated
            if rep is None:
                continue
            if gaps:
                ctx.at(rep.line, f"{cmd.name} argument {rep.name}: a repeated argument group is not implemented by "
                                 f"the binding(s) {', '.join(gaps)} (generator/cbfgen/registry.py REPEAT_BINDINGS)")
            for what, arg in roles:
                point_end = what == "motion.end" and (cmd.motion or {}).get("kind") == "point"
                if arg == rep.name and not point_end:
                    ctx.at(rep.line, f"{cmd.name}: {what} names the repeated argument {rep.name} (only a point "
                                     f"motion's end may: the group's last element)")
    # a check's target may be a group only where its kind judges items (registry CheckKind.items)
    groups = {(cmd.name, lay.repeated.name) for cmd in st.commands for lay in cmd.layouts if lay.repeated is not None}
    for ch in st.checks:
        if CHECK_KINDS[ch.kind].items:
            continue
        for t in ch.targets:
            for arg_name in t.args:
                if (t.command, arg_name) in groups:
                    judges = ", ".join(k.name for k in CHECK_KINDS.values() if k.items)
                    ctx.at(ch.line, f"check {ch.id}: kind {ch.kind} targets the repeated argument group "
                                    f"{t.command} {arg_name}; only {judges} judges a group, item by item")


PASSES: tuple[Callable[[_Ctx, _State], None], ...] = (
    _types_pass, _versions_pass, _headers_pass, _record_pass, _commands_pass, _checksums_pass, _machine_pass,
    _checks_pass, _named_coverage_pass, _checksum_fields_pass, _arg_checksum_checks_pass, _fill_order_pass,
    _deprecations_pass, _availability_pass, _capabilities_pass, _names_pass,
    _former_names_pass, _repeat_pass,
)


def _machine_target(ctx: _Ctx, t: _Map, cmd: Command, machine: Machine, cid: str) -> None:
    """A machine_limits target: its limit exists, and every layout's argument of that name has the
    limit's unit and shape (a box bounds float vectors of as many components as it has axes)."""
    try:
        lim = machine.limit(str(t["limit"]))
    except KeyError:
        ctx.fail(t, f"check {cid}: unknown machine limit {t['limit']!r}", "limit")
        return
    for lay in cmd.layouts:
        for name in t["args"]:
            a = lay.arg(name)
            if a is None:
                continue
            shape_ok = a.kind == "float" and a.count == (len(lim.axes) if lim.axes else 1)
            if a.unit != lim.unit or not shape_ok:
                ctx.fail(t, f"check {cid}: {cmd.name}.{name} ({a.type} x{a.count}, unit {a.unit}) does not "
                            f"fit machine limit {lim.name} (unit {lim.unit}"
                            + (f", {len(lim.axes)} axes)" if lim.axes else ", a scalar)"), "args")
                return


def _check_machine_coverage(ctx: _Ctx, st: _State) -> None:
    """Which arguments are positions comes from the model: every float vector argument whose unit is a
    box limit's unit (mm: points, starts, ends, centres) is targeted by that limit."""
    machine = st.machine
    if machine is None or not any(ch.kind == "machine_limits" for ch in st.checks):
        return
    names = {lim.name for lim in machine.limits}
    covered = {(t.command, a) for ch in st.checks if ch.kind == "machine_limits" for t in ch.targets
               if t.limit in names and machine.limit(t.limit).is_vector for a in t.args}
    for lim in machine.limits:
        if not lim.is_vector:
            continue
        for cmd in st.commands:
            for lay in cmd.layouts:
                for a in lay.args:
                    if a.kind == "float" and a.count == len(lim.axes) and a.unit == lim.unit \
                            and (cmd.name, a.name) not in covered:
                        ctx.at(lay.line, f"{cmd.name}.{a.name} is a position ({a.count} x {a.unit}) that no "
                                         f"machine_limits target bounds by limit {lim.name}")


def _require_arg(ctx: _Ctx, node: Any, cmd: Command, argname: str, what: str, want: RoleArg | None = None) -> None:
    """An argument a role or a check names: some layout has it, and (``want``) each layout that has it
    gives it the shape the role reads (registry.ROLE_ARGS)."""
    args = [a for lay in cmd.layouts if (a := lay.arg(argname)) is not None]
    if not args:
        ctx.fail(node, f"{cmd.name}: {what} names {argname!r}, which no layout has")
    for a in args:
        if want is not None and not role_arg_fits(want, TYPES[a.type], a.count):
            shape = {"float": "a float" if want[1] == 1 else f"a vector of {want[1]} floats", "string": "a string",
                     "integer": "an integer"}[want[0]]
            ctx.at(a.line, f"{cmd.name}: {what} names {argname} ({a.type} x{a.count}), which must be {shape}")
            break


def _check_roles(ctx: _Ctx, node: Any, cmd: Command) -> None:
    """Each kinded role names every key its kind needs (registry.ROLE_NEEDS, the one list)."""
    for role, needs in ROLE_NEEDS.items():
        value: dict[str, str] | None = getattr(cmd, role)
        if not value:
            continue
        for key in needs[value["kind"]]:
            if key not in value:
                ctx.fail(node, f"{cmd.name}: {role} kind {value['kind']} needs {key}", role)


def _plain(x: Any) -> Any:
    if isinstance(x, dict):
        return {k: _plain(v) for k, v in x.items()}
    if isinstance(x, list):
        return [_plain(v) for v in x]
    return x
