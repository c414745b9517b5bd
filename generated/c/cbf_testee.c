/* cbf_testee.c - conformance testee of the C binding (conformance/PROTOCOL.md).
 *
 * GENERATED from spec/cbf.yaml by cbfgen (generator/cbfgen/emit/c). Do not edit.
 *
 * Reads JSON lines on stdin ({"op": "decode" | "validate" | "encode" | "quit"})
 * and answers each with one JSON line on stdout. It only answers; the runner
 * judges. No malloc: every buffer is static.
 */
#define _POSIX_C_SOURCE 200809L /* open, fstat, O_NONBLOCK: only regular files are read (issue #35) */
#define CBF_IMPLEMENTATION
#include "cbf.h"

#include <float.h>
#include <stdarg.h>
#include <errno.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_FILE (32u << 20)
#define MAX_LINE (96u << 20)
#define MAX_NODES (6u << 20)
#define MAX_DEPTH 64

static uint8_t file_buf[MAX_FILE];
static uint8_t out_buf[MAX_FILE];
static char req_line[MAX_LINE];

/* ---- shared by the testee and the tool (generated from common.inc.j2) ---- */

/* What a file that is not a regular one is, as cbf says it (cbf.files.kind_of). */
static const char *not_regular(mode_t mode)
{
    return S_ISDIR(mode) ? "is a directory" : S_ISFIFO(mode) ? "is a FIFO; only regular files are read"
         : S_ISCHR(mode) ? "is a character device; only regular files are read"
         : S_ISBLK(mode) ? "is a block device; only regular files are read"
         : S_ISSOCK(mode) ? "is a socket; only regular files are read" : "is not a regular file; only regular files are read";
}

/* Read a whole file into buf; returns its size or -1 (what went wrong in *why, as cbf says it).
 * Only a regular file is opened: its status is looked at first, and it is opened without
 * blocking (a FIFO named like a CBF file cannot hang the tool), then looked at again. */
static long read_file(const char *path, uint8_t *buf, size_t cap, const char **why)
{
    FILE *fp;
    struct stat st;
    int fd;
    size_t n = 0;
    errno = 0;
    *why = "cannot open";
    if (stat(path, &st) != 0 || !S_ISREG(st.st_mode)) {
        if (errno)
            *why = errno == ENOENT ? "no such file" : errno == EACCES ? "permission denied" : "cannot open";
        else
            *why = not_regular(st.st_mode);
        return -1;
    }
    fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY);
    if (fd < 0 || fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        *why = fd < 0 ? (errno == ENOENT ? "no such file" : errno == EACCES ? "permission denied" : "cannot open")
                      : not_regular(st.st_mode);
        if (fd >= 0)
            (void)close(fd);
        return -1;
    }
    fp = fdopen(fd, "rb");
    if (!fp) {
        (void)close(fd);
        return -1;
    }
    for (;;) {
        size_t got;
        if (n == cap) {
            int c = fgetc(fp);
            fclose(fp);
            *why = "file too large";
            return c == EOF ? (long)n : -1;
        }
        got = fread(buf + n, 1, cap - n, fp);
        n += got;
        if (got == 0)
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

/* ---- option files: cutter tables (6.1.2) and machine files, by one rule (issue 28) ---- */
/* ---- option files (issue 28): the rules of generator/cbfgen/option_files.yaml, completed from the
 * spec (cbfgen/options.py), the same that cbf/option_files.json gives cbf. Every refusal is one line
 * naming the file, the line (or JSON path) and the limit, the line cbf says (tests/option_files/). */
#include <float.h>
#include <stdarg.h>

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

static char opt_why[8192];

static int opt_fail(const char *fmt, ...) CBF__PRINTF(1, 2);
static int opt_fail(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    (void)vsnprintf(opt_why, sizeof opt_why, fmt, ap);
    va_end(ap);
    return 0;
}

/* The file into buf (at most max bytes, never more read), checked to be UTF-8 as Python decodes it. */
static long opt_read(const char *path, char *buf, size_t max, const char *what)
{
    const char *why;
    long n = read_file(path, (uint8_t *)buf, max, &why);
    size_t i = 0;
    if (n < 0) {
        if (strcmp(why, "file too large") == 0)
            return opt_fail("%s: larger than the %lu bytes a %s may have (limit max_bytes)",
                            cbf_quoted(path, CBF_QUOTE_NAME), (unsigned long)max, what) - 1;
        return opt_fail("%s: cannot read %s (%s)", cbf_quoted(path, CBF_QUOTE_NAME), what, why) - 1;
    }
    buf[n] = 0;
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
        else return opt_fail("%s: offset %lu: not UTF-8 text", cbf_quoted(path, CBF_QUOTE_NAME), (unsigned long)i) - 1;
        if (u[0] == 0xE0) lo = 0xA0;
        if (u[0] == 0xED) hi = 0x9F;
        if (u[0] == 0xF0) lo = 0x90;
        if (u[0] == 0xF4) hi = 0x8F;
        for (k = 1; k < len; k++) {
            unsigned char a = k == 1 ? lo : 0x80, b = k == 1 ? hi : 0xBF;
            if (k >= left || u[k] < a || u[k] > b)
                return opt_fail("%s: offset %lu: not UTF-8 text", cbf_quoted(path, CBF_QUOTE_NAME), (unsigned long)i) - 1;
        }
        i += len;
    }
    if (memchr(buf, 0, (size_t)n))
        return opt_fail("%s: offset %lu: not text (a NUL byte)", cbf_quoted(path, CBF_QUOTE_NAME),
                        (unsigned long)((const char *)memchr(buf, 0, (size_t)n) - buf)) - 1;
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
    char *out;
    size_t n, cap;
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

/* A flow collection or scalar inside one, at *p; fdepth: the open flow collections around it. */
static int yj_flow(yj *y, const char **p, const char *end, int in_flow)
{
    const char *s = yj_skip(*p, end);
    if (!yj_node_mark(y, s))
        return 0;
    if (s < end && (*s == '[' || *s == '{')) {
        char close = *s == '[' ? ']' : '}';
        int mapping = *s == '{';
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
        } else {
            for (;;) {
                s = yj_skip(s, end);
                if (s >= end)
                    return yj_err(y, y->line, "a value over more than one line (one-line values only)");
                if (mapping) {
                    const char *k0;
                    if (!yj_node_mark(y, s))
                        return 0;
                    if (*s == '[' || *s == '{')
                        return yj_err(y, y->line, "a key must be a plain value (complex key)");
                    if (++keys > OPT_YAML_MAX_KEYS)
                        return opt_fail("%s: line %lu: more than %u keys in one mapping (limit max_keys)", y->file,
                                        y->line, OPT_YAML_MAX_KEYS);
                    if (*s == '"' || *s == '\'') {
                        if (!yj_quoted(y, &s, end))
                            return 0;
                    } else {
                        size_t len;
                        k0 = s;
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
                } else if (!yj_flow(y, &s, end, 1)) {
                    return 0;
                }
                s = yj_skip(s, end);
                if (s >= end)
                    return yj_err(y, y->line, "a value over more than one line (one-line values only)");
                if (*s == ',') {
                    s = yj_skip(s + 1, end);
                    if (s < end && *s == close) {
                        s++;
                        break;
                    }
                    if (!yj_c(y, ','))
                        return 0;
                    continue;
                }
                if (*s == close) {
                    s++;
                    break;
                }
                return opt_fail("%s: line %lu: not YAML (expected ',' or '%c')", y->file, y->line, close);
            }
        }
        y->depth--;
        *p = s;
        return yj_c(y, close);
    }
    if (s < end && (*s == '"' || *s == '\'')) {
        if (!yj_quoted(y, &s, end))
            return 0;
        *p = s;
        return 1;
    }
    {
        const char *v0 = s;
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
}

/* The end of a plain or quoted key at p followed by ':' and a blank or the line's end, or NULL. */
static const char *yj_key_end(const char *p, const char *end)
{
    if (p < end && (*p == '"' || *p == '\'')) {
        char q = *p++;
        while (p < end && !(*p == q && !(q == '\'' && p + 1 < end && p[1] == '\'')))
            p += (q == '\'' && *p == '\'') || (q == '"' && *p == '\\') ? 2 : 1;
        if (p >= end)
            return NULL;
        p = yj_skip(p + 1, end);
        return p < end && *p == ':' && (p + 1 == end || p[1] == ' ' || p[1] == '\t') ? p : NULL;
    }
    if (p < end && (*p == '[' || *p == '{'))
        return NULL;
    for (; p < end; p++)
        if (*p == ':' && (p + 1 == end || p[1] == ' ' || p[1] == '\t'))
            return p;
    return NULL;
}

/* The node a line holds from p (its column col): a list item, a key and its value, or a value. */
static int yj_inline(yj *y, const char *p, const char *end, int col)
{
    const char *colon;
    if (!yj_node_mark(y, p))
        return 0;
    if (*p == '-' && (p + 1 == end || p[1] == ' ' || p[1] == '\t')) {
        const char *rest;
        if (y->depth && y->kind[y->depth] == 's' && y->ind[y->depth] == col && !y->pending) {
            if (!yj_c(y, ','))
                return 0;
        } else if (y->pending || (!y->depth && !y->root_done)) {
            if (!yj_open(y, 's', col))
                return 0;
        } else {
            return opt_fail("%s: line %lu: not YAML (a list item where none can be)", y->file, y->line);
        }
        y->root_done = 1;
        y->items[y->depth]++;
        rest = yj_skip(p + 1, end);
        y->pending = 1; /* the item's value: on this line, or on the lines below */
        y->pending_ind = col;
        y->pending_at = y->n;
        if (rest >= end)
            return 1;
        return yj_inline(y, rest, end, col + (int)(rest - p));
    }
    colon = yj_key_end(p, end);
    if (colon) {
        const char *v;
        if (y->depth && y->kind[y->depth] == 'm' && y->ind[y->depth] == col && !y->pending) {
            if (!yj_c(y, ','))
                return 0;
        } else if (y->pending || (!y->depth && !y->root_done)) {
            if (!yj_open(y, 'm', col))
                return 0;
        } else {
            return opt_fail("%s: line %lu: not YAML (a key where none can be)", y->file, y->line);
        }
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
            y->pending = 1;
            y->pending_ind = col;
            y->pending_at = y->n;
            return 1;
        }
        if (!yj_flow(y, &v, end, 0))
            return 0;
        if (yj_skip(v, end) < end)
            return opt_fail("%s: line %lu: not YAML (more after a value)", y->file, y->line);
        return 1;
    }
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

/* Translate the YAML text src into JSON in out (cap bytes); 0 with the one line in opt_why. */
static int yj_translate(const char *file, const char *src, char *out, size_t cap, int max_depth)
{
    yj y;
    const char *line = src;
    memset(&y, 0, sizeof y);
    y.file = file;
    y.out = out;
    y.cap = cap;
    y.max_depth = max_depth;
    out[0] = 0;
    if (memcmp(src, "\xEF\xBB\xBF", 3) == 0) /* a byte order mark, which YAML readers skip */
        line += 3;
    while (*line) {
        const char *nl = strchr(line, '\n'), *end = nl ? nl : line + strlen(line), *p = line, *c;
        int ind, quote = 0;
        y.line++;
        for (c = line; c < end; c++) { /* refuse control characters; cut a comment outside quotes */
            if ((unsigned char)*c < 0x20 && *c != '\t' && !(*c == '\r' && c + 1 == end))
                return opt_fail("%s: line %lu: not YAML (a control character)", file, y.line);
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
        while (p < end && *p == ' ')
            p++;
        ind = (int)(p - line);
        if (p < end && *p == '\t')
            return opt_fail("%s: line %lu: not YAML (a tab in the indentation)", file, y.line);
        if (p < end) {
            if (ind == 0 && end - p >= 3 && memcmp(p, "---", 3) == 0 && (end - p == 3 || p[3] == ' ')) {
                if (y.root_done || y.ended)
                    return yj_err(&y, y.line, "more than one document");
                p = yj_skip(p + 3, end);
                ind = (int)(p - line);
            } else if (ind == 0 && end - p == 3 && memcmp(p, "...", 3) == 0) {
                y.ended = 1;
                p = end;
            } else if (*p == '%') {
                return opt_fail("%s: line %lu: not YAML (a directive)", file, y.line);
            }
        }
        if (p < end) {
            int item = *p == '-' && (p + 1 == end || p[1] == ' ' || p[1] == '\t');
            if (y.ended)
                return yj_err(&y, y.line, "more than one document");
            if (y.pending && ind <= y.pending_ind
                && !(item && ind == y.pending_ind && y.depth && y.kind[y.depth] == 'm') && !yj_null(&y))
                return 0;
            while (y.depth && !y.pending && (y.ind[y.depth] > ind || (y.ind[y.depth] == ind && y.kind[y.depth] == 's'
                                                                      && !item)))
                if (!yj_close(&y))
                    return 0;
            if (!yj_inline(&y, p, end, ind))
                return 0;
        }
        if (!yj_c(&y, '\n'))
            return 0;
        if (!nl)
            break;
        line = nl + 1;
    }
    while (y.depth)
        if (!yj_close(&y))
            return 0;
    if (!y.root_done && !yj_put(&y, "null", 4))
        return 0;
    return 1;
}

/* ---- cutter tables (6.1.2): the rows, each checked as it comes by the shared rules ---- */
static char cutter_names[OPT_CUTTER_MAX_ROWS][OPT_CUTTER_NAME_BYTES];
static unsigned long cutter_lines[OPT_CUTTER_MAX_ROWS];
static cbf_cutter cutters[OPT_CUTTER_MAX_ROWS];
static size_t ncutters;
static char cutter_text[OPT_CUTTER_MAX_BYTES + 1u];
static char cutter_json[4u * OPT_CUTTER_MAX_BYTES + 64u];
static const char *cutter_file;

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
    memcpy(cutter_names[ncutters], name, strlen(name) + 1); /* chars <= max: fits OPT_CUTTER_NAME_BYTES */
    cutter_lines[ncutters] = line;
    cutters[ncutters].name = cutter_names[ncutters];
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

static int cutters_yaml(const char *path)
{
    cj j;
    int seen = 0;
    if (!yj_translate(path, cutter_text, cutter_json, sizeof cutter_json, OPT_CUTTER_MAX_DEPTH))
        return 0;
    memset(&j, 0, sizeof j);
    j.s = cutter_json;
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

/* Read a cutter table into cutters[0..ncutters); 0 with the one line in opt_why. */
static int load_cutters(const char *path)
{
    long n;
    static char shown[8192]; /* the name as messages show it (the quoting rule) */
    ncutters = 0;
    (void)cbf_quote(shown, sizeof shown, path, strlen(path), CBF_QUOTE_NAME);
    cutter_file = shown;
    n = opt_read(path, cutter_text, OPT_CUTTER_MAX_BYTES, opt_cutter_what);
    if (n < 0)
        return 0;
    if (opt_is_yaml(path)) {
        if (!cutters_yaml(shown))
            return 0;
    } else if (!cutters_csv(cutter_text)) {
        return 0;
    }
    if (!ncutters)
        return opt_fail("%s: no cutters (the table is empty)", shown);
    return 1;
}

/* ---- machine files (decision L1, check machine_limits; machine_file.inc.j2) ----
 * The JSON form of `machine:` in spec/cbf.yaml (schema generated/python/cbf/machine.schema.json):
 *   {"name": "...", "limits": {"<limit>": {"unit": "<the spec's unit>", "min": N | [N, ...],
 *    "max": N | [N, ...], "axes": [...], "doc": "..."}, ...}}
 * every limit of cbf_machine_limit_names with unit, min and max; one number per axis for a box;
 * min <= max. Both tools read it as JSON, or as YAML for .yaml/.yml (the option-file subset above,
 * translated to JSON with its lines). A bad file gives one line naming the file and the JSON path
 * (or the line), as cbf says it. */
static cbf_machine machine_file;
static char machine_why[8192];
static char machine_text[OPT_MACHINE_MAX_BYTES + 1u];
static char machine_json[4u * OPT_MACHINE_MAX_BYTES + 64u]; /* a YAML machine file, as JSON */

typedef struct mjson { const char *s; size_t n, i; const char *file; } mjson;

static const char *const machine_file_keys[] = { "name", "doc", "decision", "limits", NULL };
static const char *const machine_limit_keys[] = { "unit", "min", "max", "doc", "axes", NULL };

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
static int mj_number(mjson *j, double *out, int *finite)
{
    size_t start = j->i, len;
    char buf[128];
    if (j->i < j->n && j->s[j->i] == '-')
        j->i++;
    if (j->i < j->n && j->s[j->i] == '0') {
        j->i++;
    } else if (j->i < j->n && j->s[j->i] >= '1' && j->s[j->i] <= '9') {
        while (j->i < j->n && j->s[j->i] >= '0' && j->s[j->i] <= '9')
            j->i++;
    } else {
        return mj_syntax(j, "expected a value");
    }
    if (j->i < j->n && j->s[j->i] == '.') {
        j->i++;
        if (!(j->i < j->n && j->s[j->i] >= '0' && j->s[j->i] <= '9'))
            return mj_syntax(j, "expected a digit");
        while (j->i < j->n && j->s[j->i] >= '0' && j->s[j->i] <= '9')
            j->i++;
    }
    if (j->i < j->n && (j->s[j->i] == 'e' || j->s[j->i] == 'E')) {
        j->i++;
        if (j->i < j->n && (j->s[j->i] == '+' || j->s[j->i] == '-'))
            j->i++;
        if (!(j->i < j->n && j->s[j->i] >= '0' && j->s[j->i] <= '9'))
            return mj_syntax(j, "expected a digit");
        while (j->i < j->n && j->s[j->i] >= '0' && j->s[j->i] <= '9')
            j->i++;
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

static int mj_unknown(mjson *j, const char *path, const char *key, const char *const *known)
{
    char list[512];
    size_t k, at = 0;
    list[0] = 0;
    for (k = 0; known[k]; k++)
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
        return mj_unknown(j, path, key, known);
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
        return mj_unknown(j, path, key, cbf_machine_limit_names);
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
        return mj_unknown(j, path, key, machine_file_keys);
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

/* Read a machine file into machine_file; 0 with the one line in machine_why. */
static int load_machine(const char *path)
{
    long n = opt_read(path, machine_text, OPT_MACHINE_MAX_BYTES, opt_machine_what);
    static char shown[8192]; /* the name as messages show it (the quoting rule) */
    mjson j;
    unsigned has_limits = 0;
    int li, a;
    if (n < 0) {
        (void)snprintf(machine_why, sizeof machine_why, "%s", opt_why);
        return 0;
    }
    memset(&machine_file, 0, sizeof machine_file);
    (void)cbf_quote(shown, sizeof shown, path, strlen(path), CBF_QUOTE_NAME);
    j.s = machine_text;
    j.n = (size_t)n;
    if (opt_is_yaml(path)) {
        if (!yj_translate(shown, machine_text, machine_json, sizeof machine_json, OPT_MACHINE_MAX_DEPTH)) {
            (void)snprintf(machine_why, sizeof machine_why, "%s", opt_why);
            return 0;
        }
        j.s = machine_json;
        j.n = strlen(machine_json);
    } else if (!opt_json_depth(shown, machine_text, (size_t)n, OPT_MACHINE_MAX_DEPTH)) {
        (void)snprintf(machine_why, sizeof machine_why, "%s", opt_why);
        return 0;
    }
    j.i = 0;
    j.file = shown;
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

/* ---- output ---------------------------------------------------------------- */
static void put(const char *s) { fputs(s, stdout); }

static void put_string(const uint8_t *s, size_t n)
{
    size_t i;
    putchar('"');
    for (i = 0; i < n; i++) {
        unsigned c = s[i];
        if (c == '"' || c == '\\') {
            putchar('\\');
            putchar((int)c);
        } else if (c < 0x20u || c >= 0x7Fu) {
            printf("\\u%04x", c);
        } else {
            putchar((int)c);
        }
    }
    putchar('"');
}

static void put_cstring(const char *s) { put_string((const uint8_t *)s, strlen(s)); }

static void put_hex(const uint8_t *p, size_t n)
{
    static const char digits[] = "0123456789abcdef";
    size_t i;
    putchar('"');
    for (i = 0; i < n; i++) {
        putchar(digits[p[i] >> 4]);
        putchar(digits[p[i] & 15u]);
    }
    putchar('"');
}

static void put_float(float f)
{
    uint32_t bits = cbf_float_bits(f);
    if ((bits & 0x7F800000u) == 0x7F800000u || bits == 0x80000000u)
        printf("\"0x%08lx\"", (unsigned long)bits);
    else
        printf("%.9g", (double)f);
}

/* Element i of an integer field, in decimal, exact at every registered width and signedness
 * (from its bits: a double would round beyond 2^53). */
static void put_int(const cbf_field_info *f, const uint8_t *base, unsigned i)
{
    uint64_t u = cbf_field_bits(f, base, i);
    unsigned bits = 8u * f->elem;
    char d[24];
    size_t n = 0;
    if (f->kind == CBF_KIND_SINT && ((u >> (bits - 1u)) & 1u)) {
        putchar('-');
        u = (bits < 64u ? ((uint64_t)1 << bits) : (uint64_t)0) - u; /* the magnitude, mod 2^64 */
    }
    do {
        d[n++] = (char)('0' + (int)(u % 10u));
        u /= 10u;
    } while (u);
    while (n)
        putchar(d[--n]);
}

/* One field's value of a byte image, as canonical JSON (PROTOCOL.md). */
static void put_value(const cbf_field_info *f, const uint8_t *base)
{
    size_t size = (size_t)f->elem * f->count;
    unsigned i;
    switch (f->kind) {
    case CBF_KIND_UINT:
    case CBF_KIND_SINT:
        put_int(f, base, 0);
        break;
    case CBF_KIND_FLOAT:
        if (f->count > 1u)
            putchar('[');
        for (i = 0; i < f->count; i++) {
            if (i)
                put(", ");
            put_float(cbf_field_float(f, base, i));
        }
        if (f->count > 1u)
            putchar(']');
        break;
    case CBF_KIND_STRING: {
        size_t n = size;
        while (n && base[f->offset + n - 1] == 0u)
            n--;
        put_string(base + f->offset, n);
        break;
    }
    default:
        put_hex(base + f->offset, size);
        break;
    }
}

/* One field of a byte image, as canonical JSON: "name": value. */
static void put_field(const cbf_field_info *f, const uint8_t *base)
{
    printf("\"%s\": ", f->name);
    put_value(f, base);
}

/* A repeated argument group (issue 25, point 3) of n items, item bytes each: "name": [item, ...],
 * each item as its field row (the row describes one) says, one after another. */
static void put_group(const cbf_field_info *f, const uint8_t *base, size_t n, size_t item)
{
    cbf_field_info one = *f;
    size_t i;
    printf("\"%s\": [", f->name);
    for (i = 0; i < n; i++) {
        if (i)
            put(", ");
        put_value(&one, base);
        one.offset = (unsigned short)(one.offset + item);
    }
    putchar(']');
}

static void put_error(const char *kind, long offset, const char *message)
{
    put("{\"ok\": false, \"error\": {\"kind\": ");
    put_cstring(kind);
    if (offset >= 0)
        printf(", \"offset\": %ld", offset);
    else
        put(", \"offset\": null");
    put(", \"message\": ");
    put_cstring(message);
    put("}}\n");
}

/* ---- a small JSON reader: a DOM of nodes over the request line ----------------- */
enum { J_NULL, J_FALSE, J_TRUE, J_NUM, J_STR, J_ARR, J_OBJ };
typedef struct jnode {
    unsigned char type;
    uint32_t start, len; /* the token's text (strings: inside the quotes) */
    int32_t first, next; /* children; for objects a key node is followed by its value node */
} jnode;
static jnode nodes[MAX_NODES];
static uint32_t nnodes;
static const char *jtext;
static size_t jlen, jpos;
static const char *jerr;

static void jws(void)
{
    while (jpos < jlen && (jtext[jpos] == ' ' || jtext[jpos] == '\t' || jtext[jpos] == '\r' || jtext[jpos] == '\n'))
        jpos++;
}

static int32_t jalloc(unsigned char type)
{
    if (nnodes >= MAX_NODES) {
        jerr = "JSON too large";
        return -1;
    }
    nodes[nnodes].type = type;
    nodes[nnodes].start = (uint32_t)jpos;
    nodes[nnodes].len = 0;
    nodes[nnodes].first = -1;
    nodes[nnodes].next = -1;
    return (int32_t)nnodes++;
}

static int jdigit(char c) { return c >= '0' && c <= '9'; }

static int32_t jvalue(int depth);

static int32_t jstring(void)
{
    int32_t n;
    jpos++; /* opening quote */
    n = jalloc(J_STR);
    if (n < 0)
        return -1;
    nodes[n].start = (uint32_t)jpos;
    while (jpos < jlen && jtext[jpos] != '"') {
        unsigned char c = (unsigned char)jtext[jpos];
        if (c < 0x20u) {
            jerr = "control character in string";
            return -1;
        }
        if (c == '\\') {
            jpos++;
            if (jpos >= jlen)
                break;
        }
        jpos++;
    }
    if (jpos >= jlen) {
        jerr = "unterminated string";
        return -1;
    }
    nodes[n].len = (uint32_t)(jpos - nodes[n].start);
    jpos++;
    return n;
}

static int32_t jvalue(int depth)
{
    int32_t n, prev = -1;
    if (depth > MAX_DEPTH) {
        jerr = "JSON nested too deep";
        return -1;
    }
    jws();
    if (jpos >= jlen) {
        jerr = "unexpected end of JSON";
        return -1;
    }
    switch (jtext[jpos]) {
    case '"':
        return jstring();
    case '{':
    case '[': {
        int obj = jtext[jpos] == '{';
        char close = obj ? '}' : ']';
        n = jalloc(obj ? J_OBJ : J_ARR);
        if (n < 0)
            return -1;
        jpos++;
        jws();
        if (jpos < jlen && jtext[jpos] == close) {
            jpos++;
            return n;
        }
        for (;;) {
            int32_t k = -1, v;
            jws();
            if (obj) {
                if (jpos >= jlen || jtext[jpos] != '"') {
                    jerr = "expected a key";
                    return -1;
                }
                k = jstring();
                if (k < 0)
                    return -1;
                jws();
                if (jpos >= jlen || jtext[jpos] != ':') {
                    jerr = "expected ':'";
                    return -1;
                }
                jpos++;
            }
            v = jvalue(depth + 1);
            if (v < 0)
                return -1;
            if (obj) {
                if (prev < 0) nodes[n].first = k; else nodes[prev].next = k;
                nodes[k].next = v;
            } else {
                if (prev < 0) nodes[n].first = v; else nodes[prev].next = v;
            }
            prev = v;
            jws();
            if (jpos < jlen && jtext[jpos] == ',') {
                jpos++;
                continue;
            }
            if (jpos < jlen && jtext[jpos] == close) {
                jpos++;
                return n;
            }
            jerr = obj ? "expected ',' or '}'" : "expected ',' or ']'";
            return -1;
        }
    }
    case 't':
        if (jlen - jpos >= 4 && memcmp(jtext + jpos, "true", 4) == 0) { n = jalloc(J_TRUE); jpos += 4; return n; }
        break;
    case 'f':
        if (jlen - jpos >= 5 && memcmp(jtext + jpos, "false", 5) == 0) { n = jalloc(J_FALSE); jpos += 5; return n; }
        break;
    case 'n':
        if (jlen - jpos >= 4 && memcmp(jtext + jpos, "null", 4) == 0) { n = jalloc(J_NULL); jpos += 4; return n; }
        break;
    default:
        if (jtext[jpos] == '-' || jdigit(jtext[jpos])) {
            n = jalloc(J_NUM);
            if (n < 0)
                return -1;
            if (jtext[jpos] == '-')
                jpos++;
            if (jpos < jlen && jtext[jpos] == '0') {
                jpos++;
            } else if (jpos < jlen && jdigit(jtext[jpos])) {
                while (jpos < jlen && jdigit(jtext[jpos])) jpos++;
            } else {
                jerr = "bad number";
                return -1;
            }
            if (jpos < jlen && jtext[jpos] == '.') {
                jpos++;
                if (jpos >= jlen || !jdigit(jtext[jpos])) { jerr = "bad number"; return -1; }
                while (jpos < jlen && jdigit(jtext[jpos])) jpos++;
            }
            if (jpos < jlen && (jtext[jpos] == 'e' || jtext[jpos] == 'E')) {
                jpos++;
                if (jpos < jlen && (jtext[jpos] == '+' || jtext[jpos] == '-')) jpos++;
                if (jpos >= jlen || !jdigit(jtext[jpos])) { jerr = "bad number"; return -1; }
                while (jpos < jlen && jdigit(jtext[jpos])) jpos++;
            }
            nodes[n].len = (uint32_t)(jpos - nodes[n].start);
            return n;
        }
        break;
    }
    jerr = "unexpected character";
    return -1;
}

static int32_t jparse(const char *text, size_t len)
{
    int32_t root;
    jtext = text;
    jlen = len;
    jpos = 0;
    nnodes = 0;
    jerr = NULL;
    root = jvalue(0);
    if (root < 0)
        return -1;
    jws();
    if (jpos != jlen) {
        jerr = "text after the JSON value";
        return -1;
    }
    return root;
}

static int hexval(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

/* Decode a JSON string to bytes: latin1 != 0 maps code points U+0000..U+00FF
 * to one byte each (others fail), else the bytes are UTF-8. Returns the length or -1. */
static long jstr(int32_t n, uint8_t *out, size_t cap, int latin1)
{
    const char *s;
    size_t i, len, o = 0;
    if (n < 0 || nodes[n].type != J_STR)
        return -1;
    s = jtext + nodes[n].start;
    len = nodes[n].len;
    for (i = 0; i < len;) {
        unsigned long cp;
        unsigned char c = (unsigned char)s[i];
        if (c == '\\') {
            char e;
            if (len - i < 2)
                return -1;
            e = s[i + 1];
            i += 2;
            switch (e) {
            case '"': cp = '"'; break;
            case '\\': cp = '\\'; break;
            case '/': cp = '/'; break;
            case 'b': cp = 8; break;
            case 'f': cp = 12; break;
            case 'n': cp = 10; break;
            case 'r': cp = 13; break;
            case 't': cp = 9; break;
            case 'u': {
                int k;
                cp = 0;
                if (len - i < 4)
                    return -1;
                for (k = 0; k < 4; k++) {
                    int h = hexval(s[i + (size_t)k]);
                    if (h < 0)
                        return -1;
                    cp = cp * 16u + (unsigned long)h;
                }
                i += 4;
                if (cp >= 0xD800u && cp < 0xDC00u) {
                    unsigned long lo = 0;
                    if (len - i < 6 || s[i] != '\\' || s[i + 1] != 'u')
                        return -1;
                    for (k = 0; k < 4; k++) {
                        int h = hexval(s[i + 2 + (size_t)k]);
                        if (h < 0)
                            return -1;
                        lo = lo * 16u + (unsigned long)h;
                    }
                    if (lo < 0xDC00u || lo >= 0xE000u)
                        return -1;
                    i += 6;
                    cp = 0x10000u + ((cp - 0xD800u) << 10) + (lo - 0xDC00u);
                } else if (cp >= 0xDC00u && cp < 0xE000u) {
                    return -1;
                }
                break;
            }
            default:
                return -1;
            }
        } else if (c < 0x80u) {
            cp = c;
            i++;
        } else {
            size_t extra = c >= 0xF0u ? 3u : c >= 0xE0u ? 2u : c >= 0xC0u ? 1u : 0u;
            size_t k;
            if (!extra || c >= 0xF8u || len - i <= extra)
                return -1;
            cp = c & (0x3Fu >> extra);
            for (k = 1; k <= extra; k++) {
                unsigned char d = (unsigned char)s[i + k];
                if ((d & 0xC0u) != 0x80u)
                    return -1;
                cp = (cp << 6) | (d & 0x3Fu);
            }
            i += extra + 1;
        }
        if (latin1) {
            if (cp > 0xFFu || o >= cap)
                return -1;
            out[o++] = (uint8_t)cp;
        } else {
            uint8_t tmp[4];
            size_t k, m;
            if (cp < 0x80u) { tmp[0] = (uint8_t)cp; m = 1; }
            else if (cp < 0x800u) { tmp[0] = (uint8_t)(0xC0u | (cp >> 6)); tmp[1] = (uint8_t)(0x80u | (cp & 0x3Fu)); m = 2; }
            else if (cp < 0x10000u) { tmp[0] = (uint8_t)(0xE0u | (cp >> 12)); tmp[1] = (uint8_t)(0x80u | ((cp >> 6) & 0x3Fu)); tmp[2] = (uint8_t)(0x80u | (cp & 0x3Fu)); m = 3; }
            else { tmp[0] = (uint8_t)(0xF0u | (cp >> 18)); tmp[1] = (uint8_t)(0x80u | ((cp >> 12) & 0x3Fu)); tmp[2] = (uint8_t)(0x80u | ((cp >> 6) & 0x3Fu)); tmp[3] = (uint8_t)(0x80u | (cp & 0x3Fu)); m = 4; }
            if (cap - o < m)
                return -1;
            for (k = 0; k < m; k++)
                out[o++] = tmp[k];
        }
    }
    return (long)o;
}

/* A JSON string as a NUL-terminated UTF-8 C string in out (cap bytes). */
static int jcstr(int32_t n, char *out, size_t cap)
{
    long len;
    if (cap == 0)
        return 0;
    len = jstr(n, (uint8_t *)out, cap - 1, 0);
    if (len < 0)
        return 0;
    out[len] = 0;
    return memchr(out, 0, (size_t)len) == NULL;
}

static int jeq(int32_t n, const char *s)
{
    size_t l = strlen(s);
    return n >= 0 && nodes[n].type == J_STR && nodes[n].len == l && memcmp(jtext + nodes[n].start, s, l) == 0;
}

/* The value of key in object n (the last one, as Python's json), or -1. */
static int32_t jget(int32_t n, const char *key)
{
    int32_t k, found = -1;
    if (n < 0 || nodes[n].type != J_OBJ)
        return -1;
    for (k = nodes[n].first; k >= 0; k = nodes[nodes[k].next].next)
        if (jeq(k, key))
            found = nodes[k].next;
    return found;
}

static size_t jcount(int32_t n)
{
    size_t c = 0;
    int32_t k;
    if (n < 0 || (nodes[n].type != J_OBJ && nodes[n].type != J_ARR))
        return 0;
    for (k = nodes[n].first; k >= 0; k = nodes[n].type == J_OBJ ? nodes[nodes[k].next].next : nodes[k].next)
        c++;
    return c;
}

/* An unsigned JSON integer (no fraction, no exponent) up to max. */
static int juint(int32_t n, uint32_t max, uint32_t *out)
{
    const char *s;
    size_t i;
    unsigned long long v = 0;
    if (n < 0 || nodes[n].type != J_NUM)
        return 0;
    s = jtext + nodes[n].start;
    if (nodes[n].len == 2 && s[0] == '-' && s[1] == '0') {
        *out = 0; /* -0 is the integer 0 in JSON readers */
        return 1;
    }
    for (i = 0; i < nodes[n].len; i++) {
        if (!jdigit(s[i]))
            return 0;
        v = v * 10u + (unsigned long long)(s[i] - '0');
        if (v > max)
            return 0;
    }
    *out = (uint32_t)v;
    return 1;
}

/* An integer of ``bits`` bits, signed or not, from a JSON number (no fraction, no exponent; -0 is
 * 0), as its two's complement bits; 0 when it is not one or does not fit. */
static int jint(int32_t n, int sign, unsigned bits, uint64_t *out)
{
    const char *s;
    size_t i = 0;
    uint64_t v = 0, lim;
    int neg = 0;
    if (n < 0 || nodes[n].type != J_NUM)
        return 0;
    s = jtext + nodes[n].start;
    if (nodes[n].len > 0 && s[0] == '-') {
        neg = 1;
        i = 1;
    }
    if (i >= nodes[n].len)
        return 0;
    for (; i < nodes[n].len; i++) {
        unsigned dg;
        if (!jdigit(s[i]))
            return 0;
        dg = (unsigned)(s[i] - '0');
        if (v > (UINT64_MAX - dg) / 10u)
            return 0;
        v = v * 10u + dg;
    }
    if (neg && v == 0u)
        neg = 0;
    if (!sign)
        lim = neg ? 0u : bits >= 64u ? UINT64_MAX : (((uint64_t)1 << bits) - 1u);
    else
        lim = ((uint64_t)1 << (bits - 1u)) - (neg ? 0u : 1u);
    if (v > lim || (neg && !sign))
        return 0;
    *out = neg ? (uint64_t)0 - v : v;
    return 1;
}

/* A binary32 from a JSON number (rounded from the double, as Python's struct
 * does; out of range fails) or a "0xXXXXXXXX" bit string. */
static int jfloat(int32_t n, uint32_t *bits)
{
    char tmp[512];
    double d;
    float f;
    if (n >= 0 && nodes[n].type == J_STR) {
        uint8_t s[16];
        long len = jstr(n, s, sizeof s, 1);
        uint32_t v = 0;
        long i;
        if (len != 10 || s[0] != '0' || s[1] != 'x')
            return 0;
        for (i = 2; i < 10; i++) {
            int h = hexval((char)s[i]);
            if (h < 0)
                return 0;
            v = (v << 4) | (uint32_t)h;
        }
        *bits = v;
        return 1;
    }
    if (n < 0 || nodes[n].type != J_NUM || nodes[n].len >= sizeof tmp)
        return 0;
    memcpy(tmp, jtext + nodes[n].start, nodes[n].len);
    tmp[nodes[n].len] = 0;
    d = strtod(tmp, NULL);
    if (!(d == d) || d >= 3.4028235677973366e38 || d <= -3.4028235677973366e38)
        return 0; /* rounds to infinity: not a binary32 */
    if (d > (double)FLT_MAX)
        f = FLT_MAX;
    else if (d < -(double)FLT_MAX)
        f = -FLT_MAX;
    else
        f = (float)d;
    *bits = cbf_float_bits(f);
    return 1;
}

static const char *enc_err;
static char enc_msg[256];

static int fail(const char *fmt, ...) CBF__PRINTF(1, 2);
static int fail(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(enc_msg, sizeof enc_msg, fmt, ap);
    va_end(ap);
    enc_err = enc_msg;
    return 0;
}

/* Pack one field from JSON into a byte image at f->offset. */
static int pack_field(const cbf_field_info *f, int32_t v, uint8_t *base)
{
    size_t size = (size_t)f->elem * f->count;
    uint8_t *d = base + f->offset;
    unsigned i;
    switch (f->kind) {
    case CBF_KIND_UINT:
    case CBF_KIND_SINT: {
        uint64_t x;
        if (!jint(v, f->kind == CBF_KIND_SINT, 8u * f->elem, &x))
            return fail("field %s: not %s integer of its size", f->name,
                        f->kind == CBF_KIND_SINT ? "a signed" : "an unsigned");
        for (i = 0; i < f->elem; i++)
            d[i] = (uint8_t)((x >> (8u * i)) & 0xFFu);
        return 1;
    }
    case CBF_KIND_FLOAT: {
        int32_t e = v;
        if (f->count > 1u) {
            if (v < 0 || nodes[v].type != J_ARR || jcount(v) != f->count)
                return fail("field %s: expected an array of floats", f->name);
            e = nodes[v].first;
        }
        for (i = 0; i < f->count; i++, e = nodes[e].next) {
            uint32_t bits;
            unsigned k;
            if (!jfloat(e, &bits))
                return fail("field %s: not a binary32 value", f->name);
            for (k = 0; k < 4u; k++)
                d[4u * i + k] = (uint8_t)((bits >> (8u * k)) & 0xFFu);
        }
        return 1;
    }
    case CBF_KIND_STRING: {
        long n = jstr(v, d, size, 1);
        if (n < 0)
            return fail("field %s: not a string of at most its size in ISO-8859-1", f->name);
        memset(d + n, 0, size - (size_t)n);
        return 1;
    }
    default: {
        uint8_t hex[2 * 256 + 2];
        long n = jstr(v, hex, sizeof hex, 1);
        size_t k;
        if (n < 0 || (size_t)n != 2u * size)
            return fail("field %s: expected hex of its size", f->name);
        for (k = 0; k < size; k++) {
            int hi = hexval((char)hex[2 * k]), lo = hexval((char)hex[2 * k + 1]);
            if (hi < 0 || lo < 0)
                return fail("field %s: not hex", f->name);
            d[k] = (uint8_t)((hi << 4) | lo);
        }
        return 1;
    }
    }
}

static long unhex(int32_t v, uint8_t *out, size_t cap)
{
    const char *s;
    size_t i, n;
    if (v < 0 || nodes[v].type != J_STR || nodes[v].len % 2u)
        return -1;
    s = jtext + nodes[v].start;
    n = nodes[v].len / 2u;
    if (n > cap)
        return -1;
    for (i = 0; i < n; i++) {
        int hi = hexval(s[2 * i]), lo = hexval(s[2 * i + 1]);
        if (hi < 0 || lo < 0)
            return -1;
        out[i] = (uint8_t)((hi << 4) | lo);
    }
    return (long)n;
}

/* ---- ops ------------------------------------------------------------------- */
static void op_decode(int32_t req)
{
    char path[4096];
    const char *why;
    long n;
    cbf_reader r;
    cbf_record rec;
    int rc;
    const cbf_field_info *hf, *rf, *af;
    size_t nh, nr, na, i;
    if (!jcstr(jget(req, "file"), path, sizeof path)) {
        put_error("request", -1, "decode needs a file");
        return;
    }
    n = read_file(path, file_buf, sizeof file_buf, &why);
    if (n < 0) {
        put_error("io", -1, why);
        return;
    }
    rc = cbf_reader_init(&r, file_buf, (size_t)n);
    if (rc == CBF_ERR_TRUNCATED_HEADER) {
        put_error("truncated_header", 0, "the file is shorter than the header");
        return;
    }
    while ((rc = cbf_next_record(&r, &rec)) == 1) {}
    if (rc == CBF_ERR_TRUNCATED_RECORD) {
        put_error("truncated_record", (long)r.pos, "the last record is cut");
        return;
    }
    (void)cbf_reader_init(&r, file_buf, (size_t)n);
    put("{\"ok\": true, \"result\": {\"header\": {");
    nh = cbf_header_fields(r.header.layout, &hf);
    for (i = 0; i < nh; i++) {
        if (i)
            put(", ");
        put_field(&hf[i], file_buf);
    }
    put("}, \"records\": [");
    nr = cbf_record_fields(&rf);
    while (cbf_next_record(&r, &rec) == 1) {
        const uint8_t *p = file_buf + rec.offset;
        const char *name = cbf_command_name(rec.command);
        if (rec.index)
            put(", ");
        printf("{\"offset\": %lu", (unsigned long)rec.offset);
        for (i = 0; i < nr; i++) {
            put(", ");
            put_field(&rf[i], p);
        }
        put(", \"command\": ");
        if (name)
            put_cstring(name);
        else
            put("null");
        if (rec.layout != CBF_LAYOUT__NONE) {
            size_t item = 0;
            const long group = cbf_layout_group(rec.layout, NULL, NULL, &item);
            put(", \"args\": {");
            na = cbf_layout_fields(rec.layout, &af);
            for (i = 0; i < na; i++) {
                if (i)
                    put(", ");
                if ((long)i == group)
                    put_group(&af[i], rec.args, (size_t)cbf_layout_items(rec.layout, rec.nargs), item);
                else
                    put_field(&af[i], rec.args);
            }
            put("}}");
        } else {
            put(", \"args\": null, \"raw_args\": ");
            put_hex(rec.args, rec.nargs);
            put("}");
        }
    }
    put("], \"trailing\": ");
    put_hex(file_buf + r.pos, r.trailing);
    put("}}\n");
}

static int first_finding;

static void on_finding(void *user, const cbf_finding *f)
{
    (void)user;
    if (!first_finding)
        put(", ");
    first_finding = 0;
    put("{\"check\": ");
    put_cstring(f->check);
    printf(", \"severity\": \"%s\", \"record\": ", f->severity == CBF_SEVERITY_ERROR ? "error" : "warning");
    if (f->record < 0)
        put("null");
    else
        printf("%ld", f->record);
    printf(", \"offset\": %lu, \"message\": ", (unsigned long)f->offset);
    put_cstring(f->message);
    put("}");
}

static void op_validate(int32_t req)
{
    char path[4096], pname[64], part[1024], cpath[4096];
    const char *why;
    long n;
    int32_t v;
    cbf_options opt;
    memset(&opt, 0, sizeof opt);
    if (!jcstr(jget(req, "file"), path, sizeof path)) {
        put_error("request", -1, "validate needs a file");
        return;
    }
    v = jget(req, "profile");
    if (v < 0 || nodes[v].type == J_NULL)
        opt.profile = CBF_PROFILE_DEFAULT;
    else if (!jcstr(v, pname, sizeof pname) || (opt.profile = cbf_profile_find(pname)) < 0) {
        put_error("request", -1, "unknown profile");
        return;
    }
    v = jget(req, "part_number");
    if (v >= 0 && nodes[v].type != J_NULL) {
        if (!jcstr(v, part, sizeof part)) {
            put_error("request", -1, "bad part_number");
            return;
        }
        opt.part_number = part;
    }
    v = jget(req, "cutters");
    if (v >= 0 && nodes[v].type != J_NULL) {
        if (!jcstr(v, cpath, sizeof cpath) || !load_cutters(cpath)) {
            put_error("cutters", -1, "cannot read the cutter table");
            return;
        }
        opt.cutters = cutters;
        opt.ncutters = ncutters;
    }
    v = jget(req, "machine"); /* machine limits (L1): a machine file, or null for the default */
    if (v >= 0 && nodes[v].type != J_NULL) {
        if (!jcstr(v, cpath, sizeof cpath) || !load_machine(cpath)) {
            put_error("machine", -1, machine_why);
            return;
        }
        opt.machine = &machine_file;
    }
    n = read_file(path, file_buf, sizeof file_buf, &why);
    if (n < 0) {
        put_error("io", -1, why);
        return;
    }
    put("{\"ok\": true, \"findings\": [");
    first_finding = 1;
    (void)cbf_validate(file_buf, (size_t)n, &opt, on_finding, NULL);
    put("]}\n");
}

static int has_error;
static const char *first_error_check;
static long first_error_record;
/* A writer makes files that validate: no error, and strings in ASCII (N4). */
static const char *const refused_warnings[] = {
    CBF_CHECK_STRING_ASCII,
    NULL
};

static void on_error_finding(void *user, const cbf_finding *f)
{
    size_t i;
    int refuse = f->severity == CBF_SEVERITY_ERROR;
    (void)user;
    for (i = 0; refused_warnings[i] && !refuse; i++)
        refuse = strcmp(f->check, refused_warnings[i]) == 0;
    if (refuse && !has_error) {
        has_error = 1;
        first_error_check = f->check;
        first_error_record = f->record;
    }
}

/* The layout for an args object, as the reference does: the first of the
 * version's decode candidates, then every layout of the command, whose
 * argument names are the object's keys and whose size is arg_size when given. */
static int keys_match(int lay, int32_t args)
{
    const cbf_field_info *af;
    size_t na = cbf_layout_fields(lay, &af), i;
    if (na != jcount(args))
        return 0;
    for (i = 0; i < na; i++)
        if (jget(args, af[i].name) < 0)
            return 0;
    return 1;
}

/* The argument bytes an args object makes in a layout: its size, or with a repeated group (issue
 * 25, point 3) size + item * n for the n items of the object's list; -1 when the list is not one of
 * n items the group takes (the reference's layouts are made one per n: none fits). */
static long json_nb(int lay, int32_t args)
{
    const cbf_field_info *af;
    int32_t g;
    const int group = cbf_layout_group(lay, NULL, NULL, NULL);
    if (group < 0)
        return cbf_layout_size(lay);
    (void)cbf_layout_fields(lay, &af);
    g = jget(args, af[group].name);
    if (g < 0 || nodes[g].type != J_ARR)
        return -1;
    return cbf_layout_nb(lay, jcount(g));
}

static int choose_layout(int code, int version, int32_t args, int has_size, uint32_t want_size)
{
    int cands[CBF_LAYOUT__COUNT + 1], n, k, lay;
    long nb;
    n = cbf_args_candidates(code, version, cands, CBF_LAYOUT__COUNT);
    for (k = 0; k < n; k++)
        if (keys_match(cands[k], args) && (nb = json_nb(cands[k], args)) >= 0
            && (!has_size || (uint32_t)nb == want_size))
            return cands[k];
    for (lay = 0; lay < CBF_LAYOUT__COUNT; lay++)
        if (cbf_layout_code(lay) == code && keys_match(lay, args) && (nb = json_nb(lay, args)) >= 0
            && (!has_size || (uint32_t)nb == want_size))
            return lay;
    return CBF_LAYOUT__NONE;
}

/* Why an args object whose keys name a layout with a repeated group fits none: its group is no list,
 * or a list of an n outside min..max (the message names both); 1 when that is it (the message set). */
static int group_misfit(int code, int version, int32_t args, const char *where)
{
    int cands[CBF_LAYOUT__COUNT + 1], n, k;
    n = cbf_args_candidates(code, version, cands, CBF_LAYOUT__COUNT);
    for (k = 0; k < n; k++) {
        const cbf_field_info *af;
        size_t lo = 0, hi = 0;
        int32_t g;
        const int group = cbf_layout_group(cands[k], &lo, &hi, NULL);
        if (group < 0 || !keys_match(cands[k], args))
            continue;
        (void)cbf_layout_fields(cands[k], &af);
        g = jget(args, af[group].name);
        if (nodes[g].type != J_ARR)
            (void)fail("%s.args.%s: expected a list of items", where, af[group].name);
        else
            (void)fail("%s.args.%s: %lu items; the group holds %lu to %lu", where, af[group].name,
                       (unsigned long)jcount(g), (unsigned long)lo, (unsigned long)hi);
        return 1;
    }
    return 0;
}

/* A repeated group from its JSON list into a byte image: each item packed as the group's field
 * row (one item) says, at its place. */
static int pack_group(const cbf_field_info *f, int32_t v, uint8_t *base, size_t item)
{
    cbf_field_info one = *f;
    int32_t e;
    if (v < 0 || nodes[v].type != J_ARR)
        return fail("field %s: expected a list of items", f->name);
    for (e = nodes[v].first; e >= 0; e = nodes[e].next) {
        if (!pack_field(&one, e, base))
            return 0;
        one.offset = (unsigned short)(one.offset + item);
    }
    return 1;
}

/* 1 when every key of object o is one of names[0..n) or of the fields. */
static int known_keys(int32_t o, const cbf_field_info *fields, size_t nf, const char *const *names)
{
    int32_t k;
    for (k = nodes[o].first; k >= 0; k = nodes[nodes[k].next].next) {
        size_t i;
        int ok = 0;
        for (i = 0; i < nf && !ok; i++)
            ok = jeq(k, fields[i].name);
        for (i = 0; names && names[i] && !ok; i++)
            ok = jeq(k, names[i]);
        if (!ok)
            return 0;
    }
    return 1;
}

static const cbf_field_info *role_field(const cbf_field_info *fields, size_t n, int role)
{
    size_t i;
    for (i = 0; i < n; i++)
        if (fields[i].role == role)
            return &fields[i];
    return NULL;
}

static int encode(int32_t doc, int keep, int profile, long *size)
{
    static uint8_t header_bytes[CBF_HEADER_SIZE];
    static uint8_t args[1u << 16];
    static const char *const top_keys[] = { "header", "records", "trailing", NULL };
    static const char *const rec_keys[] = { "offset", "command", "args", "raw_args", NULL };
    int32_t hdr, recs, trail, r;
    const cbf_field_info *hf, *rf, *fcode, *fsize;
    size_t nh, nr, i;
    uint32_t major = 0, minor = 0, index = 0;
    int version, hl;
    cbf_header h;
    cbf_writer w;
    long rc;
    if (doc < 0 || nodes[doc].type != J_OBJ)
        return fail("%s", "$: expected an object");
    if (!known_keys(doc, NULL, 0, top_keys))
        return fail("%s", "$: unknown key");
    hdr = jget(doc, "header");
    recs = jget(doc, "records");
    trail = jget(doc, "trailing");
    if (hdr < 0 || nodes[hdr].type != J_OBJ)
        return fail("%s", "$.header: expected an object");
    if (recs >= 0 && nodes[recs].type != J_ARR)
        return fail("%s", "$.records: expected a list");
    if (trail >= 0 && nodes[trail].type != J_STR)
        return fail("%s", "$.trailing: expected a hex string");
    nh = cbf_header_fields(0, &hf);
    {
        int32_t vmaj = jget(hdr, role_field(hf, nh, CBF_ROLE_VERSION_MAJOR)->name);
        int32_t vmin = jget(hdr, role_field(hf, nh, CBF_ROLE_VERSION_MINOR)->name);
        if ((vmaj >= 0 && !juint(vmaj, 0xFFu, &major)) || (vmin >= 0 && !juint(vmin, 0xFFu, &minor)))
            return fail("%s", "$.header: bad version");
    }
    version = cbf_version_find(major, minor);
    if (!keep && !cbf_version_writable(version))
        return fail("header: version %lu.%lu is not writable", (unsigned long)major, (unsigned long)minor);
    hl = cbf_version_header_layout(version);
    nh = cbf_header_fields(hl, &hf);
    if (!known_keys(hdr, hf, nh, NULL))
        return fail("%s", "$.header: unknown key for the version's header layout");
    memset(header_bytes, 0, sizeof header_bytes);
    for (i = 0; i < nh; i++) {
        int32_t v = jget(hdr, hf[i].name);
        if (v < 0) {
            if (hf[i].flags & CBF_FIELD_MAGIC) {
                size_t k;
                for (k = 0; k < hf[i].elem; k++)
                    header_bytes[hf[i].offset + k] = (uint8_t)((hf[i].magic >> (8u * k)) & 0xFFu);
                continue;
            }
            if (hf[i].checksum || hf[i].role == CBF_ROLE_COMMAND_COUNT || hf[i].kind == CBF_KIND_STRING
                || hf[i].kind == CBF_KIND_BYTES)
                continue; /* zero / empty by default */
            return fail("$.header: missing %s", hf[i].name);
        }
        if (!pack_field(&hf[i], v, header_bytes))
            return 0;
    }
    (void)cbf_header_decode(header_bytes, sizeof header_bytes, &h);
    if (cbf_encode_begin(&w, out_buf, sizeof out_buf, &h) != CBF_OK)
        return fail("%s", "header: cannot encode");
    nr = cbf_record_fields(&rf);
    fcode = role_field(rf, nr, CBF_ROLE_CODE);
    fsize = role_field(rf, nr, CBF_ROLE_ARG_SIZE);
    if (!keep && recs >= 0 && jcount(recs) > 65535u)
        return fail("%s", "too many commands for the count field");
    for (r = recs >= 0 ? nodes[recs].first : -1; r >= 0; r = nodes[r].next, index++) {
        int32_t a, jname, jsize;
        uint32_t code = 0, want_size = 0;
        int has_size;
        long nargs;
        cbf_record_head head;
        char where[64];
        snprintf(where, sizeof where, "$.records[%lu]", (unsigned long)index);
        if (nodes[r].type != J_OBJ)
            return fail("%s: expected an object", where);
        if (!known_keys(r, rf, nr, rec_keys))
            return fail("%s: unknown key", where);
        jname = jget(r, "command");
        if (jget(r, fcode->name) >= 0 && nodes[jget(r, fcode->name)].type != J_NULL) {
            if (!juint(jget(r, fcode->name), 0xFFu, &code))
                return fail("%s: bad command code", where);
        } else {
            char cname[64];
            int c, found = 0;
            if (!jcstr(jname, cname, sizeof cname))
                return fail("%s: needs a code or a known command name", where);
            for (c = 0; c < 256 && !found; c++)
                if (cbf_command_name(c) && strcmp(cbf_command_name(c), cname) == 0) {
                    code = (uint32_t)c;
                    found = 1;
                }
            if (!found)
                return fail("%s: needs a code or a known command name", where);
        }
        if (jname >= 0 && nodes[jname].type != J_NULL) {
            char cname[64];
            const char *known = cbf_command_name((int)code);
            if (!jcstr(jname, cname, sizeof cname) || !known || strcmp(known, cname) != 0)
                return fail("%s.command: does not match the code", where);
        }
        jsize = jget(r, fsize->name);
        has_size = jsize >= 0 && nodes[jsize].type != J_NULL;
        if (has_size && !juint(jsize, 0xFFFFFFFFu, &want_size))
            return fail("%s: bad arg_size", where);
        a = jget(r, "args");
        if (a >= 0 && nodes[a].type != J_NULL) {
            int lay;
            const cbf_field_info *af;
            size_t na, item = 0;
            long group;
            if (nodes[a].type != J_OBJ)
                return fail("%s.args: expected an object", where);
            if (!cbf_command_name((int)code))
                return fail("%s.args: an unknown code takes raw_args only", where);
            lay = choose_layout((int)code, version, a, has_size, want_size);
            if (lay == CBF_LAYOUT__NONE)
                return group_misfit((int)code, version, a, where)
                       ? 0 : fail("%s.args: the keys match no layout of the command", where);
            na = cbf_layout_fields(lay, &af);
            nargs = json_nb(lay, a);
            group = cbf_layout_group(lay, NULL, NULL, &item);
            memset(args, 0, (size_t)nargs);
            for (i = 0; i < na; i++)
                if (!((long)i == group ? pack_group(&af[i], jget(a, af[i].name), args, item)
                                       : pack_field(&af[i], jget(a, af[i].name), args)))
                    return 0;
        } else {
            int32_t raw = jget(r, "raw_args");
            nargs = (raw < 0 || nodes[raw].type == J_NULL) ? 0 : unhex(raw, args, sizeof args);
            if (nargs < 0)
                return fail("%s.raw_args: not hex", where);
        }
        if (has_size && want_size != (uint32_t)nargs)
            return fail("%s: arg_size differs from the number of argument bytes", where);
        if (!keep) {
            if (!cbf_command_name((int)code))
                return fail("%s: unknown command code", where);
            if (!cbf_command_available((int)code, version))
                return fail("%s: the command is not available in the version", where);
            if (cbf_args_layout((int)code, version, (size_t)nargs) == CBF_LAYOUT__NONE)
                return fail("%s: no layout of that size in the version", where);
        }
        memset(&head, 0, sizeof head);
        for (i = 0; i < nr; i++) {
            const cbf_field_info *f = &rf[i];
            uint32_t val = 0, max = f->elem >= 4u ? 0xFFFFFFFFu : ((1u << (8u * f->elem)) - 1u);
            int32_t jv = jget(r, f->name);
            int given = jv >= 0 && nodes[jv].type != J_NULL;
            if (given && f->role != CBF_ROLE_CODE && f->role != CBF_ROLE_ARG_SIZE && !juint(jv, max, &val))
                return fail("%s: %s out of range", where, f->name);
            if (f->role == CBF_ROLE_CODE) val = code;
            else if (f->role == CBF_ROLE_ARG_SIZE) {
                if ((unsigned long)nargs > max)
                    return fail("%s: too many argument bytes", where);
                val = (uint32_t)nargs;
            } else if (f->role == CBF_ROLE_SEQUENCE && !keep) val = index & max;
            else if (f->role == CBF_ROLE_CODE_COPY && (!keep || !given)) val = code;
            else if (f->checksum && (!keep || !given)) val = cbf_args_checksum(args, (size_t)nargs);
            cbf_member_set_uint(f, &head, val);
        }
        if (cbf_encode_record_stored(&w, &head, args, (size_t)nargs) != CBF_OK)
            return fail("%s: cannot encode", where);
    }
    if (trail >= 0) {
        long n = unhex(trail, out_buf + w.len, sizeof out_buf - w.len);
        if (n < 0)
            return fail("%s", "$.trailing: not hex");
        if (n > 0 && !keep)
            return fail("%s", "trailing bytes can only be written with keep_stored");
        if (cbf_encode_bytes(&w, out_buf + w.len, (size_t)n) != CBF_OK)
            return fail("%s", "trailing: cannot encode");
    }
    rc = cbf_encode_end(&w, profile, !keep);
    if (rc < 0)
        return fail("cannot finish the file: %s", cbf_strerror((int)rc));
    if (!keep) {
        cbf_options opt;
        memset(&opt, 0, sizeof opt);
        opt.profile = profile;
        has_error = 0;
        (void)cbf_validate(out_buf, (size_t)rc, &opt, on_error_finding, NULL);
        if (has_error)
            return fail("the result would fail check %s (record %ld)", first_error_check, first_error_record);
    }
    *size = rc;
    return 1;
}

static void put_base64(const uint8_t *p, size_t n)
{
    static const char t[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    size_t i;
    putchar('"');
    for (i = 0; n - i >= 3; i += 3) {
        unsigned long v = ((unsigned long)p[i] << 16) | ((unsigned long)p[i + 1] << 8) | p[i + 2];
        putchar(t[(v >> 18) & 63u]);
        putchar(t[(v >> 12) & 63u]);
        putchar(t[(v >> 6) & 63u]);
        putchar(t[v & 63u]);
    }
    if (n - i == 1) {
        unsigned long v = (unsigned long)p[i] << 16;
        putchar(t[(v >> 18) & 63u]);
        putchar(t[(v >> 12) & 63u]);
        put("==");
    } else if (n - i == 2) {
        unsigned long v = ((unsigned long)p[i] << 16) | ((unsigned long)p[i + 1] << 8);
        putchar(t[(v >> 18) & 63u]);
        putchar(t[(v >> 12) & 63u]);
        putchar(t[(v >> 6) & 63u]);
        putchar('=');
    }
    putchar('"');
}

static void op_encode(int32_t req)
{
    int32_t keep = jget(req, "keep_stored"), prof = jget(req, "profile");
    char pname[64];
    int profile = CBF_PROFILE_DEFAULT;
    long size = 0;
    if (prof >= 0 && nodes[prof].type != J_NULL) {
        if (!jcstr(prof, pname, sizeof pname) || (profile = cbf_profile_find(pname)) < 0) {
            put_error("encode", -1, "unknown profile");
            return;
        }
    }
    enc_err = "encode failed";
    if (!encode(jget(req, "json"), keep >= 0 && nodes[keep].type == J_TRUE, profile, &size)) {
        put_error("encode", -1, enc_err);
        return;
    }
    put("{\"ok\": true, \"bytes\": ");
    put_base64(out_buf, (size_t)size);
    put("}\n");
}

/* Read one line into `req_line`; returns its length, -1 at EOF, -2 when too long (skipped). */
static long read_line(void)
{
    size_t n = 0;
    int c;
    int too_long = 0;
    while ((c = getchar()) != EOF && c != '\n') {
        if (n < sizeof req_line - 1)
            req_line[n++] = (char)c;
        else
            too_long = 1;
    }
    if (c == EOF && n == 0 && !too_long)
        return -1;
    req_line[n] = 0;
    return too_long ? -2 : (long)n;
}

int main(void)
{
    for (;;) {
        long n = read_line();
        int32_t req, op;
        if (n == -1)
            break;
        if (n == -2) {
            put_error("request", -1, "request line too long");
            fflush(stdout);
            continue;
        }
        if (n == 0)
            continue;
        req = jparse(req_line, (size_t)n);
        if (req < 0 || nodes[req].type != J_OBJ) {
            put_error("request", -1, jerr ? jerr : "the request is not a JSON object");
            fflush(stdout);
            continue;
        }
        op = jget(req, "op");
        if (jeq(op, "quit"))
            break;
        if (jeq(op, "decode"))
            op_decode(req);
        else if (jeq(op, "validate"))
            op_validate(req);
        else if (jeq(op, "encode"))
            op_encode(req);
        else
            put("{\"skipped\": true}\n");
        fflush(stdout);
    }
    return 0;
}
