/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stepper.c — the problems' fixed-step classical RK4: the library's (src/ode/rk4_classic.c),
 * whose call of 2 dt takes two classical steps of dt on GSL's rk4 grid, applied by
 * gsl_odeiv2_step_apply with no control object, so that no step is ever refused or resized:
 * 8 right-hand sides a call. The time is set by the caller at each step (t0 + 2 dt, not
 * accumulated), so that a long run's forcing phase does not drift by rounding. A failed step
 * ends the caller's run. */
#include <gsl/gsl_errno.h>

#include "fricreg.h"
#include "ode/rk4_classic.h"
#include "prob_internal.h"

int prob_rk4_init(struct prob_rk4 *r, int (*f)(double, const double[], double[], void *),
                  size_t dim, void *params, double dt)
{
    r->sys = (gsl_odeiv2_system){f, NULL, dim, params};
    r->dt = dt;
    r->step = gsl_odeiv2_step_alloc(fr_step_rk4_classic(), dim);
    return r->step != NULL ? FRICREG_OK : FRICREG_ENOMEM;
}

int prob_rk4_advance(struct prob_rk4 *r, double t0, double y[], const int *law_status)
{
    int status = gsl_odeiv2_step_apply(r->step, t0, 2.0 * r->dt, y, NULL, NULL, NULL, &r->sys);
    if (status == GSL_SUCCESS)
        return FRICREG_OK;
    return status == GSL_EBADFUNC && *law_status != FRICREG_OK ? *law_status : FRICREG_EINTEGRATOR;
}

void prob_rk4_free(struct prob_rk4 *r)
{
    if (r->step != NULL)
        gsl_odeiv2_step_free(r->step);
    r->step = NULL;
}
