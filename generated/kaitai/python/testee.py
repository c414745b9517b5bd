"""Conformance testee of the Kaitai-generated Python parser (conformance/PROTOCOL.md).

Generated from spec/cbf.yaml by cbfgen; do not edit. Decode only: it drives
the generated parser record by record (so a truncation names its record's
offset) and turns the object tree into the canonical JSON.
"""

import json
import struct
import sys

from kaitaistruct import KaitaiStream, ValidationFailedError, BytesIO

from cbf_kaitai import Cbf

HEADER_SIZE = 128
HEADER_FIELDS = [('start_pattern', 'uint', 1), ('file_checksum', 'uint', 1), ('header_checksum', 'uint', 1), ('reserved_ecc', 'bytes', 1), ('version_major', 'uint', 1), ('version_minor', 'uint', 1)]
HEADER_TAILS = {'HeaderV2': [('implant_descriptor', 'string', 1), ('configuration_descriptor', 'string', 1), ('command_count', 'uint', 1), ('end_pattern', 'uint', 1)], 'HeaderV1': [('implant_descriptor', 'string', 1), ('reserved_98', 'bytes', 1), ('command_count', 'uint', 1), ('end_pattern', 'uint', 1)]}
RECORD_FIELDS = [('sequence', 'uint', 1), ('code', 'uint', 1), ('code_copy', 'uint', 1), ('arg_size', 'uint', 1), ('reserved', 'uint', 1), ('arg_checksum', 'uint', 1)]
ARGS = {'ArgsCheckpoint': [('name', 'string', 1), ('recovery_point', 'float', 3), ('completion', 'float', 1)], 'ArgsCheckpointV1': [('name', 'string', 1)], 'ArgsCutter': [('name', 'string', 1), ('length', 'float', 1), ('radius', 'float', 1), ('head_length', 'float', 1), ('reserved', 'bytes', 1)], 'ArgsCutterV1': [('name', 'string', 1), ('length', 'float', 1), ('radius', 'float', 1), ('reserved', 'bytes', 1)], 'ArgsOrient': [('approach', 'float', 3), ('reserved', 'bytes', 1)], 'ArgsOrient5b': [('start_approach', 'float', 3), ('end_approach', 'float', 3)], 'ArgsPhase': [('name', 'string', 1)], 'ArgsEnableSkip': [('name', 'string', 1)], 'ArgsStartshape': [('name', 'string', 1), ('moves', 'uint', 1)], 'ArgsEndshape': [('name', 'string', 1), ('moves', 'uint', 1)], 'ArgsDecelOff': [], 'ArgsDecelOn': [], 'ArgsPoint': [('point', 'float', 3)], 'ArgsLine': [('start', 'float', 3), ('end', 'float', 3)], 'ArgsLine5b': [('start_pos', 'float', 3), ('end_pos', 'float', 3), ('start_orient', 'float', 3), ('end_orient', 'float', 3)], 'ArgsArc': [('start', 'float', 3), ('middle', 'float', 3), ('end', 'float', 3)], 'ArgsArc5b': [('start_pos', 'float', 3), ('mid_pos', 'float', 3), ('end_pos', 'float', 3), ('start_orient', 'float', 3), ('end_orient', 'float', 3)], 'ArgsCircle': [('start', 'float', 3), ('center', 'float', 3), ('normal', 'float', 3), ('ndegrees', 'float', 1)], 'ArgsCircle5b': [('start', 'float', 3), ('center', 'float', 3), ('normal', 'float', 3), ('ndegrees', 'float', 1), ('start_orient', 'float', 3), ('end_orient', 'float', 3)], 'ArgsHelix': [('start', 'float', 3), ('center', 'float', 3), ('normal', 'float', 3), ('ndegrees', 'float', 1), ('length', 'float', 1)], 'ArgsHelix5b': [('start', 'float', 3), ('center', 'float', 3), ('normal', 'float', 3), ('ndegrees', 'float', 1), ('length', 'float', 1), ('start_orient', 'float', 3), ('end_orient', 'float', 3)], 'ArgsSpeed': [('speed', 'float', 1)], 'ArgsAccel': [('accel', 'float', 1), ('decel', 'float', 1)], 'ArgsCutterOn': [], 'ArgsCutterOff': [], 'ArgsGuide': [('message', 'string', 1)], 'ArgsFcparms': [('nom_speed', 'float', 1), ('max_speed', 'float', 1), ('min_speed', 'float', 1), ('max_force', 'float', 1)], 'ArgsVersion': [('cutfile', 'string', 1), ('format', 'string', 1), ('reserved', 'bytes', 1)], 'ArgsVersionImplib': [('cutfile', 'string', 1), ('format', 'string', 1)], 'ArgsComment': [('text', 'string', 1)]}


def f32(v):
    bits = struct.unpack("<I", struct.pack("<f", v))[0]
    if v != v or v in (float("inf"), float("-inf")) or (v == 0.0 and bits >> 31):
        return "0x%08x" % bits
    return v


def value(kind, count, v):
    if count < 0:  # a repeated group: items of -count elements, read flat
        flat = [value(kind, 1, x) for x in v]
        return flat if count == -1 else [flat[i:i - count] for i in range(0, len(flat), -count)]
    if kind == "float":
        return [f32(x) for x in v] if count > 1 else f32(v)
    if kind == "bytes":
        return v.hex()
    return v


def fields(obj, spec):
    return {name: value(kind, count, getattr(obj, name)) for name, kind, count in spec}


def decode(path):
    with open(path, "rb") as fh:
        data = fh.read()
    if len(data) < HEADER_SIZE:
        return {"ok": False, "error": {"kind": "truncated_header", "offset": 0, "message": "short header"}}
    io = KaitaiStream(BytesIO(data))
    root = Cbf.__new__(Cbf)
    root._io, root._parent, root._root = io, None, root
    try:
        root.header = Cbf.Header(io, root, root)
    except ValidationFailedError as exc:
        return {"ok": False, "error": {"kind": "validation", "offset": 0, "message": str(exc)}}
    header = fields(root.header, HEADER_FIELDS)
    header.update(fields(root.header.layout, HEADER_TAILS[type(root.header.layout).__name__]))
    records = []
    while not io.is_eof():
        pos = io.pos()
        try:
            rec = Cbf.Record(io, root, root)
        except EOFError as exc:
            return {"ok": False, "error": {"kind": "truncated_record", "offset": pos, "message": str(exc)}}
        except ValidationFailedError as exc:
            return {"ok": False, "error": {"kind": "validation", "offset": pos, "message": str(exc)}}
        out = {"offset": pos}
        out.update(fields(rec, RECORD_FIELDS))
        command = rec.command
        out["command"] = command.name.upper() if hasattr(command, "name") else None
        if isinstance(rec.args, bytes):
            out["args"] = None
            out["raw_args"] = rec.args.hex()
        else:
            out["args"] = fields(rec.args, ARGS[type(rec.args).__name__])
        records.append(out)
    return {"ok": True, "result": {"header": header, "records": records, "trailing": ""}}


def main():
    for line in sys.stdin:
        if not line.strip():
            continue
        req = json.loads(line)
        if req.get("op") == "quit":
            return 0
        if req.get("op") == "decode":
            try:
                answer = decode(req["file"])
            except Exception as exc:  # reported, not judged
                answer = {"ok": False, "error": {"kind": "exception", "offset": None, "message": repr(exc)}}
        else:
            answer = {"skipped": True}
        sys.stdout.write(json.dumps(answer) + "\n")
        sys.stdout.flush()
    return 0


if __name__ == "__main__":
    sys.exit(main())
