/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_qsma.c — Check suite for quasi-static modal analysis (fricreg_hb_qsma_at,
 * fricreg_hb_qsma_sensitivities, fricreg_hb_qsma.h). Where the numbers come from:
 *
 *   - the 1-dof Jenkins oscillator (m = k = 1, kt, mun, C = c M): stuck below a = mun/kt,
 *     ω² = 1 + kt; above, λ(a) = a + mun, ω² = 1 + mun/a, and Masing's loop is the Jenkins
 *     element's own, D = 4 mun (a − mun/kt); ζ = c/(2 ω_k) + D/(2π λ a). To 1e-12;
 *   - Segalman's four-parameter Iwan joint discretized into sliders (fricreg_iwan_set_segalman)
 *     on a unit modal mass beside K0: exactly the discrete sliders' sums (F = Σ min(k_j a, φ_j),
 *     D = Σ 4 φ_j (a − φ_j/k_j) over the slipped ones) to 1e-12, and the continuous model's
 *     closed form (the fit's modal Iwan, fricreg_fit_eval) to the discretization's error,
 *     measured and bounded below;
 *   - the EPMC backbone (fricreg_hb_nma_at, modal damping ζ_k = 0.1 % by Rayleigh's a0) of
 *     NLvib's 3-dof Jenkins chain (tests/support/hb_chain.h) and of the 60-dof chain with ten
 *     Jenkins elements (test_hb_nma_sensitivity.c's): the measured differences in ω and ζ,
 *     bounded with a margin (docs/identification.md states them);
 *   - a 2-dof model where a slipping slider is turned back and sticks again: the path against
 *     10^5 load steps with each slider's return mapping (an independent solve), to 1e-6;
 *   - a sparse model against the same model dense, to 1e-13;
 *   - 3-D contacts (the marched path): a contact loaded along a line at its rest state's normal
 *     force against the Jenkins oscillator of that slip force (the exact path), ω to 1e-12 and ζ
 *     within the trapezoid's bound at the kink; the inclined plane against EPMC (measured,
 *     bounded as above); the preloads' refusals;
 *   - the sensitivities against central differences of whole QSMA runs (relative step 1e-6:
 *     the path is exact, so the difference's error is its h² term and rounding), to 1e-6 of
 *     each derivative's largest magnitude, on those models, the Iwan one per slider, the 2-dof
 *     model through its slider stuck again, the inclined plane's contact (kt, mu, kn, n0; the
 *     marched path's own derivatives), and the amplitude and damping parameters;
 *   - every status, nothing written on failure.
 *
 * HB_PRINT=1 prints the measured agreements. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "fricreg_element.h"
#include "fricreg_fit.h"
#include "fricreg_iwan.h"
#include "fricreg_hb_qsma.h"
#include "hb_chain.h"

#define SENTINEL (-777.125)
#define LONG_N 60
#define LONG_M 10
#define NS 200 /* the Iwan joint's sliders */

static const double pi = 3.14159265358979323846;

enum {
    ELEMENT = FRICREG_HB_NMA_PARAM_ELEMENT,
    DAMPING = FRICREG_HB_NMA_PARAM_DAMPING,
    AMPLITUDE = FRICREG_HB_NMA_PARAM_AMPLITUDE
};

static int print(void)
{
    return getenv("HB_PRINT") != NULL;
}

/* ---- The models --------------------------------------------------------------------------- */

/* m = k = 1, one Jenkins element (kt, mun), C = c M. */
static fricreg_hb *oscillator(double kt, double mun, double c)
{
    const double one = 1.0, cc = c;
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(1, 1, 1, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 1, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 1, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, 1, &cc), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, 1, &one, &kt, &mun), FRICREG_OK);
    return hb;
}

/* A unit modal mass beside K0 with Segalman's joint (F_S, K_T, χ, β) in NS sliders. */
static fricreg_hb *modal_iwan(const double *p, double K0, double *k, double *phi)
{
    fricreg_iwan *iw = NULL;
    ck_assert_int_eq(fricreg_iwan_create(1, 1, NS, &iw), FRICREG_OK);
    ck_assert_int_eq(fricreg_iwan_set_segalman(iw, 1, p, p + 1, p + 2, p + 3, 1e-6), FRICREG_OK);
    ck_assert_int_eq(fricreg_iwan_get_params(iw, 1, NS, k, phi), FRICREG_OK);
    fricreg_iwan_free(iw);
    double params[2 * NS];
    memcpy(params, k, NS * sizeof *k);
    memcpy(params + NS, phi, NS * sizeof *phi);
    const double one = 1.0, zero = 0.0;
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(1, 1, 1, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 1, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 1, &K0), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, 1, &zero), FRICREG_OK);
    ck_assert_int_eq(
        fricreg_hb_add_elements(hb, fricreg_element_sliders(fricreg_element_lookup("iwan"), NS), 1,
                                1, &one, params),
        FRICREG_OK);
    return hb;
}

/* test_hb_nma_sensitivity.c's 60-dof chain: unit masses and springs, fixed at one end, ten
 * Jenkins elements to the ground at dofs 3, 9, ..., 57 (kt, mun), H = 3. */
static fricreg_hb *long_chain(double kt, double mun)
{
    static double M[LONG_N * LONG_N], K[LONG_N * LONG_N], J[LONG_M * LONG_N];
    const size_t n = LONG_N;
    memset(M, 0, sizeof M);
    memset(K, 0, sizeof K);
    memset(J, 0, sizeof J);
    for (size_t i = 0; i < n; i++) {
        M[i * n + i] = 1.0;
        K[i * n + i] = i + 1 < n ? 2.0 : 1.0;
        if (i > 0)
            K[i * n + i - 1] = K[(i - 1) * n + i] = -1.0;
    }
    double kts[LONG_M], muns[LONG_M];
    for (size_t e = 0; e < LONG_M; e++) {
        J[e * n + 6 * e + 3] = 1.0;
        kts[e] = kt;
        muns[e] = mun;
    }
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(n, LONG_M, 3, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, n, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, n, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, LONG_M, n, J, kts, muns), FRICREG_OK);
    return hb;
}

/* ---- Closed forms ------------------------------------------------------------------------- */

START_TEST(oscillator_closed_form)
{
    /* kt = 2.385, mun = 0.7: slip from a = 0.2935; c = 0.013 */
    const double kt = 2.385, mun = 0.7, c = 0.013, d = mun / kt, wk = sqrt(1.0 + kt);
    const double a[6] = {0.01, 0.2, 0.2935, 0.5, 3.7, 250.0};
    double w[6], z[6];
    fricreg_hb *hb = oscillator(kt, mun, c);
    ck_assert_int_eq(fricreg_hb_qsma_at(hb, 0, 6, a, w, z), FRICREG_OK);
    for (int i = 0; i < 6; i++) {
        double lam = a[i] <= d ? (1.0 + kt) * a[i] : a[i] + mun;
        double D = a[i] <= d ? 0.0 : 4.0 * mun * (a[i] - d);
        double we = sqrt(lam / a[i]), ze = c / (2.0 * wk) + D / (2.0 * pi * lam * a[i]);
        ck_assert_double_eq_tol(w[i], we, 1e-12 * we);
        ck_assert_double_eq_tol(z[i], ze, 1e-12 * fmax(ze, 1e-3));
    }
    fricreg_hb_free(hb);
}
END_TEST

/* The continuous joint's backbone by the fit's closed form, ω and ζ at modal amplitudes. */
static void continuous_iwan(const double *p, double K0, size_t n, const double *a, double *w,
                            double *z)
{
    fricreg_fit *fit = NULL;
    ck_assert_int_eq(fricreg_fit_create(&fit), FRICREG_OK);
    const double pf[FRICREG_FIT_NPARAMS] = {
        [FRICREG_FIT_FS] = p[0],   [FRICREG_FIT_KT] = p[1],   [FRICREG_FIT_CHI] = p[2],
        [FRICREG_FIT_BETA] = p[3], [FRICREG_FIT_ZETA0] = 0.0, [FRICREG_FIT_K0] = K0};
    ck_assert_int_eq(fricreg_fit_eval(fit, pf, FRICREG_FIT_DISPLACEMENT, n, a, w, z, NULL, NULL,
                                      NULL),
                     FRICREG_OK);
    for (size_t i = 0; i < n; i++)
        w[i] *= 2.0 * pi;
    fricreg_fit_free(fit);
}

START_TEST(iwan_closed_forms)
{
    /* F_S 1.3, K_T 2.385, χ −0.4, β 0.6; K0 0.8: φ_max = F_S (1 + β)/(K_T c) = 0.998 */
    const double p[4] = {1.3, 2.385, -0.4, 0.6}, K0 = 0.8;
    enum { N = 9 };
    const double a[N] = {1e-3, 3e-3, 0.01, 0.03, 0.1, 0.3, 0.7, 1.5, 4.0};
    double k[NS], phi[NS], w[N], z[N], wc[N], zc[N], ew = 0.0, ez = 0.0;
    fricreg_hb *hb = modal_iwan(p, K0, k, phi);
    ck_assert_int_eq(fricreg_hb_qsma_at(hb, 0, N, a, w, z), FRICREG_OK);
    continuous_iwan(p, K0, N, a, wc, zc);
    for (int i = 0; i < N; i++) {
        double F = 0.0, D = 0.0; /* the discrete sliders' own sums */
        for (int j = 0; j < NS; j++) {
            F += fmin(k[j] * a[i], phi[j]);
            if (phi[j] > 0.0 && k[j] * a[i] > phi[j])
                D += 4.0 * phi[j] * (a[i] - phi[j] / k[j]);
        }
        double lam = K0 * a[i] + F, we = sqrt(lam / a[i]), ze = D / (2.0 * pi * lam * a[i]);
        ck_assert_double_eq_tol(w[i], we, 1e-12 * we);
        ck_assert_double_eq_tol(z[i], ze, 1e-11 * ze + 1e-15);
        ew = fmax(ew, fabs(w[i] - wc[i]) / wc[i]);
        ez = fmax(ez, fabs(z[i] - zc[i]) / zc[i]);
    }
    if (print())
        printf("Iwan, %d sliders, against the continuous closed form: omega %.2e, zeta %.2e\n", NS,
               ew, ez);
    ck_assert_double_le(ew, 1.5e-4);
    ck_assert_double_le(ez, 2e-2);
    fricreg_hb_free(hb);
}
END_TEST

/* ---- A slider that sticks again, against small load steps ------------------------------- */

/* A 2-dof model (M = I) where element 0's slider, slipping, is reversed by element 1's slip
 * (found by a random search): the path sticks it again. */
static const double RK[4] = {3.0370836809450129, -1.7892334053708396, -1.7892334053708396,
                             2.1397012116106698};
static const double RJ[4] = {-1.0, 0.0, 1.0, 1.0};
static const double RKT[2] = {1.2423243703983373, 2.3987421473016695};
static const double RMU[2] = {0.18902423972684157, 1.085883817535771};

/* The same path by load steps dλ with each slider's return mapping (an independent solve:
 * Newton on the stick/slip forces from the committed slips, no events), λ(q) and its integral
 * by the trapezoid rule over the steps: ω and ζ at the amplitudes a[n]. */
static void load_steps(double dl, size_t n, const double *a, double *w, double *z)
{
    double K0[4], phi[2];
    for (int i = 0; i < 4; i++)
        K0[i] = RK[i];
    for (int e = 0; e < 2; e++)
        for (int i = 0; i < 2; i++)
            for (int j = 0; j < 2; j++)
                K0[2 * i + j] += RKT[e] * RJ[2 * e + i] * RJ[2 * e + j];
    /* the lower eigenpair of the symmetric 2 x 2 K0 */
    double tr = K0[0] + K0[3], det = K0[0] * K0[3] - K0[1] * K0[2];
    double l0 = 0.5 * tr - sqrt(0.25 * tr * tr - det);
    phi[0] = K0[1];
    phi[1] = l0 - K0[0];
    double nrm = hypot(phi[0], phi[1]), sg = fabs(phi[0]) >= fabs(phi[1]) ? phi[0] : phi[1];
    phi[0] /= copysign(nrm, sg);
    phi[1] /= copysign(nrm, sg);
    double x[2] = {0.0, 0.0}, zs[2] = {0.0, 0.0}, lam = 0.0, q = 0.0, I = 0.0;
    size_t i = 0;
    while (i < n) {
        double ln = lam + dl, f[2], kt[2];
        for (int it = 0; it < 50; it++) { /* Newton: piecewise linear, a few iterations */
            double R[2], A[4];
            for (int e = 0; e < 2; e++) {
                double u = RJ[2 * e] * x[0] + RJ[2 * e + 1] * x[1], ft = RKT[e] * (u - zs[e]);
                f[e] = fabs(ft) <= RMU[e] ? ft : copysign(RMU[e], ft);
                kt[e] = fabs(ft) <= RMU[e] ? RKT[e] : 0.0;
            }
            for (int r = 0; r < 2; r++) {
                R[r] = RK[2 * r] * x[0] + RK[2 * r + 1] * x[1] - ln * phi[r];
                for (int e = 0; e < 2; e++)
                    R[r] += RJ[2 * e + r] * f[e];
                for (int c = 0; c < 2; c++) {
                    A[2 * r + c] = RK[2 * r + c];
                    for (int e = 0; e < 2; e++)
                        A[2 * r + c] += kt[e] * RJ[2 * e + r] * RJ[2 * e + c];
                }
            }
            double dA = A[0] * A[3] - A[1] * A[2];
            double d0 = (A[3] * R[0] - A[1] * R[1]) / dA, d1 = (A[0] * R[1] - A[2] * R[0]) / dA;
            x[0] -= d0;
            x[1] -= d1;
            if (fabs(d0) + fabs(d1) < 1e-15)
                break;
        }
        for (int e = 0; e < 2; e++) { /* commit the slips */
            double u = RJ[2 * e] * x[0] + RJ[2 * e + 1] * x[1], ft = RKT[e] * (u - zs[e]);
            if (fabs(ft) > RMU[e])
                zs[e] = u - copysign(RMU[e], ft) / RKT[e];
        }
        double qn = phi[0] * x[0] + phi[1] * x[1];
        for (; i < n && qn >= a[i]; i++) {
            double la = lam + (ln - lam) * (a[i] - q) / (qn - q);
            double Ia = I + 0.5 * (a[i] - q) * (lam + la), D = 8.0 * Ia - 4.0 * a[i] * la;
            w[i] = sqrt(la / a[i]);
            z[i] = D / (2.0 * pi * la * a[i]);
        }
        I += 0.5 * (qn - q) * (lam + ln);
        q = qn;
        lam = ln;
    }
}

START_TEST(restick_against_load_steps)
{
    /* element 0 slips first (a = 0.64); element 1's slip (a = 0.68) turns its row back, so it
     * sticks again: the path's events against 10^5 load steps, whose error is O(dλ) at each
     * change of pattern */
    enum { N = 5 };
    const double M[4] = {1.0, 0.0, 0.0, 1.0}, a[N] = {0.3, 0.66, 0.7, 2.0, 5.0};
    double w[N], z[N], ws[N], zs[N], ew = 0.0, ez = 0.0;
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(2, 2, 1, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 2, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, RK), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 2, 2, RJ, RKT, RMU), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_qsma_at(hb, 0, N, a, w, z), FRICREG_OK);
    load_steps(2.2e-4, N, a, ws, zs);
    for (int i = 0; i < N; i++) {
        ew = fmax(ew, fabs(w[i] - ws[i]) / ws[i]);
        ez = fmax(ez, fabs(z[i] - zs[i]));
    }
    if (print())
        printf("a slider stuck again, against load steps: omega %.2e, zeta %.2e (absolute)\n", ew,
               ez);
    ck_assert_double_le(ew, 1e-6);
    ck_assert_double_le(ez, 1e-6);
    fricreg_hb_free(hb);
}
END_TEST

/* ---- 3-D contacts: the marched path ------------------------------------------------------- */

/* Three unit masses, K = diag(1, 2, 3), one contact_3d element on them (x, y, normal: J = I):
 * its lowest stuck mode moves x alone, so that the contact loads along x at the normal force
 * of its rest state, N = 3 n0/(3 + kn) (the preload pushes the normal dof to g_0 = −n0/(3 +
 * kn)): the Jenkins oscillator of slip force mu N. */
static fricreg_hb *contact_line(double kt, double mu, double kn, double n0)
{
    const double M[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, K[9] = {1, 0, 0, 0, 2, 0, 0, 0, 3};
    const double p[5] = {kt, mu, kn, n0, 0.0};
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(3, 1, 1, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 3, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 3, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("contact_3d"), 1, 3, M, p),
                     FRICREG_OK);
    return hb;
}

/* The same with a Jenkins element with lift-off (jenkins_normal) on two unit masses, K =
 * diag(1, 3): x slides, the second dof presses; the same rest state's N = 3 n0/(3 + kn). */
static fricreg_hb *liftoff_line(double kt, double mu, double kn, double n0)
{
    const double M[4] = {1, 0, 0, 1}, K[4] = {1, 0, 0, 3}, p[5] = {kt, mu, kn, n0, 0.0};
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(2, 1, 1, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 2, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("jenkins_normal"), 1, 2, M,
                                             p),
                     FRICREG_OK);
    return hb;
}

/* test_hb_contact_3d.c's inclined plane (test_hb_nma_sensitivity.c's contact model): a 2-dof
 * mass on one contact_3d element whose normal row (0.4, −0.3) couples both dofs, so that the
 * normal force moves as the contact slides and the tangential force turns; kt = 1.5, mu = 0.4,
 * kn = 2, n0 = 0.5 (the HB layout's order: kt, mu, kn, n0). */
static const double PLANE_P[4] = {1.5, 0.4, 2.0, 0.5};
static fricreg_hb *contact_plane(void)
{
    const double M[4] = {1.0, 0.0, 0.0, 1.2}, K[4] = {2.0, -0.3, -0.3, 1.5};
    const double J[6] = {1.0, 0.0, 0.0, 1.0, 0.4, -0.3};
    const double p[5] = {PLANE_P[0], PLANE_P[1], PLANE_P[2], PLANE_P[3], 0.0};
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(2, 1, 5, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 2, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("contact_3d"), 1, 2, J, p),
                     FRICREG_OK);
    return hb;
}

START_TEST(contact_line_as_jenkins)
{
    /* The march's return mapping is exact along a line, so λ is the exact path's to rounding;
     * its trapezoid misses the kink at the first slip by at most kt h²/8 in ∫λ (h the step,
     * 2^floor(log2(a_max/256))), so ζ by kt h² / (2π λ a). */
    const double kt = 2.5, mu = 0.35, kn = 4.0, n0 = 1.4, N = 3.0 * n0 / (3.0 + kn);
    const double a[6] = {0.05, 0.19, 0.1961, 0.5, 1.7, 6.0};
    double w[6], z[6], wj[6], zj[6], wl[6], zl[6];
    fricreg_hb *hb = contact_line(kt, mu, kn, n0), *jk = oscillator(kt, mu * N, 0.0);
    fricreg_hb *lo = liftoff_line(kt, mu, kn, n0);
    ck_assert_int_eq(fricreg_hb_qsma_at(hb, 0, 6, a, w, z), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_qsma_at(jk, 0, 6, a, wj, zj), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_qsma_at(lo, 0, 6, a, wl, zl), FRICREG_OK);
    double h = ldexp(1.0, (int)floor(log2(a[5] / 256.0))), worst = 0.0;
    for (size_t i = 0; i < 6; i++) {
        double lambda = wj[i] * wj[i] * a[i], bound = kt * h * h / (2.0 * pi * lambda * a[i]);
        ck_assert_double_eq_tol(w[i], wj[i], 1e-12 * wj[i]);
        ck_assert_double_le(fabs(z[i] - zj[i]), 1.0001 * bound + 1e-14);
        worst = fmax(worst, fabs(z[i] - zj[i]) / bound);
        /* the lift-off element on its line is the contact on its own, to rounding */
        ck_assert_double_eq_tol(wl[i], w[i], 1e-13 * w[i]);
        ck_assert_double_eq_tol(zl[i], z[i], 1e-13 * z[i] + 1e-16);
    }
    if (print())
        printf("contact_3d on a line: zeta within %.2f of the trapezoid's bound\n", worst);
    fricreg_hb_free(hb);
    fricreg_hb_free(jk);
    fricreg_hb_free(lo);
}
END_TEST

/* ---- Against EPMC ------------------------------------------------------------------------- */

/* The largest differences of QSMA against EPMC (modal damping) at n amplitudes from a0 to a1,
 * geometric (EPMC's march at ratios 1.1 apart: with longer steps it may land on another
 * branch): ω and ζ relative, ζ absolute, and ζ relative from the amplitude dev up. */
struct agreement {
    double w, z, z_abs, z_dev;
};

static struct agreement against_epmc(const char *name, fricreg_hb *hb, size_t mode, double a0,
                                     double a1, size_t n, double dev)
{
    double a[64], w[64], z[64];
    for (size_t i = 0; i < n; i++)
        a[i] = a0 * pow(a1 / a0, (double)i / (double)(n - 1));
    clock_t t0 = clock();
    ck_assert_int_eq(fricreg_hb_qsma_at(hb, mode, n, a, w, z), FRICREG_OK);
    clock_t t1 = clock();
    int status = fricreg_hb_nma_at(hb, mode, FRICREG_HB_NMA_DAMPING_MODAL, n, a);
    clock_t t2 = clock();
    if (status != FRICREG_OK)
        printf("%s: %s\n", name, fricreg_hb_errmsg(hb));
    ck_assert_int_eq(status, FRICREG_OK);
    struct agreement g = {0.0, 0.0, 0.0, 0.0};
    for (size_t i = 0; i < n; i++) {
        double ai, we, ze;
        ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &ai, &we, &ze, 0, 0, NULL), FRICREG_OK);
        g.w = fmax(g.w, fabs(w[i] - we) / we);
        g.z = fmax(g.z, fabs(z[i] - ze) / ze);
        g.z_abs = fmax(g.z_abs, fabs(z[i] - ze));
        if (a[i] >= dev)
            g.z_dev = fmax(g.z_dev, fabs(z[i] - ze) / ze);
        if (getenv("HB_PRINT_ALL"))
            printf("%s a %.4g: omega %.8g %.8g zeta %.6g %.6g\n", name, a[i], w[i], we, z[i], ze);
    }
    if (print())
        printf("%s: QSMA against EPMC, omega %.2e, zeta %.2e (%.2e absolute, %.2e from a = %g); "
               "CPU %.2g s against %.2g s\n",
               name, g.w, g.z, g.z_abs, g.z_dev, dev, (double)(t1 - t0) / CLOCKS_PER_SEC,
               (double)(t2 - t1) / CLOCKS_PER_SEC);
    return g;
}

/* Rayleigh's a0 for ζ_k = 0.1 % of mode k (ω_k from QSMA below any slip). */
static void light_damping(fricreg_hb *hb, size_t mode)
{
    double a = 1e-9, w, z;
    ck_assert_int_eq(fricreg_hb_qsma_at(hb, mode, 1, &a, &w, &z), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_rayleigh(hb, 2e-3 * w, 0.0), FRICREG_OK);
}

START_TEST(epmc_chain)
{
    fricreg_hb *hb = hb_chain(0, 0);
    ck_assert_ptr_nonnull(hb);
    light_damping(hb, 0);
    ck_assert_int_eq(fricreg_hb_set_newton(hb, 1e-12, 50), FRICREG_OK);
    /* from below the first slip (a = 0.87) to 0.97: beyond 0.975 EPMC's backbone folds (an
     * internal resonance, which QSMA has no counterpart of). Measured: ω 1.36e-2, ζ 1.95 of
     * EPMC's (1.31e-2 absolute): the stiff elements (kt = 20 beside unit springs) slipping
     * change the mode's shape, the slipped structure's lowest mode far below ω_k. */
    struct agreement g = against_epmc("3-dof chain", hb, 0, 0.5, 0.97, 30, 0.0);
    ck_assert_double_le(g.w, 1.7e-2);
    ck_assert_double_le(g.z, 2.4);
    ck_assert_double_le(g.z_abs, 1.6e-2);
    fricreg_hb_free(hb);
}
END_TEST

START_TEST(epmc_long_chain)
{
    fricreg_hb *hb = long_chain(0.2, 0.02);
    light_damping(hb, 2);
    ck_assert_int_eq(fricreg_hb_set_newton(hb, 1e-12, 50), FRICREG_OK);
    /* mode 2 from below the first slip (a = 0.62) to a = 4, where ζ reaches 0.15 (not light):
     * measured ω 3.15e-2, ζ 0.235 of EPMC's (7.0e-3 absolute), the largest relative one just
     * past the onset; from a = 0.78 (1.25 times the onset) 5.1e-2 */
    struct agreement g = against_epmc("60-dof chain", hb, 2, 0.3, 4.0, 28, 0.78);
    ck_assert_double_le(g.w, 4e-2);
    ck_assert_double_le(g.z, 0.3);
    ck_assert_double_le(g.z_abs, 9e-3);
    ck_assert_double_le(g.z_dev, 6.5e-2);
    fricreg_hb_free(hb);
}
END_TEST

START_TEST(epmc_contact_3d)
{
    fricreg_hb *hb = contact_plane();
    light_damping(hb, 0);
    ck_assert_int_eq(fricreg_hb_set_newton(hb, 1e-12, 50), FRICREG_OK);
    /* from stuck (the first slip at a = 0.11) to 3, the normal force moving with the slip and
     * the contact opening at the top. Measured: ω 3.58e-2, ζ 0.190 of EPMC's from a = 0.3 up
     * (2.07e-2 absolute; just past the onset, where ζ is small, up to 7.8 times): the static
     * path presses the contact one way only, where the vibration presses and relieves it in
     * turn, so Masing's doubled curve is QSMA's assumption here, not the contact's loop */
    struct agreement g = against_epmc("contact_3d plane", hb, 0, 0.05, 3.0, 30, 0.3);
    ck_assert_double_le(g.w, 4.5e-2);
    ck_assert_double_le(g.z_dev, 0.25);
    ck_assert_double_le(g.z_abs, 2.6e-2);
    fricreg_hb_free(hb);
}
END_TEST

/* ---- Sensitivities against central differences --------------------------------------------- */

struct par {
    int kind;
    size_t first, count, index;
};

/* QSMA's ω, ζ with parameter P moved to value (an element's, Rayleigh's a0, or the amplitudes
 * scaled by value). */
static void run_at(fricreg_hb *hb, size_t mode, size_t n, const double *a, const struct par *P,
                   double value, double *w, double *z)
{
    double as[32];
    for (size_t i = 0; i < n; i++)
        as[i] = P->kind == AMPLITUDE ? a[i] * value : a[i];
    if (P->kind == ELEMENT)
        ck_assert_int_eq(fricreg_hb_set_element_param(hb, P->first, P->count, P->index, value),
                         FRICREG_OK);
    if (P->kind == DAMPING)
        ck_assert_int_eq(fricreg_hb_set_rayleigh(hb, value, 0.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_qsma_at(hb, mode, n, as, w, z), FRICREG_OK);
}

/* Each parameter's exact derivatives against central differences, to tol of the largest. */
static void check_differences(const char *name, fricreg_hb *hb, size_t mode, size_t n,
                              const double *a, size_t np, const struct par *P, const double *p0,
                              double tol)
{
    int kind[8];
    size_t first[8], count[8], index[8];
    double dw[32 * 8], dz[32 * 8], worst = 0.0;
    for (size_t k = 0; k < np; k++) {
        kind[k] = P[k].kind;
        first[k] = P[k].first;
        count[k] = P[k].count;
        index[k] = P[k].index;
    }
    ck_assert_int_eq(fricreg_hb_qsma_sensitivities(hb, mode, n, a, np, kind, first, count, index,
                                                   dw, dz),
                     FRICREG_OK);
    for (size_t k = 0; k < np; k++) {
        double h = 1e-6 * p0[k], wp[32], zp[32], wm[32], zm[32], mw = 0.0, mz = 0.0, ew = 0.0,
               ez = 0.0;
        run_at(hb, mode, n, a, &P[k], p0[k] + h, wp, zp);
        run_at(hb, mode, n, a, &P[k], p0[k] - h, wm, zm);
        run_at(hb, mode, n, a, &P[k], p0[k], wm + 16, zm + 16); /* back */
        for (size_t i = 0; i < n; i++) {
            /* the amplitude's difference is in the scale s of a s: d/ds = a d/da */
            double sw = P[k].kind == AMPLITUDE ? a[i] : 1.0;
            double cw = (wp[i] - wm[i]) / (2.0 * h), cz = (zp[i] - zm[i]) / (2.0 * h);
            mw = fmax(mw, fabs(cw));
            mz = fmax(mz, fabs(cz));
            ew = fmax(ew, fabs(sw * dw[i * np + k] - cw));
            ez = fmax(ez, fabs(sw * dz[i * np + k] - cz));
        }
        if (getenv("HB_PRINT_ALL"))
            printf("%s parameter %zu: omega %.2e of %.3g, zeta %.2e of %.3g\n", name, k, ew, mw, ez,
                   mz);
        ck_assert_double_le(ew, tol * mw + 1e-13);
        ck_assert_double_le(ez, tol * mz + 1e-13);
        worst = fmax(worst, fmax(ew / fmax(mw, 1e-300), ez / fmax(mz, 1e-300)));
    }
    if (print())
        printf("%s: sensitivities against central differences within %.2e\n", name, worst);
}

START_TEST(sensitivities_oscillator)
{
    /* the closed form's derivatives: above slip ω² = 1 + mun/a, dω/dmun = 1/(2 ω a) */
    const double kt = 2.385, mun = 0.7, a = 3.7;
    fricreg_hb *hb = oscillator(kt, mun, 0.0);
    int kind[3] = {ELEMENT, ELEMENT, AMPLITUDE};
    size_t first[3] = {0, 0, 0}, count[3] = {1, 1, 1}, index[3] = {0, 1, 0};
    double dw[3], dz[3], w = sqrt(1.0 + mun / a);
    ck_assert_int_eq(fricreg_hb_qsma_sensitivities(hb, 0, 1, &a, 3, kind, first, count, index, dw,
                                                   dz),
                     FRICREG_OK);
    ck_assert_double_eq_tol(dw[1], 1.0 / (2.0 * w * a), 1e-12);
    ck_assert_double_eq_tol(dw[2], -mun / (a * a) / (2.0 * w), 1e-12);
    /* ζ = 4 mun (a − mun/kt) / (2π (a + mun) a): dζ/dkt = 4 mun² / kt² / (2π (a + mun) a) */
    ck_assert_double_eq_tol(dz[0], 4.0 * mun * mun / (kt * kt) / (2.0 * pi * (a + mun) * a), 1e-12);
    ck_assert_double_eq_tol(dw[0], 0.0, 1e-15);
    fricreg_hb_free(hb);
}
END_TEST

START_TEST(sensitivities_chain)
{
    fricreg_hb *hb = hb_chain(0, 0);
    ck_assert_ptr_nonnull(hb);
    ck_assert_int_eq(fricreg_hb_set_rayleigh(hb, 0.004, 0.0), FRICREG_OK);
    const double a[6] = {0.02, 0.07, 0.15, 0.4, 1.3, 4.0};
    const struct par P[5] = {{ELEMENT, 0, 2, 0},
                             {ELEMENT, 0, 2, 1},
                             {ELEMENT, 1, 1, 0},
                             {DAMPING, 0, 0, 1},
                             {AMPLITUDE, 0, 0, 0}};
    const double p0[5] = {20.0, 1.0, 20.0, 0.004, 1.0};
    check_differences("3-dof chain", hb, 0, 6, a, 5, P, p0, 1e-6);
    check_differences("3-dof chain mode 1", hb, 1, 6, a, 5, P, p0, 1e-6);
    fricreg_hb_free(hb);
}
END_TEST

START_TEST(sensitivities_long_chain)
{
    fricreg_hb *hb = long_chain(0.2, 0.02);
    ck_assert_int_eq(fricreg_hb_set_rayleigh(hb, 0.001, 0.0), FRICREG_OK);
    const double a[6] = {0.3, 0.8, 1.3, 2.1, 3.3, 4.0};
    const struct par P[5] = {{ELEMENT, 0, LONG_M, 0},
                             {ELEMENT, 0, LONG_M, 1},
                             {ELEMENT, 4, 3, 0},
                             {DAMPING, 0, 0, 1},
                             {AMPLITUDE, 0, 0, 0}};
    const double p0[5] = {0.2, 0.02, 0.2, 0.001, 1.0};
    check_differences("60-dof chain", hb, 2, 6, a, 5, P, p0, 1e-6);
    fricreg_hb_free(hb);
}
END_TEST

START_TEST(sensitivities_restick)
{
    /* through the event where element 0's slider sticks again: its slip moves with every
     * parameter (the event's λ and x) */
    const double M[4] = {1.0, 0.0, 0.0, 1.0}, a[6] = {0.3, 0.66, 0.7, 1.0, 2.0, 5.0};
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(2, 2, 1, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 2, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, RK), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_rayleigh(hb, 0.004, 0.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 2, 2, RJ, RKT, RMU), FRICREG_OK);
    const struct par P[6] = {{ELEMENT, 0, 1, 0}, {ELEMENT, 0, 1, 1}, {ELEMENT, 1, 1, 0},
                             {ELEMENT, 1, 1, 1}, {DAMPING, 0, 0, 1}, {AMPLITUDE, 0, 0, 0}};
    const double p0[6] = {RKT[0], RMU[0], RKT[1], RMU[1], 0.004, 1.0};
    check_differences("2-dof, a slider stuck again", hb, 0, 6, a, 6, P, p0, 1e-6);
    fricreg_hb_free(hb);
}
END_TEST

START_TEST(sensitivities_iwan)
{
    const double p[4] = {1.3, 2.385, -0.4, 0.6}, K0 = 0.8;
    double k[NS], phi[NS];
    fricreg_hb *hb = modal_iwan(p, K0, k, phi);
    const double a[5] = {0.004, 0.04, 0.3, 0.7, 2.5};
    /* a slider slipping early (its slip force), one late (its stiffness), the delta's */
    const struct par P[4] = {{ELEMENT, 0, 1, NS + 150},
                             {ELEMENT, 0, 1, 190},
                             {ELEMENT, 0, 1, 2 * NS - 1},
                             {AMPLITUDE, 0, 0, 0}};
    const double p0[4] = {phi[150], k[190], phi[NS - 1], 1.0};
    check_differences("Iwan", hb, 0, 5, a, 4, P, p0, 1e-6);
    fricreg_hb_free(hb);
}
END_TEST

START_TEST(sensitivities_liftoff)
{
    /* test_hb_liftoff.c's contact (dof 0 slides, dof 1 presses, g = −x_1): a jenkins_normal
     * element kt = 1.7, mu = 0.5, kn = 3, n0 = 0.6, from stuck through slip to lift-off */
    const double M[4] = {1.3, 0, 0, 0.9}, K[4] = {2.385, -0.3, -0.3, 1.5}, J[4] = {1, 0, 0, -1};
    const double p[5] = {1.7, 0.5, 3.0, 0.6, 0.0}, a[6] = {0.05, 0.2, 0.45, 0.9, 1.6, 3.0};
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(2, 1, 5, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 2, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_rayleigh(hb, 0.004, 0.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("jenkins_normal"), 1, 2, J,
                                             p),
                     FRICREG_OK);
    const struct par P[6] = {{ELEMENT, 0, 1, 0}, {ELEMENT, 0, 1, 1}, {ELEMENT, 0, 1, 2},
                             {ELEMENT, 0, 1, 3}, {DAMPING, 0, 0, 1}, {AMPLITUDE, 0, 0, 0}};
    const double p0[6] = {p[0], p[1], p[2], p[3], 0.004, 1.0};
    check_differences("jenkins_normal", hb, 0, 6, a, 6, P, p0, 1e-6);
    fricreg_hb_free(hb);
}
END_TEST

START_TEST(sensitivities_contact_3d)
{
    /* the plane from stuck (a = 0.02) through slip with the normal force moving to lift-off;
     * the marched path's own derivatives, which the differences of whole runs see */
    fricreg_hb *hb = contact_plane();
    ck_assert_int_eq(fricreg_hb_set_rayleigh(hb, 0.004, 0.0), FRICREG_OK);
    const double a[6] = {0.02, 0.15, 0.4, 0.9, 1.6, 3.0};
    const struct par P[6] = {{ELEMENT, 0, 1, 0}, {ELEMENT, 0, 1, 1}, {ELEMENT, 0, 1, 2},
                             {ELEMENT, 0, 1, 3}, {DAMPING, 0, 0, 1}, {AMPLITUDE, 0, 0, 0}};
    const double p0[6] = {PLANE_P[0], PLANE_P[1], PLANE_P[2], PLANE_P[3], 0.004, 1.0};
    check_differences("contact_3d plane", hb, 0, 6, a, 6, P, p0, 1e-6);
    check_differences("contact_3d plane mode 1", hb, 1, 6, a, 6, P, p0, 1e-6);
    fricreg_hb_free(hb);
}
END_TEST

/* ---- A sparse model ---------------------------------------------------------------------- */

START_TEST(sparse_as_dense)
{
    /* NLvib's chain with Rayleigh damping, its M and K given by compressed columns (the model
     * sparse), against the dense one: the same numbers to rounding */
    const int64_t mp[4] = {0, 1, 2, 3}, mi[3] = {0, 1, 2}, kp[4] = {0, 2, 5, 7},
                  ki[7] = {0, 1, 0, 1, 2, 1, 2};
    const double mv[3] = {1.0, 1.0, 1.0}, kv[7] = {2.0, -1.0, -1.0, 2.0, -1.0, -1.0, 2.0};
    const double J[6] = {1.0, 0.0, 0.0, -1.0, 1.0, 0.0}, kt[2] = {20.0, 20.0}, mun[2] = {1.0, 1.0};
    const double a[4] = {0.5, 0.95, 2.0, 7.0};
    double w[4], z[4], ws[4], zs[4];
    fricreg_hb *hb = hb_chain(0, 0), *sp = NULL;
    ck_assert_ptr_nonnull(hb);
    ck_assert_int_eq(fricreg_hb_set_rayleigh(hb, 0.01, 0.003), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_create(3, 2, 3, &sp), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass_csc(sp, 3, 0, mp, mi, mv), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness_csc(sp, 3, 0, kp, ki, kv), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_rayleigh(sp, 0.01, 0.003), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(sp, 2, 3, J, kt, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_qsma_at(hb, 0, 4, a, w, z), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_qsma_at(sp, 0, 4, a, ws, zs), FRICREG_OK);
    for (int i = 0; i < 4; i++) {
        ck_assert_double_eq_tol(ws[i], w[i], 1e-13 * w[i]);
        ck_assert_double_eq_tol(zs[i], z[i], 1e-13 * z[i]);
    }
    fricreg_hb_free(hb);
    fricreg_hb_free(sp);
}
END_TEST

/* ---- Statuses ------------------------------------------------------------------------------ */

static void unwritten(const double *v, size_t n)
{
    for (size_t i = 0; i < n; i++)
        ck_assert_double_eq(v[i], SENTINEL);
}

START_TEST(statuses)
{
    fricreg_hb *hb = oscillator(2.385, 0.7, 0.0);
    double a[3] = {0.1, 0.5, 1.0}, w[3] = {SENTINEL, SENTINEL, SENTINEL},
           z[3] = {SENTINEL, SENTINEL, SENTINEL};
    ck_assert_int_eq(fricreg_hb_qsma_at(NULL, 0, 3, a, w, z), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_qsma_at(hb, 0, 3, NULL, w, z), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_qsma_at(hb, 0, 3, a, NULL, z), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_qsma_at(hb, 0, 3, a, w, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_qsma_at(hb, 1, 3, a, w, z), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_qsma_at(hb, 0, 0, a, w, z), FRICREG_EINVAL);
    a[1] = 0.05; /* not increasing */
    ck_assert_int_eq(fricreg_hb_qsma_at(hb, 0, 3, a, w, z), FRICREG_EINVAL);
    a[1] = NAN;
    ck_assert_int_eq(fricreg_hb_qsma_at(hb, 0, 3, a, w, z), FRICREG_ENONFINITE);
    a[1] = 0.5;
    a[0] = 0.0;
    ck_assert_int_eq(fricreg_hb_qsma_at(hb, 0, 3, a, w, z), FRICREG_EINVAL);
    a[0] = 0.1;
    unwritten(w, 3);
    unwritten(z, 3);
    /* sensitivities: NULLs, a kind, an index, a range, a0 without Rayleigh */
    int kind[1] = {ELEMENT};
    size_t first[1] = {0}, count[1] = {1}, index[1] = {0};
    double dw[3] = {SENTINEL, SENTINEL, SENTINEL}, dz[3] = {SENTINEL, SENTINEL, SENTINEL};
    ck_assert_int_eq(fricreg_hb_qsma_sensitivities(hb, 0, 3, a, 1, NULL, first, count, index, dw,
                                                   dz),
                     FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_qsma_sensitivities(hb, 0, 3, a, 1, kind, first, count, index, NULL,
                                                   dz),
                     FRICREG_ENULL);
    index[0] = 2;
    ck_assert_int_eq(fricreg_hb_qsma_sensitivities(hb, 0, 3, a, 1, kind, first, count, index, dw,
                                                   dz),
                     FRICREG_EINVAL);
    index[0] = 0;
    count[0] = 2;
    ck_assert_int_eq(fricreg_hb_qsma_sensitivities(hb, 0, 3, a, 1, kind, first, count, index, dw,
                                                   dz),
                     FRICREG_EINVAL);
    count[0] = 1;
    kind[0] = 7;
    ck_assert_int_eq(fricreg_hb_qsma_sensitivities(hb, 0, 3, a, 1, kind, first, count, index, dw,
                                                   dz),
                     FRICREG_EINVAL);
    kind[0] = DAMPING;
    index[0] = 1;
    ck_assert_int_eq(fricreg_hb_qsma_sensitivities(hb, 0, 3, a, 1, kind, first, count, index, dw,
                                                   dz),
                     FRICREG_EINVAL);
    unwritten(dw, 3);
    unwritten(dz, 3);
    ck_assert_int_eq(fricreg_hb_qsma_sensitivities(hb, 0, 3, a, 0, NULL, NULL, NULL, NULL, dw, dz),
                     FRICREG_OK);
    fricreg_hb_free(hb);
}
END_TEST

START_TEST(refusals)
{
    double a[2] = {0.1, 3.0}, w[2] = {SENTINEL, SENTINEL}, z[2] = {SENTINEL, SENTINEL};
    /* macroslip: no spring beside the element, K_t = 0 once it slips at a = 0.2935 */
    const double one = 1.0, zero = 0.0, kt = 2.385, mun = 0.7;
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(1, 1, 1, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_qsma_at(hb, 0, 2, a, w, z), FRICREG_EINVAL); /* no elements */
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 1, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 1, &zero), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, 1, &one, &kt, &mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_qsma_at(hb, 0, 2, a, w, z), FRICREG_ESINGULAR);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "macroslip"));
    ck_assert_int_eq(fricreg_hb_qsma_at(hb, 0, 1, a, w, z), FRICREG_OK); /* below it */
    ck_assert_double_eq_tol(w[0], sqrt(kt), 1e-14);
    ck_assert_double_eq(w[1], SENTINEL);
    fricreg_hb_free(hb);
    /* a type it does not take: iwan_normal (sliders sharing a normal law), named */
    const double Je[4] = {1.0, 0.0, 0.4, -0.3}, pc[7] = {2.0, 1.0, 0.3, 0.2, 1.5, 1.0, 0.0};
    const fricreg_element_type *iwan2 =
        fricreg_element_sliders(fricreg_element_lookup("iwan_normal"), 2);
    ck_assert_int_eq(fricreg_hb_create(2, 1, 3, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, (const double[4]){2.0, -0.3, -0.3, 1.5}),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, iwan2, 1, 2, Je, pc), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_qsma_at(hb, 0, 2, a, w, z), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "iwan_normal"));
    fricreg_hb_free(hb);
    /* contacts whose preloads at rest open one another: both press dof 0, and contact 0's
     * n0 = 5 pushes it back by 1.03, past what contact 1's n0 = 0.1 holds (N = −1.45) */
    const double J2[12] = {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 1, 0};
    const double p2[10] = {2.0, 0.3, 1.5, 5.0, 0.0, 2.0, 0.3, 1.5, 0.1, 0.0};
    ck_assert_int_eq(fricreg_hb_create(2, 2, 3, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, (const double[4]){2.0, -0.3, -0.3, 1.5}),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("contact_3d"), 2, 2, J2,
                                             p2),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_qsma_at(hb, 0, 2, a, w, z), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "contact 1"));
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "open"));
    /* or close one: contact 1 (n0 = −0.1, open) pressed by contact 0's push from the other side */
    const double J3[12] = {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, -1, 0};
    const double p3[10] = {2.0, 0.3, 1.5, 5.0, 0.0, 2.0, 0.3, 1.5, -0.1, 0.0};
    ck_assert_int_eq(fricreg_hb_clear_elements(hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("contact_3d"), 2, 2, J3,
                                             p3),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_qsma_at(hb, 0, 2, a, w, z), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "close"));
    fricreg_hb_free(hb);
    /* no rest state: a body held by its contact alone (K = 0), whose preload fixes the normal
     * dof but not the tangential ones (K + kn J_n^T J_n singular; K_0 is not) */
    const double I3[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, Z3[9] = {0};
    ck_assert_int_eq(fricreg_hb_create(3, 1, 3, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 3, Z3), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("contact_3d"), 1, 3, I3,
                                             (const double[5]){2.0, 0.3, 1.5, 1.0, 0.0}),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_qsma_at(hb, 0, 2, a, w, z), FRICREG_ESINGULAR);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "rest state"));
    fricreg_hb_free(hb);
    /* a contact's gap (index 4): HB's normal law has none */
    hb = contact_plane();
    int kind = ELEMENT;
    size_t first = 0, count = 1, gap = 4;
    double dw[2] = {SENTINEL, SENTINEL}, dz[2] = {SENTINEL, SENTINEL};
    ck_assert_int_eq(fricreg_hb_qsma_sensitivities(hb, 0, 2, a, 1, &kind, &first, &count, &gap, dw,
                                                   dz),
                     FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "kt, mu, kn, n0"));
    unwritten(dw, 2);
    unwritten(dz, 2);
    fricreg_hb_free(hb);
    ck_assert_double_eq(w[1], SENTINEL);
    ck_assert_double_eq(z[1], SENTINEL);
}
END_TEST

static Suite *qsma_suite(void)
{
    Suite *s = suite_create("hb_qsma");
    TCase *tc = tcase_create("closed_forms");
    tcase_add_test(tc, oscillator_closed_form);
    tcase_add_test(tc, iwan_closed_forms);
    tcase_add_test(tc, restick_against_load_steps);
    tcase_add_test(tc, sparse_as_dense);
    tcase_add_test(tc, contact_line_as_jenkins);
    suite_add_tcase(s, tc);
    tc = tcase_create("epmc");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, epmc_chain);
    tcase_add_test(tc, epmc_long_chain);
    tcase_add_test(tc, epmc_contact_3d);
    suite_add_tcase(s, tc);
    tc = tcase_create("sensitivities");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, sensitivities_oscillator);
    tcase_add_test(tc, sensitivities_chain);
    tcase_add_test(tc, sensitivities_long_chain);
    tcase_add_test(tc, sensitivities_iwan);
    tcase_add_test(tc, sensitivities_restick);
    tcase_add_test(tc, sensitivities_contact_3d);
    tcase_add_test(tc, sensitivities_liftoff);
    suite_add_tcase(s, tc);
    tc = tcase_create("statuses");
    tcase_add_test(tc, statuses);
    tcase_add_test(tc, refusals);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(qsma_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
