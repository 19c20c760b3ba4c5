/* SPDX-License-Identifier: GPL-3.0-or-later */
/**
 * \file
 * fricreg_structure_run.h — a structure stepped in time: one step, a run by Newmark, HHT-alpha or
 * central difference, a run by GSL's steppers with their tolerances, the observer and the bound on
 * the steps, and checkpoints that continue a run in another process.
 *
 * Part of fricreg_structure.h, which includes it (so does every header of the structure:
 * include either), split out by object since 1.9; the structure, its model and the
 * conventions are fricreg_structure.h's.
 */
#ifndef FRICREG_STRUCTURE_RUN_H
#define FRICREG_STRUCTURE_RUN_H

#include "fricreg_structure.h"

#ifdef __cplusplus
extern "C" {
#endif

/** \defgroup structure_run Structure: stepping and runs (fricreg_structure_run.h)
 *  \{ */

/** Advance one step of dt > 0 (time units) with the selected scheme (Newmark and HHT-alpha
 *  below; central difference at fricreg_structure_set_central_difference).
 *
 *  Unknown: the acceleration a at t + dt, with u = u_pred + beta dt^2 a and
 *  v = v_pred + gamma dt a. Residual (HHT-alpha; Newmark: alpha = 0):
 *  R(a) = M a + (1 + alpha) (C v + K u - p~ - J^T f) - alpha (the same at t),
 *  p~ = p - M r a_g, f = f(J v, a_free(u, v)) from the friction law. For given forces f, R = 0
 *  is linear: K_eff a = b + (1 + alpha) J^T f, K_eff = M + (1 + alpha)(gamma dt C +
 *  beta dt^2 K). So Newton runs on the m forces: the contact velocities and free accelerations
 *  at the step's end are affine in f, zdot = z0 + c W_eff f and a_free = a0 - (W - W_eff) f
 *  (W_eff = J K_eff^-1 J^T, c = (1 + alpha) gamma dt), and G(f) = f - F(zdot, a_free) = 0 is
 *  solved on the exact tangent of the law F (fricreg_ctx_tangent): dG/df = I - c F_z W_eff +
 *  F_a (W - W_eff). Its iterates are those of Newton on a mapped through a(f), and R =
 *  (1 + alpha) J^T G there, which the stopping rule reads (fricreg_structure_set_newton).
 *  The m x m Newton matrix is never formed: the law's tangent is taken row by row, a slope
 *  s_i in zdot_i (sliding contacts, contacts held on a bound) or the consistent law's
 *  equation of a free contact, [W df]_i + k_i dzdot_i + dafree_i = 0 (docs/coupled.md), so
 *  that the rows to solve are (W_eff + diag(1/(c |s_i|))) df = ... on the near-stick
 *  contacts and their band's, df_i = -G_i on the others: a sparse Cholesky factor (CHOLMOD)
 *  of that block of W_eff plus a diagonal, refactored only when the block or the diagonal
 *  changes, with W_eff's entries below 2^-53 sqrt(W_eff,ii W_eff,jj) left out (far contacts
 *  barely interact over a step). A falling Stribeck branch (s_i > 0), where that matrix is
 *  not positive definite, goes dense: GSL's QR with column pivoting on the near-stick rows. First guess: the forces at t or,
 *  if their residual is above the tolerance and that one's smaller, the same with the
 *  contacts whose force is below the bound (law (4): in its band, sticking) keeping their
 *  velocities over the step. Each Newton direction is first cut where it would carry a
 *  slipping contact across the whole band (to zdot_i = 0, once per contact and step), then
 *  halved until the residual's 2-norm decreases (Armijo, 1e-4), at most 30 halvings; should
 *  that stall, Newton starts again from the forces at t without the cuts. A step whose Newton
 *  does not converge within max_iter iterations in all (or whose line search or Newton matrix
 *  fails) is still taken, from its last iterate, and counted in
 *  FRICREG_SSTAT_NEWTON_FAILURES. The energy balance is updated (fricreg_structure_get_value).
 *
 *  Cost: the first step after a model setter factors M (CHOLMOD) and forms W and the
 *  equilibrium acceleration at t; the first step with a new dt factors K_eff (nested
 *  dissection from 4096 degrees of freedom, minimum degree below) and forms Y = L^-1 P J^T
 *  column by column on each contact's reach and W_eff = Y^T Y (Y kept where it has fewer
 *  entries than the factor, else its products are triangular solves). A step within 1e-9
 *  of the factored dt (a run's steps, whose lengths carry the rounding of t) is taken with
 *  that dt. Then each step costs two forward and two backward solves with K_eff's factor at
 *  most and products with M, C and K, O(nnz), and in the contacts products with W_eff per
 *  residual and a Newton factor where the near-stick set changed: a frictionless step's cost
 *  plus the contacts' (docs/benchmark.md, scaling).
 *  Steps other than these first ones make no heap allocation (fricreg_structure_create).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_EINVAL if dt <= 0, t + dt rounds to t, dt
 *  is so large that K_eff's entries overflow, J was never set, or W = J M^-1 J^T has an entry beyond the double range or a W_ii below
 *  DBL_MIN ~ 2.2e-308 (J and M of scales too far apart); FRICREG_ENONFINITE if dt is not
 *  finite, or an element's sliders' force (or, where Newton needs it, stiffness) sums to
 *  beyond the double range (fricreg_structure_set_iwan; the message names the element, as
 *  fricreg_iwan_trial's); FRICREG_ENOTSYM or
 *  FRICREG_ENOTPSD if the context refuses W (not expected: W is formed symmetric from a
 *  positive definite M and non-zero rows of J); FRICREG_ENOTPSD if K_eff is not positive
 *  definite (K or C indefinite, an unstable structure, at too large a dt: the message says
 *  so); FRICREG_ESINGULAR (redundant contacts
 *  sticking together: their forces are not unique); FRICREG_ESTEP (central
 *  difference beyond its stability bounds); FRICREG_EDIVERGED if the residual or the state
 *  becomes non-finite or beyond 1e100; FRICREG_ENOMEM (the factors, the first steps above).
 *  On failure nothing a getter shows changes: u, v, a, f, the energies and the counters are
 *  those before the call (a first step after set_initial or a setter computes the
 *  acceleration at t before it fails: that is undone). */
FRICREG_API int fricreg_structure_step(fricreg_structure *s, double dt);

/** Step from the current time to t_end with steps of dt, the last one shortened to land on
 *  t_end (step k ends at t_start + k dt exactly, no accumulated rounding). A call with the
 *  same dt that starts where the last run ended, on one of its step times t_0 + K dt (no
 *  step, run_ode or set_initial between), continues its grid: its steps end at
 *  t_0 + (K + k) dt, so that a run split into two calls (or continued after
 *  fricreg_structure_restore) takes the steps of one call, bit for bit (since 1.7; before,
 *  at t_start + k dt of each call). The observer
 *  (fricreg_structure_set_observer) sees every step and may stop the run.
 *  Returns FRICREG_OK (also when the observer stopped it) or the codes of
 *  fricreg_structure_step, and FRICREG_EINVAL if t_end is not after the current time, needs
 *  more than 2^31 steps, or the call comes from the observer. On failure the state is that of
 *  the last successful step. */
FRICREG_API int fricreg_structure_run(fricreg_structure *s, double dt, double t_end);

/** Called by fricreg_structure_run after every step, and by fricreg_structure_run_ode after
 *  every GSL step, with the state at time t: displacements u[ndof], velocities v[ndof]
 *  (length and time units of the model) and the friction forces f[m] at (t, u, v) (force
 *  units), valid during the call only. Return 0 to go on, nonzero to stop the run there: the
 *  call then returns FRICREG_OK at time t. It may call the structure's getters; any other call
 *  on it from here returns FRICREG_EINVAL and changes nothing; it must not free it. Since 1.6
 *  (FRICREG_1.6). */
typedef int (*fricreg_structure_observer)(void *user, double t, size_t ndof, const double u[],
                                          const double v[], size_t m, const double f[]);

/** Install an observer of the long runs (NULL removes it); user is passed back unchanged.
 *  Returns FRICREG_OK; FRICREG_ENULL if s is NULL; FRICREG_EINVAL if called from the observer
 *  during a run. Since 1.6 (FRICREG_1.6). */
FRICREG_API int fricreg_structure_set_observer(fricreg_structure *s, fricreg_structure_observer fn,
                                               void *user);

/** Bound the adaptive steps accepted by one fricreg_structure_run_ode call at max_steps >= 1,
 *  or remove the bound with 0; by default 10^4 for the laws that jump ((1), (2), Karnopp) and
 *  10^6 for the others, as fricreg_sim_set_max_steps. A call that needs more returns
 *  FRICREG_EWORK with the state of its last step: an adaptive stepper meets the bound with a
 *  law that jumps ((1), (2), Karnopp), which it chases across zdot = 0 in ever smaller steps
 *  (the message says so). Fixed steps are bounded before the run starts (2^31).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_EINVAL if max_steps < 0 or called from the
 *  observer during a run. Since 1.6 (FRICREG_1.6). */
FRICREG_API int fricreg_structure_set_max_steps(fricreg_structure *s, int64_t max_steps);

/** Integrate from the current time to t_end with one of GSL's steppers (enum
 *  fricreg_integrator of fricreg_types.h), as the reference systems' drivers do: the
 *  first-order system u' = v, M v' = p~ - C v - K u + J^T f, with the input work, the viscous
 *  and each contact's friction dissipation integrated by the same scheme as extra states
 *  (so the balance's residual measures the scheme's energy error).
 *
 *  rtol = atol = 0: fixed steps dt > 0 (the last one shortened to end on t_end; RK4 is the
 *  classical one, the paper's method). A fixed explicit step passes the guard that
 *  fricreg_sim_run applies, or is refused (FRICREG_ESTEP): dt (lambda + c_max) within the
 *  stepper's stick-zone bound (lambda = fricreg_ctx_stick_stiffness, the chord's for (1), (2)
 *  and Karnopp; c_max the largest eigenvalue of M^-1 C), dt omega_max within its bound on the
 *  imaginary axis and within 1/sqrt 2 (omega_max^2 the largest eigenvalue of M^-1 K).
 *  Otherwise adaptive, dt the first step, under GSL's standard control (|error_k| <= atol +
 *  rtol |y_k| in every component k of y = (u, v, W_in, E_visc, D_1 ... D_m)), or under
 *  absolute tolerances per component: those of fricreg_structure_set_ode_abs_tolerances
 *  while set (in place of atol), or with atol = FRICREG_ATOL_FROM_EPS (-1) and rtol > 0
 *  (since 1.6, FRICREG_1.6) the rule from eps, fricreg_sim's (fricreg_sim_set_integrator)
 *  carried through J: law (4) reads the contact velocity zdot_i = sum_j J_ij v_j, which lies
 *  inside its band |zdot_i| < eps at a stick while the v_j may be of order 1, so a relative
 *  tolerance on v, or one atol >= eps, leaves the force of a stick uncontrolled. Each velocity
 *  v_j that a contact reads (J_ij != 0) is held absolutely, with no relative part, to
 *    atol_v_j = min(1e-3 eps min_{i: J_ij != 0} 1 / sum_k |J_ik|, rtol x 1 velocity unit),
 *  which bounds every contact's velocity error by 1e-3 eps (velocity units, as J v); every
 *  other component (the displacements, velocities no contact reads, W_in, E_visc and the D_i)
 *  keeps rtol + rtol |y_k|, the standard level with atol = rtol in the model's units.
 *  Contacts whose row of J is zero read nothing: with no contact reading any dof the rule is
 *  the standard control with atol = rtol. Measured (tests/structure/test_structure_ode_tolerances.c, a
 *  3-dof chain with two contacts at eps = 1e-5, 4 load periods, rtol 1e-6): the two
 *  contacts' dissipation errors against a converged run are 5.7e-3 and 1.7e-1 of it (msbdf)
 *  and 1.1e-5, 1.3e-4 (rkf45) with atol = rtol, 1.0e-6, 1.1e-5 (msbdf) and 4.4e-8, 2.2e-9
 *  (rkf45) with the rule (docs/structural.md). fricreg_structure_get_ode_abs_tolerances gives
 *  the values.
 *  Implicit steppers use a forward-difference Jacobian (2 ndof + 3 + m right-hand sides).
 *  The load and ground records are read at every stage time (interpolated). Allocates the
 *  GSL driver and O((2 ndof + m)^2) doubles for the run. Counts GSL steps in
 *  FRICREG_SSTAT_STEPS (no Newton iterations). Afterwards fricreg_structure_step continues
 *  from the state reached, its acceleration from the equation of motion.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_EINVAL for an unknown integrator or
 *  FRICREG_INT_CENTRAL or FRICREG_INT_CENTRAL_IMEX (fricreg_sim's only: use
 *  fricreg_structure_step's central difference), dt <= 0, rtol < 0, atol < 0 other than
 *  FRICREG_ATOL_FROM_EPS, FRICREG_ATOL_FROM_EPS with rtol = 0, t_end not after
 *  the current time, more than 2^31 fixed steps, J never set, W out of range (as
 *  fricreg_structure_step), rtol > 0 with atol = 0 for rk1imp, rk2imp, rk4imp, msadams or msbdf
 *  (as fricreg_sim_set_integrator; not with tolerances per component), or a stepper that
 *  solves its Newton matrix I - h c J by
 *  GSL's LU (rk1imp, rk2imp, rk4imp, bsimp, msbdf) where that matrix can be singular, which GSL
 *  would report to its error handler: on an unstable structure (K or C not positive
 *  semidefinite), or where the largest step (dt; t_end - t when adaptive) times the stiffest
 *  rate exceeds 1e12 (omega_max + c_max + m max_i W_ii 2 mun_i / max(eps, 1.5e-8), the
 *  friction's steepest slope as the forward-difference Jacobian sees it: near 1/DBL_EPSILON the
 *  identity is lost to rounding); FRICREG_ENONFINITE; FRICREG_ESTEP; FRICREG_ESINGULAR;
 *  FRICREG_EDIVERGED (the state non-finite or beyond 1e100); FRICREG_EINTEGRATOR (GSL failed,
 *  e.g. the adaptive step underflowed, or an entry of an implicit stepper's Jacobian times the
 *  largest step is beyond 1e100 or NaN: a load or a state so large that GSL's LU could round
 *  I - h c J to a singular matrix); FRICREG_EWORK (more adaptive steps than
 *  fricreg_structure_set_max_steps allows); FRICREG_ENOMEM. On failure the state is that of the
 *  last accepted step, its acceleration and forces from the equation of motion there (or,
 *  where that fails too, FRICREG_ESINGULAR or FRICREG_EDIVERGED, those of the run's start);
 *  with no step accepted, nothing a getter shows changes (the energy balance starts at the
 *  first accepted step). The observer sees every GSL step (one more right-hand side each for
 *  its forces) and may stop the run (FRICREG_OK); a call from the observer is FRICREG_EINVAL. */
FRICREG_API int fricreg_structure_run_ode(fricreg_structure *s, int integrator, double dt,
                                          double rtol, double atol, double t_end);

/** Set an absolute tolerance per component of fricreg_structure_run_ode's state
 *  y = (u, v, W_in, E_visc, D_1 ... D_m), as SUNDIALS' CVodeSVtolerances and
 *  fricreg_sim_set_abs_tolerances: while set, every adaptive run_ode call (rtol > 0 or
 *  atol != 0) accepts a step where |error_k| <= atol[k] + rtol |y_k| in every component k, in
 *  place of its atol argument, which then only selects adaptive steps (any atol > 0 with
 *  rtol = 0 runs on these alone); rtol = atol = 0 still takes fixed steps. The components:
 *  ndof displacements u (length), ndof velocities v (length/time), the input work W_in, the
 *  viscous dissipation E_visc and each contact's friction dissipation D_i (force x length),
 *  n = 2 ndof + 2 + m. Passed on to the error estimate's companion, which runs at them / 16.
 *  Since 1.6 (FRICREG_1.6).
 *
 *  s     in/out: the structure.
 *  n     in: 2 ndof + 2 + m, or 0 to remove the tolerances set (run_ode's atol applies again).
 *  atol  in: atol[n], each finite and > 0; copied. May be NULL with n = 0.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if s is NULL or atol is NULL with n > 0; FRICREG_ESIZE if
 *  n is neither 0 nor 2 ndof + 2 + m; FRICREG_ENONFINITE for an entry not finite;
 *  FRICREG_EINVAL for an entry <= 0, or when called from the observer during a run;
 *  FRICREG_ENOMEM. On failure nothing is changed. */
FRICREG_API int fricreg_structure_set_ode_abs_tolerances(fricreg_structure *s, size_t n,
                                                         const double atol[]);

/** Copy the absolute tolerances per component of y = (u, v, W_in, E_visc, D_1 ... D_m)
 *  (fricreg_structure_set_ode_abs_tolerances) that the last adaptive
 *  fricreg_structure_run_ode call asked for, evaluated now: those set (while set, even before
 *  any call), the call's one atol in every component, or under FRICREG_ATOL_FROM_EPS the
 *  rule's (fricreg_structure_run_ode: the call's rtol, the eps and J in use now; the entries
 *  of the velocities that contacts read carry no relative part, the others rtol |y_k| on top);
 *  zeros before any adaptive call. Since 1.6 (FRICREG_1.6).
 *
 *  s     in: the structure; not modified.
 *  n     in: 2 ndof + 2 + m.
 *  atol  out: atol[n]; written only on success.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if s or atol is NULL; FRICREG_ESIZE if n is not
 *  2 ndof + 2 + m. */
FRICREG_API int fricreg_structure_get_ode_abs_tolerances(const fricreg_structure *s, size_t n,
                                                         double atol[]);

/* ---- Checkpoints: a run saved and continued in another process ----------------------------- */

/** Save everything the structure carries from one step to the next into buf[*size], so that
 *  fricreg_structure_restore into a structure set up the same way continues the run bit for
 *  bit as this one would (since 1.7, FRICREG_1.7). The two-call idiom of sqlite3_serialize:
 *  with buf NULL, *size receives the bytes needed and nothing else happens; then a buffer of
 *  that size is filled.
 *
 *  What is saved: the time t and the grid of the last fricreg_structure_run (so that a run
 *  continued after a restore takes the steps an uninterrupted one takes), u, v, a, p~ and the
 *  friction forces at t with whether they hold the equation of motion there (Newmark's a is its
 *  step's, not the equilibrium's), the dt K_eff was factored for (a run's steps within 1e-9 of
 *  it are taken with it), the energy balance, each contact's dissipation, the counters, the
 *  peak displacements, the warnings' trackers, list and what the handler was given, the
 *  elements' committed and trial sliders, forces and dissipation, the context's warm start and
 *  cached factor (a coupled W), Newmark's near-stick block as its next step would find it
 *  (the dense path's held factor, whose last bits depend on the blocks before it, or the
 *  sparse path's block and shifts; since 1.8), and the error estimate with its companions,
 *  each saved the same way, nested. What is not: the model and the settings (checked by
 *  restore against a fingerprint: sizes, kinds, scheme, law, contact solver and their
 *  parameters one by one, the matrices, the records, the bounds and the set tolerances
 *  hashed), the observer and the warning handler,
 *  the bound on adaptive steps (fricreg_structure_set_max_steps: the restored structure's own)
 *  and the last error. GSL's steppers carry nothing between fricreg_structure_run_ode calls
 *  (each call starts its driver anew), so a checkpoint between two calls continues an adaptive
 *  run exactly too.
 *
 *  The blob is for the same build on the same machine: native byte order and type sizes, with
 *  a header (magic, format version, byte-order mark, the library version, the payload's length
 *  and hash) that fricreg_structure_restore checks. Its size is about 8 (6 ndof + 4 m) bytes
 *  plus the elements' state, a few kB of fixed fields (the warnings' messages), with a
 *  coupled dense W 8 m^2 at most, and the near-stick block's factor, at most 8 q (q + 3) for a
 *  dense one of q rows (q <= m: its factor and kept complement) or 9 m for the sparse path's;
 *  each companion adds its own.
 *
 *  s     in: the structure (not changed but for its last error).
 *  buf   out: the checkpoint, *size bytes; NULL to ask for the size.
 *  size  in: buf's length in bytes; out: the checkpoint's length (also when it does not fit).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if s or size is NULL; FRICREG_ESIZE if *size is below the
 *  checkpoint's length (then *size is that length, buf untouched); FRICREG_EINVAL if called
 *  from the observer or the warning handler during a run, or for a structure whose contacts
 *  couple through a sparse W (more than 64 contacts not on separate degrees of freedom, with
 *  the model set up by a step): the context's factor, updated row by row by CHOLMOD, is not
 *  carried (not supported; the message says so). Allocates nothing. */
FRICREG_API int fricreg_structure_save(fricreg_structure *s, void *buf, size_t *size);

/** Restore a checkpoint of fricreg_structure_save into s, which must be set up as the saved
 *  structure was when it was saved: the same sizes, model matrices, influence, load pattern,
 *  records, bounds, law and eps, scheme and its parameters, Newton's settings, elements,
 *  error estimate (on or off, its companions), contact solver (as set:
 *  fricreg_structure_set_contact_solver, since 1.8) and run_ode tolerances set (since 1.7,
 *  FRICREG_1.7). Its state
 *  then becomes the saved one (fricreg_structure_save lists it), whatever it was, and a run
 *  from here gives, bit for bit, what the saved structure would have given. With the steps of
 *  fricreg_structure_run that is also the uninterrupted run: a run of dt to T1, saved,
 *  restored and run to T2 takes the steps of one run to T2 where T1 is one of its step times
 *  (the rounded k dt equals T1, e.g. dt = 0.01, T1 = 0.5), and is then the same to the last
 *  bit, its error estimate included. The observer, the warning handler and the bound on
 *  adaptive steps stay s's own.
 *
 *  s     in/out: a structure set up as the saved one.
 *  buf   in: size bytes from fricreg_structure_save, of the same build on the same machine.
 *
 *  Cost: the set-up of the model (M's factor, W) and K_eff's factor at the saved dt, as the
 *  first step after a model setter (they allocate), the sparse path's near-stick block
 *  factored as the saved structure held it, and with the error estimate on, the companions
 *  made as a run's first step makes them.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if s or buf is NULL; FRICREG_EINVAL if buf is not a
 *  checkpoint (magic), is truncated or corrupted (length, hash or a field out of range), was
 *  written by another format, library version, byte order or type size, or if s is not set up
 *  as the saved structure (the message names the first difference: e.g. "the checkpoint's
 *  structure has ndof = 3, this one 4", or the model or the excitation as a whole), or when
 *  called from the observer or the warning handler during a run; the statuses of the set-up
 *  and of K_eff's factor (FRICREG_ENOMEM, FRICREG_ENOTPSD, ... as fricreg_structure_step); a
 *  companion's failure (its message after "the error estimate's companion: "); the sparse
 *  path's near-stick block factor's (FRICREG_ENOMEM, FRICREG_ESINGULAR). On failure the state
 *  of s is unchanged (the set-up and K_eff's factor may have been made: they are what its
 *  next step makes; a near-stick block factor held may have been dropped, so that its next
 *  step factors the block afresh, the same answers to rounding). */
FRICREG_API int fricreg_structure_restore(fricreg_structure *s, const void *buf, size_t size);

/** \} */

#ifdef __cplusplus
}
#endif

#endif /* FRICREG_STRUCTURE_RUN_H */
