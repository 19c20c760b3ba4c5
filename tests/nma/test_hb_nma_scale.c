/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_nma_scale.c — Check suite for the nonlinear modes' Newton at the model's scale
 * (fricreg_hb_nma, fricreg_hb_nma_continue; fricreg_hb_nma.h): a model in SI
 * units with the default tolerance.
 *
 * The model: a chain of n = 30 masses m = 0.01 kg, springs k = 1e9 N/m, fixed at one end (dof 0
 * grounded by k), free at the other, where a Jenkins element kt = 1e8 N/m, mu N = 100 N
 * grounds it (J = e_29): stiffnesses of 1e8–1e9 N/m, slip at 1e-6 m, forces of 1e2 N.
 *
 * Where the numbers come from: until 1.8, fricreg_hb_nma stopped on this backbone at the
 * default tolerance 1e-10 with "Newton's line search found no decrease of |R| = 6.2e-12 at
 * amplitude 0.0079" (measured): |R| relative to |q| sits at the rounding floor of the
 * condensation (D_h's condition, 1e9 N/m against 0.01 kg at 1e4 rad/s, times the unit
 * roundoff) above 1e-10. Newton's own step is then within the tolerance of the unknowns, and
 * the point converged; a looser tolerance, 1e-9, never meets the floor and is the reference:
 * the two backbones agree to that tolerance. The fully slipped limit: the chain with a free
 * end, ω_1 = 2 sqrt(k/m) sin(π/(2(2n + 1))) (the fixed-free chain's closed form), which the
 * backbone approaches as the element's force, bounded by mu N, falls against the springs'. */
#include <check.h>
#include <math.h>
#include <stdlib.h>

#include "fricreg_hb.h"

#define N 30
#define MASS 0.01
#define KS 1e9
#define KT 1e8
#define MUN 100.0

static const double pi = 3.14159265358979323846;

static fricreg_hb *chain(double tol)
{
    static double M[N * N], K[N * N], J[N];
    for (size_t i = 0; i < N; i++) {
        M[i * N + i] = MASS;
        K[i * N + i] = i + 1 < N ? 2.0 * KS : KS;
        if (i > 0)
            K[i * N + i - 1] = K[(i - 1) * N + i] = -KS;
    }
    J[N - 1] = 1.0;
    fricreg_hb *hb = NULL;
    const double kt = KT, mun = MUN;
    ck_assert_int_eq(fricreg_hb_create(N, 1, 7, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, N, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, N, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, N, J, &kt, &mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_newton(hb, tol, 50), FRICREG_OK);
    return hb;
}

/* (a) The march at the default tolerance runs from 1e-6 to 1e-2 m, every point within 1e-9 of
 * ω and 1e-8 of ζ (relative) of the march at 1e-9 (measured: 9.5e-12 and 8.5e-11). */
START_TEST(si_default_tolerance)
{
    const size_t np = 30;
    fricreg_hb *ref = chain(1e-9), *hb = chain(1e-10);
    ck_assert_int_eq(fricreg_hb_nma(ref, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 1e-6, 1e-2, np),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 1e-6, 1e-2, np),
                     FRICREG_OK);
    double worst_w = 0.0, worst_z = 0.0;
    for (size_t i = 0; i < np; i++) {
        double a, w, z, ar, wr, zr;
        ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &a, &w, &z, 0, 0, NULL), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_nma_point(ref, i, &ar, &wr, &zr, 0, 0, NULL), FRICREG_OK);
        ck_assert_double_eq(a, ar);
        worst_w = fmax(worst_w, fabs(w - wr) / wr);
        if (zr > 0.0)
            worst_z = fmax(worst_z, fabs(z - zr) / zr);
    }
    ck_assert_double_le(worst_w, 1e-9);
    ck_assert_double_le(worst_z, 1e-8);
    fricreg_hb_free(ref);
    fricreg_hb_free(hb);
}
END_TEST

/* (b) The continuation at the default tolerance, the same range: the fully slipped limit at
 * a = 1e-2 m (the element's slip 1e-6 m, its force 1e2 N against the chain's 1e7 N), ω within
 * 1e-6 of the free-ended chain's closed form (measured 2.0e-8). */
START_TEST(si_continuation_slipped_limit)
{
    fricreg_hb *hb = chain(1e-10);
    const size_t np = 20;
    ck_assert_int_eq(fricreg_hb_nma_continue(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 1e-6, 1e-2, np),
                     FRICREG_OK);
    double a, w, z;
    ck_assert_int_eq(fricreg_hb_nma_point(hb, np - 1, &a, &w, &z, 0, 0, NULL), FRICREG_OK);
    double w1 = 2.0 * sqrt(KS / MASS) * sin(pi / (2.0 * (2.0 * N + 1.0)));
    ck_assert_double_eq_tol(a, 1e-2, 1e-12);
    ck_assert_double_eq_tol(w, w1, 1e-6 * w1);
    fricreg_hb_free(hb);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("hb_nma_scale");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, si_default_tolerance);
    tcase_add_test(tc, si_continuation_slipped_limit);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
