/* SPDX-License-Identifier: GPL-3.0-or-later */
/* coupling.h — internal: W's rows and columns as the near-stick solvers read them, whether W
 * is dense (ctx->W, row-major) or sparse (ctx->sp): the one place that knows the difference
 * outside the factor (factor.c, sparse_block.c) and the set-up. */
#ifndef FRICREG_COUPLING_H
#define FRICREG_COUPLING_H

#include <stddef.h>

#include "ctx_internal.h"

/* sum_j W_ij x_j over every contact j (x indexed by contact), W_ii x_i left out when
 * skip_diagonal. The dense sum runs over j in order, as it always has. */
double fr_w_row_dot(const fricreg_ctx *ctx, size_t i, const double x[], int skip_diagonal);

/* sum_j |W_ij| x_j, x >= 0. */
double fr_w_row_abs_dot(const fricreg_ctx *ctx, size_t i, const double x[]);

/* out[a] = W_{set[a], k} for a < n. */
void fr_w_column_gather(fricreg_ctx *ctx, size_t k, const size_t set[], size_t n, double out[]);

#endif
