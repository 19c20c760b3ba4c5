/* SPDX-License-Identifier: GPL-3.0-or-later */
/* contact_step.c — fricreg_ctx_solve_step: the contact-space Newton of one implicit step
 * (Newmark, HHT-alpha, a BDF) for a caller who keeps their own integrator and their own K_eff
 * solve, with the safeguards of fricreg_structure's steps (newmark.c): the stick guess, the
 * stop of a slipping contact at zdot = 0, and the backtracking line search. The inputs are
 * checked here, dense or compressed; the solver is the context's (contact_step_solver.c) and
 * Newton runs on it (contact_step_newton.c). */
#include <math.h>
#include <string.h>

#include "base/error.h"
#include "base/matrix_input.h"
#include "contact_step_newton.h"
#include "contact_step_solver.h"
#include "ctx/ctx_driver.h"
#include "fricreg_structure.h"
#include "step_pattern.h"

#define SYM_TOL 1e-12 /* |A_ij - A_ji| <= SYM_TOL sqrt(A_ii A_jj), as the context's setters */

static int fail_as(fricreg_ctx *ctx, int code, const char *who, const char *what)
{
    return fr_error_set(fr_ctx_error(ctx), code, "%s: %s", who, what);
}

static int fail(fricreg_ctx *ctx, int code, const char *what)
{
    return fail_as(ctx, code, "solve_step", what);
}

#define SYM_TILE 32 /* the checks' tiles: A_ji a row of a tile away, not m doubles */

/* A (m x m, row-major) read once, by tiles: FRICREG_ENONFINITE if an entry is NaN or
 * infinite, else FRICREG_ENOTPSD if a diagonal entry is below DBL_MIN, else FRICREG_ENOTSYM
 * if |A_ij - A_ji| > SYM_TOL sqrt(A_ii A_jj) somewhere, else FRICREG_OK. One pass for both
 * checks: at m = 2000 the input's O(m^2) reading is most of a step's time. */
static int check_matrix(const double A[], size_t m)
{
    int diagonal = FRICREG_OK, symmetric = FRICREG_OK;
    for (size_t i = 0; i < m; i++) {
        if (!isfinite(A[i * m + i]))
            return FRICREG_ENONFINITE;
        if (!(A[i * m + i] >= 0x1p-1022))
            diagonal = FRICREG_ENOTPSD;
    }
    for (size_t i0 = 0; i0 < m; i0 += SYM_TILE)
        for (size_t j0 = i0; j0 < m; j0 += SYM_TILE)
            for (size_t i = i0; i < i0 + SYM_TILE && i < m; i++)
                for (size_t j = j0 > i + 1 ? j0 : i + 1; j < j0 + SYM_TILE && j < m; j++) {
                    double a = A[i * m + j], b = A[j * m + i];
                    if (!isfinite(a) || !isfinite(b))
                        return FRICREG_ENONFINITE;
                    if (a != b && symmetric == FRICREG_OK && diagonal == FRICREG_OK &&
                        fabs(a - b) > SYM_TOL * sqrt(A[i * m + i]) * sqrt(A[j * m + j]))
                        symmetric = FRICREG_ENOTSYM;
                }
    return diagonal != FRICREG_OK ? diagonal : symmetric;
}

static int all_finite(const double x[], size_t n)
{
    for (size_t k = 0; k < n; k++)
        if (!isfinite(x[k]))
            return 0;
    return 1;
}

/* Checks of what every entry point takes alike, in the dense call's order: the vectors and
 * the outputs NULL, m, then c, tol, max_iter and flags. */
static int check_arguments(fricreg_ctx *ctx, const char *who, size_t m, const double zdot_start[],
                           const double zdot_pred[], const double a_pred[], double c, double tol,
                           int max_iter, int flags, const double f[], const int info[])
{
    if (zdot_start == NULL || zdot_pred == NULL || a_pred == NULL || f == NULL || info == NULL)
        return fail_as(ctx, FRICREG_ENULL, who, "a required array is NULL");
    if (m != fricreg_ctx_size(ctx))
        return fr_error_set(fr_ctx_error(ctx), FRICREG_ESIZE,
                            "%s: m = %zu, the context has %zu contacts", who, m,
                            fricreg_ctx_size(ctx));
    if (!isfinite(c) || !isfinite(tol))
        return fail_as(ctx, FRICREG_ENONFINITE, who, "c or tol is NaN or infinite");
    if (!(c > 0.0) || !(tol > 0.0) || max_iter < 1 || (flags & ~FRICREG_STEP_PLAIN) != 0)
        return fail_as(ctx, FRICREG_EINVAL, who,
                       "needs c > 0, tol > 0, max_iter >= 1, known flags");
    return FRICREG_OK;
}

/* W's diagonal against the context's coupling's (to 1e-12 relative); w_ii one of them. */
static int check_coupling_diagonal(fricreg_ctx *ctx, const char *who, size_t i, double w_ii)
{
    const double *wd = fr_ctx_coupling_diagonal(ctx);
    if (fabs(w_ii - wd[i]) <= SYM_TOL * wd[i])
        return FRICREG_OK;
    return fr_error_set(fr_ctx_error(ctx), FRICREG_EINVAL,
                        "%s: W_%zu%zu = %g, the context's coupling has %g", who, i, i, w_ii, wd[i]);
}

/* The step on the solver s, its matrices filled and checked. */
static int run(fricreg_ctx *ctx, struct fr_step_solver *s, const char *who,
               const double zdot_start[], const double zdot_pred[], const double a_pred[], double c,
               double tol, int max_iter, int flags, double f[], int info[])
{
    size_t m = s->m;
    s->ctx = ctx;
    s->c = c;
    s->z0 = zdot_pred;
    s->a0 = a_pred;
    s->mun = fr_ctx_bounds(ctx);
    memcpy(s->f0, f, m * sizeof *f);
    int converged = 0, iters = 0;
    int status = fr_contact_step_newton(s, zdot_start, tol, max_iter, flags & FRICREG_STEP_PLAIN,
                                        &converged, &iters);
    if (status == FRICREG_OK) {
        memcpy(f, s->v[FR_STEP_V_FK].data, m * sizeof *f);
        info[0] = iters;
        info[1] = converged;
    } else if (status == FRICREG_EDIVERGED) {
        fail_as(ctx, status, who, "the residual is not finite");
    } else if (status == FRICREG_ENOMEM) {
        fr_ctx_drop_workspace(ctx); /* whatever failed half way is not kept */
        fail_as(ctx, status, who, "no memory for the dense Newton matrix");
    }
    return status;
}

int fricreg_ctx_solve_step(fricreg_ctx *ctx, size_t m, const double zdot_start[],
                           const double zdot_pred[], const double a_pred[], const double W[],
                           const double Weff[], double c, double tol, int max_iter, int flags,
                           double f[], int info[])
{
    if (ctx == NULL)
        return FRICREG_ENULL;
    if (W == NULL || Weff == NULL)
        return fail(ctx, FRICREG_ENULL, "a required array is NULL");
    int status = check_arguments(ctx, "solve_step", m, zdot_start, zdot_pred, a_pred, c, tol,
                                 max_iter, flags, f, info);
    if (status != FRICREG_OK)
        return status;
    status = check_matrix(W, m);
    int status_eff = check_matrix(Weff, m);
    if (!all_finite(zdot_start, m) || !all_finite(zdot_pred, m) || !all_finite(a_pred, m) ||
        !all_finite(f, m) || status == FRICREG_ENONFINITE || status_eff == FRICREG_ENONFINITE)
        return fail(ctx, FRICREG_ENONFINITE, "an input array holds NaN or infinity");
    if (status == FRICREG_OK)
        status = status_eff;
    if (status != FRICREG_OK)
        return fail(ctx, status,
                    status == FRICREG_ENOTSYM ? "W or W_eff is not symmetric"
                                              : "W or W_eff has a diagonal entry below DBL_MIN");
    for (size_t i = 0; i < m; i++)
        if ((status = check_coupling_diagonal(ctx, "solve_step", i, W[i * m + i])) != FRICREG_OK)
            return status;

    struct fr_step_inputs in = {W, Weff, NULL, NULL};
    struct fr_step_solver *s = fr_contact_step_solver(ctx, m, &in);
    if (s == NULL)
        return fail(ctx, FRICREG_ENOMEM, "no memory");
    return run(ctx, s, "solve_step", zdot_start, zdot_pred, a_pred, c, tol, max_iter, flags, f,
               info);
}

/* The compressed inputs' values summed, checked as the dense call's and stored in s. */
static int store_compressed(fricreg_ctx *ctx, struct fr_step_solver *s,
                            const struct fr_step_inputs *in, const char *who)
{
    size_t i = 0, j = 0, ie = 0, je = 0;
    int status = fr_step_pattern_values(&s->pw, in->sw, s->W, &i, &j);
    int status_eff = fr_step_pattern_values(&s->pweff, in->sweff, s->Weff, &ie, &je);
    const char *name = status != FRICREG_OK ? "W" : "W_eff";
    if (status == FRICREG_OK) {
        status = status_eff;
        i = ie;
        j = je;
    }
    long long base = (in->sw->flags & FRICREG_SPARSE_ONE_BASED) ? 1 : 0;
    if (status == FRICREG_ENOTPSD)
        return fr_error_set(fr_ctx_error(ctx), status,
                            "%s: %s(%lld, %lld) is missing or below DBL_MIN", who, name,
                            (long long)i + base, (long long)i + base);
    if (status == FRICREG_ENOTSYM)
        return fr_error_set(fr_ctx_error(ctx), status,
                            "%s: %s(%lld, %lld) and %s(%lld, %lld) differ: not symmetric", who,
                            name, (long long)i + base, (long long)j + base, name,
                            (long long)j + base, (long long)i + base);
    for (size_t k = 0; k < s->m; k++)
        if ((status = check_coupling_diagonal(ctx, who, k,
                                              fr_step_pattern_diagonal(&s->pw, s->W, k))) !=
            FRICREG_OK)
            return status;
    fr_step_pattern_store(&s->pw, s->W);
    if (fr_step_pattern_store(&s->pweff, s->Weff))
        s->nm.block.held = 0; /* the factor held is of the old values */
    return FRICREG_OK;
}

/* The _csr and _csc entries: the arrays checked as the coupling setters check theirs
 * (fr_compressed_check), the values as the dense call's. */
static int solve_step_compressed(fricreg_ctx *ctx, size_t m, int by_columns,
                                 const double zdot_start[], const double zdot_pred[],
                                 const double a_pred[], int sparse_flags, const int64_t w_ptr[],
                                 const int64_t w_ind[], const double w_values[],
                                 const int64_t weff_ptr[], const int64_t weff_ind[],
                                 const double weff_values[], double c, double tol, int max_iter,
                                 int flags, double f[], int info[], const char *who)
{
    if (ctx == NULL)
        return FRICREG_ENULL;
    int status = check_arguments(ctx, who, m, zdot_start, zdot_pred, a_pred, c, tol, max_iter,
                                 flags, f, info);
    if (status != FRICREG_OK)
        return status;
    struct fr_compressed sw = {m, m, by_columns, sparse_flags, w_ptr, w_ind, w_values};
    struct fr_compressed sweff = {m, m, by_columns, sparse_flags, weff_ptr, weff_ind, weff_values};
    if ((status = fr_compressed_check(&sw, 1, fr_ctx_error(ctx), who)) != FRICREG_OK ||
        (status = fr_compressed_check(&sweff, 1, fr_ctx_error(ctx), who)) != FRICREG_OK)
        return status;
    if (!all_finite(zdot_start, m) || !all_finite(zdot_pred, m) || !all_finite(a_pred, m) ||
        !all_finite(f, m))
        return fail_as(ctx, FRICREG_ENONFINITE, who, "an input array holds NaN or infinity");

    struct fr_step_inputs in = {NULL, NULL, &sw, &sweff};
    struct fr_step_solver *s = fr_contact_step_solver(ctx, m, &in);
    if (s == NULL)
        return fail_as(ctx, FRICREG_ENOMEM, who, "no memory");
    if ((status = store_compressed(ctx, s, &in, who)) != FRICREG_OK)
        return status;
    return run(ctx, s, who, zdot_start, zdot_pred, a_pred, c, tol, max_iter, flags, f, info);
}

int fricreg_ctx_solve_step_csr(fricreg_ctx *ctx, size_t m, const double zdot_start[],
                               const double zdot_pred[], const double a_pred[], int sparse_flags,
                               const int64_t w_rowptr[], const int64_t w_colind[],
                               const double w_values[], const int64_t weff_rowptr[],
                               const int64_t weff_colind[], const double weff_values[], double c,
                               double tol, int max_iter, int flags, double f[], int info[])
{
    return solve_step_compressed(ctx, m, 0, zdot_start, zdot_pred, a_pred, sparse_flags, w_rowptr,
                                 w_colind, w_values, weff_rowptr, weff_colind, weff_values, c, tol,
                                 max_iter, flags, f, info, "solve_step_csr");
}

int fricreg_ctx_solve_step_matrix(fricreg_ctx *ctx, size_t m, const double zdot_start[],
                                  const double zdot_pred[], const double a_pred[], int format,
                                  const int64_t w_ptr[], const int64_t w_ind[],
                                  const double w_values[], const int64_t weff_ptr[],
                                  const int64_t weff_ind[], const double weff_values[], double c,
                                  double tol, int max_iter, int flags, double f[], int info[])
{
    if (ctx == NULL)
        return FRICREG_ENULL;
    int compressed = 0, by_columns = 0, sparse_flags = 0;
    int status = fr_matrix_format(format, &compressed, &by_columns, &sparse_flags,
                                  fr_ctx_error(ctx), "solve_step_matrix");
    if (status != FRICREG_OK)
        return status;
    if (!compressed)
        return fricreg_ctx_solve_step(ctx, m, zdot_start, zdot_pred, a_pred, w_values, weff_values,
                                      c, tol, max_iter, flags, f, info);
    return solve_step_compressed(ctx, m, by_columns, zdot_start, zdot_pred, a_pred, sparse_flags,
                                 w_ptr, w_ind, w_values, weff_ptr, weff_ind, weff_values, c, tol,
                                 max_iter, flags, f, info, "solve_step_matrix");
}

int fricreg_ctx_solve_step_csc(fricreg_ctx *ctx, size_t m, const double zdot_start[],
                               const double zdot_pred[], const double a_pred[], int sparse_flags,
                               const int64_t w_colptr[], const int64_t w_rowind[],
                               const double w_values[], const int64_t weff_colptr[],
                               const int64_t weff_rowind[], const double weff_values[], double c,
                               double tol, int max_iter, int flags, double f[], int info[])
{
    return solve_step_compressed(ctx, m, 1, zdot_start, zdot_pred, a_pred, sparse_flags, w_colptr,
                                 w_rowind, w_values, weff_colptr, weff_rowind, weff_values, c, tol,
                                 max_iter, flags, f, info, "solve_step_csc");
}
