/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_tolerances.c — fricreg_sim's absolute tolerances per component
 * (fricreg_sim_set_abs_tolerances, FRICREG_ATOL_FROM_EPS: src/sim/sim.c, rule_tolerances).
 *
 * Where the expected values come from:
 *   - the two blocks (paper defaults, Eqs. (7)) at eps = 1e-6: D on belt cycle 4 = 1.7355132
 *     within 3e-7 and the stick fractions of cycle 4, 0.31816 and 0.42990, as derived in
 *     tests/sim/test_kink_location.c (RK4 extrapolated in eps; rkf45, rk8pd, msbdf at rtol 1e-8 …
 *     1e-11);
 *   - the two blocks at eps = 1e-4: D on cycle 4 = 1.7354975267 (msbdf and rkf45 at rtol 1e-11,
 *     atol 1e-13, test_kink_location.c);
 *   - the rule's values: velocities min(1e-3 eps, rtol), positions and D rtol
 *     (docs/integrators.md, "Absolute tolerances from eps").
 * Measured with the rule, msbdf, kink location on (docs/integrators.md's table):
 *   eps = 1e-6: rtol 1e-4: D4 -4.8e-6, stick (0.3188, 0.4299); rtol 1e-6: -4.9e-6, the same;
 *   eps = 1e-4: rtol 1e-4: D4 +1.9e-5; rtol 1e-6: +1.2e-5.
 * Asserted at the task's targets (1e-4 and stick 1e-3 at rtol 1e-6; 1e-2 at rtol 1e-4), which
 * the measured errors meet by 20x and 1.7x (stick) and 2000x. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg.h"
#include "fricreg_sim.h"

#define D_REF_TWOBLOCK_EPS6 1.7355132
#define D_REF_TWOBLOCK_EPS4 1.7354975267
static const double stick_ref_eps6[2] = {0.31816, 0.42990};

struct outcome {
    double D4, stick[2];
};

static double relative(double x, double ref)
{
    return fabs(x - ref) / fabs(ref);
}

static struct outcome two_blocks(double eps, double rtol, double atol)
{
    fricreg_sim *sim = NULL;
    struct outcome out = {0.0, {0.0, 0.0}};
    double D[4];
    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_TWOBLOCK, &sim), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, eps), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_MSBDF, 0.01, rtol, atol),
                     FRICREG_OK);
    int status = fricreg_sim_run_cycles(sim, 4);
    ck_assert_msg(status == FRICREG_OK, "run: %s", fricreg_sim_errmsg(sim));
    ck_assert_int_eq(fricreg_sim_get_dissipation(sim, 4, D), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_stick_fraction(sim, 2, out.stick), FRICREG_OK);
    fricreg_sim_free(sim);
    out.D4 = D[3];
    printf("twoblock msbdf eps %g rtol %g atol %g: D4 = %.10f, stick (%.5f, %.5f)\n", eps, rtol,
           atol, out.D4, out.stick[0], out.stick[1]);
    return out;
}

/* The task's target at eps = 1e-6: rtol 1e-6 with the default (rule) atol within 1e-4 in D
 * and 1e-3 in the stick fractions, rtol 1e-4 within 1e-2. With one atol = rtol = 1e-6 for
 * every component, D4 was +8.0e-3 off (test_kink_location.c). */
START_TEST(two_blocks_eps_1e_6_rule)
{
    struct outcome o = two_blocks(1e-6, 1e-6, FRICREG_ATOL_FROM_EPS);
    ck_assert_double_lt(relative(o.D4, D_REF_TWOBLOCK_EPS6), 1e-4);
    for (int i = 0; i < 2; i++)
        ck_assert_double_eq_tol(o.stick[i], stick_ref_eps6[i], 1e-3);
    o = two_blocks(1e-6, 1e-4, FRICREG_ATOL_FROM_EPS);
    ck_assert_double_lt(relative(o.D4, D_REF_TWOBLOCK_EPS6), 1e-2);
    for (int i = 0; i < 2; i++)
        ck_assert_double_eq_tol(o.stick[i], stick_ref_eps6[i], 1e-2);
}
END_TEST

START_TEST(two_blocks_eps_1e_4_rule)
{
    struct outcome o = two_blocks(1e-4, 1e-6, FRICREG_ATOL_FROM_EPS);
    ck_assert_double_lt(relative(o.D4, D_REF_TWOBLOCK_EPS4), 1e-4);
    o = two_blocks(1e-4, 1e-4, FRICREG_ATOL_FROM_EPS);
    ck_assert_double_lt(relative(o.D4, D_REF_TWOBLOCK_EPS4), 1e-2);
}
END_TEST

/* The rule's numbers, by fricreg_sim_get_abs_tolerances: positions and D rtol, velocities
 * min(1e-3 eps, rtol); at the level of each eps of an extrapolation, its own eps (the getter
 * reads the eps in use). A scalar atol fills every component; fixed steps give zeros. */
START_TEST(getter_reports_the_rule)
{
    fricreg_sim *sim = NULL;
    double atol[5] = {0}, sentinel[3] = {-7.0, -7.0, -7.0};
    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_TWOBLOCK, &sim), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_abs_tolerances(sim, 5, atol), FRICREG_OK);
    for (int i = 0; i < 5; i++)
        ck_assert_double_eq(atol[i], 0.0); /* fixed-step RK4 */
    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, 2.385e-6), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_MSBDF, 0.01, 1e-6,
                                                FRICREG_ATOL_FROM_EPS),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_abs_tolerances(sim, 5, atol), FRICREG_OK);
    const double expect[5] = {1e-6, 1e-6, 2.385e-9, 2.385e-9, 1e-6};
    for (int i = 0; i < 5; i++)
        ck_assert_double_eq_tol(atol[i], expect[i], 1e-15 * expect[i]);
    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, 2.385), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_abs_tolerances(sim, 5, atol), FRICREG_OK);
    ck_assert_double_eq(atol[2], 1e-6); /* rtol caps the velocities' */
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RKF45, 0.01, 1e-6, 2.385e-7),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_abs_tolerances(sim, 5, atol), FRICREG_OK);
    for (int i = 0; i < 5; i++)
        ck_assert_double_eq(atol[i], 2.385e-7);
    ck_assert_int_eq(fricreg_sim_get_abs_tolerances(sim, 3, sentinel), FRICREG_ESIZE);
    ck_assert_double_eq(sentinel[0], -7.0);
    ck_assert_int_eq(fricreg_sim_get_abs_tolerances(NULL, 5, atol), FRICREG_ENULL);
    fricreg_sim_free(sim);
}
END_TEST

/* The warning on loose tolerances (fricreg_sim_warning_count): raised where a velocity's level
 * atol + rtol x 1 exceeds 0.01 eps, at the boundary exactly as documented; never by the rule
 * from eps nor by fixed steps; read back with its code and message; judged on the settings,
 * so the same before and after a run, and the run's numbers the same either way. */
START_TEST(loose_tolerances_warn)
{
    fricreg_sim *sim = NULL;
    int code = -1;
    char msg[256], tiny[8];
    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_TWOBLOCK, &sim), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, 1e-6), FRICREG_OK);
    ck_assert_uint_eq(fricreg_sim_warning_count(sim), 0); /* fixed-step RK4 */
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_MSBDF, 0.01, 1e-6,
                                                FRICREG_ATOL_FROM_EPS),
                     FRICREG_OK);
    ck_assert_uint_eq(fricreg_sim_warning_count(sim), 0);
    /* level 1e-6 + 1e-6 = 2e-6 against 0.01 eps = 1e-8 */
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_MSBDF, 0.01, 1e-6, 1e-6),
                     FRICREG_OK);
    ck_assert_uint_eq(fricreg_sim_warning_count(sim), 1);
    ck_assert_int_eq(fricreg_sim_get_warning(sim, 0, &code, msg, sizeof msg), FRICREG_OK);
    ck_assert_int_eq(code, FRICREG_WARN_TOL_LOOSE);
    ck_assert_str_eq(fricreg_warning_name(code), "tol_loose");
    ck_assert_str_eq(msg, fricreg_sim_warning_message(sim, 0));
    ck_assert_ptr_nonnull(strstr(msg, "2e-06"));
    ck_assert_int_eq(fricreg_sim_get_warning(sim, 0, &code, tiny, sizeof tiny), FRICREG_OK);
    ck_assert_uint_eq(strlen(tiny), sizeof tiny - 1);
    code = -1;
    ck_assert_int_eq(fricreg_sim_get_warning(sim, 1, &code, msg, sizeof msg), FRICREG_EINVAL);
    ck_assert_int_eq(code, -1);
    ck_assert_str_eq(fricreg_sim_warning_message(sim, 1), "");
    ck_assert_int_eq(fricreg_sim_get_warning(sim, 0, NULL, msg, sizeof msg), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_sim_get_warning(NULL, 0, &code, msg, sizeof msg), FRICREG_ENULL);
    ck_assert_uint_eq(fricreg_sim_warning_count(NULL), 0);
    ck_assert_str_eq(fricreg_sim_warning_message(NULL, 0), "");
    /* at the boundary: rtol 1e-9, atol 1e-8 - 1e-9 is the level 0.01 eps exactly, no warning;
     * the next atol up warns */
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_MSBDF, 0.01, 1e-9, 9e-9),
                     FRICREG_OK);
    ck_assert_uint_eq(fricreg_sim_warning_count(sim), 0);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_MSBDF, 0.01, 1e-9, 9.1e-9),
                     FRICREG_OK);
    ck_assert_uint_eq(fricreg_sim_warning_count(sim), 1);
    /* per component: a loose velocity entry warns, loose positions and D do not */
    const double fine[5] = {1e-3, 1e-3, 1e-9, 1e-9, 1e-3},
                 loose[5] = {1e-9, 1e-9, 1e-9, 1e-7, 1e-9};
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_MSBDF, 0.01, 0.0, 0.0),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_abs_tolerances(sim, 5, fine), FRICREG_OK);
    ck_assert_uint_eq(fricreg_sim_warning_count(sim), 0);
    ck_assert_int_eq(fricreg_sim_set_abs_tolerances(sim, 5, loose), FRICREG_OK);
    ck_assert_uint_eq(fricreg_sim_warning_count(sim), 1);
    fricreg_sim_free(sim);
}
END_TEST

/* The caller's tolerances: copied, reported, used (the run is adaptive even with rtol 0),
 * replaced by a later set_integrator; refused with a message, nothing changed, for each error
 * the docstring names; a chain whose n changed is refused at the run. */
START_TEST(caller_tolerances)
{
    fricreg_sim *sim = NULL;
    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_OSCILLATOR, &sim), FRICREG_OK);
    double mine[3] = {2.385e-7, 1e-9, 1e-7}, got[3];
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RKF45, 0.01, 0.0, 1e-8),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_abs_tolerances(sim, 3, mine), FRICREG_OK);
    mine[0] = 99.0; /* copied */
    ck_assert_int_eq(fricreg_sim_get_abs_tolerances(sim, 3, got), FRICREG_OK);
    ck_assert_double_eq(got[0], 2.385e-7);
    ck_assert_double_eq(got[1], 1e-9);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 1), FRICREG_OK);
    int64_t steps = 0;
    ck_assert_int_eq(fricreg_sim_get_stat(sim, FRICREG_SIM_STAT_STEPS, &steps), FRICREG_OK);
    ck_assert_int_gt(steps, 0);

    const double bad[3] = {1e-6, 0.0, 1e-6}, nan3[3] = {1e-6, NAN, 1e-6};
    ck_assert_int_eq(fricreg_sim_set_abs_tolerances(sim, 3, bad), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "atol[1]"));
    ck_assert_int_eq(fricreg_sim_set_abs_tolerances(sim, 3, nan3), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_sim_set_abs_tolerances(sim, 5, got), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_sim_set_abs_tolerances(sim, 3, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_sim_set_abs_tolerances(NULL, 3, got), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_sim_get_abs_tolerances(sim, 3, got), FRICREG_OK);
    ck_assert_double_eq(got[0], 2.385e-7); /* unchanged by the failures */

    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RKF45, 0.01, 1e-6, 1e-8),
                     FRICREG_OK); /* replaces them */
    ck_assert_int_eq(fricreg_sim_get_abs_tolerances(sim, 3, got), FRICREG_OK);
    ck_assert_double_eq(got[0], 1e-8);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_CENTRAL, 0.01, 0.0, 0.0),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_abs_tolerances(sim, 3, got), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_CENTRAL, 0.01, 0.0,
                                                FRICREG_ATOL_FROM_EPS),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_MSBDF, 0.01, 0.0,
                                                FRICREG_ATOL_FROM_EPS),
                     FRICREG_EINVAL); /* the rule needs rtol > 0 */
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_MSBDF, 0.01, 1e-6, -2.385),
                     FRICREG_EINVAL);
    fricreg_sim_free(sim);

    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_CHAIN, &sim), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_N, 2), FRICREG_OK);
    const double five[5] = {1e-6, 1e-6, 1e-8, 1e-8, 1e-6};
    ck_assert_int_eq(fricreg_sim_set_abs_tolerances(sim, 5, five), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_N, 3), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run(sim, 0.1), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "set them again"));
    fricreg_sim_free(sim);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("tolerances");
    TCase *tc = tcase_create("tolerances");
    tcase_add_test(tc, two_blocks_eps_1e_6_rule);
    tcase_add_test(tc, two_blocks_eps_1e_4_rule);
    tcase_add_test(tc, getter_reports_the_rule);
    tcase_add_test(tc, caller_tolerances);
    tcase_add_test(tc, loose_tolerances_warn);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
