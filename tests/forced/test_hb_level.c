/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_level.c — Check suite for the continuation in the excitation level at a fixed
 * frequency (fricreg_hb_continue_level, fricreg_hb_point_level, fricreg_hb_bifurcation_level)
 * and the point solve without a guess that starts along it (fricreg_hb_solve; fricreg_hb.h).
 *
 * The models:
 *   - the Jenkins oscillator: m = 1, k = 1, c = 0.02, one Jenkins element kt = 2 on the dof
 *     (J = 1), mu N = 0.5 (or 1e6: stuck at every level here), p_c = 1, H = 7, Omega = 1.5.
 *   - the gap pair of test_hb_stability.c: 2 unit masses, K = [140 −20; −20 180], C = 0.002 K,
 *     one lift-off element tangential along dof 2, normal g = −x_1, kt = 40, mu = 0.01,
 *     N0 = −10, kn = 500 (a unilateral spring with a gap of 0.02: hardening), p_c = (2, 1),
 *     H = 7. Above its linear resonance (Omega = 15.2) the amplitude against the level is an
 *     S-curve: folds near λ = 1.05 and 0.25; at Omega = 14 the branch from the linear regime
 *     folds twice below λ = 1.
 *   - the bilinear oscillator (bilinear_oscillator), H = 7, Omega = 1.6.
 *
 * Where the numbers come from:
 *   - stuck (mu N = 1e6): (R) is linear, so every point's RMS is λ times the RMS at λ = 1
 *     (a point solve), to 1e-10 (one Newton step solves a linear corrector exactly).
 *   - the Jenkins oscillator slipping: every point against a point solve at its level (the
 *     excitation λ p_c set, Newton from a zero guess: independent of the continuation), to 1e-8
 *     of the RMS (both converged to Newton's 1e-10).
 *   - the fold in λ of the gap pair at Omega = 15.2: the largest λ at which point solves
 *     (Newton from the last lower-branch solution, the excitation λ (p_c, p_s)) still land on
 *     the lower branch, by bisection to 1e-8, against the located FRICREG_HB_TP to 1e-6; the
 *     stable flag flips across it (a saddle-node: the middle branch is unstable).
 *   - the point solve without a guess against the continuation in the level from 1e-3 to 1
 *     (fricreg_hb_continue_level's last point): equal to 1e-8 of q, with the same stability; at
 *     Omega = 14 Newton from a zero guess (the stuck response, the start until 1.6) finds no
 *     solution (the issue: point solves failed where the continuation passed), at 15.2 the
 *     solve returns the lowest of the three solutions at λ = 1, the one reached from the linear
 *     regime.
 *   - the bilinear oscillator's point solve without a guess against warm-started point solves
 *     walked down from 2 rad/s (its response is homogeneous in the forcing: the level's branch
 *     does not reach it, the branch in Omega from a nearby frequency does).
 *   - an undamped pair at its linear resonances (K − Ω² M singular in closed form):
 *     FRICREG_ESINGULAR before a bound of 10 Newton steps would stop the solve. */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_element.h"
#include "fricreg_hb.h"

#define H 7
#define NC (2 * H + 1)
#define MAXP 2000

static fricreg_hb *oscillator(double mun)
{
    fricreg_hb *hb = NULL;
    const double one = 1.0, c = 0.02, kt = 2.0, zero = 0.0;
    ck_assert_int_eq(fricreg_hb_create(1, 1, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 1, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 1, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, 1, &c), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, 1, &one, &kt, &mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, 1, &one, &zero), FRICREG_OK);
    return hb;
}

static const double gap_pc[2] = {2.0, 1.0}, gap_ps[2] = {0.0, 0.0};

static fricreg_hb *gap_pair(int stability)
{
    fricreg_hb *hb = NULL;
    const double M[4] = {1, 0, 0, 1}, K[4] = {140, -20, -20, 180}, J[2] = {0, 1}, Jn[2] = {-1, 0},
                 kt = 40, mu = 0.01, n0 = -10, kn = 500;
    double C[4];
    for (int i = 0; i < 4; i++)
        C[i] = 0.002 * K[i];
    ck_assert_int_eq(fricreg_hb_create(2, 1, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 2, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, 2, C), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_normal_elements(hb, 1, 2, J, Jn, &kt, &mu, &n0, &kn),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, 2, gap_pc, gap_ps), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stability(hb, stability), FRICREG_OK);
    return hb;
}

/* The excitation λ times the model's (pc, ps). */
static void scale_excitation(fricreg_hb *hb, size_t n, const double *pc, const double *ps,
                             double level)
{
    double sc[2], ss[2];
    for (size_t k = 0; k < n; k++)
        sc[k] = level * pc[k], ss[k] = level * ps[k];
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, n, sc, ss), FRICREG_OK);
}

/* Dof k's RMS over a period from the last solution's displacements. */
static double solution_rms(fricreg_hb *hb, size_t n, size_t k)
{
    double x[2 * NC], s = 0.0;
    ck_assert_int_eq(fricreg_hb_displacement(hb, n, NC, x), FRICREG_OK);
    for (int c = 0; c < NC; c++)
        s += (c == 0 ? 1.0 : 0.5) * x[k * NC + c] * x[k * NC + c];
    return sqrt(s);
}

/* The stored points' levels and dof 0's RMS into level[], rms[]; their count. */
static size_t branch(fricreg_hb *hb, size_t n, double omega, double *level, double *rms)
{
    size_t np = fricreg_hb_points(hb);
    ck_assert_uint_le(np, MAXP);
    for (size_t k = 0; k < np; k++) {
        double w = 0.0, r[2];
        ck_assert_int_eq(fricreg_hb_point(hb, k, &w, n, r), FRICREG_OK);
        ck_assert_double_eq(w, omega); /* a level branch's points share its Ω */
        ck_assert_int_eq(fricreg_hb_point_level(hb, k, &level[k]), FRICREG_OK);
        rms[k] = r[0];
    }
    return np;
}

static double level_buf[MAXP], rms_buf[MAXP];

START_TEST(stuck_is_linear_in_level)
{
    fricreg_hb *hb = oscillator(1e6);
    ck_assert_int_eq(fricreg_hb_continue_level(hb, 1.5, 0.1, 2.5, NC, NULL), FRICREG_OK);
    size_t np = branch(hb, 1, 1.5, level_buf, rms_buf);
    ck_assert_uint_ge(np, 3);
    ck_assert_double_eq(level_buf[0], 0.1);
    ck_assert_double_eq(level_buf[np - 1], 2.5);
    double q[NC];
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.5, NC, NULL, q), FRICREG_OK);
    double unit = solution_rms(hb, 1, 0);
    for (size_t k = 0; k < np; k++) {
        ck_assert(k == 0 || level_buf[k] > level_buf[k - 1]);
        ck_assert_double_le(fabs(rms_buf[k] - level_buf[k] * unit), 1e-10 * level_buf[k] * unit);
    }
    ck_assert_uint_eq(fricreg_hb_bifurcations(hb), 0);
    fricreg_hb_free(hb);
}
END_TEST

START_TEST(jenkins_against_point_solves)
{
    fricreg_hb *hb = oscillator(0.5);
    const double one = 1.0, zero = 0.0;
    ck_assert_int_eq(fricreg_hb_continue_level(hb, 1.5, 0.05, 3.0, NC, NULL), FRICREG_OK);
    size_t np = branch(hb, 1, 1.5, level_buf, rms_buf);
    ck_assert_uint_ge(np, 5);
    /* the last point is the driver's solution, at level1 */
    ck_assert_double_le(fabs(solution_rms(hb, 1, 0) - rms_buf[np - 1]), 1e-12 * rms_buf[np - 1]);
    double q[NC] = {0};
    for (size_t k = 0; k < np; k++) { /* Newton from the last level's solution */
        scale_excitation(hb, 1, &one, &zero, level_buf[k]);
        ck_assert_int_eq(fricreg_hb_solve(hb, 1.5, NC, q, q), FRICREG_OK);
        ck_assert_double_le(fabs(solution_rms(hb, 1, 0) - rms_buf[k]), 1e-8 * rms_buf[k]);
    }
    /* the element slips at the top of the branch: not the linear response */
    double gain = (rms_buf[np - 1] / level_buf[np - 1]) / (rms_buf[0] / level_buf[0]);
    ck_assert_double_gt(fabs(gain - 1.0), 0.05);
    fricreg_hb_free(hb);
}
END_TEST

/* Newton from the lower branch's solution qlo at lo lands on the lower branch at level: the
 * same stretch of the branch (within a fifth of its amplitude of qlo). */
static int on_lower_branch(fricreg_hb *hb, double level, const double *qlo, double *q)
{
    scale_excitation(hb, 2, gap_pc, gap_ps, level);
    if (fricreg_hb_solve(hb, 15.2, 2 * NC, qlo, q) != FRICREG_OK)
        return 0;
    double d = 0.0, s = 0.0;
    for (int j = 0; j < 2 * NC; j++)
        d = fmax(d, fabs(q[j] - qlo[j])), s = fmax(s, fabs(qlo[j]));
    return d <= 0.2 * s;
}

START_TEST(fold_in_level)
{
    fricreg_hb *hb = gap_pair(1);
    ck_assert_int_eq(fricreg_hb_continue_level(hb, 15.2, 0.05, 2.0, 2 * NC, NULL), FRICREG_OK);
    size_t np = branch(hb, 2, 15.2, level_buf, rms_buf);
    ck_assert_uint_eq(fricreg_hb_bifurcations(hb), 2);
    double fold[2];
    for (size_t i = 0; i < 2; i++) {
        int type = 0, s0 = 0, s1 = 0;
        double w = 0.0, r[2], mu = 0.0;
        size_t k = 0;
        ck_assert_int_eq(fricreg_hb_bifurcation(hb, i, &type, &w, &k, 2, r), FRICREG_OK);
        ck_assert_int_eq(type, FRICREG_HB_TP);
        ck_assert_double_eq(w, 15.2);
        ck_assert_int_eq(fricreg_hb_bifurcation_level(hb, i, &fold[i]), FRICREG_OK);
        /* the lower branch's fold a largest λ, the upper's a smallest */
        if (i == 0)
            ck_assert(fold[i] >= fmax(level_buf[k], level_buf[k + 1]) - 1e-12);
        else
            ck_assert(fold[i] <= fmin(level_buf[k], level_buf[k + 1]) + 1e-12);
        /* the stable flag flips at the fold: by the exact monodromy (the orbit's multiplier,
         * the automatic choice for lift-off) within one point of it, the HB's truncation error
         * (measured: one point before the upper fold) */
        ck_assert_int_eq(fricreg_hb_point_stability(hb, k - 1, &s0, &mu), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_point_stability(hb, k + 2, &s1, &mu), FRICREG_OK);
        ck_assert_int_ne(s0, s1);
    }
    ck_assert_double_gt(fold[0], 1.0); /* the lower branch's fold, then the upper's */
    ck_assert_double_lt(fold[1], 1.0);
    ck_assert_double_gt(level_buf[np - 1], level_buf[0]);
    /* the fold by point solves: lo on the lower branch (the old start there, Newton from zero),
     * hi beyond the fold */
    double qlo[2 * NC] = {0}, q[2 * NC], lo = 0.9, hi = 1.2;
    scale_excitation(hb, 2, gap_pc, gap_ps, lo);
    ck_assert_int_eq(fricreg_hb_solve(hb, 15.2, 2 * NC, qlo, qlo), FRICREG_OK);
    ck_assert_double_lt(solution_rms(hb, 2, 0), rms_buf[0] / 0.05 * 1.2); /* nearly linear */
    ck_assert_int_eq(on_lower_branch(hb, hi, qlo, q), 0);
    while (hi - lo > 1e-8) {
        double mid = 0.5 * (lo + hi);
        if (on_lower_branch(hb, mid, qlo, q)) {
            lo = mid;
            memcpy(qlo, q, sizeof q);
        } else {
            hi = mid;
        }
    }
    ck_assert_double_le(fabs(0.5 * (lo + hi) - fold[0]), 1e-6);
    /* a later solve has the excitation as set (λ = 1 again): peak does not apply */
    double w = 0.0, r = 0.0;
    ck_assert_int_eq(fricreg_hb_peak(hb, 0, &w, &r), FRICREG_EINVAL);
    fricreg_hb_free(hb);
}
END_TEST

/* The point solve without a guess at omega against the level's continuation from 1e-3 to 1:
 * q to 1e-8, the same stability; the solution's dof-0 RMS into *rms. */
static void solve_is_continuation(fricreg_hb *hb, double omega, double *rms)
{
    double q[2 * NC];
    size_t before = fricreg_hb_points(hb);
    ck_assert_int_eq(fricreg_hb_solve(hb, omega, 2 * NC, NULL, q), FRICREG_OK);
    int stable = -1, stable_c = -2;
    double mu = 0.0, mu_c = 0.0;
    ck_assert_int_eq(fricreg_hb_point_stability(hb, FRICREG_HB_SOLUTION, &stable, &mu), FRICREG_OK);
    ck_assert_uint_eq(fricreg_hb_points(hb), before); /* the solve stores no branch */
    *rms = solution_rms(hb, 2, 0);
    ck_assert_int_eq(fricreg_hb_continue_level(hb, omega, 1e-3, 1.0, 2 * NC, NULL), FRICREG_OK);
    size_t np = fricreg_hb_points(hb);
    double r[2], w;
    ck_assert_int_eq(fricreg_hb_point(hb, np - 1, &w, 2, r), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_point_stability(hb, np - 1, &stable_c, &mu_c), FRICREG_OK);
    ck_assert_int_eq(stable, stable_c);
    ck_assert_double_le(fabs(mu - mu_c), 1e-6 * mu_c);
    ck_assert_double_le(fabs(*rms - r[0]), 1e-8 * r[0]);
}

START_TEST(point_solve_follows_the_level)
{
    fricreg_hb *hb = gap_pair(1);
    double q[2 * NC], zero[2 * NC] = {0}, rms = 0.0;
    /* Omega = 14: Newton from the stuck response finds nothing; the level's branch does */
    ck_assert_int_eq(fricreg_hb_solve(hb, 14.0, 2 * NC, zero, q), FRICREG_EWORK);
    solve_is_continuation(hb, 14.0, &rms);
    /* a branch without a guess begins at that solution */
    double w0 = 0.0, r0[2];
    ck_assert_int_eq(fricreg_hb_continue(hb, 14.0, 14.05, 2 * NC, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_point(hb, 0, &w0, 2, r0), FRICREG_OK);
    ck_assert_double_eq(w0, 14.0);
    ck_assert_double_le(fabs(r0[0] - rms), 1e-8 * rms);
    /* Omega = 15.2: three solutions at λ = 1 on the S-curve; the solve returns the lowest */
    solve_is_continuation(hb, 15.2, &rms);
    ck_assert_int_eq(fricreg_hb_continue_level(hb, 15.2, 0.05, 2.0, 2 * NC, NULL), FRICREG_OK);
    size_t np = branch(hb, 2, 15.2, level_buf, rms_buf), crossings = 0;
    double lowest = INFINITY;
    for (size_t k = 0; k + 1 < np; k++)
        if ((level_buf[k] - 1.0) * (level_buf[k + 1] - 1.0) <= 0.0) {
            crossings++;
            lowest = fmin(lowest, fmin(rms_buf[k], rms_buf[k + 1]));
        }
    ck_assert_uint_eq(crossings, 3);
    ck_assert_double_le(rms, lowest * 1.2);
    /* a solve without stability has none to give */
    fricreg_hb *plain = gap_pair(0);
    ck_assert_int_eq(fricreg_hb_solve(plain, 15.2, 2 * NC, NULL, q), FRICREG_OK);
    int stable = 0;
    double mu = 0.0;
    ck_assert_int_eq(fricreg_hb_point_stability(plain, FRICREG_HB_SOLUTION, &stable, &mu),
                     FRICREG_EINVAL);
    fricreg_hb_free(plain);
    fricreg_hb_free(hb);
}
END_TEST

/* The last stored point's dof RMS into rms[2] and its stability; its Ω returned. */
static double last_point(fricreg_hb *hb, double *rms, int *stable, double *mu_max)
{
    size_t np = fricreg_hb_points(hb);
    double w = 0.0;
    ck_assert_uint_gt(np, 0);
    ck_assert_int_eq(fricreg_hb_point(hb, np - 1, &w, 2, rms), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_point_stability(hb, np - 1, stable, mu_max), FRICREG_OK);
    return w;
}

/* The gap pair at 1.5 times its excitation, at 3.55 rad/s: the level's branch from the linear
 * regime ends on a closed branch, at an unstable solution (measured rms_2 0.008543, mu_max
 * 1.052), which 1.7's default start took: its continuation went round the closed branch and
 * stopped, "doubles back". The sweeps from 2.05 up and from 5.05 down agree on a stable
 * solution there (rms_2 0.008417, mu_max 0.756), and the start without a guess now takes it,
 * to 1e-8, the continuation then reaching 4.05; the solve without a guess too. Without
 * stability there is no verdict to go by: the start is the level branch's end, as before. */
START_TEST(unstable_start_takes_the_stable_branch)
{
    const double omega = 3.55, rms_tol = 1e-8;
    double up[2], down[2], level_end[2], first[2], r[2], mu_max = 0.0, w = 0.0, q[2 * NC];
    int stable = -1;
    fricreg_hb *hb = gap_pair(1);
    scale_excitation(hb, 2, gap_pc, gap_ps, 1.5);
    /* the level's branch: its end unstable */
    ck_assert_int_eq(fricreg_hb_continue_level(hb, omega, 1e-3, 1.0, 2 * NC, NULL), FRICREG_OK);
    last_point(hb, level_end, &stable, &mu_max);
    ck_assert_int_eq(stable, 0);
    ck_assert_double_gt(mu_max, 1.0);
    /* the independent sweeps, both ending stable on one solution */
    ck_assert_int_eq(fricreg_hb_continue(hb, 2.05, omega, 2 * NC, NULL), FRICREG_OK);
    ck_assert_double_eq(last_point(hb, up, &stable, &mu_max), omega);
    ck_assert_int_eq(stable, 1);
    ck_assert_int_eq(fricreg_hb_continue(hb, 5.05, omega, 2 * NC, NULL), FRICREG_OK);
    ck_assert_double_eq(last_point(hb, down, &stable, &mu_max), omega);
    ck_assert_int_eq(stable, 1);
    for (int k = 0; k < 2; k++) {
        ck_assert_double_le(fabs(up[k] - down[k]), rms_tol * up[k]);
        ck_assert_double_gt(fabs(level_end[k] - up[k]), 1e-3 * up[k]); /* another solution */
    }
    /* the start without a guess: the sweeps' solution, stable, and on to Omega1 */
    ck_assert_msg(fricreg_hb_continue(hb, omega, 4.05, 2 * NC, NULL) == FRICREG_OK, "%s",
                  fricreg_hb_errmsg(hb));
    ck_assert_double_eq(last_point(hb, r, &stable, &mu_max), 4.05);
    ck_assert_int_eq(fricreg_hb_point(hb, 0, &w, 2, first), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_point_stability(hb, 0, &stable, &mu_max), FRICREG_OK);
    if (getenv("HB_PRINT"))
        fprintf(stderr, "rms_2 at %g: level %.10g, start %.10g (mu_max %.4f), sweeps %.10g %.10g\n",
                omega, level_end[1], first[1], mu_max, up[1], down[1]);
    ck_assert_int_eq(stable, 1);
    ck_assert_double_le(mu_max, 1.0);
    for (int k = 0; k < 2; k++)
        ck_assert_double_le(fabs(first[k] - up[k]), rms_tol * up[k]);
    ck_assert_int_eq(fricreg_hb_solve(hb, omega, 2 * NC, NULL, q), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_point_stability(hb, FRICREG_HB_SOLUTION, &stable, &mu_max),
                     FRICREG_OK);
    ck_assert_int_eq(stable, 1);
    ck_assert_double_le(fabs(solution_rms(hb, 2, 1) - up[1]), rms_tol * up[1]);
    fricreg_hb_free(hb);
    /* stability off: the level branch's end */
    hb = gap_pair(0);
    scale_excitation(hb, 2, gap_pc, gap_ps, 1.5);
    ck_assert_int_eq(fricreg_hb_solve(hb, omega, 2 * NC, NULL, q), FRICREG_OK);
    ck_assert_double_le(fabs(solution_rms(hb, 2, 1) - level_end[1]), rms_tol * level_end[1]);
    fricreg_hb_free(hb);
}
END_TEST

/* The bilinear oscillator of test_hb_stability.c: m = 1, k = 1, c = 0.04, a unilateral spring
 * kn = 9 at x < 0 without gap or preload (mu = 0), p_c = 1. Its response is homogeneous in
 * the forcing, so the level's branch is a ray that is no easier to follow than its end. */
static fricreg_hb *bilinear_oscillator(void)
{
    fricreg_hb *hb = NULL;
    const double one = 1.0, c = 0.04, Jn = -1.0, mu = 0.0, n0 = 0.0, kn = 9.0, zero = 0.0;
    ck_assert_int_eq(fricreg_hb_create(1, 1, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 1, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 1, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, 1, &c), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_normal_elements(hb, 1, 1, &one, &Jn, &one, &mu, &n0, &kn),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, 1, &one, &zero), FRICREG_OK);
    return hb;
}

/* Near the bilinear oscillator's resonance (1.52 rad/s) Newton fails from the plain guesses
 * (stuck or free: here closed or open) and along the level's ray; the solve without a guess
 * then follows the branch in Omega from a nearby frequency where they converge. Its solution
 * against warm-started point solves walked down from 2 rad/s in steps of 0.01, to 1e-8 of q;
 * a continuation without a guess starts from it. */
START_TEST(homogeneous_response_from_a_nearby_frequency)
{
    fricreg_hb *hb = bilinear_oscillator();
    const double omega = 1.6;
    double q[2 * NC], walked[2 * NC], zero[2 * NC] = {0};
    ck_assert_int_eq(fricreg_hb_solve(hb, omega, 2 * NC, zero, q), FRICREG_EWORK);
    ck_assert_int_eq(fricreg_hb_solve(hb, omega, 2 * NC, NULL, q), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(hb, 2.0, 2 * NC, NULL, walked), FRICREG_OK);
    for (int i = 1; i <= 40; i++)
        ck_assert_int_eq(fricreg_hb_solve(hb, 2.0 - 0.01 * i, 2 * NC, walked, walked), FRICREG_OK);
    double scale = 0.0, diff = 0.0;
    for (int j = 0; j < 2 * NC; j++)
        scale = fmax(scale, fabs(walked[j])), diff = fmax(diff, fabs(q[j] - walked[j]));
    ck_assert_double_le(diff, 1e-8 * scale);
    ck_assert_int_eq(fricreg_hb_continue(hb, omega, 1.65, 2 * NC, NULL), FRICREG_OK);
    fricreg_hb_free(hb);
}
END_TEST

/* Two models whose level branch the start leaves for the plain guesses at λ = 1, Ω = 0.8,
 * H = 3, contact_3d elements to the ground (kt 20, mu 0.25, kn 50, n0 4) on nodes of unit
 * masses in x, y and the normal z, springs S in x and y and 40 S in z, Rayleigh damping
 * 0.02/√S K (bench/hb_interface_rom.c and bench/hb_contact_3d_chain.c at one contact):
 *   - one node (S = 4/π²), forced 0.5 cos Ωt on x, 0.3 sin Ωt on y and 7.5 cos Ωt on z: the
 *     contact lifts off at λ = 1 (least N −21); near λ = 0.07 its sticks turn to slips whose
 *     sampled AFT's kinks lie closer than the corrector converges, and the branch crawls
 *     (4051 Newton iterations in 1.9 before ds_min; since 1.10 left after 50 steps in a row
 *     within 100 ds_min: about 300);
 *   - three nodes in a chain ground-0-1-2 (S = 36/π²), the contact on node 1, forced 0.5 cos
 *     Ωt on x, 0.3 sin Ωt on y and 0.5 cos Ωt on z at node 2: past the first slip the
 *     corrector contracts by 0.75 an iteration (1212 iterations in 1.9, its failed correctors
 *     50 each; since 1.10 given up after 8 without a tenfold fall: about 350).
 * Both end at the plain guesses' solution (Newton from a zero guess), to 1e-8. */
static int count_iterations(void *user, int64_t iterations, double parameter, double residual)
{
    (void)parameter, (void)residual;
    *(int64_t *)user = iterations;
    return 0;
}

static fricreg_hb *contact_nodes(size_t nodes, const double load[3])
{
    const double PI = 3.14159265358979323846, S = pow(2.0 * (double)nodes / PI, 2.0);
    const double p[5] = {20, 0.25, 50, 4, 0}, ks[3] = {S, S, 40 * S};
    size_t n = 3 * nodes, at = 3 * (nodes / 2); /* the contact's node: the middle one */
    double M[81] = {0}, K[81] = {0}, J[27] = {0}, pc[9] = {0}, ps[9] = {0};
    for (size_t i = 0; i < n; i++) {
        size_t d = i % 3;
        M[i * n + i] = 1.0;
        K[i * n + i] += ks[d];
        if (i >= 3) {
            K[(i - 3) * n + i - 3] += ks[d];
            K[i * n + i - 3] = K[(i - 3) * n + i] = -ks[d];
        }
    }
    for (size_t r = 0; r < 3; r++)
        J[r * n + at + r] = 1.0;
    pc[n - 3] = load[0], ps[n - 2] = load[1], pc[n - 1] = load[2];
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(n, 1, 3, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, n, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, n, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_rayleigh(hb, 0.0, 0.02 / sqrt(S)), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, n, pc, ps), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("contact_3d"), 1, n, J, p),
                     FRICREG_OK);
    return hb;
}

START_TEST(crawling_level_branch_gives_way)
{
    const size_t nodes[2] = {1, 3};
    const double loads[2][3] = {{0.5, 0.3, 7.5}, {0.5, 0.3, 0.5}};
    const int64_t most[2] = {1000, 700}; /* measured 306 and 346 */
    fricreg_hb *hb = contact_nodes(nodes[_i], loads[_i]);
    double q[21], plain[21], zero[21] = {0};
    int64_t iterations = 0;
    ck_assert_int_eq(fricreg_hb_set_monitor(hb, count_iterations, &iterations), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(hb, 0.8, 21, NULL, q), FRICREG_OK);
    ck_assert_int_le(iterations, most[_i]);
    ck_assert_int_eq(fricreg_hb_solve(hb, 0.8, 21, zero, plain), FRICREG_OK);
    double scale = 0.0, diff = 0.0;
    for (int j = 0; j < 21; j++)
        scale = fmax(scale, fabs(plain[j])), diff = fmax(diff, fabs(q[j] - plain[j]));
    ck_assert_double_le(diff, 1e-8 * scale);
    fricreg_hb_free(hb);
}
END_TEST

START_TEST(bad_input)
{
    fricreg_hb *hb = oscillator(0.5);
    double level = 0.0, q0[NC] = {0};
    ck_assert_int_eq(fricreg_hb_continue_level(NULL, 1.5, 0.1, 1.0, NC, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_continue_level(hb, 0.0, 0.1, 1.0, NC, NULL), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_continue_level(hb, NAN, 0.1, 1.0, NC, NULL), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_hb_continue_level(hb, 1.5, NAN, 1.0, NC, NULL), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_hb_continue_level(hb, 1.5, 0.1, INFINITY, NC, NULL),
                     FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_hb_continue_level(hb, 1.5, -0.1, 1.0, NC, NULL), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "level0 = -0.1"));
    ck_assert_int_eq(fricreg_hb_continue_level(hb, 1.5, 0.5, 0.5, NC, NULL), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_continue_level(hb, 1.5, 0.1, 1.0, NC - 1, NULL), FRICREG_ESIZE);
    q0[2] = NAN;
    ck_assert_int_eq(fricreg_hb_continue_level(hb, 1.5, 0.1, 1.0, NC, q0), FRICREG_ENONFINITE);
    ck_assert_uint_eq(fricreg_hb_points(hb), 0); /* nothing changed */
    ck_assert_int_eq(fricreg_hb_point_level(hb, 0, &level), FRICREG_EINVAL);
    /* downwards, from level 0 (the zero response), and the levels read back */
    ck_assert_int_eq(fricreg_hb_continue_level(hb, 1.5, 1.0, 0.0, NC, NULL), FRICREG_OK);
    size_t np = fricreg_hb_points(hb);
    ck_assert_int_eq(fricreg_hb_point_level(hb, np - 1, &level), FRICREG_OK);
    ck_assert_double_eq(level, 0.0);
    ck_assert_int_eq(fricreg_hb_point_level(NULL, 0, &level), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_point_level(hb, 0, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_point_level(hb, np, &level), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_bifurcation_level(NULL, 0, &level), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_bifurcation_level(hb, 0, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_bifurcation_level(hb, 0, &level), FRICREG_EINVAL);
    /* an Ω branch's points and bifurcations are at λ = 1 */
    ck_assert_int_eq(fricreg_hb_continue(hb, 1.2, 1.8, NC, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_point_level(hb, 1, &level), FRICREG_OK);
    ck_assert_double_eq(level, 1.0);
    fricreg_hb_free(hb);
}
END_TEST

/* An undamped pair with a marched jenkins_2d element, solved without a guess at each of its
 * linear resonances (1 and sqrt(3) rad/s), where D_1 is singular: FRICREG_ESINGULAR before
 * any Newton step (the routes crept up on the resonance for 4 602 steps and a minute before;
 * the bound of 10 would have stopped them with FRICREG_EWORK). */
START_TEST(singular_start_fails_at_once)
{
    const double M[4] = {1, 0, 0, 1}, K[4] = {2, -1, -1, 2}, J[4] = {1, 0, 0, 1};
    const double params[2] = {1.0, 0.5}, pc[2] = {1, 0}, ps[2] = {0, 0};
    const double resonances[2] = {1.0, sqrt(3.0)};
    for (int i = 0; i < 2; i++) {
        fricreg_hb *hb = NULL;
        double q[2 * NC];
        ck_assert_int_eq(fricreg_hb_create(2, 1, H, &hb), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_set_mass(hb, 2, M), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, K), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("jenkins_2d"), 1, 2, J,
                                                 params),
                         FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_set_excitation(hb, 2, pc, ps), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_set_max_iterations(hb, 10), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_solve(hb, resonances[i], 2 * NC, NULL, q), FRICREG_ESINGULAR);
        ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "singular"));
        fricreg_hb_free(hb);
    }
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("hb_level");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, stuck_is_linear_in_level);
    tcase_add_test(tc, jenkins_against_point_solves);
    tcase_add_test(tc, fold_in_level);
    tcase_add_test(tc, point_solve_follows_the_level);
    tcase_add_test(tc, unstable_start_takes_the_stable_branch);
    tcase_add_test(tc, homogeneous_response_from_a_nearby_frequency);
    tcase_add_loop_test(tc, crawling_level_branch_gives_way, 0, 2);
    tcase_add_test(tc, bad_input);
    tcase_add_test(tc, singular_start_fails_at_once);
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
