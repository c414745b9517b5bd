"""Format documentation emitter: Markdown pages and SVG figures from the spec model.

Every command, field, check, clause, decision and erratum comes from the
model; free text passes through text.prose (escaped, tolerances as values,
decision ids as links). The golden cases (their .cbf read with the model by
hexdump.py, see golden.py), the traceability status with each binding's
failure list, and the reliability figures come from conformance/ (when a
report is missing the page says so). The pages are index.md, one page per
command under commands/, golden/index.md and one page per golden case, and
fields.md (the static index of every field and check); the figures are under
svg/. The HTML site (site.py, `make docs`), the browser check (browser.py)
and the PDF (pdf.py) render the same pages.
"""

from __future__ import annotations

import json
import math
import re
import struct
from pathlib import Path
from typing import Any

from ... import __version__, registry
from ...diff import version_steps
from ...model import Check, Command, Layout, Spec, ident
from ...render import environment
from . import golden, svg, text

HERE = Path(__file__).parent
REPO = HERE.parents[3]
OUT = "docs"
GOLDEN = REPO / "conformance" / "golden"
REPORT = REPO / "conformance" / "report.json"
RELIABILITY = REPO / "conformance" / "reliability.json"
# The folder the output folder sits in: a page links a file of the repository (the spec, the golden README,
# a case's hex source, the kit's guide) only when the file is there, relative to the page; otherwise it
# names it as text. cbfgen sets it to its --out folder's parent; the checkout's generated/ sits in REPO.
ROOT = REPO


def _anchor(text: str) -> str:
    return ident(text).replace("_", "-")


COMMANDS = "commands"  # the folder of the command pages


def command_page(c: Command) -> str:
    """The page of a command, relative to the docs folder."""
    return f"{COMMANDS}/{_anchor(c.name)}.md"


def layout_svg(lay: Layout) -> str:
    """The argument diagram of a layout, relative to the docs folder."""
    suffix = f"-{_anchor(lay.variant)}" if lay.variant else ""
    return f"svg/cmd-{_anchor(lay.command)}{suffix}.svg"


def case_page(name: str) -> str:
    """The page of a golden case, relative to the docs folder."""
    return f"golden/{name}.md"


GOLDEN_INDEX = "golden/index.md"
CUT_PAGE = "cut.md"  # the companion document: the CUT text format
FIELD_INDEX = "fields.md"
GALLERY = "gallery"  # the toolpath gallery's folder in the site (site.py, made by cbf.gallery)


def header_svg(layout_id: str) -> str:
    return f"svg/header-{_anchor(layout_id)}.svg"


RECORD_SVG = "svg/record.svg"
MOTION_SVG = "svg/motion.svg"


def _read_json(path: Path) -> dict[str, Any] | None:
    try:
        data: dict[str, Any] = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    return data if isinstance(data, dict) else None


def _report() -> dict[str, Any] | None:
    return _read_json(REPORT)


def _reliability_file() -> dict[str, Any] | None:
    return _read_json(RELIABILITY)


FAILURES = REPO / "conformance" / "failures"


def known_failures(binding: str) -> tuple[set[str], list[str]]:
    """The cases a binding's failure list names, and the list's own explanation (its comment lines)."""
    try:
        text = (FAILURES / f"{binding}.txt").read_text(encoding="utf-8")
    except OSError:
        return set(), []
    names = {line.split()[0] for line in text.splitlines() if line.strip() and not line.startswith("#")}
    notes = [line[1:].strip() for line in text.splitlines() if line.startswith("#")]
    start = next((k + 1 for k, line in enumerate(notes) if line.lower().startswith("why")), 0)
    return names, notes[start:]


def _traceability(spec: Spec, report: dict[str, Any] | None) -> list[dict[str, Any]]:
    """Per check: its golden cases and, per binding, counts of pass / not expressible / fail / not run."""
    rows = []
    bindings = sorted((report or {}).get("bindings", {}).items())
    listed = {name: known_failures(name)[0] for name, _ in bindings}
    for check in spec.checks:
        cases = []
        if report:
            cases = sorted(name for name, c in report.get("cases", {}).items() if check.id in c.get("checks", []))
        status: dict[str, dict[str, int]] = {}
        for binding, b in bindings:
            counts = {"pass": 0, "not expressible": 0, "fail": 0, "not run": 0}
            for name in cases:
                res = b.get("results", {}).get(name, {}).get("status", "skip") if b.get("available", True) else "skip"
                if res == "pass":
                    counts["pass"] += 1
                elif res == "fail":
                    counts["not expressible" if name in listed[binding] else "fail"] += 1
                else:
                    counts["not run"] += 1
            status[binding] = counts
        rows.append({"check": check, "cases": cases, "status": status})
    return rows


def _rate(entry: Any) -> dict[str, Any]:
    """trials, detected and the detection rate in percent of one reliability entry."""
    e = entry if isinstance(entry, dict) else {}
    trials, detected = int(e.get("trials", 0) or 0), int(e.get("detected", 0) or 0)
    # Truncated, never rounded up: 19,999 of 20,000 reads 99.99 %, not 100.00 %.
    rate = f"{math.floor(10000 * detected / trials) / 100:.2f} %" if trials else "—"
    misses = e.get("misses", [])
    missed = len(misses) if isinstance(misses, list) else 0
    return {"trials": trials, "detected": detected, "rate": rate, "misses": missed}


def _rate_rows(table: Any, outer: str) -> list[dict[str, Any]]:
    rows = []
    for key, classes in sorted((table or {}).items()):
        for cls, entry in sorted((classes or {}).items()):
            rows.append({outer: key, "class": cls, **_rate(entry)})
    return rows


MISSES_SHOWN = 5  # missed corruptions listed per binding and class


def _misses(table: Any) -> list[dict[str, Any]]:
    rows = []
    for binding, classes in sorted((table or {}).items()):
        for cls, entry in sorted((classes or {}).items()):
            misses = entry.get("misses", []) if isinstance(entry, dict) else []
            for m in (misses if isinstance(misses, list) else [])[:MISSES_SHOWN]:
                m = m if isinstance(m, dict) else {}
                rest = ", ".join(f"{k}={m[k]}" for k in sorted(m) if k not in ("file", "offset"))
                rows.append({"binding": binding, "class": cls, "file": m.get("file", ""),
                             "offset": m.get("offset", ""), "detail": rest})
    return rows


def _reliability(data: dict[str, Any] | None) -> dict[str, Any] | None:
    """conformance/reliability.json as table rows (None when the file is missing or unreadable)."""
    if data is None:
        return None
    diff = data.get("differential") or {}
    fuzz = data.get("fuzz") or {}
    return {
        "corruption": _rate_rows(data.get("corruption"), "binding"),
        "misses": _misses(data.get("corruption")),
        "misses_shown": MISSES_SHOWN,
        "run": {k: data[k] for k in ("mode", "seed") if k in data},
        "blind_spots": _rate_rows(data.get("blind_spots"), "variant"),
        "differential": diff if isinstance(diff, dict) else {},
        "fuzz": [{"name": name, **(v if isinstance(v, dict) else {})} for name, v in sorted(fuzz.items())],
    }


def _worked_example(spec: Spec) -> dict[str, Any]:
    """A checksum example computed here from a record the model describes (the first motion command)."""
    cmd = next(c for c in spec.commands if c.motion and c.motion.get("kind") == "line")
    lay = cmd.primary
    values: list[float] = []
    raw = b""
    n = 0
    for a in lay.args:
        if a.kind == "float":
            vals = [float(n + k) for k in range(a.count)]
            n += a.count
            values += vals
            raw += struct.pack(("<" if spec.meta["byte_order"] == "little" else ">") + "f" * a.count, *vals)
        else:
            raw += bytes(a.size)
    return {"command": cmd, "layout": lay, "numbers": values, "hex": raw.hex(" "),
            "sum": sum(raw), "nonzero": [f"0x{b:02X}" for b in raw if b]}


def _motion_names(spec: Spec, kind: str) -> dict[str, str] | None:
    for c in spec.commands:
        if c.motion and c.motion.get("kind") == kind:
            return dict(c.motion)
    return None


def figures(spec: Spec, per_row: int = 16, narrow: bool = False) -> dict[str, str]:
    """Every SVG figure, by path relative to the docs folder; per_row: the bytes a row of a byte-field
    diagram shows (the HTML site also draws them 8 a row, for narrow screens)."""
    out: dict[str, str] = {}
    for h in spec.headers.values():
        versions = ", ".join(v.id for v in spec.versions if v.header == h.id)
        out[header_svg(h.id)] = svg.byte_field(f"Header layout {h.id} (versions {versions}), {h.size} bytes",
                                               h.fields, h.size, per_row, narrow)
    rec = spec.record
    out[RECORD_SVG] = svg.byte_field(f"Record head, {rec.head_size} bytes (then the arguments)",
                                     rec.fields, rec.head_size, min(per_row, rec.head_size), narrow)
    for c in spec.commands:
        for lay in c.layouts:
            if lay.args:
                name = f"{c.name}{' ' + lay.variant if lay.variant else ''}"
                # a repeated group (issue 25, point 3): drawn with its fewest items, named name[i]
                shown = lay.sized(lay.sizes[0]) if lay.repeated is not None else lay
                rep = f" + {lay.repeated.size}·n" if lay.repeated is not None else ""
                out[layout_svg(lay)] = svg.byte_field(f"{name} arguments, {lay.size}{rep} bytes",
                                                      (shown or lay).args, (shown or lay).size, per_row, narrow)
    circle = _motion_names(spec, "circle")
    if circle:
        out[MOTION_SVG] = svg.motion(circle, _motion_names(spec, "helix"), "Circle and helix end points")
    return out


def _quantities(spec: Spec) -> list[dict[str, Any]]:
    """Tolerances and limits as the reader needs them: a label, the value with its unit, the key for a tooltip."""
    rows = []
    for table, values in (("tolerances", spec.tolerances), ("limits", spec.limits)):
        for key in values:
            base, _, suffix = key.rpartition("_")
            label = (base if base and suffix in spec.units else key).replace("_", " ")
            rows.append({"kind": table[:-1], "label": label, "key": f"{table}.{key}",
                         "value": text.value_html(spec, table, key)})
    return rows


def _cut_rows(spec: Spec) -> list[dict[str, Any]]:
    """Every layout of every command in the CUT keyword table (version-specific layouts included)."""
    rows = []
    for c in spec.commands:
        kw = c.name.lower() if spec.cut["keyword_case"] == "lower" else c.name
        for lay in c.layouts:
            args = []
            for a in lay.args:
                if a.reserved:
                    continue
                how = (" (vector)" if a.is_vector else " (rest of line)" if a.text
                       else " (word)" if a.kind == "string" else "")
                args.append(a.name + how)
            rows.append({"command": c, "keyword": kw, "layout": lay, "args": args})
    return rows


def _field_index(spec: Spec) -> list[dict[str, str]]:
    """Every field and check with where it is described: the static search page."""
    rows = []
    for h in spec.headers.values():
        for f in h.fields:
            rows.append({"name": f.name, "what": f"header {h.id} field, offset {f.offset}",
                         "href": f"index.md#header-{h.id}", "label": f"header layout {h.id}"})
    for f in spec.record.fields:
        rows.append({"name": f.name, "what": f"record head field, offset {f.offset}", "href": "index.md#records",
                     "label": "record head"})
    for c in spec.commands:
        for lay in c.layouts:
            tag = f" ({lay.variant})" if lay.variant else ""
            for a in lay.args:
                rows.append({"name": a.name, "what": f"{c.name}{tag} argument, offset {a.offset}",
                             "href": f"{command_page(c)}#layout-{_anchor(lay.variant or 'primary')}",
                             "label": f"{c.name} layout {lay.variant or 'primary'}"})
        rows.append({"name": c.name, "what": f"command 0x{c.code:02X}", "href": command_page(c),
                     "label": f"{c.name} page"})
    for k in spec.checks:
        rows.append({"name": k.id, "what": f"check ({k.kind}, {k.severity})",
                     "href": f"index.md#check-{_anchor(k.id)}", "label": f"check {k.id}"})
    for d in spec.decisions:
        rows.append({"name": d.id, "what": f"decision: {d.topic}", "href": f"index.md#decision-{_anchor(d.id)}",
                     "label": f"decision {d.id}"})
    return sorted(rows, key=lambda r: (r["name"].lower(), r["what"]))


# -- 300071 as a controlled document (issue 26) ----------------------------------------
NOTE_ID = re.compile(r"\b([A-Z][0-9]+)\b")


class DocumentError(ValueError):
    """The spec's document frame names a note (decision or erratum) it does not have."""


def _notes(spec: Spec) -> dict[str, dict[str, Any]]:
    """Every decision and erratum by id: kind, id, topic, text and (errata) the revision it corrects."""
    out: dict[str, dict[str, Any]] = {}
    for d in spec.decisions:
        out[d.id] = {"kind": "decision", "id": d.id, "topic": d.topic, "text": d.text, "evidence": d.evidence,
                     "anchor": f"decision-{_anchor(d.id)}"}
    raw = {str(e["id"]): e for e in spec.raw.get("errata", [])}
    for e in spec.errata:
        out[e.id] = {"kind": "erratum", "id": e.id, "topic": e.clause or "", "text": e.text,
                     "revision": str(raw.get(e.id, {}).get("revision", "")), "evidence": "",
                     "anchor": f"erratum-{_anchor(e.id)}"}
    return out


def _note_refs(spec: Spec, ids: list[str] | tuple[str, ...]) -> list[dict[str, Any]]:
    notes = _notes(spec)
    missing = [i for i in ids if i not in notes]
    if missing:
        raise DocumentError(f"meta.clauses names {', '.join(missing)}, which is no decision or erratum")
    return [notes[i] for i in ids]


def _ids_in(spec: Spec, *texts: str | None) -> list[str]:
    """The decision and erratum ids a text names, in order, once each."""
    notes = _notes(spec)
    seen: list[str] = []
    for t in texts:
        for m in NOTE_ID.finditer(t or ""):
            if m.group(1) in notes and m.group(1) not in seen:
                seen.append(m.group(1))
    return seen


def type_text(a: Any) -> str:
    """An argument's type as table 5.1 writes it: string(16), float, float(3), byte, N bytes."""
    if a.kind == "string":
        return f"string({a.size})"
    if a.kind == "float":
        return "float" if a.count == 1 else f"float({a.count})"
    if a.kind == "uint":
        return "byte" if a.elem_size == 1 and a.count == 1 else f"uint{8 * a.elem_size}" + (
            f"({a.count})" if a.count > 1 else "")
    return f"{a.size} bytes"


def _table_51(spec: Spec) -> list[dict[str, Any]]:
    """Table 5.1: per command, the writable versions' majors, name, code, bytes and arguments, in the
    spec's order, with the decisions and errata its layouts name."""
    rows = []
    writable = list(spec.writable_versions)
    for c in spec.commands:
        vers = [v for v in writable if c.available_in(v.id)]
        lays = []
        for v in vers:
            for lay in c.layouts_for(v.id):
                if not lay.profiles and lay not in lays:
                    lays.append(lay)
        if not lays:
            lays = [c.primary]
        args = []
        for a in lays[0].args:
            label = a.name.replace("_", " ")
            args.append(f"{label}: {type_text(a)}")
        sizes = sorted({lay.size for lay in lays})
        ids = _ids_in(spec, lays[0].doc, *(a.doc for a in lays[0].args if a.reserved),
                      c.erratum if c.declared_size else None)
        rows.append({"command": c, "ver": ",".join(str(v.major) for v in vers), "hex": f"{c.code:02X}",
                     "bytes": " or ".join(str(n) for n in sizes), "doc": c.doc.rstrip("."),
                     "args": args, "notes": _note_refs(spec, ids)})
    return rows


def _document(spec: Spec) -> dict[str, Any]:
    """300071's frame and body from meta: title block, approvals, release, history, sections with their
    clauses (verbatim text, notes resolved), the checks enforcing each clause."""
    m = spec.meta
    checks_by_clause: dict[str, list[Check]] = {}
    for k in spec.checks:
        checks_by_clause.setdefault(k.id, []).append(k)
    sections = []
    clauses = list(m.get("clauses", []))
    for sec in m.get("sections", []):
        own = [c for c in clauses if str(c["number"]).split(".")[0] == str(sec["id"])]
        sections.append({"id": str(sec["id"]), "title": sec["title"], "clauses": [
            {"title": None, "table": None, **c, "id": str(c["number"]), "depth": str(c["number"]).count("."),
             "notes": _note_refs(spec, list(c.get("notes", []))),
             "checks": checks_by_clause.get(str(c["number"]), [])} for c in own]})
    seen: set[str] = set()
    for sec_ in sections:  # a note is given whole where it first applies, by id and topic after that
        for c_ in sec_["clauses"]:
            c_["notes"] = [{**n, "first": n["id"] not in seen} for n in c_["notes"]]
            seen.update(n["id"] for n in c_["notes"])
    clause_ids = {str(c["number"]) for c in clauses}
    added = [k for k in spec.checks if k.id not in clause_ids]
    headers = []
    for v in spec.writable_versions:
        h = spec.headers[v.header]
        if h not in headers:
            headers.append(h)
    older = [h for h in spec.headers.values() if h not in headers]
    return {"sections": sections, "added_checks": added, "headers_42": headers, "headers_older": older,
            "table_51": _table_51(spec), "history": list(m.get("history", [])),
            "approvals": list(m.get("approvals", [])),
            "release": {"date": None, "change_order": None, **dict(m.get("release", {}))},
            "clause_text": {str(c["number"]): c["text"] for c in clauses},
            "notes": _notes(spec)}


def _settable_fields(spec: Spec) -> list[Any]:
    """The header fields a CUT text may set (no derived role), once each, in header order."""
    fields: list[Any] = []
    for h in spec.headers.values():
        for f in h.fields:
            if f.role not in registry.DERIVED_HEADER_ROLES and f.name not in [g.name for g in fields]:
                fields.append(f)
    return fields


def _cut_part(spec: Spec) -> str:
    """The part number of the CUT specification 300071 cites (meta.related)."""
    return next((str(r["id"]) for r in spec.meta.get("related", []) if "(CUT)" in str(r.get("title", ""))), "?")


def _version_keyword(spec: Spec, lower: bool) -> str:
    """The keyword of the command that sets the format version ("" when none does)."""
    cmd = next((c for c in spec.commands if c.sets and "format_version" in c.sets), None)
    if cmd is None:
        return ""
    return cmd.name.lower() if lower else cmd.name


def _cut_doc(spec: Spec) -> dict[str, Any]:
    """What the companion document needs beyond spec.cut: the keywords, the header fields a CUT text
    may set, the descriptor fields of the default version, the versions without a configuration
    descriptor, the checks that report an empty descriptor, the keyword of the VERSION-like command."""
    lower = spec.cut["keyword_case"] == "lower"
    keywords = [c.name.lower() if lower else c.name for c in spec.commands]
    head = spec.header_for(spec.default_version)
    by_role = {f.role: f for f in head.fields}
    # the decision that makes this page 300072's stand-in: the one whose text names the CUT document
    cut_note = next((d.id for d in spec.decisions if "companion document" in d.text), "")
    quoted = [f'"{k}"' for k in keywords]
    rows = [" | ".join(quoted[k:k + 5]) for k in range(0, len(quoted), 5)]
    return {"keywords": keywords, "keyword_alts": "\n                | ".join(rows), "fields": _settable_fields(spec),
            "implant": by_role.get("implant_descriptor"),
            "config": by_role.get("configuration_descriptor"),
            "no_config": [v.id for v in spec.versions
                          if not any(f.role == "configuration_descriptor" for f in spec.headers[v.header].fields)],
            "descriptor_checks": spec.checks_of_kind("descriptor_word"),
            # the clauses that send the reader to the CUT document: those the CUT decision notes
            "note": cut_note,
            "part": _cut_part(spec),
            "citing": [str(c["number"]) for c in spec.meta.get("clauses", []) if cut_note in c.get("notes", [])],
            "version_command": _version_keyword(spec, lower),
            # the arguments that take the rest of the line (text: true), "COMMAND's arg", once each
            "text_args": list(dict.fromkeys(f"{c.name}'s {a.name}" for c in spec.commands for lay in c.layouts
                                            for a in lay.args if a.text)),
            # the header field the check line's N is compared with (the default version's file checksum)
            "file_checksum": next((f for f in head.fields if f.checksum == "file"), None)}


def context(spec: Spec) -> dict[str, Any]:
    """The context every page (Markdown and HTML) is rendered from."""
    report = _report()
    cases = golden.load_cases(GOLDEN)
    bindings = sorted((report or {}).get("bindings", {}))
    return {
        "spec": spec,
        "revision": spec.revision,
        "toolkit_version": __version__,
        "report": report,
        "trace": _traceability(spec, report),
        "limitations": {b: known_failures(b)[1] for b in bindings},
        "reliability": _reliability(_reliability_file()),
        "cases": cases,
        "case_names": {c.name for c in cases},
        "examples": golden.examples(spec, cases),
        "cut_example": golden.cut_example(spec, cases),
        "header_example": golden.header_example(spec, cases),
        "example": _worked_example(spec),
        "versions": [v.id for v in spec.versions],
        "figures": figures(spec),
        "record_svg": RECORD_SVG,
        "motion_svg": MOTION_SVG,
        "quantities": _quantities(spec),
        "cut_rows": _cut_rows(spec),
        "field_index": _field_index(spec),
        "golden_index": GOLDEN_INDEX,
        "field_index_page": FIELD_INDEX,
        "cut_page": CUT_PAGE,
        "doc": _document(spec),
        "cut_doc": _cut_doc(spec),
    }


def _why(k: Check, c: Command) -> str | None:
    """Why check k reads the arguments of command c, from the model and the kind's wording
    (registry.KIND_WORDING); None when it does not. Checks that read every record alike
    (sequence, code copy, size, checksum, ...) are not listed per command."""
    if any(t.command == c.name for t in k.targets):
        return f"names {c.name}"
    reads = registry.wording(k.kind).reads
    return None if reads is None else reads(k, c)


def _scope(k: Check) -> str:
    """What a check's parameters add to its prose: the versions it judges (issue 25, point 4; an
    availability check's versions are its subject, said in its text) and what its kind's wording
    says of its parameters (registry.KIND_WORDING: a range's bounds, a deprecation)."""
    out = []
    w = registry.wording(k.kind)
    if k.versions and not registry.kind(k.kind).gates and not w.own_versions:
        out.append(f"Judges files of version {', '.join(k.versions)} only.")
    if w.scope is not None and (said := w.scope(k)):
        out.append(said)
    return (" " + " ".join(out)) if out else ""


def _checksum_places(spec: Spec, tag: str) -> str:
    """Where the checksum field ``tag`` is stored, for the docs' checksum table: the header layouts
    (name and offset), the record head, or the command layouts whose arguments carry it, with the
    byte ranges of the record its named fields resolve to (issue 25, point 1)."""
    out = [f"header {h.id} `{f.name}` at {f.offset}" for h in spec.headers.values() for f in h.fields
           if f.checksum == tag]
    out += [f"record head `{f.name}` at {f.offset}" for f in spec.record.fields if f.checksum == tag]
    for c, lay, ck in spec.checksum_layouts(tag):
        spans = ", ".join(f"{a}..{b - 1}" for a, b in ck.ranges)
        out.append(f"[{c.name}]({command_page(c)}){f' layout {lay.variant}' if lay.variant else ''} "
                   f"argument `{ck.field.name}` at record byte {spec.record.head_size + ck.field.offset}, "
                   f"over {', '.join(f'`{n}`' for n in ck.covers)} (record bytes {spans})")
    return "; ".join(out)


def _checks_of(spec: Spec, c: Command) -> list[tuple[Check, str]]:
    return [(k, why) for k in spec.checks if (why := _why(k, c)) is not None]


def _environment(spec: Spec) -> Any:
    env = environment(HERE / "templates")
    env.filters["anchor"] = _anchor
    env.filters["scope"] = _scope
    env.filters["page"] = command_page
    env.filters["case_page"] = case_page
    env.filters["layout_svg"] = layout_svg
    env.filters["header_svg"] = header_svg
    env.filters["prose"] = lambda value, index="": text.prose(spec, value, index)
    env.filters["md"] = text.md_escape
    env.globals["repo_link"] = repo_link
    env.globals["checksum_places"] = lambda tag: _checksum_places(spec, tag)
    return env


def repo_link(path: str, depth: int, label: str | None = None) -> str:
    """A Markdown link from a docs page (depth: its folders below docs/) to a repository file (path from
    the repository's root), when the file is there; else its name as text (a link to nothing is broken)."""
    label = label or f"`{path}`"
    if (ROOT / path).is_file():
        return f"[{label}]({'../' * (depth + 2)}{path})"
    return label if label.startswith("`") else f"{label} (`{path}` in the toolkit's repository)"


def emit(spec: Spec, ctx: dict[str, Any] | None = None) -> dict[str, bytes]:
    """Every Markdown page and figure, by path under generated/ (ctx: a context(spec) already built)."""
    env = _environment(spec)
    ctx = ctx if ctx is not None else context(spec)
    files = {f"{OUT}/index.md": env.get_template("index.md.j2").render(**ctx).encode()}
    page = env.get_template("command.md.j2")
    for c in spec.commands:
        files[f"{OUT}/{command_page(c)}"] = page.render(c=c, checks=_checks_of(spec, c), **ctx).encode()
    files[f"{OUT}/{GOLDEN_INDEX}"] = env.get_template("golden_index.md.j2").render(**ctx).encode()
    case_tpl = env.get_template("golden_case.md.j2")
    for case in ctx["cases"]:
        files[f"{OUT}/{case_page(case.name)}"] = case_tpl.render(**golden.page_context(spec, case), **ctx).encode()
    files[f"{OUT}/{CUT_PAGE}"] = env.get_template("cut.md.j2").render(**ctx).encode()
    files[f"{OUT}/{FIELD_INDEX}"] = env.get_template("fields.md.j2").render(**ctx).encode()
    for rel, svg_text in ctx["figures"].items():
        files[f"{OUT}/{rel}"] = svg_text.encode()
    # The "Changes" page: each version against the one before it, by cbfgen diff's comparison (issue 12).
    available = {v.id: [c.name for c in spec.commands if c.available_in(v.id)] for v in spec.versions}
    files[f"{OUT}/changes.md"] = env.get_template("changes.md.j2").render(
        steps=version_steps(spec), available=available, **ctx).encode()
    return files


def reference(spec: Spec) -> str:
    """The reference page (index.md) alone: 300071 rev N with its appendices (the seed-conformance test
    renders it for many edited specs)."""
    return str(_environment(spec).get_template("index.md.j2").render(**context(spec)))
