/* SPDX-License-Identifier: GPL-3.0-or-later */
/* structure_summary.h — what a run of `fricreg-sim structure` reports (structure_summary.c):
 * the library's warnings, its error estimates, and the JSON summary of the run. */
#ifndef FRICREG_CLI_STRUCTURE_SUMMARY_H
#define FRICREG_CLI_STRUCTURE_SUMMARY_H

#include "structure_steps.h"

/* The error estimates of the headline quantities against eps -> 0, the library's
 * (fricreg_structure_set_error_estimate: a companion at eps / 2 and dt / 2, or tolerances / 16,
 * err = 3 |q - q_companion|; docs/structural.md, "Error estimate"). NULL arrays: none made. */
struct structure_estimate {
    double *peak_err, *D_err, *De_err; /* [n], [m], [me]; +infinity where a companion failed */
    int *peak_kind, *D_kind, *De_kind; /* their kinds (enum fricreg_estimate_kind) */
};

/* The library's warnings on the structure and its run (fricreg_structure_warning_count, judged
 * by the caller after the run), each printed once on stderr. */
void cli_structure_warnings(fricreg_structure *s, struct cli_warnings *w);

/* The library's estimates into est (one allocation, at est->peak_err, and one of their kinds,
 * at est->peak_kind), if it made them. */
void cli_structure_estimate(const fricreg_structure *s, const struct structure_input *in,
                            struct structure_estimate *est);

/* The JSON summary of the run that ended: the settings, the state and peaks at the dofs shown,
 * the dissipations and the elements' fields, each estimate with its kinds, the energy balance,
 * Newton's counts, the CPU time and the warnings. */
void cli_structure_summary(FILE *out, const struct structure_options *o,
                           const struct structure_input *in, const fricreg_structure *s,
                           const struct structure_run *run, double eps, double cpu_seconds,
                           const struct cli_warnings *warnings,
                           const struct structure_estimate *est);

#endif
