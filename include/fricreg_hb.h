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
 * per Newton iteration m AFTs (O(H³) each) and a real LU of order m (2H + 1), or from
 * m (2H + 1) = 512 on, where most rows of the elements' Jacobian are a stiffness on the
 * diagonal (stuck elements, closed contacts' normal rows), the LU of its capacitance on the
 * other rows (docs/hb_size.md). A dense model
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
 *
 * This header declares the driver, its model, elements and settings, and the monitor; since 1.9
 * each of the driver's other objects has a header of its own, which this one includes:
 * fricreg_hb_forced.h (the solve, the continuation, its points, peak and bifurcations),
 * fricreg_hb_stability.h (Floquet multipliers and exponents), fricreg_hb_nma.h (nonlinear
 * modes) and fricreg_hb_qsma.h (quasi-static modal analysis).
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
 *  m          elements, m >= 1: no fixed bound, the memory is the limit (the dense Newton
 *             matrix of order nq + 1, nq = rows of J times 2H + 1, grows as its square:
 *             docs/hb_size.md).
 *  harmonics  H, 1 <= H <= FRICREG_HB_MAX_HARMONICS.
 *  out        out: the new object, released with fricreg_hb_free. Written only on success.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if out is NULL; FRICREG_EINVAL if ndof, m or H is out of
 *  its range; FRICREG_ENOMEM when the memory is short, or when a buffer's size for m
 *  elements overflows size_t or Newton's order overflows LAPACK's int. With no object to keep
 *  it, a failure has no message beyond its status, as for fricreg_ctx_create. Since 1.6. */
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
 *  bit as before; new code may use fricreg_hb_add_elements, which also mixes kinds.
 *  \deprecated Since 1.9, a wrapper kept for the ABI: new code calls fricreg_hb_add_elements (the
 *  equivalence bit for bit: docs/joints.md, "The per-kind setters"). */
FRICREG_API int fricreg_hb_set_elements(fricreg_hb *hb, size_t m, size_t ndof, const double J[],
                                        const double kt[], const double mun[]);

/** fricreg_hb_set_elements under the structure's name (fricreg_structure_set_jenkins: the
 *  same arguments and meaning), its messages naming set_jenkins. Since 1.7 (FRICREG_1.7).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_ENONFINITE; FRICREG_EINVAL, as
 *  fricreg_hb_set_elements.
 *  \deprecated Since 1.9, a wrapper kept for the ABI: new code calls fricreg_hb_add_elements (the
 *  equivalence bit for bit: docs/joints.md, "The per-kind setters"). */
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
 *  checked before anything changes, and nothing changes on failure. Since 1.6.
 *  \deprecated Since 1.9, a wrapper kept for the ABI: new code calls fricreg_hb_add_elements (the
 *  equivalence bit for bit: docs/joints.md, "The per-kind setters"). */
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
 *  failure. Since 1.6 (FRICREG_1.6).
 *  \deprecated Since 1.9, a wrapper kept for the ABI: new code calls fricreg_hb_add_elements (the
 *  equivalence bit for bit: docs/joints.md, "The per-kind setters"). */
FRICREG_API int fricreg_hb_set_normal_elements(fricreg_hb *hb, size_t m, size_t ndof,
                                               const double Jt[], const double Jn[],
                                               const double kt[], const double mu[],
                                               const double n0[], const double kn[]);

/** fricreg_hb_set_normal_elements under the structure's name
 *  (fricreg_structure_set_jenkins_normal: the same arguments and meaning), its messages naming
 *  set_jenkins_normal. Since 1.7 (FRICREG_1.7).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_ENONFINITE; FRICREG_EINVAL;
 *  FRICREG_ENOMEM, as fricreg_hb_set_normal_elements.
 *  \deprecated Since 1.9, a wrapper kept for the ABI: new code calls fricreg_hb_add_elements (the
 *  equivalence bit for bit: docs/joints.md, "The per-kind setters"). */
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
 *  on failure. Since 1.7 (FRICREG_1.7).
 *  \deprecated Since 1.9, a wrapper kept for the ABI: new code calls fricreg_hb_add_elements (the
 *  equivalence bit for bit: docs/joints.md, "The per-kind setters"). */
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
 *  own error (tests/hb/test_hb_contact_3d.c).
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
 *  (FRICREG_1.7).
 *  \deprecated Since 1.9, a wrapper kept for the ABI: new code calls fricreg_hb_add_elements (the
 *  equivalence bit for bit: docs/joints.md, "The per-kind setters"). */
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

/** The linear solvers of Newton's matrix I + Ĝ Ĵ (fricreg_hb_set_newton_solver). */
enum fricreg_hb_newton_solver {
    FRICREG_HB_NEWTON_AUTO = 0,       /**< by the capacitance where nq >= 512 and at most 0.8 nq
                                           rows of Ĵ are off its diagonal, else dense, from
                                           order 1024 refined on an earlier LU first (the
                                           default since 1.10) */
    FRICREG_HB_NEWTON_DENSE = 1,      /**< LAPACK's LU of the whole matrix, of order nq (+1 on
                                           a continuation's border), each matrix its own: 1.9's
                                           solver */
    FRICREG_HB_NEWTON_CAPACITANCE = 2 /**< by the capacitance at every size and share, dense
                                           only where the stuck part alone is singular (and
                                           there as AUTO's) */
};

/** Choose how Newton's matrix I + Ĝ Ĵ is solved, at the next iteration on. Most rows of Ĵ are
 *  a stiffness on its diagonal (a stuck element's harmonics, a closed contact's normal rows),
 *  and with those rows L and the s others, Woodbury's identity solves the matrix through the
 *  capacitance of order s and one complex LU of the L rows a harmonic (docs/harmonic_balance.md,
 *  "Size"): 2 s³/3 flops and kept factors against the dense LU's 2 nq³/3. Results agree with
 *  the dense solver's to rounding (about 1e-10 of their scale measured), not bit for bit:
 *  FRICREG_HB_NEWTON_DENSE gives 1.9's. The capacitance's room (about 32 (H + 1) m² bytes) is
 *  allocated here when elements are set, and by the element setters after; where that fails in
 *  an element setter, the dense LU serves. From order 1024, AUTO and CAPACITANCE solve a dense
 *  matrix first by iterative refinement on the LU factor of the last one factored, when of
 *  its order (the iterations' and the continuation's points' matrices differ little):
 *  x <- x + A_held^-1 (b - A x), A applied without forming it, until |b - A x| <= 1e-12 |b|
 *  (∞-norms) in at most 20 corrections, each shrinking the residual by half;
 *  else the matrix's own LU (2 nq³/3 flops), which is held next. A public solve or
 *  continuation starts without a held factor, so the same call gives the same bits. Measured
 *  on sweeps of an interface ROM lifting off, the same points: 85 contacts (order 1786) 65 s
 *  against 104 (docs/hb_size.md). Since 1.10 (FRICREG_1.10).
 *
 *  solver   enum fricreg_hb_newton_solver.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb is NULL; FRICREG_EINVAL if solver is none of the
 *  enum; FRICREG_ENOMEM if the capacitance's room cannot be allocated (the solver then stays
 *  the one before). */
FRICREG_API int fricreg_hb_set_newton_solver(fricreg_hb *hb, int solver);

/** How the receptances G_h = J D_h^-1 J^T (and D_h^-1 P_h) are solved
 *  (fricreg_hb_set_receptance). */
enum fricreg_hb_receptance {
    FRICREG_HB_RECEPTANCE_AUTO = 0, /**< through the modes where n >= 200, else by the LU (the
                                         default since 1.10) */
    FRICREG_HB_RECEPTANCE_LU = 1,   /**< LAPACK's LU of each D_h at each frequency: 1.9's */
    FRICREG_HB_RECEPTANCE_MODES = 2 /**< through the modes at every size */
};

/** Choose how a dense model's D_h(Ω) = K − (hΩ)² M + i hΩ C are solved, at the next frequency
 *  on. Where C is Rayleigh's (fricreg_hb_set_rayleigh: C = a0 M + a1 K) or zero (as created),
 *  the modes of K φ = λ M φ (LAPACK's dsygvd, once a model: about 10 n³ flops, n² + m n
 *  doubles kept) make every D_h diagonal, D_h^-1 = Φ diag(1/d_k) Φ^T with
 *  d_k = λ_k (1 + i hΩ a1) + i hΩ a0 − (hΩ)², so a frequency costs one real product with Φ a
 *  harmonic, 4 n² (m + 1) flops, and as much for the continuation's Ω derivative, where the LU
 *  costs 8 n³/3 + 8 n² (m + 1) and the derivative 12 n² (m + 1) + 8 m² n more
 *  (docs/hb_size.md): at an interface ROM of 859 dofs and 696 rows, 0.34 s against 1.25 s a
 *  continuation's frequency, measured in one run. Results agree with the LU's to rounding
 *  amplified by M's condition number, not bit for bit, so the modes serve only where M is
 *  positive definite with a reciprocal condition number (1-norm, LAPACK's dpocon) of at least
 *  1e-6; elsewhere, with a nonzero damping matrix (fricreg_hb_set_damping), and for a sparse
 *  model (above 4096 dofs, or set sparse), the LU serves whatever the choice.
 *  FRICREG_HB_RECEPTANCE_LU gives 1.9's results bit for bit. Since 1.10 (FRICREG_1.10).
 *
 *  method   enum fricreg_hb_receptance.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb is NULL; FRICREG_EINVAL if method is none of the
 *  enum (the choice then stays). A solve that finds a mode's |d_k| below 1e-14 of its terms'
 *  scale returns FRICREG_ESINGULAR, as the LU's pivot test does. */
FRICREG_API int fricreg_hb_set_receptance(fricreg_hb *hb, int method);

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

/* The driver's other objects, a header each since 1.9: included here, so that including
 * fricreg_hb.h alone declares the whole driver as 1.8's did. */
#include "fricreg_hb_forced.h"
#include "fricreg_hb_stability.h"
#include "fricreg_hb_nma.h"
#include "fricreg_hb_qsma.h"

#endif /* FRICREG_HB_H */
