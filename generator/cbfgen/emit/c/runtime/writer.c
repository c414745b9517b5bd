/* ---- writer ---------------------------------------------------------------- */
static int cbf__wfail(cbf_writer *w, int err)
{
    if (w->error == CBF_OK)
        w->error = err;
    return w->error;
}

int cbf_encode_begin(cbf_writer *w, uint8_t *buf, size_t cap, const cbf_header *h)
{
    long rc;
    if (!w)
        return CBF_ERR_ARGUMENT;
    memset(w, 0, sizeof *w);
    if (!buf || !h)
        return cbf__wfail(w, CBF_ERR_ARGUMENT);
    w->buf = buf;
    w->cap = cap;
    rc = cbf_header_encode(h, buf, cap);
    if (rc < 0)
        return cbf__wfail(w, (int)rc);
    w->version = cbf_version_find(h->major, h->minor);
    if (w->version == CBF_V__UNKNOWN) {
        /* the version field as stored in the header image decides */
        const cbf_field_info *fmaj = cbf__header_field_by_role(0, CBF_ROLE_VERSION_MAJOR);
        const cbf_field_info *fmin = cbf__header_field_by_role(0, CBF_ROLE_VERSION_MINOR);
        if (fmaj && fmin)
            w->version = cbf_version_find(cbf__get_u(buf + fmaj->offset, fmaj->elem),
                                          cbf__get_u(buf + fmin->offset, fmin->elem));
    }
    w->eff_version = cbf__eff_version(w->version);
    w->len = CBF_HEADER_SIZE;
    w->records_end = CBF_HEADER_SIZE;
    return CBF_OK;
}

int cbf_encode_record_stored(cbf_writer *w, const cbf_record_head *head, const uint8_t *args, size_t nargs)
{
    size_t k;
    uint8_t *p;
    if (!w || !w->buf)
        return CBF_ERR_ARGUMENT;
    if (w->error)
        return w->error;
    if (!head || (!args && nargs))
        return cbf__wfail(w, CBF_ERR_ARGUMENT);
    if (w->len != w->records_end)
        return cbf__wfail(w, CBF_ERR_ARGUMENT); /* records after trailing bytes */
    if (w->cap - w->len < CBF_RECORD_HEAD_SIZE || w->cap - w->len - CBF_RECORD_HEAD_SIZE < nargs)
        return cbf__wfail(w, CBF_ERR_BUFFER);
    p = w->buf + w->len;
    for (k = 0; k < CBF__NRECORD_FIELDS; k++) {
        const cbf_field_info *f = &cbf__record_fields[k];
        const unsigned char *m = (const unsigned char *)head + f->member;
        uint32_t v;
        if (f->elem == 1) { uint8_t x; memcpy(&x, m, 1); v = x; }
        else if (f->elem == 2) { uint16_t x; memcpy(&x, m, 2); v = x; }
        else memcpy(&v, m, 4);
        if (f->role == CBF_ROLE_ARG_SIZE && v != nargs)
            return cbf__wfail(w, CBF_ERR_RANGE);
        cbf__put_u(p + f->offset, v, f->elem);
    }
    if (nargs)
        memcpy(p + CBF_RECORD_HEAD_SIZE, args, nargs);
    w->len += CBF_RECORD_HEAD_SIZE + nargs;
    w->records_end = w->len;
    w->count++;
    return CBF_OK;
}

/* A filling writer writes only what the version has: a known command that the
 * version lists, with an argument size that is one of its layouts in that
 * version. cbf_encode_end also asks that the profile accept the layout. */
static int cbf__record_writable(int version, int code, size_t nb)
{
    return cbf_command_available(code, version) && cbf_args_layout(code, version, nb) != CBF_LAYOUT__NONE;
}

static inline int cbf__profile_accepts(int layout, int profile)
{
    return cbf__layouts[layout].profiles == 0u || (cbf__layouts[layout].profiles & CBF__PBIT(profile)) != 0u;
}

static int cbf__same_field(const cbf_field_info *a, const cbf_field_info *b)
{
    return strcmp(a->name, b->name) == 0 && a->kind == b->kind && a->flags == b->flags && a->offset == b->offset
           && a->elem == b->elem && a->count == b->count
           && (a->unit == b->unit || (a->unit && b->unit && strcmp(a->unit, b->unit) == 0));
}

/* The layout a profile's writers write a record in (N8: implib writes the
 * short layout its profile lists): a command with a layout of its own under
 * the profile in the version is written in the first such layout. A record in
 * a longer layout that starts with the same fields is cut to it when the
 * fields cut off are reserved and zero. Returns the size to keep (nb when nothing changes), or -1 when the
 * record cannot be written so (the profile's reader could not read it). */
static long cbf__profile_size(int version, int code, const uint8_t *args, size_t nb, int profile)
{
    int cmd = cbf__cmd_index(code), have = cbf_args_layout(code, version, nb), own = -1, k;
    size_t i;
    const cbf__layout *L, *H;
    if (cmd < 0 || have == CBF_LAYOUT__NONE || version < 0 || version >= CBF__NVERSIONS)
        return (long)nb;
    for (k = 0; k < cbf__commands[cmd].nlayouts && own < 0; k++) {
        int lay = cbf__commands[cmd].first_layout + k;
        if ((cbf__layouts[lay].versions & CBF__VBIT(version)) && (cbf__layouts[lay].profiles & CBF__PBIT(profile)))
            own = lay;
    }
    if (own < 0 || (cbf__layouts[have].profiles & CBF__PBIT(profile)))
        return (long)nb;
    L = &cbf__layouts[own];
    H = &cbf__layouts[have];
    if (L->nargs > H->nargs || L->size > H->size || L->group >= 0 || H->group >= 0)
        return -1; /* a repeated group is never cut */
    for (i = 0; i < L->nargs; i++)
        if (!cbf__same_field(&cbf__args[L->first_arg + i], &cbf__args[H->first_arg + i]))
            return -1;
    for (i = L->nargs; i < H->nargs; i++)
        if (!(cbf__args[H->first_arg + i].flags & CBF__F_RESERVED))
            return -1;
    for (i = L->size; i < nb; i++)
        if (args[i] != 0u)
            return -1;
    return (long)L->size;
}


int cbf_encode_record(cbf_writer *w, int code, const uint8_t *args, size_t nargs)
{
    cbf_record_head head;
    size_t k;
    if (!w || !w->buf)
        return CBF_ERR_ARGUMENT;
    if (w->error)
        return w->error;
    if (code < 0 || code > 0xFF || (!args && nargs))
        return cbf__wfail(w, CBF_ERR_RANGE);
    if (!cbf__record_writable(w->version, code, nargs))
        return cbf__wfail(w, CBF_ERR_NOT_WRITABLE);
    memset(&head, 0, sizeof head);
    for (k = 0; k < CBF__NRECORD_FIELDS; k++) {
        const cbf_field_info *f = &cbf__record_fields[k];
        unsigned char *m = (unsigned char *)&head + f->member;
        uint32_t v = 0u, max = f->elem >= 4u ? 0xFFFFFFFFu : ((1u << (8u * f->elem)) - 1u);
        if (f->role == CBF_ROLE_SEQUENCE) v = (uint32_t)(w->count & max);
        else if (f->role == CBF_ROLE_CODE || f->role == CBF_ROLE_CODE_COPY) v = (uint32_t)code;
        else if (f->role == CBF_ROLE_ARG_SIZE) {
            if (nargs > max)
                return cbf__wfail(w, CBF_ERR_RANGE);
            v = (uint32_t)nargs;
        } else if (f->checksum == CBF__CK_ARGS) v = cbf_args_checksum(args, nargs);
        if (v > max)
            return cbf__wfail(w, CBF_ERR_RANGE);
        if (f->elem == 1) { uint8_t x = (uint8_t)v; memcpy(m, &x, 1); }
        else if (f->elem == 2) { uint16_t x = (uint16_t)v; memcpy(m, &x, 2); }
        else memcpy(m, &v, 4);
    }
    return cbf_encode_record_stored(w, &head, args, nargs);
}

int cbf_encode_bytes(cbf_writer *w, const uint8_t *bytes, size_t n)
{
    if (!w || !w->buf)
        return CBF_ERR_ARGUMENT;
    if (w->error)
        return w->error;
    if (!bytes && n)
        return cbf__wfail(w, CBF_ERR_ARGUMENT);
    if (w->cap - w->len < n)
        return cbf__wfail(w, CBF_ERR_BUFFER);
    if (n)
        memcpy(w->buf + w->len, bytes, n);
    w->len += n;
    return CBF_OK;
}

/* The record at pos cut to the profile's layout (the bytes after it move up); its argument size, or -1
 * when the profile has no layout for it. */
static long cbf__fill_cut(cbf_writer *w, size_t pos, int profile, const cbf_field_info *f_code,
                          const cbf_field_info *f_nb, const cbf_field_info *f_ck)
{
    uint8_t *p = w->buf + pos;
    int code = (int)cbf__get_u(p + f_code->offset, f_code->elem);
    size_t nb = cbf__get_u(p + f_nb->offset, f_nb->elem);
    long keep = cbf__profile_size(w->version, code, p + CBF_RECORD_HEAD_SIZE, nb, profile);
    if (keep < 0)
        return -1;
    if ((size_t)keep < nb) { /* cut to the profile's layout: the bytes after it move up */
        size_t cut = nb - (size_t)keep, end = pos + CBF_RECORD_HEAD_SIZE + nb;
        memmove(p + CBF_RECORD_HEAD_SIZE + keep, w->buf + end, w->len - end);
        w->len -= cut;
        w->records_end -= cut;
        nb = (size_t)keep;
        cbf__put_u(p + f_nb->offset, (uint32_t)nb, f_nb->elem);
        if (f_ck)
            cbf__put_u(p + f_ck->offset, cbf_args_checksum(p + CBF_RECORD_HEAD_SIZE, nb), f_ck->elem);
    }
    return (long)nb;
}

/* Every record written: cut to the profile's layout, writable, and its checksum fields filled. Records
 * appended with cbf_encode_record_stored pass the same test. */
static int cbf__fill_records(cbf_writer *w, int profile)
{
    const cbf_field_info *f_code = cbf__record_field_by_role(CBF_ROLE_CODE);
    const cbf_field_info *f_nb = cbf__record_field_by_role(CBF_ROLE_ARG_SIZE);
    const cbf_field_info *f_ck = cbf__record_field_by_tag(CBF__CK_ARGS);
    size_t pos = CBF_HEADER_SIZE;
    while (f_code && f_nb && pos < w->records_end) {
        uint8_t *p = w->buf + pos;
        int code = (int)cbf__get_u(p + f_code->offset, f_code->elem);
        long got = cbf__fill_cut(w, pos, profile, f_code, f_nb, f_ck);
        size_t nb;
        int layout;
        if (got < 0)
            return CBF_ERR_NOT_WRITABLE;
        nb = (size_t)got;
        layout = cbf_args_layout(code, w->version, nb);
        if (!cbf__record_writable(w->version, code, nb) || !cbf__profile_accepts(layout, profile))
            return CBF_ERR_NOT_WRITABLE;
        /* checksum fields among the arguments (issue 25, point 1), then the head's sum over them */
        if (cbf__fill_argcks(layout, p, nb) && f_ck)
            cbf__put_u(p + f_ck->offset, cbf_args_checksum(p + CBF_RECORD_HEAD_SIZE, nb), f_ck->elem);
        pos += CBF_RECORD_HEAD_SIZE + nb;
    }
    return CBF_OK;
}

/* The header layout lay's magic numbers and command count. */
static int cbf__fill_header(cbf_writer *w, int lay)
{
    size_t i;
    for (i = 0; i < cbf__headers[lay].nfields; i++) {
        const cbf_field_info *f = &cbf__headers[lay].fields[i];
        if (f->kind != CBF__K_UINT)
            continue;
        if (f->flags & CBF__F_MAGIC)
            cbf__put_u(w->buf + f->offset, f->magic, f->elem);
        if (f->role == CBF_ROLE_COMMAND_COUNT) {
            uint32_t max = f->elem >= 4u ? 0xFFFFFFFFu : ((1u << (8u * f->elem)) - 1u);
            if (w->count > max)
                return CBF_ERR_RANGE;
            cbf__put_u(w->buf + f->offset, (uint32_t)w->count, f->elem);
        }
    }
    return CBF_OK;
}

/* The header's checksum fields, in their fill order (the file's over the profile's first coverage). */
static void cbf__fill_header_sums(cbf_writer *w, int lay, int profile)
{
    size_t i;
    for (i = 0; i < sizeof cbf__fill_order / sizeof cbf__fill_order[0]; i++) {
        int tag = cbf__fill_order[i];
        const cbf__ckfield *k = cbf__ckfield_of(tag);
        const cbf_field_info *f = cbf__header_field_by_tag(lay, tag);
        int cov;
        if (tag == CBF__CK_ARGS || !k || !f)
            continue; /* argument checksums are written with each record */
        cov = (tag == CBF__CK_FILE && cbf__profiles[profile].file[0] >= 0) ? cbf__profiles[profile].file[0]
                                                                             : k->coverage;
        cbf__put_u(w->buf + f->offset,
                   cbf__cover(cov, tag == CBF__CK_FILE ? cbf__profiles[profile].file_alg : k->alg, f->elem, w->buf,
                              w->len, w->records_end, NULL, 0), f->elem);
    }
}

long cbf_encode_end(cbf_writer *w, int profile, int fill)
{
    int lay, rc;
    if (!w || !w->buf)
        return CBF_ERR_ARGUMENT;
    if (w->error)
        return w->error;
    if (profile < 0 || profile >= CBF_PROFILE__COUNT)
        return cbf__wfail(w, CBF_ERR_ARGUMENT);
    if (!fill)
        return (long)w->len;
    if (!cbf_version_writable(w->version))
        return cbf__wfail(w, CBF_ERR_NOT_WRITABLE);
    rc = cbf__fill_records(w, profile);
    if (rc != CBF_OK)
        return cbf__wfail(w, rc);
    lay = cbf__versions[w->eff_version].header;
    rc = cbf__fill_header(w, lay);
    if (rc != CBF_OK)
        return cbf__wfail(w, rc);
    cbf__fill_header_sums(w, lay, profile);
    return (long)w->len;
}
