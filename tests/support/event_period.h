/* SPDX-License-Identifier: GPL-3.0-or-later */
/* event_period.h — the event-driven shootings' shared parts (jenkins_events.c,
 * liftoff_events.c): one period of a system whose right-hand side changes at switches located
 * on the way (GSL's rk8pd at a fixed step of T/2000 between them, each switch found by
 * bisection on the step to 1e-14 T), and the shooting's Newton step. */
#ifndef FRICREG_TEST_EVENT_PERIOD_H
#define FRICREG_TEST_EVENT_PERIOD_H

#include <stddef.h>

#include <gsl/gsl_odeiv2.h>

/* The caller's system: ode's right-hand side reads the mode from ode.params, as do the two
 * callbacks, which get ode.params. */
struct event_system {
    gsl_odeiv2_system ode;
    /* Negative until the mode's next switch, at y. */
    double (*until_switch)(void *params, const double y[]);
    /* The new mode after the switch that fired at y, and y's jumps there, in place. */
    void (*switch_mode)(void *params, double y[]);
};

/* z[ode.dimension] at t0 + T from z0 at t0 (at most 8 numbers). */
void event_period(struct event_system *es, double t0, double T, const double *z0, double *z);

/* The shooting's Newton step on z = P(z): z −= (Phi − I)^-1 r, r = P(z) − z, Phi[nz nz] the
 * period map's Jacobian (row-major; destroyed), by GSL's LU. */
void shooting_newton_step(size_t nz, double *Phi, double *r, double *z);

#endif
