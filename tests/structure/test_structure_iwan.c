/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_structure_iwan.c — Check suite for Iwan elements as joints of a fricreg_structure
 * (fricreg_structure_set_iwan).
 *
 * Where the numbers come from:
 *   - an Iwan element of ns sliders is ns Jenkins elements on copies of its row (the same
 *     equations; fricreg_structure_set_jenkins, test_structure_jenkins's reference): the
 *     histories, forces and dissipation agree to rounding (1e-12 of the amplitude), for
 *     Newmark, HHT-alpha and the central difference, on a chain of three masses with two
 *     elements of three sliders;
 *   - the closed form of a displacement-driven Iwan element of amplitude A: sum over its
 *     sliders that slip (phi_s/k_s < A) of 4 phi_s (A - phi_s/k_s) per cycle, the others
 *     elastic;
 *   - harmonic balance with the same Iwan element (fricreg_hb_set_iwan at H = 21): the steady
 *     RMS within 1e-3;
 *   - average-acceleration Newmark's energy balance closes with the sliders' dissipation. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_hb.h"
#include "fricreg_structure.h"
#include "quiet_check.h"

static const double PI = 3.14159265358979323846;

#define NS 3
#define MAXN 3

struct model {
    size_t n, me;
    double M[MAXN * MAXN], K[MAXN * MAXN], C[MAXN * MAXN];
    double J[2 * MAXN];            /* [me n] */
    double k[2 * NS], phi[2 * NS]; /* [me NS] */
    double ps[MAXN];               /* p(t) = ps sin(Omega t) */
};

/* The oscillator of test_structure_jenkins with its element split into three sliders of
 * slip displacements 0.05, 0.15 and 0.4 (the whole element's stiffness 1.7). */
static struct model oscillator(void)
{
    struct model m = {.n = 1, .me = 1};
    m.M[0] = 1.3;
    m.K[0] = 2.385;
    m.C[0] = 0.12;
    m.J[0] = 1.0;
    const double k[NS] = {0.6, 0.7, 0.4}, slip[NS] = {0.05, 0.15, 0.4};
    for (int j = 0; j < NS; j++)
        m.k[j] = k[j], m.phi[j] = k[j] * slip[j];
    m.ps[0] = 0.6;
    return m;
}

/* test_structure_jenkins's chain: three masses, an element to ground on mass 3 and one
 * between masses 1 and 2, each of three sliders. */
static struct model chain(void)
{
    struct model m = {.n = 3, .me = 2};
    const double mass[3] = {1.1, 0.9, 1.25}, ks[3] = {3.2, 2.1, 1.6};
    for (int i = 0; i < 3; i++)
        m.M[4 * i] = mass[i];
    m.K[0] = ks[0] + ks[1];
    m.K[1] = m.K[3] = -ks[1];
    m.K[4] = ks[1] + ks[2];
    m.K[5] = m.K[7] = -ks[2];
    m.K[8] = ks[2];
    for (int i = 0; i < 9; i++)
        m.C[i] = 0.03 * m.M[i] + 0.01 * m.K[i];
    m.J[2] = 1.0;
    m.J[3] = -1.0, m.J[4] = 1.0;
    const double k[2 * NS] = {1.0, 0.9, 0.6, 0.5, 0.5, 0.4},
                       phi[2 * NS] = {0.05, 0.12, 0.13, 0.02, 0.05, 0.05};
    memcpy(m.k, k, sizeof k);
    memcpy(m.phi, phi, sizeof phi);
    m.ps[0] = 0.8;
    return m;
}

/* A structure of the model (one contact of bound 0), its elements as Iwan elements
 * (copies = 0) or as NS Jenkins elements each on a copy of the row (copies = 1), the load
 * sampled every dt for nsteps steps; scheme 0 Newmark, 1 HHT(-0.1), 2 central difference. */
static fricreg_structure *make(const struct model *m, int copies, int scheme, double omega,
                               double dt, int nsteps)
{
    fricreg_structure *s = NULL;
    size_t n = m->n;
    ck_assert_int_eq(fricreg_structure_create(n, 1, &s), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_mass(s, n, m->M), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_stiffness(s, n, m->K), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_damping(s, n, m->C), FRICREG_OK);
    double J[MAXN] = {0}, zero = 0.0;
    J[0] = 1.0;
    ck_assert_int_eq(fricreg_structure_set_contacts(s, 1, n, J), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_bounds(s, 1, &zero), FRICREG_OK);
    if (copies) {
        double Je[2 * NS * MAXN];
        for (size_t j = 0; j < m->me * NS; j++)
            memcpy(Je + j * n, m->J + (j / NS) * n, n * sizeof *Je);
        ck_assert_int_eq(fricreg_structure_set_jenkins(s, m->me * NS, n, Je, m->k, m->phi),
                         FRICREG_OK);
    } else {
        ck_assert_int_eq(fricreg_structure_set_iwan(s, m->me, n, m->J, NS, m->k, m->phi),
                         FRICREG_OK);
    }
    if (scheme == 1)
        ck_assert_int_eq(fricreg_structure_set_hht(s, -0.1), FRICREG_OK);
    else if (scheme == 2)
        ck_assert_int_eq(fricreg_structure_set_central_difference(s), FRICREG_OK);
    double *g = malloc(((size_t)nsteps + 1) * sizeof *g);
    ck_assert_ptr_nonnull(g);
    for (int k = 0; k <= nsteps; k++)
        g[k] = sin(omega * k * dt);
    ck_assert_int_eq(fricreg_structure_set_load(s, n, m->ps, 0.0, dt, (size_t)nsteps + 1, g),
                     FRICREG_OK);
    free(g);
    ck_assert_int_eq(fricreg_structure_set_newton(s, 1e-13, 50), FRICREG_OK);
    return s;
}

START_TEST(iwan_is_jenkins_copies)
{
    struct model m = chain();
    const int N = 256, periods = 20, nsteps = N * periods;
    const double omega = 1.3, dt = 2.0 * PI / omega / N;
    for (int scheme = 0; scheme < 3; scheme++) {
        fricreg_structure *a = make(&m, 0, scheme, omega, dt, nsteps),
                          *b = make(&m, 1, scheme, omega, dt, nsteps);
        double amp = 0.0, diff = 0.0, xa[MAXN], xb[MAXN];
        for (int k = 1; k <= nsteps; k++) {
            double t0;
            ck_assert_int_eq(fricreg_structure_get_value(a, FRICREG_SVALUE_TIME, &t0), FRICREG_OK);
            ck_assert_int_eq(fricreg_structure_step(a, k * dt - t0), FRICREG_OK);
            ck_assert_int_eq(fricreg_structure_get_value(b, FRICREG_SVALUE_TIME, &t0), FRICREG_OK);
            ck_assert_int_eq(fricreg_structure_step(b, k * dt - t0), FRICREG_OK);
            fricreg_structure_get_state(a, m.n, xa, NULL, NULL);
            fricreg_structure_get_state(b, m.n, xb, NULL, NULL);
            for (size_t i = 0; i < m.n; i++) {
                amp = fmax(amp, fabs(xb[i]));
                diff = fmax(diff, fabs(xa[i] - xb[i]));
            }
        }
        double fa[2], wa[2 * NS], Da[2], fb[2 * NS], wb[2 * NS], Db[2 * NS];
        ck_assert_int_eq(fricreg_structure_get_iwan_state(a, 2, NS, fa, wa, Da), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_get_jenkins_state(b, 2 * NS, fb, wb, Db), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_get_jenkins_state(a, 2, fa, wa, NULL), FRICREG_ESIZE);
        double dw = 0.0, df = 0.0, dD = 0.0, fscale = 0.0, Dscale = 0.0, ea, eb;
        for (int i = 0; i < 2; i++) {
            double f = 0.0, D = 0.0;
            for (int j = 0; j < NS; j++) {
                f += fb[NS * i + j];
                D += Db[NS * i + j];
                dw = fmax(dw, fabs(wa[NS * i + j] - wb[NS * i + j]));
            }
            df = fmax(df, fabs(fa[i] - f));
            dD = fmax(dD, fabs(Da[i] - D));
            fscale = fmax(fscale, fabs(f));
            Dscale = fmax(Dscale, fabs(D));
        }
        fricreg_structure_get_value(a, FRICREG_SVALUE_JENKINS, &ea);
        fricreg_structure_get_value(b, FRICREG_SVALUE_JENKINS, &eb);
        if (getenv("IWAN_PRINT"))
            fprintf(stderr,
                    "scheme %d: |x_iwan - x_copies| %.3e of %.4g; |f| %.2e of %.3g, |w| %.2e, "
                    "|D| %.2e of %.4g\n",
                    scheme, diff, amp, df, fscale, dw, dD, Dscale);
        ck_assert_msg(diff <= 1e-12 * amp, "scheme %d: histories differ by %g of %g", scheme, diff,
                      amp);
        ck_assert(df <= 1e-12 * fscale);
        ck_assert(dw <= 1e-12 * amp);
        ck_assert(dD <= 1e-12 * Dscale);
        ck_assert(Dscale > 0.0);
        ck_assert_double_eq_tol(ea, eb, 1e-12 * eb);
        fricreg_structure_free(a);
        fricreg_structure_free(b);
    }
}
END_TEST

/* One cycle's dissipation of an Iwan element at q = A sin(omega t), driven through a stiff
 * spring kg to ground as in test_structure_jenkins: sliders 0..2 slip (phi/k < A), slider 3
 * stays elastic. */
START_TEST(dissipation_closed_form)
{
    const double kg = 1e6, A = 0.4, omega = 1.0, mass = 1.0;
    const double k[4] = {3.0, 1.0, 2.0, 0.5}, phi[4] = {0.5, 0.05, 0.6, 0.3};
    const int N = 4000;
    const double T = 2.0 * PI / omega, dt = T / N;
    fricreg_structure *s = NULL;
    double J = 1.0, zero = 0.0, p = kg * A;
    ck_assert_int_eq(fricreg_structure_create(1, 1, &s), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_mass(s, 1, &mass), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_stiffness(s, 1, &kg), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_contacts(s, 1, 1, &J), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_bounds(s, 1, &zero), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_iwan(s, 1, 1, &J, 4, k, phi), FRICREG_OK);
    const int cycles = 3;
    double *g = malloc(((size_t)cycles * N + 1) * sizeof *g);
    ck_assert_ptr_nonnull(g);
    for (int j = 0; j <= cycles * N; j++)
        g[j] = sin(omega * j * dt);
    ck_assert_int_eq(fricreg_structure_set_load(s, 1, &p, 0.0, dt, (size_t)cycles * N + 1, g),
                     FRICREG_OK);
    free(g);
    double u0 = 0.0, v0 = A * omega;
    ck_assert_int_eq(fricreg_structure_set_initial(s, 1, &u0, &v0), FRICREG_OK);
    double D[4] = {0}, w[4];
    for (int c = 1; c <= cycles; c++) {
        ck_assert_int_eq(fricreg_structure_run(s, dt, c * T), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_get_iwan_state(s, 1, 4, NULL, w, &D[c]), FRICREG_OK);
    }
    double want = 0.0;
    for (int j = 0; j < 4; j++)
        if (phi[j] / k[j] < A)
            want += 4.0 * phi[j] * (A - phi[j] / k[j]);
    ck_assert_double_eq(w[3], 0.0); /* the elastic slider never moved */
    for (int c = 2; c <= cycles; c++) {
        double got = D[c] - D[c - 1];
        if (getenv("IWAN_PRINT"))
            fprintf(stderr, "cycle %d: dissipation %.10g, closed form %.10g (rel %.2e)\n", c, got,
                    want, fabs(got / want - 1.0));
        ck_assert_msg(fabs(got - want) <= 1e-4 * want, "cycle %d: %.10g, closed form %.10g", c, got,
                      want);
    }
    fricreg_structure_free(s);
}
END_TEST

/* The oscillator's steady state after 100 periods against HB at H = 21 with the same Iwan
 * element; the balance closes with the sliders' dissipation. */
START_TEST(oscillator_against_hb)
{
    struct model m = oscillator();
    const int N = 1024, periods = 100, nsteps = N * periods;
    const double omega = 1.5, dt = 2.0 * PI / omega / N;
    fricreg_structure *s = make(&m, 0, 0, omega, dt, nsteps);
    double rms = 0.0, x;
    for (int k = 1; k <= nsteps; k++) {
        double t0;
        QUIET_OK(fricreg_structure_get_value(s, FRICREG_SVALUE_TIME, &t0));
        QUIET_OK(fricreg_structure_step(s, k * dt - t0));
        if (k > nsteps - N) {
            fricreg_structure_get_state(s, 1, &x, NULL, NULL);
            rms += x * x;
        }
    }
    rms = sqrt(rms / N);
    int64_t imax, fails;
    fricreg_structure_get_stat(s, FRICREG_SSTAT_NEWTON_MAX, &imax);
    fricreg_structure_get_stat(s, FRICREG_SSTAT_NEWTON_FAILURES, &fails);

    const int H = 21;
    size_t nc = 2 * H + 1;
    double q[2 * 21 + 1], xh[2 * 21 + 1], pc = 0.0;
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(1, 1, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 1, m.M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 1, m.K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, 1, m.C), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_iwan(hb, 1, 1, m.J, NS, m.k, m.phi), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, 1, &pc, m.ps), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(hb, omega, nc, NULL, q), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_displacement(hb, 1, nc, xh), FRICREG_OK);
    double rms_hb = xh[0] * xh[0];
    for (size_t c = 1; c < nc; c++)
        rms_hb += 0.5 * xh[c] * xh[c];
    rms_hb = sqrt(rms_hb);
    fricreg_hb_free(hb);

    double residual, input, dissipated, w[NS];
    fricreg_structure_get_value(s, FRICREG_SVALUE_RESIDUAL, &residual);
    fricreg_structure_get_value(s, FRICREG_SVALUE_INPUT, &input);
    fricreg_structure_get_value(s, FRICREG_SVALUE_JENKINS, &dissipated);
    ck_assert_int_eq(fricreg_structure_get_iwan_state(s, 1, NS, NULL, w, NULL), FRICREG_OK);
    if (getenv("IWAN_PRINT"))
        fprintf(stderr,
                "RMS structure %.10g HB %.10g (rel %.2e); Newton max %lld, failures %lld; "
                "residual %.2e of input %.4g, dissipated %.4g\n",
                rms, rms_hb, fabs(rms / rms_hb - 1.0), (long long)imax, (long long)fails, residual,
                input, dissipated);
    ck_assert_msg(fabs(rms - rms_hb) <= 1e-3 * rms_hb, "RMS %.9g, HB %.9g", rms, rms_hb);
    ck_assert_int_eq(fails, 0);
    ck_assert(dissipated > 0.1 * input);
    ck_assert_msg(fabs(residual) <= 1e-9 * fabs(input), "residual %g of input %g", residual, input);
    fricreg_structure_free(s);
}
END_TEST

/* The CSR setter builds the same elements as the dense one; set_iwan with ns = 1 is
 * set_jenkins; the getters' sizes. */
START_TEST(csr_and_sizes)
{
    struct model m = oscillator();
    const double omega = 1.5, dt = 0.01;
    fricreg_structure *a = make(&m, 0, 0, omega, dt, 500), *b = make(&m, 0, 0, omega, dt, 500);
    int64_t rowptr[2] = {0, 1}, colind[1] = {0};
    ck_assert_int_eq(fricreg_structure_set_iwan_csr(b, 1, 1, 0, rowptr, colind, m.J, NS, m.k,
                                                    m.phi),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run(a, dt, 5.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run(b, dt, 5.0), FRICREG_OK);
    double fa, wa[NS], fb, wb[NS];
    fricreg_structure_get_iwan_state(a, 1, NS, &fa, wa, NULL);
    fricreg_structure_get_iwan_state(b, 1, NS, &fb, wb, NULL);
    ck_assert_double_eq(fa, fb);
    for (int j = 0; j < NS; j++)
        ck_assert_double_eq(wa[j], wb[j]);
    ck_assert(fabs(wa[0]) > 0.0);
    ck_assert_int_eq(fricreg_structure_get_iwan_state(a, 1, NS - 1, &fa, NULL, NULL),
                     FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_structure_get_jenkins_state(a, 1, &fa, NULL, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_iwan(a, 1, 1, m.J, 0, m.k, m.phi), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_structure_errmsg(a), "ns = 0"));

    /* ns = 1: Jenkins elements, bit for bit */
    fricreg_structure *c = make(&m, 0, 0, omega, dt, 500), *d = make(&m, 0, 0, omega, dt, 500);
    ck_assert_int_eq(fricreg_structure_set_iwan(c, 1, 1, m.J, 1, m.k, m.phi), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_jenkins(d, 1, 1, m.J, m.k, m.phi), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run(c, dt, 5.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run(d, dt, 5.0), FRICREG_OK);
    double uc, ud;
    fricreg_structure_get_state(c, 1, &uc, NULL, NULL);
    fricreg_structure_get_state(d, 1, &ud, NULL, NULL);
    ck_assert_double_eq(uc, ud);
    fricreg_structure_free(a);
    fricreg_structure_free(b);
    fricreg_structure_free(c);
    fricreg_structure_free(d);
}
END_TEST

/* The sliders' sums overflow, as in test_iwan's sums_overflow: two sliders of k = 1e300,
 * phi = 1e308 both slip beyond q = 1e8 (k q > phi), their force 2e308 > DBL_MAX. Each slider's
 * force is finite; until the sums were checked the step failed with the friction law's or
 * Newton's complaint of an infinite number (or, on the central difference, handed it on).
 * M = 1e300 keeps the stuck frequency sqrt(2e300/1e300) = 1.41 rad/s within the central
 * difference's bound at dt = 0.1. Each path fails with FRICREG_ENONFINITE naming the element,
 * the state unchanged: the equilibrium at t = 0 (u0 = 1e10), Newmark's Newton on the step's
 * end (v0 = 1e12: u_pred = 1e11), the central difference's explicit forces (the same), and
 * the joint path's Newton (a friction contact of bound 1 beside the element: joint_step.c).
 * A sum that stays finite (1e308 + 0.5e308 = 1.5e308 < DBL_MAX at t = 0, a = -1.5e308/M)
 * still steps on every path, unloading from that sum: Newton's merit, a sum of squares of
 * forces, no longer overflows beyond 1e154 on its own (Newmark's and the joint path's). */
enum { NEWMARK, CENTRAL, JOINT };

static fricreg_structure *overflowing(double phi1, double u0, double v0, int path)
{
    fricreg_structure *s = NULL;
    const double big_m = 1e300, one = 1.0, bound = path == JOINT ? 1.0 : 0.0;
    const double k[2] = {1e300, 1e300}, phi[2] = {1e308, phi1};
    ck_assert_int_eq(fricreg_structure_create(1, 1, &s), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_mass(s, 1, &big_m), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_stiffness(s, 1, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_contacts(s, 1, 1, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_bounds(s, 1, &bound), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_iwan(s, 1, 1, &one, 2, k, phi), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_initial(s, 1, &u0, &v0), FRICREG_OK);
    if (path == CENTRAL)
        ck_assert_int_eq(fricreg_structure_set_central_difference(s), FRICREG_OK);
    return s;
}

START_TEST(sums_overflow)
{
    const double cases[4][3] = {{1e10, 0.0, NEWMARK},
                                {0.0, 1e12, NEWMARK},
                                {0.0, 1e12, CENTRAL},
                                {0.0, 1e12, JOINT}};
    const char *when[4] = {"at t = 0:", "at t = 0.1:", "at t = 0.1:", "at t = 0.1:"};
    for (int c = 0; c < 4; c++) {
        fricreg_structure *s = overflowing(1e308, cases[c][0], cases[c][1], (int)cases[c][2]);
        ck_assert_int_eq(fricreg_structure_step(s, 0.1), FRICREG_ENONFINITE);
        ck_assert_int_eq(fricreg_structure_errcode(s), FRICREG_ENONFINITE);
        const char *msg = fricreg_structure_errmsg(s);
        ck_assert_msg(strstr(msg, "element 0's sliders sum to a force of inf") != NULL &&
                          strstr(msg, when[c]) != NULL && strstr(msg, "overflows") != NULL,
                      "case %d: %s", c, msg);
        double u, v, a, f = -1.0, w[2] = {-1.0, -1.0};
        ck_assert_int_eq(fricreg_structure_get_state(s, 1, &u, &v, &a), FRICREG_OK);
        ck_assert_double_eq(u, cases[c][0]);
        ck_assert_double_eq(v, cases[c][1]);
        ck_assert_int_eq(fricreg_structure_get_iwan_state(s, 1, 2, &f, w, NULL), FRICREG_OK);
        ck_assert_double_eq(f, 0.0);
        ck_assert_double_eq(w[0], 0.0);
        ck_assert_double_eq(w[1], 0.0);
        fricreg_structure_free(s);
    }
    for (int path = NEWMARK; path <= JOINT; path++) {
        fricreg_structure *s = overflowing(0.5e308, 1e10, 0.0, path);
        ck_assert_msg(fricreg_structure_step(s, 0.1) == FRICREG_OK, "path %d: %s", path,
                      fricreg_structure_errmsg(s));
        double f, u, v, a;
        ck_assert_int_eq(fricreg_structure_get_iwan_state(s, 1, 2, &f, NULL, NULL), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_get_state(s, 1, &u, &v, &a), FRICREG_OK);
        /* both slipped at t = 0, then unload elastically by k (u0 - u1): u1 = u0 - dt^2 a/2
         * (the central difference; Newmark's average acceleration takes a quarter of dt^2 at
         * each end, the same to 1e-5 of the step's travel: k dt^2 / 4M = 0.005) */
        double tol = path == CENTRAL ? 1.0 : 1e-2 * 0.005 * 1.5e8;
        ck_assert_msg(fabs(u - (1e10 - 0.005 * 1.5e8)) <= tol, "path %d: u = %.17g", path, u);
        ck_assert_double_eq_tol(f, 1.5e308 - 2e300 * (1e10 - u), 1e-9 * 1.5e308);
        fricreg_structure_free(s);
    }
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("structure_iwan");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, iwan_is_jenkins_copies);
    tcase_add_test(tc, dissipation_closed_form);
    tcase_add_test(tc, oscillator_against_hb);
    tcase_add_test(tc, csr_and_sizes);
    tcase_add_test(tc, sums_overflow);
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
