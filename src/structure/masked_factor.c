/* SPDX-License-Identifier: GPL-3.0-or-later */
/* masked_factor.c — principal blocks of one sparse SPD matrix, factored without allocating
 * (masked_factor.h). */
#include <math.h>
#include <string.h>

#include "base/sparse_factor.h"
#include "fricreg.h"
#include "masked_factor.h"

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
    memset(f, 0, sizeof *f);
}

/* A fill-reducing order of W's pattern (AMD, postordered) into f->perm. */
static int order(struct fr_masked_factor *f, const cholmod_sparse *W, cholmod_common *c)
{
    fr_cholmod_ordering(c, CHOLMOD_AMD, 0);
    cholmod_factor *L = cholmod_l_analyze((cholmod_sparse *)W, c);
    f->perm = cholmod_l_malloc(f->m, sizeof *f->perm, c);
    int ok = L != NULL && f->perm != NULL;
    if (ok)
        memcpy(f->perm, L->Perm, f->m * sizeof *f->perm);
    cholmod_l_free_factor(&L, c);
    return ok;
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

int fr_masked_factor_prepare(struct fr_masked_factor *f, const cholmod_sparse *W, cholmod_common *c)
{
    memset(f, 0, sizeof *f);
    f->m = W->ncol;
    f->b = cholmod_l_malloc(f->m, sizeof *f->b, c);
    f->held_shift = cholmod_l_malloc(f->m, sizeof *f->held_shift, c);
    f->held_set = cholmod_l_malloc(f->m, sizeof *f->held_set, c);
    int ok = f->b && f->held_shift && f->held_set && order(f, W, c) && permute(f, W, c) &&
             analyse(f, c);
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

/* The block and shifts of the factor held: those of the last factorization (f->held). */
static int holds(const struct fr_masked_factor *f, const unsigned char *set, const double *shift)
{
    if (!f->held)
        return 0;
    for (size_t i = 0; i < f->m; i++) {
        unsigned char in = set != NULL && set[i];
        if (in != f->held_set[i] || (in && (shift ? shift[i] : 0.0) != f->held_shift[i]))
            return 0;
    }
    return 1;
}

static void hold(struct fr_masked_factor *f, const unsigned char *set, const double *shift)
{
    for (size_t i = 0; i < f->m; i++) {
        f->held_set[i] = set != NULL && set[i];
        f->held_shift[i] = f->held_set[i] && shift ? shift[i] : 0.0;
    }
    f->held = 1;
}

int fr_masked_factor_solve(struct fr_masked_factor *f, const cholmod_sparse *W,
                           const unsigned char *set, const double *shift, const double b[],
                           double x[], cholmod_common *c)
{
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
