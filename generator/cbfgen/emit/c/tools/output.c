/* ---- output: what the tools print goes through a sink (cbf_tool_sink), never to a FILE* of the engine ----
 * Text for the normal output is gathered in a buffer and handed to the sink's out in pieces (at the latest
 * when a call of the engine returns); a line for the error output is handed to err whole, after what the
 * normal output holds so far. */

/* How a name from the command line or a request (a file name) is spelled in every line the tools print:
 * the one place that decides it. The quoting rule (cbf_quote, the same as cbf's cbf.quoting): a plain name
 * as it is, any other between double quotes with escapes, so no name starts a line with "::" or carries a
 * line break. The text is valid until the next call (a name too long for it is cut, and says so). */
#define CBF_TOOL_NAME_BYTES 16384u /* the most a name takes as printed (longer is cut, and says so) */
const char *cbf_tool_name(const char *name)
{
    static char shown[CBF_TOOL_NAME_BYTES];
    if (cbf_quote(shown, sizeof shown, name, strlen(name), CBF_QUOTE_NAME) >= sizeof shown)
        (void)memcpy(shown + sizeof shown - 9u, "...(cut)", 8u);
    return shown;
}

typedef struct tool_out {
    const cbf_tool_sink *sink;
    size_t n;
    char buf[1u << 16];
} tool_out;

static tool_out tout;

static void out_flush(void)
{
    if (tout.n && tout.sink && tout.sink->out)
        tout.sink->out(tout.sink->user, tout.buf, tout.n);
    tout.n = 0;
}

static void out_begin(const cbf_tool_sink *sink)
{
    tout.sink = sink;
    tout.n = 0;
}

static void out_put(const char *s, size_t n)
{
    if (tout.n + n > sizeof tout.buf) {
        out_flush();
        if (n > sizeof tout.buf) {
            if (tout.sink && tout.sink->out)
                tout.sink->out(tout.sink->user, s, n);
            return;
        }
    }
    memcpy(tout.buf + tout.n, s, n);
    tout.n += n;
}

static void out_str(const char *s) { out_put(s, strlen(s)); }

static void out_char(char c)
{
    if (tout.n == sizeof tout.buf)
        out_flush();
    tout.buf[tout.n++] = c;
}

/* fmt formatted (into line when it fits, else into a buffer of its size), to the output or the error output. */
static void out_vformat(int to_err, const char *fmt, va_list ap) CBF__PRINTF(2, 0);
static void out_vformat(int to_err, const char *fmt, va_list ap)
{
    char line[1024], *text = line;
    va_list again;
    int len;
    va_copy(again, ap);
    len = vsnprintf(line, sizeof line, fmt, ap);
    if (len < 0) {
        va_end(again);
        return;
    }
    if ((size_t)len >= sizeof line) {
        text = (char *)malloc((size_t)len + 1u);
        if (text)
            (void)vsnprintf(text, (size_t)len + 1u, fmt, again);
    }
    va_end(again);
    if (!text)
        return;
    if (!to_err) {
        out_put(text, (size_t)len);
    } else {
        out_flush();
        if (tout.sink && tout.sink->err)
            tout.sink->err(tout.sink->user, text, (size_t)len);
    }
    if (text != line)
        free(text);
}

static void out_printf(const char *fmt, ...) CBF__PRINTF(1, 2);
static void out_printf(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    out_vformat(0, fmt, ap);
    va_end(ap);
}

static void err_printf(const char *fmt, ...) CBF__PRINTF(1, 2);
static void err_printf(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    out_vformat(1, fmt, ap);
    va_end(ap);
}
