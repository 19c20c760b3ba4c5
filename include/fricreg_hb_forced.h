/* SPDX-License-Identifier: GPL-3.0-or-later */
/**
 * \file
 * fricreg_hb_forced.h — harmonic balance's forced response: the solve at one frequency, the
 * displacements and the truncation error, the continuation in the frequency or the level with its
 * stored points and peak, and the bifurcations located along a branch (fricreg_hb.h's equations
 * (HB), (R)).
 *
 * Part of fricreg_hb.h, which includes it (so does every header of the driver: include
 * either), split out by object since 1.9; the driver, its model and the conventions are
 * fricreg_hb.h's. Since 1.6 unless a function says otherwise.
 */
#ifndef FRICREG_HB_FORCED_H
#define FRICREG_HB_FORCED_H

#include "fricreg_hb.h"

#ifdef __cplusplus
extern "C" {
#endif

/** \defgroup hb_forced Joints: harmonic balance, the forced response (fricreg_hb_forced.h)
 *  \{ */

/** Solve the HB equations (R) at the excitation frequency omega by Newton's method with a
 *  backtracking line search on |R|², from the guess q0 or, if q0 is NULL, the solution reached
 *  continuously from the linear regime along the branch in the excitation level λ at omega
 *  (on an S-curve in λ, the lower branch). First, 1.6's start: Newton at λ = 0 and at λ = 1
 *  from the response with every element stuck (then, should that fail, with every element
 *  slipping freely); if the line between the two solutions solves (R) at λ = 1e-3 (Newton's
 *  tolerance), every element keeps to one linear regime along it (stuck, closed or open: each
 *  a set of inequalities linear in λ), the line is the branch and its end is returned.
 *  Otherwise fricreg_hb_continue_level's continuation from λ = 1e-3 to 1, its points not
 *  stored (the branch of fricreg_hb_continue and its bifurcations are kept), and should that
 *  fail, 1.6's solution at λ = 1 if it had one. Since 1.10 its correctors are given up after
 *  8 iterations whose steps have not fallen tenfold (a shorter step follows) and the branch
 *  where it crawls, 50 accepted steps in a row below 100 ds_min (kink after kink of the 3-D
 *  contact's sampled AFT: docs/harmonic_balance.md), for that solution
 *  (fricreg_hb_continue_level follows the branch whole, its correctors to max_iter). Should
 *  that fail too (a response homogeneous in the forcing, e.g. a unilateral spring without gap or
 *  preload, whose level branch is a ray no easier than its end), the continuation in Ω to
 *  omega, points not stored, from the nearest of Ω (1 + d) and Ω / (1 + d), d = 0.05, 0.1,
 *  0.2, 0.4, 0.8, where 1.6's start converges (since 1.7); on its failure too, 1.6's start's
 *  error is returned. With
 *  stability on (fricreg_hb_set_stability), a route whose solution is unstable does not end
 *  the start: the solution is held while the later routes (1.6's solution at λ = 1, the
 *  continuation in Ω from a nearby frequency) are tried, and the first stable one is returned
 *  (the level's branch can end on a closed branch of the response, unstable there, that the
 *  sweeps from either side never reach); none stable, the held one (since 1.8). For 1.6's
 *  start alone, pass a zero q0 (Newton's first step from zero, where the elements are stuck,
 *  is the stuck response).
 *  The solution is kept for fricreg_hb_displacement and, with stability on
 *  (fricreg_hb_set_stability), its stability for fricreg_hb_point_stability with
 *  FRICREG_HB_SOLUTION. Cost without a guess: three Newton solves on the linear branch;
 *  otherwise the continuation's points (75 to 170 on bench/hb_level.c's gap pair, 30 to 200
 *  times the old start's time), each a few Newton iterations at the one factorization of
 *  omega; Hill's method at the solution only.
 *
 *  omega        excitation circular frequency Ω > 0 (finite), 1/time (rad/s).
 *  nq           must equal m (2H + 1), or 2 m (2H + 1) with fricreg_hb_set_normal_elements.
 *  q0[nq]       guess, or NULL: element i's coefficients (q0, a_1, b_1, ..., a_H, b_H) at
 *               q0[(2H+1) i .. (2H+1) i + 2H] (with lift-off: row i of J's, rows 2i and
 *               2i + 1 element i's u and g), displacement units; finite.
 *  q[nq]        out: the solution, in the same layout. May alias q0.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb or q is NULL; FRICREG_EINVAL if omega <= 0 or
 *  the elements were not set; FRICREG_ENONFINITE if omega or some q0[j] is NaN or infinite,
 *  or an intermediate overflows (a model, element or excitation scale near the double range:
 *  D_h itself or its solves, or fricreg_aft_jenkins_exact's bound on 8 kt sum |q|);
 *  FRICREG_ESIZE if nq is not m (2H + 1) (2 m (2H + 1) with lift-off); FRICREG_ESINGULAR if
 *  K or some D_h(Ω) is singular (dense: a pivot of its LU factor below 1e-14 of the largest entry of |K| + (hΩ)² |M| +
 *  hΩ |C|; sparse: KLU's smallest over largest pivot magnitude below 1e-14, or a zero
 *  pivot; header comment), or Newton's matrix is; FRICREG_ENOMEM (a sparse model: KLU's
 *  analysis or factor); FRICREG_EWORK if Newton did not converge within max_iter iterations
 *  (or its line search found no decrease); FRICREG_EINTEGRATOR if the AFT's root solver
 *  failed (fricreg_aft_jenkins_exact) or, stability on, GSL's QR on Hill's matrix did not
 *  converge (fricreg_hb_set_stability); FRICREG_EWORK if stopped by the monitor or
 *  fricreg_hb_set_max_iterations's bound ("Monitoring and stopping a solve": nothing written). On failure q and the kept solution are
 *  untouched. Since 1.6. */
FRICREG_API int fricreg_hb_solve(fricreg_hb *hb, double omega, size_t nq, const double q0[],
                                 double q[]);

/** The displacements' Fourier coefficients of the last solution (fricreg_hb_solve, or the
 *  last point of fricreg_hb_continue), from (HB): X_h = D_h^-1 (P_h − J^T F_h(q)).
 *
 *  ndof          must equal the driver's degrees of freedom.
 *  nc            must equal 2H + 1.
 *  x[ndof nc]    out: dof k's coefficients (x0, a_1, b_1, ..., a_H, b_H) at x[nc k ..
 *                nc k + 2H], displacement units.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb or x is NULL; FRICREG_ESIZE if ndof or nc is not
 *  the driver's; FRICREG_EINVAL if there is no solution yet (or the model changed since);
 *  FRICREG_EINTEGRATOR as fricreg_hb_solve (FRICREG_ENONFINITE cannot arise: the solution's
 *  evaluation succeeded before); FRICREG_ENOMEM (a sparse model whose solves a later failed
 *  call moved: they are redone, with KLU's factors). Since 1.6. */
FRICREG_API int fricreg_hb_displacement(fricreg_hb *hb, size_t ndof, size_t nc, double x[]);

/** An error estimate of the truncation of the Fourier series at H harmonics, for the RMS of
 *  each dof and the amplitude of its fundamental, of the last solution or of a stored
 *  continuation point: the same model (matrices dense or sparse, damping, elements,
 *  excitation, Newton's settings) solved by Galerkin at H' = 2H + 1 harmonics in a companion
 *  driver made for the call, by Newton's method from the H solution padded with zeros (Krack
 *  & Gross Sec. 2.4: the convergence check by more harmonics), and
 *
 *      rms_error[k] = 2 |rms_k(H') − rms_k(H)|,  amplitude_error[k] = 2 ||X_1,k(H')| − |X_1,k(H)||
 *
 *  with rms_k as fricreg_hb_point's (all harmonics) and X_1,k dof k's fundamental (a_1, b_1 of
 *  fricreg_hb_displacement). The factor 2 makes it a bound on the error against the converged
 *  series, |rms_k(H) − rms_k(∞)|, whenever H' harmonics at least halve that error (so at most
 *  3 times it then): friction's kinked forces give algebraic convergence, about H^-3 to H^-4
 *  on the oscillator and the 3-dof chain of tests/forced/test_hb_truncation.c, where the estimate is
 *  1.6 to 2.6 times the error against H = 40 for H = 3 .. 19 (and 0, to rounding, where every
 *  element sticks: the response is the linear one, a single harmonic). The driver's solution,
 *  points, factors and error record are not changed on success; the companion is freed before the call returns.
 *
 *  Cost: the companion's creation and H' + 1 factors of D_h at the point's Ω, and its Newton
 *  solve at order m (2H' + 1) = m (4H + 3), which from the padded start takes typically 2
 *  iterations (1 where every element sticks): its first step is the classical "one Newton
 *  step" estimate, the second confirms it; where H truncates much, more (65 on a chain with
 *  Dahl elements 3% off at H = 7), so its bound is 4 times fricreg_hb_set_newton's (since
 *  1.8; 1.7 used that bound). Each iteration costs about 8 times one at H (an LU
 *  of twice the order; m AFTs at twice the harmonics). Measured (bench/hb_truncation.c, H = 3
 *  to 19, on the 3-dof chain and a 200-dof sparse rod): 2.4 to 6.3 times a continuation step
 *  at H (fricreg_hb_solve from the solution at Ω − 0.01: the H + 1 factors and its Newton
 *  iterations), and 0.007 to 0.4 times fricreg_hb_solve without a guess. Allocates the companion
 *  (fricreg_hb_create's memory at H', and a sparse model's copy, analysis and factors) and
 *  4 ndof doubles, all freed before it returns. Watched by the monitor as a solving call
 *  ("Monitoring and stopping a solve", the parameter Ω).
 *
 *  k                  the point's index, 0 <= k < fricreg_hb_points(hb) (its Ω and, on a
 *                     branch of fricreg_hb_continue_level, its level λ), or
 *                     FRICREG_HB_SOLUTION for the last solution (fricreg_hb_solve's, or the
 *                     last point of a continuation).
 *  ndof               must equal the driver's degrees of freedom.
 *  rms_error[ndof]    out: each dof's estimate, displacement units, >= 0.
 *  amplitude_error[ndof]  out, or NULL: each dof's estimate for |X_1|, displacement units, >= 0.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb or rms_error is NULL; FRICREG_ESIZE if ndof is not
 *  the driver's; FRICREG_EINVAL if 2H + 1 > FRICREG_HB_MAX_HARMONICS (H > 19), if there is no
 *  solution (k = FRICREG_HB_SOLUTION: none yet, or the model changed since), if k is out of
 *  range, or if the model or elements changed since the branch, or if called from the
 *  monitor; FRICREG_ENOMEM. When the solve at 2H + 1 fails, its status: FRICREG_ESINGULAR,
 *  FRICREG_EWORK (Newton did not converge, or stopped by the monitor or
 *  fricreg_hb_set_max_iterations's bound), FRICREG_EINTEGRATOR, FRICREG_ENONFINITE, as
 *  fricreg_hb_solve's, the message saying it was the solve at 2H + 1 and why. On failure
 *  rms_error and amplitude_error are untouched and so is the driver but for its error
 *  record. Since 1.7 (FRICREG_1.7). */
FRICREG_API int fricreg_hb_truncation_error(fricreg_hb *hb, size_t k, size_t ndof,
                                            double rms_error[], double amplitude_error[]);

/** Follow the periodic response from omega0 to omega1 by pseudo-arclength continuation in Ω
 *  (Keller's, Krack & Gross Ch. 5): from the solution at omega0 (fricreg_hb_solve's: from q0,
 *  or without one the solution reached from the linear regime along the excitation level, as
 *  fricreg_hb_solve's with q0 NULL; a zero q0 gives 1.6's start), a tangent predictor and a Newton corrector with a line search on (R)
 *  bordered by the arclength condition, with the step control of fricreg_hb_set_continuation
 *  (the parametrization passes turning points in Ω, and the kinks of the branch where the
 *  elements' stick/slip or contact pattern changes); the last point is solved at omega1
 *  exactly. Each point's Ω, the RMS of each dof over one period, rms_k² = x0² + (1/2) Σ_h
 *  (a_h² + b_h²) (all harmonics), and its unknowns q are stored (fricreg_hb_points,
 *  fricreg_hb_point, fricreg_hb_peak), replacing those of an earlier call; the last point is
 *  the one fricreg_hb_displacement gives. A branch that doubles back on itself (a new point
 *  within a tenth of a step of an earlier stretch of the branch, heading the same way, after a
 *  way along the branch of more than 3 times the distance between them) would never reach
 *  omega1: onto its first two stretches, it has come round a closed branch (an isola) and the
 *  continuation returns FRICREG_OK with the loop's points, the last one (the driver's
 *  solution) short of omega1, which is how a caller tells (since 1.8); onto a later stretch
 *  (a jump from one part of the branch onto another, across a sharp peak) it stops there with
 *  FRICREG_EWORK.
 *
 *  omega0, omega1  the interval's ends, > 0 (finite), omega0 != omega1 (either order), rad/s.
 *  nq, q0          as fricreg_hb_solve (q0 the guess at omega0, or NULL).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb is NULL; FRICREG_EINVAL if omega0 or omega1 <= 0,
 *  they are equal, or the elements were not set; FRICREG_ENONFINITE if omega0, omega1 or some
 *  q0[j] is NaN or infinite, or an intermediate overflows (as fricreg_hb_solve); FRICREG_ESIZE
 *  if nq is not fricreg_hb_solve's; FRICREG_ESINGULAR,
 *  FRICREG_EWORK, FRICREG_EINTEGRATOR as fricreg_hb_solve at omega0; FRICREG_EINTEGRATOR if
 *  the step fell below ds_min; FRICREG_EWORK if max_points were stored before omega1, or the
 *  branch doubled back onto a later stretch of itself (the message says which);
 *  FRICREG_ENOMEM (for the first 64 points before anything changed; for more, later, with the
 *  points so far kept; or KLU's, as fricreg_hb_solve, with the points so far kept);
 *  FRICREG_EWORK if stopped by the monitor or fricreg_hb_set_max_iterations's bound (the points
 *  reached kept, no bifurcations located: "Monitoring and stopping a solve"). On
 *  failure the points reached so far are kept (fricreg_hb_points
 *  counts them; 0 if the solve at omega0 failed) and fricreg_hb_displacement gives the last
 *  solution. Allocates room for the points, 64 at first, doubling: (1 + ndof + nq + 1)
 *  doubles each. Since 1.6. */
FRICREG_API int fricreg_hb_continue(fricreg_hb *hb, double omega0, double omega1, size_t nq,
                                    const double q0[]);

/** Follow the periodic response at the fixed excitation frequency omega from the excitation
 *  level λ = level0 to level1, the excitation being λ times fricreg_hb_set_excitation's (p_c,
 *  p_s): the S-curve of the amplitude against the level. The engine of fricreg_hb_continue
 *  with λ as the continued parameter in place of Ω: (R) is linear in the load, so
 *  R_λ = −J D_h^-1 P_h (one factorization of every D_h at omega serves the whole branch), the
 *  scaled unknowns (q/qs, λ/|level1 − level0|), the same step control, turning points in λ
 *  passed and located. Each point's RMS and unknowns are stored as fricreg_hb_continue's
 *  (replacing those of an earlier call): fricreg_hb_point gives its omega (the same for every
 *  point) and RMS, fricreg_hb_point_level its λ; fricreg_hb_point_stability its stability
 *  (stability on); the last point, at level1, is the one fricreg_hb_displacement gives.
 *  Bifurcations are located as along an Ω branch (fricreg_hb_bifurcation), FRICREG_HB_TP
 *  then meaning a fold in λ (the tangent's λ component changes sign), and
 *  fricreg_hb_bifurcation_level gives their λ. fricreg_hb_peak does not apply to such a branch.
 *  Later solves use the excitation as set (λ = 1).
 *
 *  omega           excitation frequency Ω > 0 (finite), rad/s.
 *  level0, level1  the levels' ends, >= 0 (finite), level0 != level1 (either order),
 *                  nondimensional.
 *  nq, q0          as fricreg_hb_solve (q0 the guess at level0, or NULL: the stuck guess,
 *                  then the slipping one, at level0).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb is NULL; FRICREG_EINVAL if omega <= 0, level0 or
 *  level1 < 0, they are equal, or the elements were not set; FRICREG_ENONFINITE if omega,
 *  level0, level1 or some q0[j] is NaN or infinite, or an intermediate overflows (as
 *  fricreg_hb_solve); FRICREG_ESIZE if nq is not fricreg_hb_solve's; FRICREG_ESINGULAR,
 *  FRICREG_EWORK, FRICREG_EINTEGRATOR as fricreg_hb_solve at level0; FRICREG_EINTEGRATOR if the
 *  step fell below ds_min; FRICREG_EWORK if max_points were stored before level1, or the
 *  branch doubled back onto a later stretch of itself (onto its first two: FRICREG_OK, the
 *  closed branch's points, the last short of level1, as fricreg_hb_continue), or it was
 *  stopped by the monitor or
 *  fricreg_hb_set_max_iterations's bound; FRICREG_ENOMEM; the points reached kept on failure,
 *  all as fricreg_hb_continue. Allocates as fricreg_hb_continue. Since 1.7 (FRICREG_1.7). */
FRICREG_API int fricreg_hb_continue_level(fricreg_hb *hb, double omega, double level0,
                                          double level1, size_t nq, const double q0[]);

/** Number of points stored by the last fricreg_hb_continue or fricreg_hb_continue_level; 0 if
 *  none or hb is NULL. Returns that number, not a status. Since 1.6. */
FRICREG_API size_t fricreg_hb_points(const fricreg_hb *hb);

/** One stored continuation point: its frequency and the RMS of each dof.
 *
 *  k           point index, 0 <= k < fricreg_hb_points(hb), in the order of the branch.
 *  omega       out: its excitation frequency Ω, rad/s (on a branch of
 *              fricreg_hb_continue_level, its fixed Ω: fricreg_hb_point_level gives λ).
 *  ndof        must equal the driver's degrees of freedom.
 *  rms[ndof]   out: each dof's RMS over one period (fricreg_hb_continue), displacement units.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb, omega or rms is NULL; FRICREG_EINVAL if k is
 *  out of range; FRICREG_ESIZE if ndof is not the driver's. Since 1.6. */
FRICREG_API int fricreg_hb_point(fricreg_hb *hb, size_t k, double *omega, size_t ndof,
                                 double rms[]);

/** The excitation level λ of a stored continuation point: the continued parameter of
 *  fricreg_hb_continue_level's branch, 1 on fricreg_hb_continue's.
 *
 *  k      point index, 0 <= k < fricreg_hb_points(hb).
 *  level  out: λ, nondimensional (the excitation is λ (p_c, p_s)).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb or level is NULL; FRICREG_EINVAL if k is out of
 *  range. Since 1.7 (FRICREG_1.7). */
FRICREG_API int fricreg_hb_point_level(fricreg_hb *hb, size_t k, double *level);

/** The displacements' Fourier coefficients of a stored continuation point, or of the last
 *  solution, from (HB): X_h = D_h^-1 (P_h − J^T F_h(q)) at the point's unknowns q, Ω and
 *  level, recomputed (one factorization of D_h and one force evaluation); the points keep
 *  their unknowns only, so a branch's memory does not grow with 2H + 1. Reading changes no
 *  later result of the driver.
 *
 *  k             point index, 0 <= k < fricreg_hb_points(hb), in the order of the branch, or
 *                FRICREG_HB_SOLUTION for the last solution (then as fricreg_hb_displacement).
 *  ndof          must equal the driver's degrees of freedom.
 *  nc            must equal 2H + 1.
 *  x[ndof nc]    out: dof j's coefficients (x0, a_1, b_1, ..., a_H, b_H) at x[nc j ..
 *                nc j + 2H], displacement units; their RMS is fricreg_hb_point's rms.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb or x is NULL; FRICREG_ESIZE if ndof or nc is not
 *  the driver's; FRICREG_EINVAL if k is out of range, the model or elements changed since
 *  the branch (k = FRICREG_HB_SOLUTION: no solution yet, or the model changed since), or
 *  called from the monitor; otherwise as fricreg_hb_displacement. Since 1.8 (FRICREG_1.8). */
FRICREG_API int fricreg_hb_point_displacement(fricreg_hb *hb, size_t k, size_t ndof, size_t nc,
                                              double x[]);

/** The largest RMS of one dof along the last fricreg_hb_continue's branch, located between the
 *  stored points rather than sampled at them: the stored point of the largest RMS and its two
 *  neighbours bracket it, and Brent's minimization without derivatives (R. P. Brent,
 *  "Algorithms for Minimization without Derivatives", 1973, Ch. 5: golden section and
 *  successive parabolic interpolation) maximizes the RMS over the branch's points between them,
 *  each solved by the continuation's corrector on a hyperplane normal to the neighbours' chord
 *  (a fixed Ω would not do at a fold), to 1e-6 of the chord's length (the RMS then to about
 *  1e-12 of itself, below Newton's tolerance). Typically 10 to 20 corrector solves. A largest
 *  RMS at the branch's first or last point is that point's. The branch's points, the driver's
 *  last solution (fricreg_hb_displacement) and its error record on success are not changed.
 *
 *  dof     the dof, 0 <= dof < ndof.
 *  omega   out: the excitation frequency of the largest RMS, rad/s. Written only on success.
 *  rms     out: that RMS over one period (as fricreg_hb_point's), displacement units.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb, omega or rms is NULL; FRICREG_EINVAL if dof is out
 *  of range, or there is no branch (no fricreg_hb_continue yet, none of its points stored, or
 *  the model or elements changed since; after a failed continuation the points reached
 *  serve); FRICREG_EWORK if a corrector did not converge within the Newton settings'
 *  iterations, or the location was stopped by the monitor or fricreg_hb_set_max_iterations's
 *  bound (omega and rms not written); FRICREG_ESINGULAR, FRICREG_EINTEGRATOR, FRICREG_ENOMEM as
 *  fricreg_hb_solve;
 *  FRICREG_EINVAL if the branch is fricreg_hb_continue_level's (in λ, not Ω). Since 1.7
 *  (FRICREG_1.7). */
FRICREG_API int fricreg_hb_peak(fricreg_hb *hb, size_t dof, double *omega, double *rms);

/** The kinds of bifurcation fricreg_hb_continue locates along a branch. */
enum fricreg_hb_bifurcation_type {
    FRICREG_HB_TP = 1, /**< turning point (fold in Ω): the tangent's Ω component changes sign */
    FRICREG_HB_BP = 2, /**< branch point: the bordered Jacobian's determinant changes sign */
    FRICREG_HB_PD = 3, /**< period doubling: a real multiplier crosses −1 (stability on) */
    FRICREG_HB_NS = 4 /**< Neimark–Sacker: a complex pair crosses the unit circle (stability on) */
};

/** Number of bifurcations fricreg_hb_continue located along its branch (fricreg_hb_bifurcation);
 *  0 if none or hb is NULL. Returns that number, not a status. Since 1.7 (FRICREG_1.7). */
FRICREG_API size_t fricreg_hb_bifurcations(const fricreg_hb *hb);

/** One located bifurcation of the last fricreg_hb_continue's branch, in the order of the branch.
 *
 *  Between two successive stored points, a sign change of a test function marks one: the
 *  tangent's Ω component (FRICREG_HB_TP), the determinant of the bordered Jacobian
 *  [R_q R_Ω; t^T] (FRICREG_HB_BP; it keeps its sign at a turning point), and with stability on
 *  (fricreg_hb_set_stability) a change of the stable flag not so explained, labelled by the
 *  exponent that crossed: Im λ at ±Ω/2 a period doubling (FRICREG_HB_PD), otherwise complex a
 *  Neimark–Sacker bifurcation (FRICREG_HB_NS), real a branch point (FRICREG_HB_BP). Each is
 *  located by bisection on its test function (a change of stability: that exponent's
 *  crossing of the unit circle, |μ| = 1, not the flag's margin) along the chord of the two
 *  points, each trial point solved by the continuation's corrector on the hyperplane normal
 *  to the chord, to 1e-9 of the chord (so Ω to about 1e-9 |Ω1 − Ω0| at most, far less at a
 *  turning point where Ω is stationary); a trial whose corrector fails ends the bisection at
 *  the bracket's nearer stored point. One bifurcation per pair of points at most (the first test that
 *  changed, in the order above).
 *
 *  i          index, 0 <= i < fricreg_hb_bifurcations(hb).
 *  type       out: an enum fricreg_hb_bifurcation_type.
 *  omega      out: its excitation frequency, rad/s (on a branch of fricreg_hb_continue_level,
 *             its fixed Ω: fricreg_hb_bifurcation_level gives λ).
 *  point      out, or NULL: the index k of the stored point before it (it lies between k and
 *             k + 1).
 *  ndof       must equal the driver's degrees of freedom.
 *  rms[ndof]  out: each dof's RMS there (as fricreg_hb_point's), displacement units.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb, type, omega or rms is NULL; FRICREG_EINVAL if i is
 *  out of range; FRICREG_ESIZE if ndof is not the driver's. Nothing is written on failure.
 *  Since 1.7 (FRICREG_1.7). */
FRICREG_API int fricreg_hb_bifurcation(fricreg_hb *hb, size_t i, int *type, double *omega,
                                       size_t *point, size_t ndof, double rms[]);

/** The excitation level λ of a located bifurcation (fricreg_hb_bifurcation): where it lies
 *  on a branch of fricreg_hb_continue_level (located to 1e-9 of the chord, as Ω is along an Ω
 *  branch; at a fold in λ, FRICREG_HB_TP, λ is stationary and far better); 1 on
 *  fricreg_hb_continue's.
 *
 *  i      index, 0 <= i < fricreg_hb_bifurcations(hb).
 *  level  out: λ, nondimensional.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb or level is NULL; FRICREG_EINVAL if i is out of
 *  range. Since 1.7 (FRICREG_1.7). */
FRICREG_API int fricreg_hb_bifurcation_level(fricreg_hb *hb, size_t i, double *level);

/** \} */

#ifdef __cplusplus
}
#endif

#endif /* FRICREG_HB_FORCED_H */
