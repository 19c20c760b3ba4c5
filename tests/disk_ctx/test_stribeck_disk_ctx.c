/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_stribeck_disk_ctx.c — Check suite for static > kinetic (Stribeck) friction in the 2-D
 * context (fricreg_disk_ctx_set_stribeck, fricreg_stribeck.h).
 *
 * Where the numbers come from:
 *   - the scalar 2-D law fricreg_stribeck_disk_eval (checked against closed forms in
 *     test_stribeck.c): with isotropic uncoupled blocks w_i I the context must give its numbers
 *     at f_eq,i = -a_free,i/w_i; with a dense W whose diagonal blocks are isotropic, the coupled
 *     law's defining property (fricreg_disk_ctx.h: each f_i is the W_ii-metric projection, here
 *     Euclidean) is that f_i is the scalar law at f_eq,i = -(a_free,i + sum_{j != i} W_ij f_j)/w_i,
 *     formed here from the returned f;
 *   - fricreg_disk_ctx_set_bounds(fk): fs = fk must give its bits (forces and tangent);
 *   - Coulomb's stick problem at rest: a_free = -W f* with |f*_i| < fs_i holds f = f* at zero
 *     acceleration; scaled by s, the first contact breaks away at s = min_i fs_i/|f*_i|;
 *   - central differences for the tangent (two step sizes must agree: no kink in the step), and
 *     a one-sided difference at rest along the direction the contact slides;
 *   - continuity: the largest jump of f over steps of 1e-9 eps, as test_disk_ctx.c measures it.
 * Inputs come from a fixed xorshift generator: every run checks the same points. */
#include <check.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_disk_ctx.h"
#include "fricreg_stribeck.h"
#include "disk_ctx_checks.h"
#include "random.h"

#define MAXM 4
#define N2 (2 * MAXM)

static uint64_t rng_state = 0x9e3779b97f4a7c15u;
static double uniform(double lo, double hi)
{
    return xorshift64star_uniform(&rng_state, lo, hi);
}

/* A random SPD W of order 2m whose diagonal blocks are isotropic: B B^T/n + shift I, each
 * diagonal block then raised to (its largest eigenvalue) I, which adds a semidefinite matrix. */
static void isotropic_spd(size_t m, double shift, double W[])
{
    size_t n = 2 * m;
    double work[N2 * N2];
    random_gram_spd(xorshift64star_uniform, &rng_state, n, shift, work, W);
    for (size_t i = 0; i < m; i++) {
        double *b = W + 2 * i * n + 2 * i, a = b[0], c = b[1], d = b[n + 1];
        double top = 0.5 * (a + d) + hypot(0.5 * (a - d), c);
        b[0] = b[n + 1] = top;
        b[1] = b[n] = 0.0;
    }
}

struct params {
    double fs[MAXM], fk[MAXM], vs[MAXM], delta[MAXM];
};

static void random_params(size_t m, double eps, struct params *p)
{
    static const double deltas[3] = {0.5, 1.0, 2.0};
    for (size_t i = 0; i < m; i++) {
        p->fs[i] = uniform(0.2, 2.0);
        p->fk[i] = p->fs[i] * uniform(0.2, 0.9);
        p->vs[i] = eps * uniform(0.2, 5.0);
        p->delta[i] = deltas[(int)uniform(0.0, 2.999)];
    }
}

/* zdot: at rest, in the band or sliding (up to 3 eps); a_free: O(fs). */
static void random_state(size_t m, double eps, double zdot[], double afree[])
{
    for (size_t i = 0; i < m; i++) {
        double pick = uniform(0.0, 1.0);
        double speed = pick < 0.2   ? 0.0
                       : pick < 0.7 ? uniform(0.0, 1.0) * eps
                                    : uniform(1.0, 3.0) * eps;
        double th = uniform(0.0, 6.3);
        zdot[2 * i] = speed * cos(th);
        zdot[2 * i + 1] = speed * sin(th);
        afree[2 * i] = uniform(-2.5, 2.5);
        afree[2 * i + 1] = uniform(-2.5, 2.5);
    }
}

static fricreg_disk_ctx *make_ctx(size_t m, double eps, const struct params *p, const double W[])
{
    fricreg_disk_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_disk_ctx_create(m, &ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_disk_ctx_set_law(ctx, FRICREG_DISK_QUINN, eps), FRICREG_OK);
    if (W != NULL)
        ck_assert_msg(fricreg_disk_ctx_set_coupling_dense(ctx, m, W) == FRICREG_OK, "%s",
                      fricreg_disk_ctx_errmsg(ctx));
    ck_assert_int_eq(fricreg_disk_ctx_set_stribeck(ctx, m, p->fs, p->fk, p->vs, p->delta),
                     FRICREG_OK);
    return ctx;
}

/* ---- The scalar law, contact by contact ---------------------------------------------------- */

START_TEST(test_isotropic_blocks_are_the_scalar_law)
{
    const double eps = 0.03;
    double worst = 0.0;
    for (int trial = 0; trial < 300; trial++) {
        const size_t m = 4;
        struct params p;
        double w[16], zdot[8], afree[8], f[8];
        random_params(m, eps, &p);
        random_state(m, eps, zdot, afree);
        for (size_t i = 0; i < m; i++) {
            w[4 * i] = w[4 * i + 3] = uniform(0.3, 3.0);
            w[4 * i + 1] = w[4 * i + 2] = 0.0;
        }
        fricreg_disk_ctx *ctx = make_ctx(m, eps, &p, NULL);
        ck_assert_int_eq(fricreg_disk_ctx_set_coupling_blocks(ctx, m, w), FRICREG_OK);
        eval_ok(ctx, m, zdot, afree, f);
        for (size_t i = 0; i < m; i++) {
            double feq[2] = {-afree[2 * i] / w[4 * i], -afree[2 * i + 1] / w[4 * i]}, ref[2];
            ck_assert_int_eq(fricreg_stribeck_disk_eval(zdot + 2 * i, feq, p.fs[i], p.fk[i],
                                                        p.vs[i], p.delta[i], eps, ref),
                             FRICREG_OK);
            for (int a = 0; a < 2; a++) {
                double d = fabs(f[2 * i + a] - ref[a]) / p.fs[i];
                worst = fmax(worst, d);
                ck_assert_msg(d <= 8.0 * DBL_EPSILON, "trial %d contact %zu: %.17g vs %.17g", trial,
                              i, f[2 * i + a], ref[a]);
            }
        }
        fricreg_disk_ctx_free(ctx);
    }
    printf("stribeck_disk_ctx: isotropic blocks vs fricreg_stribeck_disk_eval: %.3g fs\n", worst);
}
END_TEST

/* Dense W with isotropic diagonal blocks: each f_i is the scalar law at the f_eq,i that the
 * others' returned forces give. */
START_TEST(test_dense_is_the_scalar_law_at_its_f_eq)
{
    const double eps = 0.03;
    double worst = 0.0;
    for (int trial = 0; trial < 300; trial++) {
        size_t m = 2 + (size_t)trial % 3, n = 2 * m;
        struct params p;
        double W[N2 * N2], zdot[N2], afree[N2], f[N2];
        random_params(m, eps, &p);
        random_state(m, eps, zdot, afree);
        isotropic_spd(m, uniform(0.1, 0.5), W);
        fricreg_disk_ctx *ctx = make_ctx(m, eps, &p, W);
        eval_ok(ctx, m, zdot, afree, f);
        for (size_t i = 0; i < m; i++) {
            double feq[2], ref[2], w = W[2 * i * n + 2 * i];
            for (int a = 0; a < 2; a++) {
                double s = afree[2 * i + a];
                for (size_t j = 0; j < m; j++)
                    for (int b = 0; j != i && b < 2; b++)
                        s += W[(2 * i + a) * n + 2 * j + b] * f[2 * j + b];
                feq[a] = -s / w;
            }
            ck_assert_int_eq(fricreg_stribeck_disk_eval(zdot + 2 * i, feq, p.fs[i], p.fk[i],
                                                        p.vs[i], p.delta[i], eps, ref),
                             FRICREG_OK);
            for (int a = 0; a < 2; a++) {
                double d = fabs(f[2 * i + a] - ref[a]) / p.fs[i];
                worst = fmax(worst, d);
                ck_assert_msg(d <= 1e-11, "trial %d contact %zu: %.17g vs %.17g", trial, i,
                              f[2 * i + a], ref[a]);
            }
        }
        fricreg_disk_ctx_free(ctx);
    }
    printf("stribeck_disk_ctx: dense W, f_i vs the scalar law at its f_eq: %.3g fs\n", worst);
}
END_TEST

/* ---- fs = fk: the context's own bounds ------------------------------------------------------ */

START_TEST(test_equal_bounds_are_set_bounds)
{
    const double eps = 0.03;
    for (int trial = 0; trial < 100; trial++) {
        size_t m = 1 + (size_t)trial % 4, n = 2 * m;
        struct params p;
        double W[N2 * N2], zdot[N2], afree[N2], f1[N2], f2[N2];
        double T1[2][N2 * N2], T2[2][N2 * N2];
        random_params(m, eps, &p);
        for (size_t i = 0; i < m; i++)
            p.fk[i] = p.fs[i];
        random_state(m, eps, zdot, afree);
        isotropic_spd(m, uniform(0.1, 0.5), W);
        W[1] = W[n] = 0.05; /* contact 0's block anisotropic too */
        fricreg_disk_ctx *a = make_ctx(m, eps, &p, W), *b = NULL;
        ck_assert_int_eq(fricreg_disk_ctx_create(m, &b), FRICREG_OK);
        ck_assert_int_eq(fricreg_disk_ctx_set_law(b, FRICREG_DISK_QUINN, eps), FRICREG_OK);
        ck_assert_int_eq(fricreg_disk_ctx_set_coupling_dense(b, m, W), FRICREG_OK);
        ck_assert_int_eq(fricreg_disk_ctx_set_bounds(b, m, p.fk), FRICREG_OK);
        eval_ok(a, m, zdot, afree, f1);
        eval_ok(b, m, zdot, afree, f2);
        ck_assert_msg(memcmp(f1, f2, n * sizeof *f1) == 0, "trial %d: forces differ", trial);
        int s1 = fricreg_disk_ctx_tangent(a, m, T1[0], T1[1]);
        int s2 = fricreg_disk_ctx_tangent(b, m, T2[0], T2[1]);
        ck_assert_int_eq(s1, s2);
        if (s1 == FRICREG_OK)
            ck_assert_msg(memcmp(T1[0], T2[0], n * n * sizeof(double)) == 0 &&
                              memcmp(T1[1], T2[1], n * n * sizeof(double)) == 0,
                          "trial %d: tangents differ", trial);
        fricreg_disk_ctx_free(a);
        fricreg_disk_ctx_free(b);
    }
}
END_TEST

/* ---- Stick at rest and break-away ----------------------------------------------------------- */

/* a_free = -s W f*: while |s f*_i| <= fs_i for all i the coupled stick problem holds f = s f*
 * (zero acceleration); f* is chosen with fk_i < |f*_i| < fs_i, which kinetic bounds could not
 * hold. The first contact breaks away at s = min fs_i/|f*_i|. */
START_TEST(test_stick_and_break_away)
{
    const double eps = 0.02;
    for (int trial = 0; trial < 60; trial++) {
        size_t m = 2 + (size_t)trial % 3, n = 2 * m;
        struct params p;
        double W[N2 * N2], fstar[N2], zdot[N2] = {0}, afree[N2], f[N2], acc[N2];
        random_params(m, eps, &p);
        isotropic_spd(m, uniform(0.1, 0.5), W);
        double s_break = INFINITY;
        for (size_t i = 0; i < m; i++) {
            double mag = p.fk[i] + uniform(0.2, 0.9) * (p.fs[i] - p.fk[i]), th = uniform(0, 6.3);
            fstar[2 * i] = mag * cos(th), fstar[2 * i + 1] = mag * sin(th);
            s_break = fmin(s_break, p.fs[i] / mag);
        }
        fricreg_disk_ctx *ctx = make_ctx(m, eps, &p, W);
        const double scales[3] = {1.0, s_break * (1.0 - 1e-9), s_break * (1.0 + 1e-6)};
        for (int k = 0; k < 3; k++) {
            double s = scales[k];
            for (size_t r = 0; r < n; r++) {
                afree[r] = 0.0;
                for (size_t c = 0; c < n; c++)
                    afree[r] -= s * W[r * n + c] * fstar[c];
            }
            eval_ok(ctx, m, zdot, afree, f);
            for (size_t r = 0; r < n; r++) {
                acc[r] = afree[r];
                for (size_t c = 0; c < n; c++)
                    acc[r] += W[r * n + c] * f[c];
            }
            double a = max_abs(acc, n), scale = max_abs(afree, n);
            for (size_t i = 0; i < m; i++)
                ck_assert_double_le(hypot(f[2 * i], f[2 * i + 1]), p.fs[i] * (1.0 + 1e-14));
            if (k < 2) { /* holds: f = s f*, at rest */
                ck_assert_msg(a <= 1e-12 * scale, "trial %d, s = %g: acceleration %g", trial, s, a);
                for (size_t r = 0; r < n; r++)
                    ck_assert_double_eq_tol(f[r], s * fstar[r], 1e-12);
            } else { /* breaks away: some contact accelerates */
                ck_assert_msg(a > 1e-9 * scale, "trial %d: no break-away past s = %g (%g)", trial,
                              s_break, a);
            }
        }
        /* kinetic bounds (set_bounds(fk)) cannot hold f*: the same a_free slips */
        ck_assert_int_eq(fricreg_disk_ctx_set_bounds(ctx, m, p.fk), FRICREG_OK);
        for (size_t r = 0; r < n; r++) {
            afree[r] = 0.0;
            for (size_t c = 0; c < n; c++)
                afree[r] -= W[r * n + c] * fstar[c];
        }
        eval_ok(ctx, m, zdot, afree, f);
        for (size_t r = 0; r < n; r++) {
            acc[r] = afree[r];
            for (size_t c = 0; c < n; c++)
                acc[r] += W[r * n + c] * f[c];
        }
        ck_assert_double_gt(max_abs(acc, n), 1e-6);
        fricreg_disk_ctx_free(ctx);
    }
}
END_TEST

/* ---- Continuity --------------------------------------------------------------------------- */

/* Across |zdot_0| = eps and through rest, with a dense W: the largest jump over steps of
 * 1e-9 eps stays below 1e-8 fs, as in test_disk_ctx.c (Lipschitz constant 10 fs/eps: the
 * band's bound falls by at most fs over eps, so the slope grows by less than fs/eps). */
START_TEST(test_continuity)
{
    const size_t m = 3;
    const double eps = 0.02, h = 1e-9 * eps;
    double worst = 0.0;
    for (int trial = 0; trial < 6; trial++) {
        struct params p;
        double W[36], zdot[6], afree[6];
        random_params(m, eps, &p);
        p.fs[0] = 1.0, p.fk[0] = 0.4, p.vs[0] = 0.5 * eps, p.delta[0] = trial % 2 ? 0.5 : 2.0;
        isotropic_spd(m, 0.5, W);
        W[1] = W[6] = 0.1; /* contact 0's block anisotropic */
        for (size_t k = 0; k < 6; k++)
            afree[k] = uniform(-1.5, 1.5);
        for (size_t k = 2; k < 6; k++)
            zdot[k] = uniform(-0.5, 0.5) * eps;
        double th = uniform(0.0, 6.3), dir[2] = {cos(th), sin(th)};
        fricreg_disk_ctx *ctx = make_ctx(m, eps, &p, W);
        worst = fmax(worst,
                     disk_ctx_sweep(ctx, m, zdot, afree, dir, eps, h, 300)); /* |zdot_0| = eps */
        worst = fmax(worst, disk_ctx_sweep(ctx, m, zdot, afree, dir, 0.0, h, 300)); /* through 0 */
        fricreg_disk_ctx_free(ctx);
    }
    printf("stribeck_disk_ctx: largest jump over steps of 1e-9 eps: %.3g fs\n", worst);
    ck_assert_msg(worst < 1e-8, "jump %g", worst);
}
END_TEST

/* ---- The tangent ---------------------------------------------------------------------------- */

/* Dense W (anisotropic blocks) and block-diagonal W, zdot in the band and sliding. */
START_TEST(test_tangent_central_differences)
{
    const double eps = 0.05;
    int checked = 0, tried = 0;
    for (int trial = 0; trial < 160; trial++) {
        size_t m = 1 + (size_t)trial % 4, n = 2 * m;
        struct params p;
        double W[N2 * N2], zdot[N2], afree[N2];
        random_params(m, eps, &p);
        random_state(m, eps, zdot, afree);
        for (size_t i = 0; i < m; i++) /* away from rest: |zdot| = 0 is a kink */
            if (zdot[2 * i] == 0.0 && zdot[2 * i + 1] == 0.0)
                zdot[2 * i] = 0.3 * eps;
        isotropic_spd(m, uniform(0.1, 0.5), W);
        W[1] = W[n] = 0.07;
        fricreg_disk_ctx *ctx = make_ctx(m, eps, &p, trial % 2 ? W : NULL);
        if (trial % 2 == 0) {
            double w[16];
            for (size_t i = 0; i < m; i++) {
                const double *b = W + 2 * i * n + 2 * i;
                w[4 * i] = b[0], w[4 * i + 1] = b[1], w[4 * i + 2] = b[n], w[4 * i + 3] = b[n + 1];
            }
            ck_assert_int_eq(fricreg_disk_ctx_set_coupling_blocks(ctx, m, w), FRICREG_OK);
        }
        checked += disk_ctx_check_tangent(ctx, m, zdot, afree, eps);
        tried++;
        fricreg_disk_ctx_free(ctx);
    }
    printf("stribeck_disk_ctx: tangent checked on %d of %d random cases\n", checked, tried);
    ck_assert_int_ge(checked, tried * 3 / 4);
}
END_TEST

/* At rest a saturated contact is differentiated along the direction it will slide, u = -f/|f|
 * (fricreg_disk_ctx.h); with Stribeck friction its bound falls along u at (k(eps) - fs)/eps.
 * One-sided differences (f(h u) - f(0))/h, h -> 0, must converge to T u. */
START_TEST(test_tangent_at_rest_one_sided)
{
    const double eps = 0.05;
    struct params p = {{1.0, 0.8}, {0.3, 0.5}, {0.02, 0.04}, {1.0, 2.0}};
    double W[16] = {1.2, 0, 0.3, 0.1, 0, 1.2, 0.1, -0.2, 0.3, 0.1, 0.9, 0, 0.1, -0.2, 0, 0.9};
    double zdot[4] = {0.0, 0.0, 0.01, -0.005}, afree[4] = {2.0, -1.0, 0.1, 0.2}, f0[4], T[16];
    fricreg_disk_ctx *ctx = make_ctx(2, eps, &p, W);
    eval_ok(ctx, 2, zdot, afree, f0);
    ck_assert_double_eq_tol(hypot(f0[0], f0[1]), 1.0, 1e-12); /* saturated at fs */
    ck_assert_int_eq(fricreg_disk_ctx_tangent(ctx, 2, T, NULL), FRICREG_OK);
    double u[2] = {-f0[0] / hypot(f0[0], f0[1]), -f0[1] / hypot(f0[0], f0[1])}, prev = INFINITY;
    for (int k = 0; k < 3; k++) {
        double h = 1e-6 * eps * pow(0.1, k), z[4] = {h * u[0], h * u[1], zdot[2], zdot[3]}, f[4];
        eval_ok(ctx, 2, z, afree, f);
        double err = 0.0;
        for (int r = 0; r < 4; r++)
            err = fmax(err, fabs((f[r] - f0[r]) / h - (T[4 * r] * u[0] + T[4 * r + 1] * u[1])));
        ck_assert_msg(err <= fmax(1e-4, 0.2 * prev), "h = %g: error %g", h, err);
        prev = err;
    }
    ck_assert_double_le(prev, 1e-4); /* the slope is O(fs/eps) = 20 */
    fricreg_disk_ctx_free(ctx);
}
END_TEST

/* ---- Setters -------------------------------------------------------------------------------- */

/* set_law(QUINN) keeps Stribeck friction with the new eps; FORCE_BALANCE, set_bounds and m = 0
 * switch it off. */
START_TEST(test_setter_rules)
{
    struct params p = {{1.0}, {0.4}, {0.01}, {1.0}};
    const double mun[1] = {0.7}, zdot[2] = {0.012, 0.0}, afree[2] = {-0.3, 2.0};
    double f[2], ref[2], feq[2] = {0.3, -2.0};
    fricreg_disk_ctx *ctx = make_ctx(1, 0.02, &p, NULL);
    ck_assert_int_eq(fricreg_disk_ctx_set_law(ctx, FRICREG_DISK_QUINN, 0.05), FRICREG_OK);
    eval_ok(ctx, 1, zdot, afree, f);
    fricreg_stribeck_disk_eval(zdot, feq, 1.0, 0.4, 0.01, 1.0, 0.05, ref);
    ck_assert_double_eq_tol(f[0], ref[0], 1e-15);
    ck_assert_double_eq_tol(f[1], ref[1], 1e-15);

    /* m = 0 (arrays NULL): the bounds of set_bounds (defaults 1) */
    ck_assert_int_eq(fricreg_disk_ctx_set_stribeck(ctx, 0, NULL, NULL, NULL, NULL), FRICREG_OK);
    eval_ok(ctx, 1, zdot, afree, f);
    fricreg_disk_eval(FRICREG_DISK_QUINN, zdot, feq, 1.0, 0.05, ref);
    ck_assert_double_eq_tol(f[0], ref[0], 1e-15);
    ck_assert_double_eq_tol(f[1], ref[1], 1e-15);

    /* set_bounds after set_stribeck: its bounds */
    ck_assert_int_eq(fricreg_disk_ctx_set_stribeck(ctx, 1, p.fs, p.fk, p.vs, p.delta), FRICREG_OK);
    ck_assert_int_eq(fricreg_disk_ctx_set_bounds(ctx, 1, mun), FRICREG_OK);
    eval_ok(ctx, 1, zdot, afree, f);
    fricreg_disk_eval(FRICREG_DISK_QUINN, zdot, feq, 0.7, 0.05, ref);
    ck_assert_double_eq_tol(f[0], ref[0], 1e-15);
    ck_assert_double_eq_tol(f[1], ref[1], 1e-15);

    /* FORCE_BALANCE switches it off; set_stribeck selects QUINN again */
    ck_assert_int_eq(fricreg_disk_ctx_set_stribeck(ctx, 1, p.fs, p.fk, p.vs, p.delta), FRICREG_OK);
    ck_assert_int_eq(fricreg_disk_ctx_set_law(ctx, FRICREG_DISK_FORCE_BALANCE, 0.05), FRICREG_OK);
    eval_ok(ctx, 1, zdot, afree, f);
    ck_assert_double_eq_tol(f[0], -0.7, 1e-15); /* sliding with mun */
    ck_assert_int_eq(fricreg_disk_ctx_set_stribeck(ctx, 1, p.fs, p.fk, p.vs, p.delta), FRICREG_OK);
    eval_ok(ctx, 1, zdot, afree, f);
    fricreg_stribeck_disk_eval(zdot, feq, 1.0, 0.4, 0.01, 1.0, 0.05, ref);
    ck_assert_double_eq_tol(f[0], ref[0], 1e-15);
    ck_assert_double_eq_tol(f[1], ref[1], 1e-15);
    fricreg_disk_ctx_free(ctx);
}
END_TEST

static void expect_fail(fricreg_disk_ctx *ctx, int got, int want)
{
    ck_assert_int_eq(got, want);
    ck_assert_int_eq(fricreg_disk_ctx_errcode(ctx), want);
    ck_assert_str_ne(fricreg_disk_ctx_errmsg(ctx), "");
}

/* Every refused call leaves the context as it was: the same forces, bit for bit, and the last
 * evaluation's tangent still available. */
START_TEST(test_bad_input_leaves_context)
{
    const size_t m = 2;
    struct params p = {{1.0, 0.8}, {0.3, 0.5}, {0.02, 0.04}, {1.0, 2.0}};
    double W[16] = {1.2, 0, 0.3, 0.1, 0, 1.2, 0.1, -0.2, 0.3, 0.1, 0.9, 0, 0.1, -0.2, 0, 0.9};
    const double zdot[4] = {0.01, 0.0, 0.07, -0.005}, afree[4] = {0.9, -0.4, 0.1, 0.2};
    double f0[4], f[4], T[16];
    fricreg_disk_ctx *ctx = make_ctx(m, 0.05, &p, W);
    eval_ok(ctx, m, zdot, afree, f0);
    struct {
        int contact, which; /* parameter 0 fs, 1 fk, 2 vs, 3 delta */
        double value;
        int want;
    } bad[] = {{0, 0, NAN, FRICREG_ENONFINITE}, {1, 3, INFINITY, FRICREG_ENONFINITE},
               {1, 1, -1e-300, FRICREG_EINVAL}, {0, 1, 1.5, FRICREG_EINVAL},
               {1, 0, 0.2, FRICREG_EINVAL},     {0, 0, 2e250, FRICREG_EINVAL},
               {1, 2, 0.0, FRICREG_EINVAL},     {0, 3, -1.0, FRICREG_EINVAL}};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        struct params q = p;
        double *arr[4] = {q.fs, q.fk, q.vs, q.delta};
        arr[bad[k].which][bad[k].contact] = bad[k].value;
        expect_fail(ctx, fricreg_disk_ctx_set_stribeck(ctx, m, q.fs, q.fk, q.vs, q.delta),
                    bad[k].want);
        ck_assert_int_eq(fricreg_disk_ctx_tangent(ctx, m, T, NULL), FRICREG_OK);
        eval_ok(ctx, m, zdot, afree, f);
        ck_assert_msg(memcmp(f, f0, sizeof f) == 0, "case %zu changed the context", k);
    }
    expect_fail(ctx, fricreg_disk_ctx_set_stribeck(ctx, 3, p.fs, p.fk, p.vs, p.delta),
                FRICREG_ESIZE);
    expect_fail(ctx, fricreg_disk_ctx_set_stribeck(ctx, m, p.fs, NULL, p.vs, p.delta),
                FRICREG_ENULL);
    ck_assert_int_eq(fricreg_disk_ctx_set_stribeck(NULL, m, p.fs, p.fk, p.vs, p.delta),
                     FRICREG_ENULL);
    eval_ok(ctx, m, zdot, afree, f);
    ck_assert(memcmp(f, f0, sizeof f) == 0);

    /* refused while Stribeck friction is off: the bounds stay those of set_bounds */
    const double mun[2] = {0.6, 0.3};
    ck_assert_int_eq(fricreg_disk_ctx_set_bounds(ctx, m, mun), FRICREG_OK);
    eval_ok(ctx, m, zdot, afree, f0);
    struct params q = p;
    q.fk[0] = 2.0;
    expect_fail(ctx, fricreg_disk_ctx_set_stribeck(ctx, m, q.fs, q.fk, q.vs, q.delta),
                FRICREG_EINVAL);
    eval_ok(ctx, m, zdot, afree, f);
    ck_assert(memcmp(f, f0, sizeof f) == 0);
    fricreg_disk_ctx_free(ctx);
}
END_TEST

static Suite *stribeck_disk_ctx_suite(void)
{
    Suite *s = suite_create("stribeck_disk_ctx");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, test_isotropic_blocks_are_the_scalar_law);
    tcase_add_test(tc, test_dense_is_the_scalar_law_at_its_f_eq);
    tcase_add_test(tc, test_equal_bounds_are_set_bounds);
    tcase_add_test(tc, test_stick_and_break_away);
    tcase_add_test(tc, test_continuity);
    tcase_add_test(tc, test_tangent_central_differences);
    tcase_add_test(tc, test_tangent_at_rest_one_sided);
    tcase_add_test(tc, test_setter_rules);
    tcase_add_test(tc, test_bad_input_leaves_context);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(stribeck_disk_ctx_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
