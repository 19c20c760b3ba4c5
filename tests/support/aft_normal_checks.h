/* SPDX-License-Identifier: GPL-3.0-or-later */
/* aft_normal_checks.h — what the two lift-off AFT suites (test_aft_normal.c: sampled,
 * test_aft_normal_exact.c: exact) check alike, written once: the time-domain element's
 * coefficients, the same three cases against them, and the Jacobian against central
 * differences. Either path is passed as its function: both have the same arguments. */
#ifndef FRICREG_TESTS_AFT_NORMAL_CHECKS_H
#define FRICREG_TESTS_AFT_NORMAL_CHECKS_H

#include <stddef.h>

#include "fricreg_aft.h"

/* fricreg_aft_jenkins_normal_sampled or fricreg_aft_jenkins_normal_exact. */
typedef int (*aft_normal_fn)(fricreg_aft *aft, double kt, double mu, double n0, double kn, size_t n,
                             const double u[], const double g[], double f[], double nf[],
                             double jac[]);

/* u(θ) from its 2H + 1 coefficients (fricreg_aft.h's layout). */
double aft_normal_at(int harmonics, const double *c, double th);

/* The time-domain element (fricreg_jenkins_trial_normal and commit) marched three periods
 * over ns samples from a relaxed slider: the last period's f and N through a plain DFT (no
 * FFT) into f[2H + 1], nf[2H + 1]; u and g hold 2H + 1 coefficients (fricreg_aft.h's layout). */
void aft_normal_time_domain(int harmonics, size_t ns, double kt, double mu, double n0, double kn,
                            const double *u, const double *g, double *f, double *nf);

/* The path against the time-domain element at ns samples, in its three cases: opening where
 * sin θ < -2/3, a bound moving between 1.2 and 2.8 without opening, and stuck (kt (max u -
 * min u) = 0.3 below 2 mu N_min = 0.96, centred); f within tol of mu (|N0| + 4 kn) and N
 * within tol of |N0| + 4 kn. a has harmonics H = 3. */
void aft_normal_check_time_domain_cases(fricreg_aft *a, aft_normal_fn path, size_t ns, double tol);

/* Central differences (step 1e-6) of f and N in u and g against the path's Jacobian, within
 * 1e-6 of max(kt, kn); u and g hold 2H + 1 coefficients of a's H. */
void aft_normal_check_jacobian(fricreg_aft *a, aft_normal_fn path, double kt, double mu, double n0,
                               double kn, const double *u, const double *g);

/* The path's refusals (a of harmonics H = 3, name the function's name without "fricreg_aft_"):
 * NULL arrays (ENULL), a wrong n (ESIZE), kt <= 0, mu < 0 or kn < 0 (EINVAL, the message
 * naming mu and kn), a NaN n0, an infinite g entry and an overflowing normal force
 * (ENONFINITE), each leaving f and nf as they were and the code recorded in a. */
void aft_normal_check_bad_input(fricreg_aft *a, aft_normal_fn path, const char *name);

/* The stuck slider nearest the centre: u = cos θ, g = cos θ / 2, kt = mu = kn = 1, so the stuck
 * sliders are [lo, hi] = [0.5 − n0, n0 − 1.5] (n0 >= 1) and the centre 0 lies above hi for
 * n0 < 1.5: the slider at hi, f = cos θ + 1.5 − n0, continuous into the centred stick
 * (f = cos θ) at n0 = 1.5 (the march alone gave lo, f0 = n0 − 0.5: a jump of 1 there). f0 and
 * f's first harmonic to tol at n0 from 1 to 1.7 and 1e-9 either side of 1.5; the Jacobian
 * at n0 = 1.2 against differences. */
void aft_normal_check_nearest_stuck(fricreg_aft *a, aft_normal_fn path, double tol);

#endif
