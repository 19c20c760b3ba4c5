/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_sparse.c — Check suite for the harmonic-balance driver's sparse model (fricreg_hb.h:
 * the _csc setters, KLU's factors), on the rod of tests/support/hb_rod.h.
 *
 * Where the numbers come from: the dense path (GSL's complex LU, tested against closed forms
 * and time integration in test_hb.c) on the same model. The two factorizations differ in
 * their pivots and rounding only: the condensed solution q and the displacements agree to
 * 1e-12 relative (of their largest entry) on a 16-dof rod, and to 1e-10 on 200 dofs, where
 * the condition of D_h grows with n² (the rod's stiffness against its mass). */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_hb.h"
#include "hb_rod.h"

#define H 5
#define NC (2 * H + 1)
#define NQ (HB_ROD_M * NC)

static const double OMEGA = 1.35; /* near the rod's first resonance */

/* The largest |a_k − b_k| over the largest |b_k|. */
static double rel_diff(size_t count, const double *a, const double *b)
{
    double d = 0.0, s = 0.0;
    for (size_t k = 0; k < count; k++) {
        d = fmax(d, fabs(a[k] - b[k]));
        s = fmax(s, fabs(b[k]));
    }
    return d / s;
}

/* Solves the rod at OMEGA (the model set dense or in form), q[NQ] and x[n NC]. */
static fricreg_hb *solved(const struct hb_rod *r, int dense, enum hb_rod_form form, int one_based,
                          int harmonics, double *q, double *x)
{
    fricreg_hb *hb = NULL;
    size_t nc = 2 * (size_t)harmonics + 1;
    ck_assert_int_eq(fricreg_hb_create(r->n, r->m, harmonics, &hb), FRICREG_OK);
    ck_assert_int_eq(hb_rod_set(hb, r, dense, form, one_based), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(hb, OMEGA, r->m * nc, NULL, q), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_displacement(hb, r->n, nc, x), FRICREG_OK);
    return hb;
}

START_TEST(dense_and_sparse_forms_agree)
{
    struct hb_rod r;
    ck_assert_int_eq(hb_rod_build(&r, 16), 0);
    double qd[NQ], xd[16 * NC], q[NQ], x[16 * NC];
    fricreg_hb_free(solved(&r, 1, HB_ROD_FULL, 0, H, qd, xd));
    /* the elements slip: a nonlinear solution, not the stuck linear one */
    for (int one_based = 0; one_based <= 1; one_based++)
        for (int form = HB_ROD_FULL; form <= HB_ROD_LOWER; form++) {
            fricreg_hb_free(solved(&r, 0, (enum hb_rod_form)form, one_based, H, q, x));
            ck_assert_double_le(rel_diff(NQ, q, qd), 1e-12);
            ck_assert_double_le(rel_diff(16 * NC, x, xd), 1e-12);
        }
    /* a dense model turned sparse by one _csc setter (its other matrices converted), then a
     * dense setter on the sparse model (converted to it); Rayleigh damping on the sparse M, K */
    double *A = malloc(16 * 16 * sizeof *A);
    int64_t p[17], i[5 * 16];
    double v[5 * 16];
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(16, HB_ROD_M, H, &hb), FRICREG_OK);
    ck_assert_int_eq(hb_rod_set(hb, &r, 1, HB_ROD_FULL, 0), FRICREG_OK);
    hb_rod_csc(&r, 2, HB_ROD_UPPER, 0, p, i, v);
    ck_assert_int_eq(fricreg_hb_set_stiffness_csc(hb, 16, FRICREG_SPARSE_UPPER, p, i, v),
                     FRICREG_OK);
    hb_rod_dense(&r, 0, A);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 16, A), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(hb, OMEGA, NQ, NULL, q), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_displacement(hb, 16, NC, x), FRICREG_OK);
    ck_assert_double_le(rel_diff(NQ, q, qd), 1e-12);
    ck_assert_double_le(rel_diff(16 * NC, x, xd), 1e-12);
    ck_assert_int_eq(fricreg_hb_set_rayleigh(hb, 0.05, 0.005), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(hb, OMEGA, NQ, NULL, q), FRICREG_OK);
    fricreg_hb *hd = NULL;
    ck_assert_int_eq(fricreg_hb_create(16, HB_ROD_M, H, &hd), FRICREG_OK);
    ck_assert_int_eq(hb_rod_set(hd, &r, 1, HB_ROD_FULL, 0), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_rayleigh(hd, 0.05, 0.005), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(hd, OMEGA, NQ, NULL, qd), FRICREG_OK);
    ck_assert_double_le(rel_diff(NQ, q, qd), 1e-12);
    fricreg_hb_free(hd);
    fricreg_hb_free(hb);
    free(A);
    hb_rod_free(&r);
}
END_TEST

/* One point solve on 200 dofs, dense against sparse, at H = 7; then a continuation over the
 * resonance on the sparse path, whose points agree with the dense path's at the same step
 * control. */
START_TEST(two_hundred_dofs)
{
    enum { N = 200, H7 = 7, NC7 = 2 * H7 + 1 };
    struct hb_rod r;
    ck_assert_int_eq(hb_rod_build(&r, N), 0);
    double qd[HB_ROD_M * NC7], q[HB_ROD_M * NC7];
    double *xd = malloc(N * NC7 * sizeof *xd), *x = malloc(N * NC7 * sizeof *x);
    fricreg_hb *hd = solved(&r, 1, HB_ROD_FULL, 0, H7, qd, xd);
    fricreg_hb *hs = solved(&r, 0, HB_ROD_LOWER, 1, H7, q, x);
    ck_assert_double_le(rel_diff(HB_ROD_M * NC7, q, qd), 1e-10);
    ck_assert_double_le(rel_diff(N * NC7, x, xd), 1e-10);
    fricreg_hb *both[2] = {hd, hs};
    for (int k = 0; k < 2; k++) {
        ck_assert_int_eq(fricreg_hb_set_continuation(both[k], 0.05, 1e-6, 0.1, 2000), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_continue(both[k], 1.1, 1.6, HB_ROD_M * NC7, NULL), FRICREG_OK);
    }
    size_t np = fricreg_hb_points(hd);
    ck_assert_uint_ge(np, 10);
    ck_assert_uint_eq(fricreg_hb_points(hs), np);
    for (size_t k = 0; k < np; k += np / 7) {
        double od, os, *rd = xd, *rs = x;
        ck_assert_int_eq(fricreg_hb_point(hd, k, &od, N, rd), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_point(hs, k, &os, N, rs), FRICREG_OK);
        ck_assert_double_le(fabs(os - od), 1e-9 * od);
        ck_assert_double_le(rel_diff(N, rs, rd), 1e-9);
    }
    fricreg_hb_free(hd);
    fricreg_hb_free(hs);
    free(xd);
    free(x);
    hb_rod_free(&r);
}
END_TEST

/* The model: 10^4 dofs, three elements, H = 7, the frequency response over the top of
 * the first resonance by continuation (beyond the dense driver's 4096 dofs: sparse only; the
 * whole 1.1 to 1.6 rad/s is bench/hb_sparse.c's). The solves' forward error grows with the
 * condition of D_h, here n² (about 3e-8 of q at 10^4 dofs, against 1e-11 at 200), above the
 * default tolerance 1e-10: the corrector stops where it stalls at that rounding (until 1.9 it
 * did not converge, and the test set 1e-7). The peak lies within 1% of the 200-dof rod's (the
 * discretization has converged). */
START_TEST(ten_thousand_dofs)
{
    enum { N = 10000, H7 = 7, NC7 = 2 * H7 + 1 };
    struct hb_rod r;
    ck_assert_int_eq(hb_rod_build(&r, N), 0);
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(N, HB_ROD_M, H7, &hb), FRICREG_OK);
    /* the dense setters refuse nothing here: they convert to the sparse model */
    ck_assert_int_eq(hb_rod_set(hb, &r, 0, HB_ROD_UPPER, 0), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_continuation(hb, 0.1, 1e-6, 0.1, 2000), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_continue(hb, 1.28, 1.37, HB_ROD_M * NC7, NULL), FRICREG_OK);
    size_t np = fricreg_hb_points(hb);
    ck_assert_uint_ge(np, 5);
    double omega, *rms = malloc(N * sizeof *rms), peak = 0.0;
    for (size_t k = 0; k < np; k++) {
        ck_assert_int_eq(fricreg_hb_point(hb, k, &omega, N, rms), FRICREG_OK);
        peak = fmax(peak, rms[N - 1]);
    }
    ck_assert_double_eq(omega, 1.37);
    ck_assert_double_le(fabs(peak - 1.3447569), 0.01 * 1.3447569); /* the 200-dof rod's peak */
    double *x = malloc(N * NC7 * sizeof *x);
    ck_assert_int_eq(fricreg_hb_displacement(hb, N, NC7, x), FRICREG_OK);
    free(x);
    free(rms);
    fricreg_hb_free(hb);
    hb_rod_free(&r);
}
END_TEST

/* A tolerance below the solves' rounding: at 1e-14 on the 200-dof rod (their forward error
 * about 1e-11 of q) the corrector stalls at every point, and stops there
 * (fricreg_hb_set_newton): the continuation over the resonance completes, on the sparse path
 * and on the dense one, and its points are those a solve at their frequency gives at 1e-10
 * (no rounding floor at a fixed Ω, where the factors do not change) to 1e-9. Until 1.9 it
 * failed ("did not converge"). */
START_TEST(tolerance_below_rounding)
{
    enum { N = 200, H7 = 7, NC7 = 2 * H7 + 1 };
    struct hb_rod r;
    ck_assert_int_eq(hb_rod_build(&r, N), 0);
    double q[HB_ROD_M * NC7], *x = malloc(N * NC7 * sizeof *x),
                              *ref = malloc(N * NC7 * sizeof *ref);
    for (int dense = 0; dense <= 1; dense++) {
        fricreg_hb *hb = NULL, *at = NULL;
        ck_assert_int_eq(fricreg_hb_create(N, HB_ROD_M, H7, &hb), FRICREG_OK);
        ck_assert_int_eq(hb_rod_set(hb, &r, dense, HB_ROD_LOWER, 0), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_set_newton(hb, 1e-14, 50), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_set_continuation(hb, 0.05, 1e-6, 0.1, 2000), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_continue(hb, 1.1, 1.6, HB_ROD_M * NC7, NULL), FRICREG_OK);
        size_t np = fricreg_hb_points(hb);
        ck_assert_uint_ge(np, 10);
        ck_assert_int_eq(fricreg_hb_create(N, HB_ROD_M, H7, &at), FRICREG_OK);
        ck_assert_int_eq(hb_rod_set(at, &r, dense, HB_ROD_LOWER, 0), FRICREG_OK);
        for (size_t k = 0; k < np; k += np / 7) {
            double omega;
            ck_assert_int_eq(fricreg_hb_point(hb, k, &omega, N, ref), FRICREG_OK); /* its Ω */
            ck_assert_int_eq(fricreg_hb_point_displacement(hb, k, N, NC7, x), FRICREG_OK);
            ck_assert_int_eq(fricreg_hb_solve(at, omega, HB_ROD_M * NC7, NULL, q), FRICREG_OK);
            ck_assert_int_eq(fricreg_hb_displacement(at, N, NC7, ref), FRICREG_OK);
            ck_assert_double_le(rel_diff(N * NC7, x, ref), 1e-9);
        }
        fricreg_hb_free(at);
        fricreg_hb_free(hb);
    }
    free(x);
    free(ref);
    hb_rod_free(&r);
}
END_TEST

/* Each documented error of the _csc setters, with its message, and the model untouched: the
 * solution after the failures is the one before. */
START_TEST(bad_csc_input)
{
    struct hb_rod r;
    ck_assert_int_eq(hb_rod_build(&r, 16), 0);
    double q0[NQ], x0[16 * NC], q[NQ];
    fricreg_hb *hb = solved(&r, 0, HB_ROD_FULL, 0, H, q0, x0);
    int64_t p[17], i[5 * 16];
    double v[5 * 16];
    hb_rod_csc(&r, 0, HB_ROD_UPPER, 0, p, i, v);
    const int U = FRICREG_SPARSE_UPPER;
    ck_assert_int_eq(fricreg_hb_set_mass_csc(NULL, 16, U, p, i, v), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_set_mass_csc(hb, 16, U, NULL, i, v), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_set_stiffness_csc(hb, 16, U, p, NULL, v), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_set_damping_csc(hb, 16, U, p, i, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_set_mass_csc(hb, 15, U, p, i, v), FRICREG_ESIZE);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "set_mass_csc"));
    ck_assert_int_eq(fricreg_hb_set_mass_csc(hb, 16, 8, p, i, v), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_set_mass_csc(hb, 16, U | FRICREG_SPARSE_LOWER, p, i, v),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_set_mass_csc(hb, 16, U | FRICREG_SPARSE_ONE_BASED, p, i, v),
                     FRICREG_EINVAL); /* colptr[0] = 0, not the base 1 */
    int64_t keep = i[3];
    i[3] = 16; /* row out of range */
    ck_assert_int_eq(fricreg_hb_set_stiffness_csc(hb, 16, U, p, i, v), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "set_stiffness_csc"));
    i[3] = keep;
    ck_assert_int_eq(fricreg_hb_set_mass_csc(hb, 16, FRICREG_SPARSE_LOWER, p, i, v),
                     FRICREG_EINVAL); /* upper entries given as the lower triangle */
    int64_t pk = p[5];
    p[5] = p[4] - 1; /* colptr decreasing */
    ck_assert_int_eq(fricreg_hb_set_damping_csc(hb, 16, U, p, i, v), FRICREG_EINVAL);
    p[5] = pk;
    double vk = v[2];
    v[2] = NAN;
    ck_assert_int_eq(fricreg_hb_set_damping_csc(hb, 16, U, p, i, v), FRICREG_ENONFINITE);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "set_damping_csc"));
    v[2] = vk;
    /* whole but not symmetric: the whole K with one off-diagonal entry changed */
    hb_rod_csc(&r, 2, HB_ROD_FULL, 0, p, i, v);
    v[3] *= 1.5;
    ck_assert_int_eq(fricreg_hb_set_stiffness_csc(hb, 16, 0, p, i, v), FRICREG_ENOTSYM);
    ck_assert_int_eq(fricreg_hb_errcode(hb), FRICREG_ENOTSYM);
    ck_assert_int_eq(fricreg_hb_solve(hb, OMEGA, NQ, NULL, q), FRICREG_OK);
    ck_assert_double_eq(rel_diff(NQ, q, q0), 0.0);
    /* a singular sparse K (no stiffness at all) at the static term */
    int64_t pz[17] = {0};
    ck_assert_int_eq(fricreg_hb_set_stiffness_csc(hb, 16, 0, pz, NULL, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(hb, OMEGA, NQ, NULL, q), FRICREG_ESINGULAR);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "KLU"));
    fricreg_hb_free(hb);
    hb_rod_free(&r);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("hb_sparse");
    TCase *tc = tcase_create("hb_sparse");
    TCase *branches = tcase_create("branches"); /* dense against sparse: 80 % of the time */
    /* 3 s: the release tier's (hb_sparse_release); the sparse paths run at 10^4 dofs */
    tcase_set_tags(branches, "release");
    tcase_add_test(tc, dense_and_sparse_forms_agree);
    tcase_add_test(branches, two_hundred_dofs);
    tcase_add_test(branches, tolerance_below_rounding);
    tcase_add_test(tc, ten_thousand_dofs);
    tcase_add_test(tc, bad_csc_input);
    suite_add_tcase(s, tc);
    suite_add_tcase(s, branches);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
