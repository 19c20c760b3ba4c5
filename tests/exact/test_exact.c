/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_exact.c — the semi-analytical ("exact") solution of the oscillator, Eq. (5), under
 * classical Coulomb friction (1) with force balance at rest (2) (fricreg_exact.h).
 *
 * x'' + x = f + a sin(omega t), f_eq = x - a sin(omega t). Expected numbers come from closed
 * forms derived in the comments (the unforced half-cycles, the resonant secular solution, the
 * first breakaway), from the energy balance of (5) evaluated by GSL quadrature on the
 * closed-form velocity, from the switching conditions themselves, and from brute-force RK4 runs
 * of fricreg_sim (fricreg_sim.h) at tiny steps. */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include "fricreg_exact.h"
#include "fricreg_sim.h"
#include "quiet_check.h"

#define PI 3.14159265358979323846

/* ---------------------------------------------------------------- helpers */

static fricreg_exact *solve(double a, double omega, double mun, double x0, double v0, double t_end)
{
    fricreg_exact *ex = NULL;
    int status = fricreg_exact_solve(a, omega, mun, x0, v0, t_end, &ex);
    ck_assert_msg(status == FRICREG_OK && ex != NULL,
                  "solve(a=%g, omega=%g, mun=%g, x0=%g, v0=%g, t_end=%g): status %d", a, omega, mun,
                  x0, v0, t_end, status);
    return ex;
}

static void state(const fricreg_exact *ex, double t, double *x, double *v)
{
    int status = fricreg_exact_state(ex, t, x, v);
    QUIET_ASSERT(status == FRICREG_OK, "state at t = %.17g: status %d", t, status);
}

static double position(const fricreg_exact *ex, double t)
{
    double x, v;
    state(ex, t, &x, &v);
    return x;
}

static double velocity(const fricreg_exact *ex, double t)
{
    double x, v;
    state(ex, t, &x, &v);
    return v;
}

struct switches {
    size_t n;
    double *t;
    int *stick;
};

static struct switches get_switches(const fricreg_exact *ex)
{
    struct switches sw = {fricreg_exact_nswitches(ex), NULL, NULL};
    sw.t = malloc((sw.n + 1) * sizeof *sw.t);
    sw.stick = malloc((sw.n + 1) * sizeof *sw.stick);
    ck_assert(sw.t != NULL && sw.stick != NULL);
    ck_assert_int_eq(fricreg_exact_switches(ex, sw.n, sw.t, sw.stick), FRICREG_OK);
    return sw;
}

static void free_switches(struct switches *sw)
{
    free(sw->t);
    free(sw->stick);
}

/* D of every whole cycle; *ncycles receives their number. */
static double *dissipation(const fricreg_exact *ex, size_t *ncycles)
{
    *ncycles = fricreg_exact_ncycles(ex);
    double *D = malloc((*ncycles + 1) * sizeof *D);
    ck_assert(D != NULL);
    ck_assert_int_eq(fricreg_exact_dissipation(ex, *ncycles, D), FRICREG_OK);
    return D;
}

/* Switches strictly inside (ta, tb). */
static size_t switches_within(const struct switches *sw, double ta, double tb)
{
    size_t count = 0;
    for (size_t k = 0; k < sw->n; k++)
        count += sw->t[k] > ta && sw->t[k] < tb;
    return count;
}

/* ------------------------------------------------- energy balance by quadrature */

struct forcing {
    const fricreg_exact *ex;
    double a, omega;
};

/* Power of the forcing, a sin(omega t) x'(t), with x' from the closed form. */
static double forcing_power(double t, void *params)
{
    const struct forcing *fo = params;
    return fo->a * sin(fo->omega * t) * velocity(fo->ex, t);
}

/* W = ∫ a sin(omega t) x' dt over [ta, tb] by gsl_integration_qag (Gauss-Kronrod 21, relative
 * tolerance tol; absolute tol/100 for the slivers between a switch and a cycle boundary, whose
 * integral is ~0). With sw, split at every switching time inside so that each piece is one
 * closed form; with sw NULL, in one go, qag bisecting towards the kinks of x' itself. */
static double forcing_work(const struct forcing *fo, const struct switches *sw, double ta,
                           double tb, double tol, gsl_integration_workspace *ws)
{
    gsl_function F = {forcing_power, (void *)fo};
    double total = 0.0, lo = ta;
    size_t nsw = sw != NULL ? sw->n : 0;
    for (size_t k = 0; k <= nsw && lo < tb; k++) {
        double hi = k < nsw ? fmin(sw->t[k], tb) : tb;
        if (hi <= lo)
            continue;
        double piece, abserr;
        int status = gsl_integration_qag(&F, lo, hi, 1e-2 * tol, tol, 1000, GSL_INTEG_GAUSS21, ws,
                                         &piece, &abserr);
        ck_assert_msg(status == GSL_SUCCESS, "qag on [%.17g, %.17g], tol %g: %s", lo, hi, tol,
                      gsl_strerror(status));
        total += piece;
        lo = hi;
    }
    return total;
}

static double energy(const fricreg_exact *ex, double t)
{
    double x, v;
    state(ex, t, &x, &v);
    return 0.5 * (x * x + v * v);
}

/* Largest relative gap over all whole cycles between the solver's D_k and the energy balance
 * of (5): d/dt (x^2 + x'^2)/2 = x' (f + a sin(omega t)) and D = -∫ x' f dt give
 * D_k = W_k - (E((k+1)T) - E(kT)). W_k by forcing_work, split at the switches or not. */
static double balance_gap(const fricreg_exact *ex, double a, double omega, int split, double tol)
{
    struct forcing fo = {ex, a, omega};
    struct switches sw = get_switches(ex);
    size_t n;
    double *D = dissipation(ex, &n), T = 2.0 * PI / omega, worst = 0.0;
    gsl_integration_workspace *ws = gsl_integration_workspace_alloc(1000);
    ck_assert(ws != NULL);
    for (size_t k = 0; k < n; k++) {
        double ta = (double)k * T, tb = (double)(k + 1) * T;
        double balance = forcing_work(&fo, split ? &sw : NULL, ta, tb, tol, ws) -
                         (energy(ex, tb) - energy(ex, ta));
        ck_assert_msg(D[k] > 0.0, "cycle %zu: D = %g", k, D[k]);
        worst = fmax(worst, fabs(D[k] - balance) / D[k]);
    }
    gsl_integration_workspace_free(ws);
    free(D);
    free_switches(&sw);
    return worst;
}

/* --------------------------------------------------- 1. the unforced oscillator */

/* Spec "Unforced": from (2.75, 0) with mun = 1 the body slides as x = 1 + 1.75 cos t until
 * x' = 0 at t = pi, where |f_eq| = |x| = 0.75 <= mun: one switch, into a stick at -0.75 for
 * ever. Cycle 1 (omega = 1, T = 2 pi) slides 2.75 - (-0.75) = 3.5, so D = mun 3.5; later cycles
 * slide nothing. Tolerances: a few ulps of the numbers involved. */
START_TEST(test_unforced_paper_case)
{
    fricreg_exact *ex = solve(0.0, 1.0, 1.0, 2.75, 0.0, 20.0);
    struct switches sw = get_switches(ex);
    ck_assert_uint_eq(sw.n, 1);
    ck_assert_double_eq_tol(sw.t[0], PI, 1e-14);
    ck_assert_int_eq(sw.stick[0], 1);
    static const double times[] = {0.0, 0.2385, 1.0, 1.7318, 2.5, 3.1, 3.14};
    for (size_t i = 0; i < sizeof times / sizeof times[0]; i++) {
        double x, v, t = times[i];
        state(ex, t, &x, &v);
        ck_assert_double_eq_tol(x, 1.0 + 1.75 * cos(t), 1e-14);
        ck_assert_double_eq_tol(v, -1.75 * sin(t), 1e-14);
    }
    for (double t = 3.2; t <= 20.0; t += 1.6797) {
        double x, v;
        state(ex, t, &x, &v);
        ck_assert_double_eq_tol(x, -0.75, 1e-14);
        ck_assert_double_eq(v, 0.0);
    }
    ck_assert_double_eq_tol(position(ex, 20.0), -0.75, 1e-14);
    size_t n;
    double *D = dissipation(ex, &n);
    ck_assert_uint_eq(n, 3); /* 20 / (2 pi) = 3.18 */
    ck_assert_double_eq_tol(D[0], 3.5, 1e-14);
    ck_assert_double_eq(D[1], 0.0);
    ck_assert_double_eq(D[2], 0.0);
    double frac;
    ck_assert_int_eq(fricreg_exact_stick_fraction(ex, 0.0, 2.0 * PI, &frac), FRICREG_OK);
    ck_assert_double_eq_tol(frac, 0.5, 1e-14);
    ck_assert_int_eq(fricreg_exact_stick_fraction(ex, 4.0, 20.0, &frac), FRICREG_OK);
    ck_assert_double_eq(frac, 1.0);
    free(D);
    free_switches(&sw);
    fricreg_exact_free(ex);
}
END_TEST

/* Unforced Coulomb motion by hand: from rest at x with |x| > mun the body slides away from the
 * sign of x, about the offset c = sgn(x) mun, for half a natural period (pi), ending at the
 * mirror point 2c - x: the amplitude about the offset drops by 2 mun per half-cycle. It stops
 * for good at the first turning point with |x| <= mun. Worked out for mun = 0.731, x0 = -3.1:
 * -3.1 -> 2(-0.731) + 3.1 = 1.638 -> 2(0.731) - 1.638 = -0.176: two switches (a reversal at pi,
 * a stick at 2 pi), rest at -0.176, D of cycle 1 = 0.731 (4.738 + 1.814) = 4.789512. The loop
 * below applies the same rule to more (mun, x0), chosen with every turning point at least 0.05
 * from +-mun (an end exactly on the bound is test_rest_on_the_friction_bound's subject). */
START_TEST(test_unforced_half_cycles_by_hand)
{
    static const double cases[][2] = {{0.731, -3.1}, {0.2385, 5.17}, {1.37, 9.9}, {0.05, -1.23}};
    const double mun = cases[_i][0], x0 = cases[_i][1];
    double x_hand[64] = {x0};
    size_t half = 0;
    while (fabs(x_hand[half]) > mun) {
        double c = (x_hand[half] > 0.0 ? 1.0 : -1.0) * mun;
        x_hand[half + 1] = 2.0 * c - x_hand[half];
        half++;
        ck_assert(half < 63);
    }
    double slid = 0.0;
    for (size_t k = 0; k < half; k++)
        slid += fabs(x_hand[k + 1] - x_hand[k]);
    if (_i == 0) { /* the worked example above */
        ck_assert_uint_eq(half, 2);
        ck_assert_double_eq_tol(x_hand[2], -0.176, 1e-14);
        ck_assert_double_eq_tol(mun * slid, 4.789512, 1e-13);
    }

    double t_end = (double)(half + 2) * PI + 0.5;
    fricreg_exact *ex = solve(0.0, 1.0, mun, x0, 0.0, t_end);
    struct switches sw = get_switches(ex);
    ck_assert_uint_eq(sw.n, half);
    for (size_t k = 0; k < half; k++) {
        ck_assert_double_eq_tol(sw.t[k], (double)(k + 1) * PI, 1e-13 * (double)(k + 1));
        ck_assert_int_eq(sw.stick[k], k + 1 == half);
        ck_assert_double_eq_tol(position(ex, sw.t[k]), x_hand[k + 1], 1e-13 * fabs(x0));
    }
    ck_assert_double_eq_tol(position(ex, t_end), x_hand[half], 1e-13 * fabs(x0));
    ck_assert_double_eq(velocity(ex, t_end), 0.0);
    size_t n;
    double *D = dissipation(ex, &n), total = 0.0;
    for (size_t k = 0; k < n; k++)
        total += D[k];
    ck_assert_double_eq_tol(total, mun * slid, 1e-13 * mun * slid);
    free(D);
    free_switches(&sw);
    fricreg_exact_free(ex);
}
END_TEST

/* A start with x' != 0 slides in the direction of x' (header). From x0 = 0.3, v0 = 1.7 with
 * mun = 0.5: about c = -0.5, x = c + 0.8 cos t + 1.7 sin t, which stops where tan t = 1.7/0.8,
 * t1 = atan2(1.7, 0.8) = 1.13095, at c + sqrt(0.8^2 + 1.7^2) = 1.37883 > mun; then the rule of
 * test_unforced_half_cycles_by_hand: a reversal, half a period later (t1 + pi) at
 * 2(0.5) - 1.37883 = -0.37883, |x| <= mun: stick. D = mun (1.37883 - 0.3 + 2 (1.37883 - 0.5)). */
START_TEST(test_unforced_initial_velocity)
{
    const double mun = 0.5, c = -0.5, A = 0.3 - c, B = 1.7;
    const double t1 = atan2(B, A), x1 = c + hypot(A, B), x2 = 2.0 * mun - x1;
    fricreg_exact *ex = solve(0.0, 1.0, mun, 0.3, 1.7, 12.0);
    struct switches sw = get_switches(ex);
    ck_assert_uint_eq(sw.n, 2);
    ck_assert_double_eq_tol(sw.t[0], t1, 1e-14);
    ck_assert_double_eq_tol(sw.t[1], t1 + PI, 1e-14);
    ck_assert_int_eq(sw.stick[0], 0);
    ck_assert_int_eq(sw.stick[1], 1);
    ck_assert_double_eq_tol(position(ex, sw.t[0]), x1, 1e-14);
    ck_assert_double_eq_tol(position(ex, 12.0), x2, 1e-14);
    for (double t = 0.05; t < t1; t += 0.1) {
        double x, v;
        state(ex, t, &x, &v);
        ck_assert_double_eq_tol(x, c + A * cos(t) + B * sin(t), 1e-14);
        ck_assert_double_eq_tol(v, -A * sin(t) + B * cos(t), 1e-14);
    }
    size_t n;
    double *D = dissipation(ex, &n);
    ck_assert_uint_eq(n, 1);
    ck_assert_double_eq_tol(D[0], mun * (x1 - 0.3 + 2.0 * (x1 - mun)), 1e-14);
    free(D);
    free_switches(&sw);
    fricreg_exact_free(ex);
}
END_TEST

/* At rest with |f_eq| = mun exactly and no forcing, the force balance (2) gives f = -f_eq: zero
 * acceleration, an equilibrium, so x = x0 for ever and nothing switches. The same point is
 * reached by a slide: from 3 with mun = 1 the body slides about +1 to 2(1) - 3 = -1 at t = pi,
 * on the bound, and stays there (one switch, a stick). Also mun = 0 at the origin (frictionless
 * equilibrium). A solver that alternates zero-length stick and slip phases here never returns
 * (it grows its phase list until memory runs out): hence this TCase's short timeout. */
START_TEST(test_rest_on_the_friction_bound)
{
    static const double cases[][3] = {{1.0, 1.0, 0},
                                      {0.731, -0.731, 0},
                                      {0.0, 0.0, 0},
                                      {1.0, 3.0, 1}};
    const double mun = cases[_i][0], x0 = cases[_i][1];
    const size_t switches = (size_t)cases[_i][2];
    fricreg_exact *ex = NULL;
    int status = fricreg_exact_solve(0.0, 1.0, mun, x0, 0.0, 10.0, &ex);
    ck_assert_msg(status == FRICREG_OK, "mun = %g, x0 = %g: status %d", mun, x0, status);
    ck_assert_uint_eq(fricreg_exact_nswitches(ex), switches);
    double x_rest = switches ? 2.0 * mun - x0 : x0;
    ck_assert_double_eq_tol(position(ex, 10.0), x_rest, 1e-14);
    ck_assert_double_eq(velocity(ex, 10.0), 0.0);
    fricreg_exact_free(ex);
}
END_TEST

/* mun = 0: Eq. (5) is the linear forced oscillator; from rest at the origin
 * x = P (sin(omega t) - omega sin t), P = a/(1 - omega^2), and D = 0. At t = 0, f_eq = 0 =
 * mun, so the start is on the bound, as in the previous test; the sign of a must not matter
 * (a = +-2.385, omega = 0.5). Tolerance: rounding of |x| <= 2 |P| = 6.4 (1e-13). */
START_TEST(test_frictionless_forced)
{
    const double a = _i ? -2.385 : 2.385, omega = 0.5, P = a / (1.0 - omega * omega);
    fricreg_exact *ex = NULL;
    int status = fricreg_exact_solve(a, omega, 0.0, 0.0, 0.0, 30.0, &ex);
    ck_assert_msg(status == FRICREG_OK, "a = %g: status %d", a, status);
    for (double t = 0.0; t <= 30.0; t += 0.7318) {
        double x, v;
        state(ex, t, &x, &v);
        ck_assert_double_eq_tol(x, P * (sin(omega * t) - omega * sin(t)), 1e-13);
        ck_assert_double_eq_tol(v, P * omega * (cos(omega * t) - cos(t)), 1e-13);
    }
    size_t n;
    double *D = dissipation(ex, &n);
    ck_assert_uint_eq(n, 2);
    ck_assert_double_eq(D[0], 0.0);
    ck_assert_double_eq(D[1], 0.0);
    free(D);
    fricreg_exact_free(ex);
}
END_TEST

/* At rest on the bound with the forcing pushing outwards the body slides at once: no stick,
 * and no switch at t = 0 (the header counts phase changes after t = 0). a = 2, omega = 0.5,
 * mun = 1, x0 = -1: f_eq = -1 - 2 sin(t/2). Slip s = +1 about c = -1 with P = 8/3:
 * x = -1 + (8/3) sin(t/2) - (4/3) sin t, x' = (4/3)(cos(t/2) - cos t), first zero at
 * t = 4 pi/3, where x = 2 sqrt(3) - 1 and |f_eq| = sqrt(3) - 1 <= mun: a stick. The mirror
 * image (a = -2, x0 = 1) likewise. */
START_TEST(test_breakaway_at_start)
{
    const double sign = _i ? -1.0 : 1.0;
    fricreg_exact *ex = solve(2.0 * sign, 0.5, 1.0, -1.0 * sign, 0.0, 6.0);
    struct switches sw = get_switches(ex);
    ck_assert_uint_ge(sw.n, 1);
    ck_assert_msg(sw.t[0] > 0.0, "a switch at t = %g (stick %d) before the first stop", sw.t[0],
                  sw.stick[0]);
    ck_assert_double_eq_tol(sw.t[0], 4.0 * PI / 3.0, 1e-14);
    ck_assert_int_eq(sw.stick[0], 1);
    ck_assert_double_eq_tol(position(ex, sw.t[0]), sign * (2.0 * sqrt(3.0) - 1.0), 1e-14);
    for (double t = 0.1; t < 4.0; t += 0.3)
        ck_assert_double_eq_tol(velocity(ex, t), sign * (4.0 / 3.0) * (cos(t / 2.0) - cos(t)),
                                1e-14);
    free_switches(&sw);
    fricreg_exact_free(ex);
}
END_TEST

/* ------------------------------------------------- 2, 3. the energy balance */

/* Spec "Forced" (a = 2, omega = 0.5, mun = 1, from rest at the origin, 50 cycles): every D_k
 * against the energy balance (balance_gap), as a convergence study in the qag tolerance.
 * Integrated in one go per cycle, qag must resolve the kinks of x' at the switches by
 * bisection: the gap follows the tolerance down (measured 1.2e-7, 1.6e-10, 2.0e-11, 8.1e-14 at
 * 1e-6 … 1e-12): asserted below each tolerance, and more than 100-fold smaller at 1e-12 than
 * at 1e-6. Split at the switches, each piece is analytic and Gauss-Kronrod 21 is exact to
 * rounding at once (2.2e-14 at every tolerance): asserted below 1e-12, twelve significant
 * digits of D (the paper's claim) against an independent computation.
 * The balance is independent of how the solver accounts D (mun |dx| summed over the slips),
 * but blind to the switching times (a slightly misplaced switch changes the energy only to
 * second order): test_switching_conditions checks those. */
START_TEST(test_stick_slip_energy_balance)
{
    const double a = 2.0, omega = 0.5, T = 2.0 * PI / omega;
    fricreg_exact *ex = solve(a, omega, 1.0, 0.0, 0.0, 50.0 * T);
    ck_assert_uint_eq(fricreg_exact_ncycles(ex), 50);
    static const double tols[] = {1e-6, 1e-8, 1e-10, 1e-12};
    const size_t ntols = sizeof tols / sizeof tols[0];
    double whole[4];
    for (size_t i = 0; i < ntols; i++) {
        whole[i] = balance_gap(ex, a, omega, 0, tols[i]);
        ck_assert_msg(whole[i] <= tols[i], "unsplit, qag tol %g: relative gap %.3g", tols[i],
                      whole[i]);
        double split = balance_gap(ex, a, omega, 1, tols[i]);
        ck_assert_msg(split < 1e-12, "split, qag tol %g: relative gap %.3g", tols[i], split);
    }
    ck_assert_double_lt(whole[ntols - 1], 1e-12);
    ck_assert_double_gt(whole[0], 100.0 * whole[ntols - 1]);
    fricreg_exact_free(ex);
}
END_TEST

/* The same balance (split, qag at 1e-12) for the no-stick case of the spec (a = 3,
 * omega = 1.5) and at resonance, where the solver uses the secular form -(a/2) t cos t:
 * a = 1.2 and 2 from rest at the origin, a = 2 from -2.385 (test_resonance_amplitude_growth).
 * 40 cycles each. Measured gaps 2.5e-14, 5.5e-14, 9.0e-15, 1.0e-14; asserted below 1e-12. */
START_TEST(test_energy_balance_other_regimes)
{
    static const double cases[][4] = {{3.0, 1.5, 1.0, 0.0},
                                      {1.2, 1.0, 1.0, 0.0},
                                      {2.0, 1.0, 1.0, 0.0},
                                      {2.0, 1.0, 1.0, -2.385}};
    const double a = cases[_i][0], omega = cases[_i][1], mun = cases[_i][2], x0 = cases[_i][3];
    fricreg_exact *ex = solve(a, omega, mun, x0, 0.0, 40.0 * 2.0 * PI / omega);
    ck_assert_uint_eq(fricreg_exact_ncycles(ex), 40);
    double gap = balance_gap(ex, a, omega, 1, 1e-12);
    ck_assert_msg(gap < 1e-12, "a = %g, omega = %g, x0 = %g: relative gap %.3g", a, omega, x0, gap);
    fricreg_exact_free(ex);
}
END_TEST

/* Resonance (omega = 1), closed form. On a slip of direction s starting at rest at t0 = k pi,
 * x = -s mun - (a/2) t cos t + A cos(t - t0) + B sin(t - t0); x'(t0) = 0 gives
 * B = (a/2) cos(k pi), and then x'((k + 1) pi) = 0 for any A: every slip lasts exactly pi, and
 * x((k+1) pi) = -2 s mun - x(k pi) + (a pi/2)(-1)^k. Starting from rest at x0 = -2.385 < -mun
 * (s = +1 first) the forcing is in phase with the velocity on every half-cycle, and
 * |x(k pi)| = 2.385 + k (a pi/2 - 2 mun): the amplitude grows by pi - 2 per half-cycle for
 * a = 2 > 4 mun/pi (Den Hartog's bound), without a stop. D of cycle c slides
 * |x_2c| + 2|x_2c+1| + |x_2c+2|. Tolerances: rounding of numbers up to 25 (1e-13 relative). */
START_TEST(test_resonance_amplitude_growth)
{
    const double a = 2.0, mun = 1.0, X0 = 2.385, t_end = 10.0 * 2.0 * PI + 1.0;
    fricreg_exact *ex = solve(a, 1.0, mun, -X0, 0.0, t_end);
    struct switches sw = get_switches(ex);
    ck_assert_uint_eq(sw.n, 20);
    double amp[21];
    for (size_t k = 0; k <= 20; k++)
        amp[k] = X0 + (double)k * (a * PI / 2.0 - 2.0 * mun);
    for (size_t k = 1; k <= 20; k++) {
        ck_assert_double_eq_tol(sw.t[k - 1], (double)k * PI, 1e-13 * (double)k * PI);
        ck_assert_int_eq(sw.stick[k - 1], 0);
        double x_expected = (k % 2 ? 1.0 : -1.0) * amp[k];
        ck_assert_double_eq_tol(position(ex, sw.t[k - 1]), x_expected, 1e-13 * amp[k]);
    }
    size_t n;
    double *D = dissipation(ex, &n);
    ck_assert_uint_eq(n, 10);
    for (size_t c = 0; c < n; c++) {
        double expected = mun * (amp[2 * c] + 2.0 * amp[2 * c + 1] + amp[2 * c + 2]);
        ck_assert_double_eq_tol(D[c], expected, 1e-13 * expected);
    }
    free(D);
    free_switches(&sw);
    fricreg_exact_free(ex);
}
END_TEST

/* Resonance from rest at the origin. f_eq = -a sin t: the body sticks until a sin t = mun.
 * a = 0.9 < mun: never, so no switch, D = 0, stick fraction 1 (exactly). a = 2 > 4 mun/pi:
 * breaks away at t = asin(1/2) = pi/6 (closed form, 1e-14), sticks once more early in cycle 1
 * (x' = 0 at t = 3.021 with |f_eq| = 0.959), then slides for ever with growing amplitude. By
 * the half-cycle argument of test_resonance_amplitude_growth, once the reversals lock to k pi
 * each cycle adds 2 (a pi/2 - 2 mun) to the amplitude, so D_{k+1} - D_k -> 4 mun (a pi - 4 mun)
 * = 9.13274: the increments approach it monotonically (measured deviation 9e-8 after cycle 2,
 * 3e-9 after cycle 4, 8e-13 after cycle 19), asserted to 1e-8 relative from cycle 4 on.
 * a = 1.2 < 4 mun/pi: bounded stick-slip, sticking in every late cycle, D converged
 * (cycles 39 and 40 agree to 1e-10). */
START_TEST(test_resonance_from_rest)
{
    const double T = 2.0 * PI;
    fricreg_exact *ex = solve(0.9, 1.0, 1.0, 0.0, 0.0, 20.0 * T);
    size_t n;
    double *D = dissipation(ex, &n), frac;
    ck_assert_uint_eq(fricreg_exact_nswitches(ex), 0);
    for (size_t k = 0; k < n; k++)
        ck_assert_double_eq(D[k], 0.0);
    ck_assert_int_eq(fricreg_exact_stick_fraction(ex, 0.0, 20.0 * T, &frac), FRICREG_OK);
    ck_assert_double_eq(frac, 1.0);
    free(D);
    fricreg_exact_free(ex);

    ex = solve(2.0, 1.0, 1.0, 0.0, 0.0, 20.0 * T);
    struct switches sw = get_switches(ex);
    ck_assert_double_eq_tol(sw.t[0], PI / 6.0, 1e-14);
    ck_assert_int_eq(sw.stick[0], 0);
    for (size_t k = 1; k < sw.n; k++)
        if (sw.t[k] > T)
            ck_assert_int_eq(sw.stick[k], 0);
    D = dissipation(ex, &n);
    const double growth = 4.0 * (2.0 * PI - 4.0);
    for (size_t k = 1; k + 2 < n; k++) /* D[k + 1] - D[k] rises towards growth */
        ck_assert_double_lt(D[k + 1] - D[k], D[k + 2] - D[k + 1]);
    for (size_t k = 3; k + 1 < n; k++)
        ck_assert_double_eq_tol(D[k + 1] - D[k], growth, 1e-8 * growth);
    ck_assert_double_gt(D[n - 1], 10.0 * D[0]);
    free(D);
    free_switches(&sw);
    fricreg_exact_free(ex);

    ex = solve(1.2, 1.0, 1.0, 0.0, 0.0, 40.0 * T);
    D = dissipation(ex, &n);
    ck_assert_double_eq_tol(D[39], D[38], 1e-10 * D[39]);
    for (size_t k = 30; k < 40; k++) {
        double ta = (double)k * T, tb = (double)(k + 1) * T;
        ck_assert_int_eq(fricreg_exact_stick_fraction(ex, ta, tb, &frac), FRICREG_OK);
        ck_assert_double_gt(frac, 0.0);
        ck_assert_double_lt(frac, 1.0);
    }
    free(D);
    fricreg_exact_free(ex);
}
END_TEST

/* ------------------------------------------------- 4. the switching conditions */

/* The cases of the switching tests: {a, omega, mun}, from rest at the origin, 30 cycles.
 * a = 2, omega = 0.1 sticks and slips several times per forcing cycle. */
static const double regimes[][3] = {
    {2.0, 0.5, 1.0}, {3.0, 1.5, 1.0}, {1.2, 1.0, 1.0}, {2.0, 0.1, 1.0}, {2.385, 0.7318, 0.4137}};

/* At every switch, by its definition in (1)+(2) (header and spec): slip -> stick where x' = 0
 * (the velocity one ulp before, from the phase before, below 1e-12) with |f_eq| <= mun; stick
 * -> slip where |f_eq| = mun (1e-12), the new slip heading against f_eq; a reversal (slip ->
 * slip) where x' = 0 with |f_eq| >= mun. No two sticks in a row. Between switches, at 16 points:
 * a stick keeps x' = 0, x constant and |f_eq| <= mun; a slip keeps one sign of x'. From rest
 * at the origin f_eq(0) = 0, so the first phase is a stick ending at a sin(omega t) = mun. */
START_TEST(test_switching_conditions)
{
    const double a = regimes[_i][0], omega = regimes[_i][1], mun = regimes[_i][2];
    const double t_end = 30.0 * 2.0 * PI / omega;
    fricreg_exact *ex = solve(a, omega, mun, 0.0, 0.0, t_end);
    struct switches sw = get_switches(ex);
    ck_assert_uint_gt(sw.n, 30);
    ck_assert_double_eq_tol(sw.t[0], asin(mun / a) / omega, 1e-14);
    for (size_t k = 1; k < sw.n; k++) /* "increasing": no zero-length phase */
        ck_assert_double_gt(sw.t[k], sw.t[k - 1]);
    int was_stick = 1;
    for (size_t k = 0; k < sw.n; k++) {
        double t = sw.t[k], x, v, x_before, v_before;
        state(ex, t, &x, &v);
        state(ex, nextafter(t, 0.0), &x_before, &v_before);
        double feq = x - a * sin(omega * t);
        ck_assert_double_eq(v, 0.0);
        if (sw.stick[k]) {
            ck_assert_msg(!was_stick, "switch %zu at t = %.17g: two sticks in a row", k, t);
            ck_assert_msg(fabs(v_before) < 1e-12, "switch %zu (stick) at t = %.17g: v = %g", k, t,
                          v_before);
            ck_assert_double_le(fabs(feq), mun + 1e-12);
        } else if (was_stick) {
            ck_assert_msg(fabs(fabs(feq) - mun) < 1e-12,
                          "switch %zu (breakaway) at %.17g: "
                          "|f_eq| - mun = %g",
                          k, t, fabs(feq) - mun);
        } else {
            ck_assert_msg(fabs(v_before) < 1e-12, "switch %zu (reversal) at t = %.17g: v = %g", k,
                          t, v_before);
            ck_assert_double_ge(fabs(feq), mun - 1e-12);
        }
        ck_assert_double_eq_tol(x, x_before, 1e-13 * (1.0 + fabs(x))); /* x is continuous */
        if (!sw.stick[k]) /* the slip heads against f_eq: x' just after has the sign of -f_eq */
            ck_assert_double_lt(velocity(ex, fmin(t + 1e-3, t_end)) * feq, 0.0);
        was_stick = sw.stick[k];
    }
    for (size_t k = 0; k + 1 < sw.n; k++) {
        double t0 = sw.t[k], t1 = sw.t[k + 1], x0 = position(ex, t0), sign = 0.0;
        for (int j = 1; j <= 16; j++) {
            double t = t0 + (t1 - t0) * j / 17.0, x, v;
            state(ex, t, &x, &v);
            if (sw.stick[k]) {
                ck_assert_double_eq(v, 0.0);
                ck_assert_double_eq(x, x0);
                ck_assert_double_le(fabs(x - a * sin(omega * t)), mun);
            } else {
                ck_assert_double_ne(v, 0.0);
                if (sign == 0.0)
                    sign = v > 0.0 ? 1.0 : -1.0;
                ck_assert_msg(v * sign > 0.0, "slip %zu changes direction at t = %.17g", k, t);
            }
        }
    }
    free_switches(&sw);
    fricreg_exact_free(ex);
}
END_TEST

/* The closed forms solve Eq. (5): on every slip, central differences of the returned state
 * (h = 1e-4) give x' = v and x'' + x = -mun sgn(x') + a sin(omega t). Truncation h^2/6 |x'''|
 * ~ 2e-9 |x| and rounding eps |x|/h ~ 2e-12 |x|: tolerance 1e-7 (1 + |x|). Points within 2h
 * of a switch are skipped. Includes resonance (secular form) and its neighbour 1 - 1e-3. */
START_TEST(test_closed_form_satisfies_equation_5)
{
    static const double cases[][3] = {{2.0, 0.5, 1.0}, {3.0, 1.5, 1.0},   {2.0, 1.0, 1.0},
                                      {1.2, 1.0, 1.0}, {1.2, 0.999, 1.0}, {2.385, 0.7318, 0.4137}};
    const double a = cases[_i][0], omega = cases[_i][1], mun = cases[_i][2], h = 1e-4;
    const double t_end = 5.0 * 2.0 * PI / omega;
    fricreg_exact *ex = solve(a, omega, mun, 0.0, 0.0, t_end);
    struct switches sw = get_switches(ex);
    int checked = 0;
    for (double t = 0.0123; t < t_end - 2.0 * h; t += t_end / 997.0) {
        if (switches_within(&sw, t - 2.0 * h, t + 2.0 * h) > 0)
            continue;
        double x, v, xm, vm, xp, vp;
        state(ex, t, &x, &v);
        if (v == 0.0)
            continue; /* a stick: test_switching_conditions */
        state(ex, t - h, &xm, &vm);
        state(ex, t + h, &xp, &vp);
        double tol = 1e-7 * (1.0 + fabs(x));
        ck_assert_double_eq_tol((xp - xm) / (2.0 * h), v, tol);
        double residual = (vp - vm) / (2.0 * h) + x + (v > 0.0 ? mun : -mun) - a * sin(omega * t);
        ck_assert_msg(fabs(residual) < tol, "t = %.17g: residual of (5) %g", t, residual);
        checked++;
    }
    ck_assert_int_gt(checked, 300);
    free_switches(&sw);
    fricreg_exact_free(ex);
}
END_TEST

/* ------------------------------------------------- 5. against brute-force simulation */

/* fricreg_sim of the forced case (a = 2, omega = 0.5, from rest at the origin), fixed-step RK4
 * of step dt, law `law` with eps = 2 dt (the paper's rule), 50 cycles. Returns D of cycle 50;
 * *stick gets the near-stick fraction (|x'| < eps) of that cycle. */
static double simulated_D50(int law, double dt, double *stick)
{
    fricreg_sim *sim = NULL;
    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_OSCILLATOR, &sim), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_A, 2.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_OMEGA, 0.5), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_X0, 0.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_V0, 0.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_law(sim, law, 0.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RK4, dt, 0.0, 0.0), FRICREG_OK);
    int status = fricreg_sim_run_cycles(sim, 50);
    ck_assert_msg(status == FRICREG_OK, "run: %s", fricreg_sim_errmsg(sim));
    double D[50];
    ck_assert_int_eq(fricreg_sim_get_dissipation(sim, 50, D), FRICREG_OK);
    if (stick != NULL)
        ck_assert_int_eq(fricreg_sim_get_stick_fraction(sim, 1, stick), FRICREG_OK);
    fricreg_sim_free(sim);
    return D[49];
}

static double exact_D50(double *stick)
{
    const double T = 4.0 * PI;
    fricreg_exact *ex = solve(2.0, 0.5, 1.0, 0.0, 0.0, 50.0 * T);
    size_t n;
    double *D = dissipation(ex, &n), D50 = D[49];
    ck_assert_int_eq(fricreg_exact_stick_fraction(ex, 49.0 * T, 50.0 * T, stick), FRICREG_OK);
    free(D);
    fricreg_exact_free(ex);
    return D50;
}

/* Paper Fig. 7a: the error of (4) scales as dt^2. Measured errors of D_50 (exact
 * 10.4274336335641): 3.1e-5 at dt = 0.01, 3.3e-7 at 0.001 (3.2e-8 relative), so dt^2 predicts
 * 3.3e-9 (3.1e-10 relative) at 1e-4; measured 10.4274336281933, 5.4e-9 (5.2e-10 relative).
 * Asserted: below 1e-9 relative at 1e-4 (three times the dt^2 prediction, for the irregular
 * part of the error), and falling at least 30-fold from 1e-3 to 1e-4 (dt^2: 100; seen: 61). */
START_TEST(test_quinn_converges_to_exact_as_dt_squared)
{
    double stick;
    const double D_exact = exact_D50(&stick);
    double err3 = fabs(simulated_D50(FRICREG_LAW_QUINN, 1e-3, NULL) - D_exact) / D_exact;
    double err4 = fabs(simulated_D50(FRICREG_LAW_QUINN, 1e-4, NULL) - D_exact) / D_exact;
    ck_assert_double_lt(err4, 1e-9);
    ck_assert_double_gt(err3 / err4, 30.0);
}
END_TEST

/* Paper Fig. 7a: classical Coulomb (1) converges only as dt, irregularly (it chatters through
 * every stick): at dt = 1e-4 within 1e-3 relative of the exact D_50, i.e. an O(dt) error with a
 * constant up to 10. Measured: -2.0e-5 relative (+3.1e-5 at dt = 1e-3: not monotone). */
START_TEST(test_coulomb_converges_to_exact)
{
    double stick;
    const double D_exact = exact_D50(&stick);
    double D = simulated_D50(FRICREG_LAW_COULOMB, 1e-4, NULL);
    ck_assert_double_eq_tol(D, D_exact, 1e-3 * D_exact);
}
END_TEST

/* Stick fraction of cycle 50: the simulation reports the time with |x'| < eps (eps = 2e-4),
 * the exact solver the time at rest. They differ by the slip time spent with |x'| < eps: at a
 * breakaway |f_eq| - mun grows as j t with j = a omega |cos(omega t)| <= 1, so x' ~ j t^2/2
 * and |x'| < eps lasts sqrt(2 eps/j) >= 0.02 (of T = 12.6: 0.16%); at a stop the deceleration
 * is O(1), eps/O(1) ~ 2e-4. Two sticks per cycle: the simulated fraction exceeds the exact one
 * by 0 to about 0.5%, so it must lie in [exact - 1e-4, exact + 0.01]. This compares like with
 * like (the near-stick set contains the stick) and needs no velocity threshold of our own.
 * Measured: exact 0.175033, simulated 0.179145 (+0.41%). */
START_TEST(test_stick_fraction_matches_simulation)
{
    double stick_exact, stick_sim;
    exact_D50(&stick_exact);
    simulated_D50(FRICREG_LAW_QUINN, 1e-4, &stick_sim);
    ck_assert_double_gt(stick_exact, 0.1);
    ck_assert_double_ge(stick_sim, stick_exact - 1e-4);
    ck_assert_double_le(stick_sim, stick_exact + 0.01);
}
END_TEST

/* ------------------------------------------------- 7. several switches per cycle */

/* The spec's no-stick case a = 3, omega = 1.5, from rest at the origin: in steady state (from
 * cycle 10 on) each forcing cycle has exactly two switches, both reversals (no stick), and the
 * per-cycle D has settled (cycles 49 and 50 agree to 1e-9). */
START_TEST(test_no_stick_case_two_reversals_per_cycle)
{
    const double a = 3.0, omega = 1.5, T = 2.0 * PI / omega;
    fricreg_exact *ex = solve(a, omega, 1.0, 0.0, 0.0, 50.0 * T);
    struct switches sw = get_switches(ex);
    for (size_t c = 10; c < 50; c++) {
        size_t count = switches_within(&sw, (double)c * T, (double)(c + 1) * T);
        ck_assert_msg(count == 2, "cycle %zu: %zu switches", c + 1, count);
    }
    for (size_t k = 1; k < sw.n; k++) /* only the first switch (the breakaway) ends a stick */
        ck_assert_int_eq(sw.stick[k], 0);
    double frac;
    ck_assert_int_eq(fricreg_exact_stick_fraction(ex, 10.0 * T, 50.0 * T, &frac), FRICREG_OK);
    ck_assert_double_eq(frac, 0.0);
    size_t n;
    double *D = dissipation(ex, &n);
    ck_assert_double_eq_tol(D[49], D[48], 1e-9 * D[49]);
    free(D);
    free_switches(&sw);
    fricreg_exact_free(ex);
}
END_TEST

/* ------------------------------------------------- 6. error paths */

#define SENTINEL ((fricreg_exact *)&sentinel_storage)
static int sentinel_storage;

/* Header: ENULL for a NULL out; ENONFINITE for NaN or Inf in any input (checked before the
 * ranges); EINVAL for omega <= 0, mun < 0, t_end <= 0, more than 10^6 cycles. *out untouched. */
START_TEST(test_solve_rejects_bad_input)
{
    ck_assert_int_eq(fricreg_exact_solve(2.0, 0.5, 1.0, 0.0, 0.0, 10.0, NULL), FRICREG_ENULL);
    enum { NONFIN = FRICREG_ENONFINITE, INVAL = FRICREG_EINVAL };
    static const struct {
        double a, omega, mun, x0, v0, t_end;
        int status;
    } cases[] = {
        {NAN, 1, 1, 0, 0, 10, NONFIN},
        {1, NAN, 1, 0, 0, 10, NONFIN},
        {1, 1, NAN, 0, 0, 10, NONFIN},
        {1, 1, 1, NAN, 0, 10, NONFIN},
        {1, 1, 1, 0, NAN, 10, NONFIN},
        {1, 1, 1, 0, 0, NAN, NONFIN},
        {INFINITY, 1, 1, 0, 0, 10, NONFIN},
        {1, -INFINITY, 1, 0, 0, 10, NONFIN},
        {1, 1, INFINITY, 0, 0, 10, NONFIN},
        {1, 1, 1, -INFINITY, 0, 10, NONFIN},
        {1, 1, 1, 0, INFINITY, 10, NONFIN},
        {1, 1, 1, 0, 0, INFINITY, NONFIN},
        {1, 0, 1, 0, 0, 10, INVAL},
        {1, -0.5, 1, 0, 0, 10, INVAL},
        {1, 1, -1e-300, 0, 0, 10, INVAL},
        {1, 1, -1, 0, 0, 10, INVAL},
        {1, 1, 1, 0, 0, 0, INVAL},
        {1, 1, 1, 0, 0, -2.385, INVAL},
        {1, 1, 1, 0, 0, 1e6 * 2 * PI * 1.000001, INVAL}, /* just over 10^6 cycles */
        {1, 0.25, 1, 0, 0, 1e6 * 8 * PI * 1.000001, INVAL},
        {1, 1, 1, 0, 0, 1e300, INVAL},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        fricreg_exact *ex = SENTINEL;
        int status = fricreg_exact_solve(cases[i].a, cases[i].omega, cases[i].mun, cases[i].x0,
                                         cases[i].v0, cases[i].t_end, &ex);
        ck_assert_msg(status == cases[i].status, "case %zu: status %d, expected %d", i, status,
                      cases[i].status);
        ck_assert_ptr_eq(ex, SENTINEL);
    }
}
END_TEST

/* Header: state() ENULL for NULL ex, x or v; EINVAL for t outside [0, t_end] (or NaN); on
 * failure x and v untouched. The end points themselves are valid. */
START_TEST(test_state_rejects_bad_input)
{
    fricreg_exact *ex = solve(2.0, 0.5, 1.0, 0.0, 0.0, 30.0);
    double x = 2.385, v = -2.385;
    ck_assert_int_eq(fricreg_exact_state(NULL, 1.0, &x, &v), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_exact_state(ex, 1.0, NULL, &v), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_exact_state(ex, 1.0, &x, NULL), FRICREG_ENULL);
    static const double bad[] = {-1e-300, -1.0, 30.000000000001, 1e300, NAN, INFINITY, -INFINITY};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        ck_assert_int_eq(fricreg_exact_state(ex, bad[i], &x, &v), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_exact_state(ex, nextafter(30.0, 31.0), &x, &v), FRICREG_EINVAL);
    ck_assert_double_eq(x, 2.385);
    ck_assert_double_eq(v, -2.385);
    ck_assert_int_eq(fricreg_exact_state(ex, 0.0, &x, &v), FRICREG_OK);
    ck_assert_double_eq(x, 0.0);
    ck_assert_double_eq(v, 0.0);
    ck_assert_int_eq(fricreg_exact_state(ex, 30.0, &x, &v), FRICREG_OK);
    fricreg_exact_free(ex);
}
END_TEST

/* Header: switches() and dissipation() ENULL for NULL ex (or NULL array with n > 0), ESIZE for
 * any n but the count; arrays untouched on failure. n = 0 with NULL arrays is fine when the
 * count is 0. nswitches/ncycles of NULL are 0; free(NULL) does nothing. */
START_TEST(test_arrays_reject_wrong_size)
{
    fricreg_exact *ex = solve(2.0, 0.5, 1.0, 0.0, 0.0, 10.0 * 4.0 * PI);
    size_t ns = fricreg_exact_nswitches(ex), nc = fricreg_exact_ncycles(ex);
    ck_assert_uint_eq(nc, 10);
    ck_assert_uint_gt(ns, 10);
    double times[64], D[64];
    int sticks[64];
    ck_assert_uint_lt(ns, 63);
    for (size_t i = 0; i < 64; i++)
        times[i] = D[i] = -2.385, sticks[i] = 7;
    const size_t wrong_ns[] = {0, ns - 1, ns + 1}, wrong_nc[] = {0, nc - 1, nc + 1};
    for (size_t i = 0; i < 3; i++) {
        ck_assert_int_eq(fricreg_exact_switches(ex, wrong_ns[i], times, sticks), FRICREG_ESIZE);
        ck_assert_int_eq(fricreg_exact_switches(ex, wrong_ns[i], times, NULL), FRICREG_ESIZE);
        ck_assert_int_eq(fricreg_exact_dissipation(ex, wrong_nc[i], D), FRICREG_ESIZE);
    }
    ck_assert_int_eq(fricreg_exact_switches(NULL, ns, times, sticks), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_exact_switches(ex, ns, NULL, sticks), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_exact_dissipation(NULL, nc, D), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_exact_dissipation(ex, nc, NULL), FRICREG_ENULL);
    for (size_t i = 0; i < 64; i++) {
        ck_assert_double_eq(times[i], -2.385);
        ck_assert_double_eq(D[i], -2.385);
        ck_assert_int_eq(sticks[i], 7);
    }
    /* sticks may be NULL */
    ck_assert_int_eq(fricreg_exact_switches(ex, ns, times, NULL), FRICREG_OK);
    fricreg_exact_free(ex);

    ex = solve(0.0, 1.0, 1.0, 0.3, 0.0, 5.0); /* at rest inside the bound: 0 switches, 0 cycles */
    ck_assert_uint_eq(fricreg_exact_nswitches(ex), 0);
    ck_assert_uint_eq(fricreg_exact_ncycles(ex), 0);
    ck_assert_int_eq(fricreg_exact_switches(ex, 0, NULL, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_exact_dissipation(ex, 0, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_exact_dissipation(ex, 1, D), FRICREG_ESIZE);
    fricreg_exact_free(ex);

    ck_assert_uint_eq(fricreg_exact_nswitches(NULL), 0);
    ck_assert_uint_eq(fricreg_exact_ncycles(NULL), 0);
    fricreg_exact_free(NULL);
}
END_TEST

/* Header: stick_fraction() ENULL for NULL ex or fraction; EINVAL unless
 * 0 <= t0 < t1 <= t_end; *fraction untouched on failure. */
START_TEST(test_stick_fraction_rejects_bad_interval)
{
    fricreg_exact *ex = solve(2.0, 0.5, 1.0, 0.0, 0.0, 30.0);
    double frac = -2.385;
    ck_assert_int_eq(fricreg_exact_stick_fraction(NULL, 0.0, 1.0, &frac), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_exact_stick_fraction(ex, 0.0, 1.0, NULL), FRICREG_ENULL);
    static const double bad[][2] = {{-1e-300, 1.0},         {1.0, 1.0},     {2.0, 1.0},
                                    {0.0, 30.000000000001}, {NAN, 1.0},     {0.0, NAN},
                                    {-INFINITY, 1.0},       {0.0, INFINITY}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        ck_assert_msg(fricreg_exact_stick_fraction(ex, bad[i][0], bad[i][1], &frac) ==
                          FRICREG_EINVAL,
                      "interval %zu", i);
    ck_assert_double_eq(frac, -2.385);
    /* From rest at the origin the body sticks until 2 sin(t/2) = 1, t = pi/3 (closed form). */
    ck_assert_int_eq(fricreg_exact_stick_fraction(ex, 0.0, 2.0, &frac), FRICREG_OK);
    ck_assert_double_eq_tol(frac, PI / 6.0, 1e-14);
    fricreg_exact_free(ex);
}
END_TEST

/* ------------------------------------ 7. the object: create, run, messages, counters (1.1) */

/* Allocation failure on demand, for the ENOMEM paths: this program's realloc and calloc come
 * before libc's for the library too (ELF symbol interposition) and fail once their countdown
 * reaches 0 (-1: never). glibc only, and not under AddressSanitizer, which owns them. */
#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__)
#define CAN_FAIL_ALLOCATION 1
extern void *__libc_realloc(void *p, size_t size);
extern void *__libc_calloc(size_t n, size_t size);
static int realloc_fails_in = -1, calloc_fails_in = -1;

static int countdown(int *fails_in)
{
    if (*fails_in == 0)
        return 1;
    if (*fails_in > 0)
        --*fails_in;
    return 0;
}

void *realloc(void *p, size_t size)
{
    return countdown(&realloc_fails_in) ? NULL : __libc_realloc(p, size);
}

void *calloc(size_t n, size_t size)
{
    return countdown(&calloc_fails_in) ? NULL : __libc_calloc(n, size);
}
#else
#define CAN_FAIL_ALLOCATION 0
#endif

static fricreg_exact *create(double a, double omega, double mun, double x0, double v0)
{
    fricreg_exact *ex = NULL;
    ck_assert_int_eq(fricreg_exact_create(a, omega, mun, x0, v0, &ex), FRICREG_OK);
    ck_assert_ptr_nonnull(ex);
    return ex;
}

static double get_value(const fricreg_exact *ex, int which)
{
    double value = -2.385;
    ck_assert_int_eq(fricreg_exact_get_value(ex, which, &value), FRICREG_OK);
    return value;
}

static int64_t get_stat(const fricreg_exact *ex, int which)
{
    int64_t value = -7;
    ck_assert_int_eq(fricreg_exact_get_stat(ex, which, &value), FRICREG_OK);
    return value;
}

/* The two solutions have the same switches and dissipation, bit for bit. */
static void assert_same_solution(const fricreg_exact *p, const fricreg_exact *q)
{
    struct switches a = get_switches(p), b = get_switches(q);
    ck_assert_uint_eq(a.n, b.n);
    for (size_t k = 0; k < a.n; k++) {
        ck_assert_double_eq(a.t[k], b.t[k]);
        ck_assert_int_eq(a.stick[k], b.stick[k]);
    }
    size_t na, nb;
    double *Da = dissipation(p, &na), *Db = dissipation(q, &nb);
    ck_assert_uint_eq(na, nb);
    for (size_t k = 0; k < na; k++)
        ck_assert_double_eq(Da[k], Db[k]);
    free(Da);
    free(Db);
    free_switches(&a);
    free_switches(&b);
}

/* fricreg_exact_solve is create + run (header): the same solution bit for bit, in the regimes
 * of the spec (stick-slip, no stick, resonance). run_cycles(k) is run(k T) with T the object's
 * period: ncycles = k and the time reached is k T exactly. */
START_TEST(test_create_run_equals_solve)
{
    static const double cases[][5] = {{2.0, 0.5, 1.0, 0.0, 0.0},
                                      {3.0, 1.5, 1.0, 0.0, 0.0},
                                      {1.2, 1.0, 1.0, -2.385, 0.0},
                                      {0.0, 1.0, 0.731, 0.3, 1.7}};
    const double *c = cases[_i];
    const int cycles = 7;
    fricreg_exact *ex = create(c[0], c[1], c[2], c[3], c[4]);
    const double T = get_value(ex, FRICREG_EXACT_VALUE_PERIOD);
    ck_assert_double_eq_tol(T, 2.0 * PI / c[1], 4e-16 * T);
    ck_assert_int_eq(fricreg_exact_run_cycles(ex, cycles), FRICREG_OK);
    ck_assert_uint_eq(fricreg_exact_ncycles(ex), (size_t)cycles);
    ck_assert_double_eq(get_value(ex, FRICREG_EXACT_VALUE_TIME), cycles * T);
    fricreg_exact *ref = solve(c[0], c[1], c[2], c[3], c[4], cycles * T);
    assert_same_solution(ex, ref);
    fricreg_exact_free(ref);

    ck_assert_int_eq(fricreg_exact_run(ex, 23.85), FRICREG_OK);
    ck_assert_double_eq(get_value(ex, FRICREG_EXACT_VALUE_TIME), 23.85);
    ref = solve(c[0], c[1], c[2], c[3], c[4], 23.85);
    assert_same_solution(ex, ref);
    fricreg_exact_free(ref);
    ck_assert_int_eq(fricreg_exact_errcode(ex), FRICREG_OK);
    ck_assert_str_eq(fricreg_exact_errmsg(ex), "");
    fricreg_exact_free(ex);
}
END_TEST

/* Header: before a run the object holds no solution: time 0, counters 0, no switches or cycles,
 * state() and stick_fraction() EINVAL (no time covered), empty arrays fine; the period is
 * already known (2 pi/omega). */
START_TEST(test_before_a_run)
{
    fricreg_exact *ex = create(2.0, 2.385, 1.0, 0.0, 0.0);
    ck_assert_double_eq(get_value(ex, FRICREG_EXACT_VALUE_TIME), 0.0);
    ck_assert_double_eq_tol(get_value(ex, FRICREG_EXACT_VALUE_PERIOD), 2.0 * PI / 2.385, 1e-15);
    for (int k = FRICREG_EXACT_STAT_SCAN_POINTS; k <= FRICREG_EXACT_STAT_ROOT_ITERS; k++)
        ck_assert_int_eq(get_stat(ex, k), 0);
    ck_assert_uint_eq(fricreg_exact_nswitches(ex), 0);
    ck_assert_uint_eq(fricreg_exact_ncycles(ex), 0);
    double x = 2.385, v = -2.385, frac = 7.0;
    ck_assert_int_eq(fricreg_exact_state(ex, 0.0, &x, &v), FRICREG_EINVAL);
    ck_assert_double_eq(x, 2.385);
    ck_assert_double_eq(v, -2.385);
    ck_assert_int_eq(fricreg_exact_stick_fraction(ex, 0.0, 1.0, &frac), FRICREG_EINVAL);
    ck_assert_double_eq(frac, 7.0);
    ck_assert_int_eq(fricreg_exact_switches(ex, 0, NULL, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_exact_dissipation(ex, 0, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_exact_errcode(ex), FRICREG_OK);
    ck_assert_str_eq(fricreg_exact_errmsg(ex), "");
    fricreg_exact_free(ex);
}
END_TEST

/* A second run replaces the first: a shorter one gives the shorter solution (as a fresh
 * solve), and its own counters. */
START_TEST(test_run_replaces_solution)
{
    fricreg_exact *ex = create(2.0, 0.5, 1.0, 0.0, 0.0);
    ck_assert_int_eq(fricreg_exact_run(ex, 60.0), FRICREG_OK);
    size_t long_switches = fricreg_exact_nswitches(ex);
    int64_t long_scan = get_stat(ex, FRICREG_EXACT_STAT_SCAN_POINTS);
    ck_assert_int_eq(fricreg_exact_run(ex, 17.31), FRICREG_OK);
    ck_assert_uint_lt(fricreg_exact_nswitches(ex), long_switches);
    ck_assert_int_lt(get_stat(ex, FRICREG_EXACT_STAT_SCAN_POINTS), long_scan);
    fricreg_exact *ref = solve(2.0, 0.5, 1.0, 0.0, 0.0, 17.31);
    assert_same_solution(ex, ref);
    for (int k = FRICREG_EXACT_STAT_SCAN_POINTS; k <= FRICREG_EXACT_STAT_ROOT_ITERS; k++)
        ck_assert_int_eq(get_stat(ex, k), get_stat(ref, k));
    fricreg_exact_free(ref);
    fricreg_exact_free(ex);
}
END_TEST

/* Counters (header): each phase is scanned by safe steps — no root of its "holds" function g
 * lies within the step (Taylor's bound on g'') — of at least h, 1/1024 of the shortest period
 * in g, so the scan never takes more points than the fixed grid of step
 * h = 2 pi/max(1, omega)/1024 it replaced (t_end/h within one point per phase, plus the
 * halved first steps: asserted <= t_end/h + 2 phases), and at least one per phase. The safe
 * steps take few points per phase (measured 5 to 16): asserted below 64 per phase. Each switch
 * is one root (these regimes have no phase of zero length). Brent, superlinear, needs fewer
 * iterations per root than bisection from the largest step (the free period 2 pi) down to
 * 2 ulps of t, log2(2 pi/(2 eps t_end)); and at least one unless the scan hits a root exactly.
 * Cases: the unforced paper case, stick-slip at omega = 0.5 and 2.385, a long no-stick run. */
START_TEST(test_counters_follow_the_scan_grid)
{
    static const double cases[][6] = {{0.0, 1.0, 1.0, 2.75, 0.0, 20.0},
                                      {2.0, 0.5, 1.0, 0.0, 0.0, 30.0},
                                      {2.0, 2.385, 1.0, 0.0, 0.0, 30.0},
                                      {0.3, 1.0, 0.1, 1.2, 0.0, 200.0}};
    const double *c = cases[_i], t_end = c[5];
    fricreg_exact *ex = create(c[0], c[1], c[2], c[3], c[4]);
    ck_assert_int_eq(fricreg_exact_run(ex, t_end), FRICREG_OK);
    const double h = 2.0 * PI / fmax(1.0, c[1]) / 1024.0, grid = t_end / h;
    const double phases = (double)fricreg_exact_nswitches(ex) + 1.0;
    const int64_t scan = get_stat(ex, FRICREG_EXACT_STAT_SCAN_POINTS);
    const int64_t roots = get_stat(ex, FRICREG_EXACT_STAT_ROOTS);
    const int64_t iterations = get_stat(ex, FRICREG_EXACT_STAT_ROOT_ITERS);
    ck_assert_msg((double)scan >= phases &&
                      (double)scan <= fmin(grid + 2.0 * phases, 64.0 * phases),
                  "case %d: %lld scan points for a grid of %.2f points and %g phases", _i,
                  (long long)scan, grid, phases);
    ck_assert_int_eq(roots, (int64_t)fricreg_exact_nswitches(ex));
    const double bisection = log2(2.0 * PI / (2.0 * GSL_DBL_EPSILON * t_end));
    ck_assert_msg(iterations >= roots && (double)iterations <= bisection * (double)roots,
                  "case %d: %lld Brent iterations for %lld roots", _i, (long long)iterations,
                  (long long)roots);
    fricreg_exact_free(ex);
}
END_TEST

/* The work of a run is bounded (header: at most 2^22 - 1 switches and 2^27 scan points; a scan
 * step must stay above 2^-32 t). Three cases that once hung or took seconds to minutes, judged
 * by the counters, never by time:
 * - omega = 1e-300 (a = 2, mun = 1, from rest at 0, one cycle): the body sticks until
 *   2 sin(omega t) = 1, t = (pi/6)/omega = 5.2e299, where a slip would need steps of
 *   2 pi/1024 — lost in the rounding of t: refused there with EINVAL, at once (the old scan
 *   never advanced), the object as before the run. With mun = 3 > |x| + |a| the stick holds
 *   for ever: solved with no scan at all.
 * - omega = 1e6, t_end = 1 (159155 cycles; 11.5 s and 1.6e8 scan points on the old grid),
 *   a = 2e12, mun = 1e12 (the motion of order 1): stick-slip with two switches per cycle
 *   (318308 in 159154.9 cycles); at most 8 scan points per phase (measured 7.0). Its first
 *   20 cycles are those of a 20-cycle run, bit for bit, whose dissipation matches the energy
 *   balance to 1e-4: the balance's own conditioning grows as omega^2 (gaps measured 9e-12,
 *   9e-10, 5.5e-8 at omega = 300, 3e3, 3e4 with a = 2 omega^2, mun = omega^2), and the old
 *   solver gave 5.5e-5 here too (its switch times and these agree to 4.4e-16).
 * - omega = 1 at the cycle cap 10^6 (33 s, 1e9 scan points before): a = 2, mun = 1 from
 *   rest slides for ever after cycle 1 with each cycle adding 4 mun (a pi - 4 mun) = 9.13274
 *   to D (test_resonance_from_rest); 2e6 switches, at most 8 scan points per phase (measured
 *   6.0), and D's increments over the last cycles still that closed form to 1e-9. */
START_TEST(test_work_is_bounded_slow_forcing)
{
    fricreg_exact *ex = create(2.0, 1e-300, 1.0, 0.0, 0.0);
    ck_assert_int_eq(fricreg_exact_run_cycles(ex, 1), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_exact_errmsg(ex), "lost in the rounding of t"));
    ck_assert_double_eq(get_value(ex, FRICREG_EXACT_VALUE_TIME), 0.0);
    ck_assert_int_eq(get_stat(ex, FRICREG_EXACT_STAT_SCAN_POINTS), 0);
    fricreg_exact_free(ex);
    ex = create(2.0, 1e-300, 3.0, 0.0, 0.0);
    ck_assert_int_eq(fricreg_exact_run_cycles(ex, 1), FRICREG_OK);
    ck_assert_uint_eq(fricreg_exact_nswitches(ex), 0);
    ck_assert_int_eq(get_stat(ex, FRICREG_EXACT_STAT_SCAN_POINTS), 0);
    fricreg_exact_free(ex);
}
END_TEST

START_TEST(test_work_is_bounded_fast_forcing)
{
    const double omega = 1e6, T = 2.0 * PI / omega;
    fricreg_exact *ex = create(2e12, omega, 1e12, 0.0, 0.0);
    ck_assert_int_eq(fricreg_exact_run(ex, 1.0), FRICREG_OK);
    size_t n = fricreg_exact_nswitches(ex);
    ck_assert_uint_ge(n, 2 * (size_t)(1.0 / T)); /* 159154.9 cycles: measured 318308 */
    ck_assert_uint_le(n, 2 * (size_t)(1.0 / T) + 4);
    ck_assert_int_le(get_stat(ex, FRICREG_EXACT_STAT_SCAN_POINTS), 8 * (int64_t)(n + 1));
    fricreg_exact *ref = solve(2e12, omega, 1e12, 0.0, 0.0, 20.0 * T);
    struct switches all = get_switches(ex), first = get_switches(ref);
    for (size_t k = 0; k + 1 < first.n; k++)
        ck_assert_double_eq(all.t[k], first.t[k]);
    double gap = balance_gap(ref, 2e12, omega, 1, 1e-12);
    ck_assert_msg(gap < 1e-4, "omega = 1e6: relative gap %.3g", gap);
    free_switches(&all);
    free_switches(&first);
    fricreg_exact_free(ref);
    fricreg_exact_free(ex);
}
END_TEST

START_TEST(test_work_is_bounded_cycle_cap)
{
    fricreg_exact *ex = create(2.0, 1.0, 1.0, 0.0, 0.0);
    ck_assert_int_eq(fricreg_exact_run_cycles(ex, 1000000), FRICREG_OK);
    size_t n = fricreg_exact_nswitches(ex);
    ck_assert_uint_ge(n, 2000000);
    ck_assert_int_le(get_stat(ex, FRICREG_EXACT_STAT_SCAN_POINTS), 8 * (int64_t)(n + 1));
    size_t ncycles;
    double *D = dissipation(ex, &ncycles), step = 4.0 * (2.0 * PI - 4.0);
    ck_assert_uint_eq(ncycles, 1000000);
    for (size_t k = ncycles - 5; k < ncycles; k++)
        ck_assert_double_eq_tol(D[k] - D[k - 1], step, 1e-9 * D[k]);
    free(D);
    fricreg_exact_free(ex);
}
END_TEST

/* Header: create() ENULL for a NULL out, ENONFINITE for NaN or Inf in any number (before the
 * ranges), EINVAL for omega <= 0 or mun < 0; *out untouched. */
START_TEST(test_create_rejects_bad_input)
{
    ck_assert_int_eq(fricreg_exact_create(2.0, 0.5, 1.0, 0.0, 0.0, NULL), FRICREG_ENULL);
    static const struct {
        double a, omega, mun, x0, v0;
        int status;
    } cases[] = {
        {NAN, 1, 1, 0, 0, FRICREG_ENONFINITE},      {1, NAN, 1, 0, 0, FRICREG_ENONFINITE},
        {1, 1, NAN, 0, 0, FRICREG_ENONFINITE},      {1, 1, 1, NAN, 0, FRICREG_ENONFINITE},
        {1, 1, 1, 0, NAN, FRICREG_ENONFINITE},      {-INFINITY, 1, 1, 0, 0, FRICREG_ENONFINITE},
        {1, INFINITY, 1, 0, 0, FRICREG_ENONFINITE}, {1, 1, INFINITY, 0, 0, FRICREG_ENONFINITE},
        {1, 1, 1, INFINITY, 0, FRICREG_ENONFINITE}, {1, 1, 1, 0, -INFINITY, FRICREG_ENONFINITE},
        {1, 0, -1, 0, NAN, FRICREG_ENONFINITE},     {1, 0, 1, 0, 0, FRICREG_EINVAL},
        {1, -0.5, 1, 0, 0, FRICREG_EINVAL},         {1, 1, -1e-300, 0, 0, FRICREG_EINVAL},
        {1, 1, -2.385, 0, 0, FRICREG_EINVAL},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        fricreg_exact *ex = SENTINEL;
        int status = fricreg_exact_create(cases[i].a, cases[i].omega, cases[i].mun, cases[i].x0,
                                          cases[i].v0, &ex);
        ck_assert_msg(status == cases[i].status, "case %zu: status %d, expected %d", i, status,
                      cases[i].status);
        ck_assert_ptr_eq(ex, SENTINEL);
    }
}
END_TEST

/* Runs that must fail on an object that holds the solution of run(30): each gives its status,
 * records it with the message below, and leaves that solution as it was. */
static void expect_run_failure(fricreg_exact *ex, int status, int by_cycles, double arg,
                               const char *message)
{
    size_t switches = fricreg_exact_nswitches(ex);
    int64_t scan = get_stat(ex, FRICREG_EXACT_STAT_SCAN_POINTS);
    int got = by_cycles ? fricreg_exact_run_cycles(ex, (int)arg) : fricreg_exact_run(ex, arg);
    ck_assert_int_eq(got, status);
    ck_assert_int_eq(fricreg_exact_errcode(ex), status);
    ck_assert_str_eq(fricreg_exact_errmsg(ex), message);
    ck_assert_double_eq(get_value(ex, FRICREG_EXACT_VALUE_TIME), 30.0);
    ck_assert_uint_eq(fricreg_exact_nswitches(ex), switches);
    ck_assert_int_eq(get_stat(ex, FRICREG_EXACT_STAT_SCAN_POINTS), scan);
    ck_assert_double_eq_tol(position(ex, PI / 3.0), 0.0, 1e-15); /* still the same solution */
}

/* Header: every message of run() and run_cycles(), word for word; they name the value. A
 * successful call does not clear the last error. From rest at the origin with a = 2,
 * omega = 0.5, the body sticks until 2 sin(t/2) = 1, t = pi/3 (as in
 * test_stick_fraction_rejects_bad_interval). T = 4 pi = 12.5664. */
START_TEST(test_run_messages)
{
    fricreg_exact *ex = create(2.0, 0.5, 1.0, 0.0, 0.0);
    ck_assert_int_eq(fricreg_exact_run(ex, 30.0), FRICREG_OK);
    expect_run_failure(ex, FRICREG_ENONFINITE, 0, NAN, "run: t_end = nan is not finite");
    expect_run_failure(ex, FRICREG_ENONFINITE, 0, -INFINITY, "run: t_end = -inf is not finite");
    expect_run_failure(ex, FRICREG_EINVAL, 0, 0.0, "run: t_end = 0 must be > 0");
    expect_run_failure(ex, FRICREG_EINVAL, 0, -2.385, "run: t_end = -2.385 must be > 0");
    expect_run_failure(ex, FRICREG_EINVAL, 0, 1e300,
                       "run: t_end = 1e+300 spans 7.95775e+298 "
                       "forcing cycles of period 12.5664, more than 10^6");
    /* just over 10^6 cycles: 4 pi 10^6 (1 + 1e-6) */
    expect_run_failure(ex, FRICREG_EINVAL, 0, 12566383.3,
                       "run: t_end = 1.25664e+07 spans "
                       "1e+06 forcing cycles of period 12.5664, more than 10^6");
    expect_run_failure(ex, FRICREG_EINVAL, 1, 0, "run_cycles: cycles = 0 must be from 1 to 10^6");
    expect_run_failure(ex, FRICREG_EINVAL, 1, -3, "run_cycles: cycles = -3 must be from 1 to 10^6");
    expect_run_failure(ex, FRICREG_EINVAL, 1, 1000001,
                       "run_cycles: cycles = 1000001 must be from 1 to 10^6");
    /* Neither a success nor a getter's failure (const object) changes the last error. */
    const char *last = "run_cycles: cycles = 1000001 must be from 1 to 10^6";
    ck_assert_int_eq(fricreg_exact_run_cycles(ex, 2), FRICREG_OK);
    double x, v, frac, value;
    int64_t count;
    ck_assert_int_eq(fricreg_exact_state(ex, -1.0, &x, &v), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_exact_stick_fraction(ex, 2.0, 1.0, &frac), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_exact_switches(ex, 1000, NULL, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_exact_dissipation(ex, 1000, &x), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_exact_get_value(ex, -1, &value), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_exact_get_stat(ex, -1, &count), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_exact_errcode(ex), FRICREG_EINVAL);
    ck_assert_str_eq(fricreg_exact_errmsg(ex), last);
    ck_assert_int_eq(fricreg_exact_run(NULL, 30.0), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_exact_run_cycles(NULL, 2), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_exact_errcode(NULL), FRICREG_OK);
    ck_assert_str_eq(fricreg_exact_errmsg(NULL), "NULL exact solution");
    fricreg_exact_free(ex);
}
END_TEST

/* Header: errmsg_copy() truncates to len - 1 characters and a NUL and returns the full length
 * (as snprintf); writes nothing for a NULL buf or len 0; copies "NULL exact solution" for a
 * NULL object. */
START_TEST(test_errmsg_copy)
{
    fricreg_exact *ex = create(2.0, 0.5, 1.0, 0.0, 0.0);
    const char *message = "run: t_end = -2.385 must be > 0"; /* 31 characters */
    ck_assert_int_eq(fricreg_exact_run(ex, -2.385), FRICREG_EINVAL);
    char buf[40];
    memset(buf, '#', sizeof buf);
    ck_assert_uint_eq(fricreg_exact_errmsg_copy(ex, buf, 12), 31);
    ck_assert_str_eq(buf, "run: t_end ");
    ck_assert_int_eq(buf[12], '#');
    ck_assert_uint_eq(fricreg_exact_errmsg_copy(ex, buf, sizeof buf), 31);
    ck_assert_str_eq(buf, message);
    memset(buf, '#', sizeof buf);
    ck_assert_uint_eq(fricreg_exact_errmsg_copy(ex, buf, 0), 0);
    ck_assert_int_eq(buf[0], '#');
    ck_assert_uint_eq(fricreg_exact_errmsg_copy(ex, NULL, 12), 0);
    ck_assert_uint_eq(fricreg_exact_errmsg_copy(NULL, buf, sizeof buf), 19);
    ck_assert_str_eq(buf, "NULL exact solution");
    fricreg_exact_free(ex);
}
END_TEST

/* Header: get_value() and get_stat() ENULL for a NULL object or output, EINVAL for an unknown
 * quantity or counter; the output untouched on failure. */
START_TEST(test_getters_reject_bad_input)
{
    fricreg_exact *ex = solve(2.0, 0.5, 1.0, 0.0, 0.0, 30.0);
    double value = -2.385;
    int64_t count = -7;
    ck_assert_int_eq(fricreg_exact_get_value(NULL, FRICREG_EXACT_VALUE_TIME, &value),
                     FRICREG_ENULL);
    ck_assert_int_eq(fricreg_exact_get_value(ex, FRICREG_EXACT_VALUE_TIME, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_exact_get_stat(NULL, FRICREG_EXACT_STAT_ROOTS, &count), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_exact_get_stat(ex, FRICREG_EXACT_STAT_ROOTS, NULL), FRICREG_ENULL);
    static const int unknown[] = {-1, 2, 3, 1000};
    for (size_t i = 0; i < sizeof unknown / sizeof unknown[0]; i++) {
        int which = unknown[i];
        if (which != 2)
            ck_assert_int_eq(fricreg_exact_get_stat(ex, which, &count), FRICREG_EINVAL);
        ck_assert_int_eq(fricreg_exact_get_value(ex, which, &value), FRICREG_EINVAL);
    }
    ck_assert_double_eq(value, -2.385);
    ck_assert_int_eq(count, -7);
    ck_assert_double_eq(get_value(ex, FRICREG_EXACT_VALUE_TIME), 30.0);
    fricreg_exact_free(ex);
}
END_TEST

/* ENOMEM, by failing the allocation itself. create(): its calloc fails, *out untouched. run():
 * the phase list grows by doubling from 64, so in a run of 64 switches (65 phases; the long
 * no-stick case of test_counters_follow_the_scan_grid) its second realloc, at phase 64, fails;
 * the message gives the phase and its start time, the 64th switch; the earlier solution stays;
 * the same run succeeds once memory is back. */
START_TEST(test_out_of_memory)
{
#if CAN_FAIL_ALLOCATION
    fricreg_exact *ex = SENTINEL;
    calloc_fails_in = 0;
    int status = fricreg_exact_create(0.3, 1.0, 0.1, 1.2, 0.0, &ex);
    calloc_fails_in = -1;
    ck_assert_int_eq(status, FRICREG_ENOMEM);
    ck_assert_ptr_eq(ex, SENTINEL);

    ex = create(0.3, 1.0, 0.1, 1.2, 0.0);
    ck_assert_int_eq(fricreg_exact_run(ex, 200.0), FRICREG_OK);
    struct switches sw = get_switches(ex);
    ck_assert_uint_eq(sw.n, 64);
    char expected[128];
    snprintf(expected, sizeof expected, "run: out of memory at phase 64, t = %.17g", sw.t[63]);
    ck_assert_int_eq(fricreg_exact_run(ex, 30.0), FRICREG_OK);
    size_t switches_30 = fricreg_exact_nswitches(ex);

    realloc_fails_in = 1;
    status = fricreg_exact_run(ex, 200.0);
    realloc_fails_in = -1;
    ck_assert_int_eq(status, FRICREG_ENOMEM);
    ck_assert_int_eq(fricreg_exact_errcode(ex), FRICREG_ENOMEM);
    ck_assert_str_eq(fricreg_exact_errmsg(ex), expected);
    ck_assert_double_eq(get_value(ex, FRICREG_EXACT_VALUE_TIME), 30.0);
    ck_assert_uint_eq(fricreg_exact_nswitches(ex), switches_30);

    ck_assert_int_eq(fricreg_exact_run(ex, 200.0), FRICREG_OK);
    ck_assert_uint_eq(fricreg_exact_nswitches(ex), 64);
    free_switches(&sw);
    fricreg_exact_free(ex);
#endif
}
END_TEST

static Suite *exact_suite(void)
{
    Suite *s = suite_create("exact");
    TCase *unforced = tcase_create("unforced");
    tcase_add_test(unforced, test_unforced_paper_case);
    tcase_add_loop_test(unforced, test_unforced_half_cycles_by_hand, 0, 4);
    tcase_add_test(unforced, test_unforced_initial_velocity);
    suite_add_tcase(s, unforced);

    /* Starts and stops on |f_eq| = mun. A failure here can be a hang that eats memory
     * (~30 MB/s): cut it short. */
    TCase *bound = tcase_create("on_the_bound");
    tcase_set_timeout(bound, 5.0);
    tcase_add_loop_test(bound, test_rest_on_the_friction_bound, 0, 4);
    tcase_add_loop_test(bound, test_frictionless_forced, 0, 2);
    tcase_add_loop_test(bound, test_breakaway_at_start, 0, 2);
    suite_add_tcase(s, bound);

    TCase *energy = tcase_create("energy_balance");
    tcase_add_test(energy, test_stick_slip_energy_balance);
    tcase_add_loop_test(energy, test_energy_balance_other_regimes, 0, 4);
    suite_add_tcase(s, energy);

    TCase *resonance = tcase_create("resonance");
    tcase_add_test(resonance, test_resonance_amplitude_growth);
    tcase_add_test(resonance, test_resonance_from_rest);
    suite_add_tcase(s, resonance);

    TCase *switching = tcase_create("switching");
    tcase_add_loop_test(switching, test_switching_conditions, 0,
                        (int)(sizeof regimes / sizeof regimes[0]));
    tcase_add_loop_test(switching, test_closed_form_satisfies_equation_5, 0, 6);
    tcase_add_test(switching, test_no_stick_case_two_reversals_per_cycle);
    suite_add_tcase(s, switching);

    /* Simulations at small dt against the exact solution (4 s): the release tier's
     * (exact_release); the quick tier checks the solution against its closed forms above. */
    TCase *brute = tcase_create("brute_force");
    tcase_set_tags(brute, "release");
    tcase_add_test(brute, test_quinn_converges_to_exact_as_dt_squared);
    tcase_add_test(brute, test_coulomb_converges_to_exact);
    tcase_add_test(brute, test_stick_fraction_matches_simulation);
    suite_add_tcase(s, brute);

    TCase *errors = tcase_create("errors");
    tcase_add_test(errors, test_solve_rejects_bad_input);
    tcase_add_test(errors, test_state_rejects_bad_input);
    tcase_add_test(errors, test_arrays_reject_wrong_size);
    tcase_add_test(errors, test_stick_fraction_rejects_bad_interval);
    suite_add_tcase(s, errors);

    TCase *object = tcase_create("object");
    tcase_add_loop_test(object, test_create_run_equals_solve, 0, 4);
    tcase_add_test(object, test_before_a_run);
    tcase_add_test(object, test_run_replaces_solution);
    tcase_add_loop_test(object, test_counters_follow_the_scan_grid, 0, 4);
    tcase_add_test(object, test_create_rejects_bad_input);
    tcase_add_test(object, test_run_messages);
    tcase_add_test(object, test_errmsg_copy);
    tcase_add_test(object, test_getters_reject_bad_input);
    tcase_add_test(object, test_out_of_memory);
    suite_add_tcase(s, object);

    /* Runs up to the work limits (5 s): the release tier's (exact_release) */
    TCase *work = tcase_create("work");
    tcase_set_timeout(work, 300.0); /* 2e6 switches: ~3 s alone, the machine may be shared */
    tcase_set_tags(work, "release");
    tcase_add_test(work, test_work_is_bounded_slow_forcing);
    tcase_add_test(work, test_work_is_bounded_fast_forcing);
    tcase_add_test(work, test_work_is_bounded_cycle_cap);
    suite_add_tcase(s, work);
    return s;
}

int main(void)
{
    gsl_set_error_handler_off(); /* qag reports through its status, asserted in the test */
    SRunner *sr = srunner_create(exact_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
