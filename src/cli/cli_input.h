/* SPDX-License-Identifier: GPL-3.0-or-later */
/* cli_input.h — the plain-text input files of `fricreg-sim structure` (input.c; its matrices:
 * matrix_market.h). Each reader prints one line naming option, file and line or entry to
 * stderr and returns CLI_EXIT_USAGE on a bad file; on success it returns 0 and the caller
 * frees the array it wrote. */
#ifndef FRICREG_CLI_INPUT_H
#define FRICREG_CLI_INPUT_H

#include "cli.h"

/* Lines of ncols finite numbers (separated by blanks or commas; lines starting with # or %
 * and blank lines skipped) into values[nrows*ncols], row by row. */
int cli_read_columns(const char *option, const char *path, size_t ncols, size_t *nrows,
                     double **values);

/* A ground-motion record: two columns t, a_g on a uniform grid (each time within 1e-6 steps of
 * t0 + k dt_rec, dt_rec from the first and last times), n >= 2 samples into ag[n]. */
int cli_read_record(const char *option, const char *path, double *t0, double *dt_rec, size_t *n,
                    double **ag);

#endif
