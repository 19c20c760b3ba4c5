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
 * and the direction df = -T^-1 G. The context gives its tangent row by row
 * (fr_ctx_tangent_rows): explicit, dF_i = s_i dzdot_i, or implicit, [W dF]_i + k_i dzdot_i +
 * dafree_i = 0 (the consistent law's free contacts, or a diagonal W's near-stick ones). Row i
 * of T df = -G is then, with dF_E = df_E + G_E on the explicit rows E,
 *   explicit:  df_i - c s_i [W_eff df]_i = -G_i,
 *   implicit:  (1 + c k_i) [W_eff df]_i = -[W G]_i,
 * and with every s_i <= 0 and 1 + c k_i > 0 (every law but a falling Stribeck branch) the
 * rows of N (implicit, or s_i < 0) are (W_eff,NN + diag(shift_N)) df_N = b_N - W_eff,NR df_R,
 * shift_i = 1 / (c |s_i|) on the explicit rows and 0 on the implicit ones: symmetric positive
 * definite, a Cholesky factor of the block (masked_factor.h): CHOLMOD's sparse one on W_eff's
 * pattern (analysed once per K_eff), whose other rows and columns are set to the identity,
 * where W_eff's factor is sparse (contacts far apart on a structure barely interacting over a
 * step: contact_factor.c leaves out entries below the rounding of the diagonal), LAPACK's
 * dpotrf on the block alone where it fills, or, on fricreg_structure's sparse path
 * (FRICREG_CONTACT_SOLVER_SPARSE), through CHOLMOD's factor of K_eff + J^T T J
 * (contact_sparse.h); the rest, R (s_i = 0: sliding contacts), is
 * df_i = -G_i. Otherwise (T not of that form) dense: T_NN from the context's dense tangent, by GSL's
 * QR with column pivoting (which allocates nothing; GSL 2.7's LU allocates its pivots on
 * every call), O(|N|^3). */
#ifndef FRICREG_NEWTON_MATRIX_H
#define FRICREG_NEWTON_MATRIX_H

#include <stddef.h>

#include <cholmod.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_permutation.h>
#include <gsl/gsl_vector.h>

#include "fricreg.h"
#include "contact_sparse.h"
#include "masked_factor.h"

struct fr_newton_matrix {
    size_t m;
    /* Dense: allocated at the first dense solve, m x m row-major. */
    double *Fz, *Fa, *T, *row; /* row: [m] one row of T being formed */
    gsl_permutation *perm;
    gsl_vector *tau, *norm, *rhs, *sol; /* [m] views of |N| */
    size_t *rows;                       /* [m] N, ascending */
    /* Contact by contact: the context's rows, and W_eff's pattern with the identity where the
     * rows are not in N. */
    double *fz;                /* [m] d F_i/d zdot_i's sign (0: F_i does not move with zdot_i) */
    double *coef, *wg, *shift; /* [m] s_i or k_i; [W G], then scratch; the shifts */
    unsigned char *implicit;   /* [m] */
    unsigned char *in_n;       /* [m] */
    size_t *runs;              /* [3 (m + 1)] runs of rows for W_eff's products (delassus_runs.h) */
    double *b;                 /* [m] */
    struct fr_masked_factor block; /* W_eff's principal blocks (shifted) */
    enum fr_block_storage storage; /* the blocks' (FR_BLOCK_CHOSEN unless a test forces one) */
    /* The blocks solved in the structure's space instead (contact_sparse.h; not owned, NULL:
     * the masked factor's): set by the structure after each prepare. */
    struct fr_contact_sparse *sparse;
};

/* Ready for the contacts of a new K_eff: the blocks of W_eff (m x m, upper, sorted) ready in
 * nm->storage (masked_factor.h), and with dense set the dense form allocated (otherwise it is allocated at its
 * first use, a falling Stribeck branch). FRICREG_OK or
 * FRICREG_ENOMEM. */
int fr_newton_matrix_prepare(struct fr_newton_matrix *nm, const cholmod_sparse *Weff, int dense,
                             cholmod_common *c);

void fr_newton_matrix_free(struct fr_newton_matrix *nm, cholmod_common *c);

/* The direction df[m] = -T^-1 G[m] at the context's last evaluation, with coef = c above,
 * W and W_eff m x m upper triangles (stype 1, sorted), and its product weff_df[m] = W_eff df:
 * on the block's implicit rows from the solve's own equations, on the others by a product
 * over those rows alone where W_eff is packed (delassus_runs.h); equal to the whole product
 * to the solve's rounding. FRICREG_OK; FRICREG_ESINGULAR (T singular); FRICREG_ENOMEM (the
 * dense form could not be allocated); the context's tangent's status. */
int fr_newton_direction(struct fr_newton_matrix *nm, fricreg_ctx *ctx, double coef,
                        const cholmod_sparse *W, const cholmod_sparse *Weff, const double G[],
                        double df[], double weff_df[], cholmod_common *c);

/* x_S = W_eff,SS^-1 b_S for the contacts marked in set[m] (x elsewhere untouched), through
 * the same factor, and weff_x[m] = W_eff [x_S; 0] (b_S on S, a product over the other rows
 * alone where W_eff is packed and they are few). FRICREG_OK, FRICREG_ESINGULAR (W_eff,SS
 * singular: contacts that depend on each other), or CHOLMOD's failure. */
int fr_newton_stick_solve(struct fr_newton_matrix *nm, const cholmod_sparse *Weff,
                          const unsigned char set[], const double b[], double x[], double weff_x[],
                          cholmod_common *c);

/* The first trial fraction of a Newton direction (Newmark's stop of a slipping contact,
 * newmark.c and contact_step_newton.c): with zdot[m] the velocities at the iterate, weff_df[m] =
 * W_eff df, coef = c, fz[m] the slopes' signs of the last direction (nm->fz), the largest
 * lambda in (0, 1] at which a slipping contact (mun_i > 0, fz_i = 0) not yet stopped this step
 * reaches zdot_i = 0 where the full step takes it from one side across the whole band
 * (|zdot_i + c [W_eff df]_i| >= eps on the other); that contact is marked in stopped[m]. */
double fr_newton_first_stop(size_t m, const double zdot[], const double weff_df[], double coef,
                            double eps, const double mun[], const double fz[],
                            unsigned char stopped[]);

/* The right-hand side b[m] of the stick guess's W_eff,SS df_S = b_S - [W_eff f]_S, f the
 * start's forces with products weff_f[m] = [W_eff f]: with exact set (law (4), diagonal W
 * w[m]), the band's own affine piece, b_i = (-a0_i - k_i z0_i) / (1 + c k_i) - [W_eff f]_i,
 * k_i = 2 mun_i w_i / eps; otherwise the forces that keep the velocities at the step's start
 * zstart[m], b_i = (zstart_i - zdot_i) / c with zdot[m] at f. b may alias zstart. */
void fr_newton_stick_rhs(size_t m, int exact, double coef, double eps, const double mun[],
                         const double w[], const double z0[], const double a0[],
                         const double weff_f[], const double zstart[], const double zdot[],
                         double b[]);

#endif
