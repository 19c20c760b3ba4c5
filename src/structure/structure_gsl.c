/* SPDX-License-Identifier: GPL-3.0-or-later */
/* structure_gsl.c — the setters of fricreg_structure_gsl.h: a GSL sparse matrix (COO, CSC or
 * CSR) read entry by entry into CHOLMOD's triplets, then the road of every model matrix
 * (model.c, src/base/matrix_input.h). Never dense. */
#include <math.h>
#include <stddef.h>

#include <gsl/gsl_spmatrix.h>

#include "base/matrix_input.h"
#include "fricreg_structure_gsl.h"
#include "structure_internal.h"

/* Entry k of S (stored position k) into (row, col). */
static void position(const gsl_spmatrix *S, size_t k, size_t *row, size_t *col)
{
    if (S->sptype == GSL_SPMATRIX_COO) {
        *row = (size_t)S->i[k];
        *col = (size_t)S->p[k];
        return;
    }
    /* Compressed: the outer index of position k, by bisection on the pointers. */
    size_t outer = S->sptype == GSL_SPMATRIX_CSC ? S->size2 : S->size1, lo = 0, hi = outer;
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if ((size_t)S->p[mid] <= k)
            lo = mid;
        else
            hi = mid;
    }
    *row = S->sptype == GSL_SPMATRIX_CSC ? (size_t)S->i[k] : lo;
    *col = S->sptype == GSL_SPMATRIX_CSC ? lo : (size_t)S->i[k];
}

/* S (nrows x ncols, as the structure needs) checked and installed as matrix `which`. */
static int set_sparse(fricreg_structure *s, int which, const char *who, const gsl_spmatrix *S,
                      size_t nrows, size_t ncols)
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, who);
    if (S == NULL)
        return fr_fail(s, FRICREG_ENULL, "%s: the matrix is NULL", who);
    if (S->size1 != nrows || S->size2 != ncols)
        return fr_fail(s, FRICREG_ESIZE,
                       "%s: the matrix is %zu x %zu, the structure needs %zu x %zu", who, S->size1,
                       S->size2, nrows, ncols);
    if (S->sptype != GSL_SPMATRIX_COO && S->sptype != GSL_SPMATRIX_CSC &&
        S->sptype != GSL_SPMATRIX_CSR)
        return fr_fail(s, FRICREG_EINVAL, "%s: unknown storage type %d (GSL has COO, CSC and CSR)",
                       who, S->sptype);
    size_t nnz = S->nz;
    for (size_t k = 0; k < nnz; k++)
        if (!isfinite(S->data[k])) {
            size_t row, col;
            position(S, k, &row, &col);
            return fr_fail(s, FRICREG_ENONFINITE, "%s: entry (%zu, %zu) is not finite", who, row,
                           col);
        }
    cholmod_triplet *T = fr_triplet_new(nrows, ncols, nnz, &s->cc);
    if (T == NULL)
        return fr_fail(s, FRICREG_ENOMEM, "%s: no memory for the sparse matrix", who);
    SuiteSparse_long *Ti = T->i, *Tj = T->j;
    double *Tx = T->x;
    for (size_t k = 0; k < nnz; k++) {
        size_t row, col;
        position(S, k, &row, &col);
        Ti[k] = (SuiteSparse_long)row;
        Tj[k] = (SuiteSparse_long)col;
        Tx[k] = S->data[k];
    }
    T->nnz = nnz;
    cholmod_sparse *A = NULL;
    int status = fr_triplet_finish(T, which != FR_CONTACTS, 0, &s->cc, &A, &s->err, who);
    return status != FRICREG_OK ? status : fr_structure_install(s, which, A, who);
}

int fricreg_structure_set_mass_sparse(fricreg_structure *s, const gsl_spmatrix *M)
{
    return set_sparse(s, FR_MASS, "set_mass_sparse", M, s ? s->n : 0, s ? s->n : 0);
}

int fricreg_structure_set_stiffness_sparse(fricreg_structure *s, const gsl_spmatrix *K)
{
    return set_sparse(s, FR_STIFFNESS, "set_stiffness_sparse", K, s ? s->n : 0, s ? s->n : 0);
}

int fricreg_structure_set_damping_sparse(fricreg_structure *s, const gsl_spmatrix *C)
{
    return set_sparse(s, FR_DAMPING, "set_damping_sparse", C, s ? s->n : 0, s ? s->n : 0);
}

int fricreg_structure_set_contacts_sparse(fricreg_structure *s, const gsl_spmatrix *J)
{
    return set_sparse(s, FR_CONTACTS, "set_contacts_sparse", J, s ? s->m : 0, s ? s->n : 0);
}
