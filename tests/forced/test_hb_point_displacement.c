/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_point_displacement.c — Check suite for the displacements' coefficients of a stored
 * continuation point (fricreg_hb_point_displacement; fricreg_hb.h).
 *
 * The model: the Jenkins oscillator of test_hb_level.c — m = 1, k = 1, c = 0.02, one Jenkins
 * element kt = 2 on the dof, mu N = 0.5 (slips) or 1e6 (stuck), p_c = 1, H = 7.
 *
 * Where the numbers come from:
 *   - each point's RMS (fricreg_hb_point, stored while the branch ran) against the RMS of its
 *     recomputed coefficients, sqrt(x0² + Σ (a_h² + b_h²)/2): the same sums of the same
 *     factors and forces, to 1e-14;
 *   - the last point against fricreg_hb_displacement, which recomputes the same solution:
 *     bit for bit;
 *   - each point against a point solve at its Ω from the previous point solve (a natural-
 *     parameter walk: none of the continuation's machinery), both converged to Newton's 1e-10:
 *     to 1e-8 of the largest coefficient;
 *   - stuck, (HB) is linear: each point of a branch in the level λ is λ times the point solve
 *     at λ = 1, to 1e-10;
 *   - a driver that read every point against one that read none: the same peak and later
 *     solve, bit for bit. */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_hb.h"

#define H 7
#define NC (2 * H + 1)
#define MAXP 400
#define SENTINEL (-777.125)

static fricreg_hb *oscillator(double mun)
{
    fricreg_hb *hb = NULL;
    const double one = 1.0, c = 0.02, kt = 2.0, zero = 0.0;
    ck_assert_int_eq(fricreg_hb_create(1, 1, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 1, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 1, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, 1, &c), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, 1, &one, &kt, &mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, 1, &one, &zero), FRICREG_OK);
    return hb;
}

static double rms_of(const double *x)
{
    double s = 0.0;
    for (int c = 0; c < NC; c++)
        s += (c == 0 ? 1.0 : 0.5) * x[c] * x[c];
    return sqrt(s);
}

static double largest(const double *x)
{
    double a = 0.0;
    for (int c = 0; c < NC; c++)
        a = fmax(a, fabs(x[c]));
    return a;
}

static double omega_buf[MAXP], x_buf[MAXP * NC];

START_TEST(omega_branch)
{
    fricreg_hb *hb = oscillator(0.5);
    ck_assert_int_eq(fricreg_hb_continue(hb, 1.2, 1.8, NC, NULL), FRICREG_OK);
    size_t np = fricreg_hb_points(hb);
    ck_assert_uint_ge(np, 5);
    ck_assert_uint_le(np, MAXP);
    for (size_t k = 0; k < np; k++) {
        double rms;
        ck_assert_int_eq(fricreg_hb_point(hb, k, &omega_buf[k], 1, &rms), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_point_displacement(hb, k, 1, NC, x_buf + k * NC), FRICREG_OK);
        ck_assert_double_le(fabs(rms_of(x_buf + k * NC) - rms), 1e-14 * rms);
    }
    double x[NC];
    ck_assert_int_eq(fricreg_hb_displacement(hb, 1, NC, x), FRICREG_OK);
    ck_assert_mem_eq(x, x_buf + (np - 1) * NC, sizeof x);
    ck_assert_int_eq(fricreg_hb_point_displacement(hb, FRICREG_HB_SOLUTION, 1, NC, x), FRICREG_OK);
    ck_assert_mem_eq(x, x_buf + (np - 1) * NC, sizeof x);
    /* the natural-parameter walk: the points keep their branch (a point solve replaces only the
     * last solution) */
    double q[NC], *guess = NULL;
    for (size_t k = 0; k < np; k++, guess = q) {
        ck_assert_int_eq(fricreg_hb_solve(hb, omega_buf[k], NC, guess, q), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_displacement(hb, 1, NC, x), FRICREG_OK);
        const double *xk = x_buf + k * NC;
        for (int c = 0; c < NC; c++)
            ck_assert_double_le(fabs(x[c] - xk[c]), 1e-8 * largest(xk));
    }
    ck_assert_uint_eq(fricreg_hb_points(hb), np);
    fricreg_hb_free(hb);
}
END_TEST

START_TEST(level_branch_stuck)
{
    fricreg_hb *hb = oscillator(1e6);
    ck_assert_int_eq(fricreg_hb_continue_level(hb, 1.5, 0.1, 2.5, NC, NULL), FRICREG_OK);
    size_t np = fricreg_hb_points(hb);
    ck_assert_uint_ge(np, 3);
    double q[NC], unit[NC], x[NC];
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.5, NC, NULL, q), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_displacement(hb, 1, NC, unit), FRICREG_OK);
    for (size_t k = 0; k < np; k++) {
        double level;
        ck_assert_int_eq(fricreg_hb_point_level(hb, k, &level), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_point_displacement(hb, k, 1, NC, x), FRICREG_OK);
        for (int c = 0; c < NC; c++)
            ck_assert_double_le(fabs(x[c] - level * unit[c]), 1e-10 * level * largest(unit));
    }
    fricreg_hb_free(hb);
}
END_TEST

/* A getter changes no later result: the located peak and a later solve from the branch's
 * end, after every point's coefficients were read, equal those of a driver that read none, bit
 * for bit. */
START_TEST(reading_changes_no_result)
{
    double peak[2][2], q[2][NC], x[NC];
    for (int read = 0; read < 2; read++) {
        fricreg_hb *hb = oscillator(0.5);
        ck_assert_int_eq(fricreg_hb_continue(hb, 1.2, 1.8, NC, NULL), FRICREG_OK);
        for (size_t k = 0; read && k < fricreg_hb_points(hb); k++)
            ck_assert_int_eq(fricreg_hb_point_displacement(hb, k, 1, NC, x), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_peak(hb, 0, &peak[read][0], &peak[read][1]), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_solve(hb, 1.5, NC, NULL, q[read]), FRICREG_OK);
        fricreg_hb_free(hb);
    }
    ck_assert_mem_eq(peak[0], peak[1], sizeof peak[0]);
    ck_assert_mem_eq(q[0], q[1], sizeof q[0]);
}
END_TEST

static void assert_untouched(const double *x)
{
    for (int c = 0; c < NC; c++)
        ck_assert_double_eq(x[c], SENTINEL);
}

START_TEST(bad_input)
{
    fricreg_hb *hb = oscillator(0.5);
    double x[NC], c2 = 0.04;
    for (int c = 0; c < NC; c++)
        x[c] = SENTINEL;
    ck_assert_int_eq(fricreg_hb_point_displacement(hb, 0, 1, NC, x), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_point_displacement(hb, FRICREG_HB_SOLUTION, 1, NC, x),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_continue(hb, 1.2, 1.4, NC, NULL), FRICREG_OK);
    size_t np = fricreg_hb_points(hb);
    ck_assert_int_eq(fricreg_hb_point_displacement(NULL, 0, 1, NC, x), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_point_displacement(hb, 0, 1, NC, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_point_displacement(hb, 0, 2, NC, x), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_hb_point_displacement(hb, 0, 1, NC - 1, x), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_hb_point_displacement(hb, np, 1, NC, x), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "points stored"));
    assert_untouched(x);
    /* a changed model leaves the points' Ω and RMS but not the model they solved */
    ck_assert_int_eq(fricreg_hb_set_damping(hb, 1, &c2), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_point_displacement(hb, 0, 1, NC, x), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "changed since the branch"));
    assert_untouched(x);
    fricreg_hb_free(hb);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("hb_point_displacement");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, omega_branch);
    tcase_add_test(tc, level_branch_stuck);
    tcase_add_test(tc, reading_changes_no_result);
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
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
