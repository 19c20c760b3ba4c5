/* SPDX-License-Identifier: GPL-3.0-or-later */
/* sparse_setup.c — fricreg_ctx_set_coupling_csr and _csc: a sparse W checked as
 * set_coupling_dense checks its W (ctx.c), then installed (sparse_coupling.h). Nothing on the
 * way is O(m^2) in memory or O(m^3) in time.
 *
 * The checks, in the dense setter's order and with its tolerances, all on the Jacobi-scaled
 * A = D^-1/2 W D^-1/2 (D = diag W, unit diagonal), so that units do not matter:
 *   - every W_ii >= DBL_MIN;
 *   - given whole, symmetric: |W_ij - W_ji| <= 1e-12 sqrt(W_ii W_jj); the symmetric part
 *     (W + W^T)/2 is used;
 *   - |a_ij| <= 1 + tol (a negative 2 x 2 minor, caught before the factorization, which it
 *     could overflow), tol = 1e-12 r with r the largest count of entries in a row of W: a
 *     bound of the largest eigenvalue of a semidefinite A (|a_ij| <= 1), and the dense
 *     setter's 1e-12 m for a row as full as a dense one's;
 *   - semidefinite: the Cholesky factorization (CHOLMOD, simplicial LL^T, AMD) of A + tol I
 *     exists, i.e. the smallest eigenvalue of A is above -tol (to rounding, which is far below
 *     tol): the dense setter's test, which asks the same of GSL's eigenvalues at O(m^3).
 * A singular W (redundant contacts) passes, as in the dense setter; an evaluation then refuses
 * a singular block with FRICREG_ESINGULAR. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "box_qp.h"
#include "ctx_internal.h"
#include "partition_consistent.h"
#include "sparse_block.h"
#include "sparse_coupling.h"
#include "base/matrix_input.h"
#include "base/sparse_factor.h"
#include "base/sparse_ops.h"

#define SYMMETRY_RTOL 1e-12
#define PSD_RTOL 1e-12

/* The message's index of row or column i: the caller's base. */
#define SHOWN(i) ((long long)(i) + base)

static int out_of_memory(fricreg_ctx *ctx, const char *who)
{
    return fr_fail(ctx, FRICREG_ENOMEM, "%s: out of memory for m = %zu", who, ctx->m);
}

/* diag[j] = A_jj, each >= DBL_MIN: a mobility whose inverse, the scale of the tangent, does
 * not overflow (as the dense setter). */
static int check_diagonal(fricreg_ctx *ctx, const cholmod_sparse *A, long long base, double diag[],
                          const char *who)
{
    for (size_t j = 0; j < ctx->m; j++) {
        diag[j] = fr_csc_entry(A, (SuiteSparse_long)j, (SuiteSparse_long)j);
        if (!(diag[j] >= DBL_MIN))
            return fr_fail(ctx, FRICREG_ENOTPSD, "%s: W(%lld, %lld) = %g must be >= %g", who,
                           SHOWN(j), SHOWN(j), diag[j], DBL_MIN);
    }
    return FRICREG_OK;
}

/* A given whole: |A_ij - A_ji| <= 1e-12 sqrt(A_ii A_jj), from D = A - A^T. */
static int check_symmetry(fricreg_ctx *ctx, const cholmod_sparse *A, const cholmod_sparse *D,
                          const double diag[], long long base, const char *who)
{
    const SuiteSparse_long *Dp = D->p, *Di = D->i;
    const double *Dx = D->x;
    for (size_t j = 0; j < ctx->m; j++)
        for (SuiteSparse_long p = Dp[j]; p < Dp[j + 1]; p++) {
            SuiteSparse_long i = Di[p];
            if (i < (SuiteSparse_long)j &&
                fabs(Dx[p]) / sqrt(diag[i]) / sqrt(diag[j]) > SYMMETRY_RTOL)
                return fr_fail(ctx, FRICREG_ENOTSYM,
                               "%s: W(%lld, %lld) = %g but W(%lld, %lld) = %g", who, SHOWN(i),
                               SHOWN(j), fr_csc_entry(A, i, (SuiteSparse_long)j), SHOWN(j),
                               SHOWN(i), fr_csc_entry(A, (SuiteSparse_long)j, i));
        }
    return FRICREG_OK;
}

/* A given whole, square and sorted: checked, then *W = (A + A^T)/2, both triangles. */
static int symmetric_part(fricreg_ctx *ctx, cholmod_sparse *A, cholmod_common *c, long long base,
                          double diag[], cholmod_sparse **W, const char *who)
{
    int status = check_diagonal(ctx, A, base, diag, who);
    if (status != FRICREG_OK)
        return status;
    cholmod_sparse *At = cholmod_l_transpose(A, 1, c), *D = NULL;
    if (At != NULL)
        D = cholmod_l_add(A, At, (double[2]){1.0, 0.0}, (double[2]){-1.0, 0.0}, 1, 1, c);
    status = D == NULL ? out_of_memory(ctx, who) : check_symmetry(ctx, A, D, diag, base, who);
    if (status == FRICREG_OK) {
        *W = cholmod_l_add(A, At, (double[2]){0.5, 0.0}, (double[2]){0.5, 0.0}, 1, 1, c);
        if (*W == NULL)
            status = out_of_memory(ctx, who);
    }
    cholmod_l_free_sparse(&At, c);
    cholmod_l_free_sparse(&D, c);
    return status;
}

/* The caller's arrays (checked) as the whole symmetric W, sorted, with its diagonal checked
 * into diag. */
static int whole_matrix(fricreg_ctx *ctx, const struct fr_compressed *a, cholmod_common *c,
                        double diag[], cholmod_sparse **W, const char *who)
{
    long long base = (a->flags & FRICREG_SPARSE_ONE_BASED) ? 1 : 0;
    int triangle = (a->flags & (FRICREG_SPARSE_UPPER | FRICREG_SPARSE_LOWER)) != 0;
    cholmod_sparse *A = NULL;
    int status = fr_compressed_to_cholmod(a, triangle, c, &A, &ctx->err, who);
    if (status != FRICREG_OK)
        return status;
    if (triangle) { /* A is the upper triangle (stype 1): both, sorted */
        *W = cholmod_l_copy(A, 0, 1, c);
        status = *W != NULL && cholmod_l_sort(*W, c) ? check_diagonal(ctx, *W, base, diag, who)
                                                     : out_of_memory(ctx, who);
    } else {
        status = symmetric_part(ctx, A, c, base, diag, W, who);
    }
    cholmod_l_free_sparse(&A, c);
    return status;
}

/* The upper triangle of A = D^-1/2 W D^-1/2 into *U, with |a_ij| <= 1 + tol checked and
 * tol = 1e-12 r, r W's largest count of entries in a row. */
static int scaled_upper(fricreg_ctx *ctx, const cholmod_sparse *W, const double diag[],
                        cholmod_common *c, long long base, cholmod_sparse **U, double *tol,
                        const char *who)
{
    const SuiteSparse_long *Wp = W->p;
    SuiteSparse_long widest = 1;
    for (size_t j = 0; j < ctx->m; j++)
        widest = Wp[j + 1] - Wp[j] > widest ? Wp[j + 1] - Wp[j] : widest;
    *tol = PSD_RTOL * (double)widest;
    *U = cholmod_l_copy((cholmod_sparse *)W, 1, 1, c);
    if (*U == NULL)
        return out_of_memory(ctx, who);
    const SuiteSparse_long *Up = (*U)->p, *Ui = (*U)->i;
    double *Ux = (*U)->x;
    for (size_t j = 0; j < ctx->m; j++)
        for (SuiteSparse_long p = Up[j]; p < Up[j + 1]; p++) {
            SuiteSparse_long i = Ui[p];
            Ux[p] = Ux[p] / sqrt(diag[i]) / sqrt(diag[j]);
            if (!(fabs(Ux[p]) <= 1.0 + *tol))
                return fr_fail(
                    ctx, FRICREG_ENOTPSD,
                    "%s: W(%lld, %lld)^2 > W(%lld, %lld) W(%lld, %lld): not semidefinite", who,
                    SHOWN(i), SHOWN(j), SHOWN(i), SHOWN(i), SHOWN(j), SHOWN(j));
        }
    return FRICREG_OK;
}

/* Semidefinite: A + tol I has a Cholesky factor. */
static int check_semidefinite(fricreg_ctx *ctx, const cholmod_sparse *W, const double diag[],
                              cholmod_common *c, long long base, const char *who)
{
    cholmod_sparse *U = NULL;
    double tol = 0.0;
    int status = scaled_upper(ctx, W, diag, c, base, &U, &tol, who);
    if (status != FRICREG_OK) {
        cholmod_l_free_sparse(&U, c);
        return status;
    }
    c->nmethods = 1;
    c->method[0].ordering = CHOLMOD_AMD;
    c->postorder = 1;
    c->supernodal = CHOLMOD_SIMPLICIAL; /* no BLAS: nothing of OpenBLAS's threads */
    c->final_ll = 1;
    c->final_asis = 1;
    cholmod_factor *L = cholmod_l_analyze(U, c);
    if (L != NULL)
        cholmod_l_factorize_p(U, (double[2]){tol, 0.0}, NULL, 0, L, c);
    if (L != NULL && c->status == CHOLMOD_NOT_POSDEF)
        status = fr_fail(ctx, FRICREG_ENOTPSD,
                         "%s: D^-1/2 W D^-1/2 + %g I (D = diag W) has no Cholesky factor"
                         " (contact %lld): W is not positive semidefinite",
                         who, tol, SHOWN(((SuiteSparse_long *)L->Perm)[L->minor]));
    else if (L == NULL || c->status < CHOLMOD_OK)
        status = out_of_memory(ctx, who);
    cholmod_l_free_factor(&L, c);
    cholmod_l_free_sparse(&U, c);
    return status;
}

/* What the context needs beside the coupling: the QP and the right-hand side of the solves. */
static int allocate_solver(fricreg_ctx *ctx, struct fr_box_qp *qp, double **rhs)
{
    *rhs = malloc(ctx->m * sizeof **rhs);
    int status = fr_box_qp_alloc(qp, ctx->m);
    if (*rhs != NULL && status == FRICREG_OK)
        return FRICREG_OK;
    free(*rhs);
    fr_box_qp_free(qp);
    return FRICREG_ENOMEM;
}

static void install(fricreg_ctx *ctx, struct fr_sparse_coupling *sp, const double diag[],
                    struct fr_box_qp *qp, double *rhs)
{
    fr_ctx_free_coupling(ctx);
    memcpy(ctx->w_diag, diag, ctx->m * sizeof *diag);
    ctx->w_unit = 0;
    ctx->sp = sp;
    ctx->qp = *qp;
    ctx->qp.bulk = 1; /* box_qp_bulk.c */
    ctx->rhs = rhs;
    ctx->last_valid = 0;
    /* A first QP started with every contact free takes an iteration, O(m + nnz(L)) here, for
     * each contact that is not; from each row's own minimizer, one for each wrong guess. */
    fr_consistent_forget_working_set(ctx);
}

static int set_sparse(fricreg_ctx *ctx, const struct fr_compressed *a, const char *who)
{
    long long base = (a->flags & FRICREG_SPARSE_ONE_BASED) ? 1 : 0;
    struct fr_sparse_coupling *sp = calloc(1, sizeof *sp);
    double *diag = malloc(ctx->m * sizeof *diag), *rhs = NULL;
    struct fr_box_qp qp = {0};
    cholmod_sparse *W = NULL;
    int status = sp && diag ? fr_cholmod_start(&sp->c) : FRICREG_ENOMEM;
    if (status != FRICREG_OK)
        status = out_of_memory(ctx, who);
    else if ((status = whole_matrix(ctx, a, &sp->c, diag, &W, who)) == FRICREG_OK &&
             (status = check_semidefinite(ctx, W, diag, &sp->c, base, who)) == FRICREG_OK) {
        status = fr_sparse_coupling_build(sp, W); /* sp owns W from here */
        W = NULL;
        if (status == FRICREG_OK)
            status = fr_sparse_block_alloc(sp);
        if (status == FRICREG_OK)
            status = allocate_solver(ctx, &qp, &rhs);
        if (status != FRICREG_OK)
            status = out_of_memory(ctx, who);
    }
    if (status == FRICREG_OK) {
        install(ctx, sp, diag, &qp, rhs);
        free(diag);
        return FRICREG_OK;
    }
    if (sp != NULL) {
        cholmod_l_free_sparse(&W, &sp->c);
        fr_sparse_block_free(sp);
        fr_sparse_coupling_free(sp);
    }
    free(sp);
    free(diag);
    return status;
}

/* The setters' common entry: the context, m, then the arrays (fr_compressed_check). */
static int set_compressed(fricreg_ctx *ctx, size_t m, int by_columns, int flags,
                          const int64_t ptr[], const int64_t ind[], const double val[],
                          const char *who)
{
    if (ctx == NULL)
        return FRICREG_ENULL;
    if (m != ctx->m)
        return fr_fail(ctx, FRICREG_ESIZE, "%s: m = %zu, context has %zu contacts", who, m, ctx->m);
    struct fr_compressed a = {m, m, by_columns, flags, ptr, ind, val};
    int status = fr_compressed_check(&a, 1, &ctx->err, who);
    return status == FRICREG_OK ? set_sparse(ctx, &a, who) : status;
}

int fricreg_ctx_set_coupling_csr(fricreg_ctx *ctx, size_t m, int flags, const int64_t rowptr[],
                                 const int64_t colind[], const double values[])
{
    return set_compressed(ctx, m, 0, flags, rowptr, colind, values, "set_coupling_csr");
}

int fricreg_ctx_set_coupling_csc(fricreg_ctx *ctx, size_t m, int flags, const int64_t colptr[],
                                 const int64_t rowind[], const double values[])
{
    return set_compressed(ctx, m, 1, flags, colptr, rowind, values, "set_coupling_csc");
}
