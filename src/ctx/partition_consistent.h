/* SPDX-License-Identifier: GPL-3.0-or-later */
/* partition_consistent.h — internal: the consistent law's near-stick forces, the box QP on S
 * (partition_consistent.c). */
#ifndef FRICREG_PARTITION_CONSISTENT_H
#define FRICREG_PARTITION_CONSISTENT_H

#include "ctx_internal.h"

/* The consistent law: the box QP on S (docs/coupled.md). Takes ctx->f with the slip forces on
 * L and 0 on S = ctx->stick[ctx->n_stick] (W dense) and completes ctx->f and ctx->f_eq on S.
 * FRICREG_OK or FRICREG_ESINGULAR (recorded); on failure ctx->f and ctx->f_eq are scratch. */
int fr_eval_consistent(fricreg_ctx *ctx, const double zdot[], const double a_free[]);

/* Every contact's working set forgotten: each starts the next QP from its own row's minimizer
 * (entering_side), as a contact that enters S does. */
void fr_consistent_forget_working_set(fricreg_ctx *ctx);

#endif
