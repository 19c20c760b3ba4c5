/* SPDX-License-Identifier: GPL-3.0-or-later */
/* contact_step_newton.h — internal: the contact-space Newton of fricreg_ctx_solve_step on its
 * solver (contact_step_newton.c). */
#ifndef FRICREG_CONTACT_STEP_NEWTON_H
#define FRICREG_CONTACT_STEP_NEWTON_H

#include "contact_step_solver.h"

/* Newton as newmark.c's newton(), or plain (full steps from f0, no guess), on the solver s
 * (its context, c, the predictions, the bounds and f0 set): the forces end in
 * s->v[FR_STEP_V_FK], whether Newton converged into *converged, its iterations into *iters.
 * The context's status, or FRICREG_EDIVERGED where the residual is not finite. */
int fr_contact_step_newton(struct fr_step_solver *s, const double zstart[], double tol,
                           int max_iter, int plain, int *converged, int *iters);

#endif
