/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_structure_liftoff.c — Check suite for Jenkins and Iwan elements with a normal load and
 * lift-off as joints of a fricreg_structure (fricreg_structure_set_jenkins_normal,
 * fricreg_structure_set_iwan_normal).
 *
 * Where the numbers come from:
 *   - a stuck (mu huge), closed element is two springs: the run equals one without the
 *     element, K + kt J_e^T J_e + kn J_n^T J_n and the load less J_n^T n0, to 1e-12, for
 *     Newmark, HHT-alpha and the central difference; its normal force is n0 + kn J_n u and
 *     average-acceleration Newmark's balance closes with N^2/(2 kn) in the strain;
 *   - the standalone element (fricreg_jenkins_trial_normal or fricreg_iwan_trial_normal, then
 *     commit) driven step by step by the structure's own q = J_e u and g = J_n u gives the
 *     structure's tangential and normal forces, through slips and separations, to Newton's
 *     tolerance (1e-10 asserted);
 *   - an Iwan element of one slider is the Jenkins element, bit for bit. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_iwan.h"
#include "fricreg_jenkins.h"
#include "fricreg_structure.h"

/* Two dofs: x (tangential) and z (normal), a spring each to ground, the element's rows
 * Je = (1, 0.2) and Jn = (-0.1, 1) (coupled), the load p sin(omega t) (or constant p). */
static const double M2[4] = {1.2, 0.0, 0.0, 0.9}, K2[4] = {2.0, 0.3, 0.3, 1.0},
                    C2[4] = {0.05, 0.0, 0.0, 0.04}, JE[2] = {1.0, 0.2}, JN[2] = {-0.1, 1.0};

static fricreg_structure *make(const double K[4], const double p[2], int sine, double omega,
                               double dt, int nsteps, int scheme)
{
    fricreg_structure *s = NULL;
    double J[2] = {1.0, 0.0}, zero = 0.0;
    ck_assert_int_eq(fricreg_structure_create(2, 1, &s), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_mass(s, 2, M2), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_stiffness(s, 2, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_damping(s, 2, C2), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_contacts(s, 1, 2, J), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_bounds(s, 1, &zero), FRICREG_OK);
    double *g = malloc(((size_t)nsteps + 1) * sizeof *g);
    ck_assert_ptr_nonnull(g);
    for (int k = 0; k <= nsteps; k++)
        g[k] = sine ? sin(omega * k * dt) : 1.0;
    ck_assert_int_eq(fricreg_structure_set_load(s, 2, p, 0.0, dt, (size_t)nsteps + 1, g),
                     FRICREG_OK);
    free(g);
    if (scheme == 1)
        ck_assert_int_eq(fricreg_structure_set_hht(s, -0.1), FRICREG_OK);
    else if (scheme == 2)
        ck_assert_int_eq(fricreg_structure_set_central_difference(s), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_newton(s, 1e-13, 50), FRICREG_OK);
    return s;
}

START_TEST(stuck_closed_is_two_springs)
{
    const double kt = 2.2, mu = 1e20, n0 = 0.5, kn = 3.0, dt = 0.01;
    const double p[2] = {0.7, 0.4};
    const int nsteps = 2000;
    double Klin[4], plin[2];
    for (int i = 0; i < 2; i++) {
        plin[i] = p[i] - JN[i] * n0;
        for (int k = 0; k < 2; k++)
            Klin[2 * i + k] = K2[2 * i + k] + kt * JE[i] * JE[k] + kn * JN[i] * JN[k];
    }
    for (int scheme = 0; scheme < 3; scheme++) {
        fricreg_structure *a = make(K2, p, 0, 0.0, dt, nsteps, scheme),
                          *b = make(Klin, plin, 0, 0.0, dt, nsteps, scheme);
        ck_assert_int_eq(fricreg_structure_set_jenkins_normal(a, 1, 2, JE, JN, &kt, &mu, &n0, &kn),
                         FRICREG_OK);
        double ua[2], ub[2], va[2], vb[2], f, N, Nmin = INFINITY;
        for (int k = 1; k <= nsteps; k++) {
            ck_assert_int_eq(fricreg_structure_step(a, dt), FRICREG_OK);
            ck_assert_int_eq(fricreg_structure_get_normal_forces(a, 1, &N), FRICREG_OK);
            Nmin = fmin(Nmin, N);
        }
        ck_assert_int_eq(fricreg_structure_run(b, dt, nsteps * dt), FRICREG_OK);
        fricreg_structure_get_state(a, 2, ua, va, NULL);
        fricreg_structure_get_state(b, 2, ub, vb, NULL);
        fricreg_structure_get_jenkins_state(a, 1, &f, NULL, NULL);
        double scale = fmax(fabs(ub[0]), fabs(ub[1])), vscale = fmax(fabs(vb[0]), fabs(vb[1]));
        double q = JE[0] * ua[0] + JE[1] * ua[1], g = JN[0] * ua[0] + JN[1] * ua[1];
        if (getenv("LIFTOFF_PRINT"))
            fprintf(stderr, "stuck closed, scheme %d: |du| %.2e |dv| %.2e of %.3g, %.3g; N >= %g\n",
                    scheme, fmax(fabs(ua[0] - ub[0]), fabs(ua[1] - ub[1])),
                    fmax(fabs(va[0] - vb[0]), fabs(va[1] - vb[1])), scale, vscale, Nmin);
        ck_assert(Nmin > 0.0); /* closed throughout */
        for (int k = 0; k < 2; k++) {
            ck_assert_double_eq_tol(ua[k], ub[k], 1e-12 * scale);
            ck_assert_double_eq_tol(va[k], vb[k], 1e-12 * vscale);
        }
        ck_assert_double_eq_tol(f, kt * q, 1e-12 * kt * scale);
        ck_assert_double_eq_tol(N, n0 + kn * g, 1e-12 * (n0 + kn * scale));
        if (scheme == 0) { /* the balance closes with the normal spring's N^2/(2 kn) */
            double residual, input;
            fricreg_structure_get_value(a, FRICREG_SVALUE_RESIDUAL, &residual);
            fricreg_structure_get_value(a, FRICREG_SVALUE_INPUT, &input);
            if (getenv("LIFTOFF_PRINT"))
                fprintf(stderr, "  residual %.2e of input %.4g\n", residual, input);
            ck_assert(fabs(residual) <= 1e-9 * fabs(input));
        }
        fricreg_structure_free(a);
        fricreg_structure_free(b);
    }
}
END_TEST

/* The standalone element beside a structure: Jenkins (fricreg_jenkins, one slider) or Iwan
 * (fricreg_iwan, ns sliders of slip forces mu_s n0 at the reference N0 = n0), trial at the
 * structure's q and g, then committed. */
struct standalone {
    fricreg_jenkins *jk;
    fricreg_iwan *iw;
};

static struct standalone standalone_new(size_t ns, const double k[], const double mu[], double n0,
                                        double kn)
{
    struct standalone el = {NULL, NULL};
    if (ns == 0) { /* the Jenkins element: k[0] = kt, mu[0] = mu */
        double one = 1.0;
        ck_assert_int_eq(fricreg_jenkins_create(1, 1, &el.jk), FRICREG_OK);
        ck_assert_int_eq(fricreg_jenkins_set_params(el.jk, 1, k, &one), FRICREG_OK);
        ck_assert_int_eq(fricreg_jenkins_set_normal(el.jk, 1, mu, &n0, &kn), FRICREG_OK);
        return el;
    }
    double phi[8];
    ck_assert_uint_le(ns, 8);
    for (size_t j = 0; j < ns; j++)
        phi[j] = mu[j] * n0;
    ck_assert_int_eq(fricreg_iwan_create(1, 1, ns, &el.iw), FRICREG_OK);
    ck_assert_int_eq(fricreg_iwan_set_params(el.iw, 1, ns, k, phi), FRICREG_OK);
    ck_assert_int_eq(fricreg_iwan_set_normal(el.iw, 1, &n0, &kn), FRICREG_OK);
    return el;
}

static void standalone_step(struct standalone *el, double q, double g, double *f, double *N)
{
    if (el->jk != NULL) {
        ck_assert_int_eq(fricreg_jenkins_trial_normal(el->jk, 1, &q, &g, f, N, NULL, NULL),
                         FRICREG_OK);
        ck_assert_int_eq(fricreg_jenkins_commit(el->jk), FRICREG_OK);
        return;
    }
    ck_assert_int_eq(fricreg_iwan_trial_normal(el->iw, 1, &q, &g, f, N, NULL, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_iwan_commit(el->iw), FRICREG_OK);
}

/* Slips and separations under 0.8 sin and 2 sin on x and z, for each scheme: the element set
 * by set_jenkins_normal (ns = 0) or set_iwan_normal (ns sliders) and the standalone element at
 * the structure's displacements, committed after every step, give the same forces. */
static void against_standalone(size_t ns, const double k[], const double mu[])
{
    const double n0 = 1.0, kn = 4.0, omega = 1.1, dt = 0.005;
    const double p[2] = {0.8, 2.0};
    const int nsteps = 6000;
    for (int scheme = 0; scheme < 3; scheme++) {
        fricreg_structure *s = make(K2, p, 1, omega, dt, nsteps, scheme);
        if (ns == 0)
            ck_assert_int_eq(fricreg_structure_set_jenkins_normal(s, 1, 2, JE, JN, k, mu, &n0, &kn),
                             FRICREG_OK);
        else
            ck_assert_int_eq(fricreg_structure_set_iwan_normal(s, 1, 2, JE, JN, ns, k, mu, &n0,
                                                               &kn),
                             FRICREG_OK);
        struct standalone el = standalone_new(ns, k, mu, n0, kn);
        size_t nw = ns == 0 ? 1 : ns;
        int open = 0, slipping = 0;
        double df = 0.0, dN = 0.0, fscale = 0.0, Nscale = 0.0, w0[8] = {0.0};
        for (int step = 1; step <= nsteps; step++) {
            double t0, u[2], f, N, w[8], fj, Nj;
            ck_assert_int_eq(fricreg_structure_get_value(s, FRICREG_SVALUE_TIME, &t0), FRICREG_OK);
            ck_assert_int_eq(fricreg_structure_step(s, step * dt - t0), FRICREG_OK);
            fricreg_structure_get_state(s, 2, u, NULL, NULL);
            ck_assert_int_eq(fricreg_structure_get_iwan_state(s, 1, nw, &f, w, NULL), FRICREG_OK);
            fricreg_structure_get_normal_forces(s, 1, &N);
            standalone_step(&el, JE[0] * u[0] + JE[1] * u[1], JN[0] * u[0] + JN[1] * u[1], &fj,
                            &Nj);
            df = fmax(df, fabs(f - fj));
            dN = fmax(dN, fabs(N - Nj));
            fscale = fmax(fscale, fabs(fj));
            Nscale = fmax(Nscale, Nj);
            open += Nj == 0.0;
            slipping += Nj > 0.0 && memcmp(w, w0, nw * sizeof *w) != 0;
            memcpy(w0, w, nw * sizeof *w);
        }
        double residual, input;
        fricreg_structure_get_value(s, FRICREG_SVALUE_RESIDUAL, &residual);
        fricreg_structure_get_value(s, FRICREG_SVALUE_INPUT, &input);
        if (getenv("LIFTOFF_PRINT"))
            fprintf(stderr,
                    "ns %zu, scheme %d: |f - f_element| %.2e of %.3g, |N - N_element| %.2e of "
                    "%.3g; %d steps open, %d slipping; balance residual %.2e of input %.4g\n",
                    ns, scheme, df, fscale, dN, Nscale, open, slipping, residual, input);
        /* the crossings make the balance inexact: the energy check stands aside */
        size_t warnings = fricreg_structure_warning_count(s);
        for (size_t j = 0; j < warnings; j++) {
            int code;
            ck_assert_int_eq(fricreg_structure_get_warning(s, j, &code, NULL, 0), FRICREG_OK);
            ck_assert_int_ne(code, FRICREG_WARN_ENERGY);
        }
        ck_assert_int_gt(open, 100);
        ck_assert_int_gt(slipping, 100);
        ck_assert_msg(df <= 1e-10 * fscale, "scheme %d: f differs by %g", scheme, df);
        ck_assert_msg(dN <= 1e-10 * Nscale, "scheme %d: N differs by %g", scheme, dN);
        fricreg_jenkins_free(el.jk);
        fricreg_iwan_free(el.iw);
        fricreg_structure_free(s);
    }
}

START_TEST(against_standalone_element)
{
    const double kt = 3.0, mu = 0.4;
    against_standalone(0, &kt, &mu);
}
END_TEST

/* Three sliders that slip one after another (slip displacements mu_s n0/k_s of 0.05, 0.2 and
 * 0.5 at the preload) against fricreg_iwan's element with the same normal law. */
START_TEST(iwan_against_standalone_element)
{
    const double k[3] = {2.0, 1.0, 0.4}, mu[3] = {0.1, 0.2, 0.2};
    against_standalone(3, k, mu);
}
END_TEST

/* set_iwan_normal with one slider is set_jenkins_normal, bit for bit, under each scheme. */
START_TEST(iwan_one_slider_is_jenkins)
{
    const double kt = 3.0, mu = 0.4, n0 = 1.0, kn = 4.0, dt = 0.005;
    const double p[2] = {0.8, 2.0};
    const int nsteps = 1500;
    for (int scheme = 0; scheme < 3; scheme++) {
        fricreg_structure *a = make(K2, p, 1, 1.1, dt, nsteps, scheme),
                          *b = make(K2, p, 1, 1.1, dt, nsteps, scheme);
        ck_assert_int_eq(fricreg_structure_set_jenkins_normal(a, 1, 2, JE, JN, &kt, &mu, &n0, &kn),
                         FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_set_iwan_normal(b, 1, 2, JE, JN, 1, &kt, &mu, &n0, &kn),
                         FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_run(a, dt, nsteps * dt), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_run(b, dt, nsteps * dt), FRICREG_OK);
        double ua[2], ub[2], va[2], vb[2], fa[3], fb[3], ea, eb;
        fricreg_structure_get_state(a, 2, ua, va, NULL);
        fricreg_structure_get_state(b, 2, ub, vb, NULL);
        fricreg_structure_get_jenkins_state(a, 1, fa, fa + 1, fa + 2);
        fricreg_structure_get_iwan_state(b, 1, 1, fb, fb + 1, fb + 2);
        fricreg_structure_get_value(a, FRICREG_SVALUE_STRAIN, &ea);
        fricreg_structure_get_value(b, FRICREG_SVALUE_STRAIN, &eb);
        ck_assert_mem_eq(ua, ub, sizeof ua);
        ck_assert_mem_eq(va, vb, sizeof va);
        ck_assert_mem_eq(fa, fb, sizeof fa);
        ck_assert_double_eq(ea, eb);
        ck_assert(fa[2] > 0.0); /* it slipped */
        fricreg_structure_free(a);
        fricreg_structure_free(b);
    }
}
END_TEST

/* Refusals: kn <= 0, a zero normal row, NULL J_n, an Iwan element of no slider or with a
 * negative mu (the elements in force kept); the getter without a normal law. */
START_TEST(refusals)
{
    const double p[2] = {0.8, 2.0}, kt = 3.0, mu = 0.4, n0 = 1.0, kn = 4.0, zero = 0.0;
    const double Jzero[2] = {0.0, 0.0};
    fricreg_structure *s = make(K2, p, 1, 1.0, 0.01, 10, 0);
    double N = -1.0;
    ck_assert_int_eq(fricreg_structure_set_jenkins_normal(s, 1, 2, JE, JN, &kt, &mu, &n0, &zero),
                     FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_structure_errmsg(s), "kn"));
    ck_assert_int_eq(fricreg_structure_set_jenkins_normal(s, 1, 2, JE, Jzero, &kt, &mu, &n0, &kn),
                     FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_structure_errmsg(s), "J_n"));
    ck_assert_int_eq(fricreg_structure_set_jenkins_normal(s, 1, 2, JE, NULL, &kt, &mu, &n0, &kn),
                     FRICREG_ENULL);
    const double k2[2] = {1.0, 2.0}, mu2[2] = {0.1, -0.1};
    ck_assert_int_eq(fricreg_structure_set_iwan_normal(s, 1, 2, JE, JN, 0, k2, mu2, &n0, &kn),
                     FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_structure_errmsg(s), "ns = 0"));
    ck_assert_int_eq(fricreg_structure_set_iwan_normal(s, 1, 2, JE, JN, 2, k2, mu2, &n0, &kn),
                     FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_structure_errmsg(s), "mu"));
    ck_assert_int_eq(fricreg_structure_set_iwan_normal(s, 1, 2, JE, JN, 1, k2, mu2, &n0, &zero),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_set_iwan_normal(s, 1, 2, JE, NULL, 1, k2, mu2, &n0, &kn),
                     FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_set_jenkins(s, 1, 2, JE, &kt, &mu), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_iwan_normal(s, 1, 2, JE, JN, 2, k2, mu2, &n0, &kn),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_get_normal_forces(s, 1, &N), FRICREG_EINVAL);
    ck_assert_double_eq(N, -1.0);
    ck_assert_int_eq(fricreg_structure_set_jenkins_normal(s, 1, 2, JE, JN, &kt, &mu, &n0, &kn),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_normal_forces(s, 2, &N), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_structure_step(s, 0.01), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_normal_forces(s, 1, &N), FRICREG_OK);
    ck_assert(N > 0.0);
    fricreg_structure_free(s);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("structure_liftoff");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, stuck_closed_is_two_springs);
    tcase_add_test(tc, against_standalone_element);
    tcase_add_test(tc, iwan_against_standalone_element);
    tcase_add_test(tc, iwan_one_slider_is_jenkins);
    tcase_add_test(tc, refusals);
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
