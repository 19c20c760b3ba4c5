/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_context.c — Check suite for the context: life cycle, setters, error state, the f_eq
 * partition of Sec. 3.3 (fricreg_ctx_eval) and its counters.
 *
 * Expected values: the partition of shared/spec/paper.md ("The general partition, Sec. 3.3") and
 * law (4), evaluated by hand in exact rational arithmetic. Most tests use the two-block system of
 * "Reference system 3": W = [[1, -1], [-1, 2]] (det 1, W^-1 = [[2, 1], [1, 1]]), mun = (0.5, 0.25),
 * with eps = 0.02, so eps/2 = 0.01 and 2 mun/eps = (50, 25). */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg.h"
#include "random.h"

#define SENTINEL (-777.125) /* written into outputs before a call that must fail */
#define TOL 1e-13           /* absolute, for forces of order 1 after a 2x2 solve */

static const double W2B[4] = {1.0, -1.0, -1.0, 2.0};
static const double MUN2B[2] = {0.5, 0.25};
#define EPS2B 0.02

/* ---- Helpers ----------------------------------------------------------------------------- */

static fricreg_ctx *make_ctx(size_t m)
{
    fricreg_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_ctx_create(m, &ctx), FRICREG_OK);
    ck_assert_ptr_nonnull(ctx);
    return ctx;
}

/* The two-block context under the consistent law (the default): dense W2B, bounds MUN2B,
 * law (4) with eps = 0.02. */
static fricreg_ctx *make_two_block_consistent(void)
{
    fricreg_ctx *ctx = make_ctx(2);
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, W2B), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, 2, MUN2B), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, EPS2B), FRICREG_OK);
    return ctx;
}

/* The same under the paper's partition, whose joint f_eq the hand solutions below assume. */
static fricreg_ctx *make_two_block(void)
{
    fricreg_ctx *ctx = make_two_block_consistent();
    ck_assert_int_eq(fricreg_ctx_set_partition(ctx, FRICREG_PARTITION_PAPER), FRICREG_OK);
    return ctx;
}

static int64_t counter(const fricreg_ctx *ctx, int which)
{
    int64_t value = -1;
    ck_assert_int_eq(fricreg_ctx_get_stat(ctx, which, &value), FRICREG_OK);
    return value;
}

static void expect_stats(const fricreg_ctx *ctx, int64_t evals, int64_t feq, int64_t fact,
                         int64_t solves)
{
    ck_assert_int_eq(counter(ctx, FRICREG_STAT_EVALS), evals);
    ck_assert_int_eq(counter(ctx, FRICREG_STAT_FEQ_CONTACTS), feq);
    ck_assert_int_eq(counter(ctx, FRICREG_STAT_FACTORIZATIONS), fact);
    ck_assert_int_eq(counter(ctx, FRICREG_STAT_SOLVES), solves);
}

/* Contacts added to or removed from a held factor instead of a new factorization. */
static void expect_updates(const fricreg_ctx *ctx, int64_t updates)
{
    ck_assert_int_eq(counter(ctx, FRICREG_STAT_FACTOR_UPDATES), updates);
}

/* A call on ctx just failed with `code`: the context records it, with a non-empty message that
 * errmsg_copy truncates into a small buffer while returning the full length. */
static void expect_failure_recorded(const fricreg_ctx *ctx, int status, int code, const char *what)
{
    ck_assert_msg(status == code, "%s: status %d, expected %d", what, status, code);
    ck_assert_msg(fricreg_ctx_errcode(ctx) == code, "%s: errcode %d, expected %d", what,
                  fricreg_ctx_errcode(ctx), code);
    const char *msg = fricreg_ctx_errmsg(ctx);
    ck_assert_ptr_nonnull(msg);
    size_t n = strlen(msg);
    ck_assert_msg(n > 0, "%s: empty error message", what);

    char small[6];
    memset(small, 'x', sizeof small);
    ck_assert_uint_eq(fricreg_ctx_errmsg_copy(ctx, small, sizeof small), n);
    ck_assert_uint_eq(strlen(small), n < 5 ? n : 5);
    ck_assert_int_eq(strncmp(small, msg, 5), 0);

    char big[512];
    ck_assert_uint_eq(fricreg_ctx_errmsg_copy(ctx, big, sizeof big), n);
    ck_assert_str_eq(big, msg);
}

/* Outputs of a failed eval must be untouched. */
static void fill(double a[], size_t n, double value)
{
    for (size_t i = 0; i < n; i++)
        a[i] = value;
}

static void expect_untouched(const double a[], size_t n)
{
    for (size_t i = 0; i < n; i++)
        ck_assert_msg(a[i] == SENTINEL, "output[%zu] = %g written by a failed call", i, a[i]);
}

/* ---- Life cycle -------------------------------------------------------------------------- */

/* fricreg_ctx_create: m = 0 or m > 2^26 is EINVAL, out NULL is ENULL, *out untouched on failure;
 * fricreg_ctx_size; fricreg_ctx_free(NULL) is a no-op. */
START_TEST(create_and_free)
{
    static char dummy;
    fricreg_ctx *const untouched = (fricreg_ctx *)(void *)&dummy;
    fricreg_ctx *ctx = untouched;
    ck_assert_int_eq(fricreg_ctx_create(0, &ctx), FRICREG_EINVAL);
    ck_assert_ptr_eq(ctx, untouched);
    ck_assert_int_eq(fricreg_ctx_create(((size_t)1 << 26) + 1, &ctx), FRICREG_EINVAL);
    ck_assert_ptr_eq(ctx, untouched);
    ck_assert_int_eq(fricreg_ctx_create(SIZE_MAX, &ctx), FRICREG_EINVAL);
    ck_assert_ptr_eq(ctx, untouched);
    ck_assert_int_eq(fricreg_ctx_create(3, NULL), FRICREG_ENULL);

    ctx = make_ctx(3);
    ck_assert_uint_eq(fricreg_ctx_size(ctx), 3);
    ck_assert_uint_eq(fricreg_ctx_size(NULL), 0);
    fricreg_ctx_free(ctx);
    fricreg_ctx_free(NULL);

    ctx = make_ctx(1);
    ck_assert_uint_eq(fricreg_ctx_size(ctx), 1);
    fricreg_ctx_free(ctx);
}
END_TEST

/* A fresh context has no error; a NULL context reads as "NULL context". */
START_TEST(error_state_initial_and_null)
{
    fricreg_ctx *ctx = make_ctx(2);
    char buf[16];
    ck_assert_int_eq(fricreg_ctx_errcode(ctx), FRICREG_OK);
    ck_assert_str_eq(fricreg_ctx_errmsg(ctx), "");
    memset(buf, 'x', sizeof buf);
    ck_assert_uint_eq(fricreg_ctx_errmsg_copy(ctx, buf, sizeof buf), 0);
    ck_assert_str_eq(buf, "");
    fricreg_ctx_free(ctx);

    ck_assert_int_eq(fricreg_ctx_errcode(NULL), FRICREG_OK);
    ck_assert_str_eq(fricreg_ctx_errmsg(NULL), "NULL context");
    ck_assert_uint_eq(fricreg_ctx_errmsg_copy(NULL, buf, sizeof buf), strlen("NULL context"));
    ck_assert_str_eq(buf, "NULL context");
    ck_assert_uint_eq(fricreg_ctx_errmsg_copy(NULL, buf, 5), strlen("NULL context"));
    ck_assert_str_eq(buf, "NULL");
}
END_TEST

/* errmsg_copy edge cases (header): buf NULL or len 0 returns 0 and writes nothing; len 1 gives
 * "" and the full length; a successful call does not clear the last error. */
START_TEST(errmsg_copy_edges_and_persistence)
{
    fricreg_ctx *ctx = make_ctx(2);
    int status = fricreg_ctx_set_law(ctx, 7, 0.0731);
    expect_failure_recorded(ctx, status, FRICREG_EINVAL, "set_law(7)");
    size_t n = strlen(fricreg_ctx_errmsg(ctx));

    char buf[4] = {'q', 'q', 'q', 'q'};
    ck_assert_uint_eq(fricreg_ctx_errmsg_copy(ctx, NULL, 100), 0);
    ck_assert_uint_eq(fricreg_ctx_errmsg_copy(ctx, buf, 0), 0);
    ck_assert_int_eq(buf[0], 'q');
    ck_assert_uint_eq(fricreg_ctx_errmsg_copy(ctx, buf, 1), n);
    ck_assert_int_eq(buf[0], '\0');
    ck_assert_int_eq(buf[1], 'q');

    /* Success does not clear it; the next failure replaces it. */
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_TANH, 0.0731), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_errcode(ctx), FRICREG_EINVAL);
    ck_assert_uint_eq(strlen(fricreg_ctx_errmsg(ctx)), n);
    status = fricreg_ctx_set_law(ctx, FRICREG_LAW_TANH, NAN);
    expect_failure_recorded(ctx, status, FRICREG_ENONFINITE, "set_law(NaN)");
    fricreg_ctx_free(ctx);
}
END_TEST

/* ---- Defaults and the uncoupled partition ------------------------------------------------ */

/* Defaults: law (4), eps = 1e-3, mun = 1, W = I, so f_eq,i = -a_free,i on S = {|zdot| < 1e-3}.
 * Contact 0: f_eq = -0.37, xi = 0.0005(-0.37) = -0.000185, zdot - xi = 0.000315 (inside),
 *   f = -(2/1e-3)(0.000315) = -0.63.
 * Contact 1: f_eq = 0.81, xi = 0.000405, zdot - xi = -0.000605 (outside), f = +1.
 * Contact 2: |zdot| = 0.0031 >= eps: slip, f = -1, f_eq NaN. */
START_TEST(defaults_quinn_unit_bounds_identity)
{
    fricreg_ctx *ctx = make_ctx(3);
    const double zdot[3] = {0.00013, -0.0002, 0.0031}, a[3] = {0.37, -0.81, 2.2};
    double f[3], feq[3];
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 3, zdot, a, f, feq), FRICREG_OK);
    ck_assert_double_eq_tol(feq[0], -0.37, TOL);
    ck_assert_double_eq_tol(feq[1], 0.81, TOL);
    ck_assert_double_nan(feq[2]);
    ck_assert_double_eq_tol(f[0], -0.63, 1e-12);
    ck_assert_double_eq(f[1], 1.0);
    ck_assert_double_eq(f[2], -1.0);
    expect_stats(ctx, 1, 2, 0, 0);
    fricreg_ctx_free(ctx);
}
END_TEST

/* Diagonal W = diag(2.385, 0.731, 1.913), mun = (0.9, 0.35, 1.2), law (4), eps = 0.0731:
 * contact 0: f_eq = 0.617/2.385 = 0.25870020964360585, xi = 0.03655 f_eq/0.9, inside:
 *   f = -(1.8/0.0731)(0.0104 - xi) = 0.0026126583440162668;
 * contact 1: f_eq = -0.5117/0.731 = -0.7 (beyond mun = 0.35: xi = -eps/2), zdot - xi = -0.00365:
 *   f = -(0.7/0.0731)(-0.00365) = 0.034952120383036939;
 * contact 2: |zdot| >= eps: slip, f = -1.2 sgn(-0.0873) = 1.2, f_eq NaN. No factorization. */
START_TEST(diagonal_coupling_divides)
{
    fricreg_ctx *ctx = make_ctx(3);
    const double w[3] = {2.385, 0.731, 1.913}, mun[3] = {0.9, 0.35, 1.2};
    const double zdot[3] = {0.0104, -0.0402, -0.0873}, a[3] = {-0.617, 0.5117, 4.4};
    double f[3], feq[3];
    ck_assert_int_eq(fricreg_ctx_set_coupling_diagonal(ctx, 3, w), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, 3, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 0.0731), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 3, zdot, a, f, feq), FRICREG_OK);
    ck_assert_double_eq_tol(feq[0], 0.25870020964360585, TOL);
    ck_assert_double_eq_tol(feq[1], -0.7, TOL);
    ck_assert_double_nan(feq[2]);
    ck_assert_double_eq_tol(f[0], 0.0026126583440162668, TOL);
    ck_assert_double_eq_tol(f[1], 0.034952120383036939, TOL);
    ck_assert_double_eq(f[2], 1.2);
    expect_stats(ctx, 1, 2, 0, 0);
    fricreg_ctx_free(ctx);
}
END_TEST

/* xorshift64*: the same inputs on every machine. */
static uint64_t rng_state = 0x9E3779B97F4A7C15u;
static double uniform01(void)
{
    return xorshift64star_uniform(&rng_state, 0.0, 1.0);
}

static int same_bits(double a, double b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

/* A diagonal W takes one fused pass (partition.c): per contact it must give exactly the law at
 * (zdot_i, f_eq,i = -a_free,i/w_i), f_eq out on S and NaN off it, and count |S| in
 * FEQ_CONTACTS, for each law that reads f_eq. m = 1001 is not a multiple of the vector or lane
 * widths; the contacts are 40% at rest, 20% near stick, 40% slipping, with a few exactly at
 * |zdot| = eps (off S) and at the least subnormal (off S for (2) only). */
START_TEST(diagonal_pass_is_the_law_contact_by_contact)
{
    enum { M = 1001 };
    static double w[M], mun[M], zdot[M], a[M], f[M], feq[M];
    const int laws[3] = {FRICREG_LAW_QUINN, FRICREG_LAW_KARNOPP, FRICREG_LAW_FORCE_BALANCE};
    const double eps = 0.0731;
    for (size_t i = 0; i < M; i++) {
        double u = uniform01(), sign = uniform01() < 0.5 ? -1.0 : 1.0;
        zdot[i] = u < 0.4 ? 0.0 : u < 0.6 ? sign * eps * uniform01() : sign * (eps + uniform01());
        w[i] = 0.3 + 2.7 * uniform01();
        mun[i] = 0.1 + 2.4 * uniform01();
        a[i] = (4.0 * uniform01() - 2.0) * mun[i] * w[i];
    }
    zdot[17] = 0.0731, zdot[18] = -0.0731, zdot[999] = 0x1p-1074, zdot[1000] = -0.0;
    fricreg_ctx *ctx = make_ctx(M);
    ck_assert_int_eq(fricreg_ctx_set_coupling_diagonal(ctx, M, w), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, M, mun), FRICREG_OK);
    int64_t counted = 0;
    for (int l = 0; l < 3; l++) {
        ck_assert_int_eq(fricreg_ctx_set_law(ctx, laws[l], eps), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_eval(ctx, M, zdot, a, f, feq), FRICREG_OK);
        for (size_t i = 0; i < M; i++) {
            double fe = -a[i] / w[i], expected;
            int near = laws[l] == FRICREG_LAW_FORCE_BALANCE ? zdot[i] == 0.0 : fabs(zdot[i]) < eps;
            ck_assert_int_eq(fricreg_law_eval(laws[l], zdot[i], fe, mun[i], eps, &expected),
                             FRICREG_OK);
            ck_assert_msg(same_bits(f[i], expected), "law %d, contact %zu: f %.17g, law %.17g",
                          laws[l], i, f[i], expected);
            ck_assert_msg(near ? same_bits(feq[i], fe) : isnan(feq[i]),
                          "law %d, contact %zu: f_eq %.17g", laws[l], i, feq[i]);
            counted += near;
        }
        ck_assert_int_eq(counter(ctx, FRICREG_STAT_FEQ_CONTACTS), counted);
    }
    ck_assert_int_gt(counted, 3 * M / 2); /* S was not empty: ~60% for (4), Karnopp */
    fricreg_ctx_free(ctx);
}
END_TEST

/* The fast finiteness check is a sum (partition.c): a NaN or an infinity in any position,
 * lane or tail, is found and named, nothing is written, and the tangent still describes the
 * last successful evaluation (its copies of the inputs untouched). Finite inputs whose sum
 * overflows are no failure. W = I, m = 11. */
START_TEST(diagonal_eval_validation_every_position)
{
    enum { M = 11 };
    double zdot[M], a[M], f[M], feq[M], before[M * M], after[M * M];
    fricreg_ctx *ctx = make_ctx(M);
    for (size_t i = 0; i < M; i++) {
        zdot[i] = 0.0131 * (double)i - 0.0731;
        a[i] = 0.41 * (double)i - 1.913;
    }
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 0.0731), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, M, zdot, a, f, feq), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_tangent(ctx, M, before, NULL), FRICREG_OK);
    for (size_t p = 0; p < M; p++)
        for (int which = 0; which < 2; which++) {
            double *arr = which == 0 ? zdot : a, keep = arr[p];
            char name[32];
            arr[p] = p % 2 ? NAN : -INFINITY;
            fill(f, M, SENTINEL);
            fill(feq, M, SENTINEL);
            expect_failure_recorded(ctx, fricreg_ctx_eval(ctx, M, zdot, a, f, feq),
                                    FRICREG_ENONFINITE, "non-finite input");
            snprintf(name, sizeof name, "%s[%zu]", which == 0 ? "zdot" : "a_free", p);
            ck_assert_msg(strstr(fricreg_ctx_errmsg(ctx), name) != NULL, "\"%s\" does not name %s",
                          fricreg_ctx_errmsg(ctx), name);
            expect_untouched(f, M);
            expect_untouched(feq, M);
            ck_assert_int_eq(fricreg_ctx_tangent(ctx, M, after, NULL), FRICREG_OK);
            for (size_t k = 0; k < M * M; k++)
                ck_assert_msg(same_bits(before[k], after[k]), "%s: tangent changed", name);
            arr[p] = keep;
        }
    for (size_t i = 0; i < M; i++) {
        zdot[i] = 1.5e308;
        a[i] = 1.7e308;
    }
    ck_assert_int_eq(fricreg_ctx_eval(ctx, M, zdot, a, f, NULL), FRICREG_OK);
    for (size_t i = 0; i < M; i++)
        ck_assert_double_eq(f[i], -1.0); /* default bounds 1, slipping forward */
    fricreg_ctx_free(ctx);
}
END_TEST

/* ---- The two-block system (Reference system 3) ------------------------------------------- */

/* Both near-stick: f_eq = -W^-1 a = -[[2,1],[1,1]] (0.213, -0.347) = (-0.079, 0.134).
 * xi = 0.01 (-0.158, 0.536) = (-0.00158, 0.00536);
 * f0 = -50 (0.0037 + 0.00158) = -0.264; f1 = -25 (-0.0031 - 0.00536) = 0.2115. */
START_TEST(two_block_both_near_stick)
{
    fricreg_ctx *ctx = make_two_block();
    const double zdot[2] = {0.0037, -0.0031}, a[2] = {0.213, -0.347};
    double f[2], feq[2];
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, zdot, a, f, feq), FRICREG_OK);
    ck_assert_double_eq_tol(feq[0], -0.079, TOL);
    ck_assert_double_eq_tol(feq[1], 0.134, TOL);
    ck_assert_double_eq_tol(f[0], -0.264, TOL);
    ck_assert_double_eq_tol(f[1], 0.2115, TOL);
    /* The residual of W f_eq = -a_free, written out. */
    ck_assert_double_eq_tol(feq[0] - feq[1], -0.213, TOL);
    ck_assert_double_eq_tol(-feq[0] + 2.0 * feq[1], 0.347, TOL);
    expect_stats(ctx, 1, 2, 1, 1);

    /* f_eq is optional. */
    double g[2];
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, zdot, a, g, NULL), FRICREG_OK);
    ck_assert_double_eq(g[0], f[0]);
    ck_assert_double_eq(g[1], f[1]);
    fricreg_ctx_free(ctx);
}
END_TEST

/* Only contact 0 near-stick: f1 = -0.25 sgn(0.153) = -0.25;
 * f_eq0 = -(a0 + W01 f1) = -(0.213 + (-1)(-0.25)) = -0.463; xi0 = 0.01 (-0.926) = -0.00926;
 * f0 = -50 (-0.0041 + 0.00926) = -0.258. */
START_TEST(two_block_only_lower_near_stick)
{
    fricreg_ctx *ctx = make_two_block();
    const double zdot[2] = {-0.0041, 0.153}, a[2] = {0.213, -0.347};
    double f[2], feq[2];
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, zdot, a, f, feq), FRICREG_OK);
    ck_assert_double_eq_tol(feq[0], -0.463, TOL);
    ck_assert_double_nan(feq[1]);
    ck_assert_double_eq_tol(f[0], -0.258, TOL);
    ck_assert_double_eq(f[1], -0.25);
    expect_stats(ctx, 1, 1, 1, 1);
    fricreg_ctx_free(ctx);
}
END_TEST

/* Only contact 1 near-stick: f0 = -0.5 sgn(-0.287) = 0.5;
 * f_eq1 = -(a1 + W10 f0)/W11 = -(-0.347 - 0.5)/2 = 0.4235 (> mun1: xi1 = 0.01);
 * f1 = -25 (0.0029 - 0.01) = 0.1775. */
START_TEST(two_block_only_upper_near_stick)
{
    fricreg_ctx *ctx = make_two_block();
    const double zdot[2] = {-0.287, 0.0029}, a[2] = {0.213, -0.347};
    double f[2], feq[2];
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, zdot, a, f, feq), FRICREG_OK);
    ck_assert_double_nan(feq[0]);
    ck_assert_double_eq_tol(feq[1], 0.4235, TOL);
    ck_assert_double_eq(f[0], 0.5);
    ck_assert_double_eq_tol(f[1], 0.1775, TOL);
    fricreg_ctx_free(ctx);
}
END_TEST

/* (1), (3) and tanh never read f_eq: S is empty whatever zdot is, so no f_eq (NaN), no
 * factorization. zdot = (0.0037, 0): (1) gives (-0.5, 0); (3) gives -(0.5/0.02) 0.0037 = -0.0925;
 * tanh gives -0.5 tanh(0.185) = -0.091458978432780071. */
START_TEST(laws_without_feq_have_empty_stick_set)
{
    fricreg_ctx *ctx = make_two_block();
    const double zdot[2] = {0.0037, 0.0}, a[2] = {0.213, -0.347};
    const int laws[3] = {FRICREG_LAW_COULOMB, FRICREG_LAW_VELOCITY_LIMITED, FRICREG_LAW_TANH};
    const double f0[3] = {-0.5, -0.0925, -0.091458978432780071};
    double f[2], feq[2];
    for (int k = 0; k < 3; k++) {
        ck_assert_int_eq(fricreg_ctx_set_law(ctx, laws[k], EPS2B), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, zdot, a, f, feq), FRICREG_OK);
        ck_assert_double_eq_tol(f[0], f0[k], TOL);
        ck_assert_double_eq(f[1], 0.0);
        ck_assert_double_nan(feq[0]);
        ck_assert_double_nan(feq[1]);
    }
    expect_stats(ctx, 3, 0, 0, 0);
    fricreg_ctx_free(ctx);
}
END_TEST

/* (2) reads f_eq only at zdot == 0 exactly; Karnopp on |zdot| < eps. With a = (0.213, -0.347):
 * S = {0} with f1 = -0.25: f_eq0 = -0.463 and (2) gives f0 = 0.5 sat(-0.926) = -0.463;
 * S = {0, 1}: f_eq = (-0.079, 0.134), both below their bounds, so f = f_eq. */
START_TEST(force_balance_and_karnopp_stick_sets)
{
    fricreg_ctx *ctx = make_two_block();
    const double a[2] = {0.213, -0.347};
    double f[2], feq[2];

    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_FORCE_BALANCE, EPS2B), FRICREG_OK);
    const double z_one[2] = {0.0, 0.0037};
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z_one, a, f, feq), FRICREG_OK);
    ck_assert_double_eq_tol(feq[0], -0.463, TOL);
    ck_assert_double_nan(feq[1]);
    ck_assert_double_eq_tol(f[0], -0.463, TOL);
    ck_assert_double_eq(f[1], -0.25);
    const double z_both[2] = {0.0, -0.0};
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z_both, a, f, feq), FRICREG_OK);
    ck_assert_double_eq_tol(feq[0], -0.079, TOL);
    ck_assert_double_eq_tol(feq[1], 0.134, TOL);
    ck_assert_double_eq_tol(f[0], -0.079, TOL);
    ck_assert_double_eq_tol(f[1], 0.134, TOL);
    const double z_none[2] = {1e-300, -0.0031}; /* (2): not at rest, so (1) */
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z_none, a, f, feq), FRICREG_OK);
    ck_assert_double_eq(f[0], -0.5);
    ck_assert_double_eq(f[1], 0.25);
    expect_stats(ctx, 3, 3, 1, 2); /* {0} factored, then contact 1 added: an update */
    expect_updates(ctx, 1);

    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_KARNOPP, EPS2B), FRICREG_OK);
    const double z_k[2] = {0.0037, -0.0031};
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z_k, a, f, feq), FRICREG_OK);
    ck_assert_double_eq_tol(f[0], -0.079, TOL);
    ck_assert_double_eq_tol(f[1], 0.134, TOL);
    const double z_edge[2] = {0.0037, EPS2B}; /* |zdot1| = eps: slip */
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z_edge, a, f, feq), FRICREG_OK);
    ck_assert_double_eq_tol(f[0], -0.463, TOL);
    ck_assert_double_eq(f[1], -0.25);
    ck_assert_double_nan(feq[1]);
    fricreg_ctx_free(ctx);
}
END_TEST

/* ---- Factorization reuse and counters ---------------------------------------------------- */

/* No factorization when S is empty (dense W) or when W is diagonal (W = I default, then an
 * explicit diagonal): FEQ_CONTACTS still counts the near-stick contacts. */
START_TEST(stats_no_factorization_without_stick_set_or_dense_w)
{
    fricreg_ctx *ctx = make_two_block();
    const double slip[2] = {0.153, -0.287}, near[2] = {0.0037, -0.0031};
    const double a[2] = {0.213, -0.347};
    double f[2];
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, slip, a, f, NULL), FRICREG_OK);
    ck_assert_double_eq(f[0], -0.5);
    ck_assert_double_eq(f[1], 0.25);
    expect_stats(ctx, 1, 0, 0, 0);
    fricreg_ctx_free(ctx);

    ctx = make_ctx(2);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, EPS2B), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, near, a, f, NULL), FRICREG_OK);
    const double w[2] = {2.385, 0.731};
    ck_assert_int_eq(fricreg_ctx_set_coupling_diagonal(ctx, 2, w), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, near, a, f, NULL), FRICREG_OK);
    expect_stats(ctx, 2, 4, 0, 0);
    fricreg_ctx_free(ctx);
}
END_TEST

/* Dense W2B. The factor of W_SS is kept while S holds (new zdot inside eps and new a_free only
 * re-solve) and updated when S changes, one FACTOR_UPDATES per contact added or removed,
 * including to another set of the same size ({0} -> {1}: W00 = 1 but W11 = 2, so a stale
 * factor would give f_eq1 = 0.847 instead of 0.4235). Two contacts are "a few": no
 * factorization after the first.
 * Step values (hand-solved above and in two_block_*): a' = (-0.0829, 0.1411) gives
 * f_eq = -W^-1 a' = (0.0247, -0.0582), xi = (0.000494, -0.002328),
 * f = (-50(-0.0052 - 0.000494), -25(0.0061 + 0.002328)) = (0.2847, -0.2107). */
START_TEST(stats_factor_reused_while_stick_set_holds)
{
    fricreg_ctx *ctx = make_two_block();
    const double a[2] = {0.213, -0.347}, a2[2] = {-0.0829, 0.1411};
    double f[2], feq[2];

    const double z1[2] = {0.0037, -0.0031}; /* S = {0, 1}: factorize, solve */
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z1, a, f, feq), FRICREG_OK);
    ck_assert_double_eq_tol(feq[0], -0.079, TOL);
    expect_stats(ctx, 1, 2, 1, 1);

    const double z2[2] = {-0.0052, 0.0061}; /* same S, new zdot and a_free: solve only */
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z2, a2, f, feq), FRICREG_OK);
    ck_assert_double_eq_tol(feq[0], 0.0247, TOL);
    ck_assert_double_eq_tol(feq[1], -0.0582, TOL);
    ck_assert_double_eq_tol(f[0], 0.2847, TOL);
    ck_assert_double_eq_tol(f[1], -0.2107, TOL);
    expect_stats(ctx, 2, 4, 1, 2);

    expect_updates(ctx, 0);

    const double z3[2] = {-0.0041, 0.153}; /* S = {0}: contact 1 removed */
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z3, a, f, feq), FRICREG_OK);
    ck_assert_double_eq_tol(feq[0], -0.463, TOL);
    ck_assert_double_eq_tol(f[0], -0.258, TOL);
    expect_stats(ctx, 3, 5, 1, 3);
    expect_updates(ctx, 1);

    const double z4[2] = {-0.287, 0.0029}; /* S = {1}: 0 removed, 1 added */
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z4, a, f, feq), FRICREG_OK);
    ck_assert_double_eq_tol(feq[1], 0.4235, TOL);
    ck_assert_double_eq_tol(f[1], 0.1775, TOL);
    expect_stats(ctx, 4, 6, 1, 4);
    expect_updates(ctx, 3);

    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z4, a, f, feq), FRICREG_OK); /* S = {1} again */
    expect_stats(ctx, 5, 7, 1, 5);
    expect_updates(ctx, 3);

    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z1, a, f, feq), FRICREG_OK); /* back to {0, 1} */
    ck_assert_double_eq_tol(feq[0], -0.079, TOL);
    ck_assert_double_eq_tol(feq[1], 0.134, TOL);
    expect_stats(ctx, 6, 9, 1, 6);
    expect_updates(ctx, 4);
    fricreg_ctx_free(ctx);
}
END_TEST

/* set_coupling_dense invalidates the factor, even with the same S: with W2B again it
 * refactorizes; with W' = [[2.385, 0.413], [0.413, 0.731]] (det 1.572866) the solve must use
 * W': f_eq = -W'^-1 (0.213, -0.347) = (-0.19010773962944078, 0.582099174373405), and (4) gives
 * f0 = -50 (0.0037 + 0.01 (-0.3802...)) = -0.37510773962944077, f1 = 0.25 (f_eq1 > mun1,
 * zdot1 - xi1 = -0.0131 outside). set_coupling_diagonal then drops the dense W. */
START_TEST(stats_set_coupling_invalidates_factor)
{
    fricreg_ctx *ctx = make_two_block();
    const double z[2] = {0.0037, -0.0031}, a[2] = {0.213, -0.347};
    const double Wp[4] = {2.385, 0.413, 0.413, 0.731};
    double f[2], feq[2];
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z, a, f, feq), FRICREG_OK);
    expect_stats(ctx, 1, 2, 1, 1);

    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, W2B), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z, a, f, feq), FRICREG_OK);
    ck_assert_double_eq_tol(feq[0], -0.079, TOL);
    expect_stats(ctx, 2, 4, 2, 2);

    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, Wp), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z, a, f, feq), FRICREG_OK);
    ck_assert_double_eq_tol(feq[0], -0.19010773962944078, TOL);
    ck_assert_double_eq_tol(feq[1], 0.582099174373405, TOL);
    ck_assert_double_eq_tol(f[0], -0.37510773962944077, TOL);
    ck_assert_double_eq(f[1], 0.25);
    expect_stats(ctx, 3, 6, 3, 3);

    /* Diagonal w = (2.385, 0.731): f_eq = -a/w = (-0.089308176100628925, 0.47469220246238031),
     * no factorization or solve. */
    const double w[2] = {2.385, 0.731};
    ck_assert_int_eq(fricreg_ctx_set_coupling_diagonal(ctx, 2, w), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z, a, f, feq), FRICREG_OK);
    ck_assert_double_eq_tol(feq[0], -0.089308176100628925, TOL);
    ck_assert_double_eq_tol(feq[1], 0.47469220246238031, TOL);
    expect_stats(ctx, 4, 8, 3, 3);
    fricreg_ctx_free(ctx);
}
END_TEST

/* reset_stats zeroes every counter (and accepts NULL); EVALS counts successful evals only. */
START_TEST(stats_reset_and_failed_evals_not_counted)
{
    fricreg_ctx *ctx = make_two_block();
    const double z[2] = {0.0037, -0.0031}, a[2] = {0.213, -0.347};
    const double bad_z[2] = {0.0037, NAN};
    double f[2];
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z, a, f, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 3, z, a, f, NULL), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, bad_z, a, f, NULL), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z, a, f, NULL), FRICREG_OK);
    expect_stats(ctx, 2, 4, 1, 2);
    fricreg_ctx_reset_stats(ctx);
    expect_stats(ctx, 0, 0, 0, 0);
    fricreg_ctx_reset_stats(NULL);
    /* The factor survives a reset: the same S solves without refactorizing. */
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z, a, f, NULL), FRICREG_OK);
    expect_stats(ctx, 1, 2, 0, 1);
    fricreg_ctx_free(ctx);
}
END_TEST

/* get_stat: unknown counter is EINVAL, NULL ctx or value is ENULL; *value untouched. */
START_TEST(get_stat_errors)
{
    fricreg_ctx *ctx = make_ctx(2);
    int64_t value = -4242;
    ck_assert_int_eq(fricreg_ctx_get_stat(ctx, 6, &value), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_ctx_get_stat(ctx, -1, &value), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_ctx_get_stat(ctx, 99, &value), FRICREG_EINVAL);
    ck_assert_int_eq(value, -4242);
    ck_assert_int_eq(fricreg_ctx_get_stat(NULL, FRICREG_STAT_EVALS, &value), FRICREG_ENULL);
    ck_assert_int_eq(value, -4242);
    ck_assert_int_eq(fricreg_ctx_get_stat(ctx, FRICREG_STAT_EVALS, NULL), FRICREG_ENULL);
    for (int k = FRICREG_STAT_EVALS; k <= FRICREG_STAT_FACTOR_UPDATES; k++) {
        value = -4242;
        ck_assert_int_eq(fricreg_ctx_get_stat(ctx, k, &value), FRICREG_OK);
        ck_assert_int_eq(value, 0);
    }
    fricreg_ctx_free(ctx);
}
END_TEST

/* ---- Setter and eval errors -------------------------------------------------------------- */

/* The two-block case of two_block_both_near_stick, used after failed calls to show that the law,
 * eps, bounds and W in effect are still the good ones: f = (-0.264, 0.2115). */
static void expect_two_block_state_intact(fricreg_ctx *ctx)
{
    const double zdot[2] = {0.0037, -0.0031}, a[2] = {0.213, -0.347};
    double f[2], feq[2];
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, zdot, a, f, feq), FRICREG_OK);
    ck_assert_double_eq_tol(feq[0], -0.079, TOL);
    ck_assert_double_eq_tol(feq[1], 0.134, TOL);
    ck_assert_double_eq_tol(f[0], -0.264, TOL);
    ck_assert_double_eq_tol(f[1], 0.2115, TOL);
}

/* set_law: ENULL, EINVAL (unknown law, eps <= 0, for every law), ENONFINITE; the law and eps
 * in effect stay (law (4), eps = 0.02). A change to (1) would give f = (-0.5, 0.25). */
START_TEST(set_law_errors)
{
    fricreg_ctx *ctx = make_two_block();
    ck_assert_int_eq(fricreg_ctx_set_law(NULL, FRICREG_LAW_QUINN, EPS2B), FRICREG_ENULL);
    expect_failure_recorded(ctx, fricreg_ctx_set_law(ctx, 0, 0.0731), FRICREG_EINVAL, "law 0");
    expect_failure_recorded(ctx, fricreg_ctx_set_law(ctx, 7, 0.0731), FRICREG_EINVAL, "law 7");
    expect_failure_recorded(ctx, fricreg_ctx_set_law(ctx, -1, 0.0731), FRICREG_EINVAL, "law -1");
    for (int law = FRICREG_LAW_COULOMB; law <= FRICREG_LAW_QUINN; law++) {
        expect_failure_recorded(ctx, fricreg_ctx_set_law(ctx, law, 0.0), FRICREG_EINVAL, "eps 0");
        expect_failure_recorded(ctx, fricreg_ctx_set_law(ctx, law, -0.0731), FRICREG_EINVAL,
                                "eps < 0");
        expect_failure_recorded(ctx, fricreg_ctx_set_law(ctx, law, NAN), FRICREG_ENONFINITE,
                                "eps NaN");
        expect_failure_recorded(ctx, fricreg_ctx_set_law(ctx, law, INFINITY), FRICREG_ENONFINITE,
                                "eps Inf");
    }
    expect_two_block_state_intact(ctx);
    fricreg_ctx_free(ctx);
}
END_TEST

/* set_bounds: ENULL, ESIZE, ENONFINITE, EINVAL; a rejected array (even one whose first element
 * is fine) leaves the old bounds: slip forces stay (-0.5, +0.25). mun = 0 is valid. */
START_TEST(set_bounds_errors)
{
    fricreg_ctx *ctx = make_two_block();
    const double good3[3] = {0.5, 0.25, 0.731};
    const double nan_[2] = {7.1, NAN}, inf_[2] = {INFINITY, 0.25}, neg[2] = {7.1, -0.3};
    ck_assert_int_eq(fricreg_ctx_set_bounds(NULL, 2, MUN2B), FRICREG_ENULL);
    expect_failure_recorded(ctx, fricreg_ctx_set_bounds(ctx, 2, NULL), FRICREG_ENULL, "NULL");
    expect_failure_recorded(ctx, fricreg_ctx_set_bounds(ctx, 3, good3), FRICREG_ESIZE, "m=3");
    expect_failure_recorded(ctx, fricreg_ctx_set_bounds(ctx, 1, good3), FRICREG_ESIZE, "m=1");
    expect_failure_recorded(ctx, fricreg_ctx_set_bounds(ctx, 2, nan_), FRICREG_ENONFINITE, "NaN");
    expect_failure_recorded(ctx, fricreg_ctx_set_bounds(ctx, 2, inf_), FRICREG_ENONFINITE, "Inf");
    expect_failure_recorded(ctx, fricreg_ctx_set_bounds(ctx, 2, neg), FRICREG_EINVAL, "mun<0");

    const double slip[2] = {0.153, -0.287}, a[2] = {0.213, -0.347};
    double f[2];
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, slip, a, f, NULL), FRICREG_OK);
    ck_assert_double_eq(f[0], -0.5);
    ck_assert_double_eq(f[1], 0.25);
    expect_two_block_state_intact(ctx);

    const double zero_and_other[2] = {0.0, 0.731};
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, 2, zero_and_other), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, slip, a, f, NULL), FRICREG_OK);
    ck_assert_double_eq(f[0], 0.0);
    ck_assert_double_eq(f[1], 0.731);
    fricreg_ctx_free(ctx);
}
END_TEST

/* set_coupling_diagonal: ENULL, ESIZE, ENONFINITE, EINVAL (w <= 0); the old coupling stays:
 * after diag(2.385, 0.731), f_eq = -a/w = (-0.089308176100628925, 0.47469220246238031) with
 * mun = 1, eps = 0.02: f = (-100 (0.0037 - 0.01 f_eq0), -100 (-0.0031 - 0.01 f_eq1))
 * = (-0.45930817610062891, 0.78469220246238025). A failed diagonal set also keeps a dense W. */
START_TEST(set_coupling_diagonal_errors)
{
    fricreg_ctx *ctx = make_ctx(2);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, EPS2B), FRICREG_OK);
    const double w[2] = {2.385, 0.731}, w3[3] = {2.385, 0.731, 1.0};
    const double nan_[2] = {2.0, NAN}, inf_[2] = {-INFINITY, 2.0};
    const double zero[2] = {4.4, 0.0}, neg[2] = {4.4, -1.3};
    ck_assert_int_eq(fricreg_ctx_set_coupling_diagonal(ctx, 2, w), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_coupling_diagonal(NULL, 2, w), FRICREG_ENULL);
    expect_failure_recorded(ctx, fricreg_ctx_set_coupling_diagonal(ctx, 2, NULL), FRICREG_ENULL,
                            "NULL");
    expect_failure_recorded(ctx, fricreg_ctx_set_coupling_diagonal(ctx, 3, w3), FRICREG_ESIZE,
                            "m=3");
    expect_failure_recorded(ctx, fricreg_ctx_set_coupling_diagonal(ctx, 2, nan_),
                            FRICREG_ENONFINITE, "NaN");
    expect_failure_recorded(ctx, fricreg_ctx_set_coupling_diagonal(ctx, 2, inf_),
                            FRICREG_ENONFINITE, "-Inf");
    expect_failure_recorded(ctx, fricreg_ctx_set_coupling_diagonal(ctx, 2, zero), FRICREG_EINVAL,
                            "w=0");
    expect_failure_recorded(ctx, fricreg_ctx_set_coupling_diagonal(ctx, 2, neg), FRICREG_EINVAL,
                            "w<0");

    const double z[2] = {0.0037, -0.0031}, a[2] = {0.213, -0.347};
    double f[2], feq[2];
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z, a, f, feq), FRICREG_OK);
    ck_assert_double_eq_tol(feq[0], -0.089308176100628925, TOL);
    ck_assert_double_eq_tol(feq[1], 0.47469220246238031, TOL);
    ck_assert_double_eq_tol(f[0], -0.45930817610062891, TOL);
    ck_assert_double_eq_tol(f[1], 0.78469220246238025, TOL);
    fricreg_ctx_free(ctx);

    ctx = make_two_block();
    expect_failure_recorded(ctx, fricreg_ctx_set_coupling_diagonal(ctx, 2, zero), FRICREG_EINVAL,
                            "w=0 after dense");
    expect_two_block_state_intact(ctx);
    expect_stats(ctx, 1, 2, 1, 1); /* still dense: one factorization */
    fricreg_ctx_free(ctx);
}
END_TEST

/* set_coupling_dense: ENULL, ESIZE (also m*m overflowing), ENONFINITE, ENOTSYM (beyond the
 * 1e-12 tolerance relative to sqrt(W_ii W_jj); within it accepted; asym_scaled passed the
 * former tolerance relative to max|W|, as a fuzz finding did), ENOTPSD ([[1,2],[2,1]] has eigenvalues 3 and
 * -1; zero or negative diagonal). The old W2B stays in effect after each failure. */
START_TEST(set_coupling_dense_errors)
{
    fricreg_ctx *ctx = make_two_block();
    const double W3[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    const double nan_[4] = {1.0, NAN, -1.0, 2.0}, inf_[4] = {1.0, -1.0, -1.0, INFINITY};
    const double asym[4] = {1.0, -1.0, -0.9, 2.0};
    const double asym_small[4] = {2.385, -1.0, -1.0 + 1e-10, 2.0}; /* 1e-10 > 1e-12 * 2.18 */
    const double asym_scaled[4] = {1e200, 1e90, -1e90, 1.0};       /* 2e90 < 1e-12 * 1e200 */
    const double indefinite[4] = {1.0, 2.0, 2.0, 1.0};
    const double zero_diag[4] = {0.0, 0.0, 0.0, 1.3}; /* PSD, but contact 0 cannot move */
    const double neg_diag[4] = {-1.0, 0.0, 0.0, 2.0};
    const double zero_diag_last[4] = {2.385, 0.0, 0.0, 0.0};

    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(NULL, 2, W2B), FRICREG_ENULL);
    expect_failure_recorded(ctx, fricreg_ctx_set_coupling_dense(ctx, 2, NULL), FRICREG_ENULL,
                            "NULL");
    expect_failure_recorded(ctx, fricreg_ctx_set_coupling_dense(ctx, 3, W3), FRICREG_ESIZE, "m=3");
    expect_failure_recorded(ctx, fricreg_ctx_set_coupling_dense(ctx, 1, W3), FRICREG_ESIZE, "m=1");
    expect_failure_recorded(ctx, fricreg_ctx_set_coupling_dense(ctx, SIZE_MAX / 2, W3),
                            FRICREG_ESIZE, "m*m overflows");
    expect_failure_recorded(ctx, fricreg_ctx_set_coupling_dense(ctx, 2, nan_), FRICREG_ENONFINITE,
                            "NaN");
    expect_failure_recorded(ctx, fricreg_ctx_set_coupling_dense(ctx, 2, inf_), FRICREG_ENONFINITE,
                            "Inf");
    expect_failure_recorded(ctx, fricreg_ctx_set_coupling_dense(ctx, 2, asym), FRICREG_ENOTSYM,
                            "asym");
    expect_failure_recorded(ctx, fricreg_ctx_set_coupling_dense(ctx, 2, asym_small),
                            FRICREG_ENOTSYM, "asym 1e-10");
    expect_failure_recorded(ctx, fricreg_ctx_set_coupling_dense(ctx, 2, asym_scaled),
                            FRICREG_ENOTSYM, "asym beside a large W_00");
    expect_failure_recorded(ctx, fricreg_ctx_set_coupling_dense(ctx, 2, indefinite),
                            FRICREG_ENOTPSD, "indefinite");
    expect_failure_recorded(ctx, fricreg_ctx_set_coupling_dense(ctx, 2, zero_diag), FRICREG_ENOTPSD,
                            "W00 = 0");
    expect_failure_recorded(ctx, fricreg_ctx_set_coupling_dense(ctx, 2, neg_diag), FRICREG_ENOTPSD,
                            "W00 < 0");
    expect_failure_recorded(ctx, fricreg_ctx_set_coupling_dense(ctx, 2, zero_diag_last),
                            FRICREG_ENOTPSD, "W11 = 0");
    expect_two_block_state_intact(ctx);
    expect_stats(ctx, 1, 2, 1, 1); /* the failures did not invalidate the factor */
    expect_two_block_state_intact(ctx);
    expect_stats(ctx, 2, 4, 1, 2);

    /* Asymmetry below the tolerance, 1e-13 < 1e-12 * sqrt(2.385 * 2), is accepted. */
    const double asym_tiny[4] = {2.385, -1.0, -1.0 + 1e-13, 2.0};
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, asym_tiny), FRICREG_OK);
    fricreg_ctx_free(ctx);
}
END_TEST

/* eval: ENULL (each array), ESIZE, ENONFINITE (zdot or a_free); outputs untouched, no counter
 * moves, the factor is not built. */
/* Overflow is refused, not passed off as success:
 *  - a subnormal eps makes 2/eps overflow, and law (4) then gave +mun at v = 0 whatever f_eq
 *    was; eps >= DBL_MIN is required, and at eps = DBL_MIN (4) is still the force balance (2)
 *    at v = 0: f = mun sat(f_eq/mun) = 0.3 for f_eq = 0.3, mun = 1;
 *  - W = [[1, 1.5], [1.5, 1]] * 1e308 is indefinite (eigenvalues 2.5e308 and -0.5e308); its
 *    eigenvalues overflowed to NaN inside GSL and the check passed it. */
START_TEST(overflow_is_refused)
{
    double f = SENTINEL;
    ck_assert_int_eq(fricreg_law_eval(FRICREG_LAW_QUINN, 0.0, 0.3, 1.0, 1e-310, &f),
                     FRICREG_EINVAL);
    ck_assert_double_eq(f, SENTINEL);
    ck_assert_int_eq(fricreg_law_eval(FRICREG_LAW_QUINN, 0.0, 0.3, 1.0, 2.2250738585072014e-308,
                                      &f),
                     FRICREG_OK);
    ck_assert_double_eq_tol(f, 0.3, 1e-15);
    fricreg_ctx *ctx = make_ctx(2);
    expect_failure_recorded(ctx, fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 1e-310),
                            FRICREG_EINVAL, "set_law, subnormal eps");
    const double W[4] = {1e308, 1.5e308, 1.5e308, 1e308};
    expect_failure_recorded(ctx, fricreg_ctx_set_coupling_dense(ctx, 2, W), FRICREG_ENOTPSD,
                            "indefinite W near DBL_MAX");
    const double W_spd[4] = {1.5e308, 1e308, 1e308, 1.5e308}; /* eigenvalues 2.5e308, 0.5e308 */
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, W_spd), FRICREG_OK);
    fricreg_ctx_free(ctx);
}
END_TEST

START_TEST(eval_errors)
{
    fricreg_ctx *ctx = make_two_block();
    const double z[2] = {0.0037, -0.0031}, a[2] = {0.213, -0.347};
    const double z_nan[2] = {0.0037, NAN}, z_inf[2] = {-INFINITY, 0.0};
    const double a_inf[2] = {INFINITY, -0.347}, a_nan[2] = {0.213, NAN};
    const double z3[3] = {0.0037, -0.0031, 0.0}, a3[3] = {0.213, -0.347, 0.0};
    double f[3], feq[3];

    fill(f, 3, SENTINEL);
    fill(feq, 3, SENTINEL);
    ck_assert_int_eq(fricreg_ctx_eval(NULL, 2, z, a, f, feq), FRICREG_ENULL);
    expect_failure_recorded(ctx, fricreg_ctx_eval(ctx, 2, NULL, a, f, feq), FRICREG_ENULL,
                            "zdot NULL");
    expect_failure_recorded(ctx, fricreg_ctx_eval(ctx, 2, z, NULL, f, feq), FRICREG_ENULL,
                            "a_free NULL");
    expect_failure_recorded(ctx, fricreg_ctx_eval(ctx, 2, z, a, NULL, feq), FRICREG_ENULL,
                            "f NULL");
    expect_failure_recorded(ctx, fricreg_ctx_eval(ctx, 3, z3, a3, f, feq), FRICREG_ESIZE, "m=3");
    expect_failure_recorded(ctx, fricreg_ctx_eval(ctx, 1, z3, a3, f, feq), FRICREG_ESIZE, "m=1");
    expect_failure_recorded(ctx, fricreg_ctx_eval(ctx, 2, z_nan, a, f, feq), FRICREG_ENONFINITE,
                            "zdot NaN");
    expect_failure_recorded(ctx, fricreg_ctx_eval(ctx, 2, z_inf, a, f, feq), FRICREG_ENONFINITE,
                            "zdot -Inf");
    expect_failure_recorded(ctx, fricreg_ctx_eval(ctx, 2, z, a_inf, f, feq), FRICREG_ENONFINITE,
                            "a_free Inf");
    expect_failure_recorded(ctx, fricreg_ctx_eval(ctx, 2, z, a_nan, f, feq), FRICREG_ENONFINITE,
                            "a_free NaN");
    expect_untouched(f, 3);
    expect_untouched(feq, 3);
    expect_stats(ctx, 0, 0, 0, 0);
    expect_two_block_state_intact(ctx);
    fricreg_ctx_free(ctx);
}
END_TEST

/* ESINGULAR: W = [[1,1],[1,1]] is PSD (eigenvalues 0, 2), so set_coupling_dense accepts it, but
 * with both contacts near-stick W_SS = W is singular (redundant contacts). Outputs untouched,
 * EVALS/SOLVES/FEQ_CONTACTS unchanged. With only contact 0 near-stick W_SS = [1] is fine:
 * f1 = -0.25, f_eq0 = -(0.213 + 1 (-0.25)) = 0.037, xi0 = 0.00074, f0 = -50 (0.0037 - 0.00074)
 * = -0.148. Then both near-stick again fails again (the 1x1 factor must not be reused). */
START_TEST(eval_singular_stick_block)
{
    fricreg_ctx *ctx = make_two_block();
    const double Ws[4] = {1.0, 1.0, 1.0, 1.0};
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, Ws), FRICREG_OK);
    const double both[2] = {0.0037, -0.0031}, one[2] = {0.0037, 0.153}, a[2] = {0.213, -0.347};
    double f[2], feq[2];

    fill(f, 2, SENTINEL);
    fill(feq, 2, SENTINEL);
    expect_failure_recorded(ctx, fricreg_ctx_eval(ctx, 2, both, a, f, feq), FRICREG_ESINGULAR,
                            "singular W_SS");
    expect_untouched(f, 2);
    expect_untouched(feq, 2);
    ck_assert_int_eq(counter(ctx, FRICREG_STAT_EVALS), 0);
    ck_assert_int_eq(counter(ctx, FRICREG_STAT_SOLVES), 0);
    ck_assert_int_eq(counter(ctx, FRICREG_STAT_FEQ_CONTACTS), 0);

    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, one, a, f, feq), FRICREG_OK);
    ck_assert_double_eq_tol(feq[0], 0.037, TOL);
    ck_assert_double_nan(feq[1]);
    ck_assert_double_eq_tol(f[0], -0.148, TOL);
    ck_assert_double_eq(f[1], -0.25);

    fill(f, 2, SENTINEL);
    fill(feq, 2, SENTINEL);
    expect_failure_recorded(ctx, fricreg_ctx_eval(ctx, 2, both, a, f, feq), FRICREG_ESINGULAR,
                            "singular W_SS again");
    expect_untouched(f, 2);
    expect_untouched(feq, 2);
    ck_assert_int_eq(counter(ctx, FRICREG_STAT_EVALS), 1);
    fricreg_ctx_free(ctx);
}
END_TEST

/* A failed factorization must not leave a factor that a later eval reuses. W = [[0.731, 1.462],
 * [1.462, 2.924]] is PSD of rank 1 (det 0.731 * 2.924 - 1.462^2 = 0): S = {0} factors W00 = 0.731,
 * S = {0, 1} fails (ESINGULAR) and overwrites the factor storage (pivoting puts 2.924 first),
 * then S = {0} must be factorized again. With f1 = -0.25: f_eq0 = -(0.213 + 1.462 (-0.25))/0.731
 * = 0.20861833105335156 (a reused 2x2 pivot would give 0.0521545...), xi0 = 0.01 f_eq0/0.5,
 * f0 = -50 (0.0037 - xi0) = 0.023618331053351573. */
START_TEST(eval_failed_factorization_leaves_no_stale_factor)
{
    fricreg_ctx *ctx = make_two_block();
    const double Wr[4] = {0.731, 1.462, 1.462, 2.924};
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, Wr), FRICREG_OK);
    const double both[2] = {0.0037, -0.0031}, one[2] = {0.0037, 0.153}, a[2] = {0.213, -0.347};
    double f[2], feq[2];
    for (int round = 0; round < 2; round++) {
        ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, one, a, f, feq), FRICREG_OK);
        ck_assert_double_eq_tol(feq[0], 0.20861833105335156, TOL);
        ck_assert_double_eq_tol(f[0], 0.023618331053351573, TOL);
        ck_assert_double_eq(f[1], -0.25);
        expect_failure_recorded(ctx, fricreg_ctx_eval(ctx, 2, both, a, f, feq), FRICREG_ESINGULAR,
                                "rank-1 W_SS");
    }
    ck_assert_int_eq(counter(ctx, FRICREG_STAT_EVALS), 2);
    ck_assert_int_eq(counter(ctx, FRICREG_STAT_SOLVES), 2);
    fricreg_ctx_free(ctx);
}
END_TEST

/* Nearly singular: W = [[1, 1-1e-14], [1-1e-14, 1]] has eigenvalues 1e-14 and 2 (PSD, accepted)
 * and reciprocal condition number about 5e-15 < 1e-12: ESINGULAR. */
START_TEST(eval_nearly_singular_stick_block)
{
    fricreg_ctx *ctx = make_two_block();
    const double Wn[4] = {1.0, 1.0 - 1e-14, 1.0 - 1e-14, 1.0};
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, Wn), FRICREG_OK);
    const double both[2] = {0.0037, -0.0031}, a[2] = {0.213, -0.347};
    double f[2];
    fill(f, 2, SENTINEL);
    expect_failure_recorded(ctx, fricreg_ctx_eval(ctx, 2, both, a, f, NULL), FRICREG_ESINGULAR,
                            "nearly singular W_SS");
    expect_untouched(f, 2);
    fricreg_ctx_free(ctx);
}
END_TEST

/* ---- A larger dense case ----------------------------------------------------------------- */

#define M5 5
static const double A5[M5][M5] = {{0.731, -0.412, 1.137, 0.213, -0.905},
                                  {0.318, 1.913, -0.627, 0.044, 0.566},
                                  {-1.205, 0.097, 0.388, 1.472, -0.251},
                                  {0.659, -0.733, 0.142, -0.318, 1.064},
                                  {0.027, 0.851, -1.318, 0.594, 0.377}};

/* W = A A^T + 0.1 I: symmetric positive definite (eigenvalues >= 0.1). */
static void make_spd5(double W[M5 * M5])
{
    for (int i = 0; i < M5; i++)
        for (int j = 0; j < M5; j++) {
            double s = (i == j) ? 0.1 : 0.0;
            for (int k = 0; k < M5; k++)
                s += A5[i][k] * A5[j][k];
            W[i * M5 + j] = s;
        }
}

/* Residual of row i of W_SS f_eq,S + a_free,S + W_SL f_L = 0, relative to the size of its
 * terms. */
static double row_residual(const double W[], int i, const double x[], double a_i)
{
    double r = a_i, scale = fabs(a_i);
    for (int j = 0; j < M5; j++) {
        r += W[i * M5 + j] * x[j];
        scale += fabs(W[i * M5 + j] * x[j]);
    }
    return fabs(r) / scale;
}

/* m = 5, all contacts near-stick: W f_eq = -a_free to 1e-12 relative, and every f is law (4)
 * at (zdot_i, f_eq,i) (the scalar law, tested in test_law). Then S = {0, 2, 3} with contacts 1
 * and 4 sliding: f_L = (-0.35, +0.731), and the S rows of W f + a_free vanish with f_eq on S. */
START_TEST(dense_five_contacts_residual)
{
    double W[M5 * M5];
    make_spd5(W);
    const double mun[M5] = {0.9, 0.35, 1.2, 2.385, 0.731};
    const double a[M5] = {0.617, -1.385, 0.244, 2.031, -0.779};
    const double eps = 0.0731;
    fricreg_ctx *ctx = make_ctx(M5);
    ck_assert_int_eq(fricreg_ctx_set_partition(ctx, FRICREG_PARTITION_PAPER), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, M5, W), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, M5, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, eps), FRICREG_OK);

    const double z_all[M5] = {0.0104, -0.0402, 0.0003, 0.0611, -0.0217};
    double f[M5], feq[M5];
    ck_assert_int_eq(fricreg_ctx_eval(ctx, M5, z_all, a, f, feq), FRICREG_OK);
    for (int i = 0; i < M5; i++) {
        ck_assert_double_finite(feq[i]);
        ck_assert_double_le(row_residual(W, i, feq, a[i]), 1e-12);
        double expect = SENTINEL;
        ck_assert_int_eq(fricreg_law_eval(FRICREG_LAW_QUINN, z_all[i], feq[i], mun[i], eps,
                                          &expect),
                         FRICREG_OK);
        ck_assert_double_eq_tol(f[i], expect, 1e-15);
    }
    expect_stats(ctx, 1, 5, 1, 1);

    const double z_mixed[M5] = {0.0104, 0.2, 0.0003, 0.0611, -0.15};
    ck_assert_int_eq(fricreg_ctx_eval(ctx, M5, z_mixed, a, f, feq), FRICREG_OK);
    ck_assert_double_eq(f[1], -0.35);
    ck_assert_double_eq(f[4], 0.731);
    ck_assert_double_nan(feq[1]);
    ck_assert_double_nan(feq[4]);
    double x[M5] = {feq[0], f[1], feq[2], feq[3], f[4]}; /* f_eq on S, f on L */
    const int S[3] = {0, 2, 3};
    for (int k = 0; k < 3; k++) {
        int i = S[k];
        ck_assert_double_le(row_residual(W, i, x, a[i]), 1e-12);
        double expect = SENTINEL;
        ck_assert_int_eq(fricreg_law_eval(FRICREG_LAW_QUINN, z_mixed[i], feq[i], mun[i], eps,
                                          &expect),
                         FRICREG_OK);
        ck_assert_double_eq_tol(f[i], expect, 1e-15);
    }
    expect_stats(ctx, 2, 8, 1, 2); /* contacts 1 and 4 removed from the factor of all five */
    expect_updates(ctx, 2);
    fricreg_ctx_free(ctx);
}
END_TEST

/* ---- The consistent law (the default partition; docs/coupled.md) ------------------------ */

/* Both near-stick, both free in their boxes. c = 2 zdot/eps = (0.37, -0.31); boxes
 * [-0.5, 0.5 (1 - 0.37)] = [-0.5, 0.315] and [-0.25 (1 - 0.31), 0.25] = [-0.1725, 0.25];
 * b = a + diag(W) c mun = (0.213 + 0.185, -0.347 - 0.155) = (0.398, -0.502);
 * f = -W^-1 b = -[[2, 1], [1, 1]] b = (-0.294, 0.104), inside both boxes.
 * f_eq,i given the other's actual force: f_eq0 = -(0.213 - 0.104) = -0.109,
 * f_eq1 = -(-0.347 + 0.294)/2 = 0.0265; and f_i = f_eq,i - c_i mun_i. The paper's partition
 * gives (-0.264, 0.2115) here (two_block_both_near_stick). One QP iteration, one factor. */
START_TEST(consistent_two_block_both_free)
{
    fricreg_ctx *ctx = make_two_block_consistent();
    const double zdot[2] = {0.0037, -0.0031}, a[2] = {0.213, -0.347};
    double f[2], feq[2];
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, zdot, a, f, feq), FRICREG_OK);
    ck_assert_double_eq_tol(f[0], -0.294, TOL);
    ck_assert_double_eq_tol(f[1], 0.104, TOL);
    ck_assert_double_eq_tol(feq[0], -0.109, TOL);
    ck_assert_double_eq_tol(feq[1], 0.0265, TOL);
    for (int i = 0; i < 2; i++) { /* law (4) at (zdot_i, f_eq,i): the consistent fixed point */
        double law = SENTINEL;
        ck_assert_int_eq(fricreg_law_eval(FRICREG_LAW_QUINN, zdot[i], feq[i], MUN2B[i], EPS2B,
                                          &law),
                         FRICREG_OK);
        ck_assert_double_eq_tol(f[i], law, TOL);
    }
    expect_stats(ctx, 1, 2, 1, 1);
    ck_assert_int_eq(counter(ctx, FRICREG_STAT_QP_ITERATIONS), 1);
    /* Same inputs again: the warm start is right and the factor is reused. */
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, zdot, a, f, NULL), FRICREG_OK);
    ck_assert_double_eq_tol(f[0], -0.294, TOL);
    expect_stats(ctx, 2, 4, 1, 2);
    ck_assert_int_eq(counter(ctx, FRICREG_STAT_QP_ITERATIONS), 2);
    fricreg_ctx_free(ctx);
}
END_TEST

/* The jumps of docs/coupled.md, at the band edge |zdot_j| = eps(1 -+ 1e-9).
 * (a) a = (0.1, 0.1), zdot = (0, eps(1 -+ 1e-9)). Outside: f1 = -0.25, S = {0}:
 *     f0 = -(0.1 + (-1)(-0.25)) = -0.35. Inside: c1 = 2 (1 - 1e-9), box1 = [-0.25,
 *     -0.25 + 5e-10]; f1 is held at -0.25 (its free value -(b1 - f0)/2 = -0.725 is below),
 *     so f0 = -0.35 again. The paper's joint f_eq = -W^-1 a = (-0.3, -0.2) gives f0 = -0.30.
 * (b) a = (-0.3, 0.1), zdot = (eps(1 -+ 1e-9), 0). Outside: f0 = -0.5, S = {1}:
 *     f1 = clamp(-(0.1 + 0.5)/2, -0.25, 0.25) = -0.25. Inside: f0 held at -0.5 (its free value
 *     -(b0 - f1) = -(0.7 + 0.25) is below), and f1 = -0.25 again. The paper's: f_eq = (0.5, 0.2),
 *     f1 = +0.2, a jump of 1.8 mun1 with a change of sign. */
START_TEST(consistent_no_jump_at_band_edge)
{
    const double a_cases[2][2] = {{0.1, 0.1}, {-0.3, 0.1}};
    const int edge[2] = {1, 0}, watch[2] = {0, 1};
    const double consistent[2] = {-0.35, -0.25}, paper_inside[2] = {-0.30, 0.2};
    for (int k = 0; k < 2; k++) {
        for (int paper = 0; paper < 2; paper++) {
            fricreg_ctx *ctx = paper ? make_two_block() : make_two_block_consistent();
            double inside[2] = {0.0, 0.0}, outside[2] = {0.0, 0.0}, fin[2], fout[2];
            inside[edge[k]] = EPS2B * (1.0 - 1e-9);
            outside[edge[k]] = EPS2B * (1.0 + 1e-9);
            ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, inside, a_cases[k], fin, NULL), FRICREG_OK);
            ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, outside, a_cases[k], fout, NULL), FRICREG_OK);
            int i = watch[k];
            ck_assert_double_eq_tol(fout[i], consistent[k], TOL);
            ck_assert_double_eq_tol(fin[i], paper ? paper_inside[k] : consistent[k], TOL);
            fricreg_ctx_free(ctx);
        }
    }
}
END_TEST

/* m = 5 (make_spd5), mixed: every near-stick contact satisfies law (4) at (zdot_i, f_eq,i) with
 * f_eq,i = -(a_i + sum_{j != i} W_ij f_j)/W_ii from the returned forces (the consistent law's
 * defining fixed point), slip contacts have -mun sgn(zdot). The a_free are large enough that
 * some contacts saturate, so the QP's bounds are active; a second evaluation from the kept
 * working set takes one iteration and no factorization. */
START_TEST(consistent_five_contacts_fixed_point)
{
    double W[M5 * M5];
    make_spd5(W);
    const double mun[M5] = {0.9, 0.35, 1.2, 2.385, 0.731};
    const double a[M5] = {1.617, -2.385, 0.244, 3.031, -1.779};
    const double z[M5] = {0.0104, 0.2, 0.0003, -0.0611, -0.0217};
    const double eps = 0.0731;
    fricreg_ctx *ctx = make_ctx(M5);
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, M5, W), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, M5, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, eps), FRICREG_OK);
    double f[M5], feq[M5];
    ck_assert_int_eq(fricreg_ctx_eval(ctx, M5, z, a, f, feq), FRICREG_OK);
    int held = 0;
    for (int i = 0; i < M5; i++) {
        if (fabs(z[i]) >= eps) {
            ck_assert_double_eq(f[i], -mun[i] * (z[i] > 0 ? 1.0 : -1.0));
            ck_assert_double_nan(feq[i]);
            continue;
        }
        double others = 0.0;
        for (int j = 0; j < M5; j++)
            others += j == i ? 0.0 : W[i * M5 + j] * f[j];
        ck_assert_double_eq_tol(feq[i], -(a[i] + others) / W[i * M5 + i], 1e-12);
        double law = SENTINEL;
        ck_assert_int_eq(fricreg_law_eval(FRICREG_LAW_QUINN, z[i], feq[i], mun[i], eps, &law),
                         FRICREG_OK);
        ck_assert_double_eq_tol(f[i], law, 1e-12);
        held += fabs(law - (feq[i] - 2.0 * z[i] / eps * mun[i])) > 1e-9; /* on a bound */
    }
    ck_assert_int_gt(held, 0);
    int64_t fact = counter(ctx, FRICREG_STAT_FACTORIZATIONS);
    int64_t iters = counter(ctx, FRICREG_STAT_QP_ITERATIONS);
    double g[M5];
    ck_assert_int_eq(fricreg_ctx_eval(ctx, M5, z, a, g, NULL), FRICREG_OK);
    for (int i = 0; i < M5; i++)
        ck_assert_double_eq_tol(g[i], f[i], 1e-15);
    ck_assert_int_eq(counter(ctx, FRICREG_STAT_FACTORIZATIONS), fact);
    ck_assert_int_eq(counter(ctx, FRICREG_STAT_QP_ITERATIONS), iters + 1);
    fricreg_ctx_free(ctx);
}
END_TEST

/* The singularity test is scale-invariant: W = diag(1, 1e-14) passed as dense is regular (its
 * contact 1 is just very heavy), under both partitions; before, rcond 1e-14 was refused.
 * a = (0.213, -3.47e-15), zdot = (0.0037, 0): f_eq = (-0.213, 0.347); (4) gives
 * f0 = -50 (0.0037 + 0.01 (0.426)) = -0.398 and f1 = 0.25 sat(0.347/0.25) = 0.25. */
START_TEST(singularity_test_is_scale_invariant)
{
    const double Wd[4] = {1.0, 0.0, 0.0, 1e-14}, a[2] = {0.213, -3.47e-15};
    const double z[2] = {0.0037, 0.0};
    for (int paper = 0; paper < 2; paper++) {
        fricreg_ctx *ctx = paper ? make_two_block() : make_two_block_consistent();
        ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, Wd), FRICREG_OK);
        double f[2];
        ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z, a, f, NULL), FRICREG_OK);
        ck_assert_double_eq_tol(f[0], -0.398, TOL);
        ck_assert_double_eq_tol(f[1], 0.25, TOL);
        fricreg_ctx_free(ctx);
    }
}
END_TEST

/* A truly redundant pair, W = [[1, 1], [1, 1]] (also scaled), both free at rest: ESINGULAR
 * under the consistent law too, outputs untouched, no evaluation counted. */
START_TEST(consistent_redundant_pair_is_singular)
{
    fricreg_ctx *ctx = make_two_block_consistent();
    const double Ws[4] = {1.0, 1.0, 1.0, 1.0}, Wr[4] = {0.731, 1.462, 1.462, 2.924};
    const double z[2] = {0.0, 0.0}, a[2] = {0.0213, -0.0347};
    double f[2], feq[2];
    for (int k = 0; k < 2; k++) {
        ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, k ? Wr : Ws), FRICREG_OK);
        fill(f, 2, SENTINEL);
        fill(feq, 2, SENTINEL);
        expect_failure_recorded(ctx, fricreg_ctx_eval(ctx, 2, z, a, f, feq), FRICREG_ESINGULAR,
                                "redundant pair, consistent law");
        expect_untouched(f, 2);
        expect_untouched(feq, 2);
    }
    ck_assert_int_eq(counter(ctx, FRICREG_STAT_EVALS), 0);
    fricreg_ctx_free(ctx);
}
END_TEST

static Suite *context_suite(void)
{
    Suite *s = suite_create("context");
    TCase *tc = tcase_create("lifecycle");
    tcase_add_test(tc, create_and_free);
    tcase_add_test(tc, error_state_initial_and_null);
    tcase_add_test(tc, errmsg_copy_edges_and_persistence);
    suite_add_tcase(s, tc);

    tc = tcase_create("partition");
    tcase_add_test(tc, defaults_quinn_unit_bounds_identity);
    tcase_add_test(tc, diagonal_coupling_divides);
    tcase_add_test(tc, diagonal_pass_is_the_law_contact_by_contact);
    tcase_add_test(tc, two_block_both_near_stick);
    tcase_add_test(tc, two_block_only_lower_near_stick);
    tcase_add_test(tc, two_block_only_upper_near_stick);
    tcase_add_test(tc, laws_without_feq_have_empty_stick_set);
    tcase_add_test(tc, force_balance_and_karnopp_stick_sets);
    tcase_add_test(tc, dense_five_contacts_residual);
    suite_add_tcase(s, tc);

    tc = tcase_create("consistent");
    tcase_add_test(tc, consistent_two_block_both_free);
    tcase_add_test(tc, consistent_no_jump_at_band_edge);
    tcase_add_test(tc, consistent_five_contacts_fixed_point);
    tcase_add_test(tc, singularity_test_is_scale_invariant);
    tcase_add_test(tc, consistent_redundant_pair_is_singular);
    suite_add_tcase(s, tc);

    tc = tcase_create("stats");
    tcase_add_test(tc, stats_no_factorization_without_stick_set_or_dense_w);
    tcase_add_test(tc, stats_factor_reused_while_stick_set_holds);
    tcase_add_test(tc, stats_set_coupling_invalidates_factor);
    tcase_add_test(tc, stats_reset_and_failed_evals_not_counted);
    tcase_add_test(tc, get_stat_errors);
    suite_add_tcase(s, tc);

    tc = tcase_create("errors");
    tcase_add_test(tc, set_law_errors);
    tcase_add_test(tc, set_bounds_errors);
    tcase_add_test(tc, set_coupling_diagonal_errors);
    tcase_add_test(tc, set_coupling_dense_errors);
    tcase_add_test(tc, eval_errors);
    tcase_add_test(tc, diagonal_eval_validation_every_position);
    tcase_add_test(tc, overflow_is_refused);
    tcase_add_test(tc, eval_singular_stick_block);
    tcase_add_test(tc, eval_failed_factorization_leaves_no_stale_factor);
    tcase_add_test(tc, eval_nearly_singular_stick_block);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(context_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
