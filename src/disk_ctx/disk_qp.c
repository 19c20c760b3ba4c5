/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_qp.c — fricreg_disk_ctx_eval: the consistent coupled 2-D law (fricreg_disk_ctx.h;
 * docs/laws2d.md, "Coupled 2-D contacts in a context"): fixed (sliding) contacts first, then
 * the near-stick contacts' QP over their disks, contact by contact (disk_block.c), by block
 * Gauss-Seidel (disk_sweep.c) and the projected Newton method (disk_newton.c) when W couples
 * them. */
#include <math.h>
#include <string.h>

#include "disk_ctx_internal.h"
#include "law/contact_check.h"
#include "law/law_disk.h"

#define GS_TOL 1e-14 /* a sweep moves no force by more than this times its bound: converged */
#define GS_MAX_SWEEPS 20000
#define GS_FIRST 8           /* sweeps before Newton's method */
#define NEWTON_MAX_ITER 100  /* Newton's iterations after the first sweeps */
#define NEWTON_RETRY_ITER 10 /* and between later sweeps */

/* Sorts contact i: fixed (its force written to ctx->f) or near stick (centre -p, radius). */
static void classify(fricreg_disk_ctx *ctx, size_t i, const double v[2])
{
    double r = v[0] == 0.0 && v[1] == 0.0 ? 0.0 : hypot(v[0], v[1]); /* at rest: no call */
    double mun = fr_disk_bound(ctx, i, r);                           /* Stribeck: B_i(r) */
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

/* The fixed contacts' share of each near-stick contact's acceleration, once, into ctx->g. */
static int add_fixed_share(fricreg_disk_ctx *ctx)
{
    for (size_t k = 0; k < ctx->n_near; k++) {
        size_t i = ctx->near[k];
        fr_disk_add_coupling(ctx, i, 1, ctx->g + 2 * i);
        if (!isfinite(ctx->g[2 * i]) || !isfinite(ctx->g[2 * i + 1]))
            return fr_fail(ctx, FRICREG_ENONFINITE, "eval: contact %zu's acceleration overflows",
                           i);
    }
    return FRICREG_OK;
}

/* Up to `sweeps` block Gauss-Seidel sweeps; *converged when one moves no force by more than
 * GS_TOL times its bound. */
static int sweep_until(fricreg_disk_ctx *ctx, int sweeps, int *converged)
{
    *converged = 0;
    for (int sweep = 1; sweep <= sweeps && !*converged; sweep++) {
        double moved = 0.0;
        int status = fr_disk_sweep(ctx, &moved);
        if (status != FRICREG_OK)
            return status;
        *converged = moved <= GS_TOL;
    }
    return FRICREG_OK;
}

/* The near-stick contacts' starting forces into the coupled W's scratch (save), or back
 * (restore): Newton starts where the sweeps did. Sweeps far from converging leave contacts on
 * their circles that the solution has inside (each sweep's subproblems see the others'
 * unconverged forces), and Newton would hold them there at first; the warm start, the last
 * solution, holds the right ones. */
static void keep_start(fricreg_disk_ctx *ctx, int save)
{
    double *kept = ctx->cpl->fl; /* Newton's, unused by the sweeps */
    for (size_t k = 0; k < ctx->n_near; k++) {
        size_t i = ctx->near[k];
        double *from = save ? ctx->f : kept, *to = save ? kept : ctx->f;
        to[2 * i] = from[2 * i];
        to[2 * i + 1] = from[2 * i + 1];
    }
}

/* The near-stick QP of a coupled W. Block Gauss-Seidel first, which ends in a few sweeps on
 * weakly coupled contacts (and gives there the numbers it always gave); else the projected
 * Newton method on the reduced Hessian's sparse factor (disk_newton.c), with which the next
 * evaluation then starts (an integrator's next state is near this one). Should Newton fail
 * (a singular W on the set), sweeps continue to GS_MAX_SWEEPS, with Newton retried after
 * sweeps 16, 32, ... */
static int solve_coupled(fricreg_disk_ctx *ctx, int warm)
{
    struct fr_disk_coupled *cpl = ctx->cpl;
    int converged = 0, status = add_fixed_share(ctx);
    if (status == FRICREG_OK && !(warm && cpl->newton_last)) {
        keep_start(ctx, 1);
        status = sweep_until(ctx, GS_FIRST, &converged);
        if (status != FRICREG_OK || converged) {
            cpl->newton_last = 0;
            return status;
        }
        keep_start(ctx, 0);
    }
    if (status == FRICREG_OK)
        status = fr_disk_newton(ctx, NEWTON_MAX_ITER, GS_TOL, &converged);
    for (int done = GS_FIRST, chunk = GS_FIRST;
         status == FRICREG_OK && !converged && done < GS_MAX_SWEEPS; chunk *= 2) {
        int n = chunk < GS_MAX_SWEEPS - done ? chunk : GS_MAX_SWEEPS - done;
        status = sweep_until(ctx, n, &converged);
        done += n;
        if (status == FRICREG_OK && !converged)
            status = fr_disk_newton(ctx, NEWTON_RETRY_ITER, GS_TOL, &converged);
    }
    if (status != FRICREG_OK)
        return status;
    if (!converged)
        return fr_fail(ctx, FRICREG_ESINGULAR,
                       "eval: neither Newton's method nor %d block Gauss-Seidel sweeps "
                       "converged (W on the near-stick contacts singular or badly conditioned)",
                       GS_MAX_SWEEPS);
    cpl->newton_last = 1;
    return FRICREG_OK;
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
    if (ctx->cpl == NULL) { /* uncoupled: one exact subproblem per contact */
        for (size_t k = 0; k < ctx->n_near; k++)
            fr_disk_solve_contact(ctx, ctx->near[k], ctx->g + 2 * ctx->near[k]);
    } else if ((status = solve_coupled(ctx, warm)) != FRICREG_OK) {
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
