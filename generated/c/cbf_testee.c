/* cbf_testee.c - conformance testee of the C binding (conformance/PROTOCOL.md).
 *
 * GENERATED from spec/cbf.yaml by cbfgen (generator/cbfgen/emit/c). Do not edit.
 *
 * Reads JSON lines on stdin ({"op": "decode" | "validate" | "encode" | "quit"})
 * and answers each with one JSON line on stdout. It only answers; the runner
 * judges. No malloc: every buffer is static.
 */
#define CBF_IMPLEMENTATION
#include "cbf.h"

#include <float.h>
#include <stdarg.h>
#include <errno.h>
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

/* Read a whole file into buf; returns its size or -1 (what went wrong in *why, as cbf says it). */
static long read_file(const char *path, uint8_t *buf, size_t cap, const char **why)
{
    FILE *fp;
    size_t n = 0;
    errno = 0;
    fp = fopen(path, "rb");
    *why = "cannot open";
    if (!fp) {
        *why = errno == ENOENT ? "no such file" : errno == EACCES ? "permission denied"
             : errno == EISDIR ? "is a directory" : "cannot open";
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

/* ---- cutter tables (6.1.2): CSV with a header row, or YAML rows of name, length, radius ---- */
#define MAX_CUTTERS 4096
#define CUTTER_NAME 128
static char cutter_names[MAX_CUTTERS][CUTTER_NAME];
static cbf_cutter cutters[MAX_CUTTERS];
static size_t ncutters;
static uint8_t cutter_text[1u << 20];

static int is_blank(int c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

/* Trim spaces and one pair of quotes; writes a NUL at the end. */
static char *trim(char *s)
{
    size_t n;
    while (*s && is_blank((unsigned char)*s))
        s++;
    n = strlen(s);
    while (n && is_blank((unsigned char)s[n - 1]))
        s[--n] = 0;
    if (n >= 2 && (s[0] == '"' || s[0] == '\'') && s[n - 1] == s[0]) {
        s[n - 1] = 0;
        s++;
    }
    return s;
}

static int parse_double(const char *s, double *out)
{
    char *end;
    if (!*s)
        return 0;
    *out = strtod(s, &end);
    return *trim(end) == 0;
}

static int cutter_add(const char *name, const char *length, const char *radius)
{
    size_t n = strlen(name);
    double l, r;
    if (ncutters == MAX_CUTTERS || n >= CUTTER_NAME || !parse_double(length, &l) || !parse_double(radius, &r))
        return 0;
    memcpy(cutter_names[ncutters], name, n + 1);
    cutters[ncutters].name = cutter_names[ncutters];
    cutters[ncutters].length = l;
    cutters[ncutters].radius = r;
    ncutters++;
    return 1;
}

/* CSV: the first row names the columns (name, length, radius in any order). */
static int cutters_csv(char *text)
{
    char *line, *save = text;
    int col[3] = { -1, -1, -1 }, first = 1;
    static const char *const want[3] = { "name", "length", "radius" };
    while ((line = save) != NULL && *line) {
        char *cells[32];
        int nc = 0, k;
        char *p = line;
        save = strchr(line, '\n');
        if (save)
            *save++ = 0;
        if (!*trim(line))
            continue;
        cells[nc++] = p;
        for (; *p; p++) {
            if (*p == ',') {
                *p = 0;
                if (nc < 32)
                    cells[nc++] = p + 1;
            }
        }
        for (k = 0; k < nc; k++)
            cells[k] = trim(cells[k]);
        if (first) {
            int i;
            first = 0;
            for (k = 0; k < nc; k++)
                for (i = 0; i < 3; i++)
                    if (strcmp(cells[k], want[i]) == 0)
                        col[i] = k;
            if (col[0] < 0 || col[1] < 0 || col[2] < 0)
                return 0;
            continue;
        }
        if (col[0] >= nc || col[1] >= nc || col[2] >= nc)
            return 0;
        if (!cutter_add(cells[col[0]], cells[col[1]], cells[col[2]]))
            return 0;
    }
    return 1;
}

/* YAML, the forms a cutter table takes: an optional "cutters:" key, then
 * "- name: X" items with "length:"/"radius:" lines, or "- {name: X, length: L, radius: R}". */
static int cutters_yaml(char *text)
{
    char *save = text, *line;
    char name[CUTTER_NAME] = "", length[64] = "", radius[64] = "";
    int open = 0;
    while ((line = save) != NULL && *line) {
        char *s, *colon;
        save = strchr(line, '\n');
        if (save)
            *save++ = 0;
        if ((s = strchr(line, '#')) != NULL)
            *s = 0;
        s = trim(line);
        if (!*s || strcmp(s, "---") == 0 || strcmp(s, "cutters:") == 0)
            continue;
        if (*s == '-') {
            if (open && !cutter_add(name, length, radius))
                return 0;
            open = 1;
            name[0] = length[0] = radius[0] = 0;
            s = trim(s + 1);
            if (*s == '{') {
                char *part = s + 1, *close = strrchr(s, '}');
                if (!close)
                    return 0;
                *close = 0;
                while (part) {
                    char *next = strchr(part, ',');
                    if (next)
                        *next++ = 0;
                    colon = strchr(part, ':');
                    if (colon) {
                        char *k, *v;
                        *colon = 0;
                        k = trim(part);
                        v = trim(colon + 1);
                        if (strcmp(k, "name") == 0 && strlen(v) < sizeof name) strcpy(name, v);
                        else if (strcmp(k, "length") == 0 && strlen(v) < sizeof length) strcpy(length, v);
                        else if (strcmp(k, "radius") == 0 && strlen(v) < sizeof radius) strcpy(radius, v);
                    }
                    part = next;
                }
                continue;
            }
            if (!*s)
                continue;
        }
        colon = strchr(s, ':');
        if (!colon || !open)
            return 0;
        *colon = 0;
        {
            char *k = trim(s), *v = trim(colon + 1);
            if (strcmp(k, "name") == 0 && strlen(v) < sizeof name) strcpy(name, v);
            else if (strcmp(k, "length") == 0 && strlen(v) < sizeof length) strcpy(length, v);
            else if (strcmp(k, "radius") == 0 && strlen(v) < sizeof radius) strcpy(radius, v);
        }
    }
    if (open && !cutter_add(name, length, radius))
        return 0;
    return 1;
}

static int load_cutters(const char *path)
{
    const char *why;
    long n = read_file(path, cutter_text, sizeof cutter_text - 1, &why);
    size_t plen = strlen(path);
    ncutters = 0;
    if (n < 0)
        return 0;
    cutter_text[n] = 0;
    if ((plen >= 5 && strcmp(path + plen - 5, ".yaml") == 0) || (plen >= 4 && strcmp(path + plen - 4, ".yml") == 0))
        return cutters_yaml((char *)cutter_text);
    return cutters_csv((char *)cutter_text);
}

/* ---- machine files (decision L1, check machine_limits; machine_file.inc.j2) ----
 * The JSON form of `machine:` in spec/cbf.yaml (schema generated/python/cbf/machine.schema.json):
 *   {"name": "...", "limits": {"<limit>": {"unit": "<the spec's unit>", "min": N | [N, ...],
 *    "max": N | [N, ...], "axes": [...], "doc": "..."}, ...}}
 * every limit of cbf_machine_limit_names with unit, min and max; one number per axis for a box;
 * min <= max. cbf (Python) reads the same file, and YAML too; cbf-c reads JSON only. A bad
 * file gives one line naming the file and the JSON path (or line and column), as cbf says it. */
#include <float.h>
#include <stdarg.h>

static cbf_machine machine_file;
static char machine_why[8192];
static char machine_text[1u << 16];

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
                return mj_fail(j, path, "duplicate key '%s'", key);
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
    return mj_fail(j, path, "unknown key '%s' (known: %s)", key, list);
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
    const char *why;
    long n = read_file(path, (uint8_t *)machine_text, sizeof machine_text - 1, &why);
    mjson j;
    unsigned has_limits = 0;
    int li, a;
    if (n < 0) {
        (void)snprintf(machine_why, sizeof machine_why, "%s: cannot read machine file (%s)", path, why);
        return 0;
    }
    machine_text[n] = 0;
    memset(&machine_file, 0, sizeof machine_file);
    j.s = machine_text;
    j.n = (size_t)n;
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

/* One field of a byte image, as canonical JSON (PROTOCOL.md). */
static void put_field(const cbf_field_info *f, const uint8_t *base)
{
    size_t size = (size_t)f->elem * f->count;
    unsigned i;
    printf("\"%s\": ", f->name);
    switch (f->kind) {
    case CBF_KIND_UINT:
        printf("%lu", (unsigned long)cbf_field_uint(f, base));
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
    case CBF_KIND_UINT: {
        uint32_t x, max = f->elem >= 4u ? 0xFFFFFFFFu : ((1u << (8u * f->elem)) - 1u);
        if (!juint(v, max, &x))
            return fail("field %s: not an unsigned integer of its size", f->name);
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
            put(", \"args\": {");
            na = cbf_layout_fields(rec.layout, &af);
            for (i = 0; i < na; i++) {
                if (i)
                    put(", ");
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

static int choose_layout(int code, int version, int32_t args, int has_size, uint32_t want_size)
{
    int cands[CBF_LAYOUT__COUNT + 1], n, k, lay;
    n = cbf_args_candidates(code, version, cands, CBF_LAYOUT__COUNT);
    for (k = 0; k < n; k++)
        if (keys_match(cands[k], args) && (!has_size || (uint32_t)cbf_layout_size(cands[k]) == want_size))
            return cands[k];
    for (lay = 0; lay < CBF_LAYOUT__COUNT; lay++)
        if (cbf_layout_code(lay) == code && keys_match(lay, args)
            && (!has_size || (uint32_t)cbf_layout_size(lay) == want_size))
            return lay;
    return CBF_LAYOUT__NONE;
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
            size_t na;
            if (nodes[a].type != J_OBJ)
                return fail("%s.args: expected an object", where);
            if (!cbf_command_name((int)code))
                return fail("%s.args: an unknown code takes raw_args only", where);
            lay = choose_layout((int)code, version, a, has_size, want_size);
            if (lay == CBF_LAYOUT__NONE)
                return fail("%s.args: the keys match no layout of the command", where);
            na = cbf_layout_fields(lay, &af);
            nargs = cbf_layout_size(lay);
            memset(args, 0, (size_t)nargs);
            for (i = 0; i < na; i++)
                if (!pack_field(&af[i], jget(a, af[i].name), args))
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
