// This is a generated file! Please edit source .ksy file and use kaitai-struct-compiler to rebuild

package com.thinksurgical.cbf.kaitai;

import io.kaitai.struct.ByteBufferKaitaiStream;
import io.kaitai.struct.KaitaiStruct;
import io.kaitai.struct.KaitaiStream;
import java.io.IOException;
import java.util.Map;
import java.util.HashMap;
import java.util.ArrayList;
import java.util.List;
import java.nio.charset.StandardCharsets;


/**
 * The CBF file provides the toolpath information for cutting implant cavities with the ROBODOC System (1.1). It carries a 128-byte header and a sequence of variable-length command records. It can be created from, and converted to, an ASCII format, the CUT file (1.2). Generated from spec/cbf.yaml; do not edit. Kaitai checks here the magic numbers, the code copy, the argument size per command and version, and version gating. It cannot check: 4.2 (The file header is 128 bytes long.); 4.3 (The cutting data consists of variable length records.); 6.1.1 (The first word in the Implant Descriptor field in the file header should be the implant part number.); part_number_first (The implant descriptor begins with the implant part number (4.2; 6.1.1 compares it when one is given).); 6.1.2 (The length and radius of every cutter (specified by the CUTTER command) should agree, within 0.01 millimeters, with the values specified in the robot's cutter database.); 6.2.1 (The checksum of the entire file should match the value specified in the file header.); 6.2.2 (The number of commands in the file should match the value specified in the file header.); 6.3.1 (The checksum of the file header should match the specified value.); 6.4.1 (The sequence number should be one greater than the previous sequence number (first record should have sequence number 0).); 6.4.4 (The checksum of the command argument bytes should match the specified value.); 6.4.5 (The starting point of a motion command (e.g., LINE, ARC, CIRCLE, etc.) should match the ending point of the previous motion command.); version_supported (The processing software can read the version number and adjust the parsing logic appropriately.); unknown_command (An unknown command code is an error; its record is kept whole.); trailing_bytes (No byte follows the last record.); reserved_nonzero (The record's reserved byte should be 0.); string_tail (A string ends at its first NUL; the bytes after it are padding.); string_ascii (Strings are ASCII.); non_finite (Floats are finite.); speed_positive (SPEED is greater than 0.); accel_positive (Acceleration and deceleration are greater than 0.); cutter_positive (Cutter length and radius are greater than 0.); normal_nonzero (A circle or helix normal has non-zero length.); checkpoint_range (CHECKPOINT completion lies in 0..100.); checkpoint_falling (CHECKPOINT completion does not fall.); fcparms_order (FCPARMS speeds satisfy min <= nom <= max.); orientation_jump (A 5-axis command starts at the current tool orientation.); machine_limits (Positions lie in the machine's workspace; speeds, accelerations and cutter sizes lie in its ranges.); shape (STARTSHAPE name,n ... ENDSHAPE name,n enclose exactly n motion commands; shapes do not nest.).
 * @see "Specification, Implant Support Software, TCAT, part number 300071, revision 03"
 */
public class Cbf extends KaitaiStruct {
    public static Cbf fromFile(String fileName) throws IOException {
        return new Cbf(new ByteBufferKaitaiStream(fileName));
    }

    public enum Command {
        GUIDE(17),
        PHASE(33),
        ENABLE_SKIP(34),
        DECEL_OFF(43),
        POINT(51),
        CHECKPOINT(60),
        ACCEL(71),
        DECEL_ON(78),
        VERSION(85),
        ORIENT(88),
        ORIENT5B(89),
        COMMENT(90),
        ENDSHAPE(101),
        CUTTER_OFF(102),
        CIRCLE(122),
        CIRCLE5B(123),
        SPEED(139),
        ARC(148),
        ARC5B(149),
        CUTTER(163),
        LINE(182),
        LINE5B(183),
        CUTTER_ON(187),
        STARTSHAPE(201),
        HELIX(226),
        HELIX5B(227),
        FCPARMS(252);

        private final long id;
        Command(long id) { this.id = id; }
        public long id() { return id; }
        private static final Map<Long, Command> byId = new HashMap<Long, Command>(27);
        static {
            for (Command e : Command.values())
                byId.put(e.id(), e);
        }
        public static Command byId(long id) { return byId.get(id); }
    }

    public Cbf(KaitaiStream _io) {
        this(_io, null, null);
    }

    public Cbf(KaitaiStream _io, KaitaiStruct _parent) {
        this(_io, _parent, null);
    }

    public Cbf(KaitaiStream _io, KaitaiStruct _parent, Cbf _root) {
        super(_io);
        this._parent = _parent;
        this._root = _root == null ? this : _root;
        _read();
    }
    private void _read() {
        this.header = new Header(this._io, this, _root);
        this.records = new ArrayList<Record>();
        {
            int i = 0;
            while (!this._io.isEof()) {
                this.records.add(new Record(this._io, this, _root));
                i++;
            }
        }
    }

    public void _fetchInstances() {
        this.header._fetchInstances();
        for (int i = 0; i < this.records.size(); i++) {
            this.records.get(((Number) (i)).intValue())._fetchInstances();
        }
    }

    /**
     * ACCEL: Acceleration and deceleration. Versions 1.x, 2.x, 3.0, 4.0; 8 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsAccel extends KaitaiStruct {
        public static ArgsAccel fromFile(String fileName) throws IOException {
            return new ArgsAccel(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsAccel(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsAccel(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsAccel(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.accel = this._io.readF4le();
            this.decel = this._io.readF4le();
        }

        public void _fetchInstances() {
        }
        private float accel;
        private float decel;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Acceleration. [m/s^2]
         */
        public float accel() { return accel; }

        /**
         * Deceleration. [m/s^2]
         */
        public float decel() { return decel; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * ARC: Arc move. Versions 1.x, 2.x, 3.0; 36 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsArc extends KaitaiStruct {
        public static ArgsArc fromFile(String fileName) throws IOException {
            return new ArgsArc(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsArc(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsArc(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsArc(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.start = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.start.add(this._io.readF4le());
            }
            this.middle = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.middle.add(this._io.readF4le());
            }
            this.end = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.end.add(this._io.readF4le());
            }
        }

        public void _fetchInstances() {
            for (int i = 0; i < this.start.size(); i++) {
            }
            for (int i = 0; i < this.middle.size(); i++) {
            }
            for (int i = 0; i < this.end.size(); i++) {
            }
        }
        private List<Float> start;
        private List<Float> middle;
        private List<Float> end;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Start point. [mm]
         */
        public List<Float> start() { return start; }

        /**
         * A point in the middle of the arc. [mm]
         */
        public List<Float> middle() { return middle; }

        /**
         * End point. [mm]
         */
        public List<Float> end() { return end; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * ARC5B: Arc move, 5 axis. Versions 1.x, 2.x, 3.0; 60 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsArc5b extends KaitaiStruct {
        public static ArgsArc5b fromFile(String fileName) throws IOException {
            return new ArgsArc5b(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsArc5b(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsArc5b(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsArc5b(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.startPos = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.startPos.add(this._io.readF4le());
            }
            this.midPos = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.midPos.add(this._io.readF4le());
            }
            this.endPos = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.endPos.add(this._io.readF4le());
            }
            this.startOrient = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.startOrient.add(this._io.readF4le());
            }
            this.endOrient = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.endOrient.add(this._io.readF4le());
            }
        }

        public void _fetchInstances() {
            for (int i = 0; i < this.startPos.size(); i++) {
            }
            for (int i = 0; i < this.midPos.size(); i++) {
            }
            for (int i = 0; i < this.endPos.size(); i++) {
            }
            for (int i = 0; i < this.startOrient.size(); i++) {
            }
            for (int i = 0; i < this.endOrient.size(); i++) {
            }
        }
        private List<Float> startPos;
        private List<Float> midPos;
        private List<Float> endPos;
        private List<Float> startOrient;
        private List<Float> endOrient;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Start position. [mm]
         */
        public List<Float> startPos() { return startPos; }

        /**
         * Middle position. [mm]
         */
        public List<Float> midPos() { return midPos; }

        /**
         * End position. [mm]
         */
        public List<Float> endPos() { return endPos; }

        /**
         * Start orientation.
         */
        public List<Float> startOrient() { return startOrient; }

        /**
         * End orientation.
         */
        public List<Float> endOrient() { return endOrient; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * CHECKPOINT: Check-point. Versions 2.x, 3.0, 4.0; 32 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsCheckpoint extends KaitaiStruct {
        public static ArgsCheckpoint fromFile(String fileName) throws IOException {
            return new ArgsCheckpoint(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsCheckpoint(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsCheckpoint(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsCheckpoint(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.name = new String(KaitaiStream.bytesStripRight(this._io.readBytes(16), (byte) 0), StandardCharsets.ISO_8859_1);
            this.recoveryPoint = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.recoveryPoint.add(this._io.readF4le());
            }
            this.completion = this._io.readF4le();
        }

        public void _fetchInstances() {
            for (int i = 0; i < this.recoveryPoint.size(); i++) {
            }
        }
        private String name;
        private List<Float> recoveryPoint;
        private float completion;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Check-point name.
         */
        public String name() { return name; }

        /**
         * Recovery point. [mm]
         */
        public List<Float> recoveryPoint() { return recoveryPoint; }

        /**
         * Completion percentage. [percent]
         */
        public float completion() { return completion; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * CHECKPOINT: Check-point. Versions 1.x; 16 bytes.
     * @see "300071 rev 03, 7.2.2.2"
     */
    public static class ArgsCheckpointV1 extends KaitaiStruct {
        public static ArgsCheckpointV1 fromFile(String fileName) throws IOException {
            return new ArgsCheckpointV1(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsCheckpointV1(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsCheckpointV1(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsCheckpointV1(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.name = new String(KaitaiStream.bytesStripRight(this._io.readBytes(16), (byte) 0), StandardCharsets.ISO_8859_1);
        }

        public void _fetchInstances() {
        }
        private String name;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Check-point name.
         */
        public String name() { return name; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * CIRCLE: Circle. Versions 1.x, 2.x, 3.0; 40 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsCircle extends KaitaiStruct {
        public static ArgsCircle fromFile(String fileName) throws IOException {
            return new ArgsCircle(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsCircle(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsCircle(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsCircle(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.start = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.start.add(this._io.readF4le());
            }
            this.center = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.center.add(this._io.readF4le());
            }
            this.normal = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.normal.add(this._io.readF4le());
            }
            this.ndegrees = this._io.readF4le();
        }

        public void _fetchInstances() {
            for (int i = 0; i < this.start.size(); i++) {
            }
            for (int i = 0; i < this.center.size(); i++) {
            }
            for (int i = 0; i < this.normal.size(); i++) {
            }
        }
        private List<Float> start;
        private List<Float> center;
        private List<Float> normal;
        private float ndegrees;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Start point. [mm]
         */
        public List<Float> start() { return start; }

        /**
         * Centre point. [mm]
         */
        public List<Float> center() { return center; }

        /**
         * Axis direction (need not be unit length); rotation by the right-hand rule.
         */
        public List<Float> normal() { return normal; }

        /**
         * Angle swept about the normal. [deg]
         */
        public float ndegrees() { return ndegrees; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * CIRCLE5B: Circle, 5 axis. Versions 1.x, 2.x, 3.0; 64 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsCircle5b extends KaitaiStruct {
        public static ArgsCircle5b fromFile(String fileName) throws IOException {
            return new ArgsCircle5b(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsCircle5b(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsCircle5b(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsCircle5b(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.start = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.start.add(this._io.readF4le());
            }
            this.center = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.center.add(this._io.readF4le());
            }
            this.normal = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.normal.add(this._io.readF4le());
            }
            this.ndegrees = this._io.readF4le();
            this.startOrient = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.startOrient.add(this._io.readF4le());
            }
            this.endOrient = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.endOrient.add(this._io.readF4le());
            }
        }

        public void _fetchInstances() {
            for (int i = 0; i < this.start.size(); i++) {
            }
            for (int i = 0; i < this.center.size(); i++) {
            }
            for (int i = 0; i < this.normal.size(); i++) {
            }
            for (int i = 0; i < this.startOrient.size(); i++) {
            }
            for (int i = 0; i < this.endOrient.size(); i++) {
            }
        }
        private List<Float> start;
        private List<Float> center;
        private List<Float> normal;
        private float ndegrees;
        private List<Float> startOrient;
        private List<Float> endOrient;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Start point. [mm]
         */
        public List<Float> start() { return start; }

        /**
         * Centre point. [mm]
         */
        public List<Float> center() { return center; }

        /**
         * Axis direction (need not be unit length); rotation by the right-hand rule.
         */
        public List<Float> normal() { return normal; }

        /**
         * Angle swept about the normal. [deg]
         */
        public float ndegrees() { return ndegrees; }

        /**
         * Start orientation.
         */
        public List<Float> startOrient() { return startOrient; }

        /**
         * End orientation.
         */
        public List<Float> endOrient() { return endOrient; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * COMMENT: Comment. Versions 1.x, 2.x, 3.0, 4.0; 40 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsComment extends KaitaiStruct {
        public static ArgsComment fromFile(String fileName) throws IOException {
            return new ArgsComment(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsComment(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsComment(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsComment(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.text = new String(KaitaiStream.bytesStripRight(this._io.readBytes(40), (byte) 0), StandardCharsets.ISO_8859_1);
        }

        public void _fetchInstances() {
        }
        private String text;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Comment text.
         */
        public String text() { return text; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * CUTTER: Change cutter. Versions 2.x, 3.0, 4.0; 32 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsCutter extends KaitaiStruct {
        public static ArgsCutter fromFile(String fileName) throws IOException {
            return new ArgsCutter(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsCutter(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsCutter(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsCutter(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.name = new String(KaitaiStream.bytesStripRight(this._io.readBytes(16), (byte) 0), StandardCharsets.ISO_8859_1);
            this.length = this._io.readF4le();
            this.radius = this._io.readF4le();
            this.headLength = this._io.readF4le();
            this.reserved = this._io.readBytes(4);
        }

        public void _fetchInstances() {
        }
        private String name;
        private float length;
        private float radius;
        private float headLength;
        private byte[] reserved;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Cutter name (part number).
         */
        public String name() { return name; }

        /**
         * Cutter length (6.1.2). [mm]
         */
        public float length() { return length; }

        /**
         * Cutter radius (6.1.2). [mm]
         */
        public float radius() { return radius; }

        /**
         * Cutter head length (7.2.2.3). [mm]
         */
        public float headLength() { return headLength; }

        /**
         * 4 bytes reserved (N7).
         */
        public byte[] reserved() { return reserved; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * CUTTER_OFF: Turn cutter off. Versions 1.x, 2.x, 3.0, 4.0; 0 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsCutterOff extends KaitaiStruct {
        public static ArgsCutterOff fromFile(String fileName) throws IOException {
            return new ArgsCutterOff(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsCutterOff(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsCutterOff(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsCutterOff(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
        }

        public void _fetchInstances() {
        }
        private Cbf _root;
        private Cbf.Record _parent;
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * CUTTER_ON: Turn cutter on. Versions 1.x, 2.x, 3.0, 4.0; 0 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsCutterOn extends KaitaiStruct {
        public static ArgsCutterOn fromFile(String fileName) throws IOException {
            return new ArgsCutterOn(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsCutterOn(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsCutterOn(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsCutterOn(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
        }

        public void _fetchInstances() {
        }
        private Cbf _root;
        private Cbf.Record _parent;
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * CUTTER: Change cutter. Versions 1.x; 32 bytes.
     * @see "300071 rev 03, 7.2.2.3"
     */
    public static class ArgsCutterV1 extends KaitaiStruct {
        public static ArgsCutterV1 fromFile(String fileName) throws IOException {
            return new ArgsCutterV1(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsCutterV1(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsCutterV1(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsCutterV1(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.name = new String(KaitaiStream.bytesStripRight(this._io.readBytes(16), (byte) 0), StandardCharsets.ISO_8859_1);
            this.length = this._io.readF4le();
            this.radius = this._io.readF4le();
            this.reserved = this._io.readBytes(8);
        }

        public void _fetchInstances() {
        }
        private String name;
        private float length;
        private float radius;
        private byte[] reserved;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Cutter name (part number).
         */
        public String name() { return name; }

        /**
         * Cutter length (6.1.2). [mm]
         */
        public float length() { return length; }

        /**
         * Cutter radius (6.1.2). [mm]
         */
        public float radius() { return radius; }

        /**
         * 8 bytes reserved; head length came in 2.0 (7.2.2.3).
         */
        public byte[] reserved() { return reserved; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * DECEL_OFF: Turn on motion blending (i.e., don't decelerate). Versions 2.x, 3.0, 4.0; 0 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsDecelOff extends KaitaiStruct {
        public static ArgsDecelOff fromFile(String fileName) throws IOException {
            return new ArgsDecelOff(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsDecelOff(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsDecelOff(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsDecelOff(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
        }

        public void _fetchInstances() {
        }
        private Cbf _root;
        private Cbf.Record _parent;
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * DECEL_ON: Turn off motion blending (i.e., decelerate). Versions 2.x, 3.0, 4.0; 0 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsDecelOn extends KaitaiStruct {
        public static ArgsDecelOn fromFile(String fileName) throws IOException {
            return new ArgsDecelOn(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsDecelOn(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsDecelOn(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsDecelOn(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
        }

        public void _fetchInstances() {
        }
        private Cbf _root;
        private Cbf.Record _parent;
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * ENABLE_SKIP: Enable skip to phase. Versions 1.x, 2.x, 3.0, 4.0; 16 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsEnableSkip extends KaitaiStruct {
        public static ArgsEnableSkip fromFile(String fileName) throws IOException {
            return new ArgsEnableSkip(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsEnableSkip(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsEnableSkip(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsEnableSkip(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.name = new String(KaitaiStream.bytesStripRight(this._io.readBytes(16), (byte) 0), StandardCharsets.ISO_8859_1);
        }

        public void _fetchInstances() {
        }
        private String name;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Name of the phase to skip to.
         */
        public String name() { return name; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * ENDSHAPE: End of a shape; same arguments as STARTSHAPE (redundancy). Versions 1.x, 2.x, 3.0, 4.0; 6 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsEndshape extends KaitaiStruct {
        public static ArgsEndshape fromFile(String fileName) throws IOException {
            return new ArgsEndshape(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsEndshape(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsEndshape(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsEndshape(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.name = new String(KaitaiStream.bytesStripRight(this._io.readBytes(5), (byte) 0), StandardCharsets.ISO_8859_1);
            this.moves = this._io.readU1();
        }

        public void _fetchInstances() {
        }
        private String name;
        private int moves;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Shape name, as in STARTSHAPE.
         */
        public String name() { return name; }

        /**
         * Number of (move) commands, as in STARTSHAPE. [count]
         */
        public int moves() { return moves; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * FCPARMS: Force control parameters. Versions 2.x, 3.0, 4.0; 16 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsFcparms extends KaitaiStruct {
        public static ArgsFcparms fromFile(String fileName) throws IOException {
            return new ArgsFcparms(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsFcparms(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsFcparms(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsFcparms(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.nomSpeed = this._io.readF4le();
            this.maxSpeed = this._io.readF4le();
            this.minSpeed = this._io.readF4le();
            this.maxForce = this._io.readF4le();
        }

        public void _fetchInstances() {
        }
        private float nomSpeed;
        private float maxSpeed;
        private float minSpeed;
        private float maxForce;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Nominal speed. [m/s]
         */
        public float nomSpeed() { return nomSpeed; }

        /**
         * Maximum speed. [m/s]
         */
        public float maxSpeed() { return maxSpeed; }

        /**
         * Minimum speed. [m/s]
         */
        public float minSpeed() { return minSpeed; }

        /**
         * Maximum force. [N]
         */
        public float maxForce() { return maxForce; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * GUIDE: Guide message. Versions 1.x, 2.x, 3.0, 4.0; 32 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsGuide extends KaitaiStruct {
        public static ArgsGuide fromFile(String fileName) throws IOException {
            return new ArgsGuide(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsGuide(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsGuide(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsGuide(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.message = new String(KaitaiStream.bytesStripRight(this._io.readBytes(32), (byte) 0), StandardCharsets.ISO_8859_1);
        }

        public void _fetchInstances() {
        }
        private String message;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Message.
         */
        public String message() { return message; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * HELIX: Helix. Versions 2.x, 3.0; 44 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsHelix extends KaitaiStruct {
        public static ArgsHelix fromFile(String fileName) throws IOException {
            return new ArgsHelix(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsHelix(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsHelix(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsHelix(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.start = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.start.add(this._io.readF4le());
            }
            this.center = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.center.add(this._io.readF4le());
            }
            this.normal = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.normal.add(this._io.readF4le());
            }
            this.ndegrees = this._io.readF4le();
            this.length = this._io.readF4le();
        }

        public void _fetchInstances() {
            for (int i = 0; i < this.start.size(); i++) {
            }
            for (int i = 0; i < this.center.size(); i++) {
            }
            for (int i = 0; i < this.normal.size(); i++) {
            }
        }
        private List<Float> start;
        private List<Float> center;
        private List<Float> normal;
        private float ndegrees;
        private float length;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Start point. [mm]
         */
        public List<Float> start() { return start; }

        /**
         * Centre point. [mm]
         */
        public List<Float> center() { return center; }

        /**
         * Axis direction (need not be unit length); rotation by the right-hand rule.
         */
        public List<Float> normal() { return normal; }

        /**
         * Angle swept about the normal. [deg]
         */
        public float ndegrees() { return ndegrees; }

        /**
         * Axial advance along the unit normal. [mm]
         */
        public float length() { return length; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * HELIX5B: Helix, 5 axis. Versions 1.x, 2.x, 3.0; 68 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsHelix5b extends KaitaiStruct {
        public static ArgsHelix5b fromFile(String fileName) throws IOException {
            return new ArgsHelix5b(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsHelix5b(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsHelix5b(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsHelix5b(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.start = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.start.add(this._io.readF4le());
            }
            this.center = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.center.add(this._io.readF4le());
            }
            this.normal = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.normal.add(this._io.readF4le());
            }
            this.ndegrees = this._io.readF4le();
            this.length = this._io.readF4le();
            this.startOrient = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.startOrient.add(this._io.readF4le());
            }
            this.endOrient = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.endOrient.add(this._io.readF4le());
            }
        }

        public void _fetchInstances() {
            for (int i = 0; i < this.start.size(); i++) {
            }
            for (int i = 0; i < this.center.size(); i++) {
            }
            for (int i = 0; i < this.normal.size(); i++) {
            }
            for (int i = 0; i < this.startOrient.size(); i++) {
            }
            for (int i = 0; i < this.endOrient.size(); i++) {
            }
        }
        private List<Float> start;
        private List<Float> center;
        private List<Float> normal;
        private float ndegrees;
        private float length;
        private List<Float> startOrient;
        private List<Float> endOrient;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Start point. [mm]
         */
        public List<Float> start() { return start; }

        /**
         * Centre point. [mm]
         */
        public List<Float> center() { return center; }

        /**
         * Axis direction (need not be unit length); rotation by the right-hand rule.
         */
        public List<Float> normal() { return normal; }

        /**
         * Angle swept about the normal. [deg]
         */
        public float ndegrees() { return ndegrees; }

        /**
         * Axial advance along the unit normal. [mm]
         */
        public float length() { return length; }

        /**
         * Start orientation.
         */
        public List<Float> startOrient() { return startOrient; }

        /**
         * End orientation.
         */
        public List<Float> endOrient() { return endOrient; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * LINE: Straight line motion. Versions 1.x, 2.x, 3.0, 4.0; 24 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsLine extends KaitaiStruct {
        public static ArgsLine fromFile(String fileName) throws IOException {
            return new ArgsLine(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsLine(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsLine(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsLine(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.start = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.start.add(this._io.readF4le());
            }
            this.end = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.end.add(this._io.readF4le());
            }
        }

        public void _fetchInstances() {
            for (int i = 0; i < this.start.size(); i++) {
            }
            for (int i = 0; i < this.end.size(); i++) {
            }
        }
        private List<Float> start;
        private List<Float> end;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Start point. [mm]
         */
        public List<Float> start() { return start; }

        /**
         * End point. [mm]
         */
        public List<Float> end() { return end; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * LINE5B: Straight line motion, 5 axis. Versions 1.x, 2.x, 3.0, 4.0; 48 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsLine5b extends KaitaiStruct {
        public static ArgsLine5b fromFile(String fileName) throws IOException {
            return new ArgsLine5b(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsLine5b(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsLine5b(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsLine5b(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.startPos = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.startPos.add(this._io.readF4le());
            }
            this.endPos = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.endPos.add(this._io.readF4le());
            }
            this.startOrient = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.startOrient.add(this._io.readF4le());
            }
            this.endOrient = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.endOrient.add(this._io.readF4le());
            }
        }

        public void _fetchInstances() {
            for (int i = 0; i < this.startPos.size(); i++) {
            }
            for (int i = 0; i < this.endPos.size(); i++) {
            }
            for (int i = 0; i < this.startOrient.size(); i++) {
            }
            for (int i = 0; i < this.endOrient.size(); i++) {
            }
        }
        private List<Float> startPos;
        private List<Float> endPos;
        private List<Float> startOrient;
        private List<Float> endOrient;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Start position. [mm]
         */
        public List<Float> startPos() { return startPos; }

        /**
         * End position. [mm]
         */
        public List<Float> endPos() { return endPos; }

        /**
         * Start orientation.
         */
        public List<Float> startOrient() { return startOrient; }

        /**
         * End orientation.
         */
        public List<Float> endOrient() { return endOrient; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * ORIENT: Orientation change. Versions 1.x, 2.x, 3.0, 4.0; 24 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsOrient extends KaitaiStruct {
        public static ArgsOrient fromFile(String fileName) throws IOException {
            return new ArgsOrient(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsOrient(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsOrient(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsOrient(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.approach = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.approach.add(this._io.readF4le());
            }
            this.reserved = this._io.readBytes(12);
        }

        public void _fetchInstances() {
            for (int i = 0; i < this.approach.size(); i++) {
            }
        }
        private List<Float> approach;
        private byte[] reserved;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Tool approach.
         */
        public List<Float> approach() { return approach; }

        /**
         * reserved: float(3); kept verbatim (N7).
         */
        public byte[] reserved() { return reserved; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * ORIENT5B: Orientation change, 5 axis. Versions 1.x, 2.x, 3.0, 4.0; 24 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsOrient5b extends KaitaiStruct {
        public static ArgsOrient5b fromFile(String fileName) throws IOException {
            return new ArgsOrient5b(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsOrient5b(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsOrient5b(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsOrient5b(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.startApproach = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.startApproach.add(this._io.readF4le());
            }
            this.endApproach = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.endApproach.add(this._io.readF4le());
            }
        }

        public void _fetchInstances() {
            for (int i = 0; i < this.startApproach.size(); i++) {
            }
            for (int i = 0; i < this.endApproach.size(); i++) {
            }
        }
        private List<Float> startApproach;
        private List<Float> endApproach;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Start approach.
         */
        public List<Float> startApproach() { return startApproach; }

        /**
         * End approach.
         */
        public List<Float> endApproach() { return endApproach; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * PHASE: Cutting phase. Versions 2.x, 3.0, 4.0; 16 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsPhase extends KaitaiStruct {
        public static ArgsPhase fromFile(String fileName) throws IOException {
            return new ArgsPhase(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsPhase(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsPhase(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsPhase(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.name = new String(KaitaiStream.bytesStripRight(this._io.readBytes(16), (byte) 0), StandardCharsets.ISO_8859_1);
        }

        public void _fetchInstances() {
        }
        private String name;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Phase name.
         */
        public String name() { return name; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * POINT: Starting goal point. Versions 1.x, 2.x, 3.0, 4.0; 12 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsPoint extends KaitaiStruct {
        public static ArgsPoint fromFile(String fileName) throws IOException {
            return new ArgsPoint(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsPoint(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsPoint(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsPoint(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.point = new ArrayList<Float>();
            for (int i = 0; i < 3; i++) {
                this.point.add(this._io.readF4le());
            }
        }

        public void _fetchInstances() {
            for (int i = 0; i < this.point.size(); i++) {
            }
        }
        private List<Float> point;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Goal point. [mm]
         */
        public List<Float> point() { return point; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * SPEED: Speed. Versions 1.x, 2.x, 3.0, 4.0; 4 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsSpeed extends KaitaiStruct {
        public static ArgsSpeed fromFile(String fileName) throws IOException {
            return new ArgsSpeed(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsSpeed(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsSpeed(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsSpeed(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.speed = this._io.readF4le();
        }

        public void _fetchInstances() {
        }
        private float speed;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Speed. [m/s]
         */
        public float speed() { return speed; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * STARTSHAPE: Start of a shape. Versions 1.x, 2.x, 3.0, 4.0; 6 bytes.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsStartshape extends KaitaiStruct {
        public static ArgsStartshape fromFile(String fileName) throws IOException {
            return new ArgsStartshape(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsStartshape(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsStartshape(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsStartshape(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.name = new String(KaitaiStream.bytesStripRight(this._io.readBytes(5), (byte) 0), StandardCharsets.ISO_8859_1);
            this.moves = this._io.readU1();
        }

        public void _fetchInstances() {
        }
        private String name;
        private int moves;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Shape name.
         */
        public String name() { return name; }

        /**
         * Number of (move) commands in the shape. [count]
         */
        public int moves() { return moves; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * VERSION: Version numbers. Versions 2.x, 3.0, 4.0; 32 bytes. Default layout (N8); the 16 listed bytes and 16 reserved bytes make up the declared 32.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsVersion extends KaitaiStruct {
        public static ArgsVersion fromFile(String fileName) throws IOException {
            return new ArgsVersion(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsVersion(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsVersion(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsVersion(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.cutfile = new String(KaitaiStream.bytesStripRight(this._io.readBytes(8), (byte) 0), StandardCharsets.ISO_8859_1);
            this.format = new String(KaitaiStream.bytesStripRight(this._io.readBytes(8), (byte) 0), StandardCharsets.ISO_8859_1);
            this.reserved = this._io.readBytes(16);
        }

        public void _fetchInstances() {
        }
        private String cutfile;
        private String format;
        private byte[] reserved;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Cutfile version.
         */
        public String cutfile() { return cutfile; }

        /**
         * Format version.
         */
        public String format() { return format; }

        /**
         * Not listed by 5.1; reserved to reach the declared 32 bytes (N8).
         */
        public byte[] reserved() { return reserved; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * VERSION: Version numbers. Versions 2.x, 3.0, 4.0; 16 bytes. Accepted under profile implib. The 16 listed bytes only, as implib writes them (N8); accepted under the implib profile.
     * @see "300071 rev 03, 5.1"
     */
    public static class ArgsVersionImplib extends KaitaiStruct {
        public static ArgsVersionImplib fromFile(String fileName) throws IOException {
            return new ArgsVersionImplib(new ByteBufferKaitaiStream(fileName));
        }

        public ArgsVersionImplib(KaitaiStream _io) {
            this(_io, null, null);
        }

        public ArgsVersionImplib(KaitaiStream _io, Cbf.Record _parent) {
            this(_io, _parent, null);
        }

        public ArgsVersionImplib(KaitaiStream _io, Cbf.Record _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.cutfile = new String(KaitaiStream.bytesStripRight(this._io.readBytes(8), (byte) 0), StandardCharsets.ISO_8859_1);
            this.format = new String(KaitaiStream.bytesStripRight(this._io.readBytes(8), (byte) 0), StandardCharsets.ISO_8859_1);
        }

        public void _fetchInstances() {
        }
        private String cutfile;
        private String format;
        private Cbf _root;
        private Cbf.Record _parent;

        /**
         * Cutfile version.
         */
        public String cutfile() { return cutfile; }

        /**
         * Format version.
         */
        public String format() { return format; }
        public Cbf _root() { return _root; }
        public Cbf.Record _parent() { return _parent; }
    }

    /**
     * File header (4.2); after the version field its layout depends on the version.
     */
    public static class Header extends KaitaiStruct {
        public static Header fromFile(String fileName) throws IOException {
            return new Header(new ByteBufferKaitaiStream(fileName));
        }

        public Header(KaitaiStream _io) {
            this(_io, null, null);
        }

        public Header(KaitaiStream _io, Cbf _parent) {
            this(_io, _parent, null);
        }

        public Header(KaitaiStream _io, Cbf _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.startPattern = this._io.readU4le();
            if (!(this.startPattern == 1403107218)) {
                throw new KaitaiStream.ValidationNotEqualError(1403107218, this.startPattern, this._io, "/types/header/seq/0");
            }
            this.fileChecksum = this._io.readU4le();
            this.headerChecksum = this._io.readU2le();
            this.reservedEcc = this._io.readBytes(6);
            this.versionMajor = this._io.readU1();
            this.versionMinor = this._io.readU1();
            switch (versionIndex()) {
            case 1: {
                this.layout = new HeaderV1(this._io, this, _root);
                break;
            }
            case 2: {
                this.layout = new HeaderV2(this._io, this, _root);
                break;
            }
            case 3: {
                this.layout = new HeaderV2(this._io, this, _root);
                break;
            }
            case 4: {
                this.layout = new HeaderV2(this._io, this, _root);
                break;
            }
            }
        }

        public void _fetchInstances() {
            switch (versionIndex()) {
            case 1: {
                ((HeaderV1) (this.layout))._fetchInstances();
                break;
            }
            case 2: {
                ((HeaderV2) (this.layout))._fetchInstances();
                break;
            }
            case 3: {
                ((HeaderV2) (this.layout))._fetchInstances();
                break;
            }
            case 4: {
                ((HeaderV2) (this.layout))._fetchInstances();
                break;
            }
            }
        }
        private Byte versionIndex;

        /**
         * 1-based index of the spec's version entry (1 = 1.x, 2 = 2.x, 3 = 3.0, 4 = 4.0); unknown versions read as 4.0.
         */
        public Byte versionIndex() {
            if (this.versionIndex != null)
                return this.versionIndex;
            this.versionIndex = ((Number) ((versionMajor() == 1 ? 1 : (versionMajor() == 2 ? 2 : ( ((versionMajor() == 3) && (versionMinor() == 0))  ? 3 : ( ((versionMajor() == 4) && (versionMinor() == 0))  ? 4 : 4)))))).byteValue();
            return this.versionIndex;
        }
        private long startPattern;
        private long fileChecksum;
        private int headerChecksum;
        private byte[] reservedEcc;
        private int versionMajor;
        private int versionMinor;
        private KaitaiStruct layout;
        private Cbf _root;
        private Cbf _parent;

        /**
         * Special pattern indicating cutting file (N5, bytes 92 B7 A1 53).
         * @see "300071 rev 03, 4.2"
         */
        public long startPattern() { return startPattern; }

        /**
         * Checksum for entire file (starting at byte 8).
         * @see "300071 rev 03, 4.2"
         */
        public long fileChecksum() { return fileChecksum; }

        /**
         * Checksum for rest of header.
         * @see "300071 rev 03, 4.2"
         */
        public int headerChecksum() { return headerChecksum; }

        /**
         * Reserved for future checksum usage (Error Correcting Codes); kept verbatim (N7).
         * @see "300071 rev 03, 4.2"
         */
        public byte[] reservedEcc() { return reservedEcc; }

        /**
         * Version number for cutfile format, major (N3).
         * @see "300071 rev 03, 4.2"
         */
        public int versionMajor() { return versionMajor; }

        /**
         * Version number for cutfile format, minor (N3).
         * @see "300071 rev 03, 4.2"
         */
        public int versionMinor() { return versionMinor; }

        /**
         * The rest of the header, laid out as the version says (7.1).
         */
        public KaitaiStruct layout() { return layout; }
        public Cbf _root() { return _root; }
        public Cbf _parent() { return _parent; }
    }

    /**
     * File header before 7.2.2.1 shortened the implant descriptor.
     */
    public static class HeaderV1 extends KaitaiStruct {
        public static HeaderV1 fromFile(String fileName) throws IOException {
            return new HeaderV1(new ByteBufferKaitaiStream(fileName));
        }

        public HeaderV1(KaitaiStream _io) {
            this(_io, null, null);
        }

        public HeaderV1(KaitaiStream _io, Cbf.Header _parent) {
            this(_io, _parent, null);
        }

        public HeaderV1(KaitaiStream _io, Cbf.Header _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.implantDescriptor = new String(KaitaiStream.bytesStripRight(this._io.readBytes(80), (byte) 0), StandardCharsets.ISO_8859_1);
            this.reserved98 = this._io.readBytes(24);
            this.commandCount = this._io.readU2le();
            this.endPattern = this._io.readU4le();
            if (!(this.endPattern == 2891860077L)) {
                throw new KaitaiStream.ValidationNotEqualError(2891860077L, this.endPattern, this._io, "/types/header_v1/seq/3");
            }
        }

        public void _fetchInstances() {
        }
        private String implantDescriptor;
        private byte[] reserved98;
        private int commandCount;
        private long endPattern;
        private Cbf _root;
        private Cbf.Header _parent;

        /**
         * Implant descriptor of 80 bytes (1.x).
         * @see "300071 rev 03, 7.2.2.1"
         */
        public String implantDescriptor() { return implantDescriptor; }

        /**
         * Reserved field at offset 98 (1.x); renamed Configuration Descriptor in 2.0.
         * @see "300071 rev 03, 7.2.2.1"
         */
        public byte[] reserved98() { return reserved98; }

        /**
         * Number of commands in cutting data section.
         * @see "300071 rev 03, 4.2"
         */
        public int commandCount() { return commandCount; }

        /**
         * Complement of the start pattern (N5).
         * @see "300071 rev 03, 4.2"
         */
        public long endPattern() { return endPattern; }
        public Cbf _root() { return _root; }
        public Cbf.Header _parent() { return _parent; }
    }

    /**
     * File header as 4.2 gives it, with the configuration descriptor of 7.2.2.1.
     */
    public static class HeaderV2 extends KaitaiStruct {
        public static HeaderV2 fromFile(String fileName) throws IOException {
            return new HeaderV2(new ByteBufferKaitaiStream(fileName));
        }

        public HeaderV2(KaitaiStream _io) {
            this(_io, null, null);
        }

        public HeaderV2(KaitaiStream _io, Cbf.Header _parent) {
            this(_io, _parent, null);
        }

        public HeaderV2(KaitaiStream _io, Cbf.Header _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.implantDescriptor = new String(KaitaiStream.bytesStripRight(this._io.readBytes(70), (byte) 0), StandardCharsets.ISO_8859_1);
            this.configurationDescriptor = new String(KaitaiStream.bytesStripRight(this._io.readBytes(34), (byte) 0), StandardCharsets.ISO_8859_1);
            this.commandCount = this._io.readU2le();
            this.endPattern = this._io.readU4le();
            if (!(this.endPattern == 2891860077L)) {
                throw new KaitaiStream.ValidationNotEqualError(2891860077L, this.endPattern, this._io, "/types/header_v2/seq/3");
            }
        }

        public void _fetchInstances() {
        }
        private String implantDescriptor;
        private String configurationDescriptor;
        private int commandCount;
        private long endPattern;
        private Cbf _root;
        private Cbf.Header _parent;

        /**
         * Implant descriptor (part number, manufacturer, type, size); the part number must be the first item (6.1.1).
         * @see "300071 rev 03, 4.2"
         */
        public String implantDescriptor() { return implantDescriptor; }

        /**
         * Configuration descriptor; the field 7.2.2.1 made of the 1.x reserved bytes.
         * @see "300071 rev 03, 4.2"
         */
        public String configurationDescriptor() { return configurationDescriptor; }

        /**
         * Number of commands in cutting data section (6.2.2).
         * @see "300071 rev 03, 4.2"
         */
        public int commandCount() { return commandCount; }

        /**
         * Special pattern indicating end of header, the complement of the start pattern (N5, bytes 6D 48 5E AC).
         * @see "300071 rev 03, 4.2"
         */
        public long endPattern() { return endPattern; }
        public Cbf _root() { return _root; }
        public Cbf.Header _parent() { return _parent; }
    }

    /**
     * A cutting-data record; the records follow the header back to back. Not expressible here: 6.4.1 (sequence), 6.4.4 (arg_checksum).
     */
    public static class Record extends KaitaiStruct {
        public static Record fromFile(String fileName) throws IOException {
            return new Record(new ByteBufferKaitaiStream(fileName));
        }

        public Record(KaitaiStream _io) {
            this(_io, null, null);
        }

        public Record(KaitaiStream _io, Cbf _parent) {
            this(_io, _parent, null);
        }

        public Record(KaitaiStream _io, Cbf _parent, Cbf _root) {
            super(_io);
            this._parent = _parent;
            this._root = _root;
            _read();
        }
        private void _read() {
            this.sequence = this._io.readU2le();
            this.code = this._io.readU1();
            {
                int _it = this.code;
                if (!( ((!( ((_root().header().versionIndex() == 4) && ( ((_it == 148) || (_it == 149) || (_it == 122) || (_it == 123) || (_it == 226) || (_it == 227)) )) )) && (!( ((_root().header().versionIndex() == 1) && ( ((_it == 33) || (_it == 43) || (_it == 78) || (_it == 226) || (_it == 252) || (_it == 85)) )) ))) )) {
                    throw new KaitaiStream.ValidationExprError(this.code, this._io, "/types/record/seq/1");
                }
            }
            this.codeCopy = this._io.readU1();
            {
                int _it = this.codeCopy;
                if (!(_it == code())) {
                    throw new KaitaiStream.ValidationExprError(this.codeCopy, this._io, "/types/record/seq/2");
                }
            }
            this.argSize = this._io.readU1();
            {
                int _it = this.argSize;
                if (!((code() == 60 ?  (( ((_root().header().versionIndex() == 1) && (_it == 16)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 32)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 32)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 32)) ))  : (code() == 163 ?  (( ((_root().header().versionIndex() == 1) && (_it == 32)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 32)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 32)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 32)) ))  : (code() == 88 ?  (( ((_root().header().versionIndex() == 1) && (_it == 24)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 24)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 24)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 24)) ))  : (code() == 89 ?  (( ((_root().header().versionIndex() == 1) && (_it == 24)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 24)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 24)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 24)) ))  : (code() == 33 ?  (( ((_root().header().versionIndex() == 1) && (_it == 16)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 16)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 16)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 16)) ))  : (code() == 34 ?  (( ((_root().header().versionIndex() == 1) && (_it == 16)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 16)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 16)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 16)) ))  : (code() == 201 ?  (( ((_root().header().versionIndex() == 1) && (_it == 6)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 6)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 6)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 6)) ))  : (code() == 101 ?  (( ((_root().header().versionIndex() == 1) && (_it == 6)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 6)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 6)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 6)) ))  : (code() == 43 ?  (( ((_root().header().versionIndex() == 1) && (_it == 0)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 0)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 0)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 0)) ))  : (code() == 78 ?  (( ((_root().header().versionIndex() == 1) && (_it == 0)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 0)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 0)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 0)) ))  : (code() == 51 ?  (( ((_root().header().versionIndex() == 1) && (_it == 12)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 12)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 12)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 12)) ))  : (code() == 182 ?  (( ((_root().header().versionIndex() == 1) && (_it == 24)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 24)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 24)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 24)) ))  : (code() == 183 ?  (( ((_root().header().versionIndex() == 1) && (_it == 48)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 48)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 48)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 48)) ))  : (code() == 148 ?  (( ((_root().header().versionIndex() == 1) && (_it == 36)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 36)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 36)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 36)) ))  : (code() == 149 ?  (( ((_root().header().versionIndex() == 1) && (_it == 60)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 60)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 60)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 60)) ))  : (code() == 122 ?  (( ((_root().header().versionIndex() == 1) && (_it == 40)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 40)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 40)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 40)) ))  : (code() == 123 ?  (( ((_root().header().versionIndex() == 1) && (_it == 64)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 64)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 64)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 64)) ))  : (code() == 226 ?  (( ((_root().header().versionIndex() == 1) && (_it == 44)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 44)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 44)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 44)) ))  : (code() == 227 ?  (( ((_root().header().versionIndex() == 1) && (_it == 68)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 68)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 68)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 68)) ))  : (code() == 139 ?  (( ((_root().header().versionIndex() == 1) && (_it == 4)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 4)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 4)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 4)) ))  : (code() == 71 ?  (( ((_root().header().versionIndex() == 1) && (_it == 8)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 8)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 8)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 8)) ))  : (code() == 187 ?  (( ((_root().header().versionIndex() == 1) && (_it == 0)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 0)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 0)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 0)) ))  : (code() == 102 ?  (( ((_root().header().versionIndex() == 1) && (_it == 0)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 0)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 0)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 0)) ))  : (code() == 17 ?  (( ((_root().header().versionIndex() == 1) && (_it == 32)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 32)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 32)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 32)) ))  : (code() == 252 ?  (( ((_root().header().versionIndex() == 1) && (_it == 16)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 16)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 16)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 16)) ))  : (code() == 85 ?  (( ((_root().header().versionIndex() == 1) && ( ((_it == 16) || (_it == 32)) )) ) || ( ((_root().header().versionIndex() == 2) && ( ((_it == 16) || (_it == 32)) )) ) || ( ((_root().header().versionIndex() == 3) && ( ((_it == 16) || (_it == 32)) )) ) || ( ((_root().header().versionIndex() == 4) && ( ((_it == 16) || (_it == 32)) )) ))  : (code() == 90 ?  (( ((_root().header().versionIndex() == 1) && (_it == 40)) ) || ( ((_root().header().versionIndex() == 2) && (_it == 40)) ) || ( ((_root().header().versionIndex() == 3) && (_it == 40)) ) || ( ((_root().header().versionIndex() == 4) && (_it == 40)) ))  : true))))))))))))))))))))))))))))) {
                    throw new KaitaiStream.ValidationExprError(this.argSize, this._io, "/types/record/seq/3");
                }
            }
            this.reserved = this._io.readU1();
            this.argChecksum = this._io.readU2le();
            switch ((((Number) (code())).intValue() * 65536 + ((Number) (argSize())).intValue() * 256) + ((Number) (_root().header().versionIndex())).intValue()) {
            case 10690561: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsCutterV1(_io_args, this, _root);
                break;
            }
            case 10690562: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsCutter(_io_args, this, _root);
                break;
            }
            case 10690563: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsCutter(_io_args, this, _root);
                break;
            }
            case 10690564: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsCutter(_io_args, this, _root);
                break;
            }
            case 1122305: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsGuide(_io_args, this, _root);
                break;
            }
            case 1122306: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsGuide(_io_args, this, _root);
                break;
            }
            case 1122307: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsGuide(_io_args, this, _root);
                break;
            }
            case 1122308: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsGuide(_io_args, this, _root);
                break;
            }
            case 11933697: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsLine(_io_args, this, _root);
                break;
            }
            case 11933698: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsLine(_io_args, this, _root);
                break;
            }
            case 11933699: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsLine(_io_args, this, _root);
                break;
            }
            case 11933700: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsLine(_io_args, this, _root);
                break;
            }
            case 12005377: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsLine5b(_io_args, this, _root);
                break;
            }
            case 12005378: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsLine5b(_io_args, this, _root);
                break;
            }
            case 12005379: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsLine5b(_io_args, this, _root);
                break;
            }
            case 12005380: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsLine5b(_io_args, this, _root);
                break;
            }
            case 12255233: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsCutterOn(_io_args, this, _root);
                break;
            }
            case 12255234: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsCutterOn(_io_args, this, _root);
                break;
            }
            case 12255235: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsCutterOn(_io_args, this, _root);
                break;
            }
            case 12255236: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsCutterOn(_io_args, this, _root);
                break;
            }
            case 13174273: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsStartshape(_io_args, this, _root);
                break;
            }
            case 13174274: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsStartshape(_io_args, this, _root);
                break;
            }
            case 13174275: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsStartshape(_io_args, this, _root);
                break;
            }
            case 13174276: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsStartshape(_io_args, this, _root);
                break;
            }
            case 14822401: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsHelix(_io_args, this, _root);
                break;
            }
            case 14822402: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsHelix(_io_args, this, _root);
                break;
            }
            case 14822403: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsHelix(_io_args, this, _root);
                break;
            }
            case 14822404: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsHelix(_io_args, this, _root);
                break;
            }
            case 14894081: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsHelix5b(_io_args, this, _root);
                break;
            }
            case 14894082: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsHelix5b(_io_args, this, _root);
                break;
            }
            case 14894083: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsHelix5b(_io_args, this, _root);
                break;
            }
            case 14894084: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsHelix5b(_io_args, this, _root);
                break;
            }
            case 16519169: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsFcparms(_io_args, this, _root);
                break;
            }
            case 16519170: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsFcparms(_io_args, this, _root);
                break;
            }
            case 16519171: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsFcparms(_io_args, this, _root);
                break;
            }
            case 16519172: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsFcparms(_io_args, this, _root);
                break;
            }
            case 2166785: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsPhase(_io_args, this, _root);
                break;
            }
            case 2166786: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsPhase(_io_args, this, _root);
                break;
            }
            case 2166787: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsPhase(_io_args, this, _root);
                break;
            }
            case 2166788: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsPhase(_io_args, this, _root);
                break;
            }
            case 2232321: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsEnableSkip(_io_args, this, _root);
                break;
            }
            case 2232322: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsEnableSkip(_io_args, this, _root);
                break;
            }
            case 2232323: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsEnableSkip(_io_args, this, _root);
                break;
            }
            case 2232324: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsEnableSkip(_io_args, this, _root);
                break;
            }
            case 2818049: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsDecelOff(_io_args, this, _root);
                break;
            }
            case 2818050: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsDecelOff(_io_args, this, _root);
                break;
            }
            case 2818051: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsDecelOff(_io_args, this, _root);
                break;
            }
            case 2818052: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsDecelOff(_io_args, this, _root);
                break;
            }
            case 3345409: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsPoint(_io_args, this, _root);
                break;
            }
            case 3345410: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsPoint(_io_args, this, _root);
                break;
            }
            case 3345411: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsPoint(_io_args, this, _root);
                break;
            }
            case 3345412: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsPoint(_io_args, this, _root);
                break;
            }
            case 3936257: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsCheckpointV1(_io_args, this, _root);
                break;
            }
            case 3940354: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsCheckpoint(_io_args, this, _root);
                break;
            }
            case 3940355: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsCheckpoint(_io_args, this, _root);
                break;
            }
            case 3940356: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsCheckpoint(_io_args, this, _root);
                break;
            }
            case 4655105: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsAccel(_io_args, this, _root);
                break;
            }
            case 4655106: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsAccel(_io_args, this, _root);
                break;
            }
            case 4655107: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsAccel(_io_args, this, _root);
                break;
            }
            case 4655108: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsAccel(_io_args, this, _root);
                break;
            }
            case 5111809: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsDecelOn(_io_args, this, _root);
                break;
            }
            case 5111810: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsDecelOn(_io_args, this, _root);
                break;
            }
            case 5111811: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsDecelOn(_io_args, this, _root);
                break;
            }
            case 5111812: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsDecelOn(_io_args, this, _root);
                break;
            }
            case 5574657: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsVersionImplib(_io_args, this, _root);
                break;
            }
            case 5574658: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsVersionImplib(_io_args, this, _root);
                break;
            }
            case 5574659: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsVersionImplib(_io_args, this, _root);
                break;
            }
            case 5574660: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsVersionImplib(_io_args, this, _root);
                break;
            }
            case 5578753: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsVersion(_io_args, this, _root);
                break;
            }
            case 5578754: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsVersion(_io_args, this, _root);
                break;
            }
            case 5578755: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsVersion(_io_args, this, _root);
                break;
            }
            case 5578756: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsVersion(_io_args, this, _root);
                break;
            }
            case 5773313: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsOrient(_io_args, this, _root);
                break;
            }
            case 5773314: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsOrient(_io_args, this, _root);
                break;
            }
            case 5773315: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsOrient(_io_args, this, _root);
                break;
            }
            case 5773316: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsOrient(_io_args, this, _root);
                break;
            }
            case 5838849: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsOrient5b(_io_args, this, _root);
                break;
            }
            case 5838850: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsOrient5b(_io_args, this, _root);
                break;
            }
            case 5838851: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsOrient5b(_io_args, this, _root);
                break;
            }
            case 5838852: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsOrient5b(_io_args, this, _root);
                break;
            }
            case 5908481: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsComment(_io_args, this, _root);
                break;
            }
            case 5908482: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsComment(_io_args, this, _root);
                break;
            }
            case 5908483: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsComment(_io_args, this, _root);
                break;
            }
            case 5908484: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsComment(_io_args, this, _root);
                break;
            }
            case 6620673: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsEndshape(_io_args, this, _root);
                break;
            }
            case 6620674: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsEndshape(_io_args, this, _root);
                break;
            }
            case 6620675: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsEndshape(_io_args, this, _root);
                break;
            }
            case 6620676: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsEndshape(_io_args, this, _root);
                break;
            }
            case 6684673: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsCutterOff(_io_args, this, _root);
                break;
            }
            case 6684674: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsCutterOff(_io_args, this, _root);
                break;
            }
            case 6684675: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsCutterOff(_io_args, this, _root);
                break;
            }
            case 6684676: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsCutterOff(_io_args, this, _root);
                break;
            }
            case 8005633: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsCircle(_io_args, this, _root);
                break;
            }
            case 8005634: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsCircle(_io_args, this, _root);
                break;
            }
            case 8005635: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsCircle(_io_args, this, _root);
                break;
            }
            case 8005636: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsCircle(_io_args, this, _root);
                break;
            }
            case 8077313: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsCircle5b(_io_args, this, _root);
                break;
            }
            case 8077314: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsCircle5b(_io_args, this, _root);
                break;
            }
            case 8077315: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsCircle5b(_io_args, this, _root);
                break;
            }
            case 8077316: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsCircle5b(_io_args, this, _root);
                break;
            }
            case 9110529: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsSpeed(_io_args, this, _root);
                break;
            }
            case 9110530: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsSpeed(_io_args, this, _root);
                break;
            }
            case 9110531: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsSpeed(_io_args, this, _root);
                break;
            }
            case 9110532: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsSpeed(_io_args, this, _root);
                break;
            }
            case 9708545: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsArc(_io_args, this, _root);
                break;
            }
            case 9708546: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsArc(_io_args, this, _root);
                break;
            }
            case 9708547: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsArc(_io_args, this, _root);
                break;
            }
            case 9708548: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsArc(_io_args, this, _root);
                break;
            }
            case 9780225: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsArc5b(_io_args, this, _root);
                break;
            }
            case 9780226: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsArc5b(_io_args, this, _root);
                break;
            }
            case 9780227: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsArc5b(_io_args, this, _root);
                break;
            }
            case 9780228: {
                KaitaiStream _io_args = this._io.substream(argSize());
                this.args = new ArgsArc5b(_io_args, this, _root);
                break;
            }
            default: {
                this.args = this._io.readBytes(argSize());
                break;
            }
            }
        }

        public void _fetchInstances() {
            switch ((((Number) (code())).intValue() * 65536 + ((Number) (argSize())).intValue() * 256) + ((Number) (_root().header().versionIndex())).intValue()) {
            case 10690561: {
                ((ArgsCutterV1) (this.args))._fetchInstances();
                break;
            }
            case 10690562: {
                ((ArgsCutter) (this.args))._fetchInstances();
                break;
            }
            case 10690563: {
                ((ArgsCutter) (this.args))._fetchInstances();
                break;
            }
            case 10690564: {
                ((ArgsCutter) (this.args))._fetchInstances();
                break;
            }
            case 1122305: {
                ((ArgsGuide) (this.args))._fetchInstances();
                break;
            }
            case 1122306: {
                ((ArgsGuide) (this.args))._fetchInstances();
                break;
            }
            case 1122307: {
                ((ArgsGuide) (this.args))._fetchInstances();
                break;
            }
            case 1122308: {
                ((ArgsGuide) (this.args))._fetchInstances();
                break;
            }
            case 11933697: {
                ((ArgsLine) (this.args))._fetchInstances();
                break;
            }
            case 11933698: {
                ((ArgsLine) (this.args))._fetchInstances();
                break;
            }
            case 11933699: {
                ((ArgsLine) (this.args))._fetchInstances();
                break;
            }
            case 11933700: {
                ((ArgsLine) (this.args))._fetchInstances();
                break;
            }
            case 12005377: {
                ((ArgsLine5b) (this.args))._fetchInstances();
                break;
            }
            case 12005378: {
                ((ArgsLine5b) (this.args))._fetchInstances();
                break;
            }
            case 12005379: {
                ((ArgsLine5b) (this.args))._fetchInstances();
                break;
            }
            case 12005380: {
                ((ArgsLine5b) (this.args))._fetchInstances();
                break;
            }
            case 12255233: {
                ((ArgsCutterOn) (this.args))._fetchInstances();
                break;
            }
            case 12255234: {
                ((ArgsCutterOn) (this.args))._fetchInstances();
                break;
            }
            case 12255235: {
                ((ArgsCutterOn) (this.args))._fetchInstances();
                break;
            }
            case 12255236: {
                ((ArgsCutterOn) (this.args))._fetchInstances();
                break;
            }
            case 13174273: {
                ((ArgsStartshape) (this.args))._fetchInstances();
                break;
            }
            case 13174274: {
                ((ArgsStartshape) (this.args))._fetchInstances();
                break;
            }
            case 13174275: {
                ((ArgsStartshape) (this.args))._fetchInstances();
                break;
            }
            case 13174276: {
                ((ArgsStartshape) (this.args))._fetchInstances();
                break;
            }
            case 14822401: {
                ((ArgsHelix) (this.args))._fetchInstances();
                break;
            }
            case 14822402: {
                ((ArgsHelix) (this.args))._fetchInstances();
                break;
            }
            case 14822403: {
                ((ArgsHelix) (this.args))._fetchInstances();
                break;
            }
            case 14822404: {
                ((ArgsHelix) (this.args))._fetchInstances();
                break;
            }
            case 14894081: {
                ((ArgsHelix5b) (this.args))._fetchInstances();
                break;
            }
            case 14894082: {
                ((ArgsHelix5b) (this.args))._fetchInstances();
                break;
            }
            case 14894083: {
                ((ArgsHelix5b) (this.args))._fetchInstances();
                break;
            }
            case 14894084: {
                ((ArgsHelix5b) (this.args))._fetchInstances();
                break;
            }
            case 16519169: {
                ((ArgsFcparms) (this.args))._fetchInstances();
                break;
            }
            case 16519170: {
                ((ArgsFcparms) (this.args))._fetchInstances();
                break;
            }
            case 16519171: {
                ((ArgsFcparms) (this.args))._fetchInstances();
                break;
            }
            case 16519172: {
                ((ArgsFcparms) (this.args))._fetchInstances();
                break;
            }
            case 2166785: {
                ((ArgsPhase) (this.args))._fetchInstances();
                break;
            }
            case 2166786: {
                ((ArgsPhase) (this.args))._fetchInstances();
                break;
            }
            case 2166787: {
                ((ArgsPhase) (this.args))._fetchInstances();
                break;
            }
            case 2166788: {
                ((ArgsPhase) (this.args))._fetchInstances();
                break;
            }
            case 2232321: {
                ((ArgsEnableSkip) (this.args))._fetchInstances();
                break;
            }
            case 2232322: {
                ((ArgsEnableSkip) (this.args))._fetchInstances();
                break;
            }
            case 2232323: {
                ((ArgsEnableSkip) (this.args))._fetchInstances();
                break;
            }
            case 2232324: {
                ((ArgsEnableSkip) (this.args))._fetchInstances();
                break;
            }
            case 2818049: {
                ((ArgsDecelOff) (this.args))._fetchInstances();
                break;
            }
            case 2818050: {
                ((ArgsDecelOff) (this.args))._fetchInstances();
                break;
            }
            case 2818051: {
                ((ArgsDecelOff) (this.args))._fetchInstances();
                break;
            }
            case 2818052: {
                ((ArgsDecelOff) (this.args))._fetchInstances();
                break;
            }
            case 3345409: {
                ((ArgsPoint) (this.args))._fetchInstances();
                break;
            }
            case 3345410: {
                ((ArgsPoint) (this.args))._fetchInstances();
                break;
            }
            case 3345411: {
                ((ArgsPoint) (this.args))._fetchInstances();
                break;
            }
            case 3345412: {
                ((ArgsPoint) (this.args))._fetchInstances();
                break;
            }
            case 3936257: {
                ((ArgsCheckpointV1) (this.args))._fetchInstances();
                break;
            }
            case 3940354: {
                ((ArgsCheckpoint) (this.args))._fetchInstances();
                break;
            }
            case 3940355: {
                ((ArgsCheckpoint) (this.args))._fetchInstances();
                break;
            }
            case 3940356: {
                ((ArgsCheckpoint) (this.args))._fetchInstances();
                break;
            }
            case 4655105: {
                ((ArgsAccel) (this.args))._fetchInstances();
                break;
            }
            case 4655106: {
                ((ArgsAccel) (this.args))._fetchInstances();
                break;
            }
            case 4655107: {
                ((ArgsAccel) (this.args))._fetchInstances();
                break;
            }
            case 4655108: {
                ((ArgsAccel) (this.args))._fetchInstances();
                break;
            }
            case 5111809: {
                ((ArgsDecelOn) (this.args))._fetchInstances();
                break;
            }
            case 5111810: {
                ((ArgsDecelOn) (this.args))._fetchInstances();
                break;
            }
            case 5111811: {
                ((ArgsDecelOn) (this.args))._fetchInstances();
                break;
            }
            case 5111812: {
                ((ArgsDecelOn) (this.args))._fetchInstances();
                break;
            }
            case 5574657: {
                ((ArgsVersionImplib) (this.args))._fetchInstances();
                break;
            }
            case 5574658: {
                ((ArgsVersionImplib) (this.args))._fetchInstances();
                break;
            }
            case 5574659: {
                ((ArgsVersionImplib) (this.args))._fetchInstances();
                break;
            }
            case 5574660: {
                ((ArgsVersionImplib) (this.args))._fetchInstances();
                break;
            }
            case 5578753: {
                ((ArgsVersion) (this.args))._fetchInstances();
                break;
            }
            case 5578754: {
                ((ArgsVersion) (this.args))._fetchInstances();
                break;
            }
            case 5578755: {
                ((ArgsVersion) (this.args))._fetchInstances();
                break;
            }
            case 5578756: {
                ((ArgsVersion) (this.args))._fetchInstances();
                break;
            }
            case 5773313: {
                ((ArgsOrient) (this.args))._fetchInstances();
                break;
            }
            case 5773314: {
                ((ArgsOrient) (this.args))._fetchInstances();
                break;
            }
            case 5773315: {
                ((ArgsOrient) (this.args))._fetchInstances();
                break;
            }
            case 5773316: {
                ((ArgsOrient) (this.args))._fetchInstances();
                break;
            }
            case 5838849: {
                ((ArgsOrient5b) (this.args))._fetchInstances();
                break;
            }
            case 5838850: {
                ((ArgsOrient5b) (this.args))._fetchInstances();
                break;
            }
            case 5838851: {
                ((ArgsOrient5b) (this.args))._fetchInstances();
                break;
            }
            case 5838852: {
                ((ArgsOrient5b) (this.args))._fetchInstances();
                break;
            }
            case 5908481: {
                ((ArgsComment) (this.args))._fetchInstances();
                break;
            }
            case 5908482: {
                ((ArgsComment) (this.args))._fetchInstances();
                break;
            }
            case 5908483: {
                ((ArgsComment) (this.args))._fetchInstances();
                break;
            }
            case 5908484: {
                ((ArgsComment) (this.args))._fetchInstances();
                break;
            }
            case 6620673: {
                ((ArgsEndshape) (this.args))._fetchInstances();
                break;
            }
            case 6620674: {
                ((ArgsEndshape) (this.args))._fetchInstances();
                break;
            }
            case 6620675: {
                ((ArgsEndshape) (this.args))._fetchInstances();
                break;
            }
            case 6620676: {
                ((ArgsEndshape) (this.args))._fetchInstances();
                break;
            }
            case 6684673: {
                ((ArgsCutterOff) (this.args))._fetchInstances();
                break;
            }
            case 6684674: {
                ((ArgsCutterOff) (this.args))._fetchInstances();
                break;
            }
            case 6684675: {
                ((ArgsCutterOff) (this.args))._fetchInstances();
                break;
            }
            case 6684676: {
                ((ArgsCutterOff) (this.args))._fetchInstances();
                break;
            }
            case 8005633: {
                ((ArgsCircle) (this.args))._fetchInstances();
                break;
            }
            case 8005634: {
                ((ArgsCircle) (this.args))._fetchInstances();
                break;
            }
            case 8005635: {
                ((ArgsCircle) (this.args))._fetchInstances();
                break;
            }
            case 8005636: {
                ((ArgsCircle) (this.args))._fetchInstances();
                break;
            }
            case 8077313: {
                ((ArgsCircle5b) (this.args))._fetchInstances();
                break;
            }
            case 8077314: {
                ((ArgsCircle5b) (this.args))._fetchInstances();
                break;
            }
            case 8077315: {
                ((ArgsCircle5b) (this.args))._fetchInstances();
                break;
            }
            case 8077316: {
                ((ArgsCircle5b) (this.args))._fetchInstances();
                break;
            }
            case 9110529: {
                ((ArgsSpeed) (this.args))._fetchInstances();
                break;
            }
            case 9110530: {
                ((ArgsSpeed) (this.args))._fetchInstances();
                break;
            }
            case 9110531: {
                ((ArgsSpeed) (this.args))._fetchInstances();
                break;
            }
            case 9110532: {
                ((ArgsSpeed) (this.args))._fetchInstances();
                break;
            }
            case 9708545: {
                ((ArgsArc) (this.args))._fetchInstances();
                break;
            }
            case 9708546: {
                ((ArgsArc) (this.args))._fetchInstances();
                break;
            }
            case 9708547: {
                ((ArgsArc) (this.args))._fetchInstances();
                break;
            }
            case 9708548: {
                ((ArgsArc) (this.args))._fetchInstances();
                break;
            }
            case 9780225: {
                ((ArgsArc5b) (this.args))._fetchInstances();
                break;
            }
            case 9780226: {
                ((ArgsArc5b) (this.args))._fetchInstances();
                break;
            }
            case 9780227: {
                ((ArgsArc5b) (this.args))._fetchInstances();
                break;
            }
            case 9780228: {
                ((ArgsArc5b) (this.args))._fetchInstances();
                break;
            }
            default: {
                break;
            }
            }
        }
        private Command command;

        /**
         * The command code as the enum (5.2).
         */
        public Command command() {
            if (this.command != null)
                return this.command;
            this.command = Cbf.Command.byId(code());
            return this.command;
        }
        private int sequence;
        private int code;
        private int codeCopy;
        private int argSize;
        private int reserved;
        private int argChecksum;
        private Object args;
        private Cbf _root;
        private Cbf _parent;

        /**
         * Command sequence number (0 - 65535); 6.4.1.
         * @see "300071 rev 03, 4.3"
         */
        public int sequence() { return sequence; }

        /**
         * Command code (5.1). Version gating (7.2.3.1, 7.2.2.4) is a valid: expression.
         * @see "300071 rev 03, 4.3"
         */
        public int code() { return code; }

        /**
         * Backup copy of command code (redundancy); 6.4.2.
         * @see "300071 rev 03, 4.3"
         */
        public int codeCopy() { return codeCopy; }

        /**
         * Number of bytes used by command arguments (nb); 6.4.3.
         * @see "300071 rev 03, 4.3"
         */
        public int argSize() { return argSize; }

        /**
         * Reserved, should be 0 (N7).
         * @see "300071 rev 03, 4.3"
         */
        public int reserved() { return reserved; }

        /**
         * Checksum of command arguments; 6.4.4.
         * @see "300071 rev 03, 4.3"
         */
        public int argChecksum() { return argChecksum; }

        /**
         * The command's arguments: the layout of the file's version whose size matches (for a command the version lacks, any of its layouts); raw bytes for an unknown code.
         */
        public Object args() { return args; }
        public Cbf _root() { return _root; }
        public Cbf _parent() { return _parent; }
    }
    private Header header;
    private List<Record> records;
    private Cbf _root;
    private KaitaiStruct _parent;

    /**
     * File header (4.2).
     */
    public Header header() { return header; }

    /**
     * The command records, framed to the end of the file (4.3).
     */
    public List<Record> records() { return records; }
    public Cbf _root() { return _root; }
    public KaitaiStruct _parent() { return _parent; }
}
