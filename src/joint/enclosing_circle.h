/* SPDX-License-Identifier: GPL-3.0-or-later */
/* enclosing_circle.h — the smallest circle enclosing a sampled planar orbit, and its centre's
 * derivative as the samples move: where a 2-D slider stuck all period is centred by the
 * sampled AFTs (aft_2d.c for the 3-D contact, aft_march.c for a marched 2-D law), the one
 * place from which it never slips when it can stick at all (kt r <= mu N). */
#ifndef FRICREG_JOINT_ENCLOSING_CIRCLE_H
#define FRICREG_JOINT_ENCLOSING_CIRCLE_H

#include <stddef.h>

struct fr_circle {
    double c[2], r2; /* centre, radius squared */
    size_t sup[3];   /* the samples on it that define it */
    int nsup;
};

/* The smallest circle enclosing the N points (x[n], y[n]), N a power of two: Welzl's
 * incremental algorithm (expected O(N) in a random order) in the scrambled order
 * n -> (n * 2654435761) mod N. */
struct fr_circle fr_enclosing_circle(const double *x, const double *y, size_t N);

/* The centre's derivative dc[2] when each of k's support points i moves by dp[i][2]: the
 * point itself, the midpoint of two, or the circumcentre of three (equal distances kept). */
void fr_circle_centre_derivative(const struct fr_circle *k, const double *x, const double *y,
                                 const double dp[3][2], double dc[2]);

#endif
