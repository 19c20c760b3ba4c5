/* SPDX-License-Identifier: GPL-3.0-or-later */
/* newton_matrix.c — the contact-space Newton direction of a Newmark / HHT-alpha step
 * (newton_matrix.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_linalg.h>

#include "base/gsl_mem.h"
#include "contact_factor.h"
#include "ctx/ctx_driver.h"
#include "delassus_runs.h"
#include "newton_matrix.h"

void fr_newton_matrix_free(struct fr_newton_matrix *nm, cholmod_common *c)
{
    void *blocks[] = {nm->Fz,   nm->Fa,    nm->T,    nm->row,  nm->perm,     nm->tau,
                      nm->norm, nm->rhs,   nm->sol,  nm->rows, nm->fz,       nm->coef,
                      nm->wg,   nm->shift, nm->in_n, nm->b,    nm->implicit, nm->runs};
    for (size_t k = 0; k < sizeof blocks / sizeof *blocks; k++)
        free(blocks[k]); /* gsl_mem.h: one block each */
    fr_masked_factor_free(&nm->block, c);
    enum fr_block_storage storage = nm->storage; /* a setting, not storage: it stays */
    memset(nm, 0, sizeof *nm);
    nm->storage = storage;
}

/* ---- Products with a symmetric sparse matrix (upper triangle, CSC) ------------------------- */

/* row[0..m) += alpha x^T S: row i of X S for x = X's row i (S symmetric). */
static void row_times_sym(const cholmod_sparse *S, double alpha, const double x[], double row[])
{
    const SuiteSparse_long *Sp = S->p, *Si = S->i;
    const double *Sx = S->x;
    for (size_t j = 0; j < S->ncol; j++)
        for (SuiteSparse_long p = Sp[j]; p < Sp[j + 1]; p++) {
            size_t k = (size_t)Si[p];
            row[j] += alpha * x[k] * Sx[p];
            if (k != j)
                row[k] += alpha * x[j] * Sx[p];
        }
}

/* ---- Dense ------------------------------------------------------------------------------- */

static int dense_allocate(struct fr_newton_matrix *nm)
{
    if (nm->T != NULL)
        return 1;
    size_t m = nm->m;
    nm->Fz = malloc(m * m * sizeof *nm->Fz);
    nm->Fa = malloc(m * m * sizeof *nm->Fa);
    nm->T = malloc(m * m * sizeof *nm->T);
    nm->row = malloc(m * sizeof *nm->row);
    nm->rows = malloc(m * sizeof *nm->rows);
    nm->perm = fr_gsl_permutation_new(m);
    nm->tau = fr_gsl_vector_new(m);
    nm->norm = fr_gsl_vector_new(m);
    nm->rhs = fr_gsl_vector_new(m);
    nm->sol = fr_gsl_vector_new(m);
    if (nm->Fz && nm->Fa && nm->T && nm->row && nm->rows && nm->perm && nm->tau && nm->norm &&
        nm->rhs && nm->sol)
        return 1;
    void *blocks[] = {nm->Fz,   nm->Fa,  nm->T,    nm->row, nm->rows,
                      nm->perm, nm->tau, nm->norm, nm->rhs, nm->sol};
    for (size_t k = 0; k < sizeof blocks / sizeof *blocks; k++)
        free(blocks[k]);
    nm->Fz = nm->Fa = nm->T = nm->row = NULL;
    nm->rows = NULL;
    nm->perm = NULL;
    nm->tau = nm->norm = nm->rhs = nm->sol = NULL;
    return 0;
}

/* Row i of T = I - c F_z W_eff + F_a (W - W_eff) into nm->row. */
static void dense_row(struct fr_newton_matrix *nm, size_t i, double coef, const cholmod_sparse *W,
                      const cholmod_sparse *Weff)
{
    size_t m = nm->m;
    const double *fz = nm->Fz + i * m, *fa = nm->Fa + i * m;
    memset(nm->row, 0, m * sizeof *nm->row);
    nm->row[i] = 1.0;
    row_times_sym(W, 1.0, fa, nm->row);
    row_times_sym(Weff, -1.0, fa, nm->row);
    row_times_sym(Weff, -coef, fz, nm->row);
}

static int row_is_identity(const double fz[], const double fa[], size_t m)
{
    for (size_t j = 0; j < m; j++)
        if (fz[j] != 0.0 || fa[j] != 0.0)
            return 0;
    return 1;
}

/* T_NN df_N = -G_N - T_NR df_R with df_R = -G_R, by QR with column pivoting. */
static int dense_direction(struct fr_newton_matrix *nm, fricreg_ctx *ctx, double coef,
                           const cholmod_sparse *W, const cholmod_sparse *Weff, const double G[],
                           double df[])
{
    size_t m = nm->m, k = 0;
    if (!dense_allocate(nm))
        return FRICREG_ENOMEM;
    int status = fricreg_ctx_tangent(ctx, m, nm->Fz, nm->Fa);
    if (status != FRICREG_OK)
        return status;
    for (size_t i = 0; i < m; i++) {
        df[i] = -G[i];
        nm->fz[i] = nm->Fz[i * m + i]; /* the slopes newmark.c's first trial reads */
        if (!row_is_identity(nm->Fz + i * m, nm->Fa + i * m, m))
            nm->rows[k++] = i;
    }
    if (k == 0)
        return FRICREG_OK;
    gsl_matrix_view T = gsl_matrix_view_array(nm->T, k, k);
    gsl_vector_view rhs = gsl_vector_subvector(nm->rhs, 0, k);
    for (size_t p = 0; p < k; p++) {
        size_t i = nm->rows[p];
        dense_row(nm, i, coef, W, Weff);
        double r = -G[i];
        for (size_t j = 0, q = 0; j < m; j++) {
            if (q < k && nm->rows[q] == j)
                gsl_matrix_set(&T.matrix, p, q++, nm->row[j]);
            else
                r -= nm->row[j] * df[j];
        }
        gsl_vector_set(&rhs.vector, p, r);
    }
    gsl_permutation perm = {k, nm->perm->data};
    gsl_vector_view tau = gsl_vector_subvector(nm->tau, 0, k);
    gsl_vector_view norm = gsl_vector_subvector(nm->norm, 0, k);
    gsl_vector_view sol = gsl_vector_subvector(nm->sol, 0, k);
    int signum;
    if (gsl_linalg_QRPT_decomp(&T.matrix, &tau.vector, &perm, &signum, &norm.vector) != GSL_SUCCESS)
        return FRICREG_ESINGULAR;
    for (size_t p = 0; p < k; p++)
        if (gsl_matrix_get(&T.matrix, p, p) == 0.0)
            return FRICREG_ESINGULAR;
    if (gsl_linalg_QRPT_solve(&T.matrix, &tau.vector, &perm, &rhs.vector, &sol.vector) !=
        GSL_SUCCESS)
        return FRICREG_ESINGULAR;
    for (size_t p = 0; p < k; p++)
        df[nm->rows[p]] = gsl_vector_get(&sol.vector, p);
    return FRICREG_OK;
}

/* ---- Contact by contact ---------------------------------------------------------------- */

int fr_newton_matrix_prepare(struct fr_newton_matrix *nm, const cholmod_sparse *Weff, int dense,
                             cholmod_common *c)
{
    size_t m = Weff->ncol;
    fr_masked_factor_free(&nm->block, c);
    if (nm->m != m || nm->fz == NULL) {
        fr_newton_matrix_free(nm, c);
        nm->m = m;
        nm->fz = malloc(m * sizeof *nm->fz);
        nm->coef = malloc(m * sizeof *nm->coef);
        nm->wg = malloc(m * sizeof *nm->wg);
        nm->shift = malloc(m * sizeof *nm->shift);
        nm->b = malloc(m * sizeof *nm->b);
        nm->implicit = malloc(m);
        nm->in_n = malloc(m);
        nm->runs = malloc(3 * (m + 1) * sizeof *nm->runs);
        if (!(nm->fz && nm->coef && nm->wg && nm->shift && nm->b && nm->implicit && nm->in_n &&
              nm->runs)) {
            fr_newton_matrix_free(nm, c); /* none kept: the next call allocates them all */
            return FRICREG_ENOMEM;
        }
    }
    if (dense && !dense_allocate(nm))
        return FRICREG_ENOMEM;
    return fr_masked_factor_prepare(&nm->block, Weff, nm->storage, c);
}

/* Each row of T df = -G from the context's rows (fr_ctx_tangent_rows), into N's shifts and
 * right-hand sides over W_eff (newton_matrix.h); df_R = -G_R. 1 if every row of N fits the
 * symmetric form (shift >= 0), 0 to go dense (a falling Stribeck branch). */
static int rows_split(struct fr_newton_matrix *nm, double coef, const cholmod_sparse *W,
                      const double G[], double df[])
{
    size_t m = nm->m;
    int any_implicit = 0;
    for (size_t i = 0; i < m; i++)
        any_implicit |= nm->implicit[i];
    if (any_implicit)
        fr_delassus_mult(W, 1.0, G, 0.0, nm->wg); /* [W G] */
    for (size_t i = 0; i < m; i++) {
        double k = nm->coef[i];
        nm->fz[i] = nm->implicit[i] ? -k : k; /* zero where F_i does not move with zdot_i */
        nm->in_n[i] = nm->implicit[i] || k != 0.0;
        nm->shift[i] = 0.0;
        if (nm->implicit[i]) { /* (1 + c k_i) [W_eff df]_i = -[W G]_i */
            double scale = 1.0 + coef * k;
            if (!(scale > 0.0))
                return 0;
            nm->b[i] = -nm->wg[i] / scale;
        } else if (k < 0.0) { /* [W_eff df]_i + df_i / (c |s_i|) = -G_i / (c |s_i|) */
            nm->shift[i] = 1.0 / (coef * -k);
            nm->b[i] = -G[i] * nm->shift[i];
        } else if (k > 0.0) {
            return 0;
        } else {
            df[i] = -G[i];
        }
    }
    return 1;
}

/* b_N -= W_eff,NR df_R, with u = W_eff [0; df_R] (all rows) into nm->wg where W_eff is packed
 * (contact_factor.h): through R's runs where they are few (delassus_runs.h), else one BLAS
 * product over all of W_eff with df_N zeroed (the block's solve writes df_N). Returns whether
 * u was formed. */
static int rows_rhs(struct fr_newton_matrix *nm, const cholmod_sparse *Weff, double df[])
{
    size_t m = nm->m;
    if (fr_delassus_packed(Weff)) {
        size_t *r_runs = nm->runs, all[2] = {0, m}, in_r;
        size_t nr = fr_runs_of(nm->in_n, 0, m, r_runs, &in_r);
        if (fr_delassus_runs_cheaper(Weff, m, 1, in_r, nr)) {
            fr_delassus_mult_runs(Weff, r_runs, nr, df, all, 1, nm->wg);
        } else {
            for (size_t i = 0; i < m; i++)
                df[i] = nm->in_n[i] ? 0.0 : df[i];
            fr_delassus_mult(Weff, 1.0, df, 0.0, nm->wg);
        }
        for (size_t i = 0; i < m; i++)
            nm->b[i] -= nm->in_n[i] ? nm->wg[i] : 0.0;
        return 1;
    }
    const SuiteSparse_long *Wp = Weff->p, *Wi = Weff->i;
    const double *Wx = Weff->x;
    for (size_t j = 0; j < m; j++)
        for (SuiteSparse_long p = Wp[j]; p < Wp[j + 1]; p++) {
            size_t i = (size_t)Wi[p];
            if (nm->in_n[i] && !nm->in_n[j])
                nm->b[i] -= Wx[p] * df[j];
            else if (nm->in_n[j] && !nm->in_n[i])
                nm->b[j] -= Wx[p] * df[i];
        }
    return 0;
}

/* weff_df = W_eff df after the block's solve, with u = W_eff [0; df_R] from rows_rhs. On the
 * implicit rows the solve's own equations give it: [W_eff df]_i = b_i + u_i (b after
 * rows_rhs, shift 0). The other rows E (R, and the shifted rows, where b_i - shift_i df_i
 * would cancel) take W_eff,EN df_N + u_E through the runs of E and N where those are few;
 * otherwise the whole product. */
static void direction_product(struct fr_newton_matrix *nm, const cholmod_sparse *Weff,
                              const double df[], double weff_df[])
{
    size_t m = nm->m, in_e, in_n;
    size_t *e_runs = nm->runs + (m + 1), *n_runs = nm->runs + 2 * (m + 1);
    size_t ne = fr_runs_of(nm->implicit, 0, m, e_runs, &in_e);
    size_t nn = fr_runs_of(nm->in_n, 1, m, n_runs, &in_n);
    if (!fr_delassus_runs_cheaper(Weff, in_e, ne, in_n, nn)) {
        fr_delassus_mult(Weff, 1.0, df, 0.0, weff_df);
        return;
    }
    fr_delassus_mult_runs(Weff, n_runs, nn, df, e_runs, ne, weff_df);
    for (size_t i = 0; i < m; i++)
        weff_df[i] = nm->implicit[i] ? nm->b[i] + nm->wg[i] : weff_df[i] + nm->wg[i];
}

int fr_newton_direction(struct fr_newton_matrix *nm, fricreg_ctx *ctx, double coef,
                        const cholmod_sparse *W, const cholmod_sparse *Weff, const double G[],
                        double df[], double weff_df[], cholmod_common *c)
{
    int status = fr_ctx_tangent_rows(ctx, nm->implicit, nm->coef);
    if (status != FRICREG_OK || !rows_split(nm, coef, W, G, df)) {
        status = dense_direction(nm, ctx, coef, W, Weff, G, df);
        if (status == FRICREG_OK)
            fr_delassus_mult(Weff, 1.0, df, 0.0, weff_df);
        return status;
    }
    int formed_u = rows_rhs(nm, Weff, df);
    if (nm->sparse != NULL)
        status = fr_contact_sparse_solve(nm->sparse, Weff, nm->in_n, nm->shift, nm->b, df, c);
    else
        status = fr_masked_factor_solve(&nm->block, Weff, nm->in_n, nm->shift, nm->b, df, c);
    if (status != FRICREG_OK)
        return status;
    if (formed_u && nm->sparse == NULL) /* the sparse path's solve may be a chord's */
        direction_product(nm, Weff, df, weff_df);
    else
        fr_delassus_mult(Weff, 1.0, df, 0.0, weff_df);
    return FRICREG_OK;
}

/* weff_x = W_eff [x_S; 0] after the stick block's solve W_eff,SS x_S = b_S: b_S on S, and
 * W_eff,RS x_S on the others through the runs of S and R where they are few; otherwise the
 * whole product of [x_S; 0] (nm->wg its scratch). */
static void stick_product(struct fr_newton_matrix *nm, const cholmod_sparse *Weff,
                          const unsigned char set[], const double b[], const double x[],
                          double weff_x[])
{
    size_t m = nm->m, in_s, in_r;
    size_t *s_runs = nm->runs, *r_runs = nm->runs + (m + 1);
    size_t ns = fr_runs_of(set, 1, m, s_runs, &in_s);
    size_t nr = fr_runs_of(set, 0, m, r_runs, &in_r);
    if (nm->sparse != NULL || !fr_delassus_runs_cheaper(Weff, in_r, nr, in_s, ns)) {
        for (size_t i = 0; i < m; i++)
            nm->wg[i] = set[i] ? x[i] : 0.0;
        fr_delassus_mult(Weff, 1.0, nm->wg, 0.0, weff_x);
        return;
    }
    fr_delassus_mult_runs(Weff, s_runs, ns, x, r_runs, nr, weff_x);
    for (size_t i = 0; i < m; i++)
        weff_x[i] = set[i] ? b[i] : weff_x[i];
}

int fr_newton_stick_solve(struct fr_newton_matrix *nm, const cholmod_sparse *Weff,
                          const unsigned char set[], const double b[], double x[], double weff_x[],
                          cholmod_common *c)
{
    int status = nm->sparse != NULL ? fr_contact_sparse_solve(nm->sparse, Weff, set, NULL, b, x, c)
                                    : fr_masked_factor_solve(&nm->block, Weff, set, NULL, b, x, c);
    if (status == FRICREG_OK)
        stick_product(nm, Weff, set, b, x, weff_x);
    return status;
}

double fr_newton_first_stop(size_t m, const double zdot[], const double weff_df[], double coef,
                            double eps, const double mun[], const double fz[],
                            unsigned char stopped[])
{
    double lambda = 1.0;
    size_t first = m;
    for (size_t i = 0; i < m; i++) {
        double z = zdot[i], z1 = z + coef * weff_df[i];
        if (!stopped[i] && mun[i] > 0.0 && fz[i] == 0.0 && z * z1 < 0.0 && fabs(z1) >= eps &&
            z / (z - z1) < lambda) {
            lambda = z / (z - z1);
            first = i;
        }
    }
    if (first < m)
        stopped[first] = 1;
    return lambda;
}

void fr_newton_stick_rhs(size_t m, int exact, double coef, double eps, const double mun[],
                         const double w[], const double z0[], const double a0[],
                         const double weff_f[], const double zstart[], const double zdot[],
                         double b[])
{
    if (exact) {
        double two_over_eps = 2.0 / eps;
        for (size_t i = 0; i < m; i++) {
            double ki = mun[i] * w[i] * two_over_eps;
            b[i] = (-a0[i] - ki * z0[i]) / (1.0 + coef * ki) - weff_f[i];
        }
    } else {
        for (size_t i = 0; i < m; i++)
            b[i] = (zstart[i] - zdot[i]) / coef;
    }
}
