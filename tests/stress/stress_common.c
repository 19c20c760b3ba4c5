/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stress_common.c — checks, the seeded generator and the energy watch of the stress suite. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "stress.h"
#include "random.h"

void stress_check(struct stress_tally *tally, int ok, const char *fmt, ...)
{
    tally->checks++;
    if (ok)
        return;
    tally->failures++;
    va_list ap;
    va_start(ap, fmt);
    printf("FAIL: ");
    vprintf(fmt, ap);
    printf("\n");
    va_end(ap);
}

double stress_uniform(uint64_t *state, double lo, double hi)
{
    return splitmix64_uniform(state, lo, hi); /* the tests' generator, tests/support/random.h */
}

double stress_log_uniform(uint64_t *state, double lo, double hi)
{
    return exp(stress_uniform(state, log(lo), log(hi)));
}

/* ---- energy of each system (formulas in stress.h) ----------------------------------------- */

static double energy(const struct stress_energy *w, size_t ndof, const double x[], const double v[])
{
    switch (w->system) {
    case FRICREG_SYSTEM_OSCILLATOR: return 0.5 * (v[0] * v[0] + x[0] * x[0]);
    case FRICREG_SYSTEM_CHAIN: {
        double n = (double)ndof, kinetic = 0.0, springs = x[ndof - 1] * x[ndof - 1];
        for (size_t i = 0; i < ndof; i++)
            kinetic += v[i] * v[i];
        for (size_t i = 0; i + 1 < ndof; i++)
            springs += (x[i] - x[i + 1]) * (x[i] - x[i + 1]);
        return 0.5 * kinetic / n + 0.5 * n * springs;
    }
    default: return 0.5 * (v[0] * v[0] + v[1] * v[1] + x[0] * x[0] + w->k * x[1] * x[1]);
    }
}

static double belt_velocity(const struct stress_energy *w, double t)
{
    return w->belt_amp * w->belt_omega * cos(w->belt_omega * t);
}

static double power_in(const struct stress_energy *w, double t, const double v[], const double f[])
{
    if (w->system == FRICREG_SYSTEM_TWOBLOCK)
        return f[0] * belt_velocity(w, t);
    return w->a * sin(w->omega * t) * v[0];
}

/* -sum_i w_i zdot_i f_i with the system's contact velocities and weights. */
static double power_dissipated(const struct stress_energy *w, double t, size_t ndof,
                               const double v[], const double f[])
{
    if (w->system == FRICREG_SYSTEM_TWOBLOCK)
        return -((v[0] - belt_velocity(w, t)) * f[0] + (v[1] - v[0]) * f[1]);
    double sum = 0.0;
    for (size_t i = 0; i < ndof; i++)
        sum += v[i] * f[i];
    return -sum / (double)ndof;
}

static int all_finite(size_t n, const double a[])
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(a[i]))
            return 0;
    return 1;
}

/* |f_i| / mun_i, the law's bound being 1 (a zero bound must give a zero force). */
static void watch_forces(struct stress_energy *w, size_t m, const double f[])
{
    for (size_t i = 0; i < m; i++) {
        double mun = w->mun[i < 1 ? 0 : 1];
        double ratio = mun > 0.0 ? fabs(f[i]) / mun : (f[i] != 0.0 ? INFINITY : 0.0);
        w->worst_force = fmax(w->worst_force, ratio);
    }
}

static void watch_creep(struct stress_energy *w, double t, double x)
{
    if (t < w->t_settle)
        return;
    if (!w->settled) {
        w->settled = 1;
        w->x_settle = x;
        return;
    }
    w->worst_creep = fmax(w->worst_creep, fabs(x - w->x_settle));
}

static int observe(void *user, double t, size_t ndof, const double x[], const double v[], size_t m,
                   const double f[], const double f_eq[])
{
    (void)f_eq;
    struct stress_energy *w = user;
    if (!all_finite(ndof, x) || !all_finite(ndof, v) || !all_finite(m, f)) {
        w->nonfinite = 1;
        return 1;
    }
    double E = energy(w, ndof, x, v);
    double p_in = power_in(w, t, v, f), p_d = power_dissipated(w, t, ndof, v, f);
    if (w->observed == 0) {
        w->E0 = E;
    } else {
        double h = t - w->t_prev;
        w->work_in += 0.5 * h * (p_in + w->p_in_prev);
        w->abs_work += 0.5 * h * (fabs(p_in) + fabs(w->p_in_prev));
        w->dissipated += 0.5 * h * (p_d + w->p_d_prev);
    }
    w->E = E;
    w->t_prev = t, w->p_in_prev = p_in, w->p_d_prev = p_d;
    w->worst_excess = fmax(w->worst_excess, E - w->E0 - w->work_in);
    w->worst_balance = fmax(w->worst_balance, fabs(E - w->E0 - w->work_in + w->dissipated));
    watch_forces(w, m, f);
    if (w->system == FRICREG_SYSTEM_OSCILLATOR)
        watch_creep(w, t, x[0]);
    w->observed++;
    return 0;
}

static double param(const fricreg_sim *sim, int which)
{
    double value = NAN;
    fricreg_sim_get_param(sim, which, &value);
    return value;
}

int stress_energy_watch(struct stress_energy *w, fricreg_sim *sim, int system)
{
    memset(w, 0, sizeof *w);
    w->system = system;
    w->worst_excess = -INFINITY;
    w->t_settle = INFINITY;
    if (system == FRICREG_SYSTEM_TWOBLOCK) {
        w->k = param(sim, FRICREG_PARAM_K);
        w->belt_amp = param(sim, FRICREG_PARAM_BELT_AMP);
        w->belt_omega = param(sim, FRICREG_PARAM_BELT_OMEGA);
        w->mun[0] = param(sim, FRICREG_PARAM_MU1);
        w->mun[1] = param(sim, FRICREG_PARAM_MU2);
    } else {
        w->a = param(sim, FRICREG_PARAM_A);
        w->omega = param(sim, FRICREG_PARAM_OMEGA);
        w->mun[0] = w->mun[1] = system == FRICREG_SYSTEM_OSCILLATOR ? param(sim, FRICREG_PARAM_MUN)
                                                                    : 1.0;
    }
    return fricreg_sim_set_observer(sim, observe, w);
}

double stress_energy_scale(const struct stress_energy *w)
{
    return fmax(w->E0, fmax(w->E, 0.0)) + w->abs_work + fabs(w->dissipated);
}
