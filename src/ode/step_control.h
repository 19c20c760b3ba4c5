/* SPDX-License-Identifier: GPL-3.0-or-later */
/* step_control.h — internal: the error control of fricreg's adaptive GSL runs (step_control.c).
 *
 * GSL's standard control on y (ode-initval2/cstd.c, a_y = 1, a_dydt = 0) with an absolute
 * level per component, as SUNDIALS' CVodeSVtolerances: D0_i = atol_i + w_i rtol |y_i|. A step
 * is rejected when max_i |yerr_i| / D0_i > 1.1 and cut by 0.9 r^(-1/q), at most 5x; an
 * accepted step with r < 0.5 lets the next grow by 0.9 r^(-1/(q+1)), at most 5x; q is the
 * stepper's order. One rule may be added to GSL's: the step after a rejected one does not grow
 * (Hairer, Norsett and Wanner, Solving ODEs I, 2nd ed., Sec. II.4, "after a step rejection
 * facmax = 1"; CVODE does the same). A step across one of law (4)'s kinks has an error
 * estimate 1e2 to 1e8 times the level; the control cuts it by 5x until a step no longer
 * crosses, whose estimate is tiny, and GSL's control then grows the next step 5x, straight back
 * across. rk8pd on the sticking oscillator (kink location off) rejected 39 % of its steps, 27 %
 * with the rule, for 17 % fewer right-hand sides. Explicit Runge-Kutta steppers only: the
 * implicit and multistep ones keep GSL's control as it is (rk4imp, on the steps the rule
 * gives, met an exact stick where its iteration failed at every step size). */
#ifndef FRICREG_STEP_CONTROL_H
#define FRICREG_STEP_CONTROL_H

#include <stddef.h>

#include <gsl/gsl_odeiv2.h>

/* The control for dim components at relative tolerance epsrel >= 0: absolute levels atol[dim]
 * (> 0 where a stepper iterates to them, integrator.h's atol_required) with the weights
 * rel_weight[dim] >= 0 of epsrel (NULL: every w_i = 1), both copied; atol NULL: every
 * atol_i = epsabs >= 0. hold_after_reject: 1 adds the rule above. NULL if an allocation
 * failed, nothing left allocated. Free with gsl_odeiv2_control_free. */
gsl_odeiv2_control *fr_step_control_new(size_t dim, const double atol[], double epsabs,
                                        const double rel_weight[], double epsrel,
                                        int hold_after_reject);

#endif
