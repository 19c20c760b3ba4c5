/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_line_search.c — the one backtracking line search of the library's Newton iterations
 * (src/base/line_search.h), white box on the static library:
 *   - the trials: alpha0, alpha0/2, ... until one is accepted, at most max_halvings halvings
 *     after the first; every rejected trial counted; a trial's error ends the search;
 *   - a direction twice the Newton step on a linear residual, r(alpha) = r0 (1 - 2 alpha): the
 *     full step only returns to |r0| and is rejected, its half reaches the root;
 *   - Armijo's two forms at their boundaries (Nocedal & Wright, Numerical Optimization, 2nd
 *     ed., Eq. 3.4, c1 = 1e-4). */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "base/line_search.h"
#include "fricreg.h"

/* A trial that records the steps it sees and accepts the one at index accept_at (-1: none),
 * or fails with fail_status at index fail_at (-1: never). */
struct recorder {
    double alpha[64];
    int count, accept_at, fail_at, fail_status;
};

static int record(void *user, double alpha, int *accept)
{
    struct recorder *r = user;
    int k = r->count++;
    r->alpha[k] = alpha;
    *accept = k == r->accept_at;
    return k == r->fail_at ? r->fail_status : FRICREG_OK;
}

START_TEST(halves_until_the_bound_counting_each_rejection)
{
    const int bounds[3] = {0, 10, 29};
    for (int b = 0; b < 3; b++) {
        int64_t rejected = 5;
        struct fr_line_search ls = {FR_ARMIJO, bounds[b], &rejected};
        struct recorder r = {{0}, 0, -1, -1, FRICREG_OK};
        int accepted = -1;
        ck_assert_int_eq(fr_line_search(&ls, 0.75, record, &r, &accepted), FRICREG_OK);
        ck_assert_int_eq(accepted, 0);
        ck_assert_int_eq(r.count, bounds[b] + 1);
        ck_assert_int_eq(rejected, 5 + bounds[b] + 1);
        for (int k = 0; k < r.count; k++)
            ck_assert_double_eq(r.alpha[k], ldexp(0.75, -k));
    }
}
END_TEST

START_TEST(stops_at_the_first_accepted_trial)
{
    int64_t rejected = 0;
    struct fr_line_search ls = {FR_ARMIJO, 30, &rejected};
    struct recorder r = {{0}, 0, 3, -1, FRICREG_OK};
    int accepted = 0;
    ck_assert_int_eq(fr_line_search(&ls, 1.0, record, &r, &accepted), FRICREG_OK);
    ck_assert_int_eq(accepted, 1);
    ck_assert_int_eq(r.count, 4);
    ck_assert_int_eq(rejected, 3);
    ck_assert_double_eq(r.alpha[3], 0.125);
    /* not counted: a NULL counter */
    struct fr_line_search quiet = {FR_ARMIJO, 30, NULL};
    struct recorder q = {{0}, 0, 1, -1, FRICREG_OK};
    ck_assert_int_eq(fr_line_search(&quiet, 1.0, record, &q, &accepted), FRICREG_OK);
    ck_assert_int_eq(accepted, 1);
    ck_assert_int_eq(q.count, 2);
}
END_TEST

START_TEST(a_trial_error_ends_the_search)
{
    int64_t rejected = 0;
    struct fr_line_search ls = {FR_ARMIJO, 30, &rejected};
    struct recorder r = {{0}, 0, -1, 2, FRICREG_ENOMEM};
    int accepted = 1;
    ck_assert_int_eq(fr_line_search(&ls, 1.0, record, &r, &accepted), FRICREG_ENOMEM);
    ck_assert_int_eq(accepted, 0);
    ck_assert_int_eq(r.count, 3);
    ck_assert_int_eq(rejected, 2); /* the failed trial is not a rejection */
}
END_TEST

/* r(alpha) = r0 (1 - 2 alpha), merit |r|: the direction is twice the Newton step. */
struct overshoot {
    const struct fr_line_search *ls;
    double r0, r, taken;
};

static int overshoot_trial(void *user, double alpha, int *accept)
{
    struct overshoot *o = user;
    double r = o->r0 * (1.0 - 2.0 * alpha);
    *accept = fr_armijo_decrease(o->ls, fabs(o->r0), fabs(r), alpha);
    if (*accept) {
        o->r = r;
        o->taken = alpha;
    }
    return FRICREG_OK;
}

START_TEST(a_doubled_newton_step_is_halved_once)
{
    int64_t rejected = 0;
    struct fr_line_search ls = {FR_ARMIJO, 30, &rejected};
    struct overshoot o = {&ls, -3.5, -3.5, 0.0};
    int accepted = 0;
    ck_assert_int_eq(fr_line_search(&ls, 1.0, overshoot_trial, &o, &accepted), FRICREG_OK);
    ck_assert_int_eq(accepted, 1);
    ck_assert_double_eq(o.taken, 0.5);
    ck_assert_double_eq(o.r, 0.0);
    ck_assert_int_eq(rejected, 1);
}
END_TEST

START_TEST(armijo_at_its_boundaries)
{
    struct fr_line_search ls = {FR_ARMIJO, 30, NULL};
    /* phi_t <= (1 - 1e-4 alpha) phi0: at alpha = 1/2 and phi0 = 2 the bound is 1.9999 */
    ck_assert(fr_armijo_decrease(&ls, 2.0, 1.9999 - 1e-12, 0.5));
    ck_assert(!fr_armijo_decrease(&ls, 2.0, 1.9999 + 1e-12, 0.5));
    ck_assert(!fr_armijo_decrease(&ls, 2.0, 2.0, 0.5)); /* no decrease */
    ck_assert(!fr_armijo_decrease(&ls, 2.0, NAN, 1.0));
    /* change <= c1 slope, slope < 0 */
    ck_assert(fr_armijo_holds(&ls, -1e-4, -1.0));
    ck_assert(!fr_armijo_holds(&ls, -0.99e-4, -1.0));
    ck_assert(!fr_armijo_holds(&ls, -1.0, 0.0)); /* no descent: never */
    ck_assert(!fr_armijo_holds(&ls, NAN, -1.0));
}
END_TEST

static Suite *line_search_suite(void)
{
    Suite *s = suite_create("line_search");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, halves_until_the_bound_counting_each_rejection);
    tcase_add_test(tc, stops_at_the_first_accepted_trial);
    tcase_add_test(tc, a_trial_error_ends_the_search);
    tcase_add_test(tc, a_doubled_newton_step_is_halved_once);
    tcase_add_test(tc, armijo_at_its_boundaries);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(line_search_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
