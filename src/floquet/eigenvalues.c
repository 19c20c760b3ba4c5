/* SPDX-License-Identifier: GPL-3.0-or-later */
/* eigenvalues.c — the eigenvalues of a dense real nonsymmetric matrix by LAPACK's dgeev,
 * eigenvalues only (hb_internal.h): balancing, Hessenberg reduction and the multishift QR
 * with aggressive early deflation of dhseqr, blocked (BLAS 3), in the caller's workspace (no
 * allocation, no GSL error handler). Hill's method (hill.c) takes its exponents from
 * them.
 *
 * The matrix is row-major, LAPACK's column-major: dgeev sees A^T, whose eigenvalues are A's. */
#include <limits.h>
#include <math.h>

#include "base/lapack.h"
#include "floquet_internal.h"

size_t fr_hb_eigenvalues_work(size_t n)
{
    int order = (int)n, query = -1, one = 1, info = 0;
    double a = 0.0, wr = 0.0, wi = 0.0, best = 0.0;
    dgeev_("N", "N", &order, &a, &order, &wr, &wi, NULL, &one, NULL, &one, &best, &query, &info, 1,
           1);
    size_t least = 3 * n > 1 ? 3 * n : 1; /* dgeev's minimum without eigenvectors */
    return info == 0 && best > (double)least && best < (double)INT_MAX ? (size_t)best : least;
}

int fr_hb_eigenvalues(double *A, size_t n, double *wr, double *wi, double *work, size_t lwork)
{
    int order = (int)n, one = 1, len = (int)lwork, info = 0;
    dgeev_("N", "N", &order, A, &order, wr, wi, NULL, &one, NULL, &one, work, &len, &info, 1, 1);
    return info;
}
