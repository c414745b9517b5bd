/* ---- header and records --------------------------------------------------- */
long cbf_header_decode(const uint8_t *buf, size_t len, cbf_header *out)
{
    const cbf_field_info *fmaj, *fmin, *fcnt;
    int lay;
    if (!buf || !out)
        return CBF_ERR_ARGUMENT;
    if (len < CBF_HEADER_SIZE)
        return CBF_ERR_TRUNCATED_HEADER;
    memset(out, 0, sizeof *out);
    fmaj = cbf__header_field_by_role(0, CBF_ROLE_VERSION_MAJOR);
    fmin = cbf__header_field_by_role(0, CBF_ROLE_VERSION_MINOR);
    out->major = fmaj ? (unsigned)cbf__get_u(buf + fmaj->offset, fmaj->elem) : 0u;
    out->minor = fmin ? (unsigned)cbf__get_u(buf + fmin->offset, fmin->elem) : 0u;
    out->version = cbf_version_find(out->major, out->minor);
    lay = cbf__versions[cbf__eff_version(out->version)].header;
    out->layout = lay;
    fcnt = cbf__header_field_by_role(lay, CBF_ROLE_COMMAND_COUNT);
    out->count = fcnt ? (unsigned long)cbf__get_u(buf + fcnt->offset, fcnt->elem) : 0ul;
    cbf__load(cbf__headers[lay].fields, cbf__headers[lay].nfields, buf,
              (unsigned char *)out + cbf__headers[lay].member);
    return CBF_HEADER_SIZE;
}

int cbf_header_init(cbf_header *h, int version)
{
    const cbf_field_info *f;
    size_t i;
    int lay;
    if (!h || version < 0 || version >= CBF__NVERSIONS)
        return CBF_ERR_ARGUMENT;
    memset(h, 0, sizeof *h);
    h->version = version;
    lay = cbf__versions[version].header;
    h->layout = lay;
    h->major = (unsigned)cbf__versions[version].major;
    h->minor = cbf__versions[version].minor < 0 ? 0u : (unsigned)cbf__versions[version].minor;
    for (i = 0; i < cbf__headers[lay].nfields; i++) {
        uint32_t v;
        f = &cbf__headers[lay].fields[i];
        if (f->role == CBF_ROLE_VERSION_MAJOR) v = h->major;
        else if (f->role == CBF_ROLE_VERSION_MINOR) v = h->minor;
        else if (f->flags & CBF__F_MAGIC) v = f->magic;
        else continue;
        if (f->kind != CBF__K_UINT)
            continue;
        if (f->elem == 1) { uint8_t x = (uint8_t)v; memcpy((unsigned char *)h + cbf__headers[lay].member + f->member, &x, 1); }
        else if (f->elem == 2) { uint16_t x = (uint16_t)v; memcpy((unsigned char *)h + cbf__headers[lay].member + f->member, &x, 2); }
        else memcpy((unsigned char *)h + cbf__headers[lay].member + f->member, &v, 4);
    }
    return CBF_OK;
}

long cbf_header_encode(const cbf_header *h, uint8_t *out, size_t cap)
{
    if (!h || !out || h->layout < 0 || h->layout >= CBF_HEADER__COUNT)
        return CBF_ERR_ARGUMENT;
    if (cap < CBF_HEADER_SIZE)
        return CBF_ERR_BUFFER;
    memset(out, 0, CBF_HEADER_SIZE);
    cbf__store(cbf__headers[h->layout].fields, cbf__headers[h->layout].nfields,
               (const unsigned char *)h + cbf__headers[h->layout].member, out);
    return CBF_HEADER_SIZE;
}

int cbf_reader_init(cbf_reader *r, const uint8_t *buf, size_t len)
{
    long rc;
    if (!r || !buf)
        return CBF_ERR_ARGUMENT;
    memset(r, 0, sizeof *r);
    rc = cbf_header_decode(buf, len, &r->header);
    if (rc < 0)
        return (int)rc;
    r->buf = buf;
    r->len = len;
    r->pos = CBF_HEADER_SIZE;
    r->eff_version = cbf__eff_version(r->header.version);
    return CBF_OK;
}

long cbf_args_decode(int layout, const uint8_t *args, size_t n, cbf_args *out)
{
    const cbf__layout *L;
    long items;
    if (!cbf__layout_ok(layout) || !out || (!args && n))
        return CBF_ERR_ARGUMENT;
    L = &cbf__layouts[layout];
    if (CBF__HAS_GROUPS && L->group >= 0) { /* a repeated group: n from nb, the items after the fixed arguments */
        items = cbf__group_n(L, n);
        if (items < 0)
            return CBF_ERR_RANGE;
        memset(out, 0, sizeof *out);
        cbf__load(&cbf__args[L->first_arg], L->nargs - 1u, args, (unsigned char *)out + L->member);
        cbf__load_group(L, args, (size_t)items, out);
        return (long)n;
    }
    if (n != L->size)
        return CBF_ERR_RANGE;
    memset(out, 0, sizeof *out);
    cbf__load(&cbf__args[L->first_arg], L->nargs, args, (unsigned char *)out + L->member);
    return (long)n;
}

long cbf_args_encode(int layout, const cbf_args *in, uint8_t *out, size_t cap)
{
    const cbf__layout *L;
    size_t n, items;
    if (!cbf__layout_ok(layout) || !in || !out)
        return CBF_ERR_ARGUMENT;
    L = &cbf__layouts[layout];
    items = CBF__HAS_GROUPS ? cbf__group_items(L, in) : 0u;
    if (CBF__HAS_GROUPS && L->group >= 0 && (items < L->group_min || items > L->group_max))
        return CBF_ERR_RANGE; /* a group of n items outside its min..max: no nb says it */
    n = L->size + (CBF__HAS_GROUPS && L->group >= 0 ? L->group_item * items : 0u);
    if (cap < n)
        return CBF_ERR_BUFFER;
    memset(out, 0, n);
    cbf__store(&cbf__args[L->first_arg], L->nargs - (L->group >= 0), (const unsigned char *)in + L->member, out);
    if (CBF__HAS_GROUPS && L->group >= 0)
        cbf__store_group(L, in, items, out);
    return (long)n;
}

CBF__HOT int cbf_next_record(cbf_reader *r, cbf_record *rec)
{
    const uint8_t *p;
    size_t nb;
    size_t k;
    if (!r || !rec || !r->buf)
        return CBF_ERR_ARGUMENT;
    if (r->pos > r->len)
        return CBF_ERR_ARGUMENT;
    r->trailing = 0;
    if (r->len - r->pos < CBF_RECORD_HEAD_SIZE) {
        nb = 0;
    } else {
        nb = cbf__head_get(r->buf + r->pos, CBF_ROLE_ARG_SIZE);
        if (r->len - r->pos - CBF_RECORD_HEAD_SIZE >= nb)
            goto whole;
    }
    /* no further complete record */
    if (r->len == r->pos)
        return 0;
    if (r->index < r->header.count)
        return CBF_ERR_TRUNCATED_RECORD;
    r->trailing = r->len - r->pos;
    return 0;
whole:
    p = r->buf + r->pos;
    memset(rec, 0, sizeof *rec);
    rec->index = r->index;
    rec->offset = r->pos;
    for (k = 0; k < CBF__NRECORD_FIELDS; k++) {
        const cbf_field_info *f = &cbf__record_fields[k];
        uint32_t v = cbf__get_u(p + f->offset, f->elem);
        unsigned char *m = (unsigned char *)&rec->head + f->member;
        if (f->elem == 1) { uint8_t x = (uint8_t)v; memcpy(m, &x, 1); }
        else if (f->elem == 2) { uint16_t x = (uint16_t)v; memcpy(m, &x, 2); }
        else memcpy(m, &v, 4);
    }
    rec->args = p + CBF_RECORD_HEAD_SIZE;
    rec->nargs = nb;
    {
        int code = (int)cbf__head_get(p, CBF_ROLE_CODE);
        rec->command = cbf__cmd_index(code) < 0 ? CBF_CMD__UNKNOWN : code;
        rec->layout = cbf__cmd_index(code) < 0 ? CBF_LAYOUT__NONE : cbf_args_layout(code, r->eff_version, nb);
    }
    if (rec->layout != CBF_LAYOUT__NONE)
        (void)cbf_args_decode(rec->layout, rec->args, nb, &rec->decoded);
    r->pos += CBF_RECORD_HEAD_SIZE + nb;
    r->index++;
    return 1;
}

