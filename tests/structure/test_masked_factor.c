/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_masked_factor.c — Check suite for the principal blocks of W_eff (src/structure/
 * masked_factor.h) in their two storages, CHOLMOD's sparse factor and LAPACK's dense one, white
 * box on the static library:
 *   - the fill rule: a full W goes dense, a tridiagonal one (its factor bidiagonal, 2m - 1 of
 *     m (m + 1) / 2 entries) stays sparse;
 *   - the same solves both ways, to 1e-10 of the largest |x|: blocks of a W with holes in its
 *     pattern, with and without shifts, refactored and held;
 *   - a block that is not positive definite (indefinite, or singular: a zero pivot) is
 *     FRICREG_ESINGULAR both ways, x untouched, and the next block is factored afresh;
 *   - the dense factor keeps the leading rows of the last one that a block keeps with their
 *     shifts, and those alone (a sequence of blocks, each against the sparse factor to 1e-10);
 *   - a factor that served as a base is kept as the spare, and a block that comes back is
 *     solved from it with nothing factored, bit for bit as before;
 *   - a W packed whole gives the same factors as one read by a pass over its pattern;
 *   - fricreg_structure's steps on a stiff membrane's edge (W_eff dense, the rule's choice) give
 *     the same forces and displacements with either storage forced, to 1e-10 relative;
 *   - a checkpoint carries the dense block a step holds, its kept complement too. */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/sparse_factor.h"
#include "fricreg.h"
#include "fricreg_structure.h"
#include "structure/masked_factor.h"
#include "structure/structure_internal.h"

#define MMAX 760

static double uniform(unsigned long *state)
{
    *state = *state * 6364136223846793005UL + 1442695040888963407UL;
    return (double)(*state >> 11) / 9007199254740992.0; /* [0, 1) */
}

/* W's upper triangle (CSC) from a dense symmetric m x m row-major A, its nonzeros only. */
static cholmod_sparse *upper(size_t m, const double A[], cholmod_common *c)
{
    size_t nnz = 0;
    for (size_t j = 0; j < m; j++)
        for (size_t i = 0; i <= j; i++)
            nnz += A[i * m + j] != 0.0;
    cholmod_sparse *W = cholmod_l_allocate_sparse(m, m, nnz, 1, 1, 1, CHOLMOD_REAL, c);
    ck_assert_ptr_nonnull(W);
    SuiteSparse_long *Wp = W->p, *Wi = W->i;
    double *Wx = W->x;
    size_t p = 0;
    for (size_t j = 0; j < m; j++) {
        Wp[j] = (SuiteSparse_long)p;
        for (size_t i = 0; i <= j; i++)
            if (A[i * m + j] != 0.0) {
                Wi[p] = (SuiteSparse_long)i;
                Wx[p++] = A[i * m + j];
            }
    }
    Wp[m] = (SuiteSparse_long)p;
    return W;
}

/* A symmetric, diagonally dominant (so positive definite) m x m matrix, each entry off the
 * diagonal present with probability density, in [-1, 1]. */
static void dominant(size_t m, double density, unsigned long *state, double A[])
{
    memset(A, 0, m * m * sizeof *A);
    for (size_t i = 0; i < m; i++)
        for (size_t j = i + 1; j < m; j++)
            if (uniform(state) < density)
                A[i * m + j] = A[j * m + i] = 2.0 * uniform(state) - 1.0;
    for (size_t i = 0; i < m; i++) {
        double sum = 0.0;
        for (size_t j = 0; j < m; j++)
            sum += fabs(A[i * m + j]);
        A[i * m + i] = sum + 0.385 + uniform(state);
    }
}

static int chosen_dense(size_t m, const double A[])
{
    cholmod_common c;
    ck_assert_int_eq(fr_cholmod_start(&c), FRICREG_OK);
    cholmod_sparse *W = upper(m, A, &c);
    struct fr_masked_factor f;
    ck_assert_int_eq(fr_masked_factor_prepare(&f, W, FR_BLOCK_CHOSEN, &c), FRICREG_OK);
    int dense = f.dense;
    fr_masked_factor_free(&f, &c);
    cholmod_l_free_sparse(&W, &c);
    fr_cholmod_finish(&c);
    return dense;
}

START_TEST(fill_rule_picks_the_storage)
{
    enum { M = 40 };
    static double A[M * M];
    unsigned long state = 2385;
    dominant(M, 1.0, &state, A);
    ck_assert(chosen_dense(M, A));
    memset(A, 0, sizeof A);
    for (size_t i = 0; i < M; i++) {
        A[i * M + i] = 2.385;
        if (i > 0)
            A[i * M + i - 1] = A[(i - 1) * M + i] = -1.0;
    }
    ck_assert(!chosen_dense(M, A));
}
END_TEST

/* A random W (dominant(), m x m, the density given, from *state on) with both storages
 * prepared on it. */
struct factor_pair {
    cholmod_common c;
    cholmod_sparse *W;
    struct fr_masked_factor sparse, dense;
};

static void pair_open(struct factor_pair *p, size_t m, double density, unsigned long *state)
{
    static double A[MMAX * MMAX];
    dominant(m, density, state, A);
    ck_assert_int_eq(fr_cholmod_start(&p->c), FRICREG_OK);
    p->W = upper(m, A, &p->c);
    ck_assert_int_eq(fr_masked_factor_prepare(&p->sparse, p->W, FR_BLOCK_SPARSE, &p->c),
                     FRICREG_OK);
    ck_assert_int_eq(fr_masked_factor_prepare(&p->dense, p->W, FR_BLOCK_DENSE, &p->c), FRICREG_OK);
}

static void pair_close(struct factor_pair *p)
{
    fr_masked_factor_free(&p->sparse, &p->c);
    fr_masked_factor_free(&p->dense, &p->c);
    cholmod_l_free_sparse(&p->W, &p->c);
    fr_cholmod_finish(&p->c);
}

START_TEST(dense_solves_equal_sparse_ones)
{
    const size_t m = 37;
    unsigned long state = 7411;
    struct factor_pair pr;
    pair_open(&pr, m, 0.4, &state);
    ck_assert(!pr.sparse.dense && pr.dense.dense);
    double b[MMAX], shift[MMAX], xs[MMAX], xd[MMAX];
    unsigned char set[MMAX];
    for (int trial = 0; trial < 24; trial++) {
        int same = trial % 3 == 2; /* the last block again: the factors held */
        for (size_t i = 0; i < m && !same; i++) {
            set[i] = uniform(&state) < 0.3 + 0.6 * (trial % 4) / 3.0;
            shift[i] = trial % 2 ? 0.0 : 10.0 * uniform(&state);
        }
        for (size_t i = 0; i < m; i++) {
            b[i] = 4.0 * uniform(&state) - 2.0;
            xs[i] = xd[i] = -7.5; /* outside the block: untouched */
        }
        const double *sh = trial % 2 ? NULL : shift;
        ck_assert_int_eq(fr_masked_factor_solve(&pr.sparse, pr.W, set, sh, b, xs, &pr.c),
                         FRICREG_OK);
        ck_assert_int_eq(fr_masked_factor_solve(&pr.dense, pr.W, set, sh, b, xd, &pr.c),
                         FRICREG_OK);
        double scale = 0.0;
        for (size_t i = 0; i < m; i++)
            scale = fmax(scale, fabs(xs[i]));
        for (size_t i = 0; i < m; i++) {
            ck_assert_double_eq_tol(xd[i], xs[i], 1e-10 * scale);
            if (!set[i])
                ck_assert_double_eq(xd[i], -7.5);
        }
    }
    pair_close(&pr);
}
END_TEST

/* W: rows 0, 1 an indefinite block [[1, 2], [2, 1]] (eigenvalues 3, -1); rows 2, 3 a singular
 * one [[1.5, 1.5], [1.5, 1.5]] (the second pivot exactly 0); row 4 couples weakly to both. */
START_TEST(not_positive_definite_is_esingular_both_ways)
{
    const size_t m = 5;
    const double A[25] = {1.0, 2.0, 0.0, 0.0, 0.1, 2.0, 1.0, 0.0, 0.0, 0.1, 0.0, 0.0,  1.5,
                          1.5, 0.1, 0.0, 0.0, 1.5, 1.5, 0.1, 0.1, 0.1, 0.1, 0.1, 2.385};
    const unsigned char indefinite[5] = {1, 1, 0, 0, 0}, singular[5] = {0, 0, 1, 1, 0},
                        good[5] = {1, 0, 1, 0, 1};
    const double b[5] = {0.3, -1.2, 0.7, 2.1, -0.4};
    cholmod_common c;
    ck_assert_int_eq(fr_cholmod_start(&c), FRICREG_OK);
    cholmod_sparse *W = upper(m, A, &c);
    const enum fr_block_storage storages[2] = {FR_BLOCK_SPARSE, FR_BLOCK_DENSE};
    double x[2][5];
    for (int k = 0; k < 2; k++) {
        struct fr_masked_factor f;
        ck_assert_int_eq(fr_masked_factor_prepare(&f, W, storages[k], &c), FRICREG_OK);
        for (size_t i = 0; i < m; i++)
            x[k][i] = 9.25;
        ck_assert_int_eq(fr_masked_factor_solve(&f, W, indefinite, NULL, b, x[k], &c),
                         FRICREG_ESINGULAR);
        ck_assert_int_eq(fr_masked_factor_solve(&f, W, good, NULL, b, x[k], &c), FRICREG_OK);
        ck_assert_int_eq(fr_masked_factor_solve(&f, W, singular, NULL, b, x[k], &c),
                         FRICREG_ESINGULAR);
        ck_assert_double_eq(x[k][1], 9.25); /* failed blocks write nothing */
        ck_assert_double_eq(x[k][3], 9.25);
        /* the failed block is not held: a shift makes it positive definite */
        const double shift[5] = {0.0, 0.0, 0.25, 0.25, 0.0};
        ck_assert_int_eq(fr_masked_factor_solve(&f, W, singular, shift, b, x[k], &c), FRICREG_OK);
        fr_masked_factor_free(&f, &c);
    }
    for (size_t i = 0; i < m; i++)
        ck_assert_double_eq_tol(x[1][i], x[0][i], 1e-12 * fabs(x[0][i]) + 1e-300);
    cholmod_l_free_sparse(&W, &c);
    fr_cholmod_finish(&c);
}
END_TEST

/* One block of the sequence below: dense solve (the factor kept from the last block where it
 * can be) against CHOLMOD's sparse factor of the same block, to 1e-10 of the largest |x|, and
 * the rows the dense factorization kept and deleted. */
static void kept_block(struct fr_masked_factor *dense, struct fr_masked_factor *sparse,
                       const cholmod_sparse *W, const unsigned char set[], const double shift[],
                       size_t kept, size_t deleted, cholmod_common *c)
{
    size_t m = dense->m;
    double b[MMAX], xs[MMAX], xd[MMAX], scale = 0.0;
    for (size_t i = 0; i < m; i++) {
        b[i] = sin(1.7 * (double)i + 0.3) + 0.2;
        xs[i] = xd[i] = -7.5;
    }
    ck_assert_int_eq(fr_masked_factor_solve(sparse, W, set, shift, b, xs, c), FRICREG_OK);
    ck_assert_int_eq(fr_masked_factor_solve(dense, W, set, shift, b, xd, c), FRICREG_OK);
    for (size_t i = 0; i < m; i++)
        scale = fmax(scale, fabs(xs[i]));
    for (size_t i = 0; i < m; i++)
        ck_assert_double_eq_tol(xd[i], xs[i], 1e-10 * scale);
    ck_assert_uint_eq(dense->kept, kept);
    ck_assert_uint_eq(dense->deleted, deleted);
}

/* The dense factor's leading rows kept (masked_factor.h): a block that grows keeps all the
 * last one's rows, one that loses its last rows keeps the rest; a shift that moves, or a first
 * row that leaves, keeps the rows after it by deleting that row (flops 2 q t^2 + the new rows',
 * against factoring the t rows again: 608 against 1 659, then 1 152 against 4 608), the shifted
 * row then last; where deleting costs more (20 of 27 rows: 1 960 against 114) the rows are
 * factored again; a trailing part that is not positive definite is FRICREG_ESINGULAR, x
 * untouched, and the next block is factored from the spare (the factor of the block before
 * the last but one, kept when the first row left: 24 rows kept by deleting row 0). */
START_TEST(dense_factor_keeps_its_leading_rows)
{
    const size_t m = 40;
    unsigned long state = 5113;
    struct factor_pair pr;
    pair_open(&pr, m, 1.0, &state);
    unsigned char set[MMAX] = {0};
    double shift[MMAX] = {0.0};
    for (size_t i = 0; i < 20; i++)
        set[i] = 1;
    kept_block(&pr.dense, &pr.sparse, pr.W, set, shift, 0, 0, &pr.c);
    for (size_t i = 20; i < 30; i++) /* grows: rows 20..29 after 0..19 */
        set[i] = 1;
    kept_block(&pr.dense, &pr.sparse, pr.W, set, shift, 20, 0, &pr.c);
    for (size_t i = 25; i < 30; i++) /* loses its last five */
        set[i] = 0;
    kept_block(&pr.dense, &pr.sparse, pr.W, set, shift, 25, 0, &pr.c);
    shift[22] = 3.5; /* a shift moves at the factor's row 22 */
    kept_block(&pr.dense, &pr.sparse, pr.W, set, shift, 24, 1, &pr.c);
    ck_assert_int_eq(pr.dense.rows[22], 23);
    ck_assert_int_eq(pr.dense.rows[24], 22); /* the shifted row now last */
    set[0] = 0;
    kept_block(&pr.dense, &pr.sparse, pr.W, set, shift, 24, 1, &pr.c);
    ck_assert_int_eq(pr.dense.rows[0], 1);
    for (size_t i = 30; i < 33; i++) /* a trailing part that is not positive definite */
        set[i] = 1;
    shift[31] = -1e3;
    double b[MMAX], x[MMAX];
    for (size_t i = 0; i < m; i++)
        b[i] = x[i] = -7.5;
    ck_assert_int_eq(fr_masked_factor_solve(&pr.dense, pr.W, set, shift, b, x, &pr.c),
                     FRICREG_ESINGULAR);
    ck_assert_uint_eq(pr.dense.kept, 24);
    for (size_t i = 0; i < m; i++)
        ck_assert_double_eq(x[i], -7.5);
    shift[31] = 0.0;
    kept_block(&pr.dense, &pr.sparse, pr.W, set, shift, 24, 1, &pr.c);
    ck_assert(pr.dense.from_spare);
    for (size_t i = 1; i <= 20; i++) /* 20 of its 27 rows leave: factored again */
        set[i] = 0;
    kept_block(&pr.dense, &pr.sparse, pr.W, set, shift, 0, 0, &pr.c);
    pair_close(&pr);
}
END_TEST

/* A block of the held rows whose shifts changed only on the last factorization's new rows is
 * factored from their kept Schur complement (masked_factor.h): rows 0..29, then 30..39 added,
 * 30..37 with shifts (30 kept); those shifts moved: 30 kept again, none deleted, against
 * CHOLMOD's factor to 1e-10 and bit for bit against a factor that reached the same block by
 * its trailing factorization (0..29, then 30..39 with the moved shifts, in the same order);
 * then one shift to none and an unshifted row given one, from the complement again; then a
 * shift moved before row 30: its row deleted, as before. */
START_TEST(dense_factor_from_the_kept_complement)
{
    const size_t m = 40;
    unsigned long state = 777;
    struct factor_pair pr;
    pair_open(&pr, m, 1.0, &state);
    struct fr_masked_factor direct = {0};
    ck_assert_int_eq(fr_masked_factor_prepare(&direct, pr.W, FR_BLOCK_DENSE, &pr.c), FRICREG_OK);
    unsigned char set[MMAX] = {0};
    double shift[MMAX] = {0.0}, moved[MMAX] = {0.0};
    memset(set, 1, 30);
    kept_block(&pr.dense, &pr.sparse, pr.W, set, shift, 0, 0, &pr.c);
    kept_block(&direct, &pr.sparse, pr.W, set, moved, 0, 0, &pr.c);
    memset(set, 1, m);
    for (size_t i = 30; i < 38; i++) {
        shift[i] = 0.5 + 0.1 * (double)i;
        moved[i] = 2.0 - 0.03 * (double)i;
    }
    kept_block(&pr.dense, &pr.sparse, pr.W, set, shift, 30, 0, &pr.c);
    ck_assert_uint_eq(pr.dense.schur_from, 30);
    kept_block(&pr.dense, &pr.sparse, pr.W, set, moved, 30, 0, &pr.c);
    kept_block(&direct, &pr.sparse, pr.W, set, moved, 30, 0, &pr.c);
    ck_assert_int_eq(memcmp(pr.dense.rows, direct.rows, m * sizeof *direct.rows), 0);
    double b[MMAX], from_complement[MMAX], trailing[MMAX];
    for (size_t i = 0; i < m; i++)
        b[i] = cos(0.9 * (double)i);
    ck_assert_int_eq(fr_masked_factor_solve(&pr.dense, pr.W, set, moved, b, from_complement, &pr.c),
                     FRICREG_OK);
    ck_assert_int_eq(fr_masked_factor_solve(&direct, pr.W, set, moved, b, trailing, &pr.c),
                     FRICREG_OK);
    ck_assert_int_eq(memcmp(from_complement, trailing, m * sizeof *b), 0);
    moved[33] = 0.0; /* to none, and an unshifted row given one: the complement still serves */
    moved[39] = 0.25;
    kept_block(&pr.dense, &pr.sparse, pr.W, set, moved, 30, 0, &pr.c);
    moved[5] = 1.5; /* before the complement's rows: deleted and put last */
    kept_block(&pr.dense, &pr.sparse, pr.W, set, moved, 39, 1, &pr.c);
    ck_assert_int_eq(pr.dense.rows[39], 5);
    fr_masked_factor_free(&direct, &pr.c);
    pair_close(&pr);
}
END_TEST

/* Rows deleted from the middle of the dense factor (delete_rows), as a stick zone's rows
 * leave in any order: all 40 rows, some shifted; then five rows at scattered places leave,
 * one staying row's shift moves, rows come back and others leave, each block against
 * CHOLMOD's sparse factor to 1e-10 with the rows kept and deleted counted. */
START_TEST(dense_factor_deletes_rows_inside)
{
    const size_t m = 40;
    unsigned long state = 90210;
    struct factor_pair pr;
    pair_open(&pr, m, 1.0, &state);
    unsigned char set[MMAX];
    double shift[MMAX] = {0.0};
    memset(set, 1, m);
    for (size_t i = 35; i < 40; i++)
        shift[i] = 0.5 + 0.1 * (double)i;
    kept_block(&pr.dense, &pr.sparse, pr.W, set, shift, 0, 0, &pr.c);
    const size_t leave[5] = {3, 7, 8, 20, 33};
    for (size_t k = 0; k < 5; k++)
        set[leave[k]] = 0;
    kept_block(&pr.dense, &pr.sparse, pr.W, set, shift, 35, 5, &pr.c);
    ck_assert_int_eq(pr.dense.rows[3], 4);
    ck_assert_int_eq(pr.dense.rows[34], 39);
    shift[36] = 9.0; /* a shifted row's slope moves: deleted, then last */
    set[12] = 0;
    kept_block(&pr.dense, &pr.sparse, pr.W, set, shift, 33, 2, &pr.c);
    ck_assert_int_eq(pr.dense.rows[33], 36);
    set[7] = set[8] = 1; /* two come back (appended), two others leave */
    set[1] = set[30] = 0;
    kept_block(&pr.dense, &pr.sparse, pr.W, set, shift, 32, 2, &pr.c);
    ck_assert_int_eq(pr.dense.rows[32], 7);
    ck_assert_int_eq(pr.dense.rows[33], 8);
    pair_close(&pr);
}
END_TEST

/* Many rows deleted at once, as a whole row of an interface starts to slip: of 760 rows, the
 * 400 after the first 300 leave and the last 60 stay, so dtpqrt runs in blocks of 50 (q / 8)
 * where a few rows take 32: the block against CHOLMOD's factor to 1e-10, all 360 staying rows
 * kept; then the 400 back, whose block the spare holds (the factor of all 760, kept intact):
 * nothing factored. */
START_TEST(dense_factor_deletes_many_rows_in_blocks)
{
    const size_t m = 760;
    unsigned long state = 4242;
    struct factor_pair pr;
    pair_open(&pr, m, 0.02, &state);
    unsigned char set[MMAX];
    double shift[MMAX] = {0.0};
    memset(set, 1, m);
    kept_block(&pr.dense, &pr.sparse, pr.W, set, shift, 0, 0, &pr.c);
    memset(set + 300, 0, 400);
    kept_block(&pr.dense, &pr.sparse, pr.W, set, shift, 360, 400, &pr.c);
    ck_assert_int_eq(pr.dense.rows[300], 700);
    memset(set + 300, 1, 400);
    kept_block(&pr.dense, &pr.sparse, pr.W, set, shift, 760, 0, &pr.c);
    ck_assert(pr.dense.from_spare);
    ck_assert_int_eq(pr.dense.rows[360], 360);
    pair_close(&pr);
}
END_TEST

/* x = the dense factor's solve of the block set, shift, for kept_block's b. */
static void dense_x(struct factor_pair *pr, const unsigned char set[], const double shift[],
                    double x[])
{
    double b[MMAX];
    for (size_t i = 0; i < pr->dense.m; i++) {
        b[i] = sin(1.7 * (double)i + 0.3) + 0.2;
        x[i] = 0.0; /* the rows outside the block are not written */
    }
    ck_assert_int_eq(fr_masked_factor_solve(&pr->dense, pr->W, set, shift, b, x, &pr->c),
                     FRICREG_OK);
}

/* The spare factor (masked_factor.h): all 40 rows A, factored afresh; rows 10..14 leave (A',
 * their rows deleted: 6 250 flops against 13 958 again), A's factor kept intact as the spare;
 * A back: solved from the spare with nothing factored, bit for bit as A's first solve; A'
 * back the same way (A' now the kept one); rows 20..24 leave A' too (A'', made from A', which
 * stays as the spare: A dropped) and A back once more, from the spare A' by appending rows
 * 10..14 (7 042 flops, against 12 333 from A''). Each block also against CHOLMOD's factor to
 * 1e-10, with the rows kept and deleted counted. */
START_TEST(dense_factor_kept_as_spare)
{
    const size_t m = 40;
    unsigned long state = 2385;
    struct factor_pair pr;
    pair_open(&pr, m, 1.0, &state);
    unsigned char all[MMAX], some[MMAX], fewer[MMAX];
    double shift[MMAX] = {0.0}, xa[MMAX], xs[MMAX], x[MMAX];
    memset(all, 1, m);
    memcpy(some, all, m);
    memset(some + 10, 0, 5);
    memcpy(fewer, some, m);
    memset(fewer + 20, 0, 5);
    kept_block(&pr.dense, &pr.sparse, pr.W, all, shift, 0, 0, &pr.c);
    dense_x(&pr, all, shift, xa);
    kept_block(&pr.dense, &pr.sparse, pr.W, some, shift, 35, 5, &pr.c);
    ck_assert(!pr.dense.from_spare && pr.dense.spare.held && pr.dense.spare_kept);
    dense_x(&pr, some, shift, xs);
    kept_block(&pr.dense, &pr.sparse, pr.W, all, shift, 40, 0, &pr.c);
    ck_assert(pr.dense.from_spare);
    dense_x(&pr, all, shift, x);
    ck_assert_int_eq(memcmp(x, xa, m * sizeof *x), 0);
    kept_block(&pr.dense, &pr.sparse, pr.W, some, shift, 35, 0, &pr.c);
    ck_assert(pr.dense.from_spare);
    dense_x(&pr, some, shift, x);
    ck_assert_int_eq(memcmp(x, xs, m * sizeof *x), 0);
    kept_block(&pr.dense, &pr.sparse, pr.W, fewer, shift, 30, 5, &pr.c);
    ck_assert(!pr.dense.from_spare && pr.dense.spare_kept);
    kept_block(&pr.dense, &pr.sparse, pr.W, all, shift, 35, 0, &pr.c);
    ck_assert(pr.dense.from_spare);
    pair_close(&pr);
}
END_TEST

/* A W packed whole (every entry of its upper triangle stored, as fr_cfactor_build stores a
 * W_eff that fills) has its blocks' columns read where they go (dense_fill_packed), any other
 * by a pass over W: the same entries, so the same factors. A sequence of blocks (fresh, grown,
 * rows deleted inside, shifted rows, one back from the spare) solved both ways, bit for bit,
 * the second way on the same W marked unsorted (so not packed, to fr_delassus_packed). */
START_TEST(dense_fill_packed_equals_the_scan)
{
    const size_t m = 40;
    unsigned long state = 6121;
    struct factor_pair pr;
    pair_open(&pr, m, 1.0, &state);
    ck_assert_uint_eq((size_t)((SuiteSparse_long *)pr.W->p)[m], m * (m + 1) / 2);
    cholmod_sparse *U = cholmod_l_copy_sparse(pr.W, &pr.c);
    ck_assert_ptr_nonnull(U);
    U->sorted = 0;
    struct fr_masked_factor scan = {0};
    ck_assert_int_eq(fr_masked_factor_prepare(&scan, U, FR_BLOCK_DENSE, &pr.c), FRICREG_OK);
    unsigned char set[MMAX] = {0};
    double shift[MMAX] = {0.0}, b[MMAX], x[MMAX], y[MMAX];
    for (size_t i = 0; i < m; i++)
        b[i] = cos(2.385 * (double)i);
    for (int k = 0; k < 6; k++) {
        if (k == 0)
            memset(set, 1, 25);
        else if (k == 1)
            memset(set, 1, m);
        else if (k == 2)
            set[4] = set[17] = set[30] = 0;
        else if (k == 3)
            for (size_t i = 33; i < 38; i++)
                shift[i] = 0.7 + 0.05 * (double)i;
        else if (k == 4)
            set[4] = 1;
        else
            memset(shift, 0, sizeof shift);
        memset(x, 0, sizeof x);
        memset(y, 0, sizeof y);
        ck_assert_int_eq(fr_masked_factor_solve(&pr.dense, pr.W, set, shift, b, x, &pr.c),
                         FRICREG_OK);
        ck_assert_int_eq(fr_masked_factor_solve(&scan, U, set, shift, b, y, &pr.c), FRICREG_OK);
        ck_assert_int_eq(memcmp(x, y, m * sizeof *x), 0);
        ck_assert_uint_eq(pr.dense.kept, scan.kept);
    }
    fr_masked_factor_free(&scan, &pr.c);
    cholmod_l_free_sparse(&U, &pr.c);
    pair_close(&pr);
}
END_TEST

/* ---- A structure's steps ------------------------------------------------------------------ */

/* bench/membrane_contacts.c in small: a SIDE x SIDE grid of 1 kg nodes, springs of 3e6 N/m
 * between neighbours and 10^3 N/m to the ground, C = 0.002 s K, shaken at 0.35 g, 4 Hz; contacts
 * on the edge row against the ground (mu N = 20 N) and on the next row against the edge
 * (4 N). At this stiffness (dt omega_max = 24) W_eff of the 2 SIDE contacts is dense. */
#define SIDE 8
#define NDOF (SIDE * SIDE)
#define NCON (2 * SIDE)
#define STEPS 120

static fricreg_structure *membrane(void)
{
    static double K[NDOF * NDOF], M[NDOF * NDOF], J[NCON * NDOF];
    double mun[NCON], r[NDOF], ag[2 * STEPS + 1];
    memset(K, 0, sizeof K);
    memset(M, 0, sizeof M);
    memset(J, 0, sizeof J);
    for (int a = 0; a < NDOF; a++) {
        int row = a / SIDE, col = a % SIDE;
        M[a * NDOF + a] = 1.0;
        K[a * NDOF + a] += 1e3;
        r[a] = 1.0;
        int nb[2] = {col + 1 < SIDE ? a + 1 : -1, row + 1 < SIDE ? a + SIDE : -1};
        for (int k = 0; k < 2; k++)
            if (nb[k] >= 0) {
                K[a * NDOF + a] += 3e6;
                K[nb[k] * NDOF + nb[k]] += 3e6;
                K[a * NDOF + nb[k]] -= 3e6;
                K[nb[k] * NDOF + a] -= 3e6;
            }
    }
    for (int c = 0; c < SIDE; c++) {
        J[c * NDOF + c] = 1.0; /* edge node c against the ground */
        mun[c] = 20.0;
        J[(SIDE + c) * NDOF + SIDE + c] = 1.0; /* the next row's node against the edge's */
        J[(SIDE + c) * NDOF + c] = -1.0;
        mun[SIDE + c] = 4.0;
    }
    for (int k = 0; k <= 2 * STEPS; k++)
        ag[k] = 0.35 * 9.81 * sin(6.283185307179586 * 4.0 * k * 0.0025);
    fricreg_structure *s = NULL;
    ck_assert_int_eq(fricreg_structure_create(NDOF, NCON, &s), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_mass(s, NDOF, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_stiffness(s, NDOF, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_rayleigh(s, 0.0, 0.002), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_contacts(s, NCON, NDOF, J), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_bounds(s, NCON, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_law(s, FRICREG_LAW_QUINN, 1e-3), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_influence(s, NDOF, r), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_ground_accel(s, 0.0, 0.0025, 2 * STEPS + 1, ag),
                     FRICREG_OK);
    return s;
}

/* Forces f[STEPS][NCON] and displacements u[STEPS][NDOF] of STEPS steps of 5 ms in the
 * storage given; the count of contact-steps stuck (|f_i| < 0.999 mu N_i) and whether the
 * blocks were dense. */
static void membrane_run(enum fr_block_storage storage, double (*f)[NCON], double (*u)[NDOF],
                         int *stuck, int *dense)
{
    fricreg_structure *s = membrane();
    s->newton.storage = storage;
    *stuck = 0;
    for (int step = 0; step < STEPS; step++) {
        int status = fricreg_structure_step(s, 0.005);
        ck_assert_msg(status == FRICREG_OK, "step %d: %s", step, fricreg_structure_errmsg(s));
        ck_assert_int_eq(fricreg_structure_get_forces(s, NCON, f[step]), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_get_state(s, NDOF, u[step], NULL, NULL), FRICREG_OK);
        for (int i = 0; i < NCON; i++)
            *stuck += fabs(f[step][i]) < 0.999 * (i < SIDE ? 20.0 : 4.0);
    }
    *dense = s->newton.block.dense;
    fricreg_structure_free(s);
}

/* g's held factor equal to f's bit for bit: rows, shifts, factor and kept complement. */
static void same_factor(const struct fr_masked_factor *f, const struct fr_masked_factor *g)
{
    size_t m = f->m, n = f->order;
    ck_assert(g->held);
    ck_assert_uint_eq(g->order, n);
    ck_assert_uint_eq(g->schur_from, f->schur_from);
    ck_assert_int_eq(memcmp(g->rows, f->rows, n * sizeof *f->rows), 0);
    ck_assert_int_eq(memcmp(g->held_set, f->held_set, m), 0);
    ck_assert_int_eq(memcmp(g->held_shift, f->held_shift, m * sizeof *f->held_shift), 0);
    for (size_t col = 0; col < n; col++)
        ck_assert_int_eq(memcmp(g->D + col * m, f->D + col * m, (col + 1) * sizeof *f->D), 0);
    for (size_t col = f->schur_from; col < n; col++) {
        ck_assert(g->schur_diag[col] == f->schur_diag[col]);
        for (size_t row = f->schur_from; row < col; row++)
            ck_assert(g->D[col + row * m] == f->D[col + row * m]);
    }
}

/* The dense block a step holds, as a checkpoint carries it (src/structure/blocks_carried.c):
 * the membrane stepped until its held factor keeps a complement (the rows of its last
 * factorization) and a spare is held, saved, restored into another that stepped on its own:
 * the same rows, shifts, factor and complement, bit for bit, of both factors, and the same one
 * kept. */
START_TEST(checkpoint_carries_the_dense_block)
{
    fricreg_structure *s = membrane(), *r = membrane();
    const struct fr_masked_factor *f = &s->newton.block, *g = &r->newton.block;
    int step = 0;
    do
        ck_assert_int_eq(fricreg_structure_step(s, 0.005), FRICREG_OK);
    while (++step < STEPS &&
           !(f->dense && f->held && f->schur_from + 1 < f->order && f->spare.held));
    ck_assert_msg(step < STEPS, "no complement of two rows or more kept with a spare");
    for (int k = 0; k < 7; k++)
        ck_assert_int_eq(fricreg_structure_step(r, 0.005), FRICREG_OK);
    size_t len = 0;
    ck_assert_int_eq(fricreg_structure_save(s, NULL, &len), FRICREG_OK);
    unsigned char *blob = malloc(len);
    ck_assert_int_eq(fricreg_structure_save(s, blob, &len), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_restore(r, blob, len), FRICREG_OK);
    same_factor(f, g);
    ck_assert_int_eq(g->spare_kept, f->spare_kept);
    struct fr_masked_factor fs = *f, gs = *g; /* their spares, as the current factors */
    fr_masked_factor_swap(&fs);
    fr_masked_factor_swap(&gs);
    same_factor(&fs, &gs);
    free(blob);
    fricreg_structure_free(s);
    fricreg_structure_free(r);
}
END_TEST

START_TEST(structure_steps_equal_in_both_storages)
{
    static double f[3][STEPS][NCON], u[3][STEPS][NDOF];
    const enum fr_block_storage storages[3] = {FR_BLOCK_SPARSE, FR_BLOCK_DENSE, FR_BLOCK_CHOSEN};
    int stuck[3], dense[3];
    for (int k = 0; k < 3; k++)
        membrane_run(storages[k], f[k], u[k], &stuck[k], &dense[k]);
    ck_assert(!dense[0] && dense[1]);
    ck_assert(dense[2]);                           /* the rule's choice on a stiff interface */
    ck_assert_int_gt(stuck[0], STEPS * NCON / 10); /* the near-stick blocks are exercised */
    double umax = 0.0;
    for (int step = 0; step < STEPS; step++)
        for (int a = 0; a < NDOF; a++)
            umax = fmax(umax, fabs(u[0][step][a]));
    double worst_f = 0.0, worst_u = 0.0;
    for (int k = 1; k < 3; k++)
        for (int step = 0; step < STEPS; step++) {
            for (int i = 0; i < NCON; i++)
                worst_f = fmax(worst_f,
                               fabs(f[k][step][i] - f[0][step][i]) / (i < SIDE ? 20.0 : 4.0));
            for (int a = 0; a < NDOF; a++)
                worst_u = fmax(worst_u, fabs(u[k][step][a] - u[0][step][a]) / umax);
        }
    printf("membrane %d x %d, %d contacts, %d steps: %d stuck contact-steps; dense against "
           "sparse: max |df| / mu N = %.2e, max |du| / max |u| = %.2e\n",
           SIDE, SIDE, NCON, STEPS, stuck[0], worst_f, worst_u);
    ck_assert_double_le(worst_f, 1e-10);
    ck_assert_double_le(worst_u, 1e-10);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("masked_factor");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, fill_rule_picks_the_storage);
    tcase_add_test(tc, dense_solves_equal_sparse_ones);
    tcase_add_test(tc, not_positive_definite_is_esingular_both_ways);
    tcase_add_test(tc, dense_factor_keeps_its_leading_rows);
    tcase_add_test(tc, dense_factor_deletes_rows_inside);
    tcase_add_test(tc, dense_factor_from_the_kept_complement);
    tcase_add_test(tc, dense_factor_deletes_many_rows_in_blocks);
    tcase_add_test(tc, dense_factor_kept_as_spare);
    tcase_add_test(tc, dense_fill_packed_equals_the_scan);
    tcase_add_test(tc, structure_steps_equal_in_both_storages);
    tcase_add_test(tc, checkpoint_carries_the_dense_block);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
