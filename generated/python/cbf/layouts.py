"""Typed layouts of Cutfile Binary Format (300071 rev 03).

Generated from spec/cbf.yaml by cbfgen; do not edit. One frozen dataclass
per header layout and per command layout, and the command codes as an
IntEnum (5.2).
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import IntEnum
from typing import ClassVar


class CommandCode(IntEnum):
    """Symbolic names of the command codes (5.2) with their hex values (5.1)."""

    GUIDE = 0x11
    """Guide message."""
    PHASE = 0x21
    """Cutting phase."""
    ENABLE_SKIP = 0x22
    """Enable skip to phase."""
    DECEL_OFF = 0x2B
    """Turn on motion blending (i.e., don't decelerate)."""
    POINT = 0x33
    """Starting goal point."""
    CHECKPOINT = 0x3C
    """Check-point."""
    ACCEL = 0x47
    """Acceleration and deceleration."""
    DECEL_ON = 0x4E
    """Turn off motion blending (i.e., decelerate)."""
    VERSION = 0x55
    """Version numbers."""
    ORIENT = 0x58
    """Orientation change."""
    ORIENT5B = 0x59
    """Orientation change, 5 axis."""
    COMMENT = 0x5A
    """Comment."""
    ENDSHAPE = 0x65
    """End of a shape; same arguments as STARTSHAPE (redundancy)."""
    CUTTER_OFF = 0x66
    """Turn cutter off."""
    CIRCLE = 0x7A
    """Circle."""
    CIRCLE5B = 0x7B
    """Circle, 5 axis."""
    SPEED = 0x8B
    """Speed."""
    ARC = 0x94
    """Arc move."""
    ARC5B = 0x95
    """Arc move, 5 axis."""
    CUTTER = 0xA3
    """Change cutter."""
    LINE = 0xB6
    """Straight line motion."""
    LINE5B = 0xB7
    """Straight line motion, 5 axis."""
    CUTTER_ON = 0xBB
    """Turn cutter on."""
    STARTSHAPE = 0xC9
    """Start of a shape."""
    HELIX = 0xE2
    """Helix."""
    HELIX5B = 0xE3
    """Helix, 5 axis."""
    FCPARMS = 0xFC
    """Force control parameters."""


@dataclass(frozen=True, slots=True, kw_only=True)
class HeaderV2:
    """File header as 4.2 gives it, with the configuration descriptor of 7.2.2.1.

    128 bytes (4.2).
    """

    LAYOUT: ClassVar[str] = "v2"
    start_pattern: int
    """Special pattern indicating cutting file (N5, bytes 92 B7 A1 53). Offset 0, u4. (4.2)"""
    file_checksum: int
    """Checksum for entire file (starting at byte 8). Offset 4, u4. (4.2)"""
    header_checksum: int
    """Checksum for rest of header. Offset 8, u2. (4.2)"""
    reserved_ecc: bytes
    """Reserved for future checksum usage (Error Correcting Codes); kept verbatim (N7). Offset 10, bytes(6). (4.2)"""
    version_major: int
    """Version number for cutfile format, major (N3). Offset 16, u1. (4.2)"""
    version_minor: int
    """Version number for cutfile format, minor (N3). Offset 17, u1. (4.2)"""
    implant_descriptor: str
    """Implant descriptor (part number, manufacturer, type, size); the part number must be the first item (6.1.1). Offset 18, str(70). (4.2)"""
    configuration_descriptor: str
    """Configuration descriptor; the field 7.2.2.1 made of the 1.x reserved bytes. Offset 88, str(34). (4.2)"""
    command_count: int
    """Number of commands in cutting data section (6.2.2). Offset 122, u2. (4.2)"""
    end_pattern: int
    """Special pattern indicating end of header, the complement of the start pattern (N5, bytes 6D 48 5E AC). Offset 124, u4. (4.2)"""

@dataclass(frozen=True, slots=True, kw_only=True)
class HeaderV1:
    """File header before 7.2.2.1 shortened the implant descriptor.

    128 bytes (7.2.2.1).
    """

    LAYOUT: ClassVar[str] = "v1"
    start_pattern: int
    """Special pattern indicating cutting file. Offset 0, u4. (4.2)"""
    file_checksum: int
    """Checksum for entire file (starting at byte 8). Offset 4, u4. (4.2)"""
    header_checksum: int
    """Checksum for rest of header. Offset 8, u2. (4.2)"""
    reserved_ecc: bytes
    """Reserved for future checksum usage; kept verbatim (N7). Offset 10, bytes(6). (4.2)"""
    version_major: int
    """Version number, major (N3). Offset 16, u1. (4.2)"""
    version_minor: int
    """Version number, minor (N3). Offset 17, u1. (4.2)"""
    implant_descriptor: str
    """Implant descriptor of 80 bytes (1.x). Offset 18, str(80). (7.2.2.1)"""
    reserved_98: bytes
    """Reserved field at offset 98 (1.x); renamed Configuration Descriptor in 2.0. Offset 98, bytes(24). (7.2.2.1)"""
    command_count: int
    """Number of commands in cutting data section. Offset 122, u2. (4.2)"""
    end_pattern: int
    """Complement of the start pattern (N5). Offset 124, u4. (4.2)"""

HEADER_CLASSES: dict[str, type] = {
    "v2": HeaderV2,
    "v1": HeaderV1,
}


@dataclass(frozen=True, slots=True, kw_only=True)
class Checkpoint:
    """CHECKPOINT (0x3C): Check-point.

    Versions 2.x, 3.0, 4.0; 32 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0x3C
    NAME: ClassVar[str] = "CHECKPOINT"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 32
    name: str
    """Check-point name. Offset 0, str(16)."""
    recovery_point: tuple[float, float, float]
    """Recovery point. [mm] Offset 16, f4(3)."""
    completion: float
    """Completion percentage. [percent] Offset 28, f4."""


@dataclass(frozen=True, slots=True, kw_only=True)
class CheckpointV1:
    """CHECKPOINT (0x3C): Check-point.

    Versions 1.x; 16 argument bytes (7.2.2.2).
    """

    CODE: ClassVar[int] = 0x3C
    NAME: ClassVar[str] = "CHECKPOINT"
    VARIANT: ClassVar[str] = "v1"
    SIZE: ClassVar[int] = 16
    name: str
    """Check-point name. Offset 0, str(16)."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Cutter:
    """CUTTER (0xA3): Change cutter.

    Versions 2.x, 3.0, 4.0; 32 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0xA3
    NAME: ClassVar[str] = "CUTTER"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 32
    name: str
    """Cutter name (part number). Offset 0, str(16)."""
    length: float
    """Cutter length (6.1.2). [mm] Offset 16, f4."""
    radius: float
    """Cutter radius (6.1.2). [mm] Offset 20, f4."""
    head_length: float
    """Cutter head length (7.2.2.3). [mm] Offset 24, f4."""
    reserved: bytes = bytes(4)
    """4 bytes reserved (N7). Offset 28, bytes(4)."""


@dataclass(frozen=True, slots=True, kw_only=True)
class CutterV1:
    """CUTTER (0xA3): Change cutter.

    Versions 1.x; 32 argument bytes (7.2.2.3).
    """

    CODE: ClassVar[int] = 0xA3
    NAME: ClassVar[str] = "CUTTER"
    VARIANT: ClassVar[str] = "v1"
    SIZE: ClassVar[int] = 32
    name: str
    """Cutter name (part number). Offset 0, str(16)."""
    length: float
    """Cutter length (6.1.2). [mm] Offset 16, f4."""
    radius: float
    """Cutter radius (6.1.2). [mm] Offset 20, f4."""
    reserved: bytes = bytes(8)
    """8 bytes reserved; head length came in 2.0 (7.2.2.3). Offset 24, bytes(8)."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Orient:
    """ORIENT (0x58): Orientation change.

    Versions 1.x, 2.x, 3.0, 4.0; 24 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0x58
    NAME: ClassVar[str] = "ORIENT"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 24
    approach: tuple[float, float, float]
    """Tool approach. Offset 0, f4(3)."""
    reserved: bytes = bytes(12)
    """reserved: float(3); kept verbatim (N7). Offset 12, bytes(12)."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Orient5b:
    """ORIENT5B (0x59): Orientation change, 5 axis.

    Versions 1.x, 2.x, 3.0, 4.0; 24 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0x59
    NAME: ClassVar[str] = "ORIENT5B"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 24
    start_approach: tuple[float, float, float]
    """Start approach. Offset 0, f4(3)."""
    end_approach: tuple[float, float, float]
    """End approach. Offset 12, f4(3)."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Phase:
    """PHASE (0x21): Cutting phase.

    Versions 2.x, 3.0, 4.0; 16 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0x21
    NAME: ClassVar[str] = "PHASE"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 16
    name: str
    """Phase name. Offset 0, str(16)."""


@dataclass(frozen=True, slots=True, kw_only=True)
class EnableSkip:
    """ENABLE_SKIP (0x22): Enable skip to phase.

    Versions 1.x, 2.x, 3.0, 4.0; 16 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0x22
    NAME: ClassVar[str] = "ENABLE_SKIP"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 16
    name: str
    """Name of the phase to skip to. Offset 0, str(16)."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Startshape:
    """STARTSHAPE (0xC9): Start of a shape.

    Versions 1.x, 2.x, 3.0, 4.0; 6 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0xC9
    NAME: ClassVar[str] = "STARTSHAPE"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 6
    name: str
    """Shape name. Offset 0, str(5)."""
    moves: int
    """Number of (move) commands in the shape. [count] Offset 5, u1."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Endshape:
    """ENDSHAPE (0x65): End of a shape; same arguments as STARTSHAPE (redundancy).

    Versions 1.x, 2.x, 3.0, 4.0; 6 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0x65
    NAME: ClassVar[str] = "ENDSHAPE"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 6
    name: str
    """Shape name, as in STARTSHAPE. Offset 0, str(5)."""
    moves: int
    """Number of (move) commands, as in STARTSHAPE. [count] Offset 5, u1."""


@dataclass(frozen=True, slots=True, kw_only=True)
class DecelOff:
    """DECEL_OFF (0x2B): Turn on motion blending (i.e., don't decelerate).

    Versions 2.x, 3.0, 4.0; 0 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0x2B
    NAME: ClassVar[str] = "DECEL_OFF"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 0


@dataclass(frozen=True, slots=True, kw_only=True)
class DecelOn:
    """DECEL_ON (0x4E): Turn off motion blending (i.e., decelerate).

    Versions 2.x, 3.0, 4.0; 0 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0x4E
    NAME: ClassVar[str] = "DECEL_ON"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 0


@dataclass(frozen=True, slots=True, kw_only=True)
class Point:
    """POINT (0x33): Starting goal point.

    Versions 1.x, 2.x, 3.0, 4.0; 12 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0x33
    NAME: ClassVar[str] = "POINT"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 12
    point: tuple[float, float, float]
    """Goal point. [mm] Offset 0, f4(3)."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Line:
    """LINE (0xB6): Straight line motion.

    Versions 1.x, 2.x, 3.0, 4.0; 24 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0xB6
    NAME: ClassVar[str] = "LINE"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 24
    start: tuple[float, float, float]
    """Start point. [mm] Offset 0, f4(3)."""
    end: tuple[float, float, float]
    """End point. [mm] Offset 12, f4(3)."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Line5b:
    """LINE5B (0xB7): Straight line motion, 5 axis.

    Versions 1.x, 2.x, 3.0, 4.0; 48 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0xB7
    NAME: ClassVar[str] = "LINE5B"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 48
    start_pos: tuple[float, float, float]
    """Start position. [mm] Offset 0, f4(3)."""
    end_pos: tuple[float, float, float]
    """End position. [mm] Offset 12, f4(3)."""
    start_orient: tuple[float, float, float]
    """Start orientation. Offset 24, f4(3)."""
    end_orient: tuple[float, float, float]
    """End orientation. Offset 36, f4(3)."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Arc:
    """ARC (0x94): Arc move.

    Versions 1.x, 2.x, 3.0; 36 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0x94
    NAME: ClassVar[str] = "ARC"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 36
    start: tuple[float, float, float]
    """Start point. [mm] Offset 0, f4(3)."""
    middle: tuple[float, float, float]
    """A point in the middle of the arc. [mm] Offset 12, f4(3)."""
    end: tuple[float, float, float]
    """End point. [mm] Offset 24, f4(3)."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Arc5b:
    """ARC5B (0x95): Arc move, 5 axis.

    Versions 1.x, 2.x, 3.0; 60 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0x95
    NAME: ClassVar[str] = "ARC5B"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 60
    start_pos: tuple[float, float, float]
    """Start position. [mm] Offset 0, f4(3)."""
    mid_pos: tuple[float, float, float]
    """Middle position. [mm] Offset 12, f4(3)."""
    end_pos: tuple[float, float, float]
    """End position. [mm] Offset 24, f4(3)."""
    start_orient: tuple[float, float, float]
    """Start orientation. Offset 36, f4(3)."""
    end_orient: tuple[float, float, float]
    """End orientation. Offset 48, f4(3)."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Circle:
    """CIRCLE (0x7A): Circle.

    Versions 1.x, 2.x, 3.0; 40 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0x7A
    NAME: ClassVar[str] = "CIRCLE"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 40
    start: tuple[float, float, float]
    """Start point. [mm] Offset 0, f4(3)."""
    center: tuple[float, float, float]
    """Centre point. [mm] Offset 12, f4(3)."""
    normal: tuple[float, float, float]
    """Axis direction (need not be unit length); rotation by the right-hand rule. Offset 24, f4(3)."""
    ndegrees: float
    """Angle swept about the normal. [deg] Offset 36, f4."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Circle5b:
    """CIRCLE5B (0x7B): Circle, 5 axis.

    Versions 1.x, 2.x, 3.0; 64 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0x7B
    NAME: ClassVar[str] = "CIRCLE5B"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 64
    start: tuple[float, float, float]
    """Start point. [mm] Offset 0, f4(3)."""
    center: tuple[float, float, float]
    """Centre point. [mm] Offset 12, f4(3)."""
    normal: tuple[float, float, float]
    """Axis direction (need not be unit length); rotation by the right-hand rule. Offset 24, f4(3)."""
    ndegrees: float
    """Angle swept about the normal. [deg] Offset 36, f4."""
    start_orient: tuple[float, float, float]
    """Start orientation. Offset 40, f4(3)."""
    end_orient: tuple[float, float, float]
    """End orientation. Offset 52, f4(3)."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Helix:
    """HELIX (0xE2): Helix.

    Versions 2.x, 3.0; 44 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0xE2
    NAME: ClassVar[str] = "HELIX"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 44
    start: tuple[float, float, float]
    """Start point. [mm] Offset 0, f4(3)."""
    center: tuple[float, float, float]
    """Centre point. [mm] Offset 12, f4(3)."""
    normal: tuple[float, float, float]
    """Axis direction (need not be unit length); rotation by the right-hand rule. Offset 24, f4(3)."""
    ndegrees: float
    """Angle swept about the normal. [deg] Offset 36, f4."""
    length: float
    """Axial advance along the unit normal. [mm] Offset 40, f4."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Helix5b:
    """HELIX5B (0xE3): Helix, 5 axis.

    Versions 1.x, 2.x, 3.0; 68 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0xE3
    NAME: ClassVar[str] = "HELIX5B"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 68
    start: tuple[float, float, float]
    """Start point. [mm] Offset 0, f4(3)."""
    center: tuple[float, float, float]
    """Centre point. [mm] Offset 12, f4(3)."""
    normal: tuple[float, float, float]
    """Axis direction (need not be unit length); rotation by the right-hand rule. Offset 24, f4(3)."""
    ndegrees: float
    """Angle swept about the normal. [deg] Offset 36, f4."""
    length: float
    """Axial advance along the unit normal. [mm] Offset 40, f4."""
    start_orient: tuple[float, float, float]
    """Start orientation. Offset 44, f4(3)."""
    end_orient: tuple[float, float, float]
    """End orientation. Offset 56, f4(3)."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Speed:
    """SPEED (0x8B): Speed.

    Versions 1.x, 2.x, 3.0, 4.0; 4 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0x8B
    NAME: ClassVar[str] = "SPEED"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 4
    speed: float
    """Speed. [m/s] Offset 0, f4."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Accel:
    """ACCEL (0x47): Acceleration and deceleration.

    Versions 1.x, 2.x, 3.0, 4.0; 8 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0x47
    NAME: ClassVar[str] = "ACCEL"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 8
    accel: float
    """Acceleration. [m/s^2] Offset 0, f4."""
    decel: float
    """Deceleration. [m/s^2] Offset 4, f4."""


@dataclass(frozen=True, slots=True, kw_only=True)
class CutterOn:
    """CUTTER_ON (0xBB): Turn cutter on.

    Versions 1.x, 2.x, 3.0, 4.0; 0 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0xBB
    NAME: ClassVar[str] = "CUTTER_ON"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 0


@dataclass(frozen=True, slots=True, kw_only=True)
class CutterOff:
    """CUTTER_OFF (0x66): Turn cutter off.

    Versions 1.x, 2.x, 3.0, 4.0; 0 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0x66
    NAME: ClassVar[str] = "CUTTER_OFF"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 0


@dataclass(frozen=True, slots=True, kw_only=True)
class Guide:
    """GUIDE (0x11): Guide message.

    Versions 1.x, 2.x, 3.0, 4.0; 32 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0x11
    NAME: ClassVar[str] = "GUIDE"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 32
    message: str
    """Message. Offset 0, str(32)."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Fcparms:
    """FCPARMS (0xFC): Force control parameters.

    Versions 2.x, 3.0, 4.0; 16 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0xFC
    NAME: ClassVar[str] = "FCPARMS"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 16
    nom_speed: float
    """Nominal speed. [m/s] Offset 0, f4."""
    max_speed: float
    """Maximum speed. [m/s] Offset 4, f4."""
    min_speed: float
    """Minimum speed. [m/s] Offset 8, f4."""
    max_force: float
    """Maximum force. [N] Offset 12, f4."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Version:
    """VERSION (0x55): Version numbers.

    Default layout (N8); the 16 listed bytes and 16 reserved bytes make up the declared 32.
    Versions 2.x, 3.0, 4.0; 32 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0x55
    NAME: ClassVar[str] = "VERSION"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 32
    cutfile: str
    """Cutfile version. Offset 0, str(8)."""
    format: str
    """Format version. Offset 8, str(8)."""
    reserved: bytes = bytes(16)
    """Not listed by 5.1; reserved to reach the declared 32 bytes (N8). Offset 16, bytes(16)."""


@dataclass(frozen=True, slots=True, kw_only=True)
class VersionImplib:
    """VERSION (0x55): Version numbers.

    The 16 listed bytes only, as implib writes them (N8); accepted under the implib profile.
    Versions 2.x, 3.0, 4.0; 16 argument bytes; accepted under profile implib (5.1).
    """

    CODE: ClassVar[int] = 0x55
    NAME: ClassVar[str] = "VERSION"
    VARIANT: ClassVar[str] = "implib"
    SIZE: ClassVar[int] = 16
    cutfile: str
    """Cutfile version. Offset 0, str(8)."""
    format: str
    """Format version. Offset 8, str(8)."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Comment:
    """COMMENT (0x5A): Comment.

    Versions 1.x, 2.x, 3.0, 4.0; 40 argument bytes (5.1).
    """

    CODE: ClassVar[int] = 0x5A
    NAME: ClassVar[str] = "COMMENT"
    VARIANT: ClassVar[str] = ""
    SIZE: ClassVar[int] = 40
    text: str
    """Comment text. Offset 0, str(40)."""


ARGS_CLASSES: dict[tuple[str, str], type] = {
    ("CHECKPOINT", ""): Checkpoint,
    ("CHECKPOINT", "v1"): CheckpointV1,
    ("CUTTER", ""): Cutter,
    ("CUTTER", "v1"): CutterV1,
    ("ORIENT", ""): Orient,
    ("ORIENT5B", ""): Orient5b,
    ("PHASE", ""): Phase,
    ("ENABLE_SKIP", ""): EnableSkip,
    ("STARTSHAPE", ""): Startshape,
    ("ENDSHAPE", ""): Endshape,
    ("DECEL_OFF", ""): DecelOff,
    ("DECEL_ON", ""): DecelOn,
    ("POINT", ""): Point,
    ("LINE", ""): Line,
    ("LINE5B", ""): Line5b,
    ("ARC", ""): Arc,
    ("ARC5B", ""): Arc5b,
    ("CIRCLE", ""): Circle,
    ("CIRCLE5B", ""): Circle5b,
    ("HELIX", ""): Helix,
    ("HELIX5B", ""): Helix5b,
    ("SPEED", ""): Speed,
    ("ACCEL", ""): Accel,
    ("CUTTER_ON", ""): CutterOn,
    ("CUTTER_OFF", ""): CutterOff,
    ("GUIDE", ""): Guide,
    ("FCPARMS", ""): Fcparms,
    ("VERSION", ""): Version,
    ("VERSION", "implib"): VersionImplib,
    ("COMMENT", ""): Comment,
}
