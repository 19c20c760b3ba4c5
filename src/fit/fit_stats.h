/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fit_stats.h — what a fit reports at its solution: the parameters, the residuals, the
 * identifiability, the covariance and the 95 % intervals (fricreg_fit.h, "The fit"). */
#ifndef FRICREG_FIT_STATS_H
#define FRICREG_FIT_STATS_H

#include "residuals.h"

/* Fills fit->result and the residuals at theta[nfree], the solution of start `start`, and
 * sets have_fit. Returns FRICREG_OK; FRICREG_EINVAL if a parameter ended at its bound;
 * FRICREG_ESINGULAR if the Jacobian is rank deficient; FRICREG_ENOMEM (the message recorded in
 * the fit; nothing reported as a fit on failure). */
int fr_fit_finish(struct fr_fit_problem *pb, const double theta[], const double theta0[]);

#endif
