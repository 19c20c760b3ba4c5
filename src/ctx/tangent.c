/* SPDX-License-Identifier: GPL-3.0-or-later */
/* tangent.c — fricreg_ctx_tangent: the Jacobian of the forces of the last evaluation.
 *
 * Recomputed from that evaluation's inputs (kept by fricreg_ctx_eval) and, for the consistent
 * law, its final working set (ctx->side), so a later failed evaluation does not disturb it.
 *   Slip contacts: the law's own slope in v (0 for (1), -mun/eps in (3)'s band,
 *     -(mun/eps) sech^2(v/eps) for tanh), nothing in a_free.
 *   Near-stick, f_eq given (diagonal W; the paper's partition with f_eq,S solved from
 *     W_SS f_eq,S = -(a_free,S + W_SL f_L)): law (4) as clamp(f_eq - c mun, lo(c), hi(c)),
 *     differentiated on its piece, times d f_eq/d a_free = -W_SS^-1.
 *   Consistent law (docs/coupled.md): from the final active set A and free set F,
 *     d f_A from the bounds, d f_F = -W_FF^-1 (d b_F + W_FA d f_A), with the eval's factor.
 * Stribeck friction (ctx_stribeck.c): the bound moves with the contact's own |zdot|, which
 *   adds d f/d mun times d mun/d zdot to the slopes above, and the slip forces
 *   -k(|zdot|) sgn(zdot) move the near-stick forces through W_SL f_L.
 * Kinks: a contact exactly on a bound counts as held there; at zdot_i = 0 the bounds' slopes
 * are those of zdot_i > 0; at |zdot_i| = eps the contact slides. */
#include <math.h>
#include <string.h>

#include "coupling.h"
#include "factor.h"
#include "law/law.h"
#include "partition.h"
#include "tangent.h"

/* d f/d zdot of a contact that does not read f_eq at zdot = v. */
static double slip_slope(int law, double v, double mun, double eps)
{
    FR_LAWS_LISTED(6);
    switch ((enum fricreg_law)law) {
    case FRICREG_LAW_VELOCITY_LIMITED: return fabs(v) < eps ? -mun / eps : 0.0;
    case FRICREG_LAW_TANH: {
        /* sech^2 is 0 far out, where mun/eps may overflow: Inf * 0 gave NaN (mun = 1.8e308,
         * eps = 2.2e-236: fuzz finding); a zero slope stays 0. */
        double t = tanh(v / eps), sech2 = 1.0 - t * t;
        return sech2 == 0.0 ? 0.0 : -(mun / eps) * sech2;
    }
    case FRICREG_LAW_COULOMB:
    case FRICREG_LAW_FORCE_BALANCE:
    case FRICREG_LAW_KARNOPP:
    case FRICREG_LAW_QUINN: break; /* (1), and (2), (4), Karnopp outside their bands */
    }
    return 0.0;
}

/* d bound_i/d zdot_i at v: 0, but for Stribeck friction (ctx_stribeck.c), whose bound moves
 * with |zdot_i|. */
double fr_tangent_bound_slope(const fricreg_ctx *ctx, size_t i, double v)
{
    return ctx->stribeck ? fr_stribeck_bound_slope(ctx, i, v) : 0.0;
}

/* d f/d mun of clamp(f_eq - c mun, lo, hi) (law.h, fr_box) at fixed c, on the piece where f
 * is held at hi (at_hi), at lo (at_lo) or free: 1 - max(c, 0), -(1 - max(-c, 0)) or -c. */
static double box_bound_weight(int at_hi, int at_lo, double c)
{
    return at_hi ? 1.0 - fmax(c, 0.0) : at_lo ? -(1.0 - fmax(-c, 0.0)) : -c;
}

/* d f/d zdot and d f/d f_eq of a near-stick contact at (v, f_eq) with f_eq held fixed; the
 * bound mun moves with v at the rate dmun (Stribeck friction; else 0). */
void fr_tangent_near_slopes(const fricreg_ctx *ctx, double v, double feq, double mun, double dmun,
                            double *dv, double *dfeq)
{
    double dc = ctx->law == FRICREG_LAW_QUINN ? 2.0 / ctx->eps : 0.0, c = v * dc;
    double dlo, dhi, piece = fr_box_piece(c, feq, mun);
    fr_box_slopes(c, mun, &dlo, &dhi);
    int at_hi = piece > 0.0, at_lo = piece < 0.0;
    *dfeq = at_hi || at_lo ? 0.0 : 1.0;
    *dv = (at_hi ? dhi : at_lo ? dlo : -mun) * dc + dmun * box_bound_weight(at_hi, at_lo, c);
}

/* d f/d zdot of a contact off the band (no f_eq): the law's slope at fixed bound, and
 * d(-mun sgn v)/d mun = -sgn v times the bound's own slope (Stribeck: -k'(|v|)). */
double fr_tangent_off_band_slope(const fricreg_ctx *ctx, size_t i, double v)
{
    return slip_slope(ctx->law, v, ctx->bound[i], ctx->eps) +
           fr_coulomb(v, fr_tangent_bound_slope(ctx, i, v));
}

/* The slopes of fr_near_tangent_code's code, kept by the diagonal pass (partition.c) for a
 * contact of bound mun: near_slopes' values without the evaluation's inputs. */
static void coded_slopes(const fricreg_ctx *ctx, double code, double mun, double *dv, double *dfeq)
{
    double dc = ctx->law == FRICREG_LAW_QUINN ? 2.0 / ctx->eps : 0.0;
    *dv = (code == 1.0 || code == 3.0 ? -mun : 0.0) * dc;
    *dfeq = code >= 2.0 ? 1.0 : 0.0;
}

/* Laws without f_eq, or a diagonal W: one contact at a time, the diagonals only; from the
 * codes the diagonal pass kept (ctx->last_coded) or from the evaluation's inputs. */
void fr_tangent_diagonal_slopes(const fricreg_ctx *ctx, size_t i, double *dv, double *da)
{
    double v = ctx->last_coded ? 0.0 : ctx->last_zdot[i], dfeq = 0.0;
    if (ctx->last_coded)
        coded_slopes(ctx, ctx->last_afree[i], ctx->bound[i], dv, &dfeq);
    else if (fr_needs_feq(ctx->law, v, ctx->eps))
        fr_tangent_near_slopes(ctx, v, -ctx->last_afree[i] / ctx->w_diag[i], ctx->bound[i],
                               fr_tangent_bound_slope(ctx, i, v), dv, &dfeq);
    else
        *dv = fr_tangent_off_band_slope(ctx, i, v);
    *da = -dfeq / ctx->w_diag[i];
}

static void tangent_diagonal(const fricreg_ctx *ctx, double dz[], double da[])
{
    size_t m = ctx->m;
    for (size_t i = 0; i < m; i++) {
        double dv, dfa;
        fr_tangent_diagonal_slopes(ctx, i, &dv, &dfa);
        if (dz)
            dz[i * m + i] = dv;
        if (da)
            da[i * m + i] = dfa;
    }
}

/* Column k of -W_BB^-1 into rhs[0..n) (B the held factor's set), then scattered into row
 * set[a] of out, column col, scaled by row_scale[a] (NULL: 1) and col_scale. */
static void scatter_solution(fricreg_ctx *ctx, const size_t set[], size_t n, double out[],
                             size_t col, const double row_scale[], double col_scale)
{
    size_t m = ctx->m;
    fr_factor_solve(ctx, ctx->rhs, "tangent"); /* cannot fail: the factor is held */
    for (size_t a = 0; a < n; a++) {
        /* A row scaled by 0 (a saturated contact) does not move, even where W_BB^-1 is
         * beyond DBL_MAX (subnormal W: Inf * 0 gave NaN, found by fuzz_ctx); nor does a zero
         * of the solution where the slope overflowed (eps = DBL_MIN: 2 mun/eps = Inf, and
         * 0 * Inf NaN, fuzz finding). */
        double scale = row_scale ? row_scale[a] : 1.0;
        out[set[a] * m + col] = scale == 0.0 || ctx->rhs[a] == 0.0
                                    ? 0.0
                                    : -ctx->rhs[a] * scale * col_scale;
    }
}

/* Columns k of the slip contacts L: with Stribeck friction f_k = -k(|zdot_k|) sgn(zdot_k) moves
 * with zdot_k (slope dz[k][k], written by tangent_slip), and the near-stick forces of
 * B = set[n] with it, through W_BL f_L: d f_B/d zdot_k = -W_BB^-1 W_B,k dz[k][k], rows scaled
 * by row_scale (the paper's d f/d f_eq; NULL: 1), with the held factor of W_BB. Nothing to do
 * under law (4)'s constant bounds: the slip forces do not move. */
static void tangent_slip_columns(fricreg_ctx *ctx, const size_t set[], size_t n, double dz[],
                                 const double row_scale[])
{
    size_t m = ctx->m;
    for (size_t k = 0; ctx->stribeck && dz && n > 0 && k < m; k++) {
        double slope = dz[k * m + k];
        if (fr_needs_feq(ctx->law, ctx->last_zdot[k], ctx->eps) || slope == 0.0)
            continue;
        fr_w_column_gather(ctx, k, set, n, ctx->rhs);
        scatter_solution(ctx, set, n, dz, k, row_scale, slope);
    }
}

/* The column k of -W_BB^-1 is solved for the right-hand side s e_k and scaled by 1/s after,
 * s the power of two nearest sqrt(W_kk) (exact, so the bits are those of e_k): the solve then
 * runs in Jacobi-scaled magnitudes, and only the final scaling can overflow, to +-Inf. With e_k
 * itself, W ~ 1e-300 overflowed inside the triangular solves and Inf - Inf gave NaN (fuzz
 * finding). */
static double column_scale(const fricreg_ctx *ctx, size_t k)
{
    int exponent;
    frexp(sqrt(ctx->w_diag[k]), &exponent);
    return ldexp(1.0, exponent);
}

/* The paper's partition: f_eq,S = -W_SS^-1 (a_free,S + W_SL f_L), then the law on S, with
 * the held factor of W_SS. */
static void tangent_paper(fricreg_ctx *ctx, double dz[], double da[])
{
    size_t m = ctx->m, s = ctx->n_stick;
    const size_t *S = ctx->stick;
    for (size_t a = 0; a < s; a++)
        ctx->rhs[a] = -(ctx->last_afree[S[a]] + fr_w_row_dot(ctx, S[a], ctx->f, 0));
    fr_factor_solve(ctx, ctx->rhs, "tangent");
    double *dfeq = ctx->qp.y; /* d f_i/d f_eq,i on S: scratch of the QP, free here */
    for (size_t a = 0; a < s; a++) {
        size_t i = S[a];
        double dv;
        double v = ctx->last_zdot[i];
        fr_tangent_near_slopes(ctx, v, ctx->rhs[a], ctx->bound[i],
                               fr_tangent_bound_slope(ctx, i, v), &dv, &dfeq[a]);
        if (dz)
            dz[i * m + i] = dv;
    }
    tangent_slip_columns(ctx, S, s, dz, dfeq);
    for (size_t b = 0; da && b < s; b++) { /* d f_eq,S/d a_free,k = -(W_SS^-1) e_k */
        double scale = column_scale(ctx, S[b]);
        memset(ctx->rhs, 0, s * sizeof *ctx->rhs);
        ctx->rhs[b] = scale;
        scatter_solution(ctx, S, s, da, S[b], dfeq, 1.0 / scale);
    }
}

/* d(bound)/d zdot of a held contact i of S: through c, and through the bound itself when it
 * moves with zdot_i (Stribeck friction). */
double fr_tangent_held_slope(const fricreg_ctx *ctx, size_t i)
{
    double dc = ctx->law == FRICREG_LAW_QUINN ? 2.0 / ctx->eps : 0.0, dlo, dhi;
    double v = ctx->last_zdot[i], c = v * dc;
    int upper = ctx->side[i] == FR_UPPER;
    fr_box_slopes(c, ctx->bound[i], &dlo, &dhi);
    return (upper ? dhi : dlo) * dc +
           fr_tangent_bound_slope(ctx, i, v) * box_bound_weight(upper, !upper, c);
}

double fr_tangent_free_slope(const fricreg_ctx *ctx, size_t k)
{
    double dc = ctx->law == FRICREG_LAW_QUINN ? 2.0 / ctx->eps : 0.0, v = ctx->last_zdot[k];
    return ctx->bound[k] * dc + v * dc * fr_tangent_bound_slope(ctx, k, v);
}

/* The consistent law's free set F (in ctx->qp.free_set), from the final working set. */
static size_t consistent_free_set(fricreg_ctx *ctx)
{
    size_t nf = 0;
    for (size_t a = 0; a < ctx->n_stick; a++)
        if (ctx->side[ctx->stick[a]] == FR_FREE)
            ctx->qp.free_set[nf++] = ctx->stick[a];
    return nf;
}

/* The consistent law: d f_F = -W_FF^-1 (d b_F + W_FA d f_A), column by column, with the held
 * factor of W_FF (F = ctx->qp.free_set[nf]). */
static void tangent_consistent(fricreg_ctx *ctx, size_t nf, double dz[], double da[])
{
    size_t m = ctx->m, s = ctx->n_stick;
    const size_t *S = ctx->stick, *F = ctx->qp.free_set;
    for (size_t b = 0; dz && b < s; b++) { /* column k = S[b] of d f/d zdot */
        size_t k = S[b];
        int held = ctx->side[k] != FR_FREE;
        double dk = held ? fr_tangent_held_slope(ctx, k) : 0.0;
        if (held)
            dz[k * m + k] = dk;
        /* d b_F/d zdot_k + W_F,k d f_k/d zdot_k = (W_F,k or W_kk e_k) times a slope, solved
         * for the matrix part and scaled by the slope after: the product W mun/eps can
         * overflow where the solution (of the size of the slope) does not (found by
         * fuzz_ctx: W ~ 1e164, mun ~ 1e151 gave Inf - Inf = NaN). */
        double slope = held ? dk : fr_tangent_free_slope(ctx, k);
        if (held)
            fr_w_column_gather(ctx, k, F, nf, ctx->rhs);
        for (size_t a = 0; !held && a < nf; a++)
            ctx->rhs[a] = F[a] == k ? ctx->w_diag[k] : 0.0;
        if (nf > 0 && slope != 0.0)
            scatter_solution(ctx, F, nf, dz, k, NULL, slope);
    }
    tangent_slip_columns(ctx, F, nf, dz, NULL);
    for (size_t b = 0; da && b < nf; b++) { /* d b_F/d a_free,k = e_k for k in F */
        double scale = column_scale(ctx, F[b]);
        memset(ctx->rhs, 0, nf * sizeof *ctx->rhs);
        ctx->rhs[b] = scale;
        scatter_solution(ctx, F, nf, da, F[b], NULL, 1.0 / scale);
    }
}

/* Slip contacts' diagonal in zdot (their f does not depend on a_free). */
static void tangent_slip(const fricreg_ctx *ctx, double dz[])
{
    size_t m = ctx->m;
    for (size_t i = 0; dz && i < m; i++)
        if (!fr_needs_feq(ctx->law, ctx->last_zdot[i], ctx->eps))
            dz[i * m + i] = fr_tangent_off_band_slope(ctx, i, ctx->last_zdot[i]);
}

int fr_tangent_check_size(fricreg_ctx *ctx, size_t m, const char *who)
{
    if (m != ctx->m)
        return fr_fail(ctx, FRICREG_ESIZE, "%s: m = %zu, context has %zu contacts", who, m, ctx->m);
    return FRICREG_OK;
}

int fr_tangent_check_kept(fricreg_ctx *ctx, const char *who)
{
    if (!ctx->keep_tangent)
        return fr_fail(ctx, FRICREG_EINVAL,
                       "%s: the evaluation's inputs are not kept (set_keep_tangent 0)", who);
    if (!ctx->last_valid)
        return fr_fail(ctx, FRICREG_EINVAL,
                       "%s: no successful evaluation since the context was created or"
                       " last set up",
                       who);
    return FRICREG_OK;
}

/* Coupled W: the split of the last evaluation and the factor the tangent solves with (W_SS
 * for the paper's partition, W_FF for the consistent law), before any output is written: the
 * factor is the only thing that can fail. *nf is the consistent law's |F|. */
static int prepare_coupled(fricreg_ctx *ctx, size_t *nf, const char *who)
{
    fr_split_contacts(ctx, ctx->last_zdot);
    *nf = 0;
    if (ctx->n_stick == 0)
        return FRICREG_OK;
    if (ctx->partition == FRICREG_PARTITION_PAPER)
        return fr_factor_ensure(ctx, ctx->stick, ctx->n_stick, who);
    *nf = consistent_free_set(ctx);
    return *nf > 0 ? fr_factor_ensure(ctx, ctx->qp.free_set, *nf, who) : FRICREG_OK;
}

int fr_tangent_prepare(fricreg_ctx *ctx, const char *who, int *coupled, size_t *nf)
{
    if (ctx->stribeck) /* the bounds of the evaluation's velocities (a failed eval since may */
        fr_stribeck_bounds(ctx, ctx->last_zdot); /* have left others) */
    *coupled = fr_coupled(ctx) && fr_law_uses_feq(ctx->law);
    *nf = 0;
    return *coupled ? prepare_coupled(ctx, nf, who) : FRICREG_OK;
}

int fricreg_ctx_tangent(fricreg_ctx *ctx, size_t m, double df_dzdot[], double df_dafree[])
{
    if (ctx == NULL)
        return FRICREG_ENULL;
    int status = fr_tangent_check_size(ctx, m, "tangent"), coupled = 0;
    if (status == FRICREG_OK && df_dzdot == NULL && df_dafree == NULL)
        status = fr_fail(ctx, FRICREG_ENULL, "tangent: df_dzdot and df_dafree are both NULL");
    if (status == FRICREG_OK)
        status = fr_tangent_check_kept(ctx, "tangent");
    size_t nf = 0;
    if (status == FRICREG_OK)
        status = fr_tangent_prepare(ctx, "tangent", &coupled, &nf);
    if (status != FRICREG_OK)
        return status;
    if (df_dzdot)
        memset(df_dzdot, 0, m * m * sizeof *df_dzdot);
    if (df_dafree)
        memset(df_dafree, 0, m * m * sizeof *df_dafree);
    if (!coupled) {
        tangent_diagonal(ctx, df_dzdot, df_dafree);
    } else {
        tangent_slip(ctx, df_dzdot);
        if (ctx->n_stick > 0 && ctx->partition == FRICREG_PARTITION_PAPER)
            tangent_paper(ctx, df_dzdot, df_dafree);
        else if (ctx->n_stick > 0)
            tangent_consistent(ctx, nf, df_dzdot, df_dafree);
    }
    return FRICREG_OK;
}
