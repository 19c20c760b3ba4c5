/* SPDX-License-Identifier: GPL-3.0-or-later */
/**
 * \file
 * fricreg_structure_elements.h — a structure's friction elements (joints) of fricreg_element.h's
 * types, and 1.x's per-kind setters and state getters (Jenkins, Iwan, 2-D, lift-off), wrappers of
 * the element table's.
 *
 * Part of fricreg_structure.h, which includes it (so does every header of the structure:
 * include either), split out by object since 1.9; the structure, its model and the
 * conventions are fricreg_structure.h's.
 */
#ifndef FRICREG_STRUCTURE_ELEMENTS_H
#define FRICREG_STRUCTURE_ELEMENTS_H

#include "fricreg_structure.h"

#ifdef __cplusplus
extern "C" {
#endif

/** \defgroup structure_elements Structure: friction elements (fricreg_structure_elements.h)
 *  \{ */

/** Add me friction elements of one type (fricreg_element.h: fricreg_element_lookup,
 *  fricreg_element_sliders, fricreg_element_at) beside those the structure holds, of any types:
 *  one structure may hold Jenkins, Iwan, 2-D, 3-D contact and lift-off elements together.
 *  Element i sees the dim = fricreg_element_dim(type) components u_i = J_i u, rows i dim ..
 *  i dim + dim - 1 of J[me dim * ndof] (row-major; in the type's order: the tangential
 *  components, then the normal displacement g of a type with a normal law), and pushes back
 *  with the type's force f_i = F(u_i; its sliders' state) of fricreg_element_eval, so the
 *  structure gets -J^T f. params[me np] holds each element's np = fricreg_element_nparams(type)
 *  parameters in the type's layout (fricreg_element.h: kt, mun; k[ns], phi[ns]; then kn, n0,
 *  gap). Units are the structure's: J dimensionless for displacement dofs, k in force per
 *  displacement, bounds in force.
 *
 *  Each step evaluates every element by its type's kernel, exactly as a host code's call of
 *  fricreg_element_eval would, inside the step's Newton: Newmark and HHT-alpha solve the
 *  elements' forces implicitly on the kernels' consistent tangents (the condensed Newton of
 *  fricreg_structure_set_jenkins, or one Newton with the contacts beside contacts of bound > 0),
 *  central difference and GSL's steppers explicitly. The elements' dissipation and springs
 *  enter the energy balance as fricreg_structure_set_jenkins's (FRICREG_SVALUE_JENKINS); their
 *  states and forces are read back by fricreg_structure_get_elements. A structure of one type
 *  gives the per-kind setters' answers bit for bit (those setters are this call's wrappers).
 *
 *  Copied. Adding elements is a model change, as a setter's: every element, the held ones too,
 *  starts again with its sliders at 0 and its dissipation at 0, and K_eff is factored again at
 *  the next step. me = 0 adds nothing (J and params may then be NULL). Allocates
 *  O(nc^2 + nnz(J)), nc the elements' coordinates, all of them. Since 1.8 (FRICREG_1.8).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL (s, type, or J or params with me > 0); FRICREG_ESIZE if
 *  ndof is not the structure's; FRICREG_EINVAL if an element's parameters are out of range
 *  (the message names the element and says why, as fricreg_element_explain), a row of J is
 *  zero, the elements would number more than 2^24, or the call comes from the observer;
 *  FRICREG_ENONFINITE (an entry of J or params); FRICREG_ENOMEM. On failure the elements in
 *  force are unchanged. */
FRICREG_API int fricreg_structure_add_elements(fricreg_structure *s,
                                               const fricreg_element_type *type, size_t me,
                                               size_t ndof, const double J[],
                                               const double params[]);

/** Remove every element (fricreg_structure_add_elements, the per-kind setters). A model change:
 *  K_eff is factored again at the next step. Since 1.8 (FRICREG_1.8).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_EINVAL from the observer. */
FRICREG_API int fricreg_structure_clear_elements(fricreg_structure *s);

/** The number of elements the structure holds, of all types (0 for s = NULL). Since 1.8
 *  (FRICREG_1.8). */
FRICREG_API size_t fricreg_structure_element_count(const fricreg_structure *s);

/** Copy the elements' forces, states and dissipations at the current time, in the order they
 *  were added: f[sum dim_i], element i's dim_i = fricreg_element_dim components (tangential
 *  forces, then the normal force N of a type with a normal law; the force the element exerts,
 *  the structure receiving -J^T f); state[sum nstate_i], element i's committed state as
 *  fricreg_element_eval takes it (its sliders' positions, nstate_i = fricreg_element_nstate);
 *  D[me] each element's dissipation since fricreg_structure_set_initial (force times
 *  displacement). Any one of f, state, D may be NULL. Since 1.8 (FRICREG_1.8).
 *  Returns FRICREG_OK; FRICREG_ENULL (s, or all three arrays); FRICREG_ESIZE if me is not
 *  fricreg_structure_element_count(s). */
FRICREG_API int fricreg_structure_get_elements(const fricreg_structure *s, size_t me, double f[],
                                               double state[], double D[]);

/** Attach me Jenkins elements (fricreg_jenkins.h's 1-D element: a spring kt in series with a
 *  Coulomb slider of bound mun) to the structure, on the rows of the element matrix
 *  Je[me*ndof] (row-major; Je[i*ndof + k] = d q_i / d u_k, dimensionless for displacement
 *  DOFs). Element i sees the relative displacement q_i = (J_e u)_i and its force
 *  fe_i = kt_i (q_i - w_i), |fe_i| <= mun_i, by the exact return mapping from its committed
 *  slider position w_i (fricreg_jenkins_trial), acts on the structure as -J_e^T fe:
 *
 *      M u'' + C u' + K u + J_e^T fe(J_e u) = p(t) - M r a_g(t) + J^T f.
 *
 *  The sliders are committed at the end of each accepted step. Newmark and HHT-alpha solve the
 *  elements implicitly: Newton on their forces at the step's end with their exact tangent (kt
 *  sticking, 0 slipping), condensed on the elements' coordinates through
 *  E = J_e K_eff^-1 J_e^T (me x me, dense, formed with K_eff's factor: me solves per dt), GSL's
 *  pivoted QR of I + (1 + alpha) beta dt^2 diag(tangent) E per iteration and a line search
 *  halving the direction until the residual's 2-norm decreases (fricreg_structure_set_newton's
 *  tolerance on max |fe - F(q)| times the step's force scale, its iterations counted with the
 *  contacts'). The forces the step ends on, which act on the structure and the getters report,
 *  are Newton's (within that tolerance of kt (q - w)) held to the bound: |fe_i| <= mun_i (with
 *  a normal law mu N_i, N_i >= 0; a 2-D element's radially) to rounding (since 1.7). The
 *  central difference evaluates them at the explicit displacement u(t + dt), its step guard
 *  reading the largest frequency of M^-1 (K + J_e^T diag(kt) J_e) (all elements sticking).
 *  fricreg_structure_run_ode refuses elements (FRICREG_EINVAL).
 *
 *  Elements beside friction contacts: where some contact's bound is > 0, Newmark and
 *  HHT-alpha solve the contacts' forces f and the elements' forces fe (with a normal law also
 *  N; nc of them) together, one Newton over the stacked m + nc unknowns on the exact tangents
 *  of both laws, coupled through [J; J_e] K_eff^-1 [J; J_e]^T (the cross block
 *  J K_eff^-1 J_e^T is formed with E, by the same nc solves per dt; Quinn's law (4) and the
 *  return mapping as above), dense: GSL's pivoted QR of the (m + nc) x (m + nc) Newton matrix
 *  per iteration, O((m + nc)^3) (for the few contacts and joints of a jointed structure), and
 *  O((m + nc)^2) memory allocated at the first such step after a model change (FRICREG_ENOMEM
 *  from the step if it cannot be). The stopping rule and the line search are the contacts'
 *  (the stop of a slipping contact at zdot = 0, law (4)'s stick guess with a diagonal W, the
 *  direction halved until the residuals' 2-norm decreases); the step converges when both the
 *  contacts' residual and max |fe - F(q)| are within the tolerance times the step's force
 *  scale (or the elements' largest force at t if larger). The central difference evaluates the
 *  elements at u(t + dt) and the contacts' law then sees their forces. With every bound 0 (a
 *  structure with elements only keeps fricreg_structure_create's one contact, bound 0) the
 *  step is the elements' alone, as without contacts, and without elements the contacts'.
 *
 *  Energy: the elements' springs' energy fe^2/(2 kt) is part of FRICREG_SVALUE_STRAIN, their
 *  dissipation, sum over steps of (w(t+dt) - w(t)) (fe(t) + fe(t+dt))/2 (the trapezoidal work
 *  less the springs' change: exact for average-acceleration Newmark), is
 *  FRICREG_SVALUE_JENKINS and is taken out of the balance's residual.
 *
 *  Copied. me = 0 removes the elements (Je, kt, mun may then be NULL). Setting elements
 *  replaces the previous ones, with every slider at w = 0 and their dissipation at 0, as does
 *  fricreg_structure_set_initial; the next step starts from the return mapping at J_e u.
 *  Like a model setter, K_eff is factored again at the next step. Allocates O(me^2 + nnz(J_e)).
 *  Since 1.6 (FRICREG_1.6). Since 1.8 this and the other per-kind setters (_iwan,
 *  _jenkins_normal, _iwan_normal, _jenkins_2d, _jenkins_2d_normal, the _csr twins) are thin
 *  wrappers: fricreg_structure_clear_elements, then fricreg_structure_add_elements with the
 *  kind's type ("jenkins", "iwan", "jenkins_normal", "iwan_normal", "jenkins_2d",
 *  "contact_3d"), bit for bit; new code may call those, which also mix types.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL (s, or Je, kt or mun with me > 0); FRICREG_ESIZE if ndof
 *  is not the structure's; FRICREG_EINVAL if me > 2^26, a row of J_e is zero, a kt_i <= 0 or
 *  a mun_i < 0, or the call comes from the observer; FRICREG_ENONFINITE (an entry of Je, kt or
 *  mun); FRICREG_ENOMEM. On failure the elements in force are unchanged.
 *  \deprecated Since 1.9, a wrapper kept for the ABI: new code calls
 *  fricreg_structure_add_elements (the equivalence bit for bit: docs/joints.md, "The per-kind
 *  setters"). */
FRICREG_API int fricreg_structure_set_jenkins(fricreg_structure *s, size_t me, size_t ndof,
                                              const double Je[], const double kt[],
                                              const double mun[]);

/** The same with J_e from compressed sparse rows: rowptr[me + 1], colind[nnz], values[nnz],
 *  flags FRICREG_SPARSE_ONE_BASED or 0 (as fricreg_structure_set_contacts_csr: the triangle
 *  flags are refused; duplicates summed). Since 1.6 (FRICREG_1.6).
 *  Returns FRICREG_OK; FRICREG_ENULL (s, kt, mun, rowptr, or colind or values with nnz > 0);
 *  FRICREG_ESIZE; FRICREG_EINVAL (flags, pointers, indices, a zero row, kt_i <= 0, mun_i < 0,
 *  me > 2^26, from the observer); FRICREG_ENONFINITE; FRICREG_ENOMEM, as
 *  fricreg_structure_set_jenkins.
 *  \deprecated Since 1.9, a wrapper kept for the ABI: new code calls
 *  fricreg_structure_add_elements (the equivalence bit for bit: docs/joints.md, "The per-kind
 *  setters"). */
FRICREG_API int fricreg_structure_set_jenkins_csr(fricreg_structure *s, size_t me, size_t ndof,
                                                  int flags, const int64_t rowptr[],
                                                  const int64_t colind[], const double values[],
                                                  const double kt[], const double mun[]);

/** Attach me 2-D Jenkins elements (fricreg_jenkins.h's element of dim = 2: a tangential
 *  spring kt in series with an isotropic Coulomb slider of bound mun, the friction disk
 *  |f| <= mun) to the structure. Element i sees the 2-D relative displacement
 *  q_i = ((J_e u)_2i, (J_e u)_2i+1), rows 2i and 2i + 1 of Je[2 me * ndof] (row-major;
 *  dimensionless for displacement DOFs), and pushes back with f_i = kt_i (q_i - w_i),
 *  |f_i| <= mun_i, by the exact radial return from its committed slider w_i
 *  (fricreg_jenkins_trial with dim = 2; Simo & Hughes 1998, Ch. 3); the structure gets
 *  -J_e^T f with f[2 me] stacked as q.
 *
 *  Everything else is fricreg_structure_set_jenkins's with 2 me coordinates: Newmark and
 *  HHT-alpha solve the forces implicitly, the condensed Newton on E = J_e K_eff^-1 J_e^T
 *  (2 me x 2 me) with the consistent tangent block diagonal, each element's 2x2 block kt I
 *  sticking and (mun/|q - w_c|)(I - n n^T) slipping (n the slip direction), in
 *  I + (1 + alpha) beta dt^2 T E; beside contacts of bound > 0 the joint Newton over m + 2 me
 *  unknowns with the same blocks; the central difference evaluates the elements at
 *  u(t + dt), its guard on K + J_e^T diag(kt, kt, ...) J_e; fricreg_structure_run_ode refuses
 *  them. Energy: the springs' |f|^2/(2 kt) in FRICREG_SVALUE_STRAIN, the dissipation, sum over
 *  steps of (w(t+dt) - w(t)) . (f(t) + f(t+dt))/2, in FRICREG_SVALUE_JENKINS (the balance
 *  closes as in 1-D). The state: fricreg_structure_get_jenkins_2d_state.
 *  An element whose motion stays on one axis is the 1-D element of set_jenkins on that row.
 *  Setting 2-D elements replaces the elements in force (Jenkins, Iwan or with a normal law).
 *
 *  me           number of elements (0 removes them: Je, kt, mun may then be NULL); 2 me <= 2^26.
 *  ndof         must be the structure's.
 *  Je[2me*ndof] row-major, two rows per element.
 *  kt[me]       stiffnesses > 0, finite (force per unit of q).
 *  mun[me]      slip force magnitudes >= 0, finite (force units).
 *
 *  Copied; every slider at w = 0 and the dissipation at 0, as after
 *  fricreg_structure_set_initial. Allocates O(me^2 + nnz(J_e)). Since 1.6 (FRICREG_1.6).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL (s, or Je, kt or mun with me > 0); FRICREG_ESIZE if ndof
 *  is not the structure's; FRICREG_EINVAL if 2 me > 2^26, a row of J_e is zero (either axis of
 *  an element), a kt_i <= 0 or a mun_i < 0, or the call comes from the observer;
 *  FRICREG_ENONFINITE (an entry of Je, kt or mun); FRICREG_ENOMEM. On failure the elements in
 *  force are unchanged.
 *  \deprecated Since 1.9, a wrapper kept for the ABI: new code calls
 *  fricreg_structure_add_elements (the equivalence bit for bit: docs/joints.md, "The per-kind
 *  setters"). */
FRICREG_API int fricreg_structure_set_jenkins_2d(fricreg_structure *s, size_t me, size_t ndof,
                                                 const double Je[], const double kt[],
                                                 const double mun[]);

/** The same with J_e (2 me rows) from compressed sparse rows: rowptr[2 me + 1], colind[nnz],
 *  values[nnz], flags FRICREG_SPARSE_ONE_BASED or 0, as fricreg_structure_set_jenkins_csr.
 *  Since 1.6 (FRICREG_1.6).
 *  Returns FRICREG_OK; FRICREG_ENULL (s, kt, mun, rowptr, or colind or values with nnz > 0);
 *  FRICREG_ESIZE; FRICREG_EINVAL (flags, pointers, indices, a zero row, kt_i <= 0, mun_i < 0,
 *  2 me > 2^26, from the observer); FRICREG_ENONFINITE; FRICREG_ENOMEM, as
 *  fricreg_structure_set_jenkins_2d.
 *  \deprecated Since 1.9, a wrapper kept for the ABI: new code calls
 *  fricreg_structure_add_elements (the equivalence bit for bit: docs/joints.md, "The per-kind
 *  setters"). */
FRICREG_API int fricreg_structure_set_jenkins_2d_csr(fricreg_structure *s, size_t me, size_t ndof,
                                                     int flags, const int64_t rowptr[],
                                                     const int64_t colind[], const double values[],
                                                     const double kt[], const double mun[]);

/** Copy the 2-D Jenkins elements' state (fricreg_structure_set_jenkins_2d, _2d_normal) at the
 *  current time: their forces f[2 me] (force units, f_i = kt_i (q_i - w_i) to Newton's
 *  tolerance, |f_i| <= mun_i (mu N_i under the normal law) to rounding,
 *  element i's (x, y) at f[2i], f[2i + 1] as the rows of J_e; -J_e^T f on the structure; 0
 *  before the first step), the committed slider positions w[2 me] (the units of q, laid out as
 *  f) and the energy each has dissipated since set_initial (or since set_jenkins_2d) D[me]
 *  (energy units, their sum FRICREG_SVALUE_JENKINS). Any of f, w, D may be NULL, not all
 *  three. Since 1.6 (FRICREG_1.6).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE if me is not the number of elements set;
 *  FRICREG_EINVAL (me > 0) if they are 1-D elements (fricreg_structure_get_jenkins_state and
 *  fricreg_structure_get_iwan_state read those), or not all 2-D elements of one slider
 *  (fricreg_structure_get_elements reads any set). */
FRICREG_API int fricreg_structure_get_jenkins_2d_state(const fricreg_structure *s, size_t me,
                                                       double f[], double w[], double D[]);

/** Copy the Jenkins elements' state at the current time: their forces f[me] (force units,
 *  fe = kt (q - w) on the element, -J_e^T fe on the structure; 0 before the first step), the
 *  committed slider positions w[me] (the units of q) and the energy each has dissipated since
 *  set_initial (or since set_jenkins) D[me] (energy units, as FRICREG_SVALUE_JENKINS). Any of
 *  f, w, D may be NULL, not all three. Since 1.6 (FRICREG_1.6).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE if me is not the number of elements set,
 *  or w is not NULL and the elements are Iwan elements of ns > 1 sliders
 *  (fricreg_structure_get_iwan_state reads those); FRICREG_EINVAL (me > 0) if f or w is not
 *  NULL and the elements are 2-D (fricreg_structure_get_jenkins_2d_state reads those; D alone
 *  is read here too) or of several dimensions (fricreg_structure_add_elements's mixes:
 *  fricreg_structure_get_elements reads any set). */
FRICREG_API int fricreg_structure_get_jenkins_state(const fricreg_structure *s, size_t me,
                                                    double f[], double w[], double D[]);

/** Attach me Iwan elements (fricreg_iwan.h's 1-D element: ns Jenkins sliders in parallel) to
 *  the structure, on the rows of Je[me*ndof] as fricreg_structure_set_jenkins. Element i sees
 *  q_i = (J_e u)_i and pushes back with the sum of its sliders' forces,
 *
 *      fe_i = sum_s f_is,   f_is = k_is (q_i - w_is),   |f_is| <= phi_is,
 *
 *  each slider by the exact return mapping from its committed position w_is (the element of
 *  fricreg_iwan_set_params and fricreg_hb_set_iwan); the structure gets -J_e^T fe. An element
 *  of ns sliders is ns Jenkins elements on copies of its row, but the step's Newton keeps me
 *  unknowns: an element's tangent is the sum of its sticking sliders' k. Everything else
 *  (Newmark/HHT implicit, central difference with the step guard on K + J_e^T diag(sum_s k) J_e,
 *  run_ode refusing elements, friction contacts beside them solved in the same step, the energy with the
 *  sliders' springs in FRICREG_SVALUE_STRAIN and their dissipation, summed over an element's
 *  sliders, in FRICREG_SVALUE_JENKINS) is as for fricreg_structure_set_jenkins, which is this
 *  call with ns = 1 (k = kt, phi = mun). Setting Iwan elements replaces the elements in force,
 *  Jenkins or Iwan.
 *
 *  me         number of elements (0 removes them: Je, k, phi may then be NULL).
 *  ndof       must be the structure's.
 *  Je         [me*ndof] row-major, as fricreg_structure_set_jenkins.
 *  ns         sliders per element, 1 to FRICREG_ELEMENT_MAX_SLIDERS (1024; since 1.8, where
 *             the elements became the "iwan" type's: fricreg_structure_add_elements); me ns
 *             <= 2^26.
 *  k[me*ns]   stiffnesses > 0 (finite), force per unit of q; element i's slider s at
 *             k[i ns + s] (row-major; Fortran: a (ns, me) array).
 *  phi[me*ns] slip forces >= 0 (finite), force units, laid out as k (Segalman's
 *             discretization: fricreg_iwan_set_segalman then fricreg_iwan_get_params).
 *
 *  Copied; every slider at w = 0 and the dissipation at 0, as after
 *  fricreg_structure_set_initial. Allocates O(me^2 + me ns + nnz(J_e)). Since 1.6
 *  (FRICREG_1.6).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL (s, or Je, k or phi with me > 0); FRICREG_ESIZE if ndof is
 *  not the structure's; FRICREG_EINVAL if ns = 0 or ns > FRICREG_ELEMENT_MAX_SLIDERS with
 *  me > 0, me ns > 2^26, a row of J_e is zero, a k <= 0 or a phi < 0, or the call comes from the observer; FRICREG_ENONFINITE (an
 *  entry of Je, k or phi); FRICREG_ENOMEM. On failure the elements in force are unchanged.
 *  \deprecated Since 1.9, a wrapper kept for the ABI: new code calls
 *  fricreg_structure_add_elements (the equivalence bit for bit: docs/joints.md, "The per-kind
 *  setters"). */
FRICREG_API int fricreg_structure_set_iwan(fricreg_structure *s, size_t me, size_t ndof,
                                           const double Je[], size_t ns, const double k[],
                                           const double phi[]);

/** The same with J_e from compressed sparse rows: rowptr[me + 1], colind[nnz], values[nnz],
 *  flags FRICREG_SPARSE_ONE_BASED or 0, as fricreg_structure_set_jenkins_csr. Since 1.6
 *  (FRICREG_1.6).
 *  Returns FRICREG_OK; FRICREG_ENULL (s, k, phi, rowptr, or colind or values with nnz > 0);
 *  FRICREG_ESIZE; FRICREG_EINVAL (flags, pointers, indices, a zero row, ns = 0 or above
 *  FRICREG_ELEMENT_MAX_SLIDERS, k <= 0, phi < 0, me ns > 2^26, from the observer); FRICREG_ENONFINITE; FRICREG_ENOMEM, as
 *  fricreg_structure_set_iwan.
 *  \deprecated Since 1.9, a wrapper kept for the ABI: new code calls
 *  fricreg_structure_add_elements (the equivalence bit for bit: docs/joints.md, "The per-kind
 *  setters"). */
FRICREG_API int fricreg_structure_set_iwan_csr(fricreg_structure *s, size_t me, size_t ndof,
                                               int flags, const int64_t rowptr[],
                                               const int64_t colind[], const double values[],
                                               size_t ns, const double k[], const double phi[]);

/** Copy the elements' state at the current time (Iwan or Jenkins elements, the latter with
 *  ns = 1): their forces f[me] (force units, the sum of the sliders' forces on the element,
 *  -J_e^T f on the structure; 0 before the first step), the committed slider positions
 *  w[me*ns] (row-major, element i's slider s at w[i ns + s], the units of q) and the energy
 *  each element has dissipated since set_initial (or since the elements were set) D[me]
 *  (energy units, their sum FRICREG_SVALUE_JENKINS). Any of f, w, D may be NULL, not all
 *  three. Since 1.6 (FRICREG_1.6).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE if me is not the number of elements set,
 *  or (me > 0) ns is not their sliders per element; FRICREG_EINVAL (me > 0) if the elements
 *  are 2-D (fricreg_structure_get_jenkins_state reads those) or of several dimensions
 *  (fricreg_structure_get_elements reads any set). */
FRICREG_API int fricreg_structure_get_iwan_state(const fricreg_structure *s, size_t me, size_t ns,
                                                 double f[], double w[], double D[]);

/** Attach me Jenkins elements with a normal load and lift-off (fricreg_jenkins_set_normal's
 *  law): element i has a tangential row i of Je[me*ndof] and a normal row i of Jn[me*ndof]
 *  (both row-major, as fricreg_structure_set_jenkins's Je), sees q_i = (J_e u)_i and the
 *  normal relative displacement g_i = (J_n u)_i (positive closing), carries the normal force
 *
 *      N_i = max(0, n0_i + kn_i g_i)
 *
 *  and the tangential force fe_i = kt_i (q_i - w_i), |fe_i| <= mu_i N_i, by
 *  fricreg_jenkins_trial_normal's return mapping from its committed slider w_i; while the
 *  element is separated (n0 + kn g < 0) fe_i = 0 and the slider follows q (its memory reset).
 *  Both forces act on the structure:
 *
 *      M u'' + C u' + K u + J_e^T fe(J_e u, J_n u) + J_n^T N(J_n u) = p(t) - M r a_g(t) + J^T f,
 *
 *  so at rest in contact the structure carries -J_n^T n0. Newmark and HHT-alpha solve the
 *  elements as fricreg_structure_set_jenkins does, on 2 me unknowns (fe, N) condensed through
 *  E = J K_eff^-1 J^T with J = (J_e over J_n), their exact tangent including dfe/dg = mu kn
 *  sign(fe) while slipping and dN/dg = kn while closed; the central difference evaluates them
 *  at u(t + dt), its step guard reading K + J_e^T diag(kt) J_e + J_n^T diag(kn) J_n. Energy:
 *  N^2/(2 kn) is part of FRICREG_SVALUE_STRAIN and the sliders' dissipation of
 *  FRICREG_SVALUE_JENKINS; the balance is exact over steps in which every element stays closed
 *  or open (a step that opens or closes one leaves a residual of the order of kn times the
 *  step's normal overshoot squared, and FRICREG_WARN_ENERGY is then not judged). The
 *  contacts beside them (one Newton over f, fe and N), run_ode and the observer are
 *  fricreg_structure_set_jenkins's. Copied; every slider at w = 0; replaces the elements in
 *  force. me = 0 removes them (the arrays may then be NULL). Since 1.6 (FRICREG_1.6).
 *
 *  kt[me]  tangential stiffness > 0 (finite), force per unit of q.
 *  mu[me]  friction coefficient >= 0 (finite).
 *  n0[me]  normal force at g = 0 (finite, force units; < 0: open at g = 0).
 *  kn[me]  normal stiffness > 0 (finite), force per unit of g.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL (s, or Je, Jn, kt, mu, n0 or kn with me > 0);
 *  FRICREG_ESIZE if ndof is not the structure's; FRICREG_EINVAL if me > 2^26, a row of J_e or
 *  J_n is zero, a kt <= 0, mu < 0 or kn <= 0, or the call comes from the observer;
 *  FRICREG_ENONFINITE (an entry of Je, Jn, kt, mu, n0 or kn); FRICREG_ENOMEM. On failure the
 *  elements in force are unchanged.
 *  \deprecated Since 1.9, a wrapper kept for the ABI: new code calls
 *  fricreg_structure_add_elements (the equivalence bit for bit: docs/joints.md, "The per-kind
 *  setters"). */
FRICREG_API int fricreg_structure_set_jenkins_normal(fricreg_structure *s, size_t me, size_t ndof,
                                                     const double Je[], const double Jn[],
                                                     const double kt[], const double mu[],
                                                     const double n0[], const double kn[]);

/** Attach me Iwan elements with a normal load and lift-off: element i is ns sliders in
 *  parallel on row i of Je[me*ndof] (as fricreg_structure_set_iwan), each bounded by its own
 *  friction coefficient times the element's normal force, which the normal row i of
 *  Jn[me*ndof] gives as fricreg_structure_set_jenkins_normal's does:
 *
 *      N_i = max(0, n0_i + kn_i g_i),   g_i = (J_n u)_i (positive closing),
 *      fe_i = sum_s k_is (q_i - w_is),   |k_is (q_i - w_is)| <= mu_is N_i,
 *
 *  each slider by the exact return mapping from its committed position (the slider of
 *  fricreg_iwan_trial_normal with phi_s = mu_s n0 at the reference N0 = n0); while the
 *  element is separated (n0 + kn g < 0) fe_i = 0, N_i = 0 and every slider follows q (the
 *  tangential memory reset). Both forces act on the structure, -J_e^T fe - J_n^T N. The step
 *  keeps 2 me unknowns (fe, N) whatever ns is: the exact tangent of an element is, on (q, g),
 *
 *      [sum of the sticking sliders' k,   kn sum of the slipping sliders' mu sign(f_s)]
 *      [0,                                kn (closed)                                ]
 *
 *  and everything else (the schemes, the contacts beside the elements, the central
 *  difference's step guard on K + J_e^T diag(sum_s k) J_e + J_n^T diag(kn) J_n, run_ode
 *  refusing elements, the energy: the sliders' springs and N^2/(2 kn) in
 *  FRICREG_SVALUE_STRAIN, their dissipation in FRICREG_SVALUE_JENKINS, exact over steps in
 *  which every element stays closed or open) is fricreg_structure_set_jenkins_normal's, which
 *  is this call with ns = 1 (bit for bit). The state: fricreg_structure_get_iwan_state and
 *  fricreg_structure_get_normal_forces. Copied; every slider at w = 0; replaces the elements
 *  in force. me = 0 removes them (the arrays may then be NULL). Since 1.7 (FRICREG_1.7).
 *
 *  me          number of elements; me ns <= 2^26.
 *  ndof        must be the structure's.
 *  Je[me*ndof] row-major, one tangential row per element.
 *  Jn[me*ndof] row-major, one normal row per element.
 *  ns          sliders per element, 1 to FRICREG_ELEMENT_MAX_SLIDERS (1024, since 1.8).
 *  k[me*ns]    slider stiffnesses > 0 (finite), force per unit of q; element i's slider s at
 *              k[i ns + s] (Fortran: a (ns, me) array).
 *  mu[me*ns]   slider friction coefficients >= 0 (finite, nondimensional), laid out as k; the
 *              element's slip force at N is N sum_s mu_s (an Iwan element's slip forces phi_s
 *              at the normal force N0 are mu_s = phi_s / N0).
 *  n0[me]      normal force at g = 0 (finite, force units; < 0: open at g = 0, a gap -n0/kn).
 *  kn[me]      normal stiffness > 0 (finite), force per unit of g.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL (s, or Je, Jn, k, mu, n0 or kn with me > 0);
 *  FRICREG_ESIZE if ndof is not the structure's; FRICREG_EINVAL if ns = 0 or
 *  ns > FRICREG_ELEMENT_MAX_SLIDERS with me > 0, me ns > 2^26, a row of J_e or J_n is zero, a k <= 0, mu < 0 or kn <= 0, or the call comes
 *  from the observer; FRICREG_ENONFINITE (an entry of Je, Jn, k, mu, n0 or kn);
 *  FRICREG_ENOMEM. On failure the elements in force are unchanged.
 *  \deprecated Since 1.9, a wrapper kept for the ABI: new code calls
 *  fricreg_structure_add_elements (the equivalence bit for bit: docs/joints.md, "The per-kind
 *  setters"). */
FRICREG_API int fricreg_structure_set_iwan_normal(fricreg_structure *s, size_t me, size_t ndof,
                                                  const double Je[], const double Jn[], size_t ns,
                                                  const double k[], const double mu[],
                                                  const double n0[], const double kn[]);

/** Attach me 3-D contact elements: 2-D Jenkins elements with a normal load and lift-off (the
 *  element of fricreg_jenkins_create(2, ...) with fricreg_jenkins_set_normal's law; tmdsimpy's
 *  3-D contact element). Element i sees the tangential relative displacement
 *  q_i = ((J_e u)_2i, (J_e u)_2i+1), rows 2i and 2i + 1 of Je[2 me * ndof] (the tangential
 *  plane's x and y, as fricreg_structure_set_jenkins_2d's Je), and the normal relative
 *  displacement g_i = (J_n u)_i, row i of Jn[me * ndof] (positive closing; both row-major,
 *  dimensionless for displacement DOFs). It carries the normal force and the tangential force
 *
 *      N_i = max(0, n0_i + kn_i g_i),
 *      f_i = kt_i (q_i - w_i),  |f_i| <= mu_i N_i  (isotropic Coulomb: the friction disk),
 *
 *  f_i by the radial return from its committed slider w_i (fricreg_jenkins_trial_normal with
 *  dim = 2; Simo & Hughes 1998, Ch. 3). While the element is separated (n0 + kn g < 0) f_i = 0,
 *  N_i = 0 and the slider follows q (w = q: the tangential memory reset), so that on
 *  re-contact the spring starts unloaded from where the surfaces meet again (a stick unless
 *  the step's own tangential motion exceeds mu N / kt). One convention for the normal law: the
 *  preload n0 at g = 0; a gap d is n0 = -kn d (open until g reaches d). Both forces act on the
 *  structure, -J_e^T f - J_n^T N, as for fricreg_structure_set_jenkins_normal.
 *
 *  The element's coordinates are the 2 me tangential rows, then the me normal rows
 *  (E = J K_eff^-1 J^T, J = J_e over J_n, 3 me x 3 me), and the exact tangent T is, per
 *  element on its (x, y, n) coordinates,
 *
 *      stick:  [kt I   0 ]    slip:  [(mu N/|d|)(I - n n^T)   mu kn n]    open:  0
 *              [0     kn ]           [0                       kn     ]
 *
 *  (d = q - w_c, n = d/|d| the slip direction; at n0 + kn g = 0 exactly the contact counts as
 *  closed with bound 0), in the Newton matrix I + (1 + alpha) beta dt^2 T E of Newmark and
 *  HHT-alpha, and beside contacts of bound > 0 in the joint Newton over m + 3 me unknowns. The
 *  central difference evaluates the elements at u(t + dt), its step guard reading
 *  K + J_e^T diag(kt, kt, ...) J_e + J_n^T diag(kn) J_n; fricreg_structure_run_ode refuses
 *  them. Energy as fricreg_structure_set_jenkins_normal's: |f|^2/(2 kt) + N^2/(2 kn) in
 *  FRICREG_SVALUE_STRAIN, the sliders' dissipation (w(t+dt) - w(t)) . (f(t) + f(t+dt))/2 in
 *  FRICREG_SVALUE_JENKINS; exact over steps in which every element stays closed or open.
 *  The state: fricreg_structure_get_jenkins_2d_state (f[2 me], w[2 me], D[me]) and
 *  fricreg_structure_get_normal_forces (N[me]). A closed element with kn g = 0 whose motion
 *  stays on one axis is the 1-D element of set_jenkins on that row, mun = mu n0. Copied;
 *  every slider at w = 0; replaces the elements in force. me = 0 removes them (the arrays may
 *  then be NULL). Since 1.7 (FRICREG_1.7).
 *
 *  me           number of elements; 2 me <= 2^26.
 *  ndof         must be the structure's.
 *  Je[2me*ndof] row-major, two tangential rows per element (x, y).
 *  Jn[me*ndof]  row-major, one normal row per element.
 *  kt[me]       tangential stiffness > 0 (finite), force per unit of q.
 *  mu[me]       friction coefficient >= 0 (finite, nondimensional).
 *  n0[me]       normal force at g = 0 (finite, force units; < 0: open at g = 0, a gap -n0/kn).
 *  kn[me]       normal stiffness > 0 (finite), force per unit of g.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL (s, or Je, Jn, kt, mu, n0 or kn with me > 0);
 *  FRICREG_ESIZE if ndof is not the structure's; FRICREG_EINVAL if 2 me > 2^26, a row of J_e
 *  (either axis) or of J_n is zero, a kt <= 0, mu < 0 or kn <= 0, or the call comes from the
 *  observer; FRICREG_ENONFINITE (an entry of Je, Jn, kt, mu, n0 or kn); FRICREG_ENOMEM. On
 *  failure the elements in force are unchanged.
 *  \deprecated Since 1.9, a wrapper kept for the ABI: new code calls
 *  fricreg_structure_add_elements (the equivalence bit for bit: docs/joints.md, "The per-kind
 *  setters"). */
FRICREG_API int fricreg_structure_set_jenkins_2d_normal(fricreg_structure *s, size_t me,
                                                        size_t ndof, const double Je[],
                                                        const double Jn[], const double kt[],
                                                        const double mu[], const double n0[],
                                                        const double kn[]);

/** Copy the normal forces N[me] (force units, max(0, n0 + kn g), 0 while separated) of the
 *  elements of fricreg_structure_set_jenkins_normal (or _2d_normal) at the current time (0
 *  before the first step); their tangential forces, sliders and dissipation are
 *  fricreg_structure_get_jenkins_state's (_2d_state's). Since 1.6 (FRICREG_1.6).
 *  Returns FRICREG_OK; FRICREG_ENULL if s or N is NULL; FRICREG_ESIZE if me is not the number
 *  of elements set; FRICREG_EINVAL if they, or some of them (fricreg_structure_add_elements's
 *  mixes: fricreg_structure_get_elements), have no normal law. */
FRICREG_API int fricreg_structure_get_normal_forces(const fricreg_structure *s, size_t me,
                                                    double N[]);

/** \} */

#ifdef __cplusplus
}
#endif

#endif /* FRICREG_STRUCTURE_ELEMENTS_H */
