/* SPDX-License-Identifier: GPL-3.0-or-later */
/* ctx_stribeck.c — static > kinetic (Stribeck) friction in the 1-D context
 * (fricreg_ctx_set_stribeck, fricreg_stribeck.h).
 *
 * The Stribeck law is law (4) with a bound that depends on the contact's own |zdot|:
 *   |zdot| <  eps:  B(|zdot|) = fs + (k(eps) - fs) |zdot|/eps   (the band, law_stribeck.h),
 *   |zdot| >= eps:  k(|zdot|) = fk + (fs - fk) exp(-(|zdot|/vs)^delta),
 * and law (4) with bound K at |zdot| >= eps is -K sgn(zdot) exactly (law.h, fr_band_scale).
 * So every evaluation path of the context — the diagonal pass, the paper's partition, the
 * consistent law's box QP with l_i = -B_i (1 - max(-c_i, 0)), u_i = B_i (1 - max(c_i, 0)),
 * b_i = a_free,i + W_ii c_i B_i + (W_SL f_L)_i (docs/coupled.md with B_i for mun_i) — runs
 * unchanged on these bounds, computed once per evaluation from zdot before the split. The
 * bound does not depend on f, so the consistent law is still a convex QP; with W diagonal it
 * is fricreg_stribeck_eval contact by contact, bit for bit (the same kernels). */
#include <math.h>
#include <stdlib.h>

#include "ctx_internal.h"
#include "fricreg_stribeck.h"
#include "law/contact_check.h"
#include "law/law.h"

void fr_stribeck_bounds(fricreg_ctx *ctx, const double zdot[])
{
    const double eps = ctx->eps;
    for (size_t i = 0; i < ctx->m; i++) {
        const struct fr_stribeck *p = &ctx->strib[i];
        double s = fabs(zdot[i]);
        ctx->strib_bound[i] = s < eps ? fr_stribeck_band_bound(p, ctx->strib_keps[i], s / eps)
                                      : fr_stribeck_kinetic(p, s);
    }
}

/* d bound/d zdot at zdot = v: in the band sgn(v) (k(eps) - fs)/eps (sgn(0) = +1: the side
 * v > 0), outside it sgn(v) k'(|v|). */
double fr_stribeck_bound_slope(const fricreg_ctx *ctx, size_t i, double v)
{
    const struct fr_stribeck *p = &ctx->strib[i];
    double s = fabs(v), sign = v < 0.0 ? -1.0 : 1.0;
    if (s < ctx->eps)
        return sign * ((ctx->strib_keps[i] - p->fs) / ctx->eps);
    return sign * fr_stribeck_kinetic_slope(p, s);
}

void fr_stribeck_refresh(fricreg_ctx *ctx)
{
    for (size_t i = 0; ctx->stribeck && i < ctx->m; i++)
        ctx->strib_keps[i] = fr_stribeck_kinetic(&ctx->strib[i], ctx->eps);
}

void fr_stribeck_off(fricreg_ctx *ctx)
{
    ctx->stribeck = 0;
    ctx->bound = ctx->mun;
}

/* The three arrays, at the first set-up only; the context is unchanged if one fails. */
static int allocate(fricreg_ctx *ctx)
{
    if (ctx->strib != NULL)
        return FRICREG_OK;
    size_t m = ctx->m;
    struct fr_stribeck *strib = malloc(m * sizeof *strib);
    double *keps = malloc(m * sizeof *keps), *bound = malloc(m * sizeof *bound);
    if (!strib || !keps || !bound) {
        free(strib), free(keps), free(bound);
        return fr_fail(ctx, FRICREG_ENOMEM, "set_stribeck: out of memory for m = %zu", m);
    }
    ctx->strib = strib;
    ctx->strib_keps = keps;
    ctx->strib_bound = bound;
    return FRICREG_OK;
}

int fricreg_ctx_set_stribeck(fricreg_ctx *ctx, size_t m, const double fs[], const double fk[],
                             const double vs[], const double delta[])
{
    if (ctx == NULL)
        return FRICREG_ENULL;
    if (m == 0) { /* the way back: law (4) with the bounds of set_bounds */
        fr_stribeck_off(ctx);
        ctx->last_valid = 0;
        return FRICREG_OK;
    }
    int status = fr_check_stribeck(&ctx->err, m, ctx->m, fs, fk, vs, delta, INFINITY);
    if (status == FRICREG_OK)
        status = allocate(ctx);
    if (status != FRICREG_OK)
        return status;
    for (size_t i = 0; i < m; i++)
        ctx->strib[i] = (struct fr_stribeck){fs[i], fk[i], vs[i], delta[i]};
    ctx->stribeck = 1;
    ctx->law = FRICREG_LAW_QUINN;
    ctx->bound = ctx->strib_bound;
    fr_stribeck_refresh(ctx);
    ctx->last_valid = 0;
    return FRICREG_OK;
}
