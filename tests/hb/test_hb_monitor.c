/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_monitor.c — Check suite for the harmonic-balance driver's monitor and work bound
 * (fricreg_hb_set_monitor, fricreg_hb_set_max_iterations; fricreg_hb.h).
 *
 * The model: 2 unit masses in a chain of springs (ground–1–2, K = [2.385 −1; −1 1.2]),
 * C = 0.03 K, one Jenkins element kt = 3.1, mu N = 0.45 on dof 1 against the ground, unit force
 * on dof 2; H = 5. Its branch from Omega = 0.4 to 2.2 crosses both resonances (some tens of
 * points); the nonlinear mode 0 from a = 0.05 to 5.
 *
 * Where the numbers come from: the unmonitored calls themselves. A monitor changes no
 * arithmetic, so a run that it watches (returning 0) equals the unwatched one bit for bit, and
 * a run it stops after k calls has stored exactly the unwatched run's first points; the counts
 * follow from the documented contract (called once per Newton step, iterations 1, 2, ..., no
 * call after the one that stopped, the bound's call N + 1 refused without calling it). */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_hb.h"

#define H 5
#define NC (2 * H + 1)
#define NQ NC /* one element */
#define MAXP 4000
#define SENTINEL (-777.125)

static fricreg_hb *chain(void)
{
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(2, 1, H, &hb), FRICREG_OK);
    const double M[4] = {1, 0, 0, 1}, K[4] = {2.385, -1, -1, 1.2};
    double C[4], J[2] = {1, 0}, kt = 3.1, mun = 0.45, pc[2] = {0, 1}, ps[2] = {0, 0};
    for (int i = 0; i < 4; i++)
        C[i] = 0.03 * K[i];
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 2, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, 2, C), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, 2, J, &kt, &mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, 2, pc, ps), FRICREG_OK);
    return hb;
}

/* The monitor's record: every call's arguments; stops (returns 1) at call stop_at (0: never);
 * with poke, tries the driver's other calls (each must be refused) and its getters. */
struct watch {
    int64_t calls, last;
    int64_t stop_at;
    int increasing; /* iterations were 1, 2, 3, ... */
    double first_parameter, last_parameter;
    fricreg_hb *hb;
    int poke, refused, getters_ok;
};

static int monitor(void *user, int64_t iterations, double parameter, double residual)
{
    struct watch *w = user;
    w->calls++;
    if (iterations != w->last + 1 || !(residual >= 0.0))
        w->increasing = 0;
    w->last = iterations;
    if (w->calls == 1)
        w->first_parameter = parameter;
    w->last_parameter = parameter;
    if (w->poke) {
        fricreg_hb *hb = w->hb;
        double q[NQ], x[2 * NC], one = 1.0, om = 0.0, rms[2];
        int refused = fricreg_hb_set_newton(hb, 1e-3, 3) == FRICREG_EINVAL &&
                      fricreg_hb_set_continuation(hb, 0.5, 0.1, 1.0, 3) == FRICREG_EINVAL &&
                      fricreg_hb_set_rayleigh(hb, 0.1, 0.1) == FRICREG_EINVAL &&
                      fricreg_hb_set_mass(hb, 2, (double[]){2, 0, 0, 2}) == FRICREG_EINVAL &&
                      fricreg_hb_set_elements(hb, 1, 2, (double[]){0, 1}, &one, &one) ==
                          FRICREG_EINVAL &&
                      fricreg_hb_set_stability(hb, 1) == FRICREG_EINVAL &&
                      fricreg_hb_set_monitor(hb, NULL, NULL) == FRICREG_EINVAL &&
                      fricreg_hb_set_max_iterations(hb, 1) == FRICREG_EINVAL &&
                      fricreg_hb_solve(hb, 1.0, NQ, NULL, q) == FRICREG_EINVAL &&
                      fricreg_hb_continue(hb, 1.0, 2.0, NQ, NULL) == FRICREG_EINVAL &&
                      fricreg_hb_continue_level(hb, 1.0, 0.0, 1.0, NQ, NULL) == FRICREG_EINVAL &&
                      fricreg_hb_nma(hb, 0, 0, 0.1, 1.0, 3) == FRICREG_EINVAL &&
                      fricreg_hb_peak(hb, 0, &om, &rms[0]) == FRICREG_EINVAL &&
                      fricreg_hb_displacement(hb, 2, NC, x) == FRICREG_EINVAL &&
                      fricreg_hb_point_displacement(hb, 0, 2, NC, x) == FRICREG_EINVAL;
        w->refused += refused;
        /* a getter answers (the points stored so far) */
        size_t k = fricreg_hb_points(hb);
        if (k == 0 || fricreg_hb_point(hb, k - 1, &om, 2, rms) == FRICREG_OK)
            w->getters_ok++;
    }
    return w->stop_at != 0 && w->calls >= w->stop_at;
}

static struct watch watching(fricreg_hb *hb, int64_t stop_at)
{
    return (struct watch){.stop_at = stop_at, .increasing = 1, .hb = hb};
}

/* The branch's stored points: Omega then the 2 RMS per point, into pts[3 k ..]; their count. */
static size_t points(fricreg_hb *hb, double *pts)
{
    size_t K = fricreg_hb_points(hb);
    ck_assert_uint_le(K, MAXP);
    for (size_t k = 0; k < K; k++)
        ck_assert_int_eq(fricreg_hb_point(hb, k, &pts[3 * k], 2, &pts[3 * k + 1]), FRICREG_OK);
    return K;
}

static int contains(const char *s, const char *part)
{
    return strstr(s, part) != NULL;
}

/* fricreg_hb_solve: a watching monitor sees iterations 1, 2, ... and changes nothing; one that
 * stops at its k-th call gets exactly k calls (no fallback after the stop), FRICREG_EWORK with
 * its message, q and the kept solution untouched. */
START_TEST(solve_watched_and_stopped)
{
    fricreg_hb *hb = chain();
    double q_ref[NQ], x_ref[2 * NC], q[NQ], x[2 * NC];
    /* the reference, unwatched, without a guess (the level start's branch) */
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.3, NQ, NULL, q_ref), FRICREG_OK);
    struct watch w = watching(hb, 0);
    ck_assert_int_eq(fricreg_hb_set_monitor(hb, monitor, &w), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.3, NQ, NULL, q), FRICREG_OK);
    ck_assert_int_gt(w.calls, 3);
    ck_assert(w.increasing);
    ck_assert_int_eq(w.last, w.calls);
    ck_assert(w.last_parameter > 0.0 && w.last_parameter <= 1.0); /* the level λ */
    ck_assert_mem_eq(q, q_ref, sizeof q);
    int64_t total = w.calls;
    /* a kept solution to be left alone: at another frequency, from a guess */
    ck_assert_int_eq(fricreg_hb_solve(hb, 0.9, NQ, q_ref, q), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_displacement(hb, 2, NC, x_ref), FRICREG_OK);
    for (int64_t k = 1; k <= total; k += total / 3) {
        w = watching(hb, k);
        for (int j = 0; j < NQ; j++)
            q[j] = SENTINEL;
        ck_assert_int_eq(fricreg_hb_solve(hb, 1.3, NQ, NULL, q), FRICREG_EWORK);
        ck_assert_int_eq(w.calls, k);
        ck_assert_int_eq(fricreg_hb_errcode(hb), FRICREG_EWORK);
        ck_assert_msg(contains(fricreg_hb_errmsg(hb), "solve: stopped by the monitor"), "%s",
                      fricreg_hb_errmsg(hb));
        for (int j = 0; j < NQ; j++)
            ck_assert(q[j] == SENTINEL);
        ck_assert_int_eq(fricreg_hb_displacement(hb, 2, NC, x), FRICREG_OK);
        ck_assert_mem_eq(x, x_ref, sizeof x);
    }
    /* the monitor removed: the unwatched result, bit for bit */
    ck_assert_int_eq(fricreg_hb_set_monitor(hb, NULL, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.3, NQ, NULL, q), FRICREG_OK);
    ck_assert_mem_eq(q, q_ref, sizeof q);
    fricreg_hb_free(hb);
}
END_TEST

/* fricreg_hb_continue: watched, the same points bit for bit; stopped at call k, FRICREG_EWORK
 * with the points reached, each the unwatched run's, and no bifurcation; the bound of N
 * iterations stops it where a monitor stopping at call N + 1 does. */
START_TEST(continue_watched_and_stopped)
{
    static double ref[3 * MAXP], got[3 * MAXP];
    fricreg_hb *hb = chain();
    ck_assert_int_eq(fricreg_hb_continue(hb, 0.4, 2.2, NQ, NULL), FRICREG_OK);
    size_t P = points(hb, ref);
    ck_assert_uint_gt(P, 20);
    struct watch w = watching(hb, 0);
    ck_assert_int_eq(fricreg_hb_set_monitor(hb, monitor, &w), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_continue(hb, 0.4, 2.2, NQ, NULL), FRICREG_OK);
    ck_assert(w.increasing);
    ck_assert(w.first_parameter == 0.4); /* Omega at the first point's Newton */
    ck_assert_uint_eq(points(hb, got), P);
    ck_assert_mem_eq(got, ref, 3 * P * sizeof(double));
    int64_t total = w.calls;
    ck_assert_int_gt(total, 2 * (int64_t)P);
    for (int64_t k = 1; k < total; k += total / 4) {
        w = watching(hb, k);
        ck_assert_int_eq(fricreg_hb_continue(hb, 0.4, 2.2, NQ, NULL), FRICREG_EWORK);
        ck_assert_int_eq(w.calls, k);
        ck_assert_msg(contains(fricreg_hb_errmsg(hb), "continue: stopped by the monitor"), "%s",
                      fricreg_hb_errmsg(hb));
        size_t K = points(hb, got);
        ck_assert_uint_lt(K, P);
        ck_assert_mem_eq(got, ref, 3 * K * sizeof(double));
        ck_assert_uint_eq(fricreg_hb_bifurcations(hb), 0);
        if (k > total / 2)
            ck_assert_uint_gt(K, 1); /* half the work in, points were reached */
        /* the bound: N = k − 1 iterations allowed, refused at the k-th without a call */
        if (k == 1)
            continue;
        w = watching(hb, 0);
        ck_assert_int_eq(fricreg_hb_set_max_iterations(hb, k - 1), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_continue(hb, 0.4, 2.2, NQ, NULL), FRICREG_EWORK);
        ck_assert_int_eq(w.calls, k - 1);
        ck_assert_msg(contains(fricreg_hb_errmsg(hb), "fricreg_hb_set_max_iterations"), "%s",
                      fricreg_hb_errmsg(hb));
        ck_assert_uint_eq(fricreg_hb_points(hb), K);
        ck_assert_int_eq(fricreg_hb_set_max_iterations(hb, 0), FRICREG_OK);
    }
    /* a bound above the need changes nothing */
    ck_assert_int_eq(fricreg_hb_set_max_iterations(hb, total), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_monitor(hb, NULL, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_continue(hb, 0.4, 2.2, NQ, NULL), FRICREG_OK);
    ck_assert_uint_eq(points(hb, got), P);
    ck_assert_mem_eq(got, ref, 3 * P * sizeof(double));
    ck_assert_int_eq(fricreg_hb_set_max_iterations(hb, -1), FRICREG_EINVAL);
    /* fricreg_hb_peak stopped at once: omega and rms untouched */
    double om = SENTINEL, rms = SENTINEL;
    w = watching(hb, 1);
    ck_assert_int_eq(fricreg_hb_set_monitor(hb, monitor, &w), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_peak(hb, 1, &om, &rms), FRICREG_EWORK);
    ck_assert_int_eq(w.calls, 1);
    ck_assert(om == SENTINEL && rms == SENTINEL);
    ck_assert_uint_eq(points(hb, got), P); /* the branch stays */
    fricreg_hb_free(hb);
}
END_TEST

/* fricreg_hb_continue_level: the monitor sees λ; stopped, the points reached kept. */
START_TEST(continue_level_stopped)
{
    static double ref[3 * MAXP], got[3 * MAXP], lref[MAXP];
    fricreg_hb *hb = chain();
    ck_assert_int_eq(fricreg_hb_continue_level(hb, 1.05, 0.0, 2.0, NQ, NULL), FRICREG_OK);
    size_t P = points(hb, ref);
    for (size_t k = 0; k < P; k++)
        ck_assert_int_eq(fricreg_hb_point_level(hb, k, &lref[k]), FRICREG_OK);
    struct watch w = watching(hb, 0);
    ck_assert_int_eq(fricreg_hb_set_monitor(hb, monitor, &w), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_continue_level(hb, 1.05, 0.0, 2.0, NQ, NULL), FRICREG_OK);
    ck_assert(w.first_parameter == 0.0 && w.last_parameter > 1.9);
    int64_t k = w.calls / 2;
    w = watching(hb, k);
    ck_assert_int_eq(fricreg_hb_continue_level(hb, 1.05, 0.0, 2.0, NQ, NULL), FRICREG_EWORK);
    ck_assert_int_eq(w.calls, k);
    size_t K = points(hb, got);
    ck_assert(K >= 1 && K < P);
    ck_assert_mem_eq(got, ref, 3 * K * sizeof(double));
    for (size_t j = 0; j < K; j++) {
        double l = 0.0;
        ck_assert_int_eq(fricreg_hb_point_level(hb, j, &l), FRICREG_OK);
        ck_assert(l == lref[j]);
    }
    fricreg_hb_free(hb);
}
END_TEST

/* fricreg_hb_nma: watched, the same backbone; stopped, the points reached are its first. */
START_TEST(nma_stopped)
{
    enum { NP = 12 };
    fricreg_hb *hb = chain();
    double ref[3 * NP], got[3 * NP];
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.05, 5.0, NP),
                     FRICREG_OK);
    ck_assert_uint_eq(fricreg_hb_nma_points(hb), NP);
    for (size_t i = 0; i < NP; i++)
        ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &ref[3 * i], &ref[3 * i + 1], &ref[3 * i + 2],
                                              0, 0, NULL),
                         FRICREG_OK);
    struct watch w = watching(hb, 0);
    ck_assert_int_eq(fricreg_hb_set_monitor(hb, monitor, &w), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.05, 5.0, NP),
                     FRICREG_OK);
    ck_assert(w.increasing);
    ck_assert(fabs(w.last_parameter - 5.0) < 1e-12); /* the amplitude, exp(log a1) */
    for (size_t i = 0; i < NP; i++) {
        ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &got[3 * i], &got[3 * i + 1], &got[3 * i + 2],
                                              0, 0, NULL),
                         FRICREG_OK);
    }
    ck_assert_mem_eq(got, ref, sizeof ref);
    int64_t k = w.calls * 2 / 3;
    w = watching(hb, k);
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.05, 5.0, NP),
                     FRICREG_EWORK);
    ck_assert_int_eq(w.calls, k);
    ck_assert_msg(contains(fricreg_hb_errmsg(hb), "nma: stopped by the monitor"), "%s",
                  fricreg_hb_errmsg(hb));
    size_t K = fricreg_hb_nma_points(hb);
    ck_assert(K >= 1 && K < NP);
    for (size_t i = 0; i < K; i++) {
        ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &got[3 * i], &got[3 * i + 1], &got[3 * i + 2],
                                              0, 0, NULL),
                         FRICREG_OK);
        ck_assert_mem_eq(&got[3 * i], &ref[3 * i], 3 * sizeof(double));
    }
    fricreg_hb_free(hb);
}
END_TEST

/* From the monitor every other call is refused and changes nothing (the run equals the
 * unwatched one bit for bit); the getters answer. */
START_TEST(calls_from_the_monitor_refused)
{
    static double ref[3 * MAXP], got[3 * MAXP];
    fricreg_hb *hb = chain();
    ck_assert_int_eq(fricreg_hb_continue(hb, 0.4, 2.2, NQ, NULL), FRICREG_OK);
    size_t P = points(hb, ref);
    struct watch w = watching(hb, 0);
    w.poke = 1;
    ck_assert_int_eq(fricreg_hb_set_monitor(hb, monitor, &w), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_continue(hb, 0.4, 2.2, NQ, NULL), FRICREG_OK);
    ck_assert_int_gt(w.calls, 0);
    ck_assert_int_eq(w.refused, w.calls);
    ck_assert_int_eq(w.getters_ok, w.calls);
    ck_assert_uint_eq(points(hb, got), P);
    ck_assert_mem_eq(got, ref, 3 * P * sizeof(double));
    /* after the call the driver takes calls again */
    ck_assert_int_eq(fricreg_hb_set_newton(hb, 1e-10, 50), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_monitor(NULL, monitor, &w), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_set_max_iterations(NULL, 3), FRICREG_ENULL);
    fricreg_hb_free(hb);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("hb_monitor");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, solve_watched_and_stopped);
    tcase_add_test(tc, continue_watched_and_stopped);
    tcase_add_test(tc, continue_level_stopped);
    tcase_add_test(tc, nma_stopped);
    tcase_add_test(tc, calls_from_the_monitor_refused);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
