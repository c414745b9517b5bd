"""cbf convert follows the spec between any two versions (issue 25, point 8), those a revision
adds included: every record of a valid file either carries over (its command, or by its motion
role a line command of the target) and the result validates without error in the target, or the
conversion is refused naming the record and a reason the model gives (the target lacks the
command and no line command carries its motion, a shape count, a missing argument).

Versions, commands and files are read from the spec and the golden cases, never named."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import convert_fills, load_yaml

import cbf
from cbf import tables as T
from cbf.convert import ConvertError, convert

GOLDEN = Path(__file__).resolve().parents[1] / "conformance" / "golden"
PAIRS = [(s.id, d.id) for s in T.VERSIONS for d in T.VERSIONS if d.writable and d.id != s.id]


def _valid(version: str) -> list[Path]:
    out = []
    for p in sorted(GOLDEN.glob("valid.*.cbf")):
        data = p.read_bytes()
        if len(data) < 1 << 16 and cbf.decode(data).version_id == version and not cbf.validate(data):
            out.append(p)
    return out


def _header_refusal(model: cbf.Cbf, msg: str, dst: str) -> bool:
    """True when msg refuses the file for a header field it sets that the target's header has no field for, by
    name or by role (a revision's new header field, flags say, set in a file of its version): the model's reason.
    False otherwise (the record check below then judges msg)."""
    src_fields = T.HEADERS[T.VERSION_BY_ID[model.version_id].header].fields
    named = [f for f in src_fields if re.search(rf"\bheader: {re.escape(f.name)}\b", msg)]
    if not named:
        return False
    f = named[0]
    dst_fields = T.HEADERS[T.VERSION_BY_ID[dst].header].fields
    if any(g.name == f.name or (f.role not in (None, "reserved") and g.role == f.role) for g in dst_fields):
        return False
    assert getattr(model.header, f.name) not in ("", 0), msg
    return True


@pytest.mark.parametrize(("src", "dst"), PAIRS)
def test_convert_between_two_versions_carries_or_refuses_by_the_model(src: str, dst: str) -> None:
    files = _valid(src)
    if not files:
        pytest.skip(f"no valid golden file of version {src}")
    for path in files:
        model = cbf.decode(path.read_bytes())
        try:
            conv = convert(model, dst, chord_tol=0.5, fill=convert_fills(model, dst))
        except ConvertError as exc:
            msg = str(exc)
            if _header_refusal(model, msg, dst):
                continue
            m = re.search(r"\brecord (\d+)\b", msg)
            assert m, f"{path.name} -> {dst}: the refusal names no record: {msg}"
            cmd = model.records[int(m.group(1))].command
            assert cmd is not None and cmd.name in msg, msg
            if not cmd.layouts_for(dst):  # the model's reason: the target lacks it, no line carries it
                assert f"not in version {dst}" in msg or "chord-tol" in msg, msg
            continue
        data = cbf.encode(conv.model)
        assert [f for f in cbf.validate(data) if f.severity == "error"] == [], (path.name, dst)
        back = cbf.decode(data)
        assert back.version_id == dst
        assert all(r.command is not None and r.command.layouts_for(dst) for r in back.records), (path.name, dst)
        # what the target lacks went by its motion role: no record of a command dst lacks is left
        lacking = {r.code for r in model.records if r.command is not None and not r.command.layouts_for(dst)}
        assert not lacking & {r.code for r in back.records}


def test_some_pair_converts_whole() -> None:
    """The test above is not all refusals: a file of some version converts to every other writable one."""
    done = 0
    for src, dst in PAIRS:
        for path in _valid(src):
            model = cbf.decode(path.read_bytes())
            try:
                convert(model, dst, chord_tol=0.5, fill=convert_fills(model, dst))
            except ConvertError:
                continue
            done += 1
    assert done >= 2


def _profile_only_cases() -> list[tuple[Path, str]]:
    """Golden files that fail validation under the default profile and pass under another one
    (but for its file checksum, which its writer refills), with that profile: read from the
    expectations."""
    sums = {c["id"] for c in T.checks_of("file_checksum")}
    out = []
    for exp in sorted(GOLDEN.glob("*.expect.yaml")):
        doc = load_yaml(exp)
        found = doc.get("validate", {})
        if not doc.get("encode") or not any(f[1] == "error" for f in found.get("default", [])):
            continue
        for profile, findings in sorted(found.items()):
            if profile != "default" and all(f[1] != "error" or str(f[0]) in sums for f in findings):
                out.append((exp.with_name(exp.name.removesuffix(".expect.yaml") + ".cbf"), profile))
    return out


@pytest.mark.parametrize(("path", "profile"), _profile_only_cases(), ids=lambda x: getattr(x, "name", x))
def test_convert_judges_its_input_under_the_profile_it_writes(tmp_path: Path, path: Path, profile: str) -> None:
    """`cbf convert --profile P` accepts a file that is sound under P (it refused one that failed
    only under the default profile, e.g. a VERSION of implib's 16 bytes)."""
    written = tmp_path / "in.cbf"
    written.write_bytes(cbf.encode(cbf.decode(path.read_bytes()), profile=profile))
    assert not [f for f in cbf.validate(written.read_bytes(), profile=profile) if f.severity == "error"]
    version = cbf.decode(written.read_bytes()).version_id
    if not next(v for v in T.VERSIONS if v.id == version).writable:
        pytest.skip(f"version {version} is read-only: convert writes only writable versions")
    res = subprocess.run([sys.executable, "-m", "cbf", "convert", str(written), "--to-version", version,
                          "--profile", profile, "-o", str(tmp_path / "out.cbf")],
                         capture_output=True, text=True, check=False)
    assert res.returncode == 0, res.stderr
    assert not [f for f in cbf.validate((tmp_path / "out.cbf").read_bytes(), profile=profile)
                if f.severity == "error"]
