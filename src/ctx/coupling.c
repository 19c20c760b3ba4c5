/* SPDX-License-Identifier: GPL-3.0-or-later */
/* coupling.c — W's rows and columns, dense or sparse (coupling.h). */
#include <math.h>

#include "coupling.h"
#include "sparse_coupling.h"

double fr_w_row_dot(const fricreg_ctx *ctx, size_t i, const double x[], int skip_diagonal)
{
    if (ctx->sp != NULL)
        return fr_sparse_row_dot(ctx->sp, i, x, skip_diagonal, NULL);
    const double *row = ctx->W + i * ctx->m;
    double sum = 0.0;
    for (size_t j = 0; j < ctx->m; j++)
        sum += skip_diagonal && j == i ? 0.0 : row[j] * x[j];
    return sum;
}

double fr_w_row_abs_dot(const fricreg_ctx *ctx, size_t i, const double x[])
{
    if (ctx->sp != NULL)
        return fr_sparse_row_abs_dot(ctx->sp, i, x);
    const double *row = ctx->W + i * ctx->m;
    double sum = 0.0;
    for (size_t j = 0; j < ctx->m; j++)
        sum += fabs(row[j]) * x[j];
    return sum;
}

void fr_w_column_gather(fricreg_ctx *ctx, size_t k, const size_t set[], size_t n, double out[])
{
    if (ctx->sp != NULL) {
        fr_sparse_column_gather(ctx->sp, k, set, n, out);
        return;
    }
    for (size_t a = 0; a < n; a++)
        out[a] = ctx->W[set[a] * ctx->m + k];
}
