// Conformance testee of the Kaitai-generated JavaScript parser (conformance/PROTOCOL.md).
// Generated from spec/cbf.yaml by cbfgen; do not edit. Decode only.
'use strict';
const fs = require('fs');
const readline = require('readline');
const KaitaiStream = require('kaitai-struct/KaitaiStream');
const Cbf = require('./Cbf.js').Cbf || require('./Cbf.js');

const HEADER_SIZE = 128;
const HEADER_FIELDS = [["start_pattern", "uint", 1, "startPattern"], ["file_checksum", "uint", 1, "fileChecksum"], ["header_checksum", "uint", 1, "headerChecksum"], ["reserved_ecc", "bytes", 1, "reservedEcc"], ["version_major", "uint", 1, "versionMajor"], ["version_minor", "uint", 1, "versionMinor"]];
const HEADER_TAILS = {"HeaderV2": [["implant_descriptor", "string", 1, "implantDescriptor"], ["configuration_descriptor", "string", 1, "configurationDescriptor"], ["command_count", "uint", 1, "commandCount"], ["end_pattern", "uint", 1, "endPattern"]], "HeaderV1": [["implant_descriptor", "string", 1, "implantDescriptor"], ["reserved_98", "bytes", 1, "reserved98"], ["command_count", "uint", 1, "commandCount"], ["end_pattern", "uint", 1, "endPattern"]]};
const RECORD_FIELDS = [["sequence", "uint", 1, "sequence"], ["code", "uint", 1, "code"], ["code_copy", "uint", 1, "codeCopy"], ["arg_size", "uint", 1, "argSize"], ["reserved", "uint", 1, "reserved"], ["arg_checksum", "uint", 1, "argChecksum"]];
const ARGS = {"ArgsCheckpoint": [["name", "string", 1, "name"], ["recovery_point", "float", 3, "recoveryPoint"], ["completion", "float", 1, "completion"]], "ArgsCheckpointV1": [["name", "string", 1, "name"]], "ArgsCutter": [["name", "string", 1, "name"], ["length", "float", 1, "length"], ["radius", "float", 1, "radius"], ["head_length", "float", 1, "headLength"], ["reserved", "bytes", 1, "reserved"]], "ArgsCutterV1": [["name", "string", 1, "name"], ["length", "float", 1, "length"], ["radius", "float", 1, "radius"], ["reserved", "bytes", 1, "reserved"]], "ArgsOrient": [["approach", "float", 3, "approach"], ["reserved", "bytes", 1, "reserved"]], "ArgsOrient5b": [["start_approach", "float", 3, "startApproach"], ["end_approach", "float", 3, "endApproach"]], "ArgsPhase": [["name", "string", 1, "name"]], "ArgsEnableSkip": [["name", "string", 1, "name"]], "ArgsStartshape": [["name", "string", 1, "name"], ["moves", "uint", 1, "moves"]], "ArgsEndshape": [["name", "string", 1, "name"], ["moves", "uint", 1, "moves"]], "ArgsDecelOff": [], "ArgsDecelOn": [], "ArgsPoint": [["point", "float", 3, "point"]], "ArgsLine": [["start", "float", 3, "start"], ["end", "float", 3, "end"]], "ArgsLine5b": [["start_pos", "float", 3, "startPos"], ["end_pos", "float", 3, "endPos"], ["start_orient", "float", 3, "startOrient"], ["end_orient", "float", 3, "endOrient"]], "ArgsArc": [["start", "float", 3, "start"], ["middle", "float", 3, "middle"], ["end", "float", 3, "end"]], "ArgsArc5b": [["start_pos", "float", 3, "startPos"], ["mid_pos", "float", 3, "midPos"], ["end_pos", "float", 3, "endPos"], ["start_orient", "float", 3, "startOrient"], ["end_orient", "float", 3, "endOrient"]], "ArgsCircle": [["start", "float", 3, "start"], ["center", "float", 3, "center"], ["normal", "float", 3, "normal"], ["ndegrees", "float", 1, "ndegrees"]], "ArgsCircle5b": [["start", "float", 3, "start"], ["center", "float", 3, "center"], ["normal", "float", 3, "normal"], ["ndegrees", "float", 1, "ndegrees"], ["start_orient", "float", 3, "startOrient"], ["end_orient", "float", 3, "endOrient"]], "ArgsHelix": [["start", "float", 3, "start"], ["center", "float", 3, "center"], ["normal", "float", 3, "normal"], ["ndegrees", "float", 1, "ndegrees"], ["length", "float", 1, "length"]], "ArgsHelix5b": [["start", "float", 3, "start"], ["center", "float", 3, "center"], ["normal", "float", 3, "normal"], ["ndegrees", "float", 1, "ndegrees"], ["length", "float", 1, "length"], ["start_orient", "float", 3, "startOrient"], ["end_orient", "float", 3, "endOrient"]], "ArgsSpeed": [["speed", "float", 1, "speed"]], "ArgsAccel": [["accel", "float", 1, "accel"], ["decel", "float", 1, "decel"]], "ArgsCutterOn": [], "ArgsCutterOff": [], "ArgsGuide": [["message", "string", 1, "message"]], "ArgsFcparms": [["nom_speed", "float", 1, "nomSpeed"], ["max_speed", "float", 1, "maxSpeed"], ["min_speed", "float", 1, "minSpeed"], ["max_force", "float", 1, "maxForce"]], "ArgsVersion": [["cutfile", "string", 1, "cutfile"], ["format", "string", 1, "format"], ["reserved", "bytes", 1, "reserved"]], "ArgsVersionImplib": [["cutfile", "string", 1, "cutfile"], ["format", "string", 1, "format"]], "ArgsComment": [["text", "string", 1, "text"]]};
const COMMANDS = {"60": "CHECKPOINT", "163": "CUTTER", "88": "ORIENT", "89": "ORIENT5B", "33": "PHASE", "34": "ENABLE_SKIP", "201": "STARTSHAPE", "101": "ENDSHAPE", "43": "DECEL_OFF", "78": "DECEL_ON", "51": "POINT", "182": "LINE", "183": "LINE5B", "148": "ARC", "149": "ARC5B", "122": "CIRCLE", "123": "CIRCLE5B", "226": "HELIX", "227": "HELIX5B", "139": "SPEED", "71": "ACCEL", "187": "CUTTER_ON", "102": "CUTTER_OFF", "17": "GUIDE", "252": "FCPARMS", "85": "VERSION", "90": "COMMENT"};

const view = new DataView(new ArrayBuffer(4));
function f32(v) {
  view.setFloat32(0, v, true);
  const bits = view.getUint32(0, true);
  if (!Number.isFinite(v) || Object.is(v, -0)) return '0x' + bits.toString(16).padStart(8, '0');
  return v;
}
function hex(bytes) { return Buffer.from(bytes).toString('hex'); }
function value(kind, count, v) {
  if (count < 0) {  // a repeated group: items of -count elements, read flat
    const flat = Array.from(v, (x) => value(kind, 1, x));
    if (count === -1) return flat;
    const items = [];
    for (let i = 0; i < flat.length; i += -count) items.push(flat.slice(i, i - count));
    return items;
  }
  if (kind === 'float') return count > 1 ? Array.from(v, f32) : f32(v);
  if (kind === 'bytes') return hex(v);
  return v;
}
function fields(obj, spec) {
  const out = {};
  for (const [name, kind, count, js] of spec) out[name] = value(kind, count, obj[js]);
  return out;
}

function decode(path) {
  const data = fs.readFileSync(path);
  if (data.length < HEADER_SIZE) return { ok: false, error: { kind: 'truncated_header', offset: 0, message: 'short header' } };
  const io = new KaitaiStream(data);
  const root = Object.create(Cbf.prototype);
  root._io = io; root._parent = null; root._root = root;
  try {
    root.header = new Cbf.Header(io, root, root);
  } catch (e) {
    return { ok: false, error: { kind: 'validation', offset: 0, message: String(e && e.message) } };
  }
  const header = fields(root.header, HEADER_FIELDS);
  const tail = root.header.layout;
  Object.assign(header, fields(tail, HEADER_TAILS[tail.constructor.name]));
  const records = [];
  while (!io.isEof()) {
    const pos = io.pos;
    let rec;
    try {
      rec = new Cbf.Record(io, root, root);
    } catch (e) {
      const kind = e instanceof KaitaiStream.EOFError ? 'truncated_record' : 'validation';
      return { ok: false, error: { kind, offset: pos, message: String(e && e.message) } };
    }
    const out = { offset: pos };
    Object.assign(out, fields(rec, RECORD_FIELDS));
    out.command = COMMANDS[rec.command] !== undefined ? COMMANDS[rec.command] : null;
    if (rec.args instanceof Uint8Array) {
      out.args = null;
      out.raw_args = hex(rec.args);
    } else {
      out.args = fields(rec.args, ARGS[rec.args.constructor.name]);
    }
    records.push(out);
  }
  return { ok: true, result: { header, records, trailing: '' } };
}

const rl = readline.createInterface({ input: process.stdin, terminal: false });
rl.on('line', (line) => {
  if (!line.trim()) return;
  const req = JSON.parse(line);
  if (req.op === 'quit') { rl.close(); process.exit(0); }
  let answer;
  if (req.op === 'decode') {
    try { answer = decode(req.file); } catch (e) {
      answer = { ok: false, error: { kind: 'exception', offset: null, message: String(e && e.stack) } };
    }
  } else {
    answer = { skipped: true };
  }
  process.stdout.write(JSON.stringify(answer) + '\n');
});
