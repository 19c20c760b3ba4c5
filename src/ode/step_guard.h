/* SPDX-License-Identifier: GPL-3.0-or-later */
/* step_guard.h — internal: the one stability guard of a fixed explicit step of a system with
 * friction contacts (step_guard.c), for fricreg_sim's reference systems and fricreg_structure
 * alike: the stepper's stick-zone and imaginary-axis bounds (integrator.h), the chord bound of
 * a law that jumps, the friction-reversal bound, and central differences' joint bound. */
#ifndef FRICREG_STEP_GUARD_H
#define FRICREG_STEP_GUARD_H

#include "base/error.h"
#include "integrator.h"

/* Central differences' margin on their linear bound (dt omega/2)^2 + dt lambda < 1
 * (step_guard.c says why 0.9). */
#define FR_CENTRAL_STEP_BOUND 0.9

/* What the guard reads of a run. Rates are in 1/time of the run's units. */
struct fr_guard_run {
    const struct fr_integrator *integ; /* the stepper's row (fixed steps) */
    double dt;                         /* the step, > 0 */
    double eps;                        /* the law's eps, > 0 */
    /* lambda * eps (fr_stiffness_times_eps, src/ctx/ctx_driver.h): the stick zone's stiffness
     * times eps, the chord's for a law that jumps; finite where lambda overflows */
    double rate;
    double omega;   /* the highest natural frequency without friction */
    double damping; /* the largest viscous decay rate (eigenvalue of M^-1 C); 0: none */
    int jumps;      /* the law jumps at zdot = 0 or its band's edge ((1), (2), Karnopp) */
    /* eps follows dt (fricreg_sim's paper rule, eps = k dt): dt lambda does not depend on dt,
     * so a refusal names the eps to set instead of a dt */
    int eps_by_rule;
};

/* FRICREG_OK if a fixed step of run->integ at run->dt is within every bound, else
 * FRICREG_ESTEP with the reason, the bound and the dt (or eps) that passes recorded in err,
 * led by `who` ("run", "step"). A stiffness beyond the double range is refused too. Steppers
 * without a stick-zone bound (implicit, multistep: they report their own failures) pass. */
int fr_step_guard(const struct fr_guard_run *run, struct fr_error *err, const char *who);

#endif
