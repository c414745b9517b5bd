/* cbf_tool.c - `cbf-c`, the reference command-line tool of the C binding:
 * validate CBF files and dump their records with the same header a robot-side
 * integrator copies (cbf.h). Its engine is cbf_tools.h; this file is its command line.
 *
 * GENERATED from spec/cbf.yaml by cbfgen (generator/cbfgen/emit/c). Do not edit.
 *
 *   cbf-c validate [--profile P] [--part-number N] [--cutters TABLE] [--machine FILE] [--max-findings N] FILE...
 *
 * validate prints what `cbf validate` prints, in its order (header first, then by record,
 * check order, offset), at most --max-findings findings a file (default 50, 0 for all).
 *   cbf-c dump [--path] FILE   (--path: each motion record's drawn path, cbf_motion_path)
 *   cbf-c encode [--profile P] [--version V] [--input-format cut] FILE.cut -o OUT
 *                              (CUT text to the CBF it encodes to, cbf_cut_encode_as, written to OUT as
 *                              cbf encode writes: atomically, every write checked; -o - is stdout)
 *   cbf-c sniff FILE           (cut or cbf: whether the engine reads it as CUT text, cbf_tool_is_cut)
 *   cbf-c --version
 *
 * Exit status, as `cbf` (README, "Exit codes"): 0 ok; 1 validate found an
 * error-severity finding; 2 bad usage or input that is not a CBF file to read:
 * missing, a directory, no permission, larger than a CBF file can be, shorter
 * than the header, both magic numbers wrong, and for dump a record cut short.
 * Each such input gets one line on stderr naming the file and what is wrong.
 * validate with several files exits with the highest status of any of them.
 */
#define _POSIX_C_SOURCE 200809L /* stat, open, fstat: the file layer reads regular files only (issue #35) */
#define CBF_IMPLEMENTATION
#define CBF_TOOLS_IMPLEMENTATION
#include "cbf.h"
#include "cbf_tools.h"

/* ==== BEGIN tools/cli.c: verbatim from generator/cbfgen/emit/c/tools/cli.c, edit it there ==== */
#line 1 "generator/cbfgen/emit/c/tools/cli.c"
/* ---- cbf-c's command line: a thin shell over the engine (cbf_tools.h) ----
 * It parses the arguments, reads each file whole into memory and hands it to the engine with a sink that
 * writes to stdout and stderr. */

/* Standard output is checked as cbf checks it: the first failed write's errno is kept, and at the end a
 * stdout that failed is one line and exit 2, what went to a regular file there cut off again (nothing that
 * looks complete stays). cbf-c encode -o - writes through the file layer, which checks the same way. */
static int stdout_errno;

static void write_stdout(void *user, const char *text, size_t len)
{
    (void)user;
    errno = 0;
    if (fwrite(text, 1, len, stdout) != len && !stdout_errno)
        stdout_errno = errno ? errno : EIO;
}

#if defined(CBF_TOOLS_POSIX) && !defined(__wasi__)
static off_t stdout_start = -1; /* where this process began writing a regular file on stdout */

static void stdout_begin(void)
{
    struct stat st;
    if (fstat(1, &st) == 0 && S_ISREG(st.st_mode))
        stdout_start = lseek(1, 0, SEEK_CUR);
}

static void stdout_cut_off(void)
{
    if (stdout_start >= 0 && ftruncate(1, stdout_start) != 0)
        stdout_start = -1; /* cut off as far as it could be */
}
#else
static void stdout_begin(void) {}
static void stdout_cut_off(void) {}
#endif

/* The exit status once stdout is flushed: status, or 2 and one line when a write to it failed. */
static int stdout_end(int status)
{
    errno = 0;
    if (fflush(stdout) != 0 && !stdout_errno)
        stdout_errno = errno ? errno : EIO;
    if (ferror(stdout) && !stdout_errno)
        stdout_errno = EIO;
    if (!stdout_errno)
        return status;
    stdout_cut_off();
    fprintf(stderr, "cbf-c: standard output: cannot write (%s)\n", strerror(stdout_errno));
    return CBF_TOOL_EXIT_USAGE;
}

static void write_stderr(void *user, const char *text, size_t len)
{
    (void)user;
    (void)fwrite(text, 1, len, stderr);
}

static const cbf_tool_sink std_sink = { write_stdout, write_stderr, NULL };

static void usage(void)
{
    int p;
    fputs("usage: cbf-c validate [--profile P] [--part-number N] [--cutters TABLE] [--machine FILE] [--max-findings N] "
          "FILE...\n"
          "       cbf-c dump [--path] FILE\n"
          "       cbf-c encode [--profile P] [--version V] [--input-format cut] FILE.cut -o OUT   (CUT text to CBF;\n"
          "                    -o - for standard output; cbf-c reads CUT text, not JSON)\n"
          "       cbf-c encode --check [--profile P] [--version V] FILE.cut...   (only check that each encodes)\n"
          "       cbf-c sniff FILE                      (cut or cbf: how the workbench reads it)\n"
          "       cbf-c --version\n"
          "profiles:", stderr);
    for (p = 0; p < CBF_PROFILE__COUNT; p++)
        fprintf(stderr, " %s", cbf_tool_profile_names[p]);
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

/* The file at path into *buf (the heap's, sized to the file: a buffer of the largest CBF file, 17 MB, was
 * the WebAssembly module's initial memory, paid by every instance); its size, or -1 and one line on stderr
 * when it cannot be read. */
static long read_cbf(const char *path, uint8_t **buf)
{
    const char *why;
    long n = cbf_tool_read_input_alloc(path, CBF_TOOL_MAX_FILE_SIZE, buf, &why);
    if (n == -2) /* larger than a CBF file can be: from its size, unread (cbf's words) */
        fprintf(stderr, "cbf-c: %s: larger than %lu bytes, the most a CBF file can hold\n", cbf_tool_name(path),
                (unsigned long)CBF_TOOL_MAX_FILE_SIZE);
    else if (n < 0)
        fprintf(stderr, "cbf-c: %s: %s\n", cbf_tool_name(path), why);
    return n < 0 ? -1 : n;
}

/* The options in argv[0..argc) that take a value: their names. */
static const char *const value_options[] = { "--profile", "--part-number", "--cutters", "--machine",
                                             "--max-findings" };

static int takes_value(const char *arg)
{
    size_t k;
    for (k = 0; k < sizeof value_options / sizeof value_options[0]; k++)
        if (strcmp(arg, value_options[k]) == 0)
            return 1;
    return 0;
}

/* One option and its value into o; 0 and one line on stderr (usage for an unknown option). */
static int parse_option(const char *arg, const char *value, cbf_tool_options *o)
{
    if (strcmp(arg, "--profile") == 0) {
        o->validate.profile = cbf_profile_find(value);
        if (o->validate.profile < 0)
            fprintf(stderr, "cbf-c: unknown profile %s\n", cbf_quoted(value, CBF_QUOTE_NAME));
        return o->validate.profile >= 0;
    }
    if (strcmp(arg, "--part-number") == 0) {
        o->validate.part_number = value;
        return 1;
    }
    if (strcmp(arg, "--cutters") == 0 || strcmp(arg, "--machine") == 0) { /* machine limits: errors */
        int ok = arg[2] == 'c' ? cbf_tool_cutters_file(value, &o->validate) : cbf_tool_machine_file(value, &o->validate);
        if (!ok)
            fprintf(stderr, "cbf-c: %s\n", cbf_quoted(cbf_tool_why(), CBF_QUOTE_TEXT)); /* names the file, the line and the limit (issue 28) */
        return ok;
    }
    {
        long v = parse_count(value);
        if (v < 0)
            fprintf(stderr, "cbf-c: --max-findings: not a count: %s\n", cbf_quoted(value, CBF_QUOTE_NAME));
        o->max_findings = (size_t)v;
        return v >= 0;
    }
}

static int cmd_validate(int argc, char **argv)
{
    cbf_tool_options o;
    int i, status = CBF_TOOL_EXIT_OK, files = 0;
    memset(&o, 0, sizeof o);
    o.validate.profile = CBF_TOOL_DEFAULT_PROFILE;
    o.max_findings = 50;
    for (i = 0; i < argc; i++) {
        if (takes_value(argv[i]) && i + 1 < argc) {
            if (!parse_option(argv[i], argv[i + 1], &o))
                return CBF_TOOL_EXIT_USAGE;
            i++;
        } else if (argv[i][0] == '-' && argv[i][1]) {
            usage();
            return CBF_TOOL_EXIT_USAGE;
        }
    }
    for (i = 0; i < argc; i++) {
        long n;
        int st;
        uint8_t *buf;
        if (takes_value(argv[i])) {
            i++;
            continue;
        }
        files++;
        n = read_cbf(argv[i], &buf);
        st = n < 0 ? CBF_TOOL_EXIT_USAGE : cbf_tool_validate_buffer(argv[i], buf, (size_t)n, &o, &std_sink);
        free(buf);
        if (st == CBF_TOOL_OUT_OF_MEMORY)
            return CBF_TOOL_EXIT_USAGE;
        if (st > status)
            status = st;
    }
    if (!files) {
        usage();
        return CBF_TOOL_EXIT_USAGE;
    }
    return status;
}

static int cmd_dump(const char *path, int drawn)
{
    uint8_t *buf;
    long n = read_cbf(path, &buf);
    int st;
    if (n < 0)
        return CBF_TOOL_EXIT_USAGE;
    st = drawn ? cbf_tool_path_buffer(path, buf, (size_t)n, &std_sink)
               : cbf_tool_dump_buffer(path, buf, (size_t)n, &std_sink);
    free(buf);
    return st;
}

/* The writable version named by its id ("4.0"), or -1 and one line on stderr naming the writable ones. */
static int parse_version(const char *value)
{
    char list[128];
    size_t used = 0;
    int v;
    for (v = 0; v < CBF__NVERSIONS; v++)
        if (cbf_version_writable(v) && strcmp(cbf_version_name(v), value) == 0)
            return v;
    list[0] = '\0';
    for (v = 0; v < CBF__NVERSIONS; v++)
        if (cbf_version_writable(v) && used < sizeof list)
            used += (size_t)snprintf(list + used, sizeof list - used, "%s%s", used ? ", " : "", cbf_version_name(v));
    fprintf(stderr, "cbf-c: --version: not a version cbf-c writes: %s (writable: %s)\n",
            cbf_quoted(value, CBF_QUOTE_NAME), list);
    return -1;
}

/* Whether text is canonical JSON rather than CUT, as cbf encode tells them apart: a name ending in .json,
 * or text whose first character (after white space) is '{'. */
static int looks_like_json(const char *path, const uint8_t *text, size_t n)
{
    size_t pn = strlen(path), i = 0;
    if (pn >= 5u && strcmp(path + pn - 5u, ".json") == 0)
        return 1;
    while (i < n && strchr(" \t\n\r\v\f", text[i]) && text[i])
        i++;
    return i < n && text[i] == '{';
}

/* Whether text holds nothing but white space (cbf encode: "empty input: nothing to encode"). */
static int is_blank(const uint8_t *text, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        if (!text[i] || !strchr(" \t\n\r\v\f\x1c\x1d\x1e\x1f", text[i]))
            return 0;
    return 1;
}

/* What cbf-c encode is asked: the options of cbf encode that CUT input has. */
typedef struct encode_options {
    int profile, version, keep, json; /* json: 1 --input-format json, 0 cut, -1 from the name or the text */
    const char *output;               /* NULL with --check: nothing is written */
} encode_options;

/* One input of cbf-c encode: its CBF written to o->output (or, with --check, only made); CBF_TOOL_EXIT_OK,
 * or CBF_TOOL_EXIT_USAGE after one line on stderr naming the file and what is wrong. */
static int encode_one(const char *path, const encode_options *o)
{
    static char why[2u * CBF_TOOL_NAME_BYTES + 256u];
    uint8_t *text, *cbf = NULL;
    const char *cause;
    long n, len;
    size_t bad, k;
    unsigned long line = 1;
    if (o->output && !cbf_tool_check_output(o->output, why, sizeof why)) { /* before the work, as cbf does */
        fprintf(stderr, "cbf-c: %s\n", why);
        return CBF_TOOL_EXIT_USAGE;
    }
    n = cbf_tool_read_input_alloc(path, CBF_TOOL_MAX_CUT_SIZE, &text, &cause);
    if (n == -2) /* from its size, unread where it has one: cbf's line */
        fprintf(stderr, "cbf-c: %s: larger than %lu bytes, the most the text of a CBF file can hold\n",
                cbf_tool_name(path), (unsigned long)CBF_TOOL_MAX_CUT_SIZE);
    else if (n < 0)
        fprintf(stderr, "cbf-c: %s: %s\n", cbf_tool_name(path), cause);
    if (n < 0)
        return CBF_TOOL_EXIT_USAGE;
    bad = cbf_utf8_prefix(text, (size_t)n); /* the runtime's one UTF-8 reader (quote.c) */
    if (bad < (size_t)n) { /* text is UTF-8 before anything else is asked of it: cbf's line */
        for (k = 0; k < bad; k++)
            line += text[k] == '\n';
        fprintf(stderr, "cbf-c: %s: line %lu (offset %lu): byte 0x%02X is not UTF-8 text\n", cbf_tool_name(path),
                line, (unsigned long)bad, (unsigned)text[bad]);
        free(text);
        return CBF_TOOL_EXIT_USAGE;
    }
    if (n >= 3 && memcmp(text, "\xEF\xBB\xBF", 3u) == 0) { /* a byte order mark (editors on Windows write one): */
        memmove(text, text + 3, (size_t)n - 3u);          /* cbf reads the text after it */
        n -= 3;
    }
    len = -1;
    if (is_blank(text, (size_t)n))
        fprintf(stderr, "cbf-c: %s: empty input: nothing to encode\n", cbf_tool_name(path));
    else if (o->json == 1 || (o->json < 0 && looks_like_json(path, text, (size_t)n)))
        fprintf(stderr, "cbf-c: %s: not CUT text: canonical JSON, which cbf-c does not read (cbf encode reads it)\n",
                cbf_tool_name(path));
    else if (o->keep) /* CUT carries no sequence numbers, count or checksums: nothing stored to keep (cbf's line) */
        fprintf(stderr, "cbf-c: %s: --keep-stored applies to JSON input only: CUT text carries no stored sequence "
                "numbers, count or checksums to keep\n", cbf_tool_name(path));
    else {
        len = cbf_tool_cut_buffer(path, text, (size_t)n, o->version, o->profile, &cbf, &std_sink);
        /* the result validates under the profile, or is refused (cbf's writer.encode), --check too */
        if (len >= 0 && cbf_tool_encode_judge(path, text, (size_t)n, cbf, (size_t)len, o->profile, &std_sink)
                            != CBF_TOOL_EXIT_OK)
            len = -1;
        if (len >= 0 && o->output && !cbf_tool_write_file(o->output, cbf, (size_t)len, why, sizeof why)) {
            fprintf(stderr, "cbf-c: %s\n", why);
            len = -1;
        }
        if (len >= 0 && o->output) /* after writing, as cbf: a deprecated record is a warning, exit 0 */
            cbf_tool_encode_warnings(o->output, cbf, (size_t)len, &std_sink);
    }
    free(text);
    free(cbf);
    return len < 0 ? CBF_TOOL_EXIT_USAGE : CBF_TOOL_EXIT_OK;
}

/* Whether an option of cbf-c encode takes the next argument as its value. */
static int encode_valued(const char *a)
{
    return strcmp(a, "--profile") == 0 || strcmp(a, "--version") == 0 || strcmp(a, "-o") == 0
           || strcmp(a, "--output") == 0 || strcmp(a, "--input-format") == 0;
}

/* An option of cbf-c encode that takes a value, into o: 1, or 0 after one line on stderr. */
static int encode_value(const char *a, const char *value, encode_options *o)
{
    if (strcmp(a, "--profile") == 0) {
        o->profile = cbf_profile_find(value);
        if (o->profile < 0)
            fprintf(stderr, "cbf-c: unknown profile %s\n", cbf_quoted(value, CBF_QUOTE_NAME));
        return o->profile >= 0;
    }
    if (strcmp(a, "--version") == 0) {
        o->version = parse_version(value);
        return o->version >= 0;
    }
    if (strcmp(a, "-o") == 0 || strcmp(a, "--output") == 0) {
        o->output = value;
        return 1;
    }
    o->json = strcmp(value, "json") == 0 ? 1 : strcmp(value, "cut") == 0 ? 0 : -2; /* --input-format */
    if (o->json == -2)
        fprintf(stderr, "cbf-c: --input-format: %s is neither cut nor json\n", cbf_quoted(value, CBF_QUOTE_NAME));
    return o->json != -2;
}

/* The arguments of cbf-c encode into o, *check, *files (the files named) and *first (the first of them):
 * CBF_TOOL_EXIT_OK, or CBF_TOOL_EXIT_USAGE after one line (or the usage) on stderr. */
static int encode_arguments(int argc, char **argv, encode_options *o, int *check, int *files, const char **first)
{
    int i;
    for (i = 0; i < argc; i++) {
        const char *a = argv[i];
        if (encode_valued(a)) {
            if (i + 1 >= argc) {
                usage();
                return CBF_TOOL_EXIT_USAGE;
            }
            if (!encode_value(a, argv[++i], o))
                return CBF_TOOL_EXIT_USAGE;
        } else if (strcmp(a, "--keep-stored") == 0) {
            o->keep = 1;
        } else if (strcmp(a, "--check") == 0) {
            *check = 1;
        } else if (a[0] == '-' && a[1]) {
            usage();
            return CBF_TOOL_EXIT_USAGE;
        } else if (!(*files)++) {
            *first = a;
        }
    }
    return CBF_TOOL_EXIT_OK;
}

/* What the arguments ask is something cbf-c encode does (files, and -o or --check but not both, one file
 * with -o): CBF_TOOL_EXIT_OK, or CBF_TOOL_EXIT_USAGE after one line on stderr. */
static int encode_request_ok(int check, int files, const encode_options *o)
{
    if (check && o->output) {
        fprintf(stderr, "cbf-c encode: --check writes nothing: drop -o\n");
        return CBF_TOOL_EXIT_USAGE;
    }
    if (!files || (!check && !o->output)) {
        fprintf(stderr, "cbf-c encode: the following arguments are required: %s\n", files ? "-o/--output" : "FILE");
        usage();
        return CBF_TOOL_EXIT_USAGE;
    }
    if (!check && files > 1) {
        fprintf(stderr, "cbf-c encode: one FILE with -o; several only with --check\n");
        return CBF_TOOL_EXIT_USAGE;
    }
    return CBF_TOOL_EXIT_OK;
}

/* cbf-c encode --check: every file, in order; the worst status. */
static int encode_check(int argc, char **argv, const encode_options *o)
{
    int i, status = CBF_TOOL_EXIT_OK;
    for (i = 0; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--profile") == 0 || strcmp(a, "--version") == 0 || strcmp(a, "--input-format") == 0)
            i++;
        else if (!(a[0] == '-' && a[1]) && encode_one(a, o) != CBF_TOOL_EXIT_OK)
            status = CBF_TOOL_EXIT_USAGE;
    }
    return status;
}

/* cbf-c encode [--profile P] [--version V] [--input-format cut] FILE -o OUT, or --check FILE...: CUT text to
 * the CBF it encodes to, written to OUT (- for standard output) as cbf encode writes it: atomically, every
 * write checked, nothing written on any refusal; with --check each file only encoded, one line for each
 * that does not (a pre-commit hook). The command line is cbf encode's for CUT input; JSON is refused with
 * one line (cbf-c reads CUT text only), --keep-stored with cbf's line (CUT stores nothing to keep). */
static int cmd_encode(int argc, char **argv)
{
    encode_options o;
    int check = 0, files = 0;
    const char *first = NULL;
    o.profile = CBF_TOOL_DEFAULT_PROFILE;
    o.version = CBF_V__UNKNOWN;
    o.keep = 0;
    o.json = -1;
    o.output = NULL;
    if (encode_arguments(argc, argv, &o, &check, &files, &first) != CBF_TOOL_EXIT_OK
        || encode_request_ok(check, files, &o) != CBF_TOOL_EXIT_OK)
        return CBF_TOOL_EXIT_USAGE;
    if (!check)
        return encode_one(first, &o);
    return encode_check(argc, argv, &o);
}

/* cbf-c sniff FILE: "cut" when the engine reads it as CUT text (cbf_tool_is_cut), else "cbf". Only the
 * file's first bytes are read (the header and the 256 of the text test): a large CBF file costs nothing. */
static int cmd_sniff(const char *path)
{
    uint8_t head[CBF_HEADER_SIZE + 256u];
    const char *why = "cannot open";
    FILE *fp = cbf_tool_open(path, &why);
    size_t n;
    if (!fp) {
        fprintf(stderr, "cbf-c: %s: %s\n", cbf_tool_name(path), why);
        return CBF_TOOL_EXIT_USAGE;
    }
    n = fread(head, 1, sizeof head, fp);
    fclose(fp);
    puts(cbf_tool_is_cut(head, n) ? "cut" : "cbf");
    return CBF_TOOL_EXIT_OK;
}

static int run(int argc, char **argv)
{
    if (argc == 2 && strcmp(argv[1], "--version") == 0) {
        printf("cbf-c %s (spec %s)\n", CBF_TOOLKIT_VERSION, CBF_SPEC_REVISION);
        return CBF_TOOL_EXIT_OK;
    }
    if (argc >= 3 && strcmp(argv[1], "validate") == 0)
        return cmd_validate(argc - 2, argv + 2);
    if (argc == 3 && strcmp(argv[1], "dump") == 0)
        return cmd_dump(argv[2], 0);
    if (argc == 4 && strcmp(argv[1], "dump") == 0 && strcmp(argv[2], "--path") == 0)
        return cmd_dump(argv[3], 1);
    if (argc >= 3 && strcmp(argv[1], "encode") == 0)
        return cmd_encode(argc - 2, argv + 2);
    if (argc == 3 && strcmp(argv[1], "sniff") == 0)
        return cmd_sniff(argv[2]);
    usage();
    return CBF_TOOL_EXIT_USAGE;
}

int main(int argc, char **argv)
{
    stdout_begin();
    return stdout_end(run(argc, argv));
}
/* ==== END tools/cli.c ==== */
#line 502 "cbf_tool.c"
