"""Conformance testee of the Python codec: JSON lines in, JSON lines out (PROTOCOL.md).

It answers and never judges.
"""

from __future__ import annotations

import base64
import json
import sys
from typing import Any

import cbf


def handle(req: dict[str, Any]) -> dict[str, Any]:
    op = req.get("op")
    if op == "decode":
        data = open(req["file"], "rb").read()
        try:
            return {"ok": True, "result": cbf.to_canonical(cbf.decode(data))}
        except cbf.CbfError as exc:
            return {"ok": False, "error": {"kind": exc.kind, "offset": exc.offset, "message": str(exc)}}
    if op == "validate":
        data = open(req["file"], "rb").read()
        cutters = cbf.load_cutter_table(req["cutters"]) if req.get("cutters") else None
        try:
            machine = cbf.load_machine(req["machine"]) if req.get("machine") else None
        except cbf.CbfError as exc:
            return {"ok": False, "error": {"kind": exc.kind, "offset": None, "message": str(exc)}}
        found = cbf.validate(data, profile=req.get("profile", "default"), part_number=req.get("part_number"),
                             cutters=cutters, machine=machine)
        return {"ok": True, "findings": [f.as_dict() for f in found]}
    if op == "encode":
        try:
            model = cbf.from_canonical(req["json"])
            out = cbf.encode(model, keep_stored=bool(req.get("keep_stored")), profile=req.get("profile", "default"))
        except cbf.CbfError as exc:
            return {"ok": False, "error": {"kind": exc.kind, "offset": exc.offset, "message": str(exc)}}
        return {"ok": True, "bytes": base64.b64encode(out).decode("ascii")}
    return {"skipped": True}


def main() -> int:
    for line in sys.stdin:
        if not line.strip():
            continue
        req = json.loads(line)
        if req.get("op") == "quit":
            return 0
        try:
            answer = handle(req)
        except Exception as exc:  # report, do not judge: the runner decides
            answer = {"ok": False, "error": {"kind": "exception", "offset": None,
                                             "message": f"{type(exc).__name__}: {exc}"}}
        sys.stdout.write(json.dumps(answer) + "\n")
        sys.stdout.flush()
    return 0


if __name__ == "__main__":
    sys.exit(main())
