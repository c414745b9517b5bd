/* ---- repeated argument groups (issue 25, point 3): nb = size + group_item * n ----------- */
/* The group's own paths stay out of line: a file of fixed layouts decodes as fast as before. */
#if defined(__GNUC__) || defined(__clang__)
#define CBF__GROUP_PATH __attribute__((noinline, cold))
#else
#define CBF__GROUP_PATH
#endif

/* n for nb argument bytes of layout L: how many items of its group a record of nb bytes holds,
 * -1 when no n in group_min..group_max tiles nb (a layout without a group: 0 for its size, else -1). */
static inline long cbf__group_n(const cbf__layout *L, size_t nb)
{
    size_t n;
    if (L->group < 0)
        return nb == L->size ? 0 : -1;
    if (nb < L->size || (nb - L->size) % L->group_item != 0u)
        return -1;
    n = (nb - L->size) / L->group_item;
    return (n >= L->group_min && n <= L->group_max) ? (long)n : -1;
}

/* Whether layout L decodes nb argument bytes (its size; with a group, one of its sizes). */
static inline int cbf__layout_takes(const cbf__layout *L, size_t nb)
{
    if (!CBF__HAS_GROUPS || L->group < 0)
        return nb == L->size; /* the common case first: a fixed layout */
    return cbf__group_n(L, nb) >= 0;
}

/* The smallest nb layout L takes above `above` (-1: its smallest), or -1 when it takes none. */
static long cbf__layout_next_size(const cbf__layout *L, long above)
{
    size_t n;
    if (L->group < 0)
        return (long)L->size > above ? (long)L->size : -1;
    n = L->group_min;
    if ((long)(L->size + L->group_item * n) <= above)
        n = ((size_t)above - L->size) / L->group_item + 1u;
    return n <= L->group_max ? (long)(L->size + L->group_item * n) : -1;
}

/* The group's items of a record (n of them, after the fixed arguments) into the decoded struct,
 * one item a time through the item's field row, and n beside them. */
CBF__GROUP_PATH static void cbf__load_group(const cbf__layout *L, const uint8_t *args, size_t n, cbf_args *out)
{
    cbf_field_info item = cbf__args[L->first_arg + (size_t)L->group];
    size_t i;
    for (i = 0; i < n; i++) {
        cbf__load(&item, 1, args, (unsigned char *)out + L->member);
        item.offset = (unsigned short)(item.offset + L->group_item);
        item.member += L->group_item; /* an item's C elements are as wide as its stored ones */
    }
    memcpy((unsigned char *)out + L->group_n, &n, sizeof n);
}

/* How many items of its group a decoded struct holds (0 for a layout without a group). */
static size_t cbf__group_items(const cbf__layout *L, const cbf_args *in)
{
    size_t n = 0;
    if (L->group >= 0)
        memcpy(&n, (const unsigned char *)in + L->group_n, sizeof n);
    return n;
}

/* The group's n items of a decoded struct into argument bytes, after the fixed arguments. */
CBF__GROUP_PATH static void cbf__store_group(const cbf__layout *L, const cbf_args *in, size_t n, uint8_t *out)
{
    cbf_field_info item = cbf__args[L->first_arg + (size_t)L->group];
    size_t i;
    for (i = 0; i < n; i++) {
        cbf__store(&item, 1, (const unsigned char *)in + L->member, out);
        item.offset = (unsigned short)(item.offset + L->group_item);
        item.member += L->group_item;
    }
}

int cbf_layout_group(int layout, size_t *min, size_t *max, size_t *item)
{
    const cbf__layout *L;
    if (layout < 0 || layout >= CBF_LAYOUT__COUNT || cbf__layouts[layout].group < 0)
        return -1;
    L = &cbf__layouts[layout];
    if (min)
        *min = L->group_min;
    if (max)
        *max = L->group_max;
    if (item)
        *item = L->group_item;
    return L->group;
}

long cbf_layout_nb(int layout, size_t n)
{
    const cbf__layout *L;
    if (layout < 0 || layout >= CBF_LAYOUT__COUNT)
        return CBF_ERR_ARGUMENT;
    L = &cbf__layouts[layout];
    if (L->group < 0) {
        if (n != 0u)
            return CBF_ERR_RANGE;
        return (long)L->size;
    }
    if (n < L->group_min || n > L->group_max)
        return CBF_ERR_RANGE;
    return (long)(L->size + L->group_item * n);
}

long cbf_layout_items(int layout, size_t nb)
{
    if (layout < 0 || layout >= CBF_LAYOUT__COUNT)
        return CBF_ERR_ARGUMENT;
    return cbf__group_n(&cbf__layouts[layout], nb);
}
