/* SPDX-License-Identifier: GPL-3.0-or-later */
/* eigen.c — eigenvalues of a symmetric matrix by GSL on memory fricreg allocates (eigen.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_matrix.h>

#include "eigen.h"
#include "fricreg.h"

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
    free(e->a);
    free(e->eval);
    free(e->d);
    free(e->sd);
    memset(e, 0, sizeof *e);
}

int fr_eigen_solve(struct fr_eigen *e)
{
    /* GSL's QR iteration never ends on a NaN or an Inf entry: refuse them here. */
    for (size_t k = 0; k < e->m * e->m; k++)
        if (!isfinite(e->a[k])) {
            for (size_t i = 0; i < e->m; i++)
                e->eval[i] = NAN; /* callers that read them see no number */
            return GSL_EDOM;
        }
    gsl_matrix_view A = gsl_matrix_view_array(e->a, e->m, e->m);
    gsl_vector_view eval = gsl_vector_view_array(e->eval, e->m);
    gsl_eigen_symm_workspace work = {e->m, e->d, e->sd};
    int status = gsl_eigen_symm(&A.matrix, &eval.vector, &work);
    return status;
}
