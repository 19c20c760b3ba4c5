/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_liftoff.c — Check suite for Jenkins and Iwan elements under a normal load with
 * lift-off in the harmonic-balance driver (fricreg_hb_set_normal_elements,
 * fricreg_hb_set_iwan_normal, fricreg_hb.h).
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
 *   - the sparse model (KLU) against the dense one (GSL's LU), to 1e-12.
 *   - Iwan elements: one slider is the Jenkins element bit for bit, four equal sliders it to
 *     1e-12; three sliders against fricreg_structure_set_iwan_normal's Newmark (1024 steps a
 *     period, 100 periods from rest, steady to 1e-7 asserted, lift-off and each slider's slip
 *     in the last period asserted) within 1e-3 relative in each dof's RMS at H = 21.
 *   - a branch through the frequency where the centred stick breaks above the stuck sliders
 *     (an 8-dof chain, the element on two dofs of its middle, H = 3): it reaches Ω1 with the
 *     defaults (until 1.10 the stuck state jumped there and the step fell below ds_min at
 *     Ω = 1.02; fricreg_aft.h). */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_linalg.h>

#include "fricreg_hb.h"
#include "fricreg_structure.h"
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

/* HB's RMS of each dof (from its coefficients x[n (2H + 1)]) within 1e-3 of the time domain's
 * steady ref[n], which must agree with the period before, prev[n], to 1e-7. */
static void agrees_with_time_domain(const char *label, const struct jenkins_model *s, int H,
                                    double omega, const double *x, const double *ref,
                                    const double *prev)
{
    size_t nc = 2 * (size_t)H + 1;
    for (size_t k = 0; k < s->n; k++) {
        double r = x[k * nc] * x[k * nc];
        for (size_t c = 1; c < nc; c++)
            r += 0.5 * x[k * nc + c] * x[k * nc + c];
        double rms = sqrt(r);
        if (getenv("HB_PRINT"))
            fprintf(stderr, "%sOmega %g dof %zu: HB %.9g Newmark %.9g rel %.2e steady %.2e\n",
                    label, omega, k, rms, ref[k], fabs(rms / ref[k] - 1.0),
                    fabs(prev[k] / ref[k] - 1.0));
        ck_assert_msg(fabs(ref[k] - prev[k]) <= 1e-7 * ref[k],
                      "Omega = %g dof %zu: the reference is not steady (%.9g, %.9g)", omega, k,
                      prev[k], ref[k]);
        ck_assert_msg(fabs(rms - ref[k]) <= 1e-3 * ref[k],
                      "Omega = %g dof %zu: HB %.9g, Newmark %.9g", omega, k, rms, ref[k]);
    }
}

START_TEST(partial_liftoff_against_time_domain)
{
    struct jenkins_model s = contact();
    const int H = 21;
    size_t nc = 2 * (size_t)H + 1;
    fricreg_hb *hb = make(&s, H, 1);
    const double omegas[2] = {1.1, 1.45};
    for (int w = 0; w < 2; w++) {
        double prev[MAXN], ref[MAXN], q[2 * 43], x[MAXN * 43];
        int flips = jenkins_newmark_rms(&s, omegas[w], 1024, 100, ref, prev, NULL);
        ck_assert_msg(flips, "Omega = %g: the contact does not open and close in the reference",
                      omegas[w]);
        hb_solve(hb, &s, H, 2, omegas[w], q, x);
        agrees_with_time_domain("", &s, H, omegas[w], x, ref, prev);
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

/* Iwan elements with lift-off (fricreg_hb_set_iwan_normal) on contact()'s rows: three sliders
 * whose stiffnesses sum to its kt = 1.7 and friction coefficients to its mu = 0.5, slipping at
 * mu_s N0/k_s = 0.067, 0.18 and 0.5 under the preload. */
static const double IWAN_K[3] = {0.9, 0.5, 0.3}, IWAN_MU[3] = {0.1, 0.15, 0.25};

static fricreg_hb *make_iwan(const struct jenkins_model *s, int H, size_t ns, const double *k,
                             const double *mu)
{
    fricreg_hb *hb = make(s, H, 0);
    ck_assert_int_eq(fricreg_hb_set_iwan_normal(hb, s->m, s->n, s->J, s->Jn, ns, k, mu, s->n0,
                                                s->kn),
                     FRICREG_OK);
    return hb;
}

/* One slider is the Jenkins element with lift-off, bit for bit; four equal sliders (kt/4,
 * mu/4 each: each carries a quarter of the force and slips with it) are it to rounding. */
START_TEST(iwan_normal_is_jenkins_normal)
{
    struct jenkins_model s = contact();
    const int H = 9;
    size_t nc = 2 * (size_t)H + 1;
    double k4[4], mu4[4];
    for (int j = 0; j < 4; j++) {
        k4[j] = s.kt[0] / 4.0;
        mu4[j] = s.mu[0] / 4.0;
    }
    fricreg_hb *hj = make(&s, H, 1), *h1 = make_iwan(&s, H, 1, s.kt, s.mu),
               *h4 = make_iwan(&s, H, 4, k4, mu4);
    const double omegas[2] = {1.1, 1.45};
    for (int w = 0; w < 2; w++) {
        double qj[2 * 19], xj[MAXN * 19], q1[2 * 19], x1[MAXN * 19], q4[2 * 19], x4[MAXN * 19];
        double amax = 0.0;
        hb_solve(hj, &s, H, 2, omegas[w], qj, xj);
        hb_solve(h1, &s, H, 2, omegas[w], q1, x1);
        hb_solve(h4, &s, H, 2, omegas[w], q4, x4);
        ck_assert_mem_eq(q1, qj, 2 * nc * sizeof *qj);
        ck_assert_mem_eq(x1, xj, s.n * nc * sizeof *xj);
        for (size_t j = 0; j < 2 * nc; j++)
            amax = fmax(amax, fabs(qj[j]));
        for (size_t j = 0; j < 2 * nc; j++)
            ck_assert_msg(fabs(q4[j] - qj[j]) <= 1e-12 * amax, "Omega %g: q[%zu] %.17g, %.17g",
                          omegas[w], j, q4[j], qj[j]);
    }
    /* the truncation estimate's companion at 2H + 1 takes the sliders and their scratch */
    double ej[MAXN], e4[MAXN];
    ck_assert_int_eq(fricreg_hb_truncation_error(hj, FRICREG_HB_SOLUTION, s.n, ej, NULL),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_truncation_error(h4, FRICREG_HB_SOLUTION, s.n, e4, NULL),
                     FRICREG_OK);
    for (size_t k = 0; k < s.n; k++)
        ck_assert_double_eq_tol(e4[k], ej[k], 1e-9 * fmax(ej[0], ej[1]));
    fricreg_hb_free(hj);
    fricreg_hb_free(h1);
    fricreg_hb_free(h4);
}
END_TEST

/* The steady state in time: fricreg_structure_set_iwan_normal's Newmark (average acceleration,
 * 1024 steps a period, from rest for 100 periods; the element the standalone fricreg_iwan's
 * to 1e-10, test_structure_liftoff) under the load pc cos(Omega t): each dof's RMS over the
 * last period, the one before into prev, and whether the element opened and closed and every
 * slider slipped in the last period. */
static int iwan_newmark_rms(const struct jenkins_model *s, double omega, double *rms, double *prev)
{
    const int N = 1024, periods = 100, total = N * periods;
    const double dt = 6.283185307179586 / omega / N, zero = 0.0, J[2] = {1.0, 0.0};
    fricreg_structure *st = NULL;
    ck_assert_int_eq(fricreg_structure_create(s->n, 1, &st), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_mass(st, s->n, s->M), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_stiffness(st, s->n, s->K), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_damping(st, s->n, s->C), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_contacts(st, 1, s->n, J), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_bounds(st, 1, &zero), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_iwan_normal(st, 1, s->n, s->J, s->Jn, 3, IWAN_K, IWAN_MU,
                                                       s->n0, s->kn),
                     FRICREG_OK);
    double *g = malloc(((size_t)total + 1) * sizeof *g);
    ck_assert_ptr_nonnull(g);
    for (int k = 0; k <= total; k++)
        g[k] = cos(omega * k * dt);
    ck_assert_int_eq(fricreg_structure_set_load(st, s->n, s->pc, 0.0, dt, (size_t)total + 1, g),
                     FRICREG_OK);
    free(g);
    ck_assert_int_eq(fricreg_structure_set_newton(st, 1e-13, 50), FRICREG_OK);
    double sum[MAXN] = {0.0}, wmin[3], wmax[3];
    int open = 0, closed = 0;
    for (int k = 1; k <= total; k++) {
        double t0, x[MAXN], w[3], N0;
        ck_assert_int_eq(fricreg_structure_get_value(st, FRICREG_SVALUE_TIME, &t0), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_step(st, k * dt - t0), FRICREG_OK);
        if (k <= total - 2 * N)
            continue;
        fricreg_structure_get_state(st, s->n, x, NULL, NULL);
        fricreg_structure_get_iwan_state(st, 1, 3, NULL, w, NULL);
        fricreg_structure_get_normal_forces(st, 1, &N0);
        for (size_t i = 0; i < s->n; i++)
            sum[i] += x[i] * x[i];
        if (k == total - N) { /* the period before the last */
            for (size_t i = 0; i < s->n; i++) {
                prev[i] = sqrt(sum[i] / N);
                sum[i] = 0.0;
            }
            memcpy(wmin, w, sizeof wmin);
            memcpy(wmax, w, sizeof wmax);
        }
        for (int j = 0; j < 3 && k > total - N; j++) {
            wmin[j] = fmin(wmin[j], w[j]);
            wmax[j] = fmax(wmax[j], w[j]);
        }
        open += k > total - N && N0 == 0.0;
        closed += k > total - N && N0 > 0.0;
    }
    for (size_t i = 0; i < s->n; i++)
        rms[i] = sqrt(sum[i] / N);
    fricreg_structure_free(st);
    int slipped = 1;
    for (int j = 0; j < 3; j++)
        slipped &= wmax[j] - wmin[j] > 1e-3;
    return open > 0 && closed > 0 && slipped;
}

/* HB at H = 21 against the time domain, where the element opens and closes and each slider
 * slips in every period: within 1e-3 relative in each dof's RMS, as the Jenkins element's. */
/* The backbone of mode 0 (fricreg_hb_nma, modal damping) from stuck and closed through slip and
 * lift-off: one Iwan slider is the Jenkins element with lift-off, bit for bit; four equal
 * sliders are it to 1e-10. Up to a = 0.03 every element is stuck and closed (they slip from
 * a = 0.05 or so): omega is the linear mode's of K + kt e0 e0^T + kn e1 e1^T against M
 * (nma_stuck.c's stiffness of the rows: kt, the sliders' sum, and kn), the root of
 * det(K_0 − lambda M) = 0 in closed form, to 1e-12; beyond, omega never rises (the contact
 * softens). The march once jumped at a = 0.0146 to omega = 1.96 (a 16-point grid from 0.01),
 * its predictor scaling the normal row's mean, the preload's static deflection, with a. */
START_TEST(iwan_normal_backbone_is_jenkins_normal)
{
    struct jenkins_model s = contact();
    const int H = 9;
    const size_t np = 16;
    double k4[4], mu4[4];
    for (int j = 0; j < 4; j++) {
        k4[j] = s.kt[0] / 4.0;
        mu4[j] = s.mu[0] / 4.0;
    }
    fricreg_hb *hb[3] = {make(&s, H, 1), make_iwan(&s, H, 1, s.kt, s.mu),
                         make_iwan(&s, H, 4, k4, mu4)};
    for (int i = 0; i < 3; i++) {
        ck_assert_int_eq(fricreg_hb_nma(hb[i], 0, FRICREG_HB_NMA_DAMPING_MODAL, 0.01, 3.0, np),
                         FRICREG_OK);
        ck_assert_uint_eq(fricreg_hb_nma_points(hb[i]), np);
    }
    /* det(K_0 − lambda M) = a lambda^2 − b lambda + c, K_0 = K + diag(kt, kn), M diagonal */
    double k00 = s.K[0] + s.kt[0], k11 = s.K[3] + s.kn[0], qa = s.M[0] * s.M[3],
           qb = k00 * s.M[3] + k11 * s.M[0], qc = k00 * k11 - s.K[1] * s.K[2];
    double omega_stuck = sqrt((qb - sqrt(qb * qb - 4.0 * qa * qc)) / (2.0 * qa));
    double first = 0.0, last = 0.0;
    for (size_t k = 0; k < np; k++) {
        double a[3], w[3], z[3];
        for (int i = 0; i < 3; i++)
            ck_assert_int_eq(fricreg_hb_nma_point(hb[i], k, &a[i], &w[i], &z[i], 0, 0, NULL),
                             FRICREG_OK);
        if (getenv("HB_PRINT"))
            fprintf(stderr, "a %.6g omega %.9f zeta %.6g | a4 %.6g omega4 %.9f\n", a[0], w[0], z[0],
                    a[2], w[2]);
        ck_assert(a[1] == a[0] && w[1] == w[0] && z[1] == z[0]);
        ck_assert_double_le(fabs(w[2] - w[0]), 1e-10 * w[0]);
        ck_assert_double_le(fabs(z[2] - z[0]), 1e-10 * fmax(z[0], 1e-3));
        if (a[0] <= 0.03)
            ck_assert_double_le(fabs(w[0] - omega_stuck), 1e-12 * omega_stuck);
        if (k == 0)
            first = w[0];
        else
            ck_assert_double_le(w[0], last);
        last = w[0];
    }
    ck_assert_double_lt(last, 0.99 * first); /* it softened: the element slipped or opened */
    for (int i = 0; i < 3; i++)
        fricreg_hb_free(hb[i]);
}
END_TEST

START_TEST(iwan_partial_liftoff_against_time_domain)
{
    struct jenkins_model s = contact();
    s.ps[1] = 0.0; /* the structure's load is one vector times a time series */
    const int H = 21;
    size_t nc = 2 * (size_t)H + 1;
    fricreg_hb *hb = make_iwan(&s, H, 3, IWAN_K, IWAN_MU);
    const double omegas[2] = {1.2, 1.45}; /* at 1.1 the time series is not periodic */
    for (int w = 0; w < 2; w++) {
        double prev[MAXN], ref[MAXN], q[2 * 43], x[MAXN * 43];
        int flips = iwan_newmark_rms(&s, omegas[w], ref, prev);
        ck_assert_msg(flips,
                      "Omega = %g: the element does not open, close and slip on every "
                      "slider in the reference",
                      omegas[w]);
        hb_solve(hb, &s, H, 2, omegas[w], q, x);
        agrees_with_time_domain("Iwan, ", &s, H, omegas[w], x, ref, prev);
    }
    fricreg_hb_free(hb);
}
END_TEST

/* A chain to ground of 8 dofs, forced at its end and two dofs before, a Jenkins element with
 * lift-off on dofs 5 (tangential) and 6 (normal), kt 1.2, mu 0.3, kn 3, N0 0.6. */
START_TEST(branch_through_the_centred_sticks_end)
{
    enum { N = 8, NC = 7 };
    double M[N * N] = {0}, K[N * N] = {0}, C[N * N], pc[N] = {0}, ps[N] = {0};
    double Jt[N] = {0}, Jn[N] = {0}, kt = 1.2, mu = 0.3, n0 = 0.6, kn = 3.0;
    for (int i = 0; i < N; i++) {
        M[i * N + i] = 1.0 + 0.1 * i;
        K[i * N + i] += i + 1 < N ? 3.0 : 2.0;
        if (i > 0)
            K[i * N + i] += 1.0;
        if (i + 1 < N)
            K[i * N + i + 1] = K[(i + 1) * N + i] = -1.0;
    }
    for (int i = 0; i < N * N; i++)
        C[i] = 0.01 * M[i] + 0.01 * K[i];
    pc[N - 1] = 0.3;
    ps[3] = 0.15;
    pc[4] = 0.09;
    Jt[5] = Jn[6] = 1.0;
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(N, 1, 3, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, N, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, N, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, N, C), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, N, pc, ps), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_normal_elements(hb, 1, N, Jt, Jn, &kt, &mu, &n0, &kn),
                     FRICREG_OK);
    ck_assert_msg(fricreg_hb_continue(hb, 0.3, 2.5, 2 * NC, NULL) == FRICREG_OK, "%s",
                  fricreg_hb_errmsg(hb));
    double w, rms[N];
    ck_assert_int_eq(fricreg_hb_point(hb, fricreg_hb_points(hb) - 1, &w, N, rms), FRICREG_OK);
    ck_assert_double_eq(w, 2.5);
    fricreg_hb_free(hb);
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
    /* Iwan elements: no slider, a negative mu, a NULL k; the lift-off elements kept */
    const double k2[2] = {1.0, 0.5}, mu2[2] = {0.2, -0.1};
    ck_assert_int_eq(fricreg_hb_set_iwan_normal(hb, 1, 2, J, Jn, 0, k2, mu2, n0, kn),
                     FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "ns = 0"));
    ck_assert_int_eq(fricreg_hb_set_iwan_normal(hb, 1, 2, J, Jn, 2, k2, mu2, n0, kn),
                     FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "mu[1]"));
    ck_assert_int_eq(fricreg_hb_set_iwan_normal(hb, 1, 2, J, Jn, 2, NULL, mu2, n0, kn),
                     FRICREG_ENULL);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "k is NULL"));
    ck_assert_int_eq(fricreg_hb_set_iwan_normal(hb, 1, 2, J, Jn, 2, k2, k2, n0, neg),
                     FRICREG_EINVAL);
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
    tcase_add_test(tc, iwan_normal_is_jenkins_normal);
    tcase_add_test(tc, iwan_normal_backbone_is_jenkins_normal);
    tcase_add_test(tc, branch_through_the_centred_sticks_end);
    tcase_add_test(tc, bad_input);
    suite_add_tcase(s, tc);
    /* the Iwan element's lift-off against Newmark (2 s): the release tier's (hb_liftoff_release);
     * the quick tier's partial_liftoff_against_time_domain is the Jenkins element's */
    TCase *td = tcase_create("time_domain");
    tcase_set_timeout(td, 60);
    tcase_set_tags(td, "release");
    tcase_add_test(td, iwan_partial_liftoff_against_time_domain);
    suite_add_tcase(s, td);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
