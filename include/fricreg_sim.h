/* SPDX-License-Identifier: GPL-3.0-or-later */
/**
 * \file
 * fricreg_sim.h — GSL ODE drivers for the paper's three reference systems.
 *
 * D. D. Quinn, J. Vib. Acoust. 126 (2004): the 1-dof oscillator, Eq. (5); the n-dof chain of
 * Sec. 3.2; the two blocks on a belt, Eqs. (7). Each driver integrates the bodies' positions and
 * velocities plus the dissipated energy D as one more state, by the same scheme, on GSL's
 * gsl_odeiv2 (fixed-step classical RK4 by default, the paper's method), and evaluates friction
 * through a fricreg context (fricreg.h). No GSL type crosses this header.
 *
 * Conventions are those of fricreg.h: int results are fricreg_status codes, nothing is printed,
 * a failed call leaves the caller's arrays untouched, one simulation per thread.
 */
#ifndef FRICREG_SIM_H
#define FRICREG_SIM_H

#include "fricreg.h"
#include "fricreg_types.h" /* enum fricreg_integrator, enum fricreg_error_estimate */

#ifdef __cplusplus
extern "C" {
#endif

/** \defgroup sim Simulation: the paper's reference systems (fricreg_sim)
 *  An opaque simulation of one of the paper's three reference systems, integrated by one of
 *  GSL's ODE steppers or fricreg's own central differences with friction from a context. Its
 *  parameters, law, integrator and step control are set, then it runs over a time or whole
 *  forcing cycles (optionally extrapolated in eps), and its getters read the results.
 *  \{ */

/** Reference systems. Values are fixed forever. */
enum fricreg_system {
    /** Eq.\ (5): x'' + x = f + a sin(omega t), one contact with bound mun, f_eq = x - a sin(wt).
     *  Paper defaults: a = 0, omega = 1 (sets the cycle length), mun = 1, x0 = 2.75, v0 = 0. */
    FRICREG_SYSTEM_OSCILLATOR = 1,
    /** Sec.\ 3.2: n blocks of mass 1/n, springs of stiffness n, block n tied to a wall, block 1
     *  driven by a sin(omega t), every block mun = 1, friction entering as f_i/n; W = I.
     *  Paper defaults: n = 32, a = 0.25, omega = 0.5, at rest at the origin. */
    FRICREG_SYSTEM_CHAIN = 2,
    /** Eqs.\ (7): lower block x1 on a belt u(t) = belt_amp sin(belt_omega t), upper block x2 on
     *  it, springs 1 and k to the ground; contacts z1 = x1 - u, z2 = x2 - x1 with bounds mu1,
     *  mu2; W = [[1, -1], [-1, 2]]. Paper defaults: k = 2, mu1 = 0.5, mu2 = 0.25,
     *  belt_amp = 1, belt_omega = 0.5, at rest at the origin. */
    FRICREG_SYSTEM_TWOBLOCK = 3
};

/** System parameters for fricreg_sim_set_param and fricreg_sim_get_param. Values are fixed
 *  forever. Which system reads which is listed at each; setting or reading one the system
 *  does not read is FRICREG_EINVAL. */
enum fricreg_param {
    FRICREG_PARAM_A = 1,          /**< forcing amplitude a (oscillator, chain), finite */
    FRICREG_PARAM_OMEGA = 2,      /**< forcing frequency omega > 0 (oscillator, chain) */
    FRICREG_PARAM_MUN = 3,        /**< friction bound mun >= 0 (oscillator) */
    FRICREG_PARAM_X0 = 4,         /**< initial position (oscillator) */
    FRICREG_PARAM_V0 = 5,         /**< initial velocity (oscillator) */
    FRICREG_PARAM_N = 6,          /**< number of blocks n, integer 2 … 10^7 (chain) */
    FRICREG_PARAM_K = 7,          /**< upper spring stiffness K > 0 (twoblock) */
    FRICREG_PARAM_MU1 = 8,        /**< lower interface bound mu1 N >= 0 (twoblock) */
    FRICREG_PARAM_MU2 = 9,        /**< upper interface bound mu2 N >= 0 (twoblock) */
    FRICREG_PARAM_BELT_AMP = 10,  /**< belt displacement amplitude (twoblock) */
    FRICREG_PARAM_BELT_OMEGA = 11 /**< belt frequency > 0 (twoblock) */
};

/** The name of an integrator: GSL's ("rk4", "msbdf", …), "rk4-gsl" for FRICREG_INT_RK4_GSL,
 *  "central" for FRICREG_INT_CENTRAL and "central-imex" for FRICREG_INT_CENTRAL_IMEX; NULL if
 *  unknown. Static storage. */
FRICREG_API const char *fricreg_integrator_name(int integrator);

/** The integrator named `name` (as above). Returns its enum value, not a status: 0 if there
 *  is none (or name is NULL). */
FRICREG_API int fricreg_integrator_from_name(const char *name);

/** Opaque simulation of one reference system: parameters, law, integrator, results. */
typedef struct fricreg_sim fricreg_sim;

/** Create a simulation of `system` (enum fricreg_system) with the paper's parameters, law (4)
 *  and fixed-step RK4 with dt = 0.01 and eps following the paper's rule (see
 *  fricreg_sim_set_law). Release with fricreg_sim_free.
 *  Returns FRICREG_OK; FRICREG_ENULL if out is NULL; FRICREG_EINVAL for an unknown system;
 *  FRICREG_ENOMEM. */
FRICREG_API int fricreg_sim_create(int system, fricreg_sim **out);

/** Release a simulation. fricreg_sim_free(NULL) does nothing. */
FRICREG_API void fricreg_sim_free(fricreg_sim *sim);

/** Set one system parameter (enum fricreg_param; units nondimensional as in the paper).
 *  Discards any results. Returns FRICREG_OK; FRICREG_ENULL; FRICREG_EINVAL for a parameter
 *  the system does not have or a value out of its range; FRICREG_ENONFINITE. */
FRICREG_API int fricreg_sim_set_param(fricreg_sim *sim, int param, double value);

/** Read the value in use of one system parameter (enum fricreg_param): the paper's default
 *  (enum fricreg_system) or the value last set by fricreg_sim_set_param. The chain's n reads
 *  as an exact integer-valued double.
 *  sim    in: the simulation; not modified (errcode and errmsg included).
 *  param  in: the parameter; the system must read it (see enum fricreg_param).
 *  value  out: the value; written only on success.
 *  Returns FRICREG_OK; FRICREG_ENULL if sim or value is NULL; FRICREG_EINVAL for a parameter
 *  the system does not read or an unknown one. Since ABI 1.1. */
FRICREG_API int fricreg_sim_get_param(const fricreg_sim *sim, int param, double *value);

/** Select the friction law (enum fricreg_law) and eps > 0; eps = 0 selects the paper's rule,
 *  recomputed from dt: eps = 2 dt (oscillator, twoblock), eps = 10 omega dt (chain).
 *  Under that rule a fixed explicit step may be refused at every dt (FRICREG_ESTEP from
 *  fricreg_sim_run, whose message names the smallest eps that passes): set eps explicitly then.
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_EINVAL for an unknown law or eps < 0;
 *  FRICREG_ENONFINITE. */
FRICREG_API int fricreg_sim_set_law(fricreg_sim *sim, int law, double eps);

/** Select how coupled contacts are partitioned (enum fricreg_partition; default
 *  FRICREG_PARTITION_CONSISTENT; see fricreg_ctx_set_partition). Only the two blocks have
 *  coupled contacts; the oscillator and the chain give the same numbers under both.
 *  Discards any results. Returns FRICREG_OK; FRICREG_ENULL; FRICREG_EINVAL for an unknown
 *  partition. */
FRICREG_API int fricreg_sim_set_partition(fricreg_sim *sim, int partition);

/** Select the integrator (enum fricreg_integrator) and its step control.
 *  rtol = atol = 0: fixed step dt > 0 (each cycle's last step is shortened to end on the cycle
 *  boundary). atol = FRICREG_ATOL_FROM_EPS (-1) with rtol > 0: adaptive with absolute
 *  tolerances per component derived from eps (since 1.6, FRICREG_1.6; the one that holds for
 *  coupled contacts): each body velocity is held to
 *  atol_v = min(1e-3 eps, rtol x 1 velocity unit) absolutely, with no relative part, and
 *  positions and D to rtol + rtol |y_i| (GSL's standard level with atol = rtol in the
 *  nondimensional systems' units). Law (4) reads the contact velocity, a difference of body
 *  velocities of order 1 that lies within its band |zdot| < eps at a stick: a relative
 *  tolerance on the body velocity, or one atol >= eps, leaves the force there uncontrolled.
 *  Measured on the two blocks (docs/integrators.md, "Absolute tolerances from eps"): msbdf at
 *  eps = 1e-6 gives D on cycle 4 within 5e-6 from rtol 1e-4 to 1e-8, where atol = rtol = 1e-6
 *  gave +8e-3; fricreg_sim_get_abs_tolerances reads the values. Otherwise (atol >= 0)
 *  adaptive with GSL's standard control (|error| <= atol + rtol |y|),
 *  dt the initial step, and no step longer than 1/32 of the forcing period: while every
 *  contact sticks the state is at rest and the error estimate is zero, so an uncapped step
 *  could pass over a whole slip phase. Implicit steppers (rk1imp, rk2imp, rk4imp, bsimp,
 *  msbdf) get the exact Jacobian of the state equations: the context's tangent
 *  (fricreg_ctx_tangent) chained through the system's linear kinematics, one right-hand side
 *  per Jacobian, exact wherever the forces are differentiable.
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_EINVAL for an unknown integrator, dt <= 0,
 *  rtol < 0 or atol < 0 other than FRICREG_ATOL_FROM_EPS, FRICREG_ATOL_FROM_EPS with
 *  rtol = 0, rtol or atol nonzero with FRICREG_INT_CENTRAL or
 *  FRICREG_INT_CENTRAL_IMEX (fixed steps only), or rtol > 0 with atol = 0 for rk1imp, rk2imp,
 *  rk4imp, msadams or msbdf (their iteration converges to atol + rtol |y|, which is 0 where a
 *  state component is 0, as at a start from rest; GSL reports that level to its error
 *  handler); FRICREG_ENONFINITE. */
FRICREG_API int fricreg_sim_set_integrator(fricreg_sim *sim, int integrator, double dt, double rtol,
                                           double atol);

/** The atol of fricreg_sim_set_integrator that selects absolute tolerances per component
 *  derived from eps (fricreg_sim_get_abs_tolerances gives them). Since 1.6 (FRICREG_1.6). */
#define FRICREG_ATOL_FROM_EPS (-1.0)

/** Set an absolute tolerance per state component, as SUNDIALS' CVodeSVtolerances does:
 *  an adaptive step is accepted where |error_i| <= atol[i] + rtol |y_i| in every component i
 *  (rtol from fricreg_sim_set_integrator, whose atol this replaces; a later
 *  fricreg_sim_set_integrator replaces these in turn). The state is y = (x, v, D): ndof body
 *  positions (length, as the system's), ndof velocities (length/time) and the dissipated
 *  energy D (force x length), n = 2 ndof + 1 components. The run is adaptive even with
 *  rtol = 0. Discards any results.
 *
 *  sim   in/out: the simulation.
 *  n     in: 2 fricreg_sim_ndof(sim) + 1 (a chain whose n changes afterwards is refused by
 *        fricreg_sim_run until they are set again).
 *  atol  in: atol[n], each finite and > 0; copied.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if sim or atol is NULL; FRICREG_ESIZE if n is not
 *  2 ndof + 1; FRICREG_ENONFINITE for an entry not finite; FRICREG_EINVAL for an entry <= 0,
 *  with FRICREG_INT_CENTRAL or FRICREG_INT_CENTRAL_IMEX (fixed steps only), or when called
 *  from the observer during a run; FRICREG_ENOMEM. On failure nothing is changed.
 *  Since 1.6 (FRICREG_1.6). */
FRICREG_API int fricreg_sim_set_abs_tolerances(fricreg_sim *sim, size_t n, const double atol[]);

/** Copy the absolute tolerances an adaptive run of sim uses, per component of y = (x, v, D)
 *  (see fricreg_sim_set_abs_tolerances), at the eps in use (FRICREG_VALUE_EPS): those set by
 *  fricreg_sim_set_abs_tolerances, the one atol of fricreg_sim_set_integrator in every
 *  component, or under FRICREG_ATOL_FROM_EPS the rule's (fricreg_sim_set_integrator: its
 *  velocity entries carry no relative part); zeros for a fixed-step run. An extrapolated run's
 *  finer levels apply the rule at their own eps / 2^k.
 *
 *  sim   in: the simulation; not modified.
 *  n     in: 2 fricreg_sim_ndof(sim) + 1.
 *  atol  out: atol[n]; written only on success.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if sim or atol is NULL; FRICREG_ESIZE if n is not
 *  2 ndof + 1 (or not the length set, for a chain whose n changed since). Since 1.6
 *  (FRICREG_1.6). */
FRICREG_API int fricreg_sim_get_abs_tolerances(const fricreg_sim *sim, size_t n, double atol[]);

/** Called after every accepted step with the state at time t: the ndof body positions x and
 *  velocities v, and the m contact friction forces f and f_eq (NaN where not computed, as in
 *  fricreg_ctx_eval), all evaluated at (t, x, v). The arrays are valid during the call only.
 *  Return 0 to go on, nonzero to stop the run early (fricreg_sim_run then returns FRICREG_OK).
 *  It may call the getters of its simulation; a setter or fricreg_sim_run called on it
 *  from here returns FRICREG_EINVAL and changes nothing (the run goes on); it must not free
 *  it. */
typedef int (*fricreg_sim_observer)(void *user, double t, size_t ndof, const double x[],
                                    const double v[], size_t m, const double f[],
                                    const double f_eq[]);

/** Install an observer (NULL removes it); user is passed back unchanged. Also called once at
 *  t = 0. Returns FRICREG_OK; FRICREG_ENULL if sim is NULL; FRICREG_EINVAL if called from the
 *  observer during a run. */
FRICREG_API int fricreg_sim_set_observer(fricreg_sim *sim, fricreg_sim_observer fn, void *user);

/** Bound the adaptive steps accepted in one forcing cycle at max_steps >= 1, or remove the
 *  bound with 0. By default 10^4 for the laws that jump ((1), (2), Karnopp), whose jump an
 *  adaptive stepper chases at a stick in ever smaller steps, and 10^6 for the others (rk8pd on
 *  the chain of 1000 blocks at rtol 1e-10 takes 4.3e5). A run whose cycle needs more returns
 *  FRICREG_EWORK. Fixed steps are bounded before the run starts (fricreg_sim_run).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_EINVAL if max_steps < 0 or called from the
 *  observer during a run. Since 1.6 (FRICREG_1.6). */
FRICREG_API int fricreg_sim_set_max_steps(fricreg_sim *sim, int64_t max_steps);

/** Whether adaptive runs stop at the kinks of the friction law (on by default since 1.6,
 *  FRICREG_1.6; docs/integrators.md, "Kink location in fricreg's drivers"). Law (4) and the
 *  others are piecewise smooth in the contact state (fricreg_ctx_switching lists the kinks):
 *  an error-controlled or multistep stepper that steps over a kink loses its order and its
 *  error estimate there, and at eps = 1e-6 msbdf with rtol = atol = 1e-6 returned D on the two
 *  blocks' cycle 4 43% too large with no stick on the upper block.
 *
 *  With location on, after each accepted adaptive step the switching functions at the new
 *  state are compared with those at the step's start (one evaluation of the friction and of
 *  fricreg_ctx_switching per step). Where a component changed sign, the first crossing is
 *  found by Brent's method on trial steps of a one-step stepper from the step's start (the
 *  run's own, or for msadams rk8pd and for msbdf rk4imp) to 1e-10 of the step (or 4 ulps of
 *  t); the step is cut to end just past the kink, on the trial step's state where GSL's error
 *  control accepts it (else the stepper re-integrates to that time under its control), and
 *  the stepper is restarted there (gsl_odeiv2_driver_reset: a multistep stepper at order 1).
 *  Each location counts as a step against fricreg_sim_set_max_steps's bound and in
 *  FRICREG_SIM_STAT_KINKS; its trial steps' right-hand sides count in
 *  FRICREG_SIM_STAT_RHS_EVALS. Fixed-step runs are never changed by this setting; with it off
 *  an adaptive run is the one of fricreg 1.5, to the bit. Measured (docs/integrators.md): the
 *  run above gives +0.8% with both stick fractions within 2e-3; location does not make an
 *  absolute tolerance of the order of eps accurate in the velocities, where a run chatters
 *  across the zone's edges at great cost (rtol = atol = 1e-4 there: 3.3 s for +1.2%); the
 *  tolerances from eps do (fricreg_sim_set_integrator, FRICREG_ATOL_FROM_EPS: -4.8e-6 in 7 ms).
 *
 *  on     in: 1 to locate the kinks (default), 0 to step over them.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if sim is NULL; FRICREG_EINVAL if on is neither 0 nor 1,
 *  or if called from the observer during a run. The last run's results are kept. */
FRICREG_API int fricreg_sim_set_kink_location(fricreg_sim *sim, int on);

/** Integrate from t = 0 and the initial conditions to t_end > 0 (replacing earlier results).
 *  D is recorded per forcing cycle of period 2 pi/omega (belt_omega for twoblock).
 *
 *  Before it starts, a fixed explicit step (rk2, rk4, rkf45, rkck, rk8pd, rk4-gsl, central) is
 *  checked, omega being the system's highest natural frequency (1; 2n for the chain;
 *  sqrt(max(1, k)) for the two blocks); each limit beyond is FRICREG_ESTEP, refused before any
 *  step:
 *   - the stick zone: dt * lambda must not exceed the stepper's stick-zone bound (rk2 2.5,
 *     rk4 2.78, rkf45 2.2, rkck 3.7, rk8pd 4.5; the negative real axis's, but rkf45's, whose
 *     stages overshoot the zone first, and rk8pd's, whose last stretch lets the stick zone
 *     ring), lambda the stiffness of fricreg_ctx_stick_stiffness
 *     (W_ii * 2 mun_i/eps for (4) under the consistent partition; coupled contacts included).
 *     For the laws that jump, (1), (2) and Karnopp, lambda is the chord of the jump across the
 *     band eps, W_ii mun_i/eps (coupled as (3)), and dt * lambda must not exceed 1, so that one
 *     step of chatter stays in the band |zdot| < eps;
 *   - dt * omega within the stepper's imaginary-axis bound (rk2 1.73, rk4 2.82, rkf45 0.7,
 *     rkck 0.88, rk8pd 3.7) and within 1/sqrt 2, beyond which a friction reversal inside one
 *     step can put energy in (src/ode/step_guard.c derives it).
 *  Central differences (FRICREG_INT_CENTRAL) instead need (dt omega/2)^2 + dt lambda < 0.9,
 *  the linear stability bound 1 of x'' = -omega^2 x - lambda x' (src/ode/step_guard.c derives it) with a
 *  margin for each cycle's shortened last step, and for the laws that jump also dt * lambda
 *  <= 1 and dt * omega <= 1/sqrt 2, as above. For (4) this is dt * lambda < 0.9: the paper's
 *  eps = 2 dt, dt * lambda = 2 mun W_ii / 2, is refused at every dt where mun W_ii >= 0.9.
 *  Under the paper's rule for eps (eps set to 0), eps is proportional to dt and dt * lambda does
 *  not depend on dt: a refusal by the stick zone then holds at every dt (e.g. the oscillator
 *  with mun = 3: dt * lambda = 3 > 2.78 for rk4), and the message says so and names the
 *  smallest eps to set instead; no eps is chosen silently, since eps changes the results.
 *  FRICREG_INT_CENTRAL_IMEX solves the friction implicitly and needs (dt omega/2)^2 < 0.9
 *  whatever eps, and dt omega <= 1/sqrt 2 as well where dt * lambda >= 0.9: with law (4)'s
 *  band not resolved by the step, a reversal within one step can put energy in, as above.
 *  tests/ode/test_guard.c sweeps these limits over every stepper, law and system from 0.5x to 1.5x
 *  the accepted dt: no accepted run leaves a stick or puts energy in beyond 1% of the run's
 *  energy scale (Karnopp with the paper's eps over wide bands excepted: its band pushes).
 *  After every step the state is checked for finiteness and for |y| <= 1e100, which no
 *  motion of these systems approaches (FRICREG_EDIVERGED, naming the time and the first such
 *  body, or the contact whose kinematics overflowed within
 *  a step).
 *
 *  Adaptive steps are bounded per forcing cycle (fricreg_sim_set_max_steps: 10^4 or 10^6):
 *  a cycle that needs more stops the run with FRICREG_EWORK, its state at the last step. An
 *  adaptive stepper meets that bound with a law that jumps ((1), (2), Karnopp), whose force
 *  it chases back and forth across zdot = 0 in ever smaller steps; the message says so.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_EINVAL if t_end <= 0, or too many fixed steps
 *  (more than 2^31 stepper calls: rk4 and rk4-gsl take two steps of dt a call, so 2^32 of
 *  theirs) or cycles (more than 10^9), or FRICREG_INT_CENTRAL_IMEX with a law other
 *  than (4) or on the two blocks; FRICREG_ENONFINITE; FRICREG_ESTEP; FRICREG_EDIVERGED; FRICREG_EINTEGRATOR
 *  (GSL failed, e.g. the adaptive step underflowed); FRICREG_EWORK; FRICREG_ESINGULAR;
 *  FRICREG_ENOMEM.
 *  On failure the results hold what was reached before it: a run refused before its first
 *  step (e.g. FRICREG_ESTEP) leaves the initial state, time 0 and no cycles. A call from the
 *  observer during a run is FRICREG_EINVAL. */
FRICREG_API int fricreg_sim_run(fricreg_sim *sim, double t_end);

/** fricreg_sim_run for `cycles` >= 1 whole forcing cycles.
 *  Returns FRICREG_OK, or the codes of fricreg_sim_run; FRICREG_EINVAL also if cycles < 1. */
FRICREG_API int fricreg_sim_run_cycles(fricreg_sim *sim, int cycles);

/** Number of bodies (degrees of freedom): 1, n or 2. 0 if sim is NULL. */
FRICREG_API size_t fricreg_sim_ndof(const fricreg_sim *sim);

/** Number of contacts: 1, n or 2. 0 if sim is NULL. */
FRICREG_API size_t fricreg_sim_ncontacts(const fricreg_sim *sim);

/** Quantities of a simulation, for fricreg_sim_get_value. Values are fixed forever. The
 *  counts (STEPS, RHS_EVALS, CYCLES) are also integer counters of fricreg_sim_get_stat, the
 *  preferred form for them. */
enum fricreg_sim_value {
    FRICREG_VALUE_TIME = 0,        /**< time reached by the last run */
    FRICREG_VALUE_EPS = 1,         /**< eps in use (after the paper's rule, if selected) */
    FRICREG_VALUE_DT = 2,          /**< step size (fixed) or initial step (adaptive) */
    FRICREG_VALUE_PERIOD = 3,      /**< forcing period 2 pi / omega */
    FRICREG_VALUE_STEPS = 4,       /**< accepted steps of the last run */
    FRICREG_VALUE_RHS_EVALS = 5,   /**< right-hand-side evaluations of the last run */
    FRICREG_VALUE_CYCLES = 6,      /**< whole forcing cycles completed by the last run */
    FRICREG_VALUE_DISSIPATION = 7, /**< total dissipated energy D(t) of the last run */
    /** the error estimate of FRICREG_VALUE_DISSIPATION (absolute; +infinity if it could not
     *  be formed), as fricreg_sim_get_dissipation_error's per cycle; fricreg_sim_get_value
     *  returns FRICREG_EINVAL when the last run made none. Since 1.6 (FRICREG_1.6). */
    FRICREG_VALUE_DISSIPATION_ERROR = 8,
    /** the kind (enum fricreg_estimate_kind, as a double: 1, 2 or 3) of
     *  FRICREG_VALUE_DISSIPATION_ERROR, as fricreg_sim_get_dissipation_error_kind's per cycle;
     *  FRICREG_EINVAL when the last run made no estimate. Since 1.8 (FRICREG_1.8). */
    FRICREG_VALUE_DISS_ERROR_KIND = 9
};

/** Read one quantity (enum fricreg_sim_value) into *value (counts as exact doubles below
 *  2^53; prefer fricreg_sim_get_stat for them).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_EINVAL for an unknown quantity, or
 *  FRICREG_VALUE_DISSIPATION_ERROR or FRICREG_VALUE_DISS_ERROR_KIND when the last run
 *  made no error estimate. */
FRICREG_API int fricreg_sim_get_value(const fricreg_sim *sim, int which, double *value);

/** Integer counters of the last run (zero before any run and after a setter discarded it),
 *  for fricreg_sim_get_stat. Values are fixed forever. */
enum fricreg_sim_stat {
    /** Accepted steps. Fixed step: steps of size dt, GSL's rk4 step of 2 dt counting as two
     *  (src/ode/integrator.c), a cycle's shortened last step as a full one and a retried step
     *  once. Adaptive: steps accepted by GSL's control. */
    FRICREG_SIM_STAT_STEPS = 0,
    /** Right-hand-side evaluations by the stepper, one per Jacobian of an implicit stepper
     *  included (the observer's friction evaluations are not). */
    FRICREG_SIM_STAT_RHS_EVALS = 1,
    /** Whole forcing cycles completed: the length of fricreg_sim_get_dissipation's record. */
    FRICREG_SIM_STAT_CYCLES = 2,
    /** Steps tried, rejected and retried smaller. Adaptive: rejected by GSL's error control
     *  or failed in the stepper (gsl_odeiv2_evolve's failed_steps). Fixed step: implicit or
     *  multistep steps whose iteration failed, retried as two halves; 0 for explicit ones. */
    FRICREG_SIM_STAT_REJECTED_STEPS = 3,
    /** Adaptive steps cut at a kink of the friction law and the stepper restarted there
     *  (fricreg_sim_set_kink_location); 0 with location off and for fixed steps. Since 1.6. */
    FRICREG_SIM_STAT_KINKS = 4
};

/** Read one counter of the last run (enum fricreg_sim_stat).
 *  sim    in: the simulation; not modified (errcode and errmsg included).
 *  which  in: the counter.
 *  value  out: the count; written only on success.
 *  Returns FRICREG_OK; FRICREG_ENULL if sim or value is NULL; FRICREG_EINVAL for an unknown
 *  counter. Since ABI 1.1. */
FRICREG_API int fricreg_sim_get_stat(const fricreg_sim *sim, int which, int64_t *value);

/** Copy the state at the end of the last run: x[ndof] positions, v[ndof] velocities (body
 *  coordinates: x for the oscillator, u_i for the chain, x1, x2 for the two blocks).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE if ndof is not fricreg_sim_ndof. */
FRICREG_API int fricreg_sim_get_state(const fricreg_sim *sim, size_t ndof, double x[], double v[]);

/** Copy the dissipation of each whole forcing cycle, D_k = -∫ sum_i w_i zdot_i f_i dt over
 *  cycle k (w_i = 1/n for the chain, else 1), into D[ncycles]; ncycles must equal
 *  FRICREG_VALUE_CYCLES. Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE. */
FRICREG_API int fricreg_sim_get_dissipation(const fricreg_sim *sim, size_t ncycles, double D[]);

/** Copy, per contact, the fraction of time with |zdot_i| < eps (the near-stick set) over the
 *  last whole cycle, or over the whole run if it completed none, into frac[m], each in
 *  [0, 1] (steps counted whole: a step ending in the band counts as near stick).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE if m is not fricreg_sim_ncontacts. */
FRICREG_API int fricreg_sim_get_stick_fraction(const fricreg_sim *sim, size_t m, double frac[]);

/* ---- Error estimate (since 1.6) ---------------------------------------------------------- */

/** Whether fricreg_sim_run (and fricreg_sim_run_cycles) estimates the error of D per cycle
 *  against the Coulomb problem, eps -> 0, where the run's D carries both the regularization
 *  error of law (4) (or of the law chosen) and the discretization or tolerance error. Off by
 *  default (fricreg-sim turns it on). The setting is kept across runs; the last run's
 *  results are kept.
 *
 *  The estimate: after a successful run, companion runs from t = 0 to the same time with
 *  every setting but eps / 2 and eps / 4 and, for a fixed step, dt / 2 and dt / 4 (the
 *  step-halving ladder of fricreg_sim_run_extrapolated, its levels 1 and 2), or, for an
 *  adaptive run, the tolerances (rtol, atol, per component, and the velocities' tolerance of
 *  the rule from eps) / 16 and / 256; they give D2 and D4 beside the run's D, per cycle and in
 *  total. Law (4)'s error in D is c eps^p, p = 1 or 2 (fricreg_sim_run_extrapolated); along
 *  dt / eps fixed a fixed step's error follows eps, so in the asymptotic range d1 = D - D2 and
 *  d2 = D2 - D4 have one sign and d1 / d2 = 2^p. An adaptive run's tolerance error is carried
 *  by the differences since each companion's is a fraction of it. The estimator, the same as
 *  fricreg_structure_set_error_estimate's:
 *  - on = FRICREG_ESTIMATE_TWO_COMPANIONS (1): where the observed order p = log2(d1 / d2) is
 *    at least 0.5, err = 2 |d1| 2^p / (2^p - 1) (Richardson's correction with the observed
 *    order, times 2; about 2 |d1| where p is above the law's orders); below (a stall: the run
 *    and the first companion agree on a wrong value; or differences that grow or change
 *    sign) the safe bound err = 6.83 (|d1| + |d2|), but 2 (|d1| + 2 |d2|) where they have
 *    opposite signs and |d2| <= |d1| / 8 (law (4)'s two orders give the error as
 *    (2/3) d1 + (8/3) d2; since 1.8); d2 below 1e-9 of D gives 2 |d1| + |d2|,
 *    d1 and d2 both below it 4 (|d1| + |d2|) (the factor 2 and p = 1's tail; their bare sum
 *    before 1.8). Each estimate has a kind (fricreg_sim_get_dissipation_error_kind, enum
 *    fricreg_estimate_kind): ASYMPTOTIC where the order was seen (or d2 alone is at the
 *    noise), BOUND below the range or with both at the noise (until 1.7 it raised
 *    FRICREG_WARN_NOT_ASYMPTOTIC, no longer raised). On the oscillator against the exact
 *    solver (tests/sim/test_error_estimate.c) within 1x ... 10x of the error in the asymptotic
 *    range.
 *  - on = FRICREG_ESTIMATE_ONE_COMPANION (2), 1.6's estimator: the level-1 companion only,
 *    err = 3 |d1|: 2x the difference is p = 1's factor, 3 the margin the calibration of
 *    bench/error_estimate.c asked for (docs/integrators.md, "Error estimate": against the
 *    exact solver and extrapolated references over fixed rk4 and rk8pd, central-imex and
 *    adaptive rkf45, rk8pd, msadams and msbdf, tolerances 1e-3 ... 1e-9 and eps from the rule
 *    to 1e-8, it bounded the error in 97.9% of 238 runs and was within 10x in 95.8%). It
 *    cannot see a stall: its kind is ASSUMED.
 *  Cost: a companion's run is about 2x the run for a fixed step (twice the steps), 4x at
 *  level 2, 1.4x ... 3x each for an adaptive one (rk8pd ... rkf45, msbdf). So with two
 *  companions a run costs about 7x, with one about 3x. The error of msadams and msbdf does
 *  not follow their tolerances, so their runs always carry FRICREG_WARN_ERROR_ESTIMATE: the
 *  estimate, not rtol, is their error bar.
 *
 *  Where a companion fails (e.g. FRICREG_EWORK, FRICREG_ESTEP at dt / 2) the run still
 *  succeeds, its estimates are +infinity, and fricreg_sim_warning_count raises
 *  FRICREG_WARN_ERROR_ESTIMATE with the companion's message; it raises it too where the last
 *  whole cycle's estimate (the total's without one) exceeds twice the answer tolerance times
 *  |D| (fricreg_sim_set_answer_rtol, 1e-2 by default; until 1.8 the tolerance itself, until
 *  1.7 10% of D), whatever its kind, and for msadams and msbdf (above). An
 *  adaptive run with velocity tolerances loose against eps also raises
 *  FRICREG_WARN_TOL_LOOSE: with any tolerances, a run either meets its error estimate or warns
 *  (the calibration sweep, over the caller's atol 1e-2 … 1e-10, found none).
 *  fricreg_sim_run_extrapolated makes no companion run: its extrapolation is the estimate.
 *
 *  sim  in/out: the simulation.
 *  on   in: enum fricreg_error_estimate: 1 (two companions) or 2 (one) to estimate, 0 not to
 *       (default).
 *  Returns FRICREG_OK; FRICREG_ENULL if sim is NULL; FRICREG_EINVAL if on is not 0, 1 or 2,
 *  or if called from the observer during a run. Since 1.6 (FRICREG_1.6); two companions and
 *  on = 2 since 1.7 (1 was one companion). */
FRICREG_API int fricreg_sim_set_error_estimate(fricreg_sim *sim, int on);

/** Copy the error estimate of each whole forcing cycle's D (fricreg_sim_get_dissipation) of
 *  the last run into err[ncycles]: absolute, in D's units, >= 0, +infinity where it could not
 *  be formed (fricreg_sim_set_error_estimate). The total D's is FRICREG_VALUE_DISSIPATION_ERROR.
 *  sim      in: the simulation; not modified.
 *  ncycles  in: FRICREG_VALUE_CYCLES of the last run.
 *  err      out: err[ncycles]; written only on success.
 *  Returns FRICREG_OK; FRICREG_ENULL if sim is NULL, or err is NULL with ncycles > 0;
 *  FRICREG_EINVAL when the last run made no estimate (the estimate off, no run, a failed run,
 *  a setter discarded it, or fricreg_sim_run_extrapolated); FRICREG_ESIZE if ncycles is not
 *  the run's cycles. Since 1.6 (FRICREG_1.6). */
FRICREG_API int fricreg_sim_get_dissipation_error(const fricreg_sim *sim, size_t ncycles,
                                                  double err[]);

/** Copy the kind of the error estimate of each whole forcing cycle's D
 *  (fricreg_sim_get_dissipation_error) of the last run into kind[ncycles]: enum
 *  fricreg_estimate_kind, FRICREG_EST_KIND_ASYMPTOTIC (1: D, D2, D4 showed the law's
 *  order, the estimate Richardson's with the observed order, expected 1 ... 3x the error),
 *  _BOUND (2: they did not, or the estimate is +infinity: a safe upper bound) or _ASSUMED (3:
 *  one companion, the order assumed); the decision of src/base/companion_estimate.c
 *  (fricreg_sim_set_error_estimate). The total D's is FRICREG_VALUE_DISS_ERROR_KIND.
 *  sim      in: the simulation; not modified.
 *  ncycles  in: FRICREG_VALUE_CYCLES of the last run.
 *  kind     out: kind[ncycles]; written only on success.
 *  Returns FRICREG_OK; FRICREG_ENULL if sim is NULL, or kind is NULL with ncycles > 0;
 *  FRICREG_EINVAL when the last run made no estimate (as fricreg_sim_get_dissipation_error);
 *  FRICREG_ESIZE if ncycles is not the run's cycles. Since 1.8 (FRICREG_1.8). */
FRICREG_API int fricreg_sim_get_dissipation_error_kind(const fricreg_sim *sim, size_t ncycles,
                                                       int kind[]);

/** Set the run's answer tolerance: fricreg_sim_warning_count raises
 *  FRICREG_WARN_ERROR_ESTIMATE where the error estimate of the last whole cycle's D (the total
 *  D's without a whole cycle) puts D's error above rtol |D|: its central value, half the
 *  estimate (the estimate bounds the error at about twice its size), above rtol |D|, whatever
 *  its kind (fricreg_sim_set_error_estimate; rtol the error a caller accepts in the answer,
 *  relative, dimensionless), and the estimate above 1e-12 of the band's work sum_i mun_i eps T
 *  over that time T (a D whose exact value is 0, a stuck contact's, is round-off and so is its
 *  estimate; docs/integrators.md, "Warnings"). Default 1e-2. Until 1.8 the whole estimate was
 *  compared, which rtol / 2 restores; until 1.7 the level was a fixed 10%. Kept across runs; it
 *  changes no result, only the warning, judged on the value in force when the warnings are
 *  judged (the run's end and fricreg_sim_warning_count).
 *  sim   in/out: the simulation.
 *  rtol  in: the tolerance, finite and > 0.
 *  Returns FRICREG_OK; FRICREG_ENULL if sim is NULL; FRICREG_EINVAL if rtol is not finite or
 *  not > 0 (nothing changed). Since 1.8 (FRICREG_1.8). */
FRICREG_API int fricreg_sim_set_answer_rtol(fricreg_sim *sim, double rtol);

/* ---- Extrapolation in eps (since ABI 1.2) ------------------------------------------------ */

/** Run the simulation at its eps and at eps/2, …, eps/2^(levels-1), and extrapolate the
 *  dissipation to eps -> 0 (Richardson), with an error estimate.
 *
 *  Law (4)'s regularization error in D has a regular expansion in eps: c eps^p + c' eps^(p+1)
 *  + …, with p = 2 where every switch is a stick (the oscillator a = 2, omega = 0.5; the
 *  chain) and p = 1 at a reversal without a stick or a breakaway set off by another contact
 *  (docs/benchmark.md). Level 0 is `sim` itself, run as fricreg_sim_run(sim, t_end) with
 *  every setting (its observer is called for this level only), so the other getters report
 *  the run at eps as before. Levels 1 … levels-1 are internal copies with every setting of
 *  sim carried over but eps_k = eps / 2^k; a fixed step is halved with eps (dt_k = dt / 2^k:
 *  the stick-zone bound dt * lambda, lambda ∝ 1/eps, stays as accepted at level 0, and the
 *  error stays a function of eps alone along dt/eps fixed); an adaptive run keeps dt (its
 *  first step) and its tolerances, which must then be well below the target error. The copies
 *  run to the time level 0 reached (an observer may stop it early).
 *
 *  Each cycle's D and the total D(t) are extrapolated on their own. The leading order p is
 *  the one the last three levels show, log2 of the ratio of successive differences rounded,
 *  when within 0.3 of an integer in 1 … 4: observed rather than declared, because it is set
 *  by the motion, not the system (the same oscillator is p = 2 when it sticks and p = 1 when
 *  it does not). Otherwise, and with levels = 2, the declared `order` is used (0 means 1: a
 *  first-order step keeps the estimate an upper bound also when the truth is p = 2, where a
 *  declared 2 on a true p = 1 would understate it), the value is flagged, and its estimate is
 *  widened to at least the last difference of the raw sequence. Columns after the first
 *  remove eps^(p+1), eps^(p+2), …. The estimate is the difference between the last two
 *  extrapolation levels (the table's last diagonal entry and the one left of it). A flag is a
 *  warning, not a failure: the numbers and their widened estimate are still returned; read
 *  FRICREG_EXTRAP_FLAGGED_CYCLES (the CLI prints it).
 *
 *  sim     in/out: the simulation; holds level 0's run and the extrapolation on success.
 *  t_end   in: end time > 0 (for whole cycles: cycles * FRICREG_VALUE_PERIOD).
 *  levels  in: 2 … 8 runs (level k at eps / 2^k); the work roughly doubles per level with a
 *          fixed step.
 *  order   in: the declared leading order, 0 … 4 (0: 1), used where none is observed.
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_EINVAL for levels or order out of range, or a
 *  call from the observer; FRICREG_ENONFINITE; and any code of fricreg_sim_run, for level 0
 *  or a copy (the message names the level, its eps and dt). On failure no extrapolation is
 *  held; sim holds level 0's run if level 0 succeeded, else what fricreg_sim_run leaves.
 *  The setters that discard results, and any run, discard it. Since ABI 1.2. */
FRICREG_API int fricreg_sim_run_extrapolated(fricreg_sim *sim, double t_end, int levels, int order);

/** fricreg_sim_run_extrapolated with the finer levels run over a window only: the last
 *  `window` whole forcing cycles, started from level 0's state (x, v) at the window's start.
 *
 *  For a motion that forgets its start, such as the limit cycle of a forced oscillator, a
 *  finer level started from level 0's state differs from one run from t = 0 by a transient
 *  that decays by the motion's contraction per cycle (the sticking oscillator a = 2,
 *  omega = 0.5: about 5x a cycle), so the window's last cycles are what the full levels
 *  would give, at window/C of their cost over C cycles (docs/benchmark.md). Level 0 runs the
 *  whole way, as in fricreg_sim_run_extrapolated.
 *
 *  Per cycle c of the window after its first, the estimate adds what is left of the
 *  transient: how far the extrapolated D moves when each finer level's difference to level 0
 *  is replaced by that of cycle c - 1 (the last change), a bound while the contraction is at
 *  least 2x a cycle (4x too large at 5x). The window's first cycle has no change to compare
 *  (its finer levels are still near level 0's motion): estimate +infinity, and so for
 *  FRICREG_EXTRAP_DISSIPATION, which is the dissipation over the window, extrapolated. The
 *  cycles before the window are not extrapolated: fricreg_sim_get_extrapolated_dissipation
 *  gives level 0's D there with the estimate +infinity. FRICREG_EXTRAP_RHS_EVALS counts
 *  every level's work. Where level 0 completes at most `window` cycles (or its observer
 *  stops it before the window ends), every level runs from t = 0 and this is
 *  fricreg_sim_run_extrapolated.
 *
 *  sim, t_end, levels, order: as fricreg_sim_run_extrapolated.
 *  window  in: >= 0 whole cycles; 0: no window (every level from t = 0).
 *  Returns FRICREG_OK; FRICREG_EINVAL for window < 0 (and as fricreg_sim_run_extrapolated);
 *  FRICREG_ENOMEM; and every code of fricreg_sim_run_extrapolated, which it is otherwise.
 *  Since ABI 1.4. */
FRICREG_API int fricreg_sim_run_extrapolated_window(fricreg_sim *sim, double t_end, int levels,
                                                    int order, int window);

/** Quantities of the last fricreg_sim_run_extrapolated, for fricreg_sim_get_extrapolation.
 *  Values are fixed forever. */
enum fricreg_extrap_value {
    FRICREG_EXTRAP_LEVELS = 0,          /**< levels run */
    FRICREG_EXTRAP_ORDER = 1,           /**< leading order used for the last whole cycle's D
                                        *   (for the total D if no whole cycle) */
    FRICREG_EXTRAP_OBSERVED_ORDER = 2,  /**< the order observed there, log2 of the last ratio
                                        *   of differences; NaN with 2 levels or converged */
    FRICREG_EXTRAP_FLAGGED_CYCLES = 3,  /**< whole cycles whose D showed no clean order */
    FRICREG_EXTRAP_DISSIPATION = 4,     /**< the total D(t) extrapolated */
    FRICREG_EXTRAP_DISSIPATION_ERR = 5, /**< its error estimate (absolute) */
    FRICREG_EXTRAP_EPS_FINEST = 6,      /**< eps / 2^(levels-1) of the finest level */
    FRICREG_EXTRAP_RHS_EVALS = 7        /**< right-hand-side evaluations of all levels */
};

/** Read one quantity of the last extrapolated run (enum fricreg_extrap_value).
 *  sim    in: the simulation; not modified.
 *  which  in: the quantity.
 *  value  out: its value; written only on success.
 *  Returns FRICREG_OK; FRICREG_ENULL if sim or value is NULL; FRICREG_EINVAL for an unknown
 *  quantity, or when sim holds no extrapolation (fricreg_sim_run_extrapolated was not the
 *  last run, failed, or a setter discarded it). Since ABI 1.2. */
FRICREG_API int fricreg_sim_get_extrapolation(const fricreg_sim *sim, int which, double *value);

/** Copy the extrapolated dissipation of each whole forcing cycle into D[ncycles] and its error
 *  estimate (absolute, >= 0) into err[ncycles]; ncycles must equal FRICREG_VALUE_CYCLES.
 *  sim      in: the simulation; not modified.
 *  ncycles  in: the number of whole cycles of the run.
 *  D, err   out: written only on success.
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_EINVAL when sim holds no extrapolation (as
 *  fricreg_sim_get_extrapolation); FRICREG_ESIZE. Since ABI 1.2. */
FRICREG_API int fricreg_sim_get_extrapolated_dissipation(const fricreg_sim *sim, size_t ncycles,
                                                         double D[], double err[]);

/** Judge the simulation's checks of plausibility now and return how many warnings they raise
 *  (enum fricreg_warning of fricreg.h; none changes a result). One check so far:
 *  - FRICREG_WARN_TOL_LOOSE: an adaptive run whose velocities are held to more than 0.01 eps,
 *    the level atol_v + rtol x 1 (velocities of order 1 in the paper's nondimensional
 *    systems; atol_v the caller's scalar or per-component velocity tolerance). Law (4) reads
 *    a contact velocity within its band |zdot| < eps: measured on the two blocks at eps = 1e-6
 *    under msbdf, a level of 1e-2 eps gave D on cycle 4 1.2e-4 off, atol = rtol = 1e-6 +8e-3
 *    (docs/integrators.md, "Warnings"). FRICREG_ATOL_FROM_EPS's tolerances (at most 1e-3 eps
 *    on velocities) never raise it.
 *  Judged on the settings in force (before or after a run); called from the observer during a
 *  run, it judges nothing and returns the list as it was.
 *  Returns the number of warnings; 0 if sim is NULL. Since 1.6 (FRICREG_1.6). */
FRICREG_API size_t fricreg_sim_warning_count(fricreg_sim *sim);

/** Read warning k, 0 <= k < fricreg_sim_warning_count(sim): its code (enum fricreg_warning)
 *  into *code and its message (English, one line, under 256 characters) into buf[len],
 *  NUL-terminated and truncated to fit (nothing written if buf is NULL or len is 0; for
 *  Fortran). The list is the last fricreg_sim_warning_count's. Returns FRICREG_OK;
 *  FRICREG_ENULL if sim or code is NULL; FRICREG_EINVAL if k is not below the count (nothing
 *  written). Since 1.6 (FRICREG_1.6). */
FRICREG_API int fricreg_sim_get_warning(const fricreg_sim *sim, size_t k, int *code, char *buf,
                                        size_t len);

/** Message of warning k of the last fricreg_sim_warning_count, as fricreg_sim_get_warning
 *  writes it; "" if sim is NULL or k is not below the count. Owned by sim, valid until its next
 *  warning_count call. Since 1.6 (FRICREG_1.6). */
FRICREG_API const char *fricreg_sim_warning_message(const fricreg_sim *sim, size_t k);

/** Route the simulation's warnings to fn (fricreg_warning_handler of fricreg.h), as SUNDIALS'
 *  CVodeSetErrHandlerFn: at the end of every fricreg_sim_run, _run_cycles, _run_extrapolated
 *  and _run_extrapolated_window, failed or not, the checks of fricreg_sim_warning_count are
 *  judged and fn is called once for each warning raised that it has not been given since the
 *  run began; a later fricreg_sim_warning_count calls it for new ones only. A caller that
 *  prints every message from fn sees what `fricreg-sim` prints. By default there is no handler
 *  and the library says nothing: the warnings are read back with fricreg_sim_warning_count.
 *
 *  fn          the handler, or NULL to remove it.
 *  user_data   passed back to fn unchanged; may be NULL.
 *
 *  The handler is the simulation's: runs on other simulations (the extrapolation's levels, the
 *  error estimate's companion) do not call it. Returns FRICREG_OK; FRICREG_ENULL if sim is
 *  NULL; FRICREG_EINVAL if called from the observer or the handler during a run (nothing
 *  changed). Since 1.7 (FRICREG_1.7). */
FRICREG_API int fricreg_sim_set_warning_handler(fricreg_sim *sim, fricreg_warning_handler fn,
                                                void *user_data);

/** Returns the status of the last failed call (FRICREG_OK if none or sim NULL). The getters, which take
 *  a const simulation, return their status without recording it. */
FRICREG_API int fricreg_sim_errcode(const fricreg_sim *sim);

/** Message of the last failed call: names the parameter, time or contact. "" if none;
 *  "NULL simulation" if sim is NULL. Owned by sim, valid until its next call. */
FRICREG_API const char *fricreg_sim_errmsg(const fricreg_sim *sim);

/** Copy the last error message into buf[len], NUL-terminated and truncated to fit (for
 *  Fortran). Returns the full message length, as snprintf does; 0 and nothing written if buf
 *  is NULL or len is 0. */
FRICREG_API size_t fricreg_sim_errmsg_copy(const fricreg_sim *sim, char *buf, size_t len);

/** \} */

#ifdef __cplusplus
}
#endif

#endif /* FRICREG_SIM_H */
