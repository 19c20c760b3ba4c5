/* SPDX-License-Identifier: GPL-3.0-or-later */
/* tangent_apply.c — fricreg_ctx_tangent_apply: the tangent of the last evaluation times a
 * direction, df = (df/dzdot) dzdot + (df/da_free) dafree, without forming the m x m tangent.
 *
 * The same Jacobian as tangent.c (docs/coupled.md), contact by contact where it is diagonal
 * and with one solve with the evaluation's factor where it is not:
 *   slip contacts:  df_i = s_i dzdot_i, s_i the law's own slope (off_band_slope);
 *   diagonal W:     df_i = dv_i dzdot_i + da_i dafree_i (tangent.c's diagonal slopes);
 *   paper's:        f_eq,S = -W_SS^-1 (a_free,S + W_SL f_L) once more (one solve), then
 *                   d f_eq,S = -W_SS^-1 (dafree_S + W_SL df_L) (a second), and
 *                   df_i = dv_i dzdot_i + (d f_i/d f_eq,i) d f_eq,i on S;
 *   consistent:     df_A from the bounds, df_i = h_i dzdot_i, and
 *                   df_F = -W_FF^-1 (W_ii t_i dzdot_F + dafree_F + W_F,A df_A + W_F,L df_L),
 *                   t_i = d(c_i bound_i)/d zdot_i (one solve).
 * W_F,. df is one pass over W's rows (sparse: O(nnz)), with df zero on F (or S) while it is
 * formed. Scratch: the context's f_eq (the product, copied out only when finite), rhs and the
 * QP's x and y, all free between evaluations. */
#include <math.h>
#include <string.h>

#include "coupling.h"
#include "factor.h"
#include "law/law.h"
#include "partition.h"
#include "tangent.h"

/* slope x, 0 when x is 0 (so that an infinite slope in a direction not asked for is no NaN). */
static double times(double slope, const double x[], size_t i)
{
    return x == NULL || x[i] == 0.0 ? 0.0 : slope * x[i];
}

/* Diagonal W, or a law that does not read f_eq: contact by contact. */
static void apply_diagonal(const fricreg_ctx *ctx, const double dz[], const double da[],
                           double out[])
{
    for (size_t i = 0; i < ctx->m; i++) {
        double dv, dfa;
        fr_tangent_diagonal_slopes(ctx, i, &dv, &dfa);
        out[i] = times(dv, dz, i) + times(dfa, da, i);
    }
}

/* Slip contacts (all but S): their own slope; S left at 0. */
static void apply_slip(const fricreg_ctx *ctx, const double dz[], double out[])
{
    memset(out, 0, ctx->m * sizeof *out);
    for (size_t i = 0; i < ctx->m; i++)
        if (!fr_needs_feq(ctx->law, ctx->last_zdot[i], ctx->eps))
            out[i] = times(fr_tangent_off_band_slope(ctx, i, ctx->last_zdot[i]), dz, i);
}

/* The paper's partition, S = ctx->stick[s], out holding df_L and 0 on S. */
static void apply_paper(fricreg_ctx *ctx, const double dz[], const double da[], double out[])
{
    size_t s = ctx->n_stick;
    const size_t *S = ctx->stick;
    double *dv = ctx->qp.x, *dfeq = ctx->qp.y; /* the QP's scratch, free here */
    for (size_t a = 0; a < s; a++)             /* f_eq,S, as the evaluation found it */
        ctx->rhs[a] = -(ctx->last_afree[S[a]] + fr_w_row_dot(ctx, S[a], ctx->f, 0));
    fr_factor_solve(ctx, ctx->rhs, "tangent_apply");
    for (size_t a = 0; a < s; a++) {
        size_t i = S[a];
        double v = ctx->last_zdot[i];
        fr_tangent_near_slopes(ctx, v, ctx->rhs[a], ctx->bound[i],
                               fr_tangent_bound_slope(ctx, i, v), &dv[a], &dfeq[a]);
    }
    for (size_t a = 0; a < s; a++) /* W_SS d f_eq,S = -(dafree_S + W_SL df_L) */
        ctx->rhs[a] = -((da ? da[S[a]] : 0.0) + fr_w_row_dot(ctx, S[a], out, 0));
    fr_factor_solve(ctx, ctx->rhs, "tangent_apply");
    for (size_t a = 0; a < s; a++)
        out[S[a]] = times(dv[a], dz, S[a]) + (dfeq[a] == 0.0 ? 0.0 : dfeq[a] * ctx->rhs[a]);
}

/* The consistent law, F = ctx->qp.free_set[nf], out holding df_L and 0 on S. */
static void apply_consistent(fricreg_ctx *ctx, size_t nf, const double dz[], const double da[],
                             double out[])
{
    const size_t *F = ctx->qp.free_set;
    for (size_t a = 0; a < ctx->n_stick; a++) { /* the held: from their bounds */
        size_t k = ctx->stick[a];
        if (ctx->side[k] != FR_FREE)
            out[k] = times(fr_tangent_held_slope(ctx, k), dz, k);
    }
    for (size_t a = 0; a < nf; a++) {
        size_t i = F[a];
        double db = times(ctx->w_diag[i] * fr_tangent_free_slope(ctx, i), dz, i);
        ctx->rhs[a] = -(db + (da ? da[i] : 0.0) + fr_w_row_dot(ctx, i, out, 0));
    }
    if (nf > 0)
        fr_factor_solve(ctx, ctx->rhs, "tangent_apply");
    for (size_t a = 0; a < nf; a++)
        out[F[a]] = ctx->rhs[a];
}

/* A direction's components, if given, are finite. */
static int check_direction(fricreg_ctx *ctx, const double x[], const char *name)
{
    for (size_t i = 0; x != NULL && i < ctx->m; i++)
        if (!isfinite(x[i]))
            return fr_fail(ctx, FRICREG_ENONFINITE, "tangent_apply: %s[%zu] = %g is not finite",
                           name, i, x[i]);
    return FRICREG_OK;
}

static int check_args(fricreg_ctx *ctx, size_t m, const double dz[], const double da[],
                      const double df[])
{
    int status = fr_tangent_check_size(ctx, m, "tangent_apply");
    if (status == FRICREG_OK && df == NULL)
        status = fr_fail(ctx, FRICREG_ENULL, "tangent_apply: df is NULL");
    if (status == FRICREG_OK)
        status = check_direction(ctx, dz, "dzdot");
    if (status == FRICREG_OK)
        status = check_direction(ctx, da, "dafree");
    return status == FRICREG_OK ? fr_tangent_check_kept(ctx, "tangent_apply") : status;
}

int fricreg_ctx_tangent_apply(fricreg_ctx *ctx, size_t m, const double dzdot[],
                              const double dafree[], double df[])
{
    if (ctx == NULL)
        return FRICREG_ENULL;
    int status = check_args(ctx, m, dzdot, dafree, df), coupled = 0;
    size_t nf = 0;
    if (status == FRICREG_OK)
        status = fr_tangent_prepare(ctx, "tangent_apply", &coupled, &nf);
    if (status != FRICREG_OK)
        return status;
    double *out = ctx->f_eq; /* scratch between evaluations */
    if (!coupled) {
        apply_diagonal(ctx, dzdot, dafree, out);
    } else {
        apply_slip(ctx, dzdot, out);
        if (ctx->n_stick > 0 && ctx->partition == FRICREG_PARTITION_PAPER)
            apply_paper(ctx, dzdot, dafree, out);
        else if (ctx->n_stick > 0)
            apply_consistent(ctx, nf, dzdot, dafree, out);
    }
    for (size_t i = 0; i < m; i++)
        if (!isfinite(out[i]))
            return fr_fail(ctx, FRICREG_ENONFINITE,
                           "tangent_apply: df[%zu] is beyond the range of double precision", i);
    memcpy(df, out, m * sizeof *df);
    return FRICREG_OK;
}
