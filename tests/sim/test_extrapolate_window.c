/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_extrapolate_window.c — extrapolation in eps with the finer levels over the last cycles
 * only (fricreg_sim_run_extrapolated_window), on the sticking oscillator a = 2, omega = 0.5
 * from rest, D on cycle 50.
 *
 * References: the same extrapolation with every level run from t = 0
 * (fricreg_sim_run_extrapolated), which the window must reproduce once the finer levels have
 * forgotten their start (the motion's contraction, about 5x a cycle: measured relative
 * differences in D on cycle 50 of 1.6e-5, 3.2e-6, 6.6e-7, 1.4e-7, 2.8e-8 for windows of
 * 1 … 5 cycles, three levels from eps = 0.04), and the exact solution (fricreg_exact.h). */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_exact.h"
#include "fricreg_sim.h"
#include "sim_runs.h"

enum { CYCLES = 50 };

static fricreg_sim *oscillator(double eps, int integrator, double dt, double tol)
{
    fricreg_sim *sim = NULL;
    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_OSCILLATOR, &sim), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_A, 2.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_OMEGA, 0.5), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_X0, 0.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, eps), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, integrator, dt, tol, tol), FRICREG_OK);
    return sim;
}

/* One extrapolated run of CYCLES cycles: D and its estimate per cycle, the work. */
struct outcome {
    double D[CYCLES], err[CYCLES], rhs;
};

static struct outcome run(fricreg_sim *sim, int levels, int order, int window)
{
    struct outcome o;
    ck_assert_int_eq(fricreg_sim_run_extrapolated_window(sim, CYCLES * sim_runs_period(sim), levels,
                                                         order, window),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_extrapolated_dissipation(sim, CYCLES, o.D, o.err), FRICREG_OK);
    o.rhs = sim_runs_extrapolation(sim, FRICREG_EXTRAP_RHS_EVALS);
    return o;
}

static double exact_D50(void)
{
    fricreg_exact *ex = NULL;
    double D[CYCLES];
    ck_assert_int_eq(fricreg_exact_create(2.0, 0.5, 1.0, 0.0, 0.0, &ex), FRICREG_OK);
    ck_assert_int_eq(fricreg_exact_run_cycles(ex, CYCLES), FRICREG_OK);
    ck_assert_int_eq(fricreg_exact_dissipation(ex, CYCLES, D), FRICREG_OK);
    fricreg_exact_free(ex);
    return D[CYCLES - 1];
}

/* Three levels from eps = 0.04 (order 2 observed), rk8pd at 1e-11: the window's result
 * approaches the full levels' geometrically (at least 3x a cycle; measured 4.9x), its
 * estimate bounds the difference (the unsettled part's share measured about 4x the true one)
 * without being more than 10x too large, and from 10 cycles on the two agree to integration
 * noise (measured 3e-12). */
START_TEST(test_window_converges_to_the_full_levels)
{
    fricreg_sim *sim = oscillator(0.04, FRICREG_INT_RK8PD, 1e-3, 1e-11);
    struct outcome full = run(sim, 3, 0, 0), w;
    const double D50 = full.D[CYCLES - 1];
    double previous = INFINITY;
    for (int window = 2; window <= 7; window++) {
        w = run(sim, 3, 0, window);
        double gap = fabs(w.D[CYCLES - 1] - D50);
        double unsettled = w.err[CYCLES - 1] - full.err[CYCLES - 1];
        ck_assert(w.err[CYCLES - 1] >= gap);
        ck_assert(unsettled > 0.0 && unsettled < 10.0 * gap);
        ck_assert(gap < previous / 3.0);
        previous = gap;
    }
    w = run(sim, 3, 0, 10);
    ck_assert(fabs(w.D[CYCLES - 1] - D50) < 1e-10 * D50);
    ck_assert(w.err[CYCLES - 1] < 1e-8 * D50);
    fricreg_sim_free(sim);
}
END_TEST

/* What the window reports: level 0's D, not extrapolated (estimate +infinity), before it; in
 * its first cycle the estimate +infinity (no change to compare yet); so the dissipation over
 * the window too; the work of every level. */
START_TEST(test_window_reports_what_it_extrapolated)
{
    enum { WINDOW = 6 };
    double level0[CYCLES];
    fricreg_sim *sim = oscillator(0.04, FRICREG_INT_RK8PD, 1e-3, 1e-9);
    struct outcome w = run(sim, 3, 0, WINDOW);
    ck_assert_int_eq(fricreg_sim_get_dissipation(sim, CYCLES, level0), FRICREG_OK);
    for (int c = 0; c < CYCLES - WINDOW; c++) {
        ck_assert_double_eq(w.D[c], level0[c]);
        ck_assert(isinf(w.err[c]) && w.err[c] > 0.0);
    }
    ck_assert(isinf(w.err[CYCLES - WINDOW]));
    for (int c = CYCLES - WINDOW + 1; c < CYCLES; c++) {
        ck_assert(isfinite(w.D[c]) && isfinite(w.err[c]));
        ck_assert(w.D[c] != level0[c]); /* extrapolated */
    }
    ck_assert(isinf(sim_runs_extrapolation(sim, FRICREG_EXTRAP_DISSIPATION_ERR)));
    /* the dissipation over the window: near the sum of its cycles' D (its own extrapolation) */
    double sum = 0.0;
    for (int c = CYCLES - WINDOW; c < CYCLES; c++)
        sum += w.D[c];
    ck_assert_double_eq_tol(sim_runs_extrapolation(sim, FRICREG_EXTRAP_DISSIPATION), sum,
                            1e-6 * sum);
    double rhs0 = NAN;
    ck_assert_int_eq(fricreg_sim_get_value(sim, FRICREG_VALUE_RHS_EVALS, &rhs0), FRICREG_OK);
    ck_assert(w.rhs > rhs0); /* level 0's and the finer levels' */
    fricreg_sim_free(sim);
}
END_TEST

/* The benchmark's method (bench/workprecision.c, rk8pd/quinn(4)/extrap2-window): two levels
 * from eps = 0.025, order 2 declared, rk8pd at 1e-10, window 10: within 1e-8 of the exact D
 * (measured 3e-9) for under 0.6 of the work of the full two levels (measured 0.57: level 0
 * over 50 cycles, level 1 over 10). */
START_TEST(test_window_reaches_1e_8_for_less_work)
{
    const double ref = exact_D50();
    fricreg_sim *sim = oscillator(0.025, FRICREG_INT_RK8PD, 1e-3, 1e-10);
    struct outcome full = run(sim, 2, 2, 0);
    struct outcome w = run(sim, 2, 2, 10);
    ck_assert(fabs(w.D[CYCLES - 1] - ref) < 1e-8 * ref);
    ck_assert(w.err[CYCLES - 1] >= fabs(w.D[CYCLES - 1] - ref));
    ck_assert(w.rhs < 0.6 * full.rhs);
    fricreg_sim_free(sim);
}
END_TEST

/* Fixed RK4 (dt = 0.05, eps by the paper's rule: 0.1, then 0.05 at dt/2): level 1's steps
 * over 10 of 50 cycles, so (1 + 2/5)/3 = 0.47 of the work, and the same D to 1e-9 relative
 * (a fixed grid: the window's level 1 takes the full level's steps from its start). */
START_TEST(test_window_fixed_step)
{
    fricreg_sim *sim = oscillator(0.0, FRICREG_INT_RK4, 0.05, 0.0);
    struct outcome full = run(sim, 2, 2, 0);
    struct outcome w = run(sim, 2, 2, 10);
    ck_assert_double_eq_tol(w.D[CYCLES - 1], full.D[CYCLES - 1], 1e-9 * full.D[CYCLES - 1]);
    ck_assert_double_eq_tol(w.rhs / full.rhs, 7.0 / 15.0, 0.01);
    fricreg_sim_free(sim);
}
END_TEST

/* window = 0 and a window covering every cycle are fricreg_sim_run_extrapolated, to the bit;
 * window < 0 is refused. */
START_TEST(test_no_window_is_the_plain_extrapolation)
{
    enum { SHORT = 4 };
    double D[SHORT], err[SHORT], Dw[SHORT], errw[SHORT];
    fricreg_sim *sim = oscillator(0.04, FRICREG_INT_RK8PD, 1e-3, 1e-8);
    double T = sim_runs_period(sim);
    ck_assert_int_eq(fricreg_sim_run_extrapolated(sim, SHORT * T, 2, 2), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_extrapolated_dissipation(sim, SHORT, D, err), FRICREG_OK);
    static const int windows[3] = {0, SHORT, SHORT + 3};
    for (int k = 0; k < 3; k++) {
        ck_assert_int_eq(fricreg_sim_run_extrapolated_window(sim, SHORT * T, 2, 2, windows[k]),
                         FRICREG_OK);
        ck_assert_int_eq(fricreg_sim_get_extrapolated_dissipation(sim, SHORT, Dw, errw),
                         FRICREG_OK);
        ck_assert_mem_eq(D, Dw, sizeof D);
        ck_assert_mem_eq(err, errw, sizeof err);
    }
    ck_assert_int_eq(fricreg_sim_run_extrapolated_window(NULL, T, 2, 2, 1), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_sim_run_extrapolated_window(sim, SHORT * T, 2, 2, -1), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_sim_errcode(sim), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "window"));
    /* the last extrapolation is still held: a refused call changes nothing */
    ck_assert_int_eq(fricreg_sim_get_extrapolated_dissipation(sim, SHORT, Dw, errw), FRICREG_OK);
    ck_assert_mem_eq(D, Dw, sizeof D);
    ck_assert_int_eq(fricreg_sim_run_extrapolated_window(sim, SHORT * T, 1, 2, 1), FRICREG_EINVAL);
    fricreg_sim_free(sim);
}
END_TEST

/* An observer that stops level 0 before the window begins: every level runs from t = 0, as
 * fricreg_sim_run_extrapolated does under the same observer. */
static int stop_after(void *user, double t, size_t ndof, const double x[], const double v[],
                      size_t m, const double f[], const double f_eq[])
{
    (void)ndof, (void)x, (void)v, (void)m, (void)f, (void)f_eq;
    return t >= *(const double *)user;
}

START_TEST(test_stopped_before_the_window)
{
    double D[3], err[3], Dw[3], errw[3], cycles = NAN;
    fricreg_sim *sim = oscillator(0.04, FRICREG_INT_RK8PD, 1e-3, 1e-8);
    double T = sim_runs_period(sim), t_stop = 3.5 * T;
    ck_assert_int_eq(fricreg_sim_set_observer(sim, stop_after, &t_stop), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_extrapolated(sim, 8 * T, 2, 2), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_value(sim, FRICREG_VALUE_CYCLES, &cycles), FRICREG_OK);
    ck_assert_double_eq(cycles, 3.0);
    ck_assert_int_eq(fricreg_sim_get_extrapolated_dissipation(sim, 3, D, err), FRICREG_OK);
    /* the window of 2 would start after cycle 6 of 8: level 0 stopped after 3 */
    ck_assert_int_eq(fricreg_sim_run_extrapolated_window(sim, 8 * T, 2, 2, 2), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_extrapolated_dissipation(sim, 3, Dw, errw), FRICREG_OK);
    ck_assert_mem_eq(D, Dw, sizeof D);
    ck_assert(isfinite(errw[0]));
    fricreg_sim_free(sim);
}
END_TEST

static Suite *window_suite(void)
{
    Suite *s = suite_create("extrapolate_window");
    TCase *refs = tcase_create("references");
    tcase_add_test(refs, test_window_converges_to_the_full_levels);
    tcase_add_test(refs, test_window_reaches_1e_8_for_less_work);
    tcase_add_test(refs, test_window_fixed_step);
    suite_add_tcase(s, refs);
    TCase *api = tcase_create("contract");
    tcase_add_test(api, test_window_reports_what_it_extrapolated);
    tcase_add_test(api, test_no_window_is_the_plain_extrapolation);
    tcase_add_test(api, test_stopped_before_the_window);
    suite_add_tcase(s, api);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(window_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
