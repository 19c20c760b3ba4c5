/* SPDX-License-Identifier: GPL-3.0-or-later */
/**
 * \file
 * fricreg_jenkins.h — Jenkins elements (elastic–slip elements) for implicit finite-element
 * codes: n independent elements, each a tangential spring of stiffness kt in series with a
 * Coulomb slider of bound mun = mu N, in 1-D or in the tangential plane (2-D). Beyond the paper:
 * the first element of "joints" (docs/joints.md).
 *
 * Each element holds its committed slider position w_c (dim components). A trial at the
 * relative tangential displacement u gives the force by the return mapping (backward Euler on
 * the slider: J. C. Simo, T. J. R. Hughes, Computational Inelasticity, Springer 1998, Ch. 1 for
 * the 1-D return mapping, Ch. 3 for the radial return; in 1-D it is exact for any path that
 * does not reverse within a step):
 *
 *     f_tr = kt (u - w_c)                                  elastic predictor
 *     |f_tr| <= mun:  f = f_tr,                df/du = kt I           (stick)
 *     |f_tr| >  mun:  f = mun f_tr/|f_tr|,     df/du = kt (mun/|f_tr|) (I - n n^T), n = f_tr/|f_tr|
 *                     w = u - f/kt             (the slider's trial position; slip)
 *
 * with |.| the absolute value in 1-D (there I - n n^T = 0: the sliding tangent is 0) and the
 * Euclidean norm in 2-D (radial return onto the disk |f| <= mun; the tangent is the consistent
 * one, symmetric). The force is continuous in u; the tangent jumps at |f_tr| = mun.
 *
 * Protocol (the one of an implicit code's Newton iterations): fricreg_jenkins_trial as often
 * as needed, which never changes the committed state; fricreg_jenkins_commit once the step has
 * converged, which makes the last trial's slider positions the committed ones. Cost O(n) per
 * call; nothing allocates after fricreg_jenkins_create.
 *
 * Normal load with lift-off (fricreg_jenkins_set_normal, fricreg_jenkins_trial_normal): the
 * bound becomes mun = mu N with the normal force N = max(0, N0 + kn g) of a preload N0 and a
 * normal stiffness kn on the normal relative displacement g, positive when the surfaces press
 * together (g < -N0/kn opens the contact). With N0 + kn g < 0 the element is separated: f = 0,
 * df/du = 0, df/dg = 0, and its slider follows the displacement (w = u: the spring unloaded,
 * the memory reset). In contact the return mapping above runs with mun = mu N, and
 *
 *     stick: df/dg = 0;     slip: df/dg = mu kn n          (dN/dg = kn)
 *
 * (the slip force mu N n grows with N along the slip direction). At N0 + kn g = 0 exactly the
 * contact is closed with mun = 0 (the one-sided derivatives of the closed side).
 *
 * The 3-D contact element (tmdsimpy's: one node of a bolted joint's contact patch) is the 2-D
 * element with a normal law: its inputs are the relative displacement (u_x, u_y, g), g positive
 * closing, its forces (f_x, f_y, N), its state the slider w in the tangential plane. One
 * convention for the normal law, the preload N0 at g = 0 (a gap d is N0 = -kn d): there is no
 * second way to give it, so nothing to reconcile. The tangential trial kt (u - w_c) returns
 * radially onto the disk |f| <= mu N (isotropic Coulomb); separation resets the memory (w = u,
 * f = 0), so that the first closed step starts from an unloaded spring at the last open
 * position. Its exact 3x3 tangent, d(f_x, f_y, N)/d(u_x, u_y, g), assembled from
 * fricreg_jenkins_trial_normal's dfdu (2x2) and dfdg (2), is
 *
 *     stick:  [kt I   0 ]    slip:  [kt (mu N/|f_tr|)(I - n n^T)   mu kn n]    open: 0
 *             [0     kn ]           [0                             kn     ]
 *
 * (dN/du = 0; dN/dg = kn where N0 + kn g >= 0, else 0). fricreg_structure_set_jenkins_2d_normal
 * puts these elements into a structure (docs/joints.md, "The 3-D contact element").
 *
 * One object, a dimension argument: the 1-D element is the 2-D one restricted to a line (the
 * same state, parameters, protocol and equations, only the norm changes), so one object type
 * with dim = 1 or 2 serves both, with the same functions and one Fortran type, rather than two
 * families of ten functions each. Arrays scale with dim: u, f and w hold dim numbers per
 * element, the tangent dim x dim.
 *
 * Conventions are those of fricreg.h: int results are fricreg_status codes, nothing is printed,
 * a failed call leaves the caller's arrays and the object's state untouched, one object per
 * thread. The object keeps the status and a message of its last failed call
 * (fricreg_jenkins_errcode, fricreg_jenkins_errmsg, fricreg_jenkins_errmsg_copy).
 * Since 1.6 (FRICREG_1.6).
 */
#ifndef FRICREG_JENKINS_H
#define FRICREG_JENKINS_H

#include "fricreg.h"

#ifdef __cplusplus
extern "C" {
#endif

/** \defgroup jenkins Joints: Jenkins elements with trial/commit (fricreg_jenkins)
 *  An opaque set of n independent Jenkins elements (a spring kt in series with a Coulomb slider
 *  of bound mun), 1-D or 2-D, with the exact return mapping, its consistent tangent and the
 *  trial/commit protocol of implicit finite-element codes (docs/joints.md).
 *  \{ */

/** Opaque set of n Jenkins elements: dim, kt and mun per element, committed and trial slider
 *  positions, the last error. */
typedef struct fricreg_jenkins fricreg_jenkins;

/** Create n independent Jenkins elements of dimension dim (1: a line; 2: the tangential
 *  plane).
 *
 *  Defaults: kt = 1 and mun = 1 for every element (fricreg_jenkins_set_params), every slider
 *  at 0 (committed and trial). All memory is allocated here: (4 + 2 dim) n doubles.
 *
 *  dim  1 or 2.
 *  n    number of elements, 1 <= n <= SIZE_MAX/64.
 *  out  out: the new object, released with fricreg_jenkins_free. Written only on success.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if out is NULL; FRICREG_EINVAL if dim is not 1 or 2, n
 *  is 0 or n > SIZE_MAX/64; FRICREG_ENOMEM. With no object to keep it, a failure has no
 *  message beyond its status, as for fricreg_ctx_create. Since 1.6. */
FRICREG_API int fricreg_jenkins_create(int dim, size_t n, fricreg_jenkins **out);

/** Release the elements. fricreg_jenkins_free(NULL) does nothing. Since 1.6. */
FRICREG_API void fricreg_jenkins_free(fricreg_jenkins *j);

/** Number of elements n; 0 if j is NULL. Returns that number, not a status. Since 1.6. */
FRICREG_API size_t fricreg_jenkins_size(const fricreg_jenkins *j);

/** Dimension of the elements, 1 or 2; 0 if j is NULL. Returns that number, not a status.
 *  Since 1.6. */
FRICREG_API int fricreg_jenkins_dim(const fricreg_jenkins *j);

/** Set each element's tangential stiffness and slip bound.
 *
 *  n       must equal the object's element count.
 *  kt[n]   tangential stiffness > 0 (finite), force per unit displacement.
 *  mun[n]  slip bound mu N >= 0 (finite), force units; 0: the element never carries a force.
 *
 *  The committed slider positions are kept; a trial not yet committed is discarded (the next
 *  fricreg_jenkins_commit without a trial keeps the committed state). All inputs are checked
 *  before anything changes. A fixed bound replaces a normal law of fricreg_jenkins_set_normal
 *  (it is the law mu = 1, N0 = mun, kn = 0).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if j, kt or mun is NULL; FRICREG_ESIZE if n differs from
 *  the element count; FRICREG_ENONFINITE if some kt[i] or mun[i] is NaN or infinite;
 *  FRICREG_EINVAL if some kt[i] <= 0 or mun[i] < 0. Since 1.6. */
FRICREG_API int fricreg_jenkins_set_params(fricreg_jenkins *j, size_t n, const double kt[],
                                           const double mun[]);

/** Trial forces and tangents at relative tangential displacements u, by the return mapping at
 *  the top of this header, from the committed slider positions. The committed state does not
 *  change; the slider's trial positions are kept for fricreg_jenkins_commit (each trial
 *  replaces the previous one).
 *
 *  n          must equal the object's element count.
 *  u[n dim]   relative displacements (finite), element i's at u[dim i .. dim i + dim - 1].
 *  f[n dim]   out: the elements' internal forces kt (u - w), |f_i| <= mun_i, laid out as u
 *             (the body whose relative displacement is u feels -f: f enters the internal
 *             force vector, as a spring's kt u does). May alias u.
 *  dfdu[n dim dim]  out, or NULL if not wanted: the consistent tangents, element i's dim x dim
 *             block at dfdu[dim dim i], row-major (df_a/du_b at [dim a + b]); each block is
 *             symmetric, so Fortran's column-major reading is the same. Stick: kt I; slip:
 *             kt (mun/|f_tr|)(I - n n^T), 0 in 1-D.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if j, u or f is NULL; FRICREG_ESIZE if n differs from the
 *  element count; FRICREG_ENONFINITE if some u is NaN or infinite, or u - w_c overflows (a
 *  displacement near 1e308). All inputs are checked before any output is written. Cost O(n);
 *  no allocation. Since 1.6. */
FRICREG_API int fricreg_jenkins_trial(fricreg_jenkins *j, size_t n, const double u[], double f[],
                                      double dfdu[]);

/** Set each element's normal law: the slip bound mu N with N = max(0, N0 + kn g) (the header's
 *  lift-off rule), g the normal relative displacement of fricreg_jenkins_trial_normal,
 *  positive when the surfaces press together. kt is kept.
 *
 *  n       must equal the object's element count.
 *  mu[n]   friction coefficient >= 0 (finite), nondimensional.
 *  n0[n]   preload N0 (finite), force units: the normal force at g = 0; negative for a contact
 *          open at g = 0 (a gap of -N0/kn).
 *  kn[n]   normal stiffness >= 0 (finite), force per unit displacement; 0: N = N0 whatever g.
 *
 *  fricreg_jenkins_trial is then fricreg_jenkins_trial_normal at g = 0 (bound mu max(0, N0)).
 *  The committed slider positions are kept; a trial not yet committed is discarded. All
 *  inputs are checked before anything changes.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if j, mu, n0 or kn is NULL; FRICREG_ESIZE if n differs
 *  from the element count; FRICREG_ENONFINITE if some mu[i], n0[i] or kn[i] is NaN or
 *  infinite, or mu[i] n0[i] or mu[i] kn[i] overflows; FRICREG_EINVAL if some mu[i] < 0 or
 *  kn[i] < 0. Since 1.6. */
FRICREG_API int fricreg_jenkins_set_normal(fricreg_jenkins *j, size_t n, const double mu[],
                                           const double n0[], const double kn[]);

/** Trial forces and tangents at tangential displacements u and normal displacements g, by the
 *  lift-off rule at the top of this header (bound mu max(0, N0 + kn g), separated for
 *  N0 + kn g < 0), from the committed slider positions. As fricreg_jenkins_trial otherwise: the
 *  committed state does not change, the sliders' trial positions (w = u where separated) are
 *  kept for fricreg_jenkins_commit.
 *
 *  n          must equal the object's element count.
 *  u[n dim]   relative tangential displacements (finite), laid out as in fricreg_jenkins_trial.
 *  g[n]       normal relative displacements (finite), displacement units, positive pressing.
 *  f[n dim]   out: tangential forces, |f_i| <= mu_i N_i; 0 where separated. May alias u.
 *  nf[n]      out, or NULL: the normal forces N = max(0, N0 + kn g) >= 0 (dN/dg = kn where
 *             N0 + kn g >= 0, else 0).
 *  dfdu[n dim dim]  out, or NULL: the tangents df/du, laid out as in fricreg_jenkins_trial;
 *             0 where separated.
 *  dfdg[n dim]  out, or NULL: df/dg per element: 0 in a stick or separated, mu kn n in a slip.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if j, u, g or f is NULL; FRICREG_ESIZE if n differs from
 *  the element count; FRICREG_ENONFINITE if some u or g is NaN or infinite, u - w_c overflows,
 *  or N0 + kn g or mu N overflows. All inputs are checked before any output is written. Cost
 *  O(n); no allocation. Since 1.6. */
FRICREG_API int fricreg_jenkins_trial_normal(fricreg_jenkins *j, size_t n, const double u[],
                                             const double g[], double f[], double nf[],
                                             double dfdu[], double dfdg[]);

/** Make the last trial's slider positions the committed state (the step has converged).
 *  Without a trial since the last commit, reset or set_params, the committed state stays.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if j is NULL. Since 1.6. */
FRICREG_API int fricreg_jenkins_commit(fricreg_jenkins *j);

/** Put every slider back at 0 (committed and trial), as after create; kt, mun and the normal
 *  law are kept.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if j is NULL. Since 1.6. */
FRICREG_API int fricreg_jenkins_reset(fricreg_jenkins *j);

/** Copy the committed slider positions into w.
 *
 *  n         must equal the object's element count.
 *  w[n dim]  out: element i's slider at w[dim i .. dim i + dim - 1], displacement units.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if j or w is NULL; FRICREG_ESIZE if n differs from the
 *  element count. Since 1.6. */
FRICREG_API int fricreg_jenkins_get_slider(fricreg_jenkins *j, size_t n, double w[]);

/** Status of the last failed call on j. Returns that code, or FRICREG_OK if none (or j NULL).
 *  A successful call does not clear it. Since 1.6. */
FRICREG_API int fricreg_jenkins_errcode(const fricreg_jenkins *j);

/** Message of the last failed call on j: names the function, the argument and its value.
 *  "" if none; "NULL Jenkins elements" if j is NULL. Owned by j, valid until its next call.
 *  Since 1.6. */
FRICREG_API const char *fricreg_jenkins_errmsg(const fricreg_jenkins *j);

/** Copy the last error message into buf[len], NUL-terminated and truncated to fit (for
 *  Fortran). Returns the full message length (excluding the NUL), as snprintf does; 0 and
 *  nothing written if buf is NULL or len is 0. Since 1.6. */
FRICREG_API size_t fricreg_jenkins_errmsg_copy(const fricreg_jenkins *j, char *buf, size_t len);

/** \} */

#ifdef __cplusplus
}
#endif

#endif /* FRICREG_JENKINS_H */
