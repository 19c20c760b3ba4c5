/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_kink_location.c — fricreg_sim's adaptive steps stopped at the friction law's kinks
 * (fricreg_sim_set_kink_location, src/sim/kinks.c).
 *
 * Where the expected values come from:
 *   - the two blocks (paper defaults, Eqs. (7)), eps = 1e-6: D on belt cycle 4 = 1.7355132
 *     within 3e-7 (tests/sim/test_twoblock_adaptive.c derives it: RK4 extrapolated in eps, rkf45
 *     and rk8pd at rtol 1e-8, msbdf at rtol 1e-10 and 1e-11); the stick fractions of cycle 4,
 *     0.31816 and 0.42990, from msbdf at rtol 1e-10 / atol 1e-12 and rtol 1e-11 / atol 1e-13
 *     (0.3181419 / 0.4299036 and 0.3181588 / 0.4299031), without kink location;
 *   - the two blocks at eps = 1e-4: D on cycle 4 = 1.7354975267, from msbdf (1.73549752668)
 *     and rkf45 (1.73549752633) at rtol 1e-11, atol 1e-13, without kink location;
 *   - the forced oscillator a = 1.2, omega = 0.5 (mun = 1, x0 = 2.75, v0 = 0): D on cycle 4
 *     from the closed-form solver (fricreg_exact, in the test), 4.546288190809958; the
 *     regularized law's own D at eps = 1e-4 and 1e-6 is within 2e-9 of it (msbdf at rtol
 *     1e-12: 4.5462881955 and 4.5462881895; rk8pd at eps = 1e-4: 4.5462881969);
 *   - with location off, the numbers of the drivers before it existed (fricreg 3b828da, the
 *     run of the issue: msbdf, rtol = atol = 1e-6, eps = 1e-6 on the two blocks), to the bit.
 * The tolerances asserted are the measured errors with a margin of about 1.5x to 4x; the
 * measurements are in each test's comment and in docs/integrators.md. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "fricreg_exact.h"
#include "fricreg_sim.h"

#define D_REF_TWOBLOCK_EPS6 1.7355132
#define D_REF_TWOBLOCK_EPS4 1.7354975267
static const double stick_ref_eps6[2] = {0.31816, 0.42990};

struct outcome {
    double D[4], stick[2];
    int64_t kinks;
};

static struct outcome run(int system, int integrator, double eps, double rtol, double atol,
                          int locate)
{
    fricreg_sim *sim = NULL;
    struct outcome out = {{0}, {0}, 0};
    ck_assert_int_eq(fricreg_sim_create(system, &sim), FRICREG_OK);
    if (system == FRICREG_SYSTEM_OSCILLATOR) {
        ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_A, 1.2), FRICREG_OK);
        ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_OMEGA, 0.5), FRICREG_OK);
    }
    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, eps), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, integrator, 0.01, rtol, atol), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_kink_location(sim, locate), FRICREG_OK);
    int status = fricreg_sim_run_cycles(sim, 4);
    ck_assert_msg(status == FRICREG_OK, "run: %s", fricreg_sim_errmsg(sim));
    size_t m = fricreg_sim_ncontacts(sim);
    ck_assert_int_eq(fricreg_sim_get_dissipation(sim, 4, out.D), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_stick_fraction(sim, m, out.stick), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_stat(sim, FRICREG_SIM_STAT_KINKS, &out.kinks), FRICREG_OK);
    fricreg_sim_free(sim);
    printf("%s %s eps %g rtol %g atol %g location %d: D4 = %.10f, stick (%.5f, %.5f), %lld "
           "kinks\n",
           system == FRICREG_SYSTEM_OSCILLATOR ? "oscillator" : "twoblock",
           fricreg_integrator_name(integrator), eps, rtol, atol, locate, out.D[3], out.stick[0],
           m > 1 ? out.stick[1] : 0.0, (long long)out.kinks);
    fflush(stdout); /* Check forks: the child may _exit before stdio flushes */
    return out;
}

static double relative(double x, double ref)
{
    return fabs(x - ref) / fabs(ref);
}

/* Location off is the run without it, to the bit: the run (msbdf, rtol = atol = 1e-6,
 * eps = 1e-6, the two blocks) gives fricreg 3b828da's D per cycle and stick fractions, D on
 * cycle 4 the +43% of the issue, no stick on the upper block. On, the same run counts kinks
 * and gives other numbers. */
START_TEST(location_off_is_the_run_without_it)
{
    static const double D_before[4] = {0x1.fc7eb8bbc5e09p+0, 0x1.4f9c822f44c0ap+2,
                                       0x1.87c6278e670d0p+1, 0x1.3e909363ffb48p+1};
    static const double stick_before[2] = {0x1.bd3b62b250530p-3, 0x1.3f9ce51515420p-19};
    struct outcome off = run(FRICREG_SYSTEM_TWOBLOCK, FRICREG_INT_MSBDF, 1e-6, 1e-6, 1e-6, 0);
    for (int k = 0; k < 4; k++)
        ck_assert_msg(off.D[k] == D_before[k], "cycle %d: %a, before %a", k + 1, off.D[k],
                      D_before[k]);
    for (int i = 0; i < 2; i++)
        ck_assert_msg(off.stick[i] == stick_before[i], "stick %d: %a, before %a", i, off.stick[i],
                      stick_before[i]);
    ck_assert_int_eq(off.kinks, 0);
    struct outcome on = run(FRICREG_SYSTEM_TWOBLOCK, FRICREG_INT_MSBDF, 1e-6, 1e-6, 1e-6, 1);
    ck_assert_int_gt(on.kinks, 0);
    ck_assert_double_ne(on.D[3], off.D[3]);
}
END_TEST

/* Fixed steps are never located: the same numbers with location on and off (rk4 and msbdf on
 * the caller's grid). */
START_TEST(fixed_steps_are_unchanged)
{
    static const int integrators[2] = {FRICREG_INT_RK4, FRICREG_INT_MSBDF};
    for (int k = 0; k < 2; k++) {
        struct outcome on = run(FRICREG_SYSTEM_TWOBLOCK, integrators[k], 0.02, 0.0, 0.0, 1);
        struct outcome off = run(FRICREG_SYSTEM_TWOBLOCK, integrators[k], 0.02, 0.0, 0.0, 0);
        for (int c = 0; c < 4; c++)
            ck_assert_double_eq(on.D[c], off.D[c]);
        ck_assert_int_eq(on.kinks, 0);
    }
}
END_TEST

/* The case, eps = 1e-6 on the two blocks with msbdf. Measured with location (without):
 *   rtol = atol = 1e-6: D4 +8.0e-3 (+0.43), stick (0.3166, 0.4314) ((0.2174, 2.4e-6));
 *   rtol = atol = 1e-8: D4 +2.6e-4 (-2.7e-3).
 * The target, 1e-4 at rtol 1e-6, is not reached: with atol = 1e-6 = eps the control
 * lets the velocity err by the width of law (4)'s zone (docs/integrators.md). */
START_TEST(msbdf_two_blocks_eps_1e_6)
{
    struct outcome o = run(FRICREG_SYSTEM_TWOBLOCK, FRICREG_INT_MSBDF, 1e-6, 1e-6, 1e-6, 1);
    ck_assert_double_lt(relative(o.D[3], D_REF_TWOBLOCK_EPS6), 1.5e-2);
    for (int i = 0; i < 2; i++)
        ck_assert_double_eq_tol(o.stick[i], stick_ref_eps6[i], 3e-3);
    o = run(FRICREG_SYSTEM_TWOBLOCK, FRICREG_INT_MSBDF, 1e-6, 1e-8, 1e-8, 1);
    ck_assert_double_lt(relative(o.D[3], D_REF_TWOBLOCK_EPS6), 1e-3);
    for (int i = 0; i < 2; i++)
        ck_assert_double_eq_tol(o.stick[i], stick_ref_eps6[i], 2e-3);
}
END_TEST

/* eps = 1e-4 on the two blocks with msbdf, location on (off):
 *   rtol = atol = 1e-4: D4 -1.8e-4 (+0.32), stick (0.320, 0.428) ((0.195, 1e-4));
 *   rtol = atol = 1e-6: D4 -7.8e-5 (-3.0e-3). */
START_TEST(msbdf_two_blocks_eps_1e_4)
{
    struct outcome o = run(FRICREG_SYSTEM_TWOBLOCK, FRICREG_INT_MSBDF, 1e-4, 1e-4, 1e-4, 1);
    ck_assert_double_lt(relative(o.D[3], D_REF_TWOBLOCK_EPS4), 1e-3);
    ck_assert_double_gt(o.stick[0], 0.3);
    ck_assert_double_gt(o.stick[1], 0.4);
    o = run(FRICREG_SYSTEM_TWOBLOCK, FRICREG_INT_MSBDF, 1e-4, 1e-6, 1e-6, 1);
    ck_assert_double_lt(relative(o.D[3], D_REF_TWOBLOCK_EPS4), 2e-4);
}
END_TEST

static double oscillator_exact_D4(void)
{
    fricreg_exact *ex = NULL;
    double D[4];
    ck_assert_int_eq(fricreg_exact_create(1.2, 0.5, 1.0, 2.75, 0.0, &ex), FRICREG_OK);
    ck_assert_int_eq(fricreg_exact_run_cycles(ex, 4), FRICREG_OK);
    ck_assert_int_eq(fricreg_exact_dissipation(ex, 4, D), FRICREG_OK);
    fricreg_exact_free(ex);
    ck_assert_double_eq_tol(D[3], 4.546288190809958, 1e-12); /* fricreg-sim exact's */
    return D[3];
}

/* The forced oscillator (a = 1.2, omega = 0.5) against its closed form, location on (off):
 *   msbdf, eps = 1e-6, rtol = atol = 1e-6: D4 +4.0e-3 (-1.0: D4 = 0, the stick never left);
 *   rkf45, eps = 1e-4, rtol = atol = 1e-6: D4 +4.9e-6 (-8.0e-5);
 *   msadams, eps = 1e-4, rtol = atol = 1e-6: D4 +8.2e-5 (+7.8e-5: its steps, limited by the
 *   stick zone's stiffness, are short; located or not, it steps close to each kink). */
START_TEST(oscillator_against_the_closed_form)
{
    double D_ref = oscillator_exact_D4();
    struct outcome o = run(FRICREG_SYSTEM_OSCILLATOR, FRICREG_INT_MSBDF, 1e-6, 1e-6, 1e-6, 1);
    ck_assert_double_lt(relative(o.D[3], D_ref), 1e-2);
    o = run(FRICREG_SYSTEM_OSCILLATOR, FRICREG_INT_RKF45, 1e-4, 1e-6, 1e-6, 1);
    ck_assert_double_lt(relative(o.D[3], D_ref), 2e-5);
    o = run(FRICREG_SYSTEM_OSCILLATOR, FRICREG_INT_MSADAMS, 1e-4, 1e-6, 1e-6, 1);
    ck_assert_double_lt(relative(o.D[3], D_ref), 2e-4);
}
END_TEST

static int change_location(void *user, double t, size_t ndof, const double x[], const double v[],
                           size_t m, const double f[], const double f_eq[])
{
    (void)t, (void)ndof, (void)x, (void)v, (void)m, (void)f, (void)f_eq;
    fricreg_sim *sim = user;
    ck_assert_int_eq(fricreg_sim_set_kink_location(sim, 0), FRICREG_EINVAL);
    return 1;
}

/* The setter: 0 and 1 only, never from the observer; the results of the last run kept. */
START_TEST(setter_refuses_what_it_documents)
{
    fricreg_sim *sim = NULL;
    ck_assert_int_eq(fricreg_sim_set_kink_location(NULL, 1), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_OSCILLATOR, &sim), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_kink_location(sim, 2), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_sim_set_kink_location(sim, -1), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RKF45, 0.01, 1e-6, 1e-8),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_observer(sim, change_location, sim), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 1), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_observer(sim, NULL, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 1), FRICREG_OK);
    int64_t steps = 0;
    ck_assert_int_eq(fricreg_sim_get_stat(sim, FRICREG_SIM_STAT_STEPS, &steps), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_kink_location(sim, 0), FRICREG_OK);
    int64_t kept = 0;
    ck_assert_int_eq(fricreg_sim_get_stat(sim, FRICREG_SIM_STAT_STEPS, &kept), FRICREG_OK);
    ck_assert_int_eq(kept, steps);
    fricreg_sim_free(sim);
}
END_TEST

static Suite *kink_location_suite(void)
{
    Suite *s = suite_create("kink_location");
    TCase *tc = tcase_create("drivers");
    tcase_add_test(tc, location_off_is_the_run_without_it);
    tcase_add_test(tc, fixed_steps_are_unchanged);
    tcase_add_test(tc, msbdf_two_blocks_eps_1e_6);
    tcase_add_test(tc, msbdf_two_blocks_eps_1e_4);
    tcase_add_test(tc, oscillator_against_the_closed_form);
    tcase_add_test(tc, setter_refuses_what_it_documents);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(kink_location_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
