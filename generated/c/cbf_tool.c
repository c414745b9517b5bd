/* cbf_tool.c - `cbf-c`, the reference command-line tool of the C binding:
 * validate CBF files and dump their records with the same header a robot-side
 * integrator copies (cbf.h).
 *
 * GENERATED from spec/cbf.yaml by cbfgen (generator/cbfgen/emit/c). Do not edit.
 *
 *   cbf-c validate [--profile P] [--part-number N] [--cutters TABLE] FILE...
 *   cbf-c dump FILE
 *
 * Exit status: 0 clean, 1 error findings (or a file that cannot be read), 2 usage.
 */
#define CBF_IMPLEMENTATION
#include "cbf.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static uint8_t file_buf[32u << 20];

/* ---- shared by the testee and the tool (generated from common.inc.j2) ---- */

/* Read a whole file into buf; returns its size or -1 (errno in *err). */
static long read_file(const char *path, uint8_t *buf, size_t cap, const char **why)
{
    FILE *fp = fopen(path, "rb");
    size_t n = 0;
    *why = "cannot open";
    if (!fp)
        return -1;
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
        fclose(fp);
        *why = "read error";
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

static const char *current_file;

static void print_finding(void *user, const cbf_finding *f)
{
    (void)user;
    printf("%s: %s %s", current_file, f->severity == CBF_SEVERITY_ERROR ? "error" : "warning", f->check);
    if (f->record >= 0)
        printf(" record %ld", f->record);
    else
        printf(" header");
    printf(" @%lu: %s\n", (unsigned long)f->offset, f->message);
}

static void usage(void)
{
    fputs("usage: cbf-c validate [--profile P] [--part-number N] [--cutters TABLE] FILE...\n"
          "       cbf-c dump FILE\n"
          "profiles:", stderr);
    {
        int p;
        static const char *const names[] = { "default", "implib" };
        for (p = 0; p < CBF_PROFILE__COUNT; p++)
            fprintf(stderr, " %s", names[p]);
    }
    fputs("\n", stderr);
}

static int cmd_validate(int argc, char **argv)
{
    cbf_options opt;
    int i, status = 0, files = 0;
    memset(&opt, 0, sizeof opt);
    opt.profile = CBF_PROFILE_DEFAULT;
    for (i = 0; i < argc; i++) {
        if (strcmp(argv[i], "--profile") == 0 && i + 1 < argc) {
            opt.profile = cbf_profile_find(argv[++i]);
            if (opt.profile < 0) {
                fprintf(stderr, "cbf-c: unknown profile %s\n", argv[i]);
                return 2;
            }
        } else if (strcmp(argv[i], "--part-number") == 0 && i + 1 < argc) {
            opt.part_number = argv[++i];
        } else if (strcmp(argv[i], "--cutters") == 0 && i + 1 < argc) {
            if (!load_cutters(argv[++i])) {
                fprintf(stderr, "cbf-c: %s: cannot read the cutter table (CSV or YAML: name, length, radius)\n", argv[i]);
                return 2;
            }
            opt.cutters = cutters;
            opt.ncutters = ncutters;
        } else if (argv[i][0] == '-' && argv[i][1]) {
            usage();
            return 2;
        }
    }
    for (i = 0; i < argc; i++) {
        const char *why;
        long n, errors;
        if (strcmp(argv[i], "--profile") == 0 || strcmp(argv[i], "--part-number") == 0
            || strcmp(argv[i], "--cutters") == 0) {
            i++;
            continue;
        }
        files++;
        current_file = argv[i];
        n = read_file(argv[i], file_buf, sizeof file_buf, &why);
        if (n < 0) {
            fprintf(stderr, "cbf-c: %s: %s\n", argv[i], why);
            status = 1;
            continue;
        }
        errors = cbf_validate(file_buf, (size_t)n, &opt, print_finding, NULL);
        if (errors > 0)
            status = 1;
        else
            printf("%s: ok\n", argv[i]);
    }
    if (!files) {
        usage();
        return 2;
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
    const char *why;
    long n = read_file(path, file_buf, sizeof file_buf, &why);
    cbf_reader r;
    cbf_record rec;
    const cbf_field_info *fields;
    size_t nf, i;
    int rc;
    if (n < 0) {
        fprintf(stderr, "cbf-c: %s: %s\n", path, why);
        return 1;
    }
    if (cbf_reader_init(&r, file_buf, (size_t)n) != CBF_OK) {
        fprintf(stderr, "cbf-c: %s: %s\n", path, cbf_strerror(CBF_ERR_TRUNCATED_HEADER));
        return 1;
    }
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
    if (rc < 0) {
        printf("error: %s at offset %lu\n", cbf_strerror(rc), (unsigned long)r.pos);
        return 1;
    }
    if (r.trailing)
        printf("trailing %lu byte(s) at %lu\n", (unsigned long)r.trailing, (unsigned long)r.pos);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc >= 3 && strcmp(argv[1], "validate") == 0)
        return cmd_validate(argc - 2, argv + 2);
    if (argc == 3 && strcmp(argv[1], "dump") == 0)
        return cmd_dump(argv[2]);
    usage();
    return 2;
}
