/* ---- the shapes of the spec's tables (filled by the generated section that follows) -- */
typedef struct cbf__version {
    const char *id;
    int major, minor; /* minor -1: any */
    int header;
    int writable;
} cbf__version;

typedef struct cbf__header_layout {
    const cbf_field_info *fields;
    size_t nfields;
    size_t size;
    size_t member; /* offsetof in cbf_header */
} cbf__header_layout;

typedef struct cbf__layout {
    int command;        /* index into cbf__commands */
    const char *variant;
    unsigned versions;  /* CBF__VBIT mask */
    unsigned profiles;  /* CBF__PBIT mask; 0: every profile */
    size_t size;
    size_t first_arg, nargs;
    size_t member;      /* offsetof in cbf_args (always 0: a union) */
    signed char motion[CBF__M__COUNT];
    signed char orient[CBF__O__COUNT];
    signed char shape[CBF__S__COUNT];
    signed char cutter[CBF__C__COUNT];
    signed char progress;
    /* A repeated argument group (issue 25, point 3): its index in the layout (the last argument; -1:
     * none); a record holds n items, group_min <= n <= group_max, nb = size + group_item * n; the
     * decoded struct keeps them in a bounded array and n at offset group_n of cbf_args. */
    signed char group;
    unsigned group_min, group_max;
    size_t group_item;
    size_t group_n;
} cbf__layout;

typedef struct cbf__command {
    int code;
    const char *name;
    int first_layout, nlayouts;
    unsigned versions;
    int motion, orient, shape, cutter;
    signed char candidates[CBF__NVERSIONS][CBF__MAX_CANDIDATES]; /* decode order per version, -1 ends */
} cbf__command;

typedef struct cbf__segment {
    int region;
    size_t start;
    long end;          /* -1: none */
    unsigned exclude;  /* record head fields left out (bit = index in cbf__record_fields) */
} cbf__segment;

typedef struct cbf__coverage { const char *name; size_t first, n; } cbf__coverage;

/* A checksum field among a layout's arguments (issue 25, point 1): layout (cbf__layouts), its row
 * of cbf__ckfields (algorithm, judging check, tag), the argument's offset and width, and the record
 * byte ranges (cbf__argck_ranges[first .. first + n)) it covers, fed in order. */
typedef struct cbf__argck { int layout; int ckfield; unsigned offset, elem; size_t first, n; } cbf__argck;
typedef struct cbf__range { unsigned start, end; } cbf__range;

/* check: the header_checksum check that judges the field (index in cbf__checks), -1 none; name: its tag */
typedef struct cbf__ckfield { int tag; int alg; int coverage; int check; const char *name; } cbf__ckfield;

typedef struct cbf__profile {
    const char *id;
    int file[CBF__MAX_COVERAGES]; /* coverages accepted for the file checksum, -1 ends */
    int hint[CBF__MAX_COVERAGES]; /* coverages named in the message when they match */
    int file_alg;                 /* the file checksum's algorithm under this profile */
    int hint_alg[CBF__MAX_COVERAGES]; /* each hint computed as the profile that accepts it */
    int hint_owner[CBF__MAX_COVERAGES]; /* that profile (its index; -1: none accepts it) */
} cbf__profile;

typedef struct cbf__target { int command; size_t first, n; } cbf__target;

typedef struct cbf__check {
    const char *id;
    int kind;
    int severity;
    unsigned versions;
    size_t first_target, ntargets;
    int has_min; double min;
    int has_max; double max;
    int min_open, max_open; /* range: the bound excludes its value (> min, < max) */
} cbf__check;

static const double cbf__tol_position = CBF_TOLERANCE_POSITION_MM;
static const double cbf__tol_orientation = CBF_TOLERANCE_ORIENTATION_DEG;
static const double cbf__tol_cutter = CBF_TOLERANCE_CUTTER_MM;
