/* SPDX-License-Identifier: GPL-3.0-or-later */
/* partition_paper.c — the paper's Sec. 3.3 partition with a dense W: every near-stick contact's
 * f_eq assumes all of S holds, W_SS f_eq,S = -(a_free,S + W_SL f_L), then the law on S. Kept to
 * reproduce the paper's Fig. 11; its force jumps when a coupled contact crosses |zdot| = eps. */
#include "factor.h"
#include "law.h"
#include "partition.h"

/* f_eq,S from W_SS f_eq,S = -(a_free,S + W_SL f_L). f holds f_L, and 0 on S. */
static int solve_feq(fricreg_ctx *ctx, const double a_free[])
{
    size_t s = ctx->n_stick, m = ctx->m;
    for (size_t a = 0; a < s; a++) {
        const double *row = ctx->W + ctx->stick[a] * m;
        double coupling = 0.0;
        for (size_t j = 0; j < m; j++)
            coupling += row[j] * ctx->f[j];
        ctx->rhs[a] = -(a_free[ctx->stick[a]] + coupling);
    }
    int status = fr_factor_ensure(ctx, ctx->stick, s, "eval");
    if (status == FRICREG_OK)
        status = fr_factor_solve(ctx, ctx->rhs, "eval");
    if (status != FRICREG_OK)
        return status;
    for (size_t a = 0; a < s; a++)
        ctx->f_eq[ctx->stick[a]] = ctx->rhs[a];
    return FRICREG_OK;
}

/* f_S = the law at (zdot_S, f_eq,S); the switch on the law stays outside the loops. */
#define STICK_LOOP(FORCE)                       \
    for (size_t a = 0; a < ctx->n_stick; a++) { \
        size_t i = ctx->stick[a];               \
        double v = zdot[i], feq = ctx->f_eq[i]; \
        ctx->f[i] = (FORCE);                    \
    }

static void apply_law_on_stick_set(fricreg_ctx *ctx, const double zdot[])
{
    const double eps = ctx->eps, *mun = ctx->mun;
    switch (ctx->law) {
    case FRICREG_LAW_QUINN: STICK_LOOP(fr_quinn(v, feq, mun[i], eps)) break;
    case FRICREG_LAW_KARNOPP: STICK_LOOP(fr_karnopp(v, feq, mun[i], eps)) break;
    default: STICK_LOOP(fr_force_balance(v, feq, mun[i])) break; /* the only other with S */
    }
}

int fr_eval_paper(fricreg_ctx *ctx, const double zdot[], const double a_free[])
{
    int status = solve_feq(ctx, a_free);
    if (status == FRICREG_OK)
        apply_law_on_stick_set(ctx, zdot);
    return status;
}
