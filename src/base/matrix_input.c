/* SPDX-License-Identifier: GPL-3.0-or-later */
/* matrix_input.c — a caller's matrix into CHOLMOD's compressed columns (matrix_input.h). Every
 * form goes through a triplet matrix, whose conversion (cholmod_l_triplet_to_sparse) sorts the
 * columns and sums duplicates. */
#include <math.h>
#include <string.h>

#include "fricreg.h"
#include "matrix_input.h"
#include "sparse_factor.h"
#include "sparse_ops.h"

#define SYMMETRY_RTOL 1e-12
#define KNOWN_FLAGS (FRICREG_SPARSE_ONE_BASED | FRICREG_SPARSE_UPPER | FRICREG_SPARSE_LOWER)

static int cholmod_failed(cholmod_common *c, struct fr_error *err, const char *who)
{
    int status = fr_cholmod_status(c->status);
    if (status == FRICREG_OK)
        status = FRICREG_ENOMEM; /* a NULL result with a warning: out of memory all the same */
    return fr_error_set(err, status, "%s: no memory for the sparse matrix", who);
}

/* ---- Checks of compressed arrays ----------------------------------------------------------- */

static int check_flags(const struct fr_compressed *a, int symmetric, struct fr_error *err,
                       const char *who)
{
    int tri = a->flags & (FRICREG_SPARSE_UPPER | FRICREG_SPARSE_LOWER);
    if (a->flags & ~KNOWN_FLAGS)
        return fr_error_set(err, FRICREG_EINVAL, "%s: unknown flags 0x%x", who, (unsigned)a->flags);
    if (tri == (FRICREG_SPARSE_UPPER | FRICREG_SPARSE_LOWER))
        return fr_error_set(err, FRICREG_EINVAL,
                            "%s: FRICREG_SPARSE_UPPER and FRICREG_SPARSE_LOWER together", who);
    if (tri && !symmetric)
        return fr_error_set(err, FRICREG_EINVAL,
                            "%s: a triangle flag for a matrix that need not be symmetric", who);
    return FRICREG_OK;
}

/* ptr[0] is the base and ptr never decreases; *nnz = ptr[outer] - base. */
static int check_ptr(const struct fr_compressed *a, int64_t base, size_t outer, size_t *nnz,
                     struct fr_error *err, const char *who)
{
    const char *name = a->by_columns ? "colptr" : "rowptr";
    if (a->ptr[0] != base)
        return fr_error_set(err, FRICREG_EINVAL, "%s: %s[0] = %lld must be %lld", who, name,
                            (long long)a->ptr[0], (long long)base);
    for (size_t k = 0; k < outer; k++)
        if (a->ptr[k + 1] < a->ptr[k])
            return fr_error_set(err, FRICREG_EINVAL, "%s: %s[%zu] = %lld is below %s[%zu] = %lld",
                                who, name, k + 1, (long long)a->ptr[k + 1], name, k,
                                (long long)a->ptr[k]);
    *nnz = (size_t)(a->ptr[outer] - base);
    return FRICREG_OK;
}

/* Whether entry (row, col) lies in the triangle the flags left out. */
static int outside_triangle(int flags, int64_t row, int64_t col)
{
    return ((flags & FRICREG_SPARSE_UPPER) && col < row) ||
           ((flags & FRICREG_SPARSE_LOWER) && col > row);
}

static int check_entries(const struct fr_compressed *a, int64_t base, size_t outer, size_t inner,
                         struct fr_error *err, const char *who)
{
    const char *name = a->by_columns ? "rowind" : "colind";
    for (size_t k = 0; k < outer; k++)
        for (int64_t p = a->ptr[k] - base; p < a->ptr[k + 1] - base; p++) {
            int64_t idx = a->ind[p] - base;
            if (idx < 0 || (uint64_t)idx >= inner)
                return fr_error_set(err, FRICREG_EINVAL,
                                    "%s: %s[%lld] = %lld is outside %lld..%lld", who, name,
                                    (long long)p, (long long)a->ind[p], (long long)base,
                                    (long long)inner - 1 + (long long)base);
            int64_t row = a->by_columns ? idx : (int64_t)k, col = a->by_columns ? (int64_t)k : idx;
            if (outside_triangle(a->flags, row, col))
                return fr_error_set(err, FRICREG_EINVAL,
                                    "%s: entry (%lld, %lld) lies outside the %s triangle given",
                                    who, (long long)(row + base), (long long)(col + base),
                                    (a->flags & FRICREG_SPARSE_UPPER) ? "upper" : "lower");
            if (!isfinite(a->val[p]))
                return fr_error_set(err, FRICREG_ENONFINITE,
                                    "%s: val[%lld] (entry (%lld, %lld)) is not finite", who,
                                    (long long)p, (long long)(row + base), (long long)(col + base));
        }
    return FRICREG_OK;
}

int fr_matrix_format(int format, int *compressed, int *by_columns, int *flags, struct fr_error *err,
                     const char *who)
{
    int layout = format & (FRICREG_MATRIX_CSR | FRICREG_MATRIX_CSC);
    if (layout == (FRICREG_MATRIX_CSR | FRICREG_MATRIX_CSC))
        return fr_error_set(err, FRICREG_EINVAL, "%s: format %d is both CSR and CSC", who, format);
    if (layout == FRICREG_MATRIX_DENSE && format != FRICREG_MATRIX_DENSE)
        return fr_error_set(err, FRICREG_EINVAL,
                            "%s: a dense matrix takes no sparse flags (format %d)", who, format);
    *compressed = layout != FRICREG_MATRIX_DENSE;
    *by_columns = layout == FRICREG_MATRIX_CSC;
    *flags = format & ~layout;
    return FRICREG_OK;
}

int fr_compressed_check(const struct fr_compressed *a, int symmetric, struct fr_error *err,
                        const char *who)
{
    int status = check_flags(a, symmetric, err, who);
    if (status != FRICREG_OK)
        return status;
    if (a->ptr == NULL)
        return fr_error_set(err, FRICREG_ENULL, "%s: %s is NULL", who,
                            a->by_columns ? "colptr" : "rowptr");
    int64_t base = (a->flags & FRICREG_SPARSE_ONE_BASED) ? 1 : 0;
    size_t outer = a->by_columns ? a->ncols : a->nrows, inner = a->by_columns ? a->nrows : a->ncols;
    size_t nnz = 0;
    if ((status = check_ptr(a, base, outer, &nnz, err, who)) != FRICREG_OK)
        return status;
    if (nnz > 0 && (a->ind == NULL || a->val == NULL))
        return fr_error_set(err, FRICREG_ENULL, "%s: %s is NULL", who,
                            a->ind == NULL ? (a->by_columns ? "rowind" : "colind") : "val");
    return check_entries(a, base, outer, inner, err, who);
}

/* ---- Triplets to compressed columns ------------------------------------------------------- */

cholmod_triplet *fr_triplet_new(size_t nrows, size_t ncols, size_t nnz, cholmod_common *c)
{
    return cholmod_l_allocate_triplet(nrows, ncols, nnz > 0 ? nnz : 1, 0, CHOLMOD_REAL, c);
}

/* sqrt of each row's largest magnitude into scale[n] (the square root: no overflow of the
 * product of two scales). */
static void row_scales(const cholmod_sparse *A, double scale[])
{
    const SuiteSparse_long *Ap = A->p, *Ai = A->i;
    const double *Ax = A->x;
    memset(scale, 0, A->nrow * sizeof *scale);
    for (size_t j = 0; j < A->ncol; j++)
        for (SuiteSparse_long p = Ap[j]; p < Ap[j + 1]; p++)
            scale[Ai[p]] = fmax(scale[Ai[p]], fabs(Ax[p]));
    for (size_t i = 0; i < A->nrow; i++)
        scale[i] = sqrt(scale[i]);
}

/* The first (i, j), i < j, in column order, where D = A - A^T is beyond the rows' scales: 1,
 * else 0. */
static int asymmetric(const cholmod_sparse *D, const double scale[], SuiteSparse_long *bi,
                      SuiteSparse_long *bj)
{
    const SuiteSparse_long *Dp = D->p, *Di = D->i;
    const double *Dx = D->x;
    for (size_t j = 0; j < D->ncol; j++)
        for (SuiteSparse_long p = Dp[j]; p < Dp[j + 1]; p++)
            if (Di[p] < (SuiteSparse_long)j &&
                fabs(Dx[p]) > SYMMETRY_RTOL * scale[Di[p]] * scale[j]) {
                *bi = Di[p];
                *bj = (SuiteSparse_long)j;
                return 1;
            }
    return 0;
}

/* A square A given whole: checked symmetric, then the upper triangle of (A + A^T)/2. */
static int symmetric_part(cholmod_sparse *A, cholmod_common *c, cholmod_sparse **out,
                          struct fr_error *err, const char *who)
{
    cholmod_sparse *At = cholmod_l_transpose(A, 1, c), *D = NULL, *S = NULL;
    double *scale = cholmod_l_malloc(A->nrow > 0 ? A->nrow : 1, sizeof *scale, c);
    if (At != NULL)
        D = cholmod_l_add(A, At, (double[2]){1.0, 0.0}, (double[2]){-1.0, 0.0}, 1, 1, c);
    int status = FRICREG_OK;
    SuiteSparse_long i, j;
    if (D == NULL || scale == NULL) {
        status = cholmod_failed(c, err, who);
    } else {
        row_scales(A, scale);
        if (asymmetric(D, scale, &i, &j))
            status = fr_error_set(err, FRICREG_ENOTSYM,
                                  "%s: entries (%ld, %ld) = %g and (%ld, %ld) = %g differ: the "
                                  "matrix is not symmetric",
                                  who, (long)i, (long)j, fr_csc_entry(A, i, j), (long)j, (long)i,
                                  fr_csc_entry(A, j, i));
    }
    if (status == FRICREG_OK) {
        S = cholmod_l_add(A, At, (double[2]){0.5, 0.0}, (double[2]){0.5, 0.0}, 1, 1, c);
        *out = S == NULL ? NULL : cholmod_l_copy(S, 1, 1, c);
        if (*out == NULL)
            status = cholmod_failed(c, err, who);
    }
    cholmod_l_free(A->nrow > 0 ? A->nrow : 1, sizeof *scale, scale, c);
    cholmod_l_free_sparse(&At, c);
    cholmod_l_free_sparse(&D, c);
    cholmod_l_free_sparse(&S, c);
    return status;
}

int fr_triplet_finish(cholmod_triplet *T, int symmetric, int triangle, cholmod_common *c,
                      cholmod_sparse **out, struct fr_error *err, const char *who)
{
    SuiteSparse_long *Ti = T->i, *Tj = T->j;
    if (symmetric && triangle) { /* every entry into the upper triangle */
        for (size_t k = 0; k < T->nnz; k++)
            if (Ti[k] > Tj[k]) {
                SuiteSparse_long tmp = Ti[k];
                Ti[k] = Tj[k];
                Tj[k] = tmp;
            }
        T->stype = 1;
    }
    cholmod_sparse *A = cholmod_l_triplet_to_sparse(T, T->nnz, c);
    cholmod_l_free_triplet(&T, c);
    if (A == NULL)
        return cholmod_failed(c, err, who);
    if (!symmetric || triangle) {
        *out = A;
        return FRICREG_OK;
    }
    int status = symmetric_part(A, c, out, err, who);
    cholmod_l_free_sparse(&A, c);
    return status;
}

int fr_compressed_to_cholmod(const struct fr_compressed *a, int symmetric, cholmod_common *c,
                             cholmod_sparse **out, struct fr_error *err, const char *who)
{
    int64_t base = (a->flags & FRICREG_SPARSE_ONE_BASED) ? 1 : 0;
    size_t outer = a->by_columns ? a->ncols : a->nrows;
    size_t nnz = (size_t)(a->ptr[outer] - base);
    cholmod_triplet *T = fr_triplet_new(a->nrows, a->ncols, nnz, c);
    if (T == NULL)
        return cholmod_failed(c, err, who);
    SuiteSparse_long *Ti = T->i, *Tj = T->j;
    double *Tx = T->x;
    for (size_t k = 0; k < outer; k++)
        for (int64_t p = a->ptr[k] - base; p < a->ptr[k + 1] - base; p++) {
            SuiteSparse_long idx = (SuiteSparse_long)(a->ind[p] - base);
            Ti[p] = a->by_columns ? idx : (SuiteSparse_long)k;
            Tj[p] = a->by_columns ? (SuiteSparse_long)k : idx;
            Tx[p] = a->val[p];
        }
    T->nnz = nnz;
    int triangle = (a->flags & (FRICREG_SPARSE_UPPER | FRICREG_SPARSE_LOWER)) != 0;
    return fr_triplet_finish(T, symmetric, triangle, c, out, err, who);
}

int fr_dense_to_cholmod(size_t nrows, size_t ncols, const double A[], int symmetric,
                        cholmod_common *c, cholmod_sparse **out, struct fr_error *err,
                        const char *who)
{
    size_t nnz = 0;
    for (size_t k = 0; k < nrows * ncols; k++) {
        if (!isfinite(A[k]))
            return fr_error_set(err, FRICREG_ENONFINITE, "%s: entry (%zu, %zu) is not finite", who,
                                k / ncols, k % ncols);
        nnz += A[k] != 0.0;
    }
    cholmod_triplet *T = fr_triplet_new(nrows, ncols, nnz, c);
    if (T == NULL)
        return cholmod_failed(c, err, who);
    SuiteSparse_long *Ti = T->i, *Tj = T->j;
    double *Tx = T->x;
    size_t p = 0;
    for (size_t i = 0; i < nrows; i++)
        for (size_t j = 0; j < ncols; j++)
            if (A[i * ncols + j] != 0.0) {
                Ti[p] = (SuiteSparse_long)i;
                Tj[p] = (SuiteSparse_long)j;
                Tx[p++] = A[i * ncols + j];
            }
    T->nnz = nnz;
    return fr_triplet_finish(T, symmetric, 0, c, out, err, who);
}
