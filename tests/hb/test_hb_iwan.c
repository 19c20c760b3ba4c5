/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_iwan.c — Check suite for Iwan elements in the harmonic-balance driver
 * (fricreg_hb_set_iwan, fricreg_hb.h).
 *
 * Where the numbers come from:
 *   - an Iwan element is its sliders in parallel on one row of J, so a model with m Iwan
 *     elements of ns sliders has the displacements of the model with m ns Jenkins elements on
 *     ns copies of each row (fricreg_hb_set_elements): the same equations, a different
 *     condensation. Both solved with Newton's tolerance 1e-13; the displacements agree to
 *     1e-11 of their scale;
 *   - the steady state in time: the oscillator of test_hb.c with an Iwan element of three
 *     sliders to ground, average-acceleration Newmark with Newton and the Iwan element's
 *     return mapping (fricreg_iwan_trial, commit after each step), 1024 steps a period, from
 *     rest until the RMS of the last two periods agree to 1e-7 (asserted), the RMS over the
 *     last period by the rectangle rule. Every slider slips in each period (asserted on the
 *     time series: the play operator's wiping-out makes the periodic state unique). HB at
 *     H = 21 within 1e-3 relative, as test_hb.c's Jenkins cases;
 *   - set_elements after set_iwan is the Jenkins model again, to the bit. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_hb.h"
#include "fricreg_iwan.h"
#include "quiet_check.h"

#define SENTINEL (-777.125)
static const double PI = 3.14159265358979323846;

/* The chain of test_hb.c: three masses on springs, Rayleigh damping; element 0 between mass 3
 * and ground, element 1 between masses 1 and 2; mass 1 excited. */
static const double CM[9] = {1.1, 0, 0, 0, 0.9, 0, 0, 0, 1.25};
static const double CK[9] = {5.3, -2.1, 0, -2.1, 3.7, -1.6, 0, -1.6, 1.6};
static const double CJ[6] = {0, 0, 1.0, -1.0, 1.0, 0};
static const double CPC[3] = {0.8, 0, 0}, CPS[3] = {0.25, 0, 0};
/* three sliders per element, row-major [2][3] */
static const double SK[6] = {1.2, 0.8, 0.5, 0.6, 0.5, 0.3};
static const double SPHI[6] = {0.05, 0.12, 0.2, 0.02, 0.05, 0.08};

static fricreg_hb *chain(size_t m, int H)
{
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(3, m, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 3, CM), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 3, CK), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_rayleigh(hb, 0.03, 0.01), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, 3, CPC, CPS), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_newton(hb, 1e-13, 50), FRICREG_OK);
    return hb;
}

START_TEST(iwan_equals_jenkins_copies)
{
    const int H = 7;
    const size_t nc = 2 * H + 1;
    fricreg_hb *iw = chain(2, H), *jk = chain(6, H);
    double J6[18], kt[6], mun[6];
    for (size_t e = 0; e < 2; e++)
        for (size_t s = 0; s < 3; s++) {
            memcpy(&J6[3 * (3 * e + s)], &CJ[3 * e], 3 * sizeof *CJ);
            kt[3 * e + s] = SK[3 * e + s];
            mun[3 * e + s] = SPHI[3 * e + s];
        }
    ck_assert_int_eq(fricreg_hb_set_iwan(iw, 2, 3, CJ, 3, SK, SPHI), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(jk, 6, 3, J6, kt, mun), FRICREG_OK);
    const double omegas[3] = {0.9, 1.2, 1.5};
    for (int w = 0; w < 3; w++) {
        double q2[2 * 15], q6[6 * 15], x2[3 * 15], x6[3 * 15], scale = 0.0;
        ck_assert_int_eq(fricreg_hb_solve(iw, omegas[w], 2 * nc, NULL, q2), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_solve(jk, omegas[w], 6 * nc, NULL, q6), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_displacement(iw, 3, nc, x2), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_displacement(jk, 3, nc, x6), FRICREG_OK);
        for (size_t i = 0; i < 3 * nc; i++)
            scale = fmax(scale, fabs(x6[i]));
        double diff = 0.0;
        for (size_t i = 0; i < 3 * nc; i++)
            diff = fmax(diff, fabs(x2[i] - x6[i]));
        if (getenv("HB_PRINT"))
            fprintf(stderr, "Omega %g: Iwan - Jenkins copies %.2e of %.3g\n", omegas[w], diff,
                    scale);
        for (size_t i = 0; i < 3 * nc; i++)
            ck_assert_msg(fabs(x2[i] - x6[i]) <= 1e-11 * scale,
                          "Omega %g: x[%zu] Iwan %.15g, Jenkins copies %.15g", omegas[w], i, x2[i],
                          x6[i]);
        for (size_t e = 0; e < 2; e++) /* the element coordinates too */
            for (size_t c = 0; c < nc; c++)
                ck_assert_double_eq_tol(q2[e * nc + c], q6[3 * e * nc + c], 1e-11 * scale);
    }
    fricreg_hb_free(iw);
    fricreg_hb_free(jk);
}
END_TEST

/* The oscillator: one dof, M = 1.3, K = 2.385, C = 0.12, an Iwan element to ground. */
static const double OK_ = 2.385, OM = 1.3, OC = 0.12, OPC = 0.6;
static const double OSK[3] = {0.9, 0.5, 0.3}, OSPHI[3] = {0.06, 0.1, 0.12};

/* Newmark from rest over `periods` periods of N steps: RMS of x over the last period (rms) and
 * the one before (prev); whether every slider's range over the last period exceeded 2 phi/k. */
static int newmark_rms(double omega, int periods, double *rms, double *prev)
{
    const int N = 1024;
    double dt = 2.0 * PI / omega / N, beta = 0.25, gamma = 0.5;
    double x = 0.0, v = 0.0, a = 0.0, sum = 0.0, qmax = 0.0, qmin = 0.0, xscale = 0.0;
    fricreg_iwan *iw = NULL;
    ck_assert_int_eq(fricreg_iwan_create(1, 1, 3, &iw), FRICREG_OK);
    ck_assert_int_eq(fricreg_iwan_set_params(iw, 1, 3, OSK, OSPHI), FRICREG_OK);
    for (int step = 1; step <= periods * N; step++) {
        double t = step * dt, xn = x, an = 0.0, vn = 0.0;
        for (int it = 0;; it++) {
            QUIET_CHECK(it < 50);
            an = (xn - x - dt * v) / (beta * dt * dt) - (0.5 / beta - 1.0) * a;
            vn = v + dt * ((1.0 - gamma) * a + gamma * an);
            double f, df;
            QUIET_OK(fricreg_iwan_trial(iw, 1, &xn, &f, &df));
            double R = OM * an + OC * vn + OK_ * xn + f - OPC * cos(omega * t);
            double Kt = OM / (beta * dt * dt) + gamma / (beta * dt) * OC + OK_ + df;
            double dx = R / Kt;
            xn -= dx;
            xscale = fmax(xscale, fabs(xn));
            if (fabs(dx) <= 1e-14 * xscale)
                break;
        }
        QUIET_OK(fricreg_iwan_commit(iw));
        x = xn, v = vn, a = an;
        if (step > (periods - 2) * N) {
            sum += x * x;
            if (step > (periods - 1) * N) {
                qmax = step == (periods - 1) * N + 1 ? x : fmax(qmax, x);
                qmin = step == (periods - 1) * N + 1 ? x : fmin(qmin, x);
            }
        }
        if (step == (periods - 1) * N) {
            *prev = sqrt(sum / N);
            sum = 0.0;
        }
    }
    *rms = sqrt(sum / N);
    fricreg_iwan_free(iw);
    int slips = 1;
    for (int s = 0; s < 3; s++)
        slips = slips && OSK[s] * (qmax - qmin) > 2.0 * OSPHI[s];
    return slips;
}

START_TEST(oscillator_against_time_domain)
{
    const int H = 21;
    const size_t nc = 2 * H + 1;
    const double J = 1.0, omegas[2] = {1.3, 1.7};
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(1, 1, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 1, &OM), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 1, &OK_), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, 1, &OC), FRICREG_OK);
    const double pc = OPC, ps = 0.0;
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, 1, &pc, &ps), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_iwan(hb, 1, 1, &J, 3, OSK, OSPHI), FRICREG_OK);
    for (int w = 0; w < 2; w++) {
        double q[43], x[43], ref, prev;
        ck_assert(newmark_rms(omegas[w], 100, &ref, &prev));
        ck_assert_double_le(fabs(ref - prev), 1e-7 * ref);
        ck_assert_int_eq(fricreg_hb_solve(hb, omegas[w], nc, NULL, q), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_displacement(hb, 1, nc, x), FRICREG_OK);
        double r = x[0] * x[0];
        for (size_t c = 1; c < nc; c++)
            r += 0.5 * x[c] * x[c];
        r = sqrt(r);
        if (getenv("HB_PRINT"))
            fprintf(stderr, "Omega %g: HB %.9g Newmark %.9g rel %.2e steady %.2e\n", omegas[w], r,
                    ref, fabs(r / ref - 1.0), fabs(prev / ref - 1.0));
        ck_assert_msg(fabs(r - ref) <= 1e-3 * ref, "Omega %g: HB %.9g, Newmark %.9g", omegas[w], r,
                      ref);
    }
    fricreg_hb_free(hb);
}
END_TEST

START_TEST(set_elements_after_set_iwan)
{
    const int H = 5;
    const size_t nc = 2 * H + 1;
    const double kt[2] = {2.5, 1.4}, mun[2] = {0.3, 0.12};
    double qa[22], qb[22];
    fricreg_hb *a = chain(2, H), *b = chain(2, H);
    ck_assert_int_eq(fricreg_hb_set_elements(a, 2, 3, CJ, kt, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_iwan(b, 2, 3, CJ, 3, SK, SPHI), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(b, 2, 3, CJ, kt, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(a, 1.1, 2 * nc, NULL, qa), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(b, 1.1, 2 * nc, NULL, qb), FRICREG_OK);
    for (size_t i = 0; i < 2 * nc; i++)
        ck_assert_double_eq(qa[i], qb[i]);
    /* an Iwan element of one slider is the Jenkins element, to the bit */
    ck_assert_int_eq(fricreg_hb_set_iwan(b, 2, 3, CJ, 1, kt, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(b, 1.1, 2 * nc, NULL, qb), FRICREG_OK);
    for (size_t i = 0; i < 2 * nc; i++)
        ck_assert_double_eq(qa[i], qb[i]);
    fricreg_hb_free(a);
    fricreg_hb_free(b);
}
END_TEST

START_TEST(bad_input)
{
    const int H = 3;
    const size_t nc = 2 * H + 1;
    fricreg_hb *hb = chain(2, H);
    double q0[14], q1[14], bad[6];
    ck_assert_int_eq(fricreg_hb_set_iwan(hb, 2, 3, CJ, 3, SK, SPHI), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.1, 2 * nc, NULL, q0), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_iwan(NULL, 2, 3, CJ, 3, SK, SPHI), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_set_iwan(hb, 2, 3, NULL, 3, SK, SPHI), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_set_iwan(hb, 2, 3, CJ, 3, NULL, SPHI), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_set_iwan(hb, 2, 3, CJ, 3, SK, NULL), FRICREG_ENULL);
    ck_assert_str_eq(fricreg_hb_errmsg(hb), "set_iwan: phi is NULL");
    ck_assert_int_eq(fricreg_hb_set_iwan(hb, 1, 3, CJ, 3, SK, SPHI), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_hb_set_iwan(hb, 2, 2, CJ, 3, SK, SPHI), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_hb_set_iwan(hb, 2, 3, CJ, 0, SK, SPHI), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_set_iwan(hb, 2, 3, CJ, FRICREG_HB_MAX_SLIDERS + 1, SK, SPHI),
                     FRICREG_EINVAL);
    memcpy(bad, SK, sizeof bad);
    bad[4] = 0.0;
    ck_assert_int_eq(fricreg_hb_set_iwan(hb, 2, 3, CJ, 3, bad, SPHI), FRICREG_EINVAL);
    ck_assert_str_eq(fricreg_hb_errmsg(hb), "set_iwan: k[4] = 0 must be > 0, phi[4] = 0.05 >= 0");
    memcpy(bad, SPHI, sizeof bad);
    bad[5] = -0.1;
    ck_assert_int_eq(fricreg_hb_set_iwan(hb, 2, 3, CJ, 3, SK, bad), FRICREG_EINVAL);
    bad[5] = NAN;
    ck_assert_int_eq(fricreg_hb_set_iwan(hb, 2, 3, CJ, 3, SK, bad), FRICREG_ENONFINITE);
    memcpy(bad, CJ, sizeof bad);
    bad[3] = bad[4] = 0.0; /* row 1 zero */
    ck_assert_int_eq(fricreg_hb_set_iwan(hb, 2, 3, bad, 3, SK, SPHI), FRICREG_EINVAL);
    bad[3] = INFINITY;
    ck_assert_int_eq(fricreg_hb_set_iwan(hb, 2, 3, bad, 3, SK, SPHI), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_hb_errcode(hb), FRICREG_ENONFINITE);
    /* nothing changed: the same solution */
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.1, 2 * nc, NULL, q1), FRICREG_OK);
    for (size_t i = 0; i < 2 * nc; i++)
        ck_assert_double_eq(q0[i], q1[i]);
    fricreg_hb_free(hb);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("hb_iwan");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, iwan_equals_jenkins_copies);
    tcase_add_test(tc, set_elements_after_set_iwan);
    tcase_add_test(tc, bad_input);
    suite_add_tcase(s, tc);
    /* The Newmark reference, 10^5 steps: native and ASan only */
    TCase *td = tcase_create("time_domain");
    tcase_set_timeout(td, 120);
    tcase_add_test(td, oscillator_against_time_domain);
    suite_add_tcase(s, td);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
