/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_central_imex.c — FRICREG_INT_CENTRAL_IMEX: central differences with law (4) implicit at
 * the step's end (src/sim/central_imex.c), and its guard (src/ode/step_guard.c, check_central_imex).
 *
 * Expected values:
 *   - order: the oscillator a = 2, omega = 0.5 (it sticks twice a cycle), eps = 4 dt, D of
 *     cycle 1 against the exact Coulomb solution (fricreg_exact.h): law (4)'s error is c eps^2
 *     there and the scheme's c' dt^2, so the observed order log2(e_k/e_{k+1}) must lie within
 *     0.2 of 2 on the last three halvings (measured 2.00, 2.00, 2.03, 2.00; 2.6e-6 at
 *     dt = 0.000625, where FRICREG_INT_CENTRAL gives 3.1e-6);
 *   - eps free of dt: eps = dt, which FRICREG_INT_CENTRAL refuses (dt lambda = 2 > 0.9), runs,
 *     and its error falls from dt = 0.01 to 0.000625 by more than 64 (second order overall
 *     would be 256; measured 245, to 6.1e-7): a bound of 1e-6 at the finest step;
 *   - (the chain against classical RK4, one right-hand side per step: test_central.c, for both
 *     central steps);
 *   - without friction (mun = 0) the scheme is FRICREG_INT_CENTRAL's: the same state, bit for
 *     bit;
 *   - a stick holds: the unforced oscillator (x0 = 2.75, mun = 1) comes to rest at
 *     x = -(2.75 - 2) = -0.75 after half a period (Coulomb: each half swing loses 2 mun); at
 *     dt = 0.01 and eps = 0.001 (dt lambda = 20, refused by FRICREG_INT_CENTRAL) it rests
 *     within 5 dt^2 of it (measured 1.0e-4) and does not move from cycle 2 to cycle 8; its
 *     near-stick fraction of a cycle at rest is 1 exactly (the summed steps passed the
 *     cycle's length by rounding: 1.000000000000007 before fricreg_sim clamped it);
 *   - the guard: (dt omega/2)^2 < 0.9 whatever eps while law (4)'s band is resolved
 *     (dt lambda < 0.9): accepted at 0.99 and refused (FRICREG_ESTEP, before any step) at 1.01
 *     of dt = 2 sqrt(0.9)/omega on the chain n = 32 (omega = 64); where the band is not
 *     resolved, dt omega <= 1/sqrt 2 as well, with the eps to raise to in the message; a
 *     stick-zone slope 2 mun/eps beyond the double range is refused (mun = 1e300);
 *   - refusals (FRICREG_EINVAL before any step): a law other than (4), the two blocks; a
 *     structure's GSL driver refuses it as it refuses FRICREG_INT_CENTRAL. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "fricreg_exact.h"
#include "fricreg_sim.h"
#include "fricreg_structure.h"
#include "sim_runs.h"

#define PI 3.14159265358979323846

/* D of cycle 1 of the oscillator a = 2, omega = 0.5 from x0 = 2.75, exactly. */
static double exact_cycle1(void)
{
    fricreg_exact *ex = NULL;
    ck_assert_int_eq(fricreg_exact_solve(2.0, 0.5, 1.0, 2.75, 0.0, 8.0 * PI, &ex), FRICREG_OK);
    double D[2] = {0.0, 0.0};
    ck_assert_int_eq(fricreg_exact_dissipation(ex, 2, D), FRICREG_OK);
    fricreg_exact_free(ex);
    return D[0];
}

enum { LEVELS = 5 };

/* |D - D_exact| of cycle 1 at dt = 0.01 by halves, eps = eps_per_dt * dt, printed. */
static void errors_by_halves(double eps_per_dt, double err[LEVELS])
{
    double D_exact = exact_cycle1(), dt = 0.01;
    for (int k = 0; k < LEVELS; k++, dt /= 2.0) {
        fricreg_sim *sim = sim_runs_sticking_oscillator(FRICREG_INT_CENTRAL_IMEX, dt,
                                                        eps_per_dt * dt);
        double D = 0.0;
        ck_assert_int_eq(sim_runs_dissipation(sim, 1, &D), FRICREG_OK);
        err[k] = fabs(D - D_exact);
        fricreg_sim_free(sim);
    }
    printf("central-imex, oscillator a = 2, omega = 0.5, eps = %g dt: |D - D_exact| of cycle 1 "
           "from dt = 0.01 by halves:",
           eps_per_dt);
    for (int k = 0; k < LEVELS; k++)
        printf(" %.3g", err[k]);
    printf("; observed order:");
    for (int k = 0; k + 1 < LEVELS; k++)
        printf(" %.3f", log2(err[k] / err[k + 1]));
    printf("\n");
}

START_TEST(oscillator_second_order_against_exact)
{
    double err[LEVELS];
    errors_by_halves(4.0, err);
    for (int k = LEVELS - 4; k + 1 < LEVELS; k++)
        ck_assert_double_eq_tol(log2(err[k] / err[k + 1]), 2.0, 0.2);
    ck_assert_double_lt(err[LEVELS - 1], 5e-6);
}
END_TEST

START_TEST(eps_free_of_dt)
{
    /* eps = dt: the explicit step's stick zone refuses it (dt lambda = 2 mun/1 = 2 > 0.9) */
    fricreg_sim *sim = sim_runs_sticking_oscillator(FRICREG_INT_CENTRAL, 0.01, 0.01);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 1), FRICREG_ESTEP);
    fricreg_sim_free(sim);
    double err[LEVELS];
    errors_by_halves(1.0, err);
    ck_assert_double_lt(err[LEVELS - 1], 1e-6);
    ck_assert_double_gt(err[0] / err[LEVELS - 1], 64.0);
}
END_TEST

START_TEST(frictionless_is_the_explicit_scheme)
{
    double x[2], v[2];
    const int integrators[2] = {FRICREG_INT_CENTRAL, FRICREG_INT_CENTRAL_IMEX};
    for (int k = 0; k < 2; k++) {
        fricreg_sim *sim = sim_runs_sticking_oscillator(integrators[k], 0.01, 0.04);
        ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_MUN, 0.0), FRICREG_OK);
        ck_assert_int_eq(fricreg_sim_run_cycles(sim, 2), FRICREG_OK);
        ck_assert_int_eq(fricreg_sim_get_state(sim, 1, &x[k], &v[k]), FRICREG_OK);
        double D[2];
        ck_assert_int_eq(fricreg_sim_get_dissipation(sim, 2, D), FRICREG_OK);
        ck_assert_double_eq(D[1], 0.0);
        fricreg_sim_free(sim);
    }
    ck_assert_double_ne(x[0], 2.75); /* it moved */
    ck_assert_double_eq(x[1], x[0]);
    ck_assert_double_eq(v[1], v[0]);
}
END_TEST

START_TEST(stick_holds_with_eps_below_dt)
{
    fricreg_sim *sim = sim_runs_make(FRICREG_SYSTEM_OSCILLATOR, FRICREG_INT_CENTRAL, 0.01, 0.001);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 1), FRICREG_ESTEP); /* dt lambda = 20 */
    fricreg_sim_free(sim);
    double x[2], v = 0.0;
    const int cycles[2] = {2, 8};
    for (int k = 0; k < 2; k++) {
        sim = sim_runs_make(FRICREG_SYSTEM_OSCILLATOR, FRICREG_INT_CENTRAL_IMEX, 0.01, 0.001);
        ck_assert_int_eq(fricreg_sim_run_cycles(sim, cycles[k]), FRICREG_OK);
        ck_assert_int_eq(fricreg_sim_get_state(sim, 1, &x[k], &v), FRICREG_OK);
        double frac = 0.0; /* the last cycle at rest throughout: 1, not 1 + rounding */
        ck_assert_int_eq(fricreg_sim_get_stick_fraction(sim, 1, &frac), FRICREG_OK);
        ck_assert_double_eq(frac, 1.0);
        fricreg_sim_free(sim);
    }
    printf("central-imex, unforced oscillator, dt = 0.01, eps = 0.001: at rest at x = %.17g "
           "after 2 cycles, %.17g after 8\n",
           x[0], x[1]);
    ck_assert_double_eq_tol(x[0], -0.75, 5.0 * 0.01 * 0.01);
    ck_assert_double_eq(x[1], x[0]);
}
END_TEST

/* The chain n = 32 (omega = 64) at dt with eps; FRICREG_ESTEP leaves time 0. */
static int chain_run(double dt, double eps, char msg[], size_t len)
{
    fricreg_sim *sim = sim_runs_make(FRICREG_SYSTEM_CHAIN, FRICREG_INT_CENTRAL_IMEX, dt, eps);
    int status = fricreg_sim_run_cycles(sim, 1);
    double t = -1.0;
    ck_assert_int_eq(fricreg_sim_get_value(sim, FRICREG_VALUE_TIME, &t), FRICREG_OK);
    if (status == FRICREG_ESTEP)
        ck_assert_double_eq(t, 0.0);
    snprintf(msg, len, "%s", fricreg_sim_errmsg(sim));
    fricreg_sim_free(sim);
    return status;
}

START_TEST(guard_springs_and_reversal)
{
    char msg[512];
    /* the springs: dt_max = 2 sqrt(0.9)/64, with eps = 0.5 (dt lambda = 0.12, resolved) and
     * with eps = 0.1 dt_max (dt lambda = 20: the reversal bound then refuses it as well) */
    double bound = 2.0 * sqrt(0.9) / 64.0;
    ck_assert_int_eq(chain_run(0.99 * bound, 0.5, msg, sizeof msg), FRICREG_OK);
    ck_assert_int_eq(chain_run(1.01 * bound, 0.5, msg, sizeof msg), FRICREG_ESTEP);
    ck_assert_ptr_nonnull(strstr(msg, "(dt*omega/2)^2"));
    /* the reversal: dt = 0.02 (dt omega = 1.28 > 1/sqrt 2); eps = 0.04 gives dt lambda =
     * 2 dt/eps = 1 >= 0.9, refused with eps to raise to 2 dt/0.9 = 0.0444; just above, run */
    ck_assert_int_eq(chain_run(0.02, 0.04, msg, sizeof msg), FRICREG_ESTEP);
    ck_assert_ptr_nonnull(strstr(msg, "raise eps to 0.0444"));
    ck_assert_int_eq(chain_run(0.02, 0.0445, msg, sizeof msg), FRICREG_OK);
    /* unresolved but within the reversal bound: dt omega = 0.7, eps = 1e-6 */
    ck_assert_int_eq(chain_run(0.7 / 64.0, 1e-6, msg, sizeof msg), FRICREG_OK);
    /* a stick-zone slope 2 mun/eps beyond the double range: refused, not run into NaN */
    fricreg_sim *sim = sim_runs_make(FRICREG_SYSTEM_OSCILLATOR, FRICREG_INT_CENTRAL_IMEX, 0.01,
                                     1e-9);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_MUN, 1e300), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 1), FRICREG_ESTEP);
    ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "beyond the double range"));
    fricreg_sim_free(sim);
}
END_TEST

START_TEST(refusals)
{
    /* a law other than (4) */
    fricreg_sim *sim = sim_runs_make(FRICREG_SYSTEM_OSCILLATOR, FRICREG_INT_CENTRAL_IMEX, 0.01,
                                     0.04);
    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_TANH, 0.04), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 1), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "law (4)"));
    double t = -1.0;
    ck_assert_int_eq(fricreg_sim_get_value(sim, FRICREG_VALUE_TIME, &t), FRICREG_OK);
    ck_assert_double_eq(t, 0.0);
    fricreg_sim_free(sim);
    /* the two blocks: their contacts are not the bodies (z2 = x2 - x1) */
    sim = sim_runs_make(FRICREG_SYSTEM_TWOBLOCK, FRICREG_INT_CENTRAL_IMEX, 0.001, 0.01);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 1), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "bodies"));
    fricreg_sim_free(sim);
    /* fixed steps only */
    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_CHAIN, &sim), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_CENTRAL_IMEX, 0.01, 1e-6, 0.0),
                     FRICREG_EINVAL);
    fricreg_sim_free(sim);
    /* a structure's GSL driver */
    fricreg_structure *s = NULL;
    ck_assert_int_eq(fricreg_structure_create(1, 1, &s), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_CENTRAL_IMEX, 0.01, 0.0, 0.0, 1.0),
                     FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_structure_errmsg(s), "central-imex"));
    fricreg_structure_free(s);
    /* the name */
    ck_assert_str_eq(fricreg_integrator_name(FRICREG_INT_CENTRAL_IMEX), "central-imex");
    ck_assert_int_eq(fricreg_integrator_from_name("central-imex"), FRICREG_INT_CENTRAL_IMEX);
}
END_TEST

int main(void)
{
    Suite *suite = suite_create("central_imex");
    TCase *tc = tcase_create("central_imex");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, oscillator_second_order_against_exact);
    tcase_add_test(tc, eps_free_of_dt);
    tcase_add_test(tc, frictionless_is_the_explicit_scheme);
    tcase_add_test(tc, stick_holds_with_eps_below_dt);
    tcase_add_test(tc, guard_springs_and_reversal);
    tcase_add_test(tc, refusals);
    suite_add_tcase(suite, tc);
    SRunner *runner = srunner_create(suite);
    srunner_run_all(runner, CK_NORMAL);
    int failed = srunner_ntests_failed(runner);
    srunner_free(runner);
    return failed == 0 ? 0 : 1;
}
