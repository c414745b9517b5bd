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

