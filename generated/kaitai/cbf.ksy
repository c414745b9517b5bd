# Generated from spec/cbf.yaml by cbfgen; do not edit.
meta:
  id: cbf
  title: Cutfile Binary Format (300071 rev 03)
  file-extension: cbf
  xref:
    thinksurgical:
    - 300071 rev 03
    - 300072 rev 07
  license: LicenseRef-THINK-Surgical-Proprietary
  ks-version: '0.11'
  endian: le
doc: 'The CBF file provides the toolpath information for cutting implant cavities with the ROBODOC System (1.1). It carries
  a 128-byte header and a sequence of variable-length command records. It can be created from, and converted to, an ASCII
  format, the CUT file (1.2). Generated from spec/cbf.yaml; do not edit. Kaitai checks here the magic numbers, the code copy,
  the argument size per command and version, and version gating. It cannot check: 4.2 (The file header is 128 bytes long.);
  4.3 (The cutting data consists of variable length records.); 6.1.1 (The first word in the Implant Descriptor field in the
  file header should be the implant part number.); part_number_first (The implant descriptor begins with the implant part
  number (4.2; 6.1.1 compares it when one is given).); 6.1.2 (The length and radius of every cutter (specified by the CUTTER
  command) should agree, within 0.01 millimeters, with the values specified in the robot''s cutter database.); 6.2.1 (The
  checksum of the entire file should match the value specified in the file header.); 6.2.2 (The number of commands in the
  file should match the value specified in the file header.); 6.3.1 (The checksum of the file header should match the specified
  value.); 6.4.1 (The sequence number should be one greater than the previous sequence number (first record should have sequence
  number 0).); 6.4.4 (The checksum of the command argument bytes should match the specified value.); 6.4.5 (The starting point
  of a motion command (e.g., LINE, ARC, CIRCLE, etc.) should match the ending point of the previous motion command.); version_supported
  (The processing software can read the version number and adjust the parsing logic appropriately.); unknown_command (An unknown
  command code is an error; its record is kept whole.); trailing_bytes (No byte follows the last record.); reserved_nonzero
  (The record''s reserved byte should be 0.); string_tail (A string ends at its first NUL; the bytes after it are padding.);
  string_ascii (Strings are ASCII.); non_finite (Floats are finite.); speed_positive (SPEED is greater than 0.); accel_positive
  (Acceleration and deceleration are greater than 0.); cutter_positive (Cutter length and radius are greater than 0.); normal_nonzero
  (A circle or helix normal has non-zero length.); checkpoint_range (CHECKPOINT completion lies in 0..100.); checkpoint_falling
  (CHECKPOINT completion does not fall.); fcparms_order (FCPARMS speeds satisfy min <= nom <= max.); orientation_jump (A 5-axis
  command starts at the current tool orientation.); machine_limits (Positions lie in the machine''s workspace; speeds, accelerations
  and cutter sizes lie in its ranges.); shape (STARTSHAPE name,n ... ENDSHAPE name,n enclose exactly n motion commands; shapes
  do not nest.).'
doc-ref: Specification, Implant Support Software, TCAT, part number 300071, revision 03
seq:
- id: header
  type: header
  doc: File header (4.2).
- id: records
  type: record
  repeat: eos
  doc: The command records, framed to the end of the file (4.3).
types:
  header:
    doc: File header (4.2); after the version field its layout depends on the version.
    seq:
    - id: start_pattern
      type: u4
      valid: '0x53a1b792'
      doc: Special pattern indicating cutting file (N5, bytes 92 B7 A1 53).
      doc-ref: 300071 rev 03, 4.2
    - id: file_checksum
      type: u4
      doc: Checksum for entire file (starting at byte 8).
      doc-ref: 300071 rev 03, 4.2
    - id: header_checksum
      type: u2
      doc: Checksum for rest of header.
      doc-ref: 300071 rev 03, 4.2
    - id: reserved_ecc
      size: 6
      doc: Reserved for future checksum usage (Error Correcting Codes); kept verbatim (N7).
      doc-ref: 300071 rev 03, 4.2
    - id: version_major
      type: u1
      doc: Version number for cutfile format, major (N3).
      doc-ref: 300071 rev 03, 4.2
    - id: version_minor
      type: u1
      doc: Version number for cutfile format, minor (N3).
      doc-ref: 300071 rev 03, 4.2
    - id: layout
      type:
        switch-on: version_index
        cases:
          1: header_v1
          2: header_v2
          3: header_v2
          4: header_v2
      doc: The rest of the header, laid out as the version says (7.1).
    instances:
      version_index:
        value: '(version_major == 1 ? 1 : (version_major == 2 ? 2 : (version_major == 3 and version_minor == 0 ? 3 : (version_major
          == 4 and version_minor == 0 ? 4 : 4))))'
        doc: 1-based index of the spec's version entry (1 = 1.x, 2 = 2.x, 3 = 3.0, 4 = 4.0); unknown versions read as 4.0.
  header_v2:
    doc: File header as 4.2 gives it, with the configuration descriptor of 7.2.2.1.
    seq:
    - id: implant_descriptor
      type: str
      size: 70
      encoding: ISO-8859-1
      pad-right: 0
      doc: Implant descriptor (part number, manufacturer, type, size); the part number must be the first item (6.1.1).
      doc-ref: 300071 rev 03, 4.2
    - id: configuration_descriptor
      type: str
      size: 34
      encoding: ISO-8859-1
      pad-right: 0
      doc: Configuration descriptor; the field 7.2.2.1 made of the 1.x reserved bytes.
      doc-ref: 300071 rev 03, 4.2
    - id: command_count
      type: u2
      doc: Number of commands in cutting data section (6.2.2).
      doc-ref: 300071 rev 03, 4.2
    - id: end_pattern
      type: u4
      valid: '0xac5e486d'
      doc: Special pattern indicating end of header, the complement of the start pattern (N5, bytes 6D 48 5E AC).
      doc-ref: 300071 rev 03, 4.2
  header_v1:
    doc: File header before 7.2.2.1 shortened the implant descriptor.
    seq:
    - id: implant_descriptor
      type: str
      size: 80
      encoding: ISO-8859-1
      pad-right: 0
      doc: Implant descriptor of 80 bytes (1.x).
      doc-ref: 300071 rev 03, 7.2.2.1
    - id: reserved_98
      size: 24
      doc: Reserved field at offset 98 (1.x); renamed Configuration Descriptor in 2.0.
      doc-ref: 300071 rev 03, 7.2.2.1
    - id: command_count
      type: u2
      doc: Number of commands in cutting data section.
      doc-ref: 300071 rev 03, 4.2
    - id: end_pattern
      type: u4
      valid: '0xac5e486d'
      doc: Complement of the start pattern (N5).
      doc-ref: 300071 rev 03, 4.2
  record:
    doc: 'A cutting-data record; the records follow the header back to back. Not expressible here: 6.4.1 (sequence), 6.4.4
      (arg_checksum).'
    seq:
    - id: sequence
      type: u2
      doc: Command sequence number (0 - 65535); 6.4.1.
      doc-ref: 300071 rev 03, 4.3
    - id: code
      type: u1
      doc: 'Command code (5.1). Version gating (7.2.3.1, 7.2.2.4) is a valid: expression.'
      doc-ref: 300071 rev 03, 4.3
      valid:
        expr: not (_root.header.version_index == 4 and (_ == 148 or _ == 149 or _ == 122 or _ == 123 or _ == 226 or _ == 227))
          and not (_root.header.version_index == 1 and (_ == 33 or _ == 43 or _ == 78 or _ == 226 or _ == 252 or _ == 85))
    - id: code_copy
      type: u1
      doc: Backup copy of command code (redundancy); 6.4.2.
      doc-ref: 300071 rev 03, 4.3
      valid:
        expr: _ == code
    - id: arg_size
      type: u1
      doc: Number of bytes used by command arguments (nb); 6.4.3.
      doc-ref: 300071 rev 03, 4.3
      valid:
        expr: 'code == 60 ? ((_root.header.version_index == 1 and (_ == 16)) or (_root.header.version_index == 2 and (_ ==
          32)) or (_root.header.version_index == 3 and (_ == 32)) or (_root.header.version_index == 4 and (_ == 32))) : code
          == 163 ? ((_root.header.version_index == 1 and (_ == 32)) or (_root.header.version_index == 2 and (_ == 32)) or
          (_root.header.version_index == 3 and (_ == 32)) or (_root.header.version_index == 4 and (_ == 32))) : code == 88
          ? ((_root.header.version_index == 1 and (_ == 24)) or (_root.header.version_index == 2 and (_ == 24)) or (_root.header.version_index
          == 3 and (_ == 24)) or (_root.header.version_index == 4 and (_ == 24))) : code == 89 ? ((_root.header.version_index
          == 1 and (_ == 24)) or (_root.header.version_index == 2 and (_ == 24)) or (_root.header.version_index == 3 and (_
          == 24)) or (_root.header.version_index == 4 and (_ == 24))) : code == 33 ? ((_root.header.version_index == 1 and
          (_ == 16)) or (_root.header.version_index == 2 and (_ == 16)) or (_root.header.version_index == 3 and (_ == 16))
          or (_root.header.version_index == 4 and (_ == 16))) : code == 34 ? ((_root.header.version_index == 1 and (_ == 16))
          or (_root.header.version_index == 2 and (_ == 16)) or (_root.header.version_index == 3 and (_ == 16)) or (_root.header.version_index
          == 4 and (_ == 16))) : code == 201 ? ((_root.header.version_index == 1 and (_ == 6)) or (_root.header.version_index
          == 2 and (_ == 6)) or (_root.header.version_index == 3 and (_ == 6)) or (_root.header.version_index == 4 and (_
          == 6))) : code == 101 ? ((_root.header.version_index == 1 and (_ == 6)) or (_root.header.version_index == 2 and
          (_ == 6)) or (_root.header.version_index == 3 and (_ == 6)) or (_root.header.version_index == 4 and (_ == 6))) :
          code == 43 ? ((_root.header.version_index == 1 and (_ == 0)) or (_root.header.version_index == 2 and (_ == 0)) or
          (_root.header.version_index == 3 and (_ == 0)) or (_root.header.version_index == 4 and (_ == 0))) : code == 78 ?
          ((_root.header.version_index == 1 and (_ == 0)) or (_root.header.version_index == 2 and (_ == 0)) or (_root.header.version_index
          == 3 and (_ == 0)) or (_root.header.version_index == 4 and (_ == 0))) : code == 51 ? ((_root.header.version_index
          == 1 and (_ == 12)) or (_root.header.version_index == 2 and (_ == 12)) or (_root.header.version_index == 3 and (_
          == 12)) or (_root.header.version_index == 4 and (_ == 12))) : code == 182 ? ((_root.header.version_index == 1 and
          (_ == 24)) or (_root.header.version_index == 2 and (_ == 24)) or (_root.header.version_index == 3 and (_ == 24))
          or (_root.header.version_index == 4 and (_ == 24))) : code == 183 ? ((_root.header.version_index == 1 and (_ ==
          48)) or (_root.header.version_index == 2 and (_ == 48)) or (_root.header.version_index == 3 and (_ == 48)) or (_root.header.version_index
          == 4 and (_ == 48))) : code == 148 ? ((_root.header.version_index == 1 and (_ == 36)) or (_root.header.version_index
          == 2 and (_ == 36)) or (_root.header.version_index == 3 and (_ == 36)) or (_root.header.version_index == 4 and (_
          == 36))) : code == 149 ? ((_root.header.version_index == 1 and (_ == 60)) or (_root.header.version_index == 2 and
          (_ == 60)) or (_root.header.version_index == 3 and (_ == 60)) or (_root.header.version_index == 4 and (_ == 60)))
          : code == 122 ? ((_root.header.version_index == 1 and (_ == 40)) or (_root.header.version_index == 2 and (_ == 40))
          or (_root.header.version_index == 3 and (_ == 40)) or (_root.header.version_index == 4 and (_ == 40))) : code ==
          123 ? ((_root.header.version_index == 1 and (_ == 64)) or (_root.header.version_index == 2 and (_ == 64)) or (_root.header.version_index
          == 3 and (_ == 64)) or (_root.header.version_index == 4 and (_ == 64))) : code == 226 ? ((_root.header.version_index
          == 1 and (_ == 44)) or (_root.header.version_index == 2 and (_ == 44)) or (_root.header.version_index == 3 and (_
          == 44)) or (_root.header.version_index == 4 and (_ == 44))) : code == 227 ? ((_root.header.version_index == 1 and
          (_ == 68)) or (_root.header.version_index == 2 and (_ == 68)) or (_root.header.version_index == 3 and (_ == 68))
          or (_root.header.version_index == 4 and (_ == 68))) : code == 139 ? ((_root.header.version_index == 1 and (_ ==
          4)) or (_root.header.version_index == 2 and (_ == 4)) or (_root.header.version_index == 3 and (_ == 4)) or (_root.header.version_index
          == 4 and (_ == 4))) : code == 71 ? ((_root.header.version_index == 1 and (_ == 8)) or (_root.header.version_index
          == 2 and (_ == 8)) or (_root.header.version_index == 3 and (_ == 8)) or (_root.header.version_index == 4 and (_
          == 8))) : code == 187 ? ((_root.header.version_index == 1 and (_ == 0)) or (_root.header.version_index == 2 and
          (_ == 0)) or (_root.header.version_index == 3 and (_ == 0)) or (_root.header.version_index == 4 and (_ == 0))) :
          code == 102 ? ((_root.header.version_index == 1 and (_ == 0)) or (_root.header.version_index == 2 and (_ == 0))
          or (_root.header.version_index == 3 and (_ == 0)) or (_root.header.version_index == 4 and (_ == 0))) : code == 17
          ? ((_root.header.version_index == 1 and (_ == 32)) or (_root.header.version_index == 2 and (_ == 32)) or (_root.header.version_index
          == 3 and (_ == 32)) or (_root.header.version_index == 4 and (_ == 32))) : code == 252 ? ((_root.header.version_index
          == 1 and (_ == 16)) or (_root.header.version_index == 2 and (_ == 16)) or (_root.header.version_index == 3 and (_
          == 16)) or (_root.header.version_index == 4 and (_ == 16))) : code == 85 ? ((_root.header.version_index == 1 and
          (_ == 16 or _ == 32)) or (_root.header.version_index == 2 and (_ == 16 or _ == 32)) or (_root.header.version_index
          == 3 and (_ == 16 or _ == 32)) or (_root.header.version_index == 4 and (_ == 16 or _ == 32))) : code == 90 ? ((_root.header.version_index
          == 1 and (_ == 40)) or (_root.header.version_index == 2 and (_ == 40)) or (_root.header.version_index == 3 and (_
          == 40)) or (_root.header.version_index == 4 and (_ == 40))) : true'
    - id: reserved
      type: u1
      doc: Reserved, should be 0 (N7).
      doc-ref: 300071 rev 03, 4.3
    - id: arg_checksum
      type: u2
      doc: Checksum of command arguments; 6.4.4.
      doc-ref: 300071 rev 03, 4.3
    - id: args
      size: arg_size
      type:
        switch-on: code.as<s4> * 65536 + arg_size.as<s4> * 256 + _root.header.version_index.as<s4>
        cases:
          3936257: args_checkpoint_v1
          3940354: args_checkpoint
          3940355: args_checkpoint
          3940356: args_checkpoint
          10690561: args_cutter_v1
          10690562: args_cutter
          10690563: args_cutter
          10690564: args_cutter
          5773313: args_orient
          5773314: args_orient
          5773315: args_orient
          5773316: args_orient
          5838849: args_orient5b
          5838850: args_orient5b
          5838851: args_orient5b
          5838852: args_orient5b
          2166785: args_phase
          2166786: args_phase
          2166787: args_phase
          2166788: args_phase
          2232321: args_enable_skip
          2232322: args_enable_skip
          2232323: args_enable_skip
          2232324: args_enable_skip
          13174273: args_startshape
          13174274: args_startshape
          13174275: args_startshape
          13174276: args_startshape
          6620673: args_endshape
          6620674: args_endshape
          6620675: args_endshape
          6620676: args_endshape
          2818049: args_decel_off
          2818050: args_decel_off
          2818051: args_decel_off
          2818052: args_decel_off
          5111809: args_decel_on
          5111810: args_decel_on
          5111811: args_decel_on
          5111812: args_decel_on
          3345409: args_point
          3345410: args_point
          3345411: args_point
          3345412: args_point
          11933697: args_line
          11933698: args_line
          11933699: args_line
          11933700: args_line
          12005377: args_line5b
          12005378: args_line5b
          12005379: args_line5b
          12005380: args_line5b
          9708545: args_arc
          9708546: args_arc
          9708547: args_arc
          9708548: args_arc
          9780225: args_arc5b
          9780226: args_arc5b
          9780227: args_arc5b
          9780228: args_arc5b
          8005633: args_circle
          8005634: args_circle
          8005635: args_circle
          8005636: args_circle
          8077313: args_circle5b
          8077314: args_circle5b
          8077315: args_circle5b
          8077316: args_circle5b
          14822401: args_helix
          14822402: args_helix
          14822403: args_helix
          14822404: args_helix
          14894081: args_helix5b
          14894082: args_helix5b
          14894083: args_helix5b
          14894084: args_helix5b
          9110529: args_speed
          9110530: args_speed
          9110531: args_speed
          9110532: args_speed
          4655105: args_accel
          4655106: args_accel
          4655107: args_accel
          4655108: args_accel
          12255233: args_cutter_on
          12255234: args_cutter_on
          12255235: args_cutter_on
          12255236: args_cutter_on
          6684673: args_cutter_off
          6684674: args_cutter_off
          6684675: args_cutter_off
          6684676: args_cutter_off
          1122305: args_guide
          1122306: args_guide
          1122307: args_guide
          1122308: args_guide
          16519169: args_fcparms
          16519170: args_fcparms
          16519171: args_fcparms
          16519172: args_fcparms
          5578753: args_version
          5574657: args_version_implib
          5578754: args_version
          5574658: args_version_implib
          5578755: args_version
          5574659: args_version_implib
          5578756: args_version
          5574660: args_version_implib
          5908481: args_comment
          5908482: args_comment
          5908483: args_comment
          5908484: args_comment
      doc: 'The command''s arguments: the layout of the file''s version whose size matches (for a command the version lacks,
        any of its layouts); raw bytes for an unknown code.'
    instances:
      command:
        value: code
        enum: command
        doc: The command code as the enum (5.2).
  args_checkpoint:
    doc: 'CHECKPOINT: Check-point. Versions 2.x, 3.0, 4.0; 32 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq:
    - id: name
      type: str
      size: 16
      encoding: ISO-8859-1
      pad-right: 0
      doc: Check-point name.
    - id: recovery_point
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: Recovery point. [mm]
    - id: completion
      type: f4
      doc: Completion percentage. [percent]
  args_checkpoint_v1:
    doc: 'CHECKPOINT: Check-point. Versions 1.x; 16 bytes.'
    doc-ref: 300071 rev 03, 7.2.2.2
    seq:
    - id: name
      type: str
      size: 16
      encoding: ISO-8859-1
      pad-right: 0
      doc: Check-point name.
  args_cutter:
    doc: 'CUTTER: Change cutter. Versions 2.x, 3.0, 4.0; 32 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq:
    - id: name
      type: str
      size: 16
      encoding: ISO-8859-1
      pad-right: 0
      doc: Cutter name (part number).
    - id: length
      type: f4
      doc: Cutter length (6.1.2). [mm]
    - id: radius
      type: f4
      doc: Cutter radius (6.1.2). [mm]
    - id: head_length
      type: f4
      doc: Cutter head length (7.2.2.3). [mm]
    - id: reserved
      size: 4
      doc: 4 bytes reserved (N7).
  args_cutter_v1:
    doc: 'CUTTER: Change cutter. Versions 1.x; 32 bytes.'
    doc-ref: 300071 rev 03, 7.2.2.3
    seq:
    - id: name
      type: str
      size: 16
      encoding: ISO-8859-1
      pad-right: 0
      doc: Cutter name (part number).
    - id: length
      type: f4
      doc: Cutter length (6.1.2). [mm]
    - id: radius
      type: f4
      doc: Cutter radius (6.1.2). [mm]
    - id: reserved
      size: 8
      doc: 8 bytes reserved; head length came in 2.0 (7.2.2.3).
  args_orient:
    doc: 'ORIENT: Orientation change. Versions 1.x, 2.x, 3.0, 4.0; 24 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq:
    - id: approach
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: Tool approach.
    - id: reserved
      size: 12
      doc: 'reserved: float(3); kept verbatim (N7).'
  args_orient5b:
    doc: 'ORIENT5B: Orientation change, 5 axis. Versions 1.x, 2.x, 3.0, 4.0; 24 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq:
    - id: start_approach
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: Start approach.
    - id: end_approach
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: End approach.
  args_phase:
    doc: 'PHASE: Cutting phase. Versions 2.x, 3.0, 4.0; 16 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq:
    - id: name
      type: str
      size: 16
      encoding: ISO-8859-1
      pad-right: 0
      doc: Phase name.
  args_enable_skip:
    doc: 'ENABLE_SKIP: Enable skip to phase. Versions 1.x, 2.x, 3.0, 4.0; 16 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq:
    - id: name
      type: str
      size: 16
      encoding: ISO-8859-1
      pad-right: 0
      doc: Name of the phase to skip to.
  args_startshape:
    doc: 'STARTSHAPE: Start of a shape. Versions 1.x, 2.x, 3.0, 4.0; 6 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq:
    - id: name
      type: str
      size: 5
      encoding: ISO-8859-1
      pad-right: 0
      doc: Shape name.
    - id: moves
      type: u1
      doc: Number of (move) commands in the shape. [count]
  args_endshape:
    doc: 'ENDSHAPE: End of a shape; same arguments as STARTSHAPE (redundancy). Versions 1.x, 2.x, 3.0, 4.0; 6 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq:
    - id: name
      type: str
      size: 5
      encoding: ISO-8859-1
      pad-right: 0
      doc: Shape name, as in STARTSHAPE.
    - id: moves
      type: u1
      doc: Number of (move) commands, as in STARTSHAPE. [count]
  args_decel_off:
    doc: 'DECEL_OFF: Turn on motion blending (i.e., don''t decelerate). Versions 2.x, 3.0, 4.0; 0 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq: []
  args_decel_on:
    doc: 'DECEL_ON: Turn off motion blending (i.e., decelerate). Versions 2.x, 3.0, 4.0; 0 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq: []
  args_point:
    doc: 'POINT: Starting goal point. Versions 1.x, 2.x, 3.0, 4.0; 12 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq:
    - id: point
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: Goal point. [mm]
  args_line:
    doc: 'LINE: Straight line motion. Versions 1.x, 2.x, 3.0, 4.0; 24 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq:
    - id: start
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: Start point. [mm]
    - id: end
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: End point. [mm]
  args_line5b:
    doc: 'LINE5B: Straight line motion, 5 axis. Versions 1.x, 2.x, 3.0, 4.0; 48 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq:
    - id: start_pos
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: Start position. [mm]
    - id: end_pos
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: End position. [mm]
    - id: start_orient
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: Start orientation.
    - id: end_orient
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: End orientation.
  args_arc:
    doc: 'ARC: Arc move. Versions 1.x, 2.x, 3.0; 36 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq:
    - id: start
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: Start point. [mm]
    - id: middle
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: A point in the middle of the arc. [mm]
    - id: end
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: End point. [mm]
  args_arc5b:
    doc: 'ARC5B: Arc move, 5 axis. Versions 1.x, 2.x, 3.0; 60 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq:
    - id: start_pos
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: Start position. [mm]
    - id: mid_pos
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: Middle position. [mm]
    - id: end_pos
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: End position. [mm]
    - id: start_orient
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: Start orientation.
    - id: end_orient
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: End orientation.
  args_circle:
    doc: 'CIRCLE: Circle. Versions 1.x, 2.x, 3.0; 40 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq:
    - id: start
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: Start point. [mm]
    - id: center
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: Centre point. [mm]
    - id: normal
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: Axis direction (need not be unit length); rotation by the right-hand rule.
    - id: ndegrees
      type: f4
      doc: Angle swept about the normal. [deg]
  args_circle5b:
    doc: 'CIRCLE5B: Circle, 5 axis. Versions 1.x, 2.x, 3.0; 64 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq:
    - id: start
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: Start point. [mm]
    - id: center
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: Centre point. [mm]
    - id: normal
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: Axis direction (need not be unit length); rotation by the right-hand rule.
    - id: ndegrees
      type: f4
      doc: Angle swept about the normal. [deg]
    - id: start_orient
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: Start orientation.
    - id: end_orient
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: End orientation.
  args_helix:
    doc: 'HELIX: Helix. Versions 2.x, 3.0; 44 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq:
    - id: start
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: Start point. [mm]
    - id: center
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: Centre point. [mm]
    - id: normal
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: Axis direction (need not be unit length); rotation by the right-hand rule.
    - id: ndegrees
      type: f4
      doc: Angle swept about the normal. [deg]
    - id: length
      type: f4
      doc: Axial advance along the unit normal. [mm]
  args_helix5b:
    doc: 'HELIX5B: Helix, 5 axis. Versions 1.x, 2.x, 3.0; 68 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq:
    - id: start
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: Start point. [mm]
    - id: center
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: Centre point. [mm]
    - id: normal
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: Axis direction (need not be unit length); rotation by the right-hand rule.
    - id: ndegrees
      type: f4
      doc: Angle swept about the normal. [deg]
    - id: length
      type: f4
      doc: Axial advance along the unit normal. [mm]
    - id: start_orient
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: Start orientation.
    - id: end_orient
      type: f4
      repeat: expr
      repeat-expr: 3
      doc: End orientation.
  args_speed:
    doc: 'SPEED: Speed. Versions 1.x, 2.x, 3.0, 4.0; 4 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq:
    - id: speed
      type: f4
      doc: Speed. [m/s]
  args_accel:
    doc: 'ACCEL: Acceleration and deceleration. Versions 1.x, 2.x, 3.0, 4.0; 8 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq:
    - id: accel
      type: f4
      doc: Acceleration. [m/s^2]
    - id: decel
      type: f4
      doc: Deceleration. [m/s^2]
  args_cutter_on:
    doc: 'CUTTER_ON: Turn cutter on. Versions 1.x, 2.x, 3.0, 4.0; 0 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq: []
  args_cutter_off:
    doc: 'CUTTER_OFF: Turn cutter off. Versions 1.x, 2.x, 3.0, 4.0; 0 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq: []
  args_guide:
    doc: 'GUIDE: Guide message. Versions 1.x, 2.x, 3.0, 4.0; 32 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq:
    - id: message
      type: str
      size: 32
      encoding: ISO-8859-1
      pad-right: 0
      doc: Message.
  args_fcparms:
    doc: 'FCPARMS: Force control parameters. Versions 2.x, 3.0, 4.0; 16 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq:
    - id: nom_speed
      type: f4
      doc: Nominal speed. [m/s]
    - id: max_speed
      type: f4
      doc: Maximum speed. [m/s]
    - id: min_speed
      type: f4
      doc: Minimum speed. [m/s]
    - id: max_force
      type: f4
      doc: Maximum force. [N]
  args_version:
    doc: 'VERSION: Version numbers. Versions 2.x, 3.0, 4.0; 32 bytes. Default layout (N8); the 16 listed bytes and 16 reserved
      bytes make up the declared 32.'
    doc-ref: 300071 rev 03, 5.1
    seq:
    - id: cutfile
      type: str
      size: 8
      encoding: ISO-8859-1
      pad-right: 0
      doc: Cutfile version.
    - id: format
      type: str
      size: 8
      encoding: ISO-8859-1
      pad-right: 0
      doc: Format version.
    - id: reserved
      size: 16
      doc: Not listed by 5.1; reserved to reach the declared 32 bytes (N8).
  args_version_implib:
    doc: 'VERSION: Version numbers. Versions 2.x, 3.0, 4.0; 16 bytes. Accepted under profile implib. The 16 listed bytes only,
      as implib writes them (N8); accepted under the implib profile.'
    doc-ref: 300071 rev 03, 5.1
    seq:
    - id: cutfile
      type: str
      size: 8
      encoding: ISO-8859-1
      pad-right: 0
      doc: Cutfile version.
    - id: format
      type: str
      size: 8
      encoding: ISO-8859-1
      pad-right: 0
      doc: Format version.
  args_comment:
    doc: 'COMMENT: Comment. Versions 1.x, 2.x, 3.0, 4.0; 40 bytes.'
    doc-ref: 300071 rev 03, 5.1
    seq:
    - id: text
      type: str
      size: 40
      encoding: ISO-8859-1
      pad-right: 0
      doc: Comment text.
enums:
  command:
    17:
      id: guide
      doc: Guide message.
    33:
      id: phase
      doc: Cutting phase.
    34:
      id: enable_skip
      doc: Enable skip to phase.
    43:
      id: decel_off
      doc: Turn on motion blending (i.e., don't decelerate).
    51:
      id: point
      doc: Starting goal point.
    60:
      id: checkpoint
      doc: Check-point.
    71:
      id: accel
      doc: Acceleration and deceleration.
    78:
      id: decel_on
      doc: Turn off motion blending (i.e., decelerate).
    85:
      id: version
      doc: Version numbers.
    88:
      id: orient
      doc: Orientation change.
    89:
      id: orient5b
      doc: Orientation change, 5 axis.
    90:
      id: comment
      doc: Comment.
    101:
      id: endshape
      doc: End of a shape; same arguments as STARTSHAPE (redundancy).
    102:
      id: cutter_off
      doc: Turn cutter off.
    122:
      id: circle
      doc: Circle.
    123:
      id: circle5b
      doc: Circle, 5 axis.
    139:
      id: speed
      doc: Speed.
    148:
      id: arc
      doc: Arc move.
    149:
      id: arc5b
      doc: Arc move, 5 axis.
    163:
      id: cutter
      doc: Change cutter.
    182:
      id: line
      doc: Straight line motion.
    183:
      id: line5b
      doc: Straight line motion, 5 axis.
    187:
      id: cutter_on
      doc: Turn cutter on.
    201:
      id: startshape
      doc: Start of a shape.
    226:
      id: helix
      doc: Helix.
    227:
      id: helix5b
      doc: Helix, 5 axis.
    252:
      id: fcparms
      doc: Force control parameters.
