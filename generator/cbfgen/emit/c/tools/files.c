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
static long cbf_tool_read_fp_alloc(FILE *fp, size_t cap, uint8_t **out, const char **why)
{
    uint8_t first[1];
    size_t n = 0, size, room;
    long got;
    uint8_t *buf;
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

long cbf_tool_read_file_alloc(const char *path, size_t cap, uint8_t **out, const char **why)
{
    FILE *fp;
    *out = NULL;
    errno = 0;
    *why = "cannot open";
    fp = cbf_tool_open(path, why);
    return fp ? cbf_tool_read_fp_alloc(fp, cap, out, why) : -1;
}

long cbf_tool_read_input_alloc(const char *path, size_t cap, uint8_t **out, const char **why)
{
    if (strcmp(path, "-") != 0)
        return cbf_tool_read_file_alloc(path, cap, out, why);
    *out = NULL;
    errno = 0;
    return cbf_tool_read_fp_alloc(stdin, cap, out, why);
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

/* ---- the output: the one writer of the tools (cbf-c encode -o), as cbf writes (cli.py, _write) ---- */

/* why[0..cap) = "NAME: what" (NAME by the quoting rule). */
static int cbf_tool_out_fail(char *why, size_t cap, const char *path, const char *what, const char *detail)
{
    (void)snprintf(why, cap, "%s: %s%s%s%s", strcmp(path, "-") == 0 ? "standard output" : cbf_tool_name(path), what,
                   detail ? " (" : "", detail ? detail : "", detail ? ")" : "");
    return 0;
}

/* POSIX (not WASI, which has no mkstemp, no modes and no temporary names of its own): the atomic writer. */
#if defined(CBF_TOOLS_POSIX) && !defined(__wasi__)
/* Every byte of data[0..n) to fd: a short write goes on from where it stopped, a write that takes nothing
 * is a full disk (never a short output). 0, or -1 with errno. */
static int cbf_tool_write_all(int fd, const uint8_t *data, size_t n)
{
    while (n) {
        ssize_t w = write(fd, data, n > (1u << 20) ? (size_t)(1u << 20) : n);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0) {
            if (w == 0)
                errno = ENOSPC;
            return -1;
        }
        data += w;
        n -= (size_t)w;
    }
    return 0;
}

/* A copy of s of the heap (NULL without memory). */
static char *cbf_tool_dup(const char *s, size_t n)
{
    char *d = (char *)malloc(n + 1u);
    if (d) {
        (void)memcpy(d, s, n);
        d[n] = '\0';
    }
    return d;
}

/* path with a symlink at its end followed to its final target (readlink, at most 40 links; a relative link
 * read from the link's folder): the temporary file goes beside that target, and the link stays a link. Of
 * the heap; NULL without memory. */
static char *cbf_tool_follow(const char *path)
{
    char *cur = cbf_tool_dup(path, strlen(path));
    int hops;
    for (hops = 0; cur && hops < 40; hops++) {
        struct stat st;
        const char *slash;
        char *link, *next;
        size_t cap, dn;
        ssize_t k;
        if (lstat(cur, &st) != 0 || !S_ISLNK(st.st_mode))
            break;
        cap = st.st_size > 0 ? (size_t)st.st_size + 1u : 4096u;
        link = (char *)malloc(cap);
        k = link ? readlink(cur, link, cap) : -1;
        if (k < 0 || (size_t)k >= cap) {
            free(link);
            break;
        }
        slash = strrchr(cur, '/');
        dn = link[0] == '/' || !slash ? 0u : (size_t)(slash - cur) + 1u;
        next = (char *)malloc(dn + (size_t)k + 1u);
        if (next) {
            (void)memcpy(next, cur, dn);
            (void)memcpy(next + dn, link, (size_t)k);
            next[dn + (size_t)k] = '\0';
        }
        free(link);
        free(cur);
        cur = next;
    }
    return cur;
}

/* Where "-o path" writes: the final target of a symlink (*target of the heap), its folder (*dir of the
 * heap; "." for none) and its name (*base, in *target). 0, or -1 when memory runs out. */
static int cbf_tool_out_where(const char *path, char **target, char **dir, const char **base)
{
    const char *slash;
    *dir = NULL;
    *target = cbf_tool_follow(path);
    if (!*target)
        return -1;
    slash = strrchr(*target, '/');
    *base = slash ? slash + 1 : *target;
    *dir = !slash ? cbf_tool_dup(".", 1u) : cbf_tool_dup(*target, slash == *target ? 1u : (size_t)(slash - *target));
    return *dir ? 0 : -1;
}

/* What a target of "-o" that is not a regular file, a character device or a FIFO is. */
static const char *cbf_tool_unwritable_kind(mode_t mode)
{
    return S_ISDIR(mode) ? NULL : S_ISREG(mode) || S_ISCHR(mode) || S_ISFIFO(mode) ? ""
         : S_ISBLK(mode) ? "a block device" : S_ISSOCK(mode) ? "a socket" : "not a regular file";
}

/* cbf_tool_check_output, and the target's status when it exists (*exists). */
static int cbf_tool_check_target(const char *path, const char *target, const char *dir, struct stat *st, int *exists,
                                 char *why, size_t cap)
{
    struct stat ds;
    char what[96];
    const char *kind;
    *exists = 0;
    if (stat(target, st) != 0) {
        if (errno != ENOENT)
            return cbf_tool_out_fail(why, cap, path, "cannot write", strerror(errno));
        if (stat(dir, &ds) != 0 || !S_ISDIR(ds.st_mode)) { /* the folder from the root, as cbf names it */
            char cwd[4096];
            int rel = dir[0] != '/' && getcwd(cwd, sizeof cwd) != NULL;
            size_t dn = strlen(dir), cn = rel ? strlen(cwd) : 0u;
            char *full = (char *)malloc(cn + dn + 2u);
            if (full && rel && strcmp(dir, ".") == 0)
                (void)memcpy(full, cwd, cn + 1u);
            else if (full)
                (void)sprintf(full, "%s%s%s", rel ? cwd : "", rel && cn > 1u ? "/" : "", dir);
            (void)snprintf(why, cap, "%s: folder %s does not exist", cbf_tool_name(path),
                           cbf_quoted(full ? full : dir, CBF_QUOTE_NAME));
            free(full);
            return 0;
        }
        return 1;
    }
    *exists = 1;
    kind = cbf_tool_unwritable_kind(st->st_mode);
    if (!kind)
        return cbf_tool_out_fail(why, cap, path, "is a directory", NULL);
    if (*kind) {
        (void)snprintf(what, sizeof what, "is %s; cbf-c writes regular files, character devices and FIFOs only", kind);
        return cbf_tool_out_fail(why, cap, path, what, NULL);
    }
    return 1;
}

int cbf_tool_check_output(const char *path, char *why, size_t cap)
{
    char *target, *dir;
    const char *base;
    struct stat st;
    int exists, ok;
    if (strcmp(path, "-") == 0)
        return 1;
    if (cbf_tool_out_where(path, &target, &dir, &base) != 0)
        ok = cbf_tool_out_fail(why, cap, path, "cannot write", "out of memory");
    else
        ok = cbf_tool_check_target(path, target, dir, &st, &exists, why, cap);
    free(target);
    free(dir);
    return ok;
}

/* Standard output: every byte written (a stdio buffer flushed first); what went to a regular file there is
 * cut off again when it fails: nothing that looks complete stays. */
static int cbf_tool_write_stdout(const uint8_t *data, size_t n, char *why, size_t cap)
{
    struct stat st;
    off_t start = -1;
    int err;
    if (fflush(stdout) != 0)
        return cbf_tool_out_fail(why, cap, "-", "cannot write", strerror(errno));
    if (fstat(1, &st) == 0 && S_ISREG(st.st_mode))
        start = lseek(1, 0, SEEK_CUR);
    if (cbf_tool_write_all(1, data, n) == 0)
        return 1;
    err = errno;
    if (start >= 0 && ftruncate(1, start) != 0)
        start = -1; /* cut off as far as it could be: the failure said is the write's */
    return cbf_tool_out_fail(why, cap, "-", "cannot write", strerror(err));
}

/* The most bytes a file name in dir may have (NAME_MAX there; 255 where it cannot be asked). */
static size_t cbf_tool_name_max(const char *dir)
{
    long m = pathconf(dir, _PC_NAME_MAX);
    return m > 0 ? (size_t)m : 255u;
}

int cbf_tool_write_file(const char *path, const uint8_t *data, size_t n, char *why, size_t cap)
{
    static const char suffix[] = ".XXXXXX"; /* mkstemp's */
    char *target = NULL, *dir = NULL, *tmp = NULL;
    const char *base;
    struct stat st;
    int exists, fd = -1, ok = 0, err = 0;
    size_t room, bn;
    if (strcmp(path, "-") == 0)
        return cbf_tool_write_stdout(data, n, why, cap);
    if (cbf_tool_out_where(path, &target, &dir, &base) != 0) {
        ok = cbf_tool_out_fail(why, cap, path, "cannot write", "out of memory");
        goto done;
    }
    if (!cbf_tool_check_target(path, target, dir, &st, &exists, why, cap))
        goto done;
    if (exists && !S_ISREG(st.st_mode)) { /* a character device or a FIFO, written straight, never replaced */
        fd = open(target, O_WRONLY | O_NOCTTY);
        if (fd < 0 || cbf_tool_write_all(fd, data, n) != 0)
            err = errno;
        if (fd >= 0 && close(fd) != 0 && !err)
            err = errno;
        ok = err ? cbf_tool_out_fail(why, cap, path, "cannot write", strerror(err)) : 1;
        goto done;
    }
    /* ".NAME.XXXXXX" beside the target, NAME cut so that it fits NAME_MAX whenever the target's name does */
    bn = strlen(base);
    room = cbf_tool_name_max(dir);
    room = room > sizeof suffix + 1u ? room - (sizeof suffix - 1u) - 2u : 1u;
    if (bn > room)
        bn = room;
    tmp = (char *)malloc(strlen(dir) + bn + sizeof suffix + 4u);
    if (!tmp) {
        ok = cbf_tool_out_fail(why, cap, path, "cannot write", "out of memory");
        goto done;
    }
    (void)sprintf(tmp, "%s/.%.*s.%s", dir, (int)bn, base, suffix + 1);
    fd = mkstemp(tmp);
    if (fd < 0) {
        ok = cbf_tool_out_fail(why, cap, path, "cannot write", strerror(errno));
        goto done;
    }
    { /* mkstemp makes 0600: an ordinary file's mode (0666 under the umask), as cbf gives it */
        mode_t mask = umask(0);
        (void)umask(mask);
        if (fchmod(fd, (mode_t)(0666u & ~(unsigned)mask)) != 0)
            err = errno;
    }
    if (!err && (cbf_tool_write_all(fd, data, n) != 0 || fsync(fd) != 0))
        err = errno;
    if (close(fd) != 0 && !err)
        err = errno;
    if (!err && rename(tmp, target) != 0)
        err = errno;
    if (err) {
        (void)unlink(tmp); /* nothing of a failed write stays, and the target is as it was */
        ok = cbf_tool_out_fail(why, cap, path, "cannot write", strerror(err));
    } else
        ok = 1;
done:
    free(tmp);
    free(target);
    free(dir);
    return ok;
}
#elif defined(__wasi__)
/* WASI (cbf-c.wasm, run by the workbench page and node's WASI): standard output only, written and flushed;
 * writing a file would need imports the page's WASI has not (rename, unlink), and the page reads -o -. */
int cbf_tool_check_output(const char *path, char *why, size_t cap)
{
    if (strcmp(path, "-") == 0)
        return 1;
    return cbf_tool_out_fail(why, cap, path, "cannot write", "cbf-c.wasm writes to standard output only: -o -");
}

int cbf_tool_write_file(const char *path, const uint8_t *data, size_t n, char *why, size_t cap)
{
    if (!cbf_tool_check_output(path, why, cap))
        return 0;
    if (fwrite(data, 1, n, stdout) != n || fflush(stdout) != 0)
        return cbf_tool_out_fail(why, cap, path, "cannot write", strerror(errno));
    return 1;
}
#else
/* Without POSIX: a file beside the target ("NAME.tmp"), written whole, closed, then renamed over it;
 * standard output written and flushed. */
int cbf_tool_check_output(const char *path, char *why, size_t cap)
{
    (void)path;
    (void)why;
    (void)cap;
    return 1;
}

int cbf_tool_write_file(const char *path, const uint8_t *data, size_t n, char *why, size_t cap)
{
    FILE *fp;
    char *tmp;
    int bad;
    if (strcmp(path, "-") == 0) {
        if (fwrite(data, 1, n, stdout) != n || fflush(stdout) != 0)
            return cbf_tool_out_fail(why, cap, path, "cannot write", strerror(errno));
        return 1;
    }
    tmp = (char *)malloc(strlen(path) + 5u);
    if (!tmp)
        return cbf_tool_out_fail(why, cap, path, "cannot write", "out of memory");
    (void)sprintf(tmp, "%s.tmp", path);
    fp = fopen(tmp, "wb");
    bad = !fp || fwrite(data, 1, n, fp) != n;
    if (fp && fclose(fp) != 0)
        bad = 1;
    if (!bad && rename(tmp, path) != 0)
        bad = 1;
    if (bad) {
        int err = errno;
        (void)remove(tmp);
        free(tmp);
        return cbf_tool_out_fail(why, cap, path, "cannot write", strerror(err));
    }
    free(tmp);
    return 1;
}
#endif
