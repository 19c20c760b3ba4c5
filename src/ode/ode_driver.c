/* SPDX-License-Identifier: GPL-3.0-or-later */
/* ode_driver.c — gsl_odeiv2_driver_alloc_y_new, with every allocation checked (ode_driver.h):
 * fricreg's own, except the stepper's private state, which only GSL can allocate; and a fixed
 * step that fails where the stepper says so only in its error estimate (bsimp). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_machine.h>

#include "ode_driver.h"

/* The type behind gsl_odeiv2_control_y_new: a data symbol libgsl exports (since GSL 1.14) but
 * gsl_odeiv2.h does not declare. */
extern const gsl_odeiv2_control_type *gsl_odeiv2_control_standard;

/* The standard control's private state (ode-initval2/cstd.c, GSL 1.14 to 2.7): eps_abs,
 * eps_rel, a_y, a_dydt. Allocated here with room to spare, so that only the stepper's own
 * state is left to GSL's allocator. */
#define CONTROL_STATE_DOUBLES 16

static gsl_odeiv2_control *control_y_new(double epsabs, double epsrel)
{
    gsl_odeiv2_control *c = malloc(sizeof *c);
    void *state = calloc(CONTROL_STATE_DOUBLES, sizeof(double));
    if (c == NULL || state == NULL) {
        free(c);
        free(state);
        return NULL;
    }
    *c = (gsl_odeiv2_control){.type = gsl_odeiv2_control_standard, .state = state};
    gsl_odeiv2_control_init(c, epsabs, epsrel, 1.0, 0.0); /* the caller checked both >= 0 */
    return c;
}

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

gsl_odeiv2_driver *fr_ode_driver_alloc(const gsl_odeiv2_system *sys, const gsl_odeiv2_step_type *T,
                                       double hstart, double epsabs, double epsrel)
{
    gsl_odeiv2_driver *d = calloc(1, sizeof *d);
    if (d == NULL)
        return NULL;
    d->sys = sys;
    d->s = gsl_odeiv2_step_alloc(T, sys->dimension);
    d->e = d->s ? evolve_new(sys->dimension) : NULL;
    d->c = d->e ? control_y_new(epsabs, epsrel) : NULL;
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
