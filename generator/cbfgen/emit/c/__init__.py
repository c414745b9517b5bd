"""C binding emitter: an stb-style single header (generated/c/cbf.h) with the
command enum (spec 5.2), per-layout argument structs, the spec as C tables, a
table-driven codec and a validator whose record checks are straight-line code
per layout (the offsets as constants); plus the conformance testee, the
`cbf-c` tool and a libFuzzer harness, all from templates beside this file.

Nothing here names a command, field, offset or check: every identifier and
number comes from the model. The hand-written C engine lives as real C files in
runtime/ (compiled and linted on their own by mk/c.mk) and goes verbatim into
cbf.h beside the generated sections of templates/cbf/ (tables, enums, structs,
per-layout code); it knows only the model's vocabulary (field kinds and roles,
check kinds, motion kinds, coverage regions, algorithm kinds).
"""

from __future__ import annotations

import re
import textwrap
from pathlib import Path
from typing import Any

from ... import __license__ as TOOLKIT_LICENSE
from ... import __version__ as TOOLKIT_VERSION
from ...escape import RESERVED, c_comment, c_string, keyword_clash, one_line
from ...model import ALGORITHM_KINDS, Field, Layout, Spec
from ...registry import CHECK_KINDS, FIELD_KINDS, TYPES, FieldType
from ...render import environment
from .machine import machine_context

HERE = Path(__file__).parent
OUT = "c"

# The model's vocabulary the engine understands (loader.py, spec comments); the field types and
# check kinds come from the registry (cbfgen/registry.py), never from a list here.
MOTION_KINDS = ("point", "line", "circle", "helix")
MOTION_KEYS = ("start", "end", "center", "normal", "degrees", "length")
ORIENT_KINDS = ("set", "path")
ORIENT_KEYS = ("start", "end")
SHAPE_KINDS = ("start", "end")
SHAPE_KEYS = ("name", "count")
CUTTER_KEYS = ("name", "length", "radius")
REGIONS = ("file", "header", "records", "args")
ALGORITHMS = tuple(ALGORITHM_KINDS)  # every kind has its branch in the template's checksum section
CHECKSUM_TAGS = ("args", "header", "file")
# Targeted check kinds whose C kernel is not cbf__target_at (runtime/validator.c): every other
# targeted kind of the registry goes there, and that switch has a case for each kind or the build fails.
_OWN_KERNEL = {"ordered": "cbf__ordered", "machine_limits": "cbf__machine_at"}


def cname(name: str) -> str:
    """A C identifier for a spec name: lower case, ASCII. A name that is reserved in C or C++ is
    refused (the loader refuses it first, escape.keyword_clash: one spelling in every binding)."""
    s = re.sub(r"\W+", "_", name, flags=re.ASCII).strip("_").lower()
    if not s or s[0].isdigit():
        s = "x" + s
    if s in RESERVED["C++"]:
        raise ValueError(f"C binding: the name {name!r} is reserved in C or C++ ({keyword_clash(name)})")
    return s


def macro(name: str) -> str:
    """An upper-case macro fragment for a spec id ("9.8.7" -> 9_8_7, "1.x" -> 1_X), ASCII only."""
    return re.sub(r"\W+", "_", name, flags=re.ASCII).strip("_").upper()


def cstr(text: str) -> str:
    """A C string literal (escape.c_string: quotes, backslashes, trigraphs, every other byte octal)."""
    return c_string(text)


# What starts a Doxygen command, an HTML tag or an entity in a /** */ comment (clang -Wdocumentation
# warns on an unknown \cmd, a lone <b, a \b without its word): escaped the Doxygen way, \x.
_DOXYGEN = re.compile(r"([\\@]|<(?=[A-Za-z/!?])|&(?=[A-Za-z#]))")


def comment(text: str) -> str:
    """Spec text on one line, safe inside /* */, /** */ and after // (escape.c_comment: no comment
    delimiters, no trigraphs, no line splice), then Doxygen's escapes: \\ and @, and < or & where
    a tag or an entity would start."""
    return _DOXYGEN.sub(r"\\\1", c_comment(one_line(text)))


def cfloat(x: float) -> str:
    r = repr(float(x))
    return r if any(c in r for c in ".eE") else r + ".0"


def field_type(f: Field) -> FieldType:
    """The registry's type of a field: the one of its kind and element size."""
    for t in TYPES.values():
        if t.kind == f.kind and t.size in (None, f.elem_size):
            return t
    raise ValueError(f"C binding: {f.name}: no registered type of kind {f.kind!r} and {f.elem_size} bytes")


def _ctype(f: Field) -> tuple[str, str]:
    """(type, array suffix) of a struct member for a field: the registry type's C type, an array
    of them for a vector; a string is char[N + 1] (NUL-terminated copy), bytes uint8_t[N]."""
    t = field_type(f)
    if t.c_type is not None:
        return t.c_type, (f"[{f.count}]" if f.count > 1 else "")
    if t.kind == "string":
        return "char", f"[{f.size} + 1]"
    return "uint8_t", f"[{f.size}]"


def _member_doc(f: Field, units: dict[str, str]) -> str:
    parts = [f.doc.rstrip(".") + "."]
    t = field_type(f)
    what = (f"string({f.size}), NUL-terminated copy" if t.kind == "string" else f"{f.size} raw bytes"
            if t.kind == "bytes" else t.float_format.removeprefix("IEEE-754 ") if t.float_format
            else f"{t.kind[0]}{t.bits}")  # u32, s16
    if t.size is not None and f.count > 1:
        what += f" x {f.count}"
    extra = [what, f"offset {f.offset}"]
    if f.unit:
        extra.append(f"unit {f.unit} ({units.get(f.unit, '').rstrip('.')})")
    if f.clause:
        extra.append(f"clause {f.clause}")
    if f.reserved:
        extra.append("reserved, kept verbatim")
    return comment(" ".join(parts) + " [" + "; ".join(extra) + "]")


def _field_row(f: Field, struct: str | None, roles: list[str], tags: list[str]) -> dict[str, Any]:
    ctype, suffix = _ctype(f)
    return {
        "name": f.name,
        "member": cname(f.name),
        "ctype": ctype,
        "suffix": suffix,
        "kind": f.kind.upper(),
        "role": ("ROLE_" + macro(f.role)) if f.role else "ROLE_NONE",
        "offset": f.offset,
        "elem": f.elem_size,
        "count": f.count,
        "size": f.size,
        "struct": struct,
        "magic": f.magic,
        "checksum": ("CK_" + macro(f.checksum)) if f.checksum else "CK_NONE",
        "flags": " | ".join(x for x in (
            "CBF__F_RESERVED" if f.reserved else "", "CBF__F_TEXT" if f.text else "",
            "CBF__F_MAGIC" if f.magic is not None else "") if x) or "0",
        "unit": f.unit,
        "macro": macro(f.name),
    }


def _newest(lay: Layout, order: dict[str, int]) -> int:
    return max(order[v] for v in lay.versions)


def _plan_layout(lay: dict[str, Any], cmd: dict[str, Any], checks: list[dict[str, Any]],
                 targets: list[dict[str, Any]], ctargets: list[dict[str, Any]], tindex: list[list[int]]) -> None:
    """What a record of this layout checks, as constants: its float and string
    arguments, the offsets the motion, orientation and shape roles read (-1: none),
    and its (check, target) pairs with the arguments each names."""
    args = lay["args"]

    def vec(i: int) -> int:
        """Offset of a 3-element float argument, -1 when the role has none."""
        return int(args[i]["offset"]) if i >= 0 and args[i]["kind"] == "FLOAT" and args[i]["count"] == 3 else -1

    def scalar(i: int) -> tuple[int, int]:
        """(offset, element count) of a float argument, (-1, 0) when the role has none."""
        return (int(args[i]["offset"]), int(args[i]["count"])) if i >= 0 and args[i]["kind"] == "FLOAT" else (-1, 0)

    def var(i: int) -> str:
        """The generated local that holds a 3-element float argument, decoded once a record (NULL: none)."""
        return f"x{i}" if vec(i) >= 0 else "NULL"

    m = dict(zip(MOTION_KEYS, lay["motion"], strict=True))
    o = dict(zip(ORIENT_KEYS, lay["orient"], strict=True))
    lay["plan"] = {
        # each float argument is decoded once into x<arg> (finite flag ok<arg>) and shared by the checks
        "values": [dict(a, row=lay["first_arg"] + i, arg=i) for i, a in enumerate(args)
                   if a["kind"] in ("FLOAT", "STRING")],
        "motion": {"start": vec(m["start"]), "end": vec(m["end"]), "center": vec(m["center"]),
                   "normal": vec(m["normal"]), "degrees": scalar(m["degrees"]), "length": scalar(m["length"]),
                   "start_var": var(m["start"]), "end_var": var(m["end"])},
        "orient": {"start": vec(o["start"]), "end": vec(o["end"]),
                   "start_var": var(o["start"]), "end_var": var(o["end"])},
        "targets": [],
    }
    for ct in ctargets[cmd["first_ct"]:cmd["first_ct"] + cmd["n_ct"]]:
        tg = targets[ct["target"]]
        rows = [tindex[tg["first"] + a][lay["index"]] for a in range(tg["n"])]
        floats = [lay["first_arg"] + i for i in rows if i >= 0 and args[i]["kind"] == "FLOAT"]
        kind = checks[ct["check"]]["kind_name"]
        kernel = _OWN_KERNEL.get(kind, "cbf__target_at")
        if kernel == "cbf__machine_at":
            continue  # its own rules (machine.py), called from the layout function too
        # a check finds nothing in a layout without its float arguments (ordered: without all of them)
        if floats if kernel == "cbf__target_at" else len(floats) == len(rows):
            lay["plan"]["targets"].append({"check": ct["check"], "target": ct["target"], "kernel": kernel,
                                           "text": ct["text"], "args": floats})


def context(spec: Spec) -> dict[str, Any]:
    if spec.meta.get("byte_order") not in ("little", "big"):
        raise ValueError("C binding: byte_order must be little or big")
    vorder = {v.id: i for i, v in enumerate(spec.versions)}
    units = spec.units
    roles: list[str] = []
    for h in spec.headers.values():
        for f in h.fields:
            if f.role and f.role not in roles:
                roles.append(f.role)
    for f in spec.record.fields:
        if f.role and f.role not in roles:
            roles.append(f.role)
    header_ids = list(spec.headers)
    headers = []
    for hid, h in spec.headers.items():
        struct = "cbf_header_" + cname(hid)
        headers.append({
            "id": hid, "macro": macro(hid), "struct": struct, "size": h.size, "clause": h.clause,
            "doc": comment(h.doc),
            "fields": [dict(_field_row(f, struct, roles, []), doc=_member_doc(f, units)) for f in h.fields],
        })
    rec_fields = [dict(_field_row(f, "cbf_record_head", roles, []), doc=_member_doc(f, units))
                  for f in spec.record.fields]
    for f in spec.record.fields:
        if f.kind != "uint":
            raise ValueError("C binding: record head fields must be unsigned integers")
    versions = [{
        "id": v.id, "macro": macro(v.id), "major": v.major, "minor": -1 if v.minor is None else v.minor,
        "header": header_ids.index(v.header), "writable": int(v.writable), "doc": comment(v.doc),
        "clause": v.clause,
    } for v in spec.versions]
    profiles = [p.id for p in spec.profiles]

    layouts: list[dict[str, Any]] = []
    commands: list[dict[str, Any]] = []
    arg_rows: list[dict[str, Any]] = []
    cmd_index = {c.name: i for i, c in enumerate(spec.commands)}
    max_layouts = 0
    for ci, c in enumerate(spec.commands):
        first = len(layouts)
        for lay in c.layouts:
            suffix = ("_" + cname(lay.variant)) if lay.variant else ""
            struct = f"cbf_{cname(c.name)}{suffix}_args"
            args = [dict(_field_row(a, struct, roles, []), doc=_member_doc(a, units)) for a in lay.args]
            for a in lay.args:
                if a.kind == "float" and a.elem_size != 4:  # the codec carries it; the checks read binary32
                    raise ValueError(f"C binding: {c.name} {a.name}: the C validator reads binary32 arguments only "
                                     "(registry.unsupported says so; the loader refuses it first)")

            def idx(name: str | None, lay: Layout = lay) -> int:
                if name is None:
                    return -1
                for i, a in enumerate(lay.args):
                    if a.name == name:
                        return i
                return -1

            def role_idx(role: dict[str, str] | None, keys: tuple[str, ...]) -> list[int]:
                return [idx((role or {}).get(k)) for k in keys]

            layouts.append({
                "index": len(layouts), "command": ci, "cmd_name": c.name,
                "variant": lay.variant, "macro": macro(c.name) + (("_" + macro(lay.variant)) if lay.variant else ""),
                "member": cname(c.name) + suffix, "struct": struct, "size": lay.size,
                "versions": lay.versions, "vmask": " | ".join(f"CBF__VBIT(CBF_V{macro(v)})" for v in lay.versions),
                "pmask": " | ".join(f"CBF__PBIT({profiles.index(p)})" for p in lay.profiles) or "0",
                "profiles": lay.profiles, "first_arg": len(arg_rows), "nargs": len(args), "args": args,
                "motion": role_idx(c.motion, MOTION_KEYS), "orient": role_idx(c.orientation, ORIENT_KEYS),
                "shape": role_idx(c.shape, SHAPE_KEYS), "cutter": role_idx(c.cutter, CUTTER_KEYS),
                "progress": idx(c.progress),
                "doc": comment(lay.doc or c.doc), "clause": lay.clause or c.clause,
            })
            arg_rows.extend(args)
        # Decode candidates per version: the version's own layouts in spec
        # order, else every layout, newest first (PROTOCOL.md).
        cands = []
        for v in spec.versions:
            own = [first + i for i, lay in enumerate(c.layouts) if v.id in lay.versions]
            if not own:
                order = sorted(range(len(c.layouts)), key=lambda i: -_newest(c.layouts[i], vorder))
                own = [first + i for i in order]
            cands.append(own)
            max_layouts = max(max_layouts, len(own))
        commands.append({
            "index": ci, "name": c.name, "macro": macro(c.name), "code": c.code, "doc": comment(c.doc),
            "clause": c.clause, "first": first, "nlayouts": len(c.layouts), "cands": cands,
            "motion": ("MOTION_" + macro(c.motion["kind"])) if c.motion else "MOTION_NONE",
            "orient": ("ORIENT_" + macro(c.orientation["kind"])) if c.orientation else "ORIENT_NONE",
            "shape": ("SHAPE_" + macro(c.shape["kind"])) if c.shape else "SHAPE_NONE",
            "cutter": int(bool(c.cutter)),
            "vmask": " | ".join(f"CBF__VBIT(CBF_V{macro(v)})" for v in c.versions),
            "layouts": [lay for lay in layouts[first:]],
            "per_version": [
                {"macro": macro(v.id), "layouts": [lay for lay in layouts[first:] if v.id in lay["versions"]]}
                for v in spec.versions
            ],
        })
    for crow in commands:
        for row in crow["cands"]:
            row.extend([-1] * (max_layouts - len(row)))

    cov_names = list(spec.checksums.coverages)
    rec_names = [f.name for f in spec.record.fields]
    segments: list[dict[str, Any]] = []
    coverages: list[dict[str, Any]] = []
    for name, cov in spec.checksums.coverages.items():
        coverages.append({"name": name, "first": len(segments), "n": len(cov.segments), "doc": comment(cov.doc)})
        for s in cov.segments:
            segments.append({
                "region": "REGION_" + macro(s.region), "start": s.start or 0,
                "end": -1 if s.end is None else s.end,
                "exclude": " | ".join(f"(1u << {rec_names.index(x)})" for x in s.exclude) or "0u",
            })
    ckfields: list[dict[str, Any]] = []
    for tag in CHECKSUM_TAGS:
        cf = spec.checksums.for_field(tag)
        kind = spec.checksums.algorithms[cf.algorithm].kind
        if kind not in ALGORITHMS:
            raise ValueError(f"C binding: checksum algorithm kind {kind!r} is not supported")
        ckfields.append({"tag": tag, "alg": "ALG_" + macro(kind), "coverage": cov_names.index(cf.coverage)})
    fill = ["CK_" + macro(t) for t in spec.checksums.fill_order]
    def alg_macro(name: str) -> str:
        return "CBF__ALG_" + macro(spec.checksums.algorithms[name].kind)

    profile_rows: list[dict[str, Any]] = []
    for p in spec.profiles:
        # a hint coverage is computed with the algorithm of the profile that accepts it
        owners = [next((q for q in spec.profiles if x in q.file_coverages), p) for x in p.hint_coverages]
        profile_rows.append({"id": p.id, "macro": macro(p.id), "doc": comment(p.doc),
                             "file": [cov_names.index(x) for x in p.file_coverages],
                             "hint": [cov_names.index(x) for x in p.hint_coverages],
                             "file_alg": alg_macro(spec.file_algorithm(p.id)),
                             "hint_alg": [alg_macro(spec.file_algorithm(q.id)) for q in owners]})
    max_cov = max([len(r["file"]) for r in profile_rows] + [len(r["hint"]) for r in profile_rows] + [1])
    for prow in profile_rows:
        prow["file_pad"] = prow["file"] + [-1] * (max_cov - len(prow["file"]))
        prow["hint_pad"] = prow["hint"] + [-1] * (max_cov - len(prow["hint"]))
        prow["hint_alg_pad"] = prow["hint_alg"] + ["CBF__ALG_NONE"] * (max_cov - len(prow["hint_alg"]))
    # per command and version: the index of the one availability check covering a
    # command the version lacks (the loader guarantees one), -1 when it has it
    check_index = {ch.id: i for i, ch in enumerate(spec.checks)}
    avail_rows = []
    for c in spec.commands:
        row = []
        for v in spec.versions:
            ach = spec.availability_check(c.name, v.id)
            row.append(check_index[ach.id] if ach is not None else -1)
        avail_rows.append({"name": c.name, "row": row})

    checks: list[dict[str, Any]] = []
    targets: list[dict[str, Any]] = []
    tnames: list[str] = []
    # per target argument, its index in each layout (-1: not there), so that the
    # validator finds it without comparing names record by record
    tindex: list[list[int]] = []
    for ch in spec.checks:
        if ch.kind not in CHECK_KINDS:
            raise ValueError(f"C binding: check {ch.id}: kind {ch.kind!r} is not in the registry")
        first = len(targets)
        for t in ch.targets:
            targets.append({"command": cmd_index[t.command], "first": len(tnames), "n": len(t.args),
                            "text": f"{t.command} {' '.join(t.args)}"})
            tnames.extend(t.args)
            for name in t.args:
                tindex.append([next((i for i, a in enumerate(lay["args"]) if a["name"] == name), -1)
                               if lay["cmd_name"] == t.command else -1 for lay in layouts])
        checks.append({
            "id": ch.id, "macro": macro(ch.id), "kind": "KIND_" + macro(ch.kind), "kind_name": ch.kind,
            "severity": ch.severity,
            "error": int(ch.severity == "error"),
            "vmask": " | ".join(f"CBF__VBIT(CBF_V{macro(v)})" for v in ch.versions) or "0",
            "first": first, "n": len(ch.targets),
            "has_min": int(ch.min is not None), "min": cfloat(ch.min or 0.0),
            "has_max": int(ch.max is not None), "max": cfloat(ch.max or 0.0),
            "text": comment(ch.text), "fails": comment(ch.fails),
            "clause": ch.clause or "", "decision": ch.decision or "",
        })
    # (check, target) pairs grouped by command, so the validator visits only the
    # checks that name the record's command (in check order, as before).
    ctargets: list[dict[str, Any]] = []
    for crow in commands:
        crow["first_ct"] = len(ctargets)
        for ci, chrow in enumerate(checks):
            for ti in range(chrow["first"], chrow["first"] + chrow["n"]):
                if targets[ti]["command"] == crow["index"]:
                    ctargets.append({"check": ci, "target": ti, "text": f"{chrow['id']}: {targets[ti]['text']}"})
        crow["n_ct"] = len(ctargets) - crow["first_ct"]
    # The straight-line validator (runtime/validator.c, templates/cbf/validator_layouts.c.j2): per layout, the
    # constants its checks read, so that each record runs a dozen loads and
    # compares instead of walking the field tables.
    for row in layouts:
        _plan_layout(row, commands[row["command"]], checks, targets, ctargets, tindex)
    max_arg = max([lay["size"] for lay in layouts] + [0])
    groups: dict[str, list[str]] = {
        "command": [str(c["macro"]) for c in commands], "layout": [str(lay["macro"]) for lay in layouts],
        "version": [str(v["macro"]) for v in versions], "check": [str(c["macro"]) for c in checks],
        "profile": [str(p["macro"]) for p in profile_rows],
    }
    for what, names in groups.items():
        dup = sorted({n for n in names if names.count(n) > 1})
        if dup:
            raise ValueError(f"C binding: two {what}s map to the same C name {dup[0]}")
    head = {f["role"][len("ROLE_"):]: f for f in rec_fields if f["role"] != "ROLE_NONE"}
    first_header = next(iter(spec.headers.values()))
    major = [f for f in first_header.fields if f.role == "version_major"]
    if not major:
        raise ValueError("C binding: the first header layout has no version_major field")
    ck_head = next((f for f in rec_fields if f["checksum"] == "CK_ARGS"), None)
    return {
        "spec": spec,
        "head": head,
        "head_checksum": ck_head,
        "version_major_offset": major[0].offset,
        "meta": spec.meta,
        "toolkit_version": TOOLKIT_VERSION,
        "toolkit_license": TOOLKIT_LICENSE,
        "spec_revision": spec.revision,
        "little": spec.meta["byte_order"] == "little",
        "pad": int(spec.meta.get("string_padding", 0)),
        "roles": [macro(r) for r in roles],
        "headers": headers,
        "header_size": spec.header_size,
        "record": {"head_size": spec.record.head_size, "fields": rec_fields, "clause": spec.record.clause,
                   "doc": comment(spec.record.doc)},
        "versions": versions,
        "default_version": [v.id for v in spec.versions].index(spec.default_version),
        "fallback_version": [v.id for v in spec.versions].index(spec.fallback_version),
        "commands": commands,
        "sorted_commands": sorted(commands, key=lambda c: c["code"]),
        "index_by_code": [next((c["index"] for c in commands if c["code"] == code), -1) for code in range(256)],
        "names_by_code": [next((c["name"] for c in commands if c["code"] == code), None) for code in range(256)],
        "layouts": layouts,
        "arg_rows": arg_rows,
        "max_layouts": max_layouts,
        "max_arg": max_arg,
        "segments": segments,
        "coverages": coverages,
        "ckfields": ckfields,
        "avail_rows": avail_rows,
        "fill": fill,
        "profiles": profile_rows,
        "max_cov": max_cov,
        "checks": checks,
        "targets": targets or [{"command": -1, "first": 0, "n": 0, "text": "none"}],
        "ntargets": len(targets),
        "tnames": tnames or [""],
        "tindex": tindex or [[-1] * len(layouts)],
        "tolerances": [{"macro": macro(k), "value": cfloat(v), "name": k} for k, v in spec.tolerances.items()],
        "limits": [{"macro": macro(k), "value": v, "name": k} for k, v in spec.limits.items()],
        "motion_kinds": [macro(k) for k in MOTION_KINDS],
        "motion_keys": [macro(k) for k in MOTION_KEYS],
        "orient_kinds": [macro(k) for k in ORIENT_KINDS],
        "orient_keys": [macro(k) for k in ORIENT_KEYS],
        "shape_kinds": [macro(k) for k in SHAPE_KINDS],
        "shape_keys": [macro(k) for k in SHAPE_KEYS],
        "cutter_keys": [macro(k) for k in CUTTER_KEYS],
        "regions": [macro(k) for k in REGIONS],
        "algorithms": [macro(k) for k in ALGORITHMS],
        "tags": [macro(k) for k in CHECKSUM_TAGS],
        "check_kinds": [macro(k) for k in CHECK_KINDS],  # the registry's, in its order
        "field_kinds": [macro(k) for k in FIELD_KINDS],
        "decisions": spec.decisions,
        "errata": spec.errata,
    }


RUNTIME = HERE / "runtime"
RUNTIME_REL = "generator/cbfgen/emit/c/runtime"  # as a compiler names it from the repository's root
_RESUME = '#line @@NEXT@@ "cbf.h"'


def runtime_section(name: str) -> str:
    """A hand-written runtime file (runtime/<name>), verbatim, between markers that name it (mk/c.mk
    compiles the files themselves in their place) and #line directives, so that a compiler's message
    about it names runtime/<name> and its line; after it, the lines are cbf.h's again."""
    text = (RUNTIME / name).read_text(encoding="utf-8")
    return (f"/* ==== BEGIN runtime/{name}: verbatim from {RUNTIME_REL}/{name}, edit it there ==== */\n"
            f'#line 1 "{RUNTIME_REL}/{name}"\n{text.rstrip(chr(10))}\n'
            f"/* ==== END runtime/{name} ==== */\n{_RESUME}")


def _resume_lines(text: str) -> str:
    """Number each #line that resumes cbf.h after a runtime section with the line that follows it."""
    lines = text.split("\n")
    for i, line in enumerate(lines):
        if line == _RESUME:
            lines[i] = f'#line {i + 2} "cbf.h"'
    return "\n".join(lines)


def emit(spec: Spec) -> dict[str, bytes]:
    env = environment(HERE / "templates")
    env.globals["runtime"] = runtime_section
    env.filters["cstr"] = cstr
    env.filters["comment"] = comment
    env.filters["cname"] = cname
    env.filters["macro"] = macro
    env.filters["wrap"] = lambda s, width=76, indent="" : ("\n" + indent).join(textwrap.wrap(s, width))
    ctx = context(spec)
    ctx.update(machine_context(spec, ctx["layouts"], cfloat, macro))  # machine.h.j2 (L1)
    out: dict[str, bytes] = {}
    for name in ("cbf.h", "cbf_testee.c", "cbf_tool.c", "cbf_fuzz.c", "cbf.pc.in"):
        text = env.get_template(name + ".j2").render(**ctx)
        out[f"{OUT}/{name}"] = (_resume_lines(text) if name == "cbf.h" else text).encode()
    return out
