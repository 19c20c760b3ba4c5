/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_stribeck.c — Check suite for static > kinetic friction (fricreg_stribeck.h), 1-D and 2-D,
 * scalar and batched.
 *
 * Where the numbers come from: the kinetic curve k(s) = fk + (fs - fk) exp(-(s/vs)^delta) in
 * closed form (hand-evaluated points below); the force balance with fs at v = 0; law (4) of
 * fricreg_law_eval and FRICREG_DISK_QUINN of fricreg_disk_eval, which the law must equal bit for
 * bit when fs = fk; and the Lipschitz bounds of docs/laws2d.md for the continuity sweeps. Inputs
 * from a fixed xorshift generator. */
#include <check.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "fricreg_disk.h"
#include "fricreg_stribeck.h"
#include "random.h"
#include "quiet_check.h"

#define SENTINEL (-777.125)
#define ULP DBL_EPSILON

static uint64_t rng_state = 0x2545f4914f6cdd1du;
static double uniform(double lo, double hi)
{
    return xorshift64star_uniform(&rng_state, lo, hi);
}

struct params {
    double fs, fk, vs, delta;
};

static struct params random_params(void)
{
    struct params p;
    p.fs = uniform(0.2, 4.1);
    p.fk = p.fs * uniform(0.3, 1.0);
    p.vs = uniform(0.01, 0.8);
    p.delta = uniform(0.4, 2.6);
    return p;
}

static double law1(const struct params *p, double v, double g, double eps)
{
    double f = SENTINEL;
    int status = fricreg_stribeck_eval(v, g, p->fs, p->fk, p->vs, p->delta, eps, &f);
    QUIET_OK(status);
    return f;
}

static void law2(const struct params *p, const double v[2], const double g[2], double eps,
                 double f[2])
{
    int status = fricreg_stribeck_disk_eval(v, g, p->fs, p->fk, p->vs, p->delta, eps, f);
    QUIET_OK(status);
}

/* k(s) as the header writes it. */
static double kinetic(const struct params *p, double s)
{
    return p->fk + (p->fs - p->fk) * exp(-pow(s / p->vs, p->delta));
}

/* |k'(s)| = (fs - fk) delta s^(delta-1)/vs^delta exp(-(s/vs)^delta), for s > 0. */
static double kinetic_slope(const struct params *p, double s)
{
    double x = s / p->vs;
    return (p->fs - p->fk) * p->delta * pow(x, p->delta - 1) / p->vs * exp(-pow(x, p->delta));
}

/* ---- the kinetic curve outside the band --------------------------------------------------- */

/* Hand-evaluated: fs = 2.5, fk = 1.5, vs = 0.2, delta = 2 at v = 0.4: (v/vs)^2 = 4,
 * k = 1.5 + exp(-4) = 1.5183156388887342; at v = -0.1: k = 1.5 + exp(-0.25) =
 * 2.2788007830714049, opposing v. delta = 0.5 at v = 0.45: (2.25)^0.5 = 1.5, k = 1.5 +
 * exp(-1.5) = 1.7231301601484299. eps = 0.05 throughout. */
START_TEST(kinetic_curve_hand_values)
{
    struct params p = {2.5, 1.5, 0.2, 2.0};
    ck_assert_double_eq_tol(law1(&p, 0.4, 7.0, 0.05), -1.5183156388887342, 1e-15);
    ck_assert_double_eq_tol(law1(&p, -0.1, 7.0, 0.05), 2.2788007830714049, 1e-15);
    p.delta = 0.5;
    ck_assert_double_eq_tol(law1(&p, 0.45, -3.0, 0.05), -1.7231301601484299, 1e-15);
    /* 2-D: the same magnitude, opposite to v = 0.45 (0.6, -0.8) */
    const double v[2] = {0.27, -0.36}, g[2] = {4.0, 1.0};
    double f[2];
    law2(&p, v, g, 0.05, f);
    ck_assert_double_eq_tol(f[0], -0.6 * 1.7231301601484299, 1e-15);
    ck_assert_double_eq_tol(f[1], 0.8 * 1.7231301601484299, 1e-15);
}
END_TEST

/* |v| >= eps: f = -k(|v|) sgn v (2-D: -k(|v|) v/|v|) for any f_eq, to an ulp of fs. */
START_TEST(kinetic_curve_outside_the_band)
{
    for (int k = 0; k < 20000; k++) {
        struct params p = random_params();
        double eps = uniform(1e-4, 0.3), s = eps * (k % 2 ? uniform(1, 1 + 1e-9) : uniform(1, 40));
        double v = k % 4 < 2 ? s : -s, g = uniform(-9, 9), want = -copysign(kinetic(&p, s), v);
        QUIET_CHECK(fabs(law1(&p, v, g, eps) - want) <= 2 * ULP * p.fs);
        double a = uniform(-4, 4), v2[2] = {s * cos(a), s * sin(a)}, g2[2] = {g, -g / 3};
        double r = hypot(v2[0], v2[1]), f[2];
        if (r < eps)
            continue;
        law2(&p, v2, g2, eps, f);
        double k2 = kinetic(&p, r);
        QUIET_CHECK(hypot(f[0] + k2 * v2[0] / r, f[1] + k2 * v2[1] / r) <= 4 * ULP * p.fs);
    }
}
END_TEST

/* ---- stick and break-away ----------------------------------------------------------------- */

/* v = 0: the force balance with fs, bit for bit: fricreg_law_eval(FORCE_BALANCE, mun = fs) and
 * fricreg_disk_eval(FORCE_BALANCE, mun = fs). So |f_eq| <= fs gives f = f_eq (no creep). */
START_TEST(zero_velocity_holds_up_to_fs)
{
    for (int k = 0; k < 5000; k++) {
        struct params p = random_params();
        double eps = uniform(1e-4, 0.3), g = uniform(-3, 3) * p.fs, want;
        ck_assert_int_eq(fricreg_law_eval(FRICREG_LAW_FORCE_BALANCE, 0.0, g, p.fs, eps, &want),
                         FRICREG_OK);
        double f = law1(&p, 0.0, g, eps);
        ck_assert(memcmp(&f, &want, sizeof f) == 0);
        if (fabs(g) <= p.fs)
            ck_assert(f == g);
        const double zero[2] = {0.0, -0.0};
        double a = uniform(-4, 4), g2[2] = {g * cos(a), g * sin(a)}, f2[2], want2[2];
        ck_assert_int_eq(fricreg_disk_eval(FRICREG_DISK_FORCE_BALANCE, zero, g2, p.fs, eps, want2),
                         FRICREG_OK);
        law2(&p, zero, g2, eps, f2);
        ck_assert(memcmp(f2, want2, sizeof f2) == 0);
        if (hypot(g2[0], g2[1]) <= p.fs)
            ck_assert(f2[0] == g2[0] && f2[1] == g2[1]);
    }
}
END_TEST

/* Break-away exactly at |f_eq| = fs: at v = 0, f_eq = +-fs is held (f = f_eq, zero
 * acceleration); the next double above is not (f = +-fs != f_eq: the contact accelerates). The
 * same along any axis in 2-D, where |(fs, 0)| = fs exactly. */
START_TEST(break_away_at_fs)
{
    for (int k = 0; k < 1000; k++) {
        struct params p = random_params();
        double eps = uniform(1e-4, 0.3);
        for (int sign = -1; sign <= 1; sign += 2) {
            double at = sign * p.fs, past = nextafter(at, sign * INFINITY);
            ck_assert(law1(&p, 0.0, at, eps) == at);
            double f = law1(&p, 0.0, past, eps);
            ck_assert(f == at && f != past);
            const double zero[2] = {0.0, 0.0};
            double g[2] = {0.0, at}, g2[2] = {0.0, past}, f2[2];
            law2(&p, zero, g, eps, f2);
            ck_assert(f2[0] == 0.0 && f2[1] == at);
            law2(&p, zero, g2, eps, f2);
            ck_assert(f2[1] != past && fabs(f2[1]) <= p.fs);
        }
    }
}
END_TEST

/* ---- fs = fk: the plain laws ---------------------------------------------------------------- */

/* With fs = fk the Stribeck law is law (4) with mun = fk (fricreg_law_eval QUINN) and, in 2-D,
 * FRICREG_DISK_QUINN: bit for bit, in and out of the band, whatever vs and delta. */
START_TEST(equal_bounds_give_the_plain_law)
{
    for (int k = 0; k < 20000; k++) {
        struct params p = random_params();
        p.fk = p.fs;
        double eps = uniform(1e-4, 0.3), v = uniform(-2, 2) * eps, g = uniform(-3, 3) * p.fs;
        if (k % 5 == 0)
            v = 0.0;
        double want, f = law1(&p, v, g, eps);
        QUIET_OK(fricreg_law_eval(FRICREG_LAW_QUINN, v, g, p.fs, eps, &want));
        QUIET_ASSERT(memcmp(&f, &want, sizeof f) == 0, "v=%.17g g=%.17g: %.17g vs %.17g", v, g, f,
                     want);
        double v2[2] = {v, uniform(-1, 1) * eps}, g2[2] = {g, uniform(-2, 2) * p.fs};
        double f2[2], want2[2];
        law2(&p, v2, g2, eps, f2);
        QUIET_OK(fricreg_disk_eval(FRICREG_DISK_QUINN, v2, g2, p.fs, eps, want2));
        QUIET_CHECK(memcmp(f2, want2, sizeof f2) == 0);
    }
}
END_TEST

/* ---- continuity, bounds, convergence -------------------------------------------------------- */

/* Local Lipschitz bound (docs/laws2d.md): in the band f is law (4) / the inscribed disk with
 * the bound B = fs + (k(eps) - fs) |v|/eps, so |df| <= |dg| + (5 B/eps + 3 |B'|) |dv| <=
 * |dg| + 8 fs/eps |dv|; outside, |df| <= |k'(|v|)| |dv| (2-D: plus the turn of v/|v|, k/|v|
 * <= fs/eps per unit of dv). Pairs 1e-14 apart around the band edge |v| = eps, v = 0 and the
 * saturation |f_eq| = B: the jump stays within the bound plus a few ulps and below 1e-12 fs. */
START_TEST(continuity_sweeps)
{
    double largest1 = 0.0, largest2 = 0.0;
    for (int k = 0; k < 40000; k++) {
        struct params p = random_params();
        double eps = uniform(1e-3, 0.3), s;
        switch (k % 3) {
        case 0: s = eps * (1 + uniform(-1e-12, 1e-12)); break;
        case 1: s = eps * uniform(0, 1e-12); break;
        default: s = eps * uniform(0, 1.1); break;
        }
        double rho = fmin(s / eps, 1.0), B = p.fs + (kinetic(&p, eps) - p.fs) * rho;
        double g = (k % 2 ? B : p.fs) * (1 + uniform(-1e-12, 1e-12)) * (k % 4 < 2 ? 1 : -1);
        double v = k % 8 < 4 ? s : -s, dv = uniform(-1, 1) * 1e-14 * eps;
        double dg = uniform(-1, 1) * 1e-14 * p.fs;
        double lv = 8 * p.fs / eps + 2 * kinetic_slope(&p, fmax(fabs(v), eps));
        double jump = fabs(law1(&p, v + dv, g + dg, eps) - law1(&p, v, g, eps));
        QUIET_ASSERT(jump <= fabs(dg) + lv * fabs(dv) + 8 * ULP * (p.fs + fabs(g)),
                     "1-D jump %.3g at v=%.17g g=%.17g", jump, v, g);
        largest1 = fmax(largest1, jump / p.fs);

        double a = uniform(-4, 4), b = a + uniform(-0.5, 0.5);
        double v2[2] = {s * cos(a), s * sin(a)}, g2[2] = {g * cos(b), g * sin(b)};
        double w2[2] = {v2[0] + dv, v2[1] - dv}, h2[2] = {g2[0] - dg, g2[1] + dg}, f[2], f2[2];
        law2(&p, v2, g2, eps, f);
        law2(&p, w2, h2, eps, f2);
        double jump2 = hypot(f2[0] - f[0], f2[1] - f[1]);
        QUIET_ASSERT(jump2 <= sqrt(2) * (fabs(dg) + (lv + p.fs / eps) * fabs(dv)) +
                                  16 * ULP * (p.fs + fabs(g)),
                     "2-D jump %.3g at v=(%.17g, %.17g)", jump2, v2[0], v2[1]);
        largest2 = fmax(largest2, jump2 / p.fs);
    }
    ck_assert(largest1 <= 1e-12 && largest2 <= 1e-12);
}
END_TEST

/* |f| <= fs always; and as eps -> 0 the force at a fixed v != 0 is the kinetic curve (once
 * eps <= |v|) while at v = 0 it stays the force balance: pointwise convergence to the set-
 * valued law. */
START_TEST(bounded_and_convergent)
{
    for (int k = 0; k < 20000; k++) {
        struct params p = random_params();
        double eps = uniform(1e-4, 0.3), v = uniform(-1.3, 1.3) * eps, g = uniform(-4, 4) * p.fs;
        QUIET_CHECK(fabs(law1(&p, v, g, eps)) <= p.fs);
        double v2[2] = {v, uniform(-1, 1) * eps}, g2[2] = {g, uniform(-4, 4) * p.fs}, f[2];
        law2(&p, v2, g2, eps, f);
        QUIET_CHECK(hypot(f[0], f[1]) <= p.fs * (1 + 4 * ULP));
    }
    struct params p = {2.5, 1.5, 0.2, 2.0};
    double v = 0.0137, g = 2.0, want = -kinetic(&p, v);
    for (double eps = 0.1; eps > 1e-6; eps /= 3) {
        double f = law1(&p, v, g, eps);
        if (eps <= v)
            ck_assert_double_eq_tol(f, want, 2 * ULP * p.fs);
        ck_assert(law1(&p, 0.0, g, eps) == g);
    }
}
END_TEST

/* ---- batch and bad input ---------------------------------------------------------------------- */

/* The batches give the scalar's bits, also in place. */
START_TEST(batch_equals_scalar)
{
    enum { M = 131 };
    double v[2 * M], g[2 * M], fs[M], fk[M], vs[M], delta[M], f[2 * M], in[2 * M];
    double eps = 0.0731;
    for (int i = 0; i < M; i++) {
        struct params p = random_params();
        fs[i] = p.fs;
        fk[i] = p.fk;
        vs[i] = p.vs;
        delta[i] = p.delta;
        v[2 * i] = i % 7 ? uniform(-1.5, 1.5) * eps : 0.0;
        v[2 * i + 1] = uniform(-1, 1) * eps;
        g[2 * i] = uniform(-3, 3);
        g[2 * i + 1] = uniform(-3, 3);
    }
    ck_assert_int_eq(fricreg_stribeck_eval_batch(eps, M, v, g, fs, fk, vs, delta, f), FRICREG_OK);
    for (int i = 0; i < M; i++) {
        double one;
        ck_assert_int_eq(fricreg_stribeck_eval(v[i], g[i], fs[i], fk[i], vs[i], delta[i], eps,
                                               &one),
                         FRICREG_OK);
        ck_assert(memcmp(&one, f + i, sizeof one) == 0);
    }
    memcpy(in, g, sizeof g);
    ck_assert_int_eq(fricreg_stribeck_eval_batch(eps, M, v, in, fs, fk, vs, delta, in), FRICREG_OK);
    ck_assert(memcmp(in, f, M * sizeof f[0]) == 0);
    ck_assert_int_eq(fricreg_stribeck_disk_eval_batch(eps, M, v, g, fs, fk, vs, delta, f),
                     FRICREG_OK);
    for (int i = 0; i < M; i++) {
        double one[2];
        ck_assert_int_eq(fricreg_stribeck_disk_eval(v + 2 * i, g + 2 * i, fs[i], fk[i], vs[i],
                                                    delta[i], eps, one),
                         FRICREG_OK);
        ck_assert(memcmp(one, f + 2 * i, sizeof one) == 0);
    }
    memcpy(in, v, sizeof v);
    ck_assert_int_eq(fricreg_stribeck_disk_eval_batch(eps, M, in, g, fs, fk, vs, delta, in),
                     FRICREG_OK);
    ck_assert(memcmp(in, f, sizeof f) == 0);
    ck_assert_int_eq(fricreg_stribeck_eval_batch(eps, 0, NULL, NULL, NULL, NULL, NULL, NULL, NULL),
                     FRICREG_OK);
}
END_TEST

/* Every refusal, with its documented code, and nothing written: NULL; NaN or infinity in each
 * number; fk > fs (kinetic above static), fk < 0, vs <= 0, delta <= 0, eps < DBL_MIN; 2-D
 * numbers beyond 1e250. */
START_TEST(bad_input)
{
    const double P[7] = {0.0123, 1.137, 2.5, 1.5, 0.2, 2.0, 0.05}; /* v g fs fk vs delta eps */
    struct {
        int index;
        double value;
        int status;
    } cases[] = {{0, NAN, FRICREG_ENONFINITE},      {1, INFINITY, FRICREG_ENONFINITE},
                 {2, NAN, FRICREG_ENONFINITE},      {3, -INFINITY, FRICREG_ENONFINITE},
                 {4, INFINITY, FRICREG_ENONFINITE}, {5, NAN, FRICREG_ENONFINITE},
                 {6, NAN, FRICREG_ENONFINITE},      {3, 2.5000001, FRICREG_EINVAL},
                 {3, -1e-300, FRICREG_EINVAL},      {4, 0.0, FRICREG_EINVAL},
                 {4, -0.2, FRICREG_EINVAL},         {5, 0.0, FRICREG_EINVAL},
                 {5, -1.0, FRICREG_EINVAL},         {6, DBL_MIN / 2, FRICREG_EINVAL},
                 {6, 0.0, FRICREG_EINVAL}};
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        double q[7];
        memcpy(q, P, sizeof q);
        q[cases[c].index] = cases[c].value;
        double f = SENTINEL, f2[2] = {SENTINEL, SENTINEL}, fb[2] = {SENTINEL, SENTINEL};
        ck_assert_int_eq(fricreg_stribeck_eval(q[0], q[1], q[2], q[3], q[4], q[5], q[6], &f),
                         cases[c].status);
        ck_assert(f == SENTINEL);
        double v2[2] = {q[0], 0.01}, g2[2] = {q[1], -0.3};
        ck_assert_int_eq(fricreg_stribeck_disk_eval(v2, g2, q[2], q[3], q[4], q[5], q[6], f2),
                         cases[c].status);
        ck_assert(f2[0] == SENTINEL && f2[1] == SENTINEL);
        /* a batch of two: the bad contact second, the first fine */
        double bv[2] = {0.001, q[0]}, bg[2] = {0.3, q[1]}, bfs[2] = {2.0, q[2]};
        double bfk[2] = {1.0, q[3]}, bvs[2] = {0.1, q[4]}, bd[2] = {1.0, q[5]};
        ck_assert_int_eq(fricreg_stribeck_eval_batch(q[6], 2, bv, bg, bfs, bfk, bvs, bd, fb),
                         cases[c].status);
        ck_assert(fb[0] == SENTINEL && fb[1] == SENTINEL);
    }
    double f = SENTINEL, f2[2] = {SENTINEL, SENTINEL};
    const double v2[2] = {0.01, 0.02}, g2[2] = {0.5, 0.1}, big[2] = {2e250, 0.0};
    ck_assert_int_eq(fricreg_stribeck_eval(0.1, 0.2, 1.0, 0.5, 0.1, 1.0, 0.01, NULL),
                     FRICREG_ENULL);
    ck_assert_int_eq(fricreg_stribeck_disk_eval(NULL, g2, 1.0, 0.5, 0.1, 1.0, 0.01, f2),
                     FRICREG_ENULL);
    ck_assert_int_eq(fricreg_stribeck_disk_eval(v2, NULL, 1.0, 0.5, 0.1, 1.0, 0.01, f2),
                     FRICREG_ENULL);
    ck_assert_int_eq(fricreg_stribeck_disk_eval(v2, g2, 1.0, 0.5, 0.1, 1.0, 0.01, NULL),
                     FRICREG_ENULL);
    ck_assert_int_eq(fricreg_stribeck_disk_eval(big, g2, 1.0, 0.5, 0.1, 1.0, 0.01, f2),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_stribeck_disk_eval(v2, g2, 3e250, 0.5, 0.1, 1.0, 0.01, f2),
                     FRICREG_EINVAL);
    ck_assert(f2[0] == SENTINEL && f2[1] == SENTINEL);
    /* the 1-D law has no such cap */
    ck_assert_int_eq(fricreg_stribeck_eval(2e250, 0.2, 3e250, 0.5, 0.1, 1.0, 0.01, &f), FRICREG_OK);
    ck_assert(f == -0.5 - (3e250 - 0.5) * exp(-pow(2e250 / 0.1, 1.0)));
    /* batches: a NULL array; a NaN in a later contact beats an earlier fk > fs */
    double a[2] = {0.01, 0.02}, b[2] = {0.3, 0.2}, fs[2] = {1.0, 1.0}, fk[2] = {2.0, 0.5};
    double vs[2] = {0.1, 0.1}, d[2] = {1.0, NAN}, out[4] = {SENTINEL, SENTINEL, SENTINEL, SENTINEL};
    ck_assert_int_eq(fricreg_stribeck_eval_batch(0.01, 2, a, b, fs, fk, NULL, d, out),
                     FRICREG_ENULL);
    ck_assert_int_eq(fricreg_stribeck_eval_batch(0.01, 2, a, b, fs, fk, vs, d, out),
                     FRICREG_ENONFINITE);
    d[1] = 1.0;
    ck_assert_int_eq(fricreg_stribeck_eval_batch(0.01, 2, a, b, fs, fk, vs, d, out),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_stribeck_disk_eval_batch(0.01, 1, a, b, fs, fk, vs, d, out),
                     FRICREG_EINVAL);
    for (int i = 0; i < 4; i++)
        ck_assert(out[i] == SENTINEL);
}
END_TEST

static Suite *stribeck_suite(void)
{
    Suite *s = suite_create("stribeck");
    /* "sweeps": thousands of random points (native and ASan; too slow under valgrind);
     * "cases": hand-worked values, batches and every refusal (valgrind too). */
    TCase *sweeps = tcase_create("sweeps"), *cases = tcase_create("cases");
    tcase_add_test(sweeps, kinetic_curve_outside_the_band);
    tcase_add_test(sweeps, zero_velocity_holds_up_to_fs);
    tcase_add_test(sweeps, equal_bounds_give_the_plain_law);
    tcase_add_test(sweeps, continuity_sweeps);
    tcase_add_test(sweeps, bounded_and_convergent);
    tcase_add_test(cases, kinetic_curve_hand_values);
    tcase_add_test(cases, break_away_at_fs);
    tcase_add_test(cases, batch_equals_scalar);
    tcase_add_test(cases, bad_input);
    suite_add_tcase(s, sweeps);
    suite_add_tcase(s, cases);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(stribeck_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
