/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_aft_normal_exact.c — Check suite for the exact AFT of a Jenkins element under normal
 * load with lift-off (fricreg_aft_jenkins_normal_exact, fricreg_aft.h).
 *
 * Where the numbers come from:
 *   - a constant normal force (kn = 0) is the Jenkins element of bound mu N0: the same
 *     coefficients and Jacobian as fricreg_aft_jenkins_exact at mun = mu N0, to rounding
 *     (1e-14 of the force scale), N = N0 exactly, ∂f/∂g = ∂N/∂g = 0;
 *   - open throughout (N0 + kn g < 0 everywhere): f, N and the Jacobian are 0 exactly; mu = 0:
 *     f = 0 and N the closed form;
 *   - the time-domain element (fricreg_jenkins_trial_normal and commit) marched three periods
 *     at NS = 2^18 samples, its last period through a plain DFT: the exact coefficients differ
 *     from it by the sampling error only, measured at 1e-11 of the force scale or below in the
 *     three cases of test_aft_normal.c (lift-off, moving bound, stuck); asserted at 1e-10;
 *   - the sampled path at N = 2^16 on a random sweep with openings: within the force scale
 *     times the sampling interval 2 pi/N (the sampled touchdown sits on a sample: an error of
 *     order u' 2 pi/N in the slider, O(N^-1)), and closer than at N = 1024 (the difference is
 *     the sampled path's error, and it converges);
 *   - the Jacobian against central differences of the same function (step 1e-6, 1e-6 of
 *     the stiffness scale). */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_aft.h"
#include "aft_normal_checks.h"

#define SENTINEL (-777.125)
#define H 3
#define NC (2 * H + 1)
#define NS (1 << 18)
static const double PI = 3.14159265358979323846;

static fricreg_aft *make(int harmonics, size_t samples)
{
    fricreg_aft *a = NULL;
    ck_assert_int_eq(fricreg_aft_create(harmonics, samples, &a), FRICREG_OK);
    return a;
}

/* A reproducible pseudo-random number in [-1, 1] (a 64-bit LCG: no libc rand state). */
static double rnd(unsigned long long *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return 2.0 * (double)(*s >> 11) / 9007199254740992.0 - 1.0;
}

START_TEST(constant_preload_is_jenkins_exact)
{
    fricreg_aft *a = make(H, 0);
    unsigned long long seed = 2385;
    for (int c = 0; c < 8; c++) {
        double u[NC], g[NC], f[NC], nf[NC], jac[4 * NC * NC], fj[NC], jj[NC * NC];
        for (int i = 0; i < NC; i++) {
            u[i] = rnd(&seed) / (1 + i / 2);
            g[i] = rnd(&seed);
        }
        /* slipping, and (c = 7) stuck: kt (max u - min u) <= 2 mu N0 */
        double kt = 2.385, mu = 0.3, n0 = c == 7 ? 40.0 : 0.5 + 0.4 * c, scale = kt + mu * n0;
        ck_assert_int_eq(fricreg_aft_jenkins_normal_exact(a, kt, mu, n0, 0.0, NC, u, g, f, nf, jac),
                         FRICREG_OK);
        ck_assert_int_eq(fricreg_aft_jenkins_exact(a, kt, mu * n0, NC, u, fj, jj), FRICREG_OK);
        for (int i = 0; i < NC; i++) {
            ck_assert_double_eq_tol(f[i], fj[i], 1e-14 * scale);
            ck_assert_double_eq_tol(nf[i], i == 0 ? n0 : 0.0, 1e-14 * n0);
            for (int j = 0; j < NC; j++) {
                ck_assert_double_eq_tol(jac[2 * NC * i + j], jj[NC * i + j], 1e-14 * scale);
                ck_assert_double_eq(jac[2 * NC * i + NC + j], 0.0);        /* df/dg: kn = 0 */
                ck_assert_double_eq(jac[2 * NC * (NC + i) + j], 0.0);      /* dN/du */
                ck_assert_double_eq(jac[2 * NC * (NC + i) + NC + j], 0.0); /* dN/dg */
            }
        }
    }
    fricreg_aft_free(a);
}
END_TEST

/* A bound far below the rounding of u (mu N0 = 1e-200 to 1e-14 against |u| = 1 to 1e10): the
 * force stays within its bound, |f_0| <= mu max N and |f_h| <= 2 mu max N, and with kn = 0 it
 * is fricreg_aft_jenkins_exact's to 1e-6 of mu N0 (it was 6e-15 against mu N0 = 1e-200: the
 * sticks' ends found in the rounding of u − w; the sticks that take no time last below
 * 1e-6 rad, so that is the most they leave out); with kn > 0 (N0 + kn g, g of 1e-3 N0) the
 * same bound on mu (N0 + kn sum |g_j|), and the Fourier coefficients of the pure slip
 * f = mu P sgn(u') (u = 0.5 + cos θ + 0.3 cos 2θ + 0.1 sin 2θ, times 1 to 1e10) to 1e-4 of that
 * bound (the midpoint rule's error at the jumps). */
START_TEST(bound_far_below_the_rounding_of_u)
{
    fricreg_aft *a = make(H, 0);
    const double mus[2] = {1.0, 0.3}, n0s[4] = {1e-200, 1e-100, 1e-20, 1e-14};
    const double bigs[3] = {1.0, 1e5, 1e10};
    for (int c = 0; c < 24; c++) {
        double mu = mus[c % 2], n0 = n0s[c / 2 % 4], big = bigs[c / 8];
        double u[NC] = {0.5 * big, big, 0.0, 0.3 * big, 0.1 * big}, g[NC] = {0}, f[NC], nf[NC],
               fj[NC];
        ck_assert_int_eq(fricreg_aft_jenkins_normal_exact(a, 2.0, mu, n0, 0.0, NC, u, g, f, nf,
                                                          NULL),
                         FRICREG_OK);
        ck_assert_int_eq(fricreg_aft_jenkins_exact(a, 2.0, mu * n0, NC, u, fj, NULL), FRICREG_OK);
        for (int i = 0; i < NC; i++) {
            ck_assert_msg(fabs(f[i]) <= (i == 0 ? 1.0 : 2.0) * mu * n0, "case %d: f[%d] = %g", c, i,
                          f[i]);
            ck_assert_double_eq_tol(f[i], fj[i], 1e-6 * mu * n0);
        }
        /* a moving normal force: P = N0 (1 + 1e-3 cos θ) through kn = 1, never open */
        g[1] = 1e-3 * n0;
        double pmax = n0 * (1.0 + 1e-3), slip[NC] = {0};
        ck_assert_int_eq(fricreg_aft_jenkins_normal_exact(a, 2.0, mu, n0, 1.0, NC, u, g, f, nf,
                                                          NULL),
                         FRICREG_OK);
        /* the pure slip's coefficients by the midpoint rule on 2^16 points (f is smooth
         * between u's four reversals, which the rule's O(1/N) error at the jumps bounds) */
        const int N = 1 << 16;
        for (int k = 0; k < N; k++) {
            double th = 2.0 * PI * (k + 0.5) / N,
                   du = -sin(th) - 0.6 * sin(2 * th) + 0.2 * cos(2 * th);
            double fs = (du > 0.0 ? 1.0 : -1.0) * mu * n0 * (1.0 + 1e-3 * cos(th));
            slip[0] += fs / N;
            for (int h = 1; h <= H; h++) {
                slip[2 * h - 1] += 2.0 * fs * cos(h * th) / N;
                slip[2 * h] += 2.0 * fs * sin(h * th) / N;
            }
        }
        for (int i = 0; i < NC; i++) {
            ck_assert_msg(fabs(f[i]) <= (i == 0 ? 1.0 : 2.0) * mu * pmax, "case %d: f[%d] = %g", c,
                          i, f[i]);
            ck_assert_double_eq_tol(f[i], slip[i], 1e-4 * mu * pmax);
        }
    }
    fricreg_aft_free(a);
}
END_TEST

/* A constant load at any scale: kt and mu of 1e-304 and 1e-200 (u of order 1, N0 = 1; kt
 * (max u - min u) just above 2 mu N0, so that the element slips briefly at each reversal)
 * give fricreg_aft_jenkins_exact's coefficients to 1e-12 of mu N0, as at scale 1. The margins
 * there are near DBL_MIN and their product underflowed to -0: the onsets' brackets were taken
 * for none, the slips lost, and the element returned stuck, 4 % of mu N0 off (fuzz target aft). */
START_TEST(constant_preload_at_tiny_scales)
{
    fricreg_aft *a = make(H, 0);
    const double scales[3] = {1e-304, 1e-200, 1.0};
    double u[NC] = {0.0, 0.0, 0.0, 0.0, -5.9454345703125e-09, -1.0, 0.0}, g[NC] = {0};
    for (int c = 0; c < 3; c++) {
        double kt = 8.204292331087753 * scales[c], mu = 7.294689145408909 * scales[c];
        double f[NC], nf[NC], fj[NC];
        ck_assert_int_eq(fricreg_aft_jenkins_normal_exact(a, kt, mu, 1.0, 0.0, NC, u, g, f, nf,
                                                          NULL),
                         FRICREG_OK);
        ck_assert_int_eq(fricreg_aft_jenkins_exact(a, kt, mu, NC, u, fj, NULL), FRICREG_OK);
        for (int i = 0; i < NC; i++)
            ck_assert_msg(fabs(f[i] - fj[i]) <= 1e-12 * mu, "scale %g: f[%d] = %g, plain %g",
                          scales[c], i, f[i], fj[i]);
    }
    fricreg_aft_free(a);
}
END_TEST

/* A spring far weaker than its bound: kt of 5e-324 and 1e-300 against mu P up to 1e10, the
 * contact opening briefly once a period (P = 1e10 (1 + cos θ) - 1e-2 sin 3θ). The element
 * barely strains, f = kt (u - w) of kt's order, while the slider after a slip stands at
 * w = u - mu P/kt, beyond the double range: it is carried as the force kt w, and f comes out
 * finite and within 1e-15 of mu max P (f was not finite; fuzz target aft). */
START_TEST(spring_far_weaker_than_its_bound)
{
    fricreg_aft *a = make(H, 0);
    const double kts[2] = {5e-324, 1e-300};
    double u[NC] = {1.0, 1.0, -10.0, 0.0, 0.0, -1.0, 0.0};
    double g[NC] = {1e10, 1e10, 0.0, 0.0, 0.0, 0.0, -1e-2}, f[NC], nf[NC], jac[4 * NC * NC];
    for (int c = 0; c < 2; c++) {
        ck_assert_int_eq(fricreg_aft_jenkins_normal_exact(a, kts[c], 0.5, 0.0, 1.0, NC, u, g, f, nf,
                                                          jac),
                         FRICREG_OK);
        for (int i = 0; i < NC; i++)
            ck_assert_msg(fabs(f[i]) <= 1e-15 * 0.5 * 2e10, "kt %g: f[%d] = %g", kts[c], i, f[i]);
        for (int i = 0; i < 4 * NC * NC; i++)
            ck_assert_msg(isfinite(jac[i]), "kt %g: jac[%d] = %g", kts[c], i, jac[i]);
    }
    fricreg_aft_free(a);
}
END_TEST

/* A touchdown that all but grazes: P = kn (1 - 1e-8 cos 3θ - sin 3θ) opens for an instant at
 * each maximum of sin 3θ, where g' is of 1e-8 against kt u' of 1e302 (mu and u of 1e300): the
 * term kt u'(θt)/g'(θt) of df/dg leaves the double range, and such a touchdown contributes 0,
 * as one with g' = 0 (the Jacobian was not finite; fuzz target aft). H = 6 as found. */
START_TEST(touchdown_that_grazes)
{
    enum { H6 = 6, NC6 = 2 * H6 + 1 };
    fricreg_aft *a = make(H6, 0);
    double u[NC6] = {0}, g[NC6] = {0}, f[NC6], nf[NC6], jac[4 * NC6 * NC6];
    u[1] = 1e300;
    g[5] = -9.99969482421875e-09;
    g[6] = -1.0;
    const double k = 215.667724609375;
    ck_assert_int_eq(fricreg_aft_jenkins_normal_exact(a, k, 1e300, k, k, NC6, u, g, f, nf, jac),
                     FRICREG_OK);
    for (int i = 0; i < 4 * NC6 * NC6; i++)
        ck_assert_msg(isfinite(jac[i]), "jac[%d] = %g", i, jac[i]);
    fricreg_aft_free(a);
}
END_TEST

START_TEST(open_throughout_and_no_friction)
{
    const double u[NC] = {0.3, 1.0, 0.0, 0.0, 0.2, 0.9, -0.1}, g[NC] = {0.0, 0.2, 0.1, 0, 0, 0, 0};
    double f[NC], nf[NC], jac[4 * NC * NC];
    fricreg_aft *a = make(H, 0);
    ck_assert_int_eq(fricreg_aft_jenkins_normal_exact(a, 2.0, 0.5, -1.0, 2.0, NC, u, g, f, nf, jac),
                     FRICREG_OK);
    for (int i = 0; i < NC; i++) {
        ck_assert_double_eq(f[i], 0.0);
        ck_assert_double_eq(nf[i], 0.0);
    }
    for (int i = 0; i < 4 * NC * NC; i++)
        ck_assert_double_eq(jac[i], 0.0);
    /* mu = 0, closed throughout: f = 0, N = N0 + kn g, dN/dg = kn I */
    ck_assert_int_eq(fricreg_aft_jenkins_normal_exact(a, 2.0, 0.0, 1.0, 2.0, NC, u, g, f, nf, jac),
                     FRICREG_OK);
    for (int i = 0; i < NC; i++) {
        ck_assert_double_eq(f[i], 0.0);
        ck_assert_double_eq_tol(nf[i], (i == 0 ? 1.0 : 0.0) + 2.0 * g[i], 1e-14);
        for (int j = 0; j < NC; j++) {
            ck_assert_double_eq(jac[2 * NC * i + j], 0.0);
            ck_assert_double_eq(jac[2 * NC * i + NC + j], 0.0);
            ck_assert_double_eq_tol(jac[2 * NC * (NC + i) + NC + j], i == j ? 2.0 : 0.0, 1e-14);
        }
    }
    fricreg_aft_free(a);
}
END_TEST

/* At 2^18 samples the time-domain element's own sampling error is 1e-11 of the force scale
 * or below (measured): the exact coefficients are asserted within 1e-10. */
START_TEST(against_the_time_domain_element)
{
    fricreg_aft *a = make(H, 0);
    aft_normal_check_time_domain_cases(a, fricreg_aft_jenkins_normal_exact, NS, 1e-10);
    fricreg_aft_free(a);
}
END_TEST

START_TEST(against_the_sampled_path)
{
    fricreg_aft *fine = make(H, 1 << 16), *coarse = make(H, 1024);
    unsigned long long seed = 1234;
    int opened = 0;
    for (int c = 0; c < 10; c++) {
        double u[NC], g[NC], f[NC], nf[NC], fs[NC], nfs[NC], fc[NC], nfc[NC];
        for (int i = 0; i < NC; i++) {
            u[i] = rnd(&seed) / (1 + i / 2);
            g[i] = rnd(&seed) / (1 + i / 2);
        }
        double kt = 1.0 + 0.5 * rnd(&seed), mu = 0.3 + 0.2 * rnd(&seed), n0 = 1.0 + rnd(&seed);
        double kn = 1.0 + 0.5 * rnd(&seed), scale = kt + mu * (fabs(n0) + 4.0 * kn);
        double err = 0.0, errc = 0.0, h = 2.0 * PI / (1 << 16);
        ck_assert_int_eq(fricreg_aft_jenkins_normal_exact(fine, kt, mu, n0, kn, NC, u, g, f, nf,
                                                          NULL),
                         FRICREG_OK);
        ck_assert_int_eq(fricreg_aft_jenkins_normal_sampled(fine, kt, mu, n0, kn, NC, u, g, fs, nfs,
                                                            NULL),
                         FRICREG_OK);
        ck_assert_int_eq(fricreg_aft_jenkins_normal_sampled(coarse, kt, mu, n0, kn, NC, u, g, fc,
                                                            nfc, NULL),
                         FRICREG_OK);
        for (int i = 0; i < NC; i++) {
            err = fmax(err, fmax(fabs(f[i] - fs[i]), fabs(nf[i] - nfs[i])));
            errc = fmax(errc, fmax(fabs(f[i] - fc[i]), fabs(nf[i] - nfc[i])));
        }
        ck_assert_msg(err < scale * h, "case %d: exact - sampled = %g, bound %g", c, err,
                      scale * h);
        ck_assert_msg(err < errc || err < 1e-12 * scale, "case %d: %g at N = 2^16, %g at 1024", c,
                      err, errc);
        for (int q = 0; q < 64 && !opened; q++)
            opened = n0 + kn * aft_normal_at(H, g, 2.0 * PI * q / 64) < 0.0;
    }
    ck_assert(opened); /* the sweep has openings */
    fricreg_aft_free(fine);
    fricreg_aft_free(coarse);
}
END_TEST

/* A march that starts on a reversal of u (the maximum) with g following u: rounding put the
 * start a hair past the slider velocity's sign change, and the slip went on through the
 * decreasing branch (f0 0.60 where the sampled path gives -0.093). The slip now stops at
 * once where its first arc already has the velocity against it. Against the sampled path at
 * N = 2^16 within the force scale times 2 pi/N, as the sweep. */
START_TEST(slip_starting_on_a_reversal)
{
    const double kt = 0.95789016068814814, mu = 0.8812804789660873, n0 = 0.77750149684841796,
                 kn = 0.07378712206789606;
    const double u[11] = {0,
                          -0.69712608666025377,
                          0.10287065040453836,
                          0.3745257784028192,
                          0.27525961427418189,
                          -0.26979934762688323,
                          -0.15405492223988049,
                          0,
                          0.17424074093543029,
                          -0.18025088197563349,
                          -0.014503629807306906};
    double g[11], f[11], nf[11], fs[11], nfs[11], scale = kt + mu * (n0 + 4.0 * kn);
    memcpy(g, u, sizeof g);
    g[0] = -0.0065336371802415805;
    fricreg_aft *a = make(5, 1 << 16);
    ck_assert_int_eq(fricreg_aft_jenkins_normal_exact(a, kt, mu, n0, kn, 11, u, g, f, nf, NULL),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_aft_jenkins_normal_sampled(a, kt, mu, n0, kn, 11, u, g, fs, nfs, NULL),
                     FRICREG_OK);
    for (int i = 0; i < 11; i++)
        ck_assert_msg(fabs(f[i] - fs[i]) < scale * 2.0 * PI / (1 << 16),
                      "f[%d] = %.12g, sampled %.12g", i, f[i], fs[i]);
    fricreg_aft_free(a);
}
END_TEST

START_TEST(jacobian_against_differences)
{
    const double u1[NC] = {0.0, 1.0, 0.0, 0, 0, 0.1, 0}, g1[NC] = {0.1, 0.0, 1.5, 0, 0, 0, 0};
    const double u2[NC] = {0.1, 1.2, 0.0, 0.0, 0.3, 0, 0}, g2[NC] = {0.0, 0.76, -0.24, 0, 0, 0, 0};
    const double u3[NC] = {0.0, 0.05, 0.0, 0, 0, 0, 0};
    fricreg_aft *a = make(H, 0);
    aft_normal_check_jacobian(a, fricreg_aft_jenkins_normal_exact, 2.0, 0.5, 1.0, 1.0, u1,
                              g1); /* lift-off: the touchdown term */
    aft_normal_check_jacobian(a, fricreg_aft_jenkins_normal_exact, 3.0, 0.4, 2.0, 1.0, u2,
                              g2); /* moving bound */
    aft_normal_check_jacobian(a, fricreg_aft_jenkins_normal_exact, 3.0, 0.4, 2.0, 1.0, u3,
                              g2); /* stuck, centred */
    unsigned long long seed = 77;
    for (int c = 0; c < 6; c++) {
        double u[NC], g[NC];
        for (int i = 0; i < NC; i++) {
            u[i] = rnd(&seed) / (1 + i / 2);
            g[i] = rnd(&seed) / (1 + i / 2);
        }
        aft_normal_check_jacobian(a, fricreg_aft_jenkins_normal_exact, 1.0 + 0.5 * rnd(&seed),
                                  0.3 + 0.2 * rnd(&seed), 1.0 + rnd(&seed), 1.0 + 0.5 * rnd(&seed),
                                  u, g);
    }
    fricreg_aft_free(a);
}
END_TEST

START_TEST(outputs_may_alias_inputs)
{
    const double u[NC] = {0.0, 1.0, 0.0, 0, 0, 0.1, 0}, g[NC] = {0.1, 0.0, 1.5, 0, 0, 0, 0};
    double f[NC], nf[NC], uf[NC], gn[NC];
    fricreg_aft *a = make(H, 0);
    ck_assert_int_eq(fricreg_aft_jenkins_normal_exact(a, 2.0, 0.5, 1.0, 1.0, NC, u, g, f, nf, NULL),
                     FRICREG_OK);
    memcpy(uf, u, sizeof uf);
    memcpy(gn, g, sizeof gn);
    ck_assert_int_eq(fricreg_aft_jenkins_normal_exact(a, 2.0, 0.5, 1.0, 1.0, NC, uf, gn, uf, gn,
                                                      NULL),
                     FRICREG_OK);
    for (int i = 0; i < NC; i++) {
        ck_assert_double_eq(uf[i], f[i]);
        ck_assert_double_eq(gn[i], nf[i]);
    }
    fricreg_aft_free(a);
}
END_TEST

/* the stuck slider nearest the centre, continuous where the centre leaves the stuck ones
 * (aft_normal_checks.h; to rounding) */
START_TEST(nearest_stuck_slider)
{
    fricreg_aft *a = make(3, 0);
    aft_normal_check_nearest_stuck(a, fricreg_aft_jenkins_normal_exact, 1e-12);
    fricreg_aft_free(a);
}
END_TEST

START_TEST(bad_input)
{
    fricreg_aft *a = make(H, 0);
    aft_normal_check_bad_input(a, fricreg_aft_jenkins_normal_exact, "jenkins_normal_exact");
    fricreg_aft_free(a);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("aft_normal_exact");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, constant_preload_is_jenkins_exact);
    tcase_add_test(tc, open_throughout_and_no_friction);
    tcase_add_test(tc, bound_far_below_the_rounding_of_u);
    tcase_add_test(tc, constant_preload_at_tiny_scales);
    tcase_add_test(tc, spring_far_weaker_than_its_bound);
    tcase_add_test(tc, touchdown_that_grazes);
    tcase_add_test(tc, slip_starting_on_a_reversal);
    tcase_add_test(tc, jacobian_against_differences);
    tcase_add_test(tc, outputs_may_alias_inputs);
    tcase_add_test(tc, nearest_stuck_slider);
    tcase_add_test(tc, bad_input);
    suite_add_tcase(s, tc);
    /* 2^18 time-domain samples and 2^16 sampled ones a case: native and ASan only */
    TCase *ts = tcase_create("sampled");
    tcase_set_timeout(ts, 60);
    tcase_add_test(ts, against_the_time_domain_element);
    tcase_add_test(ts, against_the_sampled_path);
    suite_add_tcase(s, ts);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
