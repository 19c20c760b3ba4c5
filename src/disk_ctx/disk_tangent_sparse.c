/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_tangent_sparse.c — fricreg_disk_ctx_tangent with a sparse W: the KKT conditions of
 * disk_tangent.c differentiated in each contact's frame (disk_factor.h), so that the circle's
 * multiplier drops out and the matrix is the reduced Hessian of Newton's method, sparse,
 * symmetric positive definite, factored by CHOLMOD.
 *
 * At the solution, a near-stick contact's stationarity (W f)_i + a_free,i + 2 W_ii p_i +
 * lam_i (f_i + p_i) = 0 and, on its circle, |f_i + p_i| = radius_i, differentiated in a
 * parameter: with df_i = n_i alpha_i + t_i x_i on a circle (n_i the normal, t_i the tangent),
 * the circle gives alpha_i = d radius_i - n_i . dp_i (fr_disk_normal_rate), and the tangential
 * part of stationarity no longer holds d lam_i (t_i . (f_i + p_i) = 0):
 *     t_i . [(W df)_i + 2 W_ii dp_i + lam_i (df_i + dp_i) + d a_free,i] = 0;
 * a free contact keeps both rows. So H x = -Q^T (W delta + e), delta the known parts of df
 * (the circle contacts' normal ones, a fixed contact's own slope) and e the direct terms, one
 * parameter's at a time: 4m solves with one factor, each O(entries of the factor), and the
 * outputs' (2m)^2 entries, the caller's memory. */
#include <math.h>
#include <string.h>

#include "disk_ctx_internal.h"

int fr_disk_tangent_sparse_factor(fricreg_disk_ctx *ctx)
{
    struct fr_disk_coupled *cpl = ctx->cpl;
    for (size_t k = 0; k < ctx->n_near; k++)
        if (ctx->kind[ctx->near[k]] == FR_DISK_CIRCLE)
            fr_disk_normal(ctx, ctx->near[k], cpl->nrm + 2 * ctx->near[k]);
    size_t pivot = 0;
    if (fr_disk_factor_build(&cpl->F, &cpl->w, ctx->kind, cpl->nrm, ctx->lam, &pivot) != FRICREG_OK)
        return fr_fail(ctx, FRICREG_ESINGULAR,
                       "tangent: the reduced KKT matrix of the near-stick contacts is singular "
                       "(a pivot of its LDL^T factor at contact %zu)",
                       pivot);
    return FRICREG_OK;
}

/* The known part delta of df_j and the direct term e at contact j for the parameter zdot_{j,b}
 * or a_free_{j,b}. */
static void parameter_terms(const fricreg_disk_ctx *ctx, size_t j, int b, int afree,
                            double delta[2], double e[2])
{
    delta[0] = delta[1] = e[0] = e[1] = 0.0;
    if (ctx->kind[j] == FR_DISK_FIXED) {
        double D[4];
        if (afree)
            return; /* a fixed force does not see a_free */
        fr_disk_fixed_jacobian(ctx, j, D);
        delta[0] = D[b], delta[1] = D[2 + b];
        return;
    }
    if (afree) {
        e[b] = 1.0;
        return;
    }
    double P[4];
    fr_disk_centre_jacobian(ctx, j, P);
    const double *A = ctx->blk + 4 * j;
    double lam = ctx->kind[j] == FR_DISK_CIRCLE ? ctx->lam[j] : 0.0;
    for (int a = 0; a < 2; a++)
        e[a] = (2.0 * A[2 * a] + (a == 0 ? lam : 0.0)) * P[b] +
               (2.0 * A[2 * a + 1] + (a == 1 ? lam : 0.0)) * P[2 + b];
    if (ctx->kind[j] == FR_DISK_CIRCLE) {
        double n[2], alpha = fr_disk_normal_rate(ctx, j, b, P);
        fr_disk_normal(ctx, j, n);
        delta[0] = alpha * n[0], delta[1] = alpha * n[1];
    }
}

/* The right-hand side -Q_i^T (W_ij delta + [i = j] e) of every near-stick i coupled to j, into
 * rhs (zeroed first), in the contacts' frames (a circle's normal unknown 0). */
static void parameter_rhs(fricreg_disk_ctx *ctx, size_t j, const double delta[2], const double e[2],
                          double *rhs)
{
    const struct fr_disk_coupling *w = &ctx->cpl->w;
    memset(rhs, 0, 2 * ctx->m * sizeof *rhs);
    for (int64_t k = w->ptr[j]; k < w->ptr[j + 1]; k++) {
        size_t i = (size_t)w->col[k];
        if (ctx->kind[i] == FR_DISK_FIXED)
            continue;
        const double *b = w->blk + 4 * k; /* W_ji; W_ij is its transpose */
        double v0 = b[0] * delta[0] + b[2] * delta[1], v1 = b[1] * delta[0] + b[3] * delta[1];
        if (i == j)
            v0 += e[0], v1 += e[1];
        if (ctx->kind[i] == FR_DISK_FREE) {
            rhs[2 * i] = -v0, rhs[2 * i + 1] = -v1;
        } else {
            const double *n = ctx->cpl->nrm + 2 * i;
            rhs[2 * i + 1] = -(-n[1] * v0 + n[0] * v1);
        }
    }
}

/* The solved column back in the plane, df_i = Q_i x_i (+ delta at j), into x. */
static void parameter_solution(fricreg_disk_ctx *ctx, size_t j, const double delta[2], double *x)
{
    for (size_t k = 0; k < ctx->n_near; k++) {
        size_t i = ctx->near[k];
        if (ctx->kind[i] == FR_DISK_CIRCLE) {
            const double *n = ctx->cpl->nrm + 2 * i;
            double xt = x[2 * i + 1];
            x[2 * i] = -n[1] * xt, x[2 * i + 1] = n[0] * xt;
        }
    }
    x[2 * j] += delta[0], x[2 * j + 1] += delta[1];
}

/* Column 2j+b of out from x (near-stick rows, and j's own); or whether those are finite. */
static int write_column(const fricreg_disk_ctx *ctx, size_t j, int b, const double *x, double *out)
{
    size_t m2 = 2 * ctx->m, col = 2 * j + (size_t)b;
    int finite = isfinite(x[2 * j]) && isfinite(x[2 * j + 1]);
    for (size_t k = 0; k < ctx->n_near; k++) {
        size_t i = ctx->near[k];
        finite = finite && isfinite(x[2 * i]) && isfinite(x[2 * i + 1]);
        if (out != NULL)
            out[2 * i * m2 + col] = x[2 * i], out[(2 * i + 1) * m2 + col] = x[2 * i + 1];
    }
    if (out != NULL && ctx->kind[j] == FR_DISK_FIXED)
        out[2 * j * m2 + col] = x[2 * j], out[(2 * j + 1) * m2 + col] = x[2 * j + 1];
    return finite;
}

/* Columns 2j, 2j+1 of one output; dry: nothing written, whether all are finite. */
static int fill_columns(fricreg_disk_ctx *ctx, size_t j, int afree, double *out, int dry)
{
    double *x = ctx->cpl->trial;
    for (int b = 0; b < 2; b++) {
        double delta[2], e[2];
        parameter_terms(ctx, j, b, afree, delta, e);
        parameter_rhs(ctx, j, delta, e, x);
        fr_disk_factor_solve(&ctx->cpl->F, x, x); /* its buffers are held: cannot fail */
        parameter_solution(ctx, j, delta, x);
        if (!write_column(ctx, j, b, x, dry ? NULL : out) && dry)
            return 0;
    }
    return 1;
}

int fr_disk_tangent_sparse(fricreg_disk_ctx *ctx, double *dz, double *da, int dry)
{
    int finite = 1;
    for (size_t j = 0; j < ctx->m && finite; j++) {
        if (dz != NULL)
            finite = fill_columns(ctx, j, 0, dz, dry);
        if (da != NULL && finite)
            finite = fill_columns(ctx, j, 1, da, dry);
    }
    return finite;
}
