/* SPDX-License-Identifier: GPL-3.0-or-later */
/* partition.h — internal: the slip/near-stick partition of the contacts (partition.c); the two
 * ways of finding the near-stick forces with a dense W are partition_paper.h and
 * partition_consistent.h. */
#ifndef FRICREG_PARTITION_H
#define FRICREG_PARTITION_H

#include "ctx_internal.h"

/* Splits the contacts at zdot[m]: slip contacts get their force in ctx->f, the near-stick
 * set S (where the law reads f_eq) is listed in ctx->stick[ctx->n_stick] with f = 0. */
void fr_split_contacts(fricreg_ctx *ctx, const double zdot[]);

#endif
