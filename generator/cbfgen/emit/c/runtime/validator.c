/* ---- validation ------------------------------------------------------------ */
/* The straight-line checks (below, and the string checks) are called from one generated function per
 * layout (cbf__layout_checks_*) with the layout's offsets as constants; forced inline, each folds to a
 * few loads and compares. An offset of -1 means the layout has no such argument. */
#if defined(__GNUC__) || defined(__clang__)
#define CBF__INLINE static inline __attribute__((always_inline))
#define CBF__COLD __attribute__((cold, noinline)) /* a finding's path: out of the record loop's way */
#else
#define CBF__INLINE static inline
#define CBF__COLD
#endif

typedef struct cbf__vctx {
    const uint8_t *buf;
    size_t len;
    const cbf_options *opt;
    cbf_finding_fn fn;
    void *user;
    long errors;
    int version, eff, hlayout;
    int pos_ok;
    double pos[3];
    int ori_ok;
    double ori[3];
    double ori_tan2; /* tan^2 of just under the orientation tolerance (0: always compute the angle) */
    int shape_open;
    long shape_rec;
    size_t shape_off;
    int shape_layout;
    const uint8_t *shape_args;
    unsigned long shape_moves;
    int nd_ok[CBF__NTARGETS > 0 ? CBF__NTARGETS : 1];
    double nd_prev[CBF__NTARGETS > 0 ? CBF__NTARGETS : 1];
    const cbf_machine *machine; /* the machine limits apply (opt->machine, or the default) */
    float mlo[CBF_MACHINE__COUNT][CBF_MACHINE_MAX_AXES]; /* its bounds rounded to binary32 (cbf__bound32) */
    float mhi[CBF_MACHINE__COUNT][CBF_MACHINE_MAX_AXES];
} cbf__vctx;

/* The check kinds the engine judges in its own passes (validate.c, this file, machine.c, group_checks.c), not
 * through a kernel table (validator_layouts.c.j2 holds the targeted kinds' kernels, cbf__<kind>_at). cbf.h
 * checks this list against the registry when it compiles: a kind the registry gains that neither a kernel
 * table nor this list holds fails the build, naming it (CBF__JUDGED_CBF__KIND_<KIND> undeclared); a kind listed here
 * that the registry no longer has fails too (CBF__KIND_<KIND> undeclared). Adding a kind here is adding
 * its pass: test_bindings holds each kind's constant to a use beyond its enum. The list spells the
 * constants whole (CBF__KIND_<KIND>): a kind's bare name may be a command's (version), which no C source names. */
#define CBF__PASS_KINDS(X)                                                                                        \
    X(CBF__KIND_TRUNCATED_HEADER) X(CBF__KIND_TRUNCATED_RECORD) X(CBF__KIND_PART_NUMBER)                          \
    X(CBF__KIND_DESCRIPTOR_WORD) X(CBF__KIND_CUTTER_TABLE) X(CBF__KIND_FILE_CHECKSUM) X(CBF__KIND_COMMAND_COUNT)  \
    X(CBF__KIND_HEADER_CHECKSUM) X(CBF__KIND_MAGIC) X(CBF__KIND_SEQUENCE) X(CBF__KIND_CODE_COPY)                  \
    X(CBF__KIND_ARG_SIZE) X(CBF__KIND_ARG_CHECKSUM) X(CBF__KIND_CONTINUITY) X(CBF__KIND_AVAILABILITY)             \
    X(CBF__KIND_VERSION) X(CBF__KIND_UNKNOWN_CODE) X(CBF__KIND_TRAILING) X(CBF__KIND_RESERVED_BYTE)               \
    X(CBF__KIND_STRING_TAIL) X(CBF__KIND_STRING_ASCII) X(CBF__KIND_FINITE) X(CBF__KIND_ORIENTATION)               \
    X(CBF__KIND_SHAPE) X(CBF__KIND_MACHINE_LIMITS) X(CBF__KIND_DEPRECATED)
#define CBF__JUDGED(k) CBF__JUDGED_##k = k,
#define CBF__ONE_MORE(k) +1
enum { CBF__PASS_KINDS(CBF__JUDGED) CBF__JUDGED__COUNT = 0 CBF__PASS_KINDS(CBF__ONE_MORE) };

static void cbf__vsay(cbf__vctx *v, int ci, long rec, size_t off, const char *fmt, va_list ap) CBF__PRINTF(5, 0);
static void cbf__vsay(cbf__vctx *v, int ci, long rec, size_t off, const char *fmt, va_list ap)
{
    char msg[256];
    cbf_finding f;
    unsigned scope = cbf__checks[ci].versions;
    if (scope && !(scope & CBF__VBIT(v->eff)))
        return; /* a check scoped to other versions (versions:) judges nothing in this file */
    (void)vsnprintf(msg, sizeof msg, fmt, ap);
    f.check = cbf__checks[ci].id;
    f.severity = cbf__checks[ci].severity;
    f.record = rec;
    f.offset = off;
    f.message = msg;
    if (f.severity == CBF_SEVERITY_ERROR)
        v->errors++;
    if (v->fn)
        v->fn(v->user, &f);
}

static void cbf__say(cbf__vctx *v, int ci, long rec, size_t off, const char *fmt, ...) CBF__PRINTF(5, 6);
static void cbf__say(cbf__vctx *v, int ci, long rec, size_t off, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    cbf__vsay(v, ci, rec, off, fmt, ap);
    va_end(ap);
}

/* A deprecation check's first version: the lowest bit of its mask (the loader makes the mask
 * since and every version after it). */
static int cbf__deprecation_since(int ci)
{
    int i;
    for (i = 0; i < CBF__NVERSIONS; i++)
        if (cbf__checks[ci].versions & CBF__VBIT(i))
            return i;
    return 0;
}

/* A finding for every check of a kind. */
static void cbf__each(cbf__vctx *v, int kind, long rec, size_t off, const char *fmt, ...) CBF__PRINTF(5, 6);
static void cbf__each(cbf__vctx *v, int kind, long rec, size_t off, const char *fmt, ...)
{
    int ci;
    for (ci = 0; ci < CBF__NCHECKS; ci++) {
        va_list ap;
        if (cbf__checks[ci].kind != kind)
            continue;
        va_start(ap, fmt);
        cbf__vsay(v, ci, rec, off, fmt, ap);
        va_end(ap);
    }
}

/* Appends to a message buffer (the findings' words are cbf validate's, the Python runtime's: some are
 * built in parts); a message longer than the buffer is cut, never overrun. */
static void cbf__cat(char *buf, size_t size, size_t *at, const char *fmt, ...) CBF__PRINTF(4, 5);
static void cbf__cat(char *buf, size_t size, size_t *at, const char *fmt, ...)
{
    va_list ap;
    int n;
    if (*at >= size)
        return;
    va_start(ap, fmt);
    n = vsnprintf(buf + *at, size - *at, fmt, ap);
    va_end(ap);
    if (n > 0)
        *at = *at + (size_t)n < size ? *at + (size_t)n : size - 1u;
}

/* A string value as text: its bytes read as ISO-8859-1 (the codec's string_value), out as UTF-8. */
static void cbf__text(char *buf, size_t size, size_t *at, const uint8_t *s, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        if (s[i] < 0x80u)
            cbf__cat(buf, size, at, "%c", (char)s[i]);
        else
            cbf__cat(buf, size, at, "%c%c", (char)(0xC0u | (s[i] >> 6)), (char)(0x80u | (s[i] & 0x3Fu)));
    }
}

/* A string value as Python's repr() writes it (the value decoded as ISO-8859-1): quoted with '
 * unless it holds a ' and no ", backslash escapes for the quote, \\, \t, \n, \r, and \xNN for
 * the code points str.isprintable() refuses (controls, 0x7F-0xA0, 0xAD). Code points above 0x7F
 * go out as UTF-8, as Python prints them. */
static void cbf__repr(char *buf, size_t size, size_t *at, const uint8_t *s, size_t n)
{
    size_t i;
    int sq = 0, dq = 0;
    char q;
    for (i = 0; i < n; i++) {
        sq |= s[i] == 0x27u;
        dq |= s[i] == 0x22u;
    }
    q = sq && !dq ? '"' : '\'';
    cbf__cat(buf, size, at, "%c", q);
    for (i = 0; i < n; i++) {
        uint8_t c = s[i];
        if (c == (uint8_t)q || c == 0x5Cu)
            cbf__cat(buf, size, at, "\\%c", (char)c);
        else if (c == 0x09u)
            cbf__cat(buf, size, at, "\\t");
        else if (c == 0x0Au)
            cbf__cat(buf, size, at, "\\n");
        else if (c == 0x0Du)
            cbf__cat(buf, size, at, "\\r");
        else if (c < 0x20u || (c >= 0x7Fu && c <= 0xA0u) || c == 0xADu)
            cbf__cat(buf, size, at, "\\x%02x", (unsigned)c);
        else
            cbf__text(buf, size, at, &c, 1u);
    }
    cbf__cat(buf, size, at, "%c", q);
}

/* The string's value: the bytes before the first NUL. */
static size_t cbf__strvalue_len(const uint8_t *s, size_t size)
{
    size_t i;
    for (i = 0; i < size; i++)
        if (s[i] == CBF__PAD)
            return i;
    return size;
}

/* The w (1, 2, 4 or 8) bytes at p, as the pad bytes compare with them (memcpy: any alignment). */
CBF__INLINE uint64_t cbf__bytes_at(const uint8_t *p, size_t w)
{
    uint64_t x8;
    uint32_t x4;
    uint16_t x2;
    switch (w) {
    case 8u: memcpy(&x8, p, 8u); return x8;
    case 4u: memcpy(&x4, p, 4u); return x4;
    case 2u: memcpy(&x2, p, 2u); return x2;
    default: return *p;
    }
}

/* Whether any of the n bytes at s is not the pad byte: words of 8 (4, 2, 1 below 8 bytes), the last
 * word overlapping the one before (the every-command file's strings are mostly padding, and a byte
 * loop over it was a fifth of its validation's instructions). */
CBF__INLINE int cbf__any_unpadded(const uint8_t *s, size_t n)
{
    const uint64_t pad = (uint64_t)CBF__PAD * 0x0101010101010101u;
    size_t w = n >= 8u ? 8u : n >= 4u ? 4u : n >= 2u ? 2u : 1u, i;
    uint64_t mask = w == 8u ? ~(uint64_t)0 : (((uint64_t)1 << (8u * w)) - 1u), diff = 0u;
    if (n == 0u)
        return 0;
    for (i = 0; i + w <= n; i += w)
        diff |= cbf__bytes_at(s + i, w) ^ (pad & mask);
    diff |= cbf__bytes_at(s + n - w, w) ^ (pad & mask); /* the rest: the last w bytes */
    return diff != 0u;
}

/* string_tail: the bytes after the first NUL, in hex, up to the last that is not NUL. Cold. */
CBF__COLD static void cbf__string_tail(cbf__vctx *v, const char *cmd, const cbf_field_info *f, const uint8_t *s,
                                       size_t n, size_t size, size_t base_off, long rec)
{
    char msg[256];
    size_t at = 0, last = size, i;
    while (last > n + 1u && s[last - 1u] == CBF__PAD)
        last--;
    cbf__cat(msg, sizeof msg, &at, "%s%s%s: bytes after the first NUL: ", cmd ? cmd : "", cmd ? "." : "", f->name);
    for (i = n + 1u; i < last; i++)
        cbf__cat(msg, sizeof msg, &at, "%02x", (unsigned)s[i]);
    cbf__each(v, CBF__KIND_STRING_TAIL, rec, base_off + f->offset, "%s", msg);
}

/* string_tail and string_ascii on one string field; cmd: the record's command name, NULL in the header. */
static void cbf__check_string(cbf__vctx *v, const char *cmd, const cbf_field_info *f, const uint8_t *base,
                              size_t base_off, long rec)
{
    const uint8_t *s = base + f->offset;
    size_t size = (size_t)f->elem * f->count;
    size_t n = cbf__strvalue_len(s, size), i;
    if (n < size && cbf__any_unpadded(s + n + 1u, size - n - 1u))
        cbf__string_tail(v, cmd, f, s, n, size, base_off, rec);
    for (i = 0; i < n; i++) {
        if (s[i] < 0x20u || s[i] > 0x7Eu) {
            cbf__each(v, CBF__KIND_STRING_ASCII, rec, base_off + f->offset, "%s%s%s: non-ASCII byte 0x%02X",
                      cmd ? cmd : "", cmd ? "." : "", f->name, (unsigned)s[i]);
            break;
        }
    }
}

/* Python's str.split() whitespace, for the ISO-8859-1 code points. */
static int cbf__space(uint8_t c)
{
    return c == 0x20u || (c >= 0x09u && c <= 0x0Du) || (c >= 0x1Cu && c <= 0x1Fu) || c == 0x85u || c == 0xA0u;
}

static void cbf__check_part_number(cbf__vctx *v)
{
    const cbf_field_info *f = cbf__header_field_by_role(v->hlayout, CBF_ROLE_IMPLANT_DESCRIPTOR);
    const uint8_t *s;
    size_t n, a, b, plen;
    if (!v->opt || !v->opt->part_number || !f)
        return;
    s = v->buf + f->offset;
    n = cbf__strvalue_len(s, (size_t)f->elem * f->count);
    for (a = 0; a < n && cbf__space(s[a]); a++) {}
    for (b = a; b < n && !cbf__space(s[b]); b++) {}
    plen = strlen(v->opt->part_number);
    if (plen != b - a || (plen && memcmp(s + a, v->opt->part_number, plen) != 0)) {
        char msg[512];
        size_t at = 0;
        cbf__cat(msg, sizeof msg, &at, "implant descriptor starts with ");
        cbf__repr(msg, sizeof msg, &at, s + a, b - a);
        cbf__cat(msg, sizeof msg, &at, ", expected ");
        cbf__repr(msg, sizeof msg, &at, (const uint8_t *)v->opt->part_number, plen);
        cbf__each(v, CBF__KIND_PART_NUMBER, -1, f->offset, "%s", msg);
    }
}

/* 4.2: the implant descriptor begins with the part number, so it holds at least one word. */
static void cbf__check_descriptor_word(cbf__vctx *v)
{
    const cbf_field_info *f = cbf__header_field_by_role(v->hlayout, CBF_ROLE_IMPLANT_DESCRIPTOR);
    const uint8_t *s;
    size_t n, a;
    if (!f)
        return;
    s = v->buf + f->offset;
    n = cbf__strvalue_len(s, (size_t)f->elem * f->count);
    for (a = 0; a < n && cbf__space(s[a]); a++) {}
    if (a == n)
        cbf__each(v, CBF__KIND_DESCRIPTOR_WORD, -1, f->offset,
                  "implant descriptor holds no word: no part number comes first");
}

static double cbf__norm(const double a[3]) { return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

/* The binary32 element at p, decoded once a record into *x (the generated layout
 * function reads each element of a float argument with it, one call an element,
 * and shares the values between the checks): 1 when it is finite. */
CBF__INLINE int cbf__float_at(const uint8_t *p, float *x)
{
    uint32_t u = cbf__get_u(p, 4);
    *x = cbf__bits_f4(u);
    return cbf__bits_finite(u);
}

/* The 3-element float argument at args + off as doubles: 1 when every element
 * is finite, else 0 (also when off < 0). Each element is read once. */
CBF__INLINE int cbf__vec_at(const uint8_t *args, long off, double out[3])
{
    unsigned i;
    int finite = 1;
    if (off < 0)
        return 0;
    for (i = 0; i < 3u; i++) {
        uint32_t u = cbf__get_u(args + off + 4u * i, 4);
        finite &= cbf__bits_finite(u);
        out[i] = (double)cbf__bits_f4(u);
    }
    return finite;
}

/* A float argument of n elements: its first as double; 1 when all are finite. */
CBF__INLINE int cbf__scalar_at(const uint8_t *args, long off, unsigned n, double *out)
{
    unsigned i;
    int finite = 1;
    *out = 0.0;
    if (off < 0)
        return 0;
    for (i = 0; i < n; i++) {
        uint32_t u = cbf__get_u(args + off + 4u * i, 4);
        finite &= cbf__bits_finite(u);
        if (i == 0u)
            *out = (double)cbf__bits_f4(u);
    }
    return finite;
}

/* A point of a circle or helix: start turned by th (rad, right-hand rule) about the unit axis k through
 * center, then advanced rise along k. Double precision, operations in the reference order. */
static void cbf__turned(const double start[3], const double center[3], const double k[3], double th, double rise,
                        double out[3])
{
    double p[3], kxv[3], rot[3], c, s, kdv;
    int i;
    for (i = 0; i < 3; i++)
        p[i] = start[i] - center[i];
    c = cos(th);
    s = sin(th);
    kxv[0] = k[1] * p[2] - k[2] * p[1];
    kxv[1] = k[2] * p[0] - k[0] * p[2];
    kxv[2] = k[0] * p[1] - k[1] * p[0];
    kdv = k[0] * p[0] + k[1] * p[1] + k[2] * p[2];
    for (i = 0; i < 3; i++)
        rot[i] = p[i] * c + kxv[i] * s + k[i] * kdv * (1.0 - c);
    for (i = 0; i < 3; i++)
        out[i] = center[i] + rot[i] + rise * k[i];
}

/* A circle or helix of a record's arguments: its start, centre, unit axis, turn (rad) and axial
 * advance; 0 when a value is not finite or the normal is zero. */
static int cbf__arc_of(int kind, const uint8_t *args, long o_start, long o_center, long o_normal, long o_deg,
                       unsigned n_deg, long o_len, unsigned n_len, double start[3], double center[3], double k[3],
                       double *th, double *length)
{
    double normal[3], deg = 0.0, nn;
    int i;
    *length = 0.0;
    if (!cbf__vec_at(args, o_start, start) || !cbf__vec_at(args, o_center, center)
        || !cbf__vec_at(args, o_normal, normal) || !cbf__scalar_at(args, o_deg, n_deg, &deg))
        return 0;
    if (kind == CBF__MOTION_HELIX && !cbf__scalar_at(args, o_len, n_len, length))
        return 0;
    nn = cbf__norm(normal);
    if (nn == 0.0)
        return 0;
    for (i = 0; i < 3; i++)
        k[i] = normal[i] / nn;
    *th = deg * (CBF__PI / 180.0);
    return 1;
}

/* Where a circle or helix ends (none when a value is not finite or the normal
 * is zero). */
static int cbf__arc_end(int kind, const uint8_t *args, long o_start, long o_center, long o_normal, long o_deg,
                        unsigned n_deg, long o_len, unsigned n_len, double end[3])
{
    double start[3], center[3], k[3], th, length;
    if (!cbf__arc_of(kind, args, o_start, o_center, o_normal, o_deg, n_deg, o_len, n_len, start, center, k, &th,
                     &length))
        return 0;
    cbf__turned(start, center, k, th, length, end);
    return 1;
}

/* 6.4.5: continuity of motion commands (M1). A point motion sets the current
 * position; every other motion command is compared with it when its start is
 * finite, then moves it to its end (none when a value is not finite or the
 * normal is zero). xs, xe: the start and end as the layout function decoded
 * them (ok_s, ok_e: finite; NULL: the layout has none). */
CBF__INLINE void cbf__continuity_at(cbf__vctx *v, int cmd, int kind, const uint8_t *args, long rec, size_t args_off,
                                    const float *xs, int ok_s, const float *xe, int ok_e, long o_start,
                                    long o_center, long o_normal, long o_deg, unsigned n_deg, long o_len,
                                    unsigned n_len)
{
    double end[3];
    int i;
    if (kind != CBF__MOTION_POINT && v->pos_ok && xs && ok_s) {
        double d[3], dist;
        for (i = 0; i < 3; i++)
            d[i] = (double)xs[i] - v->pos[i];
        dist = cbf__norm(d);
        if (dist > cbf__tol_position)
            cbf__each(v, CBF__KIND_CONTINUITY, rec, args_off + (size_t)o_start,
                      "%s starts %.6g mm from the current position", cbf__commands[cmd].name, dist);
    }
    if (kind == CBF__MOTION_POINT || kind == CBF__MOTION_LINE) {
        v->pos_ok = xe && ok_e;
        if (v->pos_ok)
            for (i = 0; i < 3; i++)
                end[i] = (double)xe[i];
    } else {
        v->pos_ok = cbf__arc_end(kind, args, o_start, o_center, o_normal, o_deg, n_deg, o_len, n_len, end);
    }
    if (v->pos_ok)
        for (i = 0; i < 3; i++)
            v->pos[i] = end[i];
}

/* orientation_jump (D2): the angle atan2(|a x b|, a . b) between a path
 * command's start and the current orientation (the last set/end vector that
 * was finite and non-zero). atan2 runs only when the angle may exceed the
 * tolerance: below tan^2 of a thousandth less than it (ori_tan2), it cannot.
 * xs, xe: the start and end vectors as decoded by the layout function (as in
 * cbf__continuity_at). */
CBF__INLINE void cbf__orientation_at(cbf__vctx *v, int cmd, int kind, long rec, size_t args_off, const float *xs,
                                     int ok_s, const float *xe, int ok_e)
{
    double a[3], b[3];
    int i;
    if (xs)
        for (i = 0; i < 3; i++)
            a[i] = (double)xs[i];
    if (kind == CBF__ORIENT_PATH && v->ori_ok && xs && ok_s && cbf__norm(a) > 0.0) {
        double cx[3], dot, c2;
        cx[0] = a[1] * v->ori[2] - a[2] * v->ori[1];
        cx[1] = a[2] * v->ori[0] - a[0] * v->ori[2];
        cx[2] = a[0] * v->ori[1] - a[1] * v->ori[0];
        dot = a[0] * v->ori[0] + a[1] * v->ori[1] + a[2] * v->ori[2];
        c2 = cx[0] * cx[0] + cx[1] * cx[1] + cx[2] * cx[2];
        if (!(dot > 0.0 && c2 < dot * dot * v->ori_tan2)) {
            double ang = atan2(cbf__norm(cx), dot) * (180.0 / CBF__PI);
            if (ang > cbf__tol_orientation)
                cbf__each(v, CBF__KIND_ORIENTATION, rec, args_off, "%s starts %.6g deg from the current orientation",
                          cbf__commands[cmd].name, ang);
        }
    }
    if (!xe || !ok_e) {
        v->ori_ok = 0;
        return;
    }
    for (i = 0; i < 3; i++)
        b[i] = (double)xe[i];
    v->ori_ok = cbf__norm(b) > 0.0;
    if (v->ori_ok)
        for (i = 0; i < 3; i++)
            v->ori[i] = b[i];
}

static int cbf__same_string(const uint8_t *a, size_t na, const uint8_t *b, size_t nb)
{
    /* equal after removing trailing NULs */
    while (na && a[na - 1] == CBF__PAD) na--;
    while (nb && b[nb - 1] == CBF__PAD) nb--;
    return na == nb && (na == 0 || memcmp(a, b, na) == 0);
}

/* The value of string field f of args (nothing when the layout has none), as text. */
static void cbf__name_of(char *buf, size_t size, size_t *at, const uint8_t *args, const cbf_field_info *f)
{
    if (f)
        cbf__text(buf, size, at, args + f->offset,
                  cbf__strvalue_len(args + f->offset, (size_t)f->elem * f->count));
}

static void cbf__shape(cbf__vctx *v, int cmd, int layout, const uint8_t *args, long rec, size_t off)
{
    const cbf__layout *L = &cbf__layouts[layout];
    int kind = cbf__commands[cmd].shape;
    if (cbf__commands[cmd].motion != CBF__MOTION_NONE && v->shape_open)
        v->shape_moves++;
    if (kind == CBF__SHAPE_START) {
        if (v->shape_open)
            cbf__each(v, CBF__KIND_SHAPE, rec, off, "%s inside the open shape of record %ld",
                      cbf__commands[cmd].name, v->shape_rec);
        v->shape_open = 1;
        v->shape_rec = rec;
        v->shape_off = off;
        v->shape_layout = layout;
        v->shape_args = args;
        v->shape_moves = 0;
    } else if (kind == CBF__SHAPE_END) {
        const cbf_field_info *fn, *fc, *sn, *sc;
        if (!v->shape_open) {
            cbf__each(v, CBF__KIND_SHAPE, rec, off, "%s without an open shape", cbf__commands[cmd].name);
            return;
        }
        v->shape_open = 0;
        fn = cbf__layout_arg(layout, L->shape[CBF__S_NAME]);
        fc = cbf__layout_arg(layout, L->shape[CBF__S_COUNT]);
        sn = cbf__layout_arg(v->shape_layout, cbf__layouts[v->shape_layout].shape[CBF__S_NAME]);
        sc = cbf__layout_arg(v->shape_layout, cbf__layouts[v->shape_layout].shape[CBF__S_COUNT]);
        {
            int same_name = !fn || !sn || cbf__same_string(args + fn->offset, (size_t)fn->elem * fn->count,
                                                           v->shape_args + sn->offset, (size_t)sn->elem * sn->count);
            uint32_t ce = fc ? cbf__get_u(args + fc->offset, fc->elem) : 0u;
            uint32_t cs = sc ? cbf__get_u(v->shape_args + sc->offset, sc->elem) : 0u;
            char msg[256];
            size_t at = 0;
            if (!same_name || (fc && sc && ce != cs)) {
                cbf__cat(msg, sizeof msg, &at, "%s ", cbf__commands[cmd].name);
                cbf__name_of(msg, sizeof msg, &at, args, fn);
                cbf__cat(msg, sizeof msg, &at, ",%lu does not repeat record %ld's ", (unsigned long)ce, v->shape_rec);
                cbf__name_of(msg, sizeof msg, &at, v->shape_args, sn);
                cbf__cat(msg, sizeof msg, &at, ",%lu", (unsigned long)cs);
                cbf__each(v, CBF__KIND_SHAPE, rec, off, "%s", msg);
            } else if (fc && sc && v->shape_moves != cs) {
                cbf__cat(msg, sizeof msg, &at, "shape ");
                cbf__name_of(msg, sizeof msg, &at, v->shape_args, sn);
                cbf__cat(msg, sizeof msg, &at, " encloses %lu motion commands, declares %lu", v->shape_moves,
                         (unsigned long)cs);
                cbf__each(v, CBF__KIND_SHAPE, rec, off, "%s", msg);
            }
        }
    }
}

static void cbf__cutter(cbf__vctx *v, int layout, const uint8_t *args, long rec, size_t off)
{
    /* the cutter role's keys: the name's first, then the table's values (cbfgen/options.py) */
    const cbf__layout *L = &cbf__layouts[layout];
    const cbf_field_info *fn = cbf__layout_arg(layout, L->cutter[0]);
    size_t i, n, found = (size_t)-1;
    int k;
    if (!v->opt || !v->opt->cutters || !fn)
        return;
    n = cbf__strvalue_len(args + fn->offset, (size_t)fn->elem * fn->count);
    for (i = 0; i < v->opt->ncutters; i++) {
        const char *name = v->opt->cutters[i].name;
        if (name && strlen(name) == n && (n == 0 || memcmp(name, args + fn->offset, n) == 0))
            found = i; /* the last entry of a name counts */
    }
    if (found == (size_t)-1) {
        char msg[256];
        size_t at = 0;
        cbf__cat(msg, sizeof msg, &at, "cutter ");
        cbf__repr(msg, sizeof msg, &at, args + fn->offset, n);
        cbf__cat(msg, sizeof msg, &at, " is not in the cutter table");
        cbf__each(v, CBF__KIND_CUTTER_TABLE, rec, off, "%s", msg);
        return;
    }
    for (k = 0; k < CBF_CUTTER_VALUES; k++) {
        const cbf_field_info *fv = cbf__layout_arg(layout, L->cutter[1 + k]);
        double ref = v->opt->cutters[found].value[k], x;
        if (!fv || fv->kind != CBF__K_FLOAT || !cbf__ffirst(args, fv, &x))
            continue;
        if (fabs(x - ref) > cbf__tol_cutter) { /* named by the cutter role's key, as cbf validate does */
            char msg[256];
            size_t at = 0;
            cbf__cat(msg, sizeof msg, &at, "cutter ");
            cbf__repr(msg, sizeof msg, &at, args + fn->offset, n);
            cbf__cat(msg, sizeof msg, &at, " %s %g mm, the table says %g mm", cbf__cutter_keys[1 + k], x, ref);
            cbf__each(v, CBF__KIND_CUTTER_TABLE, rec, off, "%s", msg);
        }
    }
}

/* The kernels of the checks with targets on one float argument f of the record (one signature,
 * cbf__argument_kernel; validator_layouts.c.j2 calls them through cbf__argument_kernels): positive,
 * nonzero_vector, range, nondecreasing (t: the target, for the previous value). xf: its f->count
 * elements as the layout function decoded them, finite: whether all are. Nothing is said about a value
 * that is not finite. */
CBF__INLINE void cbf__positive_at(cbf__vctx *v, int ci, size_t t, int cmd, const cbf_field_info *f, const float *xf,
                                  int finite, long rec, size_t args_off)
{
    unsigned i;
    int any_le = 0;
    (void)t;
    if (!finite)
        return;
    for (i = 0; i < f->count; i++)
        if (xf[i] <= 0.0f) any_le = 1;
    if (any_le)
        cbf__say(v, ci, rec, args_off + f->offset, "%s.%s is %g, must be > 0", cbf__commands[cmd].name, f->name,
                 (double)xf[0]);
}

CBF__INLINE void cbf__nonzero_vector_at(cbf__vctx *v, int ci, size_t t, int cmd, const cbf_field_info *f,
                                        const float *xf, int finite, long rec, size_t args_off)
{
    unsigned i;
    int all_zero = 1;
    (void)t;
    if (!finite)
        return;
    for (i = 0; i < f->count; i++)
        if (xf[i] != 0.0f) all_zero = 0;
    if (all_zero)
        cbf__say(v, ci, rec, args_off + f->offset, "%s.%s has zero length", cbf__commands[cmd].name, f->name);
}

/* range: the words of findings.range_text. */
CBF__INLINE void cbf__range_at(cbf__vctx *v, int ci, size_t t, int cmd, const cbf_field_info *f, const float *xf,
                               int finite, long rec, size_t args_off)
{
    const cbf__check *ch = &cbf__checks[ci];
    double x = (double)xf[0];
    (void)t;
    if (!finite)
        return;
    if (!(ch->has_min && (ch->min_open ? x <= ch->min : x < ch->min))
        && !(ch->has_max && (ch->max_open ? x >= ch->max : x > ch->max)))
        return;
    if (ch->has_min && ch->has_max)
        cbf__say(v, ci, rec, args_off + f->offset, "%s.%s is %g, outside %s%g..%g%s", cbf__commands[cmd].name,
                 f->name, x, ch->min_open ? "(" : "[", ch->min, ch->max, ch->max_open ? ")" : "]");
    else if (ch->has_min)
        cbf__say(v, ci, rec, args_off + f->offset, "%s.%s is %g, must be %s %g", cbf__commands[cmd].name,
                 f->name, x, ch->min_open ? ">" : ">=", ch->min);
    else
        cbf__say(v, ci, rec, args_off + f->offset, "%s.%s is %g, must be %s %g", cbf__commands[cmd].name,
                 f->name, x, ch->max_open ? "<" : "<=", ch->max);
}

CBF__INLINE void cbf__nondecreasing_at(cbf__vctx *v, int ci, size_t t, int cmd, const cbf_field_info *f,
                                       const float *xf, int finite, long rec, size_t args_off)
{
    double x = (double)xf[0];
    if (!finite)
        return;
    if (v->nd_ok[t] && x < v->nd_prev[t])
        cbf__say(v, ci, rec, args_off + f->offset, "%s.%s falls from %g to %g", cbf__commands[cmd].name,
                 f->name, v->nd_prev[t], x);
    v->nd_ok[t] = 1;
    v->nd_prev[t] = x;
}

/* ordered: the target's arguments, all finite, are in non-decreasing order (the kernel of a whole target,
 * cbf__target_kernel). */
static void cbf__ordered_at(cbf__vctx *v, int ci, size_t t, int cmd, int layout, const uint8_t *args, long rec,
                            size_t args_off)
{
    const cbf__target *tg = &cbf__targets[t];
    double prev = 0.0;
    int bad = 0;
    size_t a;
    for (a = 0; a < tg->n; a++) {
        const cbf_field_info *f = cbf__layout_arg(layout, cbf__target_arg_at[tg->first + a][layout]);
        double x;
        if (!f || f->kind != CBF__K_FLOAT || !cbf__ffirst(args, f, &x))
            return;
        if (a > 0 && x < prev)
            bad = 1;
        prev = x;
    }
    if (bad) { /* "<command>: a=1 <= b=0.5 <= c=2 does not hold", as cbf validate says it */
        char msg[256];
        size_t at = 0;
        cbf__cat(msg, sizeof msg, &at, "%s: ", cbf__commands[cmd].name);
        for (a = 0; a < tg->n; a++) {
            const cbf_field_info *f = cbf__layout_arg(layout, cbf__target_arg_at[tg->first + a][layout]);
            double x = 0.0;
            if (f)
                (void)cbf__ffirst(args, f, &x);
            cbf__cat(msg, sizeof msg, &at, "%s%s=%g", a ? " <= " : "", f ? f->name : "?", x);
        }
        cbf__cat(msg, sizeof msg, &at, " does not hold");
        cbf__say(v, ci, rec, args_off, "%s", msg);
    }
}

/* cbf__sum for a short n (at most 1024 bytes: the 16-bit lanes cannot overflow), inlined
 * where n is a constant: a record's head, a layout's arguments. With n constant the tests
 * below fold away. */
CBF__INLINE uint32_t cbf__sum_fixed(const uint8_t *p, size_t n)
{
    const uint64_t lo = 0x00FF00FF00FF00FFull;
    uint64_t lanes = 0, x, y;
    uint32_t acc = 0, w;
    size_t i = 0;
    if (n < 32u) { /* written out: gcc -O2 keeps a loop of 2 or 3 trips */
        if (n >= 16u) {
            memcpy(&x, p, sizeof x);
            memcpy(&y, p + 8u, sizeof y);
            lanes += (x & lo) + ((x >> 8) & lo) + (y & lo) + ((y >> 8) & lo);
            i = 16u;
        }
        if (n - i >= 8u) {
            memcpy(&x, p + i, sizeof x);
            lanes += (x & lo) + ((x >> 8) & lo);
            i += 8u;
        }
    } else { /* longer: a loop, which gcc vectorises */
        for (; n - i >= 8u; i += 8u) {
            memcpy(&x, p + i, sizeof x);
            lanes += (x & lo) + ((x >> 8) & lo);
        }
    }
    if (n - i >= 4u) { /* a 4-byte rest (a float argument) in the low lanes, not byte by byte */
        memcpy(&w, p + i, sizeof w);
        lanes += (uint64_t)((w & 0x00FF00FFu) + ((w >> 8) & 0x00FF00FFu));
        i += 4u;
    }
    if (n <= 256u) { /* the four lanes total at most 255 * 256 < 2^16: one multiply adds them in the top lane */
        acc = (uint32_t)((lanes * 0x0001000100010001ull) >> 48);
    } else {
        lanes = (lanes & 0x0000FFFF0000FFFFull) + ((lanes >> 16) & 0x0000FFFF0000FFFFull);
        acc = (uint32_t)(lanes & 0xFFFFFFFFull) + (uint32_t)(lanes >> 32);
    }
    for (; i < n; i++)
        acc += p[i];
    return acc;
}
