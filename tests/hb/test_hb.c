/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb.c — Check suite for the harmonic-balance driver (fricreg_hb.h).
 *
 * Where the numbers come from:
 *   - linear: with mun so large that the elements stick (kt (max q − min q) < 2 mun), the
 *     stabilized element is the spring kt on the harmonics (fricreg_aft.h's centred stick), so
 *     the response is the closed form (K + J^T kt J − Ω² M + i Ω C) X = p_c − i p_s at h = 1,
 *     and 0 on the other harmonics; X solved here by GSL's complex LU. To 1e-12 relative.
 *   - nonlinear: the steady state of the same equations in time, M x'' + C x' + K x + J^T f =
 *     p(t), by average-acceleration Newmark (beta = 1/4, gamma = 1/2, second order) with Newton
 *     on the displacements and the Jenkins elements' return mapping (fricreg_jenkins_trial,
 *     commit after each step; tests/support/jenkins_newmark.h), 1024 steps a period, from rest for long enough that the RMS of
 *     the last two periods agree to 1e-7 (asserted: the reference has reached its steady
 *     state), the RMS over the last period by the rectangle rule (exact for a periodic
 *     trigonometric polynomial sampled over one period). The frequencies are those where
 *     every element slips in each period (kt (max q − min q) > 2 mun, asserted on the time
 *     series), where the periodic state is unique (the play operator's wiping-out). HB at
 *     H = 21 against it within 1e-3 relative.
 *   - continuation: the peak of a friction-damped resonance lies between the resonance of the
 *     structure with the elements removed (slipped: K) and stuck (K + J^T kt J); their natural
 *     frequencies by GSL's generalized symmetric eigensolver. The branch's peak against the
 *     largest of point solves on a grid around it. */
#include <check.h>
#include <float.h>
#include <stdint.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_linalg.h>

#include "fricreg_element.h"
#include "fricreg_hb.h"
#include "fricreg_jenkins.h"
#include "jenkins_newmark.h"

#define SENTINEL (-777.125)
#define MAXN JENKINS_MODEL_MAXN
#define MAXM JENKINS_MODEL_MAXM
static const double PI = 3.14159265358979323846;

static fricreg_hb *make(const struct jenkins_model *s, int H, int rayleigh)
{
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(s->n, s->m, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, s->n, s->M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, s->n, s->K), FRICREG_OK);
    if (rayleigh)
        ck_assert_int_eq(fricreg_hb_set_rayleigh(hb, 0.03, 0.01), FRICREG_OK);
    else
        ck_assert_int_eq(fricreg_hb_set_damping(hb, s->n, s->C), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, s->m, s->n, s->J, s->kt, s->mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, s->n, s->pc, s->ps), FRICREG_OK);
    return hb;
}

/* rms_k² = x0² + (1/2) sum_h (a_h² + b_h²) of HB's displacement at Omega. */
static void hb_rms(fricreg_hb *hb, const struct jenkins_model *s, int H, double omega, double *rms)
{
    size_t nc = 2 * (size_t)H + 1, nq = s->m * nc;
    double q[MAXM * 83], x[MAXN * 83];
    ck_assert_int_eq(fricreg_hb_solve(hb, omega, nq, NULL, q), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_displacement(hb, s->n, nc, x), FRICREG_OK);
    for (size_t k = 0; k < s->n; k++) {
        double r = x[k * nc] * x[k * nc];
        for (size_t c = 1; c < nc; c++)
            r += 0.5 * x[k * nc + c] * x[k * nc + c];
        rms[k] = sqrt(r);
    }
}

/* The linear closed form at h = 1 with stiffness K + J^T kt J, into X[2n] (a_1, b_1 per dof). */
static void linear_response(const struct jenkins_model *s, double omega, double *X)
{
    size_t n = s->n;
    double D[2 * MAXN * MAXN], b[2 * MAXN], x[2 * MAXN];
    for (size_t i = 0; i < n; i++)
        for (size_t k = 0; k < n; k++) {
            double kk = s->K[i * n + k];
            for (size_t e = 0; e < s->m; e++)
                kk += s->J[e * n + i] * s->kt[e] * s->J[e * n + k];
            D[2 * (i * n + k)] = kk - omega * omega * s->M[i * n + k];
            D[2 * (i * n + k) + 1] = omega * s->C[i * n + k];
        }
    for (size_t i = 0; i < n; i++)
        b[2 * i] = s->pc[i], b[2 * i + 1] = -s->ps[i];
    gsl_matrix_complex_view Dv = gsl_matrix_complex_view_array(D, n, n);
    gsl_vector_complex_view bv = gsl_vector_complex_view_array(b, n);
    gsl_vector_complex_view xv = gsl_vector_complex_view_array(x, n);
    gsl_permutation *p = gsl_permutation_alloc(n);
    int sg;
    gsl_linalg_complex_LU_decomp(&Dv.matrix, p, &sg);
    gsl_linalg_complex_LU_solve(&Dv.matrix, p, &bv.vector, &xv.vector);
    gsl_permutation_free(p);
    for (size_t i = 0; i < n; i++)
        X[2 * i] = x[2 * i], X[2 * i + 1] = -x[2 * i + 1]; /* X = a − i b */
}

START_TEST(linear_stuck_closed_form)
{
    for (int which = 0; which < 2; which++) {
        struct jenkins_model s = which ? jenkins_model_chain() : jenkins_model_oscillator();
        for (size_t e = 0; e < s.m; e++)
            s.mun[e] = 1e6;
        const int Hs[2] = {1, 3};
        for (int t = 0; t < 2; t++) {
            int H = Hs[t];
            size_t nc = 2 * (size_t)H + 1;
            fricreg_hb *hb = make(&s, H, which);
            const double omegas[3] = {0.7385, 1.61, 2.9};
            for (int w = 0; w < 3; w++) {
                double q[MAXM * 7], x[MAXN * 7], X[2 * MAXN], amax = 0.0;
                ck_assert_int_eq(fricreg_hb_solve(hb, omegas[w], s.m * nc, NULL, q), FRICREG_OK);
                ck_assert_int_eq(fricreg_hb_displacement(hb, s.n, nc, x), FRICREG_OK);
                linear_response(&s, omegas[w], X);
                for (size_t i = 0; i < 2 * s.n; i++)
                    amax = fmax(amax, fabs(X[i]));
                for (size_t k = 0; k < s.n; k++)
                    for (size_t c = 0; c < nc; c++) {
                        double want = (c == 1 || c == 2) ? X[2 * k + c - 1] : 0.0;
                        ck_assert_double_eq_tol(x[k * nc + c], want, 1e-12 * amax);
                    }
                /* q = J x */
                for (size_t e = 0; e < s.m; e++)
                    for (size_t c = 0; c < nc; c++) {
                        double jx = 0.0;
                        for (size_t k = 0; k < s.n; k++)
                            jx += s.J[e * s.n + k] * x[k * nc + c];
                        ck_assert_double_eq_tol(q[e * nc + c], jx, 1e-12 * amax);
                    }
            }
            fricreg_hb_free(hb);
        }
    }
}
END_TEST

static void against_time_domain(const struct jenkins_model *s, const double *omegas, int count,
                                int periods)
{
    const int H = 21;
    fricreg_hb *hb = make(s, H, 0);
    for (int w = 0; w < count; w++) {
        double rms[MAXN], prev[MAXN], ref[MAXN];
        int slips = jenkins_newmark_rms(s, omegas[w], 1024, periods, ref, prev, NULL);
        ck_assert_msg(slips, "Omega = %g: an element sticks in the reference", omegas[w]);
        hb_rms(hb, s, H, omegas[w], rms);
        for (size_t k = 0; k < s->n; k++) {
            if (getenv("HB_PRINT"))
                fprintf(stderr, "Omega %g dof %zu: HB %.9g Newmark %.9g rel %.2e steady %.2e\n",
                        omegas[w], k, rms[k], ref[k], fabs(rms[k] / ref[k] - 1.0),
                        fabs(prev[k] / ref[k] - 1.0));
            ck_assert_msg(fabs(ref[k] - prev[k]) <= 1e-7 * ref[k],
                          "Omega = %g dof %zu: the reference is not steady (%.9g, %.9g)", omegas[w],
                          k, prev[k], ref[k]);
            ck_assert_msg(fabs(rms[k] - ref[k]) <= 1e-3 * ref[k],
                          "Omega = %g dof %zu: HB %.9g, Newmark %.9g", omegas[w], k, rms[k],
                          ref[k]);
        }
    }
    fricreg_hb_free(hb);
}

START_TEST(oscillator_against_time_domain)
{
    struct jenkins_model s = jenkins_model_oscillator();
    const double omegas[5] = {1.2, 1.35, 1.5, 1.7, 2.1};
    against_time_domain(&s, omegas, 5, 100);
}
END_TEST

START_TEST(chain_against_time_domain)
{
    struct jenkins_model s = jenkins_model_chain();
    const double omegas[5] = {1.0, 1.15, 1.3, 1.45, 1.6};
    against_time_domain(&s, omegas, 5, 100);
}
END_TEST

/* A stiffness set again after a solve: the next solve is the new model's, bit for bit as a
 * driver built with it (nothing kept across the change: K's static solves, D_0 = K at every
 * Ω, are kept while the model stays, src/hb/dynamic.c). */
START_TEST(stiffness_set_again)
{
    struct jenkins_model s = jenkins_model_chain();
    double rms[MAXN], ref[MAXN], K0[MAXN * MAXN];
    fricreg_hb *hb = make(&s, 3, 0);
    hb_rms(hb, &s, 3, 1.3, rms);
    memcpy(K0, s.K, sizeof K0);
    for (size_t i = 0; i < s.n * s.n; i++)
        s.K[i] *= 1.25;
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, s.n, s.K), FRICREG_OK);
    hb_rms(hb, &s, 3, 1.3, rms);
    fricreg_hb *fresh = make(&s, 3, 0);
    hb_rms(fresh, &s, 3, 1.3, ref);
    for (size_t k = 0; k < s.n; k++)
        ck_assert_double_eq(rms[k], ref[k]);
    memcpy(s.K, K0, sizeof K0);
    fricreg_hb_free(fresh);
    fricreg_hb_free(hb);
}
END_TEST

/* The RMS converges in H (the element force has kinks, its coefficients fall like h^-2, the
 * displacement's like h^-4): against H = 40, H = 21 is within 2e-6 (measured 4.0e-7 and
 * 2.8e-7) and H = 7 within 2e-4 (6.5e-5, 3.2e-5). */
START_TEST(harmonics_converge)
{
    struct jenkins_model s = jenkins_model_chain();
    const double omegas[2] = {1.0, 1.6};
    for (int w = 0; w < 2; w++) {
        double r40[MAXN], r21[MAXN], r7[MAXN];
        const int Hs[3] = {40, 21, 7};
        double *out[3] = {r40, r21, r7};
        for (int i = 0; i < 3; i++) {
            fricreg_hb *hb = make(&s, Hs[i], 0);
            hb_rms(hb, &s, Hs[i], omegas[w], out[i]);
            fricreg_hb_free(hb);
        }
        ck_assert_double_le(fabs(r21[0] / r40[0] - 1.0), 2e-6);
        ck_assert_double_le(fabs(r7[0] / r40[0] - 1.0), 2e-4);
    }
}
END_TEST

/* The chain's first natural frequency with stiffness K + J^T diag(kts) J. */
static double first_frequency(const struct jenkins_model *s, const double *kts)
{
    size_t n = s->n;
    double K[MAXN * MAXN], M[MAXN * MAXN], lam[MAXN];
    memcpy(M, s->M, sizeof M);
    for (size_t i = 0; i < n; i++)
        for (size_t k = 0; k < n; k++) {
            K[i * n + k] = s->K[i * n + k];
            for (size_t e = 0; e < s->m; e++)
                K[i * n + k] += s->J[e * n + i] * kts[e] * s->J[e * n + k];
        }
    gsl_matrix_view Kv = gsl_matrix_view_array(K, n, n), Mv = gsl_matrix_view_array(M, n, n);
    gsl_vector_view lv = gsl_vector_view_array(lam, n);
    gsl_eigen_gensymm_workspace *w = gsl_eigen_gensymm_alloc(n);
    gsl_eigen_gensymm(&Kv.matrix, &Mv.matrix, &lv.vector, w);
    gsl_eigen_gensymm_free(w);
    double lo = lam[0];
    for (size_t i = 1; i < n; i++)
        lo = fmin(lo, lam[i]);
    return sqrt(lo);
}

START_TEST(continuation_over_resonance)
{
    struct jenkins_model s = jenkins_model_chain();
    const int H = 7;
    const double zero[MAXM] = {0.0, 0.0};
    double w_slip = first_frequency(&s, zero), w_stick = first_frequency(&s, s.kt);
    /* the first resonance: from below the slipped one to beyond the stuck one (the second
     * mode, near 1.7 rad/s, stays outside) */
    double omega0 = 0.8 * w_slip, omega1 = 1.1 * w_stick;
    fricreg_hb *hb = make(&s, H, 1);
    ck_assert_int_eq(fricreg_hb_set_continuation(hb, 0.01, 1e-6, 0.02, 2000), FRICREG_OK);
    clock_t c0 = clock();
    ck_assert_int_eq(fricreg_hb_continue(hb, omega0, omega1, s.m * 15, NULL), FRICREG_OK);
    double seconds = (double)(clock() - c0) / CLOCKS_PER_SEC;
    size_t np = fricreg_hb_points(hb);
    ck_assert_uint_ge(np, 10);
    double omega, rms[MAXN], first, last = 0.0, peak = 0.0, w_peak = 0.0, w_lo = 0.0, w_hi = 0.0;
    ck_assert_int_eq(fricreg_hb_point(hb, 0, &first, s.n, rms), FRICREG_OK);
    for (size_t k = 0; k < np; k++) {
        ck_assert_int_eq(fricreg_hb_point(hb, k, &omega, s.n, rms), FRICREG_OK);
        if (rms[0] > peak) {
            peak = rms[0], w_peak = omega;
            double o;
            ck_assert_int_eq(fricreg_hb_point(hb, k ? k - 1 : k, &o, s.n, rms), FRICREG_OK);
            w_lo = o;
            ck_assert_int_eq(fricreg_hb_point(hb, k + 1 < np ? k + 1 : k, &o, s.n, rms),
                             FRICREG_OK);
            w_hi = o;
        }
        last = omega;
        if (getenv("HB_PRINT"))
            fprintf(stderr, "%g %g %g %g\n", omega, rms[0], rms[1], rms[2]);
    }
    ck_assert_double_eq(first, omega0);
    ck_assert_double_eq(last, omega1);
    fprintf(stderr,
            "hb continuation: %zu points, %.3f s; peak %.6g at %.6g (slip %.6g, stick %.6g)\n", np,
            seconds, peak, w_peak, w_slip, w_stick);
    ck_assert_double_gt(w_peak, w_slip);
    ck_assert_double_lt(w_peak, w_stick);
    /* point solves on a grid between the peak's neighbours: none beyond the branch's peak by
     * more than the branch's resolution, and their maximum within the neighbours */
    double best = 0.0, w_best = 0.0;
    for (int g = 0; g <= 40; g++) {
        double o = w_lo + (w_hi - w_lo) * g / 40.0, r[MAXN];
        hb_rms(hb, &s, H, o, r);
        if (r[0] > best)
            best = r[0], w_best = o;
    }
    ck_assert_double_ge(best, peak * (1.0 - 1e-9));
    ck_assert_double_le(best, peak * 1.01);
    ck_assert_double_ge(w_best, w_lo);
    ck_assert_double_le(w_best, w_hi);
    /* downwards, from the last point's solution: the same ends, the same peak */
    double q1[2 * 15], back = 0.0;
    ck_assert_int_eq(fricreg_hb_solve(hb, omega1, s.m * 15, NULL, q1), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_continue(hb, omega1, omega0, s.m * 15, q1), FRICREG_OK);
    np = fricreg_hb_points(hb);
    ck_assert_int_eq(fricreg_hb_point(hb, 0, &first, s.n, rms), FRICREG_OK);
    ck_assert_double_eq(first, omega1);
    for (size_t k = 0; k < np; k++) {
        ck_assert_int_eq(fricreg_hb_point(hb, k, &omega, s.n, rms), FRICREG_OK);
        back = fmax(back, rms[0]);
    }
    ck_assert_double_eq(omega, omega0);
    ck_assert_double_le(fabs(back - best), 0.01 * best);
    fricreg_hb_free(hb);
}
END_TEST

START_TEST(bad_input)
{
    struct jenkins_model s = jenkins_model_chain();
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(3, 2, 3, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_create(0, 2, 3, &hb), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_create(3, 0, 3, &hb), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_create(3, 2, 0, &hb), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_create(3, 2, FRICREG_HB_MAX_HARMONICS + 1, &hb), FRICREG_EINVAL);
    ck_assert_ptr_null(hb);
    fricreg_hb_free(NULL);
    ck_assert_int_eq(fricreg_hb_errcode(NULL), FRICREG_OK);
    ck_assert_str_eq(fricreg_hb_errmsg(NULL), "NULL HB driver");
    ck_assert_uint_eq(fricreg_hb_points(NULL), 0);
    ck_assert_int_eq(fricreg_hb_create(3, 2, 3, &hb), FRICREG_OK);
    size_t nq = 2 * 7;
    double q[14], x[21], bad[9], om;
    for (int i = 0; i < 14; i++)
        q[i] = SENTINEL;
    /* no elements yet */
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.0, nq, NULL, q), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_displacement(hb, 3, 7, x), FRICREG_EINVAL);
    /* the setters */
    ck_assert_int_eq(fricreg_hb_set_mass(NULL, 3, s.M), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 3, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 2, s.M), FRICREG_ESIZE);
    memcpy(bad, s.K, sizeof bad);
    bad[4] = NAN;
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 3, bad), FRICREG_ENONFINITE);
    bad[4] = s.K[4];
    bad[1] += 1e-6;
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 3, bad), FRICREG_ENOTSYM);
    ck_assert_int_eq(fricreg_hb_errcode(hb), FRICREG_ENOTSYM);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "set_stiffness"));
    char buf[8];
    size_t len = fricreg_hb_errmsg_copy(hb, buf, sizeof buf);
    ck_assert_uint_eq(len, strlen(fricreg_hb_errmsg(hb)));
    ck_assert_uint_eq(strlen(buf), 7);
    ck_assert_uint_eq(fricreg_hb_errmsg_copy(hb, NULL, 8), 0);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, 3, bad), FRICREG_ENOTSYM);
    ck_assert_int_eq(fricreg_hb_set_rayleigh(NULL, 0.1, 0.1), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_set_rayleigh(hb, INFINITY, 0.1), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_hb_set_rayleigh(hb, -0.1, 0.1), FRICREG_EINVAL);
    double Jz[6] = {0.0, 0.0, 0.0, -1.0, 1.0, 0.0}, ktb[2] = {1.0, 0.0}, munb[2] = {1.0, -1.0};
    ck_assert_int_eq(fricreg_hb_set_elements(NULL, 2, 3, s.J, s.kt, s.mun), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 2, 3, NULL, s.kt, s.mun), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 2, 3, s.J, s.kt, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, 3, s.J, s.kt, s.mun), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 2, 2, s.J, s.kt, s.mun), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 2, 3, Jz, s.kt, s.mun), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 2, 3, s.J, ktb, s.mun), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 2, 3, s.J, s.kt, munb), FRICREG_EINVAL);
    munb[1] = NAN;
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 2, 3, s.J, s.kt, munb), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_hb_set_excitation(NULL, 3, s.pc, s.ps), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, 3, s.pc, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, 1, s.pc, s.ps), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, 3, s.pc, munb), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_hb_set_newton(NULL, 1e-10, 5), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_set_newton(hb, NAN, 5), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_hb_set_newton(hb, 1.0, 5), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_set_newton(hb, 1e-10, 0), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_set_continuation(NULL, 0.01, 1e-6, 0.1, 10), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_set_continuation(hb, NAN, 1e-6, 0.1, 10), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_hb_set_continuation(hb, 0.2, 1e-6, 0.1, 10), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_set_continuation(hb, 0.01, 0.0, 0.1, 10), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_set_continuation(hb, 0.01, 1e-6, 2.0, 10), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_set_continuation(hb, 0.01, 1e-6, 0.1, 1), FRICREG_EINVAL);
    /* K = 0 (the default) is singular: the static term */
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 2, 3, s.J, s.kt, s.mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, 3, s.pc, s.ps), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.0, nq, NULL, q), FRICREG_ESINGULAR);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "K is singular"));
    /* an undamped structure at its own natural frequency (elements removed): D_1 singular */
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 3, (double[9]){2, 0, 0, 0, 2, 0, 0, 0, 2}),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(hb, sqrt(2.0), nq, NULL, q), FRICREG_ESINGULAR);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 3, s.M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 3, s.K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, 3, s.C), FRICREG_OK);
    /* overflow: D_1 at Omega = 1e300, the solves with an excitation of 1e308 */
    ck_assert_int_eq(fricreg_hb_solve(hb, 1e300, nq, NULL, q), FRICREG_ENONFINITE);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "overflows"));
    const double huge[3] = {1e308, 0.0, 0.0};
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, 3, huge, s.ps), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.0, nq, NULL, q), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, 3, s.pc, s.ps), FRICREG_OK);
    /* solve's own arguments */
    ck_assert_int_eq(fricreg_hb_solve(NULL, 1.0, nq, NULL, q), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.0, nq, NULL, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_solve(hb, 0.0, nq, NULL, q), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_solve(hb, NAN, nq, NULL, q), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.0, nq - 1, NULL, q), FRICREG_ESIZE);
    double q0[14] = {0};
    q0[3] = INFINITY;
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.0, nq, q0, q), FRICREG_ENONFINITE);
    /* Newton with one iteration cannot reach a slipping solution from the stuck response (a
     * zero guess's first step): nor, then, from the guesses the level's continuation falls
     * back on */
    ck_assert_int_eq(fricreg_hb_set_newton(hb, 1e-10, 1), FRICREG_OK);
    double zero[14] = {0};
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.05, nq, zero, q), FRICREG_EWORK);
    for (int i = 0; i < 14; i++)
        ck_assert_double_eq(q[i], SENTINEL);
    ck_assert_int_eq(fricreg_hb_displacement(hb, 3, 7, x), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_set_newton(hb, 1e-10, 50), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.05, nq, NULL, q), FRICREG_OK);
    /* kept: the last failed call's (displacement's above), not the stuck guess's in this one */
    ck_assert_int_eq(fricreg_hb_errcode(hb), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "displacement: no solution"));
    /* the displacement's arguments */
    ck_assert_int_eq(fricreg_hb_displacement(NULL, 3, 7, x), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_displacement(hb, 3, 7, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_displacement(hb, 2, 7, x), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_hb_displacement(hb, 3, 5, x), FRICREG_ESIZE);
    /* the continuation's */
    ck_assert_int_eq(fricreg_hb_continue(NULL, 0.5, 1.5, nq, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_continue(hb, 0.5, 0.5, nq, NULL), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_continue(hb, 0.5, -1.0, nq, NULL), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_continue(hb, 0.5, INFINITY, nq, NULL), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_hb_continue(hb, 0.5, 1.5, nq + 1, NULL), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_hb_set_continuation(hb, 0.01, 1e-6, 0.01, 3), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_continue(hb, 0.5, 1.5, nq, NULL), FRICREG_EWORK);
    ck_assert_uint_eq(fricreg_hb_points(hb), 3);
    ck_assert_int_eq(fricreg_hb_displacement(hb, 3, 7, x), FRICREG_OK);
    /* a corrector allowed one iteration never converges (the stuck start does, being linear
     * in q): the step halves below ds_min */
    struct jenkins_model lin = jenkins_model_chain();
    lin.mun[0] = lin.mun[1] = 1e6;
    fricreg_hb *hl = make(&lin, 3, 1);
    ck_assert_int_eq(fricreg_hb_set_newton(hl, 1e-10, 1), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_continuation(hl, 0.5, 0.5, 0.5, 100), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_continue(hl, 0.5, 1.5, nq, NULL), FRICREG_EINTEGRATOR);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hl), "ds_min"));
    ck_assert_uint_eq(fricreg_hb_points(hl), 1);
    fricreg_hb_free(hl);
    /* the points' getter */
    double r[3] = {SENTINEL, SENTINEL, SENTINEL};
    om = SENTINEL;
    ck_assert_int_eq(fricreg_hb_point(NULL, 0, &om, 3, r), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_point(hb, 0, NULL, 3, r), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_point(hb, 0, &om, 3, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_point(hb, 3, &om, 3, r), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_point(hb, 0, &om, 2, r), FRICREG_ESIZE);
    ck_assert_double_eq(om, SENTINEL);
    ck_assert_double_eq(r[0], SENTINEL);
    ck_assert_int_eq(fricreg_hb_point(hb, 0, &om, 3, r), FRICREG_OK);
    ck_assert_double_eq(om, 0.5);
    fricreg_hb_free(hb);
}
END_TEST

/* No fixed bound on the elements: 300 Jenkins elements on one dof (kt 0.0517, slip force
 * 0.00731 each) act as one element of 300 times their stiffness and slip force (elements in
 * parallel on one displacement: their forces add, each the same function of it), so the
 * oscillator (m 1, k 2.385, c 0.031, 1.7 cos Ωt at Ω = 1.3, every element slipping) answers
 * as with that one element, to the solves' rounding (1e-9 relative). A driver whose buffers
 * size_t cannot count is refused with FRICREG_ENOMEM. */
START_TEST(many_elements)
{
    enum { MANY = 300, HM = 3, NCM = 2 * HM + 1 };
    const fricreg_element_type *jenkins = fricreg_element_lookup("jenkins");
    double M = 1.0, K = 2.385, C = 0.031, pc = 1.7, ps = 0.0, x[2][NCM];
    double *J = malloc(MANY * sizeof(double)), *p = malloc(2 * MANY * sizeof(double));
    double *q = malloc(MANY * NCM * sizeof(double));
    ck_assert(J != NULL && p != NULL && q != NULL);
    for (size_t e = 0; e < MANY; e++) {
        J[e] = 1.0;
        p[2 * e] = 0.0517;
        p[2 * e + 1] = 0.00731;
    }
    double one[2] = {MANY * 0.0517, MANY * 0.00731};
    for (int model = 0; model < 2; model++) {
        size_t m = model == 0 ? MANY : 1;
        fricreg_hb *hb = NULL;
        ck_assert_int_eq(fricreg_hb_create(1, m, HM, &hb), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_set_mass(hb, 1, &M), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 1, &K), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_set_damping(hb, 1, &C), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_set_excitation(hb, 1, &pc, &ps), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_add_elements(hb, jenkins, m, 1, J, model == 0 ? p : one),
                         FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_solve(hb, 1.3, m * NCM, NULL, q), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_displacement(hb, 1, NCM, x[model]), FRICREG_OK);
        fricreg_hb_free(hb);
    }
    ck_assert_double_gt(fabs(x[1][1]), 0.1);
    for (int c = 0; c < NCM; c++)
        ck_assert_double_eq_tol(x[0][c], x[1][c], 1e-9 * fabs(x[1][1]));
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(3, SIZE_MAX / 2, 3, &hb), FRICREG_ENOMEM);
    ck_assert_ptr_null(hb);
    free(J);
    free(p);
    free(q);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("hb");
    TCase *tc = tcase_create("hb");
    tcase_add_test(tc, linear_stuck_closed_form);
    tcase_add_test(tc, harmonics_converge);
    tcase_add_test(tc, stiffness_set_again);
    tcase_add_test(tc, bad_input);
    suite_add_tcase(s, tc);
    /* 300 elements: a dense Newton matrix of order 2101 (half a second native, minutes under
     * valgrind on the reference BLAS): native and ASan (tests/CMakeLists.txt); the driver's
     * paths it takes run under valgrind in the cases above at a smaller size. */
    TCase *tm = tcase_create("many");
    tcase_add_test(tm, many_elements);
    suite_add_tcase(s, tm);
    /* The chain's branch over its resonance (2 s): the release tier's (hb_release); the quick
     * tier continues branches and locates their peaks in test_hb_continuation and
     * test_hb_nma_peaks. */
    TCase *tr = tcase_create("resonance");
    tcase_set_tags(tr, "release");
    tcase_add_test(tr, continuation_over_resonance);
    suite_add_tcase(s, tr);
    /* The Newmark references, 10^5 steps a frequency: native and ASan (tests/CMakeLists.txt);
     * 2 s, the release tier's (hb_release) */
    TCase *td = tcase_create("time_domain");
    tcase_set_tags(td, "release");
    tcase_add_test(td, oscillator_against_time_domain);
    tcase_add_test(td, chain_against_time_domain);
    suite_add_tcase(s, td);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
