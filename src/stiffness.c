/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stiffness.c — fricreg_ctx_stick_stiffness: the decay rate that bounds a fixed explicit step.
 *
 * In the stick zone a law with slope s_i at v = 0 gives d(zddot)/d(zdot) = -W_SS D_S with
 * D = diag(s) whenever f_eq is held fixed (the paper's partition, and (3), tanh, which ignore
 * f_eq). Its eigenvalues are those of D^1/2 W_SS D^1/2, bounded over every S by those of
 * D^1/2 W D^1/2 (Cauchy interlacing). Under the consistent law each free contact's
 * acceleration is -W_ii s_i zdot_i whatever the others do (docs/coupled.md), so the diagonal
 * gives the rate. Contacts held at a velocity-dependent bound (hi_i = mun_i (1 - c_i), c_i > 0,
 * or the mirror) see -(W_AA - W_AF W_FF^-1 W_FA) D_A instead, larger when several are coupled;
 * it is left out on purpose: the QP's multiplier makes such a contact accelerate towards c = 0
 * at |zddot_i| >= W_ii |c_i| mun_i, so the zone is crossed in about one step at the diagonal
 * bound, not resided in. Measured (RK4, two blocks, mun = (10, 5), eps = 0.02): crossing it
 * from 1600 states, the error after the crossing grows smoothly with dt and is O(eps) from
 * 0.25x to 1.5x the diagonal bound, with no edge at the coupled 0.59x; a slow ramp to both
 * friction limits at once tracks the fine solution to 1e-5 up to 0.99x and departs at 1.2x. */
#include <math.h>
#include <string.h>

#include "ctx_internal.h"
#include "eigen.h"

/* The slope s of the law at v = 0, per unit of mun: f = -s mun v / mun near v = 0. */
static double law_slope(int law, double mun, double eps)
{
    switch (law) {
    case FRICREG_LAW_QUINN: return 2.0 * mun / eps; /* (4a) */
    case FRICREG_LAW_VELOCITY_LIMITED:
    case FRICREG_LAW_TANH: return mun / eps; /* (3), tanh'(0) = 1 */
    default: return 0.0;                     /* (1), (2), Karnopp: no velocity feedback at rest */
    }
}

static double diagonal_rate(const fricreg_ctx *ctx)
{
    double lambda = 0.0;
    for (size_t i = 0; i < ctx->m; i++)
        lambda = fmax(lambda, ctx->w_diag[i] * law_slope(ctx->law, ctx->mun[i], ctx->eps));
    return lambda;
}

/* Largest eigenvalue of D^1/2 W D^1/2 (symmetric positive semidefinite), by GSL, with the
 * slopes of `law`. Every slope is k mun_i/eps with one k for the law, so the matrix is
 * (k/eps) (mun_max W_max) A with a_ij = sqrt(mun_i/mun_max) (W_ij/W_max) sqrt(mun_j/mun_max),
 * |a_ij| <= 1: formed directly, mun near DBL_MAX or eps near DBL_MIN made Inf and NaN entries,
 * on which GSL's eigensolver never returned (found by tests/fuzz/fuzz_ctx.c). The scale is
 * applied to the eigenvalue last, where it may round to +Inf: an honest "too stiff". */
static int coupled_rate(fricreg_ctx *ctx, int law, double *lambda)
{
    size_t m = ctx->m;
    double k = law_slope(law, 1.0, 1.0), mun_max = 0.0, w_max = 0.0;
    for (size_t i = 0; i < m; i++)
        mun_max = fmax(mun_max, ctx->mun[i]);
    for (size_t i = 0; i < m * m; i++)
        w_max = fmax(w_max, fabs(ctx->W[i]));
    *lambda = 0.0;
    if (k == 0.0 || mun_max == 0.0) /* no slope at rest: no decay rate */
        return FRICREG_OK;
    struct fr_eigen e;
    if (fr_eigen_alloc(&e, m) != FRICREG_OK)
        return FRICREG_ENOMEM;
    for (size_t i = 0; i < m; i++) {
        double si = sqrt(ctx->mun[i] / mun_max);
        for (size_t j = 0; j < m; j++)
            e.a[i * m + j] = si * (ctx->W[i * m + j] / w_max) * sqrt(ctx->mun[j] / mun_max);
    }
    int status = fr_eigen_solve(&e) ? FRICREG_ENOMEM : FRICREG_OK; /* fails only on bad sizes */
    double largest = 0.0;
    for (size_t i = 0; i < m; i++)
        largest = fmax(largest, e.eval[i]);
    fr_eigen_free(&e);
    *lambda = largest * w_max * mun_max * (k / ctx->eps);
    return status;
}

int fricreg_ctx_stick_stiffness(fricreg_ctx *ctx, double *lambda)
{
    if (ctx == NULL || lambda == NULL)
        return ctx ? fr_fail(ctx, FRICREG_ENULL, "stick_stiffness: lambda is NULL") : FRICREG_ENULL;
    int decoupled = ctx->W == NULL || (ctx->law == FRICREG_LAW_QUINN &&
                                       ctx->partition == FRICREG_PARTITION_CONSISTENT);
    if (decoupled) {
        *lambda = diagonal_rate(ctx);
        return FRICREG_OK;
    }
    double rate = 0.0;
    if (coupled_rate(ctx, ctx->law, &rate) != FRICREG_OK)
        return fr_fail(ctx, FRICREG_ENOMEM, "stick_stiffness: out of memory for m = %zu", ctx->m);
    *lambda = rate;
    return FRICREG_OK;
}

/* A law that jumps by 2 mun_i at zdot_i = 0 has no slope there; a fixed explicit step makes it
 * chatter, zdot_i moving by up to dt W_ii mun_i per step. Against the band |zdot_i| < eps that
 * the run resolves, the jump acts as its chord, law (3)'s slope mun_i/eps, coupled as (3) is. */
int fr_chord_stiffness(fricreg_ctx *ctx, double *lambda)
{
    double rate = 0.0;
    for (size_t i = 0; i < ctx->m; i++)
        rate = fmax(rate, ctx->w_diag[i] *
                              law_slope(FRICREG_LAW_VELOCITY_LIMITED, ctx->mun[i], ctx->eps));
    if (ctx->W != NULL && coupled_rate(ctx, FRICREG_LAW_VELOCITY_LIMITED, &rate) != FRICREG_OK)
        return fr_fail(ctx, FRICREG_ENOMEM, "chord_stiffness: out of memory for m = %zu", ctx->m);
    *lambda = rate;
    return FRICREG_OK;
}
