/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_contact_3d.c — Check suite for the 3-D contact element in the harmonic-balance driver
 * (fricreg_hb_set_jenkins_2d_normal, fricreg_hb.h).
 *
 * Where the numbers come from:
 *   - on one tangential axis with a constant normal force the element is the lift-off Jenkins
 *     element of fricreg_hb_set_jenkins_normal, whose AFT is exact: the responses agree to the
 *     sampled AFT's error on a line, O(N^-2) (asserted (2 pi/N)^2 = 4e-5 of the RMS at
 *     N = 1024; measured 2e-7 … 1.3e-5);
 *   - closed and stuck (N0 large, mu large): the element is the springs kt, kt, kn on its
 *     rows with the preload, a linear response (GSL's complex LU), to 1e-10;
 *   - a 2-dof mass sliding in the plane on an inclined contact (the normal row couples x and
 *     y), at Omega = 1 closed and slipping along a curved path, at 1.35 lifting off in every
 *     period (both asserted on the time series):
 *     the steady state of fricreg_structure_set_jenkins_2d_normal under Newmark (average
 *     acceleration, 100 periods from HB's state, steady to 1e-7 asserted: the state is unique),
 *     at 2048 and 4096 steps a period, extrapolated to dt -> 0 as the radial return's first
 *     order allows. HB at H = 15 agrees within its own truncation estimate
 *     (fricreg_hb_truncation_error) plus the reference's last refinement (measured: 3e-6 of
 *     the RMS and below), and Hill's method calls it stable (the march settles on it);
 *   - the backbone of the nonlinear mode starts at the stuck linear mode (closed form, 1e-12)
 *     and softens;
 *   - a continuation through the lift-off with Hill's stability passes the point solves. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_complex.h>
#include <gsl/gsl_complex_math.h>
#include <gsl/gsl_linalg.h>

#include "fricreg_hb.h"
#include "fricreg_structure.h"

#define N 2 /* dofs */
#define SENTINEL (-777.125)

/* A mass m_x, m_y moving in the plane on springs K, a 3-D contact on x and y with the normal
 * g = jn . x, forced by p cos(Omega t). */
struct plane {
    double M[N * N], K[N * N], C[N * N];
    double Je[2 * N], Jn[N];
    double kt, mu, n0, kn;
    double p[N];
};

static struct plane inclined(void)
{
    struct plane s = {.M = {1.0, 0.0, 0.0, 1.2},
                      .K = {2.0, -0.3, -0.3, 1.5},
                      .C = {0.06, 0.0, 0.0, 0.05},
                      .Je = {1.0, 0.0, 0.0, 1.0},
                      .Jn = {0.4, -0.3},
                      .kt = 1.5,
                      .mu = 0.4,
                      .n0 = 0.5,
                      .kn = 2.0,
                      .p = {0.6, 0.4}};
    return s;
}

static fricreg_hb *make(const struct plane *s, int H)
{
    fricreg_hb *hb = NULL;
    const double zero[N] = {0.0};
    ck_assert_int_eq(fricreg_hb_create(N, 1, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, N, s->M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, N, s->K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, N, s->C), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_jenkins_2d_normal(hb, 1, N, s->Je, s->Jn, &s->kt, &s->mu,
                                                      &s->n0, &s->kn),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, N, s->p, zero), FRICREG_OK);
    return hb;
}

static double rms_of(const double *x, size_t nc)
{
    double r = x[0] * x[0];
    for (size_t c = 1; c < nc; c++)
        r += 0.5 * x[c] * x[c];
    return sqrt(r);
}

/* What the element did in the last period of a march. */
struct last_period {
    int opened, closed; /* samples with N = 0, N > 0 */
    double slid[2];     /* the slider's range on x and on y */
};

/* The steady state in time at steps a period from the state x0, v0: each dof's RMS over the
 * last of 100 periods, the period before into prev, and what the element did in the last
 * period. */
static struct last_period newmark_rms(const struct plane *s, double omega, int steps,
                                      const double *x0, const double *v0, double *rms, double *prev)
{
    const int periods = 100, total = steps * periods;
    const double dt = 6.283185307179586 / omega / steps, zero = 0.0, J[N] = {1.0, 0.0};
    fricreg_structure *st = NULL;
    ck_assert_int_eq(fricreg_structure_create(N, 1, &st), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_mass(st, N, s->M), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_stiffness(st, N, s->K), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_damping(st, N, s->C), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_contacts(st, 1, N, J), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_bounds(st, 1, &zero), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_jenkins_2d_normal(st, 1, N, s->Je, s->Jn, &s->kt, &s->mu,
                                                             &s->n0, &s->kn),
                     FRICREG_OK);
    double *g = malloc(((size_t)total + 1) * sizeof *g);
    ck_assert_ptr_nonnull(g);
    for (int k = 0; k <= total; k++)
        g[k] = cos(omega * k * dt);
    ck_assert_int_eq(fricreg_structure_set_load(st, N, s->p, 0.0, dt, (size_t)total + 1, g),
                     FRICREG_OK);
    free(g);
    ck_assert_int_eq(fricreg_structure_set_newton(st, 1e-13, 50), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_initial(st, N, x0, v0), FRICREG_OK);
    double sum[N] = {0.0}, lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    struct last_period last = {0};
    for (int k = 1; k <= total; k++) {
        double t0, x[N], nf, f[2], w[2];
        ck_assert_int_eq(fricreg_structure_get_value(st, FRICREG_SVALUE_TIME, &t0), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_step(st, k * dt - t0), FRICREG_OK);
        if (k <= total - 2 * steps)
            continue;
        fricreg_structure_get_state(st, N, x, NULL, NULL);
        fricreg_structure_get_normal_forces(st, 1, &nf);
        fricreg_structure_get_jenkins_2d_state(st, 1, f, w, NULL);
        for (size_t i = 0; i < N; i++)
            sum[i] += x[i] * x[i];
        if (k == total - steps)
            for (size_t i = 0; i < N; i++) {
                prev[i] = sqrt(sum[i] / steps);
                sum[i] = 0.0;
            }
        if (k <= total - steps)
            continue;
        last.opened += nf == 0.0;
        last.closed += nf > 0.0;
        for (int a = 0; a < 2 && nf > 0.0; a++) {
            lo[a] = fmin(lo[a], w[a]);
            hi[a] = fmax(hi[a], w[a]);
        }
    }
    for (size_t i = 0; i < N; i++)
        rms[i] = sqrt(sum[i] / steps);
    for (int a = 0; a < 2; a++)
        last.slid[a] = hi[a] - lo[a];
    fricreg_structure_free(st);
    return last;
}

/* HB's displacement and velocity at t = 0 from the coefficients x[N nc]. */
static void initial_state(const double *x, size_t nc, double omega, double *x0, double *v0)
{
    for (size_t k = 0; k < N; k++) {
        x0[k] = x[k * nc];
        v0[k] = 0.0;
        for (size_t h = 1; 2 * h < nc; h++) {
            x0[k] += x[k * nc + 2 * h - 1];
            v0[k] += (double)h * omega * x[k * nc + 2 * h];
        }
    }
}

/* HB at H = 15 from the solution at H = 5 (the default start takes 146 Newton steps at H = 15
 * here, 2.4 s, against 2 from this guess): q[3 31], x[N 31]. */
static void solve_h15(const struct plane *s, double omega, double *q, double *x)
{
    fricreg_hb *h5 = make(s, 5), *hb = make(s, 15);
    double q5[3 * 11];
    ck_assert_int_eq(fricreg_hb_solve(h5, omega, 3 * 11, NULL, q5), FRICREG_OK);
    memset(q, 0, 3 * 31 * sizeof *q);
    for (size_t r = 0; r < 3; r++)
        memcpy(q + 31 * r, q5 + 11 * r, 11 * sizeof *q);
    ck_assert_int_eq(fricreg_hb_solve(hb, omega, 3 * 31, q, q), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_displacement(hb, N, 31, x), FRICREG_OK);
    fricreg_hb_free(h5);
    fricreg_hb_free(hb);
}

START_TEST(against_a_long_time_integration)
{
    struct plane s = inclined();
    const int H = 15;
    const size_t nc = 2 * (size_t)H + 1;
    /* closed throughout with a slip along a curved path; lifting off in every period */
    const double omegas[] = {1.0, 1.35};
    const int lifts[] = {0, 1};
    fricreg_hb *hb = make(&s, H);
    ck_assert_int_eq(fricreg_hb_set_stability(hb, 1), FRICREG_OK);
    for (size_t w = 0; w < sizeof omegas / sizeof *omegas; w++) {
        double r4[N], p4[N], r8[N], p8[N], q[3 * 31], x[N * 31], err[N], aerr[N], x0[N], v0[N];
        solve_h15(&s, omegas[w], q, x);
        ck_assert_int_eq(fricreg_hb_solve(hb, omegas[w], 3 * nc, q, q), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_truncation_error(hb, FRICREG_HB_SOLUTION, N, err, aerr),
                         FRICREG_OK);
        /* the march below settles on it from a nearby state: Hill's method must call it stable */
        int stable = 0;
        double mu_max;
        ck_assert_int_eq(fricreg_hb_point_stability(hb, FRICREG_HB_SOLUTION, &stable, &mu_max),
                         FRICREG_OK);
        ck_assert_msg(stable == 1, "Omega %g: unstable (%g)", omegas[w], mu_max);
        /* started at HB's state (the steady state is unique: asserted steady below) */
        initial_state(x, nc, omegas[w], x0, v0);
        newmark_rms(&s, omegas[w], 2048, x0, v0, r4, p4);
        struct last_period last = newmark_rms(&s, omegas[w], 4096, x0, v0, r8, p8);
        ck_assert_msg(last.closed > 0 && (last.opened > 0) == lifts[w] && last.slid[0] > 0.01 &&
                          last.slid[1] > 0.01,
                      "Omega %g: opened %d, closed %d, slid %g, %g", omegas[w], last.opened,
                      last.closed, last.slid[0], last.slid[1]);
        for (size_t k = 0; k < N; k++) {
            /* the radial return's first order in dt: Richardson over 2048 and 4096 steps, its
             * remainder within their difference (1.4e-6 and 6e-8 of 3.9e-6 and 6.8e-5 against
             * 4096 and 8192 steps) */
            double ref = 2.0 * r8[k] - r4[k], rms = rms_of(x + k * nc, nc);
            double tol = err[k] + fabs(r8[k] - r4[k]);
            if (getenv("HB_PRINT"))
                fprintf(stderr,
                        "Omega %g dof %zu: HB %.9g reference %.9g (%.9g, %.9g), HB - reference "
                        "%.2e, truncation estimate %.2e\n",
                        omegas[w], k, rms, ref, r4[k], r8[k], rms - ref, err[k]);
            if (getenv("HB_PRINT"))
                fprintf(stderr, "steady %.2e %.2e\n", p4[k] / r4[k] - 1, p8[k] / r8[k] - 1);
            ck_assert_msg(fabs(p4[k] - r4[k]) <= 1e-7 * r4[k] &&
                              fabs(p8[k] - r8[k]) <= 1e-7 * r8[k],
                          "Omega %g dof %zu: not steady", omegas[w], k);
            ck_assert_msg(fabs(rms - ref) <= tol, "Omega %g dof %zu: HB %.9g, reference %.9g (%g)",
                          omegas[w], k, rms, ref, tol);
        }
    }
    fricreg_hb_free(hb);
}
END_TEST

/* On one axis (no y coupling nor forcing: uy stays 0) with kn = 0 the element is
 * fricreg_hb_set_jenkins_normal's, whose AFT is exact. */
START_TEST(one_axis_is_the_liftoff_element)
{
    struct plane s = inclined();
    s.K[1] = s.K[2] = 0.0;
    s.p[1] = 0.0;
    s.Jn[0] = 0.0, s.Jn[1] = 1.0;
    s.kn = 0.0;
    const int H = 7;
    const size_t nc = 2 * (size_t)H + 1;
    fricreg_hb *hb3 = make(&s, H), *hb1 = NULL;
    const double zero[N] = {0.0};
    ck_assert_int_eq(fricreg_hb_create(N, 1, H, &hb1), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb1, N, s.M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb1, N, s.K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb1, N, s.C), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_jenkins_normal(hb1, 1, N, s.Je, s.Jn, &s.kt, &s.mu, &s.n0,
                                                   &s.kn),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb1, N, s.p, zero), FRICREG_OK);
    const double omegas[] = {0.8, 1.2, 1.6};
    double q3[3 * 15], q1[2 * 15], x3[N * 15], x1[N * 15];
    for (size_t w = 0; w < sizeof omegas / sizeof *omegas; w++) {
        /* each from the one before (the default start walks a long way here) */
        ck_assert_int_eq(fricreg_hb_solve(hb3, omegas[w], 3 * nc, w ? q3 : NULL, q3), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_displacement(hb3, N, nc, x3), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_solve(hb1, omegas[w], 2 * nc, w ? q1 : NULL, q1), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_displacement(hb1, N, nc, x1), FRICREG_OK);
        double r3 = rms_of(x3, nc), r1 = rms_of(x1, nc);
        if (getenv("HB_PRINT"))
            fprintf(stderr, "one axis, Omega %g: 3-D %.12g, 1-D %.12g, %.2e\n", omegas[w], r3, r1,
                    r3 / r1 - 1.0);
        /* the sampled AFT's kinks on a line, (2 pi/N)^2 at N = 1024 samples (H = 7) */
        ck_assert_msg(fabs(r3 - r1) <= 4e-5 * r1, "Omega %g: 3-D %.12g, 1-D %.12g", omegas[w], r3,
                      r1);
        for (size_t c = 0; c < nc; c++) /* y: the preload's static deflection only */
            ck_assert_double_eq_tol(x3[nc + c], c == 0 ? x1[nc] : 0.0, 1e-12);
    }
    fricreg_hb_free(hb3);
    fricreg_hb_free(hb1);
}
END_TEST

/* Closed and stuck (mu large, N0 large): the springs kt, kt on the tangential rows (on the
 * harmonics: the slider at the centre of the orbit's enclosing circle, the centre of a
 * harmonic ellipse) and kn on the normal row with the preload: (K + kn Jn^T Jn) x0 = -Jn^T N0
 * and (K + kt Je^T Je + kn Jn^T Jn - Omega^2 M + i Omega C) X_1 = p, GSL's complex LU. */
START_TEST(closed_stuck_is_linear)
{
    struct plane s = inclined();
    s.mu = 1e6, s.n0 = 50.0;
    double Ks[N * N], load[N], x0[N], lu[N * N];
    for (size_t i = 0; i < N; i++) {
        load[i] = -s.Jn[i] * s.n0;
        for (size_t k = 0; k < N; k++)
            Ks[i * N + k] = s.K[i * N + k] + s.kn * s.Jn[i] * s.Jn[k];
    }
    memcpy(lu, Ks, sizeof lu);
    gsl_matrix_view Kv = gsl_matrix_view_array(lu, N, N);
    gsl_vector_view lv = gsl_vector_view_array(load, N), xv = gsl_vector_view_array(x0, N);
    gsl_permutation *perm = gsl_permutation_alloc(N);
    int sg;
    gsl_linalg_LU_decomp(&Kv.matrix, perm, &sg);
    gsl_linalg_LU_solve(&Kv.matrix, perm, &lv.vector, &xv.vector);
    const int H = 3;
    const size_t nc = 2 * (size_t)H + 1;
    fricreg_hb *hb = make(&s, H);
    const double omegas[] = {0.7, 1.3, 2.5};
    for (size_t w = 0; w < sizeof omegas / sizeof *omegas; w++) {
        double om = omegas[w], D[2 * N * N], b[2 * N], X[2 * N], q[3 * 7], x[N * 7];
        for (size_t i = 0; i < N; i++) {
            b[2 * i] = s.p[i], b[2 * i + 1] = 0.0;
            for (size_t k = 0; k < N; k++) {
                double kte = s.kt * (s.Je[i] * s.Je[k] + s.Je[N + i] * s.Je[N + k]);
                D[2 * (i * N + k)] = Ks[i * N + k] + kte - om * om * s.M[i * N + k];
                D[2 * (i * N + k) + 1] = om * s.C[i * N + k];
            }
        }
        gsl_matrix_complex_view Dv = gsl_matrix_complex_view_array(D, N, N);
        gsl_vector_complex_view bv = gsl_vector_complex_view_array(b, N);
        gsl_vector_complex_view Xv = gsl_vector_complex_view_array(X, N);
        gsl_linalg_complex_LU_decomp(&Dv.matrix, perm, &sg);
        gsl_linalg_complex_LU_solve(&Dv.matrix, perm, &bv.vector, &Xv.vector);
        ck_assert_int_eq(fricreg_hb_solve(hb, om, 3 * nc, NULL, q), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_displacement(hb, N, nc, x), FRICREG_OK);
        double scale = 0.0;
        for (size_t k = 0; k < N; k++)
            scale = fmax(scale, fabs(x0[k]) + hypot(X[2 * k], X[2 * k + 1]));
        for (size_t k = 0; k < N; k++)
            for (size_t c = 0; c < nc; c++) {
                double want = c == 0 ? x0[k] : c == 1 ? X[2 * k] : c == 2 ? -X[2 * k + 1] : 0.0;
                ck_assert_msg(fabs(x[k * nc + c] - want) <= 1e-10 * scale,
                              "Omega %g dof %zu coefficient %zu: %.17g against %.17g", om, k, c,
                              x[k * nc + c], want);
            }
    }
    gsl_permutation_free(perm);
    fricreg_hb_free(hb);
}
END_TEST

/* A continuation through the lift-off with Hill's stability passes the point solves (each
 * from the one before: the default start walks a long way here). */
START_TEST(continuation_passes_the_point_solves)
{
    struct plane s = inclined();
    const int H = 3;
    const size_t nc = 2 * (size_t)H + 1;
    fricreg_hb *hb = make(&s, H), *pt = make(&s, H);
    ck_assert_int_eq(fricreg_hb_set_stability(hb, 1), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_continue(hb, 0.9, 1.5, 3 * nc, NULL), FRICREG_OK);
    size_t np = fricreg_hb_points(hb);
    ck_assert_uint_gt(np, 10);
    double q[3 * 7], x[N * 7];
    const double *guess = NULL;
    for (size_t k = 1; k + 1 < np; k += np / 6) {
        double om, rms[N], mu_max;
        int stable;
        ck_assert_int_eq(fricreg_hb_point(hb, k, &om, N, rms), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_point_stability(hb, k, &stable, &mu_max), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_solve(pt, om, 3 * nc, guess, q), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_displacement(pt, N, nc, x), FRICREG_OK);
        guess = q;
        for (size_t d = 0; d < N; d++)
            ck_assert_msg(fabs(rms_of(x + d * nc, nc) - rms[d]) <= 1e-7 * rms[d],
                          "Omega %g dof %zu: branch %.12g, point %.12g", om, d, rms[d],
                          rms_of(x + d * nc, nc));
    }
    fricreg_hb_free(hb);
    fricreg_hb_free(pt);
}
END_TEST

/* The backbone of mode 0 (modal damping): at small amplitudes the element is stuck and closed
 * (the nonlinear modes' stuck rows: kt on x and y, kn on the normal row), so omega is the
 * linear mode's of K_0 = K + kt Je^T Je + kn Jn^T Jn against M, the root of
 * det(K_0 - lambda M) = 0 in closed form, to 1e-12; beyond, omega never rises and falls by
 * 1 % at least (the element slips and opens). */
START_TEST(backbone_starts_at_the_stuck_mode)
{
    struct plane s = inclined();
    const size_t np = 12;
    fricreg_hb *hb = make(&s, 5);
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, FRICREG_HB_NMA_DAMPING_MODAL, 0.001, 3.0, np),
                     FRICREG_OK);
    ck_assert_uint_eq(fricreg_hb_nma_points(hb), np);
    double K0[N * N];
    for (size_t i = 0; i < N; i++)
        for (size_t k = 0; k < N; k++)
            K0[i * N + k] = s.K[i * N + k] +
                            s.kt * (s.Je[i] * s.Je[k] + s.Je[N + i] * s.Je[N + k]) +
                            s.kn * s.Jn[i] * s.Jn[k];
    double qa = s.M[0] * s.M[3], qb = K0[0] * s.M[3] + K0[3] * s.M[0],
           qc = K0[0] * K0[3] - K0[1] * K0[2];
    double omega_stuck = sqrt((qb - sqrt(qb * qb - 4.0 * qa * qc)) / (2.0 * qa));
    double first = 0.0, last = 0.0;
    for (size_t k = 0; k < np; k++) {
        double a, w, z;
        ck_assert_int_eq(fricreg_hb_nma_point(hb, k, &a, &w, &z, 0, 0, NULL), FRICREG_OK);
        if (getenv("HB_PRINT"))
            fprintf(stderr, "backbone: a %.6g omega %.12f (stuck %.12f) zeta %.6g\n", a, w,
                    omega_stuck, z);
        if (k == 0)
            ck_assert_double_le(fabs(w - omega_stuck), 1e-12 * omega_stuck);
        else
            ck_assert_double_le(w, last * (1.0 + 1e-12));
        first = k == 0 ? w : first;
        last = w;
    }
    ck_assert_double_lt(last, 0.99 * first);
    fricreg_hb_free(hb);
}
END_TEST

START_TEST(bad_input)
{
    struct plane s = inclined();
    fricreg_hb *hb = make(&s, 3);
    double q[3 * 7], again[3 * 7], Je[2 * N], kn = -1.0, nan = NAN;
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.2, 3 * 7, NULL, q), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_jenkins_2d_normal(NULL, 1, N, s.Je, s.Jn, &s.kt, &s.mu, &s.n0,
                                                      &s.kn),
                     FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_set_jenkins_2d_normal(hb, 1, N, NULL, s.Jn, &s.kt, &s.mu, &s.n0,
                                                      &s.kn),
                     FRICREG_ENULL);
    ck_assert_str_eq(fricreg_hb_errmsg(hb), "set_jenkins_2d_normal: Je is NULL");
    ck_assert_int_eq(fricreg_hb_set_jenkins_2d_normal(hb, 2, N, s.Je, s.Jn, &s.kt, &s.mu, &s.n0,
                                                      &s.kn),
                     FRICREG_ESIZE);
    memcpy(Je, s.Je, sizeof Je);
    Je[2] = Je[3] = 0.0; /* the y row */
    ck_assert_int_eq(fricreg_hb_set_jenkins_2d_normal(hb, 1, N, Je, s.Jn, &s.kt, &s.mu, &s.n0,
                                                      &s.kn),
                     FRICREG_EINVAL);
    ck_assert_str_eq(fricreg_hb_errmsg(hb), "set_jenkins_2d_normal: row 1 of Je is zero");
    ck_assert_int_eq(fricreg_hb_set_jenkins_2d_normal(hb, 1, N, s.Je, s.Jn, &s.kt, &s.mu, &s.n0,
                                                      &kn),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_set_jenkins_2d_normal(hb, 1, N, s.Je, s.Jn, &s.kt, &nan, &s.n0,
                                                      &s.kn),
                     FRICREG_ENONFINITE);
    /* nothing changed: the same solution to the bit */
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.2, 3 * 7, NULL, again), FRICREG_OK);
    for (size_t j = 0; j < 3 * 7; j++)
        ck_assert_double_eq(again[j], q[j]);
    fricreg_hb_free(hb);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("hb_contact_3d");
    TCase *tc = tcase_create("core"), *td = tcase_create("time_domain");
    tcase_add_test(tc, one_axis_is_the_liftoff_element);
    tcase_add_test(tc, closed_stuck_is_linear);
    tcase_add_test(tc, continuation_passes_the_point_solves);
    tcase_add_test(tc, backbone_starts_at_the_stuck_mode);
    tcase_add_test(tc, bad_input);
    tcase_add_test(td, against_a_long_time_integration);
    /* HB at H = 15 and a time march to the settled period at two frequencies (12 s): the
     * release tier's (hb_contact_3d_release) */
    tcase_set_tags(td, "release");
    suite_add_tcase(s, tc);
    suite_add_tcase(s, td);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
