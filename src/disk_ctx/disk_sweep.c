/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_sweep.c — block Gauss-Seidel over the near-stick contacts of a coupled W: each sweep
 * solves every contact's subproblem exactly (disk_block.c) given the others' latest forces, a
 * descent step on the strictly convex QP (docs/laws2d.md, "Coupled 2-D contacts in a
 * context"). */
#include <math.h>

#include "disk_ctx_internal.h"

void fr_disk_add_coupling(const fricreg_disk_ctx *ctx, size_t i, int fixed_ones, double g[2])
{
    const struct fr_disk_coupling *w = &ctx->cpl->w;
    for (int64_t k = w->ptr[i]; k < w->ptr[i + 1]; k++) {
        size_t j = (size_t)w->col[k];
        if (j == i || (ctx->kind[j] == FR_DISK_FIXED) != fixed_ones)
            continue;
        const double *fj = ctx->f + 2 * j, *b = w->blk + 4 * k;
        g[0] += b[0] * fj[0] + b[1] * fj[1];
        g[1] += b[2] * fj[0] + b[3] * fj[1];
    }
}

double fr_disk_solve_contact(fricreg_disk_ctx *ctx, size_t i, const double g[2])
{
    double *f = ctx->f + 2 * i, old0 = f[0], old1 = f[1];
    int on = fr_disk_block_solve(&ctx->eig[i], g, ctx->p + 2 * i, ctx->radius[i], ctx->brent, f,
                                 &ctx->lam[i]);
    ctx->kind[i] = on ? FR_DISK_CIRCLE : FR_DISK_FREE;
    return hypot(f[0] - old0, f[1] - old1) / ctx->bound[i];
}

int fr_disk_sweep(fricreg_disk_ctx *ctx, double *moved)
{
    *moved = 0.0;
    for (size_t k = 0; k < ctx->n_near; k++) {
        size_t i = ctx->near[k];
        double g[2] = {ctx->g[2 * i], ctx->g[2 * i + 1]};
        fr_disk_add_coupling(ctx, i, 0, g);
        if (!isfinite(g[0]) || !isfinite(g[1]))
            return fr_fail(ctx, FRICREG_ENONFINITE, "eval: contact %zu's acceleration overflows",
                           i);
        *moved = fmax(*moved, fr_disk_solve_contact(ctx, i, g));
    }
    return FRICREG_OK;
}
