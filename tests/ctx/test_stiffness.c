/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_stiffness.c — Check suite for fricreg_ctx_stick_stiffness and the partition setter.
 *
 * Expected values in closed form. Two blocks (paper's Eqs. (7)): W = [[1, -1], [-1, 2]], with
 * mun = (10, 5), eps = 0.02, so law (4)'s slopes are s = 2 mun/eps = (1000, 500).
 * Consistent law: max_i W_ii s_i = max(1000, 1000) = 1000.
 * Paper's partition: D^1/2 W D^1/2 = [[1000, -sqrt(5e5)], [-sqrt(5e5), 1000]], whose largest
 * eigenvalue is 1000 + sqrt(5e5) = 1000 (1 + 1/sqrt 2) = 1707.1067811865476: 1.707x the
 * per-contact bound (docs/coupled.md). Law (3) halves the slopes: 853.55339059327378 whatever the
 * partition, since (3) does not read f_eq. */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg.h"

#define TOL 1e-10 /* relative; GSL's symmetric eigensolver on a 2x2 */

static const double W2B[4] = {1.0, -1.0, -1.0, 2.0};
static const double MUN[2] = {10.0, 5.0};

static fricreg_ctx *make_two_block(int law)
{
    fricreg_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_ctx_create(2, &ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, W2B), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, 2, MUN), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, law, 0.02), FRICREG_OK);
    return ctx;
}

static double stiffness(fricreg_ctx *ctx)
{
    double lambda = -1.0;
    ck_assert_int_eq(fricreg_ctx_stick_stiffness(ctx, &lambda), FRICREG_OK);
    return lambda;
}

START_TEST(consistent_law_gives_the_diagonal)
{
    fricreg_ctx *ctx = make_two_block(FRICREG_LAW_QUINN);
    ck_assert_double_eq_tol(stiffness(ctx), 1000.0, TOL * 1000.0);
    fricreg_ctx_free(ctx);
}
END_TEST

START_TEST(paper_partition_gives_the_coupled_eigenvalue)
{
    fricreg_ctx *ctx = make_two_block(FRICREG_LAW_QUINN);
    ck_assert_int_eq(fricreg_ctx_set_partition(ctx, FRICREG_PARTITION_PAPER), FRICREG_OK);
    double expected = 1000.0 * (1.0 + 1.0 / sqrt(2.0));
    ck_assert_double_eq_tol(stiffness(ctx), expected, TOL * expected);
    ck_assert_int_eq(fricreg_ctx_set_partition(ctx, FRICREG_PARTITION_CONSISTENT), FRICREG_OK);
    ck_assert_double_eq_tol(stiffness(ctx), 1000.0, TOL * 1000.0);
    fricreg_ctx_free(ctx);
}
END_TEST

START_TEST(velocity_limited_is_coupled_under_either_partition)
{
    fricreg_ctx *ctx = make_two_block(FRICREG_LAW_VELOCITY_LIMITED);
    double expected = 500.0 * (1.0 + 1.0 / sqrt(2.0));
    ck_assert_double_eq_tol(stiffness(ctx), expected, TOL * expected);
    ck_assert_int_eq(fricreg_ctx_set_partition(ctx, FRICREG_PARTITION_PAPER), FRICREG_OK);
    ck_assert_double_eq_tol(stiffness(ctx), expected, TOL * expected);
    fricreg_ctx_free(ctx);
}
END_TEST

/* Diagonal W = (0.37, 2.385), mun = (1.5, 0.2), eps = 0.04: (4) gives max(0.37 * 75,
 * 2.385 * 10) = 27.75; tanh halves the slopes: 13.875; (1), (2), Karnopp: 0. */
START_TEST(diagonal_coupling_and_laws_without_slope)
{
    const double w[2] = {0.37, 2.385}, mun[2] = {1.5, 0.2};
    fricreg_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_ctx_create(2, &ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_coupling_diagonal(ctx, 2, w), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, 2, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 0.04), FRICREG_OK);
    ck_assert_double_eq_tol(stiffness(ctx), 27.75, 1e-12);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_TANH, 0.04), FRICREG_OK);
    ck_assert_double_eq_tol(stiffness(ctx), 13.875, 1e-12);
    const int flat[3] = {FRICREG_LAW_COULOMB, FRICREG_LAW_FORCE_BALANCE, FRICREG_LAW_KARNOPP};
    for (int k = 0; k < 3; k++) {
        ck_assert_int_eq(fricreg_ctx_set_law(ctx, flat[k], 0.04), FRICREG_OK);
        ck_assert_double_eq(stiffness(ctx), 0.0);
    }
    fricreg_ctx_free(ctx);
}
END_TEST

START_TEST(errors)
{
    double lambda = -3.25;
    ck_assert_int_eq(fricreg_ctx_stick_stiffness(NULL, &lambda), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_ctx_set_partition(NULL, FRICREG_PARTITION_PAPER), FRICREG_ENULL);
    fricreg_ctx *ctx = make_two_block(FRICREG_LAW_QUINN);
    ck_assert_int_eq(fricreg_ctx_stick_stiffness(ctx, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_ctx_errcode(ctx), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_ctx_set_partition(ctx, 3), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_ctx_errcode(ctx), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_ctx_errmsg(ctx), "partition 3"));
    ck_assert_int_eq(fricreg_ctx_set_partition(ctx, 0), FRICREG_EINVAL);
    ck_assert_double_eq(lambda, -3.25);
    /* the failed setter kept the consistent partition */
    ck_assert_double_eq_tol(stiffness(ctx), 1000.0, TOL * 1000.0);
    fricreg_ctx_free(ctx);
}
END_TEST

static Suite *stiffness_suite(void)
{
    Suite *s = suite_create("stiffness");
    TCase *tc = tcase_create("stiffness");
    tcase_add_test(tc, consistent_law_gives_the_diagonal);
    tcase_add_test(tc, paper_partition_gives_the_coupled_eigenvalue);
    tcase_add_test(tc, velocity_limited_is_coupled_under_either_partition);
    tcase_add_test(tc, diagonal_coupling_and_laws_without_slope);
    tcase_add_test(tc, errors);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(stiffness_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
