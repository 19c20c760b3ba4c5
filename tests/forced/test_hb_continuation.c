/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_continuation.c — Check suite for the harmonic-balance continuation's step control and
 * the located peak (fricreg_hb_continue, fricreg_hb_peak; fricreg_hb.h).
 *
 * The models:
 *   - the chain: 3 unit masses in a chain of unit springs (ground–1–2–3), C = 0.02 K, unit
 *     force on dof 2 (index 1), two Jenkins elements kt = 20, mu N = 1: element 0 between dof 1
 *     and ground, element 1 either between dofs 1 and 2 ("chain A", where the 1.6 step control
 *     stopped at Omega = 0.9757 at H = 7: the branch has kinks where the stick/slip pattern
 *     changes) or between dofs 2 and 3 ("chain B"); Omega from 0.5 to 2, across the second and
 *     third resonances.
 *   - the contact pair: 2 unit masses, K = [140 −20; −20 180] (natural frequencies 11.5 and
 *     13.7 rad/s), C = 0.002 K, one lift-off element kt = 40, mu = 0.3, N0 = 2, kn = 100,
 *     tangential along dof 1, normal g = −x_2 (opens when x_2 > N0/kn = 0.02), p_c = (2, 1).
 *
 * Where the numbers come from:
 *   - each stored point's RMS against a natural-parameter sweep: fixed-Omega fricreg_hb_solve
 *     at the branch's frequencies in order, each from the previous solution (none of these
 *     branches folds in Omega, asserted), so none of the continuation's machinery; to 1e-7.
 *   - the located peak against a fixed-Omega search: golden section on the RMS of
 *     fricreg_hb_solve (warm-started from a continuation to the bracket's lower end) over a
 *     bracket found on a grid of 401 solves around it; to 1e-9 in the RMS and 2e-5 in Omega
 *     (a smooth maximum's Omega is known to the square root of the RMS's accuracy).
 *   - the peak's convergence in H (the element forces' coefficients fall like h^-2): H = 9
 *     nearer H = 15 than H = 5 is.
 *   - a branch that doubles back (the oscillator of damping ratio 1e-5, linear: its RMS in
 *     closed form): every stored point on the closed form to 1e-6 of the peak (the corrector's
 *     1e-10 amplified by Q = 5e4), Omega past the resonance
 *     and the refused point (its Omega in the message) back below it, FRICREG_EWORK long
 *     before max_points.
 *   - the contact pair's peak from three routes (up, down, and across 5 to 14 rad/s) agree to
 *     1e-8; at the peak, the steady state in time (tests/support/jenkins_newmark.h, 1024 steps a
 *     period, 400 periods, steady to 1e-6 and the contact asserted to open and close) against
 *     H = 15 within 2e-3.
 *   - the contact pair's start without a guess at H = 7 (the CLI's default) from 11.5 to 12.5:
 *     its first point stable (Hill's method) and that of the continuations from 12.5 down and
 *     from 5 up to 1e-8. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_hb.h"
#include "jenkins_newmark.h"

#define MAXN JENKINS_MODEL_MAXN
#define MAXQ (2 * 31) /* nq at H = 15: 2 rows (two elements, or one with lift-off) */
#define SENTINEL (-777.125)

/* The chain; second: element 1 between dofs 1 and 2 (chain A) or 2 and 3 (chain B). */
static struct jenkins_model chain(int a)
{
    struct jenkins_model s = {.n = 3, .m = 2};
    const double K[9] = {2, -1, 0, -1, 2, -1, 0, -1, 1};
    for (int i = 0; i < 9; i++) {
        s.K[i] = K[i];
        s.C[i] = 0.02 * K[i];
        s.M[i] = i % 4 == 0 ? 1.0 : 0.0;
    }
    s.J[0] = 1.0; /* q_0 = x_1 */
    if (a)
        s.J[3] = -1.0, s.J[4] = 1.0; /* q_1 = x_2 − x_1 */
    else
        s.J[4] = -1.0, s.J[5] = 1.0; /* q_1 = x_3 − x_2 */
    s.kt[0] = s.kt[1] = 20.0;
    s.mun[0] = s.mun[1] = 1.0;
    s.pc[1] = 1.0;
    return s;
}

static struct jenkins_model contact_pair(void)
{
    struct jenkins_model s = {.n = 2, .m = 1, .normal = 1};
    const double K[4] = {140, -20, -20, 180};
    for (int i = 0; i < 4; i++) {
        s.K[i] = K[i];
        s.C[i] = 0.002 * K[i];
    }
    s.M[0] = s.M[3] = 1.0;
    s.J[0] = 1.0;
    s.Jn[1] = -1.0;
    s.kt[0] = 40.0;
    s.mu[0] = 0.3, s.n0[0] = 2.0, s.kn[0] = 100.0;
    s.pc[0] = 2.0, s.pc[1] = 1.0;
    return s;
}

static size_t rows(const struct jenkins_model *s)
{
    return s->normal ? 2 * s->m : s->m;
}

static fricreg_hb *make(const struct jenkins_model *s, int H)
{
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(s->n, s->m, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, s->n, s->M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, s->n, s->K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, s->n, s->C), FRICREG_OK);
    if (s->normal)
        ck_assert_int_eq(fricreg_hb_set_normal_elements(hb, s->m, s->n, s->J, s->Jn, s->kt, s->mu,
                                                        s->n0, s->kn),
                         FRICREG_OK);
    else
        ck_assert_int_eq(fricreg_hb_set_elements(hb, s->m, s->n, s->J, s->kt, s->mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, s->n, s->pc, s->ps), FRICREG_OK);
    return hb;
}

/* The last solution's q = J x (and g = Jn x) from fricreg_hb_displacement, into q[rows nc], and
 * dof k's RMS. */
static double solution(fricreg_hb *hb, const struct jenkins_model *s, int H, size_t k, double *q)
{
    size_t nc = 2 * (size_t)H + 1;
    double x[MAXN * 31];
    ck_assert_int_eq(fricreg_hb_displacement(hb, s->n, nc, x), FRICREG_OK);
    for (size_t e = 0; e < s->m && q != NULL; e++)
        for (size_t c = 0; c < nc; c++) {
            double u = 0.0, g = 0.0;
            for (size_t i = 0; i < s->n; i++) {
                u += s->J[e * s->n + i] * x[i * nc + c];
                g += s->Jn[e * s->n + i] * x[i * nc + c];
            }
            if (s->normal) {
                q[2 * e * nc + c] = u;
                q[(2 * e + 1) * nc + c] = g;
            } else {
                q[e * nc + c] = u;
            }
        }
    double r = x[k * nc] * x[k * nc];
    for (size_t c = 1; c < nc; c++)
        r += 0.5 * x[k * nc + c] * x[k * nc + c];
    return sqrt(r);
}

/* Dof k's RMS at omega by fricreg_hb_solve from (and into) q. */
static double fixed(fricreg_hb *hb, const struct jenkins_model *s, int H, size_t k, double omega,
                    double *q)
{
    size_t nq = rows(s) * (2 * (size_t)H + 1);
    ck_assert_msg(fricreg_hb_solve(hb, omega, nq, q, q) == FRICREG_OK, "solve at %.10g: %s", omega,
                  fricreg_hb_errmsg(hb));
    return solution(hb, s, H, k, NULL);
}

/* Continue over [w0, w1] with the defaults: OK, at most max_points points, from w0 to w1. */
static fricreg_hb *branch(const struct jenkins_model *s, int H, double w0, double w1,
                          size_t max_points)
{
    fricreg_hb *hb = make(s, H);
    size_t nq = rows(s) * (2 * (size_t)H + 1);
    int status = fricreg_hb_continue(hb, w0, w1, nq, NULL);
    size_t np = fricreg_hb_points(hb);
    if (getenv("HB_PRINT"))
        fprintf(stderr, "H %d, %g -> %g: status %d, %zu points\n", H, w0, w1, status, np);
    ck_assert_msg(status == FRICREG_OK, "H %d, %g -> %g: %s", H, w0, w1, fricreg_hb_errmsg(hb));
    ck_assert_uint_le(np, max_points);
    double om, rms[MAXN];
    ck_assert_int_eq(fricreg_hb_point(hb, 0, &om, s->n, rms), FRICREG_OK);
    ck_assert_double_eq(om, w0);
    ck_assert_int_eq(fricreg_hb_point(hb, np - 1, &om, s->n, rms), FRICREG_OK);
    ck_assert_double_eq(om, w1);
    return hb;
}

/* Every stored point's RMS against the natural-parameter sweep (fixed Omega, each solve from
 * the previous solution), on a branch that does not fold (monotone): to 1e-7 of the largest. */
static void against_sweep(fricreg_hb *hb, const struct jenkins_model *s, int H)
{
    size_t np = fricreg_hb_points(hb), nq = rows(s) * (2 * (size_t)H + 1);
    fricreg_hb *ref = make(s, H);
    double q[MAXQ], om, rms[MAXN], top = 0.0, dev = 0.0;
    for (size_t k = 0; k < np; k++) {
        ck_assert_int_eq(fricreg_hb_point(hb, k, &om, s->n, rms), FRICREG_OK);
        for (size_t i = 0; i < s->n; i++)
            top = fmax(top, rms[i]);
    }
    for (size_t k = 0; k < np; k++) {
        ck_assert_int_eq(fricreg_hb_point(hb, k, &om, s->n, rms), FRICREG_OK);
        /* from the previous solution; should Newton fail from there (a coarse step across a
         * kink), from the stuck guess */
        if (k == 0 || fricreg_hb_solve(ref, om, nq, q, q) != FRICREG_OK)
            ck_assert_int_eq(fricreg_hb_solve(ref, om, nq, NULL, q), FRICREG_OK);
        for (size_t i = 0; i < s->n; i++) {
            double r = solution(ref, s, H, i, NULL);
            dev = fmax(dev, fabs(r - rms[i]) / top);
            ck_assert_msg(fabs(r - rms[i]) <= 1e-7 * top,
                          "H %d, Omega %.10g, dof %zu: %.12g, %.12g", H, om, i, rms[i], r);
        }
    }
    if (getenv("HB_PRINT"))
        fprintf(stderr, "  the sweep's largest deviation %.2e of %.4g\n", dev, top);
    fricreg_hb_free(ref);
}

/* Omega along the stored points moves one way (no fold), towards w1. */
static void monotone(fricreg_hb *hb, const struct jenkins_model *s, double w0, double w1)
{
    double om, last = w0, rms[MAXN];
    for (size_t k = 1; k < fricreg_hb_points(hb); k++) {
        ck_assert_int_eq(fricreg_hb_point(hb, k, &om, s->n, rms), FRICREG_OK);
        ck_assert_double_gt((om - last) * (w1 - w0), 0.0);
        last = om;
    }
}

START_TEST(chain_every_harmonic)
{
    const int Hs[4] = {5, 7, 9, 15};
    for (int a = 0; a < 2; a++) {
        struct jenkins_model s = chain(!a);
        double peak[4];
        for (int t = 0; t < 4; t++) {
            fricreg_hb *hb = branch(&s, Hs[t], 0.5, 2.0, 400);
            monotone(hb, &s, 0.5, 2.0);
            against_sweep(hb, &s, Hs[t]);
            double om;
            ck_assert_int_eq(fricreg_hb_peak(hb, 0, &om, &peak[t]), FRICREG_OK);
            fricreg_hb_free(hb);
        }
        if (getenv("HB_PRINT"))
            fprintf(stderr, "chain %c: dof 1's peak %.10g %.10g %.10g %.10g\n", a ? 'B' : 'A',
                    peak[0], peak[1], peak[2], peak[3]);
        ck_assert_double_lt(fabs(peak[2] - peak[3]), fabs(peak[0] - peak[3]));
    }
}
END_TEST

/* A large ds_min (ds/5, where 1.6 stopped at H = 15): kinks are accepted at ds_min. */
START_TEST(chain_coarse_ds_min)
{
    struct jenkins_model s = chain(0);
    const int H = 15;
    fricreg_hb *hb = make(&s, H);
    ck_assert_int_eq(fricreg_hb_set_continuation(hb, 0.02, 0.004, 0.1, 400), FRICREG_OK);
    int status = fricreg_hb_continue(hb, 0.5, 2.0, 2 * 31, NULL);
    ck_assert_msg(status == FRICREG_OK, "%s", fricreg_hb_errmsg(hb));
    monotone(hb, &s, 0.5, 2.0);
    against_sweep(hb, &s, H);
    fricreg_hb_free(hb);
}
END_TEST

/* The located peak of each dof against golden section at fixed Omega. */
START_TEST(peak_against_fixed_omega)
{
    struct jenkins_model s = chain(1);
    const int H = 7;
    size_t nq = 2 * 15;
    fricreg_hb *hb = branch(&s, H, 0.5, 2.0, 400);
    for (size_t k = 0; k < s.n; k++) {
        double om = SENTINEL, peak = SENTINEL, sampled = 0.0, w_sampled = 0.0, o, rms[MAXN];
        ck_assert_int_eq(fricreg_hb_peak(hb, k, &om, &peak), FRICREG_OK);
        for (size_t j = 0; j < fricreg_hb_points(hb); j++) {
            ck_assert_int_eq(fricreg_hb_point(hb, j, &o, s.n, rms), FRICREG_OK);
            if (rms[k] > sampled)
                sampled = rms[k], w_sampled = o;
        }
        /* interior here: the located peak is no lower than the sampled one */
        ck_assert_double_gt(w_sampled, 0.5);
        ck_assert_double_lt(w_sampled, 2.0);
        ck_assert_double_ge(peak, sampled * (1.0 - 1e-12));
        /* the reference: a continuation to below the peak for the guess, then fixed Omega */
        double lo = om * (1.0 - 2e-3), hi = om * (1.0 + 2e-3), q[MAXQ], qlo[MAXQ], best = 0.0;
        fricreg_hb *ref = branch(&s, H, 0.5, lo, 400);
        solution(ref, &s, H, k, qlo);
        memcpy(q, qlo, sizeof q);
        int g_best = 0;
        for (int g = 0; g <= 400; g++) {
            double r = fixed(ref, &s, H, k, lo + (hi - lo) * g / 400.0, q);
            if (r > best)
                best = r, g_best = g;
        }
        ck_assert_int_gt(g_best, 0);
        ck_assert_int_lt(g_best, 400);
        double a = lo + (hi - lo) * (g_best - 1) / 400.0, c = lo + (hi - lo) * (g_best + 1) / 400.0;
        for (int it = 0; it < 50; it++) {
            double m1 = a + 0.3819660112501051 * (c - a), m2 = c - 0.3819660112501051 * (c - a);
            memcpy(q, qlo, sizeof q);
            double f1 = fixed(ref, &s, H, k, m1, q), f2 = fixed(ref, &s, H, k, m2, q);
            if (f1 > f2)
                c = m2;
            else
                a = m1;
        }
        memcpy(q, qlo, sizeof q);
        double w_ref = 0.5 * (a + c), r_ref = fixed(ref, &s, H, k, w_ref, q);
        if (getenv("HB_PRINT"))
            fprintf(stderr,
                    "dof %zu: located %.12g at %.10g, fixed Omega %.12g at %.10g (%.1e, %.1e); "
                    "sampled %.12g (%.1e)\n",
                    k, peak, om, r_ref, w_ref, peak / r_ref - 1.0, om / w_ref - 1.0, sampled,
                    sampled / peak - 1.0);
        ck_assert_double_le(fabs(peak / r_ref - 1.0), 1e-9);
        ck_assert_double_le(fabs(om / w_ref - 1.0), 2e-5);
        fricreg_hb_free(ref);
        (void)nq;
    }
    fricreg_hb_free(hb);
}
END_TEST

START_TEST(contact_pair_every_route)
{
    struct jenkins_model s = contact_pair();
    const int H = 15;
    const double ends[3][2] = {{11.5, 12.5}, {12.5, 11.5}, {5.0, 14.0}};
    double om[3], peak[3];
    for (int r = 0; r < 3; r++) {
        fricreg_hb *hb = branch(&s, H, ends[r][0], ends[r][1], 400);
        monotone(hb, &s, ends[r][0], ends[r][1]);
        if (r < 2)
            against_sweep(hb, &s, H);
        ck_assert_int_eq(fricreg_hb_peak(hb, 0, &om[r], &peak[r]), FRICREG_OK);
        if (getenv("HB_PRINT"))
            fprintf(stderr, "route %d: dof 1's peak %.12g at %.10g\n", r, peak[r], om[r]);
        fricreg_hb_free(hb);
    }
    for (int r = 1; r < 3; r++) {
        ck_assert_double_le(fabs(peak[r] / peak[0] - 1.0), 1e-8);
        ck_assert_double_le(fabs(om[r] / om[0] - 1.0), 1e-5);
    }
    fricreg_hb *hb = branch(&s, H, 11.5, 12.5, 400);
    ck_assert_int_eq(fricreg_hb_peak(hb, 1, &om[0], &peak[0]), FRICREG_OK);
    fricreg_hb_free(hb);
    hb = branch(&s, H, 12.5, 11.5, 400);
    ck_assert_int_eq(fricreg_hb_peak(hb, 1, &om[1], &peak[1]), FRICREG_OK);
    fricreg_hb_free(hb);
    ck_assert_double_le(fabs(peak[1] / peak[0] - 1.0), 1e-8);
}
END_TEST

/* The contact pair's point at omega reached from w0 at H with stability on (every point from
 * 11.5 rad/s up stable), dof k's RMS into rms[k]; the driver returned. */
static fricreg_hb *stable_route(const struct jenkins_model *s, int H, double w0, double omega,
                                double *rms)
{
    fricreg_hb *hb = make(s, H);
    ck_assert_int_eq(fricreg_hb_set_stability(hb, 1), FRICREG_OK);
    size_t nq = rows(s) * (2 * (size_t)H + 1);
    ck_assert_msg(fricreg_hb_continue(hb, w0, omega, nq, NULL) == FRICREG_OK, "%g -> %g: %s", w0,
                  omega, fricreg_hb_errmsg(hb));
    size_t np = fricreg_hb_points(hb), at = w0 == omega ? 0 : np - 1;
    for (size_t k = 0; k < np; k++) {
        int stable = 0;
        double mu_max, om, r[MAXN];
        ck_assert_int_eq(fricreg_hb_point_stability(hb, k, &stable, &mu_max), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_point(hb, k, &om, s->n, r), FRICREG_OK);
        ck_assert_msg(stable || om < 11.5, "%g -> %g: point %zu at Omega %.10g unstable, mu_max %g",
                      w0, omega, k, om, mu_max);
    }
    double om;
    ck_assert_int_eq(fricreg_hb_point(hb, at, &om, s->n, rms), FRICREG_OK);
    ck_assert_double_eq(om, omega);
    return hb;
}

/* The start without a guess at the CLI's defaults (H = 7) from 11.5 to 12.5 rad/s lands on the
 * stable branch that the continuations from 12.5 down and from 5 up follow: every point of
 * the three from 11.5 up stable, the first point at 11.5 theirs to 1e-8 (measured: 1.1e-10
 * from 12.5, 1e-12 from 5; rms_2 = 0.0423, mu_max = 0.903; 3000 random guesses at 11.5 found
 * no other solution). Below, from 5 up, the branch is unstable between two Neimark-Sacker
 * points near 10.67 and 10.82 rad/s (mu_max 1.084 at 10.73, the same at H = 7, 11 and 15). */
START_TEST(contact_pair_default_start_stable)
{
    struct jenkins_model s = contact_pair();
    const int H = 7;
    double first[MAXN], down[MAXN], up[MAXN];
    fricreg_hb *hb = stable_route(&s, H, 11.5, 12.5, down); /* its last point, unused */
    double om;
    ck_assert_int_eq(fricreg_hb_point(hb, 0, &om, s.n, first), FRICREG_OK);
    ck_assert_double_eq(om, 11.5);
    /* stability turned off: the points, stored with it, are dropped */
    ck_assert_uint_gt(fricreg_hb_points(hb), 1);
    ck_assert_int_eq(fricreg_hb_set_stability(hb, 0), FRICREG_OK);
    ck_assert_uint_eq(fricreg_hb_points(hb), 0);
    ck_assert_int_eq(fricreg_hb_point(hb, 0, &om, s.n, up), FRICREG_EINVAL);
    fricreg_hb_free(hb);
    fricreg_hb_free(stable_route(&s, H, 12.5, 11.5, down));
    fricreg_hb_free(stable_route(&s, H, 5.0, 11.5, up));
    for (size_t k = 0; k < s.n; k++) {
        if (getenv("HB_PRINT"))
            fprintf(stderr, "dof %zu at 11.5: start %.12g, from 12.5 %.12g, from 5 %.12g\n", k,
                    first[k], down[k], up[k]);
        ck_assert_double_le(fabs(first[k] / down[k] - 1.0), 1e-8);
        ck_assert_double_le(fabs(first[k] / up[k] - 1.0), 1e-8);
    }
}
END_TEST

/* The gap pair of test_hb_stability.c (the contact pair turned round: tangential along dof 2,
 * normal g = −x_1, mu = 0.01, N0 = −10, kn = 500: a unilateral spring with a gap) at twice
 * its excitation, p_c = (4, 2). */
static struct jenkins_model gap_pair_doubled(void)
{
    struct jenkins_model s = contact_pair();
    s.J[0] = 0.0, s.J[1] = 1.0;
    s.Jn[0] = -1.0, s.Jn[1] = 0.0;
    s.mu[0] = 0.01, s.n0[0] = -10.0, s.kn[0] = 500.0;
    s.pc[0] = 4.0, s.pc[1] = 2.0;
    return s;
}

/* The last point's dof RMS of a continuation from w0 to w1 at H = 7, stability on. */
static void sweep_end(const struct jenkins_model *s, double w0, double w1, double *rms)
{
    fricreg_hb *hb = branch(s, 7, w0, w1, 2000);
    ck_assert_int_eq(fricreg_hb_point(hb, fricreg_hb_points(hb) - 1, &w0, s->n, rms), FRICREG_OK);
    fricreg_hb_free(hb);
}

/* At 5 rad/s (H = 7) the start without a guess of the doubled gap pair lands on a closed
 * branch, stable there (measured rms_2 0.012549, mu_max 0.80): the continuation towards 5.5
 * goes round it (4.840 to 5.111 rad/s, 53 points) back to its start, and returns FRICREG_OK
 * with the loop, its last point short of Omega1 (1.7 stopped with FRICREG_EWORK, "doubles
 * back"). An isola: the sweeps from 4 up and from 5.5 down agree at 5 (rms_2 0.012242) to
 * 1e-8, off the loop's first point by more than 1e-3; the loop turns in Omega at both ends
 * (a TP located above 5.1 and one below 4.85) and ends within 0.05 rad/s of its start. */
START_TEST(closed_branch_is_returned)
{
    struct jenkins_model s = gap_pair_doubled();
    double up[MAXN], down[MAXN], first[MAXN], last[MAXN], om0, om1, lo = INFINITY, hi = 0.0;
    sweep_end(&s, 4.0, 5.0, up);
    sweep_end(&s, 5.5, 5.0, down);
    fricreg_hb *hb = make(&s, 7);
    ck_assert_int_eq(fricreg_hb_set_stability(hb, 1), FRICREG_OK);
    int status = fricreg_hb_continue(hb, 5.0, 5.5, rows(&s) * 15, NULL), stable = 0;
    ck_assert_msg(status == FRICREG_OK, "%s", fricreg_hb_errmsg(hb));
    size_t np = fricreg_hb_points(hb), tp_lo = 0, tp_hi = 0;
    ck_assert_uint_gt(np, 20);
    ck_assert_uint_lt(np, 400);
    for (size_t k = 0; k < np; k++) {
        ck_assert_int_eq(fricreg_hb_point(hb, k, &om1, s.n, last), FRICREG_OK);
        lo = fmin(lo, om1), hi = fmax(hi, om1);
    }
    ck_assert_int_eq(fricreg_hb_point(hb, 0, &om0, s.n, first), FRICREG_OK);
    double mu_max = 0.0;
    ck_assert_int_eq(fricreg_hb_point_stability(hb, 0, &stable, &mu_max), FRICREG_OK);
    if (getenv("HB_PRINT"))
        fprintf(stderr,
                "closed: %zu points, %.6g .. %.6g, back at %.6g; rms_2 %.10g (mu_max %.3g), "
                "sweeps %.10g %.10g\n",
                np, lo, hi, om1, first[1], mu_max, up[1], down[1]);
    ck_assert_double_eq(om0, 5.0);
    ck_assert_int_eq(stable, 1);
    ck_assert_double_ne(om1, 5.5);
    ck_assert_double_le(fabs(om1 - om0), 0.05);
    ck_assert_double_lt(lo, 4.85);
    ck_assert_double_gt(hi, 5.1);
    ck_assert_double_lt(hi, 5.5);
    for (size_t i = 0; i < fricreg_hb_bifurcations(hb); i++) {
        int type = 0;
        double om = 0.0, rms[MAXN];
        size_t k = 0;
        ck_assert_int_eq(fricreg_hb_bifurcation(hb, i, &type, &om, &k, s.n, rms), FRICREG_OK);
        tp_lo += type == FRICREG_HB_TP && om < 4.85;
        tp_hi += type == FRICREG_HB_TP && om > 5.1;
    }
    ck_assert_uint_ge(tp_lo, 1);
    ck_assert_uint_ge(tp_hi, 1);
    for (size_t k = 0; k < s.n; k++) {
        ck_assert_double_le(fabs(up[k] - down[k]), 1e-8 * up[k]);
        ck_assert_double_gt(fabs(first[k] - up[k]), 1e-3 * up[k]);
    }
    fricreg_hb_free(hb);
}
END_TEST

/* At the located peak, the steady state in time: the contact opens and closes there. */
START_TEST(contact_pair_time_domain)
{
    struct jenkins_model s = contact_pair();
    const int H = 15;
    double om, peak, rms[MAXN], prev[MAXN], ref[MAXN], q[MAXQ];
    fricreg_hb *hb = branch(&s, H, 11.5, 12.5, 400);
    ck_assert_int_eq(fricreg_hb_peak(hb, 0, &om, &peak), FRICREG_OK);
    fricreg_hb_free(hb);
    int flips = jenkins_newmark_rms(&s, om, 1024, 400, ref, prev, NULL);
    ck_assert_msg(flips, "the contact does not open and close at the peak, Omega = %g", om);
    /* HB at that Omega from the branch's solution below it */
    hb = branch(&s, H, 11.5, om * (1.0 - 1e-3), 400);
    solution(hb, &s, H, 0, q);
    rms[0] = fixed(hb, &s, H, 0, om, q);
    rms[1] = solution(hb, &s, H, 1, NULL);
    ck_assert_double_le(fabs(rms[0] / peak - 1.0), 1e-9);
    for (size_t k = 0; k < s.n; k++) {
        if (getenv("HB_PRINT"))
            fprintf(stderr, "dof %zu: HB %.9g Newmark %.9g rel %.2e steady %.2e\n", k, rms[k],
                    ref[k], rms[k] / ref[k] - 1.0, prev[k] / ref[k] - 1.0);
        ck_assert_double_le(fabs(ref[k] - prev[k]), 1e-6 * ref[k]);
        ck_assert_double_le(fabs(rms[k] - ref[k]), 2e-3 * ref[k]);
    }
    fricreg_hb_free(hb);
}
END_TEST

/* One mass m = 2 on k = 3 with a stuck element kt = 1.5 (mu N = 1e6: linear, stiffness 4.5),
 * C = 2 zeta sqrt(4.5 m), forced by 0.5 cos(Omega t), H = 3: RMS in closed form. */
static fricreg_hb *oscillator(double zeta)
{
    fricreg_hb *hb = NULL;
    double M = 2.0, K = 3.0, C = 2.0 * zeta * sqrt(9.0), J = 1.0, kt = 1.5, mun = 1e6, pc = 0.5,
           ps = 0.0;
    ck_assert_int_eq(fricreg_hb_create(1, 1, 3, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 1, &M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 1, &K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, 1, &C), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, 1, &J, &kt, &mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, 1, &pc, &ps), FRICREG_OK);
    return hb;
}

/* A branch that doubles back stops with FRICREG_EWORK, long before max_points: on the
 * oscillator of damping ratio 1e-5 the default step joins the two ends of the response circle
 * (they meet at q = 0 a few 1e-3 rad/s apart) beyond the peak and runs back down the rising
 * flank (1.6 reversed there again and again, to its 2000 points). Its points are the closed
 * form's, and Omega reversed; at damping ratio 3e-5 the branch passes. */
START_TEST(doubling_back_stops)
{
    fricreg_hb *hb = oscillator(1e-5);
    int status = fricreg_hb_continue(hb, 0.5, 3.0, 7, NULL);
    size_t np = fricreg_hb_points(hb);
    if (getenv("HB_PRINT"))
        fprintf(stderr, "zeta 1e-5: status %d, %zu points: %s\n", status, np,
                fricreg_hb_errmsg(hb));
    ck_assert_int_eq(status, FRICREG_EWORK);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "doubles back"));
    ck_assert_uint_lt(np, 400);
    double om, rms, top = 0.0, last = 0.0, C = 2.0 * 1e-5 * 3.0, want[400], big = 0.0;
    for (size_t k = 0; k < np; k++) {
        ck_assert_int_eq(fricreg_hb_point(hb, k, &om, 1, &rms), FRICREG_OK);
        double d = 4.5 - 2.0 * om * om, c = C * om;
        want[k] = 0.5 / sqrt(d * d + c * c) / sqrt(2.0);
        big = fmax(big, want[k]);
    }
    for (size_t k = 0; k < np; k++) {
        ck_assert_int_eq(fricreg_hb_point(hb, k, &om, 1, &rms), FRICREG_OK);
        ck_assert_double_le(fabs(rms - want[k]), 1e-6 * big);
        top = fmax(top, om);
        last = om;
    }
    /* the points past the resonance (1.5), the refused one (in the message) back below it */
    double back = 0.0;
    const char *at = strstr(fricreg_hb_errmsg(hb), "at Omega = ");
    ck_assert_ptr_nonnull(at);
    ck_assert_int_eq(sscanf(at, "at Omega = %lf", &back), 1);
    ck_assert_double_gt(top, 1.5);
    ck_assert_double_gt(last, 1.5);
    ck_assert_double_lt(back, 1.5);
    fricreg_hb_free(hb);
    hb = oscillator(3e-5);
    ck_assert_int_eq(fricreg_hb_continue(hb, 0.5, 3.0, 7, NULL), FRICREG_OK);
    ck_assert_uint_le(fricreg_hb_points(hb), 400);
    fricreg_hb_free(hb);
}
END_TEST

/* The stored unknowns follow nq: a branch with Jenkins elements (2 rows), then on the same
 * driver one with lift-off elements (4 rows: nq doubles; kn = 0, N = N0 throughout): its points
 * against a natural-parameter sweep; the peak refused in between (the elements changed). */
START_TEST(elements_change_between_branches)
{
    struct jenkins_model s = chain(1);
    const int H = 5;
    fricreg_hb *hb = make(&s, H);
    ck_assert_int_eq(fricreg_hb_continue(hb, 0.5, 2.0, 2 * 11, NULL), FRICREG_OK);
    double om, r;
    ck_assert_int_eq(fricreg_hb_peak(hb, 0, &om, &r), FRICREG_OK);
    struct jenkins_model n = s;
    n.normal = 1;
    for (int e = 0; e < 2; e++) {
        n.Jn[e * 3 + 2] = 1.0; /* g = x_3, no normal force: kn = 0, N0 = 1 */
        n.mu[e] = 1.0, n.n0[e] = 1.0, n.kn[e] = 0.0;
    }
    ck_assert_int_eq(fricreg_hb_set_normal_elements(hb, 2, 3, n.J, n.Jn, n.kt, n.mu, n.n0, n.kn),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_peak(hb, 0, &om, &r), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_continue(hb, 0.5, 2.0, 4 * 11, NULL), FRICREG_OK);
    ck_assert_uint_le(fricreg_hb_points(hb), 400);
    against_sweep(hb, &n, H);
    ck_assert_int_eq(fricreg_hb_peak(hb, 0, &om, &r), FRICREG_OK);
    fricreg_hb_free(hb);
}
END_TEST

START_TEST(peak_bad_input)
{
    struct jenkins_model s = chain(0);
    fricreg_hb *hb = make(&s, 3);
    double om = SENTINEL, r = SENTINEL;
    ck_assert_int_eq(fricreg_hb_peak(NULL, 0, &om, &r), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_peak(hb, 0, NULL, &r), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_peak(hb, 0, &om, NULL), FRICREG_ENULL);
    /* no branch yet */
    ck_assert_int_eq(fricreg_hb_peak(hb, 0, &om, &r), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "no branch"));
    ck_assert_int_eq(fricreg_hb_continue(hb, 0.5, 0.6, 2 * 7, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_peak(hb, 3, &om, &r), FRICREG_EINVAL);
    ck_assert_double_eq(om, SENTINEL);
    ck_assert_double_eq(r, SENTINEL);
    /* above the first resonance (0.445 rad/s) the largest RMS of dof 1 is at the branch's
     * start: that point's */
    double o, rms[MAXN];
    ck_assert_int_eq(fricreg_hb_peak(hb, 0, &om, &r), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_point(hb, 0, &o, 3, rms), FRICREG_OK);
    ck_assert_double_eq(om, 0.5);
    ck_assert_double_eq(o, 0.5);
    ck_assert_double_eq(r, rms[0]);
    /* a model change ends the branch's use */
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 3, s.K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_peak(hb, 0, &om, &r), FRICREG_EINVAL);
    /* the step control's bad input: ds <= 0, and a zero-length range */
    ck_assert_int_eq(fricreg_hb_set_continuation(hb, 0.0, 1e-6, 0.1, 10), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_set_continuation(hb, -0.01, -0.1, 0.1, 10), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_continue(hb, 0.5, 0.5, 2 * 7, NULL), FRICREG_EINVAL);
    fricreg_hb_free(hb);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("hb_continuation");
    TCase *tc = tcase_create("core"), *td = tcase_create("time_domain");
    TCase *th = tcase_create("harmonics"); /* eight branches: half the program's time */
    tcase_set_timeout(tc, 120);
    tcase_set_timeout(td, 120);
    tcase_set_timeout(th, 120);
    tcase_set_tags(th, "release"); /* 4 s: hb_continuation_release; core continues the chain */
    tcase_add_test(th, chain_every_harmonic);
    tcase_add_test(tc, contact_pair_every_route);
    tcase_add_test(tc, contact_pair_default_start_stable);
    tcase_add_test(tc, doubling_back_stops);
    tcase_add_test(tc, closed_branch_is_returned);
    tcase_add_test(tc, elements_change_between_branches);
    tcase_add_test(tc, peak_bad_input);
    tcase_add_test(td, contact_pair_time_domain);
    /* the chain at H = 15 with a coarse ds_min, and each dof's peak against golden section
     * (2 s): the release tier's (hb_continuation_release) */
    TCase *tk = tcase_create("kinks_and_peak");
    tcase_set_timeout(tk, 120);
    tcase_set_tags(tk, "release");
    tcase_add_test(tk, chain_coarse_ds_min);
    tcase_add_test(tk, peak_against_fixed_omega);
    suite_add_tcase(s, tc);
    suite_add_tcase(s, tk);
    suite_add_tcase(s, th);
    suite_add_tcase(s, td);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
