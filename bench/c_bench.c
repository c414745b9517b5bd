/* In-process timing of the C codec: decode (record iterator) and full validate,
 * and the baseline a validator is measured against: a plain one-pass byte sum
 * over the same buffer (the least any validator must do: the file checksum
 * reads every byte), compiled in the same unit with the same flags.
 *   c_bench FILE REPS  ->  one JSON line:
 *   {"bytes": N, "decode": [seconds...], "validate": [...], "bytesum": [...], "records": N, "findings": N}
 * Built by bench/bench.py with -O2 from generated/c/cbf.h. */
#define _POSIX_C_SOURCE 199309L
#define CBF_IMPLEMENTATION
#include "cbf.h"
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* The baseline: every byte read once and added, nothing else. Not inlined, and
 * its result goes to a volatile, so the compiler can neither drop nor hoist it. */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((noinline))
#endif
static uint32_t byte_sum(const uint8_t *p, size_t n)
{
    uint32_t s = 0;
    size_t i;
    for (i = 0; i < n; i++)
        s += p[i];
    return s;
}

static volatile uint32_t sink;

static void count(void *user, const cbf_finding *f)
{
    (void)f;
    ++*(long *)user;
}

int main(int argc, char **argv)
{
    FILE *fp;
    uint8_t *buf;
    long size, records = 0, findings = 0, i, reps;
    if (argc != 3 || !(fp = fopen(argv[1], "rb"))) return 2;
    fseek(fp, 0, SEEK_END);
    size = ftell(fp);
    fseek(fp, 0, SEEK_SET);
    buf = (uint8_t *)malloc((size_t)size); /* the benchmark's own buffer; the codec allocates nothing */
    if (!buf || fread(buf, 1, (size_t)size, fp) != (size_t)size) return 2;
    fclose(fp);
    reps = atol(argv[2]);
    printf("{\"bytes\": %ld, \"decode\": [", size);
    for (i = 0; i < reps; i++) {
        cbf_reader r;
        cbf_record rec;
        double t0 = now();
        records = 0;
        if (cbf_reader_init(&r, buf, (size_t)size) != CBF_OK) return 3;
        while (cbf_next_record(&r, &rec) == 1) records++;
        printf("%s%.9f", i ? ", " : "", now() - t0);
    }
    /* validate and the byte sum alternate, so that a change of load on a shared
     * machine hits both alike (their ratio is the figure) */
    {
        double *tv = (double *)malloc(2 * (size_t)reps * sizeof(double)), *ts;
        if (!tv) return 2;
        ts = tv + reps;
        for (i = 0; i < reps; i++) {
            cbf_options opt = { CBF_PROFILE_DEFAULT, NULL, NULL, 0 };
            double t0 = now();
            findings = 0;
            if (cbf_validate(buf, (size_t)size, &opt, count, &findings) < 0) return 4;
            tv[i] = now() - t0;
            t0 = now();
            sink = byte_sum(buf, (size_t)size);
            ts[i] = now() - t0;
        }
        printf("], \"validate\": [");
        for (i = 0; i < reps; i++) printf("%s%.9f", i ? ", " : "", tv[i]);
        printf("], \"bytesum\": [");
        for (i = 0; i < reps; i++) printf("%s%.9f", i ? ", " : "", ts[i]);
        free(tv);
    }
    printf("], \"records\": %ld, \"findings\": %ld}\n", records, findings);
    free(buf);
    return 0;
}
