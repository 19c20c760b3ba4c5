/* SPDX-License-Identifier: GPL-3.0-or-later */
/* box_qp_bulk.h — internal: the box QP's steps that change several bounds at once
 * (box_qp_bulk.c), for a sparse W. */
#ifndef FRICREG_BOX_QP_BULK_H
#define FRICREG_BOX_QP_BULK_H

#include <stddef.h>

#include "box_qp_state.h"

struct fricreg_ctx;

/* The bulk steps (sparse W only; the subspace minimizer y of the free set in
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
