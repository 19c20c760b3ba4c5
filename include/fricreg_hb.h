/* SPDX-License-Identifier: GPL-3.0-or-later */
/**
 * \file
 * fricreg_hb.h — harmonic balance (HB) for the periodic steady state of a linear structure with
 * 1-D Jenkins or Iwan elements (fricreg_hb_set_iwan) under harmonic excitation, at one frequency
 * or along a branch in the excitation frequency by pseudo-arclength continuation. Beyond the
 * paper: the frequency-domain driver of "joints" (docs/harmonic_balance.md), on
 * the exact AFT of fricreg_aft.h. After M. Krack and J. Gross, "Harmonic Balance for Nonlinear Vibration
 * Problems", Springer 2019 (Ch. 2 the method, Ch. 4 the condensation on the nonlinear
 * coordinates, Ch. 5 the continuation).
 *
 * The model, x[ndof] the displacements, θ = Ω t:
 *
 *     M x'' + C x' + K x + J^T f(J x) = p_c cos Ωt + p_s sin Ωt
 *
 * with M, C, K symmetric ndof x ndof (dense row-major, or sparse: the _csc setters), the
 * m x ndof matrix J (dense row-major: m is small) whose row i
 * gives element i's relative displacement q_i = J_i x, and f_i the force of a 1-D Jenkins
 * element (fricreg_jenkins.h: a spring kt_i in series with a Coulomb slider of bound mun_i),
 * the stabilized hysteresis of fricreg_aft.h, entering as a spring's kt q would. Every
 * periodic function is given by its Fourier coefficients up to harmonic H, in fricreg_aft.h's
 * layout: x_k(θ) = x0 + Σ_{h=1..H} (a_h cos hθ + b_h sin hθ) as the 2H + 1 numbers
 * (x0, a_1, b_1, ..., a_H, b_H).
 *
 * The HB equations per harmonic h, in complex form X_h = a_h − i b_h (and likewise F_h, P_h),
 * with the dynamic stiffness D_h(Ω) = K − (hΩ)² M + i hΩ C:
 *
 *     D_h X_h = P_h − J^T F_h(q),     P_1 = p_c − i p_s, P_h = 0 otherwise        (HB)
 *
 * are linear in X_h for given element forces, so they are condensed on the elements'
 * coordinates q = J x, m (2H + 1) unknowns (Krack & Gross Ch. 4):
 *
 *     R_h(q) = Q_h + G_h F_h(q) − J D_h^-1 P_h = 0,    G_h = J D_h^-1 J^T (m x m)     (R)
 *
 * with the Jacobian I + G_h ∂F_h/∂q from fricreg_aft_jenkins_exact's exact Jacobian. Newton's
 * method with a backtracking line search solves (R); the displacements then follow from (HB),
 * X_h = D_h^-1 P_h − (D_h^-1 J^T) F_h, with the solves already done for G_h. The static term
 * h = 0 is K x0 = −J^T f0 (no static load): f does not depend on the mean q0 (the stabilized
 * hysteresis is invariant under a shift of q, ∂f/∂q0 = 0), so the mean follows from the other
 * harmonics through K^-1, and K must be nonsingular. A structure held only by its joints (K
 * singular, a rigid-body mode) has a mean position that the periodic response does not decide
 * (the sliders' offsets are left by the transient): add a ground spring, small against kt, to
 * K, or eliminate the mode, before calling. Likewise each D_h (h = 1..H) must be nonsingular:
 * a structure without damping has no finite response where hΩ is one of its own (the
 * elements removed) natural frequencies; give C (or Rayleigh damping) at least a little.
 * Elements with a normal load and lift-off (fricreg_hb_set_normal_elements) have two rows of J
 * each, tangential and normal, and the same equations with F_h = (f_h, N_h) on both; 3-D
 * contact elements (fricreg_hb_set_jenkins_2d_normal) three, with F_h = (fx_h, fy_h, N_h).
 * One model may hold these kinds together, and elements of every other type of
 * fricreg_element.h, each marched by its own eval (fricreg_hb_add_elements, since 1.8): each
 * element has its own rows, in the order added.
 *
 * Cost per frequency: H + 1 complex LU factors of ndof x ndof and (H + 1)(m + 1) solves, then
 * per Newton iteration m AFTs (O(H³) each) and a real LU of order m (2H + 1). A dense model
 * (the dense setters) is factored by a complex LU with partial pivoting, O(H ndof³): for small
 * to medium ndof (at most 4096). Both dense LUs are fricreg's own, on memory allocated at
 * create and by the element setters, so a dense solve allocates nothing. A sparse
 * model (any _csc setter; the only one above 4096 dofs) by SuiteSparse's KLU, complex
 * (D_h is complex symmetric, not Hermitian, and indefinite above the first resonance: no
 * Cholesky): the pattern of D_h, the union of M's, C's and K's, is analysed once per pattern
 * (klu_l_analyze: AMD), each D_h factored with partial pivoting (klu_zl_factor) and, at later
 * frequencies, refactored on the same pivots (klu_zl_refactor) while their pivot growth stays
 * within a hundredfold of a fresh factor's. The H + 1 factors are kept from one frequency to
 * the next within a call (its Newton iterations, continuation points) while they hold at most
 * 2^24 entries in all, and freed when it returns, so that a call's results do not depend on
 * the calls before it; a larger model frees each once its solves Y_h = D_h^-1 [J^T | P_h] are
 * done, so one factor, O(nnz(L + U)), lives at a time. Y_h of
 * every harmonic, (H + 1) ndof (m + 1) complex numbers, is kept (the displacements need no
 * factor). Its cost follows the factors' fill, O(H ndof) on a banded model (measured:
 * docs/harmonic_balance.md). The solves' forward error grows with the condition of D_h (on a rod of
 * ndof elements as ndof²: about 3e-8 of q at 10^4 dofs); a continuation's corrector stops at
 * it where it lies above Newton's tolerance (fricreg_hb_set_newton).
 *
 * Conventions are those of fricreg.h: int results are fricreg_status codes, nothing is
 * printed, a failed call leaves the caller's arrays untouched, one object per thread. The
 * object keeps the status and a message of its last failed call (fricreg_hb_errcode,
 * fricreg_hb_errmsg, fricreg_hb_errmsg_copy). Since 1.7 every solving call can be watched and
 * stopped (fricreg_hb_set_monitor, fricreg_hb_set_max_iterations: FRICREG_EWORK, the group
 * "Monitoring and stopping a solve"), and from the monitor every call but the getters returns
 * FRICREG_EINVAL and changes nothing: that code is in no list below. Since 1.6 (FRICREG_1.6).
 */
#ifndef FRICREG_HB_H
#define FRICREG_HB_H

#include "fricreg.h"
#include "fricreg_aft.h"     /* FRICREG_AFT_MAX_HARMONICS */
#include "fricreg_element.h" /* fricreg_hb_add_elements's types */

#ifdef __cplusplus
extern "C" {
#endif

/** \defgroup hb Joints: harmonic balance of structures with Jenkins elements (fricreg_hb)
 *  An opaque harmonic-balance driver: a linear structure M, C, K with m 1-D Jenkins elements
 *  on rows of J, excited at the fundamental, solved for H harmonics at one frequency or along
 *  a frequency branch by pseudo-arclength continuation, condensed on the elements'
 *  coordinates (docs/harmonic_balance.md).
 *  \{ */

/** Opaque harmonic-balance driver: the model, the excitation, the solver settings, the
 *  factors of the last frequency, the last solution and the continuation's points. */
typedef struct fricreg_hb fricreg_hb;

/** Largest number of harmonics H of fricreg_hb_create: the exact AFT's, 40. */
#define FRICREG_HB_MAX_HARMONICS FRICREG_AFT_MAX_HARMONICS

/** Largest number of sliders per Iwan element of fricreg_hb_set_iwan, 1024 (Segalman's
 *  discretization at its finest resolution, fricreg_iwan.h, has fewer). */
#define FRICREG_HB_MAX_SLIDERS 1024

/** Create a harmonic-balance driver for ndof degrees of freedom, m Jenkins elements and the
 *  harmonics 0..H.
 *
 *  Defaults: M = I, C = 0, K = 0 (set_stiffness before solving: K must be nonsingular), J
 *  unset (fricreg_hb_set_elements before solving), no excitation, Newton tolerance 1e-10 with
 *  at most 50 iterations, continuation steps ds = 0.02, between 1e-6 and 0.1, at most 2000
 *  points. Up to 4096 dofs the model is dense, and all memory but the continuation's points
 *  (fricreg_hb_continue) is allocated here: O(ndof² + H m ndof + (m H)²) doubles (one D_h at a
 *  time; the solves Y_h of every harmonic); a _csc setter turns it sparse for good (its dense
 *  matrices converted, then freed). Beyond 4096 dofs the model is sparse from the start (M = I,
 *  C = K = 0 as sparse matrices), O(H m ndof + (m H)²) doubles here, and the sparse setters
 *  and solves allocate the pattern and KLU's factors (header comment).
 *
 *  ndof       degrees of freedom, 1 <= ndof <= 2^24.
 *  m          Jenkins elements, 1 <= m <= 256.
 *  harmonics  H, 1 <= H <= FRICREG_HB_MAX_HARMONICS.
 *  out        out: the new object, released with fricreg_hb_free. Written only on success.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if out is NULL; FRICREG_EINVAL if ndof, m or H is out of
 *  its range; FRICREG_ENOMEM. With no object to keep it, a failure has no message beyond its
 *  status, as for fricreg_ctx_create. Since 1.6. */
FRICREG_API int fricreg_hb_create(size_t ndof, size_t m, int harmonics, fricreg_hb **out);

/** Release the driver. fricreg_hb_free(NULL) does nothing. Since 1.6. */
FRICREG_API void fricreg_hb_free(fricreg_hb *hb);

/** Set the mass matrix M[ndof ndof], row-major, mass units (e.g. kg): finite, symmetric to
 *  1e-12 of the rows' scales (|M_ij − M_ji| <= 1e-12 sqrt(r_i r_j), r_i = max_k |M_ik|);
 *  its symmetric part (M + M^T)/2 is kept. Definiteness is not checked: what the solves need
 *  is D_h nonsingular, checked at each frequency. On a sparse model (fricreg_hb_set_mass_csc)
 *  its non-zero entries are converted to it.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb or M is NULL; FRICREG_ESIZE if ndof is not the
 *  driver's; FRICREG_ENONFINITE if an entry is NaN or infinite; FRICREG_ENOTSYM if M is not
 *  symmetric; FRICREG_ENOMEM (a sparse model only). All inputs are checked before anything
 *  changes. Since 1.6. */
FRICREG_API int fricreg_hb_set_mass(fricreg_hb *hb, size_t ndof, const double M[]);

/** Set the stiffness matrix K[ndof ndof], row-major, force per unit displacement (e.g. N/m),
 *  as fricreg_hb_set_mass (symmetric, finite); it must be nonsingular for the static term
 *  (header comment), which the solves check.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_ENONFINITE; FRICREG_ENOTSYM;
 *  FRICREG_ENOMEM, as fricreg_hb_set_mass. Since 1.6. */
FRICREG_API int fricreg_hb_set_stiffness(fricreg_hb *hb, size_t ndof, const double K[]);

/** Set the damping matrix C[ndof ndof], row-major, force per unit velocity (e.g. N s/m), as
 *  fricreg_hb_set_mass (symmetric, finite). Replaces Rayleigh damping.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_ENONFINITE; FRICREG_ENOTSYM;
 *  FRICREG_ENOMEM, as fricreg_hb_set_mass. Since 1.6. */
FRICREG_API int fricreg_hb_set_damping(fricreg_hb *hb, size_t ndof, const double C[]);

/** Set the mass matrix from compressed sparse columns: ndof x ndof, colptr[ndof + 1],
 *  rowind[nnz], values[nnz] (mass units), with the conventions of
 *  fricreg_structure_set_mass_csc and enum fricreg_sparse_flags of fricreg.h: zero-based, or
 *  one-based with FRICREG_SPARSE_ONE_BASED; given whole (then symmetric to 1e-12 of the rows'
 *  scales as fricreg_hb_set_mass, its symmetric part kept) or by one triangle
 *  (FRICREG_SPARSE_UPPER, row <= column, or FRICREG_SPARSE_LOWER); duplicates summed. Copied.
 *  The model becomes sparse: from then on D_h is factored by KLU (header comment), the
 *  dense setters convert their matrices to it, and a dense model's other two matrices are
 *  converted now (their non-zero entries). Since 1.6 (FRICREG_1.6).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb or colptr is NULL, or rowind or values while
 *  nnz > 0; FRICREG_ESIZE if ndof is not the driver's; FRICREG_EINVAL for unknown flags,
 *  both triangle flags, colptr[0] not the base, colptr decreasing, a row index out of range or
 *  an entry outside the triangle given; FRICREG_ENONFINITE if a value is NaN or infinite;
 *  FRICREG_ENOTSYM if, given whole, it is not symmetric; FRICREG_ENOMEM. The message names
 *  the array and the entry. All inputs are checked before anything changes; on failure the
 *  model is the one before the call. */
FRICREG_API int fricreg_hb_set_mass_csc(fricreg_hb *hb, size_t ndof, int flags,
                                        const int64_t colptr[], const int64_t rowind[],
                                        const double values[]);

/** Set the stiffness matrix K from compressed sparse columns, as fricreg_hb_set_mass_csc
 *  (force per unit displacement); nonsingular, as fricreg_hb_set_stiffness. Since 1.6
 *  (FRICREG_1.6).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_EINVAL; FRICREG_ENONFINITE;
 *  FRICREG_ENOTSYM; FRICREG_ENOMEM, as fricreg_hb_set_mass_csc. */
FRICREG_API int fricreg_hb_set_stiffness_csc(fricreg_hb *hb, size_t ndof, int flags,
                                             const int64_t colptr[], const int64_t rowind[],
                                             const double values[]);

/** Set the damping matrix C from compressed sparse columns, as fricreg_hb_set_mass_csc (force
 *  per unit velocity); replaces Rayleigh damping. Since 1.6 (FRICREG_1.6).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_EINVAL; FRICREG_ENONFINITE;
 *  FRICREG_ENOTSYM; FRICREG_ENOMEM, as fricreg_hb_set_mass_csc. */
FRICREG_API int fricreg_hb_set_damping_csc(fricreg_hb *hb, size_t ndof, int flags,
                                           const int64_t colptr[], const int64_t rowind[],
                                           const double values[]);

/** Set one model matrix, in any storage: the one setter of M, K and C, as
 *  fricreg_structure_set_matrix's (the same arguments, the structure's J aside), of which
 *  fricreg_hb_set_mass, _set_stiffness, _set_damping and their _csc forms are each one case
 *  (same checks and results; their messages name them, this one's "set_matrix"). A compressed
 *  matrix makes the model sparse, as fricreg_hb_set_mass_csc. Copied. Since 1.7 (FRICREG_1.7).
 *  hb      in/out: the driver; on failure the model is the one before the call.
 *  which   enum fricreg_model_matrix: FRICREG_MASS, FRICREG_STIFFNESS (nonsingular, as
 *          fricreg_hb_set_stiffness) or FRICREG_DAMPING (replaces Rayleigh damping); each
 *          symmetric to 1e-12 of the rows' scales, its symmetric part kept.
 *  nrows, ncols  both the driver's ndof.
 *  format  enum fricreg_matrix_format: FRICREG_MATRIX_DENSE (values[ndof ndof] row-major, no
 *          flag; ptr and ind not read, NULL from C), or FRICREG_MATRIX_CSR or
 *          FRICREG_MATRIX_CSC, each combined with | with enum fricreg_sparse_flags (base; whole
 *          or by one triangle).
 *  ptr     compressed: ptr[ndof + 1], from the base.
 *  ind     compressed: ind[nnz], the column (CSR) or row (CSC) of each entry.
 *  values  values[ndof ndof] (dense) or values[nnz] (compressed), the matrix's units.
 *  Returns FRICREG_OK; FRICREG_ENULL (hb, values, ptr of a compressed matrix, or ind or values
 *  with nnz > 0); FRICREG_EINVAL (which or format unknown, FRICREG_CONTACTS, flags with a
 *  dense matrix or both CSR and CSC, ptr not from the base or
 *  decreasing, an index out of range, an entry outside the triangle given; during a solve);
 *  FRICREG_ESIZE if nrows or ncols is not ndof; FRICREG_ENONFINITE; FRICREG_ENOTSYM;
 *  FRICREG_ENOMEM. The message names the array and the entry. */
FRICREG_API int fricreg_hb_set_matrix(fricreg_hb *hb, int which, size_t nrows, size_t ncols,
                                      int format, const int64_t ptr[], const int64_t ind[],
                                      const double values[]);

/** Rayleigh damping C = a0 M + a1 K (a0 in 1/s, a1 in s, both >= 0), formed from the M and K
 *  in force at each frequency, so it follows later set_mass and set_stiffness calls; replaces
 *  a damping matrix. Mode k of circular frequency w_k gets the damping ratio
 *  a0/(2 w_k) + a1 w_k/2.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb is NULL; FRICREG_ENONFINITE if a0 or a1 is NaN
 *  or infinite; FRICREG_EINVAL if a0 < 0 or a1 < 0. Since 1.6. */
FRICREG_API int fricreg_hb_set_rayleigh(fricreg_hb *hb, double a0, double a1);

/** Set the Jenkins elements: where they act and their parameters.
 *
 *  m            must equal the driver's element count.
 *  ndof         must equal the driver's degrees of freedom.
 *  J[m ndof]    row-major: element i's relative displacement is q_i = sum_k J[ndof i + k] x_k
 *               (dimensionless for displacement dofs); finite, each row non-zero. Its forces
 *               act on the structure as J^T f.
 *  kt[m]        tangential stiffnesses > 0 (finite), force per unit displacement.
 *  mun[m]       slip bounds mu N >= 0 (finite), force units.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb, J, kt or mun is NULL; FRICREG_ESIZE if m or ndof
 *  is not the driver's; FRICREG_ENONFINITE if an entry is NaN or infinite; FRICREG_EINVAL if
 *  a row of J is zero, some kt[i] <= 0 or mun[i] < 0; FRICREG_ENOMEM (since 1.8: 2 m doubles).
 *  All inputs are checked before anything changes. Since 1.6. Since 1.8 this and the other
 *  per-kind setters (set_jenkins, set_iwan, set_normal_elements, set_jenkins_normal,
 *  set_iwan_normal, set_jenkins_2d_normal) are thin wrappers kept for the ABI: each checks its
 *  arguments, then replaces the elements held by m elements of its one kind, as
 *  fricreg_hb_clear_elements and fricreg_hb_add_elements would, with the same answers bit for
 *  bit as before; new code may use fricreg_hb_add_elements, which also mixes kinds. */
FRICREG_API int fricreg_hb_set_elements(fricreg_hb *hb, size_t m, size_t ndof, const double J[],
                                        const double kt[], const double mun[]);

/** fricreg_hb_set_elements under the structure's name (fricreg_structure_set_jenkins: the
 *  same arguments and meaning), its messages naming set_jenkins. Since 1.7 (FRICREG_1.7).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_ENONFINITE; FRICREG_EINVAL, as
 *  fricreg_hb_set_elements. */
FRICREG_API int fricreg_hb_set_jenkins(fricreg_hb *hb, size_t m, size_t ndof, const double J[],
                                       const double kt[], const double mun[]);

/** Set Iwan elements instead: element i is ns Jenkins sliders in parallel on row i of J
 *  (fricreg_iwan.h in 1-D: slider s of stiffness k[ns i + s] and slip force phi[ns i + s]),
 *  its force the sum of theirs, f_i = sum_s k_s (q_i − w_s) with |k_s (q_i − w_s)| <= phi_s. In
 *  the residual each element's force coefficients and exact Jacobian come from
 *  fricreg_aft_iwan_exact (the stabilized hysteresis of fricreg_aft.h, slider by slider).
 *  fricreg_hb_set_elements is the case ns = 1 (k = kt, phi = mun) and replaces what this sets,
 *  as this replaces what it set; an Iwan element with ns sliders gives the displacements of ns
 *  Jenkins elements on ns copies of its row of J. Every element has the same ns (give a slider
 *  phi = 0 to drop it: it carries nothing).
 *
 *  m            must equal the driver's element count.
 *  ndof         must equal the driver's degrees of freedom.
 *  J[m ndof]    row-major, as fricreg_hb_set_elements.
 *  ns           sliders per element, 1 <= ns <= FRICREG_HB_MAX_SLIDERS.
 *  k[m ns]      row-major (element i's sliders at k[ns i .. ns i + ns − 1]): stiffnesses > 0
 *               (finite), force per unit displacement.
 *  phi[m ns]    same layout: slip forces >= 0 (finite), force units.
 *
 *  Allocates 2 m ns doubles (the previous set's freed on success).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb, J, k or phi is NULL; FRICREG_ESIZE if m or ndof is
 *  not the driver's; FRICREG_ENONFINITE if an entry is NaN or infinite; FRICREG_EINVAL if a row
 *  of J is zero, ns is out of its range, some k <= 0 or phi < 0; FRICREG_ENOMEM. All inputs are
 *  checked before anything changes, and nothing changes on failure. Since 1.6. */
FRICREG_API int fricreg_hb_set_iwan(fricreg_hb *hb, size_t m, size_t ndof, const double J[],
                                    size_t ns, const double k[], const double phi[]);

/** Set Jenkins elements under a normal load with lift-off instead: element i has a
 *  tangential relative displacement u_i = Jt_i x and a normal one g_i = Jn_i x (positive when
 *  the surfaces press together), the normal force N_i = max(0, N0_i + kn_i g_i) (the normal
 *  spring acts only in contact, g_i < −N0_i/kn_i opens it) and the tangential force f_i of a
 *  Jenkins element of stiffness kt_i with the slip bound mu_i N_i(θ), 0 while open (the law of
 *  fricreg_jenkins_trial_normal, fricreg_jenkins.h). The forces act on the structure as
 *  Jt^T f + Jn^T N in the model of the header comment (N0 included: a preload pushes the
 *  structure apart along Jn). In the residual each element's f and N coefficients and their
 *  exact Jacobian with respect to (u, g) come from fricreg_aft_jenkins_normal_exact. The
 *  condensation is on both coordinates: 2 m rows of J (element i's rows 2i tangential, 2i + 1
 *  normal), nq = 2 m (2H + 1) unknowns for fricreg_hb_solve and fricreg_hb_continue, element
 *  i's u coefficients at q[2 (2H+1) i ..] and its g coefficients right after them, at
 *  q[(2i + 1)(2H + 1) ..]. With kn = 0 and N0 >= 0 the element is fricreg_hb_set_elements's
 *  with mun = mu N0 (on the tangential rows; g then carries no force). The static term now has
 *  the load −Jn^T N_0: K x0 = −Jt^T f_0 − Jn^T N_0.
 *
 *  Replaces the elements of fricreg_hb_set_elements and fricreg_hb_set_iwan, which replace
 *  these in turn (back to m rows, nq = m (2H + 1)); a mix of kinds is fricreg_hb_add_elements's.
 *
 *  m            must equal the driver's element count.
 *  ndof         must equal the driver's degrees of freedom.
 *  Jt[m ndof]   row-major, tangential rows as fricreg_hb_set_elements's J: finite, each row
 *               non-zero.
 *  Jn[m ndof]   row-major, normal rows, likewise.
 *  kt[m]        tangential stiffnesses > 0 (finite), force per unit displacement.
 *  mu[m]        friction coefficients >= 0 (finite), nondimensional.
 *  n0[m]        preloads N0 (finite), force units: N at g = 0 (negative: a gap −N0/kn).
 *  kn[m]        normal stiffnesses >= 0 (finite), force per unit displacement; 0: N = max(0, N0).
 *
 *  Allocates 4 m doubles, and the first time the buffers for 2 m rows (the solves Y_h, the
 *  condensation G_h and Newton's matrix of order 2 m (2H + 1): O(H m ndof + (m H)²) doubles),
 *  which stay for the driver's life (the previous ones freed on success).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb, Jt, Jn, kt, mu, n0 or kn is NULL; FRICREG_ESIZE if
 *  m or ndof is not the driver's; FRICREG_ENONFINITE if an entry is NaN or infinite;
 *  FRICREG_EINVAL if a row of Jt or Jn is zero, some kt[i] <= 0, mu[i] < 0 or kn[i] < 0;
 *  FRICREG_ENOMEM. All inputs are checked before anything changes, and nothing changes on
 *  failure. Since 1.6 (FRICREG_1.6). */
FRICREG_API int fricreg_hb_set_normal_elements(fricreg_hb *hb, size_t m, size_t ndof,
                                               const double Jt[], const double Jn[],
                                               const double kt[], const double mu[],
                                               const double n0[], const double kn[]);

/** fricreg_hb_set_normal_elements under the structure's name
 *  (fricreg_structure_set_jenkins_normal: the same arguments and meaning), its messages naming
 *  set_jenkins_normal. Since 1.7 (FRICREG_1.7).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_ENONFINITE; FRICREG_EINVAL;
 *  FRICREG_ENOMEM, as fricreg_hb_set_normal_elements. */
FRICREG_API int fricreg_hb_set_jenkins_normal(fricreg_hb *hb, size_t m, size_t ndof,
                                              const double Jt[], const double Jn[],
                                              const double kt[], const double mu[],
                                              const double n0[], const double kn[]);

/** Set Iwan elements under a normal load with lift-off instead: element i is ns sliders in
 *  parallel on the tangential row Jt_i (as fricreg_hb_set_iwan), slider s of stiffness
 *  k[ns i + s] bounded by mu[ns i + s] N_i, with the normal force N_i = max(0, N0_i + kn_i g_i)
 *  of fricreg_hb_set_normal_elements on the normal row Jn_i (the law of
 *  fricreg_structure_set_iwan_normal and of fricreg_iwan_trial_normal with phi_s = mu_s N0).
 *  In the residual each slider's force coefficients and exact Jacobian come from
 *  fricreg_aft_jenkins_normal_exact (the stabilized hysteresis of fricreg_aft.h, slider by
 *  slider, each forgetting its place while the element is open): the element's tangential
 *  force and the tangential rows of its Jacobian are the sums over its sliders, its normal
 *  force and normal rows the normal law's. The layout of the unknowns (2 m rows of J,
 *  nq = 2 m (2H + 1)) and everything else are fricreg_hb_set_normal_elements's, which is this
 *  call with ns = 1 (k = kt, bit for bit). Stability, continuation, the nonlinear modes (the
 *  stuck stiffness the sum of the sliders' k of mu > 0 while N0 > 0) and the truncation
 *  estimate take them as they take those. Every element has the same ns (give a slider
 *  mu = 0 to drop it).
 *
 *  m            must equal the driver's element count.
 *  ndof         must equal the driver's degrees of freedom.
 *  Jt[m ndof]   row-major, tangential rows: finite, each row non-zero.
 *  Jn[m ndof]   row-major, normal rows, likewise.
 *  ns           sliders per element, 1 <= ns <= FRICREG_HB_MAX_SLIDERS.
 *  k[m ns]      row-major (element i's sliders at k[ns i .. ns i + ns − 1]): stiffnesses > 0
 *               (finite), force per unit displacement.
 *  mu[m ns]     same layout: friction coefficients >= 0 (finite), nondimensional.
 *  n0[m]        preloads N0 (finite), force units: N at g = 0 (negative: a gap −N0/kn).
 *  kn[m]        normal stiffnesses >= 0 (finite), force per unit displacement.
 *
 *  Allocates 4 m + 2 m ns + 2 (2H + 1) + 4 (2H + 1)² doubles (ns > 1: the sliders and one
 *  slider's AFT), and the first time the buffers for 2 m rows as fricreg_hb_set_normal_elements
 *  (the previous set's freed on success). Cost of a residual with its Jacobian: ns times a
 *  lift-off Jenkins element's.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb, Jt, Jn, k, mu, n0 or kn is NULL; FRICREG_ESIZE if m
 *  or ndof is not the driver's; FRICREG_ENONFINITE if an entry is NaN or infinite;
 *  FRICREG_EINVAL if a row of Jt or Jn is zero, ns is out of its range, some k <= 0, mu < 0 or
 *  kn < 0; FRICREG_ENOMEM. All inputs are checked before anything changes, and nothing changes
 *  on failure. Since 1.7 (FRICREG_1.7). */
FRICREG_API int fricreg_hb_set_iwan_normal(fricreg_hb *hb, size_t m, size_t ndof, const double Jt[],
                                           const double Jn[], size_t ns, const double k[],
                                           const double mu[], const double n0[], const double kn[]);

/** Set 3-D contact elements instead: element i is a 2-D Jenkins element on its two tangential
 *  rows of Je (an isotropic Coulomb disk |f_i| <= mu_i N_i with the radial return) under the
 *  normal law N_i = max(0, N0_i + kn_i g_i) on its normal row of Jn, lifting off where
 *  N0 + kn g < 0 with the tangential memory reset: the element of
 *  fricreg_structure_set_jenkins_2d_normal (the same arguments and layouts), in the frequency
 *  domain. In the residual each element's force coefficients (fx, fy, N) and their Jacobian
 *  come from fricreg_aft_jenkins_2d_normal_sampled at N = 64 (2H + 1) samples rounded up to a
 *  power of two and at N/2, extrapolated as 2 F(N) − F(N/2) (Richardson): the return mapping
 *  at samples lags the continuous element by a first-order term in 1/N where the slip turns
 *  (fricreg_aft.h), which this removes (the AFT at N = 1024 alone put the test's lift-off case
 *  7.7e-4 of the RMS off at H = 15). The driver's AFT workspaces grow to these samples here.
 *  Each element has three rows of J (x, y, normal: the unknowns nq = 3 m (2H + 1), element i's
 *  at 3 i (2H + 1): ux's coefficients, uy's, g's); everything else is
 *  fricreg_hb_set_jenkins_normal's: stability, continuation in Ω or the level, the nonlinear
 *  modes (stuck stiffness kt on both tangential rows and kn on the normal one while N0 > 0)
 *  and the truncation estimate take them as they take those. A closed element with kn = 0
 *  whose motion stays on the x axis is the lift-off Jenkins element of
 *  fricreg_hb_set_jenkins_normal on that row, up to the sampling of the kinks (1.3e-5 of the
 *  RMS at H = 7). On a 2-dof mass sliding on an inclined contact at H = 15 the RMS agrees with
 *  a long Newmark integration of fricreg_structure_set_jenkins_2d_normal, extrapolated in dt,
 *  to 3.0e-6 and 1.9e-6 of each dof's RMS (closed, slipping on a curved path) and 4.1e-6 and
 *  1.1e-6 (lifting off in every period), within the truncation estimate and the reference's
 *  own error (tests/test_hb_contact_3d.c).
 *
 *  m            must equal the driver's element count.
 *  ndof         must equal the driver's degrees of freedom.
 *  Je[2m ndof]  row-major, two tangential rows per element (x, y): finite, each row non-zero.
 *  Jn[m ndof]   row-major, one normal row per element, likewise.
 *  kt[m]        tangential stiffnesses > 0 (finite), force per unit displacement.
 *  mu[m]        friction coefficients >= 0 (finite), nondimensional.
 *  n0[m]        preloads N0 (finite), force units: N at g = 0 (negative: a gap −N0/kn).
 *  kn[m]        normal stiffnesses >= 0 (finite), force per unit displacement.
 *
 *  Allocates 4 m doubles, the first time the buffers for 3 m rows (as
 *  fricreg_hb_set_normal_elements does for 2 m), and two AFT workspaces of O(N H) doubles (the
 *  previous one freed on success). Cost of a residual with its Jacobian: per element, for each
 *  of its 3 (2H + 1) unknowns, one to three marches of a period (more where slips placed a
 *  stick) and 7/3 FFTs on average, at N and at N/2 samples: 66 ms a continuation point at
 *  H = 15 for one element, about 100 times fricreg_hb_set_jenkins_normal's element with its
 *  exact AFT (bench/hb_contact_3d.c).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb, Je, Jn, kt, mu, n0 or kn is NULL; FRICREG_ESIZE if m
 *  or ndof is not the driver's; FRICREG_ENONFINITE if an entry is NaN or infinite;
 *  FRICREG_EINVAL if a row of Je or Jn is zero, some kt <= 0, mu < 0 or kn < 0; FRICREG_ENOMEM.
 *  All inputs are checked before anything changes, and nothing changes on failure. Since 1.7
 *  (FRICREG_1.7). */
FRICREG_API int fricreg_hb_set_jenkins_2d_normal(fricreg_hb *hb, size_t m, size_t ndof,
                                                 const double Je[], const double Jn[],
                                                 const double kt[], const double mu[],
                                                 const double n0[], const double kn[]);

/** Add me friction elements of one type (fricreg_element.h: fricreg_element_lookup,
 *  fricreg_element_sliders) beside those the driver holds, of any types: one model may hold
 *  elements of every type of fricreg_element.h together, each evaluated by its own kind's AFT.
 *  The driver's model is whole, and can be solved, once it holds fricreg_hb_create's m
 *  elements; the solves refuse it before (FRICREG_EINVAL).
 *
 *  The AFTs. jenkins (1 row: kt, mun) and iwan (1 row: k[ns], phi[ns], any ns up to
 *  FRICREG_HB_MAX_SLIDERS) run the exact AFT of fricreg_hb_set_iwan; jenkins_normal (2 rows,
 *  tangential then normal: kt, mu, kn, n0, gap) and iwan_normal (2 rows: k[ns], mu[ns], kn, n0,
 *  gap) the exact one of fricreg_hb_set_jenkins_normal and _set_iwan_normal; contact_3d (3
 *  rows, x, y, then normal: kt, mu, kn, n0, gap) the sampled one of
 *  fricreg_hb_set_jenkins_2d_normal. Their normal law is N = max(0, n0 + kn g): gap must be 0
 *  (the preload in n0; FRICREG_EINVAL otherwise, a gap not being folded into n0 − kn gap,
 *  which would round). Every other type (jenkins_2d, jenkins_3d, iwan_2d, iwan_3d, spring, and
 *  dahl, and any law added to the table) runs the march of its fricreg_element_eval: its dim
 *  components
 *  at N = 64 (2H + 1) samples of the period, rounded up to a power of two, marched from its
 *  sliders at the middle of the orbit (a slider stuck all period then equals the exact 1-D
 *  AFT's centred one, a 2-D one the 3-D contact's, in its orbit's enclosing circle) until the
 *  state repeats (a slow contraction found by Newton's method on the periodic state), the
 *  coefficients by FFT; a 1-D law with state marched through the orbit's turns between the
 *  samples too (dahl: its loop energy equals a time-domain march of the same orbit to 1e-8), a
 *  law with state on more components extrapolated by Richardson over
 *  N and N/2 samples (its samples lag by a term in 1/N: 4e-5 of the scale for jenkins_2d moved
 *  along one axis against the exact 1-D Jenkins at H = 3), its Jacobian the exact one of the
 *  sampled march (its sliders' or its state's sensitivities carried through the period, started
 *  periodic);
 *  a law without state's Jacobian from its tangent. A marched step costs about three periods
 *  of eval a Newton iteration: the continuation of NLvib's chain with two jenkins_2d elements
 *  at H = 7 takes 9 s (test hb_march; the exact jenkins run 0.05 s), and the default start
 *  (no q0) costs most; pass q0 where a solution nearby is known.
 *
 *  Element i sees the dim = fricreg_element_dim(type) rows i dim .. i dim + dim − 1 of
 *  J[me dim * ndof] (row-major, dimensionless for displacement dofs; in the type's order: the
 *  tangential components, then the normal displacement g), appended after the rows of the
 *  elements held: the unknowns q are the elements' rows in the order they were added, each row
 *  its 2H + 1 coefficients (nq = rows (2H + 1)). params[me np] holds each element's
 *  np = fricreg_element_nparams(type) parameters in the type's layout, units the model's
 *  (stiffnesses force per displacement, slip bounds force, mu nondimensional, n0 force).
 *
 *  A model of one kind gives the answers of its per-kind setter bit for bit. A mix works with
 *  every solve, continuation, nonlinear mode and Hill's stability; the exact monodromy takes
 *  models of one kind only (under FRICREG_HB_STABILITY_AUTO a mix gets Hill's method, as a 3-D
 *  contact model does; FRICREG_HB_STABILITY_MONODROMY refuses it with FRICREG_EINVAL).
 *
 *  Copied. Adding elements is a model change: the solution, branch and backbone are dropped.
 *  me = 0 adds nothing (J and params may then be NULL). Allocates the sliders' 2 S doubles (S
 *  of all the elements held) and, the first time the elements' rows outgrow them, the buffers
 *  sized by the rows (as fricreg_hb_set_normal_elements says), which stay. Since 1.8
 *  (FRICREG_1.8).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL (hb, type, or J or params with me > 0); FRICREG_ESIZE if
 *  ndof is not the driver's or the elements would number more than fricreg_hb_create's m;
 *  FRICREG_EINVAL if an element's parameters are out of range (the message names the element
 *  and says why, as fricreg_element_explain), a gap is not 0 on an exact AFT's type, a row
 *  of J is zero, the type is marched and has state but no tangents for the march to chain its
 *  Jacobian through (a law added to the table without its slider or state tangents; the
 *  message says so, even with me = 0), or the call comes from the monitor;
 *  FRICREG_ENONFINITE (an entry of J or params); FRICREG_ENOMEM. On failure the elements held are unchanged. */
FRICREG_API int fricreg_hb_add_elements(fricreg_hb *hb, const fricreg_element_type *type, size_t me,
                                        size_t ndof, const double J[], const double params[]);

/** Remove every element (fricreg_hb_add_elements's, the per-kind setters'); the buffers stay. A
 *  model change. Since 1.8 (FRICREG_1.8). Returns FRICREG_OK; FRICREG_ENULL; FRICREG_EINVAL
 *  from the monitor. */
FRICREG_API int fricreg_hb_clear_elements(fricreg_hb *hb);

/** The number of elements the driver holds, of all types (0 for hb = NULL). Since 1.8
 *  (FRICREG_1.8). */
FRICREG_API size_t fricreg_hb_element_count(const fricreg_hb *hb);

/** Set parameter index of the elements first .. first + count − 1 to one value, in place: a
 *  parameter study or a fit (fricreg_fit_set_model_hb) moves a value without adding the
 *  elements again. index is in fricreg_element.h's layout of each element's type, as
 *  fricreg_hb_nma_point_sensitivities's FRICREG_HB_NMA_PARAM_ELEMENT: jenkins 0 kt, 1 the slip
 *  force; iwan k[ns] then the slip forces phi[ns]; jenkins_normal and contact_3d 0 kt, 1 mu,
 *  2 kn, 3 n0, 4 gap; iwan_normal k[ns], mu[ns], kn, n0, gap; a marched type (any other) its own
 *  layout. The per-kind setters' elements (fricreg_hb_set_jenkins, ...) have their types'
 *  layouts. The value is checked as fricreg_hb_add_elements checks it (a stiffness > 0, a slip
 *  force, mu or kn >= 0; a marched type's by fricreg_element_explain; a gap only 0, HB's normal
 *  law has none). A model change, as fricreg_hb_set_stiffness's: a backbone's points are read
 *  only without x after it (fricreg_hb_nma_point), the elements' earlier values gone.
 *
 *  first, count  the elements, from 0 in the order they were set or added, count >= 1.
 *  index         the parameter, < each element's parameter count.
 *  value         its new value, in the parameter's units.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb is NULL; FRICREG_EINVAL if the range is empty or
 *  beyond the elements held, index is beyond an element's parameters, the value is out of its
 *  range for an element of the range (the message names it), or the call comes from the
 *  monitor; FRICREG_ENONFINITE if value is NaN or infinite. On failure no element changes.
 *  Cost O(count), no allocation. Since 1.9 (FRICREG_1.9). */
FRICREG_API int fricreg_hb_set_element_param(fricreg_hb *hb, size_t first, size_t count,
                                             size_t index, double value);

/** Read parameter index of element e (fricreg_hb_set_element_param's layout; a gap reads 0).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb or value is NULL; FRICREG_EINVAL if e is not an
 *  element held or index is beyond its parameters. Nothing is written on failure. Since 1.9
 *  (FRICREG_1.9). */
FRICREG_API int fricreg_hb_get_element_param(fricreg_hb *hb, size_t e, size_t index, double *value);

/** Set the harmonic excitation of the fundamental, p(t) = pc cos Ωt + ps sin Ωt.
 *
 *  ndof      must equal the driver's degrees of freedom.
 *  pc[ndof]  cosine amplitudes (finite), force units.
 *  ps[ndof]  sine amplitudes (finite), force units.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb, pc or ps is NULL; FRICREG_ESIZE if ndof is not
 *  the driver's; FRICREG_ENONFINITE if an entry is NaN or infinite. Since 1.6. */
FRICREG_API int fricreg_hb_set_excitation(fricreg_hb *hb, size_t ndof, const double pc[],
                                          const double ps[]);

/** Newton's stopping rule: converged when the largest entry of the residual (R) is at most
 *  tol times the problem's displacement scale (the largest |q| of the iterate and of the
 *  response with the elements removed, J D_h^-1 P_h), after at least one iteration.
 *  A continuation's corrector (fricreg_hb_continue) also stops where the solves' rounding
 *  keeps the residual above that: where an iteration from the second on does not halve the
 *  largest |R_j|, and that entry is at most DBL_EPSILON κ₁(D_h) times the scale, κ₁ the
 *  largest over h of D_h's 1-norm condition number at the iterate's Ω, estimated from its
 *  LU factor (KLU's klu_condest, or LAPACK's zgecon on a dense model; N. J. Higham, Accuracy
 *  and Stability of Numerical Algorithms, 2nd ed., SIAM 2002, Ch. 7 and 15). The corrector
 *  moves Ω, so D_h is factored anew at each iteration and the solves' forward error, up to
 *  about u κ₁ of q, is noise in (R) that no iteration lowers: a tolerance below it failed
 *  such continuations until 1.9 ("the corrector did not converge": a 1000-dof chain at the
 *  default 1e-10). The estimate is only made at such a stall, so a corrector that converges
 *  is unchanged. Point solves (fricreg_hb_solve) keep Ω fixed and converge below it.
 *
 *  tol       0 < tol < 1 (finite), relative.
 *  max_iter  1 <= max_iter <= 1000 iterations per solve (and per continuation step).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb is NULL; FRICREG_ENONFINITE if tol is NaN or
 *  infinite; FRICREG_EINVAL if tol or max_iter is out of its range. Since 1.6. */
FRICREG_API int fricreg_hb_set_newton(fricreg_hb *hb, double tol, int max_iter);

/** The continuation's step control, in the arclength of the scaled unknowns (q divided by the
 *  largest |q| of the starting solution, raised to the largest |q| reached along the branch, Ω
 *  by |Ω1 − Ω0|, so ds = 0.01 is about a hundredth of the interval on a flat branch). Since
 *  1.7 the step follows the corrector's convergence and the branch's curvature (E. L. Allgower
 *  and K. Georg, "Numerical Continuation Methods", Springer 1990, Ch. 6): after each point the
 *  next step is ds / f, f = max(κ/0.25, (δ/ds)/0.3, α/10°, its/4) kept within [1/2, 2] (up to
 *  ds_max), κ the contraction of the corrector's first two Newton steps, δ its first step, α
 *  the angle between the tangents at the last two points, its its iterations. A step is
 *  rejected and halved when the corrector fails, ends farther than 4 ds from the last point
 *  (it would have jumped along the branch, e.g. across a sharp peak), turns the chord by more
 *  than twice the tangent's angle (it joined another part of the branch), turns the tangent
 *  by more than 20° or contracts by more than 1/2 in its first two steps, except at a kink of
 *  the branch (where the elements' stick/slip or contact pattern changes, the exact AFT's
 *  Jacobian is not smooth): a converged corrector whose tangent turned by less than 90° is
 *  accepted once halving ds did not lower the angle and the contraction by a quarter, or when
 *  halving would take ds below ds_min; there, since 1.8, also one that the jump or the chord
 *  refused but that converged within 1e-4 of the last point (in the scaled unknowns) with its
 *  chord turned by less than 90°: a fold or kink too fine to resolve, such as a sampled AFT's
 *  where a slider starts to stick. Below ds_min the step is tried once more along the secant
 *  of the last two points; then the continuation stops with
 *  FRICREG_EINTEGRATOR. (Until 1.6: grown by 1.5 after at most 4 corrector iterations, halved
 *  after a failure or a corrector that ended farther than ds/2 from its predictor; the
 *  defaults are unchanged.)
 *
 *  ds          first step, ds_min <= ds <= ds_max (finite); default 0.02.
 *  ds_min      smallest step, > 0; default 1e-6.
 *  ds_max      largest step, <= 1; default 0.1.
 *  max_points  bound on the points stored, >= 2; reaching it stops with FRICREG_EWORK;
 *              default 2000.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb is NULL; FRICREG_ENONFINITE if ds, ds_min or
 *  ds_max is NaN or infinite; FRICREG_EINVAL if they are out of order or range (ds <= 0
 *  included) or max_points < 2. Since 1.6. */
FRICREG_API int fricreg_hb_set_continuation(fricreg_hb *hb, double ds, double ds_min, double ds_max,
                                            size_t max_points);

/** \name Monitoring and stopping a solve
 *  Every solving call (fricreg_hb_solve, fricreg_hb_continue, fricreg_hb_continue_level,
 *  fricreg_hb_peak, fricreg_hb_nma, fricreg_hb_truncation_error) spends its work in Newton
 *  iterations: at one frequency, in the continuation's corrector (its points,
 *  fricreg_hb_solve's start without a guess, the bifurcations' bisection, the peak's
 *  location) and in a nonlinear mode's points. Before each Newton step the driver counts it
 *  and calls the monitor (fricreg_hb_set_monitor); a nonzero return, or more steps in one call
 *  than fricreg_hb_set_max_iterations allows, stops the call there.
 *
 *  A stopped call returns FRICREG_EWORK, its message "<function>: stopped by the monitor after
 *  N Newton iterations" (or naming the bound), and leaves what its other failures leave: no
 *  solution is written (fricreg_hb_solve's q and the kept solution are untouched, as
 *  fricreg_hb_peak's omega and rms); a continuation keeps the points reached, which are the
 *  first points of the same call unstopped, bit for bit, with no bifurcations located
 *  (fricreg_hb_bifurcations is 0); fricreg_hb_nma keeps the backbone's points reached. No
 *  fallback or retry of the call runs after a stop. Between two Newton steps the work is
 *  bounded (a residual, a real LU of order m (2H + 1) + 2, at most 11 residuals of the line
 *  search, and at a new frequency the H + 1 factors and at a stored point Hill's method), so a
 *  bound on the steps bounds the call.
 *  \{ */

/** Called before each Newton step of a solving call (the group's comment).
 *
 *  user        fricreg_hb_set_monitor's, unchanged.
 *  iterations  the Newton steps of this call so far, this one included: 1 at the first call,
 *              one more at each.
 *  parameter   the continued parameter at the iterate: Ω (rad/s) in fricreg_hb_continue,
 *              fricreg_hb_peak and fricreg_hb_truncation_error; the excitation level λ in
 *              fricreg_hb_continue_level and in fricreg_hb_solve (1 with a guess; along its start's branch in λ without one);
 *              the modal amplitude a in fricreg_hb_nma and fricreg_hb_nma_continue.
 *  residual    the iterate's largest residual entry over Newton's bound (fricreg_hb_set_newton:
 *              converged at most 1), nondimensional.
 *
 *  Return 0 to go on, nonzero to stop the call (FRICREG_EWORK). The monitor may call the
 *  getters (fricreg_hb_points, fricreg_hb_point, fricreg_hb_point_level,
 *  fricreg_hb_point_stability, fricreg_hb_bifurcations, fricreg_hb_bifurcation,
 *  fricreg_hb_bifurcation_level, fricreg_hb_nma_points, fricreg_hb_nma_point without x, the
 *  error getters); any other call on the driver from it returns FRICREG_EINVAL and changes
 *  nothing; it must not free the driver. Since 1.7 (FRICREG_1.7). */
typedef int (*fricreg_hb_monitor)(void *user, int64_t iterations, double parameter,
                                  double residual);

/** Install the monitor of the solving calls (NULL, the default, removes it); user is passed
 *  back unchanged. A monitor that returns 0 changes no result: the calls' results are those
 *  without one, bit for bit.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb is NULL; FRICREG_EINVAL if called from the monitor.
 *  Since 1.7 (FRICREG_1.7). */
FRICREG_API int fricreg_hb_set_monitor(fricreg_hb *hb, fricreg_hb_monitor fn, void *user);

/** Bound the Newton steps one solving call may take (the group's comment) at total >= 1, or
 *  remove the bound with 0 (the default). A call that would take more returns FRICREG_EWORK
 *  as if the monitor had stopped it, its message naming the bound; the count restarts at each
 *  call.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb is NULL; FRICREG_EINVAL if total < 0 or called
 *  from the monitor. Since 1.7 (FRICREG_1.7). */
FRICREG_API int fricreg_hb_set_max_iterations(fricreg_hb *hb, int64_t total);

/** \} */

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
 *  fail, 1.6's solution at λ = 1 if it had one. Should that fail too (a response homogeneous
 *  in the forcing, e.g. a unilateral spring without gap or preload, whose level branch is a
 *  ray no easier than its end), the continuation in Ω to omega, points not stored, from the
 *  nearest of Ω (1 + d) and Ω / (1 + d), d = 0.05, 0.1, 0.2, 0.4, 0.8, where 1.6's start
 *  converges (since 1.7); on its failure too, 1.6's start's error is returned. With
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
 *  on the oscillator and the 3-dof chain of tests/test_hb_truncation.c, where the estimate is
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

/** Largest number of Fourier coefficients ndof (2H + 1) of Hill's method
 *  (fricreg_hb_set_stability): its companion matrix, of order 2 ndof (2H + 1), is dense. */
#define FRICREG_HB_MAX_HILL 1024

/** The index of fricreg_hb_point_stability that names the driver's last solution (that of
 *  fricreg_hb_solve, or the last point of fricreg_hb_continue) rather than a stored point. */
#define FRICREG_HB_SOLUTION ((size_t)-1)

/** Compute the stability of every solution from now on (enable = 1), or stop (0, the default),
 *  by the method of fricreg_hb_set_stability_method: the exact monodromy of the orbit where
 *  every element is piecewise linear, Hill's method otherwise. Since 1.7 (FRICREG_1.7).
 *
 *  Hill's method (the only one before 1.8). A perturbation y(t) = e^{λt} p(t), p periodic, of
 *  a solution solves the quadratic eigenproblem (λ² M⊗I + λ (C⊗I + 2 M⊗∇) + S) P = 0 in the
 *  Fourier coefficients P of p (the full ndof (2H + 1) of them, not the condensed q), S the
 *  Jacobian of the HB equations (HB), K − (hΩ)² M ± hΩ C per harmonic plus J^T (∂F/∂q) J from
 *  the elements' exact AFT Jacobians, ∇ the derivative on one period's coefficients (Krack &
 *  Gross Sec. 5.3; G. W. Hill 1886). Solved as the eigenproblem of its companion matrix of
 *  order 2 ndof (2H + 1) by LAPACK's dgeev (since 1.8; GSL's gsl_eigen_nonsymm before); of
 *  its eigenvalues, each Floquet exponent repeated at λ + i k Ω, the 2 ndof of least |Im λ|
 *  (within ±Ω/2) are the Floquet exponents, μ = exp(2π λ/Ω) the multipliers. The elements'
 *  sliders enter through their stabilized hysteresis's Jacobian: their offsets, forgotten once
 *  they slip, are no state of their own, so beyond the verdict its multipliers are not the
 *  orbit's (on a Jenkins pair the largest is off by up to 0.44). A real negative multiplier
 *  appears as the pair Re λ ± iΩ/2; those of Im λ > 0 are selected before their conjugates, so
 *  each is counted once (two of them, as after a pair's collision on the negative real axis,
 *  give four exponents of one |Im λ|, of which |Im λ| alone could take the smaller twice);
 *  only a lone one is completed by its conjugate, counted twice. Cost per solution: about
 *  10 (2 ndof (2H + 1))³ flops, with ndof (2H + 1) <= FRICREG_HB_MAX_HILL; its matrices, 4
 *  (ndof (2H + 1))² + O(ndof (2H + 1)) doubles.
 *
 *  The exact monodromy (since 1.8), for 1-D Jenkins and Iwan elements, with or without lift-off
 *  (not the 3-D contact element): between the switches, which the exact AFT locates on the
 *  solution (slip onsets, stops, openings, touchdowns), the equations of motion linearized on
 *  the state (x, x', the offsets of the sliders that switch) are linear and time-invariant, so
 *  the monodromy matrix is the product Φ = e^{A_K Δt_K} S_K ⋯ S_1 e^{A_1 Δt_1} of the pieces'
 *  exponentials (Padé, scaling and squaring) and the saltation matrices S_k of the onsets and
 *  touchdowns, where a slider's offset starts following its element's displacement (R. I.
 *  Leine, H. Nijmeijer 2004, Ch. 7). A slider stuck over the whole period
 *  has a neutral multiplier 1, which is left out (like HB's offset ambiguity); one that slips
 *  once adds a 0, dropped. The 2 ndof left are the multipliers μ, λ = log μ Ω/2π the exponents
 *  (Im λ in (−Ω/2, Ω/2]). They are the HB orbit's own multipliers, which converge to an
 *  event-driven shooting's as H grows (8.6e-6 off at H = 40 on a Jenkins pair, where Hill's
 *  stays 0.44 away: tests/test_hb_monodromy.c). Cost per solution: a few (2 ndof +
 *  sliders)³ flops per switch, M^-1 applied once; no size limit but memory, 14 (2 ndof +
 *  sliders)² doubles (measured with the reference BLAS on a chain with 10 Jenkins elements at
 *  H = 3: 0.13 s a solution at 60 dofs, 35 s at 300, against 0.7 ms and 0.1 s for a
 *  solution's Newton from a near guess; OpenBLAS: 0.045 s and 6.1 s).
 *
 *  The condensed monodromy (since 1.9): the same on the model condensed onto the dofs B some row
 *  of J touches (R. R. Craig, M. C. C. Bampton 1968): x_I = Ψ x_B + Φ_k η, Ψ = −K_II^-1 K_IB,
 *  Φ_k the fixed-interface modes below 50 Ω (not H's: the orbit's monodromy does not depend on
 *  it; the error is about (Ω/ω_r)^4 of the first mode left out); the modes left out keep the
 *  multipliers of the structure's highest modes (from ω² and φ^T C φ), so all 2 ndof are
 *  reported. Its modes are computed once per model (LAPACK's dsygvd, O(ndof³)), its workspace
 *  made and grown by the solves (its order depends on Ω). K_II must be positive definite
 *  (FRICREG_ESINGULAR from the solve otherwise) and the model at most 4096 dofs
 *  (FRICREG_EINVAL; dense: about 9 ndof² doubles, 290 MB and 1.4 s of modes at 1500 dofs).
 *  Along continuations on chains of 60 and 300 dofs with 10 Jenkins elements, and on a gap
 *  chain with folds and Neimark–Sacker points, every point's count of unstable multipliers is
 *  the whole model's and the largest within 3e-4 of it, at 1.7-2.8x a point's cost without
 *  stability at 60 dofs and 1.3-1.9x at 300 and 1000 dofs, where the whole model's takes
 *  3.9-9.8x (60 dofs) and 190-410x (300 dofs) (bench/hb_stability_size.c, docs/stability.md).
 *
 *  Either way a solution is stable when every multiplier has |μ| <= 1 + 1e-6 (Re λ 2π/Ω <=
 *  1e-6), and each stored point then keeps 4 + 4 ndof numbers. The workspace of the method in
 *  force is allocated here, so the solves allocate nothing; elements set later that change the
 *  automatic choice have the other's made at the next solution. M must be nonsingular (checked
 *  at each solution: FRICREG_ESINGULAR from the solve). Enabling or disabling drops the stored
 *  points and the last solution (they have no stability). LAPACK reports a QR iteration that
 *  does not converge by a status, which the solve or continuation returns as
 *  FRICREG_EINTEGRATOR with a message naming Ω, the kept solution and points untouched.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb is NULL; FRICREG_EINVAL if enable is not 0 or 1, or
 *  the method in force is Hill's and ndof (2H + 1) > FRICREG_HB_MAX_HILL (the same from a
 *  solve where the elements changed since); FRICREG_ENOMEM (nothing changed). */
FRICREG_API int fricreg_hb_set_stability(fricreg_hb *hb, int enable);

/** The stability of a stored continuation point, or of the last solution.
 *
 *  k        the point's index, 0 <= k < fricreg_hb_points(hb), or FRICREG_HB_SOLUTION for the
 *           last solution (fricreg_hb_solve's, or the last point of fricreg_hb_continue).
 *  stable   out: 1 if every Floquet exponent has Re λ 2π/Ω <= 1e-6, else 0
 *           (fricreg_hb_set_stability).
 *  mu_max   out: the largest |Floquet multiplier|, exp(2π max Re λ/Ω), nondimensional.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb, stable or mu_max is NULL; FRICREG_EINVAL if
 *  stability is off, k is out of range, or (FRICREG_HB_SOLUTION) there is no solution (none
 *  since stability was turned on, or the model changed since). Since 1.7 (FRICREG_1.7). */
FRICREG_API int fricreg_hb_point_stability(fricreg_hb *hb, size_t k, int *stable, double *mu_max);

/** The Floquet exponents of a stored continuation point, or of the last solution, as the
 *  method in force computed them (fricreg_hb_set_stability_method; see fricreg_hb_set_stability).
 *
 *  k          the point's index, 0 <= k < fricreg_hb_points(hb), or FRICREG_HB_SOLUTION.
 *  nexp       must equal 2 ndof, the number of exponents.
 *  exponents  out: [nexp][2] row-major, (Re λ, Im λ) per exponent, rad/s, |Im λ| <= Ω/2,
 *             in no particular order; the multipliers are μ = exp(2π λ/Ω), and a solution is
 *             unstable by as many as have Re λ 2π/Ω > 1e-6.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb or exponents is NULL; FRICREG_ESIZE if nexp is not
 *  2 ndof; FRICREG_EINVAL as fricreg_hb_point_stability (stability off, k out of range, no
 *  solution); exponents is untouched on failure. Since 1.9 (FRICREG_1.9). */
FRICREG_API int fricreg_hb_point_exponents(fricreg_hb *hb, size_t k, size_t nexp,
                                           double exponents[]);

/** Largest order 2 ndof + sliders of the exact monodromy that FRICREG_HB_STABILITY_AUTO takes
 *  (fricreg_hb_set_stability_method): its matrices are dense, each switch costing a few times
 *  that order cubed (past it a solution takes seconds to minutes, a continuation of hundreds
 *  of points hours: chosen, not taken by default). */
#define FRICREG_HB_MAX_MONODROMY 512

/** How fricreg_hb_set_stability computes a solution's stability. */
enum fricreg_hb_stability_method {
    FRICREG_HB_STABILITY_AUTO = 0,      /**< where every element is piecewise linear (1-D
                                             Jenkins and Iwan elements, with or without
                                             lift-off): the condensed monodromy where
                                             32 <= ndof <= 1024 and the elements touch at most
                                             ndof/4 dofs (since 1.9), else the exact monodromy
                                             where its order 2 ndof + sliders is at most
                                             FRICREG_HB_MAX_MONODROMY, else the condensed one
                                             up to 4096 dofs (since 1.9); Hill's method
                                             otherwise (the default) */
    FRICREG_HB_STABILITY_HILL = 1,      /**< Hill's method, for any element */
    FRICREG_HB_STABILITY_MONODROMY = 2, /**< the exact monodromy of the orbit, at any order */
    FRICREG_HB_STABILITY_CONDENSED = 3  /**< the exact monodromy of the model condensed onto
                                             the dofs the elements touch (since 1.9) */
};

/** Choose how the stability of the next solutions is computed (fricreg_hb_set_stability);
 *  points already stored keep theirs. The default, FRICREG_HB_STABILITY_AUTO, takes the exact
 *  monodromy where the elements allow it (condensed where they touch few dofs: since 1.9;
 *  FRICREG_HB_STABILITY_MONODROMY gives 1.8's), which differs from 1.7's Hill's method beyond
 *  the verdict (the multipliers are the orbit's own); FRICREG_HB_STABILITY_HILL gives 1.7's
 *  results. Since 1.8 (FRICREG_1.8).
 *
 *  method   enum fricreg_hb_stability_method.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb is NULL; FRICREG_EINVAL if method is none of the
 *  enum, or when called from the monitor during a solve. A solve with
 *  FRICREG_HB_STABILITY_MONODROMY or _CONDENSED on elements that are not piecewise linear (the
 *  3-D contact element) returns FRICREG_EINVAL with a message. */
FRICREG_API int fricreg_hb_set_stability_method(fricreg_hb *hb, int method);

/** The method that computes the next solution's stability: FRICREG_HB_STABILITY_HILL,
 *  FRICREG_HB_STABILITY_MONODROMY or FRICREG_HB_STABILITY_CONDENSED, the automatic choice made
 *  for the elements set now (whether stability is on or not). Since 1.8 (FRICREG_1.8).
 *
 *  method   out: enum fricreg_hb_stability_method, never FRICREG_HB_STABILITY_AUTO.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb or method is NULL. */
FRICREG_API int fricreg_hb_get_stability_method(fricreg_hb *hb, int *method);

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

/** Status of the last failed call on hb. Returns that code, or FRICREG_OK if none (or hb
 *  NULL). A successful call does not clear it. Since 1.6. */
FRICREG_API int fricreg_hb_errcode(const fricreg_hb *hb);

/** Message of the last failed call on hb: names the function, the argument and its value.
 *  "" if none; "NULL HB driver" if hb is NULL. Owned by hb, valid until its next call.
 *  Since 1.6. */
FRICREG_API const char *fricreg_hb_errmsg(const fricreg_hb *hb);

/** Copy the last error message into buf[len], NUL-terminated and truncated to fit (for
 *  Fortran). Returns the full message length (excluding the NUL), as snprintf does; 0 and
 *  nothing written if buf is NULL or len is 0. Since 1.6. */
FRICREG_API size_t fricreg_hb_errmsg_copy(const fricreg_hb *hb, char *buf, size_t len);

/** \} */

#ifdef __cplusplus
}
#endif

#endif /* FRICREG_HB_H */
