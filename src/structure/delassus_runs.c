/* SPDX-License-Identifier: GPL-3.0-or-later */
/* delassus_runs.c — products with a packed W_eff restricted to runs of rows and columns
 * (delassus_runs.h). */
#include "base/lapack.h"
#include "contact_factor.h"
#include "delassus_runs.h"

size_t fr_runs_of(const unsigned char mask[], int on, size_t m, size_t runs[], size_t *members)
{
    size_t count = 0, total = 0;
    for (size_t i = 0; i < m;) {
        if ((mask[i] != 0) != on) {
            i++;
            continue;
        }
        size_t start = i;
        while (i < m && (mask[i] != 0) == on)
            i++;
        runs[2 * count] = start;
        runs[2 * count + 1] = i;
        total += i - start;
        count++;
    }
    *members = total;
    return count;
}

/* sum over the runs' parts below k of a_i x_i (a: column k's rows 0..k-1). */
static double runs_dot(const size_t runs[], size_t count, size_t k, const double a[],
                       const double x[])
{
    double sum = 0.0;
    int one = 1;
    for (size_t r = 0; r < count && runs[2 * r] < k; r++) {
        size_t lo = runs[2 * r], hi = runs[2 * r + 1] < k ? runs[2 * r + 1] : k;
        int n = (int)(hi - lo);
        sum += ddot_(&n, a + lo, &one, x + lo, &one);
    }
    return sum;
}

/* y_i += alpha a_i for the runs' parts below k. */
static void runs_axpy(const size_t runs[], size_t count, size_t k, double alpha, const double a[],
                      double y[])
{
    int one = 1;
    for (size_t r = 0; r < count && runs[2 * r] < k; r++) {
        size_t lo = runs[2 * r], hi = runs[2 * r + 1] < k ? runs[2 * r + 1] : k;
        int n = (int)(hi - lo);
        daxpy_(&n, &alpha, a + lo, &one, y + lo, &one);
    }
}

/* Whether k is in the runs, with *at the first run not wholly below k (k ascending). */
static int in_runs(const size_t runs[], size_t count, size_t k, size_t *at)
{
    while (*at < count && runs[2 * *at + 1] <= k)
        (*at)++;
    return *at < count && runs[2 * *at] <= k;
}

void fr_delassus_mult_runs(const cholmod_sparse *D, const size_t col_runs[], size_t ncol_runs,
                           const double x[], const size_t row_runs[], size_t nrow_runs, double y[])
{
    size_t m = D->ncol, at_row = 0, at_col = 0;
    const double *packed = D->x;
    for (size_t r = 0; r < nrow_runs; r++)
        for (size_t i = row_runs[2 * r]; i < row_runs[2 * r + 1]; i++)
            y[i] = 0.0;
    for (size_t k = 0; k < m; k++) {
        const double *a = packed + k * (k + 1) / 2; /* column k: D_0k .. D_kk */
        int row = in_runs(row_runs, nrow_runs, k, &at_row);
        int col = in_runs(col_runs, ncol_runs, k, &at_col);
        if (row) /* D_ki = D_ik for i < k: column k's part in the column runs */
            y[k] += runs_dot(col_runs, ncol_runs, k, a, x) + (col ? a[k] * x[k] : 0.0);
        if (col && x[k] != 0.0)
            runs_axpy(row_runs, nrow_runs, k, x[k], a, y);
    }
}

int fr_delassus_runs_cheaper(const cholmod_sparse *D, size_t rows, size_t nrow_runs, size_t cols,
                             size_t ncol_runs)
{
    double m = (double)D->ncol;
    double reads = (double)rows * (double)cols + m * (double)(nrow_runs + ncol_runs);
    return fr_delassus_packed(D) && reads < m * (m + 1) / 2;
}
