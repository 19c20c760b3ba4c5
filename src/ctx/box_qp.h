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
};

int fr_box_qp_alloc(struct fr_box_qp *qp, size_t m); /* FRICREG_OK or FRICREG_ENOMEM */
void fr_box_qp_free(struct fr_box_qp *qp);           /* safe on a zeroed or freed struct */

/* x = argmin 1/2 x^T W_SS x + b^T x on lo <= x <= hi, S = set[s] (ascending contact indices
 * into ctx->W), exactly (to rounding), from the working set qp->side. Iterations are counted in
 * FRICREG_STAT_QP_ITERATIONS. Returns FRICREG_OK, or FRICREG_ESINGULAR (recorded) if a free
 * set's W_FF is singular or the iteration safeguard is hit. */
int fr_box_qp_solve(struct fricreg_ctx *ctx, const size_t set[], size_t s);

#endif
