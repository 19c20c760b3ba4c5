/* SPDX-License-Identifier: GPL-3.0-or-later */
/* partition_paper.c — the paper's Sec. 3.3 partition with a coupled W (dense or sparse): every
 * near-stick contact's f_eq assumes all of S holds, W_SS f_eq,S = -(a_free,S + W_SL f_L), then
 * the law on S. Kept to reproduce the paper's Fig. 11; its force jumps when a coupled contact
 * crosses |zdot| = eps. */
#include "coupling.h"
#include "factor.h"
#include "law/law.h"
#include "partition_paper.h"

/* Lists the slipping contacts L (the complement of the ascending S) and their forces, packed:
 * W_SL f_L then reads only L's columns. The QP's scratch is free under this partition. */
static size_t list_slipping(fricreg_ctx *ctx)
{
    size_t *slip = ctx->qp.free_pos, n = 0, a = 0;
    double *f_slip = ctx->qp.y;
    for (size_t j = 0; j < ctx->m; j++) {
        if (a < ctx->n_stick && ctx->stick[a] == j) {
            a++;
            continue;
        }
        slip[n] = j;
        f_slip[n++] = ctx->f[j];
    }
    return n;
}

/* (W_SL f_L)_i for row i of W, in FR_LANES partial sums: independent chains, not one serial
 * sum. */
static double coupling(const double row[], const size_t slip[], const double f_slip[], size_t n)
{
    double sum[FR_LANES] = {0.0};
    size_t l = 0;
    for (; l + FR_LANES <= n; l += FR_LANES)
        for (size_t k = 0; k < FR_LANES; k++)
            sum[k] += row[slip[l + k]] * f_slip[l + k];
    for (; l < n; l++)
        sum[0] += row[slip[l]] * f_slip[l];
    return (sum[0] + sum[1]) + (sum[2] + sum[3]);
}

/* f_eq,S from W_SS f_eq,S = -(a_free,S + W_SL f_L). */
static int solve_feq(fricreg_ctx *ctx, const double a_free[])
{
    size_t s = ctx->n_stick, m = ctx->m;
    if (ctx->sp != NULL) { /* f is 0 on S: the row's product with f is W_SL f_L */
        for (size_t a = 0; a < s; a++)
            ctx->rhs[a] = -(a_free[ctx->stick[a]] + fr_w_row_dot(ctx, ctx->stick[a], ctx->f, 0));
    } else {
        size_t n_slip = list_slipping(ctx);
        for (size_t a = 0; a < s; a++) {
            const double *row = ctx->W + ctx->stick[a] * m;
            ctx->rhs[a] = -(a_free[ctx->stick[a]] +
                            coupling(row, ctx->qp.free_pos, ctx->qp.y, n_slip));
        }
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
    const double eps = ctx->eps, *mun = ctx->bound;
    FR_LAWS_LISTED(6);
    switch ((enum fricreg_law)ctx->law) {
    case FRICREG_LAW_QUINN: STICK_LOOP(fr_quinn(v, feq, mun[i], eps)) break;
    case FRICREG_LAW_KARNOPP: STICK_LOOP(fr_karnopp(v, feq, mun[i], eps)) break;
    case FRICREG_LAW_FORCE_BALANCE: STICK_LOOP(fr_force_balance(v, feq, mun[i])) break;
    case FRICREG_LAW_COULOMB:
    case FRICREG_LAW_VELOCITY_LIMITED:
    case FRICREG_LAW_TANH: break; /* their stick set S is empty */
    }
}

int fr_eval_paper(fricreg_ctx *ctx, const double zdot[], const double a_free[])
{
    int status = solve_feq(ctx, a_free);
    if (status == FRICREG_OK)
        apply_law_on_stick_set(ctx, zdot);
    return status;
}
