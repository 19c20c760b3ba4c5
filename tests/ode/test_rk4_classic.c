/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_rk4_classic.c — fixed steps of FRICREG_INT_RK4: fricreg's own classical RK4 step type
 * (src/ode/rk4_classic.c), against GSL's rk4 (FRICREG_INT_RK4_GSL).
 *
 * Expected values:
 *   - In the stick zone of (4) the oscillator is the linear decay v' = -lambda v with
 *     x + v/lambda constant (test_integrator.c, "stuck_oscillator"), so each step of
 *     z = lambda dt multiplies v by the classical stability polynomial
 *     R(-z) = 1 - z + z^2/2 - z^3/6 + z^4/24 (any 4-stage 4th-order Runge-Kutta); a run to
 *     2 dt is one call of two steps: R(-z)^2.
 *   - It keeps GSL's rk4 grid (two classical steps per call, a cycle's last call split in
 *     halves), so D per cycle equals GSL rk4's to rounding: asserted to 1e-12 relative.
 *   - It spends exactly 4 right-hand sides per step (GSL's rk4: 6). */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_sim.h"

#define STUCK_EPS 0.02
#define STUCK_LAMBDA (2.0 / STUCK_EPS)
#define STUCK_X0 (-0.5)
#define STUCK_V0 (-STUCK_EPS / 400.0)

static double classical_r(double z)
{
    return 1.0 - z + z * z / 2.0 - z * z * z / 6.0 + z * z * z * z / 24.0;
}

static fricreg_sim *stuck_oscillator(double dt)
{
    fricreg_sim *sim = NULL;
    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_OSCILLATOR, &sim), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_X0, STUCK_X0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_V0, STUCK_V0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, STUCK_EPS), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RK4, dt, 0.0, 0.0), FRICREG_OK);
    return sim;
}

static double value(const fricreg_sim *sim, int which)
{
    double x = NAN;
    ck_assert_int_eq(fricreg_sim_get_value(sim, which, &x), FRICREG_OK);
    return x;
}

static const double Z[] = {0.3125, 1.7, 2.385, 2.78};

START_TEST(one_step_is_the_classical_polynomial)
{
    double z = Z[_i], dt = z / STUCK_LAMBDA, x, v;
    fricreg_sim *sim = stuck_oscillator(dt);
    ck_assert_int_eq(fricreg_sim_run(sim, 2.0 * dt), FRICREG_OK);
    ck_assert_double_eq(value(sim, FRICREG_VALUE_STEPS), 2.0);
    ck_assert_double_eq(value(sim, FRICREG_VALUE_RHS_EVALS), 8.0);
    ck_assert_int_eq(fricreg_sim_get_state(sim, 1, &x, &v), FRICREG_OK);
    ck_assert_double_eq_tol(v / STUCK_V0, classical_r(z) * classical_r(z), 1e-12);
    ck_assert_double_eq_tol(x + v / STUCK_LAMBDA, STUCK_X0 + STUCK_V0 / STUCK_LAMBDA, 1e-15);
    fricreg_sim_free(sim);
}
END_TEST

/* The guard uses the classical bounds: 2.78 per step on the real axis. */
START_TEST(guard_uses_the_classical_bound)
{
    fricreg_sim *sim = stuck_oscillator(1.001 * 2.78 / STUCK_LAMBDA);
    ck_assert_int_eq(fricreg_sim_run(sim, 1.0), FRICREG_ESTEP);
    fricreg_sim_free(sim);
}
END_TEST

START_TEST(names)
{
    ck_assert_str_eq(fricreg_integrator_name(FRICREG_INT_RK4), "rk4");
    ck_assert_str_eq(fricreg_integrator_name(FRICREG_INT_RK4_GSL), "rk4-gsl");
    ck_assert_int_eq(fricreg_integrator_from_name("rk4-gsl"), FRICREG_INT_RK4_GSL);
}
END_TEST

/* The paper's chain (n = 32, dt = 0.01), 4 cycles, with each RK4. */
static void chain_dissipation(int integrator, double D[4], double *rhs_per_step)
{
    fricreg_sim *sim = NULL;
    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_CHAIN, &sim), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, integrator, 0.01, 0.0, 0.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 4), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_dissipation(sim, 4, D), FRICREG_OK);
    *rhs_per_step = value(sim, FRICREG_VALUE_RHS_EVALS) / value(sim, FRICREG_VALUE_STEPS);
    fricreg_sim_free(sim);
}

START_TEST(chain_matches_gsl_rk4_for_two_thirds_of_the_work)
{
    double D_gsl[4], D_classic[4], per_step_gsl, per_step_classic;
    chain_dissipation(FRICREG_INT_RK4_GSL, D_gsl, &per_step_gsl);
    chain_dissipation(FRICREG_INT_RK4, D_classic, &per_step_classic);
    for (int k = 0; k < 4; k++)
        ck_assert_double_eq_tol(D_classic[k], D_gsl[k], 1e-12 * D_gsl[k]);
    ck_assert_double_eq_tol(D_classic[3], 0.0105, 0.001 * 0.0105); /* the paper's Fig. 9 */
    ck_assert_double_eq(per_step_classic, 4.0);
    ck_assert_double_eq(per_step_gsl, 6.0);
}
END_TEST

static Suite *rk4_classic_suite(void)
{
    Suite *s = suite_create("rk4_classic");
    TCase *tc = tcase_create("rk4_classic");
    tcase_add_loop_test(tc, one_step_is_the_classical_polynomial, 0, (int)(sizeof Z / sizeof Z[0]));
    tcase_add_test(tc, guard_uses_the_classical_bound);
    tcase_add_test(tc, names);
    tcase_add_test(tc, chain_matches_gsl_rk4_for_two_thirds_of_the_work);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(rk4_classic_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
