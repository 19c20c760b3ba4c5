/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_set_matrix.c — Check suite for the one setter of each model matrix,
 * fricreg_structure_set_matrix and fricreg_hb_set_matrix, and the harmonic-balance driver's
 * element setters under the structure's names (fricreg_hb_set_jenkins, _set_jenkins_normal).
 *
 * Where the numbers come from: the setters of one matrix in one storage (fricreg_structure.h,
 * fricreg_hb.h), each a case of the one setter: the same model in the same storage must give
 * the same run and the same harmonic-balance solution bit for bit. The refusals are the
 * headers' list. */
#include <check.h>
#include <stdint.h>
#include <string.h>

#include "fricreg_hb.h"
#include "fricreg_structure.h"
#include "hb_rod.h"

/* ---- A structure: three dofs, two contacts ------------------------------------------------ */

#define N 3
#define MC 2
#define DT 1e-2
#define T_END 1.5

static const double M[N * N] = {1.0, 0.1, 0.0, 0.1, 0.8, 0.07, 0.0, 0.07, 1.3};
static const double K[N * N] = {40.0, -15.0, 0.0, -15.0, 35.0, -20.0, 0.0, -20.0, 30.0};
static const double C[N * N] = {0.2, -0.05, 0.0, -0.05, 0.15, 0.0, 0.0, 0.0, 0.1};
static const double J[MC * N] = {1.0, 0.0, 0.0, 0.0, 1.0, -0.5};

/* A dense row-major nrows x ncols matrix's non-zero entries in compressed rows (by_columns 0)
 * or columns, zero- or one-based: ptr[] (room for max(nrows, ncols) + 1), ind[], val[]. */
static void compress(const double *A, size_t nrows, size_t ncols, int by_columns, int base,
                     int64_t *ptr, int64_t *ind, double *val)
{
    size_t outer = by_columns ? ncols : nrows, inner = by_columns ? nrows : ncols, nnz = 0;
    ptr[0] = base;
    for (size_t o = 0; o < outer; o++) {
        for (size_t k = 0; k < inner; k++) {
            double a = by_columns ? A[k * ncols + o] : A[o * ncols + k];
            if (a != 0.0) {
                ind[nnz] = (int64_t)k + base;
                val[nnz++] = a;
            }
        }
        ptr[o + 1] = (int64_t)nnz + base;
    }
}

static fricreg_structure *created(void)
{
    fricreg_structure *s = NULL;
    ck_assert_int_eq(fricreg_structure_create(N, MC, &s), FRICREG_OK);
    return s;
}

/* The rest of the set-up and the run to T_END; the state (u, v, a) and the forces into out. */
static void run(fricreg_structure *s, double out[3 * N + MC])
{
    const double mun[MC] = {0.35, 0.5}, p[N] = {1.1, -0.4, 0.7}, g[2] = {1.0, 1.0};
    ck_assert_int_eq(fricreg_structure_set_bounds(s, MC, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_law(s, FRICREG_LAW_QUINN, 2e-3), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_load(s, N, p, 0.0, 10.0, 2, g), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run(s, DT, T_END), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_state(s, N, out, out + N, out + 2 * N), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_forces(s, MC, out + 3 * N), FRICREG_OK);
}

static void assert_same_run(const double a[3 * N + MC], const double b[3 * N + MC])
{
    for (size_t k = 0; k < 3 * N + MC; k++)
        ck_assert_msg(memcmp(&a[k], &b[k], sizeof *a) == 0, "output %zu: %.17g, %.17g", k, a[k],
                      b[k]);
}

/* Each storage through the one setter equals its own setter: M dense, K by rows, C by
 * columns, J by rows; then M by one-based columns, K dense, C by rows, J by columns. */
START_TEST(structure_storages_equal_their_setters)
{
    int64_t p[4][N + 1], i[4][N * N];
    double x[4][N * N], ref[3 * N + MC], got[3 * N + MC];
    for (int variant = 0; variant < 2; variant++) {
        int cols = variant, base = variant; /* variant 1: CSC one-based where compressed */
        int flags = base ? FRICREG_SPARSE_ONE_BASED : 0;
        int format = (cols ? FRICREG_MATRIX_CSC : FRICREG_MATRIX_CSR) | flags;
        int other = (cols ? FRICREG_MATRIX_CSR : FRICREG_MATRIX_CSC) | flags;
        compress(M, N, N, cols, base, p[0], i[0], x[0]);
        compress(K, N, N, !cols, base, p[1], i[1], x[1]);
        compress(C, N, N, !cols, base, p[2], i[2], x[2]);
        compress(J, MC, N, cols, base, p[3], i[3], x[3]);

        fricreg_structure *s = created();
        if (variant == 0) {
            ck_assert_int_eq(fricreg_structure_set_mass(s, N, M), FRICREG_OK);
            ck_assert_int_eq(fricreg_structure_set_stiffness_csc(s, N, flags, p[1], i[1], x[1]),
                             FRICREG_OK);
            ck_assert_int_eq(fricreg_structure_set_damping_csc(s, N, flags, p[2], i[2], x[2]),
                             FRICREG_OK);
            ck_assert_int_eq(fricreg_structure_set_contacts_csr(s, MC, N, flags, p[3], i[3], x[3]),
                             FRICREG_OK);
        } else {
            ck_assert_int_eq(fricreg_structure_set_mass_csc(s, N, flags, p[0], i[0], x[0]),
                             FRICREG_OK);
            ck_assert_int_eq(fricreg_structure_set_stiffness(s, N, K), FRICREG_OK);
            ck_assert_int_eq(fricreg_structure_set_damping_csr(s, N, flags, p[2], i[2], x[2]),
                             FRICREG_OK);
            ck_assert_int_eq(fricreg_structure_set_contacts_csc(s, MC, N, flags, p[3], i[3], x[3]),
                             FRICREG_OK);
        }
        run(s, ref);
        fricreg_structure_free(s);

        s = created();
        int dense = FRICREG_MATRIX_DENSE;
        if (variant == 0)
            ck_assert_int_eq(fricreg_structure_set_matrix(s, FRICREG_MASS, N, N, dense, NULL, NULL,
                                                          M),
                             FRICREG_OK);
        else
            ck_assert_int_eq(fricreg_structure_set_matrix(s, FRICREG_MASS, N, N, format, p[0], i[0],
                                                          x[0]),
                             FRICREG_OK);
        if (variant == 0)
            ck_assert_int_eq(fricreg_structure_set_matrix(s, FRICREG_STIFFNESS, N, N, other, p[1],
                                                          i[1], x[1]),
                             FRICREG_OK);
        else
            ck_assert_int_eq(fricreg_structure_set_matrix(s, FRICREG_STIFFNESS, N, N, dense, NULL,
                                                          NULL, K),
                             FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_set_matrix(s, FRICREG_DAMPING, N, N, other, p[2], i[2],
                                                      x[2]),
                         FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_set_matrix(s, FRICREG_CONTACTS, MC, N, format, p[3],
                                                      i[3], x[3]),
                         FRICREG_OK);
        run(s, got);
        fricreg_structure_free(s);
        assert_same_run(ref, got);
    }
}
END_TEST

/* The status and the message's start of one refused call, which changes nothing. */
static void refused(fricreg_structure *s, int status, int got, const char *start)
{
    ck_assert_int_eq(got, status);
    ck_assert_msg(strncmp(fricreg_structure_errmsg(s), start, strlen(start)) == 0,
                  "\"%s\" does not start with \"%s\"", fricreg_structure_errmsg(s), start);
}

START_TEST(structure_refusals)
{
    int64_t p[N + 1], i[N * N];
    double x[N * N], ref[3 * N + MC], got[3 * N + MC];
    int dense = FRICREG_MATRIX_DENSE, csr = FRICREG_MATRIX_CSR;
    ck_assert_int_eq(fricreg_structure_set_matrix(NULL, FRICREG_MASS, N, N, dense, NULL, NULL, M),
                     FRICREG_ENULL);
    fricreg_structure *s = created();
    ck_assert_int_eq(fricreg_structure_set_matrix(s, FRICREG_MASS, N, N, dense, NULL, NULL, M),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_matrix(s, FRICREG_STIFFNESS, N, N, dense, NULL, NULL, K),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_matrix(s, FRICREG_CONTACTS, MC, N, dense, NULL, NULL, J),
                     FRICREG_OK);
    /* which, format */
    refused(s, FRICREG_EINVAL, fricreg_structure_set_matrix(s, 0, N, N, dense, NULL, NULL, C),
            "set_matrix: which = 0 is not a model matrix");
    refused(s, FRICREG_EINVAL,
            fricreg_structure_set_matrix(s, FRICREG_CONTACTS + 1, N, N, dense, NULL, NULL, C),
            "set_matrix: which = 5 is not a model matrix");
    compress(C, N, N, 0, 0, p, i, x);
    refused(s, FRICREG_EINVAL,
            fricreg_structure_set_matrix(s, FRICREG_DAMPING, N, N, csr | FRICREG_MATRIX_CSC, p, i,
                                         x),
            "set_matrix: format 24 is both CSR and CSC");
    refused(s, FRICREG_EINVAL,
            fricreg_structure_set_matrix(s, FRICREG_DAMPING, N, N, FRICREG_SPARSE_ONE_BASED, NULL,
                                         NULL, C),
            "set_matrix: a dense matrix takes no sparse flags");
    /* a dense matrix's ptr and ind are not read (Fortran cannot pass NULL) */
    ck_assert_int_eq(fricreg_structure_set_matrix(s, FRICREG_DAMPING, N, N, dense, p, i, C),
                     FRICREG_OK);
    refused(s, FRICREG_EINVAL,
            fricreg_structure_set_matrix(s, FRICREG_DAMPING, N, N, csr | 32, p, i, x),
            "set_matrix:");
    /* a triangle for J, which need not be symmetric */
    compress(J, MC, N, 0, 0, p, i, x);
    refused(s, FRICREG_EINVAL,
            fricreg_structure_set_matrix(s, FRICREG_CONTACTS, MC, N, csr | FRICREG_SPARSE_UPPER, p,
                                         i, x),
            "set_matrix:");
    /* sizes, NULLs */
    refused(s, FRICREG_ESIZE,
            fricreg_structure_set_matrix(s, FRICREG_CONTACTS, MC + 1, N, csr, p, i, x),
            "set_matrix: the matrix is 3 x 3, the structure needs 2 x 3");
    refused(s, FRICREG_ESIZE,
            fricreg_structure_set_matrix(s, FRICREG_CONTACTS, MC, N - 1, dense, NULL, NULL, J),
            "set_matrix: J is 2 x 2, the structure needs 2 x 3");
    refused(s, FRICREG_ESIZE,
            fricreg_structure_set_matrix(s, FRICREG_DAMPING, N, N - 1, dense, NULL, NULL, C),
            "set_matrix: ndof = 2, the structure has 3");
    refused(s, FRICREG_ENULL,
            fricreg_structure_set_matrix(s, FRICREG_DAMPING, N, N, dense, NULL, NULL, NULL),
            "set_matrix: the matrix is NULL");
    refused(s, FRICREG_ENULL,
            fricreg_structure_set_matrix(s, FRICREG_DAMPING, N, N, csr, NULL, i, x), "set_matrix:");
    /* what the matrix must be: M positive definite, K symmetric */
    double bad[N * N];
    memcpy(bad, M, sizeof bad);
    bad[0] = -1.0;
    refused(s, FRICREG_ENOTPSD,
            fricreg_structure_set_matrix(s, FRICREG_MASS, N, N, dense, NULL, NULL, bad),
            "set_matrix: the mass matrix is not positive definite");
    memcpy(bad, K, sizeof bad);
    bad[1] = 1.0;
    refused(s, FRICREG_ENOTSYM,
            fricreg_structure_set_matrix(s, FRICREG_STIFFNESS, N, N, dense, NULL, NULL, bad),
            "set_matrix:");
    /* nothing changed: the run is that of a structure never refused */
    ck_assert_int_eq(fricreg_structure_set_matrix(s, FRICREG_DAMPING, N, N, dense, NULL, NULL, C),
                     FRICREG_OK);
    run(s, got);
    fricreg_structure_free(s);
    s = created();
    ck_assert_int_eq(fricreg_structure_set_mass(s, N, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_stiffness(s, N, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_damping(s, N, C), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_contacts(s, MC, N, J), FRICREG_OK);
    run(s, ref);
    fricreg_structure_free(s);
    assert_same_run(ref, got);
}
END_TEST

/* ---- The harmonic-balance driver, on tests/support/hb_rod.h's rod ------------------------- */

#define ROD_N 16
#define H 3
#define NQ (HB_ROD_M * (2 * H + 1))

static fricreg_hb *rod_driver(void)
{
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(ROD_N, HB_ROD_M, H, &hb), FRICREG_OK);
    return hb;
}

static void solve(fricreg_hb *hb, double q[NQ])
{
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.35, NQ, NULL, q), FRICREG_OK);
}

static void assert_same_solution(const double a[NQ], const double b[NQ])
{
    for (size_t k = 0; k < NQ; k++)
        ck_assert_msg(memcmp(&a[k], &b[k], sizeof *a) == 0, "q[%zu]: %.17g, %.17g", k, a[k], b[k]);
}

/* M, C, K through the one setter in storage `format` (dense: hb_rod_dense), the elements by
 * set_jenkins, the excitation. */
static void set_rod(fricreg_hb *hb, const struct hb_rod *r, int format)
{
    static const int which[3] = {FRICREG_MASS, FRICREG_DAMPING, FRICREG_STIFFNESS};
    static int64_t p[ROD_N + 1], i[ROD_N * ROD_N];
    static double x[ROD_N * ROD_N];
    for (int w = 0; w < 3; w++) {
        if (format == FRICREG_MATRIX_DENSE) {
            hb_rod_dense(r, w, x);
            ck_assert_int_eq(fricreg_hb_set_matrix(hb, which[w], ROD_N, ROD_N, format, NULL, NULL,
                                                   x),
                             FRICREG_OK);
            continue;
        }
        hb_rod_csc(r, w, HB_ROD_FULL, 0, p, i, x); /* symmetric whole: CSR's arrays too */
        ck_assert_int_eq(fricreg_hb_set_matrix(hb, which[w], ROD_N, ROD_N, format, p, i, x),
                         FRICREG_OK);
    }
    ck_assert_int_eq(fricreg_hb_set_jenkins(hb, r->m, ROD_N, r->J, r->kt, r->mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, ROD_N, r->pc, r->ps), FRICREG_OK);
}

START_TEST(hb_storages_equal_their_setters)
{
    struct hb_rod r;
    ck_assert_int_eq(hb_rod_build(&r, ROD_N), 0);
    double ref[NQ], got[NQ];
    for (int dense = 0; dense <= 1; dense++) {
        fricreg_hb *hb = rod_driver();
        ck_assert_int_eq(hb_rod_set(hb, &r, dense, HB_ROD_FULL, 0), FRICREG_OK);
        solve(hb, ref);
        fricreg_hb_free(hb);
        int formats[2] = {FRICREG_MATRIX_CSC, FRICREG_MATRIX_CSR};
        for (int f = 0; f < (dense ? 1 : 2); f++) {
            hb = rod_driver();
            set_rod(hb, &r, dense ? FRICREG_MATRIX_DENSE : formats[f]);
            solve(hb, got);
            fricreg_hb_free(hb);
            assert_same_solution(ref, got);
        }
    }
    hb_rod_free(&r);
}
END_TEST

/* set_jenkins_normal is set_normal_elements: the same solution, here with kn = 0 (the normal
 * force N0, constant). */
START_TEST(hb_normal_elements_under_the_structures_name)
{
    struct hb_rod r;
    ck_assert_int_eq(hb_rod_build(&r, ROD_N), 0);
    double mu[HB_ROD_M], kn[HB_ROD_M] = {0.0}, ref[2 * NQ], got[2 * NQ];
    for (size_t k = 0; k < HB_ROD_M; k++)
        mu[k] = 1.0;
    for (int named = 0; named <= 1; named++) {
        fricreg_hb *hb = rod_driver();
        ck_assert_int_eq(hb_rod_set(hb, &r, 0, HB_ROD_FULL, 0), FRICREG_OK);
        int status = named ? fricreg_hb_set_jenkins_normal(hb, r.m, ROD_N, r.J, r.J, r.kt, mu,
                                                           r.mun, kn)
                           : fricreg_hb_set_normal_elements(hb, r.m, ROD_N, r.J, r.J, r.kt, mu,
                                                            r.mun, kn);
        ck_assert_int_eq(status, FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_solve(hb, 1.35, 2 * NQ, NULL, named ? got : ref), FRICREG_OK);
        if (named) {
            kn[0] = -1.0;
            ck_assert_int_eq(fricreg_hb_set_jenkins_normal(hb, r.m, ROD_N, r.J, r.J, r.kt, mu,
                                                           r.mun, kn),
                             FRICREG_EINVAL);
            ck_assert_msg(strncmp(fricreg_hb_errmsg(hb), "set_jenkins_normal: kt[0]", 25) == 0,
                          "%s", fricreg_hb_errmsg(hb));
        }
        fricreg_hb_free(hb);
    }
    for (size_t k = 0; k < 2 * NQ; k++)
        ck_assert_msg(memcmp(&ref[k], &got[k], sizeof *ref) == 0, "q[%zu]", k);
    hb_rod_free(&r);
}
END_TEST

START_TEST(hb_refusals)
{
    struct hb_rod r;
    ck_assert_int_eq(hb_rod_build(&r, ROD_N), 0);
    double A[ROD_N * ROD_N];
    hb_rod_dense(&r, 0, A);
    int dense = FRICREG_MATRIX_DENSE;
    ck_assert_int_eq(fricreg_hb_set_matrix(NULL, FRICREG_MASS, ROD_N, ROD_N, dense, NULL, NULL, A),
                     FRICREG_ENULL);
    fricreg_hb *hb = rod_driver();
    ck_assert_int_eq(fricreg_hb_set_matrix(hb, FRICREG_CONTACTS, ROD_N, ROD_N, dense, NULL, NULL,
                                           A),
                     FRICREG_EINVAL);
    ck_assert_str_eq(fricreg_hb_errmsg(hb),
                     "set_matrix: which = 4 is not a model matrix of the driver (FRICREG_MASS, "
                     "FRICREG_STIFFNESS or FRICREG_DAMPING)");
    ck_assert_int_eq(fricreg_hb_set_matrix(hb, FRICREG_MASS, ROD_N, ROD_N - 1, dense, NULL, NULL,
                                           A),
                     FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_hb_set_matrix(hb, FRICREG_MASS, ROD_N, ROD_N, FRICREG_SPARSE_UPPER,
                                           NULL, NULL, A),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_set_matrix(hb, FRICREG_MASS, ROD_N, ROD_N,
                                           FRICREG_MATRIX_CSR | FRICREG_MATRIX_CSC, NULL, NULL, A),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_set_matrix(hb, FRICREG_MASS, ROD_N, ROD_N, FRICREG_MATRIX_CSC, NULL,
                                           NULL, A),
                     FRICREG_ENULL);
    double kt[HB_ROD_M] = {1.0, -1.0, 1.0};
    ck_assert_int_eq(fricreg_hb_set_jenkins(hb, r.m, ROD_N, r.J, kt, r.mun), FRICREG_EINVAL);
    ck_assert_msg(strncmp(fricreg_hb_errmsg(hb), "set_jenkins: kt[1]", 18) == 0, "%s",
                  fricreg_hb_errmsg(hb));
    /* nothing changed: the rod set now solves as one never refused */
    double ref[NQ], got[NQ];
    set_rod(hb, &r, FRICREG_MATRIX_DENSE);
    solve(hb, got);
    fricreg_hb_free(hb);
    hb = rod_driver();
    ck_assert_int_eq(hb_rod_set(hb, &r, 1, HB_ROD_FULL, 0), FRICREG_OK);
    solve(hb, ref);
    fricreg_hb_free(hb);
    assert_same_solution(ref, got);
    hb_rod_free(&r);
}
END_TEST

int main(void)
{
    Suite *suite = suite_create("set_matrix");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, structure_storages_equal_their_setters);
    tcase_add_test(tc, structure_refusals);
    tcase_add_test(tc, hb_storages_equal_their_setters);
    tcase_add_test(tc, hb_normal_elements_under_the_structures_name);
    tcase_add_test(tc, hb_refusals);
    suite_add_tcase(suite, tc);
    SRunner *sr = srunner_create(suite);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
