/* SPDX-License-Identifier: GPL-3.0-or-later */
/* partition_consistent.c — the consistent near-stick law with a dense W (docs/coupled.md).
 *
 * f_eq,i is the force that zeroes contact i's acceleration given every other contact's actual
 * force. Law (4) on S is then f_i = clamp(f_eq,i - c_i mun_i, lo_i, hi_i) (law.h, fr_box), and
 * these are exactly the optimality conditions of
 *   f_S = argmin_{lo <= f <= hi} 1/2 f^T W_SS f + b^T f,  b_i = a_free,i + W_ii c_i mun_i
 *                                                                + (W_SL f_L)_i,
 * solved by box_qp.c from the previous evaluation's working set. */
#include "law.h"
#include "partition.h"

/* The warm start of a contact outside S: where it will enter the band from its slip side.
 * Under (4) a contact entering at |c| -> 2 sits in a box that closes on its sliding force, at
 * the bound on that side; under Karnopp and (2) it enters at rest, most often holding. */
static void slip_sides(fricreg_ctx *ctx, const double zdot[])
{
    int quinn = ctx->law == FRICREG_LAW_QUINN;
    for (size_t i = 0; i < ctx->m; i++)
        ctx->side[i] = quinn ? (zdot[i] > 0.0 ? FR_LOWER : FR_UPPER) : FR_FREE;
}

/* The QP's data on S: bounds, linear term (f holds f_L and 0 on S) and warm start. */
static void build_problem(fricreg_ctx *ctx, const signed char side[], const double zdot[],
                          const double a_free[])
{
    struct fr_box_qp *qp = &ctx->qp;
    size_t m = ctx->m;
    for (size_t k = 0; k < ctx->n_stick; k++) {
        size_t i = ctx->stick[k];
        double c = fr_band_position(ctx, zdot[i]), coupling = 0.0;
        const double *row = ctx->W + i * m;
        for (size_t j = 0; j < m; j++)
            coupling += row[j] * ctx->f[j];
        fr_box(c, ctx->bound[i], &qp->lo[k], &qp->hi[k]);
        qp->b[k] = a_free[i] + row[i] * c * ctx->bound[i] + coupling;
        qp->side[k] = side[i];
    }
}

/* f_eq,i = -(a_free,i + sum_{j != i} W_ij f_j) / W_ii on S, with the final forces. */
static void consistent_feq(fricreg_ctx *ctx, const double a_free[])
{
    size_t m = ctx->m;
    for (size_t k = 0; k < ctx->n_stick; k++) {
        size_t i = ctx->stick[k];
        const double *row = ctx->W + i * m;
        double others = 0.0;
        for (size_t j = 0; j < m; j++)
            others += j == i ? 0.0 : row[j] * ctx->f[j];
        ctx->f_eq[i] = -(a_free[i] + others) / row[i];
    }
}

int fr_eval_consistent(fricreg_ctx *ctx, const double zdot[], const double a_free[])
{
    struct fr_box_qp *qp = &ctx->qp;
    if (ctx->n_stick > 0) { /* S's warm start is its last working set */
        build_problem(ctx, ctx->side, zdot, a_free);
        int status = fr_box_qp_solve(ctx, ctx->stick, ctx->n_stick);
        if (status != FRICREG_OK)
            return status;
    }
    slip_sides(ctx, zdot); /* the working set is written back only on success */
    for (size_t k = 0; k < ctx->n_stick; k++) {
        ctx->f[ctx->stick[k]] = qp->x[k];
        ctx->side[ctx->stick[k]] = qp->side[k];
    }
    consistent_feq(ctx, a_free);
    return FRICREG_OK;
}
