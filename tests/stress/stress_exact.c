/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stress_exact.c — the exact solver (fricreg_exact.h) over random parameters. Each case is
 * checked against its own energy balance: from x'' + x = f + a sin(wt) and D = -∫ x' f dt,
 *     D = W_in - (E(t_end) - E(0)),  E = (x^2 + x'^2)/2,  W_in = ∫ a sin(wt) x' dt,
 * W_in by GSL quadrature of the closed-form velocity, split at the switching times so that
 * each piece is smooth. None may hang: its work counters are bounded by the scan grid the
 * header states (h = 2 pi/max(1, omega)/1024). Some cases also run the RK4 driver with law
 * (4) at dt = 1e-3, eps = 2 dt max(1, mun), whose D per cycle must follow within its O(eps) error. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include "fricreg_exact.h"
#include "stress.h"

#define QUAD_LIMIT 1000
#define BALANCE_TOL 1e-9 /* relative; the solver's switches are exact to ~1e-12 */
#define SIM_DT 1e-3
#define SIM_TOL 1e-2 /* law (4) at eps ~ 2e-3 against (1)+(2): O(eps); measured 1.1e-3 */

struct params {
    double a, omega, mun, x0, v0;
    int cycles;
};

struct forcing {
    const fricreg_exact *ex;
    double a, omega;
};

static double forcing_power(double t, void *user)
{
    const struct forcing *fo = user;
    double x = NAN, v = NAN;
    fricreg_exact_state(fo->ex, t, &x, &v);
    return fo->a * sin(fo->omega * t) * v;
}

static double energy_at(const fricreg_exact *ex, double t)
{
    double x = NAN, v = NAN;
    fricreg_exact_state(ex, t, &x, &v);
    return 0.5 * (x * x + v * v);
}

/* W_in over [0, t_end], one quadrature per phase; NAN if GSL fails. */
static double work_in(const fricreg_exact *ex, const struct params *p, double t_end,
                      gsl_integration_workspace *ws)
{
    size_t n = fricreg_exact_nswitches(ex);
    double *times = malloc((n + 1) * sizeof *times);
    if (times == NULL || fricreg_exact_switches(ex, n, times, NULL) != FRICREG_OK) {
        free(times);
        return NAN;
    }
    struct forcing fo = {ex, p->a, p->omega};
    gsl_function F = {forcing_power, &fo};
    double total = 0.0, lo = 0.0;
    for (size_t k = 0; k <= n; k++) {
        double hi = k < n ? fmin(times[k], t_end) : t_end, piece = 0.0, err;
        if (hi > lo && gsl_integration_qag(&F, lo, hi, 1e-12, 1e-10, QUAD_LIMIT, GSL_INTEG_GAUSS21,
                                           ws, &piece, &err) != GSL_SUCCESS)
            total = NAN;
        total += piece;
        lo = fmax(lo, hi);
    }
    free(times);
    return total;
}

static double sum(const double D[], size_t n)
{
    double s = 0.0;
    for (size_t k = 0; k < n; k++)
        s += D[k];
    return s;
}

/* sum_k |D_k(RK4, law (4)) - D_k(exact)| / sum_k D_k(exact); infinite if the driver failed. */
static double sim_error(const struct params *p, const double exact[])
{
    fricreg_sim *sim = NULL;
    int status = fricreg_sim_create(FRICREG_SYSTEM_OSCILLATOR, &sim);
    const int which[5] = {FRICREG_PARAM_A, FRICREG_PARAM_OMEGA, FRICREG_PARAM_MUN, FRICREG_PARAM_X0,
                          FRICREG_PARAM_V0};
    const double value[5] = {p->a, p->omega, p->mun, p->x0, p->v0};
    for (int i = 0; i < 5 && status == FRICREG_OK; i++)
        status = fricreg_sim_set_param(sim, which[i], value[i]);
    if (status == FRICREG_OK)
        status = fricreg_sim_set_integrator(sim, FRICREG_INT_RK4, SIM_DT, 0.0, 0.0);
    /* eps = 2 dt, but at least dt lambda = dt 2 mun/eps = 1 (the step guard's bound 2.78) */
    if (status == FRICREG_OK)
        status = fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, 2.0 * SIM_DT * fmax(1.0, p->mun));
    if (status == FRICREG_OK)
        status = fricreg_sim_run_cycles(sim, p->cycles);
    double *D = malloc((size_t)p->cycles * sizeof *D), err = INFINITY; /* a failure fails */
    if (status == FRICREG_OK && D != NULL &&
        fricreg_sim_get_dissipation(sim, (size_t)p->cycles, D) == FRICREG_OK) {
        double diff = 0.0;
        for (int k = 0; k < p->cycles; k++)
            diff += fabs(D[k] - exact[k]);
        err = diff / sum(exact, (size_t)p->cycles);
    }
    free(D);
    fricreg_sim_free(sim);
    return err;
}

struct case_result {
    int status;
    double balance;    /* relative gap of the energy balance */
    double scan_ratio; /* scan points / (t_end / h) */
    int64_t roots, iters;
    size_t switches;
    double sim_err; /* NAN when not compared */
};

static struct case_result run_case(const struct params *p, int compare,
                                   gsl_integration_workspace *ws)
{
    struct case_result r = {0};
    r.sim_err = NAN;
    fricreg_exact *ex = NULL;
    r.status = fricreg_exact_create(p->a, p->omega, p->mun, p->x0, p->v0, &ex);
    if (r.status == FRICREG_OK)
        r.status = fricreg_exact_run_cycles(ex, p->cycles);
    if (r.status != FRICREG_OK) {
        fricreg_exact_free(ex);
        return r;
    }
    double t_end = 0.0, h = 2.0 * STRESS_PI / fmax(1.0, p->omega) / 1024.0;
    int64_t points = 0;
    fricreg_exact_get_value(ex, FRICREG_EXACT_VALUE_TIME, &t_end);
    fricreg_exact_get_stat(ex, FRICREG_EXACT_STAT_SCAN_POINTS, &points);
    fricreg_exact_get_stat(ex, FRICREG_EXACT_STAT_ROOTS, &r.roots);
    fricreg_exact_get_stat(ex, FRICREG_EXACT_STAT_ROOT_ITERS, &r.iters);
    r.switches = fricreg_exact_nswitches(ex);
    r.scan_ratio = (double)points / (t_end / h);

    double *D = malloc((size_t)p->cycles * sizeof *D);
    if (D == NULL || fricreg_exact_dissipation(ex, (size_t)p->cycles, D) != FRICREG_OK) {
        r.balance = NAN;
    } else {
        double E0 = energy_at(ex, 0.0), E1 = energy_at(ex, t_end);
        double W = work_in(ex, p, t_end, ws), Dsum = sum(D, (size_t)p->cycles);
        r.balance = fabs(Dsum - (W - (E1 - E0))) / (Dsum + fabs(W) + E0 + E1);
        if (compare && Dsum > 0.0)
            r.sim_err = sim_error(p, D);
    }
    free(D);
    fricreg_exact_free(ex);
    return r;
}

static struct params draw(uint64_t *rng, int max_cycles)
{
    struct params p;
    p.a = stress_uniform(rng, 0.0, 3.0);
    p.omega = stress_log_uniform(rng, 0.2, 5.0);
    p.mun = stress_log_uniform(rng, 0.05, 3.0);
    p.x0 = stress_uniform(rng, -5.0, 5.0);
    p.v0 = stress_uniform(rng, -3.0, 3.0);
    p.cycles = 1 + (int)stress_uniform(rng, 0.0, (double)max_cycles);
    return p;
}

int stress_exact_random(const struct stress_mode *mode)
{
    struct stress_tally tally = {0, 0};
    gsl_integration_workspace *ws = gsl_integration_workspace_alloc(QUAD_LIMIT);
    uint64_t rng = mode->seed;
    double worst_balance = 0.0, worst_ratio = 0.0, worst_sim = 0.0, worst_iters = 0.0;
    long long switches = 0, compared = 0;
    int worst_case = -1;
    stress_check(&tally, ws != NULL, "quadrature workspace");
    for (int i = 0; ws != NULL && i < mode->exact_cases; i++) {
        struct params p = draw(&rng, mode->exact_max_cycles);
        struct case_result r = run_case(&p, i < mode->exact_vs_sim_cases, ws);
        stress_check(&tally, r.status == FRICREG_OK && r.balance <= BALANCE_TOL,
                     "case %d (a %.17g, omega %.17g, mun %.17g, x0 %.17g, v0 %.17g, %d cycles): "
                     "status %d, balance gap %g",
                     i, p.a, p.omega, p.mun, p.x0, p.v0, p.cycles, r.status, r.balance);
        /* the header's grid: ~t_end/h points plus the halved first steps of each phase */
        stress_check(&tally, r.scan_ratio <= 2.0 + 64.0 * (double)r.roots / 1024.0,
                     "case %d: %g times the scan grid's points", i, r.scan_ratio);
        stress_check(&tally, r.iters <= 100 * (r.roots + 1), "case %d: %lld Brent iterations", i,
                     (long long)r.iters);
        if (r.balance > worst_balance)
            worst_balance = r.balance, worst_case = i;
        worst_ratio = fmax(worst_ratio, r.scan_ratio);
        worst_iters = fmax(worst_iters, (double)r.iters / (double)(r.roots + 1));
        switches += (long long)r.switches;
        if (!isnan(r.sim_err)) {
            compared++;
            stress_check(&tally, r.sim_err <= SIM_TOL, "case %d: RK4 D off by %g", i, r.sim_err);
            worst_sim = fmax(worst_sim, r.sim_err);
        }
    }
    gsl_integration_workspace_free(ws);
    printf("== exact solver over random parameters (seed %llu): a in [0,3], omega in [0.2,5], "
           "mun in [0.05,3], x0 in [-5,5], v0 in [-3,3], 1..%d cycles\n",
           (unsigned long long)mode->seed, mode->exact_max_cycles);
    printf("%-8s %-10s %-16s %-18s %-18s %-22s\n", "cases", "switches", "worst balance",
           "worst scan/grid", "Brent iters/root", "RK4 vs exact (cases)");
    printf("%-8d %-10lld %-16.3g %-18.4g %-18.3g %.3g (%lld)\n", mode->exact_cases, switches,
           worst_balance, worst_ratio, worst_iters, worst_sim, compared);
    printf("worst balance at case %d; failed checks %d of %d\n\n", worst_case, tally.failures,
           tally.checks);
    return tally.failures;
}
