/* SPDX-License-Identifier: GPL-3.0-or-later */
/* delassus_runs.h — internal: products with a packed W_eff (contact_factor.h's
 * fr_delassus_packed) restricted to some of its rows and columns, each set given as runs of
 * consecutive contacts.
 *
 * Why: inside a step's Newton most contacts stick, and the solve of the near-stick block N
 * already gives (W_eff df)_N (newton_matrix.h); only the other rows, R, need a product, and
 * W_eff,RN df_N reads |R| |N| entries, not the m^2 / 2 of the whole triangle. The contacts that
 * slip together are neighbours (a row of an interface), so R is a few runs and each run of a
 * column is one contiguous BLAS ddot or daxpy. */
#ifndef FRICREG_DELASSUS_RUNS_H
#define FRICREG_DELASSUS_RUNS_H

#include <stddef.h>

#include <cholmod.h>

/* The runs of the i in [0, m) with (mask[i] != 0) == on, as half-open intervals
 * [runs[2 r], runs[2 r + 1]), r < the count returned (at most (m + 1) / 2); runs holds
 * m + 1 entries. Their total length into *members. */
size_t fr_runs_of(const unsigned char mask[], int on, size_t m, size_t runs[], size_t *members);

/* y_i = sum over j in the column runs of D_ij x_j, for every i in the row runs (y's other
 * entries are not written, x's outside the column runs not read). D m x m, packed
 * (fr_delassus_packed). Only entries of D with one index in each set are read (once, or
 * twice where both indices are in both sets): about |rows| |cols| reads against dspmv's
 * m (m + 1) / 2, plus a BLAS call per run of a column. */
void fr_delassus_mult_runs(const cholmod_sparse *D, const size_t col_runs[], size_t ncol_runs,
                           const double x[], const size_t row_runs[], size_t nrow_runs, double y[]);

/* Whether fr_delassus_mult_runs on these sets is the cheaper product: D packed, and its
 * |rows| |cols| multiply-adds (each run counted as m more, its calls) below half of dspmv's
 * m^2 (a ddot and a daxpy over each column). Measured at m = 2528: 316 rows in one run take
 * 0.12-0.23 ms against dspmv's 1.5 ms (OpenBLAS), 0.29 against 3.3 (the reference BLAS). */
int fr_delassus_runs_cheaper(const cholmod_sparse *D, size_t rows, size_t nrow_runs, size_t cols,
                             size_t ncol_runs);

#endif
