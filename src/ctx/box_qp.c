/* SPDX-License-Identifier: GPL-3.0-or-later */
/* box_qp.c — min 1/2 x^T W_SS x + b^T x on lo <= x <= hi: the consistent near-stick law.
 *
 * Method: the primal active-set method of Nocedal & Wright, Numerical Optimization (2nd ed.),
 * Alg. 16.3, specialized to bounds. The working set holds each variable free or at one bound.
 * Each iteration minimizes over the free set F with the others fixed,
 * y_F = -W_FF^-1 (b_F + W_FA x_A), then either steps to y_F (if it is feasible) and checks the
 * multipliers of the held bounds, releasing the most negative one, or steps as far as the box
 * allows and holds the blocking bound. Chosen over block principal pivoting because it is
 * monotone: the iterates stay feasible and the objective strictly decreases on every non-zero
 * step, so (W_SS positive definite) no working set is visited twice and the method ends after
 * finitely many of the 3^s working sets; block pivoting needs an extra safeguard (Murty's
 * single pivot) to avoid cycling. A zero-length step could in theory repeat a working set,
 * hence the iteration bound, which is reported, never silently passed.
 *
 * Cost: one factorization of W_FF per new free set (cached by factor.c, so an evaluation whose
 * warm start is right reuses the last factor: one triangular solve, O(s^2)), plus O(s |A|)
 * for the multipliers. Warm start: the caller passes the previous working set in qp->side. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "box_qp.h"
#include "box_qp_bulk.h"
#include "ctx_internal.h"
#include "factor.h"
#include "law/law.h"
#include "sparse_coupling.h"
#include "base/free_all.h"

#define NONE SIZE_MAX
/* A held bound is released only if its multiplier is below -MULT_RTOL times the size of the
 * terms of the gradient: rounding must not release a bound whose multiplier is zero. */
#define MULT_RTOL 1e-13
/* The safeguard: far above what any case needs (about one iteration per contact that changes
 * its bound, usually 1 in all). */
#define MAX_ITERATIONS(s) (100 + 10 * (s))

int fr_box_qp_alloc(struct fr_box_qp *qp, size_t m)
{
    memset(qp, 0, sizeof *qp);
    qp->lo = malloc(m * sizeof *qp->lo);
    qp->hi = malloc(m * sizeof *qp->hi);
    qp->b = malloc(m * sizeof *qp->b);
    qp->x = malloc(m * sizeof *qp->x);
    qp->y = malloc(m * sizeof *qp->y);
    qp->side = malloc(m * sizeof *qp->side);
    qp->free_pos = malloc(m * sizeof *qp->free_pos);
    qp->free_set = malloc(m * sizeof *qp->free_set);
    qp->held_pos = malloc(m * sizeof *qp->held_pos);
    qp->released = malloc(m * sizeof *qp->released);
    qp->released_side = malloc(m * sizeof *qp->released_side);
    if (!qp->lo || !qp->hi || !qp->b || !qp->x || !qp->y || !qp->side || !qp->free_pos ||
        !qp->free_set || !qp->held_pos || !qp->released || !qp->released_side) {
        fr_box_qp_free(qp);
        return FRICREG_ENOMEM;
    }
    return FRICREG_OK;
}

void fr_box_qp_free(struct fr_box_qp *qp)
{
    FR_FREE_ALL(qp->lo, qp->hi, qp->b, qp->x, qp->y, qp->side, qp->free_pos, qp->free_set,
                qp->held_pos, qp->released, qp->released_side);
    memset(qp, 0, sizeof *qp);
}

/* A feasible start on the given working set; a degenerate box (lo = hi: mun = 0) is held. */
static void start(struct fr_box_qp *qp, size_t s)
{
    for (size_t k = 0; k < s; k++) {
        if (qp->lo[k] == qp->hi[k])
            qp->side[k] = FR_LOWER;
        double inside = fmin(fmax(0.0, qp->lo[k]), qp->hi[k]);
        qp->x[k] = qp->side[k] == FR_LOWER   ? qp->lo[k]
                   : qp->side[k] == FR_UPPER ? qp->hi[k]
                                             : inside;
    }
}

/* Lists the free variables (returns their count) and the held ones (qp->n_held). */
static size_t list_free(struct fr_box_qp *qp, const size_t set[], size_t s)
{
    size_t n = 0;
    qp->n_held = 0;
    for (size_t k = 0; k < s; k++)
        if (qp->side[k] == FR_FREE) {
            qp->free_pos[n] = k;
            qp->free_set[n++] = set[k];
        } else {
            qp->held_pos[qp->n_held++] = k;
        }
    return n;
}

/* sum_h row[set[pos[h]]] x[pos[h]] over h < n (pos NULL: the positions 0..n-1), and the sum
 * of the terms' magnitudes into *size, each in FR_LANES partial sums: independent chains
 * instead of one serial sum, which would wait on every addition. */
static double row_times_x(const double row[], const size_t set[], const size_t pos[],
                          const double x[], size_t n, double *size)
{
    double sum[FR_LANES] = {0.0}, mag[FR_LANES] = {0.0};
    size_t h = 0;
    for (; h + FR_LANES <= n; h += FR_LANES)
        for (size_t l = 0; l < FR_LANES; l++) {
            size_t k = pos ? pos[h + l] : h + l;
            double term = row[set[k]] * x[k];
            sum[l] += term;
            mag[l] += fabs(term);
        }
    for (; h < n; h++) {
        size_t k = pos ? pos[h] : h;
        double term = row[set[k]] * x[k];
        sum[0] += term;
        mag[0] += fabs(term);
    }
    *size = (mag[0] + mag[1]) + (mag[2] + mag[3]);
    return (sum[0] + sum[1]) + (sum[2] + sum[3]);
}

/* The positions pos[n] of x scattered by contact into the sparse coupling's zeroed scratch
 * (value 1), or cleared again (value 0). */
static double *scatter_x(fricreg_ctx *ctx, const size_t set[], const size_t pos[], size_t n,
                         int value)
{
    double *by_contact = ctx->sp->by_contact;
    for (size_t h = 0; h < n; h++) {
        size_t k = pos ? pos[h] : h;
        by_contact[set[k]] = value ? ctx->qp.x[k] : 0.0;
    }
    return by_contact;
}

/* Sparse W: y_F = -(b_F + W_FA x_A), W_FA x_A by the free rows' entries, x_A scattered by
 * contact: O(nnz) rather than |F| |A|. */
static void sparse_held_products(fricreg_ctx *ctx, const size_t set[], size_t nf)
{
    struct fr_box_qp *qp = &ctx->qp;
    const double *x_held = scatter_x(ctx, set, qp->held_pos, qp->n_held, 1);
    for (size_t a = 0; a < nf; a++) {
        size_t k = qp->free_pos[a];
        qp->y[a] = -(qp->b[k] + fr_sparse_row_dot(ctx->sp, set[k], x_held, 0, NULL));
    }
    scatter_x(ctx, set, qp->held_pos, qp->n_held, 0);
}

/* y_F = -W_FF^-1 (b_F + W_FA x_A), with the cached factor of W_FF (updated by factor.c when
 * F differs from the last iteration's by a contact or two). W_FA x_A over the held list: it is
 * usually short, and this runs once per iteration. */
static int subspace_minimizer(fricreg_ctx *ctx, const size_t set[], size_t nf)
{
    struct fr_box_qp *qp = &ctx->qp;
    size_t m = ctx->m;
    if (ctx->sp != NULL) {
        sparse_held_products(ctx, set, nf);
    } else {
        for (size_t a = 0; a < nf; a++) {
            size_t k = qp->free_pos[a];
            double size;
            qp->y[a] = -(qp->b[k] + row_times_x(ctx->W + set[k] * m, set, qp->held_pos, qp->x,
                                                qp->n_held, &size));
        }
    }
    int status = fr_factor_ensure(ctx, qp->free_set, nf, "eval");
    if (status == FRICREG_OK)
        status = fr_factor_solve(ctx, qp->y, "eval");
    /* A y that overflowed would be clamped into the box by take_step (fmax drops a NaN) and
     * returned as a force (a_free ~ 5e279 beside W_33 ~ 6e113: fuzz finding): refuse it. */
    for (size_t a = 0; status == FRICREG_OK && a < nf; a++)
        if (!isfinite(qp->y[a]))
            status = fr_fail(ctx, FRICREG_ENONFINITE,
                             "eval: the near-stick solve of %zu contacts overflowed (contact %zu):"
                             " beyond the range of double precision",
                             nf, qp->free_set[a]);
    return status;
}

/* The longest step alpha <= 1 from x towards y that stays in the box, and the bound that
 * blocks it (NONE if y is inside). A y exactly on a bound counts as blocked there, so a
 * contact sitting on its bound is held (the tangent's side at that kink). The variable just
 * released moves away from the bound it left (N&W Thm 16.5), so only its other bound is
 * tested: it may cross its whole box. */
static double step_length(const struct fr_box_qp *qp, size_t nf, size_t released,
                          signed char released_side, size_t *block, signed char *block_side)
{
    double alpha = 1.0;
    *block = NONE;
    for (size_t a = 0; a < nf; a++) {
        size_t k = qp->free_pos[a];
        double y = qp->y[a], x = qp->x[k], t;
        signed char side;
        if (y >= qp->hi[k]) {
            t = y > x ? (qp->hi[k] - x) / (y - x) : 0.0;
            side = FR_UPPER;
        } else if (y <= qp->lo[k]) {
            t = y < x ? (qp->lo[k] - x) / (y - x) : 0.0;
            side = FR_LOWER;
        } else {
            continue;
        }
        if (k == released && side == released_side)
            continue;
        t = fmax(t, 0.0);
        if (t < alpha || (t == alpha && *block == NONE)) {
            alpha = t;
            *block = k;
            *block_side = side;
        }
    }
    return alpha;
}

static void take_step(struct fr_box_qp *qp, size_t nf, double alpha, size_t block,
                      signed char block_side)
{
    for (size_t a = 0; a < nf; a++) {
        size_t k = qp->free_pos[a];
        double x = alpha == 1.0 ? qp->y[a] : qp->x[k] + alpha * (qp->y[a] - qp->x[k]);
        qp->x[k] = fmin(fmax(x, qp->lo[k]), qp->hi[k]);
    }
    if (block != NONE) {
        qp->side[block] = block_side;
        qp->x[block] = block_side == FR_LOWER ? qp->lo[block] : qp->hi[block];
    }
}

/* The held bound with the most negative multiplier (gradient W_SS x + b, signed by the side),
 * or NONE if x is optimal. A degenerate box is never released. */
static size_t most_negative_multiplier(fricreg_ctx *ctx, const size_t set[], size_t s)
{
    const struct fr_box_qp *qp = &ctx->qp;
    const double *x_all = ctx->sp != NULL ? scatter_x(ctx, set, NULL, s, 1) : NULL;
    size_t pick = NONE;
    double most = 0.0;
    for (size_t k = 0; k < s; k++) {
        if (qp->side[k] == FR_FREE || qp->lo[k] == qp->hi[k])
            continue;
        double size,
            g = qp->b[k] +
                (x_all != NULL ? fr_sparse_row_dot(ctx->sp, set[k], x_all, 0, &size)
                               : row_times_x(ctx->W + set[k] * ctx->m, set, NULL, qp->x, s, &size));
        size += fabs(qp->b[k]);
        double lambda = qp->side[k] == FR_LOWER ? g : -g;
        if (lambda < -MULT_RTOL * size && lambda < most) {
            most = lambda;
            pick = k;
        }
    }
    if (x_all != NULL)
        scatter_x(ctx, set, NULL, s, 0);
    return pick;
}

/* Whether position k is among those released together. */
static int released_together(const struct fr_box_qp *qp, size_t k)
{
    for (size_t r = 0; r < qp->n_released; r++)
        if (qp->released[r] == k)
            return 1;
    return 0;
}

/* At a minimizer of the working set: the bounds to release, as *released (one, its side in
 * *released_side) or recorded in qp->released (several, bulk); returns 0 if x is optimal. */
static int release(fricreg_ctx *ctx, const size_t set[], size_t s, size_t *released,
                   signed char *released_side)
{
    struct fr_box_qp *qp = &ctx->qp;
    if (qp->bulk) {
        size_t count = fr_box_qp_release_all(ctx, set, s);
        if (count == 1)
            *released = fr_box_qp_keep_one(qp, released_side);
        return count > 0;
    }
    *released = most_negative_multiplier(ctx, set, s);
    if (*released == NONE)
        return 0;
    *released_side = qp->side[*released];
    qp->side[*released] = FR_FREE;
    return 1;
}

int fr_box_qp_solve(fricreg_ctx *ctx, const size_t set[], size_t s)
{
    struct fr_box_qp *qp = &ctx->qp;
    size_t released = NONE;
    signed char released_side = FR_FREE;
    start(qp, s);
    qp->n_released = 0;
    for (size_t it = 0; it < MAX_ITERATIONS(s); it++) {
        ctx->stats[FRICREG_STAT_QP_ITERATIONS]++;
        size_t nf = list_free(qp, set, s), block = NONE;
        signed char block_side = FR_FREE;
        double alpha = 1.0;
        if (nf > 0) {
            int status = subspace_minimizer(ctx, set, nf);
            if (status != FRICREG_OK)
                return status;
            if (qp->bulk && released == NONE && fr_box_qp_projected_step(ctx, set, nf)) {
                qp->n_released = 0;
                continue; /* a lower point, not yet the minimizer of the new working set */
            }
            alpha = step_length(qp, nf, released, released_side, &block, &block_side);
            if (alpha == 0.0 && qp->n_released > 1 && released_together(qp, block)) {
                /* several released at once, one turns straight back: release one alone, as
                 * Alg. 16.3 does (Thm 16.5: it moves away from its bound) */
                released = fr_box_qp_keep_one(qp, &released_side);
                continue;
            }
        }
        take_step(qp, nf, alpha, block, block_side);
        released = NONE;
        qp->n_released = 0;
        if (block != NONE)
            continue; /* not yet at the minimizer of the new working set */
        if (!release(ctx, set, s, &released, &released_side))
            return FRICREG_OK;
    }
    return fr_fail(ctx, FRICREG_ESINGULAR,
                   "eval: the near-stick QP of %zu contacts (first: contact %zu) did not settle"
                   " in %zu active-set iterations (degenerate or ill-conditioned W_SS)",
                   s, set[0], (size_t)MAX_ITERATIONS(s));
}
