/* SPDX-License-Identifier: GPL-3.0-or-later */
/* ctx.c — context life cycle, setters, error state and counters. Evaluation: partition.c. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <stdint.h>
#include <string.h>

#include "box_qp.h"
#include "ctx_internal.h"
#include "sparse_block.h"
#include "sparse_coupling.h"
#include "base/eigen.h"
#include "law/contact_check.h"
#include "law/law.h"
#include "base/free_all.h"

#define SYMMETRY_RTOL 1e-12
#define PSD_RTOL 1e-12

void *fr_ctx_workspace(const fricreg_ctx *ctx)
{
    return ctx->workspace;
}

void fr_ctx_drop_workspace(fricreg_ctx *ctx)
{
    if (ctx->workspace != NULL)
        ctx->workspace_free(ctx->workspace);
    ctx->workspace = NULL;
    ctx->workspace_free = NULL;
}

void fr_ctx_keep_workspace(fricreg_ctx *ctx, void *workspace, void (*release)(void *))
{
    if (workspace != ctx->workspace)
        fr_ctx_drop_workspace(ctx);
    ctx->workspace = workspace;
    ctx->workspace_free = release;
}

/* Back to a diagonal W: the dense or sparse coupling and what it needs, released; with it the
 * drivers' workspace (sized for the scene of the old coupling). */
void fr_ctx_free_coupling(fricreg_ctx *ctx)
{
    fr_ctx_drop_workspace(ctx);
    free(ctx->W);
    free(ctx->rhs);
    ctx->W = ctx->rhs = NULL;
    fr_factor_free(&ctx->fac);
    fr_box_qp_free(&ctx->qp);
    if (ctx->sp != NULL) {
        fr_sparse_block_free(ctx->sp);
        fr_sparse_coupling_free(ctx->sp);
        free(ctx->sp);
        ctx->sp = NULL;
    }
}

void fr_ctx_forget_factor(fricreg_ctx *ctx)
{
    ctx->fac.valid = 0;
    if (ctx->sp != NULL)
        ctx->sp->block.valid = 0;
}

void fricreg_ctx_free(fricreg_ctx *ctx)
{
    if (ctx == NULL)
        return;
    fr_ctx_free_coupling(ctx);
    FR_FREE_ALL(ctx->mun, ctx->w_diag, ctx->f, ctx->f_eq, ctx->stick, ctx->side, ctx->last_zdot,
                ctx->last_afree, ctx->strib, ctx->strib_keps, ctx->strib_bound, ctx);
}

int fricreg_ctx_create(size_t m, fricreg_ctx **out)
{
    if (out == NULL)
        return FRICREG_ENULL;
    if (m == 0 || m > FR_MAX_CONTACTS)
        return FRICREG_EINVAL;
    fricreg_ctx *ctx = calloc(1, sizeof *ctx);
    if (ctx == NULL)
        return FRICREG_ENOMEM;
    ctx->m = m;
    ctx->law = FRICREG_LAW_QUINN;
    ctx->partition = FRICREG_PARTITION_CONSISTENT;
    ctx->eps = 1e-3;
    ctx->mun = malloc(m * sizeof *ctx->mun);
    ctx->w_diag = malloc(m * sizeof *ctx->w_diag);
    ctx->f = malloc(m * sizeof *ctx->f);
    ctx->f_eq = malloc(m * sizeof *ctx->f_eq);
    ctx->stick = malloc(m * sizeof *ctx->stick);
    ctx->side = calloc(m, sizeof *ctx->side); /* all free: the QP's first warm start */
    ctx->last_zdot = malloc(m * sizeof *ctx->last_zdot);
    ctx->last_afree = malloc(m * sizeof *ctx->last_afree);
    if (!ctx->mun || !ctx->w_diag || !ctx->f || !ctx->f_eq || !ctx->stick || !ctx->side ||
        !ctx->last_zdot || !ctx->last_afree) {
        fricreg_ctx_free(ctx);
        return FRICREG_ENOMEM;
    }
    for (size_t i = 0; i < m; i++)
        ctx->mun[i] = ctx->w_diag[i] = 1.0;
    ctx->w_unit = 1;
    ctx->bound = ctx->mun;
    ctx->keep_tangent = 1;
    ctx->coded_from = FR_CODED_TANGENT_FROM;
    *out = ctx;
    return FRICREG_OK;
}

size_t fricreg_ctx_size(const fricreg_ctx *ctx)
{
    return ctx ? ctx->m : 0;
}

int fr_ctx_law(const fricreg_ctx *ctx)
{
    return ctx->law;
}

double fr_ctx_eps(const fricreg_ctx *ctx)
{
    return ctx->eps;
}

const double *fr_ctx_bounds(const fricreg_ctx *ctx)
{
    return ctx->mun;
}

struct fr_error *fr_ctx_error(fricreg_ctx *ctx)
{
    return &ctx->err;
}

const double *fr_ctx_coupling_diagonal(const fricreg_ctx *ctx)
{
    return ctx->w_diag;
}

int fricreg_ctx_set_law(fricreg_ctx *ctx, int law, double eps)
{
    if (ctx == NULL)
        return FRICREG_ENULL;
    if (!fr_law_known(law))
        return fr_fail(ctx, FRICREG_EINVAL, "set_law: unknown law %d", law);
    if (!isfinite(eps))
        return fr_fail(ctx, FRICREG_ENONFINITE, "set_law: eps is not finite");
    if (!fr_eps_valid(eps))
        return fr_fail(ctx, FRICREG_EINVAL,
                       "set_law: eps = %g must be >= DBL_MIN (a normal "
                       "number > 0)",
                       eps);
    ctx->law = law;
    ctx->eps = eps;
    fr_ctx_drop_workspace(ctx);
    if (law != FRICREG_LAW_QUINN) /* Stribeck friction is (4) with its own bound */
        fr_stribeck_off(ctx);
    fr_stribeck_refresh(ctx); /* k(eps) for the new eps */
    ctx->last_valid = 0;
    return FRICREG_OK;
}

int fricreg_ctx_set_partition(fricreg_ctx *ctx, int partition)
{
    if (ctx == NULL)
        return FRICREG_ENULL;
    if (partition != FRICREG_PARTITION_CONSISTENT && partition != FRICREG_PARTITION_PAPER)
        return fr_fail(ctx, FRICREG_EINVAL, "set_partition: unknown partition %d", partition);
    ctx->partition = partition;
    fr_ctx_forget_factor(ctx);
    ctx->last_valid = 0;
    return FRICREG_OK;
}

/* fr_check_contact_array on the context (contact_check.h). */
static int check_array(fricreg_ctx *ctx, const char *what, size_t m, size_t n, const double a[])
{
    if (ctx == NULL)
        return FRICREG_ENULL;
    return fr_check_contact_array(&ctx->err, what, m, ctx->m, n, a, INFINITY);
}

int fricreg_ctx_set_bounds(fricreg_ctx *ctx, size_t m, const double mun[])
{
    if (ctx == NULL)
        return FRICREG_ENULL;
    int status = fr_check_bounds(&ctx->err, m, ctx->m, mun, DBL_MAX); /* any finite bound */
    if (status != FRICREG_OK)
        return status;
    memcpy(ctx->mun, mun, m * sizeof *mun);
    fr_stribeck_off(ctx); /* the bounds mun replace Stribeck friction's */
    ctx->last_valid = 0;
    return FRICREG_OK;
}

int fricreg_ctx_set_coupling_diagonal(fricreg_ctx *ctx, size_t m, const double w[])
{
    int status = check_array(ctx, "set_coupling_diagonal", m, m, w);
    if (status != FRICREG_OK)
        return status;
    for (size_t i = 0; i < m; i++)
        if (!(w[i] > 0.0))
            return fr_fail(ctx, FRICREG_EINVAL, "set_coupling_diagonal: w[%zu] = %g must be > 0", i,
                           w[i]);
    fr_ctx_free_coupling(ctx);
    memcpy(ctx->w_diag, w, m * sizeof *w);
    ctx->w_unit = 1;
    for (size_t i = 0; i < m; i++)
        ctx->w_unit &= w[i] == 1.0;
    ctx->last_valid = 0;
    return FRICREG_OK;
}

/* Smallest eigenvalue of the Jacobi-scaled A = D^-1/2 W D^-1/2, a_ij = W_ij d_i d_j with
 * d_i = 1/sqrt(W_ii) (GSL's symmetric eigensolver). Unit diagonal and, checked before, entries
 * |a_ij| <= 1 (+ tolerance): nothing can overflow inside the solver. */
static int min_eigenvalue(const double W[], size_t m, const double d[], double *lambda_min)
{
    struct fr_eigen e;
    if (fr_eigen_alloc(&e, m) != FRICREG_OK)
        return FRICREG_ENOMEM;
    for (size_t i = 0; i < m; i++)
        for (size_t j = 0; j < m; j++)
            e.a[i * m + j] = W[i * m + j] * d[i] * d[j];
    int status = fr_eigen_solve(&e) ? FRICREG_ENOTPSD : FRICREG_OK;
    *lambda_min = e.eval[0];
    for (size_t i = 1; i < m && !isnan(*lambda_min); i++) /* a NaN is kept, to be refused */
        if (!(e.eval[i] >= *lambda_min))
            *lambda_min = e.eval[i];
    fr_eigen_free(&e);
    return status;
}

/* W is a Delassus matrix: positive diagonal, symmetric, positive semidefinite. Semidefiniteness
 * is judged on the Jacobi-scaled A = D^-1/2 W D^-1/2 (unit diagonal), as eval judges
 * singularity: whatever each contact's units. A tolerance relative to max|W| instead let a
 * contact whose W_ii is tiny next to the others pass with a strongly indefinite coupling
 * (W = [[2.385, -1e-12], [-1e-12, 1e-270]]: found by tests/fuzz/fuzz_ctx.c), and eval then
 * returned forces that are not the law. */
static int check_delassus(fricreg_ctx *ctx, size_t m, const double W[])
{
    const char *who = "set_coupling_dense";
    /* A mobility must be a normal double: 1/W_ii beyond DBL_MAX made the tangent's -W_FF^-1
     * Inf, and 0 * Inf NaN (W = diag(2.385, 4.9e-324): fuzz finding). */
    for (size_t i = 0; i < m; i++)
        if (!(W[i * m + i] >= DBL_MIN))
            return fr_fail(ctx, FRICREG_ENOTPSD, "%s: W[%zu][%zu] = %g must be >= %g", who, i, i,
                           W[i * m + i], DBL_MIN);
    double *d = malloc(m * sizeof *d);
    if (d == NULL)
        return fr_fail(ctx, FRICREG_ENOMEM, "%s: out of memory", who);
    for (size_t i = 0; i < m; i++)
        d[i] = 1.0 / sqrt(W[i * m + i]); /* W_ii >= DBL_MIN gives d_i <= 6.7e153 */
    /* Symmetry on the scaled A too: relative to max|W| it let W_01 = 3.6e5, W_10 = -2.4e5
     * pass beside W_22 = 2.9e197 (tests/fuzz/fuzz_ctx.c), and eval, which reads one triangle
     * in its factor and whole rows elsewhere, returned forces that are not the law. */
    for (size_t i = 0; i < m; i++)
        for (size_t j = i + 1; j < m; j++)
            if (fabs(W[i * m + j] - W[j * m + i]) * d[i] * d[j] > SYMMETRY_RTOL) {
                free(d);
                return fr_fail(ctx, FRICREG_ENOTSYM, "%s: W[%zu][%zu] = %g but W[%zu][%zu] = %g",
                               who, i, j, W[i * m + j], j, i, W[j * m + i]);
            }
    /* |a_ij| > 1 is a negative 2x2 minor W_ii W_jj - W_ij^2; checked first because such an
     * a_ij may be too large for the eigensolver (infinite, even). */
    double tol = PSD_RTOL * (double)m;
    for (size_t i = 0; i < m; i++)
        for (size_t j = 0; j < m; j++)
            if (!(fabs(W[i * m + j] * d[i] * d[j]) <= 1.0 + tol)) {
                free(d);
                return fr_fail(ctx, FRICREG_ENOTPSD,
                               "%s: W[%zu][%zu]^2 > W[%zu][%zu] W[%zu][%zu]: not semidefinite", who,
                               i, j, i, i, j, j);
            }
    double lambda_min = 0.0; /* of the scaled A: NaN-safe test, a NaN is refused */
    int status = min_eigenvalue(W, m, d, &lambda_min);
    free(d);
    if (status == FRICREG_ENOMEM)
        return fr_fail(ctx, status, "%s: out of memory", who);
    if (status != FRICREG_OK || !(lambda_min >= -tol))
        return fr_fail(ctx, FRICREG_ENOTPSD,
                       "%s: smallest eigenvalue %g of D^-1/2 W D^-1/2 (D = diag W) is negative",
                       who, lambda_min);
    return FRICREG_OK;
}

int fricreg_ctx_set_coupling_dense(fricreg_ctx *ctx, size_t m, const double W[])
{
    if (m > 0 && m > SIZE_MAX / m)
        return ctx ? fr_fail(ctx, FRICREG_ESIZE, "set_coupling_dense: m = %zu", m) : FRICREG_ENULL;
    int status = check_array(ctx, "set_coupling_dense", m, m * m, W);
    if (status == FRICREG_OK)
        status = check_delassus(ctx, m, W);
    if (status != FRICREG_OK)
        return status;

    double *copy = malloc(m * m * sizeof *copy);
    double *rhs = malloc(m * sizeof *rhs);
    struct fr_factor fac;
    struct fr_box_qp qp;
    int fac_status = fr_factor_alloc(&fac, m), qp_status = fr_box_qp_alloc(&qp, m);
    if (!copy || !rhs || fac_status != FRICREG_OK || qp_status != FRICREG_OK) {
        free(copy), free(rhs);
        fr_factor_free(&fac), fr_box_qp_free(&qp);
        return fr_fail(ctx, FRICREG_ENOMEM, "set_coupling_dense: out of memory for m = %zu", m);
    }
    fr_ctx_free_coupling(ctx);
    memcpy(copy, W, m * m * sizeof *W);
    for (size_t i = 0; i < m; i++)
        ctx->w_diag[i] = W[i * m + i];
    ctx->W = copy;
    ctx->rhs = rhs;
    ctx->fac = fac; /* not valid: nothing factored yet */
    ctx->qp = qp;
    ctx->last_valid = 0;
    return FRICREG_OK;
}

int fricreg_ctx_set_keep_tangent(fricreg_ctx *ctx, int keep)
{
    if (ctx == NULL)
        return FRICREG_ENULL;
    if (keep != 0 && keep != 1)
        return fr_fail(ctx, FRICREG_EINVAL, "set_keep_tangent: keep = %d must be 0 or 1", keep);
    ctx->keep_tangent = keep;
    ctx->last_valid = 0;
    return FRICREG_OK;
}

int fricreg_ctx_get_stat(const fricreg_ctx *ctx, int which, int64_t *value)
{
    if (ctx == NULL || value == NULL)
        return FRICREG_ENULL;
    if (which < 0 || which >= FR_NSTATS)
        return FRICREG_EINVAL;
    *value = ctx->stats[which];
    return FRICREG_OK;
}

void fricreg_ctx_reset_stats(fricreg_ctx *ctx)
{
    if (ctx != NULL)
        memset(ctx->stats, 0, sizeof ctx->stats);
}

FR_ERROR_GETTERS(fricreg_ctx, "NULL context")
