// This is a generated file! Please edit source .ksy file and use kaitai-struct-compiler to rebuild

(function (root, factory) {
  if (typeof define === 'function' && define.amd) {
    define(['exports', 'kaitai-struct/KaitaiStream'], factory);
  } else if (typeof exports === 'object' && exports !== null && typeof exports.nodeType !== 'number') {
    factory(exports, require('kaitai-struct/KaitaiStream'));
  } else {
    factory(root.Cbf || (root.Cbf = {}), root.KaitaiStream);
  }
})(typeof self !== 'undefined' ? self : this, function (Cbf_, KaitaiStream) {
/**
 * The CBF file provides the toolpath information for cutting implant cavities with the ROBODOC System (1.1). It carries a 128-byte header and a sequence of variable-length command records. It can be created from, and converted to, an ASCII format, the CUT file (1.2). Generated from spec/cbf.yaml; do not edit. Kaitai checks here the magic numbers, the code copy, the argument size per command and version, and version gating. It cannot check: 4.2 (The file header is 128 bytes long.); 4.3 (The cutting data consists of variable length records.); 6.1.1 (The first word in the Implant Descriptor field in the file header should be the implant part number.); part_number_first (The implant descriptor begins with the implant part number (4.2; 6.1.1 compares it when one is given).); 6.1.2 (The length and radius of every cutter (specified by the CUTTER command) should agree, within 0.01 millimeters, with the values specified in the robot's cutter database.); 6.2.1 (The checksum of the entire file should match the value specified in the file header.); 6.2.2 (The number of commands in the file should match the value specified in the file header.); 6.3.1 (The checksum of the file header should match the specified value.); 6.4.1 (The sequence number should be one greater than the previous sequence number (first record should have sequence number 0).); 6.4.4 (The checksum of the command argument bytes should match the specified value.); 6.4.5 (The starting point of a motion command (e.g., LINE, ARC, CIRCLE, etc.) should match the ending point of the previous motion command.); version_supported (The processing software can read the version number and adjust the parsing logic appropriately.); unknown_command (An unknown command code is an error; its record is kept whole.); trailing_bytes (No byte follows the last record.); reserved_nonzero (The record's reserved byte should be 0.); string_tail (A string ends at its first NUL; the bytes after it are padding.); string_ascii (Strings are ASCII.); non_finite (Floats are finite.); speed_positive (SPEED is greater than 0.); accel_positive (Acceleration and deceleration are greater than 0.); cutter_positive (Cutter length and radius are greater than 0.); normal_nonzero (A circle or helix normal has non-zero length.); checkpoint_range (CHECKPOINT completion lies in 0..100.); checkpoint_falling (CHECKPOINT completion does not fall.); fcparms_order (FCPARMS speeds satisfy min <= nom <= max.); orientation_jump (A 5-axis command starts at the current tool orientation.); machine_limits (Positions lie in the machine's workspace; speeds, accelerations and cutter sizes lie in its ranges.); shape (STARTSHAPE name,n ... ENDSHAPE name,n enclose exactly n motion commands; shapes do not nest.).
 * @see Specification, Implant Support Software, TCAT, part number 300071, revision 03
 */

var Cbf = (function() {
  Cbf.Command = Object.freeze({
    GUIDE: 17,
    PHASE: 33,
    ENABLE_SKIP: 34,
    DECEL_OFF: 43,
    POINT: 51,
    CHECKPOINT: 60,
    ACCEL: 71,
    DECEL_ON: 78,
    VERSION: 85,
    ORIENT: 88,
    ORIENT5B: 89,
    COMMENT: 90,
    ENDSHAPE: 101,
    CUTTER_OFF: 102,
    CIRCLE: 122,
    CIRCLE5B: 123,
    SPEED: 139,
    ARC: 148,
    ARC5B: 149,
    CUTTER: 163,
    LINE: 182,
    LINE5B: 183,
    CUTTER_ON: 187,
    STARTSHAPE: 201,
    HELIX: 226,
    HELIX5B: 227,
    FCPARMS: 252,

    17: "GUIDE",
    33: "PHASE",
    34: "ENABLE_SKIP",
    43: "DECEL_OFF",
    51: "POINT",
    60: "CHECKPOINT",
    71: "ACCEL",
    78: "DECEL_ON",
    85: "VERSION",
    88: "ORIENT",
    89: "ORIENT5B",
    90: "COMMENT",
    101: "ENDSHAPE",
    102: "CUTTER_OFF",
    122: "CIRCLE",
    123: "CIRCLE5B",
    139: "SPEED",
    148: "ARC",
    149: "ARC5B",
    163: "CUTTER",
    182: "LINE",
    183: "LINE5B",
    187: "CUTTER_ON",
    201: "STARTSHAPE",
    226: "HELIX",
    227: "HELIX5B",
    252: "FCPARMS",
  });

  function Cbf(_io, _parent, _root) {
    this._io = _io;
    this._parent = _parent;
    this._root = _root || this;

    this._read();
  }
  Cbf.prototype._read = function() {
    this.header = new Header(this._io, this, this._root);
    this.records = [];
    var i = 0;
    while (!this._io.isEof()) {
      this.records.push(new Record(this._io, this, this._root));
      i++;
    }
  }

  /**
   * ACCEL: Acceleration and deceleration. Versions 1.x, 2.x, 3.0, 4.0; 8 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsAccel = Cbf.ArgsAccel = (function() {
    function ArgsAccel(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsAccel.prototype._read = function() {
      this.accel = this._io.readF4le();
      this.decel = this._io.readF4le();
    }

    /**
     * Acceleration. [m/s^2]
     */

    /**
     * Deceleration. [m/s^2]
     */

    return ArgsAccel;
  })();

  /**
   * ARC: Arc move. Versions 1.x, 2.x, 3.0; 36 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsArc = Cbf.ArgsArc = (function() {
    function ArgsArc(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsArc.prototype._read = function() {
      this.start = [];
      for (var i = 0; i < 3; i++) {
        this.start.push(this._io.readF4le());
      }
      this.middle = [];
      for (var i = 0; i < 3; i++) {
        this.middle.push(this._io.readF4le());
      }
      this.end = [];
      for (var i = 0; i < 3; i++) {
        this.end.push(this._io.readF4le());
      }
    }

    /**
     * Start point. [mm]
     */

    /**
     * A point in the middle of the arc. [mm]
     */

    /**
     * End point. [mm]
     */

    return ArgsArc;
  })();

  /**
   * ARC5B: Arc move, 5 axis. Versions 1.x, 2.x, 3.0; 60 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsArc5b = Cbf.ArgsArc5b = (function() {
    function ArgsArc5b(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsArc5b.prototype._read = function() {
      this.startPos = [];
      for (var i = 0; i < 3; i++) {
        this.startPos.push(this._io.readF4le());
      }
      this.midPos = [];
      for (var i = 0; i < 3; i++) {
        this.midPos.push(this._io.readF4le());
      }
      this.endPos = [];
      for (var i = 0; i < 3; i++) {
        this.endPos.push(this._io.readF4le());
      }
      this.startOrient = [];
      for (var i = 0; i < 3; i++) {
        this.startOrient.push(this._io.readF4le());
      }
      this.endOrient = [];
      for (var i = 0; i < 3; i++) {
        this.endOrient.push(this._io.readF4le());
      }
    }

    /**
     * Start position. [mm]
     */

    /**
     * Middle position. [mm]
     */

    /**
     * End position. [mm]
     */

    /**
     * Start orientation.
     */

    /**
     * End orientation.
     */

    return ArgsArc5b;
  })();

  /**
   * CHECKPOINT: Check-point. Versions 2.x, 3.0, 4.0; 32 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsCheckpoint = Cbf.ArgsCheckpoint = (function() {
    function ArgsCheckpoint(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsCheckpoint.prototype._read = function() {
      this.name = KaitaiStream.bytesToStr(KaitaiStream.bytesStripRight(this._io.readBytes(16), 0), "ISO-8859-1");
      this.recoveryPoint = [];
      for (var i = 0; i < 3; i++) {
        this.recoveryPoint.push(this._io.readF4le());
      }
      this.completion = this._io.readF4le();
    }

    /**
     * Check-point name.
     */

    /**
     * Recovery point. [mm]
     */

    /**
     * Completion percentage. [percent]
     */

    return ArgsCheckpoint;
  })();

  /**
   * CHECKPOINT: Check-point. Versions 1.x; 16 bytes.
   * @see 300071 rev 03, 7.2.2.2
   */

  var ArgsCheckpointV1 = Cbf.ArgsCheckpointV1 = (function() {
    function ArgsCheckpointV1(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsCheckpointV1.prototype._read = function() {
      this.name = KaitaiStream.bytesToStr(KaitaiStream.bytesStripRight(this._io.readBytes(16), 0), "ISO-8859-1");
    }

    /**
     * Check-point name.
     */

    return ArgsCheckpointV1;
  })();

  /**
   * CIRCLE: Circle. Versions 1.x, 2.x, 3.0; 40 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsCircle = Cbf.ArgsCircle = (function() {
    function ArgsCircle(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsCircle.prototype._read = function() {
      this.start = [];
      for (var i = 0; i < 3; i++) {
        this.start.push(this._io.readF4le());
      }
      this.center = [];
      for (var i = 0; i < 3; i++) {
        this.center.push(this._io.readF4le());
      }
      this.normal = [];
      for (var i = 0; i < 3; i++) {
        this.normal.push(this._io.readF4le());
      }
      this.ndegrees = this._io.readF4le();
    }

    /**
     * Start point. [mm]
     */

    /**
     * Centre point. [mm]
     */

    /**
     * Axis direction (need not be unit length); rotation by the right-hand rule.
     */

    /**
     * Angle swept about the normal. [deg]
     */

    return ArgsCircle;
  })();

  /**
   * CIRCLE5B: Circle, 5 axis. Versions 1.x, 2.x, 3.0; 64 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsCircle5b = Cbf.ArgsCircle5b = (function() {
    function ArgsCircle5b(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsCircle5b.prototype._read = function() {
      this.start = [];
      for (var i = 0; i < 3; i++) {
        this.start.push(this._io.readF4le());
      }
      this.center = [];
      for (var i = 0; i < 3; i++) {
        this.center.push(this._io.readF4le());
      }
      this.normal = [];
      for (var i = 0; i < 3; i++) {
        this.normal.push(this._io.readF4le());
      }
      this.ndegrees = this._io.readF4le();
      this.startOrient = [];
      for (var i = 0; i < 3; i++) {
        this.startOrient.push(this._io.readF4le());
      }
      this.endOrient = [];
      for (var i = 0; i < 3; i++) {
        this.endOrient.push(this._io.readF4le());
      }
    }

    /**
     * Start point. [mm]
     */

    /**
     * Centre point. [mm]
     */

    /**
     * Axis direction (need not be unit length); rotation by the right-hand rule.
     */

    /**
     * Angle swept about the normal. [deg]
     */

    /**
     * Start orientation.
     */

    /**
     * End orientation.
     */

    return ArgsCircle5b;
  })();

  /**
   * COMMENT: Comment. Versions 1.x, 2.x, 3.0, 4.0; 40 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsComment = Cbf.ArgsComment = (function() {
    function ArgsComment(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsComment.prototype._read = function() {
      this.text = KaitaiStream.bytesToStr(KaitaiStream.bytesStripRight(this._io.readBytes(40), 0), "ISO-8859-1");
    }

    /**
     * Comment text.
     */

    return ArgsComment;
  })();

  /**
   * CUTTER: Change cutter. Versions 2.x, 3.0, 4.0; 32 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsCutter = Cbf.ArgsCutter = (function() {
    function ArgsCutter(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsCutter.prototype._read = function() {
      this.name = KaitaiStream.bytesToStr(KaitaiStream.bytesStripRight(this._io.readBytes(16), 0), "ISO-8859-1");
      this.length = this._io.readF4le();
      this.radius = this._io.readF4le();
      this.headLength = this._io.readF4le();
      this.reserved = this._io.readBytes(4);
    }

    /**
     * Cutter name (part number).
     */

    /**
     * Cutter length (6.1.2). [mm]
     */

    /**
     * Cutter radius (6.1.2). [mm]
     */

    /**
     * Cutter head length (7.2.2.3). [mm]
     */

    /**
     * 4 bytes reserved (N7).
     */

    return ArgsCutter;
  })();

  /**
   * CUTTER_OFF: Turn cutter off. Versions 1.x, 2.x, 3.0, 4.0; 0 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsCutterOff = Cbf.ArgsCutterOff = (function() {
    function ArgsCutterOff(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsCutterOff.prototype._read = function() {
    }

    return ArgsCutterOff;
  })();

  /**
   * CUTTER_ON: Turn cutter on. Versions 1.x, 2.x, 3.0, 4.0; 0 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsCutterOn = Cbf.ArgsCutterOn = (function() {
    function ArgsCutterOn(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsCutterOn.prototype._read = function() {
    }

    return ArgsCutterOn;
  })();

  /**
   * CUTTER: Change cutter. Versions 1.x; 32 bytes.
   * @see 300071 rev 03, 7.2.2.3
   */

  var ArgsCutterV1 = Cbf.ArgsCutterV1 = (function() {
    function ArgsCutterV1(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsCutterV1.prototype._read = function() {
      this.name = KaitaiStream.bytesToStr(KaitaiStream.bytesStripRight(this._io.readBytes(16), 0), "ISO-8859-1");
      this.length = this._io.readF4le();
      this.radius = this._io.readF4le();
      this.reserved = this._io.readBytes(8);
    }

    /**
     * Cutter name (part number).
     */

    /**
     * Cutter length (6.1.2). [mm]
     */

    /**
     * Cutter radius (6.1.2). [mm]
     */

    /**
     * 8 bytes reserved; head length came in 2.0 (7.2.2.3).
     */

    return ArgsCutterV1;
  })();

  /**
   * DECEL_OFF: Turn on motion blending (i.e., don't decelerate). Versions 2.x, 3.0, 4.0; 0 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsDecelOff = Cbf.ArgsDecelOff = (function() {
    function ArgsDecelOff(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsDecelOff.prototype._read = function() {
    }

    return ArgsDecelOff;
  })();

  /**
   * DECEL_ON: Turn off motion blending (i.e., decelerate). Versions 2.x, 3.0, 4.0; 0 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsDecelOn = Cbf.ArgsDecelOn = (function() {
    function ArgsDecelOn(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsDecelOn.prototype._read = function() {
    }

    return ArgsDecelOn;
  })();

  /**
   * ENABLE_SKIP: Enable skip to phase. Versions 1.x, 2.x, 3.0, 4.0; 16 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsEnableSkip = Cbf.ArgsEnableSkip = (function() {
    function ArgsEnableSkip(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsEnableSkip.prototype._read = function() {
      this.name = KaitaiStream.bytesToStr(KaitaiStream.bytesStripRight(this._io.readBytes(16), 0), "ISO-8859-1");
    }

    /**
     * Name of the phase to skip to.
     */

    return ArgsEnableSkip;
  })();

  /**
   * ENDSHAPE: End of a shape; same arguments as STARTSHAPE (redundancy). Versions 1.x, 2.x, 3.0, 4.0; 6 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsEndshape = Cbf.ArgsEndshape = (function() {
    function ArgsEndshape(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsEndshape.prototype._read = function() {
      this.name = KaitaiStream.bytesToStr(KaitaiStream.bytesStripRight(this._io.readBytes(5), 0), "ISO-8859-1");
      this.moves = this._io.readU1();
    }

    /**
     * Shape name, as in STARTSHAPE.
     */

    /**
     * Number of (move) commands, as in STARTSHAPE. [count]
     */

    return ArgsEndshape;
  })();

  /**
   * FCPARMS: Force control parameters. Versions 2.x, 3.0, 4.0; 16 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsFcparms = Cbf.ArgsFcparms = (function() {
    function ArgsFcparms(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsFcparms.prototype._read = function() {
      this.nomSpeed = this._io.readF4le();
      this.maxSpeed = this._io.readF4le();
      this.minSpeed = this._io.readF4le();
      this.maxForce = this._io.readF4le();
    }

    /**
     * Nominal speed. [m/s]
     */

    /**
     * Maximum speed. [m/s]
     */

    /**
     * Minimum speed. [m/s]
     */

    /**
     * Maximum force. [N]
     */

    return ArgsFcparms;
  })();

  /**
   * GUIDE: Guide message. Versions 1.x, 2.x, 3.0, 4.0; 32 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsGuide = Cbf.ArgsGuide = (function() {
    function ArgsGuide(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsGuide.prototype._read = function() {
      this.message = KaitaiStream.bytesToStr(KaitaiStream.bytesStripRight(this._io.readBytes(32), 0), "ISO-8859-1");
    }

    /**
     * Message.
     */

    return ArgsGuide;
  })();

  /**
   * HELIX: Helix. Versions 2.x, 3.0; 44 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsHelix = Cbf.ArgsHelix = (function() {
    function ArgsHelix(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsHelix.prototype._read = function() {
      this.start = [];
      for (var i = 0; i < 3; i++) {
        this.start.push(this._io.readF4le());
      }
      this.center = [];
      for (var i = 0; i < 3; i++) {
        this.center.push(this._io.readF4le());
      }
      this.normal = [];
      for (var i = 0; i < 3; i++) {
        this.normal.push(this._io.readF4le());
      }
      this.ndegrees = this._io.readF4le();
      this.length = this._io.readF4le();
    }

    /**
     * Start point. [mm]
     */

    /**
     * Centre point. [mm]
     */

    /**
     * Axis direction (need not be unit length); rotation by the right-hand rule.
     */

    /**
     * Angle swept about the normal. [deg]
     */

    /**
     * Axial advance along the unit normal. [mm]
     */

    return ArgsHelix;
  })();

  /**
   * HELIX5B: Helix, 5 axis. Versions 1.x, 2.x, 3.0; 68 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsHelix5b = Cbf.ArgsHelix5b = (function() {
    function ArgsHelix5b(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsHelix5b.prototype._read = function() {
      this.start = [];
      for (var i = 0; i < 3; i++) {
        this.start.push(this._io.readF4le());
      }
      this.center = [];
      for (var i = 0; i < 3; i++) {
        this.center.push(this._io.readF4le());
      }
      this.normal = [];
      for (var i = 0; i < 3; i++) {
        this.normal.push(this._io.readF4le());
      }
      this.ndegrees = this._io.readF4le();
      this.length = this._io.readF4le();
      this.startOrient = [];
      for (var i = 0; i < 3; i++) {
        this.startOrient.push(this._io.readF4le());
      }
      this.endOrient = [];
      for (var i = 0; i < 3; i++) {
        this.endOrient.push(this._io.readF4le());
      }
    }

    /**
     * Start point. [mm]
     */

    /**
     * Centre point. [mm]
     */

    /**
     * Axis direction (need not be unit length); rotation by the right-hand rule.
     */

    /**
     * Angle swept about the normal. [deg]
     */

    /**
     * Axial advance along the unit normal. [mm]
     */

    /**
     * Start orientation.
     */

    /**
     * End orientation.
     */

    return ArgsHelix5b;
  })();

  /**
   * LINE: Straight line motion. Versions 1.x, 2.x, 3.0, 4.0; 24 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsLine = Cbf.ArgsLine = (function() {
    function ArgsLine(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsLine.prototype._read = function() {
      this.start = [];
      for (var i = 0; i < 3; i++) {
        this.start.push(this._io.readF4le());
      }
      this.end = [];
      for (var i = 0; i < 3; i++) {
        this.end.push(this._io.readF4le());
      }
    }

    /**
     * Start point. [mm]
     */

    /**
     * End point. [mm]
     */

    return ArgsLine;
  })();

  /**
   * LINE5B: Straight line motion, 5 axis. Versions 1.x, 2.x, 3.0, 4.0; 48 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsLine5b = Cbf.ArgsLine5b = (function() {
    function ArgsLine5b(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsLine5b.prototype._read = function() {
      this.startPos = [];
      for (var i = 0; i < 3; i++) {
        this.startPos.push(this._io.readF4le());
      }
      this.endPos = [];
      for (var i = 0; i < 3; i++) {
        this.endPos.push(this._io.readF4le());
      }
      this.startOrient = [];
      for (var i = 0; i < 3; i++) {
        this.startOrient.push(this._io.readF4le());
      }
      this.endOrient = [];
      for (var i = 0; i < 3; i++) {
        this.endOrient.push(this._io.readF4le());
      }
    }

    /**
     * Start position. [mm]
     */

    /**
     * End position. [mm]
     */

    /**
     * Start orientation.
     */

    /**
     * End orientation.
     */

    return ArgsLine5b;
  })();

  /**
   * ORIENT: Orientation change. Versions 1.x, 2.x, 3.0, 4.0; 24 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsOrient = Cbf.ArgsOrient = (function() {
    function ArgsOrient(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsOrient.prototype._read = function() {
      this.approach = [];
      for (var i = 0; i < 3; i++) {
        this.approach.push(this._io.readF4le());
      }
      this.reserved = this._io.readBytes(12);
    }

    /**
     * Tool approach.
     */

    /**
     * reserved: float(3); kept verbatim (N7).
     */

    return ArgsOrient;
  })();

  /**
   * ORIENT5B: Orientation change, 5 axis. Versions 1.x, 2.x, 3.0, 4.0; 24 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsOrient5b = Cbf.ArgsOrient5b = (function() {
    function ArgsOrient5b(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsOrient5b.prototype._read = function() {
      this.startApproach = [];
      for (var i = 0; i < 3; i++) {
        this.startApproach.push(this._io.readF4le());
      }
      this.endApproach = [];
      for (var i = 0; i < 3; i++) {
        this.endApproach.push(this._io.readF4le());
      }
    }

    /**
     * Start approach.
     */

    /**
     * End approach.
     */

    return ArgsOrient5b;
  })();

  /**
   * PHASE: Cutting phase. Versions 2.x, 3.0, 4.0; 16 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsPhase = Cbf.ArgsPhase = (function() {
    function ArgsPhase(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsPhase.prototype._read = function() {
      this.name = KaitaiStream.bytesToStr(KaitaiStream.bytesStripRight(this._io.readBytes(16), 0), "ISO-8859-1");
    }

    /**
     * Phase name.
     */

    return ArgsPhase;
  })();

  /**
   * POINT: Starting goal point. Versions 1.x, 2.x, 3.0, 4.0; 12 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsPoint = Cbf.ArgsPoint = (function() {
    function ArgsPoint(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsPoint.prototype._read = function() {
      this.point = [];
      for (var i = 0; i < 3; i++) {
        this.point.push(this._io.readF4le());
      }
    }

    /**
     * Goal point. [mm]
     */

    return ArgsPoint;
  })();

  /**
   * SPEED: Speed. Versions 1.x, 2.x, 3.0, 4.0; 4 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsSpeed = Cbf.ArgsSpeed = (function() {
    function ArgsSpeed(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsSpeed.prototype._read = function() {
      this.speed = this._io.readF4le();
    }

    /**
     * Speed. [m/s]
     */

    return ArgsSpeed;
  })();

  /**
   * STARTSHAPE: Start of a shape. Versions 1.x, 2.x, 3.0, 4.0; 6 bytes.
   * @see 300071 rev 03, 5.1
   */

  var ArgsStartshape = Cbf.ArgsStartshape = (function() {
    function ArgsStartshape(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsStartshape.prototype._read = function() {
      this.name = KaitaiStream.bytesToStr(KaitaiStream.bytesStripRight(this._io.readBytes(5), 0), "ISO-8859-1");
      this.moves = this._io.readU1();
    }

    /**
     * Shape name.
     */

    /**
     * Number of (move) commands in the shape. [count]
     */

    return ArgsStartshape;
  })();

  /**
   * VERSION: Version numbers. Versions 2.x, 3.0, 4.0; 32 bytes. Default layout (N8); the 16 listed bytes and 16 reserved bytes make up the declared 32.
   * @see 300071 rev 03, 5.1
   */

  var ArgsVersion = Cbf.ArgsVersion = (function() {
    function ArgsVersion(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsVersion.prototype._read = function() {
      this.cutfile = KaitaiStream.bytesToStr(KaitaiStream.bytesStripRight(this._io.readBytes(8), 0), "ISO-8859-1");
      this.format = KaitaiStream.bytesToStr(KaitaiStream.bytesStripRight(this._io.readBytes(8), 0), "ISO-8859-1");
      this.reserved = this._io.readBytes(16);
    }

    /**
     * Cutfile version.
     */

    /**
     * Format version.
     */

    /**
     * Not listed by 5.1; reserved to reach the declared 32 bytes (N8).
     */

    return ArgsVersion;
  })();

  /**
   * VERSION: Version numbers. Versions 2.x, 3.0, 4.0; 16 bytes. Accepted under profile implib. The 16 listed bytes only, as implib writes them (N8); accepted under the implib profile.
   * @see 300071 rev 03, 5.1
   */

  var ArgsVersionImplib = Cbf.ArgsVersionImplib = (function() {
    function ArgsVersionImplib(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    ArgsVersionImplib.prototype._read = function() {
      this.cutfile = KaitaiStream.bytesToStr(KaitaiStream.bytesStripRight(this._io.readBytes(8), 0), "ISO-8859-1");
      this.format = KaitaiStream.bytesToStr(KaitaiStream.bytesStripRight(this._io.readBytes(8), 0), "ISO-8859-1");
    }

    /**
     * Cutfile version.
     */

    /**
     * Format version.
     */

    return ArgsVersionImplib;
  })();

  /**
   * File header (4.2); after the version field its layout depends on the version.
   */

  var Header = Cbf.Header = (function() {
    function Header(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    Header.prototype._read = function() {
      this.startPattern = this._io.readU4le();
      if (!(this.startPattern == 1403107218)) {
        throw new KaitaiStream.ValidationNotEqualError(1403107218, this.startPattern, this._io, "/types/header/seq/0");
      }
      this.fileChecksum = this._io.readU4le();
      this.headerChecksum = this._io.readU2le();
      this.reservedEcc = this._io.readBytes(6);
      this.versionMajor = this._io.readU1();
      this.versionMinor = this._io.readU1();
      switch (this.versionIndex) {
      case 1:
        this.layout = new HeaderV1(this._io, this, this._root);
        break;
      case 2:
        this.layout = new HeaderV2(this._io, this, this._root);
        break;
      case 3:
        this.layout = new HeaderV2(this._io, this, this._root);
        break;
      case 4:
        this.layout = new HeaderV2(this._io, this, this._root);
        break;
      }
    }

    /**
     * 1-based index of the spec's version entry (1 = 1.x, 2 = 2.x, 3 = 3.0, 4 = 4.0); unknown versions read as 4.0.
     */
    Object.defineProperty(Header.prototype, 'versionIndex', {
      get: function() {
        if (this._m_versionIndex !== undefined)
          return this._m_versionIndex;
        this._m_versionIndex = (this.versionMajor == 1 ? 1 : (this.versionMajor == 2 ? 2 : ( ((this.versionMajor == 3) && (this.versionMinor == 0))  ? 3 : ( ((this.versionMajor == 4) && (this.versionMinor == 0))  ? 4 : 4))));
        return this._m_versionIndex;
      }
    });

    /**
     * Special pattern indicating cutting file (N5, bytes 92 B7 A1 53).
     * @see 300071 rev 03, 4.2
     */

    /**
     * Checksum for entire file (starting at byte 8).
     * @see 300071 rev 03, 4.2
     */

    /**
     * Checksum for rest of header.
     * @see 300071 rev 03, 4.2
     */

    /**
     * Reserved for future checksum usage (Error Correcting Codes); kept verbatim (N7).
     * @see 300071 rev 03, 4.2
     */

    /**
     * Version number for cutfile format, major (N3).
     * @see 300071 rev 03, 4.2
     */

    /**
     * Version number for cutfile format, minor (N3).
     * @see 300071 rev 03, 4.2
     */

    /**
     * The rest of the header, laid out as the version says (7.1).
     */

    return Header;
  })();

  /**
   * File header before 7.2.2.1 shortened the implant descriptor.
   */

  var HeaderV1 = Cbf.HeaderV1 = (function() {
    function HeaderV1(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    HeaderV1.prototype._read = function() {
      this.implantDescriptor = KaitaiStream.bytesToStr(KaitaiStream.bytesStripRight(this._io.readBytes(80), 0), "ISO-8859-1");
      this.reserved98 = this._io.readBytes(24);
      this.commandCount = this._io.readU2le();
      this.endPattern = this._io.readU4le();
      if (!(this.endPattern == 2891860077)) {
        throw new KaitaiStream.ValidationNotEqualError(2891860077, this.endPattern, this._io, "/types/header_v1/seq/3");
      }
    }

    /**
     * Implant descriptor of 80 bytes (1.x).
     * @see 300071 rev 03, 7.2.2.1
     */

    /**
     * Reserved field at offset 98 (1.x); renamed Configuration Descriptor in 2.0.
     * @see 300071 rev 03, 7.2.2.1
     */

    /**
     * Number of commands in cutting data section.
     * @see 300071 rev 03, 4.2
     */

    /**
     * Complement of the start pattern (N5).
     * @see 300071 rev 03, 4.2
     */

    return HeaderV1;
  })();

  /**
   * File header as 4.2 gives it, with the configuration descriptor of 7.2.2.1.
   */

  var HeaderV2 = Cbf.HeaderV2 = (function() {
    function HeaderV2(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    HeaderV2.prototype._read = function() {
      this.implantDescriptor = KaitaiStream.bytesToStr(KaitaiStream.bytesStripRight(this._io.readBytes(70), 0), "ISO-8859-1");
      this.configurationDescriptor = KaitaiStream.bytesToStr(KaitaiStream.bytesStripRight(this._io.readBytes(34), 0), "ISO-8859-1");
      this.commandCount = this._io.readU2le();
      this.endPattern = this._io.readU4le();
      if (!(this.endPattern == 2891860077)) {
        throw new KaitaiStream.ValidationNotEqualError(2891860077, this.endPattern, this._io, "/types/header_v2/seq/3");
      }
    }

    /**
     * Implant descriptor (part number, manufacturer, type, size); the part number must be the first item (6.1.1).
     * @see 300071 rev 03, 4.2
     */

    /**
     * Configuration descriptor; the field 7.2.2.1 made of the 1.x reserved bytes.
     * @see 300071 rev 03, 4.2
     */

    /**
     * Number of commands in cutting data section (6.2.2).
     * @see 300071 rev 03, 4.2
     */

    /**
     * Special pattern indicating end of header, the complement of the start pattern (N5, bytes 6D 48 5E AC).
     * @see 300071 rev 03, 4.2
     */

    return HeaderV2;
  })();

  /**
   * A cutting-data record; the records follow the header back to back. Not expressible here: 6.4.1 (sequence), 6.4.4 (arg_checksum).
   */

  var Record = Cbf.Record = (function() {
    function Record(_io, _parent, _root) {
      this._io = _io;
      this._parent = _parent;
      this._root = _root;

      this._read();
    }
    Record.prototype._read = function() {
      this.sequence = this._io.readU2le();
      this.code = this._io.readU1();
      var _ = this.code;
      if (!( ((!( ((this._root.header.versionIndex == 4) && ( ((_ == 148) || (_ == 149) || (_ == 122) || (_ == 123) || (_ == 226) || (_ == 227)) )) )) && (!( ((this._root.header.versionIndex == 1) && ( ((_ == 33) || (_ == 43) || (_ == 78) || (_ == 226) || (_ == 252) || (_ == 85)) )) ))) )) {
        throw new KaitaiStream.ValidationExprError(this.code, this._io, "/types/record/seq/1");
      }
      this.codeCopy = this._io.readU1();
      var _ = this.codeCopy;
      if (!(_ == this.code)) {
        throw new KaitaiStream.ValidationExprError(this.codeCopy, this._io, "/types/record/seq/2");
      }
      this.argSize = this._io.readU1();
      var _ = this.argSize;
      if (!((this.code == 60 ?  (( ((this._root.header.versionIndex == 1) && (_ == 16)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 32)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 32)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 32)) ))  : (this.code == 163 ?  (( ((this._root.header.versionIndex == 1) && (_ == 32)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 32)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 32)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 32)) ))  : (this.code == 88 ?  (( ((this._root.header.versionIndex == 1) && (_ == 24)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 24)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 24)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 24)) ))  : (this.code == 89 ?  (( ((this._root.header.versionIndex == 1) && (_ == 24)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 24)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 24)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 24)) ))  : (this.code == 33 ?  (( ((this._root.header.versionIndex == 1) && (_ == 16)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 16)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 16)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 16)) ))  : (this.code == 34 ?  (( ((this._root.header.versionIndex == 1) && (_ == 16)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 16)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 16)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 16)) ))  : (this.code == 201 ?  (( ((this._root.header.versionIndex == 1) && (_ == 6)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 6)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 6)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 6)) ))  : (this.code == 101 ?  (( ((this._root.header.versionIndex == 1) && (_ == 6)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 6)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 6)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 6)) ))  : (this.code == 43 ?  (( ((this._root.header.versionIndex == 1) && (_ == 0)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 0)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 0)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 0)) ))  : (this.code == 78 ?  (( ((this._root.header.versionIndex == 1) && (_ == 0)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 0)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 0)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 0)) ))  : (this.code == 51 ?  (( ((this._root.header.versionIndex == 1) && (_ == 12)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 12)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 12)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 12)) ))  : (this.code == 182 ?  (( ((this._root.header.versionIndex == 1) && (_ == 24)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 24)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 24)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 24)) ))  : (this.code == 183 ?  (( ((this._root.header.versionIndex == 1) && (_ == 48)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 48)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 48)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 48)) ))  : (this.code == 148 ?  (( ((this._root.header.versionIndex == 1) && (_ == 36)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 36)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 36)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 36)) ))  : (this.code == 149 ?  (( ((this._root.header.versionIndex == 1) && (_ == 60)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 60)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 60)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 60)) ))  : (this.code == 122 ?  (( ((this._root.header.versionIndex == 1) && (_ == 40)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 40)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 40)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 40)) ))  : (this.code == 123 ?  (( ((this._root.header.versionIndex == 1) && (_ == 64)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 64)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 64)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 64)) ))  : (this.code == 226 ?  (( ((this._root.header.versionIndex == 1) && (_ == 44)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 44)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 44)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 44)) ))  : (this.code == 227 ?  (( ((this._root.header.versionIndex == 1) && (_ == 68)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 68)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 68)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 68)) ))  : (this.code == 139 ?  (( ((this._root.header.versionIndex == 1) && (_ == 4)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 4)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 4)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 4)) ))  : (this.code == 71 ?  (( ((this._root.header.versionIndex == 1) && (_ == 8)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 8)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 8)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 8)) ))  : (this.code == 187 ?  (( ((this._root.header.versionIndex == 1) && (_ == 0)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 0)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 0)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 0)) ))  : (this.code == 102 ?  (( ((this._root.header.versionIndex == 1) && (_ == 0)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 0)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 0)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 0)) ))  : (this.code == 17 ?  (( ((this._root.header.versionIndex == 1) && (_ == 32)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 32)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 32)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 32)) ))  : (this.code == 252 ?  (( ((this._root.header.versionIndex == 1) && (_ == 16)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 16)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 16)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 16)) ))  : (this.code == 85 ?  (( ((this._root.header.versionIndex == 1) && ( ((_ == 16) || (_ == 32)) )) ) || ( ((this._root.header.versionIndex == 2) && ( ((_ == 16) || (_ == 32)) )) ) || ( ((this._root.header.versionIndex == 3) && ( ((_ == 16) || (_ == 32)) )) ) || ( ((this._root.header.versionIndex == 4) && ( ((_ == 16) || (_ == 32)) )) ))  : (this.code == 90 ?  (( ((this._root.header.versionIndex == 1) && (_ == 40)) ) || ( ((this._root.header.versionIndex == 2) && (_ == 40)) ) || ( ((this._root.header.versionIndex == 3) && (_ == 40)) ) || ( ((this._root.header.versionIndex == 4) && (_ == 40)) ))  : true))))))))))))))))))))))))))))) {
        throw new KaitaiStream.ValidationExprError(this.argSize, this._io, "/types/record/seq/3");
      }
      this.reserved = this._io.readU1();
      this.argChecksum = this._io.readU2le();
      switch ((this.code * 65536 + this.argSize * 256) + this._root.header.versionIndex) {
      case 10690561:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsCutterV1(_io__raw_args, this, this._root);
        break;
      case 10690562:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsCutter(_io__raw_args, this, this._root);
        break;
      case 10690563:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsCutter(_io__raw_args, this, this._root);
        break;
      case 10690564:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsCutter(_io__raw_args, this, this._root);
        break;
      case 1122305:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsGuide(_io__raw_args, this, this._root);
        break;
      case 1122306:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsGuide(_io__raw_args, this, this._root);
        break;
      case 1122307:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsGuide(_io__raw_args, this, this._root);
        break;
      case 1122308:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsGuide(_io__raw_args, this, this._root);
        break;
      case 11933697:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsLine(_io__raw_args, this, this._root);
        break;
      case 11933698:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsLine(_io__raw_args, this, this._root);
        break;
      case 11933699:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsLine(_io__raw_args, this, this._root);
        break;
      case 11933700:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsLine(_io__raw_args, this, this._root);
        break;
      case 12005377:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsLine5b(_io__raw_args, this, this._root);
        break;
      case 12005378:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsLine5b(_io__raw_args, this, this._root);
        break;
      case 12005379:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsLine5b(_io__raw_args, this, this._root);
        break;
      case 12005380:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsLine5b(_io__raw_args, this, this._root);
        break;
      case 12255233:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsCutterOn(_io__raw_args, this, this._root);
        break;
      case 12255234:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsCutterOn(_io__raw_args, this, this._root);
        break;
      case 12255235:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsCutterOn(_io__raw_args, this, this._root);
        break;
      case 12255236:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsCutterOn(_io__raw_args, this, this._root);
        break;
      case 13174273:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsStartshape(_io__raw_args, this, this._root);
        break;
      case 13174274:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsStartshape(_io__raw_args, this, this._root);
        break;
      case 13174275:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsStartshape(_io__raw_args, this, this._root);
        break;
      case 13174276:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsStartshape(_io__raw_args, this, this._root);
        break;
      case 14822401:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsHelix(_io__raw_args, this, this._root);
        break;
      case 14822402:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsHelix(_io__raw_args, this, this._root);
        break;
      case 14822403:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsHelix(_io__raw_args, this, this._root);
        break;
      case 14822404:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsHelix(_io__raw_args, this, this._root);
        break;
      case 14894081:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsHelix5b(_io__raw_args, this, this._root);
        break;
      case 14894082:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsHelix5b(_io__raw_args, this, this._root);
        break;
      case 14894083:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsHelix5b(_io__raw_args, this, this._root);
        break;
      case 14894084:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsHelix5b(_io__raw_args, this, this._root);
        break;
      case 16519169:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsFcparms(_io__raw_args, this, this._root);
        break;
      case 16519170:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsFcparms(_io__raw_args, this, this._root);
        break;
      case 16519171:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsFcparms(_io__raw_args, this, this._root);
        break;
      case 16519172:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsFcparms(_io__raw_args, this, this._root);
        break;
      case 2166785:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsPhase(_io__raw_args, this, this._root);
        break;
      case 2166786:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsPhase(_io__raw_args, this, this._root);
        break;
      case 2166787:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsPhase(_io__raw_args, this, this._root);
        break;
      case 2166788:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsPhase(_io__raw_args, this, this._root);
        break;
      case 2232321:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsEnableSkip(_io__raw_args, this, this._root);
        break;
      case 2232322:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsEnableSkip(_io__raw_args, this, this._root);
        break;
      case 2232323:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsEnableSkip(_io__raw_args, this, this._root);
        break;
      case 2232324:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsEnableSkip(_io__raw_args, this, this._root);
        break;
      case 2818049:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsDecelOff(_io__raw_args, this, this._root);
        break;
      case 2818050:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsDecelOff(_io__raw_args, this, this._root);
        break;
      case 2818051:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsDecelOff(_io__raw_args, this, this._root);
        break;
      case 2818052:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsDecelOff(_io__raw_args, this, this._root);
        break;
      case 3345409:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsPoint(_io__raw_args, this, this._root);
        break;
      case 3345410:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsPoint(_io__raw_args, this, this._root);
        break;
      case 3345411:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsPoint(_io__raw_args, this, this._root);
        break;
      case 3345412:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsPoint(_io__raw_args, this, this._root);
        break;
      case 3936257:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsCheckpointV1(_io__raw_args, this, this._root);
        break;
      case 3940354:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsCheckpoint(_io__raw_args, this, this._root);
        break;
      case 3940355:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsCheckpoint(_io__raw_args, this, this._root);
        break;
      case 3940356:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsCheckpoint(_io__raw_args, this, this._root);
        break;
      case 4655105:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsAccel(_io__raw_args, this, this._root);
        break;
      case 4655106:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsAccel(_io__raw_args, this, this._root);
        break;
      case 4655107:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsAccel(_io__raw_args, this, this._root);
        break;
      case 4655108:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsAccel(_io__raw_args, this, this._root);
        break;
      case 5111809:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsDecelOn(_io__raw_args, this, this._root);
        break;
      case 5111810:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsDecelOn(_io__raw_args, this, this._root);
        break;
      case 5111811:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsDecelOn(_io__raw_args, this, this._root);
        break;
      case 5111812:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsDecelOn(_io__raw_args, this, this._root);
        break;
      case 5574657:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsVersionImplib(_io__raw_args, this, this._root);
        break;
      case 5574658:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsVersionImplib(_io__raw_args, this, this._root);
        break;
      case 5574659:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsVersionImplib(_io__raw_args, this, this._root);
        break;
      case 5574660:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsVersionImplib(_io__raw_args, this, this._root);
        break;
      case 5578753:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsVersion(_io__raw_args, this, this._root);
        break;
      case 5578754:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsVersion(_io__raw_args, this, this._root);
        break;
      case 5578755:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsVersion(_io__raw_args, this, this._root);
        break;
      case 5578756:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsVersion(_io__raw_args, this, this._root);
        break;
      case 5773313:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsOrient(_io__raw_args, this, this._root);
        break;
      case 5773314:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsOrient(_io__raw_args, this, this._root);
        break;
      case 5773315:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsOrient(_io__raw_args, this, this._root);
        break;
      case 5773316:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsOrient(_io__raw_args, this, this._root);
        break;
      case 5838849:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsOrient5b(_io__raw_args, this, this._root);
        break;
      case 5838850:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsOrient5b(_io__raw_args, this, this._root);
        break;
      case 5838851:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsOrient5b(_io__raw_args, this, this._root);
        break;
      case 5838852:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsOrient5b(_io__raw_args, this, this._root);
        break;
      case 5908481:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsComment(_io__raw_args, this, this._root);
        break;
      case 5908482:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsComment(_io__raw_args, this, this._root);
        break;
      case 5908483:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsComment(_io__raw_args, this, this._root);
        break;
      case 5908484:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsComment(_io__raw_args, this, this._root);
        break;
      case 6620673:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsEndshape(_io__raw_args, this, this._root);
        break;
      case 6620674:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsEndshape(_io__raw_args, this, this._root);
        break;
      case 6620675:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsEndshape(_io__raw_args, this, this._root);
        break;
      case 6620676:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsEndshape(_io__raw_args, this, this._root);
        break;
      case 6684673:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsCutterOff(_io__raw_args, this, this._root);
        break;
      case 6684674:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsCutterOff(_io__raw_args, this, this._root);
        break;
      case 6684675:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsCutterOff(_io__raw_args, this, this._root);
        break;
      case 6684676:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsCutterOff(_io__raw_args, this, this._root);
        break;
      case 8005633:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsCircle(_io__raw_args, this, this._root);
        break;
      case 8005634:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsCircle(_io__raw_args, this, this._root);
        break;
      case 8005635:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsCircle(_io__raw_args, this, this._root);
        break;
      case 8005636:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsCircle(_io__raw_args, this, this._root);
        break;
      case 8077313:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsCircle5b(_io__raw_args, this, this._root);
        break;
      case 8077314:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsCircle5b(_io__raw_args, this, this._root);
        break;
      case 8077315:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsCircle5b(_io__raw_args, this, this._root);
        break;
      case 8077316:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsCircle5b(_io__raw_args, this, this._root);
        break;
      case 9110529:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsSpeed(_io__raw_args, this, this._root);
        break;
      case 9110530:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsSpeed(_io__raw_args, this, this._root);
        break;
      case 9110531:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsSpeed(_io__raw_args, this, this._root);
        break;
      case 9110532:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsSpeed(_io__raw_args, this, this._root);
        break;
      case 9708545:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsArc(_io__raw_args, this, this._root);
        break;
      case 9708546:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsArc(_io__raw_args, this, this._root);
        break;
      case 9708547:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsArc(_io__raw_args, this, this._root);
        break;
      case 9708548:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsArc(_io__raw_args, this, this._root);
        break;
      case 9780225:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsArc5b(_io__raw_args, this, this._root);
        break;
      case 9780226:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsArc5b(_io__raw_args, this, this._root);
        break;
      case 9780227:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsArc5b(_io__raw_args, this, this._root);
        break;
      case 9780228:
        this._raw_args = this._io.readBytes(this.argSize);
        var _io__raw_args = new KaitaiStream(this._raw_args);
        this.args = new ArgsArc5b(_io__raw_args, this, this._root);
        break;
      default:
        this.args = this._io.readBytes(this.argSize);
        break;
      }
    }

    /**
     * The command code as the enum (5.2).
     */
    Object.defineProperty(Record.prototype, 'command', {
      get: function() {
        if (this._m_command !== undefined)
          return this._m_command;
        this._m_command = this.code;
        return this._m_command;
      }
    });

    /**
     * Command sequence number (0 - 65535); 6.4.1.
     * @see 300071 rev 03, 4.3
     */

    /**
     * Command code (5.1). Version gating (7.2.3.1, 7.2.2.4) is a valid: expression.
     * @see 300071 rev 03, 4.3
     */

    /**
     * Backup copy of command code (redundancy); 6.4.2.
     * @see 300071 rev 03, 4.3
     */

    /**
     * Number of bytes used by command arguments (nb); 6.4.3.
     * @see 300071 rev 03, 4.3
     */

    /**
     * Reserved, should be 0 (N7).
     * @see 300071 rev 03, 4.3
     */

    /**
     * Checksum of command arguments; 6.4.4.
     * @see 300071 rev 03, 4.3
     */

    /**
     * The command's arguments: the layout of the file's version whose size matches (for a command the version lacks, any of its layouts); raw bytes for an unknown code.
     */

    return Record;
  })();

  /**
   * File header (4.2).
   */

  /**
   * The command records, framed to the end of the file (4.3).
   */

  return Cbf;
})();
Cbf_.Cbf = Cbf;
});
