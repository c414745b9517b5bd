/* ---- cbf_validate: the header, the record pass, the end of the file -------- */
/* Whether the profile's file checksum is the plain sum of every byte from a
 * start inside the header to the end of the file: the record pass then adds it
 * up as it goes (each record's head and argument sums), with no second pass. */
static int cbf__file_sum_folds(int profile, size_t *start)
{
    int cov = cbf__profiles[profile].file[0];
    const cbf__segment *seg;
    if (cov < 0 || cbf__algs[cbf__profiles[profile].file_alg].family != CBF__FAMILY_SUM || cbf__coverages[cov].n != 1u)
        return 0;
    seg = &cbf__segments[cbf__coverages[cov].first];
    if (seg->region != CBF__REGION_FILE || seg->start > CBF_HEADER_SIZE)
        return 0;
    *start = seg->start;
    return 1;
}

/* arg_size: "<command> with 20 argument bytes; expected 24" (the sizes of the command's layouts in the
 * file's version that the profile accepts, ascending, each once). Cold: a record of a bad size. */
CBF__COLD static void cbf__arg_size(cbf__vctx *v, int cmd, int profile, long rec, size_t off, size_t nb)
{
    char msg[256];
    size_t at = 0;
    long size = -1;
    int k, first = 1;
    cbf__cat(msg, sizeof msg, &at, "%s with %lu argument bytes; expected ", cbf__commands[cmd].name,
             (unsigned long)nb);
    /* ascending: each time the least size above the last of any layout (a repeated group takes
     * many, nb = size + k n), until none is left or the message is full */
    while (at + 1u < sizeof msg) {
        long next = -1;
        for (k = 0; k < CBF__MAX_CANDIDATES; k++) {
            int lay = cbf__commands[cmd].candidates[v->eff][k];
            long s;
            if (lay < 0)
                break;
            if (!cbf__profile_accepts(lay, profile))
                continue;
            s = cbf__layout_next_size(&cbf__layouts[lay], size);
            if (s >= 0 && (next < 0 || s < next))
                next = s;
        }
        if (next < 0)
            break;
        cbf__cat(msg, sizeof msg, &at, "%s%ld", first ? "" : " or ", next);
        first = 0;
        size = next;
    }
    cbf__each(v, CBF__KIND_ARG_SIZE, rec, off, "%s", msg);
}

/* shape: the file ends inside a shape, named by the command that opened it. */
CBF__COLD static void cbf__shape_unclosed(cbf__vctx *v)
{
    const cbf_field_info *sn = cbf__layout_arg(v->shape_layout, cbf__layouts[v->shape_layout].shape[CBF__S_NAME]);
    char msg[256];
    size_t at = 0;
    cbf__cat(msg, sizeof msg, &at, "shape ");
    cbf__name_of(msg, sizeof msg, &at, v->shape_args, sn);
    cbf__cat(msg, sizeof msg, &at, " is never closed");
    cbf__each(v, CBF__KIND_SHAPE, v->shape_rec, v->shape_off, "%s", msg);
}

/* Per command: the argument size last seen and what it gave (records of one
 * command almost always share one size). */
typedef struct cbf__seen { long nb; int accepted, layout, avail; } cbf__seen;

/* The head's argument checksum (6.4.4) differs: a finding of every arg_checksum check that judges
 * it (not those of a checksum field among a command's arguments, issue 25 point 1). */
static void cbf__head_sum_findings(cbf__vctx *v, long rec, size_t off, uint32_t got, uint32_t want)
{
    int ci;
    for (ci = 0; ci < CBF__NCHECKS; ci++)
        if (cbf__checks[ci].kind == CBF__KIND_ARG_CHECKSUM && !cbf__judges_argck(ci))
            cbf__say(v, ci, rec, off, "stored argument checksum %lu, computed %lu", (unsigned long)got,
                     (unsigned long)want);
}

/* Each checksum field among the arguments of the record at pos (rec, its nb argument bytes, of
 * layout), judged by its arg_checksum check at the field's offset (issue 25, point 1). */
static void cbf__check_argcks(cbf__vctx *v, int layout, const uint8_t *rec, size_t nb, long recno, size_t pos)
{
    size_t i;
    for (i = 0; i < sizeof cbf__argcks / sizeof cbf__argcks[0]; i++) {
        const cbf__argck *a = &cbf__argcks[i];
        const cbf__ckfield *k;
        uint32_t want, got;
        if (a->layout != layout || a->ckfield < 0 || (size_t)a->offset + a->elem > nb)
            continue;
        k = &cbf__ckfields[a->ckfield];
        if (k->check < 0)
            continue;
        want = cbf__argck_value(a, rec, nb);
        got = cbf__get_u(rec + CBF_RECORD_HEAD_SIZE + a->offset, a->elem);
        if (got != want)
            cbf__say(v, k->check, recno, pos + CBF_RECORD_HEAD_SIZE + a->offset, "stored %s checksum %lu, computed %lu",
                     k->name, (unsigned long)got, (unsigned long)want);
    }
}

/* The header: its version, magic numbers and strings, its checksum fields, the implant descriptor. */
static void cbf__validate_header(cbf__vctx *v, const cbf_header *h)
{
    const uint8_t *buf = v->buf;
    size_t i;
    if (v->version < 0)
        cbf__each(v, CBF__KIND_VERSION, -1, CBF__VERSION_MAJOR_OFFSET,
                  "version %u.%u is not a version of this spec; read as %s", h->major, h->minor,
                  cbf__versions[v->eff].id);
    /* header fields: magic numbers, strings */
    for (i = 0; i < cbf__headers[v->hlayout].nfields; i++) {
        const cbf_field_info *f = &cbf__headers[v->hlayout].fields[i];
        if ((f->flags & CBF__F_MAGIC) && f->kind == CBF__K_UINT) {
            uint32_t got = cbf__get_u(buf + f->offset, f->elem);
            if (got != f->magic)
                cbf__each(v, CBF__KIND_MAGIC, -1, f->offset, "%s is 0x%08lX, expected 0x%08lX", f->name,
                          (unsigned long)got, (unsigned long)f->magic);
        }
        if (f->kind == CBF__K_STRING)
            cbf__check_string(v, NULL, f, buf, 0, -1);
    }
    /* each header checksum field this version's header carries, judged by its header_checksum check */
    for (i = 0; i < sizeof cbf__ckfields / sizeof cbf__ckfields[0]; i++) {
        const cbf__ckfield *k = &cbf__ckfields[i];
        const cbf_field_info *f = k->check >= 0 ? cbf__header_field_by_tag(v->hlayout, k->tag) : NULL;
        if (f) {
            uint32_t want = cbf__cover(k->coverage, k->alg, f->elem, buf, v->len, CBF_HEADER_SIZE, NULL, 0);
            uint32_t got = cbf__get_u(buf + f->offset, f->elem);
            if (got != want)
                cbf__say(v, k->check, -1, f->offset, "stored %s checksum %lu, computed %lu", k->name,
                         (unsigned long)got, (unsigned long)want);
        }
    }
    cbf__check_part_number(v);
    cbf__check_descriptor_word(v);
}

/* The record pass's state: where it is, and the sums it adds up as it goes. */
typedef struct cbf__rpass {
    const cbf__ckfield *kck; /* the head's argument checksum field, or NULL */
    int args_sum;            /* it is a plain sum over the arguments alone (the spec's 6.4.4) */
    int folds;               /* the file checksum is summed up in the record pass (cbf__file_sum_folds) */
    int profile;
    uint32_t fold;
    size_t pos;
    unsigned long nrec;
    cbf__seen seen[CBF__NCOMMANDS];
} cbf__rpass;

/* A new argument size for the command: its layout, whether the profile accepts the size, and the
 * availability check that covers it in the file's version (-1: available). */
CBF__INLINE void cbf__seen_size(const cbf__vctx *v, cbf__seen *s, int cmd, uint32_t code, size_t nb, int profile)
{
    int k;
    s->nb = (long)nb;
    s->accepted = 0;
    for (k = 0; k < CBF__MAX_CANDIDATES; k++) {
        int lay = cbf__commands[cmd].candidates[v->eff][k];
        if (lay < 0)
            break;
        if (cbf__layout_takes(&cbf__layouts[lay], nb) && cbf__profile_accepts(lay, profile))
            s->accepted = 1;
    }
    s->layout = cbf_args_layout((int)code, v->eff, nb);
    /* availability: the command has no layout for the file's version (fallback included);
     * the finding names the one check that covers this command in this version */
    s->avail = (cbf__commands[cmd].versions & CBF__VBIT(v->eff)) ? -1 : cbf__avail_check[cmd][v->eff];
}

/* The record head at p: sequence number, code copy, argument checksums, reserved byte. */
CBF__INLINE void cbf__head_checks(cbf__vctx *v, const cbf__rpass *r, const uint8_t *p, size_t nb, int layout,
                                  uint32_t asum)
{
    const long rec = (long)r->nrec;
    const size_t pos = r->pos;
    const uint32_t code = CBF__HEAD_CODE(p), copy = CBF__HEAD_CODE_COPY(p), seq = CBF__HEAD_SEQUENCE(p);
    const uint32_t res = CBF__HEAD_RESERVED(p);
    if (seq != (uint32_t)(r->nrec & CBF__SEQUENCE_MASK))
        cbf__each(v, CBF__KIND_SEQUENCE, rec, pos + CBF__HEAD_OFF_SEQUENCE, "sequence number %lu, expected %lu",
                  (unsigned long)seq, (unsigned long)(r->nrec & CBF__SEQUENCE_MASK));
    if (code != copy)
        cbf__each(v, CBF__KIND_CODE_COPY, rec, pos + CBF__HEAD_OFF_CODE_COPY, "code copy 0x%02lX differs from code 0x%02lX",
                  (unsigned long)copy, (unsigned long)code);
#if CBF__HEAD_CK_ELEM
    {
        uint32_t want = r->args_sum ? (asum & CBF__HEAD_CK_MASK)
                        : r->kck ? cbf__cover(r->kck->coverage, r->kck->alg, CBF__HEAD_CK_ELEM, NULL, 0, 0,
                                              p + CBF_RECORD_HEAD_SIZE, nb)
                                 : 0u;
        uint32_t got = cbf__get_u(p + CBF__HEAD_CK_OFFSET, CBF__HEAD_CK_ELEM);
        if (got != want)
            cbf__head_sum_findings(v, rec, pos + CBF__HEAD_CK_OFFSET, got, want);
    }
#else
    (void)asum;
#endif
    if (layout >= 0)
        cbf__check_argcks(v, layout, p, nb, rec, pos);
    if (res != 0u)
        cbf__each(v, CBF__KIND_RESERVED_BYTE, rec, pos + CBF__HEAD_OFF_RESERVED, "reserved byte is 0x%02lX",
                  (unsigned long)res);
}

/* The record's command: known, available, of a size the profile accepts, not deprecated; then the checks
 * of its decoded arguments (the layout's function). */
CBF__INLINE void cbf__command_checks(cbf__vctx *v, const cbf__rpass *r, const uint8_t *p, int cmd, int layout,
                                     size_t nb)
{
    const long rec = (long)r->nrec;
    const size_t pos = r->pos;
    if (cmd < 0) {
        cbf__each(v, CBF__KIND_UNKNOWN_CODE, rec, pos + CBF__HEAD_OFF_CODE, "unknown command code 0x%02lX",
                  (unsigned long)CBF__HEAD_CODE(p));
        return;
    }
    if (r->seen[cmd].avail >= 0)
        cbf__say(v, r->seen[cmd].avail, rec, pos + CBF__HEAD_OFF_CODE, "%s is not available in version %s",
                 cbf__commands[cmd].name, cbf__versions[v->eff].id);
    if (!r->seen[cmd].accepted)
        cbf__arg_size(v, cmd, r->profile, rec, pos + CBF__HEAD_OFF_ARG_SIZE, nb);
    if (layout == CBF_LAYOUT__NONE)
        return;
    if (cbf__deprecated[layout] >= 0)
        cbf__say(v, cbf__deprecated[layout], rec, pos + CBF__HEAD_OFF_CODE, "%s is deprecated since version %s",
                 cbf__commands[cmd].name, cbf__versions[cbf__deprecation_since(cbf__deprecated[layout])].id);
    cbf__decoded_checks(v, layout, p + CBF_RECORD_HEAD_SIZE, rec, pos);
}

/* The records, framed by nb from the header to the end of the file (D1). */
static void cbf__record_pass(cbf__vctx *v, cbf__rpass *r)
{
    const uint8_t *buf = v->buf;
    const size_t len = v->len;
    size_t i;
    for (i = 0; i < (size_t)CBF__NCOMMANDS; i++)
        r->seen[i].nb = -1;
    while (len - r->pos >= CBF_RECORD_HEAD_SIZE) {
        const uint8_t *p = buf + r->pos;
        size_t nb = CBF__HEAD_ARG_SIZE(p);
        uint32_t code, asum = 0u;
        int cmd, layout = CBF_LAYOUT__NONE;
        if (len - r->pos - CBF_RECORD_HEAD_SIZE < nb)
            break;
        code = CBF__HEAD_CODE(p);
        cmd = cbf__cmd_index((int)code);
        if (cmd >= 0 && r->seen[cmd].nb != (long)nb) /* a new size for the command: look its layout up */
            cbf__seen_size(v, &r->seen[cmd], cmd, code, nb, r->profile);
        if (cmd >= 0)
            layout = r->seen[cmd].layout;
        if (r->args_sum)
            asum = cbf__args_sum(layout, p + CBF_RECORD_HEAD_SIZE, nb);
        if (r->folds)
            r->fold += CBF__HEAD_SUM(p) + asum;
        cbf__head_checks(v, r, p, nb, layout, asum);
        cbf__command_checks(v, r, p, cmd, layout, nb);
        r->pos += CBF_RECORD_HEAD_SIZE + nb;
        r->nrec++;
    }
}

/* The end of the file: an open shape, a record cut short or bytes after the last record, the count. */
static void cbf__validate_end(cbf__vctx *v, const cbf_header *h, const cbf__rpass *r)
{
    const size_t pos = r->pos, len = v->len;
    const unsigned long nrec = r->nrec;
    int truncated = 0;
    if (v->shape_open)
        cbf__shape_unclosed(v);
    if (pos < len) {
        if (nrec < h->count) {
            truncated = 1;
            cbf__each(v, CBF__KIND_TRUNCATED_RECORD, (long)nrec, pos,
                      "the file ends inside record %lu (%lu byte(s) left)", nrec, (unsigned long)(len - pos));
        } else {
            cbf__each(v, CBF__KIND_TRAILING, -1, pos, "%lu byte(s) after the last record", (unsigned long)(len - pos));
        }
    }
    if (!truncated && nrec != h->count) {
        const cbf_field_info *fc = cbf__header_field_by_role(v->hlayout, CBF_ROLE_COMMAND_COUNT);
        cbf__each(v, CBF__KIND_COMMAND_COUNT, -1, fc ? fc->offset : 0u, "header count %lu, the file holds %lu records",
                  h->count, nrec);
    }
}

/* file_checksum differs from every coverage of the profile: one message, the sums, then every hint coverage
 * the stored value matches. Cold. */
CBF__COLD static void cbf__file_sum_finding(cbf__vctx *v, const cbf_field_info *f, int profile, size_t pos,
                                            uint32_t got, uint32_t first)
{
    const cbf__profile *pr = &cbf__profiles[profile];
    char msg[512];
    size_t at = 0;
    int c;
    cbf__cat(msg, sizeof msg, &at, "stored file checksum %lu, computed %lu", (unsigned long)got, (unsigned long)first);
    for (c = 0; c < CBF__MAX_COVERAGES && pr->hint[c] >= 0; c++) {
        if (cbf__cover(pr->hint[c], pr->hint_alg[c], f->elem, v->buf, v->len, pos, NULL, 0) == got)
            cbf__cat(msg, sizeof msg, &at, "; it matches coverage %s (use profile %s)", cbf__coverages[pr->hint[c]].name,
                     pr->hint_owner[c] >= 0 ? cbf__profiles[pr->hint_owner[c]].id : "?");
    }
    cbf__each(v, CBF__KIND_FILE_CHECKSUM, -1, f->offset, "%s", msg);
}

/* The file checksum field, against every coverage of the profile (the first folded into the record pass
 * when it is a plain sum from inside the header, and the bytes after the last record). */
static void cbf__check_file_sum(cbf__vctx *v, const cbf__rpass *r)
{
    const cbf__ckfield *k = cbf__ckfield_of(CBF__CK_FILE);
    const cbf_field_info *f = cbf__header_field_by_tag(v->hlayout, CBF__CK_FILE);
    const int profile = r->profile;
    uint32_t got, first = 0u;
    int c, match = 0;
    if (!k || !f)
        return;
    got = cbf__get_u(v->buf + f->offset, f->elem);
    for (c = 0; c < CBF__MAX_COVERAGES && cbf__profiles[profile].file[c] >= 0; c++) {
        uint32_t want;
        if (c == 0 && r->folds) { /* the record pass's sum, and the bytes after the last record */
            want = r->fold + cbf__sum(v->buf + r->pos, v->len - r->pos);
            if (f->elem < 4u)
                want &= (1u << (8u * f->elem)) - 1u;
        } else {
            want = cbf__cover(cbf__profiles[profile].file[c], cbf__profiles[profile].file_alg, f->elem, v->buf, v->len,
                              r->pos, NULL, 0);
        }
        if (c == 0)
            first = want;
        if (want == got)
            match = 1;
    }
    if (!match)
        cbf__file_sum_finding(v, f, profile, r->pos, got, first);
}

CBF__HOT long cbf_validate(const uint8_t *buf, size_t len, const cbf_options *opt, cbf_finding_fn fn,
                          void *user)
{
    cbf__vctx v;
    cbf_header h;
    cbf__rpass r;
    size_t fold_start = 0;
    int profile = opt ? opt->profile : CBF__DEFAULT_PROFILE;
    if ((!buf && len) || profile < 0 || profile >= CBF_PROFILE__COUNT)
        return CBF_ERR_ARGUMENT;
    memset(&v, 0, sizeof v);
    v.buf = buf;
    v.len = len;
    v.opt = opt;
    v.fn = fn;
    v.user = user;
    /* below this tan^2 the orientation angle is under its tolerance (with a margin of 1/1000) */
    v.ori_tan2 = cbf__tol_orientation > 0.0 && cbf__tol_orientation < 45.0
                 ? pow(tan(cbf__tol_orientation * 0.999 * (CBF__PI / 180.0)), 2.0) : 0.0;
    cbf__machine_start(&v);
    if (len < CBF_HEADER_SIZE || !buf) {
        cbf__each(&v, CBF__KIND_TRUNCATED_HEADER, -1, 0, "file is %lu bytes, the header needs %d",
                  (unsigned long)len, CBF_HEADER_SIZE);
        return v.errors;
    }
    (void)cbf_header_decode(buf, len, &h);
    v.version = h.version;
    v.eff = cbf__eff_version(h.version);
    v.hlayout = h.layout;
    cbf__validate_header(&v, &h);

    r.pos = CBF_HEADER_SIZE;
    r.nrec = 0;
    r.profile = profile;
    r.fold = 0u;
    r.kck = cbf__ckfield_of(CBF__CK_ARGS);
    /* a plain sum over the arguments alone (the spec's 6.4.4) needs no coverage walk */
    r.args_sum = r.kck && cbf__algs[r.kck->alg].family == CBF__FAMILY_SUM && cbf__coverages[r.kck->coverage].n == 1u
                 && cbf__segments[cbf__coverages[r.kck->coverage].first].region == CBF__REGION_ARGS;
    r.folds = r.args_sum && cbf__file_sum_folds(profile, &fold_start);
    if (r.folds)
        r.fold = cbf__sum(buf + fold_start, CBF_HEADER_SIZE - fold_start);
    cbf__record_pass(&v, &r);
    cbf__validate_end(&v, &h, &r);
    cbf__check_file_sum(&v, &r);
    return v.errors;
}
