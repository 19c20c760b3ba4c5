/* SPDX-License-Identifier: GPL-3.0-or-later */
/* central_step.h — internal: fricreg_sim's central-difference steppers (central_step.c), the
 * steppers of the integrator table's central rows (src/ode/integrator.h). */
#ifndef FRICREG_CENTRAL_STEP_H
#define FRICREG_CENTRAL_STEP_H

#include <gsl/gsl_odeiv2.h>

/* Explicit central differences (Newmark beta = 0, gamma = 1/2) on fricreg_sim's state
 * (x[n], v[n], D) of dimension 2n + 1, one right-hand side per step; no error estimate. */
const gsl_odeiv2_step_type *fr_step_central(void);

/* The same scheme with the friction of the step's end solved implicitly (central_imex.c)
 * where fricreg_sim allows it (fr_central_imex_refusal); no error estimate. */
const gsl_odeiv2_step_type *fr_step_central_imex(void);

#endif
