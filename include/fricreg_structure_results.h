/* SPDX-License-Identifier: GPL-3.0-or-later */
/**
 * \file
 * fricreg_structure_results.h — what a structure's runs give: the state, the contact forces, the
 * dissipation, the values and statistics of the run, and the error estimate against the Coulomb
 * problem with its companions.
 *
 * Part of fricreg_structure.h, which includes it (so does every header of the structure:
 * include either), split out by object since 1.9; the structure, its model and the
 * conventions are fricreg_structure.h's.
 */
#ifndef FRICREG_STRUCTURE_RESULTS_H
#define FRICREG_STRUCTURE_RESULTS_H

#include "fricreg_structure.h"

#ifdef __cplusplus
extern "C" {
#endif

/** \defgroup structure_results Structure: results and error estimate (fricreg_structure_results.h)
 *  \{ */

/** Copy the state at the current time: displacements u[ndof], velocities v[ndof],
 *  accelerations a[ndof]; any of them may be NULL (not all three).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE if ndof is not the structure's. */
FRICREG_API int fricreg_structure_get_state(const fricreg_structure *s, size_t ndof, double u[],
                                            double v[], double a[]);

/** Copy the friction forces f[m] (force units) of the current state (after the last step;
 *  zero before the first). Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE. */
FRICREG_API int fricreg_structure_get_forces(const fricreg_structure *s, size_t m, double f[]);

/** Copy the energy dissipated by each contact since set_initial,
 *  D_i = -sum over steps of (z_i(t+dt) - z_i(t)) (f_i(t) + f_i(t+dt))/2 (trapezoidal; energy
 *  units), into D[m]. Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE. */
FRICREG_API int fricreg_structure_get_dissipation(const fricreg_structure *s, size_t m, double D[]);

/** Quantities of fricreg_structure_get_value. Values are fixed forever. The energies are
 *  summed over steps with the trapezoidal rule on the displacement increments du:
 *  input += du.(p~(t) + p~(t+dt))/2, viscous += du.C(v(t) + v(t+dt))/2, friction as in
 *  get_dissipation; kinetic = v.M v/2 and strain = u.K u/2 now, initial = both at t = 0;
 *  residual = initial + input - kinetic - strain - viscous - friction - jenkins (strain
 *  holding the Jenkins elements' springs' energy too). Average-acceleration
 *  Newmark makes the residual vanish to Newton's tolerance (its discrete balance is exact);
 *  HHT-alpha's numerical damping shows in it. */
enum fricreg_structure_value {
    FRICREG_SVALUE_TIME = 0,             /**< time reached */
    FRICREG_SVALUE_INPUT = 1,            /**< work of p - M r a_g since t = 0 */
    FRICREG_SVALUE_KINETIC = 2,          /**< kinetic energy now */
    FRICREG_SVALUE_STRAIN = 3,           /**< strain energy now */
    FRICREG_SVALUE_VISCOUS = 4,          /**< energy dissipated by C since t = 0 */
    FRICREG_SVALUE_FRICTION = 5,         /**< energy dissipated by all contacts since t = 0 */
    FRICREG_SVALUE_RESIDUAL = 6,         /**< the balance's residual */
    FRICREG_SVALUE_INITIAL = 7,          /**< kinetic + strain energy at t = 0 */
    FRICREG_SVALUE_GROUND_PGV = 8,       /**< the ground record's peak velocity max |integral of a_g
                                       dt| (trapezoidal from the record's start; 0 without a
                                       record): the scale of fricreg-sim's default eps and of
                                       the eps warnings (since 1.6) */
    FRICREG_SVALUE_JENKINS = 9,          /**< energy dissipated by all Jenkins or Iwan elements
                                       since t = 0 (fricreg_structure_get_jenkins_state,
                                       fricreg_structure_get_iwan_state; since 1.6) */
    FRICREG_SVALUE_COMPANION_CPU = 10,   /**< CPU seconds (C's clock(): the process's, other
                                          threads' work in the same intervals included) spent
                                          stepping the error estimate's companions since they
                                          were made (fricreg_structure_set_error_estimate: the
                                          first stepping call after set_initial), the second
                                          companion's inside the first's; 0 until an
                                          estimate is made, the last one's after it ends
                                          until the next is made. The estimate's cost beside
                                          the run's own (since 1.8) */
    FRICREG_SVALUE_COMPANIONS_USED = 11, /**< the companions that gave the error estimate
                                          now, as enum fricreg_estimate_companions: 0
                                          (finer) or 1 (coarser); with
                                          FRICREG_COMPANIONS_AUTO, 1 while the screen is
                                          quiet and 0 once the finer confirmed it (reading
                                          this, or _COMPANION_CPU or the _SCREEN_ values,
                                          settles the screen as the estimate's getters do:
                                          fricreg_structure_set_error_companions); -1
                                          without an estimate (off, not yet made, ended or
                                          failed) (since 1.9) */
    FRICREG_SVALUE_SCREEN_PEAK_ERR = 12, /**< with FRICREG_COMPANIONS_AUTO, once the finer
                                          companions confirmed: what the screen had said, its
                                          estimate of the largest peak's error (the largest
                                          over the dofs; length units) at the call's end where
                                          it doubted, +infinity where it failed; NaN where no
                                          confirmation ran (since 1.9) */
    FRICREG_SVALUE_SCREEN_DISS_ERR = 13  /**< likewise, the screen's estimate of the
                                          summed dissipations' error (contacts' and joint
                                          elements'; energy units) (since 1.9) */
};

/** Read one quantity (enum fricreg_structure_value) into *value.
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_EINVAL for an unknown quantity. */
FRICREG_API int fricreg_structure_get_value(const fricreg_structure *s, int which, double *value);

/* ---- Error estimate (since 1.6) ---------------------------------------------------------- */

/** Whether and how the structure estimates the error of its peak displacements
 *  (fricreg_structure_get_peak_displacement) and of each contact's dissipation
 *  (fricreg_structure_get_dissipation) against the Coulomb problem, eps -> 0, where a run's
 *  results carry both the regularization error of the law and the discretization (or
 *  tolerance) error. Off by default (fricreg-sim structure turns it on). Since 1.6
 *  (FRICREG_1.6); two companions and on = 2 since 1.7.
 *
 *  The estimator (docs/structural.md, "Error estimate"): companion runs along the path
 *  (eps, dt) -> (eps / 2, dt / 2) -> (eps / 4, dt / 4) give q2 and q4 beside the run's q (the
 *  finer companions described here; since 1.9 by default screened by coarser ones and run only
 *  where those doubt: fricreg_structure_set_error_companions). Law
 *  (4)'s error is c eps^p, p = 1 or 2, and along dt / eps fixed a fixed step's error follows
 *  eps, so in the asymptotic range d1 = q - q2 and d2 = q2 - q4 have one sign and
 *  d1 / d2 = 2^p. With on = FRICREG_ESTIMATE_TWO_COMPANIONS (1): where the observed order
 *  p = log2(d1 / d2) is at least 0.5, err = 2 |d1| 2^p / (2^p - 1) (Richardson's correction
 *  with the observed order, times 2; about 2 |d1| where p is above the law's orders); below
 *  (a stall: the run and the first companion agree on a wrong value; or differences that
 *  grow or change sign) err = 6.83 (|d1| + |d2|), but 2 (|d1| + 2 |d2|) where they have
 *  opposite signs and |d2| <= |d1| / 8 (law (4)'s two orders give the error as
 *  (2/3) d1 + (8/3) d2; since 1.8); d2 below 1e-9 of q gives 2 |d1| + |d2|, d1
 *  and d2 both below it 4 (|d1| + |d2|) (the factor 2 and p = 1's tail; their bare sum before
 *  1.8). With on = FRICREG_ESTIMATE_ONE_COMPANION (2), 1.6's estimator: err = 3 |d1|
 *  (fricreg_sim_set_error_estimate's, with its calibration), which cannot see a stall
 *  (bench/frame_estimate.c: a frame 5x under, no warning). Each estimate has a kind
 *  (fricreg_structure_get_error_kind, enum fricreg_estimate_kind): ASYMPTOTIC where the order
 *  was seen, BOUND below the range (until 1.7 a dissipation's raised
 *  FRICREG_WARN_NOT_ASYMPTOTIC, no longer raised), ASSUMED with one companion.
 *  The companion is a second structure, owned by s, stepped alongside it; the second
 *  companion is the first's own, made and stepped by it the same way:
 *  - it is made at the first stepping call (fricreg_structure_step, _run or _run_ode) after
 *    fricreg_structure_set_initial (or creation) with the estimate on, as a copy of everything
 *    set then (model, Rayleigh damping, influence, load and ground records, law with eps / 2,
 *    bounds, scheme, Newton's settings, the bound on adaptive steps, the elements (Jenkins,
 *    Iwan, 2-D, lift-off), the initial state); turned on (or changed between 1 and 2) later
 *    in a run, the estimate starts at the next set_initial;
 *  - at the end of every stepping call on s (successful, failed after some steps, or stopped by
 *    the observer) it is stepped from its time to s's: fricreg_structure_step(s, dt) and
 *    fricreg_structure_run(s, dt, t_end) by fricreg_structure_run(companion, dt / 2, t) (two
 *    steps per step of s, the last shortened as run's), fricreg_structure_run_ode with fixed
 *    steps by the same stepper at dt / 2, adaptive by the same stepper with dt as its first step
 *    and rtol / 16, atol / 16 (the second companion: dt / 4, or the tolerances / 256);
 *  - the setters a run may call between steps are passed on to it (before it steps next, so a
 *    refusal there fails the estimate at the next stepping call): set_bounds, set_law (eps / 2
 *    of the new eps), set_ground_accel and set_load (a caller who feeds the record step by step
 *    feeds the companion too: it reads its records at its own step ends, in between), set_newton,
 *    set_max_steps (each call of the companion's bounded as s's) and set_ode_abs_tolerances
 *    (applied at / 16 there, as run_ode's rule from eps). Every other setter after
 *    the companion was made (the model matrices, Rayleigh, influence, scheme, elements) ends the
 *    estimate until the next set_initial: the getters then return FRICREG_EINVAL.
 *  The peaks take in every step, fixed or adaptive, with the turning points inside it
 *  (fricreg_structure_get_peak_displacement), so they converge at the scheme's order or the
 *  adaptive tolerance and not with the phase of the samples; before 1.8 an adaptive run was
 *  sampled at its run_ode calls' ends only, which its companions shared: the estimate missed
 *  that sampling error (the frame of bench/frame_estimate.c under rkf45 at rtol 1e-6 called
 *  every 0.02 s: storey 1's peak 1.25e-5 off, now 7.6e-8, whatever the interval).
 *  Where a companion fails (e.g. FRICREG_ESTEP or FRICREG_EWORK at its finer setting, or no
 *  memory) s's run still succeeds, the estimates become +infinity until the next set_initial, and
 *  fricreg_structure_warning_count raises FRICREG_WARN_ERROR_ESTIMATE with the companion's
 *  message; it raises it too, whatever the kinds, where half the largest peak's estimate (its
 *  central value: the estimate bounds the error at about twice its size) exceeds the answer
 *  tolerance times the largest peak (max_i err_i / 2 > rtol max_i peak_i), or half the
 *  dissipations' summed estimates (contacts' and joint elements' together) the tolerance times
 *  their summed magnitudes (fricreg_structure_set_answer_rtol: rtol = 1e-2 by default; until
 *  1.8 the whole estimates, until 1.7 against 10%).
 *  Cost: each companion's run, about 2x and 4x s's for fixed steps (twice and four times the
 *  steps), 1.4x ... 3x each for adaptive ones (fricreg_sim_set_error_estimate); one or two more
 *  structures in memory, allocated at the run's first step (a failed allocation is a failed
 *  estimate, not a failed step). So with two companions a run costs about 7x (the frame of
 *  bench/frame_estimate.c, Newmark: 6.5x), with one about 3x.
 *
 *  s   in/out: the structure.
 *  on  in: enum fricreg_error_estimate: 1 (two companions) or 2 (one) to estimate, 0 not to
 *      (default; 0 also discards the estimate made).
 *  Returns FRICREG_OK; FRICREG_ENULL if s is NULL; FRICREG_EINVAL if on is not 0, 1 or 2, or
 *  if called from the observer during a run. */
FRICREG_API int fricreg_structure_set_error_estimate(fricreg_structure *s, int on);

/** Where the error estimate's companions sit on the path (fricreg_structure_set_error_companions). */
enum fricreg_estimate_companions {
    /** eps / 2 at dt / 2 and eps / 4 at dt / 4 (adaptive: the tolerances / 16, / 256):
     *  calibrated (docs/structural.md, "Error estimate"); about 7x a run's cost (6.5x on the
     *  frame of bench/frame_estimate.c, 7.1x on a 10^5-dof chain); the default until 1.8 */
    FRICREG_COMPANIONS_FINER = 0,
    /** 2 eps at 2 dt and 4 eps at 4 dt (adaptive: the tolerances x 2, x 4): the run's error
     *  from the coarser levels, about 0.7x a run's cost; it bounds the error less often on
     *  problems it was not derived on and warns on many runs within the tolerance
     *  (docs/structural.md, "Error estimate"), and fails near an explicit scheme's step bound
     *  (the companions' steps exceed it) */
    FRICREG_COMPANIONS_COARSER = 1,
    /** screened, the default since 1.9: the coarser companions run; where their estimate would
     *  warn (FRICREG_WARN_ERROR_ESTIMATE) or could not be formed, the finer companions run from
     *  the start and theirs is the estimate (since 1.9) */
    FRICREG_COMPANIONS_AUTO = 2
};

/** Choose where the error estimate's companions (fricreg_structure_set_error_estimate) sit:
 *  finer than the run (FRICREG_COMPANIONS_FINER), coarser (FRICREG_COMPANIONS_COARSER), or
 *  coarser first and finer where they doubt (FRICREG_COMPANIONS_AUTO, the default since 1.9).
 *  Since 1.8 (FRICREG_1.8); FRICREG_COMPANIONS_AUTO and the default since 1.9 (1.8's default
 *  was FRICREG_COMPANIONS_FINER).
 *
 *  Coarser: the companions run at (2 eps, 2 dt) and (4 eps, 4 dt), adaptive ones at the same
 *  output interval with rtol, atol x 2 and x 4 (the rule from eps, or the set tolerances,
 *  likewise: the path's own factor, so that the tolerances' share of the error follows the
 *  law's lower order), every other rule of the companions as set_error_estimate says. From the run's q
 *  and the companions' q2, q4, with d1 = q - q2 and d2 = q2 - q4: in the asymptotic range
 *  d2 / d1 = 2^p (law (4)'s error c eps^p along dt / eps fixed), so the run's own error is
 *  Richardson's from the coarser levels, |d1| / (2^p - 1); where r = d2 / d1 lies in
 *  [2^0.5, 2^2] the estimate is 2 |d1| / (r - 1) (the factor 2 the finer estimator's), kind
 *  FRICREG_EST_KIND_ASYMPTOTIC: on law (4)'s two orders, e = a eps + b eps^2 with a, b of one
 *  sign, Richardson's is at worst 3/4 of the error (at r = 3), so 2 bounds it; above 2^2 the
 *  two of opposite signs can put Richardson's any factor under (7x at r = 8). Otherwise (a
 *  stall: d1 small against d2; an order above the law's, which a stall and those opposite
 *  signs imitate; differences that change sign) 4.83 (|d1| + |d2|), kind
 *  FRICREG_EST_KIND_BOUND (both differences below 1e-9 of q: 4 (|d1| + |d2|)); with one
 *  companion (FRICREG_ESTIMATE_ONE_COMPANION) 3 |d1|, ASSUMED. The run's results are
 *  unchanged: the estimate only costs less, the coarser levels being further from the
 *  asymptotic range (more BOUND kinds). Fixed steps need each stepping call (step, run,
 *  run_ode without tolerances) to span 4 dt, the coarsest companion's step (2 dt with one
 *  companion): a shorter call fails the estimate (+infinity, FRICREG_WARN_ERROR_ESTIMATE
 *  saying why), since a companion stepping one call of dt at 2 dt would take s's own step.
 *
 *  Auto (screen, then confirm): the coarser companions run as above (the screen), and a
 *  finer pair is made beside them at the run's start, a copy as set_error_estimate says, but
 *  not stepped. Where the estimate is read (the *_error getters, get_error_kind,
 *  get_value's estimate values, fricreg_structure_warning_count) and the screen's estimate
 *  would raise FRICREG_WARN_ERROR_ESTIMATE there (half the largest peak's estimate above the
 *  answer tolerance times the largest peak, or half the summed dissipations' likewise: the
 *  warning's own test), the finer companions are stepped from the start to s's time, as s's
 *  calls stepped s, and from then on they are the estimate (every getter and the warning,
 *  exactly the finer estimator's) and the screen is freed; where the screen fails (a fixed-step
 *  call shorter than 4 dt, a companion's failure) they are stepped at once. So a run of many
 *  calls is judged where it is read, not at its first calls, whose small quantities a bound
 *  doubts; a read between calls settles it there. The getters are logically const: the read
 *  that settles may take the finer companions' time, and the structure's results do not
 *  change. Where the run was one stepping call, the finer estimates are bit for bit
 *  FRICREG_COMPANIONS_FINER's; over many calls they follow the calls as finer companions do
 *  except where consecutive calls share dt, the integrator and its tolerances, which the finer
 *  pair takes as one call (its steps the same, its time reached to rounding; an adaptive one
 *  chooses its own steps). A setter passed on to the companions (set_bounds, set_law, the
 *  records, ...) first steps the finer pair to the time of the change, so a run that changes
 *  such a setting between its steps pays the finer companions' cost as well as the screen's.
 *  What the screen said and which companions gave the estimate: fricreg_structure_get_value's
 *  FRICREG_SVALUE_COMPANIONS_USED, FRICREG_SVALUE_SCREEN_PEAK_ERR,
 *  FRICREG_SVALUE_SCREEN_DISS_ERR. Cost: the screen's, about 0.7x a run, where it is quiet;
 *  where it doubts, that plus the finer companions' (docs/structural.md, "Error estimate");
 *  memory: one more structure beside the screen's, not set up until it steps.
 *
 *  A change ends the estimate made, which starts anew at the next set_initial, as a change
 *  of on (set_error_estimate).
 *
 *  s      in/out: the structure.
 *  which  in: enum fricreg_estimate_companions, 0 (finer), 1 (coarser) or 2 (auto).
 *  Returns FRICREG_OK; FRICREG_ENULL if s is NULL; FRICREG_EINVAL, s unchanged, if which is
 *  not 0, 1 or 2, or if called from the observer during a run. */
FRICREG_API int fricreg_structure_set_error_companions(fricreg_structure *s, int which);

/** Copy the peak displacements since fricreg_structure_set_initial (or creation),
 *  peak[i] = max |u_i| over: the initial state; every fixed step (fricreg_structure_step, _run,
 *  _run_ode with fixed steps), its end and the turning points of u_i inside it, on the cubic
 *  Hermite interpolant of the step's ends (u and u' at both; for Newmark's average
 *  acceleration the scheme's own quadratic), so the peak converges at the scheme's order
 *  (since 1.7; 1.6 took the step ends only); every adaptive step of fricreg_structure_run_ode
 *  likewise, its end and its turning points on that step's Hermite interpolant (since 1.8;
 *  before, only each run_ode call's end); into peak[ndof] (length units).
 *  Tracked whether or not the error estimate is on. Since 1.6 (FRICREG_1.6).
 *  Returns FRICREG_OK; FRICREG_ENULL if s or peak is NULL; FRICREG_ESIZE if ndof is not the
 *  structure's. */
FRICREG_API int fricreg_structure_get_peak_displacement(const fricreg_structure *s, size_t ndof,
                                                        double peak[]);

/** Copy the error estimate of each peak displacement (fricreg_structure_get_peak_displacement)
 *  into err[ndof] (length units, >= 0; +infinity where a companion failed),
 *  fricreg_structure_set_error_estimate's estimator (the one chosen there), at the current
 *  time. Since 1.6 (FRICREG_1.6).
 *  s     in: the structure; not modified.
 *  ndof  in: the structure's degrees of freedom.
 *  err   out: err[ndof]; written only on success.
 *  Returns FRICREG_OK; FRICREG_ENULL if s or err is NULL; FRICREG_EINVAL when there is no
 *  estimate (the estimate off, no step taken since set_initial with it on, a setter ended it
 *  (fricreg_structure_set_error_estimate), or called from the observer during a run, when the
 *  companion has not caught up); FRICREG_ESIZE if ndof is not the structure's. */
FRICREG_API int fricreg_structure_get_peak_displacement_error(const fricreg_structure *s,
                                                              size_t ndof, double err[]);

/** Copy the error estimate of each contact's dissipation (fricreg_structure_get_dissipation)
 *  into err[m] (energy units, >= 0; +infinity where a companion failed), as
 *  fricreg_structure_get_peak_displacement_error. Since 1.6
 *  (FRICREG_1.6).
 *  Returns FRICREG_OK; FRICREG_ENULL if s or err is NULL; FRICREG_EINVAL when there is no
 *  estimate (as fricreg_structure_get_peak_displacement_error); FRICREG_ESIZE if m is not the
 *  structure's. */
FRICREG_API int fricreg_structure_get_dissipation_error(const fricreg_structure *s, size_t m,
                                                        double err[]);

/** Copy the error estimate of each joint element's dissipation (the D[me] of
 *  fricreg_structure_get_jenkins_state: Jenkins, Iwan, 2-D and lift-off elements alike) into
 *  err[me] (energy units, >= 0; +infinity where a companion failed), as
 *  fricreg_structure_get_dissipation_error: from the companions' runs along the same path
 *  (dt / 2, dt / 4 and eps with it; an element has no eps, so its error is the scheme's in dt),
 *  the estimator of fricreg_structure_set_error_estimate. An element whose three dissipations
 *  show no order along the path gets the safe bound (kind BOUND, fricreg_structure_get_error_kind);
 *  their sum, with the contacts', enters the warning of an estimate above the answer tolerance
 *  (FRICREG_WARN_ERROR_ESTIMATE). Since 1.7 (FRICREG_1.7).
 *  s     in: the structure; not modified.
 *  me    in: the number of elements set (0: nothing to write).
 *  err   out: err[me]; written only on success.
 *  Returns FRICREG_OK; FRICREG_ENULL if s or err is NULL; FRICREG_EINVAL when there is no
 *  estimate (as fricreg_structure_get_peak_displacement_error); FRICREG_ESIZE if me is not the
 *  number of elements set. */
FRICREG_API int fricreg_structure_get_jenkins_dissipation_error(const fricreg_structure *s,
                                                                size_t me, double err[]);

/** The quantities whose error fricreg_structure_set_error_estimate estimates, for
 *  fricreg_structure_get_error_kind. Values are fixed forever. Since 1.8 (FRICREG_1.8). */
enum fricreg_estimated_quantity {
    /** the peak displacements, n = ndof (fricreg_structure_get_peak_displacement_error) */
    FRICREG_EST_PEAK_DISPLACEMENT = 1,
    /** the contacts' dissipations, n = m (fricreg_structure_get_dissipation_error) */
    FRICREG_EST_DISSIPATION = 2,
    /** the joint elements' dissipations, n = the number of elements set
     *  (fricreg_structure_get_jenkins_dissipation_error) */
    FRICREG_EST_ELEMENT_DISSIPATION = 3
};

/** Copy the kind of each error estimate of `quantity` into kind[n]: enum
 *  fricreg_estimate_kind, FRICREG_EST_KIND_ASYMPTOTIC (1: q, q2, q4 showed the law's
 *  order, the estimate Richardson's with the observed order, expected 1 ... 3x the error),
 *  _BOUND (2: they did not, or a companion failed and the estimate is +infinity: a safe upper
 *  bound) or _ASSUMED (3: one companion, the order assumed), the decision of
 *  src/base/companion_estimate.c (fricreg_structure_set_error_estimate), at the current time.
 *  s         in: the structure; not modified.
 *  quantity  in: enum fricreg_estimated_quantity: FRICREG_EST_PEAK_DISPLACEMENT (n =
 *            ndof), FRICREG_EST_DISSIPATION (n = m contacts) or
 *            FRICREG_EST_ELEMENT_DISSIPATION (n = the joint elements set).
 *  n         in: the length of kind, as above.
 *  kind      out: kind[n], parallel to the *_error getter's err[n]; written only on success.
 *  Returns FRICREG_OK; FRICREG_ENULL if s or kind is NULL; FRICREG_EINVAL for an unknown
 *  quantity, or when there is no estimate (as fricreg_structure_get_peak_displacement_error);
 *  FRICREG_ESIZE if n is not the quantity's length. Since 1.8 (FRICREG_1.8). */
FRICREG_API int fricreg_structure_get_error_kind(const fricreg_structure *s, int quantity, size_t n,
                                                 int kind[]);

/** Set the run's answer tolerance: fricreg_structure_warning_count raises
 *  FRICREG_WARN_ERROR_ESTIMATE where the estimates' central values, half the estimates (which
 *  bound the errors at about twice their size), exceed it: max_i peak_err_i / 2 >
 *  rtol max_i |peak_i| or sum_j D_err_j / 2 > rtol sum_j |D_j| (contacts and joint elements
 *  together), whatever the estimates' kinds (fricreg_structure_set_error_estimate; rtol the
 *  relative error a caller accepts in the answer, dimensionless), and the estimate above
 *  1e-12 of a scale the run knows (a structure at rest: eps t for the peaks, sum_j mun_j eps t
 *  for the dissipations). Default 1e-2. Until 1.8 the whole estimates were compared, which
 *  rtol / 2 restores; until 1.7 the level was a fixed 10%. Kept across runs and set_initial;
 *  not passed to the companions (they raise no warning); it changes no result, only the
 *  warning, judged on the value in force when the warnings are judged
 *  (fricreg_structure_warning_count).
 *  s     in/out: the structure.
 *  rtol  in: the tolerance, finite and > 0.
 *  Returns FRICREG_OK; FRICREG_ENULL if s is NULL; FRICREG_EINVAL if rtol is not finite or
 *  not > 0 (nothing changed). Since 1.8 (FRICREG_1.8). */
FRICREG_API int fricreg_structure_set_answer_rtol(fricreg_structure *s, double rtol);

/** Counters since creation or set_initial, for fricreg_structure_get_stat. Fixed forever. */
enum fricreg_structure_stat {
    FRICREG_SSTAT_STEPS = 0,             /**< steps taken */
    FRICREG_SSTAT_NEWTON_ITERATIONS = 1, /**< Newton iterations (linear solves), all steps */
    FRICREG_SSTAT_NEWTON_MAX = 2,        /**< most Newton iterations in one step */
    FRICREG_SSTAT_NEWTON_FAILURES = 3,   /**< steps whose Newton did not converge */
    FRICREG_SSTAT_LINE_SEARCH_CUTS = 4   /**< halvings of Newton directions, all steps */
};

/** Read one counter (enum fricreg_structure_stat) into *value.
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_EINVAL for an unknown counter. */
FRICREG_API int fricreg_structure_get_stat(const fricreg_structure *s, int which, int64_t *value);

/** \} */

#ifdef __cplusplus
}
#endif

#endif /* FRICREG_STRUCTURE_RESULTS_H */
