/* SPDX-License-Identifier: GPL-3.0-or-later */
/* sparse_ops.h — internal: products with CHOLMOD's compressed columns that allocate nothing and
 * read the matrix as const (CHOLMOD's own cholmod_l_sdmult takes neither promise). */
#ifndef FRICREG_SPARSE_OPS_H
#define FRICREG_SPARSE_OPS_H

#include <cholmod.h>

/* y[n] = alpha S x[n] + beta y[n] for a symmetric S stored as its upper triangle (stype 1).
 * x and y must not overlap. beta = 0 ignores y's old values (a NaN there included). */
void fr_sym_mult(const cholmod_sparse *S, double alpha, const double x[], double beta, double y[]);

/* y[ncol] = A^T x[nrow] (A unsymmetric): column j's dot product with x. */
void fr_csc_mult_t(const cholmod_sparse *A, const double x[], double y[]);

/* y[nrow] += alpha A x[ncol] (A unsymmetric). */
void fr_csc_mult_add(const cholmod_sparse *A, double alpha, const double x[], double y[]);

#endif
