/* SPDX-License-Identifier: GPL-3.0-or-later */
/* box_qp_bulk.c — the box QP's steps that change several bounds at once, for a sparse W.
 *
 * Alg. 16.3 of Nocedal & Wright (box_qp.c) changes the working set by one bound per iteration:
 * it holds the first bound a step meets, or releases the one most negative multiplier. With a
 * dense W an iteration is O(s^2) and few bounds change between evaluations; with a sparse W an
 * iteration is a solve, O(m + nnz(L)), and a large set whose warm start is wrong at k
 * contacts (a tenth of 10^5 contacts entering S, some guessed wrong) would take k iterations,
 * O(k m). Two steps change many bounds at once and keep what makes the method end:
 *   - a projected step: when the subspace minimizer y leaves the box, x_F = P(y), the
 *     projection onto the box, with every clamped variable held, taken only if it lowers the
 *     objective q (else the usual step to the first bound). Each such step holds at least one
 *     more bound, so between two minimizers of working sets there are at most s of them, and
 *     q still falls from one minimizer to the next: no working set is visited twice
 *     (Moré and Toraldo's projected searches, SIAM J. Optim. 1 (1991), take such steps);
 *   - a bulk release: every held bound with a negative multiplier released together. The
 *     minimizer of the larger face is lower, but a variable released with others may turn back
 *     through its bound; if the step then has length 0 at such a variable, box_qp.c holds them
 *     all again but the most negative and releases that one alone, as Alg. 16.3 does.
 * Both run in O(nnz) per iteration, by W's rows, on vectors scattered by contact. */
#include <math.h>

#include "box_qp_bulk.h"
#include "ctx_internal.h"
#include "sparse_coupling.h"

/* A held bound is released only if its multiplier is below -MULT_RTOL times the size of the
 * terms of the gradient, as box_qp.c. */
#define MULT_RTOL 1e-13

/* v[set[k]] = value[k] for the positions pos[n] (NULL: 0..n-1), or 0 (value NULL). */
static void scatter(double v[], const size_t set[], const size_t pos[], size_t n,
                    const double value[])
{
    for (size_t h = 0; h < n; h++) {
        size_t k = pos ? pos[h] : h;
        v[set[k]] = value ? value[k] : 0.0;
    }
}

/* The change of q from x to z on the face of the working set, whose minimizer is y:
 * q = 1/2 (u - y)^T W_FF (u - y) + const there, so q(z) - q(x) = 1/2 (z - x)^T W_FF v with
 * v = z + x - 2 y (v[set[k]] scattered by contact, zero off F): one product with W_FF's rows. */
static double objective_change(const fricreg_ctx *ctx, const size_t set[], size_t nf,
                               const double z[], const double v_all[])
{
    const struct fr_box_qp *qp = &ctx->qp;
    double change = 0.0;
    for (size_t a = 0; a < nf; a++) {
        size_t k = qp->free_pos[a];
        change += (z[a] - qp->x[k]) * fr_sparse_row_dot(ctx->sp, set[k], v_all, 0, NULL);
    }
    return 0.5 * change;
}

/* y clamped into the box, and whether it had to be. */
static int clamp_y(const struct fr_box_qp *qp, size_t nf, double z[])
{
    int outside = 0;
    for (size_t a = 0; a < nf; a++) {
        size_t k = qp->free_pos[a];
        outside |= qp->y[a] >= qp->hi[k] || qp->y[a] <= qp->lo[k];
        z[a] = fmin(fmax(qp->y[a], qp->lo[k]), qp->hi[k]);
    }
    return outside;
}

int fr_box_qp_projected_step(fricreg_ctx *ctx, const size_t set[], size_t nf)
{
    struct fr_box_qp *qp = &ctx->qp;
    double *v_all = ctx->sp->by_contact;
    double *z = ctx->rhs; /* free: the subspace minimizer is in qp->y */
    if (!clamp_y(qp, nf, z))
        return 0;
    for (size_t a = 0; a < nf; a++) {
        size_t k = qp->free_pos[a];
        v_all[set[k]] = z[a] + qp->x[k] - 2.0 * qp->y[a];
    }
    double change = objective_change(ctx, set, nf, z, v_all);
    scatter(v_all, set, qp->free_pos, nf, NULL);
    if (!(change < 0.0))
        return 0;
    for (size_t a = 0; a < nf; a++) {
        size_t k = qp->free_pos[a];
        qp->x[k] = z[a];
        qp->side[k] = qp->y[a] >= qp->hi[k] ? FR_UPPER : qp->y[a] <= qp->lo[k] ? FR_LOWER : FR_FREE;
    }
    return 1;
}

size_t fr_box_qp_release_all(fricreg_ctx *ctx, const size_t set[], size_t s)
{
    struct fr_box_qp *qp = &ctx->qp;
    double *x_all = ctx->sp->by_contact, most = 0.0;
    scatter(x_all, set, NULL, s, qp->x);
    qp->n_released = 0;
    for (size_t k = 0; k < s; k++) {
        if (qp->side[k] == FR_FREE || qp->lo[k] == qp->hi[k]) /* a degenerate box stays */
            continue;
        double size, g = qp->b[k] + fr_sparse_row_dot(ctx->sp, set[k], x_all, 0, &size);
        double lambda = qp->side[k] == FR_LOWER ? g : -g;
        if (!(lambda < -MULT_RTOL * (size + fabs(qp->b[k]))))
            continue;
        size_t r = qp->n_released++;
        qp->released[r] = k;
        qp->released_side[r] = qp->side[k];
        if (lambda < most) { /* the most negative first */
            most = lambda;
            qp->released[r] = qp->released[0], qp->released_side[r] = qp->released_side[0];
            qp->released[0] = k, qp->released_side[0] = qp->side[k];
        }
    }
    scatter(x_all, set, NULL, s, NULL);
    for (size_t r = 0; r < qp->n_released; r++)
        qp->side[qp->released[r]] = FR_FREE;
    return qp->n_released;
}

size_t fr_box_qp_keep_one(struct fr_box_qp *qp, signed char *side)
{
    for (size_t r = 1; r < qp->n_released; r++)
        qp->side[qp->released[r]] = qp->released_side[r];
    *side = qp->released_side[0];
    qp->n_released = 0;
    return qp->released[0];
}
