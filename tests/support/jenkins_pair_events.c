/* SPDX-License-Identifier: GPL-3.0-or-later */
/* jenkins_pair_events.c — the event-driven integration of jenkins_pair_events.h. */
#include "jenkins_pair_events.h"

#include <check.h>
#include <math.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_odeiv2.h>

static const double PI = 3.14159265358979323846;

enum { STICK = 0, SLIP_UP = 1, SLIP_DOWN = -1 };

/* The system and the slider's mode, for GSL's right-hand side. */
struct phase {
    const struct jenkins_pair *sys;
    int mode;
};

static int rhs(double t, const double y[], double dy[], void *params)
{
    const struct phase *ph = params;
    const struct jenkins_pair *s = ph->sys;
    int d = s->dof;
    double f = ph->mode == STICK ? s->kt * (y[d] - y[4]) : ph->mode * s->mun;
    for (int i = 0; i < 2; i++) {
        double a = (i == 0 ? s->force * cos(s->omega * t) : 0.0) - (i == d ? f : 0.0);
        for (int k = 0; k < 2; k++)
            a -= s->C[2 * i + k] * y[2 + k] + s->K[2 * i + k] * y[k];
        dy[i] = y[2 + i];
        dy[2 + i] = a;
    }
    dy[4] = ph->mode == STICK ? 0.0 : y[2 + d];
    return GSL_SUCCESS;
}

/* The switch function of the mode at y: negative until the switch (stick: the margin to
 * either bound; slip: the velocity against the slip's direction). */
static double switch_function(const struct phase *ph, const double y[])
{
    const struct jenkins_pair *s = ph->sys;
    if (ph->mode == STICK)
        return fabs(s->kt * (y[s->dof] - y[4])) - s->mun;
    return -ph->mode * y[2 + s->dof];
}

/* One rk8pd step of h from (t, y) into out. */
static void step(gsl_odeiv2_step *s, gsl_odeiv2_system *sys, double t, const double y[], double h,
                 double out[])
{
    double err[5];
    memcpy(out, y, 5 * sizeof *out);
    gsl_odeiv2_step_reset(s);
    ck_assert_int_eq(gsl_odeiv2_step_apply(s, t, h, out, err, NULL, NULL, sys), GSL_SUCCESS);
}

void jenkins_pair_period(const struct jenkins_pair *sys, double t0, const double z0[5], double z[5])
{
    const double T = 2.0 * PI / sys->omega, h0 = T / 2000.0;
    struct phase ph = {sys, STICK};
    gsl_odeiv2_system ode = {rhs, NULL, 5, &ph};
    gsl_odeiv2_step *s = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, 5);
    double y[5], yn[5], t = t0, end = t0 + T;
    memcpy(y, z0, sizeof y);
    while (t < end) {
        double h = fmin(h0, end - t);
        step(s, &ode, t, y, h, yn);
        if (switch_function(&ph, yn) >= 0.0 && switch_function(&ph, y) < 0.0) {
            double lo = 0.0, hi = h; /* the switch within the step, by bisection */
            while (hi - lo > 1e-14 * T) {
                double mid = 0.5 * (lo + hi);
                step(s, &ode, t, y, mid, yn);
                if (switch_function(&ph, yn) < 0.0)
                    lo = mid;
                else
                    hi = mid;
            }
            step(s, &ode, t, y, hi, yn);
            h = hi;
            if (ph.mode == STICK) { /* slips towards the bound reached, the offset on it */
                ph.mode = yn[sys->dof] - yn[4] > 0.0 ? SLIP_UP : SLIP_DOWN;
                yn[4] = yn[sys->dof] - ph.mode * sys->mun / sys->kt;
            } else {
                ph.mode = STICK;
            }
        }
        t += h;
        memcpy(y, yn, sizeof y);
    }
    gsl_odeiv2_step_free(s);
    ck_assert_int_eq(ph.mode, STICK); /* the period ends where it started */
    memcpy(z, y, sizeof y);
}

void jenkins_pair_monodromy(const struct jenkins_pair *sys, double t0, const double z[5],
                            double Phi[25])
{
    for (int j = 0; j < 5; j++) {
        double zp[5], zm[5], fp[5], fm[5], h = 1e-6;
        memcpy(zp, z, sizeof zp);
        memcpy(zm, z, sizeof zm);
        zp[j] += h, zm[j] -= h;
        jenkins_pair_period(sys, t0, zp, fp);
        jenkins_pair_period(sys, t0, zm, fm);
        for (int i = 0; i < 5; i++)
            Phi[5 * i + j] = (fp[i] - fm[i]) / (2.0 * h);
    }
}

/* x_k(t) and v_k(t) from the coefficients x[2 (2H + 1)] at Ω. */
static void displacement_at(int H, const double *x, double omega, double t, double z[4])
{
    size_t nc = 2 * (size_t)H + 1;
    for (size_t k = 0; k < 2; k++) {
        const double *c = x + k * nc;
        z[k] = c[0], z[2 + k] = 0.0;
        for (int h = 1; h <= H; h++) {
            double a = h * omega * t;
            z[k] += c[2 * h - 1] * cos(a) + c[2 * h] * sin(a);
            z[2 + k] += h * omega * (c[2 * h] * cos(a) - c[2 * h - 1] * sin(a));
        }
    }
}

void jenkins_pair_start(const struct jenkins_pair *sys, int H, const double *x, double *t0,
                        double z[5])
{
    const int samples = 20000, d = sys->dof;
    const double T = 2.0 * PI / sys->omega;
    double w = 0.0, best = -1.0, y[4];
    for (int i = 0; i <= 2 * samples; i++) {
        double t = T * i / samples;
        displacement_at(H, x, sys->omega, t, y);
        if (i == 0)
            w = y[d];
        double trial = sys->kt * (y[d] - w);
        if (fabs(trial) > sys->mun)
            w = y[d] - copysign(sys->mun, trial) / sys->kt;
        double margin = sys->mun - fabs(sys->kt * (y[d] - w));
        if (i > samples && margin > best) {
            best = margin;
            *t0 = t;
            memcpy(z, y, sizeof y);
            z[4] = w;
        }
    }
    ck_assert_double_gt(best, 0.1 * sys->mun);
}

void jenkins_pair_shoot(const struct jenkins_pair *sys, double t0, double z[5])
{
    double zn[5], r[5], Phi[25], dz[5];
    gsl_permutation *p = gsl_permutation_alloc(5);
    for (int it = 0;; it++) {
        ck_assert_int_lt(it, 20);
        jenkins_pair_period(sys, t0, z, zn);
        double res = 0.0;
        for (int j = 0; j < 5; j++)
            r[j] = zn[j] - z[j], res = fmax(res, fabs(r[j]));
        if (res <= 1e-13)
            break;
        jenkins_pair_monodromy(sys, t0, z, Phi);
        for (int j = 0; j < 5; j++)
            Phi[6 * j] -= 1.0;
        gsl_matrix_view A = gsl_matrix_view_array(Phi, 5, 5);
        gsl_vector_view b = gsl_vector_view_array(r, 5), xv = gsl_vector_view_array(dz, 5);
        int sg;
        gsl_linalg_LU_decomp(&A.matrix, p, &sg);
        gsl_linalg_LU_solve(&A.matrix, p, &b.vector, &xv.vector);
        for (int j = 0; j < 5; j++)
            z[j] -= dz[j];
    }
    gsl_permutation_free(p);
}
