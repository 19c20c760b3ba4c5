/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_monodromy.c — Check suite for the exact monodromy of harmonic balance
 * (fricreg_hb_set_stability_method, FRICREG_HB_STABILITY_MONODROMY; fricreg_hb.h) against an
 * independent one of the time domain, sharp enough to see the HB's truncation error.
 *
 * The model: the Jenkins pair of test_hb_stability.c (2 unit masses, K = [2 −1; −1 2], C = 0.05 K,
 * one Jenkins element kt = 3, mu N = 0.4 on dof 1 against the ground, p = (cos Ω t, 0)) at
 * Ω = 0.68, where Hill's largest multiplier was 0.148 and a step-resolved shooting's 0.589.
 *
 * The reference: the periodic orbit by Newton's shooting on an event-driven integration of the
 * state (x, v, w), w the slider's offset (jenkins_pair_events.h: GSL's rk8pd between the
 * switches, each located to 1e-14 T); the monodromy by central differences of the period map (steps 1e-6 of the state's
 * scale), its eigenvalues by GSL. Its largest |multiplier| against the HB's exact monodromy at
 * H = 10, 20 and 40: the HB's converges to it as H grows (its orbit's truncation error), and
 * Hill's method's does not (printed with HB_PRINT). */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_complex_math.h>
#include <gsl/gsl_eigen.h>

#include "fricreg_hb.h"
#include "jenkins_pair_events.h"
#include "quiet_check.h"

/* The pair in the time domain (jenkins_pair_events.h). */
static const struct jenkins_pair PAIR = {.K = {2, -1, -1, 2},
                                         .C = {0.1, -0.05, -0.05, 0.1},
                                         .kt = 3.0,
                                         .mun = 0.4,
                                         .dof = 0,
                                         .force = 1.0,
                                         .omega = 0.68};

/* The largest |eigenvalue| of Phi[5 5] (destroyed). */
static double largest(double Phi[25])
{
    gsl_matrix_view A = gsl_matrix_view_array(Phi, 5, 5);
    gsl_vector_complex *ev = gsl_vector_complex_alloc(5);
    gsl_eigen_nonsymm_workspace *w = gsl_eigen_nonsymm_alloc(5);
    ck_assert_int_eq(gsl_eigen_nonsymm(&A.matrix, ev, w), 0);
    double top = 0.0;
    for (int j = 0; j < 5; j++)
        top = fmax(top, gsl_complex_abs(gsl_vector_complex_get(ev, j)));
    gsl_eigen_nonsymm_free(w);
    gsl_vector_complex_free(ev);
    return top;
}

/* The HB solution at PAIR's Ω with H harmonics by method: its mu_max, and its displacement's
 * coefficients x[2 (2H + 1)] when x is not NULL. */
static double hb_mu(int H, int method, double *x)
{
    const double M[4] = {1, 0, 0, 1}, J[2] = {1, 0}, pc[2] = {PAIR.force, 0}, ps[2] = {0, 0};
    size_t nc = 2 * (size_t)H + 1;
    fricreg_hb *hb = NULL;
    double *q = malloc(nc * sizeof *q), mu = 0.0;
    int stable = 0;
    ck_assert_ptr_nonnull(q);
    ck_assert_int_eq(fricreg_hb_create(2, 1, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 2, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, PAIR.K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, 2, PAIR.C), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, 2, J, &PAIR.kt, &PAIR.mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, 2, pc, ps), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_newton(hb, 1e-12, 50), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stability_method(hb, method), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stability(hb, 1), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(hb, PAIR.omega, nc, NULL, q), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_point_stability(hb, FRICREG_HB_SOLUTION, &stable, &mu), FRICREG_OK);
    if (x != NULL)
        ck_assert_int_eq(fricreg_hb_displacement(hb, 2, nc, x), FRICREG_OK);
    fricreg_hb_free(hb);
    free(q);
    return mu;
}

START_TEST(jenkins_pair_converges_in_h)
{
    const int Hs[3] = {10, 20, FRICREG_HB_MAX_HARMONICS};
    double *x = malloc(2 * (2 * FRICREG_HB_MAX_HARMONICS + 1) * sizeof *x), z[5], t0 = 0.0, Phi[25];
    ck_assert_ptr_nonnull(x);
    (void)hb_mu(FRICREG_HB_MAX_HARMONICS, FRICREG_HB_STABILITY_MONODROMY, x);
    jenkins_pair_start(&PAIR, FRICREG_HB_MAX_HARMONICS, x, &t0, z);
    jenkins_pair_shoot(&PAIR, t0, z);
    jenkins_pair_monodromy(&PAIR, t0, z, Phi);
    double ref = largest(Phi), err[3];
    for (int i = 0; i < 3; i++) {
        double mono = hb_mu(Hs[i], FRICREG_HB_STABILITY_MONODROMY, NULL);
        err[i] = fabs(mono / ref - 1.0);
        if (getenv("HB_PRINT"))
            fprintf(stderr, "H = %d: monodromy %.9f, Hill %.9f, shooting %.9f (%.2e)\n", Hs[i],
                    mono, hb_mu(Hs[i], FRICREG_HB_STABILITY_HILL, NULL), ref, err[i]);
    }
    /* measured 1.7e-4, 2.4e-5, 8.6e-6 (the shooting 0.589142064); Hill's 0.1465, 0.1475,
     * 0.1476: its exponents lack the slider's offset, a gap that no H closes */
    ck_assert_double_lt(err[1], err[0]);
    ck_assert_double_lt(err[2], err[1]);
    ck_assert_double_lt(err[2], 2e-5);
    ck_assert_double_gt(fabs(hb_mu(FRICREG_HB_MAX_HARMONICS, FRICREG_HB_STABILITY_HILL, NULL) -
                             ref),
                        0.3);
    free(x);
}
END_TEST

Suite *hb_monodromy_suite(void)
{
    Suite *s = suite_create("hb_monodromy");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, jenkins_pair_converges_in_h);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(hb_monodromy_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
