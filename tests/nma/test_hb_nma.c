/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_nma.c — Check suite for nonlinear modes by the extended periodic motion concept
 * (fricreg_hb_nma, fricreg_hb_nma_point; fricreg_hb.h).
 *
 * The oscillator: m = 1, k = 1, no viscous damping, one Jenkins element kt = 2, mu N = 3 on the
 * dof (J = 1), so φ = 1 and the modal amplitude a is the displacement amplitude, x = a cos θ.
 *
 * Its closed form at H = 1 (the describing function of the elastic–perfectly-plastic
 * hysteresis, the element's force at x = a cos θ expanded to its first harmonic): stuck while
 * kt a <= mu N, i.e. a <= δ = mu N/kt = 1.5, where the element is a spring kt and the mode is
 * linear, ω² = k + kt = 3, ζ = 0. Beyond, the element slips over part of the cycle; with
 * cos β = 1 − 2δ/a (β in (0, π)), the force's in-phase first-harmonic coefficient is
 * a k_re, k_re = (kt/π)(β − sin(2β)/2) (its equivalent stiffness: kt at a = δ, → 0 as a → ∞),
 * and its quadrature coefficient follows from the dissipation per cycle,
 * W = ∮ f dx = 4 mu N (a − δ) (the loop's area: docs/contributing.md). The EPMC equation
 * x'' − ξ x' + k x + f = 0 at x = a cos θ balanced on cos θ and sin θ gives
 *
 *     ω² = k + k_re,        ξ a² ω π = W   (the negative damping's work makes up W),
 *
 * so ζ = ξ/(2ω) = W / (2π a² ω²) = 4 mu N (a − δ) / (2π a² ω²).
 *
 * Where the other numbers come from: at H = 7 the stuck mode is still the linear one (the
 * element's force is kt x exactly, no higher harmonics), so the backbone starts at √3, ζ = 0. */
#include <check.h>
#include <float.h>
#include <math.h>
#include <string.h>
#include <stdlib.h>

#include "fricreg_hb.h"

#define KT 2.0
#define MUN 3.0
#define DELTA (MUN / KT)

static const double pi = 3.14159265358979323846;

/* The closed form above at amplitude a: ω² and ζ. */
static void closed_form(double a, double *omega2, double *zeta)
{
    if (a <= DELTA) {
        *omega2 = 1.0 + KT;
        *zeta = 0.0;
        return;
    }
    double beta = acos(1.0 - 2.0 * DELTA / a);
    *omega2 = 1.0 + KT / pi * (beta - 0.5 * sin(2.0 * beta));
    *zeta = 4.0 * MUN * (a - DELTA) / (2.0 * pi * a * a * *omega2);
}

static fricreg_hb *oscillator(int harmonics)
{
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(1, 1, harmonics, &hb), FRICREG_OK);
    const double one = 1.0, kt = KT, mun = MUN;
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 1, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 1, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, 1, &one, &kt, &mun), FRICREG_OK);
    return hb;
}

/* (a) H = 1: 16 amplitudes from 0.5 (stuck) to 1000 (the element slips over all but 0.3 % of
 * the cycle) against the closed form, to 1e-9 of ω² and of ζ. */
START_TEST(oscillator_closed_form)
{
    fricreg_hb *hb = oscillator(1);
    const size_t np = 16;
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.5, 1000.0, np),
                     FRICREG_OK);
    ck_assert_uint_eq(fricreg_hb_nma_points(hb), np);
    double worst_w = 0.0, worst_z = 0.0;
    for (size_t i = 0; i < np; i++) {
        double a, omega, zeta, w2, z;
        ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &a, &omega, &zeta, 0, 0, NULL), FRICREG_OK);
        ck_assert_double_eq_tol(a, 0.5 * pow(2000.0, (double)i / (np - 1)), 1e-12 * a);
        closed_form(a, &w2, &z);
        worst_w = fmax(worst_w, fabs(omega * omega - w2) / w2);
        if (z > 0.0)
            worst_z = fmax(worst_z, fabs(zeta - z) / z);
        else
            ck_assert_double_eq_tol(zeta, 0.0, 1e-12);
        /* the displacement: a cos θ, nothing at the mean */
        double x[3];
        ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &a, &omega, &zeta, 1, 3, x), FRICREG_OK);
        ck_assert_double_eq_tol(x[1], a, 1e-9 * a);
        ck_assert_double_eq_tol(x[2], 0.0, 1e-9 * a);
        ck_assert_double_eq_tol(x[0], 0.0, 1e-9 * a);
    }
    ck_assert_double_le(worst_w, 1e-9);
    ck_assert_double_le(worst_z, 1e-9);
    fricreg_hb_free(hb);
}
END_TEST

/* (a') fricreg_hb_nma_at: the oscillator at the caller's amplitudes (a test's levels, off any
 * geometric grid; one below the first slip) against the closed form to 1e-9, each stored at
 * its amplitude to 4 ulps; at a geometric grid's own amplitudes the points equal
 * fricreg_hb_nma's to 1e-12 (the same march, its targets through log and exp); and its
 * refusals. */
START_TEST(oscillator_at_amplitudes)
{
    fricreg_hb *hb = oscillator(1);
    const double levels[5] = {0.7, 2.385, 3.1, 41.7, 997.0};
    ck_assert_int_eq(fricreg_hb_nma_at(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 5, levels),
                     FRICREG_OK);
    ck_assert_uint_eq(fricreg_hb_nma_points(hb), 5);
    for (size_t i = 0; i < 5; i++) {
        double a, omega, zeta, w2, z;
        ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &a, &omega, &zeta, 0, 0, NULL), FRICREG_OK);
        ck_assert_double_eq_tol(a, levels[i], 4.0 * DBL_EPSILON * levels[i]);
        closed_form(a, &w2, &z);
        ck_assert_double_eq_tol(omega * omega, w2, 1e-9 * w2);
        ck_assert_double_eq_tol(zeta, z, 1e-9 * fmax(z, 1e-3));
    }
    const size_t np = 9;
    double grid[9], g[9][3];
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.5, 1000.0, np),
                     FRICREG_OK);
    for (size_t i = 0; i < np; i++)
        ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &grid[i], &g[i][1], &g[i][2], 0, 0, NULL),
                         FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_nma_at(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, np, grid), FRICREG_OK);
    for (size_t i = 0; i < np; i++) {
        double a, omega, zeta;
        ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &a, &omega, &zeta, 0, 0, NULL), FRICREG_OK);
        ck_assert_double_eq_tol(omega, g[i][1], 1e-12 * omega);
        ck_assert_double_eq_tol(zeta, g[i][2], 1e-12);
    }
    const double down[2] = {2.0, 1.0}, neg[2] = {-1.0, 1.0}, nan_[2] = {1.0, NAN};
    ck_assert_int_eq(fricreg_hb_nma_at(NULL, 0, 0, 2, levels), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_nma_at(hb, 0, 0, 2, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_nma_at(hb, 0, 0, 0, levels), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma_at(hb, 0, 0, 2, down), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "increase"));
    ck_assert_int_eq(fricreg_hb_nma_at(hb, 0, 0, 2, neg), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma_at(hb, 0, 0, 2, nan_), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_hb_nma_at(hb, 1, 0, 2, levels), FRICREG_EINVAL); /* mode 1 of 1 */
    ck_assert_int_eq(fricreg_hb_nma_at(hb, 0, 7, 2, levels), FRICREG_EINVAL); /* damping */
    ck_assert_uint_eq(fricreg_hb_nma_points(hb), np); /* refused before: the last kept */
    fricreg_hb_free(hb);
}
END_TEST

/* (b) H = 7: the backbone starts at the linear mode, ω = √3, ζ = 0, and ω falls once the
 * element slips. */
START_TEST(oscillator_h7_starts_linear)
{
    fricreg_hb *hb = oscillator(7);
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.1, 100.0, 12),
                     FRICREG_OK);
    double a, omega, zeta, prev = INFINITY;
    ck_assert_int_eq(fricreg_hb_nma_point(hb, 0, &a, &omega, &zeta, 0, 0, NULL), FRICREG_OK);
    ck_assert_double_eq_tol(omega, sqrt(3.0), 1e-12);
    ck_assert_double_eq_tol(zeta, 0.0, 1e-12);
    for (size_t i = 0; i < 12; i++) {
        ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &a, &omega, &zeta, 0, 0, NULL), FRICREG_OK);
        ck_assert_double_le(omega, prev + 1e-12);
        ck_assert(zeta >= -1e-12 && zeta < 0.5);
        prev = omega;
    }
    ck_assert_double_lt(omega, 1.1); /* a = 100: mostly slipping, toward k = 1 */
    fricreg_hb_free(hb);
}
END_TEST

/* (d) modal damping: two dofs, M = I, K = [2 -1; -1 2], a non-proportional C = diag(0.1, 0),
 * a Jenkins element on dof 0 (kt = 1, mu N = 100: stuck at a = 0.1). The stuck structure's
 * K_0 = [3 -1; -1 2] has λ_1 = (5 − √5)/2 and φ = (1, 3 − λ_1)/norm, so with
 * FRICREG_HB_NMA_DAMPING_MODAL (C replaced by ξ_1 M, ξ_1 = φ^T C φ = 0.1 φ_0²) the linear
 * mode is exact: ω = √λ_1, ζ = ξ_1/(2ω), to 1e-9. With the matrix C the mode couples to the
 * second one: ω and ζ move by 4.5e-4 and 1.3e-3 (measured), so the option must reach the
 * solve. */
START_TEST(modal_damping_closed_form)
{
    const double M[4] = {1, 0, 0, 1}, K[4] = {2, -1, -1, 2}, C[4] = {0.1, 0, 0, 0}, J[2] = {1, 0},
                 kt = 1.0, mun = 100.0;
    const double lambda = 0.5 * (5.0 - sqrt(5.0)), v1 = 3.0 - lambda;
    const double omega_ref = sqrt(lambda), zeta_ref = 0.1 / (1.0 + v1 * v1) / (2.0 * omega_ref);
    double omega[2], zeta[2];
    for (int modal = 0; modal < 2; modal++) {
        fricreg_hb *hb = NULL;
        ck_assert_int_eq(fricreg_hb_create(2, 1, 3, &hb), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_set_mass(hb, 2, M), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, K), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_set_damping(hb, 2, C), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, 2, J, &kt, &mun), FRICREG_OK);
        int damping = modal ? FRICREG_HB_NMA_DAMPING_MODAL : FRICREG_HB_NMA_DAMPING_MATRIX;
        ck_assert_int_eq(fricreg_hb_nma(hb, 0, damping, 0.1, 1.0, 3), FRICREG_OK);
        double a;
        ck_assert_int_eq(fricreg_hb_nma_point(hb, 0, &a, &omega[modal], &zeta[modal], 0, 0, NULL),
                         FRICREG_OK);
        fricreg_hb_free(hb);
    }
    ck_assert_double_eq_tol(omega[1], omega_ref, 1e-9 * omega_ref);
    ck_assert_double_eq_tol(zeta[1], zeta_ref, 1e-9 * zeta_ref);
    ck_assert_double_gt(fabs(omega[0] - omega_ref), 1e-4 * omega_ref);
}
END_TEST

/* (c) bad input: each status, nothing written, the points of an earlier call kept by a refused
 * one; the forced response unchanged by a backbone. */
START_TEST(bad_input)
{
    fricreg_hb *hb = oscillator(3);
    const int modal = FRICREG_HB_NMA_DAMPING_MODAL;
    ck_assert_int_eq(fricreg_hb_nma(NULL, 0, modal, 0.1, 1.0, 4), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_nma(hb, 1, modal, 0.1, 1.0, 4), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, 2, 0.1, 1.0, 4), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, modal, 1.0, 1.0, 4), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, modal, 2.0, 1.0, 4), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, modal, 0.0, 1.0, 4), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, modal, 0.1, NAN, 4), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, modal, 0.1, 1.0, 1), FRICREG_EINVAL);
    ck_assert_uint_eq(fricreg_hb_nma_points(hb), 0);
    ck_assert_uint_eq(fricreg_hb_nma_points(NULL), 0);

    /* the forced response before and after a backbone */
    const double pc = 0.7, ps = 0.0, c = 0.05;
    double x0[7], x1[7], q[7];
    ck_assert_int_eq(fricreg_hb_set_damping(hb, 1, &c), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, 1, &pc, &ps), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.3, 7, NULL, q), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_displacement(hb, 1, 7, x0), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, modal, 0.1, 10.0, 5), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_displacement(hb, 1, 7, x1), FRICREG_OK);
    for (int j = 0; j < 7; j++)
        ck_assert_double_eq(x0[j], x1[j]);

    double a = -1.0, w = -1.0, z = -1.0, x[7] = {0};
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, modal, 0.1, 1.0, 1), FRICREG_EINVAL);
    ck_assert_uint_eq(fricreg_hb_nma_points(hb), 5); /* refused: the earlier points stay */
    ck_assert_int_eq(fricreg_hb_nma_point(hb, 5, &a, &w, &z, 0, 0, NULL), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma_point(hb, 0, NULL, &w, &z, 0, 0, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_nma_point(hb, 0, &a, &w, &z, 2, 7, x), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_hb_nma_point(hb, 0, &a, &w, &z, 1, 5, x), FRICREG_ESIZE);
    ck_assert(a == -1.0 && w == -1.0 && z == -1.0 && x[0] == 0.0);
    ck_assert_int_eq(fricreg_hb_nma_point(NULL, 0, &a, &w, &z, 0, 0, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 1, &c), FRICREG_OK); /* the model changes */
    ck_assert_int_eq(fricreg_hb_nma_point(hb, 0, &a, &w, &z, 1, 7, x), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma_point(hb, 0, &a, &w, &z, 0, 0, NULL), FRICREG_OK);
    fricreg_hb_free(hb);

    /* no elements yet */
    ck_assert_int_eq(fricreg_hb_create(2, 1, 3, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, modal, 0.1, 1.0, 4), FRICREG_EINVAL);
    /* M not positive definite: eigenvalues 3 and −1 */
    const double M[4] = {1, 2, 2, 1}, K[4] = {2, -1, -1, 2}, J[2] = {1, 0}, kt = 1, mun = 1;
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 2, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, 2, J, &kt, &mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, modal, 0.1, 1.0, 4), FRICREG_ENOTPSD);
    ck_assert_int_eq(fricreg_hb_errcode(hb), FRICREG_ENOTPSD);
    ck_assert_uint_eq(fricreg_hb_nma_points(hb), 0);
    fricreg_hb_free(hb);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("hb_nma");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, oscillator_closed_form);
    tcase_add_test(tc, oscillator_at_amplitudes);
    tcase_add_test(tc, oscillator_h7_starts_linear);
    tcase_add_test(tc, bad_input);
    tcase_add_test(tc, modal_damping_closed_form);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
