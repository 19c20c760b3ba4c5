/* SPDX-License-Identifier: GPL-3.0-or-later */
/* companion_estimate.h — the one decision of the a-posteriori error estimates against the
 * Coulomb problem (eps -> 0) from companion runs along (eps, dt) -> (eps/2, dt/2) ->
 * (eps/4, dt/4): fricreg_sim's (src/sim/error_estimate.c), fricreg_structure's
 * (src/structure/error_estimate.c) and fricreg-sim's hold, belt and disk (src/cli/problems.c,
 * which compiles this file in as it does the RK4: the library does not export it). Pure. */
#ifndef FRICREG_COMPANION_ESTIMATE_H
#define FRICREG_COMPANION_ESTIMATE_H

#include "fricreg_sim.h" /* enum fricreg_error_estimate */

/* The error estimate of q by `estimator` (FRICREG_ESTIMATE_TWO_COMPANIONS or _ONE_COMPANION)
 * from its companions' values q2 (eps/2) and q4 (eps/4; ignored with one companion): >= 0,
 * in q's units. *not_asymptotic is set to 1 (never cleared) when the three show no order in
 * eps (d1/d2 below 2^0.5, or of opposite signs): a stall, where the estimate is the safe
 * bound and FRICREG_WARN_NOT_ASYMPTOTIC is due. */
double fr_companion_estimate(int estimator, double q, double q2, double q4, int *not_asymptotic);

#endif
