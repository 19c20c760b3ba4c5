/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_factor.c — Check suite for the factor of a dense W's block (src/ctx/factor.c) through the
 * public API: updated when the near-stick set (paper's partition) or the QP's free set
 * (consistent law) changes by a few contacts, refactored otherwise, and still refusing a
 * singular block.
 *
 * What the numbers are checked against:
 *   - the paper's partition: f_eq,S solves W_SS f_eq,S = -(a_free,S + W_SL f_L) (fricreg.h),
 *     so its residual, relative to the size of its terms, must be at rounding level whatever
 *     the history of the factor; and a fresh context (which factors from scratch) must give
 *     the same f_eq;
 *   - the counters' promise (fricreg.h, enum fricreg_stat): a change of k <= 2 + |B|/8
 *     contacts costs k FRICREG_STAT_FACTOR_UPDATES and no factorization; more costs one
 *     factorization; a fresh factorization follows at least every 1000 updates;
 *   - closed forms for the 2x2 blocks: W^-1 = [[1, -rho], [-rho, 1]] / (1 - rho^2). */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg.h"
#include "random.h"

#define MMAX 50
#define EPS 0.0731
#define IN_BAND 0.0123 /* |zdot| < EPS: near stick */
#define SLIP 0.587
#define SENTINEL (-777.125)

/* ---- Random numbers: splitmix64, the same cases on every run and platform --------------- */

static uint64_t rng_state = 0x2385u;

static double uniform(double lo, double hi)
{
    return splitmix64_uniform(&rng_state, lo, hi);
}

static size_t uniform_index(size_t m) /* in [0, m) */
{
    return random_size(splitmix64_uniform, &rng_state, 0, m - 1);
}

/* W = D (A A^T / m + delta I) D: SPD, condition number a few hundred at most, unequal
 * diagonal. */
static void random_spd(size_t m, double W[])
{
    static double work[MMAX * MMAX + MMAX];
    random_scaled_spd(splitmix64_uniform, &rng_state, m, 0.2, 0.6, work, W);
}

static fricreg_ctx *make_ctx(size_t m, const double W[], const double mun[], int partition)
{
    fricreg_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_ctx_create(m, &ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, m, W), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, m, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, EPS), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_partition(ctx, partition), FRICREG_OK);
    return ctx;
}

static int64_t counter(const fricreg_ctx *ctx, int which)
{
    int64_t value = -1;
    ck_assert_int_eq(fricreg_ctx_get_stat(ctx, which, &value), FRICREG_OK);
    return value;
}

static int near_stick(double v)
{
    return fabs(v) < EPS;
}

/* Moves `k` contacts across the band: each one in S leaves it, each one out enters. Returns
 * the number moved. Keeps |S| >= min_stick. */
static size_t move_contacts(size_t m, double zdot[], size_t k, size_t min_stick)
{
    size_t n_stick = 0, moved = 0;
    for (size_t i = 0; i < m; i++)
        n_stick += near_stick(zdot[i]);
    unsigned char touched[MMAX] = {0};
    while (moved < k) {
        size_t i = uniform_index(m);
        if (touched[i] || (near_stick(zdot[i]) && n_stick <= min_stick))
            continue;
        touched[i] = 1;
        if (near_stick(zdot[i])) {
            zdot[i] = uniform(-1.0, 1.0) < 0.0 ? -SLIP : SLIP;
            n_stick--;
        } else {
            zdot[i] = uniform(-IN_BAND, IN_BAND);
            n_stick++;
        }
        moved++;
    }
    return moved;
}

/* The paper's partition: |W_SS f_eq,S + a_free,S + W_SL f_L|_i over the sum of the terms'
 * magnitudes, largest over S (f_eq out holds f_eq on S, f the forces on L). */
static double relative_residual(size_t m, const double W[], const double zdot[], const double a[],
                                const double f[], const double feq[])
{
    double worst = 0.0;
    for (size_t i = 0; i < m; i++) {
        if (!near_stick(zdot[i]))
            continue;
        double r = a[i], size = fabs(a[i]);
        for (size_t j = 0; j < m; j++) {
            double term = W[i * m + j] * (near_stick(zdot[j]) ? feq[j] : f[j]);
            r += term;
            size += fabs(term);
        }
        worst = fmax(worst, fabs(r) / size);
    }
    return worst;
}

/* max_i |x_i - y_i| over S, relative to max_i |y_i|. */
static double relative_difference(size_t m, const double zdot[], const double x[], const double y[])
{
    double diff = 0.0, size = 0.0;
    for (size_t i = 0; i < m; i++)
        if (near_stick(zdot[i])) {
            diff = fmax(diff, fabs(x[i] - y[i]));
            size = fmax(size, fabs(y[i]));
        }
    return diff / size;
}

/* One random case of m contacts: W, mun, a_free, and zdot with about half near stick. */
static void random_case(size_t m, double W[], double mun[], double a[], double zdot[])
{
    random_spd(m, W);
    for (size_t i = 0; i < m; i++) {
        mun[i] = uniform(0.3, 2.385);
        a[i] = uniform(-3.0, 3.0);
        zdot[i] = uniform(-1.0, 1.0) < 0.0 ? uniform(-IN_BAND, IN_BAND)
                                           : (uniform(-1.0, 1.0) < 0.0 ? -SLIP : SLIP);
    }
}

/* ---- Updated factors solve as fresh ones do ------------------------------------------------ */

/* Random insert/delete sequences on random SPD W, m = 12, 31, 50: after every evaluation the
 * residual of f_eq,S is at rounding level (<= 1e-12 of its terms) and a fresh context's f_eq
 * agrees to 1e-12 relative; 1 to 3 contacts move per step (a few: 3 <= 2 + |S|/8 with
 * |S| >= 8), so after the first factorization every change is an update, counted one per
 * contact, and no factorization follows. */
START_TEST(updated_factor_solves_as_a_fresh_one)
{
    static const size_t sizes[3] = {12, 31, 50};
    static double W[MMAX * MMAX];
    double mun[MMAX], a[MMAX], zdot[MMAX], f[MMAX], feq[MMAX], f2[MMAX], feq2[MMAX];
    for (int c = 0; c < 3; c++) {
        size_t m = sizes[c];
        random_case(m, W, mun, a, zdot);
        size_t n_stick = 0;
        for (size_t i = 0; i < m; i++)
            n_stick += near_stick(zdot[i]);
        if (n_stick < 8) /* top up the first set to the minimum */
            for (size_t i = 0; i < m && n_stick < 8; i++)
                if (!near_stick(zdot[i]))
                    zdot[i] = 0.0037, n_stick++;
        fricreg_ctx *ctx = make_ctx(m, W, mun, FRICREG_PARTITION_PAPER);
        int64_t moved = 0;
        for (int step = 0; step < 120; step++) {
            if (step > 0)
                moved += (int64_t)move_contacts(m, zdot, 1 + (size_t)step % 3, 8);
            ck_assert_int_eq(fricreg_ctx_eval(ctx, m, zdot, a, f, feq), FRICREG_OK);
            double res = relative_residual(m, W, zdot, a, f, feq);
            ck_assert_msg(res <= 1e-12, "m = %zu, step %d: residual %.3g", m, step, res);
            fricreg_ctx *fresh = make_ctx(m, W, mun, FRICREG_PARTITION_PAPER);
            ck_assert_int_eq(fricreg_ctx_eval(fresh, m, zdot, a, f2, feq2), FRICREG_OK);
            double diff = relative_difference(m, zdot, feq, feq2);
            ck_assert_msg(diff <= 1e-12, "m = %zu, step %d: f_eq differs by %.3g", m, step, diff);
            ck_assert_int_eq(counter(fresh, FRICREG_STAT_FACTOR_UPDATES), 0);
            fricreg_ctx_free(fresh);
        }
        ck_assert_int_eq(counter(ctx, FRICREG_STAT_FACTORIZATIONS), 1);
        ck_assert_int_eq(counter(ctx, FRICREG_STAT_FACTOR_UPDATES), moved);
        fricreg_ctx_free(ctx);
    }
}
END_TEST

/* More than a few contacts at once (m = 50, |S| about 25: a few is at most 2 + 25/8 = 5):
 * moving 12 costs one factorization and no update, and the answer is still exact. */
START_TEST(many_changes_refactor)
{
    static double W[MMAX * MMAX];
    double mun[MMAX], a[MMAX], zdot[MMAX], f[MMAX], feq[MMAX];
    const size_t m = 50;
    random_case(m, W, mun, a, zdot);
    fricreg_ctx *ctx = make_ctx(m, W, mun, FRICREG_PARTITION_PAPER);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, m, zdot, a, f, feq), FRICREG_OK);
    move_contacts(m, zdot, 12, 8);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, m, zdot, a, f, feq), FRICREG_OK);
    ck_assert_double_le(relative_residual(m, W, zdot, a, f, feq), 1e-12);
    ck_assert_int_eq(counter(ctx, FRICREG_STAT_FACTORIZATIONS), 2);
    ck_assert_int_eq(counter(ctx, FRICREG_STAT_FACTOR_UPDATES), 0);
    fricreg_ctx_free(ctx);
}
END_TEST

/* The periodic fresh factorization: one contact out and one in per step (2 updates) on
 * m = 31; the 501st change would pass 1000 updates since the first factorization, so it
 * refactors instead: 2 factorizations and 2 x 599 updates after 600 changes, and the
 * residual stays at rounding level throughout. */
START_TEST(fresh_factorization_after_1000_updates)
{
    static double W[MMAX * MMAX];
    double mun[MMAX], a[MMAX], zdot[MMAX], f[MMAX], feq[MMAX];
    const size_t m = 31;
    random_case(m, W, mun, a, zdot);
    for (size_t i = 0; i < m; i++) /* 16 near stick, 15 slipping */
        zdot[i] = i % 2 == 0 ? uniform(-IN_BAND, IN_BAND) : SLIP;
    fricreg_ctx *ctx = make_ctx(m, W, mun, FRICREG_PARTITION_PAPER);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, m, zdot, a, f, feq), FRICREG_OK);
    double worst = 0.0;
    for (int step = 1; step <= 600; step++) {
        size_t out, in;
        do
            out = uniform_index(m);
        while (!near_stick(zdot[out]));
        do
            in = uniform_index(m);
        while (near_stick(zdot[in]));
        zdot[out] = -SLIP;
        zdot[in] = uniform(-IN_BAND, IN_BAND);
        ck_assert_int_eq(fricreg_ctx_eval(ctx, m, zdot, a, f, feq), FRICREG_OK);
        worst = fmax(worst, relative_residual(m, W, zdot, a, f, feq));
    }
    ck_assert_msg(worst <= 1e-12, "largest residual %.3g", worst);
    ck_assert_int_eq(counter(ctx, FRICREG_STAT_FACTORIZATIONS), 2);
    ck_assert_int_eq(counter(ctx, FRICREG_STAT_FACTOR_UPDATES), 2 * 599);
    fricreg_ctx_free(ctx);
}
END_TEST

/* The consistent law's QP updates its free set's factor too, between evaluations and between
 * its iterations. Karnopp (c = 0: the box is [-mun, mun], and a contact entering S starts
 * free), S at rest, 1 or 2 contacts in or out per step; some forces saturate (the slipping
 * contacts push with their mun), so the QP also moves contacts between its free and held
 * sets. The QP's minimizer is unique, so a fresh context's forces agree to 1e-12; and after
 * the first factorization every change of the free set is an update: no second
 * factorization, and updates made. Not one per contact moved: a contact that enters S is
 * warm-started on the side of its own row's minimizer, and one that starts and stays on a
 * bound never enters the factor (with Check's fork off, as under valgrind, the test draws
 * another W, on which 75 updates served 89 moves). */
START_TEST(consistent_law_updates_its_free_set)
{
    static double W[MMAX * MMAX];
    double mun[MMAX], a[MMAX], zdot[MMAX], f[MMAX], f2[MMAX];
    const size_t m = 40;
    random_case(m, W, mun, a, zdot);
    for (size_t i = 0; i < m; i++)
        zdot[i] = i % 3 == 0 ? SLIP : 0.0;
    fricreg_ctx *ctx = make_ctx(m, W, mun, FRICREG_PARTITION_CONSISTENT);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_KARNOPP, EPS), FRICREG_OK);
    int64_t moved = 0;
    for (int step = 0; step < 60; step++) {
        if (step > 0) {
            moved += (int64_t)move_contacts(m, zdot, 1 + (size_t)step % 2, 8);
            for (size_t i = 0; i < m; i++) /* entering contacts at rest: free */
                zdot[i] = near_stick(zdot[i]) ? 0.0 : zdot[i];
        }
        ck_assert_int_eq(fricreg_ctx_eval(ctx, m, zdot, a, f, NULL), FRICREG_OK);
        fricreg_ctx *fresh = make_ctx(m, W, mun, FRICREG_PARTITION_CONSISTENT);
        ck_assert_int_eq(fricreg_ctx_set_law(fresh, FRICREG_LAW_KARNOPP, EPS), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_eval(fresh, m, zdot, a, f2, NULL), FRICREG_OK);
        ck_assert_msg(relative_difference(m, zdot, f, f2) <= 1e-12, "step %d", step);
        fricreg_ctx_free(fresh);
    }
    ck_assert_int_eq(counter(ctx, FRICREG_STAT_FACTORIZATIONS), 1);
    ck_assert_int_gt(counter(ctx, FRICREG_STAT_FACTOR_UPDATES), 0);
    ck_assert_int_gt(moved, 0);
    fricreg_ctx_free(ctx);
}
END_TEST

/* ---- The singularity test through updates ------------------------------------------------ */

/* W = [[1, rho], [rho, 1]] scaled by (2.385, 0.731), rho = sqrt(1 - 1e-10): contact 1's pivot
 * ratio after contact 0 is 1 - rho^2 = 1e-10, regular (>= 1e-12) but too small to trust an
 * update (1e-8): the update hands over to a fresh factorization (2 in all, no update) and
 * f_eq = -W^-1 a is the closed form to 1e-4 (its condition number is 4e10, and the stored
 * rho's rounding moves 1 - rho^2 by about 2e-6 relative). At
 * zdot = (0, 0) with large bounds, W^-1 = D^-1 [[1, -rho], [-rho, 1]] D^-1 / (1 - rho^2). */
START_TEST(small_pivot_update_refactors)
{
    const double rho = sqrt(1.0 - 1e-10), d0 = 2.385, d1 = 0.731;
    const double W[4] = {d0 * d0, d0 * rho * d1, d0 * rho * d1, d1 * d1};
    const double mun[2] = {1e12, 1e12}, a[2] = {0.213, -0.347};
    const double one[2] = {0.0, SLIP}, both[2] = {0.0, 0.0};
    double f[2], feq[2];
    fricreg_ctx *ctx = make_ctx(2, W, mun, FRICREG_PARTITION_PAPER);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, one, a, f, feq), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, both, a, f, feq), FRICREG_OK);
    ck_assert_int_eq(counter(ctx, FRICREG_STAT_FACTORIZATIONS), 2);
    ck_assert_int_eq(counter(ctx, FRICREG_STAT_FACTOR_UPDATES), 0);
    double x0 = a[0] / d0, x1 = a[1] / d1; /* f_eq = -D^-1 C^-1 D^-1 a */
    double want0 = -(x0 - rho * x1) / (1e-10 * d0), want1 = -(x1 - rho * x0) / (1e-10 * d1);
    ck_assert_double_eq_tol(feq[0], want0, 1e-4 * fabs(want0));
    ck_assert_double_eq_tol(feq[1], want1, 1e-4 * fabs(want1));
    fricreg_ctx_free(ctx);
}
END_TEST

/* A redundant pair reached by an update is still refused: m = 4, W = B B^T + I/4 except that
 * contact 3 is contact 1 scaled by 1.7 (row and column 3 = 1.7 row and column 1, W_33 =
 * 2.89 W_11, PSD). S = {0, 1, 2} is regular; adding 3 is ESINGULAR (recorded, outputs
 * untouched, no evaluation counted, the verdict from a fresh factorization); S = {0, 2, 3}
 * is regular again and f_eq solves its system. */
START_TEST(redundant_pair_refused_after_updates)
{
    double W[16], B[9];
    for (int k = 0; k < 9; k++)
        B[k] = uniform(-1.0, 1.0);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double s = 0.0;
            for (int k = 0; k < 3; k++)
                s += B[i * 3 + k] * B[j * 3 + k];
            W[i * 4 + j] = s + (i == j ? 0.25 : 0.0);
        }
    for (int i = 0; i < 3; i++)
        W[i * 4 + 3] = W[3 * 4 + i] = 1.7 * W[i * 4 + 1];
    W[15] = 2.89 * W[5];
    const double mun[4] = {50.0, 60.0, 70.0, 80.0}, a[4] = {0.213, -0.347, 0.731, -0.119};
    const double z3[4] = {0.0, 0.0, 0.0, SLIP}, z4[4] = {0.0, 0.0, 0.0, 0.0};
    const double z_other[4] = {0.0, SLIP, 0.0, 0.0};
    double f[4], feq[4];
    fricreg_ctx *ctx = make_ctx(4, W, mun, FRICREG_PARTITION_PAPER);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 4, z3, a, f, feq), FRICREG_OK);
    for (int k = 0; k < 4; k++)
        f[k] = feq[k] = SENTINEL;
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 4, z4, a, f, feq), FRICREG_ESINGULAR);
    ck_assert_int_eq(fricreg_ctx_errcode(ctx), FRICREG_ESINGULAR);
    ck_assert_ptr_nonnull(strstr(fricreg_ctx_errmsg(ctx), "singular"));
    for (int k = 0; k < 4; k++) {
        ck_assert_double_eq(f[k], SENTINEL);
        ck_assert_double_eq(feq[k], SENTINEL);
    }
    ck_assert_int_eq(counter(ctx, FRICREG_STAT_EVALS), 1);
    ck_assert_int_eq(counter(ctx, FRICREG_STAT_FACTORIZATIONS), 2);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 4, z_other, a, f, feq), FRICREG_OK);
    ck_assert_double_le(relative_residual(4, W, z_other, a, f, feq), 1e-12);
    fricreg_ctx_free(ctx);
}
END_TEST

static Suite *factor_suite(void)
{
    Suite *s = suite_create("factor");
    TCase *tc = tcase_create("updates");
    tcase_add_test(tc, updated_factor_solves_as_a_fresh_one);
    tcase_add_test(tc, many_changes_refactor);
    tcase_add_test(tc, fresh_factorization_after_1000_updates);
    tcase_add_test(tc, consistent_law_updates_its_free_set);
    suite_add_tcase(s, tc);
    tc = tcase_create("singular");
    tcase_add_test(tc, small_pivot_update_refactors);
    tcase_add_test(tc, redundant_pair_refused_after_updates);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(factor_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
