"""A command added to a copy of the spec (tests/fixtures/dwell_command.yaml) shows up in
the Python codec, its CUT form and its command line after generation, with no code change."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from conftest import generate, load_yaml, spec_with_fixture_command

SCRIPT = r"""
import struct, sys
import cbf
from cbf import tables as T
from cbf.layouts import CommandCode, Dwell, Point
from cbf.model import Cbf, Record, new_header

CODE = int(sys.argv[2])  # the fixture's code, as conftest chose it for this spec
VERSION = next(v for v in T.VERSIONS if v.writable and T.BY_NAME["DWELL"].layouts_for(v.id))
assert CommandCode.DWELL == CODE
model = Cbf(new_header(f"{VERSION.major}.{VERSION.minor or 0}", implant_descriptor="PN-1"),
            (Record.of(Point(point=(0.0, 0.0, 0.0))), Record.of(Dwell(seconds=1.5))))
data = cbf.encode(model)
back = cbf.decode(data)
# where the record's code and argument-size fields are: from the model, never from rev 03's sizes
at = back.records[1].offset
code, size = T.RECORD_BY_ROLE["code"], T.RECORD_BY_ROLE["arg_size"]
field = lambda f, buf: int.from_bytes(buf[at + f.offset:at + f.end], T.SPEC["byte_order"])
assert field(code, data) == CODE and field(size, data) == 4   # the fixture's code and size
assert back.records[1].decode_args() == Dwell(seconds=1.5)
assert cbf.validate(data) == []
text = cbf.to_cut(back)
assert "dwell 1.5" in text.splitlines(), text
assert cbf.encode(cbf.from_cut(text)) == data
doc = cbf.to_canonical(back)
assert doc["records"][1]["command"] == "DWELL" and doc["records"][1]["args"] == {"seconds": 1.5}
bad = bytearray(data)   # DWELL with 5 argument bytes breaks the framing
bad[at + size.offset:at + size.end] = (5).to_bytes(size.size, T.SPEC["byte_order"])
framing = {c["id"] for c in T.CHECKS if c["kind"] in ("arg_size", "truncated_record")}
assert framing and any(f.check in framing for f in cbf.validate(bytes(bad)))
open(sys.argv[1], "wb").write(data)
"""


def test_new_command_reaches_python_cut_and_cli(tmp_path: Path, repo: Path) -> None:
    spec = spec_with_fixture_command(tmp_path)
    generate(spec, tmp_path / "gen", "python")
    env = dict(os.environ, PYTHONPATH=str(tmp_path / "gen" / "python"))
    out = tmp_path / "dwell.cbf"
    code = next(c["code"] for c in load_yaml(spec)["commands"] if c["name"] == "DWELL")
    subprocess.run([sys.executable, "-c", SCRIPT, str(out), str(code)], env=env, check=True, cwd=tmp_path)
    info = subprocess.run([sys.executable, "-m", "cbf", "info", str(out)], env=env, capture_output=True, text=True,
                          cwd=tmp_path)
    assert info.returncode == 0, info.stderr
    assert "  DWELL: 1" in info.stdout
    cut = subprocess.run([sys.executable, "-m", "cbf", "decode", str(out), "--to", "cut"], env=env,
                         capture_output=True, text=True, cwd=tmp_path)
    assert "dwell 1.5" in cut.stdout.splitlines()
    # and the committed codec does not know it: the command really came from the spec copy
    plain = subprocess.run([sys.executable, "-m", "cbf", "info", str(out)], capture_output=True, text=True,
                           env=dict(os.environ, PYTHONPATH=str(repo / "generated" / "python")), cwd=tmp_path)
    assert f"unknown 0x{code:02X}: 1" in plain.stdout
