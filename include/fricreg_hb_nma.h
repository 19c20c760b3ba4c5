/* SPDX-License-Identifier: GPL-3.0-or-later */
/**
 * \file
 * fricreg_hb_nma.h — harmonic balance's nonlinear modes: a mode's backbone by the extended
 * periodic motion concept (EPMC), its points, exact sensitivities, each harmonic's energy, modal
 * participation, and its folds and internal-resonance crossings.
 *
 * Part of fricreg_hb.h, which includes it (so does every header of the driver: include
 * either), split out by object since 1.9; the driver, its model and the conventions are
 * fricreg_hb.h's. Since 1.6 unless a function says otherwise.
 */
#ifndef FRICREG_HB_NMA_H
#define FRICREG_HB_NMA_H

#include "fricreg_hb.h"

#ifdef __cplusplus
extern "C" {
#endif

/** \defgroup hb_nma Joints: harmonic balance, nonlinear modes (fricreg_hb_nma.h)
 *  \{ */

/** \name Nonlinear modes
 *  The backbone of a mode: its natural frequency ω and damping ratio ζ as functions of its
 *  amplitude, by the extended periodic motion concept (EPMC: M. Krack, "Nonlinear modal analysis
 *  of nonconservative systems: extension of the periodic motion concept", Computers &
 *  Structures 154, 2015, pp. 59–71), on the model, elements and Newton settings of the forced
 *  response; the excitation is not used (nor changed). The periodic free motion with the
 *  dissipation made up by an artificial negative mass-proportional damping ξ M,
 *
 *      M x'' + (C − ξ M) x' + K x + J^T f(J x) = 0,      ζ = ξ / (2 ω),
 *
 *  is solved by HB for its harmonics, ω and ξ, condensed on q = J x as (R) with no load and
 *  D_h = K − (hω)² M + i hω (C − ξ M), closed by the amplitude and phase conditions on the
 *  first harmonic along the mode's linear shape φ_k (mass-normalized, φ_k^T M φ_k = 1):
 *  φ_k^T M X_1 = a (real), i.e. the modal coordinate is a cos ωt. The condensation needs each
 *  D_h(ω, ξ) nonsingular along the backbone, as the forced response does: a mode that no
 *  element takes part in (every element at a node of it) is a mode of the structure without
 *  its elements, whose D_1 is singular there (FRICREG_ESINGULAR).
 *  \{ */

/** The linear damping in a nonlinear mode (fricreg_hb_nma). Values are fixed forever. Since
 *  1.7. */
enum fricreg_hb_nma_damping {
    /** C (or Rayleigh's) as set: ζ includes it, exactly so for a mode of proportional damping. */
    FRICREG_HB_NMA_DAMPING_MATRIX = 0,
    /** C replaced by ξ_k M, ξ_k = φ_k^T C φ_k = 2 ζ_k ω_k the linear mode's: the mode's own
     *  linear damping without its coupling to the others (Krack 2015, Sec. 3). */
    FRICREG_HB_NMA_DAMPING_MODAL = 1
};

/** Follow the backbone of mode k from the modal amplitude a0 to a1 (EPMC, the section's
 *  comment): npoints points at the amplitudes a_i = a0 (a1/a0)^(i/(npoints−1)), each solved by
 *  Newton's method with the exact Jacobian (fricreg_hb_set_newton's tolerance and iterations, on (R) and
 *  on the amplitude condition relative to a) on the unknowns q, ω, ξ (ω and ξ derivatives of the
 *  condensation as for the continuation's). Where its line search finds no decrease of |R| but
 *  its own step is within the tolerance of the unknowns (each q's change within tol times the
 *  largest |q|, ω's and ξ's within tol times ω), |R| is at the rounding level of the model's
 *  scale (D_h's condition times the unit roundoff: a stiff model in SI units) and the point
 *  is converged (since 1.8; 1.7 returned FRICREG_EWORK there). The march starts at the linear mode of the
 *  structure with its elements stuck (K_0 = K + J^T diag(k) J, k the elements' stiffnesses: kt, the
 *  sum of an Iwan element's sliders of nonzero slip force, with lift-off kt and kn where the
 *  preload N0 > 0 closes the contact; K_0 φ = ω_k² M φ, mode 0 the lowest: on a dense model by
 *  GSL's symmetric eigensolver after the Cholesky factor of M, on a sparse model by shift-invert
 *  subspace iteration with Rayleigh–Ritz on CHOLMOD's factor of K_0 (K. J. Bathe, Finite
 *  Element Procedures, Sec. 11.6; max(2(k+1), k+9) vectors, Ritz values to 1e-12 and vectors
 *  to 1e-10 relative), at a0 or, if an element would slip (or open)
 *  below a0, at half the amplitude where the first one does, where the mode is the linear one
 *  exactly (ω = ω_k, ζ = ζ_k); it proceeds by natural-parameter continuation in log a, the
 *  predictor the secant of the last two solutions in (q/a, ω, ξ), a step whose corrector fails
 *  halved, down to 1/1024 of the grid's step. The amplitude is a natural parameter where the
 *  backbone is monotone in a; a backbone that folds in a (an internal resonance: a harmonic
 *  k ω near another mode's frequency) stops the march (fricreg_hb_nma_continue passes
 *  it). The points are stored (fricreg_hb_nma_points, fricreg_hb_nma_point), replacing those
 *  of an earlier call; the forced response's solution and branch are not changed. Since 1.8
 *  the crossings of a harmonic k ω with another stuck mode's frequency are found on the stored
 *  points (fricreg_hb_nma_special_points; a sparse model of at most 256 dofs then solves its
 *  dense eigenproblem too).
 *
 *  Cost per Newton iteration: the H + 1 factors of the forced response and a real LU of order
 *  m (2H + 1) + 2; once per call the linear mode: a dense model's dense eigenproblem of order
 *  ndof (O(ndof³)); a sparse model's sparse Cholesky factors of K_0 and of M, and per
 *  iteration (typically 5 to 40) a solve with p = max(2(k+1), k+9) right-hand sides and
 *  O(ndof p²) dense work. A sparse model's J rows should be sparse (an element's dofs): K_0
 *  holds the products of each row's nonzeros.
 *
 *  mode     k, 0 <= k < ndof, in ascending order of the linearized natural frequencies.
 *  damping  one of enum fricreg_hb_nma_damping.
 *  a0, a1   modal amplitudes, 0 < a0 < a1 (finite): displacement units times the square root
 *           of mass units (φ_k^T M X_1 with φ_k mass-normalized; for a unit mass, displacement).
 *  npoints  points, 2 <= npoints <= the continuation's max_points (fricreg_hb_set_continuation).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb is NULL; FRICREG_EINVAL if the elements were not
 *  set, mode >= ndof, damping is not an enumerator, not 0 < a0 < a1, npoints is out of range,
 *  or the stuck structure's mode k has ω_k² <= 0 (a sparse model: any of its modes, K_0 not
 *  positive definite); FRICREG_ENONFINITE if a0 or a1 is NaN or infinite, or an intermediate
 *  overflows (as fricreg_hb_solve; or the linear mode's reduced matrices, L^-1 K_0 L^-T with
 *  M = L L^T or the subspace's projections, with M and K of scales too far apart);
 *  FRICREG_ENOTPSD if M is not positive definite (a pivot of its Cholesky factor below 1e-14
 *  of its largest diagonal entry); FRICREG_ESINGULAR if some D_h(ω, ξ) or Newton's matrix is
 *  singular (as fricreg_hb_solve); FRICREG_EWORK if Newton did not converge (the step halved
 *  ten times), or a sparse model's subspace iteration did not converge in 300 iterations (or
 *  its mode's backward error ‖K_0 φ − λ M φ‖ / ((‖K_0‖_1 + λ ‖M‖_1) ‖φ‖) is above 1e-10),
 *  or the monitor or fricreg_hb_set_max_iterations's bound stopped it (the points reached
 *  kept); FRICREG_EINVAL also if called from the monitor; FRICREG_EINTEGRATOR as
 *  fricreg_hb_solve; FRICREG_ENOMEM. Allocates (npoints (nq + 3) +
 *  (nq + 2)² + O(H m² + ndof)) doubles, and while the linear mode is found 4 ndof² doubles
 *  (a dense model) or K_0's and M's sparse factors and 3 ndof p doubles (a sparse one). On
 *  failure after the arguments' checks the earlier points are gone and the points reached are
 *  kept, except when the first allocation (the backbone's own state) fails: then the earlier
 *  points stay. Since 1.7 (FRICREG_1.7). */
FRICREG_API int fricreg_hb_nma(fricreg_hb *hb, size_t mode, int damping, double a0, double a1,
                               size_t npoints);

/** The backbone of mode k at the caller's modal amplitudes: fricreg_hb_nma's march (from the
 *  linear mode below the first slip, the step halved where the corrector fails) through
 *  amplitude[0] < amplitude[1] < ..., a point stored at each (at exp(log a): the amplitude to
 *  its last bit or so), read as fricreg_hb_nma's (fricreg_hb_nma_point,
 *  fricreg_hb_nma_point_sensitivities, ...). For the amplitudes of a test's levels, which a
 *  geometric grid does not hold; a fold in a stops the march as fricreg_hb_nma's.
 *
 *  mode, damping  as fricreg_hb_nma's.
 *  n              the amplitudes, 1 to the driver's max_points (fricreg_hb_set_continuation).
 *  amplitude[n]   modal amplitudes φ_k^T M x_1, finite, > 0, strictly increasing; not kept.
 *
 *  Returns FRICREG_OK, or as fricreg_hb_nma (FRICREG_EINVAL for the elements, mode, damping;
 *  FRICREG_EWORK, FRICREG_ESINGULAR, ... for the march, the points reached kept); FRICREG_ENULL
 *  if hb or amplitude is NULL; FRICREG_EINVAL if n is 0 or above max_points or the amplitudes
 *  are not > 0 and increasing; FRICREG_ENONFINITE if one is NaN or infinite. Since 1.9
 *  (FRICREG_1.9). */
FRICREG_API int fricreg_hb_nma_at(fricreg_hb *hb, size_t mode, int damping, size_t n,
                                  const double amplitude[]);

/** Number of points stored by the last fricreg_hb_nma; 0 if none or hb is NULL. Returns that
 *  number, not a status. Since 1.7 (FRICREG_1.7). */
FRICREG_API size_t fricreg_hb_nma_points(const fricreg_hb *hb);

/** One point of the last backbone (fricreg_hb_nma): its amplitude, natural frequency, damping
 *  ratio and, if x is not NULL, the displacements' Fourier coefficients of the nonlinear mode's
 *  periodic motion (the free motion of the section's equation, modal coordinate a cos ωt),
 *  from (HB) with no load, X_h = −D_h^-1 J^T F_h (one factorization of every D_h).
 *
 *  i           point index, 0 <= i < fricreg_hb_nma_points(hb): by increasing amplitude after
 *              fricreg_hb_nma, in the branch's order after fricreg_hb_nma_continue.
 *  amplitude   out: its modal amplitude a (fricreg_hb_nma's units).
 *  omega       out: its natural frequency ω, rad/s.
 *  zeta        out: its damping ratio ζ = ξ/(2ω), nondimensional.
 *  ndof, nc    with x: the driver's degrees of freedom and 2H + 1; ignored when x is NULL.
 *  x[ndof nc]  out, or NULL: dof k's coefficients (x0, a_1, b_1, ..., a_H, b_H) at x[nc k ..],
 *              displacement units, as fricreg_hb_displacement's.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb, amplitude, omega or zeta is NULL; FRICREG_EINVAL
 *  if i is out of range, or x is given and the model or elements changed since fricreg_hb_nma;
 *  FRICREG_ESIZE if x is given and ndof or nc is not the driver's; FRICREG_ESINGULAR,
 *  FRICREG_EINTEGRATOR as fricreg_hb_solve (not for a point that was solved: the same
 *  evaluation succeeded there), FRICREG_ENOMEM (a sparse model: KLU's factors). Nothing is
 *  written on failure. Since 1.7 (FRICREG_1.7). */
FRICREG_API int fricreg_hb_nma_point(fricreg_hb *hb, size_t i, double *amplitude, double *omega,
                                     double *zeta, size_t ndof, size_t nc, double x[]);

/** What a parameter of fricreg_hb_nma_point_sensitivities is. Values are fixed forever. Since
 *  1.9. */
enum fricreg_hb_nma_param {
    /** Parameter index of fricreg_element.h's layout of the elements' type (jenkins,
     *  jenkins_2d, jenkins_3d: 0 kt, 1 mun; iwan, iwan_2d, iwan_3d: k[ns], phi[ns]; spring: 0 k;
     *  dahl: 0 sigma, 1 fc; jenkins_normal and contact_3d: 0 kt, 1 mu, 2 kn, 3 n0;
     *  iwan_normal: k[ns], mu[ns], kn, n0), one value shared by a range of elements. */
    FRICREG_HB_NMA_PARAM_ELEMENT = 0,
    /** The linear damping: index 0 the linear mode's modal damping ratio ζ_k (at fixed ω_k)
     *  of FRICREG_HB_NMA_DAMPING_MODAL, 1 and 2 Rayleigh's a0 and a1 (fricreg_hb_set_rayleigh). */
    FRICREG_HB_NMA_PARAM_DAMPING = 1,
    /** The modal amplitude a: the derivatives along the backbone. */
    FRICREG_HB_NMA_PARAM_AMPLITUDE = 2
};

/** The exact derivatives of point i of the last backbone (fricreg_hb_nma or
 *  fricreg_hb_nma_continue) in np parameters of the model: its natural frequency ω, its damping
 *  ratio ζ and each dof's first-harmonic amplitude |X_1| at the point's fixed modal amplitude a
 *  (or along the backbone for the amplitude itself). The point solves the section's equations
 *  R(y, p) = 0 (the condensed (R), the amplitude and phase conditions) in y = (q, ω, ξ); by the
 *  implicit function theorem
 *
 *      dy/dp = −(∂R/∂y)^-1 ∂R/∂p,      dζ/dp = (dξ/dp)/(2ω) − ξ (dω/dp)/(2ω²),
 *
 *  with ∂R/∂y Newton's matrix at the point (the point evaluated again, as fricreg_hb_nma_point
 *  with x, and factored once) and every parameter's ∂R/∂p one right-hand side of one solve. An
 *  element's ∂F/∂p is exact from the forces F and their Jacobian J = ∂F/∂U at the point, no
 *  other AFT, by the laws' homogeneity (f(u; λk, λφ) = λ f(u; k, φ) and f(λu; k, λφ) =
 *  λ f(u; k, φ) of a slider, the AFT's the same): dF/dk = J U/k, dF/dφ = (F − J U)/φ; with a
 *  normal law N = max(0, n0 + kn g), dF/dn0 = J[:, g_0]/kn (g_0 the mean of g; kn = 0:
 *  (F − J (U, G))/n0), dF_t/dkt = J_tt U/kt, dF_t/dmu = (F_t − J_tt U)/mu, dF/dkn = (F − J_tt U −
 *  n0 dF/dn0)/kn; an Iwan element's slider s by these identities on its own exact AFT or
 *  march, F_s and J_s (one AFT a parameter); a marched type's stiffness and bound (jenkins_2d,
 *  jenkins_3d, spring, dahl's sigma and fc) as a slider's, on the march's forces and Jacobian
 *  (exact for its samples). A stiffness of the stuck structure K_0 = K + J^T diag(k_r) J
 *  (kt and k_s of a slider of positive slip force, kn on a normal row closed by n0 > 0, a
 *  marched element's elastic stiffness) also
 *  moves the mode shape φ_k of the amplitude condition φ_k^T M X_1 = a (and ξ_k = φ_k^T C φ_k
 *  of the modal damping): with the bordered B = [K_0 − ω_k² M, M φ_k; φ_k^T M, 0] (symmetric,
 *  nonsingular for a simple ω_k), b^T dφ_k/dp = −Σ_r (dk_r/dp)(J_r z)(J_r φ_k) for B (z, ·) =
 *  (b, 0), b = M Re X_1, M Im X_1, C φ_k: a dense LU of order ndof + 1, so up to 256 dofs. ζ_k
 *  and a0 move ξ by 2 ω_k and 1 (D_h holds ξ − ξ_k, or a0 − ξ) and nothing else (so dω/dζ_k = 0,
 *  dζ/dζ_k = ω_k/ω); a1 enters D_h as i hω a1 K (dG_h/da1 = −Y_h^T (i hω K) Y_h), or with modal
 *  damping ξ_k by φ_k^T K φ_k. The amplitudes: dX_1 = −Y_1 dF_1 − D_1^-1 (dD_1) X_1, two or three
 *  solves with D_1 for all the parameters, d|X_1| = (Re X_1 Re dX_1 + Im X_1 Im dX_1)/|X_1|
 *  (0 at a dof where X_1 = 0). The derivatives are those of the HB solution at H harmonics,
 *  exact to Newton's tolerance on the point; at a stick–slip onset (the point where an element
 *  starts to slip or open) they are one-sided. Cost: one Newton iteration of the backbone, and
 *  per parameter O(H m² + (nq + 2)²) (an Iwan slider's parameter one AFT more), with stiffness
 *  parameters a dense LU of order ndof + 1.
 *
 *  i          point index, as fricreg_hb_nma_point's.
 *  np         the parameters, >= 0 (0: only the arguments are checked).
 *  kind[np]   each an enum fricreg_hb_nma_param.
 *  first[np], count[np]  ELEMENT: the elements first .. first + count − 1 (from 0, in the order
 *             they were set or added), count >= 1: one value that all of them share (the sum of
 *             the per-element derivatives); ignored for the other kinds.
 *  index[np]  ELEMENT: the parameter's index in each element's layout (enum
 *             fricreg_hb_nma_param); DAMPING: 0 ζ_k, 1 a0, 2 a1; ignored for AMPLITUDE.
 *  domega[np] out: dω/dp_k, rad/s per unit of p_k.
 *  dzeta[np]  out: dζ/dp_k (ζ as fricreg_hb_nma_point's), per unit of p_k.
 *  ndof       with damp: the driver's degrees of freedom; ignored when damp is NULL.
 *  damp[np ndof]  out, or NULL: d|X_1,j|/dp_k at damp[ndof k + j], |X_1,j| = the first harmonic's
 *             amplitude of dof j (hypot of x[nc j + 1], x[nc j + 2] of fricreg_hb_nma_point),
 *             displacement units per unit of p_k.
 *
 *  Not supported (FRICREG_EINVAL, the message says which): a marched type other than those
 *  above (a law added to the table later), a normal law's gap (HB's has none), a parameter
 *  whose identity divides by a value that is 0 (a slip force, mu or fc of 0, kn = 0 for kn,
 *  kn = n0 = 0 for n0), and a stiffness that moves φ_k on a model of more than 256 dofs. A
 *  sampled AFT (contact_3d, the marched types) makes the backbone piecewise smooth, its kinks
 *  where a sample's stick or slip changes: there the derivatives are one-sided.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb, domega or dzeta is NULL, or kind, first, count or
 *  index with np > 0; FRICREG_EINVAL if i is out of range, the model or elements changed since
 *  the backbone, called from the monitor, a kind or index is not one of the above, an element
 *  range is empty or beyond the elements, ζ_k is asked of a backbone with the matrix damping or
 *  a0, a1 of a model without Rayleigh damping, or a parameter is not supported (above);
 *  FRICREG_ESIZE if damp is given and ndof is not the driver's; FRICREG_ESINGULAR at a fold of
 *  the backbone in a (Newton's matrix singular: a pivot below 1e-14 of its largest entry,
 *  where the derivatives at fixed a are infinite), or if the stuck mode k is repeated (B
 *  singular), or as fricreg_hb_nma_point; FRICREG_EINTEGRATOR as fricreg_hb_nma_point (an Iwan
 *  slider's AFT or march); FRICREG_ENOMEM (np (nq + 2 + nq + m + ndof + 7) + O(ndof + H² + nq) doubles,
 *  and with stiffness parameters (ndof + 1)² + 3 ndof², during the call). Nothing is written on
 *  failure; the backbone and the driver's other results are left as they were. Since 1.9
 *  (FRICREG_1.9). */
FRICREG_API int fricreg_hb_nma_point_sensitivities(fricreg_hb *hb, size_t i, size_t np,
                                                   const int kind[], const size_t first[],
                                                   const size_t count[], const size_t index[],
                                                   double domega[], double dzeta[], size_t ndof,
                                                   double damp[]);

/** The backbone of mode k from the modal amplitude a0 to a1 by pseudo-arclength continuation
 *  (Keller's, Krack & Gross Ch. 5, as fricreg_hb_continue's), so that it passes the folds of
 *  the backbone in the amplitude (an S in a(ω): an internal resonance, where a harmonic k ω of
 *  the mode meets another mode's frequency), where fricreg_hb_nma stops. The equations, the
 *  start and the model are fricreg_hb_nma's (the extended periodic motion concept; the mode at
 *  a0 reached by its natural-parameter march from the linear mode, cheaper where the backbone
 *  is the linear mode); then the branch is followed in the scaled unknowns z = (q_h / (a u_s),
 *  q_0 / (a0 u_s), ω/ω_k, ξ/ω_k, log(a/a0)) (q_h the harmonics, q_0 the rows' means, u_s the
 *  largest |q|/a so far, from a0's: raised along the branch as fricreg_hb_continue's scale;
 *  ω_k the stuck linear mode's frequency) by a tangent predictor and a Newton corrector with a line search on the equations bordered by the
 *  arclength's hyperplane, with the step control of fricreg_hb_set_continuation (ds, ds_min,
 *  ds_max in z; a step rejected and halved when the corrector fails, ends beyond 4 ds, or the
 *  tangent turns by more than 20° or the corrector contracts by more than 1/2 in its first
 *  steps, unless halving no longer helps), until the amplitude a1, solved there exactly. Each
 *  point converges as fricreg_hb_nma's (fricreg_hb_set_newton's tolerance on (R) relative to
 *  the largest |q|, and on the amplitude and phase conditions relative to a).
 *
 *  A fold is where the tangent's log a component changes sign between two points; it is
 *  located by the linear interpolation of that component there, the point corrected onto the
 *  branch (on the hyperplane normal to the chord), and stored (fricreg_hb_nma_special_point,
 *  FRICREG_HB_NMA_FOLD). The stored points (fricreg_hb_nma_points, fricreg_hb_nma_point, in
 *  arclength order: the amplitude falls between two folds) are npoints at equal arclength in z
 *  along the branch, the first at a0 and the last at a1 the branch's own, the others each
 *  corrected onto the branch on the hyperplane normal to its stretch (so each a solution to
 *  Newton's tolerance; where that corrector fails, the nearer point of the branch). They replace
 *  those of an earlier fricreg_hb_nma or fricreg_hb_nma_continue, the folds too; the forced
 *  response's solution and branch are not changed.
 *
 *  Cost: per corrector iteration fricreg_hb_nma's (the H + 1 factors and a real LU of order
 *  m (2H + 1) + 3); the points of the branch as the step control takes them (at most
 *  max_points), then npoints correctors more.
 *
 *  mode, damping, a0, a1  as fricreg_hb_nma.
 *  npoints  the points stored, 2 <= npoints <= max_points (fricreg_hb_set_continuation): the
 *           density of the output along the branch, not the continuation's steps.
 *
 *  Returns FRICREG_OK and what fricreg_hb_nma returns, for the same reasons, and also
 *  FRICREG_EINTEGRATOR if the step fell below ds_min (the message names the amplitude and the
 *  last failure); FRICREG_EWORK if max_points points of the branch were taken before a1 (a
 *  branch that folds back for ever), or the monitor or fricreg_hb_set_max_iterations's bound
 *  stopped it; FRICREG_ESINGULAR if the bordered matrix is singular (a pivot below 1e-14 of its
 *  largest entry) at the start; FRICREG_ENOMEM. Allocates fricreg_hb_nma's and (max_points +
 *  nz + 13) nz doubles, nz = m (2H + 1) + 3, during the call. On failure after the linear mode
 *  the branch reached is kept: up to npoints of its points (resampled as above if it has more),
 *  and its folds. Since 1.8 (FRICREG_1.8). */
FRICREG_API int fricreg_hb_nma_continue(fricreg_hb *hb, size_t mode, int damping, double a0,
                                        double a1, size_t npoints);

/** The share of each harmonic in the kinetic energy of point i of the last backbone
 *  (fricreg_hb_nma or fricreg_hb_nma_continue): where it rises above the fundamental's
 *  neighbourhood, energy flows into a higher harmonic (an internal resonance; Krack & Gross
 *  2019). The measure is the kinetic energy averaged over a period, which the
 *  harmonics share without cross terms (they are orthogonal over a period: Parseval), unlike
 *  its peak or the potential energy (which the elements' hysteresis does not define per
 *  harmonic): with X_h = a_h cos(hωt) + b_h sin(hωt) the displacements' harmonic h
 *  (fricreg_hb_nma_point),
 *
 *      T_h = (hω)²/4 (a_h^T M a_h + b_h^T M b_h),   fraction[h] = T_h / Σ_{j=1..H} T_j,
 *
 *  so fraction[0] = 0 (the mean does not move) and the fractions add up to 1 (to rounding).
 *  Evaluates the point as fricreg_hb_nma_point with x does.
 *
 *  i            point index, 0 <= i < fricreg_hb_nma_points(hb), as fricreg_hb_nma_point's.
 *  nh           H + 1, the harmonics of the driver and the mean.
 *  fraction[nh] out: fraction[h] the share of harmonic h, 0 <= h <= H, nondimensional.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb or fraction is NULL; FRICREG_ESIZE if nh is not
 *  H + 1; FRICREG_EINVAL if i is out of range, the model or elements changed since the
 *  backbone, or called from the monitor; FRICREG_ENONFINITE if the energy is not finite and
 *  positive (an overflow); FRICREG_ESINGULAR, FRICREG_EINTEGRATOR, FRICREG_ENOMEM as
 *  fricreg_hb_nma_point; FRICREG_ENOMEM (ndof (2H + 4) doubles during the call). Nothing is
 *  written on failure. Since 1.8 (FRICREG_1.8). */
FRICREG_API int fricreg_hb_nma_harmonic_energy(fricreg_hb *hb, size_t i, size_t nh,
                                               double fraction[]);

/** The share of each linear mode of the structure with its elements stuck (K_0 φ_r = ω_r² M φ_r,
 *  the linearization the backbone starts from: fricreg_hb_nma's comment; every mode r, φ_r
 *  mass-normalized, ascending in ω_r, numbered as the backbone's mode argument) in harmonic h of
 *  the displacements at point i of the last backbone: which mode a harmonic excites (near an
 *  internal resonance, a higher harmonic moves mostly another mode). With a_h, b_h as
 *  fricreg_hb_nma_harmonic_energy's (h = 0: the mean x_0, b_0 = 0),
 *
 *      p_r = (φ_r^T M a_h)² + (φ_r^T M b_h)²,   fraction[r] = p_r / Σ_s p_s,
 *
 *  which adds up to 1 (Σ_s p_s = a_h^T M a_h + b_h^T M b_h: the modes are M-orthonormal and
 *  complete), every fraction 0 where harmonic h is exactly zero. The modes are solved once per
 *  backbone, at the first call (the dense eigenproblem of order ndof, O(ndof³), and ndof²
 *  doubles kept with the backbone); a sparse model's too, densified, up to 256 dofs (its
 *  subspace iteration finds its own mode only; above, FRICREG_EINVAL).
 *
 *  i                 point index, as fricreg_hb_nma_point's.
 *  harmonic          h, 0 <= h <= H (0: the mean, 1: the fundamental).
 *  nmodes            ndof: every mode of the stuck structure.
 *  fraction[nmodes]  out: fraction[r] the share of mode r (from 0, the lowest), nondimensional.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb or fraction is NULL; FRICREG_ESIZE if nmodes is not
 *  ndof; FRICREG_EINVAL if i or harmonic is out of range, the model is sparse with more than
 *  256 dofs, the model or elements changed since the backbone, or called from the monitor;
 *  FRICREG_ENOTPSD,
 *  FRICREG_ENONFINITE as fricreg_hb_nma's linear mode; FRICREG_ESINGULAR,
 *  FRICREG_EINTEGRATOR, FRICREG_ENOMEM as fricreg_hb_nma_point; FRICREG_ENOMEM (the modes'
 *  ndof² doubles, 4 ndof² during their solve, ndof (2H + 4) during the call). Nothing is
 *  written on failure. Since 1.8 (FRICREG_1.8). */
FRICREG_API int fricreg_hb_nma_modal_participation(fricreg_hb *hb, size_t i, int harmonic,
                                                   size_t nmodes, double fraction[]);

/** The kinds of special point along a backbone (fricreg_hb_nma_special_point). Values are fixed
 *  forever. Since 1.8. */
enum fricreg_hb_nma_special_type {
    /** a fold in the amplitude: the tangent's log a component changes sign (found by
     *  fricreg_hb_nma_continue only; fricreg_hb_nma stops before one) */
    FRICREG_HB_NMA_FOLD = 1,
    /** a harmonic k ω of the mode (k = 2..H) crosses another stuck linear mode's frequency ω_r,
     *  where an internal resonance can start */
    FRICREG_HB_NMA_CROSSING = 2
};

/** Number of special points of the last backbone (fricreg_hb_nma or fricreg_hb_nma_continue,
 *  also when it failed: those of the branch reached), its folds and crossings in one list
 *  (fricreg_hb_nma_special_point); 0 if none, no backbone or hb is NULL. Returns that number,
 *  not a status. Since 1.8 (FRICREG_1.8). */
FRICREG_API size_t fricreg_hb_nma_special_points(const fricreg_hb *hb);

/** Special point i of the last backbone, in the branch's order (by arclength after
 *  fricreg_hb_nma_continue, by amplitude after fricreg_hb_nma), its kind an out-argument as
 *  fricreg_hb_bifurcation's type:
 *
 *  - FRICREG_HB_NMA_FOLD, where the backbone's amplitude turns (found by
 *    fricreg_hb_nma_continue only, whose comment says how it is located: the tangent's log a
 *    component interpolated linearly to its zero, the point there corrected onto the branch);
 *    a, ω and ζ are that solution's, harmonic 1 and mode the backbone's.
 *  - FRICREG_HB_NMA_CROSSING, where a harmonic k ω of the mode (k = 2..H) crosses the frequency
 *    ω_r of another linear mode r of the structure with its elements stuck
 *    (fricreg_hb_nma_modal_participation's modes, r not the backbone's mode): an internal
 *    resonance can start there. Between two consecutive stored points a crossing is a change of
 *    sign of g = k ω − ω_r (g >= 0 at one, g < 0 at the other), placed at the fraction
 *    t = g_i / (g_i − g_{i+1}) of the stretch, with a, ω and ζ each linear in t between the two
 *    points' values (t along the stretch's arclength after fricreg_hb_nma_continue, its log a
 *    after fricreg_hb_nma: the chord's accuracy, so k ω = ω_r there to rounding while a and ζ
 *    are off by the branch's curvature times the stretch²). Found on the points stored, at the
 *    backbone's end. A sparse model's ω_r are found densified up to 256 dofs (its subspace
 *    iteration finds its own mode only; fricreg_hb_nma and fricreg_hb_nma_continue then also
 *    allocate 4 ndof² doubles and solve the dense eigenproblem, O(ndof³)); above, it has none.
 *
 *  The order: a crossing's place along the stored points is its stretch's index plus t, a
 *  fold's its arclength in the stored points' spacing (they are at equal arclength), ties a
 *  fold first, then by k, then by r.
 *
 *  i           0 <= i < fricreg_hb_nma_special_points(hb).
 *  type        out: an enum fricreg_hb_nma_special_type.
 *  amplitude   out: the modal amplitude a there (fricreg_hb_nma's units).
 *  omega       out: the backbone's natural frequency ω there, rad/s (a crossing: k ω = ω_r).
 *  zeta        out: its damping ratio ζ = ξ/(2ω) there, nondimensional.
 *  harmonic    out: k, 2 <= k <= H for a crossing; 1 for a fold.
 *  mode        out: r, the linear mode crossed, from 0 in ascending order of ω_r (as the
 *              backbone's mode argument); for a fold the backbone's own mode.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb, type, amplitude, omega, zeta, harmonic or mode is
 *  NULL; FRICREG_EINVAL if i is out of range. Nothing is written on failure. Since 1.8
 *  (FRICREG_1.8). */
FRICREG_API int fricreg_hb_nma_special_point(fricreg_hb *hb, size_t i, int *type, double *amplitude,
                                             double *omega, double *zeta, int *harmonic,
                                             size_t *mode);

/** \} */

/** \} */

#ifdef __cplusplus
}
#endif

#endif /* FRICREG_HB_NMA_H */
