/* SPDX-License-Identifier: GPL-3.0-or-later */
/* plausible.c — the validation pass of plausible.h: in SSE2 vectors on x86-64 (SSE2 is part of
 * it), in plain C elsewhere and for the tail.
 *
 * GCC 12 keeps a floating-point sum serial unless it is split into lanes by hand, and does not
 * vectorize a min reduction at all: the plain C lanes it packs into vectors only with a
 * compare, a mask and an add per c[i] for the sign (the form this file replaces). In cache that
 * pass cost as much as law (4) itself (bench/kernels.c). The SSE2 pass holds 4 independent sums
 * and 2 minima, so it runs at the adds' throughput, not their latency: two adds and a min per
 * contact. Where the CPU has AVX2 (dispatch.h) the same in AVX2 vectors, as are the law loops
 * that follow it (an AVX2 pass before SSE2 loops was once measured no faster). */
#include <float.h>
#include <math.h>

#include "base/dispatch.h"
#include "plausible.h"

#if defined(__GNUC__) && defined(__x86_64__) && defined(__SSE2__)
#define FR_SSE2_PASS 1
#include <emmintrin.h>
#endif
#ifdef FRICREG_AVX2_DISPATCH
#include <immintrin.h>
#endif

/* Contacts i0 <= i < m in plain C, in LANES independent chains, onto *total and *least. */
enum { LANES = 4 };

static void pass_c(size_t i0, size_t m, const double a[], const double b[], const double c[],
                   double *total, double *least)
{
    double s[LANES] = {0.0}, low[LANES] = {0.0};
    size_t i = i0;
    for (; i + LANES <= m; i += LANES)
        for (size_t l = 0; l < LANES; l++) {
            double u = c ? c[i + l] : 0.0;
            s[l] += (a[i + l] + (b ? b[i + l] : 0.0)) + u;
            low[l] = u < low[l] ? u : low[l];
        }
    for (; i < m; i++) {
        double u = c ? c[i] : 0.0;
        s[0] += (a[i] + (b ? b[i] : 0.0)) + u;
        low[0] = u < low[0] ? u : low[0];
    }
    /* In locals: through the pointers, each add and min waited on the store before it (a
     * third of a one-contact evaluation's time); the same adds in the same order. */
    double sum = *total, lo = *least;
    for (size_t l = 0; l < LANES; l++) {
        sum += s[l];
        lo = low[l] < lo ? low[l] : lo;
    }
    *total = sum;
    *least = lo;
}

#ifdef FR_SSE2_PASS
/* Two contacts from i: s += (a + b) + c, low = min(low, c). has_b and has_c are constants at
 * every call, so each loop below holds only the work it needs. */
static inline void step(int has_b, int has_c, const double a[], const double b[], const double c[],
                        size_t i, __m128d *s, __m128d *low)
{
    __m128d x = _mm_loadu_pd(a + i);
    if (has_b)
        x = _mm_add_pd(x, _mm_loadu_pd(b + i));
    if (has_c) {
        __m128d u = _mm_loadu_pd(c + i);
        x = _mm_add_pd(x, u);
        *low = _mm_min_pd(*low, u);
    }
    *s = _mm_add_pd(*s, x);
}

/* Whole groups of 8 contacts from 0; returns where they end. */
static inline size_t groups(int has_b, int has_c, size_t m, const double a[], const double b[],
                            const double c[], __m128d s[4], __m128d low[2])
{
    size_t i = 0;
    for (; i + 8 <= m; i += 8) {
        step(has_b, has_c, a, b, c, i, &s[0], &low[0]);
        step(has_b, has_c, a, b, c, i + 2, &s[1], &low[1]);
        step(has_b, has_c, a, b, c, i + 4, &s[2], &low[0]);
        step(has_b, has_c, a, b, c, i + 6, &s[3], &low[1]);
    }
    return i;
}
#endif

#ifdef FRICREG_AVX2_DISPATCH
/* The same in AVX2 (dispatch.h), four contacts a vector: groups of 16 from 0, onto *total
 * and *least; returns where they end. Its law loop that follows is AVX2 too: no mix of
 * vector widths between the passes. */
FR_AVX2 FR_KERNEL_BODY void step_avx2(int has_b, int has_c, const double a[], const double b[],
                                      const double c[], size_t i, __m256d *s, __m256d *low)
{
    __m256d x = _mm256_loadu_pd(a + i);
    if (has_b)
        x = _mm256_add_pd(x, _mm256_loadu_pd(b + i));
    if (has_c) {
        __m256d u = _mm256_loadu_pd(c + i);
        x = _mm256_add_pd(x, u);
        *low = _mm256_min_pd(*low, u);
    }
    *s = _mm256_add_pd(*s, x);
}

FR_AVX2 FR_KERNEL_BODY size_t groups_avx2(int has_b, int has_c, size_t m, const double a[],
                                          const double b[], const double c[], double *total,
                                          double *least)
{
    __m256d s[4], low[2];
    s[0] = s[1] = s[2] = s[3] = low[0] = low[1] = _mm256_setzero_pd();
    size_t i = 0;
    for (; i + 16 <= m; i += 16) {
        step_avx2(has_b, has_c, a, b, c, i, &s[0], &low[0]);
        step_avx2(has_b, has_c, a, b, c, i + 4, &s[1], &low[1]);
        step_avx2(has_b, has_c, a, b, c, i + 8, &s[2], &low[0]);
        step_avx2(has_b, has_c, a, b, c, i + 12, &s[3], &low[1]);
    }
    double sums[4], lows[4], sum = *total, lo = *least;
    _mm256_storeu_pd(sums, _mm256_add_pd(_mm256_add_pd(s[0], s[1]), _mm256_add_pd(s[2], s[3])));
    _mm256_storeu_pd(lows, _mm256_min_pd(low[0], low[1]));
    for (int l = 0; l < 4; l++) {
        sum += sums[l];
        lo = lows[l] < lo ? lows[l] : lo;
    }
    *total = sum;
    *least = lo;
    return i;
}

FR_AVX2 static size_t pass_avx2(size_t m, const double a[], const double b[], const double c[],
                                double *total, double *least)
{
    if (b && c)
        return groups_avx2(1, 1, m, a, b, c, total, least);
    if (c)
        return groups_avx2(0, 1, m, a, NULL, c, total, least);
    if (b)
        return groups_avx2(1, 0, m, a, b, NULL, total, least);
    return groups_avx2(0, 0, m, a, NULL, NULL, total, least);
}
#endif

int fr_plausible(size_t m, const double a[], const double b[], const double c[])
{
    double total = 0.0, least = 0.0;
    size_t i = 0;
    /* Fewer contacts than the smallest vector group (8, SSE2's; a small system such as the
     * oscillator's one contact): either vector pass would add only zeros to total and least,
     * both still 0, so the plain loop alone gives the same bits. */
    if (m < 8) {
        pass_c(0, m, a, b, c, &total, &least);
        return fabs(total) <= DBL_MAX && least == 0.0;
    }
#ifdef FRICREG_AVX2_DISPATCH
    if (fr_have_avx2()) {
        i = pass_avx2(m, a, b, c, &total, &least);
        pass_c(i, m, a, b, c, &total, &least);
        return fabs(total) <= DBL_MAX && least == 0.0;
    }
#endif
#ifdef FR_SSE2_PASS
    __m128d s[4], low[2];
    s[0] = s[1] = s[2] = s[3] = low[0] = low[1] = _mm_setzero_pd();
    if (b && c)
        i = groups(1, 1, m, a, b, c, s, low);
    else if (c)
        i = groups(0, 1, m, a, NULL, c, s, low);
    else if (b)
        i = groups(1, 0, m, a, b, NULL, s, low);
    else
        i = groups(0, 0, m, a, NULL, NULL, s, low);
    double sums[2], lows[2];
    _mm_storeu_pd(sums, _mm_add_pd(_mm_add_pd(s[0], s[1]), _mm_add_pd(s[2], s[3])));
    _mm_storeu_pd(lows, _mm_min_pd(low[0], low[1]));
    total = sums[0] + sums[1];
    least = lows[0] < lows[1] ? lows[0] : lows[1];
#endif
    pass_c(i, m, a, b, c, &total, &least);
    return fabs(total) <= DBL_MAX && least == 0.0; /* NaN-safe: a NaN is not plausible */
}
