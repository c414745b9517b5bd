// Conformance testee of the Kaitai-generated Java parser (conformance/PROTOCOL.md).
// Generated from spec/cbf.yaml by cbfgen; do not edit. Decode only: it drives the
// parser record by record and writes the canonical JSON. It uses the parser as a
// user does: the class Cbf of the package com.thinksurgical.cbf.kaitai.

import com.thinksurgical.cbf.kaitai.Cbf;
import io.kaitai.struct.ByteBufferKaitaiStream;
import io.kaitai.struct.KaitaiStream;
import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Paths;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

public class Testee {
    static final int HEADER_SIZE = 128;
    static final String[][] HEADER_FIELDS = { { "start_pattern", "uint", "1", "startPattern" }, { "file_checksum", "uint", "1", "fileChecksum" }, { "header_checksum", "uint", "1", "headerChecksum" }, { "reserved_ecc", "bytes", "1", "reservedEcc" }, { "version_major", "uint", "1", "versionMajor" }, { "version_minor", "uint", "1", "versionMinor" },  };
    static final Map<String, String[][]> HEADER_TAILS = new HashMap<>();
    static final String[][] RECORD_FIELDS = { { "sequence", "uint", "1", "sequence" }, { "code", "uint", "1", "code" }, { "code_copy", "uint", "1", "codeCopy" }, { "arg_size", "uint", "1", "argSize" }, { "reserved", "uint", "1", "reserved" }, { "arg_checksum", "uint", "1", "argChecksum" },  };
    static final Map<String, String[][]> ARGS = new HashMap<>();
    static final Map<Integer, String> COMMANDS = new HashMap<>();
    static {
        HEADER_TAILS.put("HeaderV2", new String[][] { { "implant_descriptor", "string", "1", "implantDescriptor" }, { "configuration_descriptor", "string", "1", "configurationDescriptor" }, { "command_count", "uint", "1", "commandCount" }, { "end_pattern", "uint", "1", "endPattern" },  });
        HEADER_TAILS.put("HeaderV1", new String[][] { { "implant_descriptor", "string", "1", "implantDescriptor" }, { "reserved_98", "bytes", "1", "reserved98" }, { "command_count", "uint", "1", "commandCount" }, { "end_pattern", "uint", "1", "endPattern" },  });
        ARGS.put("ArgsCheckpoint", new String[][] { { "name", "string", "1", "name" }, { "recovery_point", "float", "3", "recoveryPoint" }, { "completion", "float", "1", "completion" },  });
        ARGS.put("ArgsCheckpointV1", new String[][] { { "name", "string", "1", "name" },  });
        ARGS.put("ArgsCutter", new String[][] { { "name", "string", "1", "name" }, { "length", "float", "1", "length" }, { "radius", "float", "1", "radius" }, { "head_length", "float", "1", "headLength" }, { "reserved", "bytes", "1", "reserved" },  });
        ARGS.put("ArgsCutterV1", new String[][] { { "name", "string", "1", "name" }, { "length", "float", "1", "length" }, { "radius", "float", "1", "radius" }, { "reserved", "bytes", "1", "reserved" },  });
        ARGS.put("ArgsOrient", new String[][] { { "approach", "float", "3", "approach" }, { "reserved", "bytes", "1", "reserved" },  });
        ARGS.put("ArgsOrient5b", new String[][] { { "start_approach", "float", "3", "startApproach" }, { "end_approach", "float", "3", "endApproach" },  });
        ARGS.put("ArgsPhase", new String[][] { { "name", "string", "1", "name" },  });
        ARGS.put("ArgsEnableSkip", new String[][] { { "name", "string", "1", "name" },  });
        ARGS.put("ArgsStartshape", new String[][] { { "name", "string", "1", "name" }, { "moves", "uint", "1", "moves" },  });
        ARGS.put("ArgsEndshape", new String[][] { { "name", "string", "1", "name" }, { "moves", "uint", "1", "moves" },  });
        ARGS.put("ArgsDecelOff", new String[][] {  });
        ARGS.put("ArgsDecelOn", new String[][] {  });
        ARGS.put("ArgsPoint", new String[][] { { "point", "float", "3", "point" },  });
        ARGS.put("ArgsLine", new String[][] { { "start", "float", "3", "start" }, { "end", "float", "3", "end" },  });
        ARGS.put("ArgsLine5b", new String[][] { { "start_pos", "float", "3", "startPos" }, { "end_pos", "float", "3", "endPos" }, { "start_orient", "float", "3", "startOrient" }, { "end_orient", "float", "3", "endOrient" },  });
        ARGS.put("ArgsArc", new String[][] { { "start", "float", "3", "start" }, { "middle", "float", "3", "middle" }, { "end", "float", "3", "end" },  });
        ARGS.put("ArgsArc5b", new String[][] { { "start_pos", "float", "3", "startPos" }, { "mid_pos", "float", "3", "midPos" }, { "end_pos", "float", "3", "endPos" }, { "start_orient", "float", "3", "startOrient" }, { "end_orient", "float", "3", "endOrient" },  });
        ARGS.put("ArgsCircle", new String[][] { { "start", "float", "3", "start" }, { "center", "float", "3", "center" }, { "normal", "float", "3", "normal" }, { "ndegrees", "float", "1", "ndegrees" },  });
        ARGS.put("ArgsCircle5b", new String[][] { { "start", "float", "3", "start" }, { "center", "float", "3", "center" }, { "normal", "float", "3", "normal" }, { "ndegrees", "float", "1", "ndegrees" }, { "start_orient", "float", "3", "startOrient" }, { "end_orient", "float", "3", "endOrient" },  });
        ARGS.put("ArgsHelix", new String[][] { { "start", "float", "3", "start" }, { "center", "float", "3", "center" }, { "normal", "float", "3", "normal" }, { "ndegrees", "float", "1", "ndegrees" }, { "length", "float", "1", "length" },  });
        ARGS.put("ArgsHelix5b", new String[][] { { "start", "float", "3", "start" }, { "center", "float", "3", "center" }, { "normal", "float", "3", "normal" }, { "ndegrees", "float", "1", "ndegrees" }, { "length", "float", "1", "length" }, { "start_orient", "float", "3", "startOrient" }, { "end_orient", "float", "3", "endOrient" },  });
        ARGS.put("ArgsSpeed", new String[][] { { "speed", "float", "1", "speed" },  });
        ARGS.put("ArgsAccel", new String[][] { { "accel", "float", "1", "accel" }, { "decel", "float", "1", "decel" },  });
        ARGS.put("ArgsCutterOn", new String[][] {  });
        ARGS.put("ArgsCutterOff", new String[][] {  });
        ARGS.put("ArgsGuide", new String[][] { { "message", "string", "1", "message" },  });
        ARGS.put("ArgsFcparms", new String[][] { { "nom_speed", "float", "1", "nomSpeed" }, { "max_speed", "float", "1", "maxSpeed" }, { "min_speed", "float", "1", "minSpeed" }, { "max_force", "float", "1", "maxForce" },  });
        ARGS.put("ArgsVersion", new String[][] { { "cutfile", "string", "1", "cutfile" }, { "format", "string", "1", "format" }, { "reserved", "bytes", "1", "reserved" },  });
        ARGS.put("ArgsVersionImplib", new String[][] { { "cutfile", "string", "1", "cutfile" }, { "format", "string", "1", "format" },  });
        ARGS.put("ArgsComment", new String[][] { { "text", "string", "1", "text" },  });
        COMMANDS.put(60, "CHECKPOINT");
        COMMANDS.put(163, "CUTTER");
        COMMANDS.put(88, "ORIENT");
        COMMANDS.put(89, "ORIENT5B");
        COMMANDS.put(33, "PHASE");
        COMMANDS.put(34, "ENABLE_SKIP");
        COMMANDS.put(201, "STARTSHAPE");
        COMMANDS.put(101, "ENDSHAPE");
        COMMANDS.put(43, "DECEL_OFF");
        COMMANDS.put(78, "DECEL_ON");
        COMMANDS.put(51, "POINT");
        COMMANDS.put(182, "LINE");
        COMMANDS.put(183, "LINE5B");
        COMMANDS.put(148, "ARC");
        COMMANDS.put(149, "ARC5B");
        COMMANDS.put(122, "CIRCLE");
        COMMANDS.put(123, "CIRCLE5B");
        COMMANDS.put(226, "HELIX");
        COMMANDS.put(227, "HELIX5B");
        COMMANDS.put(139, "SPEED");
        COMMANDS.put(71, "ACCEL");
        COMMANDS.put(187, "CUTTER_ON");
        COMMANDS.put(102, "CUTTER_OFF");
        COMMANDS.put(17, "GUIDE");
        COMMANDS.put(252, "FCPARMS");
        COMMANDS.put(85, "VERSION");
        COMMANDS.put(90, "COMMENT");
    }

    static String str(String s) {
        StringBuilder b = new StringBuilder("\"");
        for (char ch : s.toCharArray()) {
            if (ch == '"' || ch == '\\') b.append('\\').append(ch);
            else if (ch < 0x20 || ch > 0x7e) b.append(String.format("\\u%04x", (int) ch));
            else b.append(ch);
        }
        return b.append('"').toString();
    }

    static String f32(float v) {
        int bits = Float.floatToRawIntBits(v);
        if (Float.isNaN(v) || Float.isInfinite(v) || (v == 0.0f && bits != 0)) return str(String.format("0x%08x", bits));
        return Double.toString((double) v);
    }

    static String hex(byte[] b) {
        StringBuilder s = new StringBuilder();
        for (byte x : b) s.append(String.format("%02x", x & 0xff));
        return s.toString();
    }

    static String value(String[] f, Object v) {
        int count = Integer.parseInt(f[2]);
        if (count < 0) { // a repeated group: items of -count elements, read flat
            String[] one = {f[0], f[1], "1", f[3]};
            List<?> list = (List<?>) v;
            StringBuilder b = new StringBuilder("[");
            for (int i = 0; i < list.size(); i++) {
                boolean open = count < -1 && i % -count == 0, close = count < -1 && (i + 1) % -count == 0;
                b.append(i > 0 ? ", " : "").append(open ? "[" : "").append(value(one, list.get(i))).append(close ? "]" : "");
            }
            return b.append("]").toString();
        }
        switch (f[1]) {
            case "float":
                if (!f[2].equals("1")) {
                    StringBuilder b = new StringBuilder("[");
                    List<?> list = (List<?>) v;
                    for (int i = 0; i < list.size(); i++) b.append(i > 0 ? ", " : "").append(f32((Float) list.get(i)));
                    return b.append("]").toString();
                }
                return f32((Float) v);
            case "bytes": return str(hex((byte[]) v));
            case "string": return str((String) v);
            default: return String.valueOf(((Number) v).longValue());
        }
    }

    static void fields(StringBuilder out, Object obj, String[][] spec) throws Exception {
        for (String[] f : spec) {
            Object v = obj.getClass().getMethod(f[3]).invoke(obj);
            out.append(out.charAt(out.length() - 1) == '{' ? "" : ", ").append(str(f[0])).append(": ").append(value(f, v));
        }
    }

    /** Runner error kind of a parse exception: Kaitai's validation errors, or reads past the end. */
    static String kind(Exception e) {
        if (e instanceof KaitaiStream.ValidationFailedError) return "validation";
        // ByteBufferKaitaiStream reads past the end as BufferUnderflowException, and a
        // size-limited substream longer than the rest as IllegalArgumentException from Buffer.limit.
        if (e instanceof java.nio.BufferUnderflowException || e instanceof java.io.EOFException
                || e instanceof IllegalArgumentException) return "truncated_record";
        return "exception";
    }

    static String error(String kind, Object offset, Throwable e) {
        return "{\"ok\": false, \"error\": {\"kind\": " + str(kind) + ", \"offset\": " + offset + ", \"message\": "
            + str(e.getMessage() != null ? e.getMessage() : e.getClass().getSimpleName()) + "}}";
    }

    static String decode(String path) throws Exception {
        byte[] data = Files.readAllBytes(Paths.get(path));
        if (data.length < HEADER_SIZE) return error("truncated_header", 0, new Exception("short header"));
        Cbf root;
        try {
            root = new Cbf(new ByteBufferKaitaiStream(Arrays.copyOf(data, HEADER_SIZE)));
        } catch (Exception e) {
            return error(kind(e), 0, e);
        }
        StringBuilder out = new StringBuilder("{\"ok\": true, \"result\": {\"header\": {");
        fields(out, root.header(), HEADER_FIELDS);
        Object tail = root.header().layout();
        fields(out, tail, HEADER_TAILS.get(tail.getClass().getSimpleName()));
        out.append("}, \"records\": [");
        KaitaiStream io = new ByteBufferKaitaiStream(data);
        io.seek(HEADER_SIZE);
        boolean first = true;
        while (!io.isEof()) {
            long pos = io.pos();
            Cbf.Record rec;
            try {
                rec = new Cbf.Record(io, root, root);
            } catch (Exception e) {
                return error(kind(e), pos, e);
            }
            out.append(first ? "{" : ", {");
            first = false;
            out.append("\"offset\": ").append(pos);
            fields(out, rec, RECORD_FIELDS);
            String name = COMMANDS.get(rec.code());
            out.append(", \"command\": ").append(name == null ? "null" : str(name));
            Object args = rec.args();
            if (args instanceof byte[]) {
                out.append(", \"args\": null, \"raw_args\": ").append(str(hex((byte[]) args)));
            } else {
                out.append(", \"args\": {");
                fields(out, args, ARGS.get(args.getClass().getSimpleName()));
                out.append("}");
            }
            out.append("}");
        }
        return out.append("], \"trailing\": \"\"}}").toString();
    }

    public static void main(String[] argv) throws Exception {
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
        PrintStream out = new PrintStream(System.out, false, "UTF-8");
        Pattern op = Pattern.compile("\"op\"\\s*:\\s*\"(\\w+)\"");
        Pattern file = Pattern.compile("\"file\"\\s*:\\s*\"((?:[^\"\\\\]|\\\\.)*)\"");
        String line;
        while ((line = in.readLine()) != null) {
            if (line.trim().isEmpty()) continue;
            Matcher m = op.matcher(line);
            String o = m.find() ? m.group(1) : "";
            if (o.equals("quit")) break;
            String answer;
            if (o.equals("decode")) {
                Matcher f = file.matcher(line);
                try {
                    answer = f.find() ? decode(f.group(1).replace("\\\\", "\\").replace("\\\"", "\"")) : error("exception", null, new Exception("no file"));
                } catch (Exception e) {
                    answer = error("exception", null, e);
                }
            } else {
                answer = "{\"skipped\": true}";
            }
            out.println(answer);
            out.flush();
        }
    }
}
