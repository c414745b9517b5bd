/* ---- checksums -----------------------------------------------------------
 * Every algorithm kind of the model, implemented once here (parameters as in
 * spec/cbf.yaml checksums.algorithms and the CRC catalogue):
 *   SUM          unsigned byte sum, reduced to the width of the field
 *   CRC16_CCITT  CRC-16/CCITT-FALSE: poly 0x1021, init 0xFFFF, not reflected, xorout 0
 *   CRC32        CRC-32/ISO-HDLC: poly 0x04C11DB7 (reflected 0xEDB88320), init/xorout 0xFFFFFFFF
 *   CRC32C       CRC-32C Castagnoli: poly 0x1EDC6F41 (reflected 0x82F63B78), init/xorout 0xFFFFFFFF
 *   FLETCHER16   bytes, sums modulo 255, sum2 << 8 | sum1
 *   FLETCHER32   16-bit little-endian words (odd tail padded with 0), sums modulo 65535, sum2 << 16 | sum1
 * A coverage feeds several ranges as one stream: Fletcher-32 keeps a pending odd byte. */
typedef struct cbf__ck { int alg; uint32_t acc, acc2; int odd; uint8_t pend; } cbf__ck;

static void cbf__ck_init(cbf__ck *c, int alg)
{
    c->alg = alg;
    c->acc = (alg == CBF__ALG_CRC32 || alg == CBF__ALG_CRC32C) ? 0xFFFFFFFFu
             : alg == CBF__ALG_CRC16_CCITT ? 0xFFFFu : 0u;
    c->acc2 = 0u;
    c->odd = 0;
    c->pend = 0u;
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

static void cbf__ck_feed(cbf__ck *c, const uint8_t *p, size_t n)
{
    size_t i;
    unsigned b;
    switch (c->alg) {
    case CBF__ALG_CRC32:
    case CBF__ALG_CRC32C: {
        const uint32_t poly = c->alg == CBF__ALG_CRC32 ? 0xEDB88320u : 0x82F63B78u;
        for (i = 0; i < n; i++) {
            c->acc ^= p[i];
            for (b = 0; b < 8u; b++)
                c->acc = (c->acc & 1u) ? ((c->acc >> 1) ^ poly) : (c->acc >> 1);
        }
        break;
    }
    case CBF__ALG_CRC16_CCITT:
        for (i = 0; i < n; i++) {
            c->acc ^= (uint32_t)p[i] << 8;
            for (b = 0; b < 8u; b++)
                c->acc = (c->acc & 0x8000u) ? (((c->acc << 1) ^ 0x1021u) & 0xFFFFu) : ((c->acc << 1) & 0xFFFFu);
        }
        break;
    case CBF__ALG_FLETCHER16:
        for (i = 0; i < n; i++) {
            c->acc = (c->acc + p[i]) % 255u;
            c->acc2 = (c->acc2 + c->acc) % 255u;
        }
        break;
    case CBF__ALG_FLETCHER32:
        for (i = 0; i < n; i++) {
            if (!c->odd) {
                c->pend = p[i];
                c->odd = 1;
                continue;
            }
            c->acc = (c->acc + ((uint32_t)c->pend | ((uint32_t)p[i] << 8))) % 65535u;
            c->acc2 = (c->acc2 + c->acc) % 65535u;
            c->odd = 0;
        }
        break;
    default:
        c->acc += cbf__sum(p, n);
        break;
    }
}

static uint32_t cbf__ck_value(const cbf__ck *c, unsigned width)
{
    uint32_t v = c->acc, s1 = c->acc, s2 = c->acc2;
    if (c->alg == CBF__ALG_CRC32 || c->alg == CBF__ALG_CRC32C) {
        v = c->acc ^ 0xFFFFFFFFu;
    } else if (c->alg == CBF__ALG_FLETCHER16) {
        v = (s2 << 8) | s1;
    } else if (c->alg == CBF__ALG_FLETCHER32) {
        if (c->odd) { /* the odd last byte, padded with a zero high byte */
            s1 = (s1 + c->pend) % 65535u;
            s2 = (s2 + s1) % 65535u;
        }
        v = (s2 << 16) | s1;
    }
    /* only a sum is wider than its field (loader.py refuses any other such algorithm) */
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
