"""Interop with implib's readers (issue 13 item 15).

(a) An implant descriptor with no word (a CUT text without a header line) is reported: the
    part number must come first (4.2); implib's reader fails on such a file.
(b) Under the implib profile the writers write the profile's own layout of a command (the
    16-byte VERSION, N8), or refuse saying why; a 32-byte VERSION from JSON was written as is.
(c) Under the implib profile the CUT writer writes only names implib's reader reads whole
    (it reads \\w+: "ph-1.a" came back as "ph"), and refuses the others, saying so.

Commands, sizes and check ids come from the spec tables, not from this file.
"""

from __future__ import annotations

import base64
import json
import re
import subprocess
import sys
from pathlib import Path

import pytest
from c_programs import built
from cli_many import run_many
from conftest import ENV

import cbf
from cbf import tables as T
from cbf.cut import keyword

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"
SMALL = GOLDEN / "valid.v3.small.cbf"


def run(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "cbf", *args], env=ENV, capture_output=True, text=True, timeout=120)


def _one_line_exit_2(res: subprocess.CompletedProcess[str]) -> str:
    assert res.returncode == 2, (res.returncode, res.stderr)
    assert "Traceback" not in res.stderr
    lines = res.stderr.strip().splitlines()
    assert len(lines) == 1, res.stderr
    return lines[0]


# -- (a) the part number comes first ------------------------------------------------------
def _descriptor_check() -> dict[str, object]:
    found = T.checks_of("descriptor_word")
    assert found, "spec/cbf.yaml has no descriptor_word check"
    return found[0]


def _small_cut() -> str:
    return cbf.to_cut(cbf.decode(SMALL.read_bytes()))


def test_cut_without_header_line_is_reported() -> None:
    check = _descriptor_check()
    text = _small_cut()
    head = T.CUT["header_keyword"]
    assert text.startswith(head + " ")
    bare = "\n".join(ln for ln in text.splitlines() if ln.split(" ", 1)[0] != head) + "\n"
    data = cbf.encode(cbf.from_cut(bare))  # still encodes: a warning, the file is well formed
    findings = [f for f in cbf.validate(data) if f.check == check["id"]]
    assert len(findings) == 1
    f = findings[0]
    info = T.HEADERS[T.VERSION_BY_ID[cbf.decode(data).version_id].header].by_role("implant_descriptor")
    assert info is not None
    assert (f.severity, f.record, f.offset) == (check["severity"], None, info.offset)
    # with the header line the same file has no such finding
    assert not [g for g in cbf.validate(cbf.encode(cbf.from_cut(text))) if g.check == check["id"]]


@pytest.mark.parametrize("descriptor", ["", " ", " \t ", "\t"])
def test_descriptor_of_whitespace_only_is_reported(descriptor: str) -> None:
    check = _descriptor_check()
    model = cbf.decode(SMALL.read_bytes())
    info = T.HEADERS[T.VERSION_BY_ID[model.version_id].header].by_role("implant_descriptor")
    assert info is not None
    raw = bytearray(SMALL.read_bytes())
    raw[info.offset:info.end] = descriptor.encode().ljust(info.size, T.PAD)
    assert [f.check for f in cbf.validate(bytes(raw))].count(str(check["id"])) == 1
    raw[info.offset:info.end] = (descriptor + "PN-1").encode().ljust(info.size, T.PAD)
    assert check["id"] not in [f.check for f in cbf.validate(bytes(raw))]


# -- (b) the profile's own layout --------------------------------------------------------------
def _profile_layouts(profile: str) -> list[tuple[T.CommandInfo, T.LayoutInfo, T.LayoutInfo]]:
    """(command, the profile's own layout, the default layout of the same version it shortens)."""
    out = []
    for cmd in T.COMMANDS:
        for lay in cmd.layouts_for(T.DEFAULT_VERSION):
            if profile in lay.profiles:
                for other in cmd.layouts_for(T.DEFAULT_VERSION):
                    if not other.profiles and other.size > lay.size:
                        out.append((cmd, lay, other))
    return out


def _implib() -> str:
    if "implib" not in T.PROFILES:
        pytest.skip("this spec has no implib profile")
    return "implib"


def test_implib_writes_its_own_layout_from_json(tmp_path: Path) -> None:
    profile = _implib()
    pairs = _profile_layouts(profile)
    assert pairs, "the implib profile has no layout of its own"
    doc = cbf.to_canonical(cbf.decode(SMALL.read_bytes()))
    names = {cmd.name: (lay, other) for cmd, lay, other in pairs}
    present = [r for r in doc["records"] if r["command"] in names]
    assert present, "the golden file holds none of the commands with an implib layout"
    for r in present:
        assert r["arg_size"] == names[r["command"]][1].size  # the long layout, as JSON gives it
    src = tmp_path / "in.json"
    src.write_text(json.dumps(doc))
    out, plain = tmp_path / "out.cbf", tmp_path / "plain.cbf"
    (res, _), (res_plain, _) = run_many([["encode", str(src), "--profile", profile, "-o", str(out)],
                                         ["encode", str(src), "-o", str(plain)]], ENV)  # one process
    assert res.returncode == 0, res.stderr
    written = cbf.decode(out.read_bytes())
    sizes = [len(r.raw_args) for r in written.records if T.BY_CODE[r.code].name in names]
    assert sizes == [names[r["command"]][0].size for r in present]
    assert cbf.validate(out.read_bytes(), profile=profile) == []
    # the default profile still writes the default layout, unchanged
    assert res_plain.returncode == 0 and plain.read_bytes() == SMALL.read_bytes()


@pytest.fixture(scope="module")
def c_testee() -> Path:
    """The C conformance testee as `make c-build` builds it (not compiled again per test: c_programs.py)."""
    return built("cbf_testee")


def _c_encode(exe: Path, doc: dict[str, object], profile: str) -> dict[str, object]:
    req = json.dumps({"op": "encode", "json": doc, "profile": profile}) + "\n" + '{"op": "quit"}\n'
    ans = subprocess.run([str(exe)], input=req, capture_output=True, text=True, check=True, timeout=120)
    out: dict[str, object] = json.loads(ans.stdout.splitlines()[0])
    return out


def test_c_writer_writes_the_implib_layout_like_python(c_testee: Path) -> None:
    """The C writer under implib writes the profile's own layout (the 16-byte VERSION), byte for
    byte what the Python writer writes; the default profile keeps the JSON's layout."""
    profile = _implib()
    names = {cmd.name: (lay, other) for cmd, lay, other in _profile_layouts(profile)}
    doc = cbf.to_canonical(cbf.decode(SMALL.read_bytes()))
    assert any(r["command"] in names for r in doc["records"])
    exe = c_testee
    got = _c_encode(exe, doc, profile)
    assert got["ok"] is True, got
    data = base64.b64decode(str(got["bytes"]))
    want = cbf.encode(cbf.from_canonical(doc), profile=profile)
    assert data == want
    cut = [(T.BY_CODE[r.code].name, len(r.raw_args)) for r in cbf.decode(data).records
           if T.BY_CODE[r.code].name in names]
    assert cut and all(n == names[name][0].size for name, n in cut)
    assert cbf.validate(data, profile=profile) == []
    default = _c_encode(exe, doc, "default")
    assert default["ok"] is True and base64.b64decode(str(default["bytes"])) == SMALL.read_bytes()


def test_c_writer_refuses_what_the_implib_layout_cannot_hold(c_testee: Path) -> None:
    profile = _implib()
    cmd, lay, other = _profile_layouts(profile)[0]
    doc = cbf.to_canonical(cbf.decode(SMALL.read_bytes()))
    rec = next(r for r in doc["records"] if r["command"] == cmd.name)
    cut_off = [f for f in other.args if f not in lay.args]
    rec["args"][cut_off[0].name] = "01" + "00" * (cut_off[0].size - 1)  # a non-zero reserved byte
    got = _c_encode(c_testee, doc, profile)
    assert got["ok"] is False, got


def test_implib_refuses_what_its_layout_cannot_hold(tmp_path: Path) -> None:
    profile = _implib()
    cmd, lay, other = _profile_layouts(profile)[0]
    doc = cbf.to_canonical(cbf.decode(SMALL.read_bytes()))
    rec = next(r for r in doc["records"] if r["command"] == cmd.name)
    cut_off = [f for f in other.args if f not in lay.args]
    assert cut_off and all(f.reserved and f.kind == "bytes" for f in cut_off)
    rec["args"][cut_off[0].name] = "01" + "00" * (cut_off[0].size - 1)  # a non-zero reserved byte
    src = tmp_path / "in.json"
    src.write_text(json.dumps(doc))
    line = _one_line_exit_2(run("encode", str(src), "--profile", profile, "-o", str(tmp_path / "x.cbf")))
    assert cmd.name in line and profile in line and f"{lay.size}-byte" in line
    assert not (tmp_path / "x.cbf").exists()


# -- (c) names implib's CUT reader reads whole --------------------------------------------------
def _with_cutter_name(name: str) -> cbf.Cbf:
    cmd = next(c for c in T.COMMANDS if c.cutter and c.layouts_for(T.DEFAULT_VERSION))
    assert cmd.cutter is not None and cmd.cutter["name"] in T.CUT["profile_words"][_implib()]["args"]
    kw = keyword(cmd)
    lines = _small_cut().splitlines()
    k = next(i for i, ln in enumerate(lines) if ln.split(" ", 1)[0] == kw)
    parts = lines[k].split(" ")
    lines[k] = " ".join([parts[0], name, *parts[2:]])
    return cbf.from_cut("\n".join(lines) + "\n")


def test_implib_cut_refuses_a_name_its_reader_would_cut() -> None:
    profile = _implib()
    rule = T.CUT["profile_words"][profile]
    pattern = rule["pattern"]
    name = "ph-1.a"
    assert not re.fullmatch(pattern, name)
    model = _with_cutter_name(name)
    assert f" {name} " in cbf.to_cut(model)  # the default reader takes the whole word
    with pytest.raises(ValueError, match=re.escape(repr(name))) as info:
        cbf.to_cut(model, profile=profile)
    read = re.match(pattern, name)
    assert read is not None and repr(read.group(0)) in str(info.value)  # says what implib would read


def test_implib_cut_writes_a_name_it_reads_whole(tmp_path: Path) -> None:
    profile = _implib()
    name = "ph_1a"
    assert re.fullmatch(T.CUT["profile_words"][profile]["pattern"], name)
    model = _with_cutter_name(name)
    text = cbf.to_cut(model, profile=profile)
    assert f" {name} " in text
    assert cbf.encode(cbf.from_cut(text, profile=profile), profile=profile) == cbf.encode(model, profile=profile)


def test_cli_decode_to_cut_under_implib_refuses_in_one_line(tmp_path: Path) -> None:
    profile = _implib()
    src = tmp_path / "ph.cbf"
    src.write_bytes(cbf.encode(_with_cutter_name("ph-1.a")))
    (refused, _), (default, _) = run_many([
        ["decode", str(src), "--to", "cut", "--profile", profile, "-o", str(tmp_path / "o.cut")],
        ["decode", str(src), "--to", "cut"]], ENV)  # one process
    line = _one_line_exit_2(refused)
    assert "ph-1.a" in line and profile in line
    assert not (tmp_path / "o.cut").exists()
    assert default.returncode == 0
