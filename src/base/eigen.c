/* SPDX-License-Identifier: GPL-3.0-or-later */
/* eigen.c — eigenvalues of a symmetric matrix by GSL on memory fricreg allocates (eigen.h). */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_matrix.h>

#include "eigen.h"
#include "fricreg.h"
#include "base/free_all.h"

int fr_eigen_alloc(struct fr_eigen *e, size_t m)
{
    memset(e, 0, sizeof *e);
    e->m = m;
    e->a = malloc(m * m * sizeof *e->a);
    e->eval = malloc(m * sizeof *e->eval);
    e->d = malloc(m * sizeof *e->d);
    e->sd = malloc(m * sizeof *e->sd);
    if (!e->a || !e->eval || !e->d || !e->sd) {
        fr_eigen_free(e);
        return FRICREG_ENOMEM;
    }
    return FRICREG_OK;
}

void fr_eigen_free(struct fr_eigen *e)
{
    FR_FREE_ALL(e->a, e->eval, e->d, e->sd);
    memset(e, 0, sizeof *e);
}

/* GSL's implicit QR iteration (gsl_eigen_symm) has no iteration cap, and among entries that
 * underflow it can stop converging: a fuzz input whose stick-stiffness matrix held entries
 * from 1 down to 1e-317 never returned (tests/fuzz/regressions/ctx/stiffness_underflow_hangs).
 * So the matrix is scaled by a power of two (exactly) to a largest entry in [0.5, 1), and
 * entries below DBL_EPSILON^2 of that are set to zero: a symmetric change of 2-norm at most
 * m DBL_EPSILON^2 max|a|, far below the eigenvalues' own rounding, about m DBL_EPSILON max|a|
 * (Weyl's inequality). No nonzero entry is then below 1e-32, far from the subnormals. Returns the
 * power of two the eigenvalues must be scaled back by. */
static int normalize(gsl_matrix *A)
{
    double largest = 0.0;
    for (size_t i = 0; i < A->size1; i++)
        for (size_t j = 0; j < A->size2; j++)
            largest = fmax(largest, fabs(gsl_matrix_get(A, i, j)));
    if (largest == 0.0)
        return 0;
    int exponent;
    frexp(largest, &exponent);
    double cut = ldexp(DBL_EPSILON * DBL_EPSILON, exponent);
    for (size_t i = 0; i < A->size1; i++)
        for (size_t j = 0; j < A->size2; j++) {
            double a = gsl_matrix_get(A, i, j);
            gsl_matrix_set(A, i, j, fabs(a) < cut ? 0.0 : ldexp(a, -exponent));
        }
    return exponent;
}

int fr_eigen_symm(gsl_matrix *A, gsl_vector *eval, gsl_eigen_symm_workspace *work)
{
    /* GSL's QR iteration never ends on a NaN or an Inf entry: refuse them here. */
    for (size_t i = 0; i < A->size1; i++)
        for (size_t j = 0; j < A->size2; j++)
            if (!isfinite(gsl_matrix_get(A, i, j))) {
                gsl_vector_set_all(eval, NAN); /* callers that read them see no number */
                return GSL_EDOM;
            }
    int exponent = normalize(A);
    int status = gsl_eigen_symm(A, eval, work);
    for (size_t i = 0; i < eval->size; i++)
        gsl_vector_set(eval, i, ldexp(gsl_vector_get(eval, i), exponent));
    return status;
}

int fr_eigen_symmv(gsl_matrix *A, gsl_vector *eval, gsl_matrix *evec,
                   gsl_eigen_symmv_workspace *work)
{
    for (size_t i = 0; i < A->size1; i++)
        for (size_t j = 0; j < A->size2; j++)
            if (!isfinite(gsl_matrix_get(A, i, j))) {
                gsl_vector_set_all(eval, NAN);
                return GSL_EDOM;
            }
    int exponent = normalize(A);
    int status = gsl_eigen_symmv(A, eval, evec, work);
    for (size_t i = 0; i < eval->size; i++)
        gsl_vector_set(eval, i, ldexp(gsl_vector_get(eval, i), exponent));
    if (status == GSL_SUCCESS)
        status = gsl_eigen_symmv_sort(eval, evec, GSL_EIGEN_SORT_VAL_ASC);
    return status;
}

int fr_eigen_solve(struct fr_eigen *e)
{
    gsl_matrix_view A = gsl_matrix_view_array(e->a, e->m, e->m);
    gsl_vector_view eval = gsl_vector_view_array(e->eval, e->m);
    gsl_eigen_symm_workspace work = {e->m, e->d, e->sd};
    return fr_eigen_symm(&A.matrix, &eval.vector, &work);
}
