/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_newton.c — the projected Newton method on the coupled 2-D law's QP
 *     min 1/2 f^T W_SS f + b^T f  over f_i in K_i (the disks), i in the near-stick set S,
 * for strongly coupled or badly conditioned W, where block Gauss-Seidel converges slowly (its
 * rate is about 1 - 1/cond(W): a stuck chain of 10^4 contacts has cond 4e7).
 *
 * Each iteration starts with a block pass: every near-stick contact's exact subproblem given
 * the others' forces (disk_block.c, as a sweep but all from one point). How far it moves the
 * forces is the stopping test, the one of the sweeps (converged: no force moves by more than
 * tol times its bound; the pass's forces are then the result). The active set holds the
 * contacts on their circles that the gradient pushes outwards (active_set below). On it,
 * Newton's step on the KKT conditions: a free contact moves in the plane, a held one along
 * its tangent t_i (the circle's curvature, its multiplier lam_i, in the Hessian) and onto
 * the circle along its normal n_i. The reduced Hessian H = Q^T (W_SS + Lambda) Q is sparse
 * and positive definite, factored by CHOLMOD (disk_factor.c), and kept while the set holds
 * and no contact is held. The step is projected onto the disks and halved until the
 * objective falls as Armijo's rule asks along the projection arc (D. P. Bertsekas,
 * "Projected Newton methods for optimization problems with simple constraints", SIAM J.
 * Control Optim. 20 (1982) 221-246): every iterate is feasible, every accepted step lowers
 * the strictly convex objective, and a step that finds no such point is replaced by a
 * Gauss-Seidel sweep, a descent step too. Once the set is right the step is exact when no
 * contact is held, and converges quadratically when some are. No allocation. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "base/line_search.h"
#include "disk_ctx_internal.h"

#define MAX_HALVINGS 29  /* 30 trials, alpha down to 2^-29 */
#define ACTIVE_ZONE 1e-3 /* the largest zone of the active set, relative to the radius */

/* acc_i = g_i + sum over near-stick j != i of W_ij f_j and the gradient
 * grad_i = acc_i + W_ii (f_i + 2 p_i) of every near-stick contact. */
static int near_accelerations(fricreg_disk_ctx *ctx)
{
    struct fr_disk_coupled *cpl = ctx->cpl;
    for (size_t k = 0; k < ctx->n_near; k++) {
        size_t i = ctx->near[k];
        double *acc = cpl->acc + 2 * i, *grad = cpl->grad + 2 * i;
        const double *f = ctx->f + 2 * i, *p = ctx->p + 2 * i, *A = ctx->blk + 4 * i;
        acc[0] = ctx->g[2 * i], acc[1] = ctx->g[2 * i + 1];
        fr_disk_add_coupling(ctx, i, 0, acc);
        if (!isfinite(acc[0]) || !isfinite(acc[1]))
            return fr_fail(ctx, FRICREG_ENONFINITE, "eval: contact %zu's acceleration overflows",
                           i);
        double h0 = f[0] + 2.0 * p[0], h1 = f[1] + 2.0 * p[1];
        grad[0] = acc[0] + A[0] * h0 + A[1] * h1;
        grad[1] = acc[1] + A[2] * h0 + A[3] * h1;
    }
    return FRICREG_OK;
}

/* Every near-stick contact's subproblem given acc, into fl, laml, onl; returns the largest
 * move over its bound. Both points lie in the bound's disk, so the move over the bound is at
 * most 2: its square cannot overflow, and one square root serves the pass. */
static double block_pass(fricreg_disk_ctx *ctx)
{
    struct fr_disk_coupled *cpl = ctx->cpl;
    double moved2 = 0.0;
    for (size_t k = 0; k < ctx->n_near; k++) {
        size_t i = ctx->near[k];
        double *fl = cpl->fl + 2 * i;
        const double *f = ctx->f + 2 * i;
        cpl->onl[i] = (signed char)fr_disk_block_solve(&ctx->eig[i], cpl->acc + 2 * i,
                                                       ctx->p + 2 * i, ctx->radius[i], ctx->brent,
                                                       fl, &cpl->laml[i]);
        double d0 = (fl[0] - f[0]) / ctx->bound[i], d1 = (fl[1] - f[1]) / ctx->bound[i];
        double d2 = d0 * d0 + d1 * d1;
        if (d2 > moved2)
            moved2 = d2;
    }
    return sqrt(moved2);
}

/* The block pass's forces as the result (exact subproblems: the sweeps' last pass). */
static void accept_block_pass(fricreg_disk_ctx *ctx)
{
    struct fr_disk_coupled *cpl = ctx->cpl;
    for (size_t k = 0; k < ctx->n_near; k++) {
        size_t i = ctx->near[k];
        ctx->f[2 * i] = cpl->fl[2 * i];
        ctx->f[2 * i + 1] = cpl->fl[2 * i + 1];
        ctx->kind[i] = cpl->onl[i] ? FR_DISK_CIRCLE : FR_DISK_FREE;
        ctx->lam[i] = cpl->laml[i];
    }
}

/* Newton's set: a contact is held on its circle when it is there already, within zone times
 * its radius (the epsilon-active set of Bertsekas's method, zone shrinking with the block
 * pass's move so that a contact coming to its circle is held before it zigzags along it),
 * its subproblem's solution is on the circle too, and the gradient pushes it outwards there
 * (its multiplier -n_i . grad_i/radius_i > 0: on the far side of its circle from its
 * solution it is pushed inwards, and crosses the disk); every other near-stick contact moves
 * freely, a step beyond its disk cut back by the projection. A held contact's normal
 * n_i = (f_i + p_i)/|f_i + p_i| and its known step n_i (radius_i - |f_i + p_i|) onto the
 * circle go into nrm and step (0 for the others). Returns whether some contact is held. */
static int active_set(fricreg_disk_ctx *ctx, double zone)
{
    struct fr_disk_coupled *cpl = ctx->cpl;
    int circle = 0;
    memset(cpl->nkind, FR_DISK_FIXED, ctx->m);
    for (size_t k = 0; k < ctx->n_near; k++) {
        size_t i = ctx->near[k];
        double *n = cpl->nrm + 2 * i, *s = cpl->step + 2 * i, R = ctx->radius[i];
        const double *f = ctx->f + 2 * i, *p = ctx->p + 2 * i;
        const double *g = cpl->grad + 2 * i;
        double y0 = f[0] + p[0], y1 = f[1] + p[1], ny = cpl->onl[i] ? hypot(y0, y1) : 0.0;
        int held = cpl->onl[i] && R - ny <= zone * R && g[0] * y0 + g[1] * y1 < 0.0;
        s[0] = s[1] = 0.0;
        cpl->nkind[i] = held ? FR_DISK_CIRCLE : FR_DISK_FREE;
        if (!held)
            continue;
        circle = 1;
        n[0] = y0 / ny, n[1] = y1 / ny;
        s[0] = (R - ny) * n[0], s[1] = (R - ny) * n[1];
    }
    return circle;
}

/* out_i = sum over near-stick j with mask[j] (all if mask is NULL) of W_ij x_j, for every
 * near-stick i. */
static void near_product(const fricreg_disk_ctx *ctx, const signed char *mask, const double x[],
                         double out[])
{
    const struct fr_disk_coupling *w = &ctx->cpl->w;
    for (size_t k = 0; k < ctx->n_near; k++) {
        size_t i = ctx->near[k];
        double s0 = 0.0, s1 = 0.0;
        for (int64_t e = w->ptr[i]; e < w->ptr[i + 1]; e++) {
            size_t j = (size_t)w->col[e];
            if (ctx->kind[j] == FR_DISK_FIXED || (mask != NULL && mask[j] != FR_DISK_CIRCLE))
                continue;
            const double *b = w->blk + 4 * e, *xj = x + 2 * j;
            s0 += b[0] * xj[0] + b[1] * xj[1];
            s1 += b[2] * xj[0] + b[3] * xj[1];
        }
        out[2 * i] = s0, out[2 * i + 1] = s1;
    }
}

/* The right-hand side of the reduced system into trial, in each contact's frame: -(grad +
 * W s) for a free contact (s the known steps onto the circles); for a circle contact its
 * tangential part with the curvature's term, -t . (grad + W s + lam (f + p)), the normal
 * unknown 0 (prescribed); 0 for the fixed contacts. */
static void reduced_rhs(fricreg_disk_ctx *ctx, int circle)
{
    struct fr_disk_coupled *cpl = ctx->cpl;
    memset(cpl->trial, 0, 2 * ctx->m * sizeof *cpl->trial);
    if (circle)
        near_product(ctx, cpl->nkind, cpl->step, cpl->wd);
    for (size_t k = 0; k < ctx->n_near; k++) {
        size_t i = ctx->near[k];
        double r0 = cpl->grad[2 * i] + (circle ? cpl->wd[2 * i] : 0.0);
        double r1 = cpl->grad[2 * i + 1] + (circle ? cpl->wd[2 * i + 1] : 0.0);
        if (cpl->nkind[i] == FR_DISK_FREE) {
            cpl->trial[2 * i] = -r0, cpl->trial[2 * i + 1] = -r1;
            continue;
        }
        const double *n = cpl->nrm + 2 * i, *f = ctx->f + 2 * i, *p = ctx->p + 2 * i;
        double t0 = -n[1], t1 = n[0];
        double curv = cpl->laml[i] * (t0 * (f[0] + p[0]) + t1 * (f[1] + p[1]));
        cpl->trial[2 * i + 1] = -(t0 * r0 + t1 * r1 + curv);
    }
}

/* Newton's step into step: the reduced system solved, back in the plane. Returns -1 if the
 * reduced Hessian is singular on the set (the caller sweeps instead), else whether some
 * contact is on its circle. */
static int newton_direction(fricreg_disk_ctx *ctx, double moved)
{
    struct fr_disk_coupled *cpl = ctx->cpl;
    int circle = active_set(ctx, fmin(ACTIVE_ZONE, moved));
    size_t pivot;
    if (!fr_disk_factor_holds(&cpl->F, cpl->nkind) &&
        fr_disk_factor_build(&cpl->F, &cpl->w, cpl->nkind, cpl->nrm, cpl->laml, &pivot) !=
            FRICREG_OK)
        return -1;
    reduced_rhs(ctx, circle);
    if (fr_disk_factor_solve(&cpl->F, cpl->trial, cpl->trial) != FRICREG_OK)
        return -1;
    for (size_t k = 0; k < ctx->n_near; k++) {
        size_t i = ctx->near[k];
        double *s = cpl->step + 2 * i;
        const double *x = cpl->trial + 2 * i, *n = cpl->nrm + 2 * i;
        if (cpl->nkind[i] == FR_DISK_FREE) {
            s[0] = x[0], s[1] = x[1];
        } else { /* the known normal part, plus the tangent's */
            s[0] += -n[1] * x[1];
            s[1] += n[0] * x[1];
        }
    }
    return circle;
}

/* trial = the projection of f + alpha step onto the disks (Euclidean: any projection keeps
 * the iterate feasible); returns whether some point was outside its disk. */
static int project_trial(fricreg_disk_ctx *ctx, double alpha)
{
    struct fr_disk_coupled *cpl = ctx->cpl;
    int clipped = 0;
    for (size_t k = 0; k < ctx->n_near; k++) {
        size_t i = ctx->near[k];
        const double *f = ctx->f + 2 * i, *s = cpl->step + 2 * i, *p = ctx->p + 2 * i;
        double *z = cpl->trial + 2 * i;
        double y0 = f[0] + alpha * s[0] + p[0], y1 = f[1] + alpha * s[1] + p[1];
        double R = ctx->radius[i];
        if (!(y0 * y0 + y1 * y1 <= R * R)) { /* outside, or squares beyond the range */
            double ny = hypot(y0, y1);
            if (ny > R) {
                y0 *= R / ny, y1 *= R / ny;
                clipped = 1;
            }
        }
        z[0] = y0 - p[0], z[1] = y1 - p[1];
    }
    return clipped;
}

/* |y|^2 - radius^2 of y = f_i + p_i, 0 within rounding of the circle (y's own rounding is
 * that of f_i and p_i, which may be far larger than the radius near the band's edge): a
 * point on its circle before and after a step adds nothing below. */
static double off_circle(const double f[2], const double p[2], double R)
{
    double y0 = f[0] + p[0], y1 = f[1] + p[1], c = (y0 * y0 + y1 * y1) - R * R;
    double size = R + fabs(f[0]) + fabs(f[1]) + fabs(p[0]) + fabs(p[1]);
    return fabs(c) <= 16.0 * DBL_EPSILON * R * size ? 0.0 : c;
}

/* The change of the objective q from f to trial, q(trial) - q(f) = grad . d + 1/2 d^T W d
 * (d = trial - f), and its first-order part *slope = grad . d. On a circle contact grad_i is
 * nearly -lam_i y_i, large, and d_i's normal part rounding on the order of DBL_EPSILON times
 * the radius, whose product would swamp a small step's change: so both are summed as
 *     grad_i . d_i = (grad_i + lam_i y_i) . d_i - lam_i/2 (|y_i'|^2 - |y_i|^2 - |d_i|^2),
 * the identity y . d = (|y + d|^2 - |y|^2 - |d|^2)/2, with the first factor small near the
 * solution and the squared radii exact where a point is on its circle. */
static double objective_change(fricreg_disk_ctx *ctx, double *slope)
{
    struct fr_disk_coupled *cpl = ctx->cpl;
    double *d = cpl->wd, lin = 0.0, quad = 0.0;
    memset(d, 0, 2 * ctx->m * sizeof *d);
    for (size_t k = 0; k < ctx->n_near; k++) {
        size_t i = ctx->near[k];
        const double *f = ctx->f + 2 * i, *z = cpl->trial + 2 * i, *p = ctx->p + 2 * i;
        const double *g = cpl->grad + 2 * i;
        double *di = d + 2 * i;
        di[0] = z[0] - f[0], di[1] = z[1] - f[1];
        if (cpl->nkind[i] != FR_DISK_CIRCLE) {
            lin += g[0] * di[0] + g[1] * di[1];
            continue;
        }
        double lam = cpl->laml[i], R = ctx->radius[i];
        double gl0 = g[0] + lam * (f[0] + p[0]), gl1 = g[1] + lam * (f[1] + p[1]);
        double grow = off_circle(z, p, R) - off_circle(f, p, R);
        lin += gl0 * di[0] + gl1 * di[1] - 0.5 * lam * (grow - (di[0] * di[0] + di[1] * di[1]));
    }
    near_product(ctx, NULL, d, cpl->acc); /* acc is recomputed at the next iterate */
    for (size_t k = 0; k < ctx->n_near; k++) {
        size_t i = ctx->near[k];
        quad += d[2 * i] * cpl->acc[2 * i] + d[2 * i + 1] * cpl->acc[2 * i + 1];
    }
    *slope = lin;
    return lin + 0.5 * quad;
}

/* A trial at alpha along the projection arc; accepted by Armijo's rule on the objective's
 * change, or at once when it is the full step and leaves every contact inside its disk with
 * none on its circle (the unconstrained minimizer on the set): then f = trial. */
struct disk_trial {
    fricreg_disk_ctx *ctx;
    const struct fr_line_search *ls;
    int circle;
};

static int disk_trial(void *user, double alpha, int *accept)
{
    struct disk_trial *t = user;
    fricreg_disk_ctx *ctx = t->ctx;
    struct fr_disk_coupled *cpl = ctx->cpl;
    int clipped = project_trial(ctx, alpha);
    double slope = 0.0, change = 0.0;
    *accept = alpha == 1.0 && !t->circle && !clipped;
    if (!*accept) {
        change = objective_change(ctx, &slope);
        *accept = fr_armijo_holds(t->ls, change, slope);
    }
    if (*accept)
        for (size_t k = 0; k < ctx->n_near; k++) {
            size_t i = ctx->near[k];
            ctx->f[2 * i] = cpl->trial[2 * i];
            ctx->f[2 * i + 1] = cpl->trial[2 * i + 1];
        }
    return FRICREG_OK;
}

/* Armijo's rule along the projection arc, alpha = 1, 1/2, ...: on success f = trial, 1. */
static int line_search(fricreg_disk_ctx *ctx, int circle)
{
    struct fr_line_search ls = {FR_ARMIJO, MAX_HALVINGS, NULL};
    struct disk_trial t = {ctx, &ls, circle};
    int accepted;
    fr_line_search(&ls, 1.0, disk_trial, &t, &accepted); /* the trials cannot fail */
    return accepted;
}

/* f onto the disks: a warm start (the last evaluation's forces) may lie outside the disks of
 * new velocities, and the line search compares feasible points. */
static void project_forces(fricreg_disk_ctx *ctx)
{
    struct fr_disk_coupled *cpl = ctx->cpl;
    memset(cpl->step, 0, 2 * ctx->m * sizeof *cpl->step);
    project_trial(ctx, 0.0);
    for (size_t k = 0; k < ctx->n_near; k++) {
        size_t i = ctx->near[k];
        ctx->f[2 * i] = cpl->trial[2 * i];
        ctx->f[2 * i + 1] = cpl->trial[2 * i + 1];
    }
}

int fr_disk_newton(fricreg_disk_ctx *ctx, int max_iter, double tol, int *converged)
{
    *converged = 0;
    project_forces(ctx);
    for (int it = 0;; it++) {
        int status = near_accelerations(ctx);
        if (status != FRICREG_OK)
            return status;
        double moved = block_pass(ctx);
        if (moved <= tol) {
            accept_block_pass(ctx);
            *converged = 1;
            return FRICREG_OK;
        }
        if (it == max_iter)
            return FRICREG_OK;
        int circle = newton_direction(ctx, moved);
        if (circle >= 0 && line_search(ctx, circle))
            continue;
        /* no descent found: a sweep, which always descends */
        if ((status = fr_disk_sweep(ctx, &moved)) != FRICREG_OK)
            return status;
    }
}
