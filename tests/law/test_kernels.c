/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_kernels.c — Check suite for the batch kernels' validation pass (src/law/plausible.c: SSE2
 * groups of 8 contacts, or AVX2 groups of 16, then a plain-C tail in 4 lanes), behind
 * fricreg_law_eval_batch and fricreg_ctx_eval, and for their vector loops (AVX2 where the CPU
 * has it, src/base/dispatch.h).
 *
 * Expected values: the promise of include/fricreg.h that bad input gets its code and a failing
 * call writes nothing (every bad element is put at every position of the groups and the tail,
 * and the output must keep its sentinels), and the scalar entry point fricreg_law_eval, which
 * a batch must equal bit for bit (law (4) of shared/spec/paper.md) where the pass raises a
 * false alarm and the exact check lets the batch through. */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg.h"
#include "random.h"
#include "quiet_check.h"

#define EPS 0.0731
#define SENTINEL (-777.125)

static const int all_laws[] = {FRICREG_LAW_COULOMB, FRICREG_LAW_FORCE_BALANCE,
                               FRICREG_LAW_KARNOPP, FRICREG_LAW_VELOCITY_LIMITED,
                               FRICREG_LAW_TANH,    FRICREG_LAW_QUINN};
#define N_LAWS (sizeof all_laws / sizeof all_laws[0])

/* xorshift64*: the same inputs on every run. */
static uint64_t rng_state = 0x9E3779B97F4A7C15u;
static double uniform(void)
{
    return xorshift64star_uniform(&rng_state, 0.0, 1.0);
}

/* Contacts stuck (v = 0), in the band and slipping; f_eq on both sides of +-mun. */
static void fill(size_t m, double v[], double f_eq[], double mun[])
{
    for (size_t i = 0; i < m; i++) {
        double u = uniform(), sign = uniform() < 0.5 ? -1.0 : 1.0;
        v[i] = u < 0.3 ? 0.0 : u < 0.6 ? sign * EPS * uniform() : sign * (EPS + uniform());
        mun[i] = i % 17 == 5 ? 0.0 : 0.25 + uniform();
        f_eq[i] = (4.0 * uniform() - 2.0) * (mun[i] + 0.1);
    }
}

static double *array(size_t m)
{
    double *a = malloc(m * sizeof *a);
    ck_assert_ptr_nonnull(a);
    return a;
}

static int all_sentinel(const double f[], size_t m)
{
    for (size_t i = 0; i < m; i++)
        if (f[i] != SENTINEL)
            return 0;
    return 1;
}

/* The sizes around the vector groups (8 contacts) and the tail's lanes (4). */
static const size_t sizes[] = {1, 2, 7, 8, 9, 15, 16, 17, 23, 31, 32, 33, 47, 64, 65, 1003};
#define N_SIZES (sizeof sizes / sizeof sizes[0])

/* Whether to put a bad element at position p of m: all of them up to 65, else the first and
 * last 40. */
static int probe_position(size_t m, size_t p)
{
    return m <= 65 || p < 40 || p + 40 >= m;
}

struct bad_case {
    int array; /* 0: v, 1: f_eq, 2: mun */
    double value;
    int code;
};
static const struct bad_case bad_cases[] = {
    {0, NAN, FRICREG_ENONFINITE},       {0, INFINITY, FRICREG_ENONFINITE},
    {0, -INFINITY, FRICREG_ENONFINITE}, {1, NAN, FRICREG_ENONFINITE},
    {1, -INFINITY, FRICREG_ENONFINITE}, {2, NAN, FRICREG_ENONFINITE},
    {2, INFINITY, FRICREG_ENONFINITE},  {2, -0.5, FRICREG_EINVAL},
    {2, -4.9e-324, FRICREG_EINVAL}};
#define N_BAD (sizeof bad_cases / sizeof bad_cases[0])

static int reads_feq(int law)
{
    return law == FRICREG_LAW_FORCE_BALANCE || law == FRICREG_LAW_KARNOPP ||
           law == FRICREG_LAW_QUINN;
}

/* Good inputs of m contacts with bad case c at position p: the batch of `law` (f_eq given or
 * NULL) returns the case's code and leaves f alone. */
static void expect_refused(int law, size_t m, size_t p, size_t c, int with_feq, double v[],
                           double f_eq[], double mun[], double f[])
{
    fill(m, v, f_eq, mun);
    double *target = bad_cases[c].array == 0 ? v : bad_cases[c].array == 1 ? f_eq : mun;
    target[p] = bad_cases[c].value;
    for (size_t i = 0; i < m; i++)
        f[i] = SENTINEL;
    int status = fricreg_law_eval_batch(law, EPS, m, v, with_feq ? f_eq : NULL, mun, f);
    QUIET_ASSERT(status == bad_cases[c].code,
                 "law %d, m %zu, array %d = %g at %zu: status %d, expected %d", law, m,
                 bad_cases[c].array, bad_cases[c].value, p, status, bad_cases[c].code);
    QUIET_ASSERT(all_sentinel(f, m), "law %d, m %zu, bad at %zu: f written on failure", law, m, p);
}

/* A bad element anywhere, in any input, for every law, with f_eq given and (where the law
 * does not read it) without. */
START_TEST(batch_rejects_every_position)
{
    size_t cap = sizes[N_SIZES - 1];
    double *v = array(cap), *f_eq = array(cap), *mun = array(cap), *f = array(cap);
    for (size_t l = 0; l < N_LAWS; l++)
        for (int with_feq = 0; with_feq < 2; with_feq++) {
            if (!with_feq && reads_feq(all_laws[l]))
                continue;
            for (size_t z = 0; z < N_SIZES; z++)
                for (size_t c = 0; c < N_BAD; c++)
                    for (size_t p = 0; p < sizes[z]; p++)
                        if (probe_position(sizes[z], p) && (with_feq || bad_cases[c].array != 1))
                            expect_refused(all_laws[l], sizes[z], p, c, with_feq, v, f_eq, mun, f);
        }
    free(v), free(f_eq), free(mun), free(f);
}
END_TEST

/* The validation's false alarms are not failures: mun = -0.0 (it passes mun >= 0), and finite
 * inputs whose sum overflows. The batch equals the scalar law there. */
START_TEST(batch_false_alarms_pass)
{
    enum { M = 40 };
    double v[M], f_eq[M], mun[M], f[M];
    for (size_t p = 0; p < M; p++) {
        fill(M, v, f_eq, mun);
        mun[p] = -0.0;
        v[(p + 3) % M] = 1.5e308;
        f_eq[(p + 5) % M] = 1.7e308;
        v[(p + 7) % M] = 1.6e308;
        ck_assert_int_eq(fricreg_law_eval_batch(FRICREG_LAW_QUINN, EPS, M, v, f_eq, mun, f),
                         FRICREG_OK);
        for (size_t i = 0; i < M; i++) {
            double ref;
            ck_assert_int_eq(fricreg_law_eval(FRICREG_LAW_QUINN, v[i], f_eq[i], mun[i], EPS, &ref),
                             FRICREG_OK);
            ck_assert_msg(memcmp(&f[i], &ref, sizeof ref) == 0, "p %zu, i %zu: %.17g vs %.17g", p,
                          i, f[i], ref);
        }
    }
}
END_TEST

/* A non-finite zdot or a_free anywhere in a W = I evaluation: refused, f untouched. */
START_TEST(context_rejects_every_position)
{
    for (size_t z = 0; z < N_SIZES; z++) {
        size_t m = sizes[z];
        double *v = array(m), *a_free = array(m), *mun = array(m), *f = array(m);
        fricreg_ctx *ctx = NULL;
        ck_assert_int_eq(fricreg_ctx_create(m, &ctx), FRICREG_OK);
        for (size_t p = 0; p < m; p++) {
            if (!probe_position(m, p))
                continue;
            for (int which = 0; which < 4; which++) {
                fill(m, v, a_free, mun);
                double bad = which % 2 ? NAN : -INFINITY;
                (which < 2 ? v : a_free)[p] = bad;
                for (size_t i = 0; i < m; i++)
                    f[i] = SENTINEL;
                ck_assert_int_eq(fricreg_ctx_eval(ctx, m, v, a_free, f, NULL), FRICREG_ENONFINITE);
                ck_assert_msg(all_sentinel(f, m), "m %zu, bad at %zu: f written", m, p);
            }
        }
        fricreg_ctx_free(ctx);
        free(v), free(a_free), free(mun), free(f);
    }
}
END_TEST

/* ---- The vector loops: in AVX2 where the CPU has it (src/base/dispatch.h), else SSE2 */

/* Contacts: odd, so that every vector loop has a remainder. */
#define M_PATH 1003

/* f[i] equals the scalar law at (v[i], f_eq[i], mun[i]) bit for bit, i < m. One assertion
 * for the whole batch: Check records each assertion it passes (at 2^18 contacts that took
 * minutes under valgrind). */
static void expect_scalar_law(int law, size_t m, const double v[], const double f_eq[],
                              const double mun[], const double f[])
{
    size_t bad = m;
    double ref = 0.0;
    for (size_t i = 0; i < m && bad == m; i++) {
        int status = fricreg_law_eval(law, v[i], f_eq ? f_eq[i] : 0.0, mun[i], EPS, &ref);
        if (status != FRICREG_OK || memcmp(&f[i], &ref, sizeof ref) != 0)
            bad = i;
    }
    ck_assert_msg(bad == m, "law %d, m %zu, i %zu: %.17g vs the scalar law's %.17g", law, m, bad,
                  bad < m ? f[bad] : 0.0, ref);
}

/* Every law, to an aligned f and to an f one element off 16-byte alignment, with f_eq and
 * (where the law does not read it) without: the scalar law, bit for bit. */
START_TEST(batch_equals_scalar_law)
{
    double v[M_PATH], f_eq[M_PATH], mun[M_PATH], out[M_PATH + 1];
    for (size_t l = 0; l < N_LAWS; l++)
        for (int c = 0; c < 4; c++) {
            double *f = out + c % 2, *feq = c < 2 ? f_eq : NULL;
            if (!feq && reads_feq(all_laws[l]))
                continue;
            fill(M_PATH, v, f_eq, mun);
            ck_assert_int_eq(fricreg_law_eval_batch(all_laws[l], EPS, M_PATH, v, feq, mun, f),
                             FRICREG_OK);
            expect_scalar_law(all_laws[l], M_PATH, v, feq, mun, f);
        }
}
END_TEST

/* From 2^19 contacts the batch streams f (src/law/law.c): the scalar law still, bit for bit, to an
 * aligned and a misaligned f, for (4) and (1), and over its own input v. */
START_TEST(batch_streamed_equals_scalar_law)
{
    enum { M_BIG = (1 << 19) + 3 };
    double *v = array(M_BIG), *f_eq = array(M_BIG), *mun = array(M_BIG), *out = array(M_BIG + 1);
    static const int laws[2] = {FRICREG_LAW_QUINN, FRICREG_LAW_COULOMB};
    for (int c = 0; c < 4; c++) {
        int law = laws[c / 2];
        double *f = out + c % 2;
        fill(M_BIG, v, f_eq, mun);
        ck_assert_int_eq(fricreg_law_eval_batch(law, EPS, M_BIG, v, f_eq, mun, f), FRICREG_OK);
        expect_scalar_law(law, M_BIG, v, f_eq, mun, f);
    }
    memcpy(out, v, M_BIG * sizeof *v); /* over v itself */
    ck_assert_int_eq(fricreg_law_eval_batch(FRICREG_LAW_QUINN, EPS, M_BIG, out, f_eq, mun, out),
                     FRICREG_OK);
    expect_scalar_law(FRICREG_LAW_QUINN, M_BIG, v, f_eq, mun, out);
    free(v), free(f_eq), free(mun), free(out);
}
END_TEST

/* f may be v or f_eq (include/fricreg.h): a batch written over its own input gives what it
 * gives into a separate array. */
START_TEST(batch_in_place)
{
    double v[M_PATH], f_eq[M_PATH], mun[M_PATH], f[M_PATH], inout[M_PATH];
    for (int over = 0; over < 2; over++) {
        fill(M_PATH, v, f_eq, mun);
        ck_assert_int_eq(fricreg_law_eval_batch(FRICREG_LAW_QUINN, EPS, M_PATH, v, f_eq, mun, f),
                         FRICREG_OK);
        memcpy(inout, over ? f_eq : v, sizeof inout);
        ck_assert_int_eq(fricreg_law_eval_batch(FRICREG_LAW_QUINN, EPS, M_PATH, over ? v : inout,
                                                over ? inout : f_eq, mun, inout),
                         FRICREG_OK);
        ck_assert_msg(memcmp(inout, f, sizeof f) == 0, "f over %s differs", over ? "f_eq" : "v");
    }
}
END_TEST

/* fricreg_ctx_eval with a diagonal W (W = I, and a general diagonal), tangent inputs kept or
 * not: f is the scalar law (4) at f_eq = -a_free/w (Sec. 3.3
 * of shared/spec/paper.md: a diagonal W decouples the contacts), bit for bit; f_eq out is that
 * f_eq on |zdot| < eps and NaN elsewhere; FRICREG_STAT_FEQ_CONTACTS counts |zdot| < eps. */
static void expect_context_law(size_t m, int unit_w, int keep, double v[], double a_free[],
                               double mun[], double w[], double feq_ref[], double f[],
                               double f_eq[])
{
    fricreg_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_ctx_create(m, &ctx), FRICREG_OK);
    fill(m, v, a_free, mun);
    for (size_t i = 0; i < m; i++)
        w[i] = unit_w ? 1.0 : 0.5 + uniform();
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, m, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, EPS), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_coupling_diagonal(ctx, m, w), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_keep_tangent(ctx, keep), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, m, v, a_free, f, f_eq), FRICREG_OK);
    int64_t near = 0, counted = 0;
    size_t bad = m;
    for (size_t i = 0; i < m; i++) {
        feq_ref[i] = -a_free[i] / w[i];
        near += fabs(v[i]) < EPS;
        int same = fabs(v[i]) < EPS ? memcmp(&f_eq[i], &feq_ref[i], sizeof *f_eq) == 0
                                    : isnan(f_eq[i]);
        if (!same && bad == m)
            bad = i;
    }
    ck_assert_msg(bad == m, "m %zu, i %zu: f_eq out %g, -a/w %g", m, bad, bad < m ? f_eq[bad] : 0.0,
                  bad < m ? feq_ref[bad] : 0.0);
    expect_scalar_law(FRICREG_LAW_QUINN, m, v, feq_ref, mun, f);
    ck_assert_int_eq(fricreg_ctx_get_stat(ctx, FRICREG_STAT_FEQ_CONTACTS, &counted), FRICREG_OK);
    ck_assert_int_eq(counted, near);
    fricreg_ctx_free(ctx);
}

START_TEST(context_diagonal_equals_scalar_law)
{
    double v[M_PATH], a_free[M_PATH], mun[M_PATH], w[M_PATH], feq_ref[M_PATH], f[M_PATH];
    double f_eq[M_PATH];
    for (int unit_w = 0; unit_w < 2; unit_w++)
        for (int keep = 0; keep < 2; keep++)
            expect_context_law(M_PATH, unit_w, keep, v, a_free, mun, w, feq_ref, f, f_eq);
}
END_TEST

static Suite *kernels_suite(void)
{
    Suite *s = suite_create("kernels");
    TCase *validation = tcase_create("validation");
    tcase_add_test(validation, batch_rejects_every_position);
    tcase_add_test(validation, batch_false_alarms_pass);
    tcase_add_test(validation, context_rejects_every_position);
    suite_add_tcase(s, validation);
    TCase *paths = tcase_create("vector_loops");
    tcase_add_test(paths, batch_equals_scalar_law);
    tcase_add_test(paths, batch_in_place);
    tcase_add_test(paths, batch_streamed_equals_scalar_law);
    tcase_add_test(paths, context_diagonal_equals_scalar_law);
    suite_add_tcase(s, paths);
    return s;
}

int main(void)
{
    SRunner *runner = srunner_create(kernels_suite());
    srunner_run_all(runner, CK_NORMAL);
    int failed = srunner_ntests_failed(runner);
    srunner_free(runner);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
