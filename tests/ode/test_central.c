/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_central.c — FRICREG_INT_CENTRAL, explicit central differences in fricreg_sim
 * (src/sim/central_step.c), and its step guard (src/ode/step_guard.c, check_central).
 *
 * Expected values:
 *   - order: the oscillator a = 2, omega = 0.5 (it sticks twice a cycle), eps = 4 dt, D of
 *     cycle 1 against the exact Coulomb solution (fricreg_exact.h): law (4)'s error is c eps^2
 *     there (fricreg_sim.h, extrapolation) and the scheme's c' dt^2, so the error falls by 4
 *     per halving of dt: the observed order log2(e_k/e_{k+1}) is printed and must lie within
 *     0.2 of 2 on the last three halvings (measured 2.00, 2.00, 2.02; 3.1e-6 at dt = 0.000625);
 *   - the chain (n = 32, eps = 0.01): D per cycle equal to classical RK4's at dt = 0.00025 (its
 *     own error ~1e-9 relative: RK4 at 0.0005 differs by 1e-9) to 1e-5 relative at
 *     dt = 0.0005 (measured 4.6e-6; FRICREG_INT_CENTRAL_IMEX, checked alike, 6.1e-6), and
 *     falling at about second order from dt = 0.002;
 *   - the two blocks (eps = 0.01): D per cycle within 1e-6 relative of RK4's at dt = 0.00025
 *     at dt = 0.0005 (measured 1.3e-7);
 *   - one right-hand side per step, plus one at t = 0;
 *   - the near-stick fractions, which the step itself accumulates where the contacts are the
 *     bodies (central_step.c's fused last pass), equal to 1e-12 those an observer sums from
 *     the states after each step (|v_i| < eps times the step), on the chain over one cycle;
 *   - the guard (dt omega/2)^2 + dt lambda < 0.9 (the linear bound 1 with a margin), omega
 *     the highest frequency and lambda the stick-zone stiffness, which gives
 *     dt_max = 1.8/(lambda + sqrt(lambda^2 + 0.9 omega^2)) for a set eps: accepted at
 *     0.99 dt_max, D within 0.1% of a run at dt_max/16 on the oscillator, whose stick zone
 *     sets it, and within 1% on the chain (a = 5, eps = 0.5), whose springs do (measured 0.07%
 *     at dt omega = 1.76); FRICREG_ESTEP at 1.01 dt_max before any step; beyond it (the
 *     internal unguarded flag) the frictionless oscillator diverges (FRICREG_EDIVERGED) at
 *     dt omega = 2.1 and stays bounded at 1.98 (32 steps a cycle);
 *   - bad input: adaptive tolerances refused (FRICREG_EINVAL, the settings kept), the paper's
 *     eps = 2 dt for the oscillator refused at every dt with the eps to set, and
 *     fricreg_structure_run_ode refuses it. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "fricreg_exact.h"
#include "fricreg_sim.h"
#include "fricreg_structure.h"
#include "sim_runs.h"
#include "sim/sim_internal.h"

START_TEST(oscillator_second_order_against_exact)
{
    fricreg_exact *ex = NULL;
    ck_assert_int_eq(fricreg_exact_solve(2.0, 0.5, 1.0, 2.75, 0.0, 8.0 * 3.14159265358979323846,
                                         &ex),
                     FRICREG_OK);
    double D_exact[2] = {0.0, 0.0};
    ck_assert_uint_eq(fricreg_exact_ncycles(ex), 2);
    ck_assert_int_eq(fricreg_exact_dissipation(ex, 2, D_exact), FRICREG_OK);
    fricreg_exact_free(ex);

    enum { LEVELS = 5 };
    double err[LEVELS], dt = 0.01;
    for (int k = 0; k < LEVELS; k++, dt /= 2.0) {
        fricreg_sim *sim = sim_runs_sticking_oscillator(FRICREG_INT_CENTRAL, dt, 4.0 * dt);
        double D = 0.0;
        ck_assert_int_eq(sim_runs_dissipation(sim, 1, &D), FRICREG_OK);
        err[k] = fabs(D - D_exact[0]);
        fricreg_sim_free(sim);
    }
    printf("central, oscillator a = 2, omega = 0.5, eps = 4 dt: |D - D_exact| of cycle 1 from "
           "dt = 0.01 by halves:");
    for (int k = 0; k < LEVELS; k++)
        printf(" %.3g", err[k]);
    printf("; observed order:");
    for (int k = 0; k + 1 < LEVELS; k++)
        printf(" %.3f", log2(err[k] / err[k + 1]));
    printf("\n");
    for (int k = LEVELS - 4; k + 1 < LEVELS; k++)
        ck_assert_double_eq_tol(log2(err[k] / err[k + 1]), 2.0, 0.2);
    ck_assert_double_lt(err[LEVELS - 1], 5e-6);
}
END_TEST

/* The chain by `integrator` at dt = 0.002, 0.001, 0.0005 against rk4's D per cycle ref[2]. */
static void chain_against_rk4(int integrator, const double ref[2])
{
    double rel[3], dt = 0.002, D[2];
    for (int k = 0; k < 3; k++, dt /= 2.0) {
        fricreg_sim *sim = sim_runs_make(FRICREG_SYSTEM_CHAIN, integrator, dt, 0.01);
        ck_assert_int_eq(sim_runs_dissipation(sim, 2, D), FRICREG_OK);
        rel[k] = fmax(fabs(D[0] / ref[0] - 1.0), fabs(D[1] / ref[1] - 1.0));
        int64_t steps = 0, rhs = 0;
        ck_assert_int_eq(fricreg_sim_get_stat(sim, FRICREG_SIM_STAT_STEPS, &steps), FRICREG_OK);
        ck_assert_int_eq(fricreg_sim_get_stat(sim, FRICREG_SIM_STAT_RHS_EVALS, &rhs), FRICREG_OK);
        ck_assert_int_eq(rhs, steps + 1); /* one friction evaluation per step */
        fricreg_sim_free(sim);
    }
    printf("%s, chain n = 32, eps = 0.01: D per cycle against rk4 at dt = 0.00025, relative "
           "%.3g, %.3g, %.3g at dt = 0.002, 0.001, 0.0005\n",
           fricreg_integrator_name(integrator), rel[0], rel[1], rel[2]);
    ck_assert_double_lt(rel[2], 1e-5);
    ck_assert_double_gt(rel[0] / rel[2], 8.0); /* second order: 16 over two halvings */
}

START_TEST(chain_equals_rk4_at_a_fine_step)
{
    double ref[2], D[2];
    fricreg_sim *sim = sim_runs_make(FRICREG_SYSTEM_CHAIN, FRICREG_INT_RK4, 0.00025, 0.01);
    ck_assert_int_eq(sim_runs_dissipation(sim, 2, ref), FRICREG_OK);
    fricreg_sim_free(sim);
    chain_against_rk4(FRICREG_INT_CENTRAL, ref);
    chain_against_rk4(FRICREG_INT_CENTRAL_IMEX, ref); /* law (4) implicit (central_imex.c) */

    /* the two blocks (coupled W), eps = 0.01: central at dt = 0.0005 against rk4 at 0.00025 */
    sim = sim_runs_make(FRICREG_SYSTEM_TWOBLOCK, FRICREG_INT_RK4, 0.00025, 0.01);
    ck_assert_int_eq(sim_runs_dissipation(sim, 2, ref), FRICREG_OK);
    fricreg_sim_free(sim);
    sim = sim_runs_make(FRICREG_SYSTEM_TWOBLOCK, FRICREG_INT_CENTRAL, 0.0005, 0.01);
    ck_assert_int_eq(sim_runs_dissipation(sim, 2, D), FRICREG_OK);
    fricreg_sim_free(sim);
    double rel2 = fmax(fabs(D[0] / ref[0] - 1.0), fabs(D[1] / ref[1] - 1.0));
    printf("central, two blocks, eps = 0.01, dt = 0.0005: D per cycle against rk4, relative "
           "%.3g\n",
           rel2);
    ck_assert_double_lt(rel2, 1e-6); /* measured 1.3e-7 */
}
END_TEST

/* Near-stick time per contact summed from the states the observer sees after each step. */
struct stick_watch {
    double eps, t_last, time[32];
};

static int watch_stick(void *user, double t, size_t ndof, const double x[], const double v[],
                       size_t m, const double f[], const double f_eq[])
{
    (void)ndof, (void)x, (void)f, (void)f_eq;
    struct stick_watch *w = user;
    for (size_t i = 0; i < m && i < 32; i++)
        w->time[i] += fabs(v[i]) < w->eps ? t - w->t_last : 0.0;
    w->t_last = t;
    return 0;
}

START_TEST(chain_stick_fraction_equals_the_observers)
{
    struct stick_watch w = {.eps = 0.01};
    fricreg_sim *sim = sim_runs_make(FRICREG_SYSTEM_CHAIN, FRICREG_INT_CENTRAL, 0.001, w.eps);
    ck_assert_int_eq(fricreg_sim_set_observer(sim, watch_stick, &w), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 1), FRICREG_OK);
    double frac[32], T = 4.0 * 3.14159265358979323846, sticking = 0.0; /* omega = 0.5 */
    ck_assert_int_eq(fricreg_sim_get_stick_fraction(sim, 32, frac), FRICREG_OK);
    for (size_t i = 0; i < 32; i++) {
        ck_assert_double_eq_tol(frac[i], w.time[i] / T, 1e-12);
        sticking += frac[i];
    }
    ck_assert_double_gt(sticking, 1.0); /* the blocks do stick: the check is not 0 = 0 */
    fricreg_sim_free(sim);
}
END_TEST

/* dt_max of the guard for a set eps: (omega dt/2)^2 + lambda dt = 0.9. */
static double dt_max(double lambda, double omega)
{
    return 1.8 / (lambda + sqrt(lambda * lambda + 0.9 * omega * omega));
}

/* The chain is driven hard (a = 5: its blocks slip at |v| >> eps), so that its springs, not
 * the stick zone's screening of them by f_eq, set the motion at its highest frequency. */
static int run_at(int system, double n, double dt, double eps, int guarded, double *D)
{
    fricreg_sim *sim = sim_runs_make(system, FRICREG_INT_CENTRAL, dt, eps);
    if (system == FRICREG_SYSTEM_CHAIN) {
        ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_N, n), FRICREG_OK);
        ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_A, 5.0), FRICREG_OK);
    }
    sim->unguarded = !guarded;
    int status = sim_runs_dissipation(sim, 1, D);
    if (status == FRICREG_ESTEP) { /* refused before any step */
        double t = -1.0;
        ck_assert_int_eq(fricreg_sim_get_value(sim, FRICREG_VALUE_TIME, &t), FRICREG_OK);
        ck_assert_double_eq(t, 0.0);
        ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "central differences"));
    }
    fricreg_sim_free(sim);
    return status;
}

START_TEST(guard_at_and_beyond_the_bound)
{
    /* the oscillator, eps = 0.05: lambda = 2 mun/eps = 40, omega = 1: the stick zone sets it */
    double bound = dt_max(40.0, 1.0), D = 0.0, D_fine = 0.0;
    ck_assert_int_eq(run_at(FRICREG_SYSTEM_OSCILLATOR, 0, 0.99 * bound, 0.05, 1, &D), FRICREG_OK);
    ck_assert_int_eq(run_at(FRICREG_SYSTEM_OSCILLATOR, 0, bound / 16, 0.05, 1, &D_fine),
                     FRICREG_OK);
    ck_assert_double_eq_tol(D, D_fine, 1e-3 * D_fine);
    ck_assert_int_eq(run_at(FRICREG_SYSTEM_OSCILLATOR, 0, 1.01 * bound, 0.05, 1, &D),
                     FRICREG_ESTEP);

    /* the chain n = 32, eps = 0.5: lambda = 4, omega = 2n = 64: its springs set it */
    bound = dt_max(4.0, 64.0);
    ck_assert_int_eq(run_at(FRICREG_SYSTEM_CHAIN, 32, 0.99 * bound, 0.5, 1, &D), FRICREG_OK);
    ck_assert_int_eq(run_at(FRICREG_SYSTEM_CHAIN, 32, bound / 16, 0.5, 1, &D_fine), FRICREG_OK);
    printf("central, chain n = 32, a = 5, eps = 0.5 at 0.99 dt_max (dt omega = %.3f): D %.6g, "
           "at dt_max/16 %.6g\n",
           0.99 * bound * 64.0, D, D_fine);
    ck_assert_double_eq_tol(D, D_fine, 1e-2 * D_fine);
    ck_assert_int_eq(run_at(FRICREG_SYSTEM_CHAIN, 32, 1.01 * bound, 0.5, 1, &D), FRICREG_ESTEP);

    /* beyond it, unguarded: the chain at 1.05 dt_max does not diverge in 4 cycles (friction on
     * every block holds its top mode); without friction the linear bound dt omega < 2 is
     * sharp: the oscillator with mun = 0 (lambda = 0) grows by 1.88 per step at dt = 2.1 and
     * overflows within 64 cycles, where 1.98 runs them at bounded energy (both refused by the
     * guard's margin, 1.897). The cycle is 32 steps (omega sets it; a = 0), so no step is
     * shortened: with 2 pi cycles, 1.98 grew to 8e26 (src/ode/step_guard.c, FR_CENTRAL_STEP_BOUND). */
    for (int k = 0; k < 2; k++) {
        double step = k ? 2.1 : 1.98;
        fricreg_sim *sim = sim_runs_make(FRICREG_SYSTEM_OSCILLATOR, FRICREG_INT_CENTRAL, step,
                                         0.05);
        ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_MUN, 0.0), FRICREG_OK);
        ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_OMEGA,
                                               2.0 * 3.14159265358979323846 / (32.0 * step)),
                         FRICREG_OK);
        sim->unguarded = 1;
        int status = fricreg_sim_run_cycles(sim, 64);
        ck_assert_int_eq(status, k ? FRICREG_EDIVERGED : FRICREG_OK);
        if (!k) { /* bounded: the scheme's invariant v^2/2 + x^2 (1 - dt^2/4)/2 is kept */
            double x = 0.0, v = 0.0, dt = 1.98;
            ck_assert_int_eq(fricreg_sim_get_state(sim, 1, &x, &v), FRICREG_OK);
            ck_assert_double_le(fabs(x), 2.75 / sqrt(1.0 - dt * dt / 4.0) * (1 + 1e-9));
        }
        sim->unguarded = 0;
        ck_assert_int_eq(fricreg_sim_run_cycles(sim, 1), FRICREG_ESTEP);
        fricreg_sim_free(sim);
    }
}
END_TEST

START_TEST(adaptive_tolerances_refused)
{
    fricreg_sim *sim = sim_runs_make(FRICREG_SYSTEM_OSCILLATOR, FRICREG_INT_RK4, 0.02, 0.0);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_CENTRAL, 0.01, 1e-6, 0.0),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_CENTRAL, 0.01, 0.0, 1e-8),
                     FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "fixed steps only"));
    double dt = 0.0;
    ck_assert_int_eq(fricreg_sim_get_value(sim, FRICREG_VALUE_DT, &dt), FRICREG_OK);
    ck_assert_double_eq(dt, 0.02); /* the settings are kept */
    fricreg_sim_free(sim);

    /* the paper's eps = 2 dt: dt*lambda = 2 mun/2 = 1 at every dt, refused with the eps */
    sim = sim_runs_make(FRICREG_SYSTEM_OSCILLATOR, FRICREG_INT_CENTRAL, 0.01, 0.0);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 1), FRICREG_ESTEP);
    ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "at every dt; set eps >="));
    fricreg_sim_free(sim);

    ck_assert_str_eq(fricreg_integrator_name(FRICREG_INT_CENTRAL), "central");
    ck_assert_int_eq(fricreg_integrator_from_name("central"), FRICREG_INT_CENTRAL);

    /* a structure's GSL driver refuses it: the structure has its own central difference */
    fricreg_structure *s = NULL;
    ck_assert_int_eq(fricreg_structure_create(1, 1, &s), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_CENTRAL, 0.01, 0.0, 0.0, 1.0),
                     FRICREG_EINVAL);
    fricreg_structure_free(s);
}
END_TEST

int main(void)
{
    Suite *suite = suite_create("central");
    TCase *tc = tcase_create("central");
    tcase_add_test(tc, oscillator_second_order_against_exact);
    tcase_add_test(tc, chain_equals_rk4_at_a_fine_step);
    tcase_add_test(tc, chain_stick_fraction_equals_the_observers);
    tcase_add_test(tc, guard_at_and_beyond_the_bound);
    tcase_add_test(tc, adaptive_tolerances_refused);
    suite_add_tcase(suite, tc);
    SRunner *runner = srunner_create(suite);
    srunner_run_all(runner, CK_NORMAL);
    int failed = srunner_ntests_failed(runner);
    srunner_free(runner);
    return failed == 0 ? 0 : 1;
}
