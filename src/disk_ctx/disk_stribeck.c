/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_stribeck.c — static > kinetic (Stribeck) friction in the 2-D context
 * (fricreg_disk_ctx_set_stribeck, fricreg_stribeck.h).
 *
 * The 2-D Stribeck law (fricreg_stribeck_disk_eval, law_stribeck.c) is FRICREG_DISK_QUINN
 * with a bound that depends on the contact's own speed r = |zdot|:
 *   r <  eps:  B(r) = fs + (k(eps) - fs) r/eps   (the band, law_stribeck.h),
 *   r >= eps:  k(r) = fk + (fs - fk) exp(-(r/vs)^delta),
 * and the inscribed disk with bound B is K = disk(-a u, B - a), a = B r/eps, while the sliding
 * force with bound k(r) is -k(r) u. The bound does not depend on f, so the coupled law is still
 * the convex QP of fricreg_disk_ctx.h with B_i in place of mun_i: classify (disk_qp.c) takes
 * the bound from here, and with isotropic blocks the context gives fricreg_stribeck_disk_eval's
 * numbers (the same kernels' arithmetic). */
#include <math.h>
#include <stdlib.h>

#include "disk_ctx_internal.h"
#include "fricreg_stribeck.h"
#include "law/contact_check.h"
#include "law/law_disk.h"

double fr_disk_bound(const fricreg_disk_ctx *ctx, size_t i, double r)
{
    if (!ctx->stribeck)
        return ctx->mun[i];
    const struct fr_stribeck *p = &ctx->strib[i];
    return r < ctx->eps ? fr_stribeck_band_bound(p, ctx->strib_keps[i], r / ctx->eps)
                        : fr_stribeck_kinetic(p, r);
}

/* In the band (k(eps) - fs)/eps, at r = 0 too (the one-sided slope along the direction the
 * contact will slide); outside it k'(r). */
double fr_disk_bound_slope(const fricreg_disk_ctx *ctx, size_t i, double r)
{
    if (!ctx->stribeck)
        return 0.0;
    const struct fr_stribeck *p = &ctx->strib[i];
    if (r < ctx->eps)
        return (ctx->strib_keps[i] - p->fs) / ctx->eps;
    return fr_stribeck_kinetic_slope(p, r);
}

void fr_disk_stribeck_refresh(fricreg_disk_ctx *ctx)
{
    for (size_t i = 0; ctx->stribeck && i < ctx->m; i++)
        ctx->strib_keps[i] = fr_stribeck_kinetic(&ctx->strib[i], ctx->eps);
}

/* The two arrays, at the first set-up only; the context is unchanged if one fails. */
static int allocate(fricreg_disk_ctx *ctx)
{
    if (ctx->strib != NULL)
        return FRICREG_OK;
    size_t m = ctx->m;
    struct fr_stribeck *strib = malloc(m * sizeof *strib);
    double *keps = malloc(m * sizeof *keps);
    if (!strib || !keps) {
        free(strib), free(keps);
        return fr_fail(ctx, FRICREG_ENOMEM, "set_stribeck: out of memory for m = %zu", m);
    }
    ctx->strib = strib;
    ctx->strib_keps = keps;
    return FRICREG_OK;
}

int fricreg_disk_ctx_set_stribeck(fricreg_disk_ctx *ctx, size_t m, const double fs[],
                                  const double fk[], const double vs[], const double delta[])
{
    if (ctx == NULL)
        return FRICREG_ENULL;
    if (m == 0) { /* the way back: the bounds of set_bounds */
        ctx->stribeck = 0;
        ctx->last_valid = 0;
        return FRICREG_OK;
    }
    int status = fr_check_stribeck(&ctx->err, m, ctx->m, fs, fk, vs, delta, FR_DISK_MAX);
    if (status == FRICREG_OK)
        status = allocate(ctx);
    if (status != FRICREG_OK)
        return status;
    for (size_t i = 0; i < m; i++)
        ctx->strib[i] = (struct fr_stribeck){fs[i], fk[i], vs[i], delta[i]};
    ctx->stribeck = 1;
    ctx->law = FRICREG_DISK_QUINN;
    fr_disk_stribeck_refresh(ctx);
    ctx->last_valid = 0;
    return FRICREG_OK;
}
