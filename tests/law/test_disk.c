/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_disk.c — Check suite for the 2-D friction laws (fricreg_disk.h): fricreg_disk_eval,
 * fricreg_disk_eval_batch, fricreg_disk_law_name, fricreg_disk_law_from_name.
 *
 * Where the numbers come from: the force balance P_D in closed form (g if |g| <= mun, else
 * mun g/|g|); the 1-D law (4) of fricreg_law_eval, which every 2-D law must give on a line
 * (docs/laws2d.md); hand-worked projections onto the lens, the inscribed disk and the disk
 * (derived in each test's comment); rotations, under which an isotropic law commutes; and the
 * Lipschitz constants of docs/laws2d.md for the continuity sweeps. Inputs are drawn from a fixed
 * xorshift generator, so every run checks the same high-entropy points. */
#include <check.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "fricreg_disk.h"
#include "random.h"
#include "quiet_check.h"

#define SENTINEL (-777.125)
#define ULP DBL_EPSILON

static const int regularized[] = {FRICREG_DISK_QUINN, FRICREG_DISK_QUINN_LENS,
                                  FRICREG_DISK_QUINN_NESTED};
#define N_REG (sizeof regularized / sizeof regularized[0])
static const int all_laws[] = {FRICREG_DISK_COULOMB, FRICREG_DISK_FORCE_BALANCE, FRICREG_DISK_QUINN,
                               FRICREG_DISK_QUINN_LENS, FRICREG_DISK_QUINN_NESTED};
#define N_ALL (sizeof all_laws / sizeof all_laws[0])

/* xorshift64*: the same sequence on every platform. */
static uint64_t rng_state = 0x9e3779b97f4a7c15u;
static double uniform(double lo, double hi)
{
    return xorshift64star_uniform(&rng_state, lo, hi);
}

static void eval(int law, const double v[2], const double g[2], double mun, double eps, double f[2])
{
    int status = fricreg_disk_eval(law, v, g, mun, eps, f);
    QUIET_ASSERT(status == FRICREG_OK, "law %d: status %d", law, status);
}

static int same_bits(const double a[2], const double b[2])
{
    return memcmp(a, b, 2 * sizeof a[0]) == 0;
}

static void rotate(double theta, const double x[2], double y[2])
{
    double c = cos(theta), s = sin(theta), y0 = c * x[0] - s * x[1], y1 = s * x[0] + c * x[1];
    y[0] = y0;
    y[1] = y1;
}

/* ---- v = 0: the force balance, exactly ---------------------------------------------------- */

/* At v = 0 every law but (1) is the 2-D (2): f = g if |g| <= mun, else mun g/|g| (computed as
 * mun (g/|g|) with |g| = hypot: g/|g| first, so that mun/|g| cannot underflow), bit for bit,
 * also for v = (-0, 0) and (0, -0). */
START_TEST(zero_velocity_is_force_balance)
{
    const double zeros[3][2] = {{0.0, 0.0}, {-0.0, 0.0}, {0.0, -0.0}};
    for (int k = 0; k < 3000; k++) {
        double mun = uniform(0.05, 7.3), eps = uniform(1e-6, 2.0);
        double rho = k % 3 == 0 ? uniform(0.0, 1.0) : uniform(0.5, 3.0), th = uniform(-4, 4);
        double g[2] = {rho * mun * cos(th), rho * mun * sin(th)}, want[2], f[2];
        double r = hypot(g[0], g[1]);
        want[0] = r <= mun ? g[0] : mun * (g[0] / r);
        want[1] = r <= mun ? g[1] : mun * (g[1] / r);
        for (int z = 0; z < 3; z++) {
            eval(FRICREG_DISK_FORCE_BALANCE, zeros[z], g, mun, eps, f);
            ck_assert_msg(same_bits(f, want), "force balance at g = (%.17g, %.17g)", g[0], g[1]);
            for (size_t l = 0; l < N_REG; l++) {
                eval(regularized[l], zeros[z], g, mun, eps, f);
                QUIET_ASSERT(same_bits(f, want),
                             "law %d at v = 0: (%.17g, %.17g), want "
                             "(%.17g, %.17g)",
                             regularized[l], f[0], f[1], want[0], want[1]);
            }
        }
        /* inside the disk the force is f_eq itself: exact stick, no creep */
        if (r <= mun)
            ck_assert(f[0] == g[0] && f[1] == g[1]);
    }
}
END_TEST

/* mun = 0 gives f = 0 for every law and input. */
START_TEST(zero_bound_gives_zero_force)
{
    for (int k = 0; k < 200; k++) {
        double v[2] = {uniform(-2, 2), uniform(-2, 2)}, g[2] = {uniform(-5, 5), uniform(-5, 5)};
        if (k % 4 == 0)
            v[0] = v[1] = 0.0;
        for (size_t l = 0; l < N_ALL; l++) {
            double f[2];
            eval(all_laws[l], v, g, 0.0, uniform(0.01, 3.0), f);
            ck_assert(f[0] == 0.0 && f[1] == 0.0);
        }
    }
}
END_TEST

/* ---- on a line: the 1-D laws ------------------------------------------------------------- */

/* With v = s e and f_eq = q e for a unit vector e, each 2-D law is its 1-D law along e:
 * f = f1d(s, q) e, to rounding (the 2-D kernels work in a rotated frame: a few ulps of mun +
 * |q|). Against fricreg_law_eval: (4) for the three regularized laws (the lens, the inscribed
 * disk and the nested form all reduce to [-mun, mun] ∩ ([-mun, mun] - c mun) on the axis),
 * (2) and (1) for the others. */
START_TEST(line_is_the_1d_law)
{
    const int pairs[][2] = {{FRICREG_DISK_COULOMB, FRICREG_LAW_COULOMB},
                            {FRICREG_DISK_FORCE_BALANCE, FRICREG_LAW_FORCE_BALANCE},
                            {FRICREG_DISK_QUINN, FRICREG_LAW_QUINN},
                            {FRICREG_DISK_QUINN_LENS, FRICREG_LAW_QUINN},
                            {FRICREG_DISK_QUINN_NESTED, FRICREG_LAW_QUINN}};
    double worst = 0.0;
    for (int k = 0; k < 20000; k++) {
        double mun = uniform(0.1, 4.7), eps = uniform(1e-4, 1.5), th = uniform(-3.5, 3.5);
        double e[2] = {cos(th), sin(th)};
        double s = k % 5 == 0 ? 0.0 : uniform(-1.6, 1.6) * eps, q = uniform(-3.0, 3.0) * mun;
        double v[2] = {s * e[0], s * e[1]}, g[2] = {q * e[0], q * e[1]};
        for (size_t p = 0; p < sizeof pairs / sizeof pairs[0]; p++) {
            double f[2], f1;
            eval(pairs[p][0], v, g, mun, eps, f);
            QUIET_OK(fricreg_law_eval(pairs[p][1], s, q, mun, eps, &f1));
            double along = f[0] * e[0] + f[1] * e[1], across = f[1] * e[0] - f[0] * e[1];
            double tol = 16 * ULP * (mun + fabs(q));
            double err = fmax(fabs(along - f1), fabs(across));
            worst = fmax(worst, err / (mun + fabs(q)));
            QUIET_ASSERT(err <= tol,
                         "law %d on a line: s=%.17g q=%.17g mun=%.17g eps=%.17g: "
                         "%.17g vs 1-D %.17g (across %.3g)",
                         pairs[p][0], s, q, mun, eps, along, f1, across);
        }
    }
    ck_assert(worst < 16 * ULP);
}
END_TEST

/* ---- isotropy, bound, sliding ------------------------------------------------------------ */

/* Rotating v and f_eq by any angle rotates f: |f(Rv, Rg) - R f(v, g)| within a few ulps of
 * mun + |g| (the kernels' own rounding), for every law, in and out of the band. */
START_TEST(rotation_invariance)
{
    for (int k = 0; k < 20000; k++) {
        double mun = uniform(0.1, 4.7), eps = uniform(1e-4, 1.5);
        double sp = uniform(0.0, 1.4) * eps, a = uniform(-4, 4), q = uniform(0, 3) * mun;
        double b = uniform(-4, 4), th = uniform(-7, 7);
        double v[2] = {sp * cos(a), sp * sin(a)}, g[2] = {q * cos(b), q * sin(b)};
        double rv[2], rg[2], f[2], rf[2], frot[2];
        rotate(th, v, rv);
        rotate(th, g, rg);
        for (size_t l = 0; l < N_ALL; l++) {
            eval(all_laws[l], v, g, mun, eps, f);
            eval(all_laws[l], rv, rg, mun, eps, frot);
            rotate(th, f, rf);
            double err = hypot(frot[0] - rf[0], frot[1] - rf[1]);
            QUIET_ASSERT(err <= 32 * ULP * (mun + q), "law %d: rotation by %.17g moves f by %.3g",
                         all_laws[l], th, err);
        }
    }
}
END_TEST

/* |f| <= mun (to the rounding of a hypot and a product) for every law and input. */
START_TEST(force_within_the_disk)
{
    for (int k = 0; k < 20000; k++) {
        double mun = uniform(0.0, 5.1), eps = uniform(1e-5, 2.0);
        double v[2] = {uniform(-1.3, 1.3) * eps, uniform(-1.3, 1.3) * eps};
        double g[2] = {uniform(-4, 4) * (mun + 0.1), uniform(-4, 4) * (mun + 0.1)};
        for (size_t l = 0; l < N_ALL; l++) {
            double f[2];
            eval(all_laws[l], v, g, mun, eps, f);
            QUIET_CHECK(hypot(f[0], f[1]) <= mun * (1 + 4 * ULP));
        }
    }
}
END_TEST

/* |v| >= eps: the default and the lens law are the sliding law (1), -mun v/|v|, bit for bit
 * (the same kernel as FRICREG_DISK_COULOMB); at v = (eps, 0) exactly (-mun, -0). The nested
 * form is not: at v = (eps, 0), f_eq = (0, mun) it is the projection of (0, mun) - (2 mun, 0)
 * onto the disk, mun (-2, 1)/sqrt(5), 26.6 degrees off the sliding direction. */
START_TEST(sliding_outside_the_band)
{
    for (int k = 0; k < 5000; k++) {
        double mun = uniform(0.1, 4.7), eps = uniform(1e-4, 1.5), a = uniform(-4, 4);
        double sp = eps * (k % 2 ? uniform(1.0, 1.0 + 1e-9) : uniform(1.0, 30.0));
        double v[2] = {sp * cos(a), sp * sin(a)}, g[2] = {uniform(-9, 9), uniform(-9, 9)};
        double slide[2], f[2];
        if (hypot(v[0], v[1]) < eps)
            continue;
        eval(FRICREG_DISK_COULOMB, v, g, mun, eps, slide);
        eval(FRICREG_DISK_QUINN, v, g, mun, eps, f);
        ck_assert(same_bits(f, slide));
        eval(FRICREG_DISK_QUINN_LENS, v, g, mun, eps, f);
        ck_assert(same_bits(f, slide));
    }
    const double mun = 2.385, eps = 0.0731, v[2] = {eps, 0.0}, g[2] = {0.0, mun};
    double f[2];
    eval(FRICREG_DISK_QUINN, v, g, mun, eps, f);
    ck_assert(f[0] == -mun && f[1] == 0.0);
    eval(FRICREG_DISK_QUINN_NESTED, v, g, mun, eps, f);
    ck_assert_double_eq_tol(f[0], -2.0 * mun / sqrt(5.0), 1e-14);
    ck_assert_double_eq_tol(f[1], mun / sqrt(5.0), 1e-14);
}
END_TEST

/* ---- hand-worked points inside the band --------------------------------------------------- */

/* mun = 2, eps = 0.5, v = (0.125, 0): c = (0.5, 0), w = c mun = (1, 0), a = 0.5.
 *  - f_eq = (1.5, 0.25): f_eq - w = (0.5, 0.25), inside every set: f = (0.5, 0.25).
 *  - f_eq = (0, 3): q = (-1, 3).
 *    Inscribed disk, centre (-0.5, 0), radius 1.5: q - centre = (-0.5, 3), |.| = sqrt(9.25);
 *      f = (-0.5, 0) + 1.5 (-0.5, 3)/sqrt(9.25).
 *    Lens of disk(0, 2) and disk(-1, 2): lens frame x = q.u + 0.5 = -0.5, y = 3; the far disk
 *      from |x| is centred at (-0.5 - 0.5, 0) in that frame... in the origin frame: q lies left
 *      of the lens axis x = -0.5, so the binding disk is disk(0, 2): P = 2 q/|q| = 2 (-1, 3)/
 *      sqrt(10), whose distance to (-1, 0) is |(-1 + 2/sqrt 10 * -1 ... )| < 2: on the arc.
 *    Nested: P(f_eq) = 2 (0, 1) = (0, 2); minus w: (-1, 2), |.| = sqrt 5 > 2: 2 (-1, 2)/sqrt 5. */
START_TEST(hand_worked_band_points)
{
    const double mun = 2.0, eps = 0.5, v[2] = {0.125, 0.0};
    double f[2];
    const double g1[2] = {1.5, 0.25};
    for (size_t l = 0; l < N_REG; l++) {
        eval(regularized[l], v, g1, mun, eps, f);
        ck_assert_double_eq_tol(f[0], 0.5, 1e-15);
        ck_assert_double_eq_tol(f[1], 0.25, 1e-15);
    }
    const double g2[2] = {0.0, 3.0};
    eval(FRICREG_DISK_QUINN, v, g2, mun, eps, f);
    ck_assert_double_eq_tol(f[0], -0.5 - 0.75 / sqrt(9.25), 1e-15);
    ck_assert_double_eq_tol(f[1], 4.5 / sqrt(9.25), 1e-15);
    eval(FRICREG_DISK_QUINN_LENS, v, g2, mun, eps, f);
    ck_assert_double_eq_tol(f[0], -2.0 / sqrt(10.0), 1e-15);
    ck_assert_double_eq_tol(f[1], 6.0 / sqrt(10.0), 1e-15);
    ck_assert(hypot(f[0] + 1.0, f[1]) <= 2.0); /* in the other disk: on the arc, not a corner */
    eval(FRICREG_DISK_QUINN_NESTED, v, g2, mun, eps, f);
    ck_assert_double_eq_tol(f[0], -2.0 / sqrt(5.0), 1e-15);
    ck_assert_double_eq_tol(f[1], 4.0 / sqrt(5.0), 1e-15);
    /* A corner of the lens: f_eq = (-0.25, 40): q = (-1.25, 40), left of the axis, nearly
     * straight up; its projection onto disk(0, 2) is 2 q/|q|, which is outside disk(-1, 2)?
     * |2q/|q| + (1, 0)|^2 = 4 + 1 + 4 (-1.25)/|q| > 4: yes, so the corner (-0.5, sqrt(3.75)). */
    const double g3[2] = {-0.25, 40.0};
    eval(FRICREG_DISK_QUINN_LENS, v, g3, mun, eps, f);
    ck_assert_double_eq_tol(f[0], -0.5, 1e-15);
    ck_assert_double_eq_tol(f[1], sqrt(3.75), 1e-15);
}
END_TEST

/* ---- continuity --------------------------------------------------------------------------- */

/* Local Lipschitz bounds of docs/laws2d.md: |df| <= |dg| + L_v |dv| with L_v = 5 mun/eps (the
 * inscribed disk: its centre -a u and radius mun - a move at mun/eps, the point g - 2 a u at
 * 2 mun/eps), 2 mun/eps (nested). The lens is Lipschitz except at its tip |v| -> eps, where its
 * corners move as sqrt(eps - |v|): its bound adds that Hoelder term,
 * sqrt(2 mun da), the change of the half-width h = sqrt(mun^2 - a^2) over a change da of
 * a = mun |v|/eps (with the rounding of |v|/eps, an ulp of mun). */
static double allowed_jump(int law, double mun, double eps, double dv, double dg, double scale)
{
    double lv = law == FRICREG_DISK_QUINN_NESTED ? 2 * mun / eps : 5 * mun / eps;
    double da = (mun / eps) * dv + 2 * ULP * mun; /* a = mun |v|/eps, rounded */
    double hoelder = law == FRICREG_DISK_QUINN_LENS ? sqrt(2 * mun * da) : 0.0;
    return dg + lv * dv + hoelder + 16 * ULP * scale;
}

/* A base point near an edge: the band edge |v| = eps, v -> 0, or anywhere in the band; f_eq
 * near the bound's circle |f_eq| = mun, near the moved circles of the band, or anywhere. */
static void edge_point(int k, double mun, double eps, double v[2], double g[2])
{
    double a = uniform(-4, 4), b = uniform(-4, 4), sp, q;
    switch (k % 4) {
    case 0: sp = eps * (1.0 + uniform(-1e-12, 1e-12)); break;
    case 1: sp = eps * uniform(0.0, 1e-12); break;
    default: sp = eps * uniform(0.0, 1.05); break;
    }
    switch ((k / 4) % 3) {
    case 0: q = mun * (1.0 + uniform(-1e-12, 1e-12)); break;
    case 1: q = mun * uniform(0.0, 1.0); break;
    default: q = mun * uniform(0.0, 4.0); break;
    }
    v[0] = sp * cos(a);
    v[1] = sp * sin(a);
    /* half the points put f_eq - w near the inscribed disk's and the lens's circles */
    double shift = k % 2 ? 2 * mun * sp / eps * 0.5 : 0.0;
    g[0] = q * cos(b) + shift * cos(a);
    g[1] = q * sin(b) + shift * sin(a);
}

/* Random pairs at distance ~1e-14 (relative to eps and mun) around points on every edge: the
 * largest jump |f(p) - f(p')| stays within the Lipschitz bound (plus a few ulps) and below
 * 1e-12 mun for the Lipschitz laws. Also pairs straddling |v| = eps exactly (one inside, one
 * outside the band). */
START_TEST(continuity_sweeps)
{
    for (size_t l = 0; l < N_REG; l++) {
        int law = regularized[l];
        double largest = 0.0;
        for (int k = 0; k < 60000; k++) {
            double mun = uniform(0.2, 3.9), eps = uniform(1e-3, 1.2), v[2], g[2], v2[2], g2[2];
            double f[2], f2[2];
            edge_point(k, mun, eps, v, g);
            double hv = 1e-14 * eps, hg = 1e-14 * mun, dv0 = uniform(-1, 1) * hv;
            double dv1 = uniform(-1, 1) * hv, dg0 = uniform(-1, 1) * hg, dg1 = uniform(-1, 1) * hg;
            if (k % 7 == 0) { /* straddle the band edge along v */
                double sp = hypot(v[0], v[1]), t = eps / sp;
                v[0] *= t * (1 - 2 * ULP);
                v[1] *= t * (1 - 2 * ULP);
                dv0 = v[0] * 4 * ULP;
                dv1 = v[1] * 4 * ULP;
            }
            v2[0] = v[0] + dv0;
            v2[1] = v[1] + dv1;
            g2[0] = g[0] + dg0;
            g2[1] = g[1] + dg1;
            eval(law, v, g, mun, eps, f);
            eval(law, v2, g2, mun, eps, f2);
            double jump = hypot(f2[0] - f[0], f2[1] - f[1]);
            double dv = hypot(v2[0] - v[0], v2[1] - v[1]), dg = hypot(g2[0] - g[0], g2[1] - g[1]);
            double scale = mun + hypot(g[0], g[1]);
            QUIET_ASSERT(jump <= allowed_jump(law, mun, eps, dv, dg, scale),
                         "law %d jumps by %.3g mun at v=(%.17g, %.17g) g=(%.17g, %.17g) "
                         "mun=%.17g eps=%.17g",
                         law, jump / mun, v[0], v[1], g[0], g[1], mun, eps);
            largest = fmax(largest, jump / mun);
        }
        if (law != FRICREG_DISK_QUINN_LENS)
            ck_assert_msg(largest <= 1e-12, "law %d: largest jump %.3g mun", law, largest);
    }
}
END_TEST

/* ---- batch ---------------------------------------------------------------------------------- */

/* The batch gives the scalar's bits contact by contact, interleaved, also in place (f = v and
 * f = f_eq). */
START_TEST(batch_equals_scalar)
{
    enum { M = 257 };
    double v[2 * M], g[2 * M], mun[M], f[2 * M], inplace[2 * M];
    for (size_t l = 0; l < N_ALL; l++) {
        double eps = uniform(0.01, 0.7);
        for (int i = 0; i < M; i++) {
            double sp = i % 9 == 0 ? 0.0 : uniform(0, 1.5) * eps, a = uniform(-4, 4);
            v[2 * i] = sp * cos(a);
            v[2 * i + 1] = sp * sin(a);
            g[2 * i] = uniform(-5, 5);
            g[2 * i + 1] = uniform(-5, 5);
            mun[i] = uniform(0, 3);
        }
        ck_assert_int_eq(fricreg_disk_eval_batch(all_laws[l], eps, M, v, g, mun, f), FRICREG_OK);
        for (int i = 0; i < M; i++) {
            double one[2];
            eval(all_laws[l], v + 2 * i, g + 2 * i, mun[i], eps, one);
            ck_assert(same_bits(one, f + 2 * i));
        }
        memcpy(inplace, v, sizeof v);
        ck_assert_int_eq(fricreg_disk_eval_batch(all_laws[l], eps, M, inplace, g, mun, inplace),
                         FRICREG_OK);
        ck_assert(memcmp(inplace, f, sizeof f) == 0);
        memcpy(inplace, g, sizeof g);
        ck_assert_int_eq(fricreg_disk_eval_batch(all_laws[l], eps, M, v, inplace, mun, inplace),
                         FRICREG_OK);
        ck_assert(memcmp(inplace, f, sizeof f) == 0);
    }
    /* (1) needs no f_eq */
    ck_assert_int_eq(fricreg_disk_eval_batch(FRICREG_DISK_COULOMB, 0.1, M, v, NULL, mun, f),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_disk_eval_batch(FRICREG_DISK_QUINN, 0.1, 0, NULL, NULL, NULL, NULL),
                     FRICREG_OK);
}
END_TEST

/* ---- bad input ------------------------------------------------------------------------------ */

static void expect_scalar(int status, int law, const double v[2], const double g[2], double mun,
                          double eps)
{
    double f[2] = {SENTINEL, SENTINEL};
    ck_assert_int_eq(fricreg_disk_eval(law, v, g, mun, eps, f), status);
    ck_assert(f[0] == SENTINEL && f[1] == SENTINEL);
}

/* Every refusal of fricreg_disk_eval with its documented code; f untouched. */
START_TEST(scalar_bad_input)
{
    const double v[2] = {0.0123, -0.0071}, g[2] = {1.137, -0.42}, L = FRICREG_DISK_QUINN;
    double f[2];
    ck_assert_int_eq(fricreg_disk_eval(L, NULL, g, 1.0, 0.1, f), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_disk_eval(L, v, g, 1.0, 0.1, NULL), FRICREG_ENULL);
    expect_scalar(FRICREG_ENULL, L, v, NULL, 1.0, 0.1);
    expect_scalar(FRICREG_ENULL, FRICREG_DISK_FORCE_BALANCE, v, NULL, 1.0, 0.1);
    expect_scalar(FRICREG_EINVAL, 0, v, g, 1.0, 0.1);
    expect_scalar(FRICREG_EINVAL, FRICREG_DISK_QUINN_NESTED + 1, v, g, 1.0, 0.1);
    expect_scalar(FRICREG_EINVAL, L, v, g, -1e-300, 0.1);
    expect_scalar(FRICREG_EINVAL, L, v, g, 1.0, DBL_MIN / 2);
    expect_scalar(FRICREG_EINVAL, L, v, g, 1.0, 0.0);
    expect_scalar(FRICREG_EINVAL, L, v, g, 1.0, -0.1);
    expect_scalar(FRICREG_ENONFINITE, L, v, g, 1.0, NAN);
    expect_scalar(FRICREG_ENONFINITE, L, v, g, 1.0, INFINITY);
    expect_scalar(FRICREG_ENONFINITE, L, v, g, NAN, 0.1);
    const double big = 1.0000001e250;
    for (int j = 0; j < 2; j++) {
        double bv[2] = {v[0], v[1]}, bg[2] = {g[0], g[1]};
        bv[j] = NAN;
        expect_scalar(FRICREG_ENONFINITE, L, bv, g, 1.0, 0.1);
        bv[j] = -INFINITY;
        expect_scalar(FRICREG_ENONFINITE, L, bv, g, 1.0, 0.1);
        bv[j] = big;
        expect_scalar(FRICREG_EINVAL, L, bv, g, 1.0, 0.1);
        bg[j] = NAN;
        expect_scalar(FRICREG_ENONFINITE, L, v, bg, 1.0, 0.1);
        bg[j] = -big;
        expect_scalar(FRICREG_EINVAL, L, v, bg, 1.0, 0.1);
    }
    expect_scalar(FRICREG_EINVAL, L, v, g, big, 0.1);
    /* (1) does not read f_eq: NULL is fine; 1e250 is fine */
    ck_assert_int_eq(fricreg_disk_eval(FRICREG_DISK_COULOMB, v, NULL, 1.0, 0.1, f), FRICREG_OK);
    const double edge[2] = {1e250, -1e250};
    ck_assert_int_eq(fricreg_disk_eval(L, edge, edge, 1e250, 0.1, f), FRICREG_OK);
    ck_assert(isfinite(f[0]) && isfinite(f[1]));
}
END_TEST

/* Every refusal of the batch: nothing written, non-finite before out-of-range wherever. */
START_TEST(batch_bad_input)
{
    enum { M = 5 };
    double v[2 * M], g[2 * M], mun[M], f[2 * M];
    for (int i = 0; i < M; i++) {
        v[2 * i] = 0.01 * (i - 2);
        v[2 * i + 1] = 0.003 * i;
        g[2 * i] = 0.4 * i;
        g[2 * i + 1] = -0.2;
        mun[i] = 1.0 + i;
    }
    const int L = FRICREG_DISK_QUINN;
#define EXPECT_BATCH(status, law, eps, vv, gg, mm)                                     \
    do {                                                                               \
        for (int i = 0; i < 2 * M; i++)                                                \
            f[i] = SENTINEL;                                                           \
        ck_assert_int_eq(fricreg_disk_eval_batch(law, eps, M, vv, gg, mm, f), status); \
        for (int i = 0; i < 2 * M; i++)                                                \
            ck_assert(f[i] == SENTINEL);                                               \
    } while (0)
    EXPECT_BATCH(FRICREG_ENULL, L, 0.1, NULL, g, mun);
    EXPECT_BATCH(FRICREG_ENULL, L, 0.1, v, NULL, mun);
    EXPECT_BATCH(FRICREG_ENULL, L, 0.1, v, g, NULL);
    ck_assert_int_eq(fricreg_disk_eval_batch(L, 0.1, M, v, g, mun, NULL), FRICREG_ENULL);
    EXPECT_BATCH(FRICREG_EINVAL, 99, 0.1, v, g, mun);
    EXPECT_BATCH(FRICREG_EINVAL, L, DBL_MIN / 4, v, g, mun);
    EXPECT_BATCH(FRICREG_ENONFINITE, L, NAN, v, g, mun);
    mun[3] = -0.5;
    EXPECT_BATCH(FRICREG_EINVAL, L, 0.1, v, g, mun);
    g[9] = INFINITY; /* later than the negative bound, and still decides */
    EXPECT_BATCH(FRICREG_ENONFINITE, L, 0.1, v, g, mun);
    /* given to (1), f_eq is validated all the same */
    EXPECT_BATCH(FRICREG_ENONFINITE, FRICREG_DISK_COULOMB, 0.1, v, g, mun);
    mun[3] = 2.0;
    g[9] = -0.2;
    v[4] = 2e250;
    EXPECT_BATCH(FRICREG_EINVAL, L, 0.1, v, g, mun);
#undef EXPECT_BATCH
}
END_TEST

/* ---- names ---------------------------------------------------------------------------------- */

/* A bound far below |f_eq| (mun/|f_eq| underflows: 1e-100 beside 1e250): the force is mun in
 * f_eq's direction (the 2-D (2); law (4) at rest and in the band), not 0 (fuzz finding of the
 * 2-D context, whose isotropic blocks use the same projection). */
START_TEST(tiny_bound_beside_huge_feq)
{
    const double v0[2] = {0.0, 0.0}, band[2] = {1e-103, 0.0}, feq[2] = {1e250, -1e250};
    const double mun = 1e-100, eps = 1e-3;
    const int laws[2] = {FRICREG_DISK_FORCE_BALANCE, FRICREG_DISK_QUINN};
    for (int k = 0; k < 2; k++)
        for (int at_rest = 0; at_rest < 2; at_rest++) {
            double f[2];
            ck_assert_int_eq(fricreg_disk_eval(laws[k], at_rest ? v0 : band, feq, mun, eps, f),
                             FRICREG_OK);
            if (!at_rest && laws[k] == FRICREG_DISK_FORCE_BALANCE)
                continue; /* sliding: -mun v/|v| */
            ck_assert_msg(fabs(f[0] - mun / sqrt(2.0)) <= 1e-3 * mun &&
                              fabs(f[1] + mun / sqrt(2.0)) <= 1e-3 * mun,
                          "law %d rest %d: f = (%g, %g)", laws[k], at_rest, f[0], f[1]);
        }
}
END_TEST

/* A subnormal velocity: the sliding force is mun in -v's direction, |f| = mun to rounding,
 * for every law that slides there (at v = (4.9e-324, 4.9e-324), |v| rounds on the subnormal
 * grid to 4.9e-324 and v/|v| was (1, 1): f = (-mun, -mun), |f| = sqrt 2 mun). */
START_TEST(subnormal_velocity_slides_at_the_bound)
{
    const double v[2] = {4.9e-324, 4.9e-324}, feq[2] = {0.0, 0.0}, mun = 2.385;
    const int laws[2] = {FRICREG_DISK_COULOMB, FRICREG_DISK_FORCE_BALANCE};
    for (int k = 0; k < 2; k++) {
        double f[2];
        ck_assert_int_eq(fricreg_disk_eval(laws[k], v, feq, mun, 1e-3, f), FRICREG_OK);
        ck_assert_double_eq_tol(f[0], -mun / sqrt(2.0), 1e-15 * mun);
        ck_assert_double_eq_tol(f[1], -mun / sqrt(2.0), 1e-15 * mun);
        ck_assert_double_le(hypot(f[0], f[1]), mun * (1.0 + 1e-15));
    }
}
END_TEST

START_TEST(names_round_trip)
{
    const char *want[] = {NULL, "coulomb", "force-balance", "quinn", "quinn-lens", "quinn-nested"};
    int law = 1;
    for (; fricreg_disk_law_name(law) != NULL; law++) {
        ck_assert_str_eq(fricreg_disk_law_name(law), want[law]);
        ck_assert_int_eq(fricreg_disk_law_from_name(want[law]), law);
    }
    ck_assert_int_eq(law, 6);
    ck_assert_ptr_null(fricreg_disk_law_name(0));
    ck_assert_ptr_null(fricreg_disk_law_name(-3));
    ck_assert_int_eq(fricreg_disk_law_from_name(NULL), 0);
    ck_assert_int_eq(fricreg_disk_law_from_name("Quinn"), 0);
    ck_assert_int_eq(fricreg_disk_law_from_name("karnopp"), 0);
}
END_TEST

static Suite *disk_suite(void)
{
    Suite *s = suite_create("disk");
    /* "sweeps": thousands of random points (native and ASan; too slow under valgrind);
     * "cases": hand-worked values, batches and every refusal (valgrind too). */
    TCase *sweeps = tcase_create("sweeps"), *cases = tcase_create("cases");
    tcase_add_test(sweeps, zero_velocity_is_force_balance);
    tcase_add_test(sweeps, line_is_the_1d_law);
    tcase_add_test(sweeps, rotation_invariance);
    tcase_add_test(sweeps, force_within_the_disk);
    tcase_add_test(sweeps, sliding_outside_the_band);
    tcase_add_test(sweeps, continuity_sweeps);
    tcase_add_test(cases, zero_bound_gives_zero_force);
    tcase_add_test(cases, hand_worked_band_points);
    tcase_add_test(cases, batch_equals_scalar);
    tcase_add_test(cases, scalar_bad_input);
    tcase_add_test(cases, batch_bad_input);
    tcase_add_test(cases, names_round_trip);
    tcase_add_test(cases, tiny_bound_beside_huge_feq);
    tcase_add_test(cases, subnormal_velocity_slides_at_the_bound);
    suite_add_tcase(s, sweeps);
    suite_add_tcase(s, cases);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(disk_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
