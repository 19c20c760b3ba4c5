/* SPDX-License-Identifier: GPL-3.0-or-later */
/* rhs.c — the ODE's right-hand side for GSL (sim_internal.h): the contacts' kinematics, the
 * friction through the context, and the system's bodies, which also give the power for D'.
 * Below the run (sim.c) and the Jacobian (sim_jacobian.c), which both evaluate it. */
#include <math.h>

#include <gsl/gsl_errno.h>

#include "ctx/ctx_driver.h"
#include "sim_internal.h"

int fr_sim_eval_friction(fricreg_sim *sim, double t, const double y[], int want_feq)
{
    const double *x = y, *v = y + sim->ndof;
    sim->zdot = sim->sys.type->contacts(&sim->sys, t, x, v, sim->zdot_buf, sim->a_free);
    if (sim->unchecked_eval && !want_feq)
        return fr_ctx_eval_unchecked(sim->ctx, sim->zdot, sim->a_free, sim->f);
    return fricreg_ctx_eval(sim->ctx, sim->m, sim->zdot, sim->a_free, sim->f,
                            want_feq ? sim->f_eq : NULL);
}

/* The first contact whose kinematics overflowed: a stage of an unstable step. */
static size_t first_nonfinite_contact(const fricreg_sim *sim)
{
    size_t i = 0;
    while (i < sim->m && isfinite(sim->zdot[i]) && isfinite(sim->a_free[i]))
        i++;
    return i;
}

/* The ODE's right-hand side for GSL (sim_internal.h): the contacts, the friction through the
 * context, and the system's bodies pass, which also gives the power for D'. */
int fr_sim_rhs(double t, const double y[], double dydt[], void *params)
{
    fricreg_sim *sim = params;
    size_t n = sim->ndof;
    sim->rhs_evals++;
    int status = fr_sim_eval_friction(sim, t, y, 0);
    if (status != FRICREG_OK) {
        sim->rhs_status = status;
        sim->bad_contact = first_nonfinite_contact(sim);
        return GSL_EBADFUNC; /* GSL stops the step at once */
    }
    double power = sim->sys.type->bodies(&sim->sys, t, y, y + n, sim->zdot, sim->a_free, sim->f,
                                         dydt);
    dydt[2 * n] = -sim->sys.type->dissipation_weight(&sim->sys) * power;
    return GSL_SUCCESS;
}
