/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fit_levels.h — the measured levels of `fricreg-sim fit` (fit_levels.c): a CSV or blank-
 * separated table of a test's backbone. */
#ifndef FRICREG_CLI_FIT_LEVELS_H
#define FRICREG_CLI_FIT_LEVELS_H

#include <stddef.h>

/* The levels of a file: n rows of 3 numbers (amplitude, freq_hz, zeta) or of 5 (with
 * sd_freq_hz, sd_zeta), every row alike; lines starting with # or % and blank lines skipped,
 * and a first line whose first token is not a number (a CSV's header). On success *cols is 3
 * or 5 and values[n cols] is the caller's to free; else one line on stderr naming option,
 * file and line, and CLI_EXIT_USAGE. */
int cli_read_levels(const char *option, const char *path, size_t *n, size_t *cols, double **values);

#endif
