/* SPDX-License-Identifier: GPL-3.0-or-later */
/* jenkins_pair_events.h — an event-driven time integration of two unit masses with one
 * Jenkins element on one of them, the time-domain reference of the harmonic-balance tests
 * (test_hb_monodromy, test_hb_nma_fold).
 *
 * The model: x'' + C x' + K x + e_d f = (p cos Ωt, 0), f the element's force on dof d:
 * kt (x_d − w) while it sticks, ±mu N while it slips (w, the slider's offset, follows x_d).
 * The state z = (x1, x2, v1, v2, w). GSL's rk8pd at a fixed step of T/2000 between the
 * switches, each switch (stick → slip where kt |x_d − w| reaches mu N, slip → stick where
 * x_d' turns) located by bisection on the step to 1e-14 T and the offset then set on its
 * bound. */
#ifndef FRICREG_TEST_JENKINS_PAIR_EVENTS_H
#define FRICREG_TEST_JENKINS_PAIR_EVENTS_H

struct jenkins_pair {
    double K[4], C[4]; /* row-major 2x2, the mass matrix the identity */
    double kt, mun;    /* the element */
    int dof;           /* the element's dof, 0 or 1 */
    double force;      /* p, on dof 0 */
    double omega;      /* Ω of the force, and the period T = 2π/Ω integrated */
};

/* z at t0 + T from z0 at t0 (the slider sticking at t0; asserted to stick at t0 + T). */
void jenkins_pair_period(const struct jenkins_pair *sys, double t0, const double z0[5],
                         double z[5]);

/* The period map's Jacobian Phi[5 5] (row-major) at z by central differences (steps 1e-6). */
void jenkins_pair_monodromy(const struct jenkins_pair *sys, double t0, const double z[5],
                            double Phi[25]);

/* A start on a harmonic-balance orbit: x[2 (2H + 1)] the two dofs' coefficients (x0, a_1,
 * b_1, ..., a_H, b_H) at the frequency sys->omega, the slider's offset from its return map
 * over two periods; *t0 and z the instant of the second period where the slider is deepest in
 * a stick (asserted: a margin above a tenth of mu N). */
void jenkins_pair_start(const struct jenkins_pair *sys, int H, const double *x, double *t0,
                        double z[5]);

/* Newton's shooting on z = period(z) from z at t0 (a forced orbit), to 1e-13. */
void jenkins_pair_shoot(const struct jenkins_pair *sys, double t0, double z[5]);

#endif
