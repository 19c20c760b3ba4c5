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
#include "sparse_coupling.h"
#include "base/eigen.h"
#include "law/law.h"

/* The slope of the law at v = 0 times eps (so finite whatever eps): s_i eps, with s_i the
 * slope of f_i = -s_i v near v = 0 (law_table.c; 0 for (1), (2) and Karnopp: no velocity
 * feedback at rest). */
static double law_slope_times_eps(int law, double mun)
{
    return fr_law_table[law].slope_at_rest * mun;
}

static double diagonal_rate(const fricreg_ctx *ctx, int law)
{
    double rate = 0.0;
    for (size_t i = 0; i < ctx->m; i++)
        rate = fmax(rate, ctx->w_diag[i] * law_slope_times_eps(law, fr_rest_bound(ctx, i)));
    return rate;
}

/* Largest eigenvalue of D^1/2 W D^1/2 (symmetric positive semidefinite) times eps, by GSL,
 * D = diag(s) the slopes of `law`. Every slope times eps is k mun_i with one k for the law, so
 * the solver sees a_ij = sqrt(mun_i/mun_max) (W_ij/W_max) sqrt(mun_j/mun_max), |a_ij| <= 1,
 * and the scales multiply its result. Formed directly, mun or W near DBL_MAX made Inf and NaN
 * entries: GSL's eigensolver then never returned (tests/fuzz/fuzz_ctx.c), or its NaN
 * eigenvalues were dropped by fmax and reported 0, a step guard that passes every step
 * (tests/stress: the two blocks with mu = 1e300, eps = 1e-10). A product that overflows is
 * +inf here, which refuses every step, as it should. */
static int coupled_rate(fricreg_ctx *ctx, int law, double *rate)
{
    size_t m = ctx->m;
    double k = law_slope_times_eps(law, 1.0), mun_max = 0.0, w_max = 0.0;
    for (size_t i = 0; i < m; i++)
        mun_max = fmax(mun_max, fr_rest_bound(ctx, i));
    for (size_t i = 0; i < m * m; i++)
        w_max = fmax(w_max, fabs(ctx->W[i]));
    *rate = 0.0;
    if (k == 0.0 || mun_max == 0.0 || w_max == 0.0) /* no slope at rest, or no coupling */
        return FRICREG_OK;
    struct fr_eigen e;
    if (fr_eigen_alloc(&e, m) != FRICREG_OK)
        return FRICREG_ENOMEM;
    for (size_t i = 0; i < m; i++) {
        double si = sqrt(fr_rest_bound(ctx, i) / mun_max);
        for (size_t j = 0; j < m; j++)
            e.a[i * m + j] = si * (ctx->W[i * m + j] / w_max) *
                             sqrt(fr_rest_bound(ctx, j) / mun_max);
    }
    int status = fr_eigen_solve(&e) ? FRICREG_ENOMEM : FRICREG_OK; /* entries are finite */
    double scaled = 0.0;
    for (size_t i = 0; i < m; i++)
        scaled = isnan(e.eval[i]) ? INFINITY : fmax(scaled, e.eval[i]); /* NaN: refuse */
    fr_eigen_free(&e);
    *rate = scaled * w_max * mun_max * k;
    return status;
}

/* Sparse W: Gershgorin's bound of the largest eigenvalue of D^1/2 W D^1/2 times eps,
 * max_i sum_j sqrt(s_i) |W_ij| sqrt(s_j): rigorous, O(nnz), and above the eigenvalue by the
 * coupling's spread (on a uniform chain W = tridiag(-w, 2w, -w), 4w against 4w cos^2(pi/2(m+1))
 * for the eigenvalue: equal as m grows). Scaled as coupled_rate, so that no term overflows;
 * s_i eps = k bound_i, the bounds in the context's f_eq scratch. */
static double sparse_rate(fricreg_ctx *ctx, int law)
{
    double k = law_slope_times_eps(law, 1.0), mun_max = 0.0, *s = ctx->f_eq;
    for (size_t i = 0; i < ctx->m; i++)
        mun_max = fmax(mun_max, s[i] = fr_rest_bound(ctx, i));
    double w_max = fr_sparse_max_abs(ctx->sp);
    if (k == 0.0 || mun_max == 0.0 || w_max == 0.0)
        return 0.0;
    return fr_sparse_gershgorin(ctx->sp, s, mun_max, w_max) * w_max * mun_max * k;
}

int fr_stiffness_times_eps(fricreg_ctx *ctx, int chord, double *rate)
{
    int law = chord ? FRICREG_LAW_VELOCITY_LIMITED : ctx->law;
    int decoupled = !fr_coupled(ctx) || (!chord && ctx->law == FRICREG_LAW_QUINN &&
                                         ctx->partition == FRICREG_PARTITION_CONSISTENT);
    if (decoupled) {
        *rate = diagonal_rate(ctx, law);
        return FRICREG_OK;
    }
    if (ctx->sp != NULL) {
        *rate = sparse_rate(ctx, law);
        return FRICREG_OK;
    }
    double value = 0.0;
    if (coupled_rate(ctx, law, &value) != FRICREG_OK)
        return fr_fail(ctx, FRICREG_ENOMEM, "%s: out of memory for m = %zu",
                       chord ? "chord_stiffness" : "stick_stiffness", ctx->m);
    *rate = value;
    return FRICREG_OK;
}

int fricreg_ctx_stick_stiffness(fricreg_ctx *ctx, double *lambda)
{
    if (ctx == NULL || lambda == NULL)
        return ctx ? fr_fail(ctx, FRICREG_ENULL, "stick_stiffness: lambda is NULL") : FRICREG_ENULL;
    double rate = 0.0;
    int status = fr_stiffness_times_eps(ctx, 0, &rate);
    if (status == FRICREG_OK)
        *lambda = rate / ctx->eps; /* +inf when it overflows: no fixed step is stable */
    return status;
}
