/* SPDX-License-Identifier: GPL-3.0-or-later */
/**
 * \file
 * fricreg_types.h — the run settings shared by the reference systems' drivers (fricreg_sim.h)
 * and the structure (fricreg_structure.h): which integrator, which error estimate.
 *
 * Only enumerations: no function, no object. fricreg_sim.h and fricreg_structure.h include it,
 * so a program that includes either has them (as with 1.7, when they lived in fricreg_sim.h).
 */
#ifndef FRICREG_TYPES_H
#define FRICREG_TYPES_H

#ifdef __cplusplus
extern "C" {
#endif

/** \defgroup types Run settings: integrators and error estimates (fricreg_sim, fricreg_structure)
 *  The integrator numbering and the estimator kinds that fricreg_sim and fricreg_structure
 *  both take.
 *  \{ */

/** Integrators: our own numbering of GSL's gsl_odeiv2 steppers. Values are fixed forever. */
enum fricreg_integrator {
    FRICREG_INT_RK2 = 1, /**< explicit embedded Runge–Kutta (2, 3) */
    /** explicit classical 4th-order Runge–Kutta (the paper's). Adaptive: GSL's rk4 (error by
     *  step doubling). Fixed steps: fricreg's own gsl_odeiv2 step type on GSL rk4's grid, the
     *  same numbers to rounding for 4 right-hand sides per step instead of 6. */
    FRICREG_INT_RK4 = 2,
    FRICREG_INT_RKF45 = 3,    /**< explicit Runge–Kutta–Fehlberg (4, 5) */
    FRICREG_INT_RKCK = 4,     /**< explicit Runge–Kutta Cash–Karp (4, 5) */
    FRICREG_INT_RK8PD = 5,    /**< explicit Runge–Kutta Prince–Dormand (8, 9) */
    FRICREG_INT_RK1IMP = 6,   /**< implicit Euler */
    FRICREG_INT_RK2IMP = 7,   /**< implicit Gaussian 2nd order */
    FRICREG_INT_RK4IMP = 8,   /**< implicit Gaussian 4th order */
    FRICREG_INT_BSIMP = 9,    /**< implicit Bulirsch–Stoer (Bader–Deuflhard) */
    FRICREG_INT_MSADAMS = 10, /**< variable-order Adams, explicit-implicit */
    FRICREG_INT_MSBDF = 11,   /**< variable-order BDF, for stiff problems */
    /** GSL's rk4 in fixed steps too (6 right-hand sides per step), to compare with
     *  FRICREG_INT_RK4. */
    FRICREG_INT_RK4_GSL = 12,
    /** explicit central differences (Newmark beta = 0, gamma = 1/2), fricreg's own, fixed steps
     *  only: x1 = x + dt v + dt^2/2 a, a1 = a(x1, v*) with the velocity predictor
     *  v* = v + dt a seen by the friction, v1 = v + dt (a + a1)/2; one right-hand side per
     *  step, second order (src/sim/central_step.c). Stable for (dt omega/2)^2 + dt lambda < 1;
     *  the guard takes 0.9 (fricreg_sim_run). Not for fricreg_structure_run_ode (the structure has its own
     *  central difference). Since 1.3.0. */
    FRICREG_INT_CENTRAL = 13,
    /** FRICREG_INT_CENTRAL with the friction of the step's end implicit (IMEX: springs
     *  explicit, friction implicit): a1 = a_free(x1) + W f1 and v1 = v + dt (a + a1)/2 with
     *  f1 = law (4) at (v1, f_eq(x1)), solved exactly contact by contact (law (4) is piecewise
     *  linear in v: no iteration; src/sim/central_imex.c). The trapezoid on the friction is
     *  A-stable, so the stick zone bounds no step: the guard is the springs',
     *  (dt omega/2)^2 < 0.9, and, where dt lambda >= 0.9 (eps below about 2.2 dt mun W_ii:
     *  law (4)'s band is crossed within one step, as a law that jumps), also
     *  dt omega <= 1/sqrt 2 (fricreg_sim_run). Second order, one right-hand side per step. Law (4) only, on systems whose contacts are the bodies with a diagonal W (the
     *  oscillator and the chain); fricreg_sim_run refuses anything else with FRICREG_EINVAL.
     *  Fixed steps only. Since 1.5.0. */
    FRICREG_INT_CENTRAL_IMEX = 14
};

/** The estimators of fricreg_sim_set_error_estimate and fricreg_structure_set_error_estimate
 *  (their argument on). Values are fixed forever. Since 1.7 (in fricreg_structure.h until
 *  fricreg_sim took the same three; in fricreg_sim.h until 1.8). */
enum fricreg_error_estimate {
    FRICREG_ESTIMATE_OFF = 0, /**< no estimate (the default) */
    /** two companions, at eps / 2 and eps / 4, the observed order and a range test; 1 was one
     *  companion until 1.6 */
    FRICREG_ESTIMATE_TWO_COMPANIONS = 1,
    FRICREG_ESTIMATE_ONE_COMPANION = 2 /**< 1.6's: one companion at eps / 2, 3 |q - q2| */
};

/** The kind of an error estimate (fricreg_sim_get_dissipation_error_kind,
 *  fricreg_structure_get_error_kind): what the three values q, q2 = q(eps / 2),
 *  q4 = q(eps / 4) of the two-companion estimator showed (src/base/companion_estimate.c), and so
 *  how far the estimate is from the error. Values are fixed forever; the names are short
 *  for Fortran's 31 characters. Since 1.8 (FRICREG_1.8);
 *  they replace FRICREG_WARN_NOT_ASYMPTOTIC, raised where the kind is BOUND until 1.7. */
enum fricreg_estimate_kind {
    /** the three values show the law's order (d1 / d2 >= 2^0.5 with d1 = q - q2,
     *  d2 = q2 - q4, or d2 at the solver's noise with d1 above it): Richardson's correction
     *  with the observed order, times 2, expected 1 ... 3x the error */
    FRICREG_EST_KIND_ASYMPTOTIC = 1,
    /** they do not (an order below the range, differences of opposite signs, or both at the
     *  solver's noise level), or the estimate could not be formed (+infinity): a safe upper
     *  bound, not an estimate of the error's size */
    FRICREG_EST_KIND_BOUND = 2,
    /** one companion (1.6's estimator, FRICREG_ESTIMATE_ONE_COMPANION): the law's lower order
     *  assumed, not checked */
    FRICREG_EST_KIND_ASSUMED = 3
};

/** \} */

#ifdef __cplusplus
}
#endif

#endif /* FRICREG_TYPES_H */
