/* SPDX-License-Identifier: GPL-3.0-or-later */
/**
 * \file
 * fricreg_ctx_step.h — the friction forces of one implicit step of the caller's own integrator on
 * a context (fricreg.h), by the contact-space Newton of fricreg_structure's steps with its
 * safeguards: for a caller who factors their own K_eff.
 *
 * Part of fricreg_structure.h, which includes it (so does every header of the structure:
 * include either), split out by object since 1.9; the structure, its model and the
 * conventions are fricreg_structure.h's.
 */
#ifndef FRICREG_CTX_STEP_H
#define FRICREG_CTX_STEP_H

#include "fricreg_structure.h"

#ifdef __cplusplus
extern "C" {
#endif

/** \defgroup ctx_step Structure: your own implicit integrator's step on a context (fricreg_ctx_step.h)
 *  \{ */

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

#endif /* FRICREG_CTX_STEP_H */
