"""Repeated argument groups (issue 25, point 3): the drill fixture tests/revisions/polyline.yaml (a
command whose argument is n points, nb = 12 n) applied to a copy of the spec, the Python package and
the C binding generated from it, and, in that package: binary, CUT and canonical JSON round trips for
random n (hypothesis, derandomised under the ci profile), the nb that no n tiles refused by the
writer and the CUT reader, and continuity through the polyline's last point; in C: the struct's
bounded array and n (encode refuses n out of range, decode leaves an untiled nb raw), and the C
testee against the Python binding on files with non-finite points, points out of the machine's
workspace and untiled nb (decode, validate with every finding's words, encode back to the bytes).

The loader refuses groups while a binding lacks them (registry.REPEAT_BINDINGS): every binding of
registry.BINDINGS carries them now, and the gate still refuses one that would not.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import pytest
import yaml
from conftest import HYPOTHESIS_PROFILE, REPO, dump_yaml, spec_doc
from revisions.drill import apply_edit, load_fixture, render

from cbfgen import loader
from cbfgen.emit import c as c_emit
from cbfgen.emit import python as py_emit
from cbfgen.model import Spec

FIXTURE = REPO / "tests" / "revisions" / "polyline.yaml"

SCRIPT = r"""
import math, struct, sys
from hypothesis import given, settings, strategies as st
import cbf
from cbf import tables as T
from cbf.errors import EncodeError
from cbf.layouts import CommandCode, Line, Point
from cbf.model import Cbf, Record, new_header

NAME = sys.argv[1]
cmd = T.BY_NAME[NAME]
lays = [lay for lay in cmd.layouts if lay.n is not None]
grp = lays[0].repeated
LO, HI = grp.repeat
K = grp.size // grp.items   # bytes per item, from the tables
FIXED = lays[0].size - K * lays[0].n
cls = lays[0].cls
version = next(v for v in T.VERSIONS if v.writable and cmd.layouts_for(v.id))
vtext = f"{version.major}.{version.minor or 0}"
f32 = st.floats(-500, 500, width=32)
vec = st.tuples(f32, f32, f32)

@settings(max_examples=int(sys.argv[2]), derandomize=sys.argv[3] == "ci", database=None, deadline=None)
@given(st.integers(LO, HI).flatmap(lambda n: st.lists(vec, min_size=n, max_size=n)))
def round_trip(points):
    model = Cbf(new_header(vtext, implant_descriptor="PN-1"),
                (Record.of(Point(point=(0.0, 0.0, 0.0))), Record.of(cls(points=tuple(points))),
                 Record.of(Line(start=points[-1], end=(1.0, 1.0, 1.0)))))
    data = cbf.encode(model)
    back = cbf.decode(data)
    rec = back.records[1]
    assert len(rec.raw_args) == FIXED + K * len(points)          # nb = fixed + k n
    assert rec.decode_args(back.version_id) == cls(points=tuple(points))
    assert cbf.encode(back) == data                               # encode(decode(b)) == b
    text = cbf.to_cut(back)
    line = text.splitlines()[-2]
    assert line.split()[0] == NAME.lower() and line.count("<") == len(points), line
    assert cbf.encode(cbf.from_cut(text)) == data                 # CUT written and read back exactly
    assert cbf.encode(cbf.from_canonical(cbf.to_canonical(back))) == data
    # continuity runs through the polyline: the LINE starts at its last point
    assert not [f for f in cbf.validate(data) if f.check == "6.4.5"]

round_trip()

# n outside min..max: the writer refuses, naming the group (the golden cases hold the validator's findings)
for n in (LO - 1, HI + 1):
    if n < 0 or FIXED + K * n > T.LIMITS["max_arg_size"]:
        continue
    try:
        cbf.encode(Cbf(new_header(vtext), (Record.of(cls(points=((1.0, 2.0, 3.0),) * n)),)))
    except EncodeError as exc:
        assert "points" in str(exc) and f"{LO} to {HI}" in str(exc), exc
    else:
        raise AssertionError(f"n={n} encoded")
# a LINE that starts at the polyline's FIRST point is discontinuous (the end is the last point)
# (the writer refuses it, naming the continuity check and the distance from the last point)
pts = ((1.0, 2.0, 3.0), (50.0, 50.0, 50.0))
cont = [c["id"] for c in T.CHECKS if c["kind"] == "continuity"]
try:
    cbf.encode(Cbf(new_header(vtext), (Record.of(Point(point=(0.0, 0.0, 0.0))), Record.of(cls(points=pts)),
                                       Record.of(Line(start=pts[0], end=(1.0, 1.0, 1.0))))))
except EncodeError as exc:
    away = f"{math.dist(pts[0], pts[-1]):.4f}"
    assert f"fail check {cont[0]}" in str(exc) and "record 2" in str(exc) and away in str(exc), exc
else:
    raise AssertionError("a LINE from the polyline's first point was written")
try:
    cbf.from_cut(f"{NAME.lower()}\n")
except Exception as exc:
    assert "0 items" in str(exc), exc
else:
    raise AssertionError("an empty group was read")
print("ok")
"""


def _revised_spec(tmp: Path) -> Path:
    doc = spec_doc()
    fx = load_fixture(FIXTURE, doc)
    for edit in fx.edits:
        if "file" not in edit:
            apply_edit(doc, edit)
    path = tmp / "cbf.yaml"
    path.write_text(dump_yaml(doc), encoding="utf-8")
    return path


@dataclass(frozen=True)
class Revised:
    spec: Spec
    gen: Path  # the Python package (gen/python) and the C binding (gen/c) of the revised spec
    name: str  # the fixture's variable-length command


@pytest.fixture(scope="module")
def revised(tmp_path_factory: pytest.TempPathFactory) -> Revised:
    tmp = tmp_path_factory.mktemp("polyline")
    spec: Spec = loader.load(_revised_spec(tmp))
    for rel, data in [*py_emit.emit(spec).items(), *c_emit.emit(spec).items()]:
        out = tmp / "gen" / rel
        out.parent.mkdir(parents=True, exist_ok=True)
        out.write_bytes(data)
    return Revised(spec, tmp / "gen", render("${name:POLYLINE}", spec_doc(), "test"))


@pytest.fixture(scope="module")
def package(revised: Revised) -> tuple[Path, str]:
    return revised.gen / "python", revised.name


def test_every_binding_carries_groups_and_the_gate_refuses_one_that_would_not(tmp_path: Path) -> None:
    from cbfgen import registry

    assert registry.repeat_unsupported() == ()
    spec = loader.load(_revised_spec(tmp_path))  # no binding is missing: the loader lets the group through
    assert any(lay.repeated is not None for c in spec.commands for lay in c.layouts)
    for missing in registry.BINDINGS:
        with pytest.MonkeyPatch.context() as mp:
            mp.setattr(registry, "REPEAT_BINDINGS", tuple(b for b in registry.BINDINGS if b != missing))
            with pytest.raises(loader.SpecError, match=f"not implemented by the binding\\(s\\) {missing} "):
                loader.load(_revised_spec(tmp_path))


def test_round_trips_for_random_n(package: tuple[Path, str]) -> None:
    pkg, name = package
    profile = HYPOTHESIS_PROFILE
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(pkg), *sys.path]))
    run = subprocess.run([sys.executable, "-c", SCRIPT, name, "60", profile], env=env, capture_output=True,
                         text=True, cwd=pkg)
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-4000:]
    assert run.stdout.strip().endswith("ok")


def test_diff_classifies_groups(tmp_path: Path) -> None:
    """cbfgen diff: the new variable command is a command_added whose size says nb = fixed + k n; a
    changed min or max of an existing version's group changes which files are judged valid: breaking."""
    from cbfgen.diff import diff

    base = tmp_path / "base"
    base.mkdir()
    new_path = _revised_spec(base)
    narrowed = yaml.safe_load(new_path.read_text(encoding="utf-8"))
    name = render("${name:POLYLINE}", spec_doc(), "test")
    group = next(c for c in narrowed["commands"] if c["name"] == name)["layouts"][0]["args"][-1]
    group["repeat"]["max"] -= 1
    narrow_path = tmp_path / "narrow.yaml"
    narrow_path.write_text(dump_yaml(narrowed), encoding="utf-8")
    old, new, narrow = loader.load(REPO / "spec" / "cbf.yaml"), loader.load(new_path), loader.load(narrow_path)
    added = [c for c in diff(old, new).changes if c.kind == "command_added"]
    assert added and all(" n (" in c.detail for c in added)
    changed = [c for c in diff(new, narrow).changes if c.kind == "field_repeat_changed"]
    assert changed and all(c.breaking for c in changed)


def test_kaitai_reads_the_group_count_from_nb(tmp_path: Path) -> None:
    """The .ksy: the group as `repeat: expr` with n from the argument substream's size, one args case per
    nb the group takes, and the arg_size rule accepting exactly nb = fixed + k n for n in min..max."""
    from cbfgen.emit.kaitai import build

    spec = loader.load(_revised_spec(tmp_path))
    ksy = build(spec)
    cmd = next(c for c in spec.commands if any(lay.repeated is not None for lay in c.layouts))
    lay = next(lay for lay in cmd.layouts if lay.repeated is not None)
    rep = lay.repeated
    assert rep is not None and rep.repeat is not None
    seq = ksy["types"]["args_" + cmd.name.lower()]["seq"]
    assert seq[-1]["repeat"] == "expr"
    assert seq[-1]["repeat-expr"] == f"(_io.size - {lay.size}) / {rep.size}" + (
        f" * {rep.count}" if rep.count > 1 else "")
    record = {a["id"]: a for a in ksy["types"]["record"]["seq"]}
    cases = record["args"]["type"]["cases"]
    vi = 1 + [v.id for v in spec.versions].index(lay.versions[0])
    taken = {nb for nb in range(256) if cases.get(cmd.code * 65536 + nb * 256 + vi) == "args_" + cmd.name.lower()}
    assert taken == set(lay.sizes)
    lo, hi = lay.size + rep.size * rep.repeat[0], lay.size + rep.size * rep.repeat[1]
    size_rule = next(a for a in record.values() if a.get("valid", {}).get("expr", "").count("?"))
    assert f"(_ >= {lo} and _ <= {hi} and (_ - {lay.size}) % {rep.size} == 0)" in size_rule["valid"]["expr"]


# -- the C binding ----------------------------------------------------------------------------
def _cc() -> str:
    cc = shutil.which("gcc")
    if cc is None:
        pytest.skip("gcc not installed")
    return cc


C_PROGRAM = r"""
#define CBF_IMPLEMENTATION
#include "cbf.h"
#include <stdio.h>
#define LAY CBF_LAYOUT_%(layout)s
#define FAIL(what) do { printf("FAIL %%s\n", what); fails++; } while (0)
static cbf_args a, b;
static uint8_t buf[CBF_MAX_ARG_SIZE + 64];

/* a group of n items whose bytes are i * 7 + 1 (any bits: encode and decode copy them exactly) */
static void fill(size_t n)
{
    unsigned char *p = (unsigned char *)&a.%(member)s.%(group)s.items;
    size_t i;
    memset(&a, 0, sizeof a);
    for (i = 0; i < n * %(item)du; i++)
        p[i] = (unsigned char)(i * 7u + 1u);
    a.%(member)s.%(group)s.n = n;
}

int main(void)
{
    size_t mn = 0, mx = 0, item = 0, ns[2] = { %(lo)du, %(hi)du }, k;
    int fails = 0;
    long nb;
    if (cbf_layout_group(LAY, &mn, &mx, &item) != %(index)d || mn != %(lo)du || mx != %(hi)du || item != %(item)du)
        FAIL("cbf_layout_group");
    if (sizeof a.%(member)s.%(group)s.items != %(hi)du * sizeof a.%(member)s.%(group)s.items[0])
        FAIL("the array is not bounded by max n");
    for (k = 0; k < 2; k++) {
        fill(ns[k]);
        nb = cbf_args_encode(LAY, &a, buf, sizeof buf);
        if (nb != (long)(%(fixed)du + %(item)du * ns[k]) || cbf_layout_nb(LAY, ns[k]) != nb)
            FAIL("encode: nb = fixed + k n");
        if (cbf_args_decode(LAY, buf, (size_t)nb, &b) != nb || memcmp(&a, &b, sizeof a) != 0)
            FAIL("decode(encode(a)) == a");
        if (cbf_args_layout(CBF_CMD_%(command)s, CBF_V%(version)s, (size_t)nb) != LAY
            || cbf_layout_items(LAY, (size_t)nb) != (long)ns[k])
            FAIL("n from nb");
    }
    fill(%(hi)du + 1u);
    if (cbf_args_encode(LAY, &a, buf, sizeof buf) != CBF_ERR_RANGE || cbf_layout_nb(LAY, %(hi)du + 1u) != CBF_ERR_RANGE)
        FAIL("n above max written");
    if (%(lo)du > 0u) {
        fill(%(lo)du - 1u);
        if (cbf_args_encode(LAY, &a, buf, sizeof buf) != CBF_ERR_RANGE)
            FAIL("n below min written");
    }
    fill(%(hi)du);
    if (cbf_args_encode(LAY, &a, buf, %(fixed)du + %(item)du * %(hi)du - 1u) != CBF_ERR_BUFFER)
        FAIL("a buffer one byte short");
    /* an nb no n tiles: not a layout of the command, the arguments stay raw */
    nb = (long)(%(fixed)du + %(item)du * %(hi)du + 1u);
    if (cbf_args_decode(LAY, buf, (size_t)nb, &b) != CBF_ERR_RANGE
        || cbf_args_layout(CBF_CMD_%(command)s, CBF_V%(version)s, (size_t)nb) != CBF_LAYOUT__NONE
        || cbf_layout_items(LAY, (size_t)nb) != -1)
        FAIL("an untiled nb decoded");
    if (!fails)
        puts("ok");
    return fails != 0;
}
"""


def test_c_struct_holds_a_bounded_group_and_the_codec_keeps_n(revised: Revised, tmp_path: Path) -> None:
    """The C API on the fixture's group, every name and number from the model: the struct's items
    bounded by max n, encode writing exactly n items (nb = fixed + k n) and refusing n outside min..max,
    decode(encode(a)) == a, n from nb, an nb no n tiles left undecoded."""
    from cbfgen.emit.c import cname, macro

    cmd = next(c for c in revised.spec.commands if c.name == revised.name)
    lay = next(lay for lay in cmd.layouts if lay.repeated is not None)
    rep = lay.repeated
    assert rep is not None and rep.repeat is not None
    version = next(v for v in revised.spec.versions if v.writable and v.id in lay.versions)
    src = tmp_path / "group.c"
    src.write_text(C_PROGRAM % {
        "layout": macro(cmd.name) + (("_" + macro(lay.variant)) if lay.variant else ""),
        "member": cname(cmd.name) + (("_" + cname(lay.variant)) if lay.variant else ""), "group": cname(rep.name),
        "command": macro(cmd.name), "version": macro(version.id), "index": len(lay.args) - 1, "lo": rep.repeat[0],
        "hi": rep.repeat[1], "item": rep.size, "fixed": lay.size}, encoding="utf-8")
    exe = tmp_path / "group"
    subprocess.run([_cc(), "-std=c99", "-O1", "-Wall", "-Wextra", "-Werror", "-I", str(revised.gen / "c"), "-o",
                    str(exe), str(src), "-lm"], check=True, capture_output=True)
    run = subprocess.run([str(exe)], capture_output=True, text=True)
    assert run.returncode == 0 and run.stdout.strip() == "ok", run.stdout + run.stderr


CMP_SCRIPT = r"""
import base64, json, random, struct, subprocess, sys, tempfile, os
import cbf
from cbf import tables as T
from cbf.errors import CbfError
from cbf.machine import DEFAULT
from cbf.layouts import Line, Point
from cbf.model import Cbf, Record, new_header

NAME, TESTEE, COUNT = sys.argv[1], sys.argv[2], int(sys.argv[3])
cmd = T.BY_NAME[NAME]
lay = next(lay for lay in cmd.layouts if lay.n is not None)
LO, HI = lay.repeated.repeat
K = lay.repeated.size // lay.repeated.items
FIXED = lay.size - K * lay.n
version = next(v for v in T.VERSIONS if v.writable and cmd.layouts_for(v.id))
vtext = f"{version.major}.{version.minor or 0}"
kind = {c["id"]: c["kind"] for c in T.CHECKS}
# a value beyond every machine limit's bounds, from the default machine
far = 2.0 * max(abs(b) for lim in DEFAULT.limits.values() for b in (*lim.lo, *lim.hi) if abs(b) < 1e30)
rng = random.Random(int(sys.argv[4]))
p = subprocess.Popen([TESTEE], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)

def ask(req):
    p.stdin.write(json.dumps(req) + "\n"); p.stdin.flush()
    return json.loads(p.stdout.readline())

def val():
    r = rng.random()
    return (float("nan") if r < 0.02 else float("inf") if r < 0.04 else rng.uniform(-far, far) if r < 0.1
            else rng.uniform(-1.0, 1.0))

def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0] if abs(x) < 3e38 else x

def norm(x):  # canonical JSON compared as binary32 values
    if isinstance(x, bool) or x is None or isinstance(x, str): return x
    if isinstance(x, (int, float)): return f32(float(x))
    if isinstance(x, list): return [norm(y) for y in x]
    return {k: norm(v) for k, v in x.items()}

seen = set()
tmp = tempfile.mkdtemp()
good = (1.0, 1.0, 1.0)[:K // 4] if K // 4 > 1 else 1.0
for t in range(COUNT):
    n = rng.randint(LO, HI)
    recs = [Record.of(Point(point=(0.0, 0.0, 0.0))), Record.of(lay.cls(points=(good,) * n))]
    if rng.random() < 0.7:
        recs.append(Record.of(Line(start=good, end=(0.5, 0.5, 0.5))))
    clean = cbf.encode(Cbf(new_header(vtext, implant_descriptor="PN-1"), tuple(recs)))
    data = bytearray(clean)
    off = cbf.decode(clean).records[1].offset + T.HEAD_SIZE
    for i in range(n * K // 4):
        data[off + FIXED + 4 * i: off + FIXED + 4 * i + 4] = struct.pack(T.BO + "f", val())
    if rng.random() < 0.3:  # an nb that no n tiles, or a group of n past max (when the file holds it)
        data[off - T.HEAD_SIZE + T.RECORD_FIELDS[T.I_SIZE].offset] = rng.choice([FIXED + K * n + 1, FIXED + K * n - 1])
    data = bytes(data)
    path = os.path.join(tmp, f"{t}.cbf")
    open(path, "wb").write(data)
    for prof in ("default", "implib"):
        c = ask({"op": "validate", "file": path, "profile": prof, "part_number": None, "cutters": None,
                 "machine": None})
        py = sorted((f.check, f.severity, f.record, f.offset, f.message) for f in cbf.validate(data, profile=prof))
        cc = sorted((f["check"], f["severity"], f["record"], f["offset"], f["message"]) for f in c["findings"])
        assert cc == py, (t, prof, cc, py)
        seen |= {(kind[f[0]], "[" in f[4]) for f in py if f[2] == 1}
    c = ask({"op": "decode", "file": path})
    try:
        py = cbf.to_canonical(cbf.decode(data))
    except CbfError:
        assert not c["ok"], t
        continue
    assert norm(c["result"]) == norm(py), (t, c["result"]["records"][1], py["records"][1])
    e = ask({"op": "encode", "json": c["result"], "keep_stored": True, "profile": "default"})
    assert e["ok"] and base64.b64decode(e["bytes"]) == data, (t, e)
    # the filling writer: from the JSON of the file Python wrote, the same bytes
    e = ask({"op": "encode", "json": cbf.to_canonical(cbf.decode(clean)), "keep_stored": False, "profile": "default"})
    assert e["ok"] and base64.b64decode(e["bytes"]) == clean, (t, e)
# a JSON group of n items outside min..max: no layout fits, the testee refuses it
one = json.loads(json.dumps(cbf.to_canonical(cbf.decode(clean))))
for n in (LO - 1, HI + 1):
    if n < 0:
        continue
    grp = cbf.to_canonical(cbf.decode(clean))["records"][1]["args"][lay.repeated.name]
    one["records"][1]["args"][lay.repeated.name] = (grp * (n // len(grp) + 1))[:n]
    for k in ("arg_size", "arg_checksum"):
        one["records"][1].pop(k, None)
    e = ask({"op": "encode", "json": one, "keep_stored": False, "profile": "default"})
    assert not e["ok"] and f"{lay.repeated.name}: {n} items; the group holds {LO} to {HI}" in e["error"]["message"], e
p.stdin.write(json.dumps({"op": "quit"}) + "\n"); p.stdin.close(); p.wait()
print(json.dumps(sorted(seen)))
"""


@pytest.fixture(scope="module")
def c_testee(revised: Revised, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The revised spec's C testee, with AddressSanitizer and UBSan (the group's reads and writes), compiled
    without optimisation, as the quick revision drill's testee (drill.QUICK_C_SAN): the test compares what it
    does, and the sanitizers check every read and write at -O0 too (2.1 CPU s to compile against 6.3 at -O1)."""
    exe = tmp_path_factory.mktemp("testee") / "cbf_testee"
    subprocess.run([_cc(), "-std=c99", "-O0", "-g0", "-fsanitize=address,undefined", "-fno-sanitize-recover=all",
                    "-o", str(exe), str(revised.gen / "c" / "cbf_testee.c"), "-lm"], check=True, capture_output=True)
    return exe


def test_c_reads_writes_and_judges_the_group_as_python_does(revised: Revised, c_testee: Path) -> None:
    """The C testee and the Python binding on files whose group holds non-finite values, values beyond
    every machine limit and an nb no n tiles: the same findings (check, severity, record, offset and
    words) under every profile, the same canonical JSON, the bytes back from it; a group of n outside
    min..max refused. The run must reach the group's findings, or it proves nothing."""
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(revised.gen / "python"), *sys.path]))
    run = subprocess.run([sys.executable, "-c", CMP_SCRIPT, revised.name, str(c_testee), "120", "25"], env=env,
                         capture_output=True, text=True, cwd=revised.gen)
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-4000:]
    seen = {tuple(x) for x in __import__("json").loads(run.stdout.strip().splitlines()[-1])}
    # the group's own findings: not finite, a machine limit item by item (named group[i]), arg_size
    assert {("finite", False), ("machine_limits", True), ("arg_size", False)} <= seen, seen


def test_cbf_c_dumps_each_item_and_validates_the_group(revised: Revised, tmp_path: Path) -> None:
    """cbf-c of the revised spec: `dump` prints the group's n items, group[0] .. group[n-1], and nothing
    past them; `validate` of a file with a polyline through valid points finds nothing (exit 0)."""
    exe = tmp_path / "cbf-c"
    # -O0: what cbf-c prints and answers is compared, not what the optimiser makes (0.5 CPU s against 1.4)
    subprocess.run([_cc(), "-std=c99", "-O0", "-o", str(exe), str(revised.gen / "c" / "cbf_tool.c"), "-lm"],
                   check=True, capture_output=True)
    script = (
        "import sys, cbf\n"
        "from cbf import tables as T\n"
        "from cbf.layouts import Point\n"
        "from cbf.model import Cbf, Record, new_header\n"
        "cmd = T.BY_NAME[sys.argv[1]]\n"
        "lay = next(lay for lay in cmd.layouts if lay.n is not None and lay.n > 1)\n"
        "v = next(v for v in T.VERSIONS if v.writable and cmd.layouts_for(v.id))\n"
        "pts = tuple((float(i), 0.0, 1.0) for i in range(lay.n))\n"
        "m = Cbf(new_header(f'{v.major}.{v.minor or 0}', implant_descriptor='PN-1'),\n"
        "        (Record.of(Point(point=(0.0, 0.0, 0.0))), Record.of(lay.cls(points=pts))))\n"
        "open(sys.argv[2], 'wb').write(cbf.encode(m))\n"
        "print(lay.n, lay.repeated.name)\n")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(revised.gen / "python"), *sys.path]))
    made = subprocess.run([sys.executable, "-c", script, revised.name, str(tmp_path / "p.cbf")], env=env,
                          capture_output=True, text=True, check=True)
    n_text, group = made.stdout.split()
    n = int(n_text)
    dump = subprocess.run([str(exe), "dump", str(tmp_path / "p.cbf")], capture_output=True, text=True)
    assert dump.returncode == 0, dump.stderr
    line = next(x for x in dump.stdout.splitlines() if x.startswith("1 @"))
    assert all(f" {group}[{i}]=" in line for i in range(n)) and f" {group}[{n}]=" not in line, line
    assert f" {group}[{n - 1}]={n - 1},0,1" in line, line
    valid = subprocess.run([str(exe), "validate", str(tmp_path / "p.cbf")], capture_output=True, text=True)
    assert valid.returncode == 0, valid.stdout + valid.stderr


def test_c_cut_reader_reads_a_group_line_as_python_does(revised: Revised, tmp_path: Path) -> None:
    """cbf-c encode of the revised spec (the C CUT reader, runtime/cut.c) against the Python package's CUT
    reader on the group's line: n items at the group's least, greatest and a middle n give Python's bytes;
    one item fewer or more than the group holds is refused by both, with the line."""
    exe = tmp_path / "cbf-c"
    subprocess.run([_cc(), "-std=c99", "-O0", "-o", str(exe), str(revised.gen / "c" / "cbf_tool.c"), "-lm"],
                   check=True, capture_output=True)
    script = (
        "import json, sys\n"
        "from cbf import codec, tables as T\n"
        "from cbf.cut import from_cut, to_cut\n"
        "from cbf.errors import CbfError\n"
        "from cbf.model import Cbf, Record, new_header\n"
        "cmd = T.BY_NAME[sys.argv[1]]\n"
        "lays = [lay for lay in cmd.layouts if lay.n is not None]\n"
        "lo, hi = lays[0].repeated.repeat\n"
        "v = next(v for v in T.VERSIONS if v.writable and cmd.layouts_for(v.id))\n"
        "out = {}\n"
        "for n in sorted({lo, (lo + hi) // 2, hi}):\n"
        "    lay = next(x for x in lays if x.n == n)\n"
        "    pts = tuple((float(i) + 0.25, -1.5, 3.0) for i in range(n))\n"
        "    head = new_header(f'{v.major}.{v.minor or 0}', implant_descriptor='PN-1')\n"
        "    m = Cbf(head, (Record.of(lay.cls(points=pts)),))\n"
        "    out[f'n{n}'] = to_cut(m)\n"
        "last = out[f'n{hi}'].rstrip('\\n').split('\\n')\n"
        "item = last[-1][len(last[-1].rsplit('<', 1)[0]):]\n"
        "out['more'] = '\\n'.join(last[:-1] + [last[-1] + ' ' + item]) + '\\n'\n"
        "first = out[f'n{lo}'].rstrip('\\n').split('\\n')\n"
        "out['fewer'] = '\\n'.join(first[:-1] + [first[-1].rsplit(' <', 1)[0]]) + '\\n'\n"
        "res = {}\n"
        "for k, text in out.items():\n"
        "    try:\n"
        "        res[k] = [text, codec.pack_file(from_cut(text)).hex(), None]\n"
        "    except CbfError as exc:\n"
        "        res[k] = [text, None, exc.line]\n"
        "print(json.dumps(res))\n")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(revised.gen / "python"), *sys.path]))
    made = subprocess.run([sys.executable, "-c", script, revised.name], env=env, capture_output=True, text=True,
                          check=True)
    cases = yaml.safe_load(made.stdout)
    assert cases["more"][1] is None and cases["fewer"][1] is None, "Python reads a group of n out of its range"
    for name, (text, want, line) in cases.items():
        path = tmp_path / f"{name}.cut"
        path.write_text(text, encoding="ascii")
        got = subprocess.run([str(exe), "encode", str(path), "-o", "-"], capture_output=True)
        if want is not None:
            assert got.returncode == 0 and got.stdout.hex() == want, (name, got.stderr)
        else:
            assert got.returncode == 2 and not got.stdout, name
            assert f": line {line}:" in got.stderr.decode(), (name, line, got.stderr)
