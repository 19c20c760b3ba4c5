/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_oscillator.c — the 2-D oscillator driven along a rotating direction (problems.h), the
 * problem on which the 2-D laws were compared (docs/laws2d.md): the sliding direction turns
 * continuously and the contact sticks part of each cycle. The dissipated energy is a fifth
 * state component, E' = -f . x', so that RK4 integrates it with the state's own weights; D is
 * its change over exactly one turn, the window's edges interpolated inside their steps. */
#include <math.h>
#include <string.h>

#include "fricreg_disk.h"
#include "prob_internal.h"

#define PI 3.14159265358979323846

struct prob_disk prob_disk_defaults(void)
{
    return (struct prob_disk){.law = FRICREG_DISK_QUINN,
                              .a = 2.0,
                              .omega = 0.5,
                              .cycles_per_turn = 7,
                              .turns_transient = 3,
                              .dt = 0.01,
                              .eps = 0.02};
}

struct disk_rhs {
    const struct prob_disk *p;
    int status; /* the law's status when it failed */
};

double prob_disk_turn(const struct prob_disk *p)
{
    return 2.0 * PI * p->cycles_per_turn / p->omega;
}

void prob_disk_forcing(const struct prob_disk *p, double t, double F[2])
{
    double s = p->a * sin(p->omega * t), phi = p->omega / p->cycles_per_turn * t;
    F[0] = s * cos(phi);
    F[1] = s * sin(phi);
}

/* The friction force at state y = (x1, x2, v1, v2) and time t: law (4) in 2-D with mu N = 1
 * and f_eq = x - F(t), the force that makes the acceleration zero. */
static int friction(const struct prob_disk *p, double t, const double y[], double F[2], double f[2])
{
    prob_disk_forcing(p, t, F);
    double feq[2] = {y[0] - F[0], y[1] - F[1]};
    return fricreg_disk_eval(p->law, y + 2, feq, 1.0, p->eps, f);
}

static int rhs(double t, const double y[], double dy[], void *params)
{
    struct disk_rhs *r = params;
    double F[2], f[2];
    int status = friction(r->p, t, y, F, f);
    if (status != FRICREG_OK) {
        r->status = status;
        return GSL_EBADFUNC;
    }
    dy[0] = y[2];
    dy[1] = y[3];
    dy[2] = -y[0] + f[0] + F[0];
    dy[3] = -y[1] + f[1] + F[1];
    dy[4] = -(f[0] * y[2] + f[1] * y[3]);
    return GSL_SUCCESS;
}

static int valid(const struct prob_disk *p)
{
    return p->a > 0.0 && p->omega > 0.0 && p->cycles_per_turn >= 1 && p->turns_transient >= 0 &&
           p->dt > 0.0 && p->eps > 0.0 && isfinite(p->a) && isfinite(p->omega) && isfinite(p->dt) &&
           isfinite(p->eps);
}

static int observe_step(const struct prob_disk *p, double t, const double y[],
                        prob_observer observe, void *user)
{
    double F[2], row[PROB_DISK_COLUMNS] = {y[0], y[1], y[2], y[3], 0.0, 0.0};
    int status = friction(p, t, y, F, row + 4);
    if (status != FRICREG_OK)
        return status;
    return observe(user, t, row, PROB_DISK_COLUMNS) != 0 ? FRICREG_ENOMEM : FRICREG_OK;
}

/* The dissipated energy at time `edge` inside the step from (t0, y0) to (t0 + h, y1): the
 * Hermite interpolant of E with its rates -f . v at both ends (fourth order, as the step), so
 * that the measured window is exactly one turn whatever dt. */
static int energy_at(struct disk_rhs *params, double edge, double t0, double h, const double y0[],
                     const double y1[], double *E)
{
    double d0[5], d1[5];
    if (rhs(t0, y0, d0, params) != GSL_SUCCESS || rhs(t0 + h, y1, d1, params) != GSL_SUCCESS)
        return params->status;
    *E = prob_hermite(y0[4], d0[4], y1[4], d1[4], h, (edge - t0) / h);
    return FRICREG_OK;
}

int prob_disk_run(const struct prob_disk *p, prob_observer observe, void *user,
                  struct prob_disk_result *r)
{
    if (!valid(p))
        return FRICREG_EINVAL;
    const double turn = prob_disk_turn(p), h = 2.0 * p->dt;
    const double t_from = p->turns_transient * turn, t_to = t_from + turn;
    const double n = ceil(t_to / h);
    if (turn < h || n > 1e10)
        return FRICREG_EINVAL;
    struct disk_rhs params = {p, FRICREG_OK};
    struct prob_rk4 rk;
    int status = prob_rk4_init(&rk, rhs, 5, &params, p->dt);
    if (status != FRICREG_OK)
        return status;
    double y[5] = {0.0, 0.0, 0.0, 0.0, 0.0}, y0[5], E_from = 0.0, E_to = 0.0;
    double in_band = 0.0, measured = 0.0, k = 0.0;
    for (; status == FRICREG_OK && k < n; k += 1.0) {
        double t0 = k * h, t1 = (k + 1.0) * h;
        memcpy(y0, y, sizeof y);
        status = prob_rk4_advance(&rk, t0, y, &params.status);
        if (status == FRICREG_OK && t0 <= t_from && t_from < t1)
            status = energy_at(&params, t_from, t0, h, y0, y, &E_from);
        if (status == FRICREG_OK && t0 < t_to && t_to <= t1)
            status = energy_at(&params, t_to, t0, h, y0, y, &E_to);
        if (status != FRICREG_OK || t1 <= t_from)
            continue;
        in_band += hypot(y[2], y[3]) < p->eps;
        measured += 1.0;
        if (observe != NULL)
            status = observe_step(p, t1, y, observe, user);
    }
    prob_rk4_free(&rk);
    if (status != FRICREG_OK)
        return status;
    *r = (struct prob_disk_result){(E_to - E_from) / p->cycles_per_turn, in_band / measured,
                                   2.0 * k, k * h};
    return FRICREG_OK;
}
