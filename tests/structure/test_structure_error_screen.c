/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_structure_error_screen.c — the screened error estimate (fricreg_structure_set_error_companions
 * with FRICREG_COMPANIONS_AUTO, the default): the coarser companions screen, and where their
 * estimate would warn or fails the finer companions run from the start and give the estimate.
 *
 * Where the numbers come from: the two estimators themselves, run alone on the same structure
 * (FRICREG_COMPANIONS_COARSER, FRICREG_COMPANIONS_FINER). A quiet screen's estimates are the
 * coarser estimator's bit for bit; a confirmed one's are the finer estimator's bit for bit,
 * with the same warnings, and what the screen had said (FRICREG_SVALUE_SCREEN_PEAK_ERR,
 * _DISS_ERR) is the coarser estimator's largest peak estimate and summed dissipation
 * estimate. The scene: two masses on springs, a friction contact on the first (bound 0.3) and
 * a Jenkins element on the second (kt 25, slip force 0.2; GSL's steppers take the scene without
 * it), a load record on both, eps = 1e-3, Newmark at dt = 0.002 over 4 s; its coarser estimate
 * is quiet at the default answer tolerance, 1e-2 (the largest estimate, the contact's
 * dissipation, 0.5 % of the summed 0.118), and doubts at 1e-7. */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_structure.h"

#define N 2
#define DT 0.002
#define T_END 4.0
#define QUIET_RTOL 1e-2
#define DOUBTING_RTOL 1e-7

static fricreg_structure *scene(int companions, int jenkins)
{
    double K[N * N] = {40.0, -15.0, -15.0, 25.0}, J[N] = {1.0, 0.0}, Je[N] = {0.0, 1.0};
    double mun = 0.3, kt = 25.0, slip = 0.2, p[N] = {1.0, -0.6}, g[401];
    for (size_t k = 0; k < 401; k++)
        g[k] = sin(4.1 * 0.01 * (double)k) + 0.4 * sin(11.3 * 0.01 * (double)k);
    fricreg_structure *s = NULL;
    ck_assert_int_eq(fricreg_structure_create(N, 1, &s), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_stiffness(s, N, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_rayleigh(s, 0.05, 0.002), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_contacts(s, 1, N, J), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_bounds(s, 1, &mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_law(s, FRICREG_LAW_QUINN, 1e-3), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_load(s, N, p, 0.0, 0.01, 401, g), FRICREG_OK);
    if (jenkins)
        ck_assert_int_eq(fricreg_structure_set_jenkins(s, 1, N, Je, &kt, &slip), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_error_estimate(s, FRICREG_ESTIMATE_TWO_COMPANIONS),
                     FRICREG_OK);
    if (companions >= 0)
        ck_assert_int_eq(fricreg_structure_set_error_companions(s, companions), FRICREG_OK);
    return s;
}

/* Every estimate, its kind and the warnings' codes, in one array (kinds and codes as doubles:
 * exact), me the Jenkins elements (0 or 1); the length. */
#define OUT_LEN 32

static size_t estimates(fricreg_structure *s, size_t me, double out[OUT_LEN])
{
    size_t k = 0;
    int kinds[N];
    memset(out, 0, OUT_LEN * sizeof *out);
    ck_assert_int_eq(fricreg_structure_get_peak_displacement_error(s, N, out), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_dissipation_error(s, 1, out + N), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_jenkins_dissipation_error(s, me, out + N + 1),
                     FRICREG_OK); /* 0 without the element */
    k = N + 2;
    int quantities[] = {FRICREG_EST_PEAK_DISPLACEMENT, FRICREG_EST_DISSIPATION,
                        FRICREG_EST_ELEMENT_DISSIPATION};
    size_t counts[] = {N, 1, me};
    for (size_t q = 0; q < 3; q++) {
        ck_assert_int_eq(fricreg_structure_get_error_kind(s, quantities[q], counts[q], kinds),
                         FRICREG_OK);
        for (size_t i = 0; i < counts[q]; i++)
            out[k++] = kinds[i];
    }
    size_t nw = fricreg_structure_warning_count(s);
    out[k++] = (double)nw;
    for (size_t w = 0; w < nw && k < OUT_LEN; w++) {
        int code = -1;
        ck_assert_int_eq(fricreg_structure_get_warning(s, w, &code, NULL, 0), FRICREG_OK);
        out[k++] = code;
    }
    return k;
}

static void same_estimates(fricreg_structure *a, fricreg_structure *b, size_t me, const char *what)
{
    double x[OUT_LEN], y[OUT_LEN];
    size_t n = estimates(a, me, x);
    ck_assert_uint_eq(estimates(b, me, y), n);
    for (size_t k = 0; k < n; k++)
        ck_assert_msg(memcmp(&x[k], &y[k], sizeof(double)) == 0, "%s, entry %zu: %.17g and %.17g",
                      what, k, x[k], y[k]);
}

static double value(const fricreg_structure *s, int which)
{
    double x = -7.0;
    ck_assert_int_eq(fricreg_structure_get_value(s, which, &x), FRICREG_OK);
    return x;
}

/* What the screen said equals the coarser estimator's largest peak estimate and its summed
 * dissipation estimate (the contact's, then the element's, as the warning sums them). */
static void screen_said(const fricreg_structure *s, fricreg_structure *coarser, size_t me)
{
    double out[OUT_LEN];
    estimates(coarser, me, out);
    ck_assert_double_eq(value(s, FRICREG_SVALUE_SCREEN_PEAK_ERR), fmax(out[0], out[1]));
    ck_assert_double_eq(value(s, FRICREG_SVALUE_SCREEN_DISS_ERR), out[N] + out[N + 1]);
}

/* The default is the screen; quiet, its estimates are the coarser estimator's and nothing
 * confirmed. */
START_TEST(test_quiet_screen_is_the_coarser_estimate)
{
    fricreg_structure *s = scene(-1, 1), *coarser = scene(FRICREG_COMPANIONS_COARSER, 1);
    ck_assert_double_eq(value(s, FRICREG_SVALUE_COMPANIONS_USED), -1.0); /* none yet */
    ck_assert_int_eq(fricreg_structure_run(s, DT, T_END), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run(coarser, DT, T_END), FRICREG_OK);
    same_estimates(s, coarser, 1, "quiet screen against coarser");
    ck_assert_double_eq(value(s, FRICREG_SVALUE_COMPANIONS_USED), FRICREG_COMPANIONS_COARSER);
    ck_assert(isnan(value(s, FRICREG_SVALUE_SCREEN_PEAK_ERR)));
    ck_assert(isnan(value(s, FRICREG_SVALUE_SCREEN_DISS_ERR)));
    ck_assert_double_gt(value(s, FRICREG_SVALUE_COMPANION_CPU), 0.0);
    ck_assert_double_eq(value(coarser, FRICREG_SVALUE_COMPANIONS_USED), FRICREG_COMPANIONS_COARSER);
    fricreg_structure_free(coarser);
    fricreg_structure_free(s);
}
END_TEST

/* Doubting, the finer companions run from the start: the finer estimator's estimates and
 * warnings bit for bit, under Newmark in one call and under an adaptive run_ode in one call. */
static void check_confirmed(int adaptive)
{
    fricreg_structure *s = scene(FRICREG_COMPANIONS_AUTO, !adaptive);
    fricreg_structure *finer = scene(FRICREG_COMPANIONS_FINER, !adaptive);
    fricreg_structure *coarser = scene(FRICREG_COMPANIONS_COARSER, !adaptive);
    fricreg_structure *all[] = {s, finer, coarser};
    for (size_t k = 0; k < 3; k++) {
        ck_assert_int_eq(fricreg_structure_set_answer_rtol(all[k], DOUBTING_RTOL), FRICREG_OK);
        ck_assert_int_eq(adaptive ? fricreg_structure_run_ode(all[k], FRICREG_INT_RKF45, DT, 1e-6,
                                                              FRICREG_ATOL_FROM_EPS, T_END)
                                  : fricreg_structure_run(all[k], DT, T_END),
                         FRICREG_OK);
    }
    same_estimates(s, finer, !adaptive, "confirmed against finer");
    ck_assert_double_eq(value(s, FRICREG_SVALUE_COMPANIONS_USED), FRICREG_COMPANIONS_FINER);
    screen_said(s, coarser, !adaptive);
    ck_assert_uint_gt(fricreg_structure_warning_count(s), 0); /* the finer doubt it too */
    fricreg_structure_free(coarser);
    fricreg_structure_free(finer);
    fricreg_structure_free(s);
}

START_TEST(test_doubting_screen_is_confirmed)
{
    check_confirmed(0);
    check_confirmed(1);
}
END_TEST

/* A screen that cannot form an estimate (fixed steps of one dt a call: the coarser steps need
 * 4 dt) is confirmed at the first call, +infinity the screen's word, the finer estimate bit
 * for bit (each later call followed as finer companions follow it). */
START_TEST(test_failed_screen_is_confirmed)
{
    fricreg_structure *s = scene(FRICREG_COMPANIONS_AUTO, 1);
    fricreg_structure *finer = scene(FRICREG_COMPANIONS_FINER, 1);
    for (int k = 0; k < 200; k++) {
        ck_assert_int_eq(fricreg_structure_step(s, DT), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_step(finer, DT), FRICREG_OK);
    }
    same_estimates(s, finer, 1, "failed screen against finer");
    ck_assert_double_eq(value(s, FRICREG_SVALUE_COMPANIONS_USED), FRICREG_COMPANIONS_FINER);
    ck_assert(isinf(value(s, FRICREG_SVALUE_SCREEN_PEAK_ERR)));
    ck_assert(isinf(value(s, FRICREG_SVALUE_SCREEN_DISS_ERR)));
    fricreg_structure_free(finer);
    fricreg_structure_free(s);
}
END_TEST

/* The parked finer pair sees every setting when the structure did: a bound changed between
 * two quiet calls, then a call of another dt, then a doubt (the answer tolerance lowered, which
 * companions do not take): the finer estimator's estimates, with the same calls and changes,
 * bit for bit. */
START_TEST(test_changes_between_calls)
{
    fricreg_structure *s = scene(FRICREG_COMPANIONS_AUTO, 1);
    fricreg_structure *finer = scene(FRICREG_COMPANIONS_FINER, 1);
    fricreg_structure *both[] = {s, finer};
    double mun = 0.22;
    for (size_t k = 0; k < 2; k++) {
        ck_assert_int_eq(fricreg_structure_run(both[k], DT, 1.0), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_set_bounds(both[k], 1, &mun), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_run(both[k], DT, 2.0), FRICREG_OK);
        if (k == 0) /* still the screen */
            ck_assert_double_eq(value(s, FRICREG_SVALUE_COMPANIONS_USED),
                                FRICREG_COMPANIONS_COARSER);
        ck_assert_int_eq(fricreg_structure_set_answer_rtol(both[k], DOUBTING_RTOL), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_run(both[k], 0.5 * DT, T_END), FRICREG_OK);
    }
    same_estimates(s, finer, 1, "changes between calls");
    ck_assert_double_eq(value(s, FRICREG_SVALUE_COMPANIONS_USED), FRICREG_COMPANIONS_FINER);
    ck_assert(isfinite(value(s, FRICREG_SVALUE_SCREEN_PEAK_ERR)));
    fricreg_structure_free(finer);
    fricreg_structure_free(s);
}
END_TEST

/* The screen is judged where the estimate is read, not at each call's end: the run in calls of
 * 50 dt, read at its end only, keeps the coarser estimate (bit for bit the coarser estimator's
 * in the same calls), although a read after its first call, at 0.1 s, where its quantities are
 * small and the coarser bounds doubt them, confirms with the finer companions. */
START_TEST(test_judged_where_read)
{
    fricreg_structure *s = scene(FRICREG_COMPANIONS_AUTO, 1);
    fricreg_structure *coarser = scene(FRICREG_COMPANIONS_COARSER, 1);
    fricreg_structure *early = scene(FRICREG_COMPANIONS_AUTO, 1);
    const int calls = (int)lround(T_END / (50 * DT));
    for (int k = 1; k <= calls; k++) {
        double t = k == calls ? T_END : 50 * DT * k;
        ck_assert_int_eq(fricreg_structure_run(s, DT, t), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_run(coarser, DT, t), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_run(early, DT, t), FRICREG_OK);
        if (k == 1)
            ck_assert_double_eq(value(early, FRICREG_SVALUE_COMPANIONS_USED),
                                FRICREG_COMPANIONS_FINER);
    }
    same_estimates(s, coarser, 1, "read at the end only");
    ck_assert_double_eq(value(s, FRICREG_SVALUE_COMPANIONS_USED), FRICREG_COMPANIONS_COARSER);
    ck_assert_double_eq(value(early, FRICREG_SVALUE_COMPANIONS_USED), FRICREG_COMPANIONS_FINER);
    fricreg_structure_free(early);
    fricreg_structure_free(coarser);
    fricreg_structure_free(s);
}
END_TEST

/* A new run (set_initial) starts with the screen again; which = 2 is accepted, 3 refused. */
START_TEST(test_new_run_screens_again)
{
    fricreg_structure *s = scene(FRICREG_COMPANIONS_AUTO, 1);
    ck_assert_int_eq(fricreg_structure_set_answer_rtol(s, DOUBTING_RTOL), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run(s, DT, 1.0), FRICREG_OK);
    ck_assert_double_eq(value(s, FRICREG_SVALUE_COMPANIONS_USED), FRICREG_COMPANIONS_FINER);
    double zero[N] = {0.0, 0.0};
    ck_assert_int_eq(fricreg_structure_set_initial(s, N, zero, zero), FRICREG_OK);
    ck_assert_double_eq(value(s, FRICREG_SVALUE_COMPANIONS_USED), -1.0);
    ck_assert_int_eq(fricreg_structure_set_answer_rtol(s, QUIET_RTOL), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run(s, DT, 1.0), FRICREG_OK);
    ck_assert_double_eq(value(s, FRICREG_SVALUE_COMPANIONS_USED), FRICREG_COMPANIONS_COARSER);
    ck_assert(isnan(value(s, FRICREG_SVALUE_SCREEN_PEAK_ERR)));
    ck_assert_int_eq(fricreg_structure_set_error_companions(s, 3), FRICREG_EINVAL);
    ck_assert_double_eq(value(s, FRICREG_SVALUE_COMPANIONS_USED), FRICREG_COMPANIONS_COARSER);
    fricreg_structure_free(s);
}
END_TEST

int main(void)
{
    Suite *suite = suite_create("structure_error_screen");
    TCase *tc = tcase_create("screen");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, test_quiet_screen_is_the_coarser_estimate);
    tcase_add_test(tc, test_doubting_screen_is_confirmed);
    tcase_add_test(tc, test_failed_screen_is_confirmed);
    tcase_add_test(tc, test_changes_between_calls);
    tcase_add_test(tc, test_judged_where_read);
    tcase_add_test(tc, test_new_run_screens_again);
    suite_add_tcase(suite, tc);
    SRunner *sr = srunner_create(suite);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
