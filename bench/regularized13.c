/* SPDX-License-Identifier: GPL-3.0-or-later */
/* regularized13.c — the three problems of issue 13 (issue13.h) under fricreg's regularized
 * laws, stepped by GSL's fixed-step classical RK4 (gsl_odeiv2_step_rk4 through
 * gsl_odeiv2_step_apply, one step of size dt = two classical half steps, as fricreg_sim's RK4:
 * 11 right-hand sides per step, the derivative at the step's end being reused).
 *   belt: law fricreg_stribeck_eval, eps = 2 dt; the period between the last two downward
 *         crossings of x = 0 and the amplitude from the extrema of x between them, both located
 *         inside a step on the cubic Hermite interpolant of (x, x') (error O(dt^4), below the
 *         method's) by GSL's Brent solver;
 *   disk: law fricreg_disk_eval (any 2-D law), eps = 2 dt, dt = one turn / N so that the turn
 *         boundaries are step ends; the dissipated energy is one more unknown, E' = -f . v;
 *   hold: law fricreg_disk_eval, eps = 20 dt as tests/test_hold.c, from rest with the load
 *         inside the friction disk; creep = |x(T) - x(0)| / T and the largest |v|. */
#include <math.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_roots.h>

#include "fricreg_disk.h"
#include "fricreg_stribeck.h"

#include "issue13.h"

/* ---- Stepping --------------------------------------------------------------------------- */

struct law_params {
    int law; /* enum fricreg_disk_law (disk, hold); unused by the belt */
    double eps;
    double load[2], mun; /* hold only */
};

/* One GSL RK4 step of size dt from (t, y) with dydt the derivative at its start; on return y
 * and dydt are at t + dt and y0, d0 keep the start. Returns GSL's status. */
static int step(gsl_odeiv2_step *st, const gsl_odeiv2_system *sys, double t, double dt, double y[],
                double dydt[], double y0[], double d0[])
{
    size_t dim = sys->dimension;
    double yerr[5], dout[5];
    memcpy(y0, y, dim * sizeof *y);
    memcpy(d0, dydt, dim * sizeof *y);
    int s = gsl_odeiv2_step_apply(st, t, dt, y, yerr, d0, dout, sys);
    memcpy(dydt, dout, dim * sizeof *y);
    return s;
}

/* ---- Locating events inside a step: the cubic Hermite interpolant ----------------------- */

/* x(theta) on [0, 1] (theta = (t - t0)/dt) through (x0, x0') and (x1, x1'), as c0 + c1 th + … */
struct cubic {
    double c[4];
    int derivative; /* 1: the root function is x'(theta), else x(theta) */
};

static struct cubic hermite(double x0, double d0, double x1, double d1, double dt)
{
    struct cubic p = {{x0, dt * d0, -3 * x0 - 2 * dt * d0 + 3 * x1 - dt * d1,
                       2 * x0 + dt * d0 - 2 * x1 + dt * d1},
                      0};
    return p;
}

static double cubic_value(const struct cubic *p, double th)
{
    return p->c[0] + th * (p->c[1] + th * (p->c[2] + th * p->c[3]));
}

static double root_fn(double th, void *vp)
{
    const struct cubic *p = vp;
    if (p->derivative)
        return p->c[1] + th * (2 * p->c[2] + th * 3 * p->c[3]);
    return cubic_value(p, th);
}

/* The root in [0, 1] of x(theta) or x'(theta), whose values at the ends differ in sign (or
 * vanish): GSL's Brent solver to 1e-14 in theta. */
static double locate(gsl_root_fsolver *solver, struct cubic *p, int derivative)
{
    p->derivative = derivative;
    gsl_function F = {root_fn, p};
    double f0 = root_fn(0.0, p), f1 = root_fn(1.0, p);
    if (f0 == 0.0)
        return 0.0;
    if (f1 == 0.0 || f0 * f1 > 0.0)
        return 1.0;
    gsl_root_fsolver_set(solver, &F, 0.0, 1.0);
    for (int it = 0; it < 100; it++) {
        gsl_root_fsolver_iterate(solver);
        double lo = gsl_root_fsolver_x_lower(solver), hi = gsl_root_fsolver_x_upper(solver);
        if (gsl_root_test_interval(lo, hi, 1e-14, 0.0) == GSL_SUCCESS)
            break;
    }
    return gsl_root_fsolver_root(solver);
}

/* ---- The belt ----------------------------------------------------------------------------- */

static int belt_rhs(double t, const double y[], double dy[], void *vp)
{
    const struct law_params *p = vp;
    double f;
    (void)t;
    if (fricreg_stribeck_eval(y[1] - BELT_V, y[0], BELT_FS, BELT_FK, BELT_VS, BELT_DELTA, p->eps,
                              &f) != FRICREG_OK)
        return GSL_EBADFUNC;
    dy[0] = y[1];
    dy[1] = -y[0] + f;
    return GSL_SUCCESS;
}

int belt_rk4_run(double dt, int cycles, struct belt_cycle *out)
{
    struct law_params p = {0, 2.0 * dt, {0.0, 0.0}, 0.0};
    gsl_odeiv2_system sys = {belt_rhs, NULL, 2, &p};
    gsl_odeiv2_step *st = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk4, 2);
    gsl_root_fsolver *solver = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    *out = (struct belt_cycle){NAN, NAN, 0.0, 0.0};
    if (!st || !solver) {
        gsl_odeiv2_step_free(st);
        gsl_root_fsolver_free(solver);
        return FRICREG_ENOMEM;
    }
    double y[2] = {0.0, BELT_V}, dydt[2], y0[2], d0[2], t = 0.0, last_cross = NAN;
    double xmax = -INFINITY, xmin = INFINITY;
    int n_cross = 0, status = belt_rhs(t, y, dydt, &p) == GSL_SUCCESS ? FRICREG_OK : FRICREG_EINVAL;
    while (status == FRICREG_OK && n_cross <= cycles) {
        if (step(st, &sys, t, dt, y, dydt, y0, d0) != GSL_SUCCESS || !isfinite(y[0])) {
            status = FRICREG_EINTEGRATOR;
            break;
        }
        struct cubic x = hermite(y0[0], d0[0], y[0], dydt[0], dt);
        if ((y0[1] > 0.0) != (y[1] > 0.0)) { /* x' changes sign: an extremum of x */
            double v = cubic_value(&x, locate(solver, &x, 1));
            xmax = fmax(xmax, v);
            xmin = fmin(xmin, v);
        }
        if (y0[0] > 0.0 && y[0] <= 0.0) { /* a downward crossing of x = 0 ends a cycle */
            double tc = t + dt * locate(solver, &x, 0);
            if (++n_cross > cycles) {
                out->period = tc - last_cross;
                out->amplitude = 0.5 * (xmax - xmin);
            }
            last_cross = tc;
            xmax = -INFINITY, xmin = INFINITY;
        }
        t += dt;
        out->steps += 1.0;
    }
    gsl_odeiv2_step_free(st);
    gsl_root_fsolver_free(solver);
    return status;
}

/* ---- The 2-D oscillator with rotating forcing -------------------------------------------- */

static int disk_rhs(double t, const double y[], double dy[], void *vp)
{
    const struct law_params *p = vp;
    double s = DISK_A * sin(DISK_OMEGA * t), phi = DISK_OMEGA / DISK_CYCLES_PER_TURN * t;
    double F[2] = {s * cos(phi), s * sin(phi)}, feq[2] = {y[0] - F[0], y[1] - F[1]}, f[2];
    if (fricreg_disk_eval(p->law, y + 2, feq, 1.0, p->eps, f) != FRICREG_OK)
        return GSL_EBADFUNC;
    dy[0] = y[2];
    dy[1] = y[3];
    dy[2] = -y[0] + f[0] + F[0];
    dy[3] = -y[1] + f[1] + F[1];
    dy[4] = -(f[0] * y[2] + f[1] * y[3]);
    return GSL_SUCCESS;
}

int disk_rk4_run(int law, long steps_per_turn, struct disk_result *out)
{
    double turn = 2.0 * ISSUE13_PI * DISK_CYCLES_PER_TURN / DISK_OMEGA;
    double dt = turn / (double)steps_per_turn;
    struct law_params p = {law, 2.0 * dt, {0.0, 0.0}, 0.0};
    gsl_odeiv2_system sys = {disk_rhs, NULL, 5, &p};
    gsl_odeiv2_step *st = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk4, 5);
    *out = (struct disk_result){NAN, 0.0, 0.0};
    if (!st)
        return FRICREG_ENOMEM;
    double y[5] = {0.0, 0.0, 0.0, 0.0, 0.0}, dydt[5], y0[5], d0[5], E_start = 0.0;
    int status = disk_rhs(0.0, y, dydt, &p) == GSL_SUCCESS ? FRICREG_OK : FRICREG_EINVAL;
    long n = (DISK_TURNS_TRANSIENT + 1) * steps_per_turn;
    for (long k = 0; k < n && status == FRICREG_OK; k++) {
        if (k == DISK_TURNS_TRANSIENT * steps_per_turn)
            E_start = y[4];
        if (step(st, &sys, (double)k * dt, dt, y, dydt, y0, d0) != GSL_SUCCESS)
            status = FRICREG_EINTEGRATOR;
    }
    gsl_odeiv2_step_free(st);
    out->steps = (double)n;
    if (status == FRICREG_OK && isfinite(y[4]))
        out->dissipation = (y[4] - E_start) / DISK_CYCLES_PER_TURN;
    return status;
}

/* ---- The hold ------------------------------------------------------------------------------ */

static int hold_rhs(double t, const double y[], double dy[], void *vp)
{
    const struct law_params *p = vp;
    double feq[2] = {-p->load[0], -p->load[1]}, f[2];
    (void)t;
    if (fricreg_disk_eval(p->law, y + 2, feq, p->mun, p->eps, f) != FRICREG_OK)
        return GSL_EBADFUNC;
    dy[0] = y[2];
    dy[1] = y[3];
    dy[2] = (p->load[0] + f[0]) / HOLD_MASS;
    dy[3] = (p->load[1] + f[1]) / HOLD_MASS;
    return GSL_SUCCESS;
}

int hold_rk4_run(int law, double dt, long steps, double *creep, double *largest_speed)
{
    double theta = atan(0.8 * HOLD_MU), along = HOLD_MASS * HOLD_GRAV * sin(theta);
    struct law_params p = {law,
                           20.0 * dt,
                           {along * cos(HOLD_PHI), along * sin(HOLD_PHI)},
                           HOLD_MU * HOLD_MASS * HOLD_GRAV * cos(theta)};
    gsl_odeiv2_system sys = {hold_rhs, NULL, 4, &p};
    gsl_odeiv2_step *st = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk4, 4);
    *creep = *largest_speed = NAN;
    if (!st)
        return FRICREG_ENOMEM;
    double y[4] = {0.125, -0.375, 0.0, 0.0}, dydt[4], y0[4], d0[4], vmax = 0.0;
    int status = hold_rhs(0.0, y, dydt, &p) == GSL_SUCCESS ? FRICREG_OK : FRICREG_EINVAL;
    for (long k = 0; k < steps && status == FRICREG_OK; k++) {
        if (step(st, &sys, (double)k * dt, dt, y, dydt, y0, d0) != GSL_SUCCESS)
            status = FRICREG_EINTEGRATOR;
        vmax = fmax(vmax, hypot(y[2], y[3]));
    }
    gsl_odeiv2_step_free(st);
    if (status == FRICREG_OK) {
        *creep = hypot(y[0] - 0.125, y[1] + 0.375) / ((double)steps * dt);
        *largest_speed = vmax;
    }
    return status;
}
