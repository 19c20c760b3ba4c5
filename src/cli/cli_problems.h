/* SPDX-License-Identifier: GPL-3.0-or-later */
/* cli_problems.h — the option parsers of `fricreg-sim hold|belt|disk` (problems.c), apart from
 * their runs so that tests/fuzz/fuzz_cli_problems.c can drive them. Each parses argv (after
 * the subcommand) into the problem's parameters and *output; on error it prints one line
 * naming the option to stderr and returns CLI_EXIT_USAGE, else 0. */
#ifndef FRICREG_CLI_PROBLEMS_H
#define FRICREG_CLI_PROBLEMS_H

#include "cli.h"
#include "problems.h"

/* estimate: --error-estimate (enum fricreg_error_estimate) and --answer-rtol. */
int cli_parse_hold(int argc, char **argv, struct prob_hold *p, enum cli_output *output,
                   struct cli_estimate_options *estimate);
int cli_parse_belt(int argc, char **argv, struct prob_belt *p, enum cli_output *output,
                   struct cli_estimate_options *estimate);
/* ref_eps: the reference run's eps (--ref-eps), 0 for none. */
int cli_parse_disk(int argc, char **argv, struct prob_disk *p, double *ref_eps,
                   enum cli_output *output, struct cli_estimate_options *estimate);

#endif
