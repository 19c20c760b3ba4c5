/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fd_jacobian.h — internal: the forward-difference Jacobian of an ODE right-hand side, for
 * GSL's implicit steppers where no analytic one is available. */
#ifndef FRICREG_FD_JACOBIAN_H
#define FRICREG_FD_JACOBIAN_H

#include <stddef.h>

/* A right-hand side in gsl_odeiv2's form: dydt[dim] = f(t, y[dim]); GSL_SUCCESS or a failure. */
typedef int (*fr_rhs_fn)(double t, const double y[], double dydt[], void *params);

/* dfdy [dim x dim, row-major] and dfdt [dim] of rhs at (t, y), by forward differences with the
 * step sqrt(DBL_EPSILON) max(|y_j|, 1) (and likewise in t). GSL's gsl_multiroot_fdjacobian is
 * not used: its step is relative to |y_j| alone, and at a stick the velocity sits at ~1e-18,
 * where that step is lost in rounding and the Jacobian becomes noise. work[3 dim] is scratch.
 * Costs dim + 2 right-hand sides; returns the first failing status of rhs, or GSL_SUCCESS. */
int fr_fd_jacobian(fr_rhs_fn rhs, void *params, size_t dim, double work[], double t,
                   const double y[], double *dfdy, double dfdt[]);

#endif
