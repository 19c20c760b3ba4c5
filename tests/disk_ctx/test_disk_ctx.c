/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_disk_ctx.c — Check suite for coupled 2-D contacts in a context (fricreg_disk_ctx.h).
 *
 * Where the numbers come from:
 *   - uncoupled isotropic blocks w_i I: the law is fricreg_disk_eval's, contact by contact, at
 *     f_eq,i = -a_free,i/w_i (the QP separates and the W_ii metric is Euclidean);
 *   - at rest: Coulomb's stick problem; a stuck contact has zero acceleration (W f + a_free = 0),
 *     a saturated one an acceleration anti-parallel to its force (maximum dissipation);
 *   - everything else: an independent solver written here, FISTA (accelerated projected
 *     gradient with adaptive restart, Beck & Teboulle 2009; O'Donoghue & Candes 2015) on the
 *     QP of fricreg_disk_ctx.h with Euclidean projections onto the product of disks, run until
 *     its fixed-point residual is below 1e-15 mun: not the library's method (block
 *     Gauss-Seidel with exact W_ii-metric block solves);
 *   - the tangent: central differences of eval;
 *   - continuity: the largest jump of f over steps of 1e-9 eps stays below 1e-8 mun, the bound
 *     a Lipschitz constant of 10 mun/eps would give (the single contact's is 5 mun/eps,
 *     fricreg_disk.h; the factor 2 is the coupling's room with the mildly coupled W used).
 * Inputs come from a fixed xorshift generator: every run checks the same points. */
#include <check.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_disk.h"
#include "fricreg_disk_ctx.h"
#include "disk_ctx_checks.h"
#include "random.h"

#define MAXM 6
#define N2 (2 * MAXM)
#define SENTINEL (-777.125)

static uint64_t rng_state = 0x2545f4914f6cdd1du;
static double uniform(double lo, double hi)
{
    return xorshift64star_uniform(&rng_state, lo, hi);
}

/* A random symmetric positive definite W of order n: B B^T/n + shift I. */
static void random_spd(size_t n, double shift, double W[])
{
    double work[N2 * N2];
    random_gram_spd(xorshift64star_uniform, &rng_state, n, shift, work, W);
}

static fricreg_disk_ctx *make_ctx(size_t m, int law, double eps, const double mun[],
                                  const double W[])
{
    fricreg_disk_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_disk_ctx_create(m, &ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_disk_ctx_set_law(ctx, law, eps), FRICREG_OK);
    ck_assert_int_eq(fricreg_disk_ctx_set_bounds(ctx, m, mun), FRICREG_OK);
    if (W != NULL)
        ck_assert_msg(fricreg_disk_ctx_set_coupling_dense(ctx, m, W) == FRICREG_OK, "%s",
                      fricreg_disk_ctx_errmsg(ctx));
    return ctx;
}

/* ---- The independent reference: FISTA on the QP ------------------------------------------- */

/* Contact i's set for the law (FRICREG_DISK_QUINN): fixed force, or centre -p and radius. */
static int contact_set(double mun, double eps, const double v[2], double p[2], double *radius,
                       double fixed[2])
{
    double r = hypot(v[0], v[1]);
    p[0] = p[1] = 0.0;
    *radius = mun;
    if (mun == 0.0 || r >= eps) {
        fixed[0] = r > 0.0 ? -mun * v[0] / r : 0.0;
        fixed[1] = r > 0.0 ? -mun * v[1] / r : 0.0;
        return 1;
    }
    if (r > 0.0) {
        p[0] = mun * v[0] / eps;
        p[1] = mun * v[1] / eps;
        *radius = mun * (1.0 - r / eps);
    }
    return 0;
}

static void project_disk(const double p[2], double radius, double x[2])
{
    double y0 = x[0] + p[0], y1 = x[1] + p[1], d = hypot(y0, y1);
    if (d > radius) {
        y0 *= radius / d;
        y1 *= radius / d;
    }
    x[0] = y0 - p[0];
    x[1] = y1 - p[1];
}

/* min 1/2 f^T W f + b^T f over f_i in K_i (fixed contacts held), b_i = a_free,i + 2 W_ii p_i. */
static void reference(size_t m, const double W[], const double mun[], double eps,
                      const double zdot[], const double a_free[], double f[])
{
    size_t n = 2 * m;
    double p[N2], radius[MAXM], b[N2], y[N2], fold[N2], grad[N2];
    int fixed[MAXM];
    double L = 0.0;
    for (size_t k = 0; k < n * n; k++)
        L += W[k] * W[k];
    L = sqrt(L); /* Frobenius norm >= the largest eigenvalue */
    for (size_t i = 0; i < m; i++)
        fixed[i] = contact_set(mun[i], eps, zdot + 2 * i, p + 2 * i, &radius[i], f + 2 * i);
    for (size_t i = 0; i < m; i++)
        for (int a = 0; a < 2; a++) {
            b[2 * i + a] = a_free[2 * i + a];
            for (int c = 0; c < 2; c++)
                b[2 * i + a] += 2.0 * W[(2 * i + a) * n + 2 * i + c] * p[2 * i + c];
            if (!fixed[i])
                f[2 * i + a] = -p[2 * i + a];
        }
    memcpy(y, f, sizeof(double) * n);
    double t = 1.0, mmax = 0.0;
    for (size_t i = 0; i < m; i++)
        mmax = fmax(mmax, mun[i]);
    for (long it = 0; it < 2000000; it++) {
        memcpy(fold, f, sizeof(double) * n);
        for (size_t k = 0; k < n; k++) {
            grad[k] = b[k];
            for (size_t l = 0; l < n; l++)
                grad[k] += W[k * n + l] * y[l];
        }
        for (size_t i = 0; i < m; i++) {
            if (fixed[i])
                continue;
            for (int a = 0; a < 2; a++)
                f[2 * i + a] = y[2 * i + a] - grad[2 * i + a] / L;
            project_disk(p + 2 * i, radius[i], f + 2 * i);
        }
        double step = 0.0, restart = 0.0;
        for (size_t k = 0; k < n; k++) {
            step = fmax(step, fabs(f[k] - fold[k]));
            restart += (y[k] - f[k]) * (f[k] - fold[k]);
        }
        if (step <= 1e-16 * mmax && it > 10)
            break;
        double tn = 0.5 * (1.0 + sqrt(1.0 + 4.0 * t * t));
        if (restart > 0.0) /* adaptive restart: momentum off when it points uphill */
            tn = 1.0, t = 1.0;
        for (size_t k = 0; k < n; k++)
            y[k] = f[k] + ((t - 1.0) / tn) * (f[k] - fold[k]);
        t = tn;
    }
}

/* ---- (a) isotropic uncoupled blocks: fricreg_disk_eval contact by contact ----------------- */

START_TEST(test_isotropic_blocks_are_the_scalar_law)
{
    const size_t m = 6;
    const double eps = 0.02;
    for (int trial = 0; trial < 200; trial++) {
        double mun[MAXM], w[4 * MAXM], zdot[N2], afree[N2], f[N2], Wd[N2 * N2];
        memset(Wd, 0, sizeof Wd);
        for (size_t i = 0; i < m; i++) {
            mun[i] = uniform(0.1, 2.0);
            double wi = uniform(0.2, 5.0);
            w[4 * i] = w[4 * i + 3] = wi;
            w[4 * i + 1] = w[4 * i + 2] = 0.0;
            Wd[2 * i * 2 * m + 2 * i] = Wd[(2 * i + 1) * 2 * m + 2 * i + 1] = wi;
            double speed = i == 0 ? 0.0 : uniform(0.0, 1.5) * eps, th = uniform(0.0, 6.3);
            zdot[2 * i] = speed * cos(th);
            zdot[2 * i + 1] = speed * sin(th);
            afree[2 * i] = uniform(-3.0, 3.0) * mun[i] * wi;
            afree[2 * i + 1] = uniform(-3.0, 3.0) * mun[i] * wi;
        }
        fricreg_disk_ctx *ctx = make_ctx(m, FRICREG_DISK_QUINN, eps, mun, NULL);
        ck_assert_int_eq(fricreg_disk_ctx_set_coupling_blocks(ctx, m, w), FRICREG_OK);
        eval_ok(ctx, m, zdot, afree, f);
        double fd[N2];
        ck_assert_int_eq(fricreg_disk_ctx_set_coupling_dense(ctx, m, Wd), FRICREG_OK);
        eval_ok(ctx, m, zdot, afree, fd);
        for (size_t i = 0; i < m; i++) {
            double feq[2] = {-afree[2 * i] / w[4 * i], -afree[2 * i + 1] / w[4 * i]}, ref[2];
            ck_assert_int_eq(fricreg_disk_eval(FRICREG_DISK_QUINN, zdot + 2 * i, feq, mun[i], eps,
                                               ref),
                             FRICREG_OK);
            for (int a = 0; a < 2; a++) {
                ck_assert_msg(fabs(f[2 * i + a] - ref[a]) <= 4.0 * DBL_EPSILON * mun[i],
                              "blocks: contact %zu: %.17g vs %.17g", i, f[2 * i + a], ref[a]);
                ck_assert_msg(fabs(fd[2 * i + a] - ref[a]) <= 4.0 * DBL_EPSILON * mun[i],
                              "dense: contact %zu: %.17g vs %.17g", i, fd[2 * i + a], ref[a]);
            }
        }
        fricreg_disk_ctx_free(ctx);
    }
}
END_TEST

/* Force balance at rest on uncoupled isotropic blocks: fricreg_disk_eval's (2), sliding else. */
START_TEST(test_force_balance_blocks)
{
    const size_t m = 4;
    double mun[] = {1.0, 0.5, 2.0, 0.25}, w[16], zdot[] = {0, 0, 0.1, -0.2, 0, 0, 0, 1e-300};
    double afree[] = {0.3, -0.4, 5.0, 1.0, -7.0, 1.0, 0.1, 0.1}, f[8];
    for (size_t i = 0; i < m; i++)
        w[4 * i] = w[4 * i + 3] = 1.0 + (double)i, w[4 * i + 1] = w[4 * i + 2] = 0.0;
    fricreg_disk_ctx *ctx = make_ctx(m, FRICREG_DISK_FORCE_BALANCE, 1.0, mun, NULL);
    ck_assert_int_eq(fricreg_disk_ctx_set_coupling_blocks(ctx, m, w), FRICREG_OK);
    eval_ok(ctx, m, zdot, afree, f);
    for (size_t i = 0; i < m; i++) {
        double feq[2] = {-afree[2 * i] / w[4 * i], -afree[2 * i + 1] / w[4 * i]}, ref[2];
        fricreg_disk_eval(FRICREG_DISK_FORCE_BALANCE, zdot + 2 * i, feq, mun[i], 1.0, ref);
        ck_assert_double_eq_tol(f[2 * i], ref[0], 4 * DBL_EPSILON * mun[i]);
        ck_assert_double_eq_tol(f[2 * i + 1], ref[1], 4 * DBL_EPSILON * mun[i]);
    }
    fricreg_disk_ctx_free(ctx);
}
END_TEST

/* ---- (b) at rest: exact stick, and maximum dissipation when saturated --------------------- */

START_TEST(test_rest_stick_exact)
{
    const size_t m = 4, n = 8;
    for (int trial = 0; trial < 50; trial++) {
        double W[64], mun[4], target[8], afree[8], zdot[8] = {0}, f[8];
        random_spd(n, 0.3, W);
        for (size_t i = 0; i < m; i++) {
            mun[i] = uniform(0.5, 2.0);
            double r = uniform(0.0, 0.9) * mun[i], th = uniform(0.0, 6.3);
            target[2 * i] = r * cos(th), target[2 * i + 1] = r * sin(th);
        }
        for (size_t k = 0; k < n; k++) { /* a_free = -W f_target: f_target sticks */
            afree[k] = 0.0;
            for (size_t l = 0; l < n; l++)
                afree[k] -= W[k * n + l] * target[l];
        }
        fricreg_disk_ctx *ctx = make_ctx(m, FRICREG_DISK_QUINN, 0.01, mun, W);
        eval_ok(ctx, m, zdot, afree, f);
        for (size_t k = 0; k < n; k++) {
            double acc = afree[k];
            for (size_t l = 0; l < n; l++)
                acc += W[k * n + l] * f[l];
            ck_assert_msg(fabs(f[k] - target[k]) <= 1e-12, "f[%zu] = %.17g, %.17g", k, f[k],
                          target[k]);
            ck_assert_msg(fabs(acc) <= 1e-12, "acceleration %zu = %g", k, acc);
        }
        fricreg_disk_ctx_free(ctx);
    }
}
END_TEST

/* Strongly coupled contacts (W = B B^T/12 + 1e-5 I): block Gauss-Seidel alone does not reach
 * its tolerance within its 20000 sweeps here (checked by turning the polish off); the Newton
 * polish on its active set gives the stick forces to about cond(W) DBL_EPSILON. */
START_TEST(test_rest_stick_strongly_coupled)
{
    const size_t m = 6, n = 12;
    double worst = 0.0;
    for (int trial = 0; trial < 10; trial++) {
        double W[144], mun[6], target[12], afree[12], zdot[12] = {0}, f[12];
        random_spd(n, 1e-5, W);
        for (size_t i = 0; i < m; i++) {
            mun[i] = 1.0;
            double r = uniform(0.0, 0.9), th = uniform(0.0, 6.3);
            target[2 * i] = r * cos(th), target[2 * i + 1] = r * sin(th);
        }
        for (size_t k = 0; k < n; k++) {
            afree[k] = 0.0;
            for (size_t l = 0; l < n; l++)
                afree[k] -= W[k * n + l] * target[l];
        }
        fricreg_disk_ctx *ctx = make_ctx(m, FRICREG_DISK_QUINN, 0.01, mun, W);
        eval_ok(ctx, m, zdot, afree, f);
        for (size_t k = 0; k < n; k++)
            worst = fmax(worst, fabs(f[k] - target[k]));
        fricreg_disk_ctx_free(ctx);
    }
    printf("disk_ctx: strongly coupled stick, largest error %.3g mun\n", worst);
    ck_assert_msg(worst <= 1e-10, "error %g", worst);
}
END_TEST

START_TEST(test_rest_saturated_dissipates_most)
{
    const size_t m = 3, n = 6;
    int saturated = 0, stuck = 0;
    for (int trial = 0; trial < 100; trial++) {
        double W[36], mun[3], afree[6], zdot[6] = {0}, f[6], ref[6];
        random_spd(n, 0.2, W);
        for (size_t i = 0; i < m; i++)
            mun[i] = uniform(0.5, 2.0);
        double scale = uniform(0.3, 3.0);
        for (size_t k = 0; k < n; k++)
            afree[k] = scale * uniform(-1.0, 1.0);
        fricreg_disk_ctx *ctx = make_ctx(m, FRICREG_DISK_QUINN, 0.01, mun, W);
        eval_ok(ctx, m, zdot, afree, f);
        reference(m, W, mun, 0.01, zdot, afree, ref);
        for (size_t i = 0; i < m; i++) {
            double acc[2];
            for (int a = 0; a < 2; a++) {
                acc[a] = afree[2 * i + a];
                for (size_t l = 0; l < n; l++)
                    acc[a] += W[(2 * i + a) * n + l] * f[l];
                ck_assert_double_eq_tol(f[2 * i + a], ref[2 * i + a], 1e-9 * mun[i]);
            }
            double nf = hypot(f[2 * i], f[2 * i + 1]), na = hypot(acc[0], acc[1]);
            if (nf >= mun[i] * (1.0 - 1e-12) && na > 1e-9) {
                saturated++;
                double cross = f[2 * i] * acc[1] - f[2 * i + 1] * acc[0];
                double dot = f[2 * i] * acc[0] + f[2 * i + 1] * acc[1];
                ck_assert_msg(fabs(cross) <= 1e-10 * nf * na && dot < 0.0,
                              "not anti-parallel: cross %g dot %g", cross, dot);
            } else {
                stuck++;
                ck_assert_msg(na <= 1e-10, "stuck contact accelerates: %g", na);
            }
        }
        fricreg_disk_ctx_free(ctx);
    }
    ck_assert_int_gt(saturated, 20);
    ck_assert_int_gt(stuck, 20);
}
END_TEST

/* ---- (c) a non-isotropic block: projection in the W_ii metric ----------------------------- */

START_TEST(test_anisotropic_block_metric)
{
    const double A[4] = {4.0, 1.5, 1.5, 1.0}, mun = 1.0, eps = 0.1;
    const double zdot[2] = {0.03, -0.02};
    int differ = 0;
    for (int trial = 0; trial < 100; trial++) {
        double afree[2] = {uniform(-8.0, 8.0), uniform(-8.0, 8.0)}, f[2], ref[2];
        fricreg_disk_ctx *ctx = make_ctx(1, FRICREG_DISK_QUINN, eps, &mun, NULL);
        ck_assert_int_eq(fricreg_disk_ctx_set_coupling_blocks(ctx, 1, A), FRICREG_OK);
        eval_ok(ctx, 1, zdot, afree, f);
        reference(1, A, &mun, eps, zdot, afree, ref);
        ck_assert_double_eq_tol(f[0], ref[0], 1e-9);
        ck_assert_double_eq_tol(f[1], ref[1], 1e-9);
        /* fricreg_disk_eval at f_eq = -A^-1 a_free: the Euclidean projection */
        double det = A[0] * A[3] - A[1] * A[2];
        double feq[2] = {-(A[3] * afree[0] - A[1] * afree[1]) / det,
                         -(-A[2] * afree[0] + A[0] * afree[1]) / det},
               eu[2];
        fricreg_disk_eval(FRICREG_DISK_QUINN, zdot, feq, mun, eps, eu);
        if (hypot(eu[0] - f[0], eu[1] - f[1]) > 1e-3)
            differ++;
        fricreg_disk_ctx_free(ctx);
    }
    ck_assert_int_gt(differ, 30); /* outside K the two projections differ */
}
END_TEST

/* ---- Random coupled cases against FISTA --------------------------------------------------- */

static void random_case(size_t m, double eps, double W[], double mun[], double zdot[],
                        double afree[])
{
    random_spd(2 * m, uniform(0.05, 0.5), W);
    for (size_t i = 0; i < m; i++) {
        mun[i] = uniform(0.1, 2.0);
        double pick = uniform(0.0, 1.0);
        double speed = pick < 0.2   ? 0.0
                       : pick < 0.8 ? uniform(0.0, 1.0) * eps
                                    : uniform(1.0, 2.0) * eps;
        double th = uniform(0.0, 6.3);
        zdot[2 * i] = speed * cos(th);
        zdot[2 * i + 1] = speed * sin(th);
        afree[2 * i] = uniform(-2.0, 2.0);
        afree[2 * i + 1] = uniform(-2.0, 2.0);
    }
}

START_TEST(test_random_against_fista)
{
    const double eps = 0.05;
    double worst = 0.0;
    for (int trial = 0; trial < 400; trial++) {
        size_t m = 1 + (size_t)trial % 4;
        double W[64], mun[4], zdot[8], afree[8], f[8], ref[8];
        random_case(m, eps, W, mun, zdot, afree);
        fricreg_disk_ctx *ctx = make_ctx(m, FRICREG_DISK_QUINN, eps, mun, W);
        eval_ok(ctx, m, zdot, afree, f);
        reference(m, W, mun, eps, zdot, afree, ref);
        double mmax = 0.0;
        for (size_t i = 0; i < m; i++)
            mmax = fmax(mmax, mun[i]);
        for (size_t k = 0; k < 2 * m; k++) {
            worst = fmax(worst, fabs(f[k] - ref[k]) / mmax);
            ck_assert_msg(fabs(f[k] - ref[k]) <= 1e-9 * mmax, "trial %d, f[%zu] = %.17g vs %.17g",
                          trial, k, f[k], ref[k]);
        }
        fricreg_disk_ctx_free(ctx);
    }
    printf("disk_ctx: largest difference to FISTA over 400 cases: %.3g max mun\n", worst);
}
END_TEST

/* ---- Continuity across the band's edge and through rest ----------------------------------- */

START_TEST(test_continuity)
{
    const size_t m = 3;
    const double eps = 0.02, h = 1e-9 * eps;
    double W[36], mun[3] = {1.0, 1.0, 1.0}, worst = 0.0;
    random_spd(6, 0.5, W);
    for (int trial = 0; trial < 6; trial++) {
        double zdot[6], afree[6];
        for (size_t k = 0; k < 6; k++)
            afree[k] = uniform(-1.5, 1.5);
        for (size_t k = 2; k < 6; k++)
            zdot[k] = uniform(-0.5, 0.5) * eps;
        double th = uniform(0.0, 6.3), dir[2] = {cos(th), sin(th)};
        fricreg_disk_ctx *ctx = make_ctx(m, FRICREG_DISK_QUINN, eps, mun, W);
        worst = fmax(worst,
                     disk_ctx_sweep(ctx, m, zdot, afree, dir, eps, h, 300)); /* |zdot_1| = eps */
        worst = fmax(worst, disk_ctx_sweep(ctx, m, zdot, afree, dir, 0.0, h, 300)); /* through 0 */
        fricreg_disk_ctx_free(ctx);
    }
    printf("disk_ctx: largest jump over steps of 1e-9 eps: %.3g mun\n", worst);
    ck_assert_msg(worst < 1e-8, "jump %g", worst);
}
END_TEST

/* ---- The tangent against central differences --------------------------------------------- */

START_TEST(test_tangent_dense)
{
    const double eps = 0.05;
    int checked = 0, tried = 0;
    for (int trial = 0; trial < 120; trial++) {
        size_t m = 1 + (size_t)trial % 4;
        double W[64], mun[4], zdot[8], afree[8];
        random_case(m, eps, W, mun, zdot, afree);
        for (size_t k = 0; k < 2 * m; k++) /* away from rest: |zdot| = 0 is a kink */
            if (zdot[k] == 0.0)
                zdot[k] = 0.3 * eps;
        fricreg_disk_ctx *ctx = make_ctx(m, FRICREG_DISK_QUINN, eps, mun, W);
        checked += disk_ctx_check_tangent(ctx, m, zdot, afree, eps);
        tried++;
        fricreg_disk_ctx_free(ctx);
    }
    printf("disk_ctx: tangent checked on %d of %d random cases\n", checked, tried);
    ck_assert_int_ge(checked, tried * 3 / 4);
}
END_TEST

START_TEST(test_tangent_blocks)
{
    const double eps = 0.05;
    int checked = 0;
    for (int trial = 0; trial < 60; trial++) {
        const size_t m = 4;
        double W[64], mun[4], zdot[8], afree[8], w[16];
        random_case(m, eps, W, mun, zdot, afree);
        for (size_t i = 0; i < m; i++) {
            w[4 * i] = W[2 * i * 8 + 2 * i], w[4 * i + 1] = W[2 * i * 8 + 2 * i + 1];
            w[4 * i + 2] = W[(2 * i + 1) * 8 + 2 * i],
                      w[4 * i + 3] = W[(2 * i + 1) * 8 + 2 * i + 1];
            if (zdot[2 * i] == 0.0 && zdot[2 * i + 1] == 0.0)
                zdot[2 * i] = 0.4 * eps;
        }
        fricreg_disk_ctx *ctx = make_ctx(m, FRICREG_DISK_QUINN, eps, mun, NULL);
        ck_assert_int_eq(fricreg_disk_ctx_set_coupling_blocks(ctx, m, w), FRICREG_OK);
        checked += disk_ctx_check_tangent(ctx, m, zdot, afree, eps);
        fricreg_disk_ctx_free(ctx);
    }
    ck_assert_int_ge(checked, 45);
}
END_TEST

/* The kink rule at rest (fricreg_disk_ctx.h): a saturated contact at rest is differentiated
 * along the direction it will slide, -f/|f|; one-sided differences along that direction agree
 * (coupled contacts, so the others' forces move too). */
START_TEST(test_tangent_at_rest_one_sided)
{
    const size_t m = 3, n = 6;
    const double eps = 0.05;
    int checked = 0;
    for (int trial = 0; trial < 40; trial++) {
        double W[36], mun[3] = {1.0, 1.0, 1.0}, zdot[6], afree[6], f[6], T[36], z[6], fh[6];
        random_spd(n, 0.5, W);
        for (size_t k = 0; k < n; k++) {
            afree[k] = uniform(-3.0, 3.0);
            zdot[k] = uniform(-0.5, 0.5) * eps;
        }
        zdot[0] = zdot[1] = 0.0; /* contact 0 at rest */
        fricreg_disk_ctx *ctx = make_ctx(m, FRICREG_DISK_QUINN, eps, mun, W);
        eval_ok(ctx, m, zdot, afree, f);
        ck_assert_int_eq(fricreg_disk_ctx_tangent(ctx, m, T, NULL), FRICREG_OK);
        double nf = hypot(f[0], f[1]);
        if (nf < 1.0 - 1e-12) { /* stuck inside: not this kink */
            fricreg_disk_ctx_free(ctx);
            continue;
        }
        double d[2] = {-f[0] / nf, -f[1] / nf}, h = 1e-7 * eps, err = 0.0, scale = 1e-3;
        memcpy(z, zdot, sizeof z);
        z[0] = h * d[0], z[1] = h * d[1];
        eval_ok(ctx, m, z, afree, fh);
        for (size_t r = 0; r < n; r++) {
            double fd = (fh[r] - f[r]) / h, t = T[r * n] * d[0] + T[r * n + 1] * d[1];
            err = fmax(err, fabs(fd - t));
            scale = fmax(scale, fabs(t));
        }
        ck_assert_msg(err <= 1e-5 * scale, "trial %d: one-sided difference off by %g of %g", trial,
                      err, scale);
        checked++;
        fricreg_disk_ctx_free(ctx);
    }
    ck_assert_int_ge(checked, 10);
}
END_TEST

/* ---- Bad input ---------------------------------------------------------------------------- */

static void expect_fail(fricreg_disk_ctx *ctx, int got, int want)
{
    ck_assert_msg(got == want, "status %d, expected %d (%s)", got, want,
                  fricreg_disk_ctx_errmsg(ctx));
    ck_assert_int_eq(fricreg_disk_ctx_errcode(ctx), want);
    ck_assert_msg(fricreg_disk_ctx_errmsg(ctx)[0] != '\0', "no message");
}

START_TEST(test_bad_input)
{
    fricreg_disk_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_disk_ctx_create(0, &ctx), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_disk_ctx_create(2, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_disk_ctx_create((size_t)1 << 40, &ctx), FRICREG_EINVAL);
    ck_assert_ptr_null(ctx);
    ck_assert_int_eq(fricreg_disk_ctx_create(2, &ctx), FRICREG_OK);
    ck_assert_uint_eq(fricreg_disk_ctx_size(ctx), 2);
    ck_assert_uint_eq(fricreg_disk_ctx_size(NULL), 0);
    ck_assert_str_eq(fricreg_disk_ctx_errmsg(NULL), "NULL context");

    double zdot[4] = {0.0, 0.0, 1e-4, 0.0}, afree[4] = {0.1, 0.2, 0.3, 0.4}, f[4], T[16];
    double nan = NAN;
    for (int k = 0; k < 4; k++)
        f[k] = SENTINEL;
    /* tangent before any evaluation */
    expect_fail(ctx, fricreg_disk_ctx_tangent(ctx, 2, T, NULL), FRICREG_EINVAL);
    /* laws and eps */
    expect_fail(ctx, fricreg_disk_ctx_set_law(ctx, FRICREG_DISK_QUINN_LENS, 0.1), FRICREG_EINVAL);
    expect_fail(ctx, fricreg_disk_ctx_set_law(ctx, FRICREG_DISK_COULOMB, 0.1), FRICREG_EINVAL);
    expect_fail(ctx, fricreg_disk_ctx_set_law(ctx, 99, 0.1), FRICREG_EINVAL);
    expect_fail(ctx, fricreg_disk_ctx_set_law(ctx, FRICREG_DISK_QUINN, 0.0), FRICREG_EINVAL);
    expect_fail(ctx, fricreg_disk_ctx_set_law(ctx, FRICREG_DISK_QUINN, -1.0), FRICREG_EINVAL);
    expect_fail(ctx, fricreg_disk_ctx_set_law(ctx, FRICREG_DISK_QUINN, 1e300), FRICREG_EINVAL);
    expect_fail(ctx, fricreg_disk_ctx_set_law(ctx, FRICREG_DISK_QUINN, nan), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_disk_ctx_set_law(NULL, FRICREG_DISK_QUINN, 0.1), FRICREG_ENULL);
    /* bounds */
    double mun_bad[2] = {1.0, -0.5}, mun_nan[2] = {nan, 1.0}, mun[2] = {1.0, 0.5};
    expect_fail(ctx, fricreg_disk_ctx_set_bounds(ctx, 2, mun_bad), FRICREG_EINVAL);
    expect_fail(ctx, fricreg_disk_ctx_set_bounds(ctx, 2, mun_nan), FRICREG_ENONFINITE);
    expect_fail(ctx, fricreg_disk_ctx_set_bounds(ctx, 3, mun), FRICREG_ESIZE);
    expect_fail(ctx, fricreg_disk_ctx_set_bounds(ctx, 2, NULL), FRICREG_ENULL);
    /* blocks */
    double nonsym[8] = {1, 0.5, 0.4, 1, 1, 0, 0, 1}, indef[8] = {1, 2, 2, 1, 1, 0, 0, 1};
    double negdiag[8] = {1, 0, 0, 1, -1, 0, 0, 1};
    expect_fail(ctx, fricreg_disk_ctx_set_coupling_blocks(ctx, 2, nonsym), FRICREG_ENOTSYM);
    expect_fail(ctx, fricreg_disk_ctx_set_coupling_blocks(ctx, 2, indef), FRICREG_ENOTPSD);
    expect_fail(ctx, fricreg_disk_ctx_set_coupling_blocks(ctx, 2, negdiag), FRICREG_ENOTPSD);
    /* a block below DBL_MIN: no mobility, its inverse overflows (the fuzz target's tangent
     * was -Inf for W_ii = 2.7e-312 I) */
    double tiny[8] = {1e-310, 0, 0, 1e-310, 1, 0, 0, 1};
    double Wtiny[16] = {1e-310, 0, 0, 0, 0, 1e-310, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    expect_fail(ctx, fricreg_disk_ctx_set_coupling_blocks(ctx, 2, tiny), FRICREG_ENOTPSD);
    expect_fail(ctx, fricreg_disk_ctx_set_coupling_dense(ctx, 2, Wtiny), FRICREG_ENOTPSD);
    expect_fail(ctx, fricreg_disk_ctx_set_coupling_blocks(ctx, 1, nonsym), FRICREG_ESIZE);
    expect_fail(ctx, fricreg_disk_ctx_set_coupling_blocks(ctx, 2, NULL), FRICREG_ENULL);
    /* dense: not symmetric, indefinite (PD blocks, coupling too strong), singular block */
    double Wn[16] = {2, 0, 1, 0, 0, 2, 0, 0, 0.5, 0, 2, 0, 0, 0, 0, 2};
    double Wi[16] = {1, 0, 1.5, 0, 0, 1, 0, 0, 1.5, 0, 1, 0, 0, 0, 0, 1};
    double Wi2[16] = {1, 0, 0.9, 0, 0, 1, 0, 0.9, 0.9, 0, 1, 0.6, 0, 0.9, 0.6, 1};
    double Ws[16] = {1, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    double Wnan[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    Wnan[5] = nan;
    expect_fail(ctx, fricreg_disk_ctx_set_coupling_dense(ctx, 2, Wn), FRICREG_ENOTSYM);
    expect_fail(ctx, fricreg_disk_ctx_set_coupling_dense(ctx, 2, Wi), FRICREG_ENOTPSD);
    expect_fail(ctx, fricreg_disk_ctx_set_coupling_dense(ctx, 2, Wi2), FRICREG_ENOTPSD);
    expect_fail(ctx, fricreg_disk_ctx_set_coupling_dense(ctx, 2, Ws), FRICREG_ENOTPSD);
    expect_fail(ctx, fricreg_disk_ctx_set_coupling_dense(ctx, 2, Wnan), FRICREG_ENONFINITE);
    expect_fail(ctx, fricreg_disk_ctx_set_coupling_dense(ctx, (size_t)1 << 62, Wn), FRICREG_ESIZE);
    /* eval */
    double znan[4] = {0, nan, 0, 0}, zbig[4] = {0, 1e260, 0, 0};
    expect_fail(ctx, fricreg_disk_ctx_eval(ctx, 2, NULL, afree, f), FRICREG_ENULL);
    expect_fail(ctx, fricreg_disk_ctx_eval(ctx, 2, zdot, NULL, f), FRICREG_ENULL);
    expect_fail(ctx, fricreg_disk_ctx_eval(ctx, 2, zdot, afree, NULL), FRICREG_ENULL);
    expect_fail(ctx, fricreg_disk_ctx_eval(ctx, 3, zdot, afree, f), FRICREG_ESIZE);
    expect_fail(ctx, fricreg_disk_ctx_eval(ctx, 2, znan, afree, f), FRICREG_ENONFINITE);
    expect_fail(ctx, fricreg_disk_ctx_eval(ctx, 2, zdot, znan, f), FRICREG_ENONFINITE);
    expect_fail(ctx, fricreg_disk_ctx_eval(ctx, 2, zbig, afree, f), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_disk_ctx_eval(NULL, 2, zdot, afree, f), FRICREG_ENULL);
    for (int k = 0; k < 4; k++)
        ck_assert_double_eq(f[k], SENTINEL); /* untouched on failure */
    /* tangent */
    eval_ok(ctx, 2, zdot, afree, f);
    for (int k = 0; k < 16; k++)
        T[k] = SENTINEL;
    expect_fail(ctx, fricreg_disk_ctx_tangent(ctx, 2, NULL, NULL), FRICREG_ENULL);
    expect_fail(ctx, fricreg_disk_ctx_tangent(ctx, 1, T, NULL), FRICREG_ESIZE);
    for (int k = 0; k < 16; k++)
        ck_assert_double_eq(T[k], SENTINEL);
    ck_assert_int_eq(fricreg_disk_ctx_tangent(ctx, 2, T, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_disk_ctx_set_bounds(ctx, 2, mun), FRICREG_OK);
    expect_fail(ctx, fricreg_disk_ctx_tangent(ctx, 2, T, NULL), FRICREG_EINVAL); /* stale */
    ck_assert_int_eq(fricreg_disk_ctx_tangent(NULL, 2, T, NULL), FRICREG_ENULL);
    /* the message copy */
    char buf[8];
    size_t len = fricreg_disk_ctx_errmsg_copy(ctx, buf, sizeof buf);
    ck_assert_uint_eq(len, strlen(fricreg_disk_ctx_errmsg(ctx)));
    ck_assert_uint_eq(strlen(buf), 7);
    ck_assert_uint_eq(fricreg_disk_ctx_errmsg_copy(ctx, NULL, 4), 0);
    fricreg_disk_ctx_free(ctx);
    fricreg_disk_ctx_free(NULL);
}
END_TEST

/* A singular dense W (two contacts with identical rows) is accepted; eval returns a status. */
START_TEST(test_singular_dense)
{
    double W[16] = {1, 0, 1, 0, 0, 1, 0, 1, 1, 0, 1, 0, 0, 1, 0, 1};
    double mun[2] = {1.0, 1.0}, zdot[4] = {0}, afree[4] = {0.1, 0.1, 0.1, 0.1}, f[4], T[16];
    fricreg_disk_ctx *ctx = make_ctx(2, FRICREG_DISK_QUINN, 0.1, mun, W);
    int status = fricreg_disk_ctx_eval(ctx, 2, zdot, afree, f);
    ck_assert(status == FRICREG_OK || status == FRICREG_ESINGULAR);
    if (status == FRICREG_OK) { /* any minimizer: W f + a_free = 0 */
        ck_assert_double_eq_tol(f[0] + f[2], -0.1, 1e-12);
        expect_fail(ctx, fricreg_disk_ctx_tangent(ctx, 2, T, NULL), FRICREG_ESINGULAR);
    }
    fricreg_disk_ctx_free(ctx);
}
END_TEST

/* A failed evaluation keeps the tangent of the last successful one (fricreg_disk_ctx.h): the
 * fuzz target found it refused (FRICREG_EINVAL) after an ESINGULAR. Both contacts at rest and
 * inside their disks: f = -W^-1 a_free, so d f/d a_free = -W^-1, W = s [[1, 1/2], [1/2, 1]] (x)
 * I, W^-1 = (1/(0.75 s)) [[1, -1/2], [-1/2, 1]] (x) I. Then contact 1 slides with its bound
 * 1e250, W_01 f_1 ~ 5e349 overflows: ENONFINITE. */
START_TEST(test_tangent_kept_after_failed_eval)
{
    const double s = 1e100, h = 0.5 * s;
    double W[16] = {s, 0, h, 0, 0, s, 0, h, h, 0, s, 0, 0, h, 0, s};
    double mun[2] = {1.0, 1e250}, zdot[4] = {0}, slide[4] = {0, 0, 1.0, 0};
    double afree[4] = {0.3 * s, -0.2 * s, 0.1 * s, 0.4 * s}, f[4], T[16];
    fricreg_disk_ctx *ctx = make_ctx(2, FRICREG_DISK_QUINN, 0.1, mun, W);
    eval_ok(ctx, 2, zdot, afree, f);
    ck_assert_double_eq_tol(hypot(f[0], f[1]), hypot(0.25, 0.4) / 0.75, 1e-15); /* inside */
    for (int k = 0; k < 4; k++)
        f[k] = SENTINEL;
    expect_fail(ctx, fricreg_disk_ctx_eval(ctx, 2, slide, afree, f), FRICREG_ENONFINITE);
    for (int k = 0; k < 4; k++)
        ck_assert_double_eq(f[k], SENTINEL);
    int status = fricreg_disk_ctx_tangent(ctx, 2, NULL, T);
    ck_assert_msg(status == FRICREG_OK, "tangent after a failed eval: %d %s", status,
                  fricreg_disk_ctx_errmsg(ctx));
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++) {
            double inv = r % 2 != c % 2 ? 0.0 : (r / 2 == c / 2 ? 1.0 : -0.5) / (0.75 * s);
            ck_assert_msg(fabs(T[4 * r + c] + inv) <= 1e-15 / s, "d f/d a_free [%d][%d] = %g", r, c,
                          T[4 * r + c]);
        }
    fricreg_disk_ctx_free(ctx);
}
END_TEST

/* A disk far smaller than the point it projects (mun = 1e-303 beside f_eq ~ 1e12): over a
 * disk that small the W_ii-metric projection is f = -mun g/|g| (g = a_free at rest, the
 * gradient at f = 0), whatever the block's anisotropy. The multiplier |D t|/mun overflows a
 * double; the fuzz target found the Euclidean projection's direction, A^-1 g, used instead:
 * (-1e-6, -1) mun/|.| here, not (-1, -1)/sqrt 2. */
START_TEST(test_tiny_disk_anisotropic_block)
{
    double w[4] = {1e6, 0.0, 0.0, 1.0}, mun = 1e-303, zdot[2] = {0.0, 0.0};
    double afree[2] = {1e12, 1e12}, f[2];
    fricreg_disk_ctx *ctx = make_ctx(1, FRICREG_DISK_QUINN, 1e-3, &mun, NULL);
    ck_assert_int_eq(fricreg_disk_ctx_set_coupling_blocks(ctx, 1, w), FRICREG_OK);
    eval_ok(ctx, 1, zdot, afree, f);
    for (int k = 0; k < 2; k++)
        ck_assert_msg(fabs(f[k] + mun / sqrt(2.0)) <= 1e-15 * mun, "f = (%g, %g)", f[0], f[1]);
    fricreg_disk_ctx_free(ctx);
}
END_TEST

/* Slopes near the double range: mun/eps = 4.5e307 (eps = DBL_MIN), a contact at rest on its
 * circle. The fuzz target found NaN in df_dzdot with FRICREG_OK; now FRICREG_ENONFINITE with
 * nothing written, while eps = 1e-300 (slopes ~ 1e300, checked by the same dry run) gives a
 * finite tangent; with W = I the force is f_eq/|f_eq| (f_eq = -a_free), so df/da_free =
 * -(I - n n^T)/|f_eq|, entries within [-1, 1]. */
START_TEST(test_tangent_overflow_refused)
{
    double mun = 1.0, zdot[2] = {0.0, 0.0}, afree[2] = {0.5, -1.0}, f[2], T[4], A[4];
    fricreg_disk_ctx *ctx = make_ctx(1, FRICREG_DISK_QUINN, DBL_MIN, &mun, NULL);
    eval_ok(ctx, 1, zdot, afree, f);
    ck_assert_double_eq_tol(hypot(f[0], f[1]), 1.0, 1e-15); /* on the circle */
    for (int k = 0; k < 4; k++)
        T[k] = SENTINEL;
    expect_fail(ctx, fricreg_disk_ctx_tangent(ctx, 1, T, NULL), FRICREG_ENONFINITE);
    for (int k = 0; k < 4; k++)
        ck_assert_double_eq(T[k], SENTINEL);
    ck_assert_int_eq(fricreg_disk_ctx_set_law(ctx, FRICREG_DISK_QUINN, 1e-300), FRICREG_OK);
    eval_ok(ctx, 1, zdot, afree, f);
    ck_assert_int_eq(fricreg_disk_ctx_tangent(ctx, 1, T, A), FRICREG_OK);
    for (int k = 0; k < 4; k++)
        ck_assert_msg(isfinite(T[k]) && fabs(A[k]) <= 1.0, "T %g A %g", T[k], A[k]);
    fricreg_disk_ctx_free(ctx);
}
END_TEST

/* An isotropic block with a bound far below |f_eq| (mun/|f_eq| underflows): f = mun f_eq/|f_eq|,
 * not 0 (fuzz finding: W = 2.1e-307 I, mun = 4.9e-324 gave f = 0). */
START_TEST(test_tiny_bound_isotropic)
{
    double mun = 1e-100, zdot[2] = {0.0, 0.0}, afree[2] = {-1e250, 0.0}, f[2];
    fricreg_disk_ctx *ctx = make_ctx(1, FRICREG_DISK_QUINN, 1e-3, &mun, NULL);
    eval_ok(ctx, 1, zdot, afree, f);
    ck_assert_msg(fabs(f[0] - mun) <= 1e-15 * mun && f[1] == 0.0, "f = (%g, %g)", f[0], f[1]);
    fricreg_disk_ctx_free(ctx);
}
END_TEST

/* The force-balance law at a subnormal velocity slides at the bound, |f| = mun (it gave
 * (-mun, -mun): |v| rounded on the subnormal grid). */
START_TEST(test_subnormal_velocity_slides)
{
    double mun = 2.385, zdot[2] = {4.9e-324, 4.9e-324}, afree[2] = {0.3, 0.1}, f[2];
    fricreg_disk_ctx *ctx = make_ctx(1, FRICREG_DISK_FORCE_BALANCE, 1e-3, &mun, NULL);
    eval_ok(ctx, 1, zdot, afree, f);
    ck_assert_double_eq_tol(f[0], -mun / sqrt(2.0), 1e-15 * mun);
    ck_assert_double_eq_tol(f[1], -mun / sqrt(2.0), 1e-15 * mun);
    fricreg_disk_ctx_free(ctx);
}
END_TEST

/* The header's range: every number at most 1e250 in magnitude. The coupling setters took a
 * block or a dense W with entries beyond it (EINVAL now, the context unchanged). */
START_TEST(test_coupling_beyond_1e250_refused)
{
    fricreg_disk_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_disk_ctx_create(1, &ctx), FRICREG_OK);
    const double big[4] = {2e250, 0.0, 0.0, 2e250}, edge[4] = {1e250, 0.0, 0.0, 1e250};
    ck_assert_int_eq(fricreg_disk_ctx_set_coupling_blocks(ctx, 1, big), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_disk_ctx_errmsg(ctx), "beyond 1e+250"));
    ck_assert_int_eq(fricreg_disk_ctx_set_coupling_dense(ctx, 1, big), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_disk_ctx_set_coupling_blocks(ctx, 1, edge), FRICREG_OK);
    ck_assert_int_eq(fricreg_disk_ctx_set_coupling_dense(ctx, 1, edge), FRICREG_OK);
    fricreg_disk_ctx_free(ctx);
}
END_TEST

static Suite *disk_ctx_suite(void)
{
    Suite *s = suite_create("disk_ctx");
    TCase *tc = tcase_create("core");
    /* the two comparisons with the test's own FISTA over random cases (500 evaluations, half
     * the program's time in the reference): natively and under ASan, not valgrind; 5 s, the
     * release tier's (disk_ctx_release) */
    TCase *sweeps = tcase_create("sweeps");
    tcase_set_tags(sweeps, "release");
    tcase_set_timeout(tc, 120);
    tcase_set_timeout(sweeps, 120);
    tcase_add_test(tc, test_isotropic_blocks_are_the_scalar_law);
    tcase_add_test(tc, test_force_balance_blocks);
    tcase_add_test(tc, test_rest_stick_exact);
    tcase_add_test(tc, test_rest_stick_strongly_coupled);
    tcase_add_test(sweeps, test_rest_saturated_dissipates_most);
    tcase_add_test(tc, test_anisotropic_block_metric);
    tcase_add_test(sweeps, test_random_against_fista);
    tcase_add_test(tc, test_continuity);
    tcase_add_test(tc, test_tangent_dense);
    tcase_add_test(tc, test_tangent_blocks);
    tcase_add_test(tc, test_tangent_at_rest_one_sided);
    tcase_add_test(tc, test_bad_input);
    tcase_add_test(tc, test_singular_dense);
    tcase_add_test(tc, test_tangent_kept_after_failed_eval);
    tcase_add_test(tc, test_tiny_disk_anisotropic_block);
    tcase_add_test(tc, test_tangent_overflow_refused);
    tcase_add_test(tc, test_tiny_bound_isotropic);
    tcase_add_test(tc, test_subnormal_velocity_slides);
    tcase_add_test(tc, test_coupling_beyond_1e250_refused);
    suite_add_tcase(s, tc);
    suite_add_tcase(s, sweeps);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(disk_ctx_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
