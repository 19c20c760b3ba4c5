/* SPDX-License-Identifier: GPL-3.0-or-later */
/* event_period.c — event_period.h's integration. */
#include "event_period.h"

#include <check.h>
#include <math.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>

enum { MAXZ = 8 };

/* One rk8pd step of h from (t, y) into out. */
static void step(gsl_odeiv2_step *s, gsl_odeiv2_system *sys, double t, const double y[], double h,
                 double out[])
{
    double err[MAXZ];
    memcpy(out, y, sys->dimension * sizeof *out);
    gsl_odeiv2_step_reset(s);
    ck_assert_int_eq(gsl_odeiv2_step_apply(s, t, h, out, err, NULL, NULL, sys), GSL_SUCCESS);
}

void event_period(struct event_system *es, double t0, double T, const double *z0, double *z)
{
    const size_t nz = es->ode.dimension;
    const double h0 = T / 2000.0;
    ck_assert_uint_le(nz, MAXZ);
    gsl_odeiv2_step *s = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, nz);
    double y[MAXZ], yn[MAXZ], t = t0, end = t0 + T;
    void *p = es->ode.params;
    memcpy(y, z0, nz * sizeof *y);
    while (t < end) {
        double h = fmin(h0, end - t);
        step(s, &es->ode, t, y, h, yn);
        if (es->until_switch(p, yn) >= 0.0 && es->until_switch(p, y) < 0.0) {
            double lo = 0.0, hi = h; /* the switch within the step, by bisection */
            while (hi - lo > 1e-14 * T) {
                double mid = 0.5 * (lo + hi);
                step(s, &es->ode, t, y, mid, yn);
                if (es->until_switch(p, yn) < 0.0)
                    lo = mid;
                else
                    hi = mid;
            }
            step(s, &es->ode, t, y, hi, yn);
            h = hi;
            es->switch_mode(p, yn);
        }
        t += h;
        memcpy(y, yn, nz * sizeof *y);
    }
    gsl_odeiv2_step_free(s);
    memcpy(z, y, nz * sizeof *z);
}

void shooting_newton_step(size_t nz, double *Phi, double *r, double *z)
{
    double dz[MAXZ];
    for (size_t j = 0; j < nz; j++)
        Phi[(nz + 1) * j] -= 1.0;
    gsl_matrix_view A = gsl_matrix_view_array(Phi, nz, nz);
    gsl_vector_view b = gsl_vector_view_array(r, nz), xv = gsl_vector_view_array(dz, nz);
    gsl_permutation *p = gsl_permutation_alloc(nz);
    int sg;
    gsl_linalg_LU_decomp(&A.matrix, p, &sg);
    gsl_linalg_LU_solve(&A.matrix, p, &b.vector, &xv.vector);
    gsl_permutation_free(p);
    for (size_t j = 0; j < nz; j++)
        z[j] -= dz[j];
}
