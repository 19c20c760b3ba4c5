/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_nma_energy.c — Check suite for what a backbone point is made of
 * (fricreg_hb_nma_harmonic_energy, fricreg_hb_nma_modal_participation; fricreg_hb.h) and where
 * a harmonic k ω crosses another linear mode's frequency (the special points of type
 * FRICREG_HB_NMA_CROSSING, fricreg_hb_nma_special_points, fricreg_hb_nma_special_point), on
 * tests/nma/test_hb_nma_fold.c's two-mass model: dof 1 grounded by k1 = 1, coupled by kc = 1/4 to
 * dof 2, grounded by k2 = 1/5 and a Jenkins element kt, μN = 1, unit masses, no viscous damping,
 * H = 3. With kt = 10 its backbone (mode 0) folds twice in the
 * amplitude, at a = 4.4324 and 4.4168.
 *
 * Where the numbers come from:
 * - the shares, from an independent evaluation: the velocity of each harmonic sampled N = 64
 *   times a period from the point's coefficients (fricreg_hb_nma_point), its kinetic energy
 *   ½ vᵀ M v averaged by the trapezoidal rule, over that of the whole velocity sampled the
 *   same way (cross terms included: they average to zero, Parseval; the rule is exact for a
 *   trigonometric polynomial of degree below N, so the two agree to rounding);
 * - the participations: the stuck structure's modes in closed form (the 2x2 symmetric
 *   eigenproblem, K_0 = [[5/4, −1/4], [−1/4, 0.45 + kt]]);
 * - the crossings: ω_1 = sqrt(λ_1(K_0)) in the same closed form, the backbone's ω at its stored
 *   points (fricreg_hb_nma_point).
 *
 * Measured on the fold model (kt = 10, 400 points from a = 0.05 to 1e4): the third harmonic's share
 * is 0 while the element sticks (the mode is linear), rises through the S to its largest, 5.24e-4,
 * at a = 4.47 (just past the lower fold; 3.4e-4 and 4.8e-4 at the points nearest the upper and the
 * lower fold), and falls to 1.13e-10 at a = 1e4 (the element slips nearly all the time: its force a
 * square wave of fixed height against a motion that grows as a); all of it is in mode 1 (the
 * element's dof: 1 − 4e-6). But 3ω never crosses ω_1 of the stuck structure: 3ω runs from 3.3450
 * (stuck) down to 3.3431 at the folds and up to 3.4490, always above ω_1 = 3.2337 (the ratio
 * ω_1/ω_0 = 2.90): the fold is near, not at, a 3:1 resonance with the stuck mode, and no crossing
 * is reported there. With kt = 11, ω_1 = 3.3847 lies inside 3ω's range, and the crossing is found
 * at a = 5.04, ω = 1.12823 (after that model's S, at a = 4.49): the special points list its folds
 * first, then the crossing (and before the S a pair of folds at the slip onset, a = 3.71264, 5.5e-5
 * above δ/φ_2 = 3.71243 of the closed form: the tangent's log a component turns twice at the
 * stick–slip kink). */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_hb.h"

#define KC 0.25
#define K1 1.0
#define K2 0.2
#define MUN 1.0
#define H 3
#define NC (2 * H + 1)

static const double pi = 3.14159265358979323846;

/* Special point i: its kind, a, ω, ζ, k, r (asserting the status). */
static int special(fricreg_hb *hb, size_t i, double *a, double *omega, double *zeta, int *k,
                   size_t *r)
{
    int type = 0;
    ck_assert_int_eq(fricreg_hb_nma_special_point(hb, i, &type, a, omega, zeta, k, r), FRICREG_OK);
    return type;
}

static fricreg_hb *model(double kt)
{
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(2, 1, H, &hb), FRICREG_OK);
    const double M[4] = {1, 0, 0, 1}, K[4] = {K1 + KC, -KC, -KC, KC + K2}, J[2] = {0, 1};
    const double mun = MUN;
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 2, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, 2, J, &kt, &mun), FRICREG_OK);
    return hb;
}

/* The stuck structure's eigenvalue (upper or lower) of [[p, r], [r, s]] and its unit vector
 * with a positive largest entry (the library's orientation; the shares do not depend on it). */
static double eigen2(double p, double r, double s, int upper, double v[2])
{
    double mean = 0.5 * (p + s), rad = sqrt(0.25 * (p - s) * (p - s) + r * r);
    double lambda = upper ? mean + rad : mean - rad, n;
    v[0] = r;
    v[1] = lambda - p;
    n = hypot(v[0], v[1]);
    v[0] /= n;
    v[1] /= n;
    return lambda;
}

/* The independent shares of the file's comment at point i: share[h] the mean kinetic energy of
 * harmonic h's sampled velocity over that of the whole (M = I). */
static void sampled_shares(fricreg_hb *hb, size_t i, double share[H + 1])
{
    double a, omega, zeta, x[2 * NC];
    ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &a, &omega, &zeta, 2, NC, x), FRICREG_OK);
    const int N = 64;
    double part[H + 1] = {0}, whole = 0.0;
    for (int j = 0; j <= N; j++) {
        double t = 2.0 * pi * j / (N * omega), w = (j == 0 || j == N) ? 0.5 : 1.0;
        double v[2] = {0, 0};
        for (int h = 1; h <= H; h++) {
            double vh[2];
            for (int d = 0; d < 2; d++) {
                double ah = x[d * NC + 2 * h - 1], bh = x[d * NC + 2 * h];
                vh[d] = h * omega * (-ah * sin(h * omega * t) + bh * cos(h * omega * t));
                v[d] += vh[d];
            }
            part[h] += w * 0.5 * (vh[0] * vh[0] + vh[1] * vh[1]);
        }
        whole += w * 0.5 * (v[0] * v[0] + v[1] * v[1]);
    }
    for (int h = 0; h <= H; h++)
        share[h] = part[h] / whole;
}

/* (a) The fold model's backbone: at every point the shares add up to 1 (to 1e-12) and agree
 * with the sampled ones (to 1e-12 absolute); while the element sticks the fundamental carries
 * it all (1 to 1e-12, the third harmonic 0 to 1e-20) in mode 0 (1 to 1e-12); the third
 * harmonic's share peaks within 2 % of the upper fold's amplitude, above both ends: the stuck
 * start's 0 and a = 1e4's 1.13e-10 by more than 1e5 (measured 4.6e6: the file's comment). */
START_TEST(energy_through_the_fold)
{
    fricreg_hb *hb = model(10.0);
    const size_t np = 400;
    ck_assert_int_eq(fricreg_hb_nma_continue(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.05, 1e4, np),
                     FRICREG_OK);
    ck_assert_uint_eq(fricreg_hb_nma_special_points(hb), 2);
    double a_fold, w_fold, z_fold;
    int kf;
    size_t rf;
    ck_assert_int_eq(special(hb, 0, &a_fold, &w_fold, &z_fold, &kf, &rf), FRICREG_HB_NMA_FOLD);
    double e[H + 1], ref[H + 1], p[2], first3 = 0.0, last3 = 0.0, peak3 = -1.0, a_peak = 0.0;
    double worst_sum = 0.0, worst_ref = 0.0;
    for (size_t i = 0; i < np; i++) {
        double a, omega, zeta;
        ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &a, &omega, &zeta, 0, 0, NULL), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_nma_harmonic_energy(hb, i, H + 1, e), FRICREG_OK);
        if (i % 8 == 0 || (a > 4.3 && a < 4.7)) { /* the sampling where it matters, and a sample */
            sampled_shares(hb, i, ref);
            for (int h = 0; h <= H; h++)
                worst_ref = fmax(worst_ref, fabs(e[h] - ref[h]));
        }
        worst_sum = fmax(worst_sum, fabs(e[0] + e[1] + e[2] + e[3] - 1.0));
        ck_assert_double_eq(e[0], 0.0);
        if (i == 0) {
            first3 = e[3];
            ck_assert_double_eq_tol(e[1], 1.0, 1e-12);
            ck_assert_int_eq(fricreg_hb_nma_modal_participation(hb, i, 1, 2, p), FRICREG_OK);
            ck_assert_double_eq_tol(p[0], 1.0, 1e-12);
            ck_assert_double_eq_tol(p[1], 0.0, 1e-12);
        }
        if (i == np - 1)
            last3 = e[3];
        if (e[3] > peak3) {
            peak3 = e[3];
            a_peak = a;
        }
    }
    ck_assert_double_le(worst_sum, 1e-12);
    ck_assert_double_le(worst_ref, 1e-12);
    ck_assert_double_le(first3, 1e-20);
    ck_assert_double_gt(peak3, 1e5 * fmax(first3, last3));
    ck_assert_double_eq_tol(a_peak, a_fold, 0.02 * a_fold);
    fricreg_hb_free(hb);
}
END_TEST

/* (b) Which mode each harmonic moves, against the closed-form modes: at the point nearest the
 * upper fold the third harmonic is in mode 1 (the element's dof: above 0.999, measured
 * 1 − 3.9e-6) and the fundamental in mode 0 (above 0.99); the shares add up to 1 to 1e-12 and
 * equal (φ_r^T X_h)² / |X_h|² with φ_r from the 2x2 closed form to 1e-12. */
START_TEST(participation_closed_form)
{
    fricreg_hb *hb = model(10.0);
    const size_t np = 60;
    ck_assert_int_eq(fricreg_hb_nma_continue(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 2.0, 10.0, np),
                     FRICREG_OK);
    double phi[2][2];
    eigen2(K1 + KC, -KC, KC + K2 + 10.0, 0, phi[0]);
    eigen2(K1 + KC, -KC, KC + K2 + 10.0, 1, phi[1]);
    size_t near = 0;
    double best = INFINITY, a, omega, zeta, x[2 * NC];
    for (size_t i = 0; i < np; i++) {
        ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &a, &omega, &zeta, 0, 0, NULL), FRICREG_OK);
        if (fabs(a - 4.4324) < best) {
            best = fabs(a - 4.4324);
            near = i;
        }
    }
    ck_assert_int_eq(fricreg_hb_nma_point(hb, near, &a, &omega, &zeta, 2, NC, x), FRICREG_OK);
    for (int h = 0; h <= H; h++) {
        double p[2], q[2] = {0, 0}, norm = 0.0;
        ck_assert_int_eq(fricreg_hb_nma_modal_participation(hb, near, h, 2, p), FRICREG_OK);
        for (int c = h ? 2 * h - 1 : 0; c <= 2 * h; c++)
            for (int r = 0; r < 2; r++) {
                double proj = phi[r][0] * x[c] + phi[r][1] * x[NC + c];
                q[r] += proj * proj;
                norm += proj * proj;
            }
        if (norm > 0.0) {
            ck_assert_double_eq_tol(p[0] + p[1], 1.0, 1e-12);
            ck_assert_double_eq_tol(p[0], q[0] / norm, 1e-12);
            ck_assert_double_eq_tol(p[1], q[1] / norm, 1e-12);
        }
        if (h == 1)
            ck_assert_double_gt(p[0], 0.99);
        if (h == 3)
            ck_assert_double_gt(p[1], 0.999);
    }
    fricreg_hb_free(hb);
}
END_TEST

/* (c) The special points, folds and crossings in one list: the fold model has no crossing (3ω
 * stays above ω_1 = 3.2337 at every point: the file's comment), which is checked point by point,
 * and its two special points are its folds (harmonic 1, the backbone's mode 0); with kt = 11,
 * ω_1 = 3.3847 is crossed by 3ω once (measured a = 5.04, ω = 1.12823): the last special point,
 * after every fold in the branch's order (its S at a = 4.49, measured 4.4942 and 4.4802, the
 * upper fold first), harmonic 3, mode 1, 3ω = ω_1 of the closed form to 1e-12, and its a and ζ
 * the linear interpolation of the two stored points around it at the fraction t where 3ω
 * crosses ω_1 (the documented rule, to 1e-12). */
START_TEST(crossings)
{
    fricreg_hb *hb = model(10.0);
    double v[2], a, omega, zeta;
    int k = 0;
    size_t r = 9;
    double w1 = sqrt(eigen2(K1 + KC, -KC, KC + K2 + 10.0, 1, v));
    ck_assert_int_eq(fricreg_hb_nma_continue(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.05, 100.0, 80),
                     FRICREG_OK);
    ck_assert_uint_eq(fricreg_hb_nma_special_points(hb), 2);
    for (size_t i = 0; i < 2; i++) {
        ck_assert_int_eq(special(hb, i, &a, &omega, &zeta, &k, &r), FRICREG_HB_NMA_FOLD);
        ck_assert(k == 1 && r == 0);
    }
    for (size_t i = 0; i < 80; i++) {
        ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &a, &omega, &zeta, 0, 0, NULL), FRICREG_OK);
        ck_assert_double_gt(3.0 * omega, w1 + 0.1);
    }
    fricreg_hb_free(hb);

    hb = model(11.0);
    w1 = sqrt(eigen2(K1 + KC, -KC, KC + K2 + 11.0, 1, v));
    const size_t np = 100;
    ck_assert_int_eq(fricreg_hb_nma_continue(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.05, 1e3, np),
                     FRICREG_OK);
    size_t n = fricreg_hb_nma_special_points(hb);
    ck_assert_uint_ge(n, 3);
    double ac, wc, zc, af[2];
    ck_assert_int_eq(special(hb, n - 1, &ac, &wc, &zc, &k, &r), FRICREG_HB_NMA_CROSSING);
    ck_assert_int_eq(k, 3);
    ck_assert_uint_eq(r, 1);
    ck_assert_double_eq_tol(3.0 * wc, w1, 1e-12 * w1);
    ck_assert_double_eq_tol(ac, 5.04, 0.01 * 5.04);
    for (size_t i = 0; i + 1 < n; i++) { /* every fold before it */
        int kf = 0;
        size_t rf = 9;
        ck_assert_int_eq(special(hb, i, &a, &omega, &zeta, &kf, &rf), FRICREG_HB_NMA_FOLD);
        ck_assert(kf == 1 && rf == 0);
        ck_assert_double_lt(a, ac);
        if (i + 3 >= n) /* the S's two */
            af[i + 3 - n] = a;
        else /* the slip onset's pair: δ/φ_2 = 3.71243 (the file's comment), to 1e-4 */
            ck_assert_double_eq_tol(a, 3.71243, 1e-4 * 3.71243);
    }
    ck_assert_double_eq_tol(af[0], 4.4942, 0.01 * 4.4942);
    ck_assert_double_eq_tol(af[1], 4.4802, 0.01 * 4.4802);
    ck_assert_double_gt(af[0], af[1]);
    int brackets = 0;
    double ao = 0.0, wo = 0.0, zo = 0.0;
    for (size_t i = 0; i < np; i++) {
        ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &a, &omega, &zeta, 0, 0, NULL), FRICREG_OK);
        if (i > 0 && (3.0 * wo >= w1) != (3.0 * omega >= w1)) {
            double t = (3.0 * wo - w1) / (3.0 * wo - 3.0 * omega);
            brackets++;
            ck_assert(wc >= fmin(wo, omega) && wc <= fmax(wo, omega));
            ck_assert(ac >= fmin(ao, a) && ac <= fmax(ao, a));
            ck_assert_double_eq_tol(ac, ao + t * (a - ao), 1e-12 * ac);
            ck_assert_double_eq_tol(zc, zo + t * (zeta - zo), 1e-12 * zc);
        }
        ao = a;
        wo = omega;
        zo = zeta;
    }
    ck_assert_int_eq(brackets, 1);
    fricreg_hb_free(hb);
}
END_TEST

/* The fold model as a sparse one (compressed columns of the upper triangles). */
static fricreg_hb *sparse_model(void)
{
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(2, 1, H, &hb), FRICREG_OK);
    const int64_t pm[3] = {0, 1, 2}, im[2] = {0, 1}, pk[3] = {0, 1, 3}, ik[3] = {0, 0, 1};
    const double vm[2] = {1, 1}, vk[3] = {K1 + KC, -KC, KC + K2}, J[2] = {0, 1};
    const double kt = 10.0, mun = MUN;
    ck_assert_int_eq(fricreg_hb_set_mass_csc(hb, 2, FRICREG_SPARSE_UPPER, pm, im, vm), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness_csc(hb, 2, FRICREG_SPARSE_UPPER, pk, ik, vk),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, 2, J, &kt, &mun), FRICREG_OK);
    return hb;
}

/* A chain of n unit masses on unit springs (tridiagonal K = (2, −1)) as a sparse model, a
 * Jenkins element kt = 10, μN = 1 on dof 0. */
static fricreg_hb *sparse_chain(size_t n)
{
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(n, 1, H, &hb), FRICREG_OK);
    int64_t *p = malloc((n + 1) * sizeof *p), *i = malloc(2 * n * sizeof *i);
    double *v = malloc(2 * n * sizeof *v), *J = calloc(n, sizeof *J);
    ck_assert(p && i && v && J);
    for (size_t j = 0; j < n; j++) { /* M = I first */
        p[j] = (int64_t)j;
        i[j] = (int64_t)j;
        v[j] = 1.0;
    }
    p[n] = (int64_t)n;
    ck_assert_int_eq(fricreg_hb_set_mass_csc(hb, n, FRICREG_SPARSE_UPPER, p, i, v), FRICREG_OK);
    size_t k = 0;
    for (size_t j = 0; j < n; j++) {
        p[j] = (int64_t)k;
        if (j > 0) {
            i[k] = (int64_t)j - 1;
            v[k++] = -1.0;
        }
        i[k] = (int64_t)j;
        v[k++] = 2.0;
    }
    p[n] = (int64_t)k;
    ck_assert_int_eq(fricreg_hb_set_stiffness_csc(hb, n, FRICREG_SPARSE_UPPER, p, i, v),
                     FRICREG_OK);
    const double kt = 10.0, mun = MUN;
    J[0] = 1.0;
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, n, J, &kt, &mun), FRICREG_OK);
    free(p);
    free(i);
    free(v);
    free(J);
    return hb;
}

/* (d) A sparse model: the fold model's, at most 256 dofs, gives the dense model's shares,
 * participations and crossing (the same points by the same Newton, KLU's factors for LAPACK's:
 * to 1e-10; its modes densified); a sparse chain of 257 dofs has no modes beyond its own: no
 * crossing, no participation (FRICREG_EINVAL, nothing written), its shares still given. */
START_TEST(sparse_model_shares)
{
    fricreg_hb *hs = sparse_model(), *hd = model(10.0);
    ck_assert_int_eq(fricreg_hb_nma_continue(hs, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 2.0, 10.0, 40),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_nma_continue(hd, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 2.0, 10.0, 40),
                     FRICREG_OK);
    double es[H + 1], ed[H + 1], ps[2], pd[2];
    for (size_t i = 0; i < 40; i++) {
        ck_assert_int_eq(fricreg_hb_nma_harmonic_energy(hs, i, H + 1, es), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_nma_harmonic_energy(hd, i, H + 1, ed), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_nma_modal_participation(hs, i, 3, 2, ps), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_nma_modal_participation(hd, i, 3, 2, pd), FRICREG_OK);
        for (int h = 0; h <= H; h++)
            ck_assert_double_eq_tol(es[h], ed[h], 1e-10);
        ck_assert_double_eq_tol(ps[1], pd[1], 1e-10);
    }
    ck_assert_double_gt(es[3], 1e-6); /* a = 10 slips: the comparison is not of zeros */
    ck_assert_uint_eq(fricreg_hb_nma_special_points(hs), fricreg_hb_nma_special_points(hd));
    fricreg_hb_free(hs);
    fricreg_hb_free(hd);

    hs = sparse_chain(257);
    double e[H + 1], p[257];
    p[0] = -1.0;
    ck_assert_int_eq(fricreg_hb_nma(hs, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 1e-3, 2e-3, 2),
                     FRICREG_OK);
    ck_assert_uint_eq(fricreg_hb_nma_special_points(hs), 0);
    ck_assert_int_eq(fricreg_hb_nma_modal_participation(hs, 0, 1, 257, p), FRICREG_EINVAL);
    ck_assert_double_eq(p[0], -1.0);
    ck_assert_int_eq(fricreg_hb_nma_harmonic_energy(hs, 0, H + 1, e), FRICREG_OK);
    ck_assert_double_eq_tol(e[1], 1.0, 1e-12);
    fricreg_hb_free(hs);
}
END_TEST

/* (e) The branch's order with folds and crossings interleaved: NLvib's 3-dof chain with two
 * Jenkins elements (bench/nlvib/chain_jenkins.m, examples/python/backbone.py: unit masses and
 * springs ground-1-2-3, C = 0.02 K, kt = 20, μN = 1 at dof 1 and between dofs 1 and 2, H = 7,
 * modal damping), mode 0 from a = 0.01 to 3 by arclength, 120 points: its special points
 * (measured: 14, 8 folds and 6 crossings of k = 2 with mode 1 and k = 5 with mode 2) are mixed
 * in kind, a fold after a crossing, so the list is no concatenation by kind; each crossing lies in the stretch of the stored points whose ω brackets its own, its a
 * the linear interpolation at the same fraction t (to 1e-9), and the crossings' places, the
 * stretch's index plus t, rise along the list (the folds lie between them, placed by the
 * continuation's arclength). */
START_TEST(special_points_in_branch_order)
{
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(3, 2, 7, &hb), FRICREG_OK);
    const double M[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, K[9] = {2, -1, 0, -1, 2, -1, 0, -1, 2};
    const double C[9] = {0.04, -0.02, 0, -0.02, 0.04, -0.02, 0, -0.02, 0.04};
    const double J[6] = {1, 0, 0, -1, 1, 0}, kt[2] = {20, 20}, mun[2] = {1, 1};
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 3, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 3, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, 3, C), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 2, 3, J, kt, mun), FRICREG_OK);
    enum { NP = 120 };
    ck_assert_int_eq(fricreg_hb_nma_continue(hb, 0, FRICREG_HB_NMA_DAMPING_MODAL, 0.01, 3.0, NP),
                     FRICREG_OK);
    double pa[NP], pw[NP], zeta, last = -1.0;
    for (size_t j = 0; j < NP; j++)
        ck_assert_int_eq(fricreg_hb_nma_point(hb, j, &pa[j], &pw[j], &zeta, 0, 0, NULL),
                         FRICREG_OK);
    size_t n = fricreg_hb_nma_special_points(hb), folds = 0, crossings = 0;
    int fold_after_crossing = 0;
    for (size_t i = 0; i < n; i++) {
        double a, w, z;
        int k;
        size_t r;
        int type = special(hb, i, &a, &w, &z, &k, &r);
        if (type == FRICREG_HB_NMA_FOLD) {
            ck_assert(k == 1 && r == 0);
            fold_after_crossing |= crossings > 0;
            folds++;
            continue;
        }
        ck_assert_int_eq(type, FRICREG_HB_NMA_CROSSING);
        ck_assert(k >= 2 && k <= 7 && r >= 1 && r <= 2);
        crossings++;
        double place = -1.0;
        for (size_t j = 0; j + 1 < NP && place < 0.0; j++) {
            if (w < fmin(pw[j], pw[j + 1]) || w > fmax(pw[j], pw[j + 1]) || pw[j] == pw[j + 1])
                continue;
            double t = (w - pw[j]) / (pw[j + 1] - pw[j]);
            if (fabs(a - (pa[j] + t * (pa[j + 1] - pa[j]))) <= 1e-9 * a)
                place = (double)j + t;
        }
        ck_assert_double_ge(place, 0.0); /* found */
        ck_assert_double_ge(place, last);
        last = place;
    }
    ck_assert_uint_eq(n, 14);
    ck_assert_uint_eq(folds, 8);
    ck_assert(crossings == 6 && fold_after_crossing);
    fricreg_hb_free(hb);
}
END_TEST

/* (f) Every status of the two getters, and of the special points' getter (test_hb_nma_fold's
 * fold_getters provokes each of its NULL arguments); nothing written on failure. */
START_TEST(getters_statuses)
{
    double e[H + 1] = {-1, -1, -1, -1}, p[2] = {-1, -1}, a = -1.0, w = -1.0, z = -1.0;
    int k = -1, t = -1;
    size_t r = 7;
    ck_assert_int_eq(fricreg_hb_nma_harmonic_energy(NULL, 0, H + 1, e), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_nma_modal_participation(NULL, 0, 1, 2, p), FRICREG_ENULL);
    ck_assert_uint_eq(fricreg_hb_nma_special_points(NULL), 0);
    ck_assert_int_eq(fricreg_hb_nma_special_point(NULL, 0, &t, &a, &w, &z, &k, &r), FRICREG_ENULL);
    fricreg_hb *hb = model(10.0);
    /* no backbone yet */
    ck_assert_int_eq(fricreg_hb_nma_harmonic_energy(hb, 0, H + 1, e), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma_modal_participation(hb, 0, 1, 2, p), FRICREG_EINVAL);
    ck_assert_uint_eq(fricreg_hb_nma_special_points(hb), 0);
    ck_assert_int_eq(fricreg_hb_nma_special_point(hb, 0, &t, &a, &w, &z, &k, &r), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 1.0, 4.0, 4), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_nma_harmonic_energy(hb, 0, H + 1, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_nma_harmonic_energy(hb, 0, H, e), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_hb_nma_harmonic_energy(hb, 4, H + 1, e), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma_modal_participation(hb, 0, 1, 2, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_nma_modal_participation(hb, 0, 1, 3, p), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_hb_nma_modal_participation(hb, 0, H + 1, 2, p), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma_modal_participation(hb, 0, -1, 2, p), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma_modal_participation(hb, 4, 1, 2, p), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma_special_point(hb, 0, &t, &a, &w, &z, NULL, &r), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_nma_special_point(hb, 0, &t, &a, &w, &z, &k, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_nma_special_point(hb, 0, &t, &a, &w, &z, &k, &r), FRICREG_EINVAL);
    ck_assert_double_eq(e[0], -1.0);
    ck_assert_double_eq(p[0], -1.0);
    ck_assert(t == -1 && k == -1 && r == 7 && a == -1.0 && w == -1.0 && z == -1.0);
    /* the model changed since the backbone */
    const double K[4] = {K1 + KC, -KC, -KC, KC + K2 + 0.1};
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_nma_harmonic_energy(hb, 0, H + 1, e), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma_modal_participation(hb, 0, 1, 2, p), FRICREG_EINVAL);
    ck_assert_double_eq(e[0], -1.0);
    ck_assert_double_eq(p[0], -1.0);
    fricreg_hb_free(hb);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("hb_nma_energy");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, energy_through_the_fold);
    tcase_add_test(tc, participation_closed_form);
    tcase_add_test(tc, crossings);
    tcase_add_test(tc, sparse_model_shares);
    tcase_add_test(tc, special_points_in_branch_order);
    tcase_add_test(tc, getters_statuses);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
