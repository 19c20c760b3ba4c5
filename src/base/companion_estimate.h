/* SPDX-License-Identifier: GPL-3.0-or-later */
/* companion_estimate.h — the one decision of the a-posteriori error estimates against the
 * Coulomb problem (eps -> 0) from companion runs along (eps, dt) -> (eps/2, dt/2) ->
 * (eps/4, dt/4): fricreg_sim's (src/sim/error_estimate.c), fricreg_structure's
 * (src/structure/error_estimate.c) and fricreg-sim's hold, belt and disk (src/cli/problem_estimate.c,
 * which compiles this file in as it does the RK4: the library does not export it). Pure. */
#ifndef FRICREG_COMPANION_ESTIMATE_H
#define FRICREG_COMPANION_ESTIMATE_H

#include "fricreg_sim.h" /* enum fricreg_error_estimate */

/* The default answer tolerance (fricreg_sim_set_answer_rtol, fricreg_structure_set_answer_rtol,
 * fricreg-sim's --answer-rtol): FRICREG_WARN_ERROR_ESTIMATE where an estimate exceeds 1% of its
 * quantity. */
#define FR_ANSWER_RTOL 1e-2

/* The error estimate of q by `estimator` (FRICREG_ESTIMATE_TWO_COMPANIONS or _ONE_COMPANION)
 * from its companions' values q2 (eps/2) and q4 (eps/4; ignored with one companion): >= 0,
 * in q's units. *kind is always set (enum fricreg_estimate_kind): ASYMPTOTIC where the three
 * show the law's order, BOUND where they show none (d1/d2 below 2^0.5, of opposite signs, or
 * both differences at a solver's noise: a stall, where the estimate is the safe bound) or
 * where no estimate could be formed (+infinity), ASSUMED with one companion. */
double fr_companion_estimate(int estimator, double q, double q2, double q4, int *kind);

/* The estimate of q's error from coarser companions, q2 = q(2 eps) at 2 dt and q4 = q(4 eps)
 * at 4 dt (fricreg_structure_set_error_companions): with d1 = q - q2, d2 = q2 - q4 and
 * r = d2 / d1 = 2^p in [2^0.5, 2^2] (up to the law's higher order: companion_estimate.c says
 * why), 2 |d1| / (r - 1) of kind ASYMPTOTIC (Richardson's from the coarser levels); otherwise 4.83 (|d1| + |d2|) of kind BOUND (both differences at a
 * solver's noise: 4 (|d1| + |d2|)); one companion: 3 |d1|, ASSUMED. */
double fr_companion_estimate_coarser(int estimator, double q, double q2, double q4, int *kind);

/* An estimate's share of its quantity's scale below which it is round-off (fr_estimate_exceeds). */
#define FR_ESTIMATE_ROUNDOFF 1e-12

/* An estimate's central value, the error it expects: every two-companion estimate above is
 * twice one (Richardson's correction or the geometric tail, times the margin 2 that makes it a
 * bound; companion_estimate.c's SAFETY), and one companion's 3 |d1| is twice 1.5 |d1|, between
 * the law's orders' |d1| 2^p / (2^p - 1) (2 |d1| and 4/3 |d1|). The warning compares that
 * value with the answer tolerance: the estimates bound the errors at about twice their size
 * (median 2.0 of the asymptotic ones), and compared whole they warned on errors from half the
 * tolerance up. */
#define FR_ESTIMATE_CENTRAL 0.5

/* 1 where the estimate err of q puts q's error above the answer tolerance answer_rtol: its
 * central value FR_ESTIMATE_CENTRAL err > answer_rtol |q|, and err > FR_ESTIMATE_ROUNDOFF scale,
 * scale (>= 0, in q's units) a size of q that the run knows; else 0 (also for a NaN err). The
 * absolute floor is for a quantity whose exact value is 0, such as a stuck contact's
 * dissipation: its estimate is round-off, and the relative rule alone warned on it. */
int fr_estimate_exceeds(double err, double q, double answer_rtol, double scale);

/* The JSON and messages' name of an enum fricreg_estimate_kind: "asymptotic", "bound",
 * "assumed"; "unknown" for another value. */
const char *fr_estimate_kind_name(int kind);

#endif
