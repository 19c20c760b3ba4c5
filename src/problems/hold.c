/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hold.c — the hold test (problems.h, docs/laws2d.md): a block on an incline under
 * a load inside the friction disk must not creep at all, and, tilted at a constant rate, must
 * leave rest at the exact angle atan(mu). Both follow from the law's exact stick: at v = 0,
 * FRICREG_DISK_QUINN returns f_eq itself, so F + f == 0 in floating point and every RK4 stage
 * from rest stays at rest until a stage's tilt is past atan(mu). The default law is that one;
 * the benchmark (bench/problems_wp.c) runs the other 2-D laws too, for their creep. */
#include <math.h>

#include "fricreg_disk.h"
#include "prob_internal.h"

struct prob_hold prob_hold_defaults(void)
{
    const double mu = 0.5385;
    return (struct prob_hold){.law = FRICREG_DISK_QUINN,
                              .mass = 2.385,
                              .g = 9.81,
                              .mu = mu,
                              .theta0 = atan(0.8 * mu),
                              .phi = 0.6180339887,
                              .kappa = 0.0,
                              .dt = 1e-4,
                              .eps = 2e-3,
                              .steps = 1e5};
}

struct hold_rhs {
    const struct prob_hold *p;
    int law;
    double F[2], mun; /* at a fixed tilt (kappa = 0): the load and the bound, computed once */
    int status;
};

static double tilt(const struct prob_hold *p, double t)
{
    return p->theta0 + p->kappa * t;
}

/* The load F = M g sin(theta) (cos phi, sin phi) and the bound mun = mu M g cos(theta) at t. */
static void load(const struct prob_hold *p, double t, double F[2], double *mun)
{
    double theta = tilt(p, t), along = p->mass * p->g * sin(theta);
    F[0] = along * cos(p->phi);
    F[1] = along * sin(p->phi);
    *mun = p->mu * p->mass * p->g * cos(theta);
}

/* y = (x1, x2, v1, v2): x' = v, M v' = F + f with f_eq = -F. */
static int rhs(double t, const double y[], double dy[], void *params)
{
    struct hold_rhs *r = params;
    const struct prob_hold *p = r->p;
    double F[2] = {r->F[0], r->F[1]}, mun = r->mun, f[2];
    if (p->kappa != 0.0)
        load(p, t, F, &mun);
    double feq[2] = {-F[0], -F[1]};
    int status = fricreg_disk_eval(r->law, y + 2, feq, mun, p->eps, f);
    if (status != FRICREG_OK) {
        r->status = status;
        return GSL_EBADFUNC;
    }
    dy[0] = y[2];
    dy[1] = y[3];
    dy[2] = (F[0] + f[0]) / p->mass;
    dy[3] = (F[1] + f[1]) / p->mass;
    return GSL_SUCCESS;
}

static int valid(const struct prob_hold *p)
{
    const double finite[8] = {p->mass, p->g, p->mu, p->theta0, p->phi, p->kappa, p->dt, p->eps};
    for (int k = 0; k < 8; k++)
        if (!isfinite(finite[k]))
            return 0;
    return p->mass > 0.0 && p->g > 0.0 && p->mu > 0.0 && p->theta0 >= 0.0 &&
           p->theta0 < 2.0 * atan(1.0) && p->kappa >= 0.0 && p->dt > 0.0 && p->eps > 0.0 &&
           p->steps >= 2.0 && p->steps <= 1e10;
}

int prob_hold_run(const struct prob_hold *p, prob_observer observe, void *user,
                  struct prob_hold_result *r)
{
    if (!valid(p))
        return FRICREG_EINVAL;
    struct hold_rhs params = {
        p, p->law != 0 ? p->law : FRICREG_DISK_QUINN, {0.0, 0.0}, 0.0, FRICREG_OK};
    load(p, 0.0, params.F, &params.mun);
    struct prob_rk4 rk;
    int status = prob_rk4_init(&rk, rhs, 4, &params, p->dt);
    if (status != FRICREG_OK)
        return status;
    const double h = 2.0 * p->dt, n = floor(p->steps / 2.0);
    double y[4] = {0.0, 0.0, 0.0, 0.0}, k = 0.0, stop = n;
    *r = (struct prob_hold_result){0};
    for (; status == FRICREG_OK && k < stop; k += 1.0) {
        double t = k * h;
        status = prob_rk4_advance(&rk, t, y, &params.status);
        if (status != FRICREG_OK)
            break;
        double row[PROB_HOLD_COLUMNS] = {tilt(p, t + h), y[0], y[1], y[2], y[3]};
        if (observe != NULL && observe(user, t + h, row, PROB_HOLD_COLUMNS) != 0)
            status = FRICREG_ENOMEM;
        int moving = y[2] != 0.0 || y[3] != 0.0;
        if (p->kappa == 0.0) { /* a fixed tilt: the creep over the whole run */
            r->creep = fmax(r->creep, hypot(y[2], y[3]));
            r->broke_away |= moving;
        } else if (moving && !r->broke_away) {
            r->broke_away = 1; /* this step left rest: its tilts bracket atan(mu) */
            r->theta_rest = tilt(p, t);
            r->theta_moving = tilt(p, t + h);
            stop = fmin(n, k + 1.0 + floor(1.0 / h)); /* one second of sliding for the plot */
        }
    }
    prob_rk4_free(&rk);
    if (status != FRICREG_OK)
        return status;
    r->displacement = hypot(y[0], y[1]);
    r->steps = 2.0 * k;
    r->t = k * h;
    if (p->kappa > 0.0 && !r->broke_away)
        return FRICREG_EDIVERGED; /* no break-away within the steps: reported by the caller */
    return FRICREG_OK;
}
