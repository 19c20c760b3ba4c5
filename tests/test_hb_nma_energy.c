/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_nma_energy.c — Check suite for what a backbone point is made of
 * (fricreg_hb_nma_harmonic_energy, fricreg_hb_nma_modal_participation; fricreg_hb.h) and where
 * a harmonic k ω crosses another linear mode's frequency (fricreg_hb_nma_crossings,
 * fricreg_hb_nma_crossing), on tests/test_hb_nma_fold.c's two-mass model: dof 1 grounded by
 * k1 = 1, coupled by kc = 1/4 to dof 2, grounded by k2 = 1/5 and a Jenkins element kt, μN = 1,
 * unit masses, no viscous damping, H = 3. With kt = 10 its backbone (mode 0) folds twice in the
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
 * at a = 5.04, ω = 1.12823 (after that model's S, at a = 4.49). */
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
    ck_assert_uint_eq(fricreg_hb_nma_folds(hb), 2);
    double a_fold, w_fold, z_fold;
    ck_assert_int_eq(fricreg_hb_nma_fold(hb, 0, &a_fold, &w_fold, &z_fold), FRICREG_OK);
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

/* (c) The crossings: the fold model has none (3ω stays above ω_1 = 3.2337 at every point: the
 * file's comment), which is checked point by point; with kt = 11, ω_1 = 3.3847 is crossed by
 * 3ω once (measured a = 5.04, ω = 1.12823): harmonic 3, mode 1, 3ω = ω_1 of the closed form
 * to 1e-12, ω and a within the two stored points around it. */
START_TEST(crossings)
{
    fricreg_hb *hb = model(10.0);
    double v[2], a, omega, zeta;
    double w1 = sqrt(eigen2(K1 + KC, -KC, KC + K2 + 10.0, 1, v));
    ck_assert_int_eq(fricreg_hb_nma_continue(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.05, 100.0, 80),
                     FRICREG_OK);
    ck_assert_uint_eq(fricreg_hb_nma_folds(hb), 2);
    ck_assert_uint_eq(fricreg_hb_nma_crossings(hb), 0);
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
    ck_assert_uint_eq(fricreg_hb_nma_crossings(hb), 1);
    int k = 0;
    size_t r = 9;
    double ac, wc;
    ck_assert_int_eq(fricreg_hb_nma_crossing(hb, 0, &k, &r, &ac, &wc), FRICREG_OK);
    ck_assert_int_eq(k, 3);
    ck_assert_uint_eq(r, 1);
    ck_assert_double_eq_tol(3.0 * wc, w1, 1e-12 * w1);
    ck_assert_double_eq_tol(ac, 5.04, 0.01 * 5.04);
    int brackets = 0;
    double ao = 0.0, wo = 0.0;
    for (size_t i = 0; i < np; i++) {
        ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &a, &omega, &zeta, 0, 0, NULL), FRICREG_OK);
        if (i > 0 && (3.0 * wo >= w1) != (3.0 * omega >= w1)) {
            brackets++;
            ck_assert(wc >= fmin(wo, omega) && wc <= fmax(wo, omega));
            ck_assert(ac >= fmin(ao, a) && ac <= fmax(ao, a));
        }
        ao = a;
        wo = omega;
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
    ck_assert_uint_eq(fricreg_hb_nma_crossings(hs), fricreg_hb_nma_crossings(hd));
    fricreg_hb_free(hs);
    fricreg_hb_free(hd);

    hs = sparse_chain(257);
    double e[H + 1], p[257];
    p[0] = -1.0;
    ck_assert_int_eq(fricreg_hb_nma(hs, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 1e-3, 2e-3, 2),
                     FRICREG_OK);
    ck_assert_uint_eq(fricreg_hb_nma_crossings(hs), 0);
    ck_assert_int_eq(fricreg_hb_nma_modal_participation(hs, 0, 1, 257, p), FRICREG_EINVAL);
    ck_assert_double_eq(p[0], -1.0);
    ck_assert_int_eq(fricreg_hb_nma_harmonic_energy(hs, 0, H + 1, e), FRICREG_OK);
    ck_assert_double_eq_tol(e[1], 1.0, 1e-12);
    fricreg_hb_free(hs);
}
END_TEST

/* (e) Every status of the four getters; nothing written on failure. */
START_TEST(getters_statuses)
{
    double e[H + 1] = {-1, -1, -1, -1}, p[2] = {-1, -1}, a = -1.0, w = -1.0;
    int k = -1;
    size_t r = 7;
    ck_assert_int_eq(fricreg_hb_nma_harmonic_energy(NULL, 0, H + 1, e), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_nma_modal_participation(NULL, 0, 1, 2, p), FRICREG_ENULL);
    ck_assert_uint_eq(fricreg_hb_nma_crossings(NULL), 0);
    ck_assert_int_eq(fricreg_hb_nma_crossing(NULL, 0, &k, &r, &a, &w), FRICREG_ENULL);
    fricreg_hb *hb = model(10.0);
    /* no backbone yet */
    ck_assert_int_eq(fricreg_hb_nma_harmonic_energy(hb, 0, H + 1, e), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma_modal_participation(hb, 0, 1, 2, p), FRICREG_EINVAL);
    ck_assert_uint_eq(fricreg_hb_nma_crossings(hb), 0);
    ck_assert_int_eq(fricreg_hb_nma_crossing(hb, 0, &k, &r, &a, &w), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 1.0, 4.0, 4), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_nma_harmonic_energy(hb, 0, H + 1, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_nma_harmonic_energy(hb, 0, H, e), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_hb_nma_harmonic_energy(hb, 4, H + 1, e), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma_modal_participation(hb, 0, 1, 2, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_nma_modal_participation(hb, 0, 1, 3, p), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_hb_nma_modal_participation(hb, 0, H + 1, 2, p), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma_modal_participation(hb, 0, -1, 2, p), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma_modal_participation(hb, 4, 1, 2, p), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma_crossing(hb, 0, NULL, &r, &a, &w), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_nma_crossing(hb, 0, &k, &r, &a, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_nma_crossing(hb, 0, &k, &r, &a, &w), FRICREG_EINVAL);
    ck_assert_double_eq(e[0], -1.0);
    ck_assert_double_eq(p[0], -1.0);
    ck_assert(k == -1 && r == 7 && a == -1.0 && w == -1.0);
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
    tcase_add_test(tc, getters_statuses);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
