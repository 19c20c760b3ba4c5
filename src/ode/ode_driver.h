/* SPDX-License-Identifier: GPL-3.0-or-later */
/* ode_driver.h — internal: a gsl_odeiv2_driver assembled from GSL's parts, all or nothing, and
 * the drivers' fixed step on it.
 *
 * gsl_odeiv2_driver_alloc_y_new cannot be used when memory may run out: its control,
 * gsl_odeiv2_control_y_new, passes the NULL of a failed allocation straight on to
 * gsl_odeiv2_control_init, which dereferences it (GSL 2.7, ode-initval2/cstd.c). */
#ifndef FRICREG_ODE_DRIVER_H
#define FRICREG_ODE_DRIVER_H

#include <gsl/gsl_odeiv2.h>

/* The driver gsl_odeiv2_driver_alloc_y_new(sys, T, hstart, epsabs, epsrel) would make, with
 * fricreg's control (step_control.h: GSL's standard one on y, a_y = 1, a_dydt = 0, and for
 * GSL's explicit Runge-Kutta steppers no growth of the step right after a rejection), or NULL
 * if any allocation failed, with nothing left allocated. epsabs, epsrel >= 0. Only
 * gsl_odeiv2_step_alloc's failure reaches GSL's error handler (docs/reliability.md). Free with
 * gsl_odeiv2_driver_free. */
gsl_odeiv2_driver *fr_ode_driver_alloc(const gsl_odeiv2_system *sys, const gsl_odeiv2_step_type *T,
                                       double hstart, double epsabs, double epsrel);

/* fr_ode_driver_alloc with tolerances per component: the level atol[i] + w[i] epsrel |y_i| in
 * component i, the per-component tolerances of SUNDIALS' CVodeSVtolerances (GSL's
 * gsl_odeiv2_control_scaled_new with eps_abs = 1 is the same rule for w = 1, but allocates
 * unchecked). atol[dim] > 0 and rel_weight[dim] >= 0 (NULL: every w[i] = 1), copied;
 * epsrel >= 0. NULL if any allocation failed, nothing left allocated. */
gsl_odeiv2_driver *fr_ode_driver_alloc_vector(const gsl_odeiv2_system *sys,
                                              const gsl_odeiv2_step_type *T, double hstart,
                                              const double atol[], const double rel_weight[],
                                              double epsrel);

/* One fixed step of h from (*t, y) by the driver's stepper, as gsl_odeiv2_evolve_apply_fixed_step
 * (no step control), which also fails where the stepper tells its failure only by its error
 * estimate: GSL's bsimp breaks off a step that meets its runaway test (a change of the state
 * beyond 100 dim times |y_i| summed over i: a component of 1e-300 beside a change of 1e-3)
 * with yerr = +Inf, y not advanced and GSL_SUCCESS, so a fixed step "succeeded" without
 * moving the state, and a run returned FRICREG_OK on a frozen state (fuzz finding). An error
 * estimate that is not finite beside a finite y restores y and *t and returns GSL_FAILURE,
 * which the drivers retry in halves. */
int fr_ode_apply_fixed_step(gsl_odeiv2_driver *d, double *t, double h, double y[]);

#endif
