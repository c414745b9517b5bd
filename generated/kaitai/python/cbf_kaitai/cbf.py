# This is a generated file! Please edit source .ksy file and use kaitai-struct-compiler to rebuild
# type: ignore

import kaitaistruct
from kaitaistruct import KaitaiStruct, KaitaiStream, BytesIO
from enum import IntEnum


if getattr(kaitaistruct, 'API_VERSION', (0, 9)) < (0, 11):
    raise Exception("Incompatible Kaitai Struct Python API: 0.11 or later is required, but you have %s" % (kaitaistruct.__version__))

class Cbf(KaitaiStruct):
    """The CBF file provides the toolpath information for cutting implant cavities with the ROBODOC System (1.1). It carries a 128-byte header and a sequence of variable-length command records. It can be created from, and converted to, an ASCII format, the CUT file (1.2). Generated from spec/cbf.yaml; do not edit. Kaitai checks here the magic numbers, the code copy, the argument size per command and version, and version gating. It cannot check: 4.2 (The file header is 128 bytes long.); 4.3 (The cutting data consists of variable length records.); 6.1.1 (The first word in the Implant Descriptor field in the file header should be the implant part number.); part_number_first (The implant descriptor begins with the implant part number (4.2; 6.1.1 compares it when one is given).); 6.1.2 (The length and radius of every cutter (specified by the CUTTER command) should agree, within 0.01 millimeters, with the values specified in the robot's cutter database.); 6.2.1 (The checksum of the entire file should match the value specified in the file header.); 6.2.2 (The number of commands in the file should match the value specified in the file header.); 6.3.1 (The checksum of the file header should match the specified value.); 6.4.1 (The sequence number should be one greater than the previous sequence number (first record should have sequence number 0).); 6.4.4 (The checksum of the command argument bytes should match the specified value.); 6.4.5 (The starting point of a motion command (e.g., LINE, ARC, CIRCLE, etc.) should match the ending point of the previous motion command.); version_supported (The processing software can read the version number and adjust the parsing logic appropriately.); unknown_command (An unknown command code is an error; its record is kept whole.); trailing_bytes (No byte follows the last record.); reserved_nonzero (The record's reserved byte should be 0.); string_tail (A string ends at its first NUL; the bytes after it are padding.); string_ascii (Strings are ASCII.); non_finite (Floats are finite.); speed_positive (SPEED is greater than 0.); accel_positive (Acceleration and deceleration are greater than 0.); cutter_positive (Cutter length and radius are greater than 0.); normal_nonzero (A circle or helix normal has non-zero length.); checkpoint_range (CHECKPOINT completion lies in 0..100.); checkpoint_falling (CHECKPOINT completion does not fall.); fcparms_order (FCPARMS speeds satisfy min <= nom <= max.); orientation_jump (A 5-axis command starts at the current tool orientation.); machine_limits (Positions lie in the machine's workspace; speeds, accelerations and cutter sizes lie in its ranges.); shape (STARTSHAPE name,n ... ENDSHAPE name,n enclose exactly n motion commands; shapes do not nest.).
    
    .. seealso::
       Specification, Implant Support Software, TCAT, part number 300071, revision 03
    """

    class Command(IntEnum):
        guide = 17
        phase = 33
        enable_skip = 34
        decel_off = 43
        point = 51
        checkpoint = 60
        accel = 71
        decel_on = 78
        version = 85
        orient = 88
        orient5b = 89
        comment = 90
        endshape = 101
        cutter_off = 102
        circle = 122
        circle5b = 123
        speed = 139
        arc = 148
        arc5b = 149
        cutter = 163
        line = 182
        line5b = 183
        cutter_on = 187
        startshape = 201
        helix = 226
        helix5b = 227
        fcparms = 252
    def __init__(self, _io, _parent=None, _root=None):
        super(Cbf, self).__init__(_io)
        self._parent = _parent
        self._root = _root or self
        self._read()

    def _read(self):
        self.header = Cbf.Header(self._io, self, self._root)
        self.records = []
        i = 0
        while not self._io.is_eof():
            self.records.append(Cbf.Record(self._io, self, self._root))
            i += 1



    def _fetch_instances(self):
        pass
        self.header._fetch_instances()
        for i in range(len(self.records)):
            pass
            self.records[i]._fetch_instances()


    class ArgsAccel(KaitaiStruct):
        """ACCEL: Acceleration and deceleration. Versions 1.x, 2.x, 3.0, 4.0; 8 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsAccel, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.accel = self._io.read_f4le()
            self.decel = self._io.read_f4le()


        def _fetch_instances(self):
            pass


    class ArgsArc(KaitaiStruct):
        """ARC: Arc move. Versions 1.x, 2.x, 3.0; 36 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsArc, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.start = []
            for i in range(3):
                self.start.append(self._io.read_f4le())

            self.middle = []
            for i in range(3):
                self.middle.append(self._io.read_f4le())

            self.end = []
            for i in range(3):
                self.end.append(self._io.read_f4le())



        def _fetch_instances(self):
            pass
            for i in range(len(self.start)):
                pass

            for i in range(len(self.middle)):
                pass

            for i in range(len(self.end)):
                pass



    class ArgsArc5b(KaitaiStruct):
        """ARC5B: Arc move, 5 axis. Versions 1.x, 2.x, 3.0; 60 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsArc5b, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.start_pos = []
            for i in range(3):
                self.start_pos.append(self._io.read_f4le())

            self.mid_pos = []
            for i in range(3):
                self.mid_pos.append(self._io.read_f4le())

            self.end_pos = []
            for i in range(3):
                self.end_pos.append(self._io.read_f4le())

            self.start_orient = []
            for i in range(3):
                self.start_orient.append(self._io.read_f4le())

            self.end_orient = []
            for i in range(3):
                self.end_orient.append(self._io.read_f4le())



        def _fetch_instances(self):
            pass
            for i in range(len(self.start_pos)):
                pass

            for i in range(len(self.mid_pos)):
                pass

            for i in range(len(self.end_pos)):
                pass

            for i in range(len(self.start_orient)):
                pass

            for i in range(len(self.end_orient)):
                pass



    class ArgsCheckpoint(KaitaiStruct):
        """CHECKPOINT: Check-point. Versions 2.x, 3.0, 4.0; 32 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsCheckpoint, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.name = (KaitaiStream.bytes_strip_right(self._io.read_bytes(16), 0)).decode(u"ISO-8859-1")
            self.recovery_point = []
            for i in range(3):
                self.recovery_point.append(self._io.read_f4le())

            self.completion = self._io.read_f4le()


        def _fetch_instances(self):
            pass
            for i in range(len(self.recovery_point)):
                pass



    class ArgsCheckpointV1(KaitaiStruct):
        """CHECKPOINT: Check-point. Versions 1.x; 16 bytes.
        
        .. seealso::
           300071 rev 03, 7.2.2.2
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsCheckpointV1, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.name = (KaitaiStream.bytes_strip_right(self._io.read_bytes(16), 0)).decode(u"ISO-8859-1")


        def _fetch_instances(self):
            pass


    class ArgsCircle(KaitaiStruct):
        """CIRCLE: Circle. Versions 1.x, 2.x, 3.0; 40 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsCircle, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.start = []
            for i in range(3):
                self.start.append(self._io.read_f4le())

            self.center = []
            for i in range(3):
                self.center.append(self._io.read_f4le())

            self.normal = []
            for i in range(3):
                self.normal.append(self._io.read_f4le())

            self.ndegrees = self._io.read_f4le()


        def _fetch_instances(self):
            pass
            for i in range(len(self.start)):
                pass

            for i in range(len(self.center)):
                pass

            for i in range(len(self.normal)):
                pass



    class ArgsCircle5b(KaitaiStruct):
        """CIRCLE5B: Circle, 5 axis. Versions 1.x, 2.x, 3.0; 64 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsCircle5b, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.start = []
            for i in range(3):
                self.start.append(self._io.read_f4le())

            self.center = []
            for i in range(3):
                self.center.append(self._io.read_f4le())

            self.normal = []
            for i in range(3):
                self.normal.append(self._io.read_f4le())

            self.ndegrees = self._io.read_f4le()
            self.start_orient = []
            for i in range(3):
                self.start_orient.append(self._io.read_f4le())

            self.end_orient = []
            for i in range(3):
                self.end_orient.append(self._io.read_f4le())



        def _fetch_instances(self):
            pass
            for i in range(len(self.start)):
                pass

            for i in range(len(self.center)):
                pass

            for i in range(len(self.normal)):
                pass

            for i in range(len(self.start_orient)):
                pass

            for i in range(len(self.end_orient)):
                pass



    class ArgsComment(KaitaiStruct):
        """COMMENT: Comment. Versions 1.x, 2.x, 3.0, 4.0; 40 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsComment, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.text = (KaitaiStream.bytes_strip_right(self._io.read_bytes(40), 0)).decode(u"ISO-8859-1")


        def _fetch_instances(self):
            pass


    class ArgsCutter(KaitaiStruct):
        """CUTTER: Change cutter. Versions 2.x, 3.0, 4.0; 32 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsCutter, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.name = (KaitaiStream.bytes_strip_right(self._io.read_bytes(16), 0)).decode(u"ISO-8859-1")
            self.length = self._io.read_f4le()
            self.radius = self._io.read_f4le()
            self.head_length = self._io.read_f4le()
            self.reserved = self._io.read_bytes(4)


        def _fetch_instances(self):
            pass


    class ArgsCutterOff(KaitaiStruct):
        """CUTTER_OFF: Turn cutter off. Versions 1.x, 2.x, 3.0, 4.0; 0 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsCutterOff, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            pass


        def _fetch_instances(self):
            pass


    class ArgsCutterOn(KaitaiStruct):
        """CUTTER_ON: Turn cutter on. Versions 1.x, 2.x, 3.0, 4.0; 0 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsCutterOn, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            pass


        def _fetch_instances(self):
            pass


    class ArgsCutterV1(KaitaiStruct):
        """CUTTER: Change cutter. Versions 1.x; 32 bytes.
        
        .. seealso::
           300071 rev 03, 7.2.2.3
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsCutterV1, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.name = (KaitaiStream.bytes_strip_right(self._io.read_bytes(16), 0)).decode(u"ISO-8859-1")
            self.length = self._io.read_f4le()
            self.radius = self._io.read_f4le()
            self.reserved = self._io.read_bytes(8)


        def _fetch_instances(self):
            pass


    class ArgsDecelOff(KaitaiStruct):
        """DECEL_OFF: Turn on motion blending (i.e., don't decelerate). Versions 2.x, 3.0, 4.0; 0 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsDecelOff, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            pass


        def _fetch_instances(self):
            pass


    class ArgsDecelOn(KaitaiStruct):
        """DECEL_ON: Turn off motion blending (i.e., decelerate). Versions 2.x, 3.0, 4.0; 0 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsDecelOn, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            pass


        def _fetch_instances(self):
            pass


    class ArgsEnableSkip(KaitaiStruct):
        """ENABLE_SKIP: Enable skip to phase. Versions 1.x, 2.x, 3.0, 4.0; 16 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsEnableSkip, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.name = (KaitaiStream.bytes_strip_right(self._io.read_bytes(16), 0)).decode(u"ISO-8859-1")


        def _fetch_instances(self):
            pass


    class ArgsEndshape(KaitaiStruct):
        """ENDSHAPE: End of a shape; same arguments as STARTSHAPE (redundancy). Versions 1.x, 2.x, 3.0, 4.0; 6 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsEndshape, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.name = (KaitaiStream.bytes_strip_right(self._io.read_bytes(5), 0)).decode(u"ISO-8859-1")
            self.moves = self._io.read_u1()


        def _fetch_instances(self):
            pass


    class ArgsFcparms(KaitaiStruct):
        """FCPARMS: Force control parameters. Versions 2.x, 3.0, 4.0; 16 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsFcparms, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.nom_speed = self._io.read_f4le()
            self.max_speed = self._io.read_f4le()
            self.min_speed = self._io.read_f4le()
            self.max_force = self._io.read_f4le()


        def _fetch_instances(self):
            pass


    class ArgsGuide(KaitaiStruct):
        """GUIDE: Guide message. Versions 1.x, 2.x, 3.0, 4.0; 32 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsGuide, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.message = (KaitaiStream.bytes_strip_right(self._io.read_bytes(32), 0)).decode(u"ISO-8859-1")


        def _fetch_instances(self):
            pass


    class ArgsHelix(KaitaiStruct):
        """HELIX: Helix. Versions 2.x, 3.0; 44 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsHelix, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.start = []
            for i in range(3):
                self.start.append(self._io.read_f4le())

            self.center = []
            for i in range(3):
                self.center.append(self._io.read_f4le())

            self.normal = []
            for i in range(3):
                self.normal.append(self._io.read_f4le())

            self.ndegrees = self._io.read_f4le()
            self.length = self._io.read_f4le()


        def _fetch_instances(self):
            pass
            for i in range(len(self.start)):
                pass

            for i in range(len(self.center)):
                pass

            for i in range(len(self.normal)):
                pass



    class ArgsHelix5b(KaitaiStruct):
        """HELIX5B: Helix, 5 axis. Versions 1.x, 2.x, 3.0; 68 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsHelix5b, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.start = []
            for i in range(3):
                self.start.append(self._io.read_f4le())

            self.center = []
            for i in range(3):
                self.center.append(self._io.read_f4le())

            self.normal = []
            for i in range(3):
                self.normal.append(self._io.read_f4le())

            self.ndegrees = self._io.read_f4le()
            self.length = self._io.read_f4le()
            self.start_orient = []
            for i in range(3):
                self.start_orient.append(self._io.read_f4le())

            self.end_orient = []
            for i in range(3):
                self.end_orient.append(self._io.read_f4le())



        def _fetch_instances(self):
            pass
            for i in range(len(self.start)):
                pass

            for i in range(len(self.center)):
                pass

            for i in range(len(self.normal)):
                pass

            for i in range(len(self.start_orient)):
                pass

            for i in range(len(self.end_orient)):
                pass



    class ArgsLine(KaitaiStruct):
        """LINE: Straight line motion. Versions 1.x, 2.x, 3.0, 4.0; 24 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsLine, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.start = []
            for i in range(3):
                self.start.append(self._io.read_f4le())

            self.end = []
            for i in range(3):
                self.end.append(self._io.read_f4le())



        def _fetch_instances(self):
            pass
            for i in range(len(self.start)):
                pass

            for i in range(len(self.end)):
                pass



    class ArgsLine5b(KaitaiStruct):
        """LINE5B: Straight line motion, 5 axis. Versions 1.x, 2.x, 3.0, 4.0; 48 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsLine5b, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.start_pos = []
            for i in range(3):
                self.start_pos.append(self._io.read_f4le())

            self.end_pos = []
            for i in range(3):
                self.end_pos.append(self._io.read_f4le())

            self.start_orient = []
            for i in range(3):
                self.start_orient.append(self._io.read_f4le())

            self.end_orient = []
            for i in range(3):
                self.end_orient.append(self._io.read_f4le())



        def _fetch_instances(self):
            pass
            for i in range(len(self.start_pos)):
                pass

            for i in range(len(self.end_pos)):
                pass

            for i in range(len(self.start_orient)):
                pass

            for i in range(len(self.end_orient)):
                pass



    class ArgsOrient(KaitaiStruct):
        """ORIENT: Orientation change. Versions 1.x, 2.x, 3.0, 4.0; 24 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsOrient, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.approach = []
            for i in range(3):
                self.approach.append(self._io.read_f4le())

            self.reserved = self._io.read_bytes(12)


        def _fetch_instances(self):
            pass
            for i in range(len(self.approach)):
                pass



    class ArgsOrient5b(KaitaiStruct):
        """ORIENT5B: Orientation change, 5 axis. Versions 1.x, 2.x, 3.0, 4.0; 24 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsOrient5b, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.start_approach = []
            for i in range(3):
                self.start_approach.append(self._io.read_f4le())

            self.end_approach = []
            for i in range(3):
                self.end_approach.append(self._io.read_f4le())



        def _fetch_instances(self):
            pass
            for i in range(len(self.start_approach)):
                pass

            for i in range(len(self.end_approach)):
                pass



    class ArgsPhase(KaitaiStruct):
        """PHASE: Cutting phase. Versions 2.x, 3.0, 4.0; 16 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsPhase, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.name = (KaitaiStream.bytes_strip_right(self._io.read_bytes(16), 0)).decode(u"ISO-8859-1")


        def _fetch_instances(self):
            pass


    class ArgsPoint(KaitaiStruct):
        """POINT: Starting goal point. Versions 1.x, 2.x, 3.0, 4.0; 12 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsPoint, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.point = []
            for i in range(3):
                self.point.append(self._io.read_f4le())



        def _fetch_instances(self):
            pass
            for i in range(len(self.point)):
                pass



    class ArgsSpeed(KaitaiStruct):
        """SPEED: Speed. Versions 1.x, 2.x, 3.0, 4.0; 4 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsSpeed, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.speed = self._io.read_f4le()


        def _fetch_instances(self):
            pass


    class ArgsStartshape(KaitaiStruct):
        """STARTSHAPE: Start of a shape. Versions 1.x, 2.x, 3.0, 4.0; 6 bytes.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsStartshape, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.name = (KaitaiStream.bytes_strip_right(self._io.read_bytes(5), 0)).decode(u"ISO-8859-1")
            self.moves = self._io.read_u1()


        def _fetch_instances(self):
            pass


    class ArgsVersion(KaitaiStruct):
        """VERSION: Version numbers. Versions 2.x, 3.0, 4.0; 32 bytes. Default layout (N8); the 16 listed bytes and 16 reserved bytes make up the declared 32.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsVersion, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.cutfile = (KaitaiStream.bytes_strip_right(self._io.read_bytes(8), 0)).decode(u"ISO-8859-1")
            self.format = (KaitaiStream.bytes_strip_right(self._io.read_bytes(8), 0)).decode(u"ISO-8859-1")
            self.reserved = self._io.read_bytes(16)


        def _fetch_instances(self):
            pass


    class ArgsVersionImplib(KaitaiStruct):
        """VERSION: Version numbers. Versions 2.x, 3.0, 4.0; 16 bytes. Accepted under profile implib. The 16 listed bytes only, as implib writes them (N8); accepted under the implib profile.
        
        .. seealso::
           300071 rev 03, 5.1
        """
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.ArgsVersionImplib, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.cutfile = (KaitaiStream.bytes_strip_right(self._io.read_bytes(8), 0)).decode(u"ISO-8859-1")
            self.format = (KaitaiStream.bytes_strip_right(self._io.read_bytes(8), 0)).decode(u"ISO-8859-1")


        def _fetch_instances(self):
            pass


    class Header(KaitaiStruct):
        """File header (4.2); after the version field its layout depends on the version."""
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.Header, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.start_pattern = self._io.read_u4le()
            if not self.start_pattern == 1403107218:
                raise kaitaistruct.ValidationNotEqualError(1403107218, self.start_pattern, self._io, u"/types/header/seq/0")
            self.file_checksum = self._io.read_u4le()
            self.header_checksum = self._io.read_u2le()
            self.reserved_ecc = self._io.read_bytes(6)
            self.version_major = self._io.read_u1()
            self.version_minor = self._io.read_u1()
            _on = self.version_index
            if _on == 1:
                pass
                self.layout = Cbf.HeaderV1(self._io, self, self._root)
            elif _on == 2:
                pass
                self.layout = Cbf.HeaderV2(self._io, self, self._root)
            elif _on == 3:
                pass
                self.layout = Cbf.HeaderV2(self._io, self, self._root)
            elif _on == 4:
                pass
                self.layout = Cbf.HeaderV2(self._io, self, self._root)


        def _fetch_instances(self):
            pass
            _on = self.version_index
            if _on == 1:
                pass
                self.layout._fetch_instances()
            elif _on == 2:
                pass
                self.layout._fetch_instances()
            elif _on == 3:
                pass
                self.layout._fetch_instances()
            elif _on == 4:
                pass
                self.layout._fetch_instances()

        @property
        def version_index(self):
            """1-based index of the spec's version entry (1 = 1.x, 2 = 2.x, 3 = 3.0, 4 = 4.0); unknown versions read as 4.0."""
            if hasattr(self, '_m_version_index'):
                return self._m_version_index

            self._m_version_index = (1 if self.version_major == 1 else (2 if self.version_major == 2 else (3 if  ((self.version_major == 3) and (self.version_minor == 0))  else (4 if  ((self.version_major == 4) and (self.version_minor == 0))  else 4))))
            return getattr(self, '_m_version_index', None)


    class HeaderV1(KaitaiStruct):
        """File header before 7.2.2.1 shortened the implant descriptor."""
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.HeaderV1, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.implant_descriptor = (KaitaiStream.bytes_strip_right(self._io.read_bytes(80), 0)).decode(u"ISO-8859-1")
            self.reserved_98 = self._io.read_bytes(24)
            self.command_count = self._io.read_u2le()
            self.end_pattern = self._io.read_u4le()
            if not self.end_pattern == 2891860077:
                raise kaitaistruct.ValidationNotEqualError(2891860077, self.end_pattern, self._io, u"/types/header_v1/seq/3")


        def _fetch_instances(self):
            pass


    class HeaderV2(KaitaiStruct):
        """File header as 4.2 gives it, with the configuration descriptor of 7.2.2.1."""
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.HeaderV2, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.implant_descriptor = (KaitaiStream.bytes_strip_right(self._io.read_bytes(70), 0)).decode(u"ISO-8859-1")
            self.configuration_descriptor = (KaitaiStream.bytes_strip_right(self._io.read_bytes(34), 0)).decode(u"ISO-8859-1")
            self.command_count = self._io.read_u2le()
            self.end_pattern = self._io.read_u4le()
            if not self.end_pattern == 2891860077:
                raise kaitaistruct.ValidationNotEqualError(2891860077, self.end_pattern, self._io, u"/types/header_v2/seq/3")


        def _fetch_instances(self):
            pass


    class Record(KaitaiStruct):
        """A cutting-data record; the records follow the header back to back. Not expressible here: 6.4.1 (sequence), 6.4.4 (arg_checksum)."""
        def __init__(self, _io, _parent=None, _root=None):
            super(Cbf.Record, self).__init__(_io)
            self._parent = _parent
            self._root = _root
            self._read()

        def _read(self):
            self.sequence = self._io.read_u2le()
            self.code = self._io.read_u1()
            _ = self.code
            if not  (((not ( ((self._root.header.version_index == 4) and ( ((_ == 148) or (_ == 149) or (_ == 122) or (_ == 123) or (_ == 226) or (_ == 227)) )) ))) and ((not ( ((self._root.header.version_index == 1) and ( ((_ == 33) or (_ == 43) or (_ == 78) or (_ == 226) or (_ == 252) or (_ == 85)) )) )))) :
                raise kaitaistruct.ValidationExprError(self.code, self._io, u"/types/record/seq/1")
            self.code_copy = self._io.read_u1()
            _ = self.code_copy
            if not _ == self.code:
                raise kaitaistruct.ValidationExprError(self.code_copy, self._io, u"/types/record/seq/2")
            self.arg_size = self._io.read_u1()
            _ = self.arg_size
            if not ( (( ((self._root.header.version_index == 1) and (_ == 16)) ) or ( ((self._root.header.version_index == 2) and (_ == 32)) ) or ( ((self._root.header.version_index == 3) and (_ == 32)) ) or ( ((self._root.header.version_index == 4) and (_ == 32)) ))  if self.code == 60 else ( (( ((self._root.header.version_index == 1) and (_ == 32)) ) or ( ((self._root.header.version_index == 2) and (_ == 32)) ) or ( ((self._root.header.version_index == 3) and (_ == 32)) ) or ( ((self._root.header.version_index == 4) and (_ == 32)) ))  if self.code == 163 else ( (( ((self._root.header.version_index == 1) and (_ == 24)) ) or ( ((self._root.header.version_index == 2) and (_ == 24)) ) or ( ((self._root.header.version_index == 3) and (_ == 24)) ) or ( ((self._root.header.version_index == 4) and (_ == 24)) ))  if self.code == 88 else ( (( ((self._root.header.version_index == 1) and (_ == 24)) ) or ( ((self._root.header.version_index == 2) and (_ == 24)) ) or ( ((self._root.header.version_index == 3) and (_ == 24)) ) or ( ((self._root.header.version_index == 4) and (_ == 24)) ))  if self.code == 89 else ( (( ((self._root.header.version_index == 1) and (_ == 16)) ) or ( ((self._root.header.version_index == 2) and (_ == 16)) ) or ( ((self._root.header.version_index == 3) and (_ == 16)) ) or ( ((self._root.header.version_index == 4) and (_ == 16)) ))  if self.code == 33 else ( (( ((self._root.header.version_index == 1) and (_ == 16)) ) or ( ((self._root.header.version_index == 2) and (_ == 16)) ) or ( ((self._root.header.version_index == 3) and (_ == 16)) ) or ( ((self._root.header.version_index == 4) and (_ == 16)) ))  if self.code == 34 else ( (( ((self._root.header.version_index == 1) and (_ == 6)) ) or ( ((self._root.header.version_index == 2) and (_ == 6)) ) or ( ((self._root.header.version_index == 3) and (_ == 6)) ) or ( ((self._root.header.version_index == 4) and (_ == 6)) ))  if self.code == 201 else ( (( ((self._root.header.version_index == 1) and (_ == 6)) ) or ( ((self._root.header.version_index == 2) and (_ == 6)) ) or ( ((self._root.header.version_index == 3) and (_ == 6)) ) or ( ((self._root.header.version_index == 4) and (_ == 6)) ))  if self.code == 101 else ( (( ((self._root.header.version_index == 1) and (_ == 0)) ) or ( ((self._root.header.version_index == 2) and (_ == 0)) ) or ( ((self._root.header.version_index == 3) and (_ == 0)) ) or ( ((self._root.header.version_index == 4) and (_ == 0)) ))  if self.code == 43 else ( (( ((self._root.header.version_index == 1) and (_ == 0)) ) or ( ((self._root.header.version_index == 2) and (_ == 0)) ) or ( ((self._root.header.version_index == 3) and (_ == 0)) ) or ( ((self._root.header.version_index == 4) and (_ == 0)) ))  if self.code == 78 else ( (( ((self._root.header.version_index == 1) and (_ == 12)) ) or ( ((self._root.header.version_index == 2) and (_ == 12)) ) or ( ((self._root.header.version_index == 3) and (_ == 12)) ) or ( ((self._root.header.version_index == 4) and (_ == 12)) ))  if self.code == 51 else ( (( ((self._root.header.version_index == 1) and (_ == 24)) ) or ( ((self._root.header.version_index == 2) and (_ == 24)) ) or ( ((self._root.header.version_index == 3) and (_ == 24)) ) or ( ((self._root.header.version_index == 4) and (_ == 24)) ))  if self.code == 182 else ( (( ((self._root.header.version_index == 1) and (_ == 48)) ) or ( ((self._root.header.version_index == 2) and (_ == 48)) ) or ( ((self._root.header.version_index == 3) and (_ == 48)) ) or ( ((self._root.header.version_index == 4) and (_ == 48)) ))  if self.code == 183 else ( (( ((self._root.header.version_index == 1) and (_ == 36)) ) or ( ((self._root.header.version_index == 2) and (_ == 36)) ) or ( ((self._root.header.version_index == 3) and (_ == 36)) ) or ( ((self._root.header.version_index == 4) and (_ == 36)) ))  if self.code == 148 else ( (( ((self._root.header.version_index == 1) and (_ == 60)) ) or ( ((self._root.header.version_index == 2) and (_ == 60)) ) or ( ((self._root.header.version_index == 3) and (_ == 60)) ) or ( ((self._root.header.version_index == 4) and (_ == 60)) ))  if self.code == 149 else ( (( ((self._root.header.version_index == 1) and (_ == 40)) ) or ( ((self._root.header.version_index == 2) and (_ == 40)) ) or ( ((self._root.header.version_index == 3) and (_ == 40)) ) or ( ((self._root.header.version_index == 4) and (_ == 40)) ))  if self.code == 122 else ( (( ((self._root.header.version_index == 1) and (_ == 64)) ) or ( ((self._root.header.version_index == 2) and (_ == 64)) ) or ( ((self._root.header.version_index == 3) and (_ == 64)) ) or ( ((self._root.header.version_index == 4) and (_ == 64)) ))  if self.code == 123 else ( (( ((self._root.header.version_index == 1) and (_ == 44)) ) or ( ((self._root.header.version_index == 2) and (_ == 44)) ) or ( ((self._root.header.version_index == 3) and (_ == 44)) ) or ( ((self._root.header.version_index == 4) and (_ == 44)) ))  if self.code == 226 else ( (( ((self._root.header.version_index == 1) and (_ == 68)) ) or ( ((self._root.header.version_index == 2) and (_ == 68)) ) or ( ((self._root.header.version_index == 3) and (_ == 68)) ) or ( ((self._root.header.version_index == 4) and (_ == 68)) ))  if self.code == 227 else ( (( ((self._root.header.version_index == 1) and (_ == 4)) ) or ( ((self._root.header.version_index == 2) and (_ == 4)) ) or ( ((self._root.header.version_index == 3) and (_ == 4)) ) or ( ((self._root.header.version_index == 4) and (_ == 4)) ))  if self.code == 139 else ( (( ((self._root.header.version_index == 1) and (_ == 8)) ) or ( ((self._root.header.version_index == 2) and (_ == 8)) ) or ( ((self._root.header.version_index == 3) and (_ == 8)) ) or ( ((self._root.header.version_index == 4) and (_ == 8)) ))  if self.code == 71 else ( (( ((self._root.header.version_index == 1) and (_ == 0)) ) or ( ((self._root.header.version_index == 2) and (_ == 0)) ) or ( ((self._root.header.version_index == 3) and (_ == 0)) ) or ( ((self._root.header.version_index == 4) and (_ == 0)) ))  if self.code == 187 else ( (( ((self._root.header.version_index == 1) and (_ == 0)) ) or ( ((self._root.header.version_index == 2) and (_ == 0)) ) or ( ((self._root.header.version_index == 3) and (_ == 0)) ) or ( ((self._root.header.version_index == 4) and (_ == 0)) ))  if self.code == 102 else ( (( ((self._root.header.version_index == 1) and (_ == 32)) ) or ( ((self._root.header.version_index == 2) and (_ == 32)) ) or ( ((self._root.header.version_index == 3) and (_ == 32)) ) or ( ((self._root.header.version_index == 4) and (_ == 32)) ))  if self.code == 17 else ( (( ((self._root.header.version_index == 1) and (_ == 16)) ) or ( ((self._root.header.version_index == 2) and (_ == 16)) ) or ( ((self._root.header.version_index == 3) and (_ == 16)) ) or ( ((self._root.header.version_index == 4) and (_ == 16)) ))  if self.code == 252 else ( (( ((self._root.header.version_index == 1) and ( ((_ == 16) or (_ == 32)) )) ) or ( ((self._root.header.version_index == 2) and ( ((_ == 16) or (_ == 32)) )) ) or ( ((self._root.header.version_index == 3) and ( ((_ == 16) or (_ == 32)) )) ) or ( ((self._root.header.version_index == 4) and ( ((_ == 16) or (_ == 32)) )) ))  if self.code == 85 else ( (( ((self._root.header.version_index == 1) and (_ == 40)) ) or ( ((self._root.header.version_index == 2) and (_ == 40)) ) or ( ((self._root.header.version_index == 3) and (_ == 40)) ) or ( ((self._root.header.version_index == 4) and (_ == 40)) ))  if self.code == 90 else True))))))))))))))))))))))))))):
                raise kaitaistruct.ValidationExprError(self.arg_size, self._io, u"/types/record/seq/3")
            self.reserved = self._io.read_u1()
            self.arg_checksum = self._io.read_u2le()
            _on = (self.code * 65536 + self.arg_size * 256) + self._root.header.version_index
            if _on == 10690561:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsCutterV1(_io__raw_args, self, self._root)
            elif _on == 10690562:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsCutter(_io__raw_args, self, self._root)
            elif _on == 10690563:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsCutter(_io__raw_args, self, self._root)
            elif _on == 10690564:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsCutter(_io__raw_args, self, self._root)
            elif _on == 1122305:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsGuide(_io__raw_args, self, self._root)
            elif _on == 1122306:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsGuide(_io__raw_args, self, self._root)
            elif _on == 1122307:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsGuide(_io__raw_args, self, self._root)
            elif _on == 1122308:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsGuide(_io__raw_args, self, self._root)
            elif _on == 11933697:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsLine(_io__raw_args, self, self._root)
            elif _on == 11933698:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsLine(_io__raw_args, self, self._root)
            elif _on == 11933699:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsLine(_io__raw_args, self, self._root)
            elif _on == 11933700:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsLine(_io__raw_args, self, self._root)
            elif _on == 12005377:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsLine5b(_io__raw_args, self, self._root)
            elif _on == 12005378:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsLine5b(_io__raw_args, self, self._root)
            elif _on == 12005379:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsLine5b(_io__raw_args, self, self._root)
            elif _on == 12005380:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsLine5b(_io__raw_args, self, self._root)
            elif _on == 12255233:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsCutterOn(_io__raw_args, self, self._root)
            elif _on == 12255234:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsCutterOn(_io__raw_args, self, self._root)
            elif _on == 12255235:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsCutterOn(_io__raw_args, self, self._root)
            elif _on == 12255236:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsCutterOn(_io__raw_args, self, self._root)
            elif _on == 13174273:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsStartshape(_io__raw_args, self, self._root)
            elif _on == 13174274:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsStartshape(_io__raw_args, self, self._root)
            elif _on == 13174275:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsStartshape(_io__raw_args, self, self._root)
            elif _on == 13174276:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsStartshape(_io__raw_args, self, self._root)
            elif _on == 14822401:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsHelix(_io__raw_args, self, self._root)
            elif _on == 14822402:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsHelix(_io__raw_args, self, self._root)
            elif _on == 14822403:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsHelix(_io__raw_args, self, self._root)
            elif _on == 14822404:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsHelix(_io__raw_args, self, self._root)
            elif _on == 14894081:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsHelix5b(_io__raw_args, self, self._root)
            elif _on == 14894082:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsHelix5b(_io__raw_args, self, self._root)
            elif _on == 14894083:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsHelix5b(_io__raw_args, self, self._root)
            elif _on == 14894084:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsHelix5b(_io__raw_args, self, self._root)
            elif _on == 16519169:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsFcparms(_io__raw_args, self, self._root)
            elif _on == 16519170:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsFcparms(_io__raw_args, self, self._root)
            elif _on == 16519171:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsFcparms(_io__raw_args, self, self._root)
            elif _on == 16519172:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsFcparms(_io__raw_args, self, self._root)
            elif _on == 2166785:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsPhase(_io__raw_args, self, self._root)
            elif _on == 2166786:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsPhase(_io__raw_args, self, self._root)
            elif _on == 2166787:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsPhase(_io__raw_args, self, self._root)
            elif _on == 2166788:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsPhase(_io__raw_args, self, self._root)
            elif _on == 2232321:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsEnableSkip(_io__raw_args, self, self._root)
            elif _on == 2232322:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsEnableSkip(_io__raw_args, self, self._root)
            elif _on == 2232323:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsEnableSkip(_io__raw_args, self, self._root)
            elif _on == 2232324:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsEnableSkip(_io__raw_args, self, self._root)
            elif _on == 2818049:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsDecelOff(_io__raw_args, self, self._root)
            elif _on == 2818050:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsDecelOff(_io__raw_args, self, self._root)
            elif _on == 2818051:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsDecelOff(_io__raw_args, self, self._root)
            elif _on == 2818052:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsDecelOff(_io__raw_args, self, self._root)
            elif _on == 3345409:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsPoint(_io__raw_args, self, self._root)
            elif _on == 3345410:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsPoint(_io__raw_args, self, self._root)
            elif _on == 3345411:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsPoint(_io__raw_args, self, self._root)
            elif _on == 3345412:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsPoint(_io__raw_args, self, self._root)
            elif _on == 3936257:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsCheckpointV1(_io__raw_args, self, self._root)
            elif _on == 3940354:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsCheckpoint(_io__raw_args, self, self._root)
            elif _on == 3940355:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsCheckpoint(_io__raw_args, self, self._root)
            elif _on == 3940356:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsCheckpoint(_io__raw_args, self, self._root)
            elif _on == 4655105:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsAccel(_io__raw_args, self, self._root)
            elif _on == 4655106:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsAccel(_io__raw_args, self, self._root)
            elif _on == 4655107:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsAccel(_io__raw_args, self, self._root)
            elif _on == 4655108:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsAccel(_io__raw_args, self, self._root)
            elif _on == 5111809:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsDecelOn(_io__raw_args, self, self._root)
            elif _on == 5111810:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsDecelOn(_io__raw_args, self, self._root)
            elif _on == 5111811:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsDecelOn(_io__raw_args, self, self._root)
            elif _on == 5111812:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsDecelOn(_io__raw_args, self, self._root)
            elif _on == 5574657:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsVersionImplib(_io__raw_args, self, self._root)
            elif _on == 5574658:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsVersionImplib(_io__raw_args, self, self._root)
            elif _on == 5574659:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsVersionImplib(_io__raw_args, self, self._root)
            elif _on == 5574660:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsVersionImplib(_io__raw_args, self, self._root)
            elif _on == 5578753:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsVersion(_io__raw_args, self, self._root)
            elif _on == 5578754:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsVersion(_io__raw_args, self, self._root)
            elif _on == 5578755:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsVersion(_io__raw_args, self, self._root)
            elif _on == 5578756:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsVersion(_io__raw_args, self, self._root)
            elif _on == 5773313:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsOrient(_io__raw_args, self, self._root)
            elif _on == 5773314:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsOrient(_io__raw_args, self, self._root)
            elif _on == 5773315:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsOrient(_io__raw_args, self, self._root)
            elif _on == 5773316:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsOrient(_io__raw_args, self, self._root)
            elif _on == 5838849:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsOrient5b(_io__raw_args, self, self._root)
            elif _on == 5838850:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsOrient5b(_io__raw_args, self, self._root)
            elif _on == 5838851:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsOrient5b(_io__raw_args, self, self._root)
            elif _on == 5838852:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsOrient5b(_io__raw_args, self, self._root)
            elif _on == 5908481:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsComment(_io__raw_args, self, self._root)
            elif _on == 5908482:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsComment(_io__raw_args, self, self._root)
            elif _on == 5908483:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsComment(_io__raw_args, self, self._root)
            elif _on == 5908484:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsComment(_io__raw_args, self, self._root)
            elif _on == 6620673:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsEndshape(_io__raw_args, self, self._root)
            elif _on == 6620674:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsEndshape(_io__raw_args, self, self._root)
            elif _on == 6620675:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsEndshape(_io__raw_args, self, self._root)
            elif _on == 6620676:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsEndshape(_io__raw_args, self, self._root)
            elif _on == 6684673:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsCutterOff(_io__raw_args, self, self._root)
            elif _on == 6684674:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsCutterOff(_io__raw_args, self, self._root)
            elif _on == 6684675:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsCutterOff(_io__raw_args, self, self._root)
            elif _on == 6684676:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsCutterOff(_io__raw_args, self, self._root)
            elif _on == 8005633:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsCircle(_io__raw_args, self, self._root)
            elif _on == 8005634:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsCircle(_io__raw_args, self, self._root)
            elif _on == 8005635:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsCircle(_io__raw_args, self, self._root)
            elif _on == 8005636:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsCircle(_io__raw_args, self, self._root)
            elif _on == 8077313:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsCircle5b(_io__raw_args, self, self._root)
            elif _on == 8077314:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsCircle5b(_io__raw_args, self, self._root)
            elif _on == 8077315:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsCircle5b(_io__raw_args, self, self._root)
            elif _on == 8077316:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsCircle5b(_io__raw_args, self, self._root)
            elif _on == 9110529:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsSpeed(_io__raw_args, self, self._root)
            elif _on == 9110530:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsSpeed(_io__raw_args, self, self._root)
            elif _on == 9110531:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsSpeed(_io__raw_args, self, self._root)
            elif _on == 9110532:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsSpeed(_io__raw_args, self, self._root)
            elif _on == 9708545:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsArc(_io__raw_args, self, self._root)
            elif _on == 9708546:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsArc(_io__raw_args, self, self._root)
            elif _on == 9708547:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsArc(_io__raw_args, self, self._root)
            elif _on == 9708548:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsArc(_io__raw_args, self, self._root)
            elif _on == 9780225:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsArc5b(_io__raw_args, self, self._root)
            elif _on == 9780226:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsArc5b(_io__raw_args, self, self._root)
            elif _on == 9780227:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsArc5b(_io__raw_args, self, self._root)
            elif _on == 9780228:
                pass
                self._raw_args = self._io.read_bytes(self.arg_size)
                _io__raw_args = KaitaiStream(BytesIO(self._raw_args))
                self.args = Cbf.ArgsArc5b(_io__raw_args, self, self._root)
            else:
                pass
                self.args = self._io.read_bytes(self.arg_size)


        def _fetch_instances(self):
            pass
            _on = (self.code * 65536 + self.arg_size * 256) + self._root.header.version_index
            if _on == 10690561:
                pass
                self.args._fetch_instances()
            elif _on == 10690562:
                pass
                self.args._fetch_instances()
            elif _on == 10690563:
                pass
                self.args._fetch_instances()
            elif _on == 10690564:
                pass
                self.args._fetch_instances()
            elif _on == 1122305:
                pass
                self.args._fetch_instances()
            elif _on == 1122306:
                pass
                self.args._fetch_instances()
            elif _on == 1122307:
                pass
                self.args._fetch_instances()
            elif _on == 1122308:
                pass
                self.args._fetch_instances()
            elif _on == 11933697:
                pass
                self.args._fetch_instances()
            elif _on == 11933698:
                pass
                self.args._fetch_instances()
            elif _on == 11933699:
                pass
                self.args._fetch_instances()
            elif _on == 11933700:
                pass
                self.args._fetch_instances()
            elif _on == 12005377:
                pass
                self.args._fetch_instances()
            elif _on == 12005378:
                pass
                self.args._fetch_instances()
            elif _on == 12005379:
                pass
                self.args._fetch_instances()
            elif _on == 12005380:
                pass
                self.args._fetch_instances()
            elif _on == 12255233:
                pass
                self.args._fetch_instances()
            elif _on == 12255234:
                pass
                self.args._fetch_instances()
            elif _on == 12255235:
                pass
                self.args._fetch_instances()
            elif _on == 12255236:
                pass
                self.args._fetch_instances()
            elif _on == 13174273:
                pass
                self.args._fetch_instances()
            elif _on == 13174274:
                pass
                self.args._fetch_instances()
            elif _on == 13174275:
                pass
                self.args._fetch_instances()
            elif _on == 13174276:
                pass
                self.args._fetch_instances()
            elif _on == 14822401:
                pass
                self.args._fetch_instances()
            elif _on == 14822402:
                pass
                self.args._fetch_instances()
            elif _on == 14822403:
                pass
                self.args._fetch_instances()
            elif _on == 14822404:
                pass
                self.args._fetch_instances()
            elif _on == 14894081:
                pass
                self.args._fetch_instances()
            elif _on == 14894082:
                pass
                self.args._fetch_instances()
            elif _on == 14894083:
                pass
                self.args._fetch_instances()
            elif _on == 14894084:
                pass
                self.args._fetch_instances()
            elif _on == 16519169:
                pass
                self.args._fetch_instances()
            elif _on == 16519170:
                pass
                self.args._fetch_instances()
            elif _on == 16519171:
                pass
                self.args._fetch_instances()
            elif _on == 16519172:
                pass
                self.args._fetch_instances()
            elif _on == 2166785:
                pass
                self.args._fetch_instances()
            elif _on == 2166786:
                pass
                self.args._fetch_instances()
            elif _on == 2166787:
                pass
                self.args._fetch_instances()
            elif _on == 2166788:
                pass
                self.args._fetch_instances()
            elif _on == 2232321:
                pass
                self.args._fetch_instances()
            elif _on == 2232322:
                pass
                self.args._fetch_instances()
            elif _on == 2232323:
                pass
                self.args._fetch_instances()
            elif _on == 2232324:
                pass
                self.args._fetch_instances()
            elif _on == 2818049:
                pass
                self.args._fetch_instances()
            elif _on == 2818050:
                pass
                self.args._fetch_instances()
            elif _on == 2818051:
                pass
                self.args._fetch_instances()
            elif _on == 2818052:
                pass
                self.args._fetch_instances()
            elif _on == 3345409:
                pass
                self.args._fetch_instances()
            elif _on == 3345410:
                pass
                self.args._fetch_instances()
            elif _on == 3345411:
                pass
                self.args._fetch_instances()
            elif _on == 3345412:
                pass
                self.args._fetch_instances()
            elif _on == 3936257:
                pass
                self.args._fetch_instances()
            elif _on == 3940354:
                pass
                self.args._fetch_instances()
            elif _on == 3940355:
                pass
                self.args._fetch_instances()
            elif _on == 3940356:
                pass
                self.args._fetch_instances()
            elif _on == 4655105:
                pass
                self.args._fetch_instances()
            elif _on == 4655106:
                pass
                self.args._fetch_instances()
            elif _on == 4655107:
                pass
                self.args._fetch_instances()
            elif _on == 4655108:
                pass
                self.args._fetch_instances()
            elif _on == 5111809:
                pass
                self.args._fetch_instances()
            elif _on == 5111810:
                pass
                self.args._fetch_instances()
            elif _on == 5111811:
                pass
                self.args._fetch_instances()
            elif _on == 5111812:
                pass
                self.args._fetch_instances()
            elif _on == 5574657:
                pass
                self.args._fetch_instances()
            elif _on == 5574658:
                pass
                self.args._fetch_instances()
            elif _on == 5574659:
                pass
                self.args._fetch_instances()
            elif _on == 5574660:
                pass
                self.args._fetch_instances()
            elif _on == 5578753:
                pass
                self.args._fetch_instances()
            elif _on == 5578754:
                pass
                self.args._fetch_instances()
            elif _on == 5578755:
                pass
                self.args._fetch_instances()
            elif _on == 5578756:
                pass
                self.args._fetch_instances()
            elif _on == 5773313:
                pass
                self.args._fetch_instances()
            elif _on == 5773314:
                pass
                self.args._fetch_instances()
            elif _on == 5773315:
                pass
                self.args._fetch_instances()
            elif _on == 5773316:
                pass
                self.args._fetch_instances()
            elif _on == 5838849:
                pass
                self.args._fetch_instances()
            elif _on == 5838850:
                pass
                self.args._fetch_instances()
            elif _on == 5838851:
                pass
                self.args._fetch_instances()
            elif _on == 5838852:
                pass
                self.args._fetch_instances()
            elif _on == 5908481:
                pass
                self.args._fetch_instances()
            elif _on == 5908482:
                pass
                self.args._fetch_instances()
            elif _on == 5908483:
                pass
                self.args._fetch_instances()
            elif _on == 5908484:
                pass
                self.args._fetch_instances()
            elif _on == 6620673:
                pass
                self.args._fetch_instances()
            elif _on == 6620674:
                pass
                self.args._fetch_instances()
            elif _on == 6620675:
                pass
                self.args._fetch_instances()
            elif _on == 6620676:
                pass
                self.args._fetch_instances()
            elif _on == 6684673:
                pass
                self.args._fetch_instances()
            elif _on == 6684674:
                pass
                self.args._fetch_instances()
            elif _on == 6684675:
                pass
                self.args._fetch_instances()
            elif _on == 6684676:
                pass
                self.args._fetch_instances()
            elif _on == 8005633:
                pass
                self.args._fetch_instances()
            elif _on == 8005634:
                pass
                self.args._fetch_instances()
            elif _on == 8005635:
                pass
                self.args._fetch_instances()
            elif _on == 8005636:
                pass
                self.args._fetch_instances()
            elif _on == 8077313:
                pass
                self.args._fetch_instances()
            elif _on == 8077314:
                pass
                self.args._fetch_instances()
            elif _on == 8077315:
                pass
                self.args._fetch_instances()
            elif _on == 8077316:
                pass
                self.args._fetch_instances()
            elif _on == 9110529:
                pass
                self.args._fetch_instances()
            elif _on == 9110530:
                pass
                self.args._fetch_instances()
            elif _on == 9110531:
                pass
                self.args._fetch_instances()
            elif _on == 9110532:
                pass
                self.args._fetch_instances()
            elif _on == 9708545:
                pass
                self.args._fetch_instances()
            elif _on == 9708546:
                pass
                self.args._fetch_instances()
            elif _on == 9708547:
                pass
                self.args._fetch_instances()
            elif _on == 9708548:
                pass
                self.args._fetch_instances()
            elif _on == 9780225:
                pass
                self.args._fetch_instances()
            elif _on == 9780226:
                pass
                self.args._fetch_instances()
            elif _on == 9780227:
                pass
                self.args._fetch_instances()
            elif _on == 9780228:
                pass
                self.args._fetch_instances()
            else:
                pass

        @property
        def command(self):
            """The command code as the enum (5.2)."""
            if hasattr(self, '_m_command'):
                return self._m_command

            self._m_command = KaitaiStream.resolve_enum(Cbf.Command, self.code)
            return getattr(self, '_m_command', None)



