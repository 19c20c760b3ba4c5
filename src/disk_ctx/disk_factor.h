/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_factor.h — internal: the reduced Hessian of the coupled 2-D law's QP on a set of
 * near-stick contacts, and its sparse LDL^T factor by CHOLMOD (Newton's step, disk_newton.c,
 * and the tangent with a sparse W, disk_tangent_sparse.c).
 *
 * Each contact has two unknowns in a frame Q_i: the identity for a contact inside its disk
 * (FR_DISK_FREE), [n_i t_i] for one on its circle (FR_DISK_CIRCLE; n_i the outward normal,
 * t_i = (-n_i1, n_i0) the tangent), whose normal unknown is prescribed and so decoupled; both
 * unknowns of a contact that is not in the set (FR_DISK_FIXED) are decoupled too. The matrix
 *     H_ij = Q_i^T (W_ij + delta_ij lam_i I) Q_j      on the coupled unknowns,
 * with a unit diagonal on the decoupled ones, is symmetric positive definite when W is on the
 * set's free directions (lam_i >= 0): the circle's curvature lam_i enters the tangent only.
 *
 * The matrix keeps one pattern, the 2x2 blocks of W, whatever the set: it is stored in a
 * fill-reducing order of the contacts (CHOLMOD's choice, on the contacts' graph) chosen once,
 * analysed once with CHOLMOD's natural ordering and simplicial LDL^T, and factored once at
 * set-up, so that later factorizations and solves allocate nothing: CHOLMOD factors a
 * pre-ordered upper triangle in place, and its solve reuses its buffers.
 *
 * Where that factor fills (a W without zero blocks: nnz(L) at least half a dense triangle, the
 * 1-D near-stick block's rule, structure/masked_factor.h), its simplicial LDL^T does without the
 * BLAS what LAPACK's blocked dpotrf does with it: then H's coupled unknowns are copied, in the same order,
 * into a dense buffer allocated at set-up and factored there by dpotrf, solved by two dtrsv. The
 * decoupled unknowns' unit rows do not touch the others, so the pivots are LDL^T's (d_k =
 * L_kk^2) and the pivot test the same. */
#ifndef FRICREG_DISK_FACTOR_H
#define FRICREG_DISK_FACTOR_H

#include <stddef.h>
#include <stdint.h>

#include <cholmod.h>

#include "disk_coupling.h"

/* The storage of H's factor: by the fill rule, or forced (the tests compare the two). */
enum fr_disk_storage { FR_DISK_STORAGE_CHOSEN = 0, FR_DISK_STORAGE_SPARSE, FR_DISK_STORAGE_DENSE };

struct fr_disk_factor {
    size_t m;
    cholmod_common c;
    int64_t *order; /* [m] position -> contact */
    int64_t *pos;   /* [m] contact -> position */
    int64_t *src;   /* [nbu] W's block of each stored block of A, in A's order (W_ji: read
                     * transposed) */
    cholmod_sparse *A;
    cholmod_factor *L;
    cholmod_dense *B, *X, *Y, *E; /* the right-hand side (caller's) and CHOLMOD's buffers */
    signed char *held;            /* [m] the kinds of the matrix in L */
    int reusable;                 /* L holds the matrix of `held`, which has no circle */
    /* Dense: H on its nc coupled unknowns, column-major nc x nc (upper), then its factor. */
    int dense;
    size_t nc;
    double *D;    /* [(2m)^2] */
    double *hd;   /* [2m] H's diagonal on the coupled unknowns, for the pivot test */
    double *bc;   /* [2m] a solve's right-hand side on them */
    int64_t *unk; /* [2m] coupled unknown c -> its position in A (2 p or 2 p + 1) */
    int64_t *at;  /* [2m] position in A -> its coupled unknown, -1 decoupled */
};

/* The pattern of w, its order, analysis, the storage (FR_DISK_STORAGE_CHOSEN: by the fill rule
 * above) and a first factorization (of the identity, which every pattern admits). FRICREG_OK
 * or FRICREG_ENOMEM (nothing held). */
int fr_disk_factor_setup(struct fr_disk_factor *F, const struct fr_disk_coupling *w,
                         enum fr_disk_storage storage);

/* Releases everything; safe on a zeroed struct. */
void fr_disk_factor_free(struct fr_disk_factor *F);

/* Assembles H for the kinds kind[m] (enum fr_disk_kind), normals n[2m] (read for circles)
 * and multipliers lam[m] (circles) and factors it. Returns FRICREG_OK, or FRICREG_ESINGULAR
 * when a pivot d_k of LDL^T is not above 1e-12 H_kk (H singular or indefinite on the set),
 * with *pivot the contact whose unknown failed. No allocation. */
int fr_disk_factor_build(struct fr_disk_factor *F, const struct fr_disk_coupling *w,
                         const signed char kind[], const double n[], const double lam[],
                         size_t *pivot);

/* Whether the factor holds H of these kinds, none of them a circle (then build is not
 * needed). */
int fr_disk_factor_holds(const struct fr_disk_factor *F, const signed char kind[]);

/* Solves H x = b in the contacts' frames: rhs[2m] and x[2m] interleaved by contact
 * (contact i at 2i, 2i+1; in its frame Q_i), x may alias rhs. Decoupled unknowns get 0 when
 * their rhs is 0. FRICREG_OK, or FRICREG_ENOMEM if CHOLMOD failed (it does not, its buffers
 * being held). */
int fr_disk_factor_solve(struct fr_disk_factor *F, const double rhs[], double x[]);

/* The symbolic analysis and factor as the PSD check of a sparse W: factors
 * D^-1/2 W D^-1/2 + shift I (D = diag W) and returns 1 if it is positive definite, 0 if not,
 * -1 out of memory. Leaves the factor to be rebuilt (reusable = 0). */
int fr_disk_factor_scaled_pd(struct fr_disk_factor *F, const struct fr_disk_coupling *w,
                             double shift);

#endif
