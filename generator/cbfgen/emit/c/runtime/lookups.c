/* ---- look-ups ------------------------------------------------------------ */
static inline int cbf__cmd_index(int code)
{
    return (code < 0 || code > 0xFF) ? -1 : cbf__index_by_code[code];
}

static const cbf_field_info *cbf__header_field_by_role(int layout, int role)
{
    size_t i;
    for (i = 0; i < cbf__headers[layout].nfields; i++)
        if (cbf__headers[layout].fields[i].role == role)
            return &cbf__headers[layout].fields[i];
    return NULL;
}

static const cbf_field_info *cbf__header_field_by_tag(int layout, int tag)
{
    size_t i;
    for (i = 0; i < cbf__headers[layout].nfields; i++)
        if (cbf__headers[layout].fields[i].checksum == tag)
            return &cbf__headers[layout].fields[i];
    return NULL;
}

static const cbf_field_info *cbf__record_field_by_role(int role)
{
    size_t i;
    for (i = 0; i < CBF__NRECORD_FIELDS; i++)
        if (cbf__record_fields[i].role == role)
            return &cbf__record_fields[i];
    return NULL;
}

static const cbf_field_info *cbf__record_field_by_tag(int tag)
{
    size_t i;
    for (i = 0; i < CBF__NRECORD_FIELDS; i++)
        if (cbf__record_fields[i].checksum == tag)
            return &cbf__record_fields[i];
    return NULL;
}

/* A uint field of a record, through a field looked up once (NULL reads 0). */
static inline uint32_t cbf__fld(const cbf_field_info *f, const uint8_t *rec)
{
    return f ? cbf__get_u(rec + f->offset, f->elem) : 0u;
}

static uint32_t cbf__head_get(const uint8_t *rec, int role)
{
    const cbf_field_info *f = cbf__record_field_by_role(role);
    return f ? cbf__get_u(rec + f->offset, f->elem) : 0u;
}

static const cbf__ckfield *cbf__ckfield_of(int tag)
{
    size_t i;
    for (i = 0; i < sizeof cbf__ckfields / sizeof cbf__ckfields[0]; i++)
        if (cbf__ckfields[i].tag == tag)
            return &cbf__ckfields[i];
    return NULL;
}

static inline const cbf_field_info *cbf__layout_arg(int layout, int i)
{
    if (i < 0)
        return NULL;
    return &cbf__args[cbf__layouts[layout].first_arg + (size_t)i];
}

const char *cbf_strerror(int err)
{
    switch (err) {
    case CBF_OK: return "ok";
    case CBF_ERR_TRUNCATED_HEADER: return "truncated_header";
    case CBF_ERR_TRUNCATED_RECORD: return "truncated_record";
    case CBF_ERR_BUFFER: return "buffer too small";
    case CBF_ERR_ARGUMENT: return "bad argument";
    case CBF_ERR_RANGE: return "value out of range";
    case CBF_ERR_NOT_WRITABLE: return "not writable";
    case CBF_ERR_INVALID: return "the result would not validate";
    case CBF_ERR_SYNTAX: return "the text does not read";
    default: return "unknown error";
    }
}

const char *cbf_command_name(int code)
{
    int i = cbf__cmd_index(code);
    return i < 0 ? NULL : cbf__commands[i].name;
}

int cbf_command_available(int code, int version)
{
    int i = cbf__cmd_index(code);
    if (i < 0 || version < 0 || version >= CBF__NVERSIONS)
        return 0;
    return (cbf__commands[i].versions & CBF__VBIT(version)) != 0u;
}

int cbf_version_find(unsigned major, unsigned minor)
{
    int i;
    for (i = 0; i < CBF__NVERSIONS; i++)
        if ((unsigned)cbf__versions[i].major == major
            && (cbf__versions[i].minor < 0 || (unsigned)cbf__versions[i].minor == minor))
            return i;
    return CBF_V__UNKNOWN;
}

const char *cbf_version_name(int version)
{
    return (version >= 0 && version < CBF__NVERSIONS) ? cbf__versions[version].id : NULL;
}

int cbf_version_writable(int version)
{
    return (version >= 0 && version < CBF__NVERSIONS) ? cbf__versions[version].writable : 0;
}

int cbf_profile_find(const char *name)
{
    int i;
    if (!name)
        return CBF_ERR_ARGUMENT;
    for (i = 0; i < CBF_PROFILE__COUNT; i++)
        if (strcmp(cbf__profiles[i].id, name) == 0)
            return i;
    return CBF_ERR_ARGUMENT;
}

static int cbf__layout_ok(int layout) { return layout >= 0 && layout < CBF_LAYOUT__COUNT; }

const char *cbf_layout_command_name(int layout)
{
    return cbf__layout_ok(layout) ? cbf__commands[cbf__layouts[layout].command].name : NULL;
}

const char *cbf_layout_variant(int layout)
{
    return cbf__layout_ok(layout) ? cbf__layouts[layout].variant : NULL;
}

int cbf_layout_code(int layout)
{
    return cbf__layout_ok(layout) ? cbf__commands[cbf__layouts[layout].command].code : CBF_ERR_ARGUMENT;
}

long cbf_layout_size(int layout)
{
    return cbf__layout_ok(layout) ? (long)cbf__layouts[layout].size : (long)CBF_ERR_ARGUMENT;
}

size_t cbf_layout_fields(int layout, const cbf_field_info **out)
{
    if (!cbf__layout_ok(layout) || !out)
        return 0;
    *out = &cbf__args[cbf__layouts[layout].first_arg];
    return cbf__layouts[layout].nargs;
}

size_t cbf_header_fields(int header_layout, const cbf_field_info **out)
{
    if (header_layout < 0 || header_layout >= CBF_HEADER__COUNT || !out)
        return 0;
    *out = cbf__headers[header_layout].fields;
    return cbf__headers[header_layout].nfields;
}

size_t cbf_record_fields(const cbf_field_info **out)
{
    if (!out)
        return 0;
    *out = cbf__record_fields;
    return CBF__NRECORD_FIELDS;
}

static inline int cbf__eff_version(int version)
{
    return version < 0 ? CBF_FALLBACK_VERSION : version;
}

int cbf_version_header_layout(int version)
{
    if (version >= CBF__NVERSIONS)
        return CBF_ERR_ARGUMENT;
    return cbf__versions[cbf__eff_version(version)].header;
}

int cbf_args_layout(int code, int version, size_t nb)
{
    int ci = cbf__cmd_index(code);
    int k;
    if (ci < 0)
        return CBF_LAYOUT__NONE;
    version = cbf__eff_version(version);
    if (version >= CBF__NVERSIONS)
        return CBF_LAYOUT__NONE;
    for (k = 0; k < CBF__MAX_CANDIDATES; k++) {
        int lay = cbf__commands[ci].candidates[version][k];
        if (lay < 0)
            break;
        if (cbf__layout_takes(&cbf__layouts[lay], nb))
            return lay;
    }
    return CBF_LAYOUT__NONE;
}

int cbf_args_candidates(int code, int version, int *out, int cap)
{
    int ci = cbf__cmd_index(code), k, n = 0;
    if (ci < 0 || !out || version >= CBF__NVERSIONS)
        return 0;
    version = cbf__eff_version(version);
    for (k = 0; k < CBF__MAX_CANDIDATES && n < cap; k++) {
        int lay = cbf__commands[ci].candidates[version][k];
        if (lay < 0)
            break;
        out[n++] = lay;
    }
    return n;
}

