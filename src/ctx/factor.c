/* SPDX-License-Identifier: GPL-3.0-or-later */
/* factor.c — the cached LDL^T factor of a principal block of W, updated in O(|B|^2) when
 * contacts enter or leave the block.
 *
 * Why unpivoted W_BB = U^T diag(d) U in order of entry (1.1: GSL's pivoted LDL^T of the
 * Jacobi-scaled block, refactored on every change): both callers change the block by a
 * contact or two at a time (the near-stick set between evaluations, the QP's free set between
 * its iterations), and a pivoted factor cannot take a new row without re-pivoting. LDL^T of a
 * symmetric positive definite matrix is backward stable without pivoting (Wilkinson), and its
 * accuracy is governed by the Jacobi-scaled condition number without any scaling being
 * applied (van der Sluis), so pivoting and scaling buy nothing but the rank test, and the
 * pivot ratios do that job for free:
 *   - a contact c enters as a new last row and column: U^T z = W_B,c by one unit triangular
 *     solve (gsl_blas_dtrsv), U_:,c = z ./ d, d_c = W_cc - z^T U_:,c, O(|B|^2); d_c / W_cc,
 *     the pivot ratio, is c's independence from the block (1 - rho^2 for a pair), in units
 *     of nothing, with no condition estimate;
 *   - the contact at position p leaves: its row and column go, and the trailing factor takes
 *     the rank-one update d_p x x^T, x the rest of row p of U, O((|B| - p)^2); positive, so
 *     no pivot falls;
 *   - a fresh factorization is the first case repeated from the empty block (bordered
 *     LDL^T, |B|^3/3 flops), in the callers' ascending contact order. Only a fresh
 *     factorization declares a block singular: an update whose new pivot ratio is below
 *     UPDATE_PIVOT_MIN, where rounding in the held factor would be amplified, hands over to
 *     one. So a redundant set is refused whatever the history (its last redundant contact to
 *     enter has pivot 0); only a nearly singular one, whose pivot ratios straddle 1e-12 and
 *     1e-8 depending on the order, can be accepted after updates and refused fresh. Nor is a
 *     fresh factor with a pivot ratio below UPDATE_PIVOT_MIN updated: deleting a contact from
 *     it by a rank-one update carries its ill-conditioning into a block that has none (a
 *     ratio of 7.6e-9 left the factor of a benign 2 x 2 block wrong in its fourth digit, and
 *     the forces with it: fuzz finding); the next change refactors.
 * Updates are used when at most few_changes(|B|) contacts change. A fresh factorization also
 * follows MAX_UPDATES updates, or a drift of the diagonal of U^T D U from W_BB's beyond
 * DRIFT_MAX (checked after each deletion, O(|B|^2) like the deletion): both bound the rounding
 * a long series of updates accumulates. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_blas.h>

#include "ctx_internal.h"
#include "factor.h"
#include "sparse_block.h"
#include "base/free_all.h"

#define FR_NOT_HELD SIZE_MAX
/* An update adding a contact with a smaller pivot ratio refactors afresh instead. */
#define UPDATE_PIVOT_MIN 1e-8
/* The largest relative drift |(U^T D U)_jj / W_jj - 1| kept after updates. */
#define DRIFT_MAX 1e-13
/* Updates since the last fresh factorization after which the next change refactors. */
#define MAX_UPDATES 1000

/* Changes worth updating: each costs about |B|^2, a fresh factorization |B|^3/3. */
static size_t few_changes(size_t n)
{
    return 2 + n / 8;
}

int fr_factor_alloc(struct fr_factor *fa, size_t m)
{
    memset(fa, 0, sizeof *fa);
    fa->set = malloc(m * sizeof *fa->set);
    fa->U = malloc(m * m * sizeof *fa->U);
    fa->d = malloc(m * sizeof *fa->d);
    fa->pos = malloc(m * sizeof *fa->pos);
    fa->order = malloc(m * sizeof *fa->order);
    fa->work = malloc(m * sizeof *fa->work);
    fa->hit = malloc(m * sizeof *fa->hit);
    if (!fa->set || !fa->U || !fa->d || !fa->pos || !fa->order || !fa->work || !fa->hit) {
        fr_factor_free(fa);
        return FRICREG_ENOMEM;
    }
    for (size_t i = 0; i < m; i++)
        fa->pos[i] = FR_NOT_HELD;
    return FRICREG_OK;
}

void fr_factor_free(struct fr_factor *fa)
{
    FR_FREE_ALL(fa->set, fa->U, fa->d, fa->pos, fa->order, fa->work, fa->hit);
    memset(fa, 0, sizeof *fa);
}

/* Empties the block. */
static void forget(struct fr_factor *fa)
{
    for (size_t p = 0; p < fa->n; p++)
        fa->pos[fa->set[p]] = FR_NOT_HELD;
    fa->n = 0;
    fa->valid = 0;
}

/* Appends contact c as position n: U^T z = W_B,c (unit triangular), U_p,n = z_p / d_p,
 * d_n = W_cc - z^T U_:,n. Returns the pivot ratio d_n / W_cc; the contact is added only if it
 * is at least pivot_min. */
static double append(struct fr_factor *fa, const double W[], size_t m, size_t c, double pivot_min)
{
    size_t n = fa->n;
    double *z = fa->work, d = W[c * m + c];
    const double *row = W + c * m;
    for (size_t p = 0; p < n; p++)
        z[p] = row[fa->set[p]];
    if (n > 0) {
        gsl_matrix_view U = gsl_matrix_view_array_with_tda(fa->U, n, n, m);
        gsl_vector_view x = gsl_vector_view_array(z, n);
        gsl_blas_dtrsv(CblasUpper, CblasTrans, CblasUnit, &U.matrix, &x.vector);
    }
    for (size_t p = 0; p < n; p++) {
        double l = z[p] / fa->d[p];
        fa->U[p * m + n] = l; /* written past the held block: harmless if c is refused */
        d -= z[p] * l;
    }
    /* W_cc >= DBL_MIN (set_coupling_dense); a pivot below DBL_MIN counts as ratio 0: its
     * inverse would overflow, and the solves would turn 0 * Inf into NaN. */
    double ratio = d >= DBL_MIN ? d / W[c * m + c] : 0.0;
    if (!(ratio >= pivot_min)) /* NaN too */
        return ratio;
    fa->U[n * m + n] = 1.0;
    fa->d[n] = d;
    fa->set[n] = c;
    fa->pos[c] = n;
    fa->n = n + 1;
    return ratio;
}

/* The trailing factor after a deletion: U^T D U + alpha x x^T, alpha > 0, updated in place
 * (rows first..first+t-1 of U, x[t]) by Gill, Golub, Murray and Saunders's method C1 (Math.
 * Comp. 28, 1974): no square roots, every pivot grows. */
static void rank_one_update(struct fr_factor *fa, size_t m, size_t first, size_t t, double x[],
                            double alpha)
{
    for (size_t j = 0; j < t; j++) {
        double p = x[j], *d = &fa->d[first + j];
        if (p == 0.0)
            continue;
        double d_new = *d + alpha * p * p, beta = alpha * p / d_new;
        alpha *= *d / d_new;
        *d = d_new;
        double *u = fa->U + (first + j) * m + (first + j);
        for (size_t r = j + 1; r < t; r++) {
            x[r] -= p * u[r - j];
            u[r - j] += beta * x[r];
        }
    }
}

/* Removes factor position p: the rows below move up and left one place, and the trailing
 * factor takes the rank-one update d_p x x^T, x = U_p,p+1.. . */
static void delete_position(struct fr_factor *fa, size_t m, size_t p)
{
    size_t n = fa->n, t = n - 1 - p;
    double *U = fa->U, *x = fa->work, alpha = fa->d[p];
    memcpy(x, U + p * m + p + 1, t * sizeof *x);
    for (size_t i = 0; i < p; i++)
        memmove(U + i * m + p, U + i * m + p + 1, t * sizeof *U);
    for (size_t i = p + 1; i < n; i++)
        memcpy(U + (i - 1) * m + (i - 1), U + i * m + i, (n - i) * sizeof *U);
    fa->pos[fa->set[p]] = FR_NOT_HELD;
    for (size_t q = p; q + 1 < n; q++) {
        fa->set[q] = fa->set[q + 1];
        fa->d[q] = fa->d[q + 1];
        fa->pos[fa->set[q]] = q;
    }
    rank_one_update(fa, m, p, t, x, alpha);
    fa->n = n - 1;
}

/* max_j |(U^T D U)_jj / W_jj - 1| over the columns j >= from. */
static double diagonal_drift(struct fr_factor *fa, const double W[], size_t m, size_t from)
{
    size_t n = fa->n;
    double *diag = fa->work, drift = 0.0;
    for (size_t j = from; j < n; j++)
        diag[j] = 0.0;
    for (size_t i = 0; i < n; i++) {
        const double *u = fa->U + i * m;
        for (size_t j = i > from ? i : from; j < n; j++)
            diag[j] += u[j] * u[j] * fa->d[i];
    }
    for (size_t j = from; j < n; j++)
        drift = fmax(drift, fabs(diag[j] / W[fa->set[j] * m + fa->set[j]] - 1.0));
    return drift;
}

static void remember_order(struct fr_factor *fa, const size_t set[], size_t n)
{
    for (size_t a = 0; a < n; a++)
        fa->order[a] = fa->pos[set[a]];
}

/* The factor of W[set, set] from scratch, contacts in the order given (ascending from the
 * callers). */
static int fresh(fricreg_ctx *ctx, const size_t set[], size_t n, const char *who)
{
    struct fr_factor *fa = &ctx->fac;
    forget(fa);
    ctx->stats[FRICREG_STAT_FACTORIZATIONS]++;
    fa->fragile = 0;
    for (size_t a = 0; a < n; a++) {
        double ratio = append(fa, ctx->W, ctx->m, set[a], FR_PIVOT_MIN);
        fa->fragile |= ratio < UPDATE_PIVOT_MIN;
        if (!(ratio >= FR_PIVOT_MIN)) {
            forget(fa);
            return fr_fail(ctx, FRICREG_ESINGULAR,
                           "%s: W on the %zu contacts (first: contact %zu) is singular: contact"
                           " %zu's pivot ratio d/W_ii %.3g is below %g: redundant contacts",
                           who, n, set[0], set[a], ratio, FR_PIVOT_MIN);
        }
    }
    fa->updates = 0;
    fa->valid = 1;
    remember_order(fa, set, n);
    return FRICREG_OK;
}

/* From the held block to set by removing the contacts not in it and appending the new ones.
 * Returns 0 if an update gave up (a small pivot or a drift): a fresh factorization must
 * follow. */
static int update(fricreg_ctx *ctx, const size_t set[], size_t n)
{
    struct fr_factor *fa = &ctx->fac;
    size_t lowest = fa->n, changes = 0;
    memset(fa->hit, 0, fa->n);
    for (size_t a = 0; a < n; a++)
        if (fa->pos[set[a]] != FR_NOT_HELD)
            fa->hit[fa->pos[set[a]]] = 1;
    for (size_t p = fa->n; p-- > 0;)
        if (!fa->hit[p]) {
            delete_position(fa, ctx->m, p);
            lowest = p, changes++;
        }
    for (size_t a = 0; a < n; a++)
        if (fa->pos[set[a]] == FR_NOT_HELD) {
            if (!(append(fa, ctx->W, ctx->m, set[a], UPDATE_PIVOT_MIN) >= UPDATE_PIVOT_MIN))
                return 0;
            changes++;
        }
    ctx->stats[FRICREG_STAT_FACTOR_UPDATES] += (int64_t)changes;
    fa->updates += changes;
    if (lowest < fa->n && diagonal_drift(fa, ctx->W, ctx->m, lowest) > DRIFT_MAX)
        return 0;
    remember_order(fa, set, n);
    return 1;
}

int fr_factor_ensure(fricreg_ctx *ctx, const size_t set[], size_t n, const char *who)
{
    if (ctx->sp != NULL)
        return fr_sparse_block_ensure(ctx, set, n, who);
    struct fr_factor *fa = &ctx->fac;
    if (!fa->valid)
        forget(fa);
    size_t held = 0;
    for (size_t a = 0; a < n; a++)
        held += fa->pos[set[a]] != FR_NOT_HELD;
    size_t changes = (fa->n - held) + (n - held);
    if (fa->valid && changes == 0) {
        remember_order(fa, set, n);
        return FRICREG_OK;
    }
    int worth = fa->valid && !fa->fragile && changes <= few_changes(n > fa->n ? n : fa->n) &&
                fa->updates + changes <= MAX_UPDATES;
    if (worth && update(ctx, set, n))
        return FRICREG_OK;
    return fresh(ctx, set, n, who);
}

int fr_factor_solve(fricreg_ctx *ctx, double r[], const char *who)
{
    (void)who; /* a held factor has positive pivots: nothing can fail */
    if (ctx->sp != NULL)
        return fr_sparse_block_solve(ctx, r);
    struct fr_factor *fa = &ctx->fac;
    size_t n = fa->n;
    double *y = fa->work;
    for (size_t a = 0; a < n; a++)
        y[fa->order[a]] = r[a];
    if (n > 0) {
        gsl_matrix_const_view U = gsl_matrix_const_view_array_with_tda(fa->U, n, n, ctx->m);
        gsl_vector_view x = gsl_vector_view_array(y, n);
        gsl_blas_dtrsv(CblasUpper, CblasTrans, CblasUnit, &U.matrix, &x.vector);
        for (size_t p = 0; p < n; p++)
            y[p] /= fa->d[p];
        gsl_blas_dtrsv(CblasUpper, CblasNoTrans, CblasUnit, &U.matrix, &x.vector);
    }
    for (size_t a = 0; a < n; a++)
        r[a] = y[fa->order[a]];
    ctx->stats[FRICREG_STAT_SOLVES]++;
    return FRICREG_OK;
}
