/* SPDX-License-Identifier: GPL-3.0-or-later */
/* sparse_ops.c — products with CHOLMOD's compressed columns (sparse_ops.h). */
#include "sparse_ops.h"

void fr_sym_mult(const cholmod_sparse *S, double alpha, const double x[], double beta, double y[])
{
    const SuiteSparse_long *Sp = S->p, *Si = S->i;
    const double *Sx = S->x;
    size_t n = S->ncol;
    for (size_t k = 0; k < n; k++)
        y[k] = beta == 0.0 ? 0.0 : beta * y[k];
    for (size_t j = 0; j < n; j++) {
        double xj = alpha * x[j], sum = 0.0;
        for (SuiteSparse_long p = Sp[j]; p < Sp[j + 1]; p++) {
            size_t i = (size_t)Si[p];
            if (i == j) {
                sum += Sx[p] * x[j];
            } else {
                y[i] += Sx[p] * xj;  /* S_ij x_j, i < j */
                sum += Sx[p] * x[i]; /* S_ji x_i */
            }
        }
        y[j] += alpha * sum;
    }
}

void fr_csc_mult_t(const cholmod_sparse *A, const double x[], double y[])
{
    const SuiteSparse_long *Ap = A->p, *Ai = A->i;
    const double *Ax = A->x;
    for (size_t j = 0; j < A->ncol; j++) {
        double sum = 0.0;
        for (SuiteSparse_long p = Ap[j]; p < Ap[j + 1]; p++)
            sum += Ax[p] * x[Ai[p]];
        y[j] = sum;
    }
}

void fr_csc_mult_add(const cholmod_sparse *A, double alpha, const double x[], double y[])
{
    const SuiteSparse_long *Ap = A->p, *Ai = A->i;
    const double *Ax = A->x;
    for (size_t j = 0; j < A->ncol; j++) {
        double xj = alpha * x[j];
        if (xj != 0.0)
            for (SuiteSparse_long p = Ap[j]; p < Ap[j + 1]; p++)
                y[Ai[p]] += Ax[p] * xj;
    }
}
