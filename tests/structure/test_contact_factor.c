/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_contact_factor.c — Check suite for the structure's factor with its contacts
 * (src/structure/contact_factor.h), white box on the static library:
 *   - D = Y^T Y is J A^-1 J^T: every 7th column (both rows of contacts), each entry against
 *     J x_j, x_j = A^-1 J^T e_j by the factor's two halves, to 1e-12 of sqrt(D_ii D_jj)
 *     (drop = 0: D exact);
 *   - D's rows that every contact shares (the top separators) go through BLAS: D equals
 *     CHOLMOD's sparse product Y^T Y on every entry to 1e-13 of sqrt(D_ii D_jj), full so
 *     stored packed, its BLAS products equal to fr_sym_mult's loops to 1e-13, and with W_eff's
 *     drop (2^-53) the same to 1e-15;
 *   - every allocation of a build that takes the shared rows through BLAS (a 32 x 32 grid, 64
 *     contacts) may fail: FRICREG_ENOMEM, the factor freed, no CHOLMOD allocation left;
 *   - project and lift are J A^-1 b and A^-1 (b + J^T g) through the halves;
 *   - forming Y leaves the factor as CHOLMOD made it: a supernodal factor stays supernodal
 *     (CHOLMOD's sparse right-hand-side solve converts the factor it is given to a simplicial
 *     one in place; Y is formed on a copy, so that the steps' solves keep the BLAS).
 * The matrix is a membrane's K_eff on a 150 x 150 grid, A = I + 0.25 L (L the grid's graph
 * Laplacian plus the identity), ordered by nested dissection (22 500 >= FR_CFACTOR_NESTED_FROM)
 * and supernodal, with contacts on the edge row against the ground and on the next row
 * against the edge. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <SuiteSparse_config.h>

#include "base/error.h"
#include "base/sparse_factor.h"
#include "base/sparse_ops.h"
#include "fricreg.h"
#include "structure/contact_factor.h"

#define SIDE 150
#define N (SIDE * SIDE)
#define M (2 * SIDE)

/* A's upper triangle on a side x side grid: column j holds the nodes above and left of it,
 * then itself. */
static cholmod_sparse *membrane(SuiteSparse_long side, cholmod_common *c)
{
    SuiteSparse_long n = side * side;
    cholmod_sparse *A = cholmod_l_allocate_sparse(n, n, 3 * n, 1, 1, 1, CHOLMOD_REAL, c);
    SuiteSparse_long *Ap = A->p, *Ai = A->i, q = 0;
    double *Ax = A->x;
    for (SuiteSparse_long j = 0; j < n; j++) {
        SuiteSparse_long r = j / side, col = j % side;
        double degree = (r > 0) + (r + 1 < side) + (col > 0) + (col + 1 < side);
        Ap[j] = q;
        if (r > 0) {
            Ai[q] = j - side;
            Ax[q++] = -0.25;
        }
        if (col > 0) {
            Ai[q] = j - 1;
            Ax[q++] = -0.25;
        }
        Ai[q] = j;
        Ax[q++] = 1.0 + 0.25 * (degree + 1.0);
    }
    Ap[n] = q;
    return A;
}

/* J^T (side^2 x 2 side): contact j < side on node j, contact side + c on node side + c against
 * node c. */
static cholmod_sparse *contacts(SuiteSparse_long side, cholmod_common *c)
{
    SuiteSparse_long m = 2 * side;
    cholmod_sparse *Jt = cholmod_l_allocate_sparse(side * side, m, 2 * m, 1, 1, 0, CHOLMOD_REAL, c);
    SuiteSparse_long *Jp = Jt->p, *Ji = Jt->i, q = 0;
    double *Jx = Jt->x;
    for (SuiteSparse_long j = 0; j < m; j++) {
        Jp[j] = q;
        if (j >= side) {
            Ji[q] = j - side;
            Jx[q++] = -1.0;
        }
        Ji[q] = j;
        Jx[q++] = 1.0;
    }
    Jp[m] = q;
    return Jt;
}

struct setup {
    cholmod_common c;
    cholmod_sparse *A, *Jt;
    struct fr_cfactor f;
    struct fr_error err;
};

static void set_up(struct setup *s)
{
    memset(s, 0, sizeof *s);
    ck_assert_int_eq(fr_cholmod_start(&s->c), FRICREG_OK);
    s->A = membrane(SIDE, &s->c);
    s->Jt = contacts(SIDE, &s->c);
    ck_assert_int_eq(fr_cfactor_build(&s->f, s->A, s->Jt, 0.0, &s->c, &s->err, "test", "A"),
                     FRICREG_OK);
}

static void tear_down(struct setup *s)
{
    fr_cfactor_free(&s->f, &s->c);
    cholmod_l_free_sparse(&s->A, &s->c);
    cholmod_l_free_sparse(&s->Jt, &s->c);
    fr_cholmod_finish(&s->c);
}

/* out[M] = J x[N]. */
static void times_j(const cholmod_sparse *Jt, const double x[], double out[])
{
    const SuiteSparse_long *Jp = Jt->p, *Ji = Jt->i;
    const double *Jx = Jt->x;
    for (size_t j = 0; j < M; j++) {
        out[j] = 0.0;
        for (SuiteSparse_long q = Jp[j]; q < Jp[j + 1]; q++)
            out[j] += Jx[q] * x[Ji[q]];
    }
}

/* x[N] += alpha J^T g[M]. */
static void add_jt(const cholmod_sparse *Jt, double alpha, const double g[], double x[])
{
    const SuiteSparse_long *Jp = Jt->p, *Ji = Jt->i;
    const double *Jx = Jt->x;
    for (size_t j = 0; j < M; j++)
        for (SuiteSparse_long q = Jp[j]; q < Jp[j + 1]; q++)
            x[Ji[q]] += alpha * Jx[q] * g[j];
}

static double d_entry(const cholmod_sparse *D, size_t i, size_t j)
{
    if (i > j) {
        size_t t = i;
        i = j;
        j = t;
    }
    const SuiteSparse_long *Dp = D->p, *Di = D->i;
    for (SuiteSparse_long q = Dp[j]; q < Dp[j + 1]; q++)
        if ((size_t)Di[q] == i)
            return ((const double *)D->x)[q];
    return 0.0;
}

START_TEST(compliance_is_j_a_inverse_jt)
{
    struct setup s;
    set_up(&s);
    static double b[N], x[N], col[M], diag[M];
    for (size_t j = 0; j < M; j++)
        diag[j] = d_entry(s.f.D, j, j);
    for (size_t j = 0; j < M; j += 7) {
        double e[M] = {0.0};
        e[j] = 1.0;
        memset(b, 0, sizeof b);
        add_jt(s.Jt, 1.0, e, b);
        fr_cfactor_solve(&s.f, b, x, &s.c);
        times_j(s.Jt, x, col);
        for (size_t i = 0; i < M; i++)
            ck_assert_msg(fabs(d_entry(s.f.D, i, j) - col[i]) <= 1e-12 * sqrt(diag[i] * diag[j]),
                          "D[%zu][%zu] = %.17g, J A^-1 J^T %.17g", i, j, d_entry(s.f.D, i, j),
                          col[i]);
    }
    tear_down(&s);
}
END_TEST

/* D against CHOLMOD's sparse product Y^T Y on every entry, and its products: the edge's
 * contacts share the top separators' rows of Y, which go through BLAS (contact_factor.c), and
 * D, full, is stored packed, its products by BLAS equal to fr_sym_mult's loops on the same
 * storage. With W_eff's drop (2^-53) the same D to that rounding. */
START_TEST(shared_rows_through_blas_equal_the_sparse_product)
{
    struct setup s;
    set_up(&s);
    ck_assert_uint_gt(s.f.shared_rows, 0);
    ck_assert(fr_delassus_packed(s.f.D));
    cholmod_sparse *Yt = cholmod_l_transpose(s.f.Y, 1, &s.c);
    cholmod_sparse *G = cholmod_l_ssmult(Yt, s.f.Y, 0, 1, 1, &s.c);
    ck_assert_ptr_nonnull(G);
    const SuiteSparse_long *Gp = G->p, *Gi = G->i;
    const double *Gx = G->x;
    static double diag[M];
    for (size_t j = 0; j < M; j++)
        diag[j] = d_entry(s.f.D, j, j);
    size_t entries = 0;
    for (size_t j = 0; j < M; j++)
        for (SuiteSparse_long q = Gp[j]; q < Gp[j + 1]; q++, entries++)
            ck_assert_double_eq_tol(d_entry(s.f.D, (size_t)Gi[q], j), Gx[q],
                                    1e-13 * sqrt(diag[Gi[q]] * diag[j]));
    ck_assert_uint_eq(entries, (size_t)M * M); /* G full: every entry of D checked */
    double g[M], blas[M], loops[M];
    for (size_t j = 0; j < M; j++) {
        g[j] = cos(0.9 * (double)j);
        blas[j] = NAN; /* beta = 0: not read */
        loops[j] = 0.0;
    }
    fr_delassus_mult(s.f.D, 2.0, g, 0.0, blas);
    fr_sym_mult(s.f.D, 2.0, g, 0.0, loops);
    for (size_t j = 0; j < M; j++)
        ck_assert_double_eq_tol(blas[j], loops[j], 1e-13 * (1.0 + fabs(loops[j])));
    fr_delassus_mult(s.f.D, -1.0, g, 0.5, blas);
    fr_sym_mult(s.f.D, -1.0, g, 0.5, loops);
    for (size_t j = 0; j < M; j++)
        ck_assert_double_eq_tol(blas[j], loops[j], 1e-13 * (1.0 + fabs(loops[j])));
    struct fr_cfactor dropped = {0};
    ck_assert_int_eq(fr_cfactor_build(&dropped, s.A, s.Jt, 0x1p-53, &s.c, &s.err, "test", "A"),
                     FRICREG_OK);
    for (size_t j = 0; j < M; j += 5)
        for (size_t i = 0; i <= j; i++)
            ck_assert_double_eq_tol(d_entry(dropped.D, i, j), d_entry(s.f.D, i, j),
                                    1e-15 * sqrt(diag[i] * diag[j]));
    fr_cfactor_free(&dropped, &s.c);
    cholmod_l_free_sparse(&Yt, &s.c);
    cholmod_l_free_sparse(&G, &s.c);
    tear_down(&s);
}
END_TEST

/* SuiteSparse's allocator (CHOLMOD's, and contact_factor.c's through cholmod_l_malloc), failing
 * once `allowed` allocations have been made (-1: never). */
static long allowed = -1;

static int allow(void)
{
    if (allowed == 0)
        return 0;
    if (allowed > 0)
        allowed--;
    return 1;
}
static void *failing_malloc(size_t n)
{
    return allow() ? malloc(n) : NULL;
}
static void *failing_calloc(size_t n, size_t size)
{
    return allow() ? calloc(n, size) : NULL;
}
static void *failing_realloc(void *p, size_t n)
{
    return allow() ? realloc(p, n) : NULL;
}

/* Every allocation of a build that takes the shared rows through BLAS (a 32 x 32 grid, 64
 * contacts), failed in turn: FRICREG_ENOMEM, the factor left freed, and none of CHOLMOD's
 * allocations outstanding but its common's workspace; then the build that succeeds. */
START_TEST(every_allocation_of_the_build_may_fail)
{
    cholmod_common c;
    ck_assert_int_eq(fr_cholmod_start(&c), FRICREG_OK);
    cholmod_sparse *A = membrane(32, &c), *Jt = contacts(32, &c);
    cholmod_l_free_work(&c); /* the common's workspace is not the build's: counted apart */
    long outstanding = (long)c.malloc_count;
    SuiteSparse_config.malloc_func = failing_malloc;
    SuiteSparse_config.calloc_func = failing_calloc;
    SuiteSparse_config.realloc_func = failing_realloc;
    struct fr_cfactor f = {0};
    struct fr_error err = {0};
    int status = FRICREG_ENOMEM;
    long k = 0;
    for (; status != FRICREG_OK; k++) {
        allowed = k;
        status = fr_cfactor_build(&f, A, Jt, 0x1p-53, &c, &err, "test", "A");
        allowed = -1;
        if (status != FRICREG_OK) {
            ck_assert_int_eq(status, FRICREG_ENOMEM);
            ck_assert_ptr_null(f.L);
            ck_assert_ptr_null(f.D);
            cholmod_l_free_work(&c);
            ck_assert_msg((long)c.malloc_count == outstanding,
                          "allocation %ld failed: %ld blocks outstanding, %ld before", k,
                          (long)c.malloc_count, outstanding);
        }
    }
    SuiteSparse_config.malloc_func = malloc;
    SuiteSparse_config.calloc_func = calloc;
    SuiteSparse_config.realloc_func = realloc;
    printf("every_allocation_of_the_build_may_fail: %ld allocations, %zu shared rows\n", k - 1,
           f.shared_rows);
    ck_assert_uint_gt(f.shared_rows, 0);
    ck_assert_int_gt(k, 20);
    fr_cfactor_free(&f, &c);
    cholmod_l_free_work(&c);
    ck_assert_int_eq((long)c.malloc_count, outstanding);
    cholmod_l_free_sparse(&A, &c);
    cholmod_l_free_sparse(&Jt, &c);
    fr_cholmod_finish(&c);
}
END_TEST

START_TEST(project_and_lift_through_the_halves)
{
    struct setup s;
    set_up(&s);
    static double b[N], y[N], x[N], ref[N];
    double g[M], out[M], want[M];
    for (size_t k = 0; k < N; k++)
        b[k] = sin(0.37 * (double)k) + 0.1;
    for (size_t j = 0; j < M; j++)
        g[j] = cos(1.3 * (double)j);
    fr_cfactor_solve(&s.f, b, ref, &s.c); /* J A^-1 b */
    times_j(s.Jt, ref, want);
    fr_cfactor_forward(&s.f, b, y, &s.c);
    fr_cfactor_project(&s.f, y, out, &s.c);
    for (size_t j = 0; j < M; j++)
        ck_assert_double_eq_tol(out[j], want[j], 1e-12 * (1.0 + fabs(want[j])));
    memcpy(x, b, sizeof x); /* A^-1 (b + J^T g) */
    add_jt(s.Jt, 1.0, g, x);
    fr_cfactor_solve(&s.f, x, ref, &s.c);
    fr_cfactor_lift(&s.f, 1.0, g, y, &s.c);
    fr_cfactor_backward(&s.f, y, x, &s.c);
    for (size_t k = 0; k < N; k++)
        ck_assert_double_eq_tol(x[k], ref[k], 1e-12 * (1.0 + fabs(ref[k])));
    tear_down(&s);
}
END_TEST

START_TEST(forming_y_keeps_the_factor_supernodal)
{
    struct setup s;
    set_up(&s);
    fr_cholmod_ordering(&s.c, CHOLMOD_NESDIS, 0); /* the build's analysis, done again */
    cholmod_factor *L = cholmod_l_analyze(s.A, &s.c);
    ck_assert_ptr_nonnull(L);
    ck_assert_msg(L->is_super, "CHOLMOD chose a simplicial factor: the grid is too small here");
    ck_assert_int_eq(s.f.L->is_super, 1);
    cholmod_l_free_factor(&L, &s.c);
    tear_down(&s);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("contact_factor");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, compliance_is_j_a_inverse_jt);
    tcase_add_test(tc, shared_rows_through_blas_equal_the_sparse_product);
    tcase_add_test(tc, every_allocation_of_the_build_may_fail);
    tcase_add_test(tc, project_and_lift_through_the_halves);
    tcase_add_test(tc, forming_y_keeps_the_factor_supernodal);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
