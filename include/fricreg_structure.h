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
                                           on the block where it fills (O(|N|^3)) */
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
 *  other: tests/test_contact_solver.c); a block that is not positive definite is
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
 *  the standard control with atol = rtol. Measured (tests/test_structure_ode_tolerances.c, a
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

/** Copy the state at the current time: displacements u[ndof], velocities v[ndof],
 *  accelerations a[ndof]; any of them may be NULL (not all three).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE if ndof is not the structure's. */
FRICREG_API int fricreg_structure_get_state(const fricreg_structure *s, size_t ndof, double u[],
                                            double v[], double a[]);

/** Copy the friction forces f[m] (force units) of the current state (after the last step;
 *  zero before the first). Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE. */
FRICREG_API int fricreg_structure_get_forces(const fricreg_structure *s, size_t m, double f[]);

/** Copy the energy dissipated by each contact since set_initial,
 *  D_i = -sum over steps of (z_i(t+dt) - z_i(t)) (f_i(t) + f_i(t+dt))/2 (trapezoidal; energy
 *  units), into D[m]. Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE. */
FRICREG_API int fricreg_structure_get_dissipation(const fricreg_structure *s, size_t m, double D[]);

/** Quantities of fricreg_structure_get_value. Values are fixed forever. The energies are
 *  summed over steps with the trapezoidal rule on the displacement increments du:
 *  input += du.(p~(t) + p~(t+dt))/2, viscous += du.C(v(t) + v(t+dt))/2, friction as in
 *  get_dissipation; kinetic = v.M v/2 and strain = u.K u/2 now, initial = both at t = 0;
 *  residual = initial + input - kinetic - strain - viscous - friction - jenkins (strain
 *  holding the Jenkins elements' springs' energy too). Average-acceleration
 *  Newmark makes the residual vanish to Newton's tolerance (its discrete balance is exact);
 *  HHT-alpha's numerical damping shows in it. */
enum fricreg_structure_value {
    FRICREG_SVALUE_TIME = 0,             /**< time reached */
    FRICREG_SVALUE_INPUT = 1,            /**< work of p - M r a_g since t = 0 */
    FRICREG_SVALUE_KINETIC = 2,          /**< kinetic energy now */
    FRICREG_SVALUE_STRAIN = 3,           /**< strain energy now */
    FRICREG_SVALUE_VISCOUS = 4,          /**< energy dissipated by C since t = 0 */
    FRICREG_SVALUE_FRICTION = 5,         /**< energy dissipated by all contacts since t = 0 */
    FRICREG_SVALUE_RESIDUAL = 6,         /**< the balance's residual */
    FRICREG_SVALUE_INITIAL = 7,          /**< kinetic + strain energy at t = 0 */
    FRICREG_SVALUE_GROUND_PGV = 8,       /**< the ground record's peak velocity max |integral of a_g
                                       dt| (trapezoidal from the record's start; 0 without a
                                       record): the scale of fricreg-sim's default eps and of
                                       the eps warnings (since 1.6) */
    FRICREG_SVALUE_JENKINS = 9,          /**< energy dissipated by all Jenkins or Iwan elements
                                       since t = 0 (fricreg_structure_get_jenkins_state,
                                       fricreg_structure_get_iwan_state; since 1.6) */
    FRICREG_SVALUE_COMPANION_CPU = 10,   /**< CPU seconds (C's clock(): the process's, other
                                          threads' work in the same intervals included) spent
                                          stepping the error estimate's companions since they
                                          were made (fricreg_structure_set_error_estimate: the
                                          first stepping call after set_initial), the second
                                          companion's inside the first's; 0 until an
                                          estimate is made, the last one's after it ends
                                          until the next is made. The estimate's cost beside
                                          the run's own (since 1.8) */
    FRICREG_SVALUE_COMPANIONS_USED = 11, /**< the companions that gave the error estimate
                                          now, as enum fricreg_estimate_companions: 0
                                          (finer) or 1 (coarser); with
                                          FRICREG_COMPANIONS_AUTO, 1 while the screen is
                                          quiet and 0 once the finer confirmed it (reading
                                          this, or _COMPANION_CPU or the _SCREEN_ values,
                                          settles the screen as the estimate's getters do:
                                          fricreg_structure_set_error_companions); -1
                                          without an estimate (off, not yet made, ended or
                                          failed) (since 1.9) */
    FRICREG_SVALUE_SCREEN_PEAK_ERR = 12, /**< with FRICREG_COMPANIONS_AUTO, once the finer
                                          companions confirmed: what the screen had said, its
                                          estimate of the largest peak's error (the largest
                                          over the dofs; length units) at the call's end where
                                          it doubted, +infinity where it failed; NaN where no
                                          confirmation ran (since 1.9) */
    FRICREG_SVALUE_SCREEN_DISS_ERR = 13  /**< likewise, the screen's estimate of the
                                          summed dissipations' error (contacts' and joint
                                          elements'; energy units) (since 1.9) */
};

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
 *  mun); FRICREG_ENOMEM. On failure the elements in force are unchanged. */
FRICREG_API int fricreg_structure_set_jenkins(fricreg_structure *s, size_t me, size_t ndof,
                                              const double Je[], const double kt[],
                                              const double mun[]);

/** The same with J_e from compressed sparse rows: rowptr[me + 1], colind[nnz], values[nnz],
 *  flags FRICREG_SPARSE_ONE_BASED or 0 (as fricreg_structure_set_contacts_csr: the triangle
 *  flags are refused; duplicates summed). Since 1.6 (FRICREG_1.6).
 *  Returns FRICREG_OK; FRICREG_ENULL (s, kt, mun, rowptr, or colind or values with nnz > 0);
 *  FRICREG_ESIZE; FRICREG_EINVAL (flags, pointers, indices, a zero row, kt_i <= 0, mun_i < 0,
 *  me > 2^26, from the observer); FRICREG_ENONFINITE; FRICREG_ENOMEM, as
 *  fricreg_structure_set_jenkins. */
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
 *  force are unchanged. */
FRICREG_API int fricreg_structure_set_jenkins_2d(fricreg_structure *s, size_t me, size_t ndof,
                                                 const double Je[], const double kt[],
                                                 const double mun[]);

/** The same with J_e (2 me rows) from compressed sparse rows: rowptr[2 me + 1], colind[nnz],
 *  values[nnz], flags FRICREG_SPARSE_ONE_BASED or 0, as fricreg_structure_set_jenkins_csr.
 *  Since 1.6 (FRICREG_1.6).
 *  Returns FRICREG_OK; FRICREG_ENULL (s, kt, mun, rowptr, or colind or values with nnz > 0);
 *  FRICREG_ESIZE; FRICREG_EINVAL (flags, pointers, indices, a zero row, kt_i <= 0, mun_i < 0,
 *  2 me > 2^26, from the observer); FRICREG_ENONFINITE; FRICREG_ENOMEM, as
 *  fricreg_structure_set_jenkins_2d. */
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
 *  entry of Je, k or phi); FRICREG_ENOMEM. On failure the elements in force are unchanged. */
FRICREG_API int fricreg_structure_set_iwan(fricreg_structure *s, size_t me, size_t ndof,
                                           const double Je[], size_t ns, const double k[],
                                           const double phi[]);

/** The same with J_e from compressed sparse rows: rowptr[me + 1], colind[nnz], values[nnz],
 *  flags FRICREG_SPARSE_ONE_BASED or 0, as fricreg_structure_set_jenkins_csr. Since 1.6
 *  (FRICREG_1.6).
 *  Returns FRICREG_OK; FRICREG_ENULL (s, k, phi, rowptr, or colind or values with nnz > 0);
 *  FRICREG_ESIZE; FRICREG_EINVAL (flags, pointers, indices, a zero row, ns = 0 or above
 *  FRICREG_ELEMENT_MAX_SLIDERS, k <= 0, phi < 0, me ns > 2^26, from the observer); FRICREG_ENONFINITE; FRICREG_ENOMEM, as
 *  fricreg_structure_set_iwan. */
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
 *  elements in force are unchanged. */
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
 *  FRICREG_ENOMEM. On failure the elements in force are unchanged. */
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
 *  failure the elements in force are unchanged. */
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

/** Read one quantity (enum fricreg_structure_value) into *value.
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_EINVAL for an unknown quantity. */
FRICREG_API int fricreg_structure_get_value(const fricreg_structure *s, int which, double *value);

/* ---- Error estimate (since 1.6) ---------------------------------------------------------- */

/** Whether and how the structure estimates the error of its peak displacements
 *  (fricreg_structure_get_peak_displacement) and of each contact's dissipation
 *  (fricreg_structure_get_dissipation) against the Coulomb problem, eps -> 0, where a run's
 *  results carry both the regularization error of the law and the discretization (or
 *  tolerance) error. Off by default (fricreg-sim structure turns it on). Since 1.6
 *  (FRICREG_1.6); two companions and on = 2 since 1.7.
 *
 *  The estimator (docs/structural.md, "Error estimate"): companion runs along the path
 *  (eps, dt) -> (eps / 2, dt / 2) -> (eps / 4, dt / 4) give q2 and q4 beside the run's q (the
 *  finer companions described here; since 1.9 by default screened by coarser ones and run only
 *  where those doubt: fricreg_structure_set_error_companions). Law
 *  (4)'s error is c eps^p, p = 1 or 2, and along dt / eps fixed a fixed step's error follows
 *  eps, so in the asymptotic range d1 = q - q2 and d2 = q2 - q4 have one sign and
 *  d1 / d2 = 2^p. With on = FRICREG_ESTIMATE_TWO_COMPANIONS (1): where the observed order
 *  p = log2(d1 / d2) is at least 0.5, err = 2 |d1| 2^p / (2^p - 1) (Richardson's correction
 *  with the observed order, times 2; about 2 |d1| where p is above the law's orders); below
 *  (a stall: the run and the first companion agree on a wrong value; or differences that
 *  grow or change sign) err = 6.83 (|d1| + |d2|), but 2 (|d1| + 2 |d2|) where they have
 *  opposite signs and |d2| <= |d1| / 8 (law (4)'s two orders give the error as
 *  (2/3) d1 + (8/3) d2; since 1.8); d2 below 1e-9 of q gives 2 |d1| + |d2|, d1
 *  and d2 both below it 4 (|d1| + |d2|) (the factor 2 and p = 1's tail; their bare sum before
 *  1.8). With on = FRICREG_ESTIMATE_ONE_COMPANION (2), 1.6's estimator: err = 3 |d1|
 *  (fricreg_sim_set_error_estimate's, with its calibration), which cannot see a stall
 *  (bench/frame_estimate.c: a frame 5x under, no warning). Each estimate has a kind
 *  (fricreg_structure_get_error_kind, enum fricreg_estimate_kind): ASYMPTOTIC where the order
 *  was seen, BOUND below the range (until 1.7 a dissipation's raised
 *  FRICREG_WARN_NOT_ASYMPTOTIC, no longer raised), ASSUMED with one companion.
 *  The companion is a second structure, owned by s, stepped alongside it; the second
 *  companion is the first's own, made and stepped by it the same way:
 *  - it is made at the first stepping call (fricreg_structure_step, _run or _run_ode) after
 *    fricreg_structure_set_initial (or creation) with the estimate on, as a copy of everything
 *    set then (model, Rayleigh damping, influence, load and ground records, law with eps / 2,
 *    bounds, scheme, Newton's settings, the bound on adaptive steps, the elements (Jenkins,
 *    Iwan, 2-D, lift-off), the initial state); turned on (or changed between 1 and 2) later
 *    in a run, the estimate starts at the next set_initial;
 *  - at the end of every stepping call on s (successful, failed after some steps, or stopped by
 *    the observer) it is stepped from its time to s's: fricreg_structure_step(s, dt) and
 *    fricreg_structure_run(s, dt, t_end) by fricreg_structure_run(companion, dt / 2, t) (two
 *    steps per step of s, the last shortened as run's), fricreg_structure_run_ode with fixed
 *    steps by the same stepper at dt / 2, adaptive by the same stepper with dt as its first step
 *    and rtol / 16, atol / 16 (the second companion: dt / 4, or the tolerances / 256);
 *  - the setters a run may call between steps are passed on to it (before it steps next, so a
 *    refusal there fails the estimate at the next stepping call): set_bounds, set_law (eps / 2
 *    of the new eps), set_ground_accel and set_load (a caller who feeds the record step by step
 *    feeds the companion too: it reads its records at its own step ends, in between), set_newton,
 *    set_max_steps (each call of the companion's bounded as s's) and set_ode_abs_tolerances
 *    (applied at / 16 there, as run_ode's rule from eps). Every other setter after
 *    the companion was made (the model matrices, Rayleigh, influence, scheme, elements) ends the
 *    estimate until the next set_initial: the getters then return FRICREG_EINVAL.
 *  The peaks take in every step, fixed or adaptive, with the turning points inside it
 *  (fricreg_structure_get_peak_displacement), so they converge at the scheme's order or the
 *  adaptive tolerance and not with the phase of the samples; before 1.8 an adaptive run was
 *  sampled at its run_ode calls' ends only, which its companions shared: the estimate missed
 *  that sampling error (the frame of bench/frame_estimate.c under rkf45 at rtol 1e-6 called
 *  every 0.02 s: storey 1's peak 1.25e-5 off, now 7.6e-8, whatever the interval).
 *  Where a companion fails (e.g. FRICREG_ESTEP or FRICREG_EWORK at its finer setting, or no
 *  memory) s's run still succeeds, the estimates become +infinity until the next set_initial, and
 *  fricreg_structure_warning_count raises FRICREG_WARN_ERROR_ESTIMATE with the companion's
 *  message; it raises it too, whatever the kinds, where half the largest peak's estimate (its
 *  central value: the estimate bounds the error at about twice its size) exceeds the answer
 *  tolerance times the largest peak (max_i err_i / 2 > rtol max_i peak_i), or half the
 *  dissipations' summed estimates (contacts' and joint elements' together) the tolerance times
 *  their summed magnitudes (fricreg_structure_set_answer_rtol: rtol = 1e-2 by default; until
 *  1.8 the whole estimates, until 1.7 against 10%).
 *  Cost: each companion's run, about 2x and 4x s's for fixed steps (twice and four times the
 *  steps), 1.4x ... 3x each for adaptive ones (fricreg_sim_set_error_estimate); one or two more
 *  structures in memory, allocated at the run's first step (a failed allocation is a failed
 *  estimate, not a failed step). So with two companions a run costs about 7x (the frame of
 *  bench/frame_estimate.c, Newmark: 6.5x), with one about 3x.
 *
 *  s   in/out: the structure.
 *  on  in: enum fricreg_error_estimate: 1 (two companions) or 2 (one) to estimate, 0 not to
 *      (default; 0 also discards the estimate made).
 *  Returns FRICREG_OK; FRICREG_ENULL if s is NULL; FRICREG_EINVAL if on is not 0, 1 or 2, or
 *  if called from the observer during a run. */
FRICREG_API int fricreg_structure_set_error_estimate(fricreg_structure *s, int on);

/** Where the error estimate's companions sit on the path (fricreg_structure_set_error_companions). */
enum fricreg_estimate_companions {
    /** eps / 2 at dt / 2 and eps / 4 at dt / 4 (adaptive: the tolerances / 16, / 256):
     *  calibrated (docs/structural.md, "Error estimate"); about 7x a run's cost (6.5x on the
     *  frame of bench/frame_estimate.c, 7.1x on a 10^5-dof chain); the default until 1.8 */
    FRICREG_COMPANIONS_FINER = 0,
    /** 2 eps at 2 dt and 4 eps at 4 dt (adaptive: the tolerances x 2, x 4): the run's error
     *  from the coarser levels, about 0.7x a run's cost; it bounds the error less often on
     *  problems it was not derived on and warns on many runs within the tolerance
     *  (docs/structural.md, "Error estimate"), and fails near an explicit scheme's step bound
     *  (the companions' steps exceed it) */
    FRICREG_COMPANIONS_COARSER = 1,
    /** screened, the default since 1.9: the coarser companions run; where their estimate would
     *  warn (FRICREG_WARN_ERROR_ESTIMATE) or could not be formed, the finer companions run from
     *  the start and theirs is the estimate (since 1.9) */
    FRICREG_COMPANIONS_AUTO = 2
};

/** Choose where the error estimate's companions (fricreg_structure_set_error_estimate) sit:
 *  finer than the run (FRICREG_COMPANIONS_FINER), coarser (FRICREG_COMPANIONS_COARSER), or
 *  coarser first and finer where they doubt (FRICREG_COMPANIONS_AUTO, the default since 1.9).
 *  Since 1.8 (FRICREG_1.8); FRICREG_COMPANIONS_AUTO and the default since 1.9 (1.8's default
 *  was FRICREG_COMPANIONS_FINER).
 *
 *  Coarser: the companions run at (2 eps, 2 dt) and (4 eps, 4 dt), adaptive ones at the same
 *  output interval with rtol, atol x 2 and x 4 (the rule from eps, or the set tolerances,
 *  likewise: the path's own factor, so that the tolerances' share of the error follows the
 *  law's lower order), every other rule of the companions as set_error_estimate says. From the run's q
 *  and the companions' q2, q4, with d1 = q - q2 and d2 = q2 - q4: in the asymptotic range
 *  d2 / d1 = 2^p (law (4)'s error c eps^p along dt / eps fixed), so the run's own error is
 *  Richardson's from the coarser levels, |d1| / (2^p - 1); where r = d2 / d1 lies in
 *  [2^0.5, 2^2] the estimate is 2 |d1| / (r - 1) (the factor 2 the finer estimator's), kind
 *  FRICREG_EST_KIND_ASYMPTOTIC: on law (4)'s two orders, e = a eps + b eps^2 with a, b of one
 *  sign, Richardson's is at worst 3/4 of the error (at r = 3), so 2 bounds it; above 2^2 the
 *  two of opposite signs can put Richardson's any factor under (7x at r = 8). Otherwise (a
 *  stall: d1 small against d2; an order above the law's, which a stall and those opposite
 *  signs imitate; differences that change sign) 4.83 (|d1| + |d2|), kind
 *  FRICREG_EST_KIND_BOUND (both differences below 1e-9 of q: 4 (|d1| + |d2|)); with one
 *  companion (FRICREG_ESTIMATE_ONE_COMPANION) 3 |d1|, ASSUMED. The run's results are
 *  unchanged: the estimate only costs less, the coarser levels being further from the
 *  asymptotic range (more BOUND kinds). Fixed steps need each stepping call (step, run,
 *  run_ode without tolerances) to span 4 dt, the coarsest companion's step (2 dt with one
 *  companion): a shorter call fails the estimate (+infinity, FRICREG_WARN_ERROR_ESTIMATE
 *  saying why), since a companion stepping one call of dt at 2 dt would take s's own step.
 *
 *  Auto (screen, then confirm): the coarser companions run as above (the screen), and a
 *  finer pair is made beside them at the run's start, a copy as set_error_estimate says, but
 *  not stepped. Where the estimate is read (the *_error getters, get_error_kind,
 *  get_value's estimate values, fricreg_structure_warning_count) and the screen's estimate
 *  would raise FRICREG_WARN_ERROR_ESTIMATE there (half the largest peak's estimate above the
 *  answer tolerance times the largest peak, or half the summed dissipations' likewise: the
 *  warning's own test), the finer companions are stepped from the start to s's time, as s's
 *  calls stepped s, and from then on they are the estimate (every getter and the warning,
 *  exactly the finer estimator's) and the screen is freed; where the screen fails (a fixed-step
 *  call shorter than 4 dt, a companion's failure) they are stepped at once. So a run of many
 *  calls is judged where it is read, not at its first calls, whose small quantities a bound
 *  doubts; a read between calls settles it there. The getters are logically const: the read
 *  that settles may take the finer companions' time, and the structure's results do not
 *  change. Where the run was one stepping call, the finer estimates are bit for bit
 *  FRICREG_COMPANIONS_FINER's; over many calls they follow the calls as finer companions do
 *  except where consecutive calls share dt, the integrator and its tolerances, which the finer
 *  pair takes as one call (its steps the same, its time reached to rounding; an adaptive one
 *  chooses its own steps). A setter passed on to the companions (set_bounds, set_law, the
 *  records, ...) first steps the finer pair to the time of the change, so a run that changes
 *  such a setting between its steps pays the finer companions' cost as well as the screen's.
 *  What the screen said and which companions gave the estimate: fricreg_structure_get_value's
 *  FRICREG_SVALUE_COMPANIONS_USED, FRICREG_SVALUE_SCREEN_PEAK_ERR,
 *  FRICREG_SVALUE_SCREEN_DISS_ERR. Cost: the screen's, about 0.7x a run, where it is quiet;
 *  where it doubts, that plus the finer companions' (docs/structural.md, "Error estimate");
 *  memory: one more structure beside the screen's, not set up until it steps.
 *
 *  A change ends the estimate made, which starts anew at the next set_initial, as a change
 *  of on (set_error_estimate).
 *
 *  s      in/out: the structure.
 *  which  in: enum fricreg_estimate_companions, 0 (finer), 1 (coarser) or 2 (auto).
 *  Returns FRICREG_OK; FRICREG_ENULL if s is NULL; FRICREG_EINVAL, s unchanged, if which is
 *  not 0, 1 or 2, or if called from the observer during a run. */
FRICREG_API int fricreg_structure_set_error_companions(fricreg_structure *s, int which);

/** Copy the peak displacements since fricreg_structure_set_initial (or creation),
 *  peak[i] = max |u_i| over: the initial state; every fixed step (fricreg_structure_step, _run,
 *  _run_ode with fixed steps), its end and the turning points of u_i inside it, on the cubic
 *  Hermite interpolant of the step's ends (u and u' at both; for Newmark's average
 *  acceleration the scheme's own quadratic), so the peak converges at the scheme's order
 *  (since 1.7; 1.6 took the step ends only); every adaptive step of fricreg_structure_run_ode
 *  likewise, its end and its turning points on that step's Hermite interpolant (since 1.8;
 *  before, only each run_ode call's end); into peak[ndof] (length units).
 *  Tracked whether or not the error estimate is on. Since 1.6 (FRICREG_1.6).
 *  Returns FRICREG_OK; FRICREG_ENULL if s or peak is NULL; FRICREG_ESIZE if ndof is not the
 *  structure's. */
FRICREG_API int fricreg_structure_get_peak_displacement(const fricreg_structure *s, size_t ndof,
                                                        double peak[]);

/** Copy the error estimate of each peak displacement (fricreg_structure_get_peak_displacement)
 *  into err[ndof] (length units, >= 0; +infinity where a companion failed),
 *  fricreg_structure_set_error_estimate's estimator (the one chosen there), at the current
 *  time. Since 1.6 (FRICREG_1.6).
 *  s     in: the structure; not modified.
 *  ndof  in: the structure's degrees of freedom.
 *  err   out: err[ndof]; written only on success.
 *  Returns FRICREG_OK; FRICREG_ENULL if s or err is NULL; FRICREG_EINVAL when there is no
 *  estimate (the estimate off, no step taken since set_initial with it on, a setter ended it
 *  (fricreg_structure_set_error_estimate), or called from the observer during a run, when the
 *  companion has not caught up); FRICREG_ESIZE if ndof is not the structure's. */
FRICREG_API int fricreg_structure_get_peak_displacement_error(const fricreg_structure *s,
                                                              size_t ndof, double err[]);

/** Copy the error estimate of each contact's dissipation (fricreg_structure_get_dissipation)
 *  into err[m] (energy units, >= 0; +infinity where a companion failed), as
 *  fricreg_structure_get_peak_displacement_error. Since 1.6
 *  (FRICREG_1.6).
 *  Returns FRICREG_OK; FRICREG_ENULL if s or err is NULL; FRICREG_EINVAL when there is no
 *  estimate (as fricreg_structure_get_peak_displacement_error); FRICREG_ESIZE if m is not the
 *  structure's. */
FRICREG_API int fricreg_structure_get_dissipation_error(const fricreg_structure *s, size_t m,
                                                        double err[]);

/** Copy the error estimate of each joint element's dissipation (the D[me] of
 *  fricreg_structure_get_jenkins_state: Jenkins, Iwan, 2-D and lift-off elements alike) into
 *  err[me] (energy units, >= 0; +infinity where a companion failed), as
 *  fricreg_structure_get_dissipation_error: from the companions' runs along the same path
 *  (dt / 2, dt / 4 and eps with it; an element has no eps, so its error is the scheme's in dt),
 *  the estimator of fricreg_structure_set_error_estimate. An element whose three dissipations
 *  show no order along the path gets the safe bound (kind BOUND, fricreg_structure_get_error_kind);
 *  their sum, with the contacts', enters the warning of an estimate above the answer tolerance
 *  (FRICREG_WARN_ERROR_ESTIMATE). Since 1.7 (FRICREG_1.7).
 *  s     in: the structure; not modified.
 *  me    in: the number of elements set (0: nothing to write).
 *  err   out: err[me]; written only on success.
 *  Returns FRICREG_OK; FRICREG_ENULL if s or err is NULL; FRICREG_EINVAL when there is no
 *  estimate (as fricreg_structure_get_peak_displacement_error); FRICREG_ESIZE if me is not the
 *  number of elements set. */
FRICREG_API int fricreg_structure_get_jenkins_dissipation_error(const fricreg_structure *s,
                                                                size_t me, double err[]);

/** The quantities whose error fricreg_structure_set_error_estimate estimates, for
 *  fricreg_structure_get_error_kind. Values are fixed forever. Since 1.8 (FRICREG_1.8). */
enum fricreg_estimated_quantity {
    /** the peak displacements, n = ndof (fricreg_structure_get_peak_displacement_error) */
    FRICREG_EST_PEAK_DISPLACEMENT = 1,
    /** the contacts' dissipations, n = m (fricreg_structure_get_dissipation_error) */
    FRICREG_EST_DISSIPATION = 2,
    /** the joint elements' dissipations, n = the number of elements set
     *  (fricreg_structure_get_jenkins_dissipation_error) */
    FRICREG_EST_ELEMENT_DISSIPATION = 3
};

/** Copy the kind of each error estimate of `quantity` into kind[n]: enum
 *  fricreg_estimate_kind, FRICREG_EST_KIND_ASYMPTOTIC (1: q, q2, q4 showed the law's
 *  order, the estimate Richardson's with the observed order, expected 1 ... 3x the error),
 *  _BOUND (2: they did not, or a companion failed and the estimate is +infinity: a safe upper
 *  bound) or _ASSUMED (3: one companion, the order assumed), the decision of
 *  src/base/companion_estimate.c (fricreg_structure_set_error_estimate), at the current time.
 *  s         in: the structure; not modified.
 *  quantity  in: enum fricreg_estimated_quantity: FRICREG_EST_PEAK_DISPLACEMENT (n =
 *            ndof), FRICREG_EST_DISSIPATION (n = m contacts) or
 *            FRICREG_EST_ELEMENT_DISSIPATION (n = the joint elements set).
 *  n         in: the length of kind, as above.
 *  kind      out: kind[n], parallel to the *_error getter's err[n]; written only on success.
 *  Returns FRICREG_OK; FRICREG_ENULL if s or kind is NULL; FRICREG_EINVAL for an unknown
 *  quantity, or when there is no estimate (as fricreg_structure_get_peak_displacement_error);
 *  FRICREG_ESIZE if n is not the quantity's length. Since 1.8 (FRICREG_1.8). */
FRICREG_API int fricreg_structure_get_error_kind(const fricreg_structure *s, int quantity, size_t n,
                                                 int kind[]);

/** Set the run's answer tolerance: fricreg_structure_warning_count raises
 *  FRICREG_WARN_ERROR_ESTIMATE where the estimates' central values, half the estimates (which
 *  bound the errors at about twice their size), exceed it: max_i peak_err_i / 2 >
 *  rtol max_i |peak_i| or sum_j D_err_j / 2 > rtol sum_j |D_j| (contacts and joint elements
 *  together), whatever the estimates' kinds (fricreg_structure_set_error_estimate; rtol the
 *  relative error a caller accepts in the answer, dimensionless), and the estimate above
 *  1e-12 of a scale the run knows (a structure at rest: eps t for the peaks, sum_j mun_j eps t
 *  for the dissipations). Default 1e-2. Until 1.8 the whole estimates were compared, which
 *  rtol / 2 restores; until 1.7 the level was a fixed 10%. Kept across runs and set_initial;
 *  not passed to the companions (they raise no warning); it changes no result, only the
 *  warning, judged on the value in force when the warnings are judged
 *  (fricreg_structure_warning_count).
 *  s     in/out: the structure.
 *  rtol  in: the tolerance, finite and > 0.
 *  Returns FRICREG_OK; FRICREG_ENULL if s is NULL; FRICREG_EINVAL if rtol is not finite or
 *  not > 0 (nothing changed). Since 1.8 (FRICREG_1.8). */
FRICREG_API int fricreg_structure_set_answer_rtol(fricreg_structure *s, double rtol);

/** Counters since creation or set_initial, for fricreg_structure_get_stat. Fixed forever. */
enum fricreg_structure_stat {
    FRICREG_SSTAT_STEPS = 0,             /**< steps taken */
    FRICREG_SSTAT_NEWTON_ITERATIONS = 1, /**< Newton iterations (linear solves), all steps */
    FRICREG_SSTAT_NEWTON_MAX = 2,        /**< most Newton iterations in one step */
    FRICREG_SSTAT_NEWTON_FAILURES = 3,   /**< steps whose Newton did not converge */
    FRICREG_SSTAT_LINE_SEARCH_CUTS = 4   /**< halvings of Newton directions, all steps */
};

/** Read one counter (enum fricreg_structure_stat) into *value.
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_EINVAL for an unknown counter. */
FRICREG_API int fricreg_structure_get_stat(const fricreg_structure *s, int which, int64_t *value);

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

/* ---- Your own implicit integrator: the contact-space step on a context --------------------- */

/** Flags of fricreg_ctx_solve_step (values fixed forever). */
enum fricreg_step_flags {
    /** Plain Newton: full steps on the exact tangent from the caller's guess, no stick guess,
     *  no stop at zdot = 0, no line search. For comparison: it fails where the safeguards do
     *  not (docs/structural.md, "Your own Newmark with fricreg"). */
    FRICREG_STEP_PLAIN = 1
};

/** The friction forces of one implicit step of the caller's own integrator (Newmark, HHT-alpha,
 *  a BDF) on a context, by the contact-space Newton of fricreg_structure's steps with its
 *  safeguards (since 1.6, FRICREG_1.6): for a caller who factors their own K_eff and only
 *  wants the m contact forces of the step, after which one linear solve gives the structure's
 *  update. Declared here because it is the structure's step made public; it needs no
 *  fricreg_structure.
 *
 *  The step's equations. With the forces f entering the structure as + J^T f, M x + C v1 +
 *  K u1 = p1 + J^T f (x the end's acceleration), a step whose end state is affine in x
 *  (Newmark: u1 = u_pred + beta dt^2 x, v1 = v_pred + gamma dt x) gives
 *  x(f) = K_eff^-1 (b + J^T f), K_eff = M + gamma dt C + beta dt^2 K, b = p1 - C v_pred -
 *  K u_pred, and the contacts' velocities and free accelerations at the end are affine in f:
 *    zdot(f)   = zdot_pred + c W_eff f,          zdot_pred = J v_pred + c J K_eff^-1 b,
 *    a_free(f) = a_pred - (W - W_eff) f,         a_pred = J K_eff^-1 b,
 *  with W = J M^-1 J^T (the context's coupling), W_eff = J K_eff^-1 J^T and c = gamma dt
 *  (HHT-alpha with w = 1 + alpha: c = w gamma dt, W_eff from w K_eff's definition, newmark.c).
 *  The step's forces solve G(f) = f - F(zdot(f), a_free(f)) = 0, F the context's law (its
 *  fricreg_ctx_eval: the paper's (1)-(4), f_eq from a_free and W, Sec. 3.3).
 *
 *  Method (fricreg_structure's, src/structure/newmark.c): Newton on the exact tangent
 *  (fricreg_ctx_tangent's), T = dG/df = I - c F_z W_eff + F_a (W - W_eff), solved contact by
 *  contact in W_eff's sparse pattern (CHOLMOD), dense by QR where a law's slope is positive;
 *  with three safeguards:
 *   - stick guess: where ||G|| at the guess f is above tol, the contacts whose guess is below
 *     their bound (|f_i| < mun_i) take the forces that keep their velocities at the step's
 *     start (W_eff,SS df_S = (zdot_start - zdot(f))_S / c), or, with law (4) and a diagonal W,
 *     the forces of the band's own affine piece (then usually exact: one iteration); taken
 *     when its residual is smaller;
 *   - stop: a slipping contact (outside (4)'s band) whose Newton step would carry it from one
 *     side of zdot = 0 across the whole band is stopped at zdot_i = 0 instead (the first trial
 *     step), each contact once a step;
 *   - line search: backtracking (halvings, at most 30) with Armijo's sufficient decrease
 *     1e-4 on the merit sqrt(G^T W G), the M^-1 norm of the structure's residual J^T G
 *     (fricreg_structure's line search reads that residual's 2-norm); where it stalls,
 *     Newton starts again from the guess without stops.
 *  The tangent at zdot_i = 0 exactly (where a stop leaves a contact) is fricreg_ctx_tangent's,
 *  unchanged: its bounds' slopes are those of zdot_i > 0. Which side of zdot = 0 the step
 *  takes is decided by the stop, not by the tangent: a contact whose Newton step would carry it
 *  across the band is halted at zdot_i = 0, coming from the side it had at the iterate, and the
 *  next iteration works on the band's own piece there.
 *
 *  ctx          a context with the law, eps, bounds and coupling W (fricreg_ctx_set_*); its
 *               last evaluation is at the returned forces on success.
 *  m            its contact count.
 *  zdot_start[m] the contacts' velocities at the step's start, J v (velocity units).
 *  zdot_pred[m] the end's velocities with no friction change, as above.
 *  a_pred[m]    the end's free accelerations at f = 0 plus W_eff f's share, as above
 *               (acceleration units): a_free(f) = a_pred - (W - W_eff) f.
 *  W[m*m]       W = J M^-1 J^T, row-major (symmetric: Fortran may pass its array), the
 *               coupling the context holds (acceleration per force): its diagonal is checked
 *               against the context's (to 1e-12 relative), its semidefiniteness is not (the
 *               context's setter checked it).
 *  Weff[m*m]    W_eff = J K_eff^-1 J^T, row-major, symmetric positive definite.
 *  c            > 0, d zdot / d (J x): gamma dt for Newmark (time units).
 *  tol          > 0, force units: converged when max_i |G_i| <= tol (at least one Newton
 *               iteration unless G is exactly 0 at the first point).
 *  max_iter     >= 1, the step's Newton iterations.
 *  flags        0 or FRICREG_STEP_PLAIN.
 *  f[m]         in: the guess (the previous step's forces); out: the step's forces (force
 *               units); the best iterate when not converged (info[1] = 0).
 *  info[2]      out: info[0] the Newton iterations made, info[1] 1 if converged, else 0.
 *  Cost: the two m x m dense inputs read (checked, and their nonzeros kept: O(m^2) per call),
 *  then per iteration one eval, one tangent's rows and one sparse solve. The first call
 *  allocates the step's solver (CHOLMOD, sparse copies of W's and W_eff's upper triangles,
 *  the Newton matrix, a few dozen vectors of m) and runs CHOLMOD's analysis of W_eff's
 *  pattern; the context keeps the solver. A later call with the same m and the same nonzero
 *  patterns of W and W_eff (exact zeros outside them; the values may change every call)
 *  refills the values and reuses it: no allocation, no analysis, and while W_eff's values and
 *  a stick set are those of the last factorization, no refactorization either. Another
 *  pattern rebuilds it, as the first call. The results are the same, bit for bit, whether the
 *  solver was kept or built. Its memory (O(m + nnz(L)), L W_eff's Cholesky factor; a dense
 *  m x m Newton matrix too, three m x m arrays, for m <= 64 and wherever the law's tangent may
 *  need it: Stribeck friction, or the paper's partition on a coupled W) is held until
 *  fricreg_ctx_free, fricreg_ctx_set_law or a coupling setter (fricreg_ctx_set_coupling_*); a
 *  call that fails with FRICREG_ENOMEM releases it (the next call builds one). A kept solver
 *  without the dense matrix is built again at the first call that may need it (after
 *  fricreg_ctx_set_stribeck or fricreg_ctx_set_partition), so that no later call allocates.
 *
 *  Returns FRICREG_OK (converged or not: read info[1]); FRICREG_ENULL if ctx or an array is
 *  NULL; FRICREG_ESIZE if m differs from the context's; FRICREG_ENONFINITE if c, tol or an
 *  input entry is NaN or infinite; FRICREG_EINVAL if c <= 0, tol <= 0, max_iter < 1, flags
 *  has an unknown bit or W's diagonal is not the context's coupling's; FRICREG_ENOTSYM if W or
 *  Weff is not symmetric (|A_ij - A_ji| > 1e-12 sqrt(A_ii A_jj)); FRICREG_ENOTPSD if a diagonal entry of W or Weff is below DBL_MIN;
 *  FRICREG_ENOMEM; FRICREG_EDIVERGED if the residual became NaN or infinite; the context's
 *  fricreg_ctx_eval status where an evaluation fails (FRICREG_ENONFINITE where the step's
 *  velocities, free accelerations or forces reach beyond its solve's range, ~1e280, as with
 *  entries near 1e308; FRICREG_ESINGULAR for redundant contacts). The failure is recorded in the
 *  context (fricreg_ctx_errmsg); on failure f and info are not written. */
FRICREG_API int fricreg_ctx_solve_step(fricreg_ctx *ctx, size_t m, const double zdot_start[],
                                       const double zdot_pred[], const double a_pred[],
                                       const double W[], const double Weff[], double c, double tol,
                                       int max_iter, int flags, double f[], int info[]);

/** fricreg_ctx_solve_step with W and W_eff in compressed sparse rows (since 1.7, FRICREG_1.7;
 *  fricreg_ctx_solve_step_matrix's FRICREG_MATRIX_CSR case):
 *  the same step, the same method and the same forces, for the models whose contacts couple
 *  only to their neighbours. The dense call reads two m x m arrays on every call, O(m^2): at
 *  m = 10^4 1.5 GiB and seconds a step however sparse W and W_eff are; here every call is
 *  O(nnz) in its inputs (bench/solve_step.c). The step solves on their upper triangles either
 *  way, so on the same matrices (an input's entries the dense one's nonzeros, W and W_eff
 *  exactly symmetric) the results are the dense call's, bit for bit.
 *
 *  ctx, m, zdot_start[m], zdot_pred[m], a_pred[m], c, tol, max_iter, flags, f[m], info[2]:
 *               as fricreg_ctx_solve_step's (velocity, acceleration, time and force units).
 *  sparse_flags enum fricreg_sparse_flags (fricreg.h), for both matrices:
 *               FRICREG_SPARSE_ONE_BASED when the indices count from 1; each matrix given
 *               whole (default) or by one triangle with its diagonal, FRICREG_SPARSE_UPPER
 *               (column >= row) or FRICREG_SPARSE_LOWER (column <= row).
 *  w_rowptr[m + 1], w_colind[nnz], w_values[nnz]
 *               W = J M^-1 J^T (acceleration per force), the coupling the context holds,
 *               in CSR as fricreg_ctx_set_coupling_csr takes it: rowptr[0] = base,
 *               non-decreasing; entries in any order within a row, duplicates summed,
 *               explicit zeros kept (they belong to the pattern). Its diagonal is checked
 *               against the context's (to 1e-12 relative), its semidefiniteness is not.
 *  weff_rowptr[m + 1], weff_colind[nnz_eff], weff_values[nnz_eff]
 *               W_eff = J K_eff^-1 J^T, symmetric positive definite, the same way.
 *  Read on every call, copied into the step's solver; the caller keeps its arrays.
 *
 *  Checked as the coupling setters check their arrays (flags, pointers, indices, the triangle
 *  left out, finite values), then as the dense call checks its matrices: every diagonal entry
 *  present and >= DBL_MIN; given whole, symmetric as |A_ij - A_ji| <= 1e-12 sqrt(A_ii A_jj),
 *  its symmetric part (A + A^T)/2 then used (the dense call uses its upper triangle: the same
 *  for a symmetric A).
 *
 *  Cost: O(m + nnz + nnz_eff) per call to read, check and store the inputs, then per
 *  iteration what the dense call's costs. The step's solver is the dense call's, kept in the
 *  context by the same rule: a later call with the same m, sparse_flags and index arrays of
 *  both matrices (the same rowptr and colind, entry for entry; the values may change every
 *  call) refills the values: no allocation, no analysis, and while W_eff's values and a stick
 *  set are those of the last factorization, no refactorization; other arrays build it again
 *  (first call: the analysis of W_eff's pattern, memory O(m + nnz + nnz_eff + nnz(L))). The
 *  results are the same, bit for bit, whether the solver was kept or built. Released as the
 *  dense call's (fricreg_ctx_free, fricreg_ctx_set_law, a coupling setter, FRICREG_ENOMEM).
 *
 *  Returns FRICREG_OK (converged or not: read info[1]); FRICREG_ENULL if ctx, a vector, f,
 *  info or a pointer array is NULL, or an index or value array while its nnz > 0;
 *  FRICREG_ESIZE if m differs from the context's; FRICREG_ENONFINITE if c, tol, a vector
 *  entry or a matrix entry is NaN or infinite; FRICREG_EINVAL if c <= 0, tol <= 0,
 *  max_iter < 1, flags has an unknown bit, sparse_flags are unknown or name both triangles, a
 *  pointer array does not start at the base or decreases, an index lies outside
 *  base .. m - 1 + base, an entry lies in the triangle left out, or W's diagonal is not the
 *  context's coupling's; FRICREG_ENOTPSD if a diagonal entry of W or W_eff is missing or below
 *  DBL_MIN; FRICREG_ENOTSYM if W or W_eff, given whole, is not symmetric; FRICREG_ENOMEM;
 *  FRICREG_EDIVERGED and the context's fricreg_ctx_eval statuses as fricreg_ctx_solve_step.
 *  The failure is recorded in the context (fricreg_ctx_errmsg); on failure f and info are not
 *  written. */
FRICREG_API int fricreg_ctx_solve_step_csr(fricreg_ctx *ctx, size_t m, const double zdot_start[],
                                           const double zdot_pred[], const double a_pred[],
                                           int sparse_flags, const int64_t w_rowptr[],
                                           const int64_t w_colind[], const double w_values[],
                                           const int64_t weff_rowptr[], const int64_t weff_colind[],
                                           const double weff_values[], double c, double tol,
                                           int max_iter, int flags, double f[], int info[]);

/** fricreg_ctx_solve_step_csr with W and W_eff in compressed sparse columns (since 1.7,
 *  FRICREG_1.7; fricreg_ctx_solve_step_matrix's FRICREG_MATRIX_CSC case): colptr[m + 1] the column pointers and rowind[nnz] each entry's row, as
 *  fricreg_ctx_set_coupling_csc takes them. One-based CSC (FRICREG_SPARSE_ONE_BASED) is what
 *  Fortran codes hold; W and W_eff being symmetric, their CSC arrays are their CSR arrays,
 *  FRICREG_SPARSE_UPPER of one being FRICREG_SPARSE_LOWER of the other.
 *
 *  ctx, m, zdot_start[m], zdot_pred[m], a_pred[m], c, tol, max_iter, flags, f[m], info[2]:
 *               as fricreg_ctx_solve_step's.
 *  sparse_flags enum fricreg_sparse_flags (base, whole or one triangle), for both matrices.
 *  w_colptr[m + 1], w_rowind[nnz], w_values[nnz]: W = J M^-1 J^T, as the context's coupling.
 *  weff_colptr[m + 1], weff_rowind[nnz_eff], weff_values[nnz_eff]: W_eff = J K_eff^-1 J^T.
 *  Checked, solved, kept and costed as by fricreg_ctx_solve_step_csr.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_ENONFINITE; FRICREG_EINVAL
 *  (c, tol, max_iter, flags, sparse_flags, pointers, indices, an entry in the triangle left
 *  out, W's diagonal); FRICREG_ENOTPSD; FRICREG_ENOTSYM; FRICREG_ENOMEM; FRICREG_EDIVERGED
 *  and the context's fricreg_ctx_eval statuses, as fricreg_ctx_solve_step_csr. On failure f
 *  and info are not written. */
FRICREG_API int fricreg_ctx_solve_step_csc(fricreg_ctx *ctx, size_t m, const double zdot_start[],
                                           const double zdot_pred[], const double a_pred[],
                                           int sparse_flags, const int64_t w_colptr[],
                                           const int64_t w_rowind[], const double w_values[],
                                           const int64_t weff_colptr[], const int64_t weff_rowind[],
                                           const double weff_values[], double c, double tol,
                                           int max_iter, int flags, double f[], int info[]);

/** fricreg_ctx_solve_step with W and W_eff in any storage, the format an argument as
 *  fricreg_structure_set_matrix takes it (since 1.8, FRICREG_1.8): dense, compressed sparse
 *  rows or compressed sparse columns. The same step, the same method and, on the same
 *  matrices, the same forces bit for bit as fricreg_ctx_solve_step (dense) and
 *  fricreg_ctx_solve_step_csr / _csc (compressed), which are its cases; the step's solver is
 *  kept in the context by their rule.
 *
 *  ctx, m, zdot_start[m], zdot_pred[m], a_pred[m], c, tol, max_iter, flags, f[m], info[2]:
 *               as fricreg_ctx_solve_step's (velocity, acceleration, time and force units).
 *  format       enum fricreg_matrix_format (fricreg.h), for both matrices:
 *               FRICREG_MATRIX_DENSE (no flag; w_values[m*m] and weff_values[m*m] row-major,
 *               symmetric, so Fortran may pass its arrays; the pointer and index arrays are
 *               not read, NULL from C), or FRICREG_MATRIX_CSR or FRICREG_MATRIX_CSC, each
 *               combined with | with enum fricreg_sparse_flags (FRICREG_SPARSE_ONE_BASED;
 *               each matrix whole, or by one triangle with its diagonal, FRICREG_SPARSE_UPPER
 *               or FRICREG_SPARSE_LOWER).
 *  w_ptr, w_ind, w_values
 *               W = J M^-1 J^T (acceleration per force), the coupling the context holds:
 *               compressed, w_ptr[m + 1] (row or column pointers from the base), w_ind[nnz]
 *               (each entry's column in CSR, row in CSC) and w_values[nnz], as
 *               fricreg_ctx_solve_step_csr / _csc read them; dense, w_values[m*m].
 *  weff_ptr, weff_ind, weff_values
 *               W_eff = J K_eff^-1 J^T, symmetric positive definite, the same way.
 *
 *  Returns FRICREG_OK (converged or not: read info[1]); FRICREG_EINVAL if format names both
 *  CSR and CSC, or is dense with a sparse flag; otherwise each status of the case it names,
 *  fricreg_ctx_solve_step (dense) or fricreg_ctx_solve_step_csr / _csc (compressed):
 *  FRICREG_ENULL, FRICREG_ESIZE, FRICREG_ENONFINITE, FRICREG_EINVAL, FRICREG_ENOTSYM,
 *  FRICREG_ENOTPSD, FRICREG_ENOMEM, FRICREG_EDIVERGED and the context's fricreg_ctx_eval
 *  statuses. The failure is recorded in the context (fricreg_ctx_errmsg); on failure f and
 *  info are not written. */
FRICREG_API int fricreg_ctx_solve_step_matrix(fricreg_ctx *ctx, size_t m, const double zdot_start[],
                                              const double zdot_pred[], const double a_pred[],
                                              int format, const int64_t w_ptr[],
                                              const int64_t w_ind[], const double w_values[],
                                              const int64_t weff_ptr[], const int64_t weff_ind[],
                                              const double weff_values[], double c, double tol,
                                              int max_iter, int flags, double f[], int info[]);

/** \} */

#ifdef __cplusplus
}
#endif

#endif /* FRICREG_STRUCTURE_H */
