/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_companion_estimate.c — the one decision of the a-posteriori error estimates
 * (src/base/companion_estimate.h), white box on the static library, against the formulas of
 * its header comment on quantities q(eps) = q0 + c eps^p whose error q - q0 is known:
 *   - in the range (d1 / d2 = 2^p, p >= 1/2): Richardson's correction with the observed order
 *     times the safety factor 2, of kind ASYMPTOTIC; at p = 1 and 2, and at p = 4 (faster
 *     than the law's orders), twice the true error; with d2 below 1e-9 of the quantity,
 *     2 |d1| + |d2|, ASYMPTOTIC too;
 *   - below it (a stall, 1 <= d1 / d2 < 2^(1/2), or differences of opposite signs): the bound
 *     6.83 (|d1| + |d2|), of kind BOUND;
 *   - differences both below 1e-9 of the quantity: 4 (|d1| + |d2|) (the factor 2 and p = 1's
 *     Richardson tail 2), of kind BOUND (no order read from noise);
 *   - one companion: 3 |d1|, of kind ASSUMED;
 *   - an estimate that could not be formed (a non-finite value): BOUND. */
#include <check.h>
#include <math.h>
#include <stdlib.h>

#include "base/companion_estimate.h"

#define OUT_BOUND 6.82842712474619 /* 2 x 2^(1/2) / (2^(1/2) - 1) */

/* q0 + c eps^p at eps, eps/2, eps/4 through the estimator; the kind into *flag (set to 0
 * first: the estimator must set it). */
static double estimate(int estimator, double q0, double c, double p, int *flag)
{
    double q = q0 + c, q2 = q0 + c * pow(0.5, p), q4 = q0 + c * pow(0.25, p);
    *flag = 0;
    return fr_companion_estimate(estimator, q, q2, q4, flag);
}

START_TEST(in_range_it_is_richardson_times_two)
{
    const double orders[4] = {0.6, 1.0, 2.0, 2.4}; /* inside the band [1/2, 5/2] */
    for (int k = 0; k < 4; k++) {
        int flag;
        double p = orders[k], c = -0.37, err = c; /* q(eps) - q0 */
        double e = estimate(FRICREG_ESTIMATE_TWO_COMPANIONS, 5.0, c, p, &flag);
        ck_assert_int_eq(flag, FRICREG_EST_KIND_ASYMPTOTIC);
        /* Richardson with the exact order recovers the error; the estimate is twice it */
        ck_assert_double_eq_tol(e, 2.0 * fabs(err), 1e-12 * fabs(err));
    }
}
END_TEST

START_TEST(a_stall_gets_the_bound_of_kind_bound)
{
    /* d1 / d2 = 1.2 (order 0.26, below the band): q and q2 nearly agree on a wrong value */
    double q = 1.0 + 0.012 + 0.01, q2 = 1.0 + 0.01, q4 = 1.0;
    int flag = 0;
    double e = fr_companion_estimate(FRICREG_ESTIMATE_TWO_COMPANIONS, q, q2, q4, &flag);
    ck_assert_int_eq(flag, FRICREG_EST_KIND_BOUND);
    ck_assert_double_eq_tol(e, OUT_BOUND * (0.012 + 0.01), 1e-12);
    /* differences of opposite signs: no order */
    flag = 0;
    e = fr_companion_estimate(FRICREG_ESTIMATE_TWO_COMPANIONS, 1.0, 1.1, 1.05, &flag);
    ck_assert_int_eq(flag, FRICREG_EST_KIND_BOUND);
    ck_assert_double_eq_tol(e, OUT_BOUND * (0.1 + 0.05), 1e-12);
}
END_TEST

START_TEST(above_the_law_s_orders_still_richardson)
{
    int flag;
    double e = estimate(FRICREG_ESTIMATE_TWO_COMPANIONS, 2.0, 0.3, 4.0, &flag); /* r = 16 */
    ck_assert_int_eq(flag, FRICREG_EST_KIND_ASYMPTOTIC);
    ck_assert_double_eq_tol(e, 2.0 * 0.3, 1e-12); /* twice the true error */
    /* q2 and q4 equal to 1e-9 of q: the limit of r -> infinity, plus the difference left */
    flag = 0;
    e = fr_companion_estimate(FRICREG_ESTIMATE_TWO_COMPANIONS, 1.5, 1.0 + 4e-10, 1.0, &flag);
    ck_assert_int_eq(flag, FRICREG_EST_KIND_ASYMPTOTIC);
    ck_assert_double_eq_tol(e, 2.0 * (0.5 - 4e-10) + 4e-10, 1e-15);
}
END_TEST

START_TEST(noise_keeps_the_factor_and_the_tail)
{
    int flag = 0;
    double e = fr_companion_estimate(FRICREG_ESTIMATE_TWO_COMPANIONS, 1.0 + 4e-10, 1.0 - 3e-10, 1.0,
                                     &flag);
    ck_assert_int_eq(flag, FRICREG_EST_KIND_BOUND);
    ck_assert_double_eq_tol(e, 4.0 * (7e-10 + 3e-10), 1e-15);
}
END_TEST

START_TEST(one_companion_is_three_times_the_difference)
{
    int flag;
    double e = estimate(FRICREG_ESTIMATE_ONE_COMPANION, 5.0, 0.4, 1.0, &flag);
    ck_assert_int_eq(flag, FRICREG_EST_KIND_ASSUMED);
    ck_assert_double_eq_tol(e, 3.0 * 0.2, 1e-12);
}
END_TEST

START_TEST(no_estimate_is_a_bound)
{
    int flag = 0;
    double e = fr_companion_estimate(FRICREG_ESTIMATE_TWO_COMPANIONS, INFINITY, 1.0, 1.0, &flag);
    ck_assert(!(e < INFINITY));
    ck_assert_int_eq(flag, FRICREG_EST_KIND_BOUND);
    ck_assert_str_eq(fr_estimate_kind_name(FRICREG_EST_KIND_ASYMPTOTIC), "asymptotic");
    ck_assert_str_eq(fr_estimate_kind_name(FRICREG_EST_KIND_BOUND), "bound");
    ck_assert_str_eq(fr_estimate_kind_name(FRICREG_EST_KIND_ASSUMED), "assumed");
    ck_assert_str_eq(fr_estimate_kind_name(0), "unknown");
}
END_TEST

int main(void)
{
    Suite *s = suite_create("companion_estimate");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, in_range_it_is_richardson_times_two);
    tcase_add_test(tc, a_stall_gets_the_bound_of_kind_bound);
    tcase_add_test(tc, above_the_law_s_orders_still_richardson);
    tcase_add_test(tc, noise_keeps_the_factor_and_the_tail);
    tcase_add_test(tc, one_companion_is_three_times_the_difference);
    tcase_add_test(tc, no_estimate_is_a_bound);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
