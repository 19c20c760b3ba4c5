/* SPDX-License-Identifier: GPL-3.0-or-later */
/* central.h — internal: explicit central differences, the one scheme behind fricreg_sim's
 * FRICREG_INT_CENTRAL (src/sim/central_step.c) and fricreg_structure's central difference
 * (src/structure/central_difference.c); its stability guard is step_guard.c's.
 *
 * Newmark's family with beta = 0, gamma = 1/2 (N. M. Newmark, J. Eng. Mech. Div. ASCE 85
 * (1959); T. J. R. Hughes, The Finite Element Method (1987), Sec. 9.1). One step of h from
 * (x, v, a), a = a(t, x, v) carried over from the end of the previous step:
 *
 *   x1 = x + h v + h^2/2 a,   v* = v + h a,   a1 = a(t + h, x1, v*),   v1 = v + h (a + a1)/2.
 *
 * Undamped, x1 is the classical three-term recurrence x_{n+1} - 2 x_n + x_{n-1} = h^2 a_n.
 * Friction and damping depend on the velocity at the new time, which the scheme does not have
 * before a1: they see the explicit predictor v* (Euler's), so one evaluation per step and
 * nothing to solve. v* is off by O(h^2) from v(t + h), so v1 is Heun's (trapezoid with an Euler
 * predictor) and the step is second order in a velocity-dependent force too. The half-step
 * velocity v + h a/2 would lag by h/2, an O(h) error in the friction, and make the scheme first
 * order wherever friction depends on velocity (the near-stick band); it would double the
 * stick-zone bound (dt lambda < 2 instead of 1), which is not worth an order. */
#ifndef FRICREG_CENTRAL_H
#define FRICREG_CENTRAL_H

/* x1 = x + h v + h^2/2 a */
static inline double fr_central_position(double h, double x, double v, double a)
{
    return x + h * v + 0.5 * h * h * a;
}

/* v* = v + h a, the velocity the evaluation at the step's end sees */
static inline double fr_central_predicted_velocity(double h, double v, double a)
{
    return v + h * a;
}

/* v1 = v + h (a + a1)/2, the trapezoid on the carried and the new acceleration */
static inline double fr_central_velocity(double h, double v, double a, double a1)
{
    return v + 0.5 * h * (a + a1);
}

#endif
