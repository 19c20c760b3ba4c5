/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_element_dahl.c — Check suite for the element type dahl (fricreg_element.h): Dahl's
 * model with exponent 1, dF/du = sigma (1 - sgn(du) F / fc).
 *
 * Where the numbers come from:
 *   - Dahl's ODE solved in closed form along a monotone path, F = s fc - (s fc - F0)
 *     exp(-sigma |u - u0| / fc), so under u = A sin(2 pi t) the settled loop's rising branch
 *     is F(u) = fc - (fc + Fm) exp(-sigma (u + A) / fc), its peak Fm = fc tanh(sigma A / fc)
 *     (Fm = F(A) with F(-A) = -Fm), at every sample whatever the number of samples: the law
 *     integrates each increment exactly;
 *   - the loop's area 2 * integral of the rising branch, 4 A fc - 2 (fc + Fm) (fc / sigma)
 *     (1 - exp(-2 sigma A / fc)), which fricreg_element_energy's backward-Euler dissipation
 *     reaches at first order in the increment (the error halves with it);
 *   - the tangent and the parameter derivatives against central differences; at u = u0 the
 *     reversal's tangent sigma (1 + |F0| / fc);
 *   - the failures the header lists. */
#include <check.h>
#include <math.h>

#include "fricreg_element.h"
#include "quiet_check.h"

#define TWO_PI 6.283185307179586
#define SIGMA 3.0
#define FC 0.5

static const fricreg_element_type *dahl(void)
{
    const fricreg_element_type *t = fricreg_element_lookup("dahl");
    ck_assert_ptr_nonnull(t);
    return t;
}

/* cycles of u = A sin(2 pi i / n) from rest; the force at each sample of the last cycle into
 * F[n + 1] (F[0] at the cycle's start), and the last cycle's dissipation by
 * fricreg_element_energy into *D. */
static void loop(int n, int cycles, double A, double *F, double *D)
{
    const double p[2] = {SIGMA, FC};
    double w[2], f[1], u[1];
    ck_assert_int_eq(fricreg_element_init(dahl(), p, w), FRICREG_OK);
    *D = 0.0;
    for (int c = 0; c < cycles; c++)
        for (int i = 1; i <= n; i++) {
            double d, e;
            u[0] = A * sin(TWO_PI * i / n);
            QUIET_OK(fricreg_element_energy(dahl(), p, w, u, &d, &e));
            QUIET_OK(fricreg_element_eval(dahl(), p, w, u, f, NULL, NULL, w));
            if (c == cycles - 1) {
                F[i] = f[0];
                *D += d;
            } else if (i == n) {
                F[0] = f[0];
            }
        }
}

START_TEST(test_closed_form_loop)
{
    const double A = 0.4, Fm = FC * tanh(SIGMA * A / FC);
    for (int n = 16; n <= 64; n *= 4) {
        double F[65], D;
        loop(n, 8, A, F, &D);
        ck_assert_msg(fabs(F[n / 4] - Fm) <= 1e-13, "n %d: peak %.17g, closed form %.17g", n,
                      F[n / 4], Fm);
        /* the rising branch from the trough at 3 n / 4 to the next peak at n / 4 (+ n) */
        for (int i = 3 * n / 4; i <= n + n / 4; i++) {
            double u = A * sin(TWO_PI * i / n), Fi = i <= n ? F[i] : F[i - n];
            double want = FC - (FC + Fm) * exp(-SIGMA * (u + A) / FC);
            ck_assert_msg(fabs(Fi - want) <= 1e-13, "n %d, sample %d: %.17g, closed form %.17g", n,
                          i, Fi, want);
        }
    }
}
END_TEST

START_TEST(test_dissipation_converges_at_first_order)
{
    const double A = 0.4, Fm = FC * tanh(SIGMA * A / FC);
    const double area = 4.0 * A * FC -
                        2.0 * (FC + Fm) * (FC / SIGMA) * (1.0 - exp(-2.0 * SIGMA * A / FC));
    static double F[4097];
    double err[2];
    for (int k = 0; k < 2; k++) {
        double D;
        loop(2048 << k, 4, A, F, &D);
        err[k] = fabs(D - area);
    }
    ck_assert_msg(err[0] < 2e-3 * area, "error %g of %g", err[0], area);
    ck_assert_msg(fabs(err[0] / err[1] - 2.0) < 0.05, "ratio %g", err[0] / err[1]);
}
END_TEST

/* f and df/du, df/dp at u from state w, against central differences. */
static void check_derivatives(const double *w, double u)
{
    const double p[2] = {SIGMA, FC}, h = 1e-6;
    double f[1], dfdu[1], dfdp[2], ws[2], up[1] = {u + h}, um[1] = {u - h}, fp[1], fm[1];
    double uu[1] = {u};
    ck_assert_int_eq(fricreg_element_eval(dahl(), p, w, uu, f, dfdu, dfdp, ws), FRICREG_OK);
    ck_assert_int_eq(fricreg_element_eval(dahl(), p, w, up, fp, NULL, NULL, ws), FRICREG_OK);
    ck_assert_int_eq(fricreg_element_eval(dahl(), p, w, um, fm, NULL, NULL, ws), FRICREG_OK);
    ck_assert_msg(fabs((fp[0] - fm[0]) / (2 * h) - dfdu[0]) <= 1e-7 * SIGMA, "df/du %.17g",
                  dfdu[0]);
    for (int j = 0; j < 2; j++) {
        double pp[2] = {p[0], p[1]}, pm[2] = {p[0], p[1]};
        pp[j] += h;
        pm[j] -= h;
        ck_assert_int_eq(fricreg_element_eval(dahl(), pp, w, uu, fp, NULL, NULL, ws), FRICREG_OK);
        ck_assert_int_eq(fricreg_element_eval(dahl(), pm, w, uu, fm, NULL, NULL, ws), FRICREG_OK);
        ck_assert_msg(fabs((fp[0] - fm[0]) / (2 * h) - dfdp[j]) <= 1e-7, "df/dp[%d] %.17g", j,
                      dfdp[j]);
    }
}

START_TEST(test_tangents)
{
    const double w[2] = {0.05, 0.1}; /* F0 = sigma (u0 - w) = 0.15 at u0 = 0.1 */
    check_derivatives(w, 0.3);       /* loading */
    check_derivatives(w, -0.2);      /* reversal */
    /* at u = u0: the reversal's tangent sigma (1 + |F0| / fc), the force F0, the state kept */
    const double p[2] = {SIGMA, FC};
    double u[1] = {0.1}, f[1], dfdu[1], ws[2];
    ck_assert_int_eq(fricreg_element_eval(dahl(), p, w, u, f, dfdu, NULL, ws), FRICREG_OK);
    ck_assert(fabs(f[0] - 0.15) <= 1e-16 && fabs(dfdu[0] - SIGMA * (1.0 + 0.15 / FC)) <= 1e-15);
    ck_assert(ws[1] == 0.1 && fabs(ws[0] - 0.05) <= 1e-16);
    /* a cut-back: the same call from the same state, bit for bit */
    double f2[1], dfdu2[1], ws2[2];
    ck_assert_int_eq(fricreg_element_eval(dahl(), p, w, u, f2, dfdu2, NULL, ws2), FRICREG_OK);
    ck_assert(f2[0] == f[0] && dfdu2[0] == dfdu[0] && ws2[0] == ws[0] && ws2[1] == ws[1]);
}
END_TEST

START_TEST(test_failures)
{
    const double w[2] = {0.0, 0.0}, u[1] = {0.1};
    double f[1] = {-7.0}, ws[2] = {-7.0, -7.0};
    char msg[120];
    const double zero_sigma[2] = {0.0, FC}, zero_fc[2] = {SIGMA, 0.0}, nan_p[2] = {NAN, FC};
    ck_assert_int_eq(fricreg_element_eval(dahl(), zero_sigma, w, u, f, NULL, NULL, ws),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_element_explain(dahl(), zero_fc, w, u, msg, sizeof msg),
                     FRICREG_EINVAL);
    ck_assert_str_eq(msg, "dahl: fc = 0 must be > 0 (params[1])");
    ck_assert_int_eq(fricreg_element_eval(dahl(), nan_p, w, u, f, NULL, NULL, ws),
                     FRICREG_ENONFINITE);
    const double tiny_fc[2] = {1e300, 1e-300}, p[2] = {SIGMA, FC}, far_w[2] = {-1e308, 1e308};
    ck_assert_int_eq(fricreg_element_eval(dahl(), tiny_fc, w, u, f, NULL, NULL, ws),
                     FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_element_eval(dahl(), p, far_w, u, f, NULL, NULL, ws),
                     FRICREG_ENONFINITE);
    ck_assert(f[0] == -7.0 && ws[0] == -7.0 && ws[1] == -7.0);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("element_dahl");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, test_closed_form_loop);
    tcase_add_test(tc, test_dissipation_converges_at_first_order);
    tcase_add_test(tc, test_tangents);
    tcase_add_test(tc, test_failures);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
