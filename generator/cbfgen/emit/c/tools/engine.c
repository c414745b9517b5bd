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
