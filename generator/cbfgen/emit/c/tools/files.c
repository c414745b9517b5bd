/* ---- the file layer: the only code of the tools that opens a file (cbf_tool.c's command line and the
 * testee read files through it; a page or any other host calls the *_buffer entry points instead) ---- */

/* The first byte of fp first (fopen opens a directory, whose size means nothing; reading it fails), then
 * its size where it can seek. 0: fp rewound; or, unseekable, that byte in buf[0] and *n = 1; or an empty
 * file, fp at its end. -1: fp closed and *why ("file too large" when its size is over cap). */
static int cbf_tool_size_first(FILE *fp, uint8_t *buf, size_t cap, size_t *n, const char **why)
{
    int first = fgetc(fp);
    long end;
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

/* Read a whole file into buf; returns its size, -2 ("file too large": over cap, from its size before
 * reading where it has one) or -1 (what went wrong in *why, as cbf says it). */
long cbf_tool_read_file(const char *path, uint8_t *buf, size_t cap, const char **why)
{
    FILE *fp;
    size_t n = 0;
    errno = 0;
    *why = "cannot open";
    fp = cbf_tool_open(path, why);
    if (!fp)
        return -1;
    /* A file larger than cap is refused from its size, unread (-2); where the size cannot be known
     * that way (a pipe), after cap bytes (issue 36). */
    if (cbf_tool_size_first(fp, buf, cap, &n, why) < 0)
        return strcmp(*why, "file too large") == 0 ? -2 : -1;
    if (n == 0 && feof(fp)) {
        fclose(fp);
        return 0;
    }
    for (;;) {
        size_t got;
        if (n == cap) {
            int c = fgetc(fp);
            fclose(fp);
            *why = "file too large";
            return c == EOF ? (long)n : -2;
        }
        got = fread(buf + n, 1, cap - n, fp);
        n += got;
        if (got == 0)
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

/* An option file read whole into opt_file_buf (at most max bytes), or 0 with the one line in opt_why. */
static char opt_file_buf[(OPT_CUTTER_MAX_BYTES > OPT_MACHINE_MAX_BYTES ? OPT_CUTTER_MAX_BYTES : OPT_MACHINE_MAX_BYTES)
                         + 1u];

static int opt_file(const char *path, size_t max, const char *what, size_t *n)
{
    const char *why;
    long got = cbf_tool_read_file(path, (uint8_t *)opt_file_buf, max, &why);
    if (got < 0) {
        if (strcmp(why, "file too large") == 0)
            (void)opt_too_large(cbf_tool_name(path), max, what);
        else
            (void)opt_fail("%s: cannot read %s (%s)", cbf_tool_name(path), what, why);
        return 0;
    }
    *n = (size_t)got;
    return 1;
}

int cbf_tool_cutters_file(const char *path, cbf_options *opt)
{
    size_t n;
    opt_last_why = opt_why;
    return opt_file(path, OPT_CUTTER_MAX_BYTES, opt_cutter_what, &n) && cbf_tool_cutters_buffer(path, opt_file_buf, n, opt);
}

int cbf_tool_machine_file(const char *path, cbf_options *opt)
{
    size_t n;
    if (!opt_file(path, OPT_MACHINE_MAX_BYTES, opt_machine_what, &n)) {
        (void)snprintf(machine_why, sizeof machine_why, "%s", opt_why);
        opt_last_why = machine_why;
        return 0;
    }
    return cbf_tool_machine_buffer(path, opt_file_buf, n, opt);
}
