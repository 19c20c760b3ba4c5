/* SPDX-License-Identifier: GPL-3.0-or-later */
/* masked_factor.c — principal blocks of one sparse SPD matrix, factored without allocating
 * (masked_factor.h). */
#include <limits.h>
#include <math.h>
#include <string.h>

#include "base/sparse_factor.h"
#include "fricreg.h"
#include "masked_factor.h"

/* LAPACK by Fortran's calling convention (as src/hb/lu.c): every argument by reference, a
 * CHARACTER's length appended as a size_t. */
void dpotrf_(const char *uplo, const int *n, double *a, const int *lda, int *info, size_t uplo_len);
void dpotrs_(const char *uplo, const int *n, const int *nrhs, const double *a, const int *lda,
             double *b, const int *ldb, int *info, size_t uplo_len);

void fr_masked_factor_free(struct fr_masked_factor *f, cholmod_common *c)
{
    size_t nnz = f->A ? (size_t)((SuiteSparse_long *)f->A->p)[f->m] : 0;
    cholmod_l_free(nnz, sizeof *f->src, f->src, c);
    cholmod_l_free(f->m, sizeof *f->perm, f->perm, c);
    cholmod_l_free(f->m, sizeof *f->b, f->b, c);
    cholmod_l_free(f->m, sizeof *f->held_shift, f->held_shift, c);
    cholmod_l_free(f->m, sizeof *f->held_set, f->held_set, c);
    cholmod_l_free_sparse(&f->A, c);
    cholmod_l_free_factor(&f->L, c);
    cholmod_l_free_dense(&f->X, c);
    cholmod_l_free_dense(&f->Yw, c);
    cholmod_l_free_dense(&f->Ew, c);
    cholmod_l_free(f->m * f->m > 0 ? f->m * f->m : 1, sizeof *f->D, f->D, c);
    cholmod_l_free(f->m, sizeof *f->at, f->at, c);
    memset(f, 0, sizeof *f);
}

/* A fill-reducing order of W's pattern (AMD, postordered) into f->perm, and the number of
 * entries of the factor in that order into *lnz. */
static int order(struct fr_masked_factor *f, const cholmod_sparse *W, double *lnz,
                 cholmod_common *c)
{
    fr_cholmod_ordering(c, CHOLMOD_AMD, 0);
    cholmod_factor *L = cholmod_l_analyze((cholmod_sparse *)W, c);
    f->perm = cholmod_l_malloc(f->m, sizeof *f->perm, c);
    int ok = L != NULL && f->perm != NULL;
    if (ok) {
        memcpy(f->perm, L->Perm, f->m * sizeof *f->perm);
        *lnz = 0.0;
        for (size_t j = 0; j < f->m; j++)
            *lnz += (double)((const SuiteSparse_long *)L->ColCount)[j];
    }
    cholmod_l_free_factor(&L, c);
    return ok;
}

/* The storage the fill rule (masked_factor.h) gives W's factor of nnz(L) = lnz; dense needs its
 * order to fit LAPACK's int. */
static int fill_is_dense(size_t m, double lnz)
{
    return m <= (size_t)INT_MAX && lnz >= FR_BLOCK_DENSE_FILL * (double)m * ((double)m + 1.0) / 2.0;
}

/* f->A = the upper triangle of P W P^T, with f->src mapping its entries to W's: the
 * permutation is done on a copy of W whose values are its entries' own positions. */
static int permute(struct fr_masked_factor *f, const cholmod_sparse *W, cholmod_common *c)
{
    size_t nnz = (size_t)((const SuiteSparse_long *)W->p)[f->m];
    cholmod_sparse *index = cholmod_l_copy_sparse((cholmod_sparse *)W, c), *full = NULL, *P = NULL;
    if (index != NULL) {
        for (size_t p = 0; p < nnz; p++)
            ((double *)index->x)[p] = (double)p;
        full = cholmod_l_copy(index, 0, 1, c); /* both triangles */
    }
    if (full != NULL)
        P = cholmod_l_submatrix(full, f->perm, (SuiteSparse_long)f->m, f->perm,
                                (SuiteSparse_long)f->m, 1, 1, c);
    if (P != NULL)
        f->A = cholmod_l_copy(P, 1, 1, c);
    cholmod_l_free_sparse(&index, c);
    cholmod_l_free_sparse(&full, c);
    cholmod_l_free_sparse(&P, c);
    if (f->A == NULL)
        return 0;
    size_t anz = (size_t)((SuiteSparse_long *)f->A->p)[f->m];
    f->src = cholmod_l_malloc(anz > 0 ? anz : 1, sizeof *f->src, c);
    if (f->src == NULL)
        return 0;
    const double *ax = f->A->x;
    for (size_t q = 0; q < anz; q++)
        f->src[q] = (SuiteSparse_long)ax[q];
    return 1;
}

/* The factor's symbolic analysis in the natural order (the matrix is permuted already). */
static int analyse(struct fr_masked_factor *f, cholmod_common *c)
{
    fr_cholmod_ordering(c, CHOLMOD_NATURAL, 1);
    f->L = cholmod_l_analyze(f->A, c);
    return f->L != NULL && f->L->ordering == CHOLMOD_NATURAL;
}

/* Dense: the buffer of the largest block, W itself, and the map to a block's rows. */
static int dense_allocate(struct fr_masked_factor *f, cholmod_common *c)
{
    f->D = cholmod_l_malloc(f->m * f->m > 0 ? f->m * f->m : 1, sizeof *f->D, c);
    f->at = cholmod_l_malloc(f->m, sizeof *f->at, c);
    return f->D != NULL && f->at != NULL;
}

int fr_masked_factor_prepare(struct fr_masked_factor *f, const cholmod_sparse *W,
                             enum fr_block_storage storage, cholmod_common *c)
{
    memset(f, 0, sizeof *f);
    f->m = W->ncol;
    f->b = cholmod_l_malloc(f->m, sizeof *f->b, c);
    f->held_shift = cholmod_l_malloc(f->m, sizeof *f->held_shift, c);
    f->held_set = cholmod_l_malloc(f->m, sizeof *f->held_set, c);
    double lnz = 0.0;
    int ok = f->b && f->held_shift && f->held_set && order(f, W, &lnz, c);
    if (ok) {
        f->dense = storage == FR_BLOCK_DENSE ||
                   (storage == FR_BLOCK_CHOSEN && fill_is_dense(f->m, lnz));
        if (f->dense) {
            ok = dense_allocate(f, c);
            if (!ok)
                fr_masked_factor_free(f, c);
            return ok ? FRICREG_OK : FRICREG_ENOMEM;
        }
    }
    ok = ok && permute(f, W, c) && analyse(f, c);
    if (ok) { /* the identity (an empty block) once: CHOLMOD sizes its workspaces */
        memset(f->b, 0, f->m * sizeof *f->b);
        ok = fr_masked_factor_solve(f, W, NULL, NULL, f->b, f->b, c) == FRICREG_OK;
    }
    if (!ok)
        fr_masked_factor_free(f, c);
    return ok ? FRICREG_OK : FRICREG_ENOMEM;
}

static void fill(struct fr_masked_factor *f, const cholmod_sparse *W, const unsigned char *set,
                 const double *shift)
{
    const SuiteSparse_long *Ap = f->A->p, *Ai = f->A->i;
    const double *Wx = W->x;
    double *Ax = f->A->x;
    for (size_t l = 0; l < f->m; l++) {
        size_t j = (size_t)f->perm[l];
        for (SuiteSparse_long q = Ap[l]; q < Ap[l + 1]; q++) {
            size_t i = (size_t)f->perm[Ai[q]];
            if (set && set[i] && set[j])
                Ax[q] = Wx[f->src[q]] + (i == j && shift ? shift[i] : 0.0);
            else
                Ax[q] = i == j ? 1.0 : 0.0;
        }
    }
}

int fr_block_is_held(size_t m, int held, const unsigned char *held_set, const double *held_shift,
                     const unsigned char *set, const double *shift)
{
    if (!held)
        return 0;
    for (size_t i = 0; i < m; i++) {
        unsigned char in = set != NULL && set[i];
        if (in != held_set[i] || (in && (shift ? shift[i] : 0.0) != held_shift[i]))
            return 0;
    }
    return 1;
}

void fr_block_hold(size_t m, unsigned char *held_set, double *held_shift, const unsigned char *set,
                   const double *shift)
{
    for (size_t i = 0; i < m; i++) {
        held_set[i] = set != NULL && set[i];
        held_shift[i] = held_set[i] && shift ? shift[i] : 0.0;
    }
}

/* The block and shifts of the factor held: those of the last factorization (f->held). */
static int holds(const struct fr_masked_factor *f, const unsigned char *set, const double *shift)
{
    return fr_block_is_held(f->m, f->held, f->held_set, f->held_shift, set, shift);
}

static void hold(struct fr_masked_factor *f, const unsigned char *set, const double *shift)
{
    fr_block_hold(f->m, f->held_set, f->held_shift, set, shift);
    f->held = 1;
}

/* D = the upper triangle of W_SS + diag(shift_S), column-major, k = |S| (f->at numbers S).
 * Entries of W below the diagonal are not read, as CHOLMOD reads an upper (stype 1) W. */
static void dense_fill(struct fr_masked_factor *f, const cholmod_sparse *W, size_t k,
                       const double *shift)
{
    const SuiteSparse_long *Wp = W->p, *Wi = W->i;
    const double *Wx = W->x;
    for (size_t q = 0; q < k; q++)
        memset(f->D + q * k, 0, (q + 1) * sizeof *f->D);
    for (size_t j = 0; j < f->m; j++) {
        SuiteSparse_long col = f->at[j];
        if (col < 0)
            continue;
        for (SuiteSparse_long p = Wp[j]; p < Wp[j + 1]; p++) {
            size_t i = (size_t)Wi[p];
            if (i <= j && f->at[i] >= 0)
                f->D[(size_t)f->at[i] + (size_t)col * k] = Wx[p];
        }
        if (shift)
            f->D[(size_t)col * (k + 1)] += shift[j];
    }
}

/* The sparse solve's dense twin: W_SS's Cholesky factor by dpotrf in f->D, then dpotrs. A
 * pivot that is not positive (W_SS not positive definite, or not a number) stops dpotrf with
 * info > 0, CHOLMOD's CHOLMOD_NOT_POSDEF. */
static int dense_solve(struct fr_masked_factor *f, const cholmod_sparse *W,
                       const unsigned char *set, const double *shift, const double b[], double x[])
{
    size_t k = 0;
    for (size_t i = 0; i < f->m; i++) {
        f->at[i] = set && set[i] ? (SuiteSparse_long)k : -1;
        if (set && set[i])
            f->b[k++] = b[i];
    }
    int order = (int)k, one = 1, info = 0;
    if (!holds(f, set, shift)) {
        f->held = 0;
        dense_fill(f, W, k, shift);
        if (k > 0)
            dpotrf_("U", &order, f->D, &order, &info, 1);
        if (info != 0)
            return FRICREG_ESINGULAR;
        hold(f, set, shift);
    }
    if (k == 0)
        return FRICREG_OK;
    dpotrs_("U", &order, &one, f->D, &order, f->b, &order, &info, 1);
    for (size_t i = 0; i < f->m; i++)
        if (f->at[i] >= 0)
            x[i] = f->b[f->at[i]];
    return FRICREG_OK;
}

int fr_masked_factor_solve(struct fr_masked_factor *f, const cholmod_sparse *W,
                           const unsigned char *set, const double *shift, const double b[],
                           double x[], cholmod_common *c)
{
    if (f->dense)
        return dense_solve(f, W, set, shift, b, x);
    for (size_t k = 0; k < f->m; k++) {
        size_t i = (size_t)f->perm[k];
        f->b[k] = set && set[i] ? b[i] : 0.0;
    }
    if (!holds(f, set, shift)) {
        f->held = 0;
        fill(f, W, set, shift);
        if (!cholmod_l_factorize(f->A, f->L, c) || c->status < CHOLMOD_OK)
            return FRICREG_ENOMEM;
        if (c->status == CHOLMOD_NOT_POSDEF)
            return FRICREG_ESINGULAR;
        hold(f, set, shift);
    }
    cholmod_dense B = {.nrow = f->m,
                       .ncol = 1,
                       .nzmax = f->m,
                       .d = f->m,
                       .x = f->b,
                       .xtype = CHOLMOD_REAL,
                       .dtype = CHOLMOD_DOUBLE};
    fr_cholmod_keep_workspace(f->Yw);
    if (!cholmod_l_solve2(CHOLMOD_A, f->L, &B, NULL, &f->X, NULL, &f->Yw, &f->Ew, c))
        return FRICREG_ENOMEM;
    const double *sol = f->X->x;
    for (size_t k = 0; k < f->m; k++) {
        size_t i = (size_t)f->perm[k];
        if (set && set[i])
            x[i] = sol[k];
    }
    return FRICREG_OK;
}
