"""Kaitai Struct emitter: generated/kaitai/cbf.ksy from the spec model.

What Kaitai can express becomes `valid:` (magic numbers, the code copy, the
argument size per command and version, version gating); the rest (sums,
continuity, shapes, ranges) is said in the `doc`. The parsers compiled by
kaitai-struct-compiler (`make generate-ksc`) live beside the .ksy.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import yaml

from ... import __license__ as TOOLKIT_LICENSE
from ... import __version__ as TOOLKIT_VERSION
from ...escape import kaitai_doc
from ...model import Command, Field, Layout, Spec, camel, common_header_prefix, ident
from ...registry import CHECK_KINDS
from ...render import environment

HERE = Path(__file__).parent

OUT = "kaitai"
# Produced by ksc after the Python emitters (mk/kaitai.mk); not stale.
# The Go parser is the module GO_MODULE (package cbf), requiring the Kaitai Go runtime. The
# pinned versions and their checksums (go.sum beside this file) are dependency facts, not format facts.
GO_MODULE = "cbf-kaitai"
GO_REQUIRES = ("github.com/kaitai-io/kaitai_struct_go_runtime v0.11.0", "golang.org/x/text v0.28.0 // indirect")
# The Java parser is the Maven artifact JAVA_GROUP:JAVA_ARTIFACT (the toolkit version), its class
# in JAVA_PACKAGE (ksc's --java-package, done by ksc_driver.js from ksc-options.json), built for
# Java JAVA_RELEASE. The runtime and the Maven plugins are pinned in the pom (dependency facts).
JAVA_GROUP = "com.thinksurgical.cbf"
JAVA_ARTIFACT = "cbf-kaitai"
JAVA_PACKAGE = "com.thinksurgical.cbf.kaitai"
JAVA_RELEASE = 11
JAVA_RUNTIME = ("io.kaitai", "kaitai-struct-runtime", "0.11")
MAVEN_PLUGINS = (
    ("maven-resources-plugin", "3.3.1"),
    ("maven-compiler-plugin", "3.13.0"),
    ("maven-jar-plugin", "3.4.2"),
    ("maven-install-plugin", "3.1.3"),
    ("maven-surefire-plugin", "3.5.2"),
    ("maven-dependency-plugin", "3.8.1"),
)
JAVA_SOURCE = "kaitai/java/src/main/java/" + JAVA_PACKAGE.replace(".", "/") + "/"
# ksc's output, and Maven's target/ if a user builds the parser in place.
KEEP = ("kaitai/python/cbf_kaitai/cbf.py", "kaitai/javascript/Cbf.js", JAVA_SOURCE + "Cbf.java", "kaitai/go/cbf.go",
        "kaitai/java/target/")


def _doc(text: str) -> str:
    return " ".join(text.split())


def _layout_type(lay: Layout) -> str:
    return "args_" + ident(lay.command) + (("_" + ident(lay.variant)) if lay.variant else "")


def _group_size_cond(lay: Layout) -> str:
    """The nb a layout with a repeated group takes, as a Kaitai expression on `_`."""
    rep = lay.repeated
    assert rep is not None and rep.repeat is not None
    lo, hi = lay.size + rep.size * rep.repeat[0], lay.size + rep.size * rep.repeat[1]
    return f"(_ >= {lo} and _ <= {hi} and (_ - {lay.size}) % {rep.size} == 0)"


def _group_attr(lay: Layout, attr: dict[str, Any]) -> dict[str, Any]:
    """A repeated group (issue 25, point 3) as `repeat: expr`: its n items' elements, one after
    another, n computed from nb (the argument substream's size): (nb - size) / k items."""
    rep = lay.repeated
    assert rep is not None
    per = f" * {rep.count}" if rep.count > 1 else ""
    return {**attr, "repeat": "expr", "repeat-expr": f"(_io.size - {lay.size}) / {rep.size}{per}",
            "doc": attr["doc"] + f" A repeated group: (nb - {lay.size}) / {rep.size} items"
                   + (f" of {rep.count} elements each, one after another." if rep.count > 1 else ".")}


def _field_attr(f: Field, encoding: str, clause: str | None, revision: str) -> dict[str, Any]:
    attr: dict[str, Any] = {"id": f.name}
    if f.ftype.kaitai is not None:  # every fixed-size type of the registry: u1..u8, s1..s8, f4, f8
        attr["type"] = f.ftype.kaitai
        if f.count > 1:
            attr["repeat"] = "expr"
            attr["repeat-expr"] = f.count
    elif f.kind == "string":
        attr.update({"type": "str", "size": f.size, "encoding": encoding, "pad-right": 0})
    else:
        attr["size"] = f.size
    if f.magic is not None:
        attr["valid"] = f"0x{f.magic:0{2 * f.size}x}"
    doc = f.doc + (f" [{f.unit}]" if f.unit else "")
    attr["doc"] = _doc(doc)
    ref = f.clause or clause
    if ref:
        attr["doc-ref"] = f"{revision}, {ref}"
    return attr


def _version_index(spec: Spec) -> str:
    """Kaitai expression: 1-based index of the version entry the header matches (fallback otherwise)."""
    fallback = [v.id for v in spec.versions].index(spec.fallback_version) + 1
    expr = str(fallback)
    for i, v in reversed(list(enumerate(spec.versions, 1))):
        major, minor = (spec.common_header_field(r).name for r in ("version_major", "version_minor"))
        cond = f"{major} == {v.major}" + (f" and {minor} == {v.minor}" if v.minor is not None else "")
        expr = f"({cond} ? {i} : {expr})"
    return expr


def _candidates(spec: Spec, cmd: Command, vid: str) -> tuple[Layout, ...]:
    own = cmd.layouts_for(vid)
    return own if own else cmd.layouts


ENCODING = "ISO-8859-1"  # strings are ASCII (N4); bytes map 1:1 so that nothing is lost


def _header_types(spec: Spec) -> dict[str, Any]:
    """The header type and one type per header layout. The fields every layout shares from offset 0
    (the loader makes sure the version fields are among them: version_index reads them), then the
    rest per layout."""
    vids = [v.id for v in spec.versions]
    first = next(iter(spec.headers.values()))
    common: list[Field] = list(common_header_prefix(tuple(spec.headers.values())))
    common_names = {f.name for f in common}
    header_type: dict[str, Any] = {
        "doc": f"File header ({first.clause}); after the version field its layout depends on the version.",
        "seq": [_field_attr(f, ENCODING, first.clause, spec.revision) for f in common] + [{
            "id": "layout",
            "type": {"switch-on": "version_index",
                     "cases": {i: f"header_{ident(spec.version(v).header)}" for i, v in enumerate(vids, 1)}},
            "doc": "The rest of the header, laid out as the version says (7.1).",
        }],
        "instances": {"version_index": {
            "value": _version_index(spec),
            "doc": "1-based index of the spec's version entry ("
                   + ", ".join(f"{i} = {v}" for i, v in enumerate(vids, 1))
                   + f"); unknown versions read as {spec.fallback_version}.",
        }},
    }
    # Layouts that diverge before the version fields (a new version's checksum field in reserved
    # bytes): the version is read where every layout has it (the loader makes sure), by position.
    for role in ("version_major", "version_minor"):
        vf = spec.common_header_field(role)
        if vf.name not in common_names:
            attr = _field_attr(vf, ENCODING, first.clause, spec.revision)
            del attr["id"]
            header_type["instances"][vf.name] = {"pos": vf.offset, **attr}
    types: dict[str, Any] = {"header": header_type}
    for hid, h in spec.headers.items():
        types[f"header_{ident(hid)}"] = {
            "doc": _doc(h.doc),
            "seq": [_field_attr(f, ENCODING, h.clause, spec.revision) for f in h.fields if f.name not in common_names],
        }
    return types


def _size_condition(spec: Spec, cmd: Command, i: int, vid: str) -> str:
    """The argument sizes a record of ``cmd`` may have in files of version ``vid`` (index i)."""
    cands = _candidates(spec, cmd, vid)
    sizes = sorted({lay.size for lay in cands if lay.repeated is None})
    # a repeated group (issue 25, point 3): every nb = size + k n, n in min..max
    groups = sorted({_group_size_cond(lay) for lay in cands if lay.repeated is not None})
    return f"(_root.header.version_index == {i} and (" + " or ".join([*(f"_ == {s}" for s in sizes), *groups]) + "))"


def _size_expr(spec: Spec, code_name: str) -> str:
    """The arg_size field's valid: expression: per command code, the sizes of each version."""
    vids = [v.id for v in spec.versions]
    cases = [f"{code_name} == {cmd.code} ? ("
             + " or ".join(_size_condition(spec, cmd, i, v) for i, v in enumerate(vids, 1)) + ")"
             for cmd in spec.commands]
    return " : ".join(cases) + " : true"


def _gates(spec: Spec) -> list[str]:
    """Version gating (the availability checks) as valid: conditions on the code field."""
    vids = [v.id for v in spec.versions]
    gates = []
    for ch in spec.checks_of_kind("availability"):
        for v in ch.versions:
            missing = [c.code for c in spec.commands if not c.available_in(v)]
            if missing:
                gates.append(f"not (_root.header.version_index == {vids.index(v) + 1} and ("
                             + " or ".join(f"_ == {c}" for c in missing) + "))")
    return gates


def _args_cases(spec: Spec) -> dict[int, str]:
    """The args switch: (code, nb, version index) -> the layout type (one case per distinct nb)."""
    cases: dict[int, str] = {}
    for cmd in spec.commands:
        for i, v in enumerate((v.id for v in spec.versions), 1):
            for lay in _candidates(spec, cmd, v):
                for nb in lay.sizes:  # one size, or every nb of a repeated group
                    cases.setdefault(cmd.code * 65536 + nb * 256 + i, _layout_type(lay))
    return cases


def _head_attr(spec: Spec, f: Field, gates: list[str], size_expr: str, code_name: str) -> dict[str, Any]:
    """A record head field, with the code copy, version gating and argument sizes as valid: expressions."""
    attr = _field_attr(f, ENCODING, spec.record.clause, spec.revision)
    if f.role == "code" and gates:
        attr["valid"] = {"expr": " and ".join(gates)}
        attr["doc"] += " Version gating (" + ", ".join(c.id for c in spec.checks_of_kind("availability")) + \
            ") is a valid: expression."
    if f.role == "code_copy":
        attr["valid"] = {"expr": f"_ == {code_name}"}
    if f.role == "arg_size":
        attr["valid"] = {"expr": size_expr}
    return attr


def _record_type(spec: Spec) -> dict[str, Any]:
    rec = spec.record
    by_role = {f.role: f for f in rec.fields}
    code_name, size_name = by_role["code"].name, by_role["arg_size"].name
    gates, size_expr = _gates(spec), _size_expr(spec, code_name)
    head = [_head_attr(spec, f, gates, size_expr, code_name) for f in rec.fields]
    head.append({
        "id": "args",
        "size": size_name,
        "type": {"switch-on": (f"{code_name}.as<s4> * 65536 + {size_name}.as<s4> * 256"
                               " + _root.header.version_index.as<s4>"),
                 "cases": _args_cases(spec)},
        "doc": "The command's arguments: the layout of the file's version whose size matches (for a command "
               "the version lacks, any of its layouts); raw bytes for an unknown code.",
    })
    return {
        "doc": _doc(rec.doc) + " Not expressible here: " + ", ".join(
            f"{c.id} ({c.kind})" for c in spec.checks if c.kind in ("arg_checksum", "sequence")) + ".",
        "seq": head,
        "instances": {"command": {"value": code_name, "enum": "command", "doc": "The command code as the enum (5.2)."}},
    }


def _layout_types(spec: Spec) -> dict[str, Any]:
    types: dict[str, Any] = {}
    for cmd in spec.commands:
        for lay in cmd.layouts:
            types[_layout_type(lay)] = {
                "doc": _doc(f"{cmd.name}: {cmd.doc} Versions {', '.join(lay.versions)}; {lay.size} bytes."
                            + (f" Accepted under profile {', '.join(lay.profiles)}." if lay.profiles else "")
                            + (f" {lay.doc}" if lay.doc else "")),
                "doc-ref": f"{spec.revision}, {lay.clause or cmd.clause}",
                "seq": [_group_attr(lay, _field_attr(a, ENCODING, None, spec.revision)) if a.repeat is not None
                        else _field_attr(a, ENCODING, None, spec.revision) for a in lay.args],
            }
    return types


def _meta(spec: Spec) -> dict[str, Any]:
    m = spec.meta
    meta: dict[str, Any] = {
        "id": m["id"],
        "title": f"{m['title']} ({spec.revision})",
        "file-extension": m["file_extension"],
        "xref": {k: v[0] if len(v) == 1 else list(v) for k, v in m.get("xref", {}).items()},
        "license": m["license"],
        "ks-version": "0.11",
        "endian": "le" if m["byte_order"] == "little" else "be",
    }
    if not meta["xref"]:  # optional in the spec: no empty mapping in the .ksy
        del meta["xref"]
    return meta


def build(spec: Spec) -> dict[str, Any]:
    m = spec.meta
    first = next(iter(spec.headers.values()))
    types = {**_header_types(spec), "record": _record_type(spec), **_layout_types(spec)}
    not_here = [c for c in spec.checks if not CHECK_KINDS[c.kind].kaitai]
    ksy: dict[str, Any] = {
        "meta": _meta(spec),
        "doc": _doc(m["doc"]) + " Generated from spec/cbf.yaml; do not edit. Kaitai checks here the magic "
               "numbers, the code copy, the argument size per command and version, and version gating. It cannot "
               "check: " + "; ".join(f"{c.id} ({_doc(c.text)})" for c in not_here) + ".",
        "doc-ref": f"{m['document']}, part number {m['part_number']}, revision {m['revision']}",
        "seq": [
            {"id": "header", "type": "header", "doc": f"File header ({first.clause})."},
            {"id": "records", "type": "record", "repeat": "eos",
             "doc": f"The command records, framed to the end of the file ({spec.record.clause})."},
        ],
        "types": types,
        "enums": {"command": {c.code: {"id": c.name.lower(), "doc": _doc(c.doc)} for c in spec.sorted_commands}},
    }
    escaped: dict[str, Any] = _escape_docs(ksy)
    return escaped


def _escape_docs(node: Any) -> Any:
    """Every `doc` and `doc-ref` of the .ksy, escaped once, whole, for every ksc target (ksc copies
    them verbatim into Python docstrings and JavaScript/Java/Go comments: escape.kaitai_doc)."""
    if isinstance(node, dict):
        return {k: kaitai_doc(v) if k in ("doc", "doc-ref") and isinstance(v, str) else _escape_docs(v)
                for k, v in node.items()}
    if isinstance(node, list):
        return [_escape_docs(v) for v in node]
    return node


class _Dumper(yaml.SafeDumper):
    pass


def _hex_int(dumper: yaml.SafeDumper, value: int) -> yaml.Node:
    return dumper.represent_int(value)


def _spec_tuples(fields: list[Field] | tuple[Field, ...]) -> list[tuple[str, str, int]]:
    # a repeated group (issue 25, point 3): count -k, its items of k elements read flat (repeat: expr)
    return [(f.name, f.kind, -f.count if f.repeat is not None else f.count) for f in fields]


def _js_fields(spec: list[tuple[str, str, int]]) -> list[tuple[str, str, int, str]]:
    def camel_lower(name: str) -> str:
        head, *rest = name.split("_")
        return head + "".join(p[:1].upper() + p[1:] for p in rest)

    return [(n, k, c, camel_lower(n)) for n, k, c in spec]


def testee_context(spec: Spec, ksy: dict[str, Any]) -> dict[str, Any]:
    def cls(type_name: str) -> str:
        return "".join(p[:1].upper() + p[1:] for p in type_name.split("_"))

    first = next(iter(spec.headers.values()))
    common = [f for f in first.fields if any(a.get("id") == f.name for a in ksy["types"]["header"]["seq"])]
    tails = {cls(f"header_{ident(h.id)}"): _spec_tuples([f for f in h.fields if f not in common and
                                                           f.name not in {c.name for c in common}])
             for h in spec.headers.values()}
    args = {cls(_layout_type(lay)): _spec_tuples(lay.args) for c in spec.commands for lay in c.layouts}
    header_fields = _spec_tuples(common)
    record_fields = _spec_tuples(spec.record.fields)
    return {
        "header_size": spec.header_size,
        "header_fields": repr(header_fields),
        "header_tails": repr(tails),
        "record_fields": repr(record_fields),
        "args": repr(args),
        "header_fields_json": json.dumps(_js_fields(header_fields)),
        "header_tails_json": json.dumps({k: _js_fields(v) for k, v in tails.items()}),
        "record_fields_json": json.dumps(_js_fields(record_fields)),
        "args_json": json.dumps({k: _js_fields(v) for k, v in args.items()}),
        "commands_json": json.dumps({str(c.code): c.name for c in spec.commands}),
        "package": spec.meta["id"],
        "java_package": JAVA_PACKAGE,
        "go_module": GO_MODULE,
        "header_fields_go": _go_fields(header_fields),
        "header_tails_go": {f"Cbf_{k}": _go_fields(v) for k, v in tails.items()},
        "record_fields_go": _go_fields(record_fields),
        "args_go": {f"Cbf_{k}": _go_fields(v) for k, v in args.items()},
        "commands": [(c.code, c.name) for c in spec.commands],
        "header_fields_js": _js_fields(header_fields),
        "header_tails_js": {k: _js_fields(v) for k, v in tails.items()},
        "record_fields_js": _js_fields(record_fields),
        "args_js": {k: _js_fields(v) for k, v in args.items()},
    }


def _go_fields(spec: list[tuple[str, str, int]]) -> list[tuple[str, str, int, str]]:
    return [(n, k, c, "".join(p[:1].upper() + p[1:] for p in n.split("_"))) for n, k, c in spec]


def emit(spec: Spec) -> dict[str, bytes]:
    ksy = build(spec)
    env = environment(HERE / "templates")
    ctx = testee_context(spec, ksy)
    testees = {
        f"{OUT}/python/testee.py": env.get_template("testee.py.j2").render(**ctx).encode(),
        f"{OUT}/javascript/testee.js": env.get_template("testee.js.j2").render(**ctx).encode(),
        f"{OUT}/go-testee/testee.go": env.get_template("testee.go.j2").render(**ctx).encode(),
        f"{OUT}/java-testee/Testee.java": env.get_template("Testee.java.j2").render(**ctx).encode(),
    }
    text = yaml.dump(ksy, Dumper=_Dumper, sort_keys=False, width=120, allow_unicode=False)
    pkg = {"go_module": GO_MODULE, "go_requires": GO_REQUIRES, "spec": spec, "version": TOOLKIT_VERSION,
           "license": TOOLKIT_LICENSE, "cls": camel(spec.meta["id"]), "module": spec.meta["id"],
           "java_group": JAVA_GROUP, "java_artifact": JAVA_ARTIFACT, "java_package": JAVA_PACKAGE,
           "java_release": JAVA_RELEASE, "java_runtime": JAVA_RUNTIME, "maven_plugins": MAVEN_PLUGINS}
    packages = {
        f"{OUT}/python/{rel}": env.get_template(f"package/python/{rel}.j2").render(**pkg).encode()
        for rel in ("pyproject.toml", "README.md", "cbf_kaitai/__init__.py")
    }
    packages[f"{OUT}/go/go.mod"] = env.get_template("package/go/go.mod.j2").render(**pkg).encode()
    packages[f"{OUT}/go/go.sum"] = (HERE / "go.sum").read_bytes()
    packages[f"{OUT}/go/README.md"] = env.get_template("package/go/README.md.j2").render(**pkg).encode()
    packages.update({
        f"{OUT}/javascript/{rel}": env.get_template(f"package/javascript/{rel}.j2").render(**pkg).encode()
        for rel in ("package.json", "README.md")
    })
    packages.update({
        f"{OUT}/java/{rel}": env.get_template(f"package/java/{rel}.j2").render(**pkg).encode()
        for rel in ("pom.xml", "README.md")
    })
    options = {"java_package": JAVA_PACKAGE}
    return {
        f"{OUT}/ksc-options.json": (json.dumps(options, indent=1, sort_keys=True) + "\n").encode(),
        f"{OUT}/cbf.ksy": ("# Generated from spec/cbf.yaml by cbfgen; do not edit.\n" + text).encode(),
        f"{OUT}/cbf.ksy.json": (json.dumps(ksy, indent=1) + "\n").encode(),
        **testees,
        **packages,
    }
