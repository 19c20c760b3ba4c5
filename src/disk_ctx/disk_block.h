/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_block.h — internal: one 2-D contact's subproblem of the coupled law,
 *     min over |f + p| <= radius of 1/2 (f - h)^T A (f - h),   A = W_ii SPD 2x2,
 * the projection of h onto a disk in the metric of A (a 2-D trust-region subproblem). */
#ifndef FRICREG_DISK_BLOCK_H
#define FRICREG_DISK_BLOCK_H

#include <gsl/gsl_roots.h>

/* A = d1 e1 e1^T + d2 e2 e2^T with e1 = (c, s), e2 = (-s, c), d1, d2 > 0. */
struct fr_disk_eig {
    double d1, d2, c, s;
};

/* The eigen-decomposition of the symmetric A = [[a, b], [b, d]] by one Jacobi rotation
 * (Golub & Van Loan, Matrix Computations, 4th ed., Alg. 8.5.1): exact for b = 0 (c = 1, s = 0),
 * so an isotropic block keeps d1 == d2 bit for bit. */
void fr_disk_eig2(double a, double b, double d, struct fr_disk_eig *e);

/* Solves the subproblem for A = e, h = -A^-1 g - 2 p (g: contact i's acceleration with f_i = 0;
 * f_eq = -A^-1 g; the law's shifted point f_eq - c mun, c mun = 2p), centre -p, radius > 0.
 * Writes f and the multiplier lam >= 0 of A (f - h) + lam (f + p) = 0; returns 1 if f is on
 * the circle, 0 if inside. Inside: f = h. On the circle with d1 == d2: the Euclidean
 * projection (fricreg_disk_eval's numbers). Else lam solves the secular equation
 * |y(lam)| = radius, y_k = d_k t_k/(d_k + lam), t = h + p in the eigenbasis, by GSL's Brent
 * solver on [0, 2 max(d) |t|/radius], where it changes sign; brent is that solver's memory. */
int fr_disk_block_solve(const struct fr_disk_eig *e, const double g[2], const double p[2],
                        double radius, gsl_root_fsolver *brent, double f[2], double *lam);

#endif
