/* SPDX-License-Identifier: GPL-3.0-or-later */
/* sparse.h — internal: the sparse model: KLU's factors of the dynamic stiffnesses, the compressed setters (sparse.c). */
#ifndef FRICREG_HB_SPARSE_H
#define FRICREG_HB_SPARSE_H

#include "hb_internal.h"

/* Factors the sparse D_h at omega (its values formed from vM, vC, vK) and solves for Y_h's
 * columns, the factor then freed. FRICREG_OK, FRICREG_ESINGULAR, FRICREG_ENONFINITE,
 * FRICREG_ENOMEM (message recorded, with fn). */
int fr_hb_sparse_solve(fricreg_hb *hb, const char *fn, int h, double omega);

/* KLU's estimate of the 1-norm condition number of D_h at omega (klu_condest: Hager's and
 * Higham's estimator, a few solves with the factor) into *kappa, from the factor that
 * fr_hb_sparse_solve left at omega, or a fresh one where it was freed. FRICREG_OK,
 * FRICREG_ESINGULAR, FRICREG_ENOMEM (message recorded, with fn). */
int fr_hb_sparse_condition(fricreg_hb *hb, const char *fn, int h, double omega, double *kappa);

/* D_h(omega)^-1 B in place for nrhs complex right-hand sides B[nrhs n] (each contiguous, KLU's
 * layout), from the factor kept at omega or a fresh one (freed after as fr_hb_sparse_solve's).
 * Statuses as fr_hb_sparse_solve's. */
int fr_hb_sparse_solve_many(fricreg_hb *hb, const char *fn, int h, double omega, size_t nrhs,
                            double *B);

/* z [n] = D_h' y [n] (complex) on the sparse pattern, D_h' = −2 h² Ω M + i h C. */
void fr_hb_sparse_derivative(fricreg_hb *hb, int h, double omega, const double *y, double *z);

/* Switches a dense driver to the sparse model (its M, C, K converted) and sets the model's
 * defaults for a sparse-only one; frees the sparse state. */
int fr_hb_sparse_defaults(fricreg_hb *hb);
void fr_hb_sparse_free(fricreg_hb *hb);
/* Frees the harmonics' LU factors (kept from one frequency to the next within a solving call),
 * so that a call's results do not depend on the pivots of the calls before it. */
void fr_hb_sparse_release(fricreg_hb *hb);

/* dst's model becomes a copy of the sparse src's M, C, K (dst turned sparse): FRICREG_OK or
 * FRICREG_ENOMEM, dst's model unchanged then. */
int fr_hb_sparse_copy(fricreg_hb *dst, const fricreg_hb *src);

/* The dense setters' path on a sparse model: the checked, symmetric dense A installed as
 * matrix which (0 M, 1 C, 2 K). */
int fr_hb_sparse_set_dense(fricreg_hb *hb, const char *fn, int which, const double *A);
/* A model matrix (which: 0 M, 1 C, 2 K) from compressed sparse columns (by_columns) or rows,
 * with enum fricreg_sparse_flags; C replaces Rayleigh's. The checks and results of
 * fricreg_hb_set_mass_csc, whose messages name fn. */
int fr_hb_set_compressed(fricreg_hb *hb, const char *fn, int which, size_t ndof, int by_columns,
                         int flags, const int64_t ptr[], const int64_t ind[],
                         const double values[]);

#endif
