/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_aft_normal.c — Check suite for the sampled AFT of a Jenkins element under normal load
 * with lift-off (fricreg_aft_jenkins_normal_sampled, fricreg_aft.h).
 *
 * Where the numbers come from:
 *   - a constant normal force (kn = 0) is the Jenkins element of bound mu N0: the same
 *     function as fricreg_aft_jenkins_sampled at mun = mu N0, to the bit (the header's promise);
 *   - an element open throughout (N0 + kn g < 0 at every sample) carries nothing: f, N and
 *     the Jacobian are 0 exactly;
 *   - against the time-domain element: fricreg_jenkins_trial_normal and commit at the same
 *     samples, marched from a relaxed slider over three periods, the last period's forces
 *     transformed by a plain DFT written here (no FFT): equal to rounding, with lift-off in
 *     part of the period, with a bound moving with g and no opening, and stuck;
 *   - the Jacobian against central differences of the same function (step 1e-6). */
#include <check.h>
#include <math.h>
#include <string.h>

#include "fricreg_aft.h"
#include "aft_normal_checks.h"
#include "fricreg_jenkins.h"

#define SENTINEL (-777.125)
#define H 3
#define NC (2 * H + 1)
#define NS 1024

static fricreg_aft *make(int harmonics, size_t samples)
{
    fricreg_aft *a = NULL;
    ck_assert_int_eq(fricreg_aft_create(harmonics, samples, &a), FRICREG_OK);
    return a;
}

START_TEST(constant_preload_is_jenkins)
{
    const double u[NC] = {0.3, 1.0, 0.0, 0.0, 0.2, 0.9, -0.1}, g[NC] = {0.4, 0.5, -0.2, 0, 0, 0, 0};
    const double kt = 2.385, mu = 0.1, bounds[2] = {0.7, 30.0}; /* slipping, stuck */
    fricreg_aft *a = make(H, NS);
    for (int c = 0; c < 2; c++) {
        double f[NC], nf[NC], jac[4 * NC * NC], fj[NC], jj[NC * NC], n0 = bounds[c] / mu;
        ck_assert_int_eq(fricreg_aft_jenkins_normal_sampled(a, kt, mu, n0, 0.0, NC, u, g, f, nf,
                                                            jac),
                         FRICREG_OK);
        ck_assert_int_eq(fricreg_aft_jenkins_sampled(a, kt, mu * n0, NC, u, fj, jj), FRICREG_OK);
        for (int i = 0; i < NC; i++) {
            ck_assert_double_eq(f[i], fj[i]);
            ck_assert_double_eq_tol(nf[i], i == 0 ? n0 : 0.0, 1e-13 * n0);
            for (int j = 0; j < NC; j++) {
                ck_assert_double_eq(jac[2 * NC * i + j], jj[NC * i + j]);
                ck_assert_double_eq(jac[2 * NC * i + NC + j], 0.0);        /* df/dg: kn = 0 */
                ck_assert_double_eq(jac[2 * NC * (NC + i) + j], 0.0);      /* dN/du */
                ck_assert_double_eq(jac[2 * NC * (NC + i) + NC + j], 0.0); /* dN/dg */
            }
        }
    }
    fricreg_aft_free(a);
}
END_TEST

START_TEST(open_throughout_is_zero)
{
    const double u[NC] = {0.3, 1.0, 0.0, 0.0, 0.2, 0.9, -0.1}, g[NC] = {0.0, 0.2, 0.1, 0, 0, 0, 0};
    double f[NC], nf[NC], jac[4 * NC * NC];
    fricreg_aft *a = make(H, NS);
    ck_assert_int_eq(fricreg_aft_jenkins_normal_sampled(a, 2.0, 0.5, -1.0, 2.0, NC, u, g, f, nf,
                                                        jac),
                     FRICREG_OK);
    for (int i = 0; i < NC; i++) {
        ck_assert_double_eq(f[i], 0.0);
        ck_assert_double_eq(nf[i], 0.0);
    }
    for (int i = 0; i < 4 * NC * NC; i++)
        ck_assert_double_eq(jac[i], 0.0);
    fricreg_aft_free(a);
}
END_TEST

START_TEST(against_the_time_domain_element)
{
    fricreg_aft *a = make(H, NS);
    aft_normal_check_time_domain_cases(a, fricreg_aft_jenkins_normal_sampled, NS, 1e-12);
    fricreg_aft_free(a);
}
END_TEST

START_TEST(jacobian_against_differences)
{
    const double u1[NC] = {0.0, 1.0, 0.0, 0, 0, 0.1, 0}, g1[NC] = {0.1, 0.0, 1.5, 0, 0, 0, 0};
    const double u2[NC] = {0.1, 1.2, 0.0, 0.0, 0.3, 0, 0}, g2[NC] = {0.0, 0.76, -0.24, 0, 0, 0, 0};
    fricreg_aft *a = make(H, NS);
    aft_normal_check_jacobian(a, fricreg_aft_jenkins_normal_sampled, 2.0, 0.5, 1.0, 1.0, u1, g1);
    aft_normal_check_jacobian(a, fricreg_aft_jenkins_normal_sampled, 3.0, 0.4, 2.0, 1.0, u2, g2);
    /* a stick from where the contact closes again (between two samples) */
    const double u3[NC] = {0.0, 0.05, 0.02, 0, 0, 0, 0}, g3[NC] = {0.0, -1.5, 0.3, 0, 0, 0, 0};
    aft_normal_check_jacobian(a, fricreg_aft_jenkins_normal_sampled, 2.0, 0.5, 1.0, 1.0, u3, g3);
    fricreg_aft_free(a);
}
END_TEST

/* the stuck slider nearest the centre, continuous where the centre leaves the stuck ones
 * (aft_normal_checks.h; the samples hold θ = 0 and π, where the extremes lie) */
START_TEST(nearest_stuck_slider)
{
    fricreg_aft *a = make(3, 1024);
    aft_normal_check_nearest_stuck(a, fricreg_aft_jenkins_normal_sampled, 1e-12);
    /* the 3-D contact on a line, marched from the centre, stops at the same slider */
    const double u[14] = {0.0, 1.0, 0, 0, 0, 0, 0}, g[7] = {0.0, 0.5, 0, 0, 0, 0, 0};
    double f[14], nf[7], f1[7], nf1[7];
    for (double n0 = 1.0; n0 < 1.75; n0 += 0.1) {
        ck_assert_int_eq(fricreg_aft_jenkins_2d_normal_sampled(a, 1, 1, n0, 1, 7, u, g, f, nf,
                                                               NULL),
                         FRICREG_OK);
        ck_assert_int_eq(fricreg_aft_jenkins_normal_sampled(a, 1, 1, n0, 1, 7, u, g, f1, nf1, NULL),
                         FRICREG_OK);
        for (int i = 0; i < 7; i++)
            ck_assert_double_le(fabs(f[i] - f1[i]), 1e-12);
    }
    fricreg_aft_free(a);
}
END_TEST

START_TEST(bad_input)
{
    const double u[NC] = {0.3, 1.0, 0, 0, 0, 0, 0}, g[NC] = {0.1, 0.2, 0, 0, 0, 0, 0};
    double f[NC], nf[NC], jac[4 * NC * NC];
    fricreg_aft *a = make(H, NS), *exact_only = make(H, 0);
    aft_normal_check_bad_input(a, fricreg_aft_jenkins_normal_sampled, "jenkins_normal_sampled");
    /* an object made for the exact path only (no samples) refuses the sampled one */
    for (int i = 0; i < NC; i++)
        f[i] = nf[i] = SENTINEL;
    ck_assert_int_eq(fricreg_aft_jenkins_normal_sampled(exact_only, 1, 1, 1, 1, NC, u, g, f, nf,
                                                        jac),
                     FRICREG_EINVAL);
    for (int i = 0; i < NC; i++) {
        ck_assert_double_eq(f[i], SENTINEL);
        ck_assert_double_eq(nf[i], SENTINEL);
    }
    /* a spring far weaker than its bound: the sampled march's slider u - mu N/kt would leave
     * the double range (kt = 5e-324 against mu N up to 2); the exact path takes it */
    const double uk[NC] = {1.0, 1.0, 0, 0, 0, 0, 0}, gk[NC] = {1.0, 1.0, 0, 0, 0, 0, 0};
    for (int i = 0; i < NC; i++)
        f[i] = nf[i] = SENTINEL;
    ck_assert_int_eq(fricreg_aft_jenkins_normal_sampled(a, 5e-324, 1, 0, 1, NC, uk, gk, f, nf, jac),
                     FRICREG_ENONFINITE);
    ck_assert_ptr_nonnull(strstr(fricreg_aft_errmsg(a), "slider's excursion"));
    for (int i = 0; i < NC; i++) {
        ck_assert_double_eq(f[i], SENTINEL);
        ck_assert_double_eq(nf[i], SENTINEL);
    }
    ck_assert_int_eq(fricreg_aft_jenkins_normal_exact(a, 5e-324, 1, 0, 1, NC, uk, gk, f, nf, jac),
                     FRICREG_OK);
    for (int i = 0; i < NC; i++)
        ck_assert(isfinite(f[i]) && fabs(f[i]) <= 2.0 * 2.0);
    fricreg_aft_free(exact_only);
    fricreg_aft_free(a);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("aft_normal");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, constant_preload_is_jenkins);
    tcase_add_test(tc, open_throughout_is_zero);
    tcase_add_test(tc, against_the_time_domain_element);
    tcase_add_test(tc, jacobian_against_differences);
    tcase_add_test(tc, nearest_stuck_slider);
    tcase_add_test(tc, bad_input);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
