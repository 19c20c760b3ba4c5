/* SPDX-License-Identifier: GPL-3.0-or-later */
/* box_qp.h — internal: the consistent near-stick law's box-constrained convex QP on S. */
#ifndef FRICREG_BOX_QP_H
#define FRICREG_BOX_QP_H

#include <stddef.h>

#include "box_qp_state.h"

struct fricreg_ctx;

int fr_box_qp_alloc(struct fr_box_qp *qp, size_t m); /* FRICREG_OK or FRICREG_ENOMEM */
void fr_box_qp_free(struct fr_box_qp *qp);           /* safe on a zeroed or freed struct */

/* x = argmin 1/2 x^T W_SS x + b^T x on lo <= x <= hi, S = set[s] (ascending contact indices
 * into ctx->W), exactly (to rounding), from the working set qp->side. Iterations are counted in
 * FRICREG_STAT_QP_ITERATIONS. Returns FRICREG_OK, or FRICREG_ESINGULAR (recorded) if a free
 * set's W_FF is singular or the iteration safeguard is hit. */
int fr_box_qp_solve(struct fricreg_ctx *ctx, const size_t set[], size_t s);

#endif
