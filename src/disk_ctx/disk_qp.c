/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_qp.c — fricreg_disk_ctx_eval: the consistent coupled 2-D law (fricreg_disk_ctx.h;
 * docs/laws2d.md, "Coupled 2-D contacts in a context"): fixed (sliding) contacts first, then
 * the near-stick contacts' QP over their disks, contact by contact (disk_block.c), by block
 * Gauss-Seidel when W couples them. */
#include <math.h>
#include <string.h>

#include "disk_ctx_internal.h"
#include "disk_polish.h"
#include "law/contact_check.h"
#include "law/law_disk.h"

#define GS_TOL 1e-14 /* a sweep moves no force by more than this times its bound: converged */
#define GS_MAX_SWEEPS 20000
#define POLISH_FIRST 8 /* Newton after sweep 8, 16, 32, ... while not converged */

/* Sorts contact i: fixed (its force written to ctx->f) or near stick (centre -p, radius). */
static void classify(fricreg_disk_ctx *ctx, size_t i, const double v[2])
{
    double r = hypot(v[0], v[1]), mun = fr_disk_bound(ctx, i, r); /* Stribeck: B_i(r) */
    double *p = ctx->p + 2 * i, *u = ctx->u + 2 * i, *f = ctx->f + 2 * i;
    ctx->r[i] = r;
    ctx->bound[i] = mun;
    u[0] = u[1] = 0.0;
    if (r > 0.0)
        fr_disk_direction(v, u);
    p[0] = p[1] = 0.0;
    ctx->radius[i] = mun;
    ctx->lam[i] = 0.0;
    int slides = ctx->law == FRICREG_DISK_QUINN ? r >= ctx->eps : r > 0.0;
    if (ctx->law == FRICREG_DISK_QUINN && r > 0.0 && !slides) {
        double rho = r / ctx->eps, a = mun * rho; /* as fr_disk_inscribed */
        p[0] = a * u[0];
        p[1] = a * u[1];
        ctx->radius[i] = mun * (1.0 - rho);
    }
    if (mun == 0.0 || slides || !(ctx->radius[i] > 0.0)) {
        ctx->kind[i] = FR_DISK_FIXED;
        f[0] = slides ? -mun * u[0] : -p[0]; /* the 2-D (1); K_i a point: its centre */
        f[1] = slides ? -mun * u[1] : -p[1];
        return;
    }
    ctx->kind[i] = FR_DISK_FREE;
    ctx->near[ctx->n_near++] = i;
}

/* g_i += sum over contacts j of `which` (j != i) of W_ij f_j, for contact i. */
static void add_coupling(const fricreg_disk_ctx *ctx, size_t i, int fixed_ones, double g[2])
{
    for (size_t j = 0; j < ctx->m; j++) {
        if (j == i || (ctx->kind[j] == FR_DISK_FIXED) != fixed_ones)
            continue;
        const double *fj = ctx->f + 2 * j;
        for (int a = 0; a < 2; a++)
            g[a] += fr_disk_w(ctx, i, a, j, 0) * fj[0] + fr_disk_w(ctx, i, a, j, 1) * fj[1];
    }
}

/* One near-stick contact's exact subproblem given g (its acceleration with f_i = 0); returns
 * how far its force moved, relative to its bound. */
static double solve_contact(fricreg_disk_ctx *ctx, size_t i, const double g[2])
{
    double *f = ctx->f + 2 * i, old0 = f[0], old1 = f[1];
    int on = fr_disk_block_solve(&ctx->eig[i], g, ctx->p + 2 * i, ctx->radius[i], ctx->brent, f,
                                 &ctx->lam[i]);
    ctx->kind[i] = on ? FR_DISK_CIRCLE : FR_DISK_FREE;
    return hypot(f[0] - old0, f[1] - old1) / ctx->bound[i];
}

/* One sweep over the near-stick contacts; *moved gets the largest change over its bound. */
static int sweep_once(fricreg_disk_ctx *ctx, double *moved)
{
    for (size_t k = 0; k < ctx->n_near; k++) {
        size_t i = ctx->near[k];
        double g[2] = {ctx->g[2 * i], ctx->g[2 * i + 1]};
        add_coupling(ctx, i, 0, g);
        if (!isfinite(g[0]) || !isfinite(g[1]))
            return fr_fail(ctx, FRICREG_ENONFINITE, "eval: contact %zu's acceleration overflows",
                           i);
        *moved = fmax(*moved, solve_contact(ctx, i, g));
    }
    return FRICREG_OK;
}

/* Block Gauss-Seidel over the near-stick contacts of a dense W: each sweep solves every
 * contact's subproblem exactly given the others' latest forces, a descent step on the strictly
 * convex QP, so the sweeps converge to its solution (linearly). */
static int gauss_seidel(fricreg_disk_ctx *ctx)
{
    for (size_t k = 0; k < ctx->n_near; k++) { /* the fixed contacts' share, once */
        size_t i = ctx->near[k];
        add_coupling(ctx, i, 1, ctx->g + 2 * i);
        if (!isfinite(ctx->g[2 * i]) || !isfinite(ctx->g[2 * i + 1]))
            return fr_fail(ctx, FRICREG_ENONFINITE, "eval: contact %zu's acceleration overflows",
                           i);
    }
    int next_polish = POLISH_FIRST;
    for (int sweep = 1; sweep <= GS_MAX_SWEEPS; sweep++) {
        double moved = 0.0;
        int status = sweep_once(ctx, &moved);
        if (status != FRICREG_OK)
            return status;
        if (moved <= GS_TOL)
            return FRICREG_OK;
        if (sweep == next_polish) { /* slow: Newton on this sweep's active set */
            next_polish *= 2;
            if (fr_disk_polish(ctx)) {
                status = sweep_once(ctx, &moved); /* verifies, and cleans to exact blocks */
                if (status != FRICREG_OK)
                    return status;
                if (moved <= GS_TOL)
                    return FRICREG_OK;
            }
        }
    }
    return fr_fail(ctx, FRICREG_ESINGULAR,
                   "eval: block Gauss-Seidel did not converge in %d sweeps (W on the "
                   "near-stick contacts singular or badly conditioned)",
                   GS_MAX_SWEEPS);
}

/* The inputs' status: NULL, then non-finite, then out of range. */
static int check_inputs(fricreg_disk_ctx *ctx, size_t m, const double zdot[], const double a_free[],
                        const double f[])
{
    int status = fr_check_eval_inputs(&ctx->err, m, ctx->m, 2 * m, zdot, a_free, f);
    if (status != FRICREG_OK)
        return status;
    for (size_t k = 0; k < 2 * m; k++)
        if (!fr_disk_in_range(zdot[k]) || !fr_disk_in_range(a_free[k]))
            return fr_fail(ctx, FRICREG_EINVAL, "eval: %s[%zu] is beyond 1e250",
                           fr_disk_in_range(zdot[k]) ? "a_free" : "zdot", k);
    return FRICREG_OK;
}

/* Classifies the contacts and solves the near-stick ones' QP into ctx->f; the state the
 * tangent reads. warm: start from the last successful forces. */
static int evaluate(fricreg_disk_ctx *ctx, const double zdot[], const double a_free[], int warm)
{
    size_t m = ctx->m;
    int status = FRICREG_OK;
    ctx->n_near = 0;
    for (size_t i = 0; i < m; i++)
        classify(ctx, i, zdot + 2 * i);
    for (size_t k = 0; k < ctx->n_near; k++) {
        size_t i = ctx->near[k];
        ctx->g[2 * i] = a_free[2 * i];
        ctx->g[2 * i + 1] = a_free[2 * i + 1];
        ctx->f[2 * i] = warm ? ctx->f_last[2 * i] : 0.0;
        ctx->f[2 * i + 1] = warm ? ctx->f_last[2 * i + 1] : 0.0;
    }
    if (ctx->W == NULL) { /* uncoupled: one exact subproblem per contact */
        for (size_t k = 0; k < ctx->n_near; k++)
            solve_contact(ctx, ctx->near[k], ctx->g + 2 * ctx->near[k]);
    } else if ((status = gauss_seidel(ctx)) != FRICREG_OK) {
        return status;
    }
    for (size_t k = 0; k < 2 * m; k++)
        if (!isfinite(ctx->f[k]))
            return fr_fail(ctx, FRICREG_ENONFINITE, "eval: force %zu overflows", k);
    return FRICREG_OK;
}

int fricreg_disk_ctx_eval(fricreg_disk_ctx *ctx, size_t m, const double zdot[],
                          const double a_free[], double f[])
{
    if (ctx == NULL)
        return FRICREG_ENULL;
    int status = check_inputs(ctx, m, zdot, a_free, f);
    if (status != FRICREG_OK)
        return status;
    int warm = ctx->last_valid && ctx->state_current;
    ctx->state_current = 0; /* a failure keeps last_valid: the tangent rebuilds the state */
    if ((status = evaluate(ctx, zdot, a_free, warm)) != FRICREG_OK)
        return status;
    memcpy(ctx->f_last, ctx->f, 2 * m * sizeof *f);
    memcpy(ctx->last_zdot, zdot, 2 * m * sizeof *zdot);
    memcpy(ctx->last_afree, a_free, 2 * m * sizeof *a_free);
    memcpy(f, ctx->f, 2 * m * sizeof *f);
    ctx->last_valid = 1;
    ctx->state_current = 1;
    return FRICREG_OK;
}

int fr_disk_restore_state(fricreg_disk_ctx *ctx)
{
    if (ctx->state_current)
        return FRICREG_OK;
    /* The same inputs from their own solution: the sweeps start converged. */
    int status = evaluate(ctx, ctx->last_zdot, ctx->last_afree, 1);
    ctx->state_current = status == FRICREG_OK;
    return status;
}
