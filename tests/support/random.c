/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Seeded random numbers for the tests (random.h). */
#include "random.h"

/* [0, 1) from the top 53 bits: every value a double, none rounded up to 1. */
static double unit_interval(uint64_t bits)
{
    return (double)(bits >> 11) * 0x1.0p-53;
}

double splitmix64_uniform(uint64_t *state, double lo, double hi)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return lo + (hi - lo) * unit_interval(z);
}

double xorshift64star_uniform(uint64_t *state, double lo, double hi)
{
    *state ^= *state >> 12;
    *state ^= *state << 25;
    *state ^= *state >> 27;
    return lo + (hi - lo) * unit_interval(*state * 0x2545F4914F6CDD1Dull);
}

size_t random_size(random_uniform_fn uniform, uint64_t *state, size_t lo, size_t hi)
{
    size_t k = lo + (size_t)uniform(state, 0.0, (double)(hi - lo + 1));
    return k > hi ? hi : k; /* the draw is below hi - lo + 1, but may round up to it */
}

void random_scaled_spd(random_uniform_fn uniform, uint64_t *state, size_t m, double delta_lo,
                       double delta_hi, double work[], double W[])
{
    double *A = work, *d = work + m * m, delta = uniform(state, delta_lo, delta_hi);
    for (size_t k = 0; k < m * m; k++)
        A[k] = uniform(state, -1.0, 1.0);
    for (size_t i = 0; i < m; i++)
        d[i] = uniform(state, 0.5, 2.0);
    for (size_t i = 0; i < m; i++)
        for (size_t j = 0; j <= i; j++) {
            double s = 0.0;
            for (size_t k = 0; k < m; k++)
                s += A[i * m + k] * A[j * m + k];
            s = s / (double)m + (i == j ? delta : 0.0);
            W[i * m + j] = W[j * m + i] = d[i] * s * d[j];
        }
}

void random_gram_spd(random_uniform_fn uniform, uint64_t *state, size_t n, double shift,
                     double work[], double W[])
{
    double *B = work;
    for (size_t k = 0; k < n * n; k++)
        B[k] = uniform(state, -1.0, 1.0);
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) {
            double s = 0.0;
            for (size_t k = 0; k < n; k++)
                s += B[i * n + k] * B[j * n + k];
            W[i * n + j] = s / (double)n + (i == j ? shift : 0.0);
        }
}
