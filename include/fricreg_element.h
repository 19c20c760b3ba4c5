/* SPDX-License-Identifier: GPL-3.0-or-later */
/**
 * \file
 * fricreg_element.h — friction elements that a host code calls point by point, the state held
 * by the caller in plain arrays: the kernel behind a legacy finite-element code's friction user
 * routine (Abaqus FRIC, ANSYS USERFRIC, CalculiX's contact springs, an OpenSees material; the
 * worked example is docs/hosts.md). Beyond the paper: the joints of docs/joints.md without an
 * object around them.
 *
 * An element type is a constant table of functions, in the manner of GSL's step types
 * (gsl_odeiv2_step_type): fricreg_element_lookup("jenkins") gives one, and a host keeps, per
 * integration point, its parameters params[nparams] and its state state[nstate] as doubles.
 * At each Newton iteration of an increment the host calls
 *
 *     fricreg_element_eval(T, params, state_old, u, f, dfdu, dfdp, state_new)
 *
 * with the state at the start of the increment and u at its end; it keeps state_new once the
 * increment converges, and after a cut-back calls again with state_old. The call is pure: the
 * same inputs give the same outputs bit for bit, it keeps nothing, allocates nothing, and may
 * run on any thread. Parameters may change from one call to the next (a host's normal force
 * sets the slip bound at every call); dfdp gives the force's derivative in each of them.
 *
 * The types (dim = the components of u and f; every vector in the host's own units):
 *
 *   name            dim  params (nparams)                          state (nstate)
 *   jenkins          1   kt, mun (2)                                w (1)
 *   jenkins_2d       2   kt, mun (2)                                w (2)
 *   jenkins_3d       3   kt, mun (2)                                w (3)
 *   jenkins_normal   2   kt, mu, kn, n0, gap (5)                    w (1)
 *   contact_3d       3   kt, mu, kn, n0, gap (5)                    w (2)
 *   iwan             1   k[ns], phi[ns] (2 ns)                      w[ns]
 *   iwan_2d          2   k[ns], phi[ns] (2 ns)                      w[2 ns], slider s at 2 s
 *   iwan_3d          3   k[ns], phi[ns] (2 ns)                      w[3 ns], slider s at 3 s
 *   iwan_normal      2   k[ns], mu[ns], kn, n0, gap (2 ns + 3)      w[ns]
 *   spring           1   k (1)                                      none (0)
 *   dahl             1   sigma, fc (2)                              w, u0 (2)
 *
 * spring is a linear spring, f = k u, df/du = k, df/dk = u (k > 0, finite): a joint's linear
 * stiffness beside its friction elements, and the table's simplest law (a new law is one file
 * and one line of the library's table: src/joint/element_spring.c). dahl is Dahl's model with
 * exponent 1 (P. R. Dahl 1968), dF/du = sigma (1 - sgn(du) F / fc), a law with state that is
 * not built from sliders: along an increment that does not reverse it is integrated exactly,
 *
 *     F = s fc - (s fc - F0) exp(-sigma |u - u0| / fc),   s = sgn(u - u0),
 *     df/du = sigma (1 - s F0 / fc) exp(-sigma |u - u0| / fc)
 *
 * from the force F0 = sigma (u0 - w) at the displacement u0 the last call ended at (state: the
 * bristles' root w and u0; state_out = (u - F/sigma, u)); at u = u0 the tangent is the
 * reversal's, s = -sgn F0 (s = 1 at F0 = 0). sigma > 0 (the stiffness at rest), fc > 0 (the
 * force it tends to under sliding), both finite with sigma / fc finite; structures and
 * harmonic balance (the march of its eval, through the orbit's turns) take it. Every other
 * one is ns
 * Jenkins sliders in parallel (ns = 1 but for the Iwan types; their ns is
 * fricreg_element_sliders'), slider s a spring k_s in series with a Coulomb slider of bound
 * b_s, returned from its old position w_s (Simo & Hughes, Computational Inelasticity, 1998,
 * Ch. 1 and 3; in 1-D exact for a path that does not reverse within the increment):
 *
 *     d_s = u_t - w_s,   stick (k_s |d_s| <= b_s): f_s = k_s d_s,  w_s' = w_s,  df_s/du = k_s I
 *                        slip:  f_s = b_s n_s,  w_s' = u_t - f_s/k_s,
 *                               df_s/du = (b_s/|d_s|)(I - n_s n_s^T),   n_s = d_s/|d_s|
 *     f_t = sum_s f_s
 *
 * with |.| the Euclidean norm of the tangential components u_t (the radial return onto the
 * disk |f_s| <= b_s: in 2-D the friction disk, in 3-D the ball, whose return keeps a plane:
 * with u and w in a contact plane, f and w' stay in it; the sliding tangent is 0 in 1-D). The
 * Jenkins types are kt = k_1 and mun = b_1; the Iwan types' are the elements of
 * fricreg_iwan.h, phi_s = b_s. A type without a normal law has u = u_t and f = f_t.
 *
 * The normal types (jenkins_normal, contact_3d, iwan_normal) add the normal displacement g as
 * u's last component, positive when the surfaces press together, and the normal force N as
 * f's last (fricreg_jenkins.h's lift-off law):
 *
 *     N = max(0, n0 + kn (g - gap)),   b_s = mu_s N   (mu_1 = mu)
 *     open (n0 + kn (g - gap) < 0): f = 0, df/du = 0, w_s' = u_t (the memory reset: on
 *     re-contact the spring starts unloaded where the surfaces meet)
 *
 * with df_t/dg = sum over slipping sliders of mu_s kn n_s and dN/dg = kn while closed. The
 * normal law is a preload n0 at g = 0 or a gap: a positive gap (closing at g = gap) with
 * n0 = 0, or n0 with gap = 0, not both. Either sign and kn = 0 are taken, and mean:
 *
 *     gap < 0 (n0 = 0): an interference, closed at g = 0 with N = kn |gap| (the preload
 *                       form's n0 = -kn gap, to rounding);
 *     n0 < 0 (gap = 0): a clearance, open while g < -n0/kn (the gap form's gap = -n0/kn);
 *     kn = 0:           a normal force given by the host, N = max(0, n0) whatever g (dN/dg = 0,
 *                       df_t/dg = 0): n0 > 0 presses, n0 < 0 (a tension) opens, and n0 = 0
 *                       (the gap form too) carries no force.
 *
 * The parameters' ranges: k_s (kt) > 0; b_s (mun, phi_s) >= 0; mu_s >= 0; kn >= 0; n0 and gap
 * finite, not both nonzero; ns <= FRICREG_ELEMENT_MAX_SLIDERS; all finite. The state: any
 * finite numbers (fricreg_element_init sets the sliders at 0).
 *
 * Conventions are those of fricreg.h: int results are fricreg_status codes, nothing is printed,
 * and a failed call writes nothing. With no object to keep a message, fricreg_element_explain
 * says why a call with the same inputs fails. Since 1.8 (FRICREG_1.8).
 */
#ifndef FRICREG_ELEMENT_H
#define FRICREG_ELEMENT_H

#include "fricreg.h"

#ifdef __cplusplus
extern "C" {
#endif

/** \defgroup element Joints: element types for host codes (fricreg_element)
 *  Friction elements as constant types of pure functions, with the parameters and state in the
 *  caller's arrays: the per-point kernel a host code's friction routine calls (docs/hosts.md).
 *  \{ */

/** An element type: a constant table owned by the library, never freed. */
typedef struct fricreg_element_type fricreg_element_type;

/** The most sliders of an Iwan type (fricreg_element_sliders). */
#define FRICREG_ELEMENT_MAX_SLIDERS 1024

/** The types' codes: code - 1 is the type's index in fricreg_element_at's list, and the code
 *  names it in the Fortran 77 entries (FRELEV's ITYPE; fricreg.fi has these names). Fixed
 *  forever: a new type gets the next code. Since 1.8. */
enum fricreg_element_code {
    FRICREG_ELEMENT_JENKINS = 1,        /**< jenkins */
    FRICREG_ELEMENT_JENKINS_2D = 2,     /**< jenkins_2d */
    FRICREG_ELEMENT_CONTACT_3D = 3,     /**< contact_3d */
    FRICREG_ELEMENT_IWAN = 4,           /**< iwan */
    FRICREG_ELEMENT_IWAN_NORMAL = 5,    /**< iwan_normal */
    FRICREG_ELEMENT_JENKINS_3D = 6,     /**< jenkins_3d */
    FRICREG_ELEMENT_JENKINS_NORMAL = 7, /**< jenkins_normal */
    FRICREG_ELEMENT_IWAN_2D = 8,        /**< iwan_2d */
    FRICREG_ELEMENT_IWAN_3D = 9,        /**< iwan_3d (the ball of jenkins_3d per slider) */
    FRICREG_ELEMENT_SPRING = 10,        /**< spring (a linear spring, no state) */
    FRICREG_ELEMENT_DAHL = 11           /**< dahl (Dahl's model: state, no slider) */
};

/** The type called name (the table at the top of this header; the Iwan types with ns = 1).
 *  Returns NULL if name is NULL or no type has that name. Since 1.8. */
FRICREG_API const fricreg_element_type *fricreg_element_lookup(const char *name);

/** The number of types: fricreg_element_at(0 .. count - 1) lists them all. Returns that
 *  number, not a status. Since 1.8. */
FRICREG_API size_t fricreg_element_count(void);

/** The type at index in the library's list (ns = 1 for the Iwan types). The list's order is
 *  fixed forever, new types appended: index + 1 is the type's code (enum
 *  fricreg_element_code), which names it in the Fortran 77 entries
 *  (fortran/fricreg_element_f77.f90). Returns NULL if index >= fricreg_element_count().
 *  Since 1.8. */
FRICREG_API const fricreg_element_type *fricreg_element_at(size_t index);

/** The type of type's family with ns sliders in parallel: for iwan, iwan_2d, iwan_3d and
 *  iwan_normal, 1 <= ns <= FRICREG_ELEMENT_MAX_SLIDERS; for the others ns = 1 only (the type
 *  itself).
 *  Returns NULL if type is NULL or ns is out of that range. Since 1.8. */
FRICREG_API const fricreg_element_type *fricreg_element_sliders(const fricreg_element_type *type,
                                                                size_t ns);

/** The type's name (static storage); NULL if type is NULL. Since 1.8. */
FRICREG_API const char *fricreg_element_name(const fricreg_element_type *type);

/** The number of components dim of u and f: 1, 2 or 3; 0 if type is NULL. Returns that
 *  number, not a status. Since 1.8. */
FRICREG_API int fricreg_element_dim(const fricreg_element_type *type);

/** The number of parameters nparams (the table at the top of this header); 0 if type is NULL.
 *  Returns that number, not a status. Since 1.8. */
FRICREG_API size_t fricreg_element_nparams(const fricreg_element_type *type);

/** The number of state variables nstate; 0 if type is NULL. Returns that number, not a
 *  status. Since 1.8. */
FRICREG_API size_t fricreg_element_nstate(const fricreg_element_type *type);

/** The number of sliders ns (1 but for the Iwan types); 0 if type is NULL. Returns that
 *  number, not a status. Since 1.8. */
FRICREG_API size_t fricreg_element_nsliders(const fricreg_element_type *type);

/** The state of an element at rest: every slider at w = 0.
 *
 *  params[nparams]  the element's parameters, checked as fricreg_element_eval checks them.
 *  state[nstate]    out: zeros. Written only on success.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if type, params or state is NULL; FRICREG_ENONFINITE if a
 *  parameter is NaN or infinite; FRICREG_EINVAL if one is out of its range (the top of this
 *  header). Since 1.8. */
FRICREG_API int fricreg_element_init(const fricreg_element_type *type, const double params[],
                                     double state[]);

/** One element's force, tangents and new state at the displacement u, from the old state: the
 *  return mapping at the top of this header.
 *
 *  params[nparams]  the parameters (the table at the top of this header).
 *  state_in[nstate] the state at the start of the increment.
 *  u[dim]           the relative displacement at the end of the increment (finite).
 *  f[dim]           out: the element's force, f_t (and N last for a normal type); the body
 *                   whose relative displacement is u feels -f (f enters the internal force
 *                   vector, as a spring's k u does).
 *  dfdu[dim*dim]    out, or NULL: the consistent tangent df_a/du_c at [dim a + c], row-major
 *                   (not symmetric for a normal type in slip: df_t/dg != dN/du_t = 0).
 *  dfdp[dim*nparams] out, or NULL: df_a/dp_j at [nparams a + j], row-major: for a slider in
 *                   stick df/dk_s = d_s, in slip df/db_s = n_s (df_t/dmu_s = N n_s); for a
 *                   normal type df/dn0 = (sum_slip mu_s n_s, 1), df/dkn = (g - gap) df/dn0 and
 *                   df/dgap = -kn df/dn0 while closed, 0 where open. At the stick/slip border
 *                   (k_s |d_s| = b_s) the stick side's, at lift-off (n0 + kn (g - gap) = 0)
 *                   the closed side's, and at a range's end (kn = 0, b_s or mu_s = 0) the
 *                   side inside it: one-sided there. The n0 and gap columns are the formula
 *                   n0 + kn (g - gap)'s, but a normal type takes only one of n0 and gap
 *                   nonzero (EINVAL otherwise): in the preload form (gap = 0, n0 != 0) the
 *                   gap column, and in the gap form (n0 = 0, gap != 0) the n0 column, have no
 *                   valid neighbour on either side, so no difference checks them; each is the
 *                   derivative along the other form (a gap h is the preload -kn h: df/dgap =
 *                   -kn df/dn0). With n0 = gap = 0 both are two-sided.
 *  state_out[nstate] out: the state at the end of the increment. May be state_in (the same
 *                   array, not a partial overlap); no other output may overlap an input.
 *
 *  Rounding: |f_t| <= sum_s b_s (times N) to 1e-12 of it and, where u - w falls below DBL_MIN
 *  (2.2e-308, where a norm keeps only absolute precision), to a few k_s times the smallest
 *  subnormal, 4.9e-324 (fuzz target fuzz_element).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if type, params, state_in, u, f or state_out is NULL;
 *  FRICREG_ENONFINITE if a parameter, state or u is NaN or infinite, or an intermediate
 *  overflows (u - w, n0 + kn (g - gap), a sum over the sliders: numbers near 1e308);
 *  FRICREG_EINVAL if a parameter is out of its range. Nothing is written on failure
 *  (fricreg_element_explain says why). Cost O(ns dim^2); no allocation; thread-safe.
 *  Since 1.8. */
FRICREG_API int fricreg_element_eval(const fricreg_element_type *type, const double params[],
                                     const double state_in[], const double u[], double f[],
                                     double dfdu[], double dfdp[], double state_out[]);

/** fricreg_element_eval at npoints points of one type at once: the same numbers bit for bit as
 *  npoints calls, for a host's integration points or a binding's arrays (one call across a
 *  language boundary in place of npoints).
 *
 *  Point i's arrays start at (row-major, contiguous, point after point):
 *  params[params_stride i]  its parameters[nparams]: params_stride 0 shares one set among all
 *                   points, params_stride >= nparams gives each point its own (nparams: a
 *                   table of npoints rows).
 *  state_in[nstate i], u[dim i]   its old state and displacement (the table's shapes:
 *                   (npoints, nstate) and (npoints, dim)).
 *  f[dim i]         out: its force.
 *  dfdu[dim dim i]  out, or NULL: its consistent tangent, row-major as eval's.
 *  dfdp[dim nparams i] out, or NULL: its derivatives in the parameters, as eval's.
 *  state_out[nstate i] out: its new state. May be state_in (the same array); no other output
 *                   may overlap an input.
 *  bad_point        out, or NULL: on failure, the first point whose inputs fail (npoints where
 *                   the failure is not a point's: a NULL array or the stride). Not written on
 *                   success.
 *
 *  Every point is checked before any output is written, so a failed call writes nothing but
 *  *bad_point; fricreg_element_explain on that point's inputs says why. Shared parameters
 *  (params_stride 0) are checked once a call. npoints = 0 does nothing and returns FRICREG_OK
 *  (the arrays may then be NULL).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if type, params, state_in, u, f or state_out is NULL
 *  (npoints > 0); FRICREG_EINVAL if params_stride is neither 0 nor >= nparams, or a point's
 *  parameter is out of its range; FRICREG_ENONFINITE as for fricreg_element_eval, at any
 *  point. Cost O(npoints ns dim^2); no allocation; thread-safe. Since 1.8. */
FRICREG_API int fricreg_element_eval_batch(const fricreg_element_type *type, size_t npoints,
                                           const double params[], size_t params_stride,
                                           const double state_in[], const double u[], double f[],
                                           double dfdu[], double dfdp[], double state_out[],
                                           size_t *bad_point);

/** The energies of the increment fricreg_element_eval makes on the same inputs, as a host
 *  reports them (Abaqus FRIC's SFD and SED; docs/hosts.md): the sliders' dissipation and the
 *  springs' stored energy, in the host's force times displacement units.
 *
 *      dissipated = sum_s f_s' . (w_s' - w_s),
 *      stored     = sum_s |f_s'|^2 / (2 k_s)  (+ N'^2 / (2 kn) for a normal type, kn > 0)
 *
 *  with w_s the state_in's slider positions, w_s' and f_s' the slider's position and force
 *  after the return mapping (the header's top; spring: f^2 / (2 k) stored, nothing
 *  dissipated). The slip happens at the force the increment ends on, so the dissipation is
 *  the return mapping's own (backward Euler; Simo & Hughes 1998, Ch. 1), never negative, and
 *  a closed 1-D loop whose increments reach its turning points dissipates exactly the
 *  closed form: 4 b (A - b/k) per cycle of amplitude A >= b/k for one slider, summed over the
 *  slipping sliders of an Iwan type. On opening (a normal type's lift-off) the tangential
 *  springs' energy is released with the memory reset: neither dissipated nor stored.
 *
 *  params, state_in, u  as for fricreg_element_eval.
 *  dissipated       out: the energy the sliders dissipate in the increment (>= 0).
 *  stored           out: the energy the springs hold at its end (>= 0).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if type, params, state_in, u, dissipated or stored is
 *  NULL; FRICREG_ENONFINITE, FRICREG_EINVAL as fricreg_element_eval, and FRICREG_ENONFINITE if
 *  an energy overflows (numbers near 1e154). Nothing is written on failure. Cost: one
 *  fricreg_element_eval without tangents, plus O(ns dim); no allocation; thread-safe.
 *  Since 1.8. */
FRICREG_API int fricreg_element_energy(const fricreg_element_type *type, const double params[],
                                       const double state_in[], const double u[],
                                       double *dissipated, double *stored);

/** Why fricreg_element_eval or fricreg_element_init fails on these inputs: the status that
 *  call returns, and a message naming the argument and its value.
 *
 *  Which call: state_in and u both given, eval's (params, state_in, u checked); both NULL,
 *  init's (params checked). One of them NULL is eval's call with that argument NULL:
 *  FRICREG_ENULL and "u is NULL (...)" or "state_in is NULL (...)", whatever the other inputs,
 *  as eval checks its NULLs first. f, dfdu, dfdp and state_out (init's state) are not
 *  arguments here: eval's FRICREG_ENULL for f or state_out NULL (stated there) is not judged.
 *
 *  params[nparams], state_in[nstate] (or NULL), u[dim] (or NULL): as for fricreg_element_eval.
 *  msg[len]  out, or NULL with len = 0: the message, NUL-terminated and cut to len - 1
 *            characters ("" on success): "<type>: <name> = <value> must be ... (params[j])" for
 *            a parameter out of its range, naming the one condition it fails.
 *
 *  Returns the status of that call: FRICREG_OK where it succeeds; FRICREG_ENULL if type or
 *  params is NULL ("type is NULL", "params is NULL") or one of state_in and u is;
 *  FRICREG_ENONFINITE, FRICREG_EINVAL as listed there. Since 1.8. */
FRICREG_API int fricreg_element_explain(const fricreg_element_type *type, const double params[],
                                        const double state_in[], const double u[], char *msg,
                                        size_t len);

/** Fill the ns sliders of an Iwan type from Segalman's four-parameter model (D. J. Segalman,
 *  J. Appl. Mech. 72 (2005) 752-760), by the rule of fricreg_iwan_set_segalman (the same
 *  numbers bit for bit): the macroslip force fs, the joint stiffness kt, the exponent chi and
 *  the delta's weight beta, on a grid whose smallest breakpoint is resolution phi_max.
 *
 *  k[ns], phi[ns]  out: the sliders' stiffnesses and slip forces, params[0 .. 2 ns - 1] of
 *                  iwan, iwan_2d or iwan_3d (iwan_normal's mu_s are phi_s / N at the normal force N
 *                  the model was fitted at). Written only on success.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if k or phi is NULL; FRICREG_ENONFINITE if a parameter is
 *  NaN or infinite, or a slider's k or phi is not finite (extreme parameters); FRICREG_EINVAL
 *  if ns = 0 or ns > FRICREG_ELEMENT_MAX_SLIDERS, fs <= 0, kt <= 0, chi <= -1 or chi > 1,
 *  beta < 0, beta > 0 with ns = 1, resolution outside (0, 1) where the grid has two points or
 *  more, or a slider's k underflows to 0. Since 1.8. */
FRICREG_API int fricreg_element_segalman(size_t ns, double fs, double kt, double chi, double beta,
                                         double resolution, double k[], double phi[]);

/** \} */

#ifdef __cplusplus
}
#endif

#endif
