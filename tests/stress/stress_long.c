/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stress_long.c — long runs: fixed RK4 steps by the million on each reference system, with
 * the energy watched after every step (stress.h). What must hold over the whole run:
 *   - the energy never exceeds its start plus the work put in, beyond the trapezoid error of
 *     the watch's own integrals (the scheme creates no energy);
 *   - E - E0 - W_in + D stays at that error too (the balance closes);
 *   - |f_i| <= mun_i at every step;
 *   - the dissipation per forcing cycle settles: the spread of the last cycles' D_k;
 *   - the unforced oscillator, once stuck, keeps its position exactly (== , no creep). */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "stress.h"

#define DT 0.01
#define LAST_CYCLES 10
/* The watch integrates W_in and D by the trapezoid rule over steps of 0.01, whose kinks (law
 * (4)'s band edges) leave errors of ~1e-5 of the energy scale (measured 1.6e-5): the energy
 * may not exceed E0 + W_in by more, and E - E0 - W_in + D must close to it. */
#define WATCH_TOL 1e-4

struct long_case {
    const char *name;
    int system;
    double a, omega;   /* oscillator only; NAN keeps the paper's */
    double spread_max; /* the settled D_k may vary by this much, relative */
};

static const struct long_case cases[] = {
    {"oscillator, unforced", FRICREG_SYSTEM_OSCILLATOR, NAN, NAN, 0.0},
    {"oscillator, a=2.385 w=0.61", FRICREG_SYSTEM_OSCILLATOR, 2.385, 0.61, 1e-9},
    {"chain n=32 (paper)", FRICREG_SYSTEM_CHAIN, NAN, NAN, 1e-9},
    {"two blocks (paper)", FRICREG_SYSTEM_TWOBLOCK, NAN, NAN, 1e-9},
};

/* (max - min) / |mean| of the last cycles' D_k; the absolute spread when their mean is 0. */
static double settled_spread(const double D[], size_t n)
{
    size_t first = n > LAST_CYCLES ? n - LAST_CYCLES : 0;
    double lo = INFINITY, hi = -INFINITY, sum = 0.0;
    for (size_t k = first; k < n; k++) {
        lo = fmin(lo, D[k]), hi = fmax(hi, D[k]);
        sum += D[k];
    }
    double mean = sum / (double)(n - first);
    return mean != 0.0 ? (hi - lo) / fabs(mean) : hi - lo;
}

struct long_result {
    int status;
    int64_t steps, cycles;
    double d_last, spread, excess, balance, force, creep, d_gap;
};

static struct long_result run_case(const struct long_case *c, long long steps)
{
    struct long_result r = {0};
    fricreg_sim *sim = NULL;
    struct stress_energy w;
    r.status = fricreg_sim_create(c->system, &sim);
    if (r.status != FRICREG_OK)
        return r;
    if (!isnan(c->a)) {
        fricreg_sim_set_param(sim, FRICREG_PARAM_A, c->a);
        fricreg_sim_set_param(sim, FRICREG_PARAM_OMEGA, c->omega);
    }
    stress_energy_watch(&w, sim, c->system);
    double period = 0.0;
    fricreg_sim_get_value(sim, FRICREG_VALUE_PERIOD, &period);
    if (c->system == FRICREG_SYSTEM_OSCILLATOR && isnan(c->a))
        w.t_settle = 10.0 * period; /* stuck after 2 cycles: the paper's Fig. 2 */
    r.status = fricreg_sim_run(sim, (double)steps * DT);
    fricreg_sim_get_stat(sim, FRICREG_SIM_STAT_STEPS, &r.steps);
    fricreg_sim_get_stat(sim, FRICREG_SIM_STAT_CYCLES, &r.cycles);
    double *D = malloc((size_t)(r.cycles > 0 ? r.cycles : 1) * sizeof *D);
    double total = 0.0;
    if (D != NULL && r.cycles > 0 &&
        fricreg_sim_get_dissipation(sim, (size_t)r.cycles, D) == FRICREG_OK) {
        r.d_last = D[r.cycles - 1];
        r.spread = settled_spread(D, (size_t)r.cycles);
    }
    fricreg_sim_get_value(sim, FRICREG_VALUE_DISSIPATION, &total);
    double scale = stress_energy_scale(&w);
    r.excess = w.worst_excess / scale;
    r.balance = w.worst_balance / scale;
    r.force = w.worst_force;
    r.creep = w.settled ? w.worst_creep : NAN;
    r.d_gap = fabs(total - w.dissipated) / scale; /* the driver's D against the watch's */
    if (w.nonfinite)
        r.status = FRICREG_EDIVERGED;
    free(D);
    fricreg_sim_free(sim);
    return r;
}

int stress_long_runs(const struct stress_mode *mode)
{
    struct stress_tally tally = {0, 0};
    double worst_excess = -INFINITY, worst_balance = 0.0;
    printf("== long runs: fixed RK4, dt = %g, %lld steps per system, energy checked every step\n",
           DT, mode->long_steps);
    printf("%-28s %10s %7s %12s %10s %10s %10s %10s %9s %6s\n", "system", "steps", "cycles",
           "D last cyc", "D spread", "excess/E", "balance/E", "D gap/E", "max|f|/mun", "creep");
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const struct long_case *c = &cases[i];
        struct long_result r = run_case(c, mode->long_steps);
        printf("%-28s %10lld %7lld %12.6g %10.2e %10.2e %10.2e %10.2e %9.6f %6.2g\n", c->name,
               (long long)r.steps, (long long)r.cycles, r.d_last, r.spread, r.excess, r.balance,
               r.d_gap, r.force, r.creep);
        worst_excess = fmax(worst_excess, r.excess);
        worst_balance = fmax(worst_balance, r.balance);
        stress_check(&tally, r.status == FRICREG_OK, "%s: status %d", c->name, r.status);
        stress_check(&tally, r.steps >= mode->long_steps, "%s: %lld steps", c->name,
                     (long long)r.steps);
        stress_check(&tally, r.spread <= c->spread_max, "%s: D_k spread %g over the last cycles",
                     c->name, r.spread);
        stress_check(&tally, r.excess <= WATCH_TOL, "%s: energy above E0 + W_in by %g", c->name,
                     r.excess);
        stress_check(&tally, r.balance <= WATCH_TOL && r.d_gap <= WATCH_TOL,
                     "%s: balance gap %g, driver's D against the watch's %g", c->name, r.balance,
                     r.d_gap);
        stress_check(&tally, r.force <= 1.0 + 4 * DBL_EPSILON, "%s: |f|/mun = %.17g", c->name,
                     r.force);
        if (c->system == FRICREG_SYSTEM_OSCILLATOR && isnan(c->a))
            stress_check(&tally, r.creep == 0.0, "%s: stick position moved by %g", c->name,
                         r.creep);
    }
    printf("worst: energy excess %.3g, balance gap %.3g of the energy scale\n\n", worst_excess,
           worst_balance);
    return tally.failures;
}
