/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_beam_si.c — Check suite for harmonic balance in SI units at the defaults
 * (fricreg_hb_nma_continue, fricreg_hb_continue; fricreg_hb.h): a published joints benchmark's
 * beam, its slip force scaled over two decades.
 *
 * The model: the cantilevered Euler–Bernoulli beam with a Jenkins element of M. Scheel et al.
 * (J. Sound Vib. 2020) as NLvib's users model it (Krack & Gross, "Harmonic Balance for
 * Nonlinear Vibration Problems", Springer 2019; there mu N = 1 N): steel (E = 185 GPa, ρ = 7830 kg/m³), 0.7 m long, a 0.03 m square
 * section, 7 Hermite elements (14 dofs: a translation and a rotation per free node), a Jenkins
 * element kt = 1.3e6 N/m, slip force mu N on the translation of the third free node, Rayleigh
 * damping of 0.8 % and 0.2 % in the stuck beam's first two modes. The entries of K from 5e5 to
 * 3e8, of M from 7e-5 to 0.5 (SI units: N/m, kg and their rotational kin); mu N = 10, 100 and
 * 1000 N, the element's slip at 7.7e-6 to 7.7e-4 m.
 *
 * Where the numbers come from:
 * - similarity: the beam is linear and the element's force homogeneous of degree one in (u,
 *   mu N), so with mu N, the amplitudes and the loads scaled by s the solutions scale by s and
 *   ω, ζ stay: each run is the mu N = 10 N run scaled, and the defaults must give it at every
 *   scale (every Newton's tolerance relative to the model's scale, the continuation's unknowns
 *   scaled);
 * - the stuck limit: the linear mode of K + kt e e^T, from GSL's generalized symmetric
 *   eigensolver, ζ the Rayleigh damping's 0.8 % (the damping proportional there, so the
 *   nonlinear mode's ζ is the linear one's exactly);
 * - the fully slipped limit: the element's force bounded by mu N, ω tends to the beam's first
 *   mode without it (GSL's eigensolver on K). */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_sort_vector.h>

#include "fricreg_hb.h"

#define NODES 8 /* with the clamped one */
#define N (2 * (NODES - 1))
#define KT 1.3e6
#define JOINT 4 /* the translation of the third free node */
#define NPOINTS 30

static double M[N * N], K[N * N], C[N * N], J[N];
static double w_stuck[2], w_free, alpha, beta;

/* The two lowest natural frequencies of (K + kt e_JOINT e_JOINT^T, M), rad/s. */
static void frequencies(double kt, double w[2])
{
    double Kc[N * N], Mc[N * N];
    for (size_t i = 0; i < N * N; i++)
        Kc[i] = K[i], Mc[i] = M[i];
    Kc[JOINT * N + JOINT] += kt;
    gsl_matrix_view A = gsl_matrix_view_array(Kc, N, N), B = gsl_matrix_view_array(Mc, N, N);
    gsl_vector *ev = gsl_vector_alloc(N);
    gsl_eigen_gensymm_workspace *ws = gsl_eigen_gensymm_alloc(N);
    ck_assert_int_eq(gsl_eigen_gensymm(&A.matrix, &B.matrix, ev, ws), 0);
    gsl_sort_vector(ev);
    w[0] = sqrt(gsl_vector_get(ev, 0));
    w[1] = sqrt(gsl_vector_get(ev, 1));
    gsl_eigen_gensymm_free(ws);
    gsl_vector_free(ev);
}

/* The beam's M, K (consistent Hermite elements, the clamped node's dofs removed), its Rayleigh
 * C = α M + β (K + kt e e^T) of ζ = 0.008 and 0.002 in the stuck modes, and J. */
static void beam(void)
{
    const double len = 0.7, side = 0.03, E = 185e9, rho = 7830.0, L = len / (NODES - 1);
    const double k = E * side * side * side * side / 12.0 / (L * L * L),
                 m = rho * side * side * L / 420.0;
    const double Ke[16] = {12,  6 * L,  -12, 6 * L,  6 * L, 4 * L * L, -6 * L, 2 * L * L,
                           -12, -6 * L, 12,  -6 * L, 6 * L, 2 * L * L, -6 * L, 4 * L * L};
    const double Me[16] = {156, 22 * L, 54,  -13 * L, 22 * L,  4 * L * L,  13 * L,  -3 * L * L,
                           54,  13 * L, 156, -22 * L, -13 * L, -3 * L * L, -22 * L, 4 * L * L};
    for (int e = 0; e < NODES - 1; e++)
        for (int a = 0; a < 4; a++)
            for (int b = 0; b < 4; b++) {
                int ga = 2 * e + a - 2, gb = 2 * e + b - 2;
                if (ga >= 0 && gb >= 0) {
                    K[ga * N + gb] += k * Ke[4 * a + b];
                    M[ga * N + gb] += m * Me[4 * a + b];
                }
            }
    J[JOINT] = 1.0;
    double wf[2];
    frequencies(KT, w_stuck);
    frequencies(0.0, wf);
    w_free = wf[0];
    const double z1 = 0.008, z2 = 0.002, w1 = w_stuck[0], w2 = w_stuck[1];
    beta = 2.0 * (z2 * w2 - z1 * w1) / (w2 * w2 - w1 * w1);
    alpha = 2.0 * z1 * w1 - beta * w1 * w1;
    for (size_t i = 0; i < N * N; i++)
        C[i] = alpha * M[i] + beta * K[i];
    C[JOINT * N + JOINT] += beta * KT; /* proportional to the stuck beam's M and K + kt e e^T */
}

/* The beam with slip force mun at H harmonics, every setting at its default. */
static fricreg_hb *model(int H, double mun)
{
    if (J[JOINT] == 0.0)
        beam();
    fricreg_hb *hb = NULL;
    const double kt = KT;
    ck_assert_int_eq(fricreg_hb_create(N, 1, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, N, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, N, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, N, C), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, N, J, &kt, &mun), FRICREG_OK);
    return hb;
}

/* The backbone of mode 0 at H, slip force mun, from a = 1e-7 mun (m √kg; stuck: the slip
 * onset lies between 3.3e-6 and 4.1e-6 mun) to 1e-2 mun (slipping over nearly all the
 * element's travel). */
static fricreg_hb *backbone(int H, double mun)
{
    fricreg_hb *hb = model(H, mun);
    int status = fricreg_hb_nma_continue(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 1e-7 * mun,
                                         1e-2 * mun, NPOINTS);
    ck_assert_msg(status == FRICREG_OK, "H = %d, mu N = %g: %s", H, mun, fricreg_hb_errmsg(hb));
    return hb;
}

/* (a) At H = 7 and 15, mu N = 10, 100, 1000 N, the defaults: every backbone runs, each the
 * 10 N one scaled (a by s, ω and ζ the same, to 1e-8 relative; measured at most 4.1e-10,
 * 2.8e-11 and 1.8e-10); its ends the closed-form limits (stuck: ω and ζ = 0.008 to 1e-10,
 * measured 2.7e-13; slipped: ω to 1e-5 of the free beam's, measured 3.9e-6). */
START_TEST(backbones_scale)
{
    const int Hs[2] = {7, 15};
    const double muns[3] = {10.0, 100.0, 1000.0};
    for (int h = 0; h < 2; h++) {
        fricreg_hb *ref = backbone(Hs[h], muns[0]);
        for (int k = 1; k < 3; k++) {
            fricreg_hb *hb = backbone(Hs[h], muns[k]);
            double s = muns[k] / muns[0], da = 0.0, dw = 0.0, dz = 0.0;
            ck_assert_uint_eq(fricreg_hb_nma_points(hb), NPOINTS);
            for (size_t i = 0; i < NPOINTS; i++) {
                double a, w, z, ar, wr, zr;
                ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &a, &w, &z, 0, 0, NULL), FRICREG_OK);
                ck_assert_int_eq(fricreg_hb_nma_point(ref, i, &ar, &wr, &zr, 0, 0, NULL),
                                 FRICREG_OK);
                da = fmax(da, fabs(a / (s * ar) - 1.0));
                dw = fmax(dw, fabs(w / wr - 1.0));
                dz = fmax(dz, fabs(z / zr - 1.0));
            }
            if (getenv("HB_PRINT"))
                fprintf(stderr, "H = %d, mu N = %g: a %.2e omega %.2e zeta %.2e\n", Hs[h], muns[k],
                        da, dw, dz);
            ck_assert_double_le(da, 1e-8);
            ck_assert_double_le(dw, 1e-8);
            ck_assert_double_le(dz, 1e-8);
            fricreg_hb_free(hb);
        }
        double a, w, z;
        ck_assert_int_eq(fricreg_hb_nma_point(ref, 0, &a, &w, &z, 0, 0, NULL), FRICREG_OK);
        if (getenv("HB_PRINT"))
            fprintf(stderr, "stuck: omega %.3e zeta %.3e\n", w / w_stuck[0] - 1.0, z / 0.008 - 1.0);
        ck_assert_double_eq_tol(w, w_stuck[0], 1e-10 * w_stuck[0]);
        ck_assert_double_eq_tol(z, 0.008, 1e-10 * 0.008);
        ck_assert_int_eq(fricreg_hb_nma_point(ref, NPOINTS - 1, &a, &w, &z, 0, 0, NULL),
                         FRICREG_OK);
        if (getenv("HB_PRINT"))
            fprintf(stderr, "slipped: omega %.3e\n", w / w_free - 1.0);
        ck_assert_double_eq_tol(w, w_free, 1e-5 * w_free);
        fricreg_hb_free(ref);
    }
}
END_TEST

/* The frequency response at H, slip force mun, a force mun on the tip's translation, from 250
 * to 450 rad/s (the first mode slipped at 302 rad/s, stuck at 390), the defaults. */
static fricreg_hb *response(int H, double mun)
{
    fricreg_hb *hb = model(H, mun);
    double pc[N] = {0}, ps[N] = {0};
    pc[N - 2] = mun;
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, N, pc, ps), FRICREG_OK);
    int status = fricreg_hb_continue(hb, 250.0, 450.0, 2 * (size_t)H + 1, NULL);
    ck_assert_msg(status == FRICREG_OK, "H = %d, mu N = %g: %s", H, mun, fricreg_hb_errmsg(hb));
    return hb;
}

/* (b) The forced response, the same similarity: at H = 7 and 15 the 1000 N branch is the 10 N
 * one scaled, point by point (the same points, Ω to 1e-9, each dof's RMS by s to 1e-8). The
 * two branches differ by rounding carried along 94 points: measured Ω 6.6e-11 and RMS 2.8e-10
 * on the reference BLAS, 1.0e-10 and 3.9e-10 on OpenBLAS with two threads. */
START_TEST(responses_scale)
{
    const int Hs[2] = {7, 15};
    for (int h = 0; h < 2; h++) {
        fricreg_hb *ref = response(Hs[h], 10.0), *hb = response(Hs[h], 1000.0);
        size_t n = fricreg_hb_points(ref);
        ck_assert_uint_eq(fricreg_hb_points(hb), n);
        double dw = 0.0, dr = 0.0;
        for (size_t i = 0; i < n; i++) {
            double w, wr, rms[N], rmsr[N];
            ck_assert_int_eq(fricreg_hb_point(hb, i, &w, N, rms), FRICREG_OK);
            ck_assert_int_eq(fricreg_hb_point(ref, i, &wr, N, rmsr), FRICREG_OK);
            dw = fmax(dw, fabs(w / wr - 1.0));
            for (size_t k = 0; k < N; k++)
                dr = fmax(dr, fabs(rms[k] / (100.0 * rmsr[k]) - 1.0));
        }
        if (getenv("HB_PRINT"))
            fprintf(stderr, "H = %d: %zu points, omega %.2e rms %.2e\n", Hs[h], n, dw, dr);
        ck_assert_double_le(dw, 1e-9);
        ck_assert_double_le(dr, 1e-8);
        fricreg_hb_free(ref);
        fricreg_hb_free(hb);
    }
}
END_TEST

int main(void)
{
    Suite *s = suite_create("hb_beam_si");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, responses_scale);
    suite_add_tcase(s, tc);
    /* (a), six backbones (2 s): the release tier's (hb_beam_si_release); (b) is the same
     * similarity on the forced branches */
    TCase *backbones = tcase_create("backbones");
    tcase_set_timeout(backbones, 300);
    tcase_set_tags(backbones, "release");
    tcase_add_test(backbones, backbones_scale);
    suite_add_tcase(s, backbones);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
