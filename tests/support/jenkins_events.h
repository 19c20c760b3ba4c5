/* SPDX-License-Identifier: GPL-3.0-or-later */
/* jenkins_events.h — an event-driven time integration of a few unit masses with one Jenkins
 * element, the time-domain reference of the harmonic-balance tests (test_hb_monodromy,
 * test_hb_nma_shooting).
 *
 * The model: x'' + C x' + K x + J^T f = p cos Ωt, n <= 3 dofs, f the element's force on its
 * row u = J x: kt (u − w) while it sticks, ±mu N while it slips (w, the slider's offset,
 * follows u). The state z = (x, v, w), 2n + 1 numbers. GSL's rk8pd at a fixed step of T/2000
 * between the switches, each switch (stick → slip where kt |u − w| reaches mu N, slip → stick
 * where u' turns) located by bisection on the step to 1e-14 T and the offset then set on its
 * bound. */
#ifndef FRICREG_TEST_JENKINS_EVENTS_H
#define FRICREG_TEST_JENKINS_EVENTS_H

#include <stddef.h>

#define JENKINS_MAXN 3
#define JENKINS_MAXZ (2 * JENKINS_MAXN + 1)

struct jenkins_system {
    size_t n; /* dofs, 1 <= n <= JENKINS_MAXN */
    double K[JENKINS_MAXN * JENKINS_MAXN], C[JENKINS_MAXN * JENKINS_MAXN]; /* row-major n x n */
    double J[JENKINS_MAXN];                                                /* the element's row */
    double kt, mun;                                                        /* the element */
    double p[JENKINS_MAXN]; /* the force's amplitudes */
    double omega;           /* Ω of the force, and the period T = 2π/Ω integrated */
};

/* z at t0 + T from z0 at t0, z[2n + 1] (the slider sticking at t0; asserted to stick at
 * t0 + T). */
void jenkins_period(const struct jenkins_system *sys, double t0, const double *z0, double *z);

/* The period map's Jacobian Phi[(2n + 1)²] (row-major) at z by central differences (steps
 * 1e-6). */
void jenkins_monodromy(const struct jenkins_system *sys, double t0, const double *z, double *Phi);

/* A start on a harmonic-balance orbit: x[n (2H + 1)] the dofs' coefficients (x0, a_1, b_1, ...,
 * a_H, b_H) at the frequency sys->omega, the slider's offset from its return map over two
 * periods; *t0 and z the instant of the second period where the slider is deepest in a stick
 * (asserted: a margin above a tenth of mu N). */
void jenkins_start(const struct jenkins_system *sys, int H, const double *x, double *t0, double *z);

/* Newton's shooting on z = period(z) from z at t0 (a forced orbit), to 1e-13. */
void jenkins_shoot(const struct jenkins_system *sys, double t0, double *z);

#endif
