/* SPDX-License-Identifier: GPL-3.0-or-later */
/**
 * \file
 * fricreg_aft.h — the alternating frequency–time (AFT) method for the 1-D Jenkins and Iwan
 * elements: from the Fourier coefficients of a periodic relative displacement, the Fourier
 * coefficients of the element force of the stabilized (periodic) hysteresis and their
 * Jacobian, for harmonic balance. Beyond the paper: the frequency-domain side of "joints"
 * (docs/aft.md). AFT after M. Krack and J. Gross, "Harmonic Balance for
 * Nonlinear Vibration Problems", Springer 2019, Sec. 3.3 (their NLvib's elasticDryFriction,
 * the Jenkins element, is sampled and marched over two periods).
 *
 * Convention, for every function: the displacement over one period, θ in [0, 2π), is
 *
 *     u(θ) = u0 + sum_{h=1..H} (a_h cos hθ + b_h sin hθ)
 *
 * given as the 2H + 1 coefficients u[] = (u0, a_1, b_1, a_2, b_2, ..., a_H, b_H); the force
 * f(θ) comes back in the same layout, f[] = (f0, fa_1, fb_1, ..., fa_H, fb_H), with
 * f0 = (1/2π) ∫ f dθ, fa_h = (1/π) ∫ f cos hθ dθ, fb_h = (1/π) ∫ f sin hθ dθ (harmonics
 * above H are dropped). The Jacobian jac[(2H+1)(2H+1)] is row-major, jac[(2H+1) i + j] =
 * ∂f[i]/∂u[j] (Fortran reading it column-major sees its transpose). The element is that of
 * fricreg_jenkins.h in 1-D: f = kt (u − w) with the slider w, |f| <= mun, of the same sign
 * as fricreg_jenkins_trial's (the spring force: u = A cos θ gives fa_1 > 0, fb_1 < 0). The
 * energy dissipated per period is ∮ f du = π sum_h h (b_h fa_h − a_h fb_h) >= 0.
 *
 * The stabilized hysteresis. With r = mun/kt and the range of u beyond the slip
 * (kt (max u − min u) > 2 mun), the element slips in every period and its periodic response is
 * unique: at the global maximum of u the slider sits at w = max u − r (the play operator's
 * wiping-out property), whatever the initial state. Below it (kt (max u − min u) <= 2 mun) the
 * element sticks after a transient and the periodic response depends on the initial state;
 * this header's rule is the centred slider w = (max u + min u)/2: the limit of the slipping
 * response as the range falls to 2 r (so f is continuous in the coefficients across the
 * threshold), and invariant under a time shift of u (a start at θ = 0, as NLvib's, is not).
 * A constant u gives f = 0 and the stick tangent kt on the harmonics.
 *
 * Two paths:
 *   - exact (fricreg_aft_jenkins_exact, fricreg_aft_iwan_exact): the velocity reversals
 *     u'(θ) = 0 are the sign changes of a trigonometric polynomial of degree H, isolated on
 *     a grid of 8H intervals certified by bounds on its derivatives and found by GSL's Brent,
 *     or, where the grid cannot certify them (a double root nearby), as the roots of a
 *     degree-2H algebraic polynomial by GSL's gsl_poly_complex_solve (companion matrix, QR);
 *     polished by Newton's method. Between two reversals u is monotone, so each
 *     stick→slip point kt (u(θ) − w) = ±mun is the one root in that bracket (GSL's Brent to
 *     4 ulps, then a Newton step); f is then
 *     integrated against cos kθ, sin kθ piece by piece in closed form (stick: kt (u − w), a
 *     trigonometric polynomial; slip: ±mun). No sampling error: the results are exact to
 *     rounding, that of kt u(θ): about DBL_EPSILON kt sum |u[j]|, and for u in the
 *     subnormals, whose spacing 2^-1074 is absolute, about kt (2H + 1) 2^-1074, which a
 *     bound mun below it does not shrink (u of 5e-324 in every coefficient, kt = 216, against
 *     mu N0 = 1e-321 with lift-off gives |f_0| = 8.6e-321); forces that are themselves
 *     subnormal carry a quantum from each product, up to (2H + 1)^2 per piece (kt = 5e-315
 *     beside u of 2e-8 and mu N0 = 2e-323 gives |f_0| = 5.8e-322). The Jacobian is exact too: f is continuous at the switch points, so their
 *     motion adds nothing; in a stick ∂f/∂u[j] = kt (φ_j(θ) − φ_j(θ_w)), θ_w the reversal where
 *     the slider stopped (u'(θ_w) = 0), and in a slip 0.
 *   - sampled (fricreg_aft_jenkins_sampled, fricreg_aft_iwan_sampled): u at N equidistant
 *     points, the return mapping of fricreg_jenkins.h marched over one period from the
 *     stabilized state at the sampled maximum (the state a march of any number of periods
 *     reaches there, so the march is already periodic), and the coefficients by GSL's real
 *     radix-2 FFT. Its error comes from the kinks of f (a stick–slip switch inside a sampling
 *     interval): O(N^-2) for the coefficients (docs/aft.md measures it). The Jacobian is the
 *     chain rule through the sampled return mapping (tangent kt in a stick, 0 in a slip) and
 *     the DFT. The sampled path is the one to extend to laws without a closed form (a
 *     velocity-only law of fricreg.h needs only f(u'(θ)) at the samples); here it serves the
 *     Jenkins and Iwan elements, beside the exact path, for comparison.
 * Lift-off (a normal displacement): both paths, fricreg_aft_jenkins_normal_exact and
 * fricreg_aft_jenkins_normal_sampled; the 3-D contact element (2-D tangential, normal lift-off):
 * the sampled path, fricreg_aft_jenkins_2d_normal_sampled (since 1.7).
 *
 * One object for both paths, with the harmonics H and the samples N fixed at create: it holds
 * every buffer an evaluation needs (the companion matrix, the roots, the pieces, the samples,
 * the FFT's array and the results before they are copied out), so an evaluation never
 * allocates (GSL's workspace rule), and the element parameters are arguments of each call
 * (an HB Newton loop changes u, seldom kt and mun, and one object serves every element of a
 * model). Conventions are those of fricreg.h: int results are fricreg_status codes, nothing is
 * printed, a failed call leaves the caller's arrays untouched, one object per thread. The
 * object keeps the status and a message of its last failed call (fricreg_aft_errcode,
 * fricreg_aft_errmsg, fricreg_aft_errmsg_copy). Since 1.6 (FRICREG_1.6).
 */
#ifndef FRICREG_AFT_H
#define FRICREG_AFT_H

#include "fricreg.h"

#ifdef __cplusplus
extern "C" {
#endif

/** \defgroup aft Joints: the alternating frequency–time method (fricreg_aft)
 *  An opaque workspace for the AFT of the 1-D Jenkins and Iwan elements: the Fourier
 *  coefficients of the stabilized hysteresis force and their Jacobian, exactly (switch points
 *  as roots of trigonometric polynomials, pieces integrated in closed form) or sampled (the
 *  return mapping at N points and GSL's FFT), docs/aft.md.
 *  \{ */

/** Opaque AFT workspace for H harmonics and N samples: every buffer of both paths, the last
 *  error. */
typedef struct fricreg_aft fricreg_aft;

/** Largest number of harmonics H of fricreg_aft_create: as far as the exact path is tested
 *  against the sampled one (docs/aft.md); its polynomial in t = tan(θ/2) has binomial
 *  coefficients up to C(2H, H). */
#define FRICREG_AFT_MAX_HARMONICS 40

/** Largest number of samples N of fricreg_aft_create, 2^24. */
#define FRICREG_AFT_MAX_SAMPLES 16777216

/** Create an AFT workspace for harmonics 0..H and, for the sampled path, N samples a period.
 *
 *  All memory is allocated here: O(H^2 + N H) doubles (since 1.7 8 N more, for the 3-D
 *  contact element).
 *
 *  harmonics  H, 1 <= H <= FRICREG_AFT_MAX_HARMONICS.
 *  samples    N: 0 (the exact path only: the sampled functions then fail with
 *             FRICREG_EINVAL), or a power of two with 2H + 2 <= N <= FRICREG_AFT_MAX_SAMPLES
 *             (every harmonic below the Nyquist frequency).
 *  out        out: the new object, released with fricreg_aft_free. Written only on success.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if out is NULL; FRICREG_EINVAL if H or N is out of its
 *  range or N is not a power of two; FRICREG_ENOMEM. With no object to keep it, a failure has
 *  no message beyond its status, as for fricreg_ctx_create. Since 1.6. */
FRICREG_API int fricreg_aft_create(int harmonics, size_t samples, fricreg_aft **out);

/** Release the workspace. fricreg_aft_free(NULL) does nothing. Since 1.6. */
FRICREG_API void fricreg_aft_free(fricreg_aft *aft);

/** Number of harmonics H; 0 if aft is NULL. Returns that number, not a status. Since 1.6. */
FRICREG_API int fricreg_aft_harmonics(const fricreg_aft *aft);

/** Number of samples N of the sampled path (0: none); 0 if aft is NULL. Returns that number,
 *  not a status. Since 1.6. */
FRICREG_API size_t fricreg_aft_samples(const fricreg_aft *aft);

/** Exact AFT of one 1-D Jenkins element: the Fourier coefficients of the force of the
 *  stabilized hysteresis under the displacement u, and their Jacobian (header comment).
 *
 *  kt     tangential stiffness > 0 (finite), force per unit displacement.
 *  mun    slip bound mu N >= 0 (finite), force units; 0 gives f = 0 and jac = 0.
 *  n      must equal 2H + 1.
 *  u[n]   displacement coefficients (u0, a_1, b_1, ..., a_H, b_H), finite, displacement units.
 *  f[n]   out: force coefficients (f0, fa_1, fb_1, ..., fa_H, fb_H), force units. May alias u.
 *  jac[n n]  out, or NULL if not wanted: ∂f[i]/∂u[j] at jac[n i + j] (row-major), force per
 *         unit displacement.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if aft, u or f is NULL; FRICREG_ESIZE if n is not
 *  2H + 1; FRICREG_ENONFINITE if kt, mun or some u[j] is NaN or infinite, or 8 max(1, kt)
 *  times the sum of |u[j]| overflows; FRICREG_EINVAL if kt <= 0 or mun < 0;
 *  FRICREG_EINTEGRATOR if GSL's polynomial root solver did not converge (30 QR iterations
 *  on one root; GSL then also calls its error handler: not seen on any input so far). All
 *  inputs are checked before anything is computed. Where mun is far below the rounding of u
 *  (mun <= 1e-12 kt sum |u[j]|: a stick's end would be lost in the rounding of u), sticks take
 *  no time: f = ±mun between the reversals, within |f| <= mun (since 1.7). Cost O(H^3) for
 *  the reversals (one root solve), O(H^2) per reversal for the rest; no allocation. Since
 *  1.6. */
FRICREG_API int fricreg_aft_jenkins_exact(fricreg_aft *aft, double kt, double mun, size_t n,
                                          const double u[], double f[], double jac[]);

/** Sampled AFT of one 1-D Jenkins element: as fricreg_aft_jenkins_exact, from the return
 *  mapping at the object's N samples and GSL's FFT (header comment); the results differ from
 *  the exact ones by the sampling error, O(N^-2).
 *
 *  Arguments, layouts and units as fricreg_aft_jenkins_exact.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if aft, u or f is NULL; FRICREG_EINVAL if the object was
 *  created with N = 0, kt <= 0 or mun < 0; FRICREG_ESIZE if n is not 2H + 1;
 *  FRICREG_ENONFINITE if kt, mun or some u[j] is NaN or infinite, or 8 max(1, kt) times
 *  the sum of |u[j]| overflows. All inputs are checked before anything is computed. Cost
 *  O(N H) for f, O(N H log N) with jac (2H FFTs of length N); no allocation. Measured at
 *  H = 40 on a loaded 2-core machine: N = 2^16, 0.03 s, 1.2 s with jac; N = 2^18, 0.4 s, 8 s
 *  with jac; about 10 minutes with jac at the largest N = 2^24 (the exact function needs no
 *  N). Since 1.6. */
FRICREG_API int fricreg_aft_jenkins_sampled(fricreg_aft *aft, double kt, double mun, size_t n,
                                            const double u[], double f[], double jac[]);

/** Exact AFT of one 1-D Iwan element of ns sliders in parallel (fricreg_iwan.h: slider s a
 *  Jenkins element of stiffness k[s] and slip force phi[s]): the sum of the sliders' exact
 *  AFTs, with the velocity reversals, which u alone decides, found once.
 *
 *  ns       number of sliders, >= 1.
 *  k[ns]    slider stiffnesses > 0 (finite), force per unit displacement.
 *  phi[ns]  slip forces >= 0 (finite), force units.
 *  n, u, f, jac  as fricreg_aft_jenkins_exact.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if aft, k, phi, u or f is NULL; FRICREG_EINVAL if ns is
 *  0, some k[s] <= 0 or phi[s] < 0; FRICREG_ESIZE if n is not 2H + 1; FRICREG_ENONFINITE if
 *  some k[s], phi[s] or u[j] is NaN or infinite, or 8 max(1, sum of k[s]) times the sum of
 *  |u[j]| overflows; FRICREG_EINTEGRATOR as fricreg_aft_jenkins_exact. Cost O(H^3) for the
 *  reversals, O(ns H^2) per reversal for the rest; no allocation. Since 1.6. */
FRICREG_API int fricreg_aft_iwan_exact(fricreg_aft *aft, size_t ns, const double k[],
                                       const double phi[], size_t n, const double u[], double f[],
                                       double jac[]);

/** Sampled AFT of one 1-D Iwan element: the sum of its sliders' sampled AFTs
 *  (fricreg_aft_jenkins_sampled), one FFT for the sum.
 *
 *  Arguments as fricreg_aft_iwan_exact.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if aft, k, phi, u or f is NULL; FRICREG_EINVAL if the
 *  object was created with N = 0, ns is 0, some k[s] <= 0 or phi[s] < 0; FRICREG_ESIZE if n is
 *  not 2H + 1; FRICREG_ENONFINITE as fricreg_aft_iwan_exact. Cost O(ns N H); no allocation.
 *  Since 1.6. */
FRICREG_API int fricreg_aft_iwan_sampled(fricreg_aft *aft, size_t ns, const double k[],
                                         const double phi[], size_t n, const double u[], double f[],
                                         double jac[]);

/** Sampled AFT of one 1-D Jenkins element under normal load with lift-off: the slip bound
 *  mu N with N = max(0, N0 + kn g) of fricreg_jenkins_set_normal, for a tangential
 *  displacement u and a normal one g (positive pressing) given by their coefficients. Returns
 *  the coefficients of the tangential force f and of the normal force N over the periodic
 *  response, and their Jacobian. Where the contact opens (N0 + kn g < 0) f = 0 and the slider
 *  follows u (its memory reset), so the response is periodic from the last opening (the
 *  contact closes where N0 + kn g, linear between two samples, crosses 0, the slider where u
 *  is then: since 1.10, not at the last open sample, so f is smooth in u and g); without
 *  an opening the bound moves with g, and the periodic state is marched to (up to 16
 *  periods, until the slider repeats to the bit), with the centred slider of the header
 *  comment, or the stuck slider nearest it where it does not hold (since 1.10, as
 *  fricreg_aft_jenkins_normal_exact), for a period that sticks throughout or slips one way
 *  only (at the periodic state such a slip has no length: the slider touches the bound, its
 *  place a leftover of the start). With kn = 0 and N0 >= 0 it equals fricreg_aft_jenkins_sampled at mun = mu N0 to
 *  the bit. Sampling error O(N^-2), as the
 *  sampled path; fricreg_aft_jenkins_normal_exact is its exact counterpart.
 *
 *  kt     tangential stiffness > 0 (finite), force per unit displacement.
 *  mu     friction coefficient >= 0 (finite), nondimensional.
 *  n0     preload N0 (finite), force units: the normal force at g = 0 (negative: open at g = 0).
 *  kn     normal stiffness >= 0 (finite), force per unit displacement.
 *  n      must equal 2H + 1.
 *  u[n]   tangential displacement coefficients (u0, a_1, b_1, ...), finite.
 *  g[n]   normal displacement coefficients, same layout, finite.
 *  f[n]   out: tangential force coefficients, force units.
 *  nf[n]  out: normal force coefficients of N(θ) = max(0, N0 + kn g(θ)), force units.
 *  jac[2n 2n]  out, or NULL if not wanted: row-major, rows (f, nf), columns (u, g):
 *         jac[2n i + j] = ∂f[i]/∂u[j], jac[2n i + n + j] = ∂f[i]/∂g[j],
 *         jac[2n (n + i) + n + j] = ∂nf[i]/∂g[j], and ∂nf/∂u = 0; one-sided at the samples'
 *         switches as fricreg_aft_jenkins_sampled's.
 *  The outputs are written after u and g are read: they may alias them.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if aft, u, g, f or nf is NULL; FRICREG_EINVAL if the
 *  object was created with N = 0, kt <= 0, mu < 0 or kn < 0; FRICREG_ESIZE if n is not
 *  2H + 1; FRICREG_ENONFINITE if kt, mu, n0, kn, some u[j] or g[j] is NaN or infinite, or the
 *  scales 8 max(1, kt) sum |u[j]| or 8 (1 + mu)(|n0| + kn (1 + sum |g[j]|)) overflow, or the
 *  slider's excursion 8 mu (|n0| + kn (1 + sum |g[j]|))/kt overflows (a spring far weaker than
 *  its bound, since 1.7: the march holds the slider's place; the exact path takes such a kt).
 *  All inputs are checked before anything is computed or written. Cost O(N H) per period marched for f
 *  and N (up to 16 periods), O(N H log N) with jac (6H FFTs of length N); no allocation.
 *  Measured at H = 40 on a loaded 2-core machine: N = 2^16, 0.07 s, 3.2 s with jac; N = 2^18,
 *  0.65 s, 28 s with jac; about half an hour with jac at the largest N = 2^24 (the exact
 *  function, fricreg_aft_jenkins_normal_exact, needs no N). Since 1.6. */
FRICREG_API int fricreg_aft_jenkins_normal_sampled(fricreg_aft *aft, double kt, double mu,
                                                   double n0, double kn, size_t n, const double u[],
                                                   const double g[], double f[], double nf[],
                                                   double jac[]);

/** Exact AFT of one 1-D Jenkins element under normal load with lift-off: the function of
 *  fricreg_aft_jenkins_normal_sampled (same arguments, outputs and layouts, so the two can be
 *  swapped) without sampling error. With the gap P(θ) = N0 + kn g(θ) and the bound
 *  mu max(0, P), the period splits into pieces: open (P < 0: f = 0, N = 0; at the touchdown
 *  the slider takes w = u, the spring unstressed), stick (f = kt (u − w), w constant) and slip
 *  (f = s mu P, s = ±1, w = u − s mu P/kt). Their switch points are roots of trigonometric
 *  polynomials of degree H: opening and touchdown P = 0; stick→slip
 *  s kt (u − w) − mu P = 0; slip→stick where the slider's velocity u' − s mu kn g'/kt changes
 *  sign. They are found as fricreg_aft_jenkins_exact finds its reversals and onsets (the sign
 *  changes of u' ± mu kn g'/kt once per call; each onset bracketed between two of them, where
 *  the margin is monotone, and found by GSL's Brent), and f, N are integrated piece by piece
 *  in closed form. The periodic response: one period from a touchdown when the contact opens;
 *  otherwise marched from the maximum of u with the slider at the positive bound until the
 *  state there repeats to the bit (up to 16 periods); a period with no slip, or slips one way
 *  only, takes the centred slider w = (max u + min u)/2 where it keeps |f| <= mu N
 *  throughout, else the stuck slider nearest it (of [max (u − mu N/kt), min (u + mu N/kt)]:
 *  since 1.10; 1.9 kept the march's, the least, which jumped where the centre left above). Where the bound is far below the rounding of u
 *  (mu (|N0| + kn sum |g_j|) <= 1e-12 kt sum |u_j|: a stick would last below 1e-6 rad and its
 *  end would be lost in the rounding of u − w), sticks take no time: the slider follows u and
 *  f = s mu P on the slips, so |f(θ)| <= mu max N still holds; and where that bound
 *  underflows to 0 (mu (|N0| + kn sum |g_j|) == 0 in double precision), f = 0 (since 1.7).
 *  With kn = 0 and N0 >= 0 it is fricreg_aft_jenkins_exact at mun = mu N0 (to rounding; to
 *  1e-6 of mu N0 where the sticks take no time; where u's oscillation is below the rounding
 *  of u itself, sum_{j>=1} |u[j]| <= 1e-12 sum |u[j]|, no motion is resolved and the two
 *  only share the bound).
 *
 *  The Jacobian is exact (f and N are continuous at the switch points, whose motion adds
 *  nothing): slip, ∂f/∂g_j = s mu kn φ_j(θ); stick after a slip ended at θw,
 *  ∂f/∂u_j = kt (φ_j(θ) − φ_j(θw)) and ∂f/∂g_j = s mu kn φ_j(θw); stick after a touchdown at
 *  θt, ∂f/∂u_j = kt (φ_j(θ) − φ_j(θt)) and ∂f/∂g_j = kt u'(θt) φ_j(θt)/g'(θt) (the touchdown
 *  moves with g; the sampled path, whose touchdown sits on a sample, has 0 there, and so has
 *  a touchdown that grazes: g'(θt) = 0, or kt u'(θt)/g'(θt) beyond DBL_MAX/(8 (2H + 1)),
 *  since 1.7);
 *  ∂N/∂g_j = kn φ_j(θ) while closed. φ_j is the basis 1, cos θ, sin θ, cos 2θ, ...
 *
 *  Arguments, layouts, units and aliasing as fricreg_aft_jenkins_normal_sampled; the object
 *  may have N = 0.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if aft, u, g, f or nf is NULL; FRICREG_EINVAL if
 *  kt <= 0, mu < 0 or kn < 0; FRICREG_ESIZE if n is not 2H + 1; FRICREG_ENONFINITE as
 *  fricreg_aft_jenkins_normal_sampled but for the slider's excursion (the slider is carried as
 *  the force kt w: any kt > 0 is taken); FRICREG_EINTEGRATOR as fricreg_aft_jenkins_exact (the
 *  outputs then untouched). All inputs are checked before anything is computed or written.
 *  Cost O(H^2) per sign change (three polynomials) and per piece, O(H^3) where the
 *  companion matrix is needed; no allocation. Since 1.6. */
FRICREG_API int fricreg_aft_jenkins_normal_exact(fricreg_aft *aft, double kt, double mu, double n0,
                                                 double kn, size_t n, const double u[],
                                                 const double g[], double f[], double nf[],
                                                 double jac[]);

/** Sampled AFT of one 3-D contact element: a 2-D Jenkins element in the tangential plane (an
 *  isotropic Coulomb disk |f| <= mu N with the radial return of fricreg_jenkins.h, dim = 2)
 *  under the normal law N = max(0, N0 + kn g) with lift-off (fricreg_jenkins_set_normal; the
 *  element of fricreg_structure_set_jenkins_2d_normal), for tangential displacements ux, uy and
 *  a normal one g (positive pressing) given by their coefficients. Returns the coefficients of
 *  the tangential forces fx, fy and of the normal force N over the periodic response, and
 *  their Jacobian, from the return mapping at N samples a period and GSL's FFT.
 *
 *  The periodic response (src/joint/aft_2d.c): where the contact opens in the period the
 *  slider follows u there, so one period from the last opening is periodic (closing between
 *  samples as fricreg_aft_jenkins_normal_sampled's). Otherwise the
 *  march starts from the centre of the smallest circle enclosing the sampled orbit (ux, uy)
 *  (1-D: the centred slider (max u + min u)/2 of the header comment, so f is continuous across
 *  the threshold of slip): a period without slip is the periodic state (a stick throughout);
 *  a slip is marched until the slider at the period's start repeats to the bit (4 periods),
 *  then found by Newton's method on w = Phi(w), the period's map, whose 2 x 2 derivative is a
 *  contraction wherever the element slips. The Jacobian is the chain rule through the samples,
 *  with the slider at the periodic start differentiated through w = Phi(w) (exact for the
 *  sampled map); a stick throughout that slips of the first periods placed is differentiated
 *  through them (the march run again for each column), one that Newton's steps reached holds
 *  its slider (the tangent of a held slider). With uy = 0 and kn = 0,
 *  fx, N and their Jacobian's (u, g) block equal fricreg_aft_jenkins_normal_sampled's (the
 *  forces to the bit where the element slips or the centred slider holds; tests/joint/test_aft_2d.c).
 *  Sampling error: the return mapping at the samples drags the slider along chords of a
 *  curved orbit, one sample behind the continuous element (as a time-stepped element is one
 *  step behind), so the error is first order in 1/N where the slip turns: a circular orbit of
 *  radius r > r_b = mu N0/kt under the constant normal force N0 (kn = 0) dissipates
 *  2 pi r_w mu N0 per period, r_w = sqrt(r^2 - r_b^2), and the value at N samples lies
 *  2 pi^2 mu N0 r_b / N below it at every r (to 6 %); slips on a line keep the O(N^-2) of the
 *  kinks. fricreg_hb_set_jenkins_2d_normal takes N = 64 (2H + 1) rounded up to a power of two
 *  and N/2, and extrapolates 2 F(N) − F(N/2), which removes the first-order term.
 *
 *  kt     tangential stiffness > 0 (finite), force per unit displacement.
 *  mu     friction coefficient >= 0 (finite), nondimensional.
 *  n0     preload N0 (finite), force units: the normal force at g = 0 (negative: open at g = 0).
 *  kn     normal stiffness >= 0 (finite), force per unit displacement.
 *  n      must equal 2H + 1.
 *  u[2n]  tangential displacement coefficients: ux's n (u0, a_1, b_1, ...), then uy's; finite.
 *  g[n]   normal displacement coefficients, same layout, finite.
 *  f[2n]  out: tangential force coefficients, fx's then fy's, force units.
 *  nf[n]  out: normal force coefficients of N(θ), force units.
 *  jac[3n 3n]  out, or NULL if not wanted: row-major, rows (fx, fy, nf), columns (ux, uy, g):
 *         jac[3n i + j] = ∂(fx, fy, nf)[i]/∂(ux, uy, g)[j]; ∂nf/∂u = 0.
 *  The outputs are written after u and g are read: they may alias them.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if aft, u, g, f or nf is NULL; FRICREG_EINVAL if the
 *  object was created with N = 0, kt <= 0, mu < 0 or kn < 0; FRICREG_ESIZE if n is not
 *  2H + 1; FRICREG_ENONFINITE if kt, mu, n0, kn, some u[j] or g[j] is NaN or infinite, or the
 *  scales of fricreg_aft_jenkins_normal_sampled overflow (either axis for u). All inputs are
 *  checked before anything is computed or written. Cost O(N H) per period marched (up to 4,
 *  then up to 40 Newton steps, each a period), O(N H log N) with jac (for each of the 6H + 3
 *  columns one to three marches of a period, up to five where slips placed a stick, and 2 FFTs
 *  of length N for a column of u, 3 for one of g); no allocation. Since 1.7 (FRICREG_1.7). */
FRICREG_API int fricreg_aft_jenkins_2d_normal_sampled(fricreg_aft *aft, double kt, double mu,
                                                      double n0, double kn, size_t n,
                                                      const double u[], const double g[],
                                                      double f[], double nf[], double jac[]);

/** Status of the last failed call on aft. Returns that code, or FRICREG_OK if none (or aft
 *  NULL). A successful call does not clear it. Since 1.6. */
FRICREG_API int fricreg_aft_errcode(const fricreg_aft *aft);

/** Message of the last failed call on aft: names the function, the argument and its value.
 *  "" if none; "NULL AFT workspace" if aft is NULL. Owned by aft, valid until its next call.
 *  Since 1.6. */
FRICREG_API const char *fricreg_aft_errmsg(const fricreg_aft *aft);

/** Copy the last error message into buf[len], NUL-terminated and truncated to fit (for
 *  Fortran). Returns the full message length (excluding the NUL), as snprintf does; 0 and
 *  nothing written if buf is NULL or len is 0. Since 1.6. */
FRICREG_API size_t fricreg_aft_errmsg_copy(const fricreg_aft *aft, char *buf, size_t len);

/** \} */

#ifdef __cplusplus
}
#endif

#endif /* FRICREG_AFT_H */
