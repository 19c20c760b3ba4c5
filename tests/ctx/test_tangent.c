/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_tangent.c — Check suite for fricreg_ctx_tangent, the Jacobian of the forces.
 *
 * Expected values in closed form on the two blocks of spec/paper.md ("Reference system 3"):
 * W = [[1, -1], [-1, 2]], W^-1 = [[2, 1], [1, 1]], mun = (0.5, 0.25), eps = 0.02, so
 * 2 mun/eps = (50, 25) and 2/eps = 100. Consistent law (docs/coupled.md): free contacts F get
 * d f_F = -W_FF^-1 (d b_F + W_FA d f_A) with d b_i/d zdot_i = W_ii 2 mun_i/eps; held contacts the
 * slope of their bound. The paper's partition: law (4) with d f_eq,S/d a_free,S = -W_SS^-1. */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "ctx/ctx_internal.h"
#include "fricreg.h"
#include "random.h"
#include "quiet_check.h"

#define TOL 1e-12
#define SENTINEL (-777.125)

static const double W2B[4] = {1.0, -1.0, -1.0, 2.0};
static const double MUN2B[2] = {0.5, 0.25};
#define EPS2B 0.02

static fricreg_ctx *make_two_block(int partition)
{
    fricreg_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_ctx_create(2, &ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, W2B), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, 2, MUN2B), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, EPS2B), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_partition(ctx, partition), FRICREG_OK);
    return ctx;
}

static void expect_matrix(const double got[], const double want[], size_t n, const char *what)
{
    for (size_t k = 0; k < n; k++)
        QUIET_ASSERT(fabs(got[k] - want[k]) <= TOL * fmax(1.0, fabs(want[k])),
                     "%s[%zu] = %.17g, expected %.17g", what, k, got[k], want[k]);
}

/* Both free: d f/d zdot = -W^-1 diag(1 * 50, 2 * 25) = -[[100, 50], [50, 50]];
 * d f/d a_free = -W^-1. And W d f/d zdot = -diag(50, 50): the accelerations decouple. */
START_TEST(consistent_both_free)
{
    fricreg_ctx *ctx = make_two_block(FRICREG_PARTITION_CONSISTENT);
    const double z[2] = {0.0037, -0.0031}, a[2] = {0.213, -0.347};
    double f[2], dz[4], da[4];
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z, a, f, NULL), FRICREG_OK);
    int64_t fact = -1;
    ck_assert_int_eq(fricreg_ctx_get_stat(ctx, FRICREG_STAT_FACTORIZATIONS, &fact), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_tangent(ctx, 2, dz, da), FRICREG_OK);
    const double want_dz[4] = {-100.0, -50.0, -50.0, -50.0}, want_da[4] = {-2.0, -1.0, -1.0, -1.0};
    expect_matrix(dz, want_dz, 4, "df_dzdot");
    expect_matrix(da, want_da, 4, "df_dafree");
    int64_t after = -1; /* the eval's factor of W_FF is reused */
    ck_assert_int_eq(fricreg_ctx_get_stat(ctx, FRICREG_STAT_FACTORIZATIONS, &after), FRICREG_OK);
    ck_assert_int_eq(after, fact);
    /* either output alone gives the same numbers */
    double only[4];
    ck_assert_int_eq(fricreg_ctx_tangent(ctx, 2, NULL, only), FRICREG_OK);
    expect_matrix(only, want_da, 4, "df_dafree alone");
    ck_assert_int_eq(fricreg_ctx_tangent(ctx, 2, only, NULL), FRICREG_OK);
    expect_matrix(only, want_dz, 4, "df_dzdot alone");
    fricreg_ctx_free(ctx);
}
END_TEST

/* Contact 1 held at its velocity-dependent upper bound. zdot = (0, 0.005): c = (0, 0.5),
 * boxes [-0.5, 0.5] and [-0.25, 0.125]; a = (0.1, -0.8): b = (0.1, -0.8 + 2 * 0.5 * 0.25)
 * = (0.1, -0.55). With f1 = 0.125: f0 = -(0.1 - 0.125) = 0.025 (free), and the multiplier
 * g1 = -0.55 - 0.025 + 0.25 = -0.325 <= 0 keeps f1 at the upper bound. Tangent:
 * d f1/d zdot1 = d hi1/d zdot1 = -0.25 * 100 = -25; d f0/d zdot0 = -50;
 * d f0/d zdot1 = -W00^-1 W01 (-25) = -25. d f/d a_free = [[-1, 0], [0, 0]]. The held contact
 * sees the Schur complement: d zddot1/d zdot1 = W10 (-25) + W11 (-25) = -25 = -(2 - 1) 25. */
START_TEST(consistent_one_held_at_moving_bound)
{
    fricreg_ctx *ctx = make_two_block(FRICREG_PARTITION_CONSISTENT);
    const double z[2] = {0.0, 0.005}, a[2] = {0.1, -0.8};
    double f[2], dz[4], da[4];
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z, a, f, NULL), FRICREG_OK);
    ck_assert_double_eq_tol(f[0], 0.025, TOL);
    ck_assert_double_eq_tol(f[1], 0.125, TOL);
    ck_assert_int_eq(fricreg_ctx_tangent(ctx, 2, dz, da), FRICREG_OK);
    const double want_dz[4] = {-50.0, -25.0, 0.0, -25.0}, want_da[4] = {-1.0, 0.0, 0.0, 0.0};
    expect_matrix(dz, want_dz, 4, "df_dzdot");
    expect_matrix(da, want_da, 4, "df_dafree");
    fricreg_ctx_free(ctx);
}
END_TEST

/* The paper's partition, both near-stick: f_eq = (-0.079, 0.134) inside the bounds and both in
 * (4)'s linear zone: d f/d zdot = -diag(50, 25), d f/d a_free = -W^-1. */
START_TEST(paper_both_near_stick)
{
    fricreg_ctx *ctx = make_two_block(FRICREG_PARTITION_PAPER);
    const double z[2] = {0.0037, -0.0031}, a[2] = {0.213, -0.347};
    double f[2], dz[4], da[4];
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z, a, f, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_tangent(ctx, 2, dz, da), FRICREG_OK);
    const double want_dz[4] = {-50.0, 0.0, 0.0, -25.0}, want_da[4] = {-2.0, -1.0, -1.0, -1.0};
    expect_matrix(dz, want_dz, 4, "df_dzdot");
    expect_matrix(da, want_da, 4, "df_dafree");
    fricreg_ctx_free(ctx);
}
END_TEST

/* Diagonal W = diag(2.385, 0.731, 1.913), mun = (0.9, 0.35, 1.2), eps = 0.0731 (the case of
 * test_context's diagonal_coupling_divides): contact 0 in (4)'s linear zone: -1.8/0.0731 in
 * zdot, -1/2.385 in a_free; contact 1 saturated (f_eq = -0.7 < -mun) and at its lower bound
 * lo = -0.35 (1 + c), c = 2 (-0.0402)/0.0731 < 0: -0.7/0.0731 in zdot, 0 in a_free; contact 2
 * slides: 0. The same W passed dense under the consistent law gives the same Jacobian. */
START_TEST(diagonal_and_its_dense_twin_agree)
{
    const double w[3] = {2.385, 0.731, 1.913}, mun[3] = {0.9, 0.35, 1.2};
    const double z[3] = {0.0104, -0.0402, -0.0873}, a[3] = {-0.617, 0.5117, 4.4};
    const double Wd[9] = {2.385, 0, 0, 0, 0.731, 0, 0, 0, 1.913};
    double want_dz[9] = {0}, want_da[9] = {0};
    want_dz[0] = -1.8 / 0.0731;
    want_dz[4] = -0.7 / 0.0731;
    want_da[0] = -1.0 / 2.385;
    for (int dense = 0; dense < 2; dense++) {
        fricreg_ctx *ctx = NULL;
        ck_assert_int_eq(fricreg_ctx_create(3, &ctx), FRICREG_OK);
        if (dense)
            ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 3, Wd), FRICREG_OK);
        else
            ck_assert_int_eq(fricreg_ctx_set_coupling_diagonal(ctx, 3, w), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, 3, mun), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 0.0731), FRICREG_OK);
        double f[3], dz[9], da[9];
        ck_assert_int_eq(fricreg_ctx_eval(ctx, 3, z, a, f, NULL), FRICREG_OK);
        ck_assert_double_eq_tol(f[1], 0.034952120383036939, TOL);
        ck_assert_int_eq(fricreg_ctx_tangent(ctx, 3, dz, da), FRICREG_OK);
        expect_matrix(dz, want_dz, 9, dense ? "dense df_dzdot" : "diagonal df_dzdot");
        expect_matrix(da, want_da, 9, dense ? "dense df_dafree" : "diagonal df_dafree");
        fricreg_ctx_free(ctx);
    }
}
END_TEST

/* From FR_CODED_TANGENT_FROM contacts on the diagonal pass keeps, instead of the evaluation's
 * inputs, one code per contact from which the tangent is rebuilt (src/law/law.h,
 * fr_near_tangent_code); coded_from = 0 (the static library's internal field) makes it do so
 * here. Both, against the same W given densely under the paper's partition, whose tangent
 * differentiates law (4) at the kept inputs: 64 contacts of (4), (2) and Karnopp, velocities
 * in and out of the band, 0 and +-eps exactly (the kink rules: v = 0 takes the side v > 0,
 * |v| = eps slides), f_eq inside and beyond the bounds: the same matrices to 1e-12. */
START_TEST(coded_diagonal_matches_dense_twin)
{
    enum { M = 64 };
    static const int laws[3] = {FRICREG_LAW_QUINN, FRICREG_LAW_FORCE_BALANCE, FRICREG_LAW_KARNOPP};
    const double eps = 0.05;
    double w[M], mun[M], z[M], a[M], Wd[M * M] = {0};
    uint64_t state = 20261122;
    for (size_t i = 0; i < M; i++) {
        w[i] = splitmix64_uniform(&state, 0.5, 2.0);
        mun[i] = splitmix64_uniform(&state, 0.1, 1.5);
        Wd[i * M + i] = w[i];
        z[i] = i % 8 == 0   ? 0.0
               : i % 8 == 1 ? eps
               : i % 8 == 2 ? -eps
                            : splitmix64_uniform(&state, -2 * eps, 2 * eps);
        a[i] = w[i] * splitmix64_uniform(&state, -2.0, 2.0) * mun[i]; /* |f_eq| up to 2 mun */
    }
    static double dz[3][M * M], da[3][M * M]; /* diagonal coded, diagonal with inputs, dense */
    for (int l = 0; l < 3; l++) {
        for (int run = 0; run < 3; run++) {
            int dense = run == 2;
            fricreg_ctx *ctx = NULL;
            double f[M];
            ck_assert_int_eq(fricreg_ctx_create(M, &ctx), FRICREG_OK);
            if (run == 0)
                ctx->coded_from = 0;
            if (dense) {
                ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, M, Wd), FRICREG_OK);
                ck_assert_int_eq(fricreg_ctx_set_partition(ctx, FRICREG_PARTITION_PAPER),
                                 FRICREG_OK);
            } else {
                ck_assert_int_eq(fricreg_ctx_set_coupling_diagonal(ctx, M, w), FRICREG_OK);
            }
            ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, M, mun), FRICREG_OK);
            ck_assert_int_eq(fricreg_ctx_set_law(ctx, laws[l], eps), FRICREG_OK);
            ck_assert_int_eq(fricreg_ctx_eval(ctx, M, z, a, f, NULL), FRICREG_OK);
            ck_assert_int_eq(fricreg_ctx_tangent(ctx, M, dz[run], da[run]), FRICREG_OK);
            ck_assert_int_eq(ctx->last_coded, run == 0);
            fricreg_ctx_free(ctx);
        }
        for (int run = 0; run < 2; run++) {
            expect_matrix(dz[run], dz[2], M * M, fricreg_law_name(laws[l]));
            expect_matrix(da[run], da[2], M * M, fricreg_law_name(laws[l]));
        }
        int slopes = 0, held = 0; /* the sample reaches every piece: the check is not 0 = 0 */
        for (size_t i = 0; i < M; i++) {
            slopes += dz[0][i * M + i] != 0.0;
            held += fabs(a[i] / w[i]) > mun[i] && da[0][i * M + i] == 0.0 && fabs(z[i]) < eps;
        }
        if (laws[l] == FRICREG_LAW_QUINN)
            ck_assert_int_gt(slopes, 8);
        ck_assert_int_gt(held, 2);
    }
}
END_TEST

/* Laws without f_eq, dense W: the slope in v on the diagonal, nothing in a_free.
 * zdot = (0.0037, 0.05), eps = 0.02: (3) gives -0.5/0.02 = -25 for contact 0 and 0 outside
 * the band; tanh gives -(mun/eps) sech^2(zdot/eps) for both. */
START_TEST(laws_without_feq)
{
    fricreg_ctx *ctx = make_two_block(FRICREG_PARTITION_CONSISTENT);
    const double z[2] = {0.0037, 0.05}, a[2] = {0.213, -0.347};
    double f[2], dz[4], da[4];
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_VELOCITY_LIMITED, EPS2B), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z, a, f, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_tangent(ctx, 2, dz, da), FRICREG_OK);
    const double zero[4] = {0}, want3[4] = {-25.0, 0.0, 0.0, 0.0};
    expect_matrix(dz, want3, 4, "(3) df_dzdot");
    expect_matrix(da, zero, 4, "(3) df_dafree");

    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_TANH, EPS2B), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z, a, f, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_tangent(ctx, 2, dz, da), FRICREG_OK);
    double c0 = cosh(0.185), c1 = cosh(2.5);
    const double want_tanh[4] = {-25.0 / (c0 * c0), 0.0, 0.0, -12.5 / (c1 * c1)};
    expect_matrix(dz, want_tanh, 4, "tanh df_dzdot");
    fricreg_ctx_free(ctx);
}
END_TEST

/* Central differences of fricreg_ctx_eval on m = 4, away from kinks, under both partitions:
 * W = A A^T + 0.3 I with a fixed A; a mix of free, held and sliding contacts. Step h = 1e-7
 * in zdot (band 0.0731 wide) and in a_free: truncation O(h^2) vanishes on the linear pieces,
 * rounding ~1e-16 * 100 / 1e-7 = 1e-7 relative. */
START_TEST(central_differences)
{
    const double A[16] = {0.731,  -0.412, 1.137, 0.213, 0.318, 1.913,  -0.627, 0.044,
                          -1.205, 0.097,  0.388, 1.472, 0.659, -0.733, 0.142,  -0.318};
    double W[16];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double s = i == j ? 0.3 : 0.0;
            for (int k = 0; k < 4; k++)
                s += A[i * 4 + k] * A[j * 4 + k];
            W[i * 4 + j] = s;
        }
    const double mun[4] = {0.9, 0.35, 1.2, 2.385}, eps = 0.0731, h = 1e-7;
    const double z[4] = {0.0104, -0.0202, 0.0003, 0.1611}, a[4] = {1.617, -0.385, 0.244, -1.031};
    for (int partition = 1; partition <= 2; partition++) {
        fricreg_ctx *ctx = NULL;
        ck_assert_int_eq(fricreg_ctx_create(4, &ctx), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 4, W), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, 4, mun), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, eps), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_set_partition(ctx, partition), FRICREG_OK);
        double f[4], dz[16], da[16], fp[4], fm[4];
        ck_assert_int_eq(fricreg_ctx_eval(ctx, 4, z, a, f, NULL), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_tangent(ctx, 4, dz, da), FRICREG_OK);
        double scale = 0.0;
        for (int k = 0; k < 16; k++)
            scale = fmax(scale, fabs(dz[k]));
        for (int j = 0; j < 4; j++) {
            for (int which = 0; which < 2; which++) {
                double zp[4], zm[4], ap[4], am[4];
                memcpy(zp, z, sizeof zp), memcpy(zm, z, sizeof zm);
                memcpy(ap, a, sizeof ap), memcpy(am, a, sizeof am);
                if (which == 0)
                    zp[j] += h, zm[j] -= h;
                else
                    ap[j] += h, am[j] -= h;
                ck_assert_int_eq(fricreg_ctx_eval(ctx, 4, zp, ap, fp, NULL), FRICREG_OK);
                ck_assert_int_eq(fricreg_ctx_eval(ctx, 4, zm, am, fm, NULL), FRICREG_OK);
                for (int i = 0; i < 4; i++) {
                    double fd = (fp[i] - fm[i]) / (2.0 * h);
                    double an = which == 0 ? dz[i * 4 + j] : da[i * 4 + j];
                    double ref = which == 0 ? scale : 1.0;
                    ck_assert_msg(fabs(fd - an) <= 1e-6 * ref,
                                  "partition %d, d f_%d/d %s_%d: %.12g vs differences %.12g",
                                  partition, i, which ? "a_free" : "zdot", j, an, fd);
                }
            }
        }
        fricreg_ctx_free(ctx);
    }
}
END_TEST

/* Errors: ENULL (ctx, both outputs), ESIZE, EINVAL before any evaluation and after each
 * setter; outputs untouched on failure. A failed evaluation leaves the last successful one's
 * Jacobian in place. */
START_TEST(errors)
{
    fricreg_ctx *ctx = make_two_block(FRICREG_PARTITION_CONSISTENT);
    double dz[9], da[4];
    for (int k = 0; k < 9; k++)
        dz[k] = SENTINEL;
    ck_assert_int_eq(fricreg_ctx_tangent(NULL, 2, dz, da), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_ctx_tangent(ctx, 2, dz, da), FRICREG_EINVAL); /* no eval yet */
    ck_assert_ptr_nonnull(strstr(fricreg_ctx_errmsg(ctx), "tangent"));
    const double z[2] = {0.0037, -0.0031}, a[2] = {0.213, -0.347};
    double f[2];
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z, a, f, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_tangent(ctx, 2, NULL, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_ctx_errcode(ctx), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_ctx_tangent(ctx, 3, dz, NULL), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_ctx_errcode(ctx), FRICREG_ESIZE);
    for (int k = 0; k < 9; k++)
        ck_assert_double_eq(dz[k], SENTINEL);

    /* a failed eval (NaN) does not disturb it */
    const double bad[2] = {NAN, 0.0};
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, bad, a, f, NULL), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_ctx_tangent(ctx, 2, dz, NULL), FRICREG_OK);
    ck_assert_double_eq_tol(dz[0], -100.0, TOL * 100.0);

    /* every setter invalidates it, also one that sets the same value */
    for (int setter = 0; setter < 5; setter++) {
        ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z, a, f, NULL), FRICREG_OK);
        switch (setter) {
        case 0: ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, EPS2B), 0); break;
        case 1: ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, 2, MUN2B), 0); break;
        case 2: ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, W2B), 0); break;
        case 3: ck_assert_int_eq(fricreg_ctx_set_partition(ctx, 1), 0); break;
        default: ck_assert_int_eq(fricreg_ctx_set_coupling_diagonal(ctx, 2, MUN2B), 0); break;
        }
        for (int k = 0; k < 4; k++)
            da[k] = SENTINEL;
        ck_assert_int_eq(fricreg_ctx_tangent(ctx, 2, NULL, da), FRICREG_EINVAL);
        for (int k = 0; k < 4; k++)
            ck_assert_double_eq(da[k], SENTINEL);
    }
    fricreg_ctx_free(ctx);
}
END_TEST

/* A failed factorization between eval and tangent: W = [[0.731, 1.462], [1.462, 2.924]] has
 * rank 1. zdot = (0.0037, 0.153): contact 1 slides (f1 = -0.25), S = F = {0}: f_eq0 =
 * -(0.213 + 1.462 (-0.25))/0.731, f0 = f_eq0 - 0.37 * 0.5 = 0.0236..., inside [-0.5, 0.315]:
 * d f0/d zdot0 = -W00^-1 W00 0.5 * 100 = -50, d f0/d a_free0 = -1/0.731. Then both at rest:
 * W_FF = W is singular (ESINGULAR), which overwrites the cached factor; the tangent is still
 * the first evaluation's, at the price of one factorization. */
START_TEST(tangent_survives_a_failed_factorization)
{
    const double Wr[4] = {0.731, 1.462, 1.462, 2.924};
    fricreg_ctx *ctx = make_two_block(FRICREG_PARTITION_CONSISTENT);
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, Wr), FRICREG_OK);
    const double z[2] = {0.0037, 0.153}, rest[2] = {0.0, 0.0}, a[2] = {0.213, -0.347};
    double f[2], dz[4], da[4];
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, z, a, f, NULL), FRICREG_OK);
    ck_assert_double_eq(f[1], -0.25);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, rest, a, f, NULL), FRICREG_ESINGULAR);
    int64_t before = -1, after = -1;
    ck_assert_int_eq(fricreg_ctx_get_stat(ctx, FRICREG_STAT_FACTORIZATIONS, &before), 0);
    ck_assert_int_eq(fricreg_ctx_tangent(ctx, 2, dz, da), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_get_stat(ctx, FRICREG_STAT_FACTORIZATIONS, &after), 0);
    ck_assert_int_eq(after, before + 1);
    const double want_dz[4] = {-50.0, 0.0, 0.0, 0.0}, want_da[4] = {-1.0 / 0.731, 0.0, 0.0, 0.0};
    expect_matrix(dz, want_dz, 4, "df_dzdot");
    expect_matrix(da, want_da, 4, "df_dafree");
    fricreg_ctx_free(ctx);
}
END_TEST

/* fricreg_ctx_set_keep_tangent: ENULL, EINVAL for keep outside {0, 1} (with a message); with
 * the inputs off, f and f_eq are the same to the bit for every law on W = I (no division), a
 * non-unit diagonal W and a dense W, and the tangent is refused (outputs untouched); turned
 * back on, it is refused until the next evaluation, then equals a context that kept them all
 * along, to the bit. 64 random contacts (5 with the dense W): a third at rest, a third in the
 * band, a third sliding; f_eq within +-2 mun. */
START_TEST(keep_tangent_off_changes_no_force)
{
    enum { M = 64, MD = 5 };
    ck_assert_int_eq(fricreg_ctx_set_keep_tangent(NULL, 0), FRICREG_ENULL);
    static double z[M], a[M], mun[M], w[M], f_on[M], f_off[M], feq_on[M], feq_off[M];
    static double dz_on[M * M], dz_off[M * M], da_on[M * M], da_off[M * M];
    uint64_t s = 0x2385u;
    const double eps = 0.0137;
    for (size_t i = 0; i < M; i++) {
        double r[4];
        for (int k = 0; k < 4; k++) {
            s = s * 6364136223846793005ULL + 1442695040888963407ULL;
            r[k] = (double)(s >> 11) * 0x1.0p-53;
        }
        z[i] = r[0] < 0.33 ? 0.0 : r[0] < 0.67 ? (2.0 * r[1] - 1.0) * eps : (2.0 * r[1] - 1.0);
        mun[i] = 0.25 + r[2];
        w[i] = 0.5 + r[3];
        a[i] = (4.0 * r[1] - 2.0) * mun[i] * w[i];
    }
    const double Wd[MD * MD] = {2.1, 0.3, -0.2, 0.1, 0.0, 0.3, 1.7,  0.4, 0.0, 0.2, -0.2, 0.4,  1.9,
                                0.5, 0.1, 0.1,  0.0, 0.5, 2.3, -0.3, 0.0, 0.2, 0.1, -0.3, 1.385};
    for (int coupling = 0; coupling < 3; coupling++)
        for (int law = FRICREG_LAW_COULOMB; law <= FRICREG_LAW_QUINN; law++) {
            size_t m = coupling == 2 ? MD : M;
            fricreg_ctx *on = NULL, *off = NULL;
            fricreg_ctx *both[2];
            ck_assert_int_eq(fricreg_ctx_create(m, &on), FRICREG_OK);
            ck_assert_int_eq(fricreg_ctx_create(m, &off), FRICREG_OK);
            both[0] = on, both[1] = off;
            for (int c = 0; c < 2; c++) {
                ck_assert_int_eq(fricreg_ctx_set_bounds(both[c], m, mun), FRICREG_OK);
                ck_assert_int_eq(fricreg_ctx_set_law(both[c], law, eps), FRICREG_OK);
                if (coupling == 1)
                    ck_assert_int_eq(fricreg_ctx_set_coupling_diagonal(both[c], m, w), 0);
                if (coupling == 2)
                    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(both[c], m, Wd), 0);
            }
            ck_assert_int_eq(fricreg_ctx_set_keep_tangent(off, 2), FRICREG_EINVAL);
            ck_assert_ptr_nonnull(strstr(fricreg_ctx_errmsg(off), "keep"));
            ck_assert_int_eq(fricreg_ctx_set_keep_tangent(off, 0), FRICREG_OK);
            ck_assert_int_eq(fricreg_ctx_eval(on, m, z, a, f_on, feq_on), FRICREG_OK);
            ck_assert_int_eq(fricreg_ctx_eval(off, m, z, a, f_off, feq_off), FRICREG_OK);
            for (size_t i = 0; i < m; i++) {
                ck_assert_mem_eq(&f_on[i], &f_off[i], sizeof f_on[i]);
                ck_assert_mem_eq(&feq_on[i], &feq_off[i], sizeof feq_on[i]);
            }
            for (size_t k = 0; k < m * m; k++)
                dz_off[k] = SENTINEL;
            ck_assert_int_eq(fricreg_ctx_tangent(off, m, dz_off, NULL), FRICREG_EINVAL);
            ck_assert_ptr_nonnull(strstr(fricreg_ctx_errmsg(off), "set_keep_tangent"));
            ck_assert_double_eq(dz_off[0], SENTINEL);
            ck_assert_int_eq(fricreg_ctx_set_keep_tangent(off, 1), FRICREG_OK);
            ck_assert_int_eq(fricreg_ctx_tangent(off, m, dz_off, NULL), FRICREG_EINVAL);
            ck_assert_int_eq(fricreg_ctx_eval(off, m, z, a, f_off, NULL), FRICREG_OK);
            ck_assert_int_eq(fricreg_ctx_tangent(on, m, dz_on, da_on), FRICREG_OK);
            ck_assert_int_eq(fricreg_ctx_tangent(off, m, dz_off, da_off), FRICREG_OK);
            ck_assert_mem_eq(dz_on, dz_off, m * m * sizeof dz_on[0]);
            ck_assert_mem_eq(da_on, da_off, m * m * sizeof da_on[0]);
            fricreg_ctx_free(on);
            fricreg_ctx_free(off);
        }
}
END_TEST

static Suite *tangent_suite(void)
{
    Suite *s = suite_create("tangent");
    TCase *tc = tcase_create("tangent");
    tcase_add_test(tc, consistent_both_free);
    tcase_add_test(tc, consistent_one_held_at_moving_bound);
    tcase_add_test(tc, paper_both_near_stick);
    tcase_add_test(tc, diagonal_and_its_dense_twin_agree);
    tcase_add_test(tc, coded_diagonal_matches_dense_twin);
    tcase_add_test(tc, laws_without_feq);
    tcase_add_test(tc, central_differences);
    tcase_add_test(tc, errors);
    tcase_add_test(tc, tangent_survives_a_failed_factorization);
    tcase_add_test(tc, keep_tangent_off_changes_no_force);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(tangent_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
