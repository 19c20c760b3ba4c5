/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fuzz_input.h — the fuzz targets' reader of their input bytes, and the contract checks they
 * share. The reader turns bytes into the values that break numerical code: one selector byte
 * picks a special value (0, -0, ±1, NaN, ±Inf, DBL_MIN, the smallest subnormal, DBL_MAX, …), a
 * moderate number from two bytes, or eight raw bytes as a double, so that the fuzzer reaches
 * both the plain and the hostile inputs. Past the end of the input every read gives 0. */
#ifndef FRICREG_FUZZ_INPUT_H
#define FRICREG_FUZZ_INPUT_H

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct fuzz_input {
    const uint8_t *data;
    size_t size, pos;
};

static inline uint8_t fuzz_byte(struct fuzz_input *in)
{
    return in->pos < in->size ? in->data[in->pos++] : 0;
}

static inline int fuzz_done(const struct fuzz_input *in)
{
    return in->pos >= in->size;
}

/* A double: mostly moderate numbers a user would pass, often a special value, sometimes any
 * bit pattern. */
static inline double fuzz_double(struct fuzz_input *in)
{
    static const double special[16] = {0.0,       -0.0,    1.0,      -1.0,    NAN,      INFINITY,
                                       -INFINITY, DBL_MIN, 4.9e-324, DBL_MAX, -DBL_MAX, 1e-300,
                                       1e300,     2.385,   1e-3,     -1e-12};
    uint8_t sel = fuzz_byte(in);
    if (sel < 64)
        return special[sel % 16];
    if (sel < 224) { /* m * 10^e, m in [-1, 1), e in [-8, 7]: moderate, both signs */
        uint8_t lo = fuzz_byte(in), hi = fuzz_byte(in);
        double m = ((double)((hi << 8) | lo) - 32768.0) / 32768.0;
        return m * pow(10.0, (double)(sel % 16) - 8.0);
    }
    uint64_t bits = 0;
    for (int k = 0; k < 8; k++)
        bits |= (uint64_t)fuzz_byte(in) << (8 * k);
    double x;
    memcpy(&x, &bits, sizeof x);
    return x;
}

/* An int from a small range [lo, lo + n), or an outlandish value now and then. */
static inline int fuzz_int(struct fuzz_input *in, int lo, int n)
{
    uint8_t sel = fuzz_byte(in);
    if (sel == 255)
        return -1;
    if (sel == 254)
        return 2147483647;
    if (sel == 253)
        return (int)(-2147483647 - 1);
    return lo + (int)(sel % (unsigned)n);
}

/* A contract violation: print it and abort, which libFuzzer records as a crash and the replay
 * as a failed test. */
#define FUZZ_REQUIRE(cond, ...)                                                         \
    do {                                                                                \
        if (!(cond)) {                                                                  \
            fprintf(stderr, "%s:%d: contract broken: %s: ", __FILE__, __LINE__, #cond); \
            fprintf(stderr, __VA_ARGS__);                                               \
            fputc('\n', stderr);                                                        \
            abort();                                                                    \
        }                                                                               \
    } while (0)

/* Fill with a recognizable sentinel; equal to the sentinel, bit for bit (NaN included). */
#define FUZZ_SENTINEL 0x5a
static inline void fuzz_fill(void *p, size_t bytes)
{
    memset(p, FUZZ_SENTINEL, bytes);
}

static inline int fuzz_untouched(const void *p, size_t bytes)
{
    const unsigned char *c = (const unsigned char *)p;
    for (size_t k = 0; k < bytes; k++)
        if (c[k] != FUZZ_SENTINEL)
            return 0;
    return 1;
}

/* Bit-for-bit equality of two arrays of doubles (NaN equal to itself). */
static inline int fuzz_same_bits(const double *a, const double *b, size_t n)
{
    return n == 0 || memcmp(a, b, n * sizeof *a) == 0;
}

static inline int fuzz_all_finite(const double *a, size_t n)
{
    for (size_t k = 0; k < n; k++)
        if (!isfinite(a[k]))
            return 0;
    return 1;
}

/* A dense n x n matrix W (row-major) of one of several kinds, for a coupling: any symmetric
 * (mostly indefinite), B B^T with B n x rank (PSD, singular when rank < n), the same scaled by
 * any double (huge, subnormal, negative, NaN), or any matrix. B: scratch of n * n doubles. */
static inline void fuzz_matrix(struct fuzz_input *in, size_t n, double W[], double B[])
{
    uint8_t kind = fuzz_byte(in) % 4;
    size_t rank = 1 + fuzz_byte(in) % n;
    double scale = fuzz_double(in);
    switch (kind) {
    case 0:
        for (size_t i = 0; i < n; i++)
            for (size_t j = i; j < n; j++)
                W[i * n + j] = W[j * n + i] = fuzz_double(in);
        break;
    case 1:
    case 3:
        for (size_t k = 0; k < n * rank; k++)
            B[k] = fuzz_double(in);
        for (size_t i = 0; i < n; i++)
            for (size_t j = 0; j < n; j++) {
                double s = 0.0;
                for (size_t k = 0; k < rank; k++)
                    s += B[i * rank + k] * B[j * rank + k];
                W[i * n + j] = kind == 3 ? s * scale : s;
            }
        break;
    default:
        for (size_t k = 0; k < n * n; k++)
            W[k] = fuzz_double(in);
    }
}

#endif
