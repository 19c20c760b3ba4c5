/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_problems.c — src/problems/, the reference problems that fricreg-sim and the benchmarks
 * share: its located events are fourth order (closed forms: cos t), bad parameters and a
 * failing law come back as their status, not as GSL's, and the hold's break-away bracket holds
 * atan(mu) in any direction. Their numbers against the benchmarks are tests/cli.sh's. */
#include <check.h>
#include <math.h>

#include "fricreg_disk.h"
#include "prob_internal.h"

#define PI 3.14159265358979323846

/* The crossing of cos t = 0 at pi/2 located on a step of h that straddles it: the Hermite
 * interpolant is fourth order, so halving h divides the error by about 16 (> 10 asserted),
 * and at h = 0.1 it is below h^4/384 * max|x''''| = 2.6e-7. */
static double crossing_error(gsl_root_fsolver *s, double h)
{
    double t0 = PI / 2 - 0.3 * h, t1 = t0 + h, theta = -1.0;
    ck_assert_int_eq(prob_hermite_crossing(s, cos(t0), -sin(t0), cos(t1), -sin(t1), h, 0.0, &theta),
                     FRICREG_OK);
    return fabs(t0 + theta * h - PI / 2);
}

START_TEST(crossing_is_fourth_order)
{
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    double e1 = crossing_error(s, 0.1), e2 = crossing_error(s, 0.05);
    ck_assert_msg(e1 < 2.6e-7 && e1 > 0.0 && e1 / e2 > 10.0, "errors %g, %g", e1, e2);
    /* a level not crossed is refused, not extrapolated */
    double theta;
    ck_assert_int_eq(prob_hermite_crossing(s, 1.0, 0.0, 2.0, 0.0, 0.1, 0.0, &theta),
                     FRICREG_EINTEGRATOR);
    gsl_root_fsolver_free(s);
}
END_TEST

/* The minimum of cos t at pi inside a step of h: located on the interpolants to their
 * accuracy, h^4/384 max|x''''| = 4.2e-6 at h = 0.2 (the step's ends alone give cos(0.07) + 1 =
 * 2.4e-3), and fourth order: halving h divides the error by more than 10. */
static double minimum_error(gsl_root_fsolver *s, double h)
{
    double t0 = PI - 0.65 * h, t1 = t0 + h, lo = INFINITY, hi = -INFINITY;
    const double y0[3] = {cos(t0), -sin(t0), -cos(t0)}, y1[3] = {cos(t1), -sin(t1), -cos(t1)};
    ck_assert_int_eq(prob_track_extremes(s, y0, y1, h, &lo, &hi), FRICREG_OK);
    ck_assert(hi == fmax(y0[0], y1[0]));
    return fabs(lo + 1.0);
}

START_TEST(extremes_are_located)
{
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    double e1 = minimum_error(s, 0.2), e2 = minimum_error(s, 0.1);
    ck_assert_msg(e1 < 4.2e-6 && e2 > 0.0 && e1 / e2 > 10.0, "errors %g, %g", e1, e2);
    gsl_root_fsolver_free(s);
}
END_TEST

/* Parameters out of range: FRICREG_EINVAL before any step; a law that fails inside a step
 * (an unknown 2-D law) returns the law's status, not FRICREG_EINTEGRATOR. */
START_TEST(bad_parameters_and_law_failures)
{
    struct prob_disk d = prob_disk_defaults();
    struct prob_disk_result dr;
    d.a = 0.0;
    ck_assert_int_eq(prob_disk_run(&d, NULL, NULL, &dr), FRICREG_EINVAL);
    d.a = 2.0, d.law = 99;
    ck_assert_int_eq(prob_disk_run(&d, NULL, NULL, &dr), FRICREG_EINVAL);
    d.law = FRICREG_DISK_QUINN, d.dt = NAN;
    ck_assert_int_eq(prob_disk_run(&d, NULL, NULL, &dr), FRICREG_EINVAL);
    struct prob_belt b = prob_belt_defaults();
    struct prob_belt_cycle c;
    b.fk = 1.5; /* kinetic above static */
    ck_assert_int_eq(prob_belt_reference(&b, NULL, NULL, &c), FRICREG_EINVAL);
    ck_assert_int_eq(prob_belt_regularized(&b, 0.5, NULL, NULL, &c), FRICREG_EINVAL);
    struct prob_hold h = {.mass = 1, .g = 9.81, .mu = 0.5, .dt = 1e-4, .eps = 2e-3, .steps = 1};
    struct prob_hold_result hr;
    ck_assert_int_eq(prob_hold_run(&h, NULL, NULL, &hr), FRICREG_EINVAL);
    h.steps = 100, h.mass = 1e300; /* the load beyond the law's 1e250 */
    ck_assert_int_eq(prob_hold_run(&h, NULL, NULL, &hr), FRICREG_EINVAL);
}
END_TEST

/* Tilted at 0.02 rad/s from 0.9 atan(mu) in 6 directions: the first step that leaves rest is
 * the one whose tilts bracket atan(mu) (the law's exact stick: no creep before, no delay
 * after), 2 kappa dt wide. */
START_TEST(breakaway_bracket_holds_the_exact_angle)
{
    for (int k = 0; k < 6; k++) {
        struct prob_hold h = {.mass = 2.385,
                              .g = 9.81,
                              .mu = 0.5385,
                              .kappa = 0.02,
                              .phi = (60.0 * k + 13.0) * PI / 180.0,
                              .dt = 1e-4,
                              .eps = 2e-3,
                              .steps = 1e6};
        struct prob_hold_result r;
        h.theta0 = 0.9 * atan(h.mu);
        ck_assert_int_eq(prob_hold_run(&h, NULL, NULL, &r), FRICREG_OK);
        double exact = atan(h.mu);
        ck_assert(r.broke_away);
        ck_assert_msg(r.theta_rest <= exact + 1e-12 && exact - 1e-12 <= r.theta_moving,
                      "[%.15g, %.15g] misses %.15g", r.theta_rest, r.theta_moving, exact);
        ck_assert(fabs(r.theta_moving - r.theta_rest - 2 * h.kappa * h.dt) < 1e-12);
    }
}
END_TEST

/* The hold under each 2-D law at a fixed tilt inside the disk (tan theta = 0.8 mu), 2000
 * steps: the laws with the force balance at v = 0 (quinn, the default; force-balance) return
 * f_eq itself there, so the block never moves (0, exactly); the sliding law alone
 * (FRICREG_DISK_COULOMB, f = 0 at v = 0) lets the load start it, so it creeps. An unknown law
 * comes back as the law's FRICREG_EINVAL. */
START_TEST(hold_runs_the_law_it_is_given)
{
    const int laws[3] = {0, FRICREG_DISK_QUINN, FRICREG_DISK_FORCE_BALANCE};
    struct prob_hold h = prob_hold_defaults(); /* tan theta0 = 0.8 mu */
    struct prob_hold_result r;
    h.steps = 2000;
    for (int k = 0; k < 3; k++) {
        h.law = laws[k];
        ck_assert_int_eq(prob_hold_run(&h, NULL, NULL, &r), FRICREG_OK);
        ck_assert(r.creep == 0.0 && r.displacement == 0.0 && !r.broke_away);
    }
    h.law = FRICREG_DISK_COULOMB;
    ck_assert_int_eq(prob_hold_run(&h, NULL, NULL, &r), FRICREG_OK);
    ck_assert(r.creep > 0.0 && r.broke_away);
    h.law = 99;
    ck_assert_int_eq(prob_hold_run(&h, NULL, NULL, &r), FRICREG_EINVAL);
}
END_TEST

/* The shared definitions the event-driven references use: one turn of the default forcing's
 * direction is 2 pi 7 / 0.5 = 28 pi; the forcing at t = pi/2 (omega t = pi/4, Omega t = pi/28)
 * is 2 sin(pi/4) (cos(pi/28), sin(pi/28)); the kinetic curve is fs at rest and
 * fk + (fs - fk)/e at vs (delta = 1). */
START_TEST(shared_definitions)
{
    struct prob_disk d = prob_disk_defaults();
    double F[2];
    ck_assert(fabs(prob_disk_turn(&d) - 28.0 * PI) < 1e-13);
    prob_disk_forcing(&d, PI / 2, F);
    ck_assert(fabs(F[0] - sqrt(2.0) * cos(PI / 28)) < 1e-15);
    ck_assert(fabs(F[1] - sqrt(2.0) * sin(PI / 28)) < 1e-15);
    struct prob_belt b = prob_belt_defaults();
    ck_assert(prob_belt_kinetic(&b, 0.0) == b.fs);
    ck_assert(fabs(prob_belt_kinetic(&b, b.vs) - (0.5 + 0.5 / exp(1.0))) < 1e-15);
}
END_TEST

static Suite *problems_suite(void)
{
    Suite *s = suite_create("problems");
    TCase *tc = tcase_create("problems");
    tcase_add_test(tc, crossing_is_fourth_order);
    tcase_add_test(tc, extremes_are_located);
    tcase_add_test(tc, bad_parameters_and_law_failures);
    tcase_add_test(tc, breakaway_bracket_holds_the_exact_angle);
    tcase_add_test(tc, hold_runs_the_law_it_is_given);
    tcase_add_test(tc, shared_definitions);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(problems_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
