/* cbf_testee.c - conformance testee of the C binding (conformance/PROTOCOL.md).
 *
 * GENERATED from spec/cbf.yaml by cbfgen (generator/cbfgen/emit/c). Do not edit.
 *
 * Reads JSON lines on stdin ({"op": "decode" | "validate" | "encode" | "quit"})
 * and answers each with one JSON line on stdout. It only answers; the runner
 * judges. No malloc: every buffer is static. Option files are read by the tools'
 * engine (cbf_tools.h), the same as cbf-c's.
 */
#define _POSIX_C_SOURCE 200809L /* stat, open, fstat: the file layer reads regular files only (issue #35) */
#define CBF_IMPLEMENTATION
#define CBF_TOOLS_IMPLEMENTATION
#include "cbf.h"
#include "cbf_tools.h"

/* A writer makes files that validate: no error, and no warning of these checks (strings in ASCII, N4). */
static const char *const refused_warnings[] = {
    CBF_CHECK_STRING_ASCII,
    NULL
};

/* ==== BEGIN tools/testee.c: verbatim from generator/cbfgen/emit/c/tools/testee.c, edit it there ==== */
#line 1 "generator/cbfgen/emit/c/tools/testee.c"
/* ---- the conformance testee (conformance/PROTOCOL.md): JSON lines in, one JSON line out each ---- */
#define MAX_FILE (32u << 20)
#define MAX_LINE (96u << 20)
#define MAX_NODES (6u << 20)
#define MAX_DEPTH 64

static uint8_t file_buf[MAX_FILE];
static uint8_t out_buf[MAX_FILE];
static char req_line[MAX_LINE];

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
        while (n && base[f->offset + n - 1] == CBF_TOOL_PAD)
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

static int32_t jfail(const char *why)
{
    jerr = why;
    return -1;
}

/* The digits at jpos (at least one); 0 when there is none. */
static int jdigits(void)
{
    if (jpos >= jlen || !jdigit(jtext[jpos]))
        return 0;
    while (jpos < jlen && jdigit(jtext[jpos]))
        jpos++;
    return 1;
}

/* A number (RFC 8259's grammar) at jpos. */
static int32_t jnumber(void)
{
    int32_t n = jalloc(J_NUM);
    if (n < 0)
        return -1;
    if (jtext[jpos] == '-')
        jpos++;
    if (jpos < jlen && jtext[jpos] == '0')
        jpos++;
    else if (!jdigits())
        return jfail("bad number");
    if (jpos < jlen && jtext[jpos] == '.') {
        jpos++;
        if (!jdigits())
            return jfail("bad number");
    }
    if (jpos < jlen && (jtext[jpos] == 'e' || jtext[jpos] == 'E')) {
        jpos++;
        if (jpos < jlen && (jtext[jpos] == '+' || jtext[jpos] == '-'))
            jpos++;
        if (!jdigits())
            return jfail("bad number");
    }
    nodes[n].len = (uint32_t)(jpos - nodes[n].start);
    return n;
}

/* true, false or null at jpos (word, its node type); -1 when the text is not the word. */
static int32_t jword(const char *word, unsigned char type)
{
    size_t len = strlen(word);
    int32_t n;
    if (jlen - jpos < len || memcmp(jtext + jpos, word, len) != 0)
        return jfail("unexpected character");
    n = jalloc(type);
    jpos += len;
    return n;
}

/* One member of an object (a key, ':' and a value) or one item of an array, linked after prev. */
static int32_t jmember(int32_t n, int obj, int32_t prev, int depth)
{
    int32_t k = -1, v;
    jws();
    if (obj) {
        if (jpos >= jlen || jtext[jpos] != '"')
            return jfail("expected a key");
        k = jstring();
        if (k < 0)
            return -1;
        jws();
        if (jpos >= jlen || jtext[jpos] != ':')
            return jfail("expected ':'");
        jpos++;
    }
    v = jvalue(depth + 1);
    if (v < 0)
        return -1;
    if (prev < 0)
        nodes[n].first = obj ? k : v;
    else
        nodes[prev].next = obj ? k : v;
    if (obj)
        nodes[k].next = v;
    return v;
}

/* An object or an array at jpos. */
static int32_t jcontainer(int depth)
{
    int obj = jtext[jpos] == '{';
    char close = obj ? '}' : ']';
    int32_t n = jalloc(obj ? J_OBJ : J_ARR), prev = -1;
    if (n < 0)
        return -1;
    jpos++;
    jws();
    if (jpos < jlen && jtext[jpos] == close) {
        jpos++;
        return n;
    }
    for (;;) {
        prev = jmember(n, obj, prev, depth);
        if (prev < 0)
            return -1;
        jws();
        if (jpos < jlen && jtext[jpos] == ',') {
            jpos++;
            continue;
        }
        if (jpos < jlen && jtext[jpos] == close) {
            jpos++;
            return n;
        }
        return jfail(obj ? "expected ',' or '}'" : "expected ',' or ']'");
    }
}

static int32_t jvalue(int depth)
{
    if (depth > MAX_DEPTH)
        return jfail("JSON nested too deep");
    jws();
    if (jpos >= jlen)
        return jfail("unexpected end of JSON");
    switch (jtext[jpos]) {
    case '"':
        return jstring();
    case '{':
    case '[':
        return jcontainer(depth);
    case 't':
        return jword("true", J_TRUE);
    case 'f':
        return jword("false", J_FALSE);
    case 'n':
        return jword("null", J_NULL);
    default:
        if (jtext[jpos] == '-' || jdigit(jtext[jpos]))
            return jnumber();
        return jfail("unexpected character");
    }
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

/* Four hex digits at s as a number; -1 when one is not a hex digit. */
static long hex4(const char *s)
{
    long v = 0;
    int k;
    for (k = 0; k < 4; k++) {
        int h = hexval(s[k]);
        if (h < 0)
            return -1;
        v = v * 16 + h;
    }
    return v;
}

/* The \u escape at s[*i] (after the "\u"), with its low surrogate when it is a high one; -1 when bad. */
static long jstr_u(const char *s, size_t len, size_t *i)
{
    long cp, lo;
    if (len - *i < 4 || (cp = hex4(s + *i)) < 0)
        return -1;
    *i += 4;
    if (cp >= 0xDC00 && cp < 0xE000)
        return -1;
    if (cp < 0xD800 || cp >= 0xDC00)
        return cp;
    if (len - *i < 6 || s[*i] != '\\' || s[*i + 1] != 'u' || (lo = hex4(s + *i + 2)) < 0 || lo < 0xDC00 || lo >= 0xE000)
        return -1;
    *i += 6;
    return 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
}

/* The escape at s[*i] (a backslash) as a code point; -1 when bad. */
static long jstr_escape(const char *s, size_t len, size_t *i)
{
    static const char from[] = "\"\\/bfnrt";
    static const long to[] = { '"', '\\', '/', 8, 12, 10, 13, 9 };
    const char *at;
    char e;
    if (len - *i < 2)
        return -1;
    e = s[*i + 1];
    *i += 2;
    if (e == 'u')
        return jstr_u(s, len, i);
    at = e ? strchr(from, e) : NULL;
    return at ? to[at - from] : -1;
}

/* The UTF-8 sequence at s[*i] (its first byte c >= 0x80) as a code point; -1 when bad. */
static long jstr_utf8(const char *s, size_t len, size_t *i)
{
    unsigned char c = (unsigned char)s[*i];
    size_t extra = c >= 0xF0u ? 3u : c >= 0xE0u ? 2u : c >= 0xC0u ? 1u : 0u, k;
    unsigned long cp;
    if (!extra || c >= 0xF8u || len - *i <= extra)
        return -1;
    cp = c & (0x3Fu >> extra);
    for (k = 1; k <= extra; k++) {
        unsigned char d = (unsigned char)s[*i + k];
        if ((d & 0xC0u) != 0x80u)
            return -1;
        cp = (cp << 6) | (d & 0x3Fu);
    }
    *i += extra + 1;
    return (long)cp;
}

/* cp as UTF-8 into out[*o..cap); 0 when it does not fit. */
static int put_utf8(unsigned long cp, uint8_t *out, size_t *o, size_t cap)
{
    uint8_t tmp[4];
    size_t k, m;
    if (cp < 0x80u) { tmp[0] = (uint8_t)cp; m = 1; }
    else if (cp < 0x800u) { tmp[0] = (uint8_t)(0xC0u | (cp >> 6)); tmp[1] = (uint8_t)(0x80u | (cp & 0x3Fu)); m = 2; }
    else if (cp < 0x10000u) { tmp[0] = (uint8_t)(0xE0u | (cp >> 12)); tmp[1] = (uint8_t)(0x80u | ((cp >> 6) & 0x3Fu)); tmp[2] = (uint8_t)(0x80u | (cp & 0x3Fu)); m = 3; }
    else { tmp[0] = (uint8_t)(0xF0u | (cp >> 18)); tmp[1] = (uint8_t)(0x80u | ((cp >> 12) & 0x3Fu)); tmp[2] = (uint8_t)(0x80u | ((cp >> 6) & 0x3Fu)); tmp[3] = (uint8_t)(0x80u | (cp & 0x3Fu)); m = 4; }
    if (cap - *o < m)
        return 0;
    for (k = 0; k < m; k++)
        out[(*o)++] = tmp[k];
    return 1;
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
        unsigned char c = (unsigned char)s[i];
        long cp;
        if (c == '\\') {
            cp = jstr_escape(s, len, &i);
        } else if (c < 0x80u) {
            cp = (long)c;
            i++;
        } else {
            cp = jstr_utf8(s, len, &i);
        }
        if (cp < 0)
            return -1;
        if (latin1) {
            if (cp > 0xFF || o >= cap)
                return -1;
            out[o++] = (uint8_t)cp;
        } else if (!put_utf8((unsigned long)cp, out, &o, cap)) {
            return -1;
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
/* x as size bytes in the spec's byte order (CBF_TOOL_LITTLE_ENDIAN, from the model). */
static void put_uint_bytes(uint8_t *d, unsigned size, uint64_t x)
{
    unsigned i;
    for (i = 0; i < size; i++)
#if CBF_TOOL_LITTLE_ENDIAN
        d[i] = (uint8_t)((x >> (8u * i)) & 0xFFu);
#else
        d[size - 1u - i] = (uint8_t)((x >> (8u * i)) & 0xFFu);
#endif
}

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
        put_uint_bytes(d, f->elem, x);
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
            if (!jfloat(e, &bits))
                return fail("field %s: not a binary32 value", f->name);
            put_uint_bytes(d + 4u * i, 4u, bits);
        }
        return 1;
    }
    case CBF_KIND_STRING: {
        long n = jstr(v, d, size, 1);
        if (n < 0)
            return fail("field %s: not a string of at most its size in ISO-8859-1", f->name);
        memset(d + n, CBF_TOOL_PAD, size - (size_t)n);
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
    n = cbf_tool_read_file(path, file_buf, sizeof file_buf, &why);
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
        opt.profile = CBF_TOOL_DEFAULT_PROFILE;
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
        if (!jcstr(v, cpath, sizeof cpath) || !cbf_tool_cutters_file(cpath, &opt)) {
            put_error("cutters", -1, "cannot read the cutter table");
            return;
        }
    }
    v = jget(req, "machine"); /* machine limits (L1): a machine file, or null for the default */
    if (v >= 0 && nodes[v].type != J_NULL) {
        if (!jcstr(v, cpath, sizeof cpath) || !cbf_tool_machine_file(cpath, &opt)) {
            put_error("machine", -1, cbf_tool_why());
            return;
        }
    }
    n = cbf_tool_read_file(path, file_buf, sizeof file_buf, &why);
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
/* A writer makes files that validate: no error, and none of refused_warnings (cbf_testee.c's table). */

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

/* An encode request in progress: the writer, the file's version, and the record head's fields. */
typedef struct enc {
    cbf_writer w;
    int version, keep;
    const cbf_field_info *rf, *fcode, *fsize;
    size_t nr;
} enc;

static uint8_t enc_args[1u << 16];

/* The header object hdr: its version, its fields packed (magic numbers and the fields the writer fills
 * by default), and the writer begun on it. */
static int encode_header(enc *e, int32_t hdr)
{
    static uint8_t header_bytes[CBF_HEADER_SIZE];
    const cbf_field_info *hf;
    size_t nh = cbf_header_fields(0, &hf), i;
    uint32_t major = 0, minor = 0;
    cbf_header h;
    int32_t vmaj = jget(hdr, role_field(hf, nh, CBF_ROLE_VERSION_MAJOR)->name);
    int32_t vmin = jget(hdr, role_field(hf, nh, CBF_ROLE_VERSION_MINOR)->name);
    if ((vmaj >= 0 && !juint(vmaj, 0xFFu, &major)) || (vmin >= 0 && !juint(vmin, 0xFFu, &minor)))
        return fail("%s", "$.header: bad version");
    e->version = cbf_version_find(major, minor);
    if (!e->keep && !cbf_version_writable(e->version))
        return fail("header: version %lu.%lu is not writable", (unsigned long)major, (unsigned long)minor);
    nh = cbf_header_fields(cbf_version_header_layout(e->version), &hf);
    if (!known_keys(hdr, hf, nh, NULL))
        return fail("%s", "$.header: unknown key for the version's header layout");
    memset(header_bytes, 0, sizeof header_bytes);
    for (i = 0; i < nh; i++) {
        int32_t v = jget(hdr, hf[i].name);
        if (v < 0) {
            if (hf[i].flags & CBF_FIELD_MAGIC) {
                put_uint_bytes(header_bytes + hf[i].offset, hf[i].elem, hf[i].magic);
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
    if (cbf_encode_begin(&e->w, out_buf, sizeof out_buf, &h) != CBF_OK)
        return fail("%s", "header: cannot encode");
    return 1;
}

/* The code of a command name; 0 when no command has that name. */
static int code_of_name(const char *name, uint32_t *code)
{
    int c;
    for (c = 0; c < 256; c++)
        if (cbf_command_name(c) && strcmp(cbf_command_name(c), name) == 0) {
            *code = (uint32_t)c;
            return 1;
        }
    return 0;
}

/* The record r's command code: its code field, else its command name; a name given with a code matches it. */
static int record_code(const enc *e, int32_t r, const char *where, uint32_t *code)
{
    int32_t jname = jget(r, "command"), jcode = jget(r, e->fcode->name);
    char cname[64];
    const char *known;
    if (jcode >= 0 && nodes[jcode].type != J_NULL) {
        if (!juint(jcode, 0xFFu, code))
            return fail("%s: bad command code", where);
    } else if (!jcstr(jname, cname, sizeof cname) || !code_of_name(cname, code)) {
        return fail("%s: needs a code or a known command name", where);
    }
    if (jname < 0 || nodes[jname].type == J_NULL)
        return 1;
    known = cbf_command_name((int)*code);
    if (!jcstr(jname, cname, sizeof cname) || !known || strcmp(known, cname) != 0)
        return fail("%s.command: does not match the code", where);
    return 1;
}

/* The args object a packed into enc_args by the layout its keys (and the size, when given) choose. */
static int record_args_object(const enc *e, int32_t a, uint32_t code, int has_size, uint32_t want_size,
                              const char *where, long *nargs)
{
    int lay;
    const cbf_field_info *af;
    size_t na, item = 0, i;
    long group;
    if (nodes[a].type != J_OBJ)
        return fail("%s.args: expected an object", where);
    if (!cbf_command_name((int)code))
        return fail("%s.args: an unknown code takes raw_args only", where);
    lay = choose_layout((int)code, e->version, a, has_size, want_size);
    if (lay == CBF_LAYOUT__NONE)
        return group_misfit((int)code, e->version, a, where) ? 0
                                                              : fail("%s.args: the keys match no layout of the command",
                                                                     where);
    na = cbf_layout_fields(lay, &af);
    *nargs = json_nb(lay, a);
    group = cbf_layout_group(lay, NULL, NULL, &item);
    memset(enc_args, 0, (size_t)*nargs);
    for (i = 0; i < na; i++)
        if (!((long)i == group ? pack_group(&af[i], jget(a, af[i].name), enc_args, item)
                               : pack_field(&af[i], jget(a, af[i].name), enc_args)))
            return 0;
    return 1;
}

/* The record r's argument bytes into enc_args (its args object, else its raw_args hex), *nargs of them. */
static int record_args(const enc *e, int32_t r, uint32_t code, const char *where, long *nargs)
{
    int32_t a = jget(r, "args"), jsize = jget(r, e->fsize->name);
    uint32_t want_size = 0;
    int has_size = jsize >= 0 && nodes[jsize].type != J_NULL;
    if (has_size && !juint(jsize, 0xFFFFFFFFu, &want_size))
        return fail("%s: bad arg_size", where);
    if (a >= 0 && nodes[a].type != J_NULL) {
        if (!record_args_object(e, a, code, has_size, want_size, where, nargs))
            return 0;
    } else {
        int32_t raw = jget(r, "raw_args");
        *nargs = (raw < 0 || nodes[raw].type == J_NULL) ? 0 : unhex(raw, enc_args, sizeof enc_args);
        if (*nargs < 0)
            return fail("%s.raw_args: not hex", where);
    }
    if (has_size && want_size != (uint32_t)*nargs)
        return fail("%s: arg_size differs from the number of argument bytes", where);
    if (e->keep)
        return 1;
    if (!cbf_command_name((int)code))
        return fail("%s: unknown command code", where);
    if (!cbf_command_available((int)code, e->version))
        return fail("%s: the command is not available in the version", where);
    if (cbf_args_layout((int)code, e->version, (size_t)*nargs) == CBF_LAYOUT__NONE)
        return fail("%s: no layout of that size in the version", where);
    return 1;
}

/* One head field's value: the writer's (code, size, sequence, code copy, checksum) unless kept as given. */
static int head_value(const enc *e, const cbf_field_info *f, int32_t jv, uint32_t code, long nargs, uint32_t index,
                      const char *where, uint32_t *val)
{
    uint32_t max = f->elem >= 4u ? 0xFFFFFFFFu : ((1u << (8u * f->elem)) - 1u);
    int given = jv >= 0 && nodes[jv].type != J_NULL;
    *val = 0;
    if (given && f->role != CBF_ROLE_CODE && f->role != CBF_ROLE_ARG_SIZE && !juint(jv, max, val))
        return fail("%s: %s out of range", where, f->name);
    if (f->role == CBF_ROLE_CODE) {
        *val = code;
    } else if (f->role == CBF_ROLE_ARG_SIZE) {
        if ((unsigned long)nargs > max)
            return fail("%s: too many argument bytes", where);
        *val = (uint32_t)nargs;
    } else if (f->role == CBF_ROLE_SEQUENCE && !e->keep) {
        *val = index & max;
    } else if (f->role == CBF_ROLE_CODE_COPY && (!e->keep || !given)) {
        *val = code;
    } else if (f->checksum && (!e->keep || !given)) {
        *val = cbf_args_checksum(enc_args, (size_t)nargs);
    }
    return 1;
}

/* The record object r, the index-th, appended to the writer. */
static int encode_record(enc *e, int32_t r, uint32_t index)
{
    static const char *const rec_keys[] = { "offset", "command", "args", "raw_args", NULL };
    uint32_t code = 0;
    long nargs = 0;
    cbf_record_head head;
    char where[64];
    size_t i;
    snprintf(where, sizeof where, "$.records[%lu]", (unsigned long)index);
    if (nodes[r].type != J_OBJ)
        return fail("%s: expected an object", where);
    if (!known_keys(r, e->rf, e->nr, rec_keys))
        return fail("%s: unknown key", where);
    if (!record_code(e, r, where, &code) || !record_args(e, r, code, where, &nargs))
        return 0;
    memset(&head, 0, sizeof head);
    for (i = 0; i < e->nr; i++) {
        uint32_t val;
        if (!head_value(e, &e->rf[i], jget(r, e->rf[i].name), code, nargs, index, where, &val))
            return 0;
        cbf_member_set_uint(&e->rf[i], &head, val);
    }
    if (cbf_encode_record_stored(&e->w, &head, enc_args, (size_t)nargs) != CBF_OK)
        return fail("%s: cannot encode", where);
    return 1;
}

/* The trailing hex string, written after the records (keep_stored only). */
static int encode_trailing(enc *e, int32_t trail)
{
    long n = unhex(trail, out_buf + e->w.len, sizeof out_buf - e->w.len);
    if (n < 0)
        return fail("%s", "$.trailing: not hex");
    if (n > 0 && !e->keep)
        return fail("%s", "trailing bytes can only be written with keep_stored");
    if (cbf_encode_bytes(&e->w, out_buf + e->w.len, (size_t)n) != CBF_OK)
        return fail("%s", "trailing: cannot encode");
    return 1;
}

/* The file finished (filled unless keep), and refused when it would not validate. */
static int encode_finish(enc *e, int profile, long *size)
{
    long rc = cbf_encode_end(&e->w, profile, !e->keep);
    if (rc < 0)
        return fail("cannot finish the file: %s", cbf_strerror((int)rc));
    if (!e->keep) {
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

static int encode(int32_t doc, int keep, int profile, long *size)
{
    static const char *const top_keys[] = { "header", "records", "trailing", NULL };
    static enc e;
    int32_t hdr, recs, trail, r;
    uint32_t index = 0;
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
    memset(&e, 0, sizeof e);
    e.keep = keep;
    if (!encode_header(&e, hdr))
        return 0;
    e.nr = cbf_record_fields(&e.rf);
    e.fcode = role_field(e.rf, e.nr, CBF_ROLE_CODE);
    e.fsize = role_field(e.rf, e.nr, CBF_ROLE_ARG_SIZE);
    if (!keep && recs >= 0 && jcount(recs) > CBF_LIMIT_MAX_COMMANDS)
        return fail("%s", "too many commands for the count field");
    for (r = recs >= 0 ? nodes[recs].first : -1; r >= 0; r = nodes[r].next, index++)
        if (!encode_record(&e, r, index))
            return 0;
    if (trail >= 0 && !encode_trailing(&e, trail))
        return 0;
    return encode_finish(&e, profile, size);
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
    int profile = CBF_TOOL_DEFAULT_PROFILE;
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
/* ==== END tools/testee.c ==== */
#line 1416 "cbf_testee.c"
