/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_iwan.c — Check suite for the Iwan elements (fricreg_iwan.h): parallel Jenkins sliders,
 * their backbone, Masing's rule and dissipation against closed forms, Segalman's
 * four-parameter model and its discretization, the normal load with lift-off, bad input.
 *
 * Where the numbers come from:
 *   - backbone: from rest, under monotone loading, slider s sticks while k_s u <= phi_s and
 *     then holds phi_s, so F(u) = sum_s min(k_s u, phi_s) and dF/du = sum over stuck sliders
 *     of k_s (each slider is fricreg_jenkins' element, exact in 1-D on a monotone path).
 *   - Masing: unloading from u_r, slider s, at +phi_s or at k_s u_r, sticks again and reaches
 *     -phi_s after a travel 2 phi_s/k_s: F(u_r) - F(u_r - v) = sum_s min(k_s v, 2 phi_s)
 *     = 2 F(v/2).
 *   - dissipation per cycle of amplitude A: slider s with phi_s/k_s < A draws the Jenkins
 *     parallelogram, 4 phi_s (A - phi_s/k_s) (test_jenkins.c); the others none. Sampling the
 *     cycle at every kink (u = +-(A - 2 phi_s/k_s)) makes f piecewise linear between samples
 *     and the trapezoid rule exact: agreement to rounding.
 *   - Segalman (fricreg_iwan.h): K_T = int rho, F_S = int phi rho; the continuous backbone
 *     F(u) = K_T u - R u^(chi+2)/((chi+1)(chi+2)) for u <= phi_max (F_S beyond), the
 *     continuous dissipation per cycle D(A) = 4 R A^(chi+3)/((chi+2)(chi+3)) for
 *     A <= phi_max (integrate 4 phi (A - phi) against R phi^chi from 0 to A).
 *   - lift-off: N = max(0, N0 + kn g), slip forces phi_s N/N0; separated: f = 0, tangents 0,
 *     sliders at u; df/dg = sum over slipping sliders of phi_s (kn/N0) sign.
 *   - sums near the double range: each slider's force is finite (|f_s| <= phi_s), so only
 *     the element's sum can overflow; where every slider slips f = sum_s phi_s, where every
 *     one sticks dF/du = sum_s k_s (the backbone above), compared with DBL_MAX. */
#include <check.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_iwan.h"

#define SENTINEL (-777.125)
#define NS_USER 5
static const double PI = 3.14159265358979323846;
/* five user sliders, slip displacements phi/k = 0.1258, 0.57, 1.3538, 0.0143, 2.0571 */
static const double K5[NS_USER] = {2.385, 1.25, 0.8125, 3.5, 0.4375},
                    P5[NS_USER] = {0.3, 0.7125, 1.1, 0.05, 0.9};

static fricreg_iwan *make_user(int dim)
{
    fricreg_iwan *iw = NULL;
    ck_assert_int_eq(fricreg_iwan_create(dim, 1, NS_USER, &iw), FRICREG_OK);
    ck_assert_int_eq(fricreg_iwan_set_params(iw, 1, NS_USER, K5, P5), FRICREG_OK);
    return iw;
}

/* The backbone of sliders k[ns], phi[ns] at u >= 0 and its slope. */
static double backbone(const double *k, const double *phi, size_t ns, double u, double *slope)
{
    double f = 0.0, t = 0.0;
    for (size_t s = 0; s < ns; s++) {
        if (k[s] * u <= phi[s]) {
            f += k[s] * u;
            t += k[s];
        } else {
            f += phi[s];
        }
    }
    if (slope)
        *slope = t;
    return f;
}

START_TEST(backbone_user_sliders)
{
    fricreg_iwan *iw = make_user(1);
    for (int i = 1; i <= 300; i++) {
        double u = 0.00813 * i, f, t, slope;
        ck_assert_int_eq(fricreg_iwan_trial(iw, 1, &u, &f, &t), FRICREG_OK);
        ck_assert_int_eq(fricreg_iwan_commit(iw), FRICREG_OK);
        double F = backbone(K5, P5, NS_USER, u, &slope);
        ck_assert_double_eq_tol(f, F, 1e-14 * F);
        ck_assert_double_eq(t, slope); /* no sample sits on a kink */
    }
    /* fully slipped: the sum of the slip forces, tangent 0 */
    double u = 2.5, f, t;
    ck_assert_int_eq(fricreg_iwan_trial(iw, 1, &u, &f, &t), FRICREG_OK);
    ck_assert_double_eq_tol(f, 3.0625, 1e-15);
    ck_assert_double_eq(t, 0.0);
    fricreg_iwan_free(iw);
}
END_TEST

START_TEST(masing_unloading)
{
    fricreg_iwan *iw = make_user(1);
    const double ur = 1.4375;
    double fr, f;
    ck_assert_int_eq(fricreg_iwan_trial(iw, 1, &ur, &fr, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_iwan_commit(iw), FRICREG_OK);
    ck_assert_double_eq_tol(fr, backbone(K5, P5, NS_USER, ur, NULL), 1e-14);
    for (int i = 1; i <= 200; i++) { /* down to -ur, a step and a commit at a time */
        double v = 2.0 * ur * i / 200.0, u = ur - v;
        ck_assert_int_eq(fricreg_iwan_trial(iw, 1, &u, &f, NULL), FRICREG_OK);
        ck_assert_int_eq(fricreg_iwan_commit(iw), FRICREG_OK);
        ck_assert_double_eq_tol(fr - f, 2.0 * backbone(K5, P5, NS_USER, v / 2.0, NULL), 1e-13);
    }
    fricreg_iwan_free(iw);
}
END_TEST

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* One element's dissipation per cycle at amplitude A, and the force at u = A on the
 * stabilized loop (*famp): from rest, load to A, then A -> -A -> A, sampled at every kink and
 * at 16 evenly spaced points of each branch, a trial and a commit per sample; the trapezoid
 * rule on f du over the closed loop (exact: f is linear between samples, up to rounding).
 * ns <= 512. */
static double cycle(fricreg_iwan *iw, double A, double *famp)
{
    size_t ns = fricreg_iwan_sliders(iw);
    static double k[512], phi[512], pts[512 + 17];
    ck_assert_uint_le(ns, 512);
    ck_assert_int_eq(fricreg_iwan_get_params(iw, 1, ns, k, phi), FRICREG_OK);
    ck_assert_int_eq(fricreg_iwan_reset(iw), FRICREG_OK);
    double f, u = A, D = 0.0, up = A, fp;
    ck_assert_int_eq(fricreg_iwan_trial(iw, 1, &u, &fp, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_iwan_commit(iw), FRICREG_OK);
    for (int branch = 0; branch < 2; branch++) {
        double sgn = branch == 0 ? -1.0 : 1.0; /* travel direction */
        size_t m = 0;
        for (size_t s = 0; s < ns; s++) /* the kinks: a travel v = 2 phi/k into the branch */
            if (2.0 * phi[s] / k[s] < 2.0 * A)
                pts[m++] = 2.0 * phi[s] / k[s];
        for (int i = 1; i <= 16; i++)
            pts[m++] = 2.0 * A * i / 16.0;
        qsort(pts, m, sizeof pts[0], cmp_double);
        for (size_t i = 0; i < m; i++) {
            u = -sgn * A + sgn * pts[i];
            ck_assert_int_eq(fricreg_iwan_trial(iw, 1, &u, &f, NULL), FRICREG_OK);
            ck_assert_int_eq(fricreg_iwan_commit(iw), FRICREG_OK);
            D += 0.5 * (f + fp) * (u - up);
            up = u;
            fp = f;
        }
    }
    *famp = fp;
    return D;
}

/* The closed form of the discrete model's dissipation per cycle: sum_s 4 phi_s (A - phi_s/k_s)
 * over the sliders with phi_s/k_s < A. */
static double dissipation_closed(const double *k, const double *phi, size_t ns, double A)
{
    double D = 0.0;
    for (size_t s = 0; s < ns; s++)
        if (phi[s] / k[s] < A)
            D += 4.0 * phi[s] * (A - phi[s] / k[s]);
    return D;
}

START_TEST(dissipation_user_sliders)
{
    fricreg_iwan *iw = make_user(1);
    const double amp[4] = {0.03125, 0.3125, 1.0625, 2.75};
    for (int i = 0; i < 4; i++) {
        double famp, D = cycle(iw, amp[i], &famp);
        double exact = dissipation_closed(K5, P5, NS_USER, amp[i]);
        printf("iwan user sliders: A = %.4f  D = %.15f  closed form %.15f\n", amp[i], D, exact);
        ck_assert_double_eq_tol(D, exact, 1e-13 * exact);
        ck_assert_double_eq_tol(famp, backbone(K5, P5, NS_USER, amp[i], NULL), 1e-14);
    }
    fricreg_iwan_free(iw);
}
END_TEST

/* The tangent of element 0 of iw (normal displacement g if with_g) against centred
 * differences of the trial force, in u and in g. */
static void check_tangent(fricreg_iwan *iw, int dim, const double *u, double g, int with_g)
{
    double f[2], t[4], tg[2], up[2], um[2], fp[2], fm[2], gp, gm, scale = 0.0;
    ck_assert_int_eq(fricreg_iwan_trial_normal(iw, 1, u, &g, f, NULL, t, tg), FRICREG_OK);
    for (int i = 0; i < NS_USER; i++)
        scale += K5[i];
    for (int b = 0; b < dim; b++) {
        double h = 1e-7;
        memcpy(up, u, sizeof up);
        memcpy(um, u, sizeof um);
        up[b] += h;
        um[b] -= h;
        ck_assert_int_eq(fricreg_iwan_trial_normal(iw, 1, up, &g, fp, NULL, NULL, NULL),
                         FRICREG_OK);
        ck_assert_int_eq(fricreg_iwan_trial_normal(iw, 1, um, &g, fm, NULL, NULL, NULL),
                         FRICREG_OK);
        for (int a = 0; a < dim; a++) {
            double fd = (fp[a] - fm[a]) / (up[b] - um[b]);
            ck_assert_msg(fabs(fd - t[dim * a + b]) <= 1e-6 * scale,
                          "dim %d: df%d/du%d = %.12g, difference %.12g", dim, a, b, t[dim * a + b],
                          fd);
        }
    }
    if (!with_g)
        return;
    gp = g + 1e-7;
    gm = g - 1e-7;
    ck_assert_int_eq(fricreg_iwan_trial_normal(iw, 1, u, &gp, fp, NULL, NULL, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_iwan_trial_normal(iw, 1, u, &gm, fm, NULL, NULL, NULL), FRICREG_OK);
    for (int a = 0; a < dim; a++) {
        double fd = (fp[a] - fm[a]) / (gp - gm);
        ck_assert_msg(fabs(fd - tg[a]) <= 1e-6 * scale, "dim %d: df%d/dg = %.12g, difference %.12g",
                      dim, a, tg[a], fd);
    }
}

START_TEST(tangent_against_differences)
{
    for (int dim = 1; dim <= 2; dim++) {
        for (int normal = 0; normal <= 1; normal++) {
            fricreg_iwan *iw = make_user(dim);
            const double n0 = 1.625, kn = 3.25;
            if (normal)
                ck_assert_int_eq(fricreg_iwan_set_normal(iw, 1, &n0, &kn), FRICREG_OK);
            const double u0[2] = {0.8125, -0.4375};
            double f[2], w[2 * NS_USER];
            ck_assert_int_eq(fricreg_iwan_trial(iw, 1, u0, f, NULL), FRICREG_OK);
            ck_assert_int_eq(fricreg_iwan_commit(iw), FRICREG_OK);
            ck_assert_int_eq(fricreg_iwan_get_slider(iw, 1, NS_USER, w), FRICREG_OK);
            int tried = 0;
            for (int k = 0; k < 40; k++) {
                double ang = 0.37 + 0.611 * k, rad = 0.05 + 0.0731 * k, g = 0.125 - 0.01 * k;
                double u[2] = {u0[0] + rad * cos(ang), u0[1] + (dim == 2 ? rad * sin(ang) : 0)};
                double scale = normal ? fmax(0.0, n0 + kn * g) / n0 : 1.0;
                /* away from every slider's kink |k (u - w)| = phi scale (and from lift-off) */
                int near = normal && fabs(n0 + kn * g) < 1e-3;
                for (int s = 0; s < NS_USER; s++) {
                    double d[2] = {u[0] - w[dim * s], dim == 2 ? u[1] - w[dim * s + 1] : 0.0};
                    double r = K5[s] * hypot(d[0], d[1]) - P5[s] * scale;
                    near |= fabs(r) < 1e-4;
                }
                if (near)
                    continue;
                check_tangent(iw, dim, u, normal ? g : 0.0, normal);
                tried++;
            }
            ck_assert_int_ge(tried, 30);
            fricreg_iwan_free(iw);
        }
    }
}
END_TEST

START_TEST(trial_keeps_committed_state)
{
    for (int dim = 1; dim <= 2; dim++) {
        fricreg_iwan *iw = make_user(dim);
        const double u1[2] = {0.9, -0.3}, u2[2] = {-0.2, 0.45};
        double f1[2], f2[2], t1[4], t2[4], w0[2 * NS_USER], w1[2 * NS_USER];
        size_t nw = (size_t)dim * NS_USER * sizeof w0[0];
        ck_assert_int_eq(fricreg_iwan_trial(iw, 1, u1, f1, NULL), FRICREG_OK);
        ck_assert_int_eq(fricreg_iwan_commit(iw), FRICREG_OK);
        ck_assert_int_eq(fricreg_iwan_get_slider(iw, 1, NS_USER, w0), FRICREG_OK);
        ck_assert_int_eq(fricreg_iwan_trial(iw, 1, u2, f1, t1), FRICREG_OK);
        ck_assert_int_eq(fricreg_iwan_trial(iw, 1, u2, f2, t2), FRICREG_OK);
        ck_assert_mem_eq(f1, f2, (size_t)dim * sizeof f1[0]);
        ck_assert_mem_eq(t1, t2, (size_t)(dim * dim) * sizeof t1[0]);
        ck_assert_int_eq(fricreg_iwan_get_slider(iw, 1, NS_USER, w1), FRICREG_OK);
        ck_assert_mem_eq(w0, w1, nw);
        /* a setter discards the pending trial */
        ck_assert_int_eq(fricreg_iwan_set_params(iw, 1, NS_USER, K5, P5), FRICREG_OK);
        ck_assert_int_eq(fricreg_iwan_commit(iw), FRICREG_OK);
        ck_assert_int_eq(fricreg_iwan_get_slider(iw, 1, NS_USER, w1), FRICREG_OK);
        ck_assert_mem_eq(w0, w1, nw);
        /* f = sum_s k_s (u - w_s) after the commit, every slider stuck or slipped */
        ck_assert_int_eq(fricreg_iwan_trial(iw, 1, u2, f1, NULL), FRICREG_OK);
        ck_assert_int_eq(fricreg_iwan_commit(iw), FRICREG_OK);
        ck_assert_int_eq(fricreg_iwan_get_slider(iw, 1, NS_USER, w1), FRICREG_OK);
        for (int a = 0; a < dim; a++) {
            double sum = 0.0;
            for (int s = 0; s < NS_USER; s++)
                sum += K5[s] * (u2[a] - w1[dim * s + a]);
            ck_assert_double_eq_tol(f1[a], sum, 1e-14);
        }
        /* f may alias u; reset puts the sliders at 0 */
        double u[2] = {u2[0], u2[1]};
        ck_assert_int_eq(fricreg_iwan_reset(iw), FRICREG_OK);
        ck_assert_int_eq(fricreg_iwan_trial(iw, 1, u2, f1, NULL), FRICREG_OK);
        ck_assert_int_eq(fricreg_iwan_trial(iw, 1, u, u, NULL), FRICREG_OK);
        ck_assert_mem_eq(u, f1, (size_t)dim * sizeof u[0]);
        ck_assert_int_eq(fricreg_iwan_get_slider(iw, 1, NS_USER, w1), FRICREG_OK);
        for (int s = 0; s < dim * NS_USER; s++)
            ck_assert_double_eq(w1[s], 0.0);
        ck_assert_uint_eq(fricreg_iwan_size(iw), 1);
        ck_assert_uint_eq(fricreg_iwan_sliders(iw), NS_USER);
        ck_assert_int_eq(fricreg_iwan_dim(iw), dim);
        fricreg_iwan_free(iw);
    }
}
END_TEST

/* ---- Segalman's model ------------------------------------------------------------------- */

struct seg {
    double fs, kt, chi, beta, phimax, R, S;
};

static struct seg seg_params(double fs, double kt, double chi, double beta)
{
    struct seg p = {fs, kt, chi, beta, 0, 0, 0};
    double r = (chi + 1.0) / (chi + 2.0);
    p.phimax = fs * (1.0 + beta) / (kt * (beta + r));
    p.R = fs * (chi + 1.0) / (pow(p.phimax, chi + 2.0) * (beta + r));
    p.S = fs * beta / (p.phimax * (beta + r));
    return p;
}

static double seg_backbone(const struct seg *p, double u)
{
    if (u >= p->phimax)
        return p->fs;
    return p->kt * u - p->R * pow(u, p->chi + 2.0) / ((p->chi + 1.0) * (p->chi + 2.0));
}

static double seg_dissipation(const struct seg *p, double A)
{
    return 4.0 * p->R * pow(A, p->chi + 3.0) / ((p->chi + 2.0) * (p->chi + 3.0));
}

static fricreg_iwan *make_segalman(const struct seg *p, size_t ns, double resolution)
{
    fricreg_iwan *iw = NULL;
    ck_assert_int_eq(fricreg_iwan_create(1, 1, ns, &iw), FRICREG_OK);
    ck_assert_int_eq(fricreg_iwan_set_segalman(iw, 1, &p->fs, &p->kt, &p->chi, &p->beta,
                                               resolution),
                     FRICREG_OK);
    return iw;
}

START_TEST(segalman_stiffness_and_slip_force)
{
    const double chis[3] = {-0.5, -0.2, -0.8125}, betas[3] = {0.0, 0.35, 2.385};
    const size_t nss[4] = {1, 2, 37, 400};
    static double k[400], phi[400];
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++)
            for (int c = 0; c < 4; c++) {
                if (betas[b] > 0.0 && nss[c] == 1)
                    continue;
                struct seg p = seg_params(2.385, 1.7e3, chis[a], betas[b]);
                fricreg_iwan *iw = make_segalman(&p, nss[c], 1e-6);
                ck_assert_int_eq(fricreg_iwan_get_params(iw, 1, nss[c], k, phi), FRICREG_OK);
                double ksum = 0.0, fsum = 0.0;
                for (size_t s = 0; s < nss[c]; s++) {
                    ck_assert(k[s] > 0.0 && phi[s] > 0.0);
                    if (s > 0 && (betas[b] == 0.0 || s + 1 < nss[c])) /* increasing slip disp. */
                        ck_assert(phi[s] / k[s] > phi[s - 1] / k[s - 1]);
                    ksum += k[s];
                    fsum += phi[s];
                }
                ck_assert_double_eq_tol(ksum, p.kt, 1e-13 * p.kt);
                ck_assert_double_eq_tol(fsum, p.fs, 1e-13 * p.fs);
                if (betas[b] > 0.0) { /* the delta: S, slipping at phi_max */
                    ck_assert_double_eq_tol(k[nss[c] - 1], p.S, 1e-13 * p.S);
                    ck_assert_double_eq_tol(phi[nss[c] - 1] / k[nss[c] - 1], p.phimax,
                                            1e-13 * p.phimax);
                }
                /* macroslip: beyond phi_max the element holds F_S */
                double u = 1.0001 * p.phimax, f, t;
                ck_assert_int_eq(fricreg_iwan_trial(iw, 1, &u, &f, &t), FRICREG_OK);
                ck_assert_double_eq_tol(f, p.fs, 1e-13 * p.fs);
                ck_assert_double_eq(t, 0.0);
                /* and its initial stiffness is K_T */
                u = 1e-9 * p.phimax;
                ck_assert_int_eq(fricreg_iwan_trial(iw, 1, &u, &f, &t), FRICREG_OK);
                ck_assert_double_eq_tol(t, p.kt, 1e-13 * p.kt);
                fricreg_iwan_free(iw);
            }
}
END_TEST

/* Largest |F_discrete(u) - F(u)|/F_S over 2000 points of u in [1e-4, 1.2] phi_max, the
 * discrete backbone being a trial from rest. */
static double backbone_error(const struct seg *p, size_t ns, double resolution)
{
    fricreg_iwan *iw = make_segalman(p, ns, resolution);
    double worst = 0.0;
    for (int i = 0; i < 2000; i++) {
        double u = p->phimax * (1e-4 + 1.2 * i / 2000.0), f;
        ck_assert_int_eq(fricreg_iwan_trial(iw, 1, &u, &f, NULL), FRICREG_OK);
        worst = fmax(worst, fabs(f - seg_backbone(p, u)) / p->fs);
    }
    fricreg_iwan_free(iw);
    return worst;
}

START_TEST(segalman_backbone_convergence)
{
    const double chis[2] = {-0.5, -0.2};
    const size_t nss[4] = {50, 100, 200, 400};
    for (int a = 0; a < 2; a++) {
        struct seg p = seg_params(2.385, 1.7e3, chis[a], 0.35);
        double err[4];
        for (int c = 0; c < 4; c++) {
            err[c] = backbone_error(&p, nss[c], 1e-8);
            printf("iwan segalman chi = %g: ns = %3zu  backbone error / F_S = %.3e\n", chis[a],
                   nss[c], err[c]);
        }
        double order = log(err[0] / err[3]) / log((double)nss[3] / (double)nss[0]);
        printf("iwan segalman chi = %g: backbone order %.3f\n", chis[a], order);
        ck_assert_msg(order > 1.8 && order < 2.2, "order %g, expected 2", order);
        ck_assert_double_le(err[2], 1.5e-3);
    }
}
END_TEST

/* Least-squares slope of y against x. */
static double slope(const double *x, const double *y, int m)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (int k = 0; k < m; k++) {
        sx += x[k];
        sy += y[k];
        sxx += x[k] * x[k];
        sxy += x[k] * y[k];
    }
    return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

START_TEST(segalman_microslip_dissipation)
{
    const double chis[2] = {-0.5, -0.2};
    const size_t ns = 200;
    static double k[200], phi[200];
    for (int a = 0; a < 2; a++) {
        struct seg p = seg_params(2.385, 1.7e3, chis[a], 0.35);
        fricreg_iwan *iw = make_segalman(&p, ns, 1e-8);
        ck_assert_int_eq(fricreg_iwan_get_params(iw, 1, ns, k, phi), FRICREG_OK);
        double lnF[11], lnD[11], worst = 0.0;
        for (int i = 0; i < 11; i++) { /* amplitudes 1e-6 .. 1e-5 phi_max */
            double A = p.phimax * pow(10.0, -6.0 + 0.1 * i), famp;
            double D = cycle(iw, A, &famp);
            double exact = dissipation_closed(k, phi, ns, A);
            /* the loop integral of f ~ F0 over a travel ~ A encloses D << F0 A: rounding
             * relative to D grows as F0 A/D (up to 1.3e5 here; measured at most 5e-16 of it) */
            ck_assert_double_eq_tol(D, exact, 1e-14 * famp * A);
            worst = fmax(worst, fabs(D / seg_dissipation(&p, A) - 1.0));
            lnF[i] = log(famp);
            lnD[i] = log(D);
        }
        double sl = slope(lnF, lnD, 11);
        printf("iwan segalman chi = %g, ns = %zu: dissipation slope %.5f (3 + chi = %g), "
               "largest |D/D_continuous - 1| = %.3e\n",
               chis[a], ns, sl, 3.0 + chis[a], worst);
        ck_assert_double_le(fabs(sl - (3.0 + chis[a])), 0.01);
        ck_assert_double_le(worst, 0.01);
        fricreg_iwan_free(iw);
    }
}
END_TEST

/* ---- Lift-off --------------------------------------------------------------------------- */

START_TEST(lift_off)
{
    for (int dim = 1; dim <= 2; dim++) {
        fricreg_iwan *iw = make_user(dim), *ref = make_user(dim);
        const double n0 = 1.625, kn = 3.25;
        ck_assert_int_eq(fricreg_iwan_set_normal(iw, 1, &n0, &kn), FRICREG_OK);
        /* in contact at g = 0: the element without a normal law, to the bit */
        for (int i = 0; i < 30; i++) {
            double u[2] = {1.3 * sin(0.41 * i), 0.7 * cos(0.29 * i)}, g = 0.0;
            double f[2], fr[2], t[4], tr[4], nf;
            ck_assert_int_eq(fricreg_iwan_trial_normal(iw, 1, u, &g, f, &nf, t, NULL), FRICREG_OK);
            ck_assert_int_eq(fricreg_iwan_trial(ref, 1, u, fr, tr), FRICREG_OK);
            ck_assert_mem_eq(f, fr, (size_t)dim * sizeof f[0]);
            ck_assert_mem_eq(t, tr, (size_t)(dim * dim) * sizeof t[0]);
            ck_assert_double_eq(nf, n0);
            ck_assert_int_eq(fricreg_iwan_commit(iw), FRICREG_OK);
            ck_assert_int_eq(fricreg_iwan_commit(ref), FRICREG_OK);
        }
        /* g = -0.25: N = 1.625 - 0.8125 = 0.8125, half the slip forces: fully slipped at u
         * far away, f = sum phi/2 along u - w */
        double g = -0.25, u[2] = {40.0, 0.0}, f[2], nf, t[4], tg[2];
        ck_assert_int_eq(fricreg_iwan_reset(iw), FRICREG_OK);
        ck_assert_int_eq(fricreg_iwan_trial_normal(iw, 1, u, &g, f, &nf, t, tg), FRICREG_OK);
        ck_assert_double_eq_tol(nf, 0.8125, 1e-15);
        ck_assert_double_eq_tol(f[0], 3.0625 / 2.0, 1e-14);
        ck_assert_double_eq_tol(tg[0], 3.0625 * kn / n0, 1e-13);
        /* separated (N0 + kn g < 0): f, tangents and N are 0, the sliders follow u */
        g = -0.5625;
        u[0] = 0.6875;
        u[1] = dim == 2 ? -0.3125 : 0.0;
        for (int a = 0; a < 4; a++)
            t[a] = SENTINEL;
        ck_assert_int_eq(fricreg_iwan_trial_normal(iw, 1, u, &g, f, &nf, t, tg), FRICREG_OK);
        for (int a = 0; a < dim; a++) {
            ck_assert_double_eq(f[a], 0.0);
            ck_assert_double_eq(tg[a], 0.0);
        }
        for (int a = 0; a < dim * dim; a++)
            ck_assert_double_eq(t[a], 0.0);
        ck_assert_double_eq(nf, 0.0);
        ck_assert_int_eq(fricreg_iwan_commit(iw), FRICREG_OK);
        double w[2 * NS_USER];
        ck_assert_int_eq(fricreg_iwan_get_slider(iw, 1, NS_USER, w), FRICREG_OK);
        for (int s = 0; s < NS_USER; s++)
            for (int a = 0; a < dim; a++)
                ck_assert_double_eq(w[dim * s + a], u[a]);
        /* contact again at u + du: every slider sticks from where it was released */
        double du = 0.001, u2[2] = {u[0] + du, u[1]};
        g = 0.0;
        ck_assert_int_eq(fricreg_iwan_trial_normal(iw, 1, u2, &g, f, &nf, t, tg), FRICREG_OK);
        ck_assert_double_eq_tol(f[0], 8.385 * du, 1e-15);
        ck_assert_double_eq_tol(t[0], 8.385, 1e-15);
        ck_assert_double_eq(tg[0], 0.0);
        fricreg_iwan_free(iw);
        fricreg_iwan_free(ref);
    }
}
END_TEST

/* ---- Bad input -------------------------------------------------------------------------- */

START_TEST(bad_input)
{
    fricreg_iwan *iw = (fricreg_iwan *)&iw, *keep = iw;
    ck_assert_int_eq(fricreg_iwan_create(1, 1, 1, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_iwan_create(3, 1, 1, &iw), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_iwan_create(1, 0, 1, &iw), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_iwan_create(1, 1, 0, &iw), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_iwan_create(2, 1 << 20, SIZE_MAX / 1024, &iw), FRICREG_EINVAL);
    ck_assert_ptr_eq(iw, keep);

    iw = make_user(2);
    double k[NS_USER], phi[NS_USER], out[16];
    memcpy(k, K5, sizeof k);
    memcpy(phi, P5, sizeof phi);
    ck_assert_int_eq(fricreg_iwan_set_params(NULL, 1, NS_USER, k, phi), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_iwan_set_params(iw, 1, NS_USER, NULL, phi), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_iwan_errcode(iw), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_iwan_set_params(iw, 2, NS_USER, k, phi), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_iwan_set_params(iw, 1, NS_USER - 1, k, phi), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_iwan_errcode(iw), FRICREG_ESIZE);
    const double kbad[4] = {0.0, -1.0, NAN, INFINITY};
    const int kcode[4] = {FRICREG_EINVAL, FRICREG_EINVAL, FRICREG_ENONFINITE, FRICREG_ENONFINITE};
    for (int i = 0; i < 4; i++) {
        k[3] = kbad[i];
        ck_assert_int_eq(fricreg_iwan_set_params(iw, 1, NS_USER, k, phi), kcode[i]);
        ck_assert_str_ne(fricreg_iwan_errmsg(iw), "");
    }
    k[3] = K5[3];
    phi[1] = -1e-300;
    ck_assert_int_eq(fricreg_iwan_set_params(iw, 1, NS_USER, k, phi), FRICREG_EINVAL);
    phi[1] = NAN;
    ck_assert_int_eq(fricreg_iwan_set_params(iw, 1, NS_USER, k, phi), FRICREG_ENONFINITE);
    /* Segalman's parameters */
    double fs = 2.385, kt = 1.7e3, chi = -0.5, beta = 0.35;
    const double chibad[4] = {-1.0, -1.5, 1.5, NAN};
    const int chicode[4] = {FRICREG_EINVAL, FRICREG_EINVAL, FRICREG_EINVAL, FRICREG_ENONFINITE};
    for (int i = 0; i < 4; i++)
        ck_assert_int_eq(fricreg_iwan_set_segalman(iw, 1, &fs, &kt, &chibad[i], &beta, 1e-6),
                         chicode[i]);
    const double neg = -2.385, zero = 0.0, inf = INFINITY;
    ck_assert_int_eq(fricreg_iwan_set_segalman(iw, 1, &neg, &kt, &chi, &beta, 1e-6),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_iwan_set_segalman(iw, 1, &fs, &zero, &chi, &beta, 1e-6),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_iwan_set_segalman(iw, 1, &fs, &inf, &chi, &beta, 1e-6),
                     FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_iwan_set_segalman(iw, 1, &fs, &kt, &chi, &neg, 1e-6), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_iwan_set_segalman(iw, 1, &fs, &kt, &chi, &beta, 1.0), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_iwan_set_segalman(iw, 1, &fs, &kt, &chi, &beta, 0.0), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_iwan_set_segalman(iw, 1, &fs, &kt, &chi, &beta, NAN),
                     FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_iwan_set_segalman(iw, 1, NULL, &kt, &chi, &beta, 1e-6), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_iwan_set_segalman(iw, 2, &fs, &kt, &chi, &beta, 1e-6), FRICREG_ESIZE);
    /* extreme parameters: a slider's stiffness underflows to 0 (K_T = the least subnormal),
     * phi_max overflows (F_S/K_T = 1e318: the delta's slip force is Inf) */
    const double kt_tiny = 4.9e-324, fs_huge = 1e308, kt_small = 1e-10;
    ck_assert_int_eq(fricreg_iwan_set_segalman(iw, 1, &fs, &kt_tiny, &chi, &beta, 1e-6),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_iwan_set_segalman(iw, 1, &fs_huge, &kt_small, &chi, &beta, 1e-6),
                     FRICREG_ENONFINITE);
    fricreg_iwan *one = NULL;
    ck_assert_int_eq(fricreg_iwan_create(1, 1, 1, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_iwan_set_segalman(one, 1, &fs, &kt, &chi, &beta, 1e-6),
                     FRICREG_EINVAL); /* beta > 0 needs a delta slider and another */
    ck_assert_int_eq(fricreg_iwan_set_segalman(one, 1, &fs, &kt, &chi, &zero, 7.0),
                     FRICREG_OK); /* one slider: k = K_T, phi = F_S; resolution unused */
    ck_assert_int_eq(fricreg_iwan_get_params(one, 1, 1, k, phi), FRICREG_OK);
    ck_assert_double_eq_tol(k[0], kt, 1e-13 * kt);
    ck_assert_double_eq_tol(phi[0], fs, 1e-13 * fs);
    fricreg_iwan_free(one);
    /* normal law */
    double n0 = 1.5, kn = 2.0;
    ck_assert_int_eq(fricreg_iwan_set_normal(iw, 1, &zero, &kn), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_iwan_set_normal(iw, 1, &n0, &neg), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_iwan_set_normal(iw, 1, &inf, &kn), FRICREG_ENONFINITE);
    const double tiny = 4.9e-324, huge = 1e308;
    ck_assert_int_eq(fricreg_iwan_set_normal(iw, 1, &tiny, &huge), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_iwan_set_normal(iw, 1, NULL, &kn), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_iwan_set_normal(iw, 0, &n0, &kn), FRICREG_ESIZE);
    /* nothing changed: the user sliders of make_user, no normal law (a stick: K sum u) */
    const double u[2] = {0.001, 0.0};
    ck_assert_int_eq(fricreg_iwan_trial(iw, 1, u, out, NULL), FRICREG_OK);
    ck_assert_double_eq_tol(out[0], 8.385 * 0.001, 1e-15);
    for (int i = 0; i < 16; i++)
        out[i] = SENTINEL;
    ck_assert_int_eq(fricreg_iwan_trial(NULL, 1, u, out, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_iwan_trial(iw, 1, NULL, out, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_iwan_trial(iw, 1, u, NULL, out), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_iwan_trial(iw, 2, u, out, out + 4), FRICREG_ESIZE);
    const double unan[2] = {0.1, NAN}, uhuge[2] = {1.5e308, 1.5e308};
    ck_assert_int_eq(fricreg_iwan_trial(iw, 1, unan, out, out + 4), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_iwan_trial(iw, 1, uhuge, out, out + 4), FRICREG_ENONFINITE);
    double g = NAN;
    ck_assert_int_eq(fricreg_iwan_trial_normal(iw, 1, u, &g, out, out + 2, out + 3, out + 7),
                     FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_iwan_trial_normal(iw, 1, u, NULL, out, NULL, NULL, NULL),
                     FRICREG_ENULL);
    ck_assert_int_eq(fricreg_iwan_set_normal(iw, 1, &n0, &huge), FRICREG_OK);
    g = 1e300; /* N0 + kn g overflows */
    ck_assert_int_eq(fricreg_iwan_trial_normal(iw, 1, u, &g, out, out + 2, out + 3, out + 7),
                     FRICREG_ENONFINITE);
    ck_assert_str_ne(fricreg_iwan_errmsg(iw), "");
    for (int i = 0; i < 16; i++)
        ck_assert_double_eq(out[i], SENTINEL);
    double w[2 * NS_USER];
    ck_assert_int_eq(fricreg_iwan_get_slider(NULL, 1, NS_USER, w), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_iwan_get_slider(iw, 1, NS_USER, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_iwan_get_slider(iw, 1, 1, w), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_iwan_get_params(iw, 1, NS_USER, NULL, phi), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_iwan_get_params(iw, 0, NS_USER, k, phi), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_iwan_commit(NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_iwan_reset(NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_iwan_errcode(NULL), FRICREG_OK);
    ck_assert_str_eq(fricreg_iwan_errmsg(NULL), "NULL Iwan elements");
    char buf[8];
    size_t len = fricreg_iwan_errmsg_copy(iw, buf, sizeof buf);
    ck_assert_uint_eq(len, strlen(fricreg_iwan_errmsg(iw)));
    ck_assert_uint_eq(strlen(buf), 7);
    ck_assert_uint_eq(fricreg_iwan_size(NULL), 0);
    ck_assert_uint_eq(fricreg_iwan_sliders(NULL), 0);
    ck_assert_int_eq(fricreg_iwan_dim(NULL), 0);
    fricreg_iwan_free(iw);
    fricreg_iwan_free(NULL);
}
END_TEST

/* The sliders' sums overflow: two sliders of k = 1e300, phi = 1e308 at u = 1e10 both slip
 * (k u = 1e310 > phi), f = 2e308 > DBL_MAX; FRICREG_OK with f = inf until the sums were
 * checked. Now FRICREG_ENONFINITE, recorded with a message, the caller's arrays and the trial
 * state untouched; a sum that stays finite (1e308 + 0.5e308 = 1.5e308 < DBL_MAX) still
 * passes; and a tangent that overflows (two stuck sliders of k = 1e308: 2e308) fails the call
 * only when the tangent is asked for. */
START_TEST(sums_overflow)
{
    fricreg_iwan *iw = NULL;
    ck_assert_int_eq(fricreg_iwan_create(1, 1, 2, &iw), FRICREG_OK);
    const double k[2] = {1e300, 1e300}, phi[2] = {1e308, 1e308}, u[1] = {1e10}, g[1] = {0.0};
    ck_assert_int_eq(fricreg_iwan_set_params(iw, 1, 2, k, phi), FRICREG_OK);
    double f[1] = {SENTINEL}, t[1] = {SENTINEL}, nf[1] = {SENTINEL}, tg[1] = {SENTINEL};
    ck_assert_int_eq(fricreg_iwan_trial(iw, 1, u, f, t), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_iwan_errcode(iw), FRICREG_ENONFINITE);
    ck_assert_ptr_nonnull(strstr(fricreg_iwan_errmsg(iw), "overflows"));
    ck_assert_int_eq(fricreg_iwan_trial(iw, 1, u, f, NULL), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_iwan_trial_normal(iw, 1, u, g, f, nf, t, tg), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_iwan_trial_normal(iw, 1, u, g, f, NULL, NULL, NULL),
                     FRICREG_ENONFINITE);
    ck_assert_double_eq(f[0], SENTINEL);
    ck_assert_double_eq(t[0], SENTINEL);
    ck_assert_double_eq(nf[0], SENTINEL);
    ck_assert_double_eq(tg[0], SENTINEL);
    /* the failed trials left no trial state: commit keeps the sliders at 0 */
    double w[2] = {SENTINEL, SENTINEL};
    ck_assert_int_eq(fricreg_iwan_commit(iw), FRICREG_OK);
    ck_assert_int_eq(fricreg_iwan_get_slider(iw, 1, 2, w), FRICREG_OK);
    ck_assert_double_eq(w[0], 0.0);
    ck_assert_double_eq(w[1], 0.0);
    /* a finite sum: both slip, f = phi_0 + phi_1, the sliders at u - phi_s/k_s */
    const double phi2[2] = {1e308, 0.5e308};
    ck_assert_int_eq(fricreg_iwan_set_params(iw, 1, 2, k, phi2), FRICREG_OK);
    ck_assert_int_eq(fricreg_iwan_trial(iw, 1, u, f, t), FRICREG_OK);
    ck_assert_double_eq(f[0], 1e308 + 0.5e308);
    ck_assert_double_eq(t[0], 0.0); /* 1-D slip: no stiffness */
    /* the tangent's sum: stuck (k u = 1e-2 <= phi = 1) at u = 1e-310, dF/du = 2e308 */
    const double kbig[2] = {1e308, 1e308}, one[2] = {1.0, 1.0}, us[1] = {1e-310};
    ck_assert_int_eq(fricreg_iwan_set_params(iw, 1, 2, kbig, one), FRICREG_OK);
    t[0] = SENTINEL;
    ck_assert_int_eq(fricreg_iwan_trial(iw, 1, us, f, t), FRICREG_ENONFINITE);
    ck_assert_double_eq(t[0], SENTINEL);
    ck_assert_int_eq(fricreg_iwan_trial(iw, 1, us, f, NULL), FRICREG_OK);
    ck_assert_double_eq(f[0], 1e308 * 1e-310 + 1e308 * 1e-310);
    /* df/dg: kn/N0 = 1e300 (finite, accepted) times phi = 1e10 on a slipping slider */
    const double n0[1] = {1.0}, kn[1] = {1e300}, k1[2] = {1.0, 1.0}, p1[2] = {1e10, 1.0};
    const double ubig[1] = {1e11};
    ck_assert_int_eq(fricreg_iwan_set_params(iw, 1, 2, k1, p1), FRICREG_OK);
    ck_assert_int_eq(fricreg_iwan_set_normal(iw, 1, n0, kn), FRICREG_OK);
    tg[0] = SENTINEL;
    ck_assert_int_eq(fricreg_iwan_trial_normal(iw, 1, ubig, g, f, nf, t, tg), FRICREG_ENONFINITE);
    ck_assert_double_eq(tg[0], SENTINEL);
    ck_assert_int_eq(fricreg_iwan_trial_normal(iw, 1, ubig, g, f, nf, t, NULL), FRICREG_OK);
    ck_assert_double_eq(f[0], 1e10 + 1.0);
    fricreg_iwan_free(iw);
}
END_TEST

static Suite *iwan_suite(void)
{
    Suite *s = suite_create("iwan");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, backbone_user_sliders);
    tcase_add_test(tc, masing_unloading);
    tcase_add_test(tc, dissipation_user_sliders);
    tcase_add_test(tc, tangent_against_differences);
    tcase_add_test(tc, trial_keeps_committed_state);
    tcase_add_test(tc, segalman_stiffness_and_slip_force);
    tcase_add_test(tc, segalman_backbone_convergence);
    tcase_add_test(tc, segalman_microslip_dissipation);
    tcase_add_test(tc, lift_off);
    tcase_add_test(tc, bad_input);
    tcase_add_test(tc, sums_overflow);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(iwan_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
