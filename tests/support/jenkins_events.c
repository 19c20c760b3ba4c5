/* SPDX-License-Identifier: GPL-3.0-or-later */
/* jenkins_events.c — the event-driven integration of jenkins_events.h. */
#include "jenkins_events.h"

#include <check.h>
#include <math.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "event_period.h"
#include "orbit_state.h"

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
static double until_switch(void *params, const double y[])
{
    const struct phase *ph = params;
    const struct jenkins_system *s = ph->sys;
    if (ph->mode == STICK)
        return fabs(s->kt * (row(s, y) - y[2 * s->n])) - s->mun;
    return -ph->mode * row(s, y + s->n);
}

/* Stick to slip towards the bound reached, the offset on it; slip to stick. */
static void switch_mode(void *params, double y[])
{
    struct phase *ph = params;
    const struct jenkins_system *sys = ph->sys;
    if (ph->mode != STICK) {
        ph->mode = STICK;
        return;
    }
    double u = row(sys, y);
    ph->mode = u - y[2 * sys->n] > 0.0 ? SLIP_UP : SLIP_DOWN;
    y[2 * sys->n] = u - ph->mode * sys->mun / sys->kt;
}

void jenkins_period(const struct jenkins_system *sys, double t0, const double *z0, double *z)
{
    struct phase ph = {sys, STICK};
    struct event_system es = {{rhs, NULL, 2 * sys->n + 1, &ph}, until_switch, switch_mode};
    event_period(&es, t0, 2.0 * PI / sys->omega, z0, z);
    ck_assert_int_eq(ph.mode, STICK); /* the period ends where it started */
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

void jenkins_start(const struct jenkins_system *sys, int H, const double *x, double *t0, double *z)
{
    const int samples = 20000;
    const size_t n = sys->n;
    const double T = 2.0 * PI / sys->omega;
    double w = 0.0, best = -1.0, y[2 * JENKINS_MAXN];
    for (int i = 0; i <= 2 * samples; i++) {
        double t = T * i / samples;
        orbit_state_at(n, H, x, sys->omega, t, y);
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
    double zn[JENKINS_MAXZ], r[JENKINS_MAXZ], Phi[JENKINS_MAXZ * JENKINS_MAXZ];
    for (int it = 0;; it++) {
        ck_assert_int_lt(it, 20);
        jenkins_period(sys, t0, z, zn);
        double res = 0.0;
        for (size_t j = 0; j < nz; j++)
            r[j] = zn[j] - z[j], res = fmax(res, fabs(r[j]));
        if (res <= 1e-13)
            break;
        jenkins_monodromy(sys, t0, z, Phi);
        shooting_newton_step(nz, Phi, r, z);
    }
}
