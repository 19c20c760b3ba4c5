/* SPDX-License-Identifier: GPL-3.0-or-later */
/* jenkins_input.h — the files of Jenkins elements, for `fricreg-sim hb` (hb.c) and
 * `fricreg-sim structure` (structure_model.c): --jenkins J.mtx (Matrix Market, m x n: element
 * i's q_i = (J x)_i) and --jenkins-params P.txt (one line per element: kt mun). */
#ifndef FRICREG_CLI_JENKINS_INPUT_H
#define FRICREG_CLI_JENKINS_INPUT_H

#include <stddef.h>

/* Two columns per row, one row per entity (rows of them: dofs or elements, named by what in
 * the message): into a[rows], b[rows], the caller's to free. 0, or CLI_EXIT_USAGE after one
 * line on stderr naming the option, the file and the line. */
int cli_read_pairs(const char *option, const char *path, size_t rows, const char *what, double **a,
                   double **b);

/* The elements: J (m x n, dense row-major, m from the file) and kt[m], mun[m], into arrays the
 * caller frees (also on failure: those set). 0, or CLI_EXIT_USAGE as cli_read_pairs. */
int cli_read_jenkins(const char *jenkins, const char *params, size_t n, size_t *m, double **J,
                     double **kt, double **mun);

#endif
