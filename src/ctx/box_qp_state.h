/* SPDX-License-Identifier: GPL-3.0-or-later */
/* box_qp_state.h — internal: the box QP's working set and workspace, part of the context's
 * layout (ctx_internal.h); its solve is box_qp.h's, its bulk steps box_qp_bulk.h's. */
#ifndef FRICREG_BOX_QP_STATE_H
#define FRICREG_BOX_QP_STATE_H

#include <stddef.h>

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

#endif
