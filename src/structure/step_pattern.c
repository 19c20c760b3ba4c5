/* SPDX-License-Identifier: GPL-3.0-or-later */
/* step_pattern.c — a compressed W or W_eff mapped onto the step's upper triangle
 * (step_pattern.h). The pattern comes from fr_compressed_to_cholmod, as the coupling setters'
 * (sparse_setup.c), with a matrix given whole folded onto its upper triangle (entries (i, j)
 * and (j, i) in one place); the values are summed through the map on every call, so that a
 * solver built by this call and one kept from the last hold the same numbers, bit for bit. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg.h"
#include "step_pattern.h"
#include "base/free_all.h"

#define SYM_TOL 1e-12 /* as contact_step.c's dense check */
#define TRIANGLES (FRICREG_SPARSE_UPPER | FRICREG_SPARSE_LOWER)

static int64_t base_of(int flags)
{
    return (flags & FRICREG_SPARSE_ONE_BASED) ? 1 : 0;
}

/* Entry (row, col) of a's k-th row (CSR) or column (CSC) at index idx. */
static void position(const struct fr_compressed *a, size_t k, int64_t idx, size_t *row, size_t *col)
{
    *row = a->by_columns ? (size_t)idx : k;
    *col = a->by_columns ? k : (size_t)idx;
}

/* The place of (i, j), i <= j, in the sorted S; -1 if absent. */
static SuiteSparse_long find(const cholmod_sparse *S, size_t i, size_t j)
{
    const SuiteSparse_long *Sp = S->p, *Si = S->i;
    SuiteSparse_long lo = Sp[j], hi = Sp[j + 1];
    while (lo < hi) {
        SuiteSparse_long mid = lo + (hi - lo) / 2;
        if (Si[mid] < (SuiteSparse_long)i)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < Sp[j + 1] && Si[lo] == (SuiteSparse_long)i ? lo : -1;
}

int fr_step_pattern_build(struct fr_step_pattern *p, const struct fr_compressed *a,
                          cholmod_common *cc, cholmod_sparse **S)
{
    int64_t base = base_of(a->flags);
    size_t m = a->nrows, nnz = (size_t)(a->ptr[m] - base);
    struct fr_compressed folded = *a;
    struct fr_error err = {0};
    if ((a->flags & TRIANGLES) == 0)
        folded.flags |= FRICREG_SPARSE_UPPER; /* pattern only: no symmetry check here */
    *p = (struct fr_step_pattern){.flags = a->flags,
                                  .by_columns = a->by_columns,
                                  .m = m,
                                  .nnz = nnz};
    if (fr_compressed_to_cholmod(&folded, 1, cc, S, &err, "solve_step") != FRICREG_OK)
        return FRICREG_ENOMEM;
    size_t nS = (size_t)((SuiteSparse_long *)(*S)->p)[m];
    p->ptr = malloc((m + 1) * sizeof *p->ptr);
    p->ind = malloc((nnz > 0 ? nnz : 1) * sizeof *p->ind);
    p->slot = malloc((nnz > 0 ? nnz : 1) * sizeof *p->slot);
    p->upper = malloc((nS > 0 ? nS : 1) * sizeof *p->upper);
    p->lower = malloc((nS > 0 ? nS : 1) * sizeof *p->lower);
    if (!(p->ptr && p->ind && p->slot && p->upper && p->lower))
        return FRICREG_ENOMEM;
    memcpy(p->ptr, a->ptr, (m + 1) * sizeof *p->ptr);
    if (nnz > 0)
        memcpy(p->ind, a->ind, nnz * sizeof *p->ind);
    for (size_t k = 0; k < m; k++)
        for (int64_t q = a->ptr[k] - base; q < a->ptr[k + 1] - base; q++) {
            size_t row, col;
            position(a, k, a->ind[q] - base, &row, &col);
            p->slot[q] = row <= col ? find(*S, row, col) : find(*S, col, row);
        }
    return FRICREG_OK;
}

int fr_step_pattern_same(const struct fr_step_pattern *p, const struct fr_compressed *a)
{
    if (p->ptr == NULL || p->flags != a->flags || p->by_columns != a->by_columns ||
        p->m != a->nrows || memcmp(p->ptr, a->ptr, (p->m + 1) * sizeof *p->ptr) != 0)
        return 0;
    return p->nnz == 0 || memcmp(p->ind, a->ind, p->nnz * sizeof *p->ind) == 0;
}

/* The diagonal's place in column j: the column's last entry, if it is (j, j); else -1. */
static SuiteSparse_long diagonal_at(const cholmod_sparse *S, size_t j)
{
    const SuiteSparse_long *Sp = S->p, *Si = S->i;
    SuiteSparse_long q = Sp[j + 1] - 1;
    return q >= Sp[j] && Si[q] == (SuiteSparse_long)j ? q : -1;
}

int fr_step_pattern_values(struct fr_step_pattern *p, const struct fr_compressed *a,
                           const cholmod_sparse *S, size_t *bi, size_t *bj)
{
    const SuiteSparse_long *Sp = S->p, *Si = S->i;
    size_t m = p->m, nS = (size_t)Sp[m];
    int64_t base = base_of(a->flags);
    int whole = (a->flags & TRIANGLES) == 0;
    memset(p->upper, 0, nS * sizeof *p->upper);
    memset(p->lower, 0, nS * sizeof *p->lower);
    for (size_t k = 0; k < m; k++)
        for (int64_t q = a->ptr[k] - base; q < a->ptr[k + 1] - base; q++) {
            size_t row, col;
            position(a, k, a->ind[q] - base, &row, &col);
            if (whole && row > col)
                p->lower[p->slot[q]] += a->val[q];
            else
                p->upper[p->slot[q]] += a->val[q];
        }
    for (size_t j = 0; j < m; j++) {
        SuiteSparse_long d = diagonal_at(S, j);
        if (d < 0 || !(p->upper[d] >= DBL_MIN)) {
            *bi = *bj = j;
            return FRICREG_ENOTPSD;
        }
    }
    if (!whole)
        return FRICREG_OK;
    for (size_t j = 0; j < m; j++)
        for (SuiteSparse_long q = Sp[j]; q < Sp[j + 1] - 1; q++) { /* above the diagonal */
            size_t i = (size_t)Si[q];
            double u = p->upper[q], l = p->lower[q];
            if (u != l && fabs(u - l) > SYM_TOL * sqrt(p->upper[diagonal_at(S, i)]) *
                                            sqrt(p->upper[diagonal_at(S, j)])) {
                *bi = i;
                *bj = j;
                return FRICREG_ENOTSYM;
            }
        }
    for (size_t j = 0; j < m; j++)
        for (SuiteSparse_long q = Sp[j]; q < Sp[j + 1] - 1; q++)
            p->upper[q] = 0.5 * p->upper[q] + 0.5 * p->lower[q]; /* as the coupling setters */
    return FRICREG_OK;
}

double fr_step_pattern_diagonal(const struct fr_step_pattern *p, const cholmod_sparse *S, size_t j)
{
    return p->upper[diagonal_at(S, j)];
}

int fr_step_pattern_store(const struct fr_step_pattern *p, cholmod_sparse *S)
{
    size_t nS = (size_t)((SuiteSparse_long *)S->p)[p->m];
    double *Sx = S->x;
    int differ = 0;
    for (size_t q = 0; q < nS; q++) {
        differ |= Sx[q] != p->upper[q];
        Sx[q] = p->upper[q];
    }
    return differ;
}

void fr_step_pattern_free(struct fr_step_pattern *p)
{
    FR_FREE_ALL(p->ptr, p->ind, p->slot, p->upper, p->lower);
    memset(p, 0, sizeof *p);
}
