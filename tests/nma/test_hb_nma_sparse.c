/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_nma_sparse.c — Check suite for the nonlinear modes' linear mode on a sparse model
 * (fricreg_hb_nma; src/nma/nma_sparse_mode.c: shift-invert subspace iteration on CHOLMOD's
 * factor of K_0 = K + J^T diag(k) J).
 *
 * (a) The membrane of NX x NY = 100 x 50 = 5000 unit masses on unit springs to their four
 * neighbours (the edge masses' to fixed walls) and a ground spring S = 0.01 under each has the
 * modes ω² = S + 4 sin²(iπ/(2(NX+1))) + 4 sin²(jπ/(2(NY+1))), i, j = 1, 2, … (the 2-D second
 * difference's eigenvalues, sines in each direction: G. Strang, Computational Science and
 * Engineering, 2007, Sec. 3.5); mode 0 is (1, 1), mode 1 (2, 1), mode 2 (3, 1). Here the
 * centre's ground spring is the Jenkins element (J = e_c, kt = S): K alone lacks it, and
 * K_0 = K + kt e_c e_c^T is the membrane above. Below the first slip the backbone is that linear
 * mode exactly (fricreg_hb_nma's docstring), so its points have ω = ω_k; with mass-proportional
 * damping C = a0 M the EPMC's ξ is a0 exactly (C − ξ M = 0), ζ = a0/(2ω). n = 5000 is above the
 * dense eigensolver's 4096. Why not the 1-D chain: an element at its end (where a chain's K_0
 * keeps a closed form) sits near a node of the low modes, |J φ| ~ n^-1.5, and D_1 = K_0 −
 * ω_k² M − kt J^T J then has a condition number ~1e11: the EPMC's Newton (not the linear mode:
 * it was 1.4e-12 off) moves ω by 1e-10 there. The centre of the membrane is an antinode of
 * modes 0 and 2.
 *
 * (b) The sparse path against the dense one (nma_eigen.c on the densified model, exact to
 * rounding) on the same chain of 200 dofs with varied masses, springs and dashpots (C not
 * proportional, so ζ depends on φ itself) and two Jenkins elements: every backbone point's ω
 * and ζ, stuck and slipping, to 1e-10.
 *
 * (c) A sparse M that is not positive definite (indefinite; a zero mass; a pivot below 1e-14)
 * gives FRICREG_ENOTPSD; a K_0 that is singular gives FRICREG_EINVAL. */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "fricreg_hb.h"

static const double pi = 3.14159265358979323846;

/* A symmetric tridiagonal matrix (diagonal d[n], off-diagonal e[n-1]) as its upper triangle's
 * compressed columns into hb: which 0 M, 1 C, 2 K. */
static void set_tridiagonal(fricreg_hb *hb, int which, size_t n, const double *d, const double *e)
{
    int64_t *p = malloc((n + 1) * sizeof *p), *i = malloc(2 * n * sizeof *i);
    double *v = malloc(2 * n * sizeof *v);
    ck_assert(p && i && v);
    size_t k = 0;
    for (size_t j = 0; j < n; j++) {
        p[j] = (int64_t)k;
        if (j > 0 && e != NULL) {
            i[k] = (int64_t)j - 1;
            v[k++] = e[j - 1];
        }
        i[k] = (int64_t)j;
        v[k++] = d[j];
    }
    p[n] = (int64_t)k;
    const int up = FRICREG_SPARSE_UPPER;
    int status = which == 0   ? fricreg_hb_set_mass_csc(hb, n, up, p, i, v)
                 : which == 1 ? fricreg_hb_set_damping_csc(hb, n, up, p, i, v)
                              : fricreg_hb_set_stiffness_csc(hb, n, up, p, i, v);
    ck_assert_int_eq(status, FRICREG_OK);
    free(p);
    free(i);
    free(v);
}

/* (a)'s membrane: NX x NY unit masses, unit springs to the 4 neighbours (the edges' to the
 * walls), dof i + NX j; the spring from dof 0 to the left wall is the element. */
#define NX 100
#define NY 50
#define S 0.01
#define CENTRE (50 + NX * 25)
static fricreg_hb *membrane(double a0)
{
    const size_t n = NX * NY;
    int64_t *p = malloc((n + 1) * sizeof *p), *i = malloc(3 * n * sizeof *i),
            *pd = malloc((n + 1) * sizeof *pd);
    double *v = malloc(3 * n * sizeof *v), *ones = malloc(n * sizeof *ones),
           *J = calloc(n, sizeof *J);
    ck_assert(p && i && pd && v && ones && J);
    size_t k = 0;
    for (size_t d = 0; d < n; d++) {
        p[d] = (int64_t)k;
        pd[d] = (int64_t)d;
        ones[d] = 1.0;
        if (d >= NX) { /* the neighbour below */
            i[k] = (int64_t)(d - NX);
            v[k++] = -1.0;
        }
        if (d % NX > 0) { /* the neighbour to the left */
            i[k] = (int64_t)d - 1;
            v[k++] = -1.0;
        }
        i[k] = (int64_t)d;
        v[k++] = d == CENTRE ? 4.0 : 4.0 + S; /* the centre's ground spring is the element */
    }
    p[n] = (int64_t)k;
    pd[n] = (int64_t)n;
    J[CENTRE] = 1.0;
    const double kt = S, mun = 1.0;
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(n, 1, 1, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass_csc(hb, n, FRICREG_SPARSE_UPPER, pd, pd, ones),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness_csc(hb, n, FRICREG_SPARSE_UPPER, p, i, v),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_rayleigh(hb, a0, 0.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, n, J, &kt, &mun), FRICREG_OK);
    free(p);
    free(i);
    free(pd);
    free(v);
    free(ones);
    free(J);
    return hb;
}

/* (a) modes 0 and 2, (1, 1) and (3, 1), to 1e-10 of ω and ζ. */
START_TEST(membrane_closed_form)
{
    const double a0 = 0.0123; /* Rayleigh's mass-proportional factor, 1/s */
    fricreg_hb *hb = membrane(a0);
    const int waves[2][2] = {{1, 1}, {3, 1}}; /* mode 0; mode 2 (mode 1 is (2, 1)) */
    const size_t modes[2] = {0, 2};
    for (int c = 0; c < 2; c++) {
        /* stuck: |J φ| = |φ_0| <= 2/sqrt((NX+1)(NY+1)) = 0.028, so the first slip is above
         * mun/kt / 0.028 = 35; both points are far below it */
        ck_assert_int_eq(fricreg_hb_nma(hb, modes[c], FRICREG_HB_NMA_DAMPING_MATRIX, 0.1, 0.2, 2),
                         FRICREG_OK);
        double sx = sin(waves[c][0] * pi / (2.0 * (NX + 1))),
               sy = sin(waves[c][1] * pi / (2.0 * (NY + 1)));
        double omega = sqrt(S + 4.0 * (sx * sx + sy * sy)), a, w, z;
        for (size_t i = 0; i < 2; i++) {
            ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &a, &w, &z, 0, 0, NULL), FRICREG_OK);
            ck_assert_double_eq_tol(w, omega, 1e-10 * omega);
            ck_assert_double_eq_tol(z, a0 / (2.0 * omega), 1e-10 * a0 / (2.0 * omega));
        }
    }
    fricreg_hb_free(hb);
}
END_TEST

/* (b)'s model: masses 1 + 0.3 sin i, springs 2.385 + 0.5 cos 1.7i (n + 1 of them, fixed–fixed),
 * dashpots 0.01 (1 + 0.5 sin 0.9i) beside them; element 0 across springs 50–51, element 1 from
 * dof 150 to the ground. Dense (row-major n x n) or sparse. */
#define NB 200
static fricreg_hb *varied_chain(int sparse)
{
    static double M[NB * NB], C[NB * NB], K[NB * NB]; /* the test's own data, one thread */
    double dm[NB], dk[NB], ek[NB], dc[NB], ec[NB], J[2 * NB] = {0};
    for (size_t i = 0; i < NB; i++) {
        double ki = 2.385 + 0.5 * cos(1.7 * i), kn = 2.385 + 0.5 * cos(1.7 * (i + 1));
        double ci = 0.01 * (1 + 0.5 * sin(0.9 * i)), cn = 0.01 * (1 + 0.5 * sin(0.9 * (i + 1)));
        dm[i] = 1.0 + 0.3 * sin((double)i);
        dk[i] = ki + kn;
        ek[i] = -kn;
        dc[i] = ci + cn;
        ec[i] = -cn;
    }
    J[50] = 1.0;
    J[51] = -1.0;
    J[NB + 150] = 1.0;
    const double kt[2] = {0.8, 1.3}, mun[2] = {0.05, 0.07};
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(NB, 2, 1, &hb), FRICREG_OK);
    if (sparse) {
        set_tridiagonal(hb, 0, NB, dm, NULL);
        set_tridiagonal(hb, 1, NB, dc, ec);
        set_tridiagonal(hb, 2, NB, dk, ek);
    } else {
        for (size_t i = 0; i < NB * NB; i++)
            M[i] = C[i] = K[i] = 0.0;
        for (size_t i = 0; i < NB; i++) {
            M[i * NB + i] = dm[i];
            C[i * NB + i] = dc[i];
            K[i * NB + i] = dk[i];
            if (i + 1 < NB) {
                C[i * NB + i + 1] = C[(i + 1) * NB + i] = ec[i];
                K[i * NB + i + 1] = K[(i + 1) * NB + i] = ek[i];
            }
        }
        ck_assert_int_eq(fricreg_hb_set_mass(hb, NB, M), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_set_damping(hb, NB, C), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_set_stiffness(hb, NB, K), FRICREG_OK);
    }
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 2, NB, J, kt, mun), FRICREG_OK);
    return hb;
}

/* (b) mode 1, H = 1, 6 points from stuck (a = 0.01) into slip (a = 7: ζ 40 times the stuck
 * one), both damping options. */
START_TEST(sparse_against_dense)
{
    fricreg_hb *dense = varied_chain(0), *sparse = varied_chain(1);
    const size_t np = 6;
    for (int damping = 0; damping < 2; damping++) {
        ck_assert_int_eq(fricreg_hb_nma(dense, 1, damping, 0.01, 7.0, np), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_nma(sparse, 1, damping, 0.01, 7.0, np), FRICREG_OK);
        double z0 = 0.0, z1 = 0.0;
        for (size_t i = 0; i < np; i++) {
            double ad, wd, zd, as, ws, zs;
            ck_assert_int_eq(fricreg_hb_nma_point(dense, i, &ad, &wd, &zd, 0, 0, NULL), FRICREG_OK);
            ck_assert_int_eq(fricreg_hb_nma_point(sparse, i, &as, &ws, &zs, 0, 0, NULL),
                             FRICREG_OK);
            ck_assert_double_eq(ad, as);
            ck_assert_double_eq_tol(ws, wd, 1e-10 * wd);
            ck_assert_double_eq_tol(zs, zd, 1e-10 * zd);
            if (i == 0)
                z0 = zd;
            z1 = zd;
        }
        ck_assert(z1 > 10.0 * z0); /* the last point slips: friction adds to ζ */
    }
    fricreg_hb_free(dense);
    fricreg_hb_free(sparse);
}
END_TEST

/* The stuck mode's shape as reported: under modal damping the first point, below the first slip,
 * is x = a φ_k cos ωt exactly, so its cosine coefficients X_1 = a φ_k have X_1^T M X_1 = a²
 * (φ_k mass-normalized) and their largest entry positive (the sign convention), on both paths
 * and modes 0 to 7 (the sign GSL's or the subspace iteration's vector comes with varies among
 * them). A φ_k flipped only up to its largest entry broke both (checked: this test fails on
 * that code). */
START_TEST(mode_shape_normalized)
{
    double x[NB * 3], a, w, z, dm[NB];
    for (size_t i = 0; i < NB; i++)
        dm[i] = 1.0 + 0.3 * sin((double)i);
    for (int sparse = 0; sparse < 2; sparse++) {
        fricreg_hb *hb = varied_chain(sparse);
        for (size_t k = 0; k < 8; k++) {
            ck_assert_int_eq(fricreg_hb_nma(hb, k, FRICREG_HB_NMA_DAMPING_MODAL, 1e-6, 2e-6, 2),
                             FRICREG_OK);
            ck_assert_int_eq(fricreg_hb_nma_point(hb, 0, &a, &w, &z, NB, 3, x), FRICREG_OK);
            double mass = 0.0, big = 0.0;
            for (size_t i = 0; i < NB; i++) {
                double c = x[3 * i + 1];
                mass += dm[i] * c * c;
                big = fabs(c) > fabs(big) ? c : big;
            }
            ck_assert_double_eq_tol(mass, a * a, 1e-9 * a * a);
            ck_assert(big > 0.0);
        }
        fricreg_hb_free(hb);
    }
}
END_TEST

/* (c) the refusals, on a 3-dof sparse model with an element on dof 0. */
START_TEST(not_positive_definite)
{
    const int64_t p[4] = {0, 1, 3, 4}, i[4] = {0, 0, 1, 2}, pd[4] = {0, 1, 2, 3};
    const double K[4] = {2.0, -1.0, 2.0, 1.5}, J[3] = {1.0, 0.0, 0.0}, kt = 1.0, mun = 1.0;
    const double indefinite[4] = {1.0, 2.0, 1.0, 1.0}; /* (0, 1) block eigenvalues 3 and −1 */
    const double massless[3] = {1.0, 0.0, 1.0}, tiny[3] = {1.0, 1e-15, 1.0};
    const double *masses[3] = {indefinite, massless, tiny};
    const int modal = FRICREG_HB_NMA_DAMPING_MODAL;
    for (int c = 0; c < 3; c++) {
        fricreg_hb *hb = NULL;
        ck_assert_int_eq(fricreg_hb_create(3, 1, 3, &hb), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_set_stiffness_csc(hb, 3, FRICREG_SPARSE_UPPER, p, i, K),
                         FRICREG_OK);
        int status = c == 0
                         ? fricreg_hb_set_mass_csc(hb, 3, FRICREG_SPARSE_UPPER, p, i, masses[c])
                         : fricreg_hb_set_mass_csc(hb, 3, FRICREG_SPARSE_UPPER, pd, pd, masses[c]);
        ck_assert_int_eq(status, FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, 3, J, &kt, &mun), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_nma(hb, 0, modal, 0.1, 1.0, 4), FRICREG_ENOTPSD);
        ck_assert_int_eq(fricreg_hb_errcode(hb), FRICREG_ENOTPSD);
        ck_assert_uint_eq(fricreg_hb_nma_points(hb), 0);
        fricreg_hb_free(hb);
    }
    /* K_0 singular: dof 2 has no spring and no element */
    const double unit[3] = {1.0, 1.0, 1.0}, Ks[4] = {2.0, -1.0, 2.0, 0.0};
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(3, 1, 3, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass_csc(hb, 3, FRICREG_SPARSE_UPPER, pd, pd, unit),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness_csc(hb, 3, FRICREG_SPARSE_UPPER, p, i, Ks),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, 3, J, &kt, &mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, modal, 0.1, 1.0, 4), FRICREG_EINVAL);
    ck_assert_uint_eq(fricreg_hb_nma_points(hb), 0);
    fricreg_hb_free(hb);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("hb_nma_sparse");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, membrane_closed_form);
    tcase_add_test(tc, sparse_against_dense);
    tcase_add_test(tc, mode_shape_normalized);
    tcase_add_test(tc, not_positive_definite);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
