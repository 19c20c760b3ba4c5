/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_switching.c — Check suite for the switching functions of the 1-D context
 * (fricreg_ctx_switching, enum fricreg_switch).
 *
 * Where the expected values come from:
 *   - the law's own evaluation (fricreg_ctx_eval with W = diag(w), f_eq = -a_free/w): along
 *     straight paths through the (v, f_eq) plane, every sign change of a live component is
 *     bracketed to 1e-12 of the path and the force shown to jump or change slope there
 *     (one-sided differences); conversely, for the piecewise linear laws ((1)-(4), Karnopp), a
 *     nonzero second difference of the force on the path's grid lies in an interval where
 *     some live component changes sign;
 *   - closed forms of the roots: law (4) at f_eq = 0.3 mun has its zone's edges at
 *     v = -0.15 eps +- eps/2, its saturation at f_eq = +-mun; Karnopp's band at +-eps;
 *   - continuity: a step dv moves the velocity components by at most |dv| (Lipschitz 1),
 *     also across the band's edges of coupled contacts under the consistent law;
 *   - GSL's rk8pd (gsl_odeiv2) on a block dragged by a belt from rest relative to the ground:
 *     zdot = -V0 + (F + mun) t until the zone's lower edge v = xi - eps/2, found by Brent's
 *     method (gsl_root_fsolver_brent) on the switching function along the step's own
 *     re-integration, against t* = (V0 + xi - eps/2)/(F + mun). */
#include <check.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_roots.h>

#include "fricreg.h"
#include "fricreg_stribeck.h"
#include "random.h"
#include "quiet_check.h"

enum { PER = FRICREG_SWITCH_PER_CONTACT };
#define SENTINEL (-777.125)

static uint64_t rng_state;

static double uniform(double lo, double hi)
{
    return splitmix64_uniform(&rng_state, lo, hi);
}

/* One contact, W = w, the law and eps given; Stribeck friction when fs > 0. */
static fricreg_ctx *one_contact(int law, double eps, double mun, double w)
{
    fricreg_ctx *ctx;
    ck_assert_int_eq(fricreg_ctx_create(1, &ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, law, eps), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, 1, &mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_coupling_diagonal(ctx, 1, &w), FRICREG_OK);
    return ctx;
}

static double force(fricreg_ctx *ctx, double w, double v, double feq)
{
    double a = -feq * w, f;
    QUIET_OK(fricreg_ctx_eval(ctx, 1, &v, &a, &f, NULL));
    return f;
}

static void switching(fricreg_ctx *ctx, double w, double v, double feq, double g[PER])
{
    double a = -feq * w;
    QUIET_OK(fricreg_ctx_switching(ctx, 1, &v, &a, NULL, g, PER));
}

/* A path s -> (v, f_eq) = (v0 + s dv, f0 + s df), s in [0, 1]. */
struct path {
    double v0, dv, f0, df;
};

static double path_force(fricreg_ctx *ctx, double w, const struct path *p, double s)
{
    return force(ctx, w, p->v0 + s * p->dv, p->f0 + s * p->df);
}

static double path_g(fricreg_ctx *ctx, double w, const struct path *p, double s, int k)
{
    double g[PER];
    switching(ctx, w, p->v0 + s * p->dv, p->f0 + s * p->df, g);
    return g[k];
}

/* The one place the docstring names where a live component changes sign with no kink:
 * Karnopp's band edge v = -eps while f_eq >= mun (f = +mun on both sides), and v = +eps while
 * f_eq <= -mun, for the band's component and the saturation's. */
static int documented_spurious(int law, int k, double v, double feq, double mun, double eps)
{
    if (law != FRICREG_LAW_KARNOPP)
        return 0;
    int lo = (k == FRICREG_SWITCH_BAND_LO || k == FRICREG_SWITCH_SAT_HI) && feq >= mun;
    int hi = (k == FRICREG_SWITCH_BAND_HI || k == FRICREG_SWITCH_SAT_LO) && feq <= -mun;
    return (lo && fabs(v + eps) < 1e-9 * eps) || (hi && fabs(v - eps) < 1e-9 * eps);
}

static int sign_of(double x)
{
    return (x > 0) - (x < 0);
}

static int law_of_ctx; /* the law of the context check_path is given */
static double eps_of_ctx;

/* Component k changes sign in [s0, s1]: bisect to 1e-12, then the force jumps there, or its
 * one-sided slopes over 1e-5 differ (by more than 1e-3 of the law's scale mun, per unit s), or
 * (Stribeck's bound at rest, where the force is C^1) its one-sided curvatures differ. */
static void assert_kink_in(fricreg_ctx *ctx, double w, const struct path *p, double s0, double s1,
                           int k, double mun)
{
    double g0 = path_g(ctx, w, p, s0, k);
    if (g0 == 0.0) /* the kink is at s0 itself */
        s1 = s0;
    for (int it = 0; it < 200 && s1 - s0 > 1e-12; it++) {
        double sm = 0.5 * (s0 + s1), gm = path_g(ctx, w, p, sm, k);
        if (sign_of(gm) == sign_of(g0))
            s0 = sm;
        else
            s1 = sm;
    }
    if (documented_spurious(law_of_ctx, k, p->v0 + s0 * p->dv, p->f0 + s0 * p->df, mun, eps_of_ctx))
        return;
    double h = 1e-5, fl = path_force(ctx, w, p, s0), fr = path_force(ctx, w, p, s1);
    double fl1 = path_force(ctx, w, p, s0 - h), fr1 = path_force(ctx, w, p, s1 + h);
    double left = (fl - fl1) / h, right = (fr1 - fr) / h;
    double curv_l = (fl - 2 * fl1 + path_force(ctx, w, p, s0 - 2 * h)) / (h * h);
    double curv_r = (path_force(ctx, w, p, s1 + 2 * h) - 2 * fr1 + fr) / (h * h);
    int jump = fabs(fr - fl) > 1e-6 * mun, bend = fabs(right - left) > 1e-3 * mun;
    int curve = fabs(curv_r - curv_l) > 1e-2 * mun;
    ck_assert_msg(jump || bend || curve,
                  "component %d changes sign at s = %.15g on (v0 %g, dv %g, f0 %g, df %g), but "
                  "the force neither jumps (%g -> %g) nor bends (slopes %g, %g)",
                  k, s0, p->v0, p->dv, p->f0, p->df, fl, fr, left, right);
}

static int live(const double g[PER], int k)
{
    return g[k] != 1.0;
}

/* Both directions of "changes sign exactly at the kinks" on one path of n + 1 samples. */
static void check_path(fricreg_ctx *ctx, double w, const struct path *p, double mun, int linear)
{
    enum { N = 400 };
    double g[N + 1][PER], f[N + 1];
    for (int j = 0; j <= N; j++) {
        double s = (double)j / N;
        switching(ctx, w, p->v0 + s * p->dv, p->f0 + s * p->df, g[j]);
        f[j] = path_force(ctx, w, p, s);
    }
    int changes[N] = {0};
    for (int j = 0; j < N; j++)
        for (int k = 0; k < PER; k++)
            if (sign_of(g[j][k]) != sign_of(g[j + 1][k])) {
                changes[j] = 1;
                assert_kink_in(ctx, w, p, (double)j / N, (double)(j + 1) / N, k, mun);
            }
    for (int j = 1; linear && j < N; j++) {
        double second = f[j + 1] - 2 * f[j] + f[j - 1];
        if (fabs(second) > 1e-9 * mun)
            ck_assert_msg(changes[j - 1] || changes[j],
                          "the force bends near s = %g (second difference %g) with no "
                          "switching function changing sign",
                          (double)j / N, second);
    }
}

static void check_law_paths(int law, int linear)
{
    const double eps = 0.0123, mun = 0.847, w = 1.7;
    fricreg_ctx *ctx = one_contact(law, eps, mun, w);
    law_of_ctx = law, eps_of_ctx = eps;
    rng_state = 0x5717c41 + (uint64_t)law;
    for (int trial = 0; trial < 40; trial++) {
        struct path p = {uniform(-2.2, 2.2) * eps, 0, uniform(-2.5, 2.5) * mun, 0};
        double v1 = uniform(-2.2, 2.2) * eps, f1 = uniform(-2.5, 2.5) * mun;
        if (trial % 4 == 0) /* pure velocity sweeps, at a fixed f_eq */
            v1 = -p.v0, f1 = p.f0;
        p.dv = v1 - p.v0, p.df = f1 - p.f0;
        check_path(ctx, w, &p, mun, linear);
    }
    fricreg_ctx_free(ctx);
}

START_TEST(test_kinks_of_each_law)
{
    static const int laws[] = {FRICREG_LAW_COULOMB, FRICREG_LAW_FORCE_BALANCE,
                               FRICREG_LAW_KARNOPP, FRICREG_LAW_VELOCITY_LIMITED,
                               FRICREG_LAW_TANH,    FRICREG_LAW_QUINN};
    check_law_paths(laws[_i], laws[_i] != FRICREG_LAW_TANH); /* tanh: smooth, not linear */
}
END_TEST

/* Which components are inert (+1) for each law, at a state near stick. */
START_TEST(test_inert_components)
{
    const double eps = 0.0123, mun = 0.847, w = 1.7;
    /* live masks by component 0..6 */
    static const struct {
        int law;
        const char *live;
    } table[] = {
        {FRICREG_LAW_COULOMB, "0010000"}, {FRICREG_LAW_FORCE_BALANCE, "0010000"},
        {FRICREG_LAW_KARNOPP, "1100011"}, {FRICREG_LAW_VELOCITY_LIMITED, "1100000"},
        {FRICREG_LAW_TANH, "0000000"},    {FRICREG_LAW_QUINN, "0001111"},
    };
    for (size_t t = 0; t < sizeof table / sizeof table[0]; t++) {
        fricreg_ctx *ctx = one_contact(table[t].law, eps, mun, w);
        for (double v = -2.1 * eps; v < 2.1 * eps; v += 0.37 * eps) {
            double g[PER];
            switching(ctx, w, v, 0.4 * mun, g);
            for (int k = 0; k < PER; k++)
                ck_assert_msg(live(g, k) || table[t].live[k] == '0',
                              "law %d component %d: inert, documented live", table[t].law, k);
            for (int k = 0; k < PER; k++)
                if (table[t].live[k] == '0')
                    ck_assert_double_eq(g[k], 1.0);
        }
        /* a zero bound: no kink, everything inert */
        double zero = 0.0, g[PER];
        ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, 1, &zero), FRICREG_OK);
        switching(ctx, w, 0.3 * eps, 0.2, g);
        for (int k = 0; k < PER; k++)
            ck_assert_double_eq(g[k], 1.0);
        fricreg_ctx_free(ctx);
    }
}
END_TEST

/* The roots in closed form. Law (4), f_eq = 0.3 mun: xi = 0.15 eps, the zone's edges at
 * 0.15 eps +- eps/2 (eps a power of two: exact); Karnopp: the band at +-eps, v exactly. */
START_TEST(test_roots_closed_form)
{
    const double eps = 1.0 / 64, mun = 0.5, w = 1.0;
    fricreg_ctx *ctx = one_contact(FRICREG_LAW_QUINN, eps, mun, w);
    double g[PER], xi = 0.5 * eps * 0.3;
    switching(ctx, w, xi + 0.5 * eps, 0.3 * mun, g);
    ck_assert_double_eq_tol(g[FRICREG_SWITCH_ZONE_HI], 0.0, 1e-18);
    ck_assert_double_gt(g[FRICREG_SWITCH_ZONE_LO], 0.0);
    switching(ctx, w, xi - 0.5 * eps, 0.3 * mun, g);
    ck_assert_double_eq_tol(g[FRICREG_SWITCH_ZONE_LO], 0.0, 1e-18);
    /* saturation: f_eq = mun at v = eps/2 (mid-zone): g5 = f_eq - mun = 0 exactly */
    switching(ctx, w, 0.5 * eps, mun, g);
    ck_assert_double_eq(g[FRICREG_SWITCH_SAT_HI], 0.0);
    switching(ctx, w, 0.5 * eps, mun * (1 + 1e-9), g);
    ck_assert_double_gt(g[FRICREG_SWITCH_SAT_HI], 0.0);
    ck_assert_double_eq_tol(g[FRICREG_SWITCH_SAT_HI], mun * 1e-9, 1e-15);
    switching(ctx, w, -0.5 * eps, -mun, g);
    ck_assert_double_eq(g[FRICREG_SWITCH_SAT_LO], 0.0);
    switching(ctx, w, -0.5 * eps, -mun * (1 + 1e-9), g);
    ck_assert_double_lt(g[FRICREG_SWITCH_SAT_LO], 0.0);
    /* sliding with f_eq beyond the bound: the saturation is no kink, g5 stays negative */
    switching(ctx, w, 1.5 * eps, 2.0 * mun, g);
    ck_assert_double_lt(g[FRICREG_SWITCH_SAT_HI], 0.0);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_KARNOPP, eps), FRICREG_OK);
    switching(ctx, w, eps, 0.1, g);
    ck_assert_double_eq(g[FRICREG_SWITCH_BAND_HI], 0.0);
    switching(ctx, w, -eps, 0.1, g);
    ck_assert_double_eq(g[FRICREG_SWITCH_BAND_LO], 0.0);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_COULOMB, eps), FRICREG_OK);
    switching(ctx, w, -0.0, 0.1, g);
    ck_assert_double_eq(g[FRICREG_SWITCH_REST], 0.0);
    ck_assert_uint_eq(fricreg_ctx_switching_count(ctx), PER);
    ck_assert_uint_eq(fricreg_ctx_switching_count(NULL), 0);
    fricreg_ctx_free(ctx);
}
END_TEST

/* Stribeck friction: band edges and rest are live, and every sign change is a kink. */
START_TEST(test_stribeck_kinks)
{
    const double eps = 0.0123, w = 1.7, fs = 0.9, fk = 0.55, vs = 0.02, delta = 1.3;
    fricreg_ctx *ctx = one_contact(FRICREG_LAW_QUINN, eps, 1.0, w);
    ck_assert_int_eq(fricreg_ctx_set_stribeck(ctx, 1, &fs, &fk, &vs, &delta), FRICREG_OK);
    law_of_ctx = FRICREG_LAW_QUINN, eps_of_ctx = eps;
    double g[PER];
    switching(ctx, w, eps, 0.1, g);
    ck_assert_double_eq(g[FRICREG_SWITCH_BAND_HI], 0.0);
    switching(ctx, w, 0.0, 0.1, g);
    ck_assert_double_eq(g[FRICREG_SWITCH_REST], 0.0);
    rng_state = 0x57b;
    for (int trial = 0; trial < 30; trial++) {
        struct path p = {uniform(-2.2, 2.2) * eps, 0, uniform(-2.5, 2.5) * fs, 0};
        p.dv = uniform(-2.2, 2.2) * eps - p.v0, p.df = uniform(-2.5, 2.5) * fs - p.f0;
        check_path(ctx, w, &p, fk, 0);
    }
    fricreg_ctx_free(ctx);
}
END_TEST

/* Lipschitz 1 in zdot for the velocity components, at a fixed f_eq (a constant bound). */
START_TEST(test_velocity_lipschitz)
{
    static const int laws[] = {FRICREG_LAW_COULOMB, FRICREG_LAW_KARNOPP,
                               FRICREG_LAW_VELOCITY_LIMITED, FRICREG_LAW_QUINN};
    const double eps = 0.0123, mun = 0.847, w = 1.7;
    rng_state = 0x11b;
    for (size_t l = 0; l < sizeof laws / sizeof laws[0]; l++) {
        fricreg_ctx *ctx = one_contact(laws[l], eps, mun, w);
        for (int trial = 0; trial < 500; trial++) {
            double v = uniform(-2, 2) * eps, dv = uniform(-0.1, 0.1) * eps;
            double feq = uniform(-2, 2) * mun, df = uniform(-0.01, 0.01) * mun, g0[PER], g1[PER];
            switching(ctx, w, v, feq, g0);
            switching(ctx, w, v + dv, feq, g1);
            for (int k = 0; k <= FRICREG_SWITCH_ZONE_LO; k++)
                ck_assert_double_le(fabs(g1[k] - g0[k]), fabs(dv) * (1 + 1e-12) + 1e-18);
            /* f_eq moves the zone by (eps/2)/mun per force, the saturation by 1 */
            switching(ctx, w, v, feq + df, g1);
            for (int k = FRICREG_SWITCH_ZONE_HI; k <= FRICREG_SWITCH_ZONE_LO; k++)
                ck_assert_double_le(fabs(g1[k] - g0[k]), fabs(df) * 0.5 * eps / mun * (1 + 1e-9));
            for (int k = FRICREG_SWITCH_SAT_HI; k <= FRICREG_SWITCH_SAT_LO; k++)
                ck_assert_double_le(fabs(g1[k] - g0[k]), fabs(df) * (1 + 1e-9) + 1e-15);
        }
        fricreg_ctx_free(ctx);
    }
}
END_TEST

/* Coupled contacts (the paper's two blocks, W = [[1, -1], [-1, 2]]) under the consistent
 * law: g uses eval's f_eq on S, and it is continuous as contact 2 crosses its band's edge. */
START_TEST(test_coupled_consistent)
{
    const double W[4] = {1.0, -1.0, -1.0, 2.0}, mun[2] = {0.5, 0.25}, eps = 0.01;
    fricreg_ctx *ctx;
    ck_assert_int_eq(fricreg_ctx_create(2, &ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, eps), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, W), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, 2, mun), FRICREG_OK);
    const double a[2] = {0.213, -0.347};
    double prev[2 * PER];
    for (int j = 0; j <= 400; j++) {
        double zdot[2] = {0.0013, 0.008 + 0.004 * j / 400.0}, f[2], feq[2], g[2 * PER];
        ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, zdot, a, f, feq), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_switching(ctx, 2, zdot, a, f, g, 2 * PER), FRICREG_OK);
        double xi = 0.5 * eps * fmax(-1.0, fmin(1.0, feq[0] / mun[0])); /* contact 1 is in S */
        ck_assert_double_eq_tol(g[FRICREG_SWITCH_ZONE_HI], zdot[0] - xi - 0.5 * eps, 1e-15);
        for (int k = 0; k < PER; k++) /* (4) with the consistent law: no band component */
            if (k <= FRICREG_SWITCH_REST)
                ck_assert_double_eq(g[PER + k], 1.0);
        for (int k = 0; j > 0 && k < 2 * PER; k++) /* steps of 1e-5 in zdot_2: no jump */
            ck_assert_double_le(fabs(g[k] - prev[k]), 1e-3);
        memcpy(prev, g, sizeof prev);
    }
    /* the paper's partition: its forces jump at the band's edges, which are live */
    ck_assert_int_eq(fricreg_ctx_set_partition(ctx, FRICREG_PARTITION_PAPER), FRICREG_OK);
    double zdot[2] = {0.0013, eps}, f[2], g[2 * PER];
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, zdot, a, f, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_switching(ctx, 2, zdot, a, f, g, 2 * PER), FRICREG_OK);
    ck_assert_double_eq(g[PER + FRICREG_SWITCH_BAND_HI], 0.0);
    fricreg_ctx_free(ctx);
}
END_TEST

static void assert_untouched(const double g[], size_t n)
{
    for (size_t i = 0; i < n; i++)
        ck_assert_double_eq(g[i], SENTINEL);
}

START_TEST(test_bad_input)
{
    const double W[4] = {1.0, -1.0, -1.0, 2.0}, zdot[2] = {0.001, -0.002};
    const double a[2] = {0.2, -0.3}, f[2] = {-0.1, 0.05};
    double g[2 * PER + 1], nan_in[2] = {NAN, 0.0}, inf_in[2] = {0.0, INFINITY};
    fricreg_ctx *ctx;
    ck_assert_int_eq(fricreg_ctx_create(2, &ctx), FRICREG_OK);
    for (size_t i = 0; i < 2 * PER + 1; i++)
        g[i] = SENTINEL;
    ck_assert_int_eq(fricreg_ctx_switching(NULL, 2, zdot, a, f, g, 2 * PER), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_ctx_switching(ctx, 3, zdot, a, f, g, 3 * PER), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_ctx_errcode(ctx), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_ctx_switching(ctx, 2, NULL, a, f, g, 2 * PER), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_ctx_switching(ctx, 2, zdot, NULL, f, g, 2 * PER), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_ctx_switching(ctx, 2, zdot, a, f, NULL, 2 * PER), FRICREG_ENULL);
    ck_assert_ptr_nonnull(strstr(fricreg_ctx_errmsg(ctx), "g is NULL"));
    ck_assert_int_eq(fricreg_ctx_switching(ctx, 2, zdot, a, f, g, 2 * PER - 1), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_ctx_switching(ctx, 2, zdot, a, f, g, 0), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_ctx_switching(ctx, 2, nan_in, a, f, g, 2 * PER), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_ctx_switching(ctx, 2, zdot, inf_in, f, g, 2 * PER),
                     FRICREG_ENONFINITE);
    ck_assert_ptr_nonnull(strstr(fricreg_ctx_errmsg(ctx), "a_free[1]"));
    assert_untouched(g, 2 * PER + 1);
    /* a diagonal W does not read f: NULL is fine, a NaN in it ignored */
    ck_assert_int_eq(fricreg_ctx_switching(ctx, 2, zdot, a, NULL, g, 2 * PER), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_switching(ctx, 2, zdot, a, nan_in, g, 2 * PER + 1), FRICREG_OK);
    ck_assert_double_eq(g[2 * PER], SENTINEL); /* only the count is written */
    /* a coupled W reads it */
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, W), FRICREG_OK);
    for (size_t i = 0; i < 2 * PER + 1; i++)
        g[i] = SENTINEL;
    ck_assert_int_eq(fricreg_ctx_switching(ctx, 2, zdot, a, NULL, g, 2 * PER), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_ctx_switching(ctx, 2, zdot, a, inf_in, g, 2 * PER),
                     FRICREG_ENONFINITE);
    ck_assert_ptr_nonnull(strstr(fricreg_ctx_errmsg(ctx), "f[1]"));
    assert_untouched(g, 2 * PER + 1);
    /* (1) reads no f_eq, so no f even when coupled */
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_COULOMB, 0.01), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_switching(ctx, 2, zdot, a, NULL, g, 2 * PER), FRICREG_OK);
    /* huge inputs: finite outputs all the same */
    const double huge_a[2] = {1e308, -1e308}, huge_f[2] = {1e308, -1e308};
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 0.01), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_switching(ctx, 2, zdot, huge_a, huge_f, g, 2 * PER), FRICREG_OK);
    for (size_t i = 0; i < 2 * PER; i++)
        ck_assert(isfinite(g[i]));
    fricreg_ctx_free(ctx);
}
END_TEST

/* ---- A root finder on GSL's rk8pd -------------------------------------------------------- */

/* A block of unit mass pulled by a constant force F on a belt of speed V0: x'' = F + f,
 * zdot = x' - V0, a_free = F, W = 1; state y = (x, x'). */
struct belt {
    fricreg_ctx *ctx;
    double F, V0;
};

static int belt_rhs(double t, const double y[], double dydt[], void *params)
{
    (void)t;
    struct belt *b = params;
    double zdot = y[1] - b->V0, f;
    if (fricreg_ctx_eval(b->ctx, 1, &zdot, &b->F, &f, NULL) != FRICREG_OK)
        return GSL_EBADFUNC;
    dydt[0] = y[1];
    dydt[1] = b->F + f;
    return GSL_SUCCESS;
}

/* Component k of the block's switching functions at state y. */
static double belt_g(const struct belt *b, const double y[], int k)
{
    double zdot = y[1] - b->V0, g[PER];
    ck_assert_int_eq(fricreg_ctx_switching(b->ctx, 1, &zdot, &b->F, NULL, g, PER), FRICREG_OK);
    return g[k];
}

/* The state at t0 + theta, from the state y0 at t0 by one rk8pd step of size theta: the
 * stepper's own continuous extension within the accepted step. */
struct step_probe {
    gsl_odeiv2_step *step;
    gsl_odeiv2_system *sys;
    struct belt *b;
    double t0, y0[2];
    int k;
};

static double probe_g(double theta, void *params)
{
    struct step_probe *p = params;
    double y[2] = {p->y0[0], p->y0[1]}, err[2];
    gsl_odeiv2_step_reset(p->step);
    if (theta > 0)
        ck_assert_int_eq(gsl_odeiv2_step_apply(p->step, p->t0, theta, y, err, NULL, NULL, p->sys),
                         GSL_SUCCESS);
    return belt_g(p->b, y, p->k);
}

/* Integrates to t_end; returns the first time component k changes sign, by Brent's method on
 * the step that brackets it. */
static double first_crossing(struct belt *b, int k, double t_end)
{
    gsl_odeiv2_system sys = {belt_rhs, NULL, 2, b};
    gsl_odeiv2_step *step = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, 2);
    gsl_odeiv2_step *probe_step = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, 2);
    gsl_odeiv2_control *con = gsl_odeiv2_control_y_new(1e-12, 1e-12);
    gsl_odeiv2_evolve *ev = gsl_odeiv2_evolve_alloc(2);
    gsl_root_fsolver *brent = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    double t = 0.0, h = 1e-3, y[2] = {0.0, 0.0}, found = NAN;
    int start_positive = belt_g(b, y, k) > 0.0;
    while (t < t_end && isnan(found)) {
        double t0 = t, y0[2] = {y[0], y[1]};
        ck_assert_int_eq(gsl_odeiv2_evolve_apply(ev, con, step, &sys, &t, t_end, &h, y),
                         GSL_SUCCESS);
        if ((belt_g(b, y, k) > 0.0) == start_positive)
            continue;
        struct step_probe p = {probe_step, &sys, b, t0, {y0[0], y0[1]}, k};
        gsl_function fn = {probe_g, &p};
        ck_assert_int_eq(gsl_root_fsolver_set(brent, &fn, 0.0, t - t0), GSL_SUCCESS);
        int status = GSL_CONTINUE;
        for (int it = 0; it < 100 && status == GSL_CONTINUE; it++) {
            ck_assert_int_eq(gsl_root_fsolver_iterate(brent), GSL_SUCCESS);
            status = gsl_root_test_interval(gsl_root_fsolver_x_lower(brent),
                                            gsl_root_fsolver_x_upper(brent), 1e-15, 0.0);
        }
        ck_assert_int_eq(status, GSL_SUCCESS);
        found = t0 + gsl_root_fsolver_root(brent);
    }
    gsl_root_fsolver_free(brent);
    gsl_odeiv2_evolve_free(ev);
    gsl_odeiv2_control_free(con);
    gsl_odeiv2_step_free(probe_step);
    gsl_odeiv2_step_free(step);
    return found;
}

/* Dragged by the belt, the block slides with f = +mun and zdot = -V0 + (F + mun) t until it
 * reaches the zone's lower edge v = xi - eps/2, xi = (eps/2) sat(f_eq/mun), f_eq = -F:
 *   t* = (V0 + xi - eps/2)/(F + mun).
 * F = 0.3 mun: xi = -0.15 eps, t* = (V0 - 0.65 eps)/(1.3 mun). F = 1.5 mun, beyond the bound
 * (the block cannot stick: f_eq saturates), xi = -eps/2, t* = (V0 - eps)/(2.5 mun). */
START_TEST(test_rk8pd_brent_first_kink)
{
    const double eps = 0.0123, mun = 0.847, V0 = 0.4;
    gsl_set_error_handler_off();
    struct belt b = {one_contact(FRICREG_LAW_QUINN, eps, mun, 1.0), 0.3 * mun, V0};
    double t_star = first_crossing(&b, FRICREG_SWITCH_ZONE_LO, 2.0);
    ck_assert_double_eq_tol(t_star, (V0 - 0.65 * eps) / (1.3 * mun), 1e-12);
    b.F = 1.5 * mun;
    t_star = first_crossing(&b, FRICREG_SWITCH_ZONE_LO, 2.0);
    ck_assert_double_eq_tol(t_star, (V0 - eps) / (2.5 * mun), 1e-12);
    /* there the saturation's component turns too: the zone's edge bounds its region */
    double t_sat = first_crossing(&b, FRICREG_SWITCH_SAT_LO, 2.0);
    ck_assert_double_eq_tol(t_sat, (V0 - eps) / (2.5 * mun), 1e-12);
    fricreg_ctx_free(b.ctx);
}
END_TEST

static Suite *switching_suite(void)
{
    Suite *s = suite_create("switching");
    TCase *tc = tcase_create("core");
    tcase_add_loop_test(tc, test_kinks_of_each_law, 0, 6);
    tcase_add_test(tc, test_inert_components);
    tcase_add_test(tc, test_roots_closed_form);
    tcase_add_test(tc, test_stribeck_kinks);
    tcase_add_test(tc, test_velocity_lipschitz);
    tcase_add_test(tc, test_coupled_consistent);
    tcase_add_test(tc, test_bad_input);
    tcase_add_test(tc, test_rk8pd_brent_first_kink);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(switching_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
