/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_stribeck_ctx.c — Check suite for static > kinetic (Stribeck) friction in the 1-D context
 * (fricreg_ctx_set_stribeck, fricreg_stribeck.h).
 *
 * Where the numbers come from:
 *   - the scalar law fricreg_stribeck_eval (itself checked against closed forms in
 *     test_stribeck.c): with W diagonal the context must give its numbers at
 *     f_eq,i = -a_free,i/W_ii bit for bit; with a dense W, the consistent law's defining
 *     property (docs/coupled.md) is that each f_i is the scalar law at
 *     f_eq,i = -(a_free,i + sum_{j != i} W_ij f_j)/W_ii, which the test forms itself from the
 *     returned f; the paper's partition, that W_SS f_eq,S = -(a_free,S + W_SL f_L);
 *   - law (4) in a context with set_bounds(fk): fs = fk must give its bits;
 *   - Coulomb's stick problem at rest: f = -W^-1 a_free while |f_i| <= fs_i (GSL's Cholesky),
 *     and at break-away the Schur complement: zddot_j = (1 - t) fs_j / (W^-1)_jj;
 *   - central differences for the tangent, on states where the one-sided differences agree
 *     (no kink within the step);
 *   - the Lipschitz continuity of the consistent law, measured as a jump free of the slope.
 * Inputs from a fixed splitmix64 generator. */
#include <check.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <gsl/gsl_linalg.h>

#include "fricreg.h"
#include "fricreg_stribeck.h"
#include "random.h"
#include "quiet_check.h"

#define MMAX 6
#define SENTINEL (-777.125)

static uint64_t rng_state;

static double uniform(double lo, double hi)
{
    return splitmix64_uniform(&rng_state, lo, hi);
}

static size_t uniform_size(size_t lo, size_t hi) /* in [lo, hi] */
{
    return random_size(splitmix64_uniform, &rng_state, lo, hi);
}

/* ---- Cases ------------------------------------------------------------------------------- */

enum coupling { DIAGONAL, DENSE_DIAGONAL, COUPLED };

typedef struct {
    size_t m;
    double W[MMAX * MMAX]; /* row-major, SPD; diagonal for DIAGONAL and DENSE_DIAGONAL */
    double fs[MMAX], fk[MMAX], vs[MMAX], delta[MMAX];
    double eps, zdot[MMAX], a_free[MMAX];
} stribeck_case;

/* W = D (A A^T / m + d I) D: SPD, condition number at most a few hundred. */
static void random_spd(size_t m, double W[])
{
    double work[MMAX * MMAX + MMAX];
    random_scaled_spd(splitmix64_uniform, &rng_state, m, 0.2, 1.0, work, W);
}

/* Velocities: some at rest, most in the band, some sliding; some exactly on the band's edge. */
static double random_velocity(double eps)
{
    double r = uniform(0.0, 1.0);
    if (r < 0.12)
        return 0.0;
    if (r < 0.18)
        return r < 0.15 ? eps : -eps;
    if (r < 0.75)
        return uniform(-eps, eps);
    return (r < 0.875 ? 1.0 : -1.0) * eps * uniform(1.0, 4.0);
}

static void random_case(stribeck_case *c, size_t m, enum coupling kind)
{
    c->m = m;
    memset(c->W, 0, sizeof c->W);
    if (kind == COUPLED)
        random_spd(m, c->W);
    else
        for (size_t i = 0; i < m; i++)
            c->W[i * m + i] = uniform(0.3, 3.0);
    c->eps = uniform(0.005, 0.2);
    for (size_t i = 0; i < m; i++) {
        c->fs[i] = uniform(0.2, 4.1);
        c->fk[i] = c->fs[i] * uniform(0.3, 1.0);
        c->vs[i] = c->eps * uniform(0.3, 20.0);
        c->delta[i] = uniform(0.4, 2.6);
    }
    for (size_t i = 0; i < m; i++) {
        double reach = 0.0;
        for (size_t k = 0; k < m; k++)
            reach += fabs(c->W[i * m + k]) * c->fs[k];
        c->zdot[i] = random_velocity(c->eps);
        c->a_free[i] = uniform(-1.2, 1.2) * (reach + 0.1);
    }
}

static double max_fs(const stribeck_case *c)
{
    double r = 0.0;
    for (size_t i = 0; i < c->m; i++)
        r = fmax(r, c->fs[i]);
    return r;
}

static void ok(fricreg_ctx *ctx, int status)
{
    QUIET_ASSERT(status == FRICREG_OK, "status %d: %s", status, fricreg_ctx_errmsg(ctx));
}

/* A context for case c: its coupling, the partition, law (4) at c->eps, Stribeck friction. */
static fricreg_ctx *make_ctx(const stribeck_case *c, enum coupling kind, int partition)
{
    fricreg_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_ctx_create(c->m, &ctx), FRICREG_OK);
    double w[MMAX];
    for (size_t i = 0; i < c->m; i++)
        w[i] = c->W[i * c->m + i];
    ok(ctx, kind == DIAGONAL ? fricreg_ctx_set_coupling_diagonal(ctx, c->m, w)
                             : fricreg_ctx_set_coupling_dense(ctx, c->m, c->W));
    ok(ctx, fricreg_ctx_set_partition(ctx, partition));
    ok(ctx, fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, c->eps));
    ok(ctx, fricreg_ctx_set_stribeck(ctx, c->m, c->fs, c->fk, c->vs, c->delta));
    return ctx;
}

static void eval(fricreg_ctx *ctx, const stribeck_case *c, const double zdot[],
                 const double a_free[], double f[], double f_eq[])
{
    ok(ctx, fricreg_ctx_eval(ctx, c->m, zdot, a_free, f, f_eq));
}

/* The scalar law of contact i at (v, g). */
static double scalar_law(const stribeck_case *c, size_t i, double v, double g)
{
    double f = SENTINEL;
    int status = fricreg_stribeck_eval(v, g, c->fs[i], c->fk[i], c->vs[i], c->delta[i], c->eps, &f);
    QUIET_OK(status);
    return f;
}

/* ---- 1. The law: W diagonal, dense, coupled ---------------------------------------------- */

/* W diagonal (set_coupling_diagonal): fricreg_stribeck_eval at f_eq = -a_free/W_ii, bit for
 * bit, and the same from the batch function; f_eq out is that value in the band, NaN off it. */
START_TEST(diagonal_is_the_scalar_law_bit_for_bit)
{
    rng_state = 0x57c0001u;
    long compared = 0;
    for (int n = 0; n < 400; n++) {
        stribeck_case c;
        random_case(&c, uniform_size(1, MMAX), DIAGONAL);
        fricreg_ctx *ctx = make_ctx(&c, DIAGONAL, FRICREG_PARTITION_CONSISTENT);
        for (int rep = 0; rep < 5; rep++) {
            double f[MMAX], f_eq[MMAX], g[MMAX], fb[MMAX];
            for (size_t i = 0; i < c.m; i++) {
                c.zdot[i] = random_velocity(c.eps);
                g[i] = -c.a_free[i] / c.W[i * c.m + i];
            }
            eval(ctx, &c, c.zdot, c.a_free, f, f_eq);
            ck_assert_int_eq(fricreg_stribeck_eval_batch(c.eps, c.m, c.zdot, g, c.fs, c.fk, c.vs,
                                                         c.delta, fb),
                             FRICREG_OK);
            for (size_t i = 0; i < c.m; i++, compared++) {
                double want = scalar_law(&c, i, c.zdot[i], g[i]);
                ck_assert_msg(f[i] == want && fb[i] == want,
                              "case %d contact %zu: ctx %.17g, scalar %.17g, batch %.17g", n, i,
                              f[i], want, fb[i]);
                if (fabs(c.zdot[i]) < c.eps)
                    ck_assert(f_eq[i] == g[i]);
                else
                    ck_assert(isnan(f_eq[i]));
            }
        }
        fricreg_ctx_free(ctx);
    }
    ck_assert_int_gt(compared, 5000);
}
END_TEST

/* A dense W that happens to be diagonal, both partitions: the scalar law to rounding (the QP
 * or the solve divides where the diagonal pass does not). */
START_TEST(dense_diagonal_is_the_scalar_law)
{
    rng_state = 0x57c0002u;
    for (int partition = 1; partition <= 2; partition++)
        for (int n = 0; n < 300; n++) {
            stribeck_case c;
            random_case(&c, uniform_size(1, MMAX), DENSE_DIAGONAL);
            fricreg_ctx *ctx = make_ctx(&c, DENSE_DIAGONAL, partition);
            for (int rep = 0; rep < 4; rep++) {
                double f[MMAX];
                for (size_t i = 0; i < c.m; i++)
                    c.zdot[i] = random_velocity(c.eps);
                eval(ctx, &c, c.zdot, c.a_free, f, NULL);
                for (size_t i = 0; i < c.m; i++) {
                    double g = -c.a_free[i] / c.W[i * c.m + i];
                    double want = scalar_law(&c, i, c.zdot[i], g);
                    ck_assert_msg(fabs(f[i] - want) <= 1e-13 * (c.fs[i] + fabs(g)),
                                  "partition %d case %d contact %zu: %.17g vs %.17g", partition, n,
                                  i, f[i], want);
                }
            }
            fricreg_ctx_free(ctx);
        }
}
END_TEST

/* Coupled W, consistent law: every f_i is the scalar law at the f_eq,i the test forms from the
 * returned forces (the QP's optimality, docs/coupled.md); f_eq out agrees with it. Random
 * walks, so the warm start is exercised too. */
START_TEST(coupled_consistent_is_the_law_at_each_contact)
{
    rng_state = 0x57c0003u;
    long near = 0;
    for (int n = 0; n < 300; n++) {
        stribeck_case c;
        random_case(&c, uniform_size(2, MMAX), COUPLED);
        fricreg_ctx *ctx = make_ctx(&c, COUPLED, FRICREG_PARTITION_CONSISTENT);
        for (int step = 0; step < 12; step++) {
            size_t j = uniform_size(0, c.m - 1);
            c.zdot[j] = random_velocity(c.eps);
            c.a_free[j] *= uniform(0.5, 1.5);
            double f[MMAX], f_eq[MMAX];
            eval(ctx, &c, c.zdot, c.a_free, f, f_eq);
            for (size_t i = 0; i < c.m; i++) {
                double others = 0.0, size = fabs(c.a_free[i]);
                for (size_t k = 0; k < c.m; k++)
                    if (k != i) {
                        others += c.W[i * c.m + k] * f[k];
                        size += fabs(c.W[i * c.m + k] * f[k]);
                    }
                double g = -(c.a_free[i] + others) / c.W[i * c.m + i];
                double tol = 1e-12 * (size / c.W[i * c.m + i] + c.fs[i]);
                double want = scalar_law(&c, i, c.zdot[i], g);
                ck_assert_msg(fabs(f[i] - want) <= tol,
                              "case %d step %d contact %zu: f %.17g, law at f_eq %.17g", n, step, i,
                              f[i], want);
                if (fabs(c.zdot[i]) < c.eps) {
                    ck_assert(fabs(f_eq[i] - g) <= tol);
                    near++;
                }
            }
        }
        fricreg_ctx_free(ctx);
    }
    ck_assert_int_gt(near, 3000);
}
END_TEST

/* Coupled W, the paper's partition: f_eq,S solves W_SS f_eq,S = -(a_free,S + W_SL f_L) with the
 * slip forces -k(|zdot|) sgn(zdot), and f is the scalar law at the returned f_eq. */
START_TEST(coupled_paper_is_the_law_at_the_joint_feq)
{
    rng_state = 0x57c0004u;
    for (int n = 0; n < 300; n++) {
        stribeck_case c;
        random_case(&c, uniform_size(2, MMAX), COUPLED);
        fricreg_ctx *ctx = make_ctx(&c, COUPLED, FRICREG_PARTITION_PAPER);
        double f[MMAX], f_eq[MMAX];
        eval(ctx, &c, c.zdot, c.a_free, f, f_eq);
        for (size_t i = 0; i < c.m; i++) {
            int in_band = fabs(c.zdot[i]) < c.eps;
            double g = in_band ? f_eq[i] : 0.0, want = scalar_law(&c, i, c.zdot[i], g);
            ck_assert_msg(f[i] == want, "case %d contact %zu: %.17g vs %.17g", n, i, f[i], want);
            if (!in_band)
                continue;
            double r = c.a_free[i], size = fabs(r); /* row i of W f_eq,S + a + W_SL f_L */
            for (size_t k = 0; k < c.m; k++) {
                double x = fabs(c.zdot[k]) < c.eps ? f_eq[k] : f[k];
                r += c.W[i * c.m + k] * x;
                size += fabs(c.W[i * c.m + k] * x);
            }
            ck_assert_msg(fabs(r) <= 1e-12 * size, "case %d row %zu residual %.3g of %.3g", n, i, r,
                          size);
        }
        fricreg_ctx_free(ctx);
    }
}
END_TEST

/* fs == fk: the numbers of law (4) with set_bounds(fk), bit for bit (f, f_eq and the tangent),
 * for every coupling and partition. Two contexts fed the same calls: their warm starts (the
 * QP's working sets) then agree too, and a different working set could change the rounding. */
START_TEST(equal_static_and_kinetic_is_law4_bit_for_bit)
{
    rng_state = 0x57c0005u;
    long compared = 0;
    for (int kind = DIAGONAL; kind <= COUPLED; kind++)
        for (int partition = 1; partition <= 2; partition++)
            for (int n = 0; n < 60; n++) {
                stribeck_case c;
                random_case(&c, uniform_size(1, MMAX), kind);
                for (size_t i = 0; i < c.m; i++)
                    c.fk[i] = c.fs[i];
                fricreg_ctx *st = make_ctx(&c, kind, partition);
                fricreg_ctx *law4 = make_ctx(&c, kind, partition);
                ok(law4, fricreg_ctx_set_bounds(law4, c.m, c.fk));
                for (int step = 0; step < 10; step++) {
                    size_t j = uniform_size(0, c.m - 1);
                    c.zdot[j] = random_velocity(c.eps);
                    double f1[MMAX], f2[MMAX], e1[MMAX], e2[MMAX];
                    double t1[MMAX * MMAX], t2[MMAX * MMAX], d1[MMAX * MMAX], d2[MMAX * MMAX];
                    eval(st, &c, c.zdot, c.a_free, f1, e1);
                    eval(law4, &c, c.zdot, c.a_free, f2, e2);
                    ck_assert(memcmp(f1, f2, c.m * sizeof *f1) == 0);
                    ck_assert(memcmp(e1, e2, c.m * sizeof *e1) == 0);
                    ok(st, fricreg_ctx_tangent(st, c.m, t1, d1));
                    ok(law4, fricreg_ctx_tangent(law4, c.m, t2, d2));
                    for (size_t k = 0; k < c.m * c.m; k++) /* == : +0 and -0 may differ */
                        QUIET_ASSERT(t1[k] == t2[k] && d1[k] == d2[k],
                                     "tangent entry %zu: %.17g vs %.17g", k, t1[k], t2[k]);
                    compared += (long)c.m;
                }
                fricreg_ctx_free(st);
                fricreg_ctx_free(law4);
            }
    ck_assert_int_gt(compared, 5000);
}
END_TEST

/* ---- 2. Continuity of the consistent law ------------------------------------------------- */

/* The jump of f at zdot_j = x, free of f's slope (test_coupled.c's measure): with
 * D(p, q) = f(q) - f(p), D(x-d, x+d) - (D(x+d, x+3d) + D(x-3d, x-d))/2 is O(f'' d^2) where f
 * is smooth on each side of x, and the jump where it jumps. Returns max_i of its modulus. */
static double jump_at(fricreg_ctx *ctx, const stribeck_case *c, size_t j, double x, double d)
{
    double zdot[MMAX], f[4][MMAX], jump = 0.0;
    static const double at[4] = {-3.0, -1.0, 1.0, 3.0};
    memcpy(zdot, c->zdot, c->m * sizeof *zdot);
    for (int k = 0; k < 4; k++) {
        zdot[j] = x + at[k] * d;
        eval(ctx, c, zdot, c->a_free, f[k], NULL);
    }
    for (size_t i = 0; i < c->m; i++) {
        double centre = f[2][i] - f[1][i];
        double sides = 0.5 * ((f[3][i] - f[2][i]) + (f[1][i] - f[0][i]));
        jump = fmax(jump, fabs(centre - sides));
    }
    return jump;
}

/* Random coupled cases: at every contact's band edges zdot_j = +-eps (where its bound turns
 * from B to k and other contacts' f_eq move) and at its rest zdot_j = 0 (the kink of |zdot| in
 * B), the consistent law's largest jump is <= 1e-12 max fs (docs/laws2d.md's continuity
 * criterion); the paper's partition, for comparison, jumps by more than 0.05 fs somewhere. */
START_TEST(consistent_is_continuous_across_band_edges)
{
    rng_state = 0x57c0006u;
    double consistent = 0.0, paper = 0.0;
    long edges = 0;
    for (int n = 0; n < 200; n++) {
        stribeck_case c;
        random_case(&c, uniform_size(2, MMAX), COUPLED);
        fricreg_ctx *cons = make_ctx(&c, COUPLED, FRICREG_PARTITION_CONSISTENT);
        fricreg_ctx *pap = make_ctx(&c, COUPLED, FRICREG_PARTITION_PAPER);
        double scale = max_fs(&c);
        for (size_t j = 0; j < c.m; j++)
            for (int side = -1; side <= 1; side++) {
                double x = side * c.eps, d = 1e-9 * c.eps;
                consistent = fmax(consistent, jump_at(cons, &c, j, x, d) / scale);
                paper = fmax(paper, jump_at(pap, &c, j, x, d) / scale);
                edges++;
            }
        fricreg_ctx_free(cons);
        fricreg_ctx_free(pap);
    }
    printf("stribeck ctx: largest jump / max fs over %ld edges: consistent %.3g, paper %.3g\n",
           edges, consistent, paper);
    fflush(stdout);
    ck_assert_msg(consistent <= 1e-12, "consistent law jumps by %.3g max fs", consistent);
    ck_assert_msg(paper > 0.05, "the paper's partition did not jump: %.3g", paper);
}
END_TEST

/* A fine sweep of one contact's velocity through the whole band and past it, the others fixed:
 * neighbouring samples differ by at most L h, L = max over the sweep of the tangent's
 * |d f_i/d zdot_j| (largest found, with a 2x margin), and across the sweep f_j runs from
 * about k(1.5 eps) on one side to -k(1.5 eps) on the other; no step is a jump. */
START_TEST(fine_sweeps_have_no_jump)
{
    rng_state = 0x57c0007u;
    double worst = 0.0;
    for (int n = 0; n < 40; n++) {
        stribeck_case c;
        random_case(&c, uniform_size(2, MMAX), COUPLED);
        fricreg_ctx *ctx = make_ctx(&c, COUPLED, FRICREG_PARTITION_CONSISTENT);
        size_t j = uniform_size(0, c.m - 1), m = c.m;
        const int steps = 6000;
        double h = 3.0 * c.eps / steps, zdot[MMAX], prev[MMAX], f[MMAX], slope = 0.0;
        double dz[MMAX * MMAX];
        memcpy(zdot, c.zdot, sizeof zdot);
        for (int k = 0; k <= steps; k++) {
            zdot[j] = -1.5 * c.eps + k * h;
            eval(ctx, &c, zdot, c.a_free, f, NULL);
            ok(ctx, fricreg_ctx_tangent(ctx, m, dz, NULL));
            for (size_t i = 0; i < m; i++)
                slope = fmax(slope, fabs(dz[i * m + j]));
            if (k > 0)
                for (size_t i = 0; i < m; i++) {
                    double step = fabs(f[i] - prev[i]);
                    worst = fmax(worst, step / (2.0 * slope * h + 1e-13 * max_fs(&c)));
                }
            memcpy(prev, f, sizeof prev);
        }
        fricreg_ctx_free(ctx);
    }
    printf("stribeck ctx: largest step / (2 L h) over the fine sweeps: %.3g\n", worst);
    fflush(stdout);
    ck_assert_msg(worst <= 1.0, "a step of %.3g times the Lipschitz bound", worst);
}
END_TEST

/* ---- 3. Stick at rest and break-away ----------------------------------------------------- */

/* (W^-1)_jj by GSL's Cholesky (independent of the library's LDL^T). */
static double inverse_diagonal(size_t m, const double W[], size_t j)
{
    gsl_matrix *A = gsl_matrix_alloc(m, m);
    gsl_vector *b = gsl_vector_alloc(m), *y = gsl_vector_alloc(m);
    for (size_t i = 0; i < m; i++)
        for (size_t k = 0; k < m; k++)
            gsl_matrix_set(A, i, k, W[i * m + k]);
    ck_assert_int_eq(gsl_linalg_cholesky_decomp1(A), 0);
    gsl_vector_set_basis(b, j);
    gsl_linalg_cholesky_solve(A, b, y);
    double inv_jj = gsl_vector_get(y, j);
    gsl_matrix_free(A);
    gsl_vector_free(b);
    gsl_vector_free(y);
    return inv_jj;
}

/* At rest, a load the contacts can hold (the stick forces f* = -W^-1 a_free within 0.9 fs):
 * f = f*, W f + a_free = 0 to rounding, under both partitions; with fk well below fs, so
 * that holding needs the static bound. Then contact j's load is scaled to t fs_j: at
 * t = 1 - 1e-9 everything still holds; at t = 1 + 1e-6 contact j breaks away (consistent law):
 * f_j = sgn(f*_j) fs_j exactly, the others still hold (zero acceleration), and contact j
 * accelerates against its force at the Schur complement's rate, zddot_j = (1 - t) fs_j /
 * (W^-1)_jj sgn(f*_j). */
START_TEST(coupled_stick_at_rest_and_break_away)
{
    rng_state = 0x57c0008u;
    for (int n = 0; n < 200; n++) {
        stribeck_case c;
        size_t m = uniform_size(2, MMAX), j = uniform_size(0, m - 1);
        random_case(&c, m, COUPLED);
        double fstar[MMAX], a[MMAX], zero[MMAX] = {0}, f[MMAX];
        for (size_t i = 0; i < m; i++) {
            c.fk[i] = 0.4 * c.fs[i];
            fstar[i] = c.fs[i] * uniform(-0.9, 0.9);
        }
        for (int partition = 1; partition <= 2; partition++) {
            fricreg_ctx *ctx = make_ctx(&c, COUPLED, partition);
            for (size_t i = 0; i < m; i++) {
                a[i] = 0.0;
                for (size_t k = 0; k < m; k++)
                    a[i] -= c.W[i * m + k] * fstar[k];
            }
            eval(ctx, &c, zero, a, f, NULL);
            for (size_t i = 0; i < m; i++) {
                double acc = a[i], size = fabs(a[i]);
                for (size_t k = 0; k < m; k++) {
                    acc += c.W[i * m + k] * f[k];
                    size += fabs(c.W[i * m + k] * f[k]);
                }
                ck_assert_msg(fabs(f[i] - fstar[i]) <= 1e-12 * max_fs(&c),
                              "case %d: f[%zu] = %.17g, stick force %.17g", n, i, f[i], fstar[i]);
                ck_assert_msg(fabs(acc) <= 1e-13 * size, "case %d: zddot[%zu] = %.3g", n, i, acc);
            }
            fricreg_ctx_free(ctx);
        }
        /* break-away: contact j's load scaled to t fs_j (the others' loads unchanged) */
        double sign = fstar[j] < 0.0 ? -1.0 : 1.0;
        for (int below = 1; below >= 0; below--) {
            double t = below ? 1.0 - 1e-9 : 1.0 + 1e-6;
            fstar[j] = sign * t * c.fs[j];
            for (size_t i = 0; i < m; i++) {
                a[i] = 0.0;
                for (size_t k = 0; k < m; k++)
                    a[i] -= c.W[i * m + k] * fstar[k];
            }
            fricreg_ctx *ctx = make_ctx(&c, COUPLED, FRICREG_PARTITION_CONSISTENT);
            eval(ctx, &c, zero, a, f, NULL);
            double acc[MMAX];
            for (size_t i = 0; i < m; i++) {
                acc[i] = a[i];
                for (size_t k = 0; k < m; k++)
                    acc[i] += c.W[i * m + k] * f[k];
            }
            double tiny = 1e-12 * max_fs(&c) * c.W[0];
            for (size_t i = 0; i < m; i++)
                if (below || i != j)
                    ck_assert_msg(fabs(acc[i]) <= 1e-11 * max_fs(&c) * (1.0 + fabs(c.W[i * m + i])),
                                  "case %d t %.10g: zddot[%zu] = %.3g", n, t, i, acc[i]);
            if (!below) {
                ck_assert_msg(f[j] == sign * c.fs[j], "case %d: f_j %.17g, fs %.17g", n, f[j],
                              c.fs[j]);
                double want = (1.0 - t) * c.fs[j] / inverse_diagonal(m, c.W, j) * sign;
                ck_assert_msg(fabs(acc[j] - want) <= 1e-4 * fabs(want) + tiny,
                              "case %d: zddot_j %.17g, Schur %.17g", n, acc[j], want);
            } else {
                ck_assert_msg(fabs(f[j] - fstar[j]) <= 1e-12 * max_fs(&c), "case %d", n);
            }
            fricreg_ctx_free(ctx);
        }
    }
}
END_TEST

/* ---- 4. The tangent ---------------------------------------------------------------------- */

/* Random states of each coupling and partition: fricreg_ctx_tangent against central
 * differences of fricreg_ctx_eval in every zdot_j and a_free_j, where the one-sided
 * differences agree (no kink within h: those are skipped, and counted). */
static void check_tangent(enum coupling kind, int partition, uint64_t seed)
{
    rng_state = seed;
    long checked = 0, skipped = 0;
    for (int n = 0; n < 150; n++) {
        stribeck_case c;
        random_case(&c, uniform_size(kind == COUPLED ? 2 : 1, MMAX), kind);
        size_t m = c.m;
        for (size_t i = 0; i < m; i++) /* off the edges: they are kinks by definition */
            if (fabs(fabs(c.zdot[i]) - c.eps) < 1e-6 * c.eps || c.zdot[i] == 0.0)
                c.zdot[i] = uniform(-1.5, 1.5) * c.eps;
        fricreg_ctx *ctx = make_ctx(&c, kind, partition);
        double f[MMAX], dz[MMAX * MMAX], da[MMAX * MMAX];
        eval(ctx, &c, c.zdot, c.a_free, f, NULL);
        ok(ctx, fricreg_ctx_tangent(ctx, m, dz, da));
        for (int along_zdot = 0; along_zdot <= 1; along_zdot++)
            for (size_t j = 0; j < m; j++) {
                double in[MMAX], fp[MMAX], fm[MMAX], f0[MMAX];
                const double *base = along_zdot ? c.zdot : c.a_free;
                double h = along_zdot ? 1e-7 * c.eps : 1e-7 * (fabs(c.a_free[j]) + max_fs(&c));
                double scale = along_zdot ? max_fs(&c) / c.eps * 50.0 : 5.0;
                memcpy(in, base, m * sizeof *in);
                in[j] = base[j] + h;
                ok(ctx, fricreg_ctx_eval(ctx, m, along_zdot ? in : c.zdot,
                                         along_zdot ? c.a_free : in, fp, NULL));
                in[j] = base[j] - h;
                ok(ctx, fricreg_ctx_eval(ctx, m, along_zdot ? in : c.zdot,
                                         along_zdot ? c.a_free : in, fm, NULL));
                in[j] = base[j];
                ok(ctx, fricreg_ctx_eval(ctx, m, along_zdot ? in : c.zdot,
                                         along_zdot ? c.a_free : in, f0, NULL));
                for (size_t i = 0; i < m; i++) {
                    double fwd = (fp[i] - f0[i]) / h, bwd = (f0[i] - fm[i]) / h;
                    if (fabs(fwd - bwd) > 1e-4 * scale) {
                        skipped++;
                        continue;
                    }
                    double central = 0.5 * (fwd + bwd);
                    double t = (along_zdot ? dz : da)[i * m + j];
                    ck_assert_msg(fabs(t - central) <= 1e-5 * scale,
                                  "coupling %d partition %d case %d: d f_%zu/d %s_%zu = %.10g, "
                                  "central difference %.10g",
                                  (int)kind, partition, n, i, along_zdot ? "zdot" : "a_free", j, t,
                                  central);
                    checked++;
                }
            }
        fricreg_ctx_free(ctx);
    }
    printf("stribeck ctx tangent (coupling %d, partition %d): %ld entries checked, %ld at "
           "kinks skipped\n",
           (int)kind, partition, checked, skipped);
    fflush(stdout);
    ck_assert_int_gt(checked, 20 * skipped);
    ck_assert_int_gt(checked, 1500);
}

START_TEST(tangent_matches_central_differences)
{
    check_tangent(DIAGONAL, FRICREG_PARTITION_CONSISTENT, 0x57c0009u);
    check_tangent(COUPLED, FRICREG_PARTITION_CONSISTENT, 0x57c000au);
    check_tangent(COUPLED, FRICREG_PARTITION_PAPER, 0x57c000bu);
}
END_TEST

/* The hand-checked slopes of one contact (W = 1, eps = 0.1, fs = 2, fk = 1, vs = 0.2,
 * delta = 2, k(eps) = 1 + exp(-0.25) = 1.7788007830714049):
 *   slip at v = 0.3: -k'(0.3) = (fs - fk)(2/0.2)(1.5) exp(-2.25) = 15 exp(-2.25)
 *     = 1.5810348...: the kinetic curve falls, so f = -k rises with v;
 *   band, free, v = 0.05, f_eq = 0.1: f = f_eq - c B, c = 1, B = 2 + (k(eps) - 2)/2;
 *     d f/dv = -(2/eps)(B + |v| dB/d|v|) = -20 (2 + (k(eps) - 2)) = -20 k(eps). */
START_TEST(tangent_hand_values)
{
    fricreg_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_ctx_create(1, &ctx), FRICREG_OK);
    double fs = 2.0, fk = 1.0, vs = 0.2, delta = 2.0, keps = 1.0 + exp(-0.25), dz, da, f;
    ok(ctx, fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 0.1));
    ok(ctx, fricreg_ctx_set_stribeck(ctx, 1, &fs, &fk, &vs, &delta));
    double v = 0.3, a = 0.0;
    ok(ctx, fricreg_ctx_eval(ctx, 1, &v, &a, &f, NULL));
    ck_assert_double_eq_tol(f, -(1.0 + exp(-2.25)), 1e-15);
    ok(ctx, fricreg_ctx_tangent(ctx, 1, &dz, &da));
    ck_assert_double_eq_tol(dz, 15.0 * exp(-2.25), 1e-13);
    ck_assert(da == 0.0);
    v = 0.05, a = -0.1;
    ok(ctx, fricreg_ctx_eval(ctx, 1, &v, &a, &f, NULL));
    ck_assert_double_eq_tol(f, 0.1 - (2.0 + 0.5 * (keps - 2.0)), 1e-15);
    ok(ctx, fricreg_ctx_tangent(ctx, 1, &dz, &da));
    ck_assert_double_eq_tol(dz, -20.0 * keps, 1e-12);
    ck_assert_double_eq_tol(da, -1.0, 1e-15);
    fricreg_ctx_free(ctx);
}
END_TEST

/* ---- 5. How the setters combine, and bad input ------------------------------------------- */

static const double FS[3] = {2.385, 1.25, 0.75}, FK[3] = {1.5, 1.25, 0.25};
static const double VS[3] = {0.03, 0.2, 0.05}, DELTA[3] = {1.0, 2.0, 0.5};
static const double ZDOT[3] = {0.0125, -0.3, 0.0}, AFREE[3] = {0.5, -0.25, 3.0};

/* f of the 3-contact context (W = diag(1.5, 0.5, 2)) at ZDOT, AFREE. */
static void forces(fricreg_ctx *ctx, double f[3])
{
    ok(ctx, fricreg_ctx_eval(ctx, 3, ZDOT, AFREE, f, NULL));
}

static fricreg_ctx *three_contacts(void)
{
    fricreg_ctx *ctx = NULL;
    static const double w[3] = {1.5, 0.5, 2.0}, mun[3] = {0.5, 0.625, 1.125};
    ck_assert_int_eq(fricreg_ctx_create(3, &ctx), FRICREG_OK);
    ok(ctx, fricreg_ctx_set_coupling_diagonal(ctx, 3, w));
    ok(ctx, fricreg_ctx_set_bounds(ctx, 3, mun));
    return ctx;
}

/* The expected forces: the scalar Stribeck law at eps, or law `law` with the bounds
 * (0.5, 0.625, 1.125), at f_eq = -a_free/W_ii. */
static void stribeck_forces(double eps, double f[3])
{
    static const double w[3] = {1.5, 0.5, 2.0};
    for (int i = 0; i < 3; i++)
        ck_assert_int_eq(fricreg_stribeck_eval(ZDOT[i], -AFREE[i] / w[i], FS[i], FK[i], VS[i],
                                               DELTA[i], eps, &f[i]),
                         FRICREG_OK);
}

static void law_forces(int law, double eps, double f[3])
{
    static const double w[3] = {1.5, 0.5, 2.0}, mun[3] = {0.5, 0.625, 1.125};
    for (int i = 0; i < 3; i++)
        ck_assert_int_eq(fricreg_law_eval(law, ZDOT[i], -AFREE[i] / w[i], mun[i], eps, &f[i]),
                         FRICREG_OK);
}

static void assert_same(const double f[3], const double want[3], const char *what)
{
    for (int i = 0; i < 3; i++)
        ck_assert_msg(f[i] == want[i], "%s: f[%d] = %.17g, expected %.17g", what, i, f[i], want[i]);
}

START_TEST(setters_combine_as_documented)
{
    fricreg_ctx *ctx = three_contacts();
    double f[3], want[3], dz[9];
    /* set_stribeck selects law (4), keeping eps (here Karnopp's 0.04 before) */
    ok(ctx, fricreg_ctx_set_law(ctx, FRICREG_LAW_KARNOPP, 0.04));
    ok(ctx, fricreg_ctx_set_stribeck(ctx, 3, FS, FK, VS, DELTA));
    forces(ctx, f);
    stribeck_forces(0.04, want);
    assert_same(f, want, "stribeck at the kept eps");
    /* set_law with (4) changes eps and keeps Stribeck friction; the tangent needs an eval */
    ok(ctx, fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 0.02));
    ck_assert_int_eq(fricreg_ctx_tangent(ctx, 3, dz, NULL), FRICREG_EINVAL);
    forces(ctx, f);
    stribeck_forces(0.02, want);
    assert_same(f, want, "stribeck at the new eps");
    /* m = 0 switches it off: (4) with the bounds set before, which it did not change */
    ok(ctx, fricreg_ctx_set_stribeck(ctx, 0, NULL, NULL, NULL, NULL));
    forces(ctx, f);
    law_forces(FRICREG_LAW_QUINN, 0.02, want);
    assert_same(f, want, "off by m = 0");
    /* another law switches it off */
    ok(ctx, fricreg_ctx_set_stribeck(ctx, 3, FS, FK, VS, DELTA));
    ok(ctx, fricreg_ctx_set_law(ctx, FRICREG_LAW_KARNOPP, 0.02));
    forces(ctx, f);
    law_forces(FRICREG_LAW_KARNOPP, 0.02, want);
    assert_same(f, want, "off by set_law(karnopp)");
    ok(ctx, fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 0.02)); /* and it stays off */
    forces(ctx, f);
    law_forces(FRICREG_LAW_QUINN, 0.02, want);
    assert_same(f, want, "still off under (4)");
    /* set_bounds switches it off: its bounds are used */
    ok(ctx, fricreg_ctx_set_stribeck(ctx, 3, FS, FK, VS, DELTA));
    static const double mun[3] = {0.5, 0.625, 1.125};
    ok(ctx, fricreg_ctx_set_bounds(ctx, 3, mun));
    forces(ctx, f);
    assert_same(f, want, "off by set_bounds");
    fricreg_ctx_free(ctx);
}
END_TEST

/* The stick-zone stiffness uses fs: with W diagonal, max_i W_ii 2 fs_i/eps (stiffness.c's
 * closed form): contact 0's 1.5 * 2 * 2.385 / 0.02 = 357.75 (with mun it would be contact 2's
 * 2 * 2 * 1.125 / 0.02 = 225). */
START_TEST(stick_stiffness_uses_the_static_bound)
{
    fricreg_ctx *ctx = three_contacts();
    double lambda = 0.0;
    ok(ctx, fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 0.02));
    ok(ctx, fricreg_ctx_set_stribeck(ctx, 3, FS, FK, VS, DELTA));
    ok(ctx, fricreg_ctx_stick_stiffness(ctx, &lambda));
    ck_assert_double_eq_tol(lambda, 1.5 * 2.0 * 2.385 / 0.02, 1e-10);
    fricreg_ctx_free(ctx);
}
END_TEST

/* One bad call: its status, recorded with a message; the context's forces unchanged. */
static void expect_refused(fricreg_ctx *ctx, int want, size_t m, const double fs[],
                           const double fk[], const double vs[], const double delta[],
                           const double before[3], const char *what)
{
    int status = fricreg_ctx_set_stribeck(ctx, m, fs, fk, vs, delta);
    ck_assert_msg(status == want, "%s: status %d, expected %d", what, status, want);
    ck_assert_int_eq(fricreg_ctx_errcode(ctx), want);
    ck_assert_msg(fricreg_ctx_errmsg(ctx)[0] != '\0', "%s: no message", what);
    double f[3];
    forces(ctx, f);
    ck_assert_msg(memcmp(f, before, sizeof f) == 0, "%s: the context changed", what);
}

/* Each bad argument: NaN and Inf (ENONFINITE, before any range error elsewhere), fk > fs,
 * fk < 0, vs <= 0, delta <= 0 (EINVAL), a wrong m (ESIZE), a NULL array (ENULL); the context
 * is unchanged, with Stribeck friction off and on (other parameters then) before the call. */
START_TEST(bad_input_leaves_the_context_unchanged)
{
    ck_assert_int_eq(fricreg_ctx_set_stribeck(NULL, 3, FS, FK, VS, DELTA), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_ctx_set_stribeck(NULL, 0, NULL, NULL, NULL, NULL), FRICREG_ENULL);
    for (int on = 0; on <= 1; on++) {
        fricreg_ctx *ctx = three_contacts();
        if (on) {
            static const double fs2[3] = {1.0, 2.0, 3.0}, fk2[3] = {0.5, 0.5, 0.5};
            ok(ctx, fricreg_ctx_set_stribeck(ctx, 3, fs2, fk2, VS, DELTA));
        }
        double before[3];
        forces(ctx, before);
        const double *args[4] = {FS, FK, VS, DELTA};
        for (int a = 0; a < 4; a++)
            for (int k = 0; k < 6; k++) {
                double bad[3];
                memcpy(bad, args[a], sizeof bad);
                static const double values[6] = {NAN, INFINITY, -INFINITY, -0.5, 0.0, 9.0};
                bad[1] = values[k];
                const double *p[4] = {FS, FK, VS, DELTA};
                p[a] = bad;
                int want = k < 3 ? FRICREG_ENONFINITE : FRICREG_OK;
                if (k >= 3) /* in range? fs >= fk_1 = 1.25; fk in [0, fs_1]; vs, delta > 0 */
                    want = (a == 0 && bad[1] < FK[1]) ||
                                   (a == 1 && (bad[1] < 0.0 || bad[1] > FS[1])) ||
                                   (a >= 2 && bad[1] <= 0.0)
                               ? FRICREG_EINVAL
                               : FRICREG_OK;
                if (want == FRICREG_OK)
                    continue;
                char what[64];
                snprintf(what, sizeof what, "on %d arg %d value %g", on, a, values[k]);
                expect_refused(ctx, want, 3, p[0], p[1], p[2], p[3], before, what);
                /* a non-finite number anywhere decides before a range error elsewhere */
                if (k < 3 && a != 1) { /* fk_0 = 9 > fs_0: a range error at contact 0 */
                    static const double fk_high[3] = {9.0, 1.25, 0.25};
                    expect_refused(ctx, FRICREG_ENONFINITE, 3, p[0], fk_high, p[2], p[3], before,
                                   "nan before range");
                }
            }
        expect_refused(ctx, FRICREG_ESIZE, 2, FS, FK, VS, DELTA, before, "m = 2");
        expect_refused(ctx, FRICREG_ESIZE, 4, FS, FK, VS, DELTA, before, "m = 4");
        expect_refused(ctx, FRICREG_ENULL, 3, NULL, FK, VS, DELTA, before, "fs NULL");
        expect_refused(ctx, FRICREG_ENULL, 3, FS, FK, VS, NULL, before, "delta NULL");
        fricreg_ctx_free(ctx);
    }
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("stribeck_ctx");
    TCase *law = tcase_create("law");
    tcase_add_test(law, diagonal_is_the_scalar_law_bit_for_bit);
    tcase_add_test(law, dense_diagonal_is_the_scalar_law);
    tcase_add_test(law, coupled_consistent_is_the_law_at_each_contact);
    tcase_add_test(law, coupled_paper_is_the_law_at_the_joint_feq);
    tcase_add_test(law, equal_static_and_kinetic_is_law4_bit_for_bit);
    suite_add_tcase(s, law);
    TCase *cont = tcase_create("continuity");
    tcase_add_test(cont, consistent_is_continuous_across_band_edges);
    tcase_add_test(cont, fine_sweeps_have_no_jump);
    suite_add_tcase(s, cont);
    TCase *stick = tcase_create("stick");
    tcase_add_test(stick, coupled_stick_at_rest_and_break_away);
    suite_add_tcase(s, stick);
    TCase *tangent = tcase_create("tangent");
    tcase_add_test(tangent, tangent_matches_central_differences);
    tcase_add_test(tangent, tangent_hand_values);
    suite_add_tcase(s, tangent);
    TCase *setters = tcase_create("setters");
    tcase_add_test(setters, setters_combine_as_documented);
    tcase_add_test(setters, stick_stiffness_uses_the_static_bound);
    tcase_add_test(setters, bad_input_leaves_the_context_unchanged);
    suite_add_tcase(s, setters);
    return s;
}

int main(void)
{
    SRunner *runner = srunner_create(suite());
    srunner_run_all(runner, CK_NORMAL);
    int failed = srunner_ntests_failed(runner);
    srunner_free(runner);
    return failed == 0 ? 0 : 1;
}
