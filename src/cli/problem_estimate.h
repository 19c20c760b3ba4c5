/* SPDX-License-Identifier: GPL-3.0-or-later */
/* problem_estimate.h — the error estimate of `fricreg-sim hold|belt|disk`'s headline numbers
 * against the Coulomb problem (eps -> 0), as fricreg_sim's and fricreg_structure's: the
 * problem run again at (eps/2, dt/2) and (eps/4, dt/4) (fricreg_structure_set_error_estimate's
 * path; one companion with --error-estimate one), and base/companion_estimate.c's estimator. */
#ifndef FRICREG_CLI_PROBLEM_ESTIMATE_H
#define FRICREG_CLI_PROBLEM_ESTIMATE_H

#include <stddef.h>

#include "cli.h"

#define CLI_ESTIMATE_MAX 3 /* headline numbers a problem estimates */

/* Runs the problem at eps / 2^k, dt / 2^k (its step count 2^k times) into q[n]; a fricreg
 * status. */
typedef int (*cli_problem_level)(const void *problem, int k, double q[]);

/* The estimate of q[n] (named names[n] in the warnings) by opt->estimator (enum
 * fricreg_error_estimate, not off) into err[n] and its kind (enum fricreg_estimate_kind) into
 * kind[n]: +infinity, of kind BOUND, where a companion failed, with
 * FRICREG_WARN_ERROR_ESTIMATE; FRICREG_WARN_ERROR_ESTIMATE too for an estimate above
 * opt->answer_rtol of a nonzero quantity, whatever its kind (a number located at a step's end,
 * as hold's break-away angle, converges with the phase of its steps, not at an order: it is
 * told by its kind, BOUND, as any other): appended to w. */
void cli_problem_estimate(cli_problem_level run, const void *problem,
                          const struct cli_estimate_options *opt, size_t n,
                          const char *const names[], const double q[], double err[], int kind[],
                          struct cli_warnings *w);

#endif
