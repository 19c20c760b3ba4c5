/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_liftoff.c — Check suite for Jenkins elements under a normal load with lift-off in the
 * harmonic-balance driver (fricreg_hb_set_normal_elements, fricreg_hb.h).
 *
 * Where the numbers come from:
 *   - kn = 0: N = N0 whatever g, so the element is fricreg_hb_set_elements's with mun = mu N0
 *     (fricreg_aft.h: fricreg_aft_jenkins_normal_exact is fricreg_aft_jenkins_exact there),
 *     and the constant N0 adds the static load −Jn^T N0 only: the displacements differ by
 *     −K^-1 Jn^T N0 in the mean (GSL's LU here) and agree on every harmonic, to 1e-12.
 *   - closed and stuck (mu huge, N0 large enough that N0 + kn g > 0 throughout): the element is
 *     the spring kt on u's harmonics (the centred stick) and the spring kn on g with the
 *     preload, so the response is linear: (K + kn Jn^T Jn) x0 = −Jn^T N0 and
 *     (K + kt Jt^T Jt + kn Jn^T Jn − Ω² M + i Ω C) X_1 = p_c − i p_s, 0 on the other harmonics;
 *     GSL's complex LU. To 1e-10 of the response.
 *   - partial lift-off: the steady state in time by the hand-written average-acceleration
 *     Newmark of tests/support/jenkins_newmark.h with fricreg_jenkins_trial_normal (1024 steps
 *     a period, from rest until the RMS of the last two periods agree to 1e-7, asserted), at
 *     two frequencies where the element opens and closes in every period (asserted on the time
 *     series: the separation wipes out the slider's memory, so the periodic state is unique).
 *     HB at H = 21 within 1e-3 relative in each dof's RMS.
 *   - the sparse model (KLU) against the dense one (GSL's LU), to 1e-12. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_linalg.h>

#include "fricreg_hb.h"
#include "jenkins_newmark.h"

#define SENTINEL (-777.125)
#define MAXN JENKINS_MODEL_MAXN

/* Two masses on coupled springs: dof 0 slides along the contact (u = x_0), dof 1 presses
 * into it (g = −x_1: the normal force pushes x_1 up, and x_1 > N0/kn opens the contact). */
static struct jenkins_model contact(void)
{
    struct jenkins_model s = {.n = 2, .m = 1, .normal = 1};
    s.M[0] = 1.3, s.M[3] = 0.9;
    s.K[0] = 2.385, s.K[1] = s.K[2] = -0.3, s.K[3] = 1.5;
    s.C[0] = 0.12, s.C[3] = 0.1;
    s.J[0] = 1.0;
    s.Jn[1] = -1.0;
    s.kt[0] = 1.7;
    s.mu[0] = 0.5, s.n0[0] = 0.6, s.kn[0] = 3.0;
    s.mun[0] = s.mu[0] * s.n0[0];
    s.pc[0] = 0.6, s.pc[1] = 0.9;
    s.ps[1] = 0.2;
    return s;
}

static fricreg_hb *make(const struct jenkins_model *s, int H, int normal)
{
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(s->n, s->m, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, s->n, s->M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, s->n, s->K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, s->n, s->C), FRICREG_OK);
    if (normal)
        ck_assert_int_eq(fricreg_hb_set_normal_elements(hb, s->m, s->n, s->J, s->Jn, s->kt, s->mu,
                                                        s->n0, s->kn),
                         FRICREG_OK);
    else
        ck_assert_int_eq(fricreg_hb_set_elements(hb, s->m, s->n, s->J, s->kt, s->mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, s->n, s->pc, s->ps), FRICREG_OK);
    return hb;
}

/* HB's displacement coefficients x[n nc] and q[rows nc] at Omega. */
static void hb_solve(fricreg_hb *hb, const struct jenkins_model *s, int H, size_t rows,
                     double omega, double *q, double *x)
{
    size_t nc = 2 * (size_t)H + 1;
    ck_assert_int_eq(fricreg_hb_solve(hb, omega, rows * nc, NULL, q), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_displacement(hb, s->n, nc, x), FRICREG_OK);
}

/* sol[n] = A^-1 b for a real A[n n] (GSL's LU). */
static void real_solve(size_t n, const double *A, const double *b, double *sol)
{
    double a[MAXN * MAXN], r[MAXN];
    memcpy(a, A, n * n * sizeof *a);
    memcpy(r, b, n * sizeof *r);
    gsl_matrix_view Av = gsl_matrix_view_array(a, n, n);
    gsl_vector_view bv = gsl_vector_view_array(r, n), xv = gsl_vector_view_array(sol, n);
    gsl_permutation *p = gsl_permutation_alloc(n);
    int sg;
    gsl_linalg_LU_decomp(&Av.matrix, p, &sg);
    gsl_linalg_LU_solve(&Av.matrix, p, &bv.vector, &xv.vector);
    gsl_permutation_free(p);
}

START_TEST(constant_normal_load_is_jenkins)
{
    struct jenkins_model s = contact();
    s.kn[0] = 0.0;
    const int H = 7;
    size_t n = s.n, nc = 2 * (size_t)H + 1;
    fricreg_hb *hn = make(&s, H, 1), *hj = make(&s, H, 0);
    ck_assert_int_eq(fricreg_hb_set_newton(hn, 1e-13, 50), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_newton(hj, 1e-13, 50), FRICREG_OK);
    /* the static load of the preload: dx0 = −K^-1 Jn^T N0 */
    double load[MAXN], dx0[MAXN];
    for (size_t k = 0; k < n; k++)
        load[k] = -s.Jn[k] * s.n0[0];
    real_solve(n, s.K, load, dx0);
    const double omegas[3] = {0.9, 1.35, 1.8};
    for (int w = 0; w < 3; w++) {
        double qn[2 * 15], xn[MAXN * 15], qj[15], xj[MAXN * 15], amax = 0.0, dev = 0.0;
        hb_solve(hn, &s, H, 2, omegas[w], qn, xn);
        hb_solve(hj, &s, H, 1, omegas[w], qj, xj);
        for (size_t j = 0; j < n * nc; j++)
            amax = fmax(amax, fabs(xj[j]));
        ck_assert_double_gt(amax, 0.1);
        for (size_t k = 0; k < n; k++)
            for (size_t c = 0; c < nc; c++) {
                double want = xj[k * nc + c] + (c == 0 ? dx0[k] : 0.0);
                dev = fmax(dev, fabs(xn[k * nc + c] - want) / amax);
                ck_assert_msg(fabs(xn[k * nc + c] - want) <= 1e-12 * amax,
                              "Omega %g dof %zu coefficient %zu: %.17g against %.17g", omegas[w], k,
                              c, xn[k * nc + c], want);
            }
        if (getenv("HB_PRINT"))
            fprintf(stderr, "kn = 0, Omega %g: %.2e of the scale %.3g\n", omegas[w], dev, amax);
        /* the unknowns: u as q of the Jenkins driver but for the mean, g = Jn x */
        for (size_t c = 0; c < nc; c++) {
            double gx = 0.0;
            for (size_t k = 0; k < n; k++)
                gx += s.Jn[k] * xn[k * nc + c];
            ck_assert_double_eq_tol(qn[nc + c], gx, 1e-12 * amax);
            if (c > 0)
                ck_assert_double_eq_tol(qn[c], qj[c], 1e-12 * amax);
        }
    }
    /* back to one row per element on the same driver: the Jenkins driver's solution, nq too */
    double q[2 * 15], x[MAXN * 15], qj[15], xj[MAXN * 15];
    ck_assert_int_eq(fricreg_hb_set_elements(hn, 1, n, s.J, s.kt, s.mun), FRICREG_OK);
    for (int i = 0; i < 30; i++)
        q[i] = SENTINEL;
    ck_assert_int_eq(fricreg_hb_solve(hn, 1.35, 2 * nc, NULL, q), FRICREG_ESIZE);
    ck_assert_double_eq(q[0], SENTINEL);
    hb_solve(hn, &s, H, 1, 1.35, q, x);
    hb_solve(hj, &s, H, 1, 1.35, qj, xj);
    for (size_t j = 0; j < nc; j++)
        ck_assert_double_eq(q[j], qj[j]);
    for (size_t j = 0; j < n * nc; j++)
        ck_assert_double_eq(x[j], xj[j]);
    fricreg_hb_free(hn);
    fricreg_hb_free(hj);
}
END_TEST

START_TEST(closed_stuck_is_linear)
{
    struct jenkins_model s = contact();
    s.mu[0] = 1e6, s.n0[0] = 50.0;
    size_t n = s.n;
    /* the static part: (K + kn Jn^T Jn) x0 = −Jn^T N0; the closed contact must hold */
    double Ks[MAXN * MAXN], load[MAXN], x0[MAXN];
    for (size_t i = 0; i < n; i++) {
        load[i] = -s.Jn[i] * s.n0[0];
        for (size_t k = 0; k < n; k++)
            Ks[i * n + k] = s.K[i * n + k] + s.kn[0] * s.Jn[i] * s.Jn[k];
    }
    real_solve(n, Ks, load, x0);
    const int Hs[2] = {1, 4};
    for (int t = 0; t < 2; t++) {
        int H = Hs[t];
        size_t nc = 2 * (size_t)H + 1;
        fricreg_hb *hb = make(&s, H, 1);
        const double omegas[3] = {0.7385, 1.61, 2.9};
        for (int w = 0; w < 3; w++) {
            double om = omegas[w], D[2 * MAXN * MAXN], b[2 * MAXN], X[2 * MAXN];
            for (size_t i = 0; i < n; i++) {
                b[2 * i] = s.pc[i], b[2 * i + 1] = -s.ps[i];
                for (size_t k = 0; k < n; k++) {
                    D[2 * (i * n + k)] = Ks[i * n + k] + s.kt[0] * s.J[i] * s.J[k] -
                                         om * om * s.M[i * n + k];
                    D[2 * (i * n + k) + 1] = om * s.C[i * n + k];
                }
            }
            gsl_matrix_complex_view Dv = gsl_matrix_complex_view_array(D, n, n);
            gsl_vector_complex_view bv = gsl_vector_complex_view_array(b, n);
            gsl_vector_complex_view Xv = gsl_vector_complex_view_array(X, n);
            gsl_permutation *p = gsl_permutation_alloc(n);
            int sg;
            gsl_linalg_complex_LU_decomp(&Dv.matrix, p, &sg);
            gsl_linalg_complex_LU_solve(&Dv.matrix, p, &bv.vector, &Xv.vector);
            gsl_permutation_free(p);
            /* the mean and the harmonics each to 1e-10 of their own scale */
            double q[2 * 9], x[MAXN * 9], a0 = 0.0, a1 = 0.0, dev = 0.0;
            hb_solve(hb, &s, H, 2, om, q, x);
            for (size_t k = 0; k < n; k++)
                a0 = fmax(a0, fabs(x0[k])), a1 = fmax(a1, hypot(X[2 * k], X[2 * k + 1]));
            for (size_t k = 0; k < n; k++)
                for (size_t c = 0; c < nc; c++) {
                    /* X = a − i b */
                    double want = c == 0 ? x0[k] : c == 1 ? X[2 * k] : c == 2 ? -X[2 * k + 1] : 0;
                    double amax = c == 0 ? a0 : a1;
                    dev = fmax(dev, fabs(x[k * nc + c] - want) / amax);
                    ck_assert_msg(fabs(x[k * nc + c] - want) <= 1e-10 * amax,
                                  "H %d Omega %g dof %zu coefficient %zu: %.17g against %.17g", H,
                                  om, k, c, x[k * nc + c], want);
                }
            if (getenv("HB_PRINT"))
                fprintf(stderr, "closed stuck, H %d Omega %g: %.2e of the scales %.3g, %.3g\n", H,
                        om, dev, a0, a1);
            /* closed throughout: N0 + kn g > 0 with g's amplitude bound */
            double gmin = q[nc];
            for (size_t c = 1; c < nc; c++)
                gmin -= fabs(q[nc + c]);
            ck_assert_double_gt(s.n0[0] + s.kn[0] * gmin, 0.0);
        }
        fricreg_hb_free(hb);
    }
}
END_TEST

START_TEST(partial_liftoff_against_time_domain)
{
    struct jenkins_model s = contact();
    const int H = 21;
    size_t nc = 2 * (size_t)H + 1;
    fricreg_hb *hb = make(&s, H, 1);
    const double omegas[2] = {1.1, 1.45};
    for (int w = 0; w < 2; w++) {
        double rms[MAXN], prev[MAXN], ref[MAXN], q[2 * 43], x[MAXN * 43];
        int flips = jenkins_newmark_rms(&s, omegas[w], 1024, 100, ref, prev, NULL);
        ck_assert_msg(flips, "Omega = %g: the contact does not open and close in the reference",
                      omegas[w]);
        hb_solve(hb, &s, H, 2, omegas[w], q, x);
        for (size_t k = 0; k < s.n; k++) {
            double r = x[k * nc] * x[k * nc];
            for (size_t c = 1; c < nc; c++)
                r += 0.5 * x[k * nc + c] * x[k * nc + c];
            rms[k] = sqrt(r);
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
END_TEST

/* The sparse model (KLU, fricreg_hb_set_*_csc) gives the dense model's solution with
 * lift-off too: its solves take the 2 m columns of J^T. K given whole (both triangles). */
START_TEST(sparse_model_equals_dense)
{
    struct jenkins_model s = contact();
    const int H = 7;
    size_t nc = 2 * (size_t)H + 1;
    fricreg_hb *hd = make(&s, H, 1), *hs = make(&s, H, 1);
    const int64_t p[3] = {0, 2, 4}, i[4] = {0, 1, 0, 1};
    ck_assert_int_eq(fricreg_hb_set_stiffness_csc(hs, 2, 0, p, i, s.K), FRICREG_OK);
    double qd[2 * 15], xd[MAXN * 15], qs[2 * 15], xs[MAXN * 15], amax = 0.0;
    hb_solve(hd, &s, H, 2, 1.45, qd, xd);
    hb_solve(hs, &s, H, 2, 1.45, qs, xs);
    for (size_t j = 0; j < 2 * nc; j++)
        amax = fmax(amax, fabs(qd[j]));
    for (size_t j = 0; j < 2 * nc; j++)
        ck_assert_double_eq_tol(qs[j], qd[j], 1e-12 * amax);
    for (size_t j = 0; j < s.n * nc; j++)
        ck_assert_double_eq_tol(xs[j], xd[j], 1e-12 * amax);
    fricreg_hb_free(hd);
    fricreg_hb_free(hs);
}
END_TEST

START_TEST(bad_input)
{
    struct jenkins_model s = contact();
    fricreg_hb *hb = make(&s, 2, 0);
    double q[10], Jz[2] = {0.0, 0.0}, Jnan[2] = {NAN, 0.0}, neg[1] = {-1.0}, inf[1] = {INFINITY};
    const double *J = s.J, *Jn = s.Jn, *kt = s.kt, *mu = s.mu, *n0 = s.n0, *kn = s.kn;
    ck_assert_int_eq(fricreg_hb_set_normal_elements(NULL, 1, 2, J, Jn, kt, mu, n0, kn),
                     FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_set_normal_elements(hb, 1, 2, J, NULL, kt, mu, n0, kn),
                     FRICREG_ENULL);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "Jn is NULL"));
    ck_assert_int_eq(fricreg_hb_set_normal_elements(hb, 1, 2, J, Jn, kt, mu, n0, NULL),
                     FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_set_normal_elements(hb, 2, 2, J, Jn, kt, mu, n0, kn),
                     FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_hb_set_normal_elements(hb, 1, 3, J, Jn, kt, mu, n0, kn),
                     FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_hb_set_normal_elements(hb, 1, 2, J, Jz, kt, mu, n0, kn),
                     FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "row 0 of Jn is zero"));
    ck_assert_int_eq(fricreg_hb_set_normal_elements(hb, 1, 2, Jnan, Jn, kt, mu, n0, kn),
                     FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_hb_set_normal_elements(hb, 1, 2, J, Jn, neg, mu, n0, kn),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_set_normal_elements(hb, 1, 2, J, Jn, kt, neg, n0, kn),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_set_normal_elements(hb, 1, 2, J, Jn, kt, mu, n0, neg),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_set_normal_elements(hb, 1, 2, J, Jn, kt, mu, inf, kn),
                     FRICREG_ENONFINITE);
    /* nothing changed: the Jenkins driver's nq still holds */
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.2, 5, NULL, q), FRICREG_OK);
    /* a negative preload is a gap: accepted; then nq is 2 m (2H + 1) */
    ck_assert_int_eq(fricreg_hb_set_normal_elements(hb, 1, 2, J, Jn, kt, mu, neg, kn), FRICREG_OK);
    for (int i = 0; i < 10; i++)
        q[i] = SENTINEL;
    ck_assert_int_eq(fricreg_hb_displacement(hb, 2, 5, (double[10]){0}), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.2, 5, NULL, q), FRICREG_ESIZE);
    ck_assert_double_eq(q[0], SENTINEL);
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.2, 10, NULL, q), FRICREG_OK);
    fricreg_hb_free(hb);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("hb_liftoff");
    TCase *tc = tcase_create("hb_liftoff");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, constant_normal_load_is_jenkins);
    tcase_add_test(tc, closed_stuck_is_linear);
    tcase_add_test(tc, partial_liftoff_against_time_domain);
    tcase_add_test(tc, sparse_model_equals_dense);
    tcase_add_test(tc, bad_input);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
