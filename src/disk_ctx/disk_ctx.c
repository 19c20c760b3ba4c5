/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_ctx.c — the 2-D context's life cycle, setters and error state (fricreg_disk_ctx.h).
 * Evaluation: disk_qp.c; tangent: disk_tangent.c. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "disk_ctx_internal.h"
#include "base/eigen.h"
#include "base/gsl_mem.h"
#include "law/contact_check.h"
#include "law/law.h"
#include "law/law_disk.h"

#define SYMMETRY_RTOL 1e-12
#define BLOCK_PD_RTOL 1e-12 /* smallest eigenvalue of a block over its largest */
#define PSD_RTOL 1e-12

static void free_kkt(fricreg_disk_ctx *ctx)
{
    free(ctx->kkt);
    free(ctx->tau);
    free(ctx->col);
    ctx->kkt = ctx->tau = ctx->col = NULL;
    ctx->kkt_max = 0;
}

/* The tangent's KKT storage for systems of order n (3 per contact at most). */
static int alloc_kkt(fricreg_disk_ctx *ctx, size_t n)
{
    double *kkt = malloc(n * n * sizeof *kkt), *tau = malloc(n * sizeof *tau);
    double *col = malloc(n * sizeof *col);
    if (!kkt || !tau || !col) {
        free(kkt), free(tau), free(col);
        return FRICREG_ENOMEM;
    }
    free_kkt(ctx);
    ctx->kkt = kkt, ctx->tau = tau, ctx->col = col;
    ctx->kkt_max = n;
    return FRICREG_OK;
}

void fricreg_disk_ctx_free(fricreg_disk_ctx *ctx)
{
    if (ctx == NULL)
        return;
    free_kkt(ctx);
    free(ctx->mun), free(ctx->eig), free(ctx->blk), free(ctx->W);
    fr_disk_coupled_free(ctx->cpl);
    free(ctx->f), free(ctx->f_last), free(ctx->g), free(ctx->p), free(ctx->u);
    free(ctx->r), free(ctx->radius), free(ctx->lam), free(ctx->kind), free(ctx->near);
    free(ctx->bound), free(ctx->strib), free(ctx->strib_keps);
    free(ctx->last_zdot), free(ctx->last_afree);
    free(ctx->row), free(ctx->mrow);
    free(ctx->brent);
    free(ctx);
}

int fricreg_disk_ctx_create(size_t m, fricreg_disk_ctx **out)
{
    if (out == NULL)
        return FRICREG_ENULL;
    if (m == 0 || m > FR_DISK_CTX_MAX)
        return FRICREG_EINVAL;
    fricreg_disk_ctx *ctx = calloc(1, sizeof *ctx);
    if (ctx == NULL)
        return FRICREG_ENOMEM;
    ctx->m = m;
    ctx->law = FRICREG_DISK_QUINN;
    ctx->eps = 1e-3;
    ctx->mun = malloc(m * sizeof *ctx->mun);
    ctx->eig = malloc(m * sizeof *ctx->eig);
    ctx->blk = malloc(4 * m * sizeof *ctx->blk);
    ctx->f = malloc(2 * m * sizeof *ctx->f);
    ctx->f_last = malloc(2 * m * sizeof *ctx->f_last);
    ctx->g = malloc(2 * m * sizeof *ctx->g);
    ctx->p = malloc(2 * m * sizeof *ctx->p);
    ctx->u = malloc(2 * m * sizeof *ctx->u);
    ctx->r = malloc(m * sizeof *ctx->r);
    ctx->radius = malloc(m * sizeof *ctx->radius);
    ctx->lam = malloc(m * sizeof *ctx->lam);
    ctx->bound = malloc(m * sizeof *ctx->bound);
    ctx->kind = malloc(m * sizeof *ctx->kind);
    ctx->near = malloc(m * sizeof *ctx->near);
    ctx->row = malloc(m * sizeof *ctx->row);
    ctx->mrow = malloc(m * sizeof *ctx->mrow);
    ctx->last_zdot = malloc(2 * m * sizeof *ctx->last_zdot);
    ctx->last_afree = malloc(2 * m * sizeof *ctx->last_afree);
    ctx->brent = fr_gsl_brent_new();
    if (!ctx->mun || !ctx->eig || !ctx->blk || !ctx->f || !ctx->f_last || !ctx->g || !ctx->p ||
        !ctx->u || !ctx->r || !ctx->radius || !ctx->lam || !ctx->bound || !ctx->kind ||
        !ctx->near || !ctx->row || !ctx->mrow || !ctx->last_zdot || !ctx->last_afree ||
        !ctx->brent || alloc_kkt(ctx, 3) != FRICREG_OK) {
        fricreg_disk_ctx_free(ctx);
        return FRICREG_ENOMEM;
    }
    for (size_t i = 0; i < m; i++) {
        ctx->mun[i] = 1.0;
        ctx->blk[4 * i] = ctx->blk[4 * i + 3] = 1.0;
        ctx->blk[4 * i + 1] = ctx->blk[4 * i + 2] = 0.0;
        fr_disk_eig2(1.0, 0.0, 1.0, &ctx->eig[i]);
    }
    *out = ctx;
    return FRICREG_OK;
}

size_t fricreg_disk_ctx_size(const fricreg_disk_ctx *ctx)
{
    return ctx ? ctx->m : 0;
}

int fricreg_disk_ctx_set_law(fricreg_disk_ctx *ctx, int law, double eps)
{
    if (ctx == NULL)
        return FRICREG_ENULL;
    if (law != FRICREG_DISK_QUINN && law != FRICREG_DISK_FORCE_BALANCE)
        return fr_fail(ctx, FRICREG_EINVAL,
                       "set_law: law %d has no coupled form (quinn or force-balance)", law);
    if (!isfinite(eps))
        return fr_fail(ctx, FRICREG_ENONFINITE, "set_law: eps is not finite");
    if (!fr_eps_valid(eps) || eps > FR_DISK_MAX)
        return fr_fail(ctx, FRICREG_EINVAL, "set_law: eps = %g must be in [DBL_MIN, 1e250]", eps);
    ctx->law = law;
    ctx->eps = eps;
    if (law != FRICREG_DISK_QUINN) /* Stribeck friction is FRICREG_DISK_QUINN's, with its bound */
        ctx->stribeck = 0;
    fr_disk_stribeck_refresh(ctx); /* k(eps) for the new eps */
    ctx->last_valid = 0;
    return FRICREG_OK;
}

/* fr_check_contact_array on the context (contact_check.h). */
static int check_array(fricreg_disk_ctx *ctx, const char *what, size_t m, size_t n,
                       const double a[])
{
    if (ctx == NULL)
        return FRICREG_ENULL;
    return fr_check_contact_array(&ctx->err, what, m, ctx->m, n, a, FR_DISK_MAX);
}

int fricreg_disk_ctx_set_bounds(fricreg_disk_ctx *ctx, size_t m, const double mun[])
{
    if (ctx == NULL)
        return FRICREG_ENULL;
    int status = fr_check_bounds(&ctx->err, m, ctx->m, mun, FR_DISK_MAX); /* the 2-D kernels' */
    if (status != FRICREG_OK)
        return status;
    memcpy(ctx->mun, mun, m * sizeof *mun);
    ctx->stribeck = 0; /* the bounds mun replace Stribeck friction's */
    ctx->last_valid = 0;
    return FRICREG_OK;
}

int fr_disk_check_block(fricreg_disk_ctx *ctx, const char *who, size_t i, double a, double b,
                        double c, double d, struct fr_disk_eig *e)
{
    double scale = fmax(fmax(fabs(a), fabs(d)), fmax(fabs(b), fabs(c)));
    if (fabs(b - c) > SYMMETRY_RTOL * scale)
        return fr_fail(ctx, FRICREG_ENOTSYM,
                       "%s: block of contact %zu is not symmetric "
                       "(%g, %g)",
                       who, i, b, c);
    if (!(a > 0.0 && d > 0.0))
        return fr_fail(ctx, FRICREG_ENOTPSD,
                       "%s: block of contact %zu has a diagonal "
                       "entry <= 0",
                       who, i);
    /* Scaled by its largest diagonal entry: no overflow in the rotation. */
    double s = fmax(a, d);
    fr_disk_eig2(a / s, 0.5 * (b + c) / s, d / s, e);
    double lo = fmin(e->d1, e->d2), hi = fmax(e->d1, e->d2);
    if (!(lo > BLOCK_PD_RTOL * hi))
        return fr_fail(ctx, FRICREG_ENOTPSD,
                       "%s: block of contact %zu is not positive "
                       "definite (eigenvalues %g, %g of the block over %g)",
                       who, i, lo, hi, s);
    if (!(lo * s >= DBL_MIN)) /* as fricreg_ctx_set_coupling_dense's W_ii >= DBL_MIN */
        return fr_fail(ctx, FRICREG_ENOTPSD,
                       "%s: block of contact %zu has the eigenvalue %g < DBL_MIN: no "
                       "mobility (its inverse, the tangent's scale, overflows)",
                       who, i, lo * s);
    e->d1 *= s;
    e->d2 *= s;
    return FRICREG_OK;
}

int fricreg_disk_ctx_set_coupling_blocks(fricreg_disk_ctx *ctx, size_t m, const double w[])
{
    const char *who = "set_coupling_blocks";
    if (ctx != NULL && m != ctx->m)
        return fr_fail(ctx, FRICREG_ESIZE, "%s: m = %zu, context has %zu contacts", who, m, ctx->m);
    int status = check_array(ctx, who, m, 4 * m, w);
    if (status != FRICREG_OK)
        return status;
    for (size_t i = 0; i < m; i++) {
        struct fr_disk_eig e;
        status = fr_disk_check_block(ctx, who, i, w[4 * i], w[4 * i + 1], w[4 * i + 2],
                                     w[4 * i + 3], &e);
        if (status != FRICREG_OK)
            return status;
    }
    if (alloc_kkt(ctx, 3) != FRICREG_OK)
        return fr_fail(ctx, FRICREG_ENOMEM, "%s: out of memory", who);
    for (size_t i = 0; i < m; i++)
        fr_disk_check_block(ctx, who, i, w[4 * i], w[4 * i + 1], w[4 * i + 2], w[4 * i + 3],
                            &ctx->eig[i]);
    memcpy(ctx->blk, w, 4 * m * sizeof *w);
    free(ctx->W);
    ctx->W = NULL;
    fr_disk_coupled_free(ctx->cpl);
    ctx->cpl = NULL;
    ctx->last_valid = 0;
    return FRICREG_OK;
}

/* The smallest eigenvalue of the Jacobi-scaled D^-1/2 W D^-1/2 (n = 2m, unit diagonal), by
 * GSL's symmetric eigensolver (eigen.h). */
static int scaled_min_eigenvalue(const double W[], size_t n, double *lambda_min)
{
    struct fr_eigen e;
    if (fr_eigen_alloc(&e, n) != FRICREG_OK)
        return FRICREG_ENOMEM;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++)
            e.a[i * n + j] = W[i * n + j] / sqrt(W[i * n + i]) / sqrt(W[j * n + j]);
    int status = fr_eigen_solve(&e) ? FRICREG_ENOTPSD : FRICREG_OK;
    double lo = e.eval[0];
    for (size_t i = 1; i < n && !isnan(lo); i++)
        if (!(e.eval[i] >= lo))
            lo = e.eval[i];
    fr_eigen_free(&e);
    *lambda_min = lo;
    return status;
}

/* W is symmetric, its diagonal blocks positive definite, and W positive semidefinite. */
static int check_dense(fricreg_disk_ctx *ctx, const char *who, size_t m, const double W[])
{
    size_t n = 2 * m;
    double scale = 0.0;
    for (size_t k = 0; k < n * n; k++)
        scale = fmax(scale, fabs(W[k]));
    for (size_t i = 0; i < n; i++)
        for (size_t j = i + 1; j < n; j++)
            if (fabs(W[i * n + j] - W[j * n + i]) > SYMMETRY_RTOL * scale)
                return fr_fail(ctx, FRICREG_ENOTSYM,
                               "%s: W[%zu][%zu] = %g but W[%zu][%zu] "
                               "= %g",
                               who, i, j, W[i * n + j], j, i, W[j * n + i]);
    for (size_t i = 0; i < m; i++) {
        struct fr_disk_eig e;
        const double *b = W + 2 * i * n + 2 * i;
        int status = fr_disk_check_block(ctx, who, i, b[0], b[1], b[n], b[n + 1], &e);
        if (status != FRICREG_OK)
            return status;
    }
    /* |a_ij| > 1 after scaling is a negative 2x2 minor; checked first because such an entry
     * may be too large for the eigensolver. */
    double tol = PSD_RTOL * (double)n;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++)
            if (!(fabs(W[i * n + j] / sqrt(W[i * n + i]) / sqrt(W[j * n + j])) <= 1.0 + tol))
                return fr_fail(ctx, FRICREG_ENOTPSD,
                               "%s: W[%zu][%zu]^2 > W[%zu][%zu] "
                               "W[%zu][%zu]: not semidefinite",
                               who, i, j, i, i, j, j);
    double lambda_min = 0.0;
    int status = scaled_min_eigenvalue(W, n, &lambda_min);
    if (status == FRICREG_ENOMEM)
        return fr_fail(ctx, status, "%s: out of memory", who);
    if (status != FRICREG_OK || !(lambda_min >= -tol))
        return fr_fail(ctx, FRICREG_ENOTPSD,
                       "%s: smallest eigenvalue %g of D^-1/2 W "
                       "D^-1/2 (D = diag W) is negative",
                       who, lambda_min);
    return FRICREG_OK;
}

int fricreg_disk_ctx_set_coupling_dense(fricreg_disk_ctx *ctx, size_t m, const double W[])
{
    const char *who = "set_coupling_dense";
    if (ctx == NULL)
        return FRICREG_ENULL;
    if (m != ctx->m) /* before m*m: a huge m must not overflow */
        return fr_fail(ctx, FRICREG_ESIZE, "%s: m = %zu, context has %zu contacts", who, m, ctx->m);
    size_t n = 2 * m;
    if (n > SIZE_MAX / n / sizeof(double) / 3)
        return fr_fail(ctx, FRICREG_ESIZE, "%s: m = %zu is too large for a dense W", who, m);
    int status = check_array(ctx, who, m, n * n, W);
    if (status == FRICREG_OK)
        status = check_dense(ctx, who, m, W);
    if (status != FRICREG_OK)
        return status;
    struct fr_disk_coupled *cpl = fr_disk_coupled_new(m);
    double *copy = malloc(n * n * sizeof *copy);
    if (cpl == NULL || copy == NULL || fr_disk_coupling_from_dense(&cpl->w, m, W) != FRICREG_OK ||
        fr_disk_factor_setup(&cpl->F, &cpl->w, FR_DISK_STORAGE_CHOSEN) != FRICREG_OK ||
        alloc_kkt(ctx, 3 * m) != FRICREG_OK) {
        free(copy);
        fr_disk_coupled_free(cpl);
        return fr_fail(ctx, FRICREG_ENOMEM, "%s: out of memory for m = %zu", who, m);
    }
    memcpy(copy, W, n * n * sizeof *W);
    fr_disk_install_coupled(ctx, cpl, copy);
    return FRICREG_OK;
}

void fr_disk_install_coupled(fricreg_disk_ctx *ctx, struct fr_disk_coupled *cpl, double *W)
{
    const struct fr_disk_coupling *w = &cpl->w;
    free(ctx->W);
    fr_disk_coupled_free(ctx->cpl);
    ctx->W = W;
    ctx->cpl = cpl;
    for (size_t i = 0; i < ctx->m; i++) {
        const double *b = w->blk + 4 * w->diag[i];
        memcpy(ctx->blk + 4 * i, b, 4 * sizeof *b);
        fr_disk_check_block(ctx, "set_coupling", i, b[0], b[1], b[2], b[3], &ctx->eig[i]);
    }
    ctx->last_valid = 0;
}

FR_ERROR_GETTERS(fricreg_disk_ctx, "NULL context")
