/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fuzz_condition.h — the context harnesses' condition number of a principal submatrix of W,
 * Jacobi-scaled: the contexts' forces are accurate to about it times the rounding of their
 * sums (fricreg.h, fricreg_disk_ctx.h), so it sets the contract checks' tolerance. */
#ifndef FRICREG_FUZZ_CONDITION_H
#define FRICREG_FUZZ_CONDITION_H

#include <math.h>
#include <stddef.h>

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_matrix.h>

#include "fuzz_input.h"

/* cond(D W_PP D), D = diag(W_ii)^-1/2, of W [n x n, row-major] on the s rows and columns
 * pos[s], by GSL's symmetric eigensolver on a copy: 1 when s = 0, +Inf when singular. */
static inline double fuzz_scaled_condition(const double W[], size_t n, const size_t pos[], size_t s)
{
    if (s == 0)
        return 1.0;
    gsl_matrix *A = gsl_matrix_alloc(s, s);
    gsl_vector *eval = gsl_vector_alloc(s);
    gsl_eigen_symm_workspace *work = gsl_eigen_symm_alloc(s);
    FUZZ_REQUIRE(A && eval && work, "harness: out of memory");
    for (size_t a = 0; a < s; a++)
        for (size_t b = 0; b < s; b++) {
            size_t i = pos[a], j = pos[b];
            gsl_matrix_set(A, a, b, W[i * n + j] / sqrt(W[i * n + i]) / sqrt(W[j * n + j]));
        }
    gsl_eigen_symm(A, eval, work);
    double lo = gsl_vector_min(eval), hi = gsl_vector_max(eval);
    gsl_eigen_symm_free(work);
    gsl_vector_free(eval);
    gsl_matrix_free(A);
    return lo > 0.0 ? hi / lo : INFINITY;
}

#endif
