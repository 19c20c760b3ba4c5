/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_chain.c — the n-dof chain of Sec. 3.2 (Fig. 8) driven through fricreg_sim.
 *
 * Paper defaults: n = 32 blocks, G(t) = a sin(omega t) with a = 0.25, omega = 0.5 (period 4 pi),
 * zero initial conditions, eps = 10 omega dt, fixed-step classical RK4; D is measured on the
 * 4th cycle (spec/paper.md, "Reference system 2"). */
#include <check.h>
#include <math.h>
#include <stdlib.h>

#include "fricreg_sim.h"

#define PI 3.14159265358979323846

static double value(const fricreg_sim *sim, int which)
{
    double out = NAN;
    ck_assert_int_eq(fricreg_sim_get_value(sim, which, &out), FRICREG_OK);
    return out;
}

/* A chain with the paper's parameters, law `law` (eps by the paper's rule) and RK4 step dt,
 * run for 4 cycles. */
static fricreg_sim *chain_run(int law, double dt)
{
    fricreg_sim *sim = NULL;
    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_CHAIN, &sim), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_law(sim, law, 0.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RK4, dt, 0.0, 0.0), FRICREG_OK);
    int status = fricreg_sim_run_cycles(sim, 4);
    ck_assert_msg(status == FRICREG_OK, "law %d dt %g: status %d (%s)", law, dt, status,
                  fricreg_sim_errmsg(sim));
    return sim;
}

/* D on the 4th cycle of law `law` at step dt. */
static double fourth_cycle_D(int law, double dt)
{
    fricreg_sim *sim = chain_run(law, dt);
    double D[4];
    ck_assert_double_eq(value(sim, FRICREG_VALUE_CYCLES), 4.0);
    ck_assert_int_eq(fricreg_sim_get_dissipation(sim, 4, D), FRICREG_OK);
    fricreg_sim_free(sim);
    return D[3];
}

/* The defaults are the paper's: n = 32 bodies and contacts, period 2 pi/0.5 = 4 pi, and
 * eps = 10 omega dt = 0.05 at dt = 0.01. */
START_TEST(test_defaults_are_the_papers)
{
    fricreg_sim *sim = NULL;
    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_CHAIN, &sim), FRICREG_OK);
    ck_assert_uint_eq(fricreg_sim_ndof(sim), 32);
    ck_assert_uint_eq(fricreg_sim_ncontacts(sim), 32);
    ck_assert_double_eq_tol(value(sim, FRICREG_VALUE_PERIOD), 4.0 * PI, 1e-14);
    ck_assert_double_eq_tol(value(sim, FRICREG_VALUE_DT), 0.01, 1e-17);
    ck_assert_double_eq_tol(value(sim, FRICREG_VALUE_EPS), 0.05, 1e-16);
    fricreg_sim_free(sim);
}
END_TEST

/* Paper Fig. 9: law (4) at dt = 0.01 gives D = 0.0105 (within 1%); the continuum quasi-static
 * micro-slip loop of the bar gives D = 2 a^3/3 = 0.010417 at a = 0.25 (within 2%: n = 32
 * blocks and inertia). */
START_TEST(test_quinn_fourth_cycle_D_matches_fig9)
{
    const double a = 0.25;
    double D4 = fourth_cycle_D(FRICREG_LAW_QUINN, 0.01);
    ck_assert_double_eq_tol(D4, 0.0105, 0.01 * 0.0105);
    ck_assert_double_eq_tol(D4, 2.0 * a * a * a / 3.0, 0.02 * 2.0 * a * a * a / 3.0);
}
END_TEST

/* Cost model of fixed-step RK4. fricreg's RK4 step dt keeps GSL rk4's grid: one call of 2 dt
 * returns two classical steps of dt. GSL's rk4 (FRICREG_INT_RK4_GSL) also takes a full step of
 * 2 dt for its step-doubling error estimate: evaluations k1 (1), full step (3), first half step
 * reusing k1 (3), k1 at the midpoint (1), second half step (3), dydt_out at the end (1) = 12 per
 * call. fricreg's own step type (FRICREG_INT_RK4 in fixed steps, src/ode/rk4_classic.c) needs the
 * two classical steps only: 8. Each cycle of T = 4 pi takes ceil(T/(2 dt)) = ceil(628.32) = 629
 * calls, the last one shortened to end on the boundary and still counted as 2 steps. 4 cycles:
 * STEPS = 4*629*2 = 5032, RHS_EVALS = 4*STEPS (GSL: 6*STEPS). (No observer: it evaluates
 * friction outside the count.) The chain's W is diagonal, so no f_eq solve adds evaluations. */
START_TEST(test_rk4_costs_four_evaluations_per_step)
{
    fricreg_sim *sim = chain_run(FRICREG_LAW_QUINN, 0.01);
    double steps = value(sim, FRICREG_VALUE_STEPS), evals = value(sim, FRICREG_VALUE_RHS_EVALS);
    ck_assert_double_eq(steps, 4.0 * 629.0 * 2.0);
    ck_assert_double_eq(evals, 4.0 * steps);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RK4_GSL, 0.01, 0.0, 0.0),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 4), FRICREG_OK);
    ck_assert_double_eq(value(sim, FRICREG_VALUE_STEPS), steps);
    ck_assert_double_eq(value(sim, FRICREG_VALUE_RHS_EVALS), 6.0 * steps);
    fricreg_sim_free(sim);
}
END_TEST

/* Paper Fig. 9: (4) stays accurate up to dt = 0.01, (1) does not. D_4 of (4) at dt = 0.01 is
 * closer to its dt = 0.001 value than D_4 of (1) at dt = 0.01 is to its own dt = 0.001 value. */
START_TEST(test_quinn_is_more_step_robust_than_coulomb)
{
    double q_coarse = fourth_cycle_D(FRICREG_LAW_QUINN, 0.01);
    double q_fine = fourth_cycle_D(FRICREG_LAW_QUINN, 0.001);
    double c_coarse = fourth_cycle_D(FRICREG_LAW_COULOMB, 0.01);
    double c_fine = fourth_cycle_D(FRICREG_LAW_COULOMB, 0.001);
    ck_assert_double_lt(fabs(q_coarse - q_fine), fabs(c_coarse - c_fine));
    /* and (4) at dt = 0.001 still sits on Fig. 9's converged value */
    ck_assert_double_eq_tol(q_fine, 0.0105, 0.01 * 0.0105);
}
END_TEST

static Suite *chain_suite(void)
{
    Suite *s = suite_create("chain");
    TCase *tc = tcase_create("paper");
    tcase_add_test(tc, test_defaults_are_the_papers);
    tcase_add_test(tc, test_quinn_fourth_cycle_D_matches_fig9);
    tcase_add_test(tc, test_rk4_costs_four_evaluations_per_step);
    tcase_add_test(tc, test_quinn_is_more_step_robust_than_coulomb);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(chain_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
