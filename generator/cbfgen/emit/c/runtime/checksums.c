/* ---- checksums -----------------------------------------------------------
 * Every algorithm kind is a row of cbf__algs (generated from cbfgen/registry.py ALGORITHMS: its
 * parameters and, for a CRC, its byte table); each family is implemented once here:
 *   SUM       unsigned byte sum, reduced to the width of the field
 *   CRC       the CRC catalogue's model (width, poly, init, refin, refout, xorout), a byte at a time
 *             through the table: reflected (refin) with the register right-aligned, else with the
 *             register left-aligned in 32 bits
 *   FLETCHER  16 or 32 bits: little-endian words of width/16 bytes (an odd tail padded with 0), two
 *             sums modulo 2^(width/2) - 1, result sum2 << width/2 | sum1
 * A coverage feeds several ranges as one stream: Fletcher keeps the bytes of a pending word. */
typedef struct cbf__ck { const cbf__alg *a; uint32_t acc, acc2; unsigned npend; uint8_t pend[4]; } cbf__ck;

static void cbf__ck_init(cbf__ck *c, int alg)
{
    c->a = &cbf__algs[alg >= 0 && alg < CBF__ALG__COUNT ? alg : CBF__ALG_NONE];
    c->acc = c->a->init;
    c->acc2 = 0u;
    c->npend = 0u;
    memset(c->pend, 0, sizeof c->pend);
}

/* The plain byte sum of p[0..n), modulo 2^32. Eight bytes at a time: the bytes
 * are added pairwise into four 16-bit lanes of a 64-bit word, which are folded
 * before they can overflow (at most 510 per step, 128 steps). */
static uint32_t cbf__sum(const uint8_t *p, size_t n)
{
    const uint64_t lo = 0x00FF00FF00FF00FFull;
    uint32_t acc = 0;
    size_t i = 0;
    while (n - i >= 8u) {
        uint64_t lanes = 0;
        size_t steps = (n - i) / 8u, k;
        if (steps > 128u)
            steps = 128u;
        for (k = 0; k < steps; k++, i += 8u) {
            uint64_t x;
            memcpy(&x, p + i, sizeof x);
            lanes += (x & lo) + ((x >> 8) & lo);
        }
        lanes = (lanes & 0x0000FFFF0000FFFFull) + ((lanes >> 16) & 0x0000FFFF0000FFFFull);
        acc += (uint32_t)(lanes & 0xFFFFFFFFull) + (uint32_t)(lanes >> 32);
    }
    for (; i < n; i++)
        acc += p[i];
    return acc;
}

/* The little-endian value of the first n bytes of q (the bytes of a word; missing ones are 0). */
static uint32_t cbf__word(const uint8_t *q, unsigned n)
{
    uint32_t w = 0;
    while (n-- > 0u)
        w = (w << 8) | q[n];
    return w;
}

/* Fletcher over p[0..n): whole words straight from p, a word split between two feeds through
 * c->pend; the sums grow in 64 bits and are reduced every 4096 words (then s1 < 2^29, s2 < 2^42). */
static void cbf__fletcher(cbf__ck *c, const uint8_t *p, size_t n)
{
    const unsigned wb = c->a->width / 16u;
    const uint32_t mod = (1u << (c->a->width / 2u)) - 1u;
    uint64_t s1 = c->acc, s2 = c->acc2;
    unsigned since = 0;
    size_t i = 0;
    while (i < n) {
        uint32_t w;
        if (c->npend == 0u && n - i >= wb) {
            w = cbf__word(p + i, wb);
            i += wb;
        } else {
            c->pend[c->npend++] = p[i++];
            if (c->npend < wb)
                continue;
            w = cbf__word(c->pend, wb);
            c->npend = 0u;
        }
        s1 += w;
        s2 += s1;
        if (++since == 4096u) {
            s1 %= mod;
            s2 %= mod;
            since = 0;
        }
    }
    c->acc = (uint32_t)(s1 % mod);
    c->acc2 = (uint32_t)(s2 % mod);
}

static void cbf__ck_feed(cbf__ck *c, const uint8_t *p, size_t n)
{
    const uint32_t *t = c->a->table;
    uint32_t r = c->acc;
    size_t i;
    switch (c->a->family) {
    case CBF__FAMILY_SUM:
        c->acc += cbf__sum(p, n);
        break;
    case CBF__FAMILY_CRC:
        if (c->a->refin) {
            for (i = 0; i < n; i++)
                r = t[(r ^ p[i]) & 0xFFu] ^ (r >> 8);
        } else {
            for (i = 0; i < n; i++)
                r = t[((r >> 24) ^ p[i]) & 0xFFu] ^ (r << 8);
        }
        c->acc = r;
        break;
    case CBF__FAMILY_FLETCHER:
        cbf__fletcher(c, p, n);
        break;
    }
}

/* The register reflected over its low `width` bits. */
static uint32_t cbf__reflect(uint32_t v, unsigned width)
{
    uint32_t out = 0;
    unsigned k;
    for (k = 0; k < width; k++, v >>= 1)
        out = (out << 1) | (v & 1u);
    return out;
}

static uint32_t cbf__ck_value(const cbf__ck *c, unsigned width)
{
    const cbf__alg *a = c->a;
    uint32_t v = c->acc;
    switch (a->family) {
    case CBF__FAMILY_SUM:
        break;
    case CBF__FAMILY_CRC:
        if (!a->refin)
            v >>= 32u - a->width;
        if (a->refin != a->refout)
            v = cbf__reflect(v, a->width);
        v ^= a->xorout;
        break;
    case CBF__FAMILY_FLETCHER: {
        uint32_t s1 = c->acc, s2 = c->acc2;
        if (c->npend) { /* the pending bytes of a last, short word, padded with zeros */
            const uint32_t mod = (1u << (a->width / 2u)) - 1u;
            s1 = (uint32_t)(((uint64_t)s1 + cbf__word(c->pend, c->npend)) % mod);
            s2 = (uint32_t)(((uint64_t)s2 + s1) % mod);
        }
        v = (s2 << (a->width / 2u)) | s1;
        break;
    }
    }
    /* only a sum is wider than its field (the loader refuses any other such algorithm) */
    return width >= 4u ? v : (v & ((1u << (8u * width)) - 1u));
}

/* A coverage over a file image buf[0..len): records lie in [header, records_end). */
static uint32_t cbf__cover(int cov, int alg, unsigned width, const uint8_t *buf, size_t len,
                              size_t records_end, const uint8_t *args, size_t nargs)
{
    cbf__ck c;
    size_t s;
    cbf__ck_init(&c, alg);
    for (s = cbf__coverages[cov].first; s < cbf__coverages[cov].first + cbf__coverages[cov].n; s++) {
        const cbf__segment *seg = &cbf__segments[s];
        if (seg->region == CBF__REGION_FILE) {
            if (seg->start < len)
                cbf__ck_feed(&c, buf + seg->start, len - seg->start);
        } else if (seg->region == CBF__REGION_HEADER) {
            size_t end = (size_t)seg->end;
            if (end > len)
                end = len;
            if (seg->start < end)
                cbf__ck_feed(&c, buf + seg->start, end - seg->start);
        } else if (seg->region == CBF__REGION_ARGS) {
            if (args && nargs)
                cbf__ck_feed(&c, args, nargs);
        } else if (seg->region == CBF__REGION_RECORDS) {
            const cbf_field_info *nbf = cbf__record_field_by_role(CBF_ROLE_ARG_SIZE);
            size_t pos = CBF_HEADER_SIZE;
            if (records_end > len)
                records_end = len;
            while (nbf && pos <= records_end && records_end - pos >= CBF_RECORD_HEAD_SIZE) {
                size_t nb = cbf__get_u(buf + pos + nbf->offset, nbf->elem);
                size_t cur = 0, k;
                if (records_end - pos - CBF_RECORD_HEAD_SIZE < nb)
                    break;
                for (k = 0; k < CBF__NRECORD_FIELDS; k++) {
                    const cbf_field_info *f = &cbf__record_fields[k];
                    if (!(seg->exclude & (1u << k)))
                        continue;
                    if (f->offset > cur)
                        cbf__ck_feed(&c, buf + pos + cur, f->offset - cur);
                    cur = (size_t)f->offset + (size_t)f->elem * f->count;
                }
                cbf__ck_feed(&c, buf + pos + cur, CBF_RECORD_HEAD_SIZE + nb - cur);
                pos += CBF_RECORD_HEAD_SIZE + nb;
            }
        }
    }
    return cbf__ck_value(&c, width);
}

uint32_t cbf_args_checksum(const uint8_t *args, size_t n)
{
    const cbf__ckfield *k = cbf__ckfield_of(CBF__CK_ARGS);
    const cbf_field_info *f = cbf__record_field_by_tag(CBF__CK_ARGS);
    if (!k || !f)
        return 0u;
    return cbf__cover(k->coverage, k->alg, f->elem, NULL, 0, 0, args, n);
}


/* ---- checksum fields among a layout's arguments (issue 25, point 1) --------
 * cbf__argcks lists them per layout, in the spec's fill order; each covers byte ranges of its
 * record (offsets from the record's first byte: the head, then the arguments), fed in order. */

/* The value of argument checksum a over the record rec of nb argument bytes (nb is its layout's size). */
static uint32_t cbf__argck_value(const cbf__argck *a, const uint8_t *rec, size_t nb)
{
    cbf__ck c;
    size_t r;
    cbf__ck_init(&c, cbf__ckfields[a->ckfield].alg);
    for (r = a->first; r < a->first + a->n; r++) {
        const cbf__range *g = &cbf__argck_ranges[r];
        if (g->start < g->end && (size_t)g->end <= CBF_RECORD_HEAD_SIZE + nb)
            cbf__ck_feed(&c, rec + g->start, (size_t)(g->end - g->start));
    }
    return cbf__ck_value(&c, a->elem);
}

/* Whether check ci judges a checksum field among arguments (not the head's argument checksum). */
static int cbf__judges_argck(int ci)
{
    size_t i;
    for (i = 0; i < sizeof cbf__argcks / sizeof cbf__argcks[0]; i++)
        if (cbf__argcks[i].ckfield >= 0 && cbf__ckfields[cbf__argcks[i].ckfield].check == ci)
            return 1;
    return 0;
}

/* Fills layout's checksum fields among the arguments of the record rec (nb argument bytes), in
 * fill order; returns whether one was written (the head's argument checksum covers them). */
static int cbf__fill_argcks(int layout, uint8_t *rec, size_t nb)
{
    size_t i;
    int any = 0;
    for (i = 0; i < sizeof cbf__argcks / sizeof cbf__argcks[0]; i++) {
        const cbf__argck *a = &cbf__argcks[i];
        if (layout < 0 || a->layout != layout || (size_t)a->offset + a->elem > nb)
            continue;
        cbf__put_u(rec + CBF_RECORD_HEAD_SIZE + a->offset, cbf__argck_value(a, rec, nb), a->elem);
        any = 1;
    }
    return any;
}
