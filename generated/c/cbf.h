/* cbf.h - Cutfile Binary Format (300071 rev 03), C99 single-header codec.
 *
 * GENERATED from spec/cbf.yaml by cbfgen (emitter generator/cbfgen/emit/c).
 * Do not edit: change the spec and run `make generate`.
 *
 * Usage: #include "cbf.h" anywhere for the declarations; in exactly one C or
 * C++ file write
 *
 *     #define CBF_IMPLEMENTATION
 *     #include "cbf.h"
 *
 * for the implementation. No function allocates memory: every buffer is the
 * caller's. Functions return a size or count (>= 0) or a negative CBF_ERR_*.
 *
 * Print the commands of a file held in buf[0..len):
 *
 *     cbf_reader r;
 *     cbf_record rec;
 *     int rc = cbf_reader_init(&r, buf, len);
 *     if (rc == CBF_OK)
 *         while ((rc = cbf_next_record(&r, &rec)) == 1)
 *             printf("%zu %s\n", rec.index, cbf_command_name(rec.head.code));
 *     // rc == 0: the end; rc < 0: cbf_strerror(rc). cbf_validate() checks the rest.
 *
 * Version: CBF_TOOLKIT_VERSION, spec CBF_SPEC_REVISION (below).
 * SPDX-License-Identifier: Apache-2.0
 *
 * Byte order: little-endian (N1). Floats: IEEE-754 binary32 (N2).
 * Strings: string(N) is N bytes, NUL-padded, no terminator when full (N4);
 * the structs hold the N bytes plus a terminating NUL, so the C string is the
 * value (the part before the first NUL) and every byte is still there.
 */
#ifndef CBF_H
#define CBF_H

#include <stddef.h>
#include <stdint.h>

/** The toolkit version that generated this header, and the spec revision it implements. */
#define CBF_TOOLKIT_VERSION "0.2.0"
#define CBF_SPEC_REVISION "300071 rev 03"

#ifdef __cplusplus
extern "C" {
#endif

/* ======================================================================= ids */

/** Format versions (7.1); the header's version field selects one. */
enum cbf_version {
    CBF_V1_X = 0, /**< CBF File Format Version 1.01 and other 1.x (read only, N10). (major 1; clause 7.2.1) */
    CBF_V2_X = 1, /**< CBF File Format Version 2.0 (read only, N10). (major 2; clause 7.2.2) */
    CBF_V3_0 = 2, /**< Version 3.0, specified by 300071 rev 03. (major 3, minor 0; clause 2.1; writable) */
    CBF_V4_0 = 3, /**< Version 4.0, which 7.2.3.1 restricts (the command table shows what it lacks). (major 4, minor 0; clause 7.2.3; writable) */
    CBF_V__COUNT = 4, /**< sentinel: number of versions */
    CBF_V__UNKNOWN = -1 /**< the header's version matches no entry */
};
#define CBF_VERSION_BIT(v) (1u << (unsigned)(v))
#define CBF_DEFAULT_VERSION CBF_V3_0
#define CBF_FALLBACK_VERSION CBF_V4_0

/** Validation profiles. */
enum cbf_profile {
    CBF_PROFILE_DEFAULT = 0, /**< What 300071 says, read with the decisions N1 to N11. */
    CBF_PROFILE_IMPLIB = 1, /**< Compatibility with files written by THINK Surgical's implib (2017): the file checksum covers implib's range (without sequence numbers) and VERSION may carry only its 16 listed bytes. Writers under this profile use implib's coverage and the 16-byte VERSION. A file whose checksum matches the default coverage instead is an error here, and the finding names the coverage it matches: accepting either coverage let any change equal to their difference (the sum of the sequence bytes; 1 for a two-record file) pass unseen, which the reliability campaign found as missed bit flips. */
    CBF_PROFILE__COUNT = 2
};

/** Command codes (5.1, 5.2): the symbolic names with their hex values. */
enum cbf_command {
    CBF_CMD_GUIDE = 0x11, /**< Guide message. (clause 5.1) */
    CBF_CMD_PHASE = 0x21, /**< Cutting phase. (clause 5.1) */
    CBF_CMD_ENABLE_SKIP = 0x22, /**< Enable skip to phase. (clause 5.1) */
    CBF_CMD_DECEL_OFF = 0x2B, /**< Turn on motion blending (i.e., don't decelerate). (clause 5.1) */
    CBF_CMD_POINT = 0x33, /**< Starting goal point. (clause 5.1) */
    CBF_CMD_CHECKPOINT = 0x3C, /**< Check-point. (clause 5.1) */
    CBF_CMD_ACCEL = 0x47, /**< Acceleration and deceleration. (clause 5.1) */
    CBF_CMD_DECEL_ON = 0x4E, /**< Turn off motion blending (i.e., decelerate). (clause 5.1) */
    CBF_CMD_VERSION = 0x55, /**< Version numbers. (clause 5.1) */
    CBF_CMD_ORIENT = 0x58, /**< Orientation change. (clause 5.1) */
    CBF_CMD_ORIENT5B = 0x59, /**< Orientation change, 5 axis. (clause 5.1) */
    CBF_CMD_COMMENT = 0x5A, /**< Comment. (clause 5.1) */
    CBF_CMD_ENDSHAPE = 0x65, /**< End of a shape; same arguments as STARTSHAPE (redundancy). (clause 5.1) */
    CBF_CMD_CUTTER_OFF = 0x66, /**< Turn cutter off. (clause 5.1) */
    CBF_CMD_CIRCLE = 0x7A, /**< Circle. (clause 5.1) */
    CBF_CMD_CIRCLE5B = 0x7B, /**< Circle, 5 axis. (clause 5.1) */
    CBF_CMD_SPEED = 0x8B, /**< Speed. (clause 5.1) */
    CBF_CMD_ARC = 0x94, /**< Arc move. (clause 5.1) */
    CBF_CMD_ARC5B = 0x95, /**< Arc move, 5 axis. (clause 5.1) */
    CBF_CMD_CUTTER = 0xA3, /**< Change cutter. (clause 5.1) */
    CBF_CMD_LINE = 0xB6, /**< Straight line motion. (clause 5.1) */
    CBF_CMD_LINE5B = 0xB7, /**< Straight line motion, 5 axis. (clause 5.1) */
    CBF_CMD_CUTTER_ON = 0xBB, /**< Turn cutter on. (clause 5.1) */
    CBF_CMD_STARTSHAPE = 0xC9, /**< Start of a shape. (clause 5.1) */
    CBF_CMD_HELIX = 0xE2, /**< Helix. (clause 5.1) */
    CBF_CMD_HELIX5B = 0xE3, /**< Helix, 5 axis. (clause 5.1) */
    CBF_CMD_FCPARMS = 0xFC, /**< Force control parameters. (clause 5.1) */
    CBF_CMD__UNKNOWN = 0x100 /**< sentinel: not a command code (codes are 0x00..0xFF) */
};
#define CBF_COMMAND_COUNT 27

/** Argument layouts, one per command and variant. */
enum cbf_layout {
    CBF_LAYOUT_CHECKPOINT = 0, /**< CHECKPOINT: 32 bytes */
    CBF_LAYOUT_CHECKPOINT_V1 = 1, /**< CHECKPOINT variant v1: 16 bytes */
    CBF_LAYOUT_CUTTER = 2, /**< CUTTER: 32 bytes */
    CBF_LAYOUT_CUTTER_V1 = 3, /**< CUTTER variant v1: 32 bytes */
    CBF_LAYOUT_ORIENT = 4, /**< ORIENT: 24 bytes */
    CBF_LAYOUT_ORIENT5B = 5, /**< ORIENT5B: 24 bytes */
    CBF_LAYOUT_PHASE = 6, /**< PHASE: 16 bytes */
    CBF_LAYOUT_ENABLE_SKIP = 7, /**< ENABLE_SKIP: 16 bytes */
    CBF_LAYOUT_STARTSHAPE = 8, /**< STARTSHAPE: 6 bytes */
    CBF_LAYOUT_ENDSHAPE = 9, /**< ENDSHAPE: 6 bytes */
    CBF_LAYOUT_DECEL_OFF = 10, /**< DECEL_OFF: 0 bytes */
    CBF_LAYOUT_DECEL_ON = 11, /**< DECEL_ON: 0 bytes */
    CBF_LAYOUT_POINT = 12, /**< POINT: 12 bytes */
    CBF_LAYOUT_LINE = 13, /**< LINE: 24 bytes */
    CBF_LAYOUT_LINE5B = 14, /**< LINE5B: 48 bytes */
    CBF_LAYOUT_ARC = 15, /**< ARC: 36 bytes */
    CBF_LAYOUT_ARC5B = 16, /**< ARC5B: 60 bytes */
    CBF_LAYOUT_CIRCLE = 17, /**< CIRCLE: 40 bytes */
    CBF_LAYOUT_CIRCLE5B = 18, /**< CIRCLE5B: 64 bytes */
    CBF_LAYOUT_HELIX = 19, /**< HELIX: 44 bytes */
    CBF_LAYOUT_HELIX5B = 20, /**< HELIX5B: 68 bytes */
    CBF_LAYOUT_SPEED = 21, /**< SPEED: 4 bytes */
    CBF_LAYOUT_ACCEL = 22, /**< ACCEL: 8 bytes */
    CBF_LAYOUT_CUTTER_ON = 23, /**< CUTTER_ON: 0 bytes */
    CBF_LAYOUT_CUTTER_OFF = 24, /**< CUTTER_OFF: 0 bytes */
    CBF_LAYOUT_GUIDE = 25, /**< GUIDE: 32 bytes */
    CBF_LAYOUT_FCPARMS = 26, /**< FCPARMS: 16 bytes */
    CBF_LAYOUT_VERSION = 27, /**< VERSION: 32 bytes */
    CBF_LAYOUT_VERSION_IMPLIB = 28, /**< VERSION variant implib: 16 bytes */
    CBF_LAYOUT_COMMENT = 29, /**< COMMENT: 40 bytes */
    CBF_LAYOUT__COUNT = 30,
    CBF_LAYOUT__NONE = -1 /**< arguments not decoded */
};

/** Header layouts. */
enum cbf_header_layout {
    CBF_HEADER_V2 = 0, /**< File header as 4.2 gives it, with the configuration descriptor of 7.2.2.1. */
    CBF_HEADER_V1 = 1, /**< File header before 7.2.2.1 shortened the implant descriptor. */
    CBF_HEADER__COUNT = 2
};

/* Check ids: the same ids in every binding (findings carry them). */
#define CBF_CHECK_4_2 "4.2" /**< error: The file header is 128 bytes long. */
#define CBF_CHECK_4_3 "4.3" /**< error: The cutting data consists of variable length records. */
#define CBF_CHECK_6_1_1 "6.1.1" /**< error: The first word in the Implant Descriptor field in the file header should be the implant part number. */
#define CBF_CHECK_PART_NUMBER_FIRST "part_number_first" /**< warning: The implant descriptor begins with the implant part number (4.2; 6.1.1 compares it when one is given). */
#define CBF_CHECK_6_1_2 "6.1.2" /**< error: The length and radius of every cutter (specified by the CUTTER command) should agree, within 0.01 millimeters, with the values specified in the robot's cutter database. */
#define CBF_CHECK_6_2_1 "6.2.1" /**< error: The checksum of the entire file should match the value specified in the file header. */
#define CBF_CHECK_6_2_2 "6.2.2" /**< error: The number of commands in the file should match the value specified in the file header. */
#define CBF_CHECK_6_3_1 "6.3.1" /**< error: The checksum of the file header should match the specified value. */
#define CBF_CHECK_6_3_2 "6.3.2" /**< error: The first and last fields of the header should match the special values specified in Section 4.2 (the spec says 5.1, erratum E2). */
#define CBF_CHECK_6_4_1 "6.4.1" /**< error: The sequence number should be one greater than the previous sequence number (first record should have sequence number 0). */
#define CBF_CHECK_6_4_2 "6.4.2" /**< error: Both command code fields should be identical. */
#define CBF_CHECK_6_4_3 "6.4.3" /**< error: The number of bytes for the command arguments should be as specified in the table in Section 5.1 (the spec says 6.1, erratum E1). */
#define CBF_CHECK_6_4_4 "6.4.4" /**< error: The checksum of the command argument bytes should match the specified value. */
#define CBF_CHECK_6_4_5 "6.4.5" /**< error: The starting point of a motion command (e.g., LINE, ARC, CIRCLE, etc.) should match the ending point of the previous motion command. */
#define CBF_CHECK_7_2_3_1 "7.2.3.1" /**< error: Version 4.0 does not support Arc, arc5b, circle, circle5b, helix, helix5b. */
#define CBF_CHECK_7_2_2_4 "7.2.2.4" /**< error: The FCPARMS, DECEL_OFF, DECEL_ON, HELIX, VERSION, and PHASE commands were added in 2.0. */
#define CBF_CHECK_VERSION_SUPPORTED "version_supported" /**< error: The processing software can read the version number and adjust the parsing logic appropriately. */
#define CBF_CHECK_UNKNOWN_COMMAND "unknown_command" /**< error: An unknown command code is an error; its record is kept whole. */
#define CBF_CHECK_TRAILING_BYTES "trailing_bytes" /**< error: No byte follows the last record. */
#define CBF_CHECK_RESERVED_NONZERO "reserved_nonzero" /**< warning: The record's reserved byte should be 0. */
#define CBF_CHECK_STRING_TAIL "string_tail" /**< warning: A string ends at its first NUL; the bytes after it are padding. */
#define CBF_CHECK_STRING_ASCII "string_ascii" /**< warning: Strings are ASCII. */
#define CBF_CHECK_NON_FINITE "non_finite" /**< error: Floats are finite. */
#define CBF_CHECK_SPEED_POSITIVE "speed_positive" /**< error: SPEED is greater than 0. */
#define CBF_CHECK_ACCEL_POSITIVE "accel_positive" /**< error: Acceleration and deceleration are greater than 0. */
#define CBF_CHECK_CUTTER_POSITIVE "cutter_positive" /**< error: Cutter length and radius are greater than 0. */
#define CBF_CHECK_NORMAL_NONZERO "normal_nonzero" /**< error: A circle or helix normal has non-zero length. */
#define CBF_CHECK_CHECKPOINT_RANGE "checkpoint_range" /**< warning: CHECKPOINT completion lies in 0..100. */
#define CBF_CHECK_CHECKPOINT_FALLING "checkpoint_falling" /**< warning: CHECKPOINT completion does not fall. */
#define CBF_CHECK_FCPARMS_ORDER "fcparms_order" /**< warning: FCPARMS speeds satisfy min <= nom <= max. */
#define CBF_CHECK_ORIENTATION_JUMP "orientation_jump" /**< warning: A 5-axis command starts at the current tool orientation. */
#define CBF_CHECK_MACHINE_LIMITS "machine_limits" /**< warning: Positions lie in the machine's workspace; speeds, accelerations and cutter sizes lie in its ranges. */
#define CBF_CHECK_SHAPE "shape" /**< error: STARTSHAPE name,n ... ENDSHAPE name,n enclose exactly n motion commands; shapes do not nest. */
#define CBF_CHECK__COUNT 33

/* =================================================================== lengths */

#define CBF_HEADER_SIZE 128
#define CBF_RECORD_HEAD_SIZE 8
#define CBF_LIMIT_MAX_COMMANDS 65535
#define CBF_LIMIT_MAX_ARG_SIZE 255
#define CBF_MAX_ARG_SIZE 68 /**< the largest layout (a repeated group at its most items) */
#define CBF_TOLERANCE_POSITION_MM 0.001
#define CBF_TOLERANCE_CUTTER_MM 0.01
#define CBF_TOLERANCE_ORIENTATION_DEG 0.1
/* A cutter table's columns (check 6.1.2): the keys of the spec's cutter role, the name's and
 * CBF_CUTTER_VALUES numbers; cbf_cutter.value[CBF_CUTTER_<COLUMN>] holds each number. */
#define CBF_CUTTER_VALUES 2
#define CBF_CUTTER_LENGTH 0 /**< cbf_cutter.value[] of the column length */
#define CBF_CUTTER_RADIUS 1 /**< cbf_cutter.value[] of the column radius */

/* Header field offsets and sizes, per header layout. */
#define CBF_HEADER_V2_START_PATTERN_OFFSET 0
#define CBF_HEADER_V2_START_PATTERN_SIZE 4
#define CBF_HEADER_V2_FILE_CHECKSUM_OFFSET 4
#define CBF_HEADER_V2_FILE_CHECKSUM_SIZE 4
#define CBF_HEADER_V2_HEADER_CHECKSUM_OFFSET 8
#define CBF_HEADER_V2_HEADER_CHECKSUM_SIZE 2
#define CBF_HEADER_V2_RESERVED_ECC_OFFSET 10
#define CBF_HEADER_V2_RESERVED_ECC_SIZE 6
#define CBF_HEADER_V2_VERSION_MAJOR_OFFSET 16
#define CBF_HEADER_V2_VERSION_MAJOR_SIZE 1
#define CBF_HEADER_V2_VERSION_MINOR_OFFSET 17
#define CBF_HEADER_V2_VERSION_MINOR_SIZE 1
#define CBF_HEADER_V2_IMPLANT_DESCRIPTOR_OFFSET 18
#define CBF_HEADER_V2_IMPLANT_DESCRIPTOR_SIZE 70
#define CBF_HEADER_V2_CONFIGURATION_DESCRIPTOR_OFFSET 88
#define CBF_HEADER_V2_CONFIGURATION_DESCRIPTOR_SIZE 34
#define CBF_HEADER_V2_COMMAND_COUNT_OFFSET 122
#define CBF_HEADER_V2_COMMAND_COUNT_SIZE 2
#define CBF_HEADER_V2_END_PATTERN_OFFSET 124
#define CBF_HEADER_V2_END_PATTERN_SIZE 4
#define CBF_HEADER_V1_START_PATTERN_OFFSET 0
#define CBF_HEADER_V1_START_PATTERN_SIZE 4
#define CBF_HEADER_V1_FILE_CHECKSUM_OFFSET 4
#define CBF_HEADER_V1_FILE_CHECKSUM_SIZE 4
#define CBF_HEADER_V1_HEADER_CHECKSUM_OFFSET 8
#define CBF_HEADER_V1_HEADER_CHECKSUM_SIZE 2
#define CBF_HEADER_V1_RESERVED_ECC_OFFSET 10
#define CBF_HEADER_V1_RESERVED_ECC_SIZE 6
#define CBF_HEADER_V1_VERSION_MAJOR_OFFSET 16
#define CBF_HEADER_V1_VERSION_MAJOR_SIZE 1
#define CBF_HEADER_V1_VERSION_MINOR_OFFSET 17
#define CBF_HEADER_V1_VERSION_MINOR_SIZE 1
#define CBF_HEADER_V1_IMPLANT_DESCRIPTOR_OFFSET 18
#define CBF_HEADER_V1_IMPLANT_DESCRIPTOR_SIZE 80
#define CBF_HEADER_V1_RESERVED_98_OFFSET 98
#define CBF_HEADER_V1_RESERVED_98_SIZE 24
#define CBF_HEADER_V1_COMMAND_COUNT_OFFSET 122
#define CBF_HEADER_V1_COMMAND_COUNT_SIZE 2
#define CBF_HEADER_V1_END_PATTERN_OFFSET 124
#define CBF_HEADER_V1_END_PATTERN_SIZE 4

/* Magic numbers (header fields with a fixed value). */
#define CBF_MAGIC_START_PATTERN 0x53A1B792u
#define CBF_MAGIC_END_PATTERN 0xAC5E486Du

/* Record head field offsets and sizes (4.3). */
#define CBF_RECORD_SEQUENCE_OFFSET 0
#define CBF_RECORD_SEQUENCE_SIZE 2
#define CBF_RECORD_CODE_OFFSET 2
#define CBF_RECORD_CODE_SIZE 1
#define CBF_RECORD_CODE_COPY_OFFSET 3
#define CBF_RECORD_CODE_COPY_SIZE 1
#define CBF_RECORD_ARG_SIZE_OFFSET 4
#define CBF_RECORD_ARG_SIZE_SIZE 1
#define CBF_RECORD_RESERVED_OFFSET 5
#define CBF_RECORD_RESERVED_SIZE 1
#define CBF_RECORD_ARG_CHECKSUM_OFFSET 6
#define CBF_RECORD_ARG_CHECKSUM_SIZE 2

/* Argument sizes per layout, and the versions each layout applies to. */
#define CBF_ARGS_CHECKPOINT_SIZE 32
#define CBF_ARGS_CHECKPOINT_VERSIONS (CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0) | CBF_VERSION_BIT(CBF_V4_0))
#define CBF_ARGS_CHECKPOINT_V1_SIZE 16
#define CBF_ARGS_CHECKPOINT_V1_VERSIONS (CBF_VERSION_BIT(CBF_V1_X))
#define CBF_ARGS_CUTTER_SIZE 32
#define CBF_ARGS_CUTTER_VERSIONS (CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0) | CBF_VERSION_BIT(CBF_V4_0))
#define CBF_ARGS_CUTTER_V1_SIZE 32
#define CBF_ARGS_CUTTER_V1_VERSIONS (CBF_VERSION_BIT(CBF_V1_X))
#define CBF_ARGS_ORIENT_SIZE 24
#define CBF_ARGS_ORIENT_VERSIONS (CBF_VERSION_BIT(CBF_V1_X) | CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0) | CBF_VERSION_BIT(CBF_V4_0))
#define CBF_ARGS_ORIENT5B_SIZE 24
#define CBF_ARGS_ORIENT5B_VERSIONS (CBF_VERSION_BIT(CBF_V1_X) | CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0) | CBF_VERSION_BIT(CBF_V4_0))
#define CBF_ARGS_PHASE_SIZE 16
#define CBF_ARGS_PHASE_VERSIONS (CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0) | CBF_VERSION_BIT(CBF_V4_0))
#define CBF_ARGS_ENABLE_SKIP_SIZE 16
#define CBF_ARGS_ENABLE_SKIP_VERSIONS (CBF_VERSION_BIT(CBF_V1_X) | CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0) | CBF_VERSION_BIT(CBF_V4_0))
#define CBF_ARGS_STARTSHAPE_SIZE 6
#define CBF_ARGS_STARTSHAPE_VERSIONS (CBF_VERSION_BIT(CBF_V1_X) | CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0) | CBF_VERSION_BIT(CBF_V4_0))
#define CBF_ARGS_ENDSHAPE_SIZE 6
#define CBF_ARGS_ENDSHAPE_VERSIONS (CBF_VERSION_BIT(CBF_V1_X) | CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0) | CBF_VERSION_BIT(CBF_V4_0))
#define CBF_ARGS_DECEL_OFF_SIZE 0
#define CBF_ARGS_DECEL_OFF_VERSIONS (CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0) | CBF_VERSION_BIT(CBF_V4_0))
#define CBF_ARGS_DECEL_ON_SIZE 0
#define CBF_ARGS_DECEL_ON_VERSIONS (CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0) | CBF_VERSION_BIT(CBF_V4_0))
#define CBF_ARGS_POINT_SIZE 12
#define CBF_ARGS_POINT_VERSIONS (CBF_VERSION_BIT(CBF_V1_X) | CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0) | CBF_VERSION_BIT(CBF_V4_0))
#define CBF_ARGS_LINE_SIZE 24
#define CBF_ARGS_LINE_VERSIONS (CBF_VERSION_BIT(CBF_V1_X) | CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0) | CBF_VERSION_BIT(CBF_V4_0))
#define CBF_ARGS_LINE5B_SIZE 48
#define CBF_ARGS_LINE5B_VERSIONS (CBF_VERSION_BIT(CBF_V1_X) | CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0) | CBF_VERSION_BIT(CBF_V4_0))
#define CBF_ARGS_ARC_SIZE 36
#define CBF_ARGS_ARC_VERSIONS (CBF_VERSION_BIT(CBF_V1_X) | CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0))
#define CBF_ARGS_ARC5B_SIZE 60
#define CBF_ARGS_ARC5B_VERSIONS (CBF_VERSION_BIT(CBF_V1_X) | CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0))
#define CBF_ARGS_CIRCLE_SIZE 40
#define CBF_ARGS_CIRCLE_VERSIONS (CBF_VERSION_BIT(CBF_V1_X) | CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0))
#define CBF_ARGS_CIRCLE5B_SIZE 64
#define CBF_ARGS_CIRCLE5B_VERSIONS (CBF_VERSION_BIT(CBF_V1_X) | CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0))
#define CBF_ARGS_HELIX_SIZE 44
#define CBF_ARGS_HELIX_VERSIONS (CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0))
#define CBF_ARGS_HELIX5B_SIZE 68
#define CBF_ARGS_HELIX5B_VERSIONS (CBF_VERSION_BIT(CBF_V1_X) | CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0))
#define CBF_ARGS_SPEED_SIZE 4
#define CBF_ARGS_SPEED_VERSIONS (CBF_VERSION_BIT(CBF_V1_X) | CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0) | CBF_VERSION_BIT(CBF_V4_0))
#define CBF_ARGS_ACCEL_SIZE 8
#define CBF_ARGS_ACCEL_VERSIONS (CBF_VERSION_BIT(CBF_V1_X) | CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0) | CBF_VERSION_BIT(CBF_V4_0))
#define CBF_ARGS_CUTTER_ON_SIZE 0
#define CBF_ARGS_CUTTER_ON_VERSIONS (CBF_VERSION_BIT(CBF_V1_X) | CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0) | CBF_VERSION_BIT(CBF_V4_0))
#define CBF_ARGS_CUTTER_OFF_SIZE 0
#define CBF_ARGS_CUTTER_OFF_VERSIONS (CBF_VERSION_BIT(CBF_V1_X) | CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0) | CBF_VERSION_BIT(CBF_V4_0))
#define CBF_ARGS_GUIDE_SIZE 32
#define CBF_ARGS_GUIDE_VERSIONS (CBF_VERSION_BIT(CBF_V1_X) | CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0) | CBF_VERSION_BIT(CBF_V4_0))
#define CBF_ARGS_FCPARMS_SIZE 16
#define CBF_ARGS_FCPARMS_VERSIONS (CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0) | CBF_VERSION_BIT(CBF_V4_0))
#define CBF_ARGS_VERSION_SIZE 32
#define CBF_ARGS_VERSION_VERSIONS (CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0) | CBF_VERSION_BIT(CBF_V4_0))
#define CBF_ARGS_VERSION_IMPLIB_SIZE 16
#define CBF_ARGS_VERSION_IMPLIB_VERSIONS (CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0) | CBF_VERSION_BIT(CBF_V4_0))
#define CBF_ARGS_COMMENT_SIZE 40
#define CBF_ARGS_COMMENT_VERSIONS (CBF_VERSION_BIT(CBF_V1_X) | CBF_VERSION_BIT(CBF_V2_X) | CBF_VERSION_BIT(CBF_V3_0) | CBF_VERSION_BIT(CBF_V4_0))

/* Per-version availability (1: the command has a layout in that version)
 * and argument sizes of each command in each version. */
#define CBF_CMD_CHECKPOINT_IN_V1_X 1
#define CBF_ARGS_CHECKPOINT_V1_SIZE_V1_X 16
#define CBF_CMD_CHECKPOINT_IN_V2_X 1
#define CBF_ARGS_CHECKPOINT_SIZE_V2_X 32
#define CBF_CMD_CHECKPOINT_IN_V3_0 1
#define CBF_ARGS_CHECKPOINT_SIZE_V3_0 32
#define CBF_CMD_CHECKPOINT_IN_V4_0 1
#define CBF_ARGS_CHECKPOINT_SIZE_V4_0 32
#define CBF_CMD_CUTTER_IN_V1_X 1
#define CBF_ARGS_CUTTER_V1_SIZE_V1_X 32
#define CBF_CMD_CUTTER_IN_V2_X 1
#define CBF_ARGS_CUTTER_SIZE_V2_X 32
#define CBF_CMD_CUTTER_IN_V3_0 1
#define CBF_ARGS_CUTTER_SIZE_V3_0 32
#define CBF_CMD_CUTTER_IN_V4_0 1
#define CBF_ARGS_CUTTER_SIZE_V4_0 32
#define CBF_CMD_ORIENT_IN_V1_X 1
#define CBF_ARGS_ORIENT_SIZE_V1_X 24
#define CBF_CMD_ORIENT_IN_V2_X 1
#define CBF_ARGS_ORIENT_SIZE_V2_X 24
#define CBF_CMD_ORIENT_IN_V3_0 1
#define CBF_ARGS_ORIENT_SIZE_V3_0 24
#define CBF_CMD_ORIENT_IN_V4_0 1
#define CBF_ARGS_ORIENT_SIZE_V4_0 24
#define CBF_CMD_ORIENT5B_IN_V1_X 1
#define CBF_ARGS_ORIENT5B_SIZE_V1_X 24
#define CBF_CMD_ORIENT5B_IN_V2_X 1
#define CBF_ARGS_ORIENT5B_SIZE_V2_X 24
#define CBF_CMD_ORIENT5B_IN_V3_0 1
#define CBF_ARGS_ORIENT5B_SIZE_V3_0 24
#define CBF_CMD_ORIENT5B_IN_V4_0 1
#define CBF_ARGS_ORIENT5B_SIZE_V4_0 24
#define CBF_CMD_PHASE_IN_V1_X 0
#define CBF_CMD_PHASE_IN_V2_X 1
#define CBF_ARGS_PHASE_SIZE_V2_X 16
#define CBF_CMD_PHASE_IN_V3_0 1
#define CBF_ARGS_PHASE_SIZE_V3_0 16
#define CBF_CMD_PHASE_IN_V4_0 1
#define CBF_ARGS_PHASE_SIZE_V4_0 16
#define CBF_CMD_ENABLE_SKIP_IN_V1_X 1
#define CBF_ARGS_ENABLE_SKIP_SIZE_V1_X 16
#define CBF_CMD_ENABLE_SKIP_IN_V2_X 1
#define CBF_ARGS_ENABLE_SKIP_SIZE_V2_X 16
#define CBF_CMD_ENABLE_SKIP_IN_V3_0 1
#define CBF_ARGS_ENABLE_SKIP_SIZE_V3_0 16
#define CBF_CMD_ENABLE_SKIP_IN_V4_0 1
#define CBF_ARGS_ENABLE_SKIP_SIZE_V4_0 16
#define CBF_CMD_STARTSHAPE_IN_V1_X 1
#define CBF_ARGS_STARTSHAPE_SIZE_V1_X 6
#define CBF_CMD_STARTSHAPE_IN_V2_X 1
#define CBF_ARGS_STARTSHAPE_SIZE_V2_X 6
#define CBF_CMD_STARTSHAPE_IN_V3_0 1
#define CBF_ARGS_STARTSHAPE_SIZE_V3_0 6
#define CBF_CMD_STARTSHAPE_IN_V4_0 1
#define CBF_ARGS_STARTSHAPE_SIZE_V4_0 6
#define CBF_CMD_ENDSHAPE_IN_V1_X 1
#define CBF_ARGS_ENDSHAPE_SIZE_V1_X 6
#define CBF_CMD_ENDSHAPE_IN_V2_X 1
#define CBF_ARGS_ENDSHAPE_SIZE_V2_X 6
#define CBF_CMD_ENDSHAPE_IN_V3_0 1
#define CBF_ARGS_ENDSHAPE_SIZE_V3_0 6
#define CBF_CMD_ENDSHAPE_IN_V4_0 1
#define CBF_ARGS_ENDSHAPE_SIZE_V4_0 6
#define CBF_CMD_DECEL_OFF_IN_V1_X 0
#define CBF_CMD_DECEL_OFF_IN_V2_X 1
#define CBF_ARGS_DECEL_OFF_SIZE_V2_X 0
#define CBF_CMD_DECEL_OFF_IN_V3_0 1
#define CBF_ARGS_DECEL_OFF_SIZE_V3_0 0
#define CBF_CMD_DECEL_OFF_IN_V4_0 1
#define CBF_ARGS_DECEL_OFF_SIZE_V4_0 0
#define CBF_CMD_DECEL_ON_IN_V1_X 0
#define CBF_CMD_DECEL_ON_IN_V2_X 1
#define CBF_ARGS_DECEL_ON_SIZE_V2_X 0
#define CBF_CMD_DECEL_ON_IN_V3_0 1
#define CBF_ARGS_DECEL_ON_SIZE_V3_0 0
#define CBF_CMD_DECEL_ON_IN_V4_0 1
#define CBF_ARGS_DECEL_ON_SIZE_V4_0 0
#define CBF_CMD_POINT_IN_V1_X 1
#define CBF_ARGS_POINT_SIZE_V1_X 12
#define CBF_CMD_POINT_IN_V2_X 1
#define CBF_ARGS_POINT_SIZE_V2_X 12
#define CBF_CMD_POINT_IN_V3_0 1
#define CBF_ARGS_POINT_SIZE_V3_0 12
#define CBF_CMD_POINT_IN_V4_0 1
#define CBF_ARGS_POINT_SIZE_V4_0 12
#define CBF_CMD_LINE_IN_V1_X 1
#define CBF_ARGS_LINE_SIZE_V1_X 24
#define CBF_CMD_LINE_IN_V2_X 1
#define CBF_ARGS_LINE_SIZE_V2_X 24
#define CBF_CMD_LINE_IN_V3_0 1
#define CBF_ARGS_LINE_SIZE_V3_0 24
#define CBF_CMD_LINE_IN_V4_0 1
#define CBF_ARGS_LINE_SIZE_V4_0 24
#define CBF_CMD_LINE5B_IN_V1_X 1
#define CBF_ARGS_LINE5B_SIZE_V1_X 48
#define CBF_CMD_LINE5B_IN_V2_X 1
#define CBF_ARGS_LINE5B_SIZE_V2_X 48
#define CBF_CMD_LINE5B_IN_V3_0 1
#define CBF_ARGS_LINE5B_SIZE_V3_0 48
#define CBF_CMD_LINE5B_IN_V4_0 1
#define CBF_ARGS_LINE5B_SIZE_V4_0 48
#define CBF_CMD_ARC_IN_V1_X 1
#define CBF_ARGS_ARC_SIZE_V1_X 36
#define CBF_CMD_ARC_IN_V2_X 1
#define CBF_ARGS_ARC_SIZE_V2_X 36
#define CBF_CMD_ARC_IN_V3_0 1
#define CBF_ARGS_ARC_SIZE_V3_0 36
#define CBF_CMD_ARC_IN_V4_0 0
#define CBF_CMD_ARC5B_IN_V1_X 1
#define CBF_ARGS_ARC5B_SIZE_V1_X 60
#define CBF_CMD_ARC5B_IN_V2_X 1
#define CBF_ARGS_ARC5B_SIZE_V2_X 60
#define CBF_CMD_ARC5B_IN_V3_0 1
#define CBF_ARGS_ARC5B_SIZE_V3_0 60
#define CBF_CMD_ARC5B_IN_V4_0 0
#define CBF_CMD_CIRCLE_IN_V1_X 1
#define CBF_ARGS_CIRCLE_SIZE_V1_X 40
#define CBF_CMD_CIRCLE_IN_V2_X 1
#define CBF_ARGS_CIRCLE_SIZE_V2_X 40
#define CBF_CMD_CIRCLE_IN_V3_0 1
#define CBF_ARGS_CIRCLE_SIZE_V3_0 40
#define CBF_CMD_CIRCLE_IN_V4_0 0
#define CBF_CMD_CIRCLE5B_IN_V1_X 1
#define CBF_ARGS_CIRCLE5B_SIZE_V1_X 64
#define CBF_CMD_CIRCLE5B_IN_V2_X 1
#define CBF_ARGS_CIRCLE5B_SIZE_V2_X 64
#define CBF_CMD_CIRCLE5B_IN_V3_0 1
#define CBF_ARGS_CIRCLE5B_SIZE_V3_0 64
#define CBF_CMD_CIRCLE5B_IN_V4_0 0
#define CBF_CMD_HELIX_IN_V1_X 0
#define CBF_CMD_HELIX_IN_V2_X 1
#define CBF_ARGS_HELIX_SIZE_V2_X 44
#define CBF_CMD_HELIX_IN_V3_0 1
#define CBF_ARGS_HELIX_SIZE_V3_0 44
#define CBF_CMD_HELIX_IN_V4_0 0
#define CBF_CMD_HELIX5B_IN_V1_X 1
#define CBF_ARGS_HELIX5B_SIZE_V1_X 68
#define CBF_CMD_HELIX5B_IN_V2_X 1
#define CBF_ARGS_HELIX5B_SIZE_V2_X 68
#define CBF_CMD_HELIX5B_IN_V3_0 1
#define CBF_ARGS_HELIX5B_SIZE_V3_0 68
#define CBF_CMD_HELIX5B_IN_V4_0 0
#define CBF_CMD_SPEED_IN_V1_X 1
#define CBF_ARGS_SPEED_SIZE_V1_X 4
#define CBF_CMD_SPEED_IN_V2_X 1
#define CBF_ARGS_SPEED_SIZE_V2_X 4
#define CBF_CMD_SPEED_IN_V3_0 1
#define CBF_ARGS_SPEED_SIZE_V3_0 4
#define CBF_CMD_SPEED_IN_V4_0 1
#define CBF_ARGS_SPEED_SIZE_V4_0 4
#define CBF_CMD_ACCEL_IN_V1_X 1
#define CBF_ARGS_ACCEL_SIZE_V1_X 8
#define CBF_CMD_ACCEL_IN_V2_X 1
#define CBF_ARGS_ACCEL_SIZE_V2_X 8
#define CBF_CMD_ACCEL_IN_V3_0 1
#define CBF_ARGS_ACCEL_SIZE_V3_0 8
#define CBF_CMD_ACCEL_IN_V4_0 1
#define CBF_ARGS_ACCEL_SIZE_V4_0 8
#define CBF_CMD_CUTTER_ON_IN_V1_X 1
#define CBF_ARGS_CUTTER_ON_SIZE_V1_X 0
#define CBF_CMD_CUTTER_ON_IN_V2_X 1
#define CBF_ARGS_CUTTER_ON_SIZE_V2_X 0
#define CBF_CMD_CUTTER_ON_IN_V3_0 1
#define CBF_ARGS_CUTTER_ON_SIZE_V3_0 0
#define CBF_CMD_CUTTER_ON_IN_V4_0 1
#define CBF_ARGS_CUTTER_ON_SIZE_V4_0 0
#define CBF_CMD_CUTTER_OFF_IN_V1_X 1
#define CBF_ARGS_CUTTER_OFF_SIZE_V1_X 0
#define CBF_CMD_CUTTER_OFF_IN_V2_X 1
#define CBF_ARGS_CUTTER_OFF_SIZE_V2_X 0
#define CBF_CMD_CUTTER_OFF_IN_V3_0 1
#define CBF_ARGS_CUTTER_OFF_SIZE_V3_0 0
#define CBF_CMD_CUTTER_OFF_IN_V4_0 1
#define CBF_ARGS_CUTTER_OFF_SIZE_V4_0 0
#define CBF_CMD_GUIDE_IN_V1_X 1
#define CBF_ARGS_GUIDE_SIZE_V1_X 32
#define CBF_CMD_GUIDE_IN_V2_X 1
#define CBF_ARGS_GUIDE_SIZE_V2_X 32
#define CBF_CMD_GUIDE_IN_V3_0 1
#define CBF_ARGS_GUIDE_SIZE_V3_0 32
#define CBF_CMD_GUIDE_IN_V4_0 1
#define CBF_ARGS_GUIDE_SIZE_V4_0 32
#define CBF_CMD_FCPARMS_IN_V1_X 0
#define CBF_CMD_FCPARMS_IN_V2_X 1
#define CBF_ARGS_FCPARMS_SIZE_V2_X 16
#define CBF_CMD_FCPARMS_IN_V3_0 1
#define CBF_ARGS_FCPARMS_SIZE_V3_0 16
#define CBF_CMD_FCPARMS_IN_V4_0 1
#define CBF_ARGS_FCPARMS_SIZE_V4_0 16
#define CBF_CMD_VERSION_IN_V1_X 0
#define CBF_CMD_VERSION_IN_V2_X 1
#define CBF_ARGS_VERSION_SIZE_V2_X 32
#define CBF_ARGS_VERSION_IMPLIB_SIZE_V2_X 16
#define CBF_CMD_VERSION_IN_V3_0 1
#define CBF_ARGS_VERSION_SIZE_V3_0 32
#define CBF_ARGS_VERSION_IMPLIB_SIZE_V3_0 16
#define CBF_CMD_VERSION_IN_V4_0 1
#define CBF_ARGS_VERSION_SIZE_V4_0 32
#define CBF_ARGS_VERSION_IMPLIB_SIZE_V4_0 16
#define CBF_CMD_COMMENT_IN_V1_X 1
#define CBF_ARGS_COMMENT_SIZE_V1_X 40
#define CBF_CMD_COMMENT_IN_V2_X 1
#define CBF_ARGS_COMMENT_SIZE_V2_X 40
#define CBF_CMD_COMMENT_IN_V3_0 1
#define CBF_ARGS_COMMENT_SIZE_V3_0 40
#define CBF_CMD_COMMENT_IN_V4_0 1
#define CBF_ARGS_COMMENT_SIZE_V4_0 40

/* ===================================================================== enums */

enum cbf_error {
    CBF_OK = 0,
    CBF_ERR_TRUNCATED_HEADER = -1, /**< fewer bytes than the header (4.2) */
    CBF_ERR_TRUNCATED_RECORD = -2, /**< the last record is cut and the count says more follow (4.3, D1) */
    CBF_ERR_BUFFER = -3,           /**< the caller's buffer is too small */
    CBF_ERR_ARGUMENT = -4,         /**< a bad argument (NULL, unknown layout, profile or version) */
    CBF_ERR_RANGE = -5,            /**< a value that the format cannot hold */
    CBF_ERR_NOT_WRITABLE = -6,     /**< the version, command or size cannot be written (the version lacks the
                                        command, or no layout of it in the version has that size) */
    CBF_ERR_INVALID = -7,          /**< the encoded file would fail an error-severity check */
    CBF_ERR_SYNTAX = -8            /**< CUT text that does not read or encode (cbf_cut_encode: its line) */
};

/** Roles of header and record fields (cbf_field_info.role). */
enum cbf_role {
    CBF_ROLE_NONE = 0,
    CBF_ROLE_START_PATTERN,
    CBF_ROLE_CHECKSUM,
    CBF_ROLE_RESERVED,
    CBF_ROLE_VERSION_MAJOR,
    CBF_ROLE_VERSION_MINOR,
    CBF_ROLE_IMPLANT_DESCRIPTOR,
    CBF_ROLE_CONFIGURATION_DESCRIPTOR,
    CBF_ROLE_COMMAND_COUNT,
    CBF_ROLE_END_PATTERN,
    CBF_ROLE_SEQUENCE,
    CBF_ROLE_CODE,
    CBF_ROLE_CODE_COPY,
    CBF_ROLE_ARG_SIZE
};

/** What a field's bytes are (cbf_field_info.kind): the field kinds of the spec language's registry. */
enum cbf_field_kind {
    CBF_KIND_UINT = 1,
    CBF_KIND_SINT = 2,
    CBF_KIND_FLOAT = 3,
    CBF_KIND_STRING = 4,
    CBF_KIND_BYTES = 5
};

enum cbf_severity { CBF_SEVERITY_WARNING = 0, CBF_SEVERITY_ERROR = 1 };

/* =================================================================== structs */

/** File header as 4.2 gives it, with the configuration descriptor of 7.2.2.1. (clause 4.2, 128 bytes) */
struct cbf_header_v2 {
    uint32_t start_pattern; /**< Special pattern indicating cutting file (N5, bytes 92 B7 A1 53). [u32; offset 0; clause 4.2] */
    uint32_t file_checksum; /**< Checksum for entire file (starting at byte 8). [u32; offset 4; clause 4.2] */
    uint16_t header_checksum; /**< Checksum for rest of header. [u16; offset 8; clause 4.2] */
    uint8_t reserved_ecc[6]; /**< Reserved for future checksum usage (Error Correcting Codes); kept verbatim (N7). [6 raw bytes; offset 10; clause 4.2] */
    uint8_t version_major; /**< Version number for cutfile format, major (N3). [u8; offset 16; clause 4.2] */
    uint8_t version_minor; /**< Version number for cutfile format, minor (N3). [u8; offset 17; clause 4.2] */
    char implant_descriptor[70 + 1]; /**< Implant descriptor (part number, manufacturer, type, size); the part number must be the first item (6.1.1). [string(70), NUL-terminated copy; offset 18; clause 4.2] */
    char configuration_descriptor[34 + 1]; /**< Configuration descriptor; the field 7.2.2.1 made of the 1.x reserved bytes. [string(34), NUL-terminated copy; offset 88; clause 4.2] */
    uint16_t command_count; /**< Number of commands in cutting data section (6.2.2). [u16; offset 122; clause 4.2] */
    uint32_t end_pattern; /**< Special pattern indicating end of header, the complement of the start pattern (N5, bytes 6D 48 5E AC). [u32; offset 124; clause 4.2] */
};

/** File header before 7.2.2.1 shortened the implant descriptor. (clause 7.2.2.1, 128 bytes) */
struct cbf_header_v1 {
    uint32_t start_pattern; /**< Special pattern indicating cutting file. [u32; offset 0; clause 4.2] */
    uint32_t file_checksum; /**< Checksum for entire file (starting at byte 8). [u32; offset 4; clause 4.2] */
    uint16_t header_checksum; /**< Checksum for rest of header. [u16; offset 8; clause 4.2] */
    uint8_t reserved_ecc[6]; /**< Reserved for future checksum usage; kept verbatim (N7). [6 raw bytes; offset 10; clause 4.2] */
    uint8_t version_major; /**< Version number, major (N3). [u8; offset 16; clause 4.2] */
    uint8_t version_minor; /**< Version number, minor (N3). [u8; offset 17; clause 4.2] */
    char implant_descriptor[80 + 1]; /**< Implant descriptor of 80 bytes (1.x). [string(80), NUL-terminated copy; offset 18; clause 7.2.2.1] */
    uint8_t reserved_98[24]; /**< Reserved field at offset 98 (1.x); renamed Configuration Descriptor in 2.0. [24 raw bytes; offset 98; clause 7.2.2.1] */
    uint16_t command_count; /**< Number of commands in cutting data section. [u16; offset 122; clause 4.2] */
    uint32_t end_pattern; /**< Complement of the start pattern (N5). [u32; offset 124; clause 4.2] */
};

/** A decoded file header. */
typedef struct cbf_header {
    int version;  /**< enum cbf_version, or CBF_V__UNKNOWN (then read as CBF_FALLBACK_VERSION) */
    int layout;   /**< enum cbf_header_layout: which member of u is valid */
    unsigned major, minor; /**< the version field */
    unsigned long count;   /**< the header's command count */
    union {
        struct cbf_header_v2 v2;
        struct cbf_header_v1 v1;
    } u;
} cbf_header;

/** A cutting-data record; the records follow the header back to back. (clause 4.3, 8 bytes) */
typedef struct cbf_record_head {
    uint16_t sequence; /**< Command sequence number (0 - 65535); 6.4.1. [u16; offset 0; clause 4.3] */
    uint8_t code; /**< Command code (5.1). [u8; offset 2; clause 4.3] */
    uint8_t code_copy; /**< Backup copy of command code (redundancy); 6.4.2. [u8; offset 3; clause 4.3] */
    uint8_t arg_size; /**< Number of bytes used by command arguments (nb); 6.4.3. [u8; offset 4; clause 4.3] */
    uint8_t reserved; /**< Reserved, should be 0 (N7). [u8; offset 5; clause 4.3] */
    uint16_t arg_checksum; /**< Checksum of command arguments; 6.4.4. [u16; offset 6; clause 4.3] */
} cbf_record_head;

/** CHECKPOINT: Check-point. 32 argument bytes; versions 2.x, 3.0, 4.0; clause 5.1. */
struct cbf_checkpoint_args {
    char name[16 + 1]; /**< Check-point name. [string(16), NUL-terminated copy; offset 0] */
    float recovery_point[3]; /**< Recovery point. [binary32 x 3; offset 16; unit mm (millimetre (N11))] */
    float completion; /**< Completion percentage. [binary32; offset 28; unit percent (percent of completion, 0 to 100)] */
};

/** CHECKPOINT (v1): Check-point. 16 argument bytes; versions 1.x; clause 7.2.2.2. */
struct cbf_checkpoint_v1_args {
    char name[16 + 1]; /**< Check-point name. [string(16), NUL-terminated copy; offset 0] */
};

/** CUTTER: Change cutter. 32 argument bytes; versions 2.x, 3.0, 4.0; clause 5.1. */
struct cbf_cutter_args {
    char name[16 + 1]; /**< Cutter name (part number). [string(16), NUL-terminated copy; offset 0] */
    float length; /**< Cutter length (6.1.2). [binary32; offset 16; unit mm (millimetre (N11))] */
    float radius; /**< Cutter radius (6.1.2). [binary32; offset 20; unit mm (millimetre (N11))] */
    float head_length; /**< Cutter head length (7.2.2.3). [binary32; offset 24; unit mm (millimetre (N11))] */
    uint8_t reserved[4]; /**< 4 bytes reserved (N7). [4 raw bytes; offset 28; reserved, kept verbatim] */
};

/** CUTTER (v1): Change cutter. 32 argument bytes; versions 1.x; clause 7.2.2.3. */
struct cbf_cutter_v1_args {
    char name[16 + 1]; /**< Cutter name (part number). [string(16), NUL-terminated copy; offset 0] */
    float length; /**< Cutter length (6.1.2). [binary32; offset 16; unit mm (millimetre (N11))] */
    float radius; /**< Cutter radius (6.1.2). [binary32; offset 20; unit mm (millimetre (N11))] */
    uint8_t reserved[8]; /**< 8 bytes reserved; head length came in 2.0 (7.2.2.3). [8 raw bytes; offset 24; reserved, kept verbatim] */
};

/** ORIENT: Orientation change. 24 argument bytes; versions 1.x, 2.x, 3.0, 4.0; clause 5.1. */
struct cbf_orient_args {
    float approach[3]; /**< Tool approach. [binary32 x 3; offset 0] */
    uint8_t reserved[12]; /**< reserved: float(3); kept verbatim (N7). [12 raw bytes; offset 12; reserved, kept verbatim] */
};

/** ORIENT5B: Orientation change, 5 axis. 24 argument bytes; versions 1.x, 2.x, 3.0, 4.0; clause 5.1. */
struct cbf_orient5b_args {
    float start_approach[3]; /**< Start approach. [binary32 x 3; offset 0] */
    float end_approach[3]; /**< End approach. [binary32 x 3; offset 12] */
};

/** PHASE: Cutting phase. 16 argument bytes; versions 2.x, 3.0, 4.0; clause 5.1. */
struct cbf_phase_args {
    char name[16 + 1]; /**< Phase name. [string(16), NUL-terminated copy; offset 0] */
};

/** ENABLE_SKIP: Enable skip to phase. 16 argument bytes; versions 1.x, 2.x, 3.0, 4.0; clause 5.1. */
struct cbf_enable_skip_args {
    char name[16 + 1]; /**< Name of the phase to skip to. [string(16), NUL-terminated copy; offset 0] */
};

/** STARTSHAPE: Start of a shape. 6 argument bytes; versions 1.x, 2.x, 3.0, 4.0; clause 5.1. */
struct cbf_startshape_args {
    char name[5 + 1]; /**< Shape name. [string(5), NUL-terminated copy; offset 0] */
    uint8_t moves; /**< Number of (move) commands in the shape. [u8; offset 5; unit count (a number of commands)] */
};

/** ENDSHAPE: End of a shape; same arguments as STARTSHAPE (redundancy). 6 argument bytes; versions 1.x, 2.x, 3.0, 4.0; clause 5.1. */
struct cbf_endshape_args {
    char name[5 + 1]; /**< Shape name, as in STARTSHAPE. [string(5), NUL-terminated copy; offset 0] */
    uint8_t moves; /**< Number of (move) commands, as in STARTSHAPE. [u8; offset 5; unit count (a number of commands)] */
};

/** DECEL_OFF: Turn on motion blending (i.e., don't decelerate). 0 argument bytes; versions 2.x, 3.0, 4.0; clause 5.1. */
struct cbf_decel_off_args {
    char unused_; /**< no arguments (C needs a member) */
};

/** DECEL_ON: Turn off motion blending (i.e., decelerate). 0 argument bytes; versions 2.x, 3.0, 4.0; clause 5.1. */
struct cbf_decel_on_args {
    char unused_; /**< no arguments (C needs a member) */
};

/** POINT: Starting goal point. 12 argument bytes; versions 1.x, 2.x, 3.0, 4.0; clause 5.1. */
struct cbf_point_args {
    float point[3]; /**< Goal point. [binary32 x 3; offset 0; unit mm (millimetre (N11))] */
};

/** LINE: Straight line motion. 24 argument bytes; versions 1.x, 2.x, 3.0, 4.0; clause 5.1. */
struct cbf_line_args {
    float start[3]; /**< Start point. [binary32 x 3; offset 0; unit mm (millimetre (N11))] */
    float end[3]; /**< End point. [binary32 x 3; offset 12; unit mm (millimetre (N11))] */
};

/** LINE5B: Straight line motion, 5 axis. 48 argument bytes; versions 1.x, 2.x, 3.0, 4.0; clause 5.1. */
struct cbf_line5b_args {
    float start_pos[3]; /**< Start position. [binary32 x 3; offset 0; unit mm (millimetre (N11))] */
    float end_pos[3]; /**< End position. [binary32 x 3; offset 12; unit mm (millimetre (N11))] */
    float start_orient[3]; /**< Start orientation. [binary32 x 3; offset 24] */
    float end_orient[3]; /**< End orientation. [binary32 x 3; offset 36] */
};

/** ARC: Arc move. 36 argument bytes; versions 1.x, 2.x, 3.0; clause 5.1. */
struct cbf_arc_args {
    float start[3]; /**< Start point. [binary32 x 3; offset 0; unit mm (millimetre (N11))] */
    float middle[3]; /**< A point in the middle of the arc. [binary32 x 3; offset 12; unit mm (millimetre (N11))] */
    float end[3]; /**< End point. [binary32 x 3; offset 24; unit mm (millimetre (N11))] */
};

/** ARC5B: Arc move, 5 axis. 60 argument bytes; versions 1.x, 2.x, 3.0; clause 5.1. */
struct cbf_arc5b_args {
    float start_pos[3]; /**< Start position. [binary32 x 3; offset 0; unit mm (millimetre (N11))] */
    float mid_pos[3]; /**< Middle position. [binary32 x 3; offset 12; unit mm (millimetre (N11))] */
    float end_pos[3]; /**< End position. [binary32 x 3; offset 24; unit mm (millimetre (N11))] */
    float start_orient[3]; /**< Start orientation. [binary32 x 3; offset 36] */
    float end_orient[3]; /**< End orientation. [binary32 x 3; offset 48] */
};

/** CIRCLE: Circle. 40 argument bytes; versions 1.x, 2.x, 3.0; clause 5.1. */
struct cbf_circle_args {
    float start[3]; /**< Start point. [binary32 x 3; offset 0; unit mm (millimetre (N11))] */
    float center[3]; /**< Centre point. [binary32 x 3; offset 12; unit mm (millimetre (N11))] */
    float normal[3]; /**< Axis direction (need not be unit length); rotation by the right-hand rule. [binary32 x 3; offset 24] */
    float ndegrees; /**< Angle swept about the normal. [binary32; offset 36; unit deg (degree of arc)] */
};

/** CIRCLE5B: Circle, 5 axis. 64 argument bytes; versions 1.x, 2.x, 3.0; clause 5.1. */
struct cbf_circle5b_args {
    float start[3]; /**< Start point. [binary32 x 3; offset 0; unit mm (millimetre (N11))] */
    float center[3]; /**< Centre point. [binary32 x 3; offset 12; unit mm (millimetre (N11))] */
    float normal[3]; /**< Axis direction (need not be unit length); rotation by the right-hand rule. [binary32 x 3; offset 24] */
    float ndegrees; /**< Angle swept about the normal. [binary32; offset 36; unit deg (degree of arc)] */
    float start_orient[3]; /**< Start orientation. [binary32 x 3; offset 40] */
    float end_orient[3]; /**< End orientation. [binary32 x 3; offset 52] */
};

/** HELIX: Helix. 44 argument bytes; versions 2.x, 3.0; clause 5.1. */
struct cbf_helix_args {
    float start[3]; /**< Start point. [binary32 x 3; offset 0; unit mm (millimetre (N11))] */
    float center[3]; /**< Centre point. [binary32 x 3; offset 12; unit mm (millimetre (N11))] */
    float normal[3]; /**< Axis direction (need not be unit length); rotation by the right-hand rule. [binary32 x 3; offset 24] */
    float ndegrees; /**< Angle swept about the normal. [binary32; offset 36; unit deg (degree of arc)] */
    float length; /**< Axial advance along the unit normal. [binary32; offset 40; unit mm (millimetre (N11))] */
};

/** HELIX5B: Helix, 5 axis. 68 argument bytes; versions 1.x, 2.x, 3.0; clause 5.1. */
struct cbf_helix5b_args {
    float start[3]; /**< Start point. [binary32 x 3; offset 0; unit mm (millimetre (N11))] */
    float center[3]; /**< Centre point. [binary32 x 3; offset 12; unit mm (millimetre (N11))] */
    float normal[3]; /**< Axis direction (need not be unit length); rotation by the right-hand rule. [binary32 x 3; offset 24] */
    float ndegrees; /**< Angle swept about the normal. [binary32; offset 36; unit deg (degree of arc)] */
    float length; /**< Axial advance along the unit normal. [binary32; offset 40; unit mm (millimetre (N11))] */
    float start_orient[3]; /**< Start orientation. [binary32 x 3; offset 44] */
    float end_orient[3]; /**< End orientation. [binary32 x 3; offset 56] */
};

/** SPEED: Speed. 4 argument bytes; versions 1.x, 2.x, 3.0, 4.0; clause 5.1. */
struct cbf_speed_args {
    float speed; /**< Speed. [binary32; offset 0; unit m/s (metre per second (N11))] */
};

/** ACCEL: Acceleration and deceleration. 8 argument bytes; versions 1.x, 2.x, 3.0, 4.0; clause 5.1. */
struct cbf_accel_args {
    float accel; /**< Acceleration. [binary32; offset 0; unit m/s^2 (metre per second squared (N11))] */
    float decel; /**< Deceleration. [binary32; offset 4; unit m/s^2 (metre per second squared (N11))] */
};

/** CUTTER_ON: Turn cutter on. 0 argument bytes; versions 1.x, 2.x, 3.0, 4.0; clause 5.1. */
struct cbf_cutter_on_args {
    char unused_; /**< no arguments (C needs a member) */
};

/** CUTTER_OFF: Turn cutter off. 0 argument bytes; versions 1.x, 2.x, 3.0, 4.0; clause 5.1. */
struct cbf_cutter_off_args {
    char unused_; /**< no arguments (C needs a member) */
};

/** GUIDE: Guide message. 32 argument bytes; versions 1.x, 2.x, 3.0, 4.0; clause 5.1. */
struct cbf_guide_args {
    char message[32 + 1]; /**< Message. [string(32), NUL-terminated copy; offset 0] */
};

/** FCPARMS: Force control parameters. 16 argument bytes; versions 2.x, 3.0, 4.0; clause 5.1. */
struct cbf_fcparms_args {
    float nom_speed; /**< Nominal speed. [binary32; offset 0; unit m/s (metre per second (N11))] */
    float max_speed; /**< Maximum speed. [binary32; offset 4; unit m/s (metre per second (N11))] */
    float min_speed; /**< Minimum speed. [binary32; offset 8; unit m/s (metre per second (N11))] */
    float max_force; /**< Maximum force. [binary32; offset 12; unit N (newton)] */
};

/** VERSION: Default layout (N8); the 16 listed bytes and 16 reserved bytes make up the declared 32. 32 argument bytes; versions 2.x, 3.0, 4.0; clause 5.1. */
struct cbf_version_args {
    char cutfile[8 + 1]; /**< Cutfile version. [string(8), NUL-terminated copy; offset 0] */
    char format[8 + 1]; /**< Format version. [string(8), NUL-terminated copy; offset 8] */
    uint8_t reserved[16]; /**< Not listed by 5.1; reserved to reach the declared 32 bytes (N8). [16 raw bytes; offset 16; reserved, kept verbatim] */
};

/** VERSION (implib): The 16 listed bytes only, as implib writes them (N8); accepted under the implib profile. 16 argument bytes; versions 2.x, 3.0, 4.0; accepted only under profile implib; clause 5.1. */
struct cbf_version_implib_args {
    char cutfile[8 + 1]; /**< Cutfile version. [string(8), NUL-terminated copy; offset 0] */
    char format[8 + 1]; /**< Format version. [string(8), NUL-terminated copy; offset 8] */
};

/** COMMENT: Comment. 40 argument bytes; versions 1.x, 2.x, 3.0, 4.0; clause 5.1. */
struct cbf_comment_args {
    char text[40 + 1]; /**< Comment text. [string(40), NUL-terminated copy; offset 0] */
};

/** Decoded arguments of any layout; the record's layout says which member. */
typedef union cbf_args {
    struct cbf_checkpoint_args checkpoint;
    struct cbf_checkpoint_v1_args checkpoint_v1;
    struct cbf_cutter_args cutter;
    struct cbf_cutter_v1_args cutter_v1;
    struct cbf_orient_args orient;
    struct cbf_orient5b_args orient5b;
    struct cbf_phase_args phase;
    struct cbf_enable_skip_args enable_skip;
    struct cbf_startshape_args startshape;
    struct cbf_endshape_args endshape;
    struct cbf_decel_off_args decel_off;
    struct cbf_decel_on_args decel_on;
    struct cbf_point_args point;
    struct cbf_line_args line;
    struct cbf_line5b_args line5b;
    struct cbf_arc_args arc;
    struct cbf_arc5b_args arc5b;
    struct cbf_circle_args circle;
    struct cbf_circle5b_args circle5b;
    struct cbf_helix_args helix;
    struct cbf_helix5b_args helix5b;
    struct cbf_speed_args speed;
    struct cbf_accel_args accel;
    struct cbf_cutter_on_args cutter_on;
    struct cbf_cutter_off_args cutter_off;
    struct cbf_guide_args guide;
    struct cbf_fcparms_args fcparms;
    struct cbf_version_args version;
    struct cbf_version_implib_args version_implib;
    struct cbf_comment_args comment;
} cbf_args;

/* ---- machine limits (decision L1, check kind machine_limits; machine.h.j2) ----
 * A machine bounds every position argument by a box and speeds, accelerations and
 * cutter sizes by ranges, in the units of the arguments. cbf_options.machine NULL:
 * the spec's default machine (cbf_machine_default), whose breaches are warnings;
 * a machine of your own (e.g. read from a machine file): its breaches are errors. */
#define CBF_MACHINE_MAX_AXES 3
enum cbf_machine_limit {
    CBF_MACHINE_WORKSPACE = 0, /**< Every position (a point, a start, end, middle or centre, a recovery point) lies in this box. (mm, axes x y z) */
    CBF_MACHINE_SPEED = 1, /**< Path speeds (SPEED, and the FCPARMS speeds). (m/s) */
    CBF_MACHINE_ACCELERATION = 2, /**< Acceleration and deceleration (ACCEL). (m/s^2) */
    CBF_MACHINE_CUTTER_LENGTH = 3, /**< Cutter length (CUTTER). (mm) */
    CBF_MACHINE_CUTTER_RADIUS = 4, /**< Cutter radius (CUTTER). (mm) */
    CBF_MACHINE__COUNT = 5
};
/** One limit: min[0]..max[0] for a range; min[i]..max[i] on axis i for a box. */
typedef struct cbf_machine_range {
    double min[CBF_MACHINE_MAX_AXES];
    double max[CBF_MACHINE_MAX_AXES];
} cbf_machine_range;
typedef struct cbf_machine {
    cbf_machine_range limit[CBF_MACHINE__COUNT]; /**< by enum cbf_machine_limit */
} cbf_machine;
/** Each limit's name (as in a machine file), unit, and number of axes (0: a range). */
extern const char *const cbf_machine_limit_names[CBF_MACHINE__COUNT];
extern const char *const cbf_machine_limit_units[CBF_MACHINE__COUNT];
extern const int cbf_machine_limit_axes[CBF_MACHINE__COUNT];
/** The axis names of each box limit (NULL past its axes). */
extern const char *const cbf_machine_limit_axis_names[CBF_MACHINE__COUNT][CBF_MACHINE_MAX_AXES];
/** The spec's default machine (L1): conservative; its breaches are warnings. */
extern const cbf_machine cbf_machine_default;
/* ==== BEGIN runtime/types.h: verbatim from generator/cbfgen/emit/c/runtime/types.h, edit it there ==== */
#line 1 "generator/cbfgen/emit/c/runtime/types.h"
/* ---- the API's types: records, reader, writer, field descriptions, findings, options ---- */
/** One record, as cbf_next_record gives it. */
typedef struct cbf_record {
    size_t index;          /**< 0-based record index */
    size_t offset;         /**< file offset of the record */
    cbf_record_head head;  /**< the head fields as stored */
    const uint8_t *args;   /**< the argument bytes, inside the caller's buffer */
    size_t nargs;          /**< number of argument bytes (nb) */
    int command;           /**< enum cbf_command (the code), or CBF_CMD__UNKNOWN */
    int layout;            /**< enum cbf_layout used for `decoded`, or CBF_LAYOUT__NONE */
    cbf_args decoded;      /**< valid when layout != CBF_LAYOUT__NONE */
} cbf_record;

/** Record iterator over a caller's buffer (framing by nb from the header to EOF, D1). */
typedef struct cbf_reader {
    const uint8_t *buf;
    size_t len;
    size_t pos;            /**< offset of the next record */
    size_t index;          /**< index of the next record */
    cbf_header header;
    int eff_version;       /**< the version whose tables are used */
    size_t trailing;       /**< after the end: number of trailing bytes at pos */
} cbf_reader;

/** Describes a header field, record head field or argument (for generic consumers). */
typedef struct cbf_field_info {
    const char *name;
    const char *unit;      /**< NULL when none */
    unsigned char kind;    /**< enum cbf_field_kind */
    unsigned char role;    /**< private role number */
    unsigned char flags;   /**< CBF_FIELD_RESERVED | CBF_FIELD_TEXT | CBF_FIELD_MAGIC */
    unsigned char checksum;/**< private checksum tag, 0 when none */
    unsigned short offset; /**< byte offset in the header, record head or arguments */
    unsigned short elem;   /**< element size */
    unsigned short count;  /**< number of elements (3 for a vector) */
    size_t member;         /**< offsetof in the struct */
    uint32_t magic;        /**< the fixed value when flags has CBF_FIELD_MAGIC */
} cbf_field_info;
#define CBF_FIELD_RESERVED 1u
#define CBF_FIELD_TEXT 2u
#define CBF_FIELD_MAGIC 4u

/** Writer state for cbf_encode_*: the file is built in the caller's buffer. */
typedef struct cbf_writer {
    uint8_t *buf;
    size_t cap;
    size_t len;
    size_t records_end;    /**< end of the last record (before trailing bytes) */
    unsigned long count;   /**< records written */
    int version;           /**< enum cbf_version of the header, or CBF_V__UNKNOWN */
    int eff_version;
    int error;             /**< first error, sticky */
} cbf_writer;

/** Why cbf_cut_encode refused CUT text: the line (from 1; 0: the text as a whole), the column (from 1;
 * 0: the line alone is named) and what is wrong, one line of printable ASCII (a token of the text is
 * quoted and cut short; nothing of the text starts the line). */
typedef struct cbf_cut_error {
    unsigned long line;
    unsigned long column;
    char message[400];
} cbf_cut_error;

/** A finding of cbf_validate. */
typedef struct cbf_finding {
    const char *check;     /**< a CBF_CHECK_* id */
    int severity;          /**< enum cbf_severity */
    long record;           /**< 0-based record index, or -1 for the header and the file */
    size_t offset;         /**< file offset of the field concerned, as every binding names it
                                (conformance/PROTOCOL.md, Findings; the runner compares it) */
    const char *message;   /**< for people; valid during the callback only */
} cbf_finding;

typedef void (*cbf_finding_fn)(void *user, const cbf_finding *finding);

/** One entry of the robot's cutter table (6.1.2): its name and its numbers, value[CBF_CUTTER_<COLUMN>]
 * for each column of the table beside the name (the keys of the spec's cutter role: CBF_CUTTER_LENGTH,
 * CBF_CUTTER_RADIUS in rev 03). */
typedef struct cbf_cutter {
    const char *name;
    double value[CBF_CUTTER_VALUES];
} cbf_cutter;

typedef struct cbf_options {
    int profile;               /**< enum cbf_profile */
    const char *part_number;   /**< 6.1.1 input, or NULL */
    const cbf_cutter *cutters; /**< 6.1.2 input, or NULL (no table given) */
    size_t ncutters;
    const cbf_machine *machine; /**< machine_limits input (L1), or NULL: the default machine, warnings */
} cbf_options;
/* ==== END runtime/types.h ==== */
#line 981 "cbf.h"
/* ==== BEGIN runtime/api.h: verbatim from generator/cbfgen/emit/c/runtime/api.h, edit it there ==== */
#line 1 "generator/cbfgen/emit/c/runtime/api.h"
/* ================================================================ prototypes */

/** Command names by code (NULL for codes that are not commands). */
extern const char *const cbf_command_names[256];

const char *cbf_strerror(int err);
/** The one quoting rule for a name or value from input in an output line (runtime/quote.c; the
 * same as the Python codec's cbf.quoting): CBF_QUOTE_NAME prints a plain name as it is and any
 * other between double quotes with escapes; CBF_QUOTE_TEXT escapes what is not plain in text.
 * cbf_quote writes at most cap bytes (NUL-terminated) and returns the length it needs;
 * cbf_quoted returns one of 4 static buffers in turn (not thread-safe). */
enum { CBF_QUOTE_NAME = 0, CBF_QUOTE_TEXT = 1 };
size_t cbf_quote(char *out, size_t cap, const char *s, size_t n, int mode);
const char *cbf_quoted(const char *s, int mode);
/** How many bytes of s[0..n) are whole UTF-8 characters before the first that is none (a byte that starts
 * none, an overlong form, a surrogate, beyond U+10FFFF, a character cut by the end): n when all are. */
size_t cbf_utf8_prefix(const uint8_t *s, size_t n);
/** Name of a command code, or NULL when the code is unknown. */
const char *cbf_command_name(int code);
/** 1 when the command has a layout in the version, else 0. */
int cbf_command_available(int code, int version);
/** enum cbf_version for a version field, or CBF_V__UNKNOWN. */
int cbf_version_find(unsigned major, unsigned minor);
const char *cbf_version_name(int version);
int cbf_version_writable(int version);
/** enum cbf_profile for a name, or CBF_ERR_ARGUMENT. */
int cbf_profile_find(const char *name);
const char *cbf_layout_command_name(int layout);
const char *cbf_layout_variant(int layout);
int cbf_layout_code(int layout);
/** A layout's argument bytes (with a repeated group: its fixed arguments', n = 0). */
long cbf_layout_size(int layout);
/** Field tables: number of fields, *out set to the first. */
size_t cbf_layout_fields(int layout, const cbf_field_info **out);
size_t cbf_header_fields(int header_layout, const cbf_field_info **out);
size_t cbf_record_fields(const cbf_field_info **out);
/** Field values in a byte image (header, record head or argument bytes): */
uint32_t cbf_field_uint(const cbf_field_info *f, const uint8_t *base);     /**< u1, u2, u4; else 0 */
float cbf_field_float(const cbf_field_info *f, const uint8_t *base, unsigned i); /**< binary32; else 0 */
uint32_t cbf_float_bits(float f);
/** Element i of an integer or float field of any registered width, as its bits (an unsigned
 *  integer as itself, a signed one in two's complement, a float as its IEEE-754 bits); 0 for
 *  other fields. */
uint64_t cbf_field_bits(const cbf_field_info *f, const uint8_t *base, unsigned i);
/** Element i of an integer or float field of any registered width, as a double (exact up to
 *  2^53 for integers); 0.0 for other fields. */
double cbf_field_number(const cbf_field_info *f, const uint8_t *base, unsigned i);
/** Field values in a struct (cbf_record_head, header or argument struct) by member offset. */
uint32_t cbf_member_uint(const cbf_field_info *f, const void *obj);
void cbf_member_set_uint(const cbf_field_info *f, void *obj, uint32_t v);
/** Header layout of a version (the fallback's for CBF_V__UNKNOWN). */
int cbf_version_header_layout(int version);
/** Decode candidates of a code in a version, in order (PROTOCOL.md): the
 *  version's own layouts, else every layout newest first. Returns the number written. */
int cbf_args_candidates(int code, int version, int *out, int cap);
/** Layout that decodes nb argument bytes of a code in a version (PROTOCOL.md), or CBF_LAYOUT__NONE. */
int cbf_args_layout(int code, int version, size_t nb);

/** Decode the header: returns CBF_HEADER_SIZE or CBF_ERR_TRUNCATED_HEADER. */
long cbf_header_decode(const uint8_t *buf, size_t len, cbf_header *out);
/** A zeroed header of a version with its magic numbers set. */
int cbf_header_init(cbf_header *h, int version);
/** Write the header fields (as stored in h) to out: returns CBF_HEADER_SIZE or an error. */
long cbf_header_encode(const cbf_header *h, uint8_t *out, size_t cap);

/** Start iterating: decodes the header. CBF_OK or CBF_ERR_TRUNCATED_HEADER. */
int cbf_reader_init(cbf_reader *r, const uint8_t *buf, size_t len);
/** Next record: 1 and *rec filled; 0 at the end (r->trailing bytes remain at r->pos);
 *  CBF_ERR_TRUNCATED_RECORD when the last record is cut before the header count is reached. */
int cbf_next_record(cbf_reader *r, cbf_record *rec);

/** Decode argument bytes with a layout: returns n (the argument bytes) or an error (CBF_ERR_RANGE when
 *  the layout does not take n bytes: a repeated group of no n in its min..max). */
long cbf_args_decode(int layout, const uint8_t *args, size_t n, cbf_args *out);
/** Encode a layout's struct into bytes: returns the bytes written (a repeated group: its n items after
 *  the fixed arguments) or an error (CBF_ERR_RANGE when the group's n is outside its min..max). */
long cbf_args_encode(int layout, const cbf_args *in, uint8_t *out, size_t cap);
/** A layout's repeated argument group (issue 25, point 3; nb = cbf_layout_size + item * n): its index
 *  among the layout's fields (cbf_layout_fields: that row describes one item), with *min and *max n and
 *  *item the bytes an item (each pointer may be NULL); -1 when the layout has none. */
int cbf_layout_group(int layout, size_t *min, size_t *max, size_t *item);
/** The argument bytes of a record of the layout with n items of its group (0 for a layout without
 *  one), or CBF_ERR_RANGE when n is outside the group's min..max. */
long cbf_layout_nb(int layout, size_t n);
/** How many items of its group a record of the layout with nb argument bytes holds (0 without a
 *  group), or -1 when the layout does not take nb bytes. */
long cbf_layout_items(int layout, size_t nb);

/** The drawn path of a motion record (its layout and argument bytes): points along its motion in the
 * engine's geometry, the last its end as the continuity check has it; a circle, helix or arc through a
 * middle point every 5 degrees of turn, at most CBF_PATH_MAX_POINTS (runtime/path.c). from: the position
 * before it, where a point motion starts (NULL: none; it starts at its end). The count written to out
 * (room for CBF_PATH_MAX_POINTS); 0 when the layout has no motion or its values are not finite. */
#define CBF_PATH_MAX_POINTS 145u
/** 1 when the layout's command is a motion (its spec role), else 0. */
int cbf_layout_moves(int layout);
size_t cbf_motion_path(int layout, const uint8_t *args, size_t nargs, const double *from, double (*out)[3]);

/** Checksum of argument bytes, as the spec computes the record's argument checksum. */
uint32_t cbf_args_checksum(const uint8_t *args, size_t n);

/** Begin a file in buf with the header h (its fields as given). */
int cbf_encode_begin(cbf_writer *w, uint8_t *buf, size_t cap, const cbf_header *h);
/** Append a record; fills sequence (the index), the code copy, nb, reserved 0 and the argument checksum.
 *  CBF_ERR_NOT_WRITABLE when the header's version lacks the command (or the code is unknown), or when
 *  nargs is not the size of one of the command's layouts in that version. */
int cbf_encode_record(cbf_writer *w, int code, const uint8_t *args, size_t nargs);
/** Append a record with every head field as given in head (nb must equal nargs). */
int cbf_encode_record_stored(cbf_writer *w, const cbf_record_head *head, const uint8_t *args, size_t nargs);
/** Append raw bytes (trailing bytes of a faulty file). */
int cbf_encode_bytes(cbf_writer *w, const uint8_t *bytes, size_t n);
/** Finish: with fill != 0 set the count, the magic numbers and the checksums
 *  in the spec's fill order (the file checksum with the profile's coverage).
 *  With fill != 0 the version must be writable and every record (stored ones
 *  too) a command of that version with the size of one of its layouts that the
 *  profile accepts, else CBF_ERR_NOT_WRITABLE. A command with a layout of the
 *  profile's own (N8) is cut to that layout when the fields cut off are
 *  reserved and zero, else CBF_ERR_NOT_WRITABLE. With fill == 0 the bytes are
 *  kept as given (a faulty file reproduced). Returns the file size or the
 *  writer's first error (errors are sticky: a refused record fails the end). */
long cbf_encode_end(cbf_writer *w, int profile, int fill);

/** CUT text (the toolkit's text form of a CBF file: the spec's `cut` section) to the CBF file it encodes to,
 * as cbf's CUT reader and writer make it: text[0..n), read in place, never past n; the file written into
 * out[0..cap) with every derived value filled (cbf_encode_end with fill) under profile, NOT validated.
 * Returns the file's size; CBF_ERR_SYNTAX with *err set when the text does not read or does not encode
 * (the line of the record concerned); CBF_ERR_BUFFER when cap is too small (the text read: call again
 * with more room; a CBF file never needs more than the header and CBF_LIMIT_MAX_COMMANDS largest
 * records); CBF_ERR_ARGUMENT for a bad argument. */
long cbf_cut_encode(const char *text, size_t n, int profile, uint8_t *out, size_t cap, cbf_cut_error *err);
/** cbf_cut_encode in a version asked for (an enum cbf_version; CBF_V__UNKNOWN: none, as cbf_cut_encode):
 * the version of a text without a version line (cbf encode --version); a version line naming another
 * version is refused with its line. */
long cbf_cut_encode_as(const char *text, size_t n, int version, int profile, uint8_t *out, size_t cap,
                       cbf_cut_error *err);
/** The line of CUT text[0..n) that holds record `record` (from 0: the lines that are not empty and not a
 * header, header_ext, check_sum, version or field line), as cbf encode names the record of a file it
 * refuses (cli.py, _cut_line_of); 0 when the text holds fewer records. */
unsigned long cbf_cut_record_line(const char *text, size_t n, unsigned long record);

/** Run every check of the spec; each finding goes to fn. Returns the number
 *  of error-severity findings, or CBF_ERR_ARGUMENT. */
long cbf_validate(const uint8_t *buf, size_t len, const cbf_options *opt, cbf_finding_fn fn, void *user);
/* ==== END runtime/api.h ==== */
#line 1128 "cbf.h"
/** One encoder a layout: cbf_args_encode and cbf_encode_record for that layout's struct. */
int cbf_encode_checkpoint(cbf_writer *w, const struct cbf_checkpoint_args *args);
int cbf_encode_checkpoint_v1(cbf_writer *w, const struct cbf_checkpoint_v1_args *args);
int cbf_encode_cutter(cbf_writer *w, const struct cbf_cutter_args *args);
int cbf_encode_cutter_v1(cbf_writer *w, const struct cbf_cutter_v1_args *args);
int cbf_encode_orient(cbf_writer *w, const struct cbf_orient_args *args);
int cbf_encode_orient5b(cbf_writer *w, const struct cbf_orient5b_args *args);
int cbf_encode_phase(cbf_writer *w, const struct cbf_phase_args *args);
int cbf_encode_enable_skip(cbf_writer *w, const struct cbf_enable_skip_args *args);
int cbf_encode_startshape(cbf_writer *w, const struct cbf_startshape_args *args);
int cbf_encode_endshape(cbf_writer *w, const struct cbf_endshape_args *args);
int cbf_encode_decel_off(cbf_writer *w, const struct cbf_decel_off_args *args);
int cbf_encode_decel_on(cbf_writer *w, const struct cbf_decel_on_args *args);
int cbf_encode_point(cbf_writer *w, const struct cbf_point_args *args);
int cbf_encode_line(cbf_writer *w, const struct cbf_line_args *args);
int cbf_encode_line5b(cbf_writer *w, const struct cbf_line5b_args *args);
int cbf_encode_arc(cbf_writer *w, const struct cbf_arc_args *args);
int cbf_encode_arc5b(cbf_writer *w, const struct cbf_arc5b_args *args);
int cbf_encode_circle(cbf_writer *w, const struct cbf_circle_args *args);
int cbf_encode_circle5b(cbf_writer *w, const struct cbf_circle5b_args *args);
int cbf_encode_helix(cbf_writer *w, const struct cbf_helix_args *args);
int cbf_encode_helix5b(cbf_writer *w, const struct cbf_helix5b_args *args);
int cbf_encode_speed(cbf_writer *w, const struct cbf_speed_args *args);
int cbf_encode_accel(cbf_writer *w, const struct cbf_accel_args *args);
int cbf_encode_cutter_on(cbf_writer *w, const struct cbf_cutter_on_args *args);
int cbf_encode_cutter_off(cbf_writer *w, const struct cbf_cutter_off_args *args);
int cbf_encode_guide(cbf_writer *w, const struct cbf_guide_args *args);
int cbf_encode_fcparms(cbf_writer *w, const struct cbf_fcparms_args *args);
int cbf_encode_version(cbf_writer *w, const struct cbf_version_args *args);
int cbf_encode_version_implib(cbf_writer *w, const struct cbf_version_implib_args *args);
int cbf_encode_comment(cbf_writer *w, const struct cbf_comment_args *args);
#ifdef __cplusplus
}
#endif
#endif /* CBF_H */

/* ============================================================ implementation */
#ifdef CBF_IMPLEMENTATION
#ifndef CBF_IMPLEMENTATION_DONE
#define CBF_IMPLEMENTATION_DONE

/* ---- the model's vocabulary, numbered --------------------------------- */
enum { CBF__CK_NONE = 0, CBF__CK_ARGS, CBF__CK_HEADER, CBF__CK_FILE };
enum { CBF__REGION_NONE = 0, CBF__REGION_FILE, CBF__REGION_HEADER, CBF__REGION_RECORDS, CBF__REGION_ARGS, CBF__REGION_FIELDS };
enum { CBF__MOTION_NONE = 0, CBF__MOTION_POINT, CBF__MOTION_LINE, CBF__MOTION_CIRCLE, CBF__MOTION_HELIX };
enum { CBF__M_START = 0, CBF__M_END = 1, CBF__M_CENTER = 2, CBF__M_NORMAL = 3, CBF__M_DEGREES = 4, CBF__M_LENGTH = 5, CBF__M_THROUGH = 6, CBF__M__COUNT };
enum { CBF__ORIENT_NONE = 0, CBF__ORIENT_SET, CBF__ORIENT_PATH };
enum { CBF__O_START = 0, CBF__O_END = 1, CBF__O__COUNT };
enum { CBF__SHAPE_NONE = 0, CBF__SHAPE_START, CBF__SHAPE_END };
enum { CBF__S_NAME = 0, CBF__S_COUNT = 1, CBF__S__COUNT };
/* The cutter role's keys: the table's columns, the name's first, then value[0..CBF_CUTTER_VALUES). */
enum { CBF__C_NAME = 0, CBF__C_LENGTH = 1, CBF__C_RADIUS = 2, CBF__C__COUNT };
#if 3 != CBF_CUTTER_VALUES + 1
#error "the cutter role's keys are the name and the cutter table's values"
#endif
static const char *const cbf__cutter_keys[CBF__C__COUNT] = { "name", "length", "radius" };
/* The check kinds of the spec language's registry (cbfgen/registry.py), in its order. The kernels of
 * the targeted kinds are called through tables indexed by kind (validator_layouts.c.j2): a targeted kind
 * the registry gains and the engine lacks fails the build. */
enum cbf__kind {
    CBF__KIND_TRUNCATED_HEADER = 1,
    CBF__KIND_TRUNCATED_RECORD = 2,
    CBF__KIND_PART_NUMBER = 3,
    CBF__KIND_DESCRIPTOR_WORD = 4,
    CBF__KIND_CUTTER_TABLE = 5,
    CBF__KIND_FILE_CHECKSUM = 6,
    CBF__KIND_COMMAND_COUNT = 7,
    CBF__KIND_HEADER_CHECKSUM = 8,
    CBF__KIND_MAGIC = 9,
    CBF__KIND_SEQUENCE = 10,
    CBF__KIND_CODE_COPY = 11,
    CBF__KIND_ARG_SIZE = 12,
    CBF__KIND_ARG_CHECKSUM = 13,
    CBF__KIND_CONTINUITY = 14,
    CBF__KIND_AVAILABILITY = 15,
    CBF__KIND_VERSION = 16,
    CBF__KIND_UNKNOWN_CODE = 17,
    CBF__KIND_TRAILING = 18,
    CBF__KIND_RESERVED_BYTE = 19,
    CBF__KIND_STRING_TAIL = 20,
    CBF__KIND_STRING_ASCII = 21,
    CBF__KIND_FINITE = 22,
    CBF__KIND_POSITIVE = 23,
    CBF__KIND_NONZERO_VECTOR = 24,
    CBF__KIND_RANGE = 25,
    CBF__KIND_NONDECREASING = 26,
    CBF__KIND_ORDERED = 27,
    CBF__KIND_ORIENTATION = 28,
    CBF__KIND_SHAPE = 29,
    CBF__KIND_MACHINE_LIMITS = 30,
    CBF__KIND_DEPRECATED = 31
};
#define CBF__PAD 0u
#define CBF__NVERSIONS 4
#define CBF__NCOMMANDS 27
#define CBF__NCHECKS 33
#define CBF__NTARGETS 25
#define CBF__MAX_CANDIDATES 2
/* 1 when a layout has a repeated argument group (issue 25, point 3): with 0, the group's branches
 * fold away and a file of fixed layouts is read exactly as before groups existed. */
#define CBF__HAS_GROUPS 0
#define CBF__MAX_COVERAGES 1

#define CBF__LITTLE_ENDIAN 1
#define CBF__DEFAULT_PROFILE CBF_PROFILE_DEFAULT
#define CBF__VERSION_MAJOR_OFFSET 16u

/* The record head's fields by role, read with their offsets and widths as constants
 * (0 when the model has no such field), for cbf_validate (runtime/validate.c). */
#define CBF__HEAD_ARG_SIZE(p) cbf__get_u((p) + 4u, 1u)
#define CBF__HEAD_OFF_ARG_SIZE 4u
#define CBF__HEAD_CODE(p) cbf__get_u((p) + 2u, 1u)
#define CBF__HEAD_OFF_CODE 2u
#define CBF__HEAD_CODE_COPY(p) cbf__get_u((p) + 3u, 1u)
#define CBF__HEAD_OFF_CODE_COPY 3u
#define CBF__HEAD_SEQUENCE(p) cbf__get_u((p) + 0u, 2u)
#define CBF__HEAD_OFF_SEQUENCE 0u
#define CBF__HEAD_RESERVED(p) cbf__get_u((p) + 5u, 1u)
#define CBF__HEAD_OFF_RESERVED 5u
#define CBF__SEQUENCE_MASK 0xFFFFu
/* the record head's argument checksum (CBF__HEAD_CK_ELEM 0: the model has none) */
#define CBF__HEAD_CK_ELEM 2u
#define CBF__HEAD_CK_OFFSET 6u
#define CBF__HEAD_CK_MASK 0xFFFFu
#define CBF__HEAD_SUM(p) cbf__sum_fixed((p), CBF_RECORD_HEAD_SIZE)
/* ==== BEGIN runtime/prologue.h: verbatim from generator/cbfgen/emit/c/runtime/prologue.h, edit it there ==== */
#line 1 "generator/cbfgen/emit/c/runtime/prologue.h"
/* ---- the implementation's prologue: headers, compiler shims, short names -- */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h> /* strtof, strtod: the CUT reader's numbers (runtime/cut.c) */
#include <string.h>

#ifdef __cplusplus
extern "C" {
#endif

/* binary32 and binary64 go through uint32_t and uint64_t with memcpy: the sizes must agree. */
typedef char cbf__assert_float_size[(sizeof(float) == sizeof(uint32_t)) ? 1 : -1];
typedef char cbf__assert_double_size[(sizeof(double) == sizeof(uint64_t)) ? 1 : -1];
typedef char cbf__assert_char_bits[(((unsigned char)-1) == 255) ? 1 : -1];

#if defined(__GNUC__) || defined(__clang__)
#define CBF__PRINTF(f, a) __attribute__((format(printf, f, a)))
/* The record loops' functions start on a cache line: their speed then no longer depends on where
 * the rest of the header happens to put them (measured: up to 8 % either way without it). */
#define CBF__HOT __attribute__((aligned(64)))
#else
#define CBF__PRINTF(f, a)
#define CBF__HOT
#endif

#define CBF__F_RESERVED CBF_FIELD_RESERVED
#define CBF__F_TEXT CBF_FIELD_TEXT
#define CBF__F_MAGIC CBF_FIELD_MAGIC
#define CBF__K_UINT CBF_KIND_UINT
#define CBF__K_SINT CBF_KIND_SINT
#define CBF__K_FLOAT CBF_KIND_FLOAT
#define CBF__K_STRING CBF_KIND_STRING
#define CBF__K_BYTES CBF_KIND_BYTES
#define CBF__VBIT(v) CBF_VERSION_BIT(v)
#define CBF__PBIT(p) (1u << (p))
#define CBF__PI 3.14159265358979323846
/* ==== END runtime/prologue.h ==== */
#line 1294 "cbf.h"
/* ==== BEGIN runtime/tables.h: verbatim from generator/cbfgen/emit/c/runtime/tables.h, edit it there ==== */
#line 1 "generator/cbfgen/emit/c/runtime/tables.h"
/* ---- the shapes of the spec's tables (filled by the generated section that follows) -- */
typedef struct cbf__version {
    const char *id;
    int major, minor; /* minor -1: any */
    int header;
    int writable;
} cbf__version;

typedef struct cbf__header_layout {
    const cbf_field_info *fields;
    size_t nfields;
    size_t size;
    size_t member; /* offsetof in cbf_header */
} cbf__header_layout;

typedef struct cbf__layout {
    int command;        /* index into cbf__commands */
    const char *variant;
    unsigned versions;  /* CBF__VBIT mask */
    unsigned profiles;  /* CBF__PBIT mask; 0: every profile */
    size_t size;
    size_t first_arg, nargs;
    size_t member;      /* offsetof in cbf_args (always 0: a union) */
    signed char motion[CBF__M__COUNT];
    signed char orient[CBF__O__COUNT];
    signed char shape[CBF__S__COUNT];
    signed char cutter[CBF__C__COUNT];
    signed char progress;
    /* A repeated argument group (issue 25, point 3): its index in the layout (the last argument; -1:
     * none); a record holds n items, group_min <= n <= group_max, nb = size + group_item * n; the
     * decoded struct keeps them in a bounded array and n at offset group_n of cbf_args. */
    signed char group;
    unsigned group_min, group_max;
    size_t group_item;
    size_t group_n;
} cbf__layout;

typedef struct cbf__command {
    int code;
    const char *name;
    int first_layout, nlayouts;
    unsigned versions;
    int motion, orient, shape, cutter;
    signed char candidates[CBF__NVERSIONS][CBF__MAX_CANDIDATES]; /* decode order per version, -1 ends */
} cbf__command;

typedef struct cbf__segment {
    int region;
    size_t start;
    long end;          /* -1: none */
    unsigned exclude;  /* record head fields left out (bit = index in cbf__record_fields) */
} cbf__segment;

typedef struct cbf__coverage { const char *name; size_t first, n; } cbf__coverage;

/* A checksum field among a layout's arguments (issue 25, point 1): layout (cbf__layouts), its row
 * of cbf__ckfields (algorithm, judging check, tag), the argument's offset and width, and the record
 * byte ranges (cbf__argck_ranges[first .. first + n)) it covers, fed in order. */
typedef struct cbf__argck { int layout; int ckfield; unsigned offset, elem; size_t first, n; } cbf__argck;
typedef struct cbf__range { unsigned start, end; } cbf__range;

/* check: the header_checksum check that judges the field (index in cbf__checks), -1 none; name: its tag */
typedef struct cbf__ckfield { int tag; int alg; int coverage; int check; const char *name; } cbf__ckfield;

typedef struct cbf__profile {
    const char *id;
    int file[CBF__MAX_COVERAGES]; /* coverages accepted for the file checksum, -1 ends */
    int hint[CBF__MAX_COVERAGES]; /* coverages named in the message when they match */
    int file_alg;                 /* the file checksum's algorithm under this profile */
    int hint_alg[CBF__MAX_COVERAGES]; /* each hint computed as the profile that accepts it */
    int hint_owner[CBF__MAX_COVERAGES]; /* that profile (its index; -1: none accepts it) */
} cbf__profile;

typedef struct cbf__target { int command; size_t first, n; } cbf__target;

typedef struct cbf__check {
    const char *id;
    int kind;
    int severity;
    unsigned versions;
    size_t first_target, ntargets;
    int has_min; double min;
    int has_max; double max;
    int min_open, max_open; /* range: the bound excludes its value (> min, < max) */
} cbf__check;

static const double cbf__tol_position = CBF_TOLERANCE_POSITION_MM;
static const double cbf__tol_orientation = CBF_TOLERANCE_ORIENTATION_DEG;
static const double cbf__tol_cutter = CBF_TOLERANCE_CUTTER_MM;
/* ==== END runtime/tables.h ==== */
#line 1387 "cbf.h"
/* ---- checksum algorithm kinds (cbfgen/registry.py ALGORITHMS), as parameters ------------
 * runtime/checksums.c implements each family once and switches on it with no default (a family
 * the registry gains and the engine lacks is a -Wswitch error); a kind is a row here. A CRC's
 * register is kept reflected (refin) or left-aligned in 32 bits; init is in that form and table
 * is its byte table, computed by the generator from the parameters (cbfgen/emit/c/algorithms.py). */
enum { CBF__ALG_NONE = 0, CBF__ALG_SUM, CBF__ALG_CRC16_CCITT, CBF__ALG_CRC32, CBF__ALG_CRC32C, CBF__ALG_FLETCHER16, CBF__ALG_FLETCHER32, CBF__ALG__COUNT };
typedef enum cbf__family {
    CBF__FAMILY_SUM,
    CBF__FAMILY_CRC,
    CBF__FAMILY_FLETCHER
} cbf__family;
typedef struct cbf__alg {
    cbf__family family;
    unsigned width;           /* bits of the result (0: a sum, reduced to its field) */
    uint32_t init;            /* a CRC register's first value, in the form it is kept */
    int refin, refout;
    uint32_t xorout;
    const uint32_t *table;    /* a CRC's byte table; NULL for the other families */
} cbf__alg;
/* crc16_ccitt: CRC-16/CCITT-FALSE (CRC-16/IBM-3740): poly 0x1021, init 0xFFFF, refin false, refout false, xorout 0x0 */
static const uint32_t cbf__crc_CRC16_CCITT[256] = {
0x00000000u, 0x10210000u, 0x20420000u, 0x30630000u, 0x40840000u, 0x50A50000u,
0x60C60000u, 0x70E70000u, 0x81080000u, 0x91290000u, 0xA14A0000u, 0xB16B0000u,
0xC18C0000u, 0xD1AD0000u, 0xE1CE0000u, 0xF1EF0000u, 0x12310000u, 0x02100000u,
0x32730000u, 0x22520000u, 0x52B50000u, 0x42940000u, 0x72F70000u, 0x62D60000u,
0x93390000u, 0x83180000u, 0xB37B0000u, 0xA35A0000u, 0xD3BD0000u, 0xC39C0000u,
0xF3FF0000u, 0xE3DE0000u, 0x24620000u, 0x34430000u, 0x04200000u, 0x14010000u,
0x64E60000u, 0x74C70000u, 0x44A40000u, 0x54850000u, 0xA56A0000u, 0xB54B0000u,
0x85280000u, 0x95090000u, 0xE5EE0000u, 0xF5CF0000u, 0xC5AC0000u, 0xD58D0000u,
0x36530000u, 0x26720000u, 0x16110000u, 0x06300000u, 0x76D70000u, 0x66F60000u,
0x56950000u, 0x46B40000u, 0xB75B0000u, 0xA77A0000u, 0x97190000u, 0x87380000u,
0xF7DF0000u, 0xE7FE0000u, 0xD79D0000u, 0xC7BC0000u, 0x48C40000u, 0x58E50000u,
0x68860000u, 0x78A70000u, 0x08400000u, 0x18610000u, 0x28020000u, 0x38230000u,
0xC9CC0000u, 0xD9ED0000u, 0xE98E0000u, 0xF9AF0000u, 0x89480000u, 0x99690000u,
0xA90A0000u, 0xB92B0000u, 0x5AF50000u, 0x4AD40000u, 0x7AB70000u, 0x6A960000u,
0x1A710000u, 0x0A500000u, 0x3A330000u, 0x2A120000u, 0xDBFD0000u, 0xCBDC0000u,
0xFBBF0000u, 0xEB9E0000u, 0x9B790000u, 0x8B580000u, 0xBB3B0000u, 0xAB1A0000u,
0x6CA60000u, 0x7C870000u, 0x4CE40000u, 0x5CC50000u, 0x2C220000u, 0x3C030000u,
0x0C600000u, 0x1C410000u, 0xEDAE0000u, 0xFD8F0000u, 0xCDEC0000u, 0xDDCD0000u,
0xAD2A0000u, 0xBD0B0000u, 0x8D680000u, 0x9D490000u, 0x7E970000u, 0x6EB60000u,
0x5ED50000u, 0x4EF40000u, 0x3E130000u, 0x2E320000u, 0x1E510000u, 0x0E700000u,
0xFF9F0000u, 0xEFBE0000u, 0xDFDD0000u, 0xCFFC0000u, 0xBF1B0000u, 0xAF3A0000u,
0x9F590000u, 0x8F780000u, 0x91880000u, 0x81A90000u, 0xB1CA0000u, 0xA1EB0000u,
0xD10C0000u, 0xC12D0000u, 0xF14E0000u, 0xE16F0000u, 0x10800000u, 0x00A10000u,
0x30C20000u, 0x20E30000u, 0x50040000u, 0x40250000u, 0x70460000u, 0x60670000u,
0x83B90000u, 0x93980000u, 0xA3FB0000u, 0xB3DA0000u, 0xC33D0000u, 0xD31C0000u,
0xE37F0000u, 0xF35E0000u, 0x02B10000u, 0x12900000u, 0x22F30000u, 0x32D20000u,
0x42350000u, 0x52140000u, 0x62770000u, 0x72560000u, 0xB5EA0000u, 0xA5CB0000u,
0x95A80000u, 0x85890000u, 0xF56E0000u, 0xE54F0000u, 0xD52C0000u, 0xC50D0000u,
0x34E20000u, 0x24C30000u, 0x14A00000u, 0x04810000u, 0x74660000u, 0x64470000u,
0x54240000u, 0x44050000u, 0xA7DB0000u, 0xB7FA0000u, 0x87990000u, 0x97B80000u,
0xE75F0000u, 0xF77E0000u, 0xC71D0000u, 0xD73C0000u, 0x26D30000u, 0x36F20000u,
0x06910000u, 0x16B00000u, 0x66570000u, 0x76760000u, 0x46150000u, 0x56340000u,
0xD94C0000u, 0xC96D0000u, 0xF90E0000u, 0xE92F0000u, 0x99C80000u, 0x89E90000u,
0xB98A0000u, 0xA9AB0000u, 0x58440000u, 0x48650000u, 0x78060000u, 0x68270000u,
0x18C00000u, 0x08E10000u, 0x38820000u, 0x28A30000u, 0xCB7D0000u, 0xDB5C0000u,
0xEB3F0000u, 0xFB1E0000u, 0x8BF90000u, 0x9BD80000u, 0xABBB0000u, 0xBB9A0000u,
0x4A750000u, 0x5A540000u, 0x6A370000u, 0x7A160000u, 0x0AF10000u, 0x1AD00000u,
0x2AB30000u, 0x3A920000u, 0xFD2E0000u, 0xED0F0000u, 0xDD6C0000u, 0xCD4D0000u,
0xBDAA0000u, 0xAD8B0000u, 0x9DE80000u, 0x8DC90000u, 0x7C260000u, 0x6C070000u,
0x5C640000u, 0x4C450000u, 0x3CA20000u, 0x2C830000u, 0x1CE00000u, 0x0CC10000u,
0xEF1F0000u, 0xFF3E0000u, 0xCF5D0000u, 0xDF7C0000u, 0xAF9B0000u, 0xBFBA0000u,
0x8FD90000u, 0x9FF80000u, 0x6E170000u, 0x7E360000u, 0x4E550000u, 0x5E740000u,
0x2E930000u, 0x3EB20000u, 0x0ED10000u, 0x1EF00000u,
};
/* crc32: CRC-32/ISO-HDLC: poly 0x4C11DB7, init 0xFFFFFFFF, refin true, refout true, xorout 0xFFFFFFFF */
static const uint32_t cbf__crc_CRC32[256] = {
0x00000000u, 0x77073096u, 0xEE0E612Cu, 0x990951BAu, 0x076DC419u, 0x706AF48Fu,
0xE963A535u, 0x9E6495A3u, 0x0EDB8832u, 0x79DCB8A4u, 0xE0D5E91Eu, 0x97D2D988u,
0x09B64C2Bu, 0x7EB17CBDu, 0xE7B82D07u, 0x90BF1D91u, 0x1DB71064u, 0x6AB020F2u,
0xF3B97148u, 0x84BE41DEu, 0x1ADAD47Du, 0x6DDDE4EBu, 0xF4D4B551u, 0x83D385C7u,
0x136C9856u, 0x646BA8C0u, 0xFD62F97Au, 0x8A65C9ECu, 0x14015C4Fu, 0x63066CD9u,
0xFA0F3D63u, 0x8D080DF5u, 0x3B6E20C8u, 0x4C69105Eu, 0xD56041E4u, 0xA2677172u,
0x3C03E4D1u, 0x4B04D447u, 0xD20D85FDu, 0xA50AB56Bu, 0x35B5A8FAu, 0x42B2986Cu,
0xDBBBC9D6u, 0xACBCF940u, 0x32D86CE3u, 0x45DF5C75u, 0xDCD60DCFu, 0xABD13D59u,
0x26D930ACu, 0x51DE003Au, 0xC8D75180u, 0xBFD06116u, 0x21B4F4B5u, 0x56B3C423u,
0xCFBA9599u, 0xB8BDA50Fu, 0x2802B89Eu, 0x5F058808u, 0xC60CD9B2u, 0xB10BE924u,
0x2F6F7C87u, 0x58684C11u, 0xC1611DABu, 0xB6662D3Du, 0x76DC4190u, 0x01DB7106u,
0x98D220BCu, 0xEFD5102Au, 0x71B18589u, 0x06B6B51Fu, 0x9FBFE4A5u, 0xE8B8D433u,
0x7807C9A2u, 0x0F00F934u, 0x9609A88Eu, 0xE10E9818u, 0x7F6A0DBBu, 0x086D3D2Du,
0x91646C97u, 0xE6635C01u, 0x6B6B51F4u, 0x1C6C6162u, 0x856530D8u, 0xF262004Eu,
0x6C0695EDu, 0x1B01A57Bu, 0x8208F4C1u, 0xF50FC457u, 0x65B0D9C6u, 0x12B7E950u,
0x8BBEB8EAu, 0xFCB9887Cu, 0x62DD1DDFu, 0x15DA2D49u, 0x8CD37CF3u, 0xFBD44C65u,
0x4DB26158u, 0x3AB551CEu, 0xA3BC0074u, 0xD4BB30E2u, 0x4ADFA541u, 0x3DD895D7u,
0xA4D1C46Du, 0xD3D6F4FBu, 0x4369E96Au, 0x346ED9FCu, 0xAD678846u, 0xDA60B8D0u,
0x44042D73u, 0x33031DE5u, 0xAA0A4C5Fu, 0xDD0D7CC9u, 0x5005713Cu, 0x270241AAu,
0xBE0B1010u, 0xC90C2086u, 0x5768B525u, 0x206F85B3u, 0xB966D409u, 0xCE61E49Fu,
0x5EDEF90Eu, 0x29D9C998u, 0xB0D09822u, 0xC7D7A8B4u, 0x59B33D17u, 0x2EB40D81u,
0xB7BD5C3Bu, 0xC0BA6CADu, 0xEDB88320u, 0x9ABFB3B6u, 0x03B6E20Cu, 0x74B1D29Au,
0xEAD54739u, 0x9DD277AFu, 0x04DB2615u, 0x73DC1683u, 0xE3630B12u, 0x94643B84u,
0x0D6D6A3Eu, 0x7A6A5AA8u, 0xE40ECF0Bu, 0x9309FF9Du, 0x0A00AE27u, 0x7D079EB1u,
0xF00F9344u, 0x8708A3D2u, 0x1E01F268u, 0x6906C2FEu, 0xF762575Du, 0x806567CBu,
0x196C3671u, 0x6E6B06E7u, 0xFED41B76u, 0x89D32BE0u, 0x10DA7A5Au, 0x67DD4ACCu,
0xF9B9DF6Fu, 0x8EBEEFF9u, 0x17B7BE43u, 0x60B08ED5u, 0xD6D6A3E8u, 0xA1D1937Eu,
0x38D8C2C4u, 0x4FDFF252u, 0xD1BB67F1u, 0xA6BC5767u, 0x3FB506DDu, 0x48B2364Bu,
0xD80D2BDAu, 0xAF0A1B4Cu, 0x36034AF6u, 0x41047A60u, 0xDF60EFC3u, 0xA867DF55u,
0x316E8EEFu, 0x4669BE79u, 0xCB61B38Cu, 0xBC66831Au, 0x256FD2A0u, 0x5268E236u,
0xCC0C7795u, 0xBB0B4703u, 0x220216B9u, 0x5505262Fu, 0xC5BA3BBEu, 0xB2BD0B28u,
0x2BB45A92u, 0x5CB36A04u, 0xC2D7FFA7u, 0xB5D0CF31u, 0x2CD99E8Bu, 0x5BDEAE1Du,
0x9B64C2B0u, 0xEC63F226u, 0x756AA39Cu, 0x026D930Au, 0x9C0906A9u, 0xEB0E363Fu,
0x72076785u, 0x05005713u, 0x95BF4A82u, 0xE2B87A14u, 0x7BB12BAEu, 0x0CB61B38u,
0x92D28E9Bu, 0xE5D5BE0Du, 0x7CDCEFB7u, 0x0BDBDF21u, 0x86D3D2D4u, 0xF1D4E242u,
0x68DDB3F8u, 0x1FDA836Eu, 0x81BE16CDu, 0xF6B9265Bu, 0x6FB077E1u, 0x18B74777u,
0x88085AE6u, 0xFF0F6A70u, 0x66063BCAu, 0x11010B5Cu, 0x8F659EFFu, 0xF862AE69u,
0x616BFFD3u, 0x166CCF45u, 0xA00AE278u, 0xD70DD2EEu, 0x4E048354u, 0x3903B3C2u,
0xA7672661u, 0xD06016F7u, 0x4969474Du, 0x3E6E77DBu, 0xAED16A4Au, 0xD9D65ADCu,
0x40DF0B66u, 0x37D83BF0u, 0xA9BCAE53u, 0xDEBB9EC5u, 0x47B2CF7Fu, 0x30B5FFE9u,
0xBDBDF21Cu, 0xCABAC28Au, 0x53B39330u, 0x24B4A3A6u, 0xBAD03605u, 0xCDD70693u,
0x54DE5729u, 0x23D967BFu, 0xB3667A2Eu, 0xC4614AB8u, 0x5D681B02u, 0x2A6F2B94u,
0xB40BBE37u, 0xC30C8EA1u, 0x5A05DF1Bu, 0x2D02EF8Du,
};
/* crc32c: CRC-32/ISCSI (Castagnoli): poly 0x1EDC6F41, init 0xFFFFFFFF, refin true, refout true, xorout 0xFFFFFFFF */
static const uint32_t cbf__crc_CRC32C[256] = {
0x00000000u, 0xF26B8303u, 0xE13B70F7u, 0x1350F3F4u, 0xC79A971Fu, 0x35F1141Cu,
0x26A1E7E8u, 0xD4CA64EBu, 0x8AD958CFu, 0x78B2DBCCu, 0x6BE22838u, 0x9989AB3Bu,
0x4D43CFD0u, 0xBF284CD3u, 0xAC78BF27u, 0x5E133C24u, 0x105EC76Fu, 0xE235446Cu,
0xF165B798u, 0x030E349Bu, 0xD7C45070u, 0x25AFD373u, 0x36FF2087u, 0xC494A384u,
0x9A879FA0u, 0x68EC1CA3u, 0x7BBCEF57u, 0x89D76C54u, 0x5D1D08BFu, 0xAF768BBCu,
0xBC267848u, 0x4E4DFB4Bu, 0x20BD8EDEu, 0xD2D60DDDu, 0xC186FE29u, 0x33ED7D2Au,
0xE72719C1u, 0x154C9AC2u, 0x061C6936u, 0xF477EA35u, 0xAA64D611u, 0x580F5512u,
0x4B5FA6E6u, 0xB93425E5u, 0x6DFE410Eu, 0x9F95C20Du, 0x8CC531F9u, 0x7EAEB2FAu,
0x30E349B1u, 0xC288CAB2u, 0xD1D83946u, 0x23B3BA45u, 0xF779DEAEu, 0x05125DADu,
0x1642AE59u, 0xE4292D5Au, 0xBA3A117Eu, 0x4851927Du, 0x5B016189u, 0xA96AE28Au,
0x7DA08661u, 0x8FCB0562u, 0x9C9BF696u, 0x6EF07595u, 0x417B1DBCu, 0xB3109EBFu,
0xA0406D4Bu, 0x522BEE48u, 0x86E18AA3u, 0x748A09A0u, 0x67DAFA54u, 0x95B17957u,
0xCBA24573u, 0x39C9C670u, 0x2A993584u, 0xD8F2B687u, 0x0C38D26Cu, 0xFE53516Fu,
0xED03A29Bu, 0x1F682198u, 0x5125DAD3u, 0xA34E59D0u, 0xB01EAA24u, 0x42752927u,
0x96BF4DCCu, 0x64D4CECFu, 0x77843D3Bu, 0x85EFBE38u, 0xDBFC821Cu, 0x2997011Fu,
0x3AC7F2EBu, 0xC8AC71E8u, 0x1C661503u, 0xEE0D9600u, 0xFD5D65F4u, 0x0F36E6F7u,
0x61C69362u, 0x93AD1061u, 0x80FDE395u, 0x72966096u, 0xA65C047Du, 0x5437877Eu,
0x4767748Au, 0xB50CF789u, 0xEB1FCBADu, 0x197448AEu, 0x0A24BB5Au, 0xF84F3859u,
0x2C855CB2u, 0xDEEEDFB1u, 0xCDBE2C45u, 0x3FD5AF46u, 0x7198540Du, 0x83F3D70Eu,
0x90A324FAu, 0x62C8A7F9u, 0xB602C312u, 0x44694011u, 0x5739B3E5u, 0xA55230E6u,
0xFB410CC2u, 0x092A8FC1u, 0x1A7A7C35u, 0xE811FF36u, 0x3CDB9BDDu, 0xCEB018DEu,
0xDDE0EB2Au, 0x2F8B6829u, 0x82F63B78u, 0x709DB87Bu, 0x63CD4B8Fu, 0x91A6C88Cu,
0x456CAC67u, 0xB7072F64u, 0xA457DC90u, 0x563C5F93u, 0x082F63B7u, 0xFA44E0B4u,
0xE9141340u, 0x1B7F9043u, 0xCFB5F4A8u, 0x3DDE77ABu, 0x2E8E845Fu, 0xDCE5075Cu,
0x92A8FC17u, 0x60C37F14u, 0x73938CE0u, 0x81F80FE3u, 0x55326B08u, 0xA759E80Bu,
0xB4091BFFu, 0x466298FCu, 0x1871A4D8u, 0xEA1A27DBu, 0xF94AD42Fu, 0x0B21572Cu,
0xDFEB33C7u, 0x2D80B0C4u, 0x3ED04330u, 0xCCBBC033u, 0xA24BB5A6u, 0x502036A5u,
0x4370C551u, 0xB11B4652u, 0x65D122B9u, 0x97BAA1BAu, 0x84EA524Eu, 0x7681D14Du,
0x2892ED69u, 0xDAF96E6Au, 0xC9A99D9Eu, 0x3BC21E9Du, 0xEF087A76u, 0x1D63F975u,
0x0E330A81u, 0xFC588982u, 0xB21572C9u, 0x407EF1CAu, 0x532E023Eu, 0xA145813Du,
0x758FE5D6u, 0x87E466D5u, 0x94B49521u, 0x66DF1622u, 0x38CC2A06u, 0xCAA7A905u,
0xD9F75AF1u, 0x2B9CD9F2u, 0xFF56BD19u, 0x0D3D3E1Au, 0x1E6DCDEEu, 0xEC064EEDu,
0xC38D26C4u, 0x31E6A5C7u, 0x22B65633u, 0xD0DDD530u, 0x0417B1DBu, 0xF67C32D8u,
0xE52CC12Cu, 0x1747422Fu, 0x49547E0Bu, 0xBB3FFD08u, 0xA86F0EFCu, 0x5A048DFFu,
0x8ECEE914u, 0x7CA56A17u, 0x6FF599E3u, 0x9D9E1AE0u, 0xD3D3E1ABu, 0x21B862A8u,
0x32E8915Cu, 0xC083125Fu, 0x144976B4u, 0xE622F5B7u, 0xF5720643u, 0x07198540u,
0x590AB964u, 0xAB613A67u, 0xB831C993u, 0x4A5A4A90u, 0x9E902E7Bu, 0x6CFBAD78u,
0x7FAB5E8Cu, 0x8DC0DD8Fu, 0xE330A81Au, 0x115B2B19u, 0x020BD8EDu, 0xF0605BEEu,
0x24AA3F05u, 0xD6C1BC06u, 0xC5914FF2u, 0x37FACCF1u, 0x69E9F0D5u, 0x9B8273D6u,
0x88D28022u, 0x7AB90321u, 0xAE7367CAu, 0x5C18E4C9u, 0x4F48173Du, 0xBD23943Eu,
0xF36E6F75u, 0x0105EC76u, 0x12551F82u, 0xE03E9C81u, 0x34F4F86Au, 0xC69F7B69u,
0xD5CF889Du, 0x27A40B9Eu, 0x79B737BAu, 0x8BDCB4B9u, 0x988C474Du, 0x6AE7C44Eu,
0xBE2DA0A5u, 0x4C4623A6u, 0x5F16D052u, 0xAD7D5351u,
};
static const cbf__alg cbf__algs[CBF__ALG__COUNT] = {
    { CBF__FAMILY_SUM, 0u, 0u, 0, 0, 0u, NULL }, /* CBF__ALG_NONE: never computed */
    { CBF__FAMILY_SUM, 0u, 0x00000000u, 0, 0, 0x00000000u, NULL }, /* sum */
    { CBF__FAMILY_CRC, 16u, 0xFFFF0000u, 0, 0, 0x00000000u, cbf__crc_CRC16_CCITT }, /* crc16_ccitt */
    { CBF__FAMILY_CRC, 32u, 0xFFFFFFFFu, 1, 1, 0xFFFFFFFFu, cbf__crc_CRC32 }, /* crc32 */
    { CBF__FAMILY_CRC, 32u, 0xFFFFFFFFu, 1, 1, 0xFFFFFFFFu, cbf__crc_CRC32C }, /* crc32c */
    { CBF__FAMILY_FLETCHER, 16u, 0x00000000u, 0, 0, 0x00000000u, NULL }, /* fletcher16 */
    { CBF__FAMILY_FLETCHER, 32u, 0x00000000u, 0, 0, 0x00000000u, NULL } /* fletcher32 */
};
/* ---- the spec as tables (their shapes: runtime/tables.h) ------------------ */

static const cbf__version cbf__versions[CBF__NVERSIONS] = {
    { "1.x", 1, -1, 1, 0 },
    { "2.x", 2, -1, 0, 0 },
    { "3.0", 3, 0, 0, 1 },
    { "4.0", 4, 0, 0, 1 },
};

static const cbf_field_info cbf__header_v2_fields[10] = {
    { "start_pattern", NULL, CBF__K_UINT, CBF_ROLE_START_PATTERN, CBF__F_MAGIC, CBF__CK_NONE, 0, 4, 1, offsetof(struct cbf_header_v2, start_pattern), 0x53A1B792u },
    { "file_checksum", NULL, CBF__K_UINT, CBF_ROLE_CHECKSUM, 0, CBF__CK_FILE, 4, 4, 1, offsetof(struct cbf_header_v2, file_checksum), 0u },
    { "header_checksum", NULL, CBF__K_UINT, CBF_ROLE_CHECKSUM, 0, CBF__CK_HEADER, 8, 2, 1, offsetof(struct cbf_header_v2, header_checksum), 0u },
    { "reserved_ecc", NULL, CBF__K_BYTES, CBF_ROLE_RESERVED, 0, CBF__CK_NONE, 10, 6, 1, offsetof(struct cbf_header_v2, reserved_ecc), 0u },
    { "version_major", NULL, CBF__K_UINT, CBF_ROLE_VERSION_MAJOR, 0, CBF__CK_NONE, 16, 1, 1, offsetof(struct cbf_header_v2, version_major), 0u },
    { "version_minor", NULL, CBF__K_UINT, CBF_ROLE_VERSION_MINOR, 0, CBF__CK_NONE, 17, 1, 1, offsetof(struct cbf_header_v2, version_minor), 0u },
    { "implant_descriptor", NULL, CBF__K_STRING, CBF_ROLE_IMPLANT_DESCRIPTOR, 0, CBF__CK_NONE, 18, 70, 1, offsetof(struct cbf_header_v2, implant_descriptor), 0u },
    { "configuration_descriptor", NULL, CBF__K_STRING, CBF_ROLE_CONFIGURATION_DESCRIPTOR, 0, CBF__CK_NONE, 88, 34, 1, offsetof(struct cbf_header_v2, configuration_descriptor), 0u },
    { "command_count", NULL, CBF__K_UINT, CBF_ROLE_COMMAND_COUNT, 0, CBF__CK_NONE, 122, 2, 1, offsetof(struct cbf_header_v2, command_count), 0u },
    { "end_pattern", NULL, CBF__K_UINT, CBF_ROLE_END_PATTERN, CBF__F_MAGIC, CBF__CK_NONE, 124, 4, 1, offsetof(struct cbf_header_v2, end_pattern), 0xAC5E486Du },
};
static const cbf_field_info cbf__header_v1_fields[10] = {
    { "start_pattern", NULL, CBF__K_UINT, CBF_ROLE_START_PATTERN, CBF__F_MAGIC, CBF__CK_NONE, 0, 4, 1, offsetof(struct cbf_header_v1, start_pattern), 0x53A1B792u },
    { "file_checksum", NULL, CBF__K_UINT, CBF_ROLE_CHECKSUM, 0, CBF__CK_FILE, 4, 4, 1, offsetof(struct cbf_header_v1, file_checksum), 0u },
    { "header_checksum", NULL, CBF__K_UINT, CBF_ROLE_CHECKSUM, 0, CBF__CK_HEADER, 8, 2, 1, offsetof(struct cbf_header_v1, header_checksum), 0u },
    { "reserved_ecc", NULL, CBF__K_BYTES, CBF_ROLE_RESERVED, 0, CBF__CK_NONE, 10, 6, 1, offsetof(struct cbf_header_v1, reserved_ecc), 0u },
    { "version_major", NULL, CBF__K_UINT, CBF_ROLE_VERSION_MAJOR, 0, CBF__CK_NONE, 16, 1, 1, offsetof(struct cbf_header_v1, version_major), 0u },
    { "version_minor", NULL, CBF__K_UINT, CBF_ROLE_VERSION_MINOR, 0, CBF__CK_NONE, 17, 1, 1, offsetof(struct cbf_header_v1, version_minor), 0u },
    { "implant_descriptor", NULL, CBF__K_STRING, CBF_ROLE_IMPLANT_DESCRIPTOR, 0, CBF__CK_NONE, 18, 80, 1, offsetof(struct cbf_header_v1, implant_descriptor), 0u },
    { "reserved_98", NULL, CBF__K_BYTES, CBF_ROLE_RESERVED, 0, CBF__CK_NONE, 98, 24, 1, offsetof(struct cbf_header_v1, reserved_98), 0u },
    { "command_count", NULL, CBF__K_UINT, CBF_ROLE_COMMAND_COUNT, 0, CBF__CK_NONE, 122, 2, 1, offsetof(struct cbf_header_v1, command_count), 0u },
    { "end_pattern", NULL, CBF__K_UINT, CBF_ROLE_END_PATTERN, CBF__F_MAGIC, CBF__CK_NONE, 124, 4, 1, offsetof(struct cbf_header_v1, end_pattern), 0xAC5E486Du },
};

static const cbf__header_layout cbf__headers[2] = {
    { cbf__header_v2_fields, 10, 128, offsetof(cbf_header, u.v2) },
    { cbf__header_v1_fields, 10, 128, offsetof(cbf_header, u.v1) },
};

static const cbf_field_info cbf__record_fields[6] = {
    { "sequence", NULL, CBF__K_UINT, CBF_ROLE_SEQUENCE, 0, CBF__CK_NONE, 0, 2, 1, offsetof(struct cbf_record_head, sequence), 0u },
    { "code", NULL, CBF__K_UINT, CBF_ROLE_CODE, 0, CBF__CK_NONE, 2, 1, 1, offsetof(struct cbf_record_head, code), 0u },
    { "code_copy", NULL, CBF__K_UINT, CBF_ROLE_CODE_COPY, 0, CBF__CK_NONE, 3, 1, 1, offsetof(struct cbf_record_head, code_copy), 0u },
    { "arg_size", NULL, CBF__K_UINT, CBF_ROLE_ARG_SIZE, 0, CBF__CK_NONE, 4, 1, 1, offsetof(struct cbf_record_head, arg_size), 0u },
    { "reserved", NULL, CBF__K_UINT, CBF_ROLE_RESERVED, 0, CBF__CK_NONE, 5, 1, 1, offsetof(struct cbf_record_head, reserved), 0u },
    { "arg_checksum", NULL, CBF__K_UINT, CBF_ROLE_CHECKSUM, 0, CBF__CK_ARGS, 6, 2, 1, offsetof(struct cbf_record_head, arg_checksum), 0u },
};
#define CBF__NRECORD_FIELDS 6

static const cbf_field_info cbf__args[74] = {
    { "name", NULL, CBF__K_STRING, CBF_ROLE_NONE, 0, CBF__CK_NONE, 0, 16, 1, offsetof(struct cbf_checkpoint_args, name), 0u },
    { "recovery_point", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 16, 4, 3, offsetof(struct cbf_checkpoint_args, recovery_point), 0u },
    { "completion", "percent", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 28, 4, 1, offsetof(struct cbf_checkpoint_args, completion), 0u },
    { "name", NULL, CBF__K_STRING, CBF_ROLE_NONE, 0, CBF__CK_NONE, 0, 16, 1, offsetof(struct cbf_checkpoint_v1_args, name), 0u },
    { "name", NULL, CBF__K_STRING, CBF_ROLE_NONE, 0, CBF__CK_NONE, 0, 16, 1, offsetof(struct cbf_cutter_args, name), 0u },
    { "length", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 16, 4, 1, offsetof(struct cbf_cutter_args, length), 0u },
    { "radius", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 20, 4, 1, offsetof(struct cbf_cutter_args, radius), 0u },
    { "head_length", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 24, 4, 1, offsetof(struct cbf_cutter_args, head_length), 0u },
    { "reserved", NULL, CBF__K_BYTES, CBF_ROLE_NONE, CBF__F_RESERVED, CBF__CK_NONE, 28, 4, 1, offsetof(struct cbf_cutter_args, reserved), 0u },
    { "name", NULL, CBF__K_STRING, CBF_ROLE_NONE, 0, CBF__CK_NONE, 0, 16, 1, offsetof(struct cbf_cutter_v1_args, name), 0u },
    { "length", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 16, 4, 1, offsetof(struct cbf_cutter_v1_args, length), 0u },
    { "radius", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 20, 4, 1, offsetof(struct cbf_cutter_v1_args, radius), 0u },
    { "reserved", NULL, CBF__K_BYTES, CBF_ROLE_NONE, CBF__F_RESERVED, CBF__CK_NONE, 24, 8, 1, offsetof(struct cbf_cutter_v1_args, reserved), 0u },
    { "approach", NULL, CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 0, 4, 3, offsetof(struct cbf_orient_args, approach), 0u },
    { "reserved", NULL, CBF__K_BYTES, CBF_ROLE_NONE, CBF__F_RESERVED, CBF__CK_NONE, 12, 12, 1, offsetof(struct cbf_orient_args, reserved), 0u },
    { "start_approach", NULL, CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 0, 4, 3, offsetof(struct cbf_orient5b_args, start_approach), 0u },
    { "end_approach", NULL, CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 12, 4, 3, offsetof(struct cbf_orient5b_args, end_approach), 0u },
    { "name", NULL, CBF__K_STRING, CBF_ROLE_NONE, 0, CBF__CK_NONE, 0, 16, 1, offsetof(struct cbf_phase_args, name), 0u },
    { "name", NULL, CBF__K_STRING, CBF_ROLE_NONE, 0, CBF__CK_NONE, 0, 16, 1, offsetof(struct cbf_enable_skip_args, name), 0u },
    { "name", NULL, CBF__K_STRING, CBF_ROLE_NONE, 0, CBF__CK_NONE, 0, 5, 1, offsetof(struct cbf_startshape_args, name), 0u },
    { "moves", "count", CBF__K_UINT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 5, 1, 1, offsetof(struct cbf_startshape_args, moves), 0u },
    { "name", NULL, CBF__K_STRING, CBF_ROLE_NONE, 0, CBF__CK_NONE, 0, 5, 1, offsetof(struct cbf_endshape_args, name), 0u },
    { "moves", "count", CBF__K_UINT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 5, 1, 1, offsetof(struct cbf_endshape_args, moves), 0u },
    { "point", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 0, 4, 3, offsetof(struct cbf_point_args, point), 0u },
    { "start", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 0, 4, 3, offsetof(struct cbf_line_args, start), 0u },
    { "end", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 12, 4, 3, offsetof(struct cbf_line_args, end), 0u },
    { "start_pos", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 0, 4, 3, offsetof(struct cbf_line5b_args, start_pos), 0u },
    { "end_pos", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 12, 4, 3, offsetof(struct cbf_line5b_args, end_pos), 0u },
    { "start_orient", NULL, CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 24, 4, 3, offsetof(struct cbf_line5b_args, start_orient), 0u },
    { "end_orient", NULL, CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 36, 4, 3, offsetof(struct cbf_line5b_args, end_orient), 0u },
    { "start", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 0, 4, 3, offsetof(struct cbf_arc_args, start), 0u },
    { "middle", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 12, 4, 3, offsetof(struct cbf_arc_args, middle), 0u },
    { "end", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 24, 4, 3, offsetof(struct cbf_arc_args, end), 0u },
    { "start_pos", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 0, 4, 3, offsetof(struct cbf_arc5b_args, start_pos), 0u },
    { "mid_pos", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 12, 4, 3, offsetof(struct cbf_arc5b_args, mid_pos), 0u },
    { "end_pos", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 24, 4, 3, offsetof(struct cbf_arc5b_args, end_pos), 0u },
    { "start_orient", NULL, CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 36, 4, 3, offsetof(struct cbf_arc5b_args, start_orient), 0u },
    { "end_orient", NULL, CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 48, 4, 3, offsetof(struct cbf_arc5b_args, end_orient), 0u },
    { "start", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 0, 4, 3, offsetof(struct cbf_circle_args, start), 0u },
    { "center", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 12, 4, 3, offsetof(struct cbf_circle_args, center), 0u },
    { "normal", NULL, CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 24, 4, 3, offsetof(struct cbf_circle_args, normal), 0u },
    { "ndegrees", "deg", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 36, 4, 1, offsetof(struct cbf_circle_args, ndegrees), 0u },
    { "start", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 0, 4, 3, offsetof(struct cbf_circle5b_args, start), 0u },
    { "center", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 12, 4, 3, offsetof(struct cbf_circle5b_args, center), 0u },
    { "normal", NULL, CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 24, 4, 3, offsetof(struct cbf_circle5b_args, normal), 0u },
    { "ndegrees", "deg", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 36, 4, 1, offsetof(struct cbf_circle5b_args, ndegrees), 0u },
    { "start_orient", NULL, CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 40, 4, 3, offsetof(struct cbf_circle5b_args, start_orient), 0u },
    { "end_orient", NULL, CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 52, 4, 3, offsetof(struct cbf_circle5b_args, end_orient), 0u },
    { "start", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 0, 4, 3, offsetof(struct cbf_helix_args, start), 0u },
    { "center", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 12, 4, 3, offsetof(struct cbf_helix_args, center), 0u },
    { "normal", NULL, CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 24, 4, 3, offsetof(struct cbf_helix_args, normal), 0u },
    { "ndegrees", "deg", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 36, 4, 1, offsetof(struct cbf_helix_args, ndegrees), 0u },
    { "length", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 40, 4, 1, offsetof(struct cbf_helix_args, length), 0u },
    { "start", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 0, 4, 3, offsetof(struct cbf_helix5b_args, start), 0u },
    { "center", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 12, 4, 3, offsetof(struct cbf_helix5b_args, center), 0u },
    { "normal", NULL, CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 24, 4, 3, offsetof(struct cbf_helix5b_args, normal), 0u },
    { "ndegrees", "deg", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 36, 4, 1, offsetof(struct cbf_helix5b_args, ndegrees), 0u },
    { "length", "mm", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 40, 4, 1, offsetof(struct cbf_helix5b_args, length), 0u },
    { "start_orient", NULL, CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 44, 4, 3, offsetof(struct cbf_helix5b_args, start_orient), 0u },
    { "end_orient", NULL, CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 56, 4, 3, offsetof(struct cbf_helix5b_args, end_orient), 0u },
    { "speed", "m/s", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 0, 4, 1, offsetof(struct cbf_speed_args, speed), 0u },
    { "accel", "m/s^2", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 0, 4, 1, offsetof(struct cbf_accel_args, accel), 0u },
    { "decel", "m/s^2", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 4, 4, 1, offsetof(struct cbf_accel_args, decel), 0u },
    { "message", NULL, CBF__K_STRING, CBF_ROLE_NONE, CBF__F_TEXT, CBF__CK_NONE, 0, 32, 1, offsetof(struct cbf_guide_args, message), 0u },
    { "nom_speed", "m/s", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 0, 4, 1, offsetof(struct cbf_fcparms_args, nom_speed), 0u },
    { "max_speed", "m/s", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 4, 4, 1, offsetof(struct cbf_fcparms_args, max_speed), 0u },
    { "min_speed", "m/s", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 8, 4, 1, offsetof(struct cbf_fcparms_args, min_speed), 0u },
    { "max_force", "N", CBF__K_FLOAT, CBF_ROLE_NONE, 0, CBF__CK_NONE, 12, 4, 1, offsetof(struct cbf_fcparms_args, max_force), 0u },
    { "cutfile", NULL, CBF__K_STRING, CBF_ROLE_NONE, 0, CBF__CK_NONE, 0, 8, 1, offsetof(struct cbf_version_args, cutfile), 0u },
    { "format", NULL, CBF__K_STRING, CBF_ROLE_NONE, 0, CBF__CK_NONE, 8, 8, 1, offsetof(struct cbf_version_args, format), 0u },
    { "reserved", NULL, CBF__K_BYTES, CBF_ROLE_NONE, CBF__F_RESERVED, CBF__CK_NONE, 16, 16, 1, offsetof(struct cbf_version_args, reserved), 0u },
    { "cutfile", NULL, CBF__K_STRING, CBF_ROLE_NONE, 0, CBF__CK_NONE, 0, 8, 1, offsetof(struct cbf_version_implib_args, cutfile), 0u },
    { "format", NULL, CBF__K_STRING, CBF_ROLE_NONE, 0, CBF__CK_NONE, 8, 8, 1, offsetof(struct cbf_version_implib_args, format), 0u },
    { "text", NULL, CBF__K_STRING, CBF_ROLE_NONE, CBF__F_TEXT, CBF__CK_NONE, 0, 40, 1, offsetof(struct cbf_comment_args, text), 0u },
};

static const cbf__layout cbf__layouts[30] = {
    { 0, "", CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), 0, 32, 0, 3, offsetof(cbf_args, checkpoint),
      { -1, -1, -1, -1, -1, -1, -1 }, { -1, -1 }, { -1, -1 }, { -1, -1, -1 }, 2, -1, 0u, 0u, 0u, 0u }, /* CHECKPOINT */
    { 0, "v1", CBF__VBIT(CBF_V1_X), 0, 16, 3, 1, offsetof(cbf_args, checkpoint_v1),
      { -1, -1, -1, -1, -1, -1, -1 }, { -1, -1 }, { -1, -1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* CHECKPOINT_V1 */
    { 1, "", CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), 0, 32, 4, 5, offsetof(cbf_args, cutter),
      { -1, -1, -1, -1, -1, -1, -1 }, { -1, -1 }, { -1, -1 }, { 0, 1, 2 }, -1, -1, 0u, 0u, 0u, 0u }, /* CUTTER */
    { 1, "v1", CBF__VBIT(CBF_V1_X), 0, 32, 9, 4, offsetof(cbf_args, cutter_v1),
      { -1, -1, -1, -1, -1, -1, -1 }, { -1, -1 }, { -1, -1 }, { 0, 1, 2 }, -1, -1, 0u, 0u, 0u, 0u }, /* CUTTER_V1 */
    { 2, "", CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), 0, 24, 13, 2, offsetof(cbf_args, orient),
      { -1, -1, -1, -1, -1, -1, -1 }, { -1, 0 }, { -1, -1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* ORIENT */
    { 3, "", CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), 0, 24, 15, 2, offsetof(cbf_args, orient5b),
      { -1, -1, -1, -1, -1, -1, -1 }, { 0, 1 }, { -1, -1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* ORIENT5B */
    { 4, "", CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), 0, 16, 17, 1, offsetof(cbf_args, phase),
      { -1, -1, -1, -1, -1, -1, -1 }, { -1, -1 }, { -1, -1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* PHASE */
    { 5, "", CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), 0, 16, 18, 1, offsetof(cbf_args, enable_skip),
      { -1, -1, -1, -1, -1, -1, -1 }, { -1, -1 }, { -1, -1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* ENABLE_SKIP */
    { 6, "", CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), 0, 6, 19, 2, offsetof(cbf_args, startshape),
      { -1, -1, -1, -1, -1, -1, -1 }, { -1, -1 }, { 0, 1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* STARTSHAPE */
    { 7, "", CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), 0, 6, 21, 2, offsetof(cbf_args, endshape),
      { -1, -1, -1, -1, -1, -1, -1 }, { -1, -1 }, { 0, 1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* ENDSHAPE */
    { 8, "", CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), 0, 0, 23, 0, offsetof(cbf_args, decel_off),
      { -1, -1, -1, -1, -1, -1, -1 }, { -1, -1 }, { -1, -1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* DECEL_OFF */
    { 9, "", CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), 0, 0, 23, 0, offsetof(cbf_args, decel_on),
      { -1, -1, -1, -1, -1, -1, -1 }, { -1, -1 }, { -1, -1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* DECEL_ON */
    { 10, "", CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), 0, 12, 23, 1, offsetof(cbf_args, point),
      { -1, 0, -1, -1, -1, -1, -1 }, { -1, -1 }, { -1, -1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* POINT */
    { 11, "", CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), 0, 24, 24, 2, offsetof(cbf_args, line),
      { 0, 1, -1, -1, -1, -1, -1 }, { -1, -1 }, { -1, -1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* LINE */
    { 12, "", CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), 0, 48, 26, 4, offsetof(cbf_args, line5b),
      { 0, 1, -1, -1, -1, -1, -1 }, { 2, 3 }, { -1, -1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* LINE5B */
    { 13, "", CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0), 0, 36, 30, 3, offsetof(cbf_args, arc),
      { 0, 2, -1, -1, -1, -1, 1 }, { -1, -1 }, { -1, -1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* ARC */
    { 14, "", CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0), 0, 60, 33, 5, offsetof(cbf_args, arc5b),
      { 0, 2, -1, -1, -1, -1, 1 }, { 3, 4 }, { -1, -1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* ARC5B */
    { 15, "", CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0), 0, 40, 38, 4, offsetof(cbf_args, circle),
      { 0, -1, 1, 2, 3, -1, -1 }, { -1, -1 }, { -1, -1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* CIRCLE */
    { 16, "", CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0), 0, 64, 42, 6, offsetof(cbf_args, circle5b),
      { 0, -1, 1, 2, 3, -1, -1 }, { 4, 5 }, { -1, -1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* CIRCLE5B */
    { 17, "", CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0), 0, 44, 48, 5, offsetof(cbf_args, helix),
      { 0, -1, 1, 2, 3, 4, -1 }, { -1, -1 }, { -1, -1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* HELIX */
    { 18, "", CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0), 0, 68, 53, 7, offsetof(cbf_args, helix5b),
      { 0, -1, 1, 2, 3, 4, -1 }, { 5, 6 }, { -1, -1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* HELIX5B */
    { 19, "", CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), 0, 4, 60, 1, offsetof(cbf_args, speed),
      { -1, -1, -1, -1, -1, -1, -1 }, { -1, -1 }, { -1, -1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* SPEED */
    { 20, "", CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), 0, 8, 61, 2, offsetof(cbf_args, accel),
      { -1, -1, -1, -1, -1, -1, -1 }, { -1, -1 }, { -1, -1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* ACCEL */
    { 21, "", CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), 0, 0, 63, 0, offsetof(cbf_args, cutter_on),
      { -1, -1, -1, -1, -1, -1, -1 }, { -1, -1 }, { -1, -1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* CUTTER_ON */
    { 22, "", CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), 0, 0, 63, 0, offsetof(cbf_args, cutter_off),
      { -1, -1, -1, -1, -1, -1, -1 }, { -1, -1 }, { -1, -1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* CUTTER_OFF */
    { 23, "", CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), 0, 32, 63, 1, offsetof(cbf_args, guide),
      { -1, -1, -1, -1, -1, -1, -1 }, { -1, -1 }, { -1, -1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* GUIDE */
    { 24, "", CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), 0, 16, 64, 4, offsetof(cbf_args, fcparms),
      { -1, -1, -1, -1, -1, -1, -1 }, { -1, -1 }, { -1, -1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* FCPARMS */
    { 25, "", CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), 0, 32, 68, 3, offsetof(cbf_args, version),
      { -1, -1, -1, -1, -1, -1, -1 }, { -1, -1 }, { -1, -1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* VERSION */
    { 25, "implib", CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), CBF__PBIT(1), 16, 71, 2, offsetof(cbf_args, version_implib),
      { -1, -1, -1, -1, -1, -1, -1 }, { -1, -1 }, { -1, -1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* VERSION_IMPLIB */
    { 26, "", CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), 0, 40, 73, 1, offsetof(cbf_args, comment),
      { -1, -1, -1, -1, -1, -1, -1 }, { -1, -1 }, { -1, -1 }, { -1, -1, -1 }, -1, -1, 0u, 0u, 0u, 0u }, /* COMMENT */
};

static const cbf__command cbf__commands[CBF__NCOMMANDS] = {
    { 0x3C, "CHECKPOINT", 0, 2, CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0) | CBF__VBIT(CBF_V1_X), CBF__MOTION_NONE, CBF__ORIENT_NONE, CBF__SHAPE_NONE, 0,
      { { 1, -1 }, { 0, -1 }, { 0, -1 }, { 0, -1 } } },
    { 0xA3, "CUTTER", 2, 2, CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0) | CBF__VBIT(CBF_V1_X), CBF__MOTION_NONE, CBF__ORIENT_NONE, CBF__SHAPE_NONE, 1,
      { { 3, -1 }, { 2, -1 }, { 2, -1 }, { 2, -1 } } },
    { 0x58, "ORIENT", 4, 1, CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), CBF__MOTION_NONE, CBF__ORIENT_SET, CBF__SHAPE_NONE, 0,
      { { 4, -1 }, { 4, -1 }, { 4, -1 }, { 4, -1 } } },
    { 0x59, "ORIENT5B", 5, 1, CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), CBF__MOTION_NONE, CBF__ORIENT_PATH, CBF__SHAPE_NONE, 0,
      { { 5, -1 }, { 5, -1 }, { 5, -1 }, { 5, -1 } } },
    { 0x21, "PHASE", 6, 1, CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), CBF__MOTION_NONE, CBF__ORIENT_NONE, CBF__SHAPE_NONE, 0,
      { { 6, -1 }, { 6, -1 }, { 6, -1 }, { 6, -1 } } },
    { 0x22, "ENABLE_SKIP", 7, 1, CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), CBF__MOTION_NONE, CBF__ORIENT_NONE, CBF__SHAPE_NONE, 0,
      { { 7, -1 }, { 7, -1 }, { 7, -1 }, { 7, -1 } } },
    { 0xC9, "STARTSHAPE", 8, 1, CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), CBF__MOTION_NONE, CBF__ORIENT_NONE, CBF__SHAPE_START, 0,
      { { 8, -1 }, { 8, -1 }, { 8, -1 }, { 8, -1 } } },
    { 0x65, "ENDSHAPE", 9, 1, CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), CBF__MOTION_NONE, CBF__ORIENT_NONE, CBF__SHAPE_END, 0,
      { { 9, -1 }, { 9, -1 }, { 9, -1 }, { 9, -1 } } },
    { 0x2B, "DECEL_OFF", 10, 1, CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), CBF__MOTION_NONE, CBF__ORIENT_NONE, CBF__SHAPE_NONE, 0,
      { { 10, -1 }, { 10, -1 }, { 10, -1 }, { 10, -1 } } },
    { 0x4E, "DECEL_ON", 11, 1, CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), CBF__MOTION_NONE, CBF__ORIENT_NONE, CBF__SHAPE_NONE, 0,
      { { 11, -1 }, { 11, -1 }, { 11, -1 }, { 11, -1 } } },
    { 0x33, "POINT", 12, 1, CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), CBF__MOTION_POINT, CBF__ORIENT_NONE, CBF__SHAPE_NONE, 0,
      { { 12, -1 }, { 12, -1 }, { 12, -1 }, { 12, -1 } } },
    { 0xB6, "LINE", 13, 1, CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), CBF__MOTION_LINE, CBF__ORIENT_NONE, CBF__SHAPE_NONE, 0,
      { { 13, -1 }, { 13, -1 }, { 13, -1 }, { 13, -1 } } },
    { 0xB7, "LINE5B", 14, 1, CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), CBF__MOTION_LINE, CBF__ORIENT_PATH, CBF__SHAPE_NONE, 0,
      { { 14, -1 }, { 14, -1 }, { 14, -1 }, { 14, -1 } } },
    { 0x94, "ARC", 15, 1, CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0), CBF__MOTION_LINE, CBF__ORIENT_NONE, CBF__SHAPE_NONE, 0,
      { { 15, -1 }, { 15, -1 }, { 15, -1 }, { 15, -1 } } },
    { 0x95, "ARC5B", 16, 1, CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0), CBF__MOTION_LINE, CBF__ORIENT_PATH, CBF__SHAPE_NONE, 0,
      { { 16, -1 }, { 16, -1 }, { 16, -1 }, { 16, -1 } } },
    { 0x7A, "CIRCLE", 17, 1, CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0), CBF__MOTION_CIRCLE, CBF__ORIENT_NONE, CBF__SHAPE_NONE, 0,
      { { 17, -1 }, { 17, -1 }, { 17, -1 }, { 17, -1 } } },
    { 0x7B, "CIRCLE5B", 18, 1, CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0), CBF__MOTION_CIRCLE, CBF__ORIENT_PATH, CBF__SHAPE_NONE, 0,
      { { 18, -1 }, { 18, -1 }, { 18, -1 }, { 18, -1 } } },
    { 0xE2, "HELIX", 19, 1, CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0), CBF__MOTION_HELIX, CBF__ORIENT_NONE, CBF__SHAPE_NONE, 0,
      { { 19, -1 }, { 19, -1 }, { 19, -1 }, { 19, -1 } } },
    { 0xE3, "HELIX5B", 20, 1, CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0), CBF__MOTION_HELIX, CBF__ORIENT_PATH, CBF__SHAPE_NONE, 0,
      { { 20, -1 }, { 20, -1 }, { 20, -1 }, { 20, -1 } } },
    { 0x8B, "SPEED", 21, 1, CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), CBF__MOTION_NONE, CBF__ORIENT_NONE, CBF__SHAPE_NONE, 0,
      { { 21, -1 }, { 21, -1 }, { 21, -1 }, { 21, -1 } } },
    { 0x47, "ACCEL", 22, 1, CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), CBF__MOTION_NONE, CBF__ORIENT_NONE, CBF__SHAPE_NONE, 0,
      { { 22, -1 }, { 22, -1 }, { 22, -1 }, { 22, -1 } } },
    { 0xBB, "CUTTER_ON", 23, 1, CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), CBF__MOTION_NONE, CBF__ORIENT_NONE, CBF__SHAPE_NONE, 0,
      { { 23, -1 }, { 23, -1 }, { 23, -1 }, { 23, -1 } } },
    { 0x66, "CUTTER_OFF", 24, 1, CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), CBF__MOTION_NONE, CBF__ORIENT_NONE, CBF__SHAPE_NONE, 0,
      { { 24, -1 }, { 24, -1 }, { 24, -1 }, { 24, -1 } } },
    { 0x11, "GUIDE", 25, 1, CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), CBF__MOTION_NONE, CBF__ORIENT_NONE, CBF__SHAPE_NONE, 0,
      { { 25, -1 }, { 25, -1 }, { 25, -1 }, { 25, -1 } } },
    { 0xFC, "FCPARMS", 26, 1, CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), CBF__MOTION_NONE, CBF__ORIENT_NONE, CBF__SHAPE_NONE, 0,
      { { 26, -1 }, { 26, -1 }, { 26, -1 }, { 26, -1 } } },
    { 0x55, "VERSION", 27, 2, CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), CBF__MOTION_NONE, CBF__ORIENT_NONE, CBF__SHAPE_NONE, 0,
      { { 27, 28 }, { 27, 28 }, { 27, 28 }, { 27, 28 } } },
    { 0x5A, "COMMENT", 29, 1, CBF__VBIT(CBF_V1_X) | CBF__VBIT(CBF_V2_X) | CBF__VBIT(CBF_V3_0) | CBF__VBIT(CBF_V4_0), CBF__MOTION_NONE, CBF__ORIENT_NONE, CBF__SHAPE_NONE, 0,
      { { 29, -1 }, { 29, -1 }, { 29, -1 }, { 29, -1 } } },
};

static const cbf__segment cbf__segments[5] = {
    { CBF__REGION_ARGS, 0, -1, 0u },
    { CBF__REGION_HEADER, 10, 128, 0u },
    { CBF__REGION_FILE, 8, -1, 0u },
    { CBF__REGION_HEADER, 8, 128, 0u },
    { CBF__REGION_RECORDS, 0, -1, (1u << 0) },
};

static const cbf__coverage cbf__coverages[4] = {
    { "args", 0, 1 }, /* The record's argument bytes; 0 when there are none. */
    { "header", 1, 1 }, /* Header bytes 10..127. */
    { "file", 2, 1 }, /* Every byte from offset 8 to the end of the file (4.2, "starting at byte 8"). */
    { "file_implib", 3, 2 }, /* implib's writer, header bytes 8..127 plus every record without its two sequence-number bytes. */
};

static const cbf__ckfield cbf__ckfields[3] = {
    { CBF__CK_ARGS, CBF__ALG_SUM, 0, -1, "args" },
    { CBF__CK_HEADER, CBF__ALG_SUM, 1, 7, "header" },
    { CBF__CK_FILE, CBF__ALG_SUM, 2, -1, "file" },
};
/* checksum fields among a layout's arguments (issue 25, point 1), in fill order within a layout;
 * their ranges are offsets from the record's first byte (head, then arguments); a layout of -1: none */
static const cbf__argck cbf__argcks[1] = {
    { -1, -1, 0u, 0u, 0u, 0u }, /* none: the spec has no checksum among arguments */
};
static const cbf__range cbf__argck_ranges[1] = {
    { 0u, 0u },
};
static const int cbf__fill_order[3] = { CBF__CK_ARGS, CBF__CK_HEADER, CBF__CK_FILE };

static const cbf__profile cbf__profiles[2] = {
    { "default", { 2 }, { 3 }, CBF__ALG_SUM, { CBF__ALG_SUM }, { 1 } },
    { "implib", { 3 }, { 2 }, CBF__ALG_SUM, { CBF__ALG_SUM }, { 0 } },
};

/* Per command and version: the availability check that covers the command
 * missing from that version (exactly one, loader.py), -1 when it is there. */
static const signed char cbf__avail_check[27][CBF__NVERSIONS] = {
    { -1, -1, -1, -1 }, /* CHECKPOINT */
    { -1, -1, -1, -1 }, /* CUTTER */
    { -1, -1, -1, -1 }, /* ORIENT */
    { -1, -1, -1, -1 }, /* ORIENT5B */
    { 15, -1, -1, -1 }, /* PHASE */
    { -1, -1, -1, -1 }, /* ENABLE_SKIP */
    { -1, -1, -1, -1 }, /* STARTSHAPE */
    { -1, -1, -1, -1 }, /* ENDSHAPE */
    { 15, -1, -1, -1 }, /* DECEL_OFF */
    { 15, -1, -1, -1 }, /* DECEL_ON */
    { -1, -1, -1, -1 }, /* POINT */
    { -1, -1, -1, -1 }, /* LINE */
    { -1, -1, -1, -1 }, /* LINE5B */
    { -1, -1, -1, 14 }, /* ARC */
    { -1, -1, -1, 14 }, /* ARC5B */
    { -1, -1, -1, 14 }, /* CIRCLE */
    { -1, -1, -1, 14 }, /* CIRCLE5B */
    { 15, -1, -1, 14 }, /* HELIX */
    { -1, -1, -1, 14 }, /* HELIX5B */
    { -1, -1, -1, -1 }, /* SPEED */
    { -1, -1, -1, -1 }, /* ACCEL */
    { -1, -1, -1, -1 }, /* CUTTER_ON */
    { -1, -1, -1, -1 }, /* CUTTER_OFF */
    { -1, -1, -1, -1 }, /* GUIDE */
    { 15, -1, -1, -1 }, /* FCPARMS */
    { 15, -1, -1, -1 }, /* VERSION */
    { -1, -1, -1, -1 }, /* COMMENT */
};

/* Per layout: the deprecation check naming it (at most one, loader.py), -1 when none;
 * its versions (the check's mask) are applied where findings are said. */
static const signed char cbf__deprecated[30] = { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 };

static const cbf__target cbf__targets[25] = {
    { 19, 0, 1 }, /* SPEED speed */
    { 20, 1, 2 }, /* ACCEL accel decel */
    { 1, 3, 2 }, /* CUTTER length radius */
    { 15, 5, 1 }, /* CIRCLE normal */
    { 16, 6, 1 }, /* CIRCLE5B normal */
    { 17, 7, 1 }, /* HELIX normal */
    { 18, 8, 1 }, /* HELIX5B normal */
    { 0, 9, 1 }, /* CHECKPOINT completion */
    { 0, 10, 1 }, /* CHECKPOINT completion */
    { 24, 11, 3 }, /* FCPARMS min_speed nom_speed max_speed */
    { 0, 14, 1 }, /* CHECKPOINT recovery_point */
    { 10, 15, 1 }, /* POINT point */
    { 11, 16, 2 }, /* LINE start end */
    { 12, 18, 2 }, /* LINE5B start_pos end_pos */
    { 13, 20, 3 }, /* ARC start middle end */
    { 14, 23, 3 }, /* ARC5B start_pos mid_pos end_pos */
    { 15, 26, 2 }, /* CIRCLE start center */
    { 16, 28, 2 }, /* CIRCLE5B start center */
    { 17, 30, 2 }, /* HELIX start center */
    { 18, 32, 2 }, /* HELIX5B start center */
    { 19, 34, 1 }, /* SPEED speed */
    { 24, 35, 3 }, /* FCPARMS nom_speed max_speed min_speed */
    { 20, 38, 2 }, /* ACCEL accel decel */
    { 1, 40, 1 }, /* CUTTER length */
    { 1, 41, 1 }, /* CUTTER radius */
};
/* The targets' arguments (cbf__target.first, n index these rows): each one's index in
 * every layout, -1 where the layout has no argument of that name. */
static const signed char cbf__target_arg_at[42][CBF_LAYOUT__COUNT] = {
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, -1, -1, -1, -1, -1, -1, -1, -1 }, /* speed */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, -1, -1, -1, -1, -1, -1, -1 }, /* accel */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 1, -1, -1, -1, -1, -1, -1, -1 }, /* decel */
    { -1, -1, 1, 1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* length */
    { -1, -1, 2, 2, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* radius */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 2, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* normal */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 2, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* normal */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 2, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* normal */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 2, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* normal */
    { 2, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* completion */
    { 2, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* completion */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 2, -1, -1, -1 }, /* min_speed */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, -1, -1, -1 }, /* nom_speed */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 1, -1, -1, -1 }, /* max_speed */
    { 1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* recovery_point */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* point */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* start */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* end */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* start_pos */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* end_pos */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* start */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* middle */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 2, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* end */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* start_pos */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* mid_pos */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 2, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* end_pos */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* start */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* center */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* start */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* center */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* start */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* center */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* start */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* center */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, -1, -1, -1, -1, -1, -1, -1, -1 }, /* speed */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, -1, -1, -1 }, /* nom_speed */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 1, -1, -1, -1 }, /* max_speed */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 2, -1, -1, -1 }, /* min_speed */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, -1, -1, -1, -1, -1, -1, -1 }, /* accel */
    { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 1, -1, -1, -1, -1, -1, -1, -1 }, /* decel */
    { -1, -1, 1, 1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* length */
    { -1, -1, 2, 2, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 }, /* radius */
};

static const cbf__check cbf__checks[CBF__NCHECKS] = {
    /* 4.2 (clause 4.2): The file is shorter than the header. No other check runs. */
    { CBF_CHECK_4_2, CBF__KIND_TRUNCATED_HEADER, 1, 0, 0, 0, 0, 0.0, 0, 0.0, 0, 0 },
    /* 4.3 (clause 4.3): The bytes after the last complete record do not hold a whole record head or its nb argument bytes, and fewer complete records than the header count precede them. 6.2.2 is then not judged. The finding's record is the index the incomplete record would have had. */
    { CBF_CHECK_4_3, CBF__KIND_TRUNCATED_RECORD, 1, 0, 0, 0, 0, 0.0, 0, 0.0, 0, 0 },
    /* 6.1.1 (clause 6.1.1): A part number is given and differs from the first whitespace-separated word of the implant descriptor. */
    { CBF_CHECK_6_1_1, CBF__KIND_PART_NUMBER, 1, 0, 0, 0, 0, 0.0, 0, 0.0, 0, 0 },
    /* part_number_first (clause 4.2): The implant descriptor holds no word: it is empty or only whitespace (a CUT text without a header line), so no part number comes first. implib's reader fails on such a file. A warning: the file is still well formed. */
    { CBF_CHECK_PART_NUMBER_FIRST, CBF__KIND_DESCRIPTOR_WORD, 0, 0, 0, 0, 0, 0.0, 0, 0.0, 0, 0 },
    /* 6.1.2 (clause 6.1.2): A cutter table is given, and a cutter's name is not in it, or its length or radius differs from the table by more than tolerances.cutter_mm. */
    { CBF_CHECK_6_1_2, CBF__KIND_CUTTER_TABLE, 1, 0, 0, 0, 0, 0.0, 0, 0.0, 0, 0 },
    /* 6.2.1 (clause 6.2.1): The stored file checksum matches none of the profile's file coverages. The message names a hint coverage that matches. */
    { CBF_CHECK_6_2_1, CBF__KIND_FILE_CHECKSUM, 1, 0, 0, 0, 0, 0.0, 0, 0.0, 0, 0 },
    /* 6.2.2 (clause 6.2.2): The number of records differs from the header's command count (N6). */
    { CBF_CHECK_6_2_2, CBF__KIND_COMMAND_COUNT, 1, 0, 0, 0, 0, 0.0, 0, 0.0, 0, 0 },
    /* 6.3.1 (clause 6.3.1): The stored header checksum differs from the sum over its coverage. */
    { CBF_CHECK_6_3_1, CBF__KIND_HEADER_CHECKSUM, 1, 0, 0, 0, 0, 0.0, 0, 0.0, 0, 0 },
    /* 6.3.2 (clause 6.3.2): The start pattern or the end pattern differs from its value; one finding per field. */
    { CBF_CHECK_6_3_2, CBF__KIND_MAGIC, 1, 0, 0, 0, 0, 0.0, 0, 0.0, 0, 0 },
    /* 6.4.1 (clause 6.4.1): Record i does not carry sequence number i modulo 65536. */
    { CBF_CHECK_6_4_1, CBF__KIND_SEQUENCE, 1, 0, 0, 0, 0, 0.0, 0, 0.0, 0, 0 },
    /* 6.4.2 (clause 6.4.2): The backup copy differs from the command code. */
    { CBF_CHECK_6_4_2, CBF__KIND_CODE_COPY, 1, 0, 0, 0, 0, 0.0, 0, 0.0, 0, 0 },
    /* 6.4.3 (clause 6.4.3): A known command's nb is not the size of a layout for the file's version (for a command the version lacks, of any of its layouts) that the profile accepts. */
    { CBF_CHECK_6_4_3, CBF__KIND_ARG_SIZE, 1, 0, 0, 0, 0, 0.0, 0, 0.0, 0, 0 },
    /* 6.4.4 (clause 6.4.4): The stored argument checksum differs from the sum of the argument bytes. */
    { CBF_CHECK_6_4_4, CBF__KIND_ARG_CHECKSUM, 1, 0, 0, 0, 0, 0.0, 0, 0.0, 0, 0 },
    /* 6.4.5 (clause 6.4.5): A motion command other than a point starts farther than tolerances.position_mm from the current position. POINT sets the current position; every motion command then moves it to its end point. Nothing is compared before the first motion command, and after a motion whose values are not finite or whose normal is zero. */
    { CBF_CHECK_6_4_5, CBF__KIND_CONTINUITY, 1, 0, 0, 0, 0, 0.0, 0, 0.0, 0, 0 },
    /* 7.2.3.1 (clause 7.2.3.1): A record's command has no layout for the file's version 4.0 (N9). */
    { CBF_CHECK_7_2_3_1, CBF__KIND_AVAILABILITY, 1, CBF__VBIT(CBF_V4_0), 0, 0, 0, 0.0, 0, 0.0, 0, 0 },
    /* 7.2.2.4 (clause 7.2.2.4): A record's command has no layout for the file's version 1.x (N10). */
    { CBF_CHECK_7_2_2_4, CBF__KIND_AVAILABILITY, 1, CBF__VBIT(CBF_V1_X), 0, 0, 0, 0.0, 0, 0.0, 0, 0 },
    /* version_supported (clause 7.1): The header's version matches no version of this spec; the file is read with fallback_version. */
    { CBF_CHECK_VERSION_SUPPORTED, CBF__KIND_VERSION, 1, 0, 0, 0, 0, 0.0, 0, 0.0, 0, 0 },
    /* unknown_command (clause 5.2) (N6): The command code is not in the command table. */
    { CBF_CHECK_UNKNOWN_COMMAND, CBF__KIND_UNKNOWN_CODE, 1, 0, 0, 0, 0, 0.0, 0, 0.0, 0, 0 },
    /* trailing_bytes (N6): Bytes follow the last complete record that do not form a whole record, and at least as many complete records as the header count precede them. The finding's record is null. */
    { CBF_CHECK_TRAILING_BYTES, CBF__KIND_TRAILING, 1, 0, 0, 0, 0, 0.0, 0, 0.0, 0, 0 },
    /* reserved_nonzero (N7): The record head's reserved byte is not 0. */
    { CBF_CHECK_RESERVED_NONZERO, CBF__KIND_RESERVED_BYTE, 0, 0, 0, 0, 0, 0.0, 0, 0.0, 0, 0 },
    /* string_tail (N4): A string field of the header or of a record has a non-NUL byte after its first NUL; one finding per field. */
    { CBF_CHECK_STRING_TAIL, CBF__KIND_STRING_TAIL, 0, 0, 0, 0, 0, 0.0, 0, 0.0, 0, 0 },
    /* string_ascii (N4): A string field of the header or of a record has a byte outside 0x20..0x7E before its first NUL; one finding per field. */
    { CBF_CHECK_STRING_ASCII, CBF__KIND_STRING_ASCII, 0, 0, 0, 0, 0, 0.0, 0, 0.0, 0, 0 },
    /* non_finite (X1): A float argument is NaN or infinite; one finding per argument (a vector counts once). */
    { CBF_CHECK_NON_FINITE, CBF__KIND_FINITE, 1, 0, 0, 0, 0, 0.0, 0, 0.0, 0, 0 },
    /* speed_positive (X1): A target argument is finite and <= 0 (one finding per argument). */
    { CBF_CHECK_SPEED_POSITIVE, CBF__KIND_POSITIVE, 1, 0, 0, 1, 0, 0.0, 0, 0.0, 0, 0 },
    /* accel_positive (X1): A target argument is finite and <= 0 (one finding per argument). */
    { CBF_CHECK_ACCEL_POSITIVE, CBF__KIND_POSITIVE, 1, 0, 1, 1, 0, 0.0, 0, 0.0, 0, 0 },
    /* cutter_positive (X1): A target argument is finite and <= 0 (one finding per argument). */
    { CBF_CHECK_CUTTER_POSITIVE, CBF__KIND_POSITIVE, 1, 0, 2, 1, 0, 0.0, 0, 0.0, 0, 0 },
    /* normal_nonzero (X1): All components of a finite target vector are zero (one finding per argument). */
    { CBF_CHECK_NORMAL_NONZERO, CBF__KIND_NONZERO_VECTOR, 1, 0, 3, 4, 0, 0.0, 0, 0.0, 0, 0 },
    /* checkpoint_range (X1): A finite target argument is below min or above max (one finding per argument). */
    { CBF_CHECK_CHECKPOINT_RANGE, CBF__KIND_RANGE, 0, 0, 7, 1, 1, 0.0, 1, 100.0, 0, 0 },
    /* checkpoint_falling (X1): A finite target argument is less than the same argument of the previous record of that command whose value was finite. */
    { CBF_CHECK_CHECKPOINT_FALLING, CBF__KIND_NONDECREASING, 0, 0, 8, 1, 0, 0.0, 0, 0.0, 0, 0 },
    /* fcparms_order (X1): The target arguments, all finite, are not in non-decreasing order. */
    { CBF_CHECK_FCPARMS_ORDER, CBF__KIND_ORDERED, 0, 0, 9, 1, 0, 0.0, 0, 0.0, 0, 0 },
    /* orientation_jump (X1): The angle between a path command's start orientation and the current orientation exceeds tolerances.orientation_deg. A set command sets the current orientation; a path command moves it to its end. Nothing is compared before the first orientation command, and after a zero-length or non-finite orientation. */
    { CBF_CHECK_ORIENTATION_JUMP, CBF__KIND_ORIENTATION, 0, 0, 10, 0, 0, 0.0, 0, 0.0, 0, 0 },
    /* machine_limits (L1): A finite target argument lies outside its limit of the machine (the target's limit in machine.limits): below min or above max, a vector in any component (the first such component is named). One finding per argument. A value that a positive check of the same argument fails (<= 0) is left to that check, as a non-finite one is left to the finite check: one fault, one finding. Without a machine file the default machine applies and the findings are warnings; with one, its limits apply and the findings are errors. */
    { CBF_CHECK_MACHINE_LIMITS, CBF__KIND_MACHINE_LIMITS, 0, 0, 10, 15, 0, 0.0, 0, 0.0, 0, 0 },
    /* shape (X2): A STARTSHAPE inside an open shape, an ENDSHAPE without an open shape, an ENDSHAPE whose name or count differs from its STARTSHAPE, a shape whose number of motion commands differs from its count (at most one finding per ENDSHAPE, reported there), or a shape still open at the end of the file (reported at its STARTSHAPE). A STARTSHAPE inside an open shape opens a new shape. Motion commands are the records of commands with a motion role (POINT included). */
    { CBF_CHECK_SHAPE, CBF__KIND_SHAPE, 1, 0, 25, 0, 0, 0.0, 0, 0.0, 0, 0 },
};

const char *const cbf_command_names[256] = {
    NULL, /* 0x00 */
    NULL, /* 0x01 */
    NULL, /* 0x02 */
    NULL, /* 0x03 */
    NULL, /* 0x04 */
    NULL, /* 0x05 */
    NULL, /* 0x06 */
    NULL, /* 0x07 */
    NULL, /* 0x08 */
    NULL, /* 0x09 */
    NULL, /* 0x0A */
    NULL, /* 0x0B */
    NULL, /* 0x0C */
    NULL, /* 0x0D */
    NULL, /* 0x0E */
    NULL, /* 0x0F */
    NULL, /* 0x10 */
    "GUIDE", /* 0x11 */
    NULL, /* 0x12 */
    NULL, /* 0x13 */
    NULL, /* 0x14 */
    NULL, /* 0x15 */
    NULL, /* 0x16 */
    NULL, /* 0x17 */
    NULL, /* 0x18 */
    NULL, /* 0x19 */
    NULL, /* 0x1A */
    NULL, /* 0x1B */
    NULL, /* 0x1C */
    NULL, /* 0x1D */
    NULL, /* 0x1E */
    NULL, /* 0x1F */
    NULL, /* 0x20 */
    "PHASE", /* 0x21 */
    "ENABLE_SKIP", /* 0x22 */
    NULL, /* 0x23 */
    NULL, /* 0x24 */
    NULL, /* 0x25 */
    NULL, /* 0x26 */
    NULL, /* 0x27 */
    NULL, /* 0x28 */
    NULL, /* 0x29 */
    NULL, /* 0x2A */
    "DECEL_OFF", /* 0x2B */
    NULL, /* 0x2C */
    NULL, /* 0x2D */
    NULL, /* 0x2E */
    NULL, /* 0x2F */
    NULL, /* 0x30 */
    NULL, /* 0x31 */
    NULL, /* 0x32 */
    "POINT", /* 0x33 */
    NULL, /* 0x34 */
    NULL, /* 0x35 */
    NULL, /* 0x36 */
    NULL, /* 0x37 */
    NULL, /* 0x38 */
    NULL, /* 0x39 */
    NULL, /* 0x3A */
    NULL, /* 0x3B */
    "CHECKPOINT", /* 0x3C */
    NULL, /* 0x3D */
    NULL, /* 0x3E */
    NULL, /* 0x3F */
    NULL, /* 0x40 */
    NULL, /* 0x41 */
    NULL, /* 0x42 */
    NULL, /* 0x43 */
    NULL, /* 0x44 */
    NULL, /* 0x45 */
    NULL, /* 0x46 */
    "ACCEL", /* 0x47 */
    NULL, /* 0x48 */
    NULL, /* 0x49 */
    NULL, /* 0x4A */
    NULL, /* 0x4B */
    NULL, /* 0x4C */
    NULL, /* 0x4D */
    "DECEL_ON", /* 0x4E */
    NULL, /* 0x4F */
    NULL, /* 0x50 */
    NULL, /* 0x51 */
    NULL, /* 0x52 */
    NULL, /* 0x53 */
    NULL, /* 0x54 */
    "VERSION", /* 0x55 */
    NULL, /* 0x56 */
    NULL, /* 0x57 */
    "ORIENT", /* 0x58 */
    "ORIENT5B", /* 0x59 */
    "COMMENT", /* 0x5A */
    NULL, /* 0x5B */
    NULL, /* 0x5C */
    NULL, /* 0x5D */
    NULL, /* 0x5E */
    NULL, /* 0x5F */
    NULL, /* 0x60 */
    NULL, /* 0x61 */
    NULL, /* 0x62 */
    NULL, /* 0x63 */
    NULL, /* 0x64 */
    "ENDSHAPE", /* 0x65 */
    "CUTTER_OFF", /* 0x66 */
    NULL, /* 0x67 */
    NULL, /* 0x68 */
    NULL, /* 0x69 */
    NULL, /* 0x6A */
    NULL, /* 0x6B */
    NULL, /* 0x6C */
    NULL, /* 0x6D */
    NULL, /* 0x6E */
    NULL, /* 0x6F */
    NULL, /* 0x70 */
    NULL, /* 0x71 */
    NULL, /* 0x72 */
    NULL, /* 0x73 */
    NULL, /* 0x74 */
    NULL, /* 0x75 */
    NULL, /* 0x76 */
    NULL, /* 0x77 */
    NULL, /* 0x78 */
    NULL, /* 0x79 */
    "CIRCLE", /* 0x7A */
    "CIRCLE5B", /* 0x7B */
    NULL, /* 0x7C */
    NULL, /* 0x7D */
    NULL, /* 0x7E */
    NULL, /* 0x7F */
    NULL, /* 0x80 */
    NULL, /* 0x81 */
    NULL, /* 0x82 */
    NULL, /* 0x83 */
    NULL, /* 0x84 */
    NULL, /* 0x85 */
    NULL, /* 0x86 */
    NULL, /* 0x87 */
    NULL, /* 0x88 */
    NULL, /* 0x89 */
    NULL, /* 0x8A */
    "SPEED", /* 0x8B */
    NULL, /* 0x8C */
    NULL, /* 0x8D */
    NULL, /* 0x8E */
    NULL, /* 0x8F */
    NULL, /* 0x90 */
    NULL, /* 0x91 */
    NULL, /* 0x92 */
    NULL, /* 0x93 */
    "ARC", /* 0x94 */
    "ARC5B", /* 0x95 */
    NULL, /* 0x96 */
    NULL, /* 0x97 */
    NULL, /* 0x98 */
    NULL, /* 0x99 */
    NULL, /* 0x9A */
    NULL, /* 0x9B */
    NULL, /* 0x9C */
    NULL, /* 0x9D */
    NULL, /* 0x9E */
    NULL, /* 0x9F */
    NULL, /* 0xA0 */
    NULL, /* 0xA1 */
    NULL, /* 0xA2 */
    "CUTTER", /* 0xA3 */
    NULL, /* 0xA4 */
    NULL, /* 0xA5 */
    NULL, /* 0xA6 */
    NULL, /* 0xA7 */
    NULL, /* 0xA8 */
    NULL, /* 0xA9 */
    NULL, /* 0xAA */
    NULL, /* 0xAB */
    NULL, /* 0xAC */
    NULL, /* 0xAD */
    NULL, /* 0xAE */
    NULL, /* 0xAF */
    NULL, /* 0xB0 */
    NULL, /* 0xB1 */
    NULL, /* 0xB2 */
    NULL, /* 0xB3 */
    NULL, /* 0xB4 */
    NULL, /* 0xB5 */
    "LINE", /* 0xB6 */
    "LINE5B", /* 0xB7 */
    NULL, /* 0xB8 */
    NULL, /* 0xB9 */
    NULL, /* 0xBA */
    "CUTTER_ON", /* 0xBB */
    NULL, /* 0xBC */
    NULL, /* 0xBD */
    NULL, /* 0xBE */
    NULL, /* 0xBF */
    NULL, /* 0xC0 */
    NULL, /* 0xC1 */
    NULL, /* 0xC2 */
    NULL, /* 0xC3 */
    NULL, /* 0xC4 */
    NULL, /* 0xC5 */
    NULL, /* 0xC6 */
    NULL, /* 0xC7 */
    NULL, /* 0xC8 */
    "STARTSHAPE", /* 0xC9 */
    NULL, /* 0xCA */
    NULL, /* 0xCB */
    NULL, /* 0xCC */
    NULL, /* 0xCD */
    NULL, /* 0xCE */
    NULL, /* 0xCF */
    NULL, /* 0xD0 */
    NULL, /* 0xD1 */
    NULL, /* 0xD2 */
    NULL, /* 0xD3 */
    NULL, /* 0xD4 */
    NULL, /* 0xD5 */
    NULL, /* 0xD6 */
    NULL, /* 0xD7 */
    NULL, /* 0xD8 */
    NULL, /* 0xD9 */
    NULL, /* 0xDA */
    NULL, /* 0xDB */
    NULL, /* 0xDC */
    NULL, /* 0xDD */
    NULL, /* 0xDE */
    NULL, /* 0xDF */
    NULL, /* 0xE0 */
    NULL, /* 0xE1 */
    "HELIX", /* 0xE2 */
    "HELIX5B", /* 0xE3 */
    NULL, /* 0xE4 */
    NULL, /* 0xE5 */
    NULL, /* 0xE6 */
    NULL, /* 0xE7 */
    NULL, /* 0xE8 */
    NULL, /* 0xE9 */
    NULL, /* 0xEA */
    NULL, /* 0xEB */
    NULL, /* 0xEC */
    NULL, /* 0xED */
    NULL, /* 0xEE */
    NULL, /* 0xEF */
    NULL, /* 0xF0 */
    NULL, /* 0xF1 */
    NULL, /* 0xF2 */
    NULL, /* 0xF3 */
    NULL, /* 0xF4 */
    NULL, /* 0xF5 */
    NULL, /* 0xF6 */
    NULL, /* 0xF7 */
    NULL, /* 0xF8 */
    NULL, /* 0xF9 */
    NULL, /* 0xFA */
    NULL, /* 0xFB */
    "FCPARMS", /* 0xFC */
    NULL, /* 0xFD */
    NULL, /* 0xFE */
    NULL, /* 0xFF */
};

/* Command table index by code, -1 for codes that are not commands. */
static const short cbf__index_by_code[256] = {
    -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1,
    -1, 23, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1,
    -1, 4, 5, -1, -1, -1, -1, -1, -1, -1, -1, 8, -1, -1, -1, -1,
    -1, -1, -1, 10, -1, -1, -1, -1, -1, -1, -1, -1, 0, -1, -1, -1,
    -1, -1, -1, -1, -1, -1, -1, 20, -1, -1, -1, -1, -1, -1, 9, -1,
    -1, -1, -1, -1, -1, 25, -1, -1, 2, 3, 26, -1, -1, -1, -1, -1,
    -1, -1, -1, -1, -1, 7, 22, -1, -1, -1, -1, -1, -1, -1, -1, -1,
    -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 15, 16, -1, -1, -1, -1,
    -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 19, -1, -1, -1, -1,
    -1, -1, -1, -1, 13, 14, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1,
    -1, -1, -1, 1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1,
    -1, -1, -1, -1, -1, -1, 11, 12, -1, -1, -1, 21, -1, -1, -1, -1,
    -1, -1, -1, -1, -1, -1, -1, -1, -1, 6, -1, -1, -1, -1, -1, -1,
    -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1,
    -1, -1, 17, 18, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1,
    -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 24, -1, -1, -1,
};
/* ==== BEGIN runtime/bytes.c: verbatim from generator/cbfgen/emit/c/runtime/bytes.c, edit it there ==== */
#line 1 "generator/cbfgen/emit/c/runtime/bytes.c"
/* ---- bytes -------------------------------------------------------------- */
static inline uint32_t cbf__get_u(const uint8_t *p, unsigned n)
{
    uint32_t v = 0;
    unsigned i;
    /* the widths the format uses, unrolled (the validator reads several a record) */
#if CBF__LITTLE_ENDIAN
    if (n == 4u)
        return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
    if (n == 2u)
        return (uint32_t)p[0] | ((uint32_t)p[1] << 8);
#else
    if (n == 4u)
        return ((uint32_t)p[0] << 24) | ((uint32_t)p[1] << 16) | ((uint32_t)p[2] << 8) | (uint32_t)p[3];
    if (n == 2u)
        return ((uint32_t)p[0] << 8) | (uint32_t)p[1];
#endif
    if (n == 1u)
        return p[0];
    for (i = 0; i < n; i++) {
#if CBF__LITTLE_ENDIAN
        v |= (uint32_t)p[i] << (8u * i);
#else
        v = (v << 8) | (uint32_t)p[i];
#endif
    }
    return v;
}

static void cbf__put_u(uint8_t *p, uint32_t v, unsigned n)
{
    unsigned i;
    for (i = 0; i < n; i++) {
#if CBF__LITTLE_ENDIAN
        p[i] = (uint8_t)((v >> (8u * i)) & 0xFFu);
#else
        p[n - 1u - i] = (uint8_t)((v >> (8u * i)) & 0xFFu);
#endif
    }
}

static inline float cbf__bits_f4(uint32_t u)
{
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

static inline float cbf__get_f4(const uint8_t *p) { return cbf__bits_f4(cbf__get_u(p, 4)); }

static uint32_t cbf__f4_bits(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u;
}

static inline int cbf__bits_finite(uint32_t u) { return (u & 0x7F800000u) != 0x7F800000u; }

/* A float field's first element as double, and whether every element is finite; each
 * element's bytes are read once. */
static int cbf__ffirst(const uint8_t *base, const cbf_field_info *f, double *first)
{
    unsigned i;
    int finite = 1;
    *first = 0.0;
    for (i = 0; i < f->count; i++) {
        uint32_t u = cbf__get_u(base + f->offset + 4u * i, 4);
        finite &= cbf__bits_finite(u);
        if (i == 0u)
            *first = (double)cbf__bits_f4(u);
    }
    return finite;
}

/* An element of 8 bytes: the bit pattern of a u8, s8 or f8. */
static uint64_t cbf__get_u64(const uint8_t *p)
{
    uint64_t v = 0;
    unsigned i;
    for (i = 0; i < 8u; i++) {
#if CBF__LITTLE_ENDIAN
        v |= (uint64_t)p[i] << (8u * i);
#else
        v = (v << 8) | (uint64_t)p[i];
#endif
    }
    return v;
}

static void cbf__put_u64(uint8_t *p, uint64_t v)
{
    unsigned i;
    for (i = 0; i < 8u; i++) {
#if CBF__LITTLE_ENDIAN
        p[i] = (uint8_t)((v >> (8u * i)) & 0xFFu);
#else
        p[7u - i] = (uint8_t)((v >> (8u * i)) & 0xFFu);
#endif
    }
}

/* One element of an integer or float field between its n bytes and its struct member (the C type
 * of the registry's type: uintN_t, intN_t, float, double). A signed integer is the unsigned one's
 * bits (intN_t is two's complement), and a float its IEEE-754 bits, so each width has one path. */
static inline void cbf__load_elem(unsigned char *m, const uint8_t *s, unsigned n)
{
    if (n == 1u) { uint8_t v = s[0]; memcpy(m, &v, sizeof v); }
    else if (n == 2u) { uint16_t v = (uint16_t)cbf__get_u(s, 2); memcpy(m, &v, sizeof v); }
    else if (n == 4u) { uint32_t v = cbf__get_u(s, 4); memcpy(m, &v, sizeof v); }
    else { uint64_t v = cbf__get_u64(s); memcpy(m, &v, sizeof v); }
}

static inline void cbf__store_elem(uint8_t *d, const unsigned char *m, unsigned n)
{
    if (n == 4u) { uint32_t v; memcpy(&v, m, sizeof v); cbf__put_u(d, v, 4); }
    else if (n == 2u) { uint16_t v; memcpy(&v, m, sizeof v); cbf__put_u(d, v, 2); }
    else if (n == 1u) { d[0] = m[0]; }
    else { uint64_t v; memcpy(&v, m, sizeof v); cbf__put_u64(d, v); }
}

/* Load fields from bytes into a struct (byte-wise through memcpy). One case a field kind of the
 * registry, no default: a kind the engine lacks fails the build (-Wswitch-enum). */
static void cbf__load(const cbf_field_info *fields, size_t n, const uint8_t *src, unsigned char *dst)
{
    size_t k;
    for (k = 0; k < n; k++) {
        const cbf_field_info *f = &fields[k];
        unsigned char *m = dst + f->member;
        const uint8_t *s = src + f->offset;
        size_t size = (size_t)f->elem * f->count;
        unsigned i;
        switch ((enum cbf_field_kind)f->kind) {
        case CBF_KIND_FLOAT:
            if (f->elem == 4u) { /* binary32, the common case: its own loop (the decoder's hot path) */
                for (i = 0; i < f->count; i++) {
                    uint32_t v = cbf__get_u(s + 4u * i, 4);
                    memcpy(m + 4u * i, &v, sizeof v);
                }
                break;
            }
            for (i = 0; i < f->count; i++)
                cbf__load_elem(m + (size_t)f->elem * i, s + (size_t)f->elem * i, f->elem);
            break;
        case CBF_KIND_UINT:
        case CBF_KIND_SINT: /* one element, in practice (registry.unsupported refuses integer vectors) */
            cbf__load_elem(m, s, f->elem);
            for (i = 1; i < f->count; i++)
                cbf__load_elem(m + (size_t)f->elem * i, s + (size_t)f->elem * i, f->elem);
            break;
        case CBF_KIND_STRING:
            memcpy(m, s, size);
            m[size] = 0;
            break;
        case CBF_KIND_BYTES:
            memcpy(m, s, size);
            break;
        }
    }
}

/* Store fields from a struct into bytes. */
static void cbf__store(const cbf_field_info *fields, size_t n, const unsigned char *src, uint8_t *dst)
{
    size_t k;
    for (k = 0; k < n; k++) {
        const cbf_field_info *f = &fields[k];
        const unsigned char *m = src + f->member;
        uint8_t *d = dst + f->offset;
        size_t size = (size_t)f->elem * f->count;
        unsigned i;
        switch ((enum cbf_field_kind)f->kind) {
        case CBF_KIND_UINT:
        case CBF_KIND_SINT:
        case CBF_KIND_FLOAT:
            for (i = 0; i < f->count; i++)
                cbf__store_elem(d + (size_t)f->elem * i, m + (size_t)f->elem * i, f->elem);
            break;
        case CBF_KIND_STRING:
        case CBF_KIND_BYTES:
            memcpy(d, m, size);
            break;
        }
    }
}

uint32_t cbf_field_uint(const cbf_field_info *f, const uint8_t *base)
{
    return (f && base && f->kind == CBF__K_UINT && f->elem <= 4u) ? cbf__get_u(base + f->offset, f->elem) : 0u;
}

float cbf_field_float(const cbf_field_info *f, const uint8_t *base, unsigned i)
{
    return (f && base && f->kind == CBF__K_FLOAT && f->elem == 4u && i < f->count) ? cbf__get_f4(base + f->offset + 4u * i) : 0.0f;
}

uint32_t cbf_float_bits(float f) { return cbf__f4_bits(f); }

uint64_t cbf_field_bits(const cbf_field_info *f, const uint8_t *base, unsigned i)
{
    unsigned char m[8];
    uint64_t u = 0;
    if (!f || !base || i >= f->count || f->elem > 8u)
        return 0u;
    switch ((enum cbf_field_kind)f->kind) {
    case CBF_KIND_UINT:
    case CBF_KIND_SINT:
    case CBF_KIND_FLOAT:
        cbf__load_elem(m, base + f->offset + (size_t)f->elem * i, f->elem);
        if (f->elem == 1u) { uint8_t x; memcpy(&x, m, 1); u = x; }
        else if (f->elem == 2u) { uint16_t x; memcpy(&x, m, 2); u = x; }
        else if (f->elem == 4u) { uint32_t x; memcpy(&x, m, 4); u = x; }
        else memcpy(&u, m, 8);
        break;
    case CBF_KIND_STRING:
    case CBF_KIND_BYTES:
        break;
    }
    return u;
}

double cbf_field_number(const cbf_field_info *f, const uint8_t *base, unsigned i)
{
    uint64_t u = cbf_field_bits(f, base, i);
    unsigned bits;
    if (!f || !base || i >= f->count || f->elem > 8u)
        return 0.0;
    bits = 8u * f->elem;
    switch ((enum cbf_field_kind)f->kind) {
    case CBF_KIND_UINT:
        return (double)u;
    case CBF_KIND_SINT: { /* sign-extended to 64 bits; int64_t is two's complement */
        int64_t v;
        if (bits < 64u && ((u >> (bits - 1u)) & 1u))
            u |= ~(uint64_t)0 << bits;
        memcpy(&v, &u, sizeof v);
        return (double)v;
    }
    case CBF_KIND_FLOAT:
        if (f->elem == 4u)
            return (double)cbf__bits_f4((uint32_t)u);
        {
            double d;
            memcpy(&d, &u, sizeof d);
            return d;
        }
    case CBF_KIND_STRING:
    case CBF_KIND_BYTES:
        break;
    }
    return 0.0;
}

uint32_t cbf_member_uint(const cbf_field_info *f, const void *obj)
{
    const unsigned char *m;
    if (!f || !obj || f->kind != CBF__K_UINT || f->elem > 4u)
        return 0u;
    m = (const unsigned char *)obj + f->member;
    if (f->elem == 1) { uint8_t x; memcpy(&x, m, 1); return x; }
    if (f->elem == 2) { uint16_t x; memcpy(&x, m, 2); return x; }
    { uint32_t x; memcpy(&x, m, 4); return x; }
}

void cbf_member_set_uint(const cbf_field_info *f, void *obj, uint32_t v)
{
    unsigned char *m;
    if (!f || !obj || f->kind != CBF__K_UINT || f->elem > 4u)
        return;
    m = (unsigned char *)obj + f->member;
    if (f->elem == 1) { uint8_t x = (uint8_t)v; memcpy(m, &x, 1); }
    else if (f->elem == 2) { uint16_t x = (uint16_t)v; memcpy(m, &x, 2); }
    else memcpy(m, &v, 4);
}
/* ==== END runtime/bytes.c ==== */
#line 2569 "cbf.h"
/* ==== BEGIN runtime/quote.c: verbatim from generator/cbfgen/emit/c/runtime/quote.c, edit it there ==== */
#line 1 "generator/cbfgen/emit/c/runtime/quote.c"
/* ---- the one quoting rule for names and values from input (issue #35) ----
 * What `cbf` applies (cbf.quoting), byte for byte, so both tools print the same line:
 * CBF_QUOTE_NAME prints a name as it is when it is plain (not empty; every character printable
 * ASCII other than '"' and '\\', or valid UTF-8 from U+00A0 up that neither breaks a line, turns
 * text around nor hides: not U+2028/U+2029, U+200B..U+200F, U+202A..U+202E, U+2060..U+206F,
 * U+FEFF, U+FFF9..U+FFFB, U+FFFE/U+FFFF; not starting with ':' or a space, not ending in a space),
 * else between double quotes with '"' and '\\' escaped, \n \r \t, a byte that is not UTF-8 (or
 * another ASCII control) as \xHH, any other character that is not plain as \u{H...}.
 * CBF_QUOTE_TEXT is the net under a line of text: every character that is not plain and not a
 * space, '"' or '\\' is escaped the same way; nothing is added around it.
 * So a name never starts a line with "::" (a GitHub workflow command), never carries a line
 * break or a terminal escape, and its exact bytes can be read back. */
static int cbf__hidden(uint32_t c)
{
    return (c >= 0x2028u && c <= 0x2029u) || (c >= 0x200Bu && c <= 0x200Fu) || (c >= 0x202Au && c <= 0x202Eu)
           || (c >= 0x2060u && c <= 0x206Fu) || c == 0xFEFFu || (c >= 0xFFF9u && c <= 0xFFFBu) || c == 0xFFFEu
           || c == 0xFFFFu;
}

/* The UTF-8 character at s (n bytes left): its length and *cp, or 0 when the byte starts none. */
static size_t cbf__utf8(const unsigned char *s, size_t n, uint32_t *cp)
{
    size_t len, i;
    uint32_t c = s[0], min;
    if (c < 0x80u) {
        *cp = c;
        return 1;
    }
    if (c >= 0xC2u && c <= 0xDFu) {
        len = 2;
        c &= 0x1Fu;
        min = 0x80u;
    } else if (c >= 0xE0u && c <= 0xEFu) {
        len = 3;
        c &= 0x0Fu;
        min = 0x800u;
    } else if (c >= 0xF0u && c <= 0xF4u) {
        len = 4;
        c &= 0x07u;
        min = 0x10000u;
    } else {
        return 0;
    }
    if (n < len)
        return 0;
    for (i = 1; i < len; i++) {
        if ((s[i] & 0xC0u) != 0x80u)
            return 0;
        c = (c << 6) | (s[i] & 0x3Fu);
    }
    if (c < min || c > 0x10FFFFu || (c >= 0xD800u && c <= 0xDFFFu))
        return 0;
    *cp = c;
    return len;
}

size_t cbf_utf8_prefix(const uint8_t *s, size_t n)
{
    size_t i = 0, len;
    uint32_t c;
    while (i < n) {
        if (!(len = cbf__utf8(s + i, n - i, &c)))
            return i;
        i += len;
    }
    return n;
}

static int cbf__plain(uint32_t c)
{
    if (c < 0x80u)
        return c >= 0x20u && c < 0x7Fu && c != '"' && c != '\\';
    return c >= 0xA0u && !cbf__hidden(c);
}

static void cbf__qput(char *out, size_t cap, size_t *at, const char *text, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++, (*at)++)
        if (*at + 1u < cap)
            out[*at] = text[i];
}

/* The escape of one character that is not printed as it is (len 0: a byte that starts no UTF-8 character). */
static void cbf__qescape(char esc[16], unsigned char byte, size_t len, uint32_t c)
{
    if (!len) {
        (void)snprintf(esc, 16, "\\x%02X", byte);
    } else if (c == '"' || c == '\\') {
        esc[0] = '\\';
        esc[1] = (char)c;
        esc[2] = '\0';
    } else if (c == '\n' || c == '\r' || c == '\t') {
        (void)snprintf(esc, 16, "\\%c", c == '\n' ? 'n' : c == '\r' ? 'r' : 't');
    } else if (c < 0x80u) {
        (void)snprintf(esc, 16, "\\x%02X", (unsigned)c);
    } else {
        (void)snprintf(esc, 16, "\\u{%lX}", (unsigned long)c);
    }
}

size_t cbf_quote(char *out, size_t cap, const char *s, size_t n, int mode)
{
    const unsigned char *u = (const unsigned char *)s;
    size_t at = 0, i, len;
    uint32_t c = 0;
    int plain = n > 0 && u[0] != ':' && u[0] != ' ' && u[n - 1u] != ' ';
    for (i = 0; plain && i < n; i += len) {
        len = cbf__utf8(u + i, n - i, &c);
        plain = len > 0 && cbf__plain(c);
    }
    if (mode == CBF_QUOTE_NAME && plain) {
        cbf__qput(out, cap, &at, s, n);
    } else {
        if (mode == CBF_QUOTE_NAME)
            cbf__qput(out, cap, &at, "\"", 1);
        for (i = 0; i < n; i += len) {
            char esc[16];
            len = cbf__utf8(u + i, n - i, &c);
            if (len && (cbf__plain(c) || (mode == CBF_QUOTE_TEXT && (c == '"' || c == '\\')))) {
                cbf__qput(out, cap, &at, s + i, len);
                continue;
            }
            cbf__qescape(esc, u[i], len, c);
            if (!len)
                len = 1;
            cbf__qput(out, cap, &at, esc, strlen(esc));
        }
        if (mode == CBF_QUOTE_NAME)
            cbf__qput(out, cap, &at, "\"", 1);
    }
    if (cap)
        out[at < cap ? at : cap - 1u] = '\0';
    return at;
}

const char *cbf_quoted(const char *s, int mode)
{
    /* a ring of buffers: a message may quote several names at once */
    static char ring[4][16384];
    static unsigned next;
    char *buf = ring[next++ % 4u];
    size_t need = cbf_quote(buf, sizeof ring[0], s, strlen(s), mode);
    if (need >= sizeof ring[0]) /* longer than a message holds: cut, and say so */
        (void)memcpy(buf + sizeof ring[0] - 9u, "...(cut)", 8u);
    return buf;
}
/* ==== END runtime/quote.c ==== */
#line 2720 "cbf.h"
/* ==== BEGIN runtime/groups.c: verbatim from generator/cbfgen/emit/c/runtime/groups.c, edit it there ==== */
#line 1 "generator/cbfgen/emit/c/runtime/groups.c"
/* ---- repeated argument groups (issue 25, point 3): nb = size + group_item * n ----------- */
/* The group's own paths stay out of line: a file of fixed layouts decodes as fast as before. */
#if defined(__GNUC__) || defined(__clang__)
#define CBF__GROUP_PATH __attribute__((noinline, cold))
#else
#define CBF__GROUP_PATH
#endif

/* n for nb argument bytes of layout L: how many items of its group a record of nb bytes holds,
 * -1 when no n in group_min..group_max tiles nb (a layout without a group: 0 for its size, else -1). */
static inline long cbf__group_n(const cbf__layout *L, size_t nb)
{
    size_t n;
    if (L->group < 0)
        return nb == L->size ? 0 : -1;
    if (nb < L->size || (nb - L->size) % L->group_item != 0u)
        return -1;
    n = (nb - L->size) / L->group_item;
    return (n >= L->group_min && n <= L->group_max) ? (long)n : -1;
}

/* Whether layout L decodes nb argument bytes (its size; with a group, one of its sizes). */
static inline int cbf__layout_takes(const cbf__layout *L, size_t nb)
{
    if (!CBF__HAS_GROUPS || L->group < 0)
        return nb == L->size; /* the common case first: a fixed layout */
    return cbf__group_n(L, nb) >= 0;
}

/* The smallest nb layout L takes above `above` (-1: its smallest), or -1 when it takes none. */
static long cbf__layout_next_size(const cbf__layout *L, long above)
{
    size_t n;
    if (L->group < 0)
        return (long)L->size > above ? (long)L->size : -1;
    n = L->group_min;
    if ((long)(L->size + L->group_item * n) <= above)
        n = ((size_t)above - L->size) / L->group_item + 1u;
    return n <= L->group_max ? (long)(L->size + L->group_item * n) : -1;
}

/* The group's items of a record (n of them, after the fixed arguments) into the decoded struct,
 * one item a time through the item's field row, and n beside them. */
CBF__GROUP_PATH static void cbf__load_group(const cbf__layout *L, const uint8_t *args, size_t n, cbf_args *out)
{
    cbf_field_info item = cbf__args[L->first_arg + (size_t)L->group];
    size_t i;
    for (i = 0; i < n; i++) {
        cbf__load(&item, 1, args, (unsigned char *)out + L->member);
        item.offset = (unsigned short)(item.offset + L->group_item);
        item.member += L->group_item; /* an item's C elements are as wide as its stored ones */
    }
    memcpy((unsigned char *)out + L->group_n, &n, sizeof n);
}

/* How many items of its group a decoded struct holds (0 for a layout without a group). */
static size_t cbf__group_items(const cbf__layout *L, const cbf_args *in)
{
    size_t n = 0;
    if (L->group >= 0)
        memcpy(&n, (const unsigned char *)in + L->group_n, sizeof n);
    return n;
}

/* The group's n items of a decoded struct into argument bytes, after the fixed arguments. */
CBF__GROUP_PATH static void cbf__store_group(const cbf__layout *L, const cbf_args *in, size_t n, uint8_t *out)
{
    cbf_field_info item = cbf__args[L->first_arg + (size_t)L->group];
    size_t i;
    for (i = 0; i < n; i++) {
        cbf__store(&item, 1, (const unsigned char *)in + L->member, out);
        item.offset = (unsigned short)(item.offset + L->group_item);
        item.member += L->group_item;
    }
}

int cbf_layout_group(int layout, size_t *min, size_t *max, size_t *item)
{
    const cbf__layout *L;
    if (layout < 0 || layout >= CBF_LAYOUT__COUNT || cbf__layouts[layout].group < 0)
        return -1;
    L = &cbf__layouts[layout];
    if (min)
        *min = L->group_min;
    if (max)
        *max = L->group_max;
    if (item)
        *item = L->group_item;
    return L->group;
}

long cbf_layout_nb(int layout, size_t n)
{
    const cbf__layout *L;
    if (layout < 0 || layout >= CBF_LAYOUT__COUNT)
        return CBF_ERR_ARGUMENT;
    L = &cbf__layouts[layout];
    if (L->group < 0) {
        if (n != 0u)
            return CBF_ERR_RANGE;
        return (long)L->size;
    }
    if (n < L->group_min || n > L->group_max)
        return CBF_ERR_RANGE;
    return (long)(L->size + L->group_item * n);
}

long cbf_layout_items(int layout, size_t nb)
{
    if (layout < 0 || layout >= CBF_LAYOUT__COUNT)
        return CBF_ERR_ARGUMENT;
    return cbf__group_n(&cbf__layouts[layout], nb);
}
/* ==== END runtime/groups.c ==== */
#line 2837 "cbf.h"
/* ==== BEGIN runtime/lookups.c: verbatim from generator/cbfgen/emit/c/runtime/lookups.c, edit it there ==== */
#line 1 "generator/cbfgen/emit/c/runtime/lookups.c"
/* ---- look-ups ------------------------------------------------------------ */
static inline int cbf__cmd_index(int code)
{
    return (code < 0 || code > 0xFF) ? -1 : cbf__index_by_code[code];
}

static const cbf_field_info *cbf__header_field_by_role(int layout, int role)
{
    size_t i;
    for (i = 0; i < cbf__headers[layout].nfields; i++)
        if (cbf__headers[layout].fields[i].role == role)
            return &cbf__headers[layout].fields[i];
    return NULL;
}

static const cbf_field_info *cbf__header_field_by_tag(int layout, int tag)
{
    size_t i;
    for (i = 0; i < cbf__headers[layout].nfields; i++)
        if (cbf__headers[layout].fields[i].checksum == tag)
            return &cbf__headers[layout].fields[i];
    return NULL;
}

static const cbf_field_info *cbf__record_field_by_role(int role)
{
    size_t i;
    for (i = 0; i < CBF__NRECORD_FIELDS; i++)
        if (cbf__record_fields[i].role == role)
            return &cbf__record_fields[i];
    return NULL;
}

static const cbf_field_info *cbf__record_field_by_tag(int tag)
{
    size_t i;
    for (i = 0; i < CBF__NRECORD_FIELDS; i++)
        if (cbf__record_fields[i].checksum == tag)
            return &cbf__record_fields[i];
    return NULL;
}

/* A uint field of a record, through a field looked up once (NULL reads 0). */
static inline uint32_t cbf__fld(const cbf_field_info *f, const uint8_t *rec)
{
    return f ? cbf__get_u(rec + f->offset, f->elem) : 0u;
}

static uint32_t cbf__head_get(const uint8_t *rec, int role)
{
    const cbf_field_info *f = cbf__record_field_by_role(role);
    return f ? cbf__get_u(rec + f->offset, f->elem) : 0u;
}

static const cbf__ckfield *cbf__ckfield_of(int tag)
{
    size_t i;
    for (i = 0; i < sizeof cbf__ckfields / sizeof cbf__ckfields[0]; i++)
        if (cbf__ckfields[i].tag == tag)
            return &cbf__ckfields[i];
    return NULL;
}

static inline const cbf_field_info *cbf__layout_arg(int layout, int i)
{
    if (i < 0)
        return NULL;
    return &cbf__args[cbf__layouts[layout].first_arg + (size_t)i];
}

const char *cbf_strerror(int err)
{
    switch (err) {
    case CBF_OK: return "ok";
    case CBF_ERR_TRUNCATED_HEADER: return "truncated_header";
    case CBF_ERR_TRUNCATED_RECORD: return "truncated_record";
    case CBF_ERR_BUFFER: return "buffer too small";
    case CBF_ERR_ARGUMENT: return "bad argument";
    case CBF_ERR_RANGE: return "value out of range";
    case CBF_ERR_NOT_WRITABLE: return "not writable";
    case CBF_ERR_INVALID: return "the result would not validate";
    case CBF_ERR_SYNTAX: return "the text does not read";
    default: return "unknown error";
    }
}

const char *cbf_command_name(int code)
{
    int i = cbf__cmd_index(code);
    return i < 0 ? NULL : cbf__commands[i].name;
}

int cbf_command_available(int code, int version)
{
    int i = cbf__cmd_index(code);
    if (i < 0 || version < 0 || version >= CBF__NVERSIONS)
        return 0;
    return (cbf__commands[i].versions & CBF__VBIT(version)) != 0u;
}

int cbf_version_find(unsigned major, unsigned minor)
{
    int i;
    for (i = 0; i < CBF__NVERSIONS; i++)
        if ((unsigned)cbf__versions[i].major == major
            && (cbf__versions[i].minor < 0 || (unsigned)cbf__versions[i].minor == minor))
            return i;
    return CBF_V__UNKNOWN;
}

const char *cbf_version_name(int version)
{
    return (version >= 0 && version < CBF__NVERSIONS) ? cbf__versions[version].id : NULL;
}

int cbf_version_writable(int version)
{
    return (version >= 0 && version < CBF__NVERSIONS) ? cbf__versions[version].writable : 0;
}

int cbf_profile_find(const char *name)
{
    int i;
    if (!name)
        return CBF_ERR_ARGUMENT;
    for (i = 0; i < CBF_PROFILE__COUNT; i++)
        if (strcmp(cbf__profiles[i].id, name) == 0)
            return i;
    return CBF_ERR_ARGUMENT;
}

static int cbf__layout_ok(int layout) { return layout >= 0 && layout < CBF_LAYOUT__COUNT; }

const char *cbf_layout_command_name(int layout)
{
    return cbf__layout_ok(layout) ? cbf__commands[cbf__layouts[layout].command].name : NULL;
}

const char *cbf_layout_variant(int layout)
{
    return cbf__layout_ok(layout) ? cbf__layouts[layout].variant : NULL;
}

int cbf_layout_code(int layout)
{
    return cbf__layout_ok(layout) ? cbf__commands[cbf__layouts[layout].command].code : CBF_ERR_ARGUMENT;
}

long cbf_layout_size(int layout)
{
    return cbf__layout_ok(layout) ? (long)cbf__layouts[layout].size : (long)CBF_ERR_ARGUMENT;
}

size_t cbf_layout_fields(int layout, const cbf_field_info **out)
{
    if (!cbf__layout_ok(layout) || !out)
        return 0;
    *out = &cbf__args[cbf__layouts[layout].first_arg];
    return cbf__layouts[layout].nargs;
}

size_t cbf_header_fields(int header_layout, const cbf_field_info **out)
{
    if (header_layout < 0 || header_layout >= CBF_HEADER__COUNT || !out)
        return 0;
    *out = cbf__headers[header_layout].fields;
    return cbf__headers[header_layout].nfields;
}

size_t cbf_record_fields(const cbf_field_info **out)
{
    if (!out)
        return 0;
    *out = cbf__record_fields;
    return CBF__NRECORD_FIELDS;
}

static inline int cbf__eff_version(int version)
{
    return version < 0 ? CBF_FALLBACK_VERSION : version;
}

int cbf_version_header_layout(int version)
{
    if (version >= CBF__NVERSIONS)
        return CBF_ERR_ARGUMENT;
    return cbf__versions[cbf__eff_version(version)].header;
}

int cbf_args_layout(int code, int version, size_t nb)
{
    int ci = cbf__cmd_index(code);
    int k;
    if (ci < 0)
        return CBF_LAYOUT__NONE;
    version = cbf__eff_version(version);
    if (version >= CBF__NVERSIONS)
        return CBF_LAYOUT__NONE;
    for (k = 0; k < CBF__MAX_CANDIDATES; k++) {
        int lay = cbf__commands[ci].candidates[version][k];
        if (lay < 0)
            break;
        if (cbf__layout_takes(&cbf__layouts[lay], nb))
            return lay;
    }
    return CBF_LAYOUT__NONE;
}

int cbf_args_candidates(int code, int version, int *out, int cap)
{
    int ci = cbf__cmd_index(code), k, n = 0;
    if (ci < 0 || !out || version >= CBF__NVERSIONS)
        return 0;
    version = cbf__eff_version(version);
    for (k = 0; k < CBF__MAX_CANDIDATES && n < cap; k++) {
        int lay = cbf__commands[ci].candidates[version][k];
        if (lay < 0)
            break;
        out[n++] = lay;
    }
    return n;
}
/* ==== END runtime/lookups.c ==== */
#line 3063 "cbf.h"
/* ==== BEGIN runtime/checksums.c: verbatim from generator/cbfgen/emit/c/runtime/checksums.c, edit it there ==== */
#line 1 "generator/cbfgen/emit/c/runtime/checksums.c"
/* ---- checksums -----------------------------------------------------------
 * Every algorithm kind is a row of cbf__algs (generated from cbfgen/registry.py ALGORITHMS: its
 * parameters and, for a CRC, its byte table); each family is implemented once here:
 *   SUM       unsigned byte sum, reduced to the width of the field
 *   CRC       the CRC catalogue's model (width, poly, init, refin, refout, xorout), a byte at a time
 *             through the table: reflected (refin) with the register right-aligned, else with the
 *             register left-aligned in 32 bits
 *   FLETCHER  16 or 32 bits: little-endian words of width/16 bytes (an odd tail padded with 0), two
 *             sums modulo 2^(width/2) - 1, result sum2 << width/2 | sum1
 * A coverage feeds several ranges as one stream: Fletcher keeps the bytes of a pending word. */
typedef struct cbf__ck { const cbf__alg *a; uint32_t acc, acc2; unsigned npend; uint8_t pend[4]; } cbf__ck;

static void cbf__ck_init(cbf__ck *c, int alg)
{
    c->a = &cbf__algs[alg >= 0 && alg < CBF__ALG__COUNT ? alg : CBF__ALG_NONE];
    c->acc = c->a->init;
    c->acc2 = 0u;
    c->npend = 0u;
    memset(c->pend, 0, sizeof c->pend);
}

/* The plain byte sum of p[0..n), modulo 2^32. Eight bytes at a time: the bytes
 * are added pairwise into four 16-bit lanes of a 64-bit word, which are folded
 * before they can overflow (at most 510 per step, 128 steps). */
static uint32_t cbf__sum(const uint8_t *p, size_t n)
{
    const uint64_t lo = 0x00FF00FF00FF00FFull;
    uint32_t acc = 0;
    size_t i = 0;
    while (n - i >= 8u) {
        uint64_t lanes = 0;
        size_t steps = (n - i) / 8u, k;
        if (steps > 128u)
            steps = 128u;
        for (k = 0; k < steps; k++, i += 8u) {
            uint64_t x;
            memcpy(&x, p + i, sizeof x);
            lanes += (x & lo) + ((x >> 8) & lo);
        }
        lanes = (lanes & 0x0000FFFF0000FFFFull) + ((lanes >> 16) & 0x0000FFFF0000FFFFull);
        acc += (uint32_t)(lanes & 0xFFFFFFFFull) + (uint32_t)(lanes >> 32);
    }
    for (; i < n; i++)
        acc += p[i];
    return acc;
}

/* The little-endian value of the first n bytes of q (the bytes of a word; missing ones are 0). */
static uint32_t cbf__word(const uint8_t *q, unsigned n)
{
    uint32_t w = 0;
    while (n-- > 0u)
        w = (w << 8) | q[n];
    return w;
}

/* Fletcher over p[0..n): whole words straight from p, a word split between two feeds through
 * c->pend; the sums grow in 64 bits and are reduced every 4096 words (then s1 < 2^29, s2 < 2^42). */
static void cbf__fletcher(cbf__ck *c, const uint8_t *p, size_t n)
{
    const unsigned wb = c->a->width / 16u;
    const uint32_t mod = (1u << (c->a->width / 2u)) - 1u;
    uint64_t s1 = c->acc, s2 = c->acc2;
    unsigned since = 0;
    size_t i = 0;
    while (i < n) {
        uint32_t w;
        if (c->npend == 0u && n - i >= wb) {
            w = cbf__word(p + i, wb);
            i += wb;
        } else {
            c->pend[c->npend++] = p[i++];
            if (c->npend < wb)
                continue;
            w = cbf__word(c->pend, wb);
            c->npend = 0u;
        }
        s1 += w;
        s2 += s1;
        if (++since == 4096u) {
            s1 %= mod;
            s2 %= mod;
            since = 0;
        }
    }
    c->acc = (uint32_t)(s1 % mod);
    c->acc2 = (uint32_t)(s2 % mod);
}

static void cbf__ck_feed(cbf__ck *c, const uint8_t *p, size_t n)
{
    const uint32_t *t = c->a->table;
    uint32_t r = c->acc;
    size_t i;
    switch (c->a->family) {
    case CBF__FAMILY_SUM:
        c->acc += cbf__sum(p, n);
        break;
    case CBF__FAMILY_CRC:
        if (c->a->refin) {
            for (i = 0; i < n; i++)
                r = t[(r ^ p[i]) & 0xFFu] ^ (r >> 8);
        } else {
            for (i = 0; i < n; i++)
                r = t[((r >> 24) ^ p[i]) & 0xFFu] ^ (r << 8);
        }
        c->acc = r;
        break;
    case CBF__FAMILY_FLETCHER:
        cbf__fletcher(c, p, n);
        break;
    }
}

/* The register reflected over its low `width` bits. */
static uint32_t cbf__reflect(uint32_t v, unsigned width)
{
    uint32_t out = 0;
    unsigned k;
    for (k = 0; k < width; k++, v >>= 1)
        out = (out << 1) | (v & 1u);
    return out;
}

static uint32_t cbf__ck_value(const cbf__ck *c, unsigned width)
{
    const cbf__alg *a = c->a;
    uint32_t v = c->acc;
    switch (a->family) {
    case CBF__FAMILY_SUM:
        break;
    case CBF__FAMILY_CRC:
        if (!a->refin)
            v >>= 32u - a->width;
        if (a->refin != a->refout)
            v = cbf__reflect(v, a->width);
        v ^= a->xorout;
        break;
    case CBF__FAMILY_FLETCHER: {
        uint32_t s1 = c->acc, s2 = c->acc2;
        if (c->npend) { /* the pending bytes of a last, short word, padded with zeros */
            const uint32_t mod = (1u << (a->width / 2u)) - 1u;
            s1 = (uint32_t)(((uint64_t)s1 + cbf__word(c->pend, c->npend)) % mod);
            s2 = (uint32_t)(((uint64_t)s2 + s1) % mod);
        }
        v = (s2 << (a->width / 2u)) | s1;
        break;
    }
    }
    /* only a sum is wider than its field (the loader refuses any other such algorithm) */
    return width >= 4u ? v : (v & ((1u << (8u * width)) - 1u));
}

/* A coverage over a file image buf[0..len): records lie in [header, records_end). */
static uint32_t cbf__cover(int cov, int alg, unsigned width, const uint8_t *buf, size_t len,
                              size_t records_end, const uint8_t *args, size_t nargs)
{
    cbf__ck c;
    size_t s;
    cbf__ck_init(&c, alg);
    for (s = cbf__coverages[cov].first; s < cbf__coverages[cov].first + cbf__coverages[cov].n; s++) {
        const cbf__segment *seg = &cbf__segments[s];
        if (seg->region == CBF__REGION_FILE) {
            if (seg->start < len)
                cbf__ck_feed(&c, buf + seg->start, len - seg->start);
        } else if (seg->region == CBF__REGION_HEADER) {
            size_t end = (size_t)seg->end;
            if (end > len)
                end = len;
            if (seg->start < end)
                cbf__ck_feed(&c, buf + seg->start, end - seg->start);
        } else if (seg->region == CBF__REGION_ARGS) {
            if (args && nargs)
                cbf__ck_feed(&c, args, nargs);
        } else if (seg->region == CBF__REGION_RECORDS) {
            const cbf_field_info *nbf = cbf__record_field_by_role(CBF_ROLE_ARG_SIZE);
            size_t pos = CBF_HEADER_SIZE;
            if (records_end > len)
                records_end = len;
            while (nbf && pos <= records_end && records_end - pos >= CBF_RECORD_HEAD_SIZE) {
                size_t nb = cbf__get_u(buf + pos + nbf->offset, nbf->elem);
                size_t cur = 0, k;
                if (records_end - pos - CBF_RECORD_HEAD_SIZE < nb)
                    break;
                for (k = 0; k < CBF__NRECORD_FIELDS; k++) {
                    const cbf_field_info *f = &cbf__record_fields[k];
                    if (!(seg->exclude & (1u << k)))
                        continue;
                    if (f->offset > cur)
                        cbf__ck_feed(&c, buf + pos + cur, f->offset - cur);
                    cur = (size_t)f->offset + (size_t)f->elem * f->count;
                }
                cbf__ck_feed(&c, buf + pos + cur, CBF_RECORD_HEAD_SIZE + nb - cur);
                pos += CBF_RECORD_HEAD_SIZE + nb;
            }
        }
    }
    return cbf__ck_value(&c, width);
}

uint32_t cbf_args_checksum(const uint8_t *args, size_t n)
{
    const cbf__ckfield *k = cbf__ckfield_of(CBF__CK_ARGS);
    const cbf_field_info *f = cbf__record_field_by_tag(CBF__CK_ARGS);
    if (!k || !f)
        return 0u;
    return cbf__cover(k->coverage, k->alg, f->elem, NULL, 0, 0, args, n);
}


/* ---- checksum fields among a layout's arguments (issue 25, point 1) --------
 * cbf__argcks lists them per layout, in the spec's fill order; each covers byte ranges of its
 * record (offsets from the record's first byte: the head, then the arguments), fed in order. */

/* The value of argument checksum a over the record rec of nb argument bytes (nb is its layout's size). */
static uint32_t cbf__argck_value(const cbf__argck *a, const uint8_t *rec, size_t nb)
{
    cbf__ck c;
    size_t r;
    cbf__ck_init(&c, cbf__ckfields[a->ckfield].alg);
    for (r = a->first; r < a->first + a->n; r++) {
        const cbf__range *g = &cbf__argck_ranges[r];
        if (g->start < g->end && (size_t)g->end <= CBF_RECORD_HEAD_SIZE + nb)
            cbf__ck_feed(&c, rec + g->start, (size_t)(g->end - g->start));
    }
    return cbf__ck_value(&c, a->elem);
}

/* Whether check ci judges a checksum field among arguments (not the head's argument checksum). */
static int cbf__judges_argck(int ci)
{
    size_t i;
    for (i = 0; i < sizeof cbf__argcks / sizeof cbf__argcks[0]; i++)
        if (cbf__argcks[i].ckfield >= 0 && cbf__ckfields[cbf__argcks[i].ckfield].check == ci)
            return 1;
    return 0;
}

/* Fills layout's checksum fields among the arguments of the record rec (nb argument bytes), in
 * fill order; returns whether one was written (the head's argument checksum covers them). */
static int cbf__fill_argcks(int layout, uint8_t *rec, size_t nb)
{
    size_t i;
    int any = 0;
    for (i = 0; i < sizeof cbf__argcks / sizeof cbf__argcks[0]; i++) {
        const cbf__argck *a = &cbf__argcks[i];
        if (layout < 0 || a->layout != layout || (size_t)a->offset + a->elem > nb)
            continue;
        cbf__put_u(rec + CBF_RECORD_HEAD_SIZE + a->offset, cbf__argck_value(a, rec, nb), a->elem);
        any = 1;
    }
    return any;
}
/* ==== END runtime/checksums.c ==== */
#line 3320 "cbf.h"
/* ==== BEGIN runtime/reader.c: verbatim from generator/cbfgen/emit/c/runtime/reader.c, edit it there ==== */
#line 1 "generator/cbfgen/emit/c/runtime/reader.c"
/* ---- header and records --------------------------------------------------- */
long cbf_header_decode(const uint8_t *buf, size_t len, cbf_header *out)
{
    const cbf_field_info *fmaj, *fmin, *fcnt;
    int lay;
    if (!buf || !out)
        return CBF_ERR_ARGUMENT;
    if (len < CBF_HEADER_SIZE)
        return CBF_ERR_TRUNCATED_HEADER;
    memset(out, 0, sizeof *out);
    fmaj = cbf__header_field_by_role(0, CBF_ROLE_VERSION_MAJOR);
    fmin = cbf__header_field_by_role(0, CBF_ROLE_VERSION_MINOR);
    out->major = fmaj ? (unsigned)cbf__get_u(buf + fmaj->offset, fmaj->elem) : 0u;
    out->minor = fmin ? (unsigned)cbf__get_u(buf + fmin->offset, fmin->elem) : 0u;
    out->version = cbf_version_find(out->major, out->minor);
    lay = cbf__versions[cbf__eff_version(out->version)].header;
    out->layout = lay;
    fcnt = cbf__header_field_by_role(lay, CBF_ROLE_COMMAND_COUNT);
    out->count = fcnt ? (unsigned long)cbf__get_u(buf + fcnt->offset, fcnt->elem) : 0ul;
    cbf__load(cbf__headers[lay].fields, cbf__headers[lay].nfields, buf,
              (unsigned char *)out + cbf__headers[lay].member);
    return CBF_HEADER_SIZE;
}

int cbf_header_init(cbf_header *h, int version)
{
    const cbf_field_info *f;
    size_t i;
    int lay;
    if (!h || version < 0 || version >= CBF__NVERSIONS)
        return CBF_ERR_ARGUMENT;
    memset(h, 0, sizeof *h);
    h->version = version;
    lay = cbf__versions[version].header;
    h->layout = lay;
    h->major = (unsigned)cbf__versions[version].major;
    h->minor = cbf__versions[version].minor < 0 ? 0u : (unsigned)cbf__versions[version].minor;
    for (i = 0; i < cbf__headers[lay].nfields; i++) {
        uint32_t v;
        f = &cbf__headers[lay].fields[i];
        if (f->role == CBF_ROLE_VERSION_MAJOR) v = h->major;
        else if (f->role == CBF_ROLE_VERSION_MINOR) v = h->minor;
        else if (f->flags & CBF__F_MAGIC) v = f->magic;
        else continue;
        if (f->kind != CBF__K_UINT)
            continue;
        if (f->elem == 1) { uint8_t x = (uint8_t)v; memcpy((unsigned char *)h + cbf__headers[lay].member + f->member, &x, 1); }
        else if (f->elem == 2) { uint16_t x = (uint16_t)v; memcpy((unsigned char *)h + cbf__headers[lay].member + f->member, &x, 2); }
        else memcpy((unsigned char *)h + cbf__headers[lay].member + f->member, &v, 4);
    }
    return CBF_OK;
}

long cbf_header_encode(const cbf_header *h, uint8_t *out, size_t cap)
{
    if (!h || !out || h->layout < 0 || h->layout >= CBF_HEADER__COUNT)
        return CBF_ERR_ARGUMENT;
    if (cap < CBF_HEADER_SIZE)
        return CBF_ERR_BUFFER;
    memset(out, 0, CBF_HEADER_SIZE);
    cbf__store(cbf__headers[h->layout].fields, cbf__headers[h->layout].nfields,
               (const unsigned char *)h + cbf__headers[h->layout].member, out);
    return CBF_HEADER_SIZE;
}

int cbf_reader_init(cbf_reader *r, const uint8_t *buf, size_t len)
{
    long rc;
    if (!r || !buf)
        return CBF_ERR_ARGUMENT;
    memset(r, 0, sizeof *r);
    rc = cbf_header_decode(buf, len, &r->header);
    if (rc < 0)
        return (int)rc;
    r->buf = buf;
    r->len = len;
    r->pos = CBF_HEADER_SIZE;
    r->eff_version = cbf__eff_version(r->header.version);
    return CBF_OK;
}

long cbf_args_decode(int layout, const uint8_t *args, size_t n, cbf_args *out)
{
    const cbf__layout *L;
    long items;
    if (!cbf__layout_ok(layout) || !out || (!args && n))
        return CBF_ERR_ARGUMENT;
    L = &cbf__layouts[layout];
    if (CBF__HAS_GROUPS && L->group >= 0) { /* a repeated group: n from nb, the items after the fixed arguments */
        items = cbf__group_n(L, n);
        if (items < 0)
            return CBF_ERR_RANGE;
        memset(out, 0, sizeof *out);
        cbf__load(&cbf__args[L->first_arg], L->nargs - 1u, args, (unsigned char *)out + L->member);
        cbf__load_group(L, args, (size_t)items, out);
        return (long)n;
    }
    if (n != L->size)
        return CBF_ERR_RANGE;
    memset(out, 0, sizeof *out);
    cbf__load(&cbf__args[L->first_arg], L->nargs, args, (unsigned char *)out + L->member);
    return (long)n;
}

long cbf_args_encode(int layout, const cbf_args *in, uint8_t *out, size_t cap)
{
    const cbf__layout *L;
    size_t n, items;
    if (!cbf__layout_ok(layout) || !in || !out)
        return CBF_ERR_ARGUMENT;
    L = &cbf__layouts[layout];
    items = CBF__HAS_GROUPS ? cbf__group_items(L, in) : 0u;
    if (CBF__HAS_GROUPS && L->group >= 0 && (items < L->group_min || items > L->group_max))
        return CBF_ERR_RANGE; /* a group of n items outside its min..max: no nb says it */
    n = L->size + (CBF__HAS_GROUPS && L->group >= 0 ? L->group_item * items : 0u);
    if (cap < n)
        return CBF_ERR_BUFFER;
    memset(out, 0, n);
    cbf__store(&cbf__args[L->first_arg], L->nargs - (L->group >= 0), (const unsigned char *)in + L->member, out);
    if (CBF__HAS_GROUPS && L->group >= 0)
        cbf__store_group(L, in, items, out);
    return (long)n;
}

CBF__HOT int cbf_next_record(cbf_reader *r, cbf_record *rec)
{
    const uint8_t *p;
    size_t nb;
    size_t k;
    if (!r || !rec || !r->buf)
        return CBF_ERR_ARGUMENT;
    if (r->pos > r->len)
        return CBF_ERR_ARGUMENT;
    r->trailing = 0;
    if (r->len - r->pos < CBF_RECORD_HEAD_SIZE) {
        nb = 0;
    } else {
        nb = cbf__head_get(r->buf + r->pos, CBF_ROLE_ARG_SIZE);
        if (r->len - r->pos - CBF_RECORD_HEAD_SIZE >= nb)
            goto whole;
    }
    /* no further complete record */
    if (r->len == r->pos)
        return 0;
    if (r->index < r->header.count)
        return CBF_ERR_TRUNCATED_RECORD;
    r->trailing = r->len - r->pos;
    return 0;
whole:
    p = r->buf + r->pos;
    memset(rec, 0, sizeof *rec);
    rec->index = r->index;
    rec->offset = r->pos;
    for (k = 0; k < CBF__NRECORD_FIELDS; k++) {
        const cbf_field_info *f = &cbf__record_fields[k];
        uint32_t v = cbf__get_u(p + f->offset, f->elem);
        unsigned char *m = (unsigned char *)&rec->head + f->member;
        if (f->elem == 1) { uint8_t x = (uint8_t)v; memcpy(m, &x, 1); }
        else if (f->elem == 2) { uint16_t x = (uint16_t)v; memcpy(m, &x, 2); }
        else memcpy(m, &v, 4);
    }
    rec->args = p + CBF_RECORD_HEAD_SIZE;
    rec->nargs = nb;
    {
        int code = (int)cbf__head_get(p, CBF_ROLE_CODE);
        rec->command = cbf__cmd_index(code) < 0 ? CBF_CMD__UNKNOWN : code;
        rec->layout = cbf__cmd_index(code) < 0 ? CBF_LAYOUT__NONE : cbf_args_layout(code, r->eff_version, nb);
    }
    if (rec->layout != CBF_LAYOUT__NONE)
        (void)cbf_args_decode(rec->layout, rec->args, nb, &rec->decoded);
    r->pos += CBF_RECORD_HEAD_SIZE + nb;
    r->index++;
    return 1;
}
/* ==== END runtime/reader.c ==== */
#line 3498 "cbf.h"
/* ==== BEGIN runtime/writer.c: verbatim from generator/cbfgen/emit/c/runtime/writer.c, edit it there ==== */
#line 1 "generator/cbfgen/emit/c/runtime/writer.c"
/* ---- writer ---------------------------------------------------------------- */
static int cbf__wfail(cbf_writer *w, int err)
{
    if (w->error == CBF_OK)
        w->error = err;
    return w->error;
}

int cbf_encode_begin(cbf_writer *w, uint8_t *buf, size_t cap, const cbf_header *h)
{
    long rc;
    if (!w)
        return CBF_ERR_ARGUMENT;
    memset(w, 0, sizeof *w);
    if (!buf || !h)
        return cbf__wfail(w, CBF_ERR_ARGUMENT);
    w->buf = buf;
    w->cap = cap;
    rc = cbf_header_encode(h, buf, cap);
    if (rc < 0)
        return cbf__wfail(w, (int)rc);
    w->version = cbf_version_find(h->major, h->minor);
    if (w->version == CBF_V__UNKNOWN) {
        /* the version field as stored in the header image decides */
        const cbf_field_info *fmaj = cbf__header_field_by_role(0, CBF_ROLE_VERSION_MAJOR);
        const cbf_field_info *fmin = cbf__header_field_by_role(0, CBF_ROLE_VERSION_MINOR);
        if (fmaj && fmin)
            w->version = cbf_version_find(cbf__get_u(buf + fmaj->offset, fmaj->elem),
                                          cbf__get_u(buf + fmin->offset, fmin->elem));
    }
    w->eff_version = cbf__eff_version(w->version);
    w->len = CBF_HEADER_SIZE;
    w->records_end = CBF_HEADER_SIZE;
    return CBF_OK;
}

int cbf_encode_record_stored(cbf_writer *w, const cbf_record_head *head, const uint8_t *args, size_t nargs)
{
    size_t k;
    uint8_t *p;
    if (!w || !w->buf)
        return CBF_ERR_ARGUMENT;
    if (w->error)
        return w->error;
    if (!head || (!args && nargs))
        return cbf__wfail(w, CBF_ERR_ARGUMENT);
    if (w->len != w->records_end)
        return cbf__wfail(w, CBF_ERR_ARGUMENT); /* records after trailing bytes */
    if (w->cap - w->len < CBF_RECORD_HEAD_SIZE || w->cap - w->len - CBF_RECORD_HEAD_SIZE < nargs)
        return cbf__wfail(w, CBF_ERR_BUFFER);
    p = w->buf + w->len;
    for (k = 0; k < CBF__NRECORD_FIELDS; k++) {
        const cbf_field_info *f = &cbf__record_fields[k];
        const unsigned char *m = (const unsigned char *)head + f->member;
        uint32_t v;
        if (f->elem == 1) { uint8_t x; memcpy(&x, m, 1); v = x; }
        else if (f->elem == 2) { uint16_t x; memcpy(&x, m, 2); v = x; }
        else memcpy(&v, m, 4);
        if (f->role == CBF_ROLE_ARG_SIZE && v != nargs)
            return cbf__wfail(w, CBF_ERR_RANGE);
        cbf__put_u(p + f->offset, v, f->elem);
    }
    if (nargs)
        memcpy(p + CBF_RECORD_HEAD_SIZE, args, nargs);
    w->len += CBF_RECORD_HEAD_SIZE + nargs;
    w->records_end = w->len;
    w->count++;
    return CBF_OK;
}

/* A filling writer writes only what the version has: a known command that the
 * version lists, with an argument size that is one of its layouts in that
 * version. cbf_encode_end also asks that the profile accept the layout. */
static int cbf__record_writable(int version, int code, size_t nb)
{
    return cbf_command_available(code, version) && cbf_args_layout(code, version, nb) != CBF_LAYOUT__NONE;
}

static inline int cbf__profile_accepts(int layout, int profile)
{
    return cbf__layouts[layout].profiles == 0u || (cbf__layouts[layout].profiles & CBF__PBIT(profile)) != 0u;
}

static int cbf__same_field(const cbf_field_info *a, const cbf_field_info *b)
{
    return strcmp(a->name, b->name) == 0 && a->kind == b->kind && a->flags == b->flags && a->offset == b->offset
           && a->elem == b->elem && a->count == b->count
           && (a->unit == b->unit || (a->unit && b->unit && strcmp(a->unit, b->unit) == 0));
}

/* The layout a profile's writers write a record in (N8: implib writes the
 * short layout its profile lists): a command with a layout of its own under
 * the profile in the version is written in the first such layout. A record in
 * a longer layout that starts with the same fields is cut to it when the
 * fields cut off are reserved and zero. Returns the size to keep (nb when nothing changes), or -1 when the
 * record cannot be written so (the profile's reader could not read it). */
static long cbf__profile_size(int version, int code, const uint8_t *args, size_t nb, int profile)
{
    int cmd = cbf__cmd_index(code), have = cbf_args_layout(code, version, nb), own = -1, k;
    size_t i;
    const cbf__layout *L, *H;
    if (cmd < 0 || have == CBF_LAYOUT__NONE || version < 0 || version >= CBF__NVERSIONS)
        return (long)nb;
    for (k = 0; k < cbf__commands[cmd].nlayouts && own < 0; k++) {
        int lay = cbf__commands[cmd].first_layout + k;
        if ((cbf__layouts[lay].versions & CBF__VBIT(version)) && (cbf__layouts[lay].profiles & CBF__PBIT(profile)))
            own = lay;
    }
    if (own < 0 || (cbf__layouts[have].profiles & CBF__PBIT(profile)))
        return (long)nb;
    L = &cbf__layouts[own];
    H = &cbf__layouts[have];
    if (L->nargs > H->nargs || L->size > H->size || L->group >= 0 || H->group >= 0)
        return -1; /* a repeated group is never cut */
    for (i = 0; i < L->nargs; i++)
        if (!cbf__same_field(&cbf__args[L->first_arg + i], &cbf__args[H->first_arg + i]))
            return -1;
    for (i = L->nargs; i < H->nargs; i++)
        if (!(cbf__args[H->first_arg + i].flags & CBF__F_RESERVED))
            return -1;
    for (i = L->size; i < nb; i++)
        if (args[i] != 0u)
            return -1;
    return (long)L->size;
}


int cbf_encode_record(cbf_writer *w, int code, const uint8_t *args, size_t nargs)
{
    cbf_record_head head;
    size_t k;
    if (!w || !w->buf)
        return CBF_ERR_ARGUMENT;
    if (w->error)
        return w->error;
    if (code < 0 || code > 0xFF || (!args && nargs))
        return cbf__wfail(w, CBF_ERR_RANGE);
    if (!cbf__record_writable(w->version, code, nargs))
        return cbf__wfail(w, CBF_ERR_NOT_WRITABLE);
    memset(&head, 0, sizeof head);
    for (k = 0; k < CBF__NRECORD_FIELDS; k++) {
        const cbf_field_info *f = &cbf__record_fields[k];
        unsigned char *m = (unsigned char *)&head + f->member;
        uint32_t v = 0u, max = f->elem >= 4u ? 0xFFFFFFFFu : ((1u << (8u * f->elem)) - 1u);
        if (f->role == CBF_ROLE_SEQUENCE) v = (uint32_t)(w->count & max);
        else if (f->role == CBF_ROLE_CODE || f->role == CBF_ROLE_CODE_COPY) v = (uint32_t)code;
        else if (f->role == CBF_ROLE_ARG_SIZE) {
            if (nargs > max)
                return cbf__wfail(w, CBF_ERR_RANGE);
            v = (uint32_t)nargs;
        } else if (f->checksum == CBF__CK_ARGS) v = cbf_args_checksum(args, nargs);
        if (v > max)
            return cbf__wfail(w, CBF_ERR_RANGE);
        if (f->elem == 1) { uint8_t x = (uint8_t)v; memcpy(m, &x, 1); }
        else if (f->elem == 2) { uint16_t x = (uint16_t)v; memcpy(m, &x, 2); }
        else memcpy(m, &v, 4);
    }
    return cbf_encode_record_stored(w, &head, args, nargs);
}

int cbf_encode_bytes(cbf_writer *w, const uint8_t *bytes, size_t n)
{
    if (!w || !w->buf)
        return CBF_ERR_ARGUMENT;
    if (w->error)
        return w->error;
    if (!bytes && n)
        return cbf__wfail(w, CBF_ERR_ARGUMENT);
    if (w->cap - w->len < n)
        return cbf__wfail(w, CBF_ERR_BUFFER);
    if (n)
        memcpy(w->buf + w->len, bytes, n);
    w->len += n;
    return CBF_OK;
}

/* The record at pos cut to the profile's layout (the bytes after it move up); its argument size, or -1
 * when the profile has no layout for it. */
static long cbf__fill_cut(cbf_writer *w, size_t pos, int profile, const cbf_field_info *f_code,
                          const cbf_field_info *f_nb, const cbf_field_info *f_ck)
{
    uint8_t *p = w->buf + pos;
    int code = (int)cbf__get_u(p + f_code->offset, f_code->elem);
    size_t nb = cbf__get_u(p + f_nb->offset, f_nb->elem);
    long keep = cbf__profile_size(w->version, code, p + CBF_RECORD_HEAD_SIZE, nb, profile);
    if (keep < 0)
        return -1;
    if ((size_t)keep < nb) { /* cut to the profile's layout: the bytes after it move up */
        size_t cut = nb - (size_t)keep, end = pos + CBF_RECORD_HEAD_SIZE + nb;
        memmove(p + CBF_RECORD_HEAD_SIZE + keep, w->buf + end, w->len - end);
        w->len -= cut;
        w->records_end -= cut;
        nb = (size_t)keep;
        cbf__put_u(p + f_nb->offset, (uint32_t)nb, f_nb->elem);
        if (f_ck)
            cbf__put_u(p + f_ck->offset, cbf_args_checksum(p + CBF_RECORD_HEAD_SIZE, nb), f_ck->elem);
    }
    return (long)nb;
}

/* Every record written: cut to the profile's layout, writable, and its checksum fields filled. Records
 * appended with cbf_encode_record_stored pass the same test. */
static int cbf__fill_records(cbf_writer *w, int profile)
{
    const cbf_field_info *f_code = cbf__record_field_by_role(CBF_ROLE_CODE);
    const cbf_field_info *f_nb = cbf__record_field_by_role(CBF_ROLE_ARG_SIZE);
    const cbf_field_info *f_ck = cbf__record_field_by_tag(CBF__CK_ARGS);
    size_t pos = CBF_HEADER_SIZE;
    while (f_code && f_nb && pos < w->records_end) {
        uint8_t *p = w->buf + pos;
        int code = (int)cbf__get_u(p + f_code->offset, f_code->elem);
        long got = cbf__fill_cut(w, pos, profile, f_code, f_nb, f_ck);
        size_t nb;
        int layout;
        if (got < 0)
            return CBF_ERR_NOT_WRITABLE;
        nb = (size_t)got;
        layout = cbf_args_layout(code, w->version, nb);
        if (!cbf__record_writable(w->version, code, nb) || !cbf__profile_accepts(layout, profile))
            return CBF_ERR_NOT_WRITABLE;
        /* checksum fields among the arguments (issue 25, point 1), then the head's sum over them */
        if (cbf__fill_argcks(layout, p, nb) && f_ck)
            cbf__put_u(p + f_ck->offset, cbf_args_checksum(p + CBF_RECORD_HEAD_SIZE, nb), f_ck->elem);
        pos += CBF_RECORD_HEAD_SIZE + nb;
    }
    return CBF_OK;
}

/* The header layout lay's magic numbers and command count. */
static int cbf__fill_header(cbf_writer *w, int lay)
{
    size_t i;
    for (i = 0; i < cbf__headers[lay].nfields; i++) {
        const cbf_field_info *f = &cbf__headers[lay].fields[i];
        if (f->kind != CBF__K_UINT)
            continue;
        if (f->flags & CBF__F_MAGIC)
            cbf__put_u(w->buf + f->offset, f->magic, f->elem);
        if (f->role == CBF_ROLE_COMMAND_COUNT) {
            uint32_t max = f->elem >= 4u ? 0xFFFFFFFFu : ((1u << (8u * f->elem)) - 1u);
            if (w->count > max)
                return CBF_ERR_RANGE;
            cbf__put_u(w->buf + f->offset, (uint32_t)w->count, f->elem);
        }
    }
    return CBF_OK;
}

/* The header's checksum fields, in their fill order (the file's over the profile's first coverage). */
static void cbf__fill_header_sums(cbf_writer *w, int lay, int profile)
{
    size_t i;
    for (i = 0; i < sizeof cbf__fill_order / sizeof cbf__fill_order[0]; i++) {
        int tag = cbf__fill_order[i];
        const cbf__ckfield *k = cbf__ckfield_of(tag);
        const cbf_field_info *f = cbf__header_field_by_tag(lay, tag);
        int cov;
        if (tag == CBF__CK_ARGS || !k || !f)
            continue; /* argument checksums are written with each record */
        cov = (tag == CBF__CK_FILE && cbf__profiles[profile].file[0] >= 0) ? cbf__profiles[profile].file[0]
                                                                             : k->coverage;
        cbf__put_u(w->buf + f->offset,
                   cbf__cover(cov, tag == CBF__CK_FILE ? cbf__profiles[profile].file_alg : k->alg, f->elem, w->buf,
                              w->len, w->records_end, NULL, 0), f->elem);
    }
}

long cbf_encode_end(cbf_writer *w, int profile, int fill)
{
    int lay, rc;
    if (!w || !w->buf)
        return CBF_ERR_ARGUMENT;
    if (w->error)
        return w->error;
    if (profile < 0 || profile >= CBF_PROFILE__COUNT)
        return cbf__wfail(w, CBF_ERR_ARGUMENT);
    if (!fill)
        return (long)w->len;
    if (!cbf_version_writable(w->version))
        return cbf__wfail(w, CBF_ERR_NOT_WRITABLE);
    rc = cbf__fill_records(w, profile);
    if (rc != CBF_OK)
        return cbf__wfail(w, rc);
    lay = cbf__versions[w->eff_version].header;
    rc = cbf__fill_header(w, lay);
    if (rc != CBF_OK)
        return cbf__wfail(w, rc);
    cbf__fill_header_sums(w, lay, profile);
    return (long)w->len;
}
/* ==== END runtime/writer.c ==== */
#line 3792 "cbf.h"
/* ---- one encoder a layout (cbf_encode_<layout>) -------------------------- */
int cbf_encode_checkpoint(cbf_writer *w, const struct cbf_checkpoint_args *args)
{
    uint8_t bytes[32];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.checkpoint, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_CHECKPOINT, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_CHECKPOINT, bytes, (size_t)n);
}

int cbf_encode_checkpoint_v1(cbf_writer *w, const struct cbf_checkpoint_v1_args *args)
{
    uint8_t bytes[16];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.checkpoint_v1, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_CHECKPOINT_V1, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_CHECKPOINT, bytes, (size_t)n);
}

int cbf_encode_cutter(cbf_writer *w, const struct cbf_cutter_args *args)
{
    uint8_t bytes[32];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.cutter, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_CUTTER, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_CUTTER, bytes, (size_t)n);
}

int cbf_encode_cutter_v1(cbf_writer *w, const struct cbf_cutter_v1_args *args)
{
    uint8_t bytes[32];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.cutter_v1, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_CUTTER_V1, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_CUTTER, bytes, (size_t)n);
}

int cbf_encode_orient(cbf_writer *w, const struct cbf_orient_args *args)
{
    uint8_t bytes[24];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.orient, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_ORIENT, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_ORIENT, bytes, (size_t)n);
}

int cbf_encode_orient5b(cbf_writer *w, const struct cbf_orient5b_args *args)
{
    uint8_t bytes[24];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.orient5b, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_ORIENT5B, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_ORIENT5B, bytes, (size_t)n);
}

int cbf_encode_phase(cbf_writer *w, const struct cbf_phase_args *args)
{
    uint8_t bytes[16];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.phase, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_PHASE, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_PHASE, bytes, (size_t)n);
}

int cbf_encode_enable_skip(cbf_writer *w, const struct cbf_enable_skip_args *args)
{
    uint8_t bytes[16];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.enable_skip, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_ENABLE_SKIP, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_ENABLE_SKIP, bytes, (size_t)n);
}

int cbf_encode_startshape(cbf_writer *w, const struct cbf_startshape_args *args)
{
    uint8_t bytes[6];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.startshape, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_STARTSHAPE, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_STARTSHAPE, bytes, (size_t)n);
}

int cbf_encode_endshape(cbf_writer *w, const struct cbf_endshape_args *args)
{
    uint8_t bytes[6];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.endshape, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_ENDSHAPE, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_ENDSHAPE, bytes, (size_t)n);
}

int cbf_encode_decel_off(cbf_writer *w, const struct cbf_decel_off_args *args)
{
    uint8_t bytes[1];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.decel_off, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_DECEL_OFF, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_DECEL_OFF, bytes, (size_t)n);
}

int cbf_encode_decel_on(cbf_writer *w, const struct cbf_decel_on_args *args)
{
    uint8_t bytes[1];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.decel_on, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_DECEL_ON, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_DECEL_ON, bytes, (size_t)n);
}

int cbf_encode_point(cbf_writer *w, const struct cbf_point_args *args)
{
    uint8_t bytes[12];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.point, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_POINT, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_POINT, bytes, (size_t)n);
}

int cbf_encode_line(cbf_writer *w, const struct cbf_line_args *args)
{
    uint8_t bytes[24];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.line, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_LINE, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_LINE, bytes, (size_t)n);
}

int cbf_encode_line5b(cbf_writer *w, const struct cbf_line5b_args *args)
{
    uint8_t bytes[48];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.line5b, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_LINE5B, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_LINE5B, bytes, (size_t)n);
}

int cbf_encode_arc(cbf_writer *w, const struct cbf_arc_args *args)
{
    uint8_t bytes[36];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.arc, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_ARC, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_ARC, bytes, (size_t)n);
}

int cbf_encode_arc5b(cbf_writer *w, const struct cbf_arc5b_args *args)
{
    uint8_t bytes[60];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.arc5b, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_ARC5B, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_ARC5B, bytes, (size_t)n);
}

int cbf_encode_circle(cbf_writer *w, const struct cbf_circle_args *args)
{
    uint8_t bytes[40];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.circle, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_CIRCLE, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_CIRCLE, bytes, (size_t)n);
}

int cbf_encode_circle5b(cbf_writer *w, const struct cbf_circle5b_args *args)
{
    uint8_t bytes[64];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.circle5b, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_CIRCLE5B, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_CIRCLE5B, bytes, (size_t)n);
}

int cbf_encode_helix(cbf_writer *w, const struct cbf_helix_args *args)
{
    uint8_t bytes[44];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.helix, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_HELIX, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_HELIX, bytes, (size_t)n);
}

int cbf_encode_helix5b(cbf_writer *w, const struct cbf_helix5b_args *args)
{
    uint8_t bytes[68];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.helix5b, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_HELIX5B, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_HELIX5B, bytes, (size_t)n);
}

int cbf_encode_speed(cbf_writer *w, const struct cbf_speed_args *args)
{
    uint8_t bytes[4];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.speed, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_SPEED, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_SPEED, bytes, (size_t)n);
}

int cbf_encode_accel(cbf_writer *w, const struct cbf_accel_args *args)
{
    uint8_t bytes[8];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.accel, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_ACCEL, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_ACCEL, bytes, (size_t)n);
}

int cbf_encode_cutter_on(cbf_writer *w, const struct cbf_cutter_on_args *args)
{
    uint8_t bytes[1];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.cutter_on, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_CUTTER_ON, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_CUTTER_ON, bytes, (size_t)n);
}

int cbf_encode_cutter_off(cbf_writer *w, const struct cbf_cutter_off_args *args)
{
    uint8_t bytes[1];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.cutter_off, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_CUTTER_OFF, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_CUTTER_OFF, bytes, (size_t)n);
}

int cbf_encode_guide(cbf_writer *w, const struct cbf_guide_args *args)
{
    uint8_t bytes[32];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.guide, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_GUIDE, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_GUIDE, bytes, (size_t)n);
}

int cbf_encode_fcparms(cbf_writer *w, const struct cbf_fcparms_args *args)
{
    uint8_t bytes[16];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.fcparms, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_FCPARMS, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_FCPARMS, bytes, (size_t)n);
}

int cbf_encode_version(cbf_writer *w, const struct cbf_version_args *args)
{
    uint8_t bytes[32];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.version, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_VERSION, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_VERSION, bytes, (size_t)n);
}

int cbf_encode_version_implib(cbf_writer *w, const struct cbf_version_implib_args *args)
{
    uint8_t bytes[16];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.version_implib, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_VERSION_IMPLIB, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_VERSION, bytes, (size_t)n);
}

int cbf_encode_comment(cbf_writer *w, const struct cbf_comment_args *args)
{
    uint8_t bytes[40];
    cbf_args a;
    long n;
    if (!w || !args)
        return CBF_ERR_ARGUMENT;
    memset(&a, 0, sizeof a);
    memcpy(&a.comment, args, sizeof *args);
    n = cbf_args_encode(CBF_LAYOUT_COMMENT, &a, bytes, sizeof bytes);
    if (n < 0)
        return (int)n;
    return cbf_encode_record(w, CBF_CMD_COMMENT, bytes, (size_t)n);
}

/* ==== BEGIN runtime/validator.c: verbatim from generator/cbfgen/emit/c/runtime/validator.c, edit it there ==== */
#line 1 "generator/cbfgen/emit/c/runtime/validator.c"
/* ---- validation ------------------------------------------------------------ */
/* The straight-line checks (below, and the string checks) are called from one generated function per
 * layout (cbf__layout_checks_*) with the layout's offsets as constants; forced inline, each folds to a
 * few loads and compares. An offset of -1 means the layout has no such argument. */
#if defined(__GNUC__) || defined(__clang__)
#define CBF__INLINE static inline __attribute__((always_inline))
#define CBF__COLD __attribute__((cold, noinline)) /* a finding's path: out of the record loop's way */
#else
#define CBF__INLINE static inline
#define CBF__COLD
#endif

typedef struct cbf__vctx {
    const uint8_t *buf;
    size_t len;
    const cbf_options *opt;
    cbf_finding_fn fn;
    void *user;
    long errors;
    int version, eff, hlayout;
    int pos_ok;
    double pos[3];
    int ori_ok;
    double ori[3];
    double ori_tan2; /* tan^2 of just under the orientation tolerance (0: always compute the angle) */
    int shape_open;
    long shape_rec;
    size_t shape_off;
    int shape_layout;
    const uint8_t *shape_args;
    unsigned long shape_moves;
    int nd_ok[CBF__NTARGETS > 0 ? CBF__NTARGETS : 1];
    double nd_prev[CBF__NTARGETS > 0 ? CBF__NTARGETS : 1];
    const cbf_machine *machine; /* the machine limits apply (opt->machine, or the default) */
    float mlo[CBF_MACHINE__COUNT][CBF_MACHINE_MAX_AXES]; /* its bounds rounded to binary32 (cbf__bound32) */
    float mhi[CBF_MACHINE__COUNT][CBF_MACHINE_MAX_AXES];
} cbf__vctx;

/* The check kinds the engine judges in its own passes (validate.c, this file, machine.c, group_checks.c), not
 * through a kernel table (validator_layouts.c.j2 holds the targeted kinds' kernels, cbf__<kind>_at). cbf.h
 * checks this list against the registry when it compiles: a kind the registry gains that neither a kernel
 * table nor this list holds fails the build, naming it (CBF__JUDGED_CBF__KIND_<KIND> undeclared); a kind listed here
 * that the registry no longer has fails too (CBF__KIND_<KIND> undeclared). Adding a kind here is adding
 * its pass: test_bindings holds each kind's constant to a use beyond its enum. The list spells the
 * constants whole (CBF__KIND_<KIND>): a kind's bare name may be a command's (version), which no C source names. */
#define CBF__PASS_KINDS(X)                                                                                        \
    X(CBF__KIND_TRUNCATED_HEADER) X(CBF__KIND_TRUNCATED_RECORD) X(CBF__KIND_PART_NUMBER)                          \
    X(CBF__KIND_DESCRIPTOR_WORD) X(CBF__KIND_CUTTER_TABLE) X(CBF__KIND_FILE_CHECKSUM) X(CBF__KIND_COMMAND_COUNT)  \
    X(CBF__KIND_HEADER_CHECKSUM) X(CBF__KIND_MAGIC) X(CBF__KIND_SEQUENCE) X(CBF__KIND_CODE_COPY)                  \
    X(CBF__KIND_ARG_SIZE) X(CBF__KIND_ARG_CHECKSUM) X(CBF__KIND_CONTINUITY) X(CBF__KIND_AVAILABILITY)             \
    X(CBF__KIND_VERSION) X(CBF__KIND_UNKNOWN_CODE) X(CBF__KIND_TRAILING) X(CBF__KIND_RESERVED_BYTE)               \
    X(CBF__KIND_STRING_TAIL) X(CBF__KIND_STRING_ASCII) X(CBF__KIND_FINITE) X(CBF__KIND_ORIENTATION)               \
    X(CBF__KIND_SHAPE) X(CBF__KIND_MACHINE_LIMITS) X(CBF__KIND_DEPRECATED)
#define CBF__JUDGED(k) CBF__JUDGED_##k = k,
#define CBF__ONE_MORE(k) +1
enum { CBF__PASS_KINDS(CBF__JUDGED) CBF__JUDGED__COUNT = 0 CBF__PASS_KINDS(CBF__ONE_MORE) };

static void cbf__vsay(cbf__vctx *v, int ci, long rec, size_t off, const char *fmt, va_list ap) CBF__PRINTF(5, 0);
static void cbf__vsay(cbf__vctx *v, int ci, long rec, size_t off, const char *fmt, va_list ap)
{
    char msg[256];
    cbf_finding f;
    unsigned scope = cbf__checks[ci].versions;
    if (scope && !(scope & CBF__VBIT(v->eff)))
        return; /* a check scoped to other versions (versions:) judges nothing in this file */
    (void)vsnprintf(msg, sizeof msg, fmt, ap);
    f.check = cbf__checks[ci].id;
    f.severity = cbf__checks[ci].severity;
    f.record = rec;
    f.offset = off;
    f.message = msg;
    if (f.severity == CBF_SEVERITY_ERROR)
        v->errors++;
    if (v->fn)
        v->fn(v->user, &f);
}

static void cbf__say(cbf__vctx *v, int ci, long rec, size_t off, const char *fmt, ...) CBF__PRINTF(5, 6);
static void cbf__say(cbf__vctx *v, int ci, long rec, size_t off, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    cbf__vsay(v, ci, rec, off, fmt, ap);
    va_end(ap);
}

/* A deprecation check's first version: the lowest bit of its mask (the loader makes the mask
 * since and every version after it). */
static int cbf__deprecation_since(int ci)
{
    int i;
    for (i = 0; i < CBF__NVERSIONS; i++)
        if (cbf__checks[ci].versions & CBF__VBIT(i))
            return i;
    return 0;
}

/* A finding for every check of a kind. */
static void cbf__each(cbf__vctx *v, int kind, long rec, size_t off, const char *fmt, ...) CBF__PRINTF(5, 6);
static void cbf__each(cbf__vctx *v, int kind, long rec, size_t off, const char *fmt, ...)
{
    int ci;
    for (ci = 0; ci < CBF__NCHECKS; ci++) {
        va_list ap;
        if (cbf__checks[ci].kind != kind)
            continue;
        va_start(ap, fmt);
        cbf__vsay(v, ci, rec, off, fmt, ap);
        va_end(ap);
    }
}

/* Appends to a message buffer (the findings' words are cbf validate's, the Python runtime's: some are
 * built in parts); a message longer than the buffer is cut, never overrun. */
static void cbf__cat(char *buf, size_t size, size_t *at, const char *fmt, ...) CBF__PRINTF(4, 5);
static void cbf__cat(char *buf, size_t size, size_t *at, const char *fmt, ...)
{
    va_list ap;
    int n;
    if (*at >= size)
        return;
    va_start(ap, fmt);
    n = vsnprintf(buf + *at, size - *at, fmt, ap);
    va_end(ap);
    if (n > 0)
        *at = *at + (size_t)n < size ? *at + (size_t)n : size - 1u;
}

/* A string value as text: its bytes read as ISO-8859-1 (the codec's string_value), out as UTF-8. */
static void cbf__text(char *buf, size_t size, size_t *at, const uint8_t *s, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        if (s[i] < 0x80u)
            cbf__cat(buf, size, at, "%c", (char)s[i]);
        else
            cbf__cat(buf, size, at, "%c%c", (char)(0xC0u | (s[i] >> 6)), (char)(0x80u | (s[i] & 0x3Fu)));
    }
}

/* A string value as Python's repr() writes it (the value decoded as ISO-8859-1): quoted with '
 * unless it holds a ' and no ", backslash escapes for the quote, \\, \t, \n, \r, and \xNN for
 * the code points str.isprintable() refuses (controls, 0x7F-0xA0, 0xAD). Code points above 0x7F
 * go out as UTF-8, as Python prints them. */
static void cbf__repr(char *buf, size_t size, size_t *at, const uint8_t *s, size_t n)
{
    size_t i;
    int sq = 0, dq = 0;
    char q;
    for (i = 0; i < n; i++) {
        sq |= s[i] == 0x27u;
        dq |= s[i] == 0x22u;
    }
    q = sq && !dq ? '"' : '\'';
    cbf__cat(buf, size, at, "%c", q);
    for (i = 0; i < n; i++) {
        uint8_t c = s[i];
        if (c == (uint8_t)q || c == 0x5Cu)
            cbf__cat(buf, size, at, "\\%c", (char)c);
        else if (c == 0x09u)
            cbf__cat(buf, size, at, "\\t");
        else if (c == 0x0Au)
            cbf__cat(buf, size, at, "\\n");
        else if (c == 0x0Du)
            cbf__cat(buf, size, at, "\\r");
        else if (c < 0x20u || (c >= 0x7Fu && c <= 0xA0u) || c == 0xADu)
            cbf__cat(buf, size, at, "\\x%02x", (unsigned)c);
        else
            cbf__text(buf, size, at, &c, 1u);
    }
    cbf__cat(buf, size, at, "%c", q);
}

/* The string's value: the bytes before the first NUL. */
static size_t cbf__strvalue_len(const uint8_t *s, size_t size)
{
    size_t i;
    for (i = 0; i < size; i++)
        if (s[i] == CBF__PAD)
            return i;
    return size;
}

/* The w (1, 2, 4 or 8) bytes at p, as the pad bytes compare with them (memcpy: any alignment). */
CBF__INLINE uint64_t cbf__bytes_at(const uint8_t *p, size_t w)
{
    uint64_t x8;
    uint32_t x4;
    uint16_t x2;
    switch (w) {
    case 8u: memcpy(&x8, p, 8u); return x8;
    case 4u: memcpy(&x4, p, 4u); return x4;
    case 2u: memcpy(&x2, p, 2u); return x2;
    default: return *p;
    }
}

/* Whether any of the n bytes at s is not the pad byte: words of 8 (4, 2, 1 below 8 bytes), the last
 * word overlapping the one before (the every-command file's strings are mostly padding, and a byte
 * loop over it was a fifth of its validation's instructions). */
CBF__INLINE int cbf__any_unpadded(const uint8_t *s, size_t n)
{
    const uint64_t pad = (uint64_t)CBF__PAD * 0x0101010101010101u;
    size_t w = n >= 8u ? 8u : n >= 4u ? 4u : n >= 2u ? 2u : 1u, i;
    uint64_t mask = w == 8u ? ~(uint64_t)0 : (((uint64_t)1 << (8u * w)) - 1u), diff = 0u;
    if (n == 0u)
        return 0;
    for (i = 0; i + w <= n; i += w)
        diff |= cbf__bytes_at(s + i, w) ^ (pad & mask);
    diff |= cbf__bytes_at(s + n - w, w) ^ (pad & mask); /* the rest: the last w bytes */
    return diff != 0u;
}

/* string_tail: the bytes after the first NUL, in hex, up to the last that is not NUL. Cold. */
CBF__COLD static void cbf__string_tail(cbf__vctx *v, const char *cmd, const cbf_field_info *f, const uint8_t *s,
                                       size_t n, size_t size, size_t base_off, long rec)
{
    char msg[256];
    size_t at = 0, last = size, i;
    while (last > n + 1u && s[last - 1u] == CBF__PAD)
        last--;
    cbf__cat(msg, sizeof msg, &at, "%s%s%s: bytes after the first NUL: ", cmd ? cmd : "", cmd ? "." : "", f->name);
    for (i = n + 1u; i < last; i++)
        cbf__cat(msg, sizeof msg, &at, "%02x", (unsigned)s[i]);
    cbf__each(v, CBF__KIND_STRING_TAIL, rec, base_off + f->offset, "%s", msg);
}

/* string_tail and string_ascii on one string field; cmd: the record's command name, NULL in the header. */
static void cbf__check_string(cbf__vctx *v, const char *cmd, const cbf_field_info *f, const uint8_t *base,
                              size_t base_off, long rec)
{
    const uint8_t *s = base + f->offset;
    size_t size = (size_t)f->elem * f->count;
    size_t n = cbf__strvalue_len(s, size), i;
    if (n < size && cbf__any_unpadded(s + n + 1u, size - n - 1u))
        cbf__string_tail(v, cmd, f, s, n, size, base_off, rec);
    for (i = 0; i < n; i++) {
        if (s[i] < 0x20u || s[i] > 0x7Eu) {
            cbf__each(v, CBF__KIND_STRING_ASCII, rec, base_off + f->offset, "%s%s%s: non-ASCII byte 0x%02X",
                      cmd ? cmd : "", cmd ? "." : "", f->name, (unsigned)s[i]);
            break;
        }
    }
}

/* Python's str.split() whitespace, for the ISO-8859-1 code points. */
static int cbf__space(uint8_t c)
{
    return c == 0x20u || (c >= 0x09u && c <= 0x0Du) || (c >= 0x1Cu && c <= 0x1Fu) || c == 0x85u || c == 0xA0u;
}

static void cbf__check_part_number(cbf__vctx *v)
{
    const cbf_field_info *f = cbf__header_field_by_role(v->hlayout, CBF_ROLE_IMPLANT_DESCRIPTOR);
    const uint8_t *s;
    size_t n, a, b, plen;
    if (!v->opt || !v->opt->part_number || !f)
        return;
    s = v->buf + f->offset;
    n = cbf__strvalue_len(s, (size_t)f->elem * f->count);
    for (a = 0; a < n && cbf__space(s[a]); a++) {}
    for (b = a; b < n && !cbf__space(s[b]); b++) {}
    plen = strlen(v->opt->part_number);
    if (plen != b - a || (plen && memcmp(s + a, v->opt->part_number, plen) != 0)) {
        char msg[512];
        size_t at = 0;
        cbf__cat(msg, sizeof msg, &at, "implant descriptor starts with ");
        cbf__repr(msg, sizeof msg, &at, s + a, b - a);
        cbf__cat(msg, sizeof msg, &at, ", expected ");
        cbf__repr(msg, sizeof msg, &at, (const uint8_t *)v->opt->part_number, plen);
        cbf__each(v, CBF__KIND_PART_NUMBER, -1, f->offset, "%s", msg);
    }
}

/* 4.2: the implant descriptor begins with the part number, so it holds at least one word. */
static void cbf__check_descriptor_word(cbf__vctx *v)
{
    const cbf_field_info *f = cbf__header_field_by_role(v->hlayout, CBF_ROLE_IMPLANT_DESCRIPTOR);
    const uint8_t *s;
    size_t n, a;
    if (!f)
        return;
    s = v->buf + f->offset;
    n = cbf__strvalue_len(s, (size_t)f->elem * f->count);
    for (a = 0; a < n && cbf__space(s[a]); a++) {}
    if (a == n)
        cbf__each(v, CBF__KIND_DESCRIPTOR_WORD, -1, f->offset,
                  "implant descriptor holds no word: no part number comes first");
}

static double cbf__norm(const double a[3]) { return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

/* The binary32 element at p, decoded once a record into *x (the generated layout
 * function reads each element of a float argument with it, one call an element,
 * and shares the values between the checks): 1 when it is finite. */
CBF__INLINE int cbf__float_at(const uint8_t *p, float *x)
{
    uint32_t u = cbf__get_u(p, 4);
    *x = cbf__bits_f4(u);
    return cbf__bits_finite(u);
}

/* The 3-element float argument at args + off as doubles: 1 when every element
 * is finite, else 0 (also when off < 0). Each element is read once. */
CBF__INLINE int cbf__vec_at(const uint8_t *args, long off, double out[3])
{
    unsigned i;
    int finite = 1;
    if (off < 0)
        return 0;
    for (i = 0; i < 3u; i++) {
        uint32_t u = cbf__get_u(args + off + 4u * i, 4);
        finite &= cbf__bits_finite(u);
        out[i] = (double)cbf__bits_f4(u);
    }
    return finite;
}

/* A float argument of n elements: its first as double; 1 when all are finite. */
CBF__INLINE int cbf__scalar_at(const uint8_t *args, long off, unsigned n, double *out)
{
    unsigned i;
    int finite = 1;
    *out = 0.0;
    if (off < 0)
        return 0;
    for (i = 0; i < n; i++) {
        uint32_t u = cbf__get_u(args + off + 4u * i, 4);
        finite &= cbf__bits_finite(u);
        if (i == 0u)
            *out = (double)cbf__bits_f4(u);
    }
    return finite;
}

/* A point of a circle or helix: start turned by th (rad, right-hand rule) about the unit axis k through
 * center, then advanced rise along k. Double precision, operations in the reference order. */
static void cbf__turned(const double start[3], const double center[3], const double k[3], double th, double rise,
                        double out[3])
{
    double p[3], kxv[3], rot[3], c, s, kdv;
    int i;
    for (i = 0; i < 3; i++)
        p[i] = start[i] - center[i];
    c = cos(th);
    s = sin(th);
    kxv[0] = k[1] * p[2] - k[2] * p[1];
    kxv[1] = k[2] * p[0] - k[0] * p[2];
    kxv[2] = k[0] * p[1] - k[1] * p[0];
    kdv = k[0] * p[0] + k[1] * p[1] + k[2] * p[2];
    for (i = 0; i < 3; i++)
        rot[i] = p[i] * c + kxv[i] * s + k[i] * kdv * (1.0 - c);
    for (i = 0; i < 3; i++)
        out[i] = center[i] + rot[i] + rise * k[i];
}

/* A circle or helix of a record's arguments: its start, centre, unit axis, turn (rad) and axial
 * advance; 0 when a value is not finite or the normal is zero. */
static int cbf__arc_of(int kind, const uint8_t *args, long o_start, long o_center, long o_normal, long o_deg,
                       unsigned n_deg, long o_len, unsigned n_len, double start[3], double center[3], double k[3],
                       double *th, double *length)
{
    double normal[3], deg = 0.0, nn;
    int i;
    *length = 0.0;
    if (!cbf__vec_at(args, o_start, start) || !cbf__vec_at(args, o_center, center)
        || !cbf__vec_at(args, o_normal, normal) || !cbf__scalar_at(args, o_deg, n_deg, &deg))
        return 0;
    if (kind == CBF__MOTION_HELIX && !cbf__scalar_at(args, o_len, n_len, length))
        return 0;
    nn = cbf__norm(normal);
    if (nn == 0.0)
        return 0;
    for (i = 0; i < 3; i++)
        k[i] = normal[i] / nn;
    *th = deg * (CBF__PI / 180.0);
    return 1;
}

/* Where a circle or helix ends (none when a value is not finite or the normal
 * is zero). */
static int cbf__arc_end(int kind, const uint8_t *args, long o_start, long o_center, long o_normal, long o_deg,
                        unsigned n_deg, long o_len, unsigned n_len, double end[3])
{
    double start[3], center[3], k[3], th, length;
    if (!cbf__arc_of(kind, args, o_start, o_center, o_normal, o_deg, n_deg, o_len, n_len, start, center, k, &th,
                     &length))
        return 0;
    cbf__turned(start, center, k, th, length, end);
    return 1;
}

/* 6.4.5: continuity of motion commands (M1). A point motion sets the current
 * position; every other motion command is compared with it when its start is
 * finite, then moves it to its end (none when a value is not finite or the
 * normal is zero). xs, xe: the start and end as the layout function decoded
 * them (ok_s, ok_e: finite; NULL: the layout has none). */
CBF__INLINE void cbf__continuity_at(cbf__vctx *v, int cmd, int kind, const uint8_t *args, long rec, size_t args_off,
                                    const float *xs, int ok_s, const float *xe, int ok_e, long o_start,
                                    long o_center, long o_normal, long o_deg, unsigned n_deg, long o_len,
                                    unsigned n_len)
{
    double end[3];
    int i;
    if (kind != CBF__MOTION_POINT && v->pos_ok && xs && ok_s) {
        double d[3], dist;
        for (i = 0; i < 3; i++)
            d[i] = (double)xs[i] - v->pos[i];
        dist = cbf__norm(d);
        if (dist > cbf__tol_position)
            cbf__each(v, CBF__KIND_CONTINUITY, rec, args_off + (size_t)o_start,
                      "%s starts %.6g mm from the current position", cbf__commands[cmd].name, dist);
    }
    if (kind == CBF__MOTION_POINT || kind == CBF__MOTION_LINE) {
        v->pos_ok = xe && ok_e;
        if (v->pos_ok)
            for (i = 0; i < 3; i++)
                end[i] = (double)xe[i];
    } else {
        v->pos_ok = cbf__arc_end(kind, args, o_start, o_center, o_normal, o_deg, n_deg, o_len, n_len, end);
    }
    if (v->pos_ok)
        for (i = 0; i < 3; i++)
            v->pos[i] = end[i];
}

/* orientation_jump (D2): the angle atan2(|a x b|, a . b) between a path
 * command's start and the current orientation (the last set/end vector that
 * was finite and non-zero). atan2 runs only when the angle may exceed the
 * tolerance: below tan^2 of a thousandth less than it (ori_tan2), it cannot.
 * xs, xe: the start and end vectors as decoded by the layout function (as in
 * cbf__continuity_at). */
CBF__INLINE void cbf__orientation_at(cbf__vctx *v, int cmd, int kind, long rec, size_t args_off, const float *xs,
                                     int ok_s, const float *xe, int ok_e)
{
    double a[3], b[3];
    int i;
    if (xs)
        for (i = 0; i < 3; i++)
            a[i] = (double)xs[i];
    if (kind == CBF__ORIENT_PATH && v->ori_ok && xs && ok_s && cbf__norm(a) > 0.0) {
        double cx[3], dot, c2;
        cx[0] = a[1] * v->ori[2] - a[2] * v->ori[1];
        cx[1] = a[2] * v->ori[0] - a[0] * v->ori[2];
        cx[2] = a[0] * v->ori[1] - a[1] * v->ori[0];
        dot = a[0] * v->ori[0] + a[1] * v->ori[1] + a[2] * v->ori[2];
        c2 = cx[0] * cx[0] + cx[1] * cx[1] + cx[2] * cx[2];
        if (!(dot > 0.0 && c2 < dot * dot * v->ori_tan2)) {
            double ang = atan2(cbf__norm(cx), dot) * (180.0 / CBF__PI);
            if (ang > cbf__tol_orientation)
                cbf__each(v, CBF__KIND_ORIENTATION, rec, args_off, "%s starts %.6g deg from the current orientation",
                          cbf__commands[cmd].name, ang);
        }
    }
    if (!xe || !ok_e) {
        v->ori_ok = 0;
        return;
    }
    for (i = 0; i < 3; i++)
        b[i] = (double)xe[i];
    v->ori_ok = cbf__norm(b) > 0.0;
    if (v->ori_ok)
        for (i = 0; i < 3; i++)
            v->ori[i] = b[i];
}

static int cbf__same_string(const uint8_t *a, size_t na, const uint8_t *b, size_t nb)
{
    /* equal after removing trailing NULs */
    while (na && a[na - 1] == CBF__PAD) na--;
    while (nb && b[nb - 1] == CBF__PAD) nb--;
    return na == nb && (na == 0 || memcmp(a, b, na) == 0);
}

/* The value of string field f of args (nothing when the layout has none), as text. */
static void cbf__name_of(char *buf, size_t size, size_t *at, const uint8_t *args, const cbf_field_info *f)
{
    if (f)
        cbf__text(buf, size, at, args + f->offset,
                  cbf__strvalue_len(args + f->offset, (size_t)f->elem * f->count));
}

static void cbf__shape(cbf__vctx *v, int cmd, int layout, const uint8_t *args, long rec, size_t off)
{
    const cbf__layout *L = &cbf__layouts[layout];
    int kind = cbf__commands[cmd].shape;
    if (cbf__commands[cmd].motion != CBF__MOTION_NONE && v->shape_open)
        v->shape_moves++;
    if (kind == CBF__SHAPE_START) {
        if (v->shape_open)
            cbf__each(v, CBF__KIND_SHAPE, rec, off, "%s inside the open shape of record %ld",
                      cbf__commands[cmd].name, v->shape_rec);
        v->shape_open = 1;
        v->shape_rec = rec;
        v->shape_off = off;
        v->shape_layout = layout;
        v->shape_args = args;
        v->shape_moves = 0;
    } else if (kind == CBF__SHAPE_END) {
        const cbf_field_info *fn, *fc, *sn, *sc;
        if (!v->shape_open) {
            cbf__each(v, CBF__KIND_SHAPE, rec, off, "%s without an open shape", cbf__commands[cmd].name);
            return;
        }
        v->shape_open = 0;
        fn = cbf__layout_arg(layout, L->shape[CBF__S_NAME]);
        fc = cbf__layout_arg(layout, L->shape[CBF__S_COUNT]);
        sn = cbf__layout_arg(v->shape_layout, cbf__layouts[v->shape_layout].shape[CBF__S_NAME]);
        sc = cbf__layout_arg(v->shape_layout, cbf__layouts[v->shape_layout].shape[CBF__S_COUNT]);
        {
            int same_name = !fn || !sn || cbf__same_string(args + fn->offset, (size_t)fn->elem * fn->count,
                                                           v->shape_args + sn->offset, (size_t)sn->elem * sn->count);
            uint32_t ce = fc ? cbf__get_u(args + fc->offset, fc->elem) : 0u;
            uint32_t cs = sc ? cbf__get_u(v->shape_args + sc->offset, sc->elem) : 0u;
            char msg[256];
            size_t at = 0;
            if (!same_name || (fc && sc && ce != cs)) {
                cbf__cat(msg, sizeof msg, &at, "%s ", cbf__commands[cmd].name);
                cbf__name_of(msg, sizeof msg, &at, args, fn);
                cbf__cat(msg, sizeof msg, &at, ",%lu does not repeat record %ld's ", (unsigned long)ce, v->shape_rec);
                cbf__name_of(msg, sizeof msg, &at, v->shape_args, sn);
                cbf__cat(msg, sizeof msg, &at, ",%lu", (unsigned long)cs);
                cbf__each(v, CBF__KIND_SHAPE, rec, off, "%s", msg);
            } else if (fc && sc && v->shape_moves != cs) {
                cbf__cat(msg, sizeof msg, &at, "shape ");
                cbf__name_of(msg, sizeof msg, &at, v->shape_args, sn);
                cbf__cat(msg, sizeof msg, &at, " encloses %lu motion commands, declares %lu", v->shape_moves,
                         (unsigned long)cs);
                cbf__each(v, CBF__KIND_SHAPE, rec, off, "%s", msg);
            }
        }
    }
}

static void cbf__cutter(cbf__vctx *v, int layout, const uint8_t *args, long rec, size_t off)
{
    /* the cutter role's keys: the name's first, then the table's values (cbfgen/options.py) */
    const cbf__layout *L = &cbf__layouts[layout];
    const cbf_field_info *fn = cbf__layout_arg(layout, L->cutter[0]);
    size_t i, n, found = (size_t)-1;
    int k;
    if (!v->opt || !v->opt->cutters || !fn)
        return;
    n = cbf__strvalue_len(args + fn->offset, (size_t)fn->elem * fn->count);
    for (i = 0; i < v->opt->ncutters; i++) {
        const char *name = v->opt->cutters[i].name;
        if (name && strlen(name) == n && (n == 0 || memcmp(name, args + fn->offset, n) == 0))
            found = i; /* the last entry of a name counts */
    }
    if (found == (size_t)-1) {
        char msg[256];
        size_t at = 0;
        cbf__cat(msg, sizeof msg, &at, "cutter ");
        cbf__repr(msg, sizeof msg, &at, args + fn->offset, n);
        cbf__cat(msg, sizeof msg, &at, " is not in the cutter table");
        cbf__each(v, CBF__KIND_CUTTER_TABLE, rec, off, "%s", msg);
        return;
    }
    for (k = 0; k < CBF_CUTTER_VALUES; k++) {
        const cbf_field_info *fv = cbf__layout_arg(layout, L->cutter[1 + k]);
        double ref = v->opt->cutters[found].value[k], x;
        if (!fv || fv->kind != CBF__K_FLOAT || !cbf__ffirst(args, fv, &x))
            continue;
        if (fabs(x - ref) > cbf__tol_cutter) { /* named by the cutter role's key, as cbf validate does */
            char msg[256];
            size_t at = 0;
            cbf__cat(msg, sizeof msg, &at, "cutter ");
            cbf__repr(msg, sizeof msg, &at, args + fn->offset, n);
            cbf__cat(msg, sizeof msg, &at, " %s %g mm, the table says %g mm", cbf__cutter_keys[1 + k], x, ref);
            cbf__each(v, CBF__KIND_CUTTER_TABLE, rec, off, "%s", msg);
        }
    }
}

/* The kernels of the checks with targets on one float argument f of the record (one signature,
 * cbf__argument_kernel; validator_layouts.c.j2 calls them through cbf__argument_kernels): positive,
 * nonzero_vector, range, nondecreasing (t: the target, for the previous value). xf: its f->count
 * elements as the layout function decoded them, finite: whether all are. Nothing is said about a value
 * that is not finite. */
CBF__INLINE void cbf__positive_at(cbf__vctx *v, int ci, size_t t, int cmd, const cbf_field_info *f, const float *xf,
                                  int finite, long rec, size_t args_off)
{
    unsigned i;
    int any_le = 0;
    (void)t;
    if (!finite)
        return;
    for (i = 0; i < f->count; i++)
        if (xf[i] <= 0.0f) any_le = 1;
    if (any_le)
        cbf__say(v, ci, rec, args_off + f->offset, "%s.%s is %g, must be > 0", cbf__commands[cmd].name, f->name,
                 (double)xf[0]);
}

CBF__INLINE void cbf__nonzero_vector_at(cbf__vctx *v, int ci, size_t t, int cmd, const cbf_field_info *f,
                                        const float *xf, int finite, long rec, size_t args_off)
{
    unsigned i;
    int all_zero = 1;
    (void)t;
    if (!finite)
        return;
    for (i = 0; i < f->count; i++)
        if (xf[i] != 0.0f) all_zero = 0;
    if (all_zero)
        cbf__say(v, ci, rec, args_off + f->offset, "%s.%s has zero length", cbf__commands[cmd].name, f->name);
}

/* range: the words of findings.range_text. */
CBF__INLINE void cbf__range_at(cbf__vctx *v, int ci, size_t t, int cmd, const cbf_field_info *f, const float *xf,
                               int finite, long rec, size_t args_off)
{
    const cbf__check *ch = &cbf__checks[ci];
    double x = (double)xf[0];
    (void)t;
    if (!finite)
        return;
    if (!(ch->has_min && (ch->min_open ? x <= ch->min : x < ch->min))
        && !(ch->has_max && (ch->max_open ? x >= ch->max : x > ch->max)))
        return;
    if (ch->has_min && ch->has_max)
        cbf__say(v, ci, rec, args_off + f->offset, "%s.%s is %g, outside %s%g..%g%s", cbf__commands[cmd].name,
                 f->name, x, ch->min_open ? "(" : "[", ch->min, ch->max, ch->max_open ? ")" : "]");
    else if (ch->has_min)
        cbf__say(v, ci, rec, args_off + f->offset, "%s.%s is %g, must be %s %g", cbf__commands[cmd].name,
                 f->name, x, ch->min_open ? ">" : ">=", ch->min);
    else
        cbf__say(v, ci, rec, args_off + f->offset, "%s.%s is %g, must be %s %g", cbf__commands[cmd].name,
                 f->name, x, ch->max_open ? "<" : "<=", ch->max);
}

CBF__INLINE void cbf__nondecreasing_at(cbf__vctx *v, int ci, size_t t, int cmd, const cbf_field_info *f,
                                       const float *xf, int finite, long rec, size_t args_off)
{
    double x = (double)xf[0];
    if (!finite)
        return;
    if (v->nd_ok[t] && x < v->nd_prev[t])
        cbf__say(v, ci, rec, args_off + f->offset, "%s.%s falls from %g to %g", cbf__commands[cmd].name,
                 f->name, v->nd_prev[t], x);
    v->nd_ok[t] = 1;
    v->nd_prev[t] = x;
}

/* ordered: the target's arguments, all finite, are in non-decreasing order (the kernel of a whole target,
 * cbf__target_kernel). */
static void cbf__ordered_at(cbf__vctx *v, int ci, size_t t, int cmd, int layout, const uint8_t *args, long rec,
                            size_t args_off)
{
    const cbf__target *tg = &cbf__targets[t];
    double prev = 0.0;
    int bad = 0;
    size_t a;
    for (a = 0; a < tg->n; a++) {
        const cbf_field_info *f = cbf__layout_arg(layout, cbf__target_arg_at[tg->first + a][layout]);
        double x;
        if (!f || f->kind != CBF__K_FLOAT || !cbf__ffirst(args, f, &x))
            return;
        if (a > 0 && x < prev)
            bad = 1;
        prev = x;
    }
    if (bad) { /* "<command>: a=1 <= b=0.5 <= c=2 does not hold", as cbf validate says it */
        char msg[256];
        size_t at = 0;
        cbf__cat(msg, sizeof msg, &at, "%s: ", cbf__commands[cmd].name);
        for (a = 0; a < tg->n; a++) {
            const cbf_field_info *f = cbf__layout_arg(layout, cbf__target_arg_at[tg->first + a][layout]);
            double x = 0.0;
            if (f)
                (void)cbf__ffirst(args, f, &x);
            cbf__cat(msg, sizeof msg, &at, "%s%s=%g", a ? " <= " : "", f ? f->name : "?", x);
        }
        cbf__cat(msg, sizeof msg, &at, " does not hold");
        cbf__say(v, ci, rec, args_off, "%s", msg);
    }
}

/* cbf__sum for a short n (at most 1024 bytes: the 16-bit lanes cannot overflow), inlined
 * where n is a constant: a record's head, a layout's arguments. With n constant the tests
 * below fold away. */
CBF__INLINE uint32_t cbf__sum_fixed(const uint8_t *p, size_t n)
{
    const uint64_t lo = 0x00FF00FF00FF00FFull;
    uint64_t lanes = 0, x, y;
    uint32_t acc = 0, w;
    size_t i = 0;
    if (n < 32u) { /* written out: gcc -O2 keeps a loop of 2 or 3 trips */
        if (n >= 16u) {
            memcpy(&x, p, sizeof x);
            memcpy(&y, p + 8u, sizeof y);
            lanes += (x & lo) + ((x >> 8) & lo) + (y & lo) + ((y >> 8) & lo);
            i = 16u;
        }
        if (n - i >= 8u) {
            memcpy(&x, p + i, sizeof x);
            lanes += (x & lo) + ((x >> 8) & lo);
            i += 8u;
        }
    } else { /* longer: a loop, which gcc vectorises */
        for (; n - i >= 8u; i += 8u) {
            memcpy(&x, p + i, sizeof x);
            lanes += (x & lo) + ((x >> 8) & lo);
        }
    }
    if (n - i >= 4u) { /* a 4-byte rest (a float argument) in the low lanes, not byte by byte */
        memcpy(&w, p + i, sizeof w);
        lanes += (uint64_t)((w & 0x00FF00FFu) + ((w >> 8) & 0x00FF00FFu));
        i += 4u;
    }
    if (n <= 256u) { /* the four lanes total at most 255 * 256 < 2^16: one multiply adds them in the top lane */
        acc = (uint32_t)((lanes * 0x0001000100010001ull) >> 48);
    } else {
        lanes = (lanes & 0x0000FFFF0000FFFFull) + ((lanes >> 16) & 0x0000FFFF0000FFFFull);
        acc = (uint32_t)(lanes & 0xFFFFFFFFull) + (uint32_t)(lanes >> 32);
    }
    for (; i < n; i++)
        acc += p[i];
    return acc;
}
/* ==== END runtime/validator.c ==== */
#line 4967 "cbf.h"
/* ==== BEGIN runtime/path.c: verbatim from generator/cbfgen/emit/c/runtime/path.c, edit it there ==== */
#line 1 "generator/cbfgen/emit/c/runtime/path.c"
/* ---- the drawn path of a motion record (issue 34: the workbench draws curves with the engine's geometry) ----
 * Points along a record's motion as its spec role reads it (start, through, end, centre, normal, turn,
 * advance): a circle or helix is turned about its axis by cbf__turned, the rotation the continuity check
 * ends it with (so the last point is the end the checks compare); an arc through a middle point is the
 * circle through the three. The points are spaced as the Python codec's drawing (cbf.geometry,
 * Curve.points): every CBF__PATH_STEP_DEG degrees of turn, at most CBF_PATH_MAX_POINTS; a flat circle of
 * more than one turn is drawn as one turn, then on to its end. */

#define CBF__PATH_STEP_DEG 5.0
#define CBF__TWO_PI (2.0 * CBF__PI)

/* The offset of the argument a layout's motion role names by key (-1: none); *n its element count. */
static long cbf__motion_arg(int layout, int key, unsigned *n)
{
    int i = cbf__layouts[layout].motion[key];
    const cbf_field_info *f;
    if (i < 0)
        return -1;
    f = &cbf__args[cbf__layouts[layout].first_arg + (size_t)i];
    if (n)
        *n = f->count;
    return (long)f->offset;
}

/* The offset of the end a layout's motion role names in a record of nargs argument bytes: when the end is
 * the layout's repeated group (a polyline's points), its last item, as the Python codec's drawing and the
 * continuity check take it; else the argument's own offset (-1: none, or no n tiles nargs). */
static long cbf__motion_end(int layout, size_t nargs)
{
    const cbf__layout *L = &cbf__layouts[layout];
    long off = cbf__motion_arg(layout, CBF__M_END, NULL);
    long n;
    if (off < 0 || L->group < 0 || L->motion[CBF__M_END] != L->group)
        return off;
    n = cbf__group_n(L, nargs);
    return n > 0 ? off + (long)(L->group_item * (size_t)(n - 1)) : -1;
}

/* ceil(x) steps, at least 1, at most max (x is a turn over the step: in degrees or in radians, as
 * cbf.geometry reckons each case, so the counts are its counts). */
static size_t cbf__path_steps(double x, size_t max)
{
    double n = ceil(x);
    if (!(n >= 1.0))
        return 1;
    return n > (double)max ? max : (size_t)n;
}

static void cbf__put(double (*out)[3], const double p[3])
{
    int i;
    for (i = 0; i < 3; i++)
        (*out)[i] = p[i];
}

/* Points of a turn th (rad, signed: about k by the right-hand rule) and an advance rise from start about
 * centre. A zero radius or turn is straight: start, then start advanced. */
static size_t cbf__path_turn(const double start[3], const double center[3], const double k[3], double th,
                             double rise, double (*out)[3])
{
    double v[3], perp[3], kdv, r, a = fabs(th), p[3];
    size_t n, j, at = 0;
    int i;
    for (i = 0; i < 3; i++)
        v[i] = start[i] - center[i];
    kdv = k[0] * v[0] + k[1] * v[1] + k[2] * v[2];
    for (i = 0; i < 3; i++)
        perp[i] = v[i] - k[i] * kdv;
    r = cbf__norm(perp);
    if (r == 0.0 || th == 0.0) {
        cbf__put(&out[0], start);
        for (i = 0; i < 3; i++)
            p[i] = start[i] + rise * k[i];
        cbf__put(&out[1], p);
        return 2;
    }
    if (rise == 0.0 && a > CBF__TWO_PI) {
        const double sign = th < 0.0 ? -1.0 : 1.0, rest = fmod(a, CBF__TWO_PI);
        const double step = CBF__PATH_STEP_DEG * (CBF__PI / 180.0);
        const size_t turn = cbf__path_steps(CBF__TWO_PI / step, CBF_PATH_MAX_POINTS / 2u);
        const size_t tail = cbf__path_steps(rest / step, CBF_PATH_MAX_POINTS / 2u);
        for (j = 0; j < turn; j++)
            cbf__turned(start, center, k, sign * (CBF__TWO_PI * (double)j / (double)turn), 0.0, out[at++]);
        for (j = 0; j < tail && at + 1 < CBF_PATH_MAX_POINTS; j++)
            cbf__turned(start, center, k, sign * (rest * (double)j / (double)tail), 0.0, out[at++]);
        cbf__turned(start, center, k, th, 0.0, out[at++]);
        return at;
    }
    n = cbf__path_steps((a * (180.0 / CBF__PI)) / CBF__PATH_STEP_DEG, CBF_PATH_MAX_POINTS - 1u);
    for (j = 0; j < n; j++)
        cbf__turned(start, center, k, th * ((double)j / (double)n), rise * ((double)j / (double)n), out[at++]);
    cbf__turned(start, center, k, th, rise, out[at++]); /* the end, as the continuity check has it */
    return at;
}

/* An arc from start through mid to end: the circle through the three, run start -> mid -> end; straight
 * when they are collinear, or so nearly that binary32 values cannot tell (cbf.geometry's rule). */
static size_t cbf__path_through(const double s[3], const double m[3], const double e[3], double (*out)[3])
{
    double u[3], w[3], n[3], a[3], rel[3], center[3], k[3], e1[3], e2[3], b[3], n2, r, th, big = 0.0, uu, ww;
    double ab[3], ap[3], den, t, d[3];
    int i;
    for (i = 0; i < 3; i++) {
        u[i] = m[i] - s[i];
        w[i] = e[i] - s[i];
        big = fmax(big, fmax(fabs(s[i]), fmax(fabs(m[i]), fabs(e[i]))));
    }
    n[0] = u[1] * w[2] - u[2] * w[1];
    n[1] = u[2] * w[0] - u[0] * w[2];
    n[2] = u[0] * w[1] - u[1] * w[0];
    n2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    /* the distance of mid from the line through start and end */
    for (i = 0; i < 3; i++) {
        ab[i] = e[i] - s[i];
        ap[i] = m[i] - s[i];
    }
    den = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
    t = den == 0.0 ? 0.0 : (ap[0] * ab[0] + ap[1] * ab[1] + ap[2] * ab[2]) / den;
    for (i = 0; i < 3; i++)
        d[i] = ap[i] - ab[i] * t;
    if (n2 == 0.0 || cbf__norm(d) <= ldexp(1.0, -24) * big) {
        cbf__put(&out[0], s);
        cbf__put(&out[1], e);
        return 2;
    }
    uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    ww = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
    for (i = 0; i < 3; i++)
        a[i] = w[i] * uu - u[i] * ww;
    rel[0] = (a[1] * n[2] - a[2] * n[1]) / (2.0 * n2);
    rel[1] = (a[2] * n[0] - a[0] * n[2]) / (2.0 * n2);
    rel[2] = (a[0] * n[1] - a[1] * n[0]) / (2.0 * n2);
    for (i = 0; i < 3; i++) {
        center[i] = s[i] + rel[i];
        k[i] = n[i] / sqrt(n2); /* start -> mid -> end runs anticlockwise about k */
        a[i] = s[i] - center[i];
    }
    r = cbf__norm(a);
    for (i = 0; i < 3; i++) {
        e1[i] = a[i] / r;
        b[i] = e[i] - center[i];
    }
    e2[0] = k[1] * e1[2] - k[2] * e1[1];
    e2[1] = k[2] * e1[0] - k[0] * e1[2];
    e2[2] = k[0] * e1[1] - k[1] * e1[0];
    th = atan2(b[0] * e2[0] + b[1] * e2[1] + b[2] * e2[2], b[0] * e1[0] + b[1] * e1[1] + b[2] * e1[2]);
    if (th <= 0.0)
        th += CBF__TWO_PI;
    return cbf__path_turn(s, center, k, th, 0.0, out);
}

int cbf_layout_moves(int layout)
{
    return cbf__layout_ok(layout) && cbf__commands[cbf__layouts[layout].command].motion != CBF__MOTION_NONE;
}

size_t cbf_motion_path(int layout, const uint8_t *args, size_t nargs, const double *from,
                       double (*out)[3])
{
    double start[3], end[3], mid[3], center[3], k[3], th, length;
    unsigned nd = 0, nl = 0;
    int kind;
    long o_deg, o_len;
    if (!cbf__layout_ok(layout) || !args || !out || nargs < cbf__layouts[layout].size)
        return 0;
    kind = cbf__commands[cbf__layouts[layout].command].motion;
    switch (kind) {
    case CBF__MOTION_POINT:
        if (!cbf__vec_at(args, cbf__motion_end(layout, nargs), end))
            return 0;
        cbf__put(&out[0], from ? from : end);
        cbf__put(&out[1], end);
        return 2;
    case CBF__MOTION_LINE:
        if (!cbf__vec_at(args, cbf__motion_arg(layout, CBF__M_START, NULL), start)
            || !cbf__vec_at(args, cbf__motion_end(layout, nargs), end))
            return 0;
        if (cbf__layouts[layout].motion[CBF__M_THROUGH] >= 0) {
            if (!cbf__vec_at(args, cbf__motion_arg(layout, CBF__M_THROUGH, NULL), mid))
                return 0;
            return cbf__path_through(start, mid, end, out);
        }
        cbf__put(&out[0], start);
        cbf__put(&out[1], end);
        return 2;
    case CBF__MOTION_CIRCLE:
    case CBF__MOTION_HELIX:
        o_deg = cbf__motion_arg(layout, CBF__M_DEGREES, &nd);
        o_len = cbf__motion_arg(layout, CBF__M_LENGTH, &nl);
        if (!cbf__arc_of(kind, args, cbf__motion_arg(layout, CBF__M_START, NULL),
                         cbf__motion_arg(layout, CBF__M_CENTER, NULL), cbf__motion_arg(layout, CBF__M_NORMAL, NULL),
                         o_deg, nd, o_len, nl, start, center, k, &th, &length))
            return 0;
        return cbf__path_turn(start, center, k, th, length, out);
    default:
        return 0;
    }
}
/* ==== END runtime/path.c ==== */
#line 5169 "cbf.h"
/* ---- machine limits (decision L1; machine.h.j2) ------------------------------ */
const char *const cbf_machine_limit_names[CBF_MACHINE__COUNT] = { "workspace", "speed", "acceleration", "cutter_length", "cutter_radius" };
const char *const cbf_machine_limit_units[CBF_MACHINE__COUNT] = { "mm", "m/s", "m/s^2", "mm", "mm" };
const int cbf_machine_limit_axes[CBF_MACHINE__COUNT] = { 3, 0, 0, 0, 0 };
const char *const cbf_machine_limit_axis_names[CBF_MACHINE__COUNT][CBF_MACHINE_MAX_AXES] = {
    { "x", "y", "z" }, /* workspace */
    { NULL, NULL, NULL }, /* speed */
    { NULL, NULL, NULL }, /* acceleration */
    { NULL, NULL, NULL }, /* cutter_length */
    { NULL, NULL, NULL }, /* cutter_radius */
};
const cbf_machine cbf_machine_default = { {
    { { -1000.0, -1000.0, -1000.0 }, { 1000.0, 1000.0, 1000.0 } }, /* workspace [mm] */
    { { 1e-05, 0.0, 0.0 }, { 1.0, 0.0, 0.0 } }, /* speed [m/s] */
    { { 0.0001, 0.0, 0.0 }, { 10.0, 0.0, 0.0 } }, /* acceleration [m/s^2] */
    { { 1.0, 0.0, 0.0 }, { 300.0, 0.0, 0.0 } }, /* cutter_length [mm] */
    { { 0.1, 0.0, 0.0 }, { 25.0, 0.0, 0.0 } }, /* cutter_radius [mm] */
} };

/* Per layout (cbf__mrule_first[layout] .. [layout + 1]): the argument (index in the layout),
 * the limit that bounds it, the check that reports it, its severity with a machine given, and
 * whether a positive check targets the argument too (a value <= 0 is then that check's). */
typedef struct cbf__mrule { int arg; int limit; int check; int given_error; int positive; } cbf__mrule;
static const cbf__mrule cbf__mrules[30] = {
    { 1, 0, 31, 1, 0 }, /* CHECKPOINT recovery_point: workspace */
    { 1, 3, 31, 1, 1 }, /* CUTTER length: cutter_length */
    { 2, 4, 31, 1, 1 }, /* CUTTER radius: cutter_radius */
    { 1, 3, 31, 1, 1 }, /* CUTTER_V1 length: cutter_length */
    { 2, 4, 31, 1, 1 }, /* CUTTER_V1 radius: cutter_radius */
    { 0, 0, 31, 1, 0 }, /* POINT point: workspace */
    { 0, 0, 31, 1, 0 }, /* LINE start: workspace */
    { 1, 0, 31, 1, 0 }, /* LINE end: workspace */
    { 0, 0, 31, 1, 0 }, /* LINE5B start_pos: workspace */
    { 1, 0, 31, 1, 0 }, /* LINE5B end_pos: workspace */
    { 0, 0, 31, 1, 0 }, /* ARC start: workspace */
    { 1, 0, 31, 1, 0 }, /* ARC middle: workspace */
    { 2, 0, 31, 1, 0 }, /* ARC end: workspace */
    { 0, 0, 31, 1, 0 }, /* ARC5B start_pos: workspace */
    { 1, 0, 31, 1, 0 }, /* ARC5B mid_pos: workspace */
    { 2, 0, 31, 1, 0 }, /* ARC5B end_pos: workspace */
    { 0, 0, 31, 1, 0 }, /* CIRCLE start: workspace */
    { 1, 0, 31, 1, 0 }, /* CIRCLE center: workspace */
    { 0, 0, 31, 1, 0 }, /* CIRCLE5B start: workspace */
    { 1, 0, 31, 1, 0 }, /* CIRCLE5B center: workspace */
    { 0, 0, 31, 1, 0 }, /* HELIX start: workspace */
    { 1, 0, 31, 1, 0 }, /* HELIX center: workspace */
    { 0, 0, 31, 1, 0 }, /* HELIX5B start: workspace */
    { 1, 0, 31, 1, 0 }, /* HELIX5B center: workspace */
    { 0, 1, 31, 1, 1 }, /* SPEED speed: speed */
    { 0, 2, 31, 1, 1 }, /* ACCEL accel: acceleration */
    { 1, 2, 31, 1, 1 }, /* ACCEL decel: acceleration */
    { 0, 1, 31, 1, 0 }, /* FCPARMS nom_speed: speed */
    { 1, 1, 31, 1, 0 }, /* FCPARMS max_speed: speed */
    { 2, 1, 31, 1, 0 }, /* FCPARMS min_speed: speed */
};
static const unsigned short cbf__mrule_first[CBF_LAYOUT__COUNT + 1] = { 0, 1, 1, 3, 5, 5, 5, 5, 5, 5, 5, 5, 5, 6, 8, 10, 13, 16, 18, 20, 22, 24, 25, 27, 27, 27, 27, 30, 30, 30, 30 };

/* out |= whether any of x's n components (n a constant) lies outside lo..hi: branch-free, written
 * out for each of the 3 axes so that it folds to n pairs of compares
 * (runtime/machine.c, cbf__machine_at). */
#define CBF__MACHINE_OUT(out, x, lo, hi, n) do { \
    if ((n) > 0u) (out) |= ((x)[0] < (lo)[0]) | ((x)[0] > (hi)[0]); \
    if ((n) > 1u) (out) |= ((x)[1] < (lo)[1]) | ((x)[1] > (hi)[1]); \
    if ((n) > 2u) (out) |= ((x)[2] < (lo)[2]) | ((x)[2] > (hi)[2]); \
} while (0)

/* ==== BEGIN runtime/machine.c: verbatim from generator/cbfgen/emit/c/runtime/machine.c, edit it there ==== */
#line 1 "generator/cbfgen/emit/c/runtime/machine.c"
/* ---- machine limits: the kernel of check kind machine_limits (decision L1) ----- */
/* A bound as the values it limits are stored: rounded to binary32, beyond its range infinite
 * (a value equal to a bound written in decimal is inside); the same rule in every binding. */
static double cbf__bound32(double b)
{
    if (b > 3.4028234663852886e38)
        return HUGE_VAL;
    if (b < -3.4028234663852886e38)
        return -HUGE_VAL;
    return (double)(float)b;
}

/* The limits a validation applies, each bound rounded to binary32 once. */
static void cbf__machine_start(cbf__vctx *v)
{
    unsigned k, i;
    v->machine = (v->opt && v->opt->machine) ? v->opt->machine : &cbf_machine_default;
    for (k = 0; k < CBF_MACHINE__COUNT; k++) {
        for (i = 0; i < CBF_MACHINE_MAX_AXES; i++) {
            v->mlo[k][i] = (float)cbf__bound32(v->machine->limit[k].min[i]); /* exact: binary32 or infinite */
            v->mhi[k][i] = (float)cbf__bound32(v->machine->limit[k].max[i]);
        }
    }
}

/* Rule j of cbf__mrules on an argument found outside its limit: one finding, naming the first
 * component out, unless a value is not finite (the finite check's) or the positive check
 * targets the argument and a value is <= 0 (that check's). item: which item of a repeated
 * group x is (named argument[item]), -1 for an argument. 1 when it found a breach. Off the
 * fast path: cold. */
CBF__COLD static int cbf__machine_breach_item(cbf__vctx *v, int cmd, int layout, unsigned j, const float *x,
                                              unsigned n, int finite, long rec, size_t off, long item)
{
    const cbf__mrule *r = &cbf__mrules[j];
    const float *lo = v->mlo[r->limit], *hi = v->mhi[r->limit];
    unsigned i, out = n;
    int le_zero = 0;
    for (i = 0; i < n && out == n; i++)
        if (x[i] < lo[i] || x[i] > hi[i])
            out = i;
    if (out == n)
        return 0; /* inside (a NaN compares false: the finite check's) */
    for (i = 0; i < n; i++)
        le_zero |= x[i] <= 0.0f;
    if (!finite || (r->positive && le_zero))
        return 0; /* the finite check's, or the positive check's */
    {
        const cbf_field_info *f = cbf__layout_arg(layout, r->arg);
        const cbf_machine_range *lim = &v->machine->limit[r->limit];
        const char *axis = cbf_machine_limit_axes[r->limit] ? cbf_machine_limit_axis_names[r->limit][out] : NULL;
        char msg[256], name[128];
        cbf_finding fd;
        if (cbf__checks[r->check].versions && !(cbf__checks[r->check].versions & CBF__VBIT(v->eff)))
            return 1; /* scoped to other versions (versions:) */
        if (item >= 0)
            (void)snprintf(name, sizeof name, "%s[%ld]", f ? f->name : "?", item);
        else
            (void)snprintf(name, sizeof name, "%s", f ? f->name : "?");
        (void)snprintf(msg, sizeof msg, "%s.%s%s%s is %.9g %s, outside the machine's %s %.9g..%.9g %s",
                       cbf__commands[cmd].name, name, axis ? " " : "", axis ? axis : "", (double)x[out],
                       cbf_machine_limit_units[r->limit], cbf_machine_limit_names[r->limit], lim->min[out],
                       lim->max[out], cbf_machine_limit_units[r->limit]);
        fd.check = cbf__checks[r->check].id;
        fd.severity = (v->opt && v->opt->machine) ? (r->given_error ? CBF_SEVERITY_ERROR : CBF_SEVERITY_WARNING)
                                                  : cbf__checks[r->check].severity;
        fd.record = rec;
        fd.offset = off;
        fd.message = msg;
        if (fd.severity == CBF_SEVERITY_ERROR)
            v->errors++;
        if (v->fn)
            v->fn(v->user, &fd);
    }
    return 1;
}

/* cbf__machine_breach_item for an argument (not an item of a group): the fast path's call. */
CBF__COLD static void cbf__machine_breach(cbf__vctx *v, int cmd, int layout, unsigned j, const float *x, unsigned n,
                                          int finite, long rec, size_t off)
{
    (void)cbf__machine_breach_item(v, cmd, layout, j, x, n, finite, rec, off, -1);
}

/* Rule j of cbf__mrules on its argument x (n floats, decoded once by the generated layout
 * function, finite: whether all are), called with j and n as constants: one branch-free
 * test of the box or range (CBF__MACHINE_OUT, written out per axis by machine.h.j2), the
 * exact finding only when a value is out. */
CBF__INLINE void cbf__machine_at(cbf__vctx *v, int cmd, int layout, unsigned j, const float *x, unsigned n, int finite,
                                 long rec, size_t off)
{
    const float *lo = v->mlo[cbf__mrules[j].limit], *hi = v->mhi[cbf__mrules[j].limit];
    int out = 0;
    CBF__MACHINE_OUT(out, x, lo, hi, n);
    if (out)
        cbf__machine_breach(v, cmd, layout, j, x, n, finite, rec, off);
}
/* ==== END runtime/machine.c ==== */
#line 5335 "cbf.h"
/* ==== BEGIN runtime/group_checks.c: verbatim from generator/cbfgen/emit/c/runtime/group_checks.c, edit it there ==== */
#line 1 "generator/cbfgen/emit/c/runtime/group_checks.c"
/* ---- the record checks of a repeated argument group (issue 25, point 3) ---------------- */
/* Whether the m binary32 values at p are all finite (the finite check judges a group as one
 * argument: one finding a record, at the group's first byte, as every binding says it). */
static inline int cbf__group_finite(const uint8_t *p, size_t m)
{
    size_t i;
    int finite = 1;
    for (i = 0; i < m; i++)
        finite &= cbf__bits_finite(cbf__get_u(p + 4u * i, 4));
    return finite;
}

/* machine_limits rule j on a group of n items at g (count floats, item_size bytes each): each
 * item is judged as an argument of its own (cbf__machine_breach_item: not when a value is not finite
 * or a positive check's); one finding a record, at the first item out, named group[item]. */
static inline void cbf__machine_group(cbf__vctx *v, int cmd, int layout, unsigned j, const uint8_t *g, size_t n,
                                      unsigned count, size_t item_size, long rec, size_t off)
{
    const float *lo = v->mlo[cbf__mrules[j].limit], *hi = v->mhi[cbf__mrules[j].limit];
    size_t i;
    for (i = 0; i < n; i++) {
        float x[CBF_MACHINE_MAX_AXES];
        unsigned e;
        int finite = 1, out = 0;
        for (e = 0; e < CBF_MACHINE_MAX_AXES; e++)
            x[e] = 0.0f;
        for (e = 0; e < count && e < CBF_MACHINE_MAX_AXES; e++)
            finite &= cbf__float_at(g + item_size * i + 4u * e, &x[e]);
        CBF__MACHINE_OUT(out, x, lo, hi, count);
        if (out && cbf__machine_breach_item(v, cmd, layout, j, x, count, finite, rec, off + item_size * i, (long)i))
            return;
    }
}
/* ==== END runtime/group_checks.c ==== */
#line 5372 "cbf.h"
/* ---- validation: the record checks of each layout, and cbf_validate ---------
 * The checks of a record whose arguments decode, one function a layout, in a
 * fixed order: finite floats and strings (argument order), the checks with
 * targets (check order), the cutter table, continuity, orientation, shapes.
 * Each float argument is read once, into x<arg> (ok<arg>: all its elements are
 * finite), and the checks share it. */
/* The kernels of the targeted check kinds (runtime/validator.c, cbf__<kind>_at), in tables indexed by kind
 * (enum cbf__kind), one table a signature ("shape"): a kind judging one float argument, a kind judging a
 * target's arguments together. The tables are made from the registry (views.kernel_shape): a targeted kind
 * the registry gains and the engine lacks fails the build, naming its kernel. An entry is a constant, so a
 * call through a table with a constant kind is a direct call. */
typedef void (*cbf__argument_kernel)(cbf__vctx *v, int ci, size_t t, int cmd, const cbf_field_info *f, const float *xf,
                                     int finite, long rec, size_t args_off);
typedef void (*cbf__target_kernel)(cbf__vctx *v, int ci, size_t t, int cmd, int layout, const uint8_t *args, long rec,
                                   size_t args_off);
static const cbf__argument_kernel cbf__argument_kernels[31 + 1] = { NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, cbf__positive_at, cbf__nonzero_vector_at, cbf__range_at, cbf__nondecreasing_at, NULL, NULL, NULL, NULL, NULL };
static const cbf__target_kernel cbf__target_kernels[31 + 1] = { NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, cbf__ordered_at, NULL, NULL, NULL, NULL };
/* Every check kind no kernel table holds is judged by one of the engine's passes (CBF__PASS_KINDS,
 * runtime/validator.c), once: a kind the registry gains and the engine does not judge fails the build here,
 * naming it. */
typedef char cbf__every_kind_judged_once[(CBF__JUDGED__COUNT == 26 && CBF__JUDGED_CBF__KIND_TRUNCATED_HEADER > 0 && CBF__JUDGED_CBF__KIND_TRUNCATED_RECORD > 0 && CBF__JUDGED_CBF__KIND_PART_NUMBER > 0 && CBF__JUDGED_CBF__KIND_DESCRIPTOR_WORD > 0 && CBF__JUDGED_CBF__KIND_CUTTER_TABLE > 0 && CBF__JUDGED_CBF__KIND_FILE_CHECKSUM > 0 && CBF__JUDGED_CBF__KIND_COMMAND_COUNT > 0 && CBF__JUDGED_CBF__KIND_HEADER_CHECKSUM > 0 && CBF__JUDGED_CBF__KIND_MAGIC > 0 && CBF__JUDGED_CBF__KIND_SEQUENCE > 0 && CBF__JUDGED_CBF__KIND_CODE_COPY > 0 && CBF__JUDGED_CBF__KIND_ARG_SIZE > 0 && CBF__JUDGED_CBF__KIND_ARG_CHECKSUM > 0 && CBF__JUDGED_CBF__KIND_CONTINUITY > 0 && CBF__JUDGED_CBF__KIND_AVAILABILITY > 0 && CBF__JUDGED_CBF__KIND_VERSION > 0 && CBF__JUDGED_CBF__KIND_UNKNOWN_CODE > 0 && CBF__JUDGED_CBF__KIND_TRAILING > 0 && CBF__JUDGED_CBF__KIND_RESERVED_BYTE > 0 && CBF__JUDGED_CBF__KIND_STRING_TAIL > 0 && CBF__JUDGED_CBF__KIND_STRING_ASCII > 0 && CBF__JUDGED_CBF__KIND_FINITE > 0 && CBF__JUDGED_CBF__KIND_ORIENTATION > 0 && CBF__JUDGED_CBF__KIND_SHAPE > 0 && CBF__JUDGED_CBF__KIND_MACHINE_LIMITS > 0 && CBF__JUDGED_CBF__KIND_DEPRECATED > 0) ? 1 : -1];
/* CHECKPOINT: 32 argument bytes */
CBF__HOT static void cbf__layout_checks_checkpoint(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const int cmd = 0; /* CHECKPOINT in cbf__commands */
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    float x1[3];
    const int ok1 = cbf__float_at(a + 16, &x1[0]) & cbf__float_at(a + 20, &x1[1]) & cbf__float_at(a + 24, &x1[2]); /* recovery_point */
    float x2[1];
    const int ok2 = cbf__float_at(a + 28, &x2[0]); /* completion */
    cbf__check_string(v, "CHECKPOINT", &cbf__args[0], a, ao, rec);
    if (!ok1)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 16u, "%s.%s is not finite", cbf__commands[cmd].name, "recovery_point");
    if (!ok2)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 28u, "%s.%s is not finite", cbf__commands[cmd].name, "completion");
    cbf__argument_kernels[CBF__KIND_RANGE](v, 27, 7u, cmd, &cbf__args[2], x2, ok2, rec, ao); /* checkpoint_range: CHECKPOINT completion */
    cbf__argument_kernels[CBF__KIND_NONDECREASING](v, 28, 8u, cmd, &cbf__args[2], x2, ok2, rec, ao); /* checkpoint_falling: CHECKPOINT completion */
    cbf__machine_at(v, cmd, CBF_LAYOUT_CHECKPOINT, 0u, x1, 3u, ok1, rec, ao + 16u); /* CHECKPOINT recovery_point: workspace */
}

/* CHECKPOINT_V1: 16 argument bytes */
CBF__HOT static void cbf__layout_checks_checkpoint_v1(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    cbf__check_string(v, "CHECKPOINT", &cbf__args[3], a, ao, rec);
}

/* CUTTER: 32 argument bytes */
CBF__HOT static void cbf__layout_checks_cutter(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const int cmd = 1; /* CUTTER in cbf__commands */
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    float x1[1];
    const int ok1 = cbf__float_at(a + 16, &x1[0]); /* length */
    float x2[1];
    const int ok2 = cbf__float_at(a + 20, &x2[0]); /* radius */
    float x3[1];
    const int ok3 = cbf__float_at(a + 24, &x3[0]); /* head_length */
    cbf__check_string(v, "CUTTER", &cbf__args[4], a, ao, rec);
    if (!ok1)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 16u, "%s.%s is not finite", cbf__commands[cmd].name, "length");
    if (!ok2)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 20u, "%s.%s is not finite", cbf__commands[cmd].name, "radius");
    if (!ok3)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 24u, "%s.%s is not finite", cbf__commands[cmd].name, "head_length");
    cbf__argument_kernels[CBF__KIND_POSITIVE](v, 25, 2u, cmd, &cbf__args[5], x1, ok1, rec, ao); /* cutter_positive: CUTTER length radius */
    cbf__argument_kernels[CBF__KIND_POSITIVE](v, 25, 2u, cmd, &cbf__args[6], x2, ok2, rec, ao); /* cutter_positive: CUTTER length radius */
    cbf__machine_at(v, cmd, CBF_LAYOUT_CUTTER, 1u, x1, 1u, ok1, rec, ao + 16u); /* CUTTER length: cutter_length */
    cbf__machine_at(v, cmd, CBF_LAYOUT_CUTTER, 2u, x2, 1u, ok2, rec, ao + 20u); /* CUTTER radius: cutter_radius */
    cbf__cutter(v, CBF_LAYOUT_CUTTER, a, rec, ao);
}

/* CUTTER_V1: 32 argument bytes */
CBF__HOT static void cbf__layout_checks_cutter_v1(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const int cmd = 1; /* CUTTER in cbf__commands */
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    float x1[1];
    const int ok1 = cbf__float_at(a + 16, &x1[0]); /* length */
    float x2[1];
    const int ok2 = cbf__float_at(a + 20, &x2[0]); /* radius */
    cbf__check_string(v, "CUTTER", &cbf__args[9], a, ao, rec);
    if (!ok1)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 16u, "%s.%s is not finite", cbf__commands[cmd].name, "length");
    if (!ok2)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 20u, "%s.%s is not finite", cbf__commands[cmd].name, "radius");
    cbf__argument_kernels[CBF__KIND_POSITIVE](v, 25, 2u, cmd, &cbf__args[10], x1, ok1, rec, ao); /* cutter_positive: CUTTER length radius */
    cbf__argument_kernels[CBF__KIND_POSITIVE](v, 25, 2u, cmd, &cbf__args[11], x2, ok2, rec, ao); /* cutter_positive: CUTTER length radius */
    cbf__machine_at(v, cmd, CBF_LAYOUT_CUTTER_V1, 3u, x1, 1u, ok1, rec, ao + 16u); /* CUTTER_V1 length: cutter_length */
    cbf__machine_at(v, cmd, CBF_LAYOUT_CUTTER_V1, 4u, x2, 1u, ok2, rec, ao + 20u); /* CUTTER_V1 radius: cutter_radius */
    cbf__cutter(v, CBF_LAYOUT_CUTTER_V1, a, rec, ao);
}

/* ORIENT: 24 argument bytes */
CBF__HOT static void cbf__layout_checks_orient(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const int cmd = 2; /* ORIENT in cbf__commands */
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    float x0[3];
    const int ok0 = cbf__float_at(a + 0, &x0[0]) & cbf__float_at(a + 4, &x0[1]) & cbf__float_at(a + 8, &x0[2]); /* approach */
    if (!ok0)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 0u, "%s.%s is not finite", cbf__commands[cmd].name, "approach");
    cbf__orientation_at(v, cmd, CBF__ORIENT_SET, rec, ao, NULL, 0, x0, ok0);
}

/* ORIENT5B: 24 argument bytes */
CBF__HOT static void cbf__layout_checks_orient5b(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const int cmd = 3; /* ORIENT5B in cbf__commands */
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    float x0[3];
    const int ok0 = cbf__float_at(a + 0, &x0[0]) & cbf__float_at(a + 4, &x0[1]) & cbf__float_at(a + 8, &x0[2]); /* start_approach */
    float x1[3];
    const int ok1 = cbf__float_at(a + 12, &x1[0]) & cbf__float_at(a + 16, &x1[1]) & cbf__float_at(a + 20, &x1[2]); /* end_approach */
    if (!ok0)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 0u, "%s.%s is not finite", cbf__commands[cmd].name, "start_approach");
    if (!ok1)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 12u, "%s.%s is not finite", cbf__commands[cmd].name, "end_approach");
    cbf__orientation_at(v, cmd, CBF__ORIENT_PATH, rec, ao, x0, ok0, x1, ok1);
}

/* PHASE: 16 argument bytes */
CBF__HOT static void cbf__layout_checks_phase(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    cbf__check_string(v, "PHASE", &cbf__args[17], a, ao, rec);
}

/* ENABLE_SKIP: 16 argument bytes */
CBF__HOT static void cbf__layout_checks_enable_skip(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    cbf__check_string(v, "ENABLE_SKIP", &cbf__args[18], a, ao, rec);
}

/* STARTSHAPE: 6 argument bytes */
CBF__HOT static void cbf__layout_checks_startshape(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const int cmd = 6; /* STARTSHAPE in cbf__commands */
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    cbf__check_string(v, "STARTSHAPE", &cbf__args[19], a, ao, rec);
    cbf__shape(v, cmd, CBF_LAYOUT_STARTSHAPE, a, rec, off);
}

/* ENDSHAPE: 6 argument bytes */
CBF__HOT static void cbf__layout_checks_endshape(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const int cmd = 7; /* ENDSHAPE in cbf__commands */
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    cbf__check_string(v, "ENDSHAPE", &cbf__args[21], a, ao, rec);
    cbf__shape(v, cmd, CBF_LAYOUT_ENDSHAPE, a, rec, off);
}

/* DECEL_OFF: 0 argument bytes */
CBF__HOT static void cbf__layout_checks_decel_off(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    (void)off;
    (void)v; (void)a; (void)rec;
}

/* DECEL_ON: 0 argument bytes */
CBF__HOT static void cbf__layout_checks_decel_on(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    (void)off;
    (void)v; (void)a; (void)rec;
}

/* POINT: 12 argument bytes */
CBF__HOT static void cbf__layout_checks_point(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const int cmd = 10; /* POINT in cbf__commands */
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    float x0[3];
    const int ok0 = cbf__float_at(a + 0, &x0[0]) & cbf__float_at(a + 4, &x0[1]) & cbf__float_at(a + 8, &x0[2]); /* point */
    if (!ok0)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 0u, "%s.%s is not finite", cbf__commands[cmd].name, "point");
    cbf__machine_at(v, cmd, CBF_LAYOUT_POINT, 5u, x0, 3u, ok0, rec, ao + 0u); /* POINT point: workspace */
    cbf__continuity_at(v, cmd, CBF__MOTION_POINT, a, rec, ao, NULL, 0, x0, ok0, -1, -1, -1, -1, 0u, -1, 0u);
    v->shape_moves += (unsigned long)v->shape_open; /* a motion command inside a shape */
}

/* LINE: 24 argument bytes */
CBF__HOT static void cbf__layout_checks_line(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const int cmd = 11; /* LINE in cbf__commands */
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    float x0[3];
    const int ok0 = cbf__float_at(a + 0, &x0[0]) & cbf__float_at(a + 4, &x0[1]) & cbf__float_at(a + 8, &x0[2]); /* start */
    float x1[3];
    const int ok1 = cbf__float_at(a + 12, &x1[0]) & cbf__float_at(a + 16, &x1[1]) & cbf__float_at(a + 20, &x1[2]); /* end */
    if (!ok0)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 0u, "%s.%s is not finite", cbf__commands[cmd].name, "start");
    if (!ok1)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 12u, "%s.%s is not finite", cbf__commands[cmd].name, "end");
    cbf__machine_at(v, cmd, CBF_LAYOUT_LINE, 6u, x0, 3u, ok0, rec, ao + 0u); /* LINE start: workspace */
    cbf__machine_at(v, cmd, CBF_LAYOUT_LINE, 7u, x1, 3u, ok1, rec, ao + 12u); /* LINE end: workspace */
    cbf__continuity_at(v, cmd, CBF__MOTION_LINE, a, rec, ao, x0, ok0, x1, ok1, 0, -1, -1, -1, 0u, -1, 0u);
    v->shape_moves += (unsigned long)v->shape_open; /* a motion command inside a shape */
}

/* LINE5B: 48 argument bytes */
CBF__HOT static void cbf__layout_checks_line5b(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const int cmd = 12; /* LINE5B in cbf__commands */
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    float x0[3];
    const int ok0 = cbf__float_at(a + 0, &x0[0]) & cbf__float_at(a + 4, &x0[1]) & cbf__float_at(a + 8, &x0[2]); /* start_pos */
    float x1[3];
    const int ok1 = cbf__float_at(a + 12, &x1[0]) & cbf__float_at(a + 16, &x1[1]) & cbf__float_at(a + 20, &x1[2]); /* end_pos */
    float x2[3];
    const int ok2 = cbf__float_at(a + 24, &x2[0]) & cbf__float_at(a + 28, &x2[1]) & cbf__float_at(a + 32, &x2[2]); /* start_orient */
    float x3[3];
    const int ok3 = cbf__float_at(a + 36, &x3[0]) & cbf__float_at(a + 40, &x3[1]) & cbf__float_at(a + 44, &x3[2]); /* end_orient */
    if (!ok0)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 0u, "%s.%s is not finite", cbf__commands[cmd].name, "start_pos");
    if (!ok1)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 12u, "%s.%s is not finite", cbf__commands[cmd].name, "end_pos");
    if (!ok2)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 24u, "%s.%s is not finite", cbf__commands[cmd].name, "start_orient");
    if (!ok3)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 36u, "%s.%s is not finite", cbf__commands[cmd].name, "end_orient");
    cbf__machine_at(v, cmd, CBF_LAYOUT_LINE5B, 8u, x0, 3u, ok0, rec, ao + 0u); /* LINE5B start_pos: workspace */
    cbf__machine_at(v, cmd, CBF_LAYOUT_LINE5B, 9u, x1, 3u, ok1, rec, ao + 12u); /* LINE5B end_pos: workspace */
    cbf__continuity_at(v, cmd, CBF__MOTION_LINE, a, rec, ao, x0, ok0, x1, ok1, 0, -1, -1, -1, 0u, -1, 0u);
    cbf__orientation_at(v, cmd, CBF__ORIENT_PATH, rec, ao, x2, ok2, x3, ok3);
    v->shape_moves += (unsigned long)v->shape_open; /* a motion command inside a shape */
}

/* ARC: 36 argument bytes */
CBF__HOT static void cbf__layout_checks_arc(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const int cmd = 13; /* ARC in cbf__commands */
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    float x0[3];
    const int ok0 = cbf__float_at(a + 0, &x0[0]) & cbf__float_at(a + 4, &x0[1]) & cbf__float_at(a + 8, &x0[2]); /* start */
    float x1[3];
    const int ok1 = cbf__float_at(a + 12, &x1[0]) & cbf__float_at(a + 16, &x1[1]) & cbf__float_at(a + 20, &x1[2]); /* middle */
    float x2[3];
    const int ok2 = cbf__float_at(a + 24, &x2[0]) & cbf__float_at(a + 28, &x2[1]) & cbf__float_at(a + 32, &x2[2]); /* end */
    if (!ok0)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 0u, "%s.%s is not finite", cbf__commands[cmd].name, "start");
    if (!ok1)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 12u, "%s.%s is not finite", cbf__commands[cmd].name, "middle");
    if (!ok2)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 24u, "%s.%s is not finite", cbf__commands[cmd].name, "end");
    cbf__machine_at(v, cmd, CBF_LAYOUT_ARC, 10u, x0, 3u, ok0, rec, ao + 0u); /* ARC start: workspace */
    cbf__machine_at(v, cmd, CBF_LAYOUT_ARC, 11u, x1, 3u, ok1, rec, ao + 12u); /* ARC middle: workspace */
    cbf__machine_at(v, cmd, CBF_LAYOUT_ARC, 12u, x2, 3u, ok2, rec, ao + 24u); /* ARC end: workspace */
    cbf__continuity_at(v, cmd, CBF__MOTION_LINE, a, rec, ao, x0, ok0, x2, ok2, 0, -1, -1, -1, 0u, -1, 0u);
    v->shape_moves += (unsigned long)v->shape_open; /* a motion command inside a shape */
}

/* ARC5B: 60 argument bytes */
CBF__HOT static void cbf__layout_checks_arc5b(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const int cmd = 14; /* ARC5B in cbf__commands */
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    float x0[3];
    const int ok0 = cbf__float_at(a + 0, &x0[0]) & cbf__float_at(a + 4, &x0[1]) & cbf__float_at(a + 8, &x0[2]); /* start_pos */
    float x1[3];
    const int ok1 = cbf__float_at(a + 12, &x1[0]) & cbf__float_at(a + 16, &x1[1]) & cbf__float_at(a + 20, &x1[2]); /* mid_pos */
    float x2[3];
    const int ok2 = cbf__float_at(a + 24, &x2[0]) & cbf__float_at(a + 28, &x2[1]) & cbf__float_at(a + 32, &x2[2]); /* end_pos */
    float x3[3];
    const int ok3 = cbf__float_at(a + 36, &x3[0]) & cbf__float_at(a + 40, &x3[1]) & cbf__float_at(a + 44, &x3[2]); /* start_orient */
    float x4[3];
    const int ok4 = cbf__float_at(a + 48, &x4[0]) & cbf__float_at(a + 52, &x4[1]) & cbf__float_at(a + 56, &x4[2]); /* end_orient */
    if (!ok0)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 0u, "%s.%s is not finite", cbf__commands[cmd].name, "start_pos");
    if (!ok1)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 12u, "%s.%s is not finite", cbf__commands[cmd].name, "mid_pos");
    if (!ok2)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 24u, "%s.%s is not finite", cbf__commands[cmd].name, "end_pos");
    if (!ok3)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 36u, "%s.%s is not finite", cbf__commands[cmd].name, "start_orient");
    if (!ok4)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 48u, "%s.%s is not finite", cbf__commands[cmd].name, "end_orient");
    cbf__machine_at(v, cmd, CBF_LAYOUT_ARC5B, 13u, x0, 3u, ok0, rec, ao + 0u); /* ARC5B start_pos: workspace */
    cbf__machine_at(v, cmd, CBF_LAYOUT_ARC5B, 14u, x1, 3u, ok1, rec, ao + 12u); /* ARC5B mid_pos: workspace */
    cbf__machine_at(v, cmd, CBF_LAYOUT_ARC5B, 15u, x2, 3u, ok2, rec, ao + 24u); /* ARC5B end_pos: workspace */
    cbf__continuity_at(v, cmd, CBF__MOTION_LINE, a, rec, ao, x0, ok0, x2, ok2, 0, -1, -1, -1, 0u, -1, 0u);
    cbf__orientation_at(v, cmd, CBF__ORIENT_PATH, rec, ao, x3, ok3, x4, ok4);
    v->shape_moves += (unsigned long)v->shape_open; /* a motion command inside a shape */
}

/* CIRCLE: 40 argument bytes */
CBF__HOT static void cbf__layout_checks_circle(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const int cmd = 15; /* CIRCLE in cbf__commands */
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    float x0[3];
    const int ok0 = cbf__float_at(a + 0, &x0[0]) & cbf__float_at(a + 4, &x0[1]) & cbf__float_at(a + 8, &x0[2]); /* start */
    float x1[3];
    const int ok1 = cbf__float_at(a + 12, &x1[0]) & cbf__float_at(a + 16, &x1[1]) & cbf__float_at(a + 20, &x1[2]); /* center */
    float x2[3];
    const int ok2 = cbf__float_at(a + 24, &x2[0]) & cbf__float_at(a + 28, &x2[1]) & cbf__float_at(a + 32, &x2[2]); /* normal */
    float x3[1];
    const int ok3 = cbf__float_at(a + 36, &x3[0]); /* ndegrees */
    if (!ok0)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 0u, "%s.%s is not finite", cbf__commands[cmd].name, "start");
    if (!ok1)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 12u, "%s.%s is not finite", cbf__commands[cmd].name, "center");
    if (!ok2)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 24u, "%s.%s is not finite", cbf__commands[cmd].name, "normal");
    if (!ok3)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 36u, "%s.%s is not finite", cbf__commands[cmd].name, "ndegrees");
    cbf__argument_kernels[CBF__KIND_NONZERO_VECTOR](v, 26, 3u, cmd, &cbf__args[40], x2, ok2, rec, ao); /* normal_nonzero: CIRCLE normal */
    cbf__machine_at(v, cmd, CBF_LAYOUT_CIRCLE, 16u, x0, 3u, ok0, rec, ao + 0u); /* CIRCLE start: workspace */
    cbf__machine_at(v, cmd, CBF_LAYOUT_CIRCLE, 17u, x1, 3u, ok1, rec, ao + 12u); /* CIRCLE center: workspace */
    cbf__continuity_at(v, cmd, CBF__MOTION_CIRCLE, a, rec, ao, x0, ok0, NULL, 0, 0, 12, 24, 36, 1u, -1, 0u);
    v->shape_moves += (unsigned long)v->shape_open; /* a motion command inside a shape */
}

/* CIRCLE5B: 64 argument bytes */
CBF__HOT static void cbf__layout_checks_circle5b(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const int cmd = 16; /* CIRCLE5B in cbf__commands */
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    float x0[3];
    const int ok0 = cbf__float_at(a + 0, &x0[0]) & cbf__float_at(a + 4, &x0[1]) & cbf__float_at(a + 8, &x0[2]); /* start */
    float x1[3];
    const int ok1 = cbf__float_at(a + 12, &x1[0]) & cbf__float_at(a + 16, &x1[1]) & cbf__float_at(a + 20, &x1[2]); /* center */
    float x2[3];
    const int ok2 = cbf__float_at(a + 24, &x2[0]) & cbf__float_at(a + 28, &x2[1]) & cbf__float_at(a + 32, &x2[2]); /* normal */
    float x3[1];
    const int ok3 = cbf__float_at(a + 36, &x3[0]); /* ndegrees */
    float x4[3];
    const int ok4 = cbf__float_at(a + 40, &x4[0]) & cbf__float_at(a + 44, &x4[1]) & cbf__float_at(a + 48, &x4[2]); /* start_orient */
    float x5[3];
    const int ok5 = cbf__float_at(a + 52, &x5[0]) & cbf__float_at(a + 56, &x5[1]) & cbf__float_at(a + 60, &x5[2]); /* end_orient */
    if (!ok0)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 0u, "%s.%s is not finite", cbf__commands[cmd].name, "start");
    if (!ok1)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 12u, "%s.%s is not finite", cbf__commands[cmd].name, "center");
    if (!ok2)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 24u, "%s.%s is not finite", cbf__commands[cmd].name, "normal");
    if (!ok3)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 36u, "%s.%s is not finite", cbf__commands[cmd].name, "ndegrees");
    if (!ok4)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 40u, "%s.%s is not finite", cbf__commands[cmd].name, "start_orient");
    if (!ok5)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 52u, "%s.%s is not finite", cbf__commands[cmd].name, "end_orient");
    cbf__argument_kernels[CBF__KIND_NONZERO_VECTOR](v, 26, 4u, cmd, &cbf__args[44], x2, ok2, rec, ao); /* normal_nonzero: CIRCLE5B normal */
    cbf__machine_at(v, cmd, CBF_LAYOUT_CIRCLE5B, 18u, x0, 3u, ok0, rec, ao + 0u); /* CIRCLE5B start: workspace */
    cbf__machine_at(v, cmd, CBF_LAYOUT_CIRCLE5B, 19u, x1, 3u, ok1, rec, ao + 12u); /* CIRCLE5B center: workspace */
    cbf__continuity_at(v, cmd, CBF__MOTION_CIRCLE, a, rec, ao, x0, ok0, NULL, 0, 0, 12, 24, 36, 1u, -1, 0u);
    cbf__orientation_at(v, cmd, CBF__ORIENT_PATH, rec, ao, x4, ok4, x5, ok5);
    v->shape_moves += (unsigned long)v->shape_open; /* a motion command inside a shape */
}

/* HELIX: 44 argument bytes */
CBF__HOT static void cbf__layout_checks_helix(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const int cmd = 17; /* HELIX in cbf__commands */
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    float x0[3];
    const int ok0 = cbf__float_at(a + 0, &x0[0]) & cbf__float_at(a + 4, &x0[1]) & cbf__float_at(a + 8, &x0[2]); /* start */
    float x1[3];
    const int ok1 = cbf__float_at(a + 12, &x1[0]) & cbf__float_at(a + 16, &x1[1]) & cbf__float_at(a + 20, &x1[2]); /* center */
    float x2[3];
    const int ok2 = cbf__float_at(a + 24, &x2[0]) & cbf__float_at(a + 28, &x2[1]) & cbf__float_at(a + 32, &x2[2]); /* normal */
    float x3[1];
    const int ok3 = cbf__float_at(a + 36, &x3[0]); /* ndegrees */
    float x4[1];
    const int ok4 = cbf__float_at(a + 40, &x4[0]); /* length */
    if (!ok0)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 0u, "%s.%s is not finite", cbf__commands[cmd].name, "start");
    if (!ok1)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 12u, "%s.%s is not finite", cbf__commands[cmd].name, "center");
    if (!ok2)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 24u, "%s.%s is not finite", cbf__commands[cmd].name, "normal");
    if (!ok3)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 36u, "%s.%s is not finite", cbf__commands[cmd].name, "ndegrees");
    if (!ok4)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 40u, "%s.%s is not finite", cbf__commands[cmd].name, "length");
    cbf__argument_kernels[CBF__KIND_NONZERO_VECTOR](v, 26, 5u, cmd, &cbf__args[50], x2, ok2, rec, ao); /* normal_nonzero: HELIX normal */
    cbf__machine_at(v, cmd, CBF_LAYOUT_HELIX, 20u, x0, 3u, ok0, rec, ao + 0u); /* HELIX start: workspace */
    cbf__machine_at(v, cmd, CBF_LAYOUT_HELIX, 21u, x1, 3u, ok1, rec, ao + 12u); /* HELIX center: workspace */
    cbf__continuity_at(v, cmd, CBF__MOTION_HELIX, a, rec, ao, x0, ok0, NULL, 0, 0, 12, 24, 36, 1u, 40, 1u);
    v->shape_moves += (unsigned long)v->shape_open; /* a motion command inside a shape */
}

/* HELIX5B: 68 argument bytes */
CBF__HOT static void cbf__layout_checks_helix5b(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const int cmd = 18; /* HELIX5B in cbf__commands */
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    float x0[3];
    const int ok0 = cbf__float_at(a + 0, &x0[0]) & cbf__float_at(a + 4, &x0[1]) & cbf__float_at(a + 8, &x0[2]); /* start */
    float x1[3];
    const int ok1 = cbf__float_at(a + 12, &x1[0]) & cbf__float_at(a + 16, &x1[1]) & cbf__float_at(a + 20, &x1[2]); /* center */
    float x2[3];
    const int ok2 = cbf__float_at(a + 24, &x2[0]) & cbf__float_at(a + 28, &x2[1]) & cbf__float_at(a + 32, &x2[2]); /* normal */
    float x3[1];
    const int ok3 = cbf__float_at(a + 36, &x3[0]); /* ndegrees */
    float x4[1];
    const int ok4 = cbf__float_at(a + 40, &x4[0]); /* length */
    float x5[3];
    const int ok5 = cbf__float_at(a + 44, &x5[0]) & cbf__float_at(a + 48, &x5[1]) & cbf__float_at(a + 52, &x5[2]); /* start_orient */
    float x6[3];
    const int ok6 = cbf__float_at(a + 56, &x6[0]) & cbf__float_at(a + 60, &x6[1]) & cbf__float_at(a + 64, &x6[2]); /* end_orient */
    if (!ok0)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 0u, "%s.%s is not finite", cbf__commands[cmd].name, "start");
    if (!ok1)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 12u, "%s.%s is not finite", cbf__commands[cmd].name, "center");
    if (!ok2)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 24u, "%s.%s is not finite", cbf__commands[cmd].name, "normal");
    if (!ok3)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 36u, "%s.%s is not finite", cbf__commands[cmd].name, "ndegrees");
    if (!ok4)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 40u, "%s.%s is not finite", cbf__commands[cmd].name, "length");
    if (!ok5)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 44u, "%s.%s is not finite", cbf__commands[cmd].name, "start_orient");
    if (!ok6)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 56u, "%s.%s is not finite", cbf__commands[cmd].name, "end_orient");
    cbf__argument_kernels[CBF__KIND_NONZERO_VECTOR](v, 26, 6u, cmd, &cbf__args[55], x2, ok2, rec, ao); /* normal_nonzero: HELIX5B normal */
    cbf__machine_at(v, cmd, CBF_LAYOUT_HELIX5B, 22u, x0, 3u, ok0, rec, ao + 0u); /* HELIX5B start: workspace */
    cbf__machine_at(v, cmd, CBF_LAYOUT_HELIX5B, 23u, x1, 3u, ok1, rec, ao + 12u); /* HELIX5B center: workspace */
    cbf__continuity_at(v, cmd, CBF__MOTION_HELIX, a, rec, ao, x0, ok0, NULL, 0, 0, 12, 24, 36, 1u, 40, 1u);
    cbf__orientation_at(v, cmd, CBF__ORIENT_PATH, rec, ao, x5, ok5, x6, ok6);
    v->shape_moves += (unsigned long)v->shape_open; /* a motion command inside a shape */
}

/* SPEED: 4 argument bytes */
CBF__HOT static void cbf__layout_checks_speed(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const int cmd = 19; /* SPEED in cbf__commands */
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    float x0[1];
    const int ok0 = cbf__float_at(a + 0, &x0[0]); /* speed */
    if (!ok0)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 0u, "%s.%s is not finite", cbf__commands[cmd].name, "speed");
    cbf__argument_kernels[CBF__KIND_POSITIVE](v, 23, 0u, cmd, &cbf__args[60], x0, ok0, rec, ao); /* speed_positive: SPEED speed */
    cbf__machine_at(v, cmd, CBF_LAYOUT_SPEED, 24u, x0, 1u, ok0, rec, ao + 0u); /* SPEED speed: speed */
}

/* ACCEL: 8 argument bytes */
CBF__HOT static void cbf__layout_checks_accel(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const int cmd = 20; /* ACCEL in cbf__commands */
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    float x0[1];
    const int ok0 = cbf__float_at(a + 0, &x0[0]); /* accel */
    float x1[1];
    const int ok1 = cbf__float_at(a + 4, &x1[0]); /* decel */
    if (!ok0)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 0u, "%s.%s is not finite", cbf__commands[cmd].name, "accel");
    if (!ok1)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 4u, "%s.%s is not finite", cbf__commands[cmd].name, "decel");
    cbf__argument_kernels[CBF__KIND_POSITIVE](v, 24, 1u, cmd, &cbf__args[61], x0, ok0, rec, ao); /* accel_positive: ACCEL accel decel */
    cbf__argument_kernels[CBF__KIND_POSITIVE](v, 24, 1u, cmd, &cbf__args[62], x1, ok1, rec, ao); /* accel_positive: ACCEL accel decel */
    cbf__machine_at(v, cmd, CBF_LAYOUT_ACCEL, 25u, x0, 1u, ok0, rec, ao + 0u); /* ACCEL accel: acceleration */
    cbf__machine_at(v, cmd, CBF_LAYOUT_ACCEL, 26u, x1, 1u, ok1, rec, ao + 4u); /* ACCEL decel: acceleration */
}

/* CUTTER_ON: 0 argument bytes */
CBF__HOT static void cbf__layout_checks_cutter_on(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    (void)off;
    (void)v; (void)a; (void)rec;
}

/* CUTTER_OFF: 0 argument bytes */
CBF__HOT static void cbf__layout_checks_cutter_off(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    (void)off;
    (void)v; (void)a; (void)rec;
}

/* GUIDE: 32 argument bytes */
CBF__HOT static void cbf__layout_checks_guide(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    cbf__check_string(v, "GUIDE", &cbf__args[63], a, ao, rec);
}

/* FCPARMS: 16 argument bytes */
CBF__HOT static void cbf__layout_checks_fcparms(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const int cmd = 24; /* FCPARMS in cbf__commands */
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    float x0[1];
    const int ok0 = cbf__float_at(a + 0, &x0[0]); /* nom_speed */
    float x1[1];
    const int ok1 = cbf__float_at(a + 4, &x1[0]); /* max_speed */
    float x2[1];
    const int ok2 = cbf__float_at(a + 8, &x2[0]); /* min_speed */
    float x3[1];
    const int ok3 = cbf__float_at(a + 12, &x3[0]); /* max_force */
    if (!ok0)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 0u, "%s.%s is not finite", cbf__commands[cmd].name, "nom_speed");
    if (!ok1)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 4u, "%s.%s is not finite", cbf__commands[cmd].name, "max_speed");
    if (!ok2)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 8u, "%s.%s is not finite", cbf__commands[cmd].name, "min_speed");
    if (!ok3)
        cbf__each(v, CBF__KIND_FINITE, rec, ao + 12u, "%s.%s is not finite", cbf__commands[cmd].name, "max_force");
    cbf__target_kernels[CBF__KIND_ORDERED](v, 29, 9u, cmd, CBF_LAYOUT_FCPARMS, a, rec, ao); /* fcparms_order: FCPARMS min_speed nom_speed max_speed */
    cbf__machine_at(v, cmd, CBF_LAYOUT_FCPARMS, 27u, x0, 1u, ok0, rec, ao + 0u); /* FCPARMS nom_speed: speed */
    cbf__machine_at(v, cmd, CBF_LAYOUT_FCPARMS, 28u, x1, 1u, ok1, rec, ao + 4u); /* FCPARMS max_speed: speed */
    cbf__machine_at(v, cmd, CBF_LAYOUT_FCPARMS, 29u, x2, 1u, ok2, rec, ao + 8u); /* FCPARMS min_speed: speed */
}

/* VERSION: 32 argument bytes */
CBF__HOT static void cbf__layout_checks_version(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    cbf__check_string(v, "VERSION", &cbf__args[68], a, ao, rec);
    cbf__check_string(v, "VERSION", &cbf__args[69], a, ao, rec);
}

/* VERSION_IMPLIB: 16 argument bytes */
CBF__HOT static void cbf__layout_checks_version_implib(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    cbf__check_string(v, "VERSION", &cbf__args[71], a, ao, rec);
    cbf__check_string(v, "VERSION", &cbf__args[72], a, ao, rec);
}

/* COMMENT: 40 argument bytes */
CBF__HOT static void cbf__layout_checks_comment(cbf__vctx *v, const uint8_t *a, long rec, size_t off)
{
    const size_t ao = off + CBF_RECORD_HEAD_SIZE;
    cbf__check_string(v, "COMMENT", &cbf__args[73], a, ao, rec);
}

/* The generated checks of a record's layout. */
static void cbf__decoded_checks(cbf__vctx *v, int layout, const uint8_t *args, long rec, size_t off)
{
    switch (layout) {
    case CBF_LAYOUT_CHECKPOINT: cbf__layout_checks_checkpoint(v, args, rec, off); break;
    case CBF_LAYOUT_CHECKPOINT_V1: cbf__layout_checks_checkpoint_v1(v, args, rec, off); break;
    case CBF_LAYOUT_CUTTER: cbf__layout_checks_cutter(v, args, rec, off); break;
    case CBF_LAYOUT_CUTTER_V1: cbf__layout_checks_cutter_v1(v, args, rec, off); break;
    case CBF_LAYOUT_ORIENT: cbf__layout_checks_orient(v, args, rec, off); break;
    case CBF_LAYOUT_ORIENT5B: cbf__layout_checks_orient5b(v, args, rec, off); break;
    case CBF_LAYOUT_PHASE: cbf__layout_checks_phase(v, args, rec, off); break;
    case CBF_LAYOUT_ENABLE_SKIP: cbf__layout_checks_enable_skip(v, args, rec, off); break;
    case CBF_LAYOUT_STARTSHAPE: cbf__layout_checks_startshape(v, args, rec, off); break;
    case CBF_LAYOUT_ENDSHAPE: cbf__layout_checks_endshape(v, args, rec, off); break;
    case CBF_LAYOUT_DECEL_OFF: cbf__layout_checks_decel_off(v, args, rec, off); break;
    case CBF_LAYOUT_DECEL_ON: cbf__layout_checks_decel_on(v, args, rec, off); break;
    case CBF_LAYOUT_POINT: cbf__layout_checks_point(v, args, rec, off); break;
    case CBF_LAYOUT_LINE: cbf__layout_checks_line(v, args, rec, off); break;
    case CBF_LAYOUT_LINE5B: cbf__layout_checks_line5b(v, args, rec, off); break;
    case CBF_LAYOUT_ARC: cbf__layout_checks_arc(v, args, rec, off); break;
    case CBF_LAYOUT_ARC5B: cbf__layout_checks_arc5b(v, args, rec, off); break;
    case CBF_LAYOUT_CIRCLE: cbf__layout_checks_circle(v, args, rec, off); break;
    case CBF_LAYOUT_CIRCLE5B: cbf__layout_checks_circle5b(v, args, rec, off); break;
    case CBF_LAYOUT_HELIX: cbf__layout_checks_helix(v, args, rec, off); break;
    case CBF_LAYOUT_HELIX5B: cbf__layout_checks_helix5b(v, args, rec, off); break;
    case CBF_LAYOUT_SPEED: cbf__layout_checks_speed(v, args, rec, off); break;
    case CBF_LAYOUT_ACCEL: cbf__layout_checks_accel(v, args, rec, off); break;
    case CBF_LAYOUT_CUTTER_ON: cbf__layout_checks_cutter_on(v, args, rec, off); break;
    case CBF_LAYOUT_CUTTER_OFF: cbf__layout_checks_cutter_off(v, args, rec, off); break;
    case CBF_LAYOUT_GUIDE: cbf__layout_checks_guide(v, args, rec, off); break;
    case CBF_LAYOUT_FCPARMS: cbf__layout_checks_fcparms(v, args, rec, off); break;
    case CBF_LAYOUT_VERSION: cbf__layout_checks_version(v, args, rec, off); break;
    case CBF_LAYOUT_VERSION_IMPLIB: cbf__layout_checks_version_implib(v, args, rec, off); break;
    case CBF_LAYOUT_COMMENT: cbf__layout_checks_comment(v, args, rec, off); break;
    default: break;
    }
}

/* The byte sum of a record's arguments, with the layout's size as a constant
 * (nb when the arguments have no layout). */
static uint32_t cbf__args_sum(int layout, const uint8_t *args, size_t nb)
{
    switch (layout) {
    case CBF_LAYOUT_CHECKPOINT: return cbf__sum_fixed(args, 32u);
    case CBF_LAYOUT_CHECKPOINT_V1: return cbf__sum_fixed(args, 16u);
    case CBF_LAYOUT_CUTTER: return cbf__sum_fixed(args, 32u);
    case CBF_LAYOUT_CUTTER_V1: return cbf__sum_fixed(args, 32u);
    case CBF_LAYOUT_ORIENT: return cbf__sum_fixed(args, 24u);
    case CBF_LAYOUT_ORIENT5B: return cbf__sum_fixed(args, 24u);
    case CBF_LAYOUT_PHASE: return cbf__sum_fixed(args, 16u);
    case CBF_LAYOUT_ENABLE_SKIP: return cbf__sum_fixed(args, 16u);
    case CBF_LAYOUT_STARTSHAPE: return cbf__sum_fixed(args, 6u);
    case CBF_LAYOUT_ENDSHAPE: return cbf__sum_fixed(args, 6u);
    case CBF_LAYOUT_DECEL_OFF: return cbf__sum_fixed(args, 0u);
    case CBF_LAYOUT_DECEL_ON: return cbf__sum_fixed(args, 0u);
    case CBF_LAYOUT_POINT: return cbf__sum_fixed(args, 12u);
    case CBF_LAYOUT_LINE: return cbf__sum_fixed(args, 24u);
    case CBF_LAYOUT_LINE5B: return cbf__sum_fixed(args, 48u);
    case CBF_LAYOUT_ARC: return cbf__sum_fixed(args, 36u);
    case CBF_LAYOUT_ARC5B: return cbf__sum_fixed(args, 60u);
    case CBF_LAYOUT_CIRCLE: return cbf__sum_fixed(args, 40u);
    case CBF_LAYOUT_CIRCLE5B: return cbf__sum_fixed(args, 64u);
    case CBF_LAYOUT_HELIX: return cbf__sum_fixed(args, 44u);
    case CBF_LAYOUT_HELIX5B: return cbf__sum_fixed(args, 68u);
    case CBF_LAYOUT_SPEED: return cbf__sum_fixed(args, 4u);
    case CBF_LAYOUT_ACCEL: return cbf__sum_fixed(args, 8u);
    case CBF_LAYOUT_CUTTER_ON: return cbf__sum_fixed(args, 0u);
    case CBF_LAYOUT_CUTTER_OFF: return cbf__sum_fixed(args, 0u);
    case CBF_LAYOUT_GUIDE: return cbf__sum_fixed(args, 32u);
    case CBF_LAYOUT_FCPARMS: return cbf__sum_fixed(args, 16u);
    case CBF_LAYOUT_VERSION: return cbf__sum_fixed(args, 32u);
    case CBF_LAYOUT_VERSION_IMPLIB: return cbf__sum_fixed(args, 16u);
    case CBF_LAYOUT_COMMENT: return cbf__sum_fixed(args, 40u);
    default: return cbf__sum(args, nb);
    }
}
/* ==== BEGIN runtime/validate.c: verbatim from generator/cbfgen/emit/c/runtime/validate.c, edit it there ==== */
#line 1 "generator/cbfgen/emit/c/runtime/validate.c"
/* ---- cbf_validate: the header, the record pass, the end of the file -------- */
/* Whether the profile's file checksum is the plain sum of every byte from a
 * start inside the header to the end of the file: the record pass then adds it
 * up as it goes (each record's head and argument sums), with no second pass. */
static int cbf__file_sum_folds(int profile, size_t *start)
{
    int cov = cbf__profiles[profile].file[0];
    const cbf__segment *seg;
    if (cov < 0 || cbf__algs[cbf__profiles[profile].file_alg].family != CBF__FAMILY_SUM || cbf__coverages[cov].n != 1u)
        return 0;
    seg = &cbf__segments[cbf__coverages[cov].first];
    if (seg->region != CBF__REGION_FILE || seg->start > CBF_HEADER_SIZE)
        return 0;
    *start = seg->start;
    return 1;
}

/* arg_size: "<command> with 20 argument bytes; expected 24" (the sizes of the command's layouts in the
 * file's version that the profile accepts, ascending, each once). Cold: a record of a bad size. */
CBF__COLD static void cbf__arg_size(cbf__vctx *v, int cmd, int profile, long rec, size_t off, size_t nb)
{
    char msg[256];
    size_t at = 0;
    long size = -1;
    int k, first = 1;
    cbf__cat(msg, sizeof msg, &at, "%s with %lu argument bytes; expected ", cbf__commands[cmd].name,
             (unsigned long)nb);
    /* ascending: each time the least size above the last of any layout (a repeated group takes
     * many, nb = size + k n), until none is left or the message is full */
    while (at + 1u < sizeof msg) {
        long next = -1;
        for (k = 0; k < CBF__MAX_CANDIDATES; k++) {
            int lay = cbf__commands[cmd].candidates[v->eff][k];
            long s;
            if (lay < 0)
                break;
            if (!cbf__profile_accepts(lay, profile))
                continue;
            s = cbf__layout_next_size(&cbf__layouts[lay], size);
            if (s >= 0 && (next < 0 || s < next))
                next = s;
        }
        if (next < 0)
            break;
        cbf__cat(msg, sizeof msg, &at, "%s%ld", first ? "" : " or ", next);
        first = 0;
        size = next;
    }
    cbf__each(v, CBF__KIND_ARG_SIZE, rec, off, "%s", msg);
}

/* shape: the file ends inside a shape, named by the command that opened it. */
CBF__COLD static void cbf__shape_unclosed(cbf__vctx *v)
{
    const cbf_field_info *sn = cbf__layout_arg(v->shape_layout, cbf__layouts[v->shape_layout].shape[CBF__S_NAME]);
    char msg[256];
    size_t at = 0;
    cbf__cat(msg, sizeof msg, &at, "shape ");
    cbf__name_of(msg, sizeof msg, &at, v->shape_args, sn);
    cbf__cat(msg, sizeof msg, &at, " is never closed");
    cbf__each(v, CBF__KIND_SHAPE, v->shape_rec, v->shape_off, "%s", msg);
}

/* Per command: the argument size last seen and what it gave (records of one
 * command almost always share one size). */
typedef struct cbf__seen { long nb; int accepted, layout, avail; } cbf__seen;

/* The head's argument checksum (6.4.4) differs: a finding of every arg_checksum check that judges
 * it (not those of a checksum field among a command's arguments, issue 25 point 1). */
static void cbf__head_sum_findings(cbf__vctx *v, long rec, size_t off, uint32_t got, uint32_t want)
{
    int ci;
    for (ci = 0; ci < CBF__NCHECKS; ci++)
        if (cbf__checks[ci].kind == CBF__KIND_ARG_CHECKSUM && !cbf__judges_argck(ci))
            cbf__say(v, ci, rec, off, "stored argument checksum %lu, computed %lu", (unsigned long)got,
                     (unsigned long)want);
}

/* Each checksum field among the arguments of the record at pos (rec, its nb argument bytes, of
 * layout), judged by its arg_checksum check at the field's offset (issue 25, point 1). */
static void cbf__check_argcks(cbf__vctx *v, int layout, const uint8_t *rec, size_t nb, long recno, size_t pos)
{
    size_t i;
    for (i = 0; i < sizeof cbf__argcks / sizeof cbf__argcks[0]; i++) {
        const cbf__argck *a = &cbf__argcks[i];
        const cbf__ckfield *k;
        uint32_t want, got;
        if (a->layout != layout || a->ckfield < 0 || (size_t)a->offset + a->elem > nb)
            continue;
        k = &cbf__ckfields[a->ckfield];
        if (k->check < 0)
            continue;
        want = cbf__argck_value(a, rec, nb);
        got = cbf__get_u(rec + CBF_RECORD_HEAD_SIZE + a->offset, a->elem);
        if (got != want)
            cbf__say(v, k->check, recno, pos + CBF_RECORD_HEAD_SIZE + a->offset, "stored %s checksum %lu, computed %lu",
                     k->name, (unsigned long)got, (unsigned long)want);
    }
}

/* The header: its version, magic numbers and strings, its checksum fields, the implant descriptor. */
static void cbf__validate_header(cbf__vctx *v, const cbf_header *h)
{
    const uint8_t *buf = v->buf;
    size_t i;
    if (v->version < 0)
        cbf__each(v, CBF__KIND_VERSION, -1, CBF__VERSION_MAJOR_OFFSET,
                  "version %u.%u is not a version of this spec; read as %s", h->major, h->minor,
                  cbf__versions[v->eff].id);
    /* header fields: magic numbers, strings */
    for (i = 0; i < cbf__headers[v->hlayout].nfields; i++) {
        const cbf_field_info *f = &cbf__headers[v->hlayout].fields[i];
        if ((f->flags & CBF__F_MAGIC) && f->kind == CBF__K_UINT) {
            uint32_t got = cbf__get_u(buf + f->offset, f->elem);
            if (got != f->magic)
                cbf__each(v, CBF__KIND_MAGIC, -1, f->offset, "%s is 0x%08lX, expected 0x%08lX", f->name,
                          (unsigned long)got, (unsigned long)f->magic);
        }
        if (f->kind == CBF__K_STRING)
            cbf__check_string(v, NULL, f, buf, 0, -1);
    }
    /* each header checksum field this version's header carries, judged by its header_checksum check */
    for (i = 0; i < sizeof cbf__ckfields / sizeof cbf__ckfields[0]; i++) {
        const cbf__ckfield *k = &cbf__ckfields[i];
        const cbf_field_info *f = k->check >= 0 ? cbf__header_field_by_tag(v->hlayout, k->tag) : NULL;
        if (f) {
            uint32_t want = cbf__cover(k->coverage, k->alg, f->elem, buf, v->len, CBF_HEADER_SIZE, NULL, 0);
            uint32_t got = cbf__get_u(buf + f->offset, f->elem);
            if (got != want)
                cbf__say(v, k->check, -1, f->offset, "stored %s checksum %lu, computed %lu", k->name,
                         (unsigned long)got, (unsigned long)want);
        }
    }
    cbf__check_part_number(v);
    cbf__check_descriptor_word(v);
}

/* The record pass's state: where it is, and the sums it adds up as it goes. */
typedef struct cbf__rpass {
    const cbf__ckfield *kck; /* the head's argument checksum field, or NULL */
    int args_sum;            /* it is a plain sum over the arguments alone (the spec's 6.4.4) */
    int folds;               /* the file checksum is summed up in the record pass (cbf__file_sum_folds) */
    int profile;
    uint32_t fold;
    size_t pos;
    unsigned long nrec;
    cbf__seen seen[CBF__NCOMMANDS];
} cbf__rpass;

/* A new argument size for the command: its layout, whether the profile accepts the size, and the
 * availability check that covers it in the file's version (-1: available). */
CBF__INLINE void cbf__seen_size(const cbf__vctx *v, cbf__seen *s, int cmd, uint32_t code, size_t nb, int profile)
{
    int k;
    s->nb = (long)nb;
    s->accepted = 0;
    for (k = 0; k < CBF__MAX_CANDIDATES; k++) {
        int lay = cbf__commands[cmd].candidates[v->eff][k];
        if (lay < 0)
            break;
        if (cbf__layout_takes(&cbf__layouts[lay], nb) && cbf__profile_accepts(lay, profile))
            s->accepted = 1;
    }
    s->layout = cbf_args_layout((int)code, v->eff, nb);
    /* availability: the command has no layout for the file's version (fallback included);
     * the finding names the one check that covers this command in this version */
    s->avail = (cbf__commands[cmd].versions & CBF__VBIT(v->eff)) ? -1 : cbf__avail_check[cmd][v->eff];
}

/* The record head at p: sequence number, code copy, argument checksums, reserved byte. */
CBF__INLINE void cbf__head_checks(cbf__vctx *v, const cbf__rpass *r, const uint8_t *p, size_t nb, int layout,
                                  uint32_t asum)
{
    const long rec = (long)r->nrec;
    const size_t pos = r->pos;
    const uint32_t code = CBF__HEAD_CODE(p), copy = CBF__HEAD_CODE_COPY(p), seq = CBF__HEAD_SEQUENCE(p);
    const uint32_t res = CBF__HEAD_RESERVED(p);
    if (seq != (uint32_t)(r->nrec & CBF__SEQUENCE_MASK))
        cbf__each(v, CBF__KIND_SEQUENCE, rec, pos + CBF__HEAD_OFF_SEQUENCE, "sequence number %lu, expected %lu",
                  (unsigned long)seq, (unsigned long)(r->nrec & CBF__SEQUENCE_MASK));
    if (code != copy)
        cbf__each(v, CBF__KIND_CODE_COPY, rec, pos + CBF__HEAD_OFF_CODE_COPY, "code copy 0x%02lX differs from code 0x%02lX",
                  (unsigned long)copy, (unsigned long)code);
#if CBF__HEAD_CK_ELEM
    {
        uint32_t want = r->args_sum ? (asum & CBF__HEAD_CK_MASK)
                        : r->kck ? cbf__cover(r->kck->coverage, r->kck->alg, CBF__HEAD_CK_ELEM, NULL, 0, 0,
                                              p + CBF_RECORD_HEAD_SIZE, nb)
                                 : 0u;
        uint32_t got = cbf__get_u(p + CBF__HEAD_CK_OFFSET, CBF__HEAD_CK_ELEM);
        if (got != want)
            cbf__head_sum_findings(v, rec, pos + CBF__HEAD_CK_OFFSET, got, want);
    }
#else
    (void)asum;
#endif
    if (layout >= 0)
        cbf__check_argcks(v, layout, p, nb, rec, pos);
    if (res != 0u)
        cbf__each(v, CBF__KIND_RESERVED_BYTE, rec, pos + CBF__HEAD_OFF_RESERVED, "reserved byte is 0x%02lX",
                  (unsigned long)res);
}

/* The record's command: known, available, of a size the profile accepts, not deprecated; then the checks
 * of its decoded arguments (the layout's function). */
CBF__INLINE void cbf__command_checks(cbf__vctx *v, const cbf__rpass *r, const uint8_t *p, int cmd, int layout,
                                     size_t nb)
{
    const long rec = (long)r->nrec;
    const size_t pos = r->pos;
    if (cmd < 0) {
        cbf__each(v, CBF__KIND_UNKNOWN_CODE, rec, pos + CBF__HEAD_OFF_CODE, "unknown command code 0x%02lX",
                  (unsigned long)CBF__HEAD_CODE(p));
        return;
    }
    if (r->seen[cmd].avail >= 0)
        cbf__say(v, r->seen[cmd].avail, rec, pos + CBF__HEAD_OFF_CODE, "%s is not available in version %s",
                 cbf__commands[cmd].name, cbf__versions[v->eff].id);
    if (!r->seen[cmd].accepted)
        cbf__arg_size(v, cmd, r->profile, rec, pos + CBF__HEAD_OFF_ARG_SIZE, nb);
    if (layout == CBF_LAYOUT__NONE)
        return;
    if (cbf__deprecated[layout] >= 0)
        cbf__say(v, cbf__deprecated[layout], rec, pos + CBF__HEAD_OFF_CODE, "%s is deprecated since version %s",
                 cbf__commands[cmd].name, cbf__versions[cbf__deprecation_since(cbf__deprecated[layout])].id);
    cbf__decoded_checks(v, layout, p + CBF_RECORD_HEAD_SIZE, rec, pos);
}

/* The records, framed by nb from the header to the end of the file (D1). */
static void cbf__record_pass(cbf__vctx *v, cbf__rpass *r)
{
    const uint8_t *buf = v->buf;
    const size_t len = v->len;
    size_t i;
    for (i = 0; i < (size_t)CBF__NCOMMANDS; i++)
        r->seen[i].nb = -1;
    while (len - r->pos >= CBF_RECORD_HEAD_SIZE) {
        const uint8_t *p = buf + r->pos;
        size_t nb = CBF__HEAD_ARG_SIZE(p);
        uint32_t code, asum = 0u;
        int cmd, layout = CBF_LAYOUT__NONE;
        if (len - r->pos - CBF_RECORD_HEAD_SIZE < nb)
            break;
        code = CBF__HEAD_CODE(p);
        cmd = cbf__cmd_index((int)code);
        if (cmd >= 0 && r->seen[cmd].nb != (long)nb) /* a new size for the command: look its layout up */
            cbf__seen_size(v, &r->seen[cmd], cmd, code, nb, r->profile);
        if (cmd >= 0)
            layout = r->seen[cmd].layout;
        if (r->args_sum)
            asum = cbf__args_sum(layout, p + CBF_RECORD_HEAD_SIZE, nb);
        if (r->folds)
            r->fold += CBF__HEAD_SUM(p) + asum;
        cbf__head_checks(v, r, p, nb, layout, asum);
        cbf__command_checks(v, r, p, cmd, layout, nb);
        r->pos += CBF_RECORD_HEAD_SIZE + nb;
        r->nrec++;
    }
}

/* The end of the file: an open shape, a record cut short or bytes after the last record, the count. */
static void cbf__validate_end(cbf__vctx *v, const cbf_header *h, const cbf__rpass *r)
{
    const size_t pos = r->pos, len = v->len;
    const unsigned long nrec = r->nrec;
    int truncated = 0;
    if (v->shape_open)
        cbf__shape_unclosed(v);
    if (pos < len) {
        if (nrec < h->count) {
            truncated = 1;
            cbf__each(v, CBF__KIND_TRUNCATED_RECORD, (long)nrec, pos,
                      "the file ends inside record %lu (%lu byte(s) left)", nrec, (unsigned long)(len - pos));
        } else {
            cbf__each(v, CBF__KIND_TRAILING, -1, pos, "%lu byte(s) after the last record", (unsigned long)(len - pos));
        }
    }
    if (!truncated && nrec != h->count) {
        const cbf_field_info *fc = cbf__header_field_by_role(v->hlayout, CBF_ROLE_COMMAND_COUNT);
        cbf__each(v, CBF__KIND_COMMAND_COUNT, -1, fc ? fc->offset : 0u, "header count %lu, the file holds %lu records",
                  h->count, nrec);
    }
}

/* file_checksum differs from every coverage of the profile: one message, the sums, then every hint coverage
 * the stored value matches. Cold. */
CBF__COLD static void cbf__file_sum_finding(cbf__vctx *v, const cbf_field_info *f, int profile, size_t pos,
                                            uint32_t got, uint32_t first)
{
    const cbf__profile *pr = &cbf__profiles[profile];
    char msg[512];
    size_t at = 0;
    int c;
    cbf__cat(msg, sizeof msg, &at, "stored file checksum %lu, computed %lu", (unsigned long)got, (unsigned long)first);
    for (c = 0; c < CBF__MAX_COVERAGES && pr->hint[c] >= 0; c++) {
        if (cbf__cover(pr->hint[c], pr->hint_alg[c], f->elem, v->buf, v->len, pos, NULL, 0) == got)
            cbf__cat(msg, sizeof msg, &at, "; it matches coverage %s (use profile %s)", cbf__coverages[pr->hint[c]].name,
                     pr->hint_owner[c] >= 0 ? cbf__profiles[pr->hint_owner[c]].id : "?");
    }
    cbf__each(v, CBF__KIND_FILE_CHECKSUM, -1, f->offset, "%s", msg);
}

/* The file checksum field, against every coverage of the profile (the first folded into the record pass
 * when it is a plain sum from inside the header, and the bytes after the last record). */
static void cbf__check_file_sum(cbf__vctx *v, const cbf__rpass *r)
{
    const cbf__ckfield *k = cbf__ckfield_of(CBF__CK_FILE);
    const cbf_field_info *f = cbf__header_field_by_tag(v->hlayout, CBF__CK_FILE);
    const int profile = r->profile;
    uint32_t got, first = 0u;
    int c, match = 0;
    if (!k || !f)
        return;
    got = cbf__get_u(v->buf + f->offset, f->elem);
    for (c = 0; c < CBF__MAX_COVERAGES && cbf__profiles[profile].file[c] >= 0; c++) {
        uint32_t want;
        if (c == 0 && r->folds) { /* the record pass's sum, and the bytes after the last record */
            want = r->fold + cbf__sum(v->buf + r->pos, v->len - r->pos);
            if (f->elem < 4u)
                want &= (1u << (8u * f->elem)) - 1u;
        } else {
            want = cbf__cover(cbf__profiles[profile].file[c], cbf__profiles[profile].file_alg, f->elem, v->buf, v->len,
                              r->pos, NULL, 0);
        }
        if (c == 0)
            first = want;
        if (want == got)
            match = 1;
    }
    if (!match)
        cbf__file_sum_finding(v, f, profile, r->pos, got, first);
}

CBF__HOT long cbf_validate(const uint8_t *buf, size_t len, const cbf_options *opt, cbf_finding_fn fn,
                          void *user)
{
    cbf__vctx v;
    cbf_header h;
    cbf__rpass r;
    size_t fold_start = 0;
    int profile = opt ? opt->profile : CBF__DEFAULT_PROFILE;
    if ((!buf && len) || profile < 0 || profile >= CBF_PROFILE__COUNT)
        return CBF_ERR_ARGUMENT;
    memset(&v, 0, sizeof v);
    v.buf = buf;
    v.len = len;
    v.opt = opt;
    v.fn = fn;
    v.user = user;
    /* below this tan^2 the orientation angle is under its tolerance (with a margin of 1/1000) */
    v.ori_tan2 = cbf__tol_orientation > 0.0 && cbf__tol_orientation < 45.0
                 ? pow(tan(cbf__tol_orientation * 0.999 * (CBF__PI / 180.0)), 2.0) : 0.0;
    cbf__machine_start(&v);
    if (len < CBF_HEADER_SIZE || !buf) {
        cbf__each(&v, CBF__KIND_TRUNCATED_HEADER, -1, 0, "file is %lu bytes, the header needs %d",
                  (unsigned long)len, CBF_HEADER_SIZE);
        return v.errors;
    }
    (void)cbf_header_decode(buf, len, &h);
    v.version = h.version;
    v.eff = cbf__eff_version(h.version);
    v.hlayout = h.layout;
    cbf__validate_header(&v, &h);

    r.pos = CBF_HEADER_SIZE;
    r.nrec = 0;
    r.profile = profile;
    r.fold = 0u;
    r.kck = cbf__ckfield_of(CBF__CK_ARGS);
    /* a plain sum over the arguments alone (the spec's 6.4.4) needs no coverage walk */
    r.args_sum = r.kck && cbf__algs[r.kck->alg].family == CBF__FAMILY_SUM && cbf__coverages[r.kck->coverage].n == 1u
                 && cbf__segments[cbf__coverages[r.kck->coverage].first].region == CBF__REGION_ARGS;
    r.folds = r.args_sum && cbf__file_sum_folds(profile, &fold_start);
    if (r.folds)
        r.fold = cbf__sum(buf + fold_start, CBF_HEADER_SIZE - fold_start);
    cbf__record_pass(&v, &r);
    cbf__validate_end(&v, &h, &r);
    cbf__check_file_sum(&v, &r);
    return v.errors;
}
/* ==== END runtime/validate.c ==== */
#line 6358 "cbf.h"
/* ---- the CUT text form's syntax (spec `cut`), read by cbf_cut_encode (runtime/cut.c) ---- */
#define CBF__CUT_LOWER 1 /* keywords compare in lower case */
static const char cbf__cut_header[] = "header";
static const char cbf__cut_header_ext[] = "header_ext";
static const char cbf__cut_checksum[] = "check_sum";
static const char cbf__cut_version[] = "cbf_version";
static const char cbf__cut_field[] = "cbf_field";
static const char cbf__cut_record[] = "cbf_record";
static const char cbf__cut_open[] = "<";
static const char cbf__cut_close[] = ">";
static const char cbf__cut_sep[] = ",";
/* The header roles CUT text never sets (written by the writer), CBF_ROLE_NONE ends. */
static const int cbf__cut_derived[] = { CBF_ROLE_START_PATTERN, CBF_ROLE_END_PATTERN, CBF_ROLE_VERSION_MAJOR, CBF_ROLE_VERSION_MINOR, CBF_ROLE_COMMAND_COUNT, CBF_ROLE_CHECKSUM, CBF_ROLE_NONE };
/* A command's former names read as the command (issue 25, point 6); NULL ends. */
static const struct cbf__cut_alias { const char *name; int code; } cbf__cut_former[] = {
    { NULL, -1 }
};
#define CBF__CUT_MAX_HEADER_FIELDS 10u
/* ==== BEGIN runtime/cut.c: verbatim from generator/cbfgen/emit/c/runtime/cut.c, edit it there ==== */
#line 1 "generator/cbfgen/emit/c/runtime/cut.c"
/* ---- CUT text -> CBF: cbf_cut_encode ----------------------------------------------------------------
 * The reader of cbf's CUT text (cut.py, from_cut) followed by its writer (codec.pack_file, every derived
 * value filled), on a buffer: the same language read into the same bytes (tests/test_c_cut_parity.py holds
 * the two to it). The words of the syntax are the spec's (cbf/cut.c.j2: the keywords, the vector's signs,
 * the derived header roles, former command names); the commands, their layouts and the header fields are
 * the tables'. Reading never changes what the text means: a line holds printable ASCII and ends at LF or
 * CR LF; a header line given twice, text after a keyword's arguments, a number beyond binary32 are
 * refused. Memory: the text is read in place, the file is written into the caller's buffer, nothing else
 * grows with the input. */

#define CBF__CUT_SHOW 40u        /* characters of a token quoted in a message */
#define CBF__CUT_INT_DIGITS 39u  /* a number of more integer digits (leading zeros aside) is >= 1e39 */
#define CBF__CUT_FRAC_DIGITS 200u /* fraction digits kept exactly (every binary32 halfway point has <= 150) */

typedef struct cbf__cutp {
    const char *t;        /* the text */
    size_t ls, le;        /* the current line, stripped of spaces: [ls, le) */
    size_t kw, kwlen;     /* its keyword */
    size_t pos;           /* the cursor, in (kw + kwlen, le] */
    unsigned long line;
    cbf_cut_error *err;
} cbf__cutp;

static int cbf__cut_digit(char ch) { return ch >= '0' && ch <= '9'; }

static char cbf__cut_lower(char ch) { return (ch >= 'A' && ch <= 'Z') ? (char)(ch - 'A' + 'a') : ch; }

/* A token of the text for a message: between quotes, cut short when long (cbf's _show). */
static const char *cbf__cut_show(char *buf, size_t cap, const char *s, size_t n)
{
    if (n <= CBF__CUT_SHOW)
        (void)snprintf(buf, cap, "'%.*s'", (int)n, s);
    else
        (void)snprintf(buf, cap, "'%.*s'... (%lu characters)", (int)CBF__CUT_SHOW, s, (unsigned long)n);
    return buf;
}

static int cbf__cut_vsay(cbf_cut_error *err, unsigned long line, unsigned long column, const char *fmt, va_list ap)
    CBF__PRINTF(4, 0);
static int cbf__cut_vsay(cbf_cut_error *err, unsigned long line, unsigned long column, const char *fmt, va_list ap)
{
    err->line = line;
    err->column = column;
    (void)vsnprintf(err->message, sizeof err->message, fmt, ap);
    return CBF_ERR_SYNTAX;
}

/* A refusal naming a line (and a column when not 0). */
static int cbf__cut_say(cbf_cut_error *err, unsigned long line, unsigned long column, const char *fmt, ...)
    CBF__PRINTF(4, 5);
static int cbf__cut_say(cbf_cut_error *err, unsigned long line, unsigned long column, const char *fmt, ...)
{
    va_list ap;
    int rc;
    va_start(ap, fmt);
    rc = cbf__cut_vsay(err, line, column, fmt, ap);
    va_end(ap);
    return rc;
}

/* A refusal of the current line, after its keyword: "KEYWORD: message". */
static int cbf__cut_fail(cbf__cutp *c, const char *fmt, ...) CBF__PRINTF(2, 3);
static int cbf__cut_fail(cbf__cutp *c, const char *fmt, ...)
{
    char text[sizeof c->err->message], kw[64];
    va_list ap;
    va_start(ap, fmt);
    (void)vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    (void)snprintf(kw, sizeof kw, "%.*s", (int)(c->kwlen < CBF__CUT_SHOW ? c->kwlen : CBF__CUT_SHOW), c->t + c->kw);
    return cbf__cut_say(c->err, c->line, 0, "%s%s: %s", kw, c->kwlen > CBF__CUT_SHOW ? "..." : "", text);
}

/* The first character a CUT line cannot hold (anything but printable ASCII, and a CR that does not end
 * the line), with its line and column; CBF_OK when there is none. */
static int cbf__cut_chars(const char *t, size_t n, cbf_cut_error *err)
{
    size_t i, ls = 0;
    unsigned long line = 1;
    for (i = 0; i < n; i++) {
        unsigned ch = (unsigned char)t[i];
        unsigned long cp;
        size_t more, k;
        if (ch == '\n') {
            line++;
            ls = i + 1u;
            continue;
        }
        if ((ch >= 0x20u && ch < 0x7Fu) || (ch == '\r' && i + 1u < n && t[i + 1u] == '\n'))
            continue;
        /* what it is: a character of UTF-8, or a byte that is none */
        more = ch >= 0xF0u && ch < 0xF5u ? 3u : ch >= 0xE0u && ch < 0xF0u ? 2u : ch >= 0xC2u && ch < 0xE0u ? 1u : 0u;
        cp = more == 3u ? (ch & 7u) : more == 2u ? (ch & 15u) : more == 1u ? (ch & 31u) : ch;
        for (k = 1; k <= more; k++) {
            unsigned nx = i + k < n ? (unsigned char)t[i + k] : 0u;
            if ((nx & 0xC0u) != 0x80u) {
                more = 0;
                break;
            }
            cp = (cp << 6) | (nx & 0x3Fu);
        }
        if (ch >= 0x80u && more == 0u)
            return cbf__cut_say(err, line, (unsigned long)(i - ls + 1u), "byte 0x%02X is not allowed (not UTF-8): CUT "
                                "text is printable ASCII, and only LF or CR LF ends a line", ch);
        return cbf__cut_say(err, line, (unsigned long)(i - ls + 1u), "character U+%04lX%s is not allowed: CUT text is "
                            "printable ASCII, and only LF or CR LF ends a line", cp,
                            ch == '\r' ? " (a CR not followed by LF)" : "");
    }
    return CBF_OK;
}

/* The next line of t[0..n) from *at: 1 and c's line, stripped of spaces, with its keyword; 0 at the end. */
static int cbf__cut_line(cbf__cutp *c, size_t n, size_t *at)
{
    const char *nl;
    size_t s = *at, e;
    if (s >= n)
        return 0;
    nl = (const char *)memchr(c->t + s, '\n', n - s);
    e = nl ? (size_t)(nl - c->t) : n;
    *at = nl ? e + 1u : n;
    if (e > s && c->t[e - 1u] == '\r')
        e--;
    c->line++;
    while (s < e && c->t[s] == ' ')
        s++;
    while (e > s && c->t[e - 1u] == ' ')
        e--;
    c->ls = s;
    c->le = e;
    c->kw = s;
    while (s < e && c->t[s] != ' ')
        s++;
    c->kwlen = s - c->kw;
    c->pos = s < e ? s + 1u : e;
    return 1;
}

/* Whether the keyword is word as written (exact), or word read in the spec's keyword case (fold). */
static int cbf__cut_kw(const cbf__cutp *c, const char *word, int fold)
{
    size_t i, n = strlen(word);
    if (n != c->kwlen)
        return 0;
    for (i = 0; i < n; i++) {
        char ch = c->t[c->kw + i];
        if ((fold && CBF__CUT_LOWER ? cbf__cut_lower(ch) : ch) != word[i])
            return 0;
    }
    return 1;
}

static void cbf__cut_skip(cbf__cutp *c)
{
    while (c->pos < c->le && c->t[c->pos] == ' ')
        c->pos++;
}

/* The next word (to the next space): its start and length; CBF_ERR_SYNTAX when there is none. */
static int cbf__cut_word(cbf__cutp *c, const char *name, size_t *start, size_t *len)
{
    cbf__cut_skip(c);
    *start = c->pos;
    while (c->pos < c->le && c->t[c->pos] != ' ')
        c->pos++;
    *len = c->pos - *start;
    return *len ? CBF_OK : cbf__cut_fail(c, "missing %s", name);
}

static int cbf__cut_expect(cbf__cutp *c, const char *token, const char *name)
{
    size_t n = strlen(token);
    cbf__cut_skip(c);
    if (c->le - c->pos < n || memcmp(c->t + c->pos, token, n) != 0)
        return cbf__cut_fail(c, "expected '%s' in %s", token, name);
    c->pos += n;
    return CBF_OK;
}

/* The rest of the line, stripped of spaces. */
static void cbf__cut_rest(cbf__cutp *c, size_t *start, size_t *len)
{
    cbf__cut_skip(c);
    *start = c->pos;
    *len = c->le - c->pos; /* the line is stripped: no space ends it */
    c->pos = c->le;
}

/* Nothing but spaces may follow the arguments. */
static int cbf__cut_end(cbf__cutp *c)
{
    char show[96];
    cbf__cut_skip(c);
    if (c->pos < c->le)
        return cbf__cut_fail(c, "unexpected text %s", cbf__cut_show(show, sizeof show, c->t + c->pos, c->le - c->pos));
    return CBF_OK;
}

static int cbf__cut_same(const char *a, const char *b, size_t bn)
{
    size_t i;
    for (i = 0; i < bn; i++)
        if (!a[i] || cbf__cut_lower(a[i]) != cbf__cut_lower(b[i]))
            return 0;
    return a[bn] == 0;
}

/* The refusal of a number's place that holds no number: what is there instead, or that nothing is. */
static int cbf__cut_not_number(cbf__cutp *c, const char *name)
{
    char show[96];
    size_t e = c->pos, ws;
    int label = !cbf__cut_same(name, c->t + c->kw, c->kwlen); /* not "speed: speed: ..." */
    while (e < c->le && c->t[e] != ' ')
        e++;
    ws = e - c->pos;
    if (ws)
        return cbf__cut_fail(c, "%s%s%s is not a number", label ? name : "", label ? ": " : "",
                             cbf__cut_show(show, sizeof show, c->t + c->pos, ws));
    return cbf__cut_fail(c, "%s%sa number is missing", label ? name : "", label ? ": " : "");
}

/* The number's decimal text for strtof/strtod into buf: its sign, "0", its integer digits d0..d1 (leading
 * zeros dropped), ".", its first CBF__CUT_FRAC_DIGITS fraction digits f0..f1, and a 1 standing for the digits
 * past those when one of them is not zero: at most CBF__CUT_INT_DIGITS + CBF__CUT_FRAC_DIGITS + 5 chars. */
static void cbf__cut_decimal(const cbf__cutp *c, int neg, size_t d0, size_t d1, size_t f0, size_t f1, char *buf)
{
    size_t k, at = 0;
    if (neg)
        buf[at++] = '-';
    buf[at++] = '0';
    for (k = d0; k < d1; k++)
        buf[at++] = c->t[k];
    buf[at++] = '.';
    for (k = f0; k < f1 && k - f0 < CBF__CUT_FRAC_DIGITS; k++)
        buf[at++] = c->t[k];
    for (; k < f1; k++) /* a digit past those kept: only whether one is not zero can matter */
        if (c->t[k] != '0') {
            buf[at++] = '1';
            break;
        }
    buf[at] = 0;
}

/* The decimal text buf rounded once to elem bytes (binary32 or binary64) into dst; the number's text
 * c->t[s..p) named in the refusal when it rounds beyond the range. */
static int cbf__cut_round(cbf__cutp *c, const char *name, unsigned elem, const char *buf, size_t s, size_t p,
                          uint8_t *dst)
{
    char show[96];
    if (elem == 4u) {
        uint32_t bits = cbf__f4_bits(strtof(buf, NULL));
        if ((bits & 0x7FFFFFFFu) == 0x7F800000u)
            return cbf__cut_fail(c, "%s: %s is outside the binary32 range", name, cbf__cut_show(show, sizeof show, c->t + s, p - s));
        cbf__put_u(dst, bits, 4u);
    } else {
        double d = strtod(buf, NULL);
        uint64_t bits;
        memcpy(&bits, &d, sizeof bits);
        if ((bits & 0x7FFFFFFFFFFFFFFFu) == 0x7FF0000000000000u)
            return cbf__cut_fail(c, "%s: %s is outside the binary64 range", name, cbf__cut_show(show, sizeof show, c->t + s, p - s));
        cbf__put_u64(dst, bits);
    }
    return CBF_OK;
}

/* The end of a run of digits from p (p itself when there is none). */
static size_t cbf__cut_digits(const cbf__cutp *c, size_t p)
{
    while (p < c->le && cbf__cut_digit(c->t[p]))
        p++;
    return p;
}

/* A number of the spec's float_pattern (an optional minus, digits, an optional point and digits), rounded
 * once to the binary32 nearest its decimal value (ties to even; cbf.floats.read_decimal): its elem bytes
 * written to dst. Beyond the binary32 range it is refused. */
static int cbf__cut_number(cbf__cutp *c, const char *name, unsigned elem, uint8_t *dst)
{
    char show[96], buf[CBF__CUT_INT_DIGITS + CBF__CUT_FRAC_DIGITS + 8u];
    size_t s, p, d0, d1, f0, f1;
    cbf__cut_skip(c);
    s = p = c->pos;
    if (p < c->le && c->t[p] == '-')
        p++;
    d0 = p;
    d1 = p = cbf__cut_digits(c, p);
    if (d1 == d0)
        return cbf__cut_not_number(c, name);
    f0 = f1 = p;
    if (p < c->le && c->t[p] == '.') {
        f0 = ++p;
        f1 = p = cbf__cut_digits(c, p);
    }
    c->pos = p;
    while (d0 < d1 && c->t[d0] == '0')
        d0++;
    if (d1 - d0 > CBF__CUT_INT_DIGITS)
        return cbf__cut_fail(c, "%s: %s is outside the binary32 range", name, cbf__cut_show(show, sizeof show, c->t + s, p - s));
    cbf__cut_decimal(c, c->t[s] == '-', d0, d1, f0, f1, buf);
    return cbf__cut_round(c, name, elem, buf, s, p, dst);
}

/* An integer of elem bytes (sint: an optional minus), ASCII digits within the field's range. */
static int cbf__cut_integer(cbf__cutp *c, const char *name, const cbf_field_info *f, uint8_t *dst)
{
    char show[96];
    size_t s, n, k, d;
    uint64_t v = 0, max;
    int neg, ok = 1, sint = f->kind == CBF__K_SINT;
    unsigned bits = 8u * f->elem;
    int rc = cbf__cut_word(c, name, &s, &n);
    if (rc)
        return rc;
    neg = sint && c->t[s] == '-';
    d = s + (neg ? 1u : 0u);
    max = bits >= 64u ? ~(uint64_t)0 : ((uint64_t)1 << bits) - 1u;
    if (sint)
        max = neg ? ((uint64_t)1 << (bits - 1u)) : ((uint64_t)1 << (bits - 1u)) - 1u;
    if (d == s + n)
        ok = 0;
    for (k = d; k < s + n && ok; k++) {
        unsigned dig;
        if (!cbf__cut_digit(c->t[k])) {
            ok = 0;
            break;
        }
        dig = (unsigned)(c->t[k] - '0');
        if (v > (max - dig) / 10u)
            ok = 0;
        else
            v = v * 10u + dig;
    }
    if (!ok)
        return cbf__cut_fail(c, "%s: %s is not %s %u-bit integer", name, cbf__cut_show(show, sizeof show, c->t + s, n),
                             sint ? "a signed" : "an unsigned", bits);
    if (neg)
        v = (~v) + 1u; /* two's complement */
    if (f->elem == 8u)
        cbf__put_u64(dst, v);
    else
        cbf__put_u(dst, (uint32_t)(v & 0xFFFFFFFFu), f->elem);
    return CBF_OK;
}

/* Hex digits, two a byte (cbf's bytes.fromhex of one word): *len bytes, written to dst when they fit cap. */
static int cbf__cut_hex(cbf__cutp *c, const char *name, uint8_t *dst, size_t cap, size_t *len)
{
    char show[96];
    size_t s, n, k;
    int rc = cbf__cut_word(c, name, &s, &n);
    if (rc)
        return rc;
    for (k = 0; k < n; k++) {
        char ch = cbf__cut_lower(c->t[s + k]);
        if (!cbf__cut_digit(ch) && !(ch >= 'a' && ch <= 'f'))
            break;
    }
    if (k < n || n % 2u)
        return cbf__cut_fail(c, "%s: %s is not hex", name, cbf__cut_show(show, sizeof show, c->t + s, n));
    *len = n / 2u;
    for (k = 0; k < *len && *len <= cap; k++) {
        unsigned v = 0, j;
        for (j = 0; j < 2u; j++) {
            char ch = cbf__cut_lower(c->t[s + 2u * k + j]);
            v = v * 16u + (unsigned)(cbf__cut_digit(ch) ? ch - '0' : ch - 'a' + 10);
        }
        dst[k] = (uint8_t)v;
    }
    return CBF_OK;
}

/* A string of at most size bytes (a text field: the rest of the line), padded. */
static int cbf__cut_string(cbf__cutp *c, const char *name, int text, size_t size, uint8_t *dst)
{
    size_t s, n;
    if (text) {
        cbf__cut_rest(c, &s, &n);
    } else {
        int rc = cbf__cut_word(c, name, &s, &n);
        if (rc)
            return rc;
    }
    if (n > size)
        return cbf__cut_fail(c, "%s: %lu characters, the field holds %lu", name, (unsigned long)n, (unsigned long)size);
    memcpy(dst, c->t + s, n);
    memset(dst + n, CBF__PAD, size - n);
    return CBF_OK;
}

/* One argument (or one item of a repeated group: count elements) into base + f->offset. */
static int cbf__cut_value(cbf__cutp *c, const cbf_field_info *f, unsigned count, const char *name, uint8_t *base)
{
    uint8_t *dst = base + f->offset;
    unsigned k;
    int rc = CBF_OK;
    switch ((enum cbf_field_kind)f->kind) {
    case CBF_KIND_FLOAT:
        if (count == 1u)
            return cbf__cut_number(c, name, f->elem, dst);
        if ((rc = cbf__cut_expect(c, cbf__cut_open, name)) != CBF_OK)
            return rc;
        for (k = 0; k < count && rc == CBF_OK; k++) {
            if (k && (rc = cbf__cut_expect(c, cbf__cut_sep, name)) != CBF_OK)
                return rc;
            rc = cbf__cut_number(c, name, f->elem, dst + (size_t)k * f->elem);
        }
        return rc ? rc : cbf__cut_expect(c, cbf__cut_close, name);
    case CBF_KIND_UINT:
    case CBF_KIND_SINT:
        return cbf__cut_integer(c, name, f, dst);
    case CBF_KIND_BYTES:
        memset(dst, 0, (size_t)f->elem * count);
        return CBF_OK;
    case CBF_KIND_STRING:
        return cbf__cut_string(c, name, (f->flags & CBF__F_TEXT) != 0u, (size_t)f->elem * count, dst);
    }
    return CBF_OK;
}

/* The layout a CUT reader picks for a command in a version under a profile: the profile's own first,
 * else the first the profile accepts; -1 when none. */
static int cbf__cut_layout(int ci, int version, int profile)
{
    int k, first = -1;
    for (k = 0; k < cbf__commands[ci].nlayouts; k++) {
        int lay = cbf__commands[ci].first_layout + k;
        const cbf__layout *L = &cbf__layouts[lay];
        if (!(L->versions & CBF__VBIT(version)))
            continue;
        if (L->profiles & CBF__PBIT(profile))
            return lay;
        if (L->profiles == 0u && first < 0)
            first = lay;
    }
    return first;
}

/* A keyword line's arguments by its layout into args: *nb bytes. */
static int cbf__cut_args(cbf__cutp *c, int lay, uint8_t *args, size_t *nb)
{
    const cbf_field_info *fields;
    size_t nf = cbf_layout_fields(lay, &fields), i, lo = 0, hi = 0, item = 0, n = 0;
    long g = cbf_layout_group(lay, &lo, &hi, &item);
    int rc;
    char label[160];
    memset(args, 0, CBF_LIMIT_MAX_ARG_SIZE);
    for (i = 0; i < nf; i++) {
        if ((long)i == g)
            continue;
        if ((size_t)fields[i].offset + (size_t)fields[i].elem * fields[i].count > CBF_LIMIT_MAX_ARG_SIZE)
            return cbf__cut_fail(c, "%s: beyond the largest record", fields[i].name);
        if ((rc = cbf__cut_value(c, &fields[i], fields[i].count, fields[i].name, args)) != CBF_OK)
            return rc;
    }
    *nb = (size_t)cbf_layout_size(lay);
    if (g >= 0) { /* a repeated group: its items to the end of the line */
        cbf_field_info one = fields[g];
        for (;;) {
            cbf__cut_skip(c);
            if (c->pos >= c->le)
                break;
            (void)snprintf(label, sizeof label, "%s[%lu]", fields[g].name, (unsigned long)n);
            if (n < hi && one.offset + item <= CBF_LIMIT_MAX_ARG_SIZE) {
                rc = cbf__cut_value(c, &one, one.count, label, args);
                one.offset = (unsigned short)(one.offset + item);
            } else { /* past the most the group holds: read, not kept */
                uint8_t scratch[CBF_LIMIT_MAX_ARG_SIZE + 8u];
                cbf_field_info at0 = one;
                at0.offset = 0;
                rc = item <= CBF_LIMIT_MAX_ARG_SIZE ? cbf__cut_value(c, &at0, at0.count, label, scratch) : CBF_OK;
            }
            if (rc)
                return rc;
            n++;
        }
        if (n < lo || n > hi)
            return cbf__cut_fail(c, "%s: %lu items; the group holds %lu to %lu", fields[g].name, (unsigned long)n,
                                 (unsigned long)lo, (unsigned long)hi);
        *nb += item * n;
    }
    return cbf__cut_end(c);
}

/* The command a keyword names (its name, or a former name, in the spec's keyword case): its code, or -1. */
static int cbf__cut_command(const cbf__cutp *c)
{
    int i;
    for (i = 0; i < CBF__NCOMMANDS; i++)
        if (CBF__CUT_LOWER ? cbf__cut_same(cbf__commands[i].name, c->t + c->kw, c->kwlen)
                           : (strlen(cbf__commands[i].name) == c->kwlen
                              && memcmp(cbf__commands[i].name, c->t + c->kw, c->kwlen) == 0))
            return cbf__commands[i].code;
    for (i = 0; cbf__cut_former[i].name; i++)
        if (CBF__CUT_LOWER ? cbf__cut_same(cbf__cut_former[i].name, c->t + c->kw, c->kwlen)
                           : (strlen(cbf__cut_former[i].name) == c->kwlen
                              && memcmp(cbf__cut_former[i].name, c->t + c->kw, c->kwlen) == 0))
            return cbf__cut_former[i].code;
    return -1;
}

static int cbf__cut_derived_role(int role)
{
    size_t i;
    for (i = 0; cbf__cut_derived[i] != CBF_ROLE_NONE; i++)
        if (cbf__cut_derived[i] == role)
            return 1;
    return 0;
}

static const char *cbf__cut_check_of(int kind)
{
    size_t i;
    for (i = 0; i < (size_t)CBF__NCHECKS; i++)
        if (cbf__checks[i].kind == kind)
            return cbf__checks[i].id;
    return "";
}

/* The first byte of a string field that the format does not carry (printable ASCII, padded), or -1. */
static long cbf__cut_bad_string(const cbf_field_info *f, const uint8_t *base)
{
    size_t k, size = (size_t)f->elem * f->count;
    if (f->kind != CBF__K_STRING)
        return -1;
    for (k = 0; k < size; k++) {
        unsigned b = base[f->offset + k];
        if (!((b >= 0x20u && b < 0x7Fu) || b == CBF__PAD))
            return (long)k;
    }
    return -1;
}

/* The reading's state beyond the line: the header as the text sets it, which line set each field. */
typedef struct cbf__cutdoc {
    int version, layout, profile;
    unsigned major, minor;                           /* the version as the text names it */
    unsigned long version_line;                      /* its version line (0: none) */
    uint8_t header[CBF_HEADER_SIZE];
    unsigned long set_on[CBF__CUT_MAX_HEADER_FIELDS]; /* header field -> the line that set it (0: none) */
    unsigned long sum_line;                          /* the check_sum line (0: none) */
    uint64_t sum;
    int sum_big;                                     /* its number beyond 64 bits */
} cbf__cutdoc;

static int cbf__cut_once(cbf__cutp *c, cbf__cutdoc *d, size_t field, const char *name)
{
    unsigned long *slot = field < CBF__CUT_MAX_HEADER_FIELDS ? &d->set_on[field] : &d->sum_line;
    if (*slot)
        return cbf__cut_fail(c, "%s is already set on line %lu; a header line is given once", name, *slot);
    *slot = c->line;
    return CBF_OK;
}

/* header / header_ext: the implant (configuration) descriptor, the rest of the line. */
static int cbf__cut_descriptor(cbf__cutp *c, cbf__cutdoc *d, int role)
{
    const cbf_field_info *hf;
    size_t nf = cbf_header_fields(d->layout, &hf), i;
    for (i = 0; i < nf && hf[i].role != role; i++) {}
    if (i == nf)
        return cbf__cut_fail(c, "version %s has no %s", cbf_version_name(d->version),
                             role == CBF_ROLE_IMPLANT_DESCRIPTOR ? "implant descriptor" : "configuration descriptor");
    if (cbf__cut_once(c, d, i, hf[i].name))
        return CBF_ERR_SYNTAX;
    {
        size_t s, n, size = (size_t)hf[i].elem * hf[i].count;
        cbf__cut_rest(c, &s, &n);
        if (n > size)
            return cbf__cut_fail(c, "%lu characters, the %s holds %lu", (unsigned long)n, hf[i].name, (unsigned long)size);
        memcpy(d->header + hf[i].offset, c->t + s, n);
        memset(d->header + hf[i].offset + n, CBF__PAD, size - n);
    }
    return CBF_OK;
}

/* check_sum N: the file checksum the text's CBF must have (compared once it is written). */
static int cbf__cut_sum(cbf__cutp *c, cbf__cutdoc *d)
{
    char show[96];
    size_t s, n, k;
    if (cbf__cut_once(c, d, CBF__CUT_MAX_HEADER_FIELDS, cbf__cut_checksum))
        return CBF_ERR_SYNTAX;
    if (cbf__cut_word(c, "checksum", &s, &n))
        return CBF_ERR_SYNTAX;
    d->sum = 0;
    d->sum_big = 0;
    for (k = 0; k < n; k++) {
        unsigned dig;
        if (!cbf__cut_digit(c->t[s + k]))
            return cbf__cut_fail(c, "%s is not a number", cbf__cut_show(show, sizeof show, c->t + s, n));
        dig = (unsigned)(c->t[s + k] - '0');
        if (d->sum > (~(uint64_t)0 - dig) / 10u)
            d->sum_big = 1;
        else
            d->sum = d->sum * 10u + dig;
    }
    return cbf__cut_end(c);
}

/* cbf_field NAME HEX: a header field the writer does not derive, byte for byte. */
static int cbf__cut_set_field(cbf__cutp *c, cbf__cutdoc *d)
{
    char show[96];
    const cbf_field_info *hf;
    size_t nf = cbf_header_fields(d->layout, &hf), i, s, n, len = 0, size;
    uint8_t raw[CBF_HEADER_SIZE];
    if (cbf__cut_word(c, "field name", &s, &n))
        return CBF_ERR_SYNTAX;
    for (i = 0; i < nf; i++)
        if (strlen(hf[i].name) == n && memcmp(hf[i].name, c->t + s, n) == 0 && !cbf__cut_derived_role(hf[i].role))
            break;
    if (i == nf)
        return cbf__cut_fail(c, "%s is not a writable header field of version %s", cbf__cut_show(show, sizeof show, c->t + s, n),
                             cbf_version_name(d->version));
    if (cbf__cut_once(c, d, i, hf[i].name) || cbf__cut_hex(c, hf[i].name, raw, sizeof raw, &len))
        return CBF_ERR_SYNTAX;
    size = (size_t)hf[i].elem * hf[i].count;
    if (len != size)
        return cbf__cut_fail(c, "%s: %lu bytes, the field holds %lu", hf[i].name, (unsigned long)len, (unsigned long)size);
    if (cbf__cut_end(c))
        return CBF_ERR_SYNTAX;
    memcpy(d->header + hf[i].offset, raw, size);
    return CBF_OK;
}

/* cbf_record CODE COPY RESERVED [ARGS]: a record as hex (CBF -> CUT -> CBF is byte-exact). */
static int cbf__cut_raw(cbf__cutp *c, int *code, unsigned *reserved, uint8_t *args, size_t *nb)
{
    uint8_t b[3];
    size_t len[3] = { 0, 0, 0 };
    if (cbf__cut_hex(c, "code", &b[0], 1, &len[0]) || cbf__cut_hex(c, "code copy", &b[1], 1, &len[1])
        || cbf__cut_hex(c, "reserved byte", &b[2], 1, &len[2]))
        return CBF_ERR_SYNTAX;
    if (len[0] != 1u || len[1] != 1u || len[2] != 1u)
        return cbf__cut_fail(c, "code, code copy and reserved byte are one hex byte each");
    *code = b[0];
    *reserved = b[2];
    *nb = 0;
    cbf__cut_skip(c);
    if (c->pos < c->le) {
        if (cbf__cut_hex(c, "arguments", args, CBF_LIMIT_MAX_ARG_SIZE, nb))
            return CBF_ERR_SYNTAX;
        if (*nb > CBF_LIMIT_MAX_ARG_SIZE)
            return cbf__cut_fail(c, "%lu argument bytes, at most %lu", (unsigned long)*nb,
                                 (unsigned long)CBF_LIMIT_MAX_ARG_SIZE);
    }
    return cbf__cut_end(c);
}

/* Why record i (code, its argument bytes) cannot be written in the version under the profile (cbf's
 * _written_args: the command, its availability, its size, its strings, the profile's layout), or NULL. */
static const char *cbf__cut_unwritable(const cbf__cutdoc *d, unsigned long i, int code, const uint8_t *args, size_t nb,
                                       char *why, size_t cap)
{
    const char *name = cbf_command_name(code), *v = cbf_version_name(d->version);
    const cbf_field_info *fields;
    size_t nf, k;
    int lay;
    if (!name) {
        (void)snprintf(why, cap, "record %lu: unknown command code 0x%02X", i, (unsigned)code);
        return why;
    }
    if (!cbf_command_available(code, d->version)) {
        (void)snprintf(why, cap, "record %lu: %s is not available in version %s", i, name, v);
        return why;
    }
    lay = cbf_args_layout(code, d->version, nb);
    if (lay == CBF_LAYOUT__NONE) {
        (void)snprintf(why, cap, "record %lu: %s has no layout of %lu bytes in version %s", i, name, (unsigned long)nb, v);
        return why;
    }
    nf = cbf_layout_fields(lay, &fields);
    for (k = 0; k < nf; k++) {
        long bad = (long)k == cbf_layout_group(lay, NULL, NULL, NULL) ? -1 : cbf__cut_bad_string(&fields[k], args);
        if (bad >= 0) {
            (void)snprintf(why, cap, "record %lu: %s: the result would fail check %s: %s holds non-ASCII byte 0x%02X at "
                           "position %ld (strings are printable ASCII, padded)", i, name,
                           cbf__cut_check_of(CBF__KIND_STRING_ASCII), fields[k].name,
                           (unsigned)args[fields[k].offset + (size_t)bad], bad);
            return why;
        }
    }
    if (cbf__profile_size(d->version, code, args, nb, d->profile) < 0) {
        (void)snprintf(why, cap, "record %lu: %s of %lu bytes: the %s profile writes a layout of its own, and these "
                       "bytes do not cut to it; %s's reader cannot read it", i, name, (unsigned long)nb,
                       cbf__profiles[d->profile].id, cbf__profiles[d->profile].id);
        return why;
    }
    return NULL;
}

/* What cbf_encode_end fills (the writer's own steps), for records cbf__cut_unwritable passed: each record cut
 * to the profile's layout with its checksum fields, then the header's count, magic numbers and checksums. A
 * record in a layout of another profile is written as the text gives it (cbf's pack_file writes it so). */
static int cbf__cut_fill(cbf_writer *w, int lay, int profile)
{
    const cbf_field_info *f_code = cbf__record_field_by_role(CBF_ROLE_CODE);
    const cbf_field_info *f_nb = cbf__record_field_by_role(CBF_ROLE_ARG_SIZE);
    const cbf_field_info *f_ck = cbf__record_field_by_tag(CBF__CK_ARGS);
    size_t pos = CBF_HEADER_SIZE;
    int rc;
    while (f_code && f_nb && pos < w->records_end) {
        uint8_t *p = w->buf + pos;
        int code = (int)cbf__get_u(p + f_code->offset, f_code->elem);
        long got = cbf__fill_cut(w, pos, profile, f_code, f_nb, f_ck);
        if (got < 0)
            return CBF_ERR_NOT_WRITABLE;
        if (cbf__fill_argcks(cbf_args_layout(code, w->version, (size_t)got), p, (size_t)got) && f_ck)
            cbf__put_u(p + f_ck->offset, cbf_args_checksum(p + CBF_RECORD_HEAD_SIZE, (size_t)got), f_ck->elem);
        pos += CBF_RECORD_HEAD_SIZE + (size_t)got;
    }
    if ((rc = cbf__fill_header(w, lay)) != CBF_OK)
        return rc;
    cbf__fill_header_sums(w, lay, profile);
    return CBF_OK;
}

typedef struct cbf__cut_seen { const char *check; int hit; } cbf__cut_seen;

static void cbf__cut_seen_fn(void *user, const cbf_finding *f)
{
    cbf__cut_seen *s = (cbf__cut_seen *)user;
    if (strcmp(f->check, s->check) == 0)
        s->hit = 1;
}

/* check_sum: the number must be the file checksum of the CBF written (or one a file coverage the profile
 * accepts gives: its file checksum check then says nothing). */
static int cbf__cut_sum_agrees(const cbf__cutdoc *d, uint8_t *out, size_t len, cbf_cut_error *err)
{
    const cbf_field_info *f = cbf__header_field_by_tag(d->layout, CBF__CK_FILE);
    uint32_t computed;
    if (!f)
        return cbf__cut_say(err, d->sum_line, 0, "%s: this spec's header has no file checksum", cbf__cut_checksum);
    computed = cbf__get_u(out + f->offset, f->elem);
    if (!d->sum_big && d->sum == computed)
        return CBF_OK;
    if (!d->sum_big && (f->elem >= 8u || d->sum < ((uint64_t)1 << (8u * f->elem)))) {
        cbf__cut_seen seen;
        cbf_options opt;
        memset(&opt, 0, sizeof opt);
        opt.profile = d->profile;
        seen.check = cbf__cut_check_of(CBF__KIND_FILE_CHECKSUM);
        seen.hit = 0;
        cbf__put_u(out + f->offset, (uint32_t)d->sum, f->elem);
        (void)cbf_validate(out, len, &opt, cbf__cut_seen_fn, &seen);
        cbf__put_u(out + f->offset, computed, f->elem);
        if (!seen.hit)
            return CBF_OK;
    }
    return cbf__cut_say(err, d->sum_line, 0, "%s: %s%llu is not the file checksum of this text, %lu", cbf__cut_checksum,
                        d->sum_big ? "a number beyond " : "", d->sum_big ? 18446744073709551615ull : (unsigned long long)d->sum,
                        (unsigned long)computed);
}

/* The version the text's one version line names, *line its line (0: none); CBF_OK or a refusal. A line
 * naming another version than the one asked for (requested: an enum cbf_version, or -1) is refused, as
 * cbf encode --version refuses it (cut.py, _version_line). */
static int cbf__cut_version_line(cbf__cutp *c, size_t n, int requested, unsigned *major, unsigned *minor,
                                 unsigned long *line)
{
    size_t at = 0;
    char show[96];
    *line = 0;
    c->line = 0;
    while (cbf__cut_line(c, n, &at)) {
        size_t s, len, k, dot = 0, parts[2] = { 0, 0 };
        unsigned v[2] = { 0, 0 };
        int ok = 1;
        if (!cbf__cut_kw(c, cbf__cut_version, 0))
            continue;
        if (*line)
            return cbf__cut_fail(c, "a second version line (the first is line %lu); a header line is given once", *line);
        cbf__cut_rest(c, &s, &len);
        for (k = 0; k < len && ok; k++) {
            char ch = c->t[s + k];
            if (ch == '.' && dot == 0)
                dot = 1;
            else if (cbf__cut_digit(ch) && parts[dot] < 3u) {
                v[dot] = v[dot] * 10u + (unsigned)(ch - '0');
                parts[dot]++;
            } else
                ok = 0;
        }
        if (!ok || !dot || !parts[0] || !parts[1] || v[0] > 255u || v[1] > 255u)
            return cbf__cut_fail(c, "%s is not major.minor (two numbers 0 to 255)", cbf__cut_show(show, sizeof show, c->t + s, len));
        if (requested >= 0 && (v[0] != *major || v[1] != *minor))
            return cbf__cut_say(c->err, c->line, 0, "%s %.*s contradicts the requested version %s", cbf__cut_version,
                                (int)len, c->t + s, cbf_version_name(requested));
        *major = v[0];
        *minor = v[1];
        *line = c->line;
    }
    return CBF_OK;
}

long cbf_cut_encode(const char *text, size_t n, int profile, uint8_t *out, size_t cap, cbf_cut_error *err)
{
    return cbf_cut_encode_as(text, n, CBF_V__UNKNOWN, profile, out, cap, err);
}

/* The header the text starts from: the version asked for (or the default) unless a version line names
 * one, its header layout, the header's fields as cbf_header_init fills them, the version fields as the text
 * names them; the writer begun on out (*full: out cannot hold a header). */
static int cbf__cut_begin(cbf__cutp *c, cbf__cutdoc *d, size_t n, int version, cbf_writer *w, uint8_t *out, size_t cap,
                          int *full)
{
    cbf_header h;
    const cbf_field_info *hf;
    size_t i = version == CBF_V__UNKNOWN ? (size_t)CBF_DEFAULT_VERSION : (size_t)version; /* without a version line */
    size_t nf;
    int rc;
    d->major = (unsigned)cbf__versions[i].major;
    d->minor = cbf__versions[i].minor < 0 ? 0u : (unsigned)cbf__versions[i].minor;
    if ((rc = cbf__cut_version_line(c, n, version, &d->major, &d->minor, &d->version_line)) != CBF_OK)
        return rc;
    d->version = cbf_version_find(d->major, d->minor);
    if (d->version == CBF_V__UNKNOWN)
        return cbf__cut_say(c->err, d->version_line ? d->version_line : 1u, 0, "version %u.%u is not a version of this spec",
                            d->major, d->minor);
    d->layout = cbf_version_header_layout(d->version);
    (void)cbf_header_init(&h, d->version);
    h.major = d->major;
    h.minor = d->minor;
    if (cbf_header_encode(&h, d->header, sizeof d->header) < 0)
        return CBF_ERR_ARGUMENT;
    nf = cbf_header_fields(d->layout, &hf);
    for (i = 0; i < nf; i++) /* the version as the text names it */
        if (hf[i].role == CBF_ROLE_VERSION_MAJOR || hf[i].role == CBF_ROLE_VERSION_MINOR)
            cbf__put_u(d->header + hf[i].offset, hf[i].role == CBF_ROLE_VERSION_MAJOR ? d->major : d->minor, hf[i].elem);
    (void)cbf_header_decode(d->header, sizeof d->header, &h);
    rc = cbf_encode_begin(w, out, cap, &h);
    if (rc == CBF_ERR_BUFFER)
        *full = 1;
    else if (rc != CBF_OK)
        return rc;
    return CBF_OK;
}

/* A header line (header, header_ext, check_sum, cbf_field) into d: 1 when the line is one (CBF_ERR_SYNTAX
 * when it is refused), 0 when it is not. */
static int cbf__cut_header_line(cbf__cutp *c, cbf__cutdoc *d)
{
    int rc;
    if (cbf__cut_kw(c, cbf__cut_header, 1))
        rc = cbf__cut_descriptor(c, d, CBF_ROLE_IMPLANT_DESCRIPTOR);
    else if (cbf__cut_kw(c, cbf__cut_header_ext, 1))
        rc = cbf__cut_descriptor(c, d, CBF_ROLE_CONFIGURATION_DESCRIPTOR);
    else if (cbf__cut_kw(c, cbf__cut_checksum, 1))
        rc = cbf__cut_sum(c, d);
    else if (cbf__cut_kw(c, cbf__cut_field, 0))
        rc = cbf__cut_set_field(c, d);
    else
        return 0;
    return rc ? CBF_ERR_SYNTAX : 1;
}

/* A record line (cbf_record, or a command's keyword and its arguments): its code, reserved byte and nb
 * argument bytes; CBF_OK or a refusal. */
static int cbf__cut_record_line(cbf__cutp *c, const cbf__cutdoc *d, int *code, unsigned *reserved, uint8_t *args,
                                size_t *nb)
{
    char show[96];
    int lay;
    if (cbf__cut_kw(c, cbf__cut_record, 0))
        return cbf__cut_raw(c, code, reserved, args, nb) ? CBF_ERR_SYNTAX : CBF_OK;
    *code = cbf__cut_command(c);
    if (*code < 0)
        return cbf__cut_say(c->err, c->line, 0, "unknown keyword %s", cbf__cut_show(show, sizeof show, c->t + c->kw, c->kwlen));
    lay = cbf__cut_layout(cbf__cmd_index(*code), d->version, d->profile);
    if (lay < 0)
        return cbf__cut_fail(c, "not available in version %s", cbf_version_name(d->version));
    return cbf__cut_args(c, lay, args, nb) ? CBF_ERR_SYNTAX : CBF_OK;
}

/* The writing: the writer, how many records the text holds, and the first that cannot be written. */
typedef struct cbf__cutw {
    cbf_writer w;
    uint8_t *out;
    int full;                /* out is too small: the text is still read to its end */
    unsigned long records;   /* the records read */
    unsigned long bad_line;  /* the line of the first record that cannot be written (0: none) */
    char *why;               /* why it cannot, why_cap bytes */
    size_t why_cap;
} cbf__cutw;

/* A record read into the writing (written while every record before could be, and out holds it);
 * CBF_OK, or the refusal of one too many records. */
static int cbf__cut_put(const cbf__cutp *c, const cbf__cutdoc *d, cbf__cutw *o, int code, unsigned reserved,
                        const uint8_t *args, size_t nb)
{
    const cbf_field_info *f;
    int rc;
    if (++o->records > (unsigned long)CBF_LIMIT_MAX_COMMANDS)
        return cbf__cut_say(c->err, c->line, 0, "%lu commands, at most %lu", o->records, (unsigned long)CBF_LIMIT_MAX_COMMANDS);
    if (o->bad_line)
        return CBF_OK; /* a record before cannot be written: the text is still read to its end */
    if (cbf__cut_unwritable(d, o->records - 1u, code, args, nb, o->why, o->why_cap)) {
        o->bad_line = c->line;
        return CBF_OK;
    }
    if (o->full)
        return CBF_OK;
    rc = cbf_encode_record(&o->w, code, args, nb);
    if (rc == CBF_ERR_BUFFER) {
        o->full = 1;
    } else if (rc != CBF_OK) {
        (void)snprintf(o->why, o->why_cap, "record %lu: cannot be written (%s)", o->records - 1u, cbf_strerror(rc));
        o->bad_line = c->line;
    } else if (reserved && (f = cbf__record_field_by_role(CBF_ROLE_RESERVED)) != NULL) {
        /* the head's reserved byte as the text gives it (cbf_record) */
        cbf__put_u(o->out + o->w.records_end - nb - CBF_RECORD_HEAD_SIZE + f->offset, reserved, f->elem);
    }
    return CBF_OK;
}

/* A version the text names but that is not written: refused, naming the writable ones; else CBF_OK. */
static int cbf__cut_writable(const cbf__cutdoc *d, cbf_cut_error *err)
{
    char list[128];
    size_t k, used = 0;
    if (cbf_version_writable(d->version))
        return CBF_OK;
    list[0] = 0;
    for (k = 0; k < (size_t)CBF__NVERSIONS; k++)
        if (cbf_version_writable((int)k) && used < sizeof list)
            used += (size_t)snprintf(list + used, sizeof list - used, "%s%s", used ? ", " : "", cbf_version_name((int)k));
    return cbf__cut_say(err, d->version_line ? d->version_line : 1u, 0, "header: version %u.%u is not writable (writable: %s)",
                        d->major, d->minor, list);
}

/* A header string field the format does not carry (the line that set it named): refused; else CBF_OK. */
static int cbf__cut_header_strings(const cbf__cutdoc *d, cbf_cut_error *err)
{
    const cbf_field_info *hf;
    size_t nf = cbf_header_fields(d->layout, &hf), i;
    for (i = 0; i < nf; i++) {
        long bad = cbf__cut_bad_string(&hf[i], d->header);
        if (bad >= 0)
            return cbf__cut_say(err, i < CBF__CUT_MAX_HEADER_FIELDS && d->set_on[i] ? d->set_on[i] : 1u, 0,
                                "header: the result would fail check %s: %s holds non-ASCII byte 0x%02X at position %ld "
                                "(strings are printable ASCII, padded)", cbf__cut_check_of(CBF__KIND_STRING_ASCII),
                                hf[i].name, (unsigned)d->header[hf[i].offset + (size_t)bad], bad);
    }
    return CBF_OK;
}

/* The text read to its end: the file it writes (its length), or why it does not. */
static long cbf__cut_finish(const cbf__cutdoc *d, cbf__cutw *o, cbf_cut_error *err)
{
    int rc;
    long len;
    if ((rc = cbf__cut_writable(d, err)) != CBF_OK || (rc = cbf__cut_header_strings(d, err)) != CBF_OK)
        return rc;
    if (o->bad_line)
        return cbf__cut_say(err, o->bad_line, 0, "%s", o->why);
    if (o->full)
        return CBF_ERR_BUFFER;
    memcpy(o->out, d->header, CBF_HEADER_SIZE); /* the header fields as the text set them; the rest is filled */
    if ((rc = cbf__cut_fill(&o->w, d->layout, d->profile)) != CBF_OK)
        return cbf__cut_say(err, 0, 0, "the text does not encode (%s)", cbf_strerror(rc));
    len = (long)o->w.len;
    if (d->sum_line && (rc = cbf__cut_sum_agrees(d, o->out, (size_t)len, err)) != CBF_OK)
        return rc;
    return len;
}

long cbf_cut_encode_as(const char *text, size_t n, int version, int profile, uint8_t *out, size_t cap,
                       cbf_cut_error *err)
{
    cbf__cutp c;
    cbf__cutdoc d;
    cbf__cutw o;
    size_t at = 0;
    int rc;
    uint8_t args[CBF_LIMIT_MAX_ARG_SIZE + 8u];
    char why[sizeof err->message];
    if (!err || (!text && n) || !out || profile < 0 || profile >= CBF_PROFILE__COUNT || version < CBF_V__UNKNOWN
        || version >= CBF__NVERSIONS)
        return CBF_ERR_ARGUMENT;
    memset(err, 0, sizeof *err);
    memset(&d, 0, sizeof d);
    memset(&c, 0, sizeof c);
    memset(&o, 0, sizeof o);
    c.t = text;
    c.err = err;
    d.profile = profile;
    o.out = out;
    o.why = why;
    o.why_cap = sizeof why;
    if ((rc = cbf__cut_chars(text, n, err)) != CBF_OK || (rc = cbf__cut_begin(&c, &d, n, version, &o.w, out, cap, &o.full)) != CBF_OK)
        return rc;
    why[0] = 0;
    c.line = 0;
    while (cbf__cut_line(&c, n, &at)) {
        int code = -1;
        unsigned reserved = 0;
        size_t nb = 0;
        if (c.kwlen == 0 || cbf__cut_kw(&c, cbf__cut_version, 0))
            continue;
        if ((rc = cbf__cut_header_line(&c, &d)) != 0) {
            if (rc < 0)
                return rc;
            continue;
        }
        if ((rc = cbf__cut_record_line(&c, &d, &code, &reserved, args, &nb)) != CBF_OK
            || (rc = cbf__cut_put(&c, &d, &o, code, reserved, args, nb)) != CBF_OK)
            return rc;
    }
    return cbf__cut_finish(&d, &o, err);
}

unsigned long cbf_cut_record_line(const char *text, size_t n, unsigned long record)
{
    cbf__cutp c;
    size_t at = 0;
    unsigned long seen = 0;
    if (!text)
        return 0;
    memset(&c, 0, sizeof c);
    c.t = text;
    while (cbf__cut_line(&c, n, &at)) {
        if (c.kwlen == 0 || cbf__cut_kw(&c, cbf__cut_header, 1) || cbf__cut_kw(&c, cbf__cut_header_ext, 1)
            || cbf__cut_kw(&c, cbf__cut_checksum, 1) || cbf__cut_kw(&c, cbf__cut_version, 1)
            || cbf__cut_kw(&c, cbf__cut_field, 1))
            continue; /* cbf's _cut_line_of: every word read in the keyword case */
        if (seen++ == record)
            return c.line;
    }
    return 0;
}
/* ==== END runtime/cut.c ==== */
#line 7412 "cbf.h"
#ifdef __cplusplus
}
#endif
#endif /* CBF_IMPLEMENTATION_DONE */
#endif /* CBF_IMPLEMENTATION */
