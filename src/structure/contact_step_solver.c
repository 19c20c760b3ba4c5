/* SPDX-License-Identifier: GPL-3.0-or-later */
/* contact_step_solver.c — the solver of fricreg_ctx_solve_step (contact_step_solver.h), built
 * from the caller's W and W_eff or kept from the context's previous call.
 *
 * The solver (CHOLMOD's workspace, W's and W_eff's upper triangles, the Newton matrix with
 * W_eff's analysed pattern, the vectors) is kept in the context between calls
 * (fr_ctx_keep_workspace, ctx_driver.h): a caller steps thousands of times on one K_eff
 * pattern, and building it cost a third of a 10-contact step (bench/solve_step.c). A call
 * whose m and patterns are the kept solver's refills the values; a new W_eff also forgets
 * the factor the masked factor holds (masked_factor.h), which is otherwise kept across calls
 * as across iterations. Every vector is written before it is read within a call (valgrind
 * holds the built solver to that), CHOLMOD's analysis depends on the pattern alone and its
 * factorization on the values alone: a kept solver gives the built one's results, bit for
 * bit (tests/structure/test_contact_step.c). */
#include <stdlib.h>
#include <string.h>

#include "base/sparse_factor.h"
#include "contact_step_solver.h"
#include "ctx/ctx_driver.h"
#include "base/free_all.h"

#define DENSE_FALLBACK_MAX 64

/* A's upper triangle (m x m, row-major) as CHOLMOD's symmetric upper form, the diagonal kept
 * and the zeros above it left out; NULL when out of memory. */
static cholmod_sparse *upper_of(const double A[], size_t m, cholmod_common *cc)
{
    size_t nnz = 0;
    for (size_t j = 0; j < m; j++)
        for (size_t i = 0; i <= j; i++)
            nnz += i == j || A[i * m + j] != 0.0;
    cholmod_sparse *S = cholmod_l_allocate_sparse(m, m, nnz, 1, 1, 1, CHOLMOD_REAL, cc);
    if (S == NULL)
        return NULL;
    SuiteSparse_long *Sp = S->p, *Si = S->i, p = 0;
    double *Sx = S->x;
    for (size_t j = 0; j < m; j++) {
        Sp[j] = p;
        for (size_t i = 0; i <= j; i++)
            if (i == j || A[i * m + j] != 0.0) {
                Si[p] = (SuiteSparse_long)i;
                Sx[p++] = A[i * m + j];
            }
    }
    Sp[m] = p;
    return S;
}

/* A's upper triangle into S's values when its nonzeros (the diagonal kept) are S's pattern,
 * the pattern upper_of(A) would build: 1, with *changed set if a value differs from S's; 0 at
 * the first entry outside the pattern (S's values then partly overwritten: rebuild it). A is
 * read row by row, in the order it lies in memory (column by column, each entry m doubles
 * from the last, made the refill of m = 2000 three times slower): next[m] holds each column's
 * next entry of S. */
static int refill(cholmod_sparse *S, const double A[], size_t m, SuiteSparse_long next[],
                  int *changed)
{
    const SuiteSparse_long *Sp = S->p, *Si = S->i;
    double *Sx = S->x;
    int differ = 0;
    memcpy(next, Sp, m * sizeof *next);
    for (size_t i = 0; i < m; i++) {
        const double *row = A + i * m;
        for (size_t j = i; j < m; j++) {
            double a = row[j];
            if (j != i && a == 0.0)
                continue;
            SuiteSparse_long p = next[j]++;
            if (p == Sp[j + 1] || Si[p] != (SuiteSparse_long)i)
                return 0;
            differ |= Sx[p] != a;
            Sx[p] = a;
        }
    }
    for (size_t j = 0; j < m; j++)
        if (next[j] != Sp[j + 1])
            return 0;
    *changed = differ;
    return 1;
}

/* The upper triangles of the inputs into s->W and s->Weff, their values those of a dense
 * input (a compressed one's are stored by the caller once checked). */
static int build_matrices(struct fr_step_solver *s, const struct fr_step_inputs *in)
{
    if (in->sw == NULL) {
        s->W = upper_of(in->W, s->m, &s->cc);
        s->Weff = upper_of(in->Weff, s->m, &s->cc);
        return s->W != NULL && s->Weff != NULL ? FRICREG_OK : FRICREG_ENOMEM;
    }
    int status = fr_step_pattern_build(&s->pw, in->sw, &s->cc, &s->W);
    return status == FRICREG_OK ? fr_step_pattern_build(&s->pweff, in->sweff, &s->cc, &s->Weff)
                                : status;
}

static int allocate(struct fr_step_solver *s, const struct fr_step_inputs *in)
{
    size_t m = s->m;
    if (fr_cholmod_start(&s->cc) != FRICREG_OK || build_matrices(s, in) != FRICREG_OK)
        return FRICREG_ENOMEM;
    s->block = malloc(FR_STEP_VECTORS * m * sizeof *s->block);
    s->stopped = malloc(m);
    s->next = malloc(m * sizeof *s->next);
    if (s->block == NULL || s->stopped == NULL || s->next == NULL)
        return FRICREG_ENOMEM;
    for (size_t k = 0; k < FR_STEP_VECTORS; k++)
        s->v[k] = (gsl_vector){.size = m, .stride = 1, .data = s->block + k * m};
    s->f0 = s->v[FR_STEP_V_F0].data;
    s->df = s->v[FR_STEP_V_DF].data;
    s->zdot = s->v[FR_STEP_V_ZDOT].data;
    s->afree = s->v[FR_STEP_V_AFREE].data;
    s->F = s->v[FR_STEP_V_F].data;
    s->b = s->v[FR_STEP_V_B].data;
    s->wg = s->v[FR_STEP_V_WG].data;
    struct fr_compliance_pair *pairs[] = {&s->at_start, &s->at_k, &s->at_t, &s->at_df,
                                          &s->at_guess};
    for (size_t k = 0; k < 5; k++)
        *pairs[k] = (struct fr_compliance_pair){&s->v[FR_STEP_V_PAIRS + 2 * k],
                                                &s->v[FR_STEP_V_PAIRS + 2 * k + 1]};
    return fr_newton_matrix_prepare(&s->nm, s->Weff, s->dense, &s->cc);
}

static void release(void *p)
{
    struct fr_step_solver *s = p;
    fr_newton_matrix_free(&s->nm, &s->cc);
    cholmod_l_free_sparse(&s->W, &s->cc);
    cholmod_l_free_sparse(&s->Weff, &s->cc);
    FR_FREE_ALL(s->block, s->stopped, s->next);
    fr_step_pattern_free(&s->pw);
    fr_step_pattern_free(&s->pweff);
    fr_cholmod_finish(&s->cc);
    free(s);
}

struct fr_step_solver *fr_contact_step_solver(fricreg_ctx *ctx, size_t m,
                                              const struct fr_step_inputs *in)
{
    struct fr_step_solver *s = fr_ctx_workspace(ctx);
    /* The dense form for a tangent without rows, reserved here, so that no step allocates
     * it; a kept solver without it, once the context can need it, is built again. */
    int dense = m <= DENSE_FALLBACK_MAX || fr_ctx_tangent_may_be_dense(ctx);
    if (s != NULL && dense && !s->dense)
        s = NULL;
    if (s != NULL && s->m == m && in->sw != NULL && fr_step_pattern_same(&s->pw, in->sw) &&
        fr_step_pattern_same(&s->pweff, in->sweff))
        return s;
    int w_changed = 0, weff_changed = 0;
    if (s != NULL && s->m == m && in->sw == NULL && refill(s->W, in->W, m, s->next, &w_changed) &&
        refill(s->Weff, in->Weff, m, s->next, &weff_changed)) {
        if (weff_changed)
            s->nm.block.held = 0; /* the factor held is of the old values */
        return s;
    }
    fr_ctx_drop_workspace(ctx);
    s = calloc(1, sizeof *s);
    if (s == NULL)
        return NULL;
    s->m = m;
    s->dense = dense;
    if (allocate(s, in) != FRICREG_OK) {
        release(s);
        return NULL;
    }
    fr_ctx_keep_workspace(ctx, s, release);
    return s;
}
