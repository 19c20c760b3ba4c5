/* SPDX-License-Identifier: GPL-3.0-or-later */
/* masked_factor.h — internal: solves with principal blocks of one symmetric positive definite
 * m x m matrix W (a step's W_eff), refactored as often as the block changes without allocating.
 *
 * Two storages, chosen once per W (fr_masked_factor_prepare). Sparse: a block W_SS (plus a
 * diagonal shift) is factored as the whole m x m matrix whose rows and columns outside S are the
 * identity's: one pattern, W's, for every S. The pattern is ordered once (AMD) and stored
 * permuted, so that each numeric factorization is CHOLMOD's simplicial one on a matrix in natural
 * order, which allocates nothing (cholmod_l_factorize permutes a matrix in any other order into
 * new storage every call). Dense: W_SS is copied into a column-major buffer of m x m doubles
 * allocated here and factored there by LAPACK's dpotrf (blocked, BLAS 3), solved by two dtrsv.
 * CHOLMOD's simplicial factor uses no BLAS and works on the whole pattern whatever S is; where
 * W's factor fills, the dense one of W_SS alone is cheaper (measured: docs/benchmark.md).
 * A solve on the block and shifts of the last factorization makes none.
 *
 * A dense factor keeps the leading rows of the last one that the new block holds with the same
 * shifts: a leading principal block's Cholesky factor is the leading block of the whole's, so
 * only the trailing rows are factored (dtrsm, dsyrk and dpotrf on them, O(q p^2 + q^2 p + q^3/3)
 * for p kept rows and q new ones instead of (p + q)^3 / 3). The rows are ordered for that: the
 * kept ones, then those without a shift, then the shifted ones (a contact in the law's band,
 * whose slope moves with every iterate) last. A near-stick set that grows and shrinks from the
 * end of its history (a stick zone's edge that advances and recedes) refactors only that edge.
 * Rows that leave from inside (or whose shift moves) are deleted where that is cheaper than
 * factoring the rows after them again: with U's staying rows T and leaving rows Q after the
 * kept ones, the block of T has the factor R of [U_TT; U_QT] (R^T R = U_TT^T U_TT +
 * U_QT^T U_QT), LAPACK's dtpqrt, 2 |Q| |T|^2 flops; the rows above keep their columns of U.
 * A block of the held rows whose shifts changed only on the last factorization's new rows (a
 * band contact's slope, a row of contacts between stick and the band) is factored from those
 * rows' Schur complement before their shifts, kept from that factorization: q^3 / 3 flops for
 * its q new rows, not the p^2 q of their products with the p kept ones. A trailing
 * factorization adds the shifts after the complement too, so that both ways give the same
 * factor to the bit.
 * Two dense factors are held (a second m x m buffer): a block is factored from whichever of the
 * two costs fewer flops, and a factor that served as that base is kept rather than replaced
 * where the new block does not hold all its rows (its kept rows copied into the other buffer,
 * the new factor made there). Why: a stick zone leaves its block and comes back (a row of
 * contacts in the law's band for an iterate, or slipping for a step), and with one factor each
 * return factored again all the rows after the first that had left. */
#ifndef FRICREG_MASKED_FACTOR_H
#define FRICREG_MASKED_FACTOR_H

#include <stddef.h>

#include <cholmod.h>

#include "block_held.h"

/* The storage of the blocks: chosen by the fill rule (fr_masked_factor_prepare), or forced
 * (the tests compare the two). */
enum fr_block_storage { FR_BLOCK_CHOSEN = 0, FR_BLOCK_SPARSE, FR_BLOCK_DENSE };

/* The fill rule: dense where CHOLMOD's factor of W in its AMD order would hold at least half the
 * entries of a dense triangle, nnz(L) >= m (m + 1) / 4. Then the simplicial factor does at
 * least 3/16 of a dense one's m^3 / 3 flops (sum_j c_j^2 >= (sum_j c_j)^2 / m, c_j L's column
 * counts), without the BLAS and on all of W whatever the block, while dpotrf works on W_SS
 * alone. */
#define FR_BLOCK_DENSE_FILL 0.5

struct fr_masked_factor {
    size_t m;
    int dense;              /* the blocks in D by LAPACK, not in A, L by CHOLMOD */
    cholmod_sparse *A;      /* P W P^T's upper triangle, its values filled per solve */
    SuiteSparse_long *src;  /* [nnz(A)] entry of A -> its entry of W */
    SuiteSparse_long *perm; /* [m] row k of P W P^T is row perm[k] of W */
    cholmod_factor *L;
    cholmod_dense *X, *Yw, *Ew;
    double *b; /* [m] */
    /* Dense: W_SS + diag(shift_S) in the factor's row order, then its upper factor U
     * (W_SS = U^T U), column-major with leading dimension m, of order rows. */
    double *D;              /* [m * m] */
    SuiteSparse_long *at;   /* [m] row i of W is row at[i] of the factor, -1 outside S */
    SuiteSparse_long *rows; /* [m] row r of the factor is row rows[r] of W */
    size_t order;           /* |S| of the factor */
    size_t kept;            /* the leading rows the last factorization kept (below) */
    size_t deleted;         /* the held rows it deleted to keep those after them (below) */
    double *qr_work;        /* [2 * 128 * m] dtpqrt's T and work (its block at most 128) */
    /* The Schur complement, before their shifts, of the rows the last factorization factored
     * (from schur_from on) given the rows before them: a block of the same rows whose shifts
     * alone changed there is factored from it (below). Its strict upper triangle is kept
     * transposed in D's strictly lower part, its diagonal here. */
    size_t schur_from;
    double *schur_diag; /* [m] */
    /* Dense: the other factor held (above), its fields as the current one's, swapped with them
     * (fr_masked_factor_swap); spare_kept: it is the one kept when a block replaces the
     * current one. from_spare: the last factorization started from it. */
    struct fr_spare_factor {
        double *D, *schur_diag, *held_shift;
        SuiteSparse_long *rows;
        unsigned char *held_set;
        size_t order, schur_from;
        int held;
    } spare;
    int spare_kept, from_spare;
    /* The block and shifts of the last factorization: a solve on the same ones reuses it
     * (a stick set that holds from one Newton iteration, or one step, to the next). */
    unsigned char *held_set; /* [m] */
    double *held_shift;      /* [m] */
    int held;
};

/* Ready for blocks of W (m x m, upper triangle, sorted) in the storage asked (FR_BLOCK_CHOSEN:
 * by the fill rule, FR_BLOCK_DENSE_FILL): sparse, ordered, permuted, analysed, and one solve
 * made to size the workspaces; dense, the buffer allocated. f must be zeroed or freed.
 * FRICREG_OK or FRICREG_ENOMEM (f then freed). */
int fr_masked_factor_prepare(struct fr_masked_factor *f, const cholmod_sparse *W,
                             enum fr_block_storage storage, cholmod_common *c);

void fr_masked_factor_free(struct fr_masked_factor *f, cholmod_common *c);

/* x_S = (W_SS + diag(shift_S))^-1 b_S for S the entries marked in set[m] (set NULL: none;
 * shift NULL: no shift); x elsewhere untouched. W must have the pattern it was prepared with. FRICREG_OK;
 * FRICREG_ESINGULAR (the block is not positive definite); FRICREG_ENOMEM. */
int fr_masked_factor_solve(struct fr_masked_factor *f, const cholmod_sparse *W,
                           const unsigned char *set, const double *shift, const double b[],
                           double x[], cholmod_common *c);

/* The dense factor held and the spare exchanged (blocks_carried.c saves and restores both). */
void fr_masked_factor_swap(struct fr_masked_factor *f);

#endif
