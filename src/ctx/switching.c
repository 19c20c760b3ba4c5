/* SPDX-License-Identifier: GPL-3.0-or-later */
/* switching.c — fricreg_ctx_switching: each contact's signed distances to the kinks of its
 * law, for the root finders of adaptive integrators (fricreg.h, enum fricreg_switch).
 *
 * Law (4) is f = -B sat(2(v - xi)/eps), xi = (eps/2) sat(f_eq/B) (law.h, fr_quinn_band). In
 * the (v, f_eq) plane it is smooth but on the two edges of its linear zone, v - xi = +-eps/2
 * (components 3, 4), and on the segments f_eq = +-B inside the zone, where xi saturates
 * (components 5, 6). A segment has ends, so no continuous function changes sign across it
 * alone: 5 is the signed distance into the region where the zone holds xi saturated at +eps/2,
 * min(f_eq - B, B a, B b) with a, b the scaled distances to the zone's edges, whose boundary
 * is the segment and two pieces of the zone's edges, every point of it a kink. The band
 * |v| < eps (0, 1) and rest v = 0 (2) are kinks of other laws and of Stribeck's bound. Every
 * component is a pure function of the inputs: nothing of the context is written. */
#include <math.h>

#include "coupling.h"
#include "ctx_internal.h"
#include "law/law.h"
#include "law/law_stribeck.h"
#include "law/plausible.h"

enum { PER = FRICREG_SWITCH_PER_CONTACT };

/* Which kinds of component are live for the context's law, coupling and partition. */
struct live {
    int band, band_always, rest, zone, sat;
    double h_sat; /* the half-width of the zone in which the law reads f_eq: eps/2, or eps */
};

static struct live live_components(const fricreg_ctx *ctx)
{
    const struct fr_law_row *law = &fr_law_table[ctx->law];
    int strib = ctx->stribeck, feq_band = (law->kinks & FR_KINK_FEQ_BAND) != 0;
    /* the paper's partition changes its stick set where a law reads f_eq over a band */
    int paper_jumps = fr_coupled(ctx) && ctx->partition == FRICREG_PARTITION_PAPER && feq_band;
    return (struct live){
        .band = (law->kinks & FR_KINK_BAND) || strib,
        .band_always = paper_jumps,
        .rest = (law->kinks & FR_KINK_REST) || strib,
        .zone = (law->kinks & FR_KINK_ZONE) != 0,
        .sat = feq_band,
        .h_sat = feq_band ? law->feq_half_band * ctx->eps : 0.5 * ctx->eps,
    };
}

/* The bound law (4) reads at velocity v: mun, or Stribeck's B(|v|) in the band and k(|v|)
 * outside it, as fr_stribeck_bounds computes it (continuous at |v| = eps). */
static double bound_at(const fricreg_ctx *ctx, size_t i, double v)
{
    if (!ctx->stribeck)
        return ctx->mun[i];
    const struct fr_stribeck *p = &ctx->strib[i];
    double s = fabs(v);
    return s < ctx->eps ? fr_stribeck_band_bound(p, ctx->strib_keps[i], s / ctx->eps)
                        : fr_stribeck_kinetic(p, s);
}

/* f_eq,i = -(a_free,i + sum_{j != i} W_ij f_j) / W_ii, as eval forms it on S. */
static double feq_of(const fricreg_ctx *ctx, size_t i, const double a_free[], const double f[])
{
    if (fr_coupled(ctx))
        return -(a_free[i] + fr_w_row_dot(ctx, i, f, 1)) / ctx->w_diag[i];
    return ctx->w_unit ? -a_free[i] : -a_free[i] / ctx->w_diag[i];
}

/* One contact's components at velocity v and equilibrium force f_eq (unused where no
 * component reads it). */
static void contact(const fricreg_ctx *ctx, const struct live *on, size_t i, double v, double f_eq,
                    double g[])
{
    const double eps = ctx->eps, half = 0.5 * eps;
    int kinks = fr_rest_bound(ctx, i) > 0.0; /* a zero bound: f = 0, no kink of its own */
    double B = bound_at(ctx, i, v);
    int band = on->band_always || (kinks && on->band);
    g[FRICREG_SWITCH_BAND_HI] = band ? v - eps : 1.0;
    g[FRICREG_SWITCH_BAND_LO] = band ? v + eps : 1.0;
    g[FRICREG_SWITCH_REST] = kinks && on->rest ? v : 1.0;
    double xi = B > 0.0 ? half * fr_clamp(f_eq / B, -1.0, 1.0) : 0.0;
    g[FRICREG_SWITCH_ZONE_HI] = kinks && on->zone ? (v - xi) - half : 1.0;
    g[FRICREG_SWITCH_ZONE_LO] = kinks && on->zone ? (v - xi) + half : 1.0;
    if (!(kinks && on->sat && B > 0.0)) {
        g[FRICREG_SWITCH_SAT_HI] = g[FRICREG_SWITCH_SAT_LO] = 1.0;
        return;
    }
    double h = on->h_sat, d = on->zone ? v - xi : v;
    double a = fr_clamp((h - d) / h, -2.0, 2.0), b = fr_clamp((h + d) / h, -2.0, 2.0);
    double inside = B * fmin(a, b), F = fr_clamp(f_eq, -3.0 * B, 3.0 * B);
    g[FRICREG_SWITCH_SAT_HI] = fmin(F - B, inside);
    g[FRICREG_SWITCH_SAT_LO] = fmax(F + B, -inside);
}

/* The first index of a[n] (and of b[n], when b is not NULL) that is not finite, or n. */
static size_t first_nonfinite(size_t n, const double a[], const double b[])
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(a[i]) || (b != NULL && !isfinite(b[i])))
            return i;
    return n;
}

static int check_inputs(fricreg_ctx *ctx, size_t m, const double zdot[], const double a_free[],
                        const double f[], int reads_f, const double g[], size_t ng)
{
    if (m != ctx->m)
        return fr_fail(ctx, FRICREG_ESIZE, "switching: m = %zu, context has %zu contacts", m,
                       ctx->m);
    if (zdot == NULL || a_free == NULL || g == NULL || (reads_f && f == NULL))
        return fr_fail(ctx, FRICREG_ENULL, "switching: %s is NULL",
                       zdot == NULL     ? "zdot"
                       : a_free == NULL ? "a_free"
                       : g == NULL      ? "g"
                                        : "f (read with a coupled W)");
    if (ng < PER * m)
        return fr_fail(ctx, FRICREG_ESIZE, "switching: ng = %zu, needs %zu (%d per contact)", ng,
                       (size_t)PER * m, PER);
    if (!fr_plausible(m, zdot, a_free, NULL)) {
        size_t k = first_nonfinite(m, zdot, a_free);
        if (k < m)
            return fr_fail(ctx, FRICREG_ENONFINITE, "switching: %s[%zu] is not finite",
                           isfinite(zdot[k]) ? "a_free" : "zdot", k);
    }
    size_t k = reads_f ? first_nonfinite(m, f, NULL) : m;
    if (k < m)
        return fr_fail(ctx, FRICREG_ENONFINITE, "switching: f[%zu] is not finite", k);
    return FRICREG_OK;
}

size_t fricreg_ctx_switching_count(const fricreg_ctx *ctx)
{
    return ctx == NULL ? 0 : PER * ctx->m;
}

int fricreg_ctx_switching(fricreg_ctx *ctx, size_t m, const double zdot[], const double a_free[],
                          const double f[], double g[], size_t ng)
{
    if (ctx == NULL)
        return FRICREG_ENULL;
    int reads_feq = fr_law_uses_feq(ctx->law), reads_f = reads_feq && fr_coupled(ctx);
    int status = check_inputs(ctx, m, zdot, a_free, f, reads_f, g, ng);
    if (status != FRICREG_OK)
        return status;
    struct live on = live_components(ctx);
    for (size_t i = 0; i < m; i++) {
        double f_eq = reads_feq ? feq_of(ctx, i, a_free, f) : 0.0;
        contact(ctx, &on, i, zdot[i], f_eq, &g[PER * i]);
    }
    return FRICREG_OK;
}
