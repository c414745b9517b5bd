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
