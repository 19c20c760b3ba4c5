/* SPDX-License-Identifier: GPL-3.0-or-later */
/* matrix_input.h — internal: a matrix as a caller gives it (dense row-major, compressed sparse
 * rows or columns as fricreg.h's enum fricreg_sparse_flags describes, or entry by entry),
 * checked and turned into CHOLMOD's compressed columns: sorted, duplicates summed, and a
 * symmetric matrix as the upper triangle (stype 1) of its symmetric part (A + A^T)/2. */
#ifndef FRICREG_MATRIX_INPUT_H
#define FRICREG_MATRIX_INPUT_H

#include <stddef.h>
#include <stdint.h>

#include <cholmod.h>

#include "base/error.h"

/* A compressed sparse matrix as a _csr or _csc setter receives it. */
struct fr_compressed {
    size_t nrows, ncols;
    int by_columns; /* CSC: ptr runs over the columns and ind holds rows; CSR: the converse */
    int flags;      /* enum fricreg_sparse_flags */
    const int64_t *ptr, *ind;
    const double *val;
};

/* The storage a one-setter format asks for (fricreg.h's enum fricreg_matrix_format, the
 * compressed ones OR'ed with enum fricreg_sparse_flags): *compressed (else dense), *by_columns
 * (CSC, else CSR) and the sparse *flags, which fr_compressed_check judges. FRICREG_OK;
 * FRICREG_EINVAL (both CSR and CSC, or flags with a dense matrix), recorded in err after who. */
int fr_matrix_format(int format, int *compressed, int *by_columns, int *flags, struct fr_error *err,
                     const char *who);

/* Checks a's arrays; symmetric says whether the matrix must be symmetric (then square; the
 * triangle flags are allowed). FRICREG_OK; FRICREG_ENULL (ptr, or ind or val while nnz > 0);
 * FRICREG_EINVAL (unknown flags, both triangles, a triangle for a matrix that need not be
 * symmetric, ptr[0] not the base, ptr decreasing, an index out of range, an entry in the
 * triangle that was left out); FRICREG_ENONFINITE. The message, recorded in err, starts with
 * who and names the array and the entry. */
int fr_compressed_check(const struct fr_compressed *a, int symmetric, struct fr_error *err,
                        const char *who);

/* The checked a in CHOLMOD's form, into *out (the caller's to free with cholmod_l_free_sparse):
 * nrows x ncols, unsymmetric (stype 0), or when symmetric the upper triangle of the
 * symmetric part. FRICREG_OK; FRICREG_ENOTSYM (given whole, entries (i, j) and (j, i) differ
 * by more than 1e-12 sqrt(r_i r_j), r_i = max_k |A_ik| the scale of row i: a change of units
 * of a degree of freedom does not change the verdict); FRICREG_ENOMEM. */
int fr_compressed_to_cholmod(const struct fr_compressed *a, int symmetric, cholmod_common *c,
                             cholmod_sparse **out, struct fr_error *err, const char *who);

/* A dense row-major nrows x ncols matrix A, finite, as the same: its non-zero entries, and
 * when symmetric (square) checked and halved as above. FRICREG_OK; FRICREG_ENONFINITE
 * (unchecked entries are the caller's to check first: none is read twice);
 * FRICREG_ENOTSYM; FRICREG_ENOMEM. */
int fr_dense_to_cholmod(size_t nrows, size_t ncols, const double A[], int symmetric,
                        cholmod_common *c, cholmod_sparse **out, struct fr_error *err,
                        const char *who);

/* Entry by entry (a GSL sparse matrix's): a triplet matrix T of nrows x ncols with room for
 * nnz entries, filled by the caller (T->i, T->j, T->x, T->nnz), then finished as above
 * (symmetric: given whole, or by one triangle when triangle is set, its entries moved to the
 * upper one). fr_triplet_finish frees T. */
cholmod_triplet *fr_triplet_new(size_t nrows, size_t ncols, size_t nnz, cholmod_common *c);
int fr_triplet_finish(cholmod_triplet *T, int symmetric, int triangle, cholmod_common *c,
                      cholmod_sparse **out, struct fr_error *err, const char *who);

#endif
