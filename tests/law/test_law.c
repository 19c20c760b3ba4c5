/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_law.c — Check suite for the friction laws: fricreg_law_eval, fricreg_law_eval_batch,
 * fricreg_law_name, fricreg_law_from_name, fricreg_strerror and the version functions.
 *
 * Expected values come from the laws table of shared/spec/paper.md (equations (1)-(4), Karnopp,
 * tanh), evaluated by hand in exact rational arithmetic and written here to 17 digits; each test
 * says which formula gives its numbers. Unless a test says otherwise mun = 2.385, eps = 0.0731,
 * so 2 mun/eps = 65.2530779753762 and eps/2 = 0.03655. */
#include <check.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg.h"
#include "random.h"
#include "quiet_check.h"

#define MUN 2.385
#define EPS 0.0731
#define SENTINEL (-777.125) /* written into outputs before a call that must fail */
#define TOL 1e-13           /* absolute, for values of order mun computed in a few flops */

static const int all_laws[] = {FRICREG_LAW_COULOMB, FRICREG_LAW_FORCE_BALANCE,
                               FRICREG_LAW_KARNOPP, FRICREG_LAW_VELOCITY_LIMITED,
                               FRICREG_LAW_TANH,    FRICREG_LAW_QUINN};
#define N_LAWS (sizeof all_laws / sizeof all_laws[0])

/* Evaluates one law and asserts success. */
static double law(int which, double v, double f_eq, double mun, double eps)
{
    double f = SENTINEL;
    int status = fricreg_law_eval(which, v, f_eq, mun, eps, &f);
    QUIET_ASSERT(status == FRICREG_OK, "law %d at v=%g f_eq=%g mun=%g eps=%g: status %d", which, v,
                 f_eq, mun, eps, status);
    return f;
}

static int same_bits(double a, double b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

/* ---- (1) Coulomb ------------------------------------------------------------------------- */

/* (1): f = -mun sgn(v), sgn(0) = 0; f_eq and eps do not enter. */
START_TEST(coulomb_is_minus_mun_sign_v)
{
    ck_assert_double_eq(law(FRICREG_LAW_COULOMB, 0.0, 1.137, MUN, EPS), 0.0);
    ck_assert_double_eq(law(FRICREG_LAW_COULOMB, 0.412, 1.137, MUN, EPS), -MUN);
    ck_assert_double_eq(law(FRICREG_LAW_COULOMB, -0.0031, 1.137, MUN, EPS), MUN);
    ck_assert_double_eq(law(FRICREG_LAW_COULOMB, 1e-300, -9.3, MUN, EPS), -MUN);
    ck_assert_double_eq(law(FRICREG_LAW_COULOMB, -1e-300, 4.71, MUN, EPS), MUN);
    /* f_eq and eps are ignored: the same v gives the same force. */
    ck_assert_double_eq(law(FRICREG_LAW_COULOMB, 0.0213, -9.3, MUN, 17.3), -MUN);
    ck_assert_double_eq(law(FRICREG_LAW_COULOMB, 0.0, 4.71, MUN, 1e-9), 0.0);
}
END_TEST

/* ---- (2) force balance at rest ----------------------------------------------------------- */

/* (2): v == 0: f = mun sat(f_eq/mun) (f_eq itself below the bound, +-mun at and above it);
 * any v != 0, however small: (1). */
START_TEST(force_balance_branches)
{
    const int L = FRICREG_LAW_FORCE_BALANCE;
    ck_assert_double_eq_tol(law(L, 0.0, 1.137, MUN, EPS), 1.137, TOL);   /* |f_eq| < mun */
    ck_assert_double_eq_tol(law(L, 0.0, -1.913, MUN, EPS), -1.913, TOL); /* |f_eq| < mun */
    ck_assert_double_eq(law(L, 0.0, 0.0, MUN, EPS), 0.0);
    ck_assert_double_eq(law(L, 0.0, MUN, MUN, EPS), MUN); /* |f_eq| = mun: sat(1) = 1 */
    ck_assert_double_eq(law(L, 0.0, -MUN, MUN, EPS), -MUN);
    ck_assert_double_eq(law(L, 0.0, 4.71, MUN, EPS), MUN); /* |f_eq| > mun */
    ck_assert_double_eq(law(L, 0.0, -9.3, MUN, EPS), -MUN);
    ck_assert_double_eq(law(L, -0.0, 4.71, MUN, EPS), MUN); /* -0 is v == 0 */
    /* Off v = 0, (1) whatever f_eq is. */
    ck_assert_double_eq(law(L, 1e-300, 1.137, MUN, EPS), -MUN);
    ck_assert_double_eq(law(L, -1e-300, 1.137, MUN, EPS), MUN);
    ck_assert_double_eq(law(L, 0.0213, -9.3, MUN, EPS), -MUN);
    ck_assert_double_eq(law(L, -0.412, 4.71, MUN, EPS), MUN);
    /* eps is ignored. */
    ck_assert_double_eq_tol(law(L, 0.0, 1.137, MUN, 5.5e-9), 1.137, TOL);
}
END_TEST

/* ---- Karnopp ----------------------------------------------------------------------------- */

/* Karnopp: |v| < eps: f = mun sat(f_eq/mun); |v| >= eps: (1). The band is open: at |v| = eps
 * the force is already -mun sgn(v). */
START_TEST(karnopp_branches)
{
    const int L = FRICREG_LAW_KARNOPP;
    const double inside = nextafter(EPS, 0.0);
    ck_assert_double_eq_tol(law(L, 0.0, 1.137, MUN, EPS), 1.137, TOL);
    ck_assert_double_eq_tol(law(L, 0.0730, 1.137, MUN, EPS), 1.137, TOL);
    ck_assert_double_eq_tol(law(L, -0.0730, -1.913, MUN, EPS), -1.913, TOL);
    ck_assert_double_eq_tol(law(L, inside, -1.913, MUN, EPS), -1.913, TOL);
    ck_assert_double_eq_tol(law(L, -inside, 1.137, MUN, EPS), 1.137, TOL);
    ck_assert_double_eq(law(L, 0.0213, MUN, MUN, EPS), MUN);
    ck_assert_double_eq(law(L, 0.0213, -MUN, MUN, EPS), -MUN);
    ck_assert_double_eq(law(L, -0.0604, 4.71, MUN, EPS), MUN);
    ck_assert_double_eq(law(L, -0.0604, -9.3, MUN, EPS), -MUN);
    /* Zone edge |v| = eps and beyond: (1), exactly +-mun. */
    ck_assert_double_eq(law(L, EPS, 1.137, MUN, EPS), -MUN);
    ck_assert_double_eq(law(L, -EPS, -1.913, MUN, EPS), MUN);
    ck_assert_double_eq(law(L, 0.0732, 4.71, MUN, EPS), -MUN);
    ck_assert_double_eq(law(L, -0.0732, -9.3, MUN, EPS), MUN);
}
END_TEST

/* ---- (3) velocity-limited ---------------------------------------------------------------- */

/* (3): |v| < eps: f = -(mun/eps) v; else (1). mun/eps = 32.6265389876881. f_eq ignored.
 * -(mun/eps) 0.0213 = -0.6949452804377565; -(mun/eps)(-0.0604) = 1.9706429548563611. */
START_TEST(velocity_limited_branches)
{
    const int L = FRICREG_LAW_VELOCITY_LIMITED;
    const double inside = nextafter(EPS, 0.0);
    ck_assert_double_eq(law(L, 0.0, 4.71, MUN, EPS), 0.0); /* no force at rest: it creeps */
    ck_assert_double_eq_tol(law(L, 0.0213, 1.137, MUN, EPS), -0.6949452804377565, TOL);
    ck_assert_double_eq_tol(law(L, -0.0604, -9.3, MUN, EPS), 1.9706429548563611, TOL);
    /* Continuous at the edge: just inside -> -mun, at the edge exactly -mun. */
    ck_assert_double_eq_tol(law(L, inside, 0.0, MUN, EPS), -MUN, 1e-15);
    ck_assert_double_eq_tol(law(L, -inside, 0.0, MUN, EPS), MUN, 1e-15);
    ck_assert_double_eq(law(L, EPS, 0.0, MUN, EPS), -MUN);
    ck_assert_double_eq(law(L, -EPS, 0.0, MUN, EPS), MUN);
    ck_assert_double_eq(law(L, 0.0732, 0.0, MUN, EPS), -MUN);
    ck_assert_double_eq(law(L, -0.412, 0.0, MUN, EPS), MUN);
}
END_TEST

/* ---- tanh -------------------------------------------------------------------------------- */

/* f = -mun tanh(v/eps): -2.385 tanh(0.0213/0.0731) = -0.67592332038582725 and
 * -2.385 tanh(-0.0604/0.0731) = 1.6181404524161656 (40-digit evaluation); odd in v. */
START_TEST(tanh_values)
{
    const int L = FRICREG_LAW_TANH;
    ck_assert_double_eq(law(L, 0.0, 4.71, MUN, EPS), 0.0);
    ck_assert_double_eq_tol(law(L, 0.0213, 1.137, MUN, EPS), -0.67592332038582725, TOL);
    ck_assert_double_eq_tol(law(L, -0.0604, -9.3, MUN, EPS), 1.6181404524161656, TOL);
    ck_assert_double_eq(law(L, -0.0213, 0.0, MUN, EPS), -law(L, 0.0213, 0.0, MUN, EPS));
    /* Far out, tanh(3.1/0.0731) = 1 - 4e-37 rounds to 1. */
    ck_assert_double_eq_tol(law(L, 3.1, 0.0, MUN, EPS), -MUN, 1e-15);
    ck_assert_double_eq_tol(law(L, -3.1, 0.0, MUN, EPS), MUN, 1e-15);
}
END_TEST

/* ---- (4) Quinn --------------------------------------------------------------------------- */

/* (4) with f_eq = 1.137 < mun: xi = (eps/2)(1.137/2.385) = 0.0174244654088050; the zone is
 * |v - xi| < 0.03655, i.e. -0.0191255... < v < 0.0539744... Inside f = -65.2530779753762 (v-xi);
 * values in exact rationals: v=0.0213: -0.25289056087551298; v=-0.0150: 2.1157961696306429;
 * v=0.0539 (just inside): -2.3801409028727769; v=-0.0191 (just inside): 2.3833337893296855. */
START_TEST(quinn_feq_below_bound_positive)
{
    const int L = FRICREG_LAW_QUINN;
    const double feq = 1.137;
    ck_assert_double_eq_tol(law(L, 0.0, feq, MUN, EPS), 1.137, TOL); /* v = 0: = (2) */
    ck_assert_double_eq_tol(law(L, 0.0213, feq, MUN, EPS), -0.25289056087551298, TOL);
    ck_assert_double_eq_tol(law(L, -0.0150, feq, MUN, EPS), 2.1157961696306429, TOL);
    ck_assert_double_eq_tol(law(L, 0.0539, feq, MUN, EPS), -2.3801409028727769, TOL);
    ck_assert_double_eq_tol(law(L, -0.0191, feq, MUN, EPS), 2.3833337893296855, TOL);
    /* Just outside: v - xi = 0.0365755 and -0.0366245. */
    ck_assert_double_eq(law(L, 0.0540, feq, MUN, EPS), -MUN);
    ck_assert_double_eq(law(L, -0.0192, feq, MUN, EPS), MUN);
    /* |v| < eps but outside the shifted zone: Quinn slides where Karnopp would stick. */
    ck_assert_double_eq(law(L, 0.0600, feq, MUN, EPS), -MUN);
    ck_assert_double_eq(law(L, 0.412, feq, MUN, EPS), -MUN);
    ck_assert_double_eq(law(L, -0.3, feq, MUN, EPS), MUN);
}
END_TEST

/* (4) with f_eq = -1.913: xi = (eps/2)(-1.913/2.385) = -0.0293166247379455; zone
 * -0.0658666... < v < 0.0072333...; v=-0.0021: -1.7759685362517099; v=0.0072 (just inside):
 * -2.3828221614227085; v=-0.0658 (just inside): 2.3806525307797539. */
START_TEST(quinn_feq_below_bound_negative)
{
    const int L = FRICREG_LAW_QUINN;
    const double feq = -1.913;
    ck_assert_double_eq_tol(law(L, 0.0, feq, MUN, EPS), -1.913, TOL);
    ck_assert_double_eq_tol(law(L, -0.0021, feq, MUN, EPS), -1.7759685362517099, TOL);
    ck_assert_double_eq_tol(law(L, 0.0072, feq, MUN, EPS), -2.3828221614227085, TOL);
    ck_assert_double_eq_tol(law(L, -0.0658, feq, MUN, EPS), 2.3806525307797539, TOL);
    ck_assert_double_eq(law(L, 0.0073, feq, MUN, EPS), -MUN);
    ck_assert_double_eq(law(L, -0.0659, feq, MUN, EPS), MUN);
}
END_TEST

/* (4) with |f_eq| = mun: xi = +-eps/2 exactly, so the zone is (0, eps) (or (-eps, 0)) and both
 * edges are hit exactly in floating point: v - xi = +-eps/2, 2(v - xi)/eps = +-1, f = -+mun.
 * Inside: v=0.0137: -65.2530779753762 (0.0137 - 0.03655) = 1.491032831737346; v=0.0365:
 * 0.0032626538987688097; f_eq=-mun, v=-0.0411: 0.29690150478796168; v = xi: f = 0. */
START_TEST(quinn_feq_at_bound_and_zone_edges)
{
    const int L = FRICREG_LAW_QUINN;
    ck_assert_double_eq(law(L, 0.0, MUN, MUN, EPS), MUN);       /* lower edge, = (2) */
    ck_assert_double_eq(law(L, EPS, MUN, MUN, EPS), -MUN);      /* upper edge */
    ck_assert_double_eq(law(L, 0.5 * EPS, MUN, MUN, EPS), 0.0); /* centre v = xi */
    ck_assert_double_eq_tol(law(L, 0.0137, MUN, MUN, EPS), 1.491032831737346, TOL);
    ck_assert_double_eq_tol(law(L, 0.0365, MUN, MUN, EPS), 0.0032626538987688097, TOL);
    ck_assert_double_eq(law(L, -1e-9, MUN, MUN, EPS), MUN); /* just below the zone */
    ck_assert_double_eq(law(L, EPS + 1e-9, MUN, MUN, EPS), -MUN);

    ck_assert_double_eq(law(L, 0.0, -MUN, MUN, EPS), -MUN);
    ck_assert_double_eq(law(L, -EPS, -MUN, MUN, EPS), MUN);
    ck_assert_double_eq(law(L, -0.5 * EPS, -MUN, MUN, EPS), 0.0);
    ck_assert_double_eq_tol(law(L, -0.0411, -MUN, MUN, EPS), 0.29690150478796168, TOL);
    ck_assert_double_eq(law(L, 1e-9, -MUN, MUN, EPS), -MUN);
    ck_assert_double_eq(law(L, -EPS - 1e-9, -MUN, MUN, EPS), MUN);
}
END_TEST

/* (4) at a generic zone edge v = xi +- eps/2 (f_eq = 1.137, -1.913): the two branches of (4)
 * meet at -+mun; in floating point within a few ulp. */
START_TEST(quinn_continuous_at_generic_edges)
{
    const int L = FRICREG_LAW_QUINN;
    const double xi_pos = 0.5 * EPS * (1.137 / MUN), xi_neg = 0.5 * EPS * (-1.913 / MUN);
    ck_assert_double_eq_tol(law(L, xi_pos + 0.5 * EPS, 1.137, MUN, EPS), -MUN, 1e-14);
    ck_assert_double_eq_tol(law(L, xi_pos - 0.5 * EPS, 1.137, MUN, EPS), MUN, 1e-14);
    ck_assert_double_eq_tol(law(L, xi_neg + 0.5 * EPS, -1.913, MUN, EPS), -MUN, 1e-14);
    ck_assert_double_eq_tol(law(L, xi_neg - 0.5 * EPS, -1.913, MUN, EPS), MUN, 1e-14);
}
END_TEST

/* (4) with |f_eq| > mun: sat(f_eq/mun) = +-1 exactly, so the force is that of f_eq = +-mun,
 * bit for bit, at every v (a grid across both zones). */
START_TEST(quinn_feq_above_bound_saturates)
{
    const int L = FRICREG_LAW_QUINN;
    for (int k = -200; k <= 200; k++) {
        double v = k * (1.3 * EPS / 200.0);
        ck_assert_double_eq(law(L, v, 4.71, MUN, EPS), law(L, v, MUN, MUN, EPS));
        ck_assert_double_eq(law(L, v, 37.9, MUN, EPS), law(L, v, MUN, MUN, EPS));
        ck_assert_double_eq(law(L, v, -9.3, MUN, EPS), law(L, v, -MUN, MUN, EPS));
    }
}
END_TEST

/* Paper, properties of (4): "at v = 0 it equals (2) exactly". Checked bit for bit against
 * FORCE_BALANCE on a grid of f_eq over [-1.5 mun, 1.5 mun] and several (mun, eps). */
START_TEST(quinn_equals_force_balance_at_rest)
{
    const double muns[] = {MUN, 0.731, 0.25, 3.3};
    const double epss[] = {EPS, 2.385e-3, 1e-3, 0.02};
    for (size_t a = 0; a < 4; a++)
        for (size_t b = 0; b < 4; b++)
            for (int k = -600; k <= 600; k++) {
                double feq = k * (1.5 * muns[a] / 600.0);
                double q = law(FRICREG_LAW_QUINN, 0.0, feq, muns[a], epss[b]);
                double fb = law(FRICREG_LAW_FORCE_BALANCE, 0.0, feq, muns[a], epss[b]);
                ck_assert_msg(q == fb,
                              "Quinn(v=0) != (2): mun=%.17g eps=%.17g f_eq=%.17g: "
                              "Quinn %.17g, force balance %.17g",
                              muns[a], epss[b], feq, q, fb);
            }
}
END_TEST

/* Continuity of (4): slope 2 mun/eps in v, slope (eps/2)/mun * 2 mun/eps = 1 in f_eq, and
 * |f| <= mun. Grid: v in [-2 eps, 2 eps], f_eq in [-1.6 mun, 1.6 mun]; the slack 1e-13 is
 * rounding only (a jump would be of order mun). */
START_TEST(quinn_lipschitz_and_bounded)
{
    const int L = FRICREG_LAW_QUINN;
    const double hv = EPS / 997.0, hf = MUN / 613.0;
    const double lip_v = 2.0 * MUN / EPS;
    for (int i = -2 * 997; i <= 2 * 997; i += 3)
        for (int j = -981; j <= 981; j += 7) {
            double v = i * hv, feq = j * hf;
            double f = law(L, v, feq, MUN, EPS);
            double fv = law(L, v + hv, feq, MUN, EPS);
            double ff = law(L, v, feq + hf, MUN, EPS);
            QUIET_ASSERT(fabs(fv - f) <= lip_v * hv + 1e-13, "jump in v at v=%.17g f_eq=%.17g", v,
                         feq);
            QUIET_ASSERT(fabs(ff - f) <= hf + 1e-13, "jump in f_eq at v=%.17g f_eq=%.17g", v, feq);
            QUIET_ASSERT(fabs(f) <= MUN, "|f| > mun at v=%.17g f_eq=%.17g", v, feq);
        }
}
END_TEST

/* As eps -> 0, (4) tends to (1) at fixed v != 0 and to (2) at v = 0. With v = 0.0137: once
 * eps <= v (eps = 0.0731e-1 ... 0.0731e-8) the zone |v - xi| < eps/2 lies inside (-eps, eps)
 * and misses v, so f = -mun exactly; at eps = 0.0731 it is still regularized (not -mun). */
START_TEST(quinn_converges_as_eps_to_zero)
{
    const int L = FRICREG_LAW_QUINN;
    double eps = EPS;
    ck_assert_double_ne(law(L, 0.0137, 0.9, MUN, eps), -MUN);
    for (int k = 1; k <= 8; k++) {
        eps /= 10.0;
        ck_assert_double_eq(law(L, 0.0137, 0.9, MUN, eps), -MUN);
        ck_assert_double_eq(law(L, -0.0137, 0.9, MUN, eps), MUN);
        ck_assert_double_eq(law(L, 0.0137, -9.3, MUN, eps), -MUN);
        ck_assert_double_eq_tol(law(L, 0.0, 0.9, MUN, eps), 0.9, TOL);
        ck_assert_double_eq_tol(law(L, 0.0, -1.913, MUN, eps), -1.913, TOL);
        ck_assert_double_eq(law(L, 0.0, 4.71, MUN, eps), MUN);
    }
}
END_TEST

/* mun = 0: every law gives f = 0 (no NaN from f_eq/mun). */
START_TEST(zero_bound_gives_zero_force)
{
    const double vs[] = {0.0, 0.0213, -0.0213, 0.3, -1e-300};
    const double feqs[] = {0.0, 1.137, -9.3};
    for (size_t l = 0; l < N_LAWS; l++)
        for (size_t i = 0; i < 5; i++)
            for (size_t j = 0; j < 3; j++) {
                double f = law(all_laws[l], vs[i], feqs[j], 0.0, EPS);
                ck_assert_msg(f == 0.0, "law %d v=%g f_eq=%g mun=0: f=%g", all_laws[l], vs[i],
                              feqs[j], f);
            }
}
END_TEST

/* ---- Batch ------------------------------------------------------------------------------- */

#define NV 11
#define NF 7
#define NM 3
#define NGRID (NV * NF * NM)

/* A grid across every branch: v at 0, +-eps, inside both zones and outside; f_eq below, at
 * and above the bound; mun = 0 included. */
static void fill_grid(double v[], double feq[], double mun[])
{
    const double vs[NV] = {-0.3,   -EPS,   -0.0604, -0.0191, -1e-300, 0.0,
                           0.0072, 0.0213, 0.0540,  EPS,     0.412};
    const double fs[NF] = {-9.3, -MUN, -1.913, 0.0, 1.137, MUN, 4.71};
    const double ms[NM] = {0.0, 0.731, MUN};
    size_t n = 0;
    for (size_t i = 0; i < NV; i++)
        for (size_t j = 0; j < NF; j++)
            for (size_t k = 0; k < NM; k++, n++) {
                v[n] = vs[i];
                feq[n] = fs[j];
                mun[n] = ms[k];
            }
}

/* The batch kernels are separate loops: they must equal the scalar entry point bit for bit. */
START_TEST(batch_equals_scalar_bitwise)
{
    double v[NGRID], feq[NGRID], mun[NGRID], f[NGRID];
    fill_grid(v, feq, mun);
    for (size_t l = 0; l < N_LAWS; l++) {
        ck_assert_int_eq(fricreg_law_eval_batch(all_laws[l], EPS, NGRID, v, feq, mun, f),
                         FRICREG_OK);
        for (size_t n = 0; n < NGRID; n++) {
            double s = law(all_laws[l], v[n], feq[n], mun[n], EPS);
            ck_assert_msg(same_bits(f[n], s),
                          "law %d v=%g f_eq=%g mun=%g: batch %.17g scalar %.17g", all_laws[l], v[n],
                          feq[n], mun[n], f[n], s);
        }
    }
}
END_TEST

/* The header lets f alias v or f_eq: inputs are read before each output is written. */
START_TEST(batch_output_may_alias_input)
{
    double v[NGRID], feq[NGRID], mun[NGRID], ref[NGRID], buf[NGRID];
    fill_grid(v, feq, mun);
    ck_assert_int_eq(fricreg_law_eval_batch(FRICREG_LAW_QUINN, EPS, NGRID, v, feq, mun, ref),
                     FRICREG_OK);
    memcpy(buf, v, sizeof buf);
    ck_assert_int_eq(fricreg_law_eval_batch(FRICREG_LAW_QUINN, EPS, NGRID, buf, feq, mun, buf),
                     FRICREG_OK);
    ck_assert_int_eq(memcmp(buf, ref, sizeof buf), 0);
    memcpy(buf, feq, sizeof buf);
    ck_assert_int_eq(fricreg_law_eval_batch(FRICREG_LAW_QUINN, EPS, NGRID, v, buf, mun, buf),
                     FRICREG_OK);
    ck_assert_int_eq(memcmp(buf, ref, sizeof buf), 0);
}
END_TEST

/* f_eq may be NULL for (1), (3) and tanh (which ignore it) and gives the same forces; the laws
 * that read it, (2), Karnopp and (4), reject NULL and leave f alone. */
START_TEST(batch_null_feq)
{
    double v[NGRID], feq[NGRID], mun[NGRID], f[NGRID], ref[NGRID];
    fill_grid(v, feq, mun);
    const int ignoring[] = {FRICREG_LAW_COULOMB, FRICREG_LAW_VELOCITY_LIMITED, FRICREG_LAW_TANH};
    for (size_t l = 0; l < 3; l++) {
        ck_assert_int_eq(fricreg_law_eval_batch(ignoring[l], EPS, NGRID, v, feq, mun, ref),
                         FRICREG_OK);
        ck_assert_int_eq(fricreg_law_eval_batch(ignoring[l], EPS, NGRID, v, NULL, mun, f),
                         FRICREG_OK);
        ck_assert_int_eq(memcmp(f, ref, sizeof f), 0);
    }
    const int reading[] = {FRICREG_LAW_FORCE_BALANCE, FRICREG_LAW_KARNOPP, FRICREG_LAW_QUINN};
    for (size_t l = 0; l < 3; l++) {
        for (size_t n = 0; n < NGRID; n++)
            f[n] = SENTINEL;
        ck_assert_int_eq(fricreg_law_eval_batch(reading[l], EPS, NGRID, v, NULL, mun, f),
                         FRICREG_ENULL);
        for (size_t n = 0; n < NGRID; n++)
            ck_assert_double_eq(f[n], SENTINEL);
    }
}
END_TEST

/* m = 0 is valid and does nothing, even with NULL arrays. */
START_TEST(batch_empty_is_ok)
{
    double f[1] = {SENTINEL};
    for (size_t l = 0; l < N_LAWS; l++) {
        ck_assert_int_eq(fricreg_law_eval_batch(all_laws[l], EPS, 0, NULL, NULL, NULL, NULL),
                         FRICREG_OK);
        const double v[1] = {0.0213}, feq[1] = {1.137}, mun[1] = {MUN};
        ck_assert_int_eq(fricreg_law_eval_batch(all_laws[l], EPS, 0, v, feq, mun, f), FRICREG_OK);
        ck_assert_double_eq(f[0], SENTINEL);
    }
}
END_TEST

/* ---- Error paths ------------------------------------------------------------------------- */

/* Scalar call that must fail with `code` and leave f alone. */
static void expect_scalar_fail(int code, int which, double v, double f_eq, double mun, double eps)
{
    double f = SENTINEL;
    int status = fricreg_law_eval(which, v, f_eq, mun, eps, &f);
    ck_assert_msg(status == code, "law %d v=%g f_eq=%g mun=%g eps=%g: status %d, expected %d",
                  which, v, f_eq, mun, eps, status, code);
    ck_assert_double_eq(f, SENTINEL);
}

START_TEST(scalar_null_output)
{
    for (size_t l = 0; l < N_LAWS; l++)
        ck_assert_int_eq(fricreg_law_eval(all_laws[l], 0.0213, 1.137, MUN, EPS, NULL),
                         FRICREG_ENULL);
}
END_TEST

START_TEST(scalar_unknown_law)
{
    expect_scalar_fail(FRICREG_EINVAL, 0, 0.0213, 1.137, MUN, EPS);
    expect_scalar_fail(FRICREG_EINVAL, 7, 0.0213, 1.137, MUN, EPS);
    expect_scalar_fail(FRICREG_EINVAL, -1, 0.0213, 1.137, MUN, EPS);
}
END_TEST

/* eps is validated for every law, even (1) and (2) which ignore it (header). */
START_TEST(scalar_bad_eps)
{
    for (size_t l = 0; l < N_LAWS; l++) {
        int L = all_laws[l];
        expect_scalar_fail(FRICREG_EINVAL, L, 0.0213, 1.137, MUN, 0.0);
        expect_scalar_fail(FRICREG_EINVAL, L, 0.0213, 1.137, MUN, -0.0);
        expect_scalar_fail(FRICREG_EINVAL, L, 0.0213, 1.137, MUN, -0.0731);
        expect_scalar_fail(FRICREG_ENONFINITE, L, 0.0213, 1.137, MUN, NAN);
        expect_scalar_fail(FRICREG_ENONFINITE, L, 0.0213, 1.137, MUN, INFINITY);
        expect_scalar_fail(FRICREG_ENONFINITE, L, 0.0213, 1.137, MUN, -INFINITY);
    }
}
END_TEST

/* v, f_eq, mun NaN or infinite: ENONFINITE (f_eq too, for every law: the header lists it);
 * mun < 0: EINVAL. */
START_TEST(scalar_bad_numbers)
{
    for (size_t l = 0; l < N_LAWS; l++) {
        int L = all_laws[l];
        expect_scalar_fail(FRICREG_ENONFINITE, L, NAN, 1.137, MUN, EPS);
        expect_scalar_fail(FRICREG_ENONFINITE, L, INFINITY, 1.137, MUN, EPS);
        expect_scalar_fail(FRICREG_ENONFINITE, L, -INFINITY, 1.137, MUN, EPS);
        expect_scalar_fail(FRICREG_ENONFINITE, L, 0.0213, NAN, MUN, EPS);
        expect_scalar_fail(FRICREG_ENONFINITE, L, 0.0213, -INFINITY, MUN, EPS);
        expect_scalar_fail(FRICREG_ENONFINITE, L, 0.0213, 1.137, NAN, EPS);
        expect_scalar_fail(FRICREG_ENONFINITE, L, 0.0213, 1.137, INFINITY, EPS);
        expect_scalar_fail(FRICREG_EINVAL, L, 0.0213, 1.137, -0.2, EPS);
        expect_scalar_fail(FRICREG_EINVAL, L, 0.0, 1.137, -MUN, EPS);
    }
}
END_TEST

/* Batch call that must fail with `code` and leave all of f[0..NB) alone. */
#define NB 4
static void expect_batch_fail(int code, int which, double eps, const double v[], const double feq[],
                              const double mun[])
{
    double f[NB];
    for (size_t n = 0; n < NB; n++)
        f[n] = SENTINEL;
    int status = fricreg_law_eval_batch(which, eps, NB, v, feq, mun, f);
    ck_assert_msg(status == code, "batch law %d eps=%g: status %d, expected %d", which, eps, status,
                  code);
    for (size_t n = 0; n < NB; n++)
        ck_assert_msg(f[n] == SENTINEL, "batch law %d: f[%zu] written on failure", which, n);
}

/* Good batch inputs, and copies with one bad element late in the array (so that a kernel that
 * wrote as it validated would have written the earlier outputs). */
static const double good_v[NB] = {0.0213, -0.0191, 0.0, 0.412};
static const double good_feq[NB] = {1.137, -1.913, 4.71, -9.3};
static const double good_mun[NB] = {MUN, 0.731, 0.25, 3.3};

START_TEST(batch_error_paths)
{
    double bad[NB], f[NB];
    for (size_t l = 0; l < N_LAWS; l++) {
        int L = all_laws[l];
        /* NULL arrays (m > 0). */
        expect_batch_fail(FRICREG_ENULL, L, EPS, NULL, good_feq, good_mun);
        expect_batch_fail(FRICREG_ENULL, L, EPS, good_v, good_feq, NULL);
        ck_assert_int_eq(fricreg_law_eval_batch(L, EPS, NB, good_v, good_feq, good_mun, NULL),
                         FRICREG_ENULL);
        /* eps. */
        expect_batch_fail(FRICREG_EINVAL, L, 0.0, good_v, good_feq, good_mun);
        expect_batch_fail(FRICREG_EINVAL, L, -0.0731, good_v, good_feq, good_mun);
        expect_batch_fail(FRICREG_ENONFINITE, L, NAN, good_v, good_feq, good_mun);
        expect_batch_fail(FRICREG_ENONFINITE, L, INFINITY, good_v, good_feq, good_mun);
        /* v NaN / Inf in the last element. */
        memcpy(bad, good_v, sizeof bad);
        bad[3] = NAN;
        expect_batch_fail(FRICREG_ENONFINITE, L, EPS, bad, good_feq, good_mun);
        bad[3] = -INFINITY;
        expect_batch_fail(FRICREG_ENONFINITE, L, EPS, bad, good_feq, good_mun);
        /* mun NaN / Inf / negative. */
        memcpy(bad, good_mun, sizeof bad);
        bad[2] = NAN;
        expect_batch_fail(FRICREG_ENONFINITE, L, EPS, good_v, good_feq, bad);
        bad[2] = INFINITY;
        expect_batch_fail(FRICREG_ENONFINITE, L, EPS, good_v, good_feq, bad);
        bad[2] = -0.25;
        expect_batch_fail(FRICREG_EINVAL, L, EPS, good_v, good_feq, bad);
        /* The good inputs pass: the failures above are the bad element's. */
        ck_assert_int_eq(fricreg_law_eval_batch(L, EPS, NB, good_v, good_feq, good_mun, f),
                         FRICREG_OK);
    }
    /* Unknown law. */
    expect_batch_fail(FRICREG_EINVAL, 0, EPS, good_v, good_feq, good_mun);
    expect_batch_fail(FRICREG_EINVAL, 7, EPS, good_v, good_feq, good_mun);
    expect_batch_fail(FRICREG_EINVAL, -1, EPS, good_v, good_feq, good_mun);
    /* f_eq NaN / Inf for the laws that read it. */
    const int reading[] = {FRICREG_LAW_FORCE_BALANCE, FRICREG_LAW_KARNOPP, FRICREG_LAW_QUINN};
    for (size_t l = 0; l < 3; l++) {
        memcpy(bad, good_feq, sizeof bad);
        bad[3] = NAN;
        expect_batch_fail(FRICREG_ENONFINITE, reading[l], EPS, good_v, bad, good_mun);
        bad[3] = INFINITY;
        expect_batch_fail(FRICREG_ENONFINITE, reading[l], EPS, good_v, bad, good_mun);
    }
}
END_TEST

/* The batch header: "FRICREG_ENONFINITE if any input is NaN or infinite", and the scalar entry
 * point rejects a NaN f_eq for every law (scalar_bad_numbers). A non-NULL f_eq array holding a
 * NaN is an input, so the batch must reject it too, even for the laws that ignore f_eq. */
START_TEST(batch_nonfinite_feq_rejected_for_every_law)
{
    const int ignoring[] = {FRICREG_LAW_COULOMB, FRICREG_LAW_VELOCITY_LIMITED, FRICREG_LAW_TANH};
    double bad[NB];
    for (size_t l = 0; l < 3; l++) {
        memcpy(bad, good_feq, sizeof bad);
        bad[1] = NAN;
        expect_batch_fail(FRICREG_ENONFINITE, ignoring[l], EPS, good_v, bad, good_mun);
    }
}
END_TEST

/* ---- The division-free form of (4) and the validation pass -------------------------------- */

/* xorshift64*: the same inputs on every machine. */
static uint64_t rng_state = 0x9E3779B97F4A7C15u;
static double uniform01(void)
{
    return xorshift64star_uniform(&rng_state, 0.0, 1.0);
}

/* |f - F| for (4)'s exact value F = clamp(g - c mun, -mun, mun), g = clamp(f_eq, -mun, mun)
 * (exact), c = 2v/eps: c and c mun are carried as double-doubles (fma gives the exact
 * remainder of a quotient and the exact error of a product, the two-sum the exact error of a
 * difference), so F is known to ~1e-31 relative and the returned error is f's own. */
static double quinn_error(double f, double v, double f_eq, double mun, double eps)
{
    double g = f_eq > mun ? mun : f_eq < -mun ? -mun : f_eq;
    double c = 2.0 * v / eps, c_lo = fma(-c, eps, 2.0 * v) / eps;           /* 2v is exact */
    double p = c * mun, p_lo = fma(c, mun, -p) + c_lo * mun;                /* p + p_lo = c mun */
    double d = g - p, gb = d - g, d_lo = (g - (d - gb)) + (-p - gb) - p_lo; /* d + d_lo */
    if (d + d_lo >= mun)
        return fabs(f - mun);
    if (d + d_lo <= -mun)
        return fabs(f + mun);
    return fabs((f - d) - d_lo); /* f - d is exact: they agree to a few ulps */
}

/* law.h writes (4) -mun sat(2v/eps - sat(f_eq/mun)) without a division, as
 * f = clamp(clamp(f_eq, -mun, mun) - c mun, -mun, mun). Its rounding, with u = 2^-53: the
 * scale k = 2/eps carries <= 3u (the quotient, and fr_band_scale's ulp), c' = fl(v k) <= 4u,
 * t = fl(c' mun) <= 5u relative, d = fl(g - t) one more u of |d|, and the clamps are exact and
 * 1-Lipschitz; in the band |c| < 2 and |d| <= mun, so |f - F| <= (5 * 2 + 1) u mun = 1.2e-15
 * mun at worst. Typical errors sit well below: 6.4e-16 mun measured over 1e6 random
 * inputs, and this test holds the kernel to that figure over its own 1e6 (fixed seed; eps
 * over six decades, v within 1.5 eps, f_eq within 2 mun), through the batch entry point. */
START_TEST(quinn_division_free_within_rounding)
{
    enum { CHUNK = 1000, CHUNKS = 1000 };
    static double v[CHUNK], feq[CHUNK], mun[CHUNK], f[CHUNK];
    double worst = 0.0;
    for (int chunk = 0; chunk < CHUNKS; chunk++) {
        double eps = pow(10.0, -6.0 + 6.0 * uniform01());
        for (int n = 0; n < CHUNK; n++) {
            mun[n] = 0.1 + 9.9 * uniform01();
            v[n] = (3.0 * uniform01() - 1.5) * eps;
            feq[n] = (4.0 * uniform01() - 2.0) * mun[n];
        }
        ck_assert_int_eq(fricreg_law_eval_batch(FRICREG_LAW_QUINN, eps, CHUNK, v, feq, mun, f),
                         FRICREG_OK);
        for (int n = 0; n < CHUNK; n++)
            worst = fmax(worst, quinn_error(f[n], v[n], feq[n], mun[n], eps) / mun[n]);
    }
    ck_assert_msg(worst <= 6.4e-16, "max |f - (4)| = %.3g mun", worst);
    ck_assert_msg(worst > 0.0, "no rounding at all: the reference is not being exercised");
}
END_TEST

/* From |v| = eps on, (4) is (1) exactly: f = -mun sgn(v) whatever f_eq. The rounded 2/eps can
 * make c = v (2/eps) fall a hair short of 2 at v = eps (eps * fl(2/eps) < 2 for about one
 * eps in seven), which left f = -mun + ~1e-16 mun there; law.h's band scale rounds up then.
 * The worst f_eq is the bound on the far side (g = +mun for v > 0). */
START_TEST(quinn_is_coulomb_from_the_band_edge_on)
{
    int short_scales = 0, wrong = 0;
    double first_wrong_eps = 0.0;
    for (int n = 0; n < 100000; n++) {
        double eps = pow(10.0, -8.0 + 8.0 * uniform01()), mun = 0.1 + 9.9 * uniform01();
        double at_edge = SENTINEL, mirrored = SENTINEL, past_edge = SENTINEL;
        short_scales += eps * (2.0 / eps) < 2.0;
        fricreg_law_eval(FRICREG_LAW_QUINN, eps, mun, mun, eps, &at_edge);
        fricreg_law_eval(FRICREG_LAW_QUINN, -eps, -mun, mun, eps, &mirrored);
        fricreg_law_eval(FRICREG_LAW_QUINN, nextafter(eps, 1.0), 1.7 * mun, mun, eps, &past_edge);
        if (at_edge != -mun || mirrored != mun || past_edge != -mun) /* counted, so that */
            first_wrong_eps = wrong++ ? first_wrong_eps : eps;       /* one assertion, not 3e5 */
    }
    ck_assert_msg(wrong == 0, "%d of 100000 eps not (1) at the band edge, the first %.17g", wrong,
                  first_wrong_eps);
    ck_assert_int_gt(short_scales, 5000); /* the case the rounding up is for did occur */
}
END_TEST

/* c = 2v/eps overflows to +-inf for |v| > eps DBL_MAX/2 (eps >= DBL_MIN is allowed): with
 * mun > 0 the force is -mun sgn(v), and with mun = 0 it is 0, although c mun = inf * 0 is a
 * NaN there (law.h's clamp maps it to a bound, +-0). */
START_TEST(quinn_overflowing_band_position)
{
    const double vs[] = {1e300, -1e300, DBL_MAX, -DBL_MAX};
    for (size_t i = 0; i < 4; i++) {
        double sign = vs[i] > 0.0 ? 1.0 : -1.0;
        ck_assert_double_eq(law(FRICREG_LAW_QUINN, vs[i], 2.913, MUN, DBL_MIN), -sign * MUN);
        ck_assert_double_eq(law(FRICREG_LAW_QUINN, vs[i], -2.913, MUN, DBL_MIN), -sign * MUN);
        double f = law(FRICREG_LAW_QUINN, vs[i], 2.913, 0.0, DBL_MIN);
        ck_assert_msg(f == 0.0, "mun = 0, v = %g: f = %g", vs[i], f);
    }
}
END_TEST

/* The batch is validated by one summing pass in lanes plus a tail (law.c): a bad element in
 * any position, lane or tail, is found, named by its code, and nothing is written. m = 11 is
 * two groups of four lanes and a tail of three. */
#define NL 11
START_TEST(batch_validation_every_position)
{
    double v[NL], feq[NL], mun[NL], f[NL];
    const double bad_values[] = {NAN, INFINITY, -INFINITY};
    for (size_t p = 0; p < NL; p++)
        for (size_t b = 0; b < 4; b++)
            for (int which = 0; which < 3; which++) {
                for (size_t n = 0; n < NL; n++) {
                    v[n] = 0.0213 * (double)n - 0.0731;
                    feq[n] = 1.137 - 0.41 * (double)n;
                    mun[n] = 0.731 + 0.2 * (double)n;
                    f[n] = SENTINEL;
                }
                double *arr = which == 0 ? v : which == 1 ? feq : mun;
                /* b = 3: the least negative mun, -2^-1074: EINVAL, however tiny */
                arr[p] = b < 3 ? bad_values[b] : which == 2 ? -0x1p-1074 : NAN;
                int expected = b == 3 && which == 2 ? FRICREG_EINVAL : FRICREG_ENONFINITE;
                int status = fricreg_law_eval_batch(FRICREG_LAW_QUINN, EPS, NL, v, feq, mun, f);
                ck_assert_msg(status == expected, "array %d, position %zu, bad %zu: status %d",
                              which, p, b, status);
                for (size_t n = 0; n < NL; n++)
                    ck_assert_msg(f[n] == SENTINEL, "f[%zu] written on failure", n);
            }
}
END_TEST

/* What the summing check must let through: finite inputs whose sum overflows (the exact check
 * then runs and passes), and mun = -0, which is >= 0. The forces are the law's: v far out of
 * the band gives -mun sgn(v); v = 0 gives (2), clamp(f_eq, -mun, mun) = 0 for mun = -0. */
START_TEST(batch_validation_no_false_alarms)
{
    double v[NL], feq[NL], mun[NL], f[NL];
    for (size_t n = 0; n < NL; n++) {
        v[n] = 1.5e308;
        feq[n] = 1.7e308;
        mun[n] = 1.2e308;
    }
    v[9] = 0.0;
    mun[9] = -0.0;
    ck_assert_int_eq(fricreg_law_eval_batch(FRICREG_LAW_QUINN, EPS, NL, v, feq, mun, f),
                     FRICREG_OK);
    for (size_t n = 0; n < NL; n++)
        ck_assert_double_eq(f[n], n == 9 ? 0.0 : -1.2e308);
}
END_TEST

/* ---- Status text and version ------------------------------------------------------------- */

/* Every code 0..FRICREG_EWORK has its own non-empty text; unknown codes get the fixed
 * fallback. */
START_TEST(strerror_texts)
{
    const char *text[FRICREG_EWORK + 1];
    for (int c = 0; c <= FRICREG_EWORK; c++) {
        text[c] = fricreg_strerror(c);
        ck_assert_ptr_nonnull(text[c]);
        ck_assert_uint_gt(strlen(text[c]), 0);
        ck_assert_str_ne(text[c], "unknown fricreg status code");
        for (int d = 0; d < c; d++)
            ck_assert_msg(strcmp(text[c], text[d]) != 0, "codes %d and %d share a text", c, d);
    }
    ck_assert_str_eq(fricreg_strerror(FRICREG_EWORK + 1), "unknown fricreg status code");
    ck_assert_str_eq(fricreg_strerror(-1), "unknown fricreg status code");
    ck_assert_str_eq(fricreg_strerror(100000), "unknown fricreg status code");
}
END_TEST

/* The linked library's version equals the header's. */
START_TEST(version_matches_header)
{
    ck_assert_int_eq(fricreg_version_number(), FRICREG_VERSION_NUMBER);
    ck_assert_int_eq(FRICREG_VERSION_NUMBER, FRICREG_VERSION_MAJOR * 10000 +
                                                 FRICREG_VERSION_MINOR * 100 +
                                                 FRICREG_VERSION_PATCH);
    ck_assert_ptr_nonnull(fricreg_version());
    ck_assert_str_eq(fricreg_version(), FRICREG_VERSION_STRING);
}
END_TEST

/* ---- Names (fricreg_law_name, fricreg_law_from_name) --------------------------------------- */

/* Header: the six names, exactly as fricreg-sim's --law has taken them since 1.0. */
START_TEST(law_names_are_the_cli_names)
{
    static const char *const expected[] = {"coulomb",          "force-balance", "karnopp",
                                           "velocity-limited", "tanh",          "quinn"};
    for (size_t l = 0; l < N_LAWS; l++)
        ck_assert_str_eq(fricreg_law_name(all_laws[l]), expected[l]);
}
END_TEST

/* Round trip both ways for every law; and the header's loop "from 1 until NULL" visits
 * exactly the laws that fricreg_law_eval accepts. */
START_TEST(law_names_round_trip)
{
    for (size_t l = 0; l < N_LAWS; l++)
        ck_assert_int_eq(fricreg_law_from_name(fricreg_law_name(all_laws[l])), all_laws[l]);
    int law = 1;
    for (; fricreg_law_name(law) != NULL; law++) {
        double f = SENTINEL;
        ck_assert_int_eq(fricreg_law_eval(law, 0.0213, 1.137, MUN, EPS, &f), FRICREG_OK);
        ck_assert_ptr_eq(fricreg_law_name(law), fricreg_law_name(law)); /* static storage */
    }
    ck_assert_int_eq(law - 1, (int)N_LAWS);
    double f = SENTINEL;
    ck_assert_int_eq(fricreg_law_eval(law, 0.0213, 1.137, MUN, EPS, &f), FRICREG_EINVAL);
}
END_TEST

/* Header: NULL for an unknown law, 0 for a NULL or unknown name; names compare exactly. */
START_TEST(law_names_unknown)
{
    static const int bad_laws[] = {0, -1, 7, 1000, INT32_MIN, INT32_MAX};
    for (size_t i = 0; i < sizeof bad_laws / sizeof bad_laws[0]; i++)
        ck_assert_ptr_null(fricreg_law_name(bad_laws[i]));
    static const char *const bad_names[] = {"",
                                            "Quinn",
                                            "QUINN",
                                            "quinn ",
                                            " quinn",
                                            "quin",
                                            "quinnn",
                                            "force_balance",
                                            "velocity limited",
                                            "coulomb+force-balance",
                                            "rk4",
                                            "1",
                                            "6"};
    for (size_t i = 0; i < sizeof bad_names / sizeof bad_names[0]; i++)
        ck_assert_msg(fricreg_law_from_name(bad_names[i]) == 0, "\"%s\" named a law", bad_names[i]);
    ck_assert_int_eq(fricreg_law_from_name(NULL), 0);
}
END_TEST

static Suite *law_suite(void)
{
    Suite *s = suite_create("law");
    TCase *tc = tcase_create("laws");
    tcase_add_test(tc, coulomb_is_minus_mun_sign_v);
    tcase_add_test(tc, force_balance_branches);
    tcase_add_test(tc, karnopp_branches);
    tcase_add_test(tc, velocity_limited_branches);
    tcase_add_test(tc, tanh_values);
    tcase_add_test(tc, quinn_feq_below_bound_positive);
    tcase_add_test(tc, quinn_feq_below_bound_negative);
    tcase_add_test(tc, quinn_feq_at_bound_and_zone_edges);
    tcase_add_test(tc, quinn_continuous_at_generic_edges);
    tcase_add_test(tc, quinn_feq_above_bound_saturates);
    tcase_add_test(tc, quinn_equals_force_balance_at_rest);
    tcase_add_test(tc, quinn_lipschitz_and_bounded);
    tcase_add_test(tc, quinn_converges_as_eps_to_zero);
    tcase_add_test(tc, zero_bound_gives_zero_force);
    tcase_add_test(tc, quinn_division_free_within_rounding);
    tcase_add_test(tc, quinn_is_coulomb_from_the_band_edge_on);
    tcase_add_test(tc, quinn_overflowing_band_position);
    suite_add_tcase(s, tc);

    tc = tcase_create("batch");
    tcase_add_test(tc, batch_equals_scalar_bitwise);
    tcase_add_test(tc, batch_output_may_alias_input);
    tcase_add_test(tc, batch_null_feq);
    tcase_add_test(tc, batch_empty_is_ok);
    suite_add_tcase(s, tc);

    tc = tcase_create("errors");
    tcase_add_test(tc, scalar_null_output);
    tcase_add_test(tc, scalar_unknown_law);
    tcase_add_test(tc, scalar_bad_eps);
    tcase_add_test(tc, scalar_bad_numbers);
    tcase_add_test(tc, batch_error_paths);
    tcase_add_test(tc, batch_nonfinite_feq_rejected_for_every_law);
    tcase_add_test(tc, batch_validation_every_position);
    tcase_add_test(tc, batch_validation_no_false_alarms);
    tcase_add_test(tc, strerror_texts);
    tcase_add_test(tc, version_matches_header);
    suite_add_tcase(s, tc);

    tc = tcase_create("names");
    tcase_add_test(tc, law_names_are_the_cli_names);
    tcase_add_test(tc, law_names_round_trip);
    tcase_add_test(tc, law_names_unknown);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(law_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
