/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_integrator.c — the real-axis stability bounds behind FRICREG_ESTEP.
 *
 * src/ode/integrator.c keeps, per explicit GSL stepper, the largest stable dt*lambda on the negative
 * real axis (rk2 2.5, rk4 2.78 per classical step, rkf45 3.6, rkck 3.7, rk8pd 5.1), rounded
 * down from values "measured by applying each GSL stepper with a fixed step to y' = -y"
 * (2.51, 2.785, 3.67, 3.73, 5.16). fricreg_sim_run refuses a fixed step with dt*lambda above
 * the stick-zone bound (lambda = 2 mun/eps for law (4)): the real-axis bound, except rkf45
 * 2.2 and rk8pd 4.5, where the nonlinear zone fails first (src/ode/integrator.c; test_guard.c
 * and test_guard_structure.c measure it).
 * Checked here twice:
 *   - directly on GSL: one fixed step of y' = -y with h = z gives y = R(-z), the stepper's
 *     stability function; |R(-z)| <= 1 on (0, bound], and the bound is tight;
 *   - through the public API: the oscillator stuck in the linear zone of (4) is the decay
 *     v' = -lambda v exactly (see test_oscillator.c), so just below the guard's bound the run
 *     succeeds and |v| decays, just above it the run is FRICREG_ESTEP.
 * GSL's rk4 step of h is two classical RK4 steps of h/2 (step doubling), so its R at h = 2z is
 * the classical R(-z) squared: fricreg's dt is the classical step. */
#include <check.h>
#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "fricreg_sim.h"

struct explicit_row {
    int id;                  /* enum fricreg_integrator */
    double table_bound;      /* src/ode/integrator.c, in fricreg's dt (classical step for rk4) */
    double measured;         /* src/ode/integrator.c's comment: the measured value */
    double gsl_steps_per_dt; /* GSL step length per fricreg dt: 2 for rk4 (step doubling) */
    double imag_bound;       /* src/ode/integrator.c: dt*omega with amplification <= 1 + 1e-4 */
    double guard_bound;      /* src/ode/integrator.c: the stick-zone bound the guard applies */
};

static const struct explicit_row rows[] = {
    {FRICREG_INT_RK2, 2.5, 2.51, 1.0, 1.73, 2.5},  {FRICREG_INT_RK4, 2.78, 2.785, 2.0, 2.82, 2.78},
    {FRICREG_INT_RKF45, 3.6, 3.67, 1.0, 0.7, 2.2}, {FRICREG_INT_RKCK, 3.7, 3.73, 1.0, 0.88, 3.7},
    {FRICREG_INT_RK8PD, 5.1, 5.16, 1.0, 3.7, 4.5},
};
#define NROWS ((int)(sizeof rows / sizeof rows[0]))

static int decay(double t, const double y[], double dydt[], void *params)
{
    (void)t, (void)params;
    dydt[0] = -y[0];
    return GSL_SUCCESS;
}

static int decay_jacobian(double t, const double y[], double *dfdy, double dfdt[], void *params)
{
    (void)t, (void)y, (void)params;
    dfdy[0] = -1.0;
    dfdt[0] = 0.0;
    return GSL_SUCCESS;
}

static const gsl_odeiv2_step_type *gsl_type(int id)
{
    switch (id) {
    case FRICREG_INT_RK2: return gsl_odeiv2_step_rk2;
    case FRICREG_INT_RK4: return gsl_odeiv2_step_rk4;
    case FRICREG_INT_RKF45: return gsl_odeiv2_step_rkf45;
    case FRICREG_INT_RKCK: return gsl_odeiv2_step_rkck;
    case FRICREG_INT_RK8PD: return gsl_odeiv2_step_rk8pd;
    case FRICREG_INT_RK1IMP: return gsl_odeiv2_step_rk1imp;
    case FRICREG_INT_RK2IMP: return gsl_odeiv2_step_rk2imp;
    case FRICREG_INT_RK4IMP: return gsl_odeiv2_step_rk4imp;
    default: return gsl_odeiv2_step_bsimp;
    }
}

/* R(-z) of a fricreg integrator: one fixed GSL step of y' = -y from y = 1, with GSL step length
 * z * (GSL steps per fricreg dt), through a driver (the implicit steppers read their error
 * levels from it) but with no step control, as src/sim/sim.c steps. */
static double stability_function(int id, double z, double gsl_steps_per_dt)
{
    gsl_odeiv2_system sys = {decay, decay_jacobian, 1, NULL};
    double h = z * gsl_steps_per_dt, t = 0.0, y = 1.0;
    gsl_error_handler_t *previous = gsl_set_error_handler_off();
    gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_type(id), h, 1e-6, 0.0);
    ck_assert_ptr_nonnull(d);
    int status = gsl_odeiv2_evolve_apply_fixed_step(d->e, NULL, d->s, &sys, &t, h, &y);
    gsl_odeiv2_driver_free(d);
    gsl_set_error_handler(previous);
    ck_assert_int_eq(status, GSL_SUCCESS);
    return y;
}

/* y' = i y as a real system: (y0, y1)' = (-y1, y0), an undamped oscillation of frequency 1. */
static int rotation(double t, const double y[], double dydt[], void *params)
{
    (void)t, (void)params;
    dydt[0] = -y[1];
    dydt[1] = y[0];
    return GSL_SUCCESS;
}

/* |R(i z)|: the amplification of one fixed step of y' = i y, as stability_function. */
static double amplification_on_imaginary_axis(int id, double z, double gsl_steps_per_dt)
{
    gsl_odeiv2_system sys = {rotation, NULL, 2, NULL};
    double h = z * gsl_steps_per_dt, t = 0.0, y[2] = {1.0, 0.0};
    gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_type(id), h, 1e-6, 0.0);
    ck_assert_ptr_nonnull(d);
    ck_assert_int_eq(gsl_odeiv2_evolve_apply_fixed_step(d->e, NULL, d->s, &sys, &t, h, y),
                     GSL_SUCCESS);
    gsl_odeiv2_driver_free(d);
    return hypot(y[0], y[1]);
}

/* The table's imaginary-axis bound (the system-frequency check of src/ode/step_guard.c) keeps the
 * amplification per step within 1 + 1e-4, and 10% beyond it the amplification is larger. */
START_TEST(test_imaginary_axis_bound)
{
    const struct explicit_row *r = &rows[_i];
    const char *name = fricreg_integrator_name(r->id);
    for (int k = 1; k <= 100; k++) {
        double z = r->imag_bound * k / 100.0;
        double A = amplification_on_imaginary_axis(r->id, z, r->gsl_steps_per_dt);
        ck_assert_msg(A <= 1.0 + 1e-4, "%s: |R(%gi)| = %.9g", name, z, A);
    }
    double beyond = amplification_on_imaginary_axis(r->id, 1.1 * r->imag_bound,
                                                    r->gsl_steps_per_dt);
    ck_assert_msg(beyond > 1.0 + 1e-4, "%s: |R(%gi)| = %.9g", name, 1.1 * r->imag_bound, beyond);
}
END_TEST

/* The table's bound is stable: |R(-z)| <= 1 on a grid of (0, bound] including the bound. */
START_TEST(test_table_bound_is_stable)
{
    const struct explicit_row *r = &rows[_i];
    for (int k = 1; k <= 400; k++) {
        double z = r->table_bound * k / 400.0;
        double R = stability_function(r->id, z, r->gsl_steps_per_dt);
        ck_assert_msg(fabs(R) <= 1.0, "%s: |R(-%g)| = %.6g > 1", fricreg_integrator_name(r->id), z,
                      fabs(R));
    }
}
END_TEST

/* The comment's measured values are the true bounds to the digits given: stable at the value,
 * unstable 0.01 above it; the table's rounding-down loses under 3% (unstable at 1.03 bound). */
START_TEST(test_measured_bound_is_tight)
{
    const struct explicit_row *r = &rows[_i];
    const char *name = fricreg_integrator_name(r->id);
    double at = stability_function(r->id, r->measured, r->gsl_steps_per_dt);
    double above = stability_function(r->id, r->measured + 0.01, r->gsl_steps_per_dt);
    double table_above = stability_function(r->id, 1.03 * r->table_bound, r->gsl_steps_per_dt);
    ck_assert_msg(fabs(at) <= 1.0, "%s: |R(-%g)| = %.6g", name, r->measured, fabs(at));
    ck_assert_msg(fabs(above) > 1.0, "%s: |R(-%g)| = %.6g", name, r->measured + 0.01, fabs(above));
    ck_assert_msg(fabs(table_above) > 1.0, "%s: |R(-%g)| = %.6g", name, 1.03 * r->table_bound,
                  fabs(table_above));
}
END_TEST

/* The table's bound 0 for the implicit one-step steppers rests on A-stability: |R(-z)| <= 1
 * however large z (here up to 1000; exact Jacobian). */
START_TEST(test_implicit_steppers_are_a_stable)
{
    static const int ids[] = {FRICREG_INT_RK1IMP, FRICREG_INT_RK2IMP, FRICREG_INT_RK4IMP,
                              FRICREG_INT_BSIMP};
    static const double zs[] = {0.5, 2.5, 5.5, 10.0, 100.0, 1000.0};
    for (size_t k = 0; k < sizeof zs / sizeof zs[0]; k++) {
        double R = stability_function(ids[_i], zs[k], 1.0);
        ck_assert_msg(fabs(R) <= 1.0, "%s: |R(-%g)| = %.6g", fricreg_integrator_name(ids[_i]),
                      zs[k], fabs(R));
    }
}
END_TEST

/* The oscillator under (4) with eps = 0.02 (lambda = 2 mun/eps = 100), stuck from the start:
 * x0 = -0.5, so xi = (eps/2) x0 = -eps/4 and the linear zone is -0.75 eps < v < 0.25 eps, where
 * v' = -lambda v and x + v/lambda is constant. v0 = -eps/400 is small enough that the RK stages,
 * which overshoot v at such z, stay in the zone (a larger v0, e.g. -eps/8, puts rkf45's stages
 * outside it near z = 3.6 and the step is no longer the linear one). Step dt = z/lambda. */
#define STUCK_EPS 0.02
#define STUCK_LAMBDA (2.0 / STUCK_EPS)
#define STUCK_X0 (-0.5)
#define STUCK_V0 (-STUCK_EPS / 400.0)
static fricreg_sim *stuck_oscillator(int id, double z)
{
    fricreg_sim *sim = NULL;
    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_OSCILLATOR, &sim), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_X0, STUCK_X0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_V0, STUCK_V0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, STUCK_EPS), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, id, z / STUCK_LAMBDA, 0.0, 0.0), FRICREG_OK);
    return sim;
}

/* dt lambda = 0.999 bound: accepted, and the stick-zone mode decays: |v| falls below |v0| (a
 * bound above the true one would make it grow, by |R| > 1 per step), while the linear invariant
 * x + v/lambda holds to rounding (the step stayed the linear one: the contact held). */
START_TEST(test_step_just_below_bound_runs_and_decays)
{
    const struct explicit_row *r = &rows[_i];
    fricreg_sim *sim = stuck_oscillator(r->id, 0.999 * r->guard_bound);
    int status = fricreg_sim_run(sim, 20.0);
    ck_assert_msg(status == FRICREG_OK, "%s: status %d (%s)", fricreg_integrator_name(r->id),
                  status, fricreg_sim_errmsg(sim));
    double x, v;
    ck_assert_int_eq(fricreg_sim_get_state(sim, 1, &x, &v), FRICREG_OK);
    ck_assert_double_lt(fabs(v), fabs(STUCK_V0));
    ck_assert_double_eq_tol(x + v / STUCK_LAMBDA, STUCK_X0 + STUCK_V0 / STUCK_LAMBDA, 1e-12);
    fricreg_sim_free(sim);
}
END_TEST

/* dt lambda = 1.001 bound: FRICREG_ESTEP before any step. */
START_TEST(test_step_just_above_bound_is_estep)
{
    const struct explicit_row *r = &rows[_i];
    fricreg_sim *sim = stuck_oscillator(r->id, 1.001 * r->guard_bound);
    ck_assert_int_eq(fricreg_sim_run(sim, 20.0), FRICREG_ESTEP);
    ck_assert_int_eq(fricreg_sim_errcode(sim), FRICREG_ESTEP);
    double steps = NAN;
    ck_assert_int_eq(fricreg_sim_get_value(sim, FRICREG_VALUE_STEPS, &steps), FRICREG_OK);
    ck_assert_double_eq(steps, 0.0);
    fricreg_sim_free(sim);
}
END_TEST

static Suite *integrator_suite(void)
{
    Suite *s = suite_create("integrator");
    TCase *gsl = tcase_create("gsl_stability");
    tcase_add_loop_test(gsl, test_table_bound_is_stable, 0, NROWS);
    tcase_add_loop_test(gsl, test_measured_bound_is_tight, 0, NROWS);
    tcase_add_loop_test(gsl, test_imaginary_axis_bound, 0, NROWS);
    tcase_add_loop_test(gsl, test_implicit_steppers_are_a_stable, 0, 4);
    suite_add_tcase(s, gsl);

    TCase *api = tcase_create("estep_boundary");
    tcase_add_loop_test(api, test_step_just_below_bound_runs_and_decays, 0, NROWS);
    tcase_add_loop_test(api, test_step_just_above_bound_is_estep, 0, NROWS);
    suite_add_tcase(s, api);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(integrator_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
