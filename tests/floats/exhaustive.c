/* The CUT float formatter, proven over every binary32 bit pattern (issue 13, item 1).
 *
 * A twin of cbf.floats.format_float: the fewest significant digits p (1..9)
 * whose correctly rounded %.{p}g text reads back, correctly rounded to binary32,
 * as the same bits (text beyond the range reads as infinity: no match), written
 * in positional notation. glibc's printf and strtof round correctly, as do
 * Python's format() and cbf.floats.parse_float, so both compute one function;
 * tests/test_float_format.py compares the two on a sample.
 *
 * Per pattern, a double-precision estimate decides each p with a wide safety
 * margin (the error is below 1e-6 of a last digit, the margin 1e-6); where it is
 * unsure, the exact test (snprintf + strtof) decides. The text is then checked
 * with strtof, the independent exact reader: that check is the proof. Every
 * 4096th pattern is also formatted by the plain loop, which must agree.
 *
 *   exhaustive [FIRST LAST]   sweep patterns FIRST..LAST (default all 2^32): every finite
 *                             pattern must read back byte-exact from text the CUT float
 *                             pattern (-?[0-9]+\.?[0-9]*) accepts; NaN and infinity are
 *                             counted as written as cbf_record (cut.py does so).
 *   exhaustive --print        read hex patterns on stdin, print the formatter's text for each.
 */
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static float from_bits(uint32_t b) { float f; memcpy(&f, &b, sizeof f); return f; }
static uint32_t to_bits(float f) { uint32_t b; memcpy(&b, &f, sizeof b); return b; }

/* Read back as the CUT reader does: correctly rounded; beyond the range is no value (-1). */
static int64_t read_back(const char *text) {
    float g = strtof(text, NULL);
    if (isinf(g)) return -1;
    return (int64_t)to_bits(g);
}

/* "%.{p}g" text to positional notation, as Python's format(Decimal(s), "f"). */
static void positional(const char *g, char *out, size_t cap) {
    const char *e = strchr(g, 'e');
    if (!e) { snprintf(out, cap, "%s", g); return; }
    char digits[32]; size_t nd = 0, before = 0; int seen_point = 0, neg = 0;
    const char *s = g;
    if (*s == '-') { neg = 1; s++; }
    for (; s < e; s++) {
        if (*s == '.') { seen_point = 1; continue; }
        digits[nd++] = *s;
        if (!seen_point) before++;
    }
    long pos = (long)before + strtol(e + 1, NULL, 10);   /* digits before the point */
    char *o = out;
    if (neg) *o++ = '-';
    if (pos <= 0) {
        *o++ = '0'; *o++ = '.';
        for (long k = 0; k < -pos; k++) *o++ = '0';
        for (size_t k = 0; k < nd; k++) *o++ = digits[k];
    } else if ((size_t)pos >= nd) {
        for (size_t k = 0; k < nd; k++) *o++ = digits[k];
        for (long k = (long)nd; k < pos; k++) *o++ = '0';
    } else {
        for (long k = 0; k < pos; k++) *o++ = digits[k];
        *o++ = '.';
        for (size_t k = (size_t)pos; k < nd; k++) *o++ = digits[k];
    }
    *o = '\0';
    (void)cap;
}

/* The exact test of one p. */
static int exact(uint32_t bits, double v, int p, char *g, size_t cap) {
    snprintf(g, cap, "%.*g", p, v);
    return read_back(g) == (int64_t)bits;
}

/* The plain loop, as cbf.floats.format_float runs it. */
static int format_slow(uint32_t bits, char *out, size_t cap) {
    double v = (double)from_bits(bits);
    char g[64];
    for (int p = 1; p <= 9; p++)
        if (exact(bits, v, p, g, sizeof g)) { positional(g, out, cap); return p; }
    return 0;
}

static double P10[141];                 /* 10^k at P10[k + 70], each correctly rounded */
#define TEN(k) P10[(k) + 70]

/* Text of N * 10^q in positional notation (N has p digits, or is 10^p after a carry). */
static void from_integer(int neg, uint64_t n, int q, char *out) {
    while (n % 10 == 0 && n) { n /= 10; q++; }
    char d[24]; int nd = snprintf(d, sizeof d, "%" PRIu64, n);
    char *o = out;
    if (neg) *o++ = '-';
    int pos = nd + q;
    if (q >= 0) {
        memcpy(o, d, (size_t)nd); o += nd;
        for (int k = 0; k < q; k++) *o++ = '0';
    } else if (pos <= 0) {
        *o++ = '0'; *o++ = '.';
        for (int k = 0; k < -pos; k++) *o++ = '0';
        memcpy(o, d, (size_t)nd); o += nd;
    } else {
        memcpy(o, d, (size_t)pos); o += pos;
        *o++ = '.';
        memcpy(o, d + pos, (size_t)(nd - pos)); o += nd - pos;
    }
    *o = '\0';
}

/* The formatter; returns p (0: nothing read back), *fallbacks counts exact tests used. */
static int format_fast(uint32_t bits, char *out, size_t cap, uint64_t *fallbacks) {
    float f = from_bits(bits);
    double v = fabs((double)f);
    int neg = (int)(bits >> 31);
    if (v == 0.0) { snprintf(out, cap, neg ? "-0" : "0"); return 1; }
    uint32_t field = (bits >> 23) & 0xFF, mant = bits & 0x7FFFFF;
    double ulp = ldexp(1.0, (field ? (int)field : 1) - 150);
    double up = ulp / 2, down = (mant == 0 && field > 1) ? ulp / 4 : ulp / 2;
    int E = (int)floor(log10(v));
    if (v < TEN(E)) E--; else if (v >= TEN(E + 1)) E++;
    int near_decade = fabs(v / TEN(E) - 1) < 1e-12 || fabs(v / TEN(E + 1) - 1) < 1e-12;
    char g[64];
    for (int p = 1; p <= 9; p++) {
        int q = E - p + 1;
        double y = v / TEN(q), fl = floor(y), n = floor(y + 0.5);
        double diff = n - y, h = (diff > 0 ? up : down) / TEN(q), ad = fabs(diff);
        int sure_n = fabs(y - fl - 0.5) > 1e-6;
        int verdict = -1;
        if (!near_decade && sure_n) {
            if (ad < h * (1 - 1e-9) - 1e-6) verdict = 1;
            else if (ad > h * (1 + 1e-9) + 1e-6) verdict = 0;
        }
        if (verdict < 0) {
            ++*fallbacks;
            if (exact(bits, (double)f, p, g, sizeof g)) { positional(g, out, cap); return p; }
            continue;
        }
        if (verdict) { from_integer(neg, (uint64_t)n, q, out); return p; }
    }
    return 0;
}

/* The CUT float pattern -?[0-9]+\.?[0-9]* (spec cut.float_pattern), matched whole. */
static int cut_number(const char *s) {
    if (*s == '-') s++;
    if (*s < '0' || *s > '9') return 0;
    while (*s >= '0' && *s <= '9') s++;
    if (*s == '.') s++;
    while (*s >= '0' && *s <= '9') s++;
    return *s == '\0';
}

int main(int argc, char **argv) {
    char out[128], slow[128];
    uint64_t fallbacks = 0;
    for (int k = -70; k <= 70; k++) { char t[16]; snprintf(t, sizeof t, "1e%d", k); TEN(k) = strtod(t, NULL); }
    if (argc == 2 && strcmp(argv[1], "--print") == 0) {
        char line[64];
        while (fgets(line, sizeof line, stdin)) {
            uint32_t bits = (uint32_t)strtoul(line, NULL, 16);
            if (!isfinite(from_bits(bits))) { puts("cbf_record"); continue; }
            puts(format_fast(bits, out, sizeof out, &fallbacks) ? out : "FAIL");
        }
        return 0;
    }
    uint64_t first = 0, last = 0xFFFFFFFFu;
    if (argc == 3) { first = strtoull(argv[1], NULL, 0); last = strtoull(argv[2], NULL, 0); }
    uint64_t good = 0, record = 0, bad = 0, compared = 0, by_digits[10] = {0};
    for (uint64_t b = first; b <= last; b++) {
        uint32_t bits = (uint32_t)b;
        if (!isfinite(from_bits(bits))) { record++; continue; }
        int p = format_fast(bits, out, sizeof out, &fallbacks);
        int ok = p && cut_number(out) && read_back(out) == (int64_t)bits;
        if (ok && (bits & 0xFFF) == 0x5A5) {   /* the plain loop agrees */
            compared++;
            ok = format_slow(bits, slow, sizeof slow) == p && strcmp(slow, out) == 0;
        }
        if (ok) { good++; by_digits[p]++; continue; }
        if (bad++ < 20) fprintf(stderr, "FAIL 0x%08" PRIx32 " -> %s\n", bits, p ? out : "(no digits)");
    }
    printf("patterns 0x%08" PRIx64 "..0x%08" PRIx64 ": %" PRIu64 " finite read back byte-exact, "
           "%" PRIu64 " NaN/infinity written as cbf_record, %" PRIu64 " failed\n", first, last, good, record, bad);
    printf("digits:");
    for (int p = 1; p <= 9; p++) printf(" %d:%" PRIu64, p, by_digits[p]);
    printf("; exact fallbacks %" PRIu64 "; %" PRIu64 " compared with the plain loop\n", fallbacks, compared);
    return bad ? 1 : 0;
}
