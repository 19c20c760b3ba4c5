/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_sparse_ctx.c — Check suite for a sparse W in the 1-D context
 * (fricreg_ctx_set_coupling_csr, _csc) and for fricreg_ctx_tangent_apply.
 *
 * The expected numbers come from the dense path on the same W (fricreg_ctx_set_coupling_dense,
 * whose own tests check it against closed forms and a brute-force QP: test_coupled.c), from
 * the diagonal path, and from closed forms:
 *   - random sparse SPD W (banded, with a few far entries; scaled unequally), every law, both
 *     partitions, Stribeck friction, along walks whose near-stick set changes by a few
 *     contacts (factor updates) or by many (fresh factorizations): the forces, f_eq and the
 *     tangent agree with the dense context's to 1e-12 (relative to the contact's bound);
 *   - one W given as CSR and CSC, zero- and one-based, whole and by either triangle, with
 *     duplicates and unsorted rows: the same forces bit for bit (the summed W is the same);
 *   - m = 20000 contacts in independent pairs (a block diagonal W): each pair's forces are a
 *     2-contact dense context's, and a diagonal W given sparse is the diagonal context;
 *   - fricreg_ctx_tangent_apply against fricreg_ctx_tangent's matrices times vectors;
 *   - redundant contacts: FRICREG_ESINGULAR, as the dense path; the setter's refusals, which
 *     leave the context as it was; the stick stiffness's Gershgorin bound against the dense
 *     eigenvalue. */
#include <check.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg.h"
#include "fricreg_stribeck.h"
#include "random.h"

#define MMAX 160
#define TOL 1e-12

static uint64_t rng_state;

static double uniform(double lo, double hi)
{
    return splitmix64_uniform(&rng_state, lo, hi);
}

static size_t uniform_size(size_t lo, size_t hi)
{
    return random_size(splitmix64_uniform, &rng_state, lo, hi);
}

/* ---- Sparse matrices ----------------------------------------------------------------------- */

/* A W of m contacts: dense row-major, and its non-zero entries as CSR (whole, zero-based). */
struct coupling {
    size_t m, nnz;
    double W[MMAX * MMAX];
    int64_t ptr[MMAX + 1], ind[MMAX * MMAX];
    double val[MMAX * MMAX];
};

static void to_csr(struct coupling *c)
{
    c->nnz = 0;
    for (size_t i = 0; i < c->m; i++) {
        c->ptr[i] = (int64_t)c->nnz;
        for (size_t j = 0; j < c->m; j++)
            if (c->W[i * c->m + j] != 0.0) {
                c->ind[c->nnz] = (int64_t)j;
                c->val[c->nnz++] = c->W[i * c->m + j];
            }
    }
    c->ptr[c->m] = (int64_t)c->nnz;
}

/* W = D (G G^T + delta I) D: G with two entries per row within three columns of the diagonal
 * and, in one row of ten, one far away; delta in [0.05, 0.3), D in [0.5, 2). SPD, banded with
 * a few far entries, condition a few hundred at most. */
static void random_sparse_spd(struct coupling *c, size_t m)
{
    static double G[MMAX * MMAX];
    double d[MMAX], delta = uniform(0.05, 0.3);
    c->m = m;
    memset(G, 0, m * m * sizeof *G);
    for (size_t i = 0; i < m; i++) {
        for (int k = 0; k < 2; k++) {
            size_t lo = i >= 3 ? i - 3 : 0, hi = i + 3 < m ? i + 3 : m - 1;
            G[i * m + uniform_size(lo, hi)] += uniform(-1.0, 1.0);
        }
        if (uniform(0.0, 1.0) < 0.1)
            G[i * m + uniform_size(0, m - 1)] += uniform(-0.5, 0.5);
    }
    for (size_t i = 0; i < m; i++)
        d[i] = uniform(0.5, 2.0);
    for (size_t i = 0; i < m; i++)
        for (size_t j = 0; j <= i; j++) {
            double s = i == j ? delta : 0.0;
            for (size_t k = 0; k < m; k++)
                s += G[i * m + k] * G[j * m + k];
            c->W[i * m + j] = c->W[j * m + i] = d[i] * s * d[j];
        }
    to_csr(c);
}

static fricreg_ctx *make_ctx(size_t m)
{
    fricreg_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_ctx_create(m, &ctx), FRICREG_OK);
    return ctx;
}

static fricreg_ctx *make_sparse(const struct coupling *c)
{
    fricreg_ctx *ctx = make_ctx(c->m);
    int status = fricreg_ctx_set_coupling_csr(ctx, c->m, 0, c->ptr, c->ind, c->val);
    ck_assert_msg(status == FRICREG_OK, "set_coupling_csr: %s", fricreg_ctx_errmsg(ctx));
    return ctx;
}

static fricreg_ctx *make_dense(const struct coupling *c)
{
    fricreg_ctx *ctx = make_ctx(c->m);
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, c->m, c->W), FRICREG_OK);
    return ctx;
}

/* ---- States ------------------------------------------------------------------------------ */

/* zdot: a sixth at rest (force balance's S), half in the band, the rest sliding. */
static double random_velocity(double eps)
{
    double r = uniform(0.0, 1.0);
    if (r < 1.0 / 6.0)
        return 0.0;
    if (r < 2.0 / 3.0)
        return uniform(-eps, eps);
    return (r < 5.0 / 6.0 ? 1.0 : -1.0) * eps * uniform(1.0, 3.0);
}

/* a_free = -W f* + noise, f* within +-1.3 mun: some contacts hold, some saturate. */
static void random_load(const struct coupling *c, const double mun[], double a_free[])
{
    double target[MMAX];
    for (size_t i = 0; i < c->m; i++)
        target[i] = uniform(-1.3, 1.3) * mun[i];
    for (size_t i = 0; i < c->m; i++) {
        double s = 0.0;
        for (size_t j = 0; j < c->m; j++)
            s += c->W[i * c->m + j] * target[j];
        a_free[i] = -s + uniform(-0.05, 0.05) * c->W[i * c->m + i] * mun[i];
    }
}

static void set_both(fricreg_ctx *a, fricreg_ctx *b, size_t m, const double mun[], int law,
                     double eps, int partition)
{
    fricreg_ctx *ctx[2] = {a, b};
    for (int k = 0; k < 2; k++) {
        ck_assert_int_eq(fricreg_ctx_set_bounds(ctx[k], m, mun), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_set_law(ctx[k], law, eps), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_set_partition(ctx[k], partition), FRICREG_OK);
    }
}

/* |got - want| <= TOL max(|want|, scale), NaN where NaN. One assertion per array: Check writes
 * every assertion's place to its log, a system call each. */
static void expect_close(const double got[], const double want[], size_t n, const double scale[],
                         const char *what, int step)
{
    size_t bad = n;
    for (size_t i = 0; i < n && bad == n; i++) {
        double size = fmax(fabs(want[i]), scale ? scale[i] : 1.0);
        if (isnan(want[i]) ? !isnan(got[i]) : !(fabs(got[i] - want[i]) <= TOL * size))
            bad = i;
    }
    ck_assert_msg(bad == n, "step %d: %s[%zu] = %.17g, expected %.17g (dense)", step, what, bad,
                  bad < n ? got[bad] : 0.0, bad < n ? want[bad] : 0.0);
}

/* ---- Sparse against dense ------------------------------------------------------------------ */

static const int laws[] = {
    FRICREG_LAW_QUINN,   FRICREG_LAW_KARNOPP,          FRICREG_LAW_FORCE_BALANCE,
    FRICREG_LAW_COULOMB, FRICREG_LAW_VELOCITY_LIMITED, FRICREG_LAW_TANH};
#define NLAWS (sizeof laws / sizeof laws[0])
#define NSTEPS 14

/* The tangents of both contexts agree, and so do their products with a direction. */
static void expect_same_tangent(fricreg_ctx *sparse, fricreg_ctx *dense, size_t m,
                                const double mun[], double eps, int step)
{
    static double Sz[MMAX * MMAX], Sa[MMAX * MMAX], Dz[MMAX * MMAX], Da[MMAX * MMAX];
    ck_assert_int_eq(fricreg_ctx_tangent(dense, m, Dz, Da), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_tangent(sparse, m, Sz, Sa), FRICREG_OK);
    double slope_scale[MMAX * MMAX];
    for (size_t k = 0; k < m * m; k++)
        slope_scale[k] = 2.0 * mun[k / m] / eps; /* the slopes' size */
    expect_close(Sz, Dz, m * m, slope_scale, "df_dzdot", step);
    expect_close(Sa, Da, m * m, NULL, "df_dafree", step);
}

static void walk(const struct coupling *c, int law, int partition, int stribeck)
{
    fricreg_ctx *sparse = make_sparse(c), *dense = make_dense(c);
    size_t m = c->m;
    double mun[MMAX], zdot[MMAX], a_free[MMAX], eps = uniform(0.01, 0.1);
    for (size_t i = 0; i < m; i++)
        mun[i] = uniform(0.25, 2.0);
    set_both(sparse, dense, m, mun, law, eps, partition);
    if (stribeck) {
        double fs[MMAX], fk[MMAX], vs[MMAX], delta[MMAX];
        for (size_t i = 0; i < m; i++) {
            fs[i] = mun[i];
            fk[i] = uniform(0.4, 0.9) * mun[i];
            vs[i] = uniform(0.5, 3.0) * eps;
            delta[i] = uniform(0.5, 2.0);
        }
        ck_assert_int_eq(fricreg_ctx_set_stribeck(sparse, m, fs, fk, vs, delta), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_set_stribeck(dense, m, fs, fk, vs, delta), FRICREG_OK);
    }
    for (size_t i = 0; i < m; i++)
        zdot[i] = random_velocity(eps);
    random_load(c, mun, a_free);
    for (int step = 0; step < NSTEPS; step++) {
        /* a few contacts move (updates), or a third of them (fresh factorizations) */
        size_t moves = step % 4 == 3 ? m / 3 : uniform_size(1, 3);
        for (size_t k = 0; step > 0 && k < moves; k++)
            zdot[uniform_size(0, m - 1)] = random_velocity(eps);
        if (step % 5 == 4)
            random_load(c, mun, a_free);
        double fs[MMAX], fd[MMAX], es[MMAX], ed[MMAX];
        int sd = fricreg_ctx_eval(dense, m, zdot, a_free, fd, ed);
        int ss = fricreg_ctx_eval(sparse, m, zdot, a_free, fs, es);
        ck_assert_msg(ss == sd, "step %d: sparse eval %d (%s), dense %d (%s)", step, ss,
                      fricreg_ctx_errmsg(sparse), sd, fricreg_ctx_errmsg(dense));
        if (sd != FRICREG_OK)
            continue;
        expect_close(fs, fd, m, mun, "f", step);
        expect_close(es, ed, m, mun, "f_eq", step);
        if (step % 3 == 0)
            expect_same_tangent(sparse, dense, m, mun, eps, step);
    }
    fricreg_ctx_free(sparse);
    fricreg_ctx_free(dense);
}

static const size_t sizes[] = {1, 2, 7, 23, 60, 150};
#define NSIZES (sizeof sizes / sizeof sizes[0])

/* Loop index: size x law x partition. */
START_TEST(sparse_matches_dense)
{
    size_t m = sizes[_i / (2 * NLAWS)];
    int law = laws[(_i / 2) % NLAWS];
    int partition = _i % 2 ? FRICREG_PARTITION_PAPER : FRICREG_PARTITION_CONSISTENT;
    rng_state = 0x5eed0000u + (uint64_t)_i;
    static struct coupling c;
    for (int trial = 0; trial < 2; trial++) {
        random_sparse_spd(&c, m);
        walk(&c, law, partition, 0);
    }
}
END_TEST

START_TEST(sparse_matches_dense_stribeck)
{
    size_t m = sizes[_i / 2];
    int partition = _i % 2 ? FRICREG_PARTITION_PAPER : FRICREG_PARTITION_CONSISTENT;
    rng_state = 0x57b1bec0u + (uint64_t)_i;
    static struct coupling c;
    random_sparse_spd(&c, m);
    walk(&c, FRICREG_LAW_QUINN, partition, 1);
}
END_TEST

/* The walks above update the sparse factor as well as refactor it: counted here on one. */
START_TEST(updates_are_used)
{
    rng_state = 0x0dda7e5u;
    static struct coupling c;
    random_sparse_spd(&c, 150);
    fricreg_ctx *sparse = make_sparse(&c);
    double mun[MMAX], zdot[MMAX], a_free[MMAX], f[MMAX], eps = 0.05;
    for (size_t i = 0; i < c.m; i++)
        mun[i] = uniform(0.25, 2.0);
    ck_assert_int_eq(fricreg_ctx_set_bounds(sparse, c.m, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(sparse, FRICREG_LAW_QUINN, eps), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_partition(sparse, FRICREG_PARTITION_PAPER), FRICREG_OK);
    for (size_t i = 0; i < c.m; i++)
        zdot[i] = random_velocity(eps);
    random_load(&c, mun, a_free);
    for (int step = 0; step < 40; step++) {
        zdot[uniform_size(0, c.m - 1)] = random_velocity(eps);
        ck_assert_int_eq(fricreg_ctx_eval(sparse, c.m, zdot, a_free, f, NULL), FRICREG_OK);
    }
    int64_t updates = 0, factorizations = 0;
    fricreg_ctx_get_stat(sparse, FRICREG_STAT_FACTOR_UPDATES, &updates);
    fricreg_ctx_get_stat(sparse, FRICREG_STAT_FACTORIZATIONS, &factorizations);
    ck_assert_msg(updates > 10 && factorizations < 20, "%lld updates, %lld factorizations",
                  (long long)updates, (long long)factorizations);
    fricreg_ctx_free(sparse);
}
END_TEST

/* ---- Input forms --------------------------------------------------------------------------- */

/* A 5 x 5 W with dyadic entries (sums exact): tridiagonal plus (0, 4). */
static const double W5[25] = {2.5,  -0.75, 0.0,  0.0,  0.25, -0.75, 3.0, 0.5, 0.0,
                              0.0,  0.0,   0.5,  1.75, -0.5, 0.0,   0.0, 0.0, -0.5,
                              2.25, 0.625, 0.25, 0.0,  0.0,  0.625, 4.0};
static const double MUN5[5] = {0.4125, 1.25, 0.3175, 2.0625, 0.8125};
static const double ZDOT5[5] = {1e-3, -0.375, 2.5e-3, 0.0, -4e-3};
static const double AFREE5[5] = {0.9375, -3.25, 0.0625, 1.625, -0.4375};

/* The entries of W5 in the triangle asked for (0 whole, 1 upper, -1 lower) as CSR arrays
 * (CSC: the same arrays read by columns, rows and columns swapped), each entry split in two
 * halves given in reverse order (duplicates, unsorted), indices from base. */
static size_t w5_arrays(int triangle, int64_t base, int64_t ptr[6], int64_t ind[50], double val[50])
{
    size_t n = 0;
    for (size_t i = 0; i < 5; i++) {
        ptr[i] = (int64_t)n + base;
        for (size_t jj = 5; jj-- > 0;) {
            double w = W5[i * 5 + jj];
            if (w == 0.0 || (triangle > 0 && jj < i) || (triangle < 0 && jj > i))
                continue;
            for (int half = 0; half < 2; half++) {
                ind[n] = (int64_t)jj + base;
                val[n++] = w / 2.0;
            }
        }
    }
    ptr[5] = (int64_t)n + base;
    return n;
}

static void eval5(fricreg_ctx *ctx, int partition, double f[5], double f_eq[5])
{
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, 5, MUN5), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 0.01), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_partition(ctx, partition), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 5, ZDOT5, AFREE5, f, f_eq), FRICREG_OK);
}

START_TEST(input_forms_agree)
{
    for (int partition = FRICREG_PARTITION_CONSISTENT; partition <= FRICREG_PARTITION_PAPER;
         partition++) {
        fricreg_ctx *dense = make_ctx(5);
        ck_assert_int_eq(fricreg_ctx_set_coupling_dense(dense, 5, W5), FRICREG_OK);
        double fd[5], ed[5], f0[5], e0[5];
        eval5(dense, partition, fd, ed);
        int first = 1;
        for (int csc = 0; csc < 2; csc++)
            for (int64_t base = 0; base < 2; base++)
                for (int triangle = -1; triangle <= 1; triangle++) {
                    int64_t ptr[6], ind[50];
                    double val[50], f[5], e[5];
                    w5_arrays(triangle, base, ptr, ind, val);
                    /* the CSR upper triangle's arrays are the CSC lower triangle's */
                    int tri = triangle == 0           ? 0
                              : (triangle > 0) != csc ? FRICREG_SPARSE_UPPER
                                                      : FRICREG_SPARSE_LOWER;
                    int flags = tri | (base ? FRICREG_SPARSE_ONE_BASED : 0);
                    fricreg_ctx *ctx = make_ctx(5);
                    int status = csc ? fricreg_ctx_set_coupling_csc(ctx, 5, flags, ptr, ind, val)
                                     : fricreg_ctx_set_coupling_csr(ctx, 5, flags, ptr, ind, val);
                    ck_assert_msg(status == FRICREG_OK, "csc %d base %d triangle %d: %s", csc,
                                  (int)base, triangle, fricreg_ctx_errmsg(ctx));
                    eval5(ctx, partition, f, e);
                    expect_close(f, fd, 5, MUN5, "f", 0);
                    expect_close(e, ed, 5, MUN5, "f_eq", 0);
                    if (first) {
                        memcpy(f0, f, sizeof f0);
                        memcpy(e0, e, sizeof e0);
                        first = 0;
                    }
                    ck_assert_msg(memcmp(f, f0, sizeof f0) == 0 && memcmp(e, e0, sizeof e0) == 0,
                                  "csc %d base %d triangle %d: not bit for bit the first form's",
                                  csc, (int)base, triangle);
                    fricreg_ctx_free(ctx);
                }
        fricreg_ctx_free(dense);
    }
}
END_TEST

/* ---- Large m: independent pairs, and a diagonal given sparse -------------------------------- */

#define NPAIRS 10000

/* W = blockdiag of the paper's two blocks [[1, -1], [-1, 2]] scaled per pair: each pair's
 * forces are a 2-contact dense context's. */
START_TEST(pairs_at_large_m)
{
    size_t m = 2 * NPAIRS;
    int64_t *ptr = malloc((m + 1) * sizeof *ptr), *ind = malloc(4 * NPAIRS * sizeof *ind);
    double *val = malloc(4 * NPAIRS * sizeof *val), *mun = malloc(m * sizeof *mun);
    double *zdot = malloc(m * sizeof *zdot), *a_free = malloc(m * sizeof *a_free);
    double *f = malloc(m * sizeof *f), *scale = malloc(NPAIRS * sizeof *scale);
    ck_assert(ptr && ind && val && mun && zdot && a_free && f && scale);
    rng_state = 0x9a125u;
    for (size_t p = 0, n = 0; p < NPAIRS; p++) {
        scale[p] = uniform(0.5, 2.0);
        const double w[4] = {scale[p], -scale[p], -scale[p], 2.0 * scale[p]};
        for (size_t r = 0; r < 2; r++) {
            ptr[2 * p + r] = (int64_t)n;
            for (size_t k = 0; k < 2; k++) {
                ind[n] = (int64_t)(2 * p + k);
                val[n++] = w[2 * r + k];
            }
        }
    }
    ptr[m] = 4 * NPAIRS;
    fricreg_ctx *ctx = make_ctx(m);
    ck_assert_int_eq(fricreg_ctx_set_coupling_csr(ctx, m, 0, ptr, ind, val), FRICREG_OK);
    for (int partition = FRICREG_PARTITION_CONSISTENT; partition <= FRICREG_PARTITION_PAPER;
         partition++) {
        double eps = 0.02;
        for (size_t i = 0; i < m; i++) {
            mun[i] = uniform(0.2, 1.0);
            zdot[i] = random_velocity(eps);
            a_free[i] = uniform(-2.0, 2.0);
        }
        ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, m, mun), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, eps), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_set_partition(ctx, partition), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_eval(ctx, m, zdot, a_free, f, NULL), FRICREG_OK);
        fricreg_ctx *pair = make_ctx(2);
        for (size_t p = 0; p < NPAIRS; p += 7) {
            const double w[4] = {scale[p], -scale[p], -scale[p], 2.0 * scale[p]};
            double fp[2];
            ck_assert_int_eq(fricreg_ctx_set_coupling_dense(pair, 2, w), FRICREG_OK);
            ck_assert_int_eq(fricreg_ctx_set_bounds(pair, 2, mun + 2 * p), FRICREG_OK);
            ck_assert_int_eq(fricreg_ctx_set_law(pair, FRICREG_LAW_QUINN, eps), FRICREG_OK);
            ck_assert_int_eq(fricreg_ctx_set_partition(pair, partition), FRICREG_OK);
            ck_assert_int_eq(fricreg_ctx_eval(pair, 2, zdot + 2 * p, a_free + 2 * p, fp, NULL),
                             FRICREG_OK);
            expect_close(f + 2 * p, fp, 2, mun + 2 * p, "f", (int)p);
        }
        fricreg_ctx_free(pair);
    }
    fricreg_ctx_free(ctx);
    free(ptr), free(ind), free(val), free(mun), free(zdot), free(a_free), free(f), free(scale);
}
END_TEST

START_TEST(diagonal_given_sparse)
{
    size_t m = 20000;
    int64_t *ptr = malloc((m + 1) * sizeof *ptr), *ind = malloc(m * sizeof *ind);
    double *w = malloc(m * sizeof *w), *zdot = malloc(m * sizeof *zdot);
    double *a_free = malloc(m * sizeof *a_free), *f = malloc(m * sizeof *f);
    double *fd = malloc(m * sizeof *fd), *e = malloc(m * sizeof *e), *ed = malloc(m * sizeof *ed);
    double *scale = malloc(m * sizeof *scale);
    ck_assert(ptr && ind && w && zdot && a_free && f && fd && e && ed && scale);
    rng_state = 0xd1a90u;
    for (size_t i = 0; i < m; i++) {
        ptr[i] = (int64_t)i + 1;
        ind[i] = (int64_t)i + 1;
        w[i] = uniform(0.5, 2.0);
        zdot[i] = random_velocity(0.01);
        a_free[i] = uniform(-2.0, 2.0);
        scale[i] = 1.0;
    }
    ptr[m] = (int64_t)m + 1;
    fricreg_ctx *sparse = make_ctx(m), *diagonal = make_ctx(m);
    ck_assert_int_eq(fricreg_ctx_set_coupling_csc(sparse, m, FRICREG_SPARSE_ONE_BASED, ptr, ind, w),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_coupling_diagonal(diagonal, m, w), FRICREG_OK);
    for (int partition = FRICREG_PARTITION_CONSISTENT; partition <= FRICREG_PARTITION_PAPER;
         partition++) {
        ck_assert_int_eq(fricreg_ctx_set_law(sparse, FRICREG_LAW_QUINN, 0.01), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_set_law(diagonal, FRICREG_LAW_QUINN, 0.01), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_set_partition(sparse, partition), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_eval(sparse, m, zdot, a_free, f, e), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_eval(diagonal, m, zdot, a_free, fd, ed), FRICREG_OK);
        expect_close(f, fd, m, scale, "f", partition);
        expect_close(e, ed, m, scale, "f_eq", partition);
        /* the product with a direction: the diagonal tangent's, contact by contact */
        ck_assert_int_eq(fricreg_ctx_tangent_apply(sparse, m, zdot, a_free, f), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_tangent_apply(diagonal, m, zdot, a_free, fd), FRICREG_OK);
        for (size_t i = 0; i < m; i++)
            scale[i] = 2.0 / 0.01 * fabs(zdot[i]) + fabs(a_free[i]) / w[i];
        expect_close(f, fd, m, scale, "df", partition);
    }
    fricreg_ctx_free(sparse);
    fricreg_ctx_free(diagonal);
    free(ptr), free(ind), free(w), free(zdot), free(a_free), free(f), free(fd), free(e), free(ed);
    free(scale);
}
END_TEST

/* ---- fricreg_ctx_tangent_apply ------------------------------------------------------------ */

/* df = Fz dz + Fa da from the tangent's matrices, against tangent_apply, directions NULL or
 * not, for one context after one evaluation. */
static void expect_apply_is_tangent(fricreg_ctx *ctx, size_t m, const char *what)
{
    static double Fz[MMAX * MMAX], Fa[MMAX * MMAX];
    double dz[MMAX], da[MMAX], df[MMAX], want[MMAX], size[MMAX];
    ck_assert_int_eq(fricreg_ctx_tangent(ctx, m, Fz, Fa), FRICREG_OK);
    for (size_t i = 0; i < m; i++) {
        dz[i] = uniform(-1.0, 1.0);
        da[i] = uniform(-1.0, 1.0);
    }
    for (int use = 1; use <= 3; use++) { /* bit 0: dz given, bit 1: da given */
        for (size_t i = 0; i < m; i++) {
            want[i] = size[i] = 0.0;
            for (size_t j = 0; j < m; j++) {
                double t = ((use & 1) ? Fz[i * m + j] * dz[j] : 0.0) +
                           ((use & 2) ? Fa[i * m + j] * da[j] : 0.0);
                want[i] += t;
                size[i] += fabs(t);
            }
            size[i] = fmax(size[i], 1e-300);
        }
        int status = fricreg_ctx_tangent_apply(ctx, m, (use & 1) ? dz : NULL, (use & 2) ? da : NULL,
                                               df);
        ck_assert_msg(status == FRICREG_OK, "%s: %s", what, fricreg_ctx_errmsg(ctx));
        expect_close(df, want, m, size, what, use);
    }
}

START_TEST(tangent_apply_matches_tangent)
{
    static struct coupling c;
    rng_state = 0xa991u + (uint64_t)_i;
    size_t m = _i % 2 ? 37 : 9;
    random_sparse_spd(&c, m);
    double mun[MMAX], zdot[MMAX], a_free[MMAX], f[MMAX], eps = 0.04;
    for (size_t i = 0; i < m; i++)
        mun[i] = uniform(0.25, 2.0);
    for (int kind = 0; kind < 3; kind++) { /* diagonal, dense, sparse */
        for (size_t l = 0; l < NLAWS; l++)
            for (int partition = FRICREG_PARTITION_CONSISTENT; partition <= FRICREG_PARTITION_PAPER;
                 partition++)
                for (int stribeck = 0; stribeck < 2; stribeck++) {
                    if (stribeck && laws[l] != FRICREG_LAW_QUINN)
                        continue;
                    fricreg_ctx *ctx = kind == 2   ? make_sparse(&c)
                                       : kind == 1 ? make_dense(&c)
                                                   : make_ctx(m);
                    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, m, mun), FRICREG_OK);
                    ck_assert_int_eq(fricreg_ctx_set_law(ctx, laws[l], eps), FRICREG_OK);
                    ck_assert_int_eq(fricreg_ctx_set_partition(ctx, partition), FRICREG_OK);
                    if (stribeck) {
                        double fk[MMAX], vs[MMAX], delta[MMAX];
                        for (size_t i = 0; i < m; i++) {
                            fk[i] = 0.6 * mun[i];
                            vs[i] = 2.0 * eps;
                            delta[i] = 1.5;
                        }
                        ck_assert_int_eq(fricreg_ctx_set_stribeck(ctx, m, mun, fk, vs, delta),
                                         FRICREG_OK);
                    }
                    for (int step = 0; step < 3; step++) {
                        for (size_t i = 0; i < m; i++)
                            zdot[i] = random_velocity(eps);
                        random_load(&c, mun, a_free);
                        ck_assert_int_eq(fricreg_ctx_eval(ctx, m, zdot, a_free, f, NULL),
                                         FRICREG_OK);
                        char what[80];
                        snprintf(what, sizeof what, "kind %d law %d partition %d stribeck %d", kind,
                                 laws[l], partition, stribeck);
                        expect_apply_is_tangent(ctx, m, what);
                    }
                    fricreg_ctx_free(ctx);
                }
    }
}
END_TEST

/* Its errors: each recorded, df untouched. */
START_TEST(tangent_apply_errors)
{
    static struct coupling c;
    rng_state = 0xe770u;
    random_sparse_spd(&c, 6);
    fricreg_ctx *ctx = make_sparse(&c);
    double dz[6] = {0}, df[6] = {-7.0, -7.0, -7.0, -7.0, -7.0, -7.0}, f[6];
    ck_assert_int_eq(fricreg_ctx_tangent_apply(NULL, 6, dz, dz, df), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_ctx_tangent_apply(ctx, 6, dz, NULL, df), FRICREG_EINVAL); /* no eval */
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 6, dz, dz, f, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_tangent_apply(ctx, 5, dz, NULL, df), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_ctx_tangent_apply(ctx, 6, dz, NULL, NULL), FRICREG_ENULL);
    dz[3] = NAN;
    ck_assert_int_eq(fricreg_ctx_tangent_apply(ctx, 6, NULL, dz, df), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_ctx_errcode(ctx), FRICREG_ENONFINITE);
    ck_assert_ptr_nonnull(strstr(fricreg_ctx_errmsg(ctx), "dafree[3]"));
    ck_assert_int_eq(fricreg_ctx_set_keep_tangent(ctx, 0), FRICREG_OK);
    dz[3] = 0.0;
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 6, dz, dz, f, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_tangent_apply(ctx, 6, dz, NULL, df), FRICREG_EINVAL);
    for (int i = 0; i < 6; i++)
        ck_assert(df[i] == -7.0);
    /* no direction at all: df = 0 */
    ck_assert_int_eq(fricreg_ctx_set_keep_tangent(ctx, 1), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 6, dz, dz, f, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_tangent_apply(ctx, 6, NULL, NULL, df), FRICREG_OK);
    for (int i = 0; i < 6; i++)
        ck_assert(df[i] == 0.0);
    /* all at rest and free: df = -W^-1 diag(2 W_ii mun_i/eps) dzdot, 2e3 W times 1e308 */
    double huge[6] = {1e308, 1e308, 1e308, 1e308, 1e308, 1e308}, kept[6];
    memcpy(kept, df, sizeof kept);
    ck_assert_int_eq(fricreg_ctx_tangent_apply(ctx, 6, huge, NULL, df), FRICREG_ENONFINITE);
    ck_assert_ptr_nonnull(strstr(fricreg_ctx_errmsg(ctx), "beyond the range"));
    ck_assert(memcmp(df, kept, sizeof kept) == 0);
    fricreg_ctx_free(ctx);
}
END_TEST

/* ---- Singular blocks, refused couplings --------------------------------------------------- */

/* Contacts 0 and 2 are redundant (W's rows 0 and 2 equal: rank 2 of 3), contact 1 apart. At
 * rest under loads both can hold, the block of {0, 2} is singular: FRICREG_ESINGULAR, as the
 * dense path. */
START_TEST(redundant_contacts_are_singular)
{
    const double W[9] = {1.5, 0.0, 1.5, 0.0, 2.0, 0.0, 1.5, 0.0, 1.5};
    const int64_t ptr[4] = {0, 2, 3, 5}, ind[5] = {0, 2, 1, 0, 2};
    const double val[5] = {1.5, 1.5, 2.0, 1.5, 1.5};
    const double zdot[3] = {0.0, 0.0, 0.0}, a_free[3] = {0.1, 0.2, 0.1}, mun[3] = {1, 1, 1};
    for (int partition = FRICREG_PARTITION_CONSISTENT; partition <= FRICREG_PARTITION_PAPER;
         partition++) {
        fricreg_ctx *sparse = make_ctx(3), *dense = make_ctx(3);
        ck_assert_int_eq(fricreg_ctx_set_coupling_csr(sparse, 3, 0, ptr, ind, val), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_set_coupling_dense(dense, 3, W), FRICREG_OK);
        double f[3] = {-7.0, -7.0, -7.0};
        for (int k = 0; k < 2; k++) {
            fricreg_ctx *ctx = k ? sparse : dense;
            ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, 3, mun), FRICREG_OK);
            ck_assert_int_eq(fricreg_ctx_set_partition(ctx, partition), FRICREG_OK);
            ck_assert_int_eq(fricreg_ctx_eval(ctx, 3, zdot, a_free, f, NULL), FRICREG_ESINGULAR);
            ck_assert_ptr_nonnull(strstr(fricreg_ctx_errmsg(ctx), "singular"));
            ck_assert(f[0] == -7.0 && f[1] == -7.0 && f[2] == -7.0);
        }
        fricreg_ctx_free(sparse);
        fricreg_ctx_free(dense);
    }
}
END_TEST

/* A refused W leaves the context as it was: the same forces, the tangent still there. */
static void expect_refused(fricreg_ctx *ctx, int status, int want, const char *text)
{
    ck_assert_msg(status == want, "status %d (%s), expected %d", status, fricreg_ctx_errmsg(ctx),
                  want);
    ck_assert_int_eq(fricreg_ctx_errcode(ctx), want);
    ck_assert_msg(strstr(fricreg_ctx_errmsg(ctx), text) != NULL, "message \"%s\" lacks \"%s\"",
                  fricreg_ctx_errmsg(ctx), text);
}

START_TEST(refused_couplings)
{
    fricreg_ctx *ctx = make_ctx(5);
    int64_t ptr[6], ind[50];
    double val[50], f0[5], e0[5], f[5], e[5], tz[25];
    w5_arrays(0, 0, ptr, ind, val);
    ck_assert_int_eq(fricreg_ctx_set_coupling_csr(ctx, 5, 0, ptr, ind, val), FRICREG_OK);
    eval5(ctx, FRICREG_PARTITION_CONSISTENT, f0, e0);
    const char *csr = "set_coupling_csr";
    expect_refused(ctx, fricreg_ctx_set_coupling_csr(ctx, 4, 0, ptr, ind, val), FRICREG_ESIZE, csr);
    expect_refused(ctx, fricreg_ctx_set_coupling_csr(ctx, 5, 0, NULL, ind, val), FRICREG_ENULL,
                   "rowptr");
    expect_refused(ctx, fricreg_ctx_set_coupling_csc(ctx, 5, 0, ptr, NULL, val), FRICREG_ENULL,
                   "rowind");
    expect_refused(ctx,
                   fricreg_ctx_set_coupling_csr(ctx, 5, FRICREG_SPARSE_UPPER | FRICREG_SPARSE_LOWER,
                                                ptr, ind, val),
                   FRICREG_EINVAL, "together");
    expect_refused(ctx, fricreg_ctx_set_coupling_csr(ctx, 5, 8, ptr, ind, val), FRICREG_EINVAL,
                   "flags");
    expect_refused(ctx, fricreg_ctx_set_coupling_csr(ctx, 5, FRICREG_SPARSE_UPPER, ptr, ind, val),
                   FRICREG_EINVAL, "triangle");
    int64_t bad = ind[3];
    ind[3] = 5;
    expect_refused(ctx, fricreg_ctx_set_coupling_csr(ctx, 5, 0, ptr, ind, val), FRICREG_EINVAL,
                   "colind");
    ind[3] = bad;
    double v = val[0];
    val[0] = NAN;
    expect_refused(ctx, fricreg_ctx_set_coupling_csr(ctx, 5, 0, ptr, ind, val), FRICREG_ENONFINITE,
                   "val");
    val[0] = v + 1e-9; /* W(0, 4) 0.25 + 1e-9 against W(4, 0) 0.25 */
    expect_refused(ctx, fricreg_ctx_set_coupling_csr(ctx, 5, 0, ptr, ind, val), FRICREG_ENOTSYM,
                   "W(0, 4)");
    val[0] = v;
    /* one-based: W(1, 1) left out of the pattern entirely */
    const int64_t ptr1[3] = {1, 3, 4}, ind1[3] = {1, 2, 1};
    const double val1[3] = {1.0, 0.5, 0.5};
    fricreg_ctx *two = make_ctx(2);
    expect_refused(two,
                   fricreg_ctx_set_coupling_csr(two, 2, FRICREG_SPARSE_ONE_BASED, ptr1, ind1, val1),
                   FRICREG_ENOTPSD, "W(2, 2) = 0");
    /* indefinite, though every 2 x 2 minor is positive: a_01 = a_12 = -a_02 = 0.9 */
    const int64_t ptr3[4] = {0, 3, 6, 9}, ind3[9] = {0, 1, 2, 0, 1, 2, 0, 1, 2};
    const double val3[9] = {1.0, 0.9, -0.9, 0.9, 1.0, 0.9, -0.9, 0.9, 1.0};
    fricreg_ctx *three = make_ctx(3);
    expect_refused(three, fricreg_ctx_set_coupling_csr(three, 3, 0, ptr3, ind3, val3),
                   FRICREG_ENOTPSD, "not positive semidefinite");
    const double val3b[9] = {1.0, 1.5, 0.0, 1.5, 1.0, 0.0, 0.0, 0.0, 1.0};
    expect_refused(three, fricreg_ctx_set_coupling_csr(three, 3, 0, ptr3, ind3, val3b),
                   FRICREG_ENOTPSD, "W(0, 1)^2");
    /* the first W is still there: the same forces, and its tangent */
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 5, ZDOT5, AFREE5, f, e), FRICREG_OK);
    ck_assert(memcmp(f, f0, sizeof f) == 0 && memcmp(e, e0, sizeof e) == 0);
    ck_assert_int_eq(fricreg_ctx_tangent(ctx, 5, tz, NULL), FRICREG_OK);
    /* a semidefinite, singular W is accepted (redundant contacts) */
    const double val3c[9] = {1.0, 1.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0};
    ck_assert_int_eq(fricreg_ctx_set_coupling_csr(three, 3, 0, ptr3, ind3, val3c), FRICREG_OK);
    fricreg_ctx_free(ctx);
    fricreg_ctx_free(two);
    fricreg_ctx_free(three);
}
END_TEST

/* ---- Stick stiffness ---------------------------------------------------------------------- */

/* Gershgorin's bound is at least the dense path's eigenvalue, and for (4) under the consistent
 * law both are the diagonal rate. */
START_TEST(stick_stiffness_bounds_dense)
{
    static struct coupling c;
    rng_state = 0x571ffu;
    random_sparse_spd(&c, 40);
    double mun[MMAX];
    for (size_t i = 0; i < c.m; i++)
        mun[i] = uniform(0.25, 2.0);
    for (int partition = FRICREG_PARTITION_CONSISTENT; partition <= FRICREG_PARTITION_PAPER;
         partition++)
        for (size_t l = 0; l < NLAWS; l++) {
            fricreg_ctx *sparse = make_sparse(&c), *dense = make_dense(&c);
            set_both(sparse, dense, c.m, mun, laws[l], 0.01, partition);
            double ls = -1.0, ld = -1.0;
            ck_assert_int_eq(fricreg_ctx_stick_stiffness(sparse, &ls), FRICREG_OK);
            ck_assert_int_eq(fricreg_ctx_stick_stiffness(dense, &ld), FRICREG_OK);
            if (laws[l] == FRICREG_LAW_QUINN && partition == FRICREG_PARTITION_CONSISTENT)
                ck_assert_double_eq(ls, ld);
            else
                ck_assert_msg(ls >= ld * (1.0 - 1e-12) && ls <= 10.0 * ld + 1e-300,
                              "law %d partition %d: sparse %g, dense %g", laws[l], partition, ls,
                              ld);
            fricreg_ctx_free(sparse);
            fricreg_ctx_free(dense);
        }
}
END_TEST

static Suite *sparse_suite(void)
{
    Suite *s = suite_create("sparse_ctx");
    TCase *tc = tcase_create("core");
    tcase_add_loop_test(tc, sparse_matches_dense, 0, (int)(NSIZES * NLAWS * 2));
    tcase_add_loop_test(tc, sparse_matches_dense_stribeck, 0, (int)(NSIZES * 2));
    tcase_add_test(tc, updates_are_used);
    tcase_add_test(tc, input_forms_agree);
    tcase_add_test(tc, pairs_at_large_m);
    tcase_add_test(tc, diagonal_given_sparse);
    tcase_add_loop_test(tc, tangent_apply_matches_tangent, 0, 2);
    tcase_add_test(tc, tangent_apply_errors);
    tcase_add_test(tc, redundant_contacts_are_singular);
    tcase_add_test(tc, refused_couplings);
    tcase_add_test(tc, stick_stiffness_bounds_dense);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *runner = srunner_create(sparse_suite());
    srunner_run_all(runner, CK_NORMAL);
    int failed = srunner_ntests_failed(runner);
    srunner_free(runner);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
