/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_nma_shooting.c — Check suite for the backbone through a fold (fricreg_hb_nma_continue;
 * fricreg_hb.h) against the time domain: each point's natural frequency against the periodic
 * orbit of an event-driven shooting at the same damping, converging as H grows.
 *
 * The model: test_hb_nma_fold.c's (two unit masses, K = [[5/4, −1/4], [−1/4, 9/20]], a Jenkins
 * element kt = 10, mu N = 1 on dof 2), whose backbone of mode 0 folds twice near a = 4.43 (a
 * 3:1 internal resonance), continued from a = 0.05 to 100 at H = 3, 7 and 15.
 *
 * The reference: a point's free motion x'' − ξ x' + K x + e_2 f = 0 (the extended periodic
 * motion concept's equation, ξ = 2 ζ ω the point's) is periodic at one period T near 2π/ω; it
 * is found by Newton's shooting (jenkins_events.h: GSL's rk8pd between the switches,
 * located to 1e-14 T) on (x_2, v_1, v_2, w, T) with x_1 held at the HB orbit's value where the
 * slider is deepest in a stick (the phase condition), from the HB orbit. ξ is monotone across
 * the S (0.0029 to 0.0079 of ζ between the folds), so the point at a given ξ is one of the
 * branch, passing the folds. The HB's ω differs from the shooting's by its truncation error,
 * which falls as H grows. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_linalg.h>

#include "fricreg_hb.h"
#include "jenkins_events.h"

#define NPOINTS 50

static fricreg_hb *model(int harmonics)
{
    fricreg_hb *hb = NULL;
    const double M[4] = {1, 0, 0, 1}, K[4] = {1.25, -0.25, -0.25, 0.45}, J[2] = {0, 1};
    const double kt = 10.0, mun = 1.0;
    ck_assert_int_eq(fricreg_hb_create(2, 1, harmonics, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 2, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, 2, J, &kt, &mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_nma_continue(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.05, 100.0,
                                             NPOINTS),
                     FRICREG_OK);
    return hb;
}

/* The free motion at ξ and Ω = omega (period 2π/Ω). */
static struct jenkins_system free_motion(double xi, double omega)
{
    struct jenkins_system s = {.n = 2,
                               .K = {1.25, -0.25, -0.25, 0.45},
                               .C = {-xi, 0, 0, -xi},
                               .J = {0, 1},
                               .kt = 10.0,
                               .mun = 1.0,
                               .omega = omega};
    return s;
}

/* r[5] = period(z) − z at the unknowns u = (x2, v1, v2, w, Ω), x1 = z[0] held. */
static void defect(double xi, const double z0[5], const double u[5], double r[5])
{
    struct jenkins_system s = free_motion(xi, u[4]);
    double z[5] = {z0[0], u[0], u[1], u[2], u[3]}, zn[5];
    jenkins_period(&s, 0.0, z, zn);
    for (int j = 0; j < 5; j++)
        r[j] = zn[j] - z[j];
}

/* The periodic free motion at ξ from the HB orbit's state z0 and frequency omega: Newton's
 * shooting, its Jacobian by central differences; returns its Ω. */
static double shoot(double xi, const double z0[5], double omega)
{
    double u[5] = {z0[1], z0[2], z0[3], z0[4], omega}, r[5], A[25], du[5];
    gsl_permutation *p = gsl_permutation_alloc(5);
    for (int it = 0;; it++) {
        ck_assert_int_lt(it, 20);
        defect(xi, z0, u, r);
        double res = 0.0;
        for (int j = 0; j < 5; j++)
            res = fmax(res, fabs(r[j]));
        if (res <= 1e-11)
            break;
        for (int j = 0; j < 5; j++) {
            double up[5], um[5], rp[5], rm[5], h = 1e-7 * fmax(1.0, fabs(u[j]));
            memcpy(up, u, sizeof up);
            memcpy(um, u, sizeof um);
            up[j] += h, um[j] -= h;
            defect(xi, z0, up, rp);
            defect(xi, z0, um, rm);
            for (int i = 0; i < 5; i++)
                A[5 * i + j] = (rp[i] - rm[i]) / (2.0 * h);
        }
        gsl_matrix_view Am = gsl_matrix_view_array(A, 5, 5);
        gsl_vector_view b = gsl_vector_view_array(r, 5), x = gsl_vector_view_array(du, 5);
        int sg;
        ck_assert_int_eq(gsl_linalg_LU_decomp(&Am.matrix, p, &sg), 0);
        ck_assert_int_eq(gsl_linalg_LU_solve(&Am.matrix, p, &b.vector, &x.vector), 0);
        for (int j = 0; j < 5; j++)
            u[j] -= du[j];
    }
    gsl_permutation_free(p);
    return u[4];
}

/* The largest |ω_HB/ω_shooting − 1| at H over the stored points with a_min <= a <= a_max. */
static double worst_frequency_error(int H, double a_min, double a_max)
{
    fricreg_hb *hb = model(H);
    size_t nc = 2 * (size_t)H + 1;
    double *x = malloc(2 * nc * sizeof *x), worst = 0.0;
    ck_assert_ptr_nonnull(x);
    for (size_t i = 0; i < fricreg_hb_nma_points(hb); i++) {
        double a, omega, zeta, z[5], t0 = 0.0;
        ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &a, &omega, &zeta, 2, nc, x), FRICREG_OK);
        if (a < a_min || a > a_max)
            continue;
        double xi = 2.0 * zeta * omega;
        struct jenkins_system s = free_motion(xi, omega);
        jenkins_start(&s, H, x, &t0, z);
        double err = fabs(omega / shoot(xi, z, omega) - 1.0);
        if (getenv("HB_PRINT"))
            fprintf(stderr, "H = %d a = %.5f omega = %.8f zeta = %.5f: %.2e\n", H, a, omega, zeta,
                    err);
        worst = fmax(worst, err);
    }
    free(x);
    fricreg_hb_free(hb);
    return worst;
}

/* (a) From the slip onset (a = 3.68; below it the mode is linear and the HB exact) through
 * the S (the folds at a = 4.456 and 4.443, H = 15) and back on the monotone branch, up to
 * a = 4.7 (ζ = 0.018; beyond, H = 3's orbit is too far from the time domain's for the
 * shooting's Newton to start from it): the HB's ω converges to the shooting's as H grows.
 * Measured, the largest relative difference: 5.8e-4 (H = 3), 5.8e-5 (H = 7), 1.6e-6 (H = 15),
 * on 5 points each, one of them between the folds (printed with HB_PRINT). */
START_TEST(frequency_converges_in_h)
{
    double e3 = worst_frequency_error(3, 3.9, 4.7), e7 = worst_frequency_error(7, 3.9, 4.7),
           e15 = worst_frequency_error(15, 3.9, 4.7);
    ck_assert_double_lt(e7, 0.2 * e3);
    ck_assert_double_lt(e15, 0.1 * e7);
    ck_assert_double_lt(e15, 5e-6);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("hb_nma_shooting");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 300);
    tcase_set_tags(tc, "release"); /* 6 s: the release tier's (hb_nma_shooting_release) */
    tcase_add_test(tc, frequency_converges_in_h);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
