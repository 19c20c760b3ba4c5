/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_elements.c — Check suite for a harmonic-balance model holding elements of several
 * kinds (fricreg_hb_add_elements, _clear_elements, _element_count).
 *
 * Where the numbers come from:
 *   - a model of three decoupled blocks (block-diagonal M, C, K, each block forced), one with
 *     a Jenkins element, one with a 3-D contact element, one with an Iwan element of three
 *     sliders, holds the three kinds at once; each block is also solved alone with its per-kind
 *     setter: each block's harmonics agree to 1e-13 of their scale at three frequencies, the
 *     model dense or sparse (measured 8.4e-15, 8.6e-15: the blocks' equations are the same,
 *     the condensation block-diagonal; only Newton's shared iterations may differ, stopped at
 *     1e-13); at Ω = 1.2 every element slips and the contact lifts off. A continuation of the
 *     mix with stability on runs, by Hill's method (the exact monodromy takes one kind:
 *     refused when chosen), and so do its nonlinear modes;
 *   - elements of one type added in two calls solve bit for bit as the per-kind setter's (the
 *     same layout and AFT), for Iwan, lift-off and 3-D contact elements;
 *   - bad input: the statuses fricreg_hb.h promises, the message naming the element, the
 *     element count and the solution unchanged after each failure. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_element.h"
#include "fricreg_hb.h"

#define H 3
#define NC (2 * H + 1)
#define NB 6 /* the blocks' dofs: A (Jenkins) 0-1, B (3-D contact) 2-3, C (Iwan) 4-5 */

/* Each block: two masses; its elements' rows and parameters in the types' layouts. */
static const double jenkins_J[2] = {1.0, -1.0}, jenkins_p[2] = {2.0, 0.3};
static const double contact_J[6] = {1.0, 0.0, 0.2, 1.0, 0.4, -0.3};
static const double contact_p[5] = {1.5, 0.4, 2.0, 0.5, 0.0}; /* kt, mu, kn, n0, gap */
static const double iwan_J[2] = {0.0, 1.0};
static const double iwan_p[6] = {1.0, 0.6, 0.4, 0.1, 0.2, 0.35}; /* k[3], phi[3] */

static void block_matrices(int b, double M[4], double K[4], double C[4], double p[2])
{
    static const double Ms[3][4] = {{1, 0, 0, 1.2}, {1, 0, 0, 1.2}, {0.8, 0, 0, 1}};
    static const double Ks[3][4] = {{3, -1, -1, 2}, {2, -0.3, -0.3, 1.5}, {2.5, -1, -1, 2}};
    static const double ps[3][2] = {{0.5, 0.2}, {0.6, 0.4}, {0.3, 0.4}};
    memcpy(M, Ms[b], sizeof Ms[b]);
    memcpy(K, Ks[b], sizeof Ks[b]);
    for (int i = 0; i < 4; i++)
        C[i] = 0.02 * M[i] + 0.01 * K[i];
    memcpy(p, ps[b], sizeof ps[b]);
}

static fricreg_hb *driver(size_t n, size_t me, const double *M, const double *K, const double *C,
                          const double *p)
{
    fricreg_hb *hb = NULL;
    double zero[NB] = {0.0};
    ck_assert_int_eq(fricreg_hb_create(n, me, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, n, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, n, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, n, C), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, n, p, zero), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_newton(hb, 1e-13, 50), FRICREG_OK);
    return hb;
}

/* Block b alone, with its per-kind setter. */
static fricreg_hb *block_alone(int b)
{
    double M[4], K[4], C[4], p[2];
    block_matrices(b, M, K, C, p);
    fricreg_hb *hb = driver(2, 1, M, K, C, p);
    int s;
    if (b == 0)
        s = fricreg_hb_set_jenkins(hb, 1, 2, jenkins_J, &jenkins_p[0], &jenkins_p[1]);
    else if (b == 1)
        s = fricreg_hb_set_jenkins_2d_normal(hb, 1, 2, contact_J, contact_J + 4, &contact_p[0],
                                             &contact_p[1], &contact_p[3], &contact_p[2]);
    else
        s = fricreg_hb_set_iwan(hb, 1, 2, iwan_J, 3, iwan_p, iwan_p + 3);
    ck_assert_int_eq(s, FRICREG_OK);
    return hb;
}

/* M made the sparse model's (fricreg_hb_set_mass_csc converts C and K too). */
static void make_sparse(fricreg_hb *hb, const double *M)
{
    int64_t ptr[NB + 1] = {0}, ind[NB * NB];
    double val[NB * NB];
    for (size_t j = 0; j < NB; j++) {
        ptr[j + 1] = ptr[j];
        for (size_t i = 0; i < NB; i++)
            if (M[i * NB + j] != 0.0) {
                ind[ptr[j + 1]] = (int64_t)i;
                val[ptr[j + 1]++] = M[i * NB + j];
            }
    }
    ck_assert_int_eq(fricreg_hb_set_mass_csc(hb, NB, FRICREG_SPARSE_ZERO_BASED, ptr, ind, val),
                     FRICREG_OK);
}

/* The three blocks in one model (dense, or sparse), their elements added by type. */
static fricreg_hb *mixed(int sparse)
{
    double M[NB * NB] = {0}, K[NB * NB] = {0}, C[NB * NB] = {0}, p[NB];
    for (int b = 0; b < 3; b++) {
        double Mb[4], Kb[4], Cb[4];
        block_matrices(b, Mb, Kb, Cb, p + 2 * b);
        for (int i = 0; i < 2; i++)
            for (int j = 0; j < 2; j++) {
                size_t at = (size_t)(2 * b + i) * NB + (size_t)(2 * b + j);
                M[at] = Mb[2 * i + j];
                K[at] = Kb[2 * i + j];
                C[at] = Cb[2 * i + j];
            }
    }
    fricreg_hb *hb = driver(NB, 3, M, K, C, p);
    if (sparse)
        make_sparse(hb, M);
    double J[3 * NB] = {0};
    memcpy(J, jenkins_J, sizeof jenkins_J);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("jenkins"), 1, NB, J,
                                             jenkins_p),
                     FRICREG_OK);
    memset(J, 0, sizeof J);
    for (int r = 0; r < 3; r++)
        memcpy(J + r * NB + 2, contact_J + 2 * r, 2 * sizeof *J);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("contact_3d"), 1, NB, J,
                                             contact_p),
                     FRICREG_OK);
    memset(J, 0, sizeof J);
    memcpy(J + 4, iwan_J, sizeof iwan_J);
    const fricreg_element_type *iwan3 = fricreg_element_sliders(fricreg_element_lookup("iwan"), 3);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, iwan3, 1, NB, J, iwan_p), FRICREG_OK);
    ck_assert_uint_eq(fricreg_hb_element_count(hb), 3);
    return hb;
}

/* Each block's harmonics in the mix (rows 0; 1-3; 4) against the block alone. */
START_TEST(mix_equals_blocks)
{
    static const double omegas[3] = {0.8, 1.0,
                                     1.2}; /* all three blocks slip at 1.2, the contact lifts off */
    static const size_t row0[3] = {0, 1, 4}, rows[3] = {1, 3, 1};
    fricreg_hb *mix = mixed(_i), *alone[3];
    for (int b = 0; b < 3; b++)
        alone[b] = block_alone(b);
    double q[5 * NC], qb[3 * NC], worst = 0.0;
    for (int i = 0; i < 3; i++) {
        ck_assert_int_eq(fricreg_hb_solve(mix, omegas[i], 5 * NC, NULL, q), FRICREG_OK);
        for (int b = 0; b < 3; b++) {
            size_t nq = rows[b] * NC;
            ck_assert_int_eq(fricreg_hb_solve(alone[b], omegas[i], nq, NULL, qb), FRICREG_OK);
            double scale = 0.0, diff = 0.0;
            for (size_t j = 0; j < nq; j++) {
                scale = fmax(scale, fabs(qb[j]));
                diff = fmax(diff, fabs(q[row0[b] * NC + j] - qb[j]));
            }
            ck_assert_double_gt(scale, 0.0);
            worst = fmax(worst, diff / scale);
            ck_assert_msg(diff <= 1e-13 * scale, "Omega %g block %d: %g of %g", omegas[i], b, diff,
                          scale);
        }
    }
    printf("mix_equals_blocks (%s): worst block difference %.3g of its scale\n",
           _i ? "sparse" : "dense", worst);
    for (int b = 0; b < 3; b++)
        fricreg_hb_free(alone[b]);
    fricreg_hb_free(mix);
}
END_TEST

/* A continuation of the mix with stability: Hill's method in force, the monodromy refused;
 * its nonlinear modes. */
START_TEST(mix_continues_with_hill)
{
    fricreg_hb *mix = mixed(0);
    int method = -1;
    ck_assert_int_eq(fricreg_hb_set_newton(mix, 1e-10, 50), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_get_stability_method(mix, &method), FRICREG_OK);
    ck_assert_int_eq(method, FRICREG_HB_STABILITY_HILL);
    ck_assert_int_eq(fricreg_hb_set_stability(mix, 1), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_continuation(mix, 0.05, 1e-6, 0.1, 200), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_continue(mix, 0.9, 1.1, 5 * NC, NULL), FRICREG_OK);
    ck_assert_uint_gt(fricreg_hb_points(mix), 2);
    int stable = -1;
    double mu_max = 0.0;
    ck_assert_int_eq(fricreg_hb_point_stability(mix, 0, &stable, &mu_max), FRICREG_OK);
    ck_assert_int_eq(stable, 1); /* damped, forced away from its resonances */
    ck_assert_int_eq(fricreg_hb_set_stability_method(mix, FRICREG_HB_STABILITY_MONODROMY),
                     FRICREG_OK);
    double q[5 * NC];
    ck_assert_int_eq(fricreg_hb_solve(mix, 1.0, 5 * NC, NULL, q), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(mix), "all of one kind"));
    /* the nonlinear modes take the mix: the lowest mode's backbone */
    ck_assert_int_eq(fricreg_hb_nma(mix, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.01, 1.0, 6),
                     FRICREG_OK);
    ck_assert_uint_eq(fricreg_hb_nma_points(mix), 6);
    fricreg_hb_free(mix);
}
END_TEST

/* The model of block `b`'s matrices with two elements of one kind on its two masses' rows:
 * by the per-kind setter (two) or by add_elements, one element a call. */
static void one_kind(int kind, int by_type, double *q, size_t *nq)
{
    double M[4], K[4], C[4], p[2];
    block_matrices(1, M, K, C, p);
    fricreg_hb *hb = driver(2, 2, M, K, C, p);
    static const double Jt[4] = {1.0, -1.0, 0.0, 1.0}, Jn[4] = {0.4, -0.3, 0.2, 0.3};
    static const double Je[8] = {1.0, 0.0, 0.0, 1.0, 0.5, 0.5, -0.5, 1.0};
    static const double kt[2] = {1.5, 1.0}, mu[2] = {0.4, 0.3}, n0[2] = {0.5, 0.7},
                        kn[2] = {2.0, 1.0};
    static const double k3[6] = {1.0, 0.6, 0.4, 0.8, 0.5, 0.2};
    static const double phi3[6] = {0.1, 0.2, 0.35, 0.05, 0.15, 0.3};
    size_t rows = kind == 0 ? 1 : kind == 1 ? 2 : 3;
    for (size_t e = 0; by_type && e < 2; e++) {
        double J[6], par[9];
        size_t np;
        const fricreg_element_type *type;
        if (kind == 0) { /* Iwan, three sliders */
            type = fricreg_element_sliders(fricreg_element_lookup("iwan"), 3);
            memcpy(J, Jt + 2 * e, 2 * sizeof *J);
            memcpy(par, k3 + 3 * e, 3 * sizeof *par);
            memcpy(par + 3, phi3 + 3 * e, 3 * sizeof *par);
            np = 6;
        } else {
            type = fricreg_element_lookup(kind == 1 ? "jenkins_normal" : "contact_3d");
            const double *tangential = kind == 1 ? Jt : Je;
            memcpy(J, tangential + (rows - 1) * 2 * e, (rows - 1) * 2 * sizeof *J);
            memcpy(J + (rows - 1) * 2, Jn + 2 * e, 2 * sizeof *J);
            double law[5] = {kt[e], mu[e], kn[e], n0[e], 0.0};
            memcpy(par, law, sizeof law);
            np = 5;
        }
        ck_assert_uint_eq(fricreg_element_nparams(type), np);
        ck_assert_int_eq(fricreg_hb_add_elements(hb, type, 1, 2, J, par), FRICREG_OK);
    }
    if (!by_type) {
        int s = kind == 0   ? fricreg_hb_set_iwan(hb, 2, 2, Jt, 3, k3, phi3)
                : kind == 1 ? fricreg_hb_set_jenkins_normal(hb, 2, 2, Jt, Jn, kt, mu, n0, kn)
                            : fricreg_hb_set_jenkins_2d_normal(hb, 2, 2, Je, Jn, kt, mu, n0, kn);
        ck_assert_int_eq(s, FRICREG_OK);
    }
    *nq = 2 * rows * NC;
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.1, *nq, NULL, q), FRICREG_OK);
    fricreg_hb_free(hb);
}

START_TEST(add_equals_setter)
{
    double a[6 * NC], b[6 * NC];
    size_t na, nb;
    one_kind(_i, 0, a, &na);
    one_kind(_i, 1, b, &nb);
    ck_assert_uint_eq(na, nb);
    ck_assert_msg(memcmp(a, b, na * sizeof *a) == 0, "kind %d: not bit for bit", _i);
}
END_TEST

/* Each failure leaves the elements and the solution as they were. */
static void refused(fricreg_hb *hb, int status, int want, const char *says, const double *q)
{
    double q2[5 * NC], x[NB * NC];
    ck_assert_int_eq(status, want);
    if (says != NULL)
        ck_assert_msg(strstr(fricreg_hb_errmsg(hb), says) != NULL, "'%s' lacks '%s'",
                      fricreg_hb_errmsg(hb), says);
    ck_assert_uint_eq(fricreg_hb_element_count(hb), 3);
    ck_assert_int_eq(fricreg_hb_displacement(hb, NB, NC, x), FRICREG_OK); /* still solved */
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.2, 5 * NC, NULL, q2), FRICREG_OK);
    ck_assert_int_eq(memcmp(q, q2, sizeof q2), 0);
}

START_TEST(bad_input)
{
    fricreg_hb *hb = mixed(0);
    const fricreg_element_type *jenkins = fricreg_element_lookup("jenkins");
    const fricreg_element_type *iwan2 = fricreg_element_sliders(fricreg_element_lookup("iwan"), 2);
    double q[5 * NC], J[2 * NB] = {1.0}, bad[5] = {2.0, 0.3, 0.0, 0.0, 0.0};
    J[NB + 1] = 1.0;
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.2, 5 * NC, NULL, q), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(NULL, jenkins, 1, NB, J, bad), FRICREG_ENULL);
    ck_assert_uint_eq(fricreg_hb_element_count(NULL), 0);
    ck_assert_int_eq(fricreg_hb_clear_elements(NULL), FRICREG_ENULL);
    refused(hb, fricreg_hb_add_elements(hb, NULL, 1, NB, J, bad), FRICREG_ENULL, "type", q);
    refused(hb, fricreg_hb_add_elements(hb, jenkins, 1, NB, NULL, bad), FRICREG_ENULL, "J", q);
    refused(hb, fricreg_hb_add_elements(hb, jenkins, 1, NB, J, NULL), FRICREG_ENULL, "params", q);
    refused(hb, fricreg_hb_add_elements(hb, jenkins, 0, NB, NULL, NULL), FRICREG_OK, NULL, q);
    refused(hb, fricreg_hb_add_elements(hb, jenkins, 1, NB - 1, J, bad), FRICREG_ESIZE, "ndof", q);
    refused(hb, fricreg_hb_add_elements(hb, jenkins, 1, NB, J, bad), FRICREG_ESIZE, "made for 3",
            q);
    double spring = -1.0;
    refused(hb, fricreg_hb_add_elements(hb, fricreg_element_lookup("spring"), 1, NB, J, &spring),
            FRICREG_ESIZE, "made for 3", q);

    /* on a fresh driver of one element, the rest: nothing held, nothing added on failure */
    fricreg_hb *one = NULL;
    ck_assert_int_eq(fricreg_hb_create(NB, 1, H, &one), FRICREG_OK);
    double iw[4] = {1.0, 0.5, 0.1, -0.2}; /* a slip force < 0 */
    ck_assert_int_eq(fricreg_hb_add_elements(one, iwan2, 1, NB, J, iw), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(one), "element 0 (iwan)"));
    iw[3] = NAN;
    ck_assert_int_eq(fricreg_hb_add_elements(one, iwan2, 1, NB, J, iw), FRICREG_ENONFINITE);
    double gap[5] = {1.5, 0.4, 2.0, 0.0, 0.1};
    ck_assert_int_eq(fricreg_hb_add_elements(one, fricreg_element_lookup("jenkins_normal"), 1, NB,
                                             J, gap),
                     FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(one), "gap"));
    double zero[NB] = {0.0};
    ck_assert_int_eq(fricreg_hb_add_elements(one, jenkins, 1, NB, zero, bad), FRICREG_EINVAL);
    ck_assert_uint_eq(fricreg_hb_element_count(one), 0);
    ck_assert_int_eq(fricreg_hb_solve(one, 1.0, NC, NULL, q), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_add_elements(one, jenkins, 1, NB, J, bad), FRICREG_OK);
    ck_assert_uint_eq(fricreg_hb_element_count(one), 1);
    ck_assert_int_eq(fricreg_hb_clear_elements(one), FRICREG_OK);
    ck_assert_uint_eq(fricreg_hb_element_count(one), 0);
    fricreg_hb_free(one);
    fricreg_hb_free(hb);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("hb_elements");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    /* the mix against each block alone at three frequencies, dense and sparse (5 s): the
     * release tier's (hb_elements_release); the quick tier solves the mix in cont and bad */
    tcase_set_tags(tc, "release");
    tcase_add_loop_test(tc, mix_equals_blocks, 0, 2);
    suite_add_tcase(s, tc);
    tc = tcase_create("cont");
    tcase_add_test(tc, mix_continues_with_hill);
    suite_add_tcase(s, tc);
    tc = tcase_create("add");
    tcase_add_loop_test(tc, add_equals_setter, 0, 3);
    suite_add_tcase(s, tc);
    tc = tcase_create("bad");
    tcase_add_test(tc, bad_input);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed ? EXIT_FAILURE : EXIT_SUCCESS;
}
