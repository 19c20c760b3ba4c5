/* SPDX-License-Identifier: GPL-3.0-or-later */
/* integrator.h — internal: our integrator enum mapped onto GSL's gsl_odeiv2 steppers. */
#ifndef FRICREG_INTEGRATOR_H
#define FRICREG_INTEGRATOR_H

#include <gsl/gsl_odeiv2.h>

struct fr_integrator {
    int id;           /* enum fricreg_integrator */
    const char *name; /* GSL's name */
    const gsl_odeiv2_step_type *(*type)(void);
    /* Largest stable dt*lambda on the negative real axis for a fixed step of this stepper
     * (0: not checked a priori, the stepper reports its own failure). */
    double real_axis_bound;
    /* Largest dt*lambda, lambda = fricreg_ctx_stick_stiffness, that the step guard accepts:
     * the real-axis bound, or less where the stick zone fails before it (integrator.c). */
    double stick_zone_bound;
    /* Largest dt*omega on the imaginary axis (an undamped oscillation of frequency omega) at
     * which the amplification per fixed step stays below 1 + 1e-4 (0: not checked). */
    double imag_axis_bound;
    /* GSL steps of this stepper per fricreg step dt (GSL's rk4: 2, see integrator.c). */
    int substeps;
    /* Absolute tolerance given to GSL's driver in a fixed-step run. Only some steppers read
     * it: the multistep ones to choose their order (1e-6 keeps them accurate), and the
     * implicit Runge-Kutta ones as their Newton tolerance, which no iteration meets once a
     * stick brings the velocity to the rounding floor: they get 1e300, no test at all. */
    double fixed_tolerance;
    /* The stepper used for fixed steps, or NULL for `type` itself: fricreg's own classical
     * RK4 for rk4, which gives GSL rk4's numbers without its error estimate. */
    const gsl_odeiv2_step_type *(*fixed_type)(void);
    /* 1 for central differences: fixed steps only, stepped by the driver's own stepper
     * (type is NULL; fricreg_sim's is src/sim/central_step.c, on its state layout (x, v, D)),
     * and one combined step bound (dt omega/2)^2 + dt lambda < 0.9 in place of the three
     * columns above (src/ode/step_guard.c, check_central). */
    int central;
    /* 1 for central differences with law (4) solved implicitly, per contact, at the step's end
     * (src/sim/central_imex.c): the stick zone then bounds no step's stability, and the guard is
     * the springs', plus the reversal bound where the step does not resolve law (4)'s band
     * (src/ode/step_guard.c, check_central_imex). */
    int implicit_friction;
    /* 1 for GSL's steppers that solve their Newton matrix I - h c J by GSL's LU (rk1imp,
     * rk2imp, rk4imp, bsimp, msbdf): gsl_linalg_LU_solve reports an exactly singular one to
     * GSL's error handler, whose default aborts. I - h c J is regular when no eigenvalue of J
     * has a positive real part, a stable system: the drivers run these steppers on stable
     * systems only (a structure's K and C positive semidefinite, structure_ode.c). */
    int lu_newton;
    /* 1 for GSL's steppers that iterate until each component's correction is below the
     * control's error level atol + rtol |y_i| (rk1imp, rk2imp, rk4imp, msadams, msbdf: they call
     * gsl_odeiv2_control_errlevel, which reports a level of 0 to GSL's error handler, whose
     * default aborts): an adaptive run with atol = 0 meets it at the first component that is 0,
     * as every start from rest is. The drivers refuse such a run (FRICREG_EINVAL). */
    int atol_required;
    /* The one-step stepper that re-steps an adaptive step from its start to locate a kink of
     * the friction law within it (src/sim/kinks.c), or NULL for `type` itself: a multistep
     * stepper's step depends on its history, so msadams has rk8pd (non-stiff, as Adams) and
     * msbdf rk4imp (A-stable, for the stiff stick zone), each from the step's start. */
    const gsl_odeiv2_step_type *(*locator)(void);
};

/* The table row of an integrator id, or NULL if unknown. */
const struct fr_integrator *fr_integrator_find(int id);

/* The GSL stepper for a run: fixed or adaptive steps; NULL for the central rows, whose
 * stepper is the driver's own (fricreg_sim's, src/sim/central_step.c). */
const gsl_odeiv2_step_type *fr_integrator_stepper(const struct fr_integrator *integ, int adaptive);

#endif
