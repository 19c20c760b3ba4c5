/* partition.c — fricreg_ctx_eval: the slip / near-stick split of Sec. 3.3.
 *
 * Slip contacts get their sliding force with no f_eq work; only the near-stick set S needs f_eq.
 * With a diagonal W that is a division per contact and law (4) contact by contact (both
 * partitions agree there); with a dense W the near-stick forces come from the consistent law's
 * QP (partition_consistent.c) or the paper's joint solve (partition_paper.c). */
#include <math.h>
#include <string.h>

#include "law.h"
#include "partition.h"

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

void fr_split_contacts(fricreg_ctx *ctx, const double zdot[])
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

/* A dense W (or a law without f_eq): split, then the near-stick forces by the partition. */
static int eval_dense(fricreg_ctx *ctx, const double zdot[], const double a_free[])
{
    fr_split_contacts(ctx, zdot);
    if (!fr_law_uses_feq(ctx->law))
        return FRICREG_OK; /* S is empty */
    if (ctx->partition == FRICREG_PARTITION_CONSISTENT)
        return fr_eval_consistent(ctx, zdot, a_free);
    return ctx->n_stick > 0 ? fr_eval_paper(ctx, zdot, a_free) : FRICREG_OK;
}

/* The tangent (tangent.c) is of the last successful evaluation: keep its inputs. */
static void remember_inputs(fricreg_ctx *ctx, const double zdot[], const double a_free[])
{
    memcpy(ctx->last_zdot, zdot, ctx->m * sizeof *zdot);
    memcpy(ctx->last_afree, a_free, ctx->m * sizeof *a_free);
    ctx->last_valid = 1;
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
        status = eval_dense(ctx, zdot, a_free);
        if (status != FRICREG_OK)
            return status;
        memcpy(f, ctx->f, m * sizeof *f);
    }
    if (f_eq != NULL)
        write_feq(ctx, f_eq);
    remember_inputs(ctx, zdot, a_free);
    ctx->stats[FRICREG_STAT_EVALS]++;
    ctx->stats[FRICREG_STAT_FEQ_CONTACTS] += (int64_t)ctx->n_stick;
    return FRICREG_OK;
}
