/* SPDX-License-Identifier: GPL-3.0-or-later */
/* ode_driver.c — gsl_odeiv2_driver_alloc_y_new, with every allocation checked (ode_driver.h). */
#include <stdlib.h>

#include <gsl/gsl_machine.h>

#include "gsl_guard.h"
#include "ode_driver.h"

/* The type behind gsl_odeiv2_control_y_new: a data symbol libgsl exports (since GSL 1.14) but
 * gsl_odeiv2.h does not declare. With it the control is allocated by the checked
 * gsl_odeiv2_control_alloc and initialized only once it exists. */
extern const gsl_odeiv2_control_type *gsl_odeiv2_control_standard;

static gsl_odeiv2_control *control_y_new(double epsabs, double epsrel)
{
    gsl_odeiv2_control *c = gsl_odeiv2_control_alloc(gsl_odeiv2_control_standard);
    if (c != NULL && gsl_odeiv2_control_init(c, epsabs, epsrel, 1.0, 0.0) != GSL_SUCCESS) {
        gsl_odeiv2_control_free(c);
        c = NULL;
    }
    return c;
}

gsl_odeiv2_driver *fr_ode_driver_alloc(const gsl_odeiv2_system *sys, const gsl_odeiv2_step_type *T,
                                       double hstart, double epsabs, double epsrel)
{
    gsl_odeiv2_driver *d = calloc(1, sizeof *d);
    if (d == NULL)
        return NULL;
    gsl_error_handler_t *previous = fr_gsl_quiet();
    d->sys = sys;
    d->s = gsl_odeiv2_step_alloc(T, sys->dimension);
    d->e = d->s ? gsl_odeiv2_evolve_alloc(sys->dimension) : NULL;
    d->c = d->e ? control_y_new(epsabs, epsrel) : NULL;
    if (d->c != NULL) {
        d->h = hstart;
        d->hmin = 0.0;
        d->hmax = GSL_DBL_MAX;
        gsl_odeiv2_step_set_driver(d->s, d);
        gsl_odeiv2_evolve_set_driver(d->e, d);
        gsl_odeiv2_control_set_driver(d->c, d);
    }
    fr_gsl_restore(previous);
    if (d->c == NULL) {
        gsl_odeiv2_driver_free(d); /* frees the parts that exist */
        return NULL;
    }
    return d;
}
