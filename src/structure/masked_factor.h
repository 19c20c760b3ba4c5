/* SPDX-License-Identifier: GPL-3.0-or-later */
/* masked_factor.h — internal: solves with principal blocks of one symmetric positive definite
 * m x m matrix W (a step's W_eff), refactored as often as the block changes without allocating.
 *
 * A block W_SS (plus a diagonal shift) is factored as the whole m x m matrix whose rows and
 * columns outside S are the identity's: one pattern, W's, for every S. The pattern is ordered
 * once (AMD) and stored permuted, so that each numeric factorization is CHOLMOD's simplicial
 * one on a matrix in natural order, which allocates nothing (cholmod_l_factorize permutes a
 * matrix in any other order into new storage every call). A solve on the block and shifts of
 * the last factorization makes none. */
#ifndef FRICREG_MASKED_FACTOR_H
#define FRICREG_MASKED_FACTOR_H

#include <stddef.h>

#include <cholmod.h>

struct fr_masked_factor {
    size_t m;
    cholmod_sparse *A;      /* P W P^T's upper triangle, its values filled per solve */
    SuiteSparse_long *src;  /* [nnz(A)] entry of A -> its entry of W */
    SuiteSparse_long *perm; /* [m] row k of P W P^T is row perm[k] of W */
    cholmod_factor *L;
    cholmod_dense *X, *Yw, *Ew;
    double *b; /* [m] */
    /* The block and shifts of the last factorization: a solve on the same ones reuses it
     * (a stick set that holds from one Newton iteration, or one step, to the next). */
    unsigned char *held_set; /* [m] */
    double *held_shift;      /* [m] */
    int held;
};

/* Ready for blocks of W (m x m, upper triangle, sorted): ordered, permuted, analysed, and one
 * solve made to size the workspaces. f must be zeroed or freed. FRICREG_OK or FRICREG_ENOMEM
 * (f then freed). */
int fr_masked_factor_prepare(struct fr_masked_factor *f, const cholmod_sparse *W,
                             cholmod_common *c);

void fr_masked_factor_free(struct fr_masked_factor *f, cholmod_common *c);

/* x_S = (W_SS + diag(shift_S))^-1 b_S for S the entries marked in set[m] (set NULL: none;
 * shift NULL: no shift); x elsewhere untouched. W must have the pattern it was prepared with. FRICREG_OK;
 * FRICREG_ESINGULAR (the block is not positive definite); FRICREG_ENOMEM. */
int fr_masked_factor_solve(struct fr_masked_factor *f, const cholmod_sparse *W,
                           const unsigned char *set, const double *shift, const double b[],
                           double x[], cholmod_common *c);

#endif
