/* SPDX-License-Identifier: GPL-3.0-or-later */
/* liftoff_events.c — the event-driven integration of liftoff_events.h. */
#include "liftoff_events.h"

#include <check.h>
#include <math.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "event_period.h"
#include "orbit_state.h"

static const double PI = 3.14159265358979323846;

enum { OPEN = 2, STICK = 0, SLIP_UP = 1, SLIP_DOWN = -1 };

/* The system, the element's mode and the touchdowns so far, for GSL's right-hand side and
 * event_period's callbacks. */
struct phase {
    const struct liftoff_system *sys;
    int mode, touchdowns;
};

static double dot(const double *a, const double *x, size_t n)
{
    double s = 0.0;
    for (size_t k = 0; k < n; k++)
        s += a[k] * x[k];
    return s;
}

/* The normal force of the closed law at x (negative: it would pull). */
static double normal_force(const struct liftoff_system *s, const double *x)
{
    return s->n0 + s->kn * dot(s->Jn, x, s->n);
}

/* The element's forces f, N at y in the mode. */
static void forces(const struct phase *ph, const double *y, double *f, double *N)
{
    const struct liftoff_system *s = ph->sys;
    size_t n = s->n;
    *f = *N = 0.0;
    if (ph->mode == OPEN)
        return;
    *N = normal_force(s, y);
    *f = ph->mode == STICK ? s->kt * (dot(s->J, y, n) - y[2 * n]) : ph->mode * s->mu * *N;
}

static int rhs(double t, const double y[], double dy[], void *params)
{
    const struct phase *ph = params;
    const struct liftoff_system *s = ph->sys;
    size_t n = s->n;
    double f, N;
    forces(ph, y, &f, &N);
    for (size_t i = 0; i < n; i++) {
        double a = s->p[i] * cos(s->omega * t) - s->J[i] * f - s->Jn[i] * N;
        for (size_t k = 0; k < n; k++)
            a -= s->C[n * i + k] * y[n + k] + s->K[n * i + k] * y[k];
        dy[i] = y[n + i];
        dy[n + i] = a;
    }
    double du = dot(s->J, y + n, n), dg = dot(s->Jn, y + n, n);
    dy[2 * n] = ph->mode == STICK  ? 0.0
                : ph->mode == OPEN ? du
                                   : du - ph->mode * s->mu * s->kn * dg / s->kt;
    return GSL_SUCCESS;
}

/* The mode's switch functions at y, negative until a switch: [0] the contact's (open: the
 * closed law's N, a touchdown; closed: −N, an opening), [1] the slider's (stick: the margin to
 * the bound; slip: the offset's velocity against the slip; open: none). */
static void switch_functions(const struct phase *ph, const double y[], double sw[2])
{
    const struct liftoff_system *s = ph->sys;
    size_t n = s->n;
    double N = normal_force(s, y);
    sw[0] = ph->mode == OPEN ? N : -N;
    if (ph->mode == OPEN)
        sw[1] = -1.0;
    else if (ph->mode == STICK)
        sw[1] = fabs(s->kt * (dot(s->J, y, n) - y[2 * n])) - s->mu * N;
    else
        sw[1] = -ph->mode *
                (dot(s->J, y + n, n) - ph->mode * s->mu * s->kn * dot(s->Jn, y + n, n) / s->kt);
}

static double until_switch(void *params, const double y[])
{
    double sw[2];
    switch_functions(params, y, sw);
    return fmax(sw[0], sw[1]);
}

/* The mode after the switch that fired at y (sw[k] >= 0), the offset set where it jumps. */
static void switch_mode(void *params, double y[])
{
    struct phase *ph = params;
    const struct liftoff_system *s = ph->sys;
    size_t n = s->n;
    double sw[2], u = dot(s->J, y, n);
    switch_functions(ph, y, sw);
    if (sw[0] >= sw[1]) { /* the contact */
        if (ph->mode == OPEN) {
            y[2 * n] = u; /* touchdown: the spring unloaded */
            ph->touchdowns++;
        }
        ph->mode = ph->mode == OPEN ? STICK : OPEN;
        return;
    }
    if (ph->mode == STICK) { /* slips towards the bound reached, the offset on it */
        ph->mode = u - y[2 * n] > 0.0 ? SLIP_UP : SLIP_DOWN;
        y[2 * n] = u - ph->mode * s->mu * normal_force(s, y) / s->kt;
    } else {
        ph->mode = STICK;
    }
}

void liftoff_period(const struct liftoff_system *sys, double t0, const double *z0, double *z,
                    int *touchdowns)
{
    struct phase ph = {sys, STICK, 0};
    struct event_system es = {{rhs, NULL, 2 * sys->n + 1, &ph}, until_switch, switch_mode};
    event_period(&es, t0, 2.0 * PI / sys->omega, z0, z);
    ck_assert_int_eq(ph.mode, STICK); /* the period ends as it started */
    if (touchdowns != NULL)
        *touchdowns = ph.touchdowns;
}

void liftoff_start(const struct liftoff_system *sys, int H, const double *x, double *t0, double *z)
{
    const int samples = 20000;
    const size_t n = sys->n;
    const double T = 2.0 * PI / sys->omega;
    double w = 0.0, best = -1.0, bound_best = 0.0, y[2 * LIFTOFF_MAXN];
    for (int i = 0; i <= 2 * samples; i++) {
        double t = T * i / samples;
        orbit_state_at(n, H, x, sys->omega, t, y);
        double u = dot(sys->J, y, n), N = fmax(0.0, normal_force(sys, y)), bound = sys->mu * N;
        if (i == 0)
            w = u;
        double trial = sys->kt * (u - w);
        if (fabs(trial) > bound)
            w = u - copysign(bound, trial) / sys->kt;
        double margin = bound - fabs(sys->kt * (u - w));
        if (i > samples && N > 0.0 && margin > best) {
            best = margin, bound_best = bound;
            *t0 = t;
            memcpy(z, y, 2 * n * sizeof *z);
            z[2 * n] = w;
        }
    }
    ck_assert_double_gt(best, 0.1 * bound_best);
}

/* Phi[nz nz] of the period map at z by central differences of step h. */
static void period_jacobian(const struct liftoff_system *sys, double t0, const double *z, double h,
                            double *Phi)
{
    const size_t nz = 2 * sys->n + 1;
    for (size_t j = 0; j < nz; j++) {
        double zp[LIFTOFF_MAXZ], zm[LIFTOFF_MAXZ], fp[LIFTOFF_MAXZ], fm[LIFTOFF_MAXZ];
        memcpy(zp, z, nz * sizeof *zp);
        memcpy(zm, z, nz * sizeof *zm);
        zp[j] += h, zm[j] -= h;
        liftoff_period(sys, t0, zp, fp, NULL);
        liftoff_period(sys, t0, zm, fm, NULL);
        for (size_t i = 0; i < nz; i++)
            Phi[nz * i + j] = (fp[i] - fm[i]) / (2.0 * h);
    }
}

void liftoff_shoot(const struct liftoff_system *sys, double t0, double *z, double *Phi)
{
    const size_t nz = 2 * sys->n + 1;
    double zn[LIFTOFF_MAXZ], r[LIFTOFF_MAXZ], scale = 0.0;
    for (size_t j = 0; j < nz; j++)
        scale = fmax(scale, fabs(z[j]));
    for (int it = 0;; it++) {
        ck_assert_int_lt(it, 30);
        liftoff_period(sys, t0, z, zn, NULL);
        double res = 0.0;
        for (size_t j = 0; j < nz; j++)
            r[j] = zn[j] - z[j], res = fmax(res, fabs(r[j]));
        if (res <= 1e-12 * scale)
            break;
        period_jacobian(sys, t0, z, 1e-7 * scale, Phi);
        shooting_newton_step(nz, Phi, r, z);
    }
    period_jacobian(sys, t0, z, 1e-7 * scale, Phi);
}
