"""cbf stats: true geometry, the time model, record numbers, and a stable JSON shape."""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path
from typing import Any

import jsonschema
import pytest

import cbf
from cbf import tables as T
from cbf.model import Cbf, Record, new_header
from cbf.stats import profile_time, stats

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"
SCHEMA = json.loads((REPO / "schemas" / "stats.schema.json").read_text(encoding="utf-8"))
V = next(v.id for v in T.VERSIONS if v.writable)


def _role(pred: Any) -> T.CommandInfo:
    return next(c for c in T.COMMANDS if pred(c) and c.layouts_for(V))


def _rec(cmd: T.CommandInfo, **values: Any) -> Record:
    lay = cmd.layouts_for(V)[0]
    full = {}
    for f in lay.args:
        if f.name in values:
            full[f.name] = values[f.name]
        elif f.kind == "float":
            full[f.name] = (0.0, 0.0, 1.0) if f.count == 3 else 1.0
        elif f.kind == "string":
            full[f.name] = "X"
        elif f.kind == "bytes":
            full[f.name] = bytes(f.size)
        else:
            full[f.name] = 0
    return Record.of(lay.cls(**full))


POINT = _role(lambda c: c.motion and c.motion["kind"] == "point")
LINE = _role(lambda c: c.motion and c.motion["kind"] == "line" and "through" not in c.motion and not c.orientation)
CIRCLE = _role(lambda c: c.motion and c.motion["kind"] == "circle" and not c.orientation)
ON = _role(lambda c: (c.sets or {}).get("cutting") is True)
SPEED = _role(lambda c: "speed" in (c.sets or {}))
ACCEL = _role(lambda c: "accel" in (c.sets or {}))


def _arg(cmd: T.CommandInfo, key: str) -> str:
    value = (cmd.sets or {})[key]
    assert isinstance(value, str)
    return value


def _speed_factor() -> float:
    """mm/s per unit of the speed argument, from the unit the spec gives it (N11: m/s)."""
    lay = next(c for c in T.SPEC["commands"] if c["code"] == SPEED.code)["layouts"][0]
    unit = next(a["unit"] for a in lay["args"] if a["name"] == _arg(SPEED, "speed"))
    return {"m/s": 1000.0, "mm/s": 1.0}[unit]


def test_true_geometry_and_cutting_split() -> None:
    pm, lm, cm = POINT.motion, LINE.motion, CIRCLE.motion
    assert pm and lm and cm
    recs = [
        _rec(POINT, **{pm["end"]: (0.0, 0.0, 0.0)}),
        _rec(LINE, **{lm["start"]: (0.0, 0.0, 0.0), lm["end"]: (10.0, 0.0, 0.0)}),
        _rec(ON),
        # a half circle of radius 5 about (5, 0, 0): length 5 pi, not its chord of 10
        _rec(CIRCLE, **{cm["start"]: (10.0, 0.0, 0.0), cm["center"]: (5.0, 0.0, 0.0),
                        cm["normal"]: (0.0, 0.0, 1.0), cm["degrees"]: 180.0}),
    ]
    s = stats(Cbf(new_header(V), recs))
    assert s.moving_mm == pytest.approx(10.0)
    assert s.cutting_mm == pytest.approx(5 * math.pi)
    assert s.box is not None
    lo, hi = s.box
    assert lo == pytest.approx((0.0, 0.0, 0.0)) and hi == pytest.approx((10.0, 5.0, 0.0))  # the arc's top, y = 5


def test_trapezoid_and_triangle() -> None:
    # 100 mm at 10 mm/s with 10 mm/s^2 both ways: ramps of 5 mm each, 90 mm cruise: 9 + 1 + 1 s
    assert profile_time(100.0, 10.0, 10.0, 10.0) == pytest.approx(11.0)
    # 4 mm cannot reach 10 mm/s: peak sqrt(40), time 2 sqrt(40) / 10
    assert profile_time(4.0, 10.0, 10.0, 10.0) == pytest.approx(2 * math.sqrt(40) / 10)
    assert profile_time(10.0, 5.0, None, None) == pytest.approx(2.0)


def test_time_uses_speed_and_accel_from_the_file() -> None:
    lm = LINE.motion
    assert lm
    f = _speed_factor()
    recs = [_rec(SPEED, **{_arg(SPEED, "speed"): 10.0 / f}),
            _rec(ACCEL, **{_arg(ACCEL, "accel"): 10.0 / f, _arg(ACCEL, "decel"): 10.0 / f}),
            _rec(LINE, **{lm["start"]: (0.0, 0.0, 0.0), lm["end"]: (100.0, 0.0, 0.0)})]
    s = stats(Cbf(new_header(V), recs))
    assert s.time_s == pytest.approx(11.0, rel=1e-6)
    assert s.timed_moves == 1 and s.untimed_moves == 0


def _valid_goldens() -> list[Path]:
    return [p for p in sorted(GOLDEN.glob("valid.*.cbf")) if not cbf.validate(p.read_bytes())]


def test_json_shape_is_stable_for_every_valid_golden() -> None:
    paths = _valid_goldens()
    assert paths
    for p in paths:
        r = subprocess.run([sys.executable, "-m", "cbf", "stats", "--json", str(p)], capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        doc = json.loads(r.stdout)
        jsonschema.validate(doc, SCHEMA)
        model = cbf.decode(p.read_bytes())
        assert doc["records"] == len(model.records)
        assert sum(doc["commands"].values()) == len(model.records)
        for item in doc["shapes"] + doc["cutters"] + doc["phases"] + doc["checkpoints"]:
            assert 0 <= item["record"] < len(model.records)


def test_record_numbers_point_at_the_records() -> None:
    p = GOLDEN / "valid.v3.all_commands.cbf"
    model = cbf.decode(p.read_bytes())
    d = stats(model).as_dict()
    assert d["checkpoints"] and d["shapes"] and d["cutters"] and d["phases"]
    for key, pred in (("checkpoints", lambda c: c.progress), ("cutters", lambda c: c.cutter),
                      ("phases", lambda c: "phase" in (c.sets or {})),
                      ("shapes", lambda c: c.shape and c.shape["kind"] == "start")):
        want = [i for i, r in enumerate(model.records) if r.command and pred(r.command)]
        assert [x["record"] for x in d[key]] == want


def test_cli_text_and_bad_input(tmp_path: Path) -> None:
    p = GOLDEN / "valid.v3.all_commands.cbf"
    r = subprocess.run([sys.executable, "-m", "cbf", "stats", str(p)], capture_output=True, text=True)
    assert r.returncode == 0 and "path length" in r.stdout and "estimated time" in r.stdout
    bad = tmp_path / "bad.cbf"
    bad.write_bytes(b"\x92\xb7\xa1\x53" + bytes(20))
    r = subprocess.run([sys.executable, "-m", "cbf", "stats", str(bad)], capture_output=True, text=True)
    assert r.returncode == 2 and r.stderr.count("\n") == 1 and "Traceback" not in r.stderr
