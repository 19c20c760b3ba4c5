/* SPDX-License-Identifier: GPL-3.0-or-later */
/* partition.c — fricreg_ctx_eval: the slip / near-stick split of Sec. 3.3.
 *
 * Slip contacts get their sliding force with no f_eq work; only the near-stick set S needs f_eq.
 * With a diagonal W that is a division per contact and law (4) contact by contact (both
 * partitions agree there); with a coupled W (dense or sparse) the near-stick forces come from
 * the consistent law's QP (partition_consistent.c) or the paper's joint solve
 * (partition_paper.c). */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "base/dispatch.h"
#include "coupling.h"
#include "law/law.h"
#include "partition.h"
#include "partition_consistent.h"
#include "partition_paper.h"
#include "law/contact_check.h"
#include "law/plausible.h"

static int check_inputs(fricreg_ctx *ctx, size_t m, const double zdot[], const double a_free[],
                        const double f[])
{
    return fr_check_eval_inputs(&ctx->err, m, ctx->m, m, zdot, a_free, f);
}

/* Splits the contacts: slip contacts get their force now, near-stick ones are listed in S
 * (and get f = 0 for now, which leaves them out of W_SL f_L). The law is fixed for the loop,
 * so the test and the force are written without branches: a select, and an index list that
 * always stores and advances only on a near-stick contact. */
#define SPLIT_LOOP(NEAR, SLIP_FORCE)           \
    for (size_t i = 0; i < ctx->m; i++) {      \
        double v = zdot[i];                    \
        int near = (NEAR);                     \
        ctx->stick[n_stick] = i;               \
        n_stick += (size_t)near;               \
        ctx->f[i] = near ? 0.0 : (SLIP_FORCE); \
    }

void fr_split_contacts(fricreg_ctx *ctx, const double zdot[])
{
    size_t n_stick = 0;
    const double eps = ctx->eps, *mun = ctx->bound;
    FR_LAWS_LISTED(6);
    switch ((enum fricreg_law)ctx->law) {
    case FRICREG_LAW_QUINN: /* outside |v| < eps both are (1), whatever f_eq is */
    case FRICREG_LAW_KARNOPP: SPLIT_LOOP(fabs(v) < eps, fr_coulomb(v, mun[i])) break;
    case FRICREG_LAW_FORCE_BALANCE: SPLIT_LOOP(v == 0.0, fr_coulomb(v, mun[i])) break;
    case FRICREG_LAW_COULOMB:
    case FRICREG_LAW_VELOCITY_LIMITED:
    case FRICREG_LAW_TANH: /* f_eq is never needed, S is empty, no list to write */
        fr_law_batch(ctx->law, eps, ctx->m, zdot, NULL, mun, ctx->f);
        break;
    }
    ctx->n_stick = n_stick;
}

/* The bits of x: for x, y >= 0 (finite or not), x < y exactly when bits(x) < bits(y). */
static inline uint64_t bits_of(double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

/* Diagonal W: f_eq,i = -a_free,i / w_i needs no solve, so f_eq, the law, the count of S,
 * f_eq out and the copies of the inputs the tangent reads are one pass of selects, straight
 * into the caller's arrays (the inputs are validated: nothing can fail). S is counted, never
 * listed: nothing reads a list here. Written for GCC's vectorizer, which is easily put off
 * (check with -fopt-info-vec):
 *   - the division is formed for every contact, as a vectorized division costs less than a
 *     branch; law (4) needs no near-stick select at all: fr_quinn_band with fr_band_scale
 *     is exactly (1) off the band;
 *   - f_eq out selects on the near-stick test written out, not kept in an int, whose width
 *     it cannot mix with doubles;
 *   - |S| is counted in 64-bit integers, as |zdot_i| < band on the bits (see bits_of): the
 *     borrow of bits(|zdot_i|) - bits(band) is the test, in SSE2's 64-bit subtract and shift
 *     (a count from a double compare needs a 64-bit compare SSE2 lacks, and a double count is
 *     added serially); band = eps, or the least subnormal for (2)'s zdot_i == 0;
 *   - the copies are restrict: they are the context's own, and without it the runtime
 *     overlap checks between seven arrays exceed what it will version for;
 *   - each choice (W = I or not, the tangent's copies or not, f_eq out or not) is its own
 *     loop: a store or a division under a flag inside the loop is a branch. */
#define DIAGONAL_LOOP(FEQ, FORCE, FEQ_OUT, KEEP)        \
    for (size_t i = 0; i < m; i++) {                    \
        double v = zdot[i], a = a_free[i], feq = (FEQ); \
        KEEP;                                           \
        f[i] = (FORCE);                                 \
        FEQ_OUT;                                        \
        n_near += (bits_of(fabs(v)) - band) >> 63;      \
    }
#define KEEP_INPUTS (last_zdot[i] = v, last_afree[i] = a)
/* The code of fr_near_tangent_code where near, else 0: computed for every contact, then
 * selected (GCC does not vectorize arithmetic under a condition, which may trap). */
static inline double tangent_code(int near, double c, double feq, double mun)
{
    double code = fr_near_tangent_code(c, feq, mun);
    return near ? code : 0.0;
}
#define KEEP_CODE(NEAR) (last_afree[i] = tangent_code((NEAR), v * dc, feq, mun[i]))
#define DIAGONAL_OUT(FEQ, NEAR, FORCE, KEEP)                          \
    if (f_eq)                                                         \
        DIAGONAL_LOOP(FEQ, FORCE, f_eq[i] = (NEAR) ? feq : NAN, KEEP) \
    else                                                              \
        DIAGONAL_LOOP(FEQ, FORCE, (void)0, KEEP)
/* W = I needs no division: -a_free,i / 1 is -a_free,i exactly. The tangent's inputs: none,
 * its code (last_zdot NULL, last_afree not), or both inputs. */
#define DIAGONAL_CASE(NEAR, FORCE)                            \
    if (w_unit && !keep)                                      \
        DIAGONAL_OUT(-a, NEAR, FORCE, (void)0)                \
    else if (w_unit && coded)                                 \
        DIAGONAL_OUT(-a, NEAR, FORCE, KEEP_CODE(NEAR))        \
    else if (w_unit)                                          \
        DIAGONAL_OUT(-a, NEAR, FORCE, KEEP_INPUTS)            \
    else if (!keep)                                           \
        DIAGONAL_OUT(-a / w[i], NEAR, FORCE, (void)0)         \
    else if (coded)                                           \
        DIAGONAL_OUT(-a / w[i], NEAR, FORCE, KEEP_CODE(NEAR)) \
    else                                                      \
        DIAGONAL_OUT(-a / w[i], NEAR, FORCE, KEEP_INPUTS)

/* The pass for law (known, reading f_eq) on m contacts; returns |S|. The tangent's inputs:
 * with last_afree NULL none (fricreg_ctx_set_keep_tangent), with last_zdot NULL the codes of
 * fr_near_tangent_code (a constant bound: mun), else both inputs; w_unit: W = I. */
FR_KERNEL_BODY size_t diagonal_loops(int law, double eps, size_t m, const double zdot[],
                                     const double a_free[], const double w[], int w_unit,
                                     const double mun[], double f[], double f_eq[],
                                     double *restrict last_zdot, double *restrict last_afree)
{
    uint64_t n_near = 0, band = bits_of(law == FRICREG_LAW_FORCE_BALANCE ? 0x1p-1074 : eps);
    double k = fr_band_scale(eps), dc = law == FRICREG_LAW_QUINN ? 2.0 / eps : 0.0;
    int keep = last_afree != NULL, coded = last_zdot == NULL;
    FR_LAWS_LISTED(6);
    switch ((enum fricreg_law)law) {
    case FRICREG_LAW_QUINN: DIAGONAL_CASE(fabs(v) < eps, fr_quinn_band(v * k, feq, mun[i])) break;
    case FRICREG_LAW_KARNOPP: DIAGONAL_CASE(fabs(v) < eps, fr_karnopp(v, feq, mun[i], eps)) break;
    case FRICREG_LAW_FORCE_BALANCE: DIAGONAL_CASE(v == 0.0, fr_force_balance(v, feq, mun[i])) break;
    case FRICREG_LAW_COULOMB:
    case FRICREG_LAW_VELOCITY_LIMITED:
    case FRICREG_LAW_TANH: break; /* they read no f_eq: not called for them */
    }
    return (size_t)n_near;
}

#ifdef FRICREG_AVX2_DISPATCH
FR_AVX2 static size_t diagonal_avx2(int law, double eps, size_t m, const double zdot[],
                                    const double a_free[], const double w[], int w_unit,
                                    const double mun[], double f[], double f_eq[],
                                    double *restrict last_zdot, double *restrict last_afree)
{
    return diagonal_loops(law, eps, m, zdot, a_free, w, w_unit, mun, f, f_eq, last_zdot,
                          last_afree);
}
#endif

/* diagonal_loops, in AVX2 where the CPU has it (dispatch.h). */
static size_t diagonal_pass(int law, double eps, size_t m, const double zdot[],
                            const double a_free[], const double w[], int w_unit, const double mun[],
                            double f[], double f_eq[], double *restrict last_zdot,
                            double *restrict last_afree)
{
#ifdef FRICREG_AVX2_DISPATCH
    if (fr_have_avx2())
        return diagonal_avx2(law, eps, m, zdot, a_free, w, w_unit, mun, f, f_eq, last_zdot,
                             last_afree);
#endif
    return diagonal_loops(law, eps, m, zdot, a_free, w, w_unit, mun, f, f_eq, last_zdot,
                          last_afree);
}

static void eval_diagonal(fricreg_ctx *ctx, const double zdot[], const double a_free[], double f[],
                          double f_eq[])
{
    int keep = ctx->keep_tangent, coded = keep && !ctx->stribeck && ctx->m >= ctx->coded_from;
    ctx->n_stick = diagonal_pass(ctx->law, ctx->eps, ctx->m, zdot, a_free, ctx->w_diag, ctx->w_unit,
                                 ctx->bound, f, f_eq, keep && !coded ? ctx->last_zdot : NULL,
                                 keep ? ctx->last_afree : NULL);
    ctx->last_valid = keep;
    ctx->last_coded = coded;
}

/* The largest |f_eq,i| a dense solve is given: beyond it the solve's amplification (up to the
 * 1e12 condition eval accepts) could overflow to Inf or NaN, and a NaN f_eq would be clamped
 * to a bound, a force passed off as the law's. */
#define FEQ_RANGE 1e280

/* Before the solve: a bound on each near-stick contact's f_eq whatever the forces,
 * (|a_free,i| + sum_j |W_ij| mun_j)/W_ii + 2 mun_i (the band's shift, and |f_j| <= mun_j),
 * within FEQ_RANGE. Bounding with the slipping forces only let the consistent law's QP
 * form W f with near-stick forces at their bounds, which overflowed for W near DBL_MAX and
 * returned forces that are not the law (tests/fuzz/regressions/ctx/). The same sums in
 * acceleration units, with the QP's shift W_ii c_i mun_i (|c_i| < 2), are bounded by
 * FEQ_RANGE too: within the force range, W = [DBL_MAX] made b_i = W_ii c_i mun_i Inf and the
 * force wrong (fuzz finding). */
static int check_feq_range(fricreg_ctx *ctx, const double a_free[])
{
    for (size_t k = 0; k < ctx->n_stick; k++) {
        size_t i = ctx->stick[k];
        double w_ii = ctx->w_diag[i];
        double load = fabs(a_free[i]) + fr_w_row_abs_dot(ctx, i, ctx->bound);
        double reach = load / w_ii + 2.0 * ctx->bound[i];
        double acceleration = load + 2.0 * w_ii * ctx->bound[i];
        if (!(reach <= FEQ_RANGE && acceleration <= FEQ_RANGE))
            return fr_fail(ctx, FRICREG_ENONFINITE,
                           "eval: contact %zu: f_eq up to (|a_free| + |W| mun)/W_ii = %g, or the"
                           " accelerations up to |a_free| + |W| mun + 2 W_ii mun = %g, beyond the"
                           " range of the near-stick solve (%g)",
                           i, reach, acceleration, FEQ_RANGE);
    }
    return FRICREG_OK;
}

/* After the solve, a safeguard: finite forces, and a finite f_eq on S. */
static int check_solution(fricreg_ctx *ctx)
{
    for (size_t i = 0; i < ctx->m; i++)
        if (!isfinite(ctx->f[i]))
            return fr_fail(ctx, FRICREG_ENONFINITE, "eval: f[%zu] overflowed", i);
    for (size_t k = 0; k < ctx->n_stick; k++)
        if (!isfinite(ctx->f_eq[ctx->stick[k]]))
            return fr_fail(ctx, FRICREG_ENONFINITE, "eval: f_eq[%zu] overflowed", ctx->stick[k]);
    return FRICREG_OK;
}

/* A coupled W (dense or sparse) and a law that reads f_eq: split, then the near-stick forces
 * by the partition. */
static int eval_coupled(fricreg_ctx *ctx, const double zdot[], const double a_free[])
{
    fr_split_contacts(ctx, zdot);
    int status = check_feq_range(ctx, a_free);
    if (status != FRICREG_OK)
        return status;
    if (ctx->partition == FRICREG_PARTITION_CONSISTENT)
        status = fr_eval_consistent(ctx, zdot, a_free); /* also with S empty: the warm start */
    else if (ctx->n_stick > 0)
        status = fr_eval_paper(ctx, zdot, a_free);
    return status == FRICREG_OK ? check_solution(ctx) : status;
}

/* The tangent (tangent.c) is of the last successful evaluation: keep its inputs, unless the
 * caller does not want the tangent. */
static void remember_inputs(fricreg_ctx *ctx, const double zdot[], const double a_free[])
{
    ctx->last_valid = ctx->keep_tangent;
    ctx->last_coded = 0;
    if (!ctx->keep_tangent)
        return;
    memcpy(ctx->last_zdot, zdot, ctx->m * sizeof *zdot);
    memcpy(ctx->last_afree, a_free, ctx->m * sizeof *a_free);
}

/* f_eq out: the solved values on S, NaN elsewhere (not computed: the law does not read it). */
static void write_feq(const fricreg_ctx *ctx, double f_eq[])
{
    for (size_t i = 0; i < ctx->m; i++)
        f_eq[i] = NAN;
    for (size_t a = 0; a < ctx->n_stick; a++)
        f_eq[ctx->stick[a]] = ctx->f_eq[ctx->stick[a]];
}

/* Laws that never read f_eq ((1), (3), tanh): f is the law at zdot whatever W is, written
 * straight into the caller's f; S is empty, f_eq out all NaN. */
static void eval_without_feq(fricreg_ctx *ctx, const double zdot[], const double a_free[],
                             double f[], double f_eq[])
{
    fr_law_batch(ctx->law, ctx->eps, ctx->m, zdot, NULL, ctx->mun, f);
    for (size_t i = 0; f_eq != NULL && i < ctx->m; i++)
        f_eq[i] = NAN;
    ctx->n_stick = 0;
    remember_inputs(ctx, zdot, a_free);
}

int fricreg_ctx_eval(fricreg_ctx *ctx, size_t m, const double zdot[], const double a_free[],
                     double f[], double f_eq[])
{
    if (ctx == NULL)
        return FRICREG_ENULL;
    int status = check_inputs(ctx, m, zdot, a_free, f);
    if (status != FRICREG_OK)
        return status;
    if (ctx->stribeck) /* the bounds at these velocities (ctx_stribeck.c): one test per call */
        fr_stribeck_bounds(ctx, zdot);
    if (!fr_law_uses_feq(ctx->law)) {
        eval_without_feq(ctx, zdot, a_free, f, f_eq);
    } else if (!fr_coupled(ctx)) {
        eval_diagonal(ctx, zdot, a_free, f, f_eq);
    } else {
        status = eval_coupled(ctx, zdot, a_free);
        if (status != FRICREG_OK)
            return status;
        memcpy(f, ctx->f, m * sizeof *f);
        if (f_eq != NULL)
            write_feq(ctx, f_eq);
        remember_inputs(ctx, zdot, a_free);
    }
    ctx->stats[FRICREG_STAT_EVALS]++;
    ctx->stats[FRICREG_STAT_FEQ_CONTACTS] += (int64_t)ctx->n_stick;
    return FRICREG_OK;
}

int fr_ctx_eval_unchecked(fricreg_ctx *ctx, const double zdot[], const double a_free[], double f[])
{
    if (ctx->stribeck || (fr_coupled(ctx) && fr_law_uses_feq(ctx->law)))
        return fricreg_ctx_eval(ctx, ctx->m, zdot, a_free, f, NULL);
    if (fr_law_uses_feq(ctx->law))
        eval_diagonal(ctx, zdot, a_free, f, NULL);
    else
        eval_without_feq(ctx, zdot, a_free, f, NULL);
    ctx->stats[FRICREG_STAT_EVALS]++;
    ctx->stats[FRICREG_STAT_FEQ_CONTACTS] += (int64_t)ctx->n_stick;
    return FRICREG_OK;
}
