/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_slopes.c — each contact's own derivatives at the last evaluation's solution, which both
 * tangents (disk_tangent.c for dense and block W, disk_tangent_sparse.c for sparse W) build
 * their right-hand sides from (disk_ctx_internal.h). */
#include <math.h>

#include "disk_ctx_internal.h"

/* d p_i / d zdot_i, row-major 2x2: p = B zdot/eps (FRICREG_DISK_QUINN in the band and at
 * rest; 0 for the force balance) with the bound B = mun, or the Stribeck bound B(|zdot|),
 * whose slope B' adds (|zdot|/eps) B' u u^T (0 at rest). */
void fr_disk_centre_jacobian(const fricreg_disk_ctx *ctx, size_t i, double P[4])
{
    double s = ctx->law == FRICREG_DISK_QUINN ? ctx->bound[i] / ctx->eps : 0.0;
    double q = ctx->law == FRICREG_DISK_QUINN && ctx->r[i] > 0.0
                   ? (ctx->r[i] / ctx->eps) * fr_disk_bound_slope(ctx, i, ctx->r[i])
                   : 0.0;
    const double *u = ctx->u + 2 * i;
    P[0] = s + q * u[0] * u[0], P[1] = q * u[0] * u[1];
    P[2] = P[1], P[3] = s + q * u[1] * u[1];
}

/* df_i/dzdot_i of a fixed contact: sliding, d(-B u) = -(B/|v|)(I - u u^T) - B'(|v|) u u^T
 * (B' = k' for Stribeck friction, else 0); -dp/dzdot on a point K_i; 0 for a bound 0. */
void fr_disk_fixed_jacobian(const fricreg_disk_ctx *ctx, size_t i, double D[4])
{
    double mun = ctx->bound[i], r = ctx->r[i];
    const double *u = ctx->u + 2 * i;
    int slides = ctx->law == FRICREG_DISK_QUINN ? r >= ctx->eps : r > 0.0;
    if (mun == 0.0) {
        D[0] = D[1] = D[2] = D[3] = 0.0;
    } else if (slides) {
        double k = -mun / r, kr = -fr_disk_bound_slope(ctx, i, r);
        D[0] = k * (1.0 - u[0] * u[0]) + kr * u[0] * u[0];
        D[1] = -k * u[0] * u[1] + kr * u[0] * u[1];
        D[2] = D[1], D[3] = k * (1.0 - u[1] * u[1]) + kr * u[1] * u[1];
    } else {
        double P[4];
        fr_disk_centre_jacobian(ctx, i, P);
        D[0] = -P[0], D[1] = -P[1], D[2] = -P[2], D[3] = -P[3];
    }
}

/* The unit normal of a circle contact; at rest (u = 0) the direction it will slide is -n. */
void fr_disk_normal(const fricreg_disk_ctx *ctx, size_t i, double n[2])
{
    const double *f = ctx->f + 2 * i, *p = ctx->p + 2 * i;
    double y0 = f[0] + p[0], y1 = f[1] + p[1], ny = hypot(y0, y1);
    n[0] = y0 / ny;
    n[1] = y1 / ny;
}

double fr_disk_normal_rate(const fricreg_disk_ctx *ctx, size_t j, int b, const double P[4])
{
    /* n^T df = d radius - n^T dp, radius = B (1 - r/eps), r = |zdot_j|:
     * d radius = (B' (1 - r/eps) - B/eps) u^T dzdot; at rest u := -n (the direction the
     * contact will slide), where the constant bound's terms cancel. */
    double nv[2];
    fr_disk_normal(ctx, j, nv);
    double r = ctx->r[j], rho = ctx->law == FRICREG_DISK_QUINN ? r / ctx->eps : 0.0;
    double ub = r > 0.0 ? ctx->u[2 * j + (size_t)b] : -nv[b];
    double s = ctx->law == FRICREG_DISK_QUINN ? ctx->bound[j] / ctx->eps : 0.0;
    double dB = ctx->law == FRICREG_DISK_QUINN ? fr_disk_bound_slope(ctx, j, r) : 0.0;
    double d_radius = (dB * (1.0 - rho) - s) * ub;
    return d_radius - (nv[0] * P[b] + nv[1] * P[2 + b]);
}
