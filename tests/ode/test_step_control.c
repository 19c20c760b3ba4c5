/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_step_control.c — the error control of fricreg's adaptive GSL runs (src/ode/step_control.h),
 * white box on the static library.
 *   - Without the rule, it is GSL's standard control (gsl_odeiv2_control_y_new): the same h and
 *     the same verdict on every call of a sequence that rejects, keeps and grows.
 *   - The rule: after a rejected step the next accepted one does not grow, the one after may.
 *   - The level per component: atol_i + w_i rtol |y_i|.
 *   - What the rule is for: rk8pd on a forced oscillator whose friction has kinks rejects at
 *     most 0.75 of the steps and evaluates at most 0.92 of the right-hand sides it does
 *     without the rule (measured: 138 and 5773 against 198 and 6488 at tol 1e-6, 198 and 9036
 *     against 333 and 10700 at 1e-8). */
#include <check.h>
#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "ode/step_control.h"

/* One call of the control for a stepper of order ord: the verdict, and the new step into *h.
 * dydt is read by GSL's control (times a_dydt = 0), not by fricreg's. */
static int judge(gsl_odeiv2_control *c, unsigned int ord, const double y[], const double yerr[],
                 size_t dim, double *h)
{
    static const double dydt[3] = {0.0, 0.0, 0.0};
    return c->type->hadjust(c->state, dim, ord, y, yerr, dydt, h);
}

/* Error ratios r that reject (> 1.1), keep (0.5 ... 1.1) and grow (< 0.5), in turn. */
static const double ratios[] = {0.3, 2.0, 0.2, 0.8, 1e-3, 50.0, 7.0, 0.01, 1.05, 0.49, 1e-12};
enum { NRATIOS = sizeof ratios / sizeof ratios[0] };

START_TEST(test_without_the_rule_it_is_gsl_standard_control)
{
    const double atol = 1e-6, rtol = 1e-4, y[2] = {3.0, -0.5};
    gsl_odeiv2_control *gsl = gsl_odeiv2_control_y_new(atol, rtol);
    gsl_odeiv2_control *own = fr_step_control_new(2, NULL, atol, NULL, rtol, 0);
    ck_assert_ptr_nonnull(own);
    for (unsigned int ord = 2; ord <= 8; ord += 3)
        for (int k = 0; k < NRATIOS; k++) {
            /* component 1 decides: its level is atol + rtol * 0.5 */
            double yerr[2] = {0.0, ratios[k] * (atol + rtol * 0.5)};
            double h_gsl = 0.01, h_own = 0.01;
            int v_gsl = judge(gsl, ord, y, yerr, 2, &h_gsl);
            int v_own = judge(own, ord, y, yerr, 2, &h_own);
            ck_assert_int_eq(v_own, v_gsl);
            ck_assert_msg(h_own == h_gsl, "ord %u, r = %g: h %.17g, GSL's %.17g", ord, ratios[k],
                          h_own, h_gsl);
        }
    gsl_odeiv2_control_free(gsl);
    gsl_odeiv2_control_free(own);
}
END_TEST

START_TEST(test_no_growth_right_after_a_rejection)
{
    const double y[1] = {1.0}, tol = 1e-6; /* level 2e-6 */
    gsl_odeiv2_control *c = fr_step_control_new(1, NULL, tol, NULL, tol, 1);
    double h = 0.01, small[1] = {2e-6 * 1e-3}, large[1] = {2e-6 * 10.0};
    ck_assert_int_eq(judge(c, 5, y, small, 1, &h), GSL_ODEIV_HADJ_INC); /* grows: no rejection */
    ck_assert_double_gt(h, 0.01);
    h = 0.01;
    ck_assert_int_eq(judge(c, 5, y, large, 1, &h), GSL_ODEIV_HADJ_DEC);
    ck_assert_double_lt(h, 0.01);
    h = 0.004;
    ck_assert_int_eq(judge(c, 5, y, small, 1, &h), GSL_ODEIV_HADJ_NIL); /* the retry: held */
    ck_assert_double_eq(h, 0.004);
    ck_assert_int_eq(judge(c, 5, y, small, 1, &h), GSL_ODEIV_HADJ_INC); /* the next: grows */
    ck_assert_double_eq_tol(h, 0.004 * 0.9 / pow(1e-3, 1.0 / 6.0), 1e-15);
    gsl_odeiv2_control_free(c);
}
END_TEST

START_TEST(test_level_per_component)
{
    const double atol[3] = {1e-3, 1e-9, 1e-6}, w[3] = {1.0, 0.0, 2.0}, rtol = 1e-4;
    const double y[3] = {10.0, 10.0, 10.0};
    gsl_odeiv2_control *c = fr_step_control_new(3, atol, 0.0, w, rtol, 0);
    for (size_t i = 0; i < 3; i++) {
        double level = atol[i] + w[i] * rtol * 10.0, errlev = 0.0;
        ck_assert_int_eq(c->type->errlevel(c->state, y[i], 0.0, 0.01, i, &errlev), GSL_SUCCESS);
        ck_assert_double_eq_tol(errlev, level, 1e-15 * level);
        double yerr[3] = {0.0, 0.0, 0.0}, h = 0.01;
        yerr[i] = 1.2 * level; /* just above 1.1 of component i's level: rejected */
        ck_assert_int_eq(judge(c, 4, y, yerr, 3, &h), GSL_ODEIV_HADJ_DEC);
        yerr[i] = 1.0 * level; /* within: kept */
        h = 0.01;
        ck_assert_int_eq(judge(c, 4, y, yerr, 3, &h), GSL_ODEIV_HADJ_NIL);
    }
    gsl_odeiv2_control_free(c);
}
END_TEST

/* ---- what the rule is for: steps across kinks ----------------------------------------------- */

/* The forced oscillator x'' + x = a cos(omega t) - sat(x' / eps) (a = 2, omega = 0.5, the
 * sticking case of the benchmarks, with the velocity-limited law's saturation for law (4)):
 * the right-hand side has kinks at |x'| = eps, where a step across one has an error estimate
 * 1e2 to 1e8 times the level. The control cuts it by 5x until a step no longer crosses; that
 * step's estimate is tiny, and GSL's control grows the next step 5x, straight back across. */
#define EPS 0.025

struct cost {
    unsigned long rejected, rhs;
};

static int kinked_oscillator(double t, const double y[], double dydt[], void *params)
{
    ((struct cost *)params)->rhs++;
    dydt[0] = y[1];
    dydt[1] = 2.0 * cos(0.5 * t) - y[0] - fmax(-1.0, fmin(1.0, y[1] / EPS));
    return GSL_SUCCESS;
}

/* rk8pd over 5 forcing periods at atol = rtol = tol, with or without the rule. */
static struct cost run_kinked(double tol, int hold_after_reject)
{
    struct cost cost = {0, 0};
    gsl_odeiv2_system sys = {kinked_oscillator, NULL, 2, &cost};
    gsl_odeiv2_step *s = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, 2);
    gsl_odeiv2_evolve *e = gsl_odeiv2_evolve_alloc(2);
    gsl_odeiv2_control *c = fr_step_control_new(2, NULL, tol, NULL, tol, hold_after_reject);
    const double pi = 4.0 * atan(1.0);
    double t = 0.0, t_end = 5.0 * 2.0 * pi / 0.5, h = 1e-4, y[2] = {0.0, 0.0};
    while (t < t_end)
        ck_assert_int_eq(gsl_odeiv2_evolve_apply(e, c, s, &sys, &t, t_end, &h, y), GSL_SUCCESS);
    cost.rejected = e->failed_steps;
    gsl_odeiv2_control_free(c);
    gsl_odeiv2_evolve_free(e);
    gsl_odeiv2_step_free(s);
    return cost;
}

START_TEST(test_the_rule_cuts_the_rejections_at_kinks)
{
    const double tol[] = {1e-6, 1e-8};
    double tol_i = tol[_i];
    struct cost gsl = run_kinked(tol_i, 0), held = run_kinked(tol_i, 1);
    ck_assert_msg(held.rejected <= 0.75 * gsl.rejected && held.rhs <= 0.92 * gsl.rhs,
                  "tol %g: rejected %lu, rhs %lu with the rule; %lu, %lu without", tol_i,
                  held.rejected, held.rhs, gsl.rejected, gsl.rhs);
}
END_TEST

static Suite *step_control_suite(void)
{
    Suite *s = suite_create("step_control");
    TCase *tc = tcase_create("control");
    tcase_add_test(tc, test_without_the_rule_it_is_gsl_standard_control);
    tcase_add_test(tc, test_no_growth_right_after_a_rejection);
    tcase_add_test(tc, test_level_per_component);
    tcase_add_loop_test(tc, test_the_rule_cuts_the_rejections_at_kinks, 0, 2);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(step_control_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
