/* SPDX-License-Identifier: GPL-3.0-or-later */
/**
 * \file
 * fricreg_disk_ctx.h — coupled 2-D contacts in a context (beyond the paper): the consistent
 * coupled law of docs/coupled.md extended to the friction disk of fricreg_disk.h.
 *
 * m contacts, each with a tangential velocity zdot_i in R^2, obey zddot = a_free + W f with a
 * Delassus matrix W of order 2m. fricreg_disk_eval gives the 2-D law at one contact for a known
 * f_eq; here f_eq,i depends on the other contacts' forces,
 *     f_eq,i = -W_ii^-1 (a_free,i + sum_{j != i} W_ij f_j)     (W_ij the 2x2 blocks),
 * and the forces of the near-stick contacts are the unique solution of the convex QP
 *     f = argmin_{f_i in K_i} 1/2 f^T W f + b^T f,   b_i = a_free,i + W_ii c_i mun_i,
 * c_i = 2 zdot_i/eps, K_i the disk of FRICREG_DISK_QUINN: centre -a_i u_i, radius mun_i - a_i
 * (a_i = mun_i |zdot_i|/eps, u_i = zdot_i/|zdot_i|), the whole disk mun_i D at zdot_i = 0.
 * Contacts with |zdot_i| >= eps slide, f_i = -mun_i u_i, and enter b of the others (docs/
 * laws2d.md, "Coupled 2-D contacts in a context"). Its optimality conditions say that each f_i
 * is the projection of f_eq,i - c_i mun_i onto K_i in the metric of W_ii: with an isotropic
 * block W_ii = w_i I that is fricreg_disk_eval's (Euclidean) law at (zdot_i, f_eq,i); with a
 * non-isotropic block it is a 2-D trust-region subproblem, NOT the Euclidean projection, and
 * the force differs from fricreg_disk_eval at the same f_eq whenever f_eq - c mun lies outside
 * K_i (the W_ii-metric projection is the one that makes contact i's acceleration point against
 * its force at rest: maximum dissipation).
 *
 * One dimension per context: this context holds only 2-D contacts and fricreg.h's holds only
 * 1-D ones. A 3-D model has a 2-D tangent plane at every contact, so its contacts are all of
 * one kind; mixing kinds would put per-contact offsets into every array and every index.
 *
 * fricreg.h's conventions hold (units, status codes, nothing modified on failure, no printing,
 * one context per thread) and fricreg_disk.h's layout: a vector is two doubles, arrays of m
 * vectors are interleaved (contact i at [2i], [2i+1]; in Fortran a (2, m) array), and a 2m x 2m
 * matrix is row-major with contact i's components at rows and columns 2i, 2i+1. Numbers must be
 * finite and at most 1e250 in magnitude. Since 1.3 (FRICREG_1.3); W as a sparse matrix
 * (fricreg_disk_ctx_set_coupling_csr, _csc) since 1.6.
 */
#ifndef FRICREG_DISK_CTX_H
#define FRICREG_DISK_CTX_H

#include "fricreg.h"
#include "fricreg_disk.h"

#ifdef __cplusplus
extern "C" {
#endif

/** \defgroup disk_ctx 2-D context: coupled 2-D contacts (fricreg_disk_ctx)
 *  An opaque context that gives the friction forces of m coupled 2-D contacts, each with a
 *  tangential velocity in R^2, under the 2-D law FRICREG_DISK_QUINN. It extends the consistent
 *  coupled law (docs/coupled.md) to the friction disk and gives the tangent for implicit
 *  integrators. Stribeck friction in a 2-D context: fricreg_disk_ctx_set_stribeck (declared in
 *  fricreg_stribeck.h).
 *  \{ */

/** Opaque context for m coupled 2-D contacts: law, eps, bounds, W and all scratch memory. */
typedef struct fricreg_disk_ctx fricreg_disk_ctx;

/** Create a context for m >= 1 two-dimensional contacts.
 *
 *  Defaults: law FRICREG_DISK_QUINN, eps = 1e-3, mun[i] = 1, W = I (uncoupled isotropic
 *  blocks). Evaluation memory is allocated here and in the coupling setters; eval never
 *  allocates.
 *
 *  m    number of contacts, 1 <= m <= 2^24.
 *  out  out: the new context, released with fricreg_disk_ctx_free. Written only on success.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if out is NULL; FRICREG_EINVAL if m is 0 or too large;
 *  FRICREG_ENOMEM. Since 1.3. */
FRICREG_API int fricreg_disk_ctx_create(size_t m, fricreg_disk_ctx **out);

/** Release a context and everything it owns. fricreg_disk_ctx_free(NULL) does nothing. */
FRICREG_API void fricreg_disk_ctx_free(fricreg_disk_ctx *ctx);

/** Number of contacts m of the context (0 if ctx is NULL). */
FRICREG_API size_t fricreg_disk_ctx_size(const fricreg_disk_ctx *ctx);

/** Select the 2-D law (enum fricreg_disk_law) and eps (velocity units, the band |zdot| < eps).
 *  Supported: FRICREG_DISK_QUINN (the sets K_i above) and FRICREG_DISK_FORCE_BALANCE (K_i the
 *  disk mun_i D at zdot_i = 0, sliding otherwise; eps validated but unused). The lens and
 *  nested laws have no coupled form here (the lens is not Lipschitz; the nested law is not a
 *  projection onto a set) and Coulomb needs no context: they are refused.
 *
 *  FRICREG_DISK_FORCE_BALANCE switches Stribeck friction (fricreg_disk_ctx_set_stribeck,
 *  fricreg_stribeck.h) off; FRICREG_DISK_QUINN keeps it, with the new eps.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if ctx is NULL; FRICREG_EINVAL for another law, or eps
 *  below DBL_MIN or above 1e250; FRICREG_ENONFINITE if eps is NaN or infinite. */
FRICREG_API int fricreg_disk_ctx_set_law(fricreg_disk_ctx *ctx, int law, double eps);

/** Set the friction bounds mun[m] = mu_i N_i (force units), 0 <= mun_i <= 1e250. Switches
 *  Stribeck friction (fricreg_disk_ctx_set_stribeck, fricreg_stribeck.h) off: these bounds
 *  replace it.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE if m differs from the context's;
 *  FRICREG_ENONFINITE; FRICREG_EINVAL if some mun[i] < 0 or > 1e250. */
FRICREG_API int fricreg_disk_ctx_set_bounds(fricreg_disk_ctx *ctx, size_t m, const double mun[]);

/** Uncoupled contacts: W block diagonal, w[4m] holding contact i's 2x2 block W_ii row-major at
 *  w[4i..4i+3] (inverse effective masses of the tangent plane). Each block must be symmetric
 *  (to 1e-12 relative) and positive definite: its smallest eigenvalue above 1e-12 times its
 *  largest, and at least DBL_MIN ~ 2.2e-308 (a smaller one is a contact with no mobility,
 *  whose inverse, the scale of its tangent, overflows; as fricreg_ctx_set_coupling_dense's
 *  W_ii). Each contact is then solved exactly, once, with no iteration.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_ENONFINITE; FRICREG_EINVAL (an
 *  entry beyond 1e250 in magnitude); FRICREG_ENOTSYM; FRICREG_ENOTPSD (a block not positive
 *  definite); FRICREG_ENOMEM. */
FRICREG_API int fricreg_disk_ctx_set_coupling_blocks(fricreg_disk_ctx *ctx, size_t m,
                                                     const double w[]);

/** Coupled contacts: dense Delassus matrix W[(2m)^2], row-major, W[(2i+a)*2m + 2j+b] the
 *  coupling of contact i's component a with contact j's component b. Copied. Refused: a matrix
 *  not symmetric to 1e-12 max|W| (FRICREG_ENOTSYM); a diagonal block W_ii not positive definite
 *  as for fricreg_disk_ctx_set_coupling_blocks, or W not positive semidefinite: the smallest
 *  eigenvalue of D^-1/2 W D^-1/2 (D = diag W; GSL's gsl_eigen_symm, O(m^3) once here) below
 *  -2m 1e-12 (FRICREG_ENOTPSD). A singular W (redundant contacts) is accepted here; an
 *  evaluation that meets it may return FRICREG_ESINGULAR. The context also holds W by its
 *  non-zero 2x2 blocks and the storage of their factor (eval's Newton method), set up here:
 *  CHOLMOD's sparse one, or where that one would fill (at least half a dense triangle, as a
 *  W without zero blocks does; since 1.8) a dense (2m)^2 buffer for LAPACK's dpotrf, blocked
 *  on the BLAS: memory O(m^2) in all, a few times W's copy.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE (also if (2m)^2 overflows);
 *  FRICREG_ENONFINITE; FRICREG_EINVAL (an entry beyond 1e250 in magnitude); FRICREG_ENOTSYM;
 *  FRICREG_ENOTPSD; FRICREG_ENOMEM. */
FRICREG_API int fricreg_disk_ctx_set_coupling_dense(fricreg_disk_ctx *ctx, size_t m,
                                                    const double W[]);

/** Coupled contacts, sparse: the Delassus matrix W of order 2m in compressed sparse rows, in
 *  the layout of fricreg_disk_ctx_set_coupling_dense (row and column 2i+a are contact i's
 *  component a; the 2x2 block W_ij couples contacts i and j), as enum fricreg_sparse_flags
 *  describes (fricreg.h): zero- or one-based, W whole or one triangle (diagonal included),
 *  duplicates summed, entries of a row in any order. Read and copied; the caller keeps its
 *  arrays. Memory: O(entries of W + entries of its sparse factor), no (2m)^2 array; evaluation
 *  allocates nothing (fricreg_disk_ctx_eval).
 *
 *  m       number of contacts, equal to the context's.
 *  flags   enum fricreg_sparse_flags, combined with |.
 *  rowptr  in: rowptr[2m + 1], rowptr[0] = base (0, or 1 with FRICREG_SPARSE_ONE_BASED),
 *          non-decreasing; nnz = rowptr[2m] - base. Fortran: integer(c_int64_t).
 *  colind  in: colind[nnz], the column (base-based, < 2m + base) of each entry of row r at
 *          rowptr[r] - base ... rowptr[r+1] - base - 1. May be NULL when nnz = 0.
 *  values  in: values[nnz], the entries (inverse mass units), finite, at most 1e250 in
 *          magnitude, each and summed with its duplicates.
 *
 *  Refused as by the dense setter: W not symmetric, judged by src/base/matrix_input.c's rule
 *  (given whole, entries (k, l) and (l, k) differing by more than 1e-12 sqrt(r_k r_l), r_k the
 *  largest magnitude in row k: a change of a contact's units does not change the verdict;
 *  FRICREG_ENOTSYM); a diagonal block W_ii not positive definite (as
 *  fricreg_disk_ctx_set_coupling_blocks; also a contact with no diagonal entry) or an entry
 *  with W_kl^2 > W_kk W_ll (FRICREG_ENOTPSD); W not positive semidefinite: the smallest
 *  eigenvalue of D^-1/2 W D^-1/2 (D = diag W) below -2m 1e-12, found here by CHOLMOD's sparse
 *  LDL^T of D^-1/2 W D^-1/2 + 2m 1e-12 I, which has a pivot <= 0 exactly then (FRICREG_ENOTPSD;
 *  cost that of one sparse factorization, not the dense setter's O(m^3)). A singular W is
 *  accepted, as by the dense setter. Nothing is changed on failure.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL (ctx, rowptr, or colind or values while nnz > 0);
 *  FRICREG_ESIZE if m differs from the context's; FRICREG_EINVAL (unknown flags, both
 *  triangles, rowptr[0] not the base or rowptr decreasing, an index out of range, an entry in
 *  the triangle left out, a value beyond 1e250); FRICREG_ENONFINITE; FRICREG_ENOTSYM;
 *  FRICREG_ENOTPSD; FRICREG_ENOMEM. Since 1.6 (FRICREG_1.6). */
FRICREG_API int fricreg_disk_ctx_set_coupling_csr(fricreg_disk_ctx *ctx, size_t m, int flags,
                                                  const int64_t rowptr[], const int64_t colind[],
                                                  const double values[]);

/** Coupled contacts, sparse, in compressed sparse columns: as
 *  fricreg_disk_ctx_set_coupling_csr with rows and columns swapped, colptr[2m + 1] and
 *  rowind[nnz] (integer(c_int64_t) in Fortran) the column pointers and row indices. W being
 *  symmetric, its CSC arrays are its CSR arrays, but for the triangle flag: a CSR upper
 *  triangle is a CSC lower one. Checks, errors and cost as fricreg_disk_ctx_set_coupling_csr.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_EINVAL; FRICREG_ENONFINITE;
 *  FRICREG_ENOTSYM; FRICREG_ENOTPSD; FRICREG_ENOMEM. Since 1.6 (FRICREG_1.6). */
FRICREG_API int fricreg_disk_ctx_set_coupling_csc(fricreg_disk_ctx *ctx, size_t m, int flags,
                                                  const int64_t colptr[], const int64_t rowind[],
                                                  const double values[]);

/** Evaluate the friction forces of all m contacts (the law above).
 *
 *  m          must equal the context's contact count.
 *  zdot       in: zdot[2m], interleaved tangential relative velocities.
 *  a_free     in: a_free[2m], interleaved free relative accelerations (those with f = 0).
 *  f          out: f[2m], interleaved friction forces, |f_i| <= mun_i. Written only on success.
 *
 *  Solver: contacts with |zdot_i| >= eps (FORCE_BALANCE: zdot_i != 0) or mun_i = 0 are fixed.
 *  Each near-stick contact's subproblem (min over K_i in the W_ii metric) is solved exactly:
 *  inside K_i by the 2x2 solve, else on its circle, in W_ii's eigenbasis, by the secular
 *  equation |y(lambda)| = radius, which is decreasing in lambda on a bracket [0, 2 d_max |t| /
 *  radius] where it changes sign, solved by GSL's gsl_root_fsolver_brent to the last bits.
 *  A block diagonal W needs one such solve per contact. A coupled W (dense or sparse setter)
 *  is solved from the last successful evaluation's forces (warm start) by two methods:
 *   - block Gauss-Seidel over the near-stick contacts (each sweep solves every subproblem
 *     given the others' latest forces: a descent method on the strictly convex QP), up to 8
 *     sweeps, which settle weakly coupled contacts;
 *   - else the projected Newton method (D. P. Bertsekas, SIAM J. Control Optim. 20 (1982)):
 *     contacts on their circles that the gradient pushes outwards are held there (moving
 *     along the circle, its curvature in the Hessian), the others move freely; the reduced
 *     Hessian Q^T (W_SS + diag(lambda_i)) Q (Q each contact's frame, normal and tangent on its
 *     circle) keeps W's pattern of 2x2 blocks and is factored by CHOLMOD's sparse LDL^T in a
 *     fill-reducing order of the contacts chosen at set-up; the step is projected onto the
 *     disks and shortened by Armijo's rule, so every accepted step lowers the objective, and a
 *     step that cannot is replaced by a sweep. With no contact on its circle the factor is
 *     kept from one evaluation to the next while the near-stick set holds, and a step is one
 *     solve. Once Newton was needed, the next evaluation starts with it.
 *  Converged when a pass of exact subproblems (the sweeps' test) moves no force by more than
 *  1e-14 mun_i; the forces are that pass's, the QP's solution to about cond(W_SS)
 *  DBL_EPSILON mun (measured: 5e-16 on well-conditioned W, 7e-13 on W = B B^T/12 + 1e-5 I,
 *  m = 6; a stuck chain of 10^4 contacts, cond 4e7, to 3e-11). Cost per Newton step: one
 *  sparse factorization (none while the set holds with no contact on its circle) and solve,
 *  O(entries of the factor), and two passes over W's blocks: O(m) on a chain; a warm-started
 *  stuck chain takes one step (docs/laws2d.md has the measured cost). Should neither
 *  converge (W singular on the near-stick set), sweeps go on to 20000, with 10 Newton
 *  steps after sweeps 16, 32, 64, ...
 *  No heap allocation: CHOLMOD's factor, its workspace and its solve's buffers are allocated
 *  by the coupling setters.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_ENONFINITE (NaN/Inf input, or an
 *  f_eq beyond the double range); FRICREG_EINVAL (an input beyond 1e250 in magnitude);
 *  FRICREG_ESINGULAR if neither method converges within those limits: W restricted to the
 *  near-stick contacts is singular or so badly conditioned that the forces are not
 *  determined to that tolerance. */
FRICREG_API int fricreg_disk_ctx_eval(fricreg_disk_ctx *ctx, size_t m, const double zdot[],
                                      const double a_free[], double f[]);

/** The Jacobian of the forces of the last successful fricreg_disk_ctx_eval, for Newton in an
 *  implicit integrator.
 *
 *  m          must equal the context's contact count.
 *  df_dzdot   out, optional (NULL to skip): (2m)^2 row-major, df_dzdot[(2i+a)*2m + 2j+b] =
 *             d f_{i,a} / d zdot_{j,b} (force per velocity).
 *  df_dafree  out, optional (NULL to skip): (2m)^2 row-major, d f_{i,a} / d a_free_{j,b}
 *             (force per acceleration). Written only on success, in full (zeros included).
 *
 *  By implicit differentiation of the QP's optimality (KKT) conditions at the solution: for
 *  near-stick contacts inside K_i, their stationarity rows (W f + b)_i = 0; for those on the
 *  circle of K_i, stationarity with its multiplier and the circle |f_i + a_i u_i| = mun_i - a_i;
 *  sliding contacts contribute d(-mun v/|v|)/dv = -(mun/|v|)(I - u u^T) (0 for mun = 0), and
 *  no a_free dependence. The linear system (order 2|S| + |circle|, dense W; per contact for
 *  blocks) is solved by GSL's Householder QR. With a sparse W (fricreg_disk_ctx_set_coupling_csr,
 *  _csc) the same conditions are taken in each contact's frame, where the circle's multiplier
 *  drops out: the matrix is the reduced Hessian of eval's Newton method, factored once by
 *  CHOLMOD's sparse LDL^T (singular: a pivot d_k not above 1e-12 of its diagonal entry), then
 *  one sparse solve per column of each output asked for, 2m each: time O(m (entries of the
 *  factor + m)), O(m^2) on a chain, plus the (2m)^2 entries of each output, the caller's
 *  memory; no (2m)^2 memory of the context's. Exact where the force is differentiable. Kinks
 *  follow fixed rules: a contact exactly on its circle (multiplier 0) is held on it; at
 *  zdot_i = 0 the circle's radius mun - mun|v|/eps has no derivative, and the one taken is that
 *  along the direction the contact will slide, -f_i/|f_i| (the radius then does not move to
 *  first order); at |zdot_i| = eps the contact slides, as eval decides. A failed evaluation
 *  since (FRICREG_ESINGULAR, FRICREG_ENONFINITE) does not change it: its state is rebuilt from
 *  the last successful evaluation's inputs, warm-started at its forces (one pass, no
 *  allocation).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if ctx is NULL or both outputs are NULL; FRICREG_ESIZE;
 *  FRICREG_EINVAL if no evaluation succeeded since creation or the last setter call;
 *  FRICREG_ESINGULAR if the KKT matrix is singular (a pivot of its R factor below 1e-13 times
 *  the largest; sparse W: of its LDL^T factor as above: redundant contacts); FRICREG_ENONFINITE if an entry overflows (mun/eps or
 *  mun/|zdot| beyond or near the double range, or W^-1: when a slope, a multiplier, an entry
 *  of W or the inverse of a diagonal block's eigenvalue exceeds 1e100, the columns are solved
 *  once without writing to check, before anything is written). */
FRICREG_API int fricreg_disk_ctx_tangent(fricreg_disk_ctx *ctx, size_t m, double df_dzdot[],
                                         double df_dafree[]);

/** Returns the status code of the last failed call on this context (FRICREG_OK if none, or
 *  ctx NULL). A successful call does not clear it. */
FRICREG_API int fricreg_disk_ctx_errcode(const fricreg_disk_ctx *ctx);

/** Message of the last failed call on this context: names the argument, contact or value.
 *  "" if none; "NULL context" if ctx is NULL. Owned by the context, valid until its next
 *  call. */
FRICREG_API const char *fricreg_disk_ctx_errmsg(const fricreg_disk_ctx *ctx);

/** Copy the last error message into buf[len], NUL-terminated and truncated to fit. Returns the
 *  full message length (excluding the NUL), as snprintf does; 0 and nothing written if buf is
 *  NULL or len is 0. */
FRICREG_API size_t fricreg_disk_ctx_errmsg_copy(const fricreg_disk_ctx *ctx, char *buf, size_t len);

/** \} */

#ifdef __cplusplus
}
#endif

#endif /* FRICREG_DISK_CTX_H */
