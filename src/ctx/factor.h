/* SPDX-License-Identifier: GPL-3.0-or-later */
/* factor.h — internal: the cached factor of one principal block W[B, B] of a dense W, updated
 * when contacts enter or leave B.
 *
 * Both partitions solve with a principal block of W: the paper's with W_SS, the consistent
 * law's QP with W_FF of its free set. The block is factored W_BB = U^T diag(d) U (LDL^T with
 * L = U^T unit lower triangular), unpivoted, in the order the contacts entered it (factor.c
 * says why). A contact that enters is a new last row and column, O(|B|^2); one that leaves is
 * a rank-one update of the trailing factor, O(|B|^2); when more than a few change, or an
 * update may have lost accuracy, the block is factored afresh. Singularity test: the smallest
 * pivot ratio d_k / W_kk of a fresh factorization below FR_PIVOT_MIN. The ratio does not
 * depend on the contacts' units (it is unchanged by a diagonal scaling of W, so
 * diag(1, 1e-14) is regular), and a redundant pair's second pivot is 0 to rounding. */
#ifndef FRICREG_FACTOR_H
#define FRICREG_FACTOR_H

#include <stddef.h>

struct fricreg_ctx;

struct fr_factor {
    size_t *set;        /* [m] contact index of each factor position 0..n-1, in order of entry */
    size_t n;           /* the block's size */
    int valid;          /* 0: U, d are stale (W or the partition changed); set, pos still agree */
    double *U;          /* [m*m] W_BB = U^T diag(d) U, U unit upper, row-major, row stride m */
    double *d;          /* [m] the pivots, > 0 */
    size_t *pos;        /* [m] factor position of each contact of W, FR_NOT_HELD if none */
    size_t *order;      /* [m] factor position of the a-th contact of the last ensure's set */
    double *work;       /* [m] scratch of solves and updates */
    unsigned char *hit; /* [m] scratch: factor positions the next block keeps */
    size_t updates;     /* contacts added or removed since the last fresh factorization */
    int fragile;        /* a pivot ratio of the held factor is below UPDATE_PIVOT_MIN: no
                           updates from it (factor.c) */
};

/* Allocates the factor storage for m contacts (nothing held); FRICREG_OK or FRICREG_ENOMEM
 * (then nothing is allocated). fr_factor_free releases it and is safe on a zeroed or freed
 * struct. */
int fr_factor_alloc(struct fr_factor *fa, size_t m);
void fr_factor_free(struct fr_factor *fa);

/* Makes ctx->fac hold the factor of W[set, set] (set: n distinct contact indices), from the
 * held one: nothing to do when the set is the same, contacts added and removed when a few
 * changed (counted in FRICREG_STAT_FACTOR_UPDATES, one per contact), else a fresh
 * factorization (FRICREG_STAT_FACTORIZATIONS). Returns FRICREG_OK, or FRICREG_ESINGULAR
 * (recorded in ctx with `who` leading the message) when a fresh factorization has a pivot
 * ratio below FR_PIVOT_MIN; the cache is then empty. Reads set, never writes it. */
int fr_factor_ensure(struct fricreg_ctx *ctx, const size_t set[], size_t n, const char *who);

/* Solves W[set, set] x = r in place with the held factor, r[n] in the order of the set given
 * to the last fr_factor_ensure, counted in FRICREG_STAT_SOLVES. Cannot fail: Returns
 * FRICREG_OK. */
int fr_factor_solve(struct fricreg_ctx *ctx, double r[], const char *who);

#endif
