/* cbf_tools.h - the engine of the C binding's tools (cbf-c, the conformance testee): a CBF file, a
 * cutter table and a machine file read, framed, validated and dumped from a buffer in memory, with
 * what cbf-c prints written through a sink. The command line (cbf_tool.c) and the testee are shells
 * over it; a WebAssembly page can call the same entry points on a buffer.
 *
 * GENERATED from spec/cbf.yaml by cbfgen (generator/cbfgen/emit/c). Do not edit.
 *
 * Include it after cbf.h in one translation unit with CBF_TOOLS_IMPLEMENTATION defined (and
 * CBF_IMPLEMENTATION, or cbf.h's implementation linked in).
 */
#ifndef CBF_TOOLS_H
#define CBF_TOOLS_H
#include "cbf.h"
#ifdef __cplusplus
extern "C" {
#endif
/* ==== BEGIN tools/tools_api.h: verbatim from generator/cbfgen/emit/c/tools/tools_api.h, edit it there ==== */
#line 1 "generator/cbfgen/emit/c/tools/tools_api.h"
/* ================================================================ the tools' engine: entry points
 * What cbf-c does, on bytes in memory: a host (the command line of cbf_tool.c, the conformance testee, a
 * WebAssembly page) gives a buffer and a sink and gets back what the tool prints and its exit status.
 * Nothing here opens a file but the *_file functions of the file layer. */

/** Exit statuses, as cbf's (README, "Exit codes"). */
enum cbf_tool_exit {
    CBF_TOOL_EXIT_OK = 0,       /**< no error-severity finding */
    CBF_TOOL_EXIT_FINDINGS = 1, /**< validate found an error-severity finding */
    CBF_TOOL_EXIT_USAGE = 2,    /**< bad usage, or input that is not a CBF file to read */
    CBF_TOOL_OUT_OF_MEMORY = -1 /**< the findings could not be held: one line said so; stop (exit 2) */
};

/** Where the tools' text goes: out gets the normal output, err one line at a time (each ends in a line
 * break); len bytes of text, not NUL-terminated. user is passed back. */
typedef void (*cbf_tool_write_fn)(void *user, const char *text, size_t len);
typedef struct cbf_tool_sink {
    cbf_tool_write_fn out;
    cbf_tool_write_fn err;
    void *user;
} cbf_tool_sink;

/** validate's options: the engine's (profile, part number, cutter table, machine), and the most findings
 * printed for a file (0: all). */
typedef struct cbf_tool_options {
    cbf_options validate;
    size_t max_findings;
} cbf_tool_options;

/** The most bytes a CBF file can hold: the header and every record at its largest. */
#define CBF_TOOL_MAX_FILE_SIZE ((size_t)CBF_HEADER_SIZE + ((size_t)CBF_LIMIT_MAX_COMMANDS + 1u) \
                                * ((size_t)CBF_RECORD_HEAD_SIZE + (size_t)CBF_LIMIT_MAX_ARG_SIZE))

/** How a name (a file name from the command line or a request) is spelled in every line the tools print:
 * the quoting rule (cbf_quote), in a buffer valid until the next call. */
const char *cbf_tool_name(const char *name);

/** 1 when buf[0..n) can be read as a CBF file; else 0 and one line on sink->err naming the file (name) and
 * what is wrong: larger than a CBF file can be, shorter than the header, every magic number wrong. */
int cbf_tool_frame_buffer(const char *name, const uint8_t *buf, size_t n, const cbf_tool_sink *sink);
/** cbf-c validate of one file: its findings in cbf's order and its summary line on sink->out; the status. */
int cbf_tool_validate_buffer(const char *name, const uint8_t *buf, size_t n, const cbf_tool_options *opt,
                             const cbf_tool_sink *sink);
/** cbf-c dump of one file: the header and each record, one line each, on sink->out; the status. */
int cbf_tool_dump_buffer(const char *name, const uint8_t *buf, size_t n, const cbf_tool_sink *sink);
/** cbf-c dump --path of one file: each motion record's drawn path (cbf_motion_path), one line a record,
 * INDEX x,y,z x,y,z ... (a point motion from where the motion before it ended); the status. */
int cbf_tool_path_buffer(const char *name, const uint8_t *buf, size_t n, const cbf_tool_sink *sink);

/** CUT text (the toolkit's text form, spec `cut`): 1 when buf[0..n) is to be read as CUT rather than as a
 * CBF file (no magic number of the header right, or shorter than the header, and its first 256 bytes text:
 * printable ASCII, TAB, CR, LF), else 0. The workbench page asks it of a dropped file. */
int cbf_tool_is_cut(const uint8_t *buf, size_t n);
/** The most CUT text the engine reads: 64 times the largest CBF file (cbf encode's bound). */
#define CBF_TOOL_MAX_CUT_SIZE (64u * CBF_TOOL_MAX_FILE_SIZE)
/** cbf-c encode of one CUT text: the CBF it encodes to (cbf_cut_encode_as: version, CBF_V__UNKNOWN for
 * the text's own or the default, under profile) in *out, a buffer of the heap the caller frees, and its
 * size; or -1, *out NULL, and one line on sink->err naming the file, the line (and column) and what is
 * wrong. */
long cbf_tool_cut_buffer(const char *name, const uint8_t *text, size_t n, int version, int profile, uint8_t **out,
                         const cbf_tool_sink *sink);
/** cbf encode's judgement of cbf[0..len), the CBF that CUT text[0..n) (the file name) encoded to under profile
 * (cbf_tool_cut_buffer): a writer makes files that validate, so the first finding in cbf's order that is an
 * error or of a string_ascii check refuses it: one line on sink->err naming the file, the CUT line of the
 * record concerned (else the finding's offset) and the check, as cbf's; CBF_TOOL_EXIT_USAGE. Else
 * CBF_TOOL_EXIT_OK and nothing printed. */
int cbf_tool_encode_judge(const char *name, const uint8_t *text, size_t n, const uint8_t *cbf, size_t len, int profile,
                          const cbf_tool_sink *sink);
/** cbf encode's warnings once cbf[0..len) is written to output (its name): one line on sink->err for each
 * record of a command or layout the file's version deprecates (the findings of the spec's checks of kind
 * deprecated, under the default profile, in cbf's order), at most ten, then one line counting the rest.
 * Nothing when the spec deprecates nothing. The exit status is not changed by them. */
void cbf_tool_encode_warnings(const char *output, const uint8_t *cbf, size_t len, const cbf_tool_sink *sink);

/** Option files (a cutter table, 6.1.2; a machine file): text[0..n) read by the rules cbf reads them by
 * (name: the file's name, whose extension says CSV, JSON or YAML). 1 and opt's cutters (or machine) set to
 * the engine's copy, valid until the next call; else 0 and cbf_tool_why() says why in one line. */
int cbf_tool_cutters_buffer(const char *name, const char *text, size_t n, cbf_options *opt);
int cbf_tool_machine_buffer(const char *name, const char *text, size_t n, cbf_options *opt);
/** The one line naming the file, the line (or JSON path) and the limit of the last refusal. */
const char *cbf_tool_why(void);

/* ---- the file layer (files.c) ---- */
/** Read a whole file into buf; its size, or -1 and *why (as cbf says it: "no such file", ...). A file of
  * more than cap bytes is -2 and "file too large" (from its size, unread, where it has one). */
long cbf_tool_read_file(const char *path, uint8_t *buf, size_t cap, const char **why);
/** As cbf_tool_read_file, into a buffer of the heap sized to the file, *out (the caller frees it); *why
 * "out of memory" when it cannot be had. */
long cbf_tool_read_file_alloc(const char *path, size_t cap, uint8_t **out, const char **why);
/** As cbf_tool_read_file_alloc, "-" being standard input (read to its end; cbf's rule for an input). */
long cbf_tool_read_input_alloc(const char *path, size_t cap, uint8_t **out, const char **why);
/** cbf_tool_cutters_buffer and cbf_tool_machine_buffer of a file read whole (at most its max_bytes). */
int cbf_tool_cutters_file(const char *path, cbf_options *opt);
int cbf_tool_machine_file(const char *path, cbf_options *opt);
/** Whether an output path can be written, before the work is done (cbf's _check_output): 1; or 0 and one
 * line in why[0..cap) naming the output and what is wrong (its folder does not exist, it is a directory,
 * a block device or a socket). "-" (standard output) can always be tried. */
int cbf_tool_check_output(const char *path, char *why, size_t cap);
/** data[0..n) written to path: to a regular file atomically (a temporary file beside the final target of
 * a symlink, written whole, synced, closed and renamed over the target; on any failure removed: the
 * target is as it was); into a character device or FIFO directly; "-": standard output, where what was
 * written to a regular file is cut off again on failure. 1; or 0 and one line in why[0..cap) naming the
 * output ("standard output" for "-") and the system's reason. Every write is checked: a full disk or
 * /dev/full is a failure, never a short file. */
int cbf_tool_write_file(const char *path, const uint8_t *data, size_t n, char *why, size_t cap);
/* ==== END tools/tools_api.h ==== */
#line 126 "cbf_tools.h"
#ifdef __cplusplus
}
#endif
#endif /* CBF_TOOLS_H */

#ifdef CBF_TOOLS_IMPLEMENTATION
#ifndef CBF_TOOLS_IMPLEMENTATION_DONE
#define CBF_TOOLS_IMPLEMENTATION_DONE
#include <errno.h>
#include <float.h>
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
/* The file layer opens regular files only (stat, open without blocking, fstat) where POSIX is there: a
 * program defines _POSIX_C_SOURCE 200809L before its first #include (cbf-c and the testee do). */
#if !defined(CBF_TOOLS_POSIX) && defined(_POSIX_C_SOURCE) && _POSIX_C_SOURCE >= 200809L
#define CBF_TOOLS_POSIX 1
#endif
#ifdef CBF_TOOLS_POSIX
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>
#endif
#ifdef __cplusplus
extern "C" {
#endif

/* ---- the spec's names and numbers the tools print and check (from the model) ---- */
#define CBF_TOOL_PAD 0u /* the string padding byte */
#define CBF_TOOL_LITTLE_ENDIAN 1
#define CBF_TOOL_DEFAULT_PROFILE CBF_PROFILE_DEFAULT
static const char *const cbf_tool_profile_names[CBF_PROFILE__COUNT] = { "default", "implib" };
/* The spec's checks in their order: findings print in cbf's one order (header first, then by
 * record, check order, offset, message), whatever order the engine reports them in. */
static const char *const cbf_tool_check_order[CBF_CHECK__COUNT] = { "4.2", "4.3", "6.1.1", "part_number_first", "6.1.2", "6.2.1", "6.2.2", "6.3.1", "6.3.2", "6.4.1", "6.4.2", "6.4.3", "6.4.4", "6.4.5", "7.2.3.1", "7.2.2.4", "version_supported", "unknown_command", "trailing_bytes", "reserved_nonzero", "string_tail", "string_ascii", "non_finite", "speed_positive", "accel_positive", "cutter_positive", "normal_nonzero", "checkpoint_range", "checkpoint_falling", "fcparms_order", "orientation_jump", "machine_limits", "shape" };
/* Each check's kind (the registry's name), in the same order: cbf encode refuses a result with an error or a
 * string_ascii finding and warns for each record a deprecated check finds (cli.py, _encode_one and
 * _warn_deprecated). */
static const char *const cbf_tool_check_kinds[CBF_CHECK__COUNT] = { "truncated_header", "truncated_record", "part_number", "descriptor_word", "cutter_table", "file_checksum", "command_count", "header_checksum", "magic", "sequence", "code_copy", "arg_size", "arg_checksum", "continuity", "availability", "availability", "version", "unknown_code", "trailing", "reserved_byte", "string_tail", "string_ascii", "finite", "positive", "positive", "positive", "nonzero_vector", "range", "nondecreasing", "ordered", "orientation", "machine_limits", "shape" };

/* ---- option files (issue 28): the rules of generator/cbfgen/option_files.yaml, completed from the
 * spec (cbfgen/options.py), the same that cbf/option_files.json gives cbf. Every refusal is one line
 * naming the file, the line (or JSON path) and the limit, the line cbf says (tests/option_files/). */
#define OPT_CUTTER_MAX_BYTES 1048576u
#define OPT_CUTTER_MAX_ROWS 4096u
#define OPT_CUTTER_MAX_COLUMNS 32
#define OPT_CUTTER_MAX_DEPTH 3
#define OPT_CUTTER_MAX_NAME 16u
#define OPT_MACHINE_MAX_BYTES 65536u
#define OPT_MACHINE_MAX_DEPTH 4
#define OPT_YAML_MAX_KEYS 64u
#define OPT_NEST_CAP 32 /* the deepest any option file may nest, and then one more */
#if OPT_CUTTER_MAX_DEPTH >= OPT_NEST_CAP || OPT_MACHINE_MAX_DEPTH >= OPT_NEST_CAP
#error "option_files.yaml: max_depth beyond OPT_NEST_CAP"
#endif
#define OPT_CUTTER_NAME_BYTES (4u * OPT_CUTTER_MAX_NAME + 1u) /* UTF-8: up to 4 bytes a character */
static const char opt_cutter_what[] = "cutter table";
static const char opt_machine_what[] = "machine file";
/* A cutter table's columns (cbfgen/options.py: the keys of the spec's cutter role): the name's
 * first, then the numbers, value[k] of cbf_cutter, in the order of opt_cutter_values. */
#define OPT_CUTTER_COLUMNS 3
#if OPT_CUTTER_COLUMNS != CBF_CUTTER_VALUES + 1
#error "a cutter table's columns are the name and cbf_cutter's values"
#endif
static const char *const opt_cutter_columns[OPT_CUTTER_COLUMNS] = { "name", "length", "radius" };
static const char *const opt_columns_list = "name, length, radius";
static const struct { const char *column; int positive; const char *check; } opt_cutter_values[CBF_CUTTER_VALUES] = {
    { "length", 1, "cutter_positive" },
    { "radius", 1, "cutter_positive" },
};
/* A machine file's keys, and a limit's (decision L1). */
static const char *const machine_file_keys[] = { "name", "doc", "decision", "limits", NULL };
static const char *const machine_limit_keys[] = { "unit", "min", "max", "doc", "axes", NULL };

/* ==== BEGIN tools/output.c: verbatim from generator/cbfgen/emit/c/tools/output.c, edit it there ==== */
#line 1 "generator/cbfgen/emit/c/tools/output.c"
/* ---- output: what the tools print goes through a sink (cbf_tool_sink), never to a FILE* of the engine ----
 * Text for the normal output is gathered in a buffer and handed to the sink's out in pieces (at the latest
 * when a call of the engine returns); a line for the error output is handed to err whole, after what the
 * normal output holds so far. */

/* How a name from the command line or a request (a file name) is spelled in every line the tools print:
 * the one place that decides it. The quoting rule (cbf_quote, the same as cbf's cbf.quoting): a plain name
 * as it is, any other between double quotes with escapes, so no name starts a line with "::" or carries a
 * line break. The text is valid until the next call (a name too long for it is cut, and says so). */
#define CBF_TOOL_NAME_BYTES 16384u /* the most a name takes as printed (longer is cut, and says so) */
const char *cbf_tool_name(const char *name)
{
    static char shown[CBF_TOOL_NAME_BYTES];
    if (cbf_quote(shown, sizeof shown, name, strlen(name), CBF_QUOTE_NAME) >= sizeof shown)
        (void)memcpy(shown + sizeof shown - 9u, "...(cut)", 8u);
    return shown;
}

typedef struct tool_out {
    const cbf_tool_sink *sink;
    size_t n;
    char buf[1u << 16];
} tool_out;

static tool_out tout;

static void out_flush(void)
{
    if (tout.n && tout.sink && tout.sink->out)
        tout.sink->out(tout.sink->user, tout.buf, tout.n);
    tout.n = 0;
}

static void out_begin(const cbf_tool_sink *sink)
{
    tout.sink = sink;
    tout.n = 0;
}

static void out_put(const char *s, size_t n)
{
    if (tout.n + n > sizeof tout.buf) {
        out_flush();
        if (n > sizeof tout.buf) {
            if (tout.sink && tout.sink->out)
                tout.sink->out(tout.sink->user, s, n);
            return;
        }
    }
    memcpy(tout.buf + tout.n, s, n);
    tout.n += n;
}

static void out_str(const char *s) { out_put(s, strlen(s)); }

static void out_char(char c)
{
    if (tout.n == sizeof tout.buf)
        out_flush();
    tout.buf[tout.n++] = c;
}

/* fmt formatted (into line when it fits, else into a buffer of its size), to the output or the error output. */
static void out_vformat(int to_err, const char *fmt, va_list ap) CBF__PRINTF(2, 0);
static void out_vformat(int to_err, const char *fmt, va_list ap)
{
    char line[1024], *text = line;
    va_list again;
    int len;
    va_copy(again, ap);
    len = vsnprintf(line, sizeof line, fmt, ap);
    if (len < 0) {
        va_end(again);
        return;
    }
    if ((size_t)len >= sizeof line) {
        text = (char *)malloc((size_t)len + 1u);
        if (text)
            (void)vsnprintf(text, (size_t)len + 1u, fmt, again);
    }
    va_end(again);
    if (!text)
        return;
    if (!to_err) {
        out_put(text, (size_t)len);
    } else {
        out_flush();
        if (tout.sink && tout.sink->err)
            tout.sink->err(tout.sink->user, text, (size_t)len);
    }
    if (text != line)
        free(text);
}

static void out_printf(const char *fmt, ...) CBF__PRINTF(1, 2);
static void out_printf(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    out_vformat(0, fmt, ap);
    va_end(ap);
}

static void err_printf(const char *fmt, ...) CBF__PRINTF(1, 2);
static void err_printf(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    out_vformat(1, fmt, ap);
    va_end(ap);
}
/* ==== END tools/output.c ==== */
#line 318 "cbf_tools.h"
/* ==== BEGIN tools/optfiles.c: verbatim from generator/cbfgen/emit/c/tools/optfiles.c, edit it there ==== */
#line 1 "generator/cbfgen/emit/c/tools/optfiles.c"
static char opt_why[8192];
static const char *opt_last_why = opt_why; /* the line of the last refusal */

static int opt_fail(const char *fmt, ...) CBF__PRINTF(1, 2);
static int opt_fail(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    (void)vsnprintf(opt_why, sizeof opt_why, fmt, ap);
    va_end(ap);
    return 0;
}

/* The most an option file may have, said as cbf says it. */
static long opt_too_large(const char *path, size_t max, const char *what)
{
    return opt_fail("%s: larger than the %lu bytes a %s may have (limit max_bytes)", path, (unsigned long)max, what) - 1;
}

/* *text freed (and NULL); v. */
static long opt_drop(char **text, long v)
{
    free(*text);
    *text = NULL;
    return v;
}

/* An option file's bytes (data[0..n)), at most max, copied into *text (the heap's, size + 1 bytes: the
 * caller frees it) and checked to be UTF-8 as Python decodes it; its size, or -1 with the one line in
 * opt_why (and nothing to free). Buffers of max bytes held for every run were most of the WebAssembly
 * module's initial memory (bench/NOTES.md, round 5). */
static long opt_read(const char *path, const char *data, size_t size, char **text, size_t max, const char *what)
{
    long n = (long)size;
    size_t i = 0;
    char *buf;
    *text = NULL;
    if (size > max)
        return opt_too_large(path, max, what);
    buf = (char *)malloc(size + 1u);
    if (!buf)
        return opt_fail("%s: out of memory reading the %s", path, what) - 1;
    *text = buf;
    memcpy(buf, data, size);
    buf[size] = 0;
    while (i < (size_t)n) { /* strict UTF-8: no overlong forms, surrogates or values beyond U+10FFFF */
        const unsigned char *u = (const unsigned char *)buf + i;
        size_t left = (size_t)n - i, len, k;
        unsigned char lo = 0x80, hi = 0xBF;
        if (u[0] < 0x80) {
            i++;
            continue;
        }
        if (u[0] >= 0xC2 && u[0] <= 0xDF) len = 2;
        else if (u[0] >= 0xE0 && u[0] <= 0xEF) len = 3;
        else if (u[0] >= 0xF0 && u[0] <= 0xF4) len = 4;
        else return opt_drop(text, opt_fail("%s: offset %lu: not UTF-8 text", path, (unsigned long)i) - 1);
        if (u[0] == 0xE0) lo = 0xA0;
        if (u[0] == 0xED) hi = 0x9F;
        if (u[0] == 0xF0) lo = 0x90;
        if (u[0] == 0xF4) hi = 0x8F;
        for (k = 1; k < len; k++) {
            unsigned char a = k == 1 ? lo : 0x80, b = k == 1 ? hi : 0xBF;
            if (k >= left || u[k] < a || u[k] > b)
                return opt_drop(text, opt_fail("%s: offset %lu: not UTF-8 text", path, (unsigned long)i) - 1);
        }
        i += len;
    }
    if (memchr(buf, 0, (size_t)n))
        return opt_drop(text, opt_fail("%s: offset %lu: not text (a NUL byte)", path,
                                       (unsigned long)((const char *)memchr(buf, 0, (size_t)n) - buf)) - 1);
    return n;
}

static size_t opt_chars(const char *s) /* UTF-8 characters, as Python's len() */
{
    size_t n = 0;
    for (; *s; s++)
        n += ((unsigned char)*s & 0xC0u) != 0x80u;
    return n;
}

/* RFC 8259's number grammar, the whole of s. */
static int opt_is_number(const char *s)
{
    if (*s == '-')
        s++;
    if (*s == '0') {
        s++;
    } else if (*s >= '1' && *s <= '9') {
        while (*s >= '0' && *s <= '9')
            s++;
    } else {
        return 0;
    }
    if (*s == '.') {
        s++;
        if (!(*s >= '0' && *s <= '9'))
            return 0;
        while (*s >= '0' && *s <= '9')
            s++;
    }
    if (*s == 'e' || *s == 'E') {
        s++;
        if (*s == '+' || *s == '-')
            s++;
        if (!(*s >= '0' && *s <= '9'))
            return 0;
        while (*s >= '0' && *s <= '9')
            s++;
    }
    return *s == 0;
}

static int opt_lower_eq(const char *s, const char *word)
{
    for (; *s && *word; s++, word++)
        if ((*s >= 'A' && *s <= 'Z' ? *s - 'A' + 'a' : *s) != *word)
            return 0;
    return *s == 0 && *word == 0;
}

/* NULL and *out set, or why text is not a usable number ("not a number", "not a finite number"). */
static const char *opt_number(const char *s, double *out)
{
    const char *w = s;
    if (opt_is_number(s)) {
        *out = strtod(s, NULL);
        return *out <= DBL_MAX && *out >= -DBL_MAX ? NULL : "not a finite number";
    }
    if (*w == '+' || *w == '-')
        w++;
    if (*w == '.')
        w++;
    if (opt_lower_eq(w, "nan") || opt_lower_eq(w, "inf") || opt_lower_eq(w, "infinity"))
        return "not a finite number";
    return "not a number";
}

/* "line L, column C: nested deeper than N levels" for the first bracket beyond max outside strings
 * (columns in characters), before the JSON reader reads a byte: its nesting is then bounded. */
static int opt_json_depth(const char *path, const char *s, size_t n, int max)
{
    size_t i;
    unsigned long line = 1, col = 0;
    int depth = 0, in_string = 0, escaped = 0;
    for (i = 0; i < n; i++) {
        char c = s[i];
        if (((unsigned char)c & 0xC0u) != 0x80u)
            col++;
        if (in_string) {
            if (escaped) escaped = 0;
            else if (c == '\\') escaped = 1;
            else if (c == '"') in_string = 0;
            else if (c == '\n') { line++; col = 0; }
            continue;
        }
        if (c == '"') {
            in_string = 1;
        } else if (c == '[' || c == '{') {
            if (++depth > max)
                return opt_fail("%s: line %lu, column %lu: nested deeper than %d levels (limit max_depth)", path, line,
                                col, max);
        } else if (c == ']' || c == '}') {
            depth--;
        } else if (c == '\n') {
            line++;
            col = 0;
        }
    }
    return 1;
}

/* ---- YAML, the subset both tools read (option_files.yaml), as JSON text with the same lines ----
 * Block and flow mappings and lists of one-line plain or quoted scalars, '#' comments, one document.
 * Anchors, aliases, tags, complex keys, multi-line values, a second document and nesting beyond the
 * limit are refused at the line they start, as cbf refuses them; a plain scalar becomes a JSON number
 * (RFC 8259 grammar), true, false, null ('~' and nothing too) or a string, as cbf resolves it. The
 * JSON keeps every source line break, so a JSON line is the YAML line. */
typedef struct yj {
    const char *file;
    char *out; /* the heap's: room bytes, grown to at most cap */
    size_t n, room, cap;
    int max_depth, depth;
    int ind[OPT_NEST_CAP + 1];
    char kind[OPT_NEST_CAP + 1]; /* 'm' or 's'; flow collections live only inside yj_flow */
    unsigned items[OPT_NEST_CAP + 1];
    int pending, pending_ind; /* a key or list item whose value is still to come */
    size_t pending_at; /* where its value goes: before the line breaks output since */
    unsigned long line, scalar_line; /* scalar_line: the last line that ended in a plain scalar value */
    int root_done, ended;
} yj;

static int yj_put(yj *y, const char *s, size_t len)
{
    if (y->cap - y->n <= len)
        return opt_fail("%s: line %lu: not YAML (too long once read)", y->file, y->line);
    if (y->room - y->n <= len) { /* grown by doubling, within cap (the test above) */
        size_t room = y->room;
        char *grown;
        while (room - y->n <= len)
            room = room >= y->cap / 2u ? y->cap : 2u * room;
        grown = (char *)realloc(y->out, room);
        if (!grown)
            return opt_fail("%s: line %lu: out of memory", y->file, y->line);
        y->out = grown;
        y->room = room;
    }
    memcpy(y->out + y->n, s, len);
    y->n += len;
    y->out[y->n] = 0;
    return 1;
}

static int yj_c(yj *y, char c) { return yj_put(y, &c, 1); }

static int yj_err(yj *y, unsigned long line, const char *what)
{
    return opt_fail("%s: line %lu: %s", y->file, line, what);
}

/* The null of a value that never came, on the line of its key or item (as cbf's reader places it). */
static int yj_null(yj *y)
{
    size_t breaks = y->n - y->pending_at, k;
    y->n = y->pending_at;
    if (!yj_put(y, "null", 4))
        return 0;
    for (k = 0; k < breaks; k++)
        if (!yj_c(y, '\n'))
            return 0;
    y->pending = 0;
    return 1;
}

static int yj_open(yj *y, char kind, int ind)
{
    if (y->depth >= y->max_depth)
        return opt_fail("%s: line %lu: nested deeper than %d levels (limit max_depth)", y->file, y->line, y->max_depth);
    y->depth++;
    y->kind[y->depth] = kind;
    y->ind[y->depth] = ind;
    y->items[y->depth] = 0;
    y->pending = 0;
    return yj_c(y, kind == 'm' ? '{' : '[');
}

static int yj_close(yj *y)
{
    if (y->pending && !yj_null(y))
        return 0;
    if (!yj_c(y, y->kind[y->depth] == 'm' ? '}' : ']'))
        return 0;
    y->depth--;
    return 1;
}

/* A JSON string of s[0..len) (control characters were refused with the line). */
static int yj_string(yj *y, const char *s, size_t len)
{
    size_t k;
    if (!yj_c(y, '"'))
        return 0;
    for (k = 0; k < len; k++) {
        if ((s[k] == '"' || s[k] == '\\') && !yj_c(y, '\\'))
            return 0;
        if (!yj_c(y, s[k]))
            return 0;
    }
    return yj_c(y, '"');
}

/* A plain scalar resolved as cbf resolves it. */
static int yj_plain(yj *y, const char *s, size_t len)
{
    char buf[512];
    if (len == 0 || (len == 1 && s[0] == '~'))
        return yj_put(y, "null", 4);
    if (len < sizeof buf) {
        memcpy(buf, s, len);
        buf[len] = 0;
        if (opt_is_number(buf) || strcmp(buf, "true") == 0 || strcmp(buf, "false") == 0 || strcmp(buf, "null") == 0)
            return yj_put(y, s, len);
    }
    return yj_string(y, s, len);
}

/* A quoted scalar at *p (' or "), ending on this line; *p moves past it. */
static int yj_quoted(yj *y, const char **p, const char *end)
{
    char q = **p;
    const char *s = *p + 1;
    if (!yj_c(y, '"'))
        return 0;
    for (;;) {
        if (s >= end)
            return yj_err(y, y->line, "a value over more than one line (one-line values only)");
        if (q == '\'' && *s == '\'') {
            if (s + 1 < end && s[1] == '\'') {
                if (!yj_c(y, '\''))
                    return 0;
                s += 2;
                continue;
            }
            break;
        }
        if (q == '"' && *s == '"')
            break;
        if (q == '"' && *s == '\\') {
            if (s + 1 >= end || !strchr("\"\\/bfnrtu", s[1]))
                return opt_fail("%s: line %lu: not YAML (an escape this reader does not read)", y->file, y->line);
            if (!yj_put(y, s, 2))
                return 0;
            s += 2;
            continue;
        }
        if ((*s == '"' || *s == '\\') && !yj_c(y, '\\'))
            return 0;
        if (!yj_c(y, *s))
            return 0;
        s++;
    }
    *p = s + 1;
    return yj_c(y, '"');
}

static int yj_node_mark(yj *y, const char *p)
{
    if (*p == '&' || *p == '*')
        return yj_err(y, y->line, "anchors and aliases are not allowed (limit: none)");
    if (*p == '!')
        return yj_err(y, y->line, "tags are not allowed");
    if (*p == '|' || *p == '>')
        return yj_err(y, y->line, "a value over more than one line (one-line values only)");
    if (*p == '?' && (p[1] == ' ' || p[1] == 0 || p[1] == '\t'))
        return yj_err(y, y->line, "a key must be a plain value (complex key)");
    return 1;
}

static const char *yj_skip(const char *p, const char *end)
{
    while (p < end && (*p == ' ' || *p == '\t'))
        p++;
    return p;
}

static int yj_flow(yj *y, const char **p, const char *end, int in_flow);

/* A plain scalar at *p: of a flow collection (in_flow: it ends at ',', ']' or '}') or a block value. */
static int yj_flow_plain(yj *y, const char **p, const char *end, int in_flow)
{
    const char *s = *p, *v0 = s;
    size_t len;
    while (s < end && !(in_flow && (*s == ',' || *s == ']' || *s == '}'))) {
        if (*s == ':' && (s + 1 == end || s[1] == ' ' || s[1] == '\t'))
            return opt_fail("%s: line %lu: not YAML (a ': ' inside a value)", y->file, y->line);
        s++;
    }
    len = (size_t)(s - v0);
    while (len && (v0[len - 1] == ' ' || v0[len - 1] == '\t'))
        len--;
    *p = s;
    if (!in_flow)
        y->scalar_line = y->line;
    return yj_plain(y, v0, len);
}

/* An entry of a flow mapping at *sp: its key (plain or quoted), ':' and its value (null when it has none). */
static int yj_flow_entry(yj *y, const char **sp, const char *end, char close, unsigned *keys)
{
    const char *s = *sp;
    if (!yj_node_mark(y, s))
        return 0;
    if (*s == '[' || *s == '{')
        return yj_err(y, y->line, "a key must be a plain value (complex key)");
    if (++*keys > OPT_YAML_MAX_KEYS)
        return opt_fail("%s: line %lu: more than %u keys in one mapping (limit max_keys)", y->file, y->line,
                        OPT_YAML_MAX_KEYS);
    if (*s == '"' || *s == '\'') {
        if (!yj_quoted(y, &s, end))
            return 0;
    } else {
        const char *k0 = s;
        size_t len;
        while (s < end && *s != ',' && *s != close && !(*s == ':' && (s + 1 >= end || s[1] == ' ')))
            s++;
        len = (size_t)(s - k0);
        while (len && (k0[len - 1] == ' ' || k0[len - 1] == '\t'))
            len--;
        if (!yj_string(y, k0, len))
            return 0;
    }
    s = yj_skip(s, end);
    if (!yj_c(y, ':'))
        return 0;
    if (s < end && *s == ':') {
        s++;
        if (!yj_flow(y, &s, end, 1))
            return 0;
    } else if (!yj_put(y, "null", 4)) {
        return 0;
    }
    *sp = s;
    return 1;
}

/* What follows an entry at *sp: ',' and another entry (1), the close, after a ',' or not (2); 0 refused. */
static int yj_flow_next(yj *y, const char **sp, const char *end, char close)
{
    const char *s = yj_skip(*sp, end);
    if (s >= end)
        return yj_err(y, y->line, "a value over more than one line (one-line values only)");
    if (*s == ',') {
        s = yj_skip(s + 1, end);
        if (s < end && *s == close) {
            *sp = s + 1;
            return 2;
        }
        *sp = s;
        return yj_c(y, ',');
    }
    if (*s == close) {
        *sp = s + 1;
        return 2;
    }
    return opt_fail("%s: line %lu: not YAML (expected ',' or '%c')", y->file, y->line, close);
}

/* A flow collection at *p ('[' or '{'), on one line. */
static int yj_flow_collection(yj *y, const char **p, const char *end)
{
    const char *s = *p;
    char close = *s == '[' ? ']' : '}';
    int mapping = *s == '{', more = 1;
    unsigned keys = 0;
    if (y->depth >= y->max_depth)
        return opt_fail("%s: line %lu: nested deeper than %d levels (limit max_depth)", y->file, y->line,
                        y->max_depth);
    y->depth++;
    if (!yj_c(y, *s))
        return 0;
    s = yj_skip(s + 1, end);
    if (s < end && *s == close) {
        s++;
        more = 2;
    }
    while (more == 1) {
        s = yj_skip(s, end);
        if (s >= end)
            return yj_err(y, y->line, "a value over more than one line (one-line values only)");
        if (mapping ? !yj_flow_entry(y, &s, end, close, &keys) : !yj_flow(y, &s, end, 1))
            return 0;
        more = yj_flow_next(y, &s, end, close);
        if (!more)
            return 0;
    }
    y->depth--;
    *p = s;
    return yj_c(y, close);
}

/* A flow collection or scalar at *p (in_flow: inside a flow collection). */
static int yj_flow(yj *y, const char **p, const char *end, int in_flow)
{
    const char *s = yj_skip(*p, end);
    if (!yj_node_mark(y, s))
        return 0;
    *p = s;
    if (s < end && (*s == '[' || *s == '{'))
        return yj_flow_collection(y, p, end);
    if (s < end && (*s == '"' || *s == '\''))
        return yj_quoted(y, p, end);
    return yj_flow_plain(y, p, end, in_flow);
}

/* Whether p is a ':' followed by a blank or the line's end. */
static int yj_colon_at(const char *p, const char *end)
{
    return *p == ':' && (p + 1 == end || p[1] == ' ' || p[1] == '\t');
}

/* The end of a quoted key at p: the ':' after its closing quote, or NULL. */
static const char *yj_quoted_key_end(const char *p, const char *end)
{
    char q = *p++;
    while (p < end && !(*p == q && !(q == '\'' && p + 1 < end && p[1] == '\'')))
        p += (q == '\'' && *p == '\'') || (q == '"' && *p == '\\') ? 2 : 1;
    if (p >= end)
        return NULL;
    p = yj_skip(p + 1, end);
    return p < end && yj_colon_at(p, end) ? p : NULL;
}

/* The end of a plain or quoted key at p followed by ':' and a blank or the line's end, or NULL. */
static const char *yj_key_end(const char *p, const char *end)
{
    if (p < end && (*p == '"' || *p == '\''))
        return yj_quoted_key_end(p, end);
    if (p < end && (*p == '[' || *p == '{'))
        return NULL;
    for (; p < end; p++)
        if (yj_colon_at(p, end))
            return p;
    return NULL;
}

static int yj_inline(yj *y, const char *p, const char *end, int col);

/* Where a new list item ('s') or key ('m') at column col goes: after a sibling (a ','), or opening a
 * collection as a pending value or the root; 0 (refused) where none can be. */
static int yj_entry(yj *y, char kind, int col)
{
    if (y->depth && y->kind[y->depth] == kind && y->ind[y->depth] == col && !y->pending)
        return yj_c(y, ',');
    if (y->pending || (!y->depth && !y->root_done))
        return yj_open(y, kind, col);
    return opt_fail("%s: line %lu: not YAML (a %s where none can be)", y->file, y->line,
                    kind == 's' ? "list item" : "key");
}

/* The value of a list item or key is still to come: on this line, or on the lines below. */
static void yj_pending(yj *y, int col)
{
    y->pending = 1;
    y->pending_ind = col;
    y->pending_at = y->n;
}

/* A list item at p ("- "), and its value when it is on this line. */
static int yj_item(yj *y, const char *p, const char *end, int col)
{
    const char *rest;
    if (!yj_entry(y, 's', col))
        return 0;
    y->root_done = 1;
    y->items[y->depth]++;
    rest = yj_skip(p + 1, end);
    yj_pending(y, col);
    if (rest >= end)
        return 1;
    return yj_inline(y, rest, end, col + (int)(rest - p));
}

/* A key at p (ending at colon) and its value when it is on this line. */
static int yj_key(yj *y, const char *p, const char *colon, const char *end, int col)
{
    const char *v;
    if (!yj_entry(y, 'm', col))
        return 0;
    y->root_done = 1;
    if (++y->items[y->depth] > OPT_YAML_MAX_KEYS)
        return opt_fail("%s: line %lu: more than %u keys in one mapping (limit max_keys)", y->file, y->line,
                        OPT_YAML_MAX_KEYS);
    if (*p == '"' || *p == '\'') {
        const char *q = p;
        if (!yj_quoted(y, &q, end))
            return 0;
    } else {
        size_t len = (size_t)(colon - p);
        while (len && (p[len - 1] == ' ' || p[len - 1] == '\t'))
            len--;
        if (!yj_string(y, p, len))
            return 0;
    }
    if (!yj_c(y, ':'))
        return 0;
    v = yj_skip(colon + 1, end);
    if (v >= end) {
        yj_pending(y, col);
        return 1;
    }
    if (!yj_flow(y, &v, end, 0))
        return 0;
    if (yj_skip(v, end) < end)
        return opt_fail("%s: line %lu: not YAML (more after a value)", y->file, y->line);
    return 1;
}

/* The node a line holds from p (its column col): a list item, a key and its value, or a value. */
static int yj_inline(yj *y, const char *p, const char *end, int col)
{
    const char *colon;
    if (!yj_node_mark(y, p))
        return 0;
    if (*p == '-' && (p + 1 == end || p[1] == ' ' || p[1] == '\t'))
        return yj_item(y, p, end, col);
    colon = yj_key_end(p, end);
    if (colon)
        return yj_key(y, p, colon, end, col);
    if (!y->pending && (y->depth || y->root_done)) {
        if (y->scalar_line && y->scalar_line + 1 == y->line)
            return yj_err(y, y->scalar_line, "a value over more than one line (one-line values only)");
        return opt_fail("%s: line %lu: not YAML (a value where none can be)", y->file, y->line);
    }
    y->pending = 0;
    y->root_done = 1;
    if (!yj_flow(y, &p, end, 0))
        return 0;
    if (yj_skip(p, end) < end)
        return opt_fail("%s: line %lu: not YAML (more after a value)", y->file, y->line);
    return 1;
}

/* The end of a line's content (line..end): control characters refused, a comment outside quotes cut, trailing
 * blanks dropped; NULL when refused (the one line in opt_why). */
static const char *yj_content_end(const yj *y, const char *line, const char *end)
{
    const char *c;
    int quote = 0;
    for (c = line; c < end; c++) {
        if ((unsigned char)*c < 0x20 && *c != '\t' && !(*c == '\r' && c + 1 == end)) {
            (void)opt_fail("%s: line %lu: not YAML (a control character)", y->file, y->line);
            return NULL;
        }
        if (quote) {
            if (*c == quote)
                quote = 0;
        } else if ((*c == '"' || *c == '\'') && (c == line || strchr(" \t[{,:-", c[-1]))) {
            quote = *c;
        } else if (*c == '#' && (c == line || c[-1] == ' ' || c[-1] == '\t')) {
            end = c;
            break;
        }
    }
    while (end > line && (end[-1] == ' ' || end[-1] == '\t' || end[-1] == '\r'))
        end--;
    return end;
}

/* The document markers at *pp, the start of a line's content (its indentation *ind): "---" (the content
 * follows it), "..." (the document ends), a directive (refused). */
static int yj_markers(yj *y, const char *line, const char **pp, const char *end, int *ind)
{
    const char *p = *pp;
    if (p >= end)
        return 1;
    if (*ind == 0 && end - p >= 3 && memcmp(p, "---", 3) == 0 && (end - p == 3 || p[3] == ' ')) {
        if (y->root_done || y->ended)
            return yj_err(y, y->line, "more than one document");
        p = yj_skip(p + 3, end);
        *ind = (int)(p - line);
    } else if (*ind == 0 && end - p == 3 && memcmp(p, "...", 3) == 0) {
        y->ended = 1;
        p = end;
    } else if (*p == '%') {
        return opt_fail("%s: line %lu: not YAML (a directive)", y->file, y->line);
    }
    *pp = p;
    return 1;
}

/* A line's node at p (indentation ind): the pending value it ends, the collections it closes, then itself. */
static int yj_line_node(yj *y, const char *p, const char *end, int ind)
{
    int item = *p == '-' && (p + 1 == end || p[1] == ' ' || p[1] == '\t');
    if (y->ended)
        return yj_err(y, y->line, "more than one document");
    if (y->pending && ind <= y->pending_ind && !(item && ind == y->pending_ind && y->depth && y->kind[y->depth] == 'm')
        && !yj_null(y))
        return 0;
    while (y->depth && !y->pending
           && (y->ind[y->depth] > ind || (y->ind[y->depth] == ind && y->kind[y->depth] == 's' && !item)))
        if (!yj_close(y))
            return 0;
    return yj_inline(y, p, end, ind);
}

static int yj_lines(yj *y, const char *src);

/* Translate the YAML text src into JSON text in *out (the heap's, at most cap bytes with its NUL: the
 * caller frees it); 0 with the one line in opt_why (and nothing to free). */
static int yj_translate(const char *file, const char *src, char **out, size_t cap, int max_depth)
{
    yj y;
    memset(&y, 0, sizeof y);
    y.file = file;
    y.cap = cap;
    y.room = cap < 4096u ? cap : 4096u;
    y.max_depth = max_depth;
    *out = NULL;
    y.out = (char *)malloc(y.room);
    if (!y.out)
        return opt_fail("%s: out of memory", file);
    y.out[0] = 0;
    if (!yj_lines(&y, src)) {
        free(y.out);
        return 0;
    }
    *out = y.out;
    return 1;
}

/* yj_translate's work, line by line, into y->out. */
static int yj_lines(yj *y, const char *src)
{
    const char *file = y->file, *line = src;
    if (strncmp(src, "\xEF\xBB\xBF", 3) == 0) /* a byte order mark, which YAML readers skip (src: NUL-ended) */
        line += 3;
    while (*line) {
        const char *nl = strchr(line, '\n'), *end = nl ? nl : line + strlen(line), *p = line;
        int ind;
        y->line++;
        end = yj_content_end(y, line, end);
        if (!end)
            return 0;
        while (p < end && *p == ' ')
            p++;
        ind = (int)(p - line);
        if (p < end && *p == '\t')
            return opt_fail("%s: line %lu: not YAML (a tab in the indentation)", file, y->line);
        if (!yj_markers(y, line, &p, end, &ind))
            return 0;
        if (p < end && !yj_line_node(y, p, end, ind))
            return 0;
        if (!yj_c(y, '\n'))
            return 0;
        if (!nl)
            break;
        line = nl + 1;
    }
    while (y->depth)
        if (!yj_close(y))
            return 0;
    if (!y->root_done && !yj_put(y, "null", 4))
        return 0;
    return 1;
}

/* ---- cutter tables (6.1.2): the rows, each checked as it comes by the shared rules ---- */
/* The rows of the last table, the heap's, grown by doubling to at most OPT_CUTTER_MAX_ROWS (room rows);
 * cutters[k].name is cutter_names[k], set once the table is read (a row added may move the names). */
typedef char cutter_name[OPT_CUTTER_NAME_BYTES];
static cutter_name *cutter_names;
static unsigned long *cutter_lines;
static cbf_cutter *cutters;
static size_t ncutters, cutter_room;
static char *cutter_text; /* the table's text while it is read (opt_read) */
static const char *cutter_file;

/* Room for one more row; 0 with the one line in opt_why when the heap has none. */
static int cutter_grow(unsigned long line)
{
    size_t room = cutter_room ? 2u * cutter_room : 64u;
    cutter_name *names;
    unsigned long *lines;
    cbf_cutter *rows;
    if (room > OPT_CUTTER_MAX_ROWS)
        room = OPT_CUTTER_MAX_ROWS;
    names = (cutter_name *)realloc(cutter_names, room * sizeof *cutter_names);
    if (names)
        cutter_names = names;
    lines = (unsigned long *)realloc(cutter_lines, room * sizeof *cutter_lines);
    if (lines)
        cutter_lines = lines;
    rows = (cbf_cutter *)realloc(cutters, room * sizeof *cutters);
    if (rows)
        cutters = rows;
    if (!names || !lines || !rows)
        return opt_fail("%s: line %lu: out of memory", cutter_file, line);
    cutter_room = room;
    return 1;
}

/* A row: cell[0] the name, cell[1 + k] the text of value k. */
static int cutter_add(unsigned long line, const char *const cell[OPT_CUTTER_COLUMNS])
{
    const char *name = cell[0];
    size_t k, chars = opt_chars(name);
    double v[CBF_CUTTER_VALUES];
    if (ncutters >= OPT_CUTTER_MAX_ROWS)
        return opt_fail("%s: line %lu: more than %u cutters (limit max_rows)", cutter_file, line, OPT_CUTTER_MAX_ROWS);
    if (!*name)
        return opt_fail("%s: line %lu: empty cutter name", cutter_file, line);
    if (chars > OPT_CUTTER_MAX_NAME)
        return opt_fail("%s: line %lu: cutter name of %lu characters, longer than the %u a cutter record holds "
                        "(limit max_name)", cutter_file, line, (unsigned long)chars, OPT_CUTTER_MAX_NAME);
    for (k = 0; k < CBF_CUTTER_VALUES; k++) {
        const char *text = cell[1 + k], *why = opt_number(text, &v[k]);
        if (why)
            return opt_fail("%s: line %lu: %s '%s' is %s", cutter_file, line, opt_cutter_values[k].column,
                            cbf_quoted(text, CBF_QUOTE_NAME), why);
        if (opt_cutter_values[k].positive && v[k] <= 0.0)
            return opt_fail("%s: line %lu: %s %s is not greater than 0 (check %s)", cutter_file, line,
                            opt_cutter_values[k].column, text, opt_cutter_values[k].check);
    }
    for (k = 0; k < ncutters; k++)
        if (strcmp(cutter_names[k], name) == 0)
            return opt_fail("%s: line %lu: cutter '%s' given twice (first on line %lu)", cutter_file, line,
                            cbf_quoted(name, CBF_QUOTE_NAME),
                            cutter_lines[k]);
    if (ncutters == cutter_room && !cutter_grow(line))
        return 0;
    memcpy(cutter_names[ncutters], name, strlen(name) + 1); /* chars <= max: fits OPT_CUTTER_NAME_BYTES */
    cutter_lines[ncutters] = line;
    cutters[ncutters].name = NULL; /* set when the table is read (load_cutters) */
    for (k = 0; k < CBF_CUTTER_VALUES; k++)
        cutters[ncutters].value[k] = v[k];
    ncutters++;
    return 1;
}

static int opt_blank(int c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

/* A CSV cell: trimmed of blanks, then of one pair of matching quotes (writes a NUL at the end). */
static char *opt_cell(char *s)
{
    size_t n;
    while (*s && opt_blank((unsigned char)*s))
        s++;
    n = strlen(s);
    while (n && opt_blank((unsigned char)s[n - 1]))
        s[--n] = 0;
    if (n >= 2 && (s[0] == '"' || s[0] == '\'') && s[n - 1] == s[0]) {
        s[n - 1] = 0;
        s++;
    }
    return s;
}

/* CSV: the first non-blank line names the columns (opt_cutter_columns, in any order). */
static int cutters_csv(char *text)
{
    char *line = text;
    int col[OPT_CUTTER_COLUMNS], header = 1, i;
    unsigned long n = 0;
    for (i = 0; i < OPT_CUTTER_COLUMNS; i++)
        col[i] = -1;
    while (line) {
        char *cells[OPT_CUTTER_MAX_COLUMNS], *p = line, *next = strchr(line, '\n');
        int nc = 1, k, blank = 1;
        n++;
        if (next)
            *next++ = 0;
        for (p = line; *p; p++)
            blank &= opt_blank((unsigned char)*p);
        if (blank) {
            line = next;
            continue;
        }
        cells[0] = line;
        for (p = line; *p; p++) {
            if (*p != ',')
                continue;
            if (nc == OPT_CUTTER_MAX_COLUMNS)
                return opt_fail("%s: line %lu: more than %d columns (limit max_columns)", cutter_file, n,
                                OPT_CUTTER_MAX_COLUMNS);
            *p = 0;
            cells[nc++] = p + 1;
        }
        for (k = 0; k < nc; k++)
            cells[k] = opt_cell(cells[k]);
        if (header) {
            header = 0;
            for (i = 0; i < OPT_CUTTER_COLUMNS; i++)
                for (k = 0; k < nc && col[i] < 0; k++)
                    if (strcmp(cells[k], opt_cutter_columns[i]) == 0)
                        col[i] = k;
            for (i = 0; i < OPT_CUTTER_COLUMNS; i++)
                if (col[i] < 0)
                    return opt_fail("%s: line %lu: the header row needs the columns %s", cutter_file, n,
                                    opt_columns_list);
        } else {
            const char *row[OPT_CUTTER_COLUMNS];
            for (i = 0; i < OPT_CUTTER_COLUMNS; i++) {
                if (col[i] >= nc)
                    return opt_fail("%s: line %lu: needs %s", cutter_file, n, opt_columns_list);
                row[i] = cells[col[i]];
            }
            if (!cutter_add(n, row))
                return 0;
        }
        line = next;
    }
    return 1;
}

/* ---- the JSON a YAML table becomes, walked with its lines ---- */
typedef struct cj { const char *s; size_t i, at; unsigned long line; } cj;

static unsigned long cj_line(cj *j) /* the line of position i (moving forward only) */
{
    for (; j->at < j->i; j->at++)
        j->line += j->s[j->at] == '\n';
    return j->line;
}

static void cj_ws(cj *j)
{
    while (j->s[j->i] == ' ' || j->s[j->i] == '\n' || j->s[j->i] == '\t' || j->s[j->i] == '\r')
        j->i++;
}

/* A scalar's text as cbf shows it: a string's characters, a number, true, false or null as written. */
static void cj_scalar(cj *j, char *out, size_t cap)
{
    size_t k = 0;
    if (j->s[j->i] == '"') {
        j->i++;
        while (j->s[j->i] && j->s[j->i] != '"') {
            char c = j->s[j->i++];
            if (c == '\\') {
                c = j->s[j->i++];
                if (c == 'n') c = '\n';
                else if (c == 't') c = '\t';
                else if (c == 'r') c = '\r';
                else if (c == 'b') c = '\b';
                else if (c == 'f') c = '\f';
                else if (c == 'u') {
                    unsigned u = 0, q;
                    for (q = 0; q < 4 && j->s[j->i]; q++, j->i++) {
                        char h = j->s[j->i];
                        u = u * 16u + (unsigned)(h <= '9' ? h - '0' : (h | 0x20) - 'a' + 10);
                    }
                    c = u < 0x80u ? (char)u : '?';
                }
            }
            if (k + 1 < cap)
                out[k++] = c;
        }
        if (j->s[j->i] == '"')
            j->i++;
    } else {
        while (j->s[j->i] && !strchr(",]} \n\t\r", j->s[j->i])) {
            if (k + 1 < cap)
                out[k++] = j->s[j->i];
            j->i++;
        }
    }
    out[k] = 0;
}

static int cutters_rows(cj *j)
{
    cj_ws(j);
    if (strncmp(j->s + j->i, "null", 4) == 0) {
        j->i += 4;
        return 1;
    }
    if (j->s[j->i] != '[')
        return opt_fail("%s: line %lu: expected a list of cutters (%s)", cutter_file, cj_line(j), opt_columns_list);
    j->i++;
    for (;;) {
        unsigned long row;
        char got[OPT_CUTTER_COLUMNS][OPT_CUTTER_NAME_BYTES + 64];
        int have[OPT_CUTTER_COLUMNS] = { 0 }, k;
        cj_ws(j);
        if (j->s[j->i] == ']') {
            j->i++;
            return 1;
        }
        if (j->s[j->i] == ',') {
            j->i++;
            continue;
        }
        row = cj_line(j);
        if (j->s[j->i] != '{')
            return opt_fail("%s: line %lu: a cutter is a mapping of %s", cutter_file, row, opt_columns_list);
        j->i++;
        for (;;) {
            char key[256];
            unsigned long kline;
            cj_ws(j);
            if (j->s[j->i] == '}') {
                j->i++;
                break;
            }
            if (j->s[j->i] == ',') {
                j->i++;
                continue;
            }
            kline = cj_line(j);
            cj_scalar(j, key, sizeof key);
            for (k = 0; k < OPT_CUTTER_COLUMNS && strcmp(key, opt_cutter_columns[k]) != 0; k++)
                ;
            if (k == OPT_CUTTER_COLUMNS)
                return opt_fail("%s: line %lu: unknown key '%s' (known: %s)", cutter_file, kline,
                                cbf_quoted(key, CBF_QUOTE_NAME),
                                opt_columns_list);
            if (have[k])
                return opt_fail("%s: line %lu: duplicate key '%s'", cutter_file, kline, cbf_quoted(key, CBF_QUOTE_NAME));
            cj_ws(j);
            if (j->s[j->i] == ':')
                j->i++;
            cj_ws(j);
            if (j->s[j->i] == '[' || j->s[j->i] == '{')
                return opt_fail("%s: line %lu: %s must be one value", cutter_file, cj_line(j), key);
            cj_scalar(j, got[k], sizeof got[k]);
            have[k] = 1;
        }
        {
            const char *cell[OPT_CUTTER_COLUMNS];
            for (k = 0; k < OPT_CUTTER_COLUMNS; k++) {
                if (!have[k])
                    return opt_fail("%s: line %lu: needs %s", cutter_file, row, opt_columns_list);
                cell[k] = got[k];
            }
            if (!cutter_add(row, cell))
                return 0;
        }
    }
}

static int cutters_json(const char *path, const char *json);

static int cutters_yaml(const char *path)
{
    char *json;
    int ok;
    /* the JSON text: at most 4 bytes a byte of YAML, and a few more (as the buffer of that size was) */
    if (!yj_translate(path, cutter_text, &json, 4u * OPT_CUTTER_MAX_BYTES + 64u, OPT_CUTTER_MAX_DEPTH))
        return 0;
    ok = cutters_json(path, json);
    free(json);
    return ok;
}

/* The rows of a cutter table read as JSON text (a YAML table, translated). */
static int cutters_json(const char *path, const char *json)
{
    cj j;
    int seen = 0;
    memset(&j, 0, sizeof j);
    j.s = json;
    j.line = 1;
    cj_ws(&j);
    if (j.s[j.i] != '{')
        return j.s[j.i] == 'n' ? 1 : cutters_rows(&j);
    j.i++;
    for (;;) {
        char key[256];
        unsigned long kline;
        cj_ws(&j);
        if (j.s[j.i] == '}' || !j.s[j.i])
            return 1;
        if (j.s[j.i] == ',') {
            j.i++;
            continue;
        }
        kline = cj_line(&j);
        cj_scalar(&j, key, sizeof key);
        if (strcmp(key, "cutters") != 0)
            return opt_fail("%s: line %lu: unknown key '%s' (known: cutters)", path, kline,
                            cbf_quoted(key, CBF_QUOTE_NAME));
        if (seen++)
            return opt_fail("%s: line %lu: duplicate key 'cutters'", path, kline);
        cj_ws(&j);
        if (j.s[j.i] == ':')
            j.i++;
        if (!cutters_rows(&j))
            return 0;
    }
}

/* Whether a path names a YAML file (.yaml or .yml, in any case, as cbf decides). */
static int opt_is_yaml(const char *path)
{
    const char *dot = strrchr(path, '.'), *slash = strrchr(path, '/');
    if (!dot || (slash && dot < slash) || dot == path || (slash && dot == slash + 1))
        return 0;
    return opt_lower_eq(dot, ".yaml") || opt_lower_eq(dot, ".yml");
}

/* A cutter table (name: its file name, which says CSV or YAML; text[0..n): its bytes) into cutters[0..ncutters);
 * 0 with the one line in opt_why. */
static int load_cutters(const char *name, const char *text, size_t size)
{
    static char path[CBF_TOOL_NAME_BYTES]; /* the name as every message shows it (cbf_tool_name: the quoting rule) */
    long n;
    (void)snprintf(path, sizeof path, "%s", cbf_tool_name(name));
    size_t k;
    int ok;
    ncutters = 0;
    cutter_file = path;
    n = opt_read(path, text, size, &cutter_text, OPT_CUTTER_MAX_BYTES, opt_cutter_what);
    if (n < 0)
        return 0;
    ok = opt_is_yaml(name) ? cutters_yaml(path) : cutters_csv(cutter_text);
    free(cutter_text);
    cutter_text = NULL;
    if (!ok)
        return 0;
    if (!ncutters)
        return opt_fail("%s: no cutters (the table is empty)", path);
    for (k = 0; k < ncutters; k++)
        cutters[k].name = cutter_names[k];
    return 1;
}

/* ---- machine files (the spec's machine decision, check machine_limits) ----
 * The JSON form of `machine:` in spec/cbf.yaml (schema generated/python/cbf/machine.schema.json):
 *   {"name": "...", "limits": {"<limit>": {"unit": "<the spec's unit>", "min": N | [N, ...],
 *    "max": N | [N, ...], "axes": [...], "doc": "..."}, ...}}
 * every limit of cbf_machine_limit_names with unit, min and max; one number per axis for a box;
 * min <= max. Both tools read it as JSON, or as YAML for .yaml/.yml (the option-file subset above,
 * translated to JSON with its lines). A bad file gives one line naming the file and the JSON path
 * (or the line), as cbf says it. */
static cbf_machine machine_file;
static char machine_why[8192];

typedef struct mjson { const char *s; size_t n, i; const char *file; } mjson;


static int mj_fail(mjson *j, const char *path, const char *fmt, ...) CBF__PRINTF(3, 4);
static int mj_fail(mjson *j, const char *path, const char *fmt, ...)
{
    va_list ap;
    size_t k;
    (void)snprintf(machine_why, sizeof machine_why, "%s: %s: ", j->file, path);
    k = strlen(machine_why);
    va_start(ap, fmt);
    (void)vsnprintf(machine_why + k, sizeof machine_why - k, fmt, ap);
    va_end(ap);
    return 0;
}

static int mj_syntax(mjson *j, const char *what)
{
    unsigned long line = 1, col = 1;
    size_t k;
    for (k = 0; k < j->i && k < j->n; k++) {
        if (j->s[k] == '\n') {
            line++;
            col = 1;
        } else {
            col++;
        }
    }
    (void)snprintf(machine_why, sizeof machine_why, "%s: line %lu, column %lu: not JSON (%s)", j->file, line, col,
                   what);
    return 0;
}

static void mj_ws(mjson *j)
{
    while (j->i < j->n && (j->s[j->i] == ' ' || j->s[j->i] == '\t' || j->s[j->i] == '\n' || j->s[j->i] == '\r'))
        j->i++;
}

static int mj_peek(mjson *j)
{
    mj_ws(j);
    return j->i < j->n ? (unsigned char)j->s[j->i] : -1;
}

static int mj_hex4(const char *p, unsigned *out)
{
    unsigned k, v = 0;
    for (k = 0; k < 4; k++) {
        char c = p[k];
        v <<= 4;
        if (c >= '0' && c <= '9') v |= (unsigned)(c - '0');
        else if (c >= 'a' && c <= 'f') v |= (unsigned)(c - 'a' + 10);
        else if (c >= 'A' && c <= 'F') v |= (unsigned)(c - 'A' + 10);
        else return 0;
    }
    *out = v;
    return 1;
}

/* A JSON string into out (UTF-8 as given; \u escapes above ASCII become '?': no key or unit has them). */
static int mj_string(mjson *j, char *out, size_t cap)
{
    size_t k = 0;
    if (mj_peek(j) != '"')
        return mj_syntax(j, "expected a string");
    j->i++;
    for (;;) {
        char c;
        if (j->i >= j->n)
            return mj_syntax(j, "unterminated string");
        c = j->s[j->i++];
        if (c == '"')
            break;
        if ((unsigned char)c < 0x20)
            return mj_syntax(j, "control character in a string");
        if (c == '\\') {
            unsigned u;
            if (j->i >= j->n)
                return mj_syntax(j, "unterminated string");
            c = j->s[j->i++];
            switch (c) {
            case '"': case '\\': case '/': break;
            case 'b': c = '\b'; break;
            case 'f': c = '\f'; break;
            case 'n': c = '\n'; break;
            case 'r': c = '\r'; break;
            case 't': c = '\t'; break;
            case 'u':
                if (j->n - j->i < 4 || !mj_hex4(j->s + j->i, &u))
                    return mj_syntax(j, "bad \\u escape");
                j->i += 4;
                c = u < 0x80u ? (char)u : '?';
                break;
            default:
                return mj_syntax(j, "bad escape");
            }
        }
        if (k + 1 >= cap)
            return mj_syntax(j, "string too long");
        out[k++] = c;
    }
    out[k] = 0;
    return 1;
}

/* A JSON number (RFC 8259 grammar); *finite says whether it fits a double. */
static int mj_is_digit(const mjson *j)
{
    return j->i < j->n && j->s[j->i] >= '0' && j->s[j->i] <= '9';
}

/* The digits at j->i, at least one; 0 when there is none. */
static int mj_digits(mjson *j)
{
    if (!mj_is_digit(j))
        return 0;
    while (mj_is_digit(j))
        j->i++;
    return 1;
}

static int mj_number(mjson *j, double *out, int *finite)
{
    size_t start = j->i, len;
    char buf[128];
    if (j->i < j->n && j->s[j->i] == '-')
        j->i++;
    if (j->i < j->n && j->s[j->i] == '0')
        j->i++;
    else if (!mj_digits(j))
        return mj_syntax(j, "expected a value");
    if (j->i < j->n && j->s[j->i] == '.') {
        j->i++;
        if (!mj_digits(j))
            return mj_syntax(j, "expected a digit");
    }
    if (j->i < j->n && (j->s[j->i] == 'e' || j->s[j->i] == 'E')) {
        j->i++;
        if (j->i < j->n && (j->s[j->i] == '+' || j->s[j->i] == '-'))
            j->i++;
        if (!mj_digits(j))
            return mj_syntax(j, "expected a digit");
    }
    len = j->i - start;
    if (len >= sizeof buf)
        return mj_syntax(j, "number too long");
    memcpy(buf, j->s + start, len);
    buf[len] = 0;
    *out = strtod(buf, NULL);
    *finite = *out <= DBL_MAX && *out >= -DBL_MAX; /* false for an overflow (HUGE_VAL) and for NaN */
    return 1;
}

/* The kind of the next value, for "expected ..." (0 when it does not start a value). */
static int mj_kind(mjson *j)
{
    int c = mj_peek(j);
    if (c == '{' || c == '[' || c == '"') return c;
    if (c == '-' || (c >= '0' && c <= '9')) return 'n';
    if (c == 't' || c == 'f' || c == 'n') return 'l';
    return 0;
}

static int mj_expect_number(mjson *j, const char *path, double *out)
{
    int finite = 0;
    if (mj_kind(j) != 'n') {
        if (!mj_kind(j))
            return mj_syntax(j, "expected a value");
        return mj_fail(j, path, "expected a number");
    }
    if (!mj_number(j, out, &finite))
        return 0;
    if (!finite)
        return mj_fail(j, path, "not a finite number");
    return 1;
}

/* "{" key ":" value ("," key ":" value)* "}": calls on_key for each key, with the duplicate check. */
typedef int (*mj_key_fn)(mjson *j, const char *path, const char *key, void *ctx);

static int mj_object(mjson *j, const char *path, mj_key_fn on_key, void *ctx)
{
    char keys[16][64];
    size_t nkeys = 0, k;
    if (mj_kind(j) != '{')
        return mj_kind(j) ? mj_fail(j, path, "expected an object") : mj_syntax(j, "expected a value");
    j->i++;
    if (mj_peek(j) == '}') {
        j->i++;
        return 1;
    }
    for (;;) {
        char key[64];
        if (!mj_string(j, key, sizeof key))
            return 0;
        if (mj_peek(j) != ':')
            return mj_syntax(j, "expected ':'");
        j->i++;
        for (k = 0; k < nkeys; k++)
            if (strcmp(keys[k], key) == 0)
                return mj_fail(j, path, "duplicate key '%s'", cbf_quoted(key, CBF_QUOTE_NAME));
        if (nkeys < 16)
            (void)snprintf(keys[nkeys++], sizeof keys[0], "%s", key);
        if (!on_key(j, path, key, ctx))
            return 0;
        if (mj_peek(j) == ',') {
            j->i++;
            continue;
        }
        if (mj_peek(j) == '}') {
            j->i++;
            return 1;
        }
        return mj_syntax(j, "expected ',' or '}'");
    }
}

/* known: n names, or fewer ended by NULL (cbf_machine_limit_names has no NULL: reading one past it was a
 * global-buffer-overflow that AddressSanitizer found on a machine file with an unknown limit). */
static int mj_unknown(mjson *j, const char *path, const char *key, const char *const *known, size_t n)
{
    char list[512];
    size_t k, at = 0;
    list[0] = 0;
    for (k = 0; k < n && known[k]; k++)
        at += (size_t)snprintf(list + at, sizeof list - at, "%s%s", k ? ", " : "", known[k]);
    return mj_fail(j, path, "unknown key '%s' (known: %s)", cbf_quoted(key, CBF_QUOTE_NAME), list);
}

/* A string the reader keeps nowhere (name, doc, decision). */
static int mj_any_string(mjson *j, const char *path)
{
    char skip[4096];
    if (mj_kind(j) != '"')
        return mj_kind(j) ? mj_fail(j, path, "expected a string") : mj_syntax(j, "expected a value");
    return mj_string(j, skip, sizeof skip);
}

typedef struct mj_limit { int index; unsigned seen; } mj_limit;

/* min or max: a number, or for a box a list of one number per axis. */
static int mj_bound(mjson *j, const char *path, int li, double *out)
{
    int naxes = cbf_machine_limit_axes[li], n = 0;
    char ipath[320];
    if (!naxes)
        return mj_expect_number(j, path, out);
    if (mj_kind(j) != '[')
        return mj_kind(j) ? mj_fail(j, path, "expected a list") : mj_syntax(j, "expected a value");
    j->i++;
    if (mj_peek(j) != ']') {
        for (;;) {
            double x;
            (void)snprintf(ipath, sizeof ipath, "%s[%d]", path, n);
            if (!mj_expect_number(j, ipath, &x))
                return 0;
            if (n < naxes)
                out[n] = x;
            n++;
            if (mj_peek(j) == ',') {
                j->i++;
                continue;
            }
            break;
        }
    }
    if (mj_peek(j) != ']')
        return mj_syntax(j, "expected ',' or ']'");
    j->i++;
    if (n != naxes)
        return mj_fail(j, path, "expected %d items, got %d", naxes, n);
    return 1;
}

/* axes: a list of strings equal to the spec's axes (optional). */
static int mj_axes(mjson *j, const char *path, int li)
{
    char got[512], item[64], ipath[320];
    size_t at = 0;
    int n = 0, same = 1, naxes = cbf_machine_limit_axes[li];
    if (mj_kind(j) != '[')
        return mj_kind(j) ? mj_fail(j, path, "expected a list") : mj_syntax(j, "expected a value");
    j->i++;
    at += (size_t)snprintf(got, sizeof got, "[");
    if (mj_peek(j) != ']') {
        for (;;) {
            (void)snprintf(ipath, sizeof ipath, "%s[%d]", path, n);
            if (mj_kind(j) != '"')
                return mj_kind(j) ? mj_fail(j, ipath, "expected a string") : mj_syntax(j, "expected a value");
            if (!mj_string(j, item, sizeof item))
                return 0;
            if (n >= naxes || strcmp(item, cbf_machine_limit_axis_names[li][n]) != 0)
                same = 0;
            if (at < sizeof got)
                at += (size_t)snprintf(got + at, sizeof got - at, "%s\"%s\"", n ? ", " : "", item);
            n++;
            if (mj_peek(j) == ',') {
                j->i++;
                continue;
            }
            break;
        }
    }
    if (mj_peek(j) != ']')
        return mj_syntax(j, "expected ',' or ']'");
    j->i++;
    if (at < sizeof got)
        (void)snprintf(got + at, sizeof got - at, "]");
    if (!same || n != naxes) {
        char want[256];
        int k;
        size_t w = (size_t)snprintf(want, sizeof want, "[");
        for (k = 0; k < naxes; k++)
            w += (size_t)snprintf(want + w, sizeof want - w, "%s\"%s\"", k ? ", " : "", cbf_machine_limit_axis_names[li][k]);
        (void)snprintf(want + w, sizeof want - w, "]");
        return mj_fail(j, path, "must be %s, got %s", want, got);
    }
    return 1;
}

static int mj_limit_key(mjson *j, const char *path, const char *key, void *ctx)
{
    mj_limit *L = (mj_limit *)ctx;
    cbf_machine_range *r = &machine_file.limit[L->index];
    char kpath[256];
    unsigned k;
    for (k = 0; machine_limit_keys[k]; k++)
        if (strcmp(machine_limit_keys[k], key) == 0)
            break;
    if (!machine_limit_keys[k] || (strcmp(key, "axes") == 0 && !cbf_machine_limit_axes[L->index])) {
        const char *known[8];
        unsigned n = 0, q;
        for (q = 0; machine_limit_keys[q] && n < 7; q++)
            if (strcmp(machine_limit_keys[q], "axes") != 0 || cbf_machine_limit_axes[L->index])
                known[n++] = machine_limit_keys[q];
        known[n] = NULL;
        return mj_unknown(j, path, key, known, n);
    }
    (void)snprintf(kpath, sizeof kpath, "%s.%s", path, key);
    L->seen |= 1u << k;
    if (strcmp(key, "unit") == 0) {
        char unit[64];
        if (mj_kind(j) != '"')
            return mj_kind(j) ? mj_fail(j, kpath, "expected a string") : mj_syntax(j, "expected a value");
        if (!mj_string(j, unit, sizeof unit))
            return 0;
        if (strcmp(unit, cbf_machine_limit_units[L->index]) != 0)
            return mj_fail(j, kpath, "must be \"%s\", got \"%s\"", cbf_machine_limit_units[L->index], unit);
        return 1;
    }
    if (strcmp(key, "min") == 0)
        return mj_bound(j, kpath, L->index, r->min);
    if (strcmp(key, "max") == 0)
        return mj_bound(j, kpath, L->index, r->max);
    if (strcmp(key, "axes") == 0)
        return mj_axes(j, kpath, L->index);
    return mj_any_string(j, kpath);
}

static int mj_limits_key(mjson *j, const char *path, const char *key, void *ctx)
{
    unsigned *seen = (unsigned *)ctx;
    char kpath[256];
    mj_limit L;
    int li;
    for (li = 0; li < CBF_MACHINE__COUNT; li++)
        if (strcmp(cbf_machine_limit_names[li], key) == 0)
            break;
    if (li == CBF_MACHINE__COUNT)
        return mj_unknown(j, path, key, cbf_machine_limit_names, CBF_MACHINE__COUNT);
    (void)snprintf(kpath, sizeof kpath, "%s.%s", path, key);
    *seen |= 1u << li;
    L.index = li;
    L.seen = 0;
    if (!mj_object(j, kpath, mj_limit_key, &L))
        return 0;
    {
        static const char *const required[] = { "unit", "min", "max" };
        unsigned q, k;
        for (q = 0; q < 3; q++) {
            for (k = 0; machine_limit_keys[k]; k++)
                if (strcmp(machine_limit_keys[k], required[q]) == 0)
                    break;
            if (!(L.seen & (1u << k)))
                return mj_fail(j, kpath, "missing '%s'", required[q]);
        }
    }
    return 1;
}

static int mj_top_key(mjson *j, const char *path, const char *key, void *ctx)
{
    unsigned *seen = (unsigned *)ctx;
    char kpath[256];
    unsigned k;
    for (k = 0; machine_file_keys[k]; k++)
        if (strcmp(machine_file_keys[k], key) == 0)
            break;
    if (!machine_file_keys[k])
        return mj_unknown(j, path, key, machine_file_keys, sizeof machine_file_keys / sizeof *machine_file_keys);
    (void)snprintf(kpath, sizeof kpath, "%s.%s", path, key);
    if (strcmp(key, "limits") == 0) {
        unsigned lseen = 0;
        int li;
        seen[0] = 1;
        if (!mj_object(j, kpath, mj_limits_key, &lseen))
            return 0;
        for (li = 0; li < CBF_MACHINE__COUNT; li++)
            if (!(lseen & (1u << li)))
                return mj_fail(j, kpath, "missing '%s'", cbf_machine_limit_names[li]);
        return 1;
    }
    return mj_any_string(j, kpath);
}

/* A machine file (name: its file name, which says JSON or YAML; text[0..n): its bytes) into machine_file;
 * 0 with the one line in machine_why. */
static int machine_read(const char *path, mjson *j);

static int load_machine(const char *name, const char *text, size_t size)
{
    static char path[CBF_TOOL_NAME_BYTES]; /* the name as every message shows it (cbf_tool_name: the quoting rule) */
    char *mtext, *json = NULL;
    long n;
    mjson j;
    int ok;
    (void)snprintf(path, sizeof path, "%s", cbf_tool_name(name));
    n = opt_read(path, text, size, &mtext, OPT_MACHINE_MAX_BYTES, opt_machine_what);
    if (n < 0) {
        (void)snprintf(machine_why, sizeof machine_why, "%s", opt_why);
        return 0;
    }
    memset(&machine_file, 0, sizeof machine_file);
    j.s = mtext;
    j.n = (size_t)n;
    if (opt_is_yaml(name)) {
        /* the JSON text: at most 4 bytes a byte of YAML, and a few more (as the buffer of that size was) */
        ok = yj_translate(path, mtext, &json, 4u * OPT_MACHINE_MAX_BYTES + 64u, OPT_MACHINE_MAX_DEPTH);
        if (ok) {
            j.s = json;
            j.n = strlen(json);
        }
    } else {
        ok = opt_json_depth(path, mtext, (size_t)n, OPT_MACHINE_MAX_DEPTH);
    }
    if (!ok)
        (void)snprintf(machine_why, sizeof machine_why, "%s", opt_why);
    else
        ok = machine_read(path, &j);
    free(json);
    free(mtext);
    return ok;
}

/* The machine file's JSON text (j) into machine_file; 0 with the one line in machine_why. */
static int machine_read(const char *path, mjson *jp)
{
    mjson j = *jp;
    unsigned has_limits = 0;
    int li, a;
    j.i = 0;
    j.file = path;
    if (!mj_object(&j, "$", mj_top_key, &has_limits))
        return 0;
    if (mj_peek(&j) != -1)
        return mj_syntax(&j, "extra data");
    if (!has_limits)
        return mj_fail(&j, "$", "missing 'limits'");
    for (li = 0; li < CBF_MACHINE__COUNT; li++) {
        int naxes = cbf_machine_limit_axes[li];
        for (a = 0; a < (naxes ? naxes : 1); a++) {
            if (machine_file.limit[li].min[a] > machine_file.limit[li].max[a]) {
                char lpath[128];
                (void)snprintf(lpath, sizeof lpath, "$.limits.%s", cbf_machine_limit_names[li]);
                if (naxes)
                    return mj_fail(&j, lpath, "min exceeds max on axis %s", cbf_machine_limit_axis_names[li][a]);
                return mj_fail(&j, lpath, "min exceeds max");
            }
        }
    }
    return 1;
}

/* ---- the entry points (cbf_tools.h) ---- */
int cbf_tool_cutters_buffer(const char *name, const char *text, size_t n, cbf_options *opt)
{
    opt_last_why = opt_why;
    if (!load_cutters(name, text, n))
        return 0;
    opt->cutters = cutters;
    opt->ncutters = ncutters;
    return 1;
}

int cbf_tool_machine_buffer(const char *name, const char *text, size_t n, cbf_options *opt)
{
    opt_last_why = machine_why;
    if (!load_machine(name, text, n))
        return 0;
    opt->machine = &machine_file;
    return 1;
}

const char *cbf_tool_why(void) { return opt_last_why; }
/* ==== END tools/optfiles.c ==== */
#line 1927 "cbf_tools.h"
/* ==== BEGIN tools/files.c: verbatim from generator/cbfgen/emit/c/tools/files.c, edit it there ==== */
#line 1 "generator/cbfgen/emit/c/tools/files.c"
/* ---- the file layer: the only code of the tools that opens a file (cbf_tool.c's command line and the
 * testee read files through it; a page or any other host calls the *_buffer entry points instead) ---- */

/* The first byte of fp first (fopen opens a directory, whose size means nothing; reading it fails), then
 * its size where it can seek (*size; 0 where it cannot, or says 0). 0: fp rewound; or, unseekable, that
 * byte in buf[0] and *n = 1; or an empty file, fp at its end. -1: fp closed and *why ("file too large"
 * when its size is over cap). */
static int cbf_tool_size_first(FILE *fp, uint8_t *buf, size_t cap, size_t *n, size_t *size, const char **why)
{
    int first = fgetc(fp);
    long end;
    *size = 0;
    if (first == EOF) {
        int bad = ferror(fp), err = errno;
        if (!bad)
            return 0;
        fclose(fp);
        *why = err == EISDIR ? "is a directory" : "read error";
        return -1;
    }
    if (fseek(fp, 0L, SEEK_END) != 0) { /* not seekable: the byte read is the first of the input */
        clearerr(fp);
        if (cap == 0) {
            fclose(fp);
            *why = "file too large";
            return -1;
        }
        buf[0] = (uint8_t)first;
        *n = 1;
        return 0;
    }
    end = ftell(fp);
    if (end > 0 && (unsigned long)end > (unsigned long)cap) {
        fclose(fp);
        *why = "file too large";
        return -1;
    }
    if (fseek(fp, 0L, SEEK_SET) != 0) {
        fclose(fp);
        *why = "read error";
        return -1;
    }
    *size = end > 0 ? (size_t)end : 0u;
    return 0;
}

/* Why a file could not be opened, as cbf says it. */
static const char *cbf_tool_open_error(int err)
{
    return err == ENOENT ? "no such file" : err == EACCES ? "permission denied" : err == EISDIR ? "is a directory"
         : "cannot open";
}

#ifdef CBF_TOOLS_POSIX
/* What a file that is not a regular one is, as cbf says it (cbf.files.kind_of). */
static const char *cbf_tool_not_regular(mode_t mode)
{
    return S_ISDIR(mode) ? "is a directory" : S_ISFIFO(mode) ? "is a FIFO; only regular files are read"
         : S_ISCHR(mode) ? "is a character device; only regular files are read"
         : S_ISBLK(mode) ? "is a block device; only regular files are read"
         : S_ISSOCK(mode) ? "is a socket; only regular files are read"
         : "is not a regular file; only regular files are read";
}

/* Only a regular file is opened (issue #35): its status is looked at first, it is opened without blocking
 * (a FIFO named like a CBF file cannot hang the tool, a device is never read) and looked at again. */
static FILE *cbf_tool_open(const char *path, const char **why)
{
    struct stat st;
    int fd;
    FILE *fp;
    if (stat(path, &st) != 0) {
        *why = cbf_tool_open_error(errno);
        return NULL;
    }
    if (!S_ISREG(st.st_mode)) {
        *why = cbf_tool_not_regular(st.st_mode);
        return NULL;
    }
    fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY);
    if (fd < 0) {
        *why = cbf_tool_open_error(errno);
        return NULL;
    }
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) { /* the file opened is the file looked at */
        *why = cbf_tool_not_regular(st.st_mode);
        (void)close(fd);
        return NULL;
    }
    fp = fdopen(fd, "rb");
    if (!fp)
        (void)close(fd);
    return fp;
}
#else
/* Without POSIX (a host that defines no _POSIX_C_SOURCE): fopen, which cannot tell a FIFO apart. */
static FILE *cbf_tool_open(const char *path, const char **why)
{
    FILE *fp = fopen(path, "rb");
    if (!fp)
        *why = cbf_tool_open_error(errno);
    return fp;
}
#endif

/* The rest of fp into *bufp (room bytes; n read so far), at most cap bytes in all; fp closed. When grow,
 * *bufp is the heap's and grows (by doubling, to cap; room + 1 bytes allocated) when the file holds more
 * than room (a pipe, or a file longer than its size said); else room is cap. Its size, -2 ("file too
 * large") or -1 (*why: "read error", "is a directory", "out of memory"). */
static long cbf_tool_read_rest(FILE *fp, uint8_t **bufp, size_t room, size_t n, size_t cap, int grow,
                               const char **why)
{
    for (;;) {
        size_t got;
        if (n == room) { /* full: one more byte says whether the file ends here */
            int c = fgetc(fp);
            uint8_t *grown;
            if (c == EOF)
                break;
            if (!grow || room >= cap) {
                fclose(fp);
                *why = "file too large";
                return -2;
            }
            room = room >= cap / 2u ? cap : 2u * room + 1u;
            grown = (uint8_t *)realloc(*bufp, room + 1u);
            if (!grown) {
                fclose(fp);
                *why = "out of memory";
                return -1;
            }
            *bufp = grown;
            (*bufp)[n++] = (uint8_t)c;
        }
        got = fread(*bufp + n, 1, room - n, fp);
        n += got;
        if (got == 0 && n < room) /* the end, or an error; full: the test above */
            break;
    }
    if (ferror(fp)) {
        *why = errno == EISDIR ? "is a directory" : "read error"; /* fopen opens a directory; reading fails */
        fclose(fp);
        return -1;
    }
    fclose(fp);
    return (long)n;
}

/* Read a whole file into buf; returns its size, -2 ("file too large": over cap, from its size before
 * reading where it has one) or -1 (what went wrong in *why, as cbf says it). */
long cbf_tool_read_file(const char *path, uint8_t *buf, size_t cap, const char **why)
{
    FILE *fp;
    size_t n = 0, size;
    errno = 0;
    *why = "cannot open";
    fp = cbf_tool_open(path, why);
    if (!fp)
        return -1;
    /* A file larger than cap is refused from its size, unread (-2); where the size cannot be known
     * that way (a pipe), after cap bytes (issue 36). */
    if (cbf_tool_size_first(fp, buf, cap, &n, &size, why) < 0)
        return strcmp(*why, "file too large") == 0 ? -2 : -1;
    if (n == 0 && feof(fp)) {
        fclose(fp);
        return 0;
    }
    return cbf_tool_read_rest(fp, &buf, cap, n, cap, 0, why);
}

/* As cbf_tool_read_file, into a buffer of the heap sized to the file (its size + 1 where it has one;
 * grown to at most cap + 1 where it does not), *out; the caller frees it. Nothing in *out on failure. A
 * tool that held a buffer of cap bytes for every file made the WebAssembly module's initial memory
 * 24 MB, paid by every instance (bench/NOTES.md, round 5). */
static long cbf_tool_read_fp_alloc(FILE *fp, size_t cap, uint8_t **out, const char **why)
{
    uint8_t first[1];
    size_t n = 0, size, room;
    long got;
    uint8_t *buf;
    if (cbf_tool_size_first(fp, first, cap, &n, &size, why) < 0)
        return strcmp(*why, "file too large") == 0 ? -2 : -1;
    room = size ? size : cap < 4096u ? cap : 4096u;
    buf = (uint8_t *)malloc(room + 1u);
    if (!buf) {
        fclose(fp);
        *why = "out of memory";
        return -1;
    }
    if (n)
        buf[0] = first[0];
    if (n == 0 && feof(fp)) {
        fclose(fp);
        *out = buf;
        return 0;
    }
    got = cbf_tool_read_rest(fp, &buf, room, n, cap, 1, why);
    if (got < 0)
        free(buf);
    else
        *out = buf;
    return got;
}

long cbf_tool_read_file_alloc(const char *path, size_t cap, uint8_t **out, const char **why)
{
    FILE *fp;
    *out = NULL;
    errno = 0;
    *why = "cannot open";
    fp = cbf_tool_open(path, why);
    return fp ? cbf_tool_read_fp_alloc(fp, cap, out, why) : -1;
}

long cbf_tool_read_input_alloc(const char *path, size_t cap, uint8_t **out, const char **why)
{
    if (strcmp(path, "-") != 0)
        return cbf_tool_read_file_alloc(path, cap, out, why);
    *out = NULL;
    errno = 0;
    return cbf_tool_read_fp_alloc(stdin, cap, out, why);
}

/* An option file read whole into *text (the heap's; at most max bytes), or 0 with the one line in opt_why. */
static int opt_file(const char *path, size_t max, const char *what, char **text, size_t *n)
{
    const char *why;
    uint8_t *buf;
    long got = cbf_tool_read_file_alloc(path, max, &buf, &why);
    if (got < 0) {
        if (strcmp(why, "file too large") == 0)
            (void)opt_too_large(cbf_tool_name(path), max, what);
        else
            (void)opt_fail("%s: cannot read %s (%s)", cbf_tool_name(path), what, why);
        return 0;
    }
    *text = (char *)buf;
    *n = (size_t)got;
    return 1;
}

int cbf_tool_cutters_file(const char *path, cbf_options *opt)
{
    size_t n;
    char *text;
    int ok;
    opt_last_why = opt_why;
    if (!opt_file(path, OPT_CUTTER_MAX_BYTES, opt_cutter_what, &text, &n))
        return 0;
    ok = cbf_tool_cutters_buffer(path, text, n, opt);
    free(text);
    return ok;
}

int cbf_tool_machine_file(const char *path, cbf_options *opt)
{
    size_t n;
    char *text;
    int ok;
    if (!opt_file(path, OPT_MACHINE_MAX_BYTES, opt_machine_what, &text, &n)) {
        (void)snprintf(machine_why, sizeof machine_why, "%s", opt_why);
        opt_last_why = machine_why;
        return 0;
    }
    ok = cbf_tool_machine_buffer(path, text, n, opt);
    free(text);
    return ok;
}

/* ---- the output: the one writer of the tools (cbf-c encode -o), as cbf writes (cli.py, _write) ---- */

/* why[0..cap) = "NAME: what" (NAME by the quoting rule). */
static int cbf_tool_out_fail(char *why, size_t cap, const char *path, const char *what, const char *detail)
{
    (void)snprintf(why, cap, "%s: %s%s%s%s", strcmp(path, "-") == 0 ? "standard output" : cbf_tool_name(path), what,
                   detail ? " (" : "", detail ? detail : "", detail ? ")" : "");
    return 0;
}

/* POSIX (not WASI, which has no mkstemp, no modes and no temporary names of its own): the atomic writer. */
#if defined(CBF_TOOLS_POSIX) && !defined(__wasi__)
/* Every byte of data[0..n) to fd: a short write goes on from where it stopped, a write that takes nothing
 * is a full disk (never a short output). 0, or -1 with errno. */
static int cbf_tool_write_all(int fd, const uint8_t *data, size_t n)
{
    while (n) {
        ssize_t w = write(fd, data, n > (1u << 20) ? (size_t)(1u << 20) : n);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0) {
            if (w == 0)
                errno = ENOSPC;
            return -1;
        }
        data += w;
        n -= (size_t)w;
    }
    return 0;
}

/* A copy of s of the heap (NULL without memory). */
static char *cbf_tool_dup(const char *s, size_t n)
{
    char *d = (char *)malloc(n + 1u);
    if (d) {
        (void)memcpy(d, s, n);
        d[n] = '\0';
    }
    return d;
}

/* path with a symlink at its end followed to its final target (readlink, at most 40 links; a relative link
 * read from the link's folder): the temporary file goes beside that target, and the link stays a link. Of
 * the heap; NULL without memory. */
static char *cbf_tool_follow(const char *path)
{
    char *cur = cbf_tool_dup(path, strlen(path));
    int hops;
    for (hops = 0; cur && hops < 40; hops++) {
        struct stat st;
        const char *slash;
        char *link, *next;
        size_t cap, dn;
        ssize_t k;
        if (lstat(cur, &st) != 0 || !S_ISLNK(st.st_mode))
            break;
        cap = st.st_size > 0 ? (size_t)st.st_size + 1u : 4096u;
        link = (char *)malloc(cap);
        k = link ? readlink(cur, link, cap) : -1;
        if (k < 0 || (size_t)k >= cap) {
            free(link);
            break;
        }
        slash = strrchr(cur, '/');
        dn = link[0] == '/' || !slash ? 0u : (size_t)(slash - cur) + 1u;
        next = (char *)malloc(dn + (size_t)k + 1u);
        if (next) {
            (void)memcpy(next, cur, dn);
            (void)memcpy(next + dn, link, (size_t)k);
            next[dn + (size_t)k] = '\0';
        }
        free(link);
        free(cur);
        cur = next;
    }
    return cur;
}

/* Where "-o path" writes: the final target of a symlink (*target of the heap), its folder (*dir of the
 * heap; "." for none) and its name (*base, in *target). 0, or -1 when memory runs out. */
static int cbf_tool_out_where(const char *path, char **target, char **dir, const char **base)
{
    const char *slash;
    *dir = NULL;
    *target = cbf_tool_follow(path);
    if (!*target)
        return -1;
    slash = strrchr(*target, '/');
    *base = slash ? slash + 1 : *target;
    *dir = !slash ? cbf_tool_dup(".", 1u) : cbf_tool_dup(*target, slash == *target ? 1u : (size_t)(slash - *target));
    return *dir ? 0 : -1;
}

/* What a target of "-o" that is not a regular file, a character device or a FIFO is. */
static const char *cbf_tool_unwritable_kind(mode_t mode)
{
    return S_ISDIR(mode) ? NULL : S_ISREG(mode) || S_ISCHR(mode) || S_ISFIFO(mode) ? ""
         : S_ISBLK(mode) ? "a block device" : S_ISSOCK(mode) ? "a socket" : "not a regular file";
}

/* cbf_tool_check_output, and the target's status when it exists (*exists). */
static int cbf_tool_check_target(const char *path, const char *target, const char *dir, struct stat *st, int *exists,
                                 char *why, size_t cap)
{
    struct stat ds;
    char what[96];
    const char *kind;
    *exists = 0;
    if (stat(target, st) != 0) {
        if (errno != ENOENT)
            return cbf_tool_out_fail(why, cap, path, "cannot write", strerror(errno));
        if (stat(dir, &ds) != 0 || !S_ISDIR(ds.st_mode)) { /* the folder from the root, as cbf names it */
            char cwd[4096];
            int rel = dir[0] != '/' && getcwd(cwd, sizeof cwd) != NULL;
            size_t dn = strlen(dir), cn = rel ? strlen(cwd) : 0u;
            char *full = (char *)malloc(cn + dn + 2u);
            if (full && rel && strcmp(dir, ".") == 0)
                (void)memcpy(full, cwd, cn + 1u);
            else if (full)
                (void)sprintf(full, "%s%s%s", rel ? cwd : "", rel && cn > 1u ? "/" : "", dir);
            (void)snprintf(why, cap, "%s: folder %s does not exist", cbf_tool_name(path),
                           cbf_quoted(full ? full : dir, CBF_QUOTE_NAME));
            free(full);
            return 0;
        }
        return 1;
    }
    *exists = 1;
    kind = cbf_tool_unwritable_kind(st->st_mode);
    if (!kind)
        return cbf_tool_out_fail(why, cap, path, "is a directory", NULL);
    if (*kind) {
        (void)snprintf(what, sizeof what, "is %s; cbf-c writes regular files, character devices and FIFOs only", kind);
        return cbf_tool_out_fail(why, cap, path, what, NULL);
    }
    return 1;
}

int cbf_tool_check_output(const char *path, char *why, size_t cap)
{
    char *target, *dir;
    const char *base;
    struct stat st;
    int exists, ok;
    if (strcmp(path, "-") == 0)
        return 1;
    if (cbf_tool_out_where(path, &target, &dir, &base) != 0)
        ok = cbf_tool_out_fail(why, cap, path, "cannot write", "out of memory");
    else
        ok = cbf_tool_check_target(path, target, dir, &st, &exists, why, cap);
    free(target);
    free(dir);
    return ok;
}

/* Standard output: every byte written (a stdio buffer flushed first); what went to a regular file there is
 * cut off again when it fails: nothing that looks complete stays. */
static int cbf_tool_write_stdout(const uint8_t *data, size_t n, char *why, size_t cap)
{
    struct stat st;
    off_t start = -1;
    int err;
    if (fflush(stdout) != 0)
        return cbf_tool_out_fail(why, cap, "-", "cannot write", strerror(errno));
    if (fstat(1, &st) == 0 && S_ISREG(st.st_mode))
        start = lseek(1, 0, SEEK_CUR);
    if (cbf_tool_write_all(1, data, n) == 0)
        return 1;
    err = errno;
    if (start >= 0 && ftruncate(1, start) != 0)
        start = -1; /* cut off as far as it could be: the failure said is the write's */
    return cbf_tool_out_fail(why, cap, "-", "cannot write", strerror(err));
}

/* The most bytes a file name in dir may have (NAME_MAX there; 255 where it cannot be asked). */
static size_t cbf_tool_name_max(const char *dir)
{
    long m = pathconf(dir, _PC_NAME_MAX);
    return m > 0 ? (size_t)m : 255u;
}

int cbf_tool_write_file(const char *path, const uint8_t *data, size_t n, char *why, size_t cap)
{
    static const char suffix[] = ".XXXXXX"; /* mkstemp's */
    char *target = NULL, *dir = NULL, *tmp = NULL;
    const char *base;
    struct stat st;
    int exists, fd = -1, ok = 0, err = 0;
    size_t room, bn;
    if (strcmp(path, "-") == 0)
        return cbf_tool_write_stdout(data, n, why, cap);
    if (cbf_tool_out_where(path, &target, &dir, &base) != 0) {
        ok = cbf_tool_out_fail(why, cap, path, "cannot write", "out of memory");
        goto done;
    }
    if (!cbf_tool_check_target(path, target, dir, &st, &exists, why, cap))
        goto done;
    if (exists && !S_ISREG(st.st_mode)) { /* a character device or a FIFO, written straight, never replaced */
        fd = open(target, O_WRONLY | O_NOCTTY);
        if (fd < 0 || cbf_tool_write_all(fd, data, n) != 0)
            err = errno;
        if (fd >= 0 && close(fd) != 0 && !err)
            err = errno;
        ok = err ? cbf_tool_out_fail(why, cap, path, "cannot write", strerror(err)) : 1;
        goto done;
    }
    /* ".NAME.XXXXXX" beside the target, NAME cut so that it fits NAME_MAX whenever the target's name does */
    bn = strlen(base);
    room = cbf_tool_name_max(dir);
    room = room > sizeof suffix + 1u ? room - (sizeof suffix - 1u) - 2u : 1u;
    if (bn > room)
        bn = room;
    tmp = (char *)malloc(strlen(dir) + bn + sizeof suffix + 4u);
    if (!tmp) {
        ok = cbf_tool_out_fail(why, cap, path, "cannot write", "out of memory");
        goto done;
    }
    (void)sprintf(tmp, "%s/.%.*s.%s", dir, (int)bn, base, suffix + 1);
    fd = mkstemp(tmp);
    if (fd < 0) {
        ok = cbf_tool_out_fail(why, cap, path, "cannot write", strerror(errno));
        goto done;
    }
    { /* mkstemp makes 0600: an ordinary file's mode (0666 under the umask), as cbf gives it */
        mode_t mask = umask(0);
        (void)umask(mask);
        if (fchmod(fd, (mode_t)(0666u & ~(unsigned)mask)) != 0)
            err = errno;
    }
    if (!err && (cbf_tool_write_all(fd, data, n) != 0 || fsync(fd) != 0))
        err = errno;
    if (close(fd) != 0 && !err)
        err = errno;
    if (!err && rename(tmp, target) != 0)
        err = errno;
    if (err) {
        (void)unlink(tmp); /* nothing of a failed write stays, and the target is as it was */
        ok = cbf_tool_out_fail(why, cap, path, "cannot write", strerror(err));
    } else
        ok = 1;
done:
    free(tmp);
    free(target);
    free(dir);
    return ok;
}
#elif defined(__wasi__)
/* WASI (cbf-c.wasm, run by the workbench page and node's WASI): standard output only, written and flushed;
 * writing a file would need imports the page's WASI has not (rename, unlink), and the page reads -o -. */
int cbf_tool_check_output(const char *path, char *why, size_t cap)
{
    if (strcmp(path, "-") == 0)
        return 1;
    return cbf_tool_out_fail(why, cap, path, "cannot write", "cbf-c.wasm writes to standard output only: -o -");
}

int cbf_tool_write_file(const char *path, const uint8_t *data, size_t n, char *why, size_t cap)
{
    if (!cbf_tool_check_output(path, why, cap))
        return 0;
    if (fwrite(data, 1, n, stdout) != n || fflush(stdout) != 0)
        return cbf_tool_out_fail(why, cap, path, "cannot write", strerror(errno));
    return 1;
}
#else
/* Without POSIX: a file beside the target ("NAME.tmp"), written whole, closed, then renamed over it;
 * standard output written and flushed. */
int cbf_tool_check_output(const char *path, char *why, size_t cap)
{
    (void)path;
    (void)why;
    (void)cap;
    return 1;
}

int cbf_tool_write_file(const char *path, const uint8_t *data, size_t n, char *why, size_t cap)
{
    FILE *fp;
    char *tmp;
    int bad;
    if (strcmp(path, "-") == 0) {
        if (fwrite(data, 1, n, stdout) != n || fflush(stdout) != 0)
            return cbf_tool_out_fail(why, cap, path, "cannot write", strerror(errno));
        return 1;
    }
    tmp = (char *)malloc(strlen(path) + 5u);
    if (!tmp)
        return cbf_tool_out_fail(why, cap, path, "cannot write", "out of memory");
    (void)sprintf(tmp, "%s.tmp", path);
    fp = fopen(tmp, "wb");
    bad = !fp || fwrite(data, 1, n, fp) != n;
    if (fp && fclose(fp) != 0)
        bad = 1;
    if (!bad && rename(tmp, path) != 0)
        bad = 1;
    if (bad) {
        int err = errno;
        (void)remove(tmp);
        free(tmp);
        return cbf_tool_out_fail(why, cap, path, "cannot write", strerror(err));
    }
    free(tmp);
    return 1;
}
#endif
/* ==== END tools/files.c ==== */
#line 2506 "cbf_tools.h"
/* ==== BEGIN tools/engine.c: verbatim from generator/cbfgen/emit/c/tools/engine.c, edit it there ==== */
#line 1 "generator/cbfgen/emit/c/tools/engine.c"
/* ---- cbf-c's engine on a buffer: frame, validate with options, dump (README, "Exit codes") ----
 * Every function here works on bytes in memory and prints through the sink; the command line (cbf_tool.c)
 * and any other host (a page, a test) are shells over it. */

typedef struct held_finding {
    long record;   /* -1: the header and the file */
    int order;     /* index in cbf_tool_check_order */
    int error;
    unsigned long offset;
    const char *check;
    char *message; /* a copy: the engine's is valid during the callback only */
} held_finding;

static held_finding *held;
static size_t nheld, capheld;
static int out_of_memory;

static int check_rank(const char *id)
{
    int i;
    for (i = 0; i < CBF_CHECK__COUNT; i++)
        if (strcmp(cbf_tool_check_order[i], id) == 0)
            return i;
    return 0; /* as cbf's finding_order: an id the spec lacks sorts first */
}

/* Keep each finding; they print sorted, after the file is validated. */
static void hold_finding(void *user, const cbf_finding *f)
{
    held_finding *h;
    size_t len = strlen(f->message) + 1;
    (void)user;
    if (nheld == capheld) {
        size_t cap = capheld ? 2 * capheld : 64;
        held_finding *grown = (held_finding *)realloc(held, cap * sizeof *held);
        if (!grown) {
            out_of_memory = 1;
            return;
        }
        held = grown;
        capheld = cap;
    }
    h = &held[nheld];
    h->message = (char *)malloc(len);
    if (!h->message) {
        out_of_memory = 1;
        return;
    }
    memcpy(h->message, f->message, len);
    h->record = f->record;
    h->order = check_rank(f->check);
    h->error = f->severity == CBF_SEVERITY_ERROR;
    h->offset = (unsigned long)f->offset;
    h->check = f->check;
    nheld++;
}

static int finding_cmp(const void *pa, const void *pb)
{
    const held_finding *a = (const held_finding *)pa, *b = (const held_finding *)pb;
    if (a->record != b->record)
        return a->record < b->record ? -1 : 1;
    if (a->order != b->order)
        return a->order < b->order ? -1 : 1;
    if (a->offset != b->offset)
        return a->offset < b->offset ? -1 : 1;
    return strcmp(a->message, b->message);
}

/* One line per finding, as cbf prints it (README): file:offset: severity check (record N): message */
static void print_finding(const char *file, const held_finding *f)
{
    out_printf("%s:%lu: %s %s (", file, f->offset, f->error ? "error" : "warning", f->check);
    if (f->record >= 0)
        out_printf("record %ld", f->record);
    else
        out_str("header");
    out_printf("): %s\n", cbf_quoted(f->message, CBF_QUOTE_TEXT));
}

/* Whether the header's magic numbers are all wrong (cbf's test, from the same fields of the model);
 * the one line that says so on the error output. */
static int frame_magic(const char *file, const uint8_t *buf, size_t n)
{
    const cbf_field_info *fields;
    size_t nf, i, nmagic = 0, nright = 0, first = 0;
    int text = 1;
    nf = cbf_header_fields(cbf_version_header_layout(CBF_DEFAULT_VERSION), &fields);
    for (i = 0; i < nf; i++) {
        if (!(fields[i].flags & CBF_FIELD_MAGIC))
            continue;
        if (!nmagic++)
            first = i;
        if (cbf_field_uint(&fields[i], buf) == fields[i].magic)
            nright++;
    }
    if (!nmagic || nright)
        return 1;
    for (i = 0; i < n && i < 256u && text; i++)
        text = (buf[i] >= 0x20u && buf[i] < 0x7Fu) || buf[i] == '\t' || buf[i] == '\r' || buf[i] == '\n';
    out_flush();
    {
        char names[1024];
        size_t at = 0;
        names[0] = 0;
        for (i = 0; i < nf; i++)
            if ((fields[i].flags & CBF_FIELD_MAGIC) && at < sizeof names)
                at += (size_t)snprintf(names + at, sizeof names - at, "%s%s", i == first ? "" : ", ", fields[i].name);
        err_printf("cbf-c: %s: offset %u: not a CBF file: no magic number of the header is right (%s)%s\n", file,
                   (unsigned)fields[first].offset, names, text ? "; it is text" : "");
    }
    return 0;
}

/* 1 when buf[0..n) can be read as a CBF file; else 0 and one line on the error output: larger than a
 * CBF file can be, shorter than the header, or every magic number of the header wrong. */
static int frame(const char *file, const uint8_t *buf, size_t n)
{
    if (n > CBF_TOOL_MAX_FILE_SIZE) {
        err_printf("cbf-c: %s: larger than %lu bytes, the most a CBF file can hold\n", file,
                   (unsigned long)CBF_TOOL_MAX_FILE_SIZE);
        return 0;
    }
    if (n < CBF_HEADER_SIZE) {
        err_printf("cbf-c: %s: offset 0: file is %ld bytes, the header needs %d: not a CBF file\n", file, (long)n,
                   CBF_HEADER_SIZE);
        return 0;
    }
    return frame_magic(file, buf, n);
}

/* One of the tool's operations on a buffer, its output to sink (the buffer entry points below). */
static int on_buffer(int (*op)(const char *, const uint8_t *, size_t), const char *name, const uint8_t *buf, size_t n,
                     const cbf_tool_sink *sink)
{
    int status;
    out_begin(sink);
    status = op(cbf_tool_name(name), buf, n);
    out_flush();
    return status;
}

int cbf_tool_frame_buffer(const char *name, const uint8_t *buf, size_t n, const cbf_tool_sink *sink)
{
    return on_buffer(frame, name, buf, n, sink);
}

/* The findings held, sorted, at most max of them (0: all), and the summary line; frees them. */
static void print_findings(const char *file, long errors, const cbf_tool_options *o)
{
    size_t k, max = o->max_findings;
    if (nheld) /* held is NULL before the first finding: qsort's pointer must not be (UBSan) */
        qsort(held, nheld, sizeof *held, finding_cmp);
    for (k = 0; k < nheld; k++) {
        if (max == 0 || k < max)
            print_finding(file, &held[k]);
        free(held[k].message);
    }
    if (max && nheld > max)
        out_printf("%s: %lu more finding(s) not shown (--max-findings 0 prints all)\n", file,
                   (unsigned long)(nheld - max));
    out_printf("%s: %s: %ld error(s), %ld warning(s) [profile %s]\n", file, errors > 0 ? "FAIL" : "ok", errors,
               (long)nheld - errors, cbf_tool_profile_names[o->validate.profile]);
}

int cbf_tool_validate_buffer(const char *name, const uint8_t *buf, size_t n, const cbf_tool_options *o,
                             const cbf_tool_sink *sink)
{
    const char *file = cbf_tool_name(name);
    long errors;
    int status = CBF_TOOL_EXIT_OK;
    out_begin(sink);
    if (o->validate.profile < 0 || o->validate.profile >= CBF_PROFILE__COUNT) {
        err_printf("cbf-c: %s: no such profile\n", file);
        return CBF_TOOL_EXIT_USAGE;
    }
    if (!frame(file, buf, n))
        return CBF_TOOL_EXIT_USAGE;
    nheld = 0;
    out_of_memory = 0;
    errors = cbf_validate(buf, n, &o->validate, hold_finding, NULL);
    if (out_of_memory) {
        size_t k;
        for (k = 0; k < nheld; k++)
            free(held[k].message);
        err_printf("cbf-c: %s: out of memory holding its findings\n", file);
        return CBF_TOOL_OUT_OF_MEMORY;
    }
    if (errors > 0)
        status = CBF_TOOL_EXIT_FINDINGS;
    print_findings(file, errors, o);
    out_flush();
    return status;
}

/* An integer field, exact at every registered width and signedness (from its bits). */
static void dump_int(const cbf_field_info *f, const uint8_t *base)
{
    uint64_t u = cbf_field_bits(f, base, 0);
    unsigned bits = 8u * f->elem;
    char d[24];
    size_t n = 0;
    if (f->kind == CBF_KIND_SINT && ((u >> (bits - 1u)) & 1u)) {
        out_char('-');
        u = (bits < 64u ? ((uint64_t)1 << bits) : (uint64_t)0) - u;
    }
    do {
        d[n++] = (char)('0' + (int)(u % 10u));
        u /= 10u;
    } while (u);
    while (n)
        out_char(d[--n]);
}

static void dump_string(const cbf_field_info *f, const uint8_t *base, size_t size)
{
    size_t i;
    out_char('"');
    for (i = 0; i < size && base[f->offset + i] != CBF_TOOL_PAD; i++) {
        unsigned c = base[f->offset + i];
        if (c >= 0x20u && c < 0x7Fu && c != '"' && c != '\\')
            out_char((char)c);
        else
            out_printf("\\x%02x", c);
    }
    out_char('"');
}

static void dump_hex(const uint8_t *p, size_t n)
{
    static const char digits[] = "0123456789abcdef";
    size_t i;
    for (i = 0; i < n; i++) {
        out_char(digits[p[i] >> 4]);
        out_char(digits[p[i] & 15u]);
    }
}

static void dump_field(const cbf_field_info *f, const uint8_t *base)
{
    size_t size = (size_t)f->elem * f->count, i;
    out_char(' ');
    out_str(f->name);
    out_char('=');
    switch ((enum cbf_field_kind)f->kind) {
    case CBF_KIND_UINT:
    case CBF_KIND_SINT:
        dump_int(f, base);
        break;
    case CBF_KIND_FLOAT:
        for (i = 0; i < f->count; i++)
            out_printf("%s%.9g", i ? "," : "", (double)cbf_field_float(f, base, (unsigned)i));
        if (f->unit)
            out_str(f->unit);
        break;
    case CBF_KIND_STRING:
        dump_string(f, base, size);
        break;
    case CBF_KIND_BYTES:
        dump_hex(base + f->offset, size);
        break;
    }
}

/* A repeated argument group (issue 25, point 3): each of its n items as a field, name[i]=value. */
static void dump_group(const cbf_field_info *f, const uint8_t *base, size_t n, size_t item)
{
    cbf_field_info one = *f;
    char name[160];
    size_t k;
    one.name = name;
    for (k = 0; k < n; k++) {
        (void)snprintf(name, sizeof name, "%s[%lu]", f->name, (unsigned long)k);
        dump_field(&one, base);
        one.offset = (unsigned short)(one.offset + item);
    }
}

static void dump_header(const cbf_reader *r, const uint8_t *buf)
{
    const cbf_field_info *fields;
    size_t nf, i;
    out_printf("header version %u.%u (%s)", r->header.major, r->header.minor,
               r->header.version < 0 ? "unknown" : cbf_version_name(r->header.version));
    nf = cbf_header_fields(r->header.layout, &fields);
    for (i = 0; i < nf; i++)
        dump_field(&fields[i], buf);
    out_char('\n');
}

static void dump_record(const cbf_record *rec, const uint8_t *buf)
{
    const cbf_field_info *fields;
    size_t nf, i;
    const char *name = cbf_command_name(rec->command);
    out_printf("%lu @%lu %s", (unsigned long)rec->index, (unsigned long)rec->offset, name ? name : "?");
    nf = cbf_record_fields(&fields);
    for (i = 0; i < nf; i++)
        dump_field(&fields[i], buf + rec->offset);
    if (rec->layout != CBF_LAYOUT__NONE) {
        size_t item = 0;
        const long group = cbf_layout_group(rec->layout, NULL, NULL, &item);
        nf = cbf_layout_fields(rec->layout, &fields);
        out_str(" |");
        for (i = 0; i < nf; i++) {
            if ((long)i == group)
                dump_group(&fields[i], rec->args, (size_t)cbf_layout_items(rec->layout, rec->nargs), item);
            else
                dump_field(&fields[i], rec->args);
        }
    } else {
        out_str(" | raw=");
        dump_hex(rec->args, rec->nargs);
    }
    out_char('\n');
}

/* 1 when every record of the file frames (r then reads it from its first record); else 0 and one line
 * on stderr. The records are framed first, as cbf decodes before it prints: a cut record is one line. */
static int records_framed(const char *file, const uint8_t *buf, size_t n, cbf_reader *r)
{
    cbf_record rec;
    int rc;
    if (!frame(file, buf, n))
        return 0;
    if (cbf_reader_init(r, buf, n) != CBF_OK)
        return 0; /* frame refused a short file already */
    while ((rc = cbf_next_record(r, &rec)) == 1) {}
    if (rc < 0) {
        err_printf("cbf-c: %s: offset %lu: record %lu is cut: %lu byte(s) left, the header counts %lu record(s) (%s)\n",
                   file, (unsigned long)r->pos, (unsigned long)r->index, (unsigned long)(n - r->pos),
                   (unsigned long)r->header.count, cbf_strerror(rc));
        return 0;
    }
    (void)cbf_reader_init(r, buf, n);
    return 1;
}

static int dump(const char *file, const uint8_t *buf, size_t n)
{
    cbf_reader r;
    cbf_record rec;
    int rc;
    if (!records_framed(file, buf, n, &r))
        return CBF_TOOL_EXIT_USAGE;
    dump_header(&r, buf);
    while ((rc = cbf_next_record(&r, &rec)) == 1)
        dump_record(&rec, buf);
    if (r.trailing)
        out_printf("trailing %lu byte(s) at %lu\n", (unsigned long)r.trailing, (unsigned long)r.pos);
    return CBF_TOOL_EXIT_OK;
}

int cbf_tool_dump_buffer(const char *name, const uint8_t *buf, size_t n, const cbf_tool_sink *sink)
{
    return on_buffer(dump, name, buf, n, sink);
}

/* cbf-c dump --path: each motion record's drawn path (cbf_motion_path), one line a record,
 * INDEX x,y,z x,y,z ...; a point motion starts where the motion before it ended (as cbf.geometry's
 * walk: none after a motion of no path). */
static int dump_path(const char *file, const uint8_t *buf, size_t n)
{
    static double pts[CBF_PATH_MAX_POINTS][3];
    double last[3];
    int have = 0;
    cbf_reader r;
    cbf_record rec;
    if (!records_framed(file, buf, n, &r))
        return CBF_TOOL_EXIT_USAGE;
    while (cbf_next_record(&r, &rec) == 1) {
        size_t k, np = cbf_motion_path(rec.layout, rec.args, rec.nargs, have ? last : NULL, pts);
        if (np == 0) {
            have = have && !cbf_layout_moves(rec.layout); /* a motion of no path: no position after it */
            continue;
        }
        out_printf("%lu", (unsigned long)rec.index);
        for (k = 0; k < np; k++)
            out_printf(" %.9g,%.9g,%.9g", pts[k][0], pts[k][1], pts[k][2]);
        out_char('\n');
        for (k = 0; k < 3u; k++)
            last[k] = pts[np - 1u][k];
        have = 1;
    }
    return CBF_TOOL_EXIT_OK;
}

int cbf_tool_path_buffer(const char *name, const uint8_t *buf, size_t n, const cbf_tool_sink *sink)
{
    return on_buffer(dump_path, name, buf, n, sink);
}

/* ---- CUT text (issue 34: a dropped CUT file is shown as the CBF it encodes to) ---- */

/* Whether buf[0..n) is text to read as CUT rather than a CBF file: no magic number of the header is right
 * (or it is shorter than the header) and its first 256 bytes are text, frame_magic's test of text. */
int cbf_tool_is_cut(const uint8_t *buf, size_t n)
{
    const cbf_field_info *fields;
    size_t nf, i;
    if (n == 0)
        return 0;
    if (n >= CBF_HEADER_SIZE) {
        nf = cbf_header_fields(cbf_version_header_layout(CBF_DEFAULT_VERSION), &fields);
        for (i = 0; i < nf; i++)
            if ((fields[i].flags & CBF_FIELD_MAGIC) && cbf_field_uint(&fields[i], buf) == fields[i].magic)
                return 0;
    }
    for (i = 0; i < n && i < 256u; i++)
        if (!((buf[i] >= 0x20u && buf[i] < 0x7Fu) || buf[i] == '\t' || buf[i] == '\r' || buf[i] == '\n'))
            return 0;
    return 1;
}

long cbf_tool_cut_buffer(const char *name, const uint8_t *text, size_t n, int version, int profile, uint8_t **out,
                         const cbf_tool_sink *sink)
{
    const char *file = cbf_tool_name(name);
    size_t cap = (size_t)CBF_HEADER_SIZE + 8u * n + 256u;
    cbf_cut_error err;
    long len = CBF_ERR_BUFFER;
    *out = NULL;
    out_begin(sink);
    if (n > CBF_TOOL_MAX_CUT_SIZE) {
        err_printf("cbf-c: %s: larger than %lu bytes, the most the text of a CBF file can hold\n", file,
                   (unsigned long)CBF_TOOL_MAX_CUT_SIZE);
        return -1;
    }
    if (cap > CBF_TOOL_MAX_FILE_SIZE || cap < n)
        cap = CBF_TOOL_MAX_FILE_SIZE;
    while (len == CBF_ERR_BUFFER) { /* a first guess from the text's size, then room for the largest file */
        free(*out);
        *out = (uint8_t *)malloc(cap);
        if (!*out) {
            err_printf("cbf-c: %s: out of memory for the CBF it encodes to\n", file);
            return -1;
        }
        len = cbf_cut_encode_as((const char *)text, n, version, profile, *out, cap, &err);
        if (len == CBF_ERR_BUFFER && cap == CBF_TOOL_MAX_FILE_SIZE)
            break;
        cap = CBF_TOOL_MAX_FILE_SIZE;
    }
    if (len < 0) {
        free(*out);
        *out = NULL;
        if (len != CBF_ERR_SYNTAX)
            err_printf("cbf-c: %s: the text does not encode (%s)\n", file, cbf_strerror((int)len));
        else if (err.line && err.column)
            err_printf("cbf-c: %s: line %lu, column %lu: %s\n", file, err.line, err.column, err.message);
        else if (err.line)
            err_printf("cbf-c: %s: line %lu: %s\n", file, err.line, err.message);
        else
            err_printf("cbf-c: %s: %s\n", file, err.message);
        return -1;
    }
    return len;
}

/* ---- cbf encode's judgement of the file it made, and its warnings (cli.py: _encode_one, writer.encode,
 * _cut_line_of, _warn_deprecated). Both are driven by the checks' kinds (cbf_tool_check_kinds): no
 * command or check is named here. ---- */

/* Whether cbf encode refuses a result with this finding: an error, or a finding of a check of kind
 * string_ascii (a writer writes strings in ASCII, N4). */
static int refuses(const cbf_finding *f, int order)
{
    return f->severity == CBF_SEVERITY_ERROR || strcmp(cbf_tool_check_kinds[order], "string_ascii") == 0;
}

static held_finding refusal; /* the first refusing finding in cbf's order (finding_cmp) */
static int refused;

/* f as a held finding of rank order, its message borrowed (compared only: kept_message copies it). */
static held_finding borrowed(const cbf_finding *f, int order)
{
    held_finding h;
    h.order = order;
    h.record = f->record;
    h.error = f->severity == CBF_SEVERITY_ERROR;
    h.offset = (unsigned long)f->offset;
    h.check = f->check;
    h.message = (char *)(uintptr_t)f->message;
    return h;
}

/* A copy of f's message to keep past the callback; NULL (out_of_memory set) when none can be made. */
static char *kept_message(const cbf_finding *f)
{
    size_t len = strlen(f->message) + 1u;
    char *copy = (char *)malloc(len);
    if (!copy) {
        out_of_memory = 1;
        return NULL;
    }
    memcpy(copy, f->message, len);
    return copy;
}

static void keep_refusal(void *user, const cbf_finding *f)
{
    held_finding h;
    char *copy;
    (void)user;
    h = borrowed(f, check_rank(f->check));
    if (!refuses(f, h.order))
        return;
    if (refused && finding_cmp(&h, &refusal) >= 0)
        return;
    if (!(copy = kept_message(f)))
        return;
    free(refusal.message);
    refusal = h;
    refusal.message = copy;
    refused = 1;
}

static int word_byte(unsigned char c)
{
    return (c >= '0' && c <= '9') || (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_' || c >= 0x80u;
}

/* The CUT line of the record what cbf says names ("record N", the first such word: cbf's _cut_line_of),
 * 0 when it names none or the text holds no such record. */
static unsigned long said_record_line(const char *said, const uint8_t *text, size_t n)
{
    static const char word[] = "record ";
    const char *p;
    for (p = strstr(said, word); p; p = strstr(p + 1, word)) {
        const char *d = p + sizeof word - 1u;
        unsigned long want = 0;
        size_t k = 0;
        int big = 0;
        if (p > said && word_byte((unsigned char)p[-1]))
            continue;
        for (; d[k] >= '0' && d[k] <= '9'; k++) {
            if (want > (ULONG_MAX - 9u) / 10u)
                big = 1;
            else
                want = want * 10u + (unsigned long)(d[k] - '0');
        }
        if (!k || word_byte((unsigned char)d[k]))
            continue;
        return big ? 0 : cbf_cut_record_line((const char *)text, n, want);
    }
    return 0;
}

int cbf_tool_encode_judge(const char *name, const uint8_t *text, size_t n, const uint8_t *cbf, size_t len, int profile,
                          const cbf_tool_sink *sink)
{
    const char *file = cbf_tool_name(name);
    cbf_options opt;
    char *said;
    size_t cap;
    unsigned long line;
    out_begin(sink);
    memset(&opt, 0, sizeof opt);
    opt.profile = profile;
    refused = 0;
    out_of_memory = 0;
    refusal.message = NULL;
    (void)cbf_validate(cbf, len, &opt, keep_refusal, NULL);
    if (out_of_memory) {
        free(refusal.message);
        refusal.message = NULL;
        err_printf("cbf-c: %s: out of memory judging the CBF it encodes to\n", file);
        return CBF_TOOL_EXIT_USAGE;
    }
    if (!refused)
        return CBF_TOOL_EXIT_OK;
    /* EncodeError: "{record N|file}: the result would fail check C: message", at the finding's offset */
    cap = strlen(refusal.message) + strlen(refusal.check) + 96u;
    said = (char *)malloc(cap);
    if (!said) {
        err_printf("cbf-c: %s: out of memory judging the CBF it encodes to\n", file);
    } else {
        if (refusal.record >= 0)
            (void)snprintf(said, cap, "record %ld: the result would fail check %s: %s", refusal.record, refusal.check,
                           refusal.message);
        else
            (void)snprintf(said, cap, "file: the result would fail check %s: %s", refusal.check, refusal.message);
        line = said_record_line(said, text, n);
        if (line)
            err_printf("cbf-c: %s: line %lu: %s\n", file, line, cbf_quoted(said, CBF_QUOTE_TEXT));
        else
            err_printf("cbf-c: %s: offset %lu: %s\n", file, refusal.offset, cbf_quoted(said, CBF_QUOTE_TEXT));
        free(said);
    }
    free(refusal.message);
    refusal.message = NULL;
    return CBF_TOOL_EXIT_USAGE;
}

/* The most deprecated records cbf encode names one by one (cli.py, _warn_deprecated's `most`). */
#define CBF_TOOL_MOST_DEPRECATION_WARNINGS 10u

static unsigned long ndeprecated;
static held_finding first_deprecated[CBF_TOOL_MOST_DEPRECATION_WARNINGS]; /* the first in cbf's order */
static size_t nfirst;

static int is_deprecation(int order) { return strcmp(cbf_tool_check_kinds[order], "deprecated") == 0; }

/* Count each deprecated record; keep the first CBF_TOOL_MOST_DEPRECATION_WARNINGS in cbf's order (memory
 * bounded however many records a file deprecates). */
static void keep_deprecated(void *user, const cbf_finding *f)
{
    held_finding h;
    size_t k;
    char *copy;
    (void)user;
    h = borrowed(f, check_rank(f->check));
    if (!is_deprecation(h.order))
        return;
    ndeprecated++;
    if (nfirst == CBF_TOOL_MOST_DEPRECATION_WARNINGS && finding_cmp(&h, &first_deprecated[nfirst - 1u]) >= 0)
        return;
    if (!(copy = kept_message(f)))
        return;
    if (nfirst == CBF_TOOL_MOST_DEPRECATION_WARNINGS)
        free(first_deprecated[--nfirst].message);
    for (k = nfirst; k > 0 && finding_cmp(&h, &first_deprecated[k - 1u]) < 0; k--)
        first_deprecated[k] = first_deprecated[k - 1u];
    first_deprecated[k] = h;
    first_deprecated[k].message = copy;
    nfirst++;
}

void cbf_tool_encode_warnings(const char *output, const uint8_t *cbf, size_t len, const cbf_tool_sink *sink)
{
    const char *label;
    cbf_options opt;
    size_t k;
    int any = 0;
    for (k = 0; k < (size_t)CBF_CHECK__COUNT && !any; k++)
        any = is_deprecation((int)k);
    if (!any) /* the spec deprecates nothing: no record to warn for, and no validation to pay */
        return;
    out_begin(sink);
    memset(&opt, 0, sizeof opt);
    opt.profile = CBF_TOOL_DEFAULT_PROFILE; /* as cbf: validate's findings under its default profile */
    nfirst = 0;
    ndeprecated = 0;
    out_of_memory = 0;
    (void)cbf_validate(cbf, len, &opt, keep_deprecated, NULL);
    label = cbf_tool_name(output);
    for (k = 0; k < nfirst; k++) {
        err_printf("cbf-c: warning: %s: record %ld at offset %lu: %s (check %s, %s)\n", label,
                   first_deprecated[k].record, first_deprecated[k].offset,
                   cbf_quoted(first_deprecated[k].message, CBF_QUOTE_TEXT), first_deprecated[k].check,
                   first_deprecated[k].error ? "error" : "warning");
        free(first_deprecated[k].message);
    }
    nfirst = 0;
    if (ndeprecated > (unsigned long)k)
        err_printf("cbf-c: warning: %s: %lu more deprecated record(s)\n", label, ndeprecated - (unsigned long)k);
}
/* ==== END tools/engine.c ==== */
#line 3166 "cbf_tools.h"
#ifdef __cplusplus
}
#endif
#endif /* CBF_TOOLS_IMPLEMENTATION_DONE */
#endif /* CBF_TOOLS_IMPLEMENTATION */
