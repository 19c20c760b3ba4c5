/* SPDX-License-Identifier: GPL-3.0-or-later */
/* aft_march_turns.c — the turns of a 1-D orbit between the march's samples (aft_march.h): a
 * law integrated exactly along a monotone path (dahl) is exact at the samples when the march
 * steps through each turn first, where the path between two samples reverses; a law marched
 * straight from sample to sample lags by the stretch it skips there (a term in 1/N^2 for a
 * smooth law: 2e-5 of the loop at N = 512). The turn's u is stationary in its angle, so its
 * derivative in u's coefficients is the basis there (aft_march_jacobian.c). */
#include <math.h>

#include <gsl/gsl_errno.h>

#include "aft_march_internal.h"
#include "base/fr_math.h"

#define MAX_BRENT 100

/* u's coefficients and harmonics for u' at an angle. */
struct orbit {
    const double *u;
    int H;
};

/* u'(theta) = sum_h h (b_h cos h theta - a_h sin h theta). */
static double velocity(double theta, void *params)
{
    const struct orbit *o = params;
    double v = 0.0;
    for (int h = 1; h <= o->H; h++)
        v += h * (o->u[2 * h] * cos(h * theta) - o->u[2 * h - 1] * sin(h * theta));
    return v;
}

void fr_aft_march_basis_at(const fricreg_aft *a, double theta, double *phi)
{
    phi[0] = 1.0;
    for (int h = 1; h <= a->H; h++) {
        phi[2 * h - 1] = cos(h * theta);
        phi[2 * h] = sin(h * theta);
    }
}

/* The angle in [lo, hi] where u' = 0, u' of opposite signs at the ends. */
static double turn_in(gsl_root_fsolver *brent, struct orbit *o, double lo, double hi)
{
    gsl_function F = {velocity, o};
    gsl_root_fsolver_set(brent, &F, lo, hi);
    for (int it = 0; it < MAX_BRENT; it++) {
        gsl_root_fsolver_iterate(brent);
        lo = gsl_root_fsolver_x_lower(brent);
        hi = gsl_root_fsolver_x_upper(brent);
        if (gsl_root_test_interval(lo, hi, 0.0, 1e-15) == GSL_SUCCESS)
            break;
    }
    return gsl_root_fsolver_root(brent);
}

void fr_aft_march_turns(const fricreg_aft *a, struct fr_aft_march *w, const double *u, int find)
{
    size_t N = a->N;
    struct orbit o = {u, a->H};
    double step = FR_TWO_PI / (double)N, before = velocity(-step, &o);
    for (size_t n = 0; n < N; n++) {
        double theta = step * (double)n, now = velocity(theta, &o);
        w->tturn[n] = NAN;
        if (find && ((before < 0.0 && now > 0.0) || (before > 0.0 && now < 0.0))) {
            double t = turn_in(a->brent, &o, theta - step, theta),
                   phi[2 * FRICREG_AFT_MAX_HARMONICS + 1];
            fr_aft_march_basis_at(a, t, phi);
            w->tturn[n] = t;
            w->uturn[n] = 0.0;
            for (size_t j = 0; j < a->nc; j++)
                w->uturn[n] += u[j] * phi[j];
        }
        before = now;
    }
}
