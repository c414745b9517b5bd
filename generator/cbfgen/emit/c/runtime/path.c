/* ---- the drawn path of a motion record (issue 34: the workbench draws curves with the engine's geometry) ----
 * Points along a record's motion as its spec role reads it (start, through, end, centre, normal, turn,
 * advance): a circle or helix is turned about its axis by cbf__turned, the rotation the continuity check
 * ends it with (so the last point is the end the checks compare); an arc through a middle point is the
 * circle through the three. The points are spaced as the Python codec's drawing (cbf.geometry,
 * Curve.points): every CBF__PATH_STEP_DEG degrees of turn, at most CBF_PATH_MAX_POINTS; a flat circle of
 * more than one turn is drawn as one turn, then on to its end. */

#define CBF__PATH_STEP_DEG 5.0
#define CBF__TWO_PI (2.0 * CBF__PI)

/* The offset of the argument a layout's motion role names by key (-1: none); *n its element count. */
static long cbf__motion_arg(int layout, int key, unsigned *n)
{
    int i = cbf__layouts[layout].motion[key];
    const cbf_field_info *f;
    if (i < 0)
        return -1;
    f = &cbf__args[cbf__layouts[layout].first_arg + (size_t)i];
    if (n)
        *n = f->count;
    return (long)f->offset;
}

/* The offset of the end a layout's motion role names in a record of nargs argument bytes: when the end is
 * the layout's repeated group (a polyline's points), its last item, as the Python codec's drawing and the
 * continuity check take it; else the argument's own offset (-1: none, or no n tiles nargs). */
static long cbf__motion_end(int layout, size_t nargs)
{
    const cbf__layout *L = &cbf__layouts[layout];
    long off = cbf__motion_arg(layout, CBF__M_END, NULL);
    long n;
    if (off < 0 || L->group < 0 || L->motion[CBF__M_END] != L->group)
        return off;
    n = cbf__group_n(L, nargs);
    return n > 0 ? off + (long)(L->group_item * (size_t)(n - 1)) : -1;
}

/* ceil(x) steps, at least 1, at most max (x is a turn over the step: in degrees or in radians, as
 * cbf.geometry reckons each case, so the counts are its counts). */
static size_t cbf__path_steps(double x, size_t max)
{
    double n = ceil(x);
    if (!(n >= 1.0))
        return 1;
    return n > (double)max ? max : (size_t)n;
}

static void cbf__put(double (*out)[3], const double p[3])
{
    int i;
    for (i = 0; i < 3; i++)
        (*out)[i] = p[i];
}

/* Points of a turn th (rad, signed: about k by the right-hand rule) and an advance rise from start about
 * centre. A zero radius or turn is straight: start, then start advanced. */
static size_t cbf__path_turn(const double start[3], const double center[3], const double k[3], double th,
                             double rise, double (*out)[3])
{
    double v[3], perp[3], kdv, r, a = fabs(th), p[3];
    size_t n, j, at = 0;
    int i;
    for (i = 0; i < 3; i++)
        v[i] = start[i] - center[i];
    kdv = k[0] * v[0] + k[1] * v[1] + k[2] * v[2];
    for (i = 0; i < 3; i++)
        perp[i] = v[i] - k[i] * kdv;
    r = cbf__norm(perp);
    if (r == 0.0 || th == 0.0) {
        cbf__put(&out[0], start);
        for (i = 0; i < 3; i++)
            p[i] = start[i] + rise * k[i];
        cbf__put(&out[1], p);
        return 2;
    }
    if (rise == 0.0 && a > CBF__TWO_PI) {
        const double sign = th < 0.0 ? -1.0 : 1.0, rest = fmod(a, CBF__TWO_PI);
        const double step = CBF__PATH_STEP_DEG * (CBF__PI / 180.0);
        const size_t turn = cbf__path_steps(CBF__TWO_PI / step, CBF_PATH_MAX_POINTS / 2u);
        const size_t tail = cbf__path_steps(rest / step, CBF_PATH_MAX_POINTS / 2u);
        for (j = 0; j < turn; j++)
            cbf__turned(start, center, k, sign * (CBF__TWO_PI * (double)j / (double)turn), 0.0, out[at++]);
        for (j = 0; j < tail && at + 1 < CBF_PATH_MAX_POINTS; j++)
            cbf__turned(start, center, k, sign * (rest * (double)j / (double)tail), 0.0, out[at++]);
        cbf__turned(start, center, k, th, 0.0, out[at++]);
        return at;
    }
    n = cbf__path_steps((a * (180.0 / CBF__PI)) / CBF__PATH_STEP_DEG, CBF_PATH_MAX_POINTS - 1u);
    for (j = 0; j < n; j++)
        cbf__turned(start, center, k, th * ((double)j / (double)n), rise * ((double)j / (double)n), out[at++]);
    cbf__turned(start, center, k, th, rise, out[at++]); /* the end, as the continuity check has it */
    return at;
}

/* An arc from start through mid to end: the circle through the three, run start -> mid -> end; straight
 * when they are collinear, or so nearly that binary32 values cannot tell (cbf.geometry's rule). */
static size_t cbf__path_through(const double s[3], const double m[3], const double e[3], double (*out)[3])
{
    double u[3], w[3], n[3], a[3], rel[3], center[3], k[3], e1[3], e2[3], b[3], n2, r, th, big = 0.0, uu, ww;
    double ab[3], ap[3], den, t, d[3];
    int i;
    for (i = 0; i < 3; i++) {
        u[i] = m[i] - s[i];
        w[i] = e[i] - s[i];
        big = fmax(big, fmax(fabs(s[i]), fmax(fabs(m[i]), fabs(e[i]))));
    }
    n[0] = u[1] * w[2] - u[2] * w[1];
    n[1] = u[2] * w[0] - u[0] * w[2];
    n[2] = u[0] * w[1] - u[1] * w[0];
    n2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    /* the distance of mid from the line through start and end */
    for (i = 0; i < 3; i++) {
        ab[i] = e[i] - s[i];
        ap[i] = m[i] - s[i];
    }
    den = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
    t = den == 0.0 ? 0.0 : (ap[0] * ab[0] + ap[1] * ab[1] + ap[2] * ab[2]) / den;
    for (i = 0; i < 3; i++)
        d[i] = ap[i] - ab[i] * t;
    if (n2 == 0.0 || cbf__norm(d) <= ldexp(1.0, -24) * big) {
        cbf__put(&out[0], s);
        cbf__put(&out[1], e);
        return 2;
    }
    uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    ww = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
    for (i = 0; i < 3; i++)
        a[i] = w[i] * uu - u[i] * ww;
    rel[0] = (a[1] * n[2] - a[2] * n[1]) / (2.0 * n2);
    rel[1] = (a[2] * n[0] - a[0] * n[2]) / (2.0 * n2);
    rel[2] = (a[0] * n[1] - a[1] * n[0]) / (2.0 * n2);
    for (i = 0; i < 3; i++) {
        center[i] = s[i] + rel[i];
        k[i] = n[i] / sqrt(n2); /* start -> mid -> end runs anticlockwise about k */
        a[i] = s[i] - center[i];
    }
    r = cbf__norm(a);
    for (i = 0; i < 3; i++) {
        e1[i] = a[i] / r;
        b[i] = e[i] - center[i];
    }
    e2[0] = k[1] * e1[2] - k[2] * e1[1];
    e2[1] = k[2] * e1[0] - k[0] * e1[2];
    e2[2] = k[0] * e1[1] - k[1] * e1[0];
    th = atan2(b[0] * e2[0] + b[1] * e2[1] + b[2] * e2[2], b[0] * e1[0] + b[1] * e1[1] + b[2] * e1[2]);
    if (th <= 0.0)
        th += CBF__TWO_PI;
    return cbf__path_turn(s, center, k, th, 0.0, out);
}

int cbf_layout_moves(int layout)
{
    return cbf__layout_ok(layout) && cbf__commands[cbf__layouts[layout].command].motion != CBF__MOTION_NONE;
}

size_t cbf_motion_path(int layout, const uint8_t *args, size_t nargs, const double *from,
                       double (*out)[3])
{
    double start[3], end[3], mid[3], center[3], k[3], th, length;
    unsigned nd = 0, nl = 0;
    int kind;
    long o_deg, o_len;
    if (!cbf__layout_ok(layout) || !args || !out || nargs < cbf__layouts[layout].size)
        return 0;
    kind = cbf__commands[cbf__layouts[layout].command].motion;
    switch (kind) {
    case CBF__MOTION_POINT:
        if (!cbf__vec_at(args, cbf__motion_end(layout, nargs), end))
            return 0;
        cbf__put(&out[0], from ? from : end);
        cbf__put(&out[1], end);
        return 2;
    case CBF__MOTION_LINE:
        if (!cbf__vec_at(args, cbf__motion_arg(layout, CBF__M_START, NULL), start)
            || !cbf__vec_at(args, cbf__motion_end(layout, nargs), end))
            return 0;
        if (cbf__layouts[layout].motion[CBF__M_THROUGH] >= 0) {
            if (!cbf__vec_at(args, cbf__motion_arg(layout, CBF__M_THROUGH, NULL), mid))
                return 0;
            return cbf__path_through(start, mid, end, out);
        }
        cbf__put(&out[0], start);
        cbf__put(&out[1], end);
        return 2;
    case CBF__MOTION_CIRCLE:
    case CBF__MOTION_HELIX:
        o_deg = cbf__motion_arg(layout, CBF__M_DEGREES, &nd);
        o_len = cbf__motion_arg(layout, CBF__M_LENGTH, &nl);
        if (!cbf__arc_of(kind, args, cbf__motion_arg(layout, CBF__M_START, NULL),
                         cbf__motion_arg(layout, CBF__M_CENTER, NULL), cbf__motion_arg(layout, CBF__M_NORMAL, NULL),
                         o_deg, nd, o_len, nl, start, center, k, &th, &length))
            return 0;
        return cbf__path_turn(start, center, k, th, length, out);
    default:
        return 0;
    }
}
