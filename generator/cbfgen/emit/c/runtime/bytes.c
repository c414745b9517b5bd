/* ---- bytes -------------------------------------------------------------- */
static inline uint32_t cbf__get_u(const uint8_t *p, unsigned n)
{
    uint32_t v = 0;
    unsigned i;
    /* the widths the format uses, unrolled (the validator reads several a record) */
#if CBF__LITTLE_ENDIAN
    if (n == 4u)
        return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
    if (n == 2u)
        return (uint32_t)p[0] | ((uint32_t)p[1] << 8);
#else
    if (n == 4u)
        return ((uint32_t)p[0] << 24) | ((uint32_t)p[1] << 16) | ((uint32_t)p[2] << 8) | (uint32_t)p[3];
    if (n == 2u)
        return ((uint32_t)p[0] << 8) | (uint32_t)p[1];
#endif
    if (n == 1u)
        return p[0];
    for (i = 0; i < n; i++) {
#if CBF__LITTLE_ENDIAN
        v |= (uint32_t)p[i] << (8u * i);
#else
        v = (v << 8) | (uint32_t)p[i];
#endif
    }
    return v;
}

static void cbf__put_u(uint8_t *p, uint32_t v, unsigned n)
{
    unsigned i;
    for (i = 0; i < n; i++) {
#if CBF__LITTLE_ENDIAN
        p[i] = (uint8_t)((v >> (8u * i)) & 0xFFu);
#else
        p[n - 1u - i] = (uint8_t)((v >> (8u * i)) & 0xFFu);
#endif
    }
}

static inline float cbf__bits_f4(uint32_t u)
{
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

static inline float cbf__get_f4(const uint8_t *p) { return cbf__bits_f4(cbf__get_u(p, 4)); }

static uint32_t cbf__f4_bits(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u;
}

static inline int cbf__bits_finite(uint32_t u) { return (u & 0x7F800000u) != 0x7F800000u; }

/* A float field's first element as double, and whether every element is finite; each
 * element's bytes are read once. */
static int cbf__ffirst(const uint8_t *base, const cbf_field_info *f, double *first)
{
    unsigned i;
    int finite = 1;
    *first = 0.0;
    for (i = 0; i < f->count; i++) {
        uint32_t u = cbf__get_u(base + f->offset + 4u * i, 4);
        finite &= cbf__bits_finite(u);
        if (i == 0u)
            *first = (double)cbf__bits_f4(u);
    }
    return finite;
}

/* An element of 8 bytes: the bit pattern of a u8, s8 or f8. */
static uint64_t cbf__get_u64(const uint8_t *p)
{
    uint64_t v = 0;
    unsigned i;
    for (i = 0; i < 8u; i++) {
#if CBF__LITTLE_ENDIAN
        v |= (uint64_t)p[i] << (8u * i);
#else
        v = (v << 8) | (uint64_t)p[i];
#endif
    }
    return v;
}

static void cbf__put_u64(uint8_t *p, uint64_t v)
{
    unsigned i;
    for (i = 0; i < 8u; i++) {
#if CBF__LITTLE_ENDIAN
        p[i] = (uint8_t)((v >> (8u * i)) & 0xFFu);
#else
        p[7u - i] = (uint8_t)((v >> (8u * i)) & 0xFFu);
#endif
    }
}

/* One element of an integer or float field between its n bytes and its struct member (the C type
 * of the registry's type: uintN_t, intN_t, float, double). A signed integer is the unsigned one's
 * bits (intN_t is two's complement), and a float its IEEE-754 bits, so each width has one path. */
static inline void cbf__load_elem(unsigned char *m, const uint8_t *s, unsigned n)
{
    if (n == 1u) { uint8_t v = s[0]; memcpy(m, &v, sizeof v); }
    else if (n == 2u) { uint16_t v = (uint16_t)cbf__get_u(s, 2); memcpy(m, &v, sizeof v); }
    else if (n == 4u) { uint32_t v = cbf__get_u(s, 4); memcpy(m, &v, sizeof v); }
    else { uint64_t v = cbf__get_u64(s); memcpy(m, &v, sizeof v); }
}

static inline void cbf__store_elem(uint8_t *d, const unsigned char *m, unsigned n)
{
    if (n == 4u) { uint32_t v; memcpy(&v, m, sizeof v); cbf__put_u(d, v, 4); }
    else if (n == 2u) { uint16_t v; memcpy(&v, m, sizeof v); cbf__put_u(d, v, 2); }
    else if (n == 1u) { d[0] = m[0]; }
    else { uint64_t v; memcpy(&v, m, sizeof v); cbf__put_u64(d, v); }
}

/* Load fields from bytes into a struct (byte-wise through memcpy). One case a field kind of the
 * registry, no default: a kind the engine lacks fails the build (-Wswitch-enum). */
static void cbf__load(const cbf_field_info *fields, size_t n, const uint8_t *src, unsigned char *dst)
{
    size_t k;
    for (k = 0; k < n; k++) {
        const cbf_field_info *f = &fields[k];
        unsigned char *m = dst + f->member;
        const uint8_t *s = src + f->offset;
        size_t size = (size_t)f->elem * f->count;
        unsigned i;
        switch ((enum cbf_field_kind)f->kind) {
        case CBF_KIND_FLOAT:
            if (f->elem == 4u) { /* binary32, the common case: its own loop (the decoder's hot path) */
                for (i = 0; i < f->count; i++) {
                    uint32_t v = cbf__get_u(s + 4u * i, 4);
                    memcpy(m + 4u * i, &v, sizeof v);
                }
                break;
            }
            for (i = 0; i < f->count; i++)
                cbf__load_elem(m + (size_t)f->elem * i, s + (size_t)f->elem * i, f->elem);
            break;
        case CBF_KIND_UINT:
        case CBF_KIND_SINT: /* one element, in practice (registry.unsupported refuses integer vectors) */
            cbf__load_elem(m, s, f->elem);
            for (i = 1; i < f->count; i++)
                cbf__load_elem(m + (size_t)f->elem * i, s + (size_t)f->elem * i, f->elem);
            break;
        case CBF_KIND_STRING:
            memcpy(m, s, size);
            m[size] = 0;
            break;
        case CBF_KIND_BYTES:
            memcpy(m, s, size);
            break;
        }
    }
}

/* Store fields from a struct into bytes. */
static void cbf__store(const cbf_field_info *fields, size_t n, const unsigned char *src, uint8_t *dst)
{
    size_t k;
    for (k = 0; k < n; k++) {
        const cbf_field_info *f = &fields[k];
        const unsigned char *m = src + f->member;
        uint8_t *d = dst + f->offset;
        size_t size = (size_t)f->elem * f->count;
        unsigned i;
        switch ((enum cbf_field_kind)f->kind) {
        case CBF_KIND_UINT:
        case CBF_KIND_SINT:
        case CBF_KIND_FLOAT:
            for (i = 0; i < f->count; i++)
                cbf__store_elem(d + (size_t)f->elem * i, m + (size_t)f->elem * i, f->elem);
            break;
        case CBF_KIND_STRING:
        case CBF_KIND_BYTES:
            memcpy(d, m, size);
            break;
        }
    }
}

uint32_t cbf_field_uint(const cbf_field_info *f, const uint8_t *base)
{
    return (f && base && f->kind == CBF__K_UINT && f->elem <= 4u) ? cbf__get_u(base + f->offset, f->elem) : 0u;
}

float cbf_field_float(const cbf_field_info *f, const uint8_t *base, unsigned i)
{
    return (f && base && f->kind == CBF__K_FLOAT && f->elem == 4u && i < f->count) ? cbf__get_f4(base + f->offset + 4u * i) : 0.0f;
}

uint32_t cbf_float_bits(float f) { return cbf__f4_bits(f); }

uint64_t cbf_field_bits(const cbf_field_info *f, const uint8_t *base, unsigned i)
{
    unsigned char m[8];
    uint64_t u = 0;
    if (!f || !base || i >= f->count || f->elem > 8u)
        return 0u;
    switch ((enum cbf_field_kind)f->kind) {
    case CBF_KIND_UINT:
    case CBF_KIND_SINT:
    case CBF_KIND_FLOAT:
        cbf__load_elem(m, base + f->offset + (size_t)f->elem * i, f->elem);
        if (f->elem == 1u) { uint8_t x; memcpy(&x, m, 1); u = x; }
        else if (f->elem == 2u) { uint16_t x; memcpy(&x, m, 2); u = x; }
        else if (f->elem == 4u) { uint32_t x; memcpy(&x, m, 4); u = x; }
        else memcpy(&u, m, 8);
        break;
    case CBF_KIND_STRING:
    case CBF_KIND_BYTES:
        break;
    }
    return u;
}

double cbf_field_number(const cbf_field_info *f, const uint8_t *base, unsigned i)
{
    uint64_t u = cbf_field_bits(f, base, i);
    unsigned bits;
    if (!f || !base || i >= f->count || f->elem > 8u)
        return 0.0;
    bits = 8u * f->elem;
    switch ((enum cbf_field_kind)f->kind) {
    case CBF_KIND_UINT:
        return (double)u;
    case CBF_KIND_SINT: { /* sign-extended to 64 bits; int64_t is two's complement */
        int64_t v;
        if (bits < 64u && ((u >> (bits - 1u)) & 1u))
            u |= ~(uint64_t)0 << bits;
        memcpy(&v, &u, sizeof v);
        return (double)v;
    }
    case CBF_KIND_FLOAT:
        if (f->elem == 4u)
            return (double)cbf__bits_f4((uint32_t)u);
        {
            double d;
            memcpy(&d, &u, sizeof d);
            return d;
        }
    case CBF_KIND_STRING:
    case CBF_KIND_BYTES:
        break;
    }
    return 0.0;
}

uint32_t cbf_member_uint(const cbf_field_info *f, const void *obj)
{
    const unsigned char *m;
    if (!f || !obj || f->kind != CBF__K_UINT || f->elem > 4u)
        return 0u;
    m = (const unsigned char *)obj + f->member;
    if (f->elem == 1) { uint8_t x; memcpy(&x, m, 1); return x; }
    if (f->elem == 2) { uint16_t x; memcpy(&x, m, 2); return x; }
    { uint32_t x; memcpy(&x, m, 4); return x; }
}

void cbf_member_set_uint(const cbf_field_info *f, void *obj, uint32_t v)
{
    unsigned char *m;
    if (!f || !obj || f->kind != CBF__K_UINT || f->elem > 4u)
        return;
    m = (unsigned char *)obj + f->member;
    if (f->elem == 1) { uint8_t x = (uint8_t)v; memcpy(m, &x, 1); }
    else if (f->elem == 2) { uint16_t x = (uint16_t)v; memcpy(m, &x, 2); }
    else memcpy(m, &v, 4);
}

