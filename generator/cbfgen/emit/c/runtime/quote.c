/* ---- the one quoting rule for names and values from input (issue #35) ----
 * What `cbf` applies (cbf.quoting), byte for byte, so both tools print the same line:
 * CBF_QUOTE_NAME prints a name as it is when it is plain (not empty; every character printable
 * ASCII other than '"' and '\\', or valid UTF-8 from U+00A0 up that neither breaks a line, turns
 * text around nor hides: not U+2028/U+2029, U+200B..U+200F, U+202A..U+202E, U+2060..U+206F,
 * U+FEFF, U+FFF9..U+FFFB, U+FFFE/U+FFFF; not starting with ':' or a space, not ending in a space),
 * else between double quotes with '"' and '\\' escaped, \n \r \t, a byte that is not UTF-8 (or
 * another ASCII control) as \xHH, any other character that is not plain as \u{H...}.
 * CBF_QUOTE_TEXT is the net under a line of text: every character that is not plain and not a
 * space, '"' or '\\' is escaped the same way; nothing is added around it.
 * So a name never starts a line with "::" (a GitHub workflow command), never carries a line
 * break or a terminal escape, and its exact bytes can be read back. */
static int cbf__hidden(uint32_t c)
{
    return (c >= 0x2028u && c <= 0x2029u) || (c >= 0x200Bu && c <= 0x200Fu) || (c >= 0x202Au && c <= 0x202Eu)
           || (c >= 0x2060u && c <= 0x206Fu) || c == 0xFEFFu || (c >= 0xFFF9u && c <= 0xFFFBu) || c == 0xFFFEu
           || c == 0xFFFFu;
}

/* The UTF-8 character at s (n bytes left): its length and *cp, or 0 when the byte starts none. */
static size_t cbf__utf8(const unsigned char *s, size_t n, uint32_t *cp)
{
    size_t len, i;
    uint32_t c = s[0], min;
    if (c < 0x80u) {
        *cp = c;
        return 1;
    }
    if (c >= 0xC2u && c <= 0xDFu) {
        len = 2;
        c &= 0x1Fu;
        min = 0x80u;
    } else if (c >= 0xE0u && c <= 0xEFu) {
        len = 3;
        c &= 0x0Fu;
        min = 0x800u;
    } else if (c >= 0xF0u && c <= 0xF4u) {
        len = 4;
        c &= 0x07u;
        min = 0x10000u;
    } else {
        return 0;
    }
    if (n < len)
        return 0;
    for (i = 1; i < len; i++) {
        if ((s[i] & 0xC0u) != 0x80u)
            return 0;
        c = (c << 6) | (s[i] & 0x3Fu);
    }
    if (c < min || c > 0x10FFFFu || (c >= 0xD800u && c <= 0xDFFFu))
        return 0;
    *cp = c;
    return len;
}

size_t cbf_utf8_prefix(const uint8_t *s, size_t n)
{
    size_t i = 0, len;
    uint32_t c;
    while (i < n) {
        if (!(len = cbf__utf8(s + i, n - i, &c)))
            return i;
        i += len;
    }
    return n;
}

static int cbf__plain(uint32_t c)
{
    if (c < 0x80u)
        return c >= 0x20u && c < 0x7Fu && c != '"' && c != '\\';
    return c >= 0xA0u && !cbf__hidden(c);
}

static void cbf__qput(char *out, size_t cap, size_t *at, const char *text, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++, (*at)++)
        if (*at + 1u < cap)
            out[*at] = text[i];
}

/* The escape of one character that is not printed as it is (len 0: a byte that starts no UTF-8 character). */
static void cbf__qescape(char esc[16], unsigned char byte, size_t len, uint32_t c)
{
    if (!len) {
        (void)snprintf(esc, 16, "\\x%02X", byte);
    } else if (c == '"' || c == '\\') {
        esc[0] = '\\';
        esc[1] = (char)c;
        esc[2] = '\0';
    } else if (c == '\n' || c == '\r' || c == '\t') {
        (void)snprintf(esc, 16, "\\%c", c == '\n' ? 'n' : c == '\r' ? 'r' : 't');
    } else if (c < 0x80u) {
        (void)snprintf(esc, 16, "\\x%02X", (unsigned)c);
    } else {
        (void)snprintf(esc, 16, "\\u{%lX}", (unsigned long)c);
    }
}

size_t cbf_quote(char *out, size_t cap, const char *s, size_t n, int mode)
{
    const unsigned char *u = (const unsigned char *)s;
    size_t at = 0, i, len;
    uint32_t c = 0;
    int plain = n > 0 && u[0] != ':' && u[0] != ' ' && u[n - 1u] != ' ';
    for (i = 0; plain && i < n; i += len) {
        len = cbf__utf8(u + i, n - i, &c);
        plain = len > 0 && cbf__plain(c);
    }
    if (mode == CBF_QUOTE_NAME && plain) {
        cbf__qput(out, cap, &at, s, n);
    } else {
        if (mode == CBF_QUOTE_NAME)
            cbf__qput(out, cap, &at, "\"", 1);
        for (i = 0; i < n; i += len) {
            char esc[16];
            len = cbf__utf8(u + i, n - i, &c);
            if (len && (cbf__plain(c) || (mode == CBF_QUOTE_TEXT && (c == '"' || c == '\\')))) {
                cbf__qput(out, cap, &at, s + i, len);
                continue;
            }
            cbf__qescape(esc, u[i], len, c);
            if (!len)
                len = 1;
            cbf__qput(out, cap, &at, esc, strlen(esc));
        }
        if (mode == CBF_QUOTE_NAME)
            cbf__qput(out, cap, &at, "\"", 1);
    }
    if (cap)
        out[at < cap ? at : cap - 1u] = '\0';
    return at;
}

const char *cbf_quoted(const char *s, int mode)
{
    /* a ring of buffers: a message may quote several names at once */
    static char ring[4][16384];
    static unsigned next;
    char *buf = ring[next++ % 4u];
    size_t need = cbf_quote(buf, sizeof ring[0], s, strlen(s), mode);
    if (need >= sizeof ring[0]) /* longer than a message holds: cut, and say so */
        (void)memcpy(buf + sizeof ring[0] - 9u, "...(cut)", 8u);
    return buf;
}
