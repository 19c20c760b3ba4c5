/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_tangent.c — fricreg_disk_ctx_tangent: implicit differentiation of the coupled 2-D law's
 * KKT conditions at the last evaluation's solution (fricreg_disk_ctx.h; docs/laws2d.md).
 *
 * Unknowns: the derivatives of the near-stick forces f_i (two rows each) and, for a contact
 * on its circle, of its multiplier lam_i, scaled by radius_i (so that its column is the unit
 * normal n_i = (f_i + p_i)/radius_i and both blocks are of one scale). Rows:
 *   stationarity  (W f)_i + a_free,i + 2 W_ii p_i + lam_i (f_i + p_i) = 0,
 *   circle        n_i^T (f_i + p_i) - radius_i = 0 (linearized: n_i^T df_i = d radius_i -
 *                 n_i^T dp_i),
 * with p_i = mun_i zdot_i/eps (FRICREG_DISK_QUINN; 0 for the force balance), radius_i =
 * mun_i - mun_i |zdot_i|/eps, and the fixed contacts' forces entering through W. The matrix
 *   [ W_SS + diag(lam_i I)   N ]
 *   [ N^T                    0 ]
 * (N the normals of the circle contacts) is factored once by GSL's Householder QR (no
 * allocation, no GSL error path) and solved for each of the 4m parameter columns. */
#include <math.h>
#include <string.h>

#include <gsl/gsl_linalg.h>

#include "disk_ctx_internal.h"

#define PIVOT_RTOL 1e-13

static void assemble(fricreg_disk_ctx *ctx, size_t n)
{
    double *J = ctx->kkt;
    memset(J, 0, n * n * sizeof *J);
    for (size_t k = 0; k < ctx->n_near; k++) {
        size_t i = ctx->near[k], ri = ctx->row[i];
        for (size_t l = 0; l < ctx->n_near; l++) {
            size_t j = ctx->near[l], rj = ctx->row[j];
            for (int a = 0; a < 2; a++)
                for (int b = 0; b < 2; b++)
                    J[(ri + a) * n + rj + b] = fr_disk_w(ctx, i, a, j, b);
        }
        if (ctx->kind[i] != FR_DISK_CIRCLE)
            continue;
        double nv[2];
        fr_disk_normal(ctx, i, nv);
        size_t mr = ctx->mrow[i];
        for (int a = 0; a < 2; a++) {
            J[(ri + a) * n + ri + a] += ctx->lam[i];
            J[(ri + a) * n + mr] = nv[a];
            J[mr * n + ri + a] = nv[a];
        }
    }
}

/* Factors the KKT matrix (order n > 0) in place; ESINGULAR for a tiny pivot of R. */
static int factor(fricreg_disk_ctx *ctx, size_t n)
{
    gsl_matrix_view A = gsl_matrix_view_array(ctx->kkt, n, n);
    gsl_vector_view tau = gsl_vector_view_array(ctx->tau, n);
    gsl_linalg_QR_decomp(&A.matrix, &tau.vector);
    double big = 0.0;
    for (size_t k = 0; k < n; k++)
        big = fmax(big, fabs(ctx->kkt[k * n + k]));
    for (size_t k = 0; k < n; k++)
        if (!(fabs(ctx->kkt[k * n + k]) > PIVOT_RTOL * big))
            return fr_fail(ctx, FRICREG_ESINGULAR,
                           "tangent: the KKT matrix of the near-stick contacts is "
                           "singular (pivot %zu of its R factor)",
                           k);
    return FRICREG_OK;
}

/* The right-hand side -dR/d(param) of one parameter: zdot_{j,b} (afree = 0) or a_free_{j,b}
 * (afree = 1), into ctx->col; also the fixed contact's own derivative Dj. */
static void parameter_column(fricreg_disk_ctx *ctx, size_t n, size_t j, int b, int afree,
                             const double Dj[4])
{
    double *c = ctx->col;
    memset(c, 0, n * sizeof *c);
    if (ctx->kind[j] == FR_DISK_FIXED) {
        if (afree)
            return; /* a fixed force does not see a_free */
        for (size_t k = 0; k < ctx->n_near; k++) {
            size_t i = ctx->near[k];
            for (int a = 0; a < 2; a++)
                c[ctx->row[i] + a] = -(fr_disk_w(ctx, i, a, j, 0) * Dj[b] +
                                       fr_disk_w(ctx, i, a, j, 1) * Dj[2 + b]);
        }
        return;
    }
    size_t rj = ctx->row[j];
    if (afree) {
        c[rj + b] = -1.0;
        return;
    }
    double P[4];
    fr_disk_centre_jacobian(ctx, j, P);
    for (int a = 0; a < 2; a++) { /* d/dp of 2 W_jj p_j + lam (f_j + p_j), times dp/dzdot */
        double w = 0.0;
        for (int e = 0; e < 2; e++)
            w += (2.0 * ctx->blk[4 * j + 2 * a + e] + (a == e ? ctx->lam[j] : 0.0)) * P[2 * e + b];
        c[rj + a] = -w;
    }
    if (ctx->kind[j] == FR_DISK_CIRCLE)
        c[ctx->mrow[j]] = fr_disk_normal_rate(ctx, j, b, P);
}

/* Writes column (j, b) of one output (zeroed before) from the solved column and Dj. */
static void scatter(fricreg_disk_ctx *ctx, size_t j, int b, int afree, const double Dj[4],
                    double *out)
{
    size_t m2 = 2 * ctx->m, col = 2 * j + (size_t)b;
    for (size_t k = 0; k < ctx->n_near; k++) {
        size_t i = ctx->near[k];
        out[2 * i * m2 + col] = ctx->col[ctx->row[i]];
        out[(2 * i + 1) * m2 + col] = ctx->col[ctx->row[i] + 1];
    }
    if (ctx->kind[j] == FR_DISK_FIXED && !afree) {
        out[2 * j * m2 + col] = Dj[b];
        out[(2 * j + 1) * m2 + col] = Dj[2 + b];
    }
}

/* Whether the solved column (order n) and the fixed contact's own derivative are finite. */
static int column_finite(const fricreg_disk_ctx *ctx, size_t n, size_t j, int afree,
                         const double Dj[4])
{
    for (size_t k = 0; k < n; k++)
        if (!isfinite(ctx->col[k]))
            return 0;
    return afree || ctx->kind[j] != FR_DISK_FIXED ||
           (isfinite(Dj[0]) && isfinite(Dj[1]) && isfinite(Dj[2]) && isfinite(Dj[3]));
}

/* Columns (j, 0), (j, 1) of one output (df_dzdot or df_dafree) for the factored system of
 * order n of the near-stick set ctx->near. A dry run (out NULL) writes nothing and returns
 * whether every entry would be finite; otherwise returns 1. */
static int fill_columns(fricreg_disk_ctx *ctx, size_t n, size_t j, int afree, double *out)
{
    gsl_matrix_const_view A = gsl_matrix_const_view_array(ctx->kkt, n, n);
    gsl_vector_const_view tau = gsl_vector_const_view_array(ctx->tau, n);
    double Dj[4] = {0.0, 0.0, 0.0, 0.0};
    if (ctx->kind[j] == FR_DISK_FIXED)
        fr_disk_fixed_jacobian(ctx, j, Dj);
    for (int b = 0; b < 2; b++) {
        parameter_column(ctx, n, j, b, afree, Dj);
        if (n > 0) {
            gsl_vector_view x = gsl_vector_view_array(ctx->col, n);
            gsl_linalg_QR_svx(&A.matrix, &tau.vector, &x.vector);
        }
        if (out == NULL && !column_finite(ctx, n, j, afree, Dj))
            return 0;
        if (out != NULL)
            scatter(ctx, j, b, afree, Dj, out);
    }
    return 1;
}

/* Numbers the rows of the near-stick set ctx->near, assembles and factors its KKT matrix;
 * *order gets its order. */
static int prepare(fricreg_disk_ctx *ctx, size_t *order)
{
    size_t n = fr_disk_number_rows(ctx);
    *order = n;
    if (n == 0)
        return FRICREG_OK;
    assemble(ctx, n);
    return factor(ctx, n);
}

/* Dense W: one system for all near-stick contacts, every column of the outputs wanted (dry:
 * none written; returns whether all would be finite). */
static int tangent_dense(fricreg_disk_ctx *ctx, size_t n, double *dz, double *da, int dry)
{
    int finite = 1;
    for (size_t j = 0; j < ctx->m && finite; j++) {
        if (dz != NULL)
            finite = fill_columns(ctx, n, j, 0, dry ? NULL : dz);
        if (da != NULL && finite)
            finite = fill_columns(ctx, n, j, 1, dry ? NULL : da);
    }
    return finite;
}

/* Block diagonal W: every near-stick contact's factor is checked before anything is written. */
static int check_blocks(fricreg_disk_ctx *ctx)
{
    size_t *all = ctx->near, n_all = ctx->n_near, n;
    int status = FRICREG_OK;
    for (size_t k = 0; k < n_all && status == FRICREG_OK; k++) {
        ctx->near = all + k, ctx->n_near = 1;
        status = prepare(ctx, &n);
    }
    ctx->near = all, ctx->n_near = n_all;
    return status;
}

/* Block diagonal W: each near-stick contact alone (order <= 3), its own columns only; the
 * fixed contacts' diagonal blocks. */
static int tangent_blocks(fricreg_disk_ctx *ctx, double *dz, double *da, int dry)
{
    size_t *all = ctx->near, n_all = ctx->n_near, n;
    int finite = 1;
    for (size_t j = 0; j < ctx->m && finite; j++) {
        if (ctx->kind[j] != FR_DISK_FIXED) {
            ctx->near = &j, ctx->n_near = 1;
            prepare(ctx, &n);
        } else {
            ctx->n_near = 0, n = 0;
        }
        if (dz != NULL)
            finite = fill_columns(ctx, n, j, 0, dry ? NULL : dz);
        if (da != NULL && finite)
            finite = fill_columns(ctx, n, j, 1, dry ? NULL : da);
    }
    ctx->near = all, ctx->n_near = n_all;
    return finite;
}

/* Whether some scale the tangent multiplies or divides by is beyond 1e100 (a slope mun/eps or
 * mun/|zdot|, a multiplier, an entry of W or the inverse of a block's eigenvalue): only then
 * can an entry overflow, the KKT matrix's pivots being within 1e13 of each other. */
static int extreme_scales(const fricreg_disk_ctx *ctx)
{
    const double big = 1e100;
    for (size_t i = 0; i < ctx->m; i++) {
        double D[4], P[4];
        fr_disk_fixed_jacobian(ctx, i, D);
        fr_disk_centre_jacobian(ctx, i, P);
        double dmin = fmin(ctx->eig[i].d1, ctx->eig[i].d2);
        if (fmax(fmax(fabs(D[0]), fabs(D[3])), fmax(fabs(P[0]), fabs(P[3]))) > big ||
            fabs(D[1]) > big || fabs(P[1]) > big || ctx->lam[i] > big || dmin < 1.0 / big ||
            fmax(ctx->eig[i].d1, ctx->eig[i].d2) > big)
            return 1;
    }
    size_t n = 2 * ctx->m;
    for (size_t k = 0; ctx->W != NULL && k < n * n; k++)
        if (fabs(ctx->W[k]) > big)
            return 1;
    const struct fr_disk_coupling *w = ctx->cpl != NULL ? &ctx->cpl->w : NULL;
    for (int64_t k = 0; w != NULL && k < 4 * w->ptr[ctx->m]; k++)
        if (fabs(w->blk[k]) > big)
            return 1;
    return 0;
}

/* Which tangent: dense W (the bordered KKT matrix by QR), block diagonal (per contact), or
 * sparse W (the reduced Hessian's sparse factor, disk_tangent_sparse.c). */
enum shape { DENSE, BLOCKS, SPARSE };

static enum shape shape_of(const fricreg_disk_ctx *ctx)
{
    return ctx->W != NULL ? DENSE : ctx->cpl != NULL ? SPARSE : BLOCKS;
}

/* Every column of the outputs (zeroed before); dry: none written, whether all are finite. */
static int tangent_columns(fricreg_disk_ctx *ctx, size_t n, double *dz, double *da, int dry)
{
    switch (shape_of(ctx)) {
    case DENSE: return tangent_dense(ctx, n, dz, da, dry);
    case SPARSE: return fr_disk_tangent_sparse(ctx, dz, da, dry);
    default: return tangent_blocks(ctx, dz, da, dry);
    }
}

/* The factor (dense, sparse) or the blocks' factors checked, before anything is written. */
static int tangent_factor(fricreg_disk_ctx *ctx, size_t *n)
{
    *n = 0;
    switch (shape_of(ctx)) {
    case DENSE: return prepare(ctx, n);
    case SPARSE: return fr_disk_tangent_sparse_factor(ctx);
    default: return check_blocks(ctx);
    }
}

/* The slopes the tangent divides by must be finite: checked before anything is written. */
static int check_slopes(fricreg_disk_ctx *ctx)
{
    for (size_t i = 0; i < ctx->m; i++) {
        double D[4], P[4];
        fr_disk_fixed_jacobian(ctx, i, D);
        fr_disk_centre_jacobian(ctx, i, P);
        double dB = fr_disk_bound_slope(ctx, i, ctx->r[i]);
        if (!isfinite(P[0]) || !isfinite(P[1]) || !isfinite(P[3]) || !isfinite(dB) ||
            !isfinite(D[0]) || !isfinite(D[1]) || !isfinite(D[3]))
            return fr_fail(ctx, FRICREG_ENONFINITE,
                           "tangent: contact %zu's slope mun/eps, mun/|zdot| or the "
                           "Stribeck bound's overflows",
                           i);
    }
    return FRICREG_OK;
}

int fricreg_disk_ctx_tangent(fricreg_disk_ctx *ctx, size_t m, double df_dzdot[], double df_dafree[])
{
    if (ctx == NULL)
        return FRICREG_ENULL;
    if (df_dzdot == NULL && df_dafree == NULL)
        return fr_fail(ctx, FRICREG_ENULL, "tangent: both outputs are NULL");
    if (m != ctx->m)
        return fr_fail(ctx, FRICREG_ESIZE, "tangent: m = %zu, context has %zu contacts", m, ctx->m);
    if (!ctx->last_valid)
        return fr_fail(ctx, FRICREG_EINVAL,
                       "tangent: no successful evaluation since the last setter call");
    int status = fr_disk_restore_state(ctx); /* a failed eval since overwrote it */
    if (status != FRICREG_OK)
        return status;
    size_t n = 0; /* factored first: a singular system writes nothing */
    status = check_slopes(ctx);
    if (status == FRICREG_OK)
        status = tangent_factor(ctx, &n);
    if (status != FRICREG_OK)
        return status;
    /* Near the double range, a dry run first: nothing is written unless every entry is
     * finite (fuzz finding: mun/eps = 4.5e307 gave NaN with FRICREG_OK). */
    if (extreme_scales(ctx) && !tangent_columns(ctx, n, df_dzdot, df_dafree, 1))
        return fr_fail(ctx, FRICREG_ENONFINITE,
                       "tangent: an entry overflows the double range (slopes mun/eps, "
                       "mun/|zdot| or W^-1 near it)");
    size_t n2 = 4 * m * m;
    if (df_dzdot != NULL)
        memset(df_dzdot, 0, n2 * sizeof *df_dzdot);
    if (df_dafree != NULL)
        memset(df_dafree, 0, n2 * sizeof *df_dafree);
    tangent_columns(ctx, n, df_dzdot, df_dafree, 0);
    return FRICREG_OK;
}
