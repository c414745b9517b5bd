package cbf

// Conformance testee of the Kaitai-generated Go parser (conformance/PROTOCOL.md).
// Generated from spec/cbf.yaml by cbfgen; do not edit. Decode only: it drives the
// parser record by record and turns the object tree into the canonical JSON. It lives
// outside the parser's module (generated/kaitai/go-testee/); the build puts it beside
// cbf.go, because driving the parser record by record needs its unexported fields.

import (
	"bufio"
	"bytes"
	"encoding/hex"
	"encoding/json"
	"errors"
	"fmt"
	"io"
	"math"
	"os"
	"reflect"

	"github.com/kaitai-io/kaitai_struct_go_runtime/kaitai"
)

type field struct{ Name, Kind, Go string; Count int }

var headerSize = 128
var headerFields = []field{ { "start_pattern", "uint", "StartPattern", 1 }, { "file_checksum", "uint", "FileChecksum", 1 }, { "header_checksum", "uint", "HeaderChecksum", 1 }, { "reserved_ecc", "bytes", "ReservedEcc", 1 }, { "version_major", "uint", "VersionMajor", 1 }, { "version_minor", "uint", "VersionMinor", 1 },  }
var headerTails = map[string][]field{
	"Cbf_HeaderV2": { { "implant_descriptor", "string", "ImplantDescriptor", 1 }, { "configuration_descriptor", "string", "ConfigurationDescriptor", 1 }, { "command_count", "uint", "CommandCount", 1 }, { "end_pattern", "uint", "EndPattern", 1 },  },
	"Cbf_HeaderV1": { { "implant_descriptor", "string", "ImplantDescriptor", 1 }, { "reserved_98", "bytes", "Reserved98", 1 }, { "command_count", "uint", "CommandCount", 1 }, { "end_pattern", "uint", "EndPattern", 1 },  },
}
var recordFields = []field{ { "sequence", "uint", "Sequence", 1 }, { "code", "uint", "Code", 1 }, { "code_copy", "uint", "CodeCopy", 1 }, { "arg_size", "uint", "ArgSize", 1 }, { "reserved", "uint", "Reserved", 1 }, { "arg_checksum", "uint", "ArgChecksum", 1 },  }
var argsFields = map[string][]field{
	"Cbf_ArgsCheckpoint": { { "name", "string", "Name", 1 }, { "recovery_point", "float", "RecoveryPoint", 3 }, { "completion", "float", "Completion", 1 },  },
	"Cbf_ArgsCheckpointV1": { { "name", "string", "Name", 1 },  },
	"Cbf_ArgsCutter": { { "name", "string", "Name", 1 }, { "length", "float", "Length", 1 }, { "radius", "float", "Radius", 1 }, { "head_length", "float", "HeadLength", 1 }, { "reserved", "bytes", "Reserved", 1 },  },
	"Cbf_ArgsCutterV1": { { "name", "string", "Name", 1 }, { "length", "float", "Length", 1 }, { "radius", "float", "Radius", 1 }, { "reserved", "bytes", "Reserved", 1 },  },
	"Cbf_ArgsOrient": { { "approach", "float", "Approach", 3 }, { "reserved", "bytes", "Reserved", 1 },  },
	"Cbf_ArgsOrient5b": { { "start_approach", "float", "StartApproach", 3 }, { "end_approach", "float", "EndApproach", 3 },  },
	"Cbf_ArgsPhase": { { "name", "string", "Name", 1 },  },
	"Cbf_ArgsEnableSkip": { { "name", "string", "Name", 1 },  },
	"Cbf_ArgsStartshape": { { "name", "string", "Name", 1 }, { "moves", "uint", "Moves", 1 },  },
	"Cbf_ArgsEndshape": { { "name", "string", "Name", 1 }, { "moves", "uint", "Moves", 1 },  },
	"Cbf_ArgsDecelOff": {  },
	"Cbf_ArgsDecelOn": {  },
	"Cbf_ArgsPoint": { { "point", "float", "Point", 3 },  },
	"Cbf_ArgsLine": { { "start", "float", "Start", 3 }, { "end", "float", "End", 3 },  },
	"Cbf_ArgsLine5b": { { "start_pos", "float", "StartPos", 3 }, { "end_pos", "float", "EndPos", 3 }, { "start_orient", "float", "StartOrient", 3 }, { "end_orient", "float", "EndOrient", 3 },  },
	"Cbf_ArgsArc": { { "start", "float", "Start", 3 }, { "middle", "float", "Middle", 3 }, { "end", "float", "End", 3 },  },
	"Cbf_ArgsArc5b": { { "start_pos", "float", "StartPos", 3 }, { "mid_pos", "float", "MidPos", 3 }, { "end_pos", "float", "EndPos", 3 }, { "start_orient", "float", "StartOrient", 3 }, { "end_orient", "float", "EndOrient", 3 },  },
	"Cbf_ArgsCircle": { { "start", "float", "Start", 3 }, { "center", "float", "Center", 3 }, { "normal", "float", "Normal", 3 }, { "ndegrees", "float", "Ndegrees", 1 },  },
	"Cbf_ArgsCircle5b": { { "start", "float", "Start", 3 }, { "center", "float", "Center", 3 }, { "normal", "float", "Normal", 3 }, { "ndegrees", "float", "Ndegrees", 1 }, { "start_orient", "float", "StartOrient", 3 }, { "end_orient", "float", "EndOrient", 3 },  },
	"Cbf_ArgsHelix": { { "start", "float", "Start", 3 }, { "center", "float", "Center", 3 }, { "normal", "float", "Normal", 3 }, { "ndegrees", "float", "Ndegrees", 1 }, { "length", "float", "Length", 1 },  },
	"Cbf_ArgsHelix5b": { { "start", "float", "Start", 3 }, { "center", "float", "Center", 3 }, { "normal", "float", "Normal", 3 }, { "ndegrees", "float", "Ndegrees", 1 }, { "length", "float", "Length", 1 }, { "start_orient", "float", "StartOrient", 3 }, { "end_orient", "float", "EndOrient", 3 },  },
	"Cbf_ArgsSpeed": { { "speed", "float", "Speed", 1 },  },
	"Cbf_ArgsAccel": { { "accel", "float", "Accel", 1 }, { "decel", "float", "Decel", 1 },  },
	"Cbf_ArgsCutterOn": {  },
	"Cbf_ArgsCutterOff": {  },
	"Cbf_ArgsGuide": { { "message", "string", "Message", 1 },  },
	"Cbf_ArgsFcparms": { { "nom_speed", "float", "NomSpeed", 1 }, { "max_speed", "float", "MaxSpeed", 1 }, { "min_speed", "float", "MinSpeed", 1 }, { "max_force", "float", "MaxForce", 1 },  },
	"Cbf_ArgsVersion": { { "cutfile", "string", "Cutfile", 1 }, { "format", "string", "Format", 1 }, { "reserved", "bytes", "Reserved", 1 },  },
	"Cbf_ArgsVersionImplib": { { "cutfile", "string", "Cutfile", 1 }, { "format", "string", "Format", 1 },  },
	"Cbf_ArgsComment": { { "text", "string", "Text", 1 },  },
}
var commandNames = map[int]string{ 60: "CHECKPOINT", 163: "CUTTER", 88: "ORIENT", 89: "ORIENT5B", 33: "PHASE", 34: "ENABLE_SKIP", 201: "STARTSHAPE", 101: "ENDSHAPE", 43: "DECEL_OFF", 78: "DECEL_ON", 51: "POINT", 182: "LINE", 183: "LINE5B", 148: "ARC", 149: "ARC5B", 122: "CIRCLE", 123: "CIRCLE5B", 226: "HELIX", 227: "HELIX5B", 139: "SPEED", 71: "ACCEL", 187: "CUTTER_ON", 102: "CUTTER_OFF", 17: "GUIDE", 252: "FCPARMS", 85: "VERSION", 90: "COMMENT",  }

func f32(v float32) interface{} {
	bits := math.Float32bits(v)
	f := float64(v)
	if math.IsNaN(f) || math.IsInf(f, 0) || (v == 0 && bits>>31 == 1) {
		return fmt.Sprintf("0x%08x", bits)
	}
	return f
}

func value(f field, v reflect.Value) interface{} {
	if f.Count < 0 { // a repeated group: items of -Count elements, read flat
		one := field{f.Name, f.Kind, f.Go, 1}
		flat := make([]interface{}, v.Len())
		for i := 0; i < v.Len(); i++ {
			flat[i] = value(one, v.Index(i))
		}
		if f.Count == -1 {
			return flat
		}
		items := []interface{}{}
		for i := 0; i < len(flat); i += -f.Count {
			items = append(items, flat[i:i-f.Count])
		}
		return items
	}
	switch f.Kind {
	case "float":
		if f.Count > 1 {
			out := make([]interface{}, v.Len())
			for i := 0; i < v.Len(); i++ {
				out[i] = f32(float32(v.Index(i).Float()))
			}
			return out
		}
		return f32(float32(v.Float()))
	case "bytes":
		return hex.EncodeToString(v.Bytes())
	case "string":
		return v.String()
	}
	switch v.Kind() { // an integer of the width and signedness its type gives (s1..s8 read as Go's intN)
	case reflect.Int, reflect.Int8, reflect.Int16, reflect.Int32, reflect.Int64:
		return v.Int()
	default:
		return v.Uint()
	}
}

func fields(obj interface{}, spec []field) map[string]interface{} {
	out := map[string]interface{}{}
	v := reflect.ValueOf(obj).Elem()
	for _, f := range spec {
		out[f.Name] = value(f, v.FieldByName(f.Go))
	}
	return out
}

func failure(kind string, offset interface{}, err error) map[string]interface{} {
	return map[string]interface{}{"ok": false, "error": map[string]interface{}{"kind": kind, "offset": offset, "message": err.Error()}}
}

func decode(path string) map[string]interface{} {
	data, err := os.ReadFile(path)
	if err != nil {
		return failure("exception", nil, err)
	}
	if len(data) < headerSize {
		return failure("truncated_header", 0, errors.New("short header"))
	}
	stream := kaitai.NewStream(bytesReader(data))
	root := NewCbf()
	root._io, root._root = stream, root
	header := NewCbf_Header()
	if err := header.Read(stream, root, root); err != nil {
		return failure("validation", 0, err)
	}
	root.Header = header
	head := fields(header, headerFields)
	tail := header.Layout
	for k, v := range fields(tail, headerTails[reflect.TypeOf(tail).Elem().Name()]) {
		head[k] = v
	}
	records := []interface{}{}
	for {
		eof, err := stream.EOF()
		if err != nil {
			return failure("exception", nil, err)
		}
		if eof {
			break
		}
		pos, _ := stream.Pos()
		rec := NewCbf_Record()
		if err := rec.Read(stream, root, root); err != nil {
			kind := "validation"
			if errors.Is(err, io.ErrUnexpectedEOF) || errors.Is(err, io.EOF) {
				kind = "truncated_record"
			}
			return failure(kind, pos, err)
		}
		out := fields(rec, recordFields)
		out["offset"] = pos
		if name, ok := commandNames[int(rec.Code)]; ok {
			out["command"] = name
		} else {
			out["command"] = nil
		}
		if raw, ok := rec.Args.([]byte); ok || rec.Args == nil {
			if !ok {
				raw = rec._raw_Args
			}
			out["args"] = nil
			out["raw_args"] = hex.EncodeToString(raw)
		} else {
			out["args"] = fields(rec.Args, argsFields[reflect.TypeOf(rec.Args).Elem().Name()])
		}
		records = append(records, out)
	}
	return map[string]interface{}{"ok": true, "result": map[string]interface{}{"header": head, "records": records, "trailing": ""}}
}

// RunTestee answers JSON-line requests on stdin until {"op": "quit"} or the end of input.
func RunTestee() int {
	in := bufio.NewScanner(os.Stdin)
	in.Buffer(make([]byte, 1<<20), 1<<30)
	out := bufio.NewWriter(os.Stdout)
	for in.Scan() {
		var req map[string]interface{}
		if err := json.Unmarshal(in.Bytes(), &req); err != nil {
			continue
		}
		var answer map[string]interface{}
		switch req["op"] {
		case "quit":
			out.Flush()
			return 0
		case "decode":
			path, _ := req["file"].(string)
			answer = decode(path)
		default:
			answer = map[string]interface{}{"skipped": true}
		}
		line, _ := json.Marshal(answer)
		out.Write(line)
		out.WriteString("\n")
		out.Flush()
	}
	return 0
}

func bytesReader(b []byte) io.ReadSeeker { return bytes.NewReader(b) }
