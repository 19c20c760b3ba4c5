/* SPDX-License-Identifier: GPL-3.0-or-later */
/* jenkins_input.c — the Jenkins elements' files that `fricreg-sim hb` and `fricreg-sim
 * structure` share (jenkins_input.h). */
#include <stdlib.h>

#include "cli.h"
#include "cli_input.h"
#include "input_line.h"
#include "jenkins_input.h"
#include "matrix_market.h"

/* The rows x cols matrix of option's file (J), dense row-major into *out (a symmetric file's
 * lower triangle mirrored). */
static int read_dense(const char *option, const char *path, size_t rows, size_t cols, size_t *nrows,
                      size_t *ncols, double **out)
{
    struct cli_sparse A = {0};
    int status = cli_read_mtx(option, path, rows, cols, &A);
    if (status != 0)
        return status;
    double *D = calloc(A.rows * A.cols, sizeof *D);
    if (D == NULL) {
        cli_sparse_free(&A);
        return cli_file_error(option, path, 0, "out of memory");
    }
    for (size_t j = 0; j < A.cols; j++)
        for (int64_t p = A.colptr[j]; p < A.colptr[j + 1]; p++) {
            size_t i = (size_t)A.rowind[p];
            D[i * A.cols + j] = A.values[p];
            if (A.lower)
                D[j * A.cols + i] = A.values[p];
        }
    *nrows = A.rows;
    *ncols = A.cols;
    *out = D;
    cli_sparse_free(&A);
    return 0;
}

/* Two columns per row, one row per entity (dof or element): into a[rows], b[rows]. */
int cli_read_pairs(const char *option, const char *path, size_t rows, const char *what, double **a,
                   double **b)
{
    size_t got = 0;
    double *values = NULL;
    int status = cli_read_columns(option, path, 2, &got, &values);
    if (status != 0)
        return status;
    if (got != rows) {
        free(values);
        return cli_file_error(option, path, 0, "%zu lines, the model has %zu %s", got, rows, what);
    }
    *a = malloc(rows * sizeof **a);
    *b = malloc(rows * sizeof **b);
    if (*a == NULL || *b == NULL) {
        free(values);
        return cli_file_error(option, path, 0, "out of memory");
    }
    for (size_t k = 0; k < rows; k++) {
        (*a)[k] = values[2 * k];
        (*b)[k] = values[2 * k + 1];
    }
    free(values);
    return 0;
}

int cli_read_jenkins(const char *jenkins, const char *params, size_t n, size_t *m, double **J,
                     double **kt, double **mun)
{
    size_t cols = 0;
    int status = read_dense("--jenkins", jenkins, 0, n, m, &cols, J);
    if (status == 0)
        status = cli_read_pairs("--jenkins-params", params, *m, "elements (rows of --jenkins)", kt,
                                mun);
    return status;
}
