/* SPDX-License-Identifier: GPL-3.0-or-later */
/* contact_factor.h — internal: a symmetric positive definite n x n matrix A (the mass matrix M,
 * or Newmark's K_eff = M + w (gamma dt C + beta dt^2 K)) factored by CHOLMOD,
 * P A P^T = L L^T, with the contacts seen through it:
 *
 *   Y = L^-1 P J^T  (n x m, sparse),   D = Y^T Y = J A^-1 J^T  (m x m),
 *
 * so that J A^-1 b = Y^T (L^-1 P b) and A^-1 (b + J^T g) = P^T L^-T (L^-1 P b + Y g): with
 * A = M, D is the Delassus matrix W; with A = K_eff, the contacts' compliance over a step.
 * A solve with contact forces is a forward half, the forces added through Y, and a backward
 * half: one solve's cost, however the forces were found between the halves.
 *
 * Y is sparse when the ordering keeps the elimination tree shallow: column i holds the rows
 * reachable from contact i's degrees of freedom, its path to the root. A nested-dissection
 * ordering (METIS) makes that path O(log n) supernodes long on a banded or mesh-like A, where a
 * minimum-degree ordering of a chain leaves it n long (Y dense); fr_cfactor_build takes
 * nested dissection for large A (FR_CFACTOR_NESTED_FROM). */
#ifndef FRICREG_CONTACT_FACTOR_H
#define FRICREG_CONTACT_FACTOR_H

#include <stddef.h>

#include <cholmod.h>

#include "base/error.h"

/* From this order on A is ordered by nested dissection, below by minimum degree (AMD). */
#define FR_CFACTOR_NESTED_FROM 4096

struct fr_cfactor {
    size_t n, m;
    cholmod_factor *L;
    SuiteSparse_long *perm;   /* [n] P: row k of P b is b[perm[k]] (NULL: identity) */
    cholmod_sparse *Y;        /* n x m, each column sorted; freed once D is formed where the
                             * products go through triangular solves (by_solves) */
    const cholmod_sparse *Jt; /* n x m, the caller's J^T (kept for by_solves) */
    int by_solves;            /* Y's products as triangular solves with J: nnz(Y) > nnz(L) + n */
    cholmod_sparse *D;        /* m x m, the upper triangle (stype 1) of Y^T Y, sorted; whole
                             * (fr_delassus_packed) where it at least half fills */
    size_t shared_rows;       /* rows of Y whose part of D went through BLAS (contact_factor.c) */
    /* Solve scratch, sized at build so that a solve never allocates. */
    cholmod_dense *X, *Ywork, *Ework;
    double *pb, *work; /* [n] */
};

/* Factors A (n x n, stype 1, the upper triangle) and forms Y and D for the contacts Jt
 * (n x m, J^T: column i is contact i's row of J). drop > 0 leaves out of D the entries below
 * drop sqrt(D_ii D_jj) / m (0: D exact): those of a row then sum to less than drop times its
 * diagonal's scale, so that with drop = 2^-53 D f differs from Y^T (Y f) by rounding. f must be zeroed or freed; on failure it is left freed.
 * FRICREG_OK; FRICREG_ENOTPSD (A not positive definite: *minor its first column without a
 * pivot); FRICREG_ENOMEM; the error recorded in err, led by who and naming the matrix. */
int fr_cfactor_build(struct fr_cfactor *f, cholmod_sparse *A, cholmod_sparse *Jt, double drop,
                     cholmod_common *c, struct fr_error *err, const char *who, const char *name);

void fr_cfactor_free(struct fr_cfactor *f, cholmod_common *c);

/* y[n] = L^-1 P b[n] (b and y may be the same array). */
void fr_cfactor_forward(struct fr_cfactor *f, const double b[], double y[], cholmod_common *c);

/* x[n] = P^T L^-T y[n] (y and x may be the same array). */
void fr_cfactor_backward(struct fr_cfactor *f, const double y[], double x[], cholmod_common *c);

/* x[n] = A^-1 b[n]: both halves. */
void fr_cfactor_solve(struct fr_cfactor *f, const double b[], double x[], cholmod_common *c);

/* out[m] = Y^T y[n]: J A^-1 b for y = L^-1 P b. Through Y's columns, O(nnz(Y)), or, where
 * Y has more entries than L (contacts everywhere: each column of Y fills the path to the root
 * of the elimination tree), a backward solve and a product with J, O(nnz(L) + nnz(J)). */
void fr_cfactor_project(struct fr_cfactor *f, const double y[], double out[], cholmod_common *c);

/* y[n] += alpha Y g[m]: through Y's columns, or as project's, a product with J^T and a
 * forward solve. */
void fr_cfactor_lift(struct fr_cfactor *f, double alpha, const double g[], double y[],
                     cholmod_common *c);

/* out[m] = D g[m], O(nnz(D)): fr_delassus_mult. */
void fr_cfactor_compliance(const struct fr_cfactor *f, const double g[], double out[]);

/* Whether D (m x m, CHOLMOD's upper triangle, sorted) holds every entry of that triangle, as
 * fr_cfactor_build stores a D that at least half fills: D->x is then LAPACK's packed upper
 * storage (column j's rows 0..j in order). */
int fr_delassus_packed(const cholmod_sparse *D);

/* y[m] = alpha D x[m] + beta y[m] (beta 0: y's old values unread) for D as above: BLAS's
 * dspmv where D is packed (one pass over m(m+1)/2 values, no indices), fr_sym_mult
 * otherwise; the two agree to rounding. */
void fr_delassus_mult(const cholmod_sparse *D, double alpha, const double x[], double beta,
                      double y[]);

#endif
