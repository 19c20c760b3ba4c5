/* SPDX-License-Identifier: GPL-3.0-or-later */
/* tangent_rows.c — the tangent of the last evaluation as one row per contact (ctx_driver.h),
 * for a driver that solves its own Newton system with it and must not form the m x m tangent
 * (fricreg_structure's Newmark step with a sparse W).
 *
 * The rows are tangent.c's Jacobian restated contact by contact (docs/coupled.md):
 *   slip contacts, and every contact of a law that does not read f_eq: df_i = s_i dzdot_i;
 *   held contacts of the consistent law's S (on a bound): df_i = h_i dzdot_i;
 *   free contacts F: W_FF df_F = -(d b_F + W_FA df_A + W_FL df_L) is row i of
 *     [W df]_i + k_i dzdot_i + dafree_i = 0,  k_i = W_ii t_i,
 *   with t_i = d(c_i bound_i)/d zdot_i (fr_tangent_free_slope), since W_ii df_i + the other
 *   terms of row i of W df are exactly W_F. df. No factor is needed: the driver solves.
 * The paper's partition does not restate so (its f_eq,S is solved, then put through law (4)'s
 * slopes): with a coupled W and a near-stick set it is refused. */
#include "coupling.h"
#include "law/law.h"
#include "partition.h"
#include "tangent.h"

int fr_ctx_tangent_rows(fricreg_ctx *ctx, unsigned char implicit[], double coef[])
{
    int status = fr_tangent_check_kept(ctx, "tangent");
    if (status != FRICREG_OK)
        return status;
    if (ctx->stribeck) /* the bounds of the evaluation's velocities */
        fr_stribeck_bounds(ctx, ctx->last_zdot);
    int coupled = fr_coupled(ctx) && fr_law_uses_feq(ctx->law);
    if (coupled)
        fr_split_contacts(ctx, ctx->last_zdot);
    if (!coupled || ctx->n_stick == 0) {
        for (size_t i = 0; i < ctx->m; i++) {
            double da;
            fr_tangent_diagonal_slopes(ctx, i, &coef[i], &da);
            implicit[i] = 0;
            if (da != 0.0) /* a near-stick contact of a diagonal W: W_ii df_i + k_i dzdot_i */
                implicit[i] = 1, coef[i] *= -ctx->w_diag[i]; /* + dafree_i = 0 */
        }
        return FRICREG_OK;
    }
    if (ctx->partition == FRICREG_PARTITION_PAPER)
        return FRICREG_EINVAL;
    for (size_t i = 0; i < ctx->m; i++) {
        implicit[i] = 0;
        if (!fr_needs_feq(ctx->law, ctx->last_zdot[i], ctx->eps))
            coef[i] = fr_tangent_off_band_slope(ctx, i, ctx->last_zdot[i]);
    }
    for (size_t a = 0; a < ctx->n_stick; a++) {
        size_t k = ctx->stick[a];
        implicit[k] = ctx->side[k] == FR_FREE;
        coef[k] = implicit[k] ? ctx->w_diag[k] * fr_tangent_free_slope(ctx, k)
                              : fr_tangent_held_slope(ctx, k);
    }
    return FRICREG_OK;
}

int fr_ctx_tangent_may_be_dense(const fricreg_ctx *ctx)
{
    return ctx->stribeck || (fr_coupled(ctx) && fr_law_uses_feq(ctx->law) &&
                             ctx->partition == FRICREG_PARTITION_PAPER);
}
