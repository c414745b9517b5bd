/* ---- the API's types: records, reader, writer, field descriptions, findings, options ---- */
/** One record, as cbf_next_record gives it. */
typedef struct cbf_record {
    size_t index;          /**< 0-based record index */
    size_t offset;         /**< file offset of the record */
    cbf_record_head head;  /**< the head fields as stored */
    const uint8_t *args;   /**< the argument bytes, inside the caller's buffer */
    size_t nargs;          /**< number of argument bytes (nb) */
    int command;           /**< enum cbf_command (the code), or CBF_CMD__UNKNOWN */
    int layout;            /**< enum cbf_layout used for `decoded`, or CBF_LAYOUT__NONE */
    cbf_args decoded;      /**< valid when layout != CBF_LAYOUT__NONE */
} cbf_record;

/** Record iterator over a caller's buffer (framing by nb from the header to EOF, D1). */
typedef struct cbf_reader {
    const uint8_t *buf;
    size_t len;
    size_t pos;            /**< offset of the next record */
    size_t index;          /**< index of the next record */
    cbf_header header;
    int eff_version;       /**< the version whose tables are used */
    size_t trailing;       /**< after the end: number of trailing bytes at pos */
} cbf_reader;

/** Describes a header field, record head field or argument (for generic consumers). */
typedef struct cbf_field_info {
    const char *name;
    const char *unit;      /**< NULL when none */
    unsigned char kind;    /**< enum cbf_field_kind */
    unsigned char role;    /**< private role number */
    unsigned char flags;   /**< CBF_FIELD_RESERVED | CBF_FIELD_TEXT | CBF_FIELD_MAGIC */
    unsigned char checksum;/**< private checksum tag, 0 when none */
    unsigned short offset; /**< byte offset in the header, record head or arguments */
    unsigned short elem;   /**< element size */
    unsigned short count;  /**< number of elements (3 for a vector) */
    size_t member;         /**< offsetof in the struct */
    uint32_t magic;        /**< the fixed value when flags has CBF_FIELD_MAGIC */
} cbf_field_info;
#define CBF_FIELD_RESERVED 1u
#define CBF_FIELD_TEXT 2u
#define CBF_FIELD_MAGIC 4u

/** Writer state for cbf_encode_*: the file is built in the caller's buffer. */
typedef struct cbf_writer {
    uint8_t *buf;
    size_t cap;
    size_t len;
    size_t records_end;    /**< end of the last record (before trailing bytes) */
    unsigned long count;   /**< records written */
    int version;           /**< enum cbf_version of the header, or CBF_V__UNKNOWN */
    int eff_version;
    int error;             /**< first error, sticky */
} cbf_writer;

/** Why cbf_cut_encode refused CUT text: the line (from 1; 0: the text as a whole), the column (from 1;
 * 0: the line alone is named) and what is wrong, one line of printable ASCII (a token of the text is
 * quoted and cut short; nothing of the text starts the line). */
typedef struct cbf_cut_error {
    unsigned long line;
    unsigned long column;
    char message[400];
} cbf_cut_error;

/** A finding of cbf_validate. */
typedef struct cbf_finding {
    const char *check;     /**< a CBF_CHECK_* id */
    int severity;          /**< enum cbf_severity */
    long record;           /**< 0-based record index, or -1 for the header and the file */
    size_t offset;         /**< file offset of the field concerned, as every binding names it
                                (conformance/PROTOCOL.md, Findings; the runner compares it) */
    const char *message;   /**< for people; valid during the callback only */
} cbf_finding;

typedef void (*cbf_finding_fn)(void *user, const cbf_finding *finding);

/** One entry of the robot's cutter table (6.1.2): its name and its numbers, value[CBF_CUTTER_<COLUMN>]
 * for each column of the table beside the name (the keys of the spec's cutter role: CBF_CUTTER_LENGTH,
 * CBF_CUTTER_RADIUS in rev 03). */
typedef struct cbf_cutter {
    const char *name;
    double value[CBF_CUTTER_VALUES];
} cbf_cutter;

typedef struct cbf_options {
    int profile;               /**< enum cbf_profile */
    const char *part_number;   /**< 6.1.1 input, or NULL */
    const cbf_cutter *cutters; /**< 6.1.2 input, or NULL (no table given) */
    size_t ncutters;
    const cbf_machine *machine; /**< machine_limits input (L1), or NULL: the default machine, warnings */
} cbf_options;
