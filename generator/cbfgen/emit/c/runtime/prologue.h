/* ---- the implementation's prologue: headers, compiler shims, short names -- */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h> /* strtof, strtod: the CUT reader's numbers (runtime/cut.c) */
#include <string.h>

#ifdef __cplusplus
extern "C" {
#endif

/* binary32 and binary64 go through uint32_t and uint64_t with memcpy: the sizes must agree. */
typedef char cbf__assert_float_size[(sizeof(float) == sizeof(uint32_t)) ? 1 : -1];
typedef char cbf__assert_double_size[(sizeof(double) == sizeof(uint64_t)) ? 1 : -1];
typedef char cbf__assert_char_bits[(((unsigned char)-1) == 255) ? 1 : -1];

#if defined(__GNUC__) || defined(__clang__)
#define CBF__PRINTF(f, a) __attribute__((format(printf, f, a)))
/* The record loops' functions start on a cache line: their speed then no longer depends on where
 * the rest of the header happens to put them (measured: up to 8 % either way without it). */
#define CBF__HOT __attribute__((aligned(64)))
#else
#define CBF__PRINTF(f, a)
#define CBF__HOT
#endif

#define CBF__F_RESERVED CBF_FIELD_RESERVED
#define CBF__F_TEXT CBF_FIELD_TEXT
#define CBF__F_MAGIC CBF_FIELD_MAGIC
#define CBF__K_UINT CBF_KIND_UINT
#define CBF__K_SINT CBF_KIND_SINT
#define CBF__K_FLOAT CBF_KIND_FLOAT
#define CBF__K_STRING CBF_KIND_STRING
#define CBF__K_BYTES CBF_KIND_BYTES
#define CBF__VBIT(v) CBF_VERSION_BIT(v)
#define CBF__PBIT(p) (1u << (p))
#define CBF__PI 3.14159265358979323846
