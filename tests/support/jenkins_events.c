/* SPDX-License-Identifier: GPL-3.0-or-later */
/* jenkins_events.c — the event-driven integration of jenkins_events.h. */
#include "jenkins_events.h"

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
    const struct jenkins_system *sys;
    int mode;
};

static double row(const struct jenkins_system *s, const double *x)
{
    double u = 0.0;
    for (size_t k = 0; k < s->n; k++)
        u += s->J[k] * x[k];
    return u;
}

static int rhs(double t, const double y[], double dy[], void *params)
{
    const struct phase *ph = params;
    const struct jenkins_system *s = ph->sys;
    size_t n = s->n;
    double f = ph->mode == STICK ? s->kt * (row(s, y) - y[2 * n]) : ph->mode * s->mun;
    for (size_t i = 0; i < n; i++) {
        double a = s->p[i] * cos(s->omega * t) - s->J[i] * f;
        for (size_t k = 0; k < n; k++)
            a -= s->C[n * i + k] * y[n + k] + s->K[n * i + k] * y[k];
        dy[i] = y[n + i];
        dy[n + i] = a;
    }
    dy[2 * n] = ph->mode == STICK ? 0.0 : row(s, y + n);
    return GSL_SUCCESS;
}

/* The switch function of the mode at y: negative until the switch (stick: the margin to
 * either bound; slip: the velocity against the slip's direction). */
static double switch_function(const struct phase *ph, const double y[])
{
    const struct jenkins_system *s = ph->sys;
    if (ph->mode == STICK)
        return fabs(s->kt * (row(s, y) - y[2 * s->n])) - s->mun;
    return -ph->mode * row(s, y + s->n);
}

/* One rk8pd step of h from (t, y) into out. */
static void step(gsl_odeiv2_step *s, gsl_odeiv2_system *sys, double t, const double y[], double h,
                 double out[])
{
    double err[JENKINS_MAXZ];
    memcpy(out, y, sys->dimension * sizeof *out);
    gsl_odeiv2_step_reset(s);
    ck_assert_int_eq(gsl_odeiv2_step_apply(s, t, h, out, err, NULL, NULL, sys), GSL_SUCCESS);
}

void jenkins_period(const struct jenkins_system *sys, double t0, const double *z0, double *z)
{
    const size_t nz = 2 * sys->n + 1;
    const double T = 2.0 * PI / sys->omega, h0 = T / 2000.0;
    struct phase ph = {sys, STICK};
    gsl_odeiv2_system ode = {rhs, NULL, nz, &ph};
    gsl_odeiv2_step *s = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, nz);
    double y[JENKINS_MAXZ], yn[JENKINS_MAXZ], t = t0, end = t0 + T;
    memcpy(y, z0, nz * sizeof *y);
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
                double u = row(sys, yn);
                ph.mode = u - yn[nz - 1] > 0.0 ? SLIP_UP : SLIP_DOWN;
                yn[nz - 1] = u - ph.mode * sys->mun / sys->kt;
            } else {
                ph.mode = STICK;
            }
        }
        t += h;
        memcpy(y, yn, nz * sizeof *y);
    }
    gsl_odeiv2_step_free(s);
    ck_assert_int_eq(ph.mode, STICK); /* the period ends where it started */
    memcpy(z, y, nz * sizeof *z);
}

void jenkins_monodromy(const struct jenkins_system *sys, double t0, const double *z, double *Phi)
{
    const size_t nz = 2 * sys->n + 1;
    for (size_t j = 0; j < nz; j++) {
        double zp[JENKINS_MAXZ], zm[JENKINS_MAXZ], fp[JENKINS_MAXZ], fm[JENKINS_MAXZ], h = 1e-6;
        memcpy(zp, z, nz * sizeof *zp);
        memcpy(zm, z, nz * sizeof *zm);
        zp[j] += h, zm[j] -= h;
        jenkins_period(sys, t0, zp, fp);
        jenkins_period(sys, t0, zm, fm);
        for (size_t i = 0; i < nz; i++)
            Phi[nz * i + j] = (fp[i] - fm[i]) / (2.0 * h);
    }
}

/* x_k(t) and v_k(t) into z[2n] from the coefficients x[n (2H + 1)] at Ω. */
static void displacement_at(size_t n, int H, const double *x, double omega, double t, double *z)
{
    size_t nc = 2 * (size_t)H + 1;
    for (size_t k = 0; k < n; k++) {
        const double *c = x + k * nc;
        z[k] = c[0], z[n + k] = 0.0;
        for (int h = 1; h <= H; h++) {
            double a = h * omega * t;
            z[k] += c[2 * h - 1] * cos(a) + c[2 * h] * sin(a);
            z[n + k] += h * omega * (c[2 * h] * cos(a) - c[2 * h - 1] * sin(a));
        }
    }
}

void jenkins_start(const struct jenkins_system *sys, int H, const double *x, double *t0, double *z)
{
    const int samples = 20000;
    const size_t n = sys->n;
    const double T = 2.0 * PI / sys->omega;
    double w = 0.0, best = -1.0, y[2 * JENKINS_MAXN];
    for (int i = 0; i <= 2 * samples; i++) {
        double t = T * i / samples;
        displacement_at(n, H, x, sys->omega, t, y);
        double u = row(sys, y);
        if (i == 0)
            w = u;
        double trial = sys->kt * (u - w);
        if (fabs(trial) > sys->mun)
            w = u - copysign(sys->mun, trial) / sys->kt;
        double margin = sys->mun - fabs(sys->kt * (u - w));
        if (i > samples && margin > best) {
            best = margin;
            *t0 = t;
            memcpy(z, y, 2 * n * sizeof *z);
            z[2 * n] = w;
        }
    }
    ck_assert_double_gt(best, 0.1 * sys->mun);
}

void jenkins_shoot(const struct jenkins_system *sys, double t0, double *z)
{
    const size_t nz = 2 * sys->n + 1;
    double zn[JENKINS_MAXZ], r[JENKINS_MAXZ], Phi[JENKINS_MAXZ * JENKINS_MAXZ], dz[JENKINS_MAXZ];
    gsl_permutation *p = gsl_permutation_alloc(nz);
    for (int it = 0;; it++) {
        ck_assert_int_lt(it, 20);
        jenkins_period(sys, t0, z, zn);
        double res = 0.0;
        for (size_t j = 0; j < nz; j++)
            r[j] = zn[j] - z[j], res = fmax(res, fabs(r[j]));
        if (res <= 1e-13)
            break;
        jenkins_monodromy(sys, t0, z, Phi);
        for (size_t j = 0; j < nz; j++)
            Phi[(nz + 1) * j] -= 1.0;
        gsl_matrix_view A = gsl_matrix_view_array(Phi, nz, nz);
        gsl_vector_view b = gsl_vector_view_array(r, nz), xv = gsl_vector_view_array(dz, nz);
        int sg;
        gsl_linalg_LU_decomp(&A.matrix, p, &sg);
        gsl_linalg_LU_solve(&A.matrix, p, &b.vector, &xv.vector);
        for (size_t j = 0; j < nz; j++)
            z[j] -= dz[j];
    }
    gsl_permutation_free(p);
}
