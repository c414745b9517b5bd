"""`cbfgen diff OLD NEW --witness DIR` (issue 37, point 5): each breaking change shown as a file.

For each wire-breaking change `cbfgen diff` reports, the smallest file of the candidates below that
the Python codecs generated from OLD and from NEW read or judge differently: its annotated hex (the
golden language of conformance/golden/README.md, assembled by the golden assembler, which imports
no binding), the .cbf it assembles to, a golden expectation (what NEW's codecs must say: the
witness is a golden case of the revised spec) and a note naming the change and what each side says.
For each text-breaking change, the canonical JSON and the CUT text NEW writes that OLD's reader refuses.

Candidates, smallest first, for the change's version (or each version of OLD, newest first, for a
change tied to none): the header alone; then one record of the change's command (or of each command
of the version, shortest first), its arguments 1 (floats 1.0, text "W"). Each is tried as NEW's
writer writes it (its checksums under NEW) and as OLD's did (under OLD, written as literal bytes);
a record whose arguments hold their own checksum (a tag but args, header, file) is tried with it
wrong too, and a check's change takes the first candidate that check's findings tell apart.
A witness is written only when both codecs were run on it and differ: an unverified one is refused.
"""

from __future__ import annotations

import dataclasses
import importlib.util
import json
import sys
import tempfile
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType
from typing import Any

import yaml

from .diff import EXIT_BAD_INPUT, EXIT_UNVERIFIED, Change
from .loader import load
from .model import Command, Field, Layout, Spec


@dataclass(frozen=True)
class Line:
    """One line of annotated hex: its text, and where its bytes go (a checksum line's are literalized)."""

    text: str
    comment: str
    offset: int
    size: int
    checksum: bool = False


@dataclass(frozen=True)
class Candidate:
    label: str
    version: str
    lines: tuple[Line, ...]
    writer: str  # "new" | "old": whose checksums the file holds
    broken: bool = False  # an argument field's own checksum (a tag but args, header, file) stored wrong


@dataclass(frozen=True)
class Side:
    """What one codec says of a file: its decode (canonical JSON or the error) and its findings."""

    decode: Any
    findings: dict[str, list[tuple[str, str, int | None, int | None]]]


@dataclass(frozen=True)
class Witness:
    change: Change
    name: str
    hex: str
    data: bytes
    old: Side
    new: Side
    says: tuple[str, ...]  # how the two differ, one line each


# -- the candidates, as annotated hex built from the spec's roles ------------------------------------
def _uint(size: int, value: int) -> str:
    if size in (1, 2, 4, 8):
        return f"u{8 * size} {value}"
    return " ".join(f"{b:02x}" for b in value.to_bytes(size, "little"))


def _header(spec: Spec, vid: str, count: int) -> list[Line]:
    version = next(v for v in spec.versions if v.id == vid)
    out = []
    for f in spec.headers[version.header].fields:
        size = f.elem_size * f.count
        values = {"version_major": version.major, "version_minor": version.minor or 0, "command_count": count}
        if f.checksum:
            text = f"checksum {f.checksum}"
        elif f.magic is not None:
            text = " ".join(f"{b:02x}" for b in f.magic.to_bytes(size, "little"))
        elif f.kind == "string":
            text = f'str {size} "{"WITNESS" if f.role == "implant_descriptor" else "CFG-A"}"'
        elif f.role in values:
            text = _uint(size, values[f.role or ""])
        else:
            text = f"zeros {size}"
        out.append(Line(text, f"{f.offset:<4d}{f.name}", f.offset, size, bool(f.checksum)))
    return out


def _arg(f: Field, at: int) -> tuple[Line, int]:
    n = f.count * (f.repeat[0] if f.repeat else 1)
    size = f.elem_size * n
    if f.checksum:
        text = f"checksum {f.checksum}"
    elif f.kind == "float" and f.elem_size == 4:
        text = "f32 " + " ".join(["1"] * n)
    elif f.kind in ("uint", "sint") and f.elem_size in (1, 2, 4, 8):
        text = f"{'u' if f.kind == 'uint' else 'i'}{8 * f.elem_size} " + " ".join(["1"] * n)
    elif f.kind == "string":
        text = f'str {size} "W"'
    else:
        text = f"zeros {size}"
    return Line(text, f"{at:<4d}{f.name}", at, size, bool(f.checksum)), size


def _record(spec: Spec, cmd: Command, lay: Layout, at: int) -> list[Line]:
    args: list[Line] = []
    pos = at + spec.record.head_size
    for f in lay.args:
        line, size = _arg(f, pos)
        args.append(line)
        pos += size
    nb = pos - at - spec.record.head_size
    values = {"sequence": 0, "code": cmd.code, "code_copy": cmd.code, "arg_size": nb}
    head = []
    for f in spec.record.fields:
        size = f.elem_size * f.count
        text = f"checksum {f.checksum}" if f.checksum else _uint(size, values.get(f.role or "", 0))
        head.append(Line(text, f"{at + f.offset:<4d}record 0 {f.name}" + (f" ({cmd.name})" if f.role == "code" else ""),
                         at + f.offset, size, bool(f.checksum)))
    return head + args


def _versions(change: Change, old: Spec) -> list[str]:
    if change.version:
        return [change.version]
    return [v.id for v in reversed(old.versions)]


def _commands(change: Change, specs: tuple[Spec, Spec], vid: str) -> list[tuple[Spec, Command, Layout]]:
    """(spec, command, its layout for vid): the change's command in either spec, else every command."""
    out = []
    for spec in specs:
        for cmd in spec.commands:
            if change.command and cmd.name != change.command:
                continue
            lay = next((lay for lay in cmd.layouts if vid in lay.versions and not lay.variant), None)
            lay = lay or next((lay for lay in cmd.layouts if vid in lay.versions), None)
            if lay is not None:
                out.append((spec, cmd, lay))
    return sorted(out, key=lambda t: (sum(f.elem_size * f.count for f in t[2].args), t[1].code))


def candidates(change: Change, old: Spec, new: Spec) -> Iterator[Candidate]:
    for vid in _versions(change, old):
        owner = new if any(v.id == vid for v in new.versions) else old
        for writer in ("new", "old"):
            yield Candidate(f"a {vid} file, header only", vid, tuple(_header(owner, vid, 0)), writer)
        for spec, cmd, lay in _commands(change, (new, old), vid):
            lines = _header(owner, vid, 1) + _record(spec, cmd, lay, sum(ln.size for ln in _header(owner, vid, 1)))
            for writer in ("new", "old"):
                yield Candidate(f"a {vid} file holding one {cmd.name}", vid, tuple(lines), writer)
            own = [ln.text.split()[1] for ln in lines if ln.checksum and ln.text.split()[1] not in _FILLED_TAGS]
            for writer in ("new", "old") if own else ():
                yield Candidate(f"a {vid} file holding one {cmd.name}, its {', '.join(own)} wrong", vid,
                                tuple(lines), writer, broken=True)


_FILLED_TAGS = ("args", "header", "file")  # the checksums every file has: never broken on purpose


def materialize(c: Candidate, spec: Path, name: str) -> tuple[Candidate, bytes]:
    """The candidate's bytes under spec (its writer's); a broken one's own checksums as literal wrong
    bytes (each byte of the right value inverted), the checksums covering them computed after."""
    from conformance.assembler import assemble_text  # the golden assembler: it imports no binding

    data = assemble_text("\n".join(ln.text for ln in c.lines) + "\n", name, spec=spec)
    if not c.broken:
        return c, data
    lines = tuple(dataclasses.replace(
        ln, text=" ".join(f"{b ^ 0xFF:02x}" for b in data[ln.offset:ln.offset + ln.size]),
        comment=f"{ln.comment} ({ln.text.split()[1]}, wrong on purpose)", checksum=False)
        if ln.checksum and ln.text.split()[1] not in _FILLED_TAGS else ln for ln in c.lines)
    c = dataclasses.replace(c, lines=lines)
    return c, assemble_text("\n".join(ln.text for ln in c.lines) + "\n", name, spec=spec)


def hex_text(c: Candidate, data: bytes, head: list[str]) -> str:
    """The candidate as annotated hex: a checksum of OLD's writer as its literal bytes (the file then
    assembles the same under any spec), NEW's as a placeholder the assembler fills from the spec."""
    out = [f"# {line}" for line in head]
    for ln in c.lines:
        text, note = ln.text, ln.comment
        if ln.checksum and c.writer == "old":
            text = " ".join(f"{b:02x}" for b in data[ln.offset:ln.offset + ln.size])
            note += f" ({ln.text[len('checksum '):]} as OLD computes it)"
        out.append(f"{text:<34s}# {note}")
    return "\n".join(out) + "\n"


# -- running both codecs ----------------------------------------------------------------------------
def codec(spec: Spec, where: Path, name: str) -> ModuleType:
    """The Python codec generated from spec into where/, imported as package `name` (two side by side)."""
    from .emit import python as emit_python  # the Python emitter only: what the verification runs

    for rel, data in emit_python.emit(spec).items():
        dest = where / rel
        dest.parent.mkdir(parents=True, exist_ok=True)
        dest.write_bytes(data)
    init = where / "python" / "cbf" / "__init__.py"
    found = importlib.util.spec_from_file_location(name, init, submodule_search_locations=[str(init.parent)])
    assert found is not None and found.loader is not None
    module = importlib.util.module_from_spec(found)
    sys.modules[name] = module
    found.loader.exec_module(module)
    return module


def judge(cbf: Any, profiles: tuple[str, ...], data: bytes) -> Side:
    try:
        decoded: Any = cbf.to_canonical(cbf.decode(data))
    except cbf.CbfError as exc:
        decoded = {"error": {"kind": exc.kind, "offset": exc.offset}}
    findings = {}
    for p in profiles:
        found = cbf.validate(data, profile=p)
        findings[p] = sorted((str(f.check), f.severity, f.record, f.offset) for f in found)
    return Side(decoded, findings)


def _json_differences(a: Any, b: Any, path: str = "$") -> Iterator[str]:
    """Where two decodes differ: each leaf (a key only one side has, with its value)."""
    if isinstance(a, dict) and isinstance(b, dict):
        for k in list(a) + [k for k in b if k not in a]:
            if k not in b:
                yield f"OLD reads {path}.{k} = {json.dumps(a[k])}, NEW has no {k}"
            elif k not in a:
                yield f"NEW reads {path}.{k} = {json.dumps(b[k])}, OLD has no {k}"
            else:
                yield from _json_differences(a[k], b[k], f"{path}.{k}")
    elif isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        for i, (x, y) in enumerate(zip(a, b, strict=True)):
            yield from _json_differences(x, y, f"{path}[{i}]")
    elif a != b:
        yield f"{path}: OLD reads {json.dumps(a)}, NEW {json.dumps(b)}"


def _new_values(a: Any, b: Any, pointer: str = "") -> Iterator[tuple[str, Any]]:
    """(JSON pointer, NEW's value) where NEW's decode differs from OLD's: what a golden case pins."""
    if isinstance(a, dict) and isinstance(b, dict):
        for k in b:
            yield from ([(f"{pointer}/{k}", b[k])] if k not in a else _new_values(a[k], b[k], f"{pointer}/{k}"))
    elif isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        for i, (x, y) in enumerate(zip(a, b, strict=True)):
            yield from _new_values(x, y, f"{pointer}/{i}")
    elif a != b:
        yield pointer, b


def _decode_text(d: Any) -> str:
    if isinstance(d, dict) and set(d) == {"error"}:
        return f"refuses it ({d['error']['kind']} at offset {d['error']['offset']})"
    return "reads it"


def differences(old: Side, new: Side) -> tuple[str, ...]:
    """How the two sides differ, one line each (empty: they agree)."""
    out = []
    if old.decode != new.decode:
        a, b = _decode_text(old.decode), _decode_text(new.decode)
        out.extend([f"decode: OLD {a}, NEW {b}"] if a != b else
                   [f"decode: {d}" for d in list(_json_differences(old.decode, new.decode))[:4]])
    for p in sorted(set(old.findings) & set(new.findings)):
        if old.findings[p] != new.findings[p]:
            gone = [f for f in old.findings[p] if f not in new.findings[p]]
            came = [f for f in new.findings[p] if f not in old.findings[p]]
            out.extend(f"validate [{p}]: only {who} finds {_findings(fs)}" for who, fs in (("OLD", gone), ("NEW", came))
                       if fs)
    return tuple(out)


def _findings(fs: list[tuple[str, str, int | None, int | None]]) -> str:
    return ", ".join(f"{c}/{s} ({'header' if r is None else f'record {r}'}, offset {o})" for c, s, r, o in fs)


# -- a witness per breaking change -----------------------------------------------------------------
@dataclass(frozen=True)
class Codecs:
    """The two specs (their files, loaded) and their generated codecs, shared by every change."""

    old_path: Path
    new_path: Path
    old: Spec
    new: Spec
    old_codec: Any
    new_codec: Any


def _check_of(change: Change) -> str | None:
    """The check a check change is about (its detail starts with the id), else None."""
    return change.detail.split()[0].rstrip(":") if change.kind.startswith("check_") else None


def _shows_check(check: str | None, old: Side, new: Side) -> bool:
    if check is None:
        return True
    return any(f[0] == check for p in set(old.findings) | set(new.findings)
               for f in set(old.findings.get(p, [])) ^ set(new.findings.get(p, [])))


def find(change: Change, cx: Codecs, name: str) -> Witness | None:
    """The first candidate both codecs were run on and that they read or judge differently, or None. For
    a check's change, the first whose findings differ in that check (else the first that differs)."""
    from conformance.assembler import AsmError, assemble_text  # the golden assembler: it imports no binding

    check, fallback = _check_of(change), None
    for c in candidates(change, cx.old, cx.new):
        try:
            c, data = materialize(c, cx.new_path if c.writer == "new" else cx.old_path, name)
        except AsmError:  # a file its writer could not write (a checksum tag its spec lacks): not a candidate
            continue
        old = judge(cx.old_codec, tuple(p.id for p in cx.old.profiles), data)
        new = judge(cx.new_codec, tuple(p.id for p in cx.new.profiles), data)
        says = differences(old, new)
        if not says:
            continue
        head = [f"Witness of {change.kind} ({change.detail}): {c.label}, as {c.writer.upper()}'s writer writes it.",
                "OLD's and NEW's generated codecs differ on it (cbfgen diff --witness ran both):", *says]
        text = hex_text(c, data, head)
        if assemble_text(text, name, spec=cx.new_path) != data:  # the hex written must be the file verified
            continue
        found = Witness(change, name, text, data, old, new, says)
        if _shows_check(check, old, new):
            return found
        fallback = fallback or found
    return fallback


def expectation(w: Witness) -> dict[str, Any]:
    """The golden expectation of the witness: what NEW's codecs say (conformance/golden/README.md)."""
    d = w.new.decode
    refused = isinstance(d, dict) and set(d) == {"error"}
    doc: dict[str, Any] = {"description": f"Witness of {w.change.kind}: {w.change.detail}", "clauses": [],
                           "decode": {"error": d["error"]} if refused else "ok"}
    if not refused and not (isinstance(w.old.decode, dict) and set(w.old.decode) == {"error"}):
        subset = dict(list(_new_values(w.old.decode, d))[:4])  # where NEW reads otherwise: OLD fails these
        if subset:
            doc["decode_subset"] = subset
    doc["validate"] = {p: [list(f) for f in fs] for p, fs in w.new.findings.items()}
    return doc


def note(w: Witness) -> dict[str, Any]:
    return {"change": w.change.as_json(), "size": len(w.data), "differences": list(w.says),
            "old": {"decode": _decode_text(w.old.decode), "findings": {p: [list(f) for f in fs]
                                                                       for p, fs in w.old.findings.items()}},
            "new": {"decode": _decode_text(w.new.decode), "findings": {p: [list(f) for f in fs]
                                                                       for p, fs in w.new.findings.items()}}}


def _refusal(cbf: Any, form: str, text: str) -> str | None:
    """Why a codec's reader of a form (json, cut) refuses a text (its error, one line), or None when it reads it."""
    try:
        if form == "json":
            cbf.from_canonical(json.loads(text))
        else:
            cbf.from_cut(text)
    except (cbf.CbfError, KeyError, ValueError) as exc:
        return f"{type(exc).__name__}: {' '.join(str(exc).split())}"
    return None


def text_witness(change: Change, cx: Codecs) -> dict[str, Any] | None:
    """For a text-breaking change: the canonical JSON and the CUT text NEW writes of a file showing it,
    each kept when NEW reads it back and OLD refuses it (a name OLD does not know); None when no
    candidate shows one in either form."""
    from conformance.assembler import assemble_text

    new, old = cx.new_codec, cx.old_codec
    for c in candidates(change, cx.old, cx.new):
        if c.writer != "new" or "holding" not in c.label:
            continue
        data = assemble_text("\n".join(ln.text for ln in c.lines) + "\n", "text", spec=cx.new_path)
        try:
            model = new.decode(data)
            forms = {"json": json.dumps(new.to_canonical(model), indent=1) + "\n", "cut": new.to_cut(model)}
        except new.CbfError:
            continue
        shown: dict[str, Any] = {"change": change.as_json(), "file": c.label}
        for form, text in forms.items():
            if _refusal(new, form, text) is None:
                why = _refusal(old, form, text)
                if why:
                    shown[form] = {"text": text, "old": f"refuses it ({why})", "new": "reads it"}
        if "json" in shown or "cut" in shown:
            return shown
    return None


def _yaml(doc: dict[str, Any]) -> str:
    return str(yaml.safe_dump(doc, sort_keys=False, default_flow_style=None, width=1000))


def write(ws: list[Witness], texts: list[dict[str, Any]], out: Path) -> None:
    out.mkdir(parents=True, exist_ok=True)
    for w in ws:
        (out / f"{w.name}.hex").write_text(w.hex, encoding="utf-8")
        (out / f"{w.name}.cbf").write_bytes(w.data)
        (out / f"{w.name}.expect.yaml").write_text(_yaml(expectation(w)), encoding="utf-8")
        (out / f"{w.name}.witness.yaml").write_text(_yaml(note(w)), encoding="utf-8")
    for i, t in enumerate(texts, 1):
        ch = t["change"]
        name = ".".join(["text", str(i), ch["kind"]] + [f"v{ch['version']}"] * bool(ch["version"])
                        + [ch["command"] or ""] * bool(ch["command"]))
        for form in ("json", "cut"):
            if form in t:
                (out / f"{name}.{form}").write_text(t[form]["text"], encoding="utf-8")
        said = {k: ({"old": v["old"], "new": v["new"]} if k in ("json", "cut") else v) for k, v in t.items()}
        (out / f"{name}.witness.yaml").write_text(_yaml(said), encoding="utf-8")


def codecs(old_path: Path, new_path: Path, where: Path) -> Codecs:
    old, new = load(old_path), load(new_path)
    return Codecs(old_path, new_path, old, new, codec(old, where / "old", "cbf_witness_old"),
                  codec(new, where / "new", "cbf_witness_new"))


def witnesses(changes: tuple[Change, ...], cx: Codecs) -> tuple[list[Witness], list[Change]]:
    """A verified witness per wire-breaking change, and the changes none was found for."""
    found, missing = [], []
    for i, ch in enumerate(c for c in changes if c.breaking):
        name = ".".join(["witness", str(i + 1), ch.kind] + [f"v{ch.version}"] * bool(ch.version)
                        + [ch.command or ""] * bool(ch.command))
        w = find(ch, cx, name)
        if w is None:
            missing.append(ch)
        else:
            found.append(w)
    return found, missing


def run(changes: tuple[Change, ...], old_path: Path, new_path: Path, out: Path) -> int:
    """Write the witnesses of changes to out; 0, or EXIT_UNVERIFIED when a change has none (said on stderr);
    EXIT_BAD_INPUT, one line, when out is not a folder or the golden assembler is missing (a cbfgen wheel
    without the toolkit's checkout: the witnesses are assembled by conformance/assembler)."""
    if out.exists() and not out.is_dir():
        print(f"cbfgen diff: --witness {out}: not a folder", file=sys.stderr)
        return EXIT_BAD_INPUT
    if importlib.util.find_spec("conformance.assembler") is None:
        print("cbfgen diff: --witness needs the golden assembler (conformance/assembler of the CBF toolkit's "
              "checkout on PYTHONPATH)", file=sys.stderr)
        return EXIT_BAD_INPUT
    with tempfile.TemporaryDirectory(prefix="cbf-witness-") as tmp:
        cx = codecs(old_path, new_path, Path(tmp))
        found, missing = witnesses(changes, cx)
        texts = [t for ch in changes if ch.text_breaking and not ch.breaking for t in [text_witness(ch, cx)] if t]
    write(found, texts, out)
    for w in found:
        print(f"witness: {out / (w.name + '.hex')}: {len(w.data)} bytes; {'; '.join(w.says)}")
    for t in texts:
        for form in ("json", "cut"):
            if form in t:
                print(f"witness: {t['change']['kind']} {t['change']['command'] or ''}: the {form.upper()} NEW writes, "
                      f"OLD {t[form]['old']}")
    for ch in missing:
        print(f"cbfgen diff: no file shows {ch.kind} ({ch.detail}): no witness written", file=sys.stderr)
    return EXIT_UNVERIFIED if missing else 0
