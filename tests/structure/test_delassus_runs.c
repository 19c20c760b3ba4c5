/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_delassus_runs.c — Check suite for the products with a packed W_eff restricted to runs
 * of rows and columns (src/structure/delassus_runs.h), white box on the static library:
 *   - the runs of a mask: set and unset, empty, full, alternating, at both ends, with their
 *     members counted;
 *   - y_R = W_eff,RC x_C for random masks (one run to every other contact, empty sets, both
 *     full, rows and columns overlapping) equals the whole product of x zeroed outside C to
 *     rounding, 4 m 2^-53 sum_j |W_ij x_j| (the rounding bound of a sum of m products);
 *     x outside C is NaN, so a read of it shows, and y outside R keeps its sentinel;
 *   - the rule: a few rows in one run are cheaper, all rows against all columns are not, nor
 *     is a W_eff that is not packed. */
#include <check.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "random.h"
#include "structure/contact_factor.h"
#include "structure/delassus_runs.h"

#define M 97
#define SENTINEL -7.0

/* A packed m x m upper triangle (every entry, contact_factor.h) with entries drawn in
 * [-1, 1) and m on the diagonal. */
static cholmod_sparse *packed_upper(size_t m, uint64_t *state, cholmod_common *c)
{
    cholmod_sparse *D = cholmod_l_allocate_sparse(m, m, m * (m + 1) / 2, 1, 1, 1, CHOLMOD_REAL, c);
    ck_assert_ptr_nonnull(D);
    SuiteSparse_long *Dp = D->p, *Di = D->i, q = 0;
    double *Dx = D->x;
    for (size_t j = 0; j < m; j++) {
        Dp[j] = q;
        for (size_t i = 0; i <= j; i++) {
            Di[q] = (SuiteSparse_long)i;
            Dx[q++] = i == j ? (double)m : splitmix64_uniform(state, -1.0, 1.0);
        }
    }
    Dp[m] = q;
    return D;
}

static double entry(const cholmod_sparse *D, size_t i, size_t j)
{
    size_t lo = i < j ? i : j, hi = i < j ? j : i;
    return ((const double *)D->x)[hi * (hi + 1) / 2 + lo];
}

START_TEST(runs_of_masks)
{
    const unsigned char mask[10] = {1, 1, 0, 1, 0, 0, 1, 1, 1, 1};
    size_t runs[11], members;
    ck_assert_uint_eq(fr_runs_of(mask, 1, 10, runs, &members), 3);
    const size_t set[6] = {0, 2, 3, 4, 6, 10};
    ck_assert_mem_eq(runs, set, sizeof set);
    ck_assert_uint_eq(members, 7);
    ck_assert_uint_eq(fr_runs_of(mask, 0, 10, runs, &members), 2);
    const size_t unset[4] = {2, 3, 4, 6};
    ck_assert_mem_eq(runs, unset, sizeof unset);
    ck_assert_uint_eq(members, 3);

    const unsigned char alternating[9] = {1, 0, 1, 0, 1, 0, 1, 0, 1}; /* (m + 1) / 2 runs */
    ck_assert_uint_eq(fr_runs_of(alternating, 1, 9, runs, &members), 5);
    ck_assert_uint_eq(members, 5);
    ck_assert_uint_eq(runs[8], 8);
    ck_assert_uint_eq(runs[9], 9);
    ck_assert_uint_eq(fr_runs_of(alternating, 0, 9, runs, &members), 4);

    const unsigned char none[4] = {0, 0, 0, 0};
    ck_assert_uint_eq(fr_runs_of(none, 1, 4, runs, &members), 0);
    ck_assert_uint_eq(members, 0);
    ck_assert_uint_eq(fr_runs_of(none, 0, 4, runs, &members), 1);
    ck_assert_uint_eq(runs[0], 0);
    ck_assert_uint_eq(runs[1], 4);
    ck_assert_uint_eq(members, 4);
}
END_TEST

/* The masks of one case: rows and columns each as a kind of set. */
enum mask_kind { ONE_RUN, EVERY_OTHER, RANDOM, EMPTY, FULL };

static void fill_mask(enum mask_kind kind, uint64_t *state, unsigned char mask[M])
{
    size_t lo = random_size(splitmix64_uniform, state, 0, M / 2);
    size_t hi = random_size(splitmix64_uniform, state, lo, M);
    for (size_t i = 0; i < M; i++)
        switch (kind) {
        case ONE_RUN: mask[i] = i >= lo && i < hi; break;
        case EVERY_OTHER: mask[i] = i % 2 == 1; break;
        case RANDOM: mask[i] = splitmix64_uniform(state, 0.0, 1.0) < 0.3; break;
        case EMPTY: mask[i] = 0; break;
        case FULL: mask[i] = 1; break;
        }
}

START_TEST(runs_product_equals_the_whole_one)
{
    cholmod_common c;
    cholmod_l_start(&c);
    uint64_t state = 20261126;
    cholmod_sparse *D = packed_upper(M, &state, &c);
    ck_assert(fr_delassus_packed(D));
    static const enum mask_kind kinds[5] = {ONE_RUN, EVERY_OTHER, RANDOM, EMPTY, FULL};
    double worst = 0.0;
    for (int r = 0; r < 5; r++)
        for (int k = 0; k < 5; k++)
            for (int draw = 0; draw < 3; draw++) {
                unsigned char rows[M], cols[M];
                fill_mask(kinds[r], &state, rows);
                fill_mask(kinds[k], &state, cols);
                double x[M], xc[M], y[M], whole[M];
                for (size_t i = 0; i < M; i++) {
                    double v = splitmix64_uniform(&state, -1.0, 1.0);
                    x[i] = cols[i] ? v : NAN; /* outside C: never read */
                    xc[i] = cols[i] ? v : 0.0;
                    y[i] = SENTINEL;
                }
                size_t row_runs[M + 1], col_runs[M + 1], nr, nc;
                size_t ir = fr_runs_of(rows, 1, M, row_runs, &nr);
                size_t ic = fr_runs_of(cols, 1, M, col_runs, &nc);
                fr_delassus_mult_runs(D, col_runs, ic, x, row_runs, ir, y);
                fr_delassus_mult(D, 1.0, xc, 0.0, whole);
                for (size_t i = 0; i < M; i++) {
                    if (!rows[i]) {
                        ck_assert_double_eq(y[i], SENTINEL);
                        continue;
                    }
                    double scale = 0.0;
                    for (size_t j = 0; j < M; j++)
                        scale += fabs(entry(D, i, j) * xc[j]);
                    double bound = 4.0 * M * DBL_EPSILON / 2.0 * scale;
                    ck_assert_msg(fabs(y[i] - whole[i]) <= bound,
                                  "rows %d, columns %d, draw %d, row %zu: %.17g against %.17g", r,
                                  k, draw, i, y[i], whole[i]);
                    if (scale > 0.0)
                        worst = fmax(worst, fabs(y[i] - whole[i]) / scale);
                }
            }
    ck_assert_double_lt(worst, 4.0 * M * DBL_EPSILON / 2.0);
    cholmod_l_free_sparse(&D, &c);
    cholmod_l_finish(&c);
}
END_TEST

START_TEST(cheaper_rule)
{
    cholmod_common c;
    cholmod_l_start(&c);
    uint64_t state = 7;
    cholmod_sparse *D = packed_upper(M, &state, &c);
    /* 12 rows in one run against the other 85 in two: 1 020 + 3 * 97 against 97 * 98 / 2 */
    ck_assert(fr_delassus_runs_cheaper(D, 12, 1, M - 12, 2));
    /* all against all: 9 409 + 2 * 97 */
    ck_assert(!fr_delassus_runs_cheaper(D, M, 1, M, 1));
    /* every other row, 48 runs: 48 * 49 + 97 * 97 */
    ck_assert(!fr_delassus_runs_cheaper(D, 48, 48, 49, 49));
    /* not packed: the upper triangle without its last entry */
    SuiteSparse_long *Dp = D->p;
    Dp[M]--;
    ck_assert(!fr_delassus_packed(D));
    ck_assert(!fr_delassus_runs_cheaper(D, 12, 1, M - 12, 2));
    Dp[M]++;
    cholmod_l_free_sparse(&D, &c);
    cholmod_l_finish(&c);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("delassus_runs");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, runs_of_masks);
    tcase_add_test(tc, runs_product_equals_the_whole_one);
    tcase_add_test(tc, cheaper_rule);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
