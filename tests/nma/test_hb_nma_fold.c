/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_nma_fold.c — Check suite for the backbone by pseudo-arclength continuation
 * (fricreg_hb_nma_continue, its folds as special points: fricreg_hb_nma_special_points,
 * fricreg_hb_nma_special_point; fricreg_hb.h) on a backbone that folds in the amplitude: an
 * internal resonance through the third harmonic.
 *
 * The model: two unit masses, dof 1 grounded by k1 = 1, the two coupled by kc = 1/4, dof 2
 * grounded by k2 = 1/5 and by a Jenkins element kt = 10, mu N = 1 (J = [0 1]), no viscous
 * damping. Stuck, K_0 = [[5/4, −1/4], [−1/4, 10.45]]: mode 0 (mostly dof 1) at ω_0 = 1.11499,
 * mode 1 (dof 2) at 3.2337, the ratio 2.90. Mode 0 moves dof 2 by φ_2 = 0.0272 of its modal
 * amplitude, so the element slips from a = δ/φ_2 = 3.68 (δ = mu N/kt); slipping, it softens
 * dof 2 towards k2 + kc = 0.45. Near the 3:1 ratio the element's third harmonic drives mode 1
 * (3 ω = 3.34 there, 3 % above mode 1's 3.2337: near, never crossing, as test_hb_nma_energy
 * measures: so every special point of this model is a fold, for any H, since 2 ω < ω_1 < 3 ω all
 * along) and the backbone of mode 0 folds in the amplitude (at
 * a ≈ 4.43, 20 % above the slip onset: found first by a scan of this family, where
 * fricreg_hb_nma stops with "line search found no decrease" at a = 4.4325).
 *
 * Where the numbers come from:
 * - the stuck limit: ω = sqrt(λ_0(K_0)), ζ = 0 (the linear mode; the 2x2 eigenvalue closed form);
 * - the fully slipped limit: the element's force is bounded by mu N, so as a → ∞ the mode tends
 *   to the mode ψ of K_s = [[5/4, −1/4], [−1/4, 9/20]] of dof-1 shape, ω² → λ_1(K_s) = (1.7 +
 *   sqrt(0.89))/2, and by the energy balance of the extended periodic motion concept (Krack
 *   2015, Eq. 9: the negative damping's work ξ ω π c² makes up the element's loop 4 mu N (A −
 *   δ)), ζ = ξ/(2ω) = 4 mu N (A − δ)/(2π ω² c²), c = a/(φ·ψ) the amplitude along ψ (the modal
 *   amplitude a is measured along the stuck mode φ) and A = c |ψ_2| the element's;
 * - every point of the branch, on the three stretches of the S too: an independent evaluation of
 *   the equations M x'' − ξ M x' + K x + J^T f(J x) = 0 by harmonic balance, the element's force
 *   from its own return map sampled 2^14 times a period over two periods (the second one's
 *   Fourier coefficients by the trapezoidal rule: the force is continuous and piecewise smooth,
 *   so the error is O(N^-2) ≈ 1e-8 of mu N), with the amplitude condition φ^T M X_1 = a;
 * - where the backbone does not fold (below the slip onset and up to a = 4.4) the natural-
 *   parameter march, fricreg_hb_nma, is a computation of the same points at the same
 *   amplitude: the two agree to Newton's tolerance. */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_hb.h"

#define KC 0.25
#define K1 1.0
#define K2 0.2
#define KT 10.0
#define MUN 1.0

static const double pi = 3.14159265358979323846;

static fricreg_hb *model(int harmonics)
{
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(2, 1, harmonics, &hb), FRICREG_OK);
    const double M[4] = {1, 0, 0, 1}, K[4] = {K1 + KC, -KC, -KC, KC + K2}, J[2] = {0, 1};
    const double kt = KT, mun = MUN;
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 2, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, 2, J, &kt, &mun), FRICREG_OK);
    return hb;
}

/* The model's special points (every one a fold: the file's comment): their number, each
 * checked to be a fold of the backbone's mode 0 at harmonic 1. */
static size_t folds(fricreg_hb *hb)
{
    size_t n = fricreg_hb_nma_special_points(hb);
    for (size_t i = 0; i < n; i++) {
        int type = 0, harmonic = 0;
        size_t mode = 9;
        double a, omega, zeta;
        ck_assert_int_eq(fricreg_hb_nma_special_point(hb, i, &type, &a, &omega, &zeta, &harmonic,
                                                      &mode),
                         FRICREG_OK);
        ck_assert_int_eq(type, FRICREG_HB_NMA_FOLD);
        ck_assert_int_eq(harmonic, 1);
        ck_assert_uint_eq(mode, 0);
    }
    return n;
}

/* Fold i's a, ω, ζ (special point i: every one a fold). */
static int fold(fricreg_hb *hb, size_t i, double *a, double *omega, double *zeta)
{
    int type, harmonic;
    size_t mode;
    return fricreg_hb_nma_special_point(hb, i, &type, a, omega, zeta, &harmonic, &mode);
}

/* The symmetric 2x2 [[p, r], [r, s]]'s eigenvalue (upper or lower) and its unit eigenvector. */
static double eigen2(double p, double r, double s, int upper, double v[2])
{
    double mean = 0.5 * (p + s), rad = sqrt(0.25 * (p - s) * (p - s) + r * r);
    double lambda = upper ? mean + rad : mean - rad, n;
    v[0] = r;
    v[1] = lambda - p;
    n = hypot(v[0], v[1]);
    v[0] /= n;
    v[1] /= n;
    if (v[0] < 0.0) {
        v[0] = -v[0];
        v[1] = -v[1];
    }
    return lambda;
}

/* The largest residual of the equations at a stored point (relative to |K X|), with its
 * amplitude condition's relative error: X from fricreg_hb_nma_point, the element's force by
 * its return map sampled n times a period. */
static double independent_residual(fricreg_hb *hb, size_t i, int H)
{
    size_t nc = 2 * (size_t)H + 1;
    double a, omega, zeta, x[2 * 31];
    ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &a, &omega, &zeta, 2, nc, x), FRICREG_OK);
    double xi = 2.0 * zeta * omega, phi[2];
    eigen2(K1 + KC + 0.0, -KC, KC + K2 + KT, 0, phi);
    /* the element on dof 2: two periods of its return map, the second projected */
    const size_t n = 1u << 14;
    double f = 0.0, slip = 0.0, F[2 * 31] = {0};
    for (size_t k = 0; k <= 2 * n; k++) {
        double th = 2.0 * pi * (double)k / (double)n, u = x[nc];
        for (int h = 1; h <= H; h++)
            u += x[nc + 2 * h - 1] * cos(h * th) + x[nc + 2 * h] * sin(h * th);
        f = KT * (u - slip);
        if (fabs(f) > MUN) {
            slip = u - copysign(MUN, f) / KT;
            f = copysign(MUN, f);
        }
        if (k < n)
            continue;
        double wgt = (k == n || k == 2 * n) ? 0.5 : 1.0;
        F[0] += wgt * f / (double)n;
        for (int h = 1; h <= H; h++) {
            F[2 * h - 1] += wgt * 2.0 * f * cos(h * th) / (double)n;
            F[2 * h] += wgt * 2.0 * f * sin(h * th) / (double)n;
        }
    }
    const double K[4] = {K1 + KC, -KC, -KC, KC + K2};
    double worst = 0.0, scale = 0.0;
    for (size_t c = 0; c < nc; c++)
        scale = fmax(scale, fabs(K[0] * x[c]) + fabs(K[1] * x[nc + c]));
    for (int h = 0; h <= H; h++) {
        for (int d = 0; d < 2; d++) { /* dof d's cosine and sine rows */
            double w = h * omega, ac = h ? x[d * nc + 2 * h - 1] : x[d * nc],
                   bs = h ? x[d * nc + 2 * h] : 0.0;
            double kac = K[2 * d] * (h ? x[2 * h - 1] : x[0]) +
                         K[2 * d + 1] * (h ? x[nc + 2 * h - 1] : x[nc]);
            double kbs = h ? K[2 * d] * x[2 * h] + K[2 * d + 1] * x[nc + 2 * h] : 0.0;
            double rc = kac - w * w * ac - xi * w * bs + (d == 1 ? F[h ? 2 * h - 1 : 0] : 0.0);
            double rs = kbs - w * w * bs + xi * w * ac + (d == 1 && h ? F[2 * h] : 0.0);
            worst = fmax(worst, fmax(fabs(rc), fabs(rs)) / scale);
        }
    }
    double s_cos = phi[0] * x[1] + phi[1] * x[nc + 1], s_sin = phi[0] * x[2] + phi[1] * x[nc + 2];
    return fmax(worst, fmax(fabs(s_cos - a), fabs(s_sin)) / a);
}

/* (a) H = 3 from a = 0.05 (stuck) to 1e4 (slipping over all but 2e-5 of the element's travel):
 * the continuation passes the S and reports its two folds, the upper then the lower, at
 * a = 4.4324 (ω = 1.114375, ζ = 0.00303) and 4.4168 (ω = 1.114841, ζ = 0.00851) (this
 * computation's numbers, to 2e-3: a regression check, the folds located by interpolation
 * between the branch's points); the written points go back in a between them (a fold is the
 * sign change of d(log a)/ds, and the S is 0.35 % wide in a). */
START_TEST(fold_reported)
{
    fricreg_hb *hb = model(3);
    const size_t np = 400;
    ck_assert_int_eq(fricreg_hb_nma_continue(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.05, 1e4, np),
                     FRICREG_OK);
    ck_assert_uint_eq(fricreg_hb_nma_points(hb), np);
    ck_assert_uint_eq(folds(hb), 2);
    double a1, w1, z1, a2, w2, z2;
    ck_assert_int_eq(fold(hb, 0, &a1, &w1, &z1), FRICREG_OK);
    ck_assert_int_eq(fold(hb, 1, &a2, &w2, &z2), FRICREG_OK);
    ck_assert_double_eq_tol(a1, 4.4324, 2e-3 * 4.4324);
    ck_assert_double_eq_tol(a2, 4.4168, 2e-3 * 4.4168);
    ck_assert(a1 > a2);
    /* between the folds the damping ratio triples: 0.0030 at the upper fold, 0.0085 at the lower */
    ck_assert(z2 > 2.0 * z1);
    /* the written points: increasing in a, then decreasing (the middle stretch), then increasing;
     * in each of the three stretches a point with a between the folds */
    int runs = 1, inside[3] = {0, 0, 0};
    double prev = 0.0, a, omega, zeta;
    for (size_t i = 0; i < np; i++) {
        ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &a, &omega, &zeta, 0, 0, NULL), FRICREG_OK);
        if (i > 0 && (a < prev) != (runs == 2))
            runs++;
        ck_assert_int_le(runs, 3);
        if (a > a2 && a < a1)
            inside[runs - 1]++;
        prev = a;
    }
    ck_assert_int_eq(runs, 3);
    ck_assert(inside[0] > 0 && inside[1] > 0 && inside[2] > 0);
    fricreg_hb_free(hb);
}
END_TEST

/* (b) Every written point, the three stretches of the S included, solves the equations by the
 * independent evaluation of the file's comment to 1e-6 (its quadrature error is about 1e-8:
 * measured 1.5e-8; a linear interpolation between the branch's points instead of a solution
 * would be off by the branch's curvature times the step², far above). */
START_TEST(every_point_solves)
{
    fricreg_hb *hb = model(3);
    const size_t np = 120;
    ck_assert_int_eq(fricreg_hb_nma_continue(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 2.0, 10.0, np),
                     FRICREG_OK);
    ck_assert_uint_eq(folds(hb), 2);
    double worst = 0.0;
    for (size_t i = 0; i < np; i++)
        worst = fmax(worst, independent_residual(hb, i, 3));
    ck_assert_double_le(worst, 1e-6);
    fricreg_hb_free(hb);
}
END_TEST

/* (c) The limits in closed form: the first point, stuck, is the linear mode (ω = sqrt(λ_0(K_0))
 * to 1e-12, ζ = 0); the last, at a = 1e4, the fully slipped one: ω² = λ_1(K_s) to 1e-6 and ζ
 * the energy balance's to 1e-4 (the element's stuck stretches near the reversals and the
 * higher harmonics are not in the limit: measured 1.9e-7 of ω² and 3.1e-6 of ζ). */
START_TEST(limits_closed_form)
{
    fricreg_hb *hb = model(3);
    const size_t np = 30;
    ck_assert_int_eq(fricreg_hb_nma_continue(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.05, 1e4, np),
                     FRICREG_OK);
    double a, omega, zeta, phi[2], psi[2];
    double l0 = eigen2(K1 + KC, -KC, KC + K2 + KT, 0, phi);
    ck_assert_int_eq(fricreg_hb_nma_point(hb, 0, &a, &omega, &zeta, 0, 0, NULL), FRICREG_OK);
    ck_assert_double_eq_tol(a, 0.05, 1e-15);
    ck_assert_double_eq_tol(omega, sqrt(l0), 1e-12 * sqrt(l0));
    ck_assert_double_eq_tol(zeta, 0.0, 1e-12);
    double ls = eigen2(K1 + KC, -KC, KC + K2, 1, psi);
    ck_assert_int_eq(fricreg_hb_nma_point(hb, np - 1, &a, &omega, &zeta, 0, 0, NULL), FRICREG_OK);
    ck_assert_double_eq_tol(a, 1e4, 1e-9 * 1e4);
    double c = a / fabs(phi[0] * psi[0] + phi[1] * psi[1]), A = c * fabs(psi[1]);
    double zeta_s = 4.0 * MUN * (A - MUN / KT) / (2.0 * pi * ls * c * c);
    ck_assert_double_eq_tol(omega * omega, ls, 1e-6 * ls);
    ck_assert_double_eq_tol(zeta, zeta_s, 1e-4 * zeta_s);
    fricreg_hb_free(hb);
}
END_TEST

/* (d) Where the backbone does not fold, the continuation's points are the march's: at a = 4.4
 * (between the slip onset and the folds, the end of both) the two agree to Newton's tolerance
 * (1e-10, relative to the amplitude): ω to 1e-9 relative, ζ = 9.0e-4 to 1e-10 absolute (ξ is
 * fixed by the amplitude rows, to the tolerance times ω; measured: 2e-13 of ω, 1.0e-12 of ζ,
 * from different iterates: the march's secant in log a, the continuation's tangent). */
START_TEST(march_agrees_before_fold)
{
    fricreg_hb *hb = model(3);
    double am, wm, zm, ac, wc, zc;
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.05, 4.4, 12),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_nma_point(hb, 11, &am, &wm, &zm, 0, 0, NULL), FRICREG_OK);
    ck_assert_uint_eq(folds(hb), 0);
    ck_assert_int_eq(fricreg_hb_nma_continue(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.05, 4.4, 12),
                     FRICREG_OK);
    ck_assert_uint_eq(folds(hb), 0);
    ck_assert_int_eq(fricreg_hb_nma_point(hb, 11, &ac, &wc, &zc, 0, 0, NULL), FRICREG_OK);
    ck_assert_double_eq_tol(ac, am, 1e-12 * am);
    ck_assert_double_eq_tol(wc, wm, 1e-9 * wm);
    ck_assert_double_eq_tol(zc, zm, 1e-10);
    /* the march stops in the S: that is why the continuation exists */
    ck_assert_int_ne(fricreg_hb_nma(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.05, 100.0, 50),
                     FRICREG_OK);
    fricreg_hb_free(hb);
}
END_TEST

/* (e) H = 7, the setting: the same S, its folds within 1 % of H = 3's amplitude. */
START_TEST(fold_h7)
{
    fricreg_hb *hb = model(7);
    ck_assert_int_eq(fricreg_hb_nma_continue(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.05, 100.0, 50),
                     FRICREG_OK);
    ck_assert_uint_eq(folds(hb), 2);
    double a, omega, zeta;
    ck_assert_int_eq(fold(hb, 0, &a, &omega, &zeta), FRICREG_OK);
    ck_assert_double_eq_tol(a, 4.4324, 0.01 * 4.4324);
    fricreg_hb_free(hb);
}
END_TEST

/* (f) H = 15: the same S, its folds within 1 % of H = 3's amplitude (measured 4.4560 and
 * 4.4427; test_hb_nma_shooting checks its frequencies against the time domain). */
START_TEST(fold_h15)
{
    fricreg_hb *hb = model(15);
    ck_assert_int_eq(fricreg_hb_nma_continue(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.05, 100.0, 50),
                     FRICREG_OK);
    ck_assert_uint_eq(folds(hb), 2);
    double a, omega, zeta, a_lower;
    ck_assert_int_eq(fold(hb, 0, &a, &omega, &zeta), FRICREG_OK);
    ck_assert_double_eq_tol(a, 4.4324, 0.01 * 4.4324);
    ck_assert_int_eq(fold(hb, 1, &a_lower, &omega, &zeta), FRICREG_OK);
    ck_assert_double_lt(a_lower, a);
    fricreg_hb_free(hb);
}
END_TEST

/* (g) The special points' getters: every status, one NULL argument at a time (the message
 * names it), i out of range (none before a backbone, and one past the two folds after it);
 * nothing written on failure. */
START_TEST(fold_getters)
{
    double a = -1.0, omega = -1.0, zeta = -1.0;
    int type = -1, harmonic = -1;
    size_t mode = 7;
    ck_assert_uint_eq(fricreg_hb_nma_special_points(NULL), 0);
    ck_assert_int_eq(fricreg_hb_nma_special_point(NULL, 0, &type, &a, &omega, &zeta, &harmonic,
                                                  &mode),
                     FRICREG_ENULL);
    fricreg_hb *hb = model(3);
    const char *names[6] = {"type", "amplitude", "omega", "zeta", "harmonic", "mode"};
    for (int j = 0; j < 6; j++) {
        ck_assert_int_eq(fricreg_hb_nma_special_point(hb, 0, j == 0 ? NULL : &type,
                                                      j == 1 ? NULL : &a, j == 2 ? NULL : &omega,
                                                      j == 3 ? NULL : &zeta,
                                                      j == 4 ? NULL : &harmonic,
                                                      j == 5 ? NULL : &mode),
                         FRICREG_ENULL);
        ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), names[j]));
    }
    ck_assert_uint_eq(fricreg_hb_nma_special_points(hb), 0);
    ck_assert_int_eq(fricreg_hb_nma_special_point(hb, 0, &type, &a, &omega, &zeta, &harmonic,
                                                  &mode),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma_continue(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 2.0, 10.0, 40),
                     FRICREG_OK);
    ck_assert_uint_eq(folds(hb), 2);
    ck_assert_int_eq(fricreg_hb_nma_special_point(hb, 2, &type, &a, &omega, &zeta, &harmonic,
                                                  &mode),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma_special_point(hb, SIZE_MAX, &type, &a, &omega, &zeta, &harmonic,
                                                  &mode),
                     FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "2 special points"));
    ck_assert(a == -1.0 && omega == -1.0 && zeta == -1.0);
    ck_assert(type == -1 && harmonic == -1 && mode == 7);
    ck_assert_int_eq(fricreg_hb_nma_continue(hb, 2, FRICREG_HB_NMA_DAMPING_MATRIX, 0.05, 1.0, 4),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma_continue(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 1.0, 0.5, 4),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_nma_continue(NULL, 0, 0, 0.05, 1.0, 4), FRICREG_ENULL);
    fricreg_hb_free(hb);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("hb_nma_fold");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, fold_reported);
    tcase_add_test(tc, every_point_solves);
    tcase_add_test(tc, limits_closed_form);
    tcase_add_test(tc, march_agrees_before_fold);
    tcase_add_test(tc, fold_h7);
    tcase_add_test(tc, fold_h15);
    tcase_add_test(tc, fold_getters);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
