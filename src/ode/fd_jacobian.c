/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fd_jacobian.c — the forward-difference Jacobian shared by the drivers and the structure's
 * GSL runs (fd_jacobian.h). */
#include <math.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_math.h>

#include "fd_jacobian.h"

int fr_fd_jacobian(fr_rhs_fn rhs, void *params, size_t dim, double work[], double t,
                   const double y[], double *dfdy, double dfdt[])
{
    double *f0 = work, *f1 = f0 + dim, *y1 = f1 + dim;
    int status = rhs(t, y, f0, params);
    memcpy(y1, y, dim * sizeof *y);
    for (size_t j = 0; status == GSL_SUCCESS && j < dim; j++) {
        double h = GSL_SQRT_DBL_EPSILON * fmax(fabs(y[j]), 1.0);
        y1[j] = y[j] + h;
        status = rhs(t, y1, f1, params);
        y1[j] = y[j];
        for (size_t i = 0; i < dim; i++)
            dfdy[i * dim + j] = (f1[i] - f0[i]) / h;
    }
    double ht = GSL_SQRT_DBL_EPSILON * fmax(fabs(t), 1.0);
    if (status == GSL_SUCCESS)
        status = rhs(t + ht, y, f1, params);
    for (size_t i = 0; status == GSL_SUCCESS && i < dim; i++)
        dfdt[i] = (f1[i] - f0[i]) / ht;
    return status;
}
