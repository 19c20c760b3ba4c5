/* SPDX-License-Identifier: GPL-3.0-or-later */
/* factor.c — the cached, Jacobi-scaled pivoted Cholesky factor of a principal block of W. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_permutation.h>

#include "ctx_internal.h"
#include "factor.h"

/* Below this reciprocal condition number of the scaled block, W_BB is treated as singular. */
#define RCOND_MIN 1e-12

int fr_factor_alloc(struct fr_factor *fa, size_t m)
{
    memset(fa, 0, sizeof *fa);
    fa->set = malloc(m * sizeof *fa->set);
    fa->ldlt = malloc(m * m * sizeof *fa->ldlt);
    fa->perm = malloc(m * sizeof *fa->perm);
    fa->scale = malloc(m * sizeof *fa->scale);
    fa->work = malloc(3 * m * sizeof *fa->work);
    if (!fa->set || !fa->ldlt || !fa->perm || !fa->scale || !fa->work) {
        fr_factor_free(fa);
        return FRICREG_ENOMEM;
    }
    return FRICREG_OK;
}

void fr_factor_free(struct fr_factor *fa)
{
    free(fa->set);
    free(fa->ldlt);
    free(fa->perm);
    free(fa->scale);
    free(fa->work);
    memset(fa, 0, sizeof *fa);
}

static int holds(const struct fr_factor *fa, const size_t set[], size_t n)
{
    return fa->valid && fa->n == n && memcmp(fa->set, set, n * sizeof *set) == 0;
}

/* ldlt = D^-1/2 W[set, set] D^-1/2: unit diagonal, so rcond measures redundancy, not units. */
static void copy_scaled_block(struct fr_factor *fa, const double W[], size_t m, const size_t set[],
                              size_t n)
{
    for (size_t a = 0; a < n; a++)
        fa->scale[a] = 1.0 / sqrt(W[set[a] * m + set[a]]); /* W_ii > 0: set_coupling_dense */
    for (size_t a = 0; a < n; a++)
        for (size_t b = 0; b < n; b++)
            fa->ldlt[a * n + b] = fa->scale[a] * W[set[a] * m + set[b]] * fa->scale[b];
}

int fr_factor_ensure(fricreg_ctx *ctx, const size_t set[], size_t n, const char *who)
{
    struct fr_factor *fa = &ctx->fac;
    if (holds(fa, set, n))
        return FRICREG_OK;
    fa->valid = 0;
    copy_scaled_block(fa, ctx->W, ctx->m, set, n);
    gsl_matrix_view A = gsl_matrix_view_array(fa->ldlt, n, n);
    gsl_permutation p = {n, fa->perm};
    gsl_vector_view work = gsl_vector_view_array(fa->work, 3 * n);
    double rcond = 0.0;
    int status = gsl_linalg_pcholesky_decomp(&A.matrix, &p);
    if (status == GSL_SUCCESS)
        status = gsl_linalg_pcholesky_rcond(&A.matrix, &p, &rcond, &work.vector);
    ctx->stats[FRICREG_STAT_FACTORIZATIONS]++;
    if (status != GSL_SUCCESS || !(rcond >= RCOND_MIN))
        return fr_fail(ctx, FRICREG_ESINGULAR,
                       "%s: W on the %zu contacts (first: contact %zu) is singular (rcond %.3g"
                       " of the scaled block): redundant contacts",
                       who, n, set[0], rcond);
    memcpy(fa->set, set, n * sizeof *set);
    fa->n = n;
    fa->valid = 1;
    return FRICREG_OK;
}

int fr_factor_solve(fricreg_ctx *ctx, double r[], const char *who)
{
    struct fr_factor *fa = &ctx->fac;
    size_t n = fa->n;
    for (size_t a = 0; a < n; a++)
        r[a] *= fa->scale[a];
    gsl_matrix_const_view A = gsl_matrix_const_view_array(fa->ldlt, n, n);
    gsl_permutation p = {n, fa->perm};
    gsl_vector_view x = gsl_vector_view_array(r, n);
    int status = gsl_linalg_pcholesky_svx(&A.matrix, &p, &x.vector);
    ctx->stats[FRICREG_STAT_SOLVES]++;
    if (status != GSL_SUCCESS)
        return fr_fail(ctx, FRICREG_ESINGULAR, "%s: solve with W failed (GSL status %d)", who,
                       status);
    for (size_t a = 0; a < n; a++)
        r[a] *= fa->scale[a];
    return FRICREG_OK;
}
