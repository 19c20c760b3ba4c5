/* SPDX-License-Identifier: GPL-3.0-or-later */
/* sparse_ops.c — products with CHOLMOD's compressed columns (sparse_ops.h). */
#include "sparse_ops.h"

/* Column j of the upper triangle S times alpha x into out: the entries above the diagonal go
 * to out[i], i < j (set already); the column's own sum is returned. */
static double column_times(const cholmod_sparse *S, size_t j, double alpha, const double x[],
                           double out[])
{
    const SuiteSparse_long *Sp = S->p, *Si = S->i;
    const double *Sx = S->x;
    double xj = alpha * x[j], sum = 0.0;
    for (SuiteSparse_long p = Sp[j]; p < Sp[j + 1]; p++) {
        size_t i = (size_t)Si[p];
        if (i == j) {
            sum += Sx[p] * x[j];
        } else {
            out[i] += Sx[p] * xj;
            sum += Sx[p] * x[i];
        }
    }
    return alpha * sum;
}

void fr_sym_mult(const cholmod_sparse *S, double alpha, const double x[], double beta, double y[])
{
    for (size_t j = 0; j < S->ncol; j++) {
        /* y[j] is reached first here (later columns add above it): scale it now */
        y[j] = beta == 0.0 ? 0.0 : beta * y[j];
        y[j] += column_times(S, j, alpha, x, y);
    }
}

void fr_sym_mult_pair(const double y0[], const cholmod_sparse *A, double alpha, const double x[],
                      const cholmod_sparse *B, double beta, const double z[], double out[])
{
    for (size_t j = 0; j < A->ncol; j++) {
        out[j] = y0[j]; /* column j is the first to reach out[j]: later ones add above it */
        out[j] += column_times(A, j, alpha, x, out);
        out[j] += column_times(B, j, beta, z, out);
    }
}

void fr_sym_mult_combined(const double y0[], const cholmod_sparse *S, double alpha,
                          const double x[], double beta, const double z[], double out[])
{
    const SuiteSparse_long *Sp = S->p, *Si = S->i;
    const double *Sx = S->x;
    for (size_t j = 0; j < S->ncol; j++) {
        double wj = alpha * x[j] + beta * z[j], sum = 0.0;
        out[j] = y0[j]; /* column j is the first to reach out[j]: later ones add above it */
        for (SuiteSparse_long p = Sp[j]; p < Sp[j + 1]; p++) {
            size_t i = (size_t)Si[p];
            if (i != j)
                out[i] += Sx[p] * wj;
            sum += Sx[p] * (alpha * x[i] + beta * z[i]);
        }
        out[j] += sum;
    }
}

double fr_sym_bilinear(const cholmod_sparse *S, const double x[], const double y[])
{
    const SuiteSparse_long *Sp = S->p, *Si = S->i;
    const double *Sx = S->x;
    double sum = 0.0;
    for (size_t j = 0; j < S->ncol; j++)
        for (SuiteSparse_long p = Sp[j]; p < Sp[j + 1]; p++) {
            size_t i = (size_t)Si[p];
            sum += Sx[p] * (i == j ? x[j] * y[j] : x[i] * y[j] + x[j] * y[i]);
        }
    return sum;
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

SuiteSparse_long fr_csc_position(const cholmod_sparse *A, SuiteSparse_long i, SuiteSparse_long j)
{
    const SuiteSparse_long *Ap = A->p, *Ai = A->i;
    SuiteSparse_long lo = Ap[j], hi = Ap[j + 1];
    while (lo < hi) {
        SuiteSparse_long mid = lo + (hi - lo) / 2;
        if (Ai[mid] < i)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < Ap[j + 1] && Ai[lo] == i ? lo : -1;
}

double fr_csc_entry(const cholmod_sparse *A, SuiteSparse_long i, SuiteSparse_long j)
{
    SuiteSparse_long at = fr_csc_position(A, i, j);
    return at < 0 ? 0.0 : ((const double *)A->x)[at];
}
