/* cbf_tool.c - `cbf-c`, the reference command-line tool of the C binding:
 * validate CBF files and dump their records with the same header a robot-side
 * integrator copies (cbf.h).
 *
 * GENERATED from spec/cbf.yaml by cbfgen (generator/cbfgen/emit/c). Do not edit.
 *
 *   cbf-c validate [--profile P] [--part-number N] [--cutters TABLE] [--machine FILE] [--max-findings N] FILE...
 *
 * validate prints what `cbf validate` prints, in its order (header first, then by record,
 * check order, offset), at most --max-findings findings a file (default 50, 0 for all).
 *   cbf-c dump FILE
 *   cbf-c --version
 *
 * Exit status, as `cbf` (README, "Exit codes"): 0 ok; 1 validate found an
 * error-severity finding; 2 bad usage or input that is not a CBF file to read:
 * missing, a directory, no permission, larger than a CBF file can be, shorter
 * than the header, both magic numbers wrong, and for dump a record cut short.
 * Each such input gets one line on stderr naming the file and what is wrong.
 * validate with several files exits with the highest status of any of them.
 */
#define CBF_IMPLEMENTATION
#include "cbf.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The most a CBF file can hold: the header and every record at its largest. */
#define MAX_FILE_SIZE ((unsigned long)CBF_HEADER_SIZE + ((unsigned long)CBF_LIMIT_MAX_COMMANDS + 1ul) \
                       * ((unsigned long)CBF_RECORD_HEAD_SIZE + (unsigned long)CBF_LIMIT_MAX_ARG_SIZE))
static uint8_t file_buf[MAX_FILE_SIZE + 1ul];
enum { EXIT_OK = 0, EXIT_FINDINGS = 1, EXIT_USAGE = 2 };

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

static const char *const profile_names[] = { "default", "implib" };
/* The spec's checks in their order: findings print in cbf's one order (header first, then by
 * record, check order, offset, message), whatever order the engine reports them in. */
static const char *const check_order[] = { "4.2", "4.3", "6.1.1", "part_number_first", "6.1.2", "6.2.1", "6.2.2", "6.3.1", "6.3.2", "6.4.1", "6.4.2", "6.4.3", "6.4.4", "6.4.5", "7.2.3.1", "7.2.2.4", "version_supported", "unknown_command", "trailing_bytes", "reserved_nonzero", "string_tail", "string_ascii", "non_finite", "speed_positive", "accel_positive", "cutter_positive", "normal_nonzero", "checkpoint_range", "checkpoint_falling", "fcparms_order", "orientation_jump", "machine_limits", "shape" };

typedef struct held_finding {
    long record;   /* -1: the header and the file */
    int order;     /* index in check_order */
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
    for (i = 0; i < (int)(sizeof check_order / sizeof check_order[0]); i++)
        if (strcmp(check_order[i], id) == 0)
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
    printf("%s:%lu: %s %s (", file, f->offset, f->error ? "error" : "warning", f->check);
    if (f->record >= 0)
        printf("record %ld", f->record);
    else
        printf("header");
    printf("): %s\n", f->message);
}

/* Read path into file_buf; 0 and one line on stderr when it cannot be read, is
 * larger than a CBF file can be, or is not a CBF file: shorter than the header,
 * or every magic number of the header wrong (the test cbf applies, from the
 * same fields of the model). */
static int read_cbf(const char *path, size_t *size)
{
    const char *why;
    const cbf_field_info *fields;
    size_t nf, i, nmagic = 0, nright = 0, first = 0;
    long n = read_file(path, file_buf, sizeof file_buf, &why);
    if (n < 0) {
        fprintf(stderr, "cbf-c: %s: %s\n", path, why);
        return 0;
    }
    if ((unsigned long)n > MAX_FILE_SIZE) {
        fprintf(stderr, "cbf-c: %s: larger than %lu bytes, the most a CBF file can hold\n", path, MAX_FILE_SIZE);
        return 0;
    }
    if ((size_t)n < CBF_HEADER_SIZE) {
        fprintf(stderr, "cbf-c: %s: offset 0: file is %ld bytes, the header needs %d: not a CBF file\n", path, n,
                CBF_HEADER_SIZE);
        return 0;
    }
    nf = cbf_header_fields(cbf_version_header_layout(CBF_DEFAULT_VERSION), &fields);
    for (i = 0; i < nf; i++) {
        if (!(fields[i].flags & CBF_FIELD_MAGIC))
            continue;
        if (!nmagic++)
            first = i;
        if (cbf_field_uint(&fields[i], file_buf) == fields[i].magic)
            nright++;
    }
    if (nmagic && !nright) {
        int text = 1;
        for (i = 0; i < (size_t)n && i < 256u && text; i++)
            text = (file_buf[i] >= 0x20u && file_buf[i] < 0x7Fu) || file_buf[i] == '\t' || file_buf[i] == '\r'
                   || file_buf[i] == '\n';
        fprintf(stderr, "cbf-c: %s: offset %u: not a CBF file: no magic number of the header is right (",
                path, (unsigned)fields[first].offset);
        for (i = 0; i < nf; i++)
            if (fields[i].flags & CBF_FIELD_MAGIC)
                fprintf(stderr, "%s%s", i == first ? "" : ", ", fields[i].name);
        fprintf(stderr, ")%s\n", text ? "; it is text" : "");
        return 0;
    }
    *size = (size_t)n;
    return 1;
}

static void usage(void)
{
    fputs("usage: cbf-c validate [--profile P] [--part-number N] [--cutters TABLE] [--machine FILE] [--max-findings N] "
          "FILE...\n"
          "       cbf-c dump FILE\n"
          "       cbf-c --version\n"
          "profiles:", stderr);
    {
        int p;
        for (p = 0; p < CBF_PROFILE__COUNT; p++)
            fprintf(stderr, " %s", profile_names[p]);
    }
    fputs("\n", stderr);
}

/* A count for --max-findings: digits only; -1 when it is not one. */
static long parse_count(const char *s)
{
    char *end;
    unsigned long v;
    if (!*s || strspn(s, "0123456789") != strlen(s))
        return -1;
    errno = 0;
    v = strtoul(s, &end, 10);
    if (errno || v > 1000000000ul)
        return -1;
    return (long)v;
}

static int cmd_validate(int argc, char **argv)
{
    cbf_options opt;
    int i, status = 0, files = 0;
    size_t k, max_findings = 50;
    memset(&opt, 0, sizeof opt);
    opt.profile = CBF_PROFILE_DEFAULT;
    for (i = 0; i < argc; i++) {
        if (strcmp(argv[i], "--profile") == 0 && i + 1 < argc) {
            opt.profile = cbf_profile_find(argv[++i]);
            if (opt.profile < 0) {
                fprintf(stderr, "cbf-c: unknown profile %s\n", argv[i]);
                return EXIT_USAGE;
            }
        } else if (strcmp(argv[i], "--part-number") == 0 && i + 1 < argc) {
            opt.part_number = argv[++i];
        } else if (strcmp(argv[i], "--cutters") == 0 && i + 1 < argc) {
            if (!load_cutters(argv[++i])) {
                fprintf(stderr, "cbf-c: %s: cannot read the cutter table (CSV or YAML: name, length, radius)\n", argv[i]);
                return EXIT_USAGE;
            }
            opt.cutters = cutters;
            opt.ncutters = ncutters;
        } else if (strcmp(argv[i], "--machine") == 0 && i + 1 < argc) { /* machine limits (L1): errors */
            if (!load_machine(argv[++i])) {
                fprintf(stderr, "cbf-c: %s\n", machine_why);
                return EXIT_USAGE;
            }
            opt.machine = &machine_file;
        } else if (strcmp(argv[i], "--max-findings") == 0 && i + 1 < argc) {
            long v = parse_count(argv[++i]);
            if (v < 0) {
                fprintf(stderr, "cbf-c: --max-findings: not a count: %s\n", argv[i]);
                return EXIT_USAGE;
            }
            max_findings = (size_t)v;
        } else if (argv[i][0] == '-' && argv[i][1]) {
            usage();
            return EXIT_USAGE;
        }
    }
    for (i = 0; i < argc; i++) {
        size_t n;
        long errors;
        if (strcmp(argv[i], "--profile") == 0 || strcmp(argv[i], "--part-number") == 0
            || strcmp(argv[i], "--cutters") == 0 || strcmp(argv[i], "--machine") == 0
            || strcmp(argv[i], "--max-findings") == 0) {
            i++;
            continue;
        }
        files++;
        if (!read_cbf(argv[i], &n)) {
            status = EXIT_USAGE;
            continue;
        }
        nheld = 0;
        errors = cbf_validate(file_buf, n, &opt, hold_finding, NULL);
        if (out_of_memory) {
            fprintf(stderr, "cbf-c: %s: out of memory holding its findings\n", argv[i]);
            return EXIT_USAGE;
        }
        if (errors > 0 && status < EXIT_FINDINGS)
            status = EXIT_FINDINGS;
        qsort(held, nheld, sizeof *held, finding_cmp);
        for (k = 0; k < nheld; k++) {
            if (max_findings == 0 || k < max_findings)
                print_finding(argv[i], &held[k]);
            free(held[k].message);
        }
        if (max_findings && nheld > max_findings)
            printf("%s: %lu more finding(s) not shown (--max-findings 0 prints all)\n", argv[i],
                   (unsigned long)(nheld - max_findings));
        printf("%s: %s: %ld error(s), %ld warning(s) [profile %s]\n", argv[i], errors > 0 ? "FAIL" : "ok", errors,
               (long)nheld - errors, profile_names[opt.profile]);
    }
    if (!files) {
        usage();
        return EXIT_USAGE;
    }
    return status;
}

static void dump_field(const cbf_field_info *f, const uint8_t *base)
{
    size_t size = (size_t)f->elem * f->count, i;
    printf(" %s=", f->name);
    switch (f->kind) {
    case CBF_KIND_UINT:
        printf("%lu", (unsigned long)cbf_field_uint(f, base));
        break;
    case CBF_KIND_FLOAT:
        for (i = 0; i < f->count; i++)
            printf("%s%.9g", i ? "," : "", (double)cbf_field_float(f, base, (unsigned)i));
        if (f->unit)
            printf("%s", f->unit);
        break;
    case CBF_KIND_STRING:
        putchar('"');
        for (i = 0; i < size && base[f->offset + i] != 0u; i++) {
            unsigned c = base[f->offset + i];
            if (c >= 0x20u && c < 0x7Fu && c != '"' && c != '\\')
                putchar((int)c);
            else
                printf("\\x%02x", c);
        }
        putchar('"');
        break;
    default:
        for (i = 0; i < size; i++)
            printf("%02x", base[f->offset + i]);
        break;
    }
}

static int cmd_dump(const char *path)
{
    size_t n;
    cbf_reader r;
    cbf_record rec;
    const cbf_field_info *fields;
    size_t nf, i;
    int rc;
    if (!read_cbf(path, &n))
        return EXIT_USAGE;
    /* the records are framed first, as cbf decodes before it prints: a cut record is one line */
    if (cbf_reader_init(&r, file_buf, n) != CBF_OK)
        return EXIT_USAGE; /* read_cbf refused a short file already */
    while ((rc = cbf_next_record(&r, &rec)) == 1) {}
    if (rc < 0) {
        fprintf(stderr, "cbf-c: %s: offset %lu: record %lu is cut: %lu byte(s) left, the header counts %lu record(s) "
                "(%s)\n", path, (unsigned long)r.pos, (unsigned long)r.index, (unsigned long)(n - r.pos),
                (unsigned long)r.header.count, cbf_strerror(rc));
        return EXIT_USAGE;
    }
    (void)cbf_reader_init(&r, file_buf, n);
    printf("header version %u.%u (%s)", r.header.major, r.header.minor,
           r.header.version < 0 ? "unknown" : cbf_version_name(r.header.version));
    nf = cbf_header_fields(r.header.layout, &fields);
    for (i = 0; i < nf; i++)
        dump_field(&fields[i], file_buf);
    putchar('\n');
    while ((rc = cbf_next_record(&r, &rec)) == 1) {
        const char *name = cbf_command_name(rec.command);
        printf("%lu @%lu %s", (unsigned long)rec.index, (unsigned long)rec.offset, name ? name : "?");
        nf = cbf_record_fields(&fields);
        for (i = 0; i < nf; i++)
            dump_field(&fields[i], file_buf + rec.offset);
        if (rec.layout != CBF_LAYOUT__NONE) {
            nf = cbf_layout_fields(rec.layout, &fields);
            printf(" |");
            for (i = 0; i < nf; i++)
                dump_field(&fields[i], rec.args);
        } else {
            printf(" | raw=");
            for (i = 0; i < rec.nargs; i++)
                printf("%02x", rec.args[i]);
        }
        putchar('\n');
    }
    if (r.trailing)
        printf("trailing %lu byte(s) at %lu\n", (unsigned long)r.trailing, (unsigned long)r.pos);
    return EXIT_OK;
}

int main(int argc, char **argv)
{
    if (argc == 2 && strcmp(argv[1], "--version") == 0) {
        printf("cbf-c %s (spec %s)\n", CBF_TOOLKIT_VERSION, CBF_SPEC_REVISION);
        return EXIT_OK;
    }
    if (argc >= 3 && strcmp(argv[1], "validate") == 0)
        return cmd_validate(argc - 2, argv + 2);
    if (argc == 3 && strcmp(argv[1], "dump") == 0)
        return cmd_dump(argv[2]);
    usage();
    return EXIT_USAGE;
}
