/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stress.h — the numerical stress suite (docs/reliability.md): shared settings, checks and the
 * energy bookkeeping of the three reference systems. Each group is one file and one function;
 * stress_main.c runs them. Only the public API is used, as a user would. */
#ifndef FRICREG_STRESS_H
#define FRICREG_STRESS_H

#include <stddef.h>
#include <stdint.h>

#include "fricreg_sim.h"

#define STRESS_PI 3.14159265358979323846 /* C99 has no M_PI */

/* Run lengths of one mode: the short default (ctest) or --full (bench/stress.sh). */
struct stress_mode {
    int full;
    long long long_steps;   /* fixed RK4 steps per system in the long runs */
    int exact_cases;        /* random exact-solver cases */
    int exact_max_cycles;   /* their longest run, in forcing cycles */
    int exact_vs_sim_cases; /* of them, also run by the RK4 driver at a small step */
    double chain_max_n;     /* largest chain of the extreme group */
    int cond_samples;       /* random W per (m, condition number) */
    int qp_cases;           /* random coupled evaluations with mixed near-stick sets */
    uint64_t seed;
    double disk_chain_m; /* the largest stuck chain of the 2-D context (from 10^4 up, x10) */
};

/* Counts the failed checks of a group; printf-style message on failure. */
struct stress_tally {
    int checks, failures;
};

void stress_check(struct stress_tally *tally, int ok, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* A seeded generator (splitmix64 of tests/support/random.h, the state the caller's), so that
 * every platform draws the same cases. */
double stress_uniform(uint64_t *state, double lo, double hi);
double stress_log_uniform(uint64_t *state, double lo, double hi);

/* ---- energy of the reference systems, watched after every step ---------------------------
 * E is the mechanical energy, P_in the power of the forcing (or of the belt), and P_D the
 * rate of dissipation, -sum_i w_i zdot_i f_i, so that dE/dt = P_in - P_D exactly:
 *   oscillator  E = (x'^2 + x^2)/2,          P_in = a sin(wt) x'
 *   chain       E = sum u_i'^2/(2n) + (n/2) (sum_i (u_i - u_i+1)^2 + u_n^2),
 *               P_in = a sin(wt) u_1'          (masses 1/n, springs n, fricreg_sim.h)
 *   two blocks  E = (x1'^2 + x2'^2 + x1^2 + k x2^2)/2, P_in = f_1 u'(t) (the belt's work)
 * The watch integrates P_in and P_D by the trapezoid rule over the accepted steps. */
struct stress_energy {
    int system;
    double a, omega, k, belt_amp, belt_omega; /* the system's parameters */
    double mun[2]; /* friction bounds: mun (oscillator), 1 (chain, every block), mu1, mu2 */
    double E0, E, work_in, dissipated; /* start, now, integrals so far */
    double t_prev, p_in_prev, p_d_prev;
    double worst_excess;  /* max over steps of E - E0 - work_in (energy put in by the scheme) */
    double worst_balance; /* max over steps of |E - E0 - work_in + dissipated| */
    double worst_force;   /* max over steps and contacts of |f_i| / mun_i, bound 1 */
    double abs_work;      /* integral of |P_in|, for the energy scale */
    long long observed;   /* observer calls */
    int nonfinite;        /* a non-finite state or force was seen */
    /* stick creep (unforced oscillator): after t_settle, x must stay exactly x_settle */
    double t_settle, x_settle, worst_creep;
    int settled;
};

/* Set up the watch for `sim` (its parameters are read back) and install it as the observer. */
int stress_energy_watch(struct stress_energy *w, fricreg_sim *sim, int system);

/* The energy scale of a watched run: start, work put in (absolute) and dissipated. */
double stress_energy_scale(const struct stress_energy *w);

/* The groups; each prints its table and returns its number of failed checks. */
int stress_long_runs(const struct stress_mode *mode);
int stress_extreme(const struct stress_mode *mode);
int stress_exact_random(const struct stress_mode *mode);
int stress_conditioning(const struct stress_mode *mode);
int stress_disk_chain(const struct stress_mode *mode);

#endif /* FRICREG_STRESS_H */
