/* partition.c — fricreg_ctx_eval: the slip / near-stick partition of Sec. 3.3.
 *
 * Slip contacts get their sliding force with no f_eq work; only the near-stick set S needs f_eq,
 * from W_SS f_eq,S = -(a_free,S + W_SL f_L). With a diagonal W that is a division per contact;
 * with a dense W, a pivoted Cholesky (LDL^T) factor of W_SS that is kept while S and W hold. */
#include <math.h>
#include <string.h>

#include <gsl/gsl_linalg.h>
#include <gsl/gsl_permutation.h>

#include "ctx_internal.h"
#include "gsl_guard.h"
#include "law.h"

/* Below this reciprocal condition number W_SS is treated as singular. */
#define RCOND_MIN 1e-12

/* The index of the first non-finite zdot[i] or a_free[i], or m. The scan itself is
 * branch-free (it runs on every evaluation); only a failure looks for the index. */
static size_t first_nonfinite(size_t m, const double zdot[], const double a_free[])
{
    int bad = 0;
    for (size_t i = 0; i < m; i++)
        bad |= !isfinite(zdot[i]) | !isfinite(a_free[i]);
    size_t i = 0;
    while (bad && isfinite(zdot[i]) && isfinite(a_free[i]))
        i++;
    return bad ? i : m;
}

static int check_inputs(fricreg_ctx *ctx, size_t m, const double zdot[], const double a_free[],
                        const double f[])
{
    if (m != ctx->m)
        return fr_fail(ctx, FRICREG_ESIZE, "eval: m = %zu, context has %zu contacts", m, ctx->m);
    if (zdot == NULL || a_free == NULL || f == NULL)
        return fr_fail(ctx, FRICREG_ENULL, "eval: %s is NULL",
                       zdot == NULL ? "zdot" : a_free == NULL ? "a_free" : "f");
    size_t i = first_nonfinite(m, zdot, a_free);
    if (i < m)
        return fr_fail(ctx, FRICREG_ENONFINITE, "eval: %s[%zu] is not finite",
                       isfinite(zdot[i]) ? "a_free" : "zdot", i);
    return FRICREG_OK;
}

/* Splits the contacts: slip contacts get their force now, near-stick ones are listed in S
 * (and get f = 0 for now, which leaves them out of W_SL f_L). The law is fixed for the loop,
 * so the test and the force are written without branches: a select, and an index list that
 * always stores and advances only on a near-stick contact. */
#define SPLIT_LOOP(NEAR, SLIP_FORCE)                                      \
    for (size_t i = 0; i < ctx->m; i++) {                                 \
        double v = zdot[i];                                               \
        int near = (NEAR);                                                \
        ctx->stick[n_stick] = i;                                          \
        n_stick += (size_t)near;                                          \
        ctx->f[i] = near ? 0.0 : (SLIP_FORCE);                            \
    }

static void split_contacts(fricreg_ctx *ctx, const double zdot[])
{
    size_t n_stick = 0;
    const double eps = ctx->eps, *mun = ctx->mun;
    switch (ctx->law) {
    case FRICREG_LAW_QUINN: /* outside |v| < eps both are (1), whatever f_eq is */
    case FRICREG_LAW_KARNOPP:
        SPLIT_LOOP(fabs(v) < eps, fr_coulomb(v, mun[i]))
        break;
    case FRICREG_LAW_FORCE_BALANCE:
        SPLIT_LOOP(v == 0.0, fr_coulomb(v, mun[i]))
        break;
    default: /* (1), (3), tanh: f_eq is never needed */
        SPLIT_LOOP(0, fr_law(ctx->law, v, 0.0, mun[i], eps))
        break;
    }
    ctx->n_stick = n_stick;
}

static int same_stick_set(const fricreg_ctx *ctx)
{
    return ctx->factor_valid && ctx->n_stick == ctx->n_stick_prev &&
           memcmp(ctx->stick, ctx->stick_prev, ctx->n_stick * sizeof *ctx->stick) == 0;
}

/* Pivoted Cholesky LDL^T of W_SS into ctx->factor (GSL), checked for singularity. */
static int factor_stick_block(fricreg_ctx *ctx)
{
    size_t s = ctx->n_stick, m = ctx->m;
    for (size_t a = 0; a < s; a++)
        for (size_t b = 0; b < s; b++)
            ctx->factor[a * s + b] = ctx->W[ctx->stick[a] * m + ctx->stick[b]];
    gsl_matrix_view A = gsl_matrix_view_array(ctx->factor, s, s);
    gsl_permutation p = {s, ctx->perm};
    gsl_vector_view work = gsl_vector_view_array(ctx->rcond_work, 3 * s);
    double rcond = 0.0;
    gsl_error_handler_t *previous = fr_gsl_quiet();
    int status = gsl_linalg_pcholesky_decomp(&A.matrix, &p);
    if (status == GSL_SUCCESS)
        status = gsl_linalg_pcholesky_rcond(&A.matrix, &p, &rcond, &work.vector);
    fr_gsl_restore(previous);
    ctx->stats[FRICREG_STAT_FACTORIZATIONS]++;
    ctx->factor_valid = 0;
    if (status != GSL_SUCCESS || !(rcond >= RCOND_MIN))
        return fr_fail(ctx, FRICREG_ESINGULAR,
                       "eval: W_SS of the %zu near-stick contacts (first: contact %zu) is singular"
                       " (rcond %.3g): redundant contacts",
                       s, ctx->stick[0], rcond);
    memcpy(ctx->stick_prev, ctx->stick, s * sizeof *ctx->stick);
    ctx->n_stick_prev = s;
    ctx->factor_valid = 1;
    return FRICREG_OK;
}

/* f_eq,S from W_SS f_eq,S = -(a_free,S + W_SL f_L), dense W. f holds f_L, and 0 on S. */
static int solve_dense(fricreg_ctx *ctx, const double a_free[])
{
    size_t s = ctx->n_stick, m = ctx->m;
    for (size_t a = 0; a < s; a++) {
        const double *row = ctx->W + ctx->stick[a] * m;
        double coupling = 0.0;
        for (size_t j = 0; j < m; j++)
            coupling += row[j] * ctx->f[j];
        ctx->rhs[a] = -(a_free[ctx->stick[a]] + coupling);
    }
    if (!same_stick_set(ctx)) {
        int status = factor_stick_block(ctx);
        if (status != FRICREG_OK)
            return status;
    }
    gsl_matrix_const_view A = gsl_matrix_const_view_array(ctx->factor, s, s);
    gsl_permutation p = {s, ctx->perm};
    gsl_vector_view x = gsl_vector_view_array(ctx->rhs, s);
    gsl_error_handler_t *previous = fr_gsl_quiet();
    int status = gsl_linalg_pcholesky_svx(&A.matrix, &p, &x.vector);
    fr_gsl_restore(previous);
    ctx->stats[FRICREG_STAT_SOLVES]++;
    if (status != GSL_SUCCESS)
        return fr_fail(ctx, FRICREG_ESINGULAR, "eval: W_SS solve failed (GSL status %d)", status);
    for (size_t a = 0; a < s; a++)
        ctx->f_eq[ctx->stick[a]] = ctx->rhs[a];
    return FRICREG_OK;
}

/* Diagonal W: f_eq,i = -a_free,i / w_i needs no solve, so the split, f_eq and the law are
 * one pass of selects, written straight into the caller's f (nothing can fail here). The
 * division is formed for every contact, as a vectorized division costs less than a branch,
 * but only S reads it, and only S is counted and reported. */
#define DIAGONAL_LOOP(NEAR, STICK_FORCE)                                  \
    for (size_t i = 0; i < ctx->m; i++) {                                 \
        double v = zdot[i], feq = -a_free[i] / w[i];                      \
        int near = (NEAR);                                                \
        ctx->stick[n_stick] = i;                                          \
        n_stick += (size_t)near;                                          \
        ctx->f_eq[i] = feq;                                               \
        f[i] = near ? (STICK_FORCE) : fr_coulomb(v, mun[i]);              \
    }

static void eval_diagonal(fricreg_ctx *ctx, const double zdot[], const double a_free[],
                          double f[])
{
    size_t n_stick = 0;
    const double eps = ctx->eps, *mun = ctx->mun, *w = ctx->w_diag;
    switch (ctx->law) {
    case FRICREG_LAW_QUINN:
        DIAGONAL_LOOP(fabs(v) < eps, fr_quinn(v, feq, mun[i], eps))
        break;
    case FRICREG_LAW_KARNOPP:
        DIAGONAL_LOOP(fabs(v) < eps, fr_karnopp(v, feq, mun[i], eps))
        break;
    default: /* the only other law that reads f_eq */
        DIAGONAL_LOOP(v == 0.0, fr_force_balance(v, feq, mun[i]))
        break;
    }
    ctx->n_stick = n_stick;
}

/* Dense W: f_S = the law at (zdot_S, f_eq,S); the switch on the law stays outside the loops. */
#define STICK_LOOP(FORCE)                                                 \
    for (size_t a = 0; a < ctx->n_stick; a++) {                           \
        size_t i = ctx->stick[a];                                         \
        double v = zdot[i], feq = ctx->f_eq[i];                           \
        ctx->f[i] = (FORCE);                                              \
    }

static void apply_law_on_stick_set(fricreg_ctx *ctx, const double zdot[])
{
    const double eps = ctx->eps, *mun = ctx->mun;
    switch (ctx->law) {
    case FRICREG_LAW_QUINN: STICK_LOOP(fr_quinn(v, feq, mun[i], eps)) break;
    case FRICREG_LAW_KARNOPP: STICK_LOOP(fr_karnopp(v, feq, mun[i], eps)) break;
    default: STICK_LOOP(fr_force_balance(v, feq, mun[i])) break; /* the only other with S */
    }
}

/* f_eq out: the solved values on S, NaN elsewhere (not computed: the law does not read it). */
static void write_feq(const fricreg_ctx *ctx, double f_eq[])
{
    for (size_t i = 0; i < ctx->m; i++)
        f_eq[i] = NAN;
    for (size_t a = 0; a < ctx->n_stick; a++)
        f_eq[ctx->stick[a]] = ctx->f_eq[ctx->stick[a]];
}

int fricreg_ctx_eval(fricreg_ctx *ctx, size_t m, const double zdot[], const double a_free[],
                     double f[], double f_eq[])
{
    if (ctx == NULL)
        return FRICREG_ENULL;
    int status = check_inputs(ctx, m, zdot, a_free, f);
    if (status != FRICREG_OK)
        return status;
    if (ctx->W == NULL && fr_law_uses_feq(ctx->law)) {
        eval_diagonal(ctx, zdot, a_free, f);
    } else {
        split_contacts(ctx, zdot);
        if (ctx->n_stick > 0) { /* only a dense W gets here with a near-stick set */
            status = solve_dense(ctx, a_free);
            if (status != FRICREG_OK)
                return status;
            apply_law_on_stick_set(ctx, zdot);
        }
        memcpy(f, ctx->f, m * sizeof *f);
    }
    if (f_eq != NULL)
        write_feq(ctx, f_eq);
    ctx->stats[FRICREG_STAT_EVALS]++;
    ctx->stats[FRICREG_STAT_FEQ_CONTACTS] += (int64_t)ctx->n_stick;
    return FRICREG_OK;
}
