/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_sparse.c — a sparse W for the 2-D context (fricreg_disk_ctx_set_coupling_csr, _csc):
 * the caller's compressed rows or columns checked and read by src/base/matrix_input.c, then
 * the dense setter's checks on W's blocks and entries, and its semidefiniteness by a sparse
 * factorization instead of the dense setter's eigenvalues. Memory O(entries + factor). */
#include <math.h>

#include "disk_ctx_internal.h"
#include "base/matrix_input.h"
#include "base/sparse_factor.h"
#include "law/law_disk.h"

#define PSD_RTOL 1e-12 /* per unknown, as the dense setter's */

/* Every value given, and every entry after duplicates are summed, at most FR_DISK_MAX. */
static int check_range(fricreg_disk_ctx *ctx, const char *who, const struct fr_compressed *a)
{
    int64_t base = (a->flags & FRICREG_SPARSE_ONE_BASED) ? 1 : 0;
    int64_t nnz = a->ptr[2 * ctx->m] - base;
    for (int64_t p = 0; p < nnz; p++)
        if (!fr_disk_in_range(a->val[p]))
            return fr_fail(ctx, FRICREG_EINVAL, "%s: values[%lld] = %g is beyond 1e250", who,
                           (long long)p, a->val[p]);
    return FRICREG_OK;
}

static int check_summed_range(fricreg_disk_ctx *ctx, const char *who, const cholmod_sparse *U)
{
    const SuiteSparse_long *Up = U->p, *Ui = U->i;
    const double *Ux = U->x;
    for (size_t j = 0; j < U->ncol; j++)
        for (SuiteSparse_long e = Up[j]; e < Up[j + 1]; e++)
            if (!fr_disk_in_range(Ux[e]))
                return fr_fail(ctx, FRICREG_EINVAL,
                               "%s: entry (%ld, %ld) = %g, duplicates summed, is beyond 1e250", who,
                               (long)Ui[e], (long)j, Ux[e]);
    return FRICREG_OK;
}

/* The caller's arrays as W's blocks, into w. */
static int read_blocks(fricreg_disk_ctx *ctx, const char *who, const struct fr_compressed *a,
                       struct fr_disk_coupling *w)
{
    cholmod_common c;
    cholmod_sparse *U = NULL;
    if (fr_cholmod_start(&c) != FRICREG_OK)
        return fr_fail(ctx, FRICREG_ENOMEM, "%s: out of memory for m = %zu", who, ctx->m);
    int status = fr_compressed_to_cholmod(a, 1, &c, &U, &ctx->err, who);
    if (status == FRICREG_OK)
        status = check_summed_range(ctx, who, U);
    if (status == FRICREG_OK && fr_disk_coupling_from_upper(w, ctx->m, U, &c) != FRICREG_OK)
        status = fr_fail(ctx, FRICREG_ENOMEM, "%s: out of memory for m = %zu", who, ctx->m);
    cholmod_l_free_sparse(&U, &c);
    fr_cholmod_finish(&c);
    return status;
}

/* The diagonal blocks positive definite, and no entry with W_kl^2 > W_kk W_ll (a negative
 * 2x2 minor, checked before the factorization as the dense setter does). */
static int check_entries(fricreg_disk_ctx *ctx, const char *who, const struct fr_disk_coupling *w)
{
    double tol = PSD_RTOL * 2.0 * (double)ctx->m;
    for (size_t i = 0; i < ctx->m; i++) {
        const double *b = w->blk + 4 * w->diag[i];
        struct fr_disk_eig e;
        int status = fr_disk_check_block(ctx, who, i, b[0], b[1], b[2], b[3], &e);
        if (status != FRICREG_OK)
            return status;
    }
    for (size_t i = 0; i < ctx->m; i++)
        for (int64_t k = w->ptr[i]; k < w->ptr[i + 1]; k++) {
            const double *b = w->blk + 4 * k, *di = w->blk + 4 * w->diag[i];
            const double *dj = w->blk + 4 * w->diag[w->col[k]];
            for (int a = 0; a < 2; a++)
                for (int c = 0; c < 2; c++)
                    if (!(fabs(b[2 * a + c]) / sqrt(di[3 * a]) / sqrt(dj[3 * c]) <= 1.0 + tol))
                        return fr_fail(ctx, FRICREG_ENOTPSD,
                                       "%s: W[%zu][%lld]^2 > W[%zu][%zu] W[%lld][%lld]: not "
                                       "semidefinite",
                                       who, 2 * i + (size_t)a, (long long)(2 * w->col[k] + c),
                                       2 * i + (size_t)a, 2 * i + (size_t)a,
                                       (long long)(2 * w->col[k] + c),
                                       (long long)(2 * w->col[k] + c));
        }
    return FRICREG_OK;
}

/* The factor's set-up, then D^-1/2 W D^-1/2 + 2m 1e-12 I positive definite: the smallest
 * eigenvalue of D^-1/2 W D^-1/2 above -2m 1e-12, the dense setter's test. */
static int check_semidefinite(fricreg_disk_ctx *ctx, const char *who, struct fr_disk_coupled *cpl)
{
    if (fr_disk_factor_setup(&cpl->F, &cpl->w, FR_DISK_STORAGE_CHOSEN) != FRICREG_OK)
        return fr_fail(ctx, FRICREG_ENOMEM, "%s: out of memory for m = %zu", who, ctx->m);
    int pd = fr_disk_factor_scaled_pd(&cpl->F, &cpl->w, PSD_RTOL * 2.0 * (double)ctx->m);
    if (pd < 0)
        return fr_fail(ctx, FRICREG_ENOMEM, "%s: out of memory for m = %zu", who, ctx->m);
    if (pd == 0)
        return fr_fail(ctx, FRICREG_ENOTPSD,
                       "%s: D^-1/2 W D^-1/2 (D = diag W) has an eigenvalue below -2m 1e-12 (its "
                       "LDL^T factor with that shift has a pivot <= 0): not semidefinite",
                       who);
    return FRICREG_OK;
}

static int set_sparse(fricreg_disk_ctx *ctx, const char *who, size_t m, int flags, int by_columns,
                      const int64_t ptr[], const int64_t ind[], const double val[])
{
    if (ctx == NULL)
        return FRICREG_ENULL;
    if (m != ctx->m)
        return fr_fail(ctx, FRICREG_ESIZE, "%s: m = %zu, context has %zu contacts", who, m, ctx->m);
    struct fr_compressed a = {2 * m, 2 * m, by_columns, flags, ptr, ind, val};
    int status = fr_compressed_check(&a, 1, &ctx->err, who);
    if (status == FRICREG_OK)
        status = check_range(ctx, who, &a);
    if (status != FRICREG_OK)
        return status;
    struct fr_disk_coupled *cpl = fr_disk_coupled_new(m);
    if (cpl == NULL)
        return fr_fail(ctx, FRICREG_ENOMEM, "%s: out of memory for m = %zu", who, m);
    status = read_blocks(ctx, who, &a, &cpl->w);
    if (status == FRICREG_OK)
        status = check_entries(ctx, who, &cpl->w);
    if (status == FRICREG_OK)
        status = check_semidefinite(ctx, who, cpl);
    if (status != FRICREG_OK) {
        fr_disk_coupled_free(cpl);
        return status;
    }
    fr_disk_install_coupled(ctx, cpl, NULL);
    return FRICREG_OK;
}

int fricreg_disk_ctx_set_coupling_csr(fricreg_disk_ctx *ctx, size_t m, int flags,
                                      const int64_t rowptr[], const int64_t colind[],
                                      const double values[])
{
    return set_sparse(ctx, "set_coupling_csr", m, flags, 0, rowptr, colind, values);
}

int fricreg_disk_ctx_set_coupling_csc(fricreg_disk_ctx *ctx, size_t m, int flags,
                                      const int64_t colptr[], const int64_t rowind[],
                                      const double values[])
{
    return set_sparse(ctx, "set_coupling_csc", m, flags, 1, colptr, rowind, values);
}
