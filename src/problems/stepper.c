/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stepper.c — the problems' fixed-step classical RK4, taken from GSL: gsl_odeiv2_step_rk4 at
 * 2 dt returns two classical steps of dt (its error estimate is by step doubling), applied by
 * gsl_odeiv2_step_apply with no control object, so that no step is ever refused or resized.
 * No derivative is passed in or asked for: the step evaluates the one at its start itself and
 * shares it between the full step and the first half step, 11 right-hand sides in all
 * (gsl_odeiv2_evolve_apply_fixed_step evaluates it once more, and the one at the end: 12).
 * The time is set by the caller at each step (t0 + 2 dt, not accumulated), so that a long
 * run's forcing phase does not drift by rounding. A failed step ends the caller's run. */
#include <stdlib.h>

#include <gsl/gsl_errno.h>

#include "fricreg.h"
#include "prob_internal.h"

int prob_rk4_init(struct prob_rk4 *r, int (*f)(double, const double[], double[], void *),
                  size_t dim, void *params, double dt)
{
    r->sys = (gsl_odeiv2_system){f, NULL, dim, params};
    r->dt = dt;
    r->step = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk4, dim);
    r->yerr = malloc(dim * sizeof *r->yerr);
    if (r->step == NULL || r->yerr == NULL) {
        prob_rk4_free(r);
        return FRICREG_ENOMEM;
    }
    return FRICREG_OK;
}

int prob_rk4_advance(struct prob_rk4 *r, double t0, double y[], const int *law_status)
{
    int status = gsl_odeiv2_step_apply(r->step, t0, 2.0 * r->dt, y, r->yerr, NULL, NULL, &r->sys);
    if (status == GSL_SUCCESS)
        return FRICREG_OK;
    return status == GSL_EBADFUNC && *law_status != FRICREG_OK ? *law_status : FRICREG_EINTEGRATOR;
}

void prob_rk4_free(struct prob_rk4 *r)
{
    free(r->yerr);
    if (r->step != NULL)
        gsl_odeiv2_step_free(r->step);
    r->yerr = NULL;
    r->step = NULL;
}
