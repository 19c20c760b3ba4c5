/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_polish.c — Newton's method on the KKT conditions of the coupled 2-D law's QP for the
 * active set that block Gauss-Seidel has identified (disk_qp.c): near-stick contacts inside
 * their disks (stationarity rows only) and on their circles (stationarity with the multiplier
 * lam_i, and |f_i + p_i| = radius_i). Gauss-Seidel converges linearly, slowly when W couples
 * the contacts strongly; once its active set is right, Newton converges quadratically to the
 * QP's solution to rounding. The caller keeps the result only if it is consistent (every
 * lam_i >= 0, every free contact inside its disk) and a Gauss-Seidel sweep from it moves no
 * force (disk_qp.c), so a wrong active set costs time, never accuracy. */
#include <math.h>
#include <string.h>

#include <gsl/gsl_linalg.h>

#include "disk_ctx_internal.h"
#include "disk_polish.h"

#define NEWTON_MAX_ITER 8
#define NEWTON_TOL 1e-15   /* a step below this times the bound: converged */
#define NEWTON_STALL 1e-10 /* below this, a step that stops shrinking is rounding */
#define PIVOT_RTOL 1e-13
/* Beyond this many near-stick contacts a dense QR of order up to 3x it (O(n^3) a step) costs
 * more than the sweeps it saves: Gauss-Seidel alone. */
#define POLISH_MAX_NEAR 200

/* The KKT residual into ctx->col (negated: the Newton right-hand side) and the Jacobian
 * [[W_SS + diag(lam_i I), Y], [Y^T, 0]], Y the columns f_i + p_i, into ctx->kkt. */
static void linearize(fricreg_disk_ctx *ctx, size_t n)
{
    double *J = ctx->kkt, *r = ctx->col;
    memset(J, 0, n * n * sizeof *J);
    for (size_t k = 0; k < ctx->n_near; k++) {
        size_t i = ctx->near[k], ri = ctx->row[i];
        const double *p = ctx->p + 2 * i, *fi = ctx->f + 2 * i;
        double y[2] = {fi[0] + p[0], fi[1] + p[1]};
        for (int a = 0; a < 2; a++) {
            double s = ctx->g[2 * i + a]; /* a_free + the fixed contacts' share */
            for (int b = 0; b < 2; b++)
                s += 2.0 * ctx->blk[4 * i + 2 * a + b] * p[b];
            for (size_t l = 0; l < ctx->n_near; l++) {
                size_t j = ctx->near[l], rj = ctx->row[j];
                for (int b = 0; b < 2; b++) {
                    double w = fr_disk_w(ctx, i, a, j, b);
                    s += w * ctx->f[2 * j + b];
                    J[(ri + a) * n + rj + b] = w;
                }
            }
            if (ctx->kind[i] == FR_DISK_CIRCLE) {
                s += ctx->lam[i] * y[a];
                J[(ri + a) * n + ri + a] += ctx->lam[i];
                J[(ri + a) * n + ctx->mrow[i]] = y[a];
                J[ctx->mrow[i] * n + ri + a] = y[a];
            }
            r[ri + a] = -s;
        }
        if (ctx->kind[i] == FR_DISK_CIRCLE)
            r[ctx->mrow[i]] = -0.5 * (hypot(y[0], y[1]) - ctx->radius[i]) *
                              (hypot(y[0], y[1]) + ctx->radius[i]);
    }
}

/* One Newton step; returns the largest force change over its bound, or -1 if the KKT matrix
 * is singular to the pivot test. */
static double newton_step(fricreg_disk_ctx *ctx, size_t n)
{
    linearize(ctx, n);
    gsl_matrix_view A = gsl_matrix_view_array(ctx->kkt, n, n);
    gsl_vector_view tau = gsl_vector_view_array(ctx->tau, n);
    gsl_vector_view x = gsl_vector_view_array(ctx->col, n);
    gsl_linalg_QR_decomp(&A.matrix, &tau.vector);
    double big = 0.0;
    for (size_t k = 0; k < n; k++)
        big = fmax(big, fabs(ctx->kkt[k * n + k]));
    for (size_t k = 0; k < n; k++)
        if (!(fabs(ctx->kkt[k * n + k]) > PIVOT_RTOL * big))
            return -1.0;
    gsl_linalg_QR_svx(&A.matrix, &tau.vector, &x.vector);
    double moved = 0.0;
    for (size_t k = 0; k < ctx->n_near; k++) {
        size_t i = ctx->near[k], ri = ctx->row[i];
        ctx->f[2 * i] += ctx->col[ri];
        ctx->f[2 * i + 1] += ctx->col[ri + 1];
        moved = fmax(moved, hypot(ctx->col[ri], ctx->col[ri + 1]) / ctx->bound[i]);
        if (ctx->kind[i] == FR_DISK_CIRCLE)
            ctx->lam[i] += ctx->col[ctx->mrow[i]];
    }
    return moved;
}

/* Whether the Newton point fits its active set: multipliers >= 0, free contacts inside. */
static int consistent(const fricreg_disk_ctx *ctx)
{
    for (size_t k = 0; k < ctx->n_near; k++) {
        size_t i = ctx->near[k];
        const double *fi = ctx->f + 2 * i, *p = ctx->p + 2 * i;
        double d = hypot(fi[0] + p[0], fi[1] + p[1]);
        if (!isfinite(d) || (ctx->kind[i] == FR_DISK_CIRCLE && !(ctx->lam[i] >= 0.0)) ||
            (ctx->kind[i] == FR_DISK_FREE && d > ctx->radius[i] * (1.0 + 1e-12)))
            return 0;
    }
    return 1;
}

int fr_disk_polish(fricreg_disk_ctx *ctx)
{
    if (ctx->n_near == 0 || ctx->n_near > POLISH_MAX_NEAR || 3 * ctx->n_near > ctx->kkt_max)
        return 0;
    size_t n = fr_disk_number_rows(ctx);
    memcpy(ctx->f_last, ctx->f, 2 * ctx->m * sizeof *ctx->f); /* to restore on failure */
    int ok = 0;
    double before = INFINITY;
    for (int it = 0; it < NEWTON_MAX_ITER; it++) {
        double moved = newton_step(ctx, n);
        if (!(moved >= 0.0))
            break;
        /* converged, or stalled at rounding (a step no longer shrinks quadratically: with
         * an ill-conditioned W the steps level off at about cond(W) DBL_EPSILON) */
        if (moved <= NEWTON_TOL || (moved <= NEWTON_STALL && moved > 0.25 * before)) {
            ok = consistent(ctx);
            break;
        }
        before = moved;
    }
    if (!ok)
        memcpy(ctx->f, ctx->f_last, 2 * ctx->m * sizeof *ctx->f);
    return ok;
}
