/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_implicit.c — GSL's implicit steppers on the reference systems at a tiny eps, where
 * the stick zone's slope 2 mun/eps = 2e6 makes the problem stiff and the drivers' Jacobian
 * (src/sim/sim_jacobian.c: the context's exact tangent) decides whether Newton converges.
 *
 * References: the oscillator's exact solution (fricreg_exact.h, 12 digits), and the chain's
 * D on cycle 4 = 0.01049496000, within 1e-11: msbdf with the exact Jacobian at eps 1e-5 and
 * 1e-6, rtol 1e-12, atol 1e-14, both give 0.010494959994, rk8pd at eps 1e-5, rtol 1e-11
 * 0.010494960003 (10 CPU s); law (4)'s error is O(eps^2) on the chain (README: order 1.91),
 * below 1e-9 here. With the forward-difference Jacobian these runs failed or crawled:
 * rk4imp stopped on the oscillator at t = 10.5 (Newton did not converge), and msbdf on the
 * chain took more than 150 CPU s. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "fricreg_exact.h"
#include "fricreg_sim.h"

#define EPS 1e-6
#define CYCLES 4
#define CHAIN_D4 0.01049496000

/* The oscillator of the benchmark's sticking problem (a = 2, omega = 0.5: stuck 17.5 % of a
 * cycle), from an arbitrary state. */
#define OSC_A 2.0
#define OSC_OMEGA 0.5
#define OSC_X0 0.385
#define OSC_V0 (-0.217)

/* D on the last of CYCLES cycles of `sim` run with `integrator` at rtol, atol = rtol / 100. */
static double last_cycle(fricreg_sim *sim, int integrator, double rtol)
{
    double D[CYCLES];
    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, EPS), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, integrator, 0.01, rtol, rtol / 100.0),
                     FRICREG_OK);
    int status = fricreg_sim_run_cycles(sim, CYCLES);
    ck_assert_msg(status == FRICREG_OK, "%s: %s", fricreg_integrator_name(integrator),
                  fricreg_sim_errmsg(sim));
    ck_assert_int_eq(fricreg_sim_get_dissipation(sim, CYCLES, D), FRICREG_OK);
    return D[CYCLES - 1];
}

static double exact_oscillator_D(void)
{
    fricreg_exact *ex = NULL;
    double D[CYCLES];
    ck_assert_int_eq(fricreg_exact_create(OSC_A, OSC_OMEGA, 1.0, OSC_X0, OSC_V0, &ex), FRICREG_OK);
    ck_assert_int_eq(fricreg_exact_run_cycles(ex, CYCLES), FRICREG_OK);
    ck_assert_int_eq(fricreg_exact_dissipation(ex, CYCLES, D), FRICREG_OK);
    fricreg_exact_free(ex);
    return D[CYCLES - 1];
}

static fricreg_sim *oscillator(void)
{
    fricreg_sim *sim = NULL;
    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_OSCILLATOR, &sim), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_A, OSC_A), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_OMEGA, OSC_OMEGA), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_X0, OSC_X0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_V0, OSC_V0), FRICREG_OK);
    return sim;
}

static void report(const char *what, double D, double ref)
{
    printf("%s: D4 = %.10g, reference %.10g, %.2e relative\n", what, D, ref, (D - ref) / ref);
    fflush(stdout); /* Check forks: the child may _exit before stdio flushes */
}

/* rtol 1e-8: msbdf measured 1.3e-7, rk4imp 1.6e-8 from the exact D; law (4)'s own
 * error at eps = 1e-6 is O(eps^2) on the sticking oscillator (-1.5e-5 at eps = 0.04),
 * so what is left is the integrators' tolerance. */
START_TEST(oscillator_msbdf_and_rk4imp_reach_the_exact_solution)
{
    double ref = exact_oscillator_D();
    fricreg_sim *sim = oscillator();
    double D = last_cycle(sim, FRICREG_INT_MSBDF, 1e-8);
    report("oscillator msbdf", D, ref);
    ck_assert_double_eq_tol(D, ref, 1e-6 * ref);
    D = last_cycle(sim, FRICREG_INT_RK4IMP, 1e-8);
    report("oscillator rk4imp", D, ref);
    ck_assert_double_eq_tol(D, ref, 1e-6 * ref);
    fricreg_sim_free(sim);
}
END_TEST

/* The chain's 32 contacts, most of them stuck for the whole cycle: msbdf at rtol 1e-8
 * measured 8.0e-7 from the reference (1.5e-6 before adaptive steps were capped). */
START_TEST(chain_msbdf_reaches_the_reference)
{
    fricreg_sim *sim = NULL;
    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_CHAIN, &sim), FRICREG_OK);
    double D = last_cycle(sim, FRICREG_INT_MSBDF, 1e-8);
    report("chain msbdf", D, CHAIN_D4);
    ck_assert_double_eq_tol(D, CHAIN_D4, 5e-6 * CHAIN_D4);
    fricreg_sim_free(sim);
}
END_TEST

static Suite *implicit_suite(void)
{
    Suite *s = suite_create("implicit");
    TCase *tc = tcase_create("exact_jacobian"), *tchain = tcase_create("chain");
    /* msbdf on 32 contacts (6 s): the release tier's (implicit_release); exact_jacobian takes
     * the same path through the implicit integrators */
    tcase_set_tags(tchain, "release");
    tcase_add_test(tc, oscillator_msbdf_and_rk4imp_reach_the_exact_solution);
    tcase_add_test(tchain, chain_msbdf_reaches_the_reference);
    suite_add_tcase(s, tc);
    suite_add_tcase(s, tchain);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(implicit_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
