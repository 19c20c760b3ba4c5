/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hermite.c — events inside a step: the cubic Hermite interpolant of a quantity and its rate
 * over the step (fourth order, like the step), and the crossing of a level located on it by
 * GSL's Brent solver. */
#include <math.h>

#include <gsl/gsl_errno.h>

#include "fricreg.h"
#include "prob_internal.h"

double prob_hermite(double p0, double d0, double p1, double d1, double h, double theta)
{
    double s = 1.0 - theta;
    double h00 = (1.0 + 2.0 * theta) * s * s, h10 = theta * s * s;
    double h01 = theta * theta * (3.0 - 2.0 * theta), h11 = -theta * theta * s;
    return h00 * p0 + h10 * h * d0 + h01 * p1 + h11 * h * d1;
}

struct crossing {
    double p0, d0, p1, d1, h, level;
};

static double offset(double theta, void *params)
{
    const struct crossing *c = params;
    return prob_hermite(c->p0, c->d0, c->p1, c->d1, c->h, theta) - c->level;
}

int prob_hermite_crossing(gsl_root_fsolver *solver, double p0, double d0, double p1, double d1,
                          double h, double level, double *theta)
{
    struct crossing c = {p0, d0, p1, d1, h, level};
    double lo = p0 - level, hi = p1 - level;
    if (lo == 0.0 || hi == 0.0) { /* on the level at an end: GSL needs a strict bracket */
        *theta = lo == 0.0 ? 0.0 : 1.0;
        return FRICREG_OK;
    }
    if ((lo > 0.0) == (hi > 0.0))
        return FRICREG_EINTEGRATOR;
    gsl_function F = {offset, &c};
    if (gsl_root_fsolver_set(solver, &F, 0.0, 1.0) != GSL_SUCCESS)
        return FRICREG_EINTEGRATOR;
    for (int iter = 0; iter < 200; iter++) {
        if (gsl_root_fsolver_iterate(solver) != GSL_SUCCESS)
            return FRICREG_EINTEGRATOR;
        double a = gsl_root_fsolver_x_lower(solver), b = gsl_root_fsolver_x_upper(solver);
        if (gsl_root_test_interval(a, b, 1e-15, 0.0) == GSL_SUCCESS) {
            *theta = gsl_root_fsolver_root(solver);
            return FRICREG_OK;
        }
    }
    return FRICREG_EINTEGRATOR;
}

int prob_track_extremes(gsl_root_fsolver *solver, const double y0[3], const double y1[3], double h,
                        double *x_min, double *x_max)
{
    *x_min = fmin(*x_min, fmin(y0[0], y1[0]));
    *x_max = fmax(*x_max, fmax(y0[0], y1[0]));
    if ((y0[1] > 0.0 && y1[1] < 0.0) || (y0[1] < 0.0 && y1[1] > 0.0)) {
        double theta;
        int status = prob_hermite_crossing(solver, y0[1], y0[2], y1[1], y1[2], h, 0.0, &theta);
        if (status != FRICREG_OK)
            return status;
        double x = prob_hermite(y0[0], y0[1], y1[0], y1[1], h, theta);
        *x_min = fmin(*x_min, x);
        *x_max = fmax(*x_max, x);
    }
    return FRICREG_OK;
}
