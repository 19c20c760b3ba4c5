/* SPDX-License-Identifier: GPL-3.0-or-later */
/* partition_consistent.c — the consistent near-stick law with a coupled W, dense or sparse
 * (docs/coupled.md).
 *
 * f_eq,i is the force that zeroes contact i's acceleration given every other contact's actual
 * force. Law (4) on S is then f_i = clamp(f_eq,i - c_i mun_i, lo_i, hi_i) (law.h, fr_box), and
 * these are exactly the optimality conditions of
 *   f_S = argmin_{lo <= f <= hi} 1/2 f^T W_SS f + b^T f,  b_i = a_free,i + W_ii c_i mun_i
 *                                                                + (W_SL f_L)_i,
 * solved by box_qp.c from the previous evaluation's working set. */
#include "box_qp.h"
#include "coupling.h"
#include "law/law.h"
#include "partition_consistent.h"

/* ctx->side of a contact outside S after an evaluation (S's working set holds FR_LOWER,
 * FR_FREE, FR_UPPER): it has no working set to warm-start from when it enters S. */
enum { ENTERING = 2 };

void fr_consistent_forget_working_set(fricreg_ctx *ctx)
{
    for (size_t i = 0; i < ctx->m; i++)
        ctx->side[i] = ENTERING;
}

/* The warm start of a contact that enters S: its side at the minimizer of its own row with
 * the other near-stick forces at 0, y = -b/W_ii. It used to be the bound on its slip side,
 * right for a contact that crosses the band's edge (its box closes on the sliding force) but
 * wrong for one that lands deep in the band, which then cost the QP two more iterations:
 * bench/dense.c, m = 500, S jumping by 2-4 contacts per evaluation, 6.23 -> 5.27 iterations
 * per evaluation; crossing the edge, 1.00 either way. */
static signed char entering_side(double b, double w_ii, double lo, double hi)
{
    double y = -b / w_ii;
    return y >= hi ? FR_UPPER : y <= lo ? FR_LOWER : FR_FREE;
}

/* The QP's data on S: bounds, linear term (f holds f_L and 0 on S) and warm start. */
static void build_problem(fricreg_ctx *ctx, const signed char side[], const double zdot[],
                          const double a_free[])
{
    struct fr_box_qp *qp = &ctx->qp;
    for (size_t k = 0; k < ctx->n_stick; k++) {
        size_t i = ctx->stick[k];
        double c = fr_band_position(ctx, zdot[i]), w_ii = ctx->w_diag[i];
        double coupling = fr_w_row_dot(ctx, i, ctx->f, 0);
        fr_box(c, ctx->bound[i], &qp->lo[k], &qp->hi[k]);
        qp->b[k] = a_free[i] + w_ii * c * ctx->bound[i] + coupling;
        qp->side[k] = side[i] == ENTERING ? entering_side(qp->b[k], w_ii, qp->lo[k], qp->hi[k])
                                          : side[i];
    }
}

/* f_eq,i = -(a_free,i + sum_{j != i} W_ij f_j) / W_ii on S, with the final forces. */
static void consistent_feq(fricreg_ctx *ctx, const double a_free[])
{
    for (size_t k = 0; k < ctx->n_stick; k++) {
        size_t i = ctx->stick[k];
        double others = fr_w_row_dot(ctx, i, ctx->f, 1);
        ctx->f_eq[i] = -(a_free[i] + others) / ctx->w_diag[i];
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
    fr_consistent_forget_working_set(ctx); /* the working set is written back only on success */
    for (size_t k = 0; k < ctx->n_stick; k++) {
        ctx->f[ctx->stick[k]] = qp->x[k];
        ctx->side[ctx->stick[k]] = qp->side[k];
    }
    consistent_feq(ctx, a_free);
    return FRICREG_OK;
}
