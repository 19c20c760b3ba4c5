/* SPDX-License-Identifier: GPL-3.0-or-later */
/* prob_internal.h — what the problems share: the library's classical RK4 at a fixed step, and
 * events located inside a step on the cubic Hermite interpolant by GSL's Brent solver. */
#ifndef FRICREG_PROB_INTERNAL_H
#define FRICREG_PROB_INTERNAL_H

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_roots.h>

#include "problems.h"

/* Classical RK4 at dt, two steps a call (problems.h), with no step control. */
struct prob_rk4 {
    gsl_odeiv2_system sys;
    gsl_odeiv2_step *step;
    double dt;
};

/* Allocates the stepper for f of dimension dim. Returns FRICREG_OK or FRICREG_ENOMEM. */
int prob_rk4_init(struct prob_rk4 *r, int (*f)(double, const double[], double[], void *),
                  size_t dim, void *params, double dt);
/* Two classical steps of dt from t0: y at t0 + 2 dt. Returns FRICREG_OK, *law_status if the
 * right-hand side failed (it returns GSL_EBADFUNC after storing the law's status there), or
 * FRICREG_EINTEGRATOR. */
int prob_rk4_advance(struct prob_rk4 *r, double t0, double y[], const int *law_status);
void prob_rk4_free(struct prob_rk4 *r);

/* The cubic Hermite interpolant on a step of length h through (p0, d0) and (p1, d1), and its
 * time derivative, at theta in [0, 1]. */
double prob_hermite(double p0, double d0, double p1, double d1, double h, double theta);

/* The theta in [0, 1] where the interpolant crosses `level`, given that p0 and p1 lie on
 * either side of it (or on it): GSL's Brent solver to 1e-15 in theta. Returns FRICREG_OK or
 * FRICREG_EINTEGRATOR (no bracket, or the solver failed). */
int prob_hermite_crossing(gsl_root_fsolver *solver, double p0, double d0, double p1, double d1,
                          double h, double level, double *theta);

/* The extremes of x over a step from (x0, v0, a0) to (x1, v1, a1): the end values and, where
 * v changes sign, the interpolant's turning point. Updates *x_min and *x_max. */
int prob_track_extremes(gsl_root_fsolver *solver, const double y0[3], const double y1[3], double h,
                        double *x_min, double *x_max);

#endif
