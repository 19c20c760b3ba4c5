/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stepper.c — the problems' fixed-step classical RK4, taken from GSL: gsl_odeiv2_step_rk4 at
 * 2 dt returns two classical steps of dt (its error estimate is by step doubling), applied by
 * gsl_odeiv2_evolve_apply_fixed_step with no control object, so that no step is ever refused
 * or resized. The time is set by the caller at each step (t0 + 2 dt, not accumulated), so that
 * a long run's forcing phase does not drift by rounding. */
#include <gsl/gsl_errno.h>

#include "fricreg.h"
#include "prob_internal.h"

int prob_rk4_init(struct prob_rk4 *r, int (*f)(double, const double[], double[], void *),
                  size_t dim, void *params, double dt)
{
    r->sys = (gsl_odeiv2_system){f, NULL, dim, params};
    r->dt = dt;
    r->step = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk4, dim);
    r->evolve = gsl_odeiv2_evolve_alloc(dim);
    if (r->step == NULL || r->evolve == NULL) {
        prob_rk4_free(r);
        return FRICREG_ENOMEM;
    }
    return FRICREG_OK;
}

int prob_rk4_advance(struct prob_rk4 *r, double t0, double y[], const int *law_status)
{
    double t = t0;
    int status = gsl_odeiv2_evolve_apply_fixed_step(r->evolve, NULL, r->step, &r->sys, &t,
                                                    2.0 * r->dt, y);
    if (status == GSL_SUCCESS)
        return FRICREG_OK;
    return status == GSL_EBADFUNC && *law_status != FRICREG_OK ? *law_status : FRICREG_EINTEGRATOR;
}

void prob_rk4_free(struct prob_rk4 *r)
{
    if (r->evolve != NULL)
        gsl_odeiv2_evolve_free(r->evolve);
    if (r->step != NULL)
        gsl_odeiv2_step_free(r->step);
    r->evolve = NULL;
    r->step = NULL;
}
