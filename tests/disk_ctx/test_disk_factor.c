/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_disk_factor.c — Check suite for the 2-D context's reduced Hessian (src/disk_ctx/
 * disk_factor.h) in its two storages, CHOLMOD's simplicial LDL^T and LAPACK's dense Cholesky,
 * white box on the static library:
 *   - the fill rule: a full W goes dense, a block-tridiagonal one (its factor banded, about
 *     5/m of a dense triangle) stays sparse;
 *   - the same solves both ways, to 1e-12 of the largest |x|: H for sets of free, circle and
 *     fixed contacts (circles with their normals and multipliers), on a W with holes, the
 *     decoupled unknowns' right-hand sides passed through as the unit rows say;
 *   - an H that is not positive definite on the set (a contact's block indefinite, singular,
 *     or with a pivot below 1e-12 of its diagonal) is FRICREG_ESINGULAR both ways, naming the
 *     same contact, and the next set is factored afresh. */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "disk_ctx/disk_coupling.h"
#include "disk_ctx/disk_factor.h"
#include "disk_ctx/disk_kind.h"
#include "fricreg.h"

#define MMAX 24

static double uniform(unsigned long *state)
{
    *state = *state * 6364136223846793005UL + 1442695040888963407UL;
    return (double)(*state >> 11) / 9007199254740992.0; /* [0, 1) */
}

/* A symmetric, diagonally dominant (so positive definite) 2m x 2m row-major W, each block
 * off the diagonal present with probability density, entries in [-1, 1]. */
static void dominant(size_t m, double density, unsigned long *state, double W[])
{
    size_t n = 2 * m;
    memset(W, 0, n * n * sizeof *W);
    for (size_t i = 0; i < m; i++)
        for (size_t j = i; j < m; j++)
            if (i == j || uniform(state) < density)
                for (size_t a = 0; a < 2; a++)
                    for (size_t b = 0; b < 2; b++)
                        if (i != j || a < b)
                            W[(2 * i + a) * n + 2 * j + b] = W[(2 * j + b) * n + 2 * i + a] =
                                2.0 * uniform(state) - 1.0;
    for (size_t r = 0; r < n; r++) {
        double sum = 0.0;
        for (size_t c = 0; c < n; c++)
            sum += fabs(W[r * n + c]);
        W[r * n + r] = sum + 0.385 + uniform(state);
    }
}

static void setup(struct fr_disk_factor *F, struct fr_disk_coupling *w, size_t m, const double W[],
                  enum fr_disk_storage storage)
{
    memset(w, 0, sizeof *w);
    ck_assert_int_eq(fr_disk_coupling_from_dense(w, m, W), FRICREG_OK);
    ck_assert_int_eq(fr_disk_factor_setup(F, w, storage), FRICREG_OK);
}

static void release(struct fr_disk_factor *F, struct fr_disk_coupling *w)
{
    fr_disk_factor_free(F);
    fr_disk_coupling_free(w);
}

static int chosen_dense(size_t m, const double W[])
{
    struct fr_disk_factor F;
    struct fr_disk_coupling w;
    setup(&F, &w, m, W, FR_DISK_STORAGE_CHOSEN);
    int dense = F.dense;
    release(&F, &w);
    return dense;
}

START_TEST(fill_rule_picks_the_storage)
{
    enum { M = 20, N = 2 * M };
    static double W[N * N];
    unsigned long state = 2385;
    dominant(M, 1.0, &state, W);
    ck_assert(chosen_dense(M, W));
    memset(W, 0, sizeof W);
    for (size_t r = 0; r < N; r++) {
        W[r * N + r] = 4.385;
        if (r >= 2) /* contact i coupled to i - 1 only */
            W[r * N + r - 2] = W[(r - 2) * N + r] = -1.0;
    }
    ck_assert(!chosen_dense(M, W));
}
END_TEST

/* Random kinds (a third each), unit normals and multipliers lam >= 0 for the circles. */
static void random_set(size_t m, unsigned long *state, signed char kind[], double nrm[],
                       double lam[])
{
    for (size_t i = 0; i < m; i++) {
        double u = uniform(state), phi = 6.283185307179586 * uniform(state);
        kind[i] = u < 1.0 / 3.0 ? FR_DISK_FIXED : u < 2.0 / 3.0 ? FR_DISK_FREE : FR_DISK_CIRCLE;
        nrm[2 * i] = cos(phi), nrm[2 * i + 1] = sin(phi);
        lam[i] = 2.0 * uniform(state);
    }
}

START_TEST(dense_solves_equal_sparse_ones)
{
    const size_t m = 19, n = 2 * m;
    static double W[4 * MMAX * MMAX];
    unsigned long state = 7411;
    dominant(m, 0.5, &state, W);
    struct fr_disk_factor sparse, dense;
    struct fr_disk_coupling ws, wd;
    setup(&sparse, &ws, m, W, FR_DISK_STORAGE_SPARSE);
    setup(&dense, &wd, m, W, FR_DISK_STORAGE_DENSE);
    ck_assert(!sparse.dense && dense.dense);
    signed char kind[MMAX];
    double nrm[2 * MMAX], lam[MMAX], b[2 * MMAX], xs[2 * MMAX], xd[2 * MMAX];
    for (int trial = 0; trial < 24; trial++) {
        random_set(m, &state, kind, nrm, lam);
        if (trial == 0)
            memset(kind, FR_DISK_FREE, m); /* all of W */
        size_t ps = 0, pd = 0;
        ck_assert_int_eq(fr_disk_factor_build(&sparse, &ws, kind, nrm, lam, &ps), FRICREG_OK);
        ck_assert_int_eq(fr_disk_factor_build(&dense, &wd, kind, nrm, lam, &pd), FRICREG_OK);
        for (size_t u = 0; u < n; u++)
            b[u] = 2.0 * uniform(&state) - 1.0;
        ck_assert_int_eq(fr_disk_factor_solve(&sparse, b, xs), FRICREG_OK);
        ck_assert_int_eq(fr_disk_factor_solve(&dense, b, xd), FRICREG_OK);
        double scale = 0.0, diff = 0.0;
        for (size_t u = 0; u < n; u++) {
            scale = fmax(scale, fabs(xs[u]));
            diff = fmax(diff, fabs(xs[u] - xd[u]));
        }
        ck_assert_msg(diff <= 1e-12 * scale, "trial %d: %g of %g", trial, diff, scale);
        for (size_t i = 0; i < m; i++) /* a fixed contact's unit rows pass b through */
            if (kind[i] == FR_DISK_FIXED)
                ck_assert(xd[2 * i] == b[2 * i] && xd[2 * i + 1] == b[2 * i + 1]);
    }
    release(&sparse, &ws);
    release(&dense, &wd);
}
END_TEST

/* Not positive definite on the set: contact 7, uncoupled from the others, gets the diagonal
 * block [1 2; 2 1] (eigenvalues 3 and -1), [1 1; 1 1] (singular: a zero pivot, which stops
 * dpotrf) or [1 1; 1 1 + 1e-14] (a pivot of 1e-14, positive but below 1e-12 of H_kk: the
 * pivot test's own refusal). As a free contact each storage refuses it, naming contact 7. On
 * its circle with normal (1, 1)/sqrt 2 only the tangent (-1, 1)/sqrt 2 is coupled, where the
 * first block has curvature -1 (refused) and lam = 3 makes every one positive; fixed, it is out
 * of H. Each refusal leaves the next set to be factored afresh. */
START_TEST(not_positive_definite_named_alike)
{
    const size_t m = 12, n = 2 * m, bad = 7;
    const double off[3] = {2.0, 1.0, 1.0}, last[3] = {1.0, 1.0, 1.0 + 1e-14};
    static double W[4 * MMAX * MMAX];
    signed char kind[MMAX];
    double nrm[2 * MMAX], lam[MMAX];
    for (int v = 0; v < 3; v++) {
        unsigned long state = 911;
        dominant(m, 0.4, &state, W);
        for (size_t u = 0; u < n; u++)
            for (size_t a = 0; a < 2; a++)
                if (u / 2 != bad)
                    W[u * n + 2 * bad + a] = W[(2 * bad + a) * n + u] = 0.0;
        W[(2 * bad) * n + 2 * bad] = 1.0, W[(2 * bad + 1) * n + 2 * bad + 1] = last[v];
        W[(2 * bad) * n + 2 * bad + 1] = W[(2 * bad + 1) * n + 2 * bad] = off[v];
        struct fr_disk_factor F[2];
        struct fr_disk_coupling w[2];
        setup(&F[0], &w[0], m, W, FR_DISK_STORAGE_SPARSE);
        setup(&F[1], &w[1], m, W, FR_DISK_STORAGE_DENSE);
        for (int s = 0; s < 2; s++) {
            random_set(m, &state, kind, nrm, lam);
            kind[bad] = FR_DISK_FREE;
            size_t pivot = 99;
            ck_assert_int_eq(fr_disk_factor_build(&F[s], &w[s], kind, nrm, lam, &pivot),
                             FRICREG_ESINGULAR);
            ck_assert_uint_eq(pivot, bad);
            kind[bad] = FR_DISK_CIRCLE;
            nrm[2 * bad] = nrm[2 * bad + 1] = sqrt(0.5), lam[bad] = 0.0;
            if (v == 0) {
                pivot = 99;
                ck_assert_int_eq(fr_disk_factor_build(&F[s], &w[s], kind, nrm, lam, &pivot),
                                 FRICREG_ESINGULAR);
                ck_assert_uint_eq(pivot, bad);
            }
            lam[bad] = 3.0;
            ck_assert_int_eq(fr_disk_factor_build(&F[s], &w[s], kind, nrm, lam, &pivot),
                             FRICREG_OK);
            kind[bad] = FR_DISK_FIXED;
            ck_assert_int_eq(fr_disk_factor_build(&F[s], &w[s], kind, nrm, lam, &pivot),
                             FRICREG_OK);
        }
        release(&F[0], &w[0]);
        release(&F[1], &w[1]);
    }
}
END_TEST

int main(void)
{
    Suite *s = suite_create("disk_factor");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, fill_rule_picks_the_storage);
    tcase_add_test(tc, dense_solves_equal_sparse_ones);
    tcase_add_test(tc, not_positive_definite_named_alike);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
