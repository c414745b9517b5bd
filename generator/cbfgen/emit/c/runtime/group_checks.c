/* ---- the record checks of a repeated argument group (issue 25, point 3) ---------------- */
/* Whether the m binary32 values at p are all finite (the finite check judges a group as one
 * argument: one finding a record, at the group's first byte, as every binding says it). */
static inline int cbf__group_finite(const uint8_t *p, size_t m)
{
    size_t i;
    int finite = 1;
    for (i = 0; i < m; i++)
        finite &= cbf__bits_finite(cbf__get_u(p + 4u * i, 4));
    return finite;
}

/* machine_limits rule j on a group of n items at g (count floats, item_size bytes each): each
 * item is judged as an argument of its own (cbf__machine_breach_item: not when a value is not finite
 * or a positive check's); one finding a record, at the first item out, named group[item]. */
static inline void cbf__machine_group(cbf__vctx *v, int cmd, int layout, unsigned j, const uint8_t *g, size_t n,
                                      unsigned count, size_t item_size, long rec, size_t off)
{
    const float *lo = v->mlo[cbf__mrules[j].limit], *hi = v->mhi[cbf__mrules[j].limit];
    size_t i;
    for (i = 0; i < n; i++) {
        float x[CBF_MACHINE_MAX_AXES];
        unsigned e;
        int finite = 1, out = 0;
        for (e = 0; e < CBF_MACHINE_MAX_AXES; e++)
            x[e] = 0.0f;
        for (e = 0; e < count && e < CBF_MACHINE_MAX_AXES; e++)
            finite &= cbf__float_at(g + item_size * i + 4u * e, &x[e]);
        CBF__MACHINE_OUT(out, x, lo, hi, count);
        if (out && cbf__machine_breach_item(v, cmd, layout, j, x, count, finite, rec, off + item_size * i, (long)i))
            return;
    }
}
