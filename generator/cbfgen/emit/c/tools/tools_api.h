/* ================================================================ the tools' engine: entry points
 * What cbf-c does, on bytes in memory: a host (the command line of cbf_tool.c, the conformance testee, a
 * WebAssembly page) gives a buffer and a sink and gets back what the tool prints and its exit status.
 * Nothing here opens a file but the *_file functions of the file layer. */

/** Exit statuses, as cbf's (README, "Exit codes"). */
enum cbf_tool_exit {
    CBF_TOOL_EXIT_OK = 0,       /**< no error-severity finding */
    CBF_TOOL_EXIT_FINDINGS = 1, /**< validate found an error-severity finding */
    CBF_TOOL_EXIT_USAGE = 2,    /**< bad usage, or input that is not a CBF file to read */
    CBF_TOOL_OUT_OF_MEMORY = -1 /**< the findings could not be held: one line said so; stop (exit 2) */
};

/** Where the tools' text goes: out gets the normal output, err one line at a time (each ends in a line
 * break); len bytes of text, not NUL-terminated. user is passed back. */
typedef void (*cbf_tool_write_fn)(void *user, const char *text, size_t len);
typedef struct cbf_tool_sink {
    cbf_tool_write_fn out;
    cbf_tool_write_fn err;
    void *user;
} cbf_tool_sink;

/** validate's options: the engine's (profile, part number, cutter table, machine), and the most findings
 * printed for a file (0: all). */
typedef struct cbf_tool_options {
    cbf_options validate;
    size_t max_findings;
} cbf_tool_options;

/** The most bytes a CBF file can hold: the header and every record at its largest. */
#define CBF_TOOL_MAX_FILE_SIZE ((size_t)CBF_HEADER_SIZE + ((size_t)CBF_LIMIT_MAX_COMMANDS + 1u) \
                                * ((size_t)CBF_RECORD_HEAD_SIZE + (size_t)CBF_LIMIT_MAX_ARG_SIZE))

/** How a name (a file name from the command line or a request) is spelled in every line the tools print:
 * the quoting rule (cbf_quote), in a buffer valid until the next call. */
const char *cbf_tool_name(const char *name);

/** 1 when buf[0..n) can be read as a CBF file; else 0 and one line on sink->err naming the file (name) and
 * what is wrong: larger than a CBF file can be, shorter than the header, every magic number wrong. */
int cbf_tool_frame_buffer(const char *name, const uint8_t *buf, size_t n, const cbf_tool_sink *sink);
/** cbf-c validate of one file: its findings in cbf's order and its summary line on sink->out; the status. */
int cbf_tool_validate_buffer(const char *name, const uint8_t *buf, size_t n, const cbf_tool_options *opt,
                             const cbf_tool_sink *sink);
/** cbf-c dump of one file: the header and each record, one line each, on sink->out; the status. */
int cbf_tool_dump_buffer(const char *name, const uint8_t *buf, size_t n, const cbf_tool_sink *sink);
/** cbf-c dump --path of one file: each motion record's drawn path (cbf_motion_path), one line a record,
 * INDEX x,y,z x,y,z ... (a point motion from where the motion before it ended); the status. */
int cbf_tool_path_buffer(const char *name, const uint8_t *buf, size_t n, const cbf_tool_sink *sink);

/** CUT text (the toolkit's text form, spec `cut`): 1 when buf[0..n) is to be read as CUT rather than as a
 * CBF file (no magic number of the header right, or shorter than the header, and its first 256 bytes text:
 * printable ASCII, TAB, CR, LF), else 0. The workbench page asks it of a dropped file. */
int cbf_tool_is_cut(const uint8_t *buf, size_t n);
/** The most CUT text the engine reads: 64 times the largest CBF file (cbf encode's bound). */
#define CBF_TOOL_MAX_CUT_SIZE (64u * CBF_TOOL_MAX_FILE_SIZE)
/** cbf-c encode of one CUT text: the CBF it encodes to (cbf_cut_encode_as: version, CBF_V__UNKNOWN for
 * the text's own or the default, under profile) in *out, a buffer of the heap the caller frees, and its
 * size; or -1, *out NULL, and one line on sink->err naming the file, the line (and column) and what is
 * wrong. */
long cbf_tool_cut_buffer(const char *name, const uint8_t *text, size_t n, int version, int profile, uint8_t **out,
                         const cbf_tool_sink *sink);
/** cbf encode's judgement of cbf[0..len), the CBF that CUT text[0..n) (the file name) encoded to under profile
 * (cbf_tool_cut_buffer): a writer makes files that validate, so the first finding in cbf's order that is an
 * error or of a string_ascii check refuses it: one line on sink->err naming the file, the CUT line of the
 * record concerned (else the finding's offset) and the check, as cbf's; CBF_TOOL_EXIT_USAGE. Else
 * CBF_TOOL_EXIT_OK and nothing printed. */
int cbf_tool_encode_judge(const char *name, const uint8_t *text, size_t n, const uint8_t *cbf, size_t len, int profile,
                          const cbf_tool_sink *sink);
/** cbf encode's warnings once cbf[0..len) is written to output (its name): one line on sink->err for each
 * record of a command or layout the file's version deprecates (the findings of the spec's checks of kind
 * deprecated, under the default profile, in cbf's order), at most ten, then one line counting the rest.
 * Nothing when the spec deprecates nothing. The exit status is not changed by them. */
void cbf_tool_encode_warnings(const char *output, const uint8_t *cbf, size_t len, const cbf_tool_sink *sink);

/** Option files (a cutter table, 6.1.2; a machine file): text[0..n) read by the rules cbf reads them by
 * (name: the file's name, whose extension says CSV, JSON or YAML). 1 and opt's cutters (or machine) set to
 * the engine's copy, valid until the next call; else 0 and cbf_tool_why() says why in one line. */
int cbf_tool_cutters_buffer(const char *name, const char *text, size_t n, cbf_options *opt);
int cbf_tool_machine_buffer(const char *name, const char *text, size_t n, cbf_options *opt);
/** The one line naming the file, the line (or JSON path) and the limit of the last refusal. */
const char *cbf_tool_why(void);

/* ---- the file layer (files.c) ---- */
/** Read a whole file into buf; its size, or -1 and *why (as cbf says it: "no such file", ...). A file of
  * more than cap bytes is -2 and "file too large" (from its size, unread, where it has one). */
long cbf_tool_read_file(const char *path, uint8_t *buf, size_t cap, const char **why);
/** As cbf_tool_read_file, into a buffer of the heap sized to the file, *out (the caller frees it); *why
 * "out of memory" when it cannot be had. */
long cbf_tool_read_file_alloc(const char *path, size_t cap, uint8_t **out, const char **why);
/** As cbf_tool_read_file_alloc, "-" being standard input (read to its end; cbf's rule for an input). */
long cbf_tool_read_input_alloc(const char *path, size_t cap, uint8_t **out, const char **why);
/** cbf_tool_cutters_buffer and cbf_tool_machine_buffer of a file read whole (at most its max_bytes). */
int cbf_tool_cutters_file(const char *path, cbf_options *opt);
int cbf_tool_machine_file(const char *path, cbf_options *opt);
/** Whether an output path can be written, before the work is done (cbf's _check_output): 1; or 0 and one
 * line in why[0..cap) naming the output and what is wrong (its folder does not exist, it is a directory,
 * a block device or a socket). "-" (standard output) can always be tried. */
int cbf_tool_check_output(const char *path, char *why, size_t cap);
/** data[0..n) written to path: to a regular file atomically (a temporary file beside the final target of
 * a symlink, written whole, synced, closed and renamed over the target; on any failure removed: the
 * target is as it was); into a character device or FIFO directly; "-": standard output, where what was
 * written to a regular file is cut off again on failure. 1; or 0 and one line in why[0..cap) naming the
 * output ("standard output" for "-") and the system's reason. Every write is checked: a full disk or
 * /dev/full is a failure, never a short file. */
int cbf_tool_write_file(const char *path, const uint8_t *data, size_t n, char *why, size_t cap);
