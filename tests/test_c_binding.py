"""The C binding follows the spec: a command added to a copy of spec/cbf.yaml
appears in cbf.h (enum, struct, tables, encoder) and works in the codec after
regeneration, with no code change."""

from __future__ import annotations

import dataclasses
import functools
import json
import re
import shutil
import subprocess
import zlib
from pathlib import Path
from typing import Any

import pytest
import yaml
from conftest import cover_missing, generate, spec_doc

from cbfgen.loader import load
from cbfgen.model import Spec

ROOT = Path(__file__).resolve().parents[1]
SPEC = ROOT / "spec" / "cbf.yaml"
STRICT = ["-std=c99", "-Wall", "-Wextra", "-Wpedantic", "-Wconversion", "-Wsign-conversion", "-Wdouble-promotion",
          "-Wswitch-enum", "-Werror"]  # mk/c.mk's C_WARN
EVERYTHING = ["-std=c99", "-Weverything", "-Werror", "-Wno-padded", "-Wno-unknown-warning-option",
              "-Wno-declaration-after-statement"]  # mk/c.mk's C_EVERYTHING

DWELL: dict[str, Any] = {  # a command as spec/cbf.yaml writes one
    "name": "DWELL", "code": 0x44, "clause": "5.1", "doc": "Dwell.",
    # 1.x lacks it: the test names it in the availability check that covers 1.x
    # (the loader wants every version without the command covered by one check).
    "layouts": [{"versions": ["2.x", "3.0", "4.0"], "size": 4,
                 "args": [{"name": "seconds", "type": "f4", "unit": "s", "doc": "Dwell time."}]}],
}

PROGRAM = r"""
#define CBF_IMPLEMENTATION
#include "cbf.h"
#include <stdio.h>
#include <string.h>

static int errors;
/* errors only: a header from cbf_header_init has no part number, a warning (check 4.2) */
static void on(void *u, const cbf_finding *f)
{
    (void)u;
    printf("%s %d\n", f->check, f->severity);
    errors += f->severity == CBF_SEVERITY_ERROR;
}

int main(void)
{
    static uint8_t buf[4096];
    cbf_header h;
    cbf_writer w;
    cbf_reader r;
    cbf_record rec;
    cbf_options opt;
    struct cbf_dwell_args d;
    long n;
    int seen = 0;
    memset(&d, 0, sizeof d);
    d.seconds = 2.5f;
    if (cbf_header_init(&h, CBF_DEFAULT_VERSION) != CBF_OK) return 10;
    if (cbf_encode_begin(&w, buf, sizeof buf, &h) != CBF_OK) return 11;
    if (cbf_encode_dwell(&w, &d) != CBF_OK) return 12;
    n = cbf_encode_end(&w, CBF_PROFILE_DEFAULT, 1);
    if (n != CBF_HEADER_SIZE + CBF_RECORD_HEAD_SIZE + CBF_ARGS_DWELL_SIZE) return 13;
    memset(&opt, 0, sizeof opt);
    if (cbf_validate(buf, (size_t)n, &opt, on, NULL) != 0 || errors) return 14;
    if (cbf_reader_init(&r, buf, (size_t)n) != CBF_OK) return 15;
    while (cbf_next_record(&r, &rec) == 1) {
        if (rec.command != CBF_CMD_DWELL || rec.layout != CBF_LAYOUT_DWELL) return 16;
        if (rec.decoded.dwell.seconds != 2.5f) return 17;
        seen++;
    }
    if (seen != 1 || strcmp(cbf_command_name(0x44), "DWELL") != 0) return 18;
    if (!CBF_CMD_DWELL_IN_V3_0 || CBF_CMD_DWELL_IN_V1_X || CBF_ARGS_DWELL_SIZE_V4_0 != 4) return 19;
    {
        FILE *fp = fopen("dwell.cbf", "wb");
        if (!fp || fwrite(buf, 1, (size_t)n, fp) != (size_t)n) return 20;
        fclose(fp);
    }
    return 0;
}
"""


def _need(tool: str) -> str:
    path = shutil.which(tool)
    if path is None:
        pytest.skip(f"{tool} not installed")
    return path


def _generate(spec: Path, out: Path) -> None:
    generate(spec, out, "c")


@functools.cache
def _model() -> Spec:
    """The model of spec/cbf.yaml, loaded once per module (about 0.17 CPU s a load); tests only read it."""
    return load(SPEC)


# The DWELL and CRC-32 edits stay in trees of their own: under CRC-32 the C validator no longer
# folds the file's byte sum into its record pass, a path the DWELL record must go through.
def test_added_command_reaches_header_codec_and_testee(tmp_path: Path) -> None:
    cc = _need("gcc")
    doc = spec_doc()
    doc["units"]["s"] = {"doc": "second"}
    doc["commands"].append(DWELL)
    # every version without the command is named by exactly one availability check (loader.py)
    cover_missing(doc, DWELL)
    spec = tmp_path / "cbf.yaml"
    spec.write_text(yaml.safe_dump(doc, sort_keys=False), encoding="utf-8")
    out = tmp_path / "gen"
    _generate(spec, out)
    header = (out / "c" / "cbf.h").read_text(encoding="utf-8")
    for needle in ("CBF_CMD_DWELL = 0x44", "struct cbf_dwell_args {", "float seconds;", "Dwell time.",
                   "unit s (second)", "int cbf_encode_dwell(cbf_writer *w, const struct cbf_dwell_args *args);",
                   "CBF_LAYOUT_DWELL =", '"DWELL"'):
        assert needle in header, needle
    # The enum is sorted by code: DWELL sits between the commands with the codes around its own.
    model = _model()
    below = max((c for c in model.commands if c.code < DWELL["code"]), key=lambda c: c.code)
    above = min((c for c in model.commands if c.code > DWELL["code"]), key=lambda c: c.code)
    assert header.index(f"CBF_CMD_{below.name} = 0x{below.code:02X}") < header.index("CBF_CMD_DWELL = 0x44") < (
        header.index(f"CBF_CMD_{above.name} = 0x{above.code:02X}"))

    src = tmp_path / "dwell.c"
    src.write_text(PROGRAM, encoding="utf-8")
    exe = tmp_path / "dwell"
    subprocess.run([cc, *STRICT, "-I", str(out / "c"), "-o", str(exe), str(src), "-lm"], check=True,
                   capture_output=True)
    run = subprocess.run([str(exe)], cwd=tmp_path, capture_output=True, text=True)
    assert run.returncode == 0, run.stdout + run.stderr

    # The generated testee decodes the new command by name.
    testee = tmp_path / "testee"
    subprocess.run([cc, *STRICT, "-o", str(testee), str(out / "c" / "cbf_testee.c"), "-lm"], check=True,
                   capture_output=True)
    req = json.dumps({"op": "decode", "file": str(tmp_path / "dwell.cbf")}) + "\n" + '{"op": "quit"}\n'
    ans = subprocess.run([str(testee)], input=req, capture_output=True, text=True, check=True)
    result = json.loads(ans.stdout.splitlines()[0])
    assert result["ok"], result
    (rec,) = result["result"]["records"]
    assert rec["command"] == "DWELL" and rec["args"] == {"seconds": 2.5}


CRC_PROGRAM = r"""
#define CBF_IMPLEMENTATION
#include "cbf.h"
#include <stdio.h>
#include <string.h>

static long findings;
/* errors only: a header from cbf_header_init has no part number, a warning (check 4.2) */
static void on(void *u, const cbf_finding *f) { (void)u; findings += f->severity == CBF_SEVERITY_ERROR; }

int main(void)
{
    static uint8_t buf[4096];
    cbf_header h;
    cbf_writer w;
    cbf_options opt;
    long n;
    if (cbf_header_init(&h, CBF_DEFAULT_VERSION) != CBF_OK) return 10;
    if (cbf_encode_begin(&w, buf, sizeof buf, &h) != CBF_OK) return 11;
    if (cbf_encode_record(&w, CBF_CMD_@EMPTY@, NULL, 0) != CBF_OK) return 12;
    n = cbf_encode_end(&w, CBF_PROFILE_DEFAULT, 1);
    if (n < 0) return 13;
    memset(&opt, 0, sizeof opt);
    if (cbf_validate(buf, (size_t)n, &opt, on, NULL) != 0 || findings) return 14;
    {
        FILE *fp = fopen("crc.cbf", "wb");
        if (!fp || fwrite(buf, 1, (size_t)n, fp) != (size_t)n) return 16;
        fclose(fp);
    }
    buf[n - 1] ^= 1; /* a flipped byte in the header's end pattern */
    findings = 0;
    if (cbf_validate(buf, (size_t)n, &opt, on, NULL) < 2) return 15; /* magic and CRC */
    return 0;
}
"""


def test_checksum_algorithm_is_one_spec_line(tmp_path: Path) -> None:
    """FORMAT-NOTES: another algorithm must be a one-line spec change; the C codec follows it."""
    cc = _need("gcc")
    model = _model()
    doc = spec_doc()
    next(f for f in doc["checksums"]["fields"] if f["field"] == "file")["algorithm"] = "crc32"
    for p in doc["profiles"]:
        p.pop("file_algorithm", None)  # the field's algorithm, under every profile
    (segment,) = model.checksums.coverages[model.checksums.for_field("file").coverage].segments
    assert segment.region == "file" and segment.start is not None
    stored = model.header_checksum_field("file")
    # a command without arguments, so that the file is header plus one record head
    empty = next(c for c in model.commands if any(lay.size == 0 for lay in c.layouts_for(model.default_version)))
    spec = tmp_path / "cbf.yaml"
    spec.write_text(yaml.safe_dump(doc, sort_keys=False), encoding="utf-8")
    out = tmp_path / "gen"
    _generate(spec, out)
    src = tmp_path / "crc.c"
    src.write_text(CRC_PROGRAM.replace("@EMPTY@", empty.name), encoding="utf-8")
    exe = tmp_path / "crc"
    subprocess.run([cc, *STRICT, "-I", str(out / "c"), "-o", str(exe), str(src), "-lm"], check=True,
                   capture_output=True)
    run = subprocess.run([str(exe)], cwd=tmp_path, capture_output=True, text=True)
    assert run.returncode == 0, run.returncode
    data = (tmp_path / "crc.cbf").read_bytes()
    assert int.from_bytes(data[stored.offset:stored.end], "little") == zlib.crc32(data[segment.start:])


def test_templates_and_emitter_name_no_format_detail() -> None:
    """Command names, codes and check ids come from the model, never from the C templates or emitter."""
    doc = spec_doc()
    folder = ROOT / "generator" / "cbfgen" / "emit" / "c"
    text = "\n".join(p.read_text(encoding="utf-8") for p in sorted(folder.rglob("*"))
                     if p.is_file() and p.suffix in (".py", ".j2", ".c", ".h"))
    for cmd in doc["commands"]:
        assert not re.search(rf"\b{cmd['name']}\b", text), cmd["name"]
        assert not re.search(rf"\b0x{cmd['code']:02X}\b", text, re.IGNORECASE), cmd["name"]
    for check in doc["checks"]:
        if any(ch.isdigit() for ch in str(check["id"])):
            assert f'"{check["id"]}"' not in text, check["id"]


def test_generated_header_compiles_strictly(tmp_path: Path) -> None:
    cc = _need("gcc")
    src = tmp_path / "one.c"
    src.write_text('#define CBF_IMPLEMENTATION\n#include "cbf.h"\nint main(void) { return 0; }\n', encoding="utf-8")
    subprocess.run([cc, *STRICT, "-I", str(ROOT / "generated" / "c"), "-o", str(tmp_path / "one"), str(src), "-lm"],
                   check=True, capture_output=True)


# Spec text that ends a C comment, opens one inside another (-Werror=comment), is a trigraph that
# splices lines (??/), ends a line comment in a backslash, closes a string literal, or holds a newline.
HOSTILE = 'x /* a */ b "q" \\d ??/ ??= @param <b &amp; \n2nd line */ \\'


def _hostile_spec(doc: dict[str, object]) -> None:
    """Every free text of the spec that the C binding writes into a comment or a string literal."""
    d: dict[str, list[dict[str, object]]] = doc  # type: ignore[assignment]
    meta: dict[str, object] = doc["meta"]  # type: ignore[assignment]
    meta["title"] = HOSTILE
    for v in d["versions"]:
        v["doc"] = HOSTILE
    for p in d["profiles"]:
        p["doc"] = HOSTILE
    for unit in doc["units"].values():  # type: ignore[attr-defined]
        unit["doc"] = HOSTILE
    for h in doc["headers"].values():  # type: ignore[attr-defined]
        h["doc"] = HOSTILE
        for f in h["fields"]:
            f["doc"] = HOSTILE
    rec: dict[str, list[dict[str, object]]] = doc["record"]  # type: ignore[assignment]
    rec["doc"] = HOSTILE  # type: ignore[assignment]
    for f in rec["fields"]:
        f["doc"] = HOSTILE
    for c in d["commands"]:
        c["doc"] = HOSTILE
        for lay in c["layouts"]:  # type: ignore[attr-defined]
            lay["doc"] = HOSTILE
            for a in lay["args"]:
                a["doc"] = HOSTILE
    for ch in d["checks"]:
        ch["text"] = HOSTILE
        ch["fails"] = HOSTILE
    machine: dict[str, object] = doc["machine"]  # type: ignore[assignment]
    machine["doc"] = HOSTILE
    for lim in machine["limits"].values():  # type: ignore[attr-defined]
        lim["doc"] = HOSTILE


def test_hostile_spec_text_compiles_strictly(tmp_path: Path) -> None:
    """Spec text lands in cbf.h (comments, string literals) through escape.py's C functions only:
    a doc holding /*, */, a quote, backslashes, trigraphs and newlines gives a cbf.h that every
    strict compiler of mk/c.mk accepts, with the text's string values intact."""
    cc, clang = _need("gcc"), _need("clang")
    doc = spec_doc()
    _hostile_spec(doc)
    spec = tmp_path / "cbf.yaml"
    spec.write_text(yaml.safe_dump(doc, sort_keys=False), encoding="utf-8")
    out = tmp_path / "gen"
    _generate(spec, out)
    header = (out / "c" / "cbf.h").read_text(encoding="utf-8")
    assert "/* a */" not in header and "??/" not in header  # the text is there, escaped
    src = tmp_path / "one.c"
    src.write_text('#define CBF_IMPLEMENTATION\n#include "cbf.h"\n#include <string.h>\n'
                   "int main(void) { return strcmp(cbf_machine_limit_names[0], \"\") == 0; }\n", encoding="utf-8")
    for argv in ([cc, *STRICT], [clang, *EVERYTHING]):
        done = subprocess.run([*argv, "-I", str(out / "c"), "-o", str(tmp_path / "one"), str(src), "-lm"],
                              capture_output=True, text=True)
        assert done.returncode == 0, done.stderr[-3000:]
    assert subprocess.run([str(tmp_path / "one")]).returncode == 0
    for name in ("cbf_testee.c", "cbf_tool.c"):  # the programs built on the header, too
        done = subprocess.run([cc, *STRICT, "-c", str(out / "c" / name), "-o", str(tmp_path / (name + ".o"))],
                              capture_output=True, text=True)
        assert done.returncode == 0, done.stderr[-3000:]


# -- the registry's vocabulary in the C engine (issue #24 pt 2) ---------------------------------

RUNTIME = ROOT / "generator" / "cbfgen" / "emit" / "c" / "runtime"


def _switch_body(text: str, head: str) -> str:
    """The body of the switch that starts at ``head`` (braces matched)."""
    start = text.index(head) + len(head)
    depth, i = 1, start
    while depth:
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        i += 1
    return text[start:i - 1]


def test_c_engine_places_every_registered_kind_and_field_kind() -> None:
    """Each targeted check kind of the registry has its kernel in the engine, cbf__<kind>_at, named in the
    generated table of its shape and in no other (the validator dispatches through the tables, with no
    switch over kinds that passes kinds through); each field kind its case in the codec's load and store,
    with no default (the kinds come from cbfgen.registry, never from a list here)."""
    from cbfgen.emit.c import macro
    from cbfgen.emit.c.views import kernel_shape
    from cbfgen.registry import CHECK_KINDS, FIELD_KINDS

    validator = (RUNTIME / "validator.c").read_text(encoding="utf-8")
    assert "switch ((enum cbf__kind)" not in validator
    header = (ROOT / "generated" / "c" / "cbf.h").read_text(encoding="utf-8")
    tables = {shape: re.search(rf"static const cbf__{shape}_kernel cbf__{shape}_kernels\[[^]]*\] = \{{([^}}]*)\}};",
                               header) for shape in ("argument", "target")}
    for shape, found in tables.items():
        assert found, shape
        assert found.group(1).strip().split(", ")[0] == "NULL"  # kinds count from 1
    shapes = {k: kernel_shape(kind) for k, kind in CHECK_KINDS.items()}
    assert {"argument", "target"} <= set(shapes.values())
    for i, (k, shape) in enumerate(shapes.items(), start=1):
        for name, found in tables.items():
            assert found is not None
            entry = found.group(1).strip().split(", ")[i]
            assert entry == (f"cbf__{k}_at" if shape == name else "NULL"), (k, name, entry)
        if shape in tables:
            assert re.search(rf"^(?:CBF__INLINE|static) void cbf__{k}_at\(", validator, re.M), f"no C kernel for {k}"
            assert f"CBF__KIND_{macro(k)} = {i}" in header
    codec = (RUNTIME / "bytes.c").read_text(encoding="utf-8")
    for fn in ("static void cbf__load(", "static void cbf__store("):
        body = _switch_body(codec[codec.index(fn):], "switch ((enum cbf_field_kind)f->kind) {")
        assert "default:" not in body, fn
        missing = [k for k in FIELD_KINDS if f"case CBF_KIND_{macro(k)}:" not in body]
        assert not missing, f"{fn} lacks field kinds {missing}"


@pytest.mark.parametrize("what", ["check kind", "check kind of a pass", "field kind"])
def test_a_kind_the_c_engine_lacks_fails_the_build(what: str, tmp_path: Path,
                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    """A kind added to the registry and not to the C engine: the header of today's spec no longer
    compiles under mk/c.mk's flags, and the error names the kind. A targeted check kind: its kernel
    table names a kernel the engine lacks; a kind the engine judges in its own passes (no target): the
    generated check against runtime/validator.c's CBF__PASS_KINDS; a field kind: -Wswitch-enum."""
    cc = _need("gcc")
    import cbfgen.emit.c as emitter
    from cbfgen import registry
    from cbfgen.registry import CHECK_KINDS, FIELD_KINDS

    if what == "check kind":  # a targeted kind: its kernel's table names cbf__zz_new_rule_at
        rule = dataclasses.replace(CHECK_KINDS["positive"], name="zz_new_rule", doc="a new rule")
        extra = dict(CHECK_KINDS, zz_new_rule=rule)
        monkeypatch.setattr(registry, "CHECK_KINDS", extra)
        name = "cbf__zz_new_rule_at"
    elif what == "check kind of a pass":  # judged by no kernel table: the engine's passes must list it
        rule = dataclasses.replace(CHECK_KINDS["trailing"], name="zz_new_pass", doc="a new file rule")
        assert not rule.targeted
        monkeypatch.setattr(registry, "CHECK_KINDS", dict(CHECK_KINDS, zz_new_pass=rule))
        name = "CBF__JUDGED_CBF__KIND_ZZ_NEW_PASS"
    else:
        monkeypatch.setattr(registry, "FIELD_KINDS", (*FIELD_KINDS, "zz_new_type"))
        name = "CBF_KIND_ZZ_NEW_TYPE"
    out = emitter.emit(_model())
    (tmp_path / "cbf.h").write_bytes(out["c/cbf.h"])
    src = tmp_path / "one.c"
    src.write_text('#define CBF_IMPLEMENTATION\n#include "cbf.h"\nint main(void) { return 0; }\n', encoding="utf-8")
    argv = [cc, *STRICT, "-I", str(tmp_path), "-c", str(src), "-o", str(tmp_path / "one.o")]
    done = subprocess.run(argv, capture_output=True, text=True)
    assert done.returncode != 0 and name in done.stderr, done.stderr[-2000:]
    # and without the extra kind the same build passes (the failure is the kind's, not the flags')
    monkeypatch.undo()
    (tmp_path / "cbf.h").write_bytes(emitter.emit(_model())["c/cbf.h"])
    done = subprocess.run(argv, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr[-2000:]


TYPES_PROGRAM = r"""
#define CBF_IMPLEMENTATION
#include "cbf.h"
#include <stdio.h>
#include <string.h>

/* One field of each registered numeric type, at offset 0 of its own buffer. */
%(rows)s

int main(void)
{
    static const uint8_t in[8] = { 0x81, 0x92, 0xA3, 0xB4, 0xC5, 0xD6, 0xE7, 0x78 };
    uint8_t back[8];
%(checks)s
    return 0;
}
"""


def test_every_registered_type_has_a_c_type_read_and_written_in_the_spec_byte_order(tmp_path: Path) -> None:
    """Every numeric type of the registry: its C struct member type is the registry's c_type, and the
    codec (cbf__load, cbf__store) reads its bytes as the spec's byte order says and writes them back
    unchanged; cbf_field_bits and cbf_field_number read it in place. Expected values come from
    Python's struct with the registry's struct code."""
    import struct

    from cbfgen.emit.c import ctype
    from cbfgen.model import Field
    from cbfgen.registry import TYPES

    cc = _need("gcc")
    order = "<" if _model().meta["byte_order"] == "little" else ">"
    data = bytes([0x81, 0x92, 0xA3, 0xB4, 0xC5, 0xD6, 0xE7, 0x78])
    kinds = {"uint": "CBF_KIND_UINT", "sint": "CBF_KIND_SINT", "float": "CBF_KIND_FLOAT"}
    rows, checks = [], []
    numeric = [t for t in TYPES.values() if t.size is not None]
    assert {t.kind for t in numeric} == set(kinds), "a numeric kind this test does not know"
    for i, t in enumerate(numeric):
        assert t.size is not None and t.c_type is not None and t.struct_code is not None
        f = Field(name=t.name, type=t.name, kind=t.kind, offset=0, elem_size=t.size, count=1, doc="x", line=0)
        assert ctype(f) == (t.c_type, "")
        rows.append(f"static const cbf_field_info f{i} = {{ \"{t.name}\", NULL, {kinds[t.kind]}, 0, 0, 0, 0, "
                    f"{t.size}, 1, 0, 0u }};")
        want = struct.unpack(order + t.struct_code, data[:t.size])[0]
        bits = int.from_bytes(data[:t.size], "little" if order == "<" else "big")
        # the value as a C constant: a double for a float (exact), else a long long one (INT64_MIN safe)
        lit = (repr(float(want)) if t.kind == "float" else f"{want}ULL" if t.kind == "uint"
               else f"{want}LL" if want >= 0 else f"(-{-want - 1}LL - 1)")
        checks.append(f"""    {{
        {t.c_type} x;
        cbf__load(&f{i}, 1, in, (unsigned char *)&x);
        if (x != ({t.c_type})({lit})) {{ printf("{t.name} read wrong\\n"); return 1; }}
        memset(back, 0, sizeof back);
        cbf__store(&f{i}, 1, (const unsigned char *)&x, back);
        if (memcmp(back, in, {t.size}) != 0) {{ printf("{t.name} written wrong\\n"); return 2; }}
        if (cbf_field_bits(&f{i}, in, 0) != {bits}ULL) {{ printf("{t.name} bits wrong\\n"); return 3; }}
        if (cbf_field_number(&f{i}, in, 0) != (double)({lit})) {{ printf("{t.name} number wrong\\n"); return 4; }}
    }}""")
    src = tmp_path / "types.c"
    src.write_text(TYPES_PROGRAM % {"rows": "\n".join(rows), "checks": "\n".join(checks)}, encoding="utf-8")
    exe = tmp_path / "types"
    done = subprocess.run([cc, *STRICT, "-Wno-float-equal", "-I", str(ROOT / "generated" / "c"), "-o", str(exe),
                           str(src), "-lm"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr[-3000:]
    run = subprocess.run([str(exe)], capture_output=True, text=True)
    assert run.returncode == 0, run.stdout


TOOLS = RUNTIME.parent / "tools"
PROGRAMS = ("cbf_tools.h", "cbf_testee.c", "cbf_tool.c", "cbf_fuzz.c")


def test_tools_files_are_in_one_generated_file_verbatim() -> None:
    """Every hand-written file of the tools (generator/cbfgen/emit/c/tools/: the tools' engine, cbf-c's command
    line, the testee, the fuzz harness) sits in exactly one generated file of generated/c, once, byte for byte,
    between the markers that name it, after a #line directive that points a compiler at it: the engine that
    cbf-c and the testee share is in cbf_tools.h alone (issue #33, point 5)."""
    generated = {name: (ROOT / "generated" / "c" / name).read_text(encoding="utf-8") for name in PROGRAMS}
    files = sorted(p for p in TOOLS.iterdir() if p.suffix in (".c", ".h"))
    assert files
    for p in files:
        begin = f"/* ==== BEGIN tools/{p.name}: verbatim from generator/cbfgen/emit/c/tools/{p.name}"
        homes = [name for name, text in generated.items() if begin in text]
        assert len(homes) == 1 and generated[homes[0]].count(begin) == 1, (p.name, homes)
        text = generated[homes[0]]
        line = text.index("\n", text.index(begin)) + 1
        assert text[line:].startswith(f'#line 1 "generator/cbfgen/emit/c/tools/{p.name}"\n'), p.name
        body = text[text.index("\n", line) + 1:text.index(f"/* ==== END tools/{p.name} ==== */")]
        assert body == p.read_text(encoding="utf-8").rstrip("\n") + "\n", f"{p.name} is not verbatim"
    for name in ("cbf_testee.c", "cbf_tool.c"):  # both programs include the one engine
        assert '#include "cbf_tools.h"' in generated[name], name


def test_the_programs_templates_define_no_function() -> None:
    """The templates of the tools (cbf_tools.h, cbf_tool.c, cbf_testee.c, cbf_fuzz.c) emit the spec's names and
    tables only: no function body of hand-written C (that lives in tools/, linted by mk/c.mk)."""
    for name in PROGRAMS:
        text = (RUNTIME.parent / "templates" / f"{name}.j2").read_text(encoding="utf-8")
        bodies = re.findall(r"^[A-Za-z_][\w \*]*\([^;{}]*\)\s*\n\{", text, re.M)
        assert not bodies, (name, bodies)
        assert len(text.splitlines()) < 120, f"{name}.j2: {len(text.splitlines())} lines"


def test_runtime_files_are_in_the_header_verbatim() -> None:
    """Every hand-written runtime file (generator/cbfgen/emit/c/runtime/) sits in generated/c/cbf.h
    exactly once, byte for byte, between the markers that name it and after a #line directive that
    points a compiler at the file; and the templates hold no runtime file's code."""
    header = (ROOT / "generated" / "c" / "cbf.h").read_text(encoding="utf-8")
    files = sorted(p for p in RUNTIME.iterdir() if p.suffix in (".c", ".h"))
    assert files
    for p in files:
        text = p.read_text(encoding="utf-8").rstrip("\n")
        begin = f"/* ==== BEGIN runtime/{p.name}: verbatim from generator/cbfgen/emit/c/runtime/{p.name}"
        assert header.count(begin) == 1, p.name
        start = header.index(begin)
        after = header.index("\n", start) + 1
        assert header[after:].startswith(f'#line 1 "generator/cbfgen/emit/c/runtime/{p.name}"\n'), p.name
        body = header[header.index("\n", after) + 1:header.index(f"/* ==== END runtime/{p.name} ==== */")]
        assert body == text + "\n", f"{p.name} is not in cbf.h verbatim"
    # no template defines what a runtime file defines (one home for each function)
    templates = "\n".join(t.read_text(encoding="utf-8") for t in (RUNTIME.parent / "templates").rglob("*.j2"))
    for p in files:
        for head in re.findall(r"^(?:static |CBF__INLINE |CBF__HOT |CBF__COLD )*[a-z_][\w ]*\*?\b(cbf_\w+)\(",
                               p.read_text(encoding="utf-8"), re.M):
            assert not re.search(rf"^(?!#)[^\n;]*\b{head}\([^;{{}}]*\)\s*\n\{{", templates, re.M), head
    # after each section, #line gives cbf.h's own line numbers back
    for i, line in enumerate(header.split("\n"), start=1):
        if line.startswith('#line ') and line.endswith('"cbf.h"'):
            assert line == f'#line {i + 1} "cbf.h"'
