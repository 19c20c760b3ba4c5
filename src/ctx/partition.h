/* SPDX-License-Identifier: GPL-3.0-or-later */
/* partition.h — internal: the two ways of finding the near-stick forces with a dense W. */
#ifndef FRICREG_PARTITION_H
#define FRICREG_PARTITION_H

#include "ctx_internal.h"

/* Splits the contacts at zdot[m]: slip contacts get their force in ctx->f, the near-stick
 * set S (where the law reads f_eq) is listed in ctx->stick[ctx->n_stick] with f = 0. */
void fr_split_contacts(fricreg_ctx *ctx, const double zdot[]);

/* Both take ctx->f with the slip forces on L and 0 on S = ctx->stick[ctx->n_stick] (W dense;
 * S non-empty for the paper's), and complete ctx->f on S and ctx->f_eq on S. They return FRICREG_OK or
 * FRICREG_ESINGULAR (recorded); on failure ctx->f and ctx->f_eq are scratch. */

/* The paper's Sec. 3.3: W_SS f_eq,S = -(a_free,S + W_SL f_L), then the law on S
 * (partition_paper.c). */
int fr_eval_paper(fricreg_ctx *ctx, const double zdot[], const double a_free[]);

/* The consistent law: the box QP on S (partition_consistent.c, docs/coupled.md). */
int fr_eval_consistent(fricreg_ctx *ctx, const double zdot[], const double a_free[]);

/* Every contact's working set forgotten: each starts the next QP from its own row's minimizer
 * (partition_consistent.c, entering_side), as a contact that enters S does. */
void fr_consistent_forget_working_set(fricreg_ctx *ctx);

/* c_i = 2 zdot_i/eps for (4), 0 for Karnopp and (2): where contact i sits in the band. */
static inline double fr_band_position(const fricreg_ctx *ctx, double zdot)
{
    return ctx->law == FRICREG_LAW_QUINN ? zdot * (2.0 / ctx->eps) : 0.0;
}

#endif
