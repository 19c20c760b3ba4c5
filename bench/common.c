/* SPDX-License-Identifier: GPL-3.0-or-later */
/* common.c — the benchmark problems, CPU timing with repeats, and one fricreg_sim run. */
#define _POSIX_C_SOURCE 199309L /* clock_gettime */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "bench.h"

/* The adaptive steppers use law (4) with a fixed eps, chosen per problem so that the
 * regularization error stays below the 0.01% target: O(eps^2) when the motion sticks
 * (oscillator a = 2 and the chain: eps = 1e-3), but only O(eps) when velocities reverse
 * without sticking (oscillator a = 3; the two blocks), where eps = 1e-5 and 1e-4 are needed. */
const struct bench_problem bench_problems[BENCH_NPROBLEMS] = {
    {"osc_stick", "oscillator a = 2, omega = 0.5 (sustained sticking), D on cycle 50",
     FRICREG_SYSTEM_OSCILLATOR, 2.0, 0.5, 0, 50, 1e-3, 1},
    {"osc_slip", "oscillator a = 3, omega = 1.5 (no sticking), D on cycle 50",
     FRICREG_SYSTEM_OSCILLATOR, 3.0, 1.5, 0, 50, 1e-5, 1},
    {"chain", "chain n = 32, a = 0.25, omega = 0.5, D on cycle 4", FRICREG_SYSTEM_CHAIN, 0.25, 0.5,
     32, 4, 1e-3, 1},
    {"twoblock", "two blocks on a belt (K = 2, mu1 = 0.5, mu2 = 0.25), D on cycle 4",
     FRICREG_SYSTEM_TWOBLOCK, 0.0, 0.0, 0, 4, 1e-4, 0},
};

double bench_cpu_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp_double(const void *pa, const void *pb)
{
    double a = *(const double *)pa, b = *(const double *)pb;
    return (a > b) - (a < b);
}

double bench_median(double x[], size_t n)
{
    qsort(x, n, sizeof *x, cmp_double);
    return n % 2 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}

double bench_time_once(bench_fn fn, const void *arg, struct bench_run *out)
{
    double t0 = bench_cpu_seconds();
    fn(arg, out);
    return bench_cpu_seconds() - t0;
}

static int sim_setup(fricreg_sim *sim, const struct bench_sim_point *pt)
{
    const struct bench_problem *p = pt->problem;
    int s = FRICREG_OK;
    if (p->system == FRICREG_SYSTEM_OSCILLATOR) { /* from rest at the origin (spec, Eq. (5)) */
        s = fricreg_sim_set_param(sim, FRICREG_PARAM_A, p->a);
        if (s == FRICREG_OK)
            s = fricreg_sim_set_param(sim, FRICREG_PARAM_OMEGA, p->omega);
        if (s == FRICREG_OK)
            s = fricreg_sim_set_param(sim, FRICREG_PARAM_X0, 0.0);
        if (s == FRICREG_OK)
            s = fricreg_sim_set_param(sim, FRICREG_PARAM_V0, 0.0);
    } else if (p->system == FRICREG_SYSTEM_CHAIN) {
        s = fricreg_sim_set_param(sim, FRICREG_PARAM_N, (double)p->n);
        if (s == FRICREG_OK)
            s = fricreg_sim_set_param(sim, FRICREG_PARAM_A, p->a);
        if (s == FRICREG_OK)
            s = fricreg_sim_set_param(sim, FRICREG_PARAM_OMEGA, p->omega);
    }
    if (s == FRICREG_OK)
        s = fricreg_sim_set_law(sim, pt->law, pt->eps);
    if (s == FRICREG_OK && pt->partition)
        s = fricreg_sim_set_partition(sim, pt->partition);
    if (s == FRICREG_OK)
        s = fricreg_sim_set_integrator(sim, pt->integrator, pt->dt, pt->rtol, pt->rtol);
    if (s == FRICREG_OK && pt->no_kink_location)
        s = fricreg_sim_set_kink_location(sim, 0);
    return s;
}

double bench_period(const struct bench_problem *p)
{
    struct bench_sim_point pt = {p, FRICREG_LAW_QUINN, FRICREG_INT_RK4, 0.01, 0.0, 0.0, 0, 0, 0, 0,
                                 0};
    double period = NAN;
    fricreg_sim *sim = NULL;
    if (fricreg_sim_create(p->system, &sim) == FRICREG_OK && sim_setup(sim, &pt) == FRICREG_OK)
        fricreg_sim_get_value(sim, FRICREG_VALUE_PERIOD, &period);
    fricreg_sim_free(sim);
    return period;
}

static int run_plain(fricreg_sim *sim, const struct bench_sim_point *pt, double D[])
{
    int status = fricreg_sim_run_cycles(sim, pt->problem->cycle);
    return status == FRICREG_OK ? fricreg_sim_get_dissipation(sim, (size_t)pt->problem->cycle, D)
                                : status;
}

/* D per cycle extrapolated in eps; the last cycle's estimate into out->D_error, whether
 * any cycle was flagged into out->flagged. */
static int run_extrapolated(fricreg_sim *sim, const struct bench_sim_point *pt, double D[],
                            struct bench_run *out)
{
    size_t cycles = (size_t)pt->problem->cycle;
    double T = NAN, *err = malloc(cycles * sizeof *err);
    int status = err ? fricreg_sim_get_value(sim, FRICREG_VALUE_PERIOD, &T) : FRICREG_ENOMEM;
    if (status == FRICREG_OK)
        status = fricreg_sim_run_extrapolated_window(sim, (double)cycles * T, pt->levels, pt->order,
                                                     pt->window);
    if (status == FRICREG_OK)
        status = fricreg_sim_get_extrapolated_dissipation(sim, cycles, D, err);
    if (status == FRICREG_OK) {
        double flagged = 0.0;
        fricreg_sim_get_extrapolation(sim, FRICREG_EXTRAP_FLAGGED_CYCLES, &flagged);
        out->D_error = err[cycles - 1];
        out->flagged = flagged > 0.0;
    }
    free(err);
    return status;
}

int bench_sim_run(const void *point, struct bench_run *out)
{
    const struct bench_sim_point *pt = point;
    int cycle = pt->problem->cycle;
    double *D = malloc((size_t)cycle * sizeof *D);
    fricreg_sim *sim = NULL;
    *out = (struct bench_run){0};
    out->status = D ? fricreg_sim_create(pt->problem->system, &sim) : FRICREG_ENOMEM;
    if (out->status == FRICREG_OK)
        out->status = sim_setup(sim, pt);
    if (out->status == FRICREG_OK)
        out->status = pt->levels >= 2 ? run_extrapolated(sim, pt, D, out) : run_plain(sim, pt, D);
    if (out->status == FRICREG_OK) {
        out->D = D[cycle - 1];
        fricreg_sim_get_value(sim, FRICREG_VALUE_STEPS, &out->steps);
        if (pt->levels >= 2)
            fricreg_sim_get_extrapolation(sim, FRICREG_EXTRAP_RHS_EVALS, &out->rhs_evals);
        else
            fricreg_sim_get_value(sim, FRICREG_VALUE_RHS_EVALS, &out->rhs_evals);
    } else {
        snprintf(out->msg, sizeof out->msg, "%s",
                 sim ? fricreg_sim_errmsg(sim) : fricreg_strerror(out->status));
        out->D = NAN;
    }
    fricreg_sim_free(sim);
    free(D);
    return out->status;
}

double bench_rel_error(double D, double ref)
{
    return fabs(D - ref) / fabs(ref);
}

FILE *bench_open_out(const char *program, const char *dir, const char *name)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    if (f == NULL)
        fprintf(stderr, "%s: cannot write %s\n", program, path);
    return f;
}
