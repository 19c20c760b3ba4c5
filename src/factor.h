/* SPDX-License-Identifier: GPL-3.0-or-later */
/* factor.h — internal: the cached factor of one principal block W[B, B] of a dense W.
 *
 * Both partitions solve with a principal block of W: the paper's with W_SS, the consistent
 * law's QP with W_FF of its free set. The block is Jacobi-scaled, D^-1/2 W_BB D^-1/2 with
 * D = diag(W_BB), before GSL's pivoted Cholesky LDL^T, so the singularity test on its
 * reciprocal condition number does not depend on the contacts' units (diag(1, 1e-14) is
 * regular; a redundant pair is not). The factor is kept, keyed by the block's contact list,
 * and reused while the list and W hold. */
#ifndef FRICREG_FACTOR_H
#define FRICREG_FACTOR_H

#include <stddef.h>

struct fricreg_ctx;

struct fr_factor {
    size_t *set; /* [m] contact indices of the factored block, ascending; valid if valid */
    size_t n;    /* its size */
    int valid;
    double *ldlt;  /* [m*m] GSL pcholesky factor of the scaled block, packed n x n */
    size_t *perm;  /* [m] its pivot permutation */
    double *scale; /* [m] 1/sqrt(W_ii) of the block's contacts */
    double *work;  /* [3m] workspace of GSL's condition estimate */
};

/* Allocates the factor storage for m contacts; FRICREG_OK or FRICREG_ENOMEM (then nothing is
 * held). fr_factor_free releases it and is safe on a zeroed or freed struct. */
int fr_factor_alloc(struct fr_factor *fa, size_t m);
void fr_factor_free(struct fr_factor *fa);

/* Makes ctx->fac hold the factor of W[set, set] (set: n ascending contact indices), reusing
 * the held one when set is the same. A new factorization is counted in
 * FRICREG_STAT_FACTORIZATIONS. Returns FRICREG_OK, or FRICREG_ESINGULAR (recorded in ctx with
 * `who` leading the message) when the scaled block's reciprocal condition number is below
 * 1e-12; the cache is then empty. */
int fr_factor_ensure(struct fricreg_ctx *ctx, const size_t set[], size_t n, const char *who);

/* Solves W[set, set] x = r in place with the held factor (r[n] in, x out), counted in
 * FRICREG_STAT_SOLVES. Returns FRICREG_OK or FRICREG_ESINGULAR (recorded). */
int fr_factor_solve(struct fricreg_ctx *ctx, double r[], const char *who);

#endif
