/* SPDX-License-Identifier: GPL-3.0-or-later */
/* reference.c — the reference dissipations of the benchmark problems.
 *
 * The oscillators have an exact solution (fricreg_exact.h). The chain and the two blocks have
 * none: their reference is law (4) with RK4 on a ladder of halved steps (eps by the paper's
 * rule, so eps and dt shrink together), extrapolated with the order the ladder shows. The
 * chain's contacts are uncoupled, so the event-driven classical solution (CVODE, when built)
 * checks it independently. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <fricreg_exact.h>

#include "reference.h"
#ifdef FRICREG_BENCH_CVODE
#include "event_driven.h"
#endif

/* Exact D of the problem's cycle; the period and the run length come from the solver, and a
 * failure's message goes into ref->how. */
static int exact_reference(const struct bench_problem *p, struct bench_reference *ref)
{
    fricreg_exact *ex = NULL;
    double T = 0.0;
    double *D = malloc((size_t)p->cycle * sizeof *D);
    int status = D ? fricreg_exact_create(p->a, p->omega, 1.0, 0.0, 0.0, &ex) : FRICREG_ENOMEM;
    if (status == FRICREG_OK)
        status = fricreg_exact_run_cycles(ex, p->cycle);
    if (status == FRICREG_OK)
        status = fricreg_exact_get_value(ex, FRICREG_EXACT_VALUE_PERIOD, &T);
    if (status == FRICREG_OK)
        status = fricreg_exact_dissipation(ex, (size_t)p->cycle, D);
    if (status == FRICREG_OK) {
        double stick = 0.0;
        fricreg_exact_stick_fraction(ex, (p->cycle - 1) * T, p->cycle * T, &stick);
        ref->D = D[p->cycle - 1];
        ref->uncertainty = 1e-12 * fabs(ref->D); /* the solver's 12 digits (Sec. 3.1) */
        snprintf(ref->how, sizeof ref->how,
                 "exact semi-analytical solution (fricreg_exact), %zu switches, stuck %.1f%% "
                 "of cycle %d",
                 fricreg_exact_nswitches(ex), 100.0 * stick, p->cycle);
    } else if (ex != NULL) {
        snprintf(ref->how, sizeof ref->how, "fricreg_exact: %s", fricreg_exact_errmsg(ex));
    }
    fricreg_exact_free(ex);
    free(D);
    return status;
}

/* The ladder: law (4), RK4, dt_k = dt0 / 2^k, k = 0 … levels-1. */
static int ladder_reference(const struct bench_problem *p, double dt0, int levels,
                            struct bench_reference *ref, FILE *log)
{
    enum { MAX_LEVELS = 10 };
    double D[MAX_LEVELS], dt[MAX_LEVELS], cpu = 0.0;
    struct bench_run run;
    fprintf(log, "  convergence of law (4) + RK4, eps by the paper's rule (%s):\n",
            p->system == FRICREG_SYSTEM_CHAIN ? "10 omega dt" : "2 dt");
    fprintf(log, "  %-11s %-11s %-19s %-11s %s\n", "dt", "eps", "D", "D - D(2dt)",
            "ratio of differences (2 = 1st order, 4 = 2nd)");
    for (int k = 0; k < levels && k < MAX_LEVELS; k++) {
        dt[k] = dt0 / (double)(1 << k);
        struct bench_sim_point pt = {
            p, FRICREG_LAW_QUINN, FRICREG_INT_RK4, dt[k], 0.0, 0.0, 0, 0, 0, 0, 0};
        double t0 = bench_cpu_seconds();
        if (bench_sim_run(&pt, &run) != FRICREG_OK) {
            fprintf(log, "  dt = %g failed: %s\n", dt[k], run.msg);
            return run.status;
        }
        cpu += bench_cpu_seconds() - t0;
        D[k] = run.D;
        double eps = p->system == FRICREG_SYSTEM_CHAIN ? 10.0 * p->omega * dt[k] : 2.0 * dt[k];
        fprintf(log, "  %-11.4g %-11.4g %-19.15f", dt[k], eps, D[k]);
        if (k >= 1)
            fprintf(log, " %+-11.3e", D[k] - D[k - 1]);
        if (k >= 2)
            fprintf(log, " %.2f", (D[k - 1] - D[k - 2]) / (D[k] - D[k - 1]));
        fputc('\n', log);
    }
    /* Richardson: the observed order of the last three rungs, rounded to the integer order
     * p of the scheme's expansion; extrapolate the last two pairs with it. Their difference
     * estimates what the extrapolation leaves. */
    int K = levels - 1;
    double d1 = D[K - 1] - D[K - 2], d2 = D[K] - D[K - 1], observed = log2(d1 / d2);
    double p_int = round(observed);
    if (isfinite(observed) && p_int >= 1.0 && fabs(observed - p_int) < 0.3) {
        double c = 1.0 / (pow(2.0, p_int) - 1.0);
        double R_last = D[K] + c * d2, R_prev = D[K - 1] + c * d1;
        ref->D = R_last;
        ref->uncertainty = fabs(R_last - R_prev);
        snprintf(ref->how, sizeof ref->how,
                 "law (4) + RK4, dt = %g … %g (%.1f CPU s), Richardson-extrapolated with order "
                 "%.0f (observed %.2f)",
                 dt[0], dt[K], cpu, p_int, observed);
    } else { /* no clean order: take the finest rung, its last change as the error */
        ref->D = D[K];
        ref->uncertainty = fabs(d2);
        snprintf(ref->how, sizeof ref->how,
                 "law (4) + RK4 at dt = %g (%.1f CPU s), not extrapolated (no clean order)", dt[K],
                 cpu);
    }
    fprintf(log, "  extrapolated D = %.15f, uncertainty %.1e (%.1e relative)\n", ref->D,
            ref->uncertainty, ref->uncertainty / fabs(ref->D));
    return FRICREG_OK;
}

#ifdef FRICREG_BENCH_CVODE
/* The classical event-driven solution at tight tolerances, beside the reference. */
static void event_driven_check(const struct bench_problem *p, const struct bench_reference *ref,
                               FILE *log)
{
    static const struct {
        int method;
        double rtol;
    } runs[] = {{ED_BDF, 1e-10}, {ED_ADAMS, 1e-10}, {ED_ADAMS, 1e-12}};
    for (size_t k = 0; k < sizeof runs / sizeof runs[0]; k++) {
        struct ed_point pt = {p, runs[k].method, runs[k].rtol, 0.0, 0.0};
        struct bench_run run;
        double t0 = bench_cpu_seconds();
        if (ed_run(&pt, &run) != FRICREG_OK) {
            fprintf(log, "  check: event-driven CVODE failed: %s\n", run.msg);
            continue;
        }
        fprintf(log,
                "  check: event-driven classical (CVODE %s, rtol %.0e): D = %.15f, %g events, "
                "differs by %.1e relative (%.2f CPU s)\n",
                runs[k].method == ED_BDF ? "BDF" : "Adams", runs[k].rtol, run.D, run.events,
                bench_rel_error(run.D, ref->D), bench_cpu_seconds() - t0);
    }
}
#endif

int bench_reference(const struct bench_problem *p, struct bench_reference *ref, FILE *log)
{
    int status;
    if (p->system == FRICREG_SYSTEM_OSCILLATOR)
        status = exact_reference(p, ref);
    else if (p->system == FRICREG_SYSTEM_CHAIN)
        status = ladder_reference(p, 4e-4, 5, ref, log);
    else
        status = ladder_reference(p, 1e-3, 7, ref, log);
    if (status != FRICREG_OK)
        return status;
    fprintf(log, "  reference D = %.15f: %s\n", ref->D, ref->how);
#ifdef FRICREG_BENCH_CVODE
    if (p->event_driven)
        event_driven_check(p, ref, log);
#endif
    return FRICREG_OK;
}
