/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_coupled.c — Check suite for the consistent near-stick law of coupled contacts
 * (docs/coupled.md), verified against a reference written independently of the library.
 *
 * The reference. Under FRICREG_PARTITION_CONSISTENT the forces of the near-stick set S solve
 *     f_S = argmin_{l <= f <= u} 1/2 f^T W_SS f + b^T f,
 *     b_i = a_free,i + W_ii c_i mun_i + (W_SL f_L)_i,  f_L = -mun_L sgn(zdot_L),
 *     l_i = -mun_i (1 - max(-c_i, 0)),  u_i = mun_i (1 - max(c_i, 0)),
 * with c_i = 2 zdot_i / eps for law (4) and c = 0 for Karnopp and force balance (spec, "The
 * consistent law" and consequence 6). W_SS is positive definite, so the minimizer is unique and
 * is the one point meeting the KKT conditions: a free coordinate lies within [l_i, u_i] with zero
 * gradient g = W_SS f + b; one at its lower bound has g_i >= 0, one at its upper bound g_i <= 0.
 * brute_force() tries all 3^s (lower / free / upper) assignments with GSL's Cholesky on each free
 * block and keeps the one that meets them; it shares no code with the library. */
#include <check.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>

#include "fricreg.h"
#include "random.h"
#include "quiet_check.h"

#define MMAX 8        /* largest contact count of the random cases: 3^8 assignments */
#define KKT_TOL 1e-10 /* largest scaled KKT violation the reference accepts */
#define SENTINEL (-777.125)

/* ---- Random numbers: splitmix64, so every run and platform sees the same cases ------------- */

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

typedef struct {
    size_t m;
    double W[MMAX * MMAX]; /* row-major, SPD */
    double mun[MMAX], eps, zdot[MMAX], a_free[MMAX];
} contact_case;

/* W = D (A A^T / m + delta I) D with A_ij, delta and D_ii random: SPD with condition number
 * at most a few hundred, and unequal diagonal entries. */
static void random_spd(size_t m, double W[])
{
    double work[MMAX * MMAX + MMAX];
    random_scaled_spd(splitmix64_uniform, &rng_state, m, 0.2, 1.0, work, W);
}

/* zdot: mostly inside the band, some exactly at rest, some sliding either way. */
static double random_velocity(double eps)
{
    double r = uniform(0.0, 1.0);
    if (r < 0.15)
        return 0.0;
    if (r < 0.75)
        return uniform(-eps, eps);
    return (r < 0.875 ? 1.0 : -1.0) * eps * uniform(1.0, 3.0);
}

/* a_free on the scale of the largest |W f| a contact can see, so that some contacts saturate
 * and others hold. */
static void random_case(contact_case *c, size_t m)
{
    c->m = m;
    random_spd(m, c->W);
    c->eps = uniform(0.005, 0.2);
    for (size_t i = 0; i < m; i++)
        c->mun[i] = uniform(0.0, 1.0) < 0.06 ? 0.0 : uniform(0.1, 3.0);
    for (size_t i = 0; i < m; i++) {
        double reach = 0.0;
        for (size_t k = 0; k < m; k++)
            reach += fabs(c->W[i * m + k]) * c->mun[k];
        c->zdot[i] = random_velocity(c->eps);
        c->a_free[i] = uniform(-1.2, 1.2) * (reach + 0.1);
    }
}

static double max_of(const double x[], size_t n)
{
    double r = 0.0;
    for (size_t i = 0; i < n; i++)
        r = fmax(r, fabs(x[i]));
    return r;
}

/* ---- The reference: the box QP of the spec, and brute-force enumeration ------------------- */

typedef struct {
    size_t s;
    size_t idx[MMAX]; /* S, in contact order */
    double W[MMAX * MMAX], b[MMAX], l[MMAX], u[MMAX];
} box_qp;

static int near_stick(int law, double zdot, double eps)
{
    return law == FRICREG_LAW_FORCE_BALANCE ? zdot == 0.0 : fabs(zdot) < eps;
}

/* The QP of the consistent law for law (4), Karnopp or force balance; f gets the slip forces
 * -mun sgn(zdot) on L (and 0 on S). */
static void build_qp(const contact_case *c, int law, box_qp *qp, double f[])
{
    size_t m = c->m, s = 0;
    for (size_t i = 0; i < m; i++) {
        int in_s = near_stick(law, c->zdot[i], c->eps);
        f[i] = in_s ? 0.0 : -c->mun[i] * (double)((c->zdot[i] > 0) - (c->zdot[i] < 0));
        if (in_s)
            qp->idx[s++] = i;
    }
    qp->s = s;
    for (size_t a = 0; a < s; a++) {
        size_t i = qp->idx[a];
        double ci = law == FRICREG_LAW_QUINN ? 2.0 * c->zdot[i] / c->eps : 0.0;
        double slip_coupling = 0.0;
        for (size_t k = 0; k < m; k++)
            slip_coupling += c->W[i * m + k] * f[k]; /* f is 0 on S */
        qp->b[a] = c->a_free[i] + c->W[i * m + i] * ci * c->mun[i] + slip_coupling;
        qp->l[a] = -c->mun[i] * (1.0 - fmax(-ci, 0.0));
        qp->u[a] = c->mun[i] * (1.0 - fmax(ci, 0.0));
        for (size_t e = 0; e < s; e++)
            qp->W[a * s + e] = c->W[i * m + qp->idx[e]];
    }
}

enum { AT_LOWER = 0, FREE = 1, AT_UPPER = 2 };

/* The candidate of one assignment: bounds where active, W_FF f_F = -(b_F + W_FA f_A) on the
 * free set F (GSL Cholesky). Returns its scaled KKT violation (HUGE_VAL if W_FF fails). */
static double candidate(const box_qp *qp, const int state[], double f[])
{
    size_t s = qp->s, nf = 0, free_idx[MMAX];
    for (size_t a = 0; a < s; a++) {
        f[a] = state[a] == AT_LOWER ? qp->l[a] : state[a] == AT_UPPER ? qp->u[a] : 0.0;
        if (state[a] == FREE)
            free_idx[nf++] = a;
    }
    if (nf > 0) {
        double A[MMAX * MMAX], r[MMAX];
        for (size_t p = 0; p < nf; p++) {
            size_t a = free_idx[p];
            r[p] = -qp->b[a];
            for (size_t e = 0; e < s; e++)
                if (state[e] != FREE)
                    r[p] -= qp->W[a * s + e] * f[e];
            for (size_t q = 0; q < nf; q++)
                A[p * nf + q] = qp->W[a * s + free_idx[q]];
        }
        gsl_matrix_view Av = gsl_matrix_view_array(A, nf, nf);
        gsl_vector_view rv = gsl_vector_view_array(r, nf);
        if (gsl_linalg_cholesky_decomp1(&Av.matrix) != GSL_SUCCESS ||
            gsl_linalg_cholesky_svx(&Av.matrix, &rv.vector) != GSL_SUCCESS)
            return HUGE_VAL;
        for (size_t p = 0; p < nf; p++)
            f[free_idx[p]] = r[p];
    }
    double fscale = fmax(max_of(qp->l, s), max_of(qp->u, s)), bscale = max_of(qp->b, s);
    fscale = fscale > 0.0 ? fscale : 1.0;
    double gscale = bscale + max_of(qp->W, s * s) * fscale, violation = 0.0;
    for (size_t a = 0; a < s; a++) {
        double g = qp->b[a];
        for (size_t e = 0; e < s; e++)
            g += qp->W[a * s + e] * f[e];
        if (state[a] == FREE)
            violation = fmax(violation, fmax(qp->l[a] - f[a], f[a] - qp->u[a]) / fscale);
        else
            violation = fmax(violation, (state[a] == AT_LOWER ? -g : g) / gscale);
    }
    return violation;
}

/* All 3^s assignments; f_S gets the one with the smallest KKT violation, which must meet the
 * conditions (<= KKT_TOL), and every other assignment that meets them must give the same f_S
 * (uniqueness, up to ties such as l_i = u_i). Returns the number of assignments tried. */
static long brute_force(const box_qp *qp, double f_S[])
{
    size_t s = qp->s;
    long total = 1;
    for (size_t a = 0; a < s; a++)
        total *= 3;
    double best = HUGE_VAL, accepted[16][MMAX];
    int n_accepted = 0;
    for (long code = 0; code < total; code++) {
        int state[MMAX];
        long rest = code;
        for (size_t a = 0; a < s; a++, rest /= 3)
            state[a] = (int)(rest % 3);
        double f[MMAX], violation = candidate(qp, state, f);
        if (violation < best) {
            best = violation;
            memcpy(f_S, f, s * sizeof *f);
        }
        if (violation <= KKT_TOL && n_accepted < 16)
            memcpy(accepted[n_accepted++], f, s * sizeof *f);
    }
    ck_assert_msg(best <= KKT_TOL, "reference: no assignment meets KKT (best %.3g, s = %zu)", best,
                  s);
    double fscale = fmax(fmax(max_of(qp->l, s), max_of(qp->u, s)), 1e-300);
    for (int k = 0; k < n_accepted; k++)
        for (size_t a = 0; a < s; a++)
            ck_assert_msg(fabs(accepted[k][a] - f_S[a]) <= 1e-8 * fscale,
                          "reference: two KKT points differ at %zu: %.17g vs %.17g", a,
                          accepted[k][a], f_S[a]);
    return total;
}

/* Reference forces of all m contacts under the consistent law. */
static void reference_forces(const contact_case *c, int law, double f[])
{
    box_qp qp;
    double f_S[MMAX];
    build_qp(c, law, &qp, f);
    brute_force(&qp, f_S);
    for (size_t a = 0; a < qp.s; a++)
        f[qp.idx[a]] = f_S[a];
}

/* ---- The reference on hand-solved cases --------------------------------------------------- */

/* The two blocks of docs/coupled.md: W = [[1, -1], [-1, 2]] (det 1, W^-1 = [[2, 1], [1, 1]]),
 * mun = (0.5, 0.25), eps = 0.02. */
static contact_case two_block(double z1, double z2, double a1, double a2)
{
    contact_case c = {.m = 2,
                      .W = {1.0, -1.0, -1.0, 2.0},
                      .mun = {0.5, 0.25},
                      .eps = 0.02,
                      .zdot = {z1, z2},
                      .a_free = {a1, a2}};
    return c;
}

static void expect_forces(const double f[], double f1, double f2, double tol)
{
    ck_assert_double_eq_tol(f[0], f1, tol);
    ck_assert_double_eq_tol(f[1], f2, tol);
}

/* At rest, a_free = (0.1, 0.1): c = 0, b = a_free, the unconstrained minimizer
 * f = -W^-1 b = -(0.3, 0.2) lies inside the box [-0.5, 0.5] x [-0.25, 0.25]. */
START_TEST(reference_interior_at_rest)
{
    contact_case c = two_block(0.0, 0.0, 0.1, 0.1);
    double f[2];
    reference_forces(&c, FRICREG_LAW_QUINN, f);
    expect_forces(f, -0.3, -0.2, 1e-15);
}
END_TEST

/* The first jump of docs/coupled.md: zdot = (0, eps(1 - 1e-9)). c_2 = 2(1 - 1e-9) squeezes
 * contact 2's box to [l_2, u_2] = [-0.25, -0.25 + 5e-10], and b_2 = 0.1 + W_22 c_2 mun_2 =
 * 1.1 - 1e-9 pushes it to l_2 = -0.25; then f_1 = -(b_1 + W_12 f_2) / W_11 = -(0.1 + 0.25) =
 * -0.35 (gradient of contact 2: 0.35 - 0.5 + 1.1 > 0). The paper's partition gives -0.35 only
 * once contact 2 has left. */
START_TEST(reference_edge_pins_the_leaving_contact)
{
    contact_case c = two_block(0.0, 0.02 * (1.0 - 1e-9), 0.1, 0.1);
    double f[2];
    reference_forces(&c, FRICREG_LAW_QUINN, f);
    expect_forces(f, -0.35, -0.25, 1e-15);
}
END_TEST

/* The sign change of docs/coupled.md: a_free = (-0.3, 0.1), zdot = (eps(1 - 1e-9), 0).
 * Contact 1's box is [-0.5, -0.5 + 1e-9] and b_1 = -0.3 + 1 - 1e-9 puts it at -0.5; f_2's
 * unconstrained value -(0.1 - f_1)/2 = -0.3 is below -0.25, so it sits at its lower bound,
 * with gradients (-0.5 + 0.25 + 0.7, 0.5 - 0.5 + 0.1) >= 0. The paper's partition gives
 * f_2 = +0.2 here. */
START_TEST(reference_edge_with_saturated_partner)
{
    contact_case c = two_block(0.02 * (1.0 - 1e-9), 0.0, -0.3, 0.1);
    double f[2];
    reference_forces(&c, FRICREG_LAW_QUINN, f);
    expect_forces(f, -0.5, -0.25, 1e-15);
}
END_TEST

/* Saturation consistency at rest, a_free = (0.4, -0.1): the unconstrained -W^-1 a = (-0.7, -0.3)
 * leaves the box in both coordinates. With f_1 = -0.5 at its bound, f_2 = -(b_2 + W_21 f_1) / W_22
 * = -(-0.1 + 0.5)/2 = -0.2 is inside, and contact 1's gradient -0.5 + 0.2 + 0.4 = 0.1 >= 0: the
 * KKT point is (-0.5, -0.2). (The paper's partition gives law (4) at f_eq = (-0.7, -0.3):
 * (-0.5, -0.25), contact 2 saturated although it holds.) */
START_TEST(reference_one_saturated_one_holding)
{
    contact_case c = two_block(0.0, 0.0, 0.4, -0.1);
    double f[2];
    reference_forces(&c, FRICREG_LAW_QUINN, f);
    expect_forces(f, -0.5, -0.2, 1e-15);
}
END_TEST

/* Inside the band, zdot = (0.006, -0.004), a_free = (0.1, 0.1): c = (0.6, -0.4),
 * b = a_free + W_ii c_i mun_i = (0.1 + 0.3, 0.1 - 0.2) = (0.4, -0.1), box [-0.5, 0.2] x
 * [-0.15, 0.25]. Unconstrained -W^-1 b = -(0.7, 0.3) violates both lower bounds; f_1 = -0.5 with
 * f_2 free gives f_2 = -(-0.1 + 0.5)/2 = -0.2 < -0.15, so f_2 = -0.15 as well; gradients
 * (-0.5 + 0.15 + 0.4, 0.5 - 0.3 - 0.1) = (0.05, 0.1) >= 0: both at their lower bounds. */
START_TEST(reference_moving_both_at_lower_bounds)
{
    contact_case c = two_block(0.006, -0.004, 0.1, 0.1);
    double f[2];
    reference_forces(&c, FRICREG_LAW_QUINN, f);
    expect_forces(f, -0.5, -0.15, 1e-15);
}
END_TEST

/* Karnopp, zdot = (0.01, 0.03): contact 2 slides (f_2 = -0.25), contact 1 holds with c = 0:
 * b_1 = a_1 + W_12 f_2 = 0.2 + 0.25 = 0.45 gives f_1 = -0.45, inside [-0.5, 0.5]. */
START_TEST(reference_karnopp_slip_force_moves_into_b)
{
    contact_case c = two_block(0.01, 0.03, 0.2, 0.1);
    double f[2];
    reference_forces(&c, FRICREG_LAW_KARNOPP, f);
    expect_forces(f, -0.45, -0.25, 1e-15);
}
END_TEST

/* m = 3, W = diag(2, 3, 4) + 0.5 (J - I) (J all ones), every contact at rest with a large
 * a_free: the unconstrained force -W^-1 a is far outside the box, so all three saturate against
 * a_free: f = -mun sgn(a) = (-1.5, 0.75, -0.2); each gradient (W f + a)_i points the way its
 * bound requires, e.g. g_1 = -3 + 0.375 - 0.1 + 40 > 0. */
START_TEST(reference_all_saturated)
{
    contact_case c = {.m = 3,
                      .W = {2.0, 0.5, 0.5, 0.5, 3.0, 0.5, 0.5, 0.5, 4.0},
                      .mun = {1.5, 0.75, 0.2},
                      .eps = 0.05,
                      .zdot = {0.0, 0.0, 0.0},
                      .a_free = {40.0, -30.0, 20.0}};
    double f[3];
    reference_forces(&c, FRICREG_LAW_QUINN, f);
    ck_assert_double_eq_tol(f[0], -1.5, 1e-15);
    ck_assert_double_eq_tol(f[1], 0.75, 1e-15);
    ck_assert_double_eq_tol(f[2], -0.2, 1e-15);
}
END_TEST

/* 1/2 f^T W f + b^T f on S. */
static double objective(const box_qp *qp, const double f[])
{
    double q = 0.0;
    for (size_t a = 0; a < qp->s; a++) {
        double wf = 0.0;
        for (size_t e = 0; e < qp->s; e++)
            wf += qp->W[a * qp->s + e] * f[e];
        q += f[a] * (0.5 * wf + qp->b[a]);
    }
    return q;
}

/* The reference on random cases: a KKT point exists and is unique (brute_force asserts both),
 * it lies in the box, and no random point of the box has a smaller objective. */
START_TEST(reference_is_the_box_minimizer)
{
    rng_state = 0x5eed0001u;
    for (int n = 0; n < 300; n++) {
        contact_case c;
        random_case(&c, uniform_size(2, 6));
        box_qp qp;
        double f[MMAX], f_S[MMAX];
        build_qp(&c, FRICREG_LAW_QUINN, &qp, f);
        brute_force(&qp, f_S);
        for (size_t a = 0; a < qp.s; a++)
            ck_assert(f_S[a] >= qp.l[a] - 1e-14 && f_S[a] <= qp.u[a] + 1e-14);
        double best = objective(&qp, f_S);
        for (int k = 0; k < 50; k++) {
            double g[MMAX];
            for (size_t a = 0; a < qp.s; a++)
                g[a] = uniform(qp.l[a], qp.u[a]);
            ck_assert_msg(objective(&qp, g) >= best - 1e-12 * (1.0 + fabs(best)),
                          "case %d: a box point beats the reference", n);
        }
    }
}
END_TEST

/* ---- The library ------------------------------------------------------------------------- */

static fricreg_ctx *make_ctx(const contact_case *c, int law, int partition)
{
    fricreg_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_ctx_create(c->m, &ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, c->m, c->W), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, c->m, c->mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, law, c->eps), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_partition(ctx, partition), FRICREG_OK);
    return ctx;
}

static void eval(fricreg_ctx *ctx, size_t m, const double zdot[], const double a_free[], double f[],
                 double f_eq[])
{
    int status = fricreg_ctx_eval(ctx, m, zdot, a_free, f, f_eq);
    QUIET_ASSERT(status == FRICREG_OK, "eval: %s", fricreg_ctx_errmsg(ctx));
}

/* ---- 1. The library against brute force -------------------------------------------------- */

/* Thousands of random cases, m = 2..8, law (4) mostly, Karnopp and force balance too: f to
 * 1e-12 of max mun; f_eq,i = -(a_free,i + sum_{j != i} W_ij f_j) / W_ii on S (the spec's
 * definition, from the reference's forces), NaN elsewhere. A fresh context per case: no warm
 * start (warm_started_walk_matches_brute_force has them). */
START_TEST(consistent_law_matches_brute_force)
{
    static const int laws[4] = {FRICREG_LAW_QUINN, FRICREG_LAW_QUINN, FRICREG_LAW_KARNOPP,
                                FRICREG_LAW_FORCE_BALANCE};
    rng_state = 0x5eed0002u;
    double worst = 0.0, worst_feq = 0.0;
    long assignments = 0, near_stick_contacts = 0;
    size_t largest_s = 0;
    int n_cases = 3000;
    for (int n = 0; n < n_cases; n++) {
        contact_case c;
        random_case(&c, uniform_size(2, MMAX));
        int law = laws[n % 4];
        if (n % 5 == 0) /* every contact near stick: s = m, up to 3^8 assignments */
            for (size_t i = 0; i < c.m; i++)
                c.zdot[i] = law == FRICREG_LAW_FORCE_BALANCE ? 0.0 : uniform(-0.9, 0.9) * c.eps;
        fricreg_ctx *ctx = make_ctx(&c, law, FRICREG_PARTITION_CONSISTENT);
        box_qp qp;
        double f_ref[MMAX], f_S[MMAX], f[MMAX], f_eq[MMAX];
        build_qp(&c, law, &qp, f_ref);
        assignments += brute_force(&qp, f_S);
        for (size_t a = 0; a < qp.s; a++)
            f_ref[qp.idx[a]] = f_S[a];
        near_stick_contacts += (long)qp.s;
        largest_s = qp.s > largest_s ? qp.s : largest_s;
        eval(ctx, c.m, c.zdot, c.a_free, f, f_eq);
        double scale = max_of(c.mun, c.m);
        for (size_t i = 0; i < c.m; i++) {
            double err = fabs(f[i] - f_ref[i]) / (scale > 0.0 ? scale : 1.0);
            worst = fmax(worst, err);
            ck_assert_msg(err <= 1e-12, "case %d (law %d, m %zu): f[%zu] = %.17g, reference %.17g",
                          n, law, c.m, i, f[i], f_ref[i]);
            if (!near_stick(law, c.zdot[i], c.eps)) {
                ck_assert_msg(isnan(f_eq[i]), "case %d: f_eq[%zu] = %g off S", n, i, f_eq[i]);
                continue;
            }
            double others = c.a_free[i];
            for (size_t j = 0; j < c.m; j++)
                others += j == i ? 0.0 : c.W[i * c.m + j] * f_ref[j];
            double expected = -others / c.W[i * c.m + i];
            double err_feq = fabs(f_eq[i] - expected) / (scale + fabs(expected));
            worst_feq = fmax(worst_feq, err_feq);
            ck_assert_msg(err_feq <= 1e-11, "case %d: f_eq[%zu] = %.17g, expected %.17g", n, i,
                          f_eq[i], expected);
        }
        fricreg_ctx_free(ctx);
    }
    printf("brute force: %d cases, %ld near-stick contacts (s up to %zu), %ld assignments; "
           "largest |f - f_ref| / max mun %.3g, f_eq %.3g\n",
           n_cases, near_stick_contacts, largest_s, assignments, worst, worst_feq);
    fflush(stdout); /* Check forks: the child may _exit before stdio flushes */
    ck_assert_uint_eq(largest_s, MMAX);
}
END_TEST

/* The same contexts reused along a random walk of states: each evaluation starts from the
 * previous call's active set (the warm start), which must not change the answer. */
START_TEST(warm_started_walk_matches_brute_force)
{
    rng_state = 0x5eed0003u;
    for (int n = 0; n < 40; n++) {
        contact_case c;
        random_case(&c, uniform_size(2, MMAX));
        fricreg_ctx *ctx = make_ctx(&c, FRICREG_LAW_QUINN, FRICREG_PARTITION_CONSISTENT);
        for (int step = 0; step < 25; step++) {
            size_t j = uniform_size(0, c.m - 1);
            c.a_free[j] += uniform(-0.3, 0.3) * c.W[j * c.m + j] * (c.mun[j] + 0.1);
            c.zdot[j] = fmax(-1.5 * c.eps,
                             fmin(1.5 * c.eps, c.zdot[j] + uniform(-0.3, 0.3) * c.eps));
            double f_ref[MMAX], f[MMAX];
            reference_forces(&c, FRICREG_LAW_QUINN, f_ref);
            eval(ctx, c.m, c.zdot, c.a_free, f, NULL);
            double scale = fmax(max_of(c.mun, c.m), 1e-300);
            for (size_t i = 0; i < c.m; i++)
                ck_assert_msg(fabs(f[i] - f_ref[i]) <= 1e-12 * scale,
                              "walk %d step %d: f[%zu] = %.17g, reference %.17g", n, step, i, f[i],
                              f_ref[i]);
        }
        fricreg_ctx_free(ctx);
    }
}
END_TEST

/* docs/coupled.md's two-block cases through the library: the consistent law gives the hand-solved
 * values of the reference tests on both sides of each band edge. */
START_TEST(two_block_band_edge_cases)
{
    const double eps = 0.02, in = 1.0 - 1e-9, out = 1.0 + 1e-9;
    struct {
        double z1, z2, a1, a2, f1, f2;
    } rows[] = {
        {0.0, eps * in, 0.1, 0.1, -0.35, -0.25}, {0.0, eps * out, 0.1, 0.1, -0.35, -0.25},
        {eps * in, 0.0, -0.3, 0.1, -0.5, -0.25}, {eps * out, 0.0, -0.3, 0.1, -0.5, -0.25},
        {0.0, 0.0, 0.1, 0.1, -0.3, -0.2},        {0.0, 0.0, 0.4, -0.1, -0.5, -0.2},
        {0.006, -0.004, 0.1, 0.1, -0.5, -0.15},
    };
    for (size_t r = 0; r < sizeof rows / sizeof rows[0]; r++) {
        contact_case c = two_block(rows[r].z1, rows[r].z2, rows[r].a1, rows[r].a2);
        fricreg_ctx *ctx = make_ctx(&c, FRICREG_LAW_QUINN, FRICREG_PARTITION_CONSISTENT);
        double f[2];
        eval(ctx, 2, c.zdot, c.a_free, f, NULL);
        ck_assert_msg(fabs(f[0] - rows[r].f1) <= 1e-9 && fabs(f[1] - rows[r].f2) <= 1e-9,
                      "row %zu: f = (%.17g, %.17g), expected (%g, %g)", r, f[0], f[1], rows[r].f1,
                      rows[r].f2);
        fricreg_ctx_free(ctx);
    }
}
END_TEST

/* ---- 2. Continuity across every band edge and every saturation edge ---------------------- */

/* The jump of f at x along one input (zdot_j or a_free_j), free of f's slope: f is piecewise
 * affine in each input (a parametric QP with the parameter in b, l and u), so with
 * D(p, q) = f(q) - f(p), D(x-d, x+d) - (D(x+d, x+3d) + D(x-3d, x-d))/2 is zero to rounding on
 * each side's affine piece with one kink at x, and equals the jump if f jumps at x. Returns
 * max_i of its modulus. */
static double jump_at(fricreg_ctx *ctx, const contact_case *c, int along_zdot, size_t j, double x,
                      double d)
{
    double zdot[MMAX], a[MMAX], f[4][MMAX], jump = 0.0;
    static const double at[4] = {-3.0, -1.0, 1.0, 3.0};
    memcpy(zdot, c->zdot, c->m * sizeof *zdot);
    memcpy(a, c->a_free, c->m * sizeof *a);
    for (int k = 0; k < 4; k++) {
        (along_zdot ? zdot : a)[j] = x + at[k] * d;
        eval(ctx, c->m, zdot, a, f[k], NULL);
    }
    for (size_t i = 0; i < c->m; i++) {
        double centre = f[2][i] - f[1][i];
        double sides = 0.5 * ((f[3][i] - f[2][i]) + (f[1][i] - f[0][i]));
        jump = fmax(jump, fabs(centre - sides));
    }
    return jump;
}

/* f_eq,j of the context at a_free_j = x (NaN if j is not near-stick). */
static double feq_at(fricreg_ctx *ctx, const contact_case *c, size_t j, double x)
{
    double a[MMAX], f[MMAX], f_eq[MMAX];
    memcpy(a, c->a_free, c->m * sizeof *a);
    a[j] = x;
    eval(ctx, c->m, c->zdot, a, f, f_eq);
    return f_eq[j];
}

/* Bisection for a_free_j where the context's f_eq,j crosses `level` (= +-mun_j), between lo
 * and hi, whose f_eq,j - level have opposite signs. Returns 0 if they do not. */
static int saturation_edge(fricreg_ctx *ctx, const contact_case *c, size_t j, double level,
                           double lo, double hi, double *edge)
{
    double g_lo = feq_at(ctx, c, j, lo) - level, g_hi = feq_at(ctx, c, j, hi) - level;
    if (!(g_lo * g_hi < 0.0))
        return 0;
    for (int it = 0; it < 200 && hi - lo > 1e-15 * fmax(fabs(lo), fabs(hi)); it++) {
        double mid = 0.5 * (lo + hi), g = feq_at(ctx, c, j, mid) - level;
        if ((g < 0.0) == (g_lo < 0.0))
            lo = mid, g_lo = g;
        else
            hi = mid;
    }
    *edge = 0.5 * (lo + hi);
    return 1;
}

typedef struct {
    double band, saturation; /* largest jump / max mun found at each kind of edge */
    long n_band, n_saturation;
} jumps;

/* Sweep every edge of contact j of case c, law (4), in the given context. */
static void sweep_contact(fricreg_ctx *ctx, const contact_case *c, size_t j, jumps *out)
{
    double scale = fmax(max_of(c->mun, c->m), 1e-300);
    for (int side = -1; side <= 1; side += 2) { /* zdot_j = -eps, +eps, from (1 -+ 1e-9) eps */
        double jump = jump_at(ctx, c, 1, j, side * c->eps, 1e-9 * c->eps) / scale;
        out->band = fmax(out->band, jump);
        out->n_band++;
    }
    if (!(fabs(c->zdot[j]) < c->eps) || c->mun[j] == 0.0)
        return;
    /* |a_free_j| beyond W_jj mun_j + sum_k |W_jk| mun_k saturates f_eq,j under the consistent
     * law whatever the others do: the bracket of both crossings. */
    double reach = 0.0;
    for (size_t k = 0; k < c->m; k++)
        reach += fabs(c->W[j * c->m + k]) * c->mun[k];
    double big = 4.0 * (reach + c->W[j * c->m + j] * c->mun[j]);
    for (int side = -1; side <= 1; side += 2) {
        double edge;
        if (!saturation_edge(ctx, c, j, side * c->mun[j], -big, big, &edge))
            continue;
        double jump = jump_at(ctx, c, 0, j, edge, 1e-9 * fmax(fabs(edge), big * 1e-3)) / scale;
        out->saturation = fmax(out->saturation, jump);
        out->n_saturation++;
    }
}

/* Random SPD W, m = 2..8, random states: the consistent law's largest jump across every
 * |zdot_j| = eps and every |f_eq,j| = mun_j is <= 1e-12 max mun; the paper's partition, for
 * comparison, jumps by more than 0.1 mun somewhere (docs/coupled.md: up to 1.8 mun). */
START_TEST(consistent_law_is_continuous_across_every_edge)
{
    rng_state = 0x5eed0004u;
    jumps consistent = {0}, paper = {0};
    for (int n = 0; n < 400; n++) {
        contact_case c;
        random_case(&c, uniform_size(2, MMAX));
        fricreg_ctx *cons = make_ctx(&c, FRICREG_LAW_QUINN, FRICREG_PARTITION_CONSISTENT);
        fricreg_ctx *pap = make_ctx(&c, FRICREG_LAW_QUINN, FRICREG_PARTITION_PAPER);
        for (size_t j = 0; j < c.m; j++) {
            sweep_contact(cons, &c, j, &consistent);
            sweep_contact(pap, &c, j, &paper);
        }
        fricreg_ctx_free(cons);
        fricreg_ctx_free(pap);
    }
    printf("largest jump / max mun: consistent %.3g at %ld band edges, %.3g at %ld saturation "
           "edges; paper %.3g (band), %.3g (saturation)\n",
           consistent.band, consistent.n_band, consistent.saturation, consistent.n_saturation,
           paper.band, paper.saturation);
    fflush(stdout); /* Check forks: the child may _exit before stdio flushes */
    ck_assert_int_gt(consistent.n_saturation, 1000);
    ck_assert_msg(consistent.band <= 1e-12, "band-edge jump %.3g max mun", consistent.band);
    ck_assert_msg(consistent.saturation <= 1e-12, "saturation-edge jump %.3g max mun",
                  consistent.saturation);
    ck_assert_msg(paper.band > 0.1, "the paper's partition did not jump: %.3g", paper.band);
}
END_TEST

/* f and f_eq of case c with mun_j replaced by x (the context's bounds are set to it). */
static void eval_with_bound(fricreg_ctx *ctx, const contact_case *c, size_t j, double x, double f[],
                            double f_eq[])
{
    double mun[MMAX];
    memcpy(mun, c->mun, c->m * sizeof *mun);
    mun[j] = x;
    QUIET_OK(fricreg_ctx_set_bounds(ctx, c->m, mun));
    eval(ctx, c->m, c->zdot, c->a_free, f, f_eq);
}

/* The bound mun_j in (0, hi) where |f_eq,j| = mun_j (contact j starts to saturate), by
 * bisection: near 0 the bound is below |f_eq,j|; at hi (beyond what the others can push,
 * (|a_free,j| + sum_{k != j} |W_jk| mun_k) / W_jj) it is above. Returns 0 if not bracketed. */
static int bound_edge(fricreg_ctx *ctx, const contact_case *c, size_t j, double hi, double *edge)
{
    double f[MMAX], f_eq[MMAX], lo = 1e-9 * hi;
    eval_with_bound(ctx, c, j, lo, f, f_eq);
    if (!(fabs(f_eq[j]) > lo))
        return 0;
    for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; it++) {
        double mid = 0.5 * (lo + hi);
        eval_with_bound(ctx, c, j, mid, f, f_eq);
        if (fabs(f_eq[j]) > mid)
            lo = mid;
        else
            hi = mid;
    }
    *edge = 0.5 * (lo + hi);
    return 1;
}

/* The slope-free jump of jump_at, along mun_j. */
static double jump_along_bound(fricreg_ctx *ctx, const contact_case *c, size_t j, double x,
                               double d)
{
    static const double at[4] = {-3.0, -1.0, 1.0, 3.0};
    double f[4][MMAX], f_eq[MMAX], jump = 0.0;
    for (int k = 0; k < 4; k++)
        eval_with_bound(ctx, c, j, x + at[k] * d, f[k], f_eq);
    for (size_t i = 0; i < c->m; i++)
        jump = fmax(jump,
                    fabs((f[2][i] - f[1][i]) - 0.5 * ((f[3][i] - f[2][i]) + (f[1][i] - f[0][i]))));
    return jump;
}

/* fricreg.h: the consistent law is continuous in mun too. Random cases as above, every
 * near-stick contact's saturation edge along its own bound: no jump beyond rounding. */
START_TEST(consistent_law_is_continuous_in_the_bounds)
{
    rng_state = 0x5eed0007u;
    double worst = 0.0;
    long edges = 0;
    for (int n = 0; n < 300; n++) {
        contact_case c;
        random_case(&c, uniform_size(2, MMAX));
        fricreg_ctx *ctx = make_ctx(&c, FRICREG_LAW_QUINN, FRICREG_PARTITION_CONSISTENT);
        for (size_t j = 0; j < c.m; j++) {
            if (!(fabs(c.zdot[j]) < c.eps))
                continue;
            double reach = fabs(c.a_free[j]), edge;
            for (size_t k = 0; k < c.m; k++)
                reach += k == j ? 0.0 : fabs(c.W[j * c.m + k]) * c.mun[k];
            if (!bound_edge(ctx, &c, j, 2.0 * reach / c.W[j * c.m + j] + 1.0, &edge))
                continue;
            double scale = fmax(max_of(c.mun, c.m), edge);
            worst = fmax(worst, jump_along_bound(ctx, &c, j, edge, 1e-9 * edge) / scale);
            edges++;
        }
        fricreg_ctx_free(ctx);
    }
    printf("largest jump / max mun along mun_j at %ld saturation edges: %.3g\n", edges, worst);
    fflush(stdout); /* Check forks: the child may _exit before stdio flushes */
    ck_assert_int_gt(edges, 300);
    ck_assert_msg(worst <= 1e-12, "jump %.3g max mun along a bound", worst);
}
END_TEST

/* The paper's partition's jumps of docs/coupled.md, as the detector sees them: f_1
 * -0.30 -> -0.35 (0.05 = 0.1 max mun) and f_2 +0.2 -> -0.25 (0.45 = 0.9 max mun, 1.8 mun_2). */
START_TEST(paper_partition_jumps_as_measured)
{
    contact_case c = two_block(0.0, 0.0, 0.1, 0.1);
    fricreg_ctx *ctx = make_ctx(&c, FRICREG_LAW_QUINN, FRICREG_PARTITION_PAPER);
    ck_assert_double_eq_tol(jump_at(ctx, &c, 1, 1, 0.02, 1e-9 * 0.02), 0.05, 1e-9);
    c = two_block(0.0, 0.0, -0.3, 0.1);
    ck_assert_double_eq_tol(jump_at(ctx, &c, 1, 0, 0.02, 1e-9 * 0.02), 0.45, 1e-9);
    fricreg_ctx_free(ctx);
}
END_TEST

/* The accuracy promise of fricreg_ctx_eval in acceleration units (a fuzz finding,
 * tests/fuzz/regressions/ctx/consistent_subnormal_w_underflow, had W = [5e-324], which
 * set_coupling_dense now refuses: below DBL_MIN): with a 1x1 dense W the QP is law (4) at
 * f_eq = -a_free/W, to rounding while W c mun is a normal double far above 1e-292 (W = 1e-280,
 * mun = 1: 8 ulp of mun, as in the diagonal test below); at W = 1e-300, mun = 1e-20, the term
 * W c mun = 7.8e-322 is subnormal (a few bits) and the force may be anything in the box, but it
 * must still be finite, in the box, and move the contact by less than 1e-292, as the header
 * says. */
START_TEST(tiny_mobility_keeps_its_acceleration_to_1e_292)
{
    static const double mobilities[2] = {1e-280, 1e-300}, bounds[2] = {1.0, 1e-20};
    const double eps = 0.001, zdot = 3.90625e-5, a_free = 0.0, subnormal = 4.9406564584124654e-324;
    for (int k = 0; k < 2; k++) {
        fricreg_ctx *ctx = NULL;
        double f = NAN, law4 = NAN;
        ck_assert_int_eq(fricreg_law_eval(FRICREG_LAW_QUINN, zdot, 0.0, bounds[k], eps, &law4),
                         FRICREG_OK);
        ck_assert_double_eq_tol(law4, -0.078125 * bounds[k], 1e-15 * bounds[k]); /* -c mun */
        ck_assert_int_eq(fricreg_ctx_create(1, &ctx), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, eps), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, 1, &bounds[k]), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 1, &subnormal), FRICREG_ENOTPSD);
        ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 1, &mobilities[k]), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_eval(ctx, 1, &zdot, &a_free, &f, NULL), FRICREG_OK);
        ck_assert(isfinite(f) && fabs(f) <= bounds[k]);
        if (k == 0)
            ck_assert_double_eq_tol(f, law4, 8 * DBL_EPSILON);
        else
            ck_assert(fabs(mobilities[k] * (f - law4)) < DBL_MIN / DBL_EPSILON);
        fricreg_ctx_free(ctx);
    }
}
END_TEST

/* A contact that enters S from slipping, deep in the band, is warm-started on the side of its
 * own row's minimizer, here inside its box: the QP takes one iteration, where the bound of its
 * slip side took two (hold, then release: box_qp.c). W = [[1, 0.1], [0.1, 1]], mun = (1, 1),
 * eps = 0.02, a_free = (0.1, 0); both slipping at zdot = (0.5, 0.5), then zdot_0 = 0.001
 * (c_0 = 2 zdot_0/eps = 0.1, box [-1, 0.9]) with contact 1 still sliding, f_1 = -1:
 * b_0 = a_free_0 + W_00 c_0 mun_0 + W_01 f_1 = 0.1, so f_0 = -b_0/W_00 = -0.1, free. */
START_TEST(entering_contact_warm_starts_inside_its_box)
{
    static const double W[4] = {1.0, 0.1, 0.1, 1.0}, mun[2] = {1.0, 1.0};
    const double a_free[2] = {0.1, 0.0}, slipping[2] = {0.5, 0.5}, entering[2] = {0.001, 0.5};
    fricreg_ctx *ctx = NULL;
    double f[2];
    int64_t iterations = -1;
    ck_assert_int_eq(fricreg_ctx_create(2, &ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, W), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, 2, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 0.02), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, slipping, a_free, f, NULL), FRICREG_OK);
    fricreg_ctx_reset_stats(ctx);
    ck_assert_int_eq(fricreg_ctx_eval(ctx, 2, entering, a_free, f, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_get_stat(ctx, FRICREG_STAT_QP_ITERATIONS, &iterations),
                     FRICREG_OK);
    ck_assert_int_eq(iterations, 1);
    ck_assert_double_eq_tol(f[0], -0.1, 1e-15);
    ck_assert_double_eq(f[1], -1.0);
    fricreg_ctx_free(ctx);
}
END_TEST

/* ---- 3. Diagonal W: law (4) contact by contact -------------------------------------------- */

/* With W = diag(w) the QP separates, so the consistent law is law (4) at f_eq,i = -a_free,i/w_i:
 * fricreg_law_eval(QUINN, ...) to rounding (8 ulp of mun_i + |f_eq,i|, the size of the terms
 * that cancel in f_eq,i - c_i mun_i), through set_coupling_diagonal and
 * through a dense matrix that happens to be diagonal, under either partition. Karnopp too. */
START_TEST(diagonal_w_is_law_4_contact_by_contact)
{
    static const int laws[2] = {FRICREG_LAW_QUINN, FRICREG_LAW_KARNOPP};
    rng_state = 0x5eed0005u;
    double worst = 0.0;
    for (int n = 0; n < 1000; n++) {
        contact_case c;
        random_case(&c, uniform_size(2, MMAX));
        double w[MMAX];
        memset(c.W, 0, sizeof c.W);
        for (size_t i = 0; i < c.m; i++) {
            w[i] = uniform(0.2, 5.0);
            c.W[i * c.m + i] = w[i];
            c.a_free[i] = uniform(-2.0, 2.0) * w[i] * (c.mun[i] + 0.1);
        }
        int law = laws[n % 2];
        fricreg_ctx *dense = make_ctx(&c, law, FRICREG_PARTITION_CONSISTENT);
        fricreg_ctx *paper = make_ctx(&c, law, FRICREG_PARTITION_PAPER);
        fricreg_ctx *diag = make_ctx(&c, law, FRICREG_PARTITION_CONSISTENT);
        ck_assert_int_eq(fricreg_ctx_set_coupling_diagonal(diag, c.m, w), FRICREG_OK);
        fricreg_ctx *ctxs[3] = {dense, paper, diag};
        for (int k = 0; k < 3; k++) {
            double f[MMAX];
            eval(ctxs[k], c.m, c.zdot, c.a_free, f, NULL);
            for (size_t i = 0; i < c.m; i++) {
                double expected;
                ck_assert_int_eq(fricreg_law_eval(law, c.zdot[i], -c.a_free[i] / w[i], c.mun[i],
                                                  c.eps, &expected),
                                 FRICREG_OK);
                double err = fabs(f[i] - expected);
                double size = c.mun[i] + fabs(c.a_free[i] / w[i]);
                worst = fmax(worst, err / size);
                ck_assert_msg(err <= 8.0 * DBL_EPSILON * size,
                              "case %d ctx %d law %d: f[%zu] = %.17g, law %.17g", n, k, law, i,
                              f[i], expected);
            }
        }
        fricreg_ctx_free(dense);
        fricreg_ctx_free(paper);
        fricreg_ctx_free(diag);
    }
    printf("diagonal W: largest |f - law| / (mun + |f_eq|) %.3g\n", worst);
    fflush(stdout); /* Check forks: the child may _exit before stdio flushes */
}
END_TEST

/* ---- 4. The tangent ----------------------------------------------------------------------- */

/* The tangent of the last evaluation against central differences of fricreg_ctx_eval, column
 * by column: column j of df/dzdot with step h = 1e-6 eps, of df/da_free with h = 1e-6 (W_jj mun_j
 * + 0.1). Every law but tanh is piecewise affine in each input, so where no kink lies within h
 * the four differences over h from x - 2h to x + 2h agree to rounding (~1e-8 of the scale); a
 * column where they differ by more than 1e-7 of the scale straddles a kink or a jump (band
 * edge, bound, active-set change, Coulomb's v = 0) and is skipped. tanh is smooth: its central difference is O(h^2). The
 * tangent must match to 1e-6 of the scale: the largest entry of the difference matrix, at least
 * max mun / eps (df/dzdot) or 1 / max W_jj (df/da_free), so that a zero matrix is compared too.
 * Returns the number of columns compared; *worst gets the largest scaled error. */
static int check_tangent(fricreg_ctx *ctx, const contact_case *c, int law, double *worst,
                         int *skipped)
{
    size_t m = c->m;
    double T[2][MMAX * MMAX], D[2][MMAX * MMAX], f0[MMAX], floor_scale[2] = {0.0, 0.0};
    int ok[2][MMAX], compared = 0;
    eval(ctx, m, c->zdot, c->a_free, f0, NULL);
    ck_assert_int_eq(fricreg_ctx_tangent(ctx, m, T[0], T[1]), FRICREG_OK);
    for (size_t j = 0; j < m; j++) {
        floor_scale[0] = fmax(floor_scale[0], c->mun[j] / c->eps);
        floor_scale[1] = fmax(floor_scale[1], 1.0 / c->W[j * m + j]);
    }
    for (int which = 0; which < 2; which++) {
        double scale = floor_scale[which];
        for (size_t j = 0; j < m; j++) {
            double zdot[MMAX], a[MMAX], fp[MMAX], fm[MMAX], fpp[MMAX], fmm[MMAX];
            double *x = which == 0 ? zdot : a;
            double h = which == 0 ? 1e-6 * c->eps : 1e-6 * (c->W[j * m + j] * c->mun[j] + 0.1);
            memcpy(zdot, c->zdot, m * sizeof *zdot);
            memcpy(a, c->a_free, m * sizeof *a);
            double x0 = x[j];
            const double offsets[4] = {h, -h, 2.0 * h, -2.0 * h};
            double *outs[4] = {fp, fm, fpp, fmm};
            for (int k = 0; k < 4; k++) {
                x[j] = x0 + offsets[k];
                eval(ctx, m, zdot, a, outs[k], NULL);
            }
            /* the four steps from x - 2h to x + 2h are equal on one affine piece; a jump at x
             * (Coulomb at v = 0) keeps the two middle ones equal but not the outer ones */
            double kink = 0.0;
            for (size_t i = 0; i < m; i++) {
                double steps[4] = {fmm[i] - fm[i], fm[i] - f0[i], f0[i] - fp[i], fp[i] - fpp[i]};
                for (int k = 1; k < 4; k++)
                    kink = fmax(kink, fabs(steps[k] - steps[0]) / h);
                D[which][i * m + j] = (fp[i] - fm[i]) / (2.0 * h);
                scale = fmax(scale, fabs(D[which][i * m + j]));
            }
            ok[which][j] = law == FRICREG_LAW_TANH || kink <= 1e-7 * floor_scale[which];
        }
        for (size_t j = 0; j < m; j++) {
            if (!ok[which][j]) {
                (*skipped)++;
                continue;
            }
            compared++;
            for (size_t i = 0; i < m; i++) {
                double diff = fabs(T[which][i * m + j] - D[which][i * m + j]);
                double err = diff == 0.0 ? 0.0 : diff / scale; /* scale 0: every mun is 0 */
                *worst = fmax(*worst, err);
                QUIET_ASSERT(err <= 1e-6,
                             "law %d, %s, m %zu: d f_%zu / d %s_%zu = %.10g, central "
                             "difference %.10g (scale %.3g)",
                             law, which == 0 ? "df_dzdot" : "df_dafree", m, i,
                             which == 0 ? "zdot" : "a_free", j, T[which][i * m + j],
                             D[which][i * m + j], scale);
            }
        }
    }
    return compared;
}

/* Every law, both partitions, random dense SPD W (m = 2..6) and the diagonal W: the tangent
 * matches central differences away from kinks, and most columns are away from kinks. */
START_TEST(tangent_matches_central_differences)
{
    static const int laws[6] = {
        FRICREG_LAW_QUINN,   FRICREG_LAW_KARNOPP,          FRICREG_LAW_FORCE_BALANCE,
        FRICREG_LAW_COULOMB, FRICREG_LAW_VELOCITY_LIMITED, FRICREG_LAW_TANH};
    static const int partitions[2] = {FRICREG_PARTITION_CONSISTENT, FRICREG_PARTITION_PAPER};
    rng_state = 0x5eed0006u;
    for (int l = 0; l < 6; l++)
        for (int p = 0; p < 2; p++) {
            double worst = 0.0;
            int compared = 0, skipped = 0;
            for (int n = 0; n < 150; n++) {
                contact_case c;
                random_case(&c, uniform_size(2, 6));
                fricreg_ctx *ctx = make_ctx(&c, laws[l], partitions[p]);
                if (n % 5 == 0) { /* the diagonal W's own path */
                    double w[MMAX];
                    for (size_t i = 0; i < c.m; i++)
                        w[i] = c.W[i * c.m + i];
                    memset(c.W, 0, sizeof c.W);
                    for (size_t i = 0; i < c.m; i++)
                        c.W[i * c.m + i] = w[i];
                    ck_assert_int_eq(fricreg_ctx_set_coupling_diagonal(ctx, c.m, w), FRICREG_OK);
                }
                compared += check_tangent(ctx, &c, laws[l], &worst, &skipped);
                fricreg_ctx_free(ctx);
            }
            printf("tangent, law %d, partition %d: %d columns compared, %d skipped at kinks, "
                   "largest error %.3g of scale\n",
                   laws[l], partitions[p], compared, skipped, worst);
            fflush(stdout);
            ck_assert_int_gt(compared, 3 * skipped);
        }
}
END_TEST

/* Closed forms on the two blocks at rest, a_free = (0.1, 0.1) (all interior, see
 * reference_interior_at_rest). Consistent: f = -W^-1 (a_free + diag(W_ii 2 mun_i / eps) zdot),
 * so df/da_free = -W^-1 = -[[2, 1], [1, 1]] and df/dzdot = -W^-1 diag(1 * 50, 2 * 25)
 * = -[[100, 50], [50, 50]]. Paper's partition: f = f_eq - diag(2 mun / eps) zdot with
 * f_eq = -W^-1 a_free: df/da_free = -W^-1 again, df/dzdot = -diag(50, 25). */
START_TEST(tangent_closed_form_two_blocks)
{
    contact_case c = two_block(0.0, 0.0, 0.1, 0.1);
    static const double dfda[4] = {-2.0, -1.0, -1.0, -1.0};
    static const double dfdz_consistent[4] = {-100.0, -50.0, -50.0, -50.0};
    static const double dfdz_paper[4] = {-50.0, 0.0, 0.0, -25.0};
    const int partitions[2] = {FRICREG_PARTITION_CONSISTENT, FRICREG_PARTITION_PAPER};
    const double *dfdz[2] = {dfdz_consistent, dfdz_paper};
    for (int p = 0; p < 2; p++) {
        fricreg_ctx *ctx = make_ctx(&c, FRICREG_LAW_QUINN, partitions[p]);
        double f[2], Tz[4], Ta[4];
        eval(ctx, 2, c.zdot, c.a_free, f, NULL);
        ck_assert_int_eq(fricreg_ctx_tangent(ctx, 2, Tz, Ta), FRICREG_OK);
        for (int k = 0; k < 4; k++) {
            ck_assert_double_eq_tol(Ta[k], dfda[k], 1e-12);
            ck_assert_double_eq_tol(Tz[k], dfdz[p][k], 1e-10);
        }
        fricreg_ctx_free(ctx);
    }
}
END_TEST

static void expect_tangent_failure(fricreg_ctx *ctx, size_t m, double Tz[], double Ta[], int code,
                                   const char *what)
{
    double *outs[2] = {Tz, Ta};
    for (int k = 0; k < 2; k++)
        if (outs[k] != NULL)
            for (size_t i = 0; i < m * m; i++)
                outs[k][i] = SENTINEL;
    int status = fricreg_ctx_tangent(ctx, m, Tz, Ta);
    ck_assert_msg(status == code, "%s: status %d, expected %d", what, status, code);
    if (ctx != NULL) {
        ck_assert_int_eq(fricreg_ctx_errcode(ctx), code);
        ck_assert_msg(strlen(fricreg_ctx_errmsg(ctx)) > 0, "%s: no message", what);
    }
    for (int k = 0; k < 2; k++)
        if (outs[k] != NULL)
            for (size_t i = 0; i < m * m; i++)
                ck_assert_msg(outs[k][i] == SENTINEL, "%s: output written", what);
}

/* Every error return: NULL context, both outputs NULL, a wrong m, no evaluation yet, and each
 * setter invalidating the last evaluation; one NULL output is allowed and leaves it alone. */
START_TEST(tangent_errors)
{
    contact_case c = two_block(0.0, 0.0, 0.1, 0.1);
    double Tz[9], Ta[9], f[2];
    const double w[2] = {1.0, 2.0};
    fricreg_ctx *ctx = make_ctx(&c, FRICREG_LAW_QUINN, FRICREG_PARTITION_CONSISTENT);
    expect_tangent_failure(NULL, 2, Tz, Ta, FRICREG_ENULL, "NULL context");
    expect_tangent_failure(ctx, 2, Tz, Ta, FRICREG_EINVAL, "no evaluation yet");

    eval(ctx, 2, c.zdot, c.a_free, f, NULL);
    expect_tangent_failure(ctx, 2, NULL, NULL, FRICREG_ENULL, "both outputs NULL");
    expect_tangent_failure(ctx, 3, Tz, Ta, FRICREG_ESIZE, "m = 3");
    expect_tangent_failure(ctx, 1, Tz, Ta, FRICREG_ESIZE, "m = 1");
    for (int k = 0; k < 4; k++)
        Ta[k] = SENTINEL;
    ck_assert_int_eq(fricreg_ctx_tangent(ctx, 2, Tz, NULL), FRICREG_OK);
    ck_assert_double_eq_tol(Tz[0], -100.0, 1e-10);
    ck_assert_int_eq(fricreg_ctx_tangent(ctx, 2, NULL, Ta), FRICREG_OK);
    ck_assert_double_eq_tol(Ta[0], -2.0, 1e-12);

    for (int setter = 0; setter < 5; setter++) {
        eval(ctx, 2, c.zdot, c.a_free, f, NULL);
        ck_assert_int_eq(fricreg_ctx_tangent(ctx, 2, Tz, Ta), FRICREG_OK);
        switch (setter) {
        case 0:
            ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 0.02), FRICREG_OK);
            break;
        case 1: ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, 2, c.mun), FRICREG_OK); break;
        case 2: ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, c.W), FRICREG_OK); break;
        case 3: ck_assert_int_eq(fricreg_ctx_set_coupling_diagonal(ctx, 2, w), FRICREG_OK); break;
        default:
            ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, 2, c.W), FRICREG_OK);
            eval(ctx, 2, c.zdot, c.a_free, f, NULL);
            ck_assert_int_eq(fricreg_ctx_set_partition(ctx, FRICREG_PARTITION_PAPER), FRICREG_OK);
            break;
        }
        expect_tangent_failure(ctx, 2, Tz, Ta, FRICREG_EINVAL, "after a setter");
    }
    fricreg_ctx_free(ctx);
}
END_TEST

/* Column j of the one-sided difference (f(x + side h e_j) - f(x)) / (side h) along zdot
 * (which = 0) or a_free (which = 1). */
static void one_sided(fricreg_ctx *ctx, const contact_case *c, int which, size_t j, double side,
                      double h, double col[])
{
    double zdot[MMAX], a[MMAX], f0[MMAX], f1[MMAX];
    memcpy(zdot, c->zdot, c->m * sizeof *zdot);
    memcpy(a, c->a_free, c->m * sizeof *a);
    eval(ctx, c->m, zdot, a, f0, NULL);
    (which == 0 ? zdot : a)[j] += side * h;
    eval(ctx, c->m, zdot, a, f1, NULL);
    for (size_t i = 0; i < c->m; i++)
        col[i] = (f1[i] - f0[i]) / (side * h);
}

/* On a kink the tangent is the documented one-sided Jacobian (fricreg.h): the piece on the
 * side given for each column (+1 or -1), to 1e-6; the other side differs, so each case is a
 * real kink. The two blocks, all values dyadic, so the kinks are hit exactly. */
static void expect_one_sided(const contact_case *c, const double want_dz[4],
                             const double want_da[4], const int side_dz[2], const int side_da[2],
                             const char *what)
{
    fricreg_ctx *ctx = make_ctx(c, FRICREG_LAW_QUINN, FRICREG_PARTITION_CONSISTENT);
    double f[2], T[2][4];
    const double *want[2] = {want_dz, want_da};
    const int *side[2] = {side_dz, side_da};
    const double h[2] = {1e-7 * c->eps, 1e-7};
    int kinks = 0;
    eval(ctx, 2, c->zdot, c->a_free, f, NULL);
    ck_assert_int_eq(fricreg_ctx_tangent(ctx, 2, T[0], T[1]), FRICREG_OK);
    for (int which = 0; which < 2; which++)
        for (size_t j = 0; j < 2; j++) {
            double ahead[2], behind[2];
            one_sided(ctx, c, which, j, side[which][j], h[which], ahead);
            one_sided(ctx, c, which, j, -side[which][j], h[which], behind);
            for (size_t i = 0; i < 2; i++) {
                double t = T[which][i * 2 + j], scale = which == 0 ? 50.0 : 1.0;
                ck_assert_msg(fabs(t - want[which][i * 2 + j]) <= 1e-12 * scale,
                              "%s: %s[%zu][%zu] = %.17g, expected %g", what,
                              which == 0 ? "df_dzdot" : "df_dafree", i, j, t,
                              want[which][i * 2 + j]);
                ck_assert_msg(fabs(ahead[i] - t) <= 1e-6 * scale,
                              "%s: %s[%zu][%zu] = %g, one-sided difference %g", what,
                              which == 0 ? "df_dzdot" : "df_dafree", i, j, t, ahead[i]);
                kinks += fabs(behind[i] - t) > 1e-3 * scale;
            }
        }
    ck_assert_msg(kinks > 0, "%s: not a kink", what);
    fricreg_ctx_free(ctx);
}

/* Contact 2 exactly on its upper bound with zero gradient ("held there"), away from
 * zdot = 0: eps = 2^-5, zdot = (2^-8, -2^-8), so c = (0.25, -0.25), u_2 = mun_2 = 0.25 (fixed
 * for zdot_2 < 0) and b = a_free + (W_11 c_1 mun_1, W_22 c_2 mun_2) = a_free + (0.125, -0.125).
 * f = (-0.125, 0.25) with zero gradient needs b = -W f = (0.375, -0.625): a_free = (0.25, -0.5).
 * Held: f_2 = u_2 does not move; f_1 = -(b_1 + W_12 f_2) / W_11 moves with zdot_1 at
 * -2 mun_1 / eps = -32 and with a_free_1 at -1. Every input's increase raises contact 2's
 * gradient and frees it (free piece: -W^-1 diag(32, 32) and -W^-1), so the held piece is the
 * side where each input decreases. */
START_TEST(tangent_on_a_bound_holds_the_contact)
{
    contact_case c = two_block(0.00390625, -0.00390625, 0.25, -0.5);
    c.eps = 0.03125;
    const double dz[4] = {-32.0, 0.0, 0.0, 0.0}, da[4] = {-1.0, 0.0, 0.0, 0.0};
    const int side_dz[2] = {-1, -1}, side_da[2] = {-1, -1};
    expect_one_sided(&c, dz, da, side_dz, side_da, "on the bound");
}
END_TEST

/* At zdot_1 = 0 with contact 1 held at its lower bound l_1 = -mun_1 (1 - max(-c_1, 0)):
 * (reference_one_saturated_one_holding, f = (-0.5, -0.2)). The documented side is
 * zdot_1 > 0, where l_1 = -mun_1 does not move: d f_1 / d zdot_1 = 0 (for zdot_1 < 0 it would
 * be +50); f_2 = -(b_2 + W_21 f_1) / W_22 gives -25 in zdot_2 and -1/2 in a_free_2. */
START_TEST(tangent_at_rest_takes_the_positive_side)
{
    contact_case c = two_block(0.0, 0.0, 0.4, -0.1);
    const double dz[4] = {0.0, 0.0, 0.0, -25.0}, da[4] = {0.0, 0.0, 0.0, -0.5};
    const int side_dz[2] = {1, 1}, side_da[2] = {1, 1};
    expect_one_sided(&c, dz, da, side_dz, side_da, "at rest on a bound");
}
END_TEST

/* zdot_2 = eps exactly, a_free = (0.1, -2): eval lets contact 2 slide (|zdot| < eps is
 * near-stick), f_2 = -0.25 fixed, so only f_1 = -(0.1 + 0.25) moves: -50 in zdot_1, -1 in
 * a_free_1, the piece of zdot_2 > eps. Just inside the band contact 2 sits at its upper bound
 * u_2 = mun_2 (1 - c_2) (gradient -f_1 + 2 u_2 + a_2 + 2 c_2 mun_2 = 0.35 - 0.5 - 1 < 0), so
 * there f_2 and f_1 = f_2 - 0.1 move with zdot_2 at -25: a kink in that column. */
START_TEST(tangent_at_the_band_edge_slides)
{
    contact_case c = two_block(0.0, 0.02, 0.1, -2.0);
    const double dz[4] = {-50.0, 0.0, 0.0, 0.0}, da[4] = {-1.0, 0.0, 0.0, 0.0};
    const int side_dz[2] = {1, 1}, side_da[2] = {1, 1};
    expect_one_sided(&c, dz, da, side_dz, side_da, "at the band edge");
}
END_TEST

/* KNOWN DEFECT (reported to the coordinator; not registered unless the suite is compiled with
 * -DFRICREG_TEST_KNOWN_DEFECTS). fricreg.h promises that on a kink the tangent is "the
 * Jacobian of one adjacent piece". At rest with contact 2 exactly on its upper bound with zero
 * gradient (a_free = -W (-0.125, 0.25) = (0.375, -0.625), eps = 0.02, f = (-0.125, 0.25)), the
 * two documented rules combine ("held there" and "the bounds' slopes of zdot_i > 0") into
 * column zdot_2 = (-25, -25), but the adjacent pieces are (0, 0) for zdot_2 < 0 (held, u_2 fixed)
 * and (-50, -50) for zdot_2 > 0 (contact 2 freed: -W^-1 (0, 50)). */
#ifdef FRICREG_TEST_KNOWN_DEFECTS
START_TEST(tangent_on_a_bound_at_rest_is_one_adjacent_piece)
{
    contact_case c = two_block(0.0, 0.0, 0.375, -0.625);
    fricreg_ctx *ctx = make_ctx(&c, FRICREG_LAW_QUINN, FRICREG_PARTITION_CONSISTENT);
    double f[2], Tz[4], ahead[2], behind[2];
    eval(ctx, 2, c.zdot, c.a_free, f, NULL);
    ck_assert_int_eq(fricreg_ctx_tangent(ctx, 2, Tz, NULL), FRICREG_OK);
    one_sided(ctx, &c, 0, 1, 1.0, 1e-9, ahead);
    one_sided(ctx, &c, 0, 1, -1.0, 1e-9, behind);
    int is_ahead = fabs(Tz[1] - ahead[0]) + fabs(Tz[3] - ahead[1]) <= 1e-5;
    int is_behind = fabs(Tz[1] - behind[0]) + fabs(Tz[3] - behind[1]) <= 1e-5;
    ck_assert_msg(is_ahead || is_behind,
                  "column zdot_2 = (%g, %g); pieces (%g, %g) ahead, (%g, %g) behind", Tz[1], Tz[3],
                  ahead[0], ahead[1], behind[0], behind[1]);
    fricreg_ctx_free(ctx);
}
END_TEST
#endif

/* ---- Suite -------------------------------------------------------------------------------- */

static Suite *coupled_suite(void)
{
    Suite *s = suite_create("coupled");
    TCase *tc = tcase_create("reference");
    tcase_add_test(tc, reference_interior_at_rest);
    tcase_add_test(tc, reference_edge_pins_the_leaving_contact);
    tcase_add_test(tc, reference_edge_with_saturated_partner);
    tcase_add_test(tc, reference_one_saturated_one_holding);
    tcase_add_test(tc, reference_moving_both_at_lower_bounds);
    tcase_add_test(tc, reference_karnopp_slip_force_moves_into_b);
    tcase_add_test(tc, reference_all_saturated);
    tcase_add_test(tc, reference_is_the_box_minimizer);
    suite_add_tcase(s, tc);

    tc = tcase_create("library");
    tcase_add_test(tc, consistent_law_matches_brute_force);
    tcase_add_test(tc, warm_started_walk_matches_brute_force);
    tcase_add_test(tc, two_block_band_edge_cases);
    tcase_add_test(tc, consistent_law_is_continuous_across_every_edge);
    tcase_add_test(tc, consistent_law_is_continuous_in_the_bounds);
    tcase_add_test(tc, paper_partition_jumps_as_measured);
    tcase_add_test(tc, entering_contact_warm_starts_inside_its_box);
    tcase_add_test(tc, diagonal_w_is_law_4_contact_by_contact);
    tcase_add_test(tc, tiny_mobility_keeps_its_acceleration_to_1e_292);
    suite_add_tcase(s, tc);

    tc = tcase_create("tangent");
    tcase_add_test(tc, tangent_matches_central_differences);
    tcase_add_test(tc, tangent_closed_form_two_blocks);
    tcase_add_test(tc, tangent_errors);
    tcase_add_test(tc, tangent_on_a_bound_holds_the_contact);
    tcase_add_test(tc, tangent_at_rest_takes_the_positive_side);
    tcase_add_test(tc, tangent_at_the_band_edge_slides);
#ifdef FRICREG_TEST_KNOWN_DEFECTS
    tcase_add_test(tc, tangent_on_a_bound_at_rest_is_one_adjacent_piece);
#endif
    suite_add_tcase(s, tc);

    return s;
}

int main(void)
{
    gsl_set_error_handler_off(); /* the reference reads GSL's status codes itself */
    SRunner *sr = srunner_create(coupled_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
