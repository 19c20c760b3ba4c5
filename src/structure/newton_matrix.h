/* SPDX-License-Identifier: GPL-3.0-or-later */
/* newton_matrix.h — internal: the Newton matrix of a Newmark / HHT-alpha step in the contact
 * space, and the Newton direction.
 *
 * With c = (1 + alpha) gamma dt, a step's contact velocities and free accelerations are affine
 * in the friction forces f (newmark.c):
 *   zdot(f) = z0 + c W_eff f,   a_free(f) = a0 - (W - W_eff) f,
 * W = J M^-1 J^T the Delassus matrix, W_eff = J K_eff^-1 J^T. Newton solves
 * G(f) = f - F(zdot(f), a_free(f)) = 0, F the context's law, whose tangent (F_z, F_a) gives
 *   T = dG/df = I - c F_z W_eff + F_a (W - W_eff),
 * and the direction df = -T^-1 G. Rows where F_z and F_a vanish (sliding contacts) are the
 * identity: df_i = -G_i, and only the rest, N, is solved. Two ways:
 *  - the context's W is diagonal (contacts on separate degrees of freedom, e.g. a lumped M):
 *    F_z and F_a are diagonal too, and T = diag(d) - diag(e) W_eff, d_i = 1 + F_a,ii W_ii,
 *    e_i = c F_z,ii + F_a,ii. With every e_i < 0 on N (every law but a falling Stribeck
 *    branch) T_NN = diag(-e_N) (W_eff,NN + diag(d_N / -e_N)), the bracket symmetric positive
 *    definite: CHOLMOD's sparse Cholesky on W_eff's pattern (analysed once per K_eff), whose
 *    other rows and columns are set to the identity. W_eff's pattern is what makes this
 *    cheap: contacts far apart on a structure barely interact over a step (contact_factor.c
 *    leaves out entries below the rounding of the diagonal).
 *  - otherwise dense: T_NN from the context's dense tangent, by GSL's QR with column pivoting
 *    (which allocates nothing; GSL 2.7's LU allocates its pivots on every call), O(|N|^3). */
#ifndef FRICREG_NEWTON_MATRIX_H
#define FRICREG_NEWTON_MATRIX_H

#include <stddef.h>

#include <cholmod.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_permutation.h>
#include <gsl/gsl_vector.h>

#include "fricreg.h"
#include "masked_factor.h"

struct fr_newton_matrix {
    size_t m;
    /* Dense: allocated at the first dense solve, m x m row-major. */
    double *Fz, *Fa, *T, *row; /* row: [m] one row of T being formed */
    gsl_permutation *perm;
    gsl_vector *tau, *norm, *rhs, *sol; /* [m] views of |N| */
    size_t *rows;                       /* [m] N, ascending */
    /* Diagonal: W_eff's pattern with the identity where the rows are not in N. */
    double *fz, *fa, *d, *e, *shift; /* [m] */
    unsigned char *in_n;             /* [m] */
    double *b;                       /* [m] */
    struct fr_masked_factor block;   /* W_eff's principal blocks (shifted) */
};

/* Ready for the contacts of a new K_eff: the diagonal path's blocks of W_eff (m x m, upper,
 * sorted) ordered and analysed, and with dense set the dense form allocated (otherwise it is
 * allocated at its first use, a falling Stribeck branch under a diagonal W). FRICREG_OK or
 * FRICREG_ENOMEM. */
int fr_newton_matrix_prepare(struct fr_newton_matrix *nm, const cholmod_sparse *Weff, int dense,
                             cholmod_common *c);

void fr_newton_matrix_free(struct fr_newton_matrix *nm, cholmod_common *c);

/* The direction df[m] = -T^-1 G[m] at the context's last evaluation, with coef = c above,
 * W and W_eff m x m upper triangles (stype 1, sorted). w_diag is the context's W when it is
 * diagonal (fr_ctx_coupling_diagonal), else NULL. FRICREG_OK; FRICREG_ESINGULAR (T singular);
 * FRICREG_ENOMEM (the dense form could not be allocated); the context's tangent's status. */
int fr_newton_direction(struct fr_newton_matrix *nm, fricreg_ctx *ctx, double coef,
                        const cholmod_sparse *W, const cholmod_sparse *Weff, const double *w_diag,
                        const double G[], double df[], cholmod_common *c);

/* x_S = W_eff,SS^-1 b_S for the contacts marked in set[m] (x elsewhere untouched), through
 * the same sparse factor: FRICREG_OK, FRICREG_ESINGULAR (W_eff,SS singular: contacts that
 * depend on each other), or CHOLMOD's failure. */
int fr_newton_stick_solve(struct fr_newton_matrix *nm, const cholmod_sparse *Weff,
                          const unsigned char set[], const double b[], double x[],
                          cholmod_common *c);

#endif
