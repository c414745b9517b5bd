/* ---- the file layer: the only code of the tools that opens a file (cbf_tool.c's command line and the
 * testee read files through it; a page or any other host calls the *_buffer entry points instead) ---- */

/* The first byte of fp first (fopen opens a directory, whose size means nothing; reading it fails), then
 * its size where it can seek (*size; 0 where it cannot, or says 0). 0: fp rewound; or, unseekable, that
 * byte in buf[0] and *n = 1; or an empty file, fp at its end. -1: fp closed and *why ("file too large"
 * when its size is over cap). */
static int cbf_tool_size_first(FILE *fp, uint8_t *buf, size_t cap, size_t *n, size_t *size, const char **why)
{
    int first = fgetc(fp);
    long end;
    *size = 0;
    if (first == EOF) {
        int bad = ferror(fp), err = errno;
        if (!bad)
            return 0;
        fclose(fp);
        *why = err == EISDIR ? "is a directory" : "read error";
        return -1;
    }
    if (fseek(fp, 0L, SEEK_END) != 0) { /* not seekable: the byte read is the first of the input */
        clearerr(fp);
        if (cap == 0) {
            fclose(fp);
            *why = "file too large";
            return -1;
        }
        buf[0] = (uint8_t)first;
        *n = 1;
        return 0;
    }
    end = ftell(fp);
    if (end > 0 && (unsigned long)end > (unsigned long)cap) {
        fclose(fp);
        *why = "file too large";
        return -1;
    }
    if (fseek(fp, 0L, SEEK_SET) != 0) {
        fclose(fp);
        *why = "read error";
        return -1;
    }
    *size = end > 0 ? (size_t)end : 0u;
    return 0;
}

/* Why a file could not be opened, as cbf says it. */
static const char *cbf_tool_open_error(int err)
{
    return err == ENOENT ? "no such file" : err == EACCES ? "permission denied" : err == EISDIR ? "is a directory"
         : "cannot open";
}

#ifdef CBF_TOOLS_POSIX
/* What a file that is not a regular one is, as cbf says it (cbf.files.kind_of). */
static const char *cbf_tool_not_regular(mode_t mode)
{
    return S_ISDIR(mode) ? "is a directory" : S_ISFIFO(mode) ? "is a FIFO; only regular files are read"
         : S_ISCHR(mode) ? "is a character device; only regular files are read"
         : S_ISBLK(mode) ? "is a block device; only regular files are read"
         : S_ISSOCK(mode) ? "is a socket; only regular files are read"
         : "is not a regular file; only regular files are read";
}

/* Only a regular file is opened (issue #35): its status is looked at first, it is opened without blocking
 * (a FIFO named like a CBF file cannot hang the tool, a device is never read) and looked at again. */
static FILE *cbf_tool_open(const char *path, const char **why)
{
    struct stat st;
    int fd;
    FILE *fp;
    if (stat(path, &st) != 0) {
        *why = cbf_tool_open_error(errno);
        return NULL;
    }
    if (!S_ISREG(st.st_mode)) {
        *why = cbf_tool_not_regular(st.st_mode);
        return NULL;
    }
    fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY);
    if (fd < 0) {
        *why = cbf_tool_open_error(errno);
        return NULL;
    }
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) { /* the file opened is the file looked at */
        *why = cbf_tool_not_regular(st.st_mode);
        (void)close(fd);
        return NULL;
    }
    fp = fdopen(fd, "rb");
    if (!fp)
        (void)close(fd);
    return fp;
}
#else
/* Without POSIX (a host that defines no _POSIX_C_SOURCE): fopen, which cannot tell a FIFO apart. */
static FILE *cbf_tool_open(const char *path, const char **why)
{
    FILE *fp = fopen(path, "rb");
    if (!fp)
        *why = cbf_tool_open_error(errno);
    return fp;
}
#endif

/* The rest of fp into *bufp (room bytes; n read so far), at most cap bytes in all; fp closed. When grow,
 * *bufp is the heap's and grows (by doubling, to cap; room + 1 bytes allocated) when the file holds more
 * than room (a pipe, or a file longer than its size said); else room is cap. Its size, -2 ("file too
 * large") or -1 (*why: "read error", "is a directory", "out of memory"). */
static long cbf_tool_read_rest(FILE *fp, uint8_t **bufp, size_t room, size_t n, size_t cap, int grow,
                               const char **why)
{
    for (;;) {
        size_t got;
        if (n == room) { /* full: one more byte says whether the file ends here */
            int c = fgetc(fp);
            uint8_t *grown;
            if (c == EOF)
                break;
            if (!grow || room >= cap) {
                fclose(fp);
                *why = "file too large";
                return -2;
            }
            room = room >= cap / 2u ? cap : 2u * room + 1u;
            grown = (uint8_t *)realloc(*bufp, room + 1u);
            if (!grown) {
                fclose(fp);
                *why = "out of memory";
                return -1;
            }
            *bufp = grown;
            (*bufp)[n++] = (uint8_t)c;
        }
        got = fread(*bufp + n, 1, room - n, fp);
        n += got;
        if (got == 0 && n < room) /* the end, or an error; full: the test above */
            break;
    }
    if (ferror(fp)) {
        *why = errno == EISDIR ? "is a directory" : "read error"; /* fopen opens a directory; reading fails */
        fclose(fp);
        return -1;
    }
    fclose(fp);
    return (long)n;
}

/* Read a whole file into buf; returns its size, -2 ("file too large": over cap, from its size before
 * reading where it has one) or -1 (what went wrong in *why, as cbf says it). */
long cbf_tool_read_file(const char *path, uint8_t *buf, size_t cap, const char **why)
{
    FILE *fp;
    size_t n = 0, size;
    errno = 0;
    *why = "cannot open";
    fp = cbf_tool_open(path, why);
    if (!fp)
        return -1;
    /* A file larger than cap is refused from its size, unread (-2); where the size cannot be known
     * that way (a pipe), after cap bytes (issue 36). */
    if (cbf_tool_size_first(fp, buf, cap, &n, &size, why) < 0)
        return strcmp(*why, "file too large") == 0 ? -2 : -1;
    if (n == 0 && feof(fp)) {
        fclose(fp);
        return 0;
    }
    return cbf_tool_read_rest(fp, &buf, cap, n, cap, 0, why);
}

/* As cbf_tool_read_file, into a buffer of the heap sized to the file (its size + 1 where it has one;
 * grown to at most cap + 1 where it does not), *out; the caller frees it. Nothing in *out on failure. A
 * tool that held a buffer of cap bytes for every file made the WebAssembly module's initial memory
 * 24 MB, paid by every instance (bench/NOTES.md, round 5). */
long cbf_tool_read_file_alloc(const char *path, size_t cap, uint8_t **out, const char **why)
{
    FILE *fp;
    uint8_t first[1];
    size_t n = 0, size, room;
    long got;
    uint8_t *buf;
    *out = NULL;
    errno = 0;
    *why = "cannot open";
    fp = cbf_tool_open(path, why);
    if (!fp)
        return -1;
    if (cbf_tool_size_first(fp, first, cap, &n, &size, why) < 0)
        return strcmp(*why, "file too large") == 0 ? -2 : -1;
    room = size ? size : cap < 4096u ? cap : 4096u;
    buf = (uint8_t *)malloc(room + 1u);
    if (!buf) {
        fclose(fp);
        *why = "out of memory";
        return -1;
    }
    if (n)
        buf[0] = first[0];
    if (n == 0 && feof(fp)) {
        fclose(fp);
        *out = buf;
        return 0;
    }
    got = cbf_tool_read_rest(fp, &buf, room, n, cap, 1, why);
    if (got < 0)
        free(buf);
    else
        *out = buf;
    return got;
}

/* An option file read whole into *text (the heap's; at most max bytes), or 0 with the one line in opt_why. */
static int opt_file(const char *path, size_t max, const char *what, char **text, size_t *n)
{
    const char *why;
    uint8_t *buf;
    long got = cbf_tool_read_file_alloc(path, max, &buf, &why);
    if (got < 0) {
        if (strcmp(why, "file too large") == 0)
            (void)opt_too_large(cbf_tool_name(path), max, what);
        else
            (void)opt_fail("%s: cannot read %s (%s)", cbf_tool_name(path), what, why);
        return 0;
    }
    *text = (char *)buf;
    *n = (size_t)got;
    return 1;
}

int cbf_tool_cutters_file(const char *path, cbf_options *opt)
{
    size_t n;
    char *text;
    int ok;
    opt_last_why = opt_why;
    if (!opt_file(path, OPT_CUTTER_MAX_BYTES, opt_cutter_what, &text, &n))
        return 0;
    ok = cbf_tool_cutters_buffer(path, text, n, opt);
    free(text);
    return ok;
}

int cbf_tool_machine_file(const char *path, cbf_options *opt)
{
    size_t n;
    char *text;
    int ok;
    if (!opt_file(path, OPT_MACHINE_MAX_BYTES, opt_machine_what, &text, &n)) {
        (void)snprintf(machine_why, sizeof machine_why, "%s", opt_why);
        opt_last_why = machine_why;
        return 0;
    }
    ok = cbf_tool_machine_buffer(path, text, n, opt);
    free(text);
    return ok;
}
