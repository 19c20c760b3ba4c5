/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_twoblock.c — the two blocks on a belt, Eqs. (7) (Sec. 3.3), driven through fricreg_sim.
 *
 * Paper defaults: K = 2, mu1 = 0.5, mu2 = 0.25, belt u(t) = sin(0.5 t), start at rest at the
 * origin, fixed-step RK4 with dt = 0.01 and eps = 2 dt; 4 belt cycles of 4 pi. Contacts
 * z1 = x1 - u, z2 = x2 - x1, z'' = a_free + W f with W = [[1, -1], [-1, 2]],
 * a_free = [-u'' - x1, x1 - K x2] (spec/paper.md, "Reference system 3"). An observer records
 * every accepted step. */
#include <check.h>
#include <math.h>
#include <stdlib.h>

#include "fricreg_sim.h"
#include "quiet_check.h"

#define K 2.0
#define MU1 0.5
#define MU2 0.25
#define DT 0.01
#define EPS (2.0 * DT)

static double belt_v(double t)
{
    return 0.5 * cos(0.5 * t);
}
static double belt_a(double t)
{
    return -0.25 * sin(0.5 * t);
}
static double sgn(double y)
{
    return (double)(y > 0.0) - (double)(y < 0.0);
}

struct record {
    long calls;
    double t_prev;
    /* near-stick runs |zdot_i| < eps: start of the current run, longest run */
    int in_stick[2];
    double run_start[2], longest[2];
    /* partition residuals (max abs) and how often each case was seen */
    double res_both, res_lower, res_upper;
    long n_both, n_lower, n_upper;
    /* bounds */
    double max_f[2];
    /* belt work by the trapezoid rule, total variation of its integrand, largest step */
    double work, g_prev, tv, h_max;
    double x[2], v[2];
};

static int observe(void *user, double t, size_t ndof, const double x[], const double v[], size_t m,
                   const double f[], const double f_eq[])
{
    struct record *r = user;
    ck_assert_uint_eq(ndof, 2);
    ck_assert_uint_eq(m, 2);
    const double zdot[2] = {v[0] - belt_v(t), v[1] - v[0]};
    for (int i = 0; i < 2; i++) {
        int stick = fabs(zdot[i]) < EPS;
        if (stick && !r->in_stick[i])
            r->run_start[i] = t;
        if (stick && t - r->run_start[i] > r->longest[i])
            r->longest[i] = t - r->run_start[i];
        r->in_stick[i] = stick;
        r->max_f[i] = fmax(r->max_f[i], fabs(f[i]));
        /* f_eq is computed exactly where the contact is near-stick (Sec. 3.3) */
        QUIET_CHECK(!isnan(f_eq[i]) == stick);
    }

    /* Hand-solved partition (spec "Reference system 3"). b = -a_free = (u'' + x1, K x2 - x1). */
    const double b1 = belt_a(t) + x[0], b2 = K * x[1] - x[0];
    if (!isnan(f_eq[0]) && !isnan(f_eq[1])) {
        /* both: W f_eq = b, W^-1 = [[2, 1], [1, 1]] (det W = 1) */
        r->res_both = fmax(r->res_both, fabs(f_eq[0] - (2.0 * b1 + b2)));
        r->res_both = fmax(r->res_both, fabs(f_eq[1] - (b1 + b2)));
        r->n_both++;
    } else if (!isnan(f_eq[0])) {
        /* lower only: row 1 of W f = b with f2 at its sliding value -mu2 sgn(zdot2) */
        double f2 = -MU2 * sgn(zdot[1]);
        ck_assert_double_eq(f[1], f2);
        r->res_lower = fmax(r->res_lower, fabs(f_eq[0] - (b1 + f2)));
        r->n_lower++;
    } else if (!isnan(f_eq[1])) {
        /* upper only: row 2, -f1 + 2 f2_eq = b2, with f1 = -mu1 sgn(zdot1) */
        ck_assert_double_eq(f[0], -MU1 * sgn(zdot[0]));
        r->res_upper = fmax(r->res_upper, fabs(f_eq[1] - 0.5 * (f[0] + b2)));
        r->n_upper++;
    }

    /* power the belt puts in: the lower block's friction f1 acts between it and the belt */
    double g = belt_v(t) * f[0];
    if (r->calls > 0) {
        double h = t - r->t_prev;
        r->work += 0.5 * h * (g + r->g_prev);
        r->tv += fabs(g - r->g_prev);
        r->h_max = fmax(r->h_max, h);
    }
    r->g_prev = g;
    r->t_prev = t;
    r->calls++;
    for (int i = 0; i < 2; i++) {
        r->x[i] = x[i];
        r->v[i] = v[i];
    }
    return 0;
}

/* The paper's two-block run over 4 belt cycles, recorded into *r. */
static fricreg_sim *twoblock_run(struct record *r)
{
    fricreg_sim *sim = NULL;
    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_TWOBLOCK, &sim), FRICREG_OK);
    /* the residuals below are those of the paper's joint f_eq (Sec. 3.3) */
    ck_assert_int_eq(fricreg_sim_set_partition(sim, FRICREG_PARTITION_PAPER), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RK4, DT, 0.0, 0.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_observer(sim, observe, r), FRICREG_OK);
    int status = fricreg_sim_run_cycles(sim, 4);
    ck_assert_msg(status == FRICREG_OK, "run: status %d (%s)", status, fricreg_sim_errmsg(sim));
    double eps = NAN;
    ck_assert_int_eq(fricreg_sim_get_value(sim, FRICREG_VALUE_EPS, &eps), FRICREG_OK);
    ck_assert_double_eq_tol(eps, EPS, 1e-16);
    return sim;
}

/* Paper Sec. 3.3, Fig. 11: long intervals of sticking at both interfaces. Over 4 cycles of
 * length 4 pi each interface has a near-stick run longer than 1.0, and the near-stick
 * fraction of the last cycle is neither ~0 nor ~1 (in (0.05, 0.95)). */
START_TEST(test_both_interfaces_stick_for_long_intervals)
{
    struct record r = {0};
    fricreg_sim *sim = twoblock_run(&r);
    ck_assert_double_gt(r.longest[0], 1.0);
    ck_assert_double_gt(r.longest[1], 1.0);
    double frac[2];
    ck_assert_int_eq(fricreg_sim_get_stick_fraction(sim, 2, frac), FRICREG_OK);
    for (int i = 0; i < 2; i++) {
        ck_assert_double_gt(frac[i], 0.05);
        ck_assert_double_lt(frac[i], 0.95);
    }
    fricreg_sim_free(sim);
}
END_TEST

/* The f_eq partition of Sec. 3.3 agrees with the 2x2 system solved by hand in each of its three
 * cases (both near-stick, lower only, upper only), to rounding (1e-12); each case occurs. */
START_TEST(test_partition_matches_hand_solved_system)
{
    struct record r = {0};
    fricreg_sim *sim = twoblock_run(&r);
    ck_assert_int_gt(r.n_both, 0);
    ck_assert_int_gt(r.n_lower, 0);
    ck_assert_int_gt(r.n_upper, 0);
    ck_assert_double_lt(r.res_both, 1e-12);
    ck_assert_double_lt(r.res_lower, 1e-12);
    ck_assert_double_lt(r.res_upper, 1e-12);
    fricreg_sim_free(sim);
}
END_TEST

/* (4) keeps |f| <= mun: |f1| <= mu1, |f2| <= mu2 at every step (to rounding). */
START_TEST(test_friction_stays_within_bounds)
{
    struct record r = {0};
    fricreg_sim *sim = twoblock_run(&r);
    ck_assert_double_le(r.max_f[0], MU1 * (1.0 + 1e-15));
    ck_assert_double_le(r.max_f[1], MU2 * (1.0 + 1e-15));
    fricreg_sim_free(sim);
}
END_TEST

/* Energy balance of (7): with E = (v1^2 + x1^2 + v2^2 + K x2^2)/2,
 * dE/dt = v1 f1 + (v2 - v1) f2 and dD/dt = -(zdot1 f1 + zdot2 f2), so E + D grows by the belt's
 * power u' f1: D(T) = W_belt - E(T) (E(0) = 0). W_belt is integrated from the observer's samples
 * by the trapezoid rule, whose error on each step of length h is at most (h/2) times the
 * variation of u' f1 over it: in all <= (h_max/2) TV. The samples see most of TV (f1 is
 * continuous under (4)); allow twice it, plus 1e-4 for the RK4 error of D and E. */
START_TEST(test_dissipation_balances_belt_work)
{
    struct record r = {0};
    fricreg_sim *sim = twoblock_run(&r);
    double D = NAN, x[2], v[2];
    ck_assert_int_eq(fricreg_sim_get_value(sim, FRICREG_VALUE_DISSIPATION, &D), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_state(sim, 2, x, v), FRICREG_OK);
    for (int i = 0; i < 2; i++) { /* the observer saw the final state */
        ck_assert_double_eq(x[i], r.x[i]);
        ck_assert_double_eq(v[i], r.v[i]);
    }
    double E = 0.5 * (v[0] * v[0] + x[0] * x[0] + v[1] * v[1] + K * x[1] * x[1]);
    double tol = r.h_max * r.tv + 1e-4;
    ck_assert_double_gt(D, 0.0);
    ck_assert_double_eq_tol(D, r.work - E, tol);
    /* the bound is meaningful: under 2% of D */
    ck_assert_double_lt(tol, 0.02 * D);
    fricreg_sim_free(sim);
}
END_TEST

static Suite *twoblock_suite(void)
{
    Suite *s = suite_create("twoblock");
    TCase *tc = tcase_create("paper");
    tcase_add_test(tc, test_both_interfaces_stick_for_long_intervals);
    tcase_add_test(tc, test_partition_matches_hand_solved_system);
    tcase_add_test(tc, test_friction_stays_within_bounds);
    tcase_add_test(tc, test_dissipation_balances_belt_work);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(twoblock_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
