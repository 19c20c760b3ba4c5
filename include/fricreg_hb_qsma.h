/* SPDX-License-Identifier: GPL-3.0-or-later */
/**
 * \file
 * fricreg_hb_qsma.h — quasi-static modal analysis (QSMA) of a harmonic-balance driver's model: a
 * mode's amplitude-dependent natural frequency and damping ratio from static solves along the
 * mode's load direction and Masing's rule for the loop, with their exact sensitivities. The
 * cheap route to the backbone where the nonlinear mode (fricreg_hb_nma, EPMC) is the full one.
 *
 * The model is the driver's (fricreg_hb.h: M, K, C or Rayleigh's, J and the elements); its
 * excitation, Newton settings and results are neither used nor changed. Since 1.9.
 */
#ifndef FRICREG_HB_QSMA_H
#define FRICREG_HB_QSMA_H

#include <stddef.h>

#include "fricreg_hb.h"

#ifdef __cplusplus
extern "C" {
#endif

/** \defgroup hb_qsma Joints: quasi-static modal analysis (fricreg_hb_qsma.h)
 *  \{ */

/** \name Quasi-static modal analysis
 *  R. M. Lacayo, M. S. Allen, "Updating structural models containing nonlinear Iwan joints using
 *  quasi-static modal analysis", Mechanical Systems and Signal Processing 118 (2019) 133–157.
 *  Mode k of the structure with its elements stuck, K_0 φ_k = ω_k² M φ_k (K_0 = K + J^T diag(k)
 *  J, φ_k^T M φ_k = 1, its largest entry positive: fricreg_hb_nma's mode), is loaded statically
 *  from rest (every slider stuck, unloaded) along its inertia load,
 *
 *      K x + J^T F(J x) = λ M φ_k,      q = φ_k^T M x,
 *
 *  λ increasing; the modal amplitude q and λ trace the virgin loading curve λ(q). The secant
 *  frequency and Masing's loop (the unloading branch the virgin curve doubled in size) give
 *
 *      ω(a)² = λ(a)/a,    D(a) = 8 ∫_0^a λ(s) ds − 4 a λ(a),    ζ(a) = ζ_k + D / (2π λ(a) a),
 *
 *  D the dissipation per cycle of modal amplitude a, ζ_k = φ_k^T C φ_k / (2 ω_k) the linear
 *  mode's damping ratio (C or Rayleigh's a0 M + a1 K). Below the first slip ω = ω_k, ζ = ζ_k.
 *
 *  The elements must be jenkins, iwan, jenkins_normal or contact_3d (fricreg_hb_set_elements,
 *  fricreg_hb_set_iwan, fricreg_hb_set_jenkins_2d_normal or fricreg_hb_add_elements with those
 *  types). Jenkins and iwan elements are sliders of stiffness k_s and slip force φ_s,
 *  whose forces under a monotone load are piecewise linear. The path is then piecewise linear
 *  and is followed exactly from event to event (each a slider reaching its slip force: the
 *  tangent K_t = K + Σ_stuck k_s J_r^T J_r refactored, LAPACK's dense Cholesky), so λ(q) and its
 *  integral are exact to rounding, not approximated. A slider slipping whose row then moves
 *  back against its slip (a later slip elsewhere can turn it) sticks again at its bound, and the
 *  pattern is solved anew until no slider does (a cycle that does not settle: FRICREG_EINVAL).
 *
 *  With contact_3d or jenkins_normal elements (kt, mu, kn, n0: the normal force N = n0 + kn g
 *  while positive, the tangential force on a disk, or an interval, of radius mu N) the force turns as the contact slides and its
 *  bound moves with g, so the path is marched instead: from the rest state under the preloads,
 *  (K + Σ kn J_n^T J_n) x_0 = −Σ n0 J_n^T over the contacts with n0 > 0, each contact's slider
 *  centred there (no tangential force: harmonic balance's stuck contact), q = φ_k^T M (x − x_0)
 *  in steps h = 2^⌊log2(a_max/256)⌋ (256 to 511 of them up to the largest amplitude), each
 *  point the static equilibrium with every element's return mapping from the point before
 *  (backward Euler, exact along a line), solved by Newton's method on the bordered consistent
 *  tangent K_0 + J^T E J (K_0's Cholesky factor once, and Woodbury's capacitance matrix, LAPACK's
 *  LU, on the rows of the elements not stuck, where E is not 0); each amplitude is reached by a step of its own from the grid
 *  point below it, and ∫λ by the trapezoid over the points (its error at a kink of λ(q) at most
 *  Δλ' h²/8, Δλ' the kink's change of slope). The stuck structure of K_0 has kt on a contact's
 *  tangential rows (where mu > 0) and kn on its normal row where n0 > 0. A contact may open on
 *  the way (N <= 0: no force, its slider following) and close again.
 *
 *  The model is taken dense (a sparse one spread out), up to 4096 dofs; each event costs a
 *  factor of order ndof, O(ndof³); each Newton iteration of the marched path O(a³ + ndof²), a
 *  the rows of the elements not stuck (a chain of 800 dofs with 100 contacts: 2.3 s).
 *
 *  Valid where QSMA is: one mode (its loading does not excite others: the mode shape may
 *  change with the slip, but the load stays M φ_k), Masing behaviour (exact where every slider
 *  loads monotonically; where one sticks again on the way, Masing's rule on the modal curve is
 *  QSMA's assumption, not each slider's own loop), and light damping (the energy of one cycle
 *  at the secant stiffness). With 3-D contacts whose normal force moves with the mode, the
 *  static path presses each contact one way where the vibration presses and relieves it in
 *  turn: Masing's rule is then QSMA's assumption, not the contact's loop. Where the joint
 *  couples modes (internal resonances), for iwan elements with lift-off or other laws,
 *  or where the damping is not light, the nonlinear mode
 *  (fricreg_hb_nma, EPMC) is needed: also where the slip changes the mode's shape much (stiff
 *  joints, whose slipped structure has its modes far from the stuck ones). Measured against
 *  EPMC's backbone at ζ_k = 0.1 % (modal damping; docs/identification.md): on a 60-dof chain
 *  with ten soft Jenkins elements within 3.2 % in ω and 24 % of ζ (5.2 % from 1.25 times
 *  the first slip's amplitude to where ζ reaches 0.15); on NLvib's 3-dof chain of stiff
 *  elements 1.4 % in ω but ζ up to 3 times EPMC's, between the first slip and EPMC's fold; on
 *  a 2-dof mass on one contact_3d element whose normal couples both dofs, 3.6 % in ω and 19 %
 *  of ζ from 2.7 times the first slip's amplitude to where the contact opens.
 *  \{ */

/** The natural frequency and damping ratio of mode k at the modal amplitudes amplitude[] by
 *  quasi-static modal analysis (the section's equations), on the driver's model.
 *
 *  mode          k, 0 <= k < ndof, in ascending order of the stuck structure's frequencies.
 *  n             the amplitudes, >= 1.
 *  amplitude[n]  modal amplitudes a = φ_k^T M x (fricreg_hb_nma's units: displacement times the
 *                square root of mass), finite, > 0, strictly increasing.
 *  omega[n]      out: ω(a), rad/s.
 *  zeta[n]       out: ζ(a), nondimensional.
 *
 *  Cost: a dense generalized eigenproblem of order ndof, then a Cholesky factor of order ndof
 *  per slider that slips before the last amplitude. Thread safety: one driver per thread.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb, amplitude, omega or zeta is NULL; FRICREG_EINVAL if
 *  the elements were not set, an element is not jenkins, iwan, jenkins_normal or contact_3d (the
 *  message names its type), no slider has a positive slip force and no element with a normal
 *  law is held, the
 *  preloads at rest open a contact whose n0 > 0 or close one whose n0 <= 0 (the message names
 *  it), the marched path's λ is not positive at an amplitude (a contact's friction turning the
 *  load back: no secant frequency), the model has more than 4096 dofs, mode >= ndof, n is 0,
 *  an amplitude is not > 0 or they do not increase, the stuck mode k has ω_k² <= 0, the sliders
 *  sticking again at an event settle on no pattern (each round turning another back; the
 *  message gives the amplitude), or if called from the monitor; FRICREG_ENONFINITE if an amplitude is NaN or infinite, or K_0 or M is not
 *  finite, or an intermediate overflows; FRICREG_ENOTPSD if M is not positive definite;
 *  FRICREG_ESINGULAR if K_0 is singular, or if the tangent becomes singular before the last
 *  amplitude: the sliders slipping leave a rigid-body motion (macroslip: λ cannot grow, the
 *  amplitude is beyond reach; the message gives the amplitude where it happens), and with
 *  contact_3d or jenkins_normal elements if K + Σ kn J_n^T J_n or a point's bordered tangent is
 *  singular; FRICREG_EWORK with such elements if Newton's method finds no static equilibrium at a
 *  point in 50 iterations, its step halved 12 times (the message gives the amplitude);
 *  FRICREG_ENOMEM (about 8 ndof² doubles during the call). Nothing is written on failure; the driver's
 *  results (solution, branch, backbone) are not changed. Since 1.9 (FRICREG_1.9). */
FRICREG_API int fricreg_hb_qsma_at(fricreg_hb *hb, size_t mode, size_t n, const double amplitude[],
                                   double omega[], double zeta[]);

/** The exact derivatives of fricreg_hb_qsma_at's ω and ζ at each amplitude in np parameters,
 *  each described as fricreg_hb_nma_point_sensitivities describes one (enum
 *  fricreg_hb_nma_param): an element parameter shared by a range of elements (jenkins: 0 kt,
 *  1 mun; iwan: k[ns], phi[ns]; contact_3d and jenkins_normal: 0 kt, 1 mu, 2 kn, 3 n0), the linear damping (index 0 ζ_k at fixed ω_k, 1 and 2
 *  Rayleigh's a0 and a1) or the amplitude itself (along the backbone).
 *
 *  On a piece of the path (its pattern of stuck and slipping sliders fixed) the point at fixed q
 *  solves K_t x + g = λ M φ_k, φ_k^T M x = q linearly (g = Σ_slipping σ_s φ_s J_r^T), so
 *
 *      dλ/dp = (−db^T x − v^T (−dK_t x − dg + λ db)) / (b^T v),    b = M φ_k,  v = K_t^-1 b,
 *
 *  one dot product a parameter (dK_t = J_r^T J_r for a stuck slider's stiffness, dg = σ_s J_r^T
 *  for a slipping slider's slip force). A slider stuck again carries k_s (J_r x − z_s) with its
 *  slip z_s = J_r x* − σ_s φ_s/k_s set at its event x*, which moves with p: dx* = dx|_λ + v dλ_e,
 *  K_t dx|_λ = −dK_t x − dg + λ db on the piece's factor (one solve a parameter and event) and
 *  dλ_e from the slip condition of the slider that made the event. A stiffness also moves φ_k: db = M dφ_k/dp from the
 *  bordered [K_0 − ω_k² M, M φ_k; φ_k^T M, 0] (dφ_k, −dω_k²) = (−dK_0 φ_k, 0) (one dense LU of
 *  order ndof + 1), and ζ_k with it. dλ/dp is affine in q on a piece, so its integral is exact
 *  by the trapezoid rule on each piece; the events' own motion adds nothing (λ continuous across
 *  them). Then, at fixed a,
 *
 *      dω/dp = (dλ/dp) / (2 ω a),   dD/dp = 8 ∫_0^a (dλ/dp) ds − 4 a dλ/dp,
 *      dζ/dp = dζ_k/dp + (dD/dp) / (2π λ a) − (ζ − ζ_k) (dλ/dp) / λ.
 *
 *  With contact_3d or jenkins_normal elements the derivatives are the marched path's, exact for it (not for the
 *  continuous path it approximates): at each point the factored bordered tangent gives
 *  (dx, dλ) from the elements' force derivatives in p and in their states before the point,
 *  and the states are carried forward by their return mappings' derivatives (forward
 *  differentiation through the march, one solve a parameter and point); x_0 moves by
 *  (K + Σ kn J_n^T J_n) dx_0 = −Σ J_n^T (dn0 + g_0 dkn); d∫/dp is the trapezoid's.
 *  At an amplitude where a slider starts to slip the derivatives are one-sided (the piece below).
 *  Cost: fricreg_hb_qsma_at's, and per parameter and event (marched: and point) a solve
 *  on the tangent's factor, O(ndof²); with stiffness parameters one dense LU of order ndof + 1.
 *
 *  mode, n, amplitude  as fricreg_hb_qsma_at's.
 *  np         the parameters, >= 0 (0: only the arguments are checked).
 *  kind[np]   each an enum fricreg_hb_nma_param.
 *  first[np], count[np]  ELEMENT: the elements first .. first + count − 1 (from 0, in the order
 *             they were set or added), count >= 1: one value that all of them share; ignored
 *             for the other kinds.
 *  index[np]  ELEMENT: the parameter's index in each element's layout (jenkins 0 kt, 1 mun;
 *             iwan of ns sliders: 0 .. ns − 1 the stiffnesses, ns .. 2 ns − 1 the slip forces;
 *             contact_3d, jenkins_normal 0 kt, 1 mu, 2 kn, 3 n0: their gap, 4, HB's normal law
 *             has none);
 *             DAMPING: 0 ζ_k, 1 a0, 2 a1; ignored for AMPLITUDE.
 *  domega[n np]  out: dω/dp_k at amplitude i in domega[np i + k], rad/s per unit of p_k.
 *  dzeta[n np]   out: dζ/dp_k, the same layout, per unit of p_k.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb, amplitude, domega or dzeta is NULL, or kind, first,
 *  count or index with np > 0; FRICREG_EINVAL as fricreg_hb_qsma_at, or if a kind or index is not
 *  one of the above (a normal law's index above 3), an element range is empty or beyond the
 *  elements, a parameter is a slider's of slip force 0 (it carries nothing: no derivative), a0,
 *  a1 is asked of a model without Rayleigh damping; FRICREG_ENONFINITE, FRICREG_ENOTPSD, FRICREG_ESINGULAR, FRICREG_EWORK as
 *  fricreg_hb_qsma_at, and FRICREG_ESINGULAR if a stiffness moves φ_k and the stuck mode k is
 *  repeated (the bordered matrix singular: a pivot below 1e-14 of its largest entry);
 *  FRICREG_ENOMEM (with stiffness parameters (ndof + 1)² + ndof² doubles more, and np (n +
 *  ndof + sliders + ...) doubles). Nothing is written on failure; the driver's results are not
 *  changed. Since 1.9 (FRICREG_1.9). */
FRICREG_API int fricreg_hb_qsma_sensitivities(fricreg_hb *hb, size_t mode, size_t n,
                                              const double amplitude[], size_t np, const int kind[],
                                              const size_t first[], const size_t count[],
                                              const size_t index[], double domega[],
                                              double dzeta[]);

/** \} */
/** \} */

#ifdef __cplusplus
}
#endif

#endif
