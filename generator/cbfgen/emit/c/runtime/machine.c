/* ---- machine limits: the kernel of check kind machine_limits (decision L1) ----- */
/* A bound as the values it limits are stored: rounded to binary32, beyond its range infinite
 * (a value equal to a bound written in decimal is inside); the same rule in every binding. */
static double cbf__bound32(double b)
{
    if (b > 3.4028234663852886e38)
        return HUGE_VAL;
    if (b < -3.4028234663852886e38)
        return -HUGE_VAL;
    return (double)(float)b;
}

/* The limits a validation applies, each bound rounded to binary32 once. */
static void cbf__machine_start(cbf__vctx *v)
{
    unsigned k, i;
    v->machine = (v->opt && v->opt->machine) ? v->opt->machine : &cbf_machine_default;
    for (k = 0; k < CBF_MACHINE__COUNT; k++) {
        for (i = 0; i < CBF_MACHINE_MAX_AXES; i++) {
            v->mlo[k][i] = (float)cbf__bound32(v->machine->limit[k].min[i]); /* exact: binary32 or infinite */
            v->mhi[k][i] = (float)cbf__bound32(v->machine->limit[k].max[i]);
        }
    }
}

/* Rule j of cbf__mrules on an argument found outside its limit: one finding, naming the first
 * component out, unless a value is not finite (the finite check's) or the positive check
 * targets the argument and a value is <= 0 (that check's). item: which item of a repeated
 * group x is (named argument[item]), -1 for an argument. 1 when it found a breach. Off the
 * fast path: cold. */
CBF__COLD static int cbf__machine_breach_item(cbf__vctx *v, int cmd, int layout, unsigned j, const float *x,
                                              unsigned n, int finite, long rec, size_t off, long item)
{
    const cbf__mrule *r = &cbf__mrules[j];
    const float *lo = v->mlo[r->limit], *hi = v->mhi[r->limit];
    unsigned i, out = n;
    int le_zero = 0;
    for (i = 0; i < n && out == n; i++)
        if (x[i] < lo[i] || x[i] > hi[i])
            out = i;
    if (out == n)
        return 0; /* inside (a NaN compares false: the finite check's) */
    for (i = 0; i < n; i++)
        le_zero |= x[i] <= 0.0f;
    if (!finite || (r->positive && le_zero))
        return 0; /* the finite check's, or the positive check's */
    {
        const cbf_field_info *f = cbf__layout_arg(layout, r->arg);
        const cbf_machine_range *lim = &v->machine->limit[r->limit];
        const char *axis = cbf_machine_limit_axes[r->limit] ? cbf_machine_limit_axis_names[r->limit][out] : NULL;
        char msg[256], name[128];
        cbf_finding fd;
        if (cbf__checks[r->check].versions && !(cbf__checks[r->check].versions & CBF__VBIT(v->eff)))
            return 1; /* scoped to other versions (versions:) */
        if (item >= 0)
            (void)snprintf(name, sizeof name, "%s[%ld]", f ? f->name : "?", item);
        else
            (void)snprintf(name, sizeof name, "%s", f ? f->name : "?");
        (void)snprintf(msg, sizeof msg, "%s.%s%s%s is %.9g %s, outside the machine's %s %.9g..%.9g %s",
                       cbf__commands[cmd].name, name, axis ? " " : "", axis ? axis : "", (double)x[out],
                       cbf_machine_limit_units[r->limit], cbf_machine_limit_names[r->limit], lim->min[out],
                       lim->max[out], cbf_machine_limit_units[r->limit]);
        fd.check = cbf__checks[r->check].id;
        fd.severity = (v->opt && v->opt->machine) ? (r->given_error ? CBF_SEVERITY_ERROR : CBF_SEVERITY_WARNING)
                                                  : cbf__checks[r->check].severity;
        fd.record = rec;
        fd.offset = off;
        fd.message = msg;
        if (fd.severity == CBF_SEVERITY_ERROR)
            v->errors++;
        if (v->fn)
            v->fn(v->user, &fd);
    }
    return 1;
}

/* cbf__machine_breach_item for an argument (not an item of a group): the fast path's call. */
CBF__COLD static void cbf__machine_breach(cbf__vctx *v, int cmd, int layout, unsigned j, const float *x, unsigned n,
                                          int finite, long rec, size_t off)
{
    (void)cbf__machine_breach_item(v, cmd, layout, j, x, n, finite, rec, off, -1);
}

/* Rule j of cbf__mrules on its argument x (n floats, decoded once by the generated layout
 * function, finite: whether all are), called with j and n as constants: one branch-free
 * test of the box or range (CBF__MACHINE_OUT, written out per axis by machine.h.j2), the
 * exact finding only when a value is out. */
CBF__INLINE void cbf__machine_at(cbf__vctx *v, int cmd, int layout, unsigned j, const float *x, unsigned n, int finite,
                                 long rec, size_t off)
{
    const float *lo = v->mlo[cbf__mrules[j].limit], *hi = v->mhi[cbf__mrules[j].limit];
    int out = 0;
    CBF__MACHINE_OUT(out, x, lo, hi, n);
    if (out)
        cbf__machine_breach(v, cmd, layout, j, x, n, finite, rec, off);
}
