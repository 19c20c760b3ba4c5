/* SPDX-License-Identifier: GPL-3.0-or-later */
/* box_qp.h — internal: the consistent near-stick law's box-constrained convex QP on S. */
#ifndef FRICREG_BOX_QP_H
#define FRICREG_BOX_QP_H

#include <stddef.h>

struct fricreg_ctx;

/* Which bound a variable of the QP is held at: the working set of the active-set method. */
enum { FR_LOWER = -1, FR_FREE = 0, FR_UPPER = 1 };

/* Problem, solution and scratch for s <= m variables, indexed by position k in S. */
struct fr_box_qp {
    double *lo, *hi, *b; /* [m] in: bounds lo <= hi and the linear term */
    double *x;           /* [m] out: the minimizer */
    signed char *side;   /* [m] in: the working set to start from; out: the final one */
    double *y;           /* [m] scratch: the subspace minimizer on the free set */
    size_t *free_pos;    /* [m] scratch: positions of the free variables */
    size_t *free_set;    /* [m] scratch: their contact indices, the factor's key */
    size_t *held_pos;    /* [m] scratch: positions of the variables held at a bound */
    size_t n_held;       /* their count */
    /* Several working-set changes per iteration (box_qp_bulk.c), for a sparse W, whose
     * iterations cost O(m + nnz(L)) each: 0 with a dense W. */
    int bulk;
    size_t *released;           /* [m] scratch: the positions released together */
    signed char *released_side; /* [m] the bound each left */
    size_t n_released;          /* their count (0: none, or one released alone) */
};

int fr_box_qp_alloc(struct fr_box_qp *qp, size_t m); /* FRICREG_OK or FRICREG_ENOMEM */
void fr_box_qp_free(struct fr_box_qp *qp);           /* safe on a zeroed or freed struct */

/* x = argmin 1/2 x^T W_SS x + b^T x on lo <= x <= hi, S = set[s] (ascending contact indices
 * into ctx->W), exactly (to rounding), from the working set qp->side. Iterations are counted in
 * FRICREG_STAT_QP_ITERATIONS. Returns FRICREG_OK, or FRICREG_ESINGULAR (recorded) if a free
 * set's W_FF is singular or the iteration safeguard is hit. */
int fr_box_qp_solve(struct fricreg_ctx *ctx, const size_t set[], size_t s);

/* The bulk steps (box_qp_bulk.c, sparse W only; the subspace minimizer y of the free set in
 * qp->y, its positions in qp->free_pos[nf]):
 *   fr_box_qp_projected_step: when y leaves the box, x_F = the projection of y onto the box,
 *     every clamped variable held, if that lowers the objective; returns 1 if taken;
 *   fr_box_qp_release_all: at a minimizer of the working set, every held bound with a negative
 *     multiplier released, recorded in qp->released (the most negative first) and counted in
 *     qp->n_released, which it returns;
 *   fr_box_qp_keep_one: all of them held again but the most negative, which is returned, the
 *     bound it left in *side (qp->n_released back to 0). */
int fr_box_qp_projected_step(struct fricreg_ctx *ctx, const size_t set[], size_t nf);
size_t fr_box_qp_release_all(struct fricreg_ctx *ctx, const size_t set[], size_t s);
size_t fr_box_qp_keep_one(struct fr_box_qp *qp, signed char *side);

#endif
