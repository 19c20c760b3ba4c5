/* SPDX-License-Identifier: GPL-3.0-or-later */
/* contact_sparse.h — internal: the near-stick block's solve in the structure's own space, the
 * sparse twin of masked_factor.h for fricreg_structure's Newmark steps
 * (FRICREG_CONTACT_SOLVER_SPARSE).
 *
 * The block (newton_matrix.h) is, on the rows N of the direction or the stick guess,
 *   (W_eff,NN + diag(shift_N)) y_N = b_N,   W_eff = J K_eff^-1 J^T,
 * dense on a stiff continuum. With T = diag(1 / s~_N), s~_i > 0, Woodbury's identity gives
 *   (J_N K_eff^-1 J_N^T + diag(s~))^-1 r = T (r - J_N (K_eff + J_N^T T J_N)^-1 J_N^T T r),
 * one sparse factor of the n x n matrix K_eff + J^T T J (T = 0 off N), whose pattern is that
 * of K_eff + J^T J for every N and T: it is ordered and analysed once per K_eff, and refactored
 * numerically only when N changes, or the shifts change so much that the held factor, used as
 * a chord, no longer converges within a few refinements (below). s~_i is the
 * shift where it is positive, 1/(c |s_i|) of the law's slope; on the rows that have none (the
 * consistent law's free contacts, the stick guess: a constraint on J_i x) it is a regularizing
 * RHO W_eff,ii, and the solve is refined against the exact block, iterative refinement with
 * the product W_eff y in O(nnz(W_eff)): each refinement divides the error by about
 * 1 / RHO (the regularization) and it carries rounding of u / RHO (the cancellation in
 * r - J_N (...)), so that RHO = sqrt(u) takes the error to rounding in two or three. The
 * answer is then the dense block's, whose matrix the refinement reads. */
#ifndef FRICREG_CONTACT_SPARSE_H
#define FRICREG_CONTACT_SPARSE_H

#include <stddef.h>

#include <cholmod.h>

struct fr_contact_sparse {
    size_t n, m;
    const cholmod_sparse *Jt; /* n x m, the structure's J^T (not owned) */
    cholmod_sparse *A;        /* P (K_eff + J^T T J) P^T in natural order, its upper triangle
                                 (CHOLMOD's simplicial factor works on it in place) */
    double *base;             /* [nnz(A)] K_eff's values in A's layout */
    SuiteSparse_long *pptr;   /* [m + 1] contact i's products J_ai J_bi: pos/val[pptr[i]..] */
    SuiteSparse_long *pos;    /* A's entry of each product */
    double *val;              /* the products */
    SuiteSparse_long *perm;   /* [n] row k of P x is x[perm[k]] */
    cholmod_factor *L;
    cholmod_dense *X, *Yw, *Ew;
    double flops;            /* CHOLMOD's flop count of one factorization (Common->fl) */
    double *t;               /* [m] T of the factored matrix (0 off N) */
    double *y, *res, *dy;    /* [m] the answer, its residual, its correction */
    double *u, *e;           /* [m] woodbury's T r and J w */
    double *v, *w, *pv;      /* [n] J^T T r, the solve's answer, P v */
    unsigned char *held_set; /* [m] the block and shifts of the last factorization */
    double *held_shift;      /* [m] */
    int held;
};

/* Ready for the blocks of Keff (n x n, stype 1, the upper triangle) and Jt (n x m): ordered
 * (nested dissection from FR_CFACTOR_NESTED_FROM, else AMD), permuted, analysed, factored
 * once with T = 0 and solved once, so that later factorizations and solves reuse CHOLMOD's
 * storage. f must be zeroed or freed. FRICREG_OK or FRICREG_ENOMEM (f then freed). */
int fr_contact_sparse_prepare(struct fr_contact_sparse *f, const cholmod_sparse *Keff,
                              const cholmod_sparse *Jt, cholmod_common *c);

void fr_contact_sparse_free(struct fr_contact_sparse *f, cholmod_common *c);

/* x_N = (W_eff,NN + diag(shift_N))^-1 b_N, N the rows marked in set[m] (shift NULL: none),
 * Weff = J K_eff^-1 J^T (m x m, upper, sorted; the refinement's matrix), x elsewhere
 * untouched: masked_factor.h's fr_masked_factor_solve. FRICREG_OK; FRICREG_ESINGULAR (the
 * block is not positive definite: the refinement does not converge, or a diagonal entry of N
 * is not positive); FRICREG_ENOMEM. */
int fr_contact_sparse_solve(struct fr_contact_sparse *f, const cholmod_sparse *Weff,
                            const unsigned char *set, const double *shift, const double b[],
                            double x[], cholmod_common *c);

/* The block of set and shift (as above) factored and held, as a solve on them would leave it,
 * so that the next solves continue from that factor (a checkpoint's restore: blocks_carried.h).
 * set and shift may be f->held_set and f->held_shift. FRICREG_OK; FRICREG_ESINGULAR (a row
 * without a shift has no positive W_eff,ii, or the matrix is not positive definite);
 * FRICREG_ENOMEM; on failure no block is held. */
int fr_contact_sparse_hold(struct fr_contact_sparse *f, const cholmod_sparse *Weff,
                           const unsigned char *set, const double *shift, cholmod_common *c);

#endif
