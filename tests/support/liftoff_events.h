/* SPDX-License-Identifier: GPL-3.0-or-later */
/* liftoff_events.h — an event-driven time integration of a few unit masses with one Jenkins
 * element under a normal law with lift-off, the time-domain reference of the stability tests
 * where a slider sticks after a touchdown (test_hb_stability).
 *
 * The model: x'' + C x' + K x + J^T f + Jn^T N = p cos Ωt, n <= 3 dofs, the element on the rows
 * u = J x (tangential) and g = Jn x (normal): N = n0 + kn g while closed (N > 0) and 0 while
 * open; f = kt (u − w) while it sticks, d mu N while it slips in direction d (the offset w then
 * on its bound, w = u − d mu N / kt), 0 while open (w following u). The state z = (x, v, w),
 * 2n + 1 numbers. GSL's rk8pd at a fixed step of T/2000 between the switches, each located by
 * bisection on the step to 1e-14 T: an opening where N reaches 0; a touchdown where n0 + kn g
 * does, the offset then set to u (the spring unloaded: the exact monodromy's and the AFT's
 * convention); a slip onset where kt |u − w| reaches mu N; a stop where the sliding offset's
 * velocity u' − d (mu kn / kt) g' reaches 0. */
#ifndef FRICREG_TEST_LIFTOFF_EVENTS_H
#define FRICREG_TEST_LIFTOFF_EVENTS_H

#include <stddef.h>

#define LIFTOFF_MAXN 3
#define LIFTOFF_MAXZ (2 * LIFTOFF_MAXN + 1)

struct liftoff_system {
    size_t n;                                                              /* 1 <= n <= 3 */
    double K[LIFTOFF_MAXN * LIFTOFF_MAXN], C[LIFTOFF_MAXN * LIFTOFF_MAXN]; /* row-major */
    double J[LIFTOFF_MAXN], Jn[LIFTOFF_MAXN]; /* the element's tangential and normal rows */
    double kt, mu, n0, kn;                    /* the element */
    double p[LIFTOFF_MAXN];                   /* the force's amplitudes (cos Ωt) */
    double omega;                             /* Ω, and the period T = 2π/Ω integrated */
};

/* z at t0 + T from z0 at t0, z[2n + 1], the element closed and sticking at t0 (asserted to be so
 * again at t0 + T); *touchdowns (or NULL): the touchdowns on the way. */
void liftoff_period(const struct liftoff_system *sys, double t0, const double *z0, double *z,
                    int *touchdowns);

/* A start on a harmonic-balance orbit: x[n (2H + 1)] the dofs' coefficients (x0, a_1, b_1, ...)
 * at sys->omega, the offset from its return map over two periods; *t0 and z at the instant of
 * the second period where the element is closed and deepest in a stick (asserted: a margin
 * above a tenth of its bound). */
void liftoff_start(const struct liftoff_system *sys, int H, const double *x, double *t0, double *z);

/* Newton's shooting on z = period(z) from z at t0, to 1e-12; then the monodromy Phi[(2n + 1)²]
 * (row-major) at the orbit by central differences (steps 1e-7 of the state's scale). */
void liftoff_shoot(const struct liftoff_system *sys, double t0, double *z, double *Phi);

#endif
