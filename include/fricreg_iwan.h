/* SPDX-License-Identifier: GPL-3.0-or-later */
/**
 * \file
 * fricreg_iwan.h — Iwan elements for joints in implicit finite-element codes: n independent
 * elements, each ns Jenkins sliders in parallel (slider s: a spring k_s in series with a
 * Coulomb slider of slip force phi_s), in 1-D or in the tangential plane (2-D). Beyond the
 * paper: the second element of "joints" (docs/joints.md), after fricreg_jenkins.h.
 *
 * An element's force is the sum of its sliders' forces, each slider the Jenkins element of
 * fricreg_jenkins.h with kt = k_s and mun = phi_s, with its own committed position w_s
 * (W. D. Iwan, "A distributed-element model for hysteresis and its steady-state dynamic
 * response", J. Appl. Mech. 33 (1966) 893-900):
 *
 *     f = sum_s f_s(u; w_s),     df/du = sum_s df_s/du
 *
 * with f_s and df_s/du the return mapping and consistent tangent of fricreg_jenkins.h: in 1-D
 * a stuck slider gives k_s u-increments and k_s to the tangent, a slipping one its bound
 * +-phi_s and 0. In 2-D each slider returns radially onto its own disk |f_s| <= phi_s (the
 * 2-D element falls out of the 2-D Jenkins slider unchanged). Under monotone loading from rest
 * in 1-D the force is the backbone F(u) = sum_s min(k_s |u|, phi_s) sign u; unloading follows
 * Masing's rule F(u_r) - F(u) = 2 F((u_r - u)/2), exactly, for any sliders.
 *
 * The sliders are the caller's (fricreg_iwan_set_params) or those of Segalman's
 * four-parameter model (fricreg_iwan_set_segalman: D. J. Segalman, "A four-parameter Iwan
 * model for lap-type joints", J. Appl. Mech. 72 (2005) 752-760), whose continuous density of
 * slip displacements phi on [0, phi_max]
 *
 *     rho(phi) = R phi^chi + S delta(phi - phi_max)
 *     phi_max = F_S (1 + beta) / (K_T (beta + (chi + 1)/(chi + 2)))
 *     R = F_S (chi + 1) / (phi_max^(chi + 2) (beta + (chi + 1)/(chi + 2)))
 *     S = F_S beta / (phi_max (beta + (chi + 1)/(chi + 2)))
 *
 * (unit-stiffness sliders of slip displacement phi; joint stiffness K_T = int rho, macroslip
 * force F_S = int phi rho) is discretized by the rule of fricreg_iwan_set_segalman.
 *
 * Normal load with lift-off (fricreg_iwan_set_normal, fricreg_iwan_trial_normal): the
 * sliders' slip forces phi_s are those at the preload N0 and scale with the normal force
 * N = max(0, N0 + kn g), as a Coulomb slider's bound mu N: phi_s N/N0. Where N0 + kn g < 0 the
 * element is separated: every slider follows the displacement (memory reset), f = 0, and the
 * tangents are 0. In contact df/dg = sum over slipping sliders of (phi_s kn/N0) n_s.
 *
 * Protocol: fricreg_iwan_trial as often as needed (the committed sliders do not change),
 * fricreg_iwan_commit once the step has converged. Cost O(n ns) per call; nothing allocates
 * after fricreg_iwan_create.
 *
 * Conventions are those of fricreg.h: int results are fricreg_status codes, nothing is printed,
 * a failed call leaves the caller's arrays and the object's state untouched, one object per
 * thread. The object keeps the status and a message of its last failed call
 * (fricreg_iwan_errcode, fricreg_iwan_errmsg, fricreg_iwan_errmsg_copy).
 * Since 1.6 (FRICREG_1.6).
 */
#ifndef FRICREG_IWAN_H
#define FRICREG_IWAN_H

#include "fricreg.h"

#ifdef __cplusplus
extern "C" {
#endif

/** \defgroup iwan Joints: Iwan elements with trial/commit (fricreg_iwan)
 *  An opaque set of n independent Iwan elements, each ns Jenkins sliders in parallel, 1-D or
 *  2-D, with user sliders or Segalman's four-parameter model, the exact return mapping, its
 *  consistent tangent, a normal load with lift-off, and the trial/commit protocol of implicit
 *  finite-element codes (docs/joints.md).
 *  \{ */

/** Opaque set of n Iwan elements of ns sliders: dim, the sliders' stiffnesses and slip forces,
 *  the normal laws, committed and trial slider positions, the last error. */
typedef struct fricreg_iwan fricreg_iwan;

/** Create n independent Iwan elements of ns sliders each, of dimension dim (1: a line; 2: the
 *  tangential plane).
 *
 *  Defaults: every slider k_s = 1/ns and phi_s = 1/ns (each element a Jenkins element of
 *  kt = 1 and mun = 1), no normal law (N0 = 1, kn = 0: the slip forces as set), every slider at
 *  0 (committed and trial). All memory is allocated here: (2 + 3 dim) n ns + (2 + 2 dim + dim²) n
 *  doubles (the parameters, the committed, trial and next trial positions, the normal laws
 *  and a trial's sums before they are checked).
 *
 *  dim  1 or 2.
 *  n    number of elements, >= 1.
 *  ns   sliders per element, >= 1; n ns <= SIZE_MAX/64.
 *  out  out: the new object, released with fricreg_iwan_free. Written only on success.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if out is NULL; FRICREG_EINVAL if dim is not 1 or 2, n or
 *  ns is 0, or n ns > SIZE_MAX/64; FRICREG_ENOMEM (also if those doubles exceed SIZE_MAX bytes).
 *  With no object to keep it, a failure has no message beyond its status, as for
 *  fricreg_ctx_create. Since 1.6. */
FRICREG_API int fricreg_iwan_create(int dim, size_t n, size_t ns, fricreg_iwan **out);

/** Release the elements. fricreg_iwan_free(NULL) does nothing. Since 1.6. */
FRICREG_API void fricreg_iwan_free(fricreg_iwan *iw);

/** Number of elements n; 0 if iw is NULL. Returns that number, not a status. Since 1.6. */
FRICREG_API size_t fricreg_iwan_size(const fricreg_iwan *iw);

/** Sliders per element ns; 0 if iw is NULL. Returns that number, not a status. Since 1.6. */
FRICREG_API size_t fricreg_iwan_sliders(const fricreg_iwan *iw);

/** Dimension of the elements, 1 or 2; 0 if iw is NULL. Returns that number, not a status.
 *  Since 1.6. */
FRICREG_API int fricreg_iwan_dim(const fricreg_iwan *iw);

/** Set every slider's stiffness and slip force (the slip force at the preload N0 once a
 *  normal law is set).
 *
 *  n          must equal the object's element count.
 *  ns         must equal the object's sliders per element.
 *  k[n ns]    stiffnesses > 0 (finite), force per unit displacement; element e's slider s at
 *             k[ns e + s] (Fortran: a (ns, n) array).
 *  phi[n ns]  slip forces >= 0 (finite), force units, laid out as k; 0: a slider that never
 *             carries a force.
 *
 *  The committed slider positions and the normal laws are kept; a trial not yet committed is
 *  discarded. All inputs are checked before anything changes.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if iw, k or phi is NULL; FRICREG_ESIZE if n or ns differs
 *  from the object's; FRICREG_ENONFINITE if some k or phi is NaN or infinite; FRICREG_EINVAL if
 *  some k <= 0 or phi < 0. Since 1.6. */
FRICREG_API int fricreg_iwan_set_params(fricreg_iwan *iw, size_t n, size_t ns, const double k[],
                                        const double phi[]);

/** Copy the sliders' stiffnesses and slip forces (as set, or as fricreg_iwan_set_segalman
 *  discretized them) into k and phi.
 *
 *  n, ns      must equal the object's.
 *  k[n ns]    out: stiffnesses, laid out as in fricreg_iwan_set_params.
 *  phi[n ns]  out: slip forces (at the preload N0), laid out as k.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if iw, k or phi is NULL; FRICREG_ESIZE if n or ns differs
 *  from the object's. Since 1.6. */
FRICREG_API int fricreg_iwan_get_params(fricreg_iwan *iw, size_t n, size_t ns, double k[],
                                        double phi[]);

/** Set every element's sliders to Segalman's four-parameter model (the density at the top of
 *  this header), discretized by the moment rule on a geometric grid:
 *
 *  With beta > 0 the last slider is the density's delta, stiffness S and slip force S phi_max,
 *  exactly, and the m = ns - 1 others discretize R phi^chi on [0, phi_max]; with beta = 0 all
 *  m = ns do. The breakpoints are x_0 = 0 and x_j = resolution^((m - j)/(m - 1)), j = 1..m
 *  (x_1 = resolution, x_m = 1; x_1 = 1 if m = 1), in units of phi_max: geometric, so that the
 *  grid looks the same at every amplitude. Slider j takes its interval's stiffness and slip
 *  force exactly,
 *
 *      k_j   = int rho        = K_T/(1 + beta) (x_j^(chi+1) - x_(j-1)^(chi+1))
 *      phi_j = int phi rho    = (F_S - S phi_max) (x_j^(chi+2) - x_(j-1)^(chi+2)),
 *
 *  so the discrete element's stiffness sum k = K_T and macroslip force sum phi = F_S are the
 *  continuous model's to rounding, for any ns, and its slip displacement phi_j/k_j is the
 *  density's mean on the interval. On the grid's self-similar part the discrete dissipation
 *  per cycle scales exactly as amplitude^(3 + chi) between amplitudes a grid ratio apart; the
 *  measured errors against the continuous model (backbone, dissipation) and their order 2 in
 *  ns are in docs/joints.md.
 *
 *  n           must equal the object's element count.
 *  fs[n]       macroslip force F_S > 0 (finite), force units.
 *  kt[n]       joint stiffness K_T > 0 (finite), force per unit displacement.
 *  chi[n]      exponent chi, -1 < chi <= 1 (finite; Segalman: -1 < chi < 0, the microslip
 *              dissipation growing as force^(3 + chi)).
 *  beta[n]     beta >= 0 (finite), the delta's weight: S = beta R phi_max^(chi+1)/(chi + 1);
 *              > 0 requires ns >= 2.
 *  resolution  the smallest breakpoint x_1 over phi_max, 0 < resolution < 1 (ignored if m = 1):
 *              the discrete model follows the continuous one's microslip from amplitudes about
 *              10 resolution phi_max up; 1e-6 is a fair default.
 *
 *  The committed slider positions and the normal laws are kept; a trial not yet committed is
 *  discarded. All inputs are checked before anything changes.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if iw, fs, kt, chi or beta is NULL; FRICREG_ESIZE if n
 *  differs from the element count; FRICREG_ENONFINITE if some parameter or resolution is NaN
 *  or infinite, or a slider's stiffness or slip force is not finite (extreme parameters);
 *  FRICREG_EINVAL if some fs <= 0, kt <= 0, chi <= -1 or chi > 1, beta < 0, beta > 0 with
 *  ns = 1, resolution outside (0, 1) with m >= 2, or a slider's stiffness underflows to 0.
 *  Since 1.6. */
FRICREG_API int fricreg_iwan_set_segalman(fricreg_iwan *iw, size_t n, const double fs[],
                                          const double kt[], const double chi[],
                                          const double beta[], double resolution);

/** Set each element's normal law: the sliders' slip forces scale as phi_s N/N0 with
 *  N = max(0, N0 + kn g), g the normal relative displacement of fricreg_iwan_trial_normal,
 *  positive when the surfaces press together (the header's lift-off rule).
 *
 *  n       must equal the object's element count.
 *  n0[n]   preload N0 > 0 (finite), force units: the normal force at which the slip forces are
 *          phi_s.
 *  kn[n]   normal stiffness >= 0 (finite), force per unit displacement.
 *
 *  fricreg_iwan_trial is then fricreg_iwan_trial_normal at g = 0 (the slip forces as set). The
 *  committed slider positions are kept; a trial not yet committed is discarded. All inputs are
 *  checked before anything changes.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if iw, n0 or kn is NULL; FRICREG_ESIZE if n differs from
 *  the element count; FRICREG_ENONFINITE if some n0 or kn is NaN or infinite, or kn/n0
 *  overflows; FRICREG_EINVAL if some n0 <= 0 or kn < 0. Since 1.6. */
FRICREG_API int fricreg_iwan_set_normal(fricreg_iwan *iw, size_t n, const double n0[],
                                        const double kn[]);

/** Trial forces and tangents at relative tangential displacements u, from the committed
 *  slider positions: the sum of the sliders' return mappings (fricreg_jenkins.h). The
 *  committed state does not change; the sliders' trial positions are kept for
 *  fricreg_iwan_commit (each trial replaces the previous one).
 *
 *  n          must equal the object's element count.
 *  u[n dim]   relative displacements (finite), element e's at u[dim e .. dim e + dim - 1].
 *  f[n dim]   out: the elements' internal forces (the sums of the sliders' kt (u - w)), laid
 *             out as u, |f_e| <= sum_s phi_s (the body whose relative displacement is u feels
 *             -f: f enters the internal force vector, as a spring's k u does). May alias u.
 *  dfdu[n dim dim]  out, or NULL if not wanted: the consistent tangents, element e's dim x dim
 *             block at dfdu[dim dim e], row-major and symmetric: sum over stuck sliders of
 *             k_s I plus, in 2-D, sum over slipping ones of (phi_s/|u - w_s|)(I - n_s n_s^T).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if iw, u or f is NULL; FRICREG_ESIZE if n differs from
 *  the element count; FRICREG_ENONFINITE if some u is NaN or infinite, u - w_s overflows, or an
 *  element's sum over its sliders overflows (each slider's force is finite, |f_s| <= phi_s,
 *  but ns of them near DBL_MAX, or the stuck sliders' k_s in dfdu where it is asked for, can
 *  sum beyond it). On failure nothing is written and the trial state is kept. Cost O(n ns);
 *  no allocation. Since 1.6. */
FRICREG_API int fricreg_iwan_trial(fricreg_iwan *iw, size_t n, const double u[], double f[],
                                   double dfdu[]);

/** Trial forces and tangents at tangential displacements u and normal displacements g, by the
 *  lift-off rule at the top of this header (slip forces phi_s N/N0, separated for
 *  N0 + kn g < 0). As fricreg_iwan_trial otherwise.
 *
 *  n          must equal the object's element count.
 *  u[n dim]   relative tangential displacements (finite), laid out as in fricreg_iwan_trial.
 *  g[n]       normal relative displacements (finite), displacement units, positive pressing.
 *  f[n dim]   out: tangential forces; 0 where separated. May alias u.
 *  nf[n]      out, or NULL: the normal forces N = max(0, N0 + kn g) >= 0.
 *  dfdu[n dim dim]  out, or NULL: df/du as in fricreg_iwan_trial; 0 where separated.
 *  dfdg[n dim]  out, or NULL: df/dg, sum over slipping sliders of (phi_s kn/N0) n_s; 0 where
 *             separated.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if iw, u, g or f is NULL; FRICREG_ESIZE if n differs from
 *  the element count; FRICREG_ENONFINITE if some u or g is NaN or infinite, u - w_s overflows,
 *  or N0 + kn g or a scaled slip force overflows, or an element's sum over its sliders does
 *  (as fricreg_iwan_trial; also df/dg where dfdg is asked for: phi_s kn/N0). On failure
 *  nothing is written and the trial state is kept. Cost O(n ns); no allocation. Since 1.6. */
FRICREG_API int fricreg_iwan_trial_normal(fricreg_iwan *iw, size_t n, const double u[],
                                          const double g[], double f[], double nf[], double dfdu[],
                                          double dfdg[]);

/** Make the last trial's slider positions the committed state (the step has converged).
 *  Without a trial since the last commit, reset or setter, the committed state stays.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if iw is NULL. Since 1.6. */
FRICREG_API int fricreg_iwan_commit(fricreg_iwan *iw);

/** Put every slider back at 0 (committed and trial), as after create; the sliders' parameters
 *  and the normal laws are kept.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if iw is NULL. Since 1.6. */
FRICREG_API int fricreg_iwan_reset(fricreg_iwan *iw);

/** Copy the committed slider positions into w.
 *
 *  n, ns         must equal the object's.
 *  w[n ns dim]   out: element e's slider s at w[dim (ns e + s) ..], displacement units
 *                (Fortran: a (dim, ns, n) array).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if iw or w is NULL; FRICREG_ESIZE if n or ns differs from
 *  the object's. Since 1.6. */
FRICREG_API int fricreg_iwan_get_slider(fricreg_iwan *iw, size_t n, size_t ns, double w[]);

/** Status of the last failed call on iw. Returns that code, or FRICREG_OK if none (or iw
 *  NULL). A successful call does not clear it. Since 1.6. */
FRICREG_API int fricreg_iwan_errcode(const fricreg_iwan *iw);

/** Message of the last failed call on iw: names the function, the argument and its value.
 *  "" if none; "NULL Iwan elements" if iw is NULL. Owned by iw, valid until its next call.
 *  Since 1.6. */
FRICREG_API const char *fricreg_iwan_errmsg(const fricreg_iwan *iw);

/** Copy the last error message into buf[len], NUL-terminated and truncated to fit (for
 *  Fortran). Returns the full message length (excluding the NUL), as snprintf does; 0 and
 *  nothing written if buf is NULL or len is 0. Since 1.6. */
FRICREG_API size_t fricreg_iwan_errmsg_copy(const fricreg_iwan *iw, char *buf, size_t len);

/** \} */

#ifdef __cplusplus
}
#endif

#endif /* FRICREG_IWAN_H */
