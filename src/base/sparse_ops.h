/* SPDX-License-Identifier: GPL-3.0-or-later */
/* sparse_ops.h — internal: products with CHOLMOD's compressed columns that allocate nothing and
 * read the matrix as const (CHOLMOD's own cholmod_l_sdmult takes neither promise). */
#ifndef FRICREG_SPARSE_OPS_H
#define FRICREG_SPARSE_OPS_H

#include <cholmod.h>

/* y[n] = alpha S x[n] + beta y[n] for a symmetric S stored as its upper triangle (stype 1).
 * x and y must not overlap. beta = 0 ignores y's old values (a NaN there included). */
void fr_sym_mult(const cholmod_sparse *S, double alpha, const double x[], double beta, double y[]);

/* out[n] = y0[n] + alpha A x[n] + beta B z[n] for symmetric A and B stored as their upper
 * triangles, in one pass over both (out must not overlap the inputs). */
void fr_sym_mult_pair(const double y0[], const cholmod_sparse *A, double alpha, const double x[],
                      const cholmod_sparse *B, double beta, const double z[], double out[]);

/* out[n] = y0[n] + S (alpha x[n] + beta z[n]) for a symmetric S stored as its upper triangle,
 * in one pass over S (out must not overlap the inputs): Rayleigh's C v + K u = K (u + a1 v) +
 * a0 M v with one product with K. */
void fr_sym_mult_combined(const double y0[], const cholmod_sparse *S, double alpha,
                          const double x[], double beta, const double z[], double out[]);

/* x^T S y for a symmetric S stored as its upper triangle: one pass over S, no scratch. */
double fr_sym_bilinear(const cholmod_sparse *S, const double x[], const double y[]);

/* y[ncol] = A^T x[nrow] (A unsymmetric): column j's dot product with x. */
void fr_csc_mult_t(const cholmod_sparse *A, const double x[], double y[]);

/* y[nrow] += alpha A x[ncol] (A unsymmetric). */
void fr_csc_mult_add(const cholmod_sparse *A, double alpha, const double x[], double y[]);

/* The position of entry (i, j) in A's column j, whose row indices are sorted (by bisection),
 * or -1 if the column holds no row i. */
SuiteSparse_long fr_csc_position(const cholmod_sparse *A, SuiteSparse_long i, SuiteSparse_long j);

/* Entry (i, j) of A, whose columns' row indices are sorted: 0 if absent. */
double fr_csc_entry(const cholmod_sparse *A, SuiteSparse_long i, SuiteSparse_long j);

#endif
