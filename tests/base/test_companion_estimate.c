/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_companion_estimate.c — the one decision of the a-posteriori error estimates
 * (src/base/companion_estimate.h), white box on the static library, against the formulas of
 * its header comment on quantities q(eps) = q0 + c eps^p whose error q - q0 is known:
 *   - in the range (d1 / d2 = 2^p, p >= 1/2): Richardson's correction with the observed order
 *     times the safety factor 2, of kind ASYMPTOTIC; at p = 1 and 2, and at p = 4 (faster
 *     than the law's orders), twice the true error; with d2 below 1e-9 of the quantity,
 *     2 |d1| + |d2|, ASYMPTOTIC too;
 *   - below it (a stall, 1 <= d1 / d2 < 2^(1/2), or differences of opposite signs): the bound
 *     6.83 (|d1| + |d2|), of kind BOUND; but with opposite signs and |d2| <= |d1| / 8, on law
 *     (4)'s two orders q = q0 + a eps + b eps^2 (b / a in (-4/3, -10/9]), 2 (|d1| + 2 |d2|),
 *     of kind BOUND, at least twice the error (q - q0 = (2/3) d1 + (8/3) d2 exactly), and the
 *     frame's storey-2 peak of bench/frame_estimate.c at 5 ms (d1 = 7.35e-4, d2 = -4.3e-5);
 *   - differences both below 1e-9 of the quantity: 4 (|d1| + |d2|) (the factor 2 and p = 1's
 *     Richardson tail 2), of kind BOUND (no order read from noise);
 *   - one companion: 3 |d1|, of kind ASSUMED;
 *   - an estimate that could not be formed (a non-finite value): BOUND;
 *   - coarser companions, q2 = q(2 eps), q4 = q(4 eps): r = d2 / d1 = 2^p in [2^(1/2), 2^2]
 *     gives 2 |d1| / (r - 1), twice the run's own error, of kind ASYMPTOTIC; outside it (a
 *     stall below, where d1 is small against d2; an order above 2, which a stall imitates;
 *     opposite signs) 4.83 (|d1| + |d2|), BOUND; noise 4 (|d1| + |d2|), BOUND; one companion
 *     3 |d1|, ASSUMED. On law (4)'s two orders, q = q0 + a eps + b eps^2: with a, b of one
 *     sign the worst Richardson quotient, 4/3 at r = 3, is bounded 1.5x; of opposite signs at
 *     r = 8, where Richardson's |d1| / 7 is 7x under, the bound. */
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

/* Law (4)'s two orders at eps, eps/2, eps/4 with a = 1, b = beta: where d1 / d2 <= -8
 * (beta in (-4/3, -10/9]) the estimate is 2 (|d1| + 2 |d2|), of kind BOUND, at least twice the
 * error a + b; at d1 / d2 = -4 still the bound 6.83 (|d1| + |d2|). */
static double two_orders(double beta, double *err, double *d1, double *d2, int *flag)
{
    double q = 1.0 + beta, q2 = 0.5 + beta / 4.0, q4 = 0.25 + beta / 16.0;
    *err = q, *d1 = q - q2, *d2 = q2 - q4;
    *flag = 0;
    return fr_companion_estimate(FRICREG_ESTIMATE_TWO_COMPANIONS, q, q2, q4, flag);
}

START_TEST(opposite_signs_near_the_limit)
{
    int flag, cases = 0;
    double err, d1, d2;
    for (double beta = -4.0 / 3.0 + 1e-3; beta <= -10.0 / 9.0 - 1e-9; beta += 1e-3) {
        double e = two_orders(beta, &err, &d1, &d2, &flag);
        ck_assert_double_le(d1 / d2, -8.0);
        ck_assert_int_eq(flag, FRICREG_EST_KIND_BOUND);
        ck_assert_double_eq_tol(e, 2.0 * (fabs(d1) + 2.0 * fabs(d2)), 1e-14);
        ck_assert_double_eq_tol(err, 2.0 / 3.0 * d1 + 8.0 / 3.0 * d2, 1e-14);
        ck_assert_double_ge(e, 2.0 * fabs(err));
        cases++;
    }
    ck_assert_int_ge(cases, 200);
    double e = two_orders(-1.0, &err, &d1, &d2, &flag); /* d1 / d2 = -4: no order */
    ck_assert_double_eq_tol(d1 / d2, -4.0, 1e-12);
    ck_assert_int_eq(flag, FRICREG_EST_KIND_BOUND);
    ck_assert_double_eq_tol(e, OUT_BOUND * (fabs(d1) + fabs(d2)), 1e-14);
    /* the differences of the frame's storey-2 peak at 5 ms (a peak of 0.1 m taken here) */
    double q = 0.1, q2 = q - 7.35e-4, q4 = q2 + 4.3e-5;
    flag = 0;
    e = fr_companion_estimate(FRICREG_ESTIMATE_TWO_COMPANIONS, q, q2, q4, &flag);
    ck_assert_int_eq(flag, FRICREG_EST_KIND_BOUND);
    ck_assert_double_eq_tol(e, 2.0 * (7.35e-4 + 2.0 * 4.3e-5), 1e-15);
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

#define OUT_COARSER 4.82842712474619 /* 2 / (2^(1/2) - 1) */

/* q0 + c eps^p at eps, 2 eps, 4 eps through the coarser estimator. */
static double coarser(int estimator, double q0, double c, double p, int *flag)
{
    double q = q0 + c, q2 = q0 + c * pow(2.0, p), q4 = q0 + c * pow(4.0, p);
    *flag = 0;
    return fr_companion_estimate_coarser(estimator, q, q2, q4, flag);
}

START_TEST(coarser_in_range_is_richardson_times_two)
{
    const double orders[4] = {0.6, 1.0, 1.5, 2.0}; /* inside the band [1/2, 2] */
    for (int k = 0; k < 4; k++) {
        int flag;
        double c = 0.013, e = coarser(FRICREG_ESTIMATE_TWO_COMPANIONS, -3.0, c, orders[k], &flag);
        ck_assert_int_eq(flag, FRICREG_EST_KIND_ASYMPTOTIC);
        ck_assert_double_eq_tol(e, 2.0 * c, 1e-12 * c);
    }
}
END_TEST

START_TEST(coarser_out_of_range_is_the_bound)
{
    int flag;
    /* order 4 (r = 16): above the band, what a stall at the fine levels looks like */
    double e = coarser(FRICREG_ESTIMATE_TWO_COMPANIONS, 2.0, 0.01, 4.0, &flag);
    ck_assert_int_eq(flag, FRICREG_EST_KIND_BOUND);
    ck_assert_double_eq_tol(e, OUT_COARSER * (0.01 * 15.0 + 0.01 * 240.0), 1e-12);
    /* order 2.9 (r = 7.46): above the law's higher order, where no factor on Richardson's is
     * safe (coarser_two_orders) */
    e = coarser(FRICREG_ESTIMATE_TWO_COMPANIONS, 2.0, 0.01, 2.9, &flag);
    ck_assert_int_eq(flag, FRICREG_EST_KIND_BOUND);
    ck_assert_double_eq_tol(e, OUT_COARSER * 0.01 * (pow(2.0, 2.9) - 1.0) * (1.0 + pow(2.0, 2.9)),
                            1e-12);
    /* order 0.26 (r = 1.2): below it */
    e = coarser(FRICREG_ESTIMATE_TWO_COMPANIONS, 2.0, 0.01, log2(1.2), &flag);
    ck_assert_int_eq(flag, FRICREG_EST_KIND_BOUND);
    ck_assert_double_eq_tol(e, OUT_COARSER * (0.01 * 0.2 + 0.01 * 0.24), 1e-12);
    /* the run and its nearer companion equal to 1e-9, the farther off: a stall, bounded */
    flag = 0;
    e = fr_companion_estimate_coarser(FRICREG_ESTIMATE_TWO_COMPANIONS, 1.0, 1.0 + 3e-10, 1.2,
                                      &flag);
    ck_assert_int_eq(flag, FRICREG_EST_KIND_BOUND);
    ck_assert_double_eq_tol(e, OUT_COARSER * (3e-10 + (0.2 - 3e-10)), 1e-12);
    /* opposite signs */
    flag = 0;
    e = fr_companion_estimate_coarser(FRICREG_ESTIMATE_TWO_COMPANIONS, 1.0, 1.1, 1.05, &flag);
    ck_assert_int_eq(flag, FRICREG_EST_KIND_BOUND);
    ck_assert_double_eq_tol(e, OUT_COARSER * (0.1 + 0.05), 1e-12);
}
END_TEST

/* Law (4)'s two orders, q(h) = q0 + a h + b h^2 at h = 1, 2, 4 (the run's error a + b):
 *   - a = 0.03, b = 0.01 (one sign, b / a = 1/3): q - q0 = 0.04, 0.10, 0.28, so d1 = -0.06,
 *     d2 = -0.18, r = 3, the worst case of one sign (companion_estimate.c): Richardson's
 *     |d1| / 2 = 0.03 is 3/4 of the error, the estimate 2 |d1| / 2 = 0.06 is 1.5x it;
 *   - a = 0.03, b = -0.015 (opposite signs, b / a = -1/2): q - q0 = 0.015, 0, -0.12, so
 *     d1 = 0.015, d2 = 0.12, r = 8: Richardson's |d1| / 7 is 7x under the error 0.015 (the
 *     range up to 2^3 made it asymptotic at 2 |d1| / 7, 0.29x the error); the bound
 *     4.83 (0.015 + 0.12) = 0.652 >= 0.015. */
START_TEST(coarser_two_orders)
{
    int flag = 0;
    double q0 = 1.0;
    double e = fr_companion_estimate_coarser(FRICREG_ESTIMATE_TWO_COMPANIONS, q0 + 0.04, q0 + 0.10,
                                             q0 + 0.28, &flag);
    ck_assert_int_eq(flag, FRICREG_EST_KIND_ASYMPTOTIC);
    ck_assert_double_eq_tol(e / 0.04, 1.5, 1e-12);
    flag = 0;
    e = fr_companion_estimate_coarser(FRICREG_ESTIMATE_TWO_COMPANIONS, q0 + 0.015, q0, q0 - 0.12,
                                      &flag);
    ck_assert_int_eq(flag, FRICREG_EST_KIND_BOUND);
    ck_assert_double_eq_tol(e, OUT_COARSER * (0.015 + 0.12), 1e-12);
    ck_assert(e >= 0.015);
}
END_TEST

START_TEST(coarser_noise_one_companion_and_no_estimate)
{
    int flag = 0;
    double e = fr_companion_estimate_coarser(FRICREG_ESTIMATE_TWO_COMPANIONS, 1.0 + 4e-10,
                                             1.0 - 3e-10, 1.0, &flag);
    ck_assert_int_eq(flag, FRICREG_EST_KIND_BOUND);
    ck_assert_double_eq_tol(e, 4.0 * (7e-10 + 3e-10), 1e-15);
    e = coarser(FRICREG_ESTIMATE_ONE_COMPANION, 5.0, 0.4, 1.0, &flag);
    ck_assert_int_eq(flag, FRICREG_EST_KIND_ASSUMED);
    ck_assert_double_eq_tol(e, 3.0 * 0.4, 1e-12);
    flag = 0;
    e = fr_companion_estimate_coarser(FRICREG_ESTIMATE_TWO_COMPANIONS, NAN, 1.0, 1.0, &flag);
    ck_assert(!(e < INFINITY));
    ck_assert_int_eq(flag, FRICREG_EST_KIND_BOUND);
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
    tcase_add_test(tc, opposite_signs_near_the_limit);
    tcase_add_test(tc, above_the_law_s_orders_still_richardson);
    tcase_add_test(tc, noise_keeps_the_factor_and_the_tail);
    tcase_add_test(tc, one_companion_is_three_times_the_difference);
    tcase_add_test(tc, no_estimate_is_a_bound);
    tcase_add_test(tc, coarser_in_range_is_richardson_times_two);
    tcase_add_test(tc, coarser_out_of_range_is_the_bound);
    tcase_add_test(tc, coarser_two_orders);
    tcase_add_test(tc, coarser_noise_one_companion_and_no_estimate);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
