/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_extrapolate.c — extrapolation in eps (fricreg_sim_run_extrapolated) and its Richardson
 * table (src/sim/richardson.c, white box: this test links the static library).
 *
 * References: the oscillator's exact solution (fricreg_exact.h); for the chain, law (4) + RK4
 * on a ladder of halved steps, extrapolated (bench/reference.c), D on cycle 4 =
 * 0.010494960003438 +- 1.9e-11 (the CVODE event-driven classical solution at rtol 1e-12 agrees
 * to 5.2e-9 relative). */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_exact.h"
#include "fricreg_sim.h"
#include "sim_runs.h"
#include "sim/richardson.h"

#define CHAIN_D4 0.010494960003438
#define CHAIN_D4_UNCERTAINTY 1.9e-11

/* ---- The table on synthetic sequences ------------------------------------------------------ */

/* v(h) = 2.385 + 0.731 h^2 - 0.412 h^3 at h = 0.0385 / 2^k: the observed order is 2, and
 * three levels remove h^2 and h^3 exactly, leaving rounding. The estimate is the h^3 term the
 * order-2 column leaves: v_2 + (v_2 - v_1)/3 carries c h_2^3 (1 - 7/3) = -4/3 c h_2^3,
 * c = -0.412, h_2 = 0.0385/4. */
START_TEST(test_richardson_removes_a_polynomial_error)
{
    double v[3];
    for (int k = 0; k < 3; k++) {
        double h = ldexp(0.0385, -k);
        v[k] = 2.385 + 0.731 * h * h - 0.412 * h * h * h;
    }
    struct fr_richardson r;
    fr_richardson(v, 3, 0, &r);
    ck_assert_int_eq(r.order, 2);
    ck_assert_double_eq_tol(r.observed, 2.0, 0.05);
    ck_assert_int_eq(r.flagged, 0);
    ck_assert_double_eq_tol(r.value, 2.385, 1e-14);
    double h2 = 0.0385 / 4;
    ck_assert_double_eq_tol(r.error, 4.0 / 3.0 * 0.412 * h2 * h2 * h2, 1e-14);
    ck_assert(r.error >= fabs(r.value - 2.385));
}
END_TEST

/* First order with a second-order tail (the non-sticking oscillator's shape):
 * v = 8.415 - 0.62 h + 1.7 h^2 at h = 0.04 / 2^k, four levels: order 1, exact to rounding. */
START_TEST(test_richardson_first_order_with_tail)
{
    double v[4];
    for (int k = 0; k < 4; k++) {
        double h = ldexp(0.04, -k);
        v[k] = 8.415 - 0.62 * h + 1.7 * h * h;
    }
    struct fr_richardson r;
    fr_richardson(v, 4, 2, &r); /* the declared 2 is overruled by the clean observation */
    ck_assert_int_eq(r.order, 1);
    ck_assert_int_eq(r.flagged, 0);
    ck_assert_double_eq_tol(r.value, 8.415, 1e-13);
}
END_TEST

/* Differences of opposite sign: no order. The declared one is used, the value flagged, and
 * the estimate is at least the last raw difference |0.9063 - 1.3117|. */
START_TEST(test_richardson_flags_inconsistent_ratios)
{
    const double v[3] = {1.0241, 1.3117, 0.9063};
    struct fr_richardson r;
    fr_richardson(v, 3, 2, &r);
    ck_assert(isnan(r.observed));
    ck_assert_int_eq(r.flagged, 1);
    ck_assert_int_eq(r.order, 2);
    ck_assert(r.error >= 1.3117 - 0.9063);
    /* A ratio of 2.6 (order 1.38: between integers) is flagged too. */
    const double w[3] = {1.0, 1.26, 1.36};
    fr_richardson(w, 3, 0, &r);
    ck_assert_int_eq(r.flagged, 1);
    ck_assert_int_eq(r.order, 1);
    ck_assert_double_eq_tol(r.observed, log2(2.6), 1e-12);
}
END_TEST

/* Two levels: nothing to observe; the declared order, 0 meaning 1; not flagged.
 * v = {3.7, 3.4}: order 1 gives 3.4 + (3.4 - 3.7) = 3.1, estimate 0.3; order 2 gives
 * 3.4 - 0.1 = 3.3, estimate 0.1. */
START_TEST(test_richardson_two_levels_use_the_declared_order)
{
    const double v[2] = {3.7, 3.4};
    struct fr_richardson r;
    fr_richardson(v, 2, 0, &r);
    ck_assert_int_eq(r.order, 1);
    ck_assert_int_eq(r.flagged, 0);
    ck_assert(isnan(r.observed));
    ck_assert_double_eq_tol(r.value, 3.1, 1e-14);
    ck_assert_double_eq_tol(r.error, 0.3, 1e-14);
    fr_richardson(v, 2, 2, &r);
    ck_assert_double_eq_tol(r.value, 3.3, 1e-14);
    ck_assert_double_eq_tol(r.error, 0.1, 1e-14);
}
END_TEST

/* Equal values (a cycle that dissipates nothing, or converged): the value itself, error 0. */
START_TEST(test_richardson_converged_sequence)
{
    const double v[3] = {5.25, 5.25, 5.25}, zero[3] = {0.0, 0.0, 0.0};
    struct fr_richardson r;
    fr_richardson(v, 3, 0, &r);
    ck_assert_double_eq(r.value, 5.25);
    ck_assert_double_eq(r.error, 0.0);
    ck_assert_int_eq(r.flagged, 0);
    fr_richardson(zero, 3, 0, &r);
    ck_assert_double_eq(r.value, 0.0);
    ck_assert_int_eq(r.flagged, 0);
}
END_TEST

/* ---- The simulations against references ------------------------------------------------------ */

static fricreg_sim *oscillator(double a, double omega, double eps, double tol)
{
    fricreg_sim *sim = NULL;
    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_OSCILLATOR, &sim), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_A, a), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_OMEGA, omega), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_X0, 0.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, eps), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RK8PD, 1e-3, tol, tol),
                     FRICREG_OK);
    return sim;
}

/* D of cycle `cycle` of the exact solution, from rest at the origin; *total gets the sum
 * over cycles 1 … cycle (the total D at the end of the last one). */
static double exact_D_total(double a, double omega, int cycle, double *total)
{
    fricreg_exact *ex = NULL;
    double D[64];
    ck_assert_int_lt(cycle, 65);
    ck_assert_int_eq(fricreg_exact_create(a, omega, 1.0, 0.0, 0.0, &ex), FRICREG_OK);
    ck_assert_int_eq(fricreg_exact_run_cycles(ex, cycle), FRICREG_OK);
    ck_assert_int_eq(fricreg_exact_dissipation(ex, (size_t)cycle, D), FRICREG_OK);
    fricreg_exact_free(ex);
    *total = 0.0;
    for (int k = 0; k < cycle; k++)
        *total += D[k];
    return D[cycle - 1];
}

static double exact_D(double a, double omega, int cycle)
{
    double total;
    return exact_D_total(a, omega, cycle, &total);
}

/* The last cycle of a run of `levels` at eps, eps/2, …: the raw D at eps, the raw D at the
 * finest eps (a plain run of its own), the extrapolated D and its estimate. */
struct outcome {
    double raw, finest, value, estimate, order, observed;
    double total, total_estimate; /* the total D(t_end) extrapolated, and its estimate */
};

static struct outcome run_oscillator(double a, double omega, double eps, int levels, int order)
{
    enum { CYCLES = 6 };
    const double tol = 1e-12; /* rk8pd: integration error far below eps's (1e-5 and more) */
    struct outcome o;
    double D[CYCLES], err[CYCLES];
    fricreg_sim *sim = oscillator(a, omega, eps, tol);
    ck_assert_int_eq(fricreg_sim_run_extrapolated(sim, CYCLES * sim_runs_period(sim), levels,
                                                  order),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_dissipation(sim, CYCLES, D), FRICREG_OK);
    o.raw = D[CYCLES - 1];
    ck_assert_int_eq(fricreg_sim_get_extrapolated_dissipation(sim, CYCLES, D, err), FRICREG_OK);
    o.value = D[CYCLES - 1];
    o.estimate = err[CYCLES - 1];
    o.order = sim_runs_extrapolation(sim, FRICREG_EXTRAP_ORDER);
    o.observed = sim_runs_extrapolation(sim, FRICREG_EXTRAP_OBSERVED_ORDER);
    o.total = sim_runs_extrapolation(sim, FRICREG_EXTRAP_DISSIPATION);
    o.total_estimate = sim_runs_extrapolation(sim, FRICREG_EXTRAP_DISSIPATION_ERR);
    ck_assert_double_eq(sim_runs_extrapolation(sim, FRICREG_EXTRAP_LEVELS), levels);
    ck_assert_double_eq(sim_runs_extrapolation(sim, FRICREG_EXTRAP_EPS_FINEST),
                        ldexp(eps, 1 - levels));
    fricreg_sim_free(sim);
    fricreg_sim *fine = oscillator(a, omega, ldexp(eps, 1 - levels), tol);
    ck_assert_int_eq(fricreg_sim_run_cycles(fine, CYCLES), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_dissipation(fine, CYCLES, D), FRICREG_OK);
    o.finest = D[CYCLES - 1];
    fricreg_sim_free(fine);
    return o;
}

/* The sticking oscillator (a = 2, omega = 0.5): D's error is c eps^2 (measured: -1.4e-5
 * relative at eps = 0.0385). Three levels observe order 2; the finest raw level is 16x better
 * than the first (eps/4: 4^2), the extrapolation at least 1000x better than that
 * (measured 2.6e-10 against 8.7e-7), and the estimate is above the true error. */
START_TEST(test_sticking_oscillator_second_order)
{
    double total = NAN;
    const double ref = exact_D_total(2.0, 0.5, 6, &total);
    struct outcome o = run_oscillator(2.0, 0.5, 0.0385, 3, 0);
    double e_raw = o.raw - ref, e_fine = o.finest - ref, e = o.value - ref;
    ck_assert_double_eq(o.order, 2.0);
    ck_assert_double_eq_tol(o.observed, 2.0, 0.05);
    ck_assert_double_eq_tol(e_raw / e_fine, 16.0, 0.5);
    ck_assert(fabs(e) < 1e-3 * fabs(e_fine));
    ck_assert(o.estimate >= fabs(e));
    ck_assert(o.estimate < fabs(e_fine)); /* and tighter than the finest raw error */
    /* the total D over the six cycles, extrapolated on its own, within its estimate */
    ck_assert(fabs(o.total - total) <= o.total_estimate);
    ck_assert(o.total_estimate < 1e-8 * total);
}
END_TEST

/* The oscillator without sticking (a = 3, omega = 1.5): first order (-3.1e-3 relative at
 * eps = 0.0385); finest raw 4x better than the first (eps/4), three levels (orders 1, 2)
 * leave under 1e-8 relative (measured -7.7e-9), the estimate above it. */
START_TEST(test_slipping_oscillator_first_order)
{
    const double ref = exact_D(3.0, 1.5, 6);
    struct outcome o = run_oscillator(3.0, 1.5, 0.0385, 3, 0);
    double e_raw = o.raw - ref, e_fine = o.finest - ref, e = o.value - ref;
    ck_assert_double_eq(o.order, 1.0);
    ck_assert_double_eq_tol(o.observed, 1.0, 0.05);
    ck_assert_double_eq_tol(e_raw / e_fine, 4.0, 0.2);
    ck_assert(fabs(e) < 1e-8 * ref);
    ck_assert(fabs(e) < 1e-4 * fabs(e_fine));
    ck_assert(o.estimate >= fabs(e));
}
END_TEST

/* Two levels on the sticking oscillator: the declared order decides. Declared 2 (right)
 * leaves c eps^3-size terms, >= 100x below the finest raw error; the default (1) halves it
 * at best but its estimate still bounds the error (the reason for that default). */
START_TEST(test_two_levels_declared_order)
{
    const double ref = exact_D(2.0, 0.5, 6);
    struct outcome two = run_oscillator(2.0, 0.5, 0.0385, 2, 2);
    ck_assert_double_eq(two.order, 2.0);
    ck_assert(isnan(two.observed));
    ck_assert(fabs(two.value - ref) < 1e-2 * fabs(two.finest - ref));
    struct outcome one = run_oscillator(2.0, 0.5, 0.0385, 2, 0);
    ck_assert_double_eq(one.order, 1.0);
    ck_assert(one.estimate >= fabs(one.value - ref));
}
END_TEST

/* The two cheap ways to 1e-8 of the work-precision benchmark (bench/workprecision.c), on the
 * 50th cycle against the exact solution, rk8pd at rtol = atol = 1e-10:
 * - sticking oscillator: two levels from eps = 0.025 with the order declared 2 (every switch
 *   a stick): the raw finest level is off by -0.0093 eps^2 = 1.5e-6 relative, the
 *   extrapolation by O(eps^3) (measured 3e-9);
 * - oscillator without sticking: a plain run at eps = 1e-8, whose first-order error
 *   (0.075 eps relative) is below every target (measured 7e-10). */
START_TEST(test_benchmark_methods_reach_1e_8)
{
    enum { CYCLES = 50 };
    double D[CYCLES], err[CYCLES];
    const double stick_ref = exact_D(2.0, 0.5, CYCLES);
    fricreg_sim *sim = oscillator(2.0, 0.5, 0.025, 1e-10);
    ck_assert_int_eq(fricreg_sim_run_extrapolated(sim, CYCLES * sim_runs_period(sim), 2, 2),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_extrapolated_dissipation(sim, CYCLES, D, err), FRICREG_OK);
    ck_assert(fabs(D[CYCLES - 1] - stick_ref) < 1e-8 * stick_ref);
    ck_assert(err[CYCLES - 1] >= fabs(D[CYCLES - 1] - stick_ref));
    ck_assert_int_eq(fricreg_sim_get_dissipation(sim, CYCLES, D), FRICREG_OK); /* level 0 */
    ck_assert(fabs(D[CYCLES - 1] - stick_ref) > 1e-6 * stick_ref);
    fricreg_sim_free(sim);

    const double slip_ref = exact_D(3.0, 1.5, CYCLES);
    sim = oscillator(3.0, 1.5, 1e-8, 1e-10);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, CYCLES), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_dissipation(sim, CYCLES, D), FRICREG_OK);
    ck_assert(fabs(D[CYCLES - 1] - slip_ref) < 1e-8 * slip_ref);
    fricreg_sim_free(sim);
}
END_TEST

/* The chain (n = 32, the paper's): D on cycle 4 at eps = 0.0052 with rk8pd at 1e-10, three
 * levels, against the ladder reference: the error is at least 30x below the finest raw
 * level's (measured about 100x) and within the estimate (plus the reference's own
 * uncertainty). */
START_TEST(test_chain_against_the_reference)
{
    enum { CYCLES = 4 };
    fricreg_sim *sim = NULL;
    double D[CYCLES], err[CYCLES];
    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_CHAIN, &sim), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, 0.0052), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RK8PD, 1e-3, 1e-10, 1e-10),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_extrapolated(sim, CYCLES * sim_runs_period(sim), 3, 0),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_extrapolated_dissipation(sim, CYCLES, D, err), FRICREG_OK);
    double e = D[CYCLES - 1] - CHAIN_D4;
    ck_assert_double_eq(sim_runs_extrapolation(sim, FRICREG_EXTRAP_ORDER), 2.0);
    ck_assert(fabs(e) <= err[CYCLES - 1] + CHAIN_D4_UNCERTAINTY);
    /* the finest level alone */
    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, 0.0052 / 4), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, CYCLES), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_dissipation(sim, CYCLES, D), FRICREG_OK);
    ck_assert(30.0 * fabs(e) < fabs(D[CYCLES - 1] - CHAIN_D4));
    fricreg_sim_free(sim);
}
END_TEST

/* ---- The contract ------------------------------------------------------------------------- */

/* Level 0 is the caller's simulation: its getters give a plain run's numbers, bit for bit,
 * and its observer sees that run only (the same number of calls). */
static int count_calls(void *user, double t, size_t ndof, const double x[], const double v[],
                       size_t m, const double f[], const double f_eq[])
{
    (void)t, (void)ndof, (void)x, (void)v, (void)m, (void)f, (void)f_eq;
    ++*(long *)user;
    return 0;
}

START_TEST(test_level_zero_is_the_plain_run)
{
    enum { CYCLES = 3 };
    long calls_plain = 0, calls_extrap = 0;
    double D_plain[CYCLES], D[CYCLES], x_plain, v_plain, x, v;
    fricreg_sim *sim = oscillator(2.0, 0.5, 0.0413, 1e-9);
    ck_assert_int_eq(fricreg_sim_set_observer(sim, count_calls, &calls_plain), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, CYCLES), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_dissipation(sim, CYCLES, D_plain), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_state(sim, 1, &x_plain, &v_plain), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_observer(sim, count_calls, &calls_extrap), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_extrapolated(sim, CYCLES * sim_runs_period(sim), 3, 0),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_dissipation(sim, CYCLES, D), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_state(sim, 1, &x, &v), FRICREG_OK);
    ck_assert_int_eq(memcmp(D, D_plain, sizeof D), 0);
    ck_assert_double_eq(x, x_plain);
    ck_assert_double_eq(v, v_plain);
    ck_assert_int_eq(calls_extrap, calls_plain);
    fricreg_sim_free(sim);
}
END_TEST

/* A plain run of the oscillator at eps over cycles with the step bound max_steps: its status. */
static int bounded_run(double eps, int cycles, int64_t max_steps)
{
    fricreg_sim *sim = oscillator(2.0, 0.5, eps, 1e-9);
    ck_assert_int_eq(fricreg_sim_set_max_steps(sim, max_steps), FRICREG_OK);
    int status = fricreg_sim_run_cycles(sim, cycles);
    fricreg_sim_free(sim);
    return status;
}

/* The finer levels keep the caller's bound on adaptive steps (fricreg_sim_set_max_steps): with
 * the smallest bound under which a plain run at eps passes, a plain run at eps/4 (level 2) is
 * refused, and so is the extrapolation, with FRICREG_EWORK naming the level. */
START_TEST(test_finer_levels_keep_the_step_bound)
{
    enum { CYCLES = 2 };
    const double eps = 0.0413;
    int64_t bound = 16;
    while (bounded_run(eps, CYCLES, bound) != FRICREG_OK)
        bound += bound / 8;
    ck_assert_int_eq(bounded_run(eps / 4, CYCLES, bound), FRICREG_EWORK);
    fricreg_sim *sim = oscillator(2.0, 0.5, eps, 1e-9);
    ck_assert_int_eq(fricreg_sim_set_max_steps(sim, bound), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_extrapolated(sim, CYCLES * sim_runs_period(sim), 3, 0),
                     FRICREG_EWORK);
    ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "level"));
    fricreg_sim_free(sim);
}
END_TEST

/* A fixed step is halved with eps: three levels of fixed RK4 cost 1 + 2 + 4 = 7 times level
 * 0's right-hand sides (each cycle's shortened last step aside: within 1%). */
START_TEST(test_fixed_step_halves_with_eps)
{
    fricreg_sim *sim = NULL;
    double rhs0 = NAN, eps0 = NAN;
    ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_OSCILLATOR, &sim), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RK4, 0.0137, 0.0, 0.0),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_extrapolated(sim, 2 * sim_runs_period(sim), 3, 0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_value(sim, FRICREG_VALUE_RHS_EVALS, &rhs0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_value(sim, FRICREG_VALUE_EPS, &eps0), FRICREG_OK);
    ck_assert_double_eq_tol(eps0, 2 * 0.0137, 1e-15); /* the paper's rule at level 0 */
    ck_assert_double_eq_tol(sim_runs_extrapolation(sim, FRICREG_EXTRAP_RHS_EVALS) / rhs0, 7.0,
                            0.07);
    ck_assert_double_eq_tol(sim_runs_extrapolation(sim, FRICREG_EXTRAP_EPS_FINEST), eps0 / 4,
                            1e-15);
    fricreg_sim_free(sim);
}
END_TEST

static void expect_failure(const fricreg_sim *sim, int status, int code)
{
    ck_assert_int_eq(status, code);
    ck_assert_int_eq(fricreg_sim_errcode(sim), code);
    ck_assert_str_ne(fricreg_sim_errmsg(sim), "");
}

START_TEST(test_bad_input_is_refused)
{
    fricreg_sim *sim = oscillator(2.0, 0.5, 0.0413, 1e-8);
    double T = sim_runs_period(sim), out = 7.25, D[2] = {7.25, 7.25}, err[2] = {7.25, 7.25};
    ck_assert_int_eq(fricreg_sim_run_extrapolated(NULL, T, 3, 0), FRICREG_ENULL);
    expect_failure(sim, fricreg_sim_run_extrapolated(sim, T, 1, 0), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "levels"));
    expect_failure(sim, fricreg_sim_run_extrapolated(sim, T, 9, 0), FRICREG_EINVAL);
    expect_failure(sim, fricreg_sim_run_extrapolated(sim, T, 3, -1), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_sim_errmsg(sim), "order"));
    expect_failure(sim, fricreg_sim_run_extrapolated(sim, T, 3, 5), FRICREG_EINVAL);
    expect_failure(sim, fricreg_sim_run_extrapolated(sim, NAN, 3, 0), FRICREG_ENONFINITE);
    expect_failure(sim, fricreg_sim_run_extrapolated(sim, -T, 3, 0), FRICREG_EINVAL);
    /* nothing extrapolated yet: the getters refuse and write nothing */
    ck_assert_int_eq(fricreg_sim_get_extrapolation(sim, FRICREG_EXTRAP_ORDER, &out),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_sim_get_extrapolated_dissipation(sim, 2, D, err), FRICREG_EINVAL);
    ck_assert_double_eq(out, 7.25);
    ck_assert_double_eq(D[0], 7.25);
    ck_assert_double_eq(err[1], 7.25);
    ck_assert_int_eq(fricreg_sim_get_extrapolation(NULL, FRICREG_EXTRAP_ORDER, &out),
                     FRICREG_ENULL);
    ck_assert_int_eq(fricreg_sim_get_extrapolation(sim, FRICREG_EXTRAP_ORDER, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_sim_get_extrapolated_dissipation(sim, 2, NULL, err), FRICREG_ENULL);
    /* after a run: a wrong length or an unknown quantity */
    ck_assert_int_eq(fricreg_sim_run_extrapolated(sim, 2 * T, 2, 0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_extrapolated_dissipation(sim, 3, D, err), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_sim_get_extrapolation(sim, 8, &out), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_sim_get_extrapolation(sim, -1, &out), FRICREG_EINVAL);
    ck_assert_double_eq(D[0], 7.25);
    ck_assert_double_eq(out, 7.25);
    ck_assert_int_eq(fricreg_sim_get_extrapolated_dissipation(sim, 2, D, err), FRICREG_OK);
    /* a setter discards the extrapolation, as it discards the run */
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_A, 2.05), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_extrapolation(sim, FRICREG_EXTRAP_ORDER, &out),
                     FRICREG_EINVAL);
    /* a plain run too */
    ck_assert_int_eq(fricreg_sim_run_extrapolated(sim, 2 * T, 2, 0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_cycles(sim, 1), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_get_extrapolation(sim, FRICREG_EXTRAP_ORDER, &out),
                     FRICREG_EINVAL);
    fricreg_sim_free(sim);
}
END_TEST

/* Called from the observer: refused with FRICREG_EINVAL, and the run goes on. */
static int nested_status;
static int call_extrapolated(void *user, double t, size_t ndof, const double x[], const double v[],
                             size_t m, const double f[], const double f_eq[])
{
    (void)ndof, (void)x, (void)v, (void)m, (void)f, (void)f_eq;
    if (t > 1.0 && nested_status == FRICREG_OK)
        nested_status = fricreg_sim_run_extrapolated(user, 2.0, 2, 0);
    return 0;
}

START_TEST(test_refused_from_the_observer)
{
    fricreg_sim *sim = oscillator(2.0, 0.5, 0.0413, 1e-8);
    nested_status = FRICREG_OK;
    ck_assert_int_eq(fricreg_sim_set_observer(sim, call_extrapolated, sim), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run_extrapolated(sim, 2 * sim_runs_period(sim), 2, 0), FRICREG_OK);
    ck_assert_int_eq(nested_status, FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_sim_get_extrapolated_dissipation(sim, 2, (double[2]){0, 0},
                                                              (double[2]){0, 0}),
                     FRICREG_OK);
    fricreg_sim_free(sim);
}
END_TEST

static Suite *extrapolate_suite(void)
{
    Suite *s = suite_create("extrapolate");
    TCase *table = tcase_create("richardson");
    tcase_add_test(table, test_richardson_removes_a_polynomial_error);
    tcase_add_test(table, test_richardson_first_order_with_tail);
    tcase_add_test(table, test_richardson_flags_inconsistent_ratios);
    tcase_add_test(table, test_richardson_two_levels_use_the_declared_order);
    tcase_add_test(table, test_richardson_converged_sequence);
    suite_add_tcase(s, table);
    TCase *refs = tcase_create("references");
    tcase_add_test(refs, test_sticking_oscillator_second_order);
    tcase_add_test(refs, test_slipping_oscillator_first_order);
    tcase_add_test(refs, test_two_levels_declared_order);
    tcase_add_test(refs, test_benchmark_methods_reach_1e_8);
    tcase_add_test(refs, test_chain_against_the_reference);
    suite_add_tcase(s, refs);
    TCase *api = tcase_create("contract");
    tcase_add_test(api, test_level_zero_is_the_plain_run);
    tcase_add_test(api, test_fixed_step_halves_with_eps);
    tcase_add_test(api, test_finer_levels_keep_the_step_bound);
    tcase_add_test(api, test_bad_input_is_refused);
    tcase_add_test(api, test_refused_from_the_observer);
    suite_add_tcase(s, api);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(extrapolate_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
