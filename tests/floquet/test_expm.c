/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_expm.c — Check suite for the matrix exponential of the exact monodromy (white box:
 * src/floquet/expm.c, on the static library).
 *
 * Where the numbers come from: the closed forms of e^(tA) for a matrix of known blocks seen
 * through a rotation, A = Q B Qᵀ with B = diag of a damped oscillator's block
 * [[−ζ, ω], [−ω, −ζ]] (e^(tB) = e^(−ζt) [[cos ωt, sin ωt], [−sin ωt, cos ωt]]) and a Jordan
 * block [[λ, 1], [0, λ]] (e^(tB) = e^(λt) [[1, t], [0, 1]]), so e^(tA) = Q e^(tB) Qᵀ; at values
 * of t that put ‖tA‖₁ in each approximant's range (Higham 2005: degree 3, 5, 7, 9 up to θ₉ =
 * 2.1, then degree 13 and its squarings). Higham's approximants are exact to the unit roundoff
 * in backward error: the forward error here is bounded by a few hundred ulps of ‖e^(tA)‖. The
 * same closed forms from the powers of A kept once (fr_hb_expm_at, the monodromy's pieces met
 * again at another duration). */
#include <check.h>
#include <math.h>
#include <string.h>

#include "floquet/expm.h"

enum { P = 4 };

/* Q: a rotation in the (0, 2) and (1, 3) planes, dense enough that no entry of A is zero. */
static void rotation(double Q[P][P])
{
    const double c = 0.6, s = 0.8, c2 = cos(0.3), s2 = sin(0.3);
    double R1[P][P] = {{c, 0, -s, 0}, {0, 1, 0, 0}, {s, 0, c, 0}, {0, 0, 0, 1}};
    double R2[P][P] = {{1, 0, 0, 0}, {0, c2, 0, -s2}, {0, 0, 1, 0}, {0, s2, 0, c2}};
    double R3[P][P] = {{c2, -s2, 0, 0}, {s2, c2, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    double T[P][P] = {{0}};
    for (int i = 0; i < P; i++)
        for (int j = 0; j < P; j++)
            for (int k = 0; k < P; k++)
                T[i][j] += R1[i][k] * R2[k][j];
    memset(Q, 0, sizeof(double) * P * P);
    for (int i = 0; i < P; i++)
        for (int j = 0; j < P; j++)
            for (int k = 0; k < P; k++)
                Q[i][j] += T[i][k] * R3[k][j];
}

/* X = Q B Qᵀ, column-major into x[P P]. */
static void conjugate(double Q[P][P], double B[P][P], double *x)
{
    for (int i = 0; i < P; i++)
        for (int j = 0; j < P; j++) {
            double v = 0.0;
            for (int k = 0; k < P; k++)
                for (int l = 0; l < P; l++)
                    v += Q[i][k] * B[k][l] * Q[j][l];
            x[j * P + i] = v;
        }
}

/* B and e^(tB) of the blocks above at t. */
static void blocks(double t, double B[P][P], double expB[P][P])
{
    const double zeta = 0.3, omega = 2.0, lambda = -0.5;
    double B0[P][P] = {{-zeta, omega, 0, 0},
                       {-omega, -zeta, 0, 0},
                       {0, 0, lambda, 1},
                       {0, 0, 0, lambda}};
    double d = exp(-zeta * t), c = cos(omega * t), s = sin(omega * t), e = exp(lambda * t);
    double E0[P][P] = {{d * c, d * s, 0, 0}, {-d * s, d * c, 0, 0}, {0, 0, e, e * t}, {0, 0, 0, e}};
    for (int i = 0; i < P; i++)
        for (int j = 0; j < P; j++) {
            B[i][j] = t * B0[i][j];
            expB[i][j] = E0[i][j];
        }
}

START_TEST(test_closed_forms_in_every_approximant)
{
    /* ‖tA‖₁ = 3.108 t: degrees 3, 5, 7 and 9, then 13 with 0, 1, 5 and 8 squarings */
    const double ts[] = {0.001, 0.05, 0.2, 0.6, 1.5, 3.0, 40.0, 300.0};
    double Q[P][P], B[P][P], expB[P][P], a[P * P], want[P * P], got[P * P], work[6 * P * P];
    int piv[P];
    rotation(Q);
    for (size_t k = 0; k < sizeof ts / sizeof ts[0]; k++) {
        blocks(ts[k], B, expB);
        conjugate(Q, B, a);
        conjugate(Q, expB, want);
        ck_assert_int_eq(fr_hb_expm(a, P, got, work, piv), 0);
        double scale = 0.0, err = 0.0;
        for (int i = 0; i < P * P; i++) {
            scale = fmax(scale, fabs(want[i]));
            err = fmax(err, fabs(got[i] - want[i]));
        }
        ck_assert_msg(err <= 500 * 0x1p-52 * scale * (1.0 + ts[k]),
                      "t = %g: e^(tA) off by %.3g of %.3g", ts[k], err, scale);
    }
}
END_TEST

/* e^(tA) from A's powers at t = 1, kept once, over the same t: every approximant again. */
START_TEST(test_closed_forms_from_kept_powers)
{
    const double ts[] = {0.0, 0.001, 0.05, 0.2, 0.6, 1.5, 3.0, 40.0, 300.0};
    double Q[P][P], B[P][P], expB[P][P], a[P * P], pow[5 * P * P], want[P * P], got[P * P],
        work[6 * P * P];
    int piv[P];
    rotation(Q);
    blocks(1.0, B, expB);
    conjugate(Q, B, a);
    double nu = fr_hb_expm_powers(a, P, pow);
    ck_assert_double_eq_tol(nu, 3.108, 1e-3);
    for (size_t k = 0; k < sizeof ts / sizeof ts[0]; k++) {
        blocks(ts[k], B, expB);
        conjugate(Q, expB, want);
        ck_assert_int_eq(fr_hb_expm_at(pow, nu, P, ts[k], got, work, piv), 0);
        double scale = 0.0, err = 0.0;
        for (int i = 0; i < P * P; i++) {
            scale = fmax(scale, fabs(want[i]));
            err = fmax(err, fabs(got[i] - want[i]));
        }
        ck_assert_msg(err <= 500 * 0x1p-52 * scale * (1.0 + ts[k]),
                      "t = %g: e^(tA) from the kept powers off by %.3g of %.3g", ts[k], err, scale);
    }
}
END_TEST

/* A non-finite entry: −1 and E not written. */
START_TEST(test_not_finite)
{
    double a[4] = {1.0, 0.0, INFINITY, 1.0}, e[4] = {7.0, 7.0, 7.0, 7.0}, work[24];
    int piv[2];
    ck_assert_int_eq(fr_hb_expm(a, 2, e, work, piv), -1);
    for (int i = 0; i < 4; i++)
        ck_assert(e[i] == 7.0);
    double pow[20] = {0}, b[4] = {1.0, 0.0, 0.0, 1.0};
    ck_assert(fr_hb_expm_powers(a, 2, pow) == INFINITY);
    double nu = fr_hb_expm_powers(b, 2, pow);
    ck_assert_int_eq(fr_hb_expm_at(pow, nu, 2, INFINITY, e, work, piv), -1);
    for (int i = 0; i < 4; i++)
        ck_assert(e[i] == 7.0);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("expm");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, test_closed_forms_in_every_approximant);
    tcase_add_test(tc, test_closed_forms_from_kept_powers);
    tcase_add_test(tc, test_not_finite);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
