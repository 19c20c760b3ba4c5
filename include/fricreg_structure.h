/* SPDX-License-Identifier: GPL-3.0-or-later */
/**
 * \file
 * fricreg_structure.h — a linear structure with friction contacts, integrated by Newmark or
 * HHT-alpha with the friction implicit (Newton on the exact tangent), by explicit central
 * difference, or by any of GSL's steppers (fricreg_structure_run_ode).
 *
 *     M u'' + C u' + K u = p(t) - M r a_g(t) + J^T f,      zdot = J u'
 *
 * u[ndof] are the structure's displacements, M, C, K its mass, damping and stiffness
 * matrices, p(t) an external load, r the influence vector of a ground acceleration a_g(t), J
 * the m x ndof contact matrix and f[m] the friction forces, given by a fricreg context
 * (fricreg.h) from the contact velocities zdot = J u' and the free contact accelerations
 * a_free = J M^-1 (p - M r a_g - C u' - K u), with the Delassus matrix W = J M^-1 J^T. The
 * object forms W and a_free itself; coupled contacts (W not diagonal) use the consistent
 * near-stick law (FRICREG_PARTITION_CONSISTENT).
 *
 * The model is sparse inside, whatever form it is given in: M, C, K and J are kept in
 * compressed columns and factored by CHOLMOD (SuiteSparse's sparse Cholesky), so that a step
 * costs about one sparse solve with K_eff = M + gamma dt C + beta dt^2 K plus work in the m
 * contacts only (fricreg_structure_step). A lumped (diagonal) M is the cheapest, a
 * consistent one is factored once per model.
 *
 * Units are the caller's, consistent and physical: e.g. kg, N/m, N s/m, m, s, N; eps of the
 * friction law is a velocity (m/s). The matrices are given dense and row-major
 * (A[i*ncols + j]), or as compressed sparse rows or columns (the _csr and _csc setters, with
 * fricreg.h's enum fricreg_sparse_flags: one-based CSC is what Fortran codes hold), or as GSL
 * sparse matrices (fricreg_structure_gsl.h). Dense M, C and K are symmetric, so Fortran may
 * pass them as they are, while a dense J (m x ndof) must be passed transposed from a Fortran
 * J(m, ndof) array (or stored as Jt(ndof, m)).
 *
 * Conventions are those of fricreg.h: int results are fricreg_status codes, nothing is
 * printed, a failed call leaves the caller's arrays untouched, one object per thread.
 *
 * This header declares the structure, its model, loads, integrator settings, errors and
 * warnings; since 1.9 each of its other objects has a header of its own, which this one
 * includes: fricreg_structure_elements.h (friction elements), fricreg_structure_run.h (steps,
 * runs, checkpoints), fricreg_structure_results.h (state, values, error estimate) and
 * fricreg_ctx_step.h (your own integrator's step on a context).
 */
#ifndef FRICREG_STRUCTURE_H
#define FRICREG_STRUCTURE_H

#include "fricreg.h"
#include "fricreg_element.h" /* fricreg_structure_add_elements's types */
#include "fricreg_types.h"   /* enum fricreg_integrator, enum fricreg_error_estimate */
/* Programs that got fricreg_sim.h's declarations through this header (1.7 and before) keep them. */
#include "fricreg_sim.h"

#ifdef __cplusplus
extern "C" {
#endif

/** \defgroup structure Structure: a linear structure with friction contacts (fricreg_structure)
 *  An opaque linear structure M u'' + C u' + K u = p(t) - M r a_g(t) + J^T f, whose friction
 *  forces f come from a context, stepped by Newmark, HHT-alpha, central difference or GSL's
 *  steppers with its energy balance. The model matrices may also be given as GSL sparse
 *  matrices (fricreg_structure_gsl.h).
 *  \{ */

/** Opaque linear structure with friction contacts: model, excitation, integrator, state. */
typedef struct fricreg_structure fricreg_structure;

/** Create a structure of ndof >= 1 degrees of freedom and m >= 1 friction contacts.
 *
 *  Defaults: M = I, C = 0, K = 0, J unset (set_contacts before the first step), mun[i] = 1,
 *  law (4) with eps = 1e-3, r = 1 (every DOF moves with the ground; since 1.7, r = 0
 *  before), no load and no ground motion, u = u' = 0 at t = 0,
 *  average-acceleration Newmark (beta = 1/4, gamma = 1/2), Newton tolerance 1e-10 and at
 *  most 50 iterations. Allocates O(ndof + m) here. The setters copy what they are given; the
 *  first step after a model setter factors M and hands W to the contacts (its diagonal when
 *  contacts do not couple; else dense m x m up to 64 contacts, fricreg_ctx_set_coupling_dense,
 *  and sparse beyond, fricreg_ctx_set_coupling_csc), the first step with a new dt (or
 *  scheme) factors K_eff, and the step guard's first use computes the model's rates (dense
 *  eigenvalues up to 2048 degrees of freedom), and the first Newmark/HHT step that finds
 *  elements (fricreg_structure_set_jenkins) beside a contact of bound > 0 allocates the joint
 *  Newton's dense storage: those steps allocate. The other steps never do.
 *
 *  ndof  number of degrees of freedom, 1 <= ndof <= 2^40 (memory runs out first).
 *  m     number of friction contacts, 1 <= m <= 2^26 (a structure without friction: one
 *        contact with mun = 0, whose force is exactly 0).
 *  out   out: the structure, released with fricreg_structure_free. Written only on success.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if out is NULL; FRICREG_EINVAL if ndof or m is 0 or too
 *  large; FRICREG_ENOMEM. */
FRICREG_API int fricreg_structure_create(size_t ndof, size_t m, fricreg_structure **out);

/** Release a structure. fricreg_structure_free(NULL) does nothing. */
FRICREG_API void fricreg_structure_free(fricreg_structure *s);

/** Set the mass matrix M[ndof*ndof] (mass units, e.g.\ kg), symmetric to 1e-12 of the rows'
 *  scales (|M_ij - M_ji| <= 1e-12 sqrt(r_i r_j), r_i = max_k |M_ik|, so that a change of
 *  units of a degree of freedom does not change the verdict) and positive definite (CHOLMOD's
 *  Cholesky factor exists: every pivot positive). Copied, its symmetric part (M + M^T)/2, its
 *  zero entries left out.
 *  Like every model setter, it takes effect at the next step, which recomputes the
 *  acceleration at the current state from the equation of motion.
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE if ndof is not the structure's;
 *  FRICREG_ENONFINITE; FRICREG_ENOTSYM; FRICREG_ENOTPSD if M is not positive definite (a
 *  pivot of its Cholesky factor is not positive; the message names its column);
 *  FRICREG_ENOMEM. */
FRICREG_API int fricreg_structure_set_mass(fricreg_structure *s, size_t ndof, const double M[]);

/** Set the stiffness matrix K[ndof*ndof] (force per length, e.g.\ N/m), symmetric (to 1e-12 of
 *  the rows' scales, as M); it need not be definite (rigid-body modes are allowed). Copied, its
 *  symmetric part.
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_ENONFINITE; FRICREG_ENOTSYM;
 *  FRICREG_ENOMEM. */
FRICREG_API int fricreg_structure_set_stiffness(fricreg_structure *s, size_t ndof,
                                                const double K[]);

/** Set the damping matrix C[ndof*ndof] (force per velocity, e.g.\ N s/m), symmetric (to 1e-12 of
 *  the rows' scales, as M). Copied, its symmetric part; replaces Rayleigh damping.
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_ENONFINITE; FRICREG_ENOTSYM;
 *  FRICREG_ENOMEM. */
FRICREG_API int fricreg_structure_set_damping(fricreg_structure *s, size_t ndof, const double C[]);

/** Rayleigh damping C = a0 M + a1 K (a0 in 1/s, a1 in s, both >= 0), formed from the M and
 *  K in force at each step, so it follows later set_mass and set_stiffness calls. Mode k of
 *  circular frequency w_k gets the damping ratio a0/(2 w_k) + a1 w_k/2.
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ENONFINITE; FRICREG_EINVAL if a0 or a1 < 0. */
FRICREG_API int fricreg_structure_set_rayleigh(fricreg_structure *s, double a0, double a1);

/** Set the contact matrix J[m*ndof], row-major (J[i*ndof + k] = d zdot_i / d u'_k,
 *  dimensionless for displacement DOFs), so that zdot = J u' and contact i's friction force
 *  f_i acts on the structure as J^T f. Copied. Each contact must move (a non-zero row):
 *  W = J M^-1 J^T then has W_ii > 0; redundant contacts (dependent rows) make W singular,
 *  which the friction evaluation reports as FRICREG_ESINGULAR when they stick together.
 *  A row scaled by c is the same contact with its bound's force on the structure c mun_i
 *  and its band eps/c in u': any finite scale is taken (W within the double range: see
 *  fricreg_structure_step), and one far from 1 (J = 1e100 beside mun = 1 N is a bound of
 *  1e100 N) is judged, bound times |J|, by FRICREG_WARN_BOUND_SCALE.
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE if m or ndof is not the structure's;
 *  FRICREG_ENONFINITE; FRICREG_EINVAL if a row is zero; FRICREG_ENOMEM. */
FRICREG_API int fricreg_structure_set_contacts(fricreg_structure *s, size_t m, size_t ndof,
                                               const double J[]);

/** Set one model matrix, in any storage: the one setter of M, K, C and J, of which
 *  fricreg_structure_set_mass, _set_stiffness, _set_damping, _set_contacts and their _csr and
 *  _csc forms are each one case (same checks, same results bit for bit; their messages name
 *  them, this one's "set_matrix"). Copied. Since 1.7 (FRICREG_1.7).
 *  s       in/out: the structure; unchanged on failure.
 *  which   enum fricreg_model_matrix: FRICREG_MASS (positive definite: CHOLMOD's Cholesky
 *          factor must exist), FRICREG_STIFFNESS, FRICREG_DAMPING (each symmetric to 1e-12 of
 *          the rows' scales, its symmetric part taken; C replaces Rayleigh's), or
 *          FRICREG_CONTACTS (J: no zero row, as fricreg_structure_set_contacts).
 *  nrows   ndof, or m for J.
 *  ncols   ndof.
 *  format  enum fricreg_matrix_format: FRICREG_MATRIX_DENSE (values[nrows ncols] row-major,
 *          no flag; ptr and ind not read, NULL from C), or FRICREG_MATRIX_CSR or
 *          FRICREG_MATRIX_CSC, each combined with | with enum fricreg_sparse_flags (base; a
 *          symmetric matrix whole or by one triangle, not J).
 *  ptr     compressed: ptr[nrows + 1] (CSR) or ptr[ncols + 1] (CSC), from the base.
 *  ind     compressed: ind[nnz], the column (CSR) or row (CSC) of each entry.
 *  values  values[nrows ncols] (dense) or values[nnz] (compressed), the matrix's units.
 *  Returns FRICREG_OK; FRICREG_ENULL (s, values, ptr of a compressed matrix, or ind or values
 *  with nnz > 0); FRICREG_EINVAL (which or format unknown, flags with a dense matrix or both
 *  CSR and CSC, a triangle for J, ptr not from the base or
 *  decreasing, an index out of range, an entry outside the triangle given, a zero row of J;
 *  called from the observer); FRICREG_ESIZE if nrows or ncols is not the structure's;
 *  FRICREG_ENONFINITE; FRICREG_ENOTSYM; FRICREG_ENOTPSD (M); FRICREG_ENOMEM. The message names
 *  the array and the entry. */
FRICREG_API int fricreg_structure_set_matrix(fricreg_structure *s, int which, size_t nrows,
                                             size_t ncols, int format, const int64_t ptr[],
                                             const int64_t ind[], const double values[]);

/** Set the mass matrix from compressed sparse rows: ndof x ndof, rowptr[ndof + 1],
 *  colind[nnz], values[nnz] (mass units), as enum fricreg_sparse_flags of fricreg.h describes
 *  (zero- or one-based; whole, then symmetric to 1e-12 of the rows' scales as
 *  fricreg_structure_set_mass, or one triangle; duplicates summed). Positive definite:
 *  CHOLMOD's Cholesky factor must exist. A diagonal (lumped) M is the cheapest: its factor is
 *  its square root. Copied. Since 1.6 (FRICREG_1.6).
 *  Returns FRICREG_OK; FRICREG_ENULL (s, rowptr, or colind or values with nnz > 0);
 *  FRICREG_ESIZE if ndof is not the structure's; FRICREG_EINVAL (flags, rowptr not starting
 *  at the base or decreasing, an index out of range, an entry outside the triangle given);
 *  FRICREG_ENONFINITE; FRICREG_ENOTSYM; FRICREG_ENOTPSD; FRICREG_ENOMEM. The message names
 *  the array and the entry. */
FRICREG_API int fricreg_structure_set_mass_csr(fricreg_structure *s, size_t ndof, int flags,
                                               const int64_t rowptr[], const int64_t colind[],
                                               const double values[]);

/** The same from compressed sparse columns: colptr[ndof + 1], rowind[nnz], values[nnz] (for a
 *  symmetric matrix the same arrays as CSR's but for the triangle: a CSR upper triangle is a
 *  CSC lower one). Since 1.6 (FRICREG_1.6).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_EINVAL; FRICREG_ENONFINITE;
 *  FRICREG_ENOTSYM; FRICREG_ENOTPSD; FRICREG_ENOMEM, as fricreg_structure_set_mass_csr. */
FRICREG_API int fricreg_structure_set_mass_csc(fricreg_structure *s, size_t ndof, int flags,
                                               const int64_t colptr[], const int64_t rowind[],
                                               const double values[]);

/** Set the stiffness matrix K (force per length) from compressed sparse rows, as
 *  fricreg_structure_set_mass_csr but need not be definite. Since 1.6 (FRICREG_1.6).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_EINVAL; FRICREG_ENONFINITE;
 *  FRICREG_ENOTSYM; FRICREG_ENOMEM. */
FRICREG_API int fricreg_structure_set_stiffness_csr(fricreg_structure *s, size_t ndof, int flags,
                                                    const int64_t rowptr[], const int64_t colind[],
                                                    const double values[]);

/** The same from compressed sparse columns. Since 1.6 (FRICREG_1.6).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_EINVAL; FRICREG_ENONFINITE;
 *  FRICREG_ENOTSYM; FRICREG_ENOMEM. */
FRICREG_API int fricreg_structure_set_stiffness_csc(fricreg_structure *s, size_t ndof, int flags,
                                                    const int64_t colptr[], const int64_t rowind[],
                                                    const double values[]);

/** Set the damping matrix C (force per velocity) from compressed sparse rows, as
 *  fricreg_structure_set_stiffness_csr; it replaces Rayleigh damping. Since 1.6 (FRICREG_1.6).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_EINVAL; FRICREG_ENONFINITE;
 *  FRICREG_ENOTSYM; FRICREG_ENOMEM. */
FRICREG_API int fricreg_structure_set_damping_csr(fricreg_structure *s, size_t ndof, int flags,
                                                  const int64_t rowptr[], const int64_t colind[],
                                                  const double values[]);

/** The same from compressed sparse columns. Since 1.6 (FRICREG_1.6).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_EINVAL; FRICREG_ENONFINITE;
 *  FRICREG_ENOTSYM; FRICREG_ENOMEM. */
FRICREG_API int fricreg_structure_set_damping_csc(fricreg_structure *s, size_t ndof, int flags,
                                                  const int64_t colptr[], const int64_t rowind[],
                                                  const double values[]);

/** Set the contact matrix J (m x ndof, J(i, k) = d zdot_i / d u'_k) from compressed sparse
 *  rows: rowptr[m + 1], colind[nnz], values[nnz]; flags FRICREG_SPARSE_ONE_BASED or 0 (J is
 *  not symmetric: the triangle flags are refused). Each row must hold a nonzero value, as
 *  fricreg_structure_set_contacts. Since 1.6 (FRICREG_1.6).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE if m or ndof is not the structure's;
 *  FRICREG_EINVAL (flags, pointers, indices, a zero row); FRICREG_ENONFINITE;
 *  FRICREG_ENOMEM. */
FRICREG_API int fricreg_structure_set_contacts_csr(fricreg_structure *s, size_t m, size_t ndof,
                                                   int flags, const int64_t rowptr[],
                                                   const int64_t colind[], const double values[]);

/** The same from compressed sparse columns: colptr[ndof + 1], rowind[nnz], values[nnz]. Since
 *  1.6 (FRICREG_1.6).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_EINVAL; FRICREG_ENONFINITE;
 *  FRICREG_ENOMEM, as fricreg_structure_set_contacts_csr. */
FRICREG_API int fricreg_structure_set_contacts_csc(fricreg_structure *s, size_t m, size_t ndof,
                                                   int flags, const int64_t colptr[],
                                                   const int64_t rowind[], const double values[]);

/** Set the friction bounds mun[m] = mu_i N_i >= 0 (force units). May be called between any
 *  two steps (normal forces vary); the next step starts from the equilibrium acceleration
 *  with the new bounds. Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_EINVAL if
 *  some mun[i] < 0; FRICREG_ENONFINITE. */
FRICREG_API int fricreg_structure_set_bounds(fricreg_structure *s, size_t m, const double mun[]);

/** Select the friction law (enum fricreg_law) and eps > 0 (velocity units, e.g.\ m/s), as
 *  fricreg_ctx_set_law. The continuous laws (3), (4) and tanh give an implicit step with a
 *  solution that Newton finds; (1) and (2) jump at v = 0 and Karnopp at |v| = eps, where a
 *  step may have no root: such steps end on Newton's last iterate and count as failures.
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_EINVAL for an unknown law or eps <= 0;
 *  FRICREG_ENONFINITE. */
FRICREG_API int fricreg_structure_set_law(fricreg_structure *s, int law, double eps);

/** Set the influence vector r[ndof] (dimensionless): the ground acceleration a_g loads the
 *  structure with -M r a_g (r_k = 1 for every DOF that translates with the ground, 0 for one
 *  that does not, e.g. a rotation). Default r = 1 at every DOF, as the CLI's.
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_ENONFINITE. */
FRICREG_API int fricreg_structure_set_influence(fricreg_structure *s, size_t ndof,
                                                const double r[]);

/** Set the ground acceleration a_g(t) (acceleration units, e.g.\ m/s^2) as a record of n >= 2
 *  samples ag[n] at times t0 + k dt_rec, dt_rec > 0, interpolated linearly and zero outside
 *  [t0, t0 + (n-1) dt_rec] (a time within 1e-9 dt_rec of an end is on it: step times are
 *  rounded). n = 0 (ag may be NULL) removes the ground motion. Copied.
 *  A step (Newmark, HHT, central difference) reads the record at its end only (run_ode
 *  reads it at every stage time): its start keeps the load the previous step
 *  ended with (or, after set_initial or a model setter, the record's value there). So a
 *  caller who computes a_g step by step passes the two samples {a_g(t), a_g(t + dt)} with
 *  t0 = t, dt_rec = dt before each step, and gets the run of the whole record.
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_EINVAL if n is 1 or dt_rec <= 0;
 *  FRICREG_ENONFINITE; FRICREG_ENOMEM. */
FRICREG_API int fricreg_structure_set_ground_accel(fricreg_structure *s, double t0, double dt_rec,
                                                   size_t n, const double ag[]);

/** Set the external load p(t) = p[ndof] g(t) (force units): a load pattern p times a time
 *  function g given as a record like fricreg_structure_set_ground_accel's (n >= 2 samples
 *  g[n] at t0 + k dt_rec, linear, zero outside), or g = 1 at all times when n = 0 (g may be
 *  NULL: a constant load; t0 and dt_rec are then ignored). Copied. Read at step ends only,
 *  like the ground motion.
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_EINVAL if n is 1 or dt_rec <= 0
 *  with n >= 2; FRICREG_ENONFINITE; FRICREG_ENOMEM. */
FRICREG_API int fricreg_structure_set_load(fricreg_structure *s, size_t ndof, const double p[],
                                           double t0, double dt_rec, size_t n, const double g[]);

/** Restart at t = 0 from displacements u0[ndof] and velocities v0[ndof]: clears the energy
 *  balance, the dissipation and the counters, and puts the Jenkins elements' sliders back at
 *  w = 0 (fricreg_structure_set_jenkins). The initial acceleration follows from the
 *  equation of motion at the first step (friction from the law at zdot = J v0).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_ENONFINITE. */
FRICREG_API int fricreg_structure_set_initial(fricreg_structure *s, size_t ndof, const double u0[],
                                              const double v0[]);

/** Select Newmark's method with parameters 0 < beta <= 1/2 and 1/2 <= gamma <= 1
 *  (unconditionally stable for 2 beta >= gamma; average acceleration beta = 1/4, gamma = 1/2,
 *  the default, conserves energy and is second order; gamma > 1/2 damps, first order).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ENONFINITE; FRICREG_EINVAL. */
FRICREG_API int fricreg_structure_set_newmark(fricreg_structure *s, double beta, double gamma);

/** Select HHT-alpha (Hilber, Hughes and Taylor 1977) with -1/3 <= alpha <= 0: the equation
 *  of motion is weighted (1 + alpha) at the step's end and -alpha at its start, with
 *  beta = (1 - alpha)^2/4, gamma = 1/2 - alpha; second order, unconditionally stable, with
 *  numerical damping of high frequencies growing with -alpha (alpha = 0: average acceleration).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ENONFINITE; FRICREG_EINVAL. */
FRICREG_API int fricreg_structure_set_hht(fricreg_structure *s, double alpha);

/** Select the explicit central-difference method (Newmark beta = 0, gamma = 1/2):
 *  u1 = u + dt v + dt^2 a/2, then the acceleration a1 from the equation of motion with the
 *  damping and the friction at the explicit velocity v* = v + dt a (f = f(J v*, a_free)),
 *  v1 = v + dt (a + a1)/2. No Newton iteration (the counters record 0); second order
 *  undamped. Each step is refused (FRICREG_ESTEP, the state unchanged) beyond the stability
 *  bound of fricreg_sim's FRICREG_INT_CENTRAL, the same guard:
 *  (dt omega_max/2)^2 + dt (lambda + c_max) < 0.9, omega_max^2 and c_max the largest
 *  eigenvalues of M^-1 K and M^-1 C (up to 2048 degrees of freedom GSL's symmetric
 *  eigensolver on L^-1 P K P^T L^-T and the same of C, P M P^T = L L^T, O(ndof^3) once per
 *  model change; beyond, upper bounds from Gershgorin's discs of D^-1/2 K D^-1/2 over the
 *  smallest of D^-1/2 M D^-1/2, D = diag(M), O(nnz): exact for a lumped M's discs, and no
 *  bound, so no step, when M's discs reach 0), lambda = fricreg_ctx_stick_stiffness (law
 *  (4): max_i W_ii 2 mun_i/eps; for (1), (2) and Karnopp the chord W_ii mun_i/eps, with
 *  dt lambda <= 1 and dt omega_max <= 1/sqrt 2 besides). The linear bound is 1: 0.9 keeps a
 *  margin. So the paper's eps = 2 dt with W mun = 1 is refused: take eps > 2.2 dt W_ii mun_i.
 *  set_newmark or set_hht select an implicit scheme again.
 *  Returns FRICREG_OK or FRICREG_ENULL. */
FRICREG_API int fricreg_structure_set_central_difference(fricreg_structure *s);

/** Newton's stopping rule: a step converges after at least one iteration (none if the
 *  first guess's residual is exactly zero) when the residual's largest entry is at most
 *  tol times the step's force scale: the largest entry of |M a| and |C v + K u - p~ - J^T f|
 *  at the step's start, |p~| at its end, and |J|^T mun. 0 < tol < 1; 1 <= max_iter <= 1000.
 *  Iterations grow slowly as eps shrinks against dt times the contacts' accelerations (law
 *  (4) then approaches a jump): on the ten-storey example building at dt = 0.01 s, mean
 *  (max) iterations per step were 0.58 (6) at eps = 0.01 m/s, 0.71 (11) at 1e-3 and 0.76 (15)
 *  at 1e-4 (a step whose start forces hold, every damper sliding, needs none); the default
 *  max_iter = 50 leaves room.
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ENONFINITE; FRICREG_EINVAL. */
FRICREG_API int fricreg_structure_set_newton(fricreg_structure *s, double tol, int max_iter);

/** How a Newmark / HHT-alpha step solves its near-stick block (fricreg_structure_step):
 *  the rows N of the Newton direction and of the stick guess,
 *  (W_eff,NN + diag(shift_N)) y_N = b_N, W_eff = J K_eff^-1 J^T (m x m, dense on a stiff
 *  continuum), shift_i = 1/(c |s_i|) from the law's slope s_i, 0 on a free contact of the
 *  consistent law and in the stick guess. */
enum fricreg_contact_solver {
    FRICREG_CONTACT_SOLVER_AUTO = 0,  /**< the library's choice: for now the dense path */
    FRICREG_CONTACT_SOLVER_DENSE = 1, /**< a Cholesky factor of the block itself: CHOLMOD's on
                                           W_eff's pattern where it stays sparse, LAPACK's dpotrf
                                           on the block where it fills (O(|N|^3); two m x m
                                           buffers: the factor held and a spare, since 1.10) */
    FRICREG_CONTACT_SOLVER_SPARSE = 2 /**< in the structure's n unknowns: CHOLMOD's factor of
                                           K_eff + J^T T J, T = diag(1/shift_N) (0 off N) */
};

/** Choose the near-stick block's solver of the next Newmark / HHT-alpha steps (central
 *  differences and GSL's steppers have none). FRICREG_CONTACT_SOLVER_SPARSE solves the block
 *  by Woodbury's identity,
 *    (J_N K_eff^-1 J_N^T + S)^-1 r = T (r - J_N (K_eff + J_N^T T J_N)^-1 J_N^T T r),
 *  S = diag(s~_N), T = S^-1, with one sparse Cholesky factor (CHOLMOD) of the n x n matrix
 *  K_eff + J^T T J: its pattern, K_eff + J^T J's, is ordered and analysed once per K_eff (once
 *  per run at a fixed dt) and refactored numerically only when N changes, or when the shifts
 *  moved so far that the held factor, used as a chord, does not converge within 6
 *  refinements. s~_i is shift_i where positive; where a row has none (a constraint on J_i's
 *  motion) s~_i = 2^-26 W_eff,ii. Every answer is refined against the exact block (iterative
 *  refinement, products with W_eff, until the block's residual is below 2^-43 of its
 *  right-hand side), so that both paths give the same steps to rounding (within 1e-10 of each
 *  other: tests/structure/test_contact_solver.c); a block that is not positive definite is
 *  FRICREG_ESINGULAR on both (then no stick guess, as before). The sparse path's storage is
 *  allocated with K_eff's factor and its factor is CHOLMOD's simplicial one, factored in place,
 *  so that its steps allocate nothing either (a supernodal factorization allocates its update
 *  matrix at every call). On the benchmark's 10^5-dof membrane the simplicial factor costs no
 *  more; on 10^6 dofs its refactorizations are slower, and the run's first steps, where the
 *  stick zone forms, took twice as long (docs/benchmark.md). FRICREG_CONTACT_SOLVER_AUTO, the
 *  default, takes the dense path: on every case of the benchmark (docs/benchmark.md: 632 and
 *  2528 contacts on 10^5 dofs with OpenBLAS and the reference BLAS, 10^4 on 10^6 dofs with
 *  OpenBLAS) it is the faster, but for 2528 contacts on the reference BLAS, where the sparse
 *  path's simplicial factor, which calls no BLAS, runs the whole run in 0.85 of its time;
 *  CHOLMOD's flop count against |N|^3 / 3 would choose the sparse path where OpenBLAS makes
 *  the dense one 3x faster.
 *  The setting is kept by the error estimate's companion. Since 1.8 (FRICREG_1.8).
 *
 *  solver   enum fricreg_contact_solver.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if s is NULL; FRICREG_EINVAL if solver is none of the
 *  enum, or when called from the observer during a run (the setting is then unchanged). */
FRICREG_API int fricreg_structure_set_contact_solver(fricreg_structure *s, int solver);

/** The near-stick block's solver of the next Newmark / HHT-alpha step:
 *  FRICREG_CONTACT_SOLVER_DENSE or FRICREG_CONTACT_SOLVER_SPARSE, never _AUTO (the automatic
 *  choice made). Since 1.8 (FRICREG_1.8).
 *
 *  solver   out: enum fricreg_contact_solver.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if s or solver is NULL. */
FRICREG_API int fricreg_structure_get_contact_solver(const fricreg_structure *s, int *solver);

/** Status of the last failed call. Returns that code, or FRICREG_OK if none (or s NULL). The
 *  getters, which take a const structure, return their status without recording it. */
FRICREG_API int fricreg_structure_errcode(const fricreg_structure *s);

/** Message of the last failed call: names the argument, entry, time or contact. "" if none;
 *  "NULL structure" if s is NULL. Owned by s, valid until its next call. */
FRICREG_API const char *fricreg_structure_errmsg(const fricreg_structure *s);

/** Copy the last error message into buf[len], NUL-terminated and truncated to fit (for
 *  Fortran). Returns the full message length, as snprintf does; 0 and nothing written if buf
 *  is NULL or len is 0. */
FRICREG_API size_t fricreg_structure_errmsg_copy(const fricreg_structure *s, char *buf, size_t len);

/** Judge the structure's checks of plausibility now and return how many warnings they raise
 *  (0 to 16; each code of enum fricreg_warning at most once), to be read with
 *  fricreg_structure_get_warning. The checks read the model in force, its excitation and the
 *  run since fricreg_structure_set_initial (or creation); the list is emptied and judged anew
 *  at each call, so it follows every change of model, law or record, and it is never printed.
 *  No check changes a result, the state, the counters or the last error (a warning is not a
 *  failure: the calls that ran returned FRICREG_OK). Units are SI (kg, N, m, s: the header's
 *  example), thresholds from docs/structural.md, "Warnings":
 *  - FRICREG_WARN_GROUND_PEAK: the ground record's peak |a_g| outside 0.05 g .. 5 g
 *    (g = 9.80665 m/s^2): a record in g or in cm/s^2.
 *  - FRICREG_WARN_EPS_LARGE, FRICREG_WARN_EPS_SMALL: with a ground record and r != 0, eps
 *    above 0.1 or below 1e-9 times the peak ground velocity |integral of a_g dt|
 *    (trapezoidal from the record's start): eps in mm/s, or a near-jump Newton cannot follow.
 *  - FRICREG_WARN_EPS_SPEED: after a step, no contact's |zdot_i| at a step's end exceeded
 *    10 eps: the law never left its regularized band (the contacts held throughout, or eps,
 *    the excitation or the bounds are in the wrong units).
 *  - FRICREG_WARN_BOUND_SCALE: after a step, the bounds on the structure,
 *    sum_i mun_i max_k |J_ik| (mun_i for rows of +-1), outside 1e-3 .. 10 times the
 *    structure's weight g 1^T M 1 (1^T M 1 the sum of M's entries: the total mass once per
 *    translational direction); the message names the largest contact, its mun_i and |J|.
 *    Changed in 1.7: it judged each contact's mun_i W_ii against 1e-3 g .. 10 g, which
 *    flagged every refined mesh of a continuum; J's scale counts since 1.7 too (a row of 1e100
 *    beside mun = 1 slid as a bound of 1e100 N does, unflagged).
 *  - FRICREG_WARN_RECORD_SHORT: the run's time past the start of the ground or load record
 *    above 10 times the record's duration (n - 1) dt: its time step in ms? Since 1.7.
 *  - FRICREG_WARN_DT_COARSE: after a fixed step (step, run, run_ode's fixed), the longest dt
 *    above a tenth of the fundamental period 2 pi/omega_1 (omega_1^2 the smallest eigenvalue
 *    of M^-1 K with every element sticking, computed here once per model at any size by
 *    inverse iteration on K's sparse Cholesky factor, O(nnz) an iteration, an allocation; not
 *    judged where K has a rigid-body mode. Up to 1.6: a dense eigen-solve, O(ndof^3), up to
 *    2048 degrees of freedom).
 *  - FRICREG_WARN_NEWTON_FAILURES: a step ended without Newton's convergence
 *    (FRICREG_SSTAT_NEWTON_FAILURES > 0); FRICREG_WARN_NEWTON_SLOW: more than 5 iterations per
 *    step on average.
 *  - FRICREG_WARN_ENERGY: when every step since set_initial was average-acceleration Newmark
 *    (whose discrete balance is exact) and none opened or closed an element of
 *    fricreg_structure_set_jenkins_normal, |FRICREG_SVALUE_RESIDUAL| above 1e-6 of
 *    |initial| + |input|.
 *  - FRICREG_WARN_TOL_LOOSE: an adaptive fricreg_structure_run_ode call since set_initial held
 *    a contact's velocity zdot_i = (J v)_i (mun_i > 0) to a level above 0.01 eps, the level
 *    being max_i sum_j |J_ij| atol_j over its atol per component (the call's one atol, or
 *    those of fricreg_structure_set_ode_abs_tolerances) plus the calls' largest rtol times the
 *    run's largest sum_j |J_ij| |v_j| at a step's end (GSL's control holds v_j to
 *    atol_j + rtol |v_j|): law (4)'s force inside its band is then uncontrolled (fricreg_sim's
 *    threshold). The rule from eps (FRICREG_ATOL_FROM_EPS, 1e-3 eps) never raises it.
 *    Since 1.6; since 1.7 the relative part takes the run's velocities, not 1 velocity unit.
 *  - FRICREG_WARN_ERROR_ESTIMATE: with fricreg_structure_set_error_estimate on, the companion
 *    failed (the estimates are +infinity; the message says why), or an estimate is above 10%
 *    of its quantity (the largest peak_err_i against the largest peak_i, or the sum of the
 *    D_err_i against the sum of |D_i|): outside the estimate's asymptotic range.
 *  Called from the observer during a run, it judges nothing and returns the list as it was.
 *  Returns the number of warnings; 0 if s is NULL. Since 1.6 (FRICREG_1.6). */
FRICREG_API size_t fricreg_structure_warning_count(fricreg_structure *s);

/** Read warning k, 0 <= k < fricreg_structure_warning_count(s): its code (enum
 *  fricreg_warning) into *code and its message (English, one line, under 256 characters, SI
 *  units, the numbers that raised it) into buf[len], NUL-terminated and truncated to fit as
 *  fricreg_structure_errmsg_copy (nothing written if buf is NULL or len is 0; for Fortran).
 *  Warnings are listed in a fixed order of checks. The list is the last
 *  fricreg_structure_warning_count's. Returns FRICREG_OK; FRICREG_ENULL if s or code is NULL;
 *  FRICREG_EINVAL if k is not below the count (nothing written). Since 1.6 (FRICREG_1.6). */
FRICREG_API int fricreg_structure_get_warning(const fricreg_structure *s, size_t k, int *code,
                                              char *buf, size_t len);

/** Message of warning k of the last fricreg_structure_warning_count, as
 *  fricreg_structure_get_warning writes it; "" if s is NULL or k is not below the count. Owned
 *  by s, valid until its next warning_count call. Since 1.6 (FRICREG_1.6). */
FRICREG_API const char *fricreg_structure_warning_message(const fricreg_structure *s, size_t k);

/** Route the structure's warnings to fn (fricreg_warning_handler of fricreg.h), as SUNDIALS'
 *  CVodeSetErrHandlerFn: at the end of every fricreg_structure_run and _run_ode, failed or
 *  not, the checks of fricreg_structure_warning_count are judged and fn is called once for
 *  each warning raised that it has not been given since the last fricreg_structure_set_initial
 *  (or since fn was installed). fricreg_structure_step judges nothing, since its callers step
 *  in loops of their own: such a loop calls fricreg_structure_warning_count when it wants its
 *  warnings judged (e.g. at its end), and fn receives the new ones. A caller that prints
 *  every message from fn sees what `fricreg-sim structure` prints. By default there is no
 *  handler and the library says nothing.
 *
 *  fn          the handler, or NULL to remove it.
 *  user_data   passed back to fn unchanged; may be NULL.
 *
 *  The error estimate's companion structure does not call it. Returns FRICREG_OK;
 *  FRICREG_ENULL if s is NULL; FRICREG_EINVAL if called from the observer or the handler during
 *  a run (nothing changed). Since 1.7 (FRICREG_1.7). */
FRICREG_API int fricreg_structure_set_warning_handler(fricreg_structure *s,
                                                      fricreg_warning_handler fn, void *user_data);

/** \} */

#ifdef __cplusplus
}
#endif

/* The structure's other objects, a header each since 1.9: included here, so that including
 * fricreg_structure.h alone declares the whole structure as 1.8's did. */
#include "fricreg_structure_elements.h"
#include "fricreg_structure_run.h"
#include "fricreg_structure_results.h"
#include "fricreg_ctx_step.h"

#endif /* FRICREG_STRUCTURE_H */
