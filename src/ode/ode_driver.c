/* SPDX-License-Identifier: GPL-3.0-or-later */
/* ode_driver.c — gsl_odeiv2_driver_alloc_y_new, with every allocation checked (ode_driver.h):
 * fricreg's own, except the stepper's private state, which only GSL can allocate, and with
 * fricreg's control (step_control.h); and a fixed step that fails where the stepper says so
 * only in its error estimate (bsimp). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_machine.h>

#include "ode_driver.h"
#include "step_control.h"

/* gsl_odeiv2_evolve_alloc's five allocations, checked; gsl_odeiv2_evolve_free frees them. */
static gsl_odeiv2_evolve *evolve_new(size_t dim)
{
    gsl_odeiv2_evolve *e = calloc(1, sizeof *e);
    if (e == NULL)
        return NULL;
    e->dimension = dim;
    e->y0 = malloc(dim * sizeof(double));
    e->yerr = malloc(dim * sizeof(double));
    e->dydt_in = malloc(dim * sizeof(double));
    e->dydt_out = malloc(dim * sizeof(double));
    if (!e->y0 || !e->yerr || !e->dydt_in || !e->dydt_out) {
        gsl_odeiv2_evolve_free(e);
        return NULL;
    }
    return e;
}

/* Whether T is one of GSL's explicit Runge-Kutta steppers, whose steps the stick zone's
 * stiffness bounds (step_control.h). */
static int explicit_runge_kutta(const gsl_odeiv2_step_type *T)
{
    return T == gsl_odeiv2_step_rk2 || T == gsl_odeiv2_step_rk4 || T == gsl_odeiv2_step_rkf45 ||
           T == gsl_odeiv2_step_rkck || T == gsl_odeiv2_step_rk8pd;
}

/* The driver around a stepper of T and the control c (NULL: the allocation failed). */
static gsl_odeiv2_driver *driver_with(const gsl_odeiv2_system *sys, const gsl_odeiv2_step_type *T,
                                      double hstart, double epsabs, double epsrel,
                                      const double atol[], const double rel_weight[])
{
    gsl_odeiv2_driver *d = calloc(1, sizeof *d);
    if (d == NULL)
        return NULL;
    d->sys = sys;
    d->s = gsl_odeiv2_step_alloc(T, sys->dimension);
    d->e = d->s ? evolve_new(sys->dimension) : NULL;
    if (d->e != NULL)
        d->c = fr_step_control_new(sys->dimension, atol, epsabs, rel_weight, epsrel,
                                   explicit_runge_kutta(T));
    if (d->c != NULL) {
        d->h = hstart;
        d->hmin = 0.0;
        d->hmax = GSL_DBL_MAX;
        gsl_odeiv2_step_set_driver(d->s, d);
        gsl_odeiv2_evolve_set_driver(d->e, d);
        gsl_odeiv2_control_set_driver(d->c, d);
    }
    if (d->c == NULL) {
        gsl_odeiv2_driver_free(d); /* frees the parts that exist */
        return NULL;
    }
    return d;
}

gsl_odeiv2_driver *fr_ode_driver_alloc(const gsl_odeiv2_system *sys, const gsl_odeiv2_step_type *T,
                                       double hstart, double epsabs, double epsrel)
{
    return driver_with(sys, T, hstart, epsabs, epsrel, NULL, NULL);
}

gsl_odeiv2_driver *fr_ode_driver_alloc_vector(const gsl_odeiv2_system *sys,
                                              const gsl_odeiv2_step_type *T, double hstart,
                                              const double atol[], const double rel_weight[],
                                              double epsrel)
{
    return driver_with(sys, T, hstart, 0.0, epsrel, atol, rel_weight);
}

int fr_ode_apply_fixed_step(gsl_odeiv2_driver *d, double *t, double h, double y[])
{
    double t0 = *t;
    size_t dim = d->sys->dimension;
    int status = gsl_odeiv2_evolve_apply_fixed_step(d->e, NULL, d->s, d->sys, t, h, y);
    for (size_t k = 0; status == GSL_SUCCESS && k < dim; k++)
        if (isfinite(y[k]) && !isfinite(d->e->yerr[k])) {
            memcpy(y, d->e->y0, dim * sizeof *y); /* the step's start, as GSL keeps it */
            *t = t0;
            status = GSL_FAILURE;
        }
    return status;
}
