/* SPDX-License-Identifier: GPL-3.0-or-later */
/* aft_normal_checks.c — the lift-off AFT suites' shared checks (aft_normal_checks.h). */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "aft_normal_checks.h"
#include "fricreg_jenkins.h"
#include "quiet_check.h"

#define MAX_NC 15 /* the suites' 2H + 1, and room for more */
static const double PI = 3.14159265358979323846;

double aft_normal_at(int harmonics, const double *c, double th)
{
    double v = c[0];
    for (int h = 1; h <= harmonics; h++)
        v += c[2 * h - 1] * cos(h * th) + c[2 * h] * sin(h * th);
    return v;
}

void aft_normal_time_domain(int harmonics, size_t ns, double kt, double mu, double n0, double kn,
                            const double *u, const double *g, double *f, double *nf)
{
    size_t nc = 2 * (size_t)harmonics + 1;
    fricreg_jenkins *j = NULL;
    double one = 1.0;
    ck_assert_int_eq(fricreg_jenkins_create(1, 1, &j), FRICREG_OK);
    ck_assert_int_eq(fricreg_jenkins_set_params(j, 1, &kt, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_jenkins_set_normal(j, 1, &mu, &n0, &kn), FRICREG_OK);
    memset(f, 0, nc * sizeof *f);
    memset(nf, 0, nc * sizeof *nf);
    for (int p = 0; p < 3; p++)
        for (size_t n = 0; n < ns; n++) {
            double th = 2.0 * PI * (double)n / (double)ns, fn, nn;
            double un = aft_normal_at(harmonics, u, th), gn = aft_normal_at(harmonics, g, th);
            QUIET_OK(fricreg_jenkins_trial_normal(j, 1, &un, &gn, &fn, &nn, NULL, NULL));
            QUIET_OK(fricreg_jenkins_commit(j));
            if (p < 2)
                continue;
            f[0] += fn / (double)ns;
            nf[0] += nn / (double)ns;
            for (int h = 1; h <= harmonics; h++) {
                double c = 2.0 * cos(h * th) / (double)ns, s = 2.0 * sin(h * th) / (double)ns;
                f[2 * h - 1] += fn * c;
                f[2 * h] += fn * s;
                nf[2 * h - 1] += nn * c;
                nf[2 * h] += nn * s;
            }
        }
    fricreg_jenkins_free(j);
}

static void check_case(fricreg_aft *a, aft_normal_fn path, size_t ns, double tol, double kt,
                       double mu, double n0, double kn, const double *u, const double *g,
                       const char *what)
{
    enum { NC = 7 };
    double f[NC], nf[NC], ft[NC], nft[NC], normal = fabs(n0) + kn * 4.0;
    ck_assert_int_eq(path(a, kt, mu, n0, kn, NC, u, g, f, nf, NULL), FRICREG_OK);
    aft_normal_time_domain(3, ns, kt, mu, n0, kn, u, g, ft, nft);
    for (int i = 0; i < NC; i++) {
        ck_assert_msg(fabs(f[i] - ft[i]) < tol * mu * normal,
                      "%s: f[%d] = %.15g, time domain %.15g", what, i, f[i], ft[i]);
        ck_assert_msg(fabs(nf[i] - nft[i]) < tol * normal, "%s: nf[%d] = %.15g, time domain %.15g",
                      what, i, nf[i], nft[i]);
    }
}

void aft_normal_check_time_domain_cases(fricreg_aft *a, aft_normal_fn path, size_t ns, double tol)
{
    ck_assert_int_eq(fricreg_aft_harmonics(a), 3);
    const double u1[7] = {0.0, 1.0, 0.0, 0, 0, 0, 0}, g1[7] = {0.0, 0.0, 1.5, 0, 0, 0, 0};
    const double u2[7] = {0.1, 1.2, 0.0, 0.0, 0.3, 0, 0};
    const double g2[7] = {0.0, 0.8 * 0.955336489125606, -0.8 * 0.29552020666134, 0, 0, 0, 0};
    const double u3[7] = {0.0, 0.05, 0.0, 0, 0, 0, 0};
    check_case(a, path, ns, tol, 2.0, 0.5, 1.0, 1.0, u1, g1, "lift-off");
    check_case(a, path, ns, tol, 3.0, 0.4, 2.0, 1.0, u2, g2, "moving bound");
    check_case(a, path, ns, tol, 3.0, 0.4, 2.0, 1.0, u3, g2, "stuck");
}

void aft_normal_check_jacobian(fricreg_aft *a, aft_normal_fn path, double kt, double mu, double n0,
                               double kn, const double *u, const double *g)
{
    size_t nc = 2 * (size_t)fricreg_aft_harmonics(a) + 1;
    ck_assert_uint_le(nc, MAX_NC);
    double f[MAX_NC], nf[MAX_NC], jac[4 * MAX_NC * MAX_NC], x[2 * MAX_NC], h = 1e-6;
    double scale = fmax(kt, kn);
    memcpy(x, u, nc * sizeof *u);
    memcpy(x + nc, g, nc * sizeof *g);
    ck_assert_int_eq(path(a, kt, mu, n0, kn, nc, u, g, f, nf, jac), FRICREG_OK);
    for (size_t j = 0; j < 2 * nc; j++) {
        double xp[2 * MAX_NC], xm[2 * MAX_NC], fp[MAX_NC], fm[MAX_NC], np[MAX_NC], nm[MAX_NC];
        memcpy(xp, x, 2 * nc * sizeof *x);
        memcpy(xm, x, 2 * nc * sizeof *x);
        xp[j] += h;
        xm[j] -= h;
        ck_assert_int_eq(path(a, kt, mu, n0, kn, nc, xp, xp + nc, fp, np, NULL), FRICREG_OK);
        ck_assert_int_eq(path(a, kt, mu, n0, kn, nc, xm, xm + nc, fm, nm, NULL), FRICREG_OK);
        for (size_t i = 0; i < nc; i++) {
            double df = (fp[i] - fm[i]) / (2 * h), dn = (np[i] - nm[i]) / (2 * h);
            ck_assert_msg(fabs(df - jac[2 * nc * i + j]) < 1e-6 * scale,
                          "df[%zu]/dx[%zu] = %.12g, differences %.12g", i, j, jac[2 * nc * i + j],
                          df);
            ck_assert_msg(fabs(dn - jac[2 * nc * (nc + i) + j]) < 1e-6 * scale,
                          "dN[%zu]/dx[%zu] = %.12g, differences %.12g", i, j,
                          jac[2 * nc * (nc + i) + j], dn);
        }
    }
}

void aft_normal_check_bad_input(fricreg_aft *a, aft_normal_fn path, const char *name)
{
    enum { NC = 7 };
    static const double SENTINEL = -777.125;
    ck_assert_int_eq(fricreg_aft_harmonics(a), 3);
    char expect[128];
    const double u[NC] = {0.3, 1.0, 0, 0, 0, 0, 0}, g[NC] = {0.1, 0.2, 0, 0, 0, 0, 0};
    double f[NC], nf[NC], jac[4 * NC * NC], bad[NC];
    for (int i = 0; i < NC; i++)
        f[i] = nf[i] = SENTINEL;
    ck_assert_int_eq(path(NULL, 1, 1, 1, 1, NC, u, g, f, nf, jac), FRICREG_ENULL);
    ck_assert_int_eq(path(a, 1, 1, 1, 1, NC, u, NULL, f, nf, jac), FRICREG_ENULL);
    snprintf(expect, sizeof expect, "%s: g", name);
    ck_assert_ptr_nonnull(strstr(fricreg_aft_errmsg(a), expect));
    ck_assert_int_eq(path(a, 1, 1, 1, 1, NC, u, g, f, NULL, jac), FRICREG_ENULL);
    ck_assert_int_eq(path(a, 1, 1, 1, 1, NC, NULL, g, f, nf, jac), FRICREG_ENULL);
    ck_assert_int_eq(path(a, 1, 1, 1, 1, NC - 2, u, g, f, nf, jac), FRICREG_ESIZE);
    ck_assert_int_eq(path(a, 0, 1, 1, 1, NC, u, g, f, nf, jac), FRICREG_EINVAL);
    ck_assert_int_eq(path(a, 1, -1, 1, 1, NC, u, g, f, nf, jac), FRICREG_EINVAL);
    ck_assert_int_eq(path(a, 1, 1, 1, -1, NC, u, g, f, nf, jac), FRICREG_EINVAL);
    snprintf(expect, sizeof expect, "%s: kn = -1 must be >= 0", name);
    ck_assert_str_eq(fricreg_aft_errmsg(a), expect);
    ck_assert_int_eq(path(a, 1, 1, NAN, 1, NC, u, g, f, nf, jac), FRICREG_ENONFINITE);
    memcpy(bad, g, sizeof bad);
    bad[2] = INFINITY;
    ck_assert_int_eq(path(a, 1, 1, 1, 1, NC, u, bad, f, nf, jac), FRICREG_ENONFINITE);
    ck_assert_int_eq(path(a, 1, 1, 1e308, 1, NC, u, g, f, nf, jac), FRICREG_ENONFINITE);
    for (int i = 0; i < NC; i++) {
        ck_assert_double_eq(f[i], SENTINEL);
        ck_assert_double_eq(nf[i], SENTINEL);
    }
    ck_assert_int_eq(fricreg_aft_errcode(a), FRICREG_ENONFINITE);
}

void aft_normal_check_nearest_stuck(fricreg_aft *a, aft_normal_fn path, double tol)
{
    enum { NC = 7 };
    const double n0s[] = {1.0, 1.2, 1.4, 1.5 - 1e-9, 1.5 + 1e-9, 1.7};
    const double u[NC] = {0.0, 1.0, 0, 0, 0, 0, 0}, g[NC] = {0.0, 0.5, 0, 0, 0, 0, 0};
    ck_assert_int_eq(fricreg_aft_harmonics(a), 3);
    for (size_t k = 0; k < sizeof n0s / sizeof n0s[0]; k++) {
        double f[NC], nf[NC];
        ck_assert_int_eq(path(a, 1.0, 1.0, n0s[k], 1.0, NC, u, g, f, nf, NULL), FRICREG_OK);
        double f0 = fmax(0.0, 1.5 - n0s[k]);
        ck_assert_msg(fabs(f[0] - f0) <= tol && fabs(f[1] - 1.0) <= tol,
                      "n0 = %.12g: f0 = %.12g, a1 = %.12g; expected %.12g, 1", n0s[k], f[0], f[1],
                      f0);
        for (int i = 2; i < NC; i++)
            ck_assert_double_le(fabs(f[i]), tol);
    }
    aft_normal_check_jacobian(a, path, 1.0, 1.0, 1.2, 1.0, u, g);
}
