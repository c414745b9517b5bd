/* cbf_fuzz.c - libFuzzer harness of the C binding.
 *
 * GENERATED from spec/cbf.yaml by cbfgen (generator/cbfgen/emit/c). Do not edit.
 *
 * For every input: validate; decode; encode every stored value again and
 * require the same bytes; decode that and require the same records; encode
 * with the writer filling sequence numbers, code copies, the count, magic
 * numbers and checksums, and require that no check of those kinds fires.
 * Any mismatch traps; sanitizers report the rest.
 *
 *   clang -g -O1 -fsanitize=fuzzer,address,undefined cbf_fuzz.c -lm
 */
#define CBF_IMPLEMENTATION
#include "cbf.h"

#include <stdlib.h>
#include <string.h>

#define CBF_FUZZ_DEFAULT_PROFILE CBF_PROFILE_DEFAULT
/* The command code of a record head (the member of the code role). */
#define CBF_FUZZ_CODE(head) ((head).code)

/* Checks the filling writer guarantees to pass (by kind). */
static const char *const filled_checks[] = {
    CBF_CHECK_6_2_1,
    CBF_CHECK_6_2_2,
    CBF_CHECK_6_3_1,
    CBF_CHECK_6_3_2,
    CBF_CHECK_6_4_1,
    CBF_CHECK_6_4_2,
    CBF_CHECK_6_4_4,
    CBF_CHECK_RESERVED_NONZERO,
    NULL
};

/* ==== BEGIN tools/fuzz.c: verbatim from generator/cbfgen/emit/c/tools/fuzz.c, edit it there ==== */
#line 1 "generator/cbfgen/emit/c/tools/fuzz.c"
/* ---- the libFuzzer harness: round trips and the filling writer's promises, on every input ---- */
#define CHECK(cond) do { if (!(cond)) __builtin_trap(); } while (0)

static uint8_t out[1u << 20];
static uint8_t out2[1u << 20];

static long findings;
static int filled_failed;

static void count_finding(void *user, const cbf_finding *f)
{
    size_t i;
    (void)user;
    CHECK(f->check != NULL && f->message != NULL);
    CHECK(f->severity == CBF_SEVERITY_ERROR || f->severity == CBF_SEVERITY_WARNING);
    findings++;
    for (i = 0; filled_checks[i]; i++)
        if (strcmp(f->check, filled_checks[i]) == 0)
            filled_failed = 1;
}

/* The CUT reader on the bytes as text (cbf_cut_encode): an answer, never a crash; a refusal is one line of
 * text; a file it writes frames. */
static void fuzz_cut_reader(const uint8_t *data, size_t size)
{
    cbf_reader r;
    cbf_cut_error e;
    long m = cbf_cut_encode((const char *)data, size, CBF_FUZZ_DEFAULT_PROFILE, out, sizeof out, &e);
    CHECK(m >= (long)CBF_HEADER_SIZE || m == CBF_ERR_SYNTAX || m == CBF_ERR_BUFFER);
    if (m == CBF_ERR_SYNTAX)
        CHECK(e.message[0] != 0 && strchr(e.message, '\n') == NULL);
    if (m > 0)
        CHECK(cbf_reader_init(&r, out, (size_t)m) == CBF_OK);
}

/* The validator under every profile: no more errors than findings. */
static void fuzz_validate(const uint8_t *data, size_t size)
{
    cbf_options opt;
    long errors;
    int p;
    for (p = 0; p < CBF_PROFILE__COUNT; p++) {
        memset(&opt, 0, sizeof opt);
        opt.profile = p;
        findings = 0;
        errors = cbf_validate(data, size, &opt, count_finding, NULL);
        CHECK(errors >= 0 && errors <= findings);
    }
}

/* Whether the bytes are a header and whole records (the reader refuses only a short header or a record cut
 * short). */
static int fuzz_frames(const uint8_t *data, size_t size)
{
    cbf_reader r;
    cbf_record rec;
    int rc;
    if (cbf_reader_init(&r, data, size) != CBF_OK) {
        CHECK(size < CBF_HEADER_SIZE);
        return 0;
    }
    while ((rc = cbf_next_record(&r, &rec)) == 1) {}
    if (rc < 0) {
        CHECK(rc == CBF_ERR_TRUNCATED_RECORD);
        return 0;
    }
    return 1;
}

/* decode -> encode (stored values) -> the same bytes, in out: their length. */
static long fuzz_stored_round_trip(const uint8_t *data, size_t size)
{
    cbf_reader r;
    cbf_record rec;
    cbf_writer w;
    long n;
    int rc;
    CHECK(cbf_reader_init(&r, data, size) == CBF_OK);
    CHECK(cbf_encode_begin(&w, out, sizeof out, &r.header) == CBF_OK);
    while ((rc = cbf_next_record(&r, &rec)) == 1) {
        if (rec.layout != CBF_LAYOUT__NONE) {
            uint8_t args[CBF_MAX_ARG_SIZE + 1];
            long m = cbf_args_encode(rec.layout, &rec.decoded, args, sizeof args);
            CHECK(m >= 0 && (size_t)m == rec.nargs);
            CHECK(m == 0 || memcmp(args, rec.args, rec.nargs) == 0);
        }
        CHECK(cbf_encode_record_stored(&w, &rec.head, rec.args, rec.nargs) == CBF_OK);
    }
    CHECK(rc == 0);
    CHECK(cbf_encode_bytes(&w, data + r.pos, r.trailing) == CBF_OK);
    n = cbf_encode_end(&w, CBF_FUZZ_DEFAULT_PROFILE, 0);
    CHECK(n >= 0 && (size_t)n == size && memcmp(out, data, size) == 0);
    return n;
}

/* The n bytes written in out, decoded again: the same header and records as the input's. */
static void fuzz_decode_again(const uint8_t *data, size_t size, long n)
{
    cbf_reader r, r2;
    cbf_record rec, rec2;
    int rc, rc2;
    CHECK(cbf_reader_init(&r, data, size) == CBF_OK);
    CHECK(cbf_reader_init(&r2, out, (size_t)n) == CBF_OK);
    CHECK(memcmp(&r.header, &r2.header, sizeof r.header) == 0);
    for (;;) {
        rc = cbf_next_record(&r, &rec);
        rc2 = cbf_next_record(&r2, &rec2);
        CHECK(rc == rc2);
        if (rc != 1)
            break;
        CHECK(rec.offset == rec2.offset && rec.layout == rec2.layout && rec.command == rec2.command);
        CHECK(memcmp(&rec.head, &rec2.head, sizeof rec.head) == 0);
        CHECK(memcmp(&rec.decoded, &rec2.decoded, sizeof rec.decoded) == 0);
    }
    CHECK(r.trailing == r2.trailing);
}

/* The filling writer under profile p: it refuses exactly what the version lacks, and what it writes passes
 * its checks. */
static void fuzz_filled(const uint8_t *data, size_t size, int p)
{
    cbf_reader r;
    cbf_record rec;
    cbf_writer w;
    cbf_options opt;
    long n;
    int rc, refused = 0;
    CHECK(cbf_reader_init(&r, data, size) == CBF_OK);
    CHECK(cbf_encode_begin(&w, out2, sizeof out2, &r.header) == CBF_OK);
    while (!refused && cbf_next_record(&r, &rec) == 1) {
        int code = CBF_FUZZ_CODE(rec.head);
        rc = cbf_encode_record(&w, code, rec.args, rec.nargs);
        /* the filling writer refuses exactly what the version lacks: the command or the size */
        refused = !cbf_command_available(code, r.header.version)
                  || cbf_args_layout(code, r.header.version, rec.nargs) == CBF_LAYOUT__NONE;
        CHECK(rc == (refused ? CBF_ERR_NOT_WRITABLE : CBF_OK));
    }
    n = cbf_encode_end(&w, p, 1);
    CHECK(!refused || n == CBF_ERR_NOT_WRITABLE); /* the refusal sticks */
    if (n < 0)
        return; /* e.g. more records than the count field holds, a read-only version */
    memset(&opt, 0, sizeof opt);
    opt.profile = p;
    filled_failed = 0;
    findings = 0;
    (void)cbf_validate(out2, (size_t)n, &opt, count_finding, NULL);
    CHECK(!filled_failed);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    long n;
    int p;
    fuzz_cut_reader(data, size);
    fuzz_validate(data, size);
    if (!fuzz_frames(data, size) || size > sizeof out)
        return 0;
    n = fuzz_stored_round_trip(data, size);
    fuzz_decode_again(data, size, n);
    for (p = 0; p < CBF_PROFILE__COUNT; p++)
        fuzz_filled(data, size, p);
    return 0;
}
/* ==== END tools/fuzz.c ==== */
#line 205 "cbf_fuzz.c"
