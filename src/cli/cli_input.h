/* SPDX-License-Identifier: GPL-3.0-or-later */
/* cli_input.h — the input files of `fricreg-sim structure` (input.c). Each reader prints one
 * line naming option, file and line or entry to stderr and returns CLI_EXIT_USAGE on a bad
 * file; on success it returns 0 and the caller frees the array it wrote. */
#ifndef FRICREG_CLI_INPUT_H
#define FRICREG_CLI_INPUT_H

#include "cli.h"

/* A Matrix Market file, "matrix coordinate real|integer general|symmetric" (symmetric storage:
 * the lower triangle, mirrored here), as a dense row-major A[rows*cols]. */
int cli_read_mtx(const char *option, const char *path, size_t *rows, size_t *cols, double **A);

/* Lines of ncols finite numbers (separated by blanks or commas; lines starting with # or %
 * and blank lines skipped) into values[nrows*ncols], row by row. */
int cli_read_columns(const char *option, const char *path, size_t ncols, size_t *nrows,
                     double **values);

/* A ground-motion record: two columns t, a_g on a uniform grid (each time within 1e-6 steps of
 * t0 + k dt_rec, dt_rec from the first and last times), n >= 2 samples into ag[n]. */
int cli_read_record(const char *option, const char *path, double *t0, double *dt_rec, size_t *n,
                    double **ag);

#endif
