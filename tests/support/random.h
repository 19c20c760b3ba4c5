/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Seeded random numbers for the tests: the same cases on every run and platform.
 *
 * No state lives here: each test file keeps its own uint64_t state (and its own seeds), so
 * that one file's draws never depend on which other tests ran before it (CK_FORK=no under
 * valgrind runs every case in one process, in order). */
#ifndef FRICREG_TESTS_RANDOM_H
#define FRICREG_TESTS_RANDOM_H

#include <stddef.h>
#include <stdint.h>

/* A uniform draw in [lo, hi): lo + (hi - lo) u, u = the top 53 bits of the next 64 / 2^53. */
typedef double (*random_uniform_fn)(uint64_t *state, double lo, double hi);

/* splitmix64 (Steele, Lea, Flood 2014): adds the golden-ratio increment to *state. */
double splitmix64_uniform(uint64_t *state, double lo, double hi);

/* xorshift64* (Vigna 2016, shifts 12, 25, 27; multiplier 0x2545F4914F6CDD1D). *state must
 * not be 0. */
double xorshift64star_uniform(uint64_t *state, double lo, double hi);

/* An integer in [lo, hi] (lo <= hi), from one draw in [0, hi - lo + 1) rounded down. */
size_t random_size(random_uniform_fn uniform, uint64_t *state, size_t lo, size_t hi);

/* A random SPD W (m x m, row-major) with unequal diagonal: W = D (A A^T / m + delta I) D.
 * Draws, in this order: delta in [delta_lo, delta_hi), A (m x m, row-major, entries in
 * [-1, 1)), then D's diagonal in [0.5, 2). The condition number is a few hundred at most.
 * work holds m * m + m doubles. */
void random_scaled_spd(random_uniform_fn uniform, uint64_t *state, size_t m, double delta_lo,
                       double delta_hi, double work[], double W[]);

/* A random SPD W (n x n, row-major): B B^T / n + shift I, B (n x n, row-major, entries drawn
 * in [-1, 1)). work holds n * n doubles. */
void random_gram_spd(random_uniform_fn uniform, uint64_t *state, size_t n, double shift,
                     double work[], double W[]);

#endif
