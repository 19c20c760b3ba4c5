/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stress_extreme.c — extreme parameters. Each case ends in one of two ways, both checked:
 *   - a documented refusal: the status the header names, and a message that names the value;
 *   - finite results passing an invariant: the energy balance E - E0 - W_in + D = 0 (to the
 *     watch's trapezoid error, stress.h), |f| <= mun at every step, the scaling law, a stick
 *     that holds exactly, or the exact solver's dissipation.
 * Scaling law of Eq. (5): with x, a, mun, v0 and eps all multiplied by c the solution is c x(t)
 * and D is c^2 D, so D/c^2 at mun = c must equal D at mun = 1 to rounding (the steps see the
 * same numbers times c, rounded). The same holds for the two blocks with mu1, mu2, belt_amp. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_exact.h"
#include "stress.h"

#define DT 0.01
#define BALANCE_TOL 1e-4 /* of the energy scale: the watch's trapezoid error at these steps */

struct setting {
    int param; /* 0 ends a list */
    double value;
};

/* One run of `system` with the settings, law (4) with eps (0: the paper's rule) and fixed RK4
 * steps dt up to t_end, watched. The simulation is returned for queries (free it). */
static int run_sim(int system, const struct setting s[], double eps, double dt, double t_end,
                   struct stress_energy *w, fricreg_sim **out)
{
    fricreg_sim *sim = NULL;
    int status = fricreg_sim_create(system, &sim);
    for (size_t i = 0; status == FRICREG_OK && s != NULL && s[i].param != 0; i++)
        status = fricreg_sim_set_param(sim, s[i].param, s[i].value);
    if (status == FRICREG_OK)
        status = fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, eps);
    if (status == FRICREG_OK)
        status = fricreg_sim_set_integrator(sim, FRICREG_INT_RK4, dt, 0.0, 0.0);
    if (status == FRICREG_OK)
        status = stress_energy_watch(w, sim, system);
    if (status == FRICREG_OK)
        status = fricreg_sim_run(sim, t_end);
    if (status == FRICREG_OK && w->nonfinite)
        status = FRICREG_EDIVERGED;
    *out = sim;
    return status;
}

static double total_dissipation(const fricreg_sim *sim)
{
    double D = NAN;
    fricreg_sim_get_value(sim, FRICREG_VALUE_DISSIPATION, &D);
    return D;
}

static double end_position(const fricreg_sim *sim)
{
    double x[1] = {NAN}, v[1];
    fricreg_sim_get_state(sim, 1, x, v);
    return x[0];
}

/* The table: one row per case. */
static void row(struct stress_tally *tally, const char *name, int ok, const char *outcome,
                const char *figure_name, double figure)
{
    printf("%-44s %-4s %-34.34s %s %.3g\n", name, ok ? "ok" : "FAIL", outcome, figure_name, figure);
    stress_check(tally, ok, "%s: %s (%s %g)", name, outcome, figure_name, figure);
}

/* An invariant row for a watched run: OK, finite, |f| <= mun, no energy above E0 + W_in, and
 * the energy balance closes with the driver's own D. */
static double watched_row(struct stress_tally *tally, const char *name, int status,
                          const struct stress_energy *w, const fricreg_sim *sim)
{
    double scale = fmax(stress_energy_scale(w),
                        DBL_MIN * DBL_EPSILON); /* 0 for a body left at rest */
    double gap = fabs(w->E - w->E0 - w->work_in + total_dissipation(sim)) / scale;
    int ok = status == FRICREG_OK && w->worst_force <= 1.0 + 4 * DBL_EPSILON &&
             w->worst_excess <= BALANCE_TOL * scale && w->worst_balance <= BALANCE_TOL * scale &&
             gap <= BALANCE_TOL;
    char outcome[64];
    snprintf(outcome, sizeof outcome, "status %d, max|f|/mun %.6f", status, w->worst_force);
    row(tally, name, ok, outcome, "balance/E", fmax(gap, w->worst_balance / scale));
    return gap;
}

/* A refusal row: the documented status, and a message naming what was refused. */
static void refusal_row(struct stress_tally *tally, const char *name, int status, int expected,
                        const char *msg, const char *must_name)
{
    int ok = status == expected && msg != NULL && strstr(msg, must_name) != NULL;
    row(tally, name, ok, msg != NULL ? msg : "(no message)", "status", status);
}

/* ---- mun from 1e-12 to 1e12 --------------------------------------------------------------- */

static double scaled_oscillator(double c, struct stress_tally *tally, double *worst)
{
    const struct setting s[] = {{FRICREG_PARAM_MUN, c},
                                {FRICREG_PARAM_X0, 2.75 * c},
                                {FRICREG_PARAM_A, 0.385 * c},
                                {FRICREG_PARAM_OMEGA, 0.61},
                                {0, 0}};
    struct stress_energy w;
    fricreg_sim *sim = NULL;
    int status = run_sim(FRICREG_SYSTEM_OSCILLATOR, s, 2.0 * DT * c, DT, 4 * 10.3, &w, &sim);
    char name[64];
    snprintf(name, sizeof name, "oscillator, all scaled by c = %g", c);
    *worst = fmax(*worst, watched_row(tally, name, status, &w, sim));
    double D = total_dissipation(sim) / (c * c);
    fricreg_sim_free(sim);
    return D;
}

static double scaled_twoblock(double c, struct stress_tally *tally, double *worst)
{
    const struct setting s[] = {{FRICREG_PARAM_MU1, 0.5 * c},
                                {FRICREG_PARAM_MU2, 0.25 * c},
                                {FRICREG_PARAM_BELT_AMP, c},
                                {0, 0}};
    struct stress_energy w;
    fricreg_sim *sim = NULL;
    int status = run_sim(FRICREG_SYSTEM_TWOBLOCK, s, 2.0 * DT * c, DT, 30.0, &w, &sim);
    char name[64];
    snprintf(name, sizeof name, "two blocks, all scaled by c = %g", c);
    *worst = fmax(*worst, watched_row(tally, name, status, &w, sim));
    double D = total_dissipation(sim) / (c * c);
    fricreg_sim_free(sim);
    return D;
}

static void scaling_law(struct stress_tally *tally, double *worst_balance, double *worst_scaling)
{
    static const double c[] = {1e-12, 1e-6, 1e6, 1e12};
    double osc1 = scaled_oscillator(1.0, tally, worst_balance);
    double two1 = scaled_twoblock(1.0, tally, worst_balance);
    for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
        double osc = fabs(scaled_oscillator(c[i], tally, worst_balance) - osc1) / osc1;
        double two = fabs(scaled_twoblock(c[i], tally, worst_balance) - two1) / two1;
        char name[64];
        snprintf(name, sizeof name, "scaling law D(c)/c^2 = D(1), c = %g", c[i]);
        *worst_scaling = fmax(*worst_scaling, fmax(osc, two));
        /* rounding only: ~1e3 steps, each a few ulps, in a dissipative (contracting) flow */
        row(tally, name, osc <= 1e-11 && two <= 1e-11, "oscillator and two blocks", "rel diff",
            fmax(osc, two));
    }
}

/* mun = 1e12 under the paper's eps rule: refused at every dt, and the message names the
 * smallest eps that passes; that eps must then pass. x0 = 2.75 << mun: stuck for good. */
static void huge_bound(struct stress_tally *tally)
{
    const struct setting s[] = {{FRICREG_PARAM_MUN, 1e12}, {0, 0}};
    struct stress_energy w;
    fricreg_sim *sim = NULL;
    int status = run_sim(FRICREG_SYSTEM_OSCILLATOR, s, 0.0, DT, 10.0, &w, &sim);
    const char *msg = fricreg_sim_errmsg(sim);
    refusal_row(tally, "mun = 1e12, paper's eps = 2 dt", status, FRICREG_ESTEP, msg, "set eps >=");
    const char *named = strstr(msg, "set eps >= ");
    double eps = named ? strtod(named + strlen("set eps >= "), NULL) : NAN;
    fricreg_sim_free(sim);

    /* the message rounds to 6 digits: 1e-5 above it passes */
    status = run_sim(FRICREG_SYSTEM_OSCILLATOR, s, eps * (1 + 1e-5), DT, 100.0, &w, &sim);
    double moved = fabs(end_position(sim) - 2.75);
    row(tally, "mun = 1e12, eps as the message names",
        status == FRICREG_OK && moved == 0.0 && total_dissipation(sim) == 0.0,
        "stuck: x == x0, D == 0", "|x - x0|", moved);
    fricreg_sim_free(sim);
}

/* Bounds near DBL_MAX on coupled contacts: mun/eps overflows. The stick-zone stiffness must
 * then be +inf, not the 0 that 1.1 returned for a dense W (NaN eigenvalues dropped by fmax),
 * which let the step guard pass a run that diverged at its second step (the two blocks at
 * mu = 1e300, eps = 1e-10, or mu = 1e3, eps = 1e-306). With mun = 1e300 and
 * eps = 1 it is finite, and for (3) and the two blocks' W = [[1, -1], [-1, 2]] (equal bounds)
 * it is (mun/eps) lambda_max(W) = 1e300 (3 + sqrt 5)/2. */
static double stiffness_of(int law, int partition, double mun, double eps)
{
    const double W[4] = {1.0, -1.0, -1.0, 2.0}, bounds[2] = {mun, mun};
    fricreg_ctx *ctx = NULL;
    double lambda = NAN;
    if (fricreg_ctx_create(2, &ctx) == FRICREG_OK && fricreg_ctx_set_law(ctx, law, eps) == 0 &&
        fricreg_ctx_set_partition(ctx, partition) == 0 &&
        fricreg_ctx_set_coupling_dense(ctx, 2, W) == 0 &&
        fricreg_ctx_set_bounds(ctx, 2, bounds) == 0)
        fricreg_ctx_stick_stiffness(ctx, &lambda);
    fricreg_ctx_free(ctx);
    return lambda;
}

static void overflowing_stiffness(struct stress_tally *tally)
{
    static const int laws[] = {FRICREG_LAW_VELOCITY_LIMITED, FRICREG_LAW_TANH, FRICREG_LAW_QUINN};
    int all_inf = 1;
    for (int partition = FRICREG_PARTITION_CONSISTENT; partition <= FRICREG_PARTITION_PAPER;
         partition++)
        for (size_t k = 0; k < 3; k++)
            all_inf = all_inf && stiffness_of(laws[k], partition, 1e300, 1e-10) == INFINITY;
    row(tally, "stick stiffness, coupled, mun = 1e300, eps = 1e-10", all_inf,
        "+inf for (3), tanh, (4), both partitions", "lambda", all_inf ? INFINITY : 0.0);
    double expected = 1e300 * (3.0 + sqrt(5.0)) / 2.0;
    double got = stiffness_of(FRICREG_LAW_VELOCITY_LIMITED, FRICREG_PARTITION_CONSISTENT, 1e300,
                              1.0);
    double err = fabs(got - expected) / expected;
    row(tally, "stick stiffness, coupled, mun = 1e300, eps = 1", err <= 1e-14,
        "(mun/eps) lambda_max(W), law (3)", "rel err", err);

    /* The run: refused before any step, and the eps the message names then runs. mun/eps
     * overflows with modest bounds too, eps near DBL_MIN: mu = 1e3, eps = 1e-306 (bounds near
     * DBL_MAX would stop the first evaluation, f_eq being out of range). */
    static const int sim_laws[] = {FRICREG_LAW_QUINN, FRICREG_LAW_VELOCITY_LIMITED,
                                   FRICREG_LAW_KARNOPP};
    for (size_t k = 0; k < 3; k++) {
        const struct setting s[] = {{FRICREG_PARAM_MU1, 1e3}, {FRICREG_PARAM_MU2, 1e3}, {0, 0}};
        fricreg_sim *sim = NULL;
        int status = fricreg_sim_create(FRICREG_SYSTEM_TWOBLOCK, &sim);
        for (size_t i = 0; status == FRICREG_OK && s[i].param != 0; i++)
            status = fricreg_sim_set_param(sim, s[i].param, s[i].value);
        if (status == FRICREG_OK)
            status = fricreg_sim_set_law(sim, sim_laws[k], 1e-306);
        if (status == FRICREG_OK)
            status = fricreg_sim_run(sim, 1.0);
        const char *msg = fricreg_sim_errmsg(sim);
        const char *named = strstr(msg, "raise eps to ");
        double eps = named ? strtod(named + strlen("raise eps to "), NULL) : NAN;
        char name[64];
        snprintf(name, sizeof name, "two blocks, mu = 1e3, eps = 1e-306, law %d", sim_laws[k]);
        refusal_row(tally, name, status, FRICREG_ESTEP, msg, "raise eps to");
        int64_t steps = -1;
        fricreg_sim_get_stat(sim, FRICREG_SIM_STAT_STEPS, &steps);
        if (isfinite(eps) && fricreg_sim_set_law(sim, sim_laws[k], eps * (1 + 1e-5)) == FRICREG_OK)
            status = fricreg_sim_run(sim, 1.0);
        snprintf(name, sizeof name, "  the same at the eps it names, %.3g", eps);
        row(tally, name, steps == 0 && isfinite(eps) && status == FRICREG_OK, "runs", "status",
            status);
        fricreg_sim_free(sim);
    }
}

/* mun = 1e-12: a free oscillation; D per cycle is mun times the distance slid, 4 x0 per cycle
 * to O(mun) (the exact solver's, which is exact). */
static void tiny_bound(struct stress_tally *tally)
{
    const struct setting s[] = {{FRICREG_PARAM_MUN, 1e-12}, {0, 0}};
    struct stress_energy w;
    fricreg_sim *sim = NULL;
    int status = run_sim(FRICREG_SYSTEM_OSCILLATOR, s, 0.0, DT, 2.0 * 2.0 * STRESS_PI, &w, &sim);
    double D[2] = {NAN, NAN}, exact[2] = {NAN, NAN};
    fricreg_sim_get_dissipation(sim, 2, D);
    fricreg_exact *ex = NULL;
    if (fricreg_exact_solve(0.0, 1.0, 1e-12, 2.75, 0.0, 4.0 * STRESS_PI, &ex) == FRICREG_OK)
        fricreg_exact_dissipation(ex, 2, exact);
    double err = fabs(D[1] - exact[1]) / exact[1];
    /* RK4's phase error over 2 cycles at dt = 0.01 and the band eps = 0.02 at speed 2.75 */
    row(tally, "mun = 1e-12, D per cycle vs exact solver", status == FRICREG_OK && err <= 1e-3,
        "D_2 = 4 mun x0 (1 - O(mun))", "rel err", err);
    fricreg_exact_free(ex);
    fricreg_sim_free(sim);
}

/* ---- eps from 1e-12 to 1e3 with the step guard's dt ---------------------------------------- */

static void eps_sweep(struct stress_tally *tally, double *worst_balance)
{
    static const double eps[] = {1e-12, 1e-9, 1e-6, 1e-3, 1.0, 1e3};
    for (size_t i = 0; i < sizeof eps / sizeof eps[0]; i++) {
        /* dt lambda = dt 2 mun/eps = 1 (the paper's rule), within dt <= 1/2 (dt omega <= 1/sqrt 2) */
        double dt = fmin(eps[i] / 2.0, 0.5);
        struct stress_energy w;
        fricreg_sim *sim = NULL;
        int status = run_sim(FRICREG_SYSTEM_OSCILLATOR, NULL, eps[i], dt, fmin(2e4 * dt, 20.0), &w,
                             &sim);
        char name[64];
        snprintf(name, sizeof name, "eps = %g, dt = %g, unforced", eps[i], dt);
        if (dt <= DT) {
            *worst_balance = fmax(*worst_balance, watched_row(tally, name, status, &w, sim));
        } else {
            /* Unforced, so W_in = 0 exactly and no step may raise E above E0 (the watch's
             * excess, exact: no trapezoid involved). The driver's D, integrated by the same
             * RK4 as a state, closes E_end + D = E0 to RK4's global O(dt^4) error only
             * (0.5^4 = 0.06; measured 1e-3): checked at 1e-2, either sign. */
            double created = (w.E + total_dissipation(sim) - w.E0) / w.E0;
            int ok = status == FRICREG_OK && fabs(created) <= 1e-2 && w.worst_excess <= 0.0 &&
                     w.worst_force <= 1.0 + 4 * DBL_EPSILON;
            row(tally, name, ok, "E <= E0 every step, E_end + D ~ E0", "(E+D-E0)/E0", created);
        }
        fricreg_sim_free(sim);
    }
    /* A stick at eps = 1e-12 holds: x0 = 0.5 inside the bound, v0 = 0. */
    const struct setting stick[] = {{FRICREG_PARAM_X0, 0.5}, {0, 0}};
    struct stress_energy w;
    fricreg_sim *sim = NULL;
    int status = run_sim(FRICREG_SYSTEM_OSCILLATOR, stick, 1e-12, 5e-13, 1e-8, &w, &sim);
    double moved = fabs(end_position(sim) - 0.5);
    row(tally, "eps = 1e-12, stuck at x0 = 0.5", status == FRICREG_OK && moved == 0.0,
        "x == x0 after 2e4 steps", "|x - x0|", moved);
    fricreg_sim_free(sim);

    status = run_sim(FRICREG_SYSTEM_OSCILLATOR, NULL, 1e-12, DT, 1.0, &w, &sim);
    refusal_row(tally, "eps = 1e-12 with dt = 0.01", status, FRICREG_ESTEP, fricreg_sim_errmsg(sim),
                "rk4");
    fricreg_sim_free(sim);

    /* set_law takes eps >= 0; the context's eps >= DBL_MIN is checked when the run starts */
    status = run_sim(FRICREG_SYSTEM_OSCILLATOR, NULL, 1e-310, DT, 1.0, &w, &sim);
    refusal_row(tally, "eps = 1e-310 (subnormal)", status, FRICREG_EINVAL, fricreg_sim_errmsg(sim),
                "DBL_MIN");
    fricreg_sim_free(sim);
}

/* ---- forcing 0 and 1e8; omega at and 1e-9 from resonance ---------------------------------- */

static void forcing(struct stress_tally *tally, double *worst_balance)
{
    static const double a[] = {0.0, 1e8};
    for (size_t i = 0; i < 2; i++) {
        const struct setting s[] = {{FRICREG_PARAM_A, a[i]}, {FRICREG_PARAM_OMEGA, 0.61}, {0, 0}};
        struct stress_energy w;
        fricreg_sim *sim = NULL;
        int status = run_sim(FRICREG_SYSTEM_OSCILLATOR, s, 0.0, DT, 4 * 10.3, &w, &sim);
        char name[64];
        snprintf(name, sizeof name, "oscillator, a = %g", a[i]);
        *worst_balance = fmax(*worst_balance, watched_row(tally, name, status, &w, sim));
        fricreg_sim_free(sim);

        const struct setting c[] = {{FRICREG_PARAM_A, a[i]}, {0, 0}};
        status = run_sim(FRICREG_SYSTEM_CHAIN, c, 0.0, DT, 2 * 4.0 * STRESS_PI, &w, &sim);
        snprintf(name, sizeof name, "chain n = 32, a = %g", a[i]);
        *worst_balance = fmax(*worst_balance, watched_row(tally, name, status, &w, sim));
        fricreg_sim_free(sim);
    }
}

/* D per cycle of the exact solution over `cycles` cycles at a = 2 (above 4 mun/pi: the
 * amplitude grows at resonance), into D[cycles]. */
static int exact_cycles(double omega, int cycles, double D[])
{
    fricreg_exact *ex = NULL;
    int status = fricreg_exact_create(2.0, omega, 1.0, 0.0, 0.0, &ex);
    if (status == FRICREG_OK)
        status = fricreg_exact_run_cycles(ex, cycles);
    if (status == FRICREG_OK)
        status = fricreg_exact_dissipation(ex, (size_t)cycles, D);
    fricreg_exact_free(ex);
    return status;
}

static double max_rel_diff(const double a[], const double b[], size_t n)
{
    double worst = 0.0;
    for (size_t k = 0; k < n; k++)
        worst = fmax(worst, fabs(a[k] - b[k]) / fabs(b[k]));
    return worst;
}

/* At omega = 1 the exact solver uses the secular solution, at 1 +- 1e-9 the forced one with
 * 1/(1 - omega^2) ~ 5e8: the two must agree to the physics' own difference (a phase drift of
 * 1e-9 t, ~1e-7 over 10 cycles) plus the digits lost, ~1e-16 / 2e-9. RK4 with eps = 2 dt
 * follows within its O(eps) regularization error. */
static void resonance(struct stress_tally *tally, double *worst_exact)
{
    enum { CYCLES = 10 };
    double at[CYCLES], below[CYCLES], above[CYCLES], rk4[CYCLES];
    int s0 = exact_cycles(1.0, CYCLES, at);
    int s1 = exact_cycles(1.0 - 1e-9, CYCLES, below);
    int s2 = exact_cycles(1.0 + 1e-9, CYCLES, above);
    double diff = fmax(max_rel_diff(below, at, CYCLES), max_rel_diff(above, at, CYCLES));
    row(tally, "exact at omega = 1 and 1 -+ 1e-9, 10 cycles",
        s0 == FRICREG_OK && s1 == FRICREG_OK && s2 == FRICREG_OK && diff <= 1e-6, "D_k agree",
        "max rel diff", diff);

    const double omega[3] = {1.0 - 1e-9, 1.0, 1.0 + 1e-9};
    const double *exact[3] = {below, at, above};
    double err = 0.0;
    int status = FRICREG_OK;
    for (int i = 0; i < 3; i++) {
        const struct setting s[] = {{FRICREG_PARAM_A, 2.0},
                                    {FRICREG_PARAM_OMEGA, omega[i]},
                                    {FRICREG_PARAM_X0, 0.0},
                                    {0, 0}};
        struct stress_energy w;
        fricreg_sim *sim = NULL;
        int run = run_sim(FRICREG_SYSTEM_OSCILLATOR, s, 2e-3, 1e-3,
                          CYCLES * 2.0 * STRESS_PI / omega[i], &w, &sim);
        status = status != FRICREG_OK ? status : run;
        if (fricreg_sim_get_dissipation(sim, CYCLES, rk4) == FRICREG_OK)
            err = fmax(err, max_rel_diff(rk4, exact[i], CYCLES));
        else
            err = INFINITY;
        fricreg_sim_free(sim);
    }
    *worst_exact = fmax(*worst_exact, err);
    /* a = 2 > 4 mun/pi: the body never sticks, so law (4)'s band only touches the reversals */
    row(tally, "RK4 dt = 1e-3 vs exact, omega = 1, 1 -+ 1e-9", status == FRICREG_OK && err <= 1e-4,
        "D_k, eps = 2e-3", "max rel err", err);
}

/* ---- the chain from n = 2 to 1e4 (1e6 in full mode) ---------------------------------------- */

static void chain_sizes(const struct stress_mode *mode, struct stress_tally *tally,
                        double *worst_balance)
{
    static const double sizes[] = {2, 32, 1000, 1e4, 1e5, 1e6};
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0] && sizes[i] <= mode->chain_max_n; i++) {
        double n = sizes[i];
        /* dt 2n = 0.1, a fifth of the guard's limit: the watch's trapezoid rule must resolve
         * the highest modes, which block 1's start excites (paper's eps: dt lambda = 0.4) */
        double dt = fmin(0.05 / n, DT);
        /* 2e7 contact steps at most (~1 s), at least 200 steps; a whole cycle if cheaper */
        double steps = floor(fmax(200.0, fmin(4.0 * STRESS_PI / dt, 2e7 / n)));
        const struct setting s[] = {{FRICREG_PARAM_N, n}, {FRICREG_PARAM_A, 2.385}, {0, 0}};
        struct stress_energy w;
        fricreg_sim *sim = NULL;
        int status = run_sim(FRICREG_SYSTEM_CHAIN, s, 0.0, dt, steps * dt, &w, &sim);
        char name[64];
        snprintf(name, sizeof name, "chain n = %g, a = 2.385, %g steps", n, steps);
        *worst_balance = fmax(*worst_balance, watched_row(tally, name, status, &w, sim));
        fricreg_sim_free(sim);
    }
    const struct setting big[] = {{FRICREG_PARAM_N, 1000}, {0, 0}};
    struct stress_energy w;
    fricreg_sim *sim = NULL;
    int status = run_sim(FRICREG_SYSTEM_CHAIN, big, 0.0, DT, 1.0, &w, &sim);
    refusal_row(tally, "chain n = 1000 with dt = 0.01", status, FRICREG_ESTEP,
                fricreg_sim_errmsg(sim), "dt");
    fricreg_sim_free(sim);
    fricreg_sim_create(FRICREG_SYSTEM_CHAIN, &sim);
    status = fricreg_sim_set_param(sim, FRICREG_PARAM_N, 1e7 + 1);
    refusal_row(tally, "chain n = 1e7 + 1", status, FRICREG_EINVAL, fricreg_sim_errmsg(sim), "n");
    fricreg_sim_free(sim);
}

/* ---- a start exactly on the bound; subnormal inputs ---------------------------------------- */

/* x0 = mun: f_eq = mun exactly, so (2) holds the body: x' = 0, x'' = -x0 + mun = 0. Law (4)
 * gives xi = eps/2 and f = (2 mun/eps) xi = mun, the same to rounding; the exact solver stays
 * at rest (|f_eq| <= mun), D = 0. */
static void on_the_bound(struct stress_tally *tally)
{
    const double mun = 1.7;
    const struct setting s[] = {{FRICREG_PARAM_MUN, mun}, {FRICREG_PARAM_X0, mun}, {0, 0}};
    struct stress_energy w;
    fricreg_sim *sim = NULL;
    int status = run_sim(FRICREG_SYSTEM_OSCILLATOR, s, 0.0, DT, 100.0, &w, &sim);
    double moved = fabs(end_position(sim) - mun);
    /* a rounding of f = mun by one ulp moves x by ~ulp * t^2/2 at most */
    row(tally, "RK4 from x0 = mun = 1.7 (on the bound)",
        status == FRICREG_OK && moved <= 1e-12 && w.worst_force <= 1.0 + 4 * DBL_EPSILON,
        "stays at rest", "|x - x0|", moved);
    fricreg_sim_free(sim);

    fricreg_exact *ex = NULL;
    status = fricreg_exact_solve(0.0, 1.0, mun, mun, 0.0, 100.0, &ex);
    double x = NAN, v = NAN, D[15] = {0};
    if (status == FRICREG_OK) {
        fricreg_exact_state(ex, 100.0, &x, &v);
        fricreg_exact_dissipation(ex, fricreg_exact_ncycles(ex), D);
    }
    row(tally, "exact from x0 = mun = 1.7",
        status == FRICREG_OK && x == mun && v == 0.0 && D[0] == 0.0 &&
            fricreg_exact_nswitches(ex) == 0,
        "x == x0, v == 0, D == 0", "|x - x0|", fabs(x - mun));
    fricreg_exact_free(ex);
}

static void subnormal(struct stress_tally *tally)
{
    const double tiny = 3e-310; /* below DBL_MIN = 2.2e-308 */
    const struct setting s[] = {{FRICREG_PARAM_MUN, tiny},   {FRICREG_PARAM_X0, 2.5 * tiny},
                                {FRICREG_PARAM_V0, 5e-324},  {FRICREG_PARAM_A, tiny},
                                {FRICREG_PARAM_OMEGA, 0.61}, {0, 0}};
    struct stress_energy w;
    fricreg_sim *sim = NULL;
    int status = run_sim(FRICREG_SYSTEM_OSCILLATOR, s, 0.0, DT, 20.0, &w, &sim);
    double x = end_position(sim);
    /* energies underflow to 0, so the checks are the force bound and a bounded motion: the
     * the frictionless response x0 cos t + a (sin wt - w sin t)/(1 - w^2) stays within
     * x0 + a (1 + w)/(1 - w^2) = 5.06 tiny, and friction takes energy out */
    row(tally, "oscillator, mun, x0, a subnormal, v0 = 5e-324",
        status == FRICREG_OK && isfinite(x) && fabs(x) <= 5.1 * tiny &&
            w.worst_force <= 1.0 + 4 * DBL_EPSILON,
        "finite, |x| <= 5.1 tiny, |f| <= mun", "x/tiny", x / tiny);
    fricreg_sim_free(sim);

    double f = NAN;
    status = fricreg_law_eval(FRICREG_LAW_QUINN, 5e-324, -tiny, tiny, 1e-3, &f);
    /* xi = -eps/2 and v - xi = eps/2 + 5e-324 rounds to eps/2: the band's edge, f = -mun
     * both ways, which is f_eq: the force balance at rest holds with subnormal numbers */
    row(tally, "law (4) at subnormal v, f_eq, mun", status == FRICREG_OK && f == -tiny,
        "f = f_eq = -mun", "f/mun", f / tiny);

    fricreg_exact *ex = NULL;
    double D[1] = {NAN};
    status = fricreg_exact_solve(0.0, 1.0, tiny, 2.75, 0.0, 2.0 * STRESS_PI, &ex);
    if (status == FRICREG_OK)
        fricreg_exact_dissipation(ex, 1, D);
    /* D_1 = mun * 4 x0 to O(mun): the distance slid in one free cycle */
    double err = fabs(D[0] - 4.0 * 2.75 * tiny) / (4.0 * 2.75 * tiny);
    row(tally, "exact solver, mun = 3e-310", status == FRICREG_OK && err <= 1e-12, "D_1 = 4 x0 mun",
        "rel err", err);
    fricreg_exact_free(ex);
}

int stress_extreme(const struct stress_mode *mode)
{
    struct stress_tally tally = {0, 0};
    double worst_balance = 0.0, worst_scaling = 0.0, worst_exact = 0.0;
    printf("== extreme parameters: law (4), fixed RK4; refusals must be the documented ones\n");
    printf("%-44s %-4s %-34s %s\n", "case", "", "outcome", "figure");
    scaling_law(&tally, &worst_balance, &worst_scaling);
    huge_bound(&tally);
    overflowing_stiffness(&tally);
    tiny_bound(&tally);
    eps_sweep(&tally, &worst_balance);
    forcing(&tally, &worst_balance);
    resonance(&tally, &worst_exact);
    chain_sizes(mode, &tally, &worst_balance);
    on_the_bound(&tally);
    subnormal(&tally);
    printf("worst: balance gap %.3g of the energy scale, scaling law %.3g, RK4 vs exact %.3g; "
           "%d cases\n\n",
           worst_balance, worst_scaling, worst_exact, tally.checks);
    return tally.failures;
}
