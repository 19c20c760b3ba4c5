/* SPDX-License-Identifier: GPL-3.0-or-later */
/* partition_paper.h — internal: the paper's near-stick forces with a dense W (partition_paper.c). */
#ifndef FRICREG_PARTITION_PAPER_H
#define FRICREG_PARTITION_PAPER_H

#include "ctx_internal.h"

/* The paper's Sec. 3.3: W_SS f_eq,S = -(a_free,S + W_SL f_L), then the law on S. Takes ctx->f
 * with the slip forces on L and 0 on S = ctx->stick[ctx->n_stick] (W dense, S non-empty) and
 * completes ctx->f and ctx->f_eq on S. FRICREG_OK or FRICREG_ESINGULAR (recorded); on failure
 * ctx->f and ctx->f_eq are scratch. */
int fr_eval_paper(fricreg_ctx *ctx, const double zdot[], const double a_free[]);

#endif
